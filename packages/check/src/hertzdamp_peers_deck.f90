!> Reading a peer engine's contact parameters, in the engine's own keywords, into a
!> resolved `peer_deck` (hertzdamp_peers): which specification row applies, the damping
!> parameter, the effective mass and radius, and the Hertz stiffness k as the engine
!> builds it (doc/peers.md, sections 1-6).
!>
!> Input: the engine name, its parameters as tokens, and the bodies' radii and densities.
!> - lammps: the arguments of `pair_coeff I J ...` for `pair_style granular`, or of
!>   `fix ID group wall/gran granular ...` (then body 2 is a flat wall), e.g.
!>   `hertz/material 1e8 0.5 0.3 tangential linear_nohistory 0 0 damping tsuji`;
!>   the leading `pair_coeff I J` or `fix ID group wall/gran granular` may be included.
!> - the others: `key=value` tokens with the engine's own names (lists `v1,v2` for
!>   per-body values; see `peer_known_keys`).
!> Errors give a one-line message naming the key or token; nothing is printed.
module hertzdamp_peers_deck
    use hertzdamp, only: hertzdamp_rk, hertzdamp_message, HD_OK, HD_BAD_ARGUMENT
    use hertzdamp_materials, only: hertzdamp_sphere_mass, hertzdamp_effective_mass, hertzdamp_effective_radius, &
                                   hertzdamp_effective_modulus, hertzdamp_hertz_stiffness
    use hertzdamp_peers, only: peer_deck, peer_text, peer_spec_row, peer_row_law, peer_row_end, peer_row_coef, &
                               PEER_LAMMPS, PEER_LIGGGHTS, PEER_MERCURYDPM, PEER_YADE, PEER_MFIX, PEER_CHRONO, &
                               TSTEP_LIGGGHTS, TSTEP_MERCURY, TSTEP_MFIX, peer_name, &
                               COEF_GAMMA_SQRT5_BETA
    use hertzdamp_apps_text, only: lower, upper, itoa, fmt_short, ROUND_TRIP
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use, intrinsic :: iso_fortran_env, only: real32
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> LAMMPS releases whose formulas differ (doc/peers.md section 1).
    integer, parameter, public :: LAMMPS_2021 = 1     !! 29 Sep 2021 update 2 (Debian 12)
    integer, parameter, public :: LAMMPS_2023 = 2     !! 28 Mar 2023 (granular refactor) .. at least 29 Aug 2024
    integer, parameter, public :: LAMMPS_CURRENT = 3  !! lammps/lammps 07b704ca (tsuji with sqrt(2))
    character(len=*), parameter, public :: lammps_releases = '2021 2023 current'

    !> The bodies: radius and density of body 1 and 2 (<= 0: not given; body 2
    !> defaults to body 1), or a wall as body 2.
    type, public :: peer_materials
        real(wp) :: radius(2) = 0.0_wp    !! [m]
        real(wp) :: density(2) = 0.0_wp   !! [kg m^-3]
        logical :: wall = .false.
    end type peer_materials

    !> key=value pairs of a deck, with a flag for the keys consumed.
    type :: kv_list
        type(peer_text), allocatable :: key(:), val(:)
        logical, allocatable :: used(:)
    end type kv_list

    public :: peer_read_deck, peer_code, peer_known_keys, peer_parameter_problem

contains

    !> The PEER_* code of an engine name (case-insensitive), 0 if unknown.
    pure integer function peer_code(name) result(code)
        character(len=*), intent(in) :: name   !! lammps, liggghts, mercurydpm, yade, mfix, chrono
        integer :: j
        code = 0
        do j = PEER_LAMMPS, PEER_CHRONO
            if (peer_name(j) == lower(name)) code = j
        end do
    end function peer_code

    !> The keys an engine accepts, space-separated (lammps: the pair_coeff keywords).
    pure function peer_known_keys(peer) result(keys)
        integer, intent(in) :: peer   !! PEER_*
        character(len=:), allocatable :: keys
        select case (peer)
        case (PEER_LAMMPS)
            keys = 'hertz hertz/material damping tangential rolling twisting heat cutoff limit_damping'
        case (PEER_LIGGGHTS)
            keys = 'model limitForce youngsModulus poissonsRatio coefficientRestitution kn gamman tangential ' // &
                   'tangential_damping rolling_friction cohesion'
        case (PEER_MERCURYDPM)
            keys = 'species setEffectiveElasticModulusAndRestitutionCoefficient ' // &
                   'setElasticModulusAndRestitutionCoefficient setEffectiveElasticModulus setElasticModulus ' // &
                   'setEffectiveElasticModulusAndPoissonRatio setDissipation setStiffnessAndRestitutionCoefficient ' // &
                   'setDensity'
        case (PEER_YADE)
            keys = 'young poisson en betan density shape hertzian'
        case (PEER_MFIX)
            keys = 'DES_COLL_MODEL DES_EN_INPUT DES_EN_WALL_INPUT DES_ET_INPUT DES_ET_WALL_INPUT E_YOUNG V_POISSON ' // &
                   'EW_YOUNG VW_POISSON D_P0 RO_S0 DTSOLID_FACTOR'
        case (PEER_CHRONO)
            keys = 'SetContactForceModel UseMaterialProperties SetYoungModulus SetPoissonRatio SetRestitution ' // &
                   'SetKn SetGn SetCollisionSystemType wallMass'
        case default
            keys = ''
        end select
    end function peer_known_keys

    !> Read a deck.  On failure status = HD_BAD_ARGUMENT and message names the key.
    subroutine peer_read_deck(peer, tokens, mat, release, deck, status, message)
        integer, intent(in) :: peer                     !! PEER_*
        type(peer_text), intent(in) :: tokens(:)        !! the engine's parameters
        type(peer_materials), intent(in) :: mat         !! radii and densities (or peer keys give them)
        integer, intent(in) :: release                  !! LAMMPS_* (lammps only)
        type(peer_deck), intent(out) :: deck
        integer, intent(out) :: status                  !! HD_OK or HD_BAD_ARGUMENT
        character(len=:), allocatable, intent(out) :: message
        type(kv_list) :: kv
        message = ''
        deck%peer = peer
        deck%version = ''
        deck%deck_text = ''
        deck%k_text = ''
        deck%p_name = ''
        deck%p_template = ''
        allocate (deck%notes(0))
        deck%wall = mat%wall
        if (peer == PEER_LAMMPS) then
            call read_lammps(tokens, mat, release, deck, message)
        else
            call split_pairs(tokens, peer == PEER_MFIX, kv, message)
            if (len(message) == 0) then
                select case (peer)
                case (PEER_LIGGGHTS); call read_liggghts(kv, mat, deck, message)
                case (PEER_MERCURYDPM); call read_mercury(kv, mat, deck, message)
                case (PEER_YADE); call read_yade(kv, mat, deck, message)
                case (PEER_MFIX); call read_mfix(kv, mat, deck, message)
                case (PEER_CHRONO); call read_chrono(kv, mat, deck, message)
                case default; message = 'unknown engine'
                end select
            end if
            if (len(message) == 0) call check_all_used(kv, peer, message)
        end if
        if (len(message) == 0 .and. deck%row > 0) then
            deck%law = peer_row_law(deck%row)
            deck%iend = peer_row_end(deck%row)
            deck%coef = peer_row_coef(deck%row)
        end if
        if (len(message) == 0 .and. deck%row == 0) message = 'internal error: no specification row'
        if (len(message) == 0) then
            if (.not. (deck%k > 0.0_wp .and. ieee_is_finite(deck%k) .and. deck%m > 0.0_wp .and. &
                       ieee_is_finite(deck%m) .and. deck%m_damp > 0.0_wp)) then
                message = 'the stiffness or mass is out of the double-precision range'
            end if
        end if
        status = merge(HD_OK, HD_BAD_ARGUMENT, len(message) == 0)
    end subroutine peer_read_deck

    !> Why the engine would refuse the value p of the deck's damping parameter ('' if
    !> it takes it): the ranges the engines check, or where their formula breaks.
    pure function peer_parameter_problem(deck, p) result(msg)
        type(peer_deck), intent(in) :: deck   !! the resolved deck
        real(wp), intent(in) :: p             !! a value of deck%p_name
        character(len=:), allocatable :: msg
        msg = ''
        if (deck%e_deck < 0.0_wp) then
            if (.not. p >= 0.0_wp) msg = deck%p_name // ' = ' // fmt_short(p, ROUND_TRIP) // ' is negative'
            return
        end if
        if (deck%peer == PEER_LIGGGHTS) then
            if (.not. (p > 0.05_wp .and. p <= 1.0_wp)) msg = 'LIGGGHTS refuses coefficientRestitution = ' // &
                fmt_short(p, 6) // ' (it requires 0.05 < e <= 1, global_properties.cpp:488)'
        else if (.not. (p >= 0.0_wp .and. p <= 1.0_wp)) then
            msg = deck%p_name // ' = ' // fmt_short(p, 6) // ' is not a restitution coefficient in [0, 1]'
        else if (p == 0.0_wp .and. deck%coef == COEF_GAMMA_SQRT5_BETA .and. deck%peer /= PEER_MERCURYDPM) then
            msg = deck%p_name // ' = 0: the engine takes ln(0) (not guarded)'
        end if
    end function peer_parameter_problem

    ! ------------------------------------------------------------------ LAMMPS

    subroutine read_lammps(tok, mat, release, deck, msg)
        type(peer_text), intent(in) :: tok(:)
        type(peer_materials), intent(in) :: mat
        integer, intent(in) :: release
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: normal, damping, t, rel, dm, normal_text, template
        real(wp) :: kn, c, ymod, nu, x
        logical :: limit, is_fix, after_wall
        integer :: i, n, na
        n = size(tok)
        normal = ''
        normal_text = ''
        template = ''
        damping = 'viscoelastic'
        limit = .false.
        is_fix = .false.
        after_wall = .false.
        kn = 0.0_wp
        c = 0.0_wp
        ymod = 0.0_wp
        nu = 0.0_wp
        i = 1
        if (n == 0) then
            msg = 'no pair_coeff arguments given (e.g. hertz/material 1e8 0.5 0.3 damping tsuji)'
            return
        end if
        select case (tok(1)%s)
        case ('pair_coeff')
            if (n < 3) then
                msg = 'pair_coeff needs the two atom types before the model'
                return
            end if
            i = 4
        case ('pair_style')
            msg = 'give the arguments of pair_coeff (pair_style granular takes only a cutoff)'
            return
        case ('fix')
            if (n < 5) then
                msg = 'fix: expected "fix ID group wall/gran granular ..."'
                return
            end if
            if (tok(4)%s /= 'wall/gran') then
                msg = 'fix style "' // tok(4)%s // '": only fix wall/gran is checked'
                return
            end if
            if (tok(5)%s /= 'granular') then
                msg = 'fix wall/gran ' // tok(5)%s // ': only the granular style is checked (hertz, hertz/material)'
                return
            end if
            is_fix = .true.
            i = 6
        case default
        end select
        do while (i <= n .and. len(msg) == 0)
            t = tok(i)%s
            if (after_wall) then
                ! fix wall/gran keywords after the wall style
                select case (t)
                case ('wiggle'); na = 3
                case ('shear'); na = 2
                case ('contacts'); na = 0
                case ('temperature'); na = 1
                case default
                    msg = 'unknown fix wall/gran keyword "' // t // '"'
                    exit
                end select
                if (i + na > n) msg = 'fix wall/gran ' // t // ' needs ' // itoa(na) // ' values'
                i = i + na + 1
                cycle
            end if
            select case (t)
            case ('hertz', 'hertz/material')
                if (len(normal) > 0) then
                    msg = 'normal model given twice (' // normal // ' and ' // t // ')'
                    exit
                end if
                normal = t
                na = merge(2, 3, t == 'hertz')
                if (i + na > n) then
                    msg = t // ' needs ' // itoa(na) // ' values (' // trim(merge('kn eta_n0  ', 'E eta_n0 nu', &
                          t == 'hertz')) // ')'
                    exit
                end if
                normal_text = join(tok(i:i + na))
                template = tok(i)%s // ' ' // tok(i + 1)%s // ' {}'
                if (na == 3) template = template // ' ' // tok(i + 3)%s
                if (t == 'hertz') then
                    call number(tok(i + 1)%s, 'hertz kn', kn, msg)
                    call number(tok(i + 2)%s, 'hertz damping coefficient', c, msg)
                    if (len(msg) == 0 .and. .not. kn > 0.0_wp) msg = 'hertz kn = ' // tok(i + 1)%s // ' must be positive'
                else
                    call number(tok(i + 1)%s, 'hertz/material E', ymod, msg)
                    call number(tok(i + 2)%s, 'hertz/material damping coefficient', c, msg)
                    call number(tok(i + 3)%s, 'hertz/material nu', nu, msg)
                    if (len(msg) == 0) call check_modulus(ymod, 'hertz/material E', tok(i + 1)%s, msg)
                    if (len(msg) == 0) call check_poisson(nu, 'hertz/material nu', tok(i + 3)%s, msg)
                end if
                i = i + na + 1
            case ('hooke')
                msg = 'normal model hooke is a linear spring; hertzdamp checks Hertz contacts (hertz, hertz/material)'
            case ('dmt', 'jkr')
                msg = 'normal model ' // t // ' is cohesive; hertzdamp checks non-cohesive Hertz contacts ' // &
                      '(hertz, hertz/material)'
            case ('mdr')
                msg = 'normal model mdr is not a Hertz contact; hertzdamp checks hertz and hertz/material'
            case ('damping')
                if (i + 1 > n) then
                    msg = 'damping needs a model name'
                    exit
                end if
                damping = tok(i + 1)%s
                select case (damping)
                case ('velocity', 'mass_velocity', 'viscoelastic', 'tsuji', 'coeff_restitution')
                case ('none')
                    msg = 'damping none: the contact is elastic (e = 1), nothing to check'
                case default
                    msg = 'unknown damping model "' // damping // &
                          '" (velocity, mass_velocity, viscoelastic, tsuji, coeff_restitution)'
                end select
                i = i + 2
            case ('tangential', 'rolling', 'twisting', 'heat')
                if (i + 1 > n) then
                    msg = t // ' needs a model name'
                    exit
                end if
                na = submodel_args(t, tok(i + 1)%s)
                if (na < 0) then
                    msg = 'unknown ' // t // ' model "' // tok(i + 1)%s // '"'
                    exit
                end if
                if (i + 1 + na > n) then
                    msg = t // ' ' // tok(i + 1)%s // ' needs ' // itoa(na) // ' values'
                    exit
                end if
                call check_values(tok(i + 2:i + 1 + na), t // ' ' // tok(i + 1)%s, msg)
                i = i + 2 + na
            case ('cutoff')
                if (i + 1 > n) then
                    msg = 'cutoff needs a value'
                    exit
                end if
                call number(tok(i + 1)%s, 'cutoff', x, msg)
                i = i + 2
            case ('limit_damping')
                limit = .true.
                i = i + 1
            case ('xplane', 'yplane', 'zplane')
                if (.not. is_fix) then
                    msg = 'wall style ' // t // ' belongs to fix wall/gran; use --wall or give the fix line'
                    exit
                end if
                if (i + 2 > n) then
                    msg = t // ' needs lo and hi'
                    exit
                end if
                call check_values(tok(i + 1:i + 2), t, msg)
                after_wall = .true.
                i = i + 3
            case ('zcylinder', 'region')
                msg = 'wall style ' // t // ': only flat walls (xplane, yplane, zplane) are checked'
            case default
                msg = 'unknown pair_coeff keyword "' // t // '" (known: ' // peer_known_keys(PEER_LAMMPS) // ')'
            end select
        end do
        if (len(msg) > 0) return
        if (len(normal) == 0) then
            msg = 'missing normal model: hertz kn eta_n0, or hertz/material E eta_n0 nu'
            return
        end if
        if (is_fix) deck%wall = .true.
        if (is_fix .and. .not. after_wall) then
            msg = 'fix wall/gran: missing wall style (xplane, yplane or zplane)'
            return
        end if
        ! release
        select case (release)
        case (LAMMPS_2021)
            rel = '2021'
            deck%version = 'LAMMPS 29 Sep 2021 update 2 (Debian 12)'
        case (LAMMPS_2023)
            rel = '2023'
            deck%version = 'LAMMPS 28 Mar 2023 to 29 Aug 2024 (granular sub-models)'
        case default
            rel = 'current'
            deck%version = 'LAMMPS current (lammps/lammps 07b704ca)'
        end select
        if (damping == 'coeff_restitution' .and. release == LAMMPS_2021) then
            msg = 'damping coeff_restitution does not exist in LAMMPS 29 Sep 2021 (added in 27 Jun 2024); ' // &
                  'choose --release 2023 or current'
            return
        end if
        dm = damping
        if (damping == 'tsuji' .or. damping == 'coeff_restitution') then
            if (.not. (c >= 0.0_wp .and. c <= 1.0_wp)) then
                msg = normal // ' damping coefficient ' // fmt_short(c, ROUND_TRIP) // ': with damping ' // damping // &
                      ' it is the restitution coefficient e, 0 <= e <= 1'
                return
            end if
            if (damping == 'coeff_restitution' .and. c <= 0.0_wp) then
                msg = normal // ' damping coefficient 0 with damping coeff_restitution: LAMMPS takes ln(0) ' // &
                      '(not guarded), the damping is NaN'
                return
            end if
            deck%e_deck = c
            deck%p_name = normal // ' damping coefficient (e of damping ' // damping // ')'
            if (damping == 'coeff_restitution') rel = '2024'
        else
            if (.not. c >= 0.0_wp) then
                msg = normal // ' damping coefficient eta_n0 = ' // fmt_short(c, ROUND_TRIP) // ' must be >= 0'
                return
            end if
            deck%p_name = normal // ' damping coefficient eta_n0 (damping ' // damping // ')'
            if (release /= LAMMPS_2021) rel = '2023'
        end if
        deck%p = c
        deck%p_template = template // ' damping ' // damping // trim(merge(' limit_damping', '              ', limit))
        deck%row = peer_spec_row('lammps-' // rel // '-' // dm // '-' // end_word(limit))
        call bodies(mat, deck, msg)
        if (len(msg) > 0) return
        if (normal == 'hertz') then
            deck%k = kn * sqrt(deck%radius)
            deck%k_text = 'k = kn sqrt(R) (normal hertz)'
        else if (deck%wall .and. release == LAMMPS_2021) then
            deck%e_star = ymod / (2.0_wp * (1.0_wp - nu))
            deck%k = hertz_k(deck%e_star, deck%radius)
            deck%k_text = 'k = (4/3) E/(2(1-nu)) sqrt(R) (fix wall/gran hertz/material, LAMMPS 2021: 1-nu, not 1-nu^2)'
            call add_note(deck, 'LAMMPS 29 Sep 2021 fix wall/gran builds the hertz/material stiffness with 1-nu ' // &
                          'instead of 1-nu^2 (fix_wall_gran.cpp:160,171,183): k is 1+nu times the pair formula; ' // &
                          'the 2023 refactor removed this')
        else
            deck%e_star = ymod / (2.0_wp * (1.0_wp - nu) * (1.0_wp + nu))
            deck%k = hertz_k(deck%e_star, deck%radius)
            deck%k_text = 'k = (4/3) E/(2(1-nu^2)) sqrt(R) (hertz/material, one material on both sides)'
        end if
        deck%deck_text = normal_text // ' damping ' // damping // merge(' limit_damping', '              ', limit)
        deck%deck_text = trim(deck%deck_text)
        if (deck%wall) deck%deck_text = 'fix wall/gran granular ' // deck%deck_text // ' (flat wall)'
        call add_note(deck, 'LAMMPS damps with the half-step velocity (fix nve/sphere), an error of first ' // &
                      'order in the time step on top of what is shown here')
    end subroutine read_lammps

    !> Number of values of a LAMMPS granular sub-model (union of 2021 and 2023+), -1 if unknown.
    pure integer function submodel_args(kind, name) result(na)
        character(len=*), intent(in) :: kind, name
        na = -1
        select case (kind)
        case ('tangential')
            select case (name)
            case ('none'); na = 0
            case ('linear_nohistory'); na = 2
            case ('linear_history', 'linear_history_classic', 'mindlin', 'mindlin_classic', 'mindlin/force', &
                  'mindlin_rescale', 'mindlin_rescale/force'); na = 3
            case default
            end select
        case ('rolling')
            select case (name)
            case ('none'); na = 0
            case ('sds'); na = 3
            case default
            end select
        case ('twisting')
            select case (name)
            case ('none', 'marshall'); na = 0
            case ('sds'); na = 3
            case default
            end select
        case ('heat')
            select case (name)
            case ('none'); na = 0
            case ('area', 'radius'); na = 1
            case default
            end select
        case default
        end select
    end function submodel_args

    !> Values of a keyword: numbers or NULL.
    subroutine check_values(vals, what, msg)
        type(peer_text), intent(in) :: vals(:)
        character(len=*), intent(in) :: what
        character(len=:), allocatable, intent(inout) :: msg
        integer :: j
        real(wp) :: x
        do j = 1, size(vals)
            if (vals(j)%s == 'NULL') cycle
            call number(vals(j)%s, what, x, msg)
        end do
    end subroutine check_values

    ! ------------------------------------------------------------------ LIGGGHTS

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

    ! ------------------------------------------------------------------ MercuryDPM

    subroutine read_mercury(kv, mat, deck, msg)
        type(kv_list), intent(inout) :: kv
        type(peer_materials), intent(in) :: mat
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: species, v, key, calls, kind
        real(wp) :: emod, x(3), rho
        logical :: old, have_e
        type(peer_materials) :: m2
        integer :: i, nx
        species = 'HertzianViscoelasticNormalSpecies'
        if (take(kv, 'species', v)) species = v
        select case (species)
        case ('HertzianViscoelasticNormalSpecies')
            old = .false.
        case ('HertzianViscoelasticSpecies')
            old = .true.
        case default
            msg = 'species = ' // species // ': checked are HertzianViscoelasticNormalSpecies (current) and ' // &
                  'HertzianViscoelasticSpecies (Beta 2015)'
            return
        end select
        emod = -1.0_wp
        have_e = .false.
        kind = ''
        m2 = mat
        calls = ''
        ! the setters act in the order given, as the C++ calls do
        do i = 1, size(kv%key)
            key = kv%key(i)%s
            if (key == 'species') cycle
            select case (key)
            case ('setEffectiveElasticModulusAndRestitutionCoefficient', 'setElasticModulusAndRestitutionCoefficient', &
                  'setEffectiveElasticModulus', 'setEffectiveElasticModulusAndPoissonRatio', 'setElasticModulus', &
                  'setDissipation', 'setStiffnessAndRestitutionCoefficient', 'setDensity')
                kv%used(i) = .true.
                call values(kv%val(i)%s, key, x, nx, msg)
                if (len(msg) > 0) return
                calls = calls // ' ' // key // '(' // kv%val(i)%s // ')'
            case default
                cycle
            end select
            select case (key)
            case ('setEffectiveElasticModulusAndRestitutionCoefficient', 'setElasticModulusAndRestitutionCoefficient')
                if (old) call wrong_species()
                call nargs(2)
                if (len(msg) > 0) return
                call set_modulus(x(1))
                if (.not. (x(2) >= 0.0_wp .and. x(2) <= 1.0_wp)) then
                    msg = key // ': restitution ' // fmt_short(x(2), ROUND_TRIP) // ' must be in [0, 1]'
                    return
                end if
                kind = 'restitution'
                deck%p = x(2)
                deck%e_deck = x(2)
                deck%p_name = 'restitution argument of ' // key
                deck%p_template = key // '=' // fmt_short(x(1), ROUND_TRIP) // ',{}'
            case ('setEffectiveElasticModulus', 'setEffectiveElasticModulusAndPoissonRatio')
                if (old) call wrong_species()
                call nargs(merge(1, 2, key == 'setEffectiveElasticModulus'))
                if (len(msg) > 0) return
                call set_modulus(x(1))
            case ('setElasticModulus')
                call nargs(1)
                if (len(msg) > 0) return
                call set_modulus(x(1))
            case ('setDissipation')
                call nargs(1)
                if (len(msg) > 0) return
                if (.not. x(1) >= 0.0_wp) then
                    msg = 'setDissipation(' // fmt_short(x(1), ROUND_TRIP) // '): must be >= 0'
                    return
                end if
                kind = 'dissipation'
                deck%p = x(1)
                deck%e_deck = -1.0_wp
                deck%p_name = 'setDissipation'
                deck%p_template = 'setDissipation={}'
            case ('setStiffnessAndRestitutionCoefficient')
                if (.not. old) call wrong_species()
                call nargs(3)
                if (len(msg) > 0) return
                call set_modulus(x(1))
                if (.not. (x(2) > 0.0_wp .and. x(2) <= 1.0_wp)) then
                    msg = key // ': restitution ' // fmt_short(x(2), ROUND_TRIP) // ' must be in (0, 1]'
                    return
                end if
                if (.not. x(3) > 0.0_wp) then
                    msg = key // ': mass ' // fmt_short(x(3), ROUND_TRIP) // ' must be positive'
                    return
                end if
                kind = 'stiffness_restitution'
                deck%p = x(2)
                deck%e_deck = x(2)
                deck%mass_arg = x(3)
                deck%p_name = 'restitution argument of setStiffnessAndRestitutionCoefficient'
                deck%p_template = key // '=' // fmt_short(x(1), ROUND_TRIP) // ',{},' // fmt_short(x(3), ROUND_TRIP)
            case ('setDensity')
                call nargs(1)
                if (len(msg) > 0) return
                rho = x(1)
                if (mat%density(1) > 0.0_wp) then
                    msg = 'setDensity and --density both give the density; give one'
                    return
                end if
                m2%density = rho
            case default
            end select
            if (len(msg) > 0) return
        end do
        if (.not. have_e) then
            if (old) then
                msg = 'missing the elastic modulus: setElasticModulus or setStiffnessAndRestitutionCoefficient'
            else
                msg = 'missing the elastic modulus: setEffectiveElasticModulusAndRestitutionCoefficient'
            end if
            return
        end if
        if (len(kind) == 0) then
            if (old) then
                msg = 'missing the dissipation: setDissipation or setStiffnessAndRestitutionCoefficient'
            else
                msg = 'missing the dissipation: setEffectiveElasticModulusAndRestitutionCoefficient or setDissipation'
            end if
            return
        end if
        call bodies(m2, deck, msg)
        if (len(msg) > 0) return
        deck%e_star = emod
        deck%modulus_arg = emod
        if (old) then
            deck%k = hertz_k(sqrt(2.0_wp) * emod, deck%radius)
            deck%k_text = 'k = (4/3) sqrt(2) E sqrt(R) (stiffness uses sqrt(2 R delta), the "effective diameter")'
            deck%row = peer_spec_row('mercurydpm2015-' // kind // '-overlap')
            if (kind == 'stiffness_restitution') then
                call add_note(deck, 'setStiffnessAndRestitutionCoefficient applies the linear-spring rule ' // &
                              'd = beta(e) sqrt(2 mass k_) with the modulus E in place of a spring constant: ' // &
                              'd has units kg s^-1 m^-1/2, not kg s^-1')
            end if
        else
            deck%k = hertz_k(emod, deck%radius)
            deck%k_text = 'k = (4/3) E_eff sqrt(R) (E_eff: the effective modulus the species holds)'
            deck%row = peer_spec_row('mercurydpm-' // kind // '-overlap')
            deck%tstep = TSTEP_MERCURY
        end if
        deck%deck_text = species // ':' // calls
    contains
        subroutine nargs(k)
            integer, intent(in) :: k
            if (nx /= k) msg = key // ' takes ' // itoa(k) // ' arguments, got ' // itoa(nx)
        end subroutine nargs
        subroutine set_modulus(y)
            real(wp), intent(in) :: y
            call check_modulus(y, key // ' modulus', fmt_short(y, ROUND_TRIP), msg)
            emod = y
            have_e = .true.
        end subroutine set_modulus
        subroutine wrong_species()
            msg = key // ' is not a setter of ' // species
        end subroutine wrong_species
    end subroutine read_mercury

    ! ------------------------------------------------------------------ Yade

    subroutine read_yade(kv, mat, deck, msg)
        type(kv_list), intent(inout) :: kv
        type(peer_materials), intent(in) :: mat
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: v, shape
        real(wp) :: ymod(2), nu(2), e, b, ref, rho
        logical :: hertzian
        type(peer_materials) :: m2
        m2 = mat
        shape = 'Wall'
        hertzian = .false.
        if (take(kv, 'density', v)) then
            call number(v, 'density', rho, msg)
            if (mat%density(1) > 0.0_wp) msg = 'density and --density both give the density; give one'
            if (len(msg) > 0) return
            m2%density = rho
        end if
        if (take(kv, 'shape', v)) then
            shape = v
            if (.not. mat%wall) msg = 'shape = ' // v // ' applies to a wall contact (--wall)'
            if (v /= 'Wall' .and. v /= 'Facet') msg = 'shape = ' // v // ': Wall or Facet'
        end if
        if (take(kv, 'hertzian', v)) then
            if (.not. mat%wall) msg = 'hertzian applies to a wall contact (--wall)'
            select case (v)
            case ('True', 'true', '1'); hertzian = .true.
            case ('False', 'false', '0'); hertzian = .false.
            case default; msg = 'hertzian = ' // v // ': True or False'
            end select
        end if
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
        if (deck%wall) then
            ! Ig2_Wall_Sphere_ScGeom / Ig2_Facet_Sphere_ScGeom: the wall's reference radius
            ! (Ig2_Facet_Sphere_ScGeom.cpp:127, 220), R = refR1 r / (refR1 + r)
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
        end if
        deck%e_star = effective_modulus(ymod, nu)
        deck%k = hertz_k(deck%e_star, deck%radius)
        deck%k_text = 'k = Kno = (4/3) E* sqrt(R), 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2'
        if (take(kv, 'en', v)) then
            call number(v, 'en', e, msg)
            if (len(msg) > 0) return
            if (.not. (e > 0.0_wp .and. e <= 1.0_wp)) then
                msg = 'en = ' // v // ': must be in (0, 1] (Yade takes ln(en); en = 0 gives NaN)'
                return
            end if
            deck%p = e
            deck%e_deck = e
            deck%p_name = 'en'
            deck%p_template = 'en={}'
            deck%row = peer_spec_row('yade-en-force')
            deck%deck_text = 'Ip2_FrictMat_FrictMat_MindlinPhys(en=' // v // ')'
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
            return
        end if
        deck%deck_text = deck%deck_text // ' FrictMat(young=' // fmt_short(ymod(1), ROUND_TRIP) // ', poisson=' // &
                         fmt_short(nu(1), ROUND_TRIP) // ')'
        if (deck%wall) then
            deck%deck_text = deck%deck_text // ', ' // shape // ' (young=' // fmt_short(ymod(2), ROUND_TRIP) // ', poisson=' // &
                             fmt_short(nu(2), ROUND_TRIP) // ')'
            if (hertzian) deck%deck_text = deck%deck_text // ', hertzian=True'
        end if
    end subroutine read_yade

    ! ------------------------------------------------------------------ MFiX

    subroutine read_mfix(kv, mat, deck, msg)
        type(kv_list), intent(inout) :: kv
        type(peer_materials), intent(in) :: mat
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: v, ekey
        real(wp) :: ymod(2), nu(2), e, x(3)
        type(peer_materials) :: m2
        integer :: nx
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
        if (upper(unquote(v)) /= 'HERTZIAN') then
            msg = 'DES_COLL_MODEL = ' // v // ': hertzdamp checks ''HERTZIAN'' (LSD is a linear spring)'
            return
        end if
        if (take(kv, 'DES_ET_INPUT', v)) continue
        if (take(kv, 'DES_ET_WALL_INPUT', v)) continue
        if (take(kv, 'D_P0', v)) then
            if (mat%radius(1) > 0.0_wp) msg = 'D_P0 and --radius both give the particle size; give one'
            call values(v, 'D_P0', x, nx, msg)
            if (len(msg) > 0) return
            if (nx > 2) msg = 'D_P0: at most 2 values (body 1, body 2)'
            m2%radius(1:nx) = 0.5_wp * x(1:nx)
        end if
        if (take(kv, 'RO_S0', v)) then
            if (mat%density(1) > 0.0_wp) msg = 'RO_S0 and --density both give the density; give one'
            call values(v, 'RO_S0', x, nx, msg)
            if (len(msg) > 0) return
            if (nx > 2) msg = 'RO_S0: at most 2 values (body 1, body 2)'
            m2%density(1:nx) = x(1:nx)
        end if
        deck%dt_factor = 50.0_wp
        if (take(kv, 'DTSOLID_FACTOR', v)) then
            call number(v, 'DTSOLID_FACTOR', deck%dt_factor, msg)
            if (len(msg) == 0 .and. .not. deck%dt_factor > 0.0_wp) msg = 'DTSOLID_FACTOR must be positive'
        end if
        if (len(msg) > 0) return
        call bodies(m2, deck, msg)
        if (len(msg) > 0) return
        if (deck%wall) then
            call pair_values(kv, 'E_YOUNG', .false., ymod, msg)
            call pair_values(kv, 'V_POISSON', .false., nu, msg)
            if (len(msg) > 0) return
            call required(kv, 'EW_YOUNG', ymod(2), msg)
            call required(kv, 'VW_POISSON', nu(2), msg)
            ekey = 'DES_EN_WALL_INPUT'
        else
            call pair_values(kv, 'E_YOUNG', .false., ymod, msg)
            call pair_values(kv, 'V_POISSON', .false., nu, msg)
            ekey = 'DES_EN_INPUT'
        end if
        if (len(msg) > 0) return
        call check_modulus(ymod(1), 'E_YOUNG', fmt_short(ymod(1), ROUND_TRIP), msg)
        call check_modulus(ymod(2), trim(merge('EW_YOUNG', 'E_YOUNG ', deck%wall)), fmt_short(ymod(2), ROUND_TRIP), msg)
        call check_poisson(nu(1), 'V_POISSON', fmt_short(nu(1), ROUND_TRIP), msg)
        call check_poisson(nu(2), trim(merge('VW_POISSON', 'V_POISSON ', deck%wall)), fmt_short(nu(2), ROUND_TRIP), msg)
        call required(kv, ekey, e, msg)
        if (len(msg) > 0) return
        if (.not. (e >= 0.0_wp .and. e <= 1.0_wp)) then
            msg = ekey // ' = ' // fmt_short(e, ROUND_TRIP) // ': MFiX requires 0 <= e <= 1 (check_solids_dem.f)'
            return
        end if
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
    end subroutine read_mfix

    ! ------------------------------------------------------------------ Chrono

    subroutine read_chrono(kv, mat, deck, msg)
        type(kv_list), intent(inout) :: kv
        type(peer_materials), intent(in) :: mat
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: v, coll
        real(wp) :: ymod(2), nu(2), e(2), kn(2), gn(2), mwall, rphys
        real(real32) :: inv_e, e_eff, cr, kn_eff, gn_eff
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
        else
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
        end if
        deck%deck_text = deck%deck_text // ', ' // coll // merge(', wall', '      ', deck%wall)
        deck%deck_text = trim(deck%deck_text)
    end subroutine read_chrono

    ! ------------------------------------------------------------------ shared helpers

    !> Masses and radii of the bodies: effective mass and radius (a flat wall: the
    !> particle's), by the library's hertzdamp_materials.
    subroutine bodies(mat, deck, msg)
        type(peer_materials), intent(in) :: mat
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        real(wp) :: r(2), rho(2), m(2)
        integer :: st(2), st3
        r = mat%radius
        rho = mat%density
        if (.not. r(1) > 0.0_wp) then
            msg = 'missing --radius (the particle radius [m])'
            return
        end if
        if (.not. rho(1) > 0.0_wp) then
            msg = 'missing --density (the particle density [kg m^-3])'
            return
        end if
        if (.not. r(2) > 0.0_wp) r(2) = r(1)
        if (.not. rho(2) > 0.0_wp) rho(2) = rho(1)
        call hertzdamp_sphere_mass(r, rho, m, st)
        if (any(st /= HD_OK)) then
            msg = 'the particle mass (4/3) pi rho r^3: ' // hertzdamp_message(maxval(st))
            return
        end if
        deck%radius1 = r(1)
        deck%density1 = rho(1)
        deck%mass1 = m(1)
        if (deck%wall) then
            deck%m = m(1)
            deck%radius = r(1)
        else
            call hertzdamp_effective_mass(m(1), m(2), deck%m, st3)
            if (st3 == HD_OK) call hertzdamp_effective_radius(r(1), r(2), deck%radius, st3)
            if (st3 /= HD_OK) msg = 'effective mass or radius: ' // hertzdamp_message(st3)
        end if
        deck%m_damp = deck%m
    end subroutine bodies

    !> 'force' or 'overlap', the end of a row id.
    pure function end_word(limit) result(w)
        logical, intent(in) :: limit
        character(len=:), allocatable :: w
        if (limit) then
            w = 'force'
        else
            w = 'overlap'
        end if
    end function end_word

    !> 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (hertzdamp_effective_modulus; the inputs
    !> are checked before).
    function effective_modulus(ymod, nu) result(es)
        real(wp), intent(in) :: ymod(2), nu(2)
        real(wp) :: es
        integer :: st
        call hertzdamp_effective_modulus(ymod(1), nu(1), ymod(2), nu(2), es, st)
    end function effective_modulus

    !> k = (4/3) E* sqrt(R) (hertzdamp_hertz_stiffness, overflow-safe); 0 when it is out
    !> of range, which peer_read_deck reports.
    elemental function hertz_k(e_star, radius) result(k)
        real(wp), intent(in) :: e_star, radius
        real(wp) :: k
        integer :: st
        call hertzdamp_hertz_stiffness(e_star, radius, k, st)
    end function hertz_k

    subroutine check_modulus(x, what, text, msg)
        real(wp), intent(in) :: x
        character(len=*), intent(in) :: what, text
        character(len=:), allocatable, intent(inout) :: msg
        if (len(msg) > 0) return
        if (.not. (x > 0.0_wp)) msg = what // ' = ' // text // ': a modulus must be positive'
    end subroutine check_modulus

    subroutine check_poisson(x, what, text, msg)
        real(wp), intent(in) :: x
        character(len=*), intent(in) :: what, text
        character(len=:), allocatable, intent(inout) :: msg
        if (len(msg) > 0) return
        if (.not. (x > -1.0_wp .and. x <= 0.5_wp)) msg = what // ' = ' // text // ': Poisson''s ratio must be in (-1, 0.5]'
    end subroutine check_poisson

    !> A per-body value: `v` (both bodies, and the wall) or `v1,v2` (body 2 or the wall).
    subroutine pair_values(kv, key, wall, x, msg)
        type(kv_list), intent(inout) :: kv
        character(len=*), intent(in) :: key
        logical, intent(in) :: wall
        real(wp), intent(out) :: x(2)
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: v, v1, v2
        real(wp) :: y(3)
        integer :: ny
        logical :: got1, got2
        x = 0.0_wp
        if (len(msg) > 0) return
        ! MFiX style KEY(1)=, KEY(2)= as well
        got1 = take(kv, key // '(1)', v1)
        got2 = take(kv, key // '(2)', v2)
        if (take(kv, key, v)) then
            if (got1 .or. got2) then
                msg = key // ' given both whole and by index'
                return
            end if
            call values(v, key, y, ny, msg)
            if (len(msg) > 0) return
            if (ny > 2) then
                msg = key // ': at most 2 values (body 1, ' // trim(merge('the wall', 'body 2  ', wall)) // ')'
                return
            end if
            x(1) = y(1)
            x(2) = y(ny)
        else if (got1) then
            call number(v1, key // '(1)', x(1), msg)
            x(2) = x(1)
            if (got2) call number(v2, key // '(2)', x(2), msg)
        else
            msg = 'missing ' // key
        end if
    end subroutine pair_values

    subroutine required(kv, key, x, msg)
        type(kv_list), intent(inout) :: kv
        character(len=*), intent(in) :: key
        real(wp), intent(out) :: x
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: v
        x = 0.0_wp
        if (len(msg) > 0) return
        if (.not. take(kv, key, v)) then
            msg = 'missing ' // key
            return
        end if
        call number(v, key, x, msg)
    end subroutine required

    subroutine on_off(v, key, flag, msg)
        character(len=*), intent(in) :: v, key
        logical, intent(out) :: flag
        character(len=:), allocatable, intent(inout) :: msg
        flag = v == 'on'
        if (v /= 'on' .and. v /= 'off' .and. len(msg) == 0) msg = key // ' = ' // v // ': on or off'
    end subroutine on_off

    !> Comma-separated numbers (1 to 3 of them).
    subroutine values(text, what, x, n, msg)
        character(len=*), intent(in) :: text, what
        real(wp), intent(out) :: x(3)
        integer, intent(out) :: n
        character(len=:), allocatable, intent(inout) :: msg
        integer :: i, j
        x = 0.0_wp
        n = 0
        j = 1
        do i = 1, len(text) + 1
            if (i <= len(text)) then
                if (text(i:i) /= ',') cycle
            end if
            n = n + 1
            if (n > 3) then
                msg = what // ': too many values in "' // text // '"'
                return
            end if
            call number(text(j:i - 1), what, x(n), msg)
            if (len(msg) > 0) return
            j = i + 1
        end do
    end subroutine values

    !> A strict decimal number ([sign] digits [. digits] [e|E [sign] digits]), finite.
    subroutine number(text, what, x, msg)
        character(len=*), intent(in) :: text, what
        real(wp), intent(out) :: x
        character(len=:), allocatable, intent(inout) :: msg
        integer :: i, n, nd, ios
        logical :: ok
        x = 0.0_wp
        if (len(msg) > 0) return
        n = len(text)
        i = 1
        nd = 0
        ok = n > 0
        if (ok) then
            if (text(1:1) == '+' .or. text(1:1) == '-') i = 2
            call digits()
            if (i <= n) then
                if (text(i:i) == '.') then
                    i = i + 1
                    call digits()
                end if
            end if
            ok = nd > 0
            if (ok .and. i <= n) then
                if (text(i:i) == 'e' .or. text(i:i) == 'E') then
                    i = i + 1
                    if (i <= n) then
                        if (text(i:i) == '+' .or. text(i:i) == '-') i = i + 1
                    end if
                    nd = 0
                    call digits()
                    ok = nd > 0
                end if
            end if
            ok = ok .and. i > n
        end if
        if (ok) then
            read (text, *, iostat=ios) x
            ok = ios == 0 .and. ieee_is_finite(x)
        end if
        if (.not. ok) then
            x = 0.0_wp
            msg = 'malformed number "' // text // '" for ' // what
        end if
    contains
        subroutine digits()
            do while (i <= n)
                if (text(i:i) < '0' .or. text(i:i) > '9') exit
                i = i + 1
                nd = nd + 1
            end do
        end subroutine digits
    end subroutine number

    !> Split key=value tokens (MFiX: keys upper-cased, as its namelist is case-insensitive).
    subroutine split_pairs(tok, to_upper, kv, msg)
        type(peer_text), intent(in) :: tok(:)
        logical, intent(in) :: to_upper
        type(kv_list), intent(out) :: kv
        character(len=:), allocatable, intent(inout) :: msg
        integer :: i, j, k
        character(len=:), allocatable :: key
        allocate (kv%key(size(tok)), kv%val(size(tok)), kv%used(size(tok)))
        kv%used = .false.
        do i = 1, size(tok)
            j = index(tok(i)%s, '=')
            if (j <= 1) then
                msg = 'expected key=value, got "' // tok(i)%s // '"'
                return
            end if
            key = trim(adjustl(tok(i)%s(1:j - 1)))
            if (to_upper) key = upper(key)
            do k = 1, i - 1
                if (kv%key(k)%s == key) then
                    msg = 'key ' // key // ' given more than once'
                    return
                end if
            end do
            kv%key(i)%s = key
            kv%val(i)%s = trim(adjustl(tok(i)%s(j + 1:)))
            if (len(kv%val(i)%s) == 0) then
                msg = 'key ' // key // ' has no value'
                return
            end if
        end do
    end subroutine split_pairs

    !> The value of a key (and mark it used); false if absent.
    logical function take(kv, key, val)
        type(kv_list), intent(inout) :: kv
        character(len=*), intent(in) :: key
        character(len=:), allocatable, intent(out) :: val
        integer :: i
        take = .false.
        val = ''
        do i = 1, size(kv%key)
            if (kv%key(i)%s == key) then
                take = .true.
                kv%used(i) = .true.
                val = kv%val(i)%s
            end if
        end do
    end function take

    pure logical function has(kv, key)
        type(kv_list), intent(in) :: kv
        character(len=*), intent(in) :: key
        integer :: i
        has = .false.
        do i = 1, size(kv%key)
            if (kv%key(i)%s == key) has = .true.
        end do
    end function has

    subroutine check_all_used(kv, peer, msg)
        type(kv_list), intent(in) :: kv
        integer, intent(in) :: peer
        character(len=:), allocatable, intent(inout) :: msg
        integer :: i
        do i = 1, size(kv%key)
            if (.not. kv%used(i)) then
                if (index(' ' // peer_known_keys(peer) // ' ', ' ' // base_key(kv%key(i)%s) // ' ') > 0) then
                    msg = 'key ' // kv%key(i)%s // ' does not apply to this ' // peer_name(peer, title=.true.) // ' deck'
                else
                    msg = 'unknown key ' // kv%key(i)%s // ' for ' // peer_name(peer, title=.true.) // ' (known: ' // &
                          peer_known_keys(peer) // ')'
                end if
                return
            end if
        end do
    end subroutine check_all_used

    pure function base_key(key) result(b)
        character(len=*), intent(in) :: key
        character(len=:), allocatable :: b
        integer :: j
        j = index(key, '(')
        if (j > 1) then
            b = key(1:j - 1)
        else
            b = key
        end if
    end function base_key

    subroutine add_note(deck, text)
        type(peer_deck), intent(inout) :: deck
        character(len=*), intent(in) :: text
        deck%notes = [deck%notes, peer_text(text)]
    end subroutine add_note

    pure function join(t) result(s)
        type(peer_text), intent(in) :: t(:)
        character(len=:), allocatable :: s
        integer :: i
        s = ''
        do i = 1, size(t)
            if (i > 1) s = s // ' '
            s = s // t(i)%s
        end do
    end function join

    pure function unquote(s) result(r)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: r
        r = s
        if (len(r) >= 2) then
            if ((r(1:1) == '''' .and. r(len(r):len(r)) == '''') .or. (r(1:1) == '"' .and. r(len(r):len(r)) == '"')) then
                r = r(2:len(r) - 1)
            end if
        end if
    end function unquote

end module hertzdamp_peers_deck
