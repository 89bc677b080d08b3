!> Machine-precision approximants of the collision maps for every damping law
!> (doc/damping-laws.md): the linear law through `hertzdamp_fit`, the tsuji and
!> kuwabara-kono laws here, with the generated blocks of `hertzdamp_fit_data`
!> (gen/fit/gen_fit.f90, data/fit_coefficients.csv) and the exact tsuji closed forms.
!>
!> What is evaluated (L = -ln e):
!> - tsuji, overlap: alpha(e) = sqrt(5) L / sqrt(pi^2 + L^2) and e(alpha) exactly;
!>   tau_c as a polynomial of L (forward: of the exact L(alpha)).
!> - tsuji, force: e(alpha) exactly (hertzdamp_tsuji_e); alpha/L of L (analytic);
!>   tau_c of L^(1/5) (tau_c has an alpha^(4/5) term).
!> - kuwabara-kono, overlap: alpha/L and tau_c of L; L/alpha and tau_c of alpha.
!> - kuwabara-kono, force: alpha/L and tau_c of L^(1/2); L/alpha and tau_c of
!>   ln(1 + alpha^(1/2)) (non-analytic terms alpha^(5/2); e ~ alpha^(-5/3) at large alpha).
!> - z_max, tau_max (both ends): of alpha^(1/5) (tsuji), ln(1 + alpha^(1/2)) (kuwabara-kono).
!> Ranges: inverse e in [1e-4, 1]; forward down to e = 1e-5: alpha <= 2.1572 (tsuji
!> overlap; alpha >= sqrt(5): HD_NO_REBOUND), 353.5 (tsuji force), 13.88
!> (kuwabara-kono overlap), 1176 (kuwabara-kono force); beyond them HD_OUTSIDE_VALIDITY
!> (use rk45).  Measured max relative error against the reference: the header of
!> data/fit_coefficients.csv and test/test_fit_laws.f90 (below 1e-12).
module hertzdamp_fit_laws
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_OK, HD_NO_REBOUND, HD_BAD_END, HD_BAD_RESTITUTION, HD_OUTSIDE_VALIDITY, &
                                HD_END_OVERLAP, HD_END_FORCE, HD_BAD_LAW
    use hertzdamp_constants, only: hertzdamp_tau_c0
    use hertzdamp_laws, only: HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO, hertzdamp_law_status, &
                              hertzdamp_alpha_c_tsuji, hertzdamp_tsuji_e
    use hertzdamp_fit, only: hertzdamp_fit_inverse, hertzdamp_fit_forward, hertzdamp_approx_alpha_status, &
                             hertzdamp_fit_e_min_overlap, hertzdamp_fit_e_min_force
    use hertzdamp_fit_data, only: fit_law_e_min, fit_ts_alpha_max_force, fit_kk_alpha_max_overlap, &
                                  fit_kk_alpha_max_force, &
                                  ts_ov_inv_t_c, ts_ov_inv_t_x0, ts_ov_inv_t_x1, ts_ov_inv_t_scale, ts_ov_inv_t_np, &
                                  ts_fo_inv_a_c, ts_fo_inv_a_x0, ts_fo_inv_a_scale, ts_fo_inv_a_np, &
                                  ts_fo_inv_t_c, ts_fo_inv_t_x0, ts_fo_inv_t_scale, ts_fo_inv_t_np, &
                                  ts_fwd_z_c, ts_fwd_z_x0, ts_fwd_z_scale, ts_fwd_z_np, &
                                  ts_fwd_m_c, ts_fwd_m_x0, ts_fwd_m_scale, ts_fwd_m_np, &
                                  kk_ov_inv_a_c, kk_ov_inv_a_x0, kk_ov_inv_a_scale, kk_ov_inv_a_np, &
                                  kk_ov_inv_t_c, kk_ov_inv_t_x0, kk_ov_inv_t_scale, kk_ov_inv_t_np, &
                                  kk_fo_inv_a_c, kk_fo_inv_a_x0, kk_fo_inv_a_scale, kk_fo_inv_a_np, &
                                  kk_fo_inv_t_c, kk_fo_inv_t_x0, kk_fo_inv_t_scale, kk_fo_inv_t_np, &
                                  kk_ov_fwd_la_c, kk_ov_fwd_la_x0, kk_ov_fwd_la_scale, kk_ov_fwd_la_np, &
                                  kk_ov_fwd_ta_c, kk_ov_fwd_ta_x0, kk_ov_fwd_ta_scale, kk_ov_fwd_ta_np, &
                                  kk_fo_fwd_la_c, kk_fo_fwd_la_x0, kk_fo_fwd_la_scale, kk_fo_fwd_la_np, &
                                  kk_fo_fwd_ta_c, kk_fo_fwd_ta_x0, kk_fo_fwd_ta_scale, kk_fo_fwd_ta_np, &
                                  kk_fwd_z_c, kk_fwd_z_x0, kk_fwd_z_scale, kk_fwd_z_np, &
                                  kk_fwd_m_c, kk_fwd_m_x0, kk_fwd_m_scale, kk_fwd_m_np
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk
    real(wp), parameter :: pi = acos(-1.0_wp)

    public :: hertzdamp_fit_law_inverse, hertzdamp_fit_law_forward, hertzdamp_fit_law_e_min

contains

    !> Value at x of a generated block: piece i = min(int(u), np - 1) of
    !> u = max(0, (x - x0) scale), Horner in t = 2 (u - i) - 1.
    pure real(wp) function block_value(c, x0, scale, np, x) result(y)
        real(wp), intent(in) :: c(0:, 0:)   !! monomial coefficients (0:deg, 0:np-1)
        real(wp), intent(in) :: x0, scale   !! grid of the block
        integer, intent(in) :: np           !! number of pieces
        real(wp), intent(in) :: x           !! variable
        real(wp) :: u, t
        integer :: i, j
        u = max(0.0_wp, (x - x0) * scale)
        i = min(int(u), np - 1)
        t = 2.0_wp * (u - real(i, wp)) - 1.0_wp
        y = c(ubound(c, 1), i)
        do j = ubound(c, 1) - 1, 0, -1
            y = y * t + c(j, i)
        end do
    end function block_value

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

    !> The inverse map e -> (alpha, tau_c) of the law.  e finite with e_min <= e <= 1
    !> (hertzdamp_fit_law_e_min), else HD_BAD_RESTITUTION and zero outputs.
    pure elemental subroutine hertzdamp_fit_law_inverse(e, iend, law, alpha, tau_c, status)
        real(wp), intent(in) :: e          !! restitution coefficient
        integer, intent(in) :: iend        !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: law         !! HD_DAMPING_*
        real(wp), intent(out) :: alpha     !! damping parameter with e(alpha) = e
        real(wp), intent(out) :: tau_c     !! dimensionless contact duration tau_c(alpha)
        integer, intent(out) :: status     !! HD_OK, HD_BAD_RESTITUTION, HD_BAD_END or HD_BAD_LAW
        real(wp) :: l, x
        alpha = 0.0_wp
        tau_c = 0.0_wp
        status = hertzdamp_law_status(law)
        if (status /= HD_OK) return
        if (law == HD_DAMPING_LINEAR) then
            call hertzdamp_fit_inverse(e, iend, alpha, tau_c, status)
            return
        end if
        if (iend /= HD_END_OVERLAP .and. iend /= HD_END_FORCE) then
            status = HD_BAD_END
            return
        end if
        if (.not. (e >= fit_law_e_min .and. e <= 1.0_wp)) then
            status = HD_BAD_RESTITUTION
            return
        end if
        l = 0.0_wp - log(e)   ! +0 at e = 1
        if (l == 0.0_wp) then   ! e = 1: the elastic limit, exactly
            tau_c = hertzdamp_tau_c0()
            return
        end if
        if (law == HD_DAMPING_TSUJI) then
            if (iend == HD_END_OVERLAP) then
                alpha = hertzdamp_alpha_c_tsuji * l / sqrt(pi * pi + l * l)
                tau_c = block_value(ts_ov_inv_t_c, ts_ov_inv_t_x0, ts_ov_inv_t_scale, ts_ov_inv_t_np, l)
            else
                alpha = l * block_value(ts_fo_inv_a_c, ts_fo_inv_a_x0, ts_fo_inv_a_scale, ts_fo_inv_a_np, l)
                tau_c = block_value(ts_fo_inv_t_c, ts_fo_inv_t_x0, ts_fo_inv_t_scale, ts_fo_inv_t_np, l**0.2_wp)
            end if
        else
            if (iend == HD_END_OVERLAP) then
                alpha = l * block_value(kk_ov_inv_a_c, kk_ov_inv_a_x0, kk_ov_inv_a_scale, kk_ov_inv_a_np, l)
                tau_c = block_value(kk_ov_inv_t_c, kk_ov_inv_t_x0, kk_ov_inv_t_scale, kk_ov_inv_t_np, l)
            else
                x = sqrt(l)
                alpha = l * block_value(kk_fo_inv_a_c, kk_fo_inv_a_x0, kk_fo_inv_a_scale, kk_fo_inv_a_np, x)
                tau_c = block_value(kk_fo_inv_t_c, kk_fo_inv_t_x0, kk_fo_inv_t_scale, kk_fo_inv_t_np, x)
            end if
        end if
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
        real(wp) :: l, x, zm, tm
        e = 0.0_wp
        tau_c = 0.0_wp
        zm = 0.0_wp
        tm = 0.0_wp
        status = hertzdamp_law_status(law)
        if (status == HD_OK .and. law == HD_DAMPING_LINEAR) then
            call hertzdamp_fit_forward(alpha, iend, e, tau_c, status, zm, tm)
        else if (status == HD_OK) then
            status = hertzdamp_approx_alpha_status(alpha, iend)
        end if
        if (status /= HD_OK .or. law == HD_DAMPING_LINEAR) then
            if (present(z_max)) z_max = zm
            if (present(tau_max)) tau_max = tm
            return
        end if
        if (law == HD_DAMPING_TSUJI) then
            if (alpha <= fit_ts_alpha_max_force) then
                x = alpha**0.2_wp
                zm = block_value(ts_fwd_z_c, ts_fwd_z_x0, ts_fwd_z_scale, ts_fwd_z_np, x)
                tm = block_value(ts_fwd_m_c, ts_fwd_m_x0, ts_fwd_m_scale, ts_fwd_m_np, x)
            end if
            if (iend == HD_END_OVERLAP .and. alpha >= hertzdamp_alpha_c_tsuji) then
                status = HD_NO_REBOUND
                tau_c = ieee_value(1.0_wp, ieee_positive_inf)
            else
                call hertzdamp_tsuji_e(alpha, iend, e, status)
                l = 0.0_wp - log(e)
                if (iend == HD_END_OVERLAP .and. l <= ts_ov_inv_t_x1) then
                    tau_c = block_value(ts_ov_inv_t_c, ts_ov_inv_t_x0, ts_ov_inv_t_scale, ts_ov_inv_t_np, l)
                else if (iend == HD_END_FORCE .and. alpha <= fit_ts_alpha_max_force) then
                    tau_c = block_value(ts_fo_inv_t_c, ts_fo_inv_t_x0, ts_fo_inv_t_scale, ts_fo_inv_t_np, l**0.2_wp)
                else
                    status = HD_OUTSIDE_VALIDITY
                end if
            end if
        else
            if (alpha <= fit_kk_alpha_max_force) then
                x = log(1.0_wp + sqrt(alpha))
                zm = block_value(kk_fwd_z_c, kk_fwd_z_x0, kk_fwd_z_scale, kk_fwd_z_np, x)
                tm = block_value(kk_fwd_m_c, kk_fwd_m_x0, kk_fwd_m_scale, kk_fwd_m_np, x)
                if (iend == HD_END_FORCE) then
                    l = alpha * block_value(kk_fo_fwd_la_c, kk_fo_fwd_la_x0, kk_fo_fwd_la_scale, kk_fo_fwd_la_np, x)
                    tau_c = block_value(kk_fo_fwd_ta_c, kk_fo_fwd_ta_x0, kk_fo_fwd_ta_scale, kk_fo_fwd_ta_np, x)
                    e = exp(-l)
                else if (alpha <= fit_kk_alpha_max_overlap) then
                    l = alpha * block_value(kk_ov_fwd_la_c, kk_ov_fwd_la_x0, kk_ov_fwd_la_scale, kk_ov_fwd_la_np, &
                                            alpha)
                    tau_c = block_value(kk_ov_fwd_ta_c, kk_ov_fwd_ta_x0, kk_ov_fwd_ta_scale, kk_ov_fwd_ta_np, alpha)
                    e = exp(-l)
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
        if (present(z_max)) z_max = zm
        if (present(tau_max)) tau_max = tm
    end subroutine hertzdamp_fit_law_forward

end module hertzdamp_fit_laws
