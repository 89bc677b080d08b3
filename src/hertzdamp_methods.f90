!> One entry point for the forward problem alpha -> (e, tau_c, z_max, tau_max) by
!> any of the library's methods, and the dimensional forward problem
!> (k, d, m, u_in) -> (alpha, t*, e, T_c, zeta_max).
module hertzdamp_methods
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_OK, HD_NO_REBOUND, HD_NOT_SUPPORTED, HD_BAD_ARGUMENT, HD_OUT_OF_RANGE, &
                                HD_END_OVERLAP, HD_END_FORCE, HD_OUTSIDE_VALIDITY, HD_BAD_ORDER, HD_BAD_END
    use hertzdamp_series, only: hertzdamp_series_eval, hertzdamp_pade_eval, HERTZDAMP_SERIES_OK, &
                                HERTZDAMP_SERIES_INACCURATE, HERTZDAMP_SERIES_BAD_ORDER
    use hertzdamp_scaling, only: hertzdamp_reduce
    use hertzdamp_rk45, only: hertzdamp_collision, hertzdamp_rk45_collide, hertzdamp_rk45_default_tol
    use hertzdamp_fit, only: hertzdamp_fit_forward
    use hertzdamp_compact, only: hertzdamp_compact_forward
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    integer, parameter, public :: HD_METHOD_RK45 = 1     !! adaptive Dormand-Prince reference
    integer, parameter, public :: HD_METHOD_SERIES = 2   !! truncated Taylor series in alpha
    integer, parameter, public :: HD_METHOD_PADE = 3     !! Pade summation of the series
    integer, parameter, public :: HD_METHOD_COMPACT = 4  !! closed-form engineering formula
    integer, parameter, public :: HD_METHOD_FIT = 5      !! machine-precision approximant
    integer, parameter, public :: HD_METHOD_ITERATIVE = 6 !! inverse only: secant iteration over rk45 solves

    !> Method names in the order of the HD_METHOD_* constants.
    character(len=*), parameter, public :: hertzdamp_method_names = 'rk45 series pade compact fit iterative'

    public :: hertzdamp_forward_alpha, hertzdamp_forward_dim

contains

    !> e, tau_c, z_max, tau_max for one alpha by the chosen method.
    pure elemental function hertzdamp_forward_alpha(alpha, iend, method, tol, order) result(res)
        real(wp), intent(in) :: alpha            !! damping parameter
        integer, intent(in) :: iend              !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: method            !! HD_METHOD_*
        real(wp), intent(in), optional :: tol    !! rk45 tolerance
        integer, intent(in), optional :: order   !! series truncation order
        type(hertzdamp_collision) :: res
        real(wp) :: tol_
        integer :: st
        tol_ = hertzdamp_rk45_default_tol
        if (present(tol)) tol_ = tol
        select case (method)
        case (HD_METHOD_RK45)
            res = hertzdamp_rk45_collide(alpha, iend, tol_)
        case (HD_METHOD_FIT)
            ! z_max and tau_max are fitted too (0 beyond alpha = 1.3 for the overlap)
            res%alpha = alpha
            res%iend = iend
            call hertzdamp_fit_forward(alpha, iend, res%e, res%tau_c, res%status, res%z_max, res%tau_max)
        case (HD_METHOD_COMPACT)
            ! the compact formulas give e and tau_c only (z_max = tau_max = 0)
            res%alpha = alpha
            res%iend = iend
            call hertzdamp_compact_forward(alpha, iend, res%e, res%tau_c, res%status)
        case (HD_METHOD_SERIES, HD_METHOD_PADE)
            res%alpha = alpha
            res%iend = iend
            if (iend /= HD_END_OVERLAP) then
                ! the force definition is not analytic at alpha = 0 (doc/series.md)
                res%status = merge(HD_NOT_SUPPORTED, HD_BAD_END, iend == HD_END_FORCE)
                return
            end if
            if (method == HD_METHOD_SERIES) then
                call hertzdamp_series_eval(alpha, res%e, res%tau_c, res%z_max, res%tau_max, order=order, status=st)
            else
                call hertzdamp_pade_eval(alpha, res%e, res%tau_c, res%z_max, res%tau_max, status=st)
            end if
            select case (st)
            case (HERTZDAMP_SERIES_OK, HERTZDAMP_SERIES_INACCURATE)
                res%status = HD_OK
                ! a truncated series far from alpha = 0 can give a meaningless value
                if (.not. (res%e > 0.0_wp .and. res%tau_c > 0.0_wp)) res%status = HD_OUTSIDE_VALIDITY
            case (HERTZDAMP_SERIES_BAD_ORDER)
                res%status = HD_BAD_ORDER
            case default
                res%status = HD_OUTSIDE_VALIDITY
            end select
            if (res%status /= HD_OK) then
                res%e = 0.0_wp
                res%tau_c = 0.0_wp
                res%z_max = 0.0_wp
                res%tau_max = 0.0_wp
            end if
        case default
            res%alpha = alpha
            res%iend = iend
            res%status = HD_BAD_ARGUMENT
        end select
    end function hertzdamp_forward_alpha

    !> The dimensional forward problem.  On no rebound e = 0 and T_c = +inf with
    !> status HD_NO_REBOUND; on any other failure all outputs are 0.
    pure elemental subroutine hertzdamp_forward_dim(k, d, m, u, iend, method, alpha, tstar, e, tc, &
                                                   zeta_max, status, tol, order)
        real(wp), intent(in) :: k                !! Hertz stiffness [N m^-3/2]
        real(wp), intent(in) :: d                !! damping coefficient [kg s^-1]
        real(wp), intent(in) :: m                !! effective mass [kg]
        real(wp), intent(in) :: u                !! impact velocity [m s^-1]
        integer, intent(in) :: iend              !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: method            !! HD_METHOD_*
        real(wp), intent(out) :: alpha           !! damping parameter
        real(wp), intent(out) :: tstar           !! time unit [s]
        real(wp), intent(out) :: e               !! restitution coefficient
        real(wp), intent(out) :: tc              !! contact time [s]
        real(wp), intent(out) :: zeta_max        !! deepest overlap [m]
        integer, intent(out) :: status           !! HD_OK, HD_NO_REBOUND or an error
        real(wp), intent(in), optional :: tol    !! rk45 tolerance
        integer, intent(in), optional :: order   !! series order
        type(hertzdamp_collision) :: r
        e = 0.0_wp
        tc = 0.0_wp
        zeta_max = 0.0_wp
        call hertzdamp_reduce(k, d, m, u, alpha, tstar, status)
        if (status /= HD_OK) return
        r = hertzdamp_forward_alpha(alpha, iend, method, tol, order)
        status = r%status
        if (status /= HD_OK .and. status /= HD_NO_REBOUND) then
            alpha = 0.0_wp
            tstar = 0.0_wp
            return
        end if
        e = r%e
        tc = tstar * r%tau_c
        zeta_max = u * tstar * r%z_max
        if (status == HD_OK .and. .not. (ieee_is_finite(tc) .and. ieee_is_finite(zeta_max))) then
            status = HD_OUT_OF_RANGE
            e = 0.0_wp
            tc = 0.0_wp
            zeta_max = 0.0_wp
            alpha = 0.0_wp
            tstar = 0.0_wp
        end if
    end subroutine hertzdamp_forward_dim

end module hertzdamp_methods
