!> Text for the output contract of the `hertzdamp` program: valid UTF-8 everywhere
!> (invalid bytes replaced), one-line messages (control characters escaped), and the
!> number formats of the CSV and JSON outputs (fmt_short, for messages, and fmt_text,
!> fmt_text_short, for the text output, are the applications' own, hertzdamp_text_format).
module hertzdamp_cli_text
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_text_format, only: fmt_short, itoa, ROUND_TRIP, fmt_text, fmt_text_short, is_whole_text
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk
    !> U+FFFD REPLACEMENT CHARACTER, in UTF-8.
    character(len=*), parameter :: replacement = char(239) // char(191) // char(189)

    public :: utf8_clean, one_line, json_string, csv_field, fmt_csv, fmt_json
    !> The number formats and itoa of the applications, for the commands.
    public :: fmt_short, itoa, ROUND_TRIP, fmt_text, fmt_text_short, is_whole_text

contains

    !> Length of the valid UTF-8 sequence starting at s(i:i), 0 if it is not valid.
    pure integer function utf8_length(s, i) result(n)
        character(len=*), intent(in) :: s
        integer, intent(in) :: i
        integer :: c, lo, hi, k
        c = iachar(s(i:i))
        lo = 128
        hi = 191
        if (c < 128) then
            n = 1
            return
        else if (c >= 194 .and. c <= 223) then
            n = 2
        else if (c >= 224 .and. c <= 239) then
            n = 3
            if (c == 224) lo = 160      ! no overlong forms
            if (c == 237) hi = 159      ! no surrogates
        else if (c >= 240 .and. c <= 244) then
            n = 4
            if (c == 240) lo = 144
            if (c == 244) hi = 143      ! nothing above U+10FFFF
        else
            n = 0
            return
        end if
        if (i + n - 1 > len(s)) then
            n = 0
            return
        end if
        c = iachar(s(i + 1:i + 1))
        if (c < lo .or. c > hi) n = 0
        do k = i + 2, i + n - 1
            if (n == 0) exit
            c = iachar(s(k:k))
            if (c < 128 .or. c > 191) n = 0
        end do
    end function utf8_length

    !> `s` with every byte that is not part of a valid UTF-8 sequence replaced by U+FFFD.
    pure function utf8_clean(s) result(r)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: r
        character(len=:), allocatable :: buf   ! on the heap (see one_line)
        integer :: i, j, n
        allocate (character(len=3 * len(s)) :: buf)
        i = 1
        j = 0
        do while (i <= len(s))
            n = utf8_length(s, i)
            if (n == 0) then
                buf(j + 1:j + 3) = replacement
                j = j + 3
                i = i + 1
            else
                buf(j + 1:j + n) = s(i:i + n - 1)
                j = j + n
                i = i + n
            end if
        end do
        r = buf(1:j)
    end function utf8_clean

    !> `s` on one line: control characters written as \n, \r, \t or \xNN, a backslash
    !> as itself, invalid UTF-8 bytes as \xNN.  For messages on stderr.
    pure function one_line(s) result(r)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: r
        character(len=:), allocatable :: buf   ! on the heap: a message may quote a token of megabytes
        integer :: i, j, n, c
        allocate (character(len=4 * len(s)) :: buf)
        i = 1
        j = 0
        do while (i <= len(s))
            c = iachar(s(i:i))
            n = utf8_length(s, i)
            if (c == 10 .or. c == 13 .or. c == 9) then
                buf(j + 1:j + 2) = '\' // merge('n', merge('r', 't', c == 13), c == 10)
                j = j + 2
                i = i + 1
            else if (c < 32 .or. c == 127 .or. n == 0) then
                buf(j + 1:j + 4) = '\x' // hex2(c)
                j = j + 4
                i = i + 1
            else
                buf(j + 1:j + n) = s(i:i + n - 1)
                j = j + n
                i = i + n
            end if
        end do
        r = buf(1:j)
    end function one_line

    !> Two lower-case hexadecimal digits of a byte.
    pure function hex2(c) result(h)
        integer, intent(in) :: c
        character(len=2) :: h
        character(len=*), parameter :: hex = '0123456789abcdef'
        h = hex(c / 16 + 1:c / 16 + 1) // hex(mod(c, 16) + 1:mod(c, 16) + 1)
    end function hex2

    !> A JSON string literal: valid UTF-8, quotes, backslashes and control characters escaped.
    pure function json_string(s) result(r)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: r
        character(len=:), allocatable :: u
        character(len=:), allocatable :: buf
        integer :: i, j, c
        u = utf8_clean(s)
        allocate (character(len=6 * len(u) + 2) :: buf)
        buf(1:1) = '"'
        j = 1
        do i = 1, len(u)
            c = iachar(u(i:i))
            if (c < 32 .or. c == 127) then
                buf(j + 1:j + 6) = '\u00' // hex2(c)
                j = j + 6
            else if (u(i:i) == '"' .or. u(i:i) == '\') then
                buf(j + 1:j + 2) = '\' // u(i:i)
                j = j + 2
            else
                buf(j + 1:j + 1) = u(i:i)
                j = j + 1
            end if
        end do
        r = buf(1:j) // '"'
    end function json_string

    !> A CSV field (RFC 4180): valid UTF-8, quoted when it holds a comma, a quote or a
    !> line break (quotes doubled).
    pure function csv_field(s) result(r)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: r
        integer :: i
        r = utf8_clean(s)
        if (scan(r, ',"' // achar(10) // achar(13)) == 0) return
        r = '"'
        do i = 1, len(s)
            if (s(i:i) == '"') r = r // '"'
            r = r // s(i:i)
        end do
        r = utf8_clean(r // '"')
    end function csv_field

    !> A number for CSV that reads back as the same double, in the fewest significant
    !> digits that do so among 15, 16 and 17, shown with at least 16 (trailing zeros):
    !> a value typed with up to 15 digits shows as typed (0.78719 is
    !> 7.871900000000000E-001, not the 7.871899999999999E-001 of 16 digits), most
    !> others take 16, and 17 where 16 would not read back (huge(1.0) is
    !> 1.7976931348623157E+308; 16 digits would round up to infinity).  'inf', '-inf'
    !> or 'nan' if not finite.
    function fmt_csv(x) result(s)
        real(wp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=40) :: buf, b15
        real(wp) :: y
        integer :: ios, k
        if (ieee_is_nan(x)) then
            s = 'nan'
        else if (.not. ieee_is_finite(x)) then
            s = merge('inf ', '-inf', x > 0.0_wp)
            s = trim(s)
        else
            write (buf, '(es24.15e3)') x
            read (buf, *, iostat=ios) y
            if (ios /= 0 .or. .not. (y == x)) then
                write (buf, '(es25.16e3)') x
            else
                ! 15 digits can read back only when the 16th is 9, 0 or 1 (the 15-digit
                ! decimal is within 1.2 units of the 16th digit of x); 0 shows it already
                buf = adjustl(buf)
                k = index(buf, 'E') - 1
                if (buf(k:k) == '9' .or. buf(k:k) == '1') then
                    write (b15, '(es23.14e3)') x
                    read (b15, *, iostat=ios) y
                    if (ios == 0 .and. y == x) then
                        b15 = adjustl(b15)
                        k = index(b15, 'E') - 1
                        buf = b15(1:k) // '0' // b15(k + 1:)
                    end if
                end if
            end if
            s = trim(adjustl(buf))
        end if
    end function fmt_csv

    !> A number for JSON: as fmt_csv (it reads back as the same double), null when
    !> not finite.
    function fmt_json(x) result(s)
        real(wp), intent(in) :: x
        character(len=:), allocatable :: s
        if (.not. ieee_is_finite(x)) then
            s = 'null'
        else
            s = fmt_csv(x)
        end if
    end function fmt_json

end module hertzdamp_cli_text
