!> The scene engine with a host's time integrator (`hertzdamp scene --host`,
!> doc/host-schemes.md): M spheres fall head-on onto a wall, each touching it at another
!> onset phase, phi_j = (j - 1/2)/M (one contact in each of M equal cells of the phase:
!> stratified midpoint sampling).  With the host's per-pair constants (hertzdamp_pair_init
!> at the scene's N, through the engine) the mean achieved e and T_c over the contacts
!> equal the targets e and N dt within the sampling tolerance; with the continuous
!> constants (host none) in the same scheme they miss by more (the test discriminates).
!>
!> Tolerance, from the phase sampling: the phase mean of a function f of bounded
!> variation differs from its stratified midpoint sample mean by at most V(f)/M (in each
!> cell |f(mid) - cell mean| <= the variation of f over the cell).  V(f) is estimated by
!> the variation of the samples themselves, sum_j |f_(j+1) - f_j| (in phase order), which
!> captures each jump where the release moves to another step and the monotone pieces
!> between; the tolerance is that over M, plus 1e-9 for round-off of the engine's
!> positions and instants.  The mean of the phase statistics themselves is exact
!> (hertzdamp_host_solve, checked against an independent simulation in test_host).
!>
!> `scene --host S --onset-phase` (issue 32): the same scenes with each contact's own
!> constants from its onset phase (hertzdamp_pair_kd_phase through the engine): every single
!> contact's e (separation over impact speed) within 1e-5 of the target and its T_c within
!> 1e-5 of N dt, where the host's constants alone scatter e by up to 13 % (e = 0.5, N = 10);
!> --onset-phase without a host is an invalid scene.
program test_scene_host
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_END_OVERLAP, HD_END_FORCE, HD_METHOD_FIT, HD_DAMPING_LINEAR, &
                         HD_DAMPING_TSUJI, HD_HOST_NONE, HD_HOST_LAMMPS, HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2, &
                         HD_HOST_VERLET, HD_HOST_LAMMPS_PHASE, hertzdamp_host_name, hertzdamp_law_name, hertzdamp_end_name
    use hertzdamp_dem, only: hertzdamp_dem_scene, hertzdamp_dem_result, hertzdamp_dem_material, hertzdamp_dem_wall, &
                             hertzdamp_dem_check, hertzdamp_dem_run, hertzdamp_dem_check_row, hertzdamp_dem_checks_of, &
                             HD_CHECK_PASS
    use hertzdamp_testing, only: test_suite, new_suite
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    !> Contacts per run (phase cells).
    integer, parameter :: m = 64
    integer, parameter :: schemes(4) = [HD_HOST_LAMMPS, HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2, HD_HOST_VERLET]
    real(wp), parameter :: es(3) = [0.2_wp, 0.5_wp, 0.9_wp]
    integer, parameter :: ns(2) = [10, 20]
    type(test_suite) :: s
    integer :: j, i, k

    s = new_suite('test_scene_host')
    do j = 1, size(schemes)
        do i = 1, size(es)
            do k = 1, size(ns)
                call compare(schemes(j), es(i), ns(k), HD_DAMPING_LINEAR, HD_END_OVERLAP)
            end do
        end do
    end do
    ! other laws and the force end at one point each
    do j = 1, size(schemes)
        call compare(schemes(j), 0.5_wp, 10, HD_DAMPING_TSUJI, HD_END_OVERLAP)
        call compare(schemes(j), 0.5_wp, 10, HD_DAMPING_LINEAR, HD_END_FORCE)
    end do
    do j = 1, size(schemes)
        do i = 1, size(es)
            do k = 1, size(ns)
                call every_contact(schemes(j), es(i), ns(k), HD_DAMPING_LINEAR, HD_END_OVERLAP)
            end do
        end do
        call every_contact(schemes(j), 0.5_wp, 10, HD_DAMPING_TSUJI, HD_END_OVERLAP)
        call every_contact(schemes(j), 0.5_wp, 10, HD_DAMPING_LINEAR, HD_END_FORCE)
    end do
    call invalid_schemes()
    call s%finish()

contains

    !> A scheme the engine does not integrate (lammps-phase, unknown codes) or a host
    !> without constants is an invalid scene, with a message naming it.
    subroutine invalid_schemes()
        type(hertzdamp_dem_scene) :: sc
        integer :: status
        character(len=:), allocatable :: msg
        call wall_scene(0.5_wp, 10, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_LAMMPS_PHASE, HD_HOST_NONE, sc)
        call hertzdamp_dem_check(sc, status, msg)
        call s%check(status /= HD_OK .and. index(msg, 'scheme: ') == 1 .and. index(msg, 'lammps-phase') > 0, &
                     'scheme lammps-phase: an invalid scene naming it (' // msg // ')')
        call wall_scene(0.5_wp, 10, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_VERLET, 9, sc)
        call hertzdamp_dem_check(sc, status, msg)
        call s%check(status /= HD_OK .and. index(msg, 'host: ') == 1 .and. index(msg, 'unknown') > 0, &
                     'host 9: an invalid scene naming it (' // msg // ')')
        call wall_scene(0.5_wp, 10, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_MFIX_AB2, HD_HOST_NONE, sc)
        call hertzdamp_dem_check(sc, status, msg)
        call s%check(status == HD_OK, 'scheme mfix-ab2 with the continuous constants: a valid scene')
        sc%onset_phase = .true.
        call hertzdamp_dem_check(sc, status, msg)
        call s%check(status /= HD_OK .and. index(msg, 'onset_phase: ') == 1, &
                     'onset_phase without a host: an invalid scene naming it (' // msg // ')')
    end subroutine invalid_schemes

    !> The scene: m steel spheres (radius 1 mm) 3 mm apart along x, falling at 1 m/s onto
    !> a steel wall z = 0, the j-th touching it at t = (2 + (j - 1/2)/m) dt, so that its
    !> first overlap is phi_j u dt, phi_j = 1 - (j - 1/2)/m.  dt = 1e-6 s: the adaptive k
    !> stays below the physical stiffness.  scheme and host as given.
    subroutine wall_scene(e, n, law, iend, scheme, host, sc)
        real(wp), intent(in) :: e
        integer, intent(in) :: n, law, iend, scheme, host
        type(hertzdamp_dem_scene), intent(out) :: sc
        real(wp), parameter :: r = 1.0e-3_wp, u = 1.0_wp, dt = 1.0e-6_wp
        integer :: p
        sc%title = 'head-on wall contacts over the onset phase'
        sc%dt = dt
        sc%steps_per_contact = n
        sc%end_time = (4 + 4 * n) * dt
        sc%iend = iend
        sc%law = law
        sc%accuracy = 1.0e-3_wp
        sc%rest_speed = 1.0e-4_wp
        sc%host = host
        sc%scheme = scheme
        sc%mat = [hertzdamp_dem_material('steel', 7800.0_wp, 2.1e11_wp, 0.3_wp, e, 0)]
        sc%wall = [hertzdamp_dem_wall(1, [0.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp, 1.0_wp], 0)]
        allocate (sc%pmat(m), sc%radius(m), sc%x(3, m), sc%v(3, m), sc%pline(m))
        sc%pmat = 1
        sc%radius = r
        sc%pline = 0
        do p = 1, m
            sc%x(:, p) = [3.0e-3_wp * p, 0.0_wp, r + u * dt * (2.0_wp + (p - 0.5_wp) / m)]
            sc%v(:, p) = [0.0_wp, 0.0_wp, -u]
        end do
    end subroutine wall_scene

    !> Mean relative errors of e and T_c over the contacts of a run, and the tolerances
    !> of the phase sampling (module notes); ok false when the run is not as designed.
    subroutine measure(sc, lab, err_e, err_t, tol_e, tol_t, ok)
        type(hertzdamp_dem_scene), intent(in) :: sc
        character(len=*), intent(in) :: lab
        real(wp), intent(out) :: err_e, err_t, tol_e, tol_t
        logical, intent(out) :: ok
        type(hertzdamp_dem_result) :: res
        real(wp) :: ee(m), tt(m), tc
        integer :: status
        character(len=:), allocatable :: msg
        err_e = huge(1.0_wp)
        err_t = huge(1.0_wp)
        tol_e = 0.0_wp
        tol_t = 0.0_wp
        call hertzdamp_dem_check(sc, status, msg)
        ok = status == HD_OK
        call s%check(ok, lab // ': the scene is valid')
        if (.not. ok) return
        call hertzdamp_dem_run(sc, HD_METHOD_FIT, 1.0e-8_wp, res)
        ok = res%status == HD_OK .and. res%ncontacts == m
        call s%check(ok, lab // ': runs, one contact per sphere')
        if (.not. ok) return
        ok = all(res%contacts%binary .and. res%contacts%t_end > 0.0_wp .and. .not. res%contacts%bound_active)
        call s%check(ok, lab // ': every contact binary, ended, without the physical bound')
        if (.not. ok) return
        ! contact j of the run is sphere j (they touch in that order): phase order
        ok = all(res%contacts%i == [(j, j=1, m)])
        call s%check(ok, lab // ': contacts in phase order')
        if (.not. ok) return
        tc = sc%steps_per_contact * sc%dt
        ee = res%contacts%u_out / res%contacts%u_in / res%contacts%e_target
        tt = (res%contacts%t_end - res%contacts%t_start) / tc
        err_e = sum(ee) / m - 1.0_wp
        err_t = sum(tt) / m - 1.0_wp
        tol_e = sum(abs(ee(2:) - ee(:m - 1))) / m + 1.0e-9_wp
        tol_t = sum(abs(tt(2:) - tt(:m - 1))) / m + 1.0e-9_wp
    end subroutine measure

    !> One scheme, target, N, law and end with the onset-phase constants: every contact's e
    !> and T_c within 1e-5 of the targets (the host's mean-exact constants: a spread of e).
    subroutine every_contact(scheme, e, n, law, iend)
        integer, intent(in) :: scheme, n, law, iend
        real(wp), intent(in) :: e
        type(hertzdamp_dem_scene) :: sc
        type(hertzdamp_dem_result) :: res
        real(wp) :: ee(m), tt(m), spread
        integer :: form
        character(len=128) :: lab
        write (lab, '(a,a,f4.2,a,i0,5a)') hertzdamp_host_name(scheme), ', e = ', e, ', N = ', n, ', ', &
            hertzdamp_law_name(law), ', ', hertzdamp_end_name(iend), ' end, onset phase'
        spread = 0.0_wp
        do form = 1, 2
            call wall_scene(e, n, law, iend, scheme, scheme, sc)
            sc%onset_phase = form == 2
            call hertzdamp_dem_run(sc, HD_METHOD_FIT, 1.0e-8_wp, res)
            call s%check(res%status == HD_OK .and. res%ncontacts == m, trim(lab) // ': runs, one contact per sphere')
            if (.not. (res%status == HD_OK .and. res%ncontacts == m)) return
            ee = res%contacts%u_out / res%contacts%u_in / res%contacts%e_target - 1.0_wp
            tt = (res%contacts%t_end - res%contacts%t_start) / (n * sc%dt) - 1.0_wp
            if (form == 1) spread = maxval(abs(ee))
        end do
        print '(a,3(a,es9.2))', trim(lab), ': largest error of a contact: e ', maxval(abs(ee)), ', T_c ', &
            maxval(abs(tt)), '; mean-exact constants: e ', spread
        call s%check(all(res%contacts%binary .and. res%contacts%t_end > 0.0_wp .and. .not. res%contacts%bound_active), &
                     trim(lab) // ': every contact binary, ended, without the physical bound')
        call s%check(maxval(abs(ee)) <= 1.0e-5_wp, trim(lab) // ': every contact''s e within 1e-5')
        call s%check(maxval(abs(tt)) <= 1.0e-5_wp, trim(lab) // ': every contact''s T_c within 1e-5')
        call s%check(spread > 100.0_wp * maxval(abs(ee)), trim(lab) // ': the mean-exact constants scatter e ' // &
                     'by more than 100 times as much')
    end subroutine every_contact

    !> One scheme, target, N, law and end: the host's constants hit the targets within the
    !> sampling tolerance, the continuous ones miss by more than it (in e or in T_c), and
    !> the report's checks of a host run pass.
    subroutine compare(scheme, e, n, law, iend)
        integer, intent(in) :: scheme, n, law, iend
        real(wp), intent(in) :: e
        type(hertzdamp_dem_scene) :: sc
        type(hertzdamp_dem_result) :: res
        type(hertzdamp_dem_check_row), allocatable :: rows(:)
        real(wp) :: ee, et, te, tt, ee0, et0, te0, tt0
        logical :: ok, ok0
        integer :: nfail, r
        character(len=128) :: lab
        write (lab, '(a,a,f4.2,a,i0,5a)') hertzdamp_host_name(scheme), ', e = ', e, ', N = ', n, ', ', &
            hertzdamp_law_name(law), ', ', hertzdamp_end_name(iend), ' end'
        call wall_scene(e, n, law, iend, scheme, scheme, sc)
        call measure(sc, trim(lab) // ', host constants', ee, et, te, tt, ok)
        call wall_scene(e, n, law, iend, scheme, HD_HOST_NONE, sc)
        call measure(sc, trim(lab) // ', continuous constants', ee0, et0, te0, tt0, ok0)
        if (.not. (ok .and. ok0)) return
        print '(a,4(a,es9.2),a,4(a,es9.2),a)', trim(lab), ': host: mean e err ', ee, ' (tol ', te, '), T_c err ', et, &
            ' (tol ', tt, ')', '; continuous: e err ', ee0, ' (tol ', te0, '), T_c err ', et0, ' (tol ', tt0, ')'
        call s%check(abs(ee) <= te .and. abs(et) <= tt, trim(lab) // ': the host''s constants give the mean e and T_c ' // &
                     'within the phase-sampling tolerance')
        call s%check(abs(ee0) > te0 .or. abs(et0) > tt0, trim(lab) // ': the continuous constants in the same ' // &
                     'scheme miss the mean e or T_c by more than that tolerance')
        call s%check(max(abs(ee0) - te0, abs(et0) - tt0) > max(abs(ee) - te, abs(et) - tt), trim(lab) // &
                     ': the continuous constants miss by more than the host''s')
        ! the report of the host run: each contact within the phase range of the host's collision
        call wall_scene(e, n, law, iend, scheme, scheme, sc)
        call hertzdamp_dem_run(sc, HD_METHOD_FIT, 1.0e-8_wp, res)
        call hertzdamp_dem_checks_of(sc, res, rows, nfail)
        r = findloc(rows%name, 'max_e_rel_err (binary contacts)', dim=1)
        call s%check(r > 0, trim(lab) // ': the report of a host run checks e')
        if (r > 0) call s%check(rows(r)%outcome == HD_CHECK_PASS .and. rows(r + 1)%outcome == HD_CHECK_PASS, &
                                trim(lab) // ': every contact''s e and T_c within the phase range of the host''s collision')
    end subroutine compare

end program test_scene_host
