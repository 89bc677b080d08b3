!> The best single fixed stiffness and damping for a DEM engine that cannot set k and
!> d per contact (`hertzdamp invert --fixed`): over a range of impact speeds
!> [u_lo, u_hi], the (k, d) of one damping law and contact end whose restitution is
!> closest to a target e in the worst case, and whose shortest contact lasts a
!> target time T (N time steps).
!>
!> With fixed k and d, alpha(u) = alpha_lo (u/u_lo)^s with s = (4q - 1)/5 (linear
!> q = 0: alpha falls with the speed; tsuji q = 1/4: constant; kuwabara-kono q = 1/2:
!> rises), and e(u) = E(alpha(u)) with E the law's forward map.  Only alpha_lo
!> decides e(u), k and d apart do not.
!>
!> - alpha_lo minimises the worst relative error max |E(alpha(u))/e - 1| over the
!>   range.  E is monotone in alpha and alpha monotone in u, so e(u) is monotone and
!>   the worst errors sit at the ends: the minimax is where they are equal and
!>   opposite, E(alpha_lo) + E(alpha_hi) = 2 e, found by bisection in ln alpha_lo
!>   between alpha(e)/max(1, r) and alpha(e)/min(1, r), r = (u_hi/u_lo)^s, where the
!>   sum is >= and <= 2 e.  (tsuji: alpha = alpha(e), no error.)
!> - k makes the shortest contact of the range last T: T_c(u) = t*(u) tau_c(alpha(u))
!>   with t*(u) = (m/(k u^(1/2)))^(2/5), so T_c(u) = (m/k)^(2/5) u^(-1/5)
!>   tau_c(alpha(u)); its minimum over the range (on a logarithmic grid of n_grid
!>   speeds, refined by golden section) is set to T.  Then every contact of the range
!>   lasts at least T, i.e. N steps of dt = T/N.  With a physical stiffness k_phys
!>   below that k, k = k_phys (bound_active): the contacts last longer.
!> - d from alpha_lo and the k at u_lo (hertzdamp_expand).
!>
!> E and tau_c are the fitted maps of the law (hertzdamp_forward_alpha, method fit),
!> the reference integrator beyond their range; no rebound (overlap end, alpha >=
!> alpha_c) counts as e = 0.  Pure, no module state, a status (HD_*) for bad input.
module hertzdamp_fixed
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_NO_REBOUND, HD_OUTSIDE_VALIDITY, HD_BAD_RESTITUTION, HD_BAD_TIME, &
                         HD_BAD_VELOCITY, HD_BAD_MASS, HD_BAD_STIFFNESS, HD_OUT_OF_RANGE, HD_METHOD_FIT, HD_METHOD_RK45, &
                         hertzdamp_forward_alpha, hertzdamp_collision, hertzdamp_law_speed_exponent, hertzdamp_law_status, &
                         hertzdamp_invert_alpha, hertzdamp_reduce, hertzdamp_expand
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk
    !> Speeds of the logarithmic grid on which the shortest contact is located.
    integer, parameter, public :: fixed_n_grid = 401

    !> The fixed pair and what it achieves over the speed range.
    type, public :: fixed_pair
        real(wp) :: k = 0.0_wp              !! Hertz stiffness [N m^-3/2]
        real(wp) :: d = 0.0_wp              !! damping coefficient [kg s^-1 m^-q]
        real(wp) :: alpha_lo = 0.0_wp       !! alpha at the slowest impact u_lo
        real(wp) :: alpha_hi = 0.0_wp       !! alpha at the fastest impact u_hi
        real(wp) :: worst = 0.0_wp          !! max |e(u)/e - 1| over [u_lo, u_hi]
        real(wp) :: tc_min = 0.0_wp         !! the shortest contact over the range [s] (T, or longer with the bound)
        real(wp) :: u_tc_min = 0.0_wp       !! the impact speed of that contact [m s^-1]
        logical :: bound_active = .false.   !! k = k_phys (the contacts last longer than asked)
        integer :: status = HD_OK           !! HD_OK or the code naming the bad input
    end type fixed_pair

    public :: hertzdamp_fixed_pair

contains

    !> The best single fixed (k, d) for target e and shortest contact time T over the
    !> impact speeds [u_lo, u_hi] (see the module header).
    pure function hertzdamp_fixed_pair(e, tc, m, u_lo, u_hi, iend, law, k_phys) result(p)
        real(wp), intent(in) :: e                  !! target restitution coefficient, 0 < e <= 1
        real(wp), intent(in) :: tc                 !! target duration of the shortest contact [s]
        real(wp), intent(in) :: m                  !! effective mass [kg]
        real(wp), intent(in) :: u_lo, u_hi         !! the range of impact speeds [m s^-1], 0 < u_lo <= u_hi
        integer, intent(in) :: iend                !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: law                 !! HD_DAMPING_*
        real(wp), intent(in), optional :: k_phys   !! physical stiffness bound [N m^-3/2]
        type(fixed_pair) :: p
        real(wp) :: s, r, ae, tau, lo, hi, a, tstar, a0, smin, g, e1, e2
        integer :: it, st
        p%status = hertzdamp_law_status(law)
        if (p%status /= HD_OK) return
        if (.not. (e > 0.0_wp .and. e <= 1.0_wp)) p%status = HD_BAD_RESTITUTION
        if (p%status == HD_OK .and. .not. (tc > 0.0_wp .and. ieee_is_finite(tc))) p%status = HD_BAD_TIME
        if (p%status == HD_OK .and. .not. (m > 0.0_wp .and. ieee_is_finite(m))) p%status = HD_BAD_MASS
        if (p%status == HD_OK .and. .not. (u_lo > 0.0_wp .and. u_hi >= u_lo .and. ieee_is_finite(u_hi))) then
            p%status = HD_BAD_VELOCITY
        end if
        if (p%status == HD_OK .and. present(k_phys)) then
            if (.not. (k_phys > 0.0_wp .and. ieee_is_finite(k_phys))) p%status = HD_BAD_STIFFNESS
        end if
        if (p%status /= HD_OK) return
        s = hertzdamp_law_speed_exponent(law)
        r = (u_hi / u_lo)**s
        ! the one-speed inverse brackets the minimax
        call hertzdamp_invert_alpha(e, iend, ae, tau, st, law=law)
        if (st /= HD_OK) then
            p%status = st
            return
        end if
        a = 0.0_wp
        if (ae > 0.0_wp) then
            lo = log(ae / max(1.0_wp, r))
            hi = log(ae / min(1.0_wp, r))
            do it = 1, 200
                if (hi - lo <= 4.0_wp * spacing(max(abs(lo), abs(hi)))) exit
                a = 0.5_wp * (lo + hi)
                call forward(exp(a), iend, law, e1, tau, st)
                if (st == HD_OK) call forward(r * exp(a), iend, law, e2, tau, st)
                g = e1 + e2 - 2.0_wp * e
                if (st /= HD_OK) then
                    p%status = st
                    return
                end if
                if (g > 0.0_wp) then
                    lo = a
                else
                    hi = a
                end if
            end do
            a = exp(0.5_wp * (lo + hi))
        end if
        p%alpha_lo = a
        p%alpha_hi = r * a
        call forward(p%alpha_lo, iend, law, e1, tau, st)
        if (st == HD_OK) call forward(p%alpha_hi, iend, law, e2, tau, st)
        if (st /= HD_OK) then
            p%status = st
            return
        end if
        p%worst = max(abs(e1 / e - 1.0_wp), abs(e2 / e - 1.0_wp))
        ! the shortest contact: min of u^(-1/5) tau_c(alpha(u)) over the range
        call shortest(p%alpha_lo, s, u_lo, u_hi, iend, law, smin, p%u_tc_min, st)
        if (st /= HD_OK) then
            p%status = st
            return
        end if
        ! T = t*(u_min) tau_c(alpha(u_min)): t* there, then k and d from alpha and t*
        tstar = tc / (smin * p%u_tc_min**0.2_wp)
        call hertzdamp_expand(p%alpha_lo * (p%u_tc_min / u_lo)**s, tstar, m, p%u_tc_min, p%k, p%d, st, law)
        if (st == HD_OK .and. present(k_phys)) then
            if (k_phys < p%k) then
                p%k = k_phys
                p%bound_active = .true.
            end if
        end if
        ! d from alpha_lo and the t* of this k at u_lo
        if (st == HD_OK) call hertzdamp_reduce(p%k, 0.0_wp, m, u_lo, a0, tstar, st, law)
        if (st == HD_OK) call hertzdamp_expand(p%alpha_lo, tstar, m, u_lo, a0, p%d, st, law)
        if (st == HD_OK) p%tc_min = (m / p%k)**0.4_wp * smin
        if (st == HD_OK .and. .not. (ieee_is_finite(p%k) .and. ieee_is_finite(p%d) .and. p%tc_min > 0.0_wp)) then
            st = HD_OUT_OF_RANGE
        end if
        p%status = st
        if (st /= HD_OK) then
            p%k = 0.0_wp
            p%d = 0.0_wp
        end if
    end function hertzdamp_fixed_pair

    !> e and tau_c of the law at alpha (tau_c huge without rebound).
    pure subroutine forward(alpha, iend, law, e, tau, status)
        real(wp), intent(in) :: alpha
        integer, intent(in) :: iend, law
        real(wp), intent(out) :: e, tau
        integer, intent(out) :: status
        type(hertzdamp_collision) :: c
        c = hertzdamp_forward_alpha(alpha, iend, HD_METHOD_FIT, law=law)
        if (c%status == HD_OUTSIDE_VALIDITY) c = hertzdamp_forward_alpha(alpha, iend, HD_METHOD_RK45, law=law)
        status = c%status
        e = c%e
        tau = c%tau_c
        if (status == HD_NO_REBOUND) then
            status = HD_OK
            e = 0.0_wp
            tau = huge(1.0_wp)
        end if
    end subroutine forward

    !> The minimum of f(u) = u^(-1/5) tau_c(alpha_lo (u/u_lo)^s) over [u_lo, u_hi] and
    !> where it is: the least of fixed_n_grid speeds spaced evenly in ln u, refined by
    !> golden section between its neighbours.
    pure subroutine shortest(alpha_lo, s, u_lo, u_hi, iend, law, fmin, umin, status)
        real(wp), intent(in) :: alpha_lo, s, u_lo, u_hi
        integer, intent(in) :: iend, law
        real(wp), intent(out) :: fmin, umin
        integer, intent(out) :: status
        real(wp) :: x, f, lo, hi, x1, x2, f1, f2, w
        real(wp), parameter :: gr = 0.6180339887498949_wp
        integer :: i, ibest, n
        n = merge(1, fixed_n_grid, u_hi == u_lo)
        fmin = huge(1.0_wp)
        umin = u_lo
        ibest = 0
        do i = 0, n - 1
            x = log(u_lo) + (log(u_hi) - log(u_lo)) * real(i, wp) / real(max(n - 1, 1), wp)
            call f_at(x, alpha_lo, s, u_lo, iend, law, f, status)
            if (status /= HD_OK) return
            if (f < fmin) then
                fmin = f
                ibest = i
            end if
        end do
        if (.not. fmin < huge(1.0_wp)) then
            status = HD_OUTSIDE_VALIDITY   ! no contact of the range ends (no rebound anywhere)
            return
        end if
        umin = exp(log(u_lo) + (log(u_hi) - log(u_lo)) * real(ibest, wp) / real(max(n - 1, 1), wp))
        if (ibest == 0) umin = u_lo
        if (ibest == n - 1) umin = u_hi
        if (n == 1) return
        w = (log(u_hi) - log(u_lo)) / real(n - 1, wp)
        lo = max(log(u_lo), log(umin) - w)
        hi = min(log(u_hi), log(umin) + w)
        x1 = hi - gr * (hi - lo)
        x2 = lo + gr * (hi - lo)
        call f_at(x1, alpha_lo, s, u_lo, iend, law, f1, status)
        if (status == HD_OK) call f_at(x2, alpha_lo, s, u_lo, iend, law, f2, status)
        do i = 1, 80
            if (status /= HD_OK) return
            if (f1 < f2) then
                hi = x2
                x2 = x1
                f2 = f1
                x1 = hi - gr * (hi - lo)
                call f_at(x1, alpha_lo, s, u_lo, iend, law, f1, status)
            else
                lo = x1
                x1 = x2
                f1 = f2
                x2 = lo + gr * (hi - lo)
                call f_at(x2, alpha_lo, s, u_lo, iend, law, f2, status)
            end if
        end do
        if (min(f1, f2) < fmin) then
            fmin = min(f1, f2)
            umin = exp(merge(x1, x2, f1 < f2))
        end if
    end subroutine shortest

    !> f = u^(-1/5) tau_c(alpha(u)) at ln u (huge without rebound).
    pure subroutine f_at(lnu, alpha_lo, s, u_lo, iend, law, f, status)
        real(wp), intent(in) :: lnu, alpha_lo, s, u_lo
        integer, intent(in) :: iend, law
        real(wp), intent(out) :: f
        integer, intent(out) :: status
        real(wp) :: e, tau
        call forward(alpha_lo * exp(s * (lnu - log(u_lo))), iend, law, e, tau, status)
        f = huge(1.0_wp)
        if (tau < huge(1.0_wp)) f = exp(-0.2_wp * lnu) * tau
    end subroutine f_at

end module hertzdamp_fixed
