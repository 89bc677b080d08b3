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
!> - method `fit`: the exact derivative of the library's machine-precision approximant
!>   (hertzdamp_fit, hertzdamp_fit_laws): its piecewise polynomials differentiated
!>   (Horner with derivative) and composed with the change of variable of each block
!>   (alpha, w = -ln(1 - alpha/alpha_c), alpha^(1/3), L = -ln e, L^(1/5),
!>   ln(1 + alpha^(1/2))), and the derivative of the tsuji closed forms; the values
!>   are the core's own, so value and derivative belong to one function;
!> - method `rk45` (for checking): differences of the reference integrator, central
!>   with steps h = 1e-4 max(alpha, 1e-2) and h/2 and Richardson extrapolation
!>   (one-sided near a limit of the law); the optimum of a fit does not depend on
!>   the derivative, only the speed of convergence and the uncertainties do.
!>
!> No module state, nothing printed: a status (HD_*) says what went wrong.
module hertzdamp_calibrate_maps
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_OK, HD_NO_REBOUND, HD_BAD_END, HD_BAD_ALPHA, HD_OUT_OF_RANGE, &
                                HD_END_OVERLAP, HD_END_FORCE, HD_BAD_ARGUMENT
    use hertzdamp_methods, only: HD_METHOD_FIT, HD_METHOD_RK45, hertzdamp_forward_alpha
    use hertzdamp_rk45, only: hertzdamp_collision, hertzdamp_rk45_default_tol
    use hertzdamp_laws, only: CAL_LAW_LINEAR => HD_DAMPING_LINEAR, CAL_LAW_TSUJI => HD_DAMPING_TSUJI, &
                              CAL_LAW_KUWABARA_KONO => HD_DAMPING_KUWABARA_KONO, cal_max_law => hertzdamp_max_law, &
                              cal_law_name => hertzdamp_law_name, cal_law_code => hertzdamp_law_code, &
                              cal_law_q => hertzdamp_law_q, cal_law_speed_exponent => hertzdamp_law_speed_exponent, &
                              hertzdamp_law_status, hertzdamp_alpha_c_tsuji
    use hertzdamp_fit_laws, only: hertzdamp_fit_law_forward
    use hertzdamp_fit_data, only: fit_alpha_c, fit_alpha_max_force, fit_ov_fwd_lw_slope, fit_ov_fwd_tw_slope, &
                                  ov_fwd_la_c, ov_fwd_la_x0, ov_fwd_la_x1, ov_fwd_la_scale, ov_fwd_la_np, &
                                  ov_fwd_ta_c, ov_fwd_ta_x0, ov_fwd_ta_scale, ov_fwd_ta_np, &
                                  ov_fwd_lw_c, ov_fwd_lw_x0, ov_fwd_lw_x1, ov_fwd_lw_scale, ov_fwd_lw_np, &
                                  ov_fwd_tw_c, ov_fwd_tw_x0, ov_fwd_tw_scale, ov_fwd_tw_np, &
                                  fo_fwd_la_c, fo_fwd_la_x0, fo_fwd_la_scale, fo_fwd_la_np, &
                                  fo_fwd_ta_c, fo_fwd_ta_x0, fo_fwd_ta_scale, fo_fwd_ta_np, &
                                  ts_ov_inv_t_c, ts_ov_inv_t_x0, ts_ov_inv_t_scale, ts_ov_inv_t_np, &
                                  ts_fo_inv_t_c, ts_fo_inv_t_x0, ts_fo_inv_t_scale, ts_fo_inv_t_np, &
                                  kk_ov_fwd_la_c, kk_ov_fwd_la_x0, kk_ov_fwd_la_scale, kk_ov_fwd_la_np, &
                                  kk_ov_fwd_ta_c, kk_ov_fwd_ta_x0, kk_ov_fwd_ta_scale, kk_ov_fwd_ta_np, &
                                  kk_fo_fwd_la_c, kk_fo_fwd_la_x0, kk_fo_fwd_la_scale, kk_fo_fwd_la_np, &
                                  kk_fo_fwd_ta_c, kk_fo_fwd_ta_x0, kk_fo_fwd_ta_scale, kk_fo_fwd_ta_np
    use, intrinsic :: iso_c_binding, only: c_double
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk
    real(wp), parameter :: pi = acos(-1.0_wp)

    ! the law codes, names and exponents are the core's (hertzdamp_laws)
    public :: CAL_LAW_LINEAR, CAL_LAW_TSUJI, CAL_LAW_KUWABARA_KONO, cal_max_law
    public :: cal_law_name, cal_law_code, cal_law_q, cal_law_speed_exponent
    public :: cal_law_supported, cal_forward

    interface
        !> C99 cube root (libm), the same as the core fit uses.
        pure function c_cbrt(x) bind(C, name='cbrt') result(y)
            import :: c_double
            implicit none
            real(c_double), value :: x
            real(c_double) :: y
        end function c_cbrt
    end interface

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
    !> status HD_OK; HD_NO_REBOUND (overlap, alpha >= alpha_c of the law), the fit's
    !> HD_OUTSIDE_VALIDITY (e < 1e-5) and every other failure give zero outputs.
    !> tol: rk45 tolerance (default 1e-13).
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
        real(wp) :: tol_, dl
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
            call hertzdamp_fit_law_forward(alpha, iend, law, e, tau_c, status)
            if (status == HD_OK) then
                select case (law)
                case (CAL_LAW_LINEAR)
                    call fit_linear_d(alpha, iend, dl, dtau, status)
                case (CAL_LAW_TSUJI)
                    call fit_tsuji_d(alpha, iend, e, dl, dtau, status)
                case default
                    call fit_kuwabara_kono_d(alpha, iend, dl, dtau, status)
                end select
                de = -e * dl
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

    !> Value and derivative at x of a generated block (the layout of hertzdamp_fit_data:
    !> piece i = min(int(u), np - 1) of u = max(0, (x - x0) scale), Horner in
    !> t = 2 (u - i) - 1); dy is dy/dx.
    pure subroutine block_d(c, x0, scale, np, x, y, dy)
        real(wp), intent(in) :: c(0:, 0:)   !! monomial coefficients (0:deg, 0:np-1)
        real(wp), intent(in) :: x0, scale   !! grid of the block
        integer, intent(in) :: np           !! number of pieces
        real(wp), intent(in) :: x           !! variable
        real(wp), intent(out) :: y, dy      !! value and derivative in x
        real(wp) :: u, t
        integer :: i, j
        u = max(0.0_wp, (x - x0) * scale)
        i = min(int(u), np - 1)
        t = 2.0_wp * (u - real(i, wp)) - 1.0_wp
        y = c(ubound(c, 1), i)
        dy = 0.0_wp
        do j = ubound(c, 1) - 1, 0, -1
            dy = dy * t + y
            y = y * t + c(j, i)
        end do
        dy = dy * 2.0_wp * scale
        if ((x - x0) * scale < 0.0_wp) dy = 0.0_wp   ! clamped to the start of the block
    end subroutine block_d

    !> dL/dalpha (L = -ln e) and dtau_c/dalpha of the linear law's fit (hertzdamp_fit):
    !> overlap, alpha <= 0.6: L = alpha P(alpha), tau_c = T(alpha); beyond: L = P(w),
    !> tau_c = T(w), w = -ln(1 - alpha/alpha_c), linear in w past the last piece;
    !> force: L = alpha P(x), tau_c = T(x), x = alpha^(1/3).
    pure subroutine fit_linear_d(alpha, iend, dl, dtau, status)
        real(wp), intent(in) :: alpha
        integer, intent(in) :: iend
        real(wp), intent(out) :: dl, dtau
        integer, intent(out) :: status
        real(wp) :: p, dp, y, dy, w, dw, x
        status = HD_OK
        if (iend == HD_END_OVERLAP) then
            if (alpha <= ov_fwd_la_x1) then
                call block_d(ov_fwd_la_c, ov_fwd_la_x0, ov_fwd_la_scale, ov_fwd_la_np, alpha, p, dp)
                dl = p + alpha * dp
                call block_d(ov_fwd_ta_c, ov_fwd_ta_x0, ov_fwd_ta_scale, ov_fwd_ta_np, alpha, y, dtau)
            else
                w = -log(1.0_wp - alpha / fit_alpha_c)
                dw = 1.0_wp / (fit_alpha_c - alpha)
                if (w <= ov_fwd_lw_x1) then
                    call block_d(ov_fwd_lw_c, ov_fwd_lw_x0, ov_fwd_lw_scale, ov_fwd_lw_np, w, p, dp)
                    call block_d(ov_fwd_tw_c, ov_fwd_tw_x0, ov_fwd_tw_scale, ov_fwd_tw_np, w, y, dy)
                    dl = dp * dw
                    dtau = dy * dw
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
            call block_d(fo_fwd_la_c, fo_fwd_la_x0, fo_fwd_la_scale, fo_fwd_la_np, x, p, dp)
            call block_d(fo_fwd_ta_c, fo_fwd_ta_x0, fo_fwd_ta_scale, fo_fwd_ta_np, x, y, dy)
            ! dx/dalpha = 1/(3 x^2) = x/(3 alpha)
            dl = p + x * dp / 3.0_wp
            dtau = dy / (3.0_wp * x * x)
        end if
    end subroutine fit_linear_d

    !> dL/dalpha and dtau_c/dalpha of the tsuji law (hertzdamp_fit_laws).  With
    !> a = 2 alpha/5 and W^2 = 4/5 - a^2 the closed forms are L = pi a/W (overlap) and
    !> L = 2 f(x), x = W^2/a^2 = 0.8/a^2 - 1, f(x) = atan(sqrt x)/sqrt x (atanh for x < 0)
    !> (force), so dL/da = 0.8 pi/W^3 and 2 f'(x) dx/da with f'(x) = (1/(1+x) - f)/(2x)
    !> (its series near x = 0).  tau_c = T(L) (overlap), T(L^(1/5)) (force).
    pure subroutine fit_tsuji_d(alpha, iend, e, dl, dtau, status)
        real(wp), intent(in) :: alpha, e
        integer, intent(in) :: iend
        real(wp), intent(out) :: dl, dtau
        integer, intent(out) :: status
        real(wp) :: a, w2, l, y, dy, xi
        status = HD_OK
        a = 0.4_wp * alpha
        w2 = 0.16_wp * (hertzdamp_alpha_c_tsuji - alpha) * (hertzdamp_alpha_c_tsuji + alpha)
        l = 0.0_wp - log(e)
        if (iend == HD_END_OVERLAP) then
            dl = 0.4_wp * 0.8_wp * pi / (w2 * sqrt(w2))
            call block_d(ts_ov_inv_t_c, ts_ov_inv_t_x0, ts_ov_inv_t_scale, ts_ov_inv_t_np, l, y, dy)
            dtau = dy * dl
        else
            dl = 0.4_wp * 2.0_wp * f_prime(a, w2) * (-1.6_wp / a**3)
            xi = l**0.2_wp
            call block_d(ts_fo_inv_t_c, ts_fo_inv_t_x0, ts_fo_inv_t_scale, ts_fo_inv_t_np, xi, y, dy)
            dtau = dy * 0.2_wp * xi / l * dl   ! d(L^(1/5))/dL = L^(1/5)/(5 L)
        end if
    end subroutine fit_tsuji_d

    !> f'(x) for f(x) = atan(sqrt x)/sqrt x (x > 0), atanh(sqrt(-x))/sqrt(-x) (-1 < x < 0),
    !> x = w2/a^2, 1 + x = 0.8/a^2: (1/(1+x) - f)/(2x), with atanh(V/a) = ln((a + V)/sqrt(0.8))
    !> (V^2 = -w2, free of cancellation), and the series sum_{n>=1} (-1)^n n x^(n-1)/(2n+1)
    !> for |x| < 0.1.
    pure real(wp) function f_prime(a, w2) result(fp)
        real(wp), intent(in) :: a, w2
        real(wp) :: x, f, s, xn
        integer :: n
        x = w2 / (a * a)
        if (abs(x) < 0.1_wp) then
            fp = 0.0_wp
            xn = 1.0_wp
            do n = 1, 30
                fp = fp + (-1)**n * n * xn / (2 * n + 1)
                xn = xn * x
            end do
        else
            if (x > 0.0_wp) then
                s = sqrt(x)
                f = atan(s) / s
            else
                s = sqrt(-w2)
                f = a * log((a + s) / sqrt(0.8_wp)) / s
            end if
            fp = (a * a / 0.8_wp - f) / (2.0_wp * x)
        end if
    end function f_prime

    !> dL/dalpha and dtau_c/dalpha of the kuwabara-kono fit (hertzdamp_fit_laws):
    !> overlap L = alpha P(alpha), tau_c = T(alpha); force L = alpha P(x), tau_c = T(x),
    !> x = ln(1 + alpha^(1/2)), dx/dalpha = 1/(2 alpha^(1/2) (1 + alpha^(1/2))).
    pure subroutine fit_kuwabara_kono_d(alpha, iend, dl, dtau, status)
        real(wp), intent(in) :: alpha
        integer, intent(in) :: iend
        real(wp), intent(out) :: dl, dtau
        integer, intent(out) :: status
        real(wp) :: p, dp, y, dy, r, x, dx
        status = HD_OK
        if (iend == HD_END_OVERLAP) then
            call block_d(kk_ov_fwd_la_c, kk_ov_fwd_la_x0, kk_ov_fwd_la_scale, kk_ov_fwd_la_np, alpha, p, dp)
            dl = p + alpha * dp
            call block_d(kk_ov_fwd_ta_c, kk_ov_fwd_ta_x0, kk_ov_fwd_ta_scale, kk_ov_fwd_ta_np, alpha, y, dtau)
        else
            r = sqrt(alpha)
            x = log(1.0_wp + r)
            dx = 1.0_wp / (2.0_wp * r * (1.0_wp + r))
            call block_d(kk_fo_fwd_la_c, kk_fo_fwd_la_x0, kk_fo_fwd_la_scale, kk_fo_fwd_la_np, x, p, dp)
            call block_d(kk_fo_fwd_ta_c, kk_fo_fwd_ta_x0, kk_fo_fwd_ta_scale, kk_fo_fwd_ta_np, x, y, dy)
            dl = p + alpha * dp * dx
            dtau = dy * dx
        end if
    end subroutine fit_kuwabara_kono_d

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
