!> Tables of results rendered as aligned text, CSV or JSON, in time linear in the
!> number of cells: every cell is formatted once and the column widths of the text
!> output are computed in one pass.
!>
!> A cell is a number, a string, a logical or empty (`none`: a quantity the row does
!> not have, e.g. a row whose status is not ok, or a method that does not provide
!> it): empty in CSV, null in JSON, '-' in text.  Strings come out as valid UTF-8
!> (invalid bytes replaced, or escaped as \xNN in text, where control characters are
!> escaped too), CSV fields are quoted where needed, JSON strings escaped.
!>
!> Metadata pairs are strings (`meta`), numbers (`meta_num`) or logicals (`meta_bool`):
!> `# key: value` lines in text, members of the JSON object, not in CSV.  A string pair
!> may read differently in text (`meta`'s `text`; empty: not shown in text).  A JSON
!> document may carry further tables (render's `more`): each as an array of row
!> objects under its own name (`rows_key`, default "rows").
!>
!> The text output is for people, with the number formats of hertzdamp_text_format (the
!> one place of them): each column's unit in its header (`set_columns`' `units`);
!> numbers with 7 significant digits and a two-digit exponent (9.965498e+08), whole
!> numbers as integers; a column that has the same value in every row printed once
!> above the table, in the short form of a single value (`# e = 0.9`,
!> `# mass [kg] = 5.235988e-06`); a table of one row as one `name [unit] = value` line
!> per column.  CSV and JSON do not depend on any of this.
module hertzdamp_cli_output
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_cli, only: cli_buffer, cli_line
    use hertzdamp_cli_text, only: fmt_csv, fmt_text, fmt_text_short, fmt_json, json_string, csv_field, &
                                  one_line, itoa
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    integer, parameter, public :: FORMAT_TEXT = 1, FORMAT_CSV = 2, FORMAT_JSON = 3
    !> Names of the formats, in the order of the FORMAT_* constants.
    character(len=*), parameter, public :: format_choices = 'text csv json'

    integer, parameter :: CELL_NUM = 1, CELL_STR = 2, CELL_NONE = 3, CELL_BOOL = 4, CELL_INT = 5

    !> One cell.
    type :: cell
        integer :: kind = CELL_NONE
        real(wp) :: x = 0.0_wp
        logical :: b = .false.
        integer :: i = 0
        character(len=:), allocatable :: s
    end type cell

    !> A table with named columns and metadata (key = value pairs).
    type, public :: out_table
        type(cli_line), allocatable :: head(:)
        type(cli_line), allocatable :: units(:)      !! unit of each column ('' for none), text header only
        type(cli_line), allocatable :: meta_key(:)
        type(cell), allocatable :: meta_val(:)
        type(cli_line), allocatable :: meta_txt(:)   !! the value in text (when meta_alt)
        logical, allocatable :: meta_alt(:)          !! the text output shows meta_txt instead
        type(cell), allocatable :: cells(:, :)
        integer :: nrow = 0
        integer :: col = 0
        character(len=:), allocatable :: rows_key   !! JSON name of the rows array ('rows' when unset)
    contains
        procedure :: set_columns   !! comma-separated column names and, optionally, their units (call first)
        procedure :: meta          !! a metadata pair: '# key: value' in text, a member in JSON, not in CSV
        procedure :: meta_num      !! a metadata number (JSON: a number, null when not finite)
        procedure :: meta_bool     !! a metadata logical (JSON: true/false)
        procedure :: num           !! append a number to the current row
        procedure :: str           !! append a string
        procedure :: bool          !! append a logical (true/false)
        procedure :: int => int_cell  !! append an integer
        procedure :: none          !! append an empty cell
        procedure :: num_or_none   !! append a number, or an empty cell when `have` is false
        procedure :: render        !! render into a buffer in a FORMAT_*
    end type out_table

contains

    subroutine set_columns(self, names, units)
        class(out_table), intent(inout) :: self
        character(len=*), intent(in) :: names            !! comma-separated column names
        character(len=*), intent(in), optional :: units  !! comma-separated units, as many ('' for none): text header
        type(cli_line), allocatable :: u(:)
        integer :: j
        self%head = split_commas(names)
        allocate (self%units(size(self%head)), u(0))
        if (present(units)) u = split_commas(units)
        do j = 1, size(self%head)
            self%units(j)%s = ''
            if (present(units)) then
                if (j <= size(u)) self%units(j)%s = u(j)%s
            end if
        end do
        allocate (self%cells(size(self%head), 16), self%meta_key(0), self%meta_val(0), self%meta_txt(0), &
                  self%meta_alt(0))
    end subroutine set_columns

    !> The comma-separated fields of `text`, in order (empty fields kept).
    pure function split_commas(text) result(parts)
        character(len=*), intent(in) :: text
        type(cli_line), allocatable :: parts(:)
        integer :: i, j, n
        allocate (parts(count([(text(i:i) == ',', i=1, len(text))]) + 1))
        j = 1
        n = 0
        do i = 1, len(text) + 1
            if (i <= len(text)) then
                if (text(i:i) /= ',') cycle
            end if
            n = n + 1
            parts(n)%s = text(j:i - 1)
            j = i + 1
        end do
    end function split_commas

    !> Add a metadata pair (printed as a comment in text, a member in JSON, omitted in
    !> CSV); `text`: the value as the text output shows it (empty: not shown in text).
    subroutine meta(self, key, val, text)
        class(out_table), intent(inout) :: self
        character(len=*), intent(in) :: key, val
        character(len=*), intent(in), optional :: text
        call add_meta(self, key, cell(kind=CELL_STR, s=val))
        if (present(text)) then
            self%meta_txt(size(self%meta_txt)) = cli_line(text)
            self%meta_alt(size(self%meta_alt)) = .true.
        end if
    end subroutine meta

    !> A metadata number; `have` false: no value (null in JSON, - in text).
    subroutine meta_num(self, key, x, have)
        class(out_table), intent(inout) :: self
        character(len=*), intent(in) :: key
        real(wp), intent(in) :: x
        logical, intent(in), optional :: have
        logical :: h
        h = .true.
        if (present(have)) h = have
        if (h .and. x == x) then
            call add_meta(self, key, cell(kind=CELL_NUM, x=x))
        else
            call add_meta(self, key, cell(kind=CELL_NONE))
        end if
    end subroutine meta_num

    !> A metadata logical.
    subroutine meta_bool(self, key, b)
        class(out_table), intent(inout) :: self
        character(len=*), intent(in) :: key
        logical, intent(in) :: b
        call add_meta(self, key, cell(kind=CELL_BOOL, b=b))
    end subroutine meta_bool

    subroutine add_meta(self, key, val)
        class(out_table), intent(inout) :: self
        character(len=*), intent(in) :: key
        type(cell), intent(in) :: val
        self%meta_key = [self%meta_key, cli_line(key)]
        self%meta_val = [self%meta_val, val]
        self%meta_txt = [self%meta_txt, cli_line('')]
        self%meta_alt = [self%meta_alt, .false.]
    end subroutine add_meta

    !> Move to the next cell, starting a new row after the last column; the cell array
    !> doubles when full (amortised constant time).
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

    !> A number.  NaN ("does not apply") is written as an absent cell, so no output
    !> ever carries nan; an infinity stays (a no-rebound contact time is infinite:
    !> `inf` in text and CSV, null in JSON).
    subroutine num(self, x)
        class(out_table), intent(inout) :: self
        real(wp), intent(in) :: x
        call next_cell(self)
        if (x == x) then
            self%cells(self%col, self%nrow)%kind = CELL_NUM
            self%cells(self%col, self%nrow)%x = x
        else
            self%cells(self%col, self%nrow)%kind = CELL_NONE
        end if
    end subroutine num

    subroutine str(self, s)
        class(out_table), intent(inout) :: self
        character(len=*), intent(in) :: s
        call next_cell(self)
        self%cells(self%col, self%nrow)%kind = CELL_STR
        self%cells(self%col, self%nrow)%s = s
    end subroutine str

    subroutine bool(self, b)
        class(out_table), intent(inout) :: self
        logical, intent(in) :: b
        call next_cell(self)
        self%cells(self%col, self%nrow)%kind = CELL_BOOL
        self%cells(self%col, self%nrow)%b = b
    end subroutine bool

    subroutine int_cell(self, i)
        class(out_table), intent(inout) :: self
        integer, intent(in) :: i
        call next_cell(self)
        self%cells(self%col, self%nrow)%kind = CELL_INT
        self%cells(self%col, self%nrow)%i = i
    end subroutine int_cell

    subroutine none(self)
        class(out_table), intent(inout) :: self
        call next_cell(self)
        self%cells(self%col, self%nrow)%kind = CELL_NONE
    end subroutine none

    subroutine num_or_none(self, x, have)
        class(out_table), intent(inout) :: self
        real(wp), intent(in) :: x
        logical, intent(in) :: have   !! false: the row has no such value
        if (have) then
            call self%num(x)
        else
            call self%none()
        end if
    end subroutine num_or_none

    !> The text of a cell in a format.
    function cell_text(c, fmt) result(s)
        type(cell), intent(in) :: c
        integer, intent(in) :: fmt
        character(len=:), allocatable :: s
        select case (c%kind)
        case (CELL_NUM)
            select case (fmt)
            case (FORMAT_CSV); s = fmt_csv(c%x)
            case (FORMAT_JSON); s = fmt_json(c%x)
            case default; s = fmt_text(c%x)
            end select
        case (CELL_STR)
            select case (fmt)
            case (FORMAT_CSV); s = csv_field(c%s)
            case (FORMAT_JSON); s = json_string(c%s)
            case default; s = one_line(c%s)
            end select
        case (CELL_BOOL)
            s = trim(merge('true ', 'false', c%b))
        case (CELL_INT)
            s = itoa(c%i)
        case default
            select case (fmt)
            case (FORMAT_CSV); s = ''
            case (FORMAT_JSON); s = 'null'
            case default; s = '-'
            end select
        end select
    end function cell_text

    !> Number of characters (code points) of a UTF-8 string, for alignment.
    pure integer function display_width(s) result(w)
        character(len=*), intent(in) :: s
        integer :: i
        w = 0
        do i = 1, len(s)
            if (iachar(s(i:i)) < 128 .or. iachar(s(i:i)) >= 192) w = w + 1
        end do
    end function display_width

    !> Render into the buffer in the given format.  `more`: further tables, in JSON
    !> only (each as an array under its rows_key, after this table's rows; their
    !> metadata is not used).
    subroutine render(self, fmt, buf, more)
        class(out_table), intent(in) :: self
        integer, intent(in) :: fmt
        type(cli_buffer), intent(inout) :: buf
        type(out_table), intent(in), optional :: more(:)
        character(len=:), allocatable :: line
        integer :: i, j, nc, nmore
        nc = size(self%head)
        select case (fmt)
        case (FORMAT_CSV)
            line = ''
            do j = 1, nc
                line = line // merge(',', ' ', j > 1) // csv_field(self%head(j)%s)
            end do
            call buf%add(line(2:))
            do i = 1, self%nrow
                line = ''
                do j = 1, nc
                    line = line // ',' // cell_text(self%cells(j, i), fmt)
                end do
                call buf%add(line(2:))
            end do
        case (FORMAT_JSON)
            nmore = 0
            if (present(more)) nmore = size(more)
            call buf%add('{')
            do j = 1, size(self%meta_key)
                call buf%add('  ' // json_string(self%meta_key(j)%s) // ': ' // cell_text(self%meta_val(j), fmt) // ',')
            end do
            call json_rows(self, buf, nmore > 0)
            do j = 1, nmore
                call json_rows(more(j), buf, j < nmore)
            end do
            call buf%add('}')
        case default
            call render_text(self, buf)
        end select
    end subroutine render

    !> The text rendering (see the module header): metadata, the columns that never
    !> change, the table with the units in its header; one row as a list.
    subroutine render_text(self, buf)
        class(out_table), intent(in) :: self
        type(cli_buffer), intent(inout) :: buf
        type(cli_line), allocatable :: txt(:, :), head(:)
        integer, allocatable :: width(:)
        logical, allocatable :: const(:)
        character(len=:), allocatable :: line, value
        character(len=*), parameter :: comment = '# '
        integer :: i, j, nc, wname
        nc = size(self%head)
        do j = 1, size(self%meta_key)
            if (.not. self%meta_alt(j)) then
                call buf%add('# ' // one_line(self%meta_key(j)%s) // ': ' // cell_text(self%meta_val(j), FORMAT_TEXT))
            else if (len(self%meta_txt(j)%s) > 0) then
                call buf%add('# ' // one_line(self%meta_key(j)%s) // ': ' // one_line(self%meta_txt(j)%s))
            end if
        end do
        ! every cell formatted once
        allocate (txt(nc, self%nrow), head(nc), width(nc), const(nc))
        do j = 1, nc
            do i = 1, self%nrow
                txt(j, i)%s = cell_text(self%cells(j, i), FORMAT_TEXT)
            end do
            const(j) = self%nrow >= 1
            do i = 2, self%nrow
                if (const(j)) const(j) = txt(j, i)%s == txt(j, 1)%s
            end do
            head(j)%s = one_line(self%head(j)%s)
        end do
        ! the units in the header: 'name [unit]'
        do j = 1, nc
            if (len(self%units(j)%s) > 0) head(j)%s = head(j)%s // ' [' // one_line(self%units(j)%s) // ']'
        end do
        ! two rows or more: the columns that never change go above the table, unless
        ! every column does (then the table stays whole); one row: a list
        if (self%nrow >= 2 .and. all(const)) const = .false.
        wname = 0
        do j = 1, nc
            if (const(j)) wname = max(wname, display_width(head(j)%s))
        end do
        do j = 1, nc
            if (.not. const(j)) cycle
            ! the value once, in the short form of a single number
            value = txt(j, 1)%s
            if (self%cells(j, 1)%kind == CELL_NUM) value = fmt_text_short(self%cells(j, 1)%x)
            call buf%add(comment(1:merge(2, 0, self%nrow >= 2)) // pad_right(head(j)%s, wname) // ' = ' // value)
        end do
        if (self%nrow == 1) return
        do j = 1, nc
            width(j) = display_width(head(j)%s)
            do i = 1, self%nrow
                width(j) = max(width(j), display_width(txt(j, i)%s))
            end do
        end do
        line = ''
        do j = 1, nc
            if (.not. const(j)) line = line // ' ' // right(head(j)%s, width(j))
        end do
        call buf%add(line(2:))
        do i = 1, self%nrow
            line = ''
            do j = 1, nc
                if (.not. const(j)) line = line // ' ' // right(txt(j, i)%s, width(j))
            end do
            call buf%add(line(2:))
        end do
    end subroutine render_text

    !> The rows of a table as a JSON member: "rows_key": [ {...}, ... ] (a comma after
    !> it when `comma`).
    subroutine json_rows(t, buf, comma)
        type(out_table), intent(in) :: t
        type(cli_buffer), intent(inout) :: buf
        logical, intent(in) :: comma
        character(len=:), allocatable :: line
        integer :: i, j
        if (allocated(t%rows_key)) then
            call buf%add('  ' // json_string(t%rows_key) // ': [')
        else
            call buf%add('  "rows": [')
        end if
        do i = 1, t%nrow
            line = '    {'
            do j = 1, size(t%head)
                if (j > 1) line = line // ', '
                line = line // json_string(t%head(j)%s) // ': ' // cell_text(t%cells(j, i), FORMAT_JSON)
            end do
            line = line // merge('},', '} ', i < t%nrow)
            call buf%add(trim(line))
        end do
        call buf%add(trim(merge('  ],', '  ] ', comma)))
    end subroutine json_rows

    !> `s` left-justified in `width` display columns.
    function pad_right(s, width) result(r)
        character(len=*), intent(in) :: s
        integer, intent(in) :: width
        character(len=:), allocatable :: r
        r = s // repeat(' ', max(0, width - display_width(s)))
    end function pad_right

    !> `s` right-justified in `width` display columns.
    function right(s, width) result(r)
        character(len=*), intent(in) :: s
        integer, intent(in) :: width
        character(len=:), allocatable :: r
        r = repeat(' ', max(0, width - display_width(s))) // s
    end function right

end module hertzdamp_cli_output
