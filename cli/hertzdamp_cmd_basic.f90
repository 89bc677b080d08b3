!> The commands `table`, `forward` and `constants`.
module hertzdamp_cmd_basic
    use hertzdamp, only: hertzdamp_rk, hertzdamp_collision, hertzdamp_forward_alpha, hertzdamp_forward_dim, &
                         hertzdamp_message, hertzdamp_alpha_c, hertzdamp_tau_c0, &
                         hertzdamp_z_max0, hertzdamp_e1, hertzdamp_rk45_default_tol, hertzdamp_end_name, &
                         hertzdamp_series_default_order, &
                         HD_OK, HD_NO_REBOUND, HD_END_OVERLAP, HD_METHOD_RK45, HD_METHOD_SERIES, HD_METHOD_PADE
    use hertzdamp_cli, only: cli_args, cli_buffer, parse_args, parse_real, parse_real_list, parse_range, &
                             parse_choice, parse_int, fail, quit, EXIT_USAGE, EXIT_OK, EXIT_FAILURE, fmt_csv, &
                             exit_code_of, max_list_length
    use hertzdamp_cli_output, only: out_table, format_choices
    use hertzdamp_cli_help, only: print_help, wants_help
    implicit none
    private
    public :: cmd_table, cmd_forward, cmd_constants, parse_common, status_word

    integer, parameter :: wp = hertzdamp_rk

    !> Settings shared by the forward commands.
    type, public :: common_opts
        integer :: iend = HD_END_OVERLAP
        integer :: method = HD_METHOD_RK45
        integer :: fmt = 1
        real(wp) :: tol = hertzdamp_rk45_default_tol
        integer :: order = -1
        character(len=:), allocatable :: method_name, tol_text
    end type common_opts

contains

    !> `ok`, `no-rebound` or the status message.
    function status_word(status) result(w)
        integer, intent(in) :: status
        character(len=:), allocatable :: w
        select case (status)
        case (HD_OK); w = 'ok'
        case (HD_NO_REBOUND); w = 'no-rebound'
        case default; w = 'error'
        end select
    end function status_word

    !> --end, --method, --tol, --format.
    subroutine parse_common(args, c)
        type(cli_args), intent(in) :: args
        type(common_opts), intent(out) :: c
        c%iend = parse_choice(args%get('--end', 'overlap'), 'overlap force', 'contact-end definition (--end)') - 1
        c%method_name = args%get('--method', 'rk45')
        ! the forward methods (iterative is the inverse baseline only)
        c%method = parse_choice(c%method_name, 'rk45 series pade compact fit', 'method (--method)')
        c%fmt = parse_choice(args%get('--format', 'text'), format_choices, 'format (--format)')
        c%tol_text = args%get('--tol', '1e-13')
        if (args%has('--tol')) then
            c%tol = parse_real(c%tol_text, '--tol')
            if (.not. (c%tol >= 1.0e-15_wp .and. c%tol <= 1.0e-2_wp)) then
              call fail(EXIT_USAGE, 'tolerance --tol ' // c%tol_text // ' outside [1e-15, 1e-2]')
            end if
            if (c%method /= HD_METHOD_RK45) call fail(EXIT_USAGE, '--tol applies to --method rk45 only')
        end if
        if (args%has('--order')) then
            c%order = parse_int(args%get('--order', ''), '--order')
            if (c%method /= HD_METHOD_SERIES) call fail(EXIT_USAGE, '--order applies to --method series only')
        end if
        if ((c%method == HD_METHOD_SERIES .or. c%method == HD_METHOD_PADE) .and. c%iend /= HD_END_OVERLAP) then
          call fail(EXIT_USAGE, 'method ' // c%method_name // ' supports the overlap definition only: ' // &
                      'the force definition is not analytic at alpha = 0 (see doc/series.md)')
        end if
    end subroutine parse_common

    subroutine cmd_table()
        type(cli_args) :: args
        type(common_opts) :: c
        real(wp), allocatable :: alpha(:)
        type(hertzdamp_collision), allocatable :: r(:)
        type(out_table) :: t
        type(cli_buffer) :: buf
        integer :: i
        if (wants_help()) then
            call print_help('table')
            call quit(EXIT_OK)
        end if
        call parse_args(2, '--alpha --alpha-range --end --method --tol --format --order', '', args)
        call parse_common(args, c)
        allocate (alpha(0))
        if (args%has('--alpha')) alpha = [alpha, parse_real_list(args%get('--alpha', ''), '--alpha')]
        if (args%has('--alpha-range')) alpha = [alpha, parse_range(args%get('--alpha-range', ''), '--alpha-range')]
        if (size(alpha) > max_list_length) call fail(EXIT_USAGE, 'too many values of alpha (at most 10000 rows)')
        if (.not. (args%has('--alpha') .or. args%has('--alpha-range'))) then
          alpha = [(0.05_wp * i, i=0, 22), 1.12_wp, 1.13_wp]
        end if
        allocate (r(size(alpha)))
        if (c%order >= 0) then
            r = hertzdamp_forward_alpha(alpha, c%iend, c%method, c%tol, c%order)
        else
            r = hertzdamp_forward_alpha(alpha, c%iend, c%method, c%tol)
        end if
        do i = 1, size(r)
            if (r(i)%status /= HD_OK .and. r(i)%status /= HD_NO_REBOUND) then
              call fail(exit_code_of(r(i)%status), 'alpha = ' // fmt_csv(alpha(i)) // ': ' // hertzdamp_message(r(i)%status))
            end if
        end do
        call t%set_columns('alpha,e,tau_c,z_max,tau_max,status')
        call t%meta('end', hertzdamp_end_name(c%iend))
        call t%meta('method', c%method_name)
        if (c%method == HD_METHOD_RK45) call t%meta('tol', c%tol_text)
        if (c%method == HD_METHOD_SERIES) call t%meta('order', order_text(c%order))
        do i = 1, size(r)
            call t%num(alpha(i))
            call t%num(r(i)%e)
            call t%num(r(i)%tau_c)
            call t%num(r(i)%z_max)
            call t%num(r(i)%tau_max)
            call t%str(status_word(r(i)%status))
        end do
        call t%render(c%fmt, buf)
        call buf%flush_to_stdout()
        call quit(EXIT_OK)
    end subroutine cmd_table

    subroutine cmd_forward()
        type(cli_args) :: args
        type(common_opts) :: c
        real(wp) :: k, d, m, u, alpha, tstar, e, tc, zmax
        integer :: status
        type(out_table) :: t
        type(cli_buffer) :: buf
        if (wants_help()) then
            call print_help('forward')
            call quit(EXIT_OK)
        end if
        call parse_args(2, '--k --d --mass --velocity --end --method --tol --format --order', '', args)
        call parse_common(args, c)
        k = required(args, '--k')
        d = required(args, '--d')
        m = required(args, '--mass')
        u = required(args, '--velocity')
        if (c%order >= 0) then
            call hertzdamp_forward_dim(k, d, m, u, c%iend, c%method, alpha, tstar, e, tc, zmax, status, c%tol, c%order)
        else
            call hertzdamp_forward_dim(k, d, m, u, c%iend, c%method, alpha, tstar, e, tc, zmax, status, c%tol)
        end if
        if (status /= HD_OK .and. status /= HD_NO_REBOUND) call fail(exit_code_of(status), hertzdamp_message(status))
        call t%set_columns('alpha,t_star,e,t_c,zeta_max,status')
        call t%meta('end', hertzdamp_end_name(c%iend))
        call t%meta('method', c%method_name)
        call t%meta('units', 't_star [s], t_c [s], zeta_max [m]')
        call t%num(alpha)
        call t%num(tstar)
        call t%num(e)
        call t%num(tc)
        call t%num(zmax)
        call t%str(status_word(status))
        call t%render(c%fmt, buf)
        call buf%flush_to_stdout()
        call quit(EXIT_OK)
    end subroutine cmd_forward

    !> The series order as printed: the given one or the library default.
    function order_text(order) result(txt)
        integer, intent(in) :: order
        character(len=:), allocatable :: txt
        character(len=12) :: buf
        if (order >= 0) then
            write (buf, '(i0)') order
        else
            write (buf, '(i0,a)') hertzdamp_series_default_order, ' (default)'
        end if
        txt = trim(buf)
    end function order_text

    !> A required numeric option.
    real(wp) function required(args, key) result(x)
        type(cli_args), intent(in) :: args
        character(len=*), intent(in) :: key
        if (.not. args%has(key)) call fail(EXIT_USAGE, 'missing option ' // key // ' (see --help)')
        x = parse_real(args%get(key, ''), key)
    end function required

    subroutine cmd_constants()
        type(cli_args) :: args
        integer :: fmt, status
        real(wp) :: ac
        type(out_table) :: t
        type(cli_buffer) :: buf
        if (wants_help()) then
            call print_help('constants')
            call quit(EXIT_OK)
        end if
        call parse_args(2, '--format', '', args)
        fmt = parse_choice(args%get('--format', 'text'), format_choices, 'format (--format)')
        call hertzdamp_alpha_c(ac, status)
        if (status /= HD_OK) call fail(EXIT_FAILURE, 'alpha_c: ' // hertzdamp_message(status))
        call t%set_columns('name,value')
        call t%str('alpha_c')
        call t%num(ac)
        call t%str('tau_c0')
        call t%num(hertzdamp_tau_c0())
        call t%str('z_max0')
        call t%num(hertzdamp_z_max0())
        call t%str('e1')
        call t%num(hertzdamp_e1())
        call t%render(fmt, buf)
        call buf%flush_to_stdout()
        call quit(EXIT_OK)
    end subroutine cmd_constants

end module hertzdamp_cmd_basic
