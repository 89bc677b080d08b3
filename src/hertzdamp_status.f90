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
    integer, parameter, public :: HD_OUTSIDE_VALIDITY = 19 !! alpha outside the range where the method is valid
    integer, parameter, public :: HD_INACCURATE = 20       !! the method's error estimate exceeds the accuracy asked
    integer, parameter, public :: HD_BAD_RADIUS = 21       !! sphere radius not finite and positive
    integer, parameter, public :: HD_BAD_DENSITY = 22      !! density not finite and positive
    integer, parameter, public :: HD_BAD_MODULUS = 23      !! Young's modulus not finite and positive
    integer, parameter, public :: HD_BAD_POISSON = 24      !! Poisson's ratio outside (-1, 0.5]
    integer, parameter, public :: HD_BAD_LAW = 25          !! damping law not 0 (linear), 1 (tsuji) or 2 (kuwabara-kono)
    integer, parameter, public :: HD_BAD_HOST = 26         !! host scheme not one of the HD_HOST_* codes (hertzdamp_host)
    integer, parameter, public :: HD_BAD_STEPS = 27        !! steps per contact (or step h) not finite or outside the allowed range
    integer, parameter, public :: HD_HOST_UNREACHABLE = 28 !! no alpha reaches this e with the host at so few steps per contact
    integer, parameter, public :: HD_BAD_PAIR = 29         !! pair constants not set by hertzdamp_pair_init, or changed since
    integer, parameter, public :: HD_PHASE_UNREACHABLE = 30 !! some onset phase cannot reach e and T_c at so few steps
    integer, parameter, public :: HD_BAD_PHASE = 31        !! onset phase not finite or outside (0, 1]
    integer, parameter, public :: HD_NO_PHASE_TABLE = 32   !! the pair was initialised without its onset-phase table
    integer, parameter, public :: HD_BAD_TANGENTIAL = 33   !! tangential model or its parameters invalid
    integer, parameter, public :: HD_BAD_OBLIQUE = 34      !! oblique-contact argument invalid (tangential speed, radii, angle)

    !> Length of the stored messages (each fits, blank-padded).
    integer, parameter, public :: hertzdamp_message_len = 192
    !> Largest status code with a message of its own.
    integer, parameter, public :: hertzdamp_max_status = 34
    !> The message of every status code 0..hertzdamp_max_status, then that of unknown
    !> codes: the one table behind hertzdamp_message and the C hertzdamp_strerror.
    character(len=hertzdamp_message_len), parameter, public :: &
        hertzdamp_message_table(0:hertzdamp_max_status + 1) = [character(len=hertzdamp_message_len) :: &
        'success', &
        'no rebound: alpha >= alpha_c, the overlap never returns to zero (e = ' // &
            '0, contact time infinite)', &
        'integrator reached its maximum number of steps', &
        'integrator step size collapsed below round-off', &
        'invalid damping parameter alpha: must be finite, at most 1e100, >= 0 for the force ' // &
            'definition and >= -10 for the overlap definition (tsuji > -sqrt5, kuwabara-kono > -1.3884)', &
        'invalid contact-end definition: use 0 (overlap) or 1 (force)', &
        'invalid tolerance: must lie in [1e-15, 1e-2]', &
        'invalid mass: must be finite and positive', &
        'invalid impact velocity: must be finite and positive', &
        'invalid stiffness k: must be finite and positive', &
        'invalid damping coefficient d: must be finite and non-negative', &
        'invalid contact time: must be finite and positive', &
        'invalid restitution coefficient: the inverse rule needs 1e-3 <= e <= 1 (overlap) or ' // &
            '1e-4 <= e <= 1 (force); e -> 0 has no finite contact time', &
        'result out of the representable double-precision range', &
        'method does not support this contact-end definition', &
        'iteration did not converge', &
        'invalid series order: outside the stored range', &
        'invalid physical stiffness bound k_phys: must be finite and positive', &
        'invalid argument', &
        'alpha outside the validity range of the method (series: |alpha| < 1; pade: 0 <= alpha <= 0.8; ' // &
            'fit: alpha >= 0, force alpha <= 52.5; compact: e(alpha) >= 0.05); use rk45', &
        'inaccurate: the method''s own error estimate exceeds the accuracy asked (or alpha lies ' // &
            'beyond its validated range, or within the band below alpha_c where rk45 cannot resolve e)', &
        'invalid radius: must be finite and positive', &
        'invalid density: must be finite and positive', &
        'invalid Young''s modulus: must be finite and positive', &
        'invalid Poisson''s ratio: must lie in (-1, 0.5]', &
        'invalid damping law: use 0 (linear), 1 (tsuji) or 2 (kuwabara-kono)', &
        'invalid host scheme: use 0 (none), 1 (lammps), 2 (mfix-euler), 3 (mfix-ab2), 4 (verlet) or ' // &
            '5 (lammps-phase)', &
        'invalid steps per contact: must be finite with 2 <= N <= 1e5 (dimensionless step h: 1e-5 <= h <= 4)', &
        'the host cannot reach this restitution coefficient at so few steps per contact: no damping ' // &
            'alpha >= 0 gives it (hertzdamp_host_min_steps tells which N can)', &
        'invalid pair: not set by hertzdamp_pair_init (or its failure), or changed since', &
        'the host cannot reach this restitution coefficient and contact time at every onset phase at so ' // &
            'few steps per contact (hertzdamp_phase_min_steps tells which N can)', &
        'invalid onset phase: must be finite and in (0, 1] (hertzdamp_onset_phase computes it from the ' // &
            'first overlap)', &
        'the pair has no onset-phase table: initialise it with the phase form (hertzdamp_pair_init with ' // &
            'phase = .true., hertzdamp_c_pair_init_phase)', &
        'invalid tangential model or parameters', &
        'invalid oblique-contact argument', &
        'unknown status code']

    public :: hertzdamp_message

contains

    !> A one-line English explanation of a status code.
    pure function hertzdamp_message(status) result(msg)
        integer, intent(in) :: status          !! a status returned by hertzdamp
        character(len=:), allocatable :: msg
        if (status >= 0 .and. status <= hertzdamp_max_status) then
            msg = trim(hertzdamp_message_table(status))
        else
            msg = trim(hertzdamp_message_table(hertzdamp_max_status + 1))
        end if
    end function hertzdamp_message

end module hertzdamp_status
