!> Jet-free reference solution of one collision (overlap definition), in
!> quadruple precision, for measuring the series and the Pade approximants.
!>
!> Method: local series in sqrt(t) from contact start to t0; Taylor steps of
!> order 40 with steps limited to a fraction of the distance to the two branch
!> points (contact start, and the predicted contact end); the turning point by
!> Newton on the time polynomial of the step that contains it; the end by
!> matching (z, z') to the backward local series (damping -alpha, unknown exit
!> speed e and remaining time sigma) with Newton's method.  No alpha expansion
!> and no time-reversal identity is used.
module hertzdamp_gen_reference
    use hertzdamp_gen_jets, only: gk
    use hertzdamp_gen_ode, only: start_series, time_coefficients, taylor_step
    implicit none (type, external)
    private

    public :: reference_collision

    integer, parameter :: kt = 40           ! Taylor order in time
    integer, parameter :: ms = 60           ! terms of the local series
    real(gk), parameter :: rho = 0.2_gk     ! step / distance to nearest branch point
    real(gk), parameter :: hmax = 0.1_gk    ! largest step
    real(gk), parameter :: sig_match = 0.08_gk ! remaining time at which to match

contains

    !> e, tau_c, z_max, tau_max for damping alpha (alpha < alpha_c);
    !> ok = .false. when the end could not be located.
    subroutine reference_collision(alpha, e, tau_c, z_max, tau_max, ok)
        real(gk), intent(in) :: alpha          !! damping parameter
        real(gk), intent(out) :: e, tau_c      !! restitution, contact duration
        real(gk), intent(out) :: z_max, tau_max !! deepest overlap and its time
        logical, intent(out) :: ok             !! success flag
        real(gk) :: a(0:0), z(0:0), v(0:0), zc(0:0, 0:kt), t, h, tail, sig, d
        integer :: it, k
        logical :: turned
        a(0) = alpha
        t = 0.05_gk
        call start_series(a, 1.0_gk, ms, t, z, v, tail)
        turned = .false.
        ok = .false.
        z_max = 0.0_gk
        tau_max = 0.0_gk
        do it = 1, 100000
            if (turned) then
                sig = z(0) / abs(v(0))
                if (sig < sig_match) exit
                h = min(hmax, rho * sig)
            else
                h = min(hmax, rho * t)
            end if
            zc = time_coefficients(a, z, v, kt)
            if (.not. turned) then
                if (dv(zc, h) <= 0.0_gk) then
                    ! turning point inside this step: Newton on z'(d) = 0
                    d = h / 2
                    do k = 1, 60
                        d = d - dv(zc, d) / ddv(zc, d)
                    end do
                    tau_max = t + d
                    z_max = zval(zc, d)
                    turned = .true.
                end if
            end if
            call taylor_step(a, z, v, h, kt)
            t = t + h
            if (z(0) <= 0.0_gk) return
        end do
        call match_end(alpha, z(0), v(0), e, sig, ok)
        tau_c = t + sig
    contains
        pure real(gk) function zval(c, x)
            real(gk), intent(in) :: c(0:, 0:), x
            integer :: j
            zval = 0.0_gk
            do j = kt, 0, -1
                zval = zval * x + c(0, j)
            end do
        end function zval
        pure real(gk) function dv(c, x)
            real(gk), intent(in) :: c(0:, 0:), x
            integer :: j
            dv = 0.0_gk
            do j = kt, 1, -1
                dv = dv * x + j * c(0, j)
            end do
        end function dv
        pure real(gk) function ddv(c, x)
            real(gk), intent(in) :: c(0:, 0:), x
            integer :: j
            ddv = 0.0_gk
            do j = kt, 2, -1
                ddv = ddv * x + j * (j - 1) * c(0, j)
            end do
        end function ddv
    end subroutine reference_collision

    !> Find the exit speed c and remaining time sig with y(sig) = z1,
    !> y'(sig) = -v1 for  y'' - alpha y' + y^{3/2} = 0, y(0) = 0, y'(0) = c.
    subroutine match_end(alpha, z1, v1, c, sig, ok)
        real(gk), intent(in) :: alpha, z1, v1
        real(gk), intent(out) :: c, sig
        logical, intent(out) :: ok
        real(gk) :: a(0:0), f(2), fc(2), fs(2), jac(2, 2), det, dc, ds, hc, hs
        integer :: it
        a(0) = -alpha
        c = abs(v1)
        sig = z1 / abs(v1)
        ok = .false.
        do it = 1, 60
            f = resid(c, sig)
            hc = 1.0e-14_gk * c
            hs = 1.0e-14_gk * sig
            fc = resid(c + hc, sig)
            fs = resid(c, sig + hs)
            jac(:, 1) = (fc - f) / hc
            jac(:, 2) = (fs - f) / hs
            det = jac(1, 1) * jac(2, 2) - jac(1, 2) * jac(2, 1)
            dc = (f(1) * jac(2, 2) - f(2) * jac(1, 2)) / det
            ds = (jac(1, 1) * f(2) - jac(2, 1) * f(1)) / det
            c = c - dc
            sig = sig - ds
            if (abs(dc) <= 1.0e-31_gk * c .and. abs(ds) <= 1.0e-31_gk * sig) exit
        end do
        ok = abs(dc) <= 1.0e-26_gk * c .and. abs(ds) <= 1.0e-26_gk * sig
    contains
        function resid(cc, ss) result(r)
            real(gk), intent(in) :: cc, ss
            real(gk) :: r(2), y(0:0), dy(0:0), tl
            call start_series(a, cc, ms, ss, y, dy, tl)
            r(1) = y(0) - z1
            r(2) = dy(0) + v1
        end function resid
    end subroutine match_end

end module hertzdamp_gen_reference
