!> Tables of results rendered as aligned text, CSV or JSON.
module hertzdamp_cli_output
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_cli, only: cli_buffer, cli_line, fmt_csv, fmt_text, fmt_json, json_string, pad
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    integer, parameter, public :: FORMAT_TEXT = 1, FORMAT_CSV = 2, FORMAT_JSON = 3
    !> Names of the formats, in the order of the FORMAT_* constants.
    character(len=*), parameter, public :: format_choices = 'text csv json'

    !> One cell: a number or a string.
    type :: cell
        logical :: is_num = .true.
        real(wp) :: x = 0.0_wp
        character(len=:), allocatable :: s
    end type cell

    !> A table with named columns and metadata (key = value pairs).
    type, public :: out_table
        type(cli_line), allocatable :: head(:)
        type(cli_line), allocatable :: meta_key(:), meta_val(:)
        type(cell), allocatable :: cells(:, :)
        integer :: nrow = 0
        integer :: col = 0
    contains
        procedure :: set_columns, meta, num, str, render
    end type out_table

contains

    subroutine set_columns(self, names)
        class(out_table), intent(inout) :: self
        character(len=*), intent(in) :: names  !! comma-separated column names
        integer :: i, j, n
        n = 1
        do i = 1, len(names)
            if (names(i:i) == ',') n = n + 1
        end do
        allocate (self%head(n), self%cells(n, 16), self%meta_key(0), self%meta_val(0))
        j = 1
        n = 0
        do i = 1, len(names) + 1
            if (i > len(names)) then
                n = n + 1
                self%head(n)%s = names(j:)
            else if (names(i:i) == ',') then
                n = n + 1
                self%head(n)%s = names(j:i - 1)
                j = i + 1
            end if
        end do
    end subroutine set_columns

    !> Add a metadata pair (printed as a comment in text, a field in JSON, omitted in CSV).
    subroutine meta(self, key, val)
        class(out_table), intent(inout) :: self
        character(len=*), intent(in) :: key, val
        self%meta_key = [self%meta_key, cli_line(key)]
        self%meta_val = [self%meta_val, cli_line(val)]
    end subroutine meta

    subroutine next_cell(self)
        class(out_table), intent(inout) :: self
        type(cell), allocatable :: tmp(:, :)
        if (self%col == 0 .or. self%col == size(self%head)) then
            self%nrow = self%nrow + 1
            self%col = 0
            if (self%nrow > size(self%cells, 2)) then
                allocate (tmp(size(self%head), 2 * size(self%cells, 2)))
                tmp(:, 1:self%nrow - 1) = self%cells(:, 1:self%nrow - 1)
                call move_alloc(tmp, self%cells)
            end if
        end if
        self%col = self%col + 1
    end subroutine next_cell

    !> Append a number to the current row (rows fill left to right).
    subroutine num(self, x)
        class(out_table), intent(inout) :: self
        real(wp), intent(in) :: x
        call next_cell(self)
        self%cells(self%col, self%nrow) = cell(.true., x, '')
    end subroutine num

    !> Append a string to the current row.
    subroutine str(self, s)
        class(out_table), intent(inout) :: self
        character(len=*), intent(in) :: s
        call next_cell(self)
        self%cells(self%col, self%nrow) = cell(.false., 0.0_wp, s)
    end subroutine str

    !> Render into the buffer in the given format.
    subroutine render(self, fmt, buf)
        class(out_table), intent(in) :: self
        integer, intent(in) :: fmt
        type(cli_buffer), intent(inout) :: buf
        character(len=:), allocatable :: line
        integer :: i, j, w
        select case (fmt)
        case (FORMAT_CSV)
            line = ''
            do j = 1, size(self%head)
                line = line // merge(',', ' ', j > 1) // self%head(j)%s
            end do
            call buf%add(line(2:))
            do i = 1, self%nrow
                line = ''
                do j = 1, size(self%head)
                    if (self%cells(j, i)%is_num) then
                        line = line // ',' // fmt_csv(self%cells(j, i)%x)
                    else
                        line = line // ',' // self%cells(j, i)%s
                    end if
                end do
                call buf%add(line(2:))
            end do
        case (FORMAT_JSON)
            call buf%add('{')
            do j = 1, size(self%meta_key)
                call buf%add('  ' // json_string(self%meta_key(j)%s) // ': ' // json_string(self%meta_val(j)%s) // ',')
            end do
            call buf%add('  "rows": [')
            do i = 1, self%nrow
                line = '    {'
                do j = 1, size(self%head)
                    if (j > 1) line = line // ', '
                    line = line // json_string(self%head(j)%s) // ': '
                    if (self%cells(j, i)%is_num) then
                        line = line // fmt_json(self%cells(j, i)%x)
                    else
                        line = line // json_string(self%cells(j, i)%s)
                    end if
                end do
                line = line // merge('},', '} ', i < self%nrow)
                call buf%add(trim(line))
            end do
            call buf%add('  ]')
            call buf%add('}')
        case default
            do j = 1, size(self%meta_key)
                call buf%add('# ' // self%meta_key(j)%s // ': ' // self%meta_val(j)%s)
            end do
            line = ''
            do j = 1, size(self%head)
                w = col_width(self, j)
                line = line // ' ' // pad(self%head(j)%s, -w)
            end do
            call buf%add(line(2:))
            do i = 1, self%nrow
                line = ''
                do j = 1, size(self%head)
                    w = col_width(self, j)
                    if (self%cells(j, i)%is_num) then
                        line = line // ' ' // pad(trim(adjustl(fmt_text(self%cells(j, i)%x))), -w)
                    else
                        line = line // ' ' // pad(self%cells(j, i)%s, -w)
                    end if
                end do
                call buf%add(line(2:))
            end do
        end select
    end subroutine render

    integer function col_width(self, j) result(w)
        class(out_table), intent(in) :: self
        integer, intent(in) :: j
        integer :: i
        w = len(self%head(j)%s)
        do i = 1, self%nrow
            if (self%cells(j, i)%is_num) then
                w = max(w, len_trim(adjustl(fmt_text(self%cells(j, i)%x))))
            else
                w = max(w, len(self%cells(j, i)%s))
            end if
        end do
    end function col_width

end module hertzdamp_cli_output
