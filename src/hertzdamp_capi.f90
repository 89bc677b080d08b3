!> C entry points, declared in `include/hertzdamp.h`.
!>
!> Every C name carries the prefix `hertzdamp_c_`, so that it never collides with
!> the legacy Fortran externals (`hertzdamp_invert_` ...), not even when a host
!> compiles with -fno-underscoring.
!>
!> Scalars are passed by value, results through pointers, and every function
!> returns an `int` status (0 = success; the codes of `hertzdamp_status`, mirrored
!> as `#define`s in the header).  No callbacks cross the boundary and there is no
!> mutable state: the functions are safe to call from any number of threads.  They
!> use the same method as the legacy Fortran entry points (`legacy_method` in
!> `hertzdamp_flat`), give the same numbers as the module API, bit for bit, and need
!> only the Fortran runtime.  Like every procedure of a module, they pay no save and
!> restore of the floating-point environment (see hertzdamp_legacy.f90):
!> `cc ... -lhertzdamp -lgfortran -lm`.
module hertzdamp_capi
    use, intrinsic :: iso_c_binding, only: c_double, c_int, c_char, c_ptr, c_loc, c_null_char
    use hertzdamp_status, only: HD_OK, HD_BAD_ARGUMENT, hertzdamp_message_table, hertzdamp_max_status, &
                                hertzdamp_message_len
    use hertzdamp_flat, only: flat_invert, flat_invert_n, flat_invert_bounded, flat_invert_law, flat_invert_law_n, &
                              flat_pair_law, flat_forward_law
    implicit none
    private

    public :: hertzdamp_c_invert, hertzdamp_c_invert_bounded, hertzdamp_c_invert_n, hertzdamp_c_pair, &
              hertzdamp_c_forward, hertzdamp_c_strerror
    public :: hertzdamp_c_invert_law, hertzdamp_c_invert_law_n, hertzdamp_c_pair_law, hertzdamp_c_forward_law

    integer, private :: i_   ! implied-do index of the initialisation below (never used at run time)
    !> The NUL-terminated messages of hertzdamp_message_table (the one table behind
    !> hertzdamp_message), built at compile time.  Never written to: a variable only
    !> so that `c_loc` can point into it.
    character(kind=c_char, len=hertzdamp_message_len + 1), dimension(0:hertzdamp_max_status + 1), &
        target :: c_messages = [character(kind=c_char, len=hertzdamp_message_len + 1) :: &
        (hertzdamp_message_table(i_)(1:len_trim(hertzdamp_message_table(i_))) // c_null_char, &
         i_=0, hertzdamp_max_status + 1)]

contains

    !> `int hertzdamp_c_invert(double e, double tc, double m, double u, int end,
    !> double *k, double *d)`: stiffness and damping for restitution e and contact
    !> time tc (doc/theory.md section 6).  On failure *k = *d = 0; a NULL k or d gives
    !> HD_BAD_ARGUMENT.
    integer(c_int) function hertzdamp_c_invert(e, tc, m, u, iend, k, d) &
            bind(c, name='hertzdamp_c_invert') result(status)
        real(c_double), value, intent(in) :: e       !! target restitution: [1e-3, 1] (overlap), [1e-4, 1] (force)
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

    !> `int hertzdamp_c_invert_bounded(double e, double tc, double m, double u,
    !> double k_phys, int end, double *k, double *d)`: hertzdamp_c_invert with the
    !> physical-stiffness bound (k = k_phys where k_phys <= k).  On failure
    !> *k = *d = 0; a NULL k or d gives HD_BAD_ARGUMENT.
    integer(c_int) function hertzdamp_c_invert_bounded(e, tc, m, u, k_phys, iend, k, d) &
            bind(c, name='hertzdamp_c_invert_bounded') result(status)
        real(c_double), value, intent(in) :: e       !! target restitution
        real(c_double), value, intent(in) :: tc      !! target contact time [s]
        real(c_double), value, intent(in) :: m       !! effective mass [kg]
        real(c_double), value, intent(in) :: u       !! impact velocity [m/s]
        real(c_double), value, intent(in) :: k_phys  !! physical stiffness bound [N m^-3/2]
        integer(c_int), value, intent(in) :: iend    !! contact end: 0 overlap, 1 force
        real(c_double), intent(out), optional :: k   !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(out), optional :: d   !! damping coefficient [kg/s]
        real(c_double) :: k_, d_
        integer :: st
        status = HD_BAD_ARGUMENT
        if (.not. (present(k) .and. present(d))) return
        call flat_invert_bounded(e, tc, m, u, k_phys, int(iend), k_, d_, st)
        k = k_
        d = d_
        status = int(st, c_int)
    end function hertzdamp_c_invert_bounded

    !> `int hertzdamp_c_invert_n(int n, const double *e, const double *tc, const double *m,
    !> const double *u, int end, double *k, double *d, int *status)`: hertzdamp_c_invert
    !> for n contacts; status[i] is each contact's status.  Returns HD_OK when every
    !> contact succeeded, else the first non-zero status (HD_BAD_ARGUMENT, touching
    !> nothing, when an array is NULL); n <= 0 does nothing.
    integer(c_int) function hertzdamp_c_invert_n(n, e, tc, m, u, iend, k, d, st) &
            bind(c, name='hertzdamp_c_invert_n') result(status)
        integer(c_int), value, intent(in) :: n       !! number of contacts
        real(c_double), intent(in), optional :: e(n) !! target restitution coefficients (n)
        real(c_double), intent(in), optional :: tc(n) !! target contact times [s] (n)
        real(c_double), intent(in), optional :: m(n) !! effective masses [kg] (n)
        real(c_double), intent(in), optional :: u(n) !! impact velocities [m/s] (n)
        integer(c_int), value, intent(in) :: iend    !! contact end: 0 overlap, 1 force
        real(c_double), intent(out), optional :: k(n) !! Hertz stiffnesses [N m^-3/2] (n)
        real(c_double), intent(out), optional :: d(n) !! damping coefficients [kg/s] (n)
        integer(c_int), intent(out), optional :: st(n) !! status of each contact (n)
        status = HD_OK
        if (n <= 0) return
        status = HD_BAD_ARGUMENT   ! a NULL array
        if (.not. (present(e) .and. present(tc) .and. present(m) .and. present(u) .and. present(k) .and. &
                   present(d) .and. present(st))) return
        ! vectorised over the arrays; the results of n calls of hertzdamp_c_invert
        call invert_blocks(int(n), e, tc, m, u, .false., 0, int(iend), k, d, st)
        status = first_failure(st)
    end function hertzdamp_c_invert_n

    !> The array inverse in blocks of `block` contacts through local arrays: every input
    !> of a block is read before any of its results is written, so a result array may
    !> be an input array itself (in place, as hertzdamp.h allows: k over e, d over tc,
    !> ...).  A partial overlap (k starting inside e at another element) is not allowed.
    !> flat_invert_law_n with `law` when with_law, else flat_invert_n.  Same kernel, the
    !> same bits per contact as one call over the whole arrays.
    subroutine invert_blocks(n, e, tc, m, u, with_law, law, iend, k, d, st)
        integer, intent(in) :: n, law, iend
        logical, intent(in) :: with_law
        real(c_double), intent(in) :: e(n), tc(n), m(n), u(n)
        real(c_double), intent(out) :: k(n), d(n)
        integer(c_int), intent(out) :: st(n)
        integer, parameter :: block = 256
        real(c_double) :: kb(block), db(block)
        integer :: sb(block), i0, nb
        do i0 = 1, n, block
            nb = min(block, n - i0 + 1)
            if (.not. with_law) then
                call flat_invert_n(nb, e(i0:i0 + nb - 1), tc(i0:i0 + nb - 1), m(i0:i0 + nb - 1), u(i0:i0 + nb - 1), &
                                   iend, kb(1:nb), db(1:nb), sb(1:nb))
            else
                call flat_invert_law_n(nb, e(i0:i0 + nb - 1), tc(i0:i0 + nb - 1), m(i0:i0 + nb - 1), &
                                       u(i0:i0 + nb - 1), law, iend, kb(1:nb), db(1:nb), sb(1:nb))
            end if
            k(i0:i0 + nb - 1) = kb(1:nb)
            d(i0:i0 + nb - 1) = db(1:nb)
            st(i0:i0 + nb - 1) = int(sb(1:nb), c_int)
        end do
    end subroutine invert_blocks

    !> The first non-zero status of an array, or HD_OK.
    pure integer(c_int) function first_failure(st) result(status)
        integer(c_int), intent(in) :: st(:)
        integer :: i
        status = HD_OK
        do i = 1, size(st)
            if (st(i) /= HD_OK) then
                status = st(i)
                return
            end if
        end do
    end function first_failure

    !> `int hertzdamp_c_pair(double e, int end, double *alpha, double *tau_c)`: the
    !> constants of a material pair, alpha(e) and tau_c(alpha(e)); per contact
    !> k = m (tau_c/T_c)^{5/2} u^{-1/2} and d = alpha m tau_c/T_c.  On failure
    !> *alpha = *tau_c = 0; a NULL pointer gives HD_BAD_ARGUMENT.
    integer(c_int) function hertzdamp_c_pair(e, iend, alpha, tau_c) &
            bind(c, name='hertzdamp_c_pair') result(status)
        real(c_double), value, intent(in) :: e          !! target restitution
        integer(c_int), value, intent(in) :: iend       !! contact end: 0 overlap, 1 force
        real(c_double), intent(out), optional :: alpha  !! damping parameter alpha(e)
        real(c_double), intent(out), optional :: tau_c  !! dimensionless contact duration
        status = hertzdamp_c_pair_law(e, 0_c_int, iend, alpha, tau_c)
    end function hertzdamp_c_pair

    !> `int hertzdamp_c_forward(double k, double d, double m, double u, int end,
    !> double *e, double *tc)`: restitution and contact time of a contact.  Without
    !> rebound *e = 0, *tc = DBL_MAX and the status is HD_NO_REBOUND (1); on other
    !> failures *e = *tc = 0; a NULL e or tc gives HD_BAD_ARGUMENT.
    integer(c_int) function hertzdamp_c_forward(k, d, m, u, iend, e, tc) &
            bind(c, name='hertzdamp_c_forward') result(status)
        real(c_double), value, intent(in) :: k       !! Hertz stiffness [N m^-3/2]
        real(c_double), value, intent(in) :: d       !! damping coefficient [kg/s]
        real(c_double), value, intent(in) :: m       !! effective mass [kg]
        real(c_double), value, intent(in) :: u       !! impact velocity [m/s]
        integer(c_int), value, intent(in) :: iend    !! contact end: 0 overlap, 1 force
        real(c_double), intent(out), optional :: e   !! restitution coefficient
        real(c_double), intent(out), optional :: tc  !! contact time [s]
        status = hertzdamp_c_forward_law(k, d, m, u, 0_c_int, iend, e, tc)
    end function hertzdamp_c_forward

    !> `int hertzdamp_c_invert_law(double e, double tc, double m, double u, double k_phys,
    !> int law, int end, double *k, double *d)`: hertzdamp_c_invert for the damping law
    !> `law` (HERTZDAMP_DAMPING_*; d in kg s^-1 m^-q), with the physical-stiffness bound
    !> when k_phys > 0 (k_phys = 0: none).  On failure *k = *d = 0; a NULL k or d gives
    !> HD_BAD_ARGUMENT.
    integer(c_int) function hertzdamp_c_invert_law(e, tc, m, u, k_phys, law, iend, k, d) &
            bind(c, name='hertzdamp_c_invert_law') result(status)
        real(c_double), value, intent(in) :: e       !! target restitution
        real(c_double), value, intent(in) :: tc      !! target contact time [s]
        real(c_double), value, intent(in) :: m       !! effective mass [kg]
        real(c_double), value, intent(in) :: u       !! impact velocity [m/s]
        real(c_double), value, intent(in) :: k_phys  !! physical stiffness bound [N m^-3/2], 0 for none
        integer(c_int), value, intent(in) :: law     !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), value, intent(in) :: iend    !! contact end: 0 overlap, 1 force
        real(c_double), intent(out), optional :: k   !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(out), optional :: d   !! damping coefficient [kg s^-1 m^-q]
        real(c_double) :: k_, d_
        integer :: st
        status = HD_BAD_ARGUMENT
        if (.not. (present(k) .and. present(d))) return
        call flat_invert_law(e, tc, m, u, k_phys, int(law), int(iend), k_, d_, st)
        k = k_
        d = d_
        status = int(st, c_int)
    end function hertzdamp_c_invert_law

    !> `int hertzdamp_c_invert_law_n(int n, const double *e, const double *tc, const double *m,
    !> const double *u, int law, int end, double *k, double *d, int *status)`:
    !> hertzdamp_c_invert_law without the bound (k_phys = 0) for n contacts; status[i] is
    !> each contact's status.  Returns HD_OK when every contact succeeded, else the first
    !> non-zero status (HD_BAD_ARGUMENT, touching nothing, when an array is NULL); n <= 0
    !> does nothing.
    integer(c_int) function hertzdamp_c_invert_law_n(n, e, tc, m, u, law, iend, k, d, st) &
            bind(c, name='hertzdamp_c_invert_law_n') result(status)
        integer(c_int), value, intent(in) :: n       !! number of contacts
        real(c_double), intent(in), optional :: e(n) !! target restitution coefficients (n)
        real(c_double), intent(in), optional :: tc(n) !! target contact times [s] (n)
        real(c_double), intent(in), optional :: m(n) !! effective masses [kg] (n)
        real(c_double), intent(in), optional :: u(n) !! impact velocities [m/s] (n)
        integer(c_int), value, intent(in) :: law     !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), value, intent(in) :: iend    !! contact end: 0 overlap, 1 force
        real(c_double), intent(out), optional :: k(n) !! Hertz stiffnesses [N m^-3/2] (n)
        real(c_double), intent(out), optional :: d(n) !! damping coefficients [kg s^-1 m^-q] (n)
        integer(c_int), intent(out), optional :: st(n) !! status of each contact (n)
        status = HD_OK
        if (n <= 0) return
        status = HD_BAD_ARGUMENT   ! a NULL array
        if (.not. (present(e) .and. present(tc) .and. present(m) .and. present(u) .and. present(k) .and. &
                   present(d) .and. present(st))) return
        ! vectorised over the arrays; the results of n calls of hertzdamp_c_invert_law
        call invert_blocks(int(n), e, tc, m, u, .true., int(law), int(iend), k, d, st)
        status = first_failure(st)
    end function hertzdamp_c_invert_law_n

    !> `int hertzdamp_c_pair_law(double e, int law, int end, double *alpha, double *tau_c)`:
    !> the material-pair constants of the damping law `law`; per contact t* = T_c/tau_c,
    !> k = m t*^{-5/2} u^{-1/2}, d = alpha m t*^{-1} (u t*)^{-q}.  On failure
    !> *alpha = *tau_c = 0; a NULL pointer gives HD_BAD_ARGUMENT.
    integer(c_int) function hertzdamp_c_pair_law(e, law, iend, alpha, tau_c) &
            bind(c, name='hertzdamp_c_pair_law') result(status)
        real(c_double), value, intent(in) :: e          !! target restitution
        integer(c_int), value, intent(in) :: law        !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), value, intent(in) :: iend       !! contact end: 0 overlap, 1 force
        real(c_double), intent(out), optional :: alpha  !! damping parameter alpha(e)
        real(c_double), intent(out), optional :: tau_c  !! dimensionless contact duration
        real(c_double) :: a_, t_
        integer :: st
        status = HD_BAD_ARGUMENT
        if (.not. (present(alpha) .and. present(tau_c))) return
        call flat_pair_law(e, int(law), int(iend), a_, t_, st)
        alpha = a_
        tau_c = t_
        status = int(st, c_int)
    end function hertzdamp_c_pair_law

    !> `int hertzdamp_c_forward_law(double k, double d, double m, double u, int law,
    !> int end, double *e, double *tc)`: hertzdamp_c_forward for the damping law `law`
    !> (d in kg s^-1 m^-q).  Without rebound *e = 0, *tc = DBL_MAX, status
    !> HD_NO_REBOUND; on other failures *e = *tc = 0; NULL gives HD_BAD_ARGUMENT.
    integer(c_int) function hertzdamp_c_forward_law(k, d, m, u, law, iend, e, tc) &
            bind(c, name='hertzdamp_c_forward_law') result(status)
        real(c_double), value, intent(in) :: k       !! Hertz stiffness [N m^-3/2]
        real(c_double), value, intent(in) :: d       !! damping coefficient [kg s^-1 m^-q]
        real(c_double), value, intent(in) :: m       !! effective mass [kg]
        real(c_double), value, intent(in) :: u       !! impact velocity [m/s]
        integer(c_int), value, intent(in) :: law     !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), value, intent(in) :: iend    !! contact end: 0 overlap, 1 force
        real(c_double), intent(out), optional :: e   !! restitution coefficient
        real(c_double), intent(out), optional :: tc  !! contact time [s]
        real(c_double) :: e_, tc_
        integer :: st
        status = HD_BAD_ARGUMENT
        if (.not. (present(e) .and. present(tc))) return
        call flat_forward_law(k, d, m, u, int(law), int(iend), e_, tc_, st)
        e = e_
        tc = tc_
        status = int(st, c_int)
    end function hertzdamp_c_forward_law

    !> `const char *hertzdamp_c_strerror(int status)`: a static NUL-terminated English
    !> message for a status code (never NULL; unknown codes get "unknown status code").
    type(c_ptr) function hertzdamp_c_strerror(status) bind(c, name='hertzdamp_c_strerror') result(msg)
        integer(c_int), value, intent(in) :: status  !! a status code
        integer :: i
        i = hertzdamp_max_status + 1
        if (status >= 0 .and. status <= hertzdamp_max_status) i = int(status)
        msg = c_loc(c_messages(i))
    end function hertzdamp_c_strerror

end module hertzdamp_capi
