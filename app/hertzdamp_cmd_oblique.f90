!> The command `oblique`: the oblique frictional impact of a sphere on a wall or a second
!> sphere (hertzdamp_oblique), physical or softened to T_c = N dt with the adapted
!> tangential constants (doc/oblique.md).
module hertzdamp_cmd_oblique
    use hertzdamp, only: hertzdamp_rk, hertzdamp_pi, hertzdamp_message, HD_OK, hertzdamp_oblique_t, &
                         hertzdamp_oblique_result, hertzdamp_oblique_impact, hertzdamp_tangential_kt, &
                         hertzdamp_oblique_correct, hertzdamp_invert, hertzdamp_reduce, hertzdamp_expand, &
                         hertzdamp_fit_inverse, hertzdamp_tangential_choices, hertzdamp_tangential_code, &
                         hertzdamp_lever_choices, hertzdamp_lever_code, HD_TANGENTIAL_MINDLIN, HD_LEVER_RADIUS, &
                         HD_LEVER_CONTACT
    use hertzdamp_cli, only: cli_args, parse_args, parse_real, parse_choice, required_sweep, fail, EXIT_USAGE
    use hertzdamp_cli_output, only: out_table
    use hertzdamp_cli_help, only: print_help, wants_help
    use hertzdamp_cli_model, only: model_opts, parse_model, model_options, damping_unit
    use hertzdamp_cli_rows, only: row_log, row_kind, row_word, row_has_result
    use hertzdamp_cli_materials, only: cli_contact, parse_contact, contact_table, contact_options, contact_flags
    use hertzdamp_cli_plausible, only: warn_implausible, quiet_flag
    implicit none
    private
    public :: cmd_oblique

    integer, parameter :: wp = hertzdamp_rk

    !> What the oblique options give.
    type :: oblique_opts
        real(wp) :: e = 0.0_wp, u = 0.0_wp, dt = 0.0_wp, steps = 0.0_wp
        real(wp), allocatable :: angles(:)
        type(hertzdamp_oblique_t) :: c          ! the physical contact (k = k_phys, d set per angle)
        logical :: soft = .false., adapted = .true., correct = .false.
    end type oblique_opts

contains

    !> `hertzdamp oblique`: one row per angle.
    subroutine cmd_oblique()
        type(cli_args) :: args
        type(model_opts) :: m
        type(cli_contact) :: ct
        type(oblique_opts) :: o
        type(out_table) :: t
        type(row_log) :: rows
        type(hertzdamp_oblique_result) :: rp, rs
        type(hertzdamp_oblique_t) :: cs
        character(len=:), allocatable :: columns, units, cu
        real(wp) :: eta, et
        integer :: ia, st, kind
        if (wants_help()) call print_help('oblique')
        call parse_args(2, '--e --velocity --angle --tangential --friction --kt --xgammat --lever --dt --steps ' // &
                        '--tangential-stiffness ' // contact_options // ' ' // model_options, &
                        contact_flags // ' --normal-correction ' // quiet_flag, args)
        call parse_model(args, m, inverse=.true.)
        call parse_contact(args, ct)
        call parse_oblique(args, m, ct, o)
        call warn_implausible(args)
        columns = 'angle,e_n,e_t,vt_ratio,rebound_angle,omega,'
        cu = 'deg,,,,deg,rad/s,'
        units = 'angle, rebound_angle [deg], omega [rad/s]'
        if (o%soft) then
            columns = columns // 'k,d,kt,eta_t,diff_e_n,diff_e_t,diff_vt_ratio,diff_rebound_angle,diff_omega,'
            cu = cu // 'N m^-3/2,' // damping_unit(m%law) // ',,' // damping_unit(m%law) // ',,,,deg,rad/s,'
            units = units // ', k [N m^-3/2], d, eta_t [' // damping_unit(m%law) // '], kt [N/m^2 mindlin, ' // &
                    'N/m linear_history]; diff_*: softened - physical'
            if (o%correct) then
                columns = columns // 'e_target,'
                cu = cu // ','
            end if
        end if
        call contact_table(t, m, ct, columns // 'status', units, cu)
        call t%meta('tangential', args%get('--tangential', 'mindlin'))
        do ia = 1, size(o%angles)
            call physical(o, m, o%angles(ia), rp, st)
            if (st == HD_OK .and. o%soft) call softened(o, m, o%angles(ia), cs, et, rs, st)
            kind = row_kind(st)
            call t%num(o%angles(ia))
            if (o%soft) then
                call outcome(t, rs, st == HD_OK)
                eta = cs%xgammat * cs%d
                call t%num_or_none(cs%k, st == HD_OK)
                call t%num_or_none(cs%d, st == HD_OK)
                call t%num_or_none(cs%kt, st == HD_OK)
                call t%num_or_none(eta, st == HD_OK)
                call t%num_or_none(rs%e_n - rp%e_n, st == HD_OK)
                call t%num_or_none(rs%e_t - rp%e_t, st == HD_OK)
                call t%num_or_none(rs%vt_ratio - rp%vt_ratio, st == HD_OK)
                call t%num_or_none(rs%rebound_angle - rp%rebound_angle, st == HD_OK)
                call t%num_or_none(rs%omega1 - rp%omega1, st == HD_OK)
                if (o%correct) call t%num_or_none(et, st == HD_OK)
            else
                call outcome(t, rp, st == HD_OK)
            end if
            call t%str(row_word(kind))
            if (row_has_result(kind)) then
                call rows%add(kind, '')
            else
                call rows%add(kind, 'angle ' // args%get('--angle', '') // ': ' // hertzdamp_message(st))
            end if
        end do
        call rows%emit(t, m%fmt)
    end subroutine cmd_oblique

    !> The outcome's columns (omega: sphere 1's).
    subroutine outcome(t, r, have)
        type(out_table), intent(inout) :: t
        type(hertzdamp_oblique_result), intent(in) :: r
        logical, intent(in) :: have
        call t%num_or_none(r%e_n, have)
        call t%num_or_none(r%e_t, have)
        call t%num_or_none(r%vt_ratio, have)
        call t%num_or_none(r%rebound_angle, have)
        call t%num_or_none(r%omega1, have)
    end subroutine outcome

    !> Read the options of `oblique`; exit 2 naming the option on a bad value.
    subroutine parse_oblique(args, m, ct, o)
        type(cli_args), intent(in) :: args
        type(model_opts), intent(in) :: m
        type(cli_contact), intent(in) :: ct
        type(oblique_opts), intent(out) :: o
        integer :: k, tang, lever
        real(wp) :: kt
        kt = 0.0_wp
        if (.not. ct%has_bodies) call fail(EXIT_USAGE, 'oblique needs each body''s mass and radius: --radius ' // &
                                           'and --density (and --radius2, --density2 or --wall)')
        if (.not. ct%has_kphys) call fail(EXIT_USAGE, 'oblique needs the physical stiffness: --youngs-modulus ' // &
                                          'and --poisson-ratio, or --k-phys')
        if (.not. args%has('--e')) call fail(EXIT_USAGE, 'missing option --e (see --help)')
        if (.not. args%has('--velocity')) call fail(EXIT_USAGE, 'missing option --velocity (see --help)')
        if (.not. args%has('--friction')) call fail(EXIT_USAGE, 'missing option --friction (see --help)')
        o%e = parse_real(args%get('--e', ''), '--e')
        o%u = parse_real(args%get('--velocity', ''), '--velocity')
        if (.not. (o%u > 0.0_wp .and. o%u < huge(1.0_wp))) call fail(EXIT_USAGE, '--velocity ' // &
            args%get('--velocity', '') // ': the impact speed must be finite and positive')
        o%angles = required_sweep(args, '--angle')
        if (any(.not. (o%angles >= 0.0_wp .and. o%angles < 90.0_wp))) call fail(EXIT_USAGE, '--angle ' // &
            args%get('--angle', '') // ': the angles must be in [0, 90) degrees from the normal')
        k = parse_choice(args%get('--tangential', 'mindlin'), hertzdamp_tangential_choices(), &
                         'tangential model (--tangential)')
        tang = hertzdamp_tangential_code(args%get('--tangential', 'mindlin'))
        lever = HD_LEVER_CONTACT
        if (ct%wall) lever = HD_LEVER_RADIUS
        if (args%has('--lever')) then
            k = parse_choice(args%get('--lever', ''), hertzdamp_lever_choices(), 'torque lever arm (--lever)')
            lever = hertzdamp_lever_code(args%get('--lever', ''))
        end if
        if (args%has('--kt')) then
            kt = parse_real(args%get('--kt', ''), '--kt')
        else if (tang == HD_TANGENTIAL_MINDLIN .and. ct%has_mindlin) then
            kt = ct%kt_mindlin
        else
            call fail(EXIT_USAGE, 'missing option --kt (mindlin''s default 8 G* needs --youngs-modulus and ' // &
                      '--poisson-ratio; linear_history has none)')
        end if
        if (.not. (kt > 0.0_wp .and. kt < huge(1.0_wp))) call fail(EXIT_USAGE, '--kt ' // args%get('--kt', '') // &
            ': the tangential stiffness must be finite and positive')
        o%c = hertzdamp_oblique_t(m1=ct%m1, r1=ct%r1, m2=ct%m2, r2=ct%r2, k=ct%k_phys, d=0.0_wp, law=m%law, &
                                  iend=m%iend, tangential=tang, kt=kt, &
                                  xgammat=parse_real(args%get('--xgammat', '0'), '--xgammat'), &
                                  mu=parse_real(args%get('--friction', ''), '--friction'), lever=lever)
        if (.not. (o%c%mu >= 0.0_wp)) call fail(EXIT_USAGE, '--friction ' // args%get('--friction', '') // &
                                                ': the friction coefficient must be finite and non-negative')
        if (.not. (o%c%xgammat >= 0.0_wp)) call fail(EXIT_USAGE, '--xgammat ' // args%get('--xgammat', '') // &
                                                     ': must be finite and non-negative')
        o%soft = args%has('--dt') .or. args%has('--steps')
        if (o%soft .and. .not. (args%has('--dt') .and. args%has('--steps'))) then
            call fail(EXIT_USAGE, 'the softened contact needs both --dt and --steps (T_c = N dt)')
        end if
        if (o%soft) then
            o%dt = parse_real(args%get('--dt', ''), '--dt')
            o%steps = parse_real(args%get('--steps', ''), '--steps')
            if (.not. (o%dt > 0.0_wp .and. o%steps > 0.0_wp .and. o%dt * o%steps < huge(1.0_wp))) then
                call fail(EXIT_USAGE, '--dt, --steps: the time step and the steps per contact must be positive')
            end if
            k = parse_choice(args%get('--tangential-stiffness', 'adapted'), 'adapted physical', &
                             'tangential stiffness of the softened contact (--tangential-stiffness)')
            o%adapted = k == 1
            o%correct = args%has('--normal-correction')
        else if (args%has('--tangential-stiffness') .or. args%has('--normal-correction')) then
            call fail(EXIT_USAGE, '--tangential-stiffness and --normal-correction need --dt and --steps')
        end if
        if (o%correct .and. ct%wall) call fail(EXIT_USAGE, '--normal-correction is for two spheres (on a wall ' // &
                                               'the line of centres does not turn)')
    end subroutine parse_oblique

    !> The physical contact at one angle: k = k_phys, d of alpha(e) at the normal speed
    !> u cos(angle) (the rule's bound path).
    subroutine physical(o, m, angle, r, st)
        type(oblique_opts), intent(in) :: o
        type(model_opts), intent(in) :: m
        real(wp), intent(in) :: angle
        type(hertzdamp_oblique_result), intent(out) :: r
        integer, intent(out) :: st
        type(hertzdamp_oblique_t) :: c
        real(wp) :: un, a0, tstar, a, tau, k
        c = o%c
        un = o%u * cos(angle * hertzdamp_pi / 180.0_wp)
        call hertzdamp_reduce(c%k, 0.0_wp, meff(c), un, a0, tstar, st, m%law)
        if (st == HD_OK) call hertzdamp_fit_inverse(o%e, m%iend, a, tau, st, m%law)
        if (st == HD_OK) call hertzdamp_expand(a, tstar, meff(c), un, k, c%d, st, m%law)
        r = hertzdamp_oblique_result()
        if (st == HD_OK) call hertzdamp_oblique_impact(c, o%u, angle, r, st)
    end subroutine physical

    !> The softened contact at one angle: k, d of T_c = N dt at the normal speed (bound
    !> k_phys), k_t adapted (hertzdamp_tangential_kt) or physical; with --normal-correction
    !> the corrected constants (hertzdamp_oblique_correct) and their target et.
    subroutine softened(o, m, angle, c, et, r, st)
        type(oblique_opts), intent(in) :: o
        type(model_opts), intent(in) :: m
        real(wp), intent(in) :: angle
        type(hertzdamp_oblique_t), intent(out) :: c
        real(wp), intent(out) :: et
        type(hertzdamp_oblique_result), intent(out) :: r
        integer, intent(out) :: st
        real(wp) :: un, k, d, kt
        c = o%c
        et = o%e
        r = hertzdamp_oblique_result()
        un = o%u * cos(angle * hertzdamp_pi / 180.0_wp)
        if (o%correct) then
            call hertzdamp_oblique_correct(o%c, o%e, o%dt * o%steps, o%u, angle, k, d, kt, et, st)
        else
            call hertzdamp_invert(o%e, o%dt * o%steps, meff(c), un, m%iend, k, d, st, k_phys=o%c%k, law=m%law)
            kt = o%c%kt
            if (st == HD_OK .and. o%adapted) call hertzdamp_tangential_kt(c%tangential, o%c%kt, k, o%c%k, kt, st)
        end if
        if (st /= HD_OK) return
        c%k = k
        c%d = d
        c%kt = kt
        call hertzdamp_oblique_impact(c, o%u, angle, r, st)
    end subroutine softened

    !> The effective mass of the contact.
    pure real(wp) function meff(c)
        type(hertzdamp_oblique_t), intent(in) :: c
        meff = c%m1
        if (c%m2 > 0.0_wp) meff = c%m1 * c%m2 / (c%m1 + c%m2)
    end function meff

end module hertzdamp_cmd_oblique
