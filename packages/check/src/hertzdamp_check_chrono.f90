!> One Project Chrono `ChSystemSMC` Hertz contact, from `key=value` words named after
!> the C++ calls (doc/peers.md section 6): `SetYoungModulus=E[,E2] SetPoissonRatio=nu[,nu2]
!> SetRestitution=e[,e2]`, or `UseMaterialProperties=false SetKn= SetGn=`;
!> `SetCollisionSystemType=BULLET|MULTICORE`; `wallMass=` with a wall.
module hertzdamp_check_chrono
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_check_model, only: peer_deck, peer_spec_row
    use hertzdamp_check_common, only: peer_materials, kv_list, bodies, hertz_k, check_modulus, check_poisson, &
                                      pair_values, number, take, has, add_note
    use hertzdamp_text_format, only: fmt_short, ROUND_TRIP
    use, intrinsic :: iso_fortran_env, only: real32
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> The keys of a Chrono contact.
    character(len=*), parameter, public :: chrono_keys = &
        'SetContactForceModel UseMaterialProperties SetYoungModulus SetPoissonRatio SetRestitution ' // &
        'SetKn SetGn SetCollisionSystemType wallMass'

    public :: read_chrono

contains

    !> Read a Chrono contact; msg names the key on failure.
    subroutine read_chrono(kv, mat, deck, msg)
        type(kv_list), intent(inout) :: kv
        type(peer_materials), intent(in) :: mat
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: v, coll
        real(wp) :: mwall, rphys
        logical :: matprops
        matprops = .true.
        coll = 'BULLET'
        mwall = 1.0_wp
        if (take(kv, 'SetContactForceModel', v)) then
            if (v /= 'Hertz' .and. v /= 'ChSystemSMC::Hertz' .and. v /= 'ChSystemSMC::ContactForceModel::Hertz') then
                msg = 'SetContactForceModel = ' // v // ': hertzdamp checks the Hertz model'
                return
            end if
        end if
        if (take(kv, 'UseMaterialProperties', v)) then
            select case (v)
            case ('true', 'True', '1'); matprops = .true.
            case ('false', 'False', '0'); matprops = .false.
            case default; msg = 'UseMaterialProperties = ' // v // ': true or false'
            end select
        end if
        if (take(kv, 'SetCollisionSystemType', v)) then
            select case (v)
            case ('BULLET', 'ChCollisionSystem::Type::BULLET'); coll = 'BULLET'
            case ('MULTICORE', 'ChCollisionSystem::Type::MULTICORE'); coll = 'MULTICORE'
            case default; msg = 'SetCollisionSystemType = ' // v // ': BULLET or MULTICORE'
            end select
        else
            call add_note(deck, 'SetCollisionSystemType not given: assumed BULLET (ChSystem has no default ' // &
                          'collision system; BULLET is what the SMC demos use)')
        end if
        if (take(kv, 'wallMass', v)) then
            call number(v, 'wallMass', mwall, msg)
            if (len(msg) == 0 .and. .not. mwall > 0.0_wp) msg = 'wallMass = ' // v // ' must be positive'
            if (len(msg) == 0 .and. .not. mat%wall) msg = 'wallMass applies to a wall contact (--wall)'
        end if
        if (matprops .and. (has(kv, 'SetKn') .or. has(kv, 'SetGn'))) then
            msg = 'SetKn and SetGn are unused with UseMaterialProperties=true (the default)'
        else if (.not. matprops .and. (has(kv, 'SetYoungModulus') .or. has(kv, 'SetPoissonRatio') .or. &
                                       has(kv, 'SetRestitution'))) then
            msg = 'SetYoungModulus, SetPoissonRatio and SetRestitution are unused with UseMaterialProperties=false'
        end if
        if (len(msg) > 0) return
        call bodies(mat, deck, msg)
        if (len(msg) > 0) return
        rphys = deck%radius
        if (coll == 'BULLET') then
            ! the BULLET collision system leaves ChCollisionInfo's default eff_radius
            ! (ChCollisionSystemBullet.cpp:227-228, ChCollisionInfo.cpp:19)
            deck%radius = 0.1_wp
            call add_note(deck, 'Chrono BULLET collision system: the contact radius is its default 0.1 m, ' // &
                          'not R* = ' // fmt_short(rphys, ROUND_TRIP) // ' m (only MULTICORE computes it); k uses 0.1')
        end if
        if (deck%wall) then
            ! the fixed wall body keeps its mass (ChBody default 1 kg) in the damping's effective mass
            deck%m_damp = deck%m * mwall / (deck%m + mwall)
            call add_note(deck, 'against a fixed body of mass M_w = ' // fmt_short(mwall, ROUND_TRIP) // &
                          ' kg the damping uses ' // &
                          'm M_w/(m + M_w) while the dynamics has m: gamma is scaled by sqrt(M_w/(m + M_w)) = ' // &
                          fmt_short(sqrt(deck%m_damp / deck%m), 6) // ' (wallMass)')
        end if
        if (matprops) then
            call chrono_material(kv, deck, msg)
        else
            call chrono_kn_gn(kv, deck, msg)
        end if
        if (len(msg) > 0) return
        deck%deck_text = deck%deck_text // ', ' // coll // merge(', wall', '      ', deck%wall)
        deck%deck_text = trim(deck%deck_text)
    end subroutine read_chrono

    !> UseMaterialProperties(true): E, nu and e of both bodies, composited in single precision.
    subroutine chrono_material(kv, deck, msg)
        type(kv_list), intent(inout) :: kv
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        real(wp) :: ymod(2), nu(2), e(2)
        real(real32) :: inv_e, e_eff, cr
        call pair_values(kv, 'SetYoungModulus', deck%wall, ymod, msg)
        call pair_values(kv, 'SetPoissonRatio', deck%wall, nu, msg)
        call pair_values(kv, 'SetRestitution', deck%wall, e, msg)
        if (len(msg) > 0) return
        call check_modulus(ymod(1), 'SetYoungModulus', fmt_short(ymod(1), ROUND_TRIP), msg)
        call check_modulus(ymod(2), 'SetYoungModulus', fmt_short(ymod(2), ROUND_TRIP), msg)
        call check_poisson(nu(1), 'SetPoissonRatio', fmt_short(nu(1), ROUND_TRIP), msg)
        call check_poisson(nu(2), 'SetPoissonRatio', fmt_short(nu(2), ROUND_TRIP), msg)
        if (len(msg) > 0) return
        if (.not. all(e >= 0.0_wp .and. e <= 1.0_wp)) then
            msg = 'SetRestitution: must be in [0, 1]'
            return
        end if
        ! ChContactMaterialCompositeSMC (ChContactMaterialSMC.cpp:110-121): single precision
        inv_e = (1 - real(nu(1), real32) * real(nu(1), real32)) / real(ymod(1), real32) + &
                (1 - real(nu(2), real32) * real(nu(2), real32)) / real(ymod(2), real32)
        e_eff = 1 / inv_e
        cr = min(real(e(1), real32), real(e(2), real32))
        deck%e_star = real(e_eff, wp)
        deck%k = hertz_k(deck%e_star, deck%radius)
        deck%k_text = 'k = (2/3) Sn / sqrt(delta) = (4/3) E_eff sqrt(R), E_eff in single precision'
        deck%p = real(cr, wp)
        deck%e_deck = real(cr, wp)
        deck%p_name = 'SetRestitution (composite: the smaller of the two, as a float)'
        deck%p_template = 'SetRestitution={}'
        deck%row = peer_spec_row('chrono-material-force')
        deck%deck_text = 'ChSystemSMC Hertz, UseMaterialProperties(true): SetYoungModulus(' // &
                         fmt_short(ymod(1), ROUND_TRIP) // ') SetPoissonRatio(' // fmt_short(nu(1), ROUND_TRIP) // &
                         ') SetRestitution(' // fmt_short(e(1), ROUND_TRIP) // ')'
    end subroutine chrono_material

    !> UseMaterialProperties(false): kn and gn, composited as float means.
    subroutine chrono_kn_gn(kv, deck, msg)
        type(kv_list), intent(inout) :: kv
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        real(wp) :: kn(2), gn(2)
        real(real32) :: kn_eff, gn_eff
        call pair_values(kv, 'SetKn', deck%wall, kn, msg)
        call pair_values(kv, 'SetGn', deck%wall, gn, msg)
        if (len(msg) > 0) return
        if (.not. all(kn > 0.0_wp)) msg = 'SetKn must be positive'
        if (.not. all(gn >= 0.0_wp)) msg = 'SetGn must be >= 0'
        if (len(msg) > 0) return
        ! CombineStiffnessCoefficient / CombineDampingCoefficient: (a1 + a2)/2 in float
        kn_eff = (real(kn(1), real32) + real(kn(2), real32)) / 2
        gn_eff = (real(gn(1), real32) + real(gn(2), real32)) / 2
        deck%k = real(kn_eff, wp) * deck%radius
        deck%k_text = 'k = kn R (R, not sqrt(R): kn_eff = R sqrt(delta) kn)'
        deck%p = real(gn_eff, wp)
        deck%p_name = 'SetGn (composite: the mean of the two, as a float)'
        deck%p_template = 'SetGn={}'
        deck%row = peer_spec_row('chrono-kn_gn-force')
        deck%deck_text = 'ChSystemSMC Hertz, UseMaterialProperties(false): SetKn(' // fmt_short(kn(1), ROUND_TRIP) // &
                         ') SetGn(' // fmt_short(gn(1), ROUND_TRIP) // ')'
    end subroutine chrono_kn_gn

end module hertzdamp_check_chrono
