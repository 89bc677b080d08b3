!> Numbers and words in text: strict decimal numbers, a number as the shortest text that
!> reads back (and as C's "%.15g"), words split at blanks with quotes grouping them,
!> quotes stripped, the first character outside quotes, a path's directory, name
!> characters.  Nothing prints or stops.
module hertzdamp_text_parse
    use hertzdamp_text_list, only: text_list
    use hertzdamp_text_format, only: itoa, fmt_short, ROUND_TRIP
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use, intrinsic :: iso_fortran_env, only: real64
    implicit none
    private

    integer, parameter :: wp = real64

    public :: text_number, text_shortest, text_g15, text_words, text_strip_quotes, text_find_unquoted, text_directory
    public :: text_name_char, text_is_name

contains

    !> A strict decimal number ([sign] digits [. digits] [e|E [sign] digits], or
    !> [sign] . digits ...), finite.  `fortran_d`: also d/D exponents (1.0d-3).
    logical function text_number(text, x, fortran_d) result(ok)
        character(len=*), intent(in) :: text
        real(wp), intent(out) :: x
        logical, intent(in), optional :: fortran_d
        character(len=:), allocatable :: t
        integer :: i, n, nd, ios
        logical :: dexp
        x = 0.0_wp
        dexp = .false.
        if (present(fortran_d)) dexp = fortran_d
        t = text
        n = len(t)
        i = 1
        nd = 0
        ok = n > 0
        if (.not. ok) return
        if (t(1:1) == '+' .or. t(1:1) == '-') i = 2
        call digits()
        if (i <= n) then
            if (t(i:i) == '.') then
                i = i + 1
                call digits()
            end if
        end if
        ok = nd > 0
        if (ok .and. i <= n) then
            if (t(i:i) == 'e' .or. t(i:i) == 'E' .or. (dexp .and. (t(i:i) == 'd' .or. t(i:i) == 'D'))) then
                t(i:i) = 'e'
                i = i + 1
                if (i <= n) then
                    if (t(i:i) == '+' .or. t(i:i) == '-') i = i + 1
                end if
                nd = 0
                call digits()
                ok = nd > 0
            end if
        end if
        ok = ok .and. i > n
        if (.not. ok) return
        read (t, *, iostat=ios) x
        ok = ios == 0 .and. ieee_is_finite(x)
        if (.not. ok) x = 0.0_wp
    contains
        subroutine digits()
            do while (i <= n)
                if (t(i:i) < '0' .or. t(i:i) > '9') exit
                i = i + 1
                nd = nd + 1
            end do
        end subroutine digits
    end function text_number

    !> A number as the shortest text that reads back as the same double.
    function text_shortest(x) result(s)
        real(wp), intent(in) :: x
        character(len=:), allocatable :: s
        s = fmt_short(x, ROUND_TRIP)
    end function text_shortest

    !> x with at most 15 significant digits, as C's "%.15g" (LAMMPS substitutes equal-style
    !> variables so): trailing zeros dropped, plain notation for exponents -4 to 14.
    function text_g15(x) result(s)
        real(wp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=32) :: b
        character(len=15) :: d
        integer :: e, nd, ios
        if (.not. ieee_is_finite(x)) then
            s = fmt_short(x)
            return
        end if
        if (x == 0.0_wp) then
            s = '0'
            return
        end if
        write (b, '(es23.14e3)') abs(x)
        b = adjustl(b)
        d = b(1:1) // b(3:16)
        read (b(18:), *, iostat=ios) e
        if (ios /= 0) e = 0        ! (not reached: es23.14e3 always writes the exponent there)
        nd = len_trim(d)
        do while (nd > 1)
            if (d(nd:nd) /= '0') exit
            nd = nd - 1
        end do
        if (e < -4 .or. e >= 15) then
            s = d(1:1)
            if (nd > 1) s = s // '.' // d(2:nd)
            s = s // 'e' // itoa(e)
        else if (e >= 0) then
            if (nd <= e + 1) then
                s = d(1:nd) // repeat('0', e + 1 - nd)
            else
                s = d(1:e + 1) // '.' // d(e + 2:nd)
            end if
        else
            s = '0.' // repeat('0', -e - 1) // d(1:nd)
        end if
        if (x < 0.0_wp) s = '-' // s
    end function text_g15

    !> The directory part of a path, with its slash ('' for none).
    pure function text_directory(path) result(d)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: d
        d = path(1:index(path, '/', back=.true.))
    end function text_directory

    !> Append the words of s to `words`: separated by blanks and tabs; a word in single
    !> or double quotes (`quotes`) is one word without its quotes.
    subroutine text_words(s, words, quotes)
        character(len=*), intent(in) :: s
        type(text_list), intent(inout) :: words
        logical, intent(in), optional :: quotes
        integer :: i, j
        logical :: q
        character :: c
        q = .false.
        if (present(quotes)) q = quotes
        i = 1
        do while (i <= len(s))
            c = s(i:i)
            if (c == ' ' .or. c == achar(9)) then
                i = i + 1
                cycle
            end if
            if (q .and. (c == '"' .or. c == '''')) then
                j = index(s(i + 1:), c)
                if (j > 0) then
                    call words%push(s(i + 1:i + j - 1))
                    i = i + j + 1
                    cycle
                end if
            end if
            j = i
            do while (j <= len(s))
                if (s(j:j) == ' ' .or. s(j:j) == achar(9)) exit
                j = j + 1
            end do
            call words%push(s(i:j - 1))
            i = j
        end do
    end subroutine text_words

    !> s without one pair of enclosing single or double quotes.
    pure function text_strip_quotes(s) result(r)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: r
        r = trim(adjustl(s))
        if (len(r) >= 2) then
            if ((r(1:1) == '''' .and. r(len(r):len(r)) == '''') .or. (r(1:1) == '"' .and. r(len(r):len(r)) == '"')) then
                r = r(2:len(r) - 1)
            end if
        end if
    end function text_strip_quotes

    !> Position of the first character of s outside single and double quotes that is one
    !> of `set` (0: none), e.g. where a comment starts.
    pure integer function text_find_unquoted(s, set) result(k)
        character(len=*), intent(in) :: s     !! the text
        character(len=*), intent(in) :: set   !! the characters looked for
        character :: q
        integer :: i
        k = 0
        q = ' '
        do i = 1, len(s)
            if (q /= ' ') then
                if (s(i:i) == q) q = ' '
            else if (s(i:i) == '"' .or. s(i:i) == '''') then
                q = s(i:i)
            else if (index(set, s(i:i)) > 0) then
                k = i
                return
            end if
        end do
    end function text_find_unquoted

    !> Whether c may stand in a name: an ASCII letter or digit, or '_'.
    pure logical function text_name_char(c)
        character, intent(in) :: c   !! the character
        text_name_char = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z') .or. (c >= '0' .and. c <= '9') .or. &
                         c == '_'
    end function text_name_char

    !> Whether every character of s may stand in a name (text_name_char; true for '').
    pure logical function text_is_name(s)
        character(len=*), intent(in) :: s   !! the text
        text_is_name = verify(s, 'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_') == 0
    end function text_is_name

end module hertzdamp_text_parse
