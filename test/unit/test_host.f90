!> The host schemes and the per-pair host-exact constants (hertzdamp_host,
!> doc/host-schemes.md), against references that share no code with the library:
!> - each scheme stepped by this program's own code (LAMMPS written as velocity Verlet
!>   with two half kicks, MFiX's EULER and ADAMS_BASHFORTH in MFiX's form, the scene
!>   engine's sequence with its corrections, the plugin's phase force with this program's
!>   own Hurwitz zeta) agrees with hertzdamp_host_collide at random phases;
!> - the real engines: the scene engine of packages/dem/ (verlet) and Debian's LAMMPS (`lmp`,
!>   pair_style granular hertz with damping velocity and viscoelastic, with and without
!>   limit_damping) give the same e per phase;
!> - the phase means against this program's own breakpoint search and quadrature
!>   (composite Gauss-Legendre, its nodes computed here, on meshes graded towards every
!>   breakpoint);
!> - the per-pair constants make the phase means equal the targets to 1e-10 (e 0.1 to 0.99,
!>   N 5 to 1000, every law, end and scheme), host none is bit-identical to the fit's
!>   inverse, the constants converge to the continuous ones at the scheme's order, the
!>   mean tends to the continuous e and tau_c (reference integrator) as h -> 0;
!> - hertzdamp_host_min_steps (N_min - 1 fails, N_min succeeds), hertzdamp_host_alpha_for_e,
!>   the Hurwitz function (duplication formula, zeta(-1/2), zeta(-3/2)) and the phase force
!>   (the plugin's formula bit for bit for the linear law), and every bad argument.
program test_host
    use hertzdamp
    use hertzdamp_host, only: hertzdamp_host_hurwitz
    use hertzdamp_dem, only: hertzdamp_dem_scene, hertzdamp_dem_result, hertzdamp_dem_material, hertzdamp_dem_wall, &
                             hertzdamp_dem_check, hertzdamp_dem_run
    use hertzdamp_testing, only: test_suite, new_suite, rel_err
    use hertzdamp_test_host_sim, only: coll_t, zeta_h, collide, own_mean
    use hertzdamp_text_format, only: itoa, fmt_short
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: laws(3) = [HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO]
    integer, parameter :: ends(2) = [HD_END_OVERLAP, HD_END_FORCE]
    integer, parameter :: hosts(5) = [HD_HOST_LAMMPS, HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2, HD_HOST_VERLET, &
                                      HD_HOST_LAMMPS_PHASE]
    real(wp), parameter :: pi = acos(-1.0_wp)
    type(test_suite) :: s

    s = new_suite('test_host')
    call names_and_codes()
    call hurwitz_and_phase_force()
    call steppers_agree()
    call phases_side_by_side()
    call scene_engine_agrees()
    call lammps_agrees()
    call means_agree()
    call solve_meets_targets()
    call none_is_the_fit()
    call solve_order()
    call mean_tends_to_continuous()
    call min_steps()
    call reachable_found()
    call few_steps_found()
    call alpha_for_e()
    call bad_input()
    call s%finish()

contains

    ! ================================================================ names

    subroutine names_and_codes()
        integer :: k
        do k = 0, hertzdamp_max_host
            call s%check(hertzdamp_host_code(hertzdamp_host_name(k)) == k, 'host name round trip ' // hertzdamp_host_name(k))
        end do
        call s%check(hertzdamp_host_name(HD_HOST_MFIX_AB2) == 'mfix-ab2' .and. &
                     hertzdamp_host_name(HD_HOST_LAMMPS_PHASE) == 'lammps-phase', 'host names')
        call s%check(hertzdamp_host_code('liggghts') == -1 .and. hertzdamp_host_name(hertzdamp_max_host + 1) == 'unknown', &
                     'unknown host')
        call s%check(HD_BAD_HOST == 26 .and. HD_BAD_STEPS == 27 .and. HD_HOST_UNREACHABLE == 28, 'status numbers')
        do k = 26, 28
            call s%check(len(hertzdamp_message(k)) > 30 .and. hertzdamp_message(k) /= 'unknown status code', &
                         'message of status ' // itoa(k))
        end do
    end subroutine names_and_codes

    ! ================================================================ Hurwitz zeta, phase force


    subroutine hurwitz_and_phase_force()
        real(wp), parameter :: zm12 = -0.2078862249773545660173067_wp   ! zeta(-1/2)
        real(wp), parameter :: zm32 = -0.0254852018898330359495429_wp   ! zeta(-3/2)
        real(wp) :: p(3), a, worst, dup, f, fr, x
        integer :: i, j, law
        p = [0.25_wp, 0.5_wp, 1.5_wp]
        ! absolute accuracy: the sum of eight terms cancels against the tail (1e-14 for
        ! p = 1/2, 1e-13 for p = 3/2)
        call s%check_close(hertzdamp_host_hurwitz(0.5_wp, 1.0_wp), zm12, 0.0_wp, 'zeta(-1/2, 1) = zeta(-1/2)', 1.0e-14_wp)
        call s%check_close(hertzdamp_host_hurwitz(0.5_wp, 0.0_wp), zm12, 0.0_wp, 'zeta(-1/2, 0) = zeta(-1/2)', 1.0e-14_wp)
        call s%check_close(hertzdamp_host_hurwitz(1.5_wp, 1.0_wp), zm32, 0.0_wp, 'zeta(-3/2, 1) = zeta(-3/2)', 1.0e-13_wp)
        call s%check_close(hertzdamp_host_hurwitz(0.5_wp, 0.5_wp), (2.0_wp**(-0.5_wp) - 1.0_wp) * zm12, 0.0_wp, &
                           'zeta(-1/2, 1/2) = (2^(-1/2) - 1) zeta(-1/2)', 1.0e-14_wp)
        ! duplication: zeta(-p, a) + zeta(-p, a + 1/2) = 2^p zeta(-p, 2a), a in [0, 1/2];
        ! and this program's own zeta
        worst = 0.0_wp
        do i = 1, 3
            do j = 0, 20
                a = 0.025_wp * j
                dup = hertzdamp_host_hurwitz(p(i), a) + hertzdamp_host_hurwitz(p(i), a + 0.5_wp) &
                      - 2.0_wp**(-p(i)) * hertzdamp_host_hurwitz(p(i), 2.0_wp * a)
                worst = max(worst, abs(dup))
                worst = max(worst, abs(hertzdamp_host_hurwitz(p(i), 2.0_wp * a) - zeta_h(p(i), 2.0_wp * a)))
            end do
        end do
        call s%check(worst <= 1.0e-13_wp, 'Hurwitz zeta: duplication formula and own sum (absolute), max ' // fmt_short(worst, 3))
        call s%check(hertzdamp_host_hurwitz(0.5_wp, 1.5_wp) == 0.0_wp .and. hertzdamp_host_hurwitz(2.5_wp, 0.5_wp) == 0.0_wp, &
                     'Hurwitz zeta outside its domain: 0')
        ! linear law: the plugin's d zeta' (frac - 1/2) bit for bit, frac clamped
        worst = 0.0_wp
        do i = 0, 10
            fr = 0.1_wp * i
            f = hertzdamp_host_phase_force(3.7_wp, -0.83_wp, 1.0e-3_wp, fr, HD_DAMPING_LINEAR)
            call s%check(transfer(f, 0_int64) == transfer(3.7_wp * (-0.83_wp) * (fr - 0.5_wp), 0_int64), &
                         'phase force, linear: d zeta'' (frac - 1/2) bit for bit, frac ' // fmt_short(fr, 3))
        end do
        call s%check(hertzdamp_host_phase_force(2.0_wp, 1.0_wp, 0.1_wp, 1.7_wp, HD_DAMPING_LINEAR) == 1.0_wp .and. &
                     hertzdamp_host_phase_force(2.0_wp, 1.0_wp, 0.1_wp, -0.3_wp, HD_DAMPING_LINEAR) == -1.0_wp, &
                     'phase force: frac clamped to [0, 1]')
        x = 0.0_wp
        call s%check(hertzdamp_host_phase_force(2.0_wp, 1.0_wp, 0.1_wp, x / x, HD_DAMPING_LINEAR) == -1.0_wp, &
                     'phase force: frac NaN counts as 0 (as the plugin)')
        call s%check(hertzdamp_host_phase_force(2.0_wp, 1.0_wp, 0.1_wp, 0.3_wp, 7) == 0.0_wp, 'phase force, bad law: 0')
        ! q > 0: -d zeta' |zeta' dt|^q zeta_H(-q, frac), with this program's zeta
        worst = 0.0_wp
        do law = HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO
            do i = 0, 10
                fr = 0.1_wp * i
                f = hertzdamp_host_phase_force(3.7_wp, -0.83_wp, 1.0e-3_wp, fr, law)
                x = 3.7_wp * 0.83_wp * (0.83e-3_wp)**hertzdamp_law_q(law)
                worst = max(worst, abs(f - x * zeta_h(hertzdamp_law_q(law), fr)) / x)
            end do
        end do
        call s%check(worst <= 1.0e-13_wp, 'phase force, tsuji and kuwabara-kono: Hurwitz form, max (of d |zeta''|^(1+q) '// &
                     'dt^q) ' // fmt_short(worst, 3))
    end subroutine hurwitz_and_phase_force


    !> Every scheme, law and end at 40 random phases each (a fixed seed): e and tau_c of the
    !> library and of this program's steppers agree to 1e-12 (the schemes' round-off
    !> differs: LAMMPS's two half kicks, the first overlap (phi - 1) h + h).
    subroutine steppers_agree()
        real(wp) :: alpha, tau0, h, phi, e, tau, we, wt, r
        integer :: il, ie, ih, k, st, nbad, nseed
        integer, allocatable :: seed(:)
        type(coll_t) :: c
        call random_seed(size=nseed)
        allocate (seed(nseed))
        seed = 20261127 + [(k, k=1, nseed)]
        call random_seed(put=seed)
        do ih = 1, size(hosts)
            we = 0.0_wp
            wt = 0.0_wp
            nbad = 0
            do il = 1, 3
                do ie = 1, 2
                    do k = 1, 40
                        call random_number(r)
                        call hertzdamp_fit_inverse(0.05_wp + 0.94_wp * r, ends(ie), alpha, tau0, st, laws(il))
                        call random_number(r)
                        h = tau0 / (4.0_wp + 60.0_wp * r)
                        call random_number(phi)
                        phi = max(phi, 1.0e-3_wp)
                        call hertzdamp_host_collide(alpha, h, phi, laws(il), ends(ie), hosts(ih), e, tau, st)
                        c = collide(alpha, h, phi, laws(il), ends(ie), hosts(ih))
                        if ((st == HD_OK) .neqv. c%ok) then
                            nbad = nbad + 1
                            cycle
                        end if
                        if (st /= HD_OK) cycle
                        we = max(we, rel_err(e, c%e))
                        wt = max(wt, rel_err(tau, c%tau))
                    end do
                end do
            end do
            call s%check(nbad == 0 .and. we <= 1.0e-12_wp .and. wt <= 1.0e-12_wp, hertzdamp_host_name(hosts(ih)) // &
                         ': library and own stepper per phase, max rel e ' // fmt_short(we, 3) // ', tau_c ' // fmt_short(wt, 3))
            print '(a)', '  ' // hertzdamp_host_name(hosts(ih)) // ' vs own stepper (240 phases): max rel e ' // &
                fmt_short(we, 3) // &
                ', tau_c ' // fmt_short(wt, 3)
        end do
    end subroutine steppers_agree

    !> hertzdamp_host_collide_phases (the collisions side by side, as the phase statistics
    !> run them) against hertzdamp_host_collide one phase at a time: the same e, tau_c and
    !> status to the bit, every host, law and end, 41 phases per case (two of them outside
    !> (0, 1]), at regular constants, at a damping without rebound at some phases (alpha =
    !> 40, h = 0.5) and at a host without rebound at every phase (alpha = 5000); bad common
    !> arguments and a too short output.
    subroutine phases_side_by_side()
        integer, parameter :: np = 41
        real(wp) :: phi(np), e(np), tau(np), e1, t1, alpha, h, r
        real(wp) :: a_case(3), h_case(3)
        integer :: st(np), st1, il, ie, ih, ic, j, st0(np - 1), nbad, ncmp, nfail, nmixed
        call random_number(phi)
        phi(1) = 1.0_wp
        phi(2) = 0.0_wp
        phi(3) = 1.5_wp
        phi(4) = 1.0e-9_wp
        nbad = 0
        ncmp = 0
        nfail = 0
        nmixed = 0
        do ih = 1, size(hosts)
            do il = 1, 3
                do ie = 1, 2
                    call hertzdamp_fit_inverse(0.5_wp, ends(ie), alpha, r, st1, laws(il))
                    a_case = [alpha, 40.0_wp, 5000.0_wp]
                    h_case = [r / 23.0_wp, 0.5_wp, 0.05_wp]
                    do ic = 1, 3
                        h = h_case(ic)
                        call hertzdamp_host_collide_phases(a_case(ic), h, phi, laws(il), ends(ie), hosts(ih), e, tau, st)
                        do j = 1, np
                            call hertzdamp_host_collide(a_case(ic), h, phi(j), laws(il), ends(ie), hosts(ih), e1, t1, st1)
                            ncmp = ncmp + 1
                            if (st1 == HD_NO_REBOUND) nfail = nfail + 1
                            if (st(j) /= st1 .or. .not. (e(j) == e1 .and. tau(j) == t1)) nbad = nbad + 1
                        end do
                        if (any(st == HD_OK) .and. any(st == HD_NO_REBOUND)) nmixed = nmixed + 1
                    end do
                end do
            end do
        end do
        call s%check(nbad == 0 .and. nfail > 0 .and. nmixed > 0, &
                     'collisions side by side = one at a time, to the bit (' // itoa(ncmp) // ' phases, ' // &
                     itoa(nfail) // ' without rebound, ' // itoa(nmixed) // ' calls with both, ' // itoa(nbad) // ' differ)')
        print '(a)', '  side by side = one at a time: ' // itoa(ncmp) // ' phases, ' // itoa(nfail) // &
            ' without rebound, ' // itoa(nmixed) // ' calls with both, ' // itoa(nbad) // ' differ'
        call hertzdamp_host_collide_phases(-1.0_wp, 0.1_wp, phi, laws(1), ends(1), hosts(1), e, tau, st)
        call s%check(all(st == HD_BAD_ALPHA) .and. all(e == 0.0_wp), 'side by side: a bad alpha at every phase')
        call hertzdamp_host_collide_phases(1.0_wp, 0.1_wp, phi, laws(1), 7, hosts(1), e, tau, st)
        call s%check(all(st == HD_BAD_END), 'side by side: a bad end at every phase')
        st0 = -5
        call hertzdamp_host_collide_phases(1.0_wp, 0.1_wp, phi, laws(1), ends(1), hosts(1), e, tau, st0)
        call s%check(all(st0 == HD_BAD_ARGUMENT), 'side by side: a status array shorter than phi')
    end subroutine phases_side_by_side

    ! ================================================================ the real engines

    !> The scene engine of packages/dem/ (hertzdamp_dem_run), two steel spheres head-on at 1 m/s
    !> with T_c = N dt: its contact's e = u_out/u_in and (t_end - t_start)/t* against
    !> hertzdamp_host_collide with the contact's alpha and t* (from its k and d) and the
    !> phase of its touch.  Agreement within 1e-10 (the engine's start_error keeps three
    !> Bernoulli terms, 2e-10 of the Hertz correction h^(5/2); dimensional round-off).
    subroutine scene_engine_agrees()
        type(hertzdamp_dem_scene) :: sc
        type(hertzdamp_dem_result) :: res
        real(wp), parameter :: phis(3) = [0.13_wp, 0.58_wp, 0.97_wp]
        real(wp) :: phi, dt, gap, alpha, tstar, h, before, e, tau, we, wt
        integer :: il, ie, k, st, n
        character(len=:), allocatable :: msg
        we = 0.0_wp
        wt = 0.0_wp
        n = 0
        do il = 1, 3
            do ie = 1, 2
                do k = 1, 3
                    phi = phis(k)
                    dt = 1.0e-5_wp / 12.0_wp
                    gap = (1.0_wp - phi) * dt
                    sc%title = 'host'
                    sc%dt = dt
                    sc%steps_per_contact = 12
                    sc%end_time = 4.0e-5_wp
                    sc%iend = ends(ie)
                    sc%law = laws(il)
                    sc%want_duration = .true.
                    sc%rest_speed = 1.0e-4_wp
                    sc%samples = 10
                    sc%mat = [hertzdamp_dem_material('steel', 7800.0_wp, 2.1e11_wp, 0.3_wp, 0.4_wp, 0)]
                    sc%pmat = [1, 1]
                    sc%radius = [1.0e-3_wp, 1.0e-3_wp]
                    sc%x = reshape([-(1.0e-3_wp + 0.5_wp * gap), 0.0_wp, 0.0_wp, 1.0e-3_wp + 0.5_wp * gap, 0.0_wp, 0.0_wp], &
                                   [3, 2])
                    sc%v = reshape([0.5_wp, 0.0_wp, 0.0_wp, -0.5_wp, 0.0_wp, 0.0_wp], [3, 2])
                    sc%pline = [0, 0]
                    allocate (sc%wall(0))
                    call hertzdamp_dem_check(sc, st, msg)
                    call s%check(st == HD_OK, 'scene engine: the two-sphere scene is valid ' // msg)
                    if (st /= HD_OK) return
                    call hertzdamp_dem_run(sc, HD_METHOD_FIT, 1.0e-8_wp, res)
                    deallocate (sc%wall)
                    call s%check(res%status == HD_OK .and. res%ncontacts == 1, 'scene engine: one contact')
                    if (res%status /= HD_OK .or. res%ncontacts /= 1) return
                    associate (ct => res%contacts(1))
                        call hertzdamp_reduce(ct%k, ct%d, ct%m, ct%u_in, alpha, tstar, st, laws(il))
                        h = dt / tstar
                        before = ct%t_start / dt - aint(ct%t_start / dt)
                        call hertzdamp_host_collide(alpha, h, 1.0_wp - before, laws(il), ends(ie), HD_HOST_VERLET, e, tau, st)
                        call s%check(st == HD_OK .and. .not. ct%bound_active .and. ct%t_end > 0.0_wp, &
                                     'scene engine: contact ended, no stiffness bound, host collide succeeds')
                        we = max(we, rel_err(e, ct%u_out / ct%u_in))
                        wt = max(wt, rel_err(tau, (ct%t_end - ct%t_start) / tstar))
                        n = n + 1
                    end associate
                end do
            end do
        end do
        call s%check(n == 18 .and. we <= 1.0e-10_wp .and. wt <= 1.0e-10_wp, 'verlet = the scene engine, ' // itoa(n) // &
                     ' contacts, every law and end, max rel e ' // fmt_short(we, 3) // ', tau_c ' // fmt_short(wt, 3))
        print '(a)', '  verlet vs the scene engine (' // itoa(n) // ' contacts): max rel e ' // fmt_short(we, 3) // &
            ', tau_c ' // fmt_short(wt, 3)
    end subroutine scene_engine_agrees

    !> Debian's LAMMPS (lmp, which `make lammps` installs), one run of eight head-on pairs
    !> (mass 1 each, relative speed 1, 10 apart): pair_style granular hertz with damping
    !> velocity (linear) or viscoelastic (kuwabara-kono, d = eta m_eff sqrt(R_eff)), with
    !> and without limit_damping (force end), fix nve/sphere; each pair's h set by its k,
    !> its phase by its gap.  The final relative speeds against hertzdamp_host_collide
    !> (lammps) at the same alpha, h and phase: within 1e-12.
    subroutine lammps_agrees()
        character(len=*), parameter :: dir = 'build/test_host_lammps'
        real(wp), parameter :: meff = 0.5_wp, reff = 0.5_wp, dt = 0.01_wp
        real(wp), parameter :: alphas(8) = [0.5_wp, 0.7_wp, 0.3_wp, 1.1_wp, 0.6_wp, 0.9_wp, 0.4_wp, 2.0_wp]
        real(wp), parameter :: hs(8) = [0.3_wp, 0.4_wp, 0.12_wp, 0.25_wp, 0.35_wp, 0.2_wp, 0.05_wp, 0.5_wp]
        real(wp), parameter :: phis(8) = [0.37_wp, 0.05_wp, 0.95_wp, 0.5_wp, 0.71_wp, 0.22_wp, 0.64_wp, 0.999_wp]
        real(wp) :: tstar, kn, d, eta, gap, e, tau, v(16), worst
        integer :: k, st, u, ios, n, law(8), iend(8)
        character(len=256) :: line
        call execute_command_line('command -v lmp >/dev/null 2>&1', exitstat=st)
        call s%check(st == 0, 'LAMMPS: lmp is installed (make lammps installs Debian''s lammps)')
        if (st /= 0) return
        call execute_command_line('mkdir -p ' // dir)
        open (newunit=u, file=dir // '/in.pairs', status='replace', action='write')
        write (u, '(a)') 'units si', 'atom_style sphere', 'atom_modify map array', 'boundary f f f', &
            'region box block -10 10 -10 90 -10 10', 'create_box 8 box', 'comm_modify vel yes', 'pair_style granular', &
            'pair_coeff * * hertz 1000 0 damping velocity tangential linear_nohistory 0 0'
        do k = 1, 8
            law(k) = merge(HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO, k <= 4)
            iend(k) = merge(HD_END_OVERLAP, HD_END_FORCE, mod(k, 2) == 1)
            tstar = dt / hs(k)
            kn = meff / (sqrt(reff) * tstar**2.5_wp)
            d = alphas(k) * meff / tstar / tstar**hertzdamp_law_q(law(k))
            eta = merge(d, d / (meff * sqrt(reff)), law(k) == HD_DAMPING_LINEAR)
            gap = (1.0_wp - phis(k)) * dt
            write (u, '(a,i0,a,es25.17,a,i0,a)') 'create_atoms ', k, ' single ', -(1.0_wp + 0.5_wp * gap), ' ', &
                10 * (k - 1), ' 0'
            write (u, '(a,i0,a,es25.17,a,i0,a)') 'create_atoms ', k, ' single ', 1.0_wp + 0.5_wp * gap, ' ', 10 * (k - 1), ' 0'
            write (u, '(a,i0,a,i0,2(a,es25.17),4a)') 'pair_coeff ', k, ' ', k, ' hertz ', kn, ' ', eta, ' damping ', &
                trim(merge('velocity    ', 'viscoelastic', law(k) == HD_DAMPING_LINEAR)), &
                ' tangential linear_nohistory 0 0', trim(merge('              ', ' limit_damping', iend(k) == HD_END_OVERLAP))
        end do
        write (u, '(a,es25.17)') 'set type * diameter 2.0 density ', 0.75_wp / pi
        write (u, '(a)') 'velocity all set 0 0 0'
        do k = 1, 8
            write (u, '(a,i0,a)') 'set atom ', 2 * k - 1, ' vx 0.5'
            write (u, '(a,i0,a)') 'set atom ', 2 * k, ' vx -0.5'
        end do
        write (u, '(a,es25.17)') 'timestep ', dt
        write (u, '(a)') 'neighbor 1.0 bin', 'fix 1 all nve/sphere', 'thermo_style custom step', 'run 900'
        do k = 1, 16
            write (u, '(a,i0,a,i0,a)') 'variable v', k, ' equal vx[', k, ']'
            write (u, '(a,i0,a,i0,a)') 'print "VX ', k, ' $(v_v', k, ':%.17g)"'
        end do
        close (u)
        call execute_command_line('cd ' // dir // ' && lmp -in in.pairs -log none -screen out.txt >/dev/null 2>&1', &
                                  exitstat=st)
        v = huge(1.0_wp)
        open (newunit=u, file=dir // '/out.txt', status='old', action='read', iostat=ios)
        if (ios == 0) then
            do
                read (u, '(a)', iostat=ios) line
                if (ios /= 0) exit
                if (index(line, 'VX ') == 1) then
                    read (line(4:), *, iostat=ios) k, e
                    if (ios == 0 .and. k >= 1 .and. k <= 16) v(k) = e
                end if
            end do
            close (u)
        end if
        call s%check(st == 0 .and. all(v < huge(1.0_wp)), 'LAMMPS run gives the final velocities of the 16 spheres')
        worst = 0.0_wp
        n = 0
        do k = 1, 8
            call hertzdamp_host_collide(alphas(k), hs(k), phis(k), law(k), iend(k), HD_HOST_LAMMPS, e, tau, st)
            if (st /= HD_OK .or. v(2 * k) == huge(1.0_wp)) cycle
            worst = max(worst, rel_err(e, v(2 * k) - v(2 * k - 1)))
            n = n + 1
        end do
        call s%check(n == 8 .and. worst <= 1.0e-12_wp, 'lammps = Debian''s LAMMPS, 8 pairs (linear, kuwabara-kono, '// &
                     'both ends), max rel e ' // fmt_short(worst, 3))
        print '(a)', '  lammps vs Debian''s LAMMPS (' // itoa(n) // ' pairs): max rel e ' // fmt_short(worst, 3)
    end subroutine lammps_agrees


    !> hertzdamp_host_mean against this program's quadrature: every scheme, law and end at
    !> 10 and 40 steps per contact (e = 0.3 and 0.8): means within 1e-12.
    subroutine means_agree()
        real(wp), parameter :: es(2) = [0.3_wp, 0.8_wp], ns(2) = [10.0_wp, 40.0_wp]
        real(wp) :: alpha, tau0, em, tm, we, wt
        type(hertzdamp_host_stats) :: st0
        integer :: ih, il, ie, k, st, nmiss, nm
        do ih = 1, size(hosts)
            we = 0.0_wp
            wt = 0.0_wp
            nm = 0
            do il = 1, 3
                do ie = 1, 2
                    do k = 1, 2
                        call hertzdamp_fit_inverse(es(k), ends(ie), alpha, tau0, st, laws(il))
                        call hertzdamp_host_mean(alpha, tau0 / ns(k), laws(il), ends(ie), hosts(ih), st0, st)
                        call own_mean(alpha, tau0 / ns(k), laws(il), ends(ie), hosts(ih), em, tm, nmiss)
                        call s%check(st == HD_OK, 'mean succeeds')
                        nm = nm + nmiss
                        we = max(we, abs(st0%e_mean - em))
                        wt = max(wt, abs(st0%tau_mean - tm) / tm)
                        call s%check(st0%e_min <= st0%e_mean .and. st0%e_mean <= st0%e_max .and. &
                                     st0%tau_min <= st0%tau_mean .and. st0%tau_mean <= st0%tau_max .and. &
                                     st0%e_sd <= 0.5_wp * (st0%e_max - st0%e_min) + 1.0e-15_wp .and. &
                                     st0%tau_sd <= 0.5_wp * (st0%tau_max - st0%tau_min) + 1.0e-15_wp, &
                                     'statistics ordered: min <= mean <= max, sd <= (max - min)/2')
                    end do
                end do
            end do
            call s%check(nm == 0 .and. we <= 1.0e-12_wp .and. wt <= 1.0e-12_wp, hertzdamp_host_name(hosts(ih)) // &
                         ': phase means = own quadrature, max e ' // fmt_short(we, 3) // ', rel tau_c ' // fmt_short(wt, 3))
            print '(a)', '  ' // hertzdamp_host_name(hosts(ih)) // ' phase means vs own quadrature (12 cases): max e ' // &
                fmt_short(we, 3) // ', rel tau_c ' // fmt_short(wt, 3)
        end do
    end subroutine means_agree

    ! ================================================================ per-pair constants

    !> The per-pair constants of every scheme, law and end for targets e in [0.1, 0.99]
    !> and N in [5, 1000]: the phase means at alpha and h = tau_c / N, by this program's
    !> quadrature, equal e and tau_c to 1e-10.  A target the solve calls unreachable must
    !> have hertzdamp_host_min_steps > N.
    subroutine solve_meets_targets()
        real(wp), parameter :: e_list(9) = [0.1_wp, 0.2_wp, 0.35_wp, 0.5_wp, 0.65_wp, 0.8_wp, 0.9_wp, 0.95_wp, 0.99_wp]
        real(wp), parameter :: n_list(10) = [5.0_wp, 7.0_wp, 10.0_wp, 13.5_wp, 20.0_wp, 35.0_wp, 60.0_wp, 100.0_wp, &
                                             250.0_wp, 1000.0_wp]
        real(wp), parameter :: e_corner(4) = [0.1_wp, 0.1_wp, 0.99_wp, 0.99_wp]
        real(wp), parameter :: n_corner(4) = [10.0_wp, 1000.0_wp, 5.0_wp, 1000.0_wp]
        real(wp) :: e, n, alpha, tau, em, tm, we, wt
        type(hertzdamp_host_stats) :: st0
        integer :: ih, il, ie, j, i, st, nmiss, nmin, st2, nok, nun
        we = 0.0_wp
        wt = 0.0_wp
        nok = 0
        nun = 0
        i = 0
        do ih = 1, size(hosts)
            do il = 1, 3
                do ie = 1, 2
                    do j = 1, 2
                        i = i + 1
                        e = e_list(mod(7 * i, 9) + 1)
                        n = n_list(mod(3 * i + j, 10) + 1)
                        if (n >= 1000.0_wp .and. hosts(ih) /= HD_HOST_LAMMPS) n = 250.0_wp
                        call hertzdamp_host_solve(e, laws(il), ends(ie), hosts(ih), n, alpha, tau, st0, st)
                        if (st == HD_HOST_UNREACHABLE) then
                            call hertzdamp_host_min_steps(e, laws(il), ends(ie), hosts(ih), nmin, st2)
                            call s%check(st2 /= HD_OK .or. real(nmin, wp) > n, 'unreachable means N < N_min: ' // &
                                         hertzdamp_host_name(hosts(ih)) // ' e = ' // fmt_short(e, 3) // ' N = ' // fmt_short(n, 3))
                            nun = nun + 1
                            cycle
                        end if
                        call s%check(st == HD_OK, 'solve succeeds or is unreachable')
                        if (st /= HD_OK) cycle
                        call own_mean(alpha, tau / n, laws(il), ends(ie), hosts(ih), em, tm, nmiss)
                        we = max(we, abs(em / e - 1.0_wp))
                        wt = max(wt, abs(tm / tau - 1.0_wp))
                        call s%check(nmiss == 0 .and. abs(em / e - 1.0_wp) <= 1.0e-10_wp .and. &
                                     abs(tm / tau - 1.0_wp) <= 1.0e-10_wp .and. abs(st0%e_mean / e - 1.0_wp) <= 1.0e-10_wp, &
                                     hertzdamp_host_name(hosts(ih)) // ' ' // hertzdamp_law_name(laws(il)) // ' ' // &
                                     hertzdamp_end_name(ends(ie)) // ' e = ' // fmt_short(e, 3) // ' N = ' // fmt_short(n, 3) // &
                                     ': own phase means = targets, rel ' // fmt_short(em / e - 1.0_wp, 3) // ', ' // &
                                     fmt_short(tm / tau - 1.0_wp, 3))
                        nok = nok + 1
                    end do
                end do
            end do
        end do
        ! the corners of the range (linear overlap, lammps)
        do j = 1, 4
            e = e_corner(j)
            n = n_corner(j)
            call hertzdamp_host_solve(e, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_LAMMPS, n, alpha, tau, st0, st)
            call own_mean(alpha, tau / n, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_LAMMPS, em, tm, nmiss)
            call s%check(st == HD_OK .and. nmiss == 0 .and. abs(em / e - 1.0_wp) <= 1.0e-10_wp .and. &
                         abs(tm / tau - 1.0_wp) <= 1.0e-10_wp, 'lammps corner e = ' // fmt_short(e, 3) // ', N = ' // &
                         fmt_short(n, 3))
            we = max(we, abs(em / e - 1.0_wp))
            wt = max(wt, abs(tm / tau - 1.0_wp))
            nok = nok + 1
        end do
        call s%check(nok >= 50, itoa(nok) // ' targets met, ' // itoa(nun) // ' unreachable; max rel e ' // fmt_short(we, 3) // &
                     ', tau_c ' // fmt_short(wt, 3))
        print '(a)', '  per-pair constants: ' // itoa(nok) // ' targets met (own quadrature), ' // itoa(nun) // &
            ' unreachable; max rel error of the mean e ' // fmt_short(we, 3) // ', tau_c ' // fmt_short(wt, 3)
        ! the issue's example: LAMMPS, e = 0.2, N = 10 (mean error -19 % with the continuous constants)
        call hertzdamp_host_solve(0.2_wp, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_LAMMPS, 10.0_wp, alpha, tau, st0, st)
        call s%check(st == HD_OK .and. st0%e_sd > 0.1_wp * 0.2_wp, 'lammps e = 0.2, N = 10 solves, spread above 10 %')
    end subroutine solve_meets_targets

    !> host none: exactly the fit's inverse (bits), zero spread.
    subroutine none_is_the_fit()
        real(wp) :: e, a0, t0, a, t
        type(hertzdamp_host_stats) :: st0
        integer :: il, ie, k, st1, st2
        logical :: same
        same = .true.
        do il = 1, 3
            do ie = 1, 2
                do k = 0, 20
                    e = 0.05_wp + 0.95_wp * k / 20.0_wp
                    call hertzdamp_fit_inverse(e, ends(ie), a0, t0, st1, laws(il))
                    call hertzdamp_host_solve(e, laws(il), ends(ie), HD_HOST_NONE, 7.0_wp, a, t, st0, st2)
                    same = same .and. st1 == st2 .and. transfer(a, 0_int64) == transfer(a0, 0_int64) .and. &
                           transfer(t, 0_int64) == transfer(t0, 0_int64) .and. st0%e_mean == e .and. st0%e_sd == 0.0_wp &
                           .and. st0%tau_sd == 0.0_wp .and. st0%tau_mean == t0
                end do
            end do
        end do
        call s%check(same, 'host none: alpha, tau_c bit-identical to hertzdamp_fit_inverse, zero spread')
    end subroutine none_is_the_fit

    !> (alpha_N, tau_N) -> (alpha(e), tau_c) at the scheme's order, measured from N = 100,
    !> 200, 400 (e = 0.5, linear law, both ends): 1 for lammps, mfix-euler, lammps-phase
    !> (the damping from the half-step velocity), 2 for mfix-ab2 and verlet.
    subroutine solve_order()
        real(wp) :: a0, t0, a(3), t(3), oa, ot, want
        type(hertzdamp_host_stats) :: st0
        integer :: ih, ie, k, st
        do ih = 1, size(hosts)
            do ie = 1, 2
                call hertzdamp_fit_inverse(0.5_wp, ends(ie), a0, t0, st)
                do k = 1, 3
                    call hertzdamp_host_solve(0.5_wp, HD_DAMPING_LINEAR, ends(ie), hosts(ih), 100.0_wp * 2**(k - 1), a(k), &
                                              t(k), st0, st)
                end do
                oa = log((a(2) - a0) / (a(3) - a0)) / log(2.0_wp)
                ot = log((t(2) - t0) / (t(3) - t0)) / log(2.0_wp)
                want = merge(2.0_wp, 1.0_wp, hosts(ih) == HD_HOST_MFIX_AB2 .or. hosts(ih) == HD_HOST_VERLET)
                call s%check(abs(oa - want) <= 0.15_wp .and. abs(ot - want) <= 0.15_wp, hertzdamp_host_name(hosts(ih)) // &
                             ' ' // hertzdamp_end_name(ends(ie)) // ': (alpha_N, tau_N) converge at order ' // &
                             fmt_short(want, 3) // &
                             ' (observed ' // fmt_short(oa, 3) // ', ' // fmt_short(ot, 3) // ')')
            end do
        end do
    end subroutine solve_order

    !> As h -> 0 the host's phase means tend to the continuous e and tau_c of the
    !> reference integrator: first order for the lammps family (observed 1 +- 0.15), at
    !> least second for mfix-ab2 and verlet (observed >= 1.7; tsuji's e in AB2 is not yet
    !> asymptotic there, 2.7) (h = tau_c/100, /200, /400; e = 0.5, every law, overlap end).
    subroutine mean_tends_to_continuous()
        real(wp) :: a0, t0, ce(3), ct(3), oe, ot, want
        type(hertzdamp_host_stats) :: st0
        type(hertzdamp_collision) :: ref
        integer :: ih, il, k, st
        logical :: ok
        do ih = 1, size(hosts)
            do il = 1, 3
                call hertzdamp_fit_inverse(0.5_wp, HD_END_OVERLAP, a0, t0, st, laws(il))
                ref = hertzdamp_rk45_collide(a0, HD_END_OVERLAP, law=laws(il))
                do k = 1, 3
                    call hertzdamp_host_mean(a0, ref%tau_c / (50.0_wp * 2**k), laws(il), HD_END_OVERLAP, hosts(ih), st0, st)
                    ce(k) = st0%e_mean - ref%e
                    ct(k) = st0%tau_mean - ref%tau_c
                end do
                oe = log(ce(2) / ce(3)) / log(2.0_wp)
                ot = log(ct(2) / ct(3)) / log(2.0_wp)
                want = merge(2.0_wp, 1.0_wp, hosts(ih) == HD_HOST_MFIX_AB2 .or. hosts(ih) == HD_HOST_VERLET)
                if (want > 1.0_wp) then
                    ok = oe >= 1.7_wp .and. ot >= 1.7_wp
                else
                    ok = abs(oe - 1.0_wp) <= 0.15_wp .and. abs(ot - 1.0_wp) <= 0.15_wp
                end if
                call s%check(ok .and. abs(ce(3)) < 1.0e-3_wp, &
                             hertzdamp_host_name(hosts(ih)) // ' ' // hertzdamp_law_name(laws(il)) // &
                             ': mean -> continuous as h -> 0 at order ' // fmt_short(want, 3) // ' (observed ' // &
                             fmt_short(oe, 3) // ', ' // &
                             fmt_short(ot, 3) // ')')
            end do
        end do
    end subroutine mean_tends_to_continuous

    !> N_min - 1 fails, N_min succeeds.
    subroutine min_steps()
        real(wp), parameter :: es(6) = [0.1_wp, 0.1_wp, 0.3_wp, 0.5_wp, 0.05_wp, 0.2_wp]
        integer, parameter :: ihs(6) = [HD_HOST_LAMMPS, HD_HOST_MFIX_AB2, HD_HOST_LAMMPS_PHASE, HD_HOST_LAMMPS, &
                                        HD_HOST_VERLET, HD_HOST_LAMMPS]
        integer, parameter :: ils(6) = [HD_DAMPING_LINEAR, HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO, HD_DAMPING_TSUJI, &
                                        HD_DAMPING_LINEAR, HD_DAMPING_TSUJI]
        real(wp) :: a, t
        type(hertzdamp_host_stats) :: st0
        integer :: k, nmin, st, st1, st2, ih, il
        real(wp) :: e
        do k = 1, 6
            e = es(k)
            ih = ihs(k)
            il = ils(k)
            call hertzdamp_host_min_steps(e, il, HD_END_OVERLAP, ih, nmin, st)
            call hertzdamp_host_solve(e, il, HD_END_OVERLAP, ih, real(nmin - 1, wp), a, t, st0, st1)
            call hertzdamp_host_solve(e, il, HD_END_OVERLAP, ih, real(nmin, wp), a, t, st0, st2)
            call s%check(st == HD_OK .and. nmin > 2 .and. st1 == HD_HOST_UNREACHABLE .and. st2 == HD_OK, &
                         'min_steps ' // hertzdamp_host_name(ih) // ' ' // hertzdamp_law_name(il) // ' e = ' // fmt_short(e, 3) // &
                         ': N_min = ' // itoa(nmin) // ' succeeds, N_min - 1 does not')
        end do
        call hertzdamp_host_min_steps(0.5_wp, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_NONE, nmin, st)
        call s%check(st == HD_OK .and. nmin == 2, 'min_steps, host none: 2')
        call hertzdamp_host_min_steps(0.9_wp, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_LAMMPS, nmin, st)
        call s%check(st == HD_OK .and. nmin == 2, 'min_steps, lammps e = 0.9: 2 steps already')
        call min_steps_true()
    end subroutine min_steps

    !> "N >= n can" is true (issue 30, defect 2): over a grid of e, laws, ends and schemes,
    !> the solve fails at min_steps - 1 and succeeds at every N from min_steps to min_steps + 8.
    subroutine min_steps_true()
        real(wp), parameter :: es(3) = [0.05_wp, 0.2_wp, 0.5_wp]
        integer, parameter :: ihs(4) = [HD_HOST_LAMMPS, HD_HOST_MFIX_AB2, HD_HOST_VERLET, HD_HOST_LAMMPS_PHASE]
        real(wp) :: a, t
        type(hertzdamp_host_stats) :: st0
        integer :: ie, il, iend, ih, nmin, st, n, nbad, ncases, sts
        nbad = 0
        ncases = 0
        do ie = 1, size(es)
            do il = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
                do iend = HD_END_OVERLAP, HD_END_FORCE
                    do ih = 1, size(ihs)
                        call hertzdamp_host_min_steps(es(ie), il, iend, ihs(ih), nmin, st)
                        if (st /= HD_OK) then
                            nbad = nbad + 1
                            cycle
                        end if
                        ncases = ncases + 1
                        if (nmin > 2) then
                            call hertzdamp_host_solve(es(ie), il, iend, ihs(ih), real(nmin - 1, wp), a, t, st0, sts)
                            if (sts == HD_OK) nbad = nbad + 1
                        end if
                        do n = nmin, nmin + 8
                            call hertzdamp_host_solve(es(ie), il, iend, ihs(ih), real(n, wp), a, t, st0, sts)
                            if (sts /= HD_OK) nbad = nbad + 1
                        end do
                    end do
                end do
            end do
        end do
        call s%check(nbad == 0 .and. ncases == 72, 'min_steps over e = 0.05, 0.2, 0.5, every law and end, ' // &
                     'lammps/mfix-ab2/verlet/lammps-phase (72 cases): N_min - 1 fails, N_min .. N_min + 8 succeed')
    end subroutine min_steps_true

    !> Targets reachable at N are found at N (issue 30, defects 2 and 6): lammps-phase, force
    !> end, e = 0.02 at N = 6 .. 12 (Newton from the continuous constants stalled at 8, 9, 10;
    !> the old message claimed N >= 6); mfix-ab2, tsuji, force end, e = 0.001 at N = 2, 5 .. 8,
    !> 11 (6, 7 and 11 failed); mfix-ab2, linear, force end, e = 0.00533484 at N = 2 .. 8 (4
    !> and 5 failed); each solution's phase means checked by this program's own stepper and
    !> quadrature (own_mean); and the fewest N of the first case is 6.
    subroutine reachable_found()
        real(wp) :: a, t, em, tm
        type(hertzdamp_host_stats) :: st0
        integer :: n, st, nmiss, nbad, nm
        nbad = 0
        do n = 6, 12
            call hertzdamp_host_solve(0.02_wp, HD_DAMPING_LINEAR, HD_END_FORCE, HD_HOST_LAMMPS_PHASE, real(n, wp), a, t, &
                                      st0, st)
            if (st /= HD_OK) then
                nbad = nbad + 1
                cycle
            end if
            call own_mean(a, t / n, HD_DAMPING_LINEAR, HD_END_FORCE, HD_HOST_LAMMPS_PHASE, em, tm, nmiss)
            if (abs(em / 0.02_wp - 1.0_wp) > 1.0e-8_wp .or. abs(tm / t - 1.0_wp) > 1.0e-8_wp .or. nmiss /= 0) then
                nbad = nbad + 1
            end if
        end do
        call s%check(nbad == 0, 'lammps-phase, force end, e = 0.02, N = 6 .. 12: every N solved, its means (own ' // &
                     'stepper) e and tau_c = N h to 1e-8')
        call hertzdamp_host_min_steps(0.02_wp, HD_DAMPING_LINEAR, HD_END_FORCE, HD_HOST_LAMMPS_PHASE, nm, st)
        call s%check(st == HD_OK .and. nm == 6, 'lammps-phase, force end, e = 0.02: min_steps = 6 (got ' // itoa(nm) // ')')
        nbad = 0
        do n = 2, 11
            if (n == 3 .or. n == 4 .or. n == 9 .or. n == 10) cycle
            call hertzdamp_host_solve(0.001_wp, HD_DAMPING_TSUJI, HD_END_FORCE, HD_HOST_MFIX_AB2, real(n, wp), a, t, st0, st)
            if (st /= HD_OK) then
                nbad = nbad + 1
                cycle
            end if
            call own_mean(a, t / n, HD_DAMPING_TSUJI, HD_END_FORCE, HD_HOST_MFIX_AB2, em, tm, nmiss)
            if (abs(em / 0.001_wp - 1.0_wp) > 1.0e-8_wp .or. abs(tm / t - 1.0_wp) > 1.0e-8_wp .or. nmiss /= 0) then
                nbad = nbad + 1
            end if
        end do
        call s%check(nbad == 0, 'mfix-ab2, tsuji, force end, e = 0.001, N = 2, 5, 6, 7, 8, 11: every N solved, its ' // &
                     'means (own stepper) e and tau_c = N h to 1e-8')
        ! the adversarial round's residue: N = 4 and 5 were refused ("N >= 2 can") while 2, 3
        ! and 6 .. 8 were solved; the means there are steep (tau_mean / (N h) from 3 to 0.4 over
        ! 1e-4 of h), and the solve now continues from the solution at N +- 1.  The means are
        ! checked by a midpoint rule on 1e5 cells split at the breakpoints, with this program's
        ! stepper (own_mean's adaptive pieces miss 1 % of e at N = 4 here; a plain midpoint rule
        ! over 1e6 phases agrees with the library to 4e-14 in e there)
        nbad = 0
        do n = 2, 8
            call hertzdamp_host_solve(0.00533484_wp, HD_DAMPING_LINEAR, HD_END_FORCE, HD_HOST_MFIX_AB2, real(n, wp), a, &
                                      t, st0, st)
            if (st /= HD_OK) then
                nbad = nbad + 1
                cycle
            end if
            call midpoint_mean(a, t / n, HD_DAMPING_LINEAR, HD_END_FORCE, HD_HOST_MFIX_AB2, 100000, em, tm)
            if (abs(em / 0.00533484_wp - 1.0_wp) > 1.0e-8_wp .or. abs(tm / t - 1.0_wp) > 1.0e-8_wp) nbad = nbad + 1
        end do
        call s%check(nbad == 0, 'mfix-ab2, linear, force end, e = 0.00533484, N = 2 .. 8: every N solved, its means ' // &
                     '(own stepper, midpoint rule) e and tau_c = N h to 1e-8 (' // itoa(nbad) // ' not)')
    end subroutine reachable_found

    !> Targets reachable at two and three steps are found there (issue 30, defect 2 residue):
    !> lammps and mfix-euler, linear, force end, e = 0.001 and 0.002 at N = 2, 3, e = 0.005
    !> and 0.01 at N = 2 (refused before, "N >= 4 can" for e = 0.001; the solutions lie in
    !> the thin layer at alpha h = 1 where the damping stops the body in one step and the
    !> contact time falls steeply with alpha); each solution's phase means checked by this
    !> program's stepper and midpoint rule split at the breakpoints (midpoint_mean) to 1e-8;
    !> and the fewest N of e = 0.001 with lammps is 2, N = 2 .. 10 solved.
    subroutine few_steps_found()
        real(wp), parameter :: es(6) = [0.001_wp, 0.001_wp, 0.002_wp, 0.002_wp, 0.005_wp, 0.01_wp]
        integer, parameter :: ns(6) = [2, 3, 2, 3, 2, 2]
        integer, parameter :: ihs(2) = [HD_HOST_LAMMPS, HD_HOST_MFIX_EULER]
        real(wp) :: a, t, em, tm
        type(hertzdamp_host_stats) :: st0
        integer :: k, ih, st, nbad, nm, n, stm
        nbad = 0
        do ih = 1, size(ihs)
            do k = 1, size(es)
                call hertzdamp_host_solve(es(k), HD_DAMPING_LINEAR, HD_END_FORCE, ihs(ih), real(ns(k), wp), a, t, st0, st)
                if (st /= HD_OK) then
                    nbad = nbad + 1
                    cycle
                end if
                call midpoint_mean(a, t / ns(k), HD_DAMPING_LINEAR, HD_END_FORCE, ihs(ih), 100000, em, tm)
                if (abs(em / es(k) - 1.0_wp) > 1.0e-8_wp .or. abs(tm / t - 1.0_wp) > 1.0e-8_wp) nbad = nbad + 1
            end do
        end do
        call s%check(nbad == 0, 'lammps, mfix-euler, linear, force end, e = 0.001, 0.002 at N = 2, 3, e = 0.005, ' // &
                     '0.01 at N = 2: every N solved, its means (own stepper, midpoint rule) e and tau_c = N h to 1e-8 (' // &
                     itoa(nbad) // ' not)')
        ! in the thin layer where the release moves and both means jump together: e_mean
        ! rises with alpha across it, tau_mean falls (issue 30, defect 2, the last case); 4e6
        ! cells: phase intervals of another signature narrower than 1e-5, which cells' ends
        ! of the same signature do not reveal (1e5 cells: tau_c off by 2e-6, 1e6: 5e-9, 4e6: 9e-10)
        call hertzdamp_host_solve(0.02_wp, HD_DAMPING_KUWABARA_KONO, HD_END_FORCE, HD_HOST_MFIX_AB2, 2.0_wp, a, t, st0, st)
        em = 0.0_wp
        tm = 0.0_wp
        if (st == HD_OK) call midpoint_mean(a, t / 2.0_wp, HD_DAMPING_KUWABARA_KONO, HD_END_FORCE, HD_HOST_MFIX_AB2, &
                                            4000000, em, tm)
        call s%check(st == HD_OK .and. abs(em / 0.02_wp - 1.0_wp) <= 1.0e-8_wp .and. abs(tm / t - 1.0_wp) <= 1.0e-8_wp, &
                     'mfix-ab2, kuwabara-kono, force end, e = 0.02, N = 2: solved (status ' // itoa(st) // &
                     '), its means (own stepper, midpoint rule) e and tau_c = N h to 1e-8 (' // &
                     fmt_short(em / 0.02_wp - 1.0_wp, 3) // ', ' // fmt_short(tm / t - 1.0_wp, 3) // ')')
        ! the N_min that moved in tools/min_steps_cases.sh's 93 targets beside a83a7ea (3 -> 2,
        ! 3 -> 2, 2 -> 2 for mfix-euler, 4 -> 3): each solve at the new N checked by this program
        nbad = 0
        call moved_case(0.295804_wp, HD_DAMPING_LINEAR, HD_HOST_MFIX_AB2, 2, nbad)
        call moved_case(0.242146_wp, HD_DAMPING_LINEAR, HD_HOST_MFIX_AB2, 2, nbad)
        call moved_case(0.2_wp, HD_DAMPING_LINEAR, HD_HOST_MFIX_AB2, 2, nbad)
        call moved_case(0.00147927_wp, HD_DAMPING_LINEAR, HD_HOST_MFIX_EULER, 2, nbad)
        call moved_case(0.00226519_wp, HD_DAMPING_KUWABARA_KONO, HD_HOST_MFIX_AB2, 3, nbad)
        call s%check(nbad == 0, 'force end, mfix-ab2 linear e = 0.296, 0.242, 0.2 and mfix-euler linear e = ' // &
                     '0.00148 at N = 2, mfix-ab2 kuwabara-kono e = 0.00227 at N = 3: solved, its means (own stepper, ' // &
                     'midpoint rule, 1e6 cells) e and tau_c = N h to 1e-8 (' // itoa(nbad) // ' not)')
        call hertzdamp_host_min_steps(0.001_wp, HD_DAMPING_LINEAR, HD_END_FORCE, HD_HOST_LAMMPS, nm, stm)
        nbad = 0
        do n = 2, 10
            call hertzdamp_host_solve(0.001_wp, HD_DAMPING_LINEAR, HD_END_FORCE, HD_HOST_LAMMPS, real(n, wp), a, t, st0, st)
            if (st /= HD_OK) nbad = nbad + 1
        end do
        call s%check(stm == HD_OK .and. nm == 2 .and. nbad == 0, 'lammps, linear, force end, e = 0.001: min_steps = 2 ' // &
                     '(got ' // itoa(nm) // '), N = 2 .. 10 solved (' // itoa(nbad) // ' not)')
    end subroutine few_steps_found

    !> nbad + 1 unless the force-end solve of (ee, law, host) at nn succeeds and this
    !> program's midpoint means (1e6 cells) agree with it to 1e-8.
    subroutine moved_case(ee, law, host, nn, nbad)
        real(wp), intent(in) :: ee
        integer, intent(in) :: law, host, nn
        integer, intent(inout) :: nbad
        real(wp) :: a, t, em, tm
        type(hertzdamp_host_stats) :: st0
        integer :: st
        call hertzdamp_host_solve(ee, law, HD_END_FORCE, host, real(nn, wp), a, t, st0, st)
        if (st /= HD_OK) then
            nbad = nbad + 1
            return
        end if
        call midpoint_mean(a, t / nn, law, HD_END_FORCE, host, 1000000, em, tm)
        if (abs(em / ee - 1.0_wp) > 1.0e-8_wp .or. abs(tm / t - 1.0_wp) > 1.0e-8_wp) nbad = nbad + 1
    end subroutine moved_case

    !> The phase means of e and tau_c by the midpoint rule on m cells of the phase, with this
    !> program's stepper (collide): a cell whose ends differ in signature is split at the
    !> breakpoint between them (bisection to adjacent doubles) and each part takes its own
    !> midpoint, so that the jumps of e and tau_c cost no O(1/m) error.
    subroutine midpoint_mean(alpha, h, law, iend, host, m, em, tm)
        real(wp), intent(in) :: alpha, h
        integer, intent(in) :: law, iend, host, m
        real(wp), intent(out) :: em, tm
        type(coll_t) :: cl, cr, c
        real(wp) :: xl, xr, lo, hi, mid
        integer :: j
        em = 0.0_wp
        tm = 0.0_wp
        xl = 1.0e-300_wp
        cl = collide(alpha, h, xl, law, iend, host)
        do j = 1, m
            xr = real(j, wp) / real(m, wp)
            cr = collide(alpha, h, xr, law, iend, host)
            if (all(cl%sig == cr%sig)) then
                call add_cell(alpha, h, law, iend, host, xl, xr, em, tm)
            else
                lo = xl
                hi = xr
                do
                    mid = 0.5_wp * (lo + hi)
                    if (mid == lo .or. mid == hi) exit
                    c = collide(alpha, h, mid, law, iend, host)
                    if (all(c%sig == cl%sig)) then
                        lo = mid
                    else
                        hi = mid
                    end if
                end do
                call add_cell(alpha, h, law, iend, host, xl, lo, em, tm)
                call add_cell(alpha, h, law, iend, host, hi, xr, em, tm)
            end if
            xl = xr
            cl = cr
        end do
    end subroutine midpoint_mean

    !> Add the midpoint rule's e and tau_c of the cell (a, b) to em and tm.
    subroutine add_cell(alpha, h, law, iend, host, a, b, em, tm)
        real(wp), intent(in) :: alpha, h, a, b
        integer, intent(in) :: law, iend, host
        real(wp), intent(inout) :: em, tm
        type(coll_t) :: c
        c = collide(alpha, h, 0.5_wp * (a + b), law, iend, host)
        em = em + (b - a) * c%e
        tm = tm + (b - a) * c%tau
    end subroutine add_cell

    !> At a fixed h, the alpha whose phase-mean e is the target (the deck checker's
    !> corrected coefficient), checked by this program's quadrature; host none: alpha(e).
    subroutine alpha_for_e()
        real(wp) :: a0, t0, a, em, tm
        type(hertzdamp_host_stats) :: st0
        integer :: ih, st, nmiss
        do ih = 1, size(hosts)
            call hertzdamp_fit_inverse(0.6_wp, HD_END_FORCE, a0, t0, st, HD_DAMPING_TSUJI)
            call hertzdamp_host_alpha_for_e(0.6_wp, t0 / 11.0_wp, HD_DAMPING_TSUJI, HD_END_FORCE, hosts(ih), a, st0, st)
            call own_mean(a, t0 / 11.0_wp, HD_DAMPING_TSUJI, HD_END_FORCE, hosts(ih), em, tm, nmiss)
            call s%check(st == HD_OK .and. nmiss == 0 .and. abs(em / 0.6_wp - 1.0_wp) <= 1.0e-10_wp .and. &
                         abs(st0%e_mean / 0.6_wp - 1.0_wp) <= 1.0e-10_wp, 'alpha_for_e ' // hertzdamp_host_name(hosts(ih)) // &
                         ', tsuji force, h = tau_c/11: own mean e = 0.6, rel ' // fmt_short(em / 0.6_wp - 1.0_wp, 3))
        end do
        call hertzdamp_host_alpha_for_e(0.6_wp, 0.3_wp, HD_DAMPING_TSUJI, HD_END_FORCE, HD_HOST_NONE, a, st0, st)
        call s%check(st == HD_OK .and. a == a0, 'alpha_for_e, host none: the fit''s alpha(e)')
        call hertzdamp_host_alpha_for_e(0.1_wp, 1.2_wp, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_LAMMPS, a, st0, st)
        call s%check(st == HD_HOST_UNREACHABLE .and. a == 0.0_wp, 'alpha_for_e: e = 0.1 at h = 1.2 is unreachable')
    end subroutine alpha_for_e

    ! ================================================================ bad input

    subroutine bad_input()
        real(wp) :: e, tau, a, t, x, f
        type(hertzdamp_host_stats) :: st0
        type(hertzdamp_collision) :: ref
        integer :: st, nmin
        x = 0.0_wp
        ! collide: host, law, end, alpha, h, phi (in this order)
        call hertzdamp_host_collide(0.3_wp, 0.1_wp, 0.5_wp, 0, 0, hertzdamp_max_host + 1, e, tau, st)
        call s%check(st == HD_BAD_HOST .and. e == 0.0_wp .and. tau == 0.0_wp, 'collide: bad host')
        call hertzdamp_host_collide(0.3_wp, 0.1_wp, 0.5_wp, 3, 0, 1, e, tau, st)
        call s%check(st == HD_BAD_LAW, 'collide: bad law')
        call hertzdamp_host_collide(0.3_wp, 0.1_wp, 0.5_wp, 0, 2, 1, e, tau, st)
        call s%check(st == HD_BAD_END, 'collide: bad end')
        call hertzdamp_host_collide(-0.3_wp, 0.1_wp, 0.5_wp, 0, 0, 1, e, tau, st)
        call s%check(st == HD_BAD_ALPHA, 'collide: negative alpha')
        call hertzdamp_host_collide(x / x, 0.1_wp, 0.5_wp, 0, 0, 1, e, tau, st)
        call s%check(st == HD_BAD_ALPHA .and. e == 0.0_wp, 'collide: NaN alpha')
        call hertzdamp_host_collide(0.3_wp, 5.0_wp, 0.5_wp, 0, 0, 1, e, tau, st)
        call s%check(st == HD_BAD_STEPS, 'collide: h too large')
        call hertzdamp_host_collide(0.3_wp, 1.0e-7_wp, 0.5_wp, 0, 0, 1, e, tau, st)
        call s%check(st == HD_BAD_STEPS, 'collide: h too small')
        call hertzdamp_host_collide(0.3_wp, 1.0_wp / x, 0.5_wp, 0, 0, 1, e, tau, st)
        call s%check(st == HD_BAD_STEPS, 'collide: h infinite')
        call hertzdamp_host_collide(0.3_wp, 0.1_wp, 0.0_wp, 0, 0, 1, e, tau, st)
        call s%check(st == HD_BAD_ARGUMENT, 'collide: phi = 0')
        call hertzdamp_host_collide(0.3_wp, 0.1_wp, 1.5_wp, 0, 0, 1, e, tau, st)
        call s%check(st == HD_BAD_ARGUMENT, 'collide: phi > 1')
        call hertzdamp_host_collide(0.3_wp, 0.1_wp, x / x, 0, 0, 1, e, tau, st)
        call s%check(st == HD_BAD_ARGUMENT, 'collide: phi NaN')
        call hertzdamp_host_collide(1.2_wp, 0.05_wp, 0.5_wp, 0, 0, 1, e, tau, st)
        call s%check(st == HD_NO_REBOUND .and. e == 0.0_wp .and. tau == 0.0_wp, 'collide: alpha > alpha_c, no rebound')
        call hertzdamp_host_collide(0.3_wp, 0.1_wp, 0.5_wp, 0, 0, HD_HOST_NONE, e, tau, st)
        ref = hertzdamp_rk45_collide(0.3_wp)
        call s%check(st == HD_OK .and. abs(e - ref%e) <= 1.0e-13_wp, 'collide, host none: the continuous e')
        ! host none checks the arguments it does not use
        call hertzdamp_host_collide(0.3_wp, 0.1_wp, 0.0_wp, 0, 0, HD_HOST_NONE, e, tau, st)
        call s%check(st == HD_BAD_ARGUMENT, 'collide, host none: phi = 0 still refused')
        call hertzdamp_host_mean(0.3_wp, x / x, 0, 0, HD_HOST_NONE, st0, st)
        call s%check(st == HD_BAD_STEPS, 'mean, host none: NaN h still refused')
        call hertzdamp_host_solve(0.5_wp, 0, 0, HD_HOST_NONE, 1.0_wp, a, t, st0, st)
        call s%check(st == HD_BAD_STEPS .and. a == 0.0_wp, 'solve, host none: N = 1 still refused')
        ! mean
        call hertzdamp_host_mean(0.3_wp, 0.1_wp, 0, 0, -1, st0, st)
        call s%check(st == HD_BAD_HOST .and. st0%e_mean == 0.0_wp, 'mean: bad host')
        call hertzdamp_host_mean(0.3_wp, 0.1_wp, -1, 0, 1, st0, st)
        call s%check(st == HD_BAD_LAW, 'mean: bad law')
        call hertzdamp_host_mean(0.3_wp, 0.1_wp, 0, -1, 1, st0, st)
        call s%check(st == HD_BAD_END, 'mean: bad end')
        call hertzdamp_host_mean(2.0e4_wp, 0.1_wp, 0, 0, 1, st0, st)
        call s%check(st == HD_BAD_ALPHA, 'mean: alpha too large')
        call hertzdamp_host_mean(0.3_wp, -0.1_wp, 0, 0, 1, st0, st)
        call s%check(st == HD_BAD_STEPS, 'mean: negative h')
        call hertzdamp_host_mean(1.2_wp, 0.05_wp, 0, 0, 1, st0, st)
        call s%check(st == HD_NO_REBOUND .and. st0%e_mean == 0.0_wp, 'mean: no rebound')
        ! solve: host, law, end, e, steps
        call hertzdamp_host_solve(0.5_wp, 0, 0, 9, 10.0_wp, a, t, st0, st)
        call s%check(st == HD_BAD_HOST .and. a == 0.0_wp .and. t == 0.0_wp, 'solve: bad host')
        call hertzdamp_host_solve(0.5_wp, 5, 0, 1, 10.0_wp, a, t, st0, st)
        call s%check(st == HD_BAD_LAW, 'solve: bad law')
        call hertzdamp_host_solve(0.5_wp, 0, 3, 1, 10.0_wp, a, t, st0, st)
        call s%check(st == HD_BAD_END, 'solve: bad end')
        call hertzdamp_host_solve(1.5_wp, 0, 0, 1, 10.0_wp, a, t, st0, st)
        call s%check(st == HD_BAD_RESTITUTION .and. a == 0.0_wp, 'solve: e > 1')
        call hertzdamp_host_solve(1.0e-5_wp, 0, 0, 1, 10.0_wp, a, t, st0, st)
        call s%check(st == HD_BAD_RESTITUTION, 'solve: e below the fit''s range')
        call hertzdamp_host_solve(x / x, 0, 0, 1, 10.0_wp, a, t, st0, st)
        call s%check(st == HD_BAD_RESTITUTION, 'solve: e NaN')
        call hertzdamp_host_solve(0.5_wp, 0, 0, 1, 1.5_wp, a, t, st0, st)
        call s%check(st == HD_BAD_STEPS .and. a == 0.0_wp .and. t == 0.0_wp, 'solve: N < 2')
        call hertzdamp_host_solve(0.5_wp, 0, 0, 1, 2.0e5_wp, a, t, st0, st)
        call s%check(st == HD_BAD_STEPS, 'solve: N > 1e5')
        call hertzdamp_host_solve(0.5_wp, 0, 0, 1, x / x, a, t, st0, st)
        call s%check(st == HD_BAD_STEPS, 'solve: N NaN')
        call hertzdamp_host_solve(0.1_wp, 0, 0, 1, 3.0_wp, a, t, st0, st)
        call s%check(st == HD_HOST_UNREACHABLE .and. a == 0.0_wp .and. t == 0.0_wp, 'solve: e = 0.1 at N = 3 unreachable')
        ! min_steps, alpha_for_e
        call hertzdamp_host_min_steps(0.5_wp, 0, 0, 7, nmin, st)
        call s%check(st == HD_BAD_HOST .and. nmin == 0, 'min_steps: bad host')
        call hertzdamp_host_min_steps(2.0_wp, 0, 0, 1, nmin, st)
        call s%check(st == HD_BAD_RESTITUTION .and. nmin == 0, 'min_steps: bad e')
        call hertzdamp_host_alpha_for_e(0.5_wp, 0.1_wp, 0, 0, 8, a, st0, st)
        call s%check(st == HD_BAD_HOST, 'alpha_for_e: bad host')
        call hertzdamp_host_alpha_for_e(0.5_wp, 9.0_wp, 0, 0, 1, a, st0, st)
        call s%check(st == HD_BAD_STEPS .and. a == 0.0_wp, 'alpha_for_e: bad h')
        call hertzdamp_host_alpha_for_e(-0.5_wp, 0.1_wp, 0, 0, 1, a, st0, st)
        call s%check(st == HD_BAD_RESTITUTION, 'alpha_for_e: bad e')
        f = hertzdamp_host_phase_force(1.0_wp, 1.0_wp, 1.0_wp, 0.5_wp, -1)
        call s%check(f == 0.0_wp, 'phase force: bad law gives 0')
    end subroutine bad_input

end program test_host
