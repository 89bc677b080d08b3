!> The GSL iterative peer (packages/reference/src/hertzdamp_gsl_secant.f90): its rk8pd solve with
!> Hermite event location agrees with the reference integrator, and the secant over
!> it meets the accuracy asked of alpha (against the fit, 1e-13) for both ends.
program test_gsl_secant
    use hertzdamp, only: hertzdamp_rk, hertzdamp_collision, hertzdamp_rk45_collide, hertzdamp_invert_alpha, &
                         hertzdamp_end_name, HD_OK, HD_NO_REBOUND, HD_END_OVERLAP, HD_END_FORCE, HD_BAD_RESTITUTION, &
                         HD_BAD_END, HD_BAD_TOL
    use hertzdamp_gsl_secant, only: hertzdamp_gsl_secant_invert, hertzdamp_gsl_rk8pd_collision
    use hertzdamp_testing, only: test_suite, new_suite, rel_err
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    type(test_suite) :: s
    type(hertzdamp_collision) :: r
    real(wp) :: a, e, t, af, tf, worst(2)
    integer :: i, j, iend, st, st2, ns, nr, nbad
    real(wp), parameter :: tols(3) = [1.0e-6_wp, 1.0e-8_wp, 1.0e-10_wp]
    character(len=8) :: ctol
    s = new_suite('test_gsl_secant')

    ! one solve at tol 1e-13 against rk45 at 1e-15 (force-end tau_c is ill-conditioned
    ! at large alpha: the contact ends where z'' crosses zero with a small slope)
    do iend = HD_END_OVERLAP, HD_END_FORCE
        worst = 0.0_wp
        do i = 0, 20
            a = merge(1.12_wp, 50.0_wp, iend == HD_END_OVERLAP) * real(i, wp) / 20.0_wp
            r = hertzdamp_rk45_collide(a, iend, 1.0e-15_wp)
            call hertzdamp_gsl_rk8pd_collision(a, iend, 1.0e-13_wp, e, t, st, nr)
            if (st /= HD_OK) worst = 1.0_wp
            worst(1) = max(worst(1), rel_err(e, r%e))
            worst(2) = max(worst(2), rel_err(t, r%tau_c))
        end do
        print '(a, a, 2es10.2)', 'rk8pd (tol 1e-13) against rk45 (1e-15), e and tau_c: ', hertzdamp_end_name(iend), worst
        call s%check(worst(1) <= 1.0e-12_wp, 'rk8pd solve: e within 1e-12 (' // hertzdamp_end_name(iend) // ')')
        call s%check(worst(2) <= merge(1.0e-12_wp, 1.0e-11_wp, iend == HD_END_OVERLAP), &
                     'rk8pd solve: tau_c within 1e-12 (overlap), 1e-11 (force)')
    end do
    call hertzdamp_gsl_rk8pd_collision(1.2_wp, HD_END_OVERLAP, 1.0e-10_wp, e, t, st, nr)
    call s%check(st == HD_NO_REBOUND, 'rk8pd solve: alpha > alpha_c does not rebound (overlap)')

    ! the secant meets the accuracy asked of alpha
    do iend = HD_END_OVERLAP, HD_END_FORCE
        do j = 1, size(tols)
            write (ctol, '(es8.1)') tols(j)
            worst = 0.0_wp
            nbad = 0
            do i = 1, 20
                e = merge(1.0e-3_wp, 1.0e-4_wp, iend == HD_END_OVERLAP)**((real(i, wp) - 0.5_wp) / 20.0_wp)
                call hertzdamp_gsl_secant_invert(e, iend, tols(j), a, t, st, ns, nr)
                call hertzdamp_invert_alpha(e, iend, af, tf, st2)
                if (st /= HD_OK .or. st2 /= HD_OK .or. ns > 15) nbad = nbad + 1
                worst(1) = max(worst(1), abs(a - af) / af)
            end do
            print '(a, a, a, es9.2)', 'gsl secant ', hertzdamp_end_name(iend), ' tol ' // ctol // ': max rel err alpha', &
                worst(1)
            call s%check(nbad == 0 .and. worst(1) <= tols(j), 'gsl secant: alpha within tol = ' // ctol // &
                         ', at most 15 solves (' // hertzdamp_end_name(iend) // ')')
        end do
    end do
    call hertzdamp_gsl_secant_invert(1.0_wp, HD_END_OVERLAP, 1.0e-8_wp, a, t, st, ns, nr)
    call s%check(st == HD_OK .and. .not. (abs(a) > 0.0_wp) .and. ns == 0, 'gsl secant: e = 1 gives alpha = 0, no solve')
    call hertzdamp_gsl_secant_invert(1.0e-4_wp, HD_END_OVERLAP, 1.0e-8_wp, a, t, st, ns, nr)
    call s%check(st == HD_BAD_RESTITUTION, 'gsl secant: e below e_min')
    call hertzdamp_gsl_secant_invert(0.5_wp, 3, 1.0e-8_wp, a, t, st, ns, nr)
    call s%check(st == HD_BAD_END, 'gsl secant: bad end')
    call hertzdamp_gsl_secant_invert(0.5_wp, HD_END_OVERLAP, 1.0e-20_wp, a, t, st, ns, nr)
    call s%check(st == HD_BAD_TOL, 'gsl secant: bad tol')
    call s%finish()
end program test_gsl_secant
