!> A whole LAMMPS input deck read into contacts (doc/peers.md section 11): the script
!> language LAMMPS and LIGGGHTS share (hertzdamp_lmpscript) plus the commands that
!> define granular contacts and particle sizes:
!> - `pair_style granular` with `pair_coeff I J ...` (wildcards; the last assignment of a
!>   pair counts; pairs without one are mixed by LAMMPS and are checked only when the
!>   two like pairs are identical), `pair_style gran/hertz/history ...`, the linear
!>   `gran/hooke*` styles (reported), `hybrid` and `hybrid/overlay` with these substyles;
!> - `fix wall/gran` and `fix wall/gran/region` (granular or hertz/history): every atom
!>   type against every wall;
!> - `fix pour` (diam one|range|poly, dens) and `fix deposit` (LAMMPS's default size).
!> Each type is checked at its smallest diameter and lowest density (the shortest
!> contact).  Commands that are neither interpreted nor passed over are noted.
module hertzdamp_check_lammps_deck
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_check_model, only: PEER_LAMMPS
    use hertzdamp_check_scene, only: peer_scene, peer_contact, peer_scene_from_script
    use hertzdamp_lmpscript, only: lmp_script, lmp_commands, lmp_read, lmp_type_range, lmp_size, lmp_add_size, &
                                   lmp_active_types
    use hertzdamp_text_list, only: text_string, text_list, text_join
    use hertzdamp_text_parse, only: text_number
    use hertzdamp_text_format, only: itoa
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> One pair_coeff command or one granular wall fix.
    type :: lammps_rec
        integer :: ilo = 0, ihi = -1, jlo = 0, jhi = -1   !! pair_coeff: the atom types
        character(len=:), allocatable :: sub              !! pair_coeff: hybrid substyle ('' without hybrid)
        character(len=:), allocatable :: id               !! wall fix: its ID
        type(text_string), allocatable :: words(:)        !! pair_coeff: the words after the types (and
                                                          !! substyle); wall fix: all its words
        character(len=:), allocatable :: where
    end type lammps_rec

    !> What the deck defines: the LAMMPS commands of lmp_read's reader.
    type, extends(lmp_commands) :: lammps_model
        character(len=:), allocatable :: style     !! pair_style (first word)
        type(text_string), allocatable :: settings(:)  !! its arguments
        character(len=:), allocatable :: style_where
        type(lammps_rec), allocatable :: coeffs(:)
        integer :: ncoeffs = 0
        type(lammps_rec), allocatable :: walls(:)
        integer :: nwalls = 0
    contains
        procedure :: command
    end type lammps_model

    public :: read_lammps_deck

contains

    !> Read LAMMPS deck files (in order) into a scene.  msg: a file that cannot be read,
    !> or why the reading stopped.
    subroutine read_lammps_deck(paths, scene, msg)
        type(text_string), intent(in) :: paths(:)            !! the deck's files
        type(peer_scene), intent(out) :: scene
        character(len=:), allocatable, intent(out) :: msg
        type(lmp_script) :: st
        type(lammps_model) :: md
        md%style = ''
        md%style_where = ''
        allocate (md%settings(0), md%coeffs(8), md%walls(4))
        call lmp_read(st, paths, .false., md, msg)
        if (len(msg) > 0) return
        call default_timestep(st)
        call pair_contacts(st, md, scene)
        call wall_contacts(st, md, scene)
        call peer_scene_from_script(st, PEER_LAMMPS, scene)
    end subroutine read_lammps_deck

    subroutine command(self, st, w, where, handled)
        class(lammps_model), intent(inout) :: self
        type(lmp_script), intent(inout) :: st
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        logical, intent(out) :: handled
        handled = .true.
        select case (w%item(1)%s)
        case ('pair_style')
            if (w%n < 2) return
            self%style = w%item(2)%s
            self%settings = w%item(3:w%n)
            self%style_where = where
            self%ncoeffs = 0      ! a new pair style clears the coefficients
        case ('pair_coeff')
            call add_coeff(st, self, w, where)
            if (self%style == 'granular/hertzdamp') call plugin_note(st, self%settings, w, where, 'pair_style granular/hertzdamp')
        case ('fix')
            call fix_command(st, self, w, where, handled)
        case default
            handled = .false.
        end select
    end subroutine command

    !> Append a record (the array grows by doubling).
    subroutine push_rec(recs, n, r)
        type(lammps_rec), allocatable, intent(inout) :: recs(:)
        integer, intent(inout) :: n
        type(lammps_rec), intent(in) :: r
        type(lammps_rec), allocatable :: tmp(:)
        if (n == size(recs)) then
            allocate (tmp(2 * size(recs)))
            tmp(1:n) = recs(1:n)
            call move_alloc(tmp, recs)
        end if
        n = n + 1
        recs(n) = r
    end subroutine push_rec

    subroutine add_coeff(st, md, w, where)
        type(lmp_script), intent(inout) :: st
        type(lammps_model), intent(inout) :: md
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        type(lammps_rec) :: c
        integer :: k
        call lmp_type_range(st, w, 2, c%ilo, c%ihi)
        call lmp_type_range(st, w, 3, c%jlo, c%jhi)
        if (c%ilo < 1 .or. c%jlo < 1) then
            call st%note(where, 'pair_coeff: atom types ' // text_join(w%item(2:min(3, w%n))) // ' not read')
            return
        end if
        k = 4
        c%sub = ''
        if (md%style == 'hybrid' .or. md%style == 'hybrid/overlay') then
            if (w%n >= 4) c%sub = w%item(4)%s
            k = 5
        end if
        c%words = w%item(min(k, w%n + 1):w%n)
        c%where = where
        call push_rec(md%coeffs, md%ncoeffs, c)
    end subroutine add_coeff

    !> The fixes of walls and particle sizes (handled false for other styles).
    subroutine fix_command(st, md, w, where, handled)
        type(lmp_script), intent(inout) :: st
        type(lammps_model), intent(inout) :: md
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        logical, intent(inout) :: handled
        type(lammps_rec) :: r
        integer :: k
        if (w%n < 4) then
            call st%note(where, 'fix: too few words')
            return
        end if
        select case (w%item(4)%s)
        case ('wall/gran', 'wall/gran/region')
            if (w%item(3)%s /= 'all') call st%note(where, 'fix ' // w%item(2)%s // ' acts on group ' // &
                w%item(3)%s // '; the checker pairs it with every atom type')
            r%id = w%item(2)%s
            r%where = where
            r%words = w%items()
            do k = 1, md%nwalls    ! a fix ID defined again replaces the old one
                if (md%walls(k)%id == r%id) exit
            end do
            if (k > md%nwalls) then
                call push_rec(md%walls, md%nwalls, r)
            else
                md%walls(k) = r
            end if
        case ('hertzdamp/wall')
            call plugin_note(st, w%item(5:w%n), w, where, 'fix hertzdamp/wall')
            handled = .false.
        case ('pour')
            call pour(st, w, where)
        case ('deposit')
            call deposit(st, w, where)
        case default
            handled = .false.
        end select
    end subroutine fix_command

    !> The hertzdamp LAMMPS plugin (pair_style granular/hertzdamp, fix hertzdamp/wall) with
    !> a tangential model and tangential_stiffness physical: the physical k_t kept with
    !> the softened normal contact (issue 33) gets a warning (the plugin's default,
    !> adapted, scales k_t per contact).
    subroutine plugin_note(st, settings, w, where, what)
        type(lmp_script), intent(inout) :: st
        type(text_string), intent(in) :: settings(:)    !! the style's (or the fix's) keywords
        type(text_list), intent(in) :: w                 !! the command with the tangential keyword
        character(len=*), intent(in) :: where, what
        integer :: k
        logical :: physical, tangential
        physical = .false.
        do k = 1, size(settings) - 1
            if (settings(k)%s == 'tangential_stiffness' .and. settings(k + 1)%s == 'physical') physical = .true.
        end do
        tangential = .false.
        do k = 1, w%n
            if (w%item(k)%s == 'tangential') tangential = .true.
        end do
        if (physical .and. tangential) call st%note(where, 'warning: ' // what // ' (the hertzdamp LAMMPS ' // &
            'plugin) softens the normal contact and keeps the physical tangential stiffness (tangential_stiffness ' // &
            'physical): the tangential outcome is off (up to 0.36 in e_t, doc/oblique.md); remove it ' // &
            '(the default, adapted, scales k_t by k/k_phys per contact)')
    end subroutine plugin_note

    !> fix ID group pour N type seed ... diam one D | range lo hi | poly n D1 P1 ... dens lo hi
    subroutine pour(st, w, where)
        type(lmp_script), intent(inout) :: st
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        real(wp) :: dmin, dens, x, y
        integer :: t, lo, hi, i, j, np
        call lmp_type_range(st, w, 6, lo, hi)
        if (lo < 1 .or. lo /= hi) then
            call st%note(where, 'fix pour: atom type not read')
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
                    if (text_number(w%item(i + 2)%s, x)) dmin = x
                    i = i + merge(3, 4, w%item(i + 1)%s == 'one')
                case ('poly')
                    np = 0
                    if (text_number(w%item(i + 2)%s, x)) np = nint(x)
                    dmin = huge(1.0_wp)
                    do j = 1, np
                        if (i + 1 + 2 * j > w%n) exit
                        if (text_number(w%item(i + 1 + 2 * j)%s, y)) dmin = min(dmin, y)
                    end do
                    i = i + 3 + 2 * np
                case default
                    call st%note(where, 'fix pour diam ' // w%item(i + 1)%s // ' is not interpreted')
                    i = i + 2
                end select
            case ('dens')
                if (i + 1 <= w%n) then
                    if (text_number(w%item(i + 1)%s, x)) dens = x
                end if
                i = i + 3
            case ('mol')
                call st%note(where, 'fix pour mol: the molecule''s atoms and sizes are not read')
                i = i + 2
            case default
                i = i + 1
            end select
        end do
        call lmp_add_size(st, t, dmin, dens, 'fix pour ' // w%item(2)%s // ' (' // where // ')')
    end subroutine pour

    !> fix ID group deposit N type M seed ...: atoms of LAMMPS's default size.
    subroutine deposit(st, w, where)
        type(lmp_script), intent(inout) :: st
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        integer :: lo, hi, i
        call lmp_type_range(st, w, 6, lo, hi)
        if (lo < 1 .or. lo /= hi) then
            call st%note(where, 'fix deposit: atom type not read')
            return
        end if
        do i = 8, w%n
            if (w%item(i)%s == 'mol') call st%note(where, 'fix deposit mol: the molecule''s atoms and sizes ' // &
                                                         'are not read')
        end do
        call lmp_add_size(st, lo, 1.0_wp, 1.0_wp, 'fix deposit ' // w%item(2)%s // ' (' // where // &
                             ', the default diameter 1 and density 1)')
    end subroutine deposit

    !> LAMMPS's default time step where the deck sets none (update.cpp, per unit style).
    subroutine default_timestep(st)
        type(lmp_script), intent(inout) :: st
        if (st%have_dt) return
        select case (st%units)
        case ('lj'); st%dt = 0.005_wp
        case ('si', 'cgs'); st%dt = 1.0e-8_wp
        case ('micro'); st%dt = 2.0_wp
        case ('nano'); st%dt = 0.00045_wp
        case default
        end select
        if (st%dt > 0.0_wp) st%dt_text = 'LAMMPS''s default for units ' // st%units // &
                                                     ' (no timestep command)'
    end subroutine default_timestep

    !> The types that have atoms (all when none is known to have).
    subroutine active_types(st, types)
        type(lmp_script), intent(inout) :: st
        integer, allocatable, intent(out) :: types(:)
        if (st%ntypes == 0) then
            call st%note('', 'no create_box: the number of atom types is not known')
            allocate (types(0))
        else
            call lmp_active_types(st, 'no atom of any type is created, poured or deposited in the deck: every ' // &
                                  'type is checked with LAMMPS''s default size', types)
        end if
    end subroutine active_types

    subroutine pair_contacts(st, md, scene)
        type(lmp_script), intent(inout) :: st
        type(lammps_model), intent(inout) :: md
        type(peer_scene), intent(inout) :: scene
        integer, allocatable :: types(:)
        type(peer_contact) :: c
        integer :: a, b
        call active_types(st, types)
        if (len(md%style) == 0 .or. md%style == 'none') then
            call st%note('', 'no pair_style: particle-particle contacts are not checked')
            return
        end if
        do a = 1, size(types)
            do b = a, size(types)
                call pair_contact(st, md, types(a), types(b), c)
                call scene%add_contact(c)
            end do
        end do
    end subroutine pair_contacts

    !> The contact of types i <= j: its words for the contact reader, or the problem.
    subroutine pair_contact(st, md, i, j, c)
        type(lmp_script), intent(inout) :: st
        type(lammps_model), intent(in) :: md
        integer, intent(in) :: i, j
        type(peer_contact), intent(out) :: c
        character(len=:), allocatable :: si, sj
        integer :: k, ki, kj
        c%pair = itoa(i) // '-' // itoa(j)
        c%problem = ''
        c%where = md%style_where
        call lmp_size(st, i, c%mat%radius(1), c%mat%density(1), si)
        call lmp_size(st, j, c%mat%radius(2), c%mat%density(2), sj)
        c%sizes = si
        if (j /= i) c%sizes = si // '; ' // sj
        select case (md%style)
        case ('gran/hertz/history', 'gran/hooke/history', 'gran/hooke')
            c%words = prepend(md%style, md%settings)
            return
        case ('granular', 'hybrid', 'hybrid/overlay')
        case default
            c%words = style_words(md%style)
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
                if (md%coeffs(ki)%sub == md%coeffs(kj)%sub .and. text_join(md%coeffs(ki)%words) == &
                    text_join(md%coeffs(kj)%words)) then
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
        type(lammps_rec), intent(in) :: r
        type(peer_contact), intent(inout) :: c
        character(len=:), allocatable :: sub
        sub = r%sub
        if (len(sub) == 0) then
            c%words = r%words
        else if (sub == 'granular') then
            c%words = r%words
        else if (sub == 'gran/hertz/history' .or. sub == 'gran/hooke/history' .or. sub == 'gran/hooke') then
            c%words = prepend(sub, hybrid_settings(md, sub))
        else
            c%words = style_words(sub)
            c%problem = 'pair_style hybrid substyle ' // sub // ' is not a granular style the checker reads'
        end if
    end subroutine coeff_words

    !> The words `pair_style STYLE`, set one by one: gfortran 12 builds
    !> [text_string('pair_style'), text_string(md%style)] with an empty second string
    !> (and may crash freeing it) when the argument is a bare component.
    pure function style_words(style) result(w)
        character(len=*), intent(in) :: style
        type(text_string) :: w(2)
        w(1)%s = 'pair_style'
        w(2)%s = style
    end function style_words

    !> [first, rest].
    function prepend(first, rest) result(w)
        character(len=*), intent(in) :: first
        type(text_string), intent(in) :: rest(:)
        type(text_string), allocatable :: w(:)
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
        type(text_string), allocatable :: w(:)
        integer :: i, j
        real(wp) :: x
        allocate (w(0))
        do i = 1, size(md%settings)
            if (md%settings(i)%s /= sub) cycle
            do j = i + 1, size(md%settings)
                if (.not. (text_number(md%settings(j)%s, x) .or. md%settings(j)%s == 'NULL' .or. &
                           md%settings(j)%s == 'limit_damping')) exit
            end do
            w = md%settings(i + 1:j - 1)
            return
        end do
    end function hybrid_settings

    subroutine wall_contacts(st, md, scene)
        type(lmp_script), intent(inout) :: st
        type(lammps_model), intent(in) :: md
        type(peer_scene), intent(inout) :: scene
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
                call lmp_size(st, types(a), c%mat%radius(1), c%mat%density(1), c%sizes)
                c%mat%radius(2) = 0.0_wp
                c%mat%density(2) = 0.0_wp
                c%mat%wall = .true.
                call scene%add_contact(c)
            end do
        end do
    end subroutine wall_contacts

end module hertzdamp_check_lammps_deck
