!> Reading one peer engine's contact, in the engine's own keywords, into a resolved
!> `peer_deck` (hertzdamp_peers): which specification row applies, the damping
!> parameter, the effective mass and radius, and the Hertz stiffness k as the engine
!> builds it (doc/peers.md, sections 1-6).  One module per engine reads its words
!> (hertzdamp_peers_lammps, _liggghts, _mercury, _yade, _mfix, _chrono); this one picks
!> the engine and checks what they have in common.
!>
!> Input: the engine, its parameters as words, the bodies' radii and densities, and the
!> release (LAMMPS_* for lammps, YADE_* for yade).
!> - lammps: the arguments of `pair_coeff I J ...` for `pair_style granular`, a
!>   `fix ID group wall/gran granular ...` (body 2 a flat wall), or the classic
!>   `gran/hertz/history` settings;
!> - the others: `key=value` words with the engine's own names (lists `v1,v2` for
!>   per-body values; see `peer_known_keys`).
!> Errors give a one-line message naming the key or word; nothing is printed.
module hertzdamp_peers_deck
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_BAD_ARGUMENT
    use hertzdamp_peers, only: peer_deck, peer_text, peer_row_law, peer_row_end, peer_row_coef, &
                               PEER_LAMMPS, PEER_LIGGGHTS, PEER_MERCURYDPM, PEER_YADE, PEER_MFIX, PEER_CHRONO, &
                               peer_name, COEF_GAMMA_SQRT5_BETA, COEF_GAMMA_SQRT6_THORNTON, COEF_D_YADE_VN
    use hertzdamp_peers_common, only: peer_materials, kv_list, split_pairs, check_all_used
    use hertzdamp_peers_lammps, only: read_lammps, LAMMPS_2021, LAMMPS_2023, LAMMPS_CURRENT, lammps_releases, lammps_keys
    use hertzdamp_peers_liggghts, only: read_liggghts, liggghts_keys
    use hertzdamp_peers_mercury, only: read_mercury, mercury_keys
    use hertzdamp_peers_yade, only: read_yade, yade_keys, YADE_2022, YADE_2023, YADE_CURRENT, yade_releases
    use hertzdamp_peers_mfix, only: read_mfix, mfix_keys
    use hertzdamp_peers_chrono, only: read_chrono, chrono_keys
    use hertzdamp_apps_text, only: lower, fmt_short, ROUND_TRIP
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    public :: peer_materials
    public :: LAMMPS_2021, LAMMPS_2023, LAMMPS_CURRENT, lammps_releases
    public :: YADE_2022, YADE_2023, YADE_CURRENT, yade_releases
    public :: peer_read_deck, peer_code, peer_known_keys, peer_parameter_problem, peer_releases

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

    !> The releases an engine's formulas depend on (the words of --release, oldest
    !> first, the last is the default), '' when they do not.
    pure function peer_releases(peer) result(words)
        integer, intent(in) :: peer   !! PEER_*
        character(len=:), allocatable :: words
        select case (peer)
        case (PEER_LAMMPS); words = lammps_releases
        case (PEER_YADE); words = yade_releases
        case default; words = ''
        end select
    end function peer_releases

    !> The keys an engine accepts, space-separated (lammps: the pair_coeff keywords).
    pure function peer_known_keys(peer) result(keys)
        integer, intent(in) :: peer   !! PEER_*
        character(len=:), allocatable :: keys
        select case (peer)
        case (PEER_LAMMPS); keys = lammps_keys
        case (PEER_LIGGGHTS); keys = liggghts_keys
        case (PEER_MERCURYDPM); keys = mercury_keys
        case (PEER_YADE); keys = yade_keys
        case (PEER_MFIX); keys = mfix_keys
        case (PEER_CHRONO); keys = chrono_keys
        case default; keys = ''
        end select
    end function peer_known_keys

    !> Read a contact.  On failure status = HD_BAD_ARGUMENT and message names the key.
    subroutine peer_read_deck(peer, tokens, mat, release, deck, status, message)
        integer, intent(in) :: peer                     !! PEER_*
        type(peer_text), intent(in) :: tokens(:)        !! the engine's parameters
        type(peer_materials), intent(in) :: mat         !! radii and densities (or peer keys give them)
        integer, intent(in) :: release                  !! LAMMPS_* (lammps) or YADE_* (yade); else unused
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
                case (PEER_YADE); call read_yade(kv, mat, release, deck, message)
                case (PEER_MFIX); call read_mfix(kv, mat, deck, message)
                case (PEER_CHRONO); call read_chrono(kv, mat, deck, message)
                case default; message = 'unknown engine'
                end select
            end if
            if (len(message) == 0) call check_all_used(kv, peer_known_keys(peer), peer_name(peer, title=.true.), message)
        end if
        call finish(deck, message)
        status = merge(HD_OK, HD_BAD_ARGUMENT, len(message) == 0)
    end subroutine peer_read_deck

    !> The row's law, end and formula; the stiffness and mass in range.
    subroutine finish(deck, message)
        type(peer_deck), intent(inout) :: deck
        character(len=:), allocatable, intent(inout) :: message
        if (len(message) > 0) return
        if (deck%row == 0) then
            message = 'internal error: no specification row'
            return
        end if
        deck%law = peer_row_law(deck%row)
        deck%iend = peer_row_end(deck%row)
        deck%coef = peer_row_coef(deck%row)
        if (.not. (deck%k > 0.0_wp .and. ieee_is_finite(deck%k) .and. deck%m > 0.0_wp .and. &
                   ieee_is_finite(deck%m) .and. deck%m_damp > 0.0_wp)) then
            message = 'the stiffness or mass is out of the double-precision range'
        end if
    end subroutine finish

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
        else if (p == 0.0_wp .and. (deck%coef == COEF_GAMMA_SQRT6_THORNTON .or. deck%coef == COEF_D_YADE_VN)) then
            msg = deck%p_name // ' = 0: Yade divides by zero'
        end if
    end function peer_parameter_problem

end module hertzdamp_peers_deck
