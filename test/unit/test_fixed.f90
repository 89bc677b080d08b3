!> The best single fixed (k, d) (packages/calibrate: hertzdamp_fixed, `invert --fixed`)
!> against an independent brute-force search: over a grid of alpha at the slowest
!> speed (three nested logarithmic grids) and of impact speeds, the worst relative
!> error of e computed with the reference integrator (rk45), alpha(u) from the
!> definition alpha = d t* (u t*)^q / m written here.  The library's pair must be as
!> good as the best of the grid and no better than what the grid resolution allows;
!> its worst error measured with rk45 over the speeds is the one it reports (the ends
!> are the worst); its shortest contact (rk45, dense speed grid) lasts T.  tsuji: no
!> error, alpha = sqrt(5) beta(e) (closed form, overlap end).  One speed: the
!> per-contact inverse.  The stiffness bound; bad input.
program test_fixed
    use hertzdamp
    use hertzdamp_fixed, only: fixed_pair, hertzdamp_fixed_pair
    use hertzdamp_testing, only: test_suite, new_suite, rel_err
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    real(wp), parameter :: pi = acos(-1.0_wp)
    ! two glass beads of 2 mm: m* = (4/3) pi rho R^3 / 2
    real(wp), parameter :: m = 2.0_wp / 3.0_wp * pi * 2500.0_wp * 1.0e-9_wp
    real(wp), parameter :: tol = 1.0e-11_wp
    integer, parameter :: nu = 25
    type(test_suite) :: s
    type(fixed_pair) :: p, pb
    real(wp) :: k, d, a, ts, beta
    integer :: st

    s = new_suite('test_fixed')
    call against_brute_force('linear, overlap, e 0.9, 0.01-5 m/s', HD_DAMPING_LINEAR, HD_END_OVERLAP, 0.9_wp, &
                             0.01_wp, 5.0_wp, 1.0e-5_wp)
    call against_brute_force('linear, overlap, e 0.3, 0.1-10 m/s', HD_DAMPING_LINEAR, HD_END_OVERLAP, 0.3_wp, &
                             0.1_wp, 10.0_wp, 2.0e-5_wp)
    call against_brute_force('linear, force, e 0.5, 0.01-5 m/s', HD_DAMPING_LINEAR, HD_END_FORCE, 0.5_wp, &
                             0.01_wp, 5.0_wp, 1.0e-5_wp)
    call against_brute_force('kuwabara-kono, overlap, e 0.5, 0.012-5.8 m/s', HD_DAMPING_KUWABARA_KONO, &
                             HD_END_OVERLAP, 0.5_wp, 0.012_wp, 5.8_wp, 2.0e-5_wp)
    call against_brute_force('kuwabara-kono, force, e 0.7, 0.1-1 m/s', HD_DAMPING_KUWABARA_KONO, HD_END_FORCE, &
                             0.7_wp, 0.1_wp, 1.0_wp, 1.0e-5_wp)

    ! tsuji: alpha does not depend on the speed, e is exact everywhere, alpha = sqrt(5) beta(e)
    p = hertzdamp_fixed_pair(0.5_wp, 1.0e-5_wp, m, 0.01_wp, 5.0_wp, HD_END_OVERLAP, HD_DAMPING_TSUJI)
    beta = -log(0.5_wp) / sqrt(pi**2 + log(0.5_wp)**2)
    call s%check(p%status == HD_OK .and. p%worst <= 1.0e-12_wp, 'tsuji: no error over the speeds')
    call s%check(rel_err(p%alpha_lo, sqrt(5.0_wp) * beta) <= 1.0e-12_wp .and. p%alpha_hi == p%alpha_lo, &
                 'tsuji: alpha = sqrt(5) beta(e) at every speed')
    call s%check(rel_err(p%d, p%alpha_lo * sqrt(m * p%k)) <= 1.0e-12_wp, 'tsuji: d = gamma sqrt(m k)')

    ! one speed: the per-contact inverse rule, no error
    p = hertzdamp_fixed_pair(0.7_wp, 1.0e-5_wp, m, 1.0_wp, 1.0_wp, HD_END_OVERLAP, HD_DAMPING_LINEAR)
    call hertzdamp_invert(0.7_wp, 1.0e-5_wp, m, 1.0_wp, HD_END_OVERLAP, k, d, st)
    call s%check(p%status == HD_OK .and. st == HD_OK .and. p%worst <= 1.0e-13_wp, 'one speed: no error')
    call s%check(rel_err(p%k, k) <= 1.0e-12_wp .and. rel_err(p%d, d) <= 1.0e-12_wp, &
                 'one speed: k and d of hertzdamp_invert')

    ! the bound: k_phys below the k for T -> k = k_phys, the same alpha and errors, longer contacts
    p = hertzdamp_fixed_pair(0.9_wp, 1.0e-5_wp, m, 0.01_wp, 5.0_wp, HD_END_OVERLAP, HD_DAMPING_LINEAR)
    pb = hertzdamp_fixed_pair(0.9_wp, 1.0e-5_wp, m, 0.01_wp, 5.0_wp, HD_END_OVERLAP, HD_DAMPING_LINEAR, 0.5_wp * p%k)
    call s%check(pb%status == HD_OK .and. pb%bound_active .and. pb%k == 0.5_wp * p%k, 'bound: k = k_phys')
    call s%check(pb%alpha_lo == p%alpha_lo .and. pb%worst == p%worst, 'bound: the same alpha and errors')
    call s%check(rel_err(pb%tc_min, 1.0e-5_wp * 2.0_wp**0.4_wp) <= 1.0e-12_wp, &
                 'bound: the shortest contact longer by (k/k_phys)^(2/5)')
    call hertzdamp_reduce(pb%k, pb%d, m, 0.01_wp, a, ts, st)
    call s%check(st == HD_OK .and. rel_err(a, p%alpha_lo) <= 1.0e-13_wp, 'bound: d keeps alpha at u_lo')
    pb = hertzdamp_fixed_pair(0.9_wp, 1.0e-5_wp, m, 0.01_wp, 5.0_wp, HD_END_OVERLAP, HD_DAMPING_LINEAR, 2.0_wp * p%k)
    call s%check(pb%status == HD_OK .and. .not. pb%bound_active .and. pb%k == p%k, 'bound inactive: k unchanged')

    ! bad input: the status names it, k = d = 0
    call bad(0.0_wp, 1.0e-5_wp, m, 0.1_wp, 1.0_wp, HD_BAD_RESTITUTION, 'e = 0')
    call bad(1.5_wp, 1.0e-5_wp, m, 0.1_wp, 1.0_wp, HD_BAD_RESTITUTION, 'e = 1.5')
    call bad(0.5_wp, 0.0_wp, m, 0.1_wp, 1.0_wp, HD_BAD_TIME, 'tc = 0')
    call bad(0.5_wp, 1.0e-5_wp, -m, 0.1_wp, 1.0_wp, HD_BAD_MASS, 'negative mass')
    call bad(0.5_wp, 1.0e-5_wp, m, 0.0_wp, 1.0_wp, HD_BAD_VELOCITY, 'u_lo = 0')
    call bad(0.5_wp, 1.0e-5_wp, m, 1.0_wp, 0.1_wp, HD_BAD_VELOCITY, 'u_hi < u_lo')
    p = hertzdamp_fixed_pair(1.0e-7_wp, 1.0e-5_wp, m, 0.1_wp, 1.0_wp, HD_END_OVERLAP, HD_DAMPING_LINEAR)
    call hertzdamp_invert_alpha(1.0e-7_wp, HD_END_OVERLAP, a, ts, st)
    call s%check(st /= HD_OK .and. p%status == st .and. p%k == 0.0_wp, &
                 'e = 1e-7, below the fit: the status of the one-speed inverse')
    p = hertzdamp_fixed_pair(0.5_wp, 1.0e-5_wp, m, 0.1_wp, 1.0_wp, HD_END_OVERLAP, HD_DAMPING_LINEAR, -1.0_wp)
    call s%check(p%status == HD_BAD_STIFFNESS, 'negative k_phys: HD_BAD_STIFFNESS')
    call s%finish()

contains

    !> Library pair against the brute-force grid search (see the header).
    subroutine against_brute_force(label, law, iend, e, u_lo, u_hi, tc)
        character(len=*), intent(in) :: label
        integer, intent(in) :: law, iend
        real(wp), intent(in) :: e, u_lo, u_hi, tc
        real(wp) :: u(nu), lo, hi, step, best, best_a, w, worst_rk, x, tcmin, e_u, tc_u, zmax, alpha, tstar, q
        integer :: level, i, st
        q = hertzdamp_law_q(law)
        p = hertzdamp_fixed_pair(e, tc, m, u_lo, u_hi, iend, law)
        call s%check(p%status == HD_OK, label // ': status ok')
        u = [(exp(log(u_lo) + (log(u_hi) - log(u_lo)) * (i - 1) / real(nu - 1, wp)), i=1, nu)]
        ! brute force: three nested grids of 60 in ln alpha_lo, each around the best of the last
        lo = log(1.0e-3_wp)
        hi = log(5.0_wp)
        best = huge(1.0_wp)
        best_a = 0.0_wp
        do level = 1, 3
            step = (hi - lo) / 59.0_wp
            do i = 0, 59
                x = lo + step * i
                w = worst_of(exp(x), u, u_lo, q, iend, law, e)
                if (w < best) then
                    best = w
                    best_a = x
                end if
            end do
            lo = best_a - step
            hi = best_a + step
        end do
        call s%check(p%worst <= best + 1.0e-9_wp, label // ': as good as the best of the brute-force grid')
        call s%check(best - p%worst <= 2.0e-4_wp, label // ': the grid''s best within its resolution of it')
        call s%check(abs(log(p%alpha_lo) - best_a) <= 2.0e-3_wp, label // ': alpha_lo where the grid''s best is')
        ! the library's pair, dimensional, with rk45: its worst error is at the ends and is the one reported
        worst_rk = 0.0_wp
        tcmin = huge(1.0_wp)
        do i = 1, 4 * nu
            x = exp(log(u_lo) + (log(u_hi) - log(u_lo)) * (i - 1) / real(4 * nu - 1, wp))
            call hertzdamp_forward_dim(p%k, p%d, m, x, iend, HD_METHOD_RK45, alpha, tstar, e_u, tc_u, zmax, st, &
                                       tol=tol, law=law)
            if (st == HD_NO_REBOUND) then
                e_u = 0.0_wp
                tc_u = huge(1.0_wp)
                st = HD_OK
            end if
            if (st /= HD_OK) exit
            ! alpha from the definition, written here
            if (i == 1) call s%check(rel_err(alpha, p%d * tstar * (x * tstar)**q / m) <= 1.0e-13_wp, &
                                     label // ': alpha = d t* (u t*)^q / m')
            worst_rk = max(worst_rk, abs(e_u / e - 1.0_wp))
            tcmin = min(tcmin, tc_u)
        end do
        call s%check(st == HD_OK, label // ': rk45 with the pair at every speed')
        call s%check(abs(worst_rk - p%worst) <= 1.0e-9_wp, label // ': worst error of the pair by rk45 = the one reported')
        call s%check(tcmin >= tc * (1.0_wp - 1.0e-9_wp) .and. tcmin <= tc * (1.0_wp + 2.0e-3_wp), &
                     label // ': the shortest contact (rk45) lasts T')
        call hertzdamp_forward_dim(p%k, p%d, m, p%u_tc_min, iend, HD_METHOD_RK45, alpha, tstar, e_u, tc_u, zmax, st, &
                                   tol=tol, law=law)
        call s%check(st == HD_OK .and. rel_err(tc_u, tc) <= 1.0e-9_wp, label // ': at u_tc_min it lasts T (rk45)')
    end subroutine against_brute_force

    !> max over the speeds u of |e(alpha_lo (u/u_lo)^((4q-1)/5))/e - 1|, e by rk45.
    real(wp) function worst_of(alpha_lo, u, u_lo, q, iend, law, e) result(wmax)
        real(wp), intent(in) :: alpha_lo, u(:), u_lo, q, e
        integer, intent(in) :: iend, law
        type(hertzdamp_collision) :: r
        integer :: iu
        wmax = 0.0_wp
        do iu = 1, size(u)
            r = hertzdamp_rk45_collide(alpha_lo * (u(iu) / u_lo)**((4.0_wp * q - 1.0_wp) / 5.0_wp), iend, tol, law)
            if (r%status == HD_NO_REBOUND) r%e = 0.0_wp
            wmax = max(wmax, abs(r%e / e - 1.0_wp))
        end do
    end function worst_of

    subroutine bad(e, tc, mass, u_lo, u_hi, want, label)
        real(wp), intent(in) :: e, tc, mass, u_lo, u_hi
        integer, intent(in) :: want
        character(len=*), intent(in) :: label
        p = hertzdamp_fixed_pair(e, tc, mass, u_lo, u_hi, HD_END_OVERLAP, HD_DAMPING_LINEAR)
        call s%check(p%status == want .and. p%k == 0.0_wp .and. p%d == 0.0_wp, label // ': its status, k = d = 0')
    end subroutine bad

end program test_fixed
