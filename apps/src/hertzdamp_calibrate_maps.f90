!> The forward maps of the damping laws and their derivatives in alpha, as the
!> calibration fit (hertzdamp_calibrate) needs them: e(alpha), tau_c(alpha),
!> de/dalpha and dtau_c/dalpha for one law, contact end and method.
!>
!> The damping laws m zeta'' = -k zeta^(3/2) - d zeta^q zeta' are named by their
!> exponent q: `linear` (q = 0), `tsuji` (q = 1/4), `kuwabara-kono` (q = 1/2).  In
!> similarity variables alpha = d t* (u t*)^q / m with t* = m^(2/5) k^(-2/5) u^(-1/5),
!> so alpha = A u^s with s = (4q - 1)/5 and A = d m^((2q-3)/5) k^(-2(1+q)/5).
!>
!> Derivatives:
!> - method `fit`: the exact derivative of the machine-precision approximant, i.e. of
!>   its piecewise polynomials (Horner with derivative) composed with the change of
!>   variable of each block (alpha, w = -ln(1 - alpha/alpha_c), alpha^(1/3)); the values
!>   are the core's own (hertzdamp_fit_forward), so fit and derivative agree to round-off;
!> - method `rk45` (for checking): differences of the reference integrator, central
!>   with steps h = 1e-4 max(alpha, 1e-2) and h/2 and Richardson extrapolation
!>   (one-sided near a limit of the law); the optimum of a fit does not depend on
!>   the derivative, only the speed of convergence and the uncertainties do.
!>
!> No module state, nothing printed: a status (HD_*) says what went wrong.
module hertzdamp_calibrate_maps
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_OK, HD_NO_REBOUND, HD_NOT_SUPPORTED, HD_BAD_END, HD_BAD_ALPHA, &
                                HD_OUT_OF_RANGE, HD_END_OVERLAP, HD_END_FORCE, HD_BAD_ARGUMENT
    use hertzdamp_methods, only: HD_METHOD_FIT, HD_METHOD_RK45, hertzdamp_forward_alpha
    use hertzdamp_rk45, only: hertzdamp_collision, hertzdamp_rk45_default_tol
    use hertzdamp_fit, only: hertzdamp_fit_forward
    use hertzdamp_fit_data, only: fit_alpha_c, fit_alpha_max_force, &
                                  fit_ov_fwd_lw_slope, fit_ov_fwd_tw_slope, &
                                  ov_fwd_la_c, ov_fwd_la_x0, ov_fwd_la_x1, ov_fwd_la_scale, ov_fwd_la_np, &
                                  ov_fwd_ta_c, ov_fwd_ta_x0, ov_fwd_ta_scale, ov_fwd_ta_np, &
                                  ov_fwd_lw_c, ov_fwd_lw_x0, ov_fwd_lw_x1, ov_fwd_lw_scale, ov_fwd_lw_np, &
                                  ov_fwd_tw_c, ov_fwd_tw_x0, ov_fwd_tw_scale, ov_fwd_tw_np, &
                                  fo_fwd_la_c, fo_fwd_la_x0, fo_fwd_la_scale, fo_fwd_la_np, &
                                  fo_fwd_ta_c, fo_fwd_ta_x0, fo_fwd_ta_scale, fo_fwd_ta_np
    use, intrinsic :: iso_c_binding, only: c_double
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    ! The codes are those of the core's damping laws (issue 15: HD_DAMPING_*).
    integer, parameter, public :: CAL_LAW_LINEAR = 0        !! constant damping, q = 0
    integer, parameter, public :: CAL_LAW_TSUJI = 1         !! damping ~ zeta^(1/4), q = 1/4
    integer, parameter, public :: CAL_LAW_KUWABARA_KONO = 2 !! damping ~ zeta^(1/2), q = 1/2
    integer, parameter, public :: cal_max_law = 2           !! largest law code

    !> Law names in the order of the CAL_LAW_* constants (the one table of them).
    character(len=13), parameter :: law_table(0:cal_max_law) = [character(len=13) :: &
        'linear', 'tsuji', 'kuwabara-kono']

    interface
        !> C99 cube root (libm), the same as the core fit uses.
        pure function c_cbrt(x) bind(C, name='cbrt') result(y)
            import :: c_double
            implicit none
            real(c_double), value :: x
            real(c_double) :: y
        end function c_cbrt
    end interface

    public :: cal_law_name, cal_law_code, cal_law_q, cal_law_speed_exponent, cal_law_supported
    public :: cal_forward

contains

    !> Name of a law ('linear', 'tsuji', 'kuwabara-kono'; 'unknown' for other codes).
    pure function cal_law_name(law) result(name)
        integer, intent(in) :: law   !! CAL_LAW_*
        character(len=:), allocatable :: name
        if (law >= 0 .and. law <= cal_max_law) then
            name = trim(law_table(law))
        else
            name = 'unknown'
        end if
    end function cal_law_name

    !> Code of a law name (CAL_LAW_*), -1 when the name is not a law.
    pure integer function cal_law_code(name) result(law)
        character(len=*), intent(in) :: name   !! 'linear', 'tsuji' or 'kuwabara-kono'
        integer :: j
        law = -1
        do j = 0, cal_max_law
            if (trim(law_table(j)) == name) law = j
        end do
    end function cal_law_code

    !> Exponent q of the damping force d zeta^q zeta' of a law (0 for unknown codes).
    pure real(wp) function cal_law_q(law) result(q)
        integer, intent(in) :: law   !! CAL_LAW_*
        select case (law)
        case (CAL_LAW_TSUJI); q = 0.25_wp
        case (CAL_LAW_KUWABARA_KONO); q = 0.5_wp
        case default; q = 0.0_wp
        end select
    end function cal_law_q

    !> s = (4q - 1)/5: alpha = A u^s at impact speed u (-1/5, 0, 1/5).
    pure real(wp) function cal_law_speed_exponent(law) result(s)
        integer, intent(in) :: law   !! CAL_LAW_*
        s = (4.0_wp * cal_law_q(law) - 1.0_wp) / 5.0_wp
    end function cal_law_speed_exponent

    !> Whether the library computes this law by this method today (HD_OK) or not
    !> (HD_NOT_SUPPORTED; HD_BAD_ARGUMENT for an unknown law or method).
    pure integer function cal_law_supported(law, method) result(status)
        integer, intent(in) :: law      !! CAL_LAW_*
        integer, intent(in) :: method   !! HD_METHOD_FIT or HD_METHOD_RK45
        status = HD_OK
        if (law < 0 .or. law > cal_max_law) then
            status = HD_BAD_ARGUMENT
        else if (method /= HD_METHOD_FIT .and. method /= HD_METHOD_RK45) then
            status = HD_BAD_ARGUMENT
        else if (law /= CAL_LAW_LINEAR) then
            status = HD_NOT_SUPPORTED   ! the core has the linear law only (issue 15 adds the others)
        end if
    end function cal_law_supported

    !> e, tau_c and their derivatives in alpha for one law, contact end and method.
    !> status HD_OK; HD_NO_REBOUND (overlap, alpha >= alpha_c of the law) and every
    !> other failure give zero outputs.  tol: rk45 tolerance (default 1e-13).
    pure elemental subroutine cal_forward(law, iend, method, alpha, e, tau_c, de, dtau, status, tol)
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
        real(wp) :: tol_
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
        if (method == HD_METHOD_FIT) then
            call fit_linear(alpha, iend, e, tau_c, de, dtau, status)
        else
            call rk45_differences(alpha, iend, tol_, e, tau_c, de, dtau, status)
        end if
        if (status /= HD_OK) then
            e = 0.0_wp
            tau_c = 0.0_wp
            de = 0.0_wp
            dtau = 0.0_wp
        end if
    end subroutine cal_forward

    !> Polynomial and its derivative in t (Horner).
    pure subroutine horner_d(c, t, y, dy)
        real(wp), intent(in) :: c(0:)  !! monomial coefficients
        real(wp), intent(in) :: t      !! local variable
        real(wp), intent(out) :: y     !! value
        real(wp), intent(out) :: dy    !! derivative dy/dt
        integer :: j
        y = c(ubound(c, 1))
        dy = 0.0_wp
        do j = ubound(c, 1) - 1, 0, -1
            dy = dy * t + y
            y = y * t + c(j)
        end do
    end subroutine horner_d

    !> Piece and local variable of x in a block, as the core fit locates them
    !> (hertzdamp_fit: u = max(0, (x - x0) scale), piece min(int(u), np - 1)).
    pure subroutine locate(x, x0, scale, np, i, t)
        real(wp), intent(in) :: x, x0, scale
        integer, intent(in) :: np
        integer, intent(out) :: i
        real(wp), intent(out) :: t
        real(wp) :: u
        u = max(0.0_wp, (x - x0) * scale)
        i = min(int(u), np - 1)
        t = 2.0_wp * (u - real(i, wp)) - 1.0_wp
    end subroutine locate

    !> The fitted forward map of the linear law and its exact derivative.
    !> With L = -ln e: overlap, alpha <= 0.6: L = alpha P(alpha), tau_c = T(alpha);
    !> beyond: L = P(w), tau_c = T(w), w = -ln(1 - alpha/alpha_c) (linear in w past the
    !> last piece); force: L = alpha P(x), tau_c = T(x), x = alpha^(1/3).
    pure subroutine fit_linear(alpha, iend, e, tau_c, de, dtau, status)
        real(wp), intent(in) :: alpha
        integer, intent(in) :: iend
        real(wp), intent(out) :: e, tau_c, de, dtau
        integer, intent(out) :: status
        real(wp) :: p, dp, y, dy, t, dl, w, dw, x
        integer :: i
        de = 0.0_wp
        dtau = 0.0_wp
        call hertzdamp_fit_forward(alpha, iend, e, tau_c, status)
        if (status /= HD_OK) return
        if (iend == HD_END_OVERLAP) then
            if (alpha <= ov_fwd_la_x1) then
                call locate(alpha, ov_fwd_la_x0, ov_fwd_la_scale, ov_fwd_la_np, i, t)
                call horner_d(ov_fwd_la_c(:, i), t, p, dp)
                dl = p + alpha * dp * 2.0_wp * ov_fwd_la_scale
                call locate(alpha, ov_fwd_ta_x0, ov_fwd_ta_scale, ov_fwd_ta_np, i, t)
                call horner_d(ov_fwd_ta_c(:, i), t, y, dy)
                dtau = dy * 2.0_wp * ov_fwd_ta_scale
            else
                w = -log(1.0_wp - alpha / fit_alpha_c)
                dw = 1.0_wp / (fit_alpha_c - alpha)
                if (w <= ov_fwd_lw_x1) then
                    call locate(w, ov_fwd_lw_x0, ov_fwd_lw_scale, ov_fwd_lw_np, i, t)
                    call horner_d(ov_fwd_lw_c(:, i), t, p, dp)
                    dl = dp * 2.0_wp * ov_fwd_lw_scale * dw
                    call locate(w, ov_fwd_tw_x0, ov_fwd_tw_scale, ov_fwd_tw_np, i, t)
                    call horner_d(ov_fwd_tw_c(:, i), t, y, dy)
                    dtau = dy * 2.0_wp * ov_fwd_tw_scale * dw
                else
                    dl = fit_ov_fwd_lw_slope * dw
                    dtau = fit_ov_fwd_tw_slope * dw
                end if
            end if
        else
            if (alpha > fit_alpha_max_force) then
                status = HD_OUT_OF_RANGE
                return
            end if
            x = c_cbrt(alpha)
            call locate(x, fo_fwd_la_x0, fo_fwd_la_scale, fo_fwd_la_np, i, t)
            call horner_d(fo_fwd_la_c(:, i), t, p, dp)
            ! dL/dalpha = P + alpha P'(x) dx/dalpha, dx/dalpha = 1/(3 x^2) = x/(3 alpha)
            dl = p + x * dp * 2.0_wp * fo_fwd_la_scale / 3.0_wp
            call locate(x, fo_fwd_ta_x0, fo_fwd_ta_scale, fo_fwd_ta_np, i, t)
            call horner_d(fo_fwd_ta_c(:, i), t, y, dy)
            dtau = dy * 2.0_wp * fo_fwd_ta_scale / (3.0_wp * x * x)
        end if
        de = -e * dl
    end subroutine fit_linear

    !> The reference integrator and differences in alpha: central differences with
    !> steps h and h/2 combined by Richardson extrapolation (error O(h^4)); where
    !> alpha + h leaves the law's range (no rebound) or alpha - h < 0, the one-sided
    !> three-point formula (error O(h^2)).
    pure subroutine rk45_differences(alpha, iend, tol, e, tau_c, de, dtau, status)
        real(wp), intent(in) :: alpha, tol
        integer, intent(in) :: iend
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
                r(j) = hertzdamp_forward_alpha(alpha + j * 0.5_wp * h, iend, HD_METHOD_RK45, tol=tol)
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
