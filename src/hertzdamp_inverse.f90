!> TEMPORARY stand-in, replaced by the fit-based module on merge.
!>
!> The inverse problem of THEORY.md section 6 with the final signature of
!> `hertzdamp_invert`, implemented correctly but slowly: alpha(e) by a safeguarded
!> regula falsi (Illinois) on ln e(alpha) over reference-integrator solves, then
!> tau_c(alpha), t* = T_c / tau_c, k = m t*^(-5/2) u^(-1/2), d = alpha m / t*.
!> Every method code is accepted and computed this same way.  It exists only so that
!> the legacy and C entry points can be built and tested before the fit lands.
module hertzdamp_inverse
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_OK, HD_NO_REBOUND, HD_BAD_END, HD_BAD_TOL, HD_BAD_MASS, &
                                HD_BAD_VELOCITY, HD_BAD_TIME, HD_BAD_RESTITUTION, HD_BAD_KPHYS, &
                                HD_BAD_ARGUMENT, HD_NO_CONVERGENCE, HD_END_OVERLAP, HD_END_FORCE
    use hertzdamp_scaling, only: hertzdamp_expand, hertzdamp_check_positive, hertzdamp_safe_exp
    use hertzdamp_rk45, only: hertzdamp_collision, hertzdamp_rk45_collide, &
                              hertzdamp_rk45_default_tol
    use hertzdamp_methods, only: HD_METHOD_RK45, HD_METHOD_ITERATIVE, HD_METHOD_FIT
    use hertzdamp_constants, only: hertzdamp_e1
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Upper end of the alpha search: above alpha_c = 1.12799 (overlap), and the largest
    !> alpha the library supports (force).
    real(wp), parameter :: alpha_hi_overlap = 1.2_wp
    real(wp), parameter :: alpha_hi_force = 1.0e4_wp
    integer, parameter :: max_iter = 200

    public :: hertzdamp_invert

contains

    !> Stiffness and damping that give restitution `e` and contact time `tc` for a
    !> contact of mass `m` hit at speed `u` (THEORY.md section 6).  On failure k = d = 0.
    pure elemental subroutine hertzdamp_invert(e, tc, m, u, iend, k, d, status, alpha, tstar, &
                                               tau_c, bound_active, k_phys, method, tol)
        real(wp), intent(in) :: e                  !! target restitution coefficient, in (0, 1]
        real(wp), intent(in) :: tc                 !! target contact time [s]
        real(wp), intent(in) :: m                  !! effective mass [kg]
        real(wp), intent(in) :: u                  !! impact velocity [m s^-1]
        integer, intent(in) :: iend                !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out) :: k                 !! Hertz stiffness [N m^-3/2]
        real(wp), intent(out) :: d                 !! damping coefficient [kg s^-1]
        integer, intent(out) :: status             !! HD_OK or an error code
        real(wp), intent(out), optional :: alpha   !! damping parameter alpha(e)
        real(wp), intent(out), optional :: tstar   !! time unit t* of the returned k [s]
        real(wp), intent(out), optional :: tau_c   !! dimensionless contact time tau_c(alpha)
        logical, intent(out), optional :: bound_active !! true when k_phys <= k replaced k
        real(wp), intent(in), optional :: k_phys   !! physical stiffness bound [N m^-3/2]
        integer, intent(in), optional :: method    !! HD_METHOD_* (default HD_METHOD_FIT)
        real(wp), intent(in), optional :: tol      !! integrator tolerance (default 1e-13)
        real(wp) :: a, tau, ts, tol_
        integer :: method_
        logical :: bound

        k = 0.0_wp
        d = 0.0_wp
        a = 0.0_wp
        tau = 0.0_wp
        ts = 0.0_wp
        bound = .false.
        if (present(alpha)) alpha = 0.0_wp
        if (present(tstar)) tstar = 0.0_wp
        if (present(tau_c)) tau_c = 0.0_wp
        if (present(bound_active)) bound_active = .false.
        method_ = HD_METHOD_FIT
        if (present(method)) method_ = method
        tol_ = hertzdamp_rk45_default_tol
        if (present(tol)) tol_ = tol

        status = HD_OK
        if (iend /= HD_END_OVERLAP .and. iend /= HD_END_FORCE) then
            status = HD_BAD_END
        else if (method_ < HD_METHOD_RK45 .or. method_ > HD_METHOD_ITERATIVE) then
            status = HD_BAD_ARGUMENT
        else if (.not. (tol_ >= 1.0e-15_wp .and. tol_ <= 1.0e-2_wp)) then
            status = HD_BAD_TOL
        else if (.not. (e > 0.0_wp .and. e <= 1.0_wp)) then
            status = HD_BAD_RESTITUTION
        end if
        if (status == HD_OK) status = hertzdamp_check_positive(tc, HD_BAD_TIME)
        if (status == HD_OK) status = hertzdamp_check_positive(m, HD_BAD_MASS)
        if (status == HD_OK) status = hertzdamp_check_positive(u, HD_BAD_VELOCITY)
        if (status == HD_OK .and. present(k_phys)) then
          status = hertzdamp_check_positive(k_phys, HD_BAD_KPHYS)
        end if
        if (status /= HD_OK) return

        call solve_alpha(e, iend, tol_, a, tau, status)
        if (status /= HD_OK) return
        ts = tc / tau
        call hertzdamp_expand(a, ts, m, u, k, d, status)
        if (status /= HD_OK) return
        if (present(k_phys)) then
            if (k_phys <= k) then
                bound = .true.
                k = k_phys
                call hertzdamp_safe_exp(0.4_wp * log(m) - 0.4_wp * log(k_phys) - 0.2_wp * log(u), ts, &
                                        status)
                d = 0.0_wp
                if (a > 0.0_wp) call hertzdamp_safe_exp(log(a) + log(m) - log(ts), d, status)
                if (status /= HD_OK) then
                    k = 0.0_wp
                    d = 0.0_wp
                    return
                end if
            end if
        end if
        if (present(alpha)) alpha = a
        if (present(tstar)) tstar = ts
        if (present(tau_c)) tau_c = tau
        if (present(bound_active)) bound_active = bound
    end subroutine hertzdamp_invert

    !> alpha with e(alpha) = e_target and tau_c(alpha), by Illinois regula falsi on
    !> g(alpha) = ln e(alpha) - ln e_target (decreasing in alpha), bisection while the
    !> upper end has no rebound.
    pure subroutine solve_alpha(e_target, iend, tol, alpha, tau, status)
        real(wp), intent(in) :: e_target   !! target restitution, in (0, 1]
        integer, intent(in) :: iend        !! contact-end definition
        real(wp), intent(in) :: tol        !! integrator tolerance
        real(wp), intent(out) :: alpha     !! the damping parameter found
        real(wp), intent(out) :: tau       !! tau_c(alpha)
        integer, intent(out) :: status     !! HD_OK or an error code
        type(hertzdamp_collision) :: r
        real(wp) :: lo, hi, glo, ghi, g, x, lnt, best_g
        logical :: hi_finite
        integer :: it, side

        alpha = 0.0_wp
        tau = 0.0_wp
        lnt = log(e_target)
        r = hertzdamp_rk45_collide(0.0_wp, iend, tol)
        status = r%status
        if (status /= HD_OK) return
        tau = r%tau_c
        if (e_target >= 1.0_wp) return

        lo = 0.0_wp
        glo = -lnt
        hi_finite = .false.
        ghi = 0.0_wp
        if (iend == HD_END_OVERLAP) then
            hi = alpha_hi_overlap
        else
            ! expand until the restitution falls below the target
            hi = min(-lnt / hertzdamp_e1(), alpha_hi_force)
            do
                r = hertzdamp_rk45_collide(hi, iend, tol)
                status = r%status
                if (status /= HD_OK) return
                g = log(r%e) - lnt
                if (g <= 0.0_wp) exit
                lo = hi
                glo = g
                if (hi >= alpha_hi_force) then
                    status = HD_BAD_RESTITUTION
                    return
                end if
                hi = min(4.0_wp * hi, alpha_hi_force)
            end do
            ghi = g
            hi_finite = .true.
        end if

        x = min(-lnt / hertzdamp_e1(), 0.5_wp * (lo + hi))
        side = 0
        best_g = huge(1.0_wp)
        status = HD_NO_CONVERGENCE
        do it = 1, max_iter
            r = hertzdamp_rk45_collide(x, iend, tol)
            if (r%status == HD_NO_REBOUND) then
                hi = x
                hi_finite = .false.
            else if (r%status /= HD_OK) then
                status = r%status
                return
            else
                g = log(r%e) - lnt
                if (abs(g) < best_g) then
                    best_g = abs(g)
                    alpha = x
                    tau = r%tau_c
                end if
                if (abs(g) <= tol) then
                    status = HD_OK
                    exit
                end if
                if (g > 0.0_wp) then
                    lo = x
                    glo = g
                    if (side == -1) ghi = 0.5_wp * ghi
                    side = -1
                else
                    hi = x
                    ghi = g
                    hi_finite = .true.
                    if (side == 1) glo = 0.5_wp * glo
                    side = 1
                end if
            end if
            if (hi - lo <= 4.0_wp * epsilon(1.0_wp) * hi) then
                if (best_g < huge(1.0_wp)) status = HD_OK
                exit
            end if
            if (hi_finite) then
                x = (lo * ghi - hi * glo) / (ghi - glo)
                if (.not. (x > lo .and. x < hi)) x = 0.5_wp * (lo + hi)
            else
                x = 0.5_wp * (lo + hi)
            end if
        end do
        if (status /= HD_OK) then
            alpha = 0.0_wp
            tau = 0.0_wp
        else if (.not. ieee_is_finite(tau)) then
            status = HD_NO_REBOUND
        end if
    end subroutine solve_alpha

end module hertzdamp_inverse
