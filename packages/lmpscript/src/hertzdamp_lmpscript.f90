!> The input-script language LAMMPS and LIGGGHTS share, read the way the engine reads
!> it: one command per line, `&` at the end of a line continues it, `#` starts a comment
!> (outside quotes), `include` reads another file in place, `variable` defines names
!> (index, loop, world, universe, uloop, string, internal, equal), `${name}`, `$x` and
!> `$(expr)` are substituted before the words are split (not inside quotes), and quotes
!> group words.  The commands every contact depends on are interpreted here: units,
!> dimension, timestep, create_box, create_atoms, set (type and group all: diameter,
!> density, mass), read_data (not read: noted) and the integrator fixes; commands that
!> cannot change a normal contact are read and passed over.  Every other command is
!> handed to the engine's own reader (an extension of `lmp_commands`, given to
!> `lmp_read`); what neither interprets is noted with its file:line.
!>
!> An include that cannot be read, or one nested deeper than `max_depth` files (a deck
!> that includes itself), stops the reading with an error, as it stops LAMMPS.  The
!> work is linear in the deck: each line is scanned a bounded number of times and every
!> name lookup is a hash-map probe (counted in `work`).
module hertzdamp_lmpscript
    use hertzdamp, only: hertzdamp_rk, HD_HOST_NONE, HD_HOST_LAMMPS
    use hertzdamp_text_list, only: text_string, text_list, text_join
    use hertzdamp_text_parse, only: text_words, text_number, text_shortest, text_g15, text_directory, &
                                    text_find_unquoted
    use hertzdamp_text_expr, only: text_vars, text_eval, SYNTAX_LAMMPS
    use hertzdamp_text_file, only: text_read_lines, text_where
    use hertzdamp_text_format, only: itoa, fmt_short
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: max_depth = 20      !! include nesting limit

    !> One open file.
    type :: script_file
        character(len=:), allocatable :: name
        type(text_list) :: lines
        integer :: next = 1
    end type script_file

    !> The interpreter's state: what the deck sets for every engine (units, time step,
    !> integrator, atom types and their sizes), what was not interpreted, the variables
    !> and the open files.
    type, public :: lmp_script
        character(len=:), allocatable :: units    !! unit system of the deck (all numbers are in it)
        real(wp) :: dt = 0.0_wp                   !! the time step (0: unknown)
        character(len=:), allocatable :: dt_text  !! where the time step comes from
        integer :: host = HD_HOST_NONE            !! the integrator as a host scheme
        character(len=:), allocatable :: host_text  !! the integrator, or why it is not modeled
        type(text_list) :: notes                  !! what was not interpreted, with file:line
        type(text_list) :: files                  !! the files read
        integer(int64) :: work = 0                !! characters and words read, map probes (linear in the deck)
        character(len=:), allocatable :: error    !! why the reading stopped ('' when it did not)
        type(text_vars) :: vars
        type(script_file) :: stack(max_depth)
        integer :: depth = 0
        integer :: ntypes = 0                    !! create_box
        real(wp), allocatable :: diam(:)         !! smallest diameter of each type (<= 0: none known)
        real(wp), allocatable :: dens(:)         !! lowest density of each type (<= 0: none known)
        real(wp), allocatable :: mass(:)         !! set type N mass (<= 0: none)
        logical, allocatable :: atoms(:)         !! the type has atoms (created, poured, ...)
        type(text_string), allocatable :: src(:)   !! where each type's sizes come from
        integer :: dimension = 3
        logical :: liggghts = .false.            !! LIGGGHTS (communicate, atom_style granular)
        logical :: have_dt = .false.
        logical :: have_integrator = .false.
    contains
        procedure :: note => script_note         !! something not interpreted (or a remark), with file:line
    end type lmp_script

    !> An engine's own commands (pair styles, walls, particle sizes ...): the reader that
    !> `lmp_read` hands every command it does not interpret itself.
    type, abstract, public :: lmp_commands
    contains
        procedure(command_iface), deferred :: command   !! interpret one command (handled: it did)
    end type lmp_commands

    abstract interface
        subroutine command_iface(self, st, w, where, handled)
            import :: lmp_commands, lmp_script, text_list
            implicit none
            class(lmp_commands), intent(inout) :: self
            type(lmp_script), intent(inout) :: st     !! the interpreter (notes, atom types)
            type(text_list), intent(in) :: w          !! the command's words
            character(len=*), intent(in) :: where     !! its file:line
            logical, intent(out) :: handled           !! false: neither read nor passed over
        end subroutine command_iface
    end interface

    public :: lmp_read, lmp_types, lmp_type_range, lmp_size, lmp_add_size, lmp_active_types

contains

    !> Read the deck files in order (as if included one after another): the commands this
    !> module interprets on the way, every other one handed to `reader` (noted when it
    !> does not interpret it either).  msg: a deck file that cannot be read, or why the
    !> reading stopped (an include).
    subroutine lmp_read(st, paths, liggghts, reader, msg)
        type(lmp_script), intent(out) :: st
        type(text_string), intent(in) :: paths(:)            !! the deck's files
        logical, intent(in) :: liggghts                      !! LIGGGHTS (else LAMMPS)
        class(lmp_commands), intent(inout) :: reader         !! the engine's own commands
        character(len=:), allocatable, intent(out) :: msg    !! '' when the deck is read
        type(text_list) :: w
        character(len=:), allocatable :: where
        logical :: more, handled
        integer :: i
        msg = ''
        st%error = ''
        st%liggghts = liggghts
        st%units = 'lj'
        st%dt_text = ''
        st%host = HD_HOST_NONE
        st%host_text = 'no fix nve/sphere: the particles are not integrated'
        allocate (st%diam(0), st%dens(0), st%mass(0), st%atoms(0), st%src(0))
        ! the files are a stack: the first on top
        do i = size(paths), 1, -1
            call push_file(st, paths(i)%s, '')
            if (len(st%error) > 0) exit
        end do
        do while (len(st%error) == 0)
            call next_command(st, w, where, more)
            if (.not. more) exit
            call reader%command(st, w, where, handled)
            if (handled) cycle
            if (w%item(1)%s == 'fix' .and. w%n >= 4) then
                call st%note(where, 'fix style ' // w%item(4)%s // ' is not interpreted')
            else
                call st%note(where, 'command ' // w%item(1)%s // ' is not interpreted')
            end if
        end do
        msg = st%error
    end subroutine lmp_read

    !> Something the reader did not interpret (or a remark), prefixed with file:line.
    subroutine script_note(self, where, text)
        class(lmp_script), intent(inout) :: self
        character(len=*), intent(in) :: where   !! file:line ('' for none)
        character(len=*), intent(in) :: text    !! what
        call self%notes%note(where, text)
    end subroutine script_note

    !> Open a deck file or an include (`where`: the include's file:line, '' for a deck
    !> file); st%error when it cannot be read or is nested too deep.
    subroutine push_file(st, path, where)
        type(lmp_script), intent(inout) :: st
        character(len=*), intent(in) :: path, where
        character(len=:), allocatable :: m
        logical :: found
        if (st%depth == max_depth) then
            st%error = where // ': include ' // path // ': nested deeper than ' // itoa(max_depth) // &
                       ' files (does the deck include itself?); LAMMPS would not finish reading it'
            return
        end if
        st%depth = st%depth + 1
        st%stack(st%depth)%name = path
        st%stack(st%depth)%next = 1
        ! an include is looked up beside the file that includes it, then in the working directory
        if (st%depth > 1 .and. len(path) > 0) then
            if (path(1:1) /= '/') then
                inquire (file=text_directory(st%stack(st%depth - 1)%name) // path, exist=found)
                if (found) st%stack(st%depth)%name = text_directory(st%stack(st%depth - 1)%name) // path
            end if
        end if
        call text_read_lines(st%stack(st%depth)%name, st%stack(st%depth)%lines, m, st%work)
        if (len(m) > 0) then
            st%depth = st%depth - 1
            st%error = m
            if (len(where) > 0) st%error = where // ': include ' // m
            return
        end if
        call st%files%push(st%stack(st%depth)%name)
    end subroutine push_file

    !> The next logical line (continuations joined), with the file:line of its start.
    subroutine next_line(st, line, where, more)
        type(lmp_script), intent(inout) :: st
        character(len=:), allocatable, intent(out) :: line, where
        logical, intent(out) :: more
        character(len=:), allocatable :: t
        integer :: k
        type(text_list) :: parts
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
            where = text_where(f%name, f%next)
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
        line = text_join(parts%items())
    end subroutine next_line

    !> The next command the engine's reader has to interpret: its words (quotes removed)
    !> and file:line; `more` false at the end of the deck or at an error.  Common commands
    !> are interpreted on the way (see the module).
    subroutine next_command(st, words, where, more)
        type(lmp_script), intent(inout) :: st
        type(text_list), intent(out) :: words
        character(len=:), allocatable, intent(out) :: where
        logical, intent(out) :: more
        character(len=:), allocatable :: line, text
        logical :: handled
        integer :: k
        do
            call next_line(st, line, where, more)
            if (.not. more) return
            k = text_find_unquoted(line, '#')
            if (k > 0) line = line(1:k - 1)
            if (len_trim(line) == 0) cycle
            call substitute(st, line, where, text, handled)
            if (handled) cycle            ! a substitution failed: noted
            call text_words(text, words, quotes=.true.)
            st%work = st%work + len(text) + words%n
            if (words%n == 0) cycle
            call common_command(st, words, where, handled)
            more = len(st%error) == 0
            if (.not. (handled .and. more)) return
            words%n = 0
        end do
    end subroutine next_command

    !> ${name}, $x and $(expr) replaced outside quotes; `failed` when a name has no
    !> value (the command is noted and skipped, as LAMMPS would stop there).
    subroutine substitute(st, line, where, out, failed)
        type(lmp_script), intent(inout) :: st
        character(len=*), intent(in) :: line, where
        character(len=:), allocatable, intent(out) :: out
        logical, intent(out) :: failed
        type(text_list) :: parts
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
                    call st%note(where, msg // ': the command is not interpreted')
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
        out = text_join(parts%item(1:parts%n), '')   ! (parts holds the text after the last reference)
    end subroutine substitute

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
        type(lmp_script), intent(inout) :: st
        character(len=*), intent(in) :: kind, name
        character(len=:), allocatable, intent(out) :: val, msg
        real(wp) :: x
        integer :: i, k
        msg = ''
        val = ''
        if (kind == '(') then
            k = index(name, ':', back=.true.)
            if (k == 0) k = len(name) + 1
            call text_eval(name(1:k - 1), SYNTAX_LAMMPS, st%vars, x, msg)
            if (len(msg) == 0) val = text_shortest(x)
            if (len(msg) > 0) msg = '$(' // name // '): ' // msg
            return
        end if
        i = st%vars%find(name)
        st%work = st%work + 1
        if (i == 0) then
            msg = 'variable ' // name // ' is not defined'
        else if (st%vars%numeric(i) .and. len(st%vars%text(i)%s) == 0) then
            val = text_g15(st%vars%x(i))      ! an equal-style value, as LAMMPS's "%.15g"
        else if (index(st%vars%text(i)%s, 'no value:') == 1) then
            msg = 'variable ' // name // ' has ' // st%vars%text(i)%s
        else
            val = st%vars%text(i)%s
        end if
    end subroutine variable_text

    !> The commands interpreted for every engine; handled false for the others.
    subroutine common_command(st, w, where, handled)
        type(lmp_script), intent(inout) :: st
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        logical, intent(out) :: handled
        handled = .true.
        select case (w%item(1)%s)
        case ('include')
            if (w%n < 2) then
                call st%note(where, 'include without a file name')
            else
                call push_file(st, w%item(2)%s, where)
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
            call st%note(where, w%item(1)%s // ': flow control is not followed; every command is read ' // &
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
        type(lmp_script), intent(inout) :: st
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        character(len=:), allocatable :: name, style, msg
        real(wp) :: x
        integer :: i
        if (w%n < 3) then
            call st%note(where, 'variable: missing name or style')
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
                call st%note(where, 'variable ' // name // ' ' // style // ' without a value')
            else if (style == 'loop' .and. w%n == 4) then
                call st%vars%set_text(name, '1')
            else
                call st%vars%set_text(name, w%item(4)%s)
            end if
        case ('string', 'internal', 'getenv', 'format', 'file', 'atomfile', 'python', 'timer', 'atom', 'vector')
            if ((style == 'string' .or. style == 'internal') .and. w%n >= 4) then
                call st%vars%set_text(name, text_join(w%item(4:w%n)))
            else
                call st%vars%set_text(name, 'no value: ' // style // '-style variable (' // where // ')')
            end if
        case ('equal')
            call text_eval(text_join(w%item(4:w%n)), SYNTAX_LAMMPS, st%vars, x, msg)
            if (len(msg) == 0) then
                call st%vars%set_num(name, x)
            else
                call st%vars%set_text(name, 'no value: ' // msg // ' (' // where // ')')
            end if
        case default
            call st%note(where, 'variable style ' // style // ' is not interpreted')
        end select
    end subroutine define_variable

    !> units, dimension, timestep, atom_style.
    subroutine setting(st, w, where)
        type(lmp_script), intent(inout) :: st
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        real(wp) :: x
        if (w%n < 2) then
            call st%note(where, w%item(1)%s // ' without a value')
            return
        end if
        select case (w%item(1)%s)
        case ('units')
            st%units = w%item(2)%s
            select case (st%units)
            case ('si', 'cgs', 'lj', 'micro', 'nano')
            case default
                call st%note(where, 'units ' // st%units // ': granular contacts are checked in si, cgs, ' // &
                                   'lj, micro and nano units (nktv2p = 1); other units scale gran/hertz/history Kn')
            end select
        case ('dimension')
            if (w%item(2)%s == '2') st%dimension = 2
        case ('timestep')
            if (text_number(w%item(2)%s, x) .and. x > 0.0_wp) then
                st%dt = x
                st%dt_text = 'timestep ' // w%item(2)%s // ' (' // where // ')'
                st%have_dt = .true.
            else
                call st%note(where, 'timestep ' // w%item(2)%s // ': not a positive number')
            end if
        case ('atom_style')
            if (w%item(2)%s == 'granular') st%liggghts = .true.
            if (w%item(2)%s /= 'sphere' .and. w%item(2)%s /= 'granular' .and. w%item(2)%s /= 'hybrid') then
                call st%note(where, 'atom_style ' // w%item(2)%s // ': the checker expects sphere (granular)')
            end if
        case default
        end select
    end subroutine setting

    !> create_box N, create_atoms T, set type|group all ..., read_data, mass.
    subroutine atoms_command(st, w, where)
        type(lmp_script), intent(inout) :: st
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        integer :: t, lo, hi
        real(wp) :: x
        select case (w%item(1)%s)
        case ('create_box')
            if (w%n >= 2) then
                if (text_number(w%item(2)%s, x)) call lmp_types(st, nint(x))
            end if
        case ('create_atoms')
            call lmp_type_range(st, w, 2, lo, hi)
            if (lo < 1) then
                call st%note(where, 'create_atoms: atom type ' // w%item(min(2, w%n))%s // ' not read')
            else if (w%n >= 3) then
                do t = lo, hi
                    st%atoms(t) = .true.
                end do
            end if
        case ('set')
            call set_command(st, w, where)
        case ('read_data', 'read_restart')
            call st%note(where, w%item(1)%s // ': the atoms, their types and sizes in the file are not read; ' // &
                               'types without another size are checked with LAMMPS''s default diameter 1 and density 1')
            if (st%ntypes == 0) call st%note(where, w%item(1)%s // ': the number of atom types is not known')
            st%atoms = .true.
        case ('mass')
            call st%note(where, 'mass: per-type masses are not used by atom_style sphere (rmass from density)')
        case default
        end select
    end subroutine atoms_command

    !> set type N (or group all) diameter D | density rho | mass m ...
    subroutine set_command(st, w, where)
        type(lmp_script), intent(inout) :: st
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        integer :: lo, hi, i, t
        real(wp) :: x
        if (w%n < 5) return
        if (w%item(2)%s == 'type') then
            call lmp_type_range(st, w, 3, lo, hi)
        else if (w%item(2)%s == 'group' .and. w%item(3)%s == 'all') then
            lo = 1
            hi = st%ntypes
        else
            call st%note(where, 'set ' // w%item(2)%s // ' ' // w%item(3)%s // ': only set type N and set ' // &
                               'group all are mapped to atom types; this set is not used')
            return
        end if
        if (lo < 1) then
            call st%note(where, 'set: atom type ' // w%item(3)%s // ' not read')
            return
        end if
        i = 4
        do while (i + 1 <= w%n)
            select case (w%item(i)%s)
            case ('diameter', 'density', 'mass', 'density/disc')
                if (.not. text_number(w%item(i + 1)%s, x)) then
                    call st%note(where, 'set ' // w%item(i)%s // ' ' // w%item(i + 1)%s // ': not a number')
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
        type(lmp_script), intent(inout) :: st
        integer, intent(in) :: t
        character(len=*), intent(in) :: what, where
        real(wp), intent(in) :: x
        if (.not. st%atoms(t)) then
            call st%note(where, 'set type ' // itoa(t) // ' ' // what // ': no atom of type ' // itoa(t) // &
                               ' exists yet, so LAMMPS changes none')
            return
        end if
        select case (what)
        case ('diameter'); st%diam(t) = x
        case ('density'); st%dens(t) = x
        case ('mass'); st%mass(t) = x
        case default
            call st%note(where, 'set density/disc: the mass is pi r^2 rho (2d discs); the checker uses ' // &
                               '(4/3) pi r^3 rho')
            st%dens(t) = x
        end select
        if (index(st%src(t)%s, '(' // where // ')') == 0) st%src(t)%s = st%src(t)%s // ' set (' // where // ')'
    end subroutine set_one

    !> fix nve/sphere is LAMMPS's velocity Verlet (the host scheme `lammps`); other
    !> integrators are noted; the remaining fixes go to the engine's reader.
    subroutine integrator_fix(st, w, where, handled)
        type(lmp_script), intent(inout) :: st
        type(text_list), intent(in) :: w
        character(len=*), intent(in) :: where
        logical, intent(out) :: handled
        character(len=:), allocatable :: style
        handled = .false.
        if (w%n < 4) return
        style = w%item(4)%s
        select case (style)
        case ('nve/sphere', 'nve/sphere/omp', 'nve/sphere/kk')
            handled = .true.
            if (st%have_integrator .and. st%host /= HD_HOST_LAMMPS) return
            st%host = HD_HOST_LAMMPS
            st%host_text = 'fix ' // style // ' (' // where // '): velocity Verlet, the damping sees the ' // &
                                 'half-step velocity'
            st%have_integrator = .true.
        case ('nve', 'nve/limit', 'nvt/sphere', 'nph/sphere', 'npt/sphere', 'nve/asphere', 'rigid', 'rigid/small', &
              'rigid/nve', 'rigid/small/nve', 'nve/noforce', 'multisphere', 'nve/nonspherical', 'nve/superquadric')
            handled = .true.
            st%host = HD_HOST_NONE
            st%host_text = 'fix ' // style // ' (' // where // '): an integrator the checker does not model'
            st%have_integrator = .true.
        case ('gravity', 'enforce2d', 'balance', 'ave/time', 'ave/atom', 'ave/chunk', 'ave/histo', 'print', &
              'store/state', 'halt', 'check/timestep/gran', 'momentum', 'ave/euler', 'property/atom')
            handled = .true.
        case ('viscous', 'langevin', 'freeze', 'dt/reset', 'damping/cundall', 'viscous/sphere')
            handled = .true.
            call st%note(where, 'fix ' // style // ' changes the collisions (drag, frozen partners or a ' // &
                               'varying time step); the checker does not model it')
        case default
        end select
    end subroutine integrator_fix

    ! ------------------------------------------------------------------ atom types

    !> Number of atom types (create_box); the per-type arrays grow to it.
    subroutine lmp_types(st, n)
        type(lmp_script), intent(inout) :: st
        integer, intent(in) :: n
        real(wp), allocatable :: d(:), r(:), m(:)
        logical, allocatable :: a(:)
        type(text_string), allocatable :: s(:)
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
    end subroutine lmp_types

    !> The atom types of word k: N, *, N*, *N, M*N (LAMMPS utils::bounds); lo = 0 if not a type.
    subroutine lmp_type_range(st, w, k, lo, hi)
        type(lmp_script), intent(in) :: st
        type(text_list), intent(in) :: w
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
            if (text_number(t, x)) then
                lo = nint(x)
                hi = lo
            end if
        else
            lo = 1
            hi = st%ntypes
            if (j > 1) then
                if (.not. text_number(t(1:j - 1), x)) lo = 0
                if (lo > 0) lo = nint(x)
            end if
            if (j < len(t)) then
                if (.not. text_number(t(j + 1:), y)) lo = 0
                if (lo > 0) hi = nint(y)
            end if
        end if
        if (lo < 1 .or. hi > st%ntypes .or. hi < lo) then
            lo = 0
            hi = -1
        end if
    end subroutine lmp_type_range

    !> The atom types that have atoms (created, poured, deposited, ...); every type when
    !> none has, with the note `none` ('' for no note).
    subroutine lmp_active_types(st, none, types)
        type(lmp_script), intent(inout) :: st
        character(len=*), intent(in) :: none            !! the note when no type has atoms
        integer, allocatable, intent(out) :: types(:)   !! the types
        integer :: t
        types = pack([(t, t = 1, st%ntypes)], st%atoms(1:st%ntypes))
        if (size(types) > 0) return
        types = [(t, t = 1, st%ntypes)]
        if (len(none) > 0) call st%note('', none)
    end subroutine lmp_active_types

    !> Record a size (diameter, density; <= 0: not given) of type t from a source.
    subroutine lmp_add_size(st, t, diam, dens, source)
        type(lmp_script), intent(inout) :: st
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
    end subroutine lmp_add_size

    !> The radius and density a type's contacts are checked with: the smallest diameter
    !> and the lowest density any source gives (the shortest contact), LAMMPS's
    !> defaults (diameter 1, density 1) where none does; `text` says which.
    subroutine lmp_size(st, t, radius, density, text)
        type(lmp_script), intent(in) :: st
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
    end subroutine lmp_size

end module hertzdamp_lmpscript
