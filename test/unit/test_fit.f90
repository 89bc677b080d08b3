!> Tests of the fitted approximants (hertzdamp_fit) and the compact formulas
!> (hertzdamp_compact) against the reference integrator at tolerance 1e-15.
program test_fit
    use hertzdamp
    use hertzdamp_fit, only: hertzdamp_fit_alpha, hertzdamp_fit_cbrt, hertzdamp_fit_exp_neg, hertzdamp_fit_neg_log, &
                             hertzdamp_fit_root5
    use hertzdamp_testing, only: test_suite, new_suite, rel_err
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    type(test_suite) :: s
    type(hertzdamp_collision) :: r, rb
    real(wp) :: a, e, tc, a2, tc2, amax, x, emax(4), ab, l, cmax(4), zm, tm
    integer :: i, iend, st
    s = new_suite('test_fit')

    do iend = HD_END_OVERLAP, HD_END_FORCE
        ! alpha range of the 1e-12 claim: alpha(e_min)
        call hertzdamp_fit_inverse(merge(1.0e-3_wp, 1.0e-4_wp, iend == HD_END_OVERLAP), iend, amax, tc, st)
        emax = 0.0_wp
        do i = 1, 200
            x = (real(i, wp) - 0.5_wp) / 200.0_wp
            a = amax * x**merge(0.5_wp, 2.0_wp, iend == HD_END_OVERLAP)
            r = hertzdamp_rk45_collide(a, iend, 1.0e-15_wp)
            call hertzdamp_fit_forward(a, iend, e, tc, st, zm, tm)
            emax(1) = max(emax(1), rel_err(e, r%e), rel_err(tc, r%tau_c))
            emax(2) = max(emax(2), rel_err(zm, r%z_max), rel_err(tm, r%tau_max))
            call hertzdamp_fit_inverse(r%e, iend, a2, tc2, st)
            ! below alpha ~ 1e-2 the reference e (error ~1e-15 absolute) cannot resolve 1e-12 in alpha
            emax(3) = max(emax(3), abs(a2 - a) / (a + 1.0e-2_wp), rel_err(tc2, r%tau_c))
        end do
        call s%check(emax(1) < 1.0e-12_wp, 'fit forward e, tau_c within 1e-12 (' // hertzdamp_end_name(iend) // ')')
        call s%check(emax(2) < 1.0e-12_wp, 'fit forward z_max, tau_max within 1e-12')
        call s%check(emax(3) < 1.0e-12_wp, 'fit inverse alpha, tau_c within 1e-12 (' // hertzdamp_end_name(iend) // ')')
        ! relative error of alpha where alpha is small (e near 1): log-spaced alpha in [0.01, 0.3].
        ! The reference e has an absolute error ~1e-15; with d ln e / d ln alpha ~ -ln e >= 0.01
        ! that resolves alpha to ~1e-13 relative, well inside the 1e-12 asserted.
        emax(4) = 0.0_wp
        do i = 0, 120
            a = 0.01_wp * 30.0_wp**(real(i, wp) / 120.0_wp)
            r = hertzdamp_rk45_collide(a, iend, 1.0e-15_wp)
            call hertzdamp_fit_inverse(r%e, iend, a2, tc2, st)
            emax(4) = max(emax(4), rel_err(a2, a))
        end do
        call s%check(emax(4) < 1.0e-12_wp, 'fit inverse alpha within 1e-12 relative for alpha in [0.01, 0.3] (' // &
                     hertzdamp_end_name(iend) // ')')
        print '(a,a8,es10.2)', 'max rel err fit inverse alpha, alpha in [0.01, 0.3]: ', hertzdamp_end_name(iend), emax(4)
        print '(a,a8,3es10.2)', 'max rel err fit fwd (e,tau_c), (z_max,tau_max), inverse (alpha,tau_c): ', &
            hertzdamp_end_name(iend), emax(1:3)
        ! exact limits at e = 1
        call hertzdamp_fit_inverse(1.0_wp, iend, a2, tc2, st)
        call s%check(st == HD_OK .and. same(a2, 0.0_wp), 'alpha(1) = 0')
        call s%check_close(tc2, hertzdamp_tau_c0(), 1.0e-14_wp, 'tau_c(e = 1) = tau_c0')
        call hertzdamp_fit_forward(0.0_wp, iend, e, tc, st)
        call s%check_close(e, 1.0_wp, 1.0e-15_wp, 'e(0) = 1')
        call s%check_close(hertzdamp_fit_alpha(0.999_wp, iend), (1.0_wp - 0.999_wp) / hertzdamp_e1(), 5.0e-3_wp, &
                           'slope e1 at e = 1')
        ! out of range
        call hertzdamp_fit_inverse(0.5_wp * merge(1.0e-3_wp, 1.0e-4_wp, iend == HD_END_OVERLAP), iend, a2, tc2, st)
        call s%check(st == HD_BAD_RESTITUTION .and. same(a2, 0.0_wp), 'e below e_min: HD_BAD_RESTITUTION')
        call hertzdamp_fit_inverse(1.5_wp, iend, a2, tc2, st)
        call s%check(st == HD_BAD_RESTITUTION, 'e > 1: HD_BAD_RESTITUTION')
        call hertzdamp_fit_inverse(ieee_value(1.0_wp, ieee_quiet_nan), iend, a2, tc2, st)
        call s%check(st == HD_BAD_RESTITUTION .and. same(a2, 0.0_wp), 'e NaN: HD_BAD_RESTITUTION')
        call hertzdamp_fit_forward(-0.1_wp, iend, e, tc, st)
        call s%check(st == HD_OUTSIDE_VALIDITY .and. same(e, 0.0_wp), 'alpha < 0: HD_OUTSIDE_VALIDITY')
    end do
    call hertzdamp_fit_inverse(0.5_wp, 3, a2, tc2, st)
    call s%check(st == HD_BAD_END, 'bad iend')

    ! overlap: no rebound at and above alpha_c; sensible values just below
    call hertzdamp_fit_forward(1.13_wp, HD_END_OVERLAP, e, tc, st)
    call s%check(st == HD_NO_REBOUND .and. same(e, 0.0_wp) .and. .not. ieee_is_finite(tc) .and. tc > 0.0_wp, &
                 'alpha >= alpha_c: no rebound, e = 0, tau_c = +inf')
    call hertzdamp_fit_forward(hertzdamp_fit_alpha_c * (1.0_wp - 1.0e-12_wp), HD_END_OVERLAP, e, tc, st)
    call s%check(st == HD_OK .and. e > 0.0_wp .and. e < 1.0e-9_wp .and. ieee_is_finite(tc) .and. tc > 20.0_wp, &
                 'just below alpha_c: tiny e, long finite tau_c')
    call hertzdamp_fit_forward(1.1275_wp, HD_END_OVERLAP, e, tc, st)
    r = hertzdamp_rk45_collide(1.1275_wp, HD_END_OVERLAP, 1.0e-15_wp)
    call s%check_close(e, r%e, 1.0e-9_wp, 'overlap forward down to e ~ 1e-4 (fitted to e = 1e-5)')
    call hertzdamp_fit_forward(100.0_wp, HD_END_FORCE, e, tc, st)
    call s%check(st == HD_OUTSIDE_VALIDITY, 'force alpha beyond the fitted range')

    ! time reversal (doc/theory.md section 4): beta = alpha e^(-1/10) odd in ln e, tau_c e^(1/10) even.
    ! The fitted alpha(e) and the reference at -alpha e^(-1/5) must give e' = 1/e, same tau_c e^(1/10).
    emax = 0.0_wp
    do i = 1, 20
        e = 0.05_wp + 0.9_wp * (i - 1) / 19.0_wp
        call hertzdamp_fit_inverse(e, HD_END_OVERLAP, a, tc, st)
        ab = -a * e**(-0.2_wp)
        rb = hertzdamp_rk45_collide(ab, HD_END_OVERLAP, 1.0e-15_wp)
        emax(1) = max(emax(1), abs(e * rb%e - 1.0_wp))
        emax(2) = max(emax(2), rel_err(rb%tau_c * rb%e**0.1_wp, tc * e**0.1_wp))
        ! odd: beta(-L) = -beta(L) with beta(-L) = ab * rb%e^(-1/10)
        emax(3) = max(emax(3), abs(ab * rb%e**(-0.1_wp) + a * e**(-0.1_wp)) / (a * e**(-0.1_wp)))
    end do
    call s%check(emax(1) < 1.0e-12_wp, 'time reversal: e(alpha) e(-alpha e^-1/5) = 1 with the fitted alpha')
    call s%check(emax(2) < 1.0e-12_wp, 'time reversal: tau_c e^(1/10) even in ln e')
    call s%check(emax(3) < 1.0e-12_wp, 'time reversal: beta = alpha e^(-1/10) odd in ln e')

    ! compact formulas: documented max errors (doc/compact.md) on a dense grid e in [0.05, 1]
    do iend = HD_END_OVERLAP, HD_END_FORCE
        cmax = 0.0_wp
        do i = 0, 1000
            e = 0.05_wp + 0.95_wp * real(i, wp) / 1000.0_wp
            call hertzdamp_fit_inverse(e, iend, a, tc, st)        ! 1e-13 reference
            call hertzdamp_compact_inverse(e, iend, a2, tc2, st)
            if (a > 0.0_wp) cmax(1) = max(cmax(1), rel_err(a2, a))
            cmax(2) = max(cmax(2), rel_err(tc2, tc))
            call hertzdamp_compact_forward(a, iend, x, tc2, st)
            cmax(3) = max(cmax(3), rel_err(x, e))
            cmax(4) = max(cmax(4), rel_err(tc2, tc))
        end do
        print '(a,a8,4es10.2)', 'compact max rel err alpha(e), tau_c(e), e(alpha), tau_c(alpha): ', &
            hertzdamp_end_name(iend), cmax
        if (iend == HD_END_OVERLAP) then
            call s%check(cmax(1) <= 1.5e-6_wp .and. cmax(2) <= 4.0e-6_wp, 'compact overlap inverse: alpha 1.5e-6, tau_c 4e-6')
            call s%check(cmax(3) <= 3.0e-5_wp .and. cmax(4) <= 4.0e-6_wp, 'compact overlap forward: e 3e-5, tau_c 4e-6')
            ! resulting k ~ tau_c^(5/2), d ~ alpha tau_c (fixed m, u, T_c)
            call s%check(2.5_wp * cmax(2) <= 3.0e-5_wp .and. cmax(1) + cmax(2) <= 3.0e-5_wp, 'compact k, d within 3e-5')
        else
            call s%check(cmax(1) <= 5.0e-4_wp .and. cmax(2) <= 1.0e-3_wp, 'compact force inverse: alpha 5e-4, tau_c 1e-3')
            call s%check(cmax(3) <= 5.0e-4_wp .and. cmax(4) <= 1.0e-3_wp, 'compact force forward: e 5e-4, tau_c 1e-3')
        end if
        call hertzdamp_compact_inverse(1.0_wp, iend, a2, tc2, st)
        call s%check(same(a2, 0.0_wp) .and. abs(tc2 - hertzdamp_tau_c0()) <= 1.0e-15_wp * tc2, 'compact exact at e = 1')
        ! alpha(e) and tau_c(e) finite, positive and monotone down to e_min = 0.05
        l = 1.0_wp
        x = 0.0_wp
        tc = 0.0_wp
        do i = 0, 200
            e = exp(log(5.0e-2_wp) * real(i, wp) / 200.0_wp)
            call hertzdamp_compact_inverse(e, iend, a2, tc2, st)
            if (.not. (st == HD_OK .and. ieee_is_finite(a2) .and. a2 >= x .and. tc2 > 0.0_wp)) l = -1.0_wp
            if (iend == HD_END_OVERLAP .and. tc2 < tc) l = -1.0_wp   ! overlap: tau_c grows with damping
            x = a2
            tc = tc2
        end do
        call s%check(l > 0.0_wp, 'compact alpha(e) increasing, tau_c(e) positive (overlap: increasing) down to e_min = 0.05')
        call hertzdamp_compact_inverse(0.049_wp, iend, a2, tc2, st)
        call s%check(st == HD_BAD_RESTITUTION, 'compact refuses e below 0.05')
    end do
    call kernels()
    call s%finish()

contains

    !> The arithmetic kernels of the fits (-ln x, x^(1/3), exp(-x), used instead of libm so
    !> that vectorised and scalar code agree bit for bit) against quadruple precision.
    subroutine kernels()
        integer, parameter :: qp = selected_real_kind(30)
        integer :: j
        real(wp) :: x, ulp_log, ulp_cbrt, ulp_exp, ulp_root5
        real(qp) :: q
        ulp_log = 0.0_wp
        ulp_cbrt = 0.0_wp
        ulp_root5 = 0.0_wp
        ulp_exp = 0.0_wp
        do j = 0, 100000
            ! -ln x on [1e-5, 1] (the inverse needs [1e-4, 1], the forward w needs (0, 1])
            x = 10.0_wp**(-5.0_wp * real(j, wp) / 100000.0_wp)
            q = -log(real(x, qp))
            ulp_log = max(ulp_log, real(abs(hertzdamp_fit_neg_log(x) - q) / spacing(max(real(q, wp), tiny(x))), wp))
            ! x^(1/3) on [1e-17, 60] (L^(1/3) of the force inverse, alpha^(1/3) of the force forward)
            x = 10.0_wp**(-17.0_wp + 18.8_wp * real(j, wp) / 100000.0_wp)
            q = real(x, qp)**(1.0_qp / 3.0_qp)
            ulp_cbrt = max(ulp_cbrt, real(abs(hertzdamp_fit_cbrt(x) - q) / spacing(real(q, wp)), wp))
            ! x^(1/5) on the same range (L^(1/5) of the tsuji force inverse)
            q = real(x, qp)**(1.0_qp / 5.0_qp)
            ulp_root5 = max(ulp_root5, real(abs(hertzdamp_fit_root5(x) - q) / spacing(real(q, wp)), wp))
            ! exp(-x) on [0, 40] (e of the forward map)
            x = 40.0_wp * real(j, wp) / 100000.0_wp
            q = exp(-real(x, qp))
            ulp_exp = max(ulp_exp, real(abs(hertzdamp_fit_exp_neg(x) - q) / spacing(real(q, wp)), wp))
        end do
        print '(a, 4f7.3)', 'kernels: max error in ulp of -ln x, x^(1/3), exp(-x), x^(1/5): ', ulp_log, ulp_cbrt, &
            ulp_exp, ulp_root5
        call s%check(ulp_log <= 1.5_wp, '-ln x within 1.5 ulp on [1e-5, 1]')
        call s%check(ulp_cbrt <= 1.0_wp, 'x^(1/3) within 1 ulp on [1e-17, 60]')
        call s%check(ulp_exp <= 1.0_wp, 'exp(-x) within 1 ulp on [0, 40]')
        call s%check(ulp_root5 <= 1.0_wp, 'x^(1/5) within 1 ulp on [1e-17, 60]')
        call s%check(same(hertzdamp_fit_root5(0.0_wp), 0.0_wp) .and. same(hertzdamp_fit_root5(-0.0_wp), 0.0_wp) .and. &
                     same(hertzdamp_fit_root5(32.0_wp), 2.0_wp) .and. same(hertzdamp_fit_root5(1.0_wp / 32.0_wp), 0.5_wp) &
                     .and. same(hertzdamp_fit_root5(243.0_wp), 3.0_wp) .and. same(hertzdamp_fit_root5(1.0_wp), 1.0_wp), &
                     'x^(1/5) exact for 0, -0 and fifth powers')
        call s%check(same(hertzdamp_fit_neg_log(1.0_wp), 0.0_wp) .and. .not. (sign(1.0_wp, hertzdamp_fit_neg_log(1.0_wp)) &
                     < 0.0_wp), '-ln 1 = +0')
        call s%check(same(hertzdamp_fit_neg_log(0.5_wp), log(2.0_wp)) .and. same(hertzdamp_fit_neg_log(0.25_wp), &
                     2.0_wp * log(2.0_wp)), '-ln 2^-k = k ln 2, correctly rounded')
        call s%check(same(hertzdamp_fit_cbrt(0.0_wp), 0.0_wp) .and. same(hertzdamp_fit_cbrt(-0.0_wp), 0.0_wp) .and. &
                     same(hertzdamp_fit_cbrt(8.0_wp), 2.0_wp) .and. same(hertzdamp_fit_cbrt(0.125_wp), 0.5_wp) .and. &
                     same(hertzdamp_fit_cbrt(27.0_wp), 3.0_wp), 'cbrt exact for 0, -0 and cubes')
        call s%check(same(hertzdamp_fit_exp_neg(0.0_wp), 1.0_wp), 'exp(-0) = 1')
    end subroutine kernels

    !> Exact equality without -Wcompare-reals.
    pure logical function same(x, y)
        real(wp), intent(in) :: x, y
        same = .not. (abs(x - y) > 0.0_wp)
    end function same
end program test_fit
