!> Progress of long work on stderr: a percentage and an estimate of the time left.
!>
!> Shown only when stderr is a terminal, or when the user asked for it (`--progress`);
!> stdout is never touched.
!>
!> - On a terminal: nothing for work that ends within `delay` seconds (default 2);
!>   then one line, rewritten in place (carriage return) at most 4 times a second and
!>   erased by `finish`.  An error message (hertzdamp_cli error_line) erases it too
!>   and takes its place, so a failing command still shows exactly one line.
!> - With --progress into a file or pipe: a full line `hertzdamp: LABEL: ... % done,
!>   about ... left` (or `: starting`) at once and then at most every 5 seconds.  These
!>   lines were asked for and stay: on failure they precede the one error line, which
!>   is always the last line of stderr.
!>
!> Interface (a command with a `--progress` flag):
!>
!>     use hertzdamp_cli_progress, only: progress_reporter
!>     type(progress_reporter) :: p
!>     call p%start(real(total_steps, wp), 'scene', force=args%has('--progress'))
!>     do step = 1, total_steps
!>         ...                                   ! the work
!>         call p%update(real(step, wp))         ! cheap: reads the clock, prints rarely
!>     end do
!>     call p%finish()                           ! before printing the result
!>
!> `total` and `done` are in any unit of work (steps, runs, simulated seconds); the time
!> left is elapsed * (total - done) / done.  A second phase is a second start/finish.
!>
!> A progress write that fails (stderr a pipe nobody reads any more) is dropped, and so
!> is every later report of the run: SIGPIPE is ignored while a report is written, so
!> that such a write fails instead of killing the program before its results reach
!> stdout, and stays ignored after a failed one (the runtime would retry the write).
module hertzdamp_cli_progress
    use hertzdamp, only: hertzdamp_rk
    use, intrinsic :: iso_fortran_env, only: error_unit, int64
    use, intrinsic :: iso_c_binding, only: c_int, c_funptr, c_intptr_t, c_size_t, c_long
    ! write(2): a report goes to stderr unbuffered, and a failed write is seen (the
    ! Fortran runtime does not report EPIPE on the error unit, and retries it)
    use hertzdamp_cli, only: stderr_is_terminal, c_write, c_signal
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> SIGPIPE on Linux.
    integer(c_int), parameter :: sigpipe = 13

    !> Set once a report could not be written: no more reports in this run.
    logical :: stderr_broken = .false.

    !> A progress line on stderr.
    type, public :: progress_reporter
        logical :: active = .false.          !! reporting at all (terminal or forced)
        logical :: tty = .false.             !! stderr is a terminal: rewrite one line
        logical :: shown = .false.           !! something was printed
        real(wp) :: total = 1.0_wp           !! work in all
        real(wp) :: delay = 2.0_wp           !! seconds before the first report
        integer(int64) :: t0 = 0, last = 0, rate = 1
        character(len=:), allocatable :: label
    contains
        procedure :: start => progress_start    !! (total, label [, force] [, delay])
        procedure :: update => progress_update  !! (done)
        procedure :: finish => progress_finish  !! erase the line (terminal) or end it
    end type progress_reporter

contains

    !> Begin a piece of work of size `total`, called `label` in the progress line.
    subroutine progress_start(self, total, label, force, delay)
        class(progress_reporter), intent(inout) :: self
        real(wp), intent(in) :: total            !! amount of work (> 0)
        character(len=*), intent(in) :: label    !! e.g. 'scene', 'bench forward'
        logical, intent(in), optional :: force   !! report even when stderr is not a terminal
        real(wp), intent(in), optional :: delay  !! seconds of silence first (default 2)
        self%tty = stderr_is_terminal()
        self%active = self%tty
        if (present(force)) self%active = self%active .or. force
        self%total = max(total, tiny(1.0_wp))
        self%label = label
        self%shown = .false.
        ! on request, from the start; on a terminal alone, only for work over 2 s
        self%delay = merge(0.0_wp, 2.0_wp, self%active .and. .not. self%tty)
        if (present(delay)) self%delay = max(delay, 0.0_wp)
        call system_clock(self%t0, self%rate)
        self%last = self%t0
    end subroutine progress_start

    !> `done` units of the work are done: print the line if it is time to.
    subroutine progress_update(self, done)
        class(progress_reporter), intent(inout) :: self
        real(wp), intent(in) :: done
        integer(int64) :: now
        real(wp) :: elapsed, since, frac, left
        character(len=96) :: line
        if (.not. self%active) return
        call system_clock(now)
        elapsed = real(now - self%t0, wp) / real(self%rate, wp)
        since = real(now - self%last, wp) / real(self%rate, wp)
        if (elapsed < self%delay) return
        if (self%shown .and. since < merge(0.25_wp, 5.0_wp, self%tty)) return
        self%last = now
        frac = min(max(done / self%total, 0.0_wp), 1.0_wp)
        if (frac > 0.0_wp) then
            left = elapsed * (1.0_wp - frac) / frac
            write (line, '(a,f5.1,a,a,a)') ': ', 100.0_wp * frac, ' % done, about ', trim(duration(left)), ' left'
        else
            write (line, '(a)') ': starting'
        end if
        if (self%tty) then
            call report(self, achar(13) // 'hertzdamp: ' // self%label // trim(line) // achar(27) // '[K', .false.)
        else
            call report(self, 'hertzdamp: ' // self%label // trim(line), .true.)
        end if
        self%shown = .true.
    end subroutine progress_update

    !> End the work: erase the progress line on a terminal.
    subroutine progress_finish(self)
        class(progress_reporter), intent(inout) :: self
        if (self%active .and. self%shown .and. self%tty) call report(self, achar(13) // achar(27) // '[K', .false.)
        self%active = .false.
        self%shown = .false.
    end subroutine progress_finish

    !> Write one report to stderr (a whole line, or a part of one) with write(2) and
    !> SIGPIPE ignored meanwhile; if that fails, stop reporting, silently.
    subroutine report(self, text, whole_line)
        class(progress_reporter), intent(inout) :: self
        character(len=*), intent(in) :: text
        logical, intent(in) :: whole_line
        character(len=:), allocatable :: bytes
        type(c_funptr) :: previous, ignored
        integer(c_long) :: n
        integer :: done
        if (stderr_broken) then
            self%active = .false.
            return
        end if
        bytes = text
        if (whole_line) bytes = bytes // achar(10)
        flush (error_unit)   ! anything the runtime holds for stderr goes first
        previous = c_signal(sigpipe, transfer(1_c_intptr_t, previous))   ! 1 = SIG_IGN
        done = 0
        do while (done < len(bytes))
            n = c_write(2_c_int, bytes(done + 1:), int(len(bytes) - done, c_size_t))
            if (n <= 0) exit
            done = done + int(n)
        end do
        if (done < len(bytes)) then
            ! stderr is gone: SIGPIPE stays ignored, so that a later message on stderr
            ! fails as well instead of killing the program
            stderr_broken = .true.
            self%active = .false.
        else
            ignored = c_signal(sigpipe, previous)
        end if
    end subroutine report

    !> A duration for people: 42 s, 3 min 5 s, 2 h 10 min.
    function duration(t) result(s)
        real(wp), intent(in) :: t
        character(len=:), allocatable :: s
        character(len=32) :: buf
        integer :: n
        n = nint(min(max(t, 0.0_wp), 3.6e8_wp))
        if (n < 60) then
            write (buf, '(i0,a)') n, ' s'
        else if (n < 3600) then
            write (buf, '(i0,a,i0,a)') n / 60, ' min ', mod(n, 60), ' s'
        else
            write (buf, '(i0,a,i0,a)') n / 3600, ' h ', mod(n, 3600) / 60, ' min'
        end if
        s = trim(buf)
    end function duration

end module hertzdamp_cli_progress
