!> The C and legacy Fortran entry points: one binding layer, thin over the module API
!> (hertzdamp_pair for every inverse, hertzdamp_forward_dim for the forward problem), so
!> that every way in gives the module's numbers, bit for bit.  Both use the fit and need
!> only the Fortran runtime: `cc ... -lhertzdamp -lgfortran -lm`.
!>
!> **C** (`include/hertzdamp.h`): every name carries the prefix `hertzdamp_c_`, so that it
!> never collides with a legacy external (`hertzdamp_invert_` ...), not even when a host
!> compiles with -fno-underscoring.  Scalars by value, results through pointers, an `int`
!> status returned (0 = success; the codes of `hertzdamp_status`, mirrored as `#define`s
!> in the header); a NULL result pointer gives HD_BAD_ARGUMENT.  No callbacks cross the
!> boundary and there is no mutable state: safe from any number of threads.
!>
!> **Legacy Fortran** (fixed form, implicit interfaces; `include/hertzdamp.fi` declares
!> them): every argument by reference, reals DOUBLE PRECISION, integers default INTEGER,
!> the status in the last argument.  Their names and argument lists are stable across
!> versions.  Each is the C function of the same name with the status as an argument.
!>
!>       DOUBLE PRECISION E, TC, M, U, K, D
!>       INTEGER IEND, IERR
!>       CHARACTER*80 TEXT
!>       CALL HERTZDAMP_INVERT(E, TC, M, U, IEND, K, D, IERR)
!>       IF (IERR .NE. 0) CALL HERTZDAMP_MESSAGE(IERR, TEXT)
!>
!> (HERTZDAMP_MESSAGE, whose character argument has no binding-label form, is the
!> external subroutine of hertzdamp_legacy.f90.)
!>
!> Why module procedures with binding labels, and not external subroutines: gfortran
!> saves and restores the floating-point environment (`_gfortran_ieee_procedure_entry/exit`,
!> about 250 ns per call) around every procedure whose own scope sees a symbol of an
!> IEEE intrinsic module.  A `use` of any module of the library inside an external
!> subroutine brings such symbols along (every .mod that uses ieee_arithmetic, even with
!> `only:`, carries its derived types, and they travel through every module that uses
!> it), so external subroutines that used the library paid it on each call.  Here every
!> `use` is at module level, where it does not count for the procedures: they are module
!> procedures whose binding labels (`bind(c, name='hertzdamp_invert_')`, the name gfortran
!> gives an external HERTZDAMP_INVERT) keep the link names and the calling convention
!> (scalars and explicit-shape arrays by reference) of the externals.  Never `use` a
!> library module inside a procedure here; test/integration/fpenv_symbols.sh fails if an entry point
!> calls those routines again.
!>
!> One entry point is defined elsewhere and re-exported here: hertzdamp_c_pair_kd, the
!> per-contact call, lives in hertzdamp_pair so that the k, d code inlines into it (the
!> bare formula costs a few ns; a call between modules is not inlined without LTO).
module hertzdamp_capi
    use, intrinsic :: iso_c_binding, only: c_double, c_int, c_char, c_ptr, c_loc, c_null_char, c_intptr_t
    use hertzdamp_registry, only: HD_OK, HD_NO_REBOUND, HD_BAD_ARGUMENT, hertzdamp_message_table, hertzdamp_max_status, &
                                hertzdamp_message_len
    use hertzdamp_methods, only: hertzdamp_forward_dim, HD_METHOD_FIT
    use hertzdamp_pair, only: hertzdamp_pair_t, hertzdamp_pair_size, hertzdamp_pair_init, hertzdamp_invert, hertzdamp_c_pair_kd, &
                              hertzdamp_pair_status, &
                              hertzdamp_invert_contact
    use hertzdamp_host, only: HD_HOST_NONE, hertzdamp_host_stats, hertzdamp_host_mean, hertzdamp_host_min_steps
    implicit none
    private

    public :: hertzdamp_c_invert, hertzdamp_c_invert_bounded, hertzdamp_c_invert_n, hertzdamp_c_pair, &
              hertzdamp_c_forward, hertzdamp_c_strerror
    public :: hertzdamp_c_invert_law, hertzdamp_c_invert_law_n, hertzdamp_c_pair_law, hertzdamp_c_forward_law
    public :: hertzdamp_c_pair_init, hertzdamp_c_pair_kd, hertzdamp_c_pair_stats, hertzdamp_c_host_min_steps

    integer, private :: i_   ! implied-do index of the initialisation below (never used at run time)
    !> The NUL-terminated messages of hertzdamp_message_table (the one table behind
    !> hertzdamp_message), built at compile time.  Never written to: a variable only
    !> so that `c_loc` can point into it.
    character(kind=c_char, len=hertzdamp_message_len + 1), dimension(0:hertzdamp_max_status + 1), &
        target :: c_messages = [character(kind=c_char, len=hertzdamp_message_len + 1) :: &
        (hertzdamp_message_table(i_)(1:len_trim(hertzdamp_message_table(i_))) // c_null_char, &
         i_=0, hertzdamp_max_status + 1)]

contains

    ! ================================================================ C: the per-pair API

    !> `int hertzdamp_c_pair_init(double e, int law, int end, int host, double steps,
    !> hertzdamp_pair_t *p)`: the constants of a material pair (hertzdamp_pair_init); on
    !> failure *p is invalid (hertzdamp_c_pair_kd refuses it); NULL p gives HD_BAD_ARGUMENT.
    integer(c_int) function hertzdamp_c_pair_init(e, law, iend, host, steps, p) &
            bind(c, name='hertzdamp_c_pair_init') result(status)
        real(c_double), value, intent(in) :: e          !! target restitution
        integer(c_int), value, intent(in) :: law        !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), value, intent(in) :: iend       !! contact end: 0 overlap, 1 force
        integer(c_int), value, intent(in) :: host       !! host scheme (HERTZDAMP_HOST_*)
        real(c_double), value, intent(in) :: steps      !! steps per contact N (not used by host none)
        type(hertzdamp_pair_t), intent(out), optional :: p !! the pair's constants
        integer :: st
        status = HD_BAD_ARGUMENT
        if (.not. present(p)) return
        call hertzdamp_pair_init(e, int(law), int(iend), int(host), steps, p, st)
        status = int(st, c_int)
    end function hertzdamp_c_pair_init

    !> `int hertzdamp_c_pair_stats(const hertzdamp_pair_t *p, int host, double stats[8])`:
    !> what the pair's constants achieve in the host scheme `host` (HERTZDAMP_HOST_*, not
    !> necessarily the pair's own) at the pair's N steps per contact, over the onset phase
    !> (hertzdamp_host_mean at h = tau_c/N): stats = e mean, sd, min, max, then the contact
    !> time's mean, sd, min, max in units of the target T_c = N dt (host none: the continuous
    !> model, no spread).  For the log of a host that runs the pair with a scheme
    !> (a host-exact pair gives e mean = e), or with `host none` constants (the host's error).
    !> A pair not set by hertzdamp_c_pair_init gives HD_BAD_PAIR, a NULL pointer
    !> HD_BAD_ARGUMENT; on failure stats are 0.
    integer(c_int) function hertzdamp_c_pair_stats(p, host, stats) &
            bind(c, name='hertzdamp_c_pair_stats') result(status)
        type(hertzdamp_pair_t), intent(in), optional :: p      !! the pair's constants
        integer(c_int), value, intent(in) :: host              !! host scheme that runs them (HERTZDAMP_HOST_*)
        real(c_double), intent(out), optional :: stats(8)     !! e mean, sd, min, max; T_c/(N dt) mean, sd, min, max
        type(hertzdamp_host_stats) :: s
        real(c_double) :: out(8), a, tau, n
        integer :: st, law, iend
        status = HD_BAD_ARGUMENT
        if (.not. (present(p) .and. present(stats))) return
        ! everything read from the pair before stats is written: stats may overlap it
        out = 0.0_c_double
        st = hertzdamp_pair_status(p)
        a = p%alpha
        tau = p%tau_c
        n = p%steps
        law = int(p%law)
        iend = int(p%iend)
        if (st == HD_OK) then
            call hertzdamp_host_mean(a, tau / n, law, iend, int(host), s, st)
            if (st == HD_OK) out = [s%e_mean, s%e_sd, s%e_min, s%e_max, &
                                    s%tau_mean / tau, s%tau_sd / tau, s%tau_min / tau, s%tau_max / tau]
        end if
        stats = out
        status = int(st, c_int)
    end function hertzdamp_c_pair_stats

    !> `int hertzdamp_c_pair_size(void)`: the size of a pair in doubles (HERTZDAMP_PAIR_SIZE of
    !> hertzdamp.h), for a host that allocates pairs at run time (Python's ctypes).
    integer(c_int) function hertzdamp_c_pair_size() bind(c, name='hertzdamp_c_pair_size') result(n)
        n = int(hertzdamp_pair_size, c_int)
    end function hertzdamp_c_pair_size

    !> `int hertzdamp_c_host_min_steps(double e, int law, int end, int host, int *n_min)`:
    !> the fewest whole steps per contact N for which hertzdamp_c_pair_init succeeds with
    !> this host (hertzdamp_host_min_steps; host none: 2), for messages such as "N = 3 steps
    !> cannot reach e = 0.5 with lammps; N >= 6 can".  HERTZDAMP_HOST_UNREACHABLE when no N
    !> up to 1024 can; on failure *n_min = 0; a NULL n_min gives HD_BAD_ARGUMENT.
    integer(c_int) function hertzdamp_c_host_min_steps(e, law, iend, host, n_min) &
            bind(c, name='hertzdamp_c_host_min_steps') result(status)
        real(c_double), value, intent(in) :: e          !! target restitution
        integer(c_int), value, intent(in) :: law        !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), value, intent(in) :: iend       !! contact end: 0 overlap, 1 force
        integer(c_int), value, intent(in) :: host       !! host scheme (HERTZDAMP_HOST_*)
        integer(c_int), intent(out), optional :: n_min  !! fewest steps per contact that reach e
        integer :: n, st
        status = HD_BAD_ARGUMENT
        if (.not. present(n_min)) return
        call hertzdamp_host_min_steps(e, int(law), int(iend), int(host), n, st)
        n_min = int(n, c_int)
        status = int(st, c_int)
    end function hertzdamp_c_host_min_steps

    ! ================================================================ C: the one-call inverse

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
        ! hertzdamp_invert_contact directly, not through hertzdamp_c_invert_law: with -fPIC a
        ! bind(C) function is not inlined into another (it could be interposed), and each
        ! layer of call costs a few per cent of a scalar inverse
        status = HD_BAD_ARGUMENT
        if (.not. (present(k) .and. present(d))) return
        status = int(hertzdamp_invert_contact(e, tc, m, u, .false., 0.0_c_double, 0, int(iend), k_, d_), c_int)
        k = k_
        d = d_
    end function hertzdamp_c_invert

    !> `int hertzdamp_c_invert_bounded(double e, double tc, double m, double u,
    !> double k_phys, int end, double *k, double *d)`: hertzdamp_c_invert with the
    !> physical-stiffness bound (k = k_phys where k_phys <= k; k_phys must be finite and
    !> positive).  On failure *k = *d = 0; a NULL k or d gives HD_BAD_ARGUMENT.
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
        status = HD_BAD_ARGUMENT
        if (.not. (present(k) .and. present(d))) return
        status = int(hertzdamp_invert_contact(e, tc, m, u, .true., k_phys, 0, int(iend), k_, d_), c_int)
        k = k_
        d = d_
    end function hertzdamp_c_invert_bounded

    !> `int hertzdamp_c_invert_law(double e, double tc, double m, double u, double k_phys,
    !> int law, int end, double *k, double *d)`: hertzdamp_c_invert for the damping law
    !> `law` (HERTZDAMP_DAMPING_*; d in kg s^-1 m^-q), with the physical-stiffness bound
    !> when k_phys /= 0 (k_phys = 0: none; negative or not finite: HD_BAD_KPHYS).  On
    !> failure *k = *d = 0; a NULL k or d gives HD_BAD_ARGUMENT.
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
        status = HD_BAD_ARGUMENT
        if (.not. (present(k) .and. present(d))) return
        status = int(hertzdamp_invert_contact(e, tc, m, u, k_phys /= 0.0_c_double, k_phys, int(law), int(iend), k_, &
                                              d_), c_int)
        k = k_
        d = d_
    end function hertzdamp_c_invert_law

    !> `int hertzdamp_c_invert_n(int n, const double *e, const double *tc, const double *m,
    !> const double *u, int end, double *k, double *d, int *status)`: hertzdamp_c_invert
    !> for n contacts, vectorised; status[i] is each contact's status.  Returns HD_OK when
    !> every contact succeeded, else the first non-zero status (HD_BAD_ARGUMENT, touching
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
        status = hertzdamp_c_invert_law_n(n, e, tc, m, u, 0_c_int, iend, k, d, st)
    end function hertzdamp_c_invert_n

    !> `int hertzdamp_c_invert_law_n(int n, const double *e, const double *tc, const double *m,
    !> const double *u, int law, int end, double *k, double *d, int *status)`:
    !> hertzdamp_c_invert_law without the bound (k_phys = 0) for n contacts, vectorised;
    !> status[i] is each contact's status.  Returns HD_OK when every contact succeeded,
    !> else the first non-zero status (HD_BAD_ARGUMENT, touching nothing, when an array is
    !> NULL); n <= 0 does nothing.  A result array may overlap an input array, in place or
    !> shifted: the overlap is detected here and the inputs are copied first (the module's
    !> array forms, like any Fortran procedure, take no aliased arguments).  The results are
    !> those of separate arrays, bit for bit (the result arrays must not overlap each
    !> other).
    integer(c_int) function hertzdamp_c_invert_law_n(n, e, tc, m, u, law, iend, k, d, st) &
            bind(c, name='hertzdamp_c_invert_law_n') result(status)
        integer(c_int), value, intent(in) :: n       !! number of contacts
        real(c_double), intent(in), optional, target :: e(n) !! target restitution coefficients (n)
        real(c_double), intent(in), optional, target :: tc(n) !! target contact times [s] (n)
        real(c_double), intent(in), optional, target :: m(n) !! effective masses [kg] (n)
        real(c_double), intent(in), optional, target :: u(n) !! impact velocities [m/s] (n)
        integer(c_int), value, intent(in) :: law     !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), value, intent(in) :: iend    !! contact end: 0 overlap, 1 force
        real(c_double), intent(out), optional, target :: k(n) !! Hertz stiffnesses [N m^-3/2] (n)
        real(c_double), intent(out), optional, target :: d(n) !! damping coefficients [kg s^-1 m^-q] (n)
        integer(c_int), intent(out), optional, target :: st(n) !! status of each contact (n)
        real(c_double), allocatable :: copy(:, :)
        integer(c_intptr_t) :: ins(2, 4), outs(2, 3)
        integer :: i, j, ierr
        status = HD_OK
        if (n <= 0) return
        status = HD_BAD_ARGUMENT   ! a NULL array
        if (.not. (present(e) .and. present(tc) .and. present(m) .and. present(u) .and. present(k) .and. &
                   present(d) .and. present(st))) return
        ! byte ranges [first, last] of the arrays
        ins(:, 1) = byte_range(c_loc(e), 8 * int(n, c_intptr_t))
        ins(:, 2) = byte_range(c_loc(tc), 8 * int(n, c_intptr_t))
        ins(:, 3) = byte_range(c_loc(m), 8 * int(n, c_intptr_t))
        ins(:, 4) = byte_range(c_loc(u), 8 * int(n, c_intptr_t))
        outs(:, 1) = byte_range(c_loc(k), 8 * int(n, c_intptr_t))
        outs(:, 2) = byte_range(c_loc(d), 8 * int(n, c_intptr_t))
        outs(:, 3) = byte_range(c_loc(st), 4 * int(n, c_intptr_t))
        if (any([((overlap(outs(:, j), ins(:, i)), i = 1, 4), j = 1, 3)])) then
            ! a result would overwrite an input: work on copies
            allocate (copy(n, 4), stat=ierr)
            if (ierr /= 0) return
            copy(:, 1) = e
            copy(:, 2) = tc
            copy(:, 3) = m
            copy(:, 4) = u
            call hertzdamp_invert(copy(:, 1), copy(:, 2), copy(:, 3), copy(:, 4), int(iend), k, d, st, law=int(law))
        else
            call hertzdamp_invert(e, tc, m, u, int(iend), k, d, st, law=int(law))
        end if
        status = HD_OK
        do i = 1, n
            if (st(i) /= HD_OK) then
                status = st(i)
                return
            end if
        end do
    end function hertzdamp_c_invert_law_n

    !> The first and last byte address of an array of `bytes` bytes at p.
    pure function byte_range(p, bytes) result(r)
        type(c_ptr), intent(in) :: p
        integer(c_intptr_t), intent(in) :: bytes
        integer(c_intptr_t) :: r(2)
        r(1) = transfer(p, 0_c_intptr_t)
        r(2) = r(1) + bytes - 1
    end function byte_range

    !> True when two byte ranges [first, last] share a byte.
    pure logical function overlap(a, b)
        integer(c_intptr_t), intent(in) :: a(2), b(2)
        overlap = a(1) <= b(2) .and. b(1) <= a(2)
    end function overlap

    !> `int hertzdamp_c_pair(double e, int end, double *alpha, double *tau_c)`: the
    !> constants of a material pair, alpha(e) and tau_c(alpha(e)) (linear law); per contact
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

    !> `int hertzdamp_c_pair_law(double e, int law, int end, double *alpha, double *tau_c)`:
    !> the constants of a material pair (hertzdamp_pair_init, host none) of the damping law
    !> `law`; per contact t* = T_c/tau_c, k = m t*^{-5/2} u^{-1/2}, d = alpha m t*^{-1}
    !> (u t*)^{-q}.  On failure *alpha = *tau_c = 0; a NULL pointer gives HD_BAD_ARGUMENT.
    integer(c_int) function hertzdamp_c_pair_law(e, law, iend, alpha, tau_c) &
            bind(c, name='hertzdamp_c_pair_law') result(status)
        real(c_double), value, intent(in) :: e          !! target restitution
        integer(c_int), value, intent(in) :: law        !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), value, intent(in) :: iend       !! contact end: 0 overlap, 1 force
        real(c_double), intent(out), optional :: alpha  !! damping parameter alpha(e)
        real(c_double), intent(out), optional :: tau_c  !! dimensionless contact duration
        type(hertzdamp_pair_t) :: p
        integer :: st
        status = HD_BAD_ARGUMENT
        if (.not. (present(alpha) .and. present(tau_c))) return
        call hertzdamp_pair_init(e, int(law), int(iend), HD_HOST_NONE, 0.0_c_double, p, st)
        alpha = p%alpha
        tau_c = p%tau_c
        status = int(st, c_int)
    end function hertzdamp_c_pair_law

    ! ================================================================ C: forward, messages

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

    !> `int hertzdamp_c_forward_law(double k, double d, double m, double u, int law,
    !> int end, double *e, double *tc)`: hertzdamp_c_forward for the damping law `law`
    !> (d in kg s^-1 m^-q; the fit, as hertzdamp_forward_dim with HD_METHOD_FIT).  Without
    !> rebound *e = 0, *tc = DBL_MAX, status HD_NO_REBOUND; on other failures
    !> *e = *tc = 0; NULL gives HD_BAD_ARGUMENT.
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
        real(c_double) :: e_, tc_, alpha, tstar
        integer :: st
        status = HD_BAD_ARGUMENT
        if (.not. (present(e) .and. present(tc))) return
        ! without zeta_max: the fit skips the turning point (the same e, tc and status)
        call hertzdamp_forward_dim(k, d, m, u, int(iend), HD_METHOD_FIT, alpha, tstar, e_, tc_, status=st, law=int(law))
        select case (st)
        case (HD_OK)
        case (HD_NO_REBOUND)
            e_ = 0.0_c_double
            tc_ = huge(1.0_c_double)
        case default
            e_ = 0.0_c_double
            tc_ = 0.0_c_double
        end select
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

    ! ================================================================ legacy Fortran

    !> HERTZDAMP_INVERT(E, TC, M, U, IEND, K, D, IERR): stiffness k and damping d that give
    !> restitution e and contact time tc to a contact of effective mass m hit at speed u.
    !> On failure k = d = 0, ierr /= 0.
    subroutine legacy_invert(e, tc, m, u, iend, k, d, ierr) bind(c, name='hertzdamp_invert_')
        real(c_double), intent(in) :: e     !! target restitution coefficient: 1e-3 <= e <= 1 (overlap), 1e-4 <= e <= 1 (force)
        real(c_double), intent(in) :: tc    !! target contact time [s]
        real(c_double), intent(in) :: m     !! effective mass [kg]
        real(c_double), intent(in) :: u     !! impact velocity [m/s]
        integer(c_int), intent(in) :: iend  !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: k    !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(out) :: d    !! linear damping coefficient [kg/s]
        integer(c_int), intent(out) :: ierr !! 0 on success, else a status code
        ierr = int(hertzdamp_invert_contact(e, tc, m, u, .false., 0.0_c_double, 0, int(iend), k, d), c_int)
    end subroutine legacy_invert

    !> HERTZDAMP_INVERT_BOUNDED(E, TC, M, U, KPHYS, IEND, K, D, IERR): HERTZDAMP_INVERT with
    !> the physical-stiffness bound kphys = (4/3) E* sqrt(R*): where kphys <= k the contact
    !> keeps k = kphys and d = alpha m^(3/5) kphys^(2/5) u^(1/5) (it is then longer than
    !> tc, and the material's own stiffness is recovered once the time step is small
    !> enough).  On failure k = d = 0, ierr /= 0.
    subroutine legacy_invert_bounded(e, tc, m, u, kphys, iend, k, d, ierr) bind(c, name='hertzdamp_invert_bounded_')
        real(c_double), intent(in) :: e     !! target restitution coefficient
        real(c_double), intent(in) :: tc    !! target contact time [s]
        real(c_double), intent(in) :: m     !! effective mass [kg]
        real(c_double), intent(in) :: u     !! impact velocity [m/s]
        real(c_double), intent(in) :: kphys !! physical stiffness bound [N m^-3/2]
        integer(c_int), intent(in) :: iend  !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: k    !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(out) :: d    !! linear damping coefficient [kg/s]
        integer(c_int), intent(out) :: ierr !! 0 on success, else a status code
        ierr = int(hertzdamp_invert_contact(e, tc, m, u, .true., kphys, 0, int(iend), k, d), c_int)
    end subroutine legacy_invert_bounded

    !> HERTZDAMP_INVERT_N(N, E, TC, M, U, IEND, K, D, IERR): HERTZDAMP_INVERT for n contacts
    !> at once (one contact-end definition for all), vectorised; the same results, bit for
    !> bit.  n <= 0 does nothing.
    subroutine legacy_invert_n(n, e, tc, m, u, iend, k, d, ierr) bind(c, name='hertzdamp_invert_n_')
        integer(c_int), intent(in) :: n           !! number of contacts
        real(c_double), intent(in) :: e(n)        !! target restitution coefficients (n)
        real(c_double), intent(in) :: tc(n)       !! target contact times [s] (n)
        real(c_double), intent(in) :: m(n)        !! effective masses [kg] (n)
        real(c_double), intent(in) :: u(n)        !! impact velocities [m/s] (n)
        integer(c_int), intent(in) :: iend        !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: k(n)       !! Hertz stiffnesses [N m^-3/2] (n)
        real(c_double), intent(out) :: d(n)       !! damping coefficients [kg/s] (n)
        integer(c_int), intent(out) :: ierr(n)    !! status of each contact (n)
        integer(c_int) :: first
        first = hertzdamp_c_invert_law_n(n, e, tc, m, u, 0_c_int, iend, k, d, ierr)
    end subroutine legacy_invert_n

    !> HERTZDAMP_PAIR(E, IEND, ALPHA, TAUC, IERR): the constants of a material pair,
    !> alpha(e) and tau_c(alpha(e)), which depend on e and the contact end only.  Per
    !> contact (mass m, impact speed u, contact time tc):
    !>     k = m (tauc/tc)**2.5 / sqrt(u),   d = alpha m tauc/tc
    !> (d is the same for every contact of the pair with the same tc).  On failure
    !> alpha = tauc = 0, ierr /= 0.
    subroutine legacy_pair(e, iend, alpha, tauc, ierr) bind(c, name='hertzdamp_pair_')
        real(c_double), intent(in) :: e      !! target restitution coefficient
        integer(c_int), intent(in) :: iend   !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: alpha !! damping parameter alpha(e)
        real(c_double), intent(out) :: tauc  !! dimensionless contact duration tau_c(alpha)
        integer(c_int), intent(out) :: ierr  !! 0 on success, else a status code
        ierr = hertzdamp_c_pair_law(e, 0_c_int, iend, alpha, tauc)
    end subroutine legacy_pair

    !> HERTZDAMP_FORWARD(K, D, M, U, IEND, E, TC, IERR): restitution e and contact time tc
    !> of the contact (k, d, m, u).  Without rebound e = 0, tc = huge(1d0) and ierr = 1
    !> (HD_NO_REBOUND); on other failures e = tc = 0.
    subroutine legacy_forward(k, d, m, u, iend, e, tc, ierr) bind(c, name='hertzdamp_forward_')
        real(c_double), intent(in) :: k     !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(in) :: d     !! linear damping coefficient [kg/s]
        real(c_double), intent(in) :: m     !! effective mass [kg]
        real(c_double), intent(in) :: u     !! impact velocity [m/s]
        integer(c_int), intent(in) :: iend  !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: e    !! restitution coefficient
        real(c_double), intent(out) :: tc   !! contact time [s]
        integer(c_int), intent(out) :: ierr !! 0 on success, 1 no rebound, else a status code
        ierr = hertzdamp_c_forward_law(k, d, m, u, 0_c_int, iend, e, tc)
    end subroutine legacy_forward

    !> HERTZDAMP_INVERT_LAW(E, TC, M, U, KPHYS, ILAW, IEND, K, D, IERR): HERTZDAMP_INVERT for
    !> the damping law ilaw (0 linear, 1 tsuji, 2 kuwabara-kono: damping force
    !> d zeta^q zeta', q = 0, 1/4, 1/2, d in kg s^-1 m^-q), with the physical-stiffness
    !> bound kphys when kphys /= 0 (kphys = 0: no bound).  On failure k = d = 0, ierr /= 0.
    subroutine legacy_invert_law(e, tc, m, u, kphys, ilaw, iend, k, d, ierr) bind(c, name='hertzdamp_invert_law_')
        real(c_double), intent(in) :: e     !! target restitution coefficient
        real(c_double), intent(in) :: tc    !! target contact time [s]
        real(c_double), intent(in) :: m     !! effective mass [kg]
        real(c_double), intent(in) :: u     !! impact velocity [m/s]
        real(c_double), intent(in) :: kphys !! physical stiffness bound [N m^-3/2], 0 for none
        integer(c_int), intent(in) :: ilaw  !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), intent(in) :: iend  !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: k    !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(out) :: d    !! damping coefficient [kg s^-1 m^-q]
        integer(c_int), intent(out) :: ierr !! 0 on success, else a status code
        ierr = int(hertzdamp_invert_contact(e, tc, m, u, kphys /= 0.0_c_double, kphys, int(ilaw), int(iend), k, d), &
                   c_int)
    end subroutine legacy_invert_law

    !> HERTZDAMP_INVERT_LAW_N(N, E, TC, M, U, ILAW, IEND, K, D, IERR): HERTZDAMP_INVERT_LAW
    !> without the bound (KPHYS = 0) for n contacts at once (one damping law and contact
    !> end for all), vectorised; the same results, bit for bit.  n <= 0 does nothing.
    subroutine legacy_invert_law_n(n, e, tc, m, u, ilaw, iend, k, d, ierr) bind(c, name='hertzdamp_invert_law_n_')
        integer(c_int), intent(in) :: n           !! number of contacts
        real(c_double), intent(in) :: e(n)        !! target restitution coefficients (n)
        real(c_double), intent(in) :: tc(n)       !! target contact times [s] (n)
        real(c_double), intent(in) :: m(n)        !! effective masses [kg] (n)
        real(c_double), intent(in) :: u(n)        !! impact velocities [m/s] (n)
        integer(c_int), intent(in) :: ilaw        !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), intent(in) :: iend        !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: k(n)       !! Hertz stiffnesses [N m^-3/2] (n)
        real(c_double), intent(out) :: d(n)       !! damping coefficients [kg s^-1 m^-q] (n)
        integer(c_int), intent(out) :: ierr(n)    !! status of each contact (n)
        integer(c_int) :: first
        first = hertzdamp_c_invert_law_n(n, e, tc, m, u, ilaw, iend, k, d, ierr)
    end subroutine legacy_invert_law_n

    !> HERTZDAMP_PAIR_LAW(E, ILAW, IEND, ALPHA, TAUC, IERR): the material-pair constants of
    !> the damping law ilaw; per contact
    !>     tstar = tc/tauc,  k = m tstar**(-2.5) / sqrt(u),  d = alpha m / tstar / (u tstar)**q.
    subroutine legacy_pair_law(e, ilaw, iend, alpha, tauc, ierr) bind(c, name='hertzdamp_pair_law_')
        real(c_double), intent(in) :: e      !! target restitution coefficient
        integer(c_int), intent(in) :: ilaw   !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), intent(in) :: iend   !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: alpha !! damping parameter alpha(e)
        real(c_double), intent(out) :: tauc  !! dimensionless contact duration tau_c(alpha)
        integer(c_int), intent(out) :: ierr  !! 0 on success, else a status code
        ierr = hertzdamp_c_pair_law(e, ilaw, iend, alpha, tauc)
    end subroutine legacy_pair_law

    !> HERTZDAMP_FORWARD_LAW(K, D, M, U, ILAW, IEND, E, TC, IERR): HERTZDAMP_FORWARD for the
    !> damping law ilaw (d in kg s^-1 m^-q).
    subroutine legacy_forward_law(k, d, m, u, ilaw, iend, e, tc, ierr) bind(c, name='hertzdamp_forward_law_')
        real(c_double), intent(in) :: k     !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(in) :: d     !! damping coefficient [kg s^-1 m^-q]
        real(c_double), intent(in) :: m     !! effective mass [kg]
        real(c_double), intent(in) :: u     !! impact velocity [m/s]
        integer(c_int), intent(in) :: ilaw  !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), intent(in) :: iend  !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: e    !! restitution coefficient
        real(c_double), intent(out) :: tc   !! contact time [s]
        integer(c_int), intent(out) :: ierr !! 0 on success, 1 no rebound, else a status code
        ierr = hertzdamp_c_forward_law(k, d, m, u, ilaw, iend, e, tc)
    end subroutine legacy_forward_law

    !> HERTZDAMP_PAIR_INIT(E, ILAW, IEND, IHOST, STEPS, PAIR, IERR): the constants of a
    !> material pair into REAL(8) PAIR(HERTZDAMP_PAIR_SIZE) (hertzdamp_pair_init): ihost = 0 the
    !> continuous model, else the host scheme's exact constants at steps = T_c/dt steps per
    !> contact.  On failure PAIR is invalid (HERTZDAMP_PAIR_KD refuses it), ierr /= 0.
    subroutine legacy_pair_init(e, ilaw, iend, ihost, steps, pair, ierr) bind(c, name='hertzdamp_pair_init_')
        real(c_double), intent(in) :: e              !! target restitution coefficient
        integer(c_int), intent(in) :: ilaw           !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), intent(in) :: iend           !! contact end: 0 overlap, 1 force
        integer(c_int), intent(in) :: ihost          !! host scheme: 0 none, 1 lammps, 2 mfix-euler, 3 mfix-ab2,
                                                     !! 4 verlet, 5 lammps-phase
        real(c_double), intent(in) :: steps          !! steps per contact N (not used by ihost = 0)
        type(hertzdamp_pair_t), intent(out) :: pair    !! REAL(8) PAIR(HERTZDAMP_PAIR_SIZE): the constants
        integer(c_int), intent(out) :: ierr          !! 0 on success, else a status code
        ierr = hertzdamp_c_pair_init(e, ilaw, iend, ihost, steps, pair)
    end subroutine legacy_pair_init

    !> HERTZDAMP_PAIR_KD(PAIR, TC, M, U, KPHYS, K, D, IERR): k and d of one contact from the
    !> constants of HERTZDAMP_PAIR_INIT: tc = N dt its target contact time, m its effective
    !> mass, u its impact speed; kphys > 0 the physical stiffness bound (<= 0: none).  On
    !> failure k = d = 0, ierr /= 0.
    subroutine legacy_pair_kd(pair, tc, m, u, kphys, k, d, ierr) bind(c, name='hertzdamp_pair_kd_')
        type(hertzdamp_pair_t), intent(in) :: pair     !! REAL(8) PAIR(HERTZDAMP_PAIR_SIZE) of HERTZDAMP_PAIR_INIT
        real(c_double), intent(in) :: tc             !! target contact time [s]
        real(c_double), intent(in) :: m              !! effective mass [kg]
        real(c_double), intent(in) :: u              !! impact velocity [m/s]
        real(c_double), intent(in) :: kphys          !! physical stiffness bound [N m^-3/2], <= 0 for none
        real(c_double), intent(out) :: k             !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(out) :: d             !! damping coefficient [kg s^-1 m^-q]
        integer(c_int), intent(out) :: ierr          !! 0 on success, else a status code
        ierr = hertzdamp_c_pair_kd(pair, tc, m, u, kphys, k, d)
    end subroutine legacy_pair_kd

end module hertzdamp_capi
