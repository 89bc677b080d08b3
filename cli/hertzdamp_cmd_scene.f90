!> The command `scene`: run a DEM scene file with the inverse rule at every contact,
!> report the achieved restitution and contact time against the targets, the
!> energy/momentum checks, the cost, and the same scene with the iterative rule.
module hertzdamp_cmd_scene
    use hertzdamp, only: hertzdamp_rk, hertzdamp_end_name, HD_OK, HD_METHOD_ITERATIVE, HD_METHOD_SERIES, &
                         HD_METHOD_PADE, HD_METHOD_COMPACT, HD_METHOD_FIT, HD_METHOD_FIRST_ORDER, hertzdamp_method_name
    use hertzdamp_dem, only: hertzdamp_dem_scene, hertzdamp_dem_result, hertzdamp_dem_check, hertzdamp_dem_run, &
                             hertzdamp_dem_rule, hertzdamp_dem_select, hertzdamp_dem_cost_order
    use hertzdamp_scene_io, only: hertzdamp_scene_read
    use hertzdamp_cli, only: cli_args, cli_buffer, parse_args, parse_choice, fail, quit, fmt_csv, &
                             EXIT_USAGE, EXIT_OK, EXIT_FAILURE, EXIT_NO_SOLUTION
    use hertzdamp_cli_output, only: out_table, format_choices, FORMAT_JSON, FORMAT_CSV
    use hertzdamp_cli_help, only: print_help, wants_help
    use hertzdamp_cli_plot, only: plot_check_target, plot_run, plot_temp_name, gp_string
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    private
    public :: cmd_scene

    integer, parameter :: wp = hertzdamp_rk
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
        character(len=:), allocatable :: file, msg, plot, reason, terminal
        integer :: fmt, mchoice, method, status, chosen, c, nsec
        real(wp) :: err(6), tol_it, t_select
        logical :: avail(6)
        integer(int64) :: c0, c1, rate

        if (wants_help()) then
            call print_help('scene')
            call quit(EXIT_OK)
        end if
        call parse_args(2, '--method --format --plot', '', args, allow_positional=.true.)
        if (.not. allocated(args%positional)) call fail(EXIT_USAGE, 'scene needs a FILE (see hertzdamp scene --help)')
        file = args%positional
        mchoice = parse_choice(args%get('--method', 'auto'), method_choices, 'method (--method)')
        fmt = parse_choice(args%get('--format', 'text'), format_choices, 'format (--format)')
        plot = args%get('--plot', '')
        if (args%has('--plot')) call plot_check_target(plot, terminal)

        call hertzdamp_scene_read(file, sc, status, msg)
        if (status /= HD_OK) call fail(EXIT_USAGE, file // ': ' // msg)
        call hertzdamp_dem_check(sc, status, msg)
        if (status /= HD_OK) call fail(EXIT_USAGE, file // ': ' // msg)

        ! method: measured errors of every candidate at the scene's targets
        call system_clock(c0, rate)
        call hertzdamp_dem_select(sc, chosen, err, avail, status)
        call system_clock(c1)
        t_select = real(c1 - c0, wp) / real(rate, wp)
        if (status /= HD_OK) call fail(EXIT_FAILURE, 'reference solver failed while choosing the method')
        if (mchoice == 1) then
            if (chosen < 0) call fail(EXIT_NO_SOLUTION, 'no contact rule meets the accuracy ' // &
                                      trim(fmt_csv(sc%accuracy)) // ' of the scene')
            method = chosen
            c = findloc(hertzdamp_dem_cost_order, method, dim=1)
            reason = 'auto: cheapest rule (cost order first-order < compact < series < pade < fit < iterative) ' // &
                     'whose measured error ' // trim(fmt_csv(err(c))) // ' <= accuracy ' // trim(fmt_csv(sc%accuracy))
        else
            method = method_code(mchoice)
            c = findloc(hertzdamp_dem_cost_order, method, dim=1)
            if (.not. avail(c)) call fail(EXIT_USAGE, 'method ' // hertzdamp_method_name(method) // &
                                          ' is not available in this build of the library')
            reason = 'requested; measured error ' // trim(fmt_csv(err(c)))
        end if
        tol_it = min(1.0e-2_wp, max(1.0e-10_wp, 0.1_wp * sc%accuracy))

        call timed_run(sc, method, tol_it, res, cost)
        if (res%status /= HD_OK) call fail(EXIT_FAILURE, file // ': ' // res%message)
        if (method /= HD_METHOD_ITERATIVE) then
            call timed_run(sc, HD_METHOD_ITERATIVE, tol_it, res_it, cost_it)
            if (res_it%status /= HD_OK) call fail(EXIT_FAILURE, file // ' (iterative rule): ' // res_it%message)
        else
            res_it = res
            cost_it = cost
        end if

        nsec = 0
        if (fmt == FORMAT_JSON) call buf%add('{')
        call report_method(sc, file, method, reason, err, avail, t_select, fmt, buf, nsec)
        call report_contacts(sc, res, fmt, buf, nsec)
        call report_checks(sc, res, fmt, buf, nsec)
        call report_cost(method, res, cost, res_it, cost_it, fmt, buf, nsec)
        if (fmt == FORMAT_JSON) call buf%add('}')
        if (args%has('--plot')) call write_plot(sc, res, plot, terminal)
        call buf%flush_to_stdout()
        call quit(EXIT_OK)
    end subroutine cmd_scene

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

    !> Run the scene and time it; the rule's share is timed by replaying the rule on
    !> the recorded contacts (the same e, N dt, m, u_in, k_phys), repeated until at
    !> least 20 ms have passed.
    subroutine timed_run(sc, method, tol, res, cost)
        type(hertzdamp_dem_scene), intent(in) :: sc
        integer, intent(in) :: method
        real(wp), intent(in) :: tol
        type(hertzdamp_dem_result), intent(out) :: res
        type(run_cost), intent(out) :: cost
        integer(int64) :: c0, c1, rate
        integer :: reps, n
        real(wp), allocatable :: k(:), d(:), tce(:)
        logical, allocatable :: bound(:)
        integer, allocatable :: st(:)
        call system_clock(c0, rate)
        call hertzdamp_dem_run(sc, method, tol, res)
        call system_clock(c1)
        cost%total = real(c1 - c0, wp) / real(rate, wp)
        if (res%status /= HD_OK) return
        n = res%ncontacts
        if (n == 0) return
        allocate (k(n), d(n), tce(n), bound(n), st(n))
        reps = 0
        call system_clock(c0)
        do
            call hertzdamp_dem_rule(res%contacts%e_target, sc%steps_per_contact * sc%dt, res%contacts%m, &
                                    res%contacts%u_rule, res%contacts%k_phys, sc%iend, method, sc%want_duration, &
                                    tol, k, d, tce, bound, st)
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
        if (sc%want_duration) then
            write (b, '(i0)') sc%steps_per_contact
            call t%meta('wanted', 'restitution and contact duration T_c = N dt, N = ' // trim(b) // ', T_c = ' // &
                        trim(fmt_csv(sc%steps_per_contact * sc%dt)) // ' s (physical stiffness bound)')
        else
            call t%meta('wanted', 'restitution only (k = k_phys, contact duration physical)')
        end if
        call t%meta('accuracy', trim(fmt_csv(sc%accuracy)))
        call t%meta('dt', trim(fmt_csv(sc%dt)) // ' s')
        call t%meta('method', hertzdamp_method_name(method))
        call t%meta('why', reason)
        call t%meta('selection_time', trim(fmt_csv(t_select)) // ' s (one reference solve per candidate and target e)')
        do c = 1, 6
            write (b, '(i0)') c
            call t%str(trim(b))
            call t%str(hertzdamp_method_name(hertzdamp_dem_cost_order(c)))
            call t%str(trim(merge('yes', 'no ', avail(c))))
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
        real(wp) :: e_ach, tc_ach
        character(len=64) :: b
        call t%set_columns('contact,bodies,u_in,k,d,stiffness,e_target,e,e_rel_err,tc_target,tc,tc_rel_err')
        nbin = count(res%contacts%binary .and. res%contacts%t_end >= 0.0_wp)
        write (b, '(i0,a,i0,a)') res%ncontacts, ' contacts, ', nbin, ' binary and ended'
        call t%meta('contacts', trim(b))
        call t%meta('units', 'u_in [m/s], k [N m^-3/2], d [kg/s], tc [s]; e = separation/impact normal speed')
        if (.not. sc%want_duration) call t%meta('tc_target', 'physical contact time t*(k_phys) tau_c(alpha)')
        if (sc%gravity) call t%meta('gravity', 'acts during contacts too: e and tc differ from the ' // &
                                    'targets by O(g tc / u_in)')
        nrow = 0
        do c = 1, res%ncontacts
            associate (ct => res%contacts(c))
                if (.not. (ct%binary .and. ct%t_end >= 0.0_wp)) cycle
                nrow = nrow + 1
                if (nrow > max_rows) cycle
                e_ach = ct%u_out / max(ct%u_in, tiny(1.0_wp))
                tc_ach = ct%t_end - ct%t_start
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
                call t%num(e_ach)
                call t%num(abs(e_ach - ct%e_target) / ct%e_target)
                call t%num(ct%tc_target)
                call t%num(tc_ach)
                call t%num(abs(tc_ach - ct%tc_target) / ct%tc_target)
            end associate
        end do
        if (nrow > max_rows) then
            write (b, '(i0,a,i0)') max_rows, ' of ', nrow
            call t%meta('rows_shown', trim(b))
        end if
        call add_section('contacts', t, fmt, buf, nsec)
    end subroutine report_contacts

    subroutine report_checks(sc, res, fmt, buf, nsec)
        type(hertzdamp_dem_scene), intent(in) :: sc
        type(hertzdamp_dem_result), intent(in) :: res
        integer, intent(in) :: fmt
        type(cli_buffer), intent(inout) :: buf
        integer, intent(inout) :: nsec
        type(out_table) :: t
        logical, allocatable :: bin(:)
        real(wp) :: x, bound, escale
        allocate (bin(res%ncontacts))
        bin = res%contacts%binary .and. res%contacts%t_end >= 0.0_wp
        call t%set_columns('check,value,bound,result')
        call t%meta('bounds', 'binary contacts: e and tc to the method accuracy plus the time-step error, ' // &
                    'velocity Verlet O(1/N^2) for N steps per contact (bound 2/N^2, N the fewest steps ' // &
                    'per contact in the run); energy: no rise above 1/N^2 of the energy scale')
        bound = sc%accuracy + 2.0_wp / real(min_steps(sc, res), wp)**2
        if (count(bin) > 0) then
            x = maxval(abs(res%contacts%u_out / max(res%contacts%u_in, tiny(1.0_wp)) - res%contacts%e_target) / &
                       res%contacts%e_target, mask=bin)
            call row('max_e_rel_err (binary contacts)', x, bound, x <= bound, sc%gravity)
            x = maxval(abs(res%contacts%t_end - res%contacts%t_start - res%contacts%tc_target) / &
                       res%contacts%tc_target, mask=bin)
            call row('max_tc_rel_err (binary contacts)', x, bound, x <= bound, sc%gravity)
        end if
        if (sc%gravity) then
            ! gravity changes e by about -0.1 e g T_c/u_in (measured, e = 0.8): check the
            ! contacts where that is below 1e-2, with 0.25 g T_c/u_in <= 2.5e-3 added to the bound
            bin = bin .and. norm2(sc%g) * res%contacts%tc_target < 1.0e-2_wp * res%contacts%u_in
            bound = bound + 2.5e-3_wp
            if (count(bin) > 0) then
                x = maxval(abs(res%contacts%u_out / max(res%contacts%u_in, tiny(1.0_wp)) - res%contacts%e_target) / &
                           res%contacts%e_target, mask=bin)
                call row('max_e_rel_err (binary, g tc/u_in < 0.01)', x, bound, x <= bound)
                x = maxval(abs(res%contacts%t_end - res%contacts%t_start - res%contacts%tc_target) / &
                           res%contacts%tc_target, mask=bin)
                call row('max_tc_rel_err (binary, g tc/u_in < 0.01)', x, bound, x <= bound)
            end if
        end if
        call t%str('min_steps_per_contact')
        call t%num(real(min_steps(sc, res), wp))
        call t%str('-')
        call t%str('info')
        if (.not. sc%gravity .and. size(sc%wall) == 0) then
            x = res%momentum_drift / max(res%momentum_scale, tiny(1.0_wp))
            call row('momentum_drift / sum m|v|', x, 1.0e-12_wp, x <= 1.0e-12_wp)
        end if
        escale = max(abs(res%energy0), tiny(1.0_wp))
        if (sc%gravity) escale = max(escale, abs(res%energy0 - res%energy_final))
        x = res%energy_rise / escale
        bound = 1.0_wp / real(min_steps(sc, res), wp)**2
        call row('energy_rise / energy scale', x, bound, x <= bound)
        call t%str('energy_final / energy0')
        call t%num(res%energy_final / merge(res%energy0, 1.0_wp, abs(res%energy0) > 0.0_wp))
        call t%str('-')
        call t%str('info')
        if (sc%has_domain) call row('particles_left_domain', real(res%left_domain, wp), 0.0_wp, res%left_domain == 0)
        if (sc%gravity) call row('max_final_speed [m/s] (at rest)', res%max_speed_final, sc%rest_speed, res%at_rest)
        call add_section('checks', t, fmt, buf, nsec)

    contains

        !> One check; with `info_only` the bound does not apply (gravity acts during
        !> the contacts) and the result says so.
        subroutine row(name, value, bnd, ok, info_only)
            character(len=*), intent(in) :: name
            real(wp), intent(in) :: value, bnd
            logical, intent(in) :: ok
            logical, intent(in), optional :: info_only
            logical :: info
            info = .false.
            if (present(info_only)) info = info_only
            call t%str(name)
            call t%num(value)
            call t%num(bnd)
            if (info) then
                call t%str('info (gravity)')
            else
                call t%str(merge('pass', 'FAIL', ok))
            end if
        end subroutine row

    end subroutine report_checks

    !> Fewest time steps per expected contact duration among the contacts (N when none).
    integer function min_steps(sc, res) result(m)
        type(hertzdamp_dem_scene), intent(in) :: sc
        type(hertzdamp_dem_result), intent(in) :: res
        if (res%ncontacts > 0) then
            m = max(1, floor(minval(res%contacts%tc_target) / sc%dt))
        else
            m = sc%steps_per_contact
        end if
    end function min_steps

    subroutine report_cost(method, res, cost, res_it, cost_it, fmt, buf, nsec)
        integer, intent(in) :: method, fmt
        type(hertzdamp_dem_result), intent(in) :: res, res_it
        type(run_cost), intent(in) :: cost, cost_it
        type(cli_buffer), intent(inout) :: buf
        integer, intent(inout) :: nsec
        type(out_table) :: t
        call t%set_columns('rule,total_time_s,param_time_s,contacts,param_time_per_contact_s,speedup_total,speedup_params')
        call t%meta('timing', 'total: wall time of the run; params: the rule replayed on the run''s contacts')
        call line(hertzdamp_method_name(method), res, cost)
        if (method /= HD_METHOD_ITERATIVE) call line('iterative', res_it, cost_it)
        call add_section('cost', t, fmt, buf, nsec)

    contains

        subroutine line(name, r, cst)
            character(len=*), intent(in) :: name
            type(hertzdamp_dem_result), intent(in) :: r
            type(run_cost), intent(in) :: cst
            character(len=16) :: b
            call t%str(name)
            call t%num(cst%total)
            call t%num(cst%params)
            write (b, '(i0)') r%ncontacts
            call t%str(trim(b))
            call t%num(cst%params / max(1, r%ncontacts))
            call t%num(cost_it%total / max(cst%total, tiny(1.0_wp)))
            call t%num(cost_it%params / max(cst%params, tiny(1.0_wp)))
        end subroutine line

    end subroutine report_cost

    !> Positions and velocities along the trace axis against time, for up to
    !> max_plot_lines particles: data and script in $TMPDIR (default /tmp), drawn by
    !> gnuplot into plot_temp_name(plot) and renamed into place by plot_run.
    subroutine write_plot(sc, res, plot, terminal)
        type(hertzdamp_dem_scene), intent(in) :: sc
        type(hertzdamp_dem_result), intent(in) :: res
        character(len=*), intent(in) :: plot      !! target PNG (checked by plot_check_target)
        character(len=*), intent(in) :: terminal  !! pngcairo or png
        character(len=:), allocatable :: dat, gp, ax, tmpdir
        integer :: u, ios, i, k, np, stride, try, ln
        integer(int64) :: cnt
        integer, allocatable :: pick(:)
        character(len=32) :: b
        character(len=4096) :: env
        call get_environment_variable('TMPDIR', env, length=ln, status=ios)
        tmpdir = '/tmp'
        if (ios == 0 .and. ln > 0) tmpdir = trim(env)
        call system_clock(cnt)
        ! a data file of our own: status='new' never opens someone else's file
        do try = 1, 100
            write (b, '(i0)') cnt + try
            dat = tmpdir // '/hertzdamp_scene_' // trim(b) // '.dat'
            open (newunit=u, file=dat, status='new', action='write', iostat=ios)
            if (ios == 0) exit
        end do
        if (ios /= 0) call fail(EXIT_FAILURE, 'cannot write a temporary file in ' // tmpdir)
        gp = tmpdir // '/hertzdamp_scene_' // trim(b) // '.gp'
        ax = 'xyz'(res%axis:res%axis)
        np = size(res%x_trace, 2)
        stride = max(1, (np + max_plot_lines - 1) / max_plot_lines)
        pick = [(i, i=1, np, stride)]
        do k = 1, size(res%t_trace)
            write (u, '(*(es16.8))') res%t_trace(k), res%x_trace(k, pick), res%v_trace(k, pick)
        end do
        close (u)
        open (newunit=u, file=gp, status='new', action='write', iostat=ios)
        if (ios /= 0) then
            open (newunit=u, file=dat, status='old', iostat=ios)
            if (ios == 0) close (u, status='delete')
            call fail(EXIT_FAILURE, 'cannot write a temporary file in ' // tmpdir)
        end if
        write (u, '(a)') 'set terminal ' // terminal // ' size 1000,800 noenhanced'
        write (u, '(a)') 'set output ' // gp_string(plot_temp_name(plot))
        write (u, '(a)') 'set multiplot layout 2,1 title ' // gp_string(sc%title)
        write (u, '(a)') 'set key off'
        write (u, '(a)') 'set grid'
        write (u, '(a)') 'set xlabel "t [s]"'
        write (u, '(a)') 'set ylabel "' // ax // ' [m]"'
        write (b, '(i0)') size(pick)
        write (u, '(a)') 'plot for [i=2:' // trim(b) // '+1] ' // gp_string(dat) // ' using 1:i with lines'
        write (u, '(a)') 'set ylabel "v_' // ax // ' [m/s]"'
        write (u, '(a)') 'plot for [i=' // trim(b) // '+2:2*' // trim(b) // '+1] ' // gp_string(dat) // &
                         ' using 1:i with lines'
        write (u, '(a)') 'unset multiplot'
        write (u, '(a)') 'set output'
        close (u)
        call plot_run(gp, plot_temp_name(plot), plot, [character(len=len(dat)) :: dat])
    end subroutine write_plot

end module hertzdamp_cmd_scene
