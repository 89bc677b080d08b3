!> Python as Yade scripts write it, read without running it: logical statements (comments
!> removed, lines joined inside brackets and after a backslash, triple-quoted strings
!> dropped), where a call of a name starts, and a call's positional and keyword
!> arguments.  Nothing prints or stops.
module hertzdamp_text_python
    use hertzdamp_text_list, only: text_list
    use hertzdamp_text_parse, only: text_name_char, text_is_name
    use hertzdamp_text_file, only: text_where
    implicit none
    private

    public :: text_py_statements, text_py_call_at, text_py_call_args, text_py_kwarg

contains

    !> Logical text_py_statements: comments removed, lines joined inside brackets and after \,
    !> triple-quoted strings dropped; with the file:line of their first line.
    subroutine text_py_statements(lines, file, stmts, wheres)
        type(text_list), intent(in) :: lines
        character(len=*), intent(in) :: file
        type(text_list), intent(inout) :: stmts, wheres
        character(len=:), allocatable :: cur, t
        character :: q
        integer :: i, j, depth, start
        logical :: triple
        cur = ''
        depth = 0
        triple = .false.
        start = 1
        do i = 1, lines%n
            t = lines%item(i)%s
            if (triple) then
                if (index(t, '"""') > 0 .or. index(t, "'''") > 0) triple = .false.
                cycle
            end if
            q = ' '
            do j = 1, len(t)
                if (q /= ' ') then
                    if (t(j:j) == q) q = ' '
                    cycle
                end if
                select case (t(j:j))
                case ('"', '''')
                    if (j + 2 <= len(t)) then
                        if (t(j:j + 2) == repeat(t(j:j), 3)) then
                            if (index(t(j + 3:), t(j:j + 2)) == 0) triple = .true.
                            t = t(1:j - 1)
                            exit
                        end if
                    end if
                    q = t(j:j)
                case ('#')
                    t = t(1:j - 1)
                    exit
                case ('(', '[', '{'); depth = depth + 1
                case (')', ']', '}'); depth = max(0, depth - 1)
                case default
                end select
            end do
            if (len(cur) == 0) start = i
            cur = cur // ' ' // trim(t)
            if (depth > 0) cycle
            if (len_trim(t) > 0) then
                if (t(len_trim(t):len_trim(t)) == '\') then
                    cur = cur(1:len_trim(cur) - 1)
                    cycle
                end if
            end if
            if (len_trim(cur) > 0) then
                call stmts%push(trim(adjustl(cur)))
                call wheres%push(text_where(file, start))
            end if
            cur = ''
        end do
    end subroutine text_py_statements

    !> Position of the '(' of a call of name in s (a whole name, any module prefix), 0: none.
    pure integer function text_py_call_at(s, name) result(k)
        character(len=*), intent(in) :: s, name
        integer :: i, j
        k = 0
        j = 1
        do
            i = index(s(j:), name // '(')
            if (i == 0) return
            i = i + j - 1
            if (i == 1) exit
            if (.not. text_name_char(s(i - 1:i - 1))) exit
            j = i + 1
        end do
        k = i + len(name)
    end function text_py_call_at

    !> The arguments of the call whose '(' is at k: positional ones, and key=value ones.
    subroutine text_py_call_args(s, k, pos, keys, vals)
        character(len=*), intent(in) :: s
        integer, intent(in) :: k
        type(text_list), intent(out) :: pos, keys, vals
        character :: q
        integer :: i, depth, start, e
        character(len=:), allocatable :: a
        depth = 0
        q = ' '
        start = k + 1
        do i = k + 1, len(s)
            if (q /= ' ') then
                if (s(i:i) == q) q = ' '
                cycle
            end if
            select case (s(i:i))
            case ('"', ''''); q = s(i:i)
            case ('(', '[', '{'); depth = depth + 1
            case (')', ']', '}')
                if (depth == 0) then
                    call add_arg(s(start:i - 1))
                    return
                end if
                depth = depth - 1
            case (',')
                if (depth == 0) then
                    call add_arg(s(start:i - 1))
                    start = i + 1
                end if
            case default
            end select
        end do
    contains
        subroutine add_arg(text)
            character(len=*), intent(in) :: text
            a = trim(adjustl(text))
            if (len(a) == 0) return
            e = index(a, '=')
            if (e > 1 .and. index(a, '==') == 0 .and. text_is_name(trim(a(1:e - 1)))) then
                call keys%push(trim(a(1:e - 1)))
                call vals%push(trim(adjustl(a(e + 1:))))
            else
                call pos%push(a)
            end if
        end subroutine add_arg
    end subroutine text_py_call_args

    !> The value of keyword key ('' if absent).
    function text_py_kwarg(keys, vals, key) result(v)
        type(text_list), intent(in) :: keys, vals
        character(len=*), intent(in) :: key
        character(len=:), allocatable :: v
        integer :: i
        v = ''
        do i = 1, keys%n
            if (keys%item(i)%s == key) v = vals%item(i)%s
        end do
    end function text_py_kwarg

end module hertzdamp_text_python
