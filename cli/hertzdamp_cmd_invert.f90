!> The command `invert`: stiffness and damping from target restitution and contact time.
module hertzdamp_cmd_invert
    use hertzdamp, only: hertzdamp_rk, hertzdamp_invert, hertzdamp_message, hertzdamp_end_name, &
                         HD_OK, HD_BAD_RESTITUTION, HD_OUTSIDE_VALIDITY, HD_END_OVERLAP, HD_METHOD_FIT, HD_METHOD_COMPACT, &
                         HD_METHOD_SERIES, HD_METHOD_PADE, &
                         HD_METHOD_ITERATIVE
    use hertzdamp_cli, only: cli_args, cli_buffer, parse_args, parse_real, parse_real_list, parse_int, &
                             parse_choice, fail, quit, fmt_csv, EXIT_USAGE, EXIT_OK, exit_code_of
    use hertzdamp_cli_output, only: out_table, format_choices
    use hertzdamp_cli_help, only: print_help, wants_help
    implicit none
    private
    public :: cmd_invert

    integer, parameter :: wp = hertzdamp_rk

contains

    subroutine cmd_invert()
        type(cli_args) :: args
        real(wp), allocatable :: e(:), k(:), d(:), alpha(:), tstar(:), tau(:)
        logical, allocatable :: bound(:)
        integer, allocatable :: status(:)
        real(wp) :: tc, dt, m, u, kphys, tol
        integer :: steps, iend, method, fmt, i
        character(len=:), allocatable :: mname
        type(out_table) :: t
        type(cli_buffer) :: buf
        if (wants_help()) then
            call print_help('invert')
            call quit(EXIT_OK)
        end if
        call parse_args(2, '--e --tc --dt --steps --mass --velocity --k-phys --end --method --tol --format', '', args)
        iend = parse_choice(args%get('--end', 'overlap'), 'overlap force', 'contact-end definition (--end)') - 1
        mname = args%get('--method', 'fit')
        method = parse_choice(mname, 'fit compact series pade iterative', 'method (--method)')
        select case (method)
        case (1); method = HD_METHOD_FIT
        case (2); method = HD_METHOD_COMPACT
        case (3); method = HD_METHOD_SERIES
        case (4); method = HD_METHOD_PADE
        case default; method = HD_METHOD_ITERATIVE
        end select
        fmt = parse_choice(args%get('--format', 'text'), format_choices, 'format (--format)')
        if (.not. args%has('--e')) call fail(EXIT_USAGE, 'missing option --e (see --help)')
        e = parse_real_list(args%get('--e', ''), '--e')
        if (args%has('--tc')) then
            if (args%has('--dt') .or. args%has('--steps')) then
              call fail(EXIT_USAGE, 'give either --tc or --dt with --steps, not both')
            end if
            tc = parse_real(args%get('--tc', ''), '--tc')
        else
            if (.not. (args%has('--dt') .and. args%has('--steps'))) then
              call fail(EXIT_USAGE, 'missing option --tc (or --dt with --steps) (see --help)')
            end if
            dt = parse_real(args%get('--dt', ''), '--dt')
            steps = parse_int(args%get('--steps', ''), '--steps')
            if (steps < 1) call fail(EXIT_USAGE, '--steps must be >= 1')
            tc = dt * steps
        end if
        if (.not. args%has('--mass')) call fail(EXIT_USAGE, 'missing option --mass (see --help)')
        if (.not. args%has('--velocity')) call fail(EXIT_USAGE, 'missing option --velocity (see --help)')
        m = parse_real(args%get('--mass', ''), '--mass')
        u = parse_real(args%get('--velocity', ''), '--velocity')
        tol = 1.0e-10_wp
        if (args%has('--tol')) then
            if (method /= HD_METHOD_ITERATIVE) call fail(EXIT_USAGE, '--tol applies to --method iterative only')
            tol = parse_real(args%get('--tol', ''), '--tol')
        end if
        allocate (k(size(e)), d(size(e)), alpha(size(e)), tstar(size(e)), tau(size(e)), bound(size(e)), &
                  status(size(e)))
        if (args%has('--k-phys')) then
            kphys = parse_real(args%get('--k-phys', ''), '--k-phys')
            call hertzdamp_invert(e, tc, m, u, iend, k, d, status, alpha, tstar, tau, bound, kphys, method, tol)
        else
            call hertzdamp_invert(e, tc, m, u, iend, k, d, status, alpha, tstar, tau, bound, method=method, tol=tol)
        end if
        do i = 1, size(e)
            if (status(i) /= HD_OK) then
              call fail(exit_code_of(status(i)), 'e = ' // fmt_csv(e(i)) // ': ' // hertzdamp_message(status(i)))
            end if
        end do
        call t%set_columns('e,tc,mass,velocity,alpha,tau_c,t_star,k,d,bound_active,status')
        call t%meta('end', hertzdamp_end_name(iend))
        call t%meta('method', mname)
        call t%meta('units', 'tc [s], mass [kg], velocity [m/s], t_star [s], k [N m^-3/2], d [kg/s]')
        do i = 1, size(e)
            call t%num(e(i))
            call t%num(tc)
            call t%num(m)
            call t%num(u)
            call t%num(alpha(i))
            call t%num(tau(i))
            call t%num(tstar(i))
            call t%num(k(i))
            call t%num(d(i))
            call t%str(trim(merge('true ', 'false', bound(i))))
            call t%str('ok')
        end do
        call t%render(fmt, buf)
        call buf%flush_to_stdout()
        call quit(EXIT_OK)
    end subroutine cmd_invert

end module hertzdamp_cmd_invert
