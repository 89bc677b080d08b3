!> The forward maps of the damping laws and their derivatives in alpha, as the
!> calibration fit (hertzdamp_calibrate) needs them: e(alpha), tau_c(alpha),
!> de/dalpha and dtau_c/dalpha for one law, contact end and method.
!>
!> The damping laws m zeta'' = -k zeta^(3/2) - d zeta^q zeta' (hertzdamp_laws):
!> `linear` (q = 0), `tsuji` (q = 1/4), `kuwabara-kono` (q = 1/2).  In similarity
!> variables alpha = d t* (u t*)^q / m with t* = m^(2/5) k^(-2/5) u^(-1/5), so
!> alpha = A u^s with s = (4q - 1)/5 and A = d m^((2q-3)/5) k^(-2(1+q)/5).
!>
!> Derivatives:
!> - method `fit`: the exact derivative of the library's machine-precision approximant,
!>   from the core (hertzdamp_fit_forward_deriv: its piecewise polynomials differentiated
!>   and composed with the change of variable of each map, the tsuji closed forms
!>   differentiated analytically); value and derivative belong to one function; beyond
!>   the fitted maps (e < 1e-5, the force end beyond the fit's alpha) as with `rk45`;
!> - method `rk45` (for checking): differences of the reference integrator, central
!>   with steps h = 1e-4 max(alpha, 1e-2) and h/2 and Richardson extrapolation
!>   (one-sided near a limit of the law); the optimum of a fit does not depend on
!>   the derivative, only the speed of convergence and the uncertainties do.
!>
!> No module state, nothing printed: a status (HD_*) says what went wrong.
module hertzdamp_calibrate_maps
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_NO_REBOUND, HD_BAD_END, HD_BAD_ALPHA, HD_BAD_ARGUMENT, &
                         HD_OUTSIDE_VALIDITY, HD_END_OVERLAP, HD_END_FORCE, HD_METHOD_FIT, HD_METHOD_RK45, &
                         hertzdamp_forward_alpha, hertzdamp_collision, hertzdamp_rk45_default_tol, &
                         CAL_LAW_LINEAR => HD_DAMPING_LINEAR, CAL_LAW_TSUJI => HD_DAMPING_TSUJI, &
                         CAL_LAW_KUWABARA_KONO => HD_DAMPING_KUWABARA_KONO, cal_max_law => hertzdamp_max_law, &
                         cal_law_name => hertzdamp_law_name, cal_law_code => hertzdamp_law_code, &
                         cal_law_q => hertzdamp_law_q, cal_law_speed_exponent => hertzdamp_law_speed_exponent, &
                         hertzdamp_law_status, hertzdamp_fit_forward_deriv
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    ! the law codes, names and exponents are the core's (hertzdamp_laws)
    public :: CAL_LAW_LINEAR, CAL_LAW_TSUJI, CAL_LAW_KUWABARA_KONO, cal_max_law
    public :: cal_law_name, cal_law_code, cal_law_q, cal_law_speed_exponent
    public :: cal_law_supported, cal_forward

contains

    !> HD_OK for a law and a method the calibration can use (every law: fit and rk45),
    !> HD_BAD_ARGUMENT otherwise.
    pure integer function cal_law_supported(law, method) result(status)
        integer, intent(in) :: law      !! CAL_LAW_*
        integer, intent(in) :: method   !! HD_METHOD_FIT or HD_METHOD_RK45
        status = HD_OK
        if (hertzdamp_law_status(law) /= HD_OK) then
            status = HD_BAD_ARGUMENT
        else if (method /= HD_METHOD_FIT .and. method /= HD_METHOD_RK45) then
            status = HD_BAD_ARGUMENT
        end if
    end function cal_law_supported

    !> e, tau_c and their derivatives in alpha for one law, contact end and method.
    !> With method fit, alpha beyond the fitted maps (e < 1e-5, or the force end beyond
    !> the fit's alpha) is computed as with method rk45, unless `beyond` is false (then
    !> HD_OUTSIDE_VALIDITY: a fit keeps its measurements that lie inside the maps there,
    !> and does not pay for integrations where no measurement is).  status HD_OK;
    !> HD_NO_REBOUND (overlap, alpha >= alpha_c of the law) and every other failure (the
    !> reference integrator's too) give zero outputs.  tol: rk45 tolerance (default 1e-13).
    pure elemental subroutine cal_forward(law, iend, method, alpha, e, tau_c, de, dtau, status, tol, beyond)
        integer, intent(in) :: law            !! CAL_LAW_*
        integer, intent(in) :: iend           !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: method         !! HD_METHOD_FIT or HD_METHOD_RK45
        real(wp), intent(in) :: alpha         !! damping parameter, > 0
        real(wp), intent(out) :: e            !! restitution coefficient
        real(wp), intent(out) :: tau_c        !! dimensionless contact duration
        real(wp), intent(out) :: de           !! de/dalpha
        real(wp), intent(out) :: dtau         !! dtau_c/dalpha
        integer, intent(out) :: status        !! HD_OK or the failure
        real(wp), intent(in), optional :: tol !! rk45 tolerance
        logical, intent(in), optional :: beyond !! method fit: rk45 beyond the fitted maps (default true)
        real(wp) :: tol_
        logical :: beyond_
        e = 0.0_wp
        tau_c = 0.0_wp
        de = 0.0_wp
        dtau = 0.0_wp
        status = cal_law_supported(law, method)
        if (status /= HD_OK) return
        if (iend /= HD_END_OVERLAP .and. iend /= HD_END_FORCE) then
            status = HD_BAD_END
            return
        end if
        if (.not. (alpha > 0.0_wp .and. alpha <= huge(alpha))) then
            status = HD_BAD_ALPHA
            return
        end if
        tol_ = hertzdamp_rk45_default_tol
        if (present(tol)) tol_ = tol
        beyond_ = .true.
        if (present(beyond)) beyond_ = beyond
        if (method == HD_METHOD_FIT) then
            call hertzdamp_fit_forward_deriv(alpha, iend, law, e, tau_c, de, dtau, status)
            ! beyond the fitted maps (e < 1e-5, force alpha beyond the fit's range): the
            ! reference integrator, so that data there are fitted as well, not avoided
            if (status == HD_OUTSIDE_VALIDITY .and. beyond_) then
                call rk45_differences(law, alpha, iend, tol_, e, tau_c, de, dtau, status)
            end if
        else
            call rk45_differences(law, alpha, iend, tol_, e, tau_c, de, dtau, status)
        end if
        if (status /= HD_OK) then
            e = 0.0_wp
            tau_c = 0.0_wp
            de = 0.0_wp
            dtau = 0.0_wp
        end if
    end subroutine cal_forward

    !> The reference integrator and differences in alpha: central differences with
    !> steps h and h/2 combined by Richardson extrapolation (error O(h^4)); where
    !> alpha + h leaves the law's range (no rebound) or alpha - h < 0, the one-sided
    !> three-point formula (error O(h^2)).
    pure subroutine rk45_differences(law, alpha, iend, tol, e, tau_c, de, dtau, status)
        integer, intent(in) :: law, iend
        real(wp), intent(in) :: alpha, tol
        real(wp), intent(out) :: e, tau_c, de, dtau
        integer, intent(out) :: status
        type(hertzdamp_collision) :: r(-2:2)
        real(wp) :: h
        integer :: j
        de = 0.0_wp
        dtau = 0.0_wp
        h = 1.0e-4_wp * max(alpha, 1.0e-2_wp)
        do j = -2, 2
            if (alpha + j * 0.5_wp * h > 0.0_wp) then
                r(j) = hertzdamp_forward_alpha(alpha + j * 0.5_wp * h, iend, HD_METHOD_RK45, tol=tol, law=law)
            else
                r(j)%status = HD_BAD_ALPHA
            end if
        end do
        e = r(0)%e
        tau_c = r(0)%tau_c
        status = r(0)%status
        if (status /= HD_OK) return
        if (all(r(:)%status == HD_OK)) then
            de = richardson(r(:)%e)
            dtau = richardson(r(:)%tau_c)
        else if (r(-1)%status == HD_OK .and. r(-2)%status == HD_OK) then
            de = (3.0_wp * r(0)%e - 4.0_wp * r(-1)%e + r(-2)%e) / h
            dtau = (3.0_wp * r(0)%tau_c - 4.0_wp * r(-1)%tau_c + r(-2)%tau_c) / h
        else if (r(1)%status == HD_OK .and. r(2)%status == HD_OK) then
            de = (-3.0_wp * r(0)%e + 4.0_wp * r(1)%e - r(2)%e) / h
            dtau = (-3.0_wp * r(0)%tau_c + 4.0_wp * r(1)%tau_c - r(2)%tau_c) / h
        else
            status = merge(HD_NO_REBOUND, HD_BAD_ALPHA, r(1)%status == HD_NO_REBOUND)
        end if
    contains
        !> (4 D(h/2) - D(h))/3 from f at alpha + j h/2, j = -2..2.
        pure real(wp) function richardson(f) result(df)
            real(wp), intent(in) :: f(-2:2)
            df = (4.0_wp * (f(1) - f(-1)) / h - (f(2) - f(-2)) / (2.0_wp * h)) / 3.0_wp
        end function richardson
    end subroutine rk45_differences

end module hertzdamp_calibrate_maps
