!> Tests of the inverse rule hertzdamp_invert (doc/theory.md section 6).
program test_inverse
    use hertzdamp
    use hertzdamp_testing, only: test_suite, new_suite, rel_err
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    type(test_suite) :: s
    real(wp) :: k, d, a, ts, tau, e2, tc2, zm, al2, ts2, emax(4), e, m, u, tc, kb, db, k2, d2, a3, tau3
    real(wp) :: ms(4) = [1.0e-15_wp, 1.0e-6_wp, 1.0_wp, 1.0e3_wp], us(3) = [1.0e-4_wp, 1.0_wp, 1.0e2_wp]
    real(wp) :: tcs(3) = [1.0e-9_wp, 1.0e-5_wp, 1.0e-1_wp]
    integer :: i, j, jm, ju, jt, iend, st
    logical :: bound
    s = new_suite('test_inverse')

    do iend = HD_END_OVERLAP, HD_END_FORCE
        ! round trip through the reference: forward(invert(e, T_c)) = (e, T_c)
        emax = 0.0_wp
        do i = 1, 8
            e = merge(1.0e-3_wp, 1.0e-4_wp, iend == HD_END_OVERLAP)**(real(i - 1, wp) / 7.0_wp)
            do jm = 1, 4
                do ju = 1, 3
                    do jt = 1, 3
                        m = ms(jm)
                        u = us(ju)
                        tc = tcs(jt)
                        call hertzdamp_invert(e, tc, m, u, iend, k, d, st)
                        call hertzdamp_forward_dim(k, d, m, u, iend, HD_METHOD_RK45, al2, ts2, e2, tc2, zm, st, &
                                                   1.0e-15_wp)
                        emax(1) = max(emax(1), rel_err(e2, e))
                        emax(2) = max(emax(2), rel_err(tc2, tc))
                    end do
                end do
            end do
        end do
        print '(a,a8,2es10.2)', 'round trip max rel err e, T_c: ', hertzdamp_end_name(iend), emax(1:2)
        call s%check(emax(1) < 1.0e-11_wp .and. emax(2) < 1.0e-11_wp, &
                     'round trip forward(invert(e, T_c)) within 1e-11 (' // hertzdamp_end_name(iend) // ')')

        ! fit vs iterative vs reference on 200 values of e
        emax = 0.0_wp
        do i = 1, 200
            e = merge(1.0e-3_wp, 1.0e-4_wp, iend == HD_END_OVERLAP)**((real(i, wp) - 0.5_wp) / 200.0_wp)
            call hertzdamp_invert(e, 1.0e-4_wp, 1.0e-3_wp, 1.0_wp, iend, k, d, st, alpha=a, tau_c=tau)
            call hertzdamp_invert(e, 1.0e-4_wp, 1.0e-3_wp, 1.0_wp, iend, k2, d2, j, alpha=a3, tau_c=tau3, &
                                  options=hertzdamp_invert_options(method=HD_METHOD_ITERATIVE, tol=1.0e-13_wp))
            emax(1) = max(emax(1), abs(a3 - a) / (a + 1.0e-2_wp), rel_err(tau3, tau))
            emax(2) = max(emax(2), rel_err(k2, k), abs(d2 - d) / (d + 1.0e-2_wp * d / max(a, 1.0e-300_wp)))
            call hertzdamp_forward_dim(k, d, 1.0e-3_wp, 1.0_wp, iend, HD_METHOD_RK45, al2, ts2, e2, tc2, zm, st, &
                                       1.0e-15_wp)
            emax(3) = max(emax(3), rel_err(e2, e), rel_err(tc2, 1.0e-4_wp))
            if (j /= HD_OK) emax(4) = 1.0_wp
        end do
        print '(a,a8,3es10.2)', 'fit vs iterative (alpha,tau_c), (k,d); fit vs rk45 (e,T_c): ', &
            hertzdamp_end_name(iend), emax(1:3)
        call s%check(emax(4) == 0.0_wp, 'iterative converges on 200 values')
        call s%check(emax(1) < 1.0e-11_wp .and. emax(2) < 1.0e-11_wp, 'fit and iterative agree within 1e-11')
        call s%check(emax(3) < 1.0e-11_wp, 'fit against rk45 within 1e-11')

        ! edge cases
        call hertzdamp_invert(1.0_wp, 1.0e-4_wp, 1.0e-3_wp, 1.0_wp, iend, k, d, st, alpha=a, tau_c=tau)
        call s%check(st == HD_OK .and. same(a, 0.0_wp) .and. same(d, 0.0_wp) .and. k > 0.0_wp, 'e = 1: alpha = 0, d = 0')
        call s%check_close(tau, hertzdamp_tau_c0(), 1.0e-15_wp, 'e = 1: tau_c = tau_c0')
        call s%check_close(k, 1.0e-3_wp * (1.0e-4_wp / hertzdamp_tau_c0())**(-2.5_wp), 1.0e-14_wp, &
                           'e = 1: k = m t*^(-5/2) (elastic Hertz)')
        do j = 1, 5
            select case (j)
            case (1); e = 0.0_wp
            case (2); e = -0.5_wp
            case (3); e = 1.0000001_wp
            case (4); e = ieee_value(1.0_wp, ieee_quiet_nan)
            case default; e = 0.5_wp * merge(1.0e-3_wp, 1.0e-4_wp, iend == HD_END_OVERLAP)
            end select
            call hertzdamp_invert(e, 1.0e-4_wp, 1.0e-3_wp, 1.0_wp, iend, k, d, st, alpha=a, tstar=ts, tau_c=tau)
            call s%check(st == HD_BAD_RESTITUTION .and. same(k, 0.0_wp) .and. same(d, 0.0_wp) .and. same(a, 0.0_wp) .and. &
                         same(ts, 0.0_wp) .and. same(tau, 0.0_wp), 'bad e: HD_BAD_RESTITUTION, zero outputs')
        end do
    end do
    call hertzdamp_invert(5.0e-4_wp, 1.0e-4_wp, 1.0e-3_wp, 1.0_wp, HD_END_FORCE, k, d, st)
    call s%check(st == HD_OK, 'force accepts e = 5e-4')
    call hertzdamp_invert(0.5_wp, 0.0_wp, 1.0e-3_wp, 1.0_wp, 0, k, d, st)
    call s%check(st == HD_BAD_TIME .and. same(k, 0.0_wp), 'tc = 0: HD_BAD_TIME')
    call hertzdamp_invert(0.5_wp, ieee_value(1.0_wp, ieee_positive_inf), 1.0e-3_wp, 1.0_wp, 0, k, d, st)
    call s%check(st == HD_BAD_TIME, 'tc = inf: HD_BAD_TIME')
    call hertzdamp_invert(0.5_wp, 1.0e-4_wp, -1.0_wp, 1.0_wp, 0, k, d, st)
    call s%check(st == HD_BAD_MASS, 'm < 0: HD_BAD_MASS')
    call hertzdamp_invert(0.5_wp, 1.0e-4_wp, 1.0_wp, 0.0_wp, 0, k, d, st)
    call s%check(st == HD_BAD_VELOCITY, 'u = 0: HD_BAD_VELOCITY')
    call hertzdamp_invert(0.5_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, 0, k, d, st, k_phys=-1.0_wp)
    call s%check(st == HD_BAD_KPHYS, 'k_phys < 0: HD_BAD_KPHYS')
    call hertzdamp_invert(0.5_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, 2, k, d, st)
    call s%check(st == HD_BAD_END, 'iend = 2: HD_BAD_END')
    call hertzdamp_invert(0.5_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, 0, k, d, st, options=hertzdamp_invert_options(method=99))
    call s%check(st == HD_BAD_ARGUMENT, 'unknown method: HD_BAD_ARGUMENT')
    call hertzdamp_invert(0.5_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, 0, k, d, st, &
                          options=hertzdamp_invert_options(method=HD_METHOD_ITERATIVE, tol=0.5_wp))
    call s%check(st == HD_BAD_TOL, 'iterative tol 0.5: HD_BAD_TOL')
    call hertzdamp_invert(0.5_wp, 1.0e-300_wp, 1.0e300_wp, 1.0_wp, 0, k, d, st)
    call s%check(st == HD_OUT_OF_RANGE .and. same(k, 0.0_wp) .and. same(d, 0.0_wp), 'overflowing k: HD_OUT_OF_RANGE')
    ! issue 30, defect 5: a damping d > 0 that underflows is out of range, not an undamped contact
    call hertzdamp_invert(0.5_wp, 1.0e25_wp, 1.0e-300_wp, 1.0e-300_wp, 0, k, d, st)
    call s%check(st == HD_OUT_OF_RANGE .and. same(k, 0.0_wp) .and. same(d, 0.0_wp), &
                 'tc 1e25, m 1e-300, u 1e-300 (d underflows): HD_OUT_OF_RANGE, k = d = 0')
    call hertzdamp_invert(0.5_wp, 1.0e25_wp, 1.0e-310_wp, 1.0_wp, 0, k, d, st)
    call s%check(st == HD_OUT_OF_RANGE .and. same(k, 0.0_wp) .and. same(d, 0.0_wp), &
                 'tc 1e25, subnormal m 1e-310 (d underflows): HD_OUT_OF_RANGE, k = d = 0')
    call hertzdamp_invert(1.0_wp, 1.0e-4_wp, 1.0e-40_wp, 1.0_wp, 0, k, d, st)
    call s%check(st == HD_OK .and. k > 0.0_wp .and. same(d, 0.0_wp), &
                 'e = 1 (alpha = 0) on the logarithmic path: d = 0 is the undamped contact, status 0')

    ! log path = direct path (k is proportional to m at fixed t*, u: k(1e-40) = 1e-20 k(1e-20))
    call hertzdamp_invert(0.5_wp, 1.0e-4_wp, 1.0e-20_wp, 1.0_wp, 0, k, d, st)
    call hertzdamp_invert(0.5_wp, 1.0e-4_wp, 1.0e-40_wp, 1.0_wp, 0, k2, d2, st)
    call s%check_close(k2, 1.0e-20_wp * k, 1.0e-13_wp, 'log path k matches the direct path')
    call s%check_close(d2, 1.0e-20_wp * d, 1.0e-13_wp, 'log path d matches the direct path')

    ! physical stiffness bound
    call hertzdamp_invert(0.5_wp, 1.0e-4_wp, 1.0e-3_wp, 1.0_wp, 0, k, d, st, alpha=a)
    kb = 0.5_wp * k
    call hertzdamp_invert(0.5_wp, 1.0e-4_wp, 1.0e-3_wp, 1.0_wp, 0, k2, db, st, tstar=ts, bound_active=bound, k_phys=kb)
    call s%check(bound .and. same(k2, kb), 'k_phys <= k: k = k_phys, bound active')
    call s%check_close(db, a * (1.0e-3_wp)**0.6_wp * kb**0.4_wp, 1.0e-14_wp, 'bound: d = alpha m^3/5 k_phys^2/5 u^1/5')
    call hertzdamp_forward_dim(k2, db, 1.0e-3_wp, 1.0_wp, 0, HD_METHOD_RK45, al2, ts2, e2, tc2, zm, st, 1.0e-15_wp)
    call s%check_close(e2, 0.5_wp, 1.0e-11_wp, 'bound keeps e')
    call s%check(tc2 > 1.0e-4_wp, 'bound: the softer k_phys gives a longer contact than... (k_phys < k)')
    call hertzdamp_invert(0.5_wp, 1.0e-4_wp, 1.0e-3_wp, 1.0_wp, 0, k2, d2, st, bound_active=bound, k_phys=2.0_wp * k)
    call s%check(.not. bound .and. same(k2, k) .and. same(d2, d), 'k_phys > k: bound inactive')
    call hertzdamp_invert(0.5_wp, 1.0e-4_wp, 1.0e-3_wp, 1.0_wp, 0, k2, d2, st, k_phys=0.5_wp * k, tstar=ts, tau_c=tau)
    call s%check_close(ts * tau, tc2, 1.0e-11_wp, 'bound: tstar is the time unit of the returned k')

    ! compact method
    call hertzdamp_invert(0.5_wp, 1.0e-4_wp, 1.0e-3_wp, 1.0_wp, 0, k2, d2, st, &
                          options=hertzdamp_invert_options(method=HD_METHOD_COMPACT))
    call s%check(st == HD_OK .and. rel_err(k2, k) < 3.0e-5_wp .and. rel_err(d2, d) < 3.0e-5_wp, &
                 'compact method: k, d within 3e-5')
    call series_inverse_checks()
    call iterative_checks()
    call s%finish()

contains

    !> The iterative baseline (secant over rk45 solves at tol/10 min(1, |ln e|)) meets the
    !> accuracy asked of alpha for both ends over e in [e_min, 1): linear law against the
    !> fit (1e-13); tsuji overlap against its exact alpha(e) (hertzdamp_tsuji_alpha), tsuji
    !> force and kuwabara-kono against their fits (measured 2e-14 or better,
    !> data/fit_coefficients.csv).
    subroutine iterative_checks()
        real(wp) :: e, ai, ti, af, tf, worst, emin
        integer :: i, j, iend, law, st1, st2, nbad
        real(wp), parameter :: tols(3) = [1.0e-6_wp, 1.0e-8_wp, 1.0e-10_wp]
        character(len=8) :: ctol
        do law = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
            do iend = HD_END_OVERLAP, HD_END_FORCE
                emin = hertzdamp_fit_law_e_min(law, iend)
                do j = 1, size(tols)
                    if (law /= HD_DAMPING_LINEAR .and. j == 2) cycle
                    write (ctol, '(es8.1)') tols(j)
                    worst = 0.0_wp
                    nbad = 0
                    do i = 1, merge(25, 12, law == HD_DAMPING_LINEAR)
                        e = emin**((real(i, wp) - 0.5_wp) / real(merge(25, 12, law == HD_DAMPING_LINEAR), wp))
                        call hertzdamp_invert_alpha(e, iend, ai, ti, st1, method=HD_METHOD_ITERATIVE, tol=tols(j), &
                                                    law=law)
                        if (law == HD_DAMPING_TSUJI .and. iend == HD_END_OVERLAP) then
                            af = hertzdamp_tsuji_alpha(e)
                            st2 = HD_OK
                        else
                            call hertzdamp_invert_alpha(e, iend, af, tf, st2, law=law)
                        end if
                        if (st1 /= HD_OK .or. st2 /= HD_OK) nbad = nbad + 1
                        worst = max(worst, abs(ai - af) / af)
                    end do
                    print '(a, a, 1x, a, a, es9.2)', 'iterative ', trim(hertzdamp_law_name(law)), &
                        hertzdamp_end_name(iend), ' tol ' // ctol // ': max rel err alpha', worst
                    call s%check(nbad == 0 .and. worst <= tols(j), 'iterative: alpha within tol = ' // ctol // ' (' // &
                                 trim(hertzdamp_law_name(law)) // ', ' // hertzdamp_end_name(iend) // ')')
                end do
            end do
        end do
    end subroutine iterative_checks

    !> The series and Pade inverses (Newton on the formulas) against the fit (1e-13):
    !> without the accuracy guard they agree to the accuracy of the formula
    !> (default-order series 1e-12 at alpha <= 0.2, about 1e-5 at 0.8; Pade 1e-10 on
    !> [0, 0.8]); with it (default 1e-10, or 1e-6) every answer with status HD_OK is
    !> within that accuracy, and the guard lets the validated range through.
    subroutine series_inverse_checks()
        real(wp) :: e, af, tf, as, ts_, ap, tp
        real(wp), parameter :: accs(2) = [1.0e-10_wp, 1.0e-6_wp]
        integer :: i, j, st1, st2, st3, n_ok(2)
        do i = 0, 40
            e = 0.14_wp + 0.86_wp * real(i, wp) / 40.0_wp
            call hertzdamp_invert_alpha(e, HD_END_OVERLAP, af, tf, st1)
            call hertzdamp_invert_alpha(e, HD_END_OVERLAP, as, ts_, st2, method=HD_METHOD_SERIES, accuracy=huge(1.0_wp))
            call hertzdamp_invert_alpha(e, HD_END_OVERLAP, ap, tp, st3, method=HD_METHOD_PADE, accuracy=huge(1.0_wp))
            call s%check(st1 == HD_OK .and. st2 == HD_OK .and. st3 == HD_OK, 'series/pade inverse status (no guard)')
            call s%check(abs(as - af) <= merge(1.0e-11_wp, 1.0e-4_wp, af <= 0.2_wp) * max(af, 1.0e-3_wp), &
                         'series inverse agrees with fit')
            call s%check(abs(ap - af) <= 1.0e-9_wp * max(af, 1.0e-3_wp), 'pade inverse agrees with fit')
            call s%check(abs(tp - tf) <= 1.0e-9_wp * tf, 'pade tau_c agrees with fit')
        end do
        do j = 1, 2
            n_ok(j) = 0
            do i = 0, 200
                e = 0.05_wp + 0.95_wp * real(i, wp) / 200.0_wp
                call hertzdamp_invert_alpha(e, HD_END_OVERLAP, af, tf, st1)
                call hertzdamp_invert_alpha(e, HD_END_OVERLAP, as, ts_, st2, method=HD_METHOD_SERIES, accuracy=accs(j))
                call s%check(st2 == HD_OK .or. st2 == HD_INACCURATE .or. st2 == HD_OUTSIDE_VALIDITY, &
                             'series inverse with a guard: ok, inaccurate or outside validity')
                if (st2 == HD_OK) then
                    n_ok(j) = n_ok(j) + 1
                    call s%check(abs(as - af) <= accs(j) * max(af, 1.0e-3_wp) .and. abs(ts_ - tf) <= accs(j) * tf, &
                                 'series inverse with status ok is within the accuracy asked')
                else
                    call s%check(same(as, 0.0_wp) .and. same(ts_, 0.0_wp), 'series inverse refused: alpha = tau_c = 0')
                end if
                call hertzdamp_invert_alpha(e, HD_END_OVERLAP, ap, tp, st3, method=HD_METHOD_PADE, accuracy=accs(j))
                if (st3 == HD_OK) call s%check(abs(ap - af) <= accs(j) * max(af, 1.0e-3_wp) .and. &
                                               abs(tp - tf) <= accs(j) * tf, &
                                               'pade inverse with status ok is within the accuracy asked')
                ! the documented validated range: series at alpha <= 0.2 to 1e-12, Pade on [0, 0.8] to 1e-10
                if (af <= 0.2_wp) call s%check(st2 == HD_OK, 'series inverse ok at alpha <= 0.2')
            end do
        end do
        call s%check(n_ok(2) > n_ok(1), 'a looser accuracy lets more e through the series guard')
        call hertzdamp_invert_alpha(0.03_wp, HD_END_OVERLAP, as, ts_, st2, method=HD_METHOD_SERIES)
        call s%check(st2 == HD_OUTSIDE_VALIDITY .and. same(as, 0.0_wp), 'series inverse: e = 0.03 (alpha > 1) outside validity')
        call hertzdamp_invert_alpha(0.1_wp, HD_END_OVERLAP, as, ts_, st2, method=HD_METHOD_SERIES, accuracy=huge(1.0_wp))
        call hertzdamp_invert_alpha(0.1_wp, HD_END_OVERLAP, af, tf, st1)
        call s%check(st2 == HD_OK .and. abs(as - af) < 1.0e-2_wp * af, &
                     'series inverse at e = 0.1 (alpha 0.86 < 1, as the forward series) within its truncation error')
        call hertzdamp_invert_alpha(0.1_wp, HD_END_OVERLAP, as, ts_, st2, method=HD_METHOD_SERIES)
        call s%check(st2 == HD_INACCURATE, 'series inverse at e = 0.1 with the default guard: inaccurate')
        call hertzdamp_invert_alpha(0.1_wp, HD_END_OVERLAP, ap, tp, st3, method=HD_METHOD_PADE)
        call s%check(st3 == HD_OUTSIDE_VALIDITY, 'pade inverse: e = 0.1 (alpha > 0.8) outside validity')
        call hertzdamp_invert_alpha(0.5_wp, HD_END_FORCE, as, ts_, st2, method=HD_METHOD_PADE)
        call s%check(st2 == HD_NOT_SUPPORTED, 'pade inverse: force definition not supported')
        ! first order: alpha = (1 - e)/e1, tau_c = tau_c(0), exact at e = 1 with slope -e1
        call hertzdamp_invert_alpha(0.9_wp, HD_END_OVERLAP, as, ts_, st2, method=HD_METHOD_FIRST_ORDER)
        call s%check(st2 == HD_OK .and. abs(as - 0.1_wp / hertzdamp_e1()) <= 1.0e-15_wp .and. &
                     same(ts_, hertzdamp_tau_c0()), 'first-order inverse: alpha = (1 - e)/e1, tau_c = tau_c(0)')
    end subroutine series_inverse_checks

    !> Exact equality without -Wcompare-reals.
    pure logical function same(x, y)
        real(wp), intent(in) :: x, y
        same = .not. (abs(x - y) > 0.0_wp)
    end function same
end program test_inverse
