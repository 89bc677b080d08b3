!> One LAMMPS granular contact, in LAMMPS's own words, resolved to the model
!> (doc/peers.md section 1):
!> - the arguments of `pair_coeff I J ...` for `pair_style granular` (a leading
!>   `pair_coeff I J` is skipped), e.g. `hertz/material 1e8 0.5 0.3 damping tsuji`;
!> - a `fix ID group wall/gran granular ... xplane|yplane|zplane lo hi` (or
!>   `wall/gran/region granular ... region ID`): body 2 is a flat wall;
!> - the classic style `gran/hertz/history Kn Kt gamma_n gamma_t xmu dampflag
!>   [limit_damping]` (the `pair_style` arguments), and its `fix wall/gran hertz/history`.
!> Errors name the keyword; nothing prints.
module hertzdamp_check_lammps
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_check_model, only: peer_deck, peer_spec_row
    use hertzdamp_check_common, only: peer_materials, bodies, end_word, hertz_k, check_modulus, check_poisson, &
                                      number, add_note
    use hertzdamp_text_list, only: text_string, text_join
    use hertzdamp_text_format, only: itoa, fmt_short, ROUND_TRIP
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> LAMMPS releases whose formulas differ (doc/peers.md section 1).
    integer, parameter, public :: LAMMPS_2021 = 1     !! 29 Sep 2021 update 2 (Debian 12)
    integer, parameter, public :: LAMMPS_2023 = 2     !! 28 Mar 2023 (granular refactor) .. at least 29 Aug 2024
    integer, parameter, public :: LAMMPS_CURRENT = 3  !! lammps/lammps 07b704ca (tsuji with sqrt(2))
    character(len=*), parameter, public :: lammps_releases = '2021 2023 current'
    !> The keywords of a granular pair_coeff (for messages).
    character(len=*), parameter, public :: lammps_keys = &
        'hertz hertz/material damping tangential rolling twisting heat cutoff limit_damping'
    !> The words a contact in LAMMPS's words starts with: the commands and styles `head`
    !> reads, and the keywords of the granular model and of a wall fix.
    character(len=*), parameter, public :: lammps_starts = 'pair_coeff pair_style fix gran/hertz/history ' // &
        'gran/hooke/history gran/hooke hooke dmt jkr mdr xplane yplane zplane region zcylinder ' // lammps_keys

    !> A contact's words as read, before the release picks the formulas.
    type :: lammps_args
        character(len=:), allocatable :: normal        !! hertz, hertz/material, or hertz/history (classic)
        character(len=:), allocatable :: normal_text   !! the normal model's words
        character(len=:), allocatable :: template      !! the damping input with {} for the value
        character(len=:), allocatable :: damping       !! damping model (default viscoelastic)
        character(len=:), allocatable :: wall_text     !! the wall's words (fix)
        real(wp) :: kn = 0.0_wp, c = 0.0_wp, ymod = 0.0_wp, nu = 0.0_wp
        real(wp) :: kt_mindlin = 0.0_wp  !! tangential mindlin*: its kt when given as a number (0: NULL or none)
        logical :: limit = .false.       !! limit_damping
        logical :: is_fix = .false.      !! fix wall/gran
        logical :: after_wall = .false.  !! the wall style has been read
    end type lammps_args

    public :: read_lammps

contains

    !> Read a LAMMPS contact (see the module) with the formulas of the release deck%release.
    !> On failure msg names the keyword.
    subroutine read_lammps(tok, mat, deck, msg)
        type(text_string), intent(in) :: tok(:)           !! the contact's words
        type(peer_materials), intent(in) :: mat         !! radii and densities (a wall: mat%wall)
        type(peer_deck), intent(inout) :: deck          !! deck%release: LAMMPS_*
        character(len=:), allocatable, intent(inout) :: msg
        type(lammps_args) :: a
        integer :: i
        a%normal = ''
        a%normal_text = ''
        a%template = ''
        a%damping = 'viscoelastic'
        a%wall_text = ''
        if (size(tok) == 0) then
            msg = 'no pair_coeff arguments given (e.g. hertz/material 1e8 0.5 0.3 damping tsuji)'
            return
        end if
        call head(tok, a, i, msg)
        do while (i <= size(tok) .and. len(msg) == 0)
            if (a%after_wall) then
                call wall_keyword(tok, i, msg)
            else
                call keyword(tok, i, a, msg)
            end if
        end do
        if (len(msg) > 0) return
        if (len(a%normal) == 0) then
            msg = 'missing normal model: hertz kn eta_n0, or hertz/material E eta_n0 nu'
        else if (a%is_fix .and. .not. a%after_wall) then
            msg = 'fix wall/gran: missing wall style (xplane, yplane, zplane or region)'
        end if
        if (len(msg) > 0) return
        if (a%is_fix) deck%wall = .true.
        call resolve(a, mat, deck%release, deck, msg)
    end subroutine read_lammps

    !> The leading words: `pair_coeff I J`, `fix ID group wall/gran[/region] STYLE`, or
    !> the classic `gran/hertz/history` settings; i = the first word after them.
    subroutine head(tok, a, i, msg)
        type(text_string), intent(in) :: tok(:)
        type(lammps_args), intent(inout) :: a
        integer, intent(out) :: i
        character(len=:), allocatable, intent(inout) :: msg
        integer :: n
        n = size(tok)
        i = 1
        select case (tok(1)%s)
        case ('pair_coeff')
            if (n < 3) msg = 'pair_coeff needs the two atom types before the model'
            i = 4
        case ('pair_style')
            msg = 'give the arguments of pair_coeff (pair_style granular takes only a cutoff)'
        case ('gran/hertz/history')
            call classic(tok, 2, a, i, msg)
        case ('gran/hooke/history', 'gran/hooke')
            msg = 'pair_style ' // tok(1)%s // ' is a linear spring; hertzdamp checks Hertz contacts ' // &
                  '(granular hertz, hertz/material; gran/hertz/history)'
        case ('fix')
            if (n < 5) then
                msg = 'fix: expected "fix ID group wall/gran granular ..."'
            else if (tok(4)%s /= 'wall/gran' .and. tok(4)%s /= 'wall/gran/region') then
                msg = 'fix style "' // tok(4)%s // '": only fix wall/gran and wall/gran/region are checked'
            else
                a%is_fix = .true.
                select case (tok(5)%s)
                case ('granular')
                    i = 6
                case ('hertz/history')
                    call classic(tok, 6, a, i, msg)
                case ('hooke', 'hooke/history')
                    msg = 'fix ' // tok(4)%s // ' ' // tok(5)%s // ' is a linear spring; hertzdamp checks Hertz contacts'
                case default
                    msg = 'fix ' // tok(4)%s // ' ' // tok(5)%s // ': checked are the styles granular and hertz/history'
                end select
            end if
        case default
        end select
    end subroutine head

    !> The classic Hertz settings Kn Kt gamma_n gamma_t xmu dampflag [limit_damping]
    !> (pair_gran_hertz_history.cpp, settings): F = sqrt(R delta) (Kn delta - m gamma_n v_n).
    subroutine classic(tok, i0, a, i, msg)
        type(text_string), intent(in) :: tok(:)
        integer, intent(in) :: i0
        type(lammps_args), intent(inout) :: a
        integer, intent(out) :: i
        character(len=:), allocatable, intent(inout) :: msg
        real(wp) :: x
        integer :: j
        i = i0 + 6
        if (size(tok) < i0 + 5) then
            msg = 'gran/hertz/history needs Kn Kt gamma_n gamma_t xmu dampflag'
            return
        end if
        call number(tok(i0)%s, 'gran/hertz/history Kn', a%kn, msg)
        call number(tok(i0 + 2)%s, 'gran/hertz/history gamma_n', a%c, msg)
        do j = 1, 5, 2
            if (tok(i0 + j)%s /= 'NULL') call number(tok(i0 + j)%s, 'gran/hertz/history ' // &
                                                     trim(merge('Kt     ', 'gamma_t', j == 1)), x, msg)
        end do
        call number(tok(i0 + 4)%s, 'gran/hertz/history xmu', x, msg)
        if (len(msg) > 0) return
        if (.not. a%kn > 0.0_wp) msg = 'gran/hertz/history Kn = ' // tok(i0)%s // ' must be positive'
        if (.not. a%c >= 0.0_wp) msg = 'gran/hertz/history gamma_n = ' // tok(i0 + 2)%s // ' must be >= 0'
        if (tok(i0 + 5)%s /= '0' .and. tok(i0 + 5)%s /= '1') msg = 'gran/hertz/history dampflag must be 0 or 1'
        a%normal = 'hertz/history'
        a%damping = 'hertz/history'
        a%normal_text = 'gran/hertz/history ' // text_join(tok(i0:i0 + 5))
        a%template = 'gran/hertz/history ' // tok(i0)%s // ' ' // tok(i0 + 1)%s // ' {} ' // text_join(tok(i0 + 3:i0 + 5))
        if (size(tok) >= i) then
            if (tok(i)%s == 'limit_damping') then
                a%limit = .true.
                i = i + 1
            end if
        end if
    end subroutine classic

    !> One keyword of the granular model (or the wall style of a fix) at tok(i).
    subroutine keyword(tok, i, a, msg)
        type(text_string), intent(in) :: tok(:)
        integer, intent(inout) :: i
        type(lammps_args), intent(inout) :: a
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: t
        real(wp) :: x
        integer :: n, na
        n = size(tok)
        t = tok(i)%s
        select case (t)
        case ('hertz', 'hertz/material')
            call normal_model(tok, i, a, msg)
        case ('hooke')
            msg = 'normal model hooke is a linear spring; hertzdamp checks Hertz contacts (hertz, hertz/material)'
        case ('dmt', 'jkr')
            msg = 'normal model ' // t // ' is cohesive; hertzdamp checks non-cohesive Hertz contacts ' // &
                  '(hertz, hertz/material)'
        case ('mdr')
            msg = 'normal model mdr is not a Hertz contact; hertzdamp checks hertz and hertz/material'
        case ('damping')
            call damping_model(tok, i, a, msg)
        case ('tangential', 'rolling', 'twisting', 'heat')
            if (i + 1 > n) then
                msg = t // ' needs a model name'
                return
            end if
            na = submodel_args(t, tok(i + 1)%s)
            if (na < 0) then
                msg = 'unknown ' // t // ' model "' // tok(i + 1)%s // '"'
            else if (i + 1 + na > n) then
                msg = t // ' ' // tok(i + 1)%s // ' needs ' // itoa(na) // ' values'
            else
                call check_values(tok(i + 2:i + 1 + na), t // ' ' // tok(i + 1)%s, msg)
                ! (nested: Fortran's .and. does not stop at a false operand, and tok(i + 2)
                ! need not exist)
                if (len(msg) == 0 .and. na > 0 .and. t == 'tangential' .and. index(tok(i + 1)%s, 'mindlin') == 1) then
                    if (tok(i + 2)%s /= 'NULL') call number(tok(i + 2)%s, 'tangential kt', a%kt_mindlin, msg)
                end if
            end if
            i = i + 2 + na
        case ('cutoff')
            if (i + 1 > n) then
                msg = 'cutoff needs a value'
                return
            end if
            call number(tok(i + 1)%s, 'cutoff', x, msg)
            i = i + 2
        case ('limit_damping')
            a%limit = .true.
            i = i + 1
        case ('xplane', 'yplane', 'zplane', 'region')
            call wall_style(tok, i, a, msg)
        case ('zcylinder')
            msg = 'wall style ' // t // ': only flat walls (xplane, yplane, zplane) and regions are checked'
        case default
            msg = 'unknown pair_coeff keyword "' // t // '" (known: ' // lammps_keys // ')'
        end select
    end subroutine keyword

    !> hertz kn eta_n0 | hertz/material E eta_n0 nu.
    subroutine normal_model(tok, i, a, msg)
        type(text_string), intent(in) :: tok(:)
        integer, intent(inout) :: i
        type(lammps_args), intent(inout) :: a
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: t
        integer :: na
        t = tok(i)%s
        if (len(a%normal) > 0) then
            msg = 'normal model given twice (' // a%normal // ' and ' // t // ')'
            return
        end if
        a%normal = t
        na = merge(2, 3, t == 'hertz')
        if (i + na > size(tok)) then
            msg = t // ' needs ' // itoa(na) // ' values (' // trim(merge('kn eta_n0  ', 'E eta_n0 nu', t == 'hertz')) // ')'
            return
        end if
        a%normal_text = text_join(tok(i:i + na))
        a%template = tok(i)%s // ' ' // tok(i + 1)%s // ' {}'
        if (na == 3) a%template = a%template // ' ' // tok(i + 3)%s
        if (t == 'hertz') then
            call number(tok(i + 1)%s, 'hertz kn', a%kn, msg)
            call number(tok(i + 2)%s, 'hertz damping coefficient', a%c, msg)
            if (len(msg) == 0 .and. .not. a%kn > 0.0_wp) msg = 'hertz kn = ' // tok(i + 1)%s // ' must be positive'
        else
            call number(tok(i + 1)%s, 'hertz/material E', a%ymod, msg)
            call number(tok(i + 2)%s, 'hertz/material damping coefficient', a%c, msg)
            call number(tok(i + 3)%s, 'hertz/material nu', a%nu, msg)
            call check_modulus(a%ymod, 'hertz/material E', tok(i + 1)%s, msg)
            call check_poisson(a%nu, 'hertz/material nu', tok(i + 3)%s, msg)
        end if
        i = i + na + 1
    end subroutine normal_model

    subroutine damping_model(tok, i, a, msg)
        type(text_string), intent(in) :: tok(:)
        integer, intent(inout) :: i
        type(lammps_args), intent(inout) :: a
        character(len=:), allocatable, intent(inout) :: msg
        if (i + 1 > size(tok)) then
            msg = 'damping needs a model name'
            return
        end if
        a%damping = tok(i + 1)%s
        select case (a%damping)
        case ('velocity', 'mass_velocity', 'viscoelastic', 'tsuji', 'coeff_restitution')
        case ('none')
            msg = 'damping none: the contact is elastic (e = 1), nothing to check'
        case default
            msg = 'unknown damping model "' // a%damping // &
                  '" (velocity, mass_velocity, viscoelastic, tsuji, coeff_restitution)'
        end select
        i = i + 2
    end subroutine damping_model

    !> xplane|yplane|zplane lo hi, or region ID (a fix only).
    subroutine wall_style(tok, i, a, msg)
        type(text_string), intent(in) :: tok(:)
        integer, intent(inout) :: i
        type(lammps_args), intent(inout) :: a
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: t
        integer :: na
        t = tok(i)%s
        if (.not. a%is_fix) then
            msg = 'wall style ' // t // ' belongs to fix wall/gran; use --wall or give the fix line'
            return
        end if
        na = merge(1, 2, t == 'region')
        if (i + na > size(tok)) then
            msg = t // ' needs ' // trim(merge('a region ID', 'lo and hi  ', t == 'region'))
            return
        end if
        if (t /= 'region') call check_values(tok(i + 1:i + 2), t, msg)
        a%wall_text = text_join(tok(i:i + na))
        a%after_wall = .true.
        i = i + na + 1
    end subroutine wall_style

    !> fix wall/gran keywords after the wall style.
    subroutine wall_keyword(tok, i, msg)
        type(text_string), intent(in) :: tok(:)
        integer, intent(inout) :: i
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: t
        integer :: na
        t = tok(i)%s
        select case (t)
        case ('wiggle'); na = 3
        case ('shear'); na = 2
        case ('contacts'); na = 0
        case ('temperature'); na = 1
        case default
            msg = 'unknown fix wall/gran keyword "' // t // '"'
            return
        end select
        if (i + na > size(tok)) msg = 'fix wall/gran ' // t // ' needs ' // itoa(na) // ' values'
        i = i + na + 1
    end subroutine wall_keyword

    !> The release picks the formulas: the specification row, k and the notes.
    subroutine resolve(a, mat, release, deck, msg)
        type(lammps_args), intent(in) :: a
        type(peer_materials), intent(in) :: mat
        integer, intent(in) :: release
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: rel
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
        call damping_parameter(a, release, rel, deck, msg)
        if (len(msg) > 0) return
        call bodies(mat, deck, msg)
        if (len(msg) > 0) return
        call stiffness(a, release, deck)
        call tangential_note(a, deck)
        deck%deck_text = a%normal_text
        if (a%normal /= 'hertz/history') deck%deck_text = deck%deck_text // ' damping ' // a%damping
        if (a%limit) deck%deck_text = deck%deck_text // ' limit_damping'
        if (deck%wall .and. a%normal == 'hertz/history') then
            deck%deck_text = 'fix wall/gran hertz/history' // deck%deck_text(len('gran/hertz/history') + 1:) // &
                             ' (flat wall)'
        else if (deck%wall) then
            deck%deck_text = 'fix wall/gran granular ' // deck%deck_text // ' (flat wall)'
        end if
        if (index(a%wall_text, 'region') == 1) call add_note(deck, 'fix wall/gran/region: the region''s surface ' // &
            'is checked as a flat wall (R = the particle radius); a curved region changes R')
        call add_note(deck, 'LAMMPS damps with the half-step velocity (fix nve/sphere), an error of first ' // &
                      'order in the time step on top of what is shown here')
    end subroutine resolve

    !> The damping parameter, its checks and the specification row.
    subroutine damping_parameter(a, release, rel0, deck, msg)
        type(lammps_args), intent(in) :: a
        integer, intent(in) :: release
        character(len=*), intent(in) :: rel0
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: rel, name
        rel = rel0
        name = a%normal
        if (a%damping == 'coeff_restitution' .and. release == LAMMPS_2021) then
            msg = 'damping coeff_restitution does not exist in LAMMPS 29 Sep 2021 (added in 27 Jun 2024); ' // &
                  'choose --release 2023 or current'
        else if (a%damping == 'tsuji' .or. a%damping == 'coeff_restitution') then
            if (.not. (a%c >= 0.0_wp .and. a%c <= 1.0_wp)) then
                msg = name // ' damping coefficient ' // fmt_short(a%c, ROUND_TRIP) // ': with damping ' // a%damping // &
                      ' it is the restitution coefficient e, 0 <= e <= 1'
            else if (a%damping == 'coeff_restitution' .and. a%c <= 0.0_wp) then
                msg = name // ' damping coefficient 0 with damping coeff_restitution: LAMMPS takes ln(0) ' // &
                      '(not guarded), the damping is NaN'
            end if
            deck%e_deck = a%c
            deck%p_name = name // ' damping coefficient (e of damping ' // a%damping // ')'
            if (a%damping == 'coeff_restitution') rel = '2024'
        else if (a%normal == 'hertz/history') then
            deck%p_name = 'gran/hertz/history gamma_n'
            rel = 'hertz_history'
        else
            if (.not. a%c >= 0.0_wp) msg = name // ' damping coefficient eta_n0 = ' // fmt_short(a%c, ROUND_TRIP) // &
                                           ' must be >= 0'
            deck%p_name = name // ' damping coefficient eta_n0 (damping ' // a%damping // ')'
            if (release /= LAMMPS_2021) rel = '2023'
        end if
        if (len(msg) > 0) return
        deck%p = a%c
        deck%p_template = a%template
        if (a%normal /= 'hertz/history') deck%p_template = deck%p_template // ' damping ' // a%damping
        if (a%limit) deck%p_template = deck%p_template // ' limit_damping'
        if (rel == 'hertz_history') then
            deck%row = peer_spec_row('lammps-hertz_history-' // end_word(a%limit))
        else
            deck%row = peer_spec_row('lammps-' // rel // '-' // a%damping // '-' // end_word(a%limit))
        end if
    end subroutine damping_parameter

    !> A warning when mindlin's kt is far stiffer than any material gives for the normal
    !> stiffness (a physical k_t kept with a softened normal contact, issue 33): mindlin's
    !> F_t = kt a xi with kt = 8 G*, against the normal kn = k / sqrt(R*) (hertz kn, or
    !> (4/3) E* for hertz/material); 8 G* / ((4/3) E*) = 3 (1 - nu)/(2 - nu) is 1 to 2 for
    !> every isotropic material (-1 < nu <= 0.5, and any two materials lie in between).
    !> mindlin NULL takes G* from the deck's own E and nu, which scales with them.
    subroutine tangential_note(a, deck)
        type(lammps_args), intent(in) :: a
        type(peer_deck), intent(inout) :: deck
        real(wp) :: kn, ratio
        if (.not. (a%kt_mindlin > 0.0_wp) .or. .not. (deck%k > 0.0_wp .and. deck%radius > 0.0_wp)) return
        kn = deck%k / sqrt(deck%radius)
        ratio = a%kt_mindlin / kn
        if (ratio > 2.0_wp) call add_note(deck, 'warning: tangential mindlin kt = ' // fmt_short(a%kt_mindlin) // &
            ' is ' // fmt_short(ratio) // ' times the normal kn = ' // fmt_short(kn) // ', where any material ' // &
            'gives 1 to 2 (8 G*/((4/3) E*) = 3(1-nu)/(2-nu)): a physical k_t kept with a softened normal ' // &
            'contact; a softened contact needs k_t scaled by k/k_phys (doc/oblique.md; the hertzdamp LAMMPS ' // &
            'plugin scales it: tangential_stiffness adapted)')
    end subroutine tangential_note

    !> k as the release builds it (the 2021 wall's 1 - nu).
    subroutine stiffness(a, release, deck)
        type(lammps_args), intent(in) :: a
        integer, intent(in) :: release
        type(peer_deck), intent(inout) :: deck
        if (a%normal == 'hertz') then
            deck%k = a%kn * sqrt(deck%radius)
            deck%k_text = 'k = kn sqrt(R) (normal hertz)'
        else if (a%normal == 'hertz/history') then
            deck%k = a%kn * sqrt(deck%radius)
            deck%k_text = 'k = Kn sqrt(R) (gran/hertz/history, Kn/nktv2p with nktv2p = 1 in si, cgs and lj units)'
        else if (deck%wall .and. release == LAMMPS_2021) then
            deck%e_star = a%ymod / (2.0_wp * (1.0_wp - a%nu))
            deck%k = hertz_k(deck%e_star, deck%radius)
            deck%k_text = 'k = (4/3) E/(2(1-nu)) sqrt(R) (fix wall/gran hertz/material, LAMMPS 2021: 1-nu, not 1-nu^2)'
            call add_note(deck, 'LAMMPS 29 Sep 2021 fix wall/gran builds the hertz/material stiffness with 1-nu ' // &
                          'instead of 1-nu^2 (fix_wall_gran.cpp:160,171,183): k is 1+nu times the pair formula; ' // &
                          'the 2023 refactor removed this')
        else
            deck%e_star = a%ymod / (2.0_wp * (1.0_wp - a%nu) * (1.0_wp + a%nu))
            deck%k = hertz_k(deck%e_star, deck%radius)
            deck%k_text = 'k = (4/3) E/(2(1-nu^2)) sqrt(R) (hertz/material, one material on both sides)'
        end if
    end subroutine stiffness

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
        type(text_string), intent(in) :: vals(:)
        character(len=*), intent(in) :: what
        character(len=:), allocatable, intent(inout) :: msg
        integer :: j
        real(wp) :: x
        do j = 1, size(vals)
            if (vals(j)%s == 'NULL') cycle
            call number(vals(j)%s, what, x, msg)
        end do
    end subroutine check_values

end module hertzdamp_check_lammps
