!> The stored series against the reference integrator: at alpha = 0.05, 0.1, 0.2 the
!> truncated series of every order agrees with rk45 (tol 1e-15) to within the error
!> its omitted terms predict; Pade agrees to 1e-9 on [0, 0.8].
program test_series_vs_rk45
    use hertzdamp
    use hertzdamp_testing, only: test_suite, new_suite, rel_err
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    real(wp), parameter :: alphas(3) = [0.05_wp, 0.1_wp, 0.2_wp]
    real(wp), parameter :: ref_tol = 1.0e-15_wp, ref_acc = 2.0e-13_wp  ! rk45 at 1e-15: ~1e-13 relative
    type(test_suite) :: s
    type(hertzdamp_collision) :: r
    real(wp) :: e, tc, zm, tm, ee, et, worst(2)
    integer :: i, n, st
    character(len=48) :: lab

    s = new_suite('test_series_vs_rk45')
    do i = 1, size(alphas)
        r = hertzdamp_rk45_collide(alphas(i), tol=ref_tol)
        do n = 1, hertzdamp_series_max_order
            call hertzdamp_series_eval(alphas(i), e, tc, zm, tm, order=n, err_e=ee, err_tau=et, status=st)
            write (lab, '(a,f5.2,a,i0)') 'alpha=', alphas(i), ' N=', n
            call s%check(st == HD_OK, trim(lab) // ' status')
            call s%check(abs(e - r%e) <= ee + ref_acc * r%e, trim(lab) // ' e within its error estimate')
            call s%check(abs(tc - r%tau_c) <= et + ref_acc * r%tau_c, trim(lab) // ' tau_c within its error estimate')
        end do
        ! the default order is accurate to 1e-12 for alpha <= 0.2
        call hertzdamp_series_eval(alphas(i), e, tc, zm, tm)
        call s%check_close(e, r%e, 1.0e-12_wp, 'default order: e to 1e-12')
        call s%check_close(tc, r%tau_c, 1.0e-12_wp, 'default order: tau_c to 1e-12')
        call s%check_close(zm, r%z_max, 1.0e-12_wp, 'default order: z_max to 1e-12')
        call s%check_close(tm, r%tau_max, 1.0e-12_wp, 'default order: tau_max to 1e-12')
    end do
    worst = 0.0_wp
    do i = 0, 40
        r = hertzdamp_rk45_collide(0.02_wp * i, tol=ref_tol)
        call hertzdamp_pade_eval(0.02_wp * i, e, tc, zm, tm, status=st)
        call s%check(st == HD_OK, 'pade status')
        worst = max(worst, [rel_err(e, r%e), rel_err(tc, r%tau_c)])
    end do
    call s%check(worst(1) < 1.0e-9_wp, 'pade e within 1e-9 on [0, 0.8] (target 1e-6)')
    call s%check(worst(2) < 1.0e-9_wp, 'pade tau_c within 1e-9 on [0, 0.8] (target 1e-6)')
    call s%finish()
end program test_series_vs_rk45
