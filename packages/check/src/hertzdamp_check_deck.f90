!> Reading one peer engine's contact, in the engine's own keywords, into a resolved
!> `peer_deck` (hertzdamp_check_model): which specification row applies, the damping
!> parameter, the effective mass and radius, and the Hertz stiffness k as the engine
!> builds it (doc/peers.md, sections 1-6).  The engine's reader (hertzdamp_check_engines:
!> hertzdamp_check_lammps, _liggghts, _mercury, _yade, _mfix, _chrono) reads its words;
!> this module checks what they have in common.
!>
!> Input: the engine, its parameters as words, the bodies' radii and densities, and the
!> release (LAMMPS_* for lammps, YADE_* for yade).
!> - lammps: the arguments of `pair_coeff I J ...` for `pair_style granular`, a
!>   `fix ID group wall/gran granular ...` (body 2 a flat wall), or the classic
!>   `gran/hertz/history` settings;
!> - the others: `key=value` words with the engine's own names (lists `v1,v2` for
!>   per-body values; the keys of each engine are in its table row).
!> Errors give a one-line message naming the key or word; nothing is printed.
module hertzdamp_check_deck
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_BAD_ARGUMENT
    use hertzdamp_check_model, only: peer_deck, peer_row_law, peer_row_end, peer_row_coef, PEER_LIGGGHTS, &
                                     PEER_MERCURYDPM, COEF_GAMMA_SQRT5_BETA, COEF_GAMMA_SQRT6_THORNTON, COEF_D_YADE_VN
    use hertzdamp_check_common, only: peer_materials
    use hertzdamp_check_engines, only: check_engine, check_engine_of
    use hertzdamp_check_lammps, only: LAMMPS_2021, LAMMPS_2023, LAMMPS_CURRENT
    use hertzdamp_check_yade, only: YADE_2022, YADE_2023, YADE_CURRENT
    use hertzdamp_text_list, only: text_string
    use hertzdamp_text_format, only: fmt_short, ROUND_TRIP
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    public :: peer_materials
    public :: LAMMPS_2021, LAMMPS_2023, LAMMPS_CURRENT
    public :: YADE_2022, YADE_2023, YADE_CURRENT
    public :: peer_read_deck, peer_parameter_problem

contains

    !> Read a contact.  On failure status = HD_BAD_ARGUMENT and message names the key.
    subroutine peer_read_deck(peer, tokens, mat, release, deck, status, message)
        integer, intent(in) :: peer                     !! PEER_*
        type(text_string), intent(in) :: tokens(:)      !! the engine's parameters
        type(peer_materials), intent(in) :: mat         !! radii and densities (or peer keys give them)
        integer, intent(in) :: release                  !! LAMMPS_* (lammps) or YADE_* (yade); else unused
        type(peer_deck), intent(out) :: deck
        integer, intent(out) :: status                  !! HD_OK or HD_BAD_ARGUMENT
        character(len=:), allocatable, intent(out) :: message
        type(check_engine) :: e
        message = ''
        deck%peer = peer
        deck%release = release
        deck%version = ''
        deck%deck_text = ''
        deck%k_text = ''
        deck%p_name = ''
        deck%p_template = ''
        allocate (deck%notes(0))
        deck%wall = mat%wall
        e = check_engine_of(peer)
        call e%read_contact(tokens, mat, deck, message)
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

end module hertzdamp_check_deck
