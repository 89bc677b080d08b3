!> The namelist-like syntax of MFiX decks (mfix.dat, .mfx): the assignments of a line
!> (`KEY = value`, several on a line, `KEY(i)` and `KEY(i:j)` keys) and the values of one
!> (words at blanks and commas outside quotes and `@( )`, `n*value` repeats, `@(expr)`
!> expressions, `1.0d-3` exponents, quotes removed).  Nothing prints or stops.
module hertzdamp_text_namelist
    use hertzdamp_text_list, only: text_list
    use hertzdamp_text_parse, only: text_number, text_shortest, text_strip_quotes, text_name_char
    use hertzdamp_text_expr, only: text_vars, text_eval, SYNTAX_MFIX
    use, intrinsic :: iso_fortran_env, only: real64
    implicit none
    private

    integer, parameter :: wp = real64

    public :: text_nml_assignments, text_nml_values

contains

    !> The '=' of each assignment (outside quotes and parentheses) and where its key starts.
    subroutine text_nml_assignments(line, eq, kstart)
        character(len=*), intent(in) :: line
        integer, allocatable, intent(out) :: eq(:), kstart(:)
        character :: q
        integer :: i, depth, k
        allocate (eq(0), kstart(0))
        q = ' '
        depth = 0
        do i = 1, len(line)
            if (q /= ' ') then
                if (line(i:i) == q) q = ' '
                cycle
            end if
            select case (line(i:i))
            case ('"', ''''); q = line(i:i)
            case ('('); depth = depth + 1
            case (')'); depth = max(0, depth - 1)
            case ('=')
                if (depth > 0) cycle
                k = key_start(line, i)
                if (k > 0) then
                    eq = [eq, i]
                    kstart = [kstart, k]
                end if
            case default
            end select
        end do
    end subroutine text_nml_assignments

    !> Start of the key before the '=' at position e: NAME or NAME(...); 0 if none.
    pure integer function key_start(line, e) result(k)
        character(len=*), intent(in) :: line
        integer, intent(in) :: e
        integer :: j, depth
        j = e - 1
        do while (j >= 1)
            if (line(j:j) /= ' ') exit
            j = j - 1
        end do
        if (j < 1) then
            k = 0
            return
        end if
        if (line(j:j) == ')') then
            depth = 0
            do while (j >= 1)
                if (line(j:j) == ')') depth = depth + 1
                if (line(j:j) == '(') depth = depth - 1
                j = j - 1
                if (depth == 0) exit
            end do
        end if
        k = j + 1
        do while (j >= 1)
            if (.not. text_name_char(line(j:j))) exit
            k = j
            j = j - 1
        end do
        if (k > j + 1 .or. .not. text_name_char(line(max(1, k):max(1, k)))) k = 0
        if (j >= 1 .and. k > 0) then
            if (line(j:j) /= ' ' .and. line(j:j) /= ',' .and. line(j:j) /= achar(9)) k = 0
        end if
    end function key_start

    !> The values of an assignment: words split at blanks and commas outside quotes and
    !> @( ), n*value repeated, @(expr) evaluated (MFiX's syntax), d exponents read, quotes
    !> removed.
    subroutine text_nml_values(text, vars, vals, errors)
        character(len=*), intent(in) :: text       !! the text after the '='
        type(text_vars), intent(inout) :: vars     !! the names @( ) may use
        type(text_list), intent(out) :: vals       !! the values
        type(text_list), intent(inout) :: errors   !! an @( ) that is not evaluated, why (the value is left out)
        character(len=:), allocatable :: w, msg
        character :: q
        integer :: i, j, depth, star, k
        real(wp) :: x, n
        i = 1
        do while (i <= len(text))
            if (text(i:i) == ' ' .or. text(i:i) == ',' .or. text(i:i) == achar(9)) then
                i = i + 1
                cycle
            end if
            q = ' '
            depth = 0
            do j = i, len(text)
                if (q /= ' ') then
                    if (text(j:j) == q) q = ' '
                else if (text(j:j) == '"' .or. text(j:j) == '''') then
                    q = text(j:j)
                else if (text(j:j) == '(') then
                    depth = depth + 1
                else if (text(j:j) == ')') then
                    depth = depth - 1
                else if (depth == 0 .and. (text(j:j) == ' ' .or. text(j:j) == ',' .or. text(j:j) == achar(9))) then
                    exit
                end if
            end do
            w = text(i:j - 1)
            i = j
            n = 1.0_wp
            star = index(w, '*')
            if (star > 1 .and. w(1:1) /= '@' .and. w(1:1) /= '''' .and. w(1:1) /= '"') then
                if (text_number(w(1:star - 1), n)) w = w(star + 1:)
            end if
            if (len(w) > 2) then
                if (w(1:2) == '@(') then
                    call text_eval(w(3:len(w) - 1), SYNTAX_MFIX, vars, x, msg)
                    if (len(msg) > 0) then
                        call errors%push('@(' // w(3:len(w) - 1) // '): ' // msg)
                        cycle
                    end if
                    w = text_shortest(x)
                end if
            end if
            if (scan(w, 'dD') > 0) then      ! 1.0d-3 as the readers take it
                if (text_number(w, x, fortran_d=.true.)) w = text_shortest(x)
            end if
            do k = 1, max(1, nint(n))
                call vals%push(text_strip_quotes(w))
            end do
        end do
    end subroutine text_nml_values

end module hertzdamp_text_namelist
