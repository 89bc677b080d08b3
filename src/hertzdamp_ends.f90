!> The two definitions of when a contact is over (doc/theory.md section 3): their codes
!> and names.  The values are stable across versions (the C and legacy entry points take
!> them too: HERTZDAMP_END_* in hertzdamp.h).
module hertzdamp_ends
    implicit none
    private

    !> Contact ends when the overlap returns to zero (default).
    integer, parameter, public :: HD_END_OVERLAP = 0
    !> Contact ends when the total contact force returns to zero.
    integer, parameter, public :: HD_END_FORCE = 1

    public :: hertzdamp_end_name

contains

    !> Name of a contact-end definition: 'overlap' or 'force' ('unknown' for others).
    pure function hertzdamp_end_name(iend) result(name)
        integer, intent(in) :: iend   !! HD_END_OVERLAP or HD_END_FORCE
        character(len=:), allocatable :: name
        select case (iend)
        case (HD_END_OVERLAP); name = 'overlap'
        case (HD_END_FORCE); name = 'force'
        case default; name = 'unknown'
        end select
    end function hertzdamp_end_name

end module hertzdamp_ends
