!> Number and case formats shared by the applications (the deck reader of `check`, the
!> scene reader, the calibration) and the command-line program: ASCII case conversion,
!> an integer as text, the one short number format of messages (fmt_short) and the
!> number formats of every text output for people (fmt_text in tables, fmt_text_short
!> for single values and prose), in this one place.
!>
!> The text package needs nothing of the core: its reals are real64, the core's
!> hertzdamp_rk.
module hertzdamp_text_format
    use, intrinsic :: iso_fortran_env, only: real64
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
    implicit none
    private

    integer, parameter :: wp = real64
    !> `digits` of fmt_short that always read back as the same double (the shortest such form).
    integer, parameter, public :: ROUND_TRIP = 17

    public :: lower, upper, itoa, fmt_short, fmt_text, fmt_text_short, is_whole_text, prose

contains

    !> Space-separated words as prose: 'a, b or c' (conj replaces 'or'), each word between
    !> quote characters when quote is given (a registry's choices as a message lists them).
    pure function prose(words, conj, quote) result(s)
        character(len=*), intent(in) :: words             !! the words, blank-separated
        character(len=*), intent(in), optional :: conj    !! the last joint (default 'or')
        character(len=*), intent(in), optional :: quote   !! put around each word
        character(len=:), allocatable :: s, c, q, w
        integer :: i, j, n, k
        c = 'or'
        if (present(conj)) c = conj
        q = ''
        if (present(quote)) q = quote
        n = 0
        i = 1
        do while (i <= len(words))          ! count the words
            if (words(i:i) /= ' ') then
                n = n + 1
                j = index(words(i:) // ' ', ' ') + i - 1
                i = j
            end if
            i = i + 1
        end do
        s = ''
        k = 0
        i = 1
        do while (i <= len(words))
            if (words(i:i) /= ' ') then
                j = index(words(i:) // ' ', ' ') + i - 1
                w = q // words(i:j - 1) // q
                k = k + 1
                if (k == 1) then
                    s = w
                else if (k == n) then
                    s = s // ' ' // c // ' ' // w
                else
                    s = s // ', ' // w
                end if
                i = j
            end if
            i = i + 1
        end do
    end function prose

    !> `s` with the ASCII letters A-Z in lower case (other bytes unchanged).
    pure function lower(s) result(r)
        character(len=*), intent(in) :: s   !! any text
        character(len=len(s)) :: r
        integer :: i
        r = s
        do i = 1, len(s)
            if (s(i:i) >= 'A' .and. s(i:i) <= 'Z') r(i:i) = achar(iachar(s(i:i)) + 32)
        end do
    end function lower

    !> `s` with the ASCII letters a-z in upper case (other bytes unchanged).
    pure function upper(s) result(r)
        character(len=*), intent(in) :: s   !! any text
        character(len=len(s)) :: r
        integer :: i
        r = s
        do i = 1, len(s)
            if (s(i:i) >= 'a' .and. s(i:i) <= 'z') r(i:i) = achar(iachar(s(i:i)) - 32)
        end do
    end function upper

    !> An integer as text.
    pure function itoa(i) result(s)
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        character(len=12) :: buf
        write (buf, '(i0)') i
        s = trim(buf)
    end function itoa

    !> A number for people (messages, short figures): the shortest decimal that reads
    !> back as `x`, or its rounding to `digits` significant digits (default 6) when
    !> none of that many does (ROUND_TRIP digits always read back); trailing zeros
    !> dropped, plain notation from 1e-4 to below 1e6 (0.0005, 2.5, 10000), otherwise
    !> an exponent without plus sign or leading zeros (1.5e-7, 2e11, 1e100).  'inf',
    !> '-inf' or 'nan' if not finite.  CSV and JSON use their own full-precision forms.
    pure function fmt_short(x, digits) result(s)
        real(wp), intent(in) :: x                !! the number
        integer, intent(in), optional :: digits  !! at most this many significant digits (1 to ROUND_TRIP)
        character(len=:), allocatable :: s
        character(len=40) :: buf
        character(len=12) :: f
        real(wp) :: y
        integer :: d, dmax, ios
        dmax = 6
        if (present(digits)) dmax = max(1, min(ROUND_TRIP, digits))
        if (ieee_is_nan(x)) then
            s = 'nan'
            return
        else if (.not. ieee_is_finite(x)) then
            s = merge('inf ', '-inf', x > 0.0_wp)
            s = trim(s)
            return
        end if
        do d = 1, dmax
            write (f, '(a,i0,a)') '(es40.', d - 1, 'e3)'
            write (buf, f) x
            read (buf, *, iostat=ios) y
            if (ios == 0 .and. y == x) exit
        end do
        s = trim(adjustl(buf))
        call tidy(s)
    end function fmt_short

    !> A number in a table of the text output: a whole number below 1e7 as an integer
    !> (is_whole_text: 20, 0, -3), otherwise 7 significant digits with a lower-case
    !> exponent with sign and two digits (three beyond 1e99 and below 1e-99):
    !> 9.965498e+08, -1.080782e-02; 'inf', '-inf' or 'nan' if not finite.
    pure function fmt_text(x) result(s)
        real(wp), intent(in) :: x   !! the number
        character(len=:), allocatable :: s
        character(len=24) :: buf
        integer :: n
        if (.not. ieee_is_finite(x)) then
            s = fmt_short(x)
            return
        else if (is_whole_text(x)) then
            s = itoa(nint(x))
            return
        end if
        write (buf, '(es16.6e3)') x
        s = trim(adjustl(buf))
        n = len(s)
        ! d.ddddddE+0dd -> d.dddddde+dd
        if (s(n - 2:n - 2) == '0') s = s(1:n - 3) // s(n - 1:n)
        s = lower_e(s)
    end function fmt_text

    !> A single number for people (a column that never changes, a value in a
    !> sentence of the text output): a whole number below 1e7 as an integer (20, not
    !> 2.000000E+001), otherwise the shortest decimal of at most `digits` (default 7)
    !> significant digits that reads back as `x` or its rounding: plain from 1e-4 to
    !> below 1e6 (0.9, 0.0005), else with the exponent of fmt_text (9.965498e+08,
    !> 1e-05).  'inf', '-inf' or 'nan' if not finite.
    pure function fmt_text_short(x, digits) result(s)
        real(wp), intent(in) :: x                !! the number
        integer, intent(in), optional :: digits  !! at most this many significant digits (default 7)
        character(len=:), allocatable :: s
        integer :: ie, ex, ios, d
        d = 7
        if (present(digits)) d = digits
        if (is_whole_text(x)) then
            s = itoa(nint(x))
            return
        end if
        s = fmt_short(x, d)
        ie = index(s, 'e')
        if (ie == 0) return
        read (s(ie + 1:), *, iostat=ios) ex
        if (ios /= 0) return
        s = s(1:ie) // merge('-', '+', ex < 0) // repeat('0', merge(1, 0, abs(ex) < 10)) // itoa(abs(ex))
    end function fmt_text_short

    !> True when the text output writes `x` as an integer: a whole number below 1e7 in
    !> magnitude (at most 7 digits, as the other numbers of the text output).
    pure logical function is_whole_text(x)
        real(wp), intent(in) :: x   !! the number
        is_whole_text = .false.
        if (.not. ieee_is_finite(x)) return
        is_whole_text = abs(x) < 1.0e7_wp .and. x == aint(x)
    end function is_whole_text

    !> 'E' -> 'e' (the exponent letter of a number).
    pure function lower_e(s) result(r)
        character(len=*), intent(in) :: s
        character(len=len(s)) :: r
        integer :: i
        r = s
        i = index(r, 'E')
        if (i > 0) r(i:i) = 'e'
    end function lower_e

    !> 1.500e+000 -> 1.5, 2.000e+011 -> 2e11, 5.000e-001 -> 0.5.
    pure subroutine tidy(s)
        character(len=:), allocatable, intent(inout) :: s
        integer :: ie, ex, ios, j
        character(len=:), allocatable :: mant
        ie = scan(s, 'eE')
        if (ie == 0) return
        read (s(ie + 1:), *, iostat=ios) ex
        if (ios /= 0) return
        mant = s(1:ie - 1)
        if (index(mant, '.') > 0) then
            j = len(mant)
            do while (mant(j:j) == '0')
                j = j - 1
            end do
            if (mant(j:j) == '.') j = j - 1
            mant = mant(1:j)
        end if
        if (ex >= -4 .and. ex <= 5) then
            s = shift(mant, ex)
        else
            s = mant // 'e' // itoa(ex)
        end if
    end subroutine tidy

    !> Plain decimal form of mantissa * 10^ex (mantissa d.ddd, possibly signed).
    pure function shift(mant, ex) result(s)
        character(len=*), intent(in) :: mant
        integer, intent(in) :: ex
        character(len=:), allocatable :: s
        character(len=:), allocatable :: sign, dig
        integer :: p
        sign = ''
        dig = mant
        if (dig(1:1) == '-') then
            sign = '-'
            dig = dig(2:)
        end if
        p = index(dig, '.')
        if (p > 0) dig = dig(1:p - 1) // dig(p + 1:)
        ! dig holds the digits, the point after the first one
        p = 1 + ex
        if (p <= 0) then
            s = sign // '0.' // repeat('0', -p) // dig
        else if (p >= len(dig)) then
            s = sign // dig // repeat('0', p - len(dig))
        else
            s = sign // dig(1:p) // '.' // dig(p + 1:)
        end if
    end function shift

end module hertzdamp_text_format
