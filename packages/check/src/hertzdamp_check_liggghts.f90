!> One LIGGGHTS contact (`model hertz` or `hertz/stiffness`), from the `key=value` words
!> of its `fix property/global` values of a type pair (doc/peers.md section 2):
!> `model=hertz|hertz/stiffness limitForce=on|off youngsModulus=Y[,Y2] poissonsRatio=nu[,nu2]
!> coefficientRestitution=e` or `kn= gamman=`; with a wall the second values are the wall's.
module hertzdamp_check_liggghts
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_check_model, only: peer_deck, peer_spec_row, TSTEP_LIGGGHTS
    use hertzdamp_check_common, only: peer_materials, kv_list, bodies, end_word, effective_modulus, hertz_k, &
                                      check_modulus, check_poisson, pair_values, required, on_off, take, has
    use hertzdamp_text_format, only: fmt_short, ROUND_TRIP
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> The keys of a LIGGGHTS contact.
    character(len=*), parameter, public :: liggghts_keys = &
        'model limitForce youngsModulus poissonsRatio coefficientRestitution kn gamman tangential ' // &
        'tangential_damping rolling_friction cohesion'

    public :: read_liggghts

contains

    !> Read a LIGGGHTS contact; msg names the key on failure.
    subroutine read_liggghts(kv, mat, deck, msg)
        type(kv_list), intent(inout) :: kv
        type(peer_materials), intent(in) :: mat
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: model, lf, v
        real(wp) :: ymod(2), nu(2), e, kn, gamman
        logical :: limit, have_y
        model = 'hertz'
        lf = 'off'
        if (take(kv, 'model', v)) model = v
        if (take(kv, 'limitForce', v)) lf = v
        if (take(kv, 'tangential', v)) continue
        if (take(kv, 'rolling_friction', v)) continue
        if (take(kv, 'tangential_damping', v)) call on_off(v, 'tangential_damping', limit, msg)
        if (take(kv, 'cohesion', v)) then
            if (v /= 'off') msg = 'cohesion = ' // v // ': hertzdamp checks non-cohesive contacts'
        end if
        call on_off(lf, 'limitForce', limit, msg)
        if (len(msg) > 0) return
        call bodies(mat, deck, msg)
        if (len(msg) > 0) return
        have_y = has(kv, 'youngsModulus') .or. has(kv, 'poissonsRatio')
        if (have_y .or. model == 'hertz') then
            call pair_values(kv, 'youngsModulus', deck%wall, ymod, msg)
            call pair_values(kv, 'poissonsRatio', deck%wall, nu, msg)
            if (len(msg) > 0) return
            call check_modulus(ymod(1), 'youngsModulus', fmt_short(ymod(1), ROUND_TRIP), msg)
            call check_modulus(ymod(2), 'youngsModulus', fmt_short(ymod(2), ROUND_TRIP), msg)
            call check_poisson(nu(1), 'poissonsRatio', fmt_short(nu(1), ROUND_TRIP), msg)
            call check_poisson(nu(2), 'poissonsRatio', fmt_short(nu(2), ROUND_TRIP), msg)
            if (len(msg) > 0) return
            deck%e_star = effective_modulus(ymod, nu)
            deck%tstep = TSTEP_LIGGGHTS
        end if
        select case (model)
        case ('hertz')
            call required(kv, 'coefficientRestitution', e, msg)
            if (len(msg) > 0) return
            if (.not. (e > 0.05_wp .and. e <= 1.0_wp)) then
                msg = 'coefficientRestitution = ' // fmt_short(e, ROUND_TRIP) // ': LIGGGHTS requires 0.05 < e <= 1 ' // &
                      '(global_properties.cpp:488)'
                return
            end if
            deck%p = e
            deck%e_deck = e
            deck%p_name = 'coefficientRestitution'
            deck%p_template = 'coefficientRestitution={}'
            deck%k = hertz_k(deck%e_star, deck%radius)
            deck%k_text = 'k = (4/3) Y* sqrt(R), 1/Y* = (1-nu1^2)/Y1 + (1-nu2^2)/Y2'
            deck%row = peer_spec_row('liggghts-hertz-' // end_word(limit))
            deck%deck_text = 'model hertz limitForce ' // lf // ' youngsModulus ' // fmt_short(ymod(1), ROUND_TRIP) // &
                             ' ' // fmt_short(ymod(2), ROUND_TRIP) // ' poissonsRatio ' // fmt_short(nu(1), ROUND_TRIP) // &
                             ' ' // fmt_short(nu(2), ROUND_TRIP) // ' coefficientRestitution ' // fmt_short(e, ROUND_TRIP)
        case ('hertz/stiffness')
            call required(kv, 'kn', kn, msg)
            call required(kv, 'gamman', gamman, msg)
            if (len(msg) > 0) return
            if (.not. kn > 0.0_wp) msg = 'kn = ' // fmt_short(kn, ROUND_TRIP) // ' must be positive'
            if (.not. gamman >= 0.0_wp) msg = 'gamman = ' // fmt_short(gamman, ROUND_TRIP) // ' must be >= 0'
            if (len(msg) > 0) return
            deck%p = gamman
            deck%p_name = 'gamman'
            deck%p_template = 'gamman={}'
            deck%k = kn * sqrt(deck%radius)
            deck%k_text = 'k = kn sqrt(R) (model hertz/stiffness)'
            deck%row = peer_spec_row('liggghts-hertz_stiffness-' // end_word(limit))
            deck%deck_text = 'model hertz/stiffness limitForce ' // lf // ' kn ' // fmt_short(kn, ROUND_TRIP) // &
                             ' gamman ' // fmt_short(gamman, ROUND_TRIP)
        case ('hooke', 'hooke/stiffness')
            msg = 'model ' // model // ' is a linear spring; hertzdamp checks Hertz contacts (hertz, hertz/stiffness)'
        case default
            msg = 'unknown model "' // model // '" (hertz, hertz/stiffness)'
        end select
        if (deck%wall) deck%deck_text = deck%deck_text // ' (fix wall/gran, flat wall: the second values are the wall''s)'
    end subroutine read_liggghts

end module hertzdamp_check_liggghts
