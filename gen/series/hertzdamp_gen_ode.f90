!> The contact ODE  z'' + a z' + z^{3/2} = 0  in jet arithmetic (generator only).
!>
!> The damping a is itself a jet: a = (0, 1, 0, ...) makes every quantity a
!> Taylor series in alpha; a jet of degree 0 is an ordinary number, which turns
!> the same code into a scalar high-order Taylor integrator (used for reference
!> values).
module hertzdamp_gen_ode
    use hertzdamp_gen_jets, only: gk, jmul, jdiv, jpow, jconst
    implicit none (type, external)
    private

    public :: start_series, time_coefficients, taylor_step, integrate_fixed

contains

    !> Local series at contact start, in s = sqrt(t), of  u'' + a u' + u^{3/2} = 0,
    !> u(0) = 0, u'(0) = c:  u = t sum_k p_k s^k with p_0 = c, p_1 = 0 and, for m >= -1,
    !>   p_{m+2} = -[a p_m (1 + m/2) + q_{m-3}] / [((m+4)/2)((m+2)/2)],  q = p^{3/2}.
    !> Evaluates u and u' at t0 using terms 0..m_terms; `tail` returns the size
    !> (max-norm over the jet) of the last two terms of u, a truncation indicator.
    pure subroutine start_series(a, c, m_terms, t0, u, du, tail)
        real(gk), intent(in) :: a(0:)          !! damping jet
        real(gk), intent(in) :: c              !! initial velocity u'(0) > 0
        integer, intent(in) :: m_terms         !! highest power of s kept
        real(gk), intent(in) :: t0             !! evaluation time (> 0)
        real(gk), intent(out) :: u(0:ubound(a, 1))   !! u(t0)
        real(gk), intent(out) :: du(0:ubound(a, 1))  !! u'(t0)
        real(gk), intent(out) :: tail                !! size of the last two terms of u
        real(gk), allocatable :: p(:, :), q(:, :)
        real(gk) :: s0, sk, g
        integer :: n, k, m, j
        n = ubound(a, 1)
        allocate (p(0:n, 0:m_terms), q(0:n, 0:m_terms))
        p = 0.0_gk
        q = 0.0_gk
        g = 1.5_gk
        p(:, 0) = jconst(c, n)
        q(:, 0) = jconst(c**g, n)
        do m = 0, m_terms - 2
            k = m - 3
            if (k >= 1) then
                ! power recurrence: k p0 q_k = sum_j (g j - (k-j)) p_j q_{k-j}
                q(:, k) = 0.0_gk
                do j = 1, k
                    q(:, k) = q(:, k) + (g * j - (k - j)) * jmul(p(:, j), q(:, k - j))
                end do
                q(:, k) = q(:, k) / (k * c)
            end if
            p(:, m + 2) = -jmul(a, p(:, m)) * (1.0_gk + 0.5_gk * m)
            if (k >= 0) p(:, m + 2) = p(:, m + 2) - q(:, k)
            p(:, m + 2) = p(:, m + 2) / ((0.5_gk * (m + 4)) * (0.5_gk * (m + 2)))
        end do
        s0 = sqrt(t0)
        u = 0.0_gk
        du = 0.0_gk
        sk = 1.0_gk
        do k = 0, m_terms
            u = u + p(:, k) * (t0 * sk)
            du = du + p(:, k) * (0.5_gk * (k + 2) * sk)
            sk = sk * s0
        end do
        tail = t0 * s0**(m_terms - 1) * (maxval(abs(p(:, m_terms - 1))) &
                                         + s0 * maxval(abs(p(:, m_terms))))
    end subroutine start_series

    !> Taylor coefficients in the time offset d of z(t0 + d) (a series whose
    !> coefficients are jets), from z(t0) = z0 (z0(0) > 0) and z'(t0) = v0:
    !>   (k+1)(k+2) Z_{k+2} = -a (k+1) Z_{k+1} - W_k,   W = Z^{3/2}.
    pure function time_coefficients(a, z0, v0, kmax) result(zc)
        real(gk), intent(in) :: a(0:)   !! damping jet
        real(gk), intent(in) :: z0(0:)  !! z at the expansion point
        real(gk), intent(in) :: v0(0:)  !! z' at the expansion point
        integer, intent(in) :: kmax     !! highest power of d
        real(gk) :: zc(0:ubound(a, 1), 0:kmax)
        real(gk) :: w(0:ubound(a, 1), 0:kmax), s(0:ubound(a, 1))
        real(gk), parameter :: g = 1.5_gk
        integer :: k, j, n
        n = ubound(a, 1)
        zc = 0.0_gk
        w = 0.0_gk
        zc(:, 0) = z0
        if (kmax >= 1) zc(:, 1) = v0
        w(:, 0) = jpow(z0, g)
        do k = 0, kmax - 2
            if (k >= 1) then
                s = 0.0_gk
                do j = 1, k
                    s = s + (g * j - (k - j)) * jmul(zc(:, j), w(:, k - j))
                end do
                w(:, k) = jdiv(s, z0) / k
            end if
            zc(:, k + 2) = -(real(k + 1, gk) * jmul(a, zc(:, k + 1)) + w(:, k)) &
                           / real((k + 1) * (k + 2), gk)
        end do
    end function time_coefficients

    !> One Taylor step of length h (a number): z, v at t0 replaced by z, v at t0 + h.
    pure subroutine taylor_step(a, z, v, h, kmax)
        real(gk), intent(in) :: a(0:)       !! damping jet
        real(gk), intent(inout) :: z(0:)    !! z, overwritten by z(t0+h)
        real(gk), intent(inout) :: v(0:)    !! z', overwritten by z'(t0+h)
        real(gk), intent(in) :: h           !! step
        integer, intent(in) :: kmax         !! Taylor order in time
        real(gk) :: zc(0:ubound(a, 1), 0:kmax)
        integer :: k
        zc = time_coefficients(a, z, v, kmax)
        z = zc(:, kmax)
        v = kmax * zc(:, kmax)
        do k = kmax - 1, 0, -1
            z = z * h + zc(:, k)
            if (k >= 1) v = v * h + k * zc(:, k)
        end do
    end subroutine taylor_step

    !> Integrate from t0 to t1 with the deterministic step sequence
    !> h = min(rho t, hmax) (t is the distance to the branch point at t = 0),
    !> the last step shortened to land on t1.  Returns the number of steps.
    pure subroutine integrate_fixed(a, z, v, t0, t1, rho, hmax, kmax, nsteps)
        real(gk), intent(in) :: a(0:)       !! damping jet
        real(gk), intent(inout) :: z(0:)    !! z(t0) in, z(t1) out
        real(gk), intent(inout) :: v(0:)    !! z'(t0) in, z'(t1) out
        real(gk), intent(in) :: t0, t1      !! interval
        real(gk), intent(in) :: rho         !! step as a fraction of t
        real(gk), intent(in) :: hmax        !! largest step
        integer, intent(in) :: kmax         !! Taylor order in time
        integer, intent(out) :: nsteps      !! steps taken
        real(gk) :: t, h
        logical :: last
        t = t0
        nsteps = 0
        last = .false.
        do while (.not. last)
            h = min(rho * t, hmax)
            last = t + h >= t1 - 1.0e-3_gk * h
            if (last) h = t1 - t
            call taylor_step(a, z, v, h, kmax)
            t = t + h
            nsteps = nsteps + 1
        end do
    end subroutine integrate_fixed

end module hertzdamp_gen_ode
