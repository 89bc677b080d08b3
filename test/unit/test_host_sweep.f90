!> The figure of issue 26 (doc/host-schemes.md section 5.7): with the per-pair constants
!> (hertzdamp_pair_init) the mean achieved e and T_c over the onset phase are within 1e-3
!> of the targets for N >= 10, e in [0.1, 0.99], every law, both contact ends and every
!> scheme; the continuous constants (host none) on the same grid for contrast.
!>
!> The means come from this test's own simulation of each scheme and its own breakpoint
!> search and graded Gauss-Legendre quadrature (hertzdamp_test_host_sim, no code shared
!> with the library; quadrature error below 1e-12, test_host), not from hertzdamp_host_collide.
!> A target that the host cannot reach at N (HD_HOST_UNREACHABLE) must have
!> hertzdamp_host_min_steps > N; it is counted, not hidden.
!>
!>     fpm test test_host_sweep              the coarse grid (make test): e 0.1, 0.5, 0.99; N 10, 100
!>     fpm test test_host_sweep -- full      the full grid of the doc: e 0.1 ... 0.99 (9), N 10, 20, 50, 100, 1000
program test_host_sweep
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_HOST_UNREACHABLE, HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, &
                         HD_DAMPING_KUWABARA_KONO, HD_END_OVERLAP, HD_END_FORCE, HD_HOST_LAMMPS, HD_HOST_MFIX_EULER, &
                         HD_HOST_MFIX_AB2, HD_HOST_VERLET, HD_HOST_LAMMPS_PHASE, HD_HOST_NONE, hertzdamp_host_name, &
                         hertzdamp_law_name, hertzdamp_end_name, hertzdamp_pair_t, hertzdamp_pair_init, &
                         hertzdamp_host_min_steps
    use hertzdamp_testing, only: test_suite, new_suite
    use hertzdamp_test_host_sim, only: own_mean
    use hertzdamp_text_format, only: itoa, fmt_short
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: laws(3) = [HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO]
    integer, parameter :: ends(2) = [HD_END_OVERLAP, HD_END_FORCE]
    integer, parameter :: hosts(5) = [HD_HOST_LAMMPS, HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2, HD_HOST_VERLET, &
                                      HD_HOST_LAMMPS_PHASE]
    real(wp), parameter :: e_full(9) = [0.1_wp, 0.2_wp, 0.35_wp, 0.5_wp, 0.65_wp, 0.8_wp, 0.9_wp, 0.95_wp, 0.99_wp]
    real(wp), parameter :: n_full(5) = [10.0_wp, 20.0_wp, 50.0_wp, 100.0_wp, 1000.0_wp]
    real(wp), parameter :: e_coarse(3) = [0.1_wp, 0.5_wp, 0.99_wp]
    real(wp), parameter :: n_coarse(2) = [10.0_wp, 100.0_wp]
    type(test_suite) :: s
    character(len=16) :: arg
    logical :: full

    s = new_suite('test_host_sweep')
    arg = ''
    if (command_argument_count() >= 1) call get_command_argument(1, arg)
    full = arg == 'full'
    if (full) then
        call sweep(e_full, n_full)
    else
        call sweep(e_coarse, n_coarse)
    end if
    call s%finish()

contains

    !> The grid es x ns x laws x ends for every scheme: one row of the table per scheme.
    subroutine sweep(es, ns)
        real(wp), intent(in) :: es(:), ns(:)
        type(hertzdamp_pair_t) :: pair, cont
        real(wp) :: e, n, em, tm, wh(2), wc(2)
        integer :: ih, il, ie, i, k, st, nmiss, met, unreach, nmin, st2
        character(len=:), allocatable :: lab, missed
        missed = ''
        print '(a)', '<!-- BEGIN host_sweep ' // trim(merge('full  ', 'coarse', full)) // ' -->'
        print '(a)', '| host | targets met | unreachable | host constants: max err e, T_c | ' // &
            'continuous constants: max err e, T_c |'
        print '(a)', '|---|---|---|---|---|'
        do ih = 1, size(hosts)
            wh = 0.0_wp
            wc = 0.0_wp
            met = 0
            unreach = 0
            do il = 1, size(laws)
                do ie = 1, size(ends)
                    do i = 1, size(es)
                        e = es(i)
                        call hertzdamp_pair_init(e, laws(il), ends(ie), HD_HOST_NONE, 10.0_wp, cont, st)
                        call s%check(st == HD_OK, 'continuous constants ' // label(hosts(ih), laws(il), ends(ie), e, 0.0_wp))
                        do k = 1, size(ns)
                            n = ns(k)
                            lab = label(hosts(ih), laws(il), ends(ie), e, n)
                            call hertzdamp_pair_init(e, laws(il), ends(ie), hosts(ih), n, pair, st)
                            if (st == HD_HOST_UNREACHABLE) then
                                call hertzdamp_host_min_steps(e, laws(il), ends(ie), hosts(ih), nmin, st2)
                                call s%check(st2 == HD_OK .and. real(nmin, wp) > n, lab // ': unreachable, ' // &
                                             'and hertzdamp_host_min_steps says N > ' // fmt_short(n))
                                unreach = unreach + 1
                                missed = missed // ' ' // lab // ' (N >= ' // itoa(nmin) // ' can);'
                                cycle
                            end if
                            call s%check(st == HD_OK, lab // ': pair_init succeeds')
                            if (st /= HD_OK) cycle
                            call own_mean(pair%alpha, pair%tau_c / n, laws(il), ends(ie), hosts(ih), em, tm, nmiss)
                            call s%check(nmiss == 0, lab // ': own quadrature found every piece')
                            wh = max(wh, [abs(em / e - 1.0_wp), abs(tm / pair%tau_c - 1.0_wp)])
                            call s%check(abs(em / e - 1.0_wp) <= 1.0e-3_wp .and. abs(tm / pair%tau_c - 1.0_wp) <= 1.0e-3_wp, &
                                         lab // ': mean e and T_c within 1e-3 of the targets, ' // &
                                         fmt_short(em / e - 1.0_wp, 3) // ', ' // fmt_short(tm / pair%tau_c - 1.0_wp, 3))
                            met = met + 1
                            ! the continuous constants in the same scheme (contrast)
                            call own_mean(cont%alpha, cont%tau_c / n, laws(il), ends(ie), hosts(ih), em, tm, nmiss)
                            if (nmiss == 0 .and. em > 0.0_wp) then
                                wc = max(wc, [abs(em / e - 1.0_wp), abs(tm / cont%tau_c - 1.0_wp)])
                            end if
                        end do
                    end do
                end do
            end do
            print '(a)', '| ' // hertzdamp_host_name(hosts(ih)) // ' | ' // itoa(met) // ' | ' // itoa(unreach) // ' | ' // &
                fmt_short(wh(1), 2) // ', ' // fmt_short(wh(2), 2) // ' | ' // fmt_short(100 * wc(1), 3) // ' %, ' // &
                fmt_short(100 * wc(2), 3) // ' % |'
            call s%check(met > 0 .and. maxval(wh) <= 1.0e-3_wp, hertzdamp_host_name(hosts(ih)) // ': every target met ' // &
                         'within 1e-3 (max ' // fmt_short(maxval(wh), 3) // ')')
            call s%check(maxval(wc) > 1.0e-3_wp, hertzdamp_host_name(hosts(ih)) // ': the continuous constants miss by ' // &
                         'more than 1e-3 somewhere on the grid')
        end do
        print '(a)', '<!-- END host_sweep ' // trim(merge('full  ', 'coarse', full)) // ' -->'
        if (len(missed) > 0) print '(a)', 'unreachable:' // missed
    end subroutine sweep

    !> 'host law end e = .. N = ..' for the check labels.
    function label(host, law, iend, e, n) result(t)
        integer, intent(in) :: host, law, iend
        real(wp), intent(in) :: e, n
        character(len=:), allocatable :: t
        t = hertzdamp_host_name(host) // ' ' // hertzdamp_law_name(law) // ' ' // hertzdamp_end_name(iend) // ' e = ' // &
            fmt_short(e, 3) // ' N = ' // fmt_short(n, 4)
    end function label

end program test_host_sweep
