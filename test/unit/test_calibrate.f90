!> Tests of the calibration fit (packages/calibrate: hertzdamp_calibrate, hertzdamp_calibrate_maps).
!>
!> - derivatives of the forward maps against central differences of the core fit and
!>   of the reference integrator;
!> - noise-free data made by the reference integrator (rk45, tol 1e-13) from known k and
!>   d, every law the library has and both contact ends: the fit recovers k and d (or,
!>   from e alone, the combination c = d k^(-2(1+q)/5)) to 1e-8 relative, also from
!>   starts far away, and `auto` chooses the law that made the data;
!> - e alone cannot tell k: two (k, d) pairs with the same c give the same e(u) (rk45);
!> - noisy data (sigma_e = 0.005, sigma_tc = 1 %, fixed seeds of a generator written
!>   here): over many seeds the true values lie within the reported standard
!>   uncertainty in 68.27 % of the fits and within two in 95.45 %, each within a
!>   binomial allowance of 3.5 standard deviations; the p-values of chi2 are uniform
!>   (5 % below 0.05, same allowance); the mean chi2/dof is 1;
!> - the p-value function against closed forms;
!> - ill-posed inputs fail with the status that names them, a fit that cannot
!>   converge says so, data far from the law is reported with its residuals.
program test_calibrate
    use hertzdamp
    use hertzdamp_calibrate
    use hertzdamp_calibrate_maps
    use hertzdamp_testing, only: test_suite, new_suite, rel_err
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: int64 = selected_int_kind(18)
    real(wp), parameter :: pi = acos(-1.0_wp)
    type(test_suite) :: s
    !> Combined multiplicative congruential generator (L'Ecuyer 1988): two streams
    !> modulo 2147483563 and 2147483399, products below 2^47 (no overflow in int64).
    integer(int64) :: rng1 = 12345_int64, rng2 = 67890_int64
    integer :: law

    s = new_suite('test_calibrate')
    call test_gamma_q()
    do law = 0, cal_max_law
        call test_derivatives(law)
        call test_noise_free(law, HD_END_OVERLAP)
        call test_noise_free(law, HD_END_FORCE)
        call test_coverage(law)
    end do
    call test_unidentifiable_k()
    call test_ill_posed()
    call test_far_from_law()
    call test_beyond_maps()
    call test_exact_sweep()
    call test_huge_sigmas()
    call test_start_messages()
    call s%finish()

contains

    ! ------------------------------------------------------------------ helpers

    subroutine seed(k)
        integer, intent(in) :: k
        rng1 = 12345_int64 + 7919_int64 * k
        rng2 = 67890_int64 + 104729_int64 * k
    end subroutine seed

    !> Uniform in (0, 1).
    real(wp) function uniform() result(x)
        integer(int64) :: z
        rng1 = mod(40014_int64 * rng1, 2147483563_int64)
        rng2 = mod(40692_int64 * rng2, 2147483399_int64)
        z = mod(rng1 - rng2, 2147483562_int64)
        if (z < 1) z = z + 2147483562_int64
        x = real(z, wp) / 2147483563.0_wp
    end function uniform

    !> Standard normal (Box-Muller).
    real(wp) function normal() result(x)
        real(wp) :: u1, u2
        u1 = uniform()
        u2 = uniform()
        x = sqrt(-2.0_wp * log(u1)) * cos(2.0_wp * pi * u2)
    end function normal

    !> e and T_c of law `law` for k, d, m at speeds u by the reference integrator
    !> (the core's dimensional forward map: alpha = d t* (u t*)^q / m computed there).
    subroutine rk45_data(law, iend, k, d, m, u, e, tc)
        integer, intent(in) :: law, iend
        real(wp), intent(in) :: k, d, m, u(:)
        real(wp), intent(out) :: e(:), tc(:)
        real(wp) :: alpha, tstar, zm
        integer :: i, st
        do i = 1, size(u)
            call hertzdamp_forward_dim(k, d, m, u(i), iend, HD_METHOD_RK45, alpha, tstar, e(i), tc(i), zm, st, law=law)
            if (st /= HD_OK) error stop 'rk45_data: the reference integrator failed'
        end do
    end subroutine rk45_data

    !> d for law q that gives alpha = alpha1 at u = 1 m/s with k and m.
    pure real(wp) function d_for(law, alpha1, k, m) result(d)
        integer, intent(in) :: law
        real(wp), intent(in) :: alpha1, k, m
        real(wp) :: tstar, q
        q = cal_law_q(law)
        tstar = (m / k)**0.4_wp
        d = alpha1 * m / (tstar * tstar**q)
    end function d_for

    ! ------------------------------------------------------------------ tests

    subroutine test_gamma_q()
        real(wp) :: x, worst(4), sq
        integer :: i
        worst = 0.0_wp
        do i = 1, 60
            x = 0.05_wp * i**1.5_wp
            sq = sqrt(x)
            ! Q(1, x) = exp(-x); Q(1/2, x) = erfc(sqrt x); Q(3/2, x) = erfc(sqrt x) + 2 sqrt(x/pi) e^-x;
            ! Q(3, x) = e^-x (1 + x + x^2/2)
            worst(1) = max(worst(1), rel_err(cal_gamma_q(1.0_wp, x), exp(-x)))
            worst(2) = max(worst(2), rel_err(cal_gamma_q(0.5_wp, x), erfc(sq)))
            worst(3) = max(worst(3), rel_err(cal_gamma_q(1.5_wp, x), erfc(sq) + 2.0_wp * sqrt(x / pi) * exp(-x)))
            worst(4) = max(worst(4), rel_err(cal_gamma_q(3.0_wp, x), exp(-x) * (1.0_wp + x + 0.5_wp * x * x)))
        end do
        call s%check(maxval(worst) < 1.0e-12_wp, 'gamma Q(a, x) against closed forms for a = 1, 1/2, 3/2, 3')
        print '(a,4es10.2)', 'gamma Q: max rel err (a = 1, 1/2, 3/2, 3): ', worst
        call s%check(cal_gamma_q(2.0_wp, 0.0_wp) == 1.0_wp, 'Q(a, 0) = 1')
    end subroutine test_gamma_q

    !> The exact derivative of the fit against central differences of the core's fit
    !> (h = 1e-5 of alpha, and of alpha_c - alpha for an overlap end with alpha_c) and
    !> of rk45 (tol 1e-14, h = 1e-4 of the same); the rk45 method's differences against
    !> the fit derivative.  alpha over the fitted range of each law and end (e >= 1e-5).
    subroutine test_derivatives(law)
        integer, intent(in) :: law
        real(wp) :: a, h, e, tau, de, dtau, ep, tp, em, tm, worst(3), e2, t2, de2, dt2, amax(0:1), gap, ac
        integer :: iend, i, st, sp, sm, st2
        type(hertzdamp_collision) :: rp, rm
        character(len=:), allocatable :: tag
        ! largest alpha of the fitted forward maps: overlap, force
        select case (law)
        case (CAL_LAW_LINEAR); amax = [1.12_wp, 52.0_wp]
        case (CAL_LAW_TSUJI); amax = [2.15_wp, 350.0_wp]
        case default; amax = [13.8_wp, 1170.0_wp]
        end select
        do iend = HD_END_OVERLAP, HD_END_FORCE
            tag = ' (' // cal_law_name(law) // ', ' // hertzdamp_end_name(iend) // ')'
            worst = 0.0_wp
            ac = huge(1.0_wp)
            if (iend == HD_END_OVERLAP) ac = hertzdamp_law_alpha_c(law)
            do i = 1, 97
                a = amax(iend) * (real(i, wp) / 97.0_wp)**2
                call cal_forward(law, iend, HD_METHOD_FIT, a, e, tau, de, dtau, st)
                gap = min(a, ac - a)
                h = 1.0e-5_wp * gap
                call hertzdamp_fit_law_forward(a + h, iend, law, ep, tp, sp)
                call hertzdamp_fit_law_forward(a - h, iend, law, em, tm, sm)
                if (st /= HD_OK .or. sp /= HD_OK .or. sm /= HD_OK) then
                    worst = huge(1.0_wp)
                    exit
                end if
                worst(1) = max(worst(1), abs(de - (ep - em) / (2 * h)) / abs(de), &
                               abs(dtau - (tp - tm) / (2 * h)) / abs(dtau))
                h = 1.0e-4_wp * gap
                rp = hertzdamp_rk45_collide(a + h, iend, 1.0e-14_wp, law)
                rm = hertzdamp_rk45_collide(a - h, iend, 1.0e-14_wp, law)
                worst(2) = max(worst(2), abs(de - (rp%e - rm%e) / (2 * h)) / abs(de), &
                               abs(dtau - (rp%tau_c - rm%tau_c) / (2 * h)) / abs(dtau))
                call cal_forward(law, iend, HD_METHOD_RK45, a, e2, t2, de2, dt2, st2)
                worst(3) = max(worst(3), rel_err(e2, e), rel_err(t2, tau), rel_err(de2, de), rel_err(dt2, dtau))
                if (st2 /= HD_OK) worst(3) = huge(1.0_wp)
            end do
            print '(a,3es10.2)', 'derivatives: fit vs differences of fit, of rk45; rk45 method' // tag // ': ', worst
            call s%check(worst(1) < 1.0e-6_wp, 'fit derivative = differences of the fit' // tag)
            call s%check(worst(2) < 1.0e-6_wp, 'fit derivative = differences of rk45' // tag)
            call s%check(worst(3) < 1.0e-6_wp, 'rk45 method: values and differences' // tag)
        end do
        if (law /= CAL_LAW_LINEAR) return
        call cal_forward(CAL_LAW_LINEAR, HD_END_OVERLAP, HD_METHOD_FIT, 1.2_wp, e, tau, de, dtau, st)
        call s%check(st == HD_NO_REBOUND .and. e == 0.0_wp .and. tau == 0.0_wp, 'alpha > alpha_c: no rebound, zeros')
        ! beyond the fitted maps: the reference integrator, as with --method rk45
        call cal_forward(CAL_LAW_LINEAR, HD_END_FORCE, HD_METHOD_FIT, 60.0_wp, e, tau, de, dtau, st)
        call cal_forward(CAL_LAW_LINEAR, HD_END_FORCE, HD_METHOD_RK45, 60.0_wp, e2, t2, de2, dt2, st2)
        call s%check(st == HD_OK .and. st2 == HD_OK .and. e == e2 .and. tau == t2 .and. de == de2 .and. dtau == dt2 &
                     .and. e > 0.0_wp, 'force alpha beyond the fit: the values and differences of rk45')
        call cal_forward(CAL_LAW_LINEAR, HD_END_OVERLAP, HD_METHOD_FIT, 0.0_wp, e, tau, de, dtau, st)
        call s%check(st == HD_BAD_ALPHA, 'alpha = 0: HD_BAD_ALPHA (the fit works in ln alpha)')
    end subroutine test_derivatives

    !> Noise-free rk45 data: recovery to 1e-8 and the choice of the law.
    subroutine test_noise_free(law, iend)
        integer, intent(in) :: law, iend
        real(wp), parameter :: u(7) = [0.2_wp, 0.5_wp, 1.0_wp, 2.0_wp, 4.0_wp, 7.0_wp, 10.0_wp]
        real(wp), parameter :: m = 2.0e-3_wp, k = 3.0e9_wp
        real(wp) :: alpha1(2), e(7), tc(7), d, c, worst
        type(cal_options) :: o
        type(cal_result) :: res, all(0:cal_max_law)
        integer :: i, j, chosen
        character(len=:), allocatable :: tag
        alpha1 = [0.05_wp, 0.4_wp]   ! alpha at 1 m/s: nearly elastic and strongly damped
        o%mass = m
        o%iend = iend
        do j = 1, 2
            tag = ' (' // cal_law_name(law) // ', ' // hertzdamp_end_name(iend) // ', alpha(1 m/s) = ' // &
                  merge('0.05', '0.4 ', j == 1) // ')'
            d = d_for(law, alpha1(j), k, m)
            c = d * k**(-2.0_wp * (1.0_wp + cal_law_q(law)) / 5.0_wp)
            call rk45_data(law, iend, k, d, m, u, e, tc)
            ! e and tc: k and d
            call cal_fit(cal_make_data(u, e, tc), law, o, res)
            call s%check(res%status == CAL_OK .and. res%k_fitted .and. res%n_par == 2, 'e+tc fit converges' // tag)
            call s%check_close(res%k, k, 1.0e-10_wp, 'e+tc: k recovered to 1e-10' // tag)
            call s%check_close(res%d, d, 1.0e-10_wp, 'e+tc: d recovered to 1e-10' // tag)
            worst = max(rel_err(res%k, k), rel_err(res%d, d))
            ! from far away: A / 20 with k x 1000, and A x 5 with k / 1000 (from 20 times
            ! more damping the fit of kuwabara-kono can end on the plateau e ~ 0 and say so)
            do i = 1, 2
                o%a_start = alpha1(j) * merge(0.05_wp, 5.0_wp, i == 1)
                o%k_start = k * merge(1.0e3_wp, 1.0e-3_wp, i == 1)
                call cal_fit(cal_make_data(u, e, tc), law, o, res)
                call s%check(res%status == CAL_OK .and. res%iterations > 3, 'e+tc fit from far away converges' // tag)
                call s%check_close(res%k, k, 1.0e-10_wp, 'e+tc from far away: k to 1e-10' // tag)
                call s%check_close(res%d, d, 1.0e-10_wp, 'e+tc from far away: d to 1e-10' // tag)
                worst = max(worst, rel_err(res%k, k), rel_err(res%d, d))
            end do
            o%a_start = 0.0_wp
            o%k_start = 0.0_wp
            ! e only: the combination c; k and d not identified
            call cal_fit(cal_make_data(u, e), law, o, res)
            call s%check(res%status == CAL_OK .and. .not. res%kd_known .and. res%n_par == 1, 'e-only fit: c only' // tag)
            call s%check_close(res%c, c, 1.0e-10_wp, 'e only: c = d k^(-2(1+q)/5) recovered to 1e-10' // tag)
            call s%check_close(res%a, alpha1(j) , 1.0e-10_wp, 'e only: A = alpha at 1 m/s to 1e-10' // tag)
            worst = max(worst, rel_err(res%c, c))
            ! e only with k known: d
            o%k_known = k
            call cal_fit(cal_make_data(u, e), law, o, res)
            o%k_known = 0.0_wp
            call s%check(res%status == CAL_OK .and. res%kd_known .and. .not. res%k_fitted, 'e + known k' // tag)
            call s%check_close(res%d, d, 1.0e-8_wp, 'e + known k: d to 1e-8' // tag)
            ! the reference integrator in the loop (checking): the same answer
            o%method = HD_METHOD_RK45
            call cal_fit(cal_make_data(u, e, tc), law, o, res)
            o%method = HD_METHOD_FIT
            call s%check(res%status == CAL_OK, '--method rk45 converges' // tag)
            call s%check_close(res%k, k, 1.0e-9_wp, 'rk45 method: k to 1e-9' // tag)
            call s%check_close(res%d, d, 1.0e-9_wp, 'rk45 method: d to 1e-9' // tag)
            ! auto: the law that made the data, with and without contact times
            call cal_auto(cal_make_data(u, e, tc), o, all, chosen)
            call s%check(chosen == law, 'auto (e, tc) picks the law that made the data' // tag)
            call cal_auto(cal_make_data(u, e), o, all, chosen)
            call s%check(chosen == law, 'auto (e only) picks the law that made the data' // tag)
            print '(a,es10.2)', 'noise-free recovery, worst rel err' // tag // ': ', worst
        end do
    end subroutine test_noise_free

    !> Coverage of the reported uncertainties over many seeds.
    subroutine test_coverage(law)
        integer, intent(in) :: law
        integer, parameter :: nseed = 1000, n = 8
        real(wp), parameter :: sig_e = 0.005_wp, sig_t = 0.01_wp, m = 1.0e-3_wp, k = 1.0e9_wp
        real(wp) :: u(n), e0(n), tc0(n), e(n), tc(n), se(n), st(n), d, c, chi, x
        real(wp) :: inside(2, 3), small_p, z
        type(cal_options) :: o
        type(cal_result) :: r1, r2
        integer :: i, j, good
        character(len=:), allocatable :: tag
        u = [0.3_wp, 0.6_wp, 1.0_wp, 1.5_wp, 2.5_wp, 4.0_wp, 6.0_wp, 9.0_wp]
        d = d_for(law, 0.15_wp, k, m)
        c = d * k**(-2.0_wp * (1.0_wp + cal_law_q(law)) / 5.0_wp)
        call rk45_data(law, HD_END_OVERLAP, k, d, m, u, e0, tc0)
        o%mass = m
        se = sig_e
        st = sig_t * tc0
        inside = 0.0_wp
        small_p = 0.0_wp
        chi = 0.0_wp
        good = 0
        call seed(law + 1)   ! one fixed seed per law; the trials draw from the stream in turn
        do i = 1, nseed
            do j = 1, n
                e(j) = e0(j) + sig_e * normal()
                tc(j) = tc0(j) + st(j) * normal()
            end do
            call cal_fit(cal_make_data(u, e, sigma_e=se), law, o, r1)
            call cal_fit(cal_make_data(u, e, tc, se, st), law, o, r2)
            if (r1%status /= CAL_OK .or. r2%status /= CAL_OK) then
                print '(a)', 'noisy fit failed: ' // r1%message // ' / ' // r2%message
                cycle
            end if
            good = good + 1
            do j = 1, 2   ! within 1 and 2 standard uncertainties
                x = real(j, wp)
                if (abs(r1%c - c) <= x * r1%c_err) inside(j, 1) = inside(j, 1) + 1
                if (abs(r2%k - k) <= x * r2%k_err) inside(j, 2) = inside(j, 2) + 1
                if (abs(r2%d - d) <= x * r2%d_err) inside(j, 3) = inside(j, 3) + 1
            end do
            if (r2%p_value < 0.05_wp) small_p = small_p + 1
            chi = chi + r2%chi2 / r2%dof
        end do
        tag = ' (' // cal_law_name(law) // ')'
        call s%check(good == nseed, 'every noisy fit converges' // tag)
        inside = inside / max(good, 1)
        print '(a,3f8.4,a,3f8.4)', 'coverage' // tag // ' c, k, d within 1 sigma: ', inside(1, :), '; 2 sigma: ', inside(2, :)
        print '(a,f8.4,a,f8.4)', 'fraction p < 0.05: ', small_p / max(good, 1), ', mean chi2/dof: ', chi / max(good, 1)
        ! binomial allowance: 3.5 standard deviations of a fraction over nseed fits
        z = 3.5_wp
        do j = 1, 3
            call s%check(abs(inside(1, j) - 0.6827_wp) <= z * sqrt(0.6827_wp * 0.3173_wp / nseed), &
                         'coverage of 1 standard uncertainty near 68.27 %' // tag)
            call s%check(abs(inside(2, j) - 0.9545_wp) <= z * sqrt(0.9545_wp * 0.0455_wp / nseed), &
                         'coverage of 2 standard uncertainties near 95.45 %' // tag)
        end do
        call s%check(abs(small_p / max(good, 1) - 0.05_wp) <= z * sqrt(0.05_wp * 0.95_wp / nseed), &
                     'p-values uniform: 5 % below 0.05' // tag)
        ! mean of chi2/dof over nseed fits (dof = 14): 1 within 3.5 sd, sd = sqrt(2/dof/nseed)
        call s%check(abs(chi / max(good, 1) - 1.0_wp) <= z * sqrt(2.0_wp / 14.0_wp / nseed), 'mean chi2/dof = 1' // tag)
    end subroutine test_coverage

    !> Two (k, d) with the same c = d k^(-2/5) give the same e(u): k cannot be known
    !> from e alone (the reference integrator, linear law), and the fit says so.
    subroutine test_unidentifiable_k()
        real(wp), parameter :: u(4) = [0.5_wp, 1.0_wp, 2.0_wp, 4.0_wp], m = 1.0e-3_wp
        real(wp) :: e1(4), e2(4), tc1(4), tc2(4), k1, k2, d1, d2
        type(cal_options) :: o
        type(cal_result) :: r1, r2
        k1 = 1.0e9_wp
        d1 = 3.0_wp
        k2 = 7.0e10_wp
        d2 = d1 * (k2 / k1)**0.4_wp
        call rk45_data(CAL_LAW_LINEAR, HD_END_OVERLAP, k1, d1, m, u, e1, tc1)
        call rk45_data(CAL_LAW_LINEAR, HD_END_OVERLAP, k2, d2, m, u, e2, tc2)
        call s%check(maxval(abs(e1 - e2)) < 1.0e-12_wp, 'same d k^(-2/5), different k: the same e(u)')
        call s%check(maxval(abs(tc1 / tc2 - (k2 / k1)**0.4_wp)) < 1.0e-11_wp, '... and T_c in the ratio (k2/k1)^(2/5)')
        o%mass = m
        call cal_fit(cal_make_data(u, e1), CAL_LAW_LINEAR, o, r1)
        call cal_fit(cal_make_data(u, e2), CAL_LAW_LINEAR, o, r2)
        call s%check(r1%status == CAL_OK .and. .not. r1%kd_known .and. r1%k == 0.0_wp .and. r1%d == 0.0_wp, &
                     'e only: k and d reported as not identified')
        call s%check_close(r1%c, r2%c, 1.0e-10_wp, 'e only: the same c from both')
    end subroutine test_unidentifiable_k

    !> Each ill-posed input fails with its status and a message.
    subroutine test_ill_posed()
        real(wp), parameter :: u(3) = [0.5_wp, 1.0_wp, 2.0_wp]
        real(wp) :: e(3), tc(3), nan
        type(cal_options) :: o
        type(cal_result) :: r
        nan = ieee_value(1.0_wp, ieee_quiet_nan)
        e = [0.8_wp, 0.82_wp, 0.84_wp]
        tc = [5.0e-5_wp, 4.5e-5_wp, 4.0e-5_wp]
        o%mass = 1.0e-3_wp
        call expect(o, cal_make_data([1.0_wp, 1.0_wp, 1.0_wp], e), CAL_NOT_IDENTIFIED, 'one impact speed only')
        call expect(o, cal_make_data(u, [1.0_wp, 1.0_wp, 1.0_wp]), CAL_NOT_IDENTIFIED, 'e = 1 everywhere')
        call expect(o, cal_make_data(u, [0.8_wp, 1.01_wp, 0.84_wp]), CAL_BAD_DATA, 'e > 1')
        call expect(o, cal_make_data(u, [0.8_wp, 0.0_wp, 0.84_wp]), CAL_BAD_DATA, 'e = 0')
        call expect(o, cal_make_data(u, [0.8_wp, nan, 0.84_wp]), CAL_BAD_DATA, 'e NaN')
        call expect(o, cal_make_data([0.5_wp, -1.0_wp, 2.0_wp], e), CAL_BAD_DATA, 'negative speed')
        call expect(o, cal_make_data([0.5_wp, 0.0_wp, 2.0_wp], e), CAL_BAD_DATA, 'zero speed')
        call expect(o, cal_make_data([0.5_wp, nan, 2.0_wp], e), CAL_BAD_DATA, 'speed NaN')
        call expect(o, cal_make_data(u, e, [5.0e-5_wp, nan, 4.0e-5_wp]), CAL_BAD_DATA, 'tc NaN')
        call expect(o, cal_make_data(u, e, [5.0e-5_wp, -1.0_wp, 4.0e-5_wp]), CAL_BAD_DATA, 'tc < 0')
        call expect(o, cal_make_data(u, e, sigma_e=[0.01_wp, 0.0_wp, 0.01_wp]), CAL_BAD_DATA, 'sigma_e = 0')
        call expect(o, cal_make_data(u, e, sigma_e=[0.01_wp, nan, 0.01_wp]), CAL_BAD_DATA, 'sigma_e NaN')
        call expect(o, cal_make_data(u, e, tc, [0.01_wp, 0.01_wp, 0.01_wp], [1.0e-6_wp, -1.0e-6_wp, 1.0e-6_wp]), &
                    CAL_BAD_DATA, 'sigma_tc < 0')
        call expect(o, cal_make_data(u(1:0), e(1:0)), CAL_BAD_DATA, 'no rows')
        o%mass = -1.0_wp
        call expect(o, cal_make_data(u, e), CAL_BAD_DATA, 'mass < 0')
        o%mass = nan
        call expect(o, cal_make_data(u, e), CAL_BAD_DATA, 'mass NaN')
        o%mass = 1.0e-3_wp
        ! a fit that cannot converge in the iterations allowed says so
        o%max_iter = 2
        o%a_start = 50.0_wp
        o%k_start = 1.0e3_wp
        call expect(o, cal_make_data(u, e, tc), CAL_NO_CONVERGENCE, 'two iterations from far away')
        o%max_iter = 100
        o%a_start = 0.0_wp
        o%k_start = 0.0_wp
        call cal_fit(cal_make_data(u, e), 7, o, r)
        call s%check(r%status /= CAL_OK .and. len(r%message) > 0, 'unknown law: failure with a message')
    end subroutine test_ill_posed

    subroutine expect(o, dat, status, label)
        type(cal_options), intent(in) :: o
        type(cal_data), intent(in) :: dat
        integer, intent(in) :: status
        character(len=*), intent(in) :: label
        type(cal_result) :: res
        call cal_fit(dat, CAL_LAW_LINEAR, o, res)
        call s%check(res%status == status .and. len(res%message) > 0, 'ill-posed: ' // label // ' -> ' // &
                     res%message)
        call s%check(res%k == 0.0_wp .and. res%d == 0.0_wp .and. res%c == 0.0_wp, 'ill-posed: ' // label // &
                     ': no numbers')
    end subroutine expect

    !> Data no law follows (e alternating with speed): the fit converges and says
    !> that the data are far from it; the residuals are there.
    subroutine test_far_from_law()
        real(wp), parameter :: u(6) = [0.5_wp, 1.0_wp, 2.0_wp, 3.0_wp, 4.0_wp, 5.0_wp]
        real(wp), parameter :: e(6) = [0.9_wp, 0.6_wp, 0.9_wp, 0.6_wp, 0.9_wp, 0.6_wp]
        type(cal_options) :: o
        type(cal_result) :: r
        o%mass = 1.0e-3_wp
        call cal_fit(cal_make_data(u, e, sigma_e=spread(0.005_wp, 1, 6)), CAL_LAW_LINEAR, o, r)
        call s%check(r%status == CAL_OK, 'far from the law: the fit converges ' // r%message)
        call s%check(r%p_value < 1.0e-10_wp .and. index(r%note, 'far from') > 0, 'far from the law: p tiny, noted: ' // &
                     r%note)
        call s%check(r%rms_e > 0.1_wp .and. allocated(r%e_fit), 'far from the law: the residuals are reported')
    end subroutine test_far_from_law

    ! ------------------------------------------------------------------ issue 21

    !> n speeds from u0 to u1, evenly spaced in log.
    pure function log_speeds(u0, u1, n) result(u)
        real(wp), intent(in) :: u0, u1
        integer, intent(in) :: n
        real(wp) :: u(n)
        integer :: i
        do i = 1, n
            u(i) = u0 * (u1 / u0)**(real(i - 1, wp) / (n - 1))
        end do
    end function log_speeds

    !> Exact data (rk45) beyond the fitted maps, the datasets of issue 21: e below
    !> 1e-5 (kuwabara-kono, overlap, k = 1e6, d = 2512) and force-end alpha beyond 52.5
    !> (linear).  Before: `auto` chose tsuji with kuwabara-kono `no-convergence`, and
    !> the explicit kuwabara-kono fit ended at k = 1978, d = 11.6 with status ok.
    subroutine test_beyond_maps()
        real(wp), parameter :: k = 1.0e6_wp, d = 2512.0_wp
        real(wp) :: ua(5), ub(7), uc(6), ea(5), ta(5), eb(7), tb(7), ec(6), tc(6), dl, worst
        type(cal_options) :: o
        type(cal_result) :: r, all(0:cal_max_law)
        integer :: chosen
        ! item 2: m = 1e-3, 1 to 10 m/s: e = 5.2e-5 down to 5.2e-6
        ua = log_speeds(1.0_wp, 10.0_wp, 5)
        call rk45_data(CAL_LAW_KUWABARA_KONO, HD_END_OVERLAP, k, d, 1.0e-3_wp, ua, ea, ta)
        call s%check(minval(ea) < 5.2e-6_wp .and. maxval(ea) > 5.1e-5_wp, 'beyond the maps: e from 5.2e-5 to 5.2e-6')
        o%mass = 1.0e-3_wp
        call cal_auto(cal_make_data(ua, ea, ta), o, all, chosen)
        call s%check(chosen == CAL_LAW_KUWABARA_KONO, 'beyond the maps (e, tc): auto picks kuwabara-kono')
        if (chosen >= 0) then
            call s%check_close(all(chosen)%k, k, 1.0e-8_wp, 'beyond the maps (e, tc), auto: k to 1e-8')
            call s%check_close(all(chosen)%d, d, 1.0e-8_wp, 'beyond the maps (e, tc), auto: d to 1e-8')
        end if
        call cal_auto(cal_make_data(ua, ea), o, all, chosen)
        call s%check(chosen == CAL_LAW_KUWABARA_KONO, 'beyond the maps (e only): auto picks kuwabara-kono')
        if (chosen >= 0) call s%check_close(all(chosen)%c, d * k**(-0.6_wp), 1.0e-8_wp, &
                                            'beyond the maps (e only), auto: c to 1e-8')
        ! item 3: m = 1e-4, 0.01 to 10 m/s: e = 5.2e-5 down to 5.2e-8, explicit law
        ub = log_speeds(0.01_wp, 10.0_wp, 7)
        call rk45_data(CAL_LAW_KUWABARA_KONO, HD_END_OVERLAP, k, d, 1.0e-4_wp, ub, eb, tb)
        o%mass = 1.0e-4_wp
        call cal_fit(cal_make_data(ub, eb, tb), CAL_LAW_KUWABARA_KONO, o, r)
        call s%check(r%status == CAL_OK, 'beyond the maps, explicit kuwabara-kono: converges ' // r%message)
        call s%check_close(r%k, k, 1.0e-8_wp, 'beyond the maps, explicit kuwabara-kono: k to 1e-8')
        call s%check_close(r%d, d, 1.0e-8_wp, 'beyond the maps, explicit kuwabara-kono: d to 1e-8')
        call s%check(maxval(abs(r%e_fit - eb) / eb) < 1.0e-8_wp, 'beyond the maps: every e reproduced to 1e-8')
        worst = maxval(abs(r%e_fit - eb) / eb)
        ! linear, force end, alpha = 126 ... 50 (the fitted force map ends at 52.5)
        uc = log_speeds(0.1_wp, 10.0_wp, 6)
        dl = d_for(CAL_LAW_LINEAR, 80.0_wp, 1.0e9_wp, 2.0e-3_wp)
        call rk45_data(CAL_LAW_LINEAR, HD_END_FORCE, 1.0e9_wp, dl, 2.0e-3_wp, uc, ec, tc)
        o%mass = 2.0e-3_wp
        o%iend = HD_END_FORCE
        call cal_auto(cal_make_data(uc, ec, tc), o, all, chosen)
        call s%check(chosen == CAL_LAW_LINEAR, 'force alpha beyond 52.5 (e, tc): auto picks linear')
        if (chosen >= 0) then
            call s%check_close(all(chosen)%k, 1.0e9_wp, 1.0e-8_wp, 'force alpha beyond 52.5: k to 1e-8')
            call s%check_close(all(chosen)%d, dl, 1.0e-8_wp, 'force alpha beyond 52.5: d to 1e-8')
        end if
        print '(a,es10.2)', 'beyond the maps: worst relative e residual (0.01-10 m/s, e down to 5e-8): ', worst
    end subroutine test_beyond_maps

    !> Exact data of every law and end over a range of damping (alpha at 1 m/s from
    !> 0.05 to 0.9 alpha_c, 20 for kuwabara-kono (e to 4e-7), 150 with the force end,
    !> beyond the linear law's fitted 52.5), speeds 0.05 to 20 m/s:
    !> the true law recovers k and d to 1e-8, auto picks it, and every fit reported ok
    !> without sigmas has its last Gauss-Newton correction below the tolerance (never a
    !> fit that stopped short of it: before, the tolerance grew with the residuals).
    subroutine test_exact_sweep()
        integer, parameter :: nu = 6
        real(wp), parameter :: k = 2.0e8_wp, m = 5.0e-4_wp
        real(wp) :: u(nu), e(nu), tc(nu), d, alpha1, amax
        type(cal_options) :: o
        type(cal_result) :: r, all(0:cal_max_law)
        integer :: law, iend, j, chosen, l, nfit, nok, nrec, npick, nhonest, nall
        u = log_speeds(0.05_wp, 20.0_wp, nu)
        nfit = 0
        nok = 0
        nrec = 0
        npick = 0
        nhonest = 0
        nall = 0
        o%mass = m
        do law = 0, cal_max_law
            do iend = HD_END_OVERLAP, HD_END_FORCE
                o%iend = iend
                amax = merge(0.9_wp * hertzdamp_law_alpha_c(law), 150.0_wp, iend == HD_END_OVERLAP)
                if (law == CAL_LAW_KUWABARA_KONO .and. iend == HD_END_OVERLAP) amax = 20.0_wp
                do j = 0, 5
                    alpha1 = 0.05_wp * (amax / 0.05_wp)**(real(j, wp) / 5.0_wp)
                    ! the overlap end of linear and tsuji: alpha at the slowest speed below alpha_c
                    if (iend == HD_END_OVERLAP .and. law /= CAL_LAW_KUWABARA_KONO) then
                        alpha1 = min(alpha1, amax * minval(u)**(-cal_law_speed_exponent(law)) * 0.999_wp)
                    end if
                    d = d_for(law, alpha1, k, m)
                    call rk45_data(law, iend, k, d, m, u, e, tc)
                    call cal_fit(cal_make_data(u, e, tc), law, o, r)
                    nfit = nfit + 1
                    if (r%status == CAL_OK) nok = nok + 1
                    if (rel_err(r%k, k) < 1.0e-8_wp .and. rel_err(r%d, d) < 1.0e-8_wp) nrec = nrec + 1
                    if (.not. (r%status == CAL_OK .and. rel_err(r%k, k) < 1.0e-8_wp .and. rel_err(r%d, d) < 1.0e-8_wp)) then
                        print '(a,i0,a,i0,a,es10.3,a,2es12.4,1x,a)', 'exact sweep: law ', law, ' end ', iend, &
                            ' alpha1 ', alpha1, ': k, d ', r%k, r%d, r%message
                    end if
                    call cal_auto(cal_make_data(u, e, tc), o, all, chosen)
                    if (chosen == law) npick = npick + 1
                    do l = 0, cal_max_law
                        if (all(l)%status /= CAL_OK) cycle
                        nall = nall + 1
                        if (all(l)%gn_step <= 1.0e-10_wp) nhonest = nhonest + 1
                    end do
                end do
            end do
        end do
        print '(a,6(i0,1x))', 'exact sweep: fits, ok, recovered, auto right, ok fits, honest: ', nfit, nok, nrec, &
            npick, nall, nhonest
        call s%check(nok == nfit, 'exact sweep: every fit of the true law converges')
        call s%check(nrec == nfit, 'exact sweep: every fit recovers k and d to 1e-8')
        call s%check(npick == nfit, 'exact sweep: auto picks the true law every time')
        call s%check(nhonest == nall, 'exact sweep: every ok fit without sigmas has J+r <= 1e-10')
    end subroutine test_exact_sweep

    !> Standard uncertainties whose value fits a double are computed, however large the
    !> sigmas: they scale with them (sigma 1e300: uncertainties ~1e297, before inf).
    subroutine test_huge_sigmas()
        real(wp), parameter :: u(5) = [0.3_wp, 0.7_wp, 1.5_wp, 3.0_wp, 6.0_wp], m = 1.0e-3_wp, k = 1.0e9_wp
        real(wp) :: e(5), tc(5), d, one(5)
        type(cal_options) :: o
        type(cal_result) :: r1, rb, r1t, rbt
        d = d_for(CAL_LAW_LINEAR, 0.2_wp, k, m)
        call rk45_data(CAL_LAW_LINEAR, HD_END_OVERLAP, k, d, m, u, e, tc)
        o%mass = m
        one = 1.0_wp
        call cal_fit(cal_make_data(u, e, sigma_e=one), CAL_LAW_LINEAR, o, r1)
        call cal_fit(cal_make_data(u, e, sigma_e=1.0e300_wp * one), CAL_LAW_LINEAR, o, rb)
        call s%check(r1%status == CAL_OK .and. rb%status == CAL_OK, 'sigma_e = 1e300: the fit is ok')
        call s%check_close(rb%c_err, 1.0e300_wp * r1%c_err, 1.0e-8_wp, 'sigma_e = 1e300: c_err = 1e300 c_err(sigma_e = 1)')
        call s%check_close(rb%a_err, 1.0e300_wp * r1%a_err, 1.0e-8_wp, 'sigma_e = 1e300: a_err scales too')
        call cal_fit(cal_make_data(u, e, tc, one, 1.0e-3_wp * tc), CAL_LAW_LINEAR, o, r1t)
        call cal_fit(cal_make_data(u, e, tc, 1.0e300_wp * one, 1.0e297_wp * tc), CAL_LAW_LINEAR, o, rbt)
        call s%check(r1t%status == CAL_OK .and. rbt%status == CAL_OK, 'sigmas 1e300 with tc: the fit is ok')
        call s%check_close(rbt%k_err, 1.0e300_wp * r1t%k_err, 1.0e-8_wp, 'sigmas 1e300: k_err scales')
        call s%check_close(rbt%d_err, 1.0e300_wp * r1t%d_err, 1.0e-8_wp, 'sigmas 1e300: d_err scales')
        call s%check_close(rbt%c_err, 1.0e300_wp * r1t%c_err, 1.0e-8_wp, 'sigmas 1e300: c_err scales')
        call s%check(abs(rbt%corr_kd - r1t%corr_kd) < 1.0e-8_wp .and. abs(r1t%corr_kd) <= 1.0_wp, &
                     'sigmas 1e300: the same correlation of k and d')
        print '(a,3es12.4)', 'sigma 1e300: c_err, k_err, d_err: ', rbt%c_err, rbt%k_err, rbt%d_err
    end subroutine test_huge_sigmas

    !> The messages name the real cause: contact times in the wrong unit (k far beyond
    !> every double-precision stiffness at the start), sigmas too small for the weighted
    !> residuals to fit a double.
    subroutine test_start_messages()
        real(wp), parameter :: u(3) = [0.5_wp, 1.0_wp, 2.0_wp]
        real(wp), parameter :: e(3) = [0.8_wp, 0.82_wp, 0.84_wp]
        type(cal_options) :: o
        type(cal_result) :: r
        o%mass = 1.0e-3_wp
        call cal_fit(cal_make_data(u, e, [1.0e300_wp, 1.0e300_wp, 1.0e300_wp]), CAL_LAW_LINEAR, o, r)
        call s%check(r%status == CAL_FAILED .and. index(r%message, 'stiffness k = 10^-7') > 0 .and. &
                     index(r%message, 'seconds') > 0, 'tc = 1e300: the message names the stiffness: ' // r%message)
        call cal_fit(cal_make_data(u, e, sigma_e=[1.0e-310_wp, 0.01_wp, 0.01_wp]), CAL_LAW_LINEAR, o, r)
        call s%check(r%status == CAL_BAD_DATA .and. index(r%message, 'row 1: sigma_e = 1e-310 is too small') > 0, &
                     'sigma_e = 1e-310: the message names it: ' // r%message)
        call cal_fit(cal_make_data(u, e, [1.0e-4_wp, 1.0e-4_wp, 1.0e-4_wp], [0.01_wp, 0.01_wp, 0.01_wp], &
                                   [1.0e-4_wp, 1.0e-320_wp, 1.0e-4_wp]), CAL_LAW_LINEAR, o, r)
        call s%check(r%status == CAL_BAD_DATA .and. index(r%message, 'row 2: sigma_tc') > 0 .and. &
                     index(r%message, 'too small') > 0, 'sigma_tc = 1e-320: the message names it: ' // r%message)
    end subroutine test_start_messages

end program test_calibrate
