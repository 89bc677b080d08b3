!> The command `bench`: the work-precision report of the library's methods.
!>
!> Forward problem alpha -> (e, tau_c): every method against rk45 at tol 1e-15.
!> Inverse problem (e, T_c, m, u_in) -> (k, d): every method against the iterative
!> inverse at tol 1e-14, including the iterative baselines (the library's secant over
!> rk45 and the GSL peer's secant over rk8pd, each at tolerances matched to the
!> accuracy asked).  Entry points: the fit inverse through every way a user calls it
!> (module scalar and array calls, C functions through their bind(C) names, legacy
!> externals), side by side over the same 10^6 contacts, with their ratios to the
!> module scalar call, a check that they agree bit for bit, and the speed-up against
!> the fastest iterative row at equal accuracy.  Every number is measured in this run;
!> methods the library does not (yet) provide are left out.  Everything is computed
!> (and the plot written) before anything is printed: on failure stdout stays empty.
module hertzdamp_cmd_bench
    use hertzdamp, only: hertzdamp_rk, hertzdamp_collision, hertzdamp_forward_alpha, hertzdamp_message, &
                         HD_OK, HD_NO_REBOUND, HD_NOT_SUPPORTED, HD_NO_CONVERGENCE, HD_END_OVERLAP, HD_END_FORCE, &
                         HD_METHOD_RK45, HD_METHOD_SERIES, HD_METHOD_PADE, HD_METHOD_COMPACT, HD_METHOD_FIT, &
                         HD_METHOD_ITERATIVE
    use hertzdamp_inverse, only: hertzdamp_invert
    use hertzdamp_gsl, only: hertzdamp_gsl_collide, HERTZDAMP_GSL_RKF45, HERTZDAMP_GSL_RK8PD
    use hertzdamp_gsl_secant, only: hertzdamp_gsl_secant_invert
    use hertzdamp_capi, only: hertzdamp_c_invert, hertzdamp_c_invert_n
    use hertzdamp_bench_legacy, only: legacy_invert_each, legacy_invert_all
    use hertzdamp_cli_plot, only: plot_check_target, plot_run, plot_temp_name, gp_string
    use hertzdamp_bench_timer, only: bench_case, bench_measure, bench_measure_all, bench_slot, wall_seconds, median
    use hertzdamp_cli, only: cli_args, cli_buffer, parse_args, parse_choice, fail, quit, pad, EXIT_USAGE, EXIT_OK, &
                             EXIT_FAILURE
    use hertzdamp_cli_output, only: out_table, format_choices, FORMAT_TEXT, FORMAT_CSV, FORMAT_JSON
    use hertzdamp_cli_help, only: print_help, wants_help
    use, intrinsic :: iso_fortran_env, only: int64, error_unit
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan, ieee_is_finite
    implicit none
    private
    public :: cmd_bench

    integer, parameter :: wp = hertzdamp_rk

    !> How a forward case computes: through hertzdamp_forward_alpha or GSL.
    integer, parameter :: ENGINE_LIB = 1, ENGINE_GSL = 2

    !> Plot families (marker styles), in legend order.
    integer, parameter :: n_families = 9
    character(len=*), parameter :: fam(n_families) = [character(len=10) :: 'rk45', 'gsl-rkf45', 'gsl-rk8pd', &
                                                      'series', 'pade', 'compact', 'fit', 'iterative', 'gsl-secant']

    !> Floor of the e error denominator: errors of e are relative to max(e, e_floor).
    real(wp), parameter :: e_floor = 1.0e-3_wp
    !> Errors below this are drawn at this value (log axis).
    real(wp), parameter :: plot_floor = 1.0e-17_wp

    ! Inverse problem: fixed contact (SI units).
    real(wp), parameter :: inv_m = 1.0e-2_wp, inv_u = 1.0_wp, inv_tc = 1.0e-4_wp
    !> Tolerance of the iterative inverse that serves as the reference of the inverse rows.
    real(wp), parameter :: inv_ref_tol = 1.0e-14_wp
    character(len=*), parameter :: inv_ref_text = 'iterative at tol 1e-14'

    !> One forward sweep over a set of alpha.
    type, extends(bench_case) :: fwd_case
        integer :: engine = ENGINE_LIB
        integer :: method = HD_METHOD_RK45   !! HD_METHOD_* (ENGINE_LIB) or HERTZDAMP_GSL_* (ENGINE_GSL)
        real(wp) :: tol = 1.0e-13_wp
        integer :: order = -1                !! series order (< 0: not passed)
        real(wp), allocatable :: alpha(:)
        integer, allocatable :: iend(:)
        real(wp), allocatable :: e(:), tau(:)
        integer, allocatable :: status(:), steps(:), rejected(:), rhs(:)
    contains
        procedure :: run => fwd_run
    end type fwd_case

    !> One inverse sweep over a set of e (fixed m, u_in, T_c).
    type, extends(bench_case) :: inv_case
        integer :: method = HD_METHOD_FIT
        real(wp) :: tol = 1.0e-10_wp
        real(wp), allocatable :: e(:), tc(:), m(:), u(:)
        real(wp), allocatable :: k(:), d(:), alpha(:), tstar(:), tau(:)
        integer, allocatable :: status(:)
        logical, allocatable :: bound(:)
    contains
        procedure :: run => inv_run
    end type inv_case

    !> The iterative inverse of the GSL peer (secant over rk8pd) over a set of e; k and d
    !> by the direct formulas from its alpha and tau_c.
    type, extends(bench_case) :: gsl_inv_case
        real(wp) :: tol = 1.0e-10_wp
        real(wp), allocatable :: e(:), tc(:), m(:), u(:)
        real(wp), allocatable :: k(:), d(:), alpha(:), tau(:)
        integer, allocatable :: status(:), solves(:), rhs(:)
    contains
        procedure :: run => gsl_inv_run
    end type gsl_inv_case

    !> The contacts of the entry-point rows (shared by every way of calling).
    type :: entry_data
        real(wp), allocatable :: e(:), tc(:), m(:), u(:)
    end type entry_data

    !> One way of calling the fit inverse over all contacts of an entry_data.
    type, extends(bench_case) :: entry_case
        integer :: way = 1                       !! one of the WAY_* below
        type(entry_data), pointer :: in => null()
        real(wp), allocatable :: k(:), d(:)
        integer(c_int), allocatable :: status(:)
    contains
        procedure :: run => entry_run
    end type entry_case

    !> The entry points, in the order of the rows.
    integer, parameter :: n_ways = 6
    integer, parameter :: WAY_SCALAR = 1, WAY_ARRAY = 2, WAY_C = 3, WAY_C_N = 4, WAY_LEGACY = 5, WAY_LEGACY_N = 6
    character(len=*), parameter :: way_name(n_ways) = [character(len=13) :: 'module-scalar', 'module-array', &
                                                       'c', 'c-array', 'legacy', 'legacy-n']
    character(len=*), parameter :: way_label(n_ways) = [character(len=46) :: &
        'module hertzdamp_invert, one contact per call', 'module hertzdamp_invert on rank-1 arrays', &
        'C hertzdamp_c_invert, one contact per call', 'C hertzdamp_c_invert_n', &
        'legacy HERTZDAMP_INVERT, one contact per call', 'legacy HERTZDAMP_INVERT_N']

    !> What the entry-point rows found.
    type :: entry_result
        integer :: n = 0                   !! contacts
        real(wp) :: ns(n_ways) = -1.0_wp   !! ns per contact of each way
        integer :: mismatches(n_ways) = 0  !! contacts whose k, d or status differ from the module scalar call
        integer :: failed = 0              !! contacts whose status is not ok
    end type entry_result


    !> One result row.
    type :: bench_row
        character(len=:), allocatable :: problem, method, setting
        integer :: family = 0
        integer :: npts = 0, ntot = 0
        real(wp) :: err(5) = -1.0_wp   !! e, tau, alpha, k, d; < 0: not applicable
        real(wp) :: ns = -1.0_wp
        real(wp) :: steps = -1.0_wp, rejected = -1.0_wp, rhs = -1.0_wp  !! means per collision; < 0: n/a
    end type bench_row


contains

    ! ------------------------------------------------------------------ the cases

    subroutine fwd_run(self)
        class(fwd_case), intent(inout) :: self
        type(hertzdamp_collision) :: r
        integer :: i, nrhs, nst
        real(wp) :: zm, tm
        do i = 1, size(self%alpha)
            select case (self%engine)
            case (ENGINE_LIB)
                if (self%order >= 0) then
                    r = hertzdamp_forward_alpha(self%alpha(i), self%iend(i), self%method, self%tol, self%order)
                else
                    r = hertzdamp_forward_alpha(self%alpha(i), self%iend(i), self%method, self%tol)
                end if
                self%e(i) = r%e
                self%tau(i) = r%tau_c
                self%status(i) = r%status
                self%steps(i) = r%stats%steps
                self%rejected(i) = r%stats%rejected
                self%rhs(i) = r%stats%rhs_evals
            case default
                call hertzdamp_gsl_collide(self%alpha(i), self%iend(i), self%tol, self%method, self%e(i), &
                                           self%tau(i), zm, tm, self%status(i), nrhs, nst, atol=1.0e-30_wp * self%tol)
                self%steps(i) = nst
                self%rejected(i) = -1
                self%rhs(i) = nrhs
            end select
        end do
    end subroutine fwd_run

    subroutine inv_run(self)
        class(inv_case), intent(inout) :: self
        integer :: i
        do i = 1, size(self%e)
            call hertzdamp_invert(self%e(i), self%tc(i), self%m(i), self%u(i), HD_END_OVERLAP, self%k(i), self%d(i), &
                                  self%status(i), alpha=self%alpha(i), tstar=self%tstar(i), tau_c=self%tau(i), &
                                  bound_active=self%bound(i), method=self%method, tol=self%tol)
        end do
    end subroutine inv_run

    subroutine gsl_inv_run(self)
        class(gsl_inv_case), intent(inout) :: self
        integer :: i
        real(wp) :: r
        do i = 1, size(self%e)
            call hertzdamp_gsl_secant_invert(self%e(i), HD_END_OVERLAP, self%tol, self%alpha(i), self%tau(i), &
                                             self%status(i), self%solves(i), self%rhs(i))
            ! the direct formulas of the library (r = tau_c / T_c = 1/t*)
            r = self%tau(i) * (1.0_wp / self%tc(i))
            self%k(i) = self%m(i) * (r * r) * sqrt(self%tau(i) * (1.0_wp / (self%tc(i) * self%u(i))))
            self%d(i) = self%alpha(i) * self%m(i) * r
        end do
    end subroutine gsl_inv_run

    !> Every contact once through one entry point (overlap end).
    subroutine entry_run(self)
        class(entry_case), intent(inout) :: self
        integer :: i, n
        integer(c_int) :: st
        n = size(self%in%e)
        select case (self%way)
        case (WAY_SCALAR)
            do i = 1, n
                call hertzdamp_invert(self%in%e(i), self%in%tc(i), self%in%m(i), self%in%u(i), HD_END_OVERLAP, &
                                      self%k(i), self%d(i), self%status(i))
            end do
        case (WAY_ARRAY)
            call hertzdamp_invert(self%in%e, self%in%tc, self%in%m, self%in%u, HD_END_OVERLAP, self%k, self%d, &
                                  self%status)
        case (WAY_C)
            do i = 1, n
                self%status(i) = hertzdamp_c_invert(self%in%e(i), self%in%tc(i), self%in%m(i), self%in%u(i), &
                                                    int(HD_END_OVERLAP, c_int), self%k(i), self%d(i))
            end do
        case (WAY_C_N)
            st = hertzdamp_c_invert_n(int(n, c_int), self%in%e, self%in%tc, self%in%m, self%in%u, &
                                      int(HD_END_OVERLAP, c_int), self%k, self%d, self%status)
        case (WAY_LEGACY)
            ! HERTZDAMP_INVERT once per contact, declared by include/hertzdamp.fi
            call legacy_invert_each(int(n, c_int), self%in%e, self%in%tc, self%in%m, self%in%u, &
                                    int(HD_END_OVERLAP, c_int), self%k, self%d, self%status)
        case default
            call legacy_invert_all(int(n, c_int), self%in%e, self%in%tc, self%in%m, self%in%u, &
                                   int(HD_END_OVERLAP, c_int), self%k, self%d, self%status)
        end select
    end subroutine entry_run

    subroutine fwd_init(c, engine, method, tol, order, alpha, iend)
        type(fwd_case), intent(out) :: c
        integer, intent(in) :: engine, method, order
        real(wp), intent(in) :: tol, alpha(:)
        integer, intent(in) :: iend(:)
        integer :: n
        n = size(alpha)
        c%engine = engine
        c%method = method
        c%tol = tol
        c%order = order
        c%alpha = alpha
        c%iend = iend
        allocate (c%e(n), c%tau(n), c%status(n), c%steps(n), c%rejected(n), c%rhs(n))
        c%e = 0.0_wp
        c%tau = 0.0_wp
        c%status = HD_OK
        c%steps = 0
        c%rejected = 0
        c%rhs = 0
    end subroutine fwd_init

    subroutine inv_init(c, method, tol, e, tc, m, u)
        type(inv_case), intent(out) :: c
        integer, intent(in) :: method
        real(wp), intent(in) :: tol, e(:), tc(:), m(:), u(:)
        integer :: n
        n = size(e)
        c%method = method
        c%tol = tol
        c%e = e
        c%tc = tc
        c%m = m
        c%u = u
        allocate (c%k(n), c%d(n), c%alpha(n), c%tstar(n), c%tau(n), c%status(n), c%bound(n))
        c%k = 0.0_wp
        c%d = 0.0_wp
        c%alpha = 0.0_wp
        c%tstar = 0.0_wp
        c%tau = 0.0_wp
        c%status = HD_OK
        c%bound = .false.
    end subroutine inv_init

    ! ------------------------------------------------------------------ the command

    subroutine cmd_bench()
        type(cli_args) :: args
        integer :: fmt
        logical :: quick, want_plot
        character(len=:), allocatable :: plot_file, terminal
        real(wp) :: min_time, t_start
        integer :: repeats
        real(wp), allocatable :: alpha(:), e_inv(:)
        integer, allocatable :: iend(:)
        type(fwd_case) :: fref
        type(inv_case) :: iref
        type(bench_row), allocatable :: rows(:)
        type(entry_result) :: ent
        integer :: i, n_ov, n_fo
        type(cli_buffer) :: buf
        type(out_table) :: t
        type(cli_buffer) :: figs

        plot_file = ''
        terminal = ''
        if (wants_help()) then
            call print_help('bench')
            call quit(EXIT_OK)
        end if
        call parse_args(2, '--format --plot', '--quick', args)
        fmt = parse_choice(args%get('--format', 'text'), format_choices, 'format (--format)')
        quick = args%has('--quick')
        want_plot = args%has('--plot')
        terminal = ''
        if (want_plot) then
            plot_file = args%get('--plot', '')
            call plot_check_target(plot_file, terminal)
        end if
        t_start = wall_seconds()

        if (quick) then
            min_time = 0.01_wp
            repeats = 3
            alpha = [0.0_wp, 0.2_wp, 0.4_wp, 0.6_wp, 0.8_wp, 1.0_wp, 1.1_wp]
            n_ov = size(alpha)
            alpha = [alpha, 0.0_wp, 0.5_wp, 2.0_wp, 10.0_wp, 50.0_wp]
            e_inv = [1.0e-3_wp, 1.0e-2_wp, 0.1_wp, 0.5_wp, 0.9_wp, 0.99_wp]
        else
            min_time = 0.1_wp
            repeats = 5
            alpha = [(0.05_wp * i, i=0, 22)]
            n_ov = size(alpha)
            alpha = [alpha, 0.0_wp, 0.1_wp, 0.2_wp, 0.5_wp, 1.0_wp, 2.0_wp, 5.0_wp, 10.0_wp, 20.0_wp, 50.0_wp]
            e_inv = [1.0e-3_wp, 2.0e-3_wp, 5.0e-3_wp, 1.0e-2_wp, 2.0e-2_wp, 5.0e-2_wp, 0.1_wp, 0.2_wp, 0.3_wp, &
                     0.4_wp, 0.5_wp, 0.6_wp, 0.7_wp, 0.8_wp, 0.9_wp, 0.95_wp, 0.99_wp, 0.999_wp]
        end if
        n_fo = size(alpha) - n_ov
        allocate (iend(size(alpha)))
        iend(1:n_ov) = HD_END_OVERLAP
        iend(n_ov + 1:) = HD_END_FORCE

        ! References, computed once.
        call fwd_init(fref, ENGINE_LIB, HD_METHOD_RK45, 1.0e-15_wp, -1, alpha, iend)
        call fref%run()
        do i = 1, size(alpha)
            if (fref%status(i) /= HD_OK) call fail(EXIT_FAILURE, 'forward reference (rk45, tol 1e-15) failed: ' // &
                                                   hertzdamp_message(fref%status(i)))
        end do
        call inv_init(iref, HD_METHOD_ITERATIVE, inv_ref_tol, e_inv, spread(inv_tc, 1, size(e_inv)), &
                      spread(inv_m, 1, size(e_inv)), spread(inv_u, 1, size(e_inv)))
        call iref%run()
        do i = 1, size(e_inv)
            if (iref%status(i) /= HD_OK) call fail(EXIT_FAILURE, 'inverse reference (' // inv_ref_text // ') failed: ' &
                                                   // hertzdamp_message(iref%status(i)))
        end do

        allocate (rows(0))
        call forward_rows(alpha, iend, n_ov, fref, min_time, repeats, rows)
        call inverse_rows(iref, min_time, repeats, rows)
        call entry_rows(quick, min_time, repeats, rows, ent)
        call figures(rows, ent, figs)

        ! Render.
        call build_table(rows, fmt, t)
        if (fmt /= FORMAT_CSV) then
            call t%meta('bench', 'work-precision of hertzdamp: forward alpha -> (e, tau_c), inverse (e, T_c, m, ' // &
                        'u_in) -> (k, d); every number measured in this run')
            if (quick) then
                call t%meta('mode', 'quick: fewer alpha and e, each time the median of 3 batches of >= 0.01 s wall ' // &
                            'clock (full run: 5 batches of >= 0.1 s)')
            else
                call t%meta('mode', 'full: each time the median of 5 batches of >= 0.1 s wall clock (system_clock)')
            end if
            call t%meta('forward', itoa(n_ov) // ' alpha in [0, 1.1] (overlap) and ' // itoa(n_fo) // &
                        ' alpha in [0, 50] (force); reference rk45 at tol 1e-15; error of e relative to max(e, 1e-3)' &
                        // '; series and pade on the overlap alpha only')
            call t%meta('inverse', itoa(size(e_inv)) // ' e in [1e-3, 0.999] (overlap), m = 1e-2 kg, u_in = 1 m/s, ' // &
                        'T_c = 1e-4 s; reference ' // inv_ref_text // '; iterative = secant over rk45, gsl-secant = ' // &
                        'secant over GSL rk8pd, each solve at tol/10 min(1, |ln e|), setting = accuracy asked of alpha')
            call t%meta('entry', itoa(ent%n) // ' contacts (overlap), e uniform in [0.05, 0.99], m in [1e-9, 1] kg, ' // &
                        'u_in in [1e-3, 10] m/s, T_c in [1e-7, 1e-3] s (log-uniform); every entry point timed side by ' // &
                        'side (rounds of one batch each); ns_per_call = per contact')
            call t%meta('entry points', entry_legend())
            call t%meta('tolerances', 'rk45 and GSL (rkf45, rk8pd) with relative error control: absolute ' // &
                        'tolerance 1e-30 tol; rhs_evals, steps, rejected are means per collision (GSL: rejected n/a)')
            call t%meta('omitted', 'methods that report not-supported, and points whose status is not ok ' // &
                        '(column points = used/total)')
            do i = 1, figs%n
                call t%meta('figure' // itoa(i), figs%lines(i)%s)
            end do
        end if
        if (fmt == FORMAT_TEXT) then
            call render_text(t, figs%n, rows, buf)
            do i = 1, figs%n
                call buf%add('figure: ' // figs%lines(i)%s)
            end do
            call buf%add('# total bench time ' // ftoa(wall_seconds() - t_start, '(f0.1)') // ' s')
        else
            call t%render(fmt, buf)
        end if

        if (want_plot) call make_plot(rows, plot_file, terminal, quick)
        call buf%flush_to_stdout()
        call quit(EXIT_OK)
    end subroutine cmd_bench

    ! ------------------------------------------------------------------ forward

    subroutine forward_rows(alpha, iend, n_ov, fref, min_time, repeats, rows)
        real(wp), intent(in) :: alpha(:)
        integer, intent(in) :: iend(:), n_ov
        type(fwd_case), intent(in) :: fref
        real(wp), intent(in) :: min_time
        integer, intent(in) :: repeats
        type(bench_row), allocatable, intent(inout) :: rows(:)
        real(wp), parameter :: tols(5) = [1.0e-4_wp, 1.0e-6_wp, 1.0e-8_wp, 1.0e-10_wp, 1.0e-12_wp]
        character(len=*), parameter :: tol_names(5) = ['1e-4 ', '1e-6 ', '1e-8 ', '1e-10', '1e-12']
        integer, parameter :: orders(6) = [1, 2, 3, 5, 10, 20]
        integer :: j, n
        n = size(alpha)
        do j = 1, size(tols)
            call one(ENGINE_LIB, HD_METHOD_RK45, tols(j), -1, 'rk45', trim(tol_names(j)), 1, n)
        end do
        do j = 1, size(orders)
            call one(ENGINE_LIB, HD_METHOD_SERIES, 0.0_wp, orders(j), 'series', 'N=' // itoa(orders(j)), 4, n_ov)
        end do
        call one(ENGINE_LIB, HD_METHOD_PADE, 0.0_wp, -1, 'pade', '', 5, n_ov)
        call one(ENGINE_LIB, HD_METHOD_COMPACT, 0.0_wp, -1, 'compact', '', 6, n)
        call one(ENGINE_LIB, HD_METHOD_FIT, 0.0_wp, -1, 'fit', '', 7, n)
        do j = 1, size(tols)
            call one(ENGINE_GSL, HERTZDAMP_GSL_RKF45, tols(j), -1, 'gsl-rkf45', trim(tol_names(j)), 2, n)
        end do
        do j = 1, size(tols)
            call one(ENGINE_GSL, HERTZDAMP_GSL_RK8PD, tols(j), -1, 'gsl-rk8pd', trim(tol_names(j)), 3, n)
        end do
    contains
        !> One row: a first (untimed) sweep decides which points are used.
        subroutine one(engine, method, tol, order, name, setting, family, npts)
            integer, intent(in) :: engine, method, order, family, npts
            real(wp), intent(in) :: tol
            character(len=*), intent(in) :: name, setting
            type(fwd_case) :: c
            type(bench_row) :: r
            integer, allocatable :: idx(:)
            integer :: i
            real(wp) :: tol_
            tol_ = tol
            if (tol_ <= 0.0_wp) tol_ = 1.0e-13_wp
            call fwd_init(c, engine, method, tol_, order, alpha(1:npts), iend(1:npts))
            call c%run()
            idx = pack([(i, i=1, npts)], c%status == HD_OK)
            if (size(idx) == 0) return
            if (size(idx) < npts) call fwd_init(c, engine, method, tol_, order, alpha(idx), iend(idx))
            r%problem = 'forward'
            r%method = name
            r%setting = setting
            r%family = family
            r%npts = size(idx)
            r%ntot = npts
            r%ns = 1.0e9_wp * bench_measure(c, min_time, repeats) / size(idx)
            if (any(c%status /= HD_OK)) return   ! not reproducible: leave the method out
            r%err(1) = maxval(abs(c%e - fref%e(idx)) / max(fref%e(idx), e_floor))
            r%err(2) = maxval(abs(c%tau - fref%tau(idx)) / abs(fref%tau(idx)))
            if (engine == ENGINE_GSL .or. method == HD_METHOD_RK45) then
                r%steps = sum(real(c%steps, wp)) / size(idx)
                r%rhs = sum(real(c%rhs, wp)) / size(idx)
                if (engine == ENGINE_LIB) r%rejected = sum(real(c%rejected, wp)) / size(idx)
            end if
            rows = [rows, r]
        end subroutine one
    end subroutine forward_rows

    ! ------------------------------------------------------------------ inverse

    subroutine inverse_rows(iref, min_time, repeats, rows)
        type(inv_case), intent(in) :: iref
        real(wp), intent(in) :: min_time
        integer, intent(in) :: repeats
        type(bench_row), allocatable, intent(inout) :: rows(:)
        integer :: j
        real(wp), parameter :: tols(5) = [1.0e-6_wp, 1.0e-8_wp, 1.0e-10_wp, 1.0e-11_wp, 1.0e-12_wp]
        character(len=*), parameter :: tol_names(5) = ['1e-6 ', '1e-8 ', '1e-10', '1e-11', '1e-12']
        call one(HD_METHOD_FIT, 0.0_wp, 'fit', '', 7)
        call one(HD_METHOD_COMPACT, 0.0_wp, 'compact', '', 6)
        call one(HD_METHOD_SERIES, 0.0_wp, 'series', '', 4)
        call one(HD_METHOD_PADE, 0.0_wp, 'pade', '', 5)
        do j = 1, size(tols)
            call one(HD_METHOD_ITERATIVE, tols(j), 'iterative', trim(tol_names(j)), 8)
        end do
        do j = 1, size(tols)
            call one_gsl(tols(j), trim(tol_names(j)))
        end do
    contains
        !> The GSL peer's iterative inverse at accuracy tol (every point must succeed).
        subroutine one_gsl(tol, setting)
            real(wp), intent(in) :: tol
            character(len=*), intent(in) :: setting
            type(gsl_inv_case) :: c
            type(bench_row) :: r
            integer :: n
            n = size(iref%e)
            c%tol = tol
            c%e = iref%e
            c%tc = iref%tc
            c%m = iref%m
            c%u = iref%u
            allocate (c%k(n), c%d(n), c%alpha(n), c%tau(n), c%status(n), c%solves(n), c%rhs(n))
            call c%run()
            if (any(c%status /= HD_OK)) return
            r%problem = 'inverse'
            r%method = 'gsl-secant'
            r%setting = setting
            r%family = 9
            r%npts = n
            r%ntot = n
            r%ns = 1.0e9_wp * bench_measure(c, min_time, repeats) / n
            r%err(3) = maxval(rel(c%alpha, iref%alpha))
            r%err(4) = maxval(rel(c%k, iref%k))
            r%err(5) = maxval(rel(c%d, iref%d))
            r%steps = sum(real(c%solves, wp)) / n      ! solves per inverse
            r%rhs = sum(real(c%rhs, wp)) / n
            rows = [rows, r]
        end subroutine one_gsl

        subroutine one(method, tol, name, setting, family)
            integer, intent(in) :: method, family
            real(wp), intent(in) :: tol
            character(len=*), intent(in) :: name, setting
            type(inv_case) :: c
            type(bench_row) :: r
            integer, allocatable :: idx(:)
            integer :: i, n
            real(wp) :: tol_
            n = size(iref%e)
            tol_ = tol
            if (tol_ <= 0.0_wp) tol_ = 1.0e-10_wp
            call inv_init(c, method, tol_, iref%e, iref%tc, iref%m, iref%u)
            call c%run()
            idx = pack([(i, i=1, n)], c%status == HD_OK)
            if (size(idx) == 0) return
            if (size(idx) < n) call inv_init(c, method, tol_, iref%e(idx), iref%tc(idx), iref%m(idx), iref%u(idx))
            r%problem = 'inverse'
            r%method = name
            r%setting = setting
            r%family = family
            r%npts = size(idx)
            r%ntot = n
            r%ns = 1.0e9_wp * bench_measure(c, min_time, repeats) / size(idx)
            if (any(c%status /= HD_OK)) return
            r%err(3) = maxval(rel(c%alpha, iref%alpha(idx)))
            r%err(4) = maxval(rel(c%k, iref%k(idx)))
            r%err(5) = maxval(rel(c%d, iref%d(idx)))
            rows = [rows, r]
        end subroutine one
    end subroutine inverse_rows

    pure elemental real(wp) function rel(got, want)
        real(wp), intent(in) :: got, want
        rel = abs(got - want) / max(abs(want), tiny(1.0_wp))
    end function rel

    ! ------------------------------------------------------------------ entry points

    !> The fit inverse through every entry point over the same contacts, timed side by
    !> side; then every way's results against the module scalar call, bit for bit.
    subroutine entry_rows(quick, min_time, repeats, rows, res)
        logical, intent(in) :: quick
        real(wp), intent(in) :: min_time
        integer, intent(in) :: repeats
        type(bench_row), allocatable, intent(inout) :: rows(:)
        type(entry_result), intent(out) :: res
        type(entry_data), target :: dat
        type(bench_slot) :: slots(n_ways)
        real(wp) :: t(n_ways)
        integer(int64) :: seed
        integer :: w, n
        type(bench_row) :: r
        n = merge(100000, 1000000, quick)
        seed = 20261122_int64
        allocate (dat%e(n), dat%m(n), dat%u(n), dat%tc(n))
        dat%e(:) = 0.05_wp + 0.94_wp * lcg_uniform(seed, n)
        dat%m(:) = 10.0_wp**(-9.0_wp + 9.0_wp * lcg_uniform(seed, n))
        dat%u(:) = 10.0_wp**(-3.0_wp + 4.0_wp * lcg_uniform(seed, n))
        dat%tc(:) = 10.0_wp**(-7.0_wp + 4.0_wp * lcg_uniform(seed, n))
        do w = 1, n_ways
            allocate (slots(w)%c, source=entry_case(way=w, in=dat))
            select type (c => slots(w)%c)
            type is (entry_case)
                allocate (c%k(n), c%d(n), c%status(n))
                call c%run()
            end select
        end do
        t = bench_measure_all(slots, min_time, repeats)
        res%n = n
        res%ns = 1.0e9_wp * t / n
        select type (c1 => slots(1)%c)
        type is (entry_case)
            res%failed = count(c1%status /= HD_OK)
            do w = 1, n_ways
                select type (c => slots(w)%c)
                type is (entry_case)
                    res%mismatches(w) = count(transfer(c%k, 0_int64, n) /= transfer(c1%k, 0_int64, n) .or. &
                                              transfer(c%d, 0_int64, n) /= transfer(c1%d, 0_int64, n) .or. &
                                              c%status /= c1%status)
                end select
            end do
        end select
        do w = 1, n_ways
            r = bench_row('entry', trim(way_name(w)), 'n=' // itoa(n), 7, n - res%failed, n, ns=res%ns(w))
            rows = [rows, r]
        end do
    end subroutine entry_rows

    !> n uniform numbers in (0, 1) from the Park-Miller generator (reproducible everywhere).
    function lcg_uniform(seed, n) result(x)
        integer(int64), intent(inout) :: seed
        integer, intent(in) :: n
        real(wp) :: x(n)
        integer :: i
        integer(int64), parameter :: a = 16807_int64, modulus = 2147483647_int64
        do i = 1, n
            seed = mod(a * seed, modulus)
            x(i) = real(seed, wp) / real(modulus, wp)
        end do
    end function lcg_uniform


    ! ------------------------------------------------------------------ figures

    !> The 'figure' lines: ratios measured side by side in this run.
    subroutine figures(rows, ent, figs)
        type(bench_row), intent(in) :: rows(:)
        type(entry_result), intent(in) :: ent
        type(cli_buffer), intent(out) :: figs
        integer :: i_fit, i_eq, i_10, w, j
        real(wp) :: targets(2), t_rk, t_f, t_8, acc_fit, worst_c, ns_arr
        character(len=*), parameter :: target_names(2) = ['1e-8 ', '1e-10']
        character(len=:), allocatable :: q_rk, q_f, q_8, line
        ! ---- entry points
        if (ent%n > 0) then
            line = 'entry points over ' // itoa(ent%n) // ' contacts, ns per contact (ratio to the module scalar call):'
            do w = 1, n_ways
                line = line // ' ' // trim(way_name(w)) // ' ' // ftoa(ent%ns(w), '(f6.1)') // ' (' // &
                       fratio(ent%ns(w) / ent%ns(WAY_SCALAR)) // ')' // trim(merge(',', ' ', w < n_ways))
            end do
            call figs%add(line)
            if (all(ent%mismatches == 0)) then
                call figs%add('entry points: k, d and status bit-identical to the module scalar call for every ' // &
                              'contact and every entry point (' // itoa(ent%failed) // ' contacts not ok)')
            else
                line = 'entry points: NOT bit-identical to the module scalar call, contacts that differ:'
                do w = 2, n_ways
                    line = line // ' ' // trim(way_name(w)) // ' ' // itoa(ent%mismatches(w))
                end do
                call figs%add(line)
            end if
            worst_c = max(ent%ns(WAY_C), ent%ns(WAY_LEGACY)) / ent%ns(WAY_SCALAR)
            ns_arr = min(ent%ns(WAY_ARRAY), ent%ns(WAY_C_N), ent%ns(WAY_LEGACY_N))
            call figs%add('targets: legacy and C per contact at most 1.3 x the module scalar call: ' // &
                          fratio(ent%ns(WAY_LEGACY) / ent%ns(WAY_SCALAR)) // ' and ' // &
                          fratio(ent%ns(WAY_C) / ent%ns(WAY_SCALAR)) // ' (' // &
                          met(worst_c <= 1.3_wp, 'short by ' // fratio(worst_c / 1.3_wp) // ' x') // &
                          '); module scalar at most 40 ns: ' // ftoa(ent%ns(WAY_SCALAR), '(f6.1)') // ' ns (' // &
                          met(ent%ns(WAY_SCALAR) <= 40.0_wp, 'short by ' // &
                          ftoa(ent%ns(WAY_SCALAR) - 40.0_wp, '(f6.1)') // ' ns') // &
                          '); array at least 2.5 x cheaper than the scalar call: ' // &
                          fratio(ent%ns(WAY_SCALAR) / ent%ns(WAY_ARRAY)) // ' x (' // &
                          met(ent%ns(WAY_SCALAR) / ent%ns(WAY_ARRAY) >= 2.5_wp, 'short by ' // &
                          fratio(2.5_wp * ent%ns(WAY_ARRAY) / ent%ns(WAY_SCALAR)) // ' x') // &
                          '); array at most 15 ns per contact: ' // ftoa(ent%ns(WAY_ARRAY), '(f6.1)') // ' ns (' // &
                          met(ent%ns(WAY_ARRAY) <= 15.0_wp, 'short by ' // &
                          ftoa(ent%ns(WAY_ARRAY) - 15.0_wp, '(f6.1)') // ' ns') // ')')
        end if
        ! ---- against the iterative baselines, at equal accuracy
        i_fit = find_row(rows, 'inverse', 'fit', '')
        if (i_fit > 0) then
            acc_fit = maxval(rows(i_fit)%err(3:5))
            call figs%add('inverse: fit ' // ftoa(rows(i_fit)%ns, '(es9.2)') // ' ns per inverse over the ' // &
                          'inverse set, max error on alpha, k, d ' // ftoa(acc_fit, '(es9.2)') // &
                          '; iterative rows (secant over rk45 or GSL rk8pd at the accuracy asked): ' // iter_summary(rows))
            i_eq = fastest_iterative(rows, acc_fit)
            if (i_eq > 0) then
                call figs%add('speed-up at equal accuracy: the fastest iterative row as accurate as the fit is ' // &
                              row_name(rows(i_eq)) // ' (' // ftoa(rows(i_eq)%ns, '(es9.2)') // ' ns, error ' // &
                              ftoa(maxval(rows(i_eq)%err(3:5)), '(es9.2)') // '): ' // speedups(rows(i_eq)%ns))
            else
                ! the most accurate rows (errors within 10 % of the smallest count as ties: the
                ! reference resolves no finer), the fastest of them
                i_eq = most_accurate_iterative(rows)
                if (i_eq > 0) i_eq = fastest_iterative(rows, 1.1_wp * maxval(rows(i_eq)%err(3:5)))
                if (i_eq > 0) call figs%add('speed-up at equal accuracy: no iterative row reaches the fit''s ' // &
                                            'accuracy; against the fastest of the most accurate ones (error within ' // &
                                            '10 % of the smallest), ' // row_name(rows(i_eq)) // &
                                            ' (' // ftoa(rows(i_eq)%ns, '(es9.2)') // ' ns, error ' // &
                                            ftoa(maxval(rows(i_eq)%err(3:5)), '(es9.2)') // ', the fit is more ' // &
                                            'accurate): ' // speedups(rows(i_eq)%ns))
            end if
            i_10 = fastest_iterative(rows, 1.0e-10_wp)
            if (i_10 > 0) call figs%add('speed-up at accuracy 1e-10 (alpha, k, d; the fit is more accurate): ' // &
                                        'fastest iterative row ' // row_name(rows(i_10)) // ' (' // &
                                        ftoa(rows(i_10)%ns, '(es9.2)') // ' ns, error ' // &
                                        ftoa(maxval(rows(i_10)%err(3:5)), '(es9.2)') // '): ' // speedups(rows(i_10)%ns))
        end if
        targets = [1.0e-8_wp, 1.0e-10_wp]
        do j = 1, size(targets)
            call time_at_error(rows, 'rk45', targets(j), t_rk, q_rk)
            call time_at_error(rows, 'gsl-rkf45', targets(j), t_f, q_f)
            call time_at_error(rows, 'gsl-rk8pd', targets(j), t_8, q_8)
            call figs%add('forward at equal achieved error ' // trim(target_names(j)) // &
                          ' (max of e and tau_c errors; ns/call interpolated log-log between tolerances): rk45 ' // &
                          ns_text(q_rk, t_rk) // ', gsl-rk8pd ' // ns_text(q_8, t_8) // ' (' // ratio(t_8, t_rk) // &
                          '), gsl-rkf45 ' // ns_text(q_f, t_f) // ' (' // ratio(t_f, t_rk) // ')')
        end do
    contains
        !> 'met' or the shortfall.
        function met(ok, shortfall) result(r)
            logical, intent(in) :: ok
            character(len=*), intent(in) :: shortfall
            character(len=:), allocatable :: r
            if (ok) then
                r = 'met'
            else
                r = shortfall
            end if
        end function met

        !> Speed-up of every entry point (and of the inverse-set fit row) against t_iter [ns],
        !> with the target of 1000.
        function speedups(t_iter) result(r)
            real(wp), intent(in) :: t_iter
            character(len=:), allocatable :: r
            integer :: k
            real(wp) :: worst
            r = ''
            worst = huge(1.0_wp)
            if (ent%n > 0) then
                do k = 1, n_ways
                    r = r // trim(way_name(k)) // ' ' // fratio(t_iter / ent%ns(k)) // ' x, '
                    worst = min(worst, t_iter / ent%ns(k))
                end do
            end if
            r = r // 'fit on the inverse set ' // fratio(t_iter / rows(i_fit)%ns) // ' x'
            worst = min(worst, t_iter / rows(i_fit)%ns)
            r = r // ' (target at least 1000 x for every entry point: ' // &
                met(worst >= 1000.0_wp, 'short by ' // fratio(1000.0_wp / worst) // ' x') // ')'
        end function speedups
    end subroutine figures

    !> 'name = what it calls' of every entry point.
    function entry_legend() result(s)
        character(len=:), allocatable :: s
        integer :: w
        s = trim(way_name(1)) // ' = ' // trim(way_label(1))
        do w = 2, n_ways
            s = s // '; ' // trim(way_name(w)) // ' = ' // trim(way_label(w))
        end do
    end function entry_legend

    !> 'method setting' of a row.
    function row_name(r) result(s)
        type(bench_row), intent(in) :: r
        character(len=:), allocatable :: s
        s = r%method // ' ' // r%setting
    end function row_name

    logical function is_iterative(r)
        type(bench_row), intent(in) :: r
        is_iterative = r%problem == 'inverse' .and. (r%method == 'iterative' .or. r%method == 'gsl-secant')
    end function is_iterative

    !> The fastest iterative row whose max error on alpha, k and d is at most acc (0 if none).
    integer function fastest_iterative(rows, acc) result(k)
        type(bench_row), intent(in) :: rows(:)
        real(wp), intent(in) :: acc
        integer :: i
        k = 0
        do i = 1, size(rows)
            if (.not. is_iterative(rows(i))) cycle
            if (.not. (maxval(rows(i)%err(3:5)) <= acc)) cycle
            if (k == 0) then
                k = i
            else if (rows(i)%ns < rows(k)%ns) then
                k = i
            end if
        end do
    end function fastest_iterative

    !> The iterative row with the smallest max error on alpha, k and d (0 if none).
    integer function most_accurate_iterative(rows) result(k)
        type(bench_row), intent(in) :: rows(:)
        integer :: i
        k = 0
        do i = 1, size(rows)
            if (.not. is_iterative(rows(i))) cycle
            if (k == 0) then
                k = i
            else if (maxval(rows(i)%err(3:5)) < maxval(rows(k)%err(3:5))) then
                k = i
            end if
        end do
    end function most_accurate_iterative

    !> 'method setting: ns, error' of every iterative row.
    function iter_summary(rows) result(s)
        type(bench_row), intent(in) :: rows(:)
        character(len=:), allocatable :: s
        integer :: i
        s = ''
        do i = 1, size(rows)
            if (.not. is_iterative(rows(i))) cycle
            if (len(s) > 0) s = s // '; '
            s = s // row_name(rows(i)) // ' ' // ftoa(rows(i)%ns, '(es9.2)') // ' ns, error ' // &
                ftoa(maxval(rows(i)%err(3:5)), '(es9.2)')
        end do
    end function iter_summary

    !> 'N ns' (with the qualifier of time_at_error) or 'not reached'.
    function ns_text(qual, t) result(s)
        character(len=*), intent(in) :: qual
        real(wp), intent(in) :: t
        character(len=:), allocatable :: s
        if (ieee_is_nan(t)) then
            s = 'not reached'
        else
            s = qual // ftoa(t, '(es9.2)') // ' ns'
        end if
    end function ns_text

    !> A ratio with 3 significant digits.
    function fratio(x) result(s)
        real(wp), intent(in) :: x
        character(len=:), allocatable :: s
        if (x >= 100.0_wp .or. x < 0.01_wp) then
            s = ftoa(x, '(es9.2)')
        else if (x >= 10.0_wp) then
            s = ftoa(x, '(f6.1)')
        else
            s = ftoa(x, '(f6.2)')
        end if
    end function fratio

    !> 'R x rk45' for the time ratio a / b.
    function ratio(a, b) result(s)
        real(wp), intent(in) :: a, b
        character(len=:), allocatable :: s
        if (ieee_is_nan(a) .or. ieee_is_nan(b) .or. b <= 0.0_wp) then
            s = 'time ratio to rk45 n/a'
        else
            s = fratio(a / b) // ' x rk45'
        end if
    end function ratio

    !> ns per call of a forward integrator at achieved error `target`: interpolated
    !> log-log between the two tolerances whose errors bracket it (qualifier '');
    !> the loosest tolerance's time if that already achieves it ('<=');
    !> NaN if no tolerance does.
    subroutine time_at_error(rows, name, target, t, qual)
        type(bench_row), intent(in) :: rows(:)
        character(len=*), intent(in) :: name
        real(wp), intent(in) :: target
        real(wp), intent(out) :: t
        character(len=:), allocatable, intent(out) :: qual
        real(wp), allocatable :: err(:), ns(:)
        integer :: i
        real(wp) :: w
        allocate (err(0), ns(0))
        do i = 1, size(rows)
            if (rows(i)%problem == 'forward' .and. rows(i)%method == name) then
                err = [err, max(rows(i)%err(1), rows(i)%err(2))]
                ns = [ns, rows(i)%ns]
            end if
        end do
        t = ieee_value(t, ieee_quiet_nan)
        qual = ''
        if (size(err) == 0) return
        if (err(1) <= target) then
            t = ns(1)
            qual = '<='
            return
        end if
        do i = 1, size(err) - 1
            if (err(i) > target .and. err(i + 1) <= target) then
                w = (log(target) - log(err(i))) / (log(max(err(i + 1), plot_floor)) - log(err(i)))
                t = exp(log(ns(i)) + w * (log(ns(i + 1)) - log(ns(i))))
                return
            end if
        end do
    end subroutine time_at_error

    integer function find_row(rows, problem, method, setting) result(k)
        type(bench_row), intent(in) :: rows(:)
        character(len=*), intent(in) :: problem, method, setting
        integer :: i
        k = 0
        do i = 1, size(rows)
            if (rows(i)%problem == problem .and. rows(i)%method == method .and. rows(i)%setting == setting) k = i
        end do
    end function find_row

    ! ------------------------------------------------------------------ output

    subroutine build_table(rows, fmt, t)
        type(bench_row), intent(in) :: rows(:)
        integer, intent(in) :: fmt
        type(out_table), intent(out) :: t
        integer :: i, j
        if (fmt == FORMAT_TEXT) then
            call t%set_columns('problem,method,setting,points,err_e,err_tau,err_alpha,err_k,err_d,ns_per_call,' // &
                               'steps,rejected,rhs_evals')
        else
            call t%set_columns('problem,method,setting,max_rel_err_e,max_rel_err_tau,max_rel_err_alpha,' // &
                               'max_rel_err_k,max_rel_err_d,ns_per_call,rhs_evals')
        end if
        do i = 1, size(rows)
            call t%str(rows(i)%problem)
            call t%str(rows(i)%method)
            call t%str(blank_or(rows(i)%setting, fmt))
            if (fmt == FORMAT_TEXT) call t%str(itoa(rows(i)%npts) // '/' // itoa(rows(i)%ntot))
            do j = 1, 5
                call cell(rows(i)%err(j))
            end do
            call cell(rows(i)%ns)
            if (fmt == FORMAT_TEXT) then
                call cell(rows(i)%steps)
                call cell(rows(i)%rejected)
            end if
            call cell(rows(i)%rhs)
        end do
    contains
        !> A number, or the format's empty cell when negative (not applicable).
        subroutine cell(x)
            real(wp), intent(in) :: x
            if (x >= 0.0_wp) then
                call t%num(x)
            else if (fmt == FORMAT_JSON) then
                call t%num(ieee_value(x, ieee_quiet_nan))   ! rendered as null
            else if (fmt == FORMAT_TEXT) then
                call t%str('-')
            else
                call t%str('')
            end if
        end subroutine cell
    end subroutine build_table

    function blank_or(s, fmt) result(r)
        character(len=*), intent(in) :: s
        integer, intent(in) :: fmt
        character(len=:), allocatable :: r
        r = s
        if (len(s) == 0 .and. fmt == FORMAT_TEXT) r = '-'
    end function blank_or

    !> Text rendering: the '#' header (metadata without the figures, which go below
    !> the table) and a compact table with 3 significant digits.
    subroutine render_text(t, nfig, rows, buf)
        type(out_table), intent(in) :: t
        integer, intent(in) :: nfig
        type(bench_row), intent(in) :: rows(:)
        type(cli_buffer), intent(inout) :: buf
        integer :: i, j
        character(len=:), allocatable :: line
        do i = 1, size(t%meta_key) - nfig
            call buf%add('# ' // t%meta_key(i)%s // ': ' // t%meta_val(i)%s)
        end do
        call buf%add(pad('problem', 10) // ' ' // pad('method', 9) // ' ' // pad('setting', 9) // ' ' // &
                     pad('points', -7) // ' ' // pad('err_e', -9) // ' ' // pad('err_tau', -9) // ' ' // &
                     pad('err_alpha', -9) // ' ' // pad('err_k', -9) // ' ' // pad('err_d', -9) // ' ' // &
                     pad('ns/call', -9) // ' ' // pad('steps', -7) // ' ' // pad('rejected', -8) // ' ' // &
                     pad('rhs_evals', -9))
        do i = 1, size(rows)
            line = pad(rows(i)%problem, 10) // ' ' // pad(rows(i)%method, 9) // ' ' // &
                   pad(blank_or(rows(i)%setting, FORMAT_TEXT), 9) // ' ' // &
                   pad(itoa(rows(i)%npts) // '/' // itoa(rows(i)%ntot), -7)
            do j = 1, 5
                line = line // ' ' // pad(num_or_dash(rows(i)%err(j), '(es9.2)'), -9)
            end do
            line = line // ' ' // pad(num_or_dash(rows(i)%ns, '(es9.2)'), -9) // ' ' // &
                   pad(num_or_dash(rows(i)%steps, '(f7.1)'), -7) // ' ' // &
                   pad(num_or_dash(rows(i)%rejected, '(f8.2)'), -8) // ' ' // &
                   pad(num_or_dash(rows(i)%rhs, '(f9.1)'), -9)
            call buf%add(line)
        end do
    end subroutine render_text

    function num_or_dash(x, f) result(s)
        real(wp), intent(in) :: x
        character(len=*), intent(in) :: f
        character(len=:), allocatable :: s
        if (x < 0.0_wp) then
            s = '-'
        else
            s = ftoa(x, f)
        end if
    end function num_or_dash

    ! ------------------------------------------------------------------ plot

    !> Before any work: gnuplot present (else exit 4) and the target writable (else
    !> exit 2).  Chooses the terminal: pngcairo if gnuplot has it, else png.

    !> Work-precision diagram: forward and inverse panels.  Data and script go to
    !> temporary files; the PNG is written to FILE.tmp and renamed into place only
    !> when gnuplot succeeded.
    subroutine make_plot(rows, file, terminal, quick)
        type(bench_row), intent(in) :: rows(:)
        character(len=*), intent(in) :: file, terminal
        logical, intent(in) :: quick
        character(len=:), allocatable :: tmpdir, base, dat, gp, png_tmp
        type(cli_buffer) :: plots
        character(len=:), allocatable :: cmd
        integer :: u, ios, p, f, i, nblock, blocks(2, n_families)
        integer(int64) :: cnt
        character(len=*), parameter :: pts(n_families) = ['7 ', '5 ', '9 ', '13', '11', '3 ', '2 ', '1 ', '4 ']
        character(len=*), parameter :: colors(n_families) = ['#1f77b4', '#ff7f0e', '#2ca02c', '#9467bd', &
                                                             '#8c564b', '#e377c2', '#d62728', '#7f7f7f', '#17becf']
        character(len=*), parameter :: problems(2) = ['forward', 'inverse']
        real(wp) :: y
        tmpdir = env_or('TMPDIR', '/tmp')
        call system_clock(cnt)
        base = tmpdir // '/hertzdamp_bench_' // itoa8(cnt)
        dat = base // '.dat'
        gp = base // '.gp'
        png_tmp = plot_temp_name(file)

        open (newunit=u, file=dat, status='replace', action='write', iostat=ios)
        if (ios /= 0) call fail(EXIT_FAILURE, 'cannot write a temporary file in ' // tmpdir)
        nblock = 0
        blocks = -1
        do p = 1, 2
            do f = 1, n_families
                if (.not. any([(rows(i)%problem == problems(p) .and. rows(i)%family == f, i=1, size(rows))])) cycle
                blocks(p, f) = nblock
                nblock = nblock + 1
                do i = 1, size(rows)
                    if (rows(i)%problem /= problems(p) .or. rows(i)%family /= f) cycle
                    if (p == 1) then
                        y = max(rows(i)%err(1), rows(i)%err(2))
                    else
                        y = maxval(rows(i)%err(3:5))
                    end if
                    write (u, '(es14.6,1x,es14.6,1x,a)') rows(i)%ns, max(y, plot_floor), &
                        '"' // trim(rows(i)%setting) // '"'
                end do
                write (u, '(a)') ''
                write (u, '(a)') ''
            end do
        end do
        close (u)

        open (newunit=u, file=gp, status='replace', action='write', iostat=ios)
        if (ios /= 0) call fail(EXIT_FAILURE, 'cannot write a temporary file in ' // tmpdir)
        if (terminal == 'pngcairo') then
            write (u, '(a)') 'set terminal pngcairo size 1400,620 enhanced font "sans,10"'
        else
            write (u, '(a)') 'set terminal png size 1400,620'
        end if
        write (u, '(a)') 'set output ' // gp_string(png_tmp)
        write (u, '(a)') 'set multiplot layout 1,2 title "hertzdamp bench: work-precision' // &
            trim(merge(' (--quick)', '          ', quick)) // '"'
        write (u, '(a)') 'set logscale xy'
        ! fixed decades wide enough for every method (no point on the frame)
        write (u, '(a)') 'set xrange [3:3e7]'
        write (u, '(a)') 'set yrange [1e-16:1e2]'
        write (u, '(a)') 'set format x "10^{%L}"'
        write (u, '(a)') 'set format y "10^{%L}"'
        write (u, '(a)') 'set grid'
        write (u, '(a)') 'set key outside right top'
        write (u, '(a)') 'set xlabel "time per call [ns] (median)"'
        write (u, '(a)') 'set ylabel "max relative error (floor 1e-17)"'
        do p = 1, 2
            if (p == 1) then
                write (u, '(a)') 'set title "forward: alpha -> e, tau_c  (vs rk45 tol 1e-15)" noenhanced'
            else
                write (u, '(a)') 'set title "inverse: e, T_c, m, u_in -> alpha, k, d  (vs ' // inv_ref_text // ')" noenhanced'
            end if
            plots%n = 0
            do f = 1, n_families
                if (blocks(p, f) < 0) cycle
                call plots%add(gp_string(dat) // ' index ' // itoa(blocks(p, f)) // &
                               ' using 1:2 with linespoints pt ' // trim(pts(f)) // ' ps 1.5 lc rgb "' // colors(f) // &
                               '" title "' // trim(fam(f)) // '" noenhanced')
            end do
            if (plots%n == 0) then
                write (u, '(a)') 'set label 1 "no data" at graph 0.5, graph 0.5 center'
                write (u, '(a)') 'plot [1:10] [1:10] NaN notitle'
                write (u, '(a)') 'unset label 1'
            else
                cmd = 'plot '
                do i = 1, plots%n
                    cmd = cmd // plots%lines(i)%s
                    if (i < plots%n) cmd = cmd // ', '
                end do
                write (u, '(a)') cmd
            end if
        end do
        write (u, '(a)') 'unset multiplot'
        write (u, '(a)') 'set output'
        close (u)

        call plot_run(gp, png_tmp, file, [character(len=len(dat)) :: dat])
    end subroutine make_plot






    function env_or(name, default) result(v)
        character(len=*), intent(in) :: name, default
        character(len=:), allocatable :: v
        integer :: l, st
        call get_environment_variable(name, length=l, status=st)
        if (st /= 0 .or. l == 0) then
            v = default
            return
        end if
        allocate (character(len=l) :: v)
        call get_environment_variable(name, v)
    end function env_or

    ! ------------------------------------------------------------------ small helpers

    function itoa(i) result(s)
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        character(len=16) :: b
        write (b, '(i0)') i
        s = trim(b)
    end function itoa

    function itoa8(i) result(s)
        integer(int64), intent(in) :: i
        character(len=:), allocatable :: s
        character(len=24) :: b
        write (b, '(i0)') i
        s = trim(b)
    end function itoa8

    function ftoa(x, f) result(s)
        real(wp), intent(in) :: x
        character(len=*), intent(in) :: f
        character(len=:), allocatable :: s
        character(len=40) :: b
        if (.not. ieee_is_finite(x)) then
            s = 'n/a'
            return
        end if
        write (b, f) x
        s = trim(adjustl(b))
    end function ftoa

end module hertzdamp_cmd_bench
