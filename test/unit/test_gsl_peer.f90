!> Checks of the GSL odeiv2 peer solver against exact facts (doc/theory.md section 4):
!> the elastic closed forms, the first-order slope e1, the time-reversal identities,
!> agreement of the two GSL steppers, the no-rebound certificate and the force
!> definition.  Prints only the summary line on success.
program test_gsl_peer
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_testing, only: test_suite, new_suite
    use hertzdamp_gsl, only: hertzdamp_gsl_collide, gsl_sf_beta, HERTZDAMP_GSL_RKF45, HERTZDAMP_GSL_RK8PD
    use hertzdamp, only: HD_OK, HD_NO_REBOUND, HD_BAD_ARGUMENT, HD_BAD_LAW, HD_END_OVERLAP, HD_END_FORCE
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
    implicit none

    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: ov = HD_END_OVERLAP, fo = HD_END_FORCE
    integer, parameter :: rkf45 = HERTZDAMP_GSL_RKF45, rk8pd = HERTZDAMP_GSL_RK8PD

    type(test_suite) :: s

    s = new_suite('gsl_peer')
    call test_elastic()
    call test_first_order()
    call test_time_reversal()
    call test_methods_agree()
    call test_no_rebound()
    call test_force()
    call test_monotone()
    call test_bad_input()
    call test_laws()
    call s%finish()

contains

    !> One solve; returns everything.
    subroutine solve(alpha, iend, tol, method, r, status, nev)
        real(wp), intent(in) :: alpha, tol
        integer, intent(in) :: iend, method
        real(wp), intent(out) :: r(4)          ! e, tau_c, z_max, tau_max
        integer, intent(out) :: status, nev
        integer :: nst
        call hertzdamp_gsl_collide(alpha, iend, tol, method, r(1), r(2), r(3), r(4), &
            status, nev, nst)
    end subroutine solve

    !> alpha = 0: energy conservation gives z_max, tau_c, tau_max and e in closed form.
    subroutine test_elastic()
        real(wp) :: r(4), zmax0, tc0
        integer :: st, nev
        zmax0 = 1.25_wp**0.4_wp
        tc0 = 0.8_wp * zmax0 * gsl_sf_beta(0.4_wp, 0.5_wp)
        call s%check_close(zmax0, 1.0933620739432780_wp, 1e-15_wp, 'closed form z_max(0)')
        call s%check_close(tc0, 3.2180654597190431_wp, 1e-14_wp, 'closed form tau_c(0)')
        call solve(0.0_wp, ov, 1e-14_wp, rk8pd, r, st, nev)
        call s%check(st == HD_OK, 'alpha=0 status')
        call s%check_close(r(1), 1.0_wp, 1e-11_wp, 'alpha=0 e = 1')
        call s%check_close(r(2), tc0, 1e-11_wp, 'alpha=0 tau_c')
        call s%check_close(r(3), zmax0, 1e-11_wp, 'alpha=0 z_max')
        call s%check_close(r(4), 0.5_wp * tc0, 1e-11_wp, 'alpha=0 tau_max = tau_c/2')
        ! the force definition coincides with the overlap one at alpha = 0
        call solve(0.0_wp, fo, 1e-14_wp, rk8pd, r, st, nev)
        call s%check(st == HD_OK, 'alpha=0 force status')
        call s%check_close(r(1), 1.0_wp, 1e-11_wp, 'alpha=0 force e = 1')
        call s%check_close(r(2), tc0, 1e-11_wp, 'alpha=0 force tau_c')
    end subroutine test_elastic

    !> (1 - e(alpha))/alpha -> e1 = (4/5)(5/4)^{2/5} B(2/5, 3/2): Richardson in alpha
    !> removes the O(alpha) and O(alpha^2) terms of the slope.
    subroutine test_first_order()
        real(wp) :: r(4), f(3), e1, e1_rich, h
        integer :: st, nev, i
        e1 = 0.8_wp * 1.25_wp**0.4_wp * gsl_sf_beta(0.4_wp, 1.5_wp)
        call s%check_close(e1, 1.7878141442883573_wp, 1e-14_wp, 'closed form e1')
        h = 0.002_wp
        do i = 1, 3
            call solve(h * 2**(i - 1), ov, 1e-14_wp, rk8pd, r, st, nev)
            f(i) = (1.0_wp - r(1)) / (h * 2**(i - 1))
        end do
        e1_rich = (8.0_wp * f(1) - 6.0_wp * f(2) + f(3)) / 3.0_wp
        call s%check_close(e1_rich, e1, 1e-7_wp, 'first-order slope e1 (Richardson)')
        call s%check_close(f(1), e1, 0.01_wp, 'first-order slope e1 (plain, alpha=0.002)')
    end subroutine test_first_order

    !> Time reversal: e(a) e(-a e^{-1/5}) = 1, tau_c(a) = tau_max(a) + e^{-1/5}
    !> tau_max(-a e^{-1/5}), z_max(a) = e^{4/5} z_max(-a e^{-1/5}) (overlap definition).
    subroutine test_time_reversal()
        real(wp), parameter :: alphas(3) = [0.1_wp, 0.5_wp, 1.0_wp]
        real(wp) :: r(4), rb(4), ab
        integer :: st, stb, nev, i
        character(len=16) :: lab
        do i = 1, size(alphas)
            write (lab, '(a,f4.2)') ' alpha=', alphas(i)
            call solve(alphas(i), ov, 1e-13_wp, rk8pd, r, st, nev)
            ab = -alphas(i) * r(1)**(-0.2_wp)
            call solve(ab, ov, 1e-13_wp, rk8pd, rb, stb, nev)
            call s%check(st == HD_OK .and. stb == HD_OK, &
                'time reversal status' // trim(lab))
            call s%check(rb(1) > 1.0_wp, 'energy injection rebounds faster' // trim(lab))
            call s%check_close(r(1) * rb(1), 1.0_wp, 1e-10_wp, &
                'e(a) e(-a e^-1/5) = 1' // trim(lab))
            call s%check_close(r(4) + r(1)**(-0.2_wp) * rb(4), r(2), 1e-10_wp, &
                'tau_c time reversal' // trim(lab))
            call s%check_close(r(1)**0.8_wp * rb(3), r(3), 1e-10_wp, &
                'z_max time reversal' // trim(lab))
        end do
    end subroutine test_time_reversal

    !> rkf45 at 1e-12 and rk8pd at 1e-14 agree (both definitions).
    subroutine test_methods_agree()
        real(wp), parameter :: alphas(4) = [0.05_wp, 0.3_wp, 0.8_wp, 1.1_wp]
        real(wp), parameter :: alphas_f(3) = [0.5_wp, 3.0_wp, 20.0_wp]
        real(wp) :: r4(4), r8(4)
        integer :: st4, st8, nev, i, k
        character(len=24) :: lab
        do i = 1, size(alphas)
            write (lab, '(a,f5.2)') ' overlap alpha=', alphas(i)
            call solve(alphas(i), ov, 1e-12_wp, rkf45, r4, st4, nev)
            call solve(alphas(i), ov, 1e-14_wp, rk8pd, r8, st8, nev)
            call s%check(st4 == HD_OK .and. st8 == HD_OK, &
                'rkf45/rk8pd status' // trim(lab))
            do k = 1, 4
                call s%check_close(r4(k), r8(k), 1e-9_wp, 'rkf45 = rk8pd' // trim(lab))
            end do
        end do
        do i = 1, size(alphas_f)
            write (lab, '(a,f5.1)') ' force alpha=', alphas_f(i)
            call solve(alphas_f(i), fo, 1e-12_wp, rkf45, r4, st4, nev)
            call solve(alphas_f(i), fo, 1e-14_wp, rk8pd, r8, st8, nev)
            call s%check(st4 == HD_OK .and. st8 == HD_OK, &
                'rkf45/rk8pd status' // trim(lab))
            ! tau_c of the force definition is ill-conditioned at large alpha: the force
            ! -alpha z' - z^{3/2} = z'' crosses zero with slope 1.5 z^{1/2} z' ~ e, so
            ! an absolute error d in z' moves tau_c by about alpha d / (z^{1/2} e)
            do k = 1, 4
                call s%check_close(r4(k), r8(k), merge(1e-6_wp, 1e-9_wp, k == 2), &
                    'rkf45 = rk8pd' // trim(lab))
            end do
        end do
    end subroutine test_methods_agree

    !> alpha >= alpha_c (overlap): certified no rebound, quickly, and no NaN.
    subroutine test_no_rebound()
        real(wp), parameter :: alphas(3) = [1.2_wp, 3.0_wp, 100.0_wp]
        real(wp) :: r(4)
        integer :: st, nev, i, m
        do m = rkf45, rk8pd
            do i = 1, size(alphas)
                call solve(alphas(i), ov, 1e-10_wp, m, r, st, nev)
                call s%check(st == HD_NO_REBOUND, 'no rebound status')
                call s%check(nev < 5000, 'no rebound found quickly')
                call s%check(r(1) <= 0.0_wp .and. r(1) >= 0.0_wp .and. r(2) > huge(1.0_wp), &
                    'no rebound: e = 0, tau_c = Inf')
                call s%check(r(3) > 0.0_wp .and. r(4) > 0.0_wp .and. ieee_is_finite(r(3)), &
                    'no rebound: turning point reported')
            end do
        end do
        ! just below alpha_c there still is a rebound
        call solve(1.12_wp, ov, 1e-12_wp, rk8pd, r, st, nev)
        call s%check(st == HD_OK .and. r(1) > 0.0_wp .and. r(1) < 0.01_wp, &
            'alpha=1.12 rebounds weakly')
    end subroutine test_no_rebound

    !> Force definition: e > 0 for every alpha, and larger than the overlap e.
    subroutine test_force()
        real(wp), parameter :: alphas(4) = [2.0_wp, 10.0_wp, 50.0_wp, 1000.0_wp]
        real(wp) :: r(4), ro(4)
        integer :: st, sto, nev, i
        do i = 1, size(alphas)
            call solve(alphas(i), fo, 1e-10_wp, rk8pd, r, st, nev)
            call s%check(st == HD_OK .and. r(1) > 0.0_wp .and. r(1) < 1.0_wp, &
                'force definition rebounds')
            call s%check(r(2) > r(4) .and. ieee_is_finite(r(2)), 'force: tau_c > tau_max')
        end do
        call solve(0.5_wp, fo, 1e-12_wp, rk8pd, r, st, nev)
        call solve(0.5_wp, ov, 1e-12_wp, rk8pd, ro, sto, nev)
        call s%check(st == HD_OK .and. sto == HD_OK, 'alpha=0.5 status')
        call s%check(r(1) > ro(1), 'force e > overlap e at alpha=0.5')
        call s%check(r(2) < ro(2), 'force tau_c < overlap tau_c at alpha=0.5')
        call s%check_close(r(3), ro(3), 1e-14_wp, 'same turning point for both definitions')
    end subroutine test_force

    !> e decreases and tau_c increases with alpha (overlap definition).
    subroutine test_monotone()
        real(wp) :: r(4), e_prev, t_prev, a
        integer :: st, nev, i
        logical :: ok
        ok = .true.
        e_prev = huge(1.0_wp)
        t_prev = 0.0_wp
        do i = -5, 11
            a = 0.1_wp * i
            call solve(a, ov, 1e-10_wp, rk8pd, r, st, nev)
            ok = ok .and. st == HD_OK .and. r(1) < e_prev .and. r(2) > t_prev
            e_prev = r(1)
            t_prev = r(2)
        end do
        call s%check(ok, 'e decreasing, tau_c increasing in alpha')
    end subroutine test_monotone

    !> Invalid arguments give status 3 and no NaN.
    subroutine test_bad_input()
        real(wp) :: r(4)
        integer :: st, nev
        call solve(-0.5_wp, fo, 1e-10_wp, rk8pd, r, st, nev)
        call s%check(st == HD_BAD_ARGUMENT, 'force with alpha < 0 rejected')
        call solve(0.5_wp, ov, 0.0_wp, rk8pd, r, st, nev)
        call s%check(st == HD_BAD_ARGUMENT, 'tol = 0 rejected')
        call solve(0.5_wp, ov, 1e-10_wp, 7, r, st, nev)
        call s%check(st == HD_BAD_ARGUMENT, 'unknown method rejected')
        call solve(0.5_wp, 2, 1e-10_wp, rk8pd, r, st, nev)
        call s%check(st == HD_BAD_ARGUMENT .and. .not. any(ieee_is_nan(r)), &
            'unknown contact end rejected, no NaN')
    end subroutine test_bad_input

    !> The damping laws q = 1/4 (1) and 1/2 (2): tsuji against its closed forms (overlap:
    !> alpha = sqrt5 beta(e); force: e = exp(-2 z atan(sqrt(1-z^2)/z)/sqrt(1-z^2)),
    !> z = alpha/sqrt5), time reversal e(a) e(-a e^p) = 1 with p = (4q-1)/5, the
    !> no-rebound certificate of tsuji above sqrt5, and a bad law code.
    subroutine test_laws()
        real(wp) :: r(4), rb(4), z, e, a, p
        integer :: st, stb, nev, nst, law, i
        character(len=32) :: lab
        do i = 1, 5
            e = 10.0_wp**(-0.5_wp * i)
            a = -sqrt(5.0_wp) * log(e) / sqrt(acos(-1.0_wp)**2 + log(e)**2)
            call hertzdamp_gsl_collide(a, ov, 1e-14_wp, rk8pd, r(1), r(2), r(3), r(4), st, nev, nst, &
                                       atol=1e-30_wp, law=1)
            call s%check(st == HD_OK, 'tsuji overlap status')
            call s%check_close(r(1), e, 1e-11_wp, 'gsl tsuji overlap: e(sqrt5 beta(e)) = e')
            a = 0.4_wp * i
            z = a / sqrt(5.0_wp)
            call hertzdamp_gsl_collide(a, fo, 1e-14_wp, rk8pd, r(1), r(2), r(3), r(4), st, nev, nst, &
                                       atol=1e-30_wp, law=1)
            call s%check_close(r(1), exp(-2.0_wp * z * atan(sqrt(1.0_wp - z * z) / z) / sqrt(1.0_wp - z * z)), 1e-11_wp, &
                               'gsl tsuji force: closed form')
        end do
        do law = 1, 2
            p = (law - 1.0_wp) / 5.0_wp
            do i = 1, 3
                a = 0.5_wp * i
                write (lab, '(a,i2,a,f4.1)') ' law', law, ' alpha', a
                call hertzdamp_gsl_collide(a, ov, 1e-13_wp, rk8pd, r(1), r(2), r(3), r(4), st, nev, nst, law=law)
                call hertzdamp_gsl_collide(-a * r(1)**p, ov, 1e-13_wp, rk8pd, rb(1), rb(2), rb(3), rb(4), stb, nev, nst, &
                                           law=law)
                call s%check(st == HD_OK .and. stb == HD_OK, 'time reversal status' // trim(lab))
                call s%check_close(r(1) * rb(1), 1.0_wp, 1e-10_wp, 'e(a) e(-a e^p) = 1' // trim(lab))
                call s%check_close(r(4) + r(1)**(-0.2_wp) * rb(4), r(2), 1e-10_wp, 'tau_c time reversal' // trim(lab))
            end do
        end do
        call hertzdamp_gsl_collide(2.3_wp, ov, 1e-10_wp, rk8pd, r(1), r(2), r(3), r(4), st, nev, nst, law=1)
        call s%check(st == HD_NO_REBOUND .and. nev < 20000, 'gsl tsuji above sqrt5: no rebound, certified')
        call hertzdamp_gsl_collide(0.5_wp, ov, 1e-10_wp, rk8pd, r(1), r(2), r(3), r(4), st, nev, nst, law=3)
        call s%check(st == HD_BAD_LAW .and. .not. any(ieee_is_nan(r)), 'bad law rejected')
    end subroutine test_laws

end program test_gsl_peer
