!> C entry points, declared in `include/hertzdamp.h`.
!>
!> Scalars are passed by value, results through pointers, and every function
!> returns an `int` status (0 = success; the codes of `hertzdamp_status`, mirrored
!> as `#define`s in the header).  No callbacks cross the boundary and there is no
!> mutable state: the functions are safe to call from any number of threads.  They
!> use the same method as the legacy Fortran entry points (`legacy_method` in
!> `hertzdamp_flat`) and need only the Fortran runtime:
!> `cc ... -lhertzdamp -lgfortran -lm`.
module hertzdamp_capi
    use, intrinsic :: iso_c_binding, only: c_double, c_int, c_char, c_ptr, c_loc, c_null_char
    use hertzdamp_status, only: HD_OK, HD_BAD_ARGUMENT
    use hertzdamp_flat, only: flat_invert, flat_forward
    implicit none
    private

    public :: hertzdamp_c_invert, hertzdamp_c_forward, hertzdamp_c_strerror

    integer, parameter :: msg_len = 128   !! longest message + NUL, rounded up
    integer, parameter :: max_code = 18   !! largest status code with its own message

    !> The NUL-terminated message of every status code (the text of
    !> `hertzdamp_message`), then the message of unknown codes.  Never written to:
    !> it is a variable only so that `c_loc` can point into it.
    character(kind=c_char, len=msg_len), dimension(0:max_code + 1), target, save :: c_messages = [ &
        character(kind=c_char, len=msg_len) :: &
        'success' // c_null_char, &
        'no rebound: alpha >= alpha_c, the overlap never returns to zero ' // &
            '(e = 0, contact time infinite)' // c_null_char, &
        'integrator reached its maximum number of steps' // c_null_char, &
        'integrator step size collapsed below round-off' // c_null_char, &
        'invalid damping parameter alpha: must be finite, >= 0 for the force ' // &
            'definition and > -20 for the overlap definition' // c_null_char, &
        'invalid contact-end definition: use 0 (overlap) or 1 (force)' // c_null_char, &
        'invalid tolerance: must lie in [1e-15, 1e-2]' // c_null_char, &
        'invalid mass: must be finite and positive' // c_null_char, &
        'invalid impact velocity: must be finite and positive' // c_null_char, &
        'invalid stiffness k: must be finite and positive' // c_null_char, &
        'invalid damping coefficient d: must be finite and non-negative' // c_null_char, &
        'invalid contact time: must be finite and positive' // c_null_char, &
        'invalid restitution coefficient: outside the supported range' // c_null_char, &
        'result out of the representable double-precision range' // c_null_char, &
        'method does not support this contact-end definition' // c_null_char, &
        'iteration did not converge' // c_null_char, &
        'invalid series order: outside the stored range' // c_null_char, &
        'invalid physical stiffness bound k_phys: must be finite and positive' // c_null_char, &
        'invalid argument' // c_null_char, &
        'unknown status code' // c_null_char]

contains

    !> `int hertzdamp_invert(double e, double tc, double m, double u, int end,
    !> double *k, double *d)`: stiffness and damping for restitution e and contact
    !> time tc (THEORY.md section 6).  On failure *k = *d = 0; a NULL k or d gives
    !> HD_BAD_ARGUMENT.
    integer(c_int) function hertzdamp_c_invert(e, tc, m, u, iend, k, d) &
            bind(c, name='hertzdamp_invert') result(status)
        real(c_double), value, intent(in) :: e       !! target restitution coefficient, in (0, 1]
        real(c_double), value, intent(in) :: tc      !! target contact time [s]
        real(c_double), value, intent(in) :: m       !! effective mass [kg]
        real(c_double), value, intent(in) :: u       !! impact velocity [m/s]
        integer(c_int), value, intent(in) :: iend    !! contact end: 0 overlap, 1 force
        real(c_double), intent(out), optional :: k   !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(out), optional :: d   !! damping coefficient [kg/s]
        real(c_double) :: k_, d_
        integer :: st
        status = HD_BAD_ARGUMENT
        if (.not. (present(k) .and. present(d))) return
        call flat_invert(e, tc, m, u, int(iend), k_, d_, st)
        k = k_
        d = d_
        status = int(st, c_int)
    end function hertzdamp_c_invert

    !> `int hertzdamp_forward(double k, double d, double m, double u, int end,
    !> double *e, double *tc)`: restitution and contact time of a contact.  Without
    !> rebound *e = 0, *tc = DBL_MAX and the status is HD_NO_REBOUND (1); on other
    !> failures *e = *tc = 0; a NULL e or tc gives HD_BAD_ARGUMENT.
    integer(c_int) function hertzdamp_c_forward(k, d, m, u, iend, e, tc) &
            bind(c, name='hertzdamp_forward') result(status)
        real(c_double), value, intent(in) :: k       !! Hertz stiffness [N m^-3/2]
        real(c_double), value, intent(in) :: d       !! damping coefficient [kg/s]
        real(c_double), value, intent(in) :: m       !! effective mass [kg]
        real(c_double), value, intent(in) :: u       !! impact velocity [m/s]
        integer(c_int), value, intent(in) :: iend    !! contact end: 0 overlap, 1 force
        real(c_double), intent(out), optional :: e   !! restitution coefficient
        real(c_double), intent(out), optional :: tc  !! contact time [s]
        real(c_double) :: e_, tc_
        integer :: st
        status = HD_BAD_ARGUMENT
        if (.not. (present(e) .and. present(tc))) return
        call flat_forward(k, d, m, u, int(iend), e_, tc_, st)
        e = e_
        tc = tc_
        status = int(st, c_int)
    end function hertzdamp_c_forward

    !> `const char *hertzdamp_strerror(int status)`: a static NUL-terminated English
    !> message for a status code (never NULL; unknown codes get "unknown status code").
    type(c_ptr) function hertzdamp_c_strerror(status) bind(c, name='hertzdamp_strerror') result(msg)
        integer(c_int), value, intent(in) :: status  !! a status code
        integer :: i
        i = max_code + 1
        if (status >= 0 .and. status <= max_code) i = int(status)
        msg = c_loc(c_messages(i))
    end function hertzdamp_c_strerror

end module hertzdamp_capi
