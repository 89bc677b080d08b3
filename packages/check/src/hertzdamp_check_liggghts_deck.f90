!> A whole LIGGGHTS input deck read into contacts (doc/peers.md sections 2 and 11): the
!> LAMMPS script language (hertzdamp_peers_script) plus
!> - `fix ID all property/global NAME peratomtype v1 .. vN | peratomtypepair N v11 .. vNN`
!>   for youngsModulus, poissonsRatio, coefficientRestitution, coefficientFriction (and
!>   kn, gamman of model hertz/stiffness);
!> - `pair_style gran model hertz|hertz/stiffness|hooke ... [limitForce on|off] ...`;
!> - `fix wall/gran model ... primitive type T xplane|yplane|zplane ...` or `mesh n_meshes N
!>   meshes ID...` with the meshes' `fix mesh/surface ... type T` (the wall's material type);
!> - `fix particletemplate/sphere ... atom_type T density constant rho radius constant r`
!>   (and create_atoms with set, as LAMMPS).
!> Every type pair and every type against every wall becomes a contact in the words of the
!> LIGGGHTS contact reader (hertzdamp_check_liggghts).
module hertzdamp_check_liggghts_deck
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_check_model, only: PEER_LIGGGHTS
    use hertzdamp_check_scene, only: peer_scene, peer_contact, peer_scene_from_script
    use hertzdamp_lmpscript, only: lmp_script, lmp_commands, lmp_read, lmp_size, lmp_add_size, lmp_active_types
    use hertzdamp_text_list, only: text_string, text_list
    use hertzdamp_text_map, only: text_map
    use hertzdamp_text_parse, only: text_number, text_shortest
    use hertzdamp_text_format, only: itoa
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> One fix property/global.
    type :: property
        character(len=:), allocatable :: name, style, where
        real(wp), allocatable :: v(:)
        integer :: n = 0            !! peratomtypepair: the matrix order
    end type property

    !> One granular wall.
    type :: lwall
        character(len=:), allocatable :: id, where
        type(text_string), allocatable :: model(:)   !! the contact reader's words of the models
        integer, allocatable :: types(:)           !! the wall's material types
    end type lwall

    !> What the deck defines: the LIGGGHTS commands of lmp_read's reader.
    type, extends(lmp_commands) :: liggghts_model
        type(property), allocatable :: props(:)
        integer :: nprops = 0
        type(text_map) :: prop_index               !! property name -> index
        type(text_string), allocatable :: pair_words(:)
        character(len=:), allocatable :: pair_where, pair_problem
        type(lwall), allocatable :: walls(:)
        integer :: nwalls = 0
        type(text_map) :: mesh_type                !! mesh fix ID -> material type
    contains
        procedure :: command
    end type liggghts_model

    public :: read_liggghts_deck

contains

    !> Read LIGGGHTS deck files (in order) into a scene.  msg: a file that cannot be
    !> read, or why the reading stopped.
    subroutine read_liggghts_deck(paths, scene, msg)
        type(text_string), intent(in) :: paths(:)            !! the deck's files
        type(peer_scene), intent(out) :: scene
        character(len=:), allocatable, intent(out) :: msg
        type(lmp_script) :: st
        type(liggghts_model) :: md
        allocate (md%props(8), md%walls(4), md%pair_words(0))
        md%pair_where = ''
        md%pair_problem = 'no pair_style gran'
        call lmp_read(st, paths, .true., md, msg)
        if (len(msg) > 0) return
        if (.not. st%have_dt) then
            st%dt = 1.0e-8_wp
            st%dt_text = 'LIGGGHTS''s default (no timestep command)'
        end if
        call contacts(st, md, scene)
        call peer_scene_from_script(st, PEER_LIGGGHTS, scene)
    end subroutine read_liggghts_deck

    subroutine command(self, st, w, where, handled)
        class(liggghts_model), intent(inout) :: self
        type(lmp_script), intent(inout) :: st
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        logical, intent(out) :: handled
        handled = .true.
        select case (w%item(1)%s)
        case ('pair_style')
            call pair_style(self, w, where)
        case ('pair_coeff')
            if (w%n > 3) call st%note(where, 'pair_coeff with coefficients: LIGGGHTS takes them from ' // &
                                      'fix property/global; ignored')
        case ('fix')
            call fix_command(st, self, w, where, handled)
        case default
            handled = .false.
        end select
    end subroutine command

    !> The contact reader's words of `model X [tangential Y ...] keyword value ...`
    !> starting at word k; problem when a model is not a Hertz one.
    subroutine model_words(w, k, words, problem)
        type(text_list), intent(in) :: w
        integer, intent(in) :: k
        type(text_string), allocatable, intent(out) :: words(:)
        character(len=:), allocatable, intent(out) :: problem
        integer :: i
        allocate (words(0))
        problem = ''
        i = k
        do while (i + 1 <= w%n)
            select case (w%item(i)%s)
            case ('model', 'tangential', 'cohesion', 'rolling_friction', 'surface', 'limitForce', 'tangential_damping')
                words = [words, text_string(w%item(i)%s // '=' // w%item(i + 1)%s)]
            case ('primitive', 'mesh')
                return
            case default
            end select
            i = i + 2
        end do
        if (size(words) == 0) problem = 'no model given'
    end subroutine model_words

    subroutine pair_style(md, w, where)
        type(liggghts_model), intent(inout) :: md
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        md%pair_where = where
        if (w%n >= 2 .and. (w%item(2)%s == 'gran' .or. w%item(2)%s == 'bubble' .or. w%item(2)%s == 'gran_bubble')) then
            call model_words(w, 3, md%pair_words, md%pair_problem)
        else if (w%n >= 2) then
            md%pair_problem = 'pair_style ' // w%item(2)%s // ' is not read (LIGGGHTS: pair_style gran model ...)'
        end if
    end subroutine pair_style

    !> The fixes of materials, walls and particle templates (handled false for other styles).
    subroutine fix_command(st, md, w, where, handled)
        type(lmp_script), intent(inout) :: st
        type(liggghts_model), intent(inout) :: md
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        logical, intent(inout) :: handled
        if (w%n < 4) return
        select case (w%item(4)%s)
        case ('property/global')
            call add_property(st, md, w, where)
        case ('wall/gran')
            call add_wall(st, md, w, where)
        case ('mesh/surface', 'mesh/surface/stress', 'mesh/surface/planar', 'mesh/surface/stress/servo')
            call mesh(md, w)
        case ('particletemplate/sphere')
            call template(st, w, where)
        case ('particledistribution/discrete', 'insert/pack', 'insert/stream', 'insert/rate/region', &
              'move/mesh', 'wall/region/sph', 'check/timestep/gran', 'particletemplate/multisphere')
            if (w%item(4)%s == 'particletemplate/multisphere') call st%note(where, 'multisphere ' // &
                'particles are not read')
        case default
            handled = .false.
        end select
    end subroutine fix_command

    !> fix ID group property/global NAME style values.
    subroutine add_property(st, md, w, where)
        type(lmp_script), intent(inout) :: st
        type(liggghts_model), intent(inout) :: md
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        type(property) :: p
        type(property), allocatable :: tmp(:)
        integer :: i, k0, k
        real(wp) :: x
        if (w%n < 7) return
        p%name = w%item(5)%s
        p%style = w%item(6)%s
        p%where = where
        k0 = 7
        if (p%style == 'peratomtypepair' .or. p%style == 'atomtypepair') then
            if (text_number(w%item(7)%s, x)) p%n = nint(x)
            k0 = 8
        end if
        allocate (p%v(max(0, w%n - k0 + 1)))
        do i = k0, w%n
            if (.not. text_number(w%item(i)%s, p%v(i - k0 + 1))) then
                call st%note(where, 'property/global ' // p%name // ': "' // w%item(i)%s // '" is not a number')
                return
            end if
        end do
        k = md%prop_index%get(p%name)
        if (k == 0) then
            if (md%nprops == size(md%props)) then
                allocate (tmp(2 * size(md%props)))
                tmp(1:md%nprops) = md%props(1:md%nprops)
                call move_alloc(tmp, md%props)
            end if
            md%nprops = md%nprops + 1
            k = md%nprops
            call md%prop_index%put(p%name, k)
        end if
        md%props(k) = p
    end subroutine add_property

    !> fix ID group wall/gran model ... primitive type T plane pos | mesh n_meshes N meshes IDs
    subroutine add_wall(st, md, w, where)
        type(lmp_script), intent(inout) :: st
        type(liggghts_model), intent(inout) :: md
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        type(lwall) :: wl
        type(lwall), allocatable :: tmp(:)
        character(len=:), allocatable :: problem
        integer :: i, j, nm, t
        real(wp) :: x
        wl%id = w%item(2)%s
        wl%where = where
        allocate (wl%types(0))
        call model_words(w, 5, wl%model, problem)
        do i = 5, w%n
            if (w%item(i)%s == 'type' .and. i + 1 <= w%n) then
                if (text_number(w%item(i + 1)%s, x)) wl%types = [wl%types, nint(x)]
            else if (w%item(i)%s == 'xcylinder' .or. w%item(i)%s == 'ycylinder' .or. w%item(i)%s == 'zcylinder') then
                call st%note(where, 'fix wall/gran ' // w%item(i)%s // ': checked as a flat wall (R = the ' // &
                                   'particle radius); a cylinder changes R')
            else if (w%item(i)%s == 'n_meshes' .and. i + 1 <= w%n) then
                nm = 0
                if (text_number(w%item(i + 1)%s, x)) nm = nint(x)
                do j = i + 3, min(w%n, i + 2 + nm)
                    t = md%mesh_type%get(w%item(j)%s)
                    if (t > 0) then
                        wl%types = [wl%types, t]
                    else
                        call st%note(where, 'mesh ' // w%item(j)%s // ': no fix mesh/surface with a type')
                    end if
                end do
            end if
        end do
        if (len(problem) > 0 .or. size(wl%types) == 0) then
            call st%note(where, 'fix wall/gran ' // wl%id // ': no model or no wall material type; not checked')
            return
        end if
        if (md%nwalls == size(md%walls)) then
            allocate (tmp(2 * size(md%walls)))
            tmp(1:md%nwalls) = md%walls(1:md%nwalls)
            call move_alloc(tmp, md%walls)
        end if
        md%nwalls = md%nwalls + 1
        md%walls(md%nwalls) = wl
    end subroutine add_wall

    !> fix ID group mesh/surface file F type T ...: the mesh's material type.
    subroutine mesh(md, w)
        type(liggghts_model), intent(inout) :: md
        type(text_list), intent(in) :: w
        integer :: i
        real(wp) :: x
        do i = 5, w%n - 1
            if (w%item(i)%s /= 'type') cycle
            if (text_number(w%item(i + 1)%s, x)) call md%mesh_type%put(w%item(2)%s, nint(x))
        end do
    end subroutine mesh

    !> fix ID group particletemplate/sphere seed atom_type T density constant rho radius constant r
    subroutine template(st, w, where)
        type(lmp_script), intent(inout) :: st
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        real(wp) :: x, r, rho
        integer :: i, t
        t = 1
        r = 1.0_wp
        rho = 1.0_wp
        do i = 6, w%n - 1
            select case (w%item(i)%s)
            case ('atom_type')
                if (text_number(w%item(i + 1)%s, x)) t = nint(x)
            case ('density', 'radius')
                if (i + 2 > w%n) cycle
                if (w%item(i + 1)%s /= 'constant') then
                    call st%note(where, 'particletemplate/sphere ' // w%item(i)%s // ' ' // w%item(i + 1)%s // &
                                       ': only constant is read')
                else if (text_number(w%item(i + 2)%s, x)) then
                    if (w%item(i)%s == 'radius') r = x
                    if (w%item(i)%s == 'density') rho = x
                end if
            case ('relative')
                if (w%item(i + 1)%s == 'yes') call st%note(where, 'particletemplate/sphere relative yes: ' // &
                                                                 'the radius is relative; read as absolute')
            case default
            end select
        end do
        call lmp_add_size(st, t, 2.0_wp * r, rho, 'particletemplate/sphere ' // w%item(2)%s // ' (' // where // ')')
    end subroutine template

    ! ------------------------------------------------------------------ contacts

    subroutine contacts(st, md, scene)
        type(lmp_script), intent(inout) :: st
        type(liggghts_model), intent(inout) :: md
        type(peer_scene), intent(inout) :: scene
        integer, allocatable :: types(:)
        integer :: a, b, k, j
        type(peer_contact) :: c
        call lmp_active_types(st, 'no particle template or created atom: every type is checked', types)
        do a = 1, size(types)
            do b = a, size(types)
                c%pair = itoa(types(a)) // '-' // itoa(types(b))
                c%where = md%pair_where
                call contact_words(st, md, md%pair_words, md%pair_problem, types(a), types(b), .false., c)
                call scene%add_contact(c)
            end do
        end do
        do k = 1, md%nwalls
            do a = 1, size(types)
                do j = 1, size(md%walls(k)%types)
                    c%pair = itoa(types(a)) // '-wall'
                    if (md%nwalls > 1) c%pair = c%pair // ':' // md%walls(k)%id
                    if (size(md%walls(k)%types) > 1) c%pair = c%pair // '/' // itoa(md%walls(k)%types(j))
                    c%where = md%walls(k)%where
                    call contact_words(st, md, md%walls(k)%model, '', types(a), md%walls(k)%types(j), .true., c)
                    call scene%add_contact(c)
                end do
            end do
        end do
    end subroutine contacts

    !> The contact of type i with type (or wall material) j in the LIGGGHTS reader's words.
    subroutine contact_words(st, md, model, problem, i, j, wall, c)
        type(lmp_script), intent(inout) :: st
        type(liggghts_model), intent(inout) :: md
        type(text_string), intent(in) :: model(:)
        character(len=*), intent(in) :: problem
        integer, intent(in) :: i, j
        logical, intent(in) :: wall
        type(peer_contact), intent(inout) :: c
        type(text_list) :: w
        character(len=:), allocatable :: s2
        integer :: k
        c%problem = problem
        c%mat%wall = wall
        call lmp_size(st, i, c%mat%radius(1), c%mat%density(1), c%sizes)
        c%mat%radius(2) = 0.0_wp
        c%mat%density(2) = 0.0_wp
        if (.not. wall) then
            call lmp_size(st, j, c%mat%radius(2), c%mat%density(2), s2)
            if (j /= i) c%sizes = c%sizes // '; ' // s2
        end if
        do k = 1, size(model)
            call w%push(model(k)%s)
        end do
        call per_type(md, 'youngsModulus', i, j, w, c%problem)
        call per_type(md, 'poissonsRatio', i, j, w, c%problem)
        call per_pair(md, 'coefficientRestitution', i, j, w, c%problem)
        if (index(' ' // join_words(model), ' model=hertz/stiffness') > 0) then
            call per_pair(md, 'kn', i, j, w, c%problem)
            call per_pair(md, 'gamman', i, j, w, c%problem)
        end if
        c%words = w%items()
    end subroutine contact_words

    function join_words(t) result(s)
        type(text_string), intent(in) :: t(:)
        character(len=:), allocatable :: s
        integer :: i
        s = ''
        do i = 1, size(t)
            s = s // ' ' // t(i)%s
        end do
    end function join_words

    !> name=v_i,v_j of a peratomtype property.
    subroutine per_type(md, name, i, j, w, problem)
        type(liggghts_model), intent(inout) :: md
        character(len=*), intent(in) :: name
        integer, intent(in) :: i, j
        type(text_list), intent(inout) :: w
        character(len=:), allocatable, intent(inout) :: problem
        integer :: k
        k = md%prop_index%get(name)
        if (k == 0) then
            if (len(problem) == 0) problem = 'fix property/global ' // name // ' is missing'
            return
        end if
        associate (p => md%props(k))
            if (max(i, j) > size(p%v)) then
                if (len(problem) == 0) problem = 'property/global ' // name // ' (' // p%where // ') has ' // &
                                                 itoa(size(p%v)) // ' values, fewer than the atom types'
                return
            end if
            call w%push(name // '=' // text_shortest(p%v(i)) // ',' // text_shortest(p%v(j)))
        end associate
    end subroutine per_type

    !> name=v_ij of a peratomtypepair property (the N x N matrix, row by row).
    subroutine per_pair(md, name, i, j, w, problem)
        type(liggghts_model), intent(inout) :: md
        character(len=*), intent(in) :: name
        integer, intent(in) :: i, j
        type(text_list), intent(inout) :: w
        character(len=:), allocatable, intent(inout) :: problem
        integer :: k, n
        k = md%prop_index%get(name)
        if (k == 0) then
            if (len(problem) == 0) problem = 'fix property/global ' // name // ' is missing'
            return
        end if
        associate (p => md%props(k))
            n = p%n
            if (p%style == 'scalar' .and. size(p%v) == 1) then
                call w%push(name // '=' // text_shortest(p%v(1)))
            else if (n < max(i, j) .or. size(p%v) < n * n) then
                if (len(problem) == 0) problem = 'property/global ' // name // ' (' // p%where // '): not a ' // &
                                                 'peratomtypepair matrix covering types ' // itoa(i) // ' and ' // itoa(j)
            else
                call w%push(name // '=' // text_shortest(p%v((i - 1) * n + j)))
            end if
        end associate
    end subroutine per_pair

end module hertzdamp_check_liggghts_deck
