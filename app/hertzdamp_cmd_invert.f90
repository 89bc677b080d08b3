!> The commands `invert` (stiffness and damping from target restitution and contact
!> time) and `timestep` (the time step that resolves the physical contacts).
module hertzdamp_cmd_invert
    use hertzdamp, only: hertzdamp_rk, hertzdamp_invert, hertzdamp_invert_alpha, hertzdamp_invert_options, &
                         hertzdamp_message, hertzdamp_reduce, hertzdamp_hertz_time, hertzdamp_rayleigh_fraction, &
                         HD_OK, HD_BAD_RESTITUTION, HD_OUTSIDE_VALIDITY, HD_INACCURATE, HD_BAD_TIME, HD_BAD_VELOCITY, &
                         HD_OUT_OF_RANGE, HD_METHOD_ITERATIVE, HD_METHOD_FIT, HD_HOST_UNREACHABLE, HD_HOST_NONE, HD_BAD_PAIR, &
                         hertzdamp_pair_t, hertzdamp_pair_init, hertzdamp_pair_kd, hertzdamp_host_stats, &
                         hertzdamp_host_name, hertzdamp_host_min_steps, hertzdamp_host_mean, hertzdamp_forward_alpha, &
                         hertzdamp_collision, hertzdamp_host_choices, hertzdamp_host_code
    use hertzdamp_cli, only: cli_args, parse_args, parse_sweep, parse_choice, required_sweep, check_combinations, fail, &
                             EXIT_USAGE
    use hertzdamp_cli_text, only: itoa
    use hertzdamp_cli_text, only: fmt_short
    use hertzdamp_cli_output, only: out_table
    use hertzdamp_cli_help, only: print_help, wants_help
    use hertzdamp_cli_model, only: model_opts, parse_model, model_options, e_range_message, instead, damping_unit
    use hertzdamp_cli_rows, only: row_log, row_kind, row_word, row_has_result, ROW_OUTSIDE_VALIDITY, ROW_OUT_OF_RANGE
    use hertzdamp_cli_materials, only: cli_contact, parse_contact, require_mass, contact_table, contact_options, contact_flags
    use hertzdamp_cli_progress, only: progress_reporter
    use hertzdamp_cli_plausible, only: warn_implausible, quiet_flag
    use hertzdamp_cmd_fixed, only: invert_fixed
    use hertzdamp_cmd_phase, only: invert_phase
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private
    public :: cmd_invert, cmd_timestep

    integer, parameter :: wp = hertzdamp_rk

    !> The host schemes of --host, in the order of their codes (HD_HOST_* = 0, 1, ...).

    !> The --host of a command: the scheme and whether it was given.
    type :: host_opts
        logical :: given = .false.
        integer :: host = HD_HOST_NONE
    end type host_opts

contains

    !> --host: the host scheme (absent: none, no spread columns).  With --host the
    !> constants are those of hertzdamp_pair_init at N steps, so the steps are required;
    !> for a host other than none they come from the fit (no --method).
    subroutine parse_host(args, c, h)
        type(cli_args), intent(in) :: args
        type(model_opts), intent(in) :: c
        type(host_opts), intent(out) :: h
        integer :: k
        h%given = args%has('--host')
        if (.not. h%given) return
        k = parse_choice(args%get('--host', ''), hertzdamp_host_choices(), 'host scheme (--host)')
        h%host = hertzdamp_host_code(args%get('--host', ''))
        if (h%host /= HD_HOST_NONE .and. c%method /= HD_METHOD_FIT) then
            call fail(EXIT_USAGE, '--host ' // hertzdamp_host_name(h%host) // ': the host-exact constants come ' // &
                      'from the fit; --method applies to --host none')
        end if
    end subroutine parse_host

    !> Why a row of a host has no constants: the steps that cannot reach e, and the fewest
    !> that can (hertzdamp_host_min_steps), or the library's message.
    function host_reason(c, h, status, e, steps) result(s)
        type(model_opts), intent(in) :: c
        type(host_opts), intent(in) :: h
        integer, intent(in) :: status
        real(wp), intent(in) :: e, steps
        character(len=:), allocatable :: s
        integer :: nmin, st
        s = 'e = ' // fmt_short(e) // ', --steps ' // fmt_short(steps) // ' with --host ' // &
            hertzdamp_host_name(h%host) // ': ' // hertzdamp_message(status)
        if (status /= HD_HOST_UNREACHABLE) return
        call hertzdamp_host_min_steps(e, c%law, c%iend, h%host, nmin, st)
        s = 'N = ' // fmt_short(steps) // ' steps cannot reach e = ' // fmt_short(e) // ' with ' // &
            hertzdamp_host_name(h%host)
        if (st == HD_OK) then
            s = s // '; N >= ' // itoa(nmin) // ' can'
        else
            s = s // ' (' // hertzdamp_message(st) // ')'
        end if
    end function host_reason

    !> With --host: the spread columns, and what alpha, tau_c and the spreads are (the
    !> steps `where` as the command defines them) in the units line.
    subroutine host_columns(h, where, columns, units, column_units)
        type(host_opts), intent(in) :: h
        character(len=*), intent(in) :: where
        character(len=:), allocatable, intent(inout) :: columns, units, column_units
        if (.not. h%given) return
        columns = columns // 'e_spread,tc_spread,'
        column_units = column_units // ',,'
        units = units // '; host ' // hertzdamp_host_name(h%host) // ': alpha, tau_c its constants at N steps ' // &
                where // ', e_spread and tc_spread the standard deviations of the achieved e and T_c over the ' // &
                'onset phase, relative'
    end subroutine host_columns

    !> The relative spread over the onset phase (standard deviation / mean; 0 for none).
    pure real(wp) function relative_spread(sd, mean)
        real(wp), intent(in) :: sd, mean
        relative_spread = 0.0_wp
        if (mean > 0.0_wp) relative_spread = sd / mean
    end function relative_spread

    subroutine cmd_invert()
        type(cli_args) :: args
        type(model_opts) :: c
        type(cli_contact) :: ct
        real(wp), allocatable :: es(:), tcs(:), us(:), tc_dt(:), tc_steps(:)
        character(len=:), allocatable :: tc_key
        real(wp) :: e, tc, u, k, d, alpha, tstar, tau
        logical :: bound, have, tc_ok
        integer :: status, ie, it, iu, kind, n
        type(out_table) :: t
        type(row_log) :: rows
        type(progress_reporter) :: p
        type(host_opts) :: h
        type(hertzdamp_pair_t) :: pair
        type(hertzdamp_host_stats) :: stats, rstats
        integer :: st_pair
        real(wp) :: tc_act
        character(len=:), allocatable :: columns, units, column_units
        allocate (es(0), tcs(0), us(0), tc_dt(0), tc_steps(0))   ! (defined descriptors for the reallocating assignments)
        if (wants_help()) call print_help('invert')
        call parse_args(2, '--e --tc --dt --steps --velocity --host --onset-phase ' // contact_options // ' ' // &
                        model_options, contact_flags // ' --progress --fixed ' // quiet_flag, args)
        call parse_model(args, c, inverse=.true.)
        call parse_host(args, c, h)
        if (h%given .and. .not. (args%has('--dt') .and. args%has('--steps') .and. .not. args%has('--tc'))) then
            call fail(EXIT_USAGE, '--host needs --dt and --steps (the time step of the host and the steps per ' // &
                      'contact N it integrates with, T_c = N dt), not --tc')
        end if
        call parse_contact(args, ct)
        es = required_sweep(args, '--e')
        call contact_times(args, tcs, tc_key, tc_dt, tc_steps)
        us = required_sweep(args, '--velocity')
        call require_mass(ct)
        call check_combinations([size(es), size(tcs), size(us)], '--e, the contact times and --velocity')
        call warn_implausible(args)
        if (args%has('--onset-phase')) then
            if (.not. h%given .or. h%host == HD_HOST_NONE) then
                call fail(EXIT_USAGE, '--onset-phase needs --host with a scheme (and --dt, --steps): the onset ' // &
                          'phase is that of the host''s time steps')
            end if
            call invert_phase(args, c, ct, h%host, es, tcs, tc_steps, us)
        end if
        if (args%has('--fixed')) then
            if (h%given) call fail(EXIT_USAGE, '--fixed takes no --host (one k and d for every contact)')
            call invert_fixed(args, c, ct, es, tcs, tc_key, us)
        end if
        columns = 'e,tc,velocity,mass,radius_eff,k_phys,alpha,tau_c,t_star,k,d,bound_active,tc_actual,'
        units = 'tc, t_star, tc_actual [s], velocity [m/s], mass [kg], radius_eff [m], k, k_phys [N m^-3/2], d [' // &
                damping_unit(c%law) // ']'
        column_units = ',s,m/s,kg,m,N m^-3/2,,,s,N m^-3/2,' // damping_unit(c%law) // ',,s,'
        call host_columns(h, '(T_c = N dt)', columns, units, column_units)
        call contact_table(t, c, ct, columns // 'status', units, column_units)
        n = 0
        call p%start(real(size(es) * size(tcs) * size(us), wp), 'invert', force=args%has('--progress'))
        do ie = 1, size(es)
            do it = 1, size(tcs)
                ! a host: the pair's constants at these steps, once for every velocity
                if (h%given) call hertzdamp_pair_init(es(ie), c%law, c%iend, h%host, tc_steps(it), pair, st_pair, stats)
                do iu = 1, size(us)
                    e = es(ie)
                    tc = tcs(it)
                    u = us(iu)
                    ! dt x steps beyond double precision: valid input without a solution
                    tc_ok = ieee_is_finite(tc)
                    if (.not. tc_ok) then
                        status = HD_OUT_OF_RANGE
                    else if (h%given) then
                        call host_kd(pair, st_pair, tc, ct, u, k, d, status, tstar, bound)
                        alpha = pair%alpha
                        tau = pair%tau_c
                    else if (ct%has_kphys) then
                        call hertzdamp_invert(e, tc, ct%mass, u, c%iend, k, d, status, alpha, tstar, tau, bound, &
                                              ct%k_phys, c%law, hertzdamp_invert_options(c%method, c%tol, c%accuracy))
                    else
                        call hertzdamp_invert(e, tc, ct%mass, u, c%iend, k, d, status, alpha, tstar, tau, bound, &
                                              law=c%law, options=hertzdamp_invert_options(c%method, c%tol, c%accuracy))
                    end if
                    ! the contact time the returned k and d give (T_c, or longer when k = k_phys)
                    if (status == HD_OK .and. .not. ieee_is_finite(tstar * tau)) status = HD_OUT_OF_RANGE
                    tc_act = tstar * tau
                    rstats = stats
                    if (status == HD_OK .and. h%given .and. bound) then
                        call bound_host_contact(c, h, k, d, ct%mass, u, tc / tc_steps(it), tc_act, rstats, status)
                    end if
                    kind = row_kind(status)
                    if (status == HD_BAD_RESTITUTION .and. e >= 0.0_wp .and. e <= 1.0_wp) kind = ROW_OUTSIDE_VALIDITY
                    if (status == HD_HOST_UNREACHABLE) kind = ROW_OUTSIDE_VALIDITY
                    have = row_has_result(kind)
                    call row_numbers()
                    call t%str(row_word(kind))
                    if (have) then
                        call rows%add(kind, '')
                    else if (h%given .and. tc_ok .and. st_pair /= HD_OK) then
                        call rows%add(kind, host_reason(c, h, st_pair, e, tc_steps(it)))
                    else if (.not. tc_ok) then
                        call rows%add(kind, '--dt ' // fmt_short(tc_dt(it)) // ' x --steps ' // &
                                      fmt_short(tc_steps(it)) // ': the contact time is outside the ' // &
                                      'double-precision range')
                    else
                        call rows%add(kind, invert_reason(c, status, e, tc, u, tc_key))
                    end if
                    n = n + 1
                    call p%update(real(n, wp))
                end do
            end do
        end do
        call p%finish()
        call rows%emit(t, c%fmt)
    contains
        !> The numbers of one row (e, T_c, ..., the host's spreads), before its status.
        subroutine row_numbers()
        call t%num(e)
        call t%num_or_none(tc, tc_ok)
        call t%num(u)
        call t%num(ct%mass)
        call t%num_or_none(ct%radius, ct%has_radius)
        call t%num_or_none(ct%k_phys, ct%has_kphys)
        call t%num_or_none(alpha, have)
        call t%num_or_none(tau, have)
        call t%num_or_none(tstar, have)
        call t%num_or_none(k, have)
        call t%num_or_none(d, have)
        if (have) then
            call t%bool(bound)
        else
            call t%none()
        end if
        call t%num_or_none(tc_act, have)
        if (h%given) then
            call t%num_or_none(relative_spread(rstats%e_sd, rstats%e_mean), have)
            call t%num_or_none(relative_spread(rstats%tau_sd, rstats%tau_mean), have)
        end if
        end subroutine row_numbers
    end subroutine cmd_invert

    !> A host's contact where the bound is active (issue 30, defect 3): it keeps k = k_phys and
    !> lasts more than N steps, so its time unit t* and damping alpha are those of its own k and
    !> d (hertzdamp_reduce), and its step h' = dt / t* is below the pair's.  tc_act is then the
    !> phase mean of the host's collision at (alpha, h') times t*, and stats its spreads there;
    !> an h' below the host schemes' range (1e-5) is the continuous contact (no spread).
    subroutine bound_host_contact(c, h, k, d, m, u, dt, tc_act, stats, status)
        type(model_opts), intent(in) :: c
        type(host_opts), intent(in) :: h
        real(wp), intent(in) :: k, d, m, u, dt
        real(wp), intent(out) :: tc_act
        type(hertzdamp_host_stats), intent(out) :: stats
        integer, intent(inout) :: status
        real(wp) :: a, ts
        type(hertzdamp_collision) :: r
        tc_act = 0.0_wp
        call hertzdamp_reduce(k, d, m, u, a, ts, status, c%law)
        if (status /= HD_OK) return
        if (dt / ts >= 1.0e-5_wp) then
            call hertzdamp_host_mean(a, dt / ts, c%law, c%iend, h%host, stats, status)
        else
            r = hertzdamp_forward_alpha(a, c%iend, HD_METHOD_FIT, law=c%law)
            status = r%status
            stats = hertzdamp_host_stats(r%e, 0.0_wp, r%e, r%e, r%tau_c, 0.0_wp, r%tau_c, r%tau_c)
        end if
        if (status == HD_OK) tc_act = stats%tau_mean * ts
    end subroutine bound_host_contact

    !> k and d of one contact from a host's pair (st_pair: its init's status, reported
    !> when the contact's arguments are valid), with the bound when the contact has one.
    subroutine host_kd(pair, st_pair, tc, ct, u, k, d, status, tstar, bound)
        type(hertzdamp_pair_t), intent(in) :: pair
        integer, intent(in) :: st_pair
        real(wp), intent(in) :: tc, u
        type(cli_contact), intent(in) :: ct
        real(wp), intent(out) :: k, d, tstar
        integer, intent(out) :: status
        logical, intent(out) :: bound
        if (ct%has_kphys) then
            call hertzdamp_pair_kd(pair, tc, ct%mass, u, k, d, status, k_phys=ct%k_phys, bound_active=bound, &
                                   tstar=tstar)
        else
            call hertzdamp_pair_kd(pair, tc, ct%mass, u, k, d, status, bound_active=bound, tstar=tstar)
        end if
        if (status == HD_BAD_PAIR) status = st_pair
    end subroutine host_kd

    !> The target contact times: --tc LIST, or every --dt times every --steps (a
    !> product beyond double precision is inf: that row is out-of-range).
    subroutine contact_times(args, tcs, key, tc_dt, tc_steps)
        type(cli_args), intent(in) :: args
        real(wp), allocatable, intent(out) :: tcs(:)
        character(len=:), allocatable, intent(out) :: key   !! the option the times come from
        real(wp), allocatable, intent(out) :: tc_dt(:), tc_steps(:)   !! the factors of each time (0 with --tc)
        real(wp), allocatable :: dts(:), steps(:)
        integer :: i, j
        if (args%has('--tc')) then
            if (args%has('--dt') .or. args%has('--steps')) then
                call fail(EXIT_USAGE, 'give either --tc or --dt with --steps, not both')
            end if
            tcs = parse_sweep(args%get('--tc', ''), '--tc')
            key = '--tc'
            tc_dt = 0.0_wp * tcs
            tc_steps = tc_dt
            return
        end if
        if (.not. (args%has('--dt') .and. args%has('--steps'))) then
            call fail(EXIT_USAGE, 'missing option --tc (or --dt with --steps) (see --help)')
        end if
        dts = parse_sweep(args%get('--dt', ''), '--dt')
        steps = parse_steps(args)
        call check_combinations([size(dts), size(steps)], '--dt and --steps')
        tc_dt = [((dts(i), j=1, size(steps)), i=1, size(dts))]
        tc_steps = [((steps(j), j=1, size(steps)), i=1, size(dts))]
        tcs = tc_dt * tc_steps
        key = '--dt x --steps'
    end subroutine contact_times

    !> --steps: whole numbers >= 1 (a list or range of them).  A linear range of whole
    !> numbers gives them exactly (parse_range); a value within 4 ulp of a whole number,
    !> as a logarithmic range gives (1:1000:log4 has 9.999999999999998), is taken as it.
    function parse_steps(args, default) result(steps)
        type(cli_args), intent(in) :: args
        real(wp), intent(in), optional :: default
        real(wp), allocatable :: steps(:)
        real(wp) :: r
        integer :: i
        if (.not. args%has('--steps') .and. present(default)) then
            steps = [default]
            return
        end if
        steps = parse_sweep(args%get('--steps', ''), '--steps')
        do i = 1, size(steps)
            r = anint(steps(i))
            if (abs(steps(i) - r) <= 4.0_wp * spacing(r)) steps(i) = r
            if (.not. (steps(i) >= 1.0_wp .and. steps(i) <= 1.0e9_wp .and. steps(i) == anint(steps(i)))) then
                call fail(EXIT_USAGE, '--steps ' // fmt_short(steps(i)) // ': time steps per contact must be ' // &
                          'a whole number from 1 to 1e9')
            end if
        end do
    end function parse_steps

    !> Why an `invert` row has no result, naming the option.
    function invert_reason(c, status, e, tc, u, tc_key) result(s)
        type(model_opts), intent(in) :: c
        integer, intent(in) :: status
        real(wp), intent(in) :: e, tc, u
        character(len=*), intent(in) :: tc_key
        character(len=:), allocatable :: s
        select case (status)
        case (HD_BAD_RESTITUTION, HD_OUTSIDE_VALIDITY)
            s = e_range_message(c, e, fmt_short(e))
        case (HD_INACCURATE)
            s = '--e ' // fmt_short(e) // ': the error estimate of --method ' // c%method_name // &
                ' exceeds --accuracy ' // fmt_short(c%accuracy) // ' there (raise --accuracy, or ' // instead(c) // ')'
        case (HD_BAD_TIME)
            s = tc_key // ' (contact time ' // fmt_short(tc) // '): ' // hertzdamp_message(status)
        case (HD_BAD_VELOCITY)
            s = '--velocity ' // fmt_short(u) // ': ' // hertzdamp_message(status)
        case (HD_OUT_OF_RANGE)
            s = 'e = ' // fmt_short(e) // ', tc = ' // fmt_short(tc) // ', velocity = ' // fmt_short(u) // &
                ': k or d is outside the double-precision range'
        case default
            s = 'e = ' // fmt_short(e) // ': ' // hertzdamp_message(status)
            if (c%method == HD_METHOD_ITERATIVE) s = s // ' (try --method fit)'
        end select
    end function invert_reason

    !> `timestep`: for materials and a velocity range, the shortest contact of the
    !> physical model (k = k_phys, d from e) and the largest time step that resolves
    !> it with N steps, next to the elastic Hertz estimate and the Rayleigh time step
    !> of the spheres (from the elastic constants and densities).
    subroutine cmd_timestep()
        type(cli_args) :: args
        type(model_opts) :: c
        type(cli_contact) :: ct
        real(wp), allocatable :: es(:), us(:), steps(:)
        real(wp) :: alpha, tau, tstar, a0, tmin, thertz, th, umax, tcd, excess, dtmax, dt_el
        integer :: status, ie, is, iu, kind, rkind, st
        logical :: have, rhave
        type(out_table) :: t
        type(row_log) :: rows
        type(host_opts) :: h
        type(hertzdamp_pair_t) :: pair
        type(hertzdamp_host_stats) :: stats
        character(len=:), allocatable :: columns, units, column_units
        allocate (es(0), us(0), steps(0))
        if (wants_help()) call print_help('timestep')
        call parse_args(2, '--e --velocity --steps --host ' // contact_options // ' ' // model_options, &
                        contact_flags // ' ' // quiet_flag, args)
        call parse_model(args, c, inverse=.true.)
        call parse_host(args, c, h)
        if (h%given .and. .not. args%has('--steps')) then
            call fail(EXIT_USAGE, '--host needs --steps (the steps per contact N the host integrates with; ' // &
                      'timestep gives the time step dt_max for them)')
        end if
        call parse_contact(args, ct)
        call require_mass(ct)
        if (.not. ct%has_kphys) call fail(EXIT_USAGE, 'missing option --k-phys (or --radius with --youngs-modulus ' // &
                                          'and --poisson-ratio) (see --help)')
        es = required_sweep(args, '--e')
        us = required_sweep(args, '--velocity')
        steps = parse_steps(args, 10.0_wp)
        call check_combinations([size(es), size(steps)], '--e and --steps')
        call warn_implausible(args)
        call fastest_contact()

        columns = 'e,steps,velocity_max,mass,radius_eff,k_phys,alpha,tau_c,tc_damped,tc_elastic,elastic_excess,' // &
                  'dt_max,dt_elastic,t_rayleigh,dt_rayleigh,'
        units = 'velocity_max [m/s], mass [kg], radius_eff [m], k_phys [N m^-3/2], tc_damped, tc_elastic, dt_max, ' // &
                'dt_elastic, t_rayleigh, dt_rayleigh [s]; elastic_excess = tc_elastic/tc_damped - 1; dt_rayleigh = ' // &
                fmt_short(hertzdamp_rayleigh_fraction) // ' t_rayleigh'
        column_units = ',,m/s,kg,m,N m^-3/2,,,s,s,,s,s,s,s,'
        call host_columns(h, '(the fastest contact at dt_max)', columns, units, column_units)
        call contact_table(t, c, ct, columns // 'status', units, column_units)
        do ie = 1, size(es)
            if (.not. h%given) then
                call hertzdamp_invert_alpha(es(ie), c%iend, alpha, tau, status, c%method, c%tol, c%accuracy, c%law)
                call row_of(status)
            end if
            do is = 1, size(steps)
                if (h%given) then
                    ! the host's constants depend on the steps
                    call hertzdamp_pair_init(es(ie), c%law, c%iend, h%host, steps(is), pair, status, stats)
                    alpha = pair%alpha
                    tau = pair%tau_c
                    call row_of(status)
                end if
                ! the damped contact, its time steps and the elastic ones: every number
                ! the row prints must be finite and the time steps positive
                tcd = tmin * tau
                dt_el = thertz / steps(is)
                rkind = kind
                excess = 0.0_wp
                dtmax = 0.0_wp
                if (have) then
                    excess = thertz / tcd - 1.0_wp
                    dtmax = tcd / steps(is)
                    if (.not. (ieee_is_finite(tcd) .and. ieee_is_finite(excess) .and. dtmax > 0.0_wp)) then
                        rkind = ROW_OUT_OF_RANGE
                    end if
                end if
                if (.not. dt_el > 0.0_wp) rkind = ROW_OUT_OF_RANGE
                rhave = row_has_result(rkind)
                call row_numbers()
                call t%str(row_word(rkind))
                if (rhave) then
                    call rows%add(rkind, '')
                else if (h%given .and. status /= HD_OK) then
                    call rows%add(rkind, host_reason(c, h, status, es(ie), steps(is)))
                else if (have .or. .not. dt_el > 0.0_wp) then
                    call rows%add(rkind, '--e ' // fmt_short(es(ie)) // ' with --steps ' // fmt_short(steps(is)) // &
                                  ': the damped contact time t* tau_c (t* = ' // fmt_short(tmin) // ' s, tau_c = ' // &
                                  fmt_short(tau) // ') or its time step is outside the double-precision range')
                else
                    call rows%add(rkind, invert_reason(c, status, es(ie), 0.0_wp, 0.0_wp, ''))
                end if
            end do
        end do
        call rows%emit(t, c%fmt)
    contains
        !> The time unit t* and the elastic Hertz time at every velocity (both fall as
        !> u^(-1/5)): their smallest values tmin, thertz and the fastest speed umax.
        subroutine fastest_contact()
    tmin = huge(1.0_wp)
    thertz = huge(1.0_wp)
    umax = 0.0_wp
    do iu = 1, size(us)
        call hertzdamp_reduce(ct%k_phys, 0.0_wp, ct%mass, us(iu), a0, tstar, st)
        if (st == HD_OK) call hertzdamp_hertz_time(ct%mass, ct%k_phys, us(iu), th, st)
        if (st == HD_BAD_VELOCITY) call fail(EXIT_USAGE, '--velocity ' // fmt_short(us(iu)) // ': ' // &
                                             hertzdamp_message(st))
        if (st /= HD_OK) call fail(EXIT_USAGE, '--velocity ' // fmt_short(us(iu)) // &
                                   ': the contact time is outside the double-precision range')
        if (tstar < tmin) umax = us(iu)
        tmin = min(tmin, tstar)
        thertz = min(thertz, th)
    end do
        end subroutine fastest_contact

        !> The numbers of one row (e, steps, ..., the host's spreads), before its status.
        subroutine row_numbers()
        call t%num(es(ie))
        call t%num(steps(is))
        call t%num(umax)
        call t%num(ct%mass)
        call t%num_or_none(ct%radius, ct%has_radius)
        call t%num(ct%k_phys)
        call t%num_or_none(alpha, have)
        call t%num_or_none(tau, have)
        call t%num_or_none(tcd, rhave)
        call t%num(thertz)
        call t%num_or_none(excess, rhave)
        call t%num_or_none(dtmax, rhave)
        call t%num_or_none(dt_el, dt_el > 0.0_wp)
        call t%num_or_none(ct%t_rayleigh, ct%has_rayleigh)
        call t%num_or_none(hertzdamp_rayleigh_fraction * ct%t_rayleigh, ct%has_rayleigh)
        if (h%given) then
            call t%num_or_none(relative_spread(stats%e_sd, stats%e_mean), rhave)
            call t%num_or_none(relative_spread(stats%tau_sd, stats%tau_mean), rhave)
        end if
        end subroutine row_numbers

        !> The row kind of the constants' status.
        subroutine row_of(st)
            integer, intent(in) :: st
            kind = row_kind(st)
            if (st == HD_BAD_RESTITUTION .and. es(ie) >= 0.0_wp .and. es(ie) <= 1.0_wp) kind = ROW_OUTSIDE_VALIDITY
            if (st == HD_HOST_UNREACHABLE) kind = ROW_OUTSIDE_VALIDITY
            have = row_has_result(kind)
        end subroutine row_of
    end subroutine cmd_timestep

end module hertzdamp_cmd_invert
