!> One entry point for the forward problem alpha -> (e, tau_c, z_max, tau_max) by
!> any of the library's methods, and the dimensional forward problem
!> (k, d, m, u_in) -> (alpha, t*, e, T_c, zeta_max).
module hertzdamp_methods
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: HD_METHOD_RK45, HD_METHOD_SERIES, HD_METHOD_PADE, HD_METHOD_COMPACT, HD_METHOD_FIT, &
                                  HD_METHOD_ITERATIVE, HD_METHOD_FIRST_ORDER, hertzdamp_method_name, hertzdamp_method_code
    use hertzdamp_registry, only: HD_OK, HD_NO_REBOUND, HD_NOT_SUPPORTED, HD_BAD_ARGUMENT, HD_OUT_OF_RANGE, &
                                HD_OUTSIDE_VALIDITY, HD_BAD_ORDER, HD_BAD_END, HD_INACCURATE
    use hertzdamp_registry, only: HD_END_OVERLAP, HD_END_FORCE
    use hertzdamp_registry, only: HD_DAMPING_LINEAR
    use hertzdamp_laws, only: hertzdamp_law_status
    use hertzdamp_series, only: hertzdamp_series_eval, hertzdamp_pade_eval
    use hertzdamp_scaling, only: hertzdamp_reduce
    use hertzdamp_rk45, only: hertzdamp_collision, hertzdamp_rk45_collide, hertzdamp_rk45_default_tol
    use hertzdamp_fit, only: hertzdamp_approx_alpha_status
    use hertzdamp_fit_laws, only: hertzdamp_fit_law_forward
    use hertzdamp_constants, only: hertzdamp_e1, hertzdamp_tau_c0
    use hertzdamp_compact, only: hertzdamp_compact_forward
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    ! The method codes and names are rows of data/registry.toml: hertzdamp_registry has them
    ! (and the umbrella exports them).

    !> Default accuracy asked of the series and Pade formulas (relative): where their own
    !> error estimate exceeds it, they answer HD_INACCURATE instead of HD_OK.
    real(wp), parameter, public :: hertzdamp_default_accuracy = 1.0e-10_wp

    public :: hertzdamp_forward_alpha, hertzdamp_forward_dim

contains

    !> e, tau_c, z_max, tau_max for one alpha by the chosen method, for the damping law
    !> `law` (default linear).  Every law: rk45, fit and first-order (e1 of the law); the
    !> other methods exist for the linear law only (HD_NOT_SUPPORTED for the others).
    !> Series and Pade check their own error estimate against `accuracy` (relative,
    !> default hertzdamp_default_accuracy): beyond it the status is HD_INACCURATE;
    !> an accuracy of 1 or more asks for no such check.
    !> On any status but HD_OK and HD_NO_REBOUND the results are 0.
    pure elemental function hertzdamp_forward_alpha(alpha, iend, method, tol, order, accuracy, law) result(res)
        real(wp), intent(in) :: alpha              !! damping parameter
        integer, intent(in) :: iend                !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: method              !! HD_METHOD_*
        real(wp), intent(in), optional :: tol      !! rk45 tolerance
        integer, intent(in), optional :: order     !! series truncation order
        real(wp), intent(in), optional :: accuracy !! relative accuracy asked of series and Pade
        integer, intent(in), optional :: law       !! HD_DAMPING_* (default linear)
        type(hertzdamp_collision) :: res
        res = forward_alpha(alpha, iend, method, .true., tol, order, accuracy, law)
    end function hertzdamp_forward_alpha

    !> hertzdamp_forward_alpha; without `turning` the fit leaves z_max = tau_max = 0
    !> (not computed; the other methods compute them anyway).  e, tau_c and the status
    !> do not depend on `turning`.
    pure elemental function forward_alpha(alpha, iend, method, turning, tol, order, accuracy, law) result(res)
        real(wp), intent(in) :: alpha
        integer, intent(in) :: iend
        integer, intent(in) :: method
        logical, intent(in) :: turning
        real(wp), intent(in), optional :: tol
        integer, intent(in), optional :: order
        real(wp), intent(in), optional :: accuracy
        integer, intent(in), optional :: law
        type(hertzdamp_collision) :: res
        real(wp) :: tol_, acc, err_e, err_tau
        integer :: st, law_
        tol_ = hertzdamp_rk45_default_tol
        if (present(tol)) tol_ = tol
        acc = hertzdamp_default_accuracy
        if (present(accuracy)) acc = accuracy
        law_ = HD_DAMPING_LINEAR
        if (present(law)) law_ = law
        res%law = law_
        if (hertzdamp_law_status(law_) /= HD_OK) then
            res%alpha = alpha
            res%iend = iend
            res%status = hertzdamp_law_status(law_)
            return
        end if
        if (law_ /= HD_DAMPING_LINEAR .and. method /= HD_METHOD_RK45 .and. method /= HD_METHOD_FIRST_ORDER .and. &
            method /= HD_METHOD_FIT) then
            res%alpha = alpha
            res%iend = iend
            res%status = HD_NOT_SUPPORTED
            if (method < HD_METHOD_RK45 .or. method > HD_METHOD_FIRST_ORDER) res%status = HD_BAD_ARGUMENT
            return
        end if
        select case (method)
        case (HD_METHOD_RK45)
            res = hertzdamp_rk45_collide(alpha, iend, tol_, law_)
        case (HD_METHOD_FIT)
            ! z_max and tau_max are fitted too (0 beyond alpha = 1.3 for the overlap)
            res%alpha = alpha
            res%iend = iend
            if (turning) then
                call hertzdamp_fit_law_forward(alpha, iend, law_, res%e, res%tau_c, res%status, res%z_max, res%tau_max)
            else
                call hertzdamp_fit_law_forward(alpha, iend, law_, res%e, res%tau_c, res%status)
            end if
        case (HD_METHOD_COMPACT)
            ! the compact formulas give e and tau_c only (z_max = tau_max = 0)
            res%alpha = alpha
            res%iend = iend
            call hertzdamp_compact_forward(alpha, iend, res%e, res%tau_c, res%status)
        case (HD_METHOD_FIRST_ORDER)
            ! e = 1 - e1 alpha, tau_c = tau_c(0): first order in alpha (z_max, tau_max: not provided)
            res%alpha = alpha
            res%iend = iend
            res%status = hertzdamp_approx_alpha_status(alpha, iend)
            if (res%status == HD_OK) then
                res%e = 1.0_wp - hertzdamp_e1(law_) * alpha
                res%tau_c = hertzdamp_tau_c0()
                if (.not. (res%e > 0.0_wp)) then
                    res%status = HD_OUTSIDE_VALIDITY
                    res%e = 0.0_wp
                    res%tau_c = 0.0_wp
                end if
            end if
        case (HD_METHOD_SERIES, HD_METHOD_PADE)
            res%alpha = alpha
            res%iend = iend
            if (iend /= HD_END_OVERLAP) then
                ! the force definition is not analytic at alpha = 0 (doc/series.md)
                res%status = merge(HD_NOT_SUPPORTED, HD_BAD_END, iend == HD_END_FORCE)
                return
            end if
            if (method == HD_METHOD_SERIES) then
                call hertzdamp_series_eval(alpha, res%e, res%tau_c, res%z_max, res%tau_max, order=order, &
                                           err_e=err_e, err_tau=err_tau, status=st)
            else
                call hertzdamp_pade_eval(alpha, res%e, res%tau_c, res%z_max, res%tau_max, err_e=err_e, &
                                         err_tau=err_tau, status=st)
            end if
            select case (st)
            case (HD_OK, HD_INACCURATE)
                res%status = HD_OK
                ! accuracy >= 1 asks for no guard (and never multiplies a huge value)
                if (acc < 1.0_wp) then
                    if (.not. (err_e <= acc * res%e .and. err_tau <= acc * res%tau_c)) res%status = HD_INACCURATE
                end if
                ! a truncated series far from alpha = 0 can give a meaningless value
                if (.not. (res%e > 0.0_wp .and. res%tau_c > 0.0_wp)) res%status = HD_OUTSIDE_VALIDITY
            case (HD_BAD_ORDER)
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
    end function forward_alpha

    !> The dimensional forward problem (damping force d zeta^q zeta' of the law, default
    !> linear q = 0: d in kg s^-1 m^-q).  On no rebound e = 0 and T_c = +inf with
    !> status HD_NO_REBOUND; on any other failure all outputs are 0.  Without
    !> `zeta_max` the fit does not compute the turning point (the other outputs and the
    !> status are the same bits as with it).
    pure elemental subroutine hertzdamp_forward_dim(k, d, m, u, iend, method, alpha, tstar, e, tc, &
                                                   zeta_max, status, tol, order, accuracy, law)
        real(wp), intent(in) :: k                !! Hertz stiffness [N m^-3/2]
        real(wp), intent(in) :: d                !! damping coefficient [kg s^-1 m^-q] of the law
        real(wp), intent(in) :: m                !! effective mass [kg]
        real(wp), intent(in) :: u                !! impact velocity [m s^-1]
        integer, intent(in) :: iend              !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: method            !! HD_METHOD_*
        real(wp), intent(out) :: alpha           !! damping parameter
        real(wp), intent(out) :: tstar           !! time unit [s]
        real(wp), intent(out) :: e               !! restitution coefficient
        real(wp), intent(out) :: tc              !! contact time [s]
        real(wp), intent(out), optional :: zeta_max !! deepest overlap [m]
        integer, intent(out) :: status           !! HD_OK, HD_NO_REBOUND or an error
        real(wp), intent(in), optional :: tol    !! rk45 tolerance
        integer, intent(in), optional :: order   !! series order
        real(wp), intent(in), optional :: accuracy !! relative accuracy asked of series and Pade
        integer, intent(in), optional :: law     !! HD_DAMPING_* (default linear)
        type(hertzdamp_collision) :: r
        real(wp) :: zm
        e = 0.0_wp
        tc = 0.0_wp
        if (present(zeta_max)) zeta_max = 0.0_wp
        call hertzdamp_reduce(k, d, m, u, alpha, tstar, status, law)
        if (status /= HD_OK) return
        ! the turning point is needed for zeta_max, and for the range check below where
        ! u t* is so large that u t* z_max (|z_max| < 2) might overflow
        r = forward_alpha(alpha, iend, method, present(zeta_max) .or. .not. ieee_is_finite(u * tstar * 2.0_wp), &
                          tol, order, accuracy, law)
        status = r%status
        if (status /= HD_OK .and. status /= HD_NO_REBOUND) then
            alpha = 0.0_wp
            tstar = 0.0_wp
            return
        end if
        e = r%e
        tc = tstar * r%tau_c                     ! +inf without rebound (the documented answer)
        zm = u * tstar * r%z_max
        ! every result but the no-rebound contact time must be a finite double
        if (.not. (ieee_is_finite(zm) .and. (ieee_is_finite(tc) .or. status == HD_NO_REBOUND))) then
            status = HD_OUT_OF_RANGE
            e = 0.0_wp
            tc = 0.0_wp
            zm = 0.0_wp
            alpha = 0.0_wp
            tstar = 0.0_wp
        end if
        if (present(zeta_max)) zeta_max = zm
    end subroutine hertzdamp_forward_dim

end module hertzdamp_methods
