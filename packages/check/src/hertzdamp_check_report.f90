!> A report of `check` as data: metadata (key, text) in order, named columns, and rows of
!> cells (numbers, strings, empty) with each row's status (a library status: HD_OK,
!> HD_NO_REBOUND or why the row has no result) and the reason of a row without one.
!> The command-line program renders it as text, CSV or JSON; nothing here prints.
module hertzdamp_check_report
    use hertzdamp, only: hertzdamp_rk, HD_OK
    use hertzdamp_text_list, only: text_string, text_list
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    integer, parameter, public :: PEER_CELL_NONE = 0, PEER_CELL_NUM = 1, PEER_CELL_STR = 2

    !> One cell.
    type, public :: peer_cell
        integer :: kind = PEER_CELL_NONE
        real(wp) :: x = 0.0_wp
        character(len=:), allocatable :: s
    end type peer_cell

    !> The report.
    type, public :: peer_report
        type(text_list) :: keys, values               !! metadata, in order
        character(len=:), allocatable :: columns      !! comma-separated column names
        character(len=:), allocatable :: units        !! comma-separated units, as many ('' for none)
        integer :: ncol = 0
        type(peer_cell), allocatable :: cells(:, :)   !! (column, row)
        integer :: nrow = 0, col = 0
        integer, allocatable :: status(:)             !! per row: HD_OK, HD_NO_REBOUND or why none
        type(text_string), allocatable :: reason(:)     !! per row: why it has no result ('' if it has)
    contains
        procedure :: set_columns => report_set_columns
        procedure :: meta => report_meta
        procedure :: num => report_num
        procedure :: num_or_none => report_num_or_none
        procedure :: str => report_str
        procedure :: none => report_none
        procedure :: end_row => report_end_row
    end type peer_report

contains

    subroutine report_set_columns(self, names, units)
        class(peer_report), intent(inout) :: self
        character(len=*), intent(in) :: names   !! comma-separated
        character(len=*), intent(in), optional :: units   !! comma-separated, one per name ('' for none)
        integer :: i
        self%columns = names
        self%units = ''
        if (present(units)) self%units = units
        self%ncol = 1
        do i = 1, len(names)
            if (names(i:i) == ',') self%ncol = self%ncol + 1
        end do
        allocate (self%cells(self%ncol, 16), self%status(16), self%reason(16))
        self%nrow = 0
        self%col = 0
    end subroutine report_set_columns

    subroutine report_meta(self, key, val)
        class(peer_report), intent(inout) :: self
        character(len=*), intent(in) :: key, val
        call self%keys%push(key)
        call self%values%push(val)
    end subroutine report_meta

    !> The next cell of the current row (a new row grows the arrays by doubling).
    subroutine next_cell(self)
        class(peer_report), intent(inout) :: self
        type(peer_cell), allocatable :: tmp(:, :)
        integer, allocatable :: st(:)
        type(text_string), allocatable :: why(:)
        integer :: m
        if (self%col == 0) then
            self%nrow = self%nrow + 1
            if (self%nrow > size(self%status)) then
                m = 2 * size(self%status)
                allocate (tmp(self%ncol, m), st(m), why(m))
                tmp(:, 1:self%nrow - 1) = self%cells(:, 1:self%nrow - 1)
                st(1:self%nrow - 1) = self%status(1:self%nrow - 1)
                why(1:self%nrow - 1) = self%reason(1:self%nrow - 1)
                call move_alloc(tmp, self%cells)
                call move_alloc(st, self%status)
                call move_alloc(why, self%reason)
            end if
            self%status(self%nrow) = HD_OK
            self%reason(self%nrow)%s = ''
        end if
        self%col = self%col + 1
        self%cells(self%col, self%nrow) = peer_cell()
    end subroutine next_cell

    subroutine report_num(self, x)
        class(peer_report), intent(inout) :: self
        real(wp), intent(in) :: x
        call next_cell(self)
        if (x == x) then
            self%cells(self%col, self%nrow)%kind = PEER_CELL_NUM
            self%cells(self%col, self%nrow)%x = x
        end if
    end subroutine report_num

    subroutine report_num_or_none(self, x, have)
        class(peer_report), intent(inout) :: self
        real(wp), intent(in) :: x
        logical, intent(in) :: have
        if (have) then
            call self%num(x)
        else
            call self%none()
        end if
    end subroutine report_num_or_none

    subroutine report_str(self, s)
        class(peer_report), intent(inout) :: self
        character(len=*), intent(in) :: s
        call next_cell(self)
        self%cells(self%col, self%nrow)%kind = PEER_CELL_STR
        self%cells(self%col, self%nrow)%s = s
    end subroutine report_str

    subroutine report_none(self)
        class(peer_report), intent(inout) :: self
        call next_cell(self)
    end subroutine report_none

    !> Close the current row with its status and reason (the row has all its cells).
    subroutine report_end_row(self, status, reason)
        class(peer_report), intent(inout) :: self
        integer, intent(in) :: status
        character(len=*), intent(in) :: reason
        self%status(self%nrow) = status
        self%reason(self%nrow)%s = reason
        self%col = 0
    end subroutine report_end_row

end module hertzdamp_check_report
