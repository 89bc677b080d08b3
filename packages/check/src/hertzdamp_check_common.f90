!> What every engine's contact reader shares: the bodies (radii, densities, a wall), the
!> effective mass and radius and the Hertz stiffness by the library's formulas, checks of
!> moduli and Poisson's ratios, and `key=value` words (the command-line form of the
!> engines' parameters, and what the deck readers hand to the contact readers).
!>
!> Errors are one-line messages ('' when none) naming the key or value; nothing prints.
module hertzdamp_check_common
    use hertzdamp, only: hertzdamp_rk, hertzdamp_message, HD_OK, HD_END_OVERLAP, HD_END_FORCE, hertzdamp_end_name, &
                         hertzdamp_sphere_mass, hertzdamp_effective_mass, hertzdamp_effective_radius, &
                         hertzdamp_effective_modulus, hertzdamp_hertz_stiffness
    use hertzdamp_check_model, only: peer_deck
    use hertzdamp_text_list, only: text_string
    use hertzdamp_text_map, only: text_map
    use hertzdamp_text_parse, only: text_number
    use hertzdamp_text_format, only: upper
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> The bodies: radius and density of body 1 and 2 (<= 0: not given; body 2
    !> defaults to body 1), or a wall as body 2.
    type, public :: peer_materials
        real(wp) :: radius(2) = 0.0_wp    !! [m]
        real(wp) :: density(2) = 0.0_wp   !! [kg m^-3]
        logical :: wall = .false.
    end type peer_materials

    !> key=value pairs of a deck, with a flag for the keys consumed.
    type, public :: kv_list
        type(text_string), allocatable :: key(:), val(:)
        logical, allocatable :: used(:)
        type(text_map) :: map              !! key -> its index
    end type kv_list

    public :: bodies, end_word, effective_modulus, hertz_k, check_modulus, check_poisson
    public :: pair_values, required, on_off, values, number, split_pairs, take, has, check_all_used, base_key
    public :: add_note

contains

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

    !> The contact end of a row id: the library's name of the force end (the total force
    !> clipped, `limit`) or of the overlap end.
    pure function end_word(limit) result(w)
        logical, intent(in) :: limit
        character(len=:), allocatable :: w
        w = hertzdamp_end_name(merge(HD_END_FORCE, HD_END_OVERLAP, limit))
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

    !> msg (when still '') says that a modulus `what` = text is not positive.
    subroutine check_modulus(x, what, text, msg)
        real(wp), intent(in) :: x
        character(len=*), intent(in) :: what, text
        character(len=:), allocatable, intent(inout) :: msg
        if (len(msg) > 0) return
        if (.not. (x > 0.0_wp)) msg = what // ' = ' // text // ': a modulus must be positive'
    end subroutine check_modulus

    !> msg (when still '') says that a Poisson's ratio `what` = text is outside (-1, 0.5].
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
        real(wp), allocatable :: y(:)
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
            call values(v, key, y, msg)
            if (len(msg) > 0) return
            if (size(y) > 2) then
                msg = key // ': at most 2 values (body 1, ' // trim(merge('the wall', 'body 2  ', wall)) // ')'
                return
            end if
            x(1) = y(1)
            x(2) = y(size(y))
        else if (got1) then
            call number(v1, key // '(1)', x(1), msg)
            x(2) = x(1)
            if (got2) call number(v2, key // '(2)', x(2), msg)
        else
            msg = 'missing ' // key
        end if
    end subroutine pair_values

    !> The number of a key that must be given (msg names it when it is missing or malformed).
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

    !> An on|off value of a key (msg names the key for any other).
    subroutine on_off(v, key, flag, msg)
        character(len=*), intent(in) :: v, key
        logical, intent(out) :: flag
        character(len=:), allocatable, intent(inout) :: msg
        flag = v == 'on'
        if (v /= 'on' .and. v /= 'off' .and. len(msg) == 0) msg = key // ' = ' // v // ': on or off'
    end subroutine on_off

    !> Comma-separated numbers (at least one; as many as the text has).
    subroutine values(text, what, x, msg)
        character(len=*), intent(in) :: text, what
        real(wp), allocatable, intent(out) :: x(:)
        character(len=:), allocatable, intent(inout) :: msg
        integer :: i, j, n
        n = 1
        do i = 1, len(text)
            if (text(i:i) == ',') n = n + 1
        end do
        allocate (x(n))
        x = 0.0_wp
        n = 0
        j = 1
        do i = 1, len(text) + 1
            if (i <= len(text)) then
                if (text(i:i) /= ',') cycle
            end if
            n = n + 1
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
        x = 0.0_wp
        if (len(msg) > 0) return
        if (.not. text_number(text, x)) msg = 'malformed number "' // text // '" for ' // what
    end subroutine number

    !> Split key=value words (MFiX: keys upper-cased, as its namelist is case-insensitive);
    !> a key given twice is an error (found through a hash map: linear time).
    subroutine split_pairs(tok, to_upper, kv, msg)
        type(text_string), intent(in) :: tok(:)
        logical, intent(in) :: to_upper
        type(kv_list), intent(out) :: kv
        character(len=:), allocatable, intent(inout) :: msg
        integer :: i, j
        character(len=:), allocatable :: key
        allocate (kv%key(size(tok)), kv%val(size(tok)), kv%used(size(tok)))
        kv%used = .false.
        do i = 1, size(tok)
            kv%key(i)%s = ''
            kv%val(i)%s = ''
        end do
        do i = 1, size(tok)
            j = index(tok(i)%s, '=')
            if (j <= 1) then
                msg = 'expected key=value, got "' // tok(i)%s // '"'
                return
            end if
            key = trim(adjustl(tok(i)%s(1:j - 1)))
            if (to_upper) key = upper(key)
            if (kv%map%get(key) > 0) then
                msg = 'key ' // key // ' given more than once'
                return
            end if
            call kv%map%put(key, i)
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
        val = ''
        i = kv%map%get(key)
        take = i > 0
        if (take) then
            kv%used(i) = .true.
            val = kv%val(i)%s
        end if
    end function take

    !> Whether a key is given (without marking it used).
    pure logical function has(kv, key)
        type(kv_list), intent(in) :: kv
        character(len=*), intent(in) :: key
        has = kv%map%find(key) > 0
    end function has

    !> Every key used; else a message naming the first unused one (`known`: the engine's
    !> keys, space-separated; `engine`: its name as it writes it).
    subroutine check_all_used(kv, known, engine, msg)
        type(kv_list), intent(in) :: kv
        character(len=*), intent(in) :: known, engine
        character(len=:), allocatable, intent(inout) :: msg
        integer :: i
        do i = 1, size(kv%key)
            if (.not. kv%used(i)) then
                if (index(' ' // known // ' ', ' ' // base_key(kv%key(i)%s) // ' ') > 0) then
                    msg = 'key ' // kv%key(i)%s // ' does not apply to this ' // engine // ' deck'
                else
                    msg = 'unknown key ' // kv%key(i)%s // ' for ' // engine // ' (known: ' // known // ')'
                end if
                return
            end if
        end do
    end subroutine check_all_used

    !> A key without its index: KEY(2) -> KEY.
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

    !> Append a remark to the deck's notes.
    subroutine add_note(deck, text)
        type(peer_deck), intent(inout) :: deck
        character(len=*), intent(in) :: text
        deck%notes = [deck%notes, text_string(text)]
    end subroutine add_note

end module hertzdamp_check_common
