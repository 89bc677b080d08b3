!> The commands `table`, `forward` and `constants`.
module hertzdamp_cmd_basic
    use hertzdamp, only: hertzdamp_rk, hertzdamp_collision, hertzdamp_forward_alpha, hertzdamp_forward_dim, &
                         hertzdamp_message, hertzdamp_alpha_c, hertzdamp_tau_c0, hertzdamp_z_max0, hertzdamp_e1, &
                         hertzdamp_end_name, hertzdamp_alpha_max, hertzdamp_law_q, hertzdamp_law_name, &
                         HD_DAMPING_LINEAR, hertzdamp_law_has_alpha_c, hertzdamp_law_alpha_c, hertzdamp_law_code, &
                         HD_OK, HD_NO_REBOUND, HD_END_OVERLAP, HD_METHOD_RK45, HD_METHOD_SERIES, HD_METHOD_PADE, &
                         HD_BAD_ALPHA, HD_BAD_STIFFNESS, HD_BAD_DAMPING, HD_BAD_VELOCITY, HD_BAD_MASS, &
                         HD_OUT_OF_RANGE, HD_OUTSIDE_VALIDITY, HD_INACCURATE, HD_MAX_STEPS, hertzdamp_reduce, &
                         hertzdamp_safe_exp, hertzdamp_log_tstar, hertzdamp_rk45_options
    use hertzdamp_cli, only: cli_args, cli_buffer, parse_args, parse_choice, parse_sweep, parse_range, fail, quit, &
                             required_sweep, check_combinations, EXIT_USAGE, EXIT_OK, EXIT_FAILURE, max_list_length
    use hertzdamp_cli_text, only: fmt_short, itoa
    use hertzdamp_cli_output, only: out_table, format_choices
    use hertzdamp_cli_help, only: print_help, wants_help
    use hertzdamp_cli_model, only: model_opts, parse_model, model_options, method_accepts, instead, parse_law, damping_unit
    use hertzdamp_cli_rows, only: row_log, row_kind, row_word, row_has_result
    use hertzdamp_cli_materials, only: cli_contact, parse_contact, require_mass, contact_table, contact_options, contact_flags
    use hertzdamp_cli_progress, only: progress_reporter
    use hertzdamp_cli_plausible, only: warn_implausible, quiet_flag
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
    implicit none
    private
    public :: cmd_table, cmd_forward, cmd_constants, failure_reason

    integer, parameter :: wp = hertzdamp_rk

contains

    !> Why a forward computation at `alpha` has no result with the chosen method.
    function failure_reason(c, status, alpha) result(s)
        type(model_opts), intent(in) :: c
        integer, intent(in) :: status
        real(wp), intent(in) :: alpha
        character(len=:), allocatable :: s
        type(hertzdamp_rk45_options), parameter :: max_steps = hertzdamp_rk45_options()
        select case (status)
        case (HD_BAD_ALPHA, HD_OUTSIDE_VALIDITY)
            if (abs(alpha) > hertzdamp_alpha_max) then
                s = 'alpha = ' // fmt_short(alpha) // ' is beyond ' // fmt_short(hertzdamp_alpha_max) // &
                    ', the largest alpha any method takes'
                return
            end if
            s = 'alpha = ' // fmt_short(alpha) // ' is outside the range of --method ' // c%method_name // ' (' // &
                method_accepts(c) // '); ' // instead(c)
        case (HD_INACCURATE)
            s = 'alpha = ' // fmt_short(alpha) // ': the error estimate of --method ' // c%method_name // &
                ' exceeds --accuracy ' // fmt_short(c%accuracy) // ' (raise '
            if (c%method == HD_METHOD_SERIES) s = s // '--order or '
            s = s // '--accuracy, or ' // instead(c) // ')'
        case (HD_MAX_STEPS)
            ! what really happened: the contact outlasted the step budget
            s = 'alpha = ' // fmt_short(alpha) // ': the reference integrator reached its limit of ' // &
                itoa(max_steps%max_steps) // ' steps before the contact ended (damping this strong makes the ' // &
                'contact long and the equation stiff)'
        case default
            s = 'alpha = ' // fmt_short(alpha) // ': ' // hertzdamp_message(status)
        end select
    end function failure_reason

    subroutine cmd_table()
        type(cli_args) :: args
        type(model_opts) :: c
        real(wp), allocatable :: alpha(:)
        type(hertzdamp_collision), allocatable :: r(:)
        type(out_table) :: t
        type(row_log) :: rows
        type(progress_reporter) :: p
        integer :: i, kind
        logical :: have
        if (wants_help()) call print_help('table')
        call parse_args(2, '--alpha --alpha-range ' // model_options, '--progress', args)
        call parse_model(args, c, inverse=.false.)
        allocate (alpha(0))
        if (args%has('--alpha')) alpha = [alpha, parse_sweep(args%get('--alpha', ''), '--alpha')]
        if (args%has('--alpha-range')) alpha = [alpha, parse_range(args%get('--alpha-range', ''), '--alpha-range')]
        if (size(alpha) > max_list_length) call fail(EXIT_USAGE, 'too many values of alpha (at most ' // &
                                                     itoa(max_list_length) // ' rows)')
        if (.not. (args%has('--alpha') .or. args%has('--alpha-range'))) then
            alpha = [(0.05_wp * i, i=0, 22), 1.12_wp, 1.13_wp]
        end if
        allocate (r(size(alpha)))
        call p%start(real(size(alpha), wp), 'table', force=args%has('--progress'))
        do i = 1, size(alpha)
            r(i) = hertzdamp_forward_alpha(alpha(i), c%iend, c%method, c%tol, c%order, c%accuracy, c%law)
            call p%update(real(i, wp))
        end do
        call p%finish()
        call t%set_columns('alpha,e,tau_c,z_max,tau_max,status')
        call t%meta('damping', c%law_name)
        call t%meta('end', hertzdamp_end_name(c%iend))
        call t%meta('method', c%method_name)
        if (c%method == HD_METHOD_RK45) call t%meta('tol', c%tol_text)
        if (c%method == HD_METHOD_SERIES) call t%meta('order', itoa(c%order))
        if (c%method == HD_METHOD_SERIES .or. c%method == HD_METHOD_PADE) call t%meta('accuracy', c%accuracy_text)
        do i = 1, size(r)
            kind = row_kind(r(i)%status)
            have = row_has_result(kind)
            call t%num(alpha(i))
            call t%num_or_none(r(i)%e, have)
            call t%num_or_none(r(i)%tau_c, have)
            ! z_max > 0 and tau_max > 0 for every collision: 0 means the method does not give them
            call t%num_or_none(r(i)%z_max, have .and. r(i)%z_max > 0.0_wp)
            call t%num_or_none(r(i)%tau_max, have .and. r(i)%tau_max > 0.0_wp)
            call t%str(row_word(kind))
            if (have) then
                call rows%add(kind, '')
            else
                call rows%add(kind, failure_reason(c, r(i)%status, alpha(i)))
            end if
        end do
        call rows%emit(t, c%fmt)
    end subroutine cmd_table

    subroutine cmd_forward()
        type(cli_args) :: args
        type(model_opts) :: c
        type(cli_contact) :: ct
        real(wp), allocatable :: ks(:), ds(:), us(:)
        real(wp) :: k, d, u, alpha, tstar, e, tc, zmax
        integer :: status, ik, id, iu, kind, n, st
        type(out_table) :: t
        type(row_log) :: rows
        type(progress_reporter) :: p
        logical :: have, have_alpha, have_tstar
        allocate (ks(0), ds(0), us(0))   ! (defined descriptors for the reallocating assignments)
        if (wants_help()) call print_help('forward')
        call parse_args(2, '--k --d --velocity ' // contact_options // ' ' // model_options, &
                        contact_flags // ' --progress ' // quiet_flag, args)
        call parse_model(args, c, inverse=.false.)
        call parse_contact(args, ct)
        call require_mass(ct)
        if (args%has('--k')) then
            ks = parse_sweep(args%get('--k', ''), '--k')
        else if (ct%has_kphys) then
            ks = [ct%k_phys]     ! the physical stiffness of the materials
        else
            call fail(EXIT_USAGE, 'missing option --k (or the elastic constants, for k = k_phys) (see --help)')
        end if
        ds = required_sweep(args, '--d')
        us = required_sweep(args, '--velocity')
        call check_combinations([size(ks), size(ds), size(us)], '--k, --d and --velocity')
        call warn_implausible(args)
        call contact_table(t, c, ct, 'k,d,velocity,mass,radius_eff,k_phys,alpha,t_star,e,t_c,zeta_max,status', &
                           'k, k_phys [N m^-3/2], d [' // damping_unit(c%law) // '], velocity [m/s], mass [kg], ' // &
                           'radius_eff [m], ' // &
                           't_star [s], t_c [s], zeta_max [m]', &
                           'N m^-3/2,' // damping_unit(c%law) // ',m/s,kg,m,N m^-3/2,,s,,s,m,')
        n = 0
        call p%start(real(size(ks) * size(ds) * size(us), wp), 'forward', force=args%has('--progress'))
        do ik = 1, size(ks)
            do id = 1, size(ds)
                do iu = 1, size(us)
                    k = ks(ik)
                    d = ds(id)
                    u = us(iu)
                    call hertzdamp_forward_dim(k, d, ct%mass, u, c%iend, c%method, alpha, tstar, e, tc, zmax, status, &
                                               c%tol, c%order, c%accuracy, c%law)
                    have_alpha = .true.
                    have_tstar = .true.
                    ! a failed row has no alpha from the library: the message needs it
                    if (status /= HD_OK) call hertzdamp_reduce(k, d, ct%mass, u, alpha, tstar, st, law=c%law)
                    if (status /= HD_OK .and. st /= HD_OK) alpha = 0.0_wp
                    if (status == HD_OUT_OF_RANGE .or. status == HD_BAD_ALPHA) then
                        ! alpha beyond the method (or double precision): with the overlap end that is
                        ! simply no rebound; with the force end, outside the method's range
                        call overdamped(c, k, d, ct%mass, u, alpha, tstar, status, have_alpha, have_tstar)
                        if (status == HD_NO_REBOUND) then
                            e = 0.0_wp
                            tc = ieee_value(1.0_wp, ieee_positive_inf)
                            zmax = 0.0_wp
                        end if
                    end if
                    kind = row_kind(status)
                    have = row_has_result(kind)
                    call t%num(k)
                    call t%num(d)
                    call t%num(u)
                    call t%num(ct%mass)
                    call t%num_or_none(ct%radius, ct%has_radius)
                    call t%num_or_none(ct%k_phys, ct%has_kphys)
                    call t%num_or_none(alpha, have .and. have_alpha)
                    call t%num_or_none(tstar, have .and. have_tstar)
                    call t%num_or_none(e, have)
                    call t%num_or_none(tc, have)
                    call t%num_or_none(zmax, have .and. zmax > 0.0_wp)
                    call t%str(row_word(kind))
                    if (have) then
                        call rows%add(kind, '')
                    else
                        call rows%add(kind, forward_reason(c, status, k, d, u, alpha, have_alpha))
                    end if
                    n = n + 1
                    call p%update(real(n, wp))
                end do
            end do
        end do
        call p%finish()
        call rows%emit(t, c%fmt)
    end subroutine cmd_forward

    !> When alpha = d t* (u t*)^q / m is too large for the method or for double precision:
    !> no rebound with the overlap end of a law with alpha_c (alpha >= alpha_c), outside
    !> the method's range otherwise; alpha and t* reported where representable.
    subroutine overdamped(c, k, d, m, u, alpha, tstar, status, have_alpha, have_tstar)
        type(model_opts), intent(in) :: c
        real(wp), intent(in) :: k, d, m, u
        real(wp), intent(out) :: alpha, tstar
        integer, intent(inout) :: status
        logical, intent(out) :: have_alpha, have_tstar
        real(wp) :: la, lt
        integer :: st
        alpha = 0.0_wp
        tstar = 0.0_wp
        have_alpha = .false.
        have_tstar = .false.
        if (.not. (k > 0.0_wp .and. d > 0.0_wp .and. m > 0.0_wp .and. u > 0.0_wp)) return
        lt = hertzdamp_log_tstar(log(m), log(k), log(u), .true.)
        la = log(d) + lt - log(m) + hertzdamp_law_q(c%law) * (log(u) + lt)
        ! a law without alpha_c (kuwabara-kono) always rebounds: the library's status stands
        if (.not. hertzdamp_law_has_alpha_c(c%law)) return
        if (.not. (la > log(hertzdamp_law_alpha_c(c%law)) + 1.0e-6_wp)) return
        st = HD_OK
        call hertzdamp_safe_exp(lt, tstar, st)
        have_tstar = st == HD_OK
        alpha = huge(1.0_wp)
        if (have_tstar .and. la < log(huge(1.0_wp)) - 1.0_wp) alpha = exp(la)
        have_alpha = alpha < huge(1.0_wp)
        if (c%iend == HD_END_OVERLAP) then
            status = HD_NO_REBOUND
        else
            status = HD_OUTSIDE_VALIDITY
        end if
    end subroutine overdamped

    !> Why a `forward` row has no result, naming the option.
    function forward_reason(c, status, k, d, u, alpha, have_alpha) result(s)
        type(model_opts), intent(in) :: c
        integer, intent(in) :: status
        real(wp), intent(in) :: k, d, u, alpha
        logical, intent(in) :: have_alpha   !! alpha is known (else beyond double precision)
        character(len=:), allocatable :: s
        select case (status)
        case (HD_BAD_STIFFNESS); s = '--k ' // fmt_short(k) // ': ' // hertzdamp_message(status)
        case (HD_BAD_DAMPING); s = '--d ' // fmt_short(d) // ': ' // hertzdamp_message(status)
        case (HD_BAD_VELOCITY); s = '--velocity ' // fmt_short(u) // ': ' // hertzdamp_message(status)
        case (HD_BAD_MASS); s = '--mass: ' // hertzdamp_message(status)
        case (HD_OUT_OF_RANGE)
            s = 'k = ' // fmt_short(k) // ', d = ' // fmt_short(d) // ', velocity = ' // fmt_short(u) // &
                ': t*, alpha or the contact time is outside the double-precision range'
        case default
            s = 'k = ' // fmt_short(k) // ', d = ' // fmt_short(d) // ', velocity = ' // fmt_short(u) // ': ' // &
                failure_reason(c, status, merge(alpha, huge(alpha), have_alpha))
        end select
    end function forward_reason

    subroutine cmd_constants()
        type(cli_args) :: args
        integer :: fmt, status, law
        real(wp) :: ac
        type(out_table) :: t
        type(cli_buffer) :: buf
        if (wants_help()) call print_help('constants')
        call parse_args(2, '--format --damping', '', args)
        fmt = parse_choice(args%get('--format', 'text'), format_choices, 'format (--format)')
        law = parse_law(args%get('--damping', hertzdamp_law_name(HD_DAMPING_LINEAR)), '--damping')
        call t%set_columns('name,value')
        call t%meta('damping', hertzdamp_law_name(law))
        call t%str('alpha_c')
        if (hertzdamp_law_has_alpha_c(law)) then
            call hertzdamp_alpha_c(ac, status, law=law)
            if (status /= HD_OK) call fail(EXIT_FAILURE, 'alpha_c: ' // hertzdamp_message(status))
            call t%num(ac)
        else
            call t%none()   ! the overlap always returns: no critical damping
        end if
        call t%str('tau_c0')
        call t%num(hertzdamp_tau_c0())
        call t%str('z_max0')
        call t%num(hertzdamp_z_max0())
        call t%str('e1')
        call t%num(hertzdamp_e1(law))
        call t%render(fmt, buf)
        call buf%flush_to_stdout()
        call quit(EXIT_OK)
    end subroutine cmd_constants

end module hertzdamp_cmd_basic
