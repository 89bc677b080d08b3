!> TEMPORARY stand-in, dropped on merge.
!>
!> Only the interface of `hertzdamp_invert` is real: every method (fit, compact,
!> iterative, ...) is answered here by the iterative baseline, a safeguarded secant
!> on alpha with one reference (rk45) solve per iterate, followed by the algebra of
!> THEORY.md section 6.  The branch that owns this file replaces it on merge.
module hertzdamp_inverse
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_OK, HD_NO_REBOUND, HD_BAD_RESTITUTION, HD_BAD_END, HD_BAD_TIME, &
                                HD_BAD_KPHYS, HD_BAD_ARGUMENT, HD_NO_CONVERGENCE, HD_END_OVERLAP, HD_END_FORCE
    use hertzdamp_scaling, only: hertzdamp_check_positive, hertzdamp_expand, hertzdamp_safe_exp
    use hertzdamp_rk45, only: hertzdamp_collision, hertzdamp_rk45_collide
    use hertzdamp_methods, only: HD_METHOD_FIT, HD_METHOD_ITERATIVE
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    public :: hertzdamp_invert

contains

    !> k and d that give restitution e and contact time tc for mass m and impact
    !> velocity u (THEORY.md section 6), with the optional physical bound k_phys.
    pure elemental subroutine hertzdamp_invert(e, tc, m, u, iend, k, d, status, alpha, tstar, tau_c, &
                                               bound_active, k_phys, method, tol)
        real(wp), intent(in) :: e                      !! target restitution coefficient
        real(wp), intent(in) :: tc                     !! target contact time [s]
        real(wp), intent(in) :: m                      !! effective mass [kg]
        real(wp), intent(in) :: u                      !! impact velocity [m s^-1]
        integer, intent(in) :: iend                    !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out) :: k                     !! Hertz stiffness [N m^-3/2]
        real(wp), intent(out) :: d                     !! damping coefficient [kg s^-1]
        integer, intent(out) :: status                 !! HD_OK or an error code
        real(wp), intent(out), optional :: alpha       !! damping parameter alpha(e)
        real(wp), intent(out), optional :: tstar       !! time unit t* [s] of the contact
        real(wp), intent(out), optional :: tau_c       !! dimensionless contact time tau_c(alpha)
        logical, intent(out), optional :: bound_active !! true when k = k_phys was used
        real(wp), intent(in), optional :: k_phys       !! physical stiffness bound [N m^-3/2]
        integer, intent(in), optional :: method        !! HD_METHOD_* (all answered iteratively here)
        real(wp), intent(in), optional :: tol          !! relative tolerance on e (default 1e-10)
        real(wp) :: a, tau, ts, tol_, lts
        logical :: bound
        integer :: meth
        k = 0.0_wp
        d = 0.0_wp
        a = 0.0_wp
        tau = 0.0_wp
        ts = 0.0_wp
        bound = .false.
        meth = HD_METHOD_FIT
        if (present(method)) meth = method
        tol_ = 1.0e-10_wp
        if (present(tol)) tol_ = tol
        status = HD_OK
        if (meth < 1 .or. meth > HD_METHOD_ITERATIVE) status = HD_BAD_ARGUMENT
        if (iend /= HD_END_OVERLAP .and. iend /= HD_END_FORCE) status = HD_BAD_END
        if (status == HD_OK) status = hertzdamp_check_positive(e, HD_BAD_RESTITUTION)
        if (status == HD_OK .and. e > 1.0_wp) status = HD_BAD_RESTITUTION
        if (status == HD_OK) status = hertzdamp_check_positive(tc, HD_BAD_TIME)
        if (status == HD_OK .and. .not. (tol_ >= 1.0e-14_wp .and. tol_ <= 1.0e-2_wp)) status = HD_BAD_ARGUMENT
        if (status == HD_OK .and. present(k_phys)) status = hertzdamp_check_positive(k_phys, HD_BAD_KPHYS)
        if (status == HD_OK) call alpha_of_e(e, iend, tol_, a, tau, status)
        if (status == HD_OK) then
            ts = tc / tau
            call hertzdamp_expand(a, ts, m, u, k, d, status)
        end if
        if (status == HD_OK .and. present(k_phys)) then
            if (k_phys <= k) then
                bound = .true.
                k = k_phys
                lts = 0.4_wp * log(m) - 0.4_wp * log(k_phys) - 0.2_wp * log(u)
                call hertzdamp_safe_exp(lts, ts, status)
                d = 0.0_wp
                if (a > 0.0_wp) call hertzdamp_safe_exp(log(a) + log(m) - lts, d, status)
            end if
        end if
        if (status /= HD_OK) then
            k = 0.0_wp
            d = 0.0_wp
            a = 0.0_wp
            tau = 0.0_wp
            ts = 0.0_wp
            bound = .false.
        end if
        if (present(alpha)) alpha = a
        if (present(tstar)) tstar = ts
        if (present(tau_c)) tau_c = tau
        if (present(bound_active)) bound_active = bound
    end subroutine hertzdamp_invert

    !> alpha with e(alpha) = e by a secant step kept inside a shrinking bracket
    !> (bisection when the secant step leaves it); tau_c at that alpha.
    pure subroutine alpha_of_e(e, iend, tol, a, tau, status)
        real(wp), intent(in) :: e, tol
        integer, intent(in) :: iend
        real(wp), intent(out) :: a, tau
        integer, intent(out) :: status
        real(wp) :: lo, hi, flo, fhi, x, fx, rtol, xp, fp, xn
        type(hertzdamp_collision) :: r
        integer :: it
        rtol = max(1.0e-14_wp, min(1.0e-8_wp, 1.0e-2_wp * tol))
        a = 0.0_wp
        tau = 0.0_wp
        status = HD_OK
        lo = 0.0_wp
        flo = 1.0_wp - e
        r = hertzdamp_rk45_collide(0.0_wp, iend, rtol)
        if (abs(flo) <= tol * e) then
            a = 0.0_wp
            tau = r%tau_c
            status = r%status
            return
        end if
        hi = 0.5_wp
        do it = 1, 60
            r = hertzdamp_rk45_collide(hi, iend, rtol)
            if (r%status == HD_NO_REBOUND) then
                fhi = -e
            else if (r%status /= HD_OK) then
                status = r%status
                return
            else
                fhi = r%e - e
            end if
            if (fhi < 0.0_wp) exit
            lo = hi
            flo = fhi
            hi = merge(0.5_wp * (hi + 1.128_wp), 2.0_wp * hi, iend == HD_END_OVERLAP)
        end do
        if (fhi >= 0.0_wp) then
            status = HD_BAD_RESTITUTION
            return
        end if
        x = lo + (hi - lo) * flo / (flo - fhi)
        xp = hi
        fp = fhi
        do it = 1, 200
            if (.not. (x > lo .and. x < hi) .or. .not. ieee_is_finite(x)) x = 0.5_wp * (lo + hi)
            r = hertzdamp_rk45_collide(x, iend, rtol)
            if (r%status == HD_NO_REBOUND) then
                fx = -e
            else if (r%status /= HD_OK) then
                status = r%status
                return
            else
                fx = r%e - e
            end if
            if (fx > 0.0_wp) then
                lo = x
                flo = fx
            else
                hi = x
                fhi = fx
            end if
            if (abs(fx) <= tol * e .and. r%status == HD_OK) then
                a = x
                tau = r%tau_c
                return
            end if
            if (hi - lo <= 4.0_wp * epsilon(1.0_wp) * hi) exit
            xn = x - fx * (x - xp) / (fx - fp)
            xp = x
            fp = fx
            x = xn
        end do
        status = HD_NO_CONVERGENCE
    end subroutine alpha_of_e

end module hertzdamp_inverse
