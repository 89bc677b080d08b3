!> The figures of issue 32 (README.md, doc/host-schemes.md section 6): per-contact constants
!> from the onset phase.
!>
!> 1. The largest single-contact error of e and T_c with hertzdamp_pair_kd_phase, over 1000
!>    stratified onset phases and the tie's phases 1e-15, 1 - 1e-15 and 1, for lammps,
!>    mfix-euler and mfix-ab2, every law and contact end,
!>    e = 0.1, 0.2, 0.5, 0.9, 0.99 and N = 10, 20, 100 (each contact's k and d reduced to
!>    alpha, h and run by hertzdamp_host_collide; test/unit/test_phase.f90 checks a grid of
!>    them with steppers of its own), beside the mean-exact constants' largest error.
!> 2. The fewest N at which every onset phase is reachable (hertzdamp_phase_min_steps), per e,
!>    law and scheme, both contact ends, with the largest single-contact error of e there over
!>    the same phases (in parentheses).
!>
!> Run: fpm run --example phase_figures --flag "-O3 -march=x86-64-v2 -funroll-loops -fPIC" [-- min-steps]
!> (figure 2 only with an argument: it searches N for every case, a few minutes)
program phase_figures
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_HOST_LAMMPS, HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2, &
                         HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO, HD_END_OVERLAP, HD_END_FORCE, hertzdamp_pair_t, &
                         hertzdamp_pair_init, hertzdamp_pair_kd, hertzdamp_pair_kd_phase, hertzdamp_reduce, &
                         hertzdamp_host_collide, hertzdamp_host_name, hertzdamp_phase_min_steps, hertzdamp_law_name
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: hosts(3) = [HD_HOST_LAMMPS, HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2]
    real(wp), parameter :: es(5) = [0.1_wp, 0.2_wp, 0.5_wp, 0.9_wp, 0.99_wp], ns(3) = [10.0_wp, 20.0_wp, 100.0_wp]
    real(wp), parameter :: m = 1.0e-3_wp, u = 1.0_wp, dt = 1.0e-6_wp
    integer, parameter :: n_phase = 1000
    !> the phases past the stratified ones: both sides of a whole N's tie (phi = 1)
    real(wp), parameter :: extra(3) = [1.0e-15_wp, 1.0_wp - 1.0e-15_wp, 1.0_wp]
    type(hertzdamp_pair_t) :: pair
    real(wp) :: emax, tmax, mmax, err(3), phi, k, d, a, ts, e, tau
    integer :: ih, law, iend, ie, in, j, st, met, unreach, nmin(2)
    character(len=24) :: cell(4)

    write (*, '(a)') '<!-- BEGIN phase_figures 1 -->'
    write (*, '(a)') '| host | targets met | unreachable at N | phase form: max err e | max err T_c | ' // &
        'mean-exact constants: max err e |'
    write (*, '(a)') '|---|---|---|---|---|---|'
    do ih = 1, 3
        emax = 0.0_wp
        tmax = 0.0_wp
        mmax = 0.0_wp
        met = 0
        unreach = 0
        do law = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
            do iend = HD_END_OVERLAP, HD_END_FORCE
                do ie = 1, size(es)
                    do in = 1, size(ns)
                        call hertzdamp_pair_init(es(ie), law, iend, hosts(ih), ns(in), pair, st, phase=.true.)
                        if (st /= HD_OK) then
                            unreach = unreach + 1
                            cycle
                        end if
                        met = met + 1
                        do j = 1, n_phase + size(extra)
                            phi = phase_of(j)
                            call hertzdamp_pair_kd_phase(pair, ns(in) * dt, m, u, 0.0_wp, phi, k, d, st)
                            call contact(k, d, err(1:2), ns(in))
                            call hertzdamp_pair_kd(pair, ns(in) * dt, m, u, k, d, st)
                            call contact(k, d, err(3:3), ns(in))
                            emax = max(emax, err(1))
                            tmax = max(tmax, err(2))
                            mmax = max(mmax, err(3))
                        end do
                    end do
                end do
            end do
        end do
        write (*, '(a, i0, a, i0, a, es8.1, a, es8.1, a, f6.1, a)') '| ' // trim(hertzdamp_host_name(hosts(ih))) // &
            ' | ', met, ' | ', unreach, ' | ', emax, ' | ', tmax, ' | ', 100.0_wp * mmax, ' % |'
    end do
    write (*, '(a)') '<!-- END phase_figures 1 -->'
    if (command_argument_count() < 1) stop
    write (*, '(a)') ''
    write (*, '(a)') '<!-- BEGIN phase_figures 2 -->'
    write (*, '(a)') '| law | e | lammps, mfix-euler: overlap | force | mfix-ab2: overlap | force |'
    write (*, '(a)') '|---|---|---|---|---|---|'
    do law = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
        do ie = 1, size(es)
            do ih = 2, 3
                do iend = HD_END_OVERLAP, HD_END_FORCE
                    call hertzdamp_phase_min_steps(es(ie), law, iend, hosts(ih), nmin(iend + 1), st)
                    if (st /= HD_OK) nmin(iend + 1) = -1
                    ! the largest error of e over 1000 phases at that N
                    emax = huge(1.0_wp)
                    in = 1
                    if (st == HD_OK) call hertzdamp_pair_init(es(ie), law, iend, hosts(ih), real(nmin(iend + 1), wp), &
                                                              pair, st, phase=.true.)
                    if (st == HD_OK) then
                        emax = 0.0_wp
                        do j = 1, n_phase + size(extra)
                            phi = phase_of(j)
                            call hertzdamp_pair_kd_phase(pair, nmin(iend + 1) * dt, m, u, 0.0_wp, phi, k, d, st)
                            call contact(k, d, err(1:1), real(nmin(iend + 1), wp))
                            emax = max(emax, err(1))
                        end do
                    end if
                    if (emax < 1.0_wp) then
                        write (cell(2 * (ih - 2) + iend + 1), '(i4, a, es7.1, a)') nmin(iend + 1), ' (', emax, ')'
                    else
                        write (cell(2 * (ih - 2) + iend + 1), '(i4, a)') nmin(iend + 1), ' (a phase fails)'
                    end if
                end do
            end do
            write (*, '(a, f4.2, 5a)') '| ' // trim(hertzdamp_law_name(law)) // ' | ', es(ie), &
                (' | ' // trim(adjustl(cell(j))), j = 1, 4), ' |'
        end do
    end do
    write (*, '(a)') '<!-- END phase_figures 2 -->'

contains

    !> Phase j: the stratified midpoints, then the extra ones.
    pure real(wp) function phase_of(j)
        integer, intent(in) :: j
        if (j <= n_phase) then
            phase_of = (real(j, wp) - 0.5_wp) / n_phase
        else
            phase_of = extra(j - n_phase)
        end if
    end function phase_of

    !> The relative errors of e and T_c (or of e only) of the contact with k, d at phase phi.
    subroutine contact(kk, dd, er, n)
        real(wp), intent(in) :: kk, dd, n
        real(wp), intent(out) :: er(:)
        integer :: s
        call hertzdamp_reduce(kk, dd, m, u, a, ts, s, law)
        call hertzdamp_host_collide(a, dt / ts, phi, law, iend, hosts(ih), e, tau, s)
        er(1) = abs(e / es(ie) - 1.0_wp)
        if (size(er) > 1) er(2) = abs(tau * ts / (n * dt) - 1.0_wp)
        if (s /= HD_OK) er = huge(1.0_wp)
    end subroutine contact

end program phase_figures
