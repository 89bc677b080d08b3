!> Per-contact constants from the onset phase (issue 32): hertzdamp_pair_init with
!> phase = .true., hertzdamp_pair_kd_phase, hertzdamp_onset_phase, hertzdamp_phase_min_steps
!> and their C and legacy forms.
!>
!> - every contact exact: for lammps, mfix-euler and mfix-ab2, every law and both contact
!>   ends, e from 0.1 to 0.99 and N from 10 to 1000 (a representative set of (e, N) per
!>   law and end, one non-whole N), at 256 stratified onset phases plus 1e-5, 1e-3, 0.2,
!>   1 - 1e-5 and the issue's phase 0.016: k and d of hertzdamp_pair_kd_phase for a contact in SI units,
!>   reduced to (alpha, h) by the definitions here, run by this program's own steppers
!>   (LAMMPS's velocity Verlet with two half kicks, MFiX's EULER and ADAMS_BASHFORTH as
!>   cfnewvalues.f writes them; no code shared with the library): e within 1e-5 (relative)
!>   of the target and T_c within 1e-5 of N dt (issue 32 asks 1e-4 and 1e-3);
!> - a target some phase cannot reach (or whose table fails the init's check) gives
!>   HD_PHASE_UNREACHABLE, with hertzdamp_phase_min_steps above N (every target of the grid
!>   is served); the fewest N itself: init fails at N_min - 1;
!> - the ties (issue 32): at and near the phase where the release lands on a step boundary
!>   (phi = 1 for a whole N, phi_b = N - floor(N) otherwise: exactly, and 1e-15 to 3e-5 off
!>   on both sides) and at the ends 1e-15 and 1 - 1e-15: every contact within 1e-5 of e and
!>   of N dt (before the fix phi = 1 missed e by 13 % at e = 0.5, N = 10, mfix-euler);
!> - the mean-exact constants give a spread of e over the phase at least 100 times the
!>   phase form's (the regression of issue 32: 5.5 % at e = 0.5, N = 10);
!> - k and d against the closed forms with ** (k = m r^(5/2) u^(-1/2), d = alpha m r
!>   (r/u)^q, r = tau(phi)/T_c); the bound (k_phys <= k): k = k_phys and d from alpha_eff
!>   computed here; continuous at k_phys = k;
!> - the table is an addition: hertzdamp_pair_kd gives the same bits with or without it;
!> - statuses: no table, bad phase, a changed table, bad arguments; onset_phase's rules;
!> - the C functions and the legacy externals (through their binding labels) give the
!>   module's bits (pairs, k, d, phi, N_min).
program test_phase
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_PHASE_UNREACHABLE, HD_BAD_PHASE, HD_NO_PHASE_TABLE, HD_BAD_PAIR, &
                         HD_BAD_TIME, HD_BAD_VELOCITY, HD_BAD_MASS, HD_BAD_KPHYS, HD_END_OVERLAP, HD_END_FORCE, &
                         HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO, HD_HOST_NONE, HD_HOST_LAMMPS, &
                         HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2, hertzdamp_law_q, hertzdamp_host_name, &
                         hertzdamp_law_name, hertzdamp_pair_t, hertzdamp_pair_init, hertzdamp_pair_kd, &
                         hertzdamp_pair_kd_phase, hertzdamp_pair_phase_constants, hertzdamp_onset_phase, &
                         hertzdamp_phase_min_steps, hertzdamp_pair_size, hertzdamp_host_order, hertzdamp_pair_phase_status
    use hertzdamp_capi, only: hertzdamp_c_pair_init_phase, hertzdamp_c_pair_kd_phase, hertzdamp_c_onset_phase, &
                              hertzdamp_c_phase_min_steps
    use hertzdamp_testing, only: test_suite, new_suite
    use hertzdamp_text_format, only: itoa, fmt_short
    use, intrinsic :: iso_c_binding, only: c_double, c_int
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, ieee_negative_inf
    use hertzdamp_phase, only: hertzdamp_phase_header
    implicit none

    interface
        ! as a fixed-form caller declares them (include/hertzdamp.fi)
        subroutine legacy_init_phase(e, ilaw, iend, ihost, steps, pair, ierr) bind(c, name='hertzdamp_pair_init_phase_')
            import :: c_double, c_int
            implicit none
            real(c_double), intent(in) :: e, steps
            integer(c_int), intent(in) :: ilaw, iend, ihost
            real(c_double), intent(out) :: pair(256)
            integer(c_int), intent(out) :: ierr
        end subroutine legacy_init_phase
        subroutine legacy_kd_phase(pair, tc, m, u, kphys, phi, k, d, ierr) bind(c, name='hertzdamp_pair_kd_phase_')
            import :: c_double, c_int
            implicit none
            real(c_double), intent(in) :: pair(256), tc, m, u, kphys, phi
            real(c_double), intent(out) :: k, d
            integer(c_int), intent(out) :: ierr
        end subroutine legacy_kd_phase
        subroutine legacy_onset_phase(delta1, u, dt, phi, ierr) bind(c, name='hertzdamp_onset_phase_')
            import :: c_double, c_int
            implicit none
            real(c_double), intent(in) :: delta1, u, dt
            real(c_double), intent(out) :: phi
            integer(c_int), intent(out) :: ierr
        end subroutine legacy_onset_phase
        subroutine legacy_min_steps(e, ilaw, iend, ihost, nmin, ierr) bind(c, name='hertzdamp_phase_min_steps_')
            import :: c_double, c_int
            implicit none
            real(c_double), intent(in) :: e
            integer(c_int), intent(in) :: ilaw, iend, ihost
            integer(c_int), intent(out) :: nmin, ierr
        end subroutine legacy_min_steps
    end interface

    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: n_phase = 256
    !> (e, N) per law and end: e 0.1 .. 0.99, N 10 .. 1000, one non-whole N
    integer, parameter :: n_case = 6
    real(wp), parameter :: case_e(n_case) = [0.1_wp, 0.2_wp, 0.5_wp, 0.5_wp, 0.9_wp, 0.99_wp]
    real(wp), parameter :: case_n(n_case) = [10.0_wp, 10.0_wp, 20.0_wp, 12.5_wp, 100.0_wp, 1000.0_wp]
    !> a contact in SI units: effective mass, impact speed, time step
    real(wp), parameter :: mass = 2.0e-3_wp, speed = 1.3_wp, dt = 1.0e-6_wp
    type(test_suite) :: suite

    suite = new_suite('test_phase')
    call check_every_contact()
    call check_scatter_regression()
    call check_ties()
    call check_formulas_and_bound()
    call check_statuses()
    call check_onset_phase()
    call check_min_steps()
    call check_bindings()
    call suite%finish()

contains

    ! ================================================================ this test's own steppers

    !> z^q by ** (q = 0, 1/4, 1/2).
    pure real(wp) function zpow(z, q)
        real(wp), intent(in) :: z, q
        zpow = 1.0_wp
        if (q > 0.0_wp) zpow = z**q
    end function zpow

    !> One head-on contact in similarity variables (impact speed 1, overlap z, approach
    !> positive), the step before the first overlap at z = (phi - 1) h: achieved e (the
    !> final separation speed) and tau (touch to release: the overlap end linear in the
    !> overlap, the force end linear in the unclipped total force between the last step with
    !> a positive force and the first without, or the overlap zero when that comes first).
    !> host lammps: LAMMPS's velocity Verlet (v += h/2 a; z += h v; a(z, v); v += h/2 a);
    !> mfix-euler: a from (z, v) at the step's start, v += h a, z += h v; mfix-ab2:
    !> v_new = v + h (3 a - a_old)/2, z += h (v + v_new)/2, a_old = a (a_old = 0 before).
    pure subroutine own_collide(alpha, h, phi, q, iend, host, e, tau, ok)
        real(wp), intent(in) :: alpha, h, phi, q
        integer, intent(in) :: iend, host
        real(wp), intent(out) :: e, tau
        logical, intent(out) :: ok
        real(wp) :: z, v, a, aold, f, zl, fl, t, trel, vn
        logical :: released, clipped
        integer :: n
        z = (phi - 1.0_wp) * h
        v = 1.0_wp
        a = 0.0_wp
        aold = 0.0_wp
        t = 0.0_wp
        zl = 0.0_wp
        fl = 0.0_wp
        trel = 0.0_wp
        released = .false.
        clipped = .false.
        ok = .false.
        e = 0.0_wp
        tau = 0.0_wp
        do n = 0, 2000000
            ! advance one step from the state at time t (n = 0: free flight into contact)
            select case (host)
            case (HD_HOST_LAMMPS)
                v = v + 0.5_wp * h * a
                z = z + h * v
            case (HD_HOST_MFIX_EULER)
                v = v + h * a
                z = z + h * v
            case default
                vn = v + 0.5_wp * h * (3.0_wp * a - aold)
                z = z + 0.5_wp * h * (v + vn)
                v = vn
                aold = a
            end select
            t = t + h
            ! the force of the new state (LAMMPS: from z and the half-step v)
            a = 0.0_wp
            if (z > 0.0_wp) then
                f = z**1.5_wp + alpha * zpow(z, q) * v
                if (iend == HD_END_FORCE .and. .not. (f > 0.0_wp)) then
                    if (.not. released) trel = t - h + h * fl / (fl - f)
                    released = .true.
                    clipped = .true.
                else if (.not. released) then
                    a = -f
                    zl = z
                    fl = f
                else if (iend == HD_END_FORCE .and. f > 0.0_wp) then
                    a = -f      ! a clipped force that becomes positive again acts again
                end if
            else if (n > 0 .and. .not. released) then
                trel = t - h + h * zl / (zl - z)
                released = .true.
            end if
            if (host == HD_HOST_LAMMPS) v = v + 0.5_wp * h * a
            if (released .and. .not. (z > 0.0_wp) .and. a == 0.0_wp .and. aold == 0.0_wp) exit
            if (t > 1.0e3_wp) return
        end do
        if (.not. clipped .and. .not. released) return
        ! touch at h - phi h after the start (the first overlap phi h at time h)
        tau = trel - (1.0_wp - phi) * h
        e = -v
        ok = e > 0.0_wp
    end subroutine own_collide

    !> The dimensionless (alpha, h) of a contact with k, d in SI (m, u, dt, law q):
    !> t* = (m / (k u^(1/2)))^(2/5), h = dt / t*, alpha = d t* (u t*)^q / m.
    pure subroutine reduce(k, d, q, ts, alpha, h)
        real(wp), intent(in) :: k, d, q
        real(wp), intent(out) :: ts, alpha, h
        ts = (mass / (k * speed**0.5_wp))**0.4_wp
        h = dt / ts
        alpha = d * ts * (speed * ts)**q / mass
    end subroutine reduce

    !> The phases of the sweep: 256 stratified midpoints, the extremes, the issue's 0.016.
    pure function phases() result(p)
        real(wp) :: p(n_phase + 5)
        integer :: j
        do j = 1, n_phase
            p(j) = (real(j, wp) - 0.5_wp) / real(n_phase, wp)
        end do
        p(n_phase + 1:) = [1.0e-5_wp, 1.0e-3_wp, 0.016_wp, 0.2_wp, 1.0_wp - 1.0e-5_wp]
    end function phases

    ! ================================================================ the checks

    !> Every contact of every host, law, end and (e, N) case.
    subroutine check_every_contact()
        integer, parameter :: hosts(3) = [HD_HOST_LAMMPS, HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2]
        type(hertzdamp_pair_t) :: pair
        real(wp) :: ph(n_phase + 5), k, d, ts, a, h, e, tau, q, emax, tmax, eall, tall
        integer :: ih, law, iend, ic, j, st, nmin, s2, reached, unreachable
        logical :: ok, all_ok, min_ok
        character(len=160) :: label
        ph = phases()
        eall = 0.0_wp
        tall = 0.0_wp
        reached = 0
        unreachable = 0
        min_ok = .true.
        do ih = 1, 3
            do law = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
                q = hertzdamp_law_q(law)
                do iend = HD_END_OVERLAP, HD_END_FORCE
                    do ic = 1, n_case
                        call hertzdamp_pair_init(case_e(ic), law, iend, hosts(ih), case_n(ic), pair, st, phase=.true.)
                        write (label, '(a, 1x, a, 1x, i0, a, f5.2, a, f7.1)') trim(hertzdamp_host_name(hosts(ih))), &
                            trim(hertzdamp_law_name(law)), iend, ' e ', case_e(ic), ' N ', case_n(ic)
                        if (st == HD_PHASE_UNREACHABLE) then
                            ! unreachable at this N: the fewest N is above it
                            unreachable = unreachable + 1
                            if (case_n(ic) <= 100.0_wp) then
                                call hertzdamp_phase_min_steps(case_e(ic), law, iend, hosts(ih), nmin, s2)
                                if (.not. (s2 == HD_OK .and. real(nmin, wp) > case_n(ic))) min_ok = .false.
                            end if
                            write (*, '(a)') '  unreachable: ' // trim(label)
                            cycle
                        end if
                        call suite%check(st == HD_OK, 'init ' // trim(label))
                        if (st /= HD_OK) cycle
                        reached = reached + 1
                        emax = 0.0_wp
                        tmax = 0.0_wp
                        all_ok = .true.
                        do j = 1, size(ph)
                            call hertzdamp_pair_kd_phase(pair, case_n(ic) * dt, mass, speed, 0.0_wp, ph(j), k, d, st)
                            if (st /= HD_OK) then
                                all_ok = .false.
                                cycle
                            end if
                            call reduce(k, d, q, ts, a, h)
                            call own_collide(a, h, ph(j), q, iend, hosts(ih), e, tau, ok)
                            if (.not. ok) then
                                all_ok = .false.
                                cycle
                            end if
                            emax = max(emax, abs(e - case_e(ic)) / case_e(ic))
                            tmax = max(tmax, abs(tau * ts / (case_n(ic) * dt) - 1.0_wp))
                        end do
                        call suite%check(all_ok, 'every contact computed and rebounds: ' // trim(label))
                        call suite%check(emax <= 1.0e-5_wp, 'every contact e within 1e-5: ' // trim(label))
                        call suite%check(tmax <= 1.0e-5_wp, 'every contact T_c within 1e-5: ' // trim(label))
                        if (.not. (emax <= 1.0e-5_wp .and. tmax <= 1.0e-5_wp)) then
                            write (*, '(a, 2es10.2)') '  ' // trim(label), emax, tmax
                        end if
                        eall = max(eall, emax)
                        tall = max(tall, tmax)
                    end do
                end do
            end do
        end do
        write (*, '(a, i0, a, i0, a, es9.2, a, es9.2)') '  targets reached: ', reached, ', unreachable: ', &
            unreachable, '; largest error of a contact: e ', eall, ', T_c ', tall
        call suite%check(min_ok, 'unreachable targets: hertzdamp_phase_min_steps above N')
        call suite%check(reached == 3 * 3 * 2 * n_case, 'every target of the grid reachable at its N')
    end subroutine check_every_contact

    !> The ties: every host, law and end, e = 0.2, 0.5, 0.9, N = 10, 12.5, 20: the phases at
    !> and around the tie phi_b and near the ends, each contact run by this program's stepper.
    subroutine check_ties()
        integer, parameter :: hosts(3) = [HD_HOST_LAMMPS, HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2]
        real(wp), parameter :: es(3) = [0.2_wp, 0.5_wp, 0.9_wp], ns(3) = [10.0_wp, 12.5_wp, 20.0_wp]
        real(wp), parameter :: off(7) = [0.0_wp, 1.0e-15_wp, 1.0e-12_wp, 1.0e-9_wp, 1.0e-6_wp, 1.0e-5_wp, 3.0e-5_wp]
        type(hertzdamp_pair_t) :: pair
        real(wp) :: ph(2 * size(off) + 3), pb, k, d, ts, a, h, e, tau, q, emax, tmax
        integer :: ih, law, iend, ie, in, j, st, tested
        logical :: ok, all_ok
        emax = 0.0_wp
        tmax = 0.0_wp
        all_ok = .true.
        tested = 0
        do in = 1, size(ns)
            pb = ns(in) - aint(ns(in))
            if (pb == 0.0_wp) pb = 1.0_wp
            ph(1:size(off)) = pb - off
            ph(size(off) + 1:2 * size(off)) = pb + off
            ph(2 * size(off) + 1:) = [1.0e-15_wp, 1.0_wp - 1.0e-15_wp, 1.0_wp]
            do ih = 1, 3
                do law = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
                    q = hertzdamp_law_q(law)
                    do iend = HD_END_OVERLAP, HD_END_FORCE
                        do ie = 1, size(es)
                            call hertzdamp_pair_init(es(ie), law, iend, hosts(ih), ns(in), pair, st, phase=.true.)
                            ! refused only where documented: the force end at e = 0.9, N <= 20
                            if (st == HD_PHASE_UNREACHABLE .and. iend == HD_END_FORCE .and. ie == 3 .and. &
                                ns(in) <= 20.0_wp) cycle
                            if (st /= HD_OK) all_ok = .false.
                            if (st /= HD_OK) cycle
                            tested = tested + 1
                            do j = 1, size(ph)
                                if (.not. (ph(j) > 0.0_wp .and. ph(j) <= 1.0_wp)) cycle
                                call hertzdamp_pair_kd_phase(pair, ns(in) * dt, mass, speed, 0.0_wp, ph(j), k, d, st)
                                ok = st == HD_OK
                                if (ok) then
                                    call reduce(k, d, q, ts, a, h)
                                    call own_collide(a, h, ph(j), q, iend, hosts(ih), e, tau, ok)
                                end if
                                if (.not. ok) then
                                    all_ok = .false.
                                    cycle
                                end if
                                if (.not. (abs(e - es(ie)) <= 1.0e-5_wp * es(ie) .and. &
                                           abs(tau * ts / (ns(in) * dt) - 1.0_wp) <= 1.0e-5_wp)) then
                                    write (*, '(a, 4(1x, i0), f6.2, f6.1, es24.16, 2es10.2)') '  tie missed:', ih, &
                                        law, iend, ie, es(ie), ns(in), ph(j), e / es(ie) - 1.0_wp, &
                                        tau * ts / (ns(in) * dt) - 1.0_wp
                                end if
                                emax = max(emax, abs(e - es(ie)) / es(ie))
                                tmax = max(tmax, abs(tau * ts / (ns(in) * dt) - 1.0_wp))
                            end do
                        end do
                    end do
                end do
            end do
        end do
        write (*, '(a, i0, a, es9.2, a, es9.2)') '  ties: ', tested, ' targets; largest error of a contact: e ', &
            emax, ', T_c ', tmax
        call suite%check(all_ok, 'ties: every target but the refused ones served, every contact rebounds')
        call suite%check(emax <= 1.0e-5_wp, 'ties: every contact e within 1e-5')
        call suite%check(tmax <= 1.0e-5_wp, 'ties: every contact T_c within 1e-5')
    end subroutine check_ties

    !> The mean-exact constants scatter e over the phase; the phase form does not.
    subroutine check_scatter_regression()
        type(hertzdamp_pair_t) :: pair
        real(wp) :: ph(n_phase + 5), k, d, ts, a, h, e, tau, s1(2), s2(2)
        integer :: j, st, form
        logical :: ok
        real(wp), parameter :: et = 0.5_wp, n = 10.0_wp
        ph = phases()
        call hertzdamp_pair_init(et, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_MFIX_EULER, n, pair, st, phase=.true.)
        call suite%check(st == HD_OK, 'scatter: init')
        do form = 1, 2
            s1(form) = 0.0_wp
            s2(form) = 0.0_wp
            do j = 1, n_phase
                if (form == 1) then
                    call hertzdamp_pair_kd(pair, n * dt, mass, speed, k, d, st)
                else
                    call hertzdamp_pair_kd_phase(pair, n * dt, mass, speed, 0.0_wp, ph(j), k, d, st)
                end if
                call reduce(k, d, 0.0_wp, ts, a, h)
                call own_collide(a, h, ph(j), 0.0_wp, HD_END_OVERLAP, HD_HOST_MFIX_EULER, e, tau, ok)
                s1(form) = s1(form) + e
                s2(form) = s2(form) + e * e
            end do
            s1(form) = s1(form) / n_phase
            s2(form) = sqrt(max(s2(form) / n_phase - s1(form)**2, 0.0_wp)) / et
        end do
        write (*, '(a, 2es10.2)') '  sd of e / e at e = 0.5, N = 10, mean-exact and phase form: ', s2
        call suite%check(s2(1) > 0.04_wp, 'scatter: mean-exact constants spread e by more than 4 %')
        call suite%check(s2(2) < 1.0e-2_wp * s2(1), 'scatter: phase form spread below 1/100 of it')
        call suite%check(abs(s1(1) - et) < 5.0e-3_wp, 'scatter: the mean-exact mean near e (256 phases)')
    end subroutine check_scatter_regression

    !> k, d against the closed forms; the physical bound.
    subroutine check_formulas_and_bound()
        type(hertzdamp_pair_t) :: pair
        real(wp) :: a, tau, k, d, r, q, kb, db, ts, ratio, ae, kk, dk, tc
        integer :: law, st, s2
        real(wp), parameter :: phi = 0.3125_wp
        tc = 10.0_wp * dt
        do law = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
            q = hertzdamp_law_q(law)
            call hertzdamp_pair_init(0.5_wp, law, HD_END_OVERLAP, HD_HOST_LAMMPS, 10.0_wp, pair, st, phase=.true.)
            call hertzdamp_pair_phase_constants(pair, phi, a, tau, s2)
            call suite%check(st == HD_OK .and. s2 == HD_OK, 'formulas: init and constants ' // hertzdamp_law_name(law))
            call hertzdamp_pair_kd_phase(pair, tc, mass, speed, 0.0_wp, phi, k, d, st)
            r = tau / tc
            call suite%check_close(k, mass * r**2.5_wp * speed**(-0.5_wp), 1.0e-14_wp, 'k = m r^5/2 u^-1/2 ' // &
                                   hertzdamp_law_name(law))
            call suite%check_close(d, a * mass * r * (r / speed)**q, 1.0e-14_wp, 'd = alpha m r (r/u)^q ' // &
                                   hertzdamp_law_name(law))
            ! bound far below k: k = k_phys, d from alpha_eff = alpha(e) + (alpha(phi) - alpha(e)) ratio^p
            kb = 1.0e-4_wp * k
            call hertzdamp_pair_kd_phase(pair, tc, mass, speed, kb, phi, kk, dk, st)
            ts = (mass / kb)**0.4_wp * speed**(-0.2_wp)
            ratio = (tc / tau) / ts
            ae = pair%alpha_cont + (a - pair%alpha_cont) * ratio**hertzdamp_host_order(HD_HOST_LAMMPS)
            db = ae * mass / ts / (speed * ts)**q
            call suite%check(st == HD_OK .and. kk == kb, 'bound: k = k_phys exactly ' // hertzdamp_law_name(law))
            call suite%check_close(dk, db, 1.0e-12_wp, 'bound: d of alpha_eff ' // hertzdamp_law_name(law))
            ! continuous at k_phys = k: just below it, d within 1e-8 of the unbounded d
            call hertzdamp_pair_kd_phase(pair, tc, mass, speed, k * (1.0_wp - 1.0e-12_wp), phi, kk, dk, st)
            call suite%check(st == HD_OK, 'bound: just below k')
            call suite%check_close(dk, d, 1.0e-8_wp, 'bound: continuous at k_phys = k ' // hertzdamp_law_name(law))
            ! above k: no effect (the same bits as without a bound)
            call hertzdamp_pair_kd_phase(pair, tc, mass, speed, 2.0_wp * k, phi, kk, dk, st)
            call suite%check(kk == k .and. dk == d, 'bound above k: no effect ' // hertzdamp_law_name(law))
        end do
    end subroutine check_formulas_and_bound

    !> Statuses: no table, bad phase, changed table, bad arguments; pair_kd unchanged.
    subroutine check_statuses()
        type(hertzdamp_pair_t) :: p0, p1, pn
        real(wp) :: k0, d0, k1, d1, nan, tc
        integer :: s0, s1
        nan = ieee_value(1.0_wp, ieee_quiet_nan)
        tc = 10.0_wp * dt
        call hertzdamp_pair_init(0.5_wp, HD_DAMPING_TSUJI, HD_END_FORCE, HD_HOST_MFIX_AB2, 10.0_wp, p0, s0)
        call hertzdamp_pair_init(0.5_wp, HD_DAMPING_TSUJI, HD_END_FORCE, HD_HOST_MFIX_AB2, 10.0_wp, p1, s1, phase=.true.)
        call suite%check(s0 == HD_OK .and. s1 == HD_OK, 'statuses: inits')
        call suite%check(all(transfer(p0, 1_int64, 8) == transfer(p1, 1_int64, 8)), &
                         'the header is the mean-exact constants with or without the table')
        call hertzdamp_pair_kd(p0, tc, mass, speed, k0, d0, s0)
        call hertzdamp_pair_kd(p1, tc, mass, speed, k1, d1, s1)
        call suite%check(s0 == HD_OK .and. s1 == HD_OK .and. k0 == k1 .and. d0 == d1, &
                         'hertzdamp_pair_kd: the same bits with the table')
        call hertzdamp_pair_kd_phase(p0, tc, mass, speed, 0.0_wp, 0.5_wp, k0, d0, s0)
        call suite%check(s0 == HD_NO_PHASE_TABLE .and. k0 == 0.0_wp .and. d0 == 0.0_wp, 'no table: HD_NO_PHASE_TABLE')
        call bad_phase(p1, 0.0_wp, 'phi = 0')
        call bad_phase(p1, -0.25_wp, 'phi < 0')
        call bad_phase(p1, 1.0_wp + epsilon(1.0_wp), 'phi > 1')
        call bad_phase(p1, nan, 'phi NaN')
        call hertzdamp_pair_kd_phase(p1, tc, mass, speed, 0.0_wp, 1.0_wp, k1, d1, s1)
        call suite%check(s1 == HD_OK, 'phi = 1 valid')
        call hertzdamp_pair_kd_phase(p1, -tc, mass, speed, 0.0_wp, 0.5_wp, k1, d1, s1)
        call suite%check(s1 == HD_BAD_TIME, 'bad T_c')
        call hertzdamp_pair_kd_phase(p1, tc, 0.0_wp, speed, 0.0_wp, 0.5_wp, k1, d1, s1)
        call suite%check(s1 == HD_BAD_MASS, 'bad m')
        call hertzdamp_pair_kd_phase(p1, tc, mass, nan, 0.0_wp, 0.5_wp, k1, d1, s1)
        call suite%check(s1 == HD_BAD_VELOCITY, 'bad u')
        call hertzdamp_pair_kd_phase(p1, tc, mass, speed, nan, 0.5_wp, k1, d1, s1)
        call suite%check(s1 == HD_BAD_KPHYS, 'bad k_phys')
        ! a changed layout entry, a changed header field, garbage
        call check_changed_fields(p1)
        call check_changed_nodes(p1)
        pn = hertzdamp_pair_t()
        call hertzdamp_pair_kd_phase(pn, tc, mass, speed, 0.0_wp, 0.5_wp, k1, d1, s1)
        call suite%check(s1 == HD_BAD_PAIR, 'unset pair: HD_BAD_PAIR')
        ! a failed init leaves an invalid pair
        call hertzdamp_pair_init(0.99_wp, HD_DAMPING_LINEAR, HD_END_FORCE, HD_HOST_LAMMPS, 10.0_wp, pn, s1, phase=.true.)
        call suite%check(s1 == HD_PHASE_UNREACHABLE, 'e = 0.99, force end, N = 10: HD_PHASE_UNREACHABLE')
        call hertzdamp_pair_kd(pn, tc, mass, speed, k1, d1, s0)
        call suite%check(s0 == HD_BAD_PAIR, 'failed init: the pair is invalid')
        ! host none: an empty table, the pair's own constants for every phase
        call hertzdamp_pair_init(0.5_wp, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_NONE, 10.0_wp, pn, s1, phase=.true.)
        call hertzdamp_pair_kd(pn, tc, mass, speed, k0, d0, s0)
        call hertzdamp_pair_kd_phase(pn, tc, mass, speed, 0.0_wp, 0.3_wp, k1, d1, s1)
        call suite%check(s0 == HD_OK .and. s1 == HD_OK .and. k0 == k1 .and. d0 == d1, 'host none: pair_kd bits')
    end subroutine check_statuses

    !> A changed field of a valid pair p (its table built): each one the per-contact path reads
    !> (the law, the header's marker, the table's layout entries 2, 4, 5, 6 and its marker,
    !> every entry of each half's record, read by a phase in that half) gives HD_BAD_PAIR
    !> and k = 0 on the usual contact; one it does not read (alpha, the entries 7 .. 10 and
    !> the rest's marker 3) gives HD_BAD_PAIR from hertzdamp_pair_phase_status and from a
    !> contact that reads it (the bound's path: the full check), and the unchanged k, d on
    !> the usual contact.
    subroutine check_changed_fields(p)
        type(hertzdamp_pair_t), intent(in) :: p
        type(hertzdamp_pair_t) :: pn
        real(wp) :: k0, d0, k1, d1, tc, phis(4)
        integer :: s0, s1, j, hb, nbad
        integer, parameter :: read_entries(5) = [1, 2, 4, 5, 6], unread_entries(5) = [3, 7, 8, 9, 10]
        tc = 10.0_wp * dt
        ! a phase in each half: the middles of (0, P/2], (P/2, P], (P, (P + 1)/2], ((P + 1)/2, 1]
        phis = 0.5_wp * ([0.0_wp, p%phase(5), p%phase(4), p%phase(6)] + [p%phase(5), p%phase(4), p%phase(6), 1.0_wp])
        call hertzdamp_pair_kd_phase(p, tc, mass, speed, 0.0_wp, 0.5_wp, k0, d0, s0)
        call suite%check(s0 == HD_OK .and. hertzdamp_pair_phase_status(p) == HD_OK, 'changed fields: the pair valid')
        nbad = 0
        do j = 1, size(read_entries)
            pn = p
            pn%phase(read_entries(j)) = pn%phase(read_entries(j)) + 0.125_wp
            call hertzdamp_pair_kd_phase(pn, tc, mass, speed, 0.0_wp, 0.5_wp, k1, d1, s1)
            if (.not. (s1 == HD_BAD_PAIR .and. k1 == 0.0_wp)) nbad = nbad + 1
        end do
        call suite%check(nbad == 0, 'changed table (entries 1, 2, 4, 5, 6): HD_BAD_PAIR')
        nbad = 0
        do hb = 11, 29, 6
            do j = 0, 5
                pn = p
                ! a change the lookup's clamps would hide for some entries: one bit of the fraction
                pn%phase(hb + j) = transfer(ieor(transfer(pn%phase(hb + j), 1_int64), 1_int64), 1.0_wp)
                call hertzdamp_pair_kd_phase(pn, tc, mass, speed, 0.0_wp, phis((hb - 5) / 6), k1, d1, s1)
                if (.not. (s1 == HD_BAD_PAIR .and. k1 == 0.0_wp)) nbad = nbad + 1
            end do
        end do
        call suite%check(nbad == 0, 'changed record of a half (each of its 6 entries, a phase in it): HD_BAD_PAIR')
        pn = p
        pn%law = real(HD_DAMPING_LINEAR, wp)
        call hertzdamp_pair_kd_phase(pn, tc, mass, speed, 0.0_wp, 0.5_wp, k1, d1, s1)
        call suite%check(s1 == HD_BAD_PAIR .and. k1 == 0.0_wp, 'changed law: HD_BAD_PAIR')
        pn = p
        pn%marker = pn%marker * 1.5_wp
        call hertzdamp_pair_kd_phase(pn, tc, mass, speed, 0.0_wp, 0.5_wp, k1, d1, s1)
        call suite%check(s1 == HD_BAD_PAIR .and. k1 == 0.0_wp, 'changed header marker: HD_BAD_PAIR')
        ! fields the usual contact does not read: the full check refuses them
        pn = p
        pn%alpha = pn%alpha * 1.5_wp
        nbad = unread_refused(pn, tc, k0, d0)
        do j = 1, size(unread_entries)
            pn = p
            pn%phase(unread_entries(j)) = pn%phase(unread_entries(j)) + 0.125_wp
            nbad = nbad + unread_refused(pn, tc, k0, d0)
        end do
        call suite%check(nbad == 0, 'changed alpha, table entries 3, 7 .. 10: the usual contact unchanged, ' // &
                         'the full check (status, the bound''s path) HD_BAD_PAIR')
    end subroutine check_changed_fields

    !> A node value of the table changed to NaN, +-infinity, -1 or huge (the markers do not
    !> cover the nodes): at 64 phases over (0, 1], with and without the bound, each call is
    !> refused or gives a finite k > 0 and a finite d, never a NaN or an infinity with
    !> status 0; hertzdamp_pair_phase_status refuses a node not finite.  (Before: a NaN node gave
    !> k = NaN with status 0.)
    subroutine check_changed_nodes(p)
        type(hertzdamp_pair_t), intent(in) :: p
        type(hertzdamp_pair_t) :: pn
        real(wp) :: vals(5), k1, d1, tc, k0, d0
        integer :: i, iv, j, s1, nbad, nstat, last
        vals = [ieee_value(1.0_wp, ieee_quiet_nan), ieee_value(1.0_wp, ieee_positive_inf), &
                ieee_value(1.0_wp, ieee_negative_inf), -1.0_wp, huge(1.0_wp)]
        tc = 10.0_wp * dt
        call hertzdamp_pair_kd_phase(p, tc, mass, speed, 0.0_wp, 0.5_wp, k0, d0, s1)
        ! the nodes end where the last half's do (its offset, entry 33, and node count - 4, entry 32)
        last = nint(p%phase(33)) + 2 * (nint(p%phase(32)) + 4)
        nbad = 0
        nstat = 0
        do i = hertzdamp_phase_header + 1, last
            do iv = 1, size(vals)
                pn = p
                pn%phase(i) = vals(iv)
                if (iv <= 3 .and. hertzdamp_pair_phase_status(pn) /= HD_BAD_PAIR) nstat = nstat + 1
                do j = 1, 64
                    call hertzdamp_pair_kd_phase(pn, tc, mass, speed, 0.0_wp, real(j, wp) / 64.0_wp, k1, d1, s1)
                    if (s1 == HD_OK .and. .not. (k1 > 0.0_wp .and. k1 <= huge(k1) .and. abs(d1) <= huge(d1))) then
                        nbad = nbad + 1
                    end if
                    call hertzdamp_pair_kd_phase(pn, tc, mass, speed, 0.5_wp * k0, real(j, wp) / 64.0_wp, k1, d1, s1)
                    if (s1 == HD_OK .and. .not. (k1 > 0.0_wp .and. k1 <= huge(k1) .and. abs(d1) <= huge(d1))) then
                        nbad = nbad + 1
                    end if
                end do
            end do
        end do
        call suite%check(nbad == 0 .and. last > hertzdamp_phase_header + 100, 'a node changed to NaN, +-inf, -1, ' // &
                         'huge: no call gives a k or d not finite (or k <= 0) with status 0 (' // itoa(nbad) // ')')
        call suite%check(nstat == 0, 'a node changed to NaN or +-inf: hertzdamp_pair_phase_status ' // &
                         'HD_BAD_PAIR (' // itoa(nstat) // ' not)')
    end subroutine check_changed_nodes

    !> 0 when pair pn (a field the usual contact does not read changed) gives k0, d0 (the
    !> unchanged pair's) on the usual contact (T_c tc, phi = 0.5) and HD_BAD_PAIR from the
    !> full check (hertzdamp_pair_phase_status, the bound's path), else 1.
    integer function unread_refused(pn, tc, k0, d0) result(nb)
        type(hertzdamp_pair_t), intent(in) :: pn
        real(wp), intent(in) :: tc, k0, d0
        real(wp) :: k1, d1
        integer :: s1
        nb = 0
        call hertzdamp_pair_kd_phase(pn, tc, mass, speed, 0.0_wp, 0.5_wp, k1, d1, s1)
        if (.not. (s1 == HD_OK .and. k1 == k0 .and. d1 == d0)) nb = 1
        if (hertzdamp_pair_phase_status(pn) /= HD_BAD_PAIR) nb = 1
        call hertzdamp_pair_kd_phase(pn, tc, mass, speed, 0.5_wp * k0, 0.5_wp, k1, d1, s1)
        if (.not. (s1 == HD_BAD_PAIR .and. k1 == 0.0_wp)) nb = 1
    end function unread_refused

    !> phi outside (0, 1]: HD_BAD_PHASE, k = d = 0.
    subroutine bad_phase(p, phi, what)
        type(hertzdamp_pair_t), intent(in) :: p
        real(wp), intent(in) :: phi
        character(len=*), intent(in) :: what
        real(wp) :: kb, db
        integer :: sb
        call hertzdamp_pair_kd_phase(p, 10.0_wp * dt, mass, speed, 0.0_wp, phi, kb, db, sb)
        call suite%check(sb == HD_BAD_PHASE .and. kb == 0.0_wp .and. db == 0.0_wp, 'HD_BAD_PHASE: ' // what)
    end subroutine bad_phase

    !> hertzdamp_onset_phase: the ratio, the late detection, bad input.
    subroutine check_onset_phase()
        real(wp) :: phi, nan
        integer :: st
        nan = ieee_value(1.0_wp, ieee_quiet_nan)
        call hertzdamp_onset_phase(0.375e-6_wp, 2.0_wp, 0.5e-6_wp, phi, st)
        call suite%check(st == HD_OK .and. abs(phi - 0.375_wp) <= 2.0_wp * epsilon(1.0_wp), 'onset: delta1/(u dt)')
        call hertzdamp_onset_phase(1.0_wp, 1.0_wp, 1.0_wp, phi, st)
        call suite%check(st == HD_OK .and. phi == 1.0_wp, 'onset: phi = 1 exactly')
        call hertzdamp_onset_phase(3.0e-6_wp, 1.0_wp, 1.0e-6_wp, phi, st)
        call suite%check(st == HD_OK .and. phi == 1.0_wp, 'onset: late detection (phi = 3) gives 1')
        call hertzdamp_onset_phase(1.0_wp, 1.0e-200_wp, 1.0e-200_wp, phi, st)
        call suite%check(st == HD_OK .and. phi == 1.0_wp, 'onset: u dt underflow gives 1')
        call hertzdamp_onset_phase(0.0_wp, 1.0_wp, 1.0_wp, phi, st)
        call suite%check(st == HD_BAD_PHASE .and. phi == 0.0_wp, 'onset: no overlap: HD_BAD_PHASE')
        call hertzdamp_onset_phase(nan, 1.0_wp, 1.0_wp, phi, st)
        call suite%check(st == HD_BAD_PHASE, 'onset: NaN overlap')
        call hertzdamp_onset_phase(1.0_wp, -1.0_wp, 1.0_wp, phi, st)
        call suite%check(st == HD_BAD_VELOCITY, 'onset: bad u')
        call hertzdamp_onset_phase(1.0_wp, 1.0_wp, 0.0_wp, phi, st)
        call suite%check(st == HD_BAD_TIME, 'onset: bad dt')
    end subroutine check_onset_phase

    !> The fewest N: init succeeds there and fails one below.
    subroutine check_min_steps()
        type(hertzdamp_pair_t) :: p
        integer :: n, st, s1, s2
        call hertzdamp_phase_min_steps(0.9_wp, HD_DAMPING_LINEAR, HD_END_FORCE, HD_HOST_LAMMPS, n, st)
        write (*, '(a, i0)') '  fewest N, lammps linear force end e = 0.9: ', n
        call suite%check(st == HD_OK .and. n > 10, 'min steps: found, above 10')
        call hertzdamp_pair_init(0.9_wp, HD_DAMPING_LINEAR, HD_END_FORCE, HD_HOST_LAMMPS, real(n, wp), p, s1, phase=.true.)
        call hertzdamp_pair_init(0.9_wp, HD_DAMPING_LINEAR, HD_END_FORCE, HD_HOST_LAMMPS, real(n - 1, wp), p, s2, &
                                 phase=.true.)
        call suite%check(s1 == HD_OK .and. s2 == HD_PHASE_UNREACHABLE, 'min steps: init at N_min and not at N_min - 1')
        call hertzdamp_phase_min_steps(0.5_wp, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_LAMMPS, n, st)
        call suite%check(st == HD_OK .and. n >= 2 .and. n < 10, 'min steps: e = 0.5 overlap below 10')
        call hertzdamp_phase_min_steps(0.5_wp, 7, HD_END_OVERLAP, HD_HOST_LAMMPS, n, st)
        call suite%check(st /= HD_OK .and. n == 0, 'min steps: bad law')
        ! what the fewest N says holds where the reach is not monotone in N: lammps, linear,
        ! overlap end, e = 0.2 builds at N = 3, not at 4, and again from 5 (N_min was 4: the
        ! confirmation moved N onto the failing N, untested; the plugin's test found it)
        call min_steps_holds(0.2_wp, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_LAMMPS)
        call min_steps_holds(0.1_wp, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_LAMMPS)
        call min_steps_holds(0.2_wp, HD_DAMPING_TSUJI, HD_END_FORCE, HD_HOST_MFIX_AB2)
    end subroutine check_min_steps

    !> The fewest N of (e, law, iend, host): the table builds at N_min .. N_min + 3 and not at
    !> N_min - 1.
    subroutine min_steps_holds(e, law, iend, host)
        real(wp), intent(in) :: e
        integer, intent(in) :: law, iend, host
        type(hertzdamp_pair_t) :: p
        integer :: n, st, k, s1, nok
        call hertzdamp_phase_min_steps(e, law, iend, host, n, st)
        nok = 0
        do k = 0, 3
            call hertzdamp_pair_init(e, law, iend, host, real(n + k, wp), p, s1, phase=.true.)
            if (s1 == HD_OK) nok = nok + 1
        end do
        call hertzdamp_pair_init(e, law, iend, host, real(n - 1, wp), p, s1, phase=.true.)
        call suite%check(st == HD_OK .and. nok == 4 .and. s1 /= HD_OK, 'min steps ' // hertzdamp_host_name(host) // &
                         ' e = ' // fmt_short(e, 3) // ': the table builds at N_min = ' // itoa(n) // ' .. N_min + 3 (' // &
                         itoa(nok) // ' of 4), not at N_min - 1')
    end subroutine min_steps_holds

    !> C and legacy: the module's bits.
    subroutine check_bindings()
        type(hertzdamp_pair_t) :: pm, pc
        real(c_double) :: pl(256), km, dm, kc, dc, kl, dl, phm, phc, phl, kb
        integer :: sm
        integer(c_int) :: sc, sl, nm, nc, nl
        real(wp), parameter :: phis(4) = [1.0e-6_wp, 0.25_wp, 0.7_wp, 1.0_wp]
        integer :: j
        call suite%check(hertzdamp_pair_size == 256, 'pair size 256 (the legacy declaration here)')
        call hertzdamp_pair_init(0.2_wp, HD_DAMPING_KUWABARA_KONO, HD_END_OVERLAP, HD_HOST_LAMMPS, 10.5_wp, pm, sm, &
                                 phase=.true.)
        sc = hertzdamp_c_pair_init_phase(0.2_wp, HD_DAMPING_KUWABARA_KONO, HD_END_OVERLAP, HD_HOST_LAMMPS, 10.5_wp, pc)
        call legacy_init_phase(0.2_wp, int(HD_DAMPING_KUWABARA_KONO, c_int), int(HD_END_OVERLAP, c_int), &
                               int(HD_HOST_LAMMPS, c_int), 10.5_wp, pl, sl)
        call suite%check(sm == HD_OK .and. sc == HD_OK .and. sl == HD_OK, 'bindings: inits')
        call suite%check(all(transfer(pm, 1_int64, 256) == transfer(pc, 1_int64, 256)), 'bindings: C pair bits')
        call suite%check(all(transfer(pm, 1_int64, 256) == transfer(pl, 1_int64, 256)), 'bindings: legacy pair bits')
        do j = 1, size(phis)
            call hertzdamp_pair_kd_phase(pm, 1.0e-5_wp, mass, speed, 0.0_wp, phis(j), km, dm, sm)
            sc = hertzdamp_c_pair_kd_phase(pc, 1.0e-5_wp, mass, speed, 0.0_wp, phis(j), kc, dc)
            call legacy_kd_phase(pl, 1.0e-5_wp, mass, speed, 0.0_wp, phis(j), kl, dl, sl)
            call suite%check(sm == HD_OK .and. sc == HD_OK .and. sl == HD_OK .and. km == kc .and. dm == dc .and. &
                             km == kl .and. dm == dl, 'bindings: k, d bits')
            kb = 0.3_wp * km
            call hertzdamp_pair_kd_phase(pm, 1.0e-5_wp, mass, speed, kb, phis(j), km, dm, sm)
            sc = hertzdamp_c_pair_kd_phase(pc, 1.0e-5_wp, mass, speed, kb, phis(j), kc, dc)
            call legacy_kd_phase(pl, 1.0e-5_wp, mass, speed, kb, phis(j), kl, dl, sl)
            call suite%check(sm == HD_OK .and. sc == HD_OK .and. sl == HD_OK .and. km == kc .and. dm == dc .and. &
                             km == kl .and. dm == dl, 'bindings: bounded k, d bits')
        end do
        sc = hertzdamp_c_pair_kd_phase(pc, 1.0e-5_wp, mass, speed, 0.0_wp, 1.5_wp, kc, dc)
        call legacy_kd_phase(pl, 1.0e-5_wp, mass, speed, 0.0_wp, 1.5_wp, kl, dl, sl)
        call suite%check(sc == HD_BAD_PHASE .and. sl == HD_BAD_PHASE .and. kc == 0.0_wp .and. kl == 0.0_wp, &
                         'bindings: bad phase')
        call hertzdamp_onset_phase(0.7e-6_wp, 1.1_wp, 1.0e-6_wp, phm, sm)
        sc = hertzdamp_c_onset_phase(0.7e-6_wp, 1.1_wp, 1.0e-6_wp, phc)
        call legacy_onset_phase(0.7e-6_wp, 1.1_wp, 1.0e-6_wp, phl, sl)
        call suite%check(sm == HD_OK .and. sc == HD_OK .and. sl == HD_OK .and. phm == phc .and. phm == phl, &
                         'bindings: onset phase bits')
        sc = hertzdamp_c_onset_phase(-1.0_wp, 1.1_wp, 1.0e-6_wp, phc)
        call suite%check(sc == HD_BAD_PHASE, 'bindings: C onset phase bad')
        call hertzdamp_phase_min_steps(0.5_wp, HD_DAMPING_TSUJI, HD_END_OVERLAP, HD_HOST_MFIX_AB2, sm, sl)
        nm = int(sm, c_int)
        sc = hertzdamp_c_phase_min_steps(0.5_wp, HD_DAMPING_TSUJI, HD_END_OVERLAP, HD_HOST_MFIX_AB2, nc)
        call legacy_min_steps(0.5_wp, int(HD_DAMPING_TSUJI, c_int), int(HD_END_OVERLAP, c_int), &
                              int(HD_HOST_MFIX_AB2, c_int), nl, sl)
        call suite%check(sc == HD_OK .and. sl == HD_OK .and. nm == nc .and. nm == nl .and. nm >= 2, &
                         'bindings: min steps')
    end subroutine check_bindings

end program test_phase
