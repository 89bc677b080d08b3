!> `invert --fixed`: the best single fixed stiffness and damping for an engine that
!> cannot set them per contact (hertzdamp_fixed): over the range of the --velocity
!> list, the worst relative error of e is as small as one (k, d) can make it, and the
!> shortest contact of the range lasts the target time (--tc, or --dt x --steps).
!> One row per target and listed speed: what that pair achieves there.
module hertzdamp_cmd_fixed
    use hertzdamp, only: hertzdamp_rk, hertzdamp_forward_dim, hertzdamp_message, HD_OK, HD_NO_REBOUND, &
                         HD_OUTSIDE_VALIDITY, HD_BAD_RESTITUTION, HD_BAD_VELOCITY, HD_BAD_TIME, HD_METHOD_FIT, &
                         HD_METHOD_RK45
    use hertzdamp_fixed, only: fixed_pair, hertzdamp_fixed_pair
    use hertzdamp_cli, only: cli_args, fail, EXIT_USAGE
    use hertzdamp_cli_text, only: fmt_short
    use hertzdamp_cli_output, only: out_table
    use hertzdamp_cli_model, only: model_opts, damping_unit, e_range_message
    use hertzdamp_cli_rows, only: row_log, row_kind, row_word, row_has_result, ROW_OUTSIDE_VALIDITY
    use hertzdamp_cli_materials, only: cli_contact, contact_table
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
    implicit none
    private
    public :: invert_fixed

    integer, parameter :: wp = hertzdamp_rk

contains

    !> The table of `invert --fixed` for the parsed targets and speeds; never returns.
    subroutine invert_fixed(args, c, ct, es, tcs, tc_key, us)
        type(cli_args), intent(in) :: args
        type(model_opts), intent(in) :: c
        type(cli_contact), intent(in) :: ct
        real(wp), intent(in) :: es(:), tcs(:), us(:)   !! targets e and shortest contact times, the speeds
        character(len=*), intent(in) :: tc_key          !! the option the times come from
        type(fixed_pair) :: p
        type(out_table) :: t
        type(row_log) :: rows
        real(wp) :: alpha, tstar, e, tc, zmax
        integer :: ie, it, iu, st, kind
        logical :: have
        character(len=:), allocatable :: why
        if (args%has('--method') .or. args%has('--tol') .or. args%has('--accuracy')) then
            call fail(EXIT_USAGE, '--fixed finds k and d with the fitted forward maps of the law (rk45 beyond them): ' // &
                      '--method, --tol and --accuracy do not apply')
        end if
        call contact_table(t, c, ct, 'e,tc,velocity,mass,radius_eff,k_phys,k,d,bound_active,alpha,e_fixed,e_error,' // &
                           'tc_fixed,worst_e_error,status', 'tc, tc_fixed [s], velocity [m/s], mass [kg], ' // &
                           'radius_eff [m], k, k_phys [N m^-3/2], d [' // damping_unit(c%law) // ']; ' // &
                           'e_error = e_fixed/e - 1', &
                           ',s,m/s,kg,m,N m^-3/2,N m^-3/2,' // damping_unit(c%law) // ',,,,,s,,')
        call t%meta('fixed', 'one k and d for every contact: the worst |e_fixed/e - 1| over the speeds ' // &
                    fmt_short(minval(us)) // ' to ' // fmt_short(maxval(us)) // ' m/s as small as it can be, ' // &
                    'the shortest contact of that range lasting tc')
        do ie = 1, size(es)
            do it = 1, size(tcs)
                if (ct%has_kphys) then
                    p = hertzdamp_fixed_pair(es(ie), tcs(it), ct%mass, minval(us), maxval(us), c%iend, c%law, ct%k_phys)
                else
                    p = hertzdamp_fixed_pair(es(ie), tcs(it), ct%mass, minval(us), maxval(us), c%iend, c%law)
                end if
                why = ''
                if (p%status /= HD_OK) why = reason(c, p%status, es(ie), tcs(it), tc_key, us)
                do iu = 1, size(us)
                    st = p%status
                    if (st == HD_OK) call achieved(p, ct%mass, us(iu), c, alpha, tstar, e, tc, zmax, st)
                    kind = row_kind(st)
                    ! an e in [0, 1] that the law's maps do not reach: outside validity, as in invert
                    if (st == HD_BAD_RESTITUTION .and. es(ie) >= 0.0_wp .and. es(ie) <= 1.0_wp) kind = ROW_OUTSIDE_VALIDITY
                    have = row_has_result(kind)
                    call t%num(es(ie))
                    call t%num(tcs(it))
                    call t%num(us(iu))
                    call t%num(ct%mass)
                    call t%num_or_none(ct%radius, ct%has_radius)
                    call t%num_or_none(ct%k_phys, ct%has_kphys)
                    call t%num_or_none(p%k, p%status == HD_OK)
                    call t%num_or_none(p%d, p%status == HD_OK)
                    if (p%status == HD_OK) then
                        call t%bool(p%bound_active)
                    else
                        call t%none()
                    end if
                    call t%num_or_none(alpha, have)
                    call t%num_or_none(e, have)
                    call t%num_or_none(e / es(ie) - 1.0_wp, have)
                    call t%num_or_none(tc, have)
                    call t%num_or_none(p%worst, p%status == HD_OK)
                    call t%str(row_word(kind))
                    if (have) then
                        call rows%add(kind, '')
                    else if (p%status /= HD_OK) then
                        call rows%add(kind, why)
                    else
                        call rows%add(kind, '--velocity ' // fmt_short(us(iu)) // ': ' // hertzdamp_message(st))
                    end if
                end do
            end do
        end do
        call rows%emit(t, c%fmt)
    end subroutine invert_fixed

    !> What the pair does at one speed: the fit, rk45 beyond its range; no rebound
    !> is a result (e = 0, contact time inf).
    subroutine achieved(p, m, u, c, alpha, tstar, e, tc, zmax, status)
        type(fixed_pair), intent(in) :: p
        real(wp), intent(in) :: m, u
        type(model_opts), intent(in) :: c
        real(wp), intent(out) :: alpha, tstar, e, tc, zmax
        integer, intent(out) :: status
        call hertzdamp_forward_dim(p%k, p%d, m, u, c%iend, HD_METHOD_FIT, alpha, tstar, e, tc, zmax, status, law=c%law)
        if (status == HD_OUTSIDE_VALIDITY) then
            call hertzdamp_forward_dim(p%k, p%d, m, u, c%iend, HD_METHOD_RK45, alpha, tstar, e, tc, zmax, status, &
                                       law=c%law)
        end if
        if (status == HD_NO_REBOUND) then
            e = 0.0_wp
            tc = ieee_value(1.0_wp, ieee_positive_inf)
        end if
    end subroutine achieved

    !> Why no pair exists for a target, naming the option.
    function reason(c, status, e, tc, tc_key, us) result(s)
        type(model_opts), intent(in) :: c
        integer, intent(in) :: status
        real(wp), intent(in) :: e, tc, us(:)
        character(len=*), intent(in) :: tc_key
        character(len=:), allocatable :: s
        select case (status)
        case (HD_BAD_RESTITUTION, HD_OUTSIDE_VALIDITY)
            s = e_range_message(c, e, fmt_short(e))
        case (HD_BAD_VELOCITY)
            s = '--velocity ' // fmt_short(minval(us)) // ': ' // hertzdamp_message(status)
        case (HD_BAD_TIME)
            s = tc_key // ' (contact time ' // fmt_short(tc) // '): ' // hertzdamp_message(status)
        case default
            s = 'e = ' // fmt_short(e) // ', ' // tc_key // ' (contact time ' // fmt_short(tc) // '): ' // &
                hertzdamp_message(status)
        end select
    end function reason

end module hertzdamp_cmd_fixed
