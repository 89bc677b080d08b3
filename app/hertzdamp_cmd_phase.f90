!> `invert --host S --dt DT --steps N --onset-phase LIST`: per-contact constants from the
!> onset phase (issue 32, hertzdamp_pair_kd_phase).  One row per target, speed and onset
!> phase: that contact's alpha(phi), tau(phi), k and d, which make its own e and T_c = N dt
!> exact in the host's scheme (not only their mean over the phase, as --host alone).
module hertzdamp_cmd_phase
    use hertzdamp, only: hertzdamp_rk, hertzdamp_message, hertzdamp_reduce, HD_OK, HD_PHASE_UNREACHABLE, &
                         HD_BAD_RESTITUTION, HD_HOST_UNREACHABLE, hertzdamp_pair_t, hertzdamp_pair_init, &
                         hertzdamp_pair_kd_phase, hertzdamp_pair_phase_constants, hertzdamp_phase_min_steps, &
                         hertzdamp_host_name
    use hertzdamp_cli, only: cli_args, parse_sweep, check_combinations, fail, EXIT_USAGE
    use hertzdamp_cli_text, only: fmt_short, itoa
    use hertzdamp_cli_output, only: out_table
    use hertzdamp_cli_model, only: model_opts, damping_unit, e_range_message
    use hertzdamp_cli_rows, only: row_log, row_kind, row_word, row_has_result, ROW_OUTSIDE_VALIDITY
    use hertzdamp_cli_materials, only: cli_contact, contact_table
    implicit none
    private
    public :: invert_phase

    integer, parameter :: wp = hertzdamp_rk

contains

    !> The --onset-phase list: every value in (0, 1] (exit 2 naming the option otherwise).
    function parse_phases(args) result(ph)
        type(cli_args), intent(in) :: args
        real(wp), allocatable :: ph(:)
        integer :: i
        ph = parse_sweep(args%get('--onset-phase', ''), '--onset-phase')
        do i = 1, size(ph)
            if (.not. (ph(i) > 0.0_wp .and. ph(i) <= 1.0_wp)) then
                call fail(EXIT_USAGE, '--onset-phase ' // fmt_short(ph(i)) // ': an onset phase must be finite ' // &
                          'and in (0, 1] (the first overlap over u_in dt)')
            end if
        end do
    end function parse_phases

    !> The table of `invert --onset-phase` (host, targets T_c = N dt and speeds parsed by
    !> cmd_invert); never returns.  Columns: e, tc, velocity, mass, radius_eff, k_phys,
    !> onset_phase, alpha, tau_c (the phase's constants), t_star (time unit of the returned
    !> k), k, d, bound_active, status.
    subroutine invert_phase(args, c, ct, host, es, tcs, steps, us)
        type(cli_args), intent(in) :: args
        type(model_opts), intent(in) :: c
        type(cli_contact), intent(in) :: ct
        integer, intent(in) :: host                     !! the --host scheme (not none)
        real(wp), intent(in) :: es(:), tcs(:), steps(:), us(:)   !! targets, T_c = N dt, N, speeds
        real(wp), allocatable :: ph(:)
        type(hertzdamp_pair_t) :: pair
        type(out_table) :: t
        type(row_log) :: rows
        real(wp) :: k, d, a, tau, ts, ar, kp
        integer :: ie, it, iu, ip, st, st_pair, kind, s2
        logical :: have
        character(len=:), allocatable :: why
        allocate (ph(0))   ! (a defined descriptor for the reallocating assignment)
        if (args%has('--fixed')) call fail(EXIT_USAGE, '--onset-phase takes no --fixed (per-contact constants)')
        ph = parse_phases(args)
        call check_combinations([size(es), size(tcs), size(us), size(ph)], &
                                '--e, the contact times, --velocity and --onset-phase')
        call contact_table(t, c, ct, 'e,tc,velocity,mass,radius_eff,k_phys,onset_phase,alpha,tau_c,t_star,k,d,' // &
                           'bound_active,status', 'tc, t_star [s], velocity [m/s], mass [kg], radius_eff [m], k, ' // &
                           'k_phys [N m^-3/2], d [' // damping_unit(c%law) // ']; host ' // hertzdamp_host_name(host) // &
                           ': alpha, tau_c the constants of the onset phase, which make that contact''s e and ' // &
                           'T_c = N dt exact in the host''s N-step collision', &
                           ',s,m/s,kg,m,N m^-3/2,,,,s,N m^-3/2,' // damping_unit(c%law) // ',,')
        kp = 0.0_wp
        if (ct%has_kphys) kp = ct%k_phys
        do ie = 1, size(es)
            do it = 1, size(tcs)
                call hertzdamp_pair_init(es(ie), c%law, c%iend, host, steps(it), pair, st_pair, phase=.true.)
                why = ''
                if (st_pair /= HD_OK) why = init_reason(c, host, st_pair, es(ie), steps(it))
                do iu = 1, size(us)
                    do ip = 1, size(ph)
                        a = 0.0_wp
                        tau = 0.0_wp
                        ts = 0.0_wp
                        call hertzdamp_pair_kd_phase(pair, tcs(it), ct%mass, us(iu), kp, ph(ip), k, d, st)
                        if (st == HD_OK) call hertzdamp_pair_phase_constants(pair, ph(ip), a, tau, s2)
                        if (st == HD_OK) call hertzdamp_reduce(k, d, ct%mass, us(iu), ar, ts, st, c%law)
                        if (st /= HD_OK .and. st_pair /= HD_OK) st = st_pair
                        kind = row_kind(st)
                        if (st == HD_PHASE_UNREACHABLE .or. st == HD_HOST_UNREACHABLE) kind = ROW_OUTSIDE_VALIDITY
                        if (st == HD_BAD_RESTITUTION .and. es(ie) >= 0.0_wp .and. es(ie) <= 1.0_wp) then
                            kind = ROW_OUTSIDE_VALIDITY
                        end if
                        have = row_has_result(kind)
                        call t%num(es(ie))
                        call t%num(tcs(it))
                        call t%num(us(iu))
                        call t%num(ct%mass)
                        call t%num_or_none(ct%radius, ct%has_radius)
                        call t%num_or_none(ct%k_phys, ct%has_kphys)
                        call t%num(ph(ip))
                        call t%num_or_none(a, have)
                        call t%num_or_none(tau, have)
                        call t%num_or_none(ts, have)
                        call t%num_or_none(k, have)
                        call t%num_or_none(d, have)
                        if (have) then
                            call t%bool(ct%has_kphys .and. k == kp)
                        else
                            call t%none()
                        end if
                        call t%str(row_word(kind))
                        if (have) then
                            call rows%add(kind, '')
                        else if (st_pair /= HD_OK) then
                            call rows%add(kind, why)
                        else
                            call rows%add(kind, 'e = ' // fmt_short(es(ie)) // ', --velocity ' // fmt_short(us(iu)) // &
                                          ': ' // hertzdamp_message(st))
                        end if
                    end do
                end do
            end do
        end do
        call rows%emit(t, c%fmt)
    end subroutine invert_phase

    !> Why the pair has no table: e outside the law's range, or the fewest N that reach
    !> every onset phase (hertzdamp_phase_min_steps), or the library's message.
    function init_reason(c, host, status, e, steps) result(s)
        type(model_opts), intent(in) :: c
        integer, intent(in) :: host, status
        real(wp), intent(in) :: e, steps
        character(len=:), allocatable :: s
        integer :: nmin, st
        if (status == HD_BAD_RESTITUTION) then
            s = e_range_message(c, e, fmt_short(e))
            return
        end if
        s = 'e = ' // fmt_short(e) // ', --steps ' // fmt_short(steps) // ' with --host ' // hertzdamp_host_name(host) // &
            ' --onset-phase: ' // hertzdamp_message(status)
        if (status /= HD_PHASE_UNREACHABLE .and. status /= HD_HOST_UNREACHABLE) return
        call hertzdamp_phase_min_steps(e, c%law, c%iend, host, nmin, st)
        if (st == HD_OK) then
            s = 'e = ' // fmt_short(e) // ': N = ' // fmt_short(steps) // ' steps cannot reach it at every onset ' // &
                'phase with ' // hertzdamp_host_name(host) // '; N >= ' // itoa(nmin) // ' can'
        end if
    end function init_reason

end module hertzdamp_cmd_phase
