!> A whole MFiX deck (mfix.dat or a GUI .mfx file) read into contacts (doc/peers.md
!> sections 5 and 11).  The syntax is MFiX's namelist-like one: `KEY = value`, several
!> assignments on a line, `KEY(i)`, `KEY(i:j)` and `KEY = v1 v2 ...` (indices from 1),
!> `n*value` repeats, quoted strings, `.T.`/`.F.`, `@(expr)` expressions, `!` and `#`
!> comments; keys are case-insensitive.  Read: MMAX, SOLIDS_MODEL, D_P0, RO_S0,
!> DES_COLL_MODEL, E_YOUNG, V_POISSON, EW_YOUNG, VW_POISSON, DES_EN_INPUT (MFiX's pair
!> order 1-1, 1-2, ..., 1-M, 2-2, ...), DES_EN_WALL_INPUT, DES_ET_INPUT, DES_INTG_METHOD,
!> DTSOLID_FACTOR and DT.  Every pair of DEM phases and every DEM phase against the
!> wall is a contact in the words of the MFiX contact reader (hertzdamp_check_mfix); the
!> time step is MFiX's DTSOLID, computed from the contacts (hertzdamp_check_whole).
module hertzdamp_check_mfix_deck
    use hertzdamp, only: hertzdamp_rk, HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2, HD_HOST_NONE
    use hertzdamp_check_model, only: PEER_MFIX
    use hertzdamp_check_scene, only: peer_scene, peer_contact
    use hertzdamp_text_list, only: text_string, text_list
    use hertzdamp_text_map, only: text_map
    use hertzdamp_text_parse, only: text_number, text_find_unquoted
    use hertzdamp_text_expr, only: text_vars
    use hertzdamp_text_namelist, only: text_nml_assignments, text_nml_values
    use hertzdamp_text_file, only: text_read_lines, text_where
    use hertzdamp_text_format, only: upper, itoa, fmt_short
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> The keys read (other DEM keys are noted; the rest are counted).
    character(len=*), parameter :: read_keys = ' MMAX SOLIDS_MODEL D_P0 RO_S0 DES_COLL_MODEL E_YOUNG V_POISSON ' // &
        'EW_YOUNG VW_POISSON DES_EN_INPUT DES_EN_WALL_INPUT DES_ET_INPUT DES_ET_WALL_INPUT DES_INTG_METHOD ' // &
        'DTSOLID_FACTOR DT UNITS DISCRETE_ELEMENT DES_MMAX '

    !> The assignments: "KEY(i)" -> index into val/where.
    type :: mfix_values
        type(text_map) :: index
        type(text_list) :: val, where, keys
        type(text_vars) :: vars       !! for @( ) expressions (none defined: numbers only)
    end type mfix_values

    public :: read_mfix_deck

contains

    !> Read MFiX deck files (in order; a later assignment replaces an earlier one).
    subroutine read_mfix_deck(paths, scene, msg)
        type(text_string), intent(in) :: paths(:)
        type(peer_scene), intent(out) :: scene
        character(len=:), allocatable, intent(out) :: msg
        type(mfix_values) :: mv
        type(text_list) :: lines
        integer :: f, i
        msg = ''
        scene%peer = PEER_MFIX
        scene%units = 'SI'
        scene%dt_text = ''
        do f = 1, size(paths)
            call text_read_lines(paths(f)%s, lines, msg, scene%work)
            if (len(msg) > 0) return
            call scene%files%push(paths(f)%s)
            do i = 1, lines%n
                call parse_line(scene, mv, lines%item(i)%s, text_where(paths(f)%s, i))
            end do
        end do
        scene%work = scene%work + mv%index%probes
        call settings(scene, mv)
        call contacts(scene, mv)
        call unread_keys(scene, mv)
    end subroutine read_mfix_deck

    !> The assignments of one line.
    subroutine parse_line(scene, mv, line0, where)
        type(peer_scene), intent(inout) :: scene
        type(mfix_values), intent(inout) :: mv
        character(len=*), intent(in) :: line0, where
        character(len=:), allocatable :: line
        integer, allocatable :: eq(:), kstart(:)
        integer :: i, n, vend
        line = line0
        i = text_find_unquoted(line, '!#')     ! a comment
        if (i > 0) line = line(1:i - 1)
        if (len_trim(line) == 0) return
        call text_nml_assignments(line, eq, kstart)
        n = size(eq)
        if (n == 0) then
            call scene%note(where, 'not an assignment: "' // trim(adjustl(line)) // '"')
            return
        end if
        if (len_trim(line(1:kstart(1) - 1)) > 0) call scene%note(where, 'text before the first assignment: "' // &
                                                                 trim(adjustl(line(1:kstart(1) - 1))) // '"')
        do i = 1, n
            vend = len(line)
            if (i < n) vend = kstart(i + 1) - 1
            call assign(scene, mv, line(kstart(i):eq(i) - 1), line(eq(i) + 1:vend), where)
        end do
    end subroutine parse_line

    !> KEY[(i[:j])] = values: every value stored under KEY(index).
    subroutine assign(scene, mv, key0, text, where)
        type(peer_scene), intent(inout) :: scene
        type(mfix_values), intent(inout) :: mv
        character(len=*), intent(in) :: key0, text, where
        character(len=:), allocatable :: key, idx
        type(text_list) :: vals, errors
        integer :: p, lo, hi, i
        real(wp) :: x
        key = upper(trim(adjustl(key0)))
        lo = 1
        hi = huge(1)
        p = index(key, '(')
        if (p > 0) then
            idx = key(p + 1:len(key) - 1)
            key = key(1:p - 1)
            if (index(idx, ',') > 0) then
                call remember(mv, key, '', where)   ! a 2-d key (IC_EP_S(1,1) ...): not needed by the checker
                return
            end if
            i = index(idx, ':')
            if (i == 0) i = len(idx) + 1
            if (.not. text_number(idx(1:i - 1), x)) then
                call scene%note(where, key // '(' // idx // '): index not read')
                return
            end if
            lo = nint(x)
            hi = lo
            if (i <= len(idx)) then
                if (.not. text_number(idx(i + 1:), x)) then
                    call scene%note(where, key // '(' // idx // '): index not read')
                    return
                end if
                hi = nint(x)
            end if
        end if
        call text_nml_values(text, mv%vars, vals, errors)
        do i = 1, errors%n
            call scene%note(where, errors%item(i)%s)
        end do
        if (p > 0 .and. vals%n /= hi - lo + 1) call scene%note(where, key // ': ' // itoa(vals%n) // &
            ' values for ' // itoa(hi - lo + 1) // ' indices')
        do i = 1, min(vals%n, hi - lo + 1)
            call remember(mv, key, itoa(lo + i - 1), where, vals%item(i)%s)
        end do
    end subroutine assign

    !> Record KEY(i) = value (value absent: only that the key was seen).
    subroutine remember(mv, key, i, where, value)
        type(mfix_values), intent(inout) :: mv
        character(len=*), intent(in) :: key, i, where
        character(len=*), intent(in), optional :: value
        integer :: k
        if (mv%index%get('#' // key) == 0) then
            call mv%keys%push(key)
            call mv%index%put('#' // key, mv%keys%n)
        end if
        if (.not. present(value)) return
        k = mv%index%get(key // '(' // i // ')')
        if (k == 0) then
            call mv%val%push(value)
            call mv%where%push(where)
            call mv%index%put(key // '(' // i // ')', mv%val%n)
        else
            mv%val%item(k)%s = value
            mv%where%item(k)%s = where
        end if
    end subroutine remember

    !> The value of KEY(i), or with `where` the file:line that set it ('' when absent).
    pure function get(mv, key, i, where) result(v)
        type(mfix_values), intent(in) :: mv
        character(len=*), intent(in) :: key
        integer, intent(in) :: i
        logical, intent(in), optional :: where
        character(len=:), allocatable :: v
        integer :: k
        k = mv%index%find(key // '(' // itoa(i) // ')')
        v = ''
        if (k == 0) return
        v = mv%val%item(k)%s
        if (present(where)) then
            if (where) v = mv%where%item(k)%s
        end if
    end function get

    !> A number of MFiX's (d exponents allowed); `x` unchanged when absent or not a number.
    logical function get_num(mv, key, i, x) result(ok)
        type(mfix_values), intent(in) :: mv
        character(len=*), intent(in) :: key
        integer, intent(in) :: i
        real(wp), intent(inout) :: x
        real(wp) :: y
        ok = text_number(get(mv, key, i), y, fortran_d=.true.)
        if (ok) x = y
    end function get_num

    !> Units, the integrator and the time-step settings.
    subroutine settings(scene, mv)
        type(peer_scene), intent(inout) :: scene
        type(mfix_values), intent(inout) :: mv
        character(len=:), allocatable :: m, where
        real(wp) :: x
        if (len(get(mv, 'UNITS', 1)) > 0) scene%units = upper(get(mv, 'UNITS', 1))
        m = upper(get(mv, 'DES_INTG_METHOD', 1))
        where = get(mv, 'DES_INTG_METHOD', 1, where=.true.)
        select case (m)
        case ('', 'EULER')
            scene%host = HD_HOST_MFIX_EULER
            if (len(m) == 0) where = 'MFiX''s default'
            scene%host_text = 'DES_INTG_METHOD = EULER (' // where // '): v += dt F/m, then x += dt v (cfnewvalues.f)'
        case ('ADAMS_BASHFORTH')
            scene%host = HD_HOST_MFIX_AB2
            scene%host_text = 'DES_INTG_METHOD = ADAMS_BASHFORTH (' // where // '): v += dt (3a - a_old)/2, ' // &
                              'x += dt (v_old + v)/2 (cfnewvalues.f)'
        case default
            scene%host = HD_HOST_NONE
            scene%host_text = 'DES_INTG_METHOD = ' // m // ' (' // where // '): not an MFiX method the checker models'
        end select
        scene%dt_from_tcoll = .true.
        scene%dt_factor = 50.0_wp
        if (get_num(mv, 'DTSOLID_FACTOR', 1, x)) scene%dt_factor = x
        if (get_num(mv, 'DT', 1, x)) scene%dt_max = x
        scene%dt_text = ''
    end subroutine settings

    !> Every pair of DEM phases and every DEM phase against the wall.
    subroutine contacts(scene, mv)
        type(peer_scene), intent(inout) :: scene
        type(mfix_values), intent(inout) :: mv
        integer, allocatable :: dem(:)
        integer :: a, b, lc, mmax
        real(wp) :: x
        character(len=:), allocatable :: model
        mmax = 1
        if (get_num(mv, 'MMAX', 1, x)) mmax = nint(x)
        allocate (dem(0))
        do a = 1, mmax
            if (upper(get(mv, 'SOLIDS_MODEL', a)) == 'DEM' .or. upper(get(mv, 'DISCRETE_ELEMENT', 1)) == '.T.' .or. &
                upper(get(mv, 'DISCRETE_ELEMENT', 1)) == '.TRUE.') dem = [dem, a]
        end do
        if (size(dem) < mmax .and. size(dem) > 0) call scene%note('', 'phases that are not DEM (SOLIDS_MODEL): ' // &
            'MFiX offsets the DEM inputs of hybrid runs (check_solids_dem.f); the phases are read as numbered')
        if (size(dem) == 0) then
            call scene%note('', 'no SOLIDS_MODEL(m) = ''DEM'': no DEM phase to check')
            return
        end if
        model = upper(get(mv, 'DES_COLL_MODEL', 1))
        lc = 0
        do a = 1, mmax
            do b = a, mmax
                lc = lc + 1
                if (any(dem == a) .and. any(dem == b)) call pair(scene, mv, model, a, b, lc)
            end do
        end do
        do a = 1, size(dem)
            call pair(scene, mv, model, dem(a), 0, 0)
        end do
    end subroutine contacts

    !> The contact of phases m and l (l = 0: the wall), DES_EN_INPUT(lc) of the pair.
    subroutine pair(scene, mv, model, m, l, lc)
        type(peer_scene), intent(inout) :: scene
        type(mfix_values), intent(inout) :: mv
        character(len=*), intent(in) :: model
        integer, intent(in) :: m, l, lc
        type(peer_contact) :: c
        type(text_list) :: w
        character(len=:), allocatable :: where
        c%problem = ''
        c%mat%wall = l == 0
        c%pair = itoa(m) // '-' // itoa(l)
        if (l == 0) c%pair = itoa(m) // '-wall'
        call w%push('DES_COLL_MODEL=' // model)
        if (len(model) == 0) c%problem = 'DES_COLL_MODEL is not given: MFiX''s default is LSD, a linear spring'
        if (l == 0) then
            call w%push('E_YOUNG=' // need('E_YOUNG', m))
            call w%push('V_POISSON=' // need('V_POISSON', m))
            call w%push('EW_YOUNG=' // need('EW_YOUNG', 1))
            call w%push('VW_POISSON=' // need('VW_POISSON', 1))
            call w%push('DES_EN_WALL_INPUT=' // need('DES_EN_WALL_INPUT', m))
            where = get(mv, 'DES_EN_WALL_INPUT', m, where=.true.)
        else
            call w%push('E_YOUNG=' // need('E_YOUNG', m) // ',' // need('E_YOUNG', l))
            call w%push('V_POISSON=' // need('V_POISSON', m) // ',' // need('V_POISSON', l))
            call w%push('DES_EN_INPUT=' // need('DES_EN_INPUT', lc))
            where = get(mv, 'DES_EN_INPUT', lc, where=.true.)
            if (len(get(mv, 'DES_ET_INPUT', lc)) == 0) call scene%note(where, 'DES_ET_INPUT(' // itoa(lc) // &
                ') is missing: MFiX''s Hertzian model requires it and stops (check_solids_dem.f)')
        end if
        c%where = where
        if (len(where) == 0) c%where = scene%files%item(1)%s
        c%words = w%items()
        call sizes(mv, m, l, c)
        call scene%add_contact(c)
    contains
        !> KEY(i), or a problem naming it.
        function need(key, i) result(v)
            character(len=*), intent(in) :: key
            integer, intent(in) :: i
            character(len=:), allocatable :: v
            v = get(mv, key, i)
            if (len(v) == 0) then
                v = '0'
                if (len(c%problem) == 0) c%problem = 'missing ' // key // '(' // itoa(i) // ') for the pair ' // &
                                                     c%pair // ' (MFiX stops: check_solids_dem.f)'
            end if
        end function need
    end subroutine pair

    !> D_P0 and RO_S0 of the phases.
    subroutine sizes(mv, m, l, c)
        type(mfix_values), intent(inout) :: mv
        integer, intent(in) :: m, l
        type(peer_contact), intent(inout) :: c
        real(wp) :: d(2), rho(2)
        integer :: j, ph(2)
        ph = [m, l]
        d = 0.0_wp
        rho = 0.0_wp
        c%sizes = ''
        do j = 1, merge(1, 2, l == 0 .or. l == m)
            if (.not. get_num(mv, 'D_P0', ph(j), d(j))) then
                if (len(c%problem) == 0) c%problem = 'D_P0 of phase ' // itoa(ph(j)) // ' is missing'
            end if
            if (.not. get_num(mv, 'RO_S0', ph(j), rho(j))) then
                if (len(c%problem) == 0) c%problem = 'RO_S0 of phase ' // itoa(ph(j)) // ' is missing'
            end if
            if (j > 1) c%sizes = c%sizes // '; '
            c%sizes = c%sizes // 'phase ' // itoa(ph(j)) // ': D_P0 ' // fmt_short(d(j)) // ', RO_S0 ' // fmt_short(rho(j))
        end do
        if (l == m) then
            d(2) = d(1)
            rho(2) = rho(1)
        end if
        c%mat%radius = 0.5_wp * d
        c%mat%density = rho
    end subroutine sizes

    !> DEM keys not read are noted one by one; the others are counted in one note.
    subroutine unread_keys(scene, mv)
        type(peer_scene), intent(inout) :: scene
        type(mfix_values), intent(inout) :: mv
        integer :: i, nother
        character(len=:), allocatable :: k
        nother = 0
        do i = 1, mv%keys%n
            k = mv%keys%item(i)%s
            if (index(read_keys, ' ' // k // ' ') > 0) cycle
            if (index(k, 'DES_') == 1 .or. index(k, 'KN') == 1 .or. index(k, 'KT') == 1 .or. index(k, 'MEW') == 1 .or. &
                index(k, 'E_YOUNG') > 0 .or. index(k, 'POISSON') > 0 .or. index(k, 'DTSOLID') == 1) then
                call scene%note('', 'MFiX key ' // k // ' is not interpreted')
            else
                nother = nother + 1
            end if
        end do
        if (nother > 0) call scene%note('', itoa(nother) // ' other MFiX keys (fluid, geometry, initial and ' // &
                                        'boundary conditions, output) were read and do not enter the contacts')
    end subroutine unread_keys

end module hertzdamp_check_mfix_deck
