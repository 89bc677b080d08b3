!> The command `scene`: run a DEM scene file with the inverse rule at every contact,
!> report the achieved restitution and contact time against the targets, the
!> energy/momentum checks, the cost, and the same scene with the iterative rule.
!> The damping law is the scene's `damping` key, or --damping (which overrides it).
!> A scene whose checks fail prints its report and exits with EXIT_CHECKS (5).
module hertzdamp_cmd_scene
    use hertzdamp, only: hertzdamp_rk, hertzdamp_end_name, HD_OK, HD_METHOD_ITERATIVE, HD_METHOD_SERIES, &
                         HD_METHOD_PADE, HD_METHOD_COMPACT, HD_METHOD_FIT, HD_METHOD_FIRST_ORDER, hertzdamp_method_name, &
                         hertzdamp_law_code, hertzdamp_law_name, HD_HOST_NONE, HD_HOST_VERLET, hertzdamp_host_name, &
                         hertzdamp_pair_t, hertzdamp_pair_init, HD_HOST_UNREACHABLE, HD_BAD_STEPS, hertzdamp_message, &
                         hertzdamp_host_steps_min, hertzdamp_host_steps_max, hertzdamp_host_choices, hertzdamp_host_code
    use hertzdamp_dem, only: hertzdamp_dem_scene, hertzdamp_dem_result, hertzdamp_dem_check, hertzdamp_dem_state, &
                             hertzdamp_dem_start, hertzdamp_dem_advance, hertzdamp_dem_finish, hertzdamp_dem_steps_done, &
                             hertzdamp_dem_steps_total, hertzdamp_dem_rule, hertzdamp_dem_host_rule, hertzdamp_dem_select, &
                             hertzdamp_dem_cost_order, hertzdamp_dem_check_row, hertzdamp_dem_checks_of, &
                             hertzdamp_dem_ratio, hertzdamp_dem_verlet_energy, hertzdamp_dem_min_resolved, &
                             hertzdamp_dem_supports, HD_CHECK_PASS, HD_CHECK_FAIL, HD_CHECK_GRAVITY
    use hertzdamp_dem_io, only: hertzdamp_scene_read
    use hertzdamp_cli, only: cli_args, cli_buffer, parse_args, parse_choice, parse_real, fail, quit, fmt_csv, &
                             EXIT_USAGE, EXIT_OK, EXIT_FAILURE, EXIT_NO_SOLUTION
    use hertzdamp_cli_output, only: out_table, format_choices, FORMAT_JSON, FORMAT_CSV, FORMAT_TEXT
    use hertzdamp_cli_help, only: print_help, wants_help
    use hertzdamp_cli_model, only: parse_law, damping_unit, law_text
    use hertzdamp_cli_plot, only: plot_check_target, plot_scratch, plot_temp_name, gp_string
    use hertzdamp_cli_text, only: itoa, fmt_text_short, fmt_short
    use hertzdamp_cli_progress, only: progress_reporter
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    private
    public :: cmd_scene

    integer, parameter :: wp = hertzdamp_rk
    !> Exit code of a scene whose report was printed but whose checks failed.
    integer, parameter :: EXIT_CHECKS = 5
    !> --method choices; 'auto' first.
    character(len=*), parameter :: method_choices = 'auto first-order compact series pade fit iterative'
    !> Most contact rows printed.
    integer, parameter :: max_rows = 200
    !> Most particles drawn by --plot.
    integer, parameter :: max_plot_lines = 20

    !> Cost of one run.
    type :: run_cost
        real(wp) :: total = 0.0_wp     !! wall time of the run [s]
        real(wp) :: params = 0.0_wp    !! time in the contact rule [s]
    end type run_cost

contains

    subroutine cmd_scene()
        type(cli_args) :: args
        type(hertzdamp_dem_scene) :: sc
        type(hertzdamp_dem_result) :: res, res_it
        type(run_cost) :: cost, cost_it
        type(cli_buffer) :: buf
        logical :: progress
        type(hertzdamp_dem_check_row), allocatable :: rows(:)
        character(len=:), allocatable :: file, msg, plot, reason, terminal, failed_names
        integer :: fmt, mchoice, method, status, chosen, c, nsec, nfailed, nruns, law, host
        real(wp) :: err(6), tol_it, t_select
        logical :: avail(6), compare
        integer(int64) :: c0, c1, rate
        character(len=16) :: nbuf

        if (wants_help()) then
            call print_help('scene')
            call quit(EXIT_OK)
        end if
        call parse_args(2, '--method --format --plot --damping --host --dt --steps', '--progress --no-compare --onset-phase', &
                        args, &
                        allow_positional=.true.)
        if (.not. allocated(args%positional)) call fail(EXIT_USAGE, 'scene needs a FILE (see hertzdamp scene --help)')
        file = args%positional
        mchoice = parse_choice(args%get('--method', 'auto'), method_choices, 'method (--method)')
        fmt = parse_choice(args%get('--format', 'text'), format_choices, 'format (--format)')
        plot = args%get('--plot', '')
        law = -1
        if (args%has('--damping')) then
            law = parse_law(args%get('--damping', ''), '--damping')
        end if
        compare = .not. args%has('--no-compare')
        if (args%has('--plot')) call plot_check_target(plot, terminal, [file])
        host = HD_HOST_NONE
        if (args%has('--host')) then
            ! the hosts whose scheme the engine integrates with
            c = parse_choice(args%get('--host', ''), hertzdamp_host_choices(engine_only=.true.), 'host scheme (--host)')
            host = hertzdamp_host_code(args%get('--host', ''))
            if (.not. (args%has('--dt') .and. args%has('--steps'))) then
                call fail(EXIT_USAGE, '--host needs --dt and --steps (the time step of the host and the steps per ' // &
                          'contact N it integrates with, T_c = N dt)')
            end if
            if (host /= HD_HOST_NONE .and. mchoice /= 1 .and. mchoice /= 6) then
                call fail(EXIT_USAGE, '--host ' // hertzdamp_host_name(host) // ': the host-exact constants come ' // &
                          'from the fit; --method applies to --host none')
            end if
        end if

        if (args%has('--onset-phase') .and. host == HD_HOST_NONE) then
            call fail(EXIT_USAGE, '--onset-phase needs --host S (the per-contact constants of the onset phase are ' // &
                      'those of a host scheme)')
        end if

        call hertzdamp_scene_read(file, sc, status, msg)
        if (status /= HD_OK) call fail(EXIT_USAGE, file // ': ' // msg)
        sc%onset_phase = args%has('--onset-phase')
        if (law >= 0) sc%law = law   ! --damping overrides the file's damping key
        call scene_overrides(args, host, sc)
        if (host /= HD_HOST_NONE .and. .not. sc%want_duration) then
            call fail(EXIT_USAGE, '--host ' // hertzdamp_host_name(host) // ': the host-exact constants need the ' // &
                      'contact time T_c = N dt; the scene wants the restitution only (want_duration)')
        end if
        if (mchoice /= 1) then
            if (.not. hertzdamp_dem_supports(method_code(mchoice), sc%law)) then
                call fail(EXIT_USAGE, 'method ' // hertzdamp_method_name(method_code(mchoice)) // ' exists for the ' // &
                          'linear damping law only; with damping ' // hertzdamp_law_name(sc%law) // &
                          ' use --method auto, fit, iterative or first-order')
            end if
        end if
        call hertzdamp_dem_check(sc, status, msg)
        if (status /= HD_OK) call fail(EXIT_USAGE, file // ': ' // msg)

        call choose_method()
        tol_it = min(1.0e-2_wp, max(1.0e-10_wp, 0.1_wp * sc%accuracy))
        compare = compare .and. method /= HD_METHOD_ITERATIVE .and. host == HD_HOST_NONE
        nruns = merge(2, 1, compare)

        progress = args%has('--progress')
        call timed_run(sc, method, tol_it, res, cost, progress, run_label(1, nruns, method))
        if (res%status == HD_HOST_UNREACHABLE) call fail(EXIT_NO_SOLUTION, file // ': ' // res%message)
        if (res%status /= HD_OK) call fail(EXIT_FAILURE, file // ': ' // res%message)
        if (compare) then
            call timed_run(sc, HD_METHOD_ITERATIVE, tol_it, res_it, cost_it, progress, &
                           run_label(2, nruns, HD_METHOD_ITERATIVE))
            if (res_it%status /= HD_OK) call fail(EXIT_FAILURE, file // ' (iterative rule): ' // res_it%message)
        end if

        call hertzdamp_dem_checks_of(sc, res, rows, nfailed)
        nsec = 0
        if (fmt == FORMAT_JSON) call buf%add('{')
        call report_method(sc, file, method, reason, err, avail, t_select, fmt, buf, nsec)
        call report_contacts(sc, res, fmt, buf, nsec)
        call report_checks(sc, rows, fmt, buf, nsec)
        call report_cost(method, res, cost, res_it, cost_it, compare, host, fmt, buf, nsec)
        if (fmt == FORMAT_JSON) call buf%add('}')
        if (args%has('--plot')) call write_plot(sc, res, plot, terminal)
        call buf%flush_to_stdout()
        if (nfailed > 0) then
            failed_names = ''
            do c = 1, size(rows)
                if (rows(c)%outcome /= HD_CHECK_FAIL) cycle
                if (len(failed_names) > 0) failed_names = failed_names // ', '
                failed_names = failed_names // trim(rows(c)%name)
            end do
            write (nbuf, '(i0)') nfailed
            call fail(EXIT_CHECKS, file // ': ' // trim(nbuf) // ' check' // trim(merge('s ', '  ', nfailed > 1)) // &
                      ' failed (see the report): ' // failed_names)
        end if
        call quit(EXIT_OK)
    contains
        !> The method: the measured errors of every candidate at the scene's targets, then the
        !> host's fit, the cheapest that meets the accuracy (auto) or the one asked for.
        subroutine choose_method()
            call system_clock(c0, rate)
            call hertzdamp_dem_select(sc, chosen, err, avail, status)
            call system_clock(c1)
            t_select = real(c1 - c0, wp) / real(rate, wp)
            if (status /= HD_OK) call fail(EXIT_FAILURE, 'reference solver failed while choosing the method')
            if (host /= HD_HOST_NONE) then
                method = HD_METHOD_FIT
                reason = 'host ' // hertzdamp_host_name(host) // ': the per-pair constants of the fit for the host''s ' // &
                         'scheme at N = ' // itoa(sc%steps_per_contact) // ' (hertzdamp_pair_init)'
            else if (mchoice == 1) then
                if (chosen < 0) call fail(EXIT_NO_SOLUTION, 'no contact rule meets the accuracy ' // &
                                          trim(fmt_csv(sc%accuracy)) // ' of the scene')
                method = chosen
                c = findloc(hertzdamp_dem_cost_order, method, dim=1)
                reason = 'auto: cheapest rule (cost order first-order < compact < series < pade < fit < iterative) ' // &
                         'whose measured error in e and tau_c ' // number(err(c), fmt) // ' <= accuracy ' // &
                         number(sc%accuracy, fmt)
            else
                method = method_code(mchoice)
                c = findloc(hertzdamp_dem_cost_order, method, dim=1)
                if (.not. avail(c)) call fail(EXIT_USAGE, 'method ' // hertzdamp_method_name(method) // &
                                              ' is not available in this build of the library')
                reason = 'requested; measured error in e and tau_c ' // number(err(c), fmt)
            end if
        end subroutine choose_method
    end subroutine cmd_scene

    !> --dt and --steps override the scene file's dt and steps_per_contact (validated with
    !> the scene); --host sets the host whose per-pair constants give k and d and the
    !> scheme that integrates the contacts (none: the engine's own velocity Verlet with the
    !> rule of --method, today's run).
    subroutine scene_overrides(args, host, sc)
        type(cli_args), intent(in) :: args
        integer, intent(in) :: host
        type(hertzdamp_dem_scene), intent(inout) :: sc
        real(wp) :: x
        if (args%has('--dt')) then
            x = parse_real(args%get('--dt', ''), '--dt')
            if (.not. (x > 0.0_wp .and. x <= huge(x))) then
                call fail(EXIT_USAGE, '--dt ' // fmt_short(x) // ': the time step must be positive and finite')
            end if
            sc%dt = x
        end if
        if (args%has('--steps')) then
            x = parse_real(args%get('--steps', ''), '--steps')
            if (.not. (x >= 1.0_wp .and. x <= 1.0e9_wp .and. x == anint(x))) then
                call fail(EXIT_USAGE, '--steps ' // fmt_short(x) // ': time steps per contact must be ' // &
                          'a whole number from 1 to 1e9')
            end if
            sc%steps_per_contact = nint(x)
        end if
        sc%host = host
        sc%scheme = HD_HOST_VERLET
        if (host /= HD_HOST_NONE) sc%scheme = host
        ! a host's per-pair constants exist for its range of N: bad input, as invert says
        ! (issue 30, defect 8: this was a failed computation, exit 4)
        if (host /= HD_HOST_NONE .and. .not. (real(sc%steps_per_contact, wp) >= hertzdamp_host_steps_min .and. &
                                             real(sc%steps_per_contact, wp) <= hertzdamp_host_steps_max)) then
            if (args%has('--steps')) then
                call fail(EXIT_USAGE, '--steps ' // itoa(sc%steps_per_contact) // ' with --host ' // &
                          hertzdamp_host_name(host) // ': ' // hertzdamp_message(HD_BAD_STEPS))
            end if
            call fail(EXIT_USAGE, 'steps_per_contact = ' // itoa(sc%steps_per_contact) // ' of the scene with --host ' // &
                      hertzdamp_host_name(host) // ': ' // hertzdamp_message(HD_BAD_STEPS))
        end if
    end subroutine scene_overrides

    !> 'scene run 1 of 2 (compact)'
    function run_label(k, n, method) result(s)
        integer, intent(in) :: k, n, method
        character(len=:), allocatable :: s
        character(len=32) :: b
        write (b, '(a,i0,a,i0)') 'scene run ', k, ' of ', n
        s = trim(b) // ' (' // hertzdamp_method_name(method) // ')'
    end function run_label

    !> HD_* code of a --method choice other than auto.
    integer function method_code(k) result(m)
        integer, intent(in) :: k
        select case (k)
        case (2); m = HD_METHOD_FIRST_ORDER
        case (3); m = HD_METHOD_COMPACT
        case (4); m = HD_METHOD_SERIES
        case (5); m = HD_METHOD_PADE
        case (6); m = HD_METHOD_FIT
        case default; m = HD_METHOD_ITERATIVE
        end select
    end function method_code

    !> Run the scene and time it, in pieces so that the progress can be reported
    !> (hertzdamp_cli_progress: on a terminal after 2 s, or with --progress); the
    !> rule's share is timed by replaying the rule on the recorded contacts (the same
    !> e, N dt, m, u_in, k_phys), repeated until at least 20 ms have passed.
    subroutine timed_run(sc, method, tol, res, cost, progress, label)
        type(hertzdamp_dem_scene), intent(in) :: sc
        integer, intent(in) :: method
        real(wp), intent(in) :: tol
        type(hertzdamp_dem_result), intent(out) :: res
        type(run_cost), intent(out) :: cost
        logical, intent(in) :: progress   !! --progress given
        character(len=*), intent(in) :: label
        type(hertzdamp_dem_state) :: st
        type(progress_reporter) :: p
        integer(int64) :: c0, c1, rate
        integer :: reps, n, chunk, total, i, j
        type(hertzdamp_pair_t), allocatable :: pairs(:)
        real(wp), allocatable :: k(:), d(:), tce(:)
        logical, allocatable :: bound(:)
        integer, allocatable :: stat(:)
        call system_clock(c0, rate)
        call hertzdamp_dem_start(sc, method, tol, st, res)
        total = hertzdamp_dem_steps_total(st)
        chunk = max(1, min(20000, total / 200))
        call p%start(real(total, wp), label, force=progress)
        do while (hertzdamp_dem_steps_done(st) < total .and. res%status == HD_OK)
            call hertzdamp_dem_advance(sc, st, res, chunk)
            call p%update(real(hertzdamp_dem_steps_done(st), wp))
        end do
        call p%finish()
        call hertzdamp_dem_finish(sc, st, res)
        call system_clock(c1)
        cost%total = real(c1 - c0, wp) / real(rate, wp)
        if (res%status /= HD_OK) return
        n = res%ncontacts
        if (n == 0) return
        allocate (k(n), d(n), tce(n), bound(n), stat(n), pairs(n))
        reps = 0
        call system_clock(c0)
        if (sc%host /= HD_HOST_NONE) then
            ! the per-contact part of the host rule (hertzdamp_pair_kd); hertzdamp_pair_init
            ! runs once per material pair at the start of the run (in the total)
            do i = 1, n
                j = findloc(res%contacts(1:i - 1)%e_target, res%contacts(i)%e_target, dim=1)
                if (j > 0) then
                    pairs(i) = pairs(j)
                else
                    call hertzdamp_pair_init(res%contacts(i)%e_target, sc%law, sc%iend, sc%host, &
                                             real(sc%steps_per_contact, wp), pairs(i), stat(i))
                end if
            end do
        end if
        do
            if (sc%host /= HD_HOST_NONE) then
                call hertzdamp_dem_host_rule(pairs, sc%steps_per_contact * sc%dt, res%contacts%m, res%contacts%u_rule, &
                                             res%contacts%k_phys, k, d, tce, bound, stat)
            else
                call hertzdamp_dem_rule(res%contacts%e_target, sc%steps_per_contact * sc%dt, res%contacts%m, &
                                        res%contacts%u_rule, res%contacts%k_phys, sc%iend, sc%law, method, &
                                        sc%want_duration, tol, k, d, tce, bound, stat)
            end if
            reps = reps + 1
            call system_clock(c1)
            if (real(c1 - c0, wp) / real(rate, wp) > 0.02_wp .or. reps >= 100000) exit
        end do
        cost%params = real(c1 - c0, wp) / real(rate, wp) / reps
    end subroutine timed_run

    !> Render a table as one section: text and CSV one after the other (CSV with a
    !> `# name` line before its header), JSON as a member "name" of the top object.
    subroutine add_section(name, t, fmt, buf, nsec)
        character(len=*), intent(in) :: name
        type(out_table), intent(in) :: t
        integer, intent(in) :: fmt
        type(cli_buffer), intent(inout) :: buf
        integer, intent(inout) :: nsec
        type(cli_buffer) :: tmp
        integer :: i
        call t%render(fmt, tmp)
        nsec = nsec + 1
        select case (fmt)
        case (FORMAT_JSON)
            if (nsec > 1) buf%lines(buf%n)%s = buf%lines(buf%n)%s // ','
            call buf%add('  "' // name // '": {')
            do i = 2, tmp%n
                call buf%add('  ' // tmp%lines(i)%s)
            end do
        case (FORMAT_CSV)
            if (nsec > 1) call buf%add('')
            call buf%add('# ' // name)
            do i = 1, tmp%n
                call buf%add(tmp%lines(i)%s)
            end do
        case default
            if (nsec > 1) call buf%add('')
            do i = 1, tmp%n
                call buf%add(tmp%lines(i)%s)
            end do
        end select
    end subroutine add_section

    subroutine report_method(sc, file, method, reason, err, avail, t_select, fmt, buf, nsec)
        type(hertzdamp_dem_scene), intent(in) :: sc
        character(len=*), intent(in) :: file, reason
        integer, intent(in) :: method, fmt
        real(wp), intent(in) :: err(6), t_select
        logical, intent(in) :: avail(6)
        type(cli_buffer), intent(inout) :: buf
        integer, intent(inout) :: nsec
        type(out_table) :: t
        integer :: c
        character(len=16) :: b
        call t%set_columns('rank,method,available,max_error,meets_accuracy,used')
        call t%meta('scene', sc%title)
        call t%meta('file', file)
        write (b, '(i0)') size(sc%radius)
        call t%meta('particles', trim(b))
        write (b, '(i0)') size(sc%wall)
        call t%meta('walls', trim(b))
        call t%meta('contact_end', hertzdamp_end_name(sc%iend))
        call t%meta('damping', law_text(sc%law))
        if (sc%want_duration) then
            write (b, '(i0)') sc%steps_per_contact
            call t%meta('wanted', 'restitution and contact duration T_c = N dt, N = ' // trim(b) // ', T_c = ' // &
                        number(sc%steps_per_contact * sc%dt, fmt) // ' s (physical stiffness bound)')
        else
            call t%meta('wanted', 'restitution only (k = k_phys, contact duration physical)')
        end if
        call t%meta('accuracy', number(sc%accuracy, fmt))
        call t%meta('dt', number(sc%dt, fmt) // ' s')
        if (sc%host /= HD_HOST_NONE .or. sc%scheme /= HD_HOST_VERLET) then
            call t%meta('host', hertzdamp_host_name(sc%host) // ': contacts integrated by the scheme ' // &
                        hertzdamp_host_name(sc%scheme) // ' (doc/host-schemes.md)')
        end if
        call t%meta('method', hertzdamp_method_name(method))
        call t%meta('why', reason)
        call t%meta('selection_time', number(t_select, fmt) // ' s (one reference solve per candidate and target e)')
        do c = 1, 6
            write (b, '(i0)') c
            call t%str(trim(b))
            call t%str(hertzdamp_method_name(hertzdamp_dem_cost_order(c)))
            if (avail(c)) then
                call t%str('yes')
            else if (.not. hertzdamp_dem_supports(hertzdamp_dem_cost_order(c), sc%law)) then
                call t%str('no: linear law only')
            else
                call t%str('no')
            end if
            if (avail(c)) then
                call t%num(err(c))
                call t%str(trim(merge('yes', 'no ', err(c) <= sc%accuracy)))
            else
                call t%str('-')
                call t%str('-')
            end if
            call t%str(merge('*', '-', hertzdamp_dem_cost_order(c) == method))
        end do
        call add_section('method', t, fmt, buf, nsec)
    end subroutine report_method

    !> A number in a sentence of the report: the text output's short form for people,
    !> the CSV form (it reads back as the same double) in CSV and JSON.
    function number(x, fmt) result(s)
        real(wp), intent(in) :: x
        integer, intent(in) :: fmt   !! FORMAT_*
        character(len=:), allocatable :: s
        if (fmt == FORMAT_TEXT) then
            s = fmt_text_short(x)
        else
            s = trim(fmt_csv(x))
        end if
    end function number

    !> Name of the bodies of a contact: 'p3-p4' or 'p1-wall1'.
    function bodies(i, j) result(s)
        integer, intent(in) :: i, j
        character(len=:), allocatable :: s
        character(len=40) :: b
        if (j > 0) then
            write (b, '(a,i0,a,i0)') 'p', i, '-p', j
        else
            write (b, '(a,i0,a,i0)') 'p', i, '-wall', -j
        end if
        s = trim(b)
    end function bodies

    subroutine report_contacts(sc, res, fmt, buf, nsec)
        type(hertzdamp_dem_scene), intent(in) :: sc
        type(hertzdamp_dem_result), intent(in) :: res
        integer, intent(in) :: fmt
        type(cli_buffer), intent(inout) :: buf
        integer, intent(inout) :: nsec
        type(out_table) :: t
        integer :: c, nrow, nbin
        real(wp) :: e_ach, q
        logical :: ok
        character(len=64) :: b
        call t%set_columns('contact,bodies,u_in,k,d,stiffness,e_target,e,e_rel_err,tc_target,tc,tc_rel_err', &
                           ',,m/s,N m^-3/2,' // damping_unit(sc%law) // ',,,,,s,s,')
        nbin = count(res%contacts%binary .and. res%contacts%t_end >= 0.0_wp)
        write (b, '(i0,a,i0,a)') res%ncontacts, ' contacts, ', nbin, ' binary and ended'
        call t%meta('contacts', trim(b))
        call t%meta('units', 'u_in [m/s], k [N m^-3/2], d [' // damping_unit(sc%law) // '], tc [s]; e = separation/' // &
                    'impact normal speed (- where u_in <= 0)', &
                    text='in the column headers; e = separation/impact normal speed (- where u_in <= 0)')
        if (.not. sc%want_duration) call t%meta('tc_target', 'physical contact time t*(k_phys) tau_c(alpha)')
        if (sc%gravity) call t%meta('gravity', 'acts during contacts too: e and tc differ from the ' // &
                                    'targets by O(g tc / u_in)')
        nrow = 0
        do c = 1, res%ncontacts
            associate (ct => res%contacts(c))
                if (.not. (ct%binary .and. ct%t_end >= 0.0_wp)) cycle
                nrow = nrow + 1
                if (nrow > max_rows) cycle
                write (b, '(i0)') c
                call t%str(trim(b))
                call t%str(bodies(ct%i, ct%j))
                call t%num(ct%u_in)
                call t%num(ct%k)
                call t%num(ct%d)
                if (ct%bound_active) then
                    call t%str('physical')
                else
                    call t%str('rule')
                end if
                call t%num(ct%e_target)
                ok = ct%u_in > 0.0_wp
                if (ok) call hertzdamp_dem_ratio(ct%u_out, ct%u_in, e_ach, ok)
                if (ok) call hertzdamp_dem_ratio(abs(e_ach - ct%e_target), ct%e_target, q, ok)
                if (ok) then
                    call t%num(e_ach)
                    call t%num(q)
                else
                    call t%str('-')
                    call t%str('-')
                end if
                call t%num(ct%tc_target)
                call t%num(ct%t_end - ct%t_start)
                call hertzdamp_dem_ratio(abs(ct%t_end - ct%t_start - ct%tc_target), ct%tc_target, q, ok)
                if (ok) then
                    call t%num(q)
                else
                    call t%str('-')
                end if
            end associate
        end do
        if (nrow > max_rows) then
            write (b, '(i0,a,i0)') max_rows, ' of ', nrow
            call t%meta('rows_shown', trim(b))
        end if
        call add_section('contacts', t, fmt, buf, nsec)
    end subroutine report_contacts

    !> The checks computed by hertzdamp_dem_checks_of: value, bound, outcome.
    subroutine report_checks(sc, rows, fmt, buf, nsec)
        type(hertzdamp_dem_scene), intent(in) :: sc
        type(hertzdamp_dem_check_row), intent(in) :: rows(:)
        integer, intent(in) :: fmt
        type(cli_buffer), intent(inout) :: buf
        integer, intent(inout) :: nsec
        type(out_table) :: t
        integer :: i
        character(len=16) :: b1, b2
        call t%set_columns('check,value,bound,result')
        write (b1, '(f0.3)') hertzdamp_dem_verlet_energy()
        write (b2, '(i0)') nint(hertzdamp_dem_min_resolved)
        if (sc%host /= HD_HOST_NONE .or. sc%scheme /= HD_HOST_VERLET) then
            call t%meta('bounds', 'binary contacts that started at or above rest_speed, host ' // &
                        hertzdamp_host_name(sc%host) // ' (scheme ' // hertzdamp_host_name(sc%scheme) // '): e and ' // &
                        'tc within the accuracy plus the largest deviation of the host''s discrete collision from ' // &
                        'its mean over the onset phase (the means are the targets; +2.5e-3 for e and tc information ' // &
                        'only when the physical stiffness applies); the mean errors approach 0 as the contacts ' // &
                        'sample the phase; energy: information (the host schemes are first order or not symplectic)')
        else
            call t%meta('bounds', 'binary contacts that started at or above rest_speed: e and tc to the method ' // &
                        'accuracy plus the time-step error, velocity Verlet O(1/N^2) for N steps per contact ' // &
                        '(bound 2/N^2, N the fewest steps per contact in the run, at least ' // trim(b2) // &
                        '); energy: no rise above the velocity Verlet swing ' // trim(b1) // '/N^2 of the energy ' // &
                        'scale plus the gain the e bound allows, max(0, (e_max (1 + bound_e))^2 - 1)')
        end if
        do i = 1, size(rows)
            call t%str(trim(rows(i)%name))
            call t%num(rows(i)%value)
            if (rows(i)%has_bound) then
                call t%num(rows(i)%bound)
            else
                call t%str('-')
            end if
            select case (rows(i)%outcome)
            case (HD_CHECK_PASS); call t%str('pass')
            case (HD_CHECK_FAIL); call t%str('FAIL')
            case (HD_CHECK_GRAVITY); call t%str('info (gravity)')
            case default; call t%str('info')
            end select
        end do
        call add_section('checks', t, fmt, buf, nsec)
    end subroutine report_checks

    subroutine report_cost(method, res, cost, res_it, cost_it, compare, host, fmt, buf, nsec)
        integer, intent(in) :: method, fmt, host
        type(hertzdamp_dem_result), intent(in) :: res, res_it
        type(run_cost), intent(in) :: cost, cost_it
        logical, intent(in) :: compare
        type(cli_buffer), intent(inout) :: buf
        integer, intent(inout) :: nsec
        type(out_table) :: t
        if (compare .or. method == HD_METHOD_ITERATIVE) then
            call t%set_columns('rule,total_time_s,param_time_s,contacts,param_time_per_contact_s,speedup_total,' // &
                               'speedup_params')
        else
            call t%set_columns('rule,total_time_s,param_time_s,contacts,param_time_per_contact_s')
            if (host == HD_HOST_NONE) then
                call t%meta('compare', 'iterative re-run skipped (--no-compare): no speed-ups')
            else
                call t%meta('compare', 'iterative re-run skipped (--host ' // hertzdamp_host_name(host) // &
                            ': the iterative rule is the continuous model''s): no speed-ups')
            end if
        end if
        call t%meta('timing', 'total: wall time of the run; params: the rule replayed on the run''s contacts')
        if (method == HD_METHOD_ITERATIVE) then
            call line(hertzdamp_method_name(method), res, cost, cost)
        else if (compare) then
            call line(hertzdamp_method_name(method), res, cost, cost_it)
            call line('iterative', res_it, cost_it, cost_it)
        else
            call line(hertzdamp_method_name(method), res, cost)
        end if
        call add_section('cost', t, fmt, buf, nsec)

    contains

        subroutine line(name, r, cst, ref)
            character(len=*), intent(in) :: name
            type(hertzdamp_dem_result), intent(in) :: r
            type(run_cost), intent(in) :: cst
            type(run_cost), intent(in), optional :: ref   !! the iterative run (speed-ups against it)
            character(len=16) :: b
            call t%str(name)
            call t%num(cst%total)
            call t%num(cst%params)
            write (b, '(i0)') r%ncontacts
            call t%str(trim(b))
            call t%num(cst%params / max(1, r%ncontacts))
            if (present(ref)) then
                call speedup(ref%total, cst%total)
                call speedup(ref%params, cst%params)
            end if
        end subroutine line

        !> a/b, or '-' when the quotient is not a finite number (a zero time)
        subroutine speedup(a, b)
            real(wp), intent(in) :: a, b
            real(wp) :: q
            logical :: ok
            call hertzdamp_dem_ratio(a, b, q, ok)
            if (ok .and. b > 0.0_wp) then
                call t%num(q)
            else
                call t%str('-')
            end if
        end subroutine speedup

    end subroutine report_cost

    !> Positions and velocities along the trace axis against time, for up to
    !> max_plot_lines particles: data and script as scratch files (hertzdamp_cli_plot),
    !> drawn by gnuplot and renamed into place.
    subroutine write_plot(sc, res, plot, terminal)
        type(hertzdamp_dem_scene), intent(in) :: sc
        type(hertzdamp_dem_result), intent(in) :: res
        character(len=*), intent(in) :: plot      !! target PNG (checked by plot_check_target)
        character(len=*), intent(in) :: terminal  !! pngcairo or png
        type(plot_scratch) :: s
        character(len=:), allocatable :: dat, gp, ax, n
        character(len=:), allocatable :: line
        integer :: u, i, k, np, stride
        integer, allocatable :: pick(:)
        ax = 'xyz'(res%axis:res%axis)
        np = size(res%x_trace, 2)
        stride = max(1, (np + max_plot_lines - 1) / max_plot_lines)
        pick = [(i, i=1, np, stride)]
        call s%open('scene', 'dat', u, dat)
        allocate (character(len=16 * (2 * size(pick) + 1)) :: line)
        do k = 1, size(res%t_trace)
            write (line, '(*(es16.8))') res%t_trace(k), res%x_trace(k, pick), res%v_trace(k, pick)
            call s%write(u, line)
        end do
        call s%close(u)
        call s%open('scene', 'gp', u, gp)
        n = itoa(size(pick))
        call s%write(u, 'set terminal ' // terminal // ' size 1000,800 noenhanced')
        call s%write(u, 'set output ' // gp_string(plot_temp_name()))
        call s%write(u, 'set multiplot layout 2,1 title ' // gp_string(sc%title))
        call s%write(u, 'set key off')
        call s%write(u, 'set grid')
        call s%write(u, 'set xlabel "t [s]"')
        call s%write(u, 'set ylabel "' // ax // ' [m]"')
        call s%write(u, 'plot for [i=2:' // n // '+1] ' // gp_string(dat) // ' using 1:i with lines')
        call s%write(u, 'set ylabel "v_' // ax // ' [m/s]"')
        call s%write(u, 'plot for [i=' // n // '+2:2*' // n // '+1] ' // gp_string(dat) // ' using 1:i with lines')
        call s%write(u, 'unset multiplot')
        call s%write(u, 'set output')
        call s%close(u)
        call s%draw(gp, plot)
    end subroutine write_plot

end module hertzdamp_cmd_scene
