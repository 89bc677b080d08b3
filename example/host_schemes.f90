!> What a DEM host's own integrator makes of hertzdamp's constants, and what the
!> host-exact per-pair constants give (doc/host-schemes.md prints these tables).
!>
!>     fpm run --example host_schemes
!>
!> 1. Today: the continuous k, d (alpha(e), tau_c of the fit) in each host, linear law,
!>    overlap end, N = 10 and 20 steps per contact: the mean error of e and T_c over the
!>    onset phase and the spread (standard deviation over the phase).
!> 2. The per-pair constants (hertzdamp_host_solve): alpha_N / alpha, tau_N / tau_c, the
!>    residual mean errors, the spread left.
!> 3. The spread with and without the onset/release correction (lammps, lammps-phase),
!>    every law and end, at the per-pair constants.
!> 4. MFiX 21.3.2's measured runs (e = 0.5) against the range of the two MFiX schemes.
!> 5. The cost per material pair: one hertzdamp_pair_init (milliseconds on the machine that
!>    runs it).
!> 6. The scene engine (verlet) near e = 1: overlap and force end at alpha -> 0.
program host_schemes
    use hertzdamp
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: hosts(5) = [HD_HOST_LAMMPS, HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2, HD_HOST_VERLET, &
                                      HD_HOST_LAMMPS_PHASE]
    real(wp), parameter :: es(5) = [0.1_wp, 0.2_wp, 0.5_wp, 0.9_wp, 0.99_wp], ns(2) = [10.0_wp, 20.0_wp]

    call today()
    call constants()
    call correction()
    call mfix_runs()
    call cost()
    call verlet_elastic()

contains

    subroutine today()
        type(hertzdamp_host_stats) :: s
        real(wp) :: a0, t0
        integer :: i, k, j, st
        print '(a)', '## 1. Continuous constants in the host: mean error of e and T_c, and the spread of e (sd), ' // &
            'linear law, overlap end'
        print '(a)', ''
        print '(a)', '| e | N | lammps, mfix-euler | mfix-ab2 | verlet | lammps-phase |'
        print '(a)', '|---|---|---|---|---|---|'
        do i = 1, size(es)
            call hertzdamp_fit_inverse(es(i), HD_END_OVERLAP, a0, t0, st)
            do k = 1, size(ns)
                write (*, '(a,f4.2,a,i0,a)', advance='no') '| ', es(i), ' | ', nint(ns(k)), ' |'
                do j = 1, size(hosts)
                    if (hosts(j) == HD_HOST_MFIX_EULER) cycle
                    call hertzdamp_host_mean(a0, t0 / ns(k), HD_DAMPING_LINEAR, HD_END_OVERLAP, hosts(j), s, st)
                    if (st == HD_OK) then
                        write (*, '(a,f7.2,a,f6.2,a,f5.1,a)', advance='no') ' ', 100 * (s%e_mean / es(i) - 1), ' % / ', &
                            100 * (s%tau_mean / t0 - 1), ' %, sd ', 100 * s%e_sd / es(i), ' % |'
                    else
                        write (*, '(a)', advance='no') ' ' // trim(hertzdamp_message(st)) // ' |'
                    end if
                end do
                print '(a)', ''
            end do
        end do
        print '(a)', ''
    end subroutine today

    subroutine constants()
        type(hertzdamp_host_stats) :: s
        real(wp) :: a0, t0, a, t, err, worst
        integer :: i, k, j, st
        print '(a)', '## 2. Per-pair constants (linear law, overlap end): alpha_N/alpha, tau_N/tau_c, ' // &
            'mean errors left, spread of e and T_c (sd, max - min)'
        print '(a)', ''
        print '(a)', '| host | e | N | alpha_N/alpha | tau_N/tau_c | means within 1e-11 | e sd | e max-min |' // &
            ' T_c sd | T_c max-min |'
        print '(a)', '|---|---|---|---|---|---|---|---|---|---|'
        worst = 0.0_wp
        do j = 1, size(hosts)
            if (hosts(j) == HD_HOST_MFIX_EULER) cycle
            do i = 1, size(es)
                call hertzdamp_fit_inverse(es(i), HD_END_OVERLAP, a0, t0, st)
                do k = 1, size(ns)
                    call hertzdamp_host_solve(es(i), HD_DAMPING_LINEAR, HD_END_OVERLAP, hosts(j), ns(k), a, t, s, st)
                    write (*, '(a,a,a,f4.2,a,i0,a)', advance='no') '| ', hertzdamp_host_name(hosts(j)), ' | ', es(i), ' | ', &
                        nint(ns(k)), ' |'
                    if (st /= HD_OK) then
                        print '(a)', ' ' // trim(hertzdamp_message(st)) // ' | | | | | |'
                        cycle
                    end if
                    err = max(abs(s%e_mean / es(i) - 1), abs(s%tau_mean / t - 1))
                    worst = max(worst, err)
                    print '(2(f8.4,a),2a,4(f6.2,a))', a / a0, ' | ', t / t0, ' | ', merge('yes', 'no ', err < 1.0e-11_wp), &
                        ' | ', 100 * s%e_sd / es(i), ' % | ', 100 * (s%e_max - s%e_min) / es(i), &
                        ' % | ', 100 * s%tau_sd / t, ' % | ', 100 * (s%tau_max - s%tau_min) / t, ' % |'
                end do
            end do
        end do
        print '(a)', ''
        print '(a,es8.1,a)', 'Largest relative error of the phase means at the constants: ', worst, &
            ' (the library''s own quadrature; the last digits vary with the compiler flags).'
        print '(a)', ''
    end subroutine constants

    subroutine correction()
        type(hertzdamp_host_stats) :: s
        real(wp) :: a, t
        integer :: law, iend, k, j, st
        integer, parameter :: two(2) = [HD_HOST_LAMMPS, HD_HOST_LAMMPS_PHASE]
        print '(a)', '## 3. Spread without and with the onset/release correction (per-pair constants, e = 0.5): ' // &
            'sd and max - min of e and T_c, % of the target'
        print '(a)', ''
        print '(a)', '| law | end | N | lammps: e sd, range; T_c sd, range | lammps-phase: e sd, range; T_c sd, range |'
        print '(a)', '|---|---|---|---|---|'
        do law = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
            do iend = HD_END_OVERLAP, HD_END_FORCE
                do k = 1, size(ns)
                    write (*, '(5a,i0,a)', advance='no') '| ', hertzdamp_law_name(law), ' | ', hertzdamp_end_name(iend), &
                        ' | ', nint(ns(k)), ' |'
                    do j = 1, 2
                        call hertzdamp_host_solve(0.5_wp, law, iend, two(j), ns(k), a, t, s, st)
                        write (*, '(4(f7.3,a))', advance='no') 100 * s%e_sd / 0.5_wp, ', ', &
                            100 * (s%e_max - s%e_min) / 0.5_wp, '; ', 100 * s%tau_sd / t, ', ', &
                            100 * (s%tau_max - s%tau_min) / t, ' |'
                    end do
                    print '(a)', ''
                end do
            end do
        end do
        print '(a)', ''
    end subroutine correction

    subroutine mfix_runs()
        type(hertzdamp_host_stats) :: s
        real(wp) :: a0, t0
        integer :: law, k, j, st
        integer, parameter :: two(2) = [HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2]
        print '(a)', '## 4. MFiX, e = 0.5, continuous constants: mean and range of e over the phase, % of the target'
        print '(a)', ''
        print '(a)', '| law | N | mfix-euler: mean [min, max] | mfix-ab2: mean [min, max] |'
        print '(a)', '|---|---|---|---|'
        do law = HD_DAMPING_LINEAR, HD_DAMPING_TSUJI
            call hertzdamp_fit_inverse(0.5_wp, HD_END_OVERLAP, a0, t0, st, law)
            do k = 1, size(ns)
                write (*, '(3a,i0,a)', advance='no') '| ', hertzdamp_law_name(law), ' | ', nint(ns(k)), ' |'
                do j = 1, 2
                    call hertzdamp_host_mean(a0, t0 / ns(k), law, HD_END_OVERLAP, two(j), s, st)
                    write (*, '(3(f7.2,a))', advance='no') 100 * (s%e_mean / 0.5_wp - 1), ' [', &
                        100 * (s%e_min / 0.5_wp - 1), ', ', 100 * (s%e_max / 0.5_wp - 1), '] |'
                end do
                print '(a)', ''
            end do
        end do
        print '(a)', ''
    end subroutine mfix_runs

    subroutine cost()
        real(wp), parameter :: nn(4) = [10.0_wp, 20.0_wp, 100.0_wp, 1000.0_wp]
        type(hertzdamp_pair_t) :: pair
        real(wp) :: best
        integer :: j, k, r, st
        integer(int64) :: c0, c1, cr
        print '(a)', '## 5. Cost per material pair: one hertzdamp_pair_init, ms (e = 0.5, linear law, overlap end; best of 3)'
        print '(a)', ''
        print '(a)', '| host | N = 10 | N = 20 | N = 100 | N = 1000 |'
        print '(a)', '|---|---|---|---|---|'
        do j = 1, size(hosts)
            write (*, '(3a)', advance='no') '| ', hertzdamp_host_name(hosts(j)), ' |'
            do k = 1, size(nn)
                best = huge(1.0_wp)
                do r = 1, 3
                    call system_clock(c0, cr)
                    call hertzdamp_pair_init(0.5_wp, HD_DAMPING_LINEAR, HD_END_OVERLAP, hosts(j), nn(k), pair, st)
                    call system_clock(c1)
                    best = min(best, real(c1 - c0, wp) * 1.0e3_wp / real(cr, wp))
                end do
                write (*, '(f9.2,a)', advance='no') best, ' |'
            end do
            print '(a)', ''
        end do
    end subroutine cost

    subroutine verlet_elastic()
        type(hertzdamp_host_stats) :: s
        real(wp), parameter :: alphas(2) = [0.0_wp, 1.0e-6_wp]
        integer :: iend, k, st, nmin
        print '(a)', ''
        print '(a)', '## 6. verlet near e = 1 (linear law, N = 10 at tau_c(0)): e_mean - 1 at alpha = 0 and 1e-6'
        print '(a)', ''
        print '(a)', '| end | alpha = 0 | alpha = 1e-6 | N_min for e = 0.999 |'
        print '(a)', '|---|---|---|---|'
        do iend = HD_END_OVERLAP, HD_END_FORCE
            write (*, '(3a)', advance='no') '| ', hertzdamp_end_name(iend), ' |'
            do k = 1, 2
                call hertzdamp_host_mean(alphas(k), hertzdamp_tau_c0() / 10.0_wp, HD_DAMPING_LINEAR, iend, HD_HOST_VERLET, &
                                         s, st)
                write (*, '(es10.2,a)', advance='no') s%e_mean - 1.0_wp, ' |'
            end do
            call hertzdamp_host_min_steps(0.999_wp, HD_DAMPING_LINEAR, iend, HD_HOST_VERLET, nmin, st)
            print '(i5,a)', nmin, ' |'
        end do
    end subroutine verlet_elastic

end program host_schemes
