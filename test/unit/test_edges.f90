!> The case matrix of extreme and invalid inputs (issue: stiff and extreme cases).
!> Every case must finish with a status, finite outputs on success, a message on
!> failure, bounded work; valid dimensional cases must round-trip.  Prints the
!> summary table quoted in doc/accuracy.md: per class the number of cases, the NaN outputs
!> (asserted zero), the largest right-hand-side count and the slowest case (measured;
!> a crash or a hang would stop this program before the table, and the test runner
!> reports that as a failure).
program test_edges
    use hertzdamp
    use hertzdamp_testing, only: test_suite, new_suite, rel_err
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_negative_inf, ieee_is_finite
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    type(test_suite) :: s
    integer :: ncase(5), nnan(5), max_rhs
    integer(int64) :: last_tick, slowest(5), rate
    real(wp) :: alpha_c, nan, pinf, ninf
    integer :: st

    s = new_suite('test_edges')
    nan = ieee_value(1.0_wp, ieee_quiet_nan)
    pinf = ieee_value(1.0_wp, ieee_positive_inf)
    ninf = ieee_value(1.0_wp, ieee_negative_inf)
    ncase = 0
    nnan = 0
    max_rhs = 0
    slowest = 0
    call system_clock(last_tick, rate)
    call hertzdamp_alpha_c(alpha_c, st)
    call s%check(st == HD_OK, 'alpha_c')

    call alpha_edges()
    call target_edges()
    call decades()
    call bad_arguments()

    print '(a)', '| class | cases | NaN outputs | largest rhs evaluations | slowest case |'
    print '(a)', '|---|---|---|---|---|'
    call row('alpha at the edges (rk45, fit)', 1, max_rhs)
    call row('restitution targets at the edges (fit, compact, iterative)', 2, -1)
    call row('dimensional inputs over many decades (forward, inverse, round trip)', 3, -1)
    call row('zero, negative, NaN, Inf arguments', 4, -1)
    call s%check(all(nnan == 0), 'no NaN in any output')
    call s%finish()

contains

    subroutine row(label, i, rhs)
        character(len=*), intent(in) :: label
        integer, intent(in) :: i, rhs
        character(len=32) :: t
        write (t, '(f12.1,a)') 1.0e3_wp * real(slowest(i), wp) / real(rate, wp), ' ms'
        t = adjustl(t)
        if (rhs >= 0) then
            print '(a,i0,a,i0,a,i0,a)', '| ' // label // ' | ', ncase(i), ' | ', nnan(i), ' | ', rhs, ' | ' // &
                trim(t) // ' |'
        else
            print '(a,i0,a,i0,a)', '| ' // label // ' | ', ncase(i), ' | ', nnan(i), ' | - | ' // trim(t) // ' |'
        end if
    end subroutine row

    subroutine seen(i, values)
        integer, intent(in) :: i
        real(wp), intent(in) :: values(:)
        integer(int64) :: tick
        ncase(i) = ncase(i) + 1
        if (any(values /= values)) nnan(i) = nnan(i) + 1
        call system_clock(tick)
        slowest(i) = max(slowest(i), tick - last_tick)   ! time since the previous case
        last_tick = tick
    end subroutine seen

    subroutine alpha_edges()
        real(wp) :: ov(10)
        real(wp), parameter :: fo(8) = [0.0_wp, 1.0e-300_wp, 1.0e-6_wp, 2.0_wp, 10.0_wp, 100.0_wp, 1.0e4_wp, 1.0e20_wp]
        type(hertzdamp_collision) :: r
        integer :: i
        character(len=40) :: lab
        ov = [0.0_wp, 1.0e-300_wp, 1.0e-12_wp, 1.0e-6_wp, alpha_c - 1.0e-9_wp, alpha_c, alpha_c + 1.0e-9_wp, &
              2.0_wp, 1.0e20_wp, -1.0_wp]
        do i = 1, size(ov)
            write (lab, '(a,es16.8)') ' overlap alpha=', ov(i)
            r = hertzdamp_rk45_collide(ov(i))
            call seen(1, [r%e, r%tau_c, r%z_max, r%tau_max])
            max_rhs = max(max_rhs, r%stats%rhs_evals)
            call s%check(r%status == HD_OK .or. r%status == HD_NO_REBOUND, 'rk45 finishes' // lab)
            call s%check(r%stats%rhs_evals <= 1000000, 'rk45 at most 1e6 rhs' // lab)
            if (r%status == HD_OK) call s%check(ieee_is_finite(r%tau_c) .and. r%e > 0.0_wp, 'rebound finite' // lab)
            if (ov(i) >= alpha_c + 1.0e-9_wp) call s%check(r%status == HD_NO_REBOUND, 'no rebound' // lab)
            if (ov(i) <= alpha_c - 1.0e-9_wp) call s%check(r%status == HD_OK, 'rebound' // lab)
            r = hertzdamp_forward_alpha(ov(i), HD_END_OVERLAP, HD_METHOD_FIT)
            call seen(1, [r%e, r%tau_c, r%z_max, r%tau_max])
            call s%check(r%status == HD_OK .or. r%status == HD_NO_REBOUND .or. r%status == HD_OUTSIDE_VALIDITY, &
                         'fit has a status' // lab)
        end do
        do i = 1, size(fo)
            write (lab, '(a,es10.2)') ' force alpha=', fo(i)
            r = hertzdamp_rk45_collide(fo(i), HD_END_FORCE)
            call seen(1, [r%e, r%tau_c, r%z_max, r%tau_max])
            max_rhs = max(max_rhs, r%stats%rhs_evals)
            call s%check(r%status == HD_OK .and. r%e > 0.0_wp .and. ieee_is_finite(r%tau_c), 'force rebounds' // lab)
            call s%check(r%stats%rhs_evals <= 1000000, 'force at most 1e6 rhs' // lab)
        end do
        ! near alpha_c: the contact lasts long, e is tiny but positive
        r = hertzdamp_rk45_collide(alpha_c - 1.0e-9_wp)
        call s%check(r%e < 1.0e-6_wp .and. r%tau_c > 20.0_wp, 'alpha_c - 1e-9: tiny e, long contact')
    end subroutine alpha_edges

    subroutine target_edges()
        real(wp) :: targets(10), k, d, a
        integer :: i, iend, im, st
        integer, parameter :: methods(3) = [HD_METHOD_FIT, HD_METHOD_COMPACT, HD_METHOD_ITERATIVE]
        character(len=48) :: lab
        targets = [1.0_wp, 1.0_wp - 1.0e-15_wp, 1.0e-3_wp, 1.0e-8_wp, 0.0_wp, -0.5_wp, 1.5_wp, nan, pinf, ninf]
        do iend = HD_END_OVERLAP, HD_END_FORCE
            do im = 1, size(methods)
                do i = 1, size(targets)
                    write (lab, '(a,i0,a,i0,a,es10.2)') ' end=', iend, ' method=', methods(im), ' e=', targets(i)
                    call hertzdamp_invert(targets(i), 1.0e-4_wp, 1.0e-3_wp, 1.0_wp, iend, k, d, st, alpha=a, &
                                          options=hertzdamp_invert_options(method=methods(im)))
                    call seen(2, [k, d, a])
                    if (st == HD_OK) then
                        call s%check(k > 0.0_wp .and. d >= 0.0_wp .and. ieee_is_finite(k) .and. ieee_is_finite(d), &
                                     'finite k, d' // lab)
                    else
                        call s%check(k == 0.0_wp .and. d == 0.0_wp .and. len(hertzdamp_message(st)) > 10, &
                                     'zero outputs and a message' // lab)
                    end if
                    if (i <= 2) call s%check(st == HD_OK, 'e = 1 and 1 - 1e-15 are valid' // lab)
                    if (i == 1) call s%check(a == 0.0_wp .and. d == 0.0_wp, 'e = 1: no damping' // lab)
                    if (i >= 5) call s%check(st == HD_BAD_RESTITUTION, 'invalid e named' // lab)
                    if (i == 3 .and. methods(im) /= HD_METHOD_COMPACT) call s%check(st == HD_OK, 'e = 1e-3 valid' // lab)
                    if (i == 4) call s%check(st == HD_BAD_RESTITUTION, 'e = 1e-8 below the range: said so' // lab)
                end do
            end do
        end do
    end subroutine target_edges

    !> Dimensional inputs over the decades DEM codes use: the inverse then the forward
    !> problem (reference integrator) give back e and T_c to 1e-10, or a status says
    !> which value is out of range.
    subroutine decades()
        real(wp), parameter :: ms(4) = [1.0e-20_wp, 1.0e-9_wp, 1.0_wp, 1.0e6_wp]
        real(wp), parameter :: us(4) = [1.0e-8_wp, 1.0e-3_wp, 1.0_wp, 1.0e4_wp]
        real(wp), parameter :: tcs(3) = [1.0e-12_wp, 1.0e-6_wp, 1.0_wp]
        real(wp), parameter :: es(3) = [0.05_wp, 0.5_wp, 0.95_wp]
        real(wp), parameter :: ks(4) = [1.0e-3_wp, 1.0_wp, 1.0e6_wp, 1.0e15_wp]
        real(wp), parameter :: ds(4) = [0.0_wp, 1.0e-3_wp, 1.0_wp, 1.0e6_wp]
        real(wp) :: k, d, a, ts, e2, tc2, zm
        integer :: im, iu, it, ie, ik, id, st, st2, n_ok, n_range
        character(len=80) :: lab
        n_ok = 0
        n_range = 0
        do im = 1, size(ms)
            do iu = 1, size(us)
                do it = 1, size(tcs)
                    do ie = 1, size(es)
                        write (lab, '(a,4es9.1)') ' m,u,tc,e=', ms(im), us(iu), tcs(it), es(ie)
                        call hertzdamp_invert(es(ie), tcs(it), ms(im), us(iu), HD_END_OVERLAP, k, d, st)
                        call seen(3, [k, d])
                        if (st /= HD_OK) then
                            call s%check(st == HD_OUT_OF_RANGE, 'invert: ok or out of range' // lab)
                            n_range = n_range + 1
                            cycle
                        end if
                        call hertzdamp_forward_dim(k, d, ms(im), us(iu), HD_END_OVERLAP, HD_METHOD_RK45, a, ts, e2, tc2, &
                                                   zm, st2, tol=1.0e-13_wp)
                        call seen(3, [a, ts, e2, tc2, zm])
                        if (st2 == HD_OUT_OF_RANGE) then
                            n_range = n_range + 1
                            cycle
                        end if
                        call s%check(st2 == HD_OK, 'forward of invert: status' // lab)
                        call s%check(rel_err(e2, es(ie)) <= 1.0e-10_wp .and. rel_err(tc2, tcs(it)) <= 1.0e-10_wp, &
                                     'forward of invert round trip to 1e-10' // lab)
                        n_ok = n_ok + 1
                    end do
                end do
            end do
        end do
        call s%check(n_ok + n_range == 144 .and. n_ok >= 100, 'every decade combination round-trips or says out of range')
        print '(a,i0,a,i0,a)', '  decades: ', n_ok, ' round trips, ', n_range, ' out-of-range statuses'
        ! forward problem with every decade of k and d
        do im = 1, size(ms)
            do iu = 1, size(us)
                do ik = 1, size(ks)
                    do id = 1, size(ds)
                        call hertzdamp_forward_dim(ks(ik), ds(id), ms(im), us(iu), HD_END_OVERLAP, HD_METHOD_FIT, &
                                                   a, ts, e2, tc2, zm, st)
                        call seen(3, [a, ts, e2, tc2, zm])
                        call s%check(st == HD_OK .or. st == HD_NO_REBOUND .or. st == HD_OUT_OF_RANGE, &
                                     'forward over decades: a clear status')
                        if (st == HD_OK) call s%check(ieee_is_finite(tc2) .and. e2 > 0.0_wp, 'forward finite')
                    end do
                end do
            end do
        end do
    end subroutine decades

    subroutine bad_arguments()
        real(wp) :: bad(5), k, d, a, ts, e, tc, zm
        integer :: i, st
        bad = [0.0_wp, -1.0_wp, nan, pinf, ninf]
        do i = 1, size(bad)
            call hertzdamp_invert(0.5_wp, 1.0e-4_wp, bad(i), 1.0_wp, HD_END_OVERLAP, k, d, st)
            call seen(4, [k, d])
            call s%check(st == HD_BAD_MASS, 'invert: bad mass named')
            call hertzdamp_invert(0.5_wp, 1.0e-4_wp, 1.0_wp, bad(i), HD_END_OVERLAP, k, d, st)
            call seen(4, [k, d])
            call s%check(st == HD_BAD_VELOCITY, 'invert: bad velocity named')
            call hertzdamp_invert(0.5_wp, bad(i), 1.0_wp, 1.0_wp, HD_END_OVERLAP, k, d, st)
            call seen(4, [k, d])
            call s%check(st == HD_BAD_TIME, 'invert: bad contact time named')
            call hertzdamp_invert(0.5_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, HD_END_OVERLAP, k, d, st, k_phys=bad(i))
            call seen(4, [k, d])
            call s%check(st == HD_BAD_KPHYS, 'invert: bad k_phys named')
            call hertzdamp_forward_dim(bad(i), 1.0_wp, 1.0_wp, 1.0_wp, HD_END_OVERLAP, HD_METHOD_FIT, a, ts, e, tc, zm, st)
            call seen(4, [a, ts, e, tc, zm])
            call s%check(st == HD_BAD_STIFFNESS, 'forward: bad stiffness named')
            call hertzdamp_forward_dim(1.0_wp, 1.0_wp, bad(i), 1.0_wp, HD_END_OVERLAP, HD_METHOD_FIT, a, ts, e, tc, zm, st)
            call seen(4, [a, ts, e, tc, zm])
            call s%check(st == HD_BAD_MASS, 'forward: bad mass named')
            call hertzdamp_forward_dim(1.0_wp, 1.0_wp, 1.0_wp, bad(i), HD_END_OVERLAP, HD_METHOD_FIT, a, ts, e, tc, zm, st)
            call seen(4, [a, ts, e, tc, zm])
            call s%check(st == HD_BAD_VELOCITY, 'forward: bad velocity named')
            if (i > 1) then   ! d = 0 is valid (no damping)
                call hertzdamp_forward_dim(1.0_wp, bad(i), 1.0_wp, 1.0_wp, HD_END_OVERLAP, HD_METHOD_FIT, a, ts, e, tc, &
                                           zm, st)
                call seen(4, [a, ts, e, tc, zm])
                call s%check(st == HD_BAD_DAMPING, 'forward: bad damping named')
            end if
        end do
        call hertzdamp_invert(0.5_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, 7, k, d, st)
        call s%check(st == HD_BAD_END, 'invert: bad end named')
        call review_fixes()
    end subroutine bad_arguments

    !> Cases found in review: each once gave a wrong answer or hung.
    subroutine review_fixes()
        real(wp) :: ac, k, d, a, ts, e, tc, zm
        integer :: st
        type(hertzdamp_collision) :: r
        call hertzdamp_alpha_c(ac, st, tol=0.0_wp)          ! used to loop for ever
        call s%check(st == HD_BAD_TOL, 'alpha_c: zero bisection width refused')
        call hertzdamp_alpha_c(ac, st, tol=nan)             ! used to return 1.125 with HD_OK
        call s%check(st == HD_BAD_TOL, 'alpha_c: NaN width refused')
        r = hertzdamp_forward_alpha(0.7_wp, HD_END_OVERLAP, HD_METHOD_SERIES, order=1)  ! e < 0 from order 1
        call s%check(r%status == HD_OUTSIDE_VALIDITY .and. r%e == 0.0_wp, 'series: negative e is not a result')
        call hertzdamp_invert(1.0_wp, 1.0e-4_wp, 1.0e-3_wp, 1.0_wp, HD_END_OVERLAP, k, d, st, alpha=a)
        call s%check(st == HD_OK .and. .not. sign(1.0_wp, a) < 0.0_wp .and. .not. sign(1.0_wp, d) < 0.0_wp, &
                     'e = 1: alpha and d are +0, not -0')
        call hertzdamp_reduce(1.0e10_wp, 1.0e-310_wp, 1.0_wp, 1.0_wp, a, ts, st)
        call s%check(st == HD_OK .and. a == 0.0_wp .and. ts > 0.0_wp, 'subnormal damping: alpha underflows to 0')
        call hertzdamp_forward_dim(1.0e10_wp, 1.0e6_wp, 1.0e-3_wp, 1.0_wp, HD_END_FORCE, HD_METHOD_FIT, a, ts, e, tc, zm, st)
        call s%check(st /= HD_OK .and. a == 0.0_wp .and. ts == 0.0_wp .and. e == 0.0_wp, &
                     'forward_dim: every output 0 on failure')
        ! no rebound whose deepest overlap u t* z_max overflows (adversarial review):
        ! out of range, every output finite, not a no-rebound row with zeta_max = +Inf
        call hertzdamp_forward_dim(1.0e-320_wp, 1.0_wp, 1.0e-3_wp, 1.0e300_wp, HD_END_OVERLAP, HD_METHOD_FIT, a, ts, &
                                   e, tc, zm, st)
        call s%check(st == HD_OUT_OF_RANGE .and. ieee_is_finite(zm) .and. ieee_is_finite(tc), &
                     'forward_dim: an overflowing zeta_max is out of range, never Inf')
    end subroutine review_fixes

end program test_edges
