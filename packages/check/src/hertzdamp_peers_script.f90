!> The input-script language LAMMPS and LIGGGHTS share, read the way the engine reads
!> it: one command per line, `&` at the end of a line continues it, `#` starts a comment
!> (outside quotes), `include` reads another file in place, `variable` defines names
!> (index, loop, world, universe, uloop, string, internal, equal), `${name}`, `$x` and
!> `$(expr)` are substituted before the words are split (not inside quotes), and quotes
!> group words.  The commands every contact depends on are interpreted here: units,
!> dimension, timestep, create_box, create_atoms, set (type and group all: diameter,
!> density, mass), read_data (not read: noted) and the integrator fixes; commands that
!> cannot change a normal contact are read and passed over.  Every other command is
!> handed to the engine's reader (`script_next`), which notes what it cannot interpret.
!>
!> The work is linear in the deck: each line is scanned a bounded number of times and
!> every name lookup is a hash-map probe (counted in scene%work).
module hertzdamp_peers_script
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_peers, only: peer_text
    use hertzdamp_peers_text, only: peer_list, peer_vars, peer_words, peer_eval, peer_number, peer_num_text, &
                                    peer_g15, peer_directory, SYNTAX_LAMMPS
    use hertzdamp_peers_scene, only: peer_scene, peer_read_lines, peer_where
    use hertzdamp_peers_common, only: join
    use hertzdamp_host, only: HD_HOST_NONE, HD_HOST_LAMMPS
    use hertzdamp_apps_text, only: itoa, fmt_short
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: max_depth = 20      !! include nesting limit

    !> One open file.
    type :: script_file
        character(len=:), allocatable :: name
        type(peer_list) :: lines
        integer :: next = 1
    end type script_file

    !> The interpreter's state: the scene being filled, variables, open files, atom types.
    type, public :: peer_script
        type(peer_scene) :: scene
        type(peer_vars) :: vars
        type(script_file) :: stack(max_depth)
        integer :: depth = 0
        integer :: ntypes = 0                    !! create_box
        real(wp), allocatable :: diam(:)         !! smallest diameter of each type (<= 0: none known)
        real(wp), allocatable :: dens(:)         !! lowest density of each type (<= 0: none known)
        real(wp), allocatable :: mass(:)         !! set type N mass (<= 0: none)
        logical, allocatable :: atoms(:)         !! the type has atoms (created, poured, ...)
        type(peer_text), allocatable :: src(:)   !! where each type's sizes come from
        integer :: dimension = 3
        logical :: liggghts = .false.            !! LIGGGHTS (communicate, atom_style granular)
        logical :: have_dt = .false.
        logical :: have_integrator = .false.
    end type peer_script

    public :: script_open, script_next, script_types, script_type_range, script_size, script_add_size

contains

    !> Start reading the deck files (read in order, as if included one after another).
    subroutine script_open(st, paths, liggghts, msg)
        type(peer_script), intent(inout) :: st
        type(peer_text), intent(in) :: paths(:)
        logical, intent(in) :: liggghts
        character(len=:), allocatable, intent(out) :: msg
        integer :: i
        msg = ''
        st%liggghts = liggghts
        st%scene%units = 'lj'
        st%scene%dt_text = ''
        st%scene%host = HD_HOST_NONE
        st%scene%host_text = 'no fix nve/sphere: the particles are not integrated'
        allocate (st%diam(0), st%dens(0), st%mass(0), st%atoms(0), st%src(0))
        ! the files are a stack: the first on top
        do i = size(paths), 1, -1
            call push_file(st, paths(i)%s, '', msg)
            if (len(msg) > 0) return
        end do
    end subroutine script_open

    subroutine push_file(st, path, where, msg)
        type(peer_script), intent(inout) :: st
        character(len=*), intent(in) :: path, where
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: m
        logical :: found
        if (st%depth == max_depth) then
            msg = where // ': include nested deeper than ' // itoa(max_depth) // ' files'
            return
        end if
        st%depth = st%depth + 1
        st%stack(st%depth)%name = path
        st%stack(st%depth)%next = 1
        ! an include is looked up beside the file that includes it, then in the working directory
        if (st%depth > 1 .and. len(path) > 0) then
            if (path(1:1) /= '/') then
                inquire (file=peer_directory(st%stack(st%depth - 1)%name) // path, exist=found)
                if (found) st%stack(st%depth)%name = peer_directory(st%stack(st%depth - 1)%name) // path
            end if
        end if
        call peer_read_lines(st%stack(st%depth)%name, st%stack(st%depth)%lines, m, st%scene%work)
        if (len(m) > 0) then
            st%depth = st%depth - 1
            msg = m
            if (len(where) > 0) msg = where // ': include ' // m
            return
        end if
        call st%scene%files%push(st%stack(st%depth)%name)
    end subroutine push_file

    !> The next logical line (continuations joined), with the file:line of its start.
    subroutine next_line(st, line, where, more)
        type(peer_script), intent(inout) :: st
        character(len=:), allocatable, intent(out) :: line, where
        logical, intent(out) :: more
        character(len=:), allocatable :: t
        integer :: k
        type(peer_list) :: parts
        more = .false.
        line = ''
        where = ''
        do while (st%depth > 0)
            if (st%stack(st%depth)%next > st%stack(st%depth)%lines%n) then
                st%depth = st%depth - 1
                cycle
            end if
            exit
        end do
        if (st%depth == 0) return
        more = .true.
        associate (f => st%stack(st%depth))
            where = peer_where(f%name, f%next)
            do while (f%next <= f%lines%n)
                t = f%lines%item(f%next)%s
                f%next = f%next + 1
                k = len_trim(t)
                if (k == 0) exit
                if (t(k:k) /= '&') then
                    call parts%push(t(1:k))
                    exit
                end if
                call parts%push(t(1:k - 1))
            end do
        end associate
        line = join(parts%items())
    end subroutine next_line

    !> The next command the engine's reader has to interpret: its words (quotes removed)
    !> and file:line; `more` false at the end of the deck.  Common commands are
    !> interpreted on the way (see the module).
    subroutine script_next(st, words, where, more)
        type(peer_script), intent(inout) :: st
        type(peer_list), intent(out) :: words
        character(len=:), allocatable, intent(out) :: where
        logical, intent(out) :: more
        character(len=:), allocatable :: line, text
        logical :: handled
        do
            call next_line(st, line, where, more)
            if (.not. more) return
            call strip_comment(line)
            if (len_trim(line) == 0) cycle
            call substitute(st, line, where, text, handled)
            if (handled) cycle            ! a substitution failed: noted
            call peer_words(text, words, quotes=.true.)
            st%scene%work = st%scene%work + len(text) + words%n
            if (words%n == 0) cycle
            call common_command(st, words, where, handled)
            if (.not. handled) return
            words%n = 0
        end do
    end subroutine script_next

    !> Cut the line at the first # outside quotes.
    subroutine strip_comment(line)
        character(len=:), allocatable, intent(inout) :: line
        character :: q
        integer :: i
        q = ' '
        do i = 1, len(line)
            if (q /= ' ') then
                if (line(i:i) == q) q = ' '
            else if (line(i:i) == '"' .or. line(i:i) == '''') then
                q = line(i:i)
            else if (line(i:i) == '#') then
                line = line(1:i - 1)
                return
            end if
        end do
    end subroutine strip_comment

    !> ${name}, $x and $(expr) replaced outside quotes; `failed` when a name has no
    !> value (the command is noted and skipped, as LAMMPS would stop there).
    subroutine substitute(st, line, where, out, failed)
        type(peer_script), intent(inout) :: st
        character(len=*), intent(in) :: line, where
        character(len=:), allocatable, intent(out) :: out
        logical, intent(out) :: failed
        type(peer_list) :: parts
        character(len=:), allocatable :: name, val, msg
        character :: q
        integer :: i, j, start
        failed = .false.
        q = ' '
        start = 1
        i = 1
        do while (i <= len(line))
            if (q /= ' ') then
                if (line(i:i) == q) q = ' '
            else if (line(i:i) == '"' .or. line(i:i) == '''') then
                q = line(i:i)
            else if (line(i:i) == '$' .and. i < len(line)) then
                call parts%push(line(start:i - 1))
                call reference(line, i, name, j)
                call variable_text(st, line(i + 1:i + 1), name, val, msg)
                if (len(msg) > 0) then
                    call st%scene%note(where, msg // ': the command is not interpreted')
                    failed = .true.
                    return
                end if
                call parts%push(val)
                start = j + 1
                i = j
            end if
            i = i + 1
        end do
        call parts%push(line(start:))
        out = join_plain(parts)
    end subroutine substitute

    !> The text of a list without separators (linear).
    function join_plain(parts) result(s)
        type(peer_list), intent(in) :: parts
        character(len=:), allocatable :: s
        integer :: i, n, k
        n = 0
        do i = 1, parts%n
            n = n + len(parts%item(i)%s)
        end do
        allocate (character(len=n) :: s)
        k = 0
        do i = 1, parts%n
            s(k + 1:k + len(parts%item(i)%s)) = parts%item(i)%s
            k = k + len(parts%item(i)%s)
        end do
    end function join_plain

    !> The reference starting at line(i) = '$': its name (or expression) and last index j.
    subroutine reference(line, i, name, j)
        character(len=*), intent(in) :: line
        integer, intent(in) :: i
        character(len=:), allocatable, intent(out) :: name
        integer, intent(out) :: j
        character :: lb, rb
        integer :: depth
        lb = line(i + 1:i + 1)
        if (lb /= '{' .and. lb /= '(') then
            name = lb
            j = i + 1
            return
        end if
        rb = merge('}', ')', lb == '{')
        depth = 0
        do j = i + 1, len(line)
            if (line(j:j) == lb) depth = depth + 1
            if (line(j:j) == rb) depth = depth - 1
            if (depth == 0) exit
        end do
        if (j > len(line)) j = len(line)
        name = line(i + 2:j - 1)
        if (line(j:j) /= rb) name = line(i + 2:j)
    end subroutine reference

    !> The value a reference substitutes: `kind` '{' or a letter: a variable; '(': an
    !> immediate expression (an optional :format is dropped; full precision).
    subroutine variable_text(st, kind, name, val, msg)
        type(peer_script), intent(inout) :: st
        character(len=*), intent(in) :: kind, name
        character(len=:), allocatable, intent(out) :: val, msg
        real(wp) :: x
        integer :: i, k
        msg = ''
        val = ''
        if (kind == '(') then
            k = index(name, ':', back=.true.)
            if (k == 0) k = len(name) + 1
            call peer_eval(name(1:k - 1), SYNTAX_LAMMPS, st%vars, x, msg)
            if (len(msg) == 0) val = peer_num_text(x)
            if (len(msg) > 0) msg = '$(' // name // '): ' // msg
            return
        end if
        i = st%vars%find(name)
        st%scene%work = st%scene%work + 1
        if (i == 0) then
            msg = 'variable ' // name // ' is not defined'
        else if (st%vars%numeric(i) .and. len(st%vars%text(i)%s) == 0) then
            val = peer_g15(st%vars%x(i))      ! an equal-style value, as LAMMPS's "%.15g"
        else if (index(st%vars%text(i)%s, 'no value:') == 1) then
            msg = 'variable ' // name // ' has ' // st%vars%text(i)%s
        else
            val = st%vars%text(i)%s
        end if
    end subroutine variable_text


    !> The commands interpreted for every engine; handled false for the others.
    subroutine common_command(st, w, where, handled)
        type(peer_script), intent(inout) :: st
        type(peer_list), intent(in) :: w
        character(len=*), intent(in) :: where
        logical, intent(out) :: handled
        character(len=:), allocatable :: msg
        handled = .true.
        msg = ''
        select case (w%item(1)%s)
        case ('include')
            if (w%n < 2) then
                call st%scene%note(where, 'include without a file name')
            else
                call push_file(st, w%item(2)%s, where, msg)
                if (len(msg) > 0) call st%scene%note('', msg)
            end if
        case ('variable')
            call define_variable(st, w, where)
        case ('units', 'dimension', 'timestep', 'atom_style')
            call setting(st, w, where)
        case ('create_box', 'create_atoms', 'set', 'read_data', 'read_restart', 'mass')
            call atoms_command(st, w, where)
        case ('fix')
            call integrator_fix(st, w, where, handled)
        case ('jump', 'next', 'if', 'label', 'loop')
            call st%scene%note(where, w%item(1)%s // ': flow control is not followed; every command is read ' // &
                               'once, in the order of the files')
        case default
            handled = passed_over(w%item(1)%s)
        end select
    end subroutine common_command

    !> Commands that cannot change a normal contact between two particles or a particle
    !> and a wall (set-up, output, neighbor lists, regions, groups, runs).
    pure logical function passed_over(cmd)
        character(len=*), intent(in) :: cmd
        select case (cmd)
        case ('atom_modify', 'boundary', 'newton', 'comm_modify', 'comm_style', 'communicate', 'processors', &
              'neighbor', 'neigh_modify', 'region', 'group', 'velocity', 'thermo', 'thermo_style', 'thermo_modify', &
              'dump', 'dump_modify', 'undump', 'compute', 'compute_modify', 'uncompute', 'run', 'minimize', 'print', &
              'log', 'echo', 'write_restart', 'write_data', 'write_dump', 'write_coeff', 'restart', 'delete_atoms', &
              'change_box', 'lattice', 'reset_timestep', 'balance', 'unfix', 'clear', 'shell', 'quit', 'info', &
              'timer', 'displace_atoms', 'molecule', 'partition', 'suffix', 'package', 'plugin', 'python', &
              'reset_atom_ids', 'replicate', 'rerun', 'run_style', 'min_style', 'min_modify', 'fix_modify', &
              'special_bonds', 'labelmap', 'hard_particles', 'soft_particles', 'modify_timing')
            passed_over = .true.
        case default
            passed_over = .false.
        end select
    end function passed_over

    !> variable NAME STYLE args (LAMMPS variable.cpp semantics: an index-style name that
    !> exists is not redefined; equal-style formulas are evaluated when defined).
    subroutine define_variable(st, w, where)
        type(peer_script), intent(inout) :: st
        type(peer_list), intent(in) :: w
        character(len=*), intent(in) :: where
        character(len=:), allocatable :: name, style, msg
        real(wp) :: x
        integer :: i
        if (w%n < 3) then
            call st%scene%note(where, 'variable: missing name or style')
            return
        end if
        name = w%item(2)%s
        style = w%item(3)%s
        i = st%vars%find(name)
        select case (style)
        case ('delete')
            if (i > 0) call st%vars%set_text(name, 'no value: deleted at ' // where)
        case ('index', 'loop', 'world', 'universe', 'uloop')
            if (i > 0 .and. style == 'index') return
            if (w%n < 4) then
                call st%scene%note(where, 'variable ' // name // ' ' // style // ' without a value')
            else if (style == 'loop' .and. w%n == 4) then
                call st%vars%set_text(name, '1')
            else
                call st%vars%set_text(name, w%item(4)%s)
            end if
        case ('string', 'internal', 'getenv', 'format', 'file', 'atomfile', 'python', 'timer', 'atom', 'vector')
            if ((style == 'string' .or. style == 'internal') .and. w%n >= 4) then
                call st%vars%set_text(name, join(w%item(4:w%n)))
            else
                call st%vars%set_text(name, 'no value: ' // style // '-style variable (' // where // ')')
            end if
        case ('equal')
            call peer_eval(join(w%item(4:w%n)), SYNTAX_LAMMPS, st%vars, x, msg)
            if (len(msg) == 0) then
                call st%vars%set_num(name, x)
            else
                call st%vars%set_text(name, 'no value: ' // msg // ' (' // where // ')')
            end if
        case default
            call st%scene%note(where, 'variable style ' // style // ' is not interpreted')
        end select
    end subroutine define_variable

    !> units, dimension, timestep, atom_style.
    subroutine setting(st, w, where)
        type(peer_script), intent(inout) :: st
        type(peer_list), intent(in) :: w
        character(len=*), intent(in) :: where
        real(wp) :: x
        if (w%n < 2) then
            call st%scene%note(where, w%item(1)%s // ' without a value')
            return
        end if
        select case (w%item(1)%s)
        case ('units')
            st%scene%units = w%item(2)%s
            select case (st%scene%units)
            case ('si', 'cgs', 'lj', 'micro', 'nano')
            case default
                call st%scene%note(where, 'units ' // st%scene%units // ': granular contacts are checked in si, cgs, ' // &
                                   'lj, micro and nano units (nktv2p = 1); other units scale gran/hertz/history Kn')
            end select
        case ('dimension')
            if (w%item(2)%s == '2') st%dimension = 2
        case ('timestep')
            if (peer_number(w%item(2)%s, x) .and. x > 0.0_wp) then
                st%scene%dt = x
                st%scene%dt_text = 'timestep ' // w%item(2)%s // ' (' // where // ')'
                st%have_dt = .true.
            else
                call st%scene%note(where, 'timestep ' // w%item(2)%s // ': not a positive number')
            end if
        case ('atom_style')
            if (w%item(2)%s == 'granular') st%liggghts = .true.
            if (w%item(2)%s /= 'sphere' .and. w%item(2)%s /= 'granular' .and. w%item(2)%s /= 'hybrid') then
                call st%scene%note(where, 'atom_style ' // w%item(2)%s // ': the checker expects sphere (granular)')
            end if
        case default
        end select
    end subroutine setting

    !> create_box N, create_atoms T, set type|group all ..., read_data, mass.
    subroutine atoms_command(st, w, where)
        type(peer_script), intent(inout) :: st
        type(peer_list), intent(in) :: w
        character(len=*), intent(in) :: where
        integer :: t, lo, hi
        real(wp) :: x
        select case (w%item(1)%s)
        case ('create_box')
            if (w%n >= 2) then
                if (peer_number(w%item(2)%s, x)) call script_types(st, nint(x))
            end if
        case ('create_atoms')
            call script_type_range(st, w, 2, lo, hi)
            if (lo < 1) then
                call st%scene%note(where, 'create_atoms: atom type ' // w%item(min(2, w%n))%s // ' not read')
            else if (w%n >= 3) then
                do t = lo, hi
                    st%atoms(t) = .true.
                end do
            end if
        case ('set')
            call set_command(st, w, where)
        case ('read_data', 'read_restart')
            call st%scene%note(where, w%item(1)%s // ': the atoms, their types and sizes in the file are not read; ' // &
                               'types without another size are checked with LAMMPS''s default diameter 1 and density 1')
            if (st%ntypes == 0) call st%scene%note(where, w%item(1)%s // ': the number of atom types is not known')
            st%atoms = .true.
        case ('mass')
            call st%scene%note(where, 'mass: per-type masses are not used by atom_style sphere (rmass from density)')
        case default
        end select
    end subroutine atoms_command

    !> set type N (or group all) diameter D | density rho | mass m ...
    subroutine set_command(st, w, where)
        type(peer_script), intent(inout) :: st
        type(peer_list), intent(in) :: w
        character(len=*), intent(in) :: where
        integer :: lo, hi, i, t
        real(wp) :: x
        if (w%n < 5) return
        if (w%item(2)%s == 'type') then
            call script_type_range(st, w, 3, lo, hi)
        else if (w%item(2)%s == 'group' .and. w%item(3)%s == 'all') then
            lo = 1
            hi = st%ntypes
        else
            call st%scene%note(where, 'set ' // w%item(2)%s // ' ' // w%item(3)%s // ': only set type N and set ' // &
                               'group all are mapped to atom types; this set is not used')
            return
        end if
        if (lo < 1) then
            call st%scene%note(where, 'set: atom type ' // w%item(3)%s // ' not read')
            return
        end if
        i = 4
        do while (i + 1 <= w%n)
            select case (w%item(i)%s)
            case ('diameter', 'density', 'mass', 'density/disc')
                if (.not. peer_number(w%item(i + 1)%s, x)) then
                    call st%scene%note(where, 'set ' // w%item(i)%s // ' ' // w%item(i + 1)%s // ': not a number')
                else
                    do t = lo, hi
                        call set_one(st, t, w%item(i)%s, x, where)
                    end do
                end if
            case default
            end select
            i = i + 2
        end do
    end subroutine set_command

    subroutine set_one(st, t, what, x, where)
        type(peer_script), intent(inout) :: st
        integer, intent(in) :: t
        character(len=*), intent(in) :: what, where
        real(wp), intent(in) :: x
        if (.not. st%atoms(t)) then
            call st%scene%note(where, 'set type ' // itoa(t) // ' ' // what // ': no atom of type ' // itoa(t) // &
                               ' exists yet, so LAMMPS changes none')
            return
        end if
        select case (what)
        case ('diameter'); st%diam(t) = x
        case ('density'); st%dens(t) = x
        case ('mass'); st%mass(t) = x
        case default
            call st%scene%note(where, 'set density/disc: the mass is pi r^2 rho (2d discs); the checker uses ' // &
                               '(4/3) pi r^3 rho')
            st%dens(t) = x
        end select
        if (index(st%src(t)%s, '(' // where // ')') == 0) st%src(t)%s = st%src(t)%s // ' set (' // where // ')'
    end subroutine set_one

    !> fix nve/sphere is LAMMPS's velocity Verlet (the host scheme `lammps`); other
    !> integrators are noted; the remaining fixes go to the engine's reader.
    subroutine integrator_fix(st, w, where, handled)
        type(peer_script), intent(inout) :: st
        type(peer_list), intent(in) :: w
        character(len=*), intent(in) :: where
        logical, intent(out) :: handled
        character(len=:), allocatable :: style
        handled = .false.
        if (w%n < 4) return
        style = w%item(4)%s
        select case (style)
        case ('nve/sphere', 'nve/sphere/omp', 'nve/sphere/kk')
            handled = .true.
            if (st%have_integrator .and. st%scene%host /= HD_HOST_LAMMPS) return
            st%scene%host = HD_HOST_LAMMPS
            st%scene%host_text = 'fix ' // style // ' (' // where // '): velocity Verlet, the damping sees the ' // &
                                 'half-step velocity'
            st%have_integrator = .true.
        case ('nve', 'nve/limit', 'nvt/sphere', 'nph/sphere', 'npt/sphere', 'nve/asphere', 'rigid', 'rigid/small', &
              'rigid/nve', 'rigid/small/nve', 'nve/noforce', 'multisphere', 'nve/nonspherical', 'nve/superquadric')
            handled = .true.
            st%scene%host = HD_HOST_NONE
            st%scene%host_text = 'fix ' // style // ' (' // where // '): an integrator the checker does not model'
            st%have_integrator = .true.
        case ('gravity', 'enforce2d', 'balance', 'ave/time', 'ave/atom', 'ave/chunk', 'ave/histo', 'print', &
              'store/state', 'halt', 'check/timestep/gran', 'momentum', 'ave/euler', 'property/atom')
            handled = .true.
        case ('viscous', 'langevin', 'freeze', 'dt/reset', 'damping/cundall', 'viscous/sphere')
            handled = .true.
            call st%scene%note(where, 'fix ' // style // ' changes the collisions (drag, frozen partners or a ' // &
                               'varying time step); the checker does not model it')
        case default
        end select
    end subroutine integrator_fix

    ! ------------------------------------------------------------------ atom types

    !> Number of atom types (create_box); the per-type arrays grow to it.
    subroutine script_types(st, n)
        type(peer_script), intent(inout) :: st
        integer, intent(in) :: n
        real(wp), allocatable :: d(:), r(:), m(:)
        logical, allocatable :: a(:)
        type(peer_text), allocatable :: s(:)
        integer :: k, i
        if (n <= st%ntypes .or. n > 100000) return
        k = st%ntypes
        allocate (d(n), r(n), m(n), a(n), s(n))
        d = 0.0_wp
        r = 0.0_wp
        m = 0.0_wp
        a = .false.
        do i = 1, n
            s(i)%s = ''
        end do
        d(1:k) = st%diam(1:k)
        r(1:k) = st%dens(1:k)
        m(1:k) = st%mass(1:k)
        a(1:k) = st%atoms(1:k)
        s(1:k) = st%src(1:k)
        call move_alloc(d, st%diam)
        call move_alloc(r, st%dens)
        call move_alloc(m, st%mass)
        call move_alloc(a, st%atoms)
        call move_alloc(s, st%src)
        st%ntypes = n
    end subroutine script_types

    !> The atom types of word k: N, *, N*, *N, M*N (LAMMPS utils::bounds); lo = 0 if not a type.
    subroutine script_type_range(st, w, k, lo, hi)
        type(peer_script), intent(in) :: st
        type(peer_list), intent(in) :: w
        integer, intent(in) :: k
        integer, intent(out) :: lo, hi
        character(len=:), allocatable :: t
        real(wp) :: x, y
        integer :: j
        lo = 0
        hi = -1
        if (k > w%n) return
        t = w%item(k)%s
        j = index(t, '*')
        if (j == 0) then
            if (peer_number(t, x)) then
                lo = nint(x)
                hi = lo
            end if
        else
            lo = 1
            hi = st%ntypes
            if (j > 1) then
                if (.not. peer_number(t(1:j - 1), x)) lo = 0
                if (lo > 0) lo = nint(x)
            end if
            if (j < len(t)) then
                if (.not. peer_number(t(j + 1:), y)) lo = 0
                if (lo > 0) hi = nint(y)
            end if
        end if
        if (lo < 1 .or. hi > st%ntypes .or. hi < lo) then
            lo = 0
            hi = -1
        end if
    end subroutine script_type_range

    !> Record a size (diameter, density; <= 0: not given) of type t from a source.
    subroutine script_add_size(st, t, diam, dens, source)
        type(peer_script), intent(inout) :: st
        integer, intent(in) :: t
        real(wp), intent(in) :: diam, dens
        character(len=*), intent(in) :: source
        if (t < 1 .or. t > st%ntypes) return
        st%atoms(t) = .true.
        if (diam > 0.0_wp) then
            if (st%diam(t) <= 0.0_wp .or. diam < st%diam(t)) st%diam(t) = diam
        end if
        if (dens > 0.0_wp) then
            if (st%dens(t) <= 0.0_wp .or. dens < st%dens(t)) st%dens(t) = dens
        end if
        st%src(t)%s = st%src(t)%s // ' ' // source
    end subroutine script_add_size

    !> The radius and density a type's contacts are checked with: the smallest diameter
    !> and the lowest density any source gives (the shortest contact), LAMMPS's
    !> defaults (diameter 1, density 1) where none does; `text` says which.
    subroutine script_size(st, t, radius, density, text)
        type(peer_script), intent(in) :: st
        integer, intent(in) :: t
        real(wp), intent(out) :: radius, density
        character(len=:), allocatable, intent(out) :: text
        real(wp), parameter :: pi = acos(-1.0_wp)
        radius = 0.5_wp
        density = 1.0_wp
        text = 'type ' // itoa(t) // ':'
        if (st%diam(t) > 0.0_wp) then
            radius = 0.5_wp * st%diam(t)
            text = text // ' diameter ' // fmt_short(st%diam(t))
        else
            text = text // ' diameter 1 (LAMMPS default)'
        end if
        if (st%mass(t) > 0.0_wp .and. st%dens(t) <= 0.0_wp) then
            density = st%mass(t) / ((4.0_wp / 3.0_wp) * pi * radius**3)
            text = text // ', density ' // fmt_short(density) // ' (from set mass)'
        else if (st%dens(t) > 0.0_wp) then
            density = st%dens(t)
            text = text // ', density ' // fmt_short(density)
        else
            text = text // ', density 1 (LAMMPS default)'
        end if
        if (len(st%src(t)%s) > 0) text = text // ' from' // st%src(t)%s
    end subroutine script_size

end module hertzdamp_peers_script
