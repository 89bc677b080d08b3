!> The reference integrator against an independent solver of the same ODE: GSL's
!> odeiv2 rk8pd (8th-order Prince-Dormand, its own step control and event search),
!> and the elastic closed forms computed with GSL's beta function.
program test_rk45_vs_gsl
    use hertzdamp
    use hertzdamp_gsl, only: hertzdamp_gsl_collide, gsl_sf_beta, HERTZDAMP_GSL_RK8PD
    use hertzdamp_testing, only: test_suite, new_suite, rel_err
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    type(test_suite) :: s
    real(wp) :: worst(4)

    s = new_suite('test_rk45_vs_gsl')
    call closed_forms()
    worst = 0.0_wp
    ! 12 digits (doc/accuracy.md): default tolerance against rk8pd at 1e-14, every damping law
    ! (doc/damping-laws.md) and contact end, over alpha down to e ~ 1e-4
    call compare(HD_END_OVERLAP, 0.0_wp, 1.12_wp, 57, 2.0e-12_wp)
    call compare(HD_END_FORCE, 0.0_wp, 50.0_wp, 51, 2.0e-12_wp)
    call compare(HD_END_OVERLAP, 0.0_wp, 2.1_wp, 43, 2.0e-12_wp, HD_DAMPING_TSUJI)
    call compare(HD_END_FORCE, 0.0_wp, 100.0_wp, 51, 2.0e-12_wp, HD_DAMPING_TSUJI)
    call compare(HD_END_OVERLAP, 0.0_wp, 12.0_wp, 49, 2.0e-12_wp, HD_DAMPING_KUWABARA_KONO)
    call compare(HD_END_FORCE, 0.0_wp, 100.0_wp, 51, 2.0e-12_wp, HD_DAMPING_KUWABARA_KONO)
    call critical_damping()
    call s%finish()

contains

    !> doc/theory.md section 4 with GSL's beta function, independent of the Fortran gamma.
    subroutine closed_forms()
        type(hertzdamp_collision) :: r
        real(wp) :: tc0, z0, e1
        z0 = 1.25_wp**0.4_wp
        tc0 = 0.8_wp * z0 * gsl_sf_beta(0.4_wp, 0.5_wp)
        e1 = 0.8_wp * z0 * gsl_sf_beta(0.4_wp, 1.5_wp)
        call s%check_close(hertzdamp_tau_c0(), tc0, 4.0e-15_wp, 'library tau_c0 = GSL beta closed form')
        call s%check_close(hertzdamp_e1(), e1, 4.0e-15_wp, 'library e1 = GSL beta closed form')
        call s%check_close(tc0, 3.2180654597190431_wp, 4.0e-15_wp, 'tau_c0 = doc/theory.md value (GSL beta: a few ulp)')
        call s%check_close(e1, 1.7878141442883573_wp, 4.0e-15_wp, 'e1 = doc/theory.md value (GSL beta: a few ulp)')
        r = hertzdamp_rk45_collide(0.0_wp)
        call s%check_close(r%tau_c, tc0, 1.0e-12_wp, 'rk45 tau_c(0) vs GSL closed form')
        call s%check_close(r%tau_max, 0.5_wp * tc0, 1.0e-12_wp, 'rk45 tau_max(0) vs GSL closed form')
        call s%check_close(r%z_max, z0, 1.0e-12_wp, 'rk45 z_max(0) closed form')
    end subroutine closed_forms

    !> alpha_c of the linear law (overlap end) by bisection on the GSL peer's own
    !> no-rebound decision (rk8pd, tolerance 1e-14) against the library's
    !> hertzdamp_alpha_c (bisection on rk45, width 1e-11): the 10 digits doc/accuracy.md
    !> states (1.1279881355).  The GSL bracket is narrowed to 1e-10.
    subroutine critical_damping()
        real(wp) :: lo, hi, mid, ac, e, tau_c, z_max, tau_max
        integer :: st, nrhs, nsteps, it
        call hertzdamp_alpha_c(ac, st)
        call s%check(st == HD_OK, 'alpha_c: library bisection status')
        lo = 1.12_wp
        hi = 1.14_wp
        do it = 1, 60
            mid = 0.5_wp * (lo + hi)
            call hertzdamp_gsl_collide(mid, HD_END_OVERLAP, 1.0e-14_wp, HERTZDAMP_GSL_RK8PD, e, tau_c, z_max, &
                                       tau_max, st, nrhs, nsteps, atol=1.0e-30_wp)
            if (st == HD_NO_REBOUND) then
                hi = mid
            else if (st == HD_OK) then
                lo = mid
            else
                exit
            end if
            if (hi - lo <= 1.0e-10_wp) exit
        end do
        call s%check(st == HD_OK .or. st == HD_NO_REBOUND, 'alpha_c: GSL bisection ran')
        call s%check(hi - lo <= 1.0e-10_wp, 'alpha_c: GSL bracket narrowed to 1e-10')
        call s%check(abs(ac - 0.5_wp * (lo + hi)) <= 2.0e-10_wp, 'alpha_c = GSL rk8pd bisection to 2e-10 (10 digits)')
        if (abs(ac - 0.5_wp * (lo + hi)) > 2.0e-10_wp) print '(a,es24.16,a,2es24.16)', '     library ', ac, &
            ' GSL bracket ', lo, hi
        call s%check(abs(ac - 1.1279881355_wp) <= 1.0e-10_wp, 'alpha_c = 1.1279881355 as doc/accuracy.md states')
    end subroutine critical_damping

    !> Default-tolerance rk45 against rk8pd at 1e-14 on a grid of alpha; errors of e
    !> relative to max(e, 1e-3) as the issue states.
    subroutine compare(iend, a0, a1, n, tol, law)
        integer, intent(in) :: iend, n
        real(wp), intent(in) :: a0, a1, tol
        integer, intent(in), optional :: law
        type(hertzdamp_collision) :: r
        real(wp) :: alpha, e, tau_c, z_max, tau_max, err(4)
        integer :: i, st, nrhs, nsteps, law_
        character(len=80) :: lab
        err = 0.0_wp
        law_ = HD_DAMPING_LINEAR
        if (present(law)) law_ = law
        do i = 0, n - 1
            alpha = a0 + (a1 - a0) * i / (n - 1)
            r = hertzdamp_rk45_collide(alpha, iend, law=law_)
            call hertzdamp_gsl_collide(alpha, iend, 1.0e-14_wp, HERTZDAMP_GSL_RK8PD, e, tau_c, z_max, tau_max, &
                                       st, nrhs, nsteps, atol=1.0e-30_wp, law=law_)
            write (lab, '(a,a,a,a,a,es10.3)') ' ', hertzdamp_law_name(law_), ' end=', hertzdamp_end_name(iend), &
                ' alpha=', alpha
            call s%check(r%status == HD_OK .and. st == 0, 'both solvers succeed' // trim(lab))
            err(1) = max(err(1), rel_err(r%e, e, 1.0e-3_wp))
            err(2) = max(err(2), rel_err(r%tau_c, tau_c))
            err(3) = max(err(3), rel_err(r%z_max, z_max))
            err(4) = max(err(4), rel_err(r%tau_max, tau_max))
        end do
        write (lab, '(a,a,a,a)') ' ', hertzdamp_law_name(law_), ' end=', hertzdamp_end_name(iend)
        print '(a,4es10.2)', '  ' // trim(lab) // ' max rel err e, tau_c, z_max, tau_max vs rk8pd:', err
        call s%check(err(1) <= tol, 'e agrees with GSL rk8pd' // trim(lab))
        call s%check(err(2) <= tol, 'tau_c agrees with GSL rk8pd' // trim(lab))
        call s%check(err(3) <= tol, 'z_max agrees with GSL rk8pd' // trim(lab))
        call s%check(err(4) <= tol, 'tau_max agrees with GSL rk8pd' // trim(lab))
    end subroutine compare

end program test_rk45_vs_gsl
