!> A whole LAMMPS input deck read into contacts (doc/peers.md section 11): the shared
!> script language (hertzdamp_peers_script) plus the commands that define granular
!> contacts and particle sizes:
!> - `pair_style granular` with `pair_coeff I J ...` (wildcards; the last assignment of a
!>   pair counts; pairs without one are mixed by LAMMPS and are checked only when the
!>   two like pairs are identical), `pair_style gran/hertz/history ...`, the linear
!>   `gran/hooke*` styles (reported), `hybrid` and `hybrid/overlay` with these substyles;
!> - `fix wall/gran` and `fix wall/gran/region` (granular or hertz/history): every atom
!>   type against every wall;
!> - `fix pour` (diam one|range|poly, dens) and `fix deposit` (LAMMPS's default size).
!> Each type is checked at its smallest diameter and lowest density (the shortest
!> contact).  Commands that are neither interpreted nor passed over are noted.
module hertzdamp_peers_lammps_deck
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_peers, only: peer_text, PEER_LAMMPS
    use hertzdamp_peers_text, only: peer_list, peer_number
    use hertzdamp_peers_scene, only: peer_scene, peer_contact
    use hertzdamp_peers_script, only: peer_script, script_open, script_next, script_type_range, script_size, &
                                      script_add_size
    use hertzdamp_peers_common, only: join
    use hertzdamp_apps_text, only: itoa, fmt_short
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> One pair_coeff command.
    type :: coeff_rec
        integer :: ilo = 0, ihi = -1, jlo = 0, jhi = -1
        character(len=:), allocatable :: sub      !! hybrid substyle ('' without hybrid)
        type(peer_text), allocatable :: args(:)   !! the words after the types (and substyle)
        character(len=:), allocatable :: where
    end type coeff_rec

    !> One granular wall fix.
    type :: wall_rec
        character(len=:), allocatable :: id, where
        type(peer_text), allocatable :: words(:)
    end type wall_rec

    !> What the deck defines.
    type :: lammps_model
        character(len=:), allocatable :: style     !! pair_style (first word)
        type(peer_text), allocatable :: settings(:)  !! its arguments
        character(len=:), allocatable :: style_where
        type(coeff_rec), allocatable :: coeffs(:)
        integer :: ncoeffs = 0
        type(wall_rec), allocatable :: walls(:)
        integer :: nwalls = 0
    end type lammps_model

    public :: read_lammps_deck

contains

    !> Read LAMMPS deck files (in order) into a scene.  msg: a file that cannot be read.
    subroutine read_lammps_deck(paths, scene, msg)
        type(peer_text), intent(in) :: paths(:)
        type(peer_scene), intent(out) :: scene
        character(len=:), allocatable, intent(out) :: msg
        type(peer_script) :: st
        type(lammps_model) :: md
        type(peer_list) :: w
        character(len=:), allocatable :: where
        logical :: more
        call script_open(st, paths, .false., msg)
        if (len(msg) > 0) return
        md%style = ''
        md%style_where = ''
        allocate (md%settings(0), md%coeffs(8), md%walls(4))
        do
            call script_next(st, w, where, more)
            if (.not. more) exit
            call command(st, md, w, where)
        end do
        call default_timestep(st)
        call pair_contacts(st, md)
        call wall_contacts(st, md)
        scene = st%scene
        scene%peer = PEER_LAMMPS
    end subroutine read_lammps_deck

    subroutine command(st, md, w, where)
        type(peer_script), intent(inout) :: st
        type(lammps_model), intent(inout) :: md
        type(peer_list), intent(in) :: w
        character(len=*), intent(in) :: where
        select case (w%item(1)%s)
        case ('pair_style')
            if (w%n < 2) return
            md%style = w%item(2)%s
            md%settings = w%item(3:w%n)
            md%style_where = where
            md%ncoeffs = 0      ! a new pair style clears the coefficients
        case ('pair_coeff')
            call add_coeff(st, md, w, where)
        case ('fix')
            call fix_command(st, md, w, where)
        case default
            call st%scene%note(where, 'command ' // w%item(1)%s // ' is not interpreted')
        end select
    end subroutine command

    subroutine add_coeff(st, md, w, where)
        type(peer_script), intent(inout) :: st
        type(lammps_model), intent(inout) :: md
        type(peer_list), intent(in) :: w
        character(len=*), intent(in) :: where
        type(coeff_rec), allocatable :: tmp(:)
        type(coeff_rec) :: c
        integer :: k
        call script_type_range(st, w, 2, c%ilo, c%ihi)
        call script_type_range(st, w, 3, c%jlo, c%jhi)
        if (c%ilo < 1 .or. c%jlo < 1) then
            call st%scene%note(where, 'pair_coeff: atom types ' // join(w%item(2:min(3, w%n))) // ' not read')
            return
        end if
        k = 4
        c%sub = ''
        if (md%style == 'hybrid' .or. md%style == 'hybrid/overlay') then
            if (w%n >= 4) c%sub = w%item(4)%s
            k = 5
        end if
        c%args = w%item(min(k, w%n + 1):w%n)
        c%where = where
        if (md%ncoeffs == size(md%coeffs)) then
            allocate (tmp(2 * size(md%coeffs)))
            tmp(1:md%ncoeffs) = md%coeffs(1:md%ncoeffs)
            call move_alloc(tmp, md%coeffs)
        end if
        md%ncoeffs = md%ncoeffs + 1
        md%coeffs(md%ncoeffs) = c
    end subroutine add_coeff

    subroutine fix_command(st, md, w, where)
        type(peer_script), intent(inout) :: st
        type(lammps_model), intent(inout) :: md
        type(peer_list), intent(in) :: w
        character(len=*), intent(in) :: where
        type(wall_rec), allocatable :: tmp(:)
        integer :: k
        if (w%n < 4) then
            call st%scene%note(where, 'fix: too few words')
            return
        end if
        select case (w%item(4)%s)
        case ('wall/gran', 'wall/gran/region')
            if (w%item(3)%s /= 'all') call st%scene%note(where, 'fix ' // w%item(2)%s // ' acts on group ' // &
                w%item(3)%s // '; the checker pairs it with every atom type')
            do k = 1, md%nwalls    ! a fix ID defined again replaces the old one
                if (md%walls(k)%id == w%item(2)%s) exit
            end do
            if (k > md%nwalls) then
                if (md%nwalls == size(md%walls)) then
                    allocate (tmp(2 * size(md%walls)))
                    tmp(1:md%nwalls) = md%walls(1:md%nwalls)
                    call move_alloc(tmp, md%walls)
                end if
                md%nwalls = md%nwalls + 1
                k = md%nwalls
            end if
            md%walls(k)%id = w%item(2)%s
            md%walls(k)%where = where
            md%walls(k)%words = w%items()
        case ('pour')
            call pour(st, w, where)
        case ('deposit')
            call deposit(st, w, where)
        case default
            call st%scene%note(where, 'fix style ' // w%item(4)%s // ' is not interpreted')
        end select
    end subroutine fix_command

    !> fix ID group pour N type seed ... diam one D | range lo hi | poly n D1 P1 ... dens lo hi
    subroutine pour(st, w, where)
        type(peer_script), intent(inout) :: st
        type(peer_list), intent(in) :: w
        character(len=*), intent(in) :: where
        real(wp) :: dmin, dens, x, y
        integer :: t, lo, hi, i, j, np
        call script_type_range(st, w, 6, lo, hi)
        if (lo < 1 .or. lo /= hi) then
            call st%scene%note(where, 'fix pour: atom type not read')
            return
        end if
        t = lo
        dmin = 1.0_wp
        dens = 1.0_wp
        i = 8
        do while (i <= w%n)
            select case (w%item(i)%s)
            case ('diam')
                if (i + 2 > w%n) exit
                select case (w%item(i + 1)%s)
                case ('one', 'range')
                    if (peer_number(w%item(i + 2)%s, x)) dmin = x
                    i = i + merge(3, 4, w%item(i + 1)%s == 'one')
                case ('poly')
                    np = 0
                    if (peer_number(w%item(i + 2)%s, x)) np = nint(x)
                    dmin = huge(1.0_wp)
                    do j = 1, np
                        if (i + 1 + 2 * j > w%n) exit
                        if (peer_number(w%item(i + 1 + 2 * j)%s, y)) dmin = min(dmin, y)
                    end do
                    i = i + 3 + 2 * np
                case default
                    call st%scene%note(where, 'fix pour diam ' // w%item(i + 1)%s // ' is not interpreted')
                    i = i + 2
                end select
            case ('dens')
                if (i + 1 <= w%n) then
                    if (peer_number(w%item(i + 1)%s, x)) dens = x
                end if
                i = i + 3
            case ('mol')
                call st%scene%note(where, 'fix pour mol: the molecule''s atoms and sizes are not read')
                i = i + 2
            case default
                i = i + 1
            end select
        end do
        call script_add_size(st, t, dmin, dens, 'fix pour ' // w%item(2)%s // ' (' // where // ')')
    end subroutine pour

    !> fix ID group deposit N type M seed ...: atoms of LAMMPS's default size.
    subroutine deposit(st, w, where)
        type(peer_script), intent(inout) :: st
        type(peer_list), intent(in) :: w
        character(len=*), intent(in) :: where
        integer :: lo, hi, i
        call script_type_range(st, w, 6, lo, hi)
        if (lo < 1 .or. lo /= hi) then
            call st%scene%note(where, 'fix deposit: atom type not read')
            return
        end if
        do i = 8, w%n
            if (w%item(i)%s == 'mol') call st%scene%note(where, 'fix deposit mol: the molecule''s atoms and sizes ' // &
                                                         'are not read')
        end do
        call script_add_size(st, lo, 1.0_wp, 1.0_wp, 'fix deposit ' // w%item(2)%s // ' (' // where // &
                             ', the default diameter 1 and density 1)')
    end subroutine deposit

    !> LAMMPS's default time step where the deck sets none (update.cpp, per unit style).
    subroutine default_timestep(st)
        type(peer_script), intent(inout) :: st
        if (st%have_dt) return
        select case (st%scene%units)
        case ('lj'); st%scene%dt = 0.005_wp
        case ('si', 'cgs'); st%scene%dt = 1.0e-8_wp
        case ('micro'); st%scene%dt = 2.0_wp
        case ('nano'); st%scene%dt = 0.00045_wp
        case default
        end select
        if (st%scene%dt > 0.0_wp) st%scene%dt_text = 'LAMMPS''s default for units ' // st%scene%units // &
                                                     ' (no timestep command)'
    end subroutine default_timestep

    !> The types that have atoms (all when none is known to have).
    subroutine active_types(st, types)
        type(peer_script), intent(inout) :: st
        integer, allocatable, intent(out) :: types(:)
        integer :: t
        allocate (types(0))
        do t = 1, st%ntypes
            if (st%atoms(t)) types = [types, t]
        end do
        if (size(types) == 0 .and. st%ntypes > 0) then
            call st%scene%note('', 'no atom of any type is created, poured or deposited in the deck: every type ' // &
                               'is checked with LAMMPS''s default size')
            types = [(t, t = 1, st%ntypes)]
        end if
        if (st%ntypes == 0) call st%scene%note('', 'no create_box: the number of atom types is not known')
    end subroutine active_types

    subroutine pair_contacts(st, md)
        type(peer_script), intent(inout) :: st
        type(lammps_model), intent(inout) :: md
        integer, allocatable :: types(:)
        type(peer_contact) :: c
        integer :: a, b
        call active_types(st, types)
        if (len(md%style) == 0 .or. md%style == 'none') then
            call st%scene%note('', 'no pair_style: particle-particle contacts are not checked')
            return
        end if
        do a = 1, size(types)
            do b = a, size(types)
                call pair_contact(st, md, types(a), types(b), c)
                call st%scene%add_contact(c)
            end do
        end do
    end subroutine pair_contacts

    !> The contact of types i <= j: its words for the contact reader, or the problem.
    subroutine pair_contact(st, md, i, j, c)
        type(peer_script), intent(inout) :: st
        type(lammps_model), intent(in) :: md
        integer, intent(in) :: i, j
        type(peer_contact), intent(out) :: c
        character(len=:), allocatable :: si, sj
        integer :: k, ki, kj
        c%pair = itoa(i) // '-' // itoa(j)
        c%problem = ''
        c%where = md%style_where
        call script_size(st, i, c%mat%radius(1), c%mat%density(1), si)
        call script_size(st, j, c%mat%radius(2), c%mat%density(2), sj)
        c%sizes = si
        if (j /= i) c%sizes = si // '; ' // sj
        select case (md%style)
        case ('gran/hertz/history', 'gran/hooke/history', 'gran/hooke')
            c%words = prepend(md%style, md%settings)
            return
        case ('granular', 'hybrid', 'hybrid/overlay')
        case default
            c%words = [peer_text('pair_style'), peer_text(md%style)]
            c%problem = 'pair_style ' // md%style // ' is not a granular style the checker reads'
            return
        end select
        k = last_coeff(md, i, j)
        if (k == 0) then
            ki = last_coeff(md, i, i)
            kj = last_coeff(md, j, j)
            if (i == j) then
                c%problem = 'no pair_coeff covers ' // itoa(i) // ' ' // itoa(i) // ' (LAMMPS stops: all pair ' // &
                            'coeffs are not set)'
            else
                c%problem = 'no pair_coeff ' // itoa(i) // ' ' // itoa(j) // ': LAMMPS mixes the coefficients of ' // &
                            itoa(i) // '-' // itoa(i) // ' and ' // itoa(j) // '-' // itoa(j) // ', which the ' // &
                            'checker does not model'
            end if
            if (ki > 0 .and. kj > 0) then
                if (md%coeffs(ki)%sub == md%coeffs(kj)%sub .and. join(md%coeffs(ki)%args) == join(md%coeffs(kj)%args)) then
                    k = ki
                    c%problem = ''
                end if
            end if
            if (k == 0) return
        end if
        c%where = md%coeffs(k)%where
        call coeff_words(md, md%coeffs(k), c)
    end subroutine pair_contact

    !> The last pair_coeff covering (i, j) in either order (0: none).
    pure integer function last_coeff(md, i, j) result(k)
        type(lammps_model), intent(in) :: md
        integer, intent(in) :: i, j
        do k = md%ncoeffs, 1, -1
            associate (r => md%coeffs(k))
                if ((i >= r%ilo .and. i <= r%ihi .and. j >= r%jlo .and. j <= r%jhi) .or. &
                    (j >= r%ilo .and. j <= r%ihi .and. i >= r%jlo .and. i <= r%jhi)) return
            end associate
        end do
        k = 0
    end function last_coeff

    !> The contact reader's words of a pair_coeff (a hybrid substyle's settings included).
    subroutine coeff_words(md, r, c)
        type(lammps_model), intent(in) :: md
        type(coeff_rec), intent(in) :: r
        type(peer_contact), intent(inout) :: c
        character(len=:), allocatable :: sub
        sub = r%sub
        if (len(sub) == 0) then
            c%words = r%args
        else if (sub == 'granular') then
            c%words = r%args
        else if (sub == 'gran/hertz/history' .or. sub == 'gran/hooke/history' .or. sub == 'gran/hooke') then
            c%words = prepend(sub, hybrid_settings(md, sub))
        else
            c%words = [peer_text('pair_style'), peer_text(sub)]
            c%problem = 'pair_style hybrid substyle ' // sub // ' is not a granular style the checker reads'
        end if
    end subroutine coeff_words

    !> [first, rest].
    function prepend(first, rest) result(w)
        character(len=*), intent(in) :: first
        type(peer_text), intent(in) :: rest(:)
        type(peer_text), allocatable :: w(:)
        integer :: i
        allocate (w(size(rest) + 1))
        w(1)%s = first
        do i = 1, size(rest)
            w(i + 1)%s = rest(i)%s
        end do
    end function prepend

    !> The settings of a substyle on the pair_style hybrid line: the words after its
    !> name up to the next word that is neither a number, NULL nor limit_damping.
    function hybrid_settings(md, sub) result(w)
        type(lammps_model), intent(in) :: md
        character(len=*), intent(in) :: sub
        type(peer_text), allocatable :: w(:)
        integer :: i, j
        real(wp) :: x
        allocate (w(0))
        do i = 1, size(md%settings)
            if (md%settings(i)%s /= sub) cycle
            do j = i + 1, size(md%settings)
                if (.not. (peer_number(md%settings(j)%s, x) .or. md%settings(j)%s == 'NULL' .or. &
                           md%settings(j)%s == 'limit_damping')) exit
            end do
            w = md%settings(i + 1:j - 1)
            return
        end do
    end function hybrid_settings

    subroutine wall_contacts(st, md)
        type(peer_script), intent(inout) :: st
        type(lammps_model), intent(in) :: md
        integer, allocatable :: types(:)
        type(peer_contact) :: c
        integer :: a, k
        if (md%nwalls == 0) return
        call active_types(st, types)
        do k = 1, md%nwalls
            do a = 1, size(types)
                c%pair = itoa(types(a)) // '-wall'
                if (md%nwalls > 1) c%pair = c%pair // ':' // md%walls(k)%id
                c%words = md%walls(k)%words
                c%where = md%walls(k)%where
                c%problem = ''
                call script_size(st, types(a), c%mat%radius(1), c%mat%density(1), c%sizes)
                c%mat%radius(2) = 0.0_wp
                c%mat%density(2) = 0.0_wp
                c%mat%wall = .true.
                call st%scene%add_contact(c)
            end do
        end do
    end subroutine wall_contacts

end module hertzdamp_peers_lammps_deck
