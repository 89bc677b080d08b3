!> Text helpers shared by the applications (the deck reader of `check`, the scene
!> reader): ASCII case conversion.
module hertzdamp_apps_text
    implicit none
    private

    public :: lower, upper

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

end module hertzdamp_apps_text
