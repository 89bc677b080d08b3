!> A Yade Python script read into contacts (doc/peers.md sections 4 and 11), in its
!> common forms: numeric assignments `name = expr`; materials `FrictMat(young=...,
!> poisson=..., density=..., label=...)` (ViscElMat and CohFrictMat are read and reported:
!> not the Hertz-Mindlin law), appended with `O.materials.append(...)` or kept in a
!> variable; bodies `sphere(center, radius, material=...)`, `wall(...)`, `facet(...)`,
!> `facetBox(...)`, `box(...)` (utils., geom. prefixes), `SpherePack().makeCloud(...,
!> rMean=..., rRelFuzz=...)` with `toSimulation(material=...)`; the law
!> `Ip2_FrictMat_FrictMat_MindlinPhys(en=..., betan=..., vn=...)` (a number or
!> `MatchMaker(matches=((id1, id2, value), ...))`) with `Law2_ScGeom_MindlinPhys_Mindlin`;
!> the Ig2 functors' `hertzian=True`; `NewtonIntegrator(damping=...)` and `O.dt = ...`
!> (`PWaveTimeStep()` evaluated as Yade does: min r/sqrt(E/rho) over the spheres).
!> Statements that name these but cannot be evaluated are noted with file:line; other
!> Python statements are counted.
module hertzdamp_check_yade_deck
    use hertzdamp, only: hertzdamp_rk, HD_HOST_LAMMPS, HD_HOST_NONE
    use hertzdamp_check_model, only: PEER_YADE
    use hertzdamp_check_scene, only: peer_scene, peer_contact
    use hertzdamp_text_list, only: text_string, text_list
    use hertzdamp_text_parse, only: text_number, text_shortest, text_strip_quotes, text_words, text_directory, &
                                    word_char => text_name_char, text_is_name
    use hertzdamp_text_python, only: statements => text_py_statements, call_at => text_py_call_at, &
                                     call_args => text_py_call_args, kwarg => text_py_kwarg
    use hertzdamp_text_expr, only: text_vars, text_eval, SYNTAX_PYTHON
    use hertzdamp_text_file, only: text_read_lines, text_where
    use hertzdamp_text_format, only: itoa, fmt_short
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: nshape = 3          !! Wall, Facet, Box
    character(len=5), parameter :: shapes(nshape) = ['Wall ', 'Facet', 'Box  ']

    !> One material.
    type :: ymat
        character(len=:), allocatable :: kind, label, where
        real(wp) :: young = 1.0e9_wp, poisson = 0.25_wp, density = 1000.0_wp
        integer :: id = -1                     !! index in O.materials (-1: not appended)
        real(wp) :: rmin = 0.0_wp              !! smallest sphere radius (0: no sphere)
        logical :: walls(nshape) = .false.     !! used by walls of each shape
    end type ymat

    !> What the script defines.
    type :: yade_model
        type(text_vars) :: vars
        type(ymat), allocatable :: mats(:)
        integer :: nmats = 0, nappended = 0
        character(len=:), allocatable :: law_where, en, betan, vn     !! the Ip2 arguments (text)
        character(len=:), allocatable :: law_label, newton_label      !! their label= (attributes set later)
        character(len=:), allocatable :: dir                          !! the script's directory (ymport files)
        logical :: have_law = .false.
        logical :: hertzian(nshape) = .false.
        real(wp) :: damping = 0.2_wp           !! NewtonIntegrator damping (Yade's default)
        character(len=:), allocatable :: newton_where, dt_text, dt_where
        logical :: stiffness_stepper = .false.
        integer :: nother = 0                  !! statements not interpreted
        character(len=:), allocatable :: cloud_material   !! makeCloud waiting for toSimulation
        real(wp) :: cloud_rmin = 0.0_wp
    end type yade_model

    public :: read_yade_deck

contains

    !> Read Yade script files (in order) into a scene.
    subroutine read_yade_deck(paths, scene, msg)
        type(text_string), intent(in) :: paths(:)
        type(peer_scene), intent(out) :: scene
        character(len=:), allocatable, intent(out) :: msg
        type(yade_model) :: md
        type(text_list) :: lines, stmts, wheres
        integer :: f, i
        msg = ''
        scene%peer = PEER_YADE
        scene%units = 'SI'
        allocate (md%mats(8))
        md%law_where = ''
        md%en = ''
        md%betan = ''
        md%vn = ''
        md%newton_where = ''
        md%dt_text = ''
        md%dt_where = ''
        md%cloud_material = ''
        md%law_label = ''
        md%newton_label = ''
        do f = 1, size(paths)
            md%dir = text_directory(paths(f)%s)
            call text_read_lines(paths(f)%s, lines, msg, scene%work)
            if (len(msg) > 0) return
            call scene%files%push(paths(f)%s)
            call statements(lines, paths(f)%s, stmts, wheres)
            do i = 1, stmts%n
                call statement(scene, md, stmts%item(i)%s, wheres%item(i)%s)
            end do
        end do
        scene%work = scene%work + md%vars%map%probes
        if (md%nother > 0) call scene%note('', itoa(md%nother) // ' other Python statements (imports, engines, ' // &
                                           'plots, output, control flow) do not enter the contacts')
        call integrator(scene, md)
        call contacts(scene, md)
    end subroutine read_yade_deck

    !> One statement.
    subroutine statement(scene, md, s, where)
        type(peer_scene), intent(inout) :: scene
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: s, where
        integer :: k
        k = call_at(s, 'Ip2_FrictMat_FrictMat_MindlinPhys')
        if (k > 0) call law(scene, md, s, k, where)
        if (call_at(s, 'NewtonIntegrator') > 0) call newton(scene, md, s, where)
        if (index(s, 'GlobalStiffnessTimeStepper') > 0) md%stiffness_stepper = .true.
        call functors(scene, md, s, where)
        if (k > 0 .or. index(s, 'O.engines') > 0) return
        if (index(s, 'O.dt') == 1) then
            call time_step(md, s, where)
        else if (label_attribute(scene, md, s, where)) then
            continue
        else if (index(s, 'ymport.') > 0) then
            call ymport(scene, md, s, where)
        else if (index(s, 'Mat(') > 0 .or. index(s, 'O.materials.append') > 0) then
            call material(scene, md, s, where)
        else if (body_call(s) > 0) then
            call body(scene, md, s, where)
        else if (index(s, 'makeCloud') > 0 .or. index(s, 'toSimulation') > 0) then
            call cloud(scene, md, s, where)
        else if (.not. assignment(md, s)) then
            md%nother = md%nother + 1
        end if
    end subroutine statement

    !> name = expr with a numeric value: a variable.  False when not such a statement.
    logical function assignment(md, s) result(ok)
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: msg, name
        real(wp) :: x
        integer :: e
        ok = .false.
        e = index(s, '=')
        if (e < 2) return
        if (index('=<>!+-*/', s(e - 1:e - 1)) > 0) return
        if (e < len(s)) then
            if (s(e + 1:e + 1) == '=') return
        end if
        name = trim(s(1:e - 1))
        if (index(name, ',') > 0) then
            ok = tuple_assignment(md, name, s(e + 1:))
            return
        end if
        if (.not. text_is_name(name)) return
        call text_eval(trim(adjustl(s(e + 1:))), SYNTAX_PYTHON, md%vars, x, msg)
        if (len(msg) > 0) return
        call md%vars%set_num(name, x)
        ok = .true.
    end function assignment

    !> a, b, c = x, y, z (every value numeric).
    logical function tuple_assignment(md, lhs, rhs) result(ok)
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: lhs, rhs
        type(text_list) :: names, values, k2, v2
        real(wp) :: x
        integer :: i
        ok = .false.
        call call_args('(' // lhs // ')', 1, names, k2, v2)
        call call_args('(' // rhs // ')', 1, values, k2, v2)
        if (names%n /= values%n .or. names%n < 2) return
        do i = 1, names%n
            if (.not. text_is_name(names%item(i)%s)) return
        end do
        do i = 1, names%n
            call number_arg(md, values%item(i)%s, x, ok)
            if (.not. ok) return
            call md%vars%set_num(names%item(i)%s, x)
        end do
    end function tuple_assignment

    !> A number argument (a Python expression of the script's variables); ok false if not.
    subroutine number_arg(md, text, x, ok)
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: text
        real(wp), intent(inout) :: x
        logical, intent(out) :: ok
        character(len=:), allocatable :: msg
        real(wp) :: y
        call text_eval(text, SYNTAX_PYTHON, md%vars, y, msg)
        ok = len(msg) == 0
        if (ok) x = y
    end subroutine number_arg

    !> [name =] [O.materials.append(] KindMat(...) [)] | O.materials.append(name)
    subroutine material(scene, md, s, where)
        type(peer_scene), intent(inout) :: scene
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: s, where
        type(text_list) :: pos, keys, vals
        type(ymat) :: m
        type(ymat), allocatable :: tmp(:)
        integer :: k, e, i
        logical :: ok
        character(len=13), parameter :: kinds(5) = [character(len=13) :: 'FrictMat', 'ViscElMat', 'CohFrictMat', &
                                                     'ViscElCapMat', 'FrictViscoMat']
        k = 0
        do i = 1, size(kinds)
            k = call_at(s, trim(kinds(i)))
            if (k > 0) exit
        end do
        if (k == 0) then
            call append_existing(scene, md, s, where)
            return
        end if
        m%kind = trim(kinds(i))
        m%label = ''
        m%where = where
        call call_args(s, k, pos, keys, vals)
        call mat_number(kwarg(keys, vals, 'young'), m%young)
        call mat_number(kwarg(keys, vals, 'poisson'), m%poisson)
        call mat_number(kwarg(keys, vals, 'density'), m%density)
        m%label = text_strip_quotes(kwarg(keys, vals, 'label'))
        if (index(s, 'O.materials.append') > 0) then
            m%id = md%nappended
            md%nappended = md%nappended + 1
        end if
        if (md%nmats == size(md%mats)) then
            allocate (tmp(2 * size(md%mats)))
            tmp(1:md%nmats) = md%mats(1:md%nmats)
            call move_alloc(tmp, md%mats)
        end if
        md%nmats = md%nmats + 1
        md%mats(md%nmats) = m
        e = index(s, '=')
        if (e > 1 .and. e < k) then      ! name = ...: the name holds the material (or its id)
            call md%vars%set_text(trim(s(1:e - 1)), 'material:' // itoa(md%nmats))
            if (m%id >= 0) call md%vars%set_num(trim(s(1:e - 1)), real(m%id, wp))
        end if
    contains
        subroutine mat_number(text, x)
            character(len=*), intent(in) :: text
            real(wp), intent(inout) :: x
            if (len(text) == 0) return
            call number_arg(md, text, x, ok)
            if (.not. ok) call scene%note(where, m%kind // ': "' // text // '" is not evaluated')
        end subroutine mat_number
    end subroutine material

    !> O.materials.append(name) of a material kept in a variable.
    subroutine append_existing(scene, md, s, where)
        type(peer_scene), intent(inout) :: scene
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: s, where
        type(text_list) :: pos, keys, vals
        integer :: k, m
        k = call_at(s, 'append')
        if (k == 0) then
            call scene%note(where, 'material statement not interpreted: ' // s)
            return
        end if
        call call_args(s, k, pos, keys, vals)
        m = 0
        if (pos%n == 1) m = material_of(md, pos%item(1)%s)
        if (m == 0) then
            call scene%note(where, 'O.materials.append: material not read: ' // s)
            return
        end if
        md%mats(m)%id = md%nappended
        md%nappended = md%nappended + 1
    end subroutine append_existing

    !> The material an argument names: a variable holding one (or its id), an id, a label,
    !> -1 or absent (the last appended; Yade's defaultMaterial() when none).  0: unknown.
    integer function material_of(md, arg0) result(m)
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: arg0
        character(len=:), allocatable :: arg
        real(wp) :: x
        logical :: ok
        integer :: i, id
        m = 0
        arg = trim(adjustl(arg0))
        if (len(arg) == 0) arg = '-1'
        i = md%vars%find(arg)
        if (i > 0) then
            if (index(md%vars%text(i)%s, 'material:') == 1) then
                read (md%vars%text(i)%s(10:), *) m
                return
            end if
        end if
        if (arg(1:1) == '''' .or. arg(1:1) == '"') then
            do i = 1, md%nmats
                if (md%mats(i)%label == text_strip_quotes(arg) .and. md%mats(i)%id >= 0) m = i
            end do
            return
        end if
        x = -999.0_wp
        call number_arg(md, arg, x, ok)
        if (.not. ok) return
        id = nint(x)
        if (id < 0) id = md%nappended + id
        if (id < 0) then           ! no material at all: utils.defaultMaterial()
            call default_material(md)
            id = 0
        end if
        do i = 1, md%nmats
            if (md%mats(i)%id == id) m = i
        end do
    end function material_of

    !> FrictMat(density=1e3, young=1e7, poisson=.3, frictionAngle=.5, label='defaultMat') (utils.py).
    subroutine default_material(md)
        type(yade_model), intent(inout) :: md
        type(ymat) :: m
        m%kind = 'FrictMat'
        m%label = 'defaultMat'
        m%where = 'utils.defaultMaterial()'
        m%young = 1.0e7_wp
        m%poisson = 0.3_wp
        m%density = 1.0e3_wp
        m%id = md%nappended
        md%nappended = md%nappended + 1
        md%nmats = md%nmats + 1
        md%mats(md%nmats) = m
    end subroutine default_material

    !> Which body-creating call s holds (1 sphere, 2 wall, 3 facet, 4 box), 0: none.
    pure integer function body_call(s) result(kind)
        character(len=*), intent(in) :: s
        kind = 0
        if (call_at(s, 'sphere') > 0) kind = 1
        if (call_at(s, 'wall') > 0) kind = 2
        if (call_at(s, 'facet') > 0 .or. call_at(s, 'facetBox') > 0 .or. call_at(s, 'facetCylinder') > 0) kind = 3
        if (call_at(s, 'box') > 0) kind = 4
    end function body_call

    !> sphere(center, radius, material=...) | wall(..., material=...) | facet... | box...
    subroutine body(scene, md, s, where)
        type(peer_scene), intent(inout) :: scene
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: s, where
        type(text_list) :: pos, keys, vals
        integer :: kind, k, m
        real(wp) :: r
        logical :: ok
        character(len=:), allocatable :: name
        kind = body_call(s)
        select case (kind)
        case (1); name = 'sphere'
        case (2); name = 'wall'
        case (3)
            name = 'facet'
            if (call_at(s, 'facetBox') > 0) name = 'facetBox'
            if (call_at(s, 'facetCylinder') > 0) name = 'facetCylinder'
        case default; name = 'box'
        end select
        k = call_at(s, name)
        call call_args(s, k, pos, keys, vals)
        m = material_of(md, kwarg(keys, vals, 'material'))
        if (m == 0) then
            call scene%note(where, name // ': material "' // kwarg(keys, vals, 'material') // '" not read')
            return
        end if
        if (kind /= 1) then
            md%mats(m)%walls(kind - 1) = .true.
            return
        end if
        r = 0.0_wp
        ok = pos%n >= 2
        if (ok) call number_arg(md, pos%item(2)%s, r, ok)
        if (.not. ok .and. len(kwarg(keys, vals, 'radius')) > 0) call number_arg(md, kwarg(keys, vals, 'radius'), r, ok)
        if (.not. ok .or. .not. r > 0.0_wp) then
            call scene%note(where, 'sphere: the radius is not evaluated (a loop variable or a random number?)')
            return
        end if
        if (md%mats(m)%rmin <= 0.0_wp .or. r < md%mats(m)%rmin) md%mats(m)%rmin = r
    end subroutine body

    !> sp.makeCloud(..., rMean=r, rRelFuzz=f) and sp.toSimulation(material=...).
    subroutine cloud(scene, md, s, where)
        type(peer_scene), intent(inout) :: scene
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: s, where
        type(text_list) :: pos, keys, vals
        real(wp) :: r, f
        logical :: ok, ok2
        integer :: m
        if (call_at(s, 'makeCloud') > 0) then
            call call_args(s, call_at(s, 'makeCloud'), pos, keys, vals)
            r = 0.0_wp
            f = 0.0_wp
            call number_arg(md, kwarg(keys, vals, 'rMean'), r, ok)
            if (len(kwarg(keys, vals, 'rRelFuzz')) > 0) call number_arg(md, kwarg(keys, vals, 'rRelFuzz'), f, ok2)
            if (ok .and. r > 0.0_wp) then
                md%cloud_rmin = r * (1.0_wp - f)
            else
                call scene%note(where, 'makeCloud: rMean not read (psdSizes and the default rMean are not read)')
            end if
        end if
        if (call_at(s, 'toSimulation') > 0) then
            call call_args(s, call_at(s, 'toSimulation'), pos, keys, vals)
            m = material_of(md, kwarg(keys, vals, 'material'))
            if (m == 0 .or. md%cloud_rmin <= 0.0_wp) then
                call scene%note(where, 'toSimulation: the material or the cloud''s radii are not read')
            else if (md%mats(m)%rmin <= 0.0_wp .or. md%cloud_rmin < md%mats(m)%rmin) then
                md%mats(m)%rmin = md%cloud_rmin
            end if
        end if
    end subroutine cloud

    !> Ip2_FrictMat_FrictMat_MindlinPhys(en=..., betan=..., vn=...).
    subroutine law(scene, md, s, k, where)
        type(peer_scene), intent(inout) :: scene
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: s, where
        integer, intent(in) :: k
        type(text_list) :: pos, keys, vals
        call call_args(s, k, pos, keys, vals)
        md%have_law = .true.
        md%law_where = where
        md%en = kwarg(keys, vals, 'en')
        md%betan = kwarg(keys, vals, 'betan')
        md%vn = kwarg(keys, vals, 'vn')
        md%law_label = text_strip_quotes(kwarg(keys, vals, 'label'))
        if (index(s, 'Law2_ScGeom_MindlinPhys_Mindlin') == 0) call scene%note(where, &
            'Ip2_FrictMat_FrictMat_MindlinPhys without Law2_ScGeom_MindlinPhys_Mindlin in the same statement: ' // &
            'the checker assumes that law')
        if (index(s, 'includeAdhesion=True') > 0) call scene%note(where, 'includeAdhesion=True: the adhesion ' // &
            'force is not modeled (the force end differs)')
    end subroutine law

    !> Ig2 functors' hertzian flags; other contact laws.
    subroutine functors(scene, md, s, where)
        type(peer_scene), intent(inout) :: scene
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: s, where
        integer :: i, k
        character(len=*), parameter :: ig2(nshape) = [character(len=24) :: 'Ig2_Wall_Sphere_ScGeom', &
                                                      'Ig2_Facet_Sphere_ScGeom', 'Ig2_Box_Sphere_ScGeom']
        type(text_list) :: pos, keys, vals
        do i = 1, nshape
            k = call_at(s, trim(ig2(i)))
            if (k == 0) cycle
            call call_args(s, k, pos, keys, vals)
            md%hertzian(i) = kwarg(keys, vals, 'hertzian') == 'True'
        end do
        if (index(s, 'Law2_ScGeom_FrictPhys_CundallStrack') > 0 .or. index(s, 'Law2_ScGeom_ViscElPhys_Basic') > 0) then
            call scene%note(where, 'a linear contact law (CundallStrack or ViscElPhys) is in the engines: its ' // &
                            'contacts are not Hertz contacts and are not checked')
        end if
    end subroutine functors

    !> NewtonIntegrator(damping=...): Cundall's non-viscous damping (default 0.2).
    subroutine newton(scene, md, s, where)
        type(peer_scene), intent(inout) :: scene
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: s, where
        type(text_list) :: pos, keys, vals
        logical :: ok
        call call_args(s, call_at(s, 'NewtonIntegrator'), pos, keys, vals)
        md%newton_where = where
        md%newton_label = text_strip_quotes(kwarg(keys, vals, 'label'))
        md%damping = 0.2_wp
        if (len(kwarg(keys, vals, 'damping')) > 0) then
            call number_arg(md, kwarg(keys, vals, 'damping'), md%damping, ok)
            if (.not. ok) call scene%note(where, 'NewtonIntegrator damping is not evaluated')
        end if
    end subroutine newton

    !> LABEL.attr = value for the Ip2 functor's label (en, betan, vn) or the
    !> NewtonIntegrator's (damping), as Yade's examples set them after O.engines.
    logical function label_attribute(scene, md, s, where) result(done)
        type(peer_scene), intent(inout) :: scene
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: s, where
        character(len=:), allocatable :: lhs, obj, attr, rhs
        integer :: e, d
        logical :: ok
        done = .false.
        e = index(s, '=')
        if (e < 2) return
        lhs = trim(s(1:e - 1))
        d = index(lhs, '.')
        if (d < 2) return
        obj = lhs(1:d - 1)
        attr = lhs(d + 1:)
        rhs = trim(adjustl(s(e + 1:)))
        if (len(md%law_label) > 0 .and. obj == md%law_label) then
            done = .true.
            select case (attr)
            case ('en'); md%en = rhs
            case ('betan'); md%betan = rhs
            case ('vn'); md%vn = rhs
            case ('betas', 'es', 'useDamping', 'krot', 'ktwist', 'eta', 'gamma', 'frictAngle')
            case default
                call scene%note(where, lhs // ': attribute not interpreted')
            end select
            md%law_where = where
        else if (len(md%newton_label) > 0 .and. obj == md%newton_label) then
            done = .true.
            if (attr == 'damping') then
                call number_arg(md, rhs, md%damping, ok)
                if (.not. ok) call scene%note(where, lhs // ' = ' // rhs // ' is not evaluated')
                md%newton_where = where
            end if
        end if
    end function label_attribute

    !> ymport.text(file, material=...) (spheres x y z r: the radii are read from the file
    !> when it exists) and ymport.textFacets / stl / gmsh (facet walls).
    subroutine ymport(scene, md, s, where)
        type(peer_scene), intent(inout) :: scene
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: s, where
        type(text_list) :: pos, keys, vals, lines, w
        character(len=:), allocatable :: path, msg
        real(wp) :: r, rmin
        integer :: k, m, i
        logical :: facets
        facets = call_at(s, 'textFacets') > 0 .or. call_at(s, 'stl') > 0 .or. call_at(s, 'gmsh') > 0
        k = call_at(s, 'text')
        if (facets) k = max(call_at(s, 'textFacets'), call_at(s, 'stl'), call_at(s, 'gmsh'))
        if (k == 0) then
            call scene%note(where, 'ymport call not interpreted')
            return
        end if
        call call_args(s, k, pos, keys, vals)
        m = material_of(md, kwarg(keys, vals, 'material'))
        if (m == 0) then
            call scene%note(where, 'ymport: material "' // kwarg(keys, vals, 'material') // '" not read')
            return
        end if
        if (facets) then
            md%mats(m)%walls(2) = .true.
            return
        end if
        path = ''
        if (pos%n >= 1) path = text_strip_quotes(pos%item(1)%s)
        if (len(path) > 0) then
            if (path(1:1) /= '/') path = md%dir // path
        end if
        call text_read_lines(path, lines, msg, scene%work)
        if (len(msg) > 0) then
            call scene%note(where, 'ymport.text: ' // msg // ' (the spheres'' radii are in it)')
            return
        end if
        rmin = huge(1.0_wp)
        do i = 1, lines%n
            w%n = 0
            call text_words(lines%item(i)%s, w)
            if (w%n < 4) cycle
            if (text_number(w%item(4)%s, r)) rmin = min(rmin, r)
        end do
        if (rmin < huge(1.0_wp)) then
            if (md%mats(m)%rmin <= 0.0_wp .or. rmin < md%mats(m)%rmin) md%mats(m)%rmin = rmin
        else
            call scene%note(where, 'ymport.text ' // path // ': no line "x y z r"')
        end if
    end subroutine ymport

    !> O.dt = expr (PWaveTimeStep() evaluated at the end).
    subroutine time_step(md, s, where)
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: s, where
        integer :: e
        e = index(s, '=')
        if (e == 0) return
        md%dt_text = trim(adjustl(s(e + 1:)))
        md%dt_where = where
    end subroutine time_step

    !> The host scheme: Yade's NewtonIntegrator is a leapfrog (vel += dt a; pos += dt vel,
    !> NewtonIntegrator.cpp), the same sequence as LAMMPS's velocity Verlet; Cundall's
    !> damping (damping > 0) is not modeled.  The time step O.dt.
    subroutine integrator(scene, md)
        type(peer_scene), intent(inout) :: scene
        type(yade_model), intent(inout) :: md
        character(len=:), allocatable :: t, msg
        real(wp) :: x
        integer :: i, k
        if (md%damping == 0.0_wp) then
            scene%host = HD_HOST_LAMMPS
            scene%host_text = 'NewtonIntegrator(damping=0) (' // md%newton_where // '): leapfrog, vel += dt F/m then ' // &
                              'pos += dt vel (NewtonIntegrator.cpp), the sequence of LAMMPS''s velocity Verlet'
        else
            scene%host = HD_HOST_NONE
            t = 'Yade''s default'
            if (len(md%newton_where) > 0) t = md%newton_where
            scene%host_text = 'NewtonIntegrator damping = ' // fmt_short(md%damping) // ' (' // t // &
                              '): Cundall''s non-viscous damping also dissipates in every contact; not modeled'
        end if
        if (md%stiffness_stepper) then
            scene%dt_text = 'GlobalStiffnessTimeStepper changes O.dt during the run; not modeled'
            return
        end if
        t = md%dt_text
        if (len(t) == 0) then
            scene%dt_text = 'no O.dt = ... in the script'
            return
        end if
        k = index(t, 'PWaveTimeStep()')
        if (k > 0) then
            i = k
            do while (i > 1)
                if (.not. (word_char(t(i - 1:i - 1)) .or. t(i - 1:i - 1) == '.')) exit
                i = i - 1
            end do
            t = t(1:i - 1) // text_shortest(pwave(md)) // t(k + len('PWaveTimeStep()'):)
        end if
        call text_eval(t, SYNTAX_PYTHON, md%vars, x, msg)
        if (len(msg) == 0 .and. x > 0.0_wp) then
            scene%dt = x
            scene%dt_text = 'O.dt = ' // md%dt_text // ' (' // md%dt_where // ')'
        else
            scene%dt_text = 'O.dt = ' // md%dt_text // ' (' // md%dt_where // ') is not evaluated'
        end if
    end subroutine integrator

    !> Yade's PWaveTimeStep(): min over the spheres of r / sqrt(E/rho) (Shop_01.cpp).
    real(wp) function pwave(md) result(dt)
        type(yade_model), intent(in) :: md
        integer :: i
        dt = huge(1.0_wp)
        do i = 1, md%nmats
            if (md%mats(i)%rmin > 0.0_wp) dt = min(dt, md%mats(i)%rmin / sqrt(md%mats(i)%young / md%mats(i)%density))
        end do
        if (dt == huge(1.0_wp)) dt = 1.0_wp
    end function pwave

    ! ------------------------------------------------------------------ contacts

    subroutine contacts(scene, md)
        type(peer_scene), intent(inout) :: scene
        type(yade_model), intent(inout) :: md
        integer :: a, b, sh
        if (.not. md%have_law) call scene%note('', 'no Ip2_FrictMat_FrictMat_MindlinPhys: the checker reads ' // &
                                               'Yade''s Hertz-Mindlin law only')
        do a = 1, md%nmats
            if (md%mats(a)%rmin <= 0.0_wp) cycle
            do b = a, md%nmats
                if (md%mats(b)%rmin > 0.0_wp) call contact(scene, md, a, b, 0)
            end do
            do b = 1, md%nmats
                do sh = 1, nshape
                    if (md%mats(b)%walls(sh)) call contact(scene, md, a, b, sh)
                end do
            end do
        end do
    end subroutine contacts

    !> Material a's spheres with material b's spheres (shape 0) or walls of a shape.
    subroutine contact(scene, md, a, b, shape)
        type(peer_scene), intent(inout) :: scene
        type(yade_model), intent(inout) :: md
        integer, intent(in) :: a, b, shape
        type(peer_contact) :: c
        type(text_list) :: w
        c%pair = name_of(md, a) // '-' // name_of(md, b)
        if (shape > 0) c%pair = name_of(md, a) // '-' // trim(shapes(shape)) // ':' // name_of(md, b)
        c%where = md%mats(a)%where
        c%problem = ''
        if (md%mats(a)%kind /= 'FrictMat' .or. md%mats(b)%kind /= 'FrictMat') c%problem = md%mats(a)%kind // &
            ' with ' // md%mats(b)%kind // ': not the Hertz-Mindlin law of FrictMat (ViscElMat is a linear spring)'
        if (.not. md%have_law .and. len(c%problem) == 0) c%problem = 'no Ip2_FrictMat_FrictMat_MindlinPhys in the script'
        call w%push('young=' // text_shortest(md%mats(a)%young) // ',' // text_shortest(md%mats(b)%young))
        call w%push('poisson=' // text_shortest(md%mats(a)%poisson) // ',' // text_shortest(md%mats(b)%poisson))
        call damping_words(md, a, b, w, c%problem)
        c%mat%radius = [md%mats(a)%rmin, md%mats(b)%rmin]
        c%mat%density = [md%mats(a)%density, md%mats(b)%density]
        c%sizes = 'material ' // name_of(md, a) // ': smallest radius ' // fmt_short(md%mats(a)%rmin) // &
                  ', density ' // fmt_short(md%mats(a)%density)
        if (shape > 0) then
            c%mat%wall = .true.
            c%mat%radius(2) = 0.0_wp
            c%mat%density(2) = 0.0_wp
            call w%push('shape=' // trim(shapes(shape)))
            if (md%hertzian(shape)) call w%push('hertzian=True')
        else if (b /= a) then
            c%sizes = c%sizes // '; material ' // name_of(md, b) // ': smallest radius ' // fmt_short(md%mats(b)%rmin) // &
                      ', density ' // fmt_short(md%mats(b)%density)
        end if
        c%words = w%items()
        call scene%add_contact(c)
    end subroutine contact

    function name_of(md, m) result(s)
        type(yade_model), intent(in) :: md
        integer, intent(in) :: m
        character(len=:), allocatable :: s
        if (len(md%mats(m)%label) > 0) then
            s = md%mats(m)%label
        else if (md%mats(m)%id >= 0) then
            s = itoa(md%mats(m)%id)
        else
            s = 'mat' // itoa(m)
        end if
    end function name_of

    !> en=/betan=/vn= of the pair of materials (a number, or a MatchMaker's match).
    subroutine damping_words(md, a, b, w, problem)
        type(yade_model), intent(inout) :: md
        integer, intent(in) :: a, b
        type(text_list), intent(inout) :: w
        character(len=:), allocatable, intent(inout) :: problem
        character(len=:), allocatable :: v
        if (len(md%en) > 0) then
            v = match(md, md%en, a, b)
            if (len(v) == 0 .and. len(problem) == 0) problem = 'en = ' // md%en // ' (' // md%law_where // &
                                                               ') is not evaluated for this pair'
            call w%push('en=' // v)
        else if (len(md%betan) > 0) then
            v = match(md, md%betan, a, b)
            if (len(v) == 0 .and. len(problem) == 0) problem = 'betan = ' // md%betan // ' (' // md%law_where // &
                                                               ') is not evaluated for this pair'
            call w%push('betan=' // v)
        else if (md%have_law .and. len(problem) == 0) then
            problem = 'neither en nor betan: Yade''s Hertz-Mindlin contact is undamped (betan = 0)'
        end if
        if (len(md%vn) > 0) then
            v = match(md, md%vn, a, b)
            if (len(v) > 0) call w%push('vn=' // v)
            if (len(v) == 0 .and. len(problem) == 0) problem = 'vn = ' // md%vn // ' is not evaluated'
        end if
    end subroutine damping_words

    !> A MatchMaker-valued argument for materials (a, b): a number, or the value of
    !> matches=((id1, id2, v), ...) for the pair's ids ('' when not found).
    function match(md, text, a, b) result(v)
        type(yade_model), intent(inout) :: md
        character(len=*), intent(in) :: text
        integer, intent(in) :: a, b
        character(len=:), allocatable :: v
        type(text_list) :: pos, keys, vals, tri, p2, k2, v2
        real(wp) :: x, i1, i2
        logical :: ok
        integer :: i, k
        v = ''
        call number_arg(md, text, x, ok)
        if (ok) then
            v = text_shortest(x)
            return
        end if
        k = call_at(text, 'MatchMaker')
        if (k == 0) return
        call call_args(text, k, pos, keys, vals)
        tri%n = 0
        if (len(kwarg(keys, vals, 'matches')) < 2) return
        call call_args(kwarg(keys, vals, 'matches'), 1, tri, k2, v2)
        do i = 1, tri%n
            call call_args(tri%item(i)%s, 1, p2, k2, v2)
            if (p2%n /= 3) cycle
            i1 = -1.0_wp
            i2 = -1.0_wp
            call number_arg(md, p2%item(1)%s, i1, ok)
            call number_arg(md, p2%item(2)%s, i2, ok)
            if ((nint(i1) == md%mats(a)%id .and. nint(i2) == md%mats(b)%id) .or. &
                (nint(i2) == md%mats(a)%id .and. nint(i1) == md%mats(b)%id)) then
                call number_arg(md, p2%item(3)%s, x, ok)
                if (ok) v = text_shortest(x)
            end if
        end do
    end function match

end module hertzdamp_check_yade_deck
