!> One MFiX (classic) `DES_COLL_MODEL = 'HERTZIAN'` contact, from MFiX keywords as
!> `KEY=value` words (doc/peers.md section 5): `E_YOUNG V_POISSON DES_EN_INPUT`, with a
!> wall `EW_YOUNG VW_POISSON DES_EN_WALL_INPUT`; `D_P0`, `RO_S0` may replace the bodies'
!> sizes; keys are case-insensitive; `KEY(i)=` gives phase i (or, for DES_EN_INPUT, the
!> pair i in MFiX's order 1-1, 1-2, 2-2).  The contact is phase 1 with itself, with
!> phase 2 when a second phase value is given, or with the wall.
module hertzdamp_check_mfix
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_check_model, only: peer_deck, peer_spec_row, TSTEP_MFIX
    use hertzdamp_check_common, only: peer_materials, kv_list, bodies, effective_modulus, hertz_k, check_modulus, &
                                      check_poisson, pair_values, required, values, number, take, has, add_note
    use hertzdamp_text_parse, only: text_strip_quotes
    use hertzdamp_text_format, only: upper, fmt_short, ROUND_TRIP
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> The keys of an MFiX contact.
    character(len=*), parameter, public :: mfix_keys = &
        'DES_COLL_MODEL DES_EN_INPUT DES_EN_WALL_INPUT DES_ET_INPUT DES_ET_WALL_INPUT E_YOUNG V_POISSON ' // &
        'EW_YOUNG VW_POISSON D_P0 RO_S0 DTSOLID_FACTOR'

    public :: read_mfix

contains

    !> Read an MFiX contact; msg names the key on failure.
    subroutine read_mfix(kv, mat, deck, msg)
        type(kv_list), intent(inout) :: kv
        type(peer_materials), intent(in) :: mat
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: v
        type(peer_materials) :: m2
        logical :: gd(2), gr(2)
        m2 = mat
        if (has(kv, 'KN') .or. has(kv, 'KN_W')) then
            msg = 'KN is the stiffness of MFiX''s linear spring-dashpot model (DES_COLL_MODEL = ''LSD''); ' // &
                  'the HERTZIAN model takes E_YOUNG and V_POISSON'
            return
        end if
        if (.not. take(kv, 'DES_COLL_MODEL', v)) then
            msg = 'missing DES_COLL_MODEL = ''HERTZIAN'' (MFiX''s default is LSD, the linear spring-dashpot model)'
            return
        end if
        if (upper(text_strip_quotes(v)) /= 'HERTZIAN') then
            msg = 'DES_COLL_MODEL = ' // v // ': hertzdamp checks ''HERTZIAN'' (LSD is a linear spring)'
            return
        end if
        if (take(kv, 'DES_ET_INPUT', v)) continue
        if (take(kv, 'DES_ET_WALL_INPUT', v)) continue
        call phase_values(kv, 'D_P0', mat%radius(1) > 0.0_wp, '--radius', 'particle size', m2%radius, gd, msg)
        call phase_values(kv, 'RO_S0', mat%density(1) > 0.0_wp, '--density', 'density', m2%density, gr, msg)
        if (len(msg) > 0) return
        where (gd) m2%radius = 0.5_wp * m2%radius
        deck%dt_factor = 50.0_wp
        if (take(kv, 'DTSOLID_FACTOR', v)) then
            call number(v, 'DTSOLID_FACTOR', deck%dt_factor, msg)
            if (len(msg) == 0 .and. .not. deck%dt_factor > 0.0_wp) msg = 'DTSOLID_FACTOR must be positive'
        end if
        if (len(msg) > 0) return
        call bodies(m2, deck, msg)
        if (len(msg) > 0) return
        call material(kv, deck, gd(2) .or. gr(2) .or. mat%radius(2) > 0.0_wp .or. mat%density(2) > 0.0_wp, msg)
    end subroutine read_mfix

    !> A per-phase value that may replace an option: KEY=v[,v2] or KEY(1)=, KEY(2)=;
    !> x(i) set where given(i).  At most two phases.
    subroutine phase_values(kv, key, option_given, option, what, x, given, msg)
        type(kv_list), intent(inout) :: kv
        character(len=*), intent(in) :: key, option, what
        logical, intent(in) :: option_given
        real(wp), intent(inout) :: x(2)
        logical, intent(out) :: given(2)
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: v
        real(wp), allocatable :: y(:)
        integer :: n
        given = .false.
        n = 0
        if (len(msg) > 0) return
        if (take(kv, key, v)) then
            call values(v, key, y, msg)
            if (len(msg) > 0) return
            if (size(y) > 2) then
                msg = key // ': at most 2 values (body 1, body 2)'
                return
            end if
            n = size(y)
            x(1:n) = y
            given(1:n) = .true.
        end if
        if (take(kv, key // '(1)', v)) then
            if (n > 0) msg = key // ' given both whole and by index'
            call number(v, key // '(1)', x(1), msg)
            given(1) = .true.
        end if
        if (take(kv, key // '(2)', v)) then
            if (n > 0) msg = key // ' given both whole and by index'
            call number(v, key // '(2)', x(2), msg)
            given(2) = .true.
        end if
        if (any(given) .and. option_given .and. len(msg) == 0) msg = key // ' and ' // option // ' both give the ' // &
                                                                what // '; give one'
    end subroutine phase_values

    !> The moduli, the restitution coefficient of the contact's pair and the row.
    subroutine material(kv, deck, two_phases, msg)
        type(kv_list), intent(inout) :: kv
        type(peer_deck), intent(inout) :: deck
        logical, intent(in) :: two_phases     !! the particle contact is phase 1 with phase 2
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: ekey
        real(wp) :: ymod(2), nu(2), e
        logical :: two
        call pair_values(kv, 'E_YOUNG', .false., ymod, msg)
        call pair_values(kv, 'V_POISSON', .false., nu, msg)
        if (deck%wall) then
            call required(kv, 'EW_YOUNG', ymod(2), msg)
            call required(kv, 'VW_POISSON', nu(2), msg)
        end if
        if (len(msg) > 0) return
        two = two_phases .or. has_second(kv, 'E_YOUNG') .or. has_second(kv, 'V_POISSON')
        call check_modulus(ymod(1), 'E_YOUNG', fmt_short(ymod(1), ROUND_TRIP), msg)
        call check_modulus(ymod(2), trim(merge('EW_YOUNG', 'E_YOUNG ', deck%wall)), fmt_short(ymod(2), ROUND_TRIP), msg)
        call check_poisson(nu(1), 'V_POISSON', fmt_short(nu(1), ROUND_TRIP), msg)
        call check_poisson(nu(2), trim(merge('VW_POISSON', 'V_POISSON ', deck%wall)), fmt_short(nu(2), ROUND_TRIP), msg)
        call restitution(kv, deck%wall, two, ekey, e, msg)
        if (len(msg) > 0) return
        deck%e_star = effective_modulus(ymod, nu)
        deck%k = hertz_k(deck%e_star, deck%radius)
        deck%k_text = 'k = HERT_KN = (4/3) sqrt(R_EFF) E_EFF, 1/E_EFF = (1-nu1^2)/E1 + (1-nu2^2)/E2'
        deck%p = e
        deck%e_deck = e
        deck%p_name = ekey
        deck%p_template = ekey // '={}'
        deck%row = peer_spec_row('mfix-hertzian-overlap')
        deck%tstep = TSTEP_MFIX
        deck%deck_text = 'DES_COLL_MODEL=HERTZIAN ' // ekey // '=' // fmt_short(e, ROUND_TRIP) // ' E_YOUNG=' // &
                         fmt_short(ymod(1), ROUND_TRIP) // ' V_POISSON=' // fmt_short(nu(1), ROUND_TRIP)
        if (deck%wall) then
            deck%deck_text = deck%deck_text // ' EW_YOUNG=' // fmt_short(ymod(2), ROUND_TRIP) // ' VW_POISSON=' // &
                             fmt_short(nu(2), ROUND_TRIP)
            call add_note(deck, 'MFiX computes the wall TCOLL but does not fold it into DTSOLID ' // &
                          '(check_solids_dem.f:990-997): wall contacts do not limit its time step')
        end if
    end subroutine material

    !> Whether KEY(2) or a second value of KEY=v1,v2 was given (the key is not consumed).
    pure logical function has_second(kv, key)
        type(kv_list), intent(in) :: kv
        character(len=*), intent(in) :: key
        integer :: i
        has_second = has(kv, key // '(2)')
        i = kv%map%find(key)
        if (i > 0) has_second = has_second .or. index(kv%val(i)%s, ',') > 0
    end function has_second

    !> DES_EN_INPUT of the contact's pair (MFiX order 1-1, 1-2, 2-2: index 1 or 2), or
    !> DES_EN_WALL_INPUT of phase 1; the plain key is the contact's own value.
    subroutine restitution(kv, wall, two, ekey, e, msg)
        type(kv_list), intent(inout) :: kv
        logical, intent(in) :: wall, two
        character(len=:), allocatable, intent(out) :: ekey
        real(wp), intent(out) :: e
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: base, indexed, v, pair
        e = 0.0_wp
        if (wall) then
            base = 'DES_EN_WALL_INPUT'
            indexed = base // '(1)'
            pair = 'phase 1 with the wall'
        else if (two) then
            base = 'DES_EN_INPUT'
            indexed = base // '(2)'
            pair = 'the pair 1-2, index 2 in MFiX''s order 1-1, 1-2, 2-2'
        else
            base = 'DES_EN_INPUT'
            indexed = base // '(1)'
            pair = 'the pair 1-1, index 1 in MFiX''s order 1-1, 1-2, 2-2'
        end if
        ekey = base
        if (len(msg) > 0) return
        if (has(kv, base) .and. has(kv, indexed)) then
            msg = base // ' given both whole and by index'
        else if (take(kv, indexed, v)) then
            ekey = indexed
            call number(v, ekey, e, msg)
        else if (take(kv, base, v)) then
            call number(v, ekey, e, msg)
        else
            msg = 'missing ' // base // ' (' // pair // ': ' // base // ' or ' // indexed // ')'
        end if
        if (len(msg) > 0) return
        if (.not. (e >= 0.0_wp .and. e <= 1.0_wp)) then
            msg = ekey // ' = ' // fmt_short(e, ROUND_TRIP) // ': MFiX requires 0 <= e <= 1 (check_solids_dem.f)'
        end if
    end subroutine restitution

end module hertzdamp_check_mfix
