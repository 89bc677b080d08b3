!> Command-line support: strict option parsing, number parsing, output buffering
!> and the exit codes of the `hertzdamp` program.
!>
!> Every command parses all of its arguments and computes all of its rows before it
!> prints anything: on bad usage (exit 2) or no solution (exit 3) stdout stays empty
!> and stderr gets one line.
module hertzdamp_cli
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_NO_REBOUND, HD_BAD_RESTITUTION, HD_OUTSIDE_VALIDITY, &
                         HD_OUT_OF_RANGE, HD_MAX_STEPS, HD_STEP_UNDERFLOW, HD_NO_CONVERGENCE
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_size_t, c_long, c_funptr, c_intptr_t
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use hertzdamp_cli_text, only: one_line, fmt_csv, fmt_text, fmt_json, json_string, fmt_short, itoa
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    integer, parameter, public :: EXIT_OK = 0        !! success
    integer, parameter, public :: EXIT_USAGE = 2     !! bad usage: unknown option, malformed number, ...
    integer, parameter, public :: EXIT_NO_SOLUTION = 3 !! valid input without a solution
    integer, parameter, public :: EXIT_FAILURE = 4   !! the computation itself failed

    !> Largest number of values a list or range option may produce.
    integer, parameter, public :: max_list_length = 10000

    !> One `--key value` pair (value empty for flags).
    type, public :: cli_option
        character(len=:), allocatable :: key
        character(len=:), allocatable :: val
    end type cli_option

    !> The parsed options of one command.
    type, public :: cli_args
        type(cli_option), allocatable :: opts(:)
        character(len=:), allocatable :: positional  !! the single positional argument, if any
    contains
        procedure :: has => args_has
        procedure :: get => args_get
    end type cli_args

    !> Variable-length line.
    type, public :: cli_line
        character(len=:), allocatable :: s
    end type cli_line

    !> Output collected before it is printed.
    type, public :: cli_buffer
        type(cli_line), allocatable :: lines(:)
        integer :: n = 0
    contains
        procedure :: add => buffer_add
        procedure :: flush_to_stdout => buffer_flush
    end type cli_buffer

    interface
        !> POSIX write(2): stdout is written with it so that a failed write is seen.
        function c_write(fd, buf, n) bind(C, name='write') result(written)
            import :: c_int, c_char, c_size_t, c_long
            implicit none
            integer(c_int), value :: fd
            character(kind=c_char), intent(in) :: buf(*)
            integer(c_size_t), value :: n
            integer(c_long) :: written
        end function c_write
        subroutine c_exit(status) bind(C, name='exit')
            import :: c_int
            implicit none
            integer(c_int), value :: status
        end subroutine c_exit
        function c_isatty(fd) bind(C, name='isatty') result(r)
            import :: c_int
            implicit none
            integer(c_int), value :: fd
            integer(c_int) :: r
        end function c_isatty
        function c_signal(sig, handler) bind(C, name='signal') result(previous)
            import :: c_int, c_funptr
            implicit none
            integer(c_int), value :: sig
            type(c_funptr), value :: handler
            type(c_funptr) :: previous
        end function c_signal
    end interface

    !> SIGXFSZ (file size limit exceeded) on Linux.
    integer(c_int), parameter :: sigxfsz = 25

    public :: get_arg, parse_args, parse_real, parse_real_list, parse_range, parse_sweep, required_sweep, parse_int, parse_choice
    public :: check_combinations, did_you_mean
    public :: exit_code_of, write_failed, write_stdout, error_line, stderr_is_terminal, cli_start
    public :: fail, quit, fmt_csv, fmt_text, fmt_json, fmt_short, json_string, csv_join, pad
    public :: c_write, c_signal   ! POSIX write(2) and signal(2), for the progress and plot modules

contains

    !> The exit code for a library status: 3 when the input is valid but has no solution
    !> (target outside the method's range, result not representable), 4 when the
    !> computation failed (step limit, step underflow, no convergence), 2 otherwise.
    integer function exit_code_of(status) result(code)
        integer, intent(in) :: status   !! a status returned by hertzdamp
        select case (status)
        case (HD_OK, HD_NO_REBOUND)
            code = EXIT_OK
        case (HD_BAD_RESTITUTION, HD_OUTSIDE_VALIDITY, HD_OUT_OF_RANGE)
            code = EXIT_NO_SOLUTION
        case (HD_MAX_STEPS, HD_STEP_UNDERFLOW, HD_NO_CONVERGENCE)
            code = EXIT_FAILURE
        case default
            code = EXIT_USAGE
        end select
    end function exit_code_of

    !> Set up the process before any command: ignore SIGXFSZ, so that a write beyond
    !> `ulimit -f` fails (EFBIG) and is reported like a full disk (exit 4, nothing
    !> left behind) instead of killing the program with its output half-written.
    !> gnuplot, started for --plot, inherits this.
    subroutine cli_start()
        type(c_funptr) :: previous
        previous = c_signal(sigxfsz, transfer(1_c_intptr_t, previous))   ! 1 = SIG_IGN
    end subroutine cli_start

    !> True when stderr is a terminal.
    logical function stderr_is_terminal()
        stderr_is_terminal = c_isatty(2_c_int) == 1_c_int
    end function stderr_is_terminal

    !> Write `hertzdamp: message` on stderr as one line (control characters escaped).
    !> On a terminal it first returns to the start of the line and erases it, so that
    !> it replaces a progress line being shown (hertzdamp_cli_progress) instead of
    !> being appended to it: a failing command shows exactly one line.
    subroutine error_line(message)
        character(len=*), intent(in) :: message
        if (stderr_is_terminal()) write (error_unit, '(a)', advance='no') achar(13) // achar(27) // '[K'
        write (error_unit, '(a)') 'hertzdamp: ' // one_line(message)
        flush (error_unit)
    end subroutine error_line

    !> Stdout could not be written (a full disk, a closed pipe): one line on stderr, exit 4.
    subroutine write_failed()
        call error_line('cannot write the output (stdout)')
        call c_exit(int(EXIT_FAILURE, c_int))
    end subroutine write_failed

    !> Print `hertzdamp: message` on stderr and exit with `code` (stdout untouched).
    subroutine fail(code, message)
        integer, intent(in) :: code            !! exit code
        character(len=*), intent(in) :: message !! the message (control characters are escaped)
        call error_line(message)
        call quit(code)
    end subroutine fail

    !> Exit with a code, after flushing the standard units.
    subroutine quit(code)
        integer, intent(in) :: code   !! exit code
        flush (output_unit)
        flush (error_unit)
        call c_exit(int(code, c_int))
    end subroutine quit

    !> Parse the arguments from position `first` on.  `valued` and `flags` are
    !> space-separated option names; any other `--option`, a repeated option or a
    !> missing value is an error (exit 2).  At most one positional argument if
    !> `allow_positional`; any number, in order, into `positionals` when present.
    subroutine parse_args(first, valued, flags, args, allow_positional, positionals)
        integer, intent(in) :: first
        character(len=*), intent(in) :: valued, flags
        type(cli_args), intent(out) :: args
        logical, intent(in), optional :: allow_positional
        type(cli_line), allocatable, intent(out), optional :: positionals(:)
        integer :: i, n, j, np
        character(len=:), allocatable :: a, v
        type(cli_line), allocatable :: pos(:)
        logical :: pos_ok
        pos_ok = .false.
        if (present(allow_positional)) pos_ok = allow_positional
        allocate (args%opts(0))
        n = command_argument_count()
        ! positionals collected in an array of the argument count (linear in the arguments)
        allocate (pos(max(0, n - first + 1)))
        np = 0
        i = first
        do while (i <= n)
            a = get_arg(i)
            v = ''
            if (len(a) >= 2) then
                if (a(1:2) == '--') then
                    j = index(a, '=')
                    if (j > 0) then
                        v = a(j + 1:)
                        a = a(1:j - 1)
                        if (.not. in_list(a, valued)) call unknown(a, valued, flags)
                    else if (in_list(a, flags)) then
                        v = ''
                    else if (in_list(a, valued)) then
                        if (i == n) call fail(EXIT_USAGE, 'option ' // a // ' needs a value')
                        i = i + 1
                        v = get_arg(i)
                    else
                        call unknown(a, valued, flags)
                    end if
                    if (args%has(a)) call fail(EXIT_USAGE, 'option ' // a // ' given more than once')
                    args%opts = [args%opts, cli_option(a, v)]
                    i = i + 1
                    cycle
                end if
            end if
            if (present(positionals)) then
                np = np + 1
                pos(np)%s = a
            else if (pos_ok .and. .not. allocated(args%positional)) then
                args%positional = a
            else
                call fail(EXIT_USAGE, 'unexpected argument "' // a // '" (see --help)')
            end if
            i = i + 1
        end do
        if (present(positionals)) positionals = pos(1:np)
    end subroutine parse_args

    subroutine unknown(a, valued, flags)
        character(len=*), intent(in) :: a, valued, flags
        if (in_list(a, flags)) then
            call fail(EXIT_USAGE, 'option ' // a // ' takes no value')
        else
            call fail(EXIT_USAGE, 'unknown option ' // a // did_you_mean(a, valued // ' ' // flags) // ' (see --help)')
        end if
    end subroutine unknown

    !> '; did you mean X?' for the word of the space-separated `candidates` closest to
    !> `word`, '' when none is close: a candidate that `word` begins (the shortest such,
    !> `--youngs` -> --youngs-modulus), else one within an edit distance (insertions,
    !> deletions, substitutions, swaps of neighbours) of a third of its length, at least
    !> 1 and at most 3 (`--radus` -> --radius, `inverse` -> invert).  Ties are all named.
    function did_you_mean(word, candidates) result(s)
        character(len=*), intent(in) :: word         !! what was typed (an option, a command, a choice)
        character(len=*), intent(in) :: candidates   !! the words it could have meant, space-separated
        character(len=:), allocatable :: s
        character(len=:), allocatable :: best, c
        integer :: i, j, d, dbest, n
        s = ''
        best = ''
        n = 0
        dbest = huge(1)
        ! stems shorter than 3 characters (after any leading dashes) suggest nothing
        if (len(word) - (verify(word, '-') - 1) < 3 .or. verify(word, '-') == 0) return
        i = 1
        do while (i <= len(candidates))
            j = index(candidates(i:) // ' ', ' ') + i - 1
            c = candidates(i:j - 1)
            i = j + 1
            if (len(c) == 0 .or. c == word) cycle
            if (len(c) > len(word)) then
                if (c(1:len(word)) == word) then
                    d = -huge(1) + len(c)   ! a completion: before any edit, the shortest first
                else
                    d = edit_distance(word, c)
                end if
            else
                d = edit_distance(word, c)
            end if
            if (d > 0 .and. d > max(1, min(3, len(word) / 3))) cycle
            if (d < dbest) then
                dbest = d
                best = c
                n = 1
            else if (d == dbest .and. n < 3) then
                best = best // ' or ' // c
                n = n + 1
            end if
        end do
        if (n > 0) s = '; did you mean ' // best // '?'
    end function did_you_mean

    !> Optimal string alignment distance: the fewest insertions, deletions, substitutions
    !> and swaps of neighbouring characters that turn `a` into `b`.
    pure integer function edit_distance(a, b) result(d)
        character(len=*), intent(in) :: a, b
        integer :: t(0:len(a), 0:len(b)), i, j, i1, j1, cost
        do i = 0, len(a)
            t(i, 0) = i
        end do
        do j = 0, len(b)
            t(0, j) = j
        end do
        do j = 1, len(b)
            do i = 1, len(a)
                cost = merge(0, 1, a(i:i) == b(j:j))
                t(i, j) = min(t(i - 1, j) + 1, t(i, j - 1) + 1, t(i - 1, j - 1) + cost)
                ! a swap of neighbours (i, j >= 2; max() keeps the indices in range for the compiler)
                if (i > 1 .and. j > 1) then
                    i1 = max(i - 1, 1)
                    j1 = max(j - 1, 1)
                    if (a(i:i) == b(j1:j1) .and. a(i1:i1) == b(j:j)) t(i, j) = min(t(i, j), t(i1 - 1, j1 - 1) + 1)
                end if
            end do
        end do
        d = t(len(a), len(b))
    end function edit_distance

    !> Argument i of the command line, whole.
    function get_arg(i) result(a)
        integer, intent(in) :: i
        character(len=:), allocatable :: a
        integer :: l
        call get_command_argument(i, length=l)
        allocate (character(len=l) :: a)
        if (l > 0) call get_command_argument(i, a)
    end function get_arg

    logical function in_list(word, list)
        character(len=*), intent(in) :: word, list
        in_list = index(' ' // list // ' ', ' ' // word // ' ') > 0 .and. len(word) > 0
    end function in_list

    logical function args_has(self, key)
        class(cli_args), intent(in) :: self
        character(len=*), intent(in) :: key
        integer :: i
        args_has = .false.
        do i = 1, size(self%opts)
            if (self%opts(i)%key == key) args_has = .true.
        end do
    end function args_has

    !> Value of an option, or `default` when absent.
    function args_get(self, key, default) result(v)
        class(cli_args), intent(in) :: self
        character(len=*), intent(in) :: key, default
        character(len=:), allocatable :: v
        integer :: i
        v = default
        do i = 1, size(self%opts)
            if (self%opts(i)%key == key) v = self%opts(i)%val
        end do
    end function args_get

    !> A strict decimal number: [sign] digits [. digits] [e [sign] digits]; no hex,
    !> no 'inf' or 'nan', no trailing characters.  Exit 2 naming `what` otherwise.
    function parse_real(text, what) result(x)
        character(len=*), intent(in) :: text, what
        real(wp) :: x
        logical :: ok
        call read_real(text, x, ok)
        if (.not. ok) call fail(EXIT_USAGE, 'malformed number "' // text // '" for ' // what)
    end function parse_real

    !> The strict decimal number of parse_real; ok false (x = 0) when `text` is none.
    subroutine read_real(text, x, ok)
        character(len=*), intent(in) :: text
        real(wp), intent(out) :: x
        logical, intent(out) :: ok
        integer :: i, n, nd, k, ios
        character(len=:), allocatable :: s
        s = trim(adjustl(text))
        n = len(s)
        i = 1
        ok = n > 0
        if (ok) then
            if (s(1:1) == '+' .or. s(1:1) == '-') i = 2
            call skip_digits(s, i, nd)
            if (i <= n) then
                if (s(i:i) == '.') then
                    i = i + 1
                    call skip_digits(s, i, k)
                    nd = nd + k
                end if
            end if
            ok = nd > 0
            if (ok .and. i <= n) then
                if (s(i:i) == 'e' .or. s(i:i) == 'E') then
                    i = i + 1
                    if (i <= n) then
                        if (s(i:i) == '+' .or. s(i:i) == '-') i = i + 1
                    end if
                    call skip_digits(s, i, nd)
                    ok = nd > 0
                end if
            end if
            ok = ok .and. i > n
        end if
        x = 0.0_wp
        if (ok) then
            read (s, *, iostat=ios) x
            ok = ios == 0 .and. ieee_is_finite(x)
        end if
        if (.not. ok) x = 0.0_wp
    end subroutine read_real

    !> When `text` looks like a range written otherwise than A0:A1:N (a dash between
    !> two numbers, 0.05-3 but not 1e-3; '..'; '~'), the same range as A0:A1:20;
    !> '' otherwise.
    pure function range_written_otherwise(text) result(r)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: r
        integer :: i, k, w
        k = 0
        w = 0
        if (index(text, '..') > 1) then
            k = index(text, '..')
            w = 2
        else if (index(text, '~') > 1) then
            k = index(text, '~')
            w = 1
        end if
        do i = 2, len(text) - 1
            if (k > 0) exit
            if (text(i:i) /= '-') cycle
            if ((is_digit(text(i + 1:i + 1)) .or. text(i + 1:i + 1) == '.') .and. &
                (is_digit(text(i - 1:i - 1)) .or. text(i - 1:i - 1) == '.')) then
                k = i
                w = 1
            end if
        end do
        r = ''
        if (k > 0) r = text(1:k - 1) // ':' // text(k + w:) // ':20'
    end function range_written_otherwise

    !> Advance i over the decimal digits of s from position i; nd = how many.
    pure subroutine skip_digits(s, i, nd)
        character(len=*), intent(in) :: s
        integer, intent(inout) :: i
        integer, intent(out) :: nd
        nd = 0
        do while (i <= len(s))
            if (.not. is_digit(s(i:i))) exit
            i = i + 1
            nd = nd + 1
        end do
    end subroutine skip_digits

    pure logical function is_digit(c)
        character, intent(in) :: c
        is_digit = c >= '0' .and. c <= '9'
    end function is_digit

    !> A positive integer (digits only).
    integer function parse_int(text, what) result(k)
        character(len=*), intent(in) :: text, what
        integer :: i, ios
        logical :: ok
        ok = len_trim(text) > 0 .and. len_trim(text) <= 9
        do i = 1, len_trim(text)
            if (.not. is_digit(text(i:i))) ok = .false.
        end do
        k = 0
        if (ok) then
            read (text, *, iostat=ios) k
            ok = ios == 0
        end if
        if (.not. ok) call fail(EXIT_USAGE, 'malformed integer "' // text // '" for ' // what)
    end function parse_int

    !> Comma-separated numbers, none empty.
    function parse_real_list(text, what) result(x)
        character(len=*), intent(in) :: text, what
        real(wp), allocatable :: x(:)
        integer :: i, j, n
        n = 1
        do i = 1, len(text)
            if (text(i:i) == ',') n = n + 1
        end do
        if (n > max_list_length) call fail(EXIT_USAGE, 'too many values for ' // what)
        allocate (x(n))
        j = 1
        n = 0
        do i = 1, len(text) + 1
            if (i > len(text)) then
                n = n + 1
                x(n) = parse_real(text(j:), what)
            else if (text(i:i) == ',') then
                n = n + 1
                x(n) = parse_real(text(j:i - 1), what)
                j = i + 1
            end if
        end do
    end function parse_real_list

    !> `A0:A1:N`: N equally spaced values from A0 to A1 (N >= 1; N = 1 gives A0), or
    !> `A0:A1:logN`: N values spaced evenly in log from A0 to A1 (A0, A1 > 0).
    function parse_range(text, what) result(x)
        character(len=*), intent(in) :: text, what
        real(wp), allocatable :: x(:)
        integer :: i1, i2, n, i
        real(wp) :: a0, a1
        logical :: logscale
        character(len=:), allocatable :: count
        i1 = index(text, ':')
        i2 = index(text, ':', back=.true.)
        if (i1 == 0 .or. i2 == i1) call fail(EXIT_USAGE, 'range "' // text // '" for ' // what // &
                                             ' must be A0:A1:N or A0:A1:logN')
        a0 = parse_real(text(1:i1 - 1), what)
        a1 = parse_real(text(i1 + 1:i2 - 1), what)
        count = text(i2 + 1:)
        logscale = .false.
        if (len(count) >= 3) then
            logscale = count(1:3) == 'log'
            if (logscale) count = count(4:)
        end if
        n = parse_int(count, what // ' (number of points in ' // text // ')')
        if (n < 1) call fail(EXIT_USAGE, 'range "' // text // '" for ' // what // ' needs N >= 1')
        if (n > max_list_length) call fail(EXIT_USAGE, 'range "' // text // '" for ' // what // &
                                           ' has more than ' // itoa(max_list_length) // ' points')
        if (logscale .and. .not. (a0 > 0.0_wp .and. a1 > 0.0_wp)) then
            call fail(EXIT_USAGE, 'logarithmic range "' // text // '" for ' // what // ' needs A0 > 0 and A1 > 0')
        end if
        allocate (x(n))
        x(1) = a0
        do i = 2, n - 1
            if (logscale) then
                x(i) = exp(log(a0) + (log(a1) - log(a0)) * real(i - 1, wp) / real(n - 1, wp))
            else
                x(i) = range_point(a0, a1, i - 1, n - 1)
            end if
        end do
        if (n > 1) x(n) = a1
    end function parse_range

    !> Point k of m equal steps from a0 to a1: a0 + (k (a1 - a0)) / m, the product
    !> first, so that a grid of whole numbers (1:23:23, 0:1000:11) is exact: k (a1 - a0)
    !> is then an exact integer and so is its quotient by m when the step is whole.
    !> When a1 - a0 or the product overflows (-1e308:1e308:5), the weighted mean
    !> a0 (1 - t) + a1 t, t = k/m, which cannot.
    pure real(wp) function range_point(a0, a1, k, m) result(x)
        real(wp), intent(in) :: a0, a1
        integer, intent(in) :: k, m      !! 0 <= k <= m, m >= 1
        real(wp) :: p, t
        p = real(k, wp) * (a1 - a0)
        if (ieee_is_finite(p)) then
            x = a0 + p / real(m, wp)
        else
            t = real(k, wp) / real(m, wp)
            x = a0 * (1.0_wp - t) + a1 * t
        end if
    end function range_point

    !> A sweep: comma-separated items, each a number, a range A0:A1:N or a logarithmic
    !> range A0:A1:logN (see parse_range), e.g. `0.01,0.1:1:10,2:5:log4`.  At most
    !> max_list_length values in all; exit 2 naming `what` otherwise.
    function parse_sweep(text, what) result(x)
        character(len=*), intent(in) :: text   !! the option's value
        character(len=*), intent(in) :: what   !! the option's name, for messages
        real(wp), allocatable :: x(:)
        real(wp), allocatable :: part(:)
        integer :: i, j, n
        allocate (x(0))
        j = 1
        do i = 1, len(text) + 1
            if (i <= len(text)) then
                if (text(i:i) /= ',') cycle
            end if
            if (index(text(j:i - 1), ':') > 0) then
                part = parse_range(text(j:i - 1), what)
            else
                if (len(range_written_otherwise(text(j:i - 1))) > 0) call fail(EXIT_USAGE, 'malformed number "' // &
                    text(j:i - 1) // '" for ' // what // ': a range is A0:A1:N (N values from A0 to A1) or ' // &
                    'A0:A1:logN, e.g. ' // range_written_otherwise(text(j:i - 1)))
                part = [parse_real(text(j:i - 1), what)]
            end if
            n = size(x) + size(part)
            if (n > max_list_length) call fail(EXIT_USAGE, 'too many values for ' // what // ' (at most ' // &
                                               itoa(max_list_length) // ')')
            x = [x, part]
            j = i + 1
        end do
    end function parse_sweep

    !> A required sweep option (exit 2 when it is missing).
    function required_sweep(args, key) result(x)
        type(cli_args), intent(in) :: args
        character(len=*), intent(in) :: key    !! the option, e.g. '--velocity'
        real(wp), allocatable :: x(:)
        if (.not. args%has(key)) call fail(EXIT_USAGE, 'missing option ' // key // ' (see --help)')
        x = parse_sweep(args%get(key, ''), key)
    end function required_sweep

    !> Exit 2 when the combinations of the swept lists exceed max_list_length rows.
    subroutine check_combinations(sizes, names)
        integer, intent(in) :: sizes(:)          !! number of values of each list
        character(len=*), intent(in) :: names    !! the lists, for the message
        if (product(real(sizes, wp)) > max_list_length) call fail(EXIT_USAGE, 'too many combinations of ' // &
            names // ' (at most ' // itoa(max_list_length) // ' rows)')
    end subroutine check_combinations

    !> Index (1-based) of `text` in the space-separated `choices`; exit 2 otherwise.
    integer function parse_choice(text, choices, what) result(k)
        character(len=*), intent(in) :: text, choices, what
        integer :: i, j, start
        k = 0
        start = 1
        j = 0
        do i = 1, len(choices) + 1
            if (i > len(choices)) then
                j = j + 1
                if (choices(start:) == text) k = j
            else if (choices(i:i) == ' ') then
                j = j + 1
                if (choices(start:i - 1) == text) k = j
                start = i + 1
            end if
        end do
        if (k == 0 .or. len(text) == 0) call fail(EXIT_USAGE, 'invalid ' // what // ' "' // text // &
                                                   '": choose one of ' // choices // did_you_mean(text, choices))
    end function parse_choice

    subroutine buffer_add(self, line)
        class(cli_buffer), intent(inout) :: self
        character(len=*), intent(in) :: line
        type(cli_line), allocatable :: tmp(:)
        if (.not. allocated(self%lines)) allocate (self%lines(64))
        if (self%n == size(self%lines)) then
            allocate (tmp(2 * self%n))
            tmp(1:self%n) = self%lines
            call move_alloc(tmp, self%lines)
        end if
        self%n = self%n + 1
        self%lines(self%n)%s = line
    end subroutine buffer_add

    !> Write every line of the buffer to stdout (checked: exit 4 when it cannot be written).
    subroutine buffer_flush(self)
        class(cli_buffer), intent(in) :: self
        character(len=:), allocatable :: text
        integer :: i, n, pos
        n = 0
        do i = 1, self%n
            n = n + len(self%lines(i)%s) + 1
        end do
        allocate (character(len=n) :: text)
        pos = 0
        do i = 1, self%n
            text(pos + 1:pos + len(self%lines(i)%s)) = self%lines(i)%s
            pos = pos + len(self%lines(i)%s) + 1
            text(pos:pos) = achar(10)
        end do
        call write_stdout(text)
    end subroutine buffer_flush

    !> Write `text` to stdout through write(2), checking every call: a full disk, a
    !> closed pipe or /dev/full give one line on stderr and exit 4.
    subroutine write_stdout(text)
        character(len=*), intent(in) :: text   !! bytes to write (include the newlines)
        character(kind=c_char), allocatable :: bytes(:)
        integer :: j, n, pos
        integer(c_long) :: w
        flush (output_unit)
        n = len(text)
        allocate (bytes(max(n, 1)))
        do j = 1, n
            bytes(j) = text(j:j)
        end do
        pos = 0
        do while (pos < n)
            w = c_write(1_c_int, bytes(pos + 1:), int(n - pos, c_size_t))
            if (w <= 0) call write_failed()
            pos = pos + int(w)
        end do
    end subroutine write_stdout

    !> Left-justify `s` in a field of `width` characters (right-justify if width < 0).
    function pad(s, width) result(r)
        character(len=*), intent(in) :: s
        integer, intent(in) :: width
        character(len=:), allocatable :: r
        integer :: w
        w = max(abs(width), len(s))
        r = repeat(' ', w)
        if (width >= 0) then
            r(1:len(s)) = s
        else
            r(w - len(s) + 1:) = s
        end if
    end function pad

    !> Join the fields of a row with commas.
    function csv_join(fields) result(r)
        type(cli_line), intent(in) :: fields(:)
        character(len=:), allocatable :: r
        integer :: i
        r = ''
        do i = 1, size(fields)
            if (i > 1) r = r // ','
            r = r // fields(i)%s
        end do
    end function csv_join

end module hertzdamp_cli
