!> Scenes (data/scenes/*.nml) run through the library-level DEM engine:
!> - binary collisions: achieved e and T_c meet the targets to the method accuracy
!>   plus the time-step error 2/N^2 (velocity Verlet, N steps per contact), and the
!>   error falls as N = 10, 20, 40 (overlap and force contact ends);
!> - ball dropped on a wall: successive rebound heights follow e^2 up to the gravity
!>   correction |e_eff/e - 1| <= 0.25 g T_c/u_in (asserted in drop), the
!>   flights conserve energy, and the ball comes to rest at its static overlap;
!> - chain: momentum conserved to round-off, energy never increases;
!> - bed: finishes, no particle leaves the box, comes to rest;
!> - method choice: the nearly elastic chain picks a cheaper rule than the strongly
!>   damped bed, and both rules meet their scene's accuracy against the reference;
!> - invalid scene files give a status and a message naming the line or key.
program test_scene
    use hertzdamp, only: hertzdamp_rk, hertzdamp_collision, hertzdamp_rk45_collide, HD_OK, HD_END_OVERLAP, &
                         HD_END_FORCE, HD_METHOD_ITERATIVE, HD_METHOD_FIRST_ORDER, hertzdamp_invert_alpha, &
                         hertzdamp_tau_c0, hertzdamp_sphere_mass, HD_METHOD_FIT, HD_DAMPING_LINEAR, &
                         HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO, hertzdamp_law_name, hertzdamp_end_name, &
                         hertzdamp_law_q, hertzdamp_reduce, hertzdamp_tsuji_alpha, hertzdamp_e1, HD_METHOD_COMPACT, &
                         HD_METHOD_SERIES, HD_METHOD_PADE, hertzdamp_method_name
    use hertzdamp_dem, only: hertzdamp_dem_scene, hertzdamp_dem_result, hertzdamp_dem_check, hertzdamp_dem_run, &
                             hertzdamp_dem_select, hertzdamp_dem_cost_order, hertzdamp_dem_supports, &
                             hertzdamp_dem_steps_min, &
                             hertzdamp_dem_check_row, hertzdamp_dem_checks_of, hertzdamp_dem_verlet_energy, &
                             HD_CHECK_FAIL, HD_CHECK_PASS, hertzdamp_dem_state, hertzdamp_dem_start, hertzdamp_dem_advance, &
                             hertzdamp_dem_finish, hertzdamp_dem_steps_done, hertzdamp_dem_steps_total
    use hertzdamp_dem_io, only: hertzdamp_scene_read
    use hertzdamp_testing, only: test_suite, new_suite
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use, intrinsic :: iso_fortran_env, only: output_unit
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    type(test_suite) :: s
    integer :: law

    s = new_suite('test_scene')
    do law = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
        call binary_convergence(HD_END_OVERLAP, law)
        call binary_convergence(HD_END_FORCE, law)
    end do
    call speed_dependence()
    call tsuji_scene()
    call laws_methods()
    call drop()
    call drop_force_end()
    call chain_and_bed()
    call invalid_scenes()
    call unrepresentable_scenes()
    call coincident_centres()
    call checks_agree()
    call force_end_jump()
    call run_in_pieces()
    call verlet_energy_swing()
    call long_file()
    call s%finish()

contains

    !> Read a shipped scene; a failure is a failed check and stops the program.
    subroutine load(path, sc)
        character(len=*), intent(in) :: path
        type(hertzdamp_dem_scene), intent(out) :: sc
        integer :: status
        character(len=:), allocatable :: msg
        call hertzdamp_scene_read(path, sc, status, msg)
        call s%check(status == HD_OK, path // ' reads: ' // msg)
        if (status /= HD_OK) call s%finish()
        call hertzdamp_dem_check(sc, status, msg)
        call s%check(status == HD_OK, path // ' is valid: ' // msg)
        if (status /= HD_OK) call s%finish()
    end subroutine load

    !> The rule chosen by `auto` for a scene (checked to exist).
    integer function auto_method(sc) result(m)
        type(hertzdamp_dem_scene), intent(in) :: sc
        real(wp) :: err(6)
        logical :: avail(6)
        integer :: status
        call hertzdamp_dem_select(sc, m, err, avail, status)
        call s%check(status == HD_OK .and. m >= 0, 'auto finds a rule')
        if (m < 0) m = HD_METHOD_ITERATIVE
    end function auto_method

    !> Binary collisions of binary.nml with the damping law `law` and the contact end
    !> iend, at N = 10, 20, 40 steps per contact (the scene's accuracy and the rule auto
    !> picks, as the report runs it) and at N = 40, 80, 160, 320 (the fit rule and an
    !> accuracy of 1e-10, so that the bound is the time-step error 2/N^2 alone).  Each N
    !> is run four times with the touches shifted by a quarter step (initial positions
    !> moved back by v dt/4): the error constant depends on where a touch falls inside
    !> a step, and the largest of the four phases varies smoothly with N where a single
    !> phase does not (its N^2-scaled error moves by up to 3.5x between N).  Asserted:
    !> every run's e and T_c within the report's bound (the rows of
    !> hertzdamp_dem_checks_of pass) and the observed order of the largest error,
    !> log(err(N1)/err(N2)) / log(N2/N1): within 2 +- 0.6 from N = 10 to 40 (measured
    !> 1.83 to 2.52: N = 10 is not yet asymptotic) and within 2 +- 0.25 from 40 to 320
    !> (measured 1.95 to 2.20; without the damping force's trapezoid correction the
    !> tsuji and kuwabara-kono runs would fall to order 1 + q, the exponent of the
    !> error term it removes: a design note, no run here drops the correction).
    subroutine binary_convergence(iend, law)
        integer, intent(in) :: iend, law
        type(hertzdamp_dem_scene) :: sc
        integer :: k, nn(7), method
        real(wp) :: ee(7), et(7)
        character(len=64) :: lab
        nn = [10, 20, 40, 40, 80, 160, 320]
        call load('data/scenes/binary.nml', sc)
        sc%iend = iend
        sc%law = law
        method = auto_method(sc)
        write (lab, '(a,a,a,a)') 'binary, ', hertzdamp_law_name(law), ', ', hertzdamp_end_name(iend)
        do k = 1, 7
            if (k == 4) then
                sc%accuracy = 1.0e-10_wp
                method = HD_METHOD_FIT
            end if
            call phases(sc, nn(k), method, trim(lab), .true., ee(k), et(k))
        end do
        call order(lab, nn(1:3), ee(1:3), et(1:3), 0.6_wp)
        call order(lab, nn(4:7), ee(4:7), et(4:7), 0.25_wp)
        ! stronger damping, every pair at e = 0.5 (within the bound) and e = 0.3 (the
        ! overlap end reaches 3.2/N^2 at N = 10 and 20 for every law: the bound fails
        ! there, as doc/scenes.md says; asserted from N = 40 on).  At N = 10 and 20 instead:
        ! the report is honest (a run passes exactly when its error is within the bound,
        ! see phases) and the errors converge, at least at order 2 - 0.6 from N = 10 to 40
        ! (second-order Verlet; not yet asymptotic there, measured 1.8 to 3.1, faster is fine)
        call load('data/scenes/binary.nml', sc)
        sc%iend = iend
        sc%law = law
        do k = 1, 2
            sc%mat(:)%restitution = merge(0.5_wp, 0.3_wp, k == 1)
            method = auto_method(sc)
            write (lab, '(a,f3.1,4a)') 'binary e = ', sc%mat(1)%restitution, ', ', hertzdamp_law_name(law), ', ', &
                hertzdamp_end_name(iend)
            call phases(sc, 10, method, trim(lab), k == 1, ee(1), et(1))
            call phases(sc, 20, method, trim(lab), k == 1, ee(2), et(2))
            call phases(sc, 40, method, trim(lab), .true., ee(3), et(3))
            write (output_unit, '(2a,2(a,3f7.3))') trim(lab), ', N = 10, 20, 40', &
                ': err N^2 in e', ee(1:3) * nn(1:3)**2, ', in T_c', et(1:3) * nn(1:3)**2
            if (k == 2) call s%check(log(ee(1) / ee(3)) / log(4.0_wp) >= 1.4_wp .and. &
                                     log(et(1) / et(3)) / log(4.0_wp) >= 1.4_wp, trim(lab) // &
                                     ', N = 10 to 40: the e and T_c errors fall at least as N^-1.4')
        end do
    end subroutine binary_convergence

    !> Observed orders of the e and T_c errors from the first to the last N, asserted
    !> within 2 +- tol; the errors times N^2 and the orders are printed.
    subroutine order(lab, nn, ee, et, tol)
        character(len=*), intent(in) :: lab
        integer, intent(in) :: nn(:)
        real(wp), intent(in) :: ee(:), et(:), tol
        real(wp) :: pe, pt
        character(len=96) :: l2
        integer :: k
        k = size(nn)
        pe = log(ee(1) / ee(k)) / log(real(nn(k), wp) / nn(1))
        pt = log(et(1) / et(k)) / log(real(nn(k), wp) / nn(1))
        write (l2, '(2a,i0,a,i0)') trim(lab), ', N = ', nn(1), ' to ', nn(k)
        call s%check(abs(pe - 2.0_wp) <= tol .and. abs(pt - 2.0_wp) <= tol, trim(l2) // &
                     ': observed orders of the e and T_c errors within 2 +- the tolerance')
        write (output_unit, '(a,a,*(f7.3))', advance='no') trim(l2), ': err N^2 in e', ee * nn**2
        write (output_unit, '(a,*(f7.3))', advance='no') ', in T_c', et * nn**2
        write (output_unit, '(a,2f6.2)') '; order', pe, pt
    end subroutine order

    !> The scene at N steps per contact, run with the touches at four phases of a step;
    !> with `within`, each run's checks of e and T_c (the report's rows) must pass.
    !> ee, et: the largest relative errors over the runs.
    subroutine phases(sc0, n, method, lab, within, ee, et)
        type(hertzdamp_dem_scene), intent(in) :: sc0
        integer, intent(in) :: n, method
        character(len=*), intent(in) :: lab
        logical, intent(in) :: within
        real(wp), intent(out) :: ee, et
        type(hertzdamp_dem_scene) :: sc
        type(hertzdamp_dem_result) :: res
        type(hertzdamp_dem_check_row), allocatable :: rows(:)
        integer :: ph, nfail, ie, it
        character(len=96) :: l2
        ee = 0.0_wp
        et = 0.0_wp
        do ph = 0, 3
            sc = sc0
            sc%steps_per_contact = n
            sc%dt = 1.0e-5_wp / n
            sc%x = sc0%x - sc0%v * (ph * sc%dt / 4.0_wp)
            write (l2, '(a,a,i0,a,i0,a)') lab, ', N = ', n, ', phase ', ph, '/4'
            call hertzdamp_dem_run(sc, method, 1.0e-8_wp, res)
            call s%check(res%status == HD_OK, trim(l2) // ': run succeeds')
            call s%check(res%ncontacts == 15, trim(l2) // ': 15 contacts')
            if (res%status /= HD_OK .or. res%ncontacts /= 15) return
            call s%check(all(res%contacts%binary .and. res%contacts%t_end > 0.0_wp), trim(l2) // ': all binary and ended')
            ! both regimes present: rule-softened (fast) and physical (slow) contacts
            call s%check(any(res%contacts%bound_active) .and. any(.not. res%contacts%bound_active), &
                         trim(l2) // ': rule and physical-bound contacts present')
            call s%check(abs(res%momentum_drift) <= 1.0e-13_wp * res%momentum_scale, trim(l2) // ': momentum')
            call hertzdamp_dem_checks_of(sc, res, rows, nfail)
            ie = findloc(rows%name, 'max_e_rel_err (binary contacts)', dim=1)
            it = findloc(rows%name, 'max_tc_rel_err (binary contacts)', dim=1)
            call s%check(ie > 0 .and. it > 0, trim(l2) // ': the report checks e and T_c')
            if (ie == 0 .or. it == 0) return
            call s%check(abs(rows(ie)%bound - (sc%accuracy + 2.0_wp / n**2)) <= 1.0e-15_wp, &
                         trim(l2) // ': the report''s bound is accuracy + 2/N^2')
            if (within) then
                call s%check(rows(ie)%outcome == HD_CHECK_PASS .and. rows(it)%outcome == HD_CHECK_PASS, &
                             trim(l2) // ': e and T_c within the report''s bound accuracy + 2/N^2')
                call s%check(nfail == 0, trim(l2) // ': every check of the report passes')
            else
                ! beyond the bound is allowed here, but the report must say so
                call s%check(honest(rows(ie)) .and. honest(rows(it)), trim(l2) // ': the report''s e and T_c ' // &
                             'rows pass exactly when the error is within the bound, and fail otherwise')
            end if
            ee = max(ee, rows(ie)%value)
            et = max(et, rows(it)%value)
        end do
    end subroutine phases

    !> A report row with a bound whose outcome is pass exactly when its value is within it.
    logical function honest(r)
        type(hertzdamp_dem_check_row), intent(in) :: r
        honest = r%has_bound .and. (r%outcome == merge(HD_CHECK_PASS, HD_CHECK_FAIL, r%value <= r%bound))
    end function honest

    !> Impacts slower than the speed floor (rest_speed) get k and d from the rule at
    !> u_rule = rest_speed, so their alpha at the real impact speed u_in is the law's:
    !> alpha ~ u^((4q - 1)/5) at fixed k, d (doc/damping-laws.md section 1).  binary.nml
    !> with rest_speed = 2e-2 (its impacts at 1e-3 and 1e-2 m/s below the floor), N = 20,
    !> both the rule (T_c = N dt) and the physical stiffness (restitution only), both ends:
    !> - every contact's alpha, from its k, d, m and u_in (hertzdamp_reduce), is
    !>   alpha(e_target) (u_in/u_rule)^((4q - 1)/5) to 1e-12; tsuji: alpha(e_target)
    !>   itself, at every impact speed;
    !> - its achieved e is the reference integrator's e at that alpha within the
    !>   report's bound accuracy + 2/N^2: tsuji, the target e at every impact speed;
    !>   linear below the target (more damped), kuwabara-kono above it, each by more than
    !>   the bound (so the tsuji check is not idle).
    subroutine speed_dependence()
        type(hertzdamp_dem_scene) :: sc
        type(hertzdamp_dem_result) :: res
        type(hertzdamp_collision) :: r
        integer :: law, iend, mode, c, st, nslow
        real(wp) :: bound, alpha, ts, a_t, tau, p, e_ach
        logical :: ok_a, ok_e, ok_side
        character(len=80) :: lab
        do law = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
            do iend = HD_END_OVERLAP, HD_END_FORCE
                do mode = 1, 2
                    call load('data/scenes/binary.nml', sc)
                    sc%law = law
                    sc%iend = iend
                    sc%rest_speed = 2.0e-2_wp
                    sc%want_duration = mode == 1
                    sc%steps_per_contact = 20
                    sc%dt = merge(5.0e-7_wp, 2.0e-7_wp, mode == 1)
                    write (lab, '(5a)') 'speed floor, ', hertzdamp_law_name(law), ', ', hertzdamp_end_name(iend), &
                        trim(merge(', rule    ', ', physical', mode == 1))
                    call hertzdamp_dem_run(sc, HD_METHOD_FIT, 1.0e-8_wp, res)
                    call s%check(res%status == HD_OK .and. res%ncontacts == 15, trim(lab) // ': run, 15 contacts')
                    if (res%status /= HD_OK .or. res%ncontacts /= 15) cycle
                    bound = sc%accuracy + 2.0_wp / hertzdamp_dem_steps_min(sc, res)**2
                    p = (4.0_wp * hertzdamp_law_q(law) - 1.0_wp) / 5.0_wp
                    ok_a = .true.
                    ok_e = .true.
                    ok_side = .true.
                    nslow = 0
                    do c = 1, res%ncontacts
                        associate (ct => res%contacts(c))
                            call hertzdamp_reduce(ct%k, ct%d, ct%m, ct%u_in, alpha, ts, st, law=law)
                            call hertzdamp_invert_alpha(ct%e_target, iend, a_t, tau, st, law=law)
                            if (abs(alpha - a_t * (ct%u_in / ct%u_rule)**p) > 1.0e-12_wp * a_t) ok_a = .false.
                            r = hertzdamp_rk45_collide(alpha, iend, law=law)
                            e_ach = ct%u_out / ct%u_in
                            if (abs(e_ach - r%e) > bound * r%e) ok_e = .false.
                            if (ct%u_in < sc%rest_speed) then
                                nslow = nslow + 1
                                select case (law)
                                case (HD_DAMPING_TSUJI)
                                    if (abs(e_ach - ct%e_target) > bound * ct%e_target) ok_side = .false.
                                case (HD_DAMPING_LINEAR)
                                    if (e_ach > ct%e_target * (1.0_wp - bound)) ok_side = .false.
                                case default
                                    if (e_ach < ct%e_target * (1.0_wp + bound)) ok_side = .false.
                                end select
                            end if
                        end associate
                    end do
                    call s%check(nslow == 6, trim(lab) // ': six impacts below the speed floor')
                    call s%check(ok_a, trim(lab) // ': alpha = alpha(e) (u_in/u_rule)^((4q-1)/5) at every contact')
                    call s%check(ok_e, trim(lab) // ': e = e_rk45(alpha) within accuracy + 2/N^2 at every contact')
                    select case (law)
                    case (HD_DAMPING_TSUJI)
                        call s%check(ok_side, trim(lab) // ': the target e below the speed floor too')
                    case (HD_DAMPING_LINEAR)
                        call s%check(ok_side, trim(lab) // ': e below the target (beyond the bound) under the floor')
                    case default
                        call s%check(ok_side, trim(lab) // ': e above the target (beyond the bound) under the floor')
                    end select
                end do
            end do
        end do
    end subroutine speed_dependence

    !> The shipped tsuji scene (data/scenes/binary_tsuji.nml: the binary collisions with
    !> damping = 'tsuji' and the physical stiffness, as DEM engines set it up): every
    !> check of its report passes; every contact has k = k_phys and
    !> d = alpha sqrt(m k_phys) with alpha = sqrt(5) beta(e), the closed form of
    !> Antypov & Elliott (hertzdamp_tsuji_alpha), to 1e-12: one d per material pair at
    !> every impact speed, and the target e at every impact speed within the bound.
    subroutine tsuji_scene()
        type(hertzdamp_dem_scene) :: sc
        type(hertzdamp_dem_result) :: res
        type(hertzdamp_dem_check_row), allocatable :: rows(:)
        integer :: nfail, c
        real(wp) :: bound, d_closed
        logical :: ok_d, ok_e
        call load('data/scenes/binary_tsuji.nml', sc)
        call s%check(sc%law == HD_DAMPING_TSUJI .and. .not. sc%want_duration, &
                     'binary_tsuji: damping = ''tsuji'', restitution only')
        call hertzdamp_dem_run(sc, auto_method(sc), 1.0e-8_wp, res)
        call s%check(res%status == HD_OK .and. res%ncontacts == 15, 'binary_tsuji: run, 15 contacts')
        if (res%status /= HD_OK .or. res%ncontacts /= 15) return
        call hertzdamp_dem_checks_of(sc, res, rows, nfail)
        call s%check(nfail == 0, 'binary_tsuji: every check of the report passes')
        bound = sc%accuracy + 2.0_wp / hertzdamp_dem_steps_min(sc, res)**2
        ok_d = all(res%contacts%bound_active .and. res%contacts%k == res%contacts%k_phys)
        ok_e = .true.
        do c = 1, res%ncontacts
            associate (ct => res%contacts(c))
                d_closed = hertzdamp_tsuji_alpha(ct%e_target) * sqrt(ct%m * ct%k_phys)
                if (abs(ct%d - d_closed) > 1.0e-12_wp * d_closed) ok_d = .false.
                if (abs(ct%u_out / ct%u_in - ct%e_target) > bound * ct%e_target) ok_e = .false.
            end associate
        end do
        call s%check(ok_d, 'binary_tsuji: k = k_phys and d = sqrt(5) beta(e) sqrt(m k_phys) at every contact (1e-12)')
        call s%check(ok_e, 'binary_tsuji: the target e at every impact speed, 1e-3 to 10 m/s, within the bound')
        call s%check(maxval(res%contacts%u_in) / minval(res%contacts%u_in) > 9.0e3_wp, &
                     'binary_tsuji: impact speeds over four decades')
    end subroutine tsuji_scene

    !> The rules of each law in `--method auto`: compact, series and Pade are skipped
    !> for tsuji and kuwabara-kono (not provided), fit, iterative and first-order are
    !> measured.  A nearly elastic chain (e = 0.995) picks first-order for every law,
    !> and its alpha is (1 - e)/e1 with the law's own e1: within the accuracy against
    !> the law's reference integrator (with the linear law's e1 the tsuji e would be
    !> off by 1.1e-3 > 1e-3).
    subroutine laws_methods()
        type(hertzdamp_dem_scene) :: sc
        integer :: law, chosen, st, c
        real(wp) :: err(6), ee, et, alpha, tau
        logical :: avail(6), linear_only
        call load('data/scenes/chain.nml', sc)
        sc%mat(:)%restitution = 0.995_wp
        do law = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
            sc%law = law
            call hertzdamp_dem_select(sc, chosen, err, avail, st)
            call s%check(st == HD_OK .and. chosen == HD_METHOD_FIRST_ORDER, &
                         'laws: chain e = 0.995, ' // hertzdamp_law_name(law) // ': auto picks first-order')
            do c = 1, 6
                linear_only = any(hertzdamp_dem_cost_order(c) == [HD_METHOD_COMPACT, HD_METHOD_SERIES, HD_METHOD_PADE])
                call s%check(avail(c) .eqv. (law == HD_DAMPING_LINEAR .or. .not. linear_only), 'laws: ' // &
                             hertzdamp_law_name(law) // ': ' // hertzdamp_method_name(hertzdamp_dem_cost_order(c)) // &
                             ' offered exactly when the library provides it')
                call s%check(hertzdamp_dem_supports(hertzdamp_dem_cost_order(c), law) .eqv. avail(c), &
                             'laws: hertzdamp_dem_supports agrees with the selection')
            end do
            call rule_errors(sc, HD_METHOD_FIRST_ORDER, ee, et)
            call s%check(ee <= sc%accuracy .and. et <= sc%accuracy, &
                         'laws: ' // hertzdamp_law_name(law) // ': first-order within the accuracy at e = 0.995')
            call hertzdamp_invert_alpha(0.995_wp, sc%iend, alpha, tau, st, method=HD_METHOD_FIRST_ORDER, law=law)
            call s%check_close(alpha, (1.0_wp - 0.995_wp) / hertzdamp_e1(law), 1.0e-15_wp, &
                               'laws: first-order alpha = (1 - e)/e1 of the law')
        end do
    end subroutine laws_methods

    subroutine drop()
        type(hertzdamp_dem_scene) :: sc
        type(hertzdamp_dem_result) :: res
        integer :: i, nb, nchecked, st
        real(wp) :: g, h1, h2, eps, e, m, zs, bound
        logical :: ok_h, ok_f
        call load('data/scenes/drop.nml', sc)
        call hertzdamp_dem_run(sc, auto_method(sc), 1.0e-4_wp, res)
        call s%check(res%status == HD_OK, 'drop: run succeeds')
        g = norm2(sc%g)
        e = sc%mat(1)%restitution
        nb = count(res%contacts%t_end > 0.0_wp)
        call s%check(nb >= 20, 'drop: at least 20 bounces')
        ok_h = .true.
        ok_f = .true.
        nchecked = 0
        bound = 2.0_wp / sc%steps_per_contact**2
        do i = 1, nb - 1
            eps = g * res%contacts(i + 1)%tc_target / res%contacts(i + 1)%u_in
            if (eps > 0.1_wp) cycle
            ! flight between bounce i and i+1: x + v^2/(2g) is exact under velocity Verlet
            if (abs(res%contacts(i + 1)%u_in / res%contacts(i)%u_out - 1.0_wp) > 1.0e-4_wp) ok_f = .false.
            h1 = res%contacts(i)%u_out**2 / (2.0_wp * g)
            h2 = res%contacts(i + 1)%u_out**2 / (2.0_wp * g)
            nchecked = nchecked + 1
            if (abs(sqrt(h2 / h1) / e - 1.0_wp) > 0.25_wp * eps + bound) ok_h = .false.
        end do
        call s%check(nchecked >= 15, 'drop: at least 15 bounces with g T_c/u_in <= 0.1')
        call s%check(ok_h, 'drop: rebound heights h(i+1)/h(i) = e^2 within 0.25 g T_c/u_in + 2/N^2')
        call s%check(ok_f, 'drop: impact speed = previous rebound speed to 1e-4 (flight conserves energy; ' // &
                     'touch and release instants are interpolated)')
        call s%check(res%at_rest, 'drop: the ball comes to rest')
        ! at rest on the wall, pressed in by its weight: k zeta^(3/2) = m g
        call hertzdamp_sphere_mass(sc%radius(1), sc%mat(1)%density, m, st)
        zs = (m * g / res%contacts(res%ncontacts)%k)**(2.0_wp / 3.0_wp)
        call s%check_close(sc%radius(1) - res%x_final(3, 1), zs, 1.0e-3_wp, 'drop: static overlap (m g/k)^(2/3)')
        ! the discrete energy inside a contact carries the O(1/N^2) error of velocity Verlet
        call s%check(res%energy_rise <= abs(res%energy0) / sc%steps_per_contact**2, &
                     'drop: energy never increases (beyond the 1/N^2 time-step error)')
    end subroutine drop

    !> The drop scene with the force contact end: a contact released at the force zero
    !> while the ball still overlaps the wall must not keep the wall from acting again
    !> (slow bounces under gravity reverse before the overlap is gone).
    subroutine drop_force_end()
        type(hertzdamp_dem_scene) :: sc
        type(hertzdamp_dem_result) :: res
        real(wp) :: m, zs
        integer :: st
        call load('data/scenes/drop.nml', sc)
        sc%iend = HD_END_FORCE
        call hertzdamp_dem_run(sc, auto_method(sc), 1.0e-4_wp, res)
        call s%check(res%status == HD_OK, 'drop, force end: run succeeds')
        call s%check(res%left_domain == 0, 'drop, force end: the ball stays in the box')
        call s%check(res%at_rest, 'drop, force end: the ball comes to rest')
        call s%check(res%x_final(3, 1) > 0.0_wp, 'drop, force end: the ball stays above the wall')
        call hertzdamp_sphere_mass(sc%radius(1), sc%mat(1)%density, m, st)
        zs = (m * norm2(sc%g) / res%contacts(res%ncontacts)%k)**(2.0_wp / 3.0_wp)
        call s%check_close(sc%radius(1) - res%x_final(3, 1), zs, 1.0e-3_wp, &
                           'drop, force end: static overlap (m g/k)^(2/3)')
    end subroutine drop_force_end

    subroutine chain_and_bed()
        type(hertzdamp_dem_scene) :: chain, bed
        type(hertzdamp_dem_result) :: res
        integer :: m_chain, m_bed, st, c
        real(wp) :: err(6), ee, et
        logical :: avail(6)

        call load('data/scenes/chain.nml', chain)
        m_chain = auto_method(chain)
        call hertzdamp_dem_run(chain, m_chain, 1.0e-4_wp, res)
        call s%check(res%status == HD_OK, 'chain: run succeeds')
        call s%check(res%ncontacts >= 10, 'chain: every ball is hit')
        call s%check(res%momentum_drift <= 1.0e-14_wp * res%momentum_scale, 'chain: momentum conserved to round-off')
        call s%check(res%energy_rise <= 1.0e-5_wp * res%energy0, 'chain: energy never increases (beyond 1/N^2)')
        call s%check(res%energy_final < res%energy0, 'chain: energy dissipated')
        call s%check(res%v_final(1, 11) > 0.5_wp .and. abs(res%v_final(1, 1)) < 0.2_wp, &
                     'chain: the last ball flies off, the striker nearly stops')

        call load('data/scenes/bed.nml', bed)
        m_bed = auto_method(bed)
        call hertzdamp_dem_run(bed, m_bed, 1.0e-4_wp, res)
        call s%check(res%status == HD_OK, 'bed: run succeeds')
        call s%check(size(bed%radius) >= 100, 'bed: at least 100 particles')
        call s%check(res%left_domain == 0, 'bed: no particle leaves the box')
        call s%check(all(res%x_final(3, :) > 0.0_wp .and. res%x_final(1, :) > 0.0_wp .and. &
                         res%x_final(1, :) < 0.05_wp .and. res%x_final(2, :) > 0.0_wp .and. &
                         res%x_final(2, :) < 0.05_wp), 'bed: all centres inside the walls')
        call s%check(res%at_rest, 'bed: comes to rest')
        call s%check(res%energy_rise <= 1.0e-10_wp * abs(res%energy0), 'bed: energy never increases')
        call s%check(res%energy_final < res%energy0, 'bed: energy dissipated')

        ! method choice: auto counts the error in e and in tau_c, as the report checks
        ! both.  The chain (e = 0.98) is within accuracy in e with first-order but not
        ! in tau_c (2e-3 against 1e-3: the report's T_c check failed); a nearly elastic
        ! chain (e = 0.995) takes first-order, cheaper than the damped bed (e = 0.5).
        call rule_errors(chain, HD_METHOD_FIRST_ORDER, ee, et)
        call s%check(ee <= chain%accuracy .and. et > chain%accuracy, &
                     'auto: first-order meets e but not tau_c for the chain (reference rk45)')
        call s%check(m_chain /= HD_METHOD_FIRST_ORDER, 'auto: chain (e = 0.98) does not pick first-order')
        call rule_errors(chain, m_chain, ee, et)
        call s%check(ee <= chain%accuracy .and. et <= chain%accuracy, 'auto: chain rule accurate in e and tau_c')
        call rule_errors(bed, m_bed, ee, et)
        call s%check(ee <= bed%accuracy .and. et <= bed%accuracy, 'auto: bed rule accurate in e and tau_c')
        chain%mat(:)%restitution = 0.995_wp
        m_chain = auto_method(chain)
        call s%check(m_chain == HD_METHOD_FIRST_ORDER, 'auto: nearly elastic chain (e = 0.995) picks first-order')
        call rule_errors(chain, m_chain, ee, et)
        call s%check(ee <= chain%accuracy .and. et <= chain%accuracy, 'auto: first-order accurate at e = 0.995')
        call s%check(findloc(hertzdamp_dem_cost_order, m_chain, dim=1) < &
                     findloc(hertzdamp_dem_cost_order, m_bed, dim=1), 'auto: elastic scene picks a cheaper rule')
        ! the first-order rule alone would not be accurate for the bed
        call hertzdamp_dem_select(bed, c, err, avail, st)
        call s%check(err(1) > bed%accuracy, 'auto: first-order misses the bed accuracy')
    end subroutine chain_and_bed

    !> Relative errors in e and tau_c of a rule at the first material's e, against the
    !> reference integrator at the rule's alpha (the scene's damping law).
    subroutine rule_errors(sc, method, ee, et)
        type(hertzdamp_dem_scene), intent(in) :: sc
        integer, intent(in) :: method
        real(wp), intent(out) :: ee, et
        real(wp) :: alpha, tau, e
        integer :: st
        type(hertzdamp_collision) :: r
        e = sc%mat(1)%restitution
        call hertzdamp_invert_alpha(e, sc%iend, alpha, tau, st, method=method, law=sc%law)
        r = hertzdamp_rk45_collide(alpha, sc%iend, law=sc%law)
        call s%check(st == HD_OK .and. r%status == HD_OK, 'rule and reference solve succeed')
        ee = abs(r%e - e) / e
        et = abs(r%tau_c - tau) / r%tau_c
    end subroutine rule_errors

    !> A scene file with the given text must fail with a message containing `want`.
    subroutine expect_invalid(text, want, label)
        character(len=*), intent(in) :: text, want, label
        type(hertzdamp_dem_scene) :: sc
        integer :: u, status
        character(len=:), allocatable :: msg
        character(len=*), parameter :: path = 'build/test_scene_invalid.nml'
        open (newunit=u, file=path, status='replace', action='write')
        write (u, '(a)') text
        close (u)
        call hertzdamp_scene_read(path, sc, status, msg)
        if (status == HD_OK) call hertzdamp_dem_check(sc, status, msg)
        call s%check(status /= HD_OK, label // ': rejected')
        call s%check(index(msg, want) > 0, label // ': message names "' // want // '" (got: ' // msg // ')')
        open (newunit=u, file=path, status='old')
        close (u, status='delete')
    end subroutine expect_invalid

    !> A &scene line (with one particle) reads, and its damping law is `law`.
    subroutine scene_law(text, law, label)
        character(len=*), intent(in) :: text, label
        integer, intent(in) :: law
        character(len=*), parameter :: nl = new_line('a')
        character(len=*), parameter :: path = 'build/test_scene_law.nml'
        type(hertzdamp_dem_scene) :: sc
        integer :: u, status
        character(len=:), allocatable :: msg
        open (newunit=u, file=path, status='replace', action='write')
        write (u, '(a)') text // nl // '&material name = ''s'', density = 7800, youngs_modulus = 2e11, ' // &
            'poisson_ratio = 0.3, restitution = 0.9 /' // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0,0 /'
        close (u)
        call hertzdamp_scene_read(path, sc, status, msg)
        if (status == HD_OK) call hertzdamp_dem_check(sc, status, msg)
        call s%check(status == HD_OK .and. sc%law == law, label // ' (' // msg // ')')
        open (newunit=u, file=path, status='old')
        close (u, status='delete')
    end subroutine scene_law

    !> A scene with 5000 comment lines and a line of exactly 1024 characters reads
    !> (the line buffer grows by doubling).
    subroutine long_file()
        character(len=*), parameter :: path = 'build/test_scene_long.nml'
        type(hertzdamp_dem_scene) :: sc
        integer :: u, k, status
        character(len=:), allocatable :: msg
        open (newunit=u, file=path, status='replace', action='write')
        do k = 1, 5000
            write (u, '(a,i0)') '! comment line ', k
        end do
        write (u, '(a)') '&scene dt = 1e-6, steps_per_contact = 10, end_time = 1e-4 /'
        write (u, '(a)') '&material name = ''s'', density = 7800, youngs_modulus = 2e11, poisson_ratio = 0.3, ' // &
            'restitution = 0.9 /'
        write (u, '(a)') '! ' // repeat('y', 1022)
        write (u, '(a)') '&particle material = ''s'', radius = 1e-3, position = 0,0,0 /'
        close (u)
        call hertzdamp_scene_read(path, sc, status, msg)
        call s%check(status == HD_OK, '5000 comment lines and a 1024-character line: read (' // msg // ')')
        if (status == HD_OK) call s%check(size(sc%radius) == 1 .and. sc%pline(1) == 5004, &
                                          'long file: the particle and its line number')
        open (newunit=u, file=path, status='old')
        close (u, status='delete')
    end subroutine long_file

    subroutine invalid_scenes()
        character(len=*), parameter :: nl = new_line('a')
        character(len=*), parameter :: head = '&scene dt = 1e-6, steps_per_contact = 10, end_time = 1e-4 /' // nl // &
            '&material name = ''s'', density = 7800, youngs_modulus = 2e11, poisson_ratio = 0.3, restitution = 0.9 /'
        call expect_invalid(head // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0,0, colour = 1 /', &
                            'line 3', 'unknown key')
        call expect_invalid(head // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0,0,' // nl // &
                            '  velocty = 1,0,0 /', 'line 4', 'unknown key on a continuation line')
        call expect_invalid(head // nl // '&particle material = ''s'', position = 0,0,0 /', 'radius missing', &
                            'missing radius')
        call expect_invalid(head // nl // '&particle material = ''s'', radius = -1e-3, position = 0,0,0 /', &
                            'radius must be positive', 'negative radius')
        call expect_invalid(head // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0,0 /' // nl // &
                            '&particle material = ''s'', radius = 1e-3, position = 1e-3,0,0 /', 'line 4', &
                            'overlapping particles')
        call expect_invalid(head // nl // '&particle material = ''t'', radius = 1e-3, position = 0,0,0 /', &
                            'unknown material', 'unknown material')
        call expect_invalid('&scene steps_per_contact = 10, end_time = 1e-4 /', 'dt missing', 'missing dt')
        call expect_invalid(head // nl // '&particles material = ''s'' /', 'unknown group', 'unknown group')
        call expect_invalid(head // nl // 'radius = 1', 'line 3', 'text outside a group')
        call expect_invalid(head // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0,0', &
                            'not closed', 'unterminated group')
        call expect_invalid(head, 'no &particle', 'no particles')
        call expect_invalid('&scene dt = abc, steps_per_contact = 10, end_time = 1e-4 /', &
                            'line 1: &scene: malformed value of dt', 'malformed value (not an unknown key)')
        call expect_invalid(head // nl // '&particle material = ''s'', radius = 1e-3x, position = 0,0,0 /', &
                            'line 3: &particle: malformed value of radius', 'value glued to a number')
        call expect_invalid(head // nl // '! ' // repeat('x', 1100) // nl // &
                            '&particle material = ''s'', radius = 1e-3, position = 0,0,0 /', &
                            'line 3: longer than 1024 characters', 'line too long')
        call expect_invalid(head // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0,0, ' // &
                            'velocity = 0,0,NaN /', 'line 3: &particle velocity must be finite', 'NaN velocity')
        call expect_invalid('&scene dt = 1e-6, steps_per_contact = 10, end_time = 1e-4 /' // nl // &
                            '&material name = ''s'', density = Inf, youngs_modulus = 2e11, poisson_ratio = 0.3, ' // &
                            'restitution = 0.9 /' // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0,0 /', &
                            'density must be finite', 'Inf density')
        call expect_invalid(head // nl // '&wall material = ''s'', point = 0,0,0, normal = 0,0,1 /' // nl // &
                            '&particle material = ''s'', radius = 1e-3, position = 0,0,5e-4 /', 'overlaps the wall', &
                            'particle in the wall')
        ! the damping law: a name of the family, and the pairs' e within the law's range
        call expect_invalid('&scene dt = 1e-6, steps_per_contact = 10, end_time = 1e-4, damping = ''viscous'' /', &
                            'line 1: &scene: damping must be ''linear'', ''tsuji'' or ''kuwabara-kono'' (got ''viscous'')', &
                            'unknown damping law')
        call expect_invalid('&scene dt = 1e-6, steps_per_contact = 10, end_time = 1e-4, damping = 1 /', &
                            'line 1: &scene: damping must be', 'damping law a number')
        call expect_invalid('&scene dt = 1e-6, steps_per_contact = 10, end_time = 1e-4, damping = ''tsuji'' /' // nl // &
                            '&material name = ''s'', density = 7800, youngs_modulus = 2e11, poisson_ratio = 0.3, ' // &
                            'restitution = 5e-5 /' // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0,0, ' // &
                            'count = 2, spacing = 3e-3,0,0 /', &
                            'restitution: the pair''s e = sqrt(e_a e_b) = 5.0e-5 is below 1.0e-4, the smallest e of the ' // &
                            'damping law ''tsuji''', 'restitution below the tsuji range')
        call scene_law('&scene dt = 1e-6, steps_per_contact = 10, end_time = 1e-4, damping = ''Kuwabara-Kono'' /', &
                       HD_DAMPING_KUWABARA_KONO, 'damping name in capitals')
        call scene_law('&scene dt = 1e-6, steps_per_contact = 10, end_time = 1e-4 /', HD_DAMPING_LINEAR, &
                       'no damping key: linear')
    end subroutine invalid_scenes

    !> Scenes the engine cannot compute are refused at load with a message naming
    !> the key (issue 17): masses that overflow or underflow, energies that overflow,
    !> a modulus that makes the contact time overflow a step count, trace buffers
    !> beyond memory; and no value a file gives is taken for a missing key.
    subroutine unrepresentable_scenes()
        character(len=*), parameter :: nl = new_line('a')
        character(len=*), parameter :: scene = '&scene dt = 1e-6, steps_per_contact = 10, end_time = 1e-4 /'
        character(len=*), parameter :: steel = '&material name = ''s'', density = 7800, youngs_modulus = 2e11, ' // &
                                               'poisson_ratio = 0.3, restitution = 0.9 /'
        character(len=*), parameter :: head = scene // nl // steel
        character(len=*), parameter :: two = '&particle material = ''s'', radius = 1e-3, position = -2e-3,0,0, ' // &
            'velocity = 1,0,0 /' // nl // '&particle material = ''s'', radius = 1e-3, position = 2e-3,0,0, ' // &
            'velocity = -1,0,0 /'
        ! masses: radius 1e200 overflows, 2.2e-308 underflows, 1e100 gives a finite mass
        ! whose pair product overflows (today: exit 4 at the first contact)
        call expect_invalid(head // nl // '&particle material = ''s'', radius = 1e200, position = 0,0,0 /', &
                            'line 3: &particle radius: the mass', 'radius 1e200 (mass overflows)')
        call expect_invalid(head // nl // '&particle material = ''s'', radius = 2.2e-308, position = 0,0,0 /', &
                            'line 3: &particle radius: the mass', 'radius 2.2e-308 (mass underflows)')
        call expect_invalid(head // nl // '&particle material = ''s'', radius = 1e100, position = 0,0,0 /' // nl // &
                            '&particle material = ''s'', radius = 1e100, position = 3e100,0,0, velocity = -1,0,0 /', &
                            'line 3: &particle radius: the mass', 'radius 1e100 (mass product overflows)')
        ! energies: a speed of 1e200 overflows 1/2 m v^2; 1e100 is finite but its energy is not
        call expect_invalid(head // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0,0, ' // &
                            'velocity = 1e200,0,0 /', 'line 3: &particle velocity must be at most', 'velocity 1e200')
        call expect_invalid(head // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0,0, ' // &
                            'velocity = 1e80,0,0 /', 'line 3: &particle velocity: the kinetic energy scale', &
                            'velocity 1e80 (energy overflows)')
        call expect_invalid('&scene dt = 1e-6, steps_per_contact = 10, end_time = 1e-4, gravity = .true., ' // &
                            'g = 0,0,-1e200 /' // nl // steel // nl // &
                            '&particle material = ''s'', radius = 1e-3, position = 0,0,0 /', 'g must be at most', 'g 1e200')
        ! moduli: 1e-300 (the contact time 1.8e119 s overflowed the step count of the
        ! report) and 1e-100 (within the window, but 1e47 steps per contact)
        call expect_invalid(scene // nl // '&material name = ''s'', density = 7800, youngs_modulus = 1e-300, ' // &
                            'poisson_ratio = 0.3, restitution = 0.9 /' // nl // two, 'youngs_modulus must lie within', &
                            'youngs_modulus 1e-300')
        call expect_invalid(scene // nl // '&material name = ''s'', density = 7800, youngs_modulus = 1e-100, ' // &
                            'poisson_ratio = 0.3, restitution = 0.9 /' // nl // two, &
                            'youngs_modulus: the physical contact time at rest_speed', 'youngs_modulus 1e-100')
        ! restitution only (k = k_phys at every contact): a contact far shorter than one
        ! step (a density of 1e-50, a modulus of 1e100) made the run overflow at once
        call expect_invalid('&scene dt = 1e-7, end_time = 1e-5, report = ''restitution'' /' // nl // &
                            '&material name = ''s'', density = 1e-50, youngs_modulus = 2e11, poisson_ratio = 0.3, ' // &
                            'restitution = 0.9 /' // nl // two, 'dt: the shortest physical contact', 'density 1e-50')
        call expect_invalid('&scene dt = 1e-7, end_time = 1e-5, report = ''restitution'' /' // nl // &
                            '&material name = ''s'', density = 7800, youngs_modulus = 1e100, poisson_ratio = 0.3, ' // &
                            'restitution = 0.9 /' // nl // two, 'dt: the shortest physical contact', 'youngs_modulus 1e100')
        ! one step of dt = 1e50 s (end_time 5e-5): the travel of that step counts
        call expect_invalid('&scene dt = 1e50, steps_per_contact = 10, end_time = 5e-5 /' // nl // steel // nl // &
                            '&particle material = ''s'', radius = 1e-3, position = 0,0,0, velocity = 1e120,0,0 /', &
                            'the distance travelled in the run', 'one huge step')
        ! trace buffers: samples = 2147483647 (today: dies allocating 32 GB), and the
        ! product with the traced particles
        call expect_invalid('&scene dt = 1e-6, steps_per_contact = 10, end_time = 20, samples = 2147483647 /' // nl // &
                            steel // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0,0, count = 200, ' // &
                            'spacing = 0.01,0,0 /', '&scene: samples must be at most 1000000', 'samples 2147483647')
        call expect_invalid('&scene dt = 1e-6, steps_per_contact = 10, end_time = 20, samples = 100000 /' // nl // &
                            steel // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0,0, count = 200, ' // &
                            'spacing = 0.01,0,0 /', 'for a trace of 200 particles', 'samples x traced particles')
        ! no collision with the missing-key marker: -8.99e307 and -huge are given values
        call expect_invalid(head // nl // '&particle material = ''s'', radius = 1e-3, position = -9e307,0,0 /', &
                            'line 3: &particle position must lie within', 'coordinate -9e307 is not missing')
        call expect_invalid(head // nl // '&particle material = ''s'', radius = 1e-3, ' // &
                            'position = -1.7976931348623157e308,0,0 /', 'line 3: &particle position must lie within', &
                            'coordinate -huge is not missing')
        call expect_invalid('&scene dt = -1.7976931348623157e308, steps_per_contact = 10, end_time = 1 /' // nl // &
                            steel // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0,0 /', &
                            'dt must be positive', 'dt = -huge is not missing')
        call expect_invalid('&scene dt = 1e-6, steps_per_contact = -2147483647, end_time = 1e-4 /' // nl // &
                            steel // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0,0 /', &
                            'steps_per_contact must be at least 1', 'steps_per_contact = -huge(1) is not missing')
        call expect_invalid(head // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0 /', &
                            'position missing', 'two coordinates: the third is missing')
        call expect_invalid(scene // nl // '&material name = ''s'', density = 7800, youngs_modulus = 2e11, ' // &
                            'restitution = 0.9 /' // nl // '&particle material = ''s'', radius = 1e-3, position = 0,0,0 /', &
                            'poisson_ratio missing', 'missing key still found')
    end subroutine unrepresentable_scenes

    !> Two centres that meet exactly at a step point: the contact normal is defined
    !> (the direction between the centres at the start of the step, +x here), the
    !> run ends normally and no result is NaN or Inf, in every build.
    subroutine coincident_centres()
        character(len=*), parameter :: nl = new_line('a')
        character(len=*), parameter :: path = 'build/test_scene_coincident.nml'
        type(hertzdamp_dem_scene) :: sc
        type(hertzdamp_dem_result) :: res
        integer :: u, status, c
        character(len=:), allocatable :: msg
        logical :: finite_all
        open (newunit=u, file=path, status='replace', action='write')
        write (u, '(a)') '&scene dt = 1e-6, steps_per_contact = 10, end_time = 3e-6 /' // nl // &
            '&material name = ''s'', density = 7800, youngs_modulus = 2e11, poisson_ratio = 0.3, restitution = 0.9 /' &
            // nl // '&particle material = ''s'', radius = 1e-3, position = -0.5,0,0, velocity = 5e5,0,0 /' // nl // &
            '&particle material = ''s'', radius = 1e-3, position = 0.5,0,0, velocity = -5e5,0,0 /'
        close (u)
        call hertzdamp_scene_read(path, sc, status, msg)
        if (status == HD_OK) call hertzdamp_dem_check(sc, status, msg)
        call s%check(status == HD_OK, 'coincident centres: scene valid (' // msg // ')')
        open (newunit=u, file=path, status='old')
        close (u, status='delete')
        if (status /= HD_OK) return
        call hertzdamp_dem_run(sc, HD_METHOD_ITERATIVE, 1.0e-8_wp, res)
        call s%check(res%status == HD_OK, 'coincident centres: the run ends normally (' // res%message // ')')
        call s%check(res%ncontacts >= 1, 'coincident centres: a contact starts')
        if (res%ncontacts < 1) return
        call s%check(all(abs(res%contacts(1)%n_last - [1.0_wp, 0.0_wp, 0.0_wp]) <= 0.0_wp), &
                     'coincident centres: normal at onset is the start-of-step direction +x')
        finite_all = all(ieee_is_finite(res%x_final)) .and. all(ieee_is_finite(res%v_final)) .and. &
                     ieee_is_finite(res%energy_final) .and. ieee_is_finite(res%energy_rise) .and. &
                     ieee_is_finite(res%momentum_drift)
        do c = 1, res%ncontacts
            associate (ct => res%contacts(c))
                finite_all = finite_all .and. ieee_is_finite(ct%u_in) .and. ieee_is_finite(ct%u_out) .and. &
                             ieee_is_finite(ct%k) .and. ieee_is_finite(ct%d) .and. ieee_is_finite(ct%t_end) .and. &
                             all(ieee_is_finite(ct%n_last)) .and. ieee_is_finite(ct%f_last)
            end associate
        end do
        call s%check(finite_all, 'coincident centres: every result finite')
        call s%check(res%momentum_drift <= 1.0e-12_wp * res%momentum_scale, 'coincident centres: momentum conserved')
    end subroutine coincident_centres

    !> The report's checks agree with the choice of the rule and with the physics
    !> (issue 17): a restitution-only scene of nearly elastic binary collisions
    !> (e = 0.98) passes every check with the rule auto picks, and first-order, which
    !> auto used to pick on the e error alone, fails the T_c check; elastic contacts
    !> (e = 1) pass the energy check; an unresolved contact (N = 2) fails; no check of
    !> any of these runs has a non-finite value or bound.
    subroutine checks_agree()
        type(hertzdamp_dem_scene) :: sc
        type(hertzdamp_dem_result) :: res
        type(hertzdamp_dem_check_row), allocatable :: rows(:)
        integer :: nfail, m, k
        call load('data/scenes/binary.nml', sc)
        sc%want_duration = .false.
        sc%dt = 1.0e-8_wp
        sc%accuracy = 1.0e-3_wp
        sc%mat(:)%restitution = 0.98_wp
        m = auto_method(sc)
        call hertzdamp_dem_run(sc, m, 1.0e-8_wp, res)
        call hertzdamp_dem_checks_of(sc, res, rows, nfail)
        call s%check(res%status == HD_OK .and. nfail == 0, 'checks: restitution only, e = 0.98: auto passes every check')
        call s%check(count(index(rows%name, 'max_tc_rel_err') == 1 .and. rows%outcome /= HD_CHECK_FAIL) == 1, &
                     'checks: restitution only, e = 0.98: the T_c check is made')
        call s%check(all_finite(rows), 'checks: finite values and bounds (e = 0.98)')
        call hertzdamp_dem_run(sc, HD_METHOD_FIRST_ORDER, 1.0e-8_wp, res)
        call hertzdamp_dem_checks_of(sc, res, rows, nfail)
        call s%check(count(index(rows%name, 'max_tc_rel_err') == 1 .and. rows%outcome == HD_CHECK_FAIL) == 1, &
                     'checks: first-order at e = 0.98 fails the T_c check (so auto must not pick it)')

        call load('data/scenes/binary.nml', sc)
        sc%mat(:)%restitution = 1.0_wp
        do k = 10, 40, 30
            sc%steps_per_contact = k
            sc%dt = 1.0e-5_wp / k
            call hertzdamp_dem_run(sc, auto_method(sc), 1.0e-8_wp, res)
            call hertzdamp_dem_checks_of(sc, res, rows, nfail)
            call s%check(res%status == HD_OK .and. nfail == 0, 'checks: elastic contacts (e = 1) pass every check')
            call s%check(res%energy_rise / res%energy0 > 0.5_wp * hertzdamp_dem_verlet_energy() / k**2, &
                         'checks: elastic contacts show the Verlet energy swing (> c_V/(2 N^2)): the bound is not idle')
            call s%check(all_finite(rows), 'checks: finite values and bounds (e = 1)')
        end do

        call load('data/scenes/binary.nml', sc)
        sc%steps_per_contact = 2
        sc%dt = 1.0e-5_wp / 2
        call hertzdamp_dem_run(sc, auto_method(sc), 1.0e-8_wp, res)
        call hertzdamp_dem_checks_of(sc, res, rows, nfail)
        call s%check(nfail >= 1 .and. count(rows%name == 'min_steps_per_contact' .and. rows%outcome == HD_CHECK_FAIL) == 1, &
                     'checks: N = 2 steps per contact fails the resolution check')
        call s%check(all_finite(rows), 'checks: finite values and bounds (N = 2)')
    end subroutine checks_agree

    !> Force end with e = 0.9: a slow contact under the physical bound (glass, 1e-2 m/s)
    !> whose release step jumps over both the force zero and the overlap zero ends at
    !> the force zero, so its duration meets the bound (it was the overlap zero: 5 %
    !> too long at N = 10, 20 and 40 alike).
    subroutine force_end_jump()
        type(hertzdamp_dem_scene) :: sc
        type(hertzdamp_dem_result) :: res
        type(hertzdamp_dem_check_row), allocatable :: rows(:)
        integer :: nfail, k
        real(wp) :: et(3)
        character(len=8) :: lab
        call load('data/scenes/binary.nml', sc)
        sc%iend = HD_END_FORCE
        sc%mat(:)%restitution = 0.9_wp
        do k = 1, 3
            sc%steps_per_contact = 10 * 2**(k - 1)
            sc%dt = 1.0e-5_wp / sc%steps_per_contact
            write (lab, '(a,i0)') 'N = ', sc%steps_per_contact
            call hertzdamp_dem_run(sc, HD_METHOD_ITERATIVE, 1.0e-8_wp, res)
            call hertzdamp_dem_checks_of(sc, res, rows, nfail)
            call s%check(res%status == HD_OK .and. nfail == 0, 'force end, e = 0.9, ' // trim(lab) // ': every check passes')
            et(k) = maxval(abs(res%contacts%t_end - res%contacts%t_start - res%contacts%tc_target) / res%contacts%tc_target)
            call s%check(et(k) <= sc%accuracy + 2.0_wp / sc%steps_per_contact**2, &
                         'force end, e = 0.9, ' // trim(lab) // ': every T_c within accuracy + 2/N^2')
        end do
        call s%check(et(3) < et(1) / 4.0_wp, 'force end, e = 0.9: the T_c error falls with N')
    end subroutine force_end_jump

    !> A run made in pieces (hertzdamp_dem_start, _advance 7 steps at a time, _finish)
    !> is the same run, bit for bit: the state type holds everything a step needs (the
    !> per-contact k, d, state, last overlap, force and normal keyed by the pair), as a
    !> host must keep across neighbour-list rebuilds and restarts.
    subroutine run_in_pieces()
        type(hertzdamp_dem_scene) :: sc
        type(hertzdamp_dem_result) :: whole, pieces
        type(hertzdamp_dem_state) :: st
        integer :: m
        call load('data/scenes/bed.nml', sc)
        sc%iend = HD_END_FORCE
        sc%end_time = 0.1_wp
        m = auto_method(sc)
        call hertzdamp_dem_run(sc, m, 1.0e-8_wp, whole)
        call hertzdamp_dem_start(sc, m, 1.0e-8_wp, st, pieces)
        do while (hertzdamp_dem_steps_done(st) < hertzdamp_dem_steps_total(st))
            call hertzdamp_dem_advance(sc, st, pieces, 7)
        end do
        call hertzdamp_dem_finish(sc, st, pieces)
        call s%check(whole%status == HD_OK .and. pieces%status == HD_OK .and. whole%ncontacts > 100, &
                     'pieces: both runs succeed with contacts')
        call s%check(whole%ncontacts == pieces%ncontacts .and. whole%steps == pieces%steps, &
                     'pieces: same contacts and steps')
        if (whole%ncontacts /= pieces%ncontacts) return
        call s%check(all(whole%x_final == pieces%x_final) .and. all(whole%v_final == pieces%v_final) .and. &
                     all(whole%contacts%k == pieces%contacts%k) .and. all(whole%contacts%d == pieces%contacts%d) .and. &
                     all(whole%contacts%t_end == pieces%contacts%t_end) .and. &
                     whole%energy_rise == pieces%energy_rise .and. all(whole%x_trace == pieces%x_trace), &
                     'pieces: bit-identical to the run in one call (bed, force end)')
    end subroutine run_in_pieces

    logical function all_finite(rows)
        type(hertzdamp_dem_check_row), intent(in) :: rows(:)
        all_finite = all(ieee_is_finite(rows%value)) .and. all(ieee_is_finite(rows%bound))
    end function all_finite

    !> c_V of the energy bound (the swing of the velocity Verlet energy inside an
    !> undamped Hertz contact, from the modified energy) against a direct integration:
    !> z'' = -z^(3/2) (m = k = u = 1) with plain velocity Verlet at N = 160 steps per
    !> contact, largest swing of 1/2 v^2 + 2/5 z^(5/2) over 20 touch phases, times N^2.
    subroutine verlet_energy_swing()
        integer, parameter :: n = 160
        real(wp) :: h, z, v, a, en, emin, emax, swing
        integer :: ip, k
        h = hertzdamp_tau_c0() / n
        swing = 0.0_wp
        do ip = 0, 19
            z = -ip / 20.0_wp * h
            v = 1.0_wp
            a = 0.0_wp
            emin = 0.5_wp
            emax = 0.5_wp
            do k = 1, 4 * n
                v = v + 0.5_wp * h * a
                z = z + h * v
                a = -max(z, 0.0_wp)**1.5_wp
                v = v + 0.5_wp * h * a
                en = 0.5_wp * v**2 + 0.4_wp * max(z, 0.0_wp)**2.5_wp
                emin = min(emin, en)
                emax = max(emax, en)
                if (z < 0.0_wp .and. v < 0.0_wp) exit
            end do
            swing = max(swing, (emax - emin) / 0.5_wp * n**2)
        end do
        call s%check_close(swing, hertzdamp_dem_verlet_energy(), 2.0e-3_wp, &
                           'c_V = tau_c0^2 (5/4)^(1/5) (f(x0) + 5/48) matches velocity Verlet at N = 160')
    end subroutine verlet_energy_swing

end program test_scene
