!> One Yade Hertz-Mindlin contact (`Ip2_FrictMat_FrictMat_MindlinPhys` with
!> `Law2_ScGeom_MindlinPhys_Mindlin`), from `key=value` words (doc/peers.md section 4):
!> `young=E[,E2] poisson=nu[,nu2]`, one of `en=e` (with `vn=v` since 2024.02a) or
!> `betan=b`, `density=rho`; with a wall `shape=Wall|Facet|Box`, `hertzian=True|False`.
!>
!> The release decides what `en` means: up to 2022.01a gamma = sqrt(5) beta(e); from
!> 2023.02a (Debian 12) Thornton et al. (2013) eq. (B6)-(B7), gamma = sqrt(6) betan(e);
!> from 2024.02a also `vn`, the Kuwabara-Kono (Brilliantov) damping whose e at the
!> speed vn is `en` by the Mueller-Poeschel Pade.  Yade always clips the total force.
module hertzdamp_check_yade
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_check_model, only: peer_deck, peer_spec_row
    use hertzdamp_check_common, only: peer_materials, kv_list, bodies, effective_modulus, hertz_k, check_modulus, &
                                      check_poisson, pair_values, number, take, has, add_note
    use hertzdamp_text_format, only: fmt_short, ROUND_TRIP
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Yade releases whose formulas differ.
    integer, parameter, public :: YADE_2022 = 1     !! 2020.01a .. 2022.01a: en -> sqrt(5) beta(e)
    integer, parameter, public :: YADE_2023 = 2     !! 2023.02a (Debian 12): en -> Thornton (2013)
    integer, parameter, public :: YADE_CURRENT = 3  !! 2024.02a and later: en -> Thornton, en + vn -> Pade
    character(len=*), parameter, public :: yade_releases = '2022 2023 current'

    !> The keys of a Yade contact.
    character(len=*), parameter, public :: yade_keys = 'young poisson en betan vn density shape hertzian'

    public :: read_yade

contains

    !> Read a Yade contact; msg names the key on failure.
    subroutine read_yade(kv, mat, deck, msg)
        type(kv_list), intent(inout) :: kv
        type(peer_materials), intent(in) :: mat
        type(peer_deck), intent(inout) :: deck          !! deck%release: YADE_*
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: v, shape
        real(wp) :: ymod(2), nu(2), rho
        logical :: hertzian
        type(peer_materials) :: m2
        m2 = mat
        if (take(kv, 'density', v)) then
            call number(v, 'density', rho, msg)
            if (mat%density(1) > 0.0_wp) msg = 'density and --density both give the density; give one'
            if (len(msg) > 0) return
            m2%density = rho
        end if
        call wall_shape(kv, mat%wall, shape, hertzian, msg)
        if (len(msg) > 0) return
        call pair_values(kv, 'young', deck%wall, ymod, msg)
        call pair_values(kv, 'poisson', deck%wall, nu, msg)
        if (len(msg) > 0) return
        call check_modulus(ymod(1), 'young', fmt_short(ymod(1), ROUND_TRIP), msg)
        call check_modulus(ymod(2), 'young', fmt_short(ymod(2), ROUND_TRIP), msg)
        call check_poisson(nu(1), 'poisson', fmt_short(nu(1), ROUND_TRIP), msg)
        call check_poisson(nu(2), 'poisson', fmt_short(nu(2), ROUND_TRIP), msg)
        if (len(msg) > 0) return
        if (has(kv, 'en') .and. has(kv, 'betan')) then
            msg = 'en and betan: Yade takes only one of them (Ip2_FrictMat_FrictMat_MindlinPhys)'
            return
        end if
        call bodies(m2, deck, msg)
        if (len(msg) > 0) return
        if (deck%wall) call wall_radius(shape, hertzian, deck)
        deck%e_star = effective_modulus(ymod, nu)
        deck%k = hertz_k(deck%e_star, deck%radius)
        deck%k_text = 'k = Kno = (4/3) E* sqrt(R), 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2'
        call damping(kv, deck, msg)
        if (len(msg) > 0) return
        deck%deck_text = deck%deck_text // ' FrictMat(young=' // fmt_short(ymod(1), ROUND_TRIP) // ', poisson=' // &
                         fmt_short(nu(1), ROUND_TRIP) // ')'
        if (deck%wall) then
            deck%deck_text = deck%deck_text // ', ' // shape // ' (young=' // fmt_short(ymod(2), ROUND_TRIP) // ', poisson=' // &
                             fmt_short(nu(2), ROUND_TRIP) // ')'
            if (hertzian) deck%deck_text = deck%deck_text // ', hertzian=True'
        end if
    end subroutine read_yade

    subroutine wall_shape(kv, wall, shape, hertzian, msg)
        type(kv_list), intent(inout) :: kv
        logical, intent(in) :: wall
        character(len=:), allocatable, intent(out) :: shape
        logical, intent(out) :: hertzian
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: v
        shape = 'Wall'
        hertzian = .false.
        if (take(kv, 'shape', v)) then
            shape = v
            if (.not. wall) msg = 'shape = ' // v // ' applies to a wall contact (--wall)'
            if (v /= 'Wall' .and. v /= 'Facet' .and. v /= 'Box') msg = 'shape = ' // v // ': Wall, Facet or Box'
        end if
        if (take(kv, 'hertzian', v)) then
            if (.not. wall) msg = 'hertzian applies to a wall contact (--wall)'
            select case (v)
            case ('True', 'true', '1'); hertzian = .true.
            case ('False', 'false', '0'); hertzian = .false.
            case default; msg = 'hertzian = ' // v // ': True or False'
            end select
        end if
    end subroutine wall_shape

    !> Ig2_Wall_Sphere_ScGeom, Ig2_Box_Sphere_ScGeom and Ig2_Facet_Sphere_ScGeom: the
    !> wall's reference radius (Ig2_Facet_Sphere_ScGeom.cpp:127, 220;
    !> Ig2_Box_Sphere_ScGeom.cpp:78), R = refR1 r / (refR1 + r).
    subroutine wall_radius(shape, hertzian, deck)
        character(len=*), intent(in) :: shape
        logical, intent(in) :: hertzian
        type(peer_deck), intent(inout) :: deck
        real(wp) :: ref
        if (hertzian) then
            ref = 1.0e8_wp * deck%radius1
        else if (shape == 'Facet') then
            ref = 2.0_wp * deck%radius1
        else
            ref = deck%radius1
        end if
        deck%radius = ref * deck%radius1 / (ref + deck%radius1)
        if (.not. hertzian) call add_note(deck, 'Yade ' // shape // ' contact: the wall''s reference radius is ' // &
            trim(merge('2r', 'r ', shape == 'Facet')) // ', so R = ' // trim(merge('2r/3', 'r/2 ', shape == 'Facet')) // &
            ' instead of r (Ig2_Facet_Sphere_ScGeom.cpp); hertzian=True gives R = r')
    end subroutine wall_radius

    !> en (by release), en with vn, or betan: the damping parameter and the row.
    subroutine damping(kv, deck, msg)
        type(kv_list), intent(inout) :: kv
        type(peer_deck), intent(inout) :: deck   !! deck%release: YADE_*
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: v, vv
        real(wp) :: e, b
        if (has(kv, 'vn') .and. deck%release /= YADE_CURRENT) then
            msg = 'vn: Ip2_FrictMat_FrictMat_MindlinPhys has vn from Yade 2024.02a (--release current)'
        else if (has(kv, 'vn') .and. .not. has(kv, 'en')) then
            msg = 'vn needs en (the restitution coefficient at the impact speed vn)'
        end if
        if (len(msg) > 0) return
        if (take(kv, 'en', v)) then
            call number(v, 'en', e, msg)
            if (len(msg) > 0) return
            if (.not. (e > 0.0_wp .and. e <= 1.0_wp)) then
                msg = 'en = ' // v // ': must be in (0, 1] (Yade takes ln(en), or divides by zero, at en = 0)'
                return
            end if
            deck%p = e
            deck%e_deck = e
            deck%p_name = 'en'
            deck%p_template = 'en={}'
            deck%deck_text = 'Ip2_FrictMat_FrictMat_MindlinPhys(en=' // v
            if (take(kv, 'vn', vv)) then
                call number(vv, 'vn', deck%vn, msg)
                if (len(msg) == 0 .and. .not. deck%vn > 0.0_wp) msg = 'vn = ' // vv // ': must be positive'
                if (len(msg) > 0) return
                deck%p_template = 'en={},vn=' // vv
                deck%row = peer_spec_row('yade2024-vn-force')
                deck%deck_text = deck%deck_text // ', vn=' // vv
                call add_note(deck, 'vn: Yade builds a Kuwabara-Kono (viscoelastic) damping whose e is en at the ' // &
                              'impact speed vn = ' // vv // ' (Mueller-Poeschel Pade); e changes with the speed by design')
            else if (deck%release == YADE_2022) then
                deck%row = peer_spec_row('yade-en-force')
            else
                deck%row = peer_spec_row('yade2023-en-force')
            end if
            deck%deck_text = deck%deck_text // ')'
        else if (take(kv, 'betan', v)) then
            call number(v, 'betan', b, msg)
            if (len(msg) > 0) return
            if (.not. b >= 0.0_wp) then
                msg = 'betan = ' // v // ': must be >= 0'
                return
            end if
            deck%p = b
            deck%p_name = 'betan'
            deck%p_template = 'betan={}'
            deck%row = peer_spec_row('yade-betan-force')
            deck%deck_text = 'Ip2_FrictMat_FrictMat_MindlinPhys(betan=' // v // ')'
        else
            msg = 'missing en (or betan)'
        end if
        select case (deck%release)
        case (YADE_2022); deck%version = 'Yade 2020.01a to 2022.01a'
        case (YADE_2023); deck%version = 'Yade 2023.02a (Debian 12)'
        case default; deck%version = 'Yade 2024.02a and later'
        end select
    end subroutine damping

end module hertzdamp_check_yade
