!> Text helpers shared by the applications (the deck reader of `check`, the scene
!> reader, the calibration) and the command-line program: ASCII case conversion, an
!> integer as text, and the one short number format of messages and figures for people.
module hertzdamp_apps_text
    use hertzdamp_kinds, only: hertzdamp_rk
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk
    !> `digits` of fmt_short that always read back as the same double (the shortest such form).
    integer, parameter, public :: ROUND_TRIP = 17

    public :: lower, upper, itoa, fmt_short

contains

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

end module hertzdamp_apps_text
