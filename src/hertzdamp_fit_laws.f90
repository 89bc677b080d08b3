!> Machine-precision approximants of the collision maps for every damping law
!> (doc/damping-laws.md), and the exact derivatives of the forward maps.
!>
!> Inverse e -> (alpha, tau_c): the kernels of `hertzdamp_fit` for every law
!> (hertzdamp_fit_inverse with `law`), the same bits as the fast path of
!> hertzdamp_invert and of the C and legacy entry points.
!>
!> Forward alpha -> (e, tau_c[, z_max, tau_max]): the linear law through
!> `hertzdamp_fit_forward`; the tsuji and kuwabara-kono laws here, with the generated
!> maps of `hertzdamp_fit_data` (gen/fit/gen_fit.f90, data/fit_coefficients.csv) and
!> the exact tsuji closed forms.  With L = -ln e:
!> - tsuji, overlap: e(alpha) exactly; tau_c as a polynomial of L (the exact L(alpha));
!> - tsuji, force: e(alpha) exactly (hertzdamp_tsuji_l); tau_c of L^(1/5) (tau_c has an
!>   alpha^(4/5) term);
!> - kuwabara-kono, overlap: L/alpha and tau_c of alpha;
!> - kuwabara-kono, force: L/alpha and tau_c of ln(1 + alpha^(1/2)) (non-analytic terms
!>   alpha^(5/2); e ~ alpha^(-5/3) at large alpha);
!> - z_max, tau_max (both ends): of alpha^(1/5) (tsuji), ln(1 + alpha^(1/2)) (kuwabara-kono).
!> Ranges: inverse e in [1e-4, 1]; forward down to e = 1e-5: alpha <= 2.1572 (tsuji
!> overlap; alpha >= sqrt(5): HD_NO_REBOUND), 353.5 (tsuji force), 13.88
!> (kuwabara-kono overlap), 1176 (kuwabara-kono force); beyond them HD_OUTSIDE_VALIDITY
!> (use rk45).  Measured max relative error against the reference: the header of
!> data/fit_coefficients.csv and test/unit/test_fit_laws.f90 (below 1e-12).
!>
!> Derivatives (hertzdamp_fit_forward_deriv): de/dalpha and dtau_c/dalpha of the
!> functions the forward fit evaluates, for every law and end: each piecewise polynomial
!> differentiated (Horner with derivative) and composed with the change of variable of
!> its map (alpha, w = -ln(1 - alpha/alpha_c), alpha^(1/3), L, L^(1/5),
!> ln(1 + alpha^(1/2))), the variable computed as the forward fit computes it (the same
!> piece); the tsuji closed forms differentiated analytically.
module hertzdamp_fit_laws
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: HD_OK, HD_NO_REBOUND, HD_BAD_END, HD_OUTSIDE_VALIDITY, HD_OUT_OF_RANGE
    use hertzdamp_registry, only: HD_END_OVERLAP, HD_END_FORCE
    use hertzdamp_registry, only: HD_DAMPING_LINEAR, HD_DAMPING_TSUJI
    use hertzdamp_laws, only: hertzdamp_law_status, hertzdamp_alpha_c_tsuji, hertzdamp_tsuji_l
    use hertzdamp_fit, only: hertzdamp_fit_inverse, hertzdamp_fit_forward, hertzdamp_approx_alpha_status, &
                             hertzdamp_fit_e_min_overlap, hertzdamp_fit_e_min_force, hertzdamp_fit_neg_log, &
                             hertzdamp_fit_cbrt
    use hertzdamp_fit_data, only: fit_law_e_min, fit_ts_alpha_max_force, fit_kk_alpha_max_overlap, &
                                  fit_kk_alpha_max_force, fit_alpha_c, fit_alpha_max_force, fit_ov_fwd_lw_slope, &
                                  fit_ov_fwd_tw_slope, &
                                  fit_fwd_c, fit_fwd_x0, fit_fwd_x1, fit_fwd_scale, fit_fwd_np, fit_fwd_first, &
                                  fit_turn_c, fit_turn_x0, fit_turn_scale, fit_turn_np, fit_turn_first, &
                                  fit_one_c, fit_one_x0, fit_one_x1, fit_one_scale, fit_one_np, fit_one_first, &
                                  fit_map_ov_fwd_a, fit_map_ov_fwd_w, fit_map_fo_fwd, fit_map_kk_ov_fwd, &
                                  fit_map_kk_fo_fwd, fit_map_ts_turn, fit_map_kk_turn, fit_map_ts_ov_inv_t, &
                                  fit_map_ts_fo_inv_t
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> The families of hertzdamp_fit_data that the forward maps of the laws use.
    integer, parameter :: fam_fwd = 1, fam_turn = 2, fam_one = 3

    public :: hertzdamp_fit_law_inverse, hertzdamp_fit_law_forward, hertzdamp_fit_law_e_min
    public :: hertzdamp_fit_forward_deriv

contains

    !> Value y and derivative dy/dx at x of component `comp` of map `map` in a family of
    !> hertzdamp_fit_data: piece i = min(u, np - 1) of u = max(0, (x - x0) scale), Horner
    !> in t = 2 (u - i) - 1 (the piece of the kernels' `locate`).  dy = 0 where x is
    !> below the grid (clamped to its start); beyond it the last piece continues.
    pure subroutine map_eval(fam, map, comp, x, y, dy)
        integer, intent(in) :: fam, map, comp
        real(wp), intent(in) :: x
        real(wp), intent(out) :: y, dy
        select case (fam)
        case (fam_fwd)
            call piece(fit_fwd_c, fit_fwd_x0(map), fit_fwd_scale(map), fit_fwd_np(map), fit_fwd_first(map), y, dy)
        case (fam_turn)
            call piece(fit_turn_c, fit_turn_x0(map), fit_turn_scale(map), fit_turn_np(map), fit_turn_first(map), y, dy)
        case default
            call piece(fit_one_c, fit_one_x0(map), fit_one_scale(map), fit_one_np(map), fit_one_first(map), y, dy)
        end select
    contains
        pure subroutine piece(c, x0, scale, np, first, y, dy)
            real(wp), intent(in) :: c(0:, :, 0:)
            real(wp), intent(in) :: x0, scale
            integer, intent(in) :: np, first
            real(wp), intent(out) :: y, dy
            real(wp) :: u, t
            integer :: i, j
            u = max(0.0_wp, (x - x0) * scale)
            i = int(min(u, real(np - 1, wp)))
            t = 2.0_wp * (u - real(i, wp)) - 1.0_wp
            i = first + i
            y = c(ubound(c, 1), comp, i)
            dy = 0.0_wp
            do j = ubound(c, 1) - 1, 0, -1
                dy = dy * t + y
                y = y * t + c(j, comp, i)
            end do
            dy = dy * 2.0_wp * scale
            if ((x - x0) * scale < 0.0_wp) dy = 0.0_wp
        end subroutine piece
    end subroutine map_eval

    !> The value of map_eval alone.
    pure real(wp) function map_value(fam, map, comp, x) result(y)
        integer, intent(in) :: fam, map, comp
        real(wp), intent(in) :: x
        real(wp) :: dy
        call map_eval(fam, map, comp, x, y, dy)
    end function map_value

    !> Smallest restitution of the fitted inverse for a law and contact end
    !> (linear: 1e-3 overlap, 1e-4 force; tsuji and kuwabara-kono: 1e-4); 0 if invalid.
    pure elemental real(wp) function hertzdamp_fit_law_e_min(law, iend) result(e_min)
        integer, intent(in) :: law    !! HD_DAMPING_*
        integer, intent(in) :: iend   !! HD_END_OVERLAP or HD_END_FORCE
        e_min = 0.0_wp
        if (hertzdamp_law_status(law) /= HD_OK .or. (iend /= HD_END_OVERLAP .and. iend /= HD_END_FORCE)) return
        if (law == HD_DAMPING_LINEAR) then
            e_min = merge(hertzdamp_fit_e_min_overlap, hertzdamp_fit_e_min_force, iend == HD_END_OVERLAP)
        else
            e_min = fit_law_e_min
        end if
    end function hertzdamp_fit_law_e_min

    !> The inverse map e -> (alpha, tau_c) of the law: hertzdamp_fit_inverse with `law`
    !> (the kernel of every fit entry point).  e finite with e_min <= e <= 1
    !> (hertzdamp_fit_law_e_min), else HD_BAD_RESTITUTION and zero outputs.
    pure elemental subroutine hertzdamp_fit_law_inverse(e, iend, law, alpha, tau_c, status)
        real(wp), intent(in) :: e          !! restitution coefficient
        integer, intent(in) :: iend        !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: law         !! HD_DAMPING_*
        real(wp), intent(out) :: alpha     !! damping parameter with e(alpha) = e
        real(wp), intent(out) :: tau_c     !! dimensionless contact duration tau_c(alpha)
        integer, intent(out) :: status     !! HD_OK, HD_BAD_RESTITUTION, HD_BAD_END or HD_BAD_LAW
        call hertzdamp_fit_inverse(e, iend, alpha, tau_c, status, law)
    end subroutine hertzdamp_fit_law_inverse

    !> The forward map alpha -> (e, tau_c[, z_max, tau_max]) of the law.  tsuji overlap:
    !> HD_NO_REBOUND (e = 0, tau_c = +inf) for alpha >= sqrt(5).  Beyond the fitted
    !> range (module header) and for negative alpha: HD_OUTSIDE_VALIDITY, NaN: HD_BAD_ALPHA,
    !> with zero outputs.
    pure elemental subroutine hertzdamp_fit_law_forward(alpha, iend, law, e, tau_c, status, z_max, tau_max)
        real(wp), intent(in) :: alpha              !! damping parameter
        integer, intent(in) :: iend                !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: law                 !! HD_DAMPING_*
        real(wp), intent(out) :: e                 !! restitution coefficient
        real(wp), intent(out) :: tau_c             !! dimensionless contact duration
        integer, intent(out) :: status             !! HD_OK, HD_NO_REBOUND or an error
        real(wp), intent(out), optional :: z_max   !! deepest overlap (units of u_in t*)
        real(wp), intent(out), optional :: tau_max !! time of deepest overlap (units of t*)
        real(wp) :: zm, tm, dl, dtau
        ! the turning point only when asked for (it costs a map of its own)
        call law_forward(alpha, iend, law, .false., present(z_max) .or. present(tau_max), e, tau_c, status, zm, tm, &
                         dl, dtau)
        if (present(z_max)) z_max = zm
        if (present(tau_max)) tau_max = tm
    end subroutine hertzdamp_fit_law_forward

    !> The forward map of the fit with its exact derivatives: e(alpha), tau_c(alpha) as
    !> hertzdamp_fit_law_forward gives them (the same bits), de/dalpha and dtau_c/dalpha
    !> of the functions it evaluates (module header), for every law and contact end.
    !> status as hertzdamp_fit_law_forward, and HD_OUT_OF_RANGE where a derivative is
    !> infinite: alpha = 0 at the force end (tau_c - tau_c(0) grows like alpha^(2/3)
    !> (linear), alpha^(4/5) (tsuji), or its fit's variable ln(1 + alpha^(1/2)) has an
    !> infinite slope (kuwabara-kono)).  Every output is 0 when status /= HD_OK
    !> (also on no rebound).
    pure elemental subroutine hertzdamp_fit_forward_deriv(alpha, iend, law, e, tau_c, de, dtau, status)
        real(wp), intent(in) :: alpha      !! damping parameter, >= 0
        integer, intent(in) :: iend        !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: law         !! HD_DAMPING_*
        real(wp), intent(out) :: e         !! restitution coefficient
        real(wp), intent(out) :: tau_c     !! dimensionless contact duration
        real(wp), intent(out) :: de        !! de/dalpha
        real(wp), intent(out) :: dtau      !! dtau_c/dalpha
        integer, intent(out) :: status     !! HD_OK or the failure
        real(wp) :: zm, tm, dl
        logical :: singular
        ! the force end at alpha = 0: the slope of tau_c is infinite (not computed)
        singular = iend == HD_END_FORCE .and. alpha == 0.0_wp
        call law_forward(alpha, iend, law, .not. singular, .false., e, tau_c, status, zm, tm, dl, dtau)
        de = 0.0_wp
        if (status == HD_OK .and. singular) status = HD_OUT_OF_RANGE
        if (status == HD_OK) then
            de = -e * dl
            if (.not. (abs(de) <= huge(de) .and. abs(dtau) <= huge(dtau))) status = HD_OUT_OF_RANGE
        end if
        if (status /= HD_OK) then
            e = 0.0_wp
            tau_c = 0.0_wp
            de = 0.0_wp
            dtau = 0.0_wp
        end if
    end subroutine hertzdamp_fit_forward_deriv

    !> The forward map of every law (values of hertzdamp_fit_law_forward), with
    !> `turning` its turning point zm, tm (else 0), and with `deriv` dL/dalpha
    !> (L = -ln e) and dtau_c/dalpha (else 0).  e and tau_c do not depend on the switches.
    pure subroutine law_forward(alpha, iend, law, deriv, turning, e, tau_c, status, zm, tm, dl, dtau)
        real(wp), intent(in) :: alpha
        integer, intent(in) :: iend, law
        logical, intent(in) :: deriv, turning
        real(wp), intent(out) :: e, tau_c, zm, tm, dl, dtau
        integer, intent(out) :: status
        real(wp) :: l, x, p, dp, dx, sa
        e = 0.0_wp
        tau_c = 0.0_wp
        zm = 0.0_wp
        tm = 0.0_wp
        dl = 0.0_wp
        dtau = 0.0_wp
        status = hertzdamp_law_status(law)
        if (status == HD_OK .and. law == HD_DAMPING_LINEAR) then
            if (turning) then
                call hertzdamp_fit_forward(alpha, iend, e, tau_c, status, zm, tm)
            else
                call hertzdamp_fit_forward(alpha, iend, e, tau_c, status)
            end if
            if (status == HD_OK .and. deriv) call linear_deriv(alpha, iend, dl, dtau)
            return
        else if (status == HD_OK) then
            status = hertzdamp_approx_alpha_status(alpha, iend)
        end if
        if (status /= HD_OK) return
        if (law == HD_DAMPING_TSUJI) then
            if (turning .and. alpha <= fit_ts_alpha_max_force) then
                x = alpha**0.2_wp
                zm = map_value(fam_turn, fit_map_ts_turn, 1, x)
                tm = map_value(fam_turn, fit_map_ts_turn, 2, x)
            end if
            if (iend == HD_END_OVERLAP .and. alpha >= hertzdamp_alpha_c_tsuji) then
                status = HD_NO_REBOUND
                tau_c = ieee_value(1.0_wp, ieee_positive_inf)
            else
                ! L of the closed form (never -ln of the rounded e), e = exp(-L)
                if (deriv) then
                    call hertzdamp_tsuji_l(alpha, iend, l, status, dl)
                else
                    call hertzdamp_tsuji_l(alpha, iend, l, status)
                end if
                e = exp(-l)
                if (iend == HD_END_OVERLAP .and. l <= fit_one_x1(fit_map_ts_ov_inv_t)) then
                    call map_eval(fam_one, fit_map_ts_ov_inv_t, 1, l, tau_c, dp)
                    dtau = dp * dl
                else if (iend == HD_END_FORCE .and. alpha <= fit_ts_alpha_max_force) then
                    x = l**0.2_wp
                    call map_eval(fam_one, fit_map_ts_fo_inv_t, 1, x, tau_c, dp)
                    ! d(L^(1/5))/dL = L^(-4/5)/5
                    if (deriv) dtau = dp * 0.2_wp * l**(-0.8_wp) * dl
                else
                    status = HD_OUTSIDE_VALIDITY
                end if
            end if
        else
            if (alpha <= fit_kk_alpha_max_force) then
                sa = sqrt(alpha)
                x = log(1.0_wp + sa)
                if (turning) then
                    zm = map_value(fam_turn, fit_map_kk_turn, 1, x)
                    tm = map_value(fam_turn, fit_map_kk_turn, 2, x)
                end if
                if (iend == HD_END_FORCE) then
                    ! L = alpha P(x), dx/dalpha = 1/(2 sqrt(alpha) (1 + sqrt(alpha)))
                    call map_eval(fam_fwd, fit_map_kk_fo_fwd, 1, x, p, dp)
                    l = alpha * p
                    call map_eval(fam_fwd, fit_map_kk_fo_fwd, 2, x, tau_c, dtau)
                    e = exp(-l)
                    if (deriv) then
                        dl = p + dp * sa / (2.0_wp * (1.0_wp + sa))
                        dx = 1.0_wp / (2.0_wp * sa * (1.0_wp + sa))
                        dtau = dtau * dx
                    end if
                else if (alpha <= fit_kk_alpha_max_overlap) then
                    call map_eval(fam_fwd, fit_map_kk_ov_fwd, 1, alpha, p, dp)
                    l = alpha * p
                    call map_eval(fam_fwd, fit_map_kk_ov_fwd, 2, alpha, tau_c, dtau)
                    e = exp(-l)
                    dl = p + alpha * dp
                else
                    status = HD_OUTSIDE_VALIDITY
                end if
            else
                status = HD_OUTSIDE_VALIDITY
            end if
        end if
        if (status == HD_OUTSIDE_VALIDITY) then
            e = 0.0_wp
            tau_c = 0.0_wp
            zm = 0.0_wp
            tm = 0.0_wp
        end if
        if (.not. deriv) then
            dl = 0.0_wp
            dtau = 0.0_wp
        end if
    end subroutine law_forward

    !> dL/dalpha and dtau_c/dalpha of the linear law's forward kernel (hertzdamp_fit_kernels,
    !> kernel_forward_overlap and kernel_forward_force), for an alpha where it succeeded: overlap, alpha <= 0.6:
    !> L = alpha P(alpha), tau_c = T(alpha); beyond: L = P(w), tau_c = T(w),
    !> w = -ln(1 - alpha/alpha_c), linear in w past the last piece; force: L = alpha P(x),
    !> tau_c = T(x), x = alpha^(1/3).  w and x by the kernel's own -ln and cube root.
    pure subroutine linear_deriv(alpha, iend, dl, dtau)
        real(wp), intent(in) :: alpha
        integer, intent(in) :: iend
        real(wp), intent(out) :: dl, dtau
        real(wp) :: p, dp, y, w, dw, x
        if (iend == HD_END_OVERLAP) then
            if (alpha <= fit_fwd_x1(fit_map_ov_fwd_a)) then
                call map_eval(fam_fwd, fit_map_ov_fwd_a, 1, alpha, p, dp)
                dl = p + alpha * dp
                call map_eval(fam_fwd, fit_map_ov_fwd_a, 2, alpha, y, dtau)
            else
                w = hertzdamp_fit_neg_log(1.0_wp - alpha / fit_alpha_c)
                dw = 1.0_wp / (fit_alpha_c - alpha)
                if (w <= fit_fwd_x1(fit_map_ov_fwd_w)) then
                    call map_eval(fam_fwd, fit_map_ov_fwd_w, 1, w, p, dp)
                    dl = dp * dw
                    call map_eval(fam_fwd, fit_map_ov_fwd_w, 2, w, y, dtau)
                    dtau = dtau * dw
                else
                    dl = fit_ov_fwd_lw_slope * dw
                    dtau = fit_ov_fwd_tw_slope * dw
                end if
            end if
        else
            ! alpha <= alpha_max_force here (the kernel succeeded); dx/dalpha = x/(3 alpha)
            x = hertzdamp_fit_cbrt(alpha)
            call map_eval(fam_fwd, fit_map_fo_fwd, 1, x, p, dp)
            dl = p + x * dp / 3.0_wp
            call map_eval(fam_fwd, fit_map_fo_fwd, 2, x, y, dtau)
            dtau = dtau * x / (3.0_wp * alpha)   ! alpha = 0: not finite (HD_OUT_OF_RANGE)
        end if
    end subroutine linear_deriv

end module hertzdamp_fit_laws
