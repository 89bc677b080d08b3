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
!> Two entry points are defined elsewhere and re-exported here: hertzdamp_c_pair_kd and
!> hertzdamp_c_pair_kd_phase, the per-contact calls, live in hertzdamp_pair so that the
!> table and k, d code inline into them (the
!> bare formula costs a few ns; a call between modules is not inlined without LTO).
module hertzdamp_capi
    use, intrinsic :: iso_c_binding, only: c_double, c_int, c_char, c_ptr, c_loc, c_null_char, c_intptr_t
    use hertzdamp_registry, only: HD_OK, HD_NO_REBOUND, HD_BAD_ARGUMENT, hertzdamp_message_table, hertzdamp_max_status, &
                                hertzdamp_message_len
    use hertzdamp_registry, only: HD_METHOD_FIT
    use hertzdamp_methods, only: hertzdamp_forward_dim
    use hertzdamp_pair, only: hertzdamp_pair_t, hertzdamp_pair_size, hertzdamp_pair_init, hertzdamp_invert, hertzdamp_c_pair_kd, &
                              hertzdamp_pair_status, &
                              hertzdamp_invert_contact, hertzdamp_c_pair_kd_phase
    use hertzdamp_phase, only: hertzdamp_onset_phase, hertzdamp_phase_min_steps
    use hertzdamp_registry, only: HD_HOST_NONE
    use hertzdamp_host, only: hertzdamp_host_stats, hertzdamp_host_mean, hertzdamp_host_min_steps
    ! ---- for the array and lookup entry points of the Python package (issue 35; the block at the end)
    use, intrinsic :: iso_c_binding, only: c_ptrdiff_t
    use hertzdamp_registry, only: HD_BAD_PAIR, HD_BAD_STEPS, HD_OUT_OF_RANGE, HD_END_FORCE, hertzdamp_end_name, &
                                  hertzdamp_min_law, hertzdamp_max_law, hertzdamp_law_name, hertzdamp_min_end, &
                                  hertzdamp_max_end, hertzdamp_min_host, hertzdamp_max_host, hertzdamp_host_name, &
                                  hertzdamp_min_method, hertzdamp_max_method, hertzdamp_method_name, hertzdamp_status_name
    use hertzdamp_registry, only: hertzdamp_min_tangential, hertzdamp_max_tangential, hertzdamp_tangential_name, &
                                  hertzdamp_min_lever, hertzdamp_max_lever, hertzdamp_lever_name
    use hertzdamp_rk45, only: hertzdamp_rk45_default_tol
    use hertzdamp_series, only: hertzdamp_series_default_order
    use hertzdamp_methods, only: hertzdamp_default_accuracy
    use hertzdamp_pair, only: hertzdamp_pair_kd
    use hertzdamp_scaling, only: hertzdamp_reduce
    use hertzdamp_inverse, only: hertzdamp_invert_alpha
    use hertzdamp_materials, only: hertzdamp_pair_contact, hertzdamp_wall_contact, hertzdamp_rayleigh_time, &
                                   hertzdamp_hertz_time, hertzdamp_rayleigh_fraction
    ! ---- end of the block's use lines
    use hertzdamp_oblique, only: hertzdamp_oblique_t, hertzdamp_oblique_result, hertzdamp_oblique_impact, &
                                 hertzdamp_tangential_kt, hertzdamp_oblique_correct
    implicit none
    private

    public :: hertzdamp_c_invert, hertzdamp_c_invert_bounded, hertzdamp_c_invert_n, hertzdamp_c_pair, &
              hertzdamp_c_forward, hertzdamp_c_strerror
    public :: hertzdamp_c_invert_law, hertzdamp_c_invert_law_n, hertzdamp_c_pair_law, hertzdamp_c_forward_law
    public :: hertzdamp_c_pair_init, hertzdamp_c_pair_kd, hertzdamp_c_pair_stats, hertzdamp_c_host_min_steps
    public :: hertzdamp_c_pair_init_phase, hertzdamp_c_pair_kd_phase, hertzdamp_c_onset_phase, &
              hertzdamp_c_phase_min_steps
    public :: hertzdamp_c_tangential_kt, hertzdamp_c_oblique_impact, hertzdamp_c_oblique_correct
    ! ---- the block at the end (issue 35)
    public :: hertzdamp_c_code, hertzdamp_c_names, hertzdamp_c_invert_array, hertzdamp_c_forward_array, &
              hertzdamp_c_pair_kd_array, hertzdamp_c_pair_constants, hertzdamp_c_contact_array, &
              hertzdamp_c_timestep_array

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

    ! ================================================================ C: per-contact constants from the onset phase

    !> `int hertzdamp_c_pair_init_phase(double e, int law, int end, int host, double steps,
    !> hertzdamp_pair_t *p)`: hertzdamp_c_pair_init and the onset-phase table
    !> (hertzdamp_pair_init with phase = .true.); HD_PHASE_UNREACHABLE when some onset phase
    !> has no constants at this N (hertzdamp_c_phase_min_steps); on failure *p is invalid.
    integer(c_int) function hertzdamp_c_pair_init_phase(e, law, iend, host, steps, p) &
            bind(c, name='hertzdamp_c_pair_init_phase') result(status)
        real(c_double), value, intent(in) :: e          !! target restitution
        integer(c_int), value, intent(in) :: law        !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), value, intent(in) :: iend       !! contact end: 0 overlap, 1 force
        integer(c_int), value, intent(in) :: host       !! host scheme (HERTZDAMP_HOST_*)
        real(c_double), value, intent(in) :: steps      !! steps per contact N
        type(hertzdamp_pair_t), intent(out), optional :: p !! the pair's constants and table
        integer :: st
        status = HD_BAD_ARGUMENT
        if (.not. present(p)) return
        call hertzdamp_pair_init(e, int(law), int(iend), int(host), steps, p, st, phase=.true.)
        status = int(st, c_int)
    end function hertzdamp_c_pair_init_phase

    !> `int hertzdamp_c_onset_phase(double delta1, double u, double dt, double *phi)`: the
    !> onset phase delta1 / (u dt) of a contact first seen with overlap delta1
    !> (hertzdamp_onset_phase: a late detection, phi > 1, gives phi = 1); NULL HD_BAD_ARGUMENT.
    integer(c_int) function hertzdamp_c_onset_phase(delta1, u, dt, phi) &
            bind(c, name='hertzdamp_c_onset_phase') result(status)
        real(c_double), value, intent(in) :: delta1     !! first positive overlap [m]
        real(c_double), value, intent(in) :: u          !! approach speed [m/s]
        real(c_double), value, intent(in) :: dt         !! time step [s]
        real(c_double), intent(out), optional :: phi    !! onset phase in (0, 1]
        real(c_double) :: ph
        integer :: st
        status = HD_BAD_ARGUMENT
        if (.not. present(phi)) return
        call hertzdamp_onset_phase(delta1, u, dt, ph, st)
        phi = ph
        status = int(st, c_int)
    end function hertzdamp_c_onset_phase

    !> `int hertzdamp_c_phase_min_steps(double e, int law, int end, int host, int *n_min)`: the
    !> fewest whole N for which hertzdamp_c_pair_init_phase succeeds (hertzdamp_phase_min_steps);
    !> HD_PHASE_UNREACHABLE when none up to 1024 does; on failure *n_min = 0.
    integer(c_int) function hertzdamp_c_phase_min_steps(e, law, iend, host, n_min) &
            bind(c, name='hertzdamp_c_phase_min_steps') result(status)
        real(c_double), value, intent(in) :: e          !! target restitution
        integer(c_int), value, intent(in) :: law        !! damping law
        integer(c_int), value, intent(in) :: iend       !! contact end
        integer(c_int), value, intent(in) :: host       !! host scheme (HERTZDAMP_HOST_*)
        integer(c_int), intent(out), optional :: n_min  !! fewest steps per contact
        integer :: n, st
        status = HD_BAD_ARGUMENT
        if (.not. present(n_min)) return
        call hertzdamp_phase_min_steps(e, int(law), int(iend), int(host), n, st)
        n_min = int(n, c_int)
        status = int(st, c_int)
    end function hertzdamp_c_phase_min_steps

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

    !> HERTZDAMP_PAIR_INIT_PHASE(E, ILAW, IEND, IHOST, STEPS, PAIR, IERR): HERTZDAMP_PAIR_INIT
    !> and the onset-phase table (hertzdamp_c_pair_init_phase).
    subroutine legacy_pair_init_phase(e, ilaw, iend, ihost, steps, pair, ierr) &
            bind(c, name='hertzdamp_pair_init_phase_')
        real(c_double), intent(in) :: e              !! target restitution coefficient
        integer(c_int), intent(in) :: ilaw           !! damping law
        integer(c_int), intent(in) :: iend           !! contact end
        integer(c_int), intent(in) :: ihost          !! host scheme
        real(c_double), intent(in) :: steps          !! steps per contact N
        type(hertzdamp_pair_t), intent(out) :: pair    !! REAL(8) PAIR(HERTZDAMP_PAIR_SIZE)
        integer(c_int), intent(out) :: ierr          !! 0 on success, else a status code
        ierr = hertzdamp_c_pair_init_phase(e, ilaw, iend, ihost, steps, pair)
    end subroutine legacy_pair_init_phase

    !> HERTZDAMP_PAIR_KD_PHASE(PAIR, TC, M, U, KPHYS, PHI, K, D, IERR): k and d of one contact
    !> with onset phase PHI from HERTZDAMP_PAIR_INIT_PHASE (hertzdamp_c_pair_kd_phase).
    subroutine legacy_pair_kd_phase(pair, tc, m, u, kphys, phi, k, d, ierr) bind(c, name='hertzdamp_pair_kd_phase_')
        type(hertzdamp_pair_t), intent(in) :: pair     !! REAL(8) PAIR(HERTZDAMP_PAIR_SIZE)
        real(c_double), intent(in) :: tc             !! target contact time [s]
        real(c_double), intent(in) :: m              !! effective mass [kg]
        real(c_double), intent(in) :: u              !! impact velocity [m/s]
        real(c_double), intent(in) :: kphys          !! physical stiffness bound, <= 0 for none
        real(c_double), intent(in) :: phi            !! onset phase in (0, 1]
        real(c_double), intent(out) :: k             !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(out) :: d             !! damping coefficient [kg s^-1 m^-q]
        integer(c_int), intent(out) :: ierr          !! 0 on success, else a status code
        ierr = hertzdamp_c_pair_kd_phase(pair, tc, m, u, kphys, phi, k, d)
    end subroutine legacy_pair_kd_phase

    !> HERTZDAMP_ONSET_PHASE(DELTA1, U, DT, PHI, IERR): the onset phase DELTA1/(U DT), at most 1
    !> (hertzdamp_c_onset_phase).
    subroutine legacy_onset_phase(delta1, u, dt, phi, ierr) bind(c, name='hertzdamp_onset_phase_')
        real(c_double), intent(in) :: delta1         !! first positive overlap [m]
        real(c_double), intent(in) :: u              !! approach speed [m/s]
        real(c_double), intent(in) :: dt             !! time step [s]
        real(c_double), intent(out) :: phi           !! onset phase in (0, 1]
        integer(c_int), intent(out) :: ierr          !! 0 on success, else a status code
        ierr = hertzdamp_c_onset_phase(delta1, u, dt, phi)
    end subroutine legacy_onset_phase

    !> HERTZDAMP_PHASE_MIN_STEPS(E, ILAW, IEND, IHOST, NMIN, IERR): the fewest N for which
    !> HERTZDAMP_PAIR_INIT_PHASE succeeds (hertzdamp_c_phase_min_steps).
    subroutine legacy_phase_min_steps(e, ilaw, iend, ihost, nmin, ierr) bind(c, name='hertzdamp_phase_min_steps_')
        real(c_double), intent(in) :: e              !! target restitution coefficient
        integer(c_int), intent(in) :: ilaw           !! damping law
        integer(c_int), intent(in) :: iend           !! contact end
        integer(c_int), intent(in) :: ihost          !! host scheme
        integer(c_int), intent(out) :: nmin          !! fewest steps per contact
        integer(c_int), intent(out) :: ierr          !! 0 on success, else a status code
        ierr = hertzdamp_c_phase_min_steps(e, ilaw, iend, ihost, nmin)
    end subroutine legacy_phase_min_steps
    ! ================================================================ the oblique contact (C and legacy)

    !> The contact of the flat arguments (m2 = r2 = 0: a wall).
    pure function oblique_contact(m1, r1, m2, r2, k, d, law, iend, tangential, kt, xgammat, mu, lever) result(c)
        real(c_double), intent(in) :: m1, r1, m2, r2, k, d, kt, xgammat, mu
        integer(c_int), intent(in) :: law, iend, tangential, lever
        type(hertzdamp_oblique_t) :: c
        c = hertzdamp_oblique_t(m1=m1, r1=r1, m2=m2, r2=r2, k=k, d=d, law=int(law), iend=int(iend), &
                                tangential=int(tangential), kt=kt, xgammat=xgammat, mu=mu, lever=int(lever))
    end function oblique_contact

    !> `int hertzdamp_c_tangential_kt(int tangential, double kt_phys, double k, double k_phys,
    !> double *kt)`: the tangential stiffness of a softened contact (hertzdamp_tangential_kt:
    !> mindlin kt_phys k/k_phys, linear_history kt_phys (k/k_phys)^(4/5)); NULL kt gives
    !> HD_BAD_ARGUMENT.
    integer(c_int) function hertzdamp_c_tangential_kt(tangential, kt_phys, k, k_phys, kt) &
            bind(c, name='hertzdamp_c_tangential_kt') result(status)
        integer(c_int), value, intent(in) :: tangential !! HERTZDAMP_TANGENTIAL_*
        real(c_double), value, intent(in) :: kt_phys    !! the physical contact's k_t
        real(c_double), value, intent(in) :: k          !! the softened normal stiffness [N m^-3/2]
        real(c_double), value, intent(in) :: k_phys     !! the physical normal stiffness [N m^-3/2]
        real(c_double), intent(out), optional :: kt     !! the softened contact's k_t
        integer :: st
        real(c_double) :: v
        status = HD_BAD_ARGUMENT
        if (.not. present(kt)) return
        call hertzdamp_tangential_kt(int(tangential), kt_phys, k, k_phys, v, st)
        kt = v
        status = int(st, c_int)
    end function hertzdamp_c_tangential_kt

    !> `int hertzdamp_c_oblique_impact(double m1, double r1, double m2, double r2, double k,
    !> double d, int law, int end, int tangential, double kt, double xgammat, double mu,
    !> int lever, double speed, double angle, double out[8])`: the oblique impact of sphere 1
    !> on sphere 2 (m2 = r2 = 0: a wall) at speed and angle [degrees]
    !> (hertzdamp_oblique_impact, default tolerance): out = e_n, e_t, vt_ratio, rebound
    !> angle [degrees], omega1, omega2 [rad/s], sliding fraction, t_c [s]; 0 on failure.
    integer(c_int) function hertzdamp_c_oblique_impact(m1, r1, m2, r2, k, d, law, iend, tangential, kt, xgammat, &
                                                       mu, lever, speed, angle, out) &
            bind(c, name='hertzdamp_c_oblique_impact') result(status)
        real(c_double), value, intent(in) :: m1, r1, m2, r2 !! masses [kg] and radii [m]
        real(c_double), value, intent(in) :: k, d           !! normal stiffness and damping
        integer(c_int), value, intent(in) :: law, iend      !! HERTZDAMP_DAMPING_*, HERTZDAMP_END_*
        integer(c_int), value, intent(in) :: tangential     !! HERTZDAMP_TANGENTIAL_*
        real(c_double), value, intent(in) :: kt, xgammat, mu !! k_t, x_gammat, friction coefficient
        integer(c_int), value, intent(in) :: lever          !! HERTZDAMP_LEVER_*
        real(c_double), value, intent(in) :: speed, angle   !! impact speed [m/s], angle [degrees]
        real(c_double), intent(out), optional :: out(8)     !! the outcome
        type(hertzdamp_oblique_result) :: r
        integer :: st
        status = HD_BAD_ARGUMENT
        if (.not. present(out)) return
        call hertzdamp_oblique_impact(oblique_contact(m1, r1, m2, r2, k, d, law, iend, tangential, kt, xgammat, mu, &
                                                      lever), speed, angle, r, st)
        out = [r%e_n, r%e_t, r%vt_ratio, r%rebound_angle, r%omega1, r%omega2, r%slide_fraction, r%t_c]
        status = int(st, c_int)
    end function hertzdamp_c_oblique_impact

    !> `int hertzdamp_c_oblique_correct(double m1, double r1, double m2, double r2,
    !> double k_phys, int law, int end, int tangential, double kt_phys, double xgammat,
    !> double mu, int lever, double e, double tc, double speed, double angle, double out[4])`:
    !> the oblique normal correction of one contact (hertzdamp_oblique_correct, its fast
    !> default): out = k, d, k_t of the corrected target and that target e'; 0 on failure.
    integer(c_int) function hertzdamp_c_oblique_correct(m1, r1, m2, r2, k_phys, law, iend, tangential, kt_phys, &
                                                        xgammat, mu, lever, e, tc, speed, angle, out) &
            bind(c, name='hertzdamp_c_oblique_correct') result(status)
        real(c_double), value, intent(in) :: m1, r1, m2, r2 !! masses [kg] and radii [m]
        real(c_double), value, intent(in) :: k_phys         !! physical normal stiffness (bound, k_t scale)
        integer(c_int), value, intent(in) :: law, iend      !! HERTZDAMP_DAMPING_*, HERTZDAMP_END_*
        integer(c_int), value, intent(in) :: tangential     !! HERTZDAMP_TANGENTIAL_*
        real(c_double), value, intent(in) :: kt_phys, xgammat, mu !! physical k_t, x_gammat, friction
        integer(c_int), value, intent(in) :: lever          !! HERTZDAMP_LEVER_*
        real(c_double), value, intent(in) :: e, tc          !! target restitution and contact time [s]
        real(c_double), value, intent(in) :: speed, angle   !! impact speed [m/s], angle [degrees]
        real(c_double), intent(out), optional :: out(4)     !! k, d, k_t, e'
        real(c_double) :: k, d, kt, et
        integer :: st
        status = HD_BAD_ARGUMENT
        if (.not. present(out)) return
        call hertzdamp_oblique_correct(oblique_contact(m1, r1, m2, r2, k_phys, 0.0_c_double, law, iend, tangential, &
                                                       kt_phys, xgammat, mu, lever), e, tc, speed, angle, k, d, kt, et, st)
        out = [k, d, kt, et]
        status = int(st, c_int)
    end function hertzdamp_c_oblique_correct

    !> HERTZDAMP_TANGENTIAL_KT(ITANG, KTPHYS, K, KPHYS, KT, IERR): the legacy form of
    !> hertzdamp_c_tangential_kt.
    subroutine legacy_tangential_kt(itang, ktphys, k, kphys, kt, ierr) bind(c, name='hertzdamp_tangential_kt_')
        integer(c_int), intent(in) :: itang   !! tangential model: 0 linear_history, 1 mindlin
        real(c_double), intent(in) :: ktphys  !! the physical k_t
        real(c_double), intent(in) :: k       !! the softened normal stiffness [N m^-3/2]
        real(c_double), intent(in) :: kphys   !! the physical normal stiffness [N m^-3/2]
        real(c_double), intent(out) :: kt     !! the softened k_t
        integer(c_int), intent(out) :: ierr   !! 0 on success, else a status code
        ierr = hertzdamp_c_tangential_kt(itang, ktphys, k, kphys, kt)
    end subroutine legacy_tangential_kt

    !> HERTZDAMP_OBLIQUE(M1, R1, M2, R2, K, D, ILAW, IEND, ITANG, KT, XGT, MU, ILEVER, U,
    !> THETA, OUT, IERR): the legacy form of hertzdamp_c_oblique_impact, OUT(8).
    subroutine legacy_oblique(m1, r1, m2, r2, k, d, ilaw, iend, itang, kt, xgt, mu, ilever, u, theta, out, ierr) &
            bind(c, name='hertzdamp_oblique_')
        real(c_double), intent(in) :: m1, r1, m2, r2, k, d, kt, xgt, mu, u, theta !! as the C form
        integer(c_int), intent(in) :: ilaw, iend, itang, ilever                    !! as the C form
        real(c_double), intent(out) :: out(8)                                      !! the outcome
        integer(c_int), intent(out) :: ierr                                        !! 0 on success
        ierr = hertzdamp_c_oblique_impact(m1, r1, m2, r2, k, d, ilaw, iend, itang, kt, xgt, mu, ilever, u, theta, out)
    end subroutine legacy_oblique

    !> HERTZDAMP_OBLIQUE_CORRECT(M1, R1, M2, R2, KPHYS, ILAW, IEND, ITANG, KTPHYS, XGT, MU,
    !> ILEVER, E, TC, U, THETA, OUT, IERR): the legacy form of hertzdamp_c_oblique_correct,
    !> OUT(4) = K, D, KT, E'.
    subroutine legacy_oblique_correct(m1, r1, m2, r2, kphys, ilaw, iend, itang, ktphys, xgt, mu, ilever, e, tc, u, &
                                      theta, out, ierr) bind(c, name='hertzdamp_oblique_correct_')
        real(c_double), intent(in) :: m1, r1, m2, r2, kphys, ktphys, xgt, mu, e, tc, u, theta !! as the C form
        integer(c_int), intent(in) :: ilaw, iend, itang, ilever                                 !! as the C form
        real(c_double), intent(out) :: out(4)                                                   !! K, D, KT, E'
        integer(c_int), intent(out) :: ierr                                                     !! 0 on success
        ierr = hertzdamp_c_oblique_correct(m1, r1, m2, r2, kphys, ilaw, iend, itang, ktphys, xgt, mu, ilever, e, tc, &
                                           u, theta, out)
    end subroutine legacy_oblique_correct

    ! ================================================================ C: for the Python package (issue 35)
    ! BEGIN python block.  The names and codes of the enumerations (hertzdamp_c_code,
    ! hertzdamp_c_names), so that a binding reads them from the library, and array entry points
    ! with strides: an input x with stride s (in elements, s >= 0) gives contact i (from 0) the
    ! value x[i s]: s = 1 one value per contact, s = 0 one value for all (a broadcast without a
    ! copy).  The results are contiguous and must not overlap an input.  Each returns HD_OK when
    ! every contact succeeded, else the first non-zero status; n <= 0 does nothing; a NULL array
    ! that is required, or a negative stride, gives HD_BAD_ARGUMENT and touches nothing.  The
    ! contacts go through the module's array forms, contiguous inputs all at once, strided ones
    ! in blocks of up to 4096 gathered into buffers: the same bits as one call of the scalar C
    ! entry point per contact.

    !> The registry `kind` of the library: its names in the order of their codes, and the
    !> codes.  law, end, host, method, tangential, lever (HD_DAMPING_*, HD_END_*, HD_HOST_*,
    !> HD_METHOD_*, HD_TANGENTIAL_*, HD_LEVER_*), status
    !> (the HD_* codes of hertzdamp_status, lower case with dashes), stats (the fields of
    !> hertzdamp_c_pair_stats, codes their index from 0), size (pair: the doubles of
    !> hertzdamp_pair_t; stats: those of hertzdamp_c_pair_stats).
    subroutine registry(kind, count, names, codes)
        character(len=*), intent(in) :: kind
        integer, intent(out) :: count                 !! number of names; -1: no such registry
        character(len=32), intent(out) :: names(64)
        integer, intent(out) :: codes(64)
        character(len=8), parameter :: stats_names(0:7) = [character(len=8) :: &
            'e_mean', 'e_sd', 'e_min', 'e_max', 'tau_mean', 'tau_sd', 'tau_min', 'tau_max']
        integer :: i, n0
        names = ''
        codes = 0
        n0 = 0
        select case (kind)
        case ('law')
            count = hertzdamp_max_law - hertzdamp_min_law + 1
            n0 = hertzdamp_min_law
        case ('end')
            count = hertzdamp_max_end - hertzdamp_min_end + 1
            n0 = hertzdamp_min_end
        case ('host')
            count = hertzdamp_max_host - hertzdamp_min_host + 1
            n0 = hertzdamp_min_host
        case ('method')
            count = hertzdamp_max_method - hertzdamp_min_method + 1
            n0 = hertzdamp_min_method
        case ('tangential')
            count = hertzdamp_max_tangential - hertzdamp_min_tangential + 1
            n0 = hertzdamp_min_tangential
        case ('lever')
            count = hertzdamp_max_lever - hertzdamp_min_lever + 1
            n0 = hertzdamp_min_lever
        case ('status')
            count = hertzdamp_max_status + 1
        case ('stats')
            count = size(stats_names)
        case ('size')
            count = 2
            names(1:2) = [character(len=32) :: 'pair', 'stats']
            codes(1:2) = [hertzdamp_pair_size, size(stats_names)]
            return
        case default
            count = -1
            return
        end select
        do i = 1, count
            codes(i) = i - 1 + n0
            select case (kind)
            case ('law')
                names(i) = hertzdamp_law_name(codes(i))
            case ('end')
                names(i) = hertzdamp_end_name(codes(i))
            case ('host')
                names(i) = hertzdamp_host_name(codes(i))
            case ('tangential')
                names(i) = hertzdamp_tangential_name(codes(i))
            case ('lever')
                names(i) = hertzdamp_lever_name(codes(i))
            case ('method')
                names(i) = hertzdamp_method_name(codes(i))
            case ('status')
                names(i) = hertzdamp_status_name(codes(i))
            case default
                names(i) = stats_names(codes(i))
            end select
        end do
    end subroutine registry

    !> A NUL-terminated C string (at most 64 characters) as a Fortran string.
    pure function from_c(s) result(f)
        character(kind=c_char), intent(in) :: s(64)
        character(len=:), allocatable :: f
        integer :: i
        f = ''
        do i = 1, 64
            if (s(i) == c_null_char) exit
            f = f // s(i)
        end do
    end function from_c

    !> `int hertzdamp_c_code(const char *kind, const char *name, int *code)`: the code of `name`
    !> in the registry `kind` (law, end, host, method, tangential, lever, status, stats, size;
    !> see registry), e.g. ("law", "tsuji") -> HERTZDAMP_DAMPING_TSUJI, ("size", "pair") -> the doubles of
    !> hertzdamp_pair_t.  HD_BAD_ARGUMENT (and *code = -1) for an unknown kind or name or NULL.
    integer(c_int) function hertzdamp_c_code(kind, name, code) bind(c, name='hertzdamp_c_code') result(status)
        character(kind=c_char), intent(in), optional :: kind(64)  !! the registry (NUL-terminated)
        character(kind=c_char), intent(in), optional :: name(64)  !! a name of it (NUL-terminated)
        integer(c_int), intent(out), optional :: code            !! its code
        character(len=32) :: names(64)
        integer :: codes(64), count, i
        status = HD_BAD_ARGUMENT
        if (.not. (present(kind) .and. present(name) .and. present(code))) return
        code = -1_c_int
        call registry(from_c(kind), count, names, codes)
        do i = 1, count
            if (trim(names(i)) == from_c(name)) then
                code = int(codes(i), c_int)
                status = HD_OK
                return
            end if
        end do
    end function hertzdamp_c_code

    !> `int hertzdamp_c_names(const char *kind, char *buf, int len)`: the names of the registry
    !> `kind` in the order of their codes, separated by single spaces, NUL-terminated in
    !> buf[len].  HD_BAD_ARGUMENT for an unknown kind, NULL, or a buffer too short (then
    !> buf = "").
    integer(c_int) function hertzdamp_c_names(kind, buf, len) bind(c, name='hertzdamp_c_names') result(status)
        character(kind=c_char), intent(in), optional :: kind(64)  !! the registry (NUL-terminated)
        integer(c_int), value, intent(in) :: len                 !! size of buf
        character(kind=c_char), intent(out), optional :: buf(len) !! the names
        character(len=32) :: names(64)
        character(len=:), allocatable :: text
        integer :: codes(64), count, i
        status = HD_BAD_ARGUMENT
        if (.not. (present(kind) .and. present(buf)) .or. len < 1) return
        buf(1) = c_null_char
        call registry(from_c(kind), count, names, codes)
        if (count < 0) return
        text = ''
        do i = 1, count
            text = text // trim(names(i))
            if (i < count) text = text // ' '
        end do
        if (len_trim(text) + 1 > len) return
        do i = 1, len_trim(text)
            buf(i) = text(i:i)
        end do
        buf(len_trim(text) + 1) = c_null_char
        status = HD_OK
    end function hertzdamp_c_names

    !> Contacts i0 + 1 .. i0 + nc of the strided input x into buf.
    pure subroutine gather(x, s, i0, nc, buf)
        real(c_double), intent(in) :: x(:)
        integer(c_ptrdiff_t), intent(in) :: s, i0
        integer, intent(in) :: nc
        real(c_double), intent(out) :: buf(:)
        integer :: j
        if (s == 0) then
            buf(1:nc) = x(1)
        else
            do j = 1, nc
                buf(j) = x(1 + (i0 + j - 1) * s)
            end do
        end if
    end subroutine gather

    !> The first non-zero status of st (HD_OK when all are).
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

    !> `int hertzdamp_c_invert_array(ptrdiff_t n, const double *e, ptrdiff_t se, const double *tc,
    !> ptrdiff_t stc, const double *m, ptrdiff_t sm, const double *u, ptrdiff_t su, const double
    !> *k_phys, ptrdiff_t skp, const double *steps, ptrdiff_t ss, int law, int end, int host,
    !> double *k, double *d, int *status)`: hertzdamp_c_invert_law for n strided contacts (the
    !> fit).  k_phys NULL: no bound, else each must be finite and positive.  steps NULL: the
    !> continuous constants (as hertzdamp_c_invert_law, bit for bit; host must be
    !> HERTZDAMP_HOST_NONE); else the constants of hertzdamp_c_pair_init(e, law, end, host,
    !> steps) (one init per run of equal e and steps) and hertzdamp_c_pair_kd, a failed init's
    !> status for its contacts.  On failure k = d = 0.
    integer(c_int) function hertzdamp_c_invert_array(n, e, se, tc, stc, m, sm, u, su, k_phys, skp, steps, ss, &
                                                     law, iend, host, k, d, st) &
            bind(c, name='hertzdamp_c_invert_array') result(status)
        integer(c_ptrdiff_t), value, intent(in) :: n                  !! number of contacts
        integer(c_ptrdiff_t), value, intent(in) :: se, stc, sm, su, skp, ss  !! the strides (elements)
        real(c_double), intent(in), optional :: e((n - 1) * se + 1)  !! target restitution coefficients
        real(c_double), intent(in), optional :: tc((n - 1) * stc + 1)  !! target contact times [s]
        real(c_double), intent(in), optional :: m((n - 1) * sm + 1)  !! effective masses [kg]
        real(c_double), intent(in), optional :: u((n - 1) * su + 1)  !! impact velocities [m/s]
        real(c_double), intent(in), optional :: k_phys((n - 1) * skp + 1)  !! physical stiffness bounds, or NULL
        real(c_double), intent(in), optional :: steps((n - 1) * ss + 1)  !! steps per contact N, or NULL
        integer(c_int), value, intent(in) :: law                     !! HERTZDAMP_DAMPING_*
        integer(c_int), value, intent(in) :: iend                    !! HERTZDAMP_END_*
        integer(c_int), value, intent(in) :: host                    !! HERTZDAMP_HOST_* (with steps)
        real(c_double), intent(out), optional :: k(n)                !! Hertz stiffnesses [N m^-3/2]
        real(c_double), intent(out), optional :: d(n)                !! damping coefficients [kg s^-1 m^-q]
        integer(c_int), intent(out), optional :: st(n)               !! status of each contact
        real(c_double), allocatable, target :: w(:, :)
        real(c_double), pointer :: eb(:), tcb(:), mb(:), ub(:), kpb(:), sb(:)
        real(c_double) :: last_e, last_s
        integer, allocatable :: pst(:)
        integer :: last_st, nc, nb, j, ierr, ierr2, ierr3
        type(hertzdamp_pair_t), allocatable :: pb(:)
        type(hertzdamp_pair_t) :: last_pair
        logical :: have_last
        integer(c_ptrdiff_t) :: i0
        status = HD_OK
        if (n <= 0) return
        status = HD_BAD_ARGUMENT
        if (.not. (present(e) .and. present(tc) .and. present(m) .and. present(u) .and. present(k) .and. &
                   present(d) .and. present(st))) return
        if (min(se, stc, sm, su, skp, ss) < 0) return
        status = HD_BAD_STEPS
        if (.not. present(steps) .and. host /= HD_HOST_NONE) return
        if (.not. present(steps) .and. max(se, stc, sm, su) == 1 .and. min(se, stc, sm, su) == 1 .and. &
            (.not. present(k_phys) .or. skp == 1)) then
            ! contiguous: the module's array form over all of them at once (as hertzdamp_c_invert_law_n)
            call invert_contiguous(n, e, tc, m, u, k_phys, law, iend, k, d, st)
            status = first_failure(st(1:n))
            return
        end if
        ! else in blocks of up to 4096 contacts, gathered into buffers
        nb = int(min(n, 4096_c_ptrdiff_t))
        status = HD_BAD_ARGUMENT
        allocate (w(nb, 6), stat=ierr)
        allocate (pst(nb), stat=ierr2)
        allocate (pb(nb), stat=ierr3)
        if (ierr /= 0 .or. ierr2 /= 0 .or. ierr3 /= 0) return
        eb => w(:, 1)
        tcb => w(:, 2)
        mb => w(:, 3)
        ub => w(:, 4)
        kpb => w(:, 5)
        sb => w(:, 6)
        have_last = .false.
        last_e = 0.0_c_double
        last_s = 0.0_c_double
        last_st = HD_OK
        kpb = 0.0_c_double
        do i0 = 0, n - 1, nb
            nc = int(min(int(nb, c_ptrdiff_t), n - i0))
            call gather(e, se, i0, nc, eb)
            call gather(tc, stc, i0, nc, tcb)
            call gather(m, sm, i0, nc, mb)
            call gather(u, su, i0, nc, ub)
            if (present(k_phys)) call gather(k_phys, skp, i0, nc, kpb)
            if (.not. present(steps)) then
                if (present(k_phys)) then
                    call hertzdamp_invert(eb(1:nc), tcb(1:nc), mb(1:nc), ub(1:nc), int(iend), k(i0 + 1:i0 + nc), &
                                          d(i0 + 1:i0 + nc), st(i0 + 1:i0 + nc), k_phys=kpb(1:nc), law=int(law))
                else
                    call hertzdamp_invert(eb(1:nc), tcb(1:nc), mb(1:nc), ub(1:nc), int(iend), k(i0 + 1:i0 + nc), &
                                          d(i0 + 1:i0 + nc), st(i0 + 1:i0 + nc), law=int(law))
                end if
                cycle
            end if
            call gather(steps, ss, i0, nc, sb)
            do j = 1, nc
                ! one init per run of equal (e, steps): a broadcast e and N cost one
                if (.not. (have_last .and. eb(j) == last_e .and. sb(j) == last_s)) then
                    call hertzdamp_pair_init(eb(j), int(law), int(iend), int(host), sb(j), last_pair, last_st)
                    last_e = eb(j)
                    last_s = sb(j)
                    have_last = .true.
                end if
                pb(j) = last_pair
                pst(j) = last_st
            end do
            call pairs_kd(nc, pb, tcb, mb, ub, present(k_phys), kpb, k(i0 + 1:i0 + nc), d(i0 + 1:i0 + nc), &
                          st(i0 + 1:i0 + nc))
            ! a failed init: its status, where the contact's own arguments are valid
            where (st(i0 + 1:i0 + nc) == HD_BAD_PAIR) st(i0 + 1:i0 + nc) = int(pst(1:nc), c_int)
        end do
        status = first_failure(st(1:n))
    end function hertzdamp_c_invert_array

    !> hertzdamp_c_invert_array of contiguous inputs: the module's array form over all n.
    subroutine invert_contiguous(n, e, tc, m, u, k_phys, law, iend, k, d, st)
        integer(c_ptrdiff_t), intent(in) :: n
        real(c_double), intent(in) :: e(n), tc(n), m(n), u(n)
        real(c_double), intent(in), optional :: k_phys(n)
        integer(c_int), intent(in) :: law, iend
        real(c_double), intent(out) :: k(n), d(n)
        integer(c_int), intent(out) :: st(n)
        if (present(k_phys)) then
            call hertzdamp_invert(e(1:n), tc(1:n), m(1:n), u(1:n), int(iend), k(1:n), d(1:n), st(1:n), &
                                  k_phys=k_phys(1:n), law=int(law))
        else
            call hertzdamp_invert(e(1:n), tc(1:n), m(1:n), u(1:n), int(iend), k(1:n), d(1:n), st(1:n), law=int(law))
        end if
    end subroutine invert_contiguous

    !> k and d of nc contacts, each of its own pair (hertzdamp_pair_kd, elemental).
    pure subroutine pairs_kd(nc, pb, tcb, mb, ub, has_kp, kpb, k, d, stb)
        integer, intent(in) :: nc
        type(hertzdamp_pair_t), intent(in) :: pb(:)
        real(c_double), intent(in) :: tcb(:), mb(:), ub(:), kpb(:)
        logical, intent(in) :: has_kp
        real(c_double), intent(out) :: k(:), d(:)
        integer(c_int), intent(out) :: stb(:)
        if (has_kp) then
            call hertzdamp_pair_kd(pb(1:nc), tcb(1:nc), mb(1:nc), ub(1:nc), k(1:nc), d(1:nc), stb(1:nc), k_phys=kpb(1:nc))
        else
            call hertzdamp_pair_kd(pb(1:nc), tcb(1:nc), mb(1:nc), ub(1:nc), k(1:nc), d(1:nc), stb(1:nc))
        end if
    end subroutine pairs_kd

    !> `int hertzdamp_c_pair_kd_array(ptrdiff_t n, const hertzdamp_pair_t *p, const double *tc,
    !> ptrdiff_t stc, const double *m, ptrdiff_t sm, const double *u, ptrdiff_t su, const double
    !> *k_phys, ptrdiff_t skp, double *k, double *d, int *status)`: hertzdamp_c_pair_kd of one
    !> pair for n strided contacts (k_phys NULL: no bound, else each finite and positive).
    integer(c_int) function hertzdamp_c_pair_kd_array(n, p, tc, stc, m, sm, u, su, k_phys, skp, k, d, st) &
            bind(c, name='hertzdamp_c_pair_kd_array') result(status)
        integer(c_ptrdiff_t), value, intent(in) :: n                  !! number of contacts
        integer(c_ptrdiff_t), value, intent(in) :: stc, sm, su, skp  !! the strides (elements)
        type(hertzdamp_pair_t), intent(in), optional :: p             !! the pair (hertzdamp_c_pair_init)
        real(c_double), intent(in), optional :: tc((n - 1) * stc + 1)  !! target contact times N dt [s]
        real(c_double), intent(in), optional :: m((n - 1) * sm + 1)  !! effective masses [kg]
        real(c_double), intent(in), optional :: u((n - 1) * su + 1)  !! impact velocities [m/s]
        real(c_double), intent(in), optional :: k_phys((n - 1) * skp + 1)  !! physical stiffness bounds, or NULL
        real(c_double), intent(out), optional :: k(n)                !! Hertz stiffnesses [N m^-3/2]
        real(c_double), intent(out), optional :: d(n)                !! damping coefficients [kg s^-1 m^-q]
        integer(c_int), intent(out), optional :: st(n)               !! status of each contact
        real(c_double), allocatable :: w(:, :)
        integer :: nc, nb, ierr
        integer(c_ptrdiff_t) :: i0
        status = HD_OK
        if (n <= 0) return
        status = HD_BAD_ARGUMENT
        if (.not. (present(p) .and. present(tc) .and. present(m) .and. present(u) .and. present(k) .and. &
                   present(d) .and. present(st))) return
        if (min(stc, sm, su, skp) < 0) return
        nb = int(min(n, 4096_c_ptrdiff_t))
        allocate (w(nb, 4), stat=ierr)   ! T_c, m, u, k_phys of a block
        if (ierr /= 0) return
        do i0 = 0, n - 1, nb
            nc = int(min(int(nb, c_ptrdiff_t), n - i0))
            call gather(tc, stc, i0, nc, w(:, 1))
            call gather(m, sm, i0, nc, w(:, 2))
            call gather(u, su, i0, nc, w(:, 3))
            if (present(k_phys)) then
                call gather(k_phys, skp, i0, nc, w(:, 4))
                call hertzdamp_pair_kd(p, w(1:nc, 1), w(1:nc, 2), w(1:nc, 3), k(i0 + 1:i0 + nc), d(i0 + 1:i0 + nc), &
                                       st(i0 + 1:i0 + nc), k_phys=w(1:nc, 4))
            else
                call hertzdamp_pair_kd(p, w(1:nc, 1), w(1:nc, 2), w(1:nc, 3), k(i0 + 1:i0 + nc), d(i0 + 1:i0 + nc), &
                                       st(i0 + 1:i0 + nc))
            end if
        end do
        status = first_failure(st(1:n))
    end function hertzdamp_c_pair_kd_array

    !> `int hertzdamp_c_pair_constants(const hertzdamp_pair_t *p, double *alpha, double *tau_c)`:
    !> the alpha and tau_c of a pair's k, d formulas (a host: its alpha_N, tau_N).
    !> HD_BAD_PAIR (and 0) for a pair not set by hertzdamp_c_pair_init; NULL: HD_BAD_ARGUMENT.
    integer(c_int) function hertzdamp_c_pair_constants(p, alpha, tau_c) bind(c, name='hertzdamp_c_pair_constants') &
            result(status)
        type(hertzdamp_pair_t), intent(in), optional :: p   !! the pair
        real(c_double), intent(out), optional :: alpha      !! its damping parameter
        real(c_double), intent(out), optional :: tau_c      !! its dimensionless contact duration
        status = HD_BAD_ARGUMENT
        if (.not. (present(p) .and. present(alpha) .and. present(tau_c))) return
        status = int(hertzdamp_pair_status(p), c_int)
        alpha = merge(p%alpha, 0.0_c_double, status == HD_OK)
        tau_c = merge(p%tau_c, 0.0_c_double, status == HD_OK)
    end function hertzdamp_c_pair_constants

    !> `int hertzdamp_c_forward_array(ptrdiff_t n, const double *k, ptrdiff_t sk, const double *d,
    !> ptrdiff_t sd, const double *m, ptrdiff_t sm, const double *u, ptrdiff_t su, int law, int end,
    !> int method, double tol, int order, double accuracy, double *e, double *tc, int *status)`:
    !> hertzdamp_c_forward_law for n strided contacts by any forward method (the codes of the
    !> "method" registry: fit as hertzdamp_c_forward_law, bit for bit, rk45, series, pade,
    !> compact, first-order).  tol (rk45), order (series), accuracy (series, pade): 0 for the
    !> library's default.  No rebound: e = 0, tc = DBL_MAX, status HERTZDAMP_NO_REBOUND;
    !> other failures e = tc = 0.
    integer(c_int) function hertzdamp_c_forward_array(n, k, sk, d, sd, m, sm, u, su, law, iend, method, tol, order, &
                                                      accuracy, e, tc, st) &
            bind(c, name='hertzdamp_c_forward_array') result(status)
        integer(c_ptrdiff_t), value, intent(in) :: n                  !! number of contacts
        integer(c_ptrdiff_t), value, intent(in) :: sk, sd, sm, su  !! the strides (elements)
        real(c_double), intent(in), optional :: k((n - 1) * sk + 1)  !! Hertz stiffnesses [N m^-3/2]
        real(c_double), intent(in), optional :: d((n - 1) * sd + 1)  !! damping coefficients [kg s^-1 m^-q]
        real(c_double), intent(in), optional :: m((n - 1) * sm + 1)  !! effective masses [kg]
        real(c_double), intent(in), optional :: u((n - 1) * su + 1)  !! impact velocities [m/s]
        integer(c_int), value, intent(in) :: law                     !! HERTZDAMP_DAMPING_*
        integer(c_int), value, intent(in) :: iend                    !! HERTZDAMP_END_*
        integer(c_int), value, intent(in) :: method                  !! a code of the "method" registry
        real(c_double), value, intent(in) :: tol                     !! rk45 tolerance, 0: default
        integer(c_int), value, intent(in) :: order                   !! series order, 0: default
        real(c_double), value, intent(in) :: accuracy                !! series/pade accuracy, 0: default
        real(c_double), intent(out), optional :: e(n)                !! restitution coefficients
        real(c_double), intent(out), optional :: tc(n)               !! contact times [s]
        integer(c_int), intent(out), optional :: st(n)               !! status of each contact
        real(c_double), allocatable :: w(:, :)
        real(c_double) :: tol_, acc_
        integer :: nc, nb, order_, ierr
        integer(c_ptrdiff_t) :: i0
        status = HD_OK
        if (n <= 0) return
        status = HD_BAD_ARGUMENT
        if (.not. (present(k) .and. present(d) .and. present(m) .and. present(u) .and. present(e) .and. &
                   present(tc) .and. present(st))) return
        if (min(sk, sd, sm, su) < 0) return
        nb = int(min(n, 4096_c_ptrdiff_t))
        allocate (w(nb, 6), stat=ierr)   ! k, d, m, u of a block, then alpha and t* (not returned)
        if (ierr /= 0) return
        tol_ = merge(tol, hertzdamp_rk45_default_tol, tol /= 0.0_c_double)
        acc_ = merge(accuracy, hertzdamp_default_accuracy, accuracy /= 0.0_c_double)
        order_ = merge(int(order), hertzdamp_series_default_order, order /= 0)
        do i0 = 0, n - 1, nb
            nc = int(min(int(nb, c_ptrdiff_t), n - i0))
            call gather(k, sk, i0, nc, w(:, 1))
            call gather(d, sd, i0, nc, w(:, 2))
            call gather(m, sm, i0, nc, w(:, 3))
            call gather(u, su, i0, nc, w(:, 4))
            ! without zeta_max, as hertzdamp_c_forward_law (the fit then skips the turning point)
            call hertzdamp_forward_dim(w(1:nc, 1), w(1:nc, 2), w(1:nc, 3), w(1:nc, 4), int(iend), int(method), &
                                       w(1:nc, 5), w(1:nc, 6), e(i0 + 1:i0 + nc), tc(i0 + 1:i0 + nc), status=st(i0 + 1:i0 + nc), &
                                       tol=tol_, order=order_, accuracy=acc_, law=int(law))
            ! the C convention of hertzdamp_c_forward_law: no rebound tc = DBL_MAX
            where (st(i0 + 1:i0 + nc) == HD_NO_REBOUND) tc(i0 + 1:i0 + nc) = huge(1.0_c_double)
        end do
        status = first_failure(st(1:n))
    end function hertzdamp_c_forward_array

    !> `int hertzdamp_c_contact_array(ptrdiff_t n, const double *radius, ptrdiff_t sr, const double
    !> *density, ptrdiff_t srho, const double *youngs, ptrdiff_t sy, const double *poisson,
    !> ptrdiff_t snu, const double *radius2, ptrdiff_t sr2, const double *density2, ptrdiff_t srho2,
    !> const double *youngs2, ptrdiff_t sy2, const double *poisson2, ptrdiff_t snu2, int wall,
    !> double *m_eff, double *r_eff, double *k_phys, double *t_rayleigh, double *dt_rayleigh,
    !> int *status)`: the contact of two spheres (wall = 0) or of a sphere and a wall (wall /= 0:
    !> radius2 and density2 are not read and may be NULL; youngs2, poisson2 are the wall's) from
    !> material data, as the program's contact options compute it: effective mass, effective
    !> radius, k_phys = (4/3) E* sqrt(R*), and, where representable, the shorter Rayleigh time of
    !> the spheres and the time step hertzdamp_rayleigh_fraction of it (else 0; t_rayleigh and
    !> dt_rayleigh may be NULL).  On failure m_eff = r_eff = k_phys = 0.
    integer(c_int) function hertzdamp_c_contact_array(n, r1, sr1, rho1, srho1, y1, sy1, nu1, snu1, r2, sr2, rho2, &
                                                      srho2, y2, sy2, nu2, snu2, wall, m_eff, r_eff, k_phys, &
                                                      t_rayleigh, dt_rayleigh, st) &
            bind(c, name='hertzdamp_c_contact_array') result(status)
        integer(c_ptrdiff_t), value, intent(in) :: n                  !! number of contacts
        integer(c_ptrdiff_t), value, intent(in) :: sr1, srho1, sy1, snu1, sr2, srho2, sy2, snu2  !! the strides
        real(c_double), intent(in), optional :: r1((n - 1) * sr1 + 1)      !! sphere 1: radius [m]
        real(c_double), intent(in), optional :: rho1((n - 1) * srho1 + 1)  !! sphere 1: density [kg m^-3]
        real(c_double), intent(in), optional :: y1((n - 1) * sy1 + 1)      !! sphere 1: Young's modulus [Pa]
        real(c_double), intent(in), optional :: nu1((n - 1) * snu1 + 1)    !! sphere 1: Poisson's ratio
        real(c_double), intent(in), optional :: r2((n - 1) * sr2 + 1)      !! sphere 2: radius [m] (not a wall's)
        real(c_double), intent(in), optional :: rho2((n - 1) * srho2 + 1)  !! sphere 2: density (not a wall's)
        real(c_double), intent(in), optional :: y2((n - 1) * sy2 + 1)      !! sphere 2 or wall: Young's modulus
        real(c_double), intent(in), optional :: nu2((n - 1) * snu2 + 1)    !! sphere 2 or wall: Poisson's ratio
        integer(c_int), value, intent(in) :: wall                    !! body 2 is a wall when /= 0
        real(c_double), intent(out), optional :: m_eff(n)            !! effective masses [kg]
        real(c_double), intent(out), optional :: r_eff(n)            !! effective radii [m]
        real(c_double), intent(out), optional :: k_phys(n)           !! physical stiffnesses [N m^-3/2]
        real(c_double), intent(out), optional :: t_rayleigh(n)       !! Rayleigh times [s] (0: none), or NULL
        real(c_double), intent(out), optional :: dt_rayleigh(n)      !! their time steps [s], or NULL
        integer(c_int), intent(out), optional :: st(n)               !! status of each contact
        real(c_double) :: es, t1, t2
        integer :: s, s1, s2
        integer(c_ptrdiff_t) :: i
        status = HD_OK
        if (n <= 0) return
        status = HD_BAD_ARGUMENT
        if (.not. (present(r1) .and. present(rho1) .and. present(y1) .and. present(nu1) .and. present(y2) .and. &
                   present(nu2) .and. present(m_eff) .and. present(r_eff) .and. present(k_phys) .and. present(st))) return
        if (wall == 0 .and. .not. (present(r2) .and. present(rho2))) return
        if (min(sr1, srho1, sy1, snu1, sr2, srho2, sy2, snu2) < 0) return
        do i = 0, n - 1
            t2 = 0.0_c_double
            s2 = HD_OK
            if (wall == 0) then
                call hertzdamp_pair_contact(r1(1 + i * sr1), rho1(1 + i * srho1), y1(1 + i * sy1), nu1(1 + i * snu1), &
                                            r2(1 + i * sr2), rho2(1 + i * srho2), y2(1 + i * sy2), nu2(1 + i * snu2), &
                                            m_eff(i + 1), r_eff(i + 1), es, k_phys(i + 1), s)
                call hertzdamp_rayleigh_time(r2(1 + i * sr2), rho2(1 + i * srho2), y2(1 + i * sy2), nu2(1 + i * snu2), &
                                             t2, s2)
            else
                call hertzdamp_wall_contact(r1(1 + i * sr1), rho1(1 + i * srho1), y1(1 + i * sy1), nu1(1 + i * snu1), &
                                            y2(1 + i * sy2), nu2(1 + i * snu2), m_eff(i + 1), r_eff(i + 1), es, &
                                            k_phys(i + 1), s)
            end if
            call hertzdamp_rayleigh_time(r1(1 + i * sr1), rho1(1 + i * srho1), y1(1 + i * sy1), nu1(1 + i * snu1), &
                                         t1, s1)
            if (wall /= 0) t2 = t1
            ! the shorter of the spheres' (a wall has none); unknown (0) unless both are known
            if (s /= HD_OK .or. s1 /= HD_OK .or. s2 /= HD_OK) then
                t1 = 0.0_c_double
                t2 = 0.0_c_double
            end if
            if (present(t_rayleigh)) t_rayleigh(i + 1) = min(t1, t2)
            if (present(dt_rayleigh)) dt_rayleigh(i + 1) = hertzdamp_rayleigh_fraction * min(t1, t2)
            st(i + 1) = int(s, c_int)
        end do
        status = first_failure(st(1:n))
    end function hertzdamp_c_contact_array

    !> `int hertzdamp_c_timestep_array(ptrdiff_t n, const double *e, ptrdiff_t se, const double
    !> *steps, ptrdiff_t ss, const double *m, ptrdiff_t sm, const double *k_phys, ptrdiff_t skp,
    !> const double *u, ptrdiff_t su, int law, int end, int host, double *alpha, double *tau_c,
    !> double *tc_damped, double *tc_elastic, int *status)`: the physical contact (k = k_phys, d
    !> from e) as the program's `timestep` computes it, per contact: the constants alpha, tau_c
    !> of e (steps NULL: the continuous ones, hertzdamp_invert_alpha by the fit; else those of
    !> hertzdamp_c_pair_init(e, law, end, host, steps), one init per run of equal e and steps),
    !> the damped contact time t*(k_phys, m, u) tau_c and the elastic Hertz time.  The time
    !> steps are these times / steps.  On failure every result is 0.
    integer(c_int) function hertzdamp_c_timestep_array(n, e, se, steps, ss, m, sm, k_phys, skp, u, su, law, iend, &
                                                       host, alpha, tau_c, tc_damped, tc_elastic, st) &
            bind(c, name='hertzdamp_c_timestep_array') result(status)
        integer(c_ptrdiff_t), value, intent(in) :: n                  !! number of contacts
        integer(c_ptrdiff_t), value, intent(in) :: se, ss, sm, skp, su  !! the strides (elements)
        real(c_double), intent(in), optional :: e((n - 1) * se + 1)  !! restitution coefficients
        real(c_double), intent(in), optional :: steps((n - 1) * ss + 1)  !! steps per contact N, or NULL
        real(c_double), intent(in), optional :: m((n - 1) * sm + 1)  !! effective masses [kg]
        real(c_double), intent(in), optional :: k_phys((n - 1) * skp + 1)  !! physical stiffnesses [N m^-3/2]
        real(c_double), intent(in), optional :: u((n - 1) * su + 1)  !! impact velocities [m/s]
        integer(c_int), value, intent(in) :: law                     !! HERTZDAMP_DAMPING_*
        integer(c_int), value, intent(in) :: iend                    !! HERTZDAMP_END_*
        integer(c_int), value, intent(in) :: host                    !! HERTZDAMP_HOST_* (with steps)
        real(c_double), intent(out), optional :: alpha(n)            !! damping parameters
        real(c_double), intent(out), optional :: tau_c(n)            !! dimensionless contact durations
        real(c_double), intent(out), optional :: tc_damped(n)        !! damped contact times [s]
        real(c_double), intent(out), optional :: tc_elastic(n)       !! elastic Hertz times [s]
        integer(c_int), intent(out), optional :: st(n)               !! status of each contact
        type(hertzdamp_pair_t) :: pair
        real(c_double) :: a, tau, a0, tstar, th, last_e, last_s, sn
        integer :: s, sc
        logical :: have_last
        integer(c_ptrdiff_t) :: i
        status = HD_OK
        if (n <= 0) return
        status = HD_BAD_ARGUMENT
        if (.not. (present(e) .and. present(m) .and. present(k_phys) .and. present(u) .and. present(alpha) .and. &
                   present(tau_c) .and. present(tc_damped) .and. present(tc_elastic) .and. present(st))) return
        if (min(se, ss, sm, skp, su) < 0) return
        status = HD_BAD_STEPS
        if (.not. present(steps) .and. host /= HD_HOST_NONE) return
        have_last = .false.
        last_e = 0.0_c_double
        last_s = 0.0_c_double
        sc = HD_OK
        a = 0.0_c_double
        tau = 0.0_c_double
        do i = 0, n - 1
            ! the constants of (e, N), once per run of equal values
            sn = 0.0_c_double
            if (present(steps)) sn = steps(1 + i * ss)
            if (.not. (have_last .and. e(1 + i * se) == last_e .and. sn == last_s)) then
                last_e = e(1 + i * se)
                last_s = sn
                if (present(steps)) then
                    call hertzdamp_pair_init(last_e, int(law), int(iend), int(host), last_s, pair, sc)
                    a = pair%alpha
                    tau = pair%tau_c
                else
                    call hertzdamp_invert_alpha(last_e, int(iend), a, tau, sc, HD_METHOD_FIT, law=int(law))
                end if
                have_last = .true.
            end if
            ! the contact: its time unit with k_phys (d = 0), the elastic time, then the constants'
            call hertzdamp_reduce(k_phys(1 + i * skp), 0.0_c_double, m(1 + i * sm), u(1 + i * su), a0, tstar, s)
            th = 0.0_c_double
            if (s == HD_OK) call hertzdamp_hertz_time(m(1 + i * sm), k_phys(1 + i * skp), u(1 + i * su), th, s)
            if (s == HD_OK) s = sc
            alpha(i + 1) = a
            tau_c(i + 1) = tau
            tc_damped(i + 1) = tstar * tau
            tc_elastic(i + 1) = th
            if (s == HD_OK .and. .not. (tc_damped(i + 1) > 0.0_c_double .and. tc_damped(i + 1) <= huge(1.0_c_double))) then
                s = HD_OUT_OF_RANGE
            end if
            if (s /= HD_OK) then
                alpha(i + 1) = 0.0_c_double
                tau_c(i + 1) = 0.0_c_double
                tc_damped(i + 1) = 0.0_c_double
                tc_elastic(i + 1) = 0.0_c_double
            end if
            st(i + 1) = int(s, c_int)
        end do
        status = first_failure(st(1:n))
    end function hertzdamp_c_timestep_array
    ! END python block

end module hertzdamp_capi
