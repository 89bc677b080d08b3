!> Status codes returned by every hertzdamp procedure, and their messages.
!>
!> 0 means success.  The library never stops and never prints: it returns one of
!> these codes and `hertzdamp_message` explains it.  The values are stable across
!> versions (the C and legacy Fortran entry points return them too).
module hertzdamp_status
    implicit none
    private

    integer, parameter, public :: HD_OK = 0                !! success
    integer, parameter, public :: HD_NO_REBOUND = 1        !! overlap end with alpha >= alpha_c: e = 0, tau_c = +inf
    integer, parameter, public :: HD_MAX_STEPS = 2         !! integrator reached its step limit
    integer, parameter, public :: HD_STEP_UNDERFLOW = 3    !! step size collapsed below round-off
    integer, parameter, public :: HD_BAD_ALPHA = 4         !! alpha not finite or outside the supported range
    integer, parameter, public :: HD_BAD_END = 5           !! contact-end definition not 0 (overlap) or 1 (force)
    integer, parameter, public :: HD_BAD_TOL = 6           !! tolerance not in [1e-15, 1e-2]
    integer, parameter, public :: HD_BAD_MASS = 7          !! mass not finite and positive
    integer, parameter, public :: HD_BAD_VELOCITY = 8      !! impact velocity not finite and positive
    integer, parameter, public :: HD_BAD_STIFFNESS = 9     !! stiffness not finite and positive
    integer, parameter, public :: HD_BAD_DAMPING = 10      !! damping not finite and non-negative
    integer, parameter, public :: HD_BAD_TIME = 11         !! contact time not finite and positive
    integer, parameter, public :: HD_BAD_RESTITUTION = 12  !! restitution outside the supported range
    integer, parameter, public :: HD_OUT_OF_RANGE = 13     !! a result overflows or underflows double precision
    integer, parameter, public :: HD_NOT_SUPPORTED = 14    !! method does not support this contact-end definition
    integer, parameter, public :: HD_NO_CONVERGENCE = 15   !! an iteration did not converge
    integer, parameter, public :: HD_BAD_ORDER = 16        !! series order outside the stored range
    integer, parameter, public :: HD_BAD_KPHYS = 17        !! physical stiffness bound not finite and positive
    integer, parameter, public :: HD_BAD_ARGUMENT = 18     !! any other invalid argument
    integer, parameter, public :: HD_OUTSIDE_FIT = 19      !! argument outside the range of the fitted approximant

    !> Contact ends when the overlap returns to zero (default).
    integer, parameter, public :: HD_END_OVERLAP = 0
    !> Contact ends when the total contact force returns to zero.
    integer, parameter, public :: HD_END_FORCE = 1

    public :: hertzdamp_message, hertzdamp_end_name

contains

    !> A one-line English explanation of a status code.
    pure function hertzdamp_message(status) result(msg)
        integer, intent(in) :: status          !! a status returned by hertzdamp
        character(len=:), allocatable :: msg
        select case (status)
        case (HD_OK); msg = 'success'
        case (HD_NO_REBOUND); msg = 'no rebound: alpha >= alpha_c, the overlap never returns to zero ' // &
            '(e = 0, contact time infinite)'
        case (HD_MAX_STEPS); msg = 'integrator reached its maximum number of steps'
        case (HD_STEP_UNDERFLOW); msg = 'integrator step size collapsed below round-off'
        case (HD_BAD_ALPHA); msg = 'invalid damping parameter alpha: must be finite, >= 0 for the force ' // &
            'definition and > -20 for the overlap definition'
        case (HD_BAD_END); msg = 'invalid contact-end definition: use 0 (overlap) or 1 (force)'
        case (HD_BAD_TOL); msg = 'invalid tolerance: must lie in [1e-15, 1e-2]'
        case (HD_BAD_MASS); msg = 'invalid mass: must be finite and positive'
        case (HD_BAD_VELOCITY); msg = 'invalid impact velocity: must be finite and positive'
        case (HD_BAD_STIFFNESS); msg = 'invalid stiffness k: must be finite and positive'
        case (HD_BAD_DAMPING); msg = 'invalid damping coefficient d: must be finite and non-negative'
        case (HD_BAD_TIME); msg = 'invalid contact time: must be finite and positive'
        case (HD_BAD_RESTITUTION); msg = 'invalid restitution coefficient: outside the supported range ' // &
            '(the inverse rule needs e_min <= e <= 1 with e_min = 1e-3 for the overlap and 1e-4 for the ' // &
            'force definition; e -> 0 has no finite contact time)'
        case (HD_OUT_OF_RANGE); msg = 'result out of the representable double-precision range'
        case (HD_NOT_SUPPORTED); msg = 'method does not support this contact-end definition'
        case (HD_NO_CONVERGENCE); msg = 'iteration did not converge'
        case (HD_BAD_ORDER); msg = 'invalid series order: outside the stored range'
        case (HD_BAD_KPHYS); msg = 'invalid physical stiffness bound k_phys: must be finite and positive'
        case (HD_BAD_ARGUMENT); msg = 'invalid argument'
        case (HD_OUTSIDE_FIT); msg = 'argument outside the range of the fitted approximant ' // &
            '(fit/compact methods); use the rk45 method'
        case default; msg = 'unknown status code'
        end select
    end function hertzdamp_message

    !> Name of a contact-end definition: 'overlap' or 'force'.
    pure function hertzdamp_end_name(iend) result(name)
        integer, intent(in) :: iend   !! HD_END_OVERLAP or HD_END_FORCE
        character(len=:), allocatable :: name
        select case (iend)
        case (HD_END_OVERLAP); name = 'overlap'
        case (HD_END_FORCE); name = 'force'
        case default; name = 'unknown'
        end select
    end function hertzdamp_end_name

end module hertzdamp_status
