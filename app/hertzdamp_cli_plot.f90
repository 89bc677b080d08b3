!> Plots for the CLI (`bench --plot`, `scene --plot`, `calibrate --plot`), written safely:
!>
!> 1. Before any work (plot_check_target): gnuplot is there (else exit 4); an existing
!>    target must be a regular file, which is tested without opening it (a device, a
!>    FIFO, a directory or a socket is refused, exit 2, and a FIFO never blocks), and
!>    none of the command's input files (else 2: `calibrate --plot DATA.csv` would
!>    overwrite its data); the target's directory takes a new file and the temporary
!>    names are free (else 2).
!> 2. The data and the gnuplot script go to scratch files (type plot_scratch): new
!>    files of this process in scratch_dir() ($TMPDIR if it is plain, else /tmp), every
!>    write, flush and close checked and the size compared with what was written (a
!>    full disk, `ulimit -f`: the program ignores SIGXFSZ, see main.f90, so that such a
!>    write fails instead of killing the process).
!> 3. gnuplot draws into plot_temp_name(), a file of this process in
!>    scratch_dir() whose name needs no quoting, so any target name works (quotes, a
!>    leading '-', a newline).
!> 4. plot_run checks gnuplot's own output: its exit status, its error stream (any
!>    line but a warning is an error) and the PNG itself (signature, and the IEND
!>    chunk that ends every complete PNG: gnuplot exits 0 on a full disk).
!> 5. The PNG is copied to `target.hertzdamp-tmp` in the target's directory, every
!>    write checked, and renamed onto the target (atomic within a directory).
!>
!> On any failure: one line on stderr, exit 4, and every temporary file removed, so
!> nothing is left behind: neither a half-written target nor a stray file.
!>
!> Signals: from the first scratch file on, SIGINT, SIGTERM and SIGHUP (unless they
!> were ignored when the program started) remove every temporary file of the plot
!> (scratch files, gnuplot's PNG and error stream, the copy next to the target; never
!> the target), stop gnuplot (it runs in a process group of its own, which gets
!> SIGTERM) and end the program by that signal (exit 130, 143, 129 in a shell).
!> gnuplot is started with fork and exec, not system(), so that SIGINT is not ignored
!> while it runs.  The handler calls only async-signal-safe functions (kill, unlink,
!> signal, raise) on paths stored beforehand.
module hertzdamp_cli_plot
    use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char, c_funptr, c_funloc, c_ptr, c_loc, &
                                           c_null_ptr, c_intptr_t, c_long
    use hertzdamp_cli, only: fail, cli_line, EXIT_USAGE, EXIT_FAILURE, c_signal
    use hertzdamp_cli_text, only: itoa
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    private
    public :: plot_check_target, plot_run, plot_temp_name, gp_string, sh_quote, remove_file, scratch_dir

    !> The scratch files of one plot (data, curves, gnuplot script): each created new in
    !> scratch_dir(), written line by line with every write checked.  Any failure removes
    !> them all and exits 4 (one line on stderr); `draw` runs gnuplot on the script
    !> and removes them too.
    !>
    !>     type(plot_scratch) :: s
    !>     call s%open('calibrate', 'dat', u, name)   ! a new file, its unit and name
    !>     call s%write(u, line)                      ! checked
    !>     call s%close(u)                            ! flush, close, size checked
    !>     ...                                        ! more files
    !>     call s%draw(script_name, target)           ! gnuplot, checked, renamed into place
    type, public :: plot_scratch
        type(cli_line), allocatable :: names(:)     !! the files created so far
        integer, allocatable :: units(:)            !! their units (-1 once closed)
        integer(int64), allocatable :: bytes(:)     !! bytes written to each
    contains
        procedure :: open => scratch_open
        procedure :: write => scratch_write
        procedure :: close => scratch_close
        procedure :: discard => scratch_discard
        procedure :: draw => scratch_draw
    end type plot_scratch

    interface
        function c_rename(old, new) bind(C, name='rename') result(rc)
            import :: c_int, c_char
            implicit none
            character(kind=c_char), intent(in) :: old(*), new(*)
            integer(c_int) :: rc
        end function c_rename
        function c_getpid() bind(C, name='getpid') result(pid)
            import :: c_int
            implicit none
            integer(c_int) :: pid
        end function c_getpid
        function c_fork() bind(C, name='fork') result(pid)
            import :: c_int
            implicit none
            integer(c_int) :: pid
        end function c_fork
        function c_execv(path, argv) bind(C, name='execv') result(rc)
            import :: c_char, c_ptr, c_int
            implicit none
            character(kind=c_char), intent(in) :: path(*)
            type(c_ptr), intent(in) :: argv(*)
            integer(c_int) :: rc
        end function c_execv
        subroutine c_exit_child(status) bind(C, name='_exit')
            import :: c_int
            implicit none
            integer(c_int), value :: status
        end subroutine c_exit_child
        function c_waitpid(pid, status, options) bind(C, name='waitpid') result(rc)
            import :: c_int
            implicit none
            integer(c_int), value :: pid, options
            integer(c_int), intent(out) :: status
            integer(c_int) :: rc
        end function c_waitpid
        function c_setpgid(pid, pgid) bind(C, name='setpgid') result(rc)
            import :: c_int
            implicit none
            integer(c_int), value :: pid, pgid
            integer(c_int) :: rc
        end function c_setpgid
        function c_kill(pid, sig) bind(C, name='kill') result(rc)
            import :: c_int
            implicit none
            integer(c_int), value :: pid, sig
            integer(c_int) :: rc
        end function c_kill
        function c_unlink(path) bind(C, name='unlink') result(rc)
            import :: c_char, c_int
            implicit none
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int) :: rc
        end function c_unlink
        function c_raise(sig) bind(C, name='raise') result(rc)
            import :: c_int
            implicit none
            integer(c_int), value :: sig
            integer(c_int) :: rc
        end function c_raise
        function c_sigfillset(set) bind(C, name='sigfillset') result(rc)
            import :: c_long, c_int
            implicit none
            integer(c_long), intent(out) :: set(16)
            integer(c_int) :: rc
        end function c_sigfillset
        function c_sigprocmask(how, set, old) bind(C, name='sigprocmask') result(rc)
            import :: c_long, c_int
            implicit none
            integer(c_int), value :: how
            integer(c_long), intent(in) :: set(16)
            integer(c_long), intent(out) :: old(16)
            integer(c_int) :: rc
        end function c_sigprocmask
    end interface

    !> Linux signal numbers and sigprocmask operations (sigset_t: 128 bytes in glibc).
    integer(c_int), parameter :: sighup = 1, sigint = 2, sigterm = 15, sig_block = 0, sig_setmask = 2
    !> The temporary files a signal removes: NUL-terminated paths, stored before each
    !> file is created; guard_n of them are valid (volatile: read by the handler).
    integer, parameter :: guard_len = 4352, guard_max = 16
    character(kind=c_char) :: guard_paths(guard_len, guard_max)
    integer, volatile :: guard_n = 0
    !> Process group of the running gnuplot (0: none), stopped by the handler.
    integer(c_int), volatile :: guard_child = 0
    logical :: guard_installed = .false.

    !> The last 12 bytes of every complete PNG: the empty IEND chunk with its CRC.
    character(len=*), parameter :: png_end = achar(0) // achar(0) // achar(0) // achar(0) // 'IEND' // &
                                             char(174) // achar(66) // achar(96) // char(130)
    !> What a write that fails after its file was created most likely met.
    character(len=*), parameter :: full_hint = ' (disk full or file size limit?)'
    character(len=*), parameter :: png_signature = char(137) // 'PNG' // achar(13) // achar(10) // achar(26) // &
                                                   achar(10)

contains

    !> The file gnuplot draws into: $TMPDIR/hertzdamp-plot-PID.png (the same name
    !> for the whole run of this process, whatever the target).
    function plot_temp_name() result(tmp)
        character(len=:), allocatable :: tmp
        tmp = scratch_dir() // '/hertzdamp-plot-' // itoa(int(c_getpid())) // '.png'
    end function plot_temp_name

    !> The temporary name of the copy in the target's directory.
    function dir_temp_name(file) result(tmp)
        character(len=*), intent(in) :: file
        character(len=:), allocatable :: tmp
        tmp = file // '.hertzdamp-tmp'
    end function dir_temp_name

    !> The directory of scratch files: $TMPDIR if it is set and plain (printable ASCII,
    !> no quotes or backslashes, so that it needs no quoting in a gnuplot script), else
    !> /tmp.
    function scratch_dir() result(dir)
        character(len=:), allocatable :: dir
        character(len=4096) :: env
        integer :: ln, st, i
        call get_environment_variable('TMPDIR', env, length=ln, status=st)
        dir = '/tmp'
        if (st /= 0 .or. ln == 0 .or. ln > len(env)) return
        do i = 1, ln
            if (iachar(env(i:i)) < 32 .or. iachar(env(i:i)) > 126 .or. index('''"\', env(i:i)) > 0) return
        end do
        dir = env(1:ln)
    end function scratch_dir

    !> Before any work: gnuplot exists (else exit 4); the target, if it exists, is a
    !> regular file (tested, never opened; else exit 2), writable and none of `inputs`
    !> (the same file under any name; else exit 2); its directory takes a new file;
    !> the temporary names are free (else exit 2).  Returns the PNG terminal gnuplot
    !> offers (pngcairo or png).
    subroutine plot_check_target(file, terminal, inputs)
        character(len=*), intent(in) :: file
        character(len=:), allocatable, intent(out) :: terminal
        character(len=*), intent(in), optional :: inputs(:)   !! files the command reads
        integer :: es, cs, i
        if (len_trim(file) == 0) call fail(EXIT_USAGE, 'option --plot needs a file name')
        call check_kind(file)
        if (present(inputs)) then
            do i = 1, size(inputs)
                if (same_file(file, trim(inputs(i)))) call fail(EXIT_USAGE, 'the plot file "' // file // &
                    '" is the input file "' // trim(inputs(i)) // '"; refused (it would be overwritten)')
            end do
        end if
        es = 1
        cs = 0
        call execute_command_line('command -v gnuplot >/dev/null 2>&1', exitstat=es, cmdstat=cs)
        if (cs /= 0 .or. es /= 0) call fail(EXIT_FAILURE, '--plot needs gnuplot, which was not found ' // &
                                              '(Debian: apt-get install gnuplot-nox)')
        es = 1
        call execute_command_line('gnuplot -e "set terminal pngcairo" >/dev/null 2>&1', exitstat=es, cmdstat=cs)
        terminal = 'png'
        if (cs == 0 .and. es == 0) terminal = 'pngcairo'
        call check_new(dir_temp_name(file), 'cannot write the plot file "' // file // '" (directory not writable?)')
        call check_new(plot_temp_name(), 'cannot write a temporary file in ' // scratch_dir())
    end subroutine plot_check_target

    !> Exit 2 unless `file` is absent or a writable regular file; the test does not
    !> open the file (a FIFO would block, a device would be touched).
    subroutine check_kind(file)
        character(len=*), intent(in) :: file
        integer :: es, cs
        es = -1
        call execute_command_line('f=' // sh_quote(file) // '; if [ -d "$f" ]; then exit 3; ' // &
                                  'elif [ -f "$f" ]; then [ -w "$f" ] || exit 4; ' // &
                                  'elif [ -e "$f" ] || [ -L "$f" ]; then exit 5; fi; exit 0', exitstat=es, cmdstat=cs)
        if (cs /= 0) call fail(EXIT_FAILURE, 'cannot run /bin/sh to check the plot file')
        select case (es)
        case (0)
        case (3); call fail(EXIT_USAGE, 'the plot file "' // file // '" is a directory')
        case (4); call fail(EXIT_USAGE, 'cannot write the plot file "' // file // '"')
        case default
            call fail(EXIT_USAGE, 'the plot file "' // file // '" exists and is not a regular file ' // &
                      '(a device, FIFO, socket or dangling link); refused')
        end select
    end subroutine check_kind

    !> True when both names exist and are the same file (device and inode, test -ef).
    logical function same_file(a, b)
        character(len=*), intent(in) :: a, b
        integer :: es, cs
        es = 1
        call execute_command_line('[ ' // sh_quote(a) // ' -ef ' // sh_quote(b) // ' ]', exitstat=es, cmdstat=cs)
        if (cs /= 0) call fail(EXIT_FAILURE, 'cannot run /bin/sh to check the plot file')
        same_file = es == 0
    end function same_file

    !> Exit 2 unless `tmp` can be created as a new file (then it is removed again).
    subroutine check_new(tmp, message)
        character(len=*), intent(in) :: tmp, message
        integer :: u, ios
        logical :: exists
        inquire (file=tmp, exist=exists)
        if (exists) call fail(EXIT_USAGE, 'the temporary file "' // tmp // '" is in the way')
        open (newunit=u, file=tmp, status='new', action='write', iostat=ios)
        if (ios /= 0) call fail(EXIT_USAGE, message)
        close (u, status='delete')
    end subroutine check_new

    !> Run gnuplot on `script` (which draws into png_tmp = plot_temp_name()),
    !> check its output, copy the PNG next to the target and rename it into place.
    !> `script` and the `scratch` files are removed whatever happens; on failure exit 4
    !> with nothing left behind.
    subroutine plot_run(script, png_tmp, target, scratch)
        character(len=*), intent(in) :: script, png_tmp, target
        character(len=*), intent(in) :: scratch(:)
        integer :: es, cs, i
        character(len=:), allocatable :: errfile, why, png
        errfile = png_tmp // '.err'
        call guard(errfile)
        call guard(png_tmp)
        call guard(dir_temp_name(target))
        call run_gnuplot(script, errfile, es, cs)
        call remove_file(script)
        do i = 1, size(scratch)
            call remove_file(trim(scratch(i)))
        end do
        why = ''
        if (cs /= 0 .or. es /= 0) why = 'gnuplot failed (exit ' // itoa(es) // ')'
        if (len(why) == 0) why = gnuplot_errors(errfile)
        call remove_file(errfile)
        if (len(why) == 0) then
            call read_bytes(png_tmp, png, why)
            if (len(why) == 0) then
                if (len(png) < len(png_signature) + len(png_end)) then
                    why = 'gnuplot wrote an incomplete PNG'
                else if (png(1:len(png_signature)) /= png_signature .or. png(len(png) - len(png_end) + 1:) /= png_end) then
                    why = 'gnuplot wrote an incomplete PNG, no IEND chunk' // full_hint
                end if
            end if
        end if
        call remove_file(png_tmp)
        if (len(why) == 0) call write_bytes(dir_temp_name(target), png, why)
        if (len(why) == 0) then
            if (c_rename(c_str(dir_temp_name(target)), c_str(target)) /= 0) why = 'cannot rename the plot into place'
        end if
        if (len(why) > 0) then
            call remove_file(dir_temp_name(target))
            call fail(EXIT_FAILURE, why // ': no plot written to "' // target // '"')
        end if
    end subroutine plot_run

    !> The first line of gnuplot's error stream that is not a warning, or ''.
    function gnuplot_errors(errfile) result(why)
        character(len=*), intent(in) :: errfile
        character(len=:), allocatable :: why
        character(len=1024) :: line
        integer :: u, ios
        why = ''
        open (newunit=u, file=errfile, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (len_trim(line) == 0 .or. index(line, 'arning') > 0) cycle
            why = 'gnuplot: ' // trim(adjustl(line))
            exit
        end do
        close (u)
    end function gnuplot_errors

    !> The whole file as bytes; `why` says what went wrong ('' on success).
    subroutine read_bytes(file, bytes, why)
        character(len=*), intent(in) :: file
        character(len=:), allocatable, intent(out) :: bytes
        character(len=:), allocatable, intent(inout) :: why
        integer :: u, ios, n
        open (newunit=u, file=file, status='old', action='read', access='stream', form='unformatted', iostat=ios)
        if (ios /= 0) then
            bytes = ''
            why = 'gnuplot wrote no plot'
            return
        end if
        inquire (unit=u, size=n)
        allocate (character(len=max(n, 0)) :: bytes)
        if (n <= 0) then
            close (u)
            why = 'gnuplot wrote an empty plot'
            return
        end if
        read (u, iostat=ios) bytes
        close (u)
        if (ios /= 0) why = 'cannot read the plot gnuplot wrote'
    end subroutine read_bytes

    !> Write `bytes` to a new file, checking the write and the close (a full disk).
    subroutine write_bytes(file, bytes, why)
        character(len=*), intent(in) :: file, bytes
        character(len=:), allocatable, intent(inout) :: why
        integer :: u, ios, n, ios_close
        open (newunit=u, file=file, status='new', action='write', access='stream', form='unformatted', iostat=ios)
        if (ios /= 0) then
            why = 'cannot create the temporary plot file'
            return
        end if
        write (u, iostat=ios) bytes
        if (ios == 0) flush (u, iostat=ios)
        if (ios /= 0) then
            close (u, iostat=ios_close)   ! the write failed already: its status decides
            why = 'cannot write the plot' // full_hint
            if (ios_close /= 0) why = why // ' (and cannot close it)'
            return
        end if
        close (u, iostat=ios)
        if (ios /= 0) then
            why = 'cannot write the plot' // full_hint
            return
        end if
        n = -1
        inquire (file=file, size=n)
        if (n /= len(bytes)) why = 'the plot was written incompletely' // full_hint
    end subroutine write_bytes

    !> Remove a file if it exists.
    subroutine remove_file(file)
        character(len=*), intent(in) :: file
        integer :: u, ios
        logical :: exists
        inquire (file=file, exist=exists)
        if (.not. exists) return
        open (newunit=u, file=file, status='old', iostat=ios)
        if (ios == 0) close (u, status='delete')
    end subroutine remove_file

    !> Create a new scratch file scratch_dir()/hertzdamp_TAG_PID_N.EXT (N the first
    !> free number: status='new' never opens someone else's file); exit 4 when none
    !> can be created.
    subroutine scratch_open(self, tag, ext, unit, name)
        class(plot_scratch), intent(inout) :: self
        character(len=*), intent(in) :: tag, ext          !! e.g. 'calibrate', 'dat'
        integer, intent(out) :: unit
        character(len=:), allocatable, intent(out) :: name
        integer :: try, ios
        logical :: taken
        if (.not. allocated(self%names)) allocate (self%names(0), self%units(0), self%bytes(0))
        ios = 1
        do try = 1, 100
            name = scratch_dir() // '/hertzdamp_' // tag // '_' // itoa(int(c_getpid())) // '_' // itoa(try) // &
                   '.' // ext
            inquire (file=name, exist=taken)
            if (taken) cycle   ! someone else's: never guarded, never removed
            call guard(name)
            open (newunit=unit, file=name, status='new', action='write', iostat=ios)
            if (ios == 0) exit
        end do
        if (ios /= 0) call self%discard('cannot create a temporary file in ' // scratch_dir())
        self%names = [self%names, cli_line(name)]
        self%units = [self%units, unit]
        self%bytes = [self%bytes, 0_int64]
    end subroutine scratch_open

    !> Write one line to a scratch file; exit 4 (removing every scratch file) on failure.
    subroutine scratch_write(self, unit, line)
        class(plot_scratch), intent(inout) :: self
        integer, intent(in) :: unit
        character(len=*), intent(in) :: line
        integer :: ios, i
        i = findloc(self%units, unit, dim=1)
        write (unit, '(a)', iostat=ios) line
        if (ios /= 0) call self%discard('cannot write a temporary file in ' // scratch_dir() // full_hint)
        self%bytes(i) = self%bytes(i) + len(line) + 1
    end subroutine scratch_write

    !> Flush and close a scratch file and compare its size with the bytes written (a
    !> full disk can show only here); exit 4 (removing every scratch file) on failure.
    subroutine scratch_close(self, unit)
        class(plot_scratch), intent(inout) :: self
        integer, intent(in) :: unit
        integer :: ios, ios_close, i
        integer(int64) :: n
        i = findloc(self%units, unit, dim=1)
        flush (unit, iostat=ios)
        close (unit, iostat=ios_close)
        self%units(i) = -1
        n = -1
        if (ios == 0 .and. ios_close == 0) inquire (file=self%names(i)%s, size=n)
        if (n /= self%bytes(i)) call self%discard('cannot write a temporary file in ' // scratch_dir() // full_hint)
    end subroutine scratch_close

    !> Remove every scratch file (closing those still open) and, with a message, exit 4.
    subroutine scratch_discard(self, message)
        class(plot_scratch), intent(inout) :: self
        character(len=*), intent(in), optional :: message
        integer :: i, ios
        if (allocated(self%names)) then
            do i = 1, size(self%names)
                ios = 1
                if (self%units(i) >= 0) close (self%units(i), status='delete', iostat=ios)
                ! closed before, or the close could not delete it: by name
                if (ios /= 0) call remove_file(self%names(i)%s)
                self%units(i) = -1
            end do
        end if
        if (present(message)) call fail(EXIT_FAILURE, message)
    end subroutine scratch_discard

    !> Run gnuplot on the scratch file `script` (which draws into plot_temp_name())
    !> and put the PNG in place (plot_run); every scratch file is removed.
    subroutine scratch_draw(self, script, target)
        class(plot_scratch), intent(inout) :: self
        character(len=*), intent(in) :: script, target
        integer :: i, n, m
        if (.not. allocated(self%names)) call self%discard('no temporary files for the plot')
        n = 1
        m = 0
        do i = 1, size(self%names)
            if (self%units(i) >= 0) call self%discard('a temporary file of the plot was not closed')
            n = max(n, len(self%names(i)%s))
            if (self%names(i)%s /= script) m = m + 1
        end do
        call draw_with(self, script, target, n, m)
    end subroutine scratch_draw

    !> plot_run with the scratch files other than the script: m names of length <= n.
    subroutine draw_with(self, script, target, n, m)
        class(plot_scratch), intent(in) :: self
        character(len=*), intent(in) :: script, target
        integer, intent(in) :: n, m
        character(len=n) :: others(m)
        integer :: i, k
        k = 0
        do i = 1, size(self%names)
            if (self%names(i)%s == script) cycle
            k = k + 1
            others(k) = self%names(i)%s
        end do
        call plot_run(script, plot_temp_name(), target, others)
    end subroutine draw_with

    !> Remember a temporary file for the signal handler (before it is created), and
    !> install the handler with the first one.  A name that does not fit a slot, or
    !> beyond guard_max of them, is not guarded (none is: at most 6 per plot).
    subroutine guard(path)
        character(len=*), intent(in) :: path
        integer :: i
        if (len(path) >= guard_len .or. guard_n >= guard_max) return
        do i = 1, guard_n
            if (same_c_path(guard_paths(:, i), path)) return
        end do
        do i = 1, len(path)
            guard_paths(i, guard_n + 1) = path(i:i)
        end do
        guard_paths(len(path) + 1, guard_n + 1) = c_null_char
        guard_n = guard_n + 1   ! only now does the handler see the slot
        if (.not. guard_installed) then
            call catch(sigint)
            call catch(sigterm)
            call catch(sighup)
            guard_installed = .true.
        end if
    end subroutine guard

    !> True when the NUL-terminated `c` holds `path`.
    pure logical function same_c_path(c, path)
        character(kind=c_char), intent(in) :: c(:)
        character(len=*), intent(in) :: path
        integer :: i
        same_c_path = .false.
        if (len(path) + 1 > size(c)) return
        do i = 1, len(path)
            if (c(i) /= path(i:i)) return
        end do
        same_c_path = c(len(path) + 1) == c_null_char
    end function same_c_path

    !> Catch `sig` with on_signal, unless it was ignored (a background job's SIGINT).
    subroutine catch(sig)
        integer(c_int), intent(in) :: sig
        type(c_funptr) :: previous, ignored
        previous = c_signal(sig, c_funloc(on_signal))
        if (transfer(previous, 0_c_intptr_t) == 1_c_intptr_t) ignored = c_signal(sig, previous)   ! SIG_IGN stays
    end subroutine catch

    !> The handler: stop gnuplot's process group, remove the guarded files, and end the
    !> program by the same signal (default action).  Async-signal-safe calls only.
    subroutine on_signal(sig) bind(C)
        integer(c_int), value :: sig
        integer(c_int) :: rc
        type(c_funptr) :: previous
        integer :: i
        if (guard_child > 0) rc = c_kill(-guard_child, sigterm)
        do i = 1, guard_n
            rc = c_unlink(guard_paths(:, i))
        end do
        previous = c_signal(sig, transfer(0_c_intptr_t, previous))   ! SIG_DFL
        rc = c_raise(sig)
    end subroutine on_signal

    !> gnuplot SCRIPT with stdout to /dev/null and stderr to ERRFILE, in a process group
    !> of its own (the handler stops it there), waited for.  es: its exit status (-1 if
    !> it ended by a signal), cs: 0, or 1 when it could not be started.  Signals are
    !> blocked from fork until the child's process group is recorded; the child only
    !> unblocks them, sets its group and executes /bin/sh (no Fortran runtime there).
    subroutine run_gnuplot(script, errfile, es, cs)
        character(len=*), intent(in) :: script, errfile
        integer, intent(out) :: es, cs
        character(kind=c_char), allocatable, target :: sh(:), a0(:), a1(:), a2(:), a3(:), a4(:)
        type(c_ptr) :: argv(7)
        integer(c_long) :: all_signals(16), old_mask(16)
        integer(c_int) :: pid, rc, status
        allocate (sh, source=c_str('/bin/sh'))
        allocate (a0, source=c_str('sh'))
        allocate (a1, source=c_str('-c'))
        allocate (a2, source=c_str('exec gnuplot "$1" >/dev/null 2>"$2"'))
        allocate (a3, source=c_str(script))
        allocate (a4, source=c_str(errfile))
        ! sh -c CMD sh SCRIPT ERRFILE: the names are $1 and $2, no quoting needed
        argv = [c_loc(a0), c_loc(a1), c_loc(a2), c_loc(a0), c_loc(a3), c_loc(a4), c_null_ptr]
        es = -1
        cs = 1
        rc = c_sigfillset(all_signals)
        rc = c_sigprocmask(sig_block, all_signals, old_mask)
        pid = c_fork()
        if (pid == 0) then
            rc = c_sigprocmask(sig_setmask, old_mask, all_signals)
            rc = c_setpgid(0_c_int, 0_c_int)
            rc = c_execv(sh, argv)
            call c_exit_child(127_c_int)
        end if
        if (pid > 0) then
            rc = c_setpgid(pid, pid)
            guard_child = pid
        end if
        rc = c_sigprocmask(sig_setmask, old_mask, all_signals)
        if (pid < 0) return
        do
            rc = c_waitpid(pid, status, 0_c_int)
            if (rc == pid .or. rc /= -1) exit
        end do
        guard_child = 0
        if (rc /= pid) return
        cs = 0
        if (iand(status, 127_c_int) == 0) es = iand(ishft(status, -8), 255_c_int)
    end subroutine run_gnuplot

    function c_str(s) result(c)
        character(len=*), intent(in) :: s
        character(kind=c_char) :: c(len(s) + 1)
        integer :: i
        do i = 1, len(s)
            c(i) = s(i:i)
        end do
        c(len(s) + 1) = c_null_char
    end function c_str

    !> A POSIX shell single-quoted word.
    function sh_quote(s) result(r)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: r
        integer :: i
        r = ''''
        do i = 1, len(s)
            if (s(i:i) == '''') then
                r = r // '''\'''''
            else
                r = r // s(i:i)
            end if
        end do
        r = r // ''''
    end function sh_quote

    !> A gnuplot single-quoted string ('' stands for one quote).
    function gp_string(s) result(r)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: r
        integer :: i
        r = ''''
        do i = 1, len(s)
            if (s(i:i) == '''') r = r // ''''
            r = r // s(i:i)
        end do
        r = r // ''''
    end function gp_string

end module hertzdamp_cli_plot
