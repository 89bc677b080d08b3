!> Per-row status of the commands that print one row per combination of swept values
!> (`table`, `forward`, `invert`, `timestep`, and any command that sweeps).
!>
!> Every row carries a status word:
!>
!>     ok                a result
!>     no-rebound        a result: the overlap never returns to zero (e = 0, T_c = inf)
!>     bad-input         an input of this row is invalid (e.g. a negative velocity)
!>     outside-validity  the input lies outside the range of the chosen method
!>     inaccurate        the method's own error estimate exceeds --accuracy
!>     out-of-range      a result is not representable in double precision
!>     failed            the computation failed (step limit, no convergence)
!>
!> A row without a result prints its inputs and leaves the results empty (CSV), null
!> (JSON) or '-' (text).  Exit codes:
!>
!>  - every row has a result (ok, no-rebound): the table, exit 0;
!>  - some rows have none: the table, ONE line on stderr ("2 of 5 rows have no
!>    result (...); first: <why>"), exit 3 (4 if a computation failed);
!>  - no row has one: nothing on stdout, one line on stderr, exit 2 when every row
!>    is bad-input, 4 when one failed, 3 otherwise.
!>
!> Use: `call log%add(kind, message)` once per row (kind from row_kind(status) or a
!> ROW_* constant, message naming the option and value that is wrong, '' for rows
!> with a result), then `call log%emit(table, fmt)`, which never returns.
module hertzdamp_cli_rows
    use hertzdamp, only: HD_OK, HD_NO_REBOUND, HD_OUTSIDE_VALIDITY, HD_NOT_SUPPORTED, HD_INACCURATE, &
                       HD_OUT_OF_RANGE, &
                       HD_MAX_STEPS, HD_STEP_UNDERFLOW, HD_NO_CONVERGENCE
    use hertzdamp_cli, only: cli_buffer, fail, quit, error_line, EXIT_OK, EXIT_USAGE, EXIT_NO_SOLUTION, EXIT_FAILURE
    use hertzdamp_cli_text, only: itoa
    use hertzdamp_cli_output, only: out_table
    implicit none
    private

    integer, parameter, public :: ROW_OK = 1, ROW_NO_REBOUND = 2, ROW_BAD_INPUT = 3, ROW_OUTSIDE_VALIDITY = 4, &
                                  ROW_INACCURATE = 5, ROW_OUT_OF_RANGE = 6, ROW_FAILED = 7
    integer, parameter :: nkinds = 7
    !> The status words, in the order of the ROW_* constants.
    character(len=16), parameter :: words(nkinds) = [character(len=16) :: 'ok', 'no-rebound', 'bad-input', &
        'outside-validity', 'inaccurate', 'out-of-range', 'failed']
    !> Exit code of a row without a result of each kind (0: the row has a result).
    integer, parameter :: codes(nkinds) = [EXIT_OK, EXIT_OK, EXIT_USAGE, EXIT_NO_SOLUTION, EXIT_NO_SOLUTION, &
                                           EXIT_NO_SOLUTION, EXIT_FAILURE]

    !> The rows' statuses, counted.
    type, public :: row_log
        integer :: nrows = 0
        integer :: counts(nkinds) = 0
        character(len=:), allocatable :: first   !! message of the first row without a result
    contains
        procedure :: add => log_add
        procedure :: emit => log_emit
    end type row_log

    public :: row_kind, row_word, row_has_result

contains

    !> The ROW_* kind of a library status (bad-input for every invalid argument).
    pure integer function row_kind(status) result(kind)
        integer, intent(in) :: status   !! a hertzdamp status
        select case (status)
        case (HD_OK); kind = ROW_OK
        case (HD_NO_REBOUND); kind = ROW_NO_REBOUND
        case (HD_OUTSIDE_VALIDITY, HD_NOT_SUPPORTED); kind = ROW_OUTSIDE_VALIDITY
        case (HD_INACCURATE); kind = ROW_INACCURATE
        case (HD_OUT_OF_RANGE); kind = ROW_OUT_OF_RANGE
        case (HD_MAX_STEPS, HD_STEP_UNDERFLOW, HD_NO_CONVERGENCE); kind = ROW_FAILED
        case default; kind = ROW_BAD_INPUT
        end select
    end function row_kind

    !> The status word of a ROW_* kind.
    pure function row_word(kind) result(w)
        integer, intent(in) :: kind
        character(len=:), allocatable :: w
        w = trim(words(kind))
    end function row_word

    !> True for the kinds that carry a result (ok, no-rebound).
    pure logical function row_has_result(kind)
        integer, intent(in) :: kind
        row_has_result = codes(kind) == EXIT_OK
    end function row_has_result

    !> Count one row; `message` says why a row without a result has none.
    subroutine log_add(self, kind, message)
        class(row_log), intent(inout) :: self
        integer, intent(in) :: kind              !! ROW_*
        character(len=*), intent(in) :: message  !! e.g. '--velocity -1: must be finite and positive'
        self%nrows = self%nrows + 1
        self%counts(kind) = self%counts(kind) + 1
        if (.not. row_has_result(kind) .and. .not. allocated(self%first)) self%first = message
    end subroutine log_add

    !> Print the table (or not) and exit with the code the rows decide.
    subroutine log_emit(self, t, fmt)
        class(row_log), intent(in) :: self
        type(out_table), intent(in) :: t
        integer, intent(in) :: fmt
        type(cli_buffer) :: buf
        integer :: nfail, worst, k
        character(len=:), allocatable :: why
        nfail = 0
        worst = EXIT_OK
        why = ''
        do k = 1, nkinds
            if (codes(k) == EXIT_OK .or. self%counts(k) == 0) cycle
            nfail = nfail + self%counts(k)
            worst = max(worst, codes(k))
            if (len(why) > 0) why = why // ', '
            why = why // itoa(self%counts(k)) // ' ' // trim(words(k))
        end do
        if (nfail > 0 .and. nfail == self%nrows) then
            if (self%nrows == 1) call fail(worst, self%first)
            call fail(worst, 'no row has a result (' // why // '); first: ' // self%first)
        end if
        call t%render(fmt, buf)
        call buf%flush_to_stdout()
        if (nfail > 0) then
            call error_line(itoa(nfail) // ' of ' // itoa(self%nrows) // ' rows have no result (' // why // &
                            '); first: ' // self%first)
            call quit(max(EXIT_NO_SOLUTION, worst))
        end if
        call quit(EXIT_OK)
    end subroutine log_emit

end module hertzdamp_cli_rows
