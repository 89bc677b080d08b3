!> One MercuryDPM Hertz contact, from the species setters as `name=arguments` words in
!> the order of the calls (doc/peers.md section 3): the current
!> `HertzianViscoelasticNormalSpecies` (`setEffectiveElasticModulusAndRestitutionCoefficient=E*,e`,
!> `setEffectiveElasticModulus=E*`, `setDissipation=g`, `setDensity=rho`) or, with
!> `species=HertzianViscoelasticSpecies`, Beta 2015 (`setElasticModulus=E`,
!> `setDissipation=d`, `setStiffnessAndRestitutionCoefficient=E,e,mass`).
module hertzdamp_check_mercury
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_check_model, only: peer_deck, peer_spec_row, TSTEP_MERCURY
    use hertzdamp_check_common, only: peer_materials, kv_list, bodies, hertz_k, check_modulus, values, take, &
                                      add_note
    use hertzdamp_text_format, only: itoa, fmt_short, ROUND_TRIP
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> The keys of a MercuryDPM contact.
    character(len=*), parameter, public :: mercury_keys = &
        'species setEffectiveElasticModulusAndRestitutionCoefficient ' // &
        'setElasticModulusAndRestitutionCoefficient setEffectiveElasticModulus setElasticModulus ' // &
        'setEffectiveElasticModulusAndPoissonRatio setDissipation setStiffnessAndRestitutionCoefficient ' // &
        'setDensity'

    !> What the setters have set so far.
    type :: species_state
        character(len=:), allocatable :: species
        logical :: old = .false.          !! HertzianViscoelasticSpecies (Beta 2015)
        real(wp) :: emod = -1.0_wp        !! the modulus set
        logical :: have_e = .false.
        character(len=:), allocatable :: kind   !! restitution, dissipation, stiffness_restitution
        character(len=:), allocatable :: calls  !! the setters as read
        type(peer_materials) :: mat             !! with setDensity applied
    end type species_state

    public :: read_mercury

contains

    !> Read a MercuryDPM contact; msg names the setter on failure.
    subroutine read_mercury(kv, mat, deck, msg)
        type(kv_list), intent(inout) :: kv
        type(peer_materials), intent(in) :: mat
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: v, key
        real(wp), allocatable :: x(:)
        type(species_state) :: st
        integer :: i
        st%species = 'HertzianViscoelasticNormalSpecies'
        if (take(kv, 'species', v)) st%species = v
        select case (st%species)
        case ('HertzianViscoelasticNormalSpecies')
            st%old = .false.
        case ('HertzianViscoelasticSpecies')
            st%old = .true.
        case default
            msg = 'species = ' // st%species // ': checked are HertzianViscoelasticNormalSpecies (current) and ' // &
                  'HertzianViscoelasticSpecies (Beta 2015)'
            return
        end select
        st%kind = ''
        st%calls = ''
        st%mat = mat
        ! the setters act in the order given, as the C++ calls do
        do i = 1, size(kv%key)
            key = kv%key(i)%s
            select case (key)
            case ('setEffectiveElasticModulusAndRestitutionCoefficient', 'setElasticModulusAndRestitutionCoefficient', &
                  'setEffectiveElasticModulus', 'setEffectiveElasticModulusAndPoissonRatio', 'setElasticModulus', &
                  'setDissipation', 'setStiffnessAndRestitutionCoefficient', 'setDensity')
                kv%used(i) = .true.
                call values(kv%val(i)%s, key, x, msg)
                if (len(msg) > 0) return
                st%calls = st%calls // ' ' // key // '(' // kv%val(i)%s // ')'
                call setter(key, x, mat, st, deck, msg)
                if (len(msg) > 0) return
            case default
            end select
        end do
        call resolve(st, deck, msg)
    end subroutine read_mercury

    !> One setter call with its arguments x.
    subroutine setter(key, x, mat, st, deck, msg)
        character(len=*), intent(in) :: key
        real(wp), intent(in) :: x(:)
        type(peer_materials), intent(in) :: mat
        type(species_state), intent(inout) :: st
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        select case (key)
        case ('setEffectiveElasticModulusAndRestitutionCoefficient', 'setElasticModulusAndRestitutionCoefficient')
            if (st%old) msg = key // ' is not a setter of ' // st%species
            call nargs(2)
            call set_modulus(x(1))
            if (len(msg) > 0) return
            if (.not. (x(2) >= 0.0_wp .and. x(2) <= 1.0_wp)) then
                msg = key // ': restitution ' // fmt_short(x(2), ROUND_TRIP) // ' must be in [0, 1]'
                return
            end if
            st%kind = 'restitution'
            deck%p = x(2)
            deck%e_deck = x(2)
            deck%p_name = 'restitution argument of ' // key
            deck%p_template = key // '=' // fmt_short(x(1), ROUND_TRIP) // ',{}'
        case ('setEffectiveElasticModulus', 'setEffectiveElasticModulusAndPoissonRatio')
            if (st%old) msg = key // ' is not a setter of ' // st%species
            call nargs(merge(1, 2, key == 'setEffectiveElasticModulus'))
            call set_modulus(x(1))
        case ('setElasticModulus')
            call nargs(1)
            call set_modulus(x(1))
        case ('setDissipation')
            call nargs(1)
            if (len(msg) == 0 .and. .not. x(1) >= 0.0_wp) then
                msg = 'setDissipation(' // fmt_short(x(1), ROUND_TRIP) // '): must be >= 0'
            end if
            if (len(msg) > 0) return
            st%kind = 'dissipation'
            deck%p = x(1)
            deck%e_deck = -1.0_wp
            deck%p_name = 'setDissipation'
            deck%p_template = 'setDissipation={}'
        case ('setStiffnessAndRestitutionCoefficient')
            call stiffness_restitution(key, x, st, deck, msg)
        case ('setDensity')
            call nargs(1)
            if (len(msg) == 0 .and. mat%density(1) > 0.0_wp) msg = 'setDensity and --density both give the density; give one'
            if (len(msg) == 0) st%mat%density = x(1)
        case default
        end select
    contains
        subroutine nargs(k)
            integer, intent(in) :: k
            if (len(msg) == 0 .and. size(x) /= k) msg = key // ' takes ' // itoa(k) // ' arguments, got ' // itoa(size(x))
        end subroutine nargs
        subroutine set_modulus(y)
            real(wp), intent(in) :: y
            if (len(msg) > 0) return
            call check_modulus(y, key // ' modulus', fmt_short(y, ROUND_TRIP), msg)
            st%emod = y
            st%have_e = .true.
        end subroutine set_modulus
    end subroutine setter

    !> Beta 2015 setStiffnessAndRestitutionCoefficient(k_, e, mass).
    subroutine stiffness_restitution(key, x, st, deck, msg)
        character(len=*), intent(in) :: key
        real(wp), intent(in) :: x(:)
        type(species_state), intent(inout) :: st
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        if (.not. st%old) msg = key // ' is not a setter of ' // st%species
        if (len(msg) == 0 .and. size(x) /= 3) msg = key // ' takes 3 arguments, got ' // itoa(size(x))
        if (len(msg) > 0) return
        call check_modulus(x(1), key // ' modulus', fmt_short(x(1), ROUND_TRIP), msg)
        st%emod = x(1)
        st%have_e = .true.
        if (len(msg) > 0) return
        if (.not. (x(2) > 0.0_wp .and. x(2) <= 1.0_wp)) then
            msg = key // ': restitution ' // fmt_short(x(2), ROUND_TRIP) // ' must be in (0, 1]'
        else if (.not. x(3) > 0.0_wp) then
            msg = key // ': mass ' // fmt_short(x(3), ROUND_TRIP) // ' must be positive'
        end if
        if (len(msg) > 0) return
        st%kind = 'stiffness_restitution'
        deck%p = x(2)
        deck%e_deck = x(2)
        deck%mass_arg = x(3)
        deck%p_name = 'restitution argument of setStiffnessAndRestitutionCoefficient'
        deck%p_template = key // '=' // fmt_short(x(1), ROUND_TRIP) // ',{},' // fmt_short(x(3), ROUND_TRIP)
    end subroutine stiffness_restitution

    !> The species after its setters: the specification row and k.
    subroutine resolve(st, deck, msg)
        type(species_state), intent(in) :: st
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        if (.not. st%have_e) then
            if (st%old) then
                msg = 'missing the elastic modulus: setElasticModulus or setStiffnessAndRestitutionCoefficient'
            else
                msg = 'missing the elastic modulus: setEffectiveElasticModulusAndRestitutionCoefficient'
            end if
            return
        end if
        if (len(st%kind) == 0) then
            if (st%old) then
                msg = 'missing the dissipation: setDissipation or setStiffnessAndRestitutionCoefficient'
            else
                msg = 'missing the dissipation: setEffectiveElasticModulusAndRestitutionCoefficient or setDissipation'
            end if
            return
        end if
        call bodies(st%mat, deck, msg)
        if (len(msg) > 0) return
        deck%e_star = st%emod
        deck%modulus_arg = st%emod
        if (st%old) then
            deck%k = hertz_k(sqrt(2.0_wp) * st%emod, deck%radius)
            deck%k_text = 'k = (4/3) sqrt(2) E sqrt(R) (stiffness uses sqrt(2 R delta), the "effective diameter")'
            deck%row = peer_spec_row('mercurydpm2015-' // st%kind // '-overlap')
            if (st%kind == 'stiffness_restitution') then
                call add_note(deck, 'setStiffnessAndRestitutionCoefficient applies the linear-spring rule ' // &
                              'd = beta(e) sqrt(2 mass k_) with the modulus E in place of a spring constant: ' // &
                              'd has units kg s^-1 m^-1/2, not kg s^-1')
            end if
        else
            deck%k = hertz_k(st%emod, deck%radius)
            deck%k_text = 'k = (4/3) E_eff sqrt(R) (E_eff: the effective modulus the species holds)'
            deck%row = peer_spec_row('mercurydpm-' // st%kind // '-overlap')
            deck%tstep = TSTEP_MERCURY
        end if
        deck%deck_text = st%species // ':' // st%calls
    end subroutine resolve

end module hertzdamp_check_mercury
