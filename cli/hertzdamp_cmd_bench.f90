!> The command `bench`: the work-precision report of the library's methods, for every
!> damping law (or the one of --damping).
!>
!> Forward problem alpha -> (e, tau_c): every method against rk45 at tol 1e-15 (of the
!> same law).  Inverse problem (e, T_c, m, u_in) -> (k, d): every method against the
!> iterative inverse at tol 1e-14, including the iterative baselines (the library's
!> secant over rk45 for every law, and for the linear law the GSL peer's secant over
!> rk8pd, each at tolerances matched to the accuracy asked).  Entry points: the fit
!> inverse of each law through every way a user calls it (module scalar and array
!> calls, C functions through their bind(C) names, legacy externals), side by side over
!> the same 10^6 contacts, with their ratios to the module scalar call, a check that
!> they agree bit for bit, and the speed-up against the fastest iterative row at equal
!> accuracy; for the tsuji law also its inverse against the closed form of its overlap
!> end.  Every number is measured in this run; methods the library does not (yet)
!> provide are left out.  Everything is computed (and the plot written) before anything
!> is printed: on failure stdout stays empty.
module hertzdamp_cmd_bench
    use hertzdamp, only: hertzdamp_rk, hertzdamp_collision, hertzdamp_forward_alpha, hertzdamp_message, &
                         hertzdamp_law_name, HD_OK, HD_END_OVERLAP, HD_END_FORCE, HD_METHOD_RK45, HD_METHOD_SERIES, &
                         HD_METHOD_PADE, HD_METHOD_COMPACT, HD_METHOD_FIT, HD_METHOD_ITERATIVE, HD_DAMPING_LINEAR, &
                         HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO, hertzdamp_tsuji_alpha
    use hertzdamp_pair, only: hertzdamp_invert
    use hertzdamp_inverse, only: hertzdamp_invert_options
    use hertzdamp_gsl, only: hertzdamp_gsl_collide, HERTZDAMP_GSL_RKF45, HERTZDAMP_GSL_RK8PD
    use hertzdamp_gsl_secant, only: hertzdamp_gsl_secant_invert
    use hertzdamp_bench_entry, only: entry_data, entry_result, tsuji_result, entry_contacts, entry_measure, &
                                     tsuji_measure, n_ways, way_name, way_label, WAY_SCALAR, WAY_ARRAY, WAY_C, WAY_C_N, &
                                     WAY_LEGACY, WAY_LEGACY_N, n_ts, ts_name, ts_label, TS_CLOSED_ALPHA, TS_FIT_ALPHA, &
                                     TS_CLOSED_ALPHA_N, TS_FIT_ALPHA_N, TS_CLOSED_D, TS_BOUND_D, TS_CLOSED_D_N, &
                                     TS_BOUND_D_N
    use hertzdamp_cli_plot, only: plot_check_target, plot_scratch, plot_temp_name, gp_string
    use hertzdamp_cli_progress, only: progress_reporter
    use hertzdamp_bench_timer, only: bench_case, bench_measure, wall_seconds
    use hertzdamp_cli, only: cli_args, cli_buffer, parse_args, parse_choice, fail, quit, pad, EXIT_OK, EXIT_FAILURE
    use hertzdamp_cli_output, only: out_table, format_choices, FORMAT_TEXT, FORMAT_CSV, FORMAT_JSON
    use hertzdamp_cli_help, only: print_help, wants_help
    use hertzdamp_cli_text, only: itoa
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

    !> The damping laws, in the order of the rows (codes HD_DAMPING_* = 0, 1, 2).
    integer, parameter :: n_laws = 3

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
        integer :: law = HD_DAMPING_LINEAR
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
        integer :: law = HD_DAMPING_LINEAR
        real(wp) :: tol = 1.0e-10_wp
        real(wp), allocatable :: e(:), tc(:), m(:), u(:)
        real(wp), allocatable :: k(:), d(:), alpha(:), tstar(:), tau(:)
        integer, allocatable :: status(:)
        logical, allocatable :: bound(:)
    contains
        procedure :: run => inv_run
    end type inv_case

    !> The iterative inverse of the GSL peer (secant over rk8pd, linear law) over a set
    !> of e; k and d by the direct formulas from its alpha and tau_c.
    type, extends(bench_case) :: gsl_inv_case
        real(wp) :: tol = 1.0e-10_wp
        real(wp), allocatable :: e(:), tc(:), m(:), u(:)
        real(wp), allocatable :: k(:), d(:), alpha(:), tau(:)
        integer, allocatable :: status(:), solves(:), rhs(:)
    contains
        procedure :: run => gsl_inv_run
    end type gsl_inv_case

    !> One result row.
    type :: bench_row
        character(len=:), allocatable :: problem, method, setting
        integer :: law = HD_DAMPING_LINEAR
        integer :: family = 0
        integer :: npts = 0, ntot = 0
        real(wp) :: err(5) = -1.0_wp   !! e, tau, alpha, k, d; < 0: not applicable
        real(wp) :: ns = -1.0_wp
        real(wp) :: steps = -1.0_wp, rejected = -1.0_wp, rhs = -1.0_wp  !! means per collision; < 0: n/a
    end type bench_row

    !> The sets of one law: alpha of the forward rows (the first n_ov for the overlap
    !> end, the rest for the force end) and e of the inverse rows.
    type :: law_sets
        real(wp), allocatable :: alpha(:), e(:)
        integer, allocatable :: iend(:)
        integer :: n_ov = 0
        character(len=:), allocatable :: text   !! for the header
    end type law_sets

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
                    r = hertzdamp_forward_alpha(self%alpha(i), self%iend(i), self%method, self%tol, self%order, &
                                                law=self%law)
                else
                    r = hertzdamp_forward_alpha(self%alpha(i), self%iend(i), self%method, self%tol, law=self%law)
                end if
                self%e(i) = r%e
                self%tau(i) = r%tau_c
                self%status(i) = r%status
                self%steps(i) = r%stats%steps
                self%rejected(i) = r%stats%rejected
                self%rhs(i) = r%stats%rhs_evals
            case default
                call hertzdamp_gsl_collide(self%alpha(i), self%iend(i), self%tol, self%method, self%e(i), &
                                           self%tau(i), zm, tm, self%status(i), nrhs, nst, atol=1.0e-30_wp * self%tol, &
                                           law=self%law)
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
                                  bound_active=self%bound(i), law=self%law, &
                                  options=hertzdamp_invert_options(method=self%method, tol=self%tol))
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

    subroutine fwd_init(c, engine, method, law, tol, order, alpha, iend)
        type(fwd_case), intent(out) :: c
        integer, intent(in) :: engine, method, law, order
        real(wp), intent(in) :: tol, alpha(:)
        integer, intent(in) :: iend(:)
        integer :: n
        n = size(alpha)
        c%engine = engine
        c%method = method
        c%law = law
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

    subroutine inv_init(c, method, law, tol, e, tc, m, u)
        type(inv_case), intent(out) :: c
        integer, intent(in) :: method, law
        real(wp), intent(in) :: tol, e(:), tc(:), m(:), u(:)
        integer :: n
        n = size(e)
        c%method = method
        c%law = law
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

    !> The alpha and e of the rows of one law: overlap alpha up to e ~ 1e-4 (linear:
    !> 1.1, tsuji: 2.1, kuwabara-kono: 13), force alpha up to e ~ 1e-4 .. 1e-5 (50, 200,
    !> 1000), e of the inverse in [1e-3, 0.999] for every law.
    function sets_of(law, quick) result(st)
        integer, intent(in) :: law
        logical, intent(in) :: quick
        type(law_sets) :: st
        real(wp), allocatable :: fo(:)
        integer :: i
        select case (law)
        case (HD_DAMPING_LINEAR)
            if (quick) then
                st%alpha = [0.0_wp, 0.2_wp, 0.4_wp, 0.6_wp, 0.8_wp, 1.0_wp, 1.1_wp]
                fo = [0.0_wp, 0.5_wp, 2.0_wp, 10.0_wp, 50.0_wp]
            else
                st%alpha = [(0.05_wp * i, i=0, 22)]
                fo = [0.0_wp, 0.1_wp, 0.2_wp, 0.5_wp, 1.0_wp, 2.0_wp, 5.0_wp, 10.0_wp, 20.0_wp, 50.0_wp]
            end if
        case (HD_DAMPING_TSUJI)
            if (quick) then
                st%alpha = [0.0_wp, 0.4_wp, 0.8_wp, 1.2_wp, 1.6_wp, 2.0_wp]
                fo = [0.0_wp, 1.0_wp, 10.0_wp, 100.0_wp]
            else
                st%alpha = [(0.1_wp * i, i=0, 21)]
                fo = [0.0_wp, 0.1_wp, 0.2_wp, 0.5_wp, 1.0_wp, 2.0_wp, 5.0_wp, 10.0_wp, 20.0_wp, 50.0_wp, 100.0_wp, &
                      200.0_wp]
            end if
        case default
            if (quick) then
                st%alpha = [0.0_wp, 1.0_wp, 2.0_wp, 4.0_wp, 8.0_wp, 13.0_wp]
                fo = [0.0_wp, 1.0_wp, 10.0_wp, 100.0_wp, 1000.0_wp]
            else
                st%alpha = [(0.5_wp * i, i=0, 26)]
                fo = [0.0_wp, 0.1_wp, 0.2_wp, 0.5_wp, 1.0_wp, 2.0_wp, 5.0_wp, 10.0_wp, 20.0_wp, 50.0_wp, 100.0_wp, &
                      200.0_wp, 500.0_wp, 1000.0_wp]
            end if
        end select
        st%n_ov = size(st%alpha)
        st%text = itoa(st%n_ov) // ' alpha in [0, ' // short(st%alpha(st%n_ov)) // '] (overlap) and ' // &
                  itoa(size(fo)) // ' in [0, ' // short(fo(size(fo))) // '] (force)'
        st%alpha = [st%alpha, fo]
        allocate (st%iend(size(st%alpha)))
        st%iend(1:st%n_ov) = HD_END_OVERLAP
        st%iend(st%n_ov + 1:) = HD_END_FORCE
        if (quick) then
            st%e = [1.0e-3_wp, 1.0e-2_wp, 0.1_wp, 0.5_wp, 0.9_wp, 0.99_wp]
        else
            st%e = [1.0e-3_wp, 2.0e-3_wp, 5.0e-3_wp, 1.0e-2_wp, 2.0e-2_wp, 5.0e-2_wp, 0.1_wp, 0.2_wp, 0.3_wp, &
                    0.4_wp, 0.5_wp, 0.6_wp, 0.7_wp, 0.8_wp, 0.9_wp, 0.95_wp, 0.99_wp, 0.999_wp]
        end if
    end function sets_of

    ! ------------------------------------------------------------------ the command

    subroutine cmd_bench()
        type(cli_args) :: args
        integer :: fmt, sel, il, i, nl, n_entry
        logical :: quick, want_plot
        character(len=:), allocatable :: plot_file, terminal
        real(wp) :: min_time, t_start
        integer :: repeats
        integer, allocatable :: laws(:)
        type(law_sets) :: sets(n_laws)
        type(fwd_case) :: fref
        type(inv_case) :: iref
        type(bench_row), allocatable :: rows(:)
        type(entry_data) :: dat
        type(entry_result) :: ent(n_laws)
        type(tsuji_result) :: ts
        type(cli_buffer) :: buf
        type(out_table) :: t
        type(cli_buffer) :: figs
        type(progress_reporter) :: prog
        real(wp) :: done

        plot_file = ''
        terminal = ''
        if (wants_help()) then
            call print_help('bench')
            call quit(EXIT_OK)
        end if
        call parse_args(2, '--format --plot --damping', '--quick --progress', args)
        fmt = parse_choice(args%get('--format', 'text'), format_choices, 'format (--format)')
        sel = parse_choice(args%get('--damping', 'all'), 'all linear tsuji kuwabara-kono', 'damping law (--damping)')
        quick = args%has('--quick')
        want_plot = args%has('--plot')
        terminal = ''
        if (want_plot) then
            plot_file = args%get('--plot', '')
            call plot_check_target(plot_file, terminal)
        end if
        t_start = wall_seconds()
        if (sel == 1) then
            laws = [HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO]
        else
            laws = [sel - 2]
        end if
        nl = size(laws)

        if (quick) then
            min_time = 0.01_wp
            repeats = 3
            n_entry = 100000
        else
            min_time = 0.1_wp
            repeats = 5
            n_entry = 1000000
        end if

        allocate (rows(0))
        ! progress in phases: forward and inverse rows per law, the contacts, the entry
        ! points per law, the tsuji closed form
        call prog%start(real(3 * nl + 2, wp), 'bench', force=args%has('--progress'))
        done = 0.0_wp
        do il = 1, nl
            sets(il) = sets_of(laws(il), quick)
            ! references, computed once
            call fwd_init(fref, ENGINE_LIB, HD_METHOD_RK45, laws(il), 1.0e-15_wp, -1, sets(il)%alpha, sets(il)%iend)
            call fref%run()
            do i = 1, size(sets(il)%alpha)
                if (fref%status(i) /= HD_OK) call fail(EXIT_FAILURE, 'forward reference (rk45, tol 1e-15, ' // &
                                                       hertzdamp_law_name(laws(il)) // ') failed: ' // &
                                                       hertzdamp_message(fref%status(i)))
            end do
            call inv_init(iref, HD_METHOD_ITERATIVE, laws(il), inv_ref_tol, sets(il)%e, &
                          spread(inv_tc, 1, size(sets(il)%e)), spread(inv_m, 1, size(sets(il)%e)), &
                          spread(inv_u, 1, size(sets(il)%e)))
            call iref%run()
            do i = 1, size(sets(il)%e)
                if (iref%status(i) /= HD_OK) call fail(EXIT_FAILURE, 'inverse reference (' // inv_ref_text // ', ' // &
                                                       hertzdamp_law_name(laws(il)) // ') failed: ' // &
                                                       hertzdamp_message(iref%status(i)))
            end do
            if (laws(il) == HD_DAMPING_TSUJI) then
                ! the exact alpha of the overlap end (closed form) instead of the iterative one,
                ! whose error grows like that of rk45's e over -ln e as e -> 1; d is proportional to it
                iref%d = iref%d * (hertzdamp_tsuji_alpha(iref%e) / iref%alpha)
                iref%alpha = hertzdamp_tsuji_alpha(iref%e)
            end if
            call forward_rows(laws(il), sets(il), fref, min_time, repeats, rows)
            call step_done()
            call inverse_rows(laws(il), iref, min_time, repeats, rows)
            call step_done()
        end do
        call entry_contacts(n_entry, dat)
        call step_done()
        do il = 1, nl
            call entry_measure(laws(il), dat, min_time, repeats, ent(il))
            call entry_rows(ent(il), rows)
            call step_done()
        end do
        if (any(laws == HD_DAMPING_TSUJI)) then
            call tsuji_measure(dat, min_time, repeats, ts)
            call tsuji_rows(ts, rows)
        end if
        call prog%finish()
        call figures(rows, ent(1:nl), ts, figs)

        ! Render.
        call build_table(rows, fmt, t)
        if (fmt /= FORMAT_CSV) then
            call t%meta('bench', 'work-precision of hertzdamp: forward alpha -> (e, tau_c), inverse (e, T_c, m, ' // &
                        'u_in) -> (k, d), for the damping laws ' // law_list(laws) // '; every number measured in ' // &
                        'this run')
            if (quick) then
                call t%meta('mode', 'quick: fewer alpha and e, each time the median of 3 batches of >= 0.01 s wall ' // &
                            'clock (full run: 5 batches of >= 0.1 s)')
            else
                call t%meta('mode', 'full: each time the median of 5 batches of >= 0.1 s wall clock (system_clock)')
            end if
            do il = 1, nl
                call t%meta('forward ' // hertzdamp_law_name(laws(il)), sets(il)%text)
            end do
            call t%meta('forward', 'reference rk45 at tol 1e-15 of the same law; error of e relative to ' // &
                        'max(e, 1e-3); series, pade and compact: linear law only (series and pade on the overlap ' // &
                        'alpha only)')
            call t%meta('inverse', itoa(size(sets(1)%e)) // ' e in [1e-3, 0.999] (overlap), m = 1e-2 kg, ' // &
                        'u_in = 1 m/s, T_c = 1e-4 s; reference ' // inv_ref_text // ' of the same law (tsuji: ' // &
                        'with the exact alpha = sqrt5 beta(e)); iterative = ' // &
                        'secant over rk45, gsl-secant = secant over GSL rk8pd (linear law only), each solve at ' // &
                        'tol/10 min(1, |ln e|), setting = accuracy asked of alpha')
            call t%meta('entry', itoa(n_entry) // ' contacts (overlap), e uniform in [0.05, 0.99], m in ' // &
                        '[1e-9, 1] kg, u_in in [1e-3, 10] m/s, T_c in [1e-7, 1e-3] s (log-uniform), the same for ' // &
                        'every law; the entry points of one law timed side by side (rounds of one batch each); ' // &
                        'ns_per_call = per contact')
            call t%meta('entry points', entry_legend())
            if (any(laws == HD_DAMPING_TSUJI)) then
                call t%meta('closed-form', 'tsuji, overlap end, the entry contacts with k = k_phys half the ' // &
                            'stiffness of the unbounded inverse (bound active), timed side by side: ' // ts_legend() // &
                            '; err_alpha, err_d: largest relative difference from the closed form')
            end if
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

        if (want_plot) call make_plot(rows, laws, plot_file, terminal, quick)
        call buf%flush_to_stdout()
        call quit(EXIT_OK)
    contains
        subroutine step_done()
            done = done + 1.0_wp
            call prog%update(done)
        end subroutine step_done
    end subroutine cmd_bench

    !> 'linear, tsuji and kuwabara-kono' (the laws of the run).
    function law_list(laws) result(s)
        integer, intent(in) :: laws(:)
        character(len=:), allocatable :: s
        integer :: i
        s = hertzdamp_law_name(laws(1))
        do i = 2, size(laws)
            s = s // trim(merge(' and', ',   ', i == size(laws))) // ' ' // hertzdamp_law_name(laws(i))
        end do
    end function law_list

    ! ------------------------------------------------------------------ forward

    subroutine forward_rows(law, st, fref, min_time, repeats, rows)
        integer, intent(in) :: law
        type(law_sets), intent(in) :: st
        type(fwd_case), intent(in) :: fref
        real(wp), intent(in) :: min_time
        integer, intent(in) :: repeats
        type(bench_row), allocatable, intent(inout) :: rows(:)
        real(wp), parameter :: tols(5) = [1.0e-4_wp, 1.0e-6_wp, 1.0e-8_wp, 1.0e-10_wp, 1.0e-12_wp]
        character(len=*), parameter :: tol_names(5) = ['1e-4 ', '1e-6 ', '1e-8 ', '1e-10', '1e-12']
        integer, parameter :: orders(6) = [1, 2, 3, 5, 10, 20]
        integer :: j, n
        n = size(st%alpha)
        do j = 1, size(tols)
            call one(ENGINE_LIB, HD_METHOD_RK45, tols(j), -1, 'rk45', trim(tol_names(j)), 1, n)
        end do
        if (law == HD_DAMPING_LINEAR) then
            do j = 1, size(orders)
                call one(ENGINE_LIB, HD_METHOD_SERIES, 0.0_wp, orders(j), 'series', 'N=' // itoa(orders(j)), 4, st%n_ov)
            end do
            call one(ENGINE_LIB, HD_METHOD_PADE, 0.0_wp, -1, 'pade', '', 5, st%n_ov)
            call one(ENGINE_LIB, HD_METHOD_COMPACT, 0.0_wp, -1, 'compact', '', 6, n)
        end if
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
            call fwd_init(c, engine, method, law, tol_, order, st%alpha(1:npts), st%iend(1:npts))
            call c%run()
            idx = pack([(i, i=1, npts)], c%status == HD_OK)
            if (size(idx) == 0) return
            if (size(idx) < npts) call fwd_init(c, engine, method, law, tol_, order, st%alpha(idx), st%iend(idx))
            r%problem = 'forward'
            r%law = law
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

    subroutine inverse_rows(law, iref, min_time, repeats, rows)
        integer, intent(in) :: law
        type(inv_case), intent(in) :: iref
        real(wp), intent(in) :: min_time
        integer, intent(in) :: repeats
        type(bench_row), allocatable, intent(inout) :: rows(:)
        integer :: j
        real(wp), parameter :: tols(5) = [1.0e-6_wp, 1.0e-8_wp, 1.0e-10_wp, 1.0e-11_wp, 1.0e-12_wp]
        character(len=*), parameter :: tol_names(5) = ['1e-6 ', '1e-8 ', '1e-10', '1e-11', '1e-12']
        call one(HD_METHOD_FIT, 0.0_wp, 'fit', '', 7)
        if (law == HD_DAMPING_LINEAR) then
            call one(HD_METHOD_COMPACT, 0.0_wp, 'compact', '', 6)
            call one(HD_METHOD_SERIES, 0.0_wp, 'series', '', 4)
            call one(HD_METHOD_PADE, 0.0_wp, 'pade', '', 5)
        end if
        do j = 1, size(tols)
            call one(HD_METHOD_ITERATIVE, tols(j), 'iterative', trim(tol_names(j)), 8)
        end do
        if (law == HD_DAMPING_LINEAR) then
            do j = 1, size(tols)
                call one_gsl(tols(j), trim(tol_names(j)))
            end do
        end if
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
            r%law = law
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
            call inv_init(c, method, law, tol_, iref%e, iref%tc, iref%m, iref%u)
            call c%run()
            idx = pack([(i, i=1, n)], c%status == HD_OK)
            if (size(idx) == 0) return
            if (size(idx) < n) call inv_init(c, method, law, tol_, iref%e(idx), iref%tc(idx), iref%m(idx), iref%u(idx))
            r%problem = 'inverse'
            r%law = law
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

    !> The rows of the entry points of one law.
    subroutine entry_rows(ent, rows)
        type(entry_result), intent(in) :: ent
        type(bench_row), allocatable, intent(inout) :: rows(:)
        type(bench_row) :: r
        integer :: w
        do w = 1, n_ways
            r = bench_row('entry', trim(way_name(w)), 'n=' // itoa(ent%n), ent%law, 7, ent%n - ent%failed, ent%n, &
                          ns=ent%ns(w))
            rows = [rows, r]
        end do
    end subroutine entry_rows

    !> The rows of the tsuji comparison (problem closed-form): the fit's alpha and the
    !> bound's d with their largest difference from the closed form.
    subroutine tsuji_rows(ts, rows)
        type(tsuji_result), intent(in) :: ts
        type(bench_row), allocatable, intent(inout) :: rows(:)
        type(bench_row) :: r
        integer :: w
        do w = 1, n_ts
            r = bench_row('closed-form', trim(ts_name(w)), 'n=' // itoa(ts%n), HD_DAMPING_TSUJI, 7, ts%n, ts%n, &
                          ns=ts%ns(w))
            if (w == TS_FIT_ALPHA .or. w == TS_FIT_ALPHA_N) r%err(3) = ts%err_alpha
            if (w == TS_BOUND_D .or. w == TS_BOUND_D_N) r%err(5) = ts%err_d
            rows = [rows, r]
        end do
    end subroutine tsuji_rows

    ! ------------------------------------------------------------------ figures

    !> The 'figure' lines: ratios measured side by side in this run, law by law.
    subroutine figures(rows, ent, ts, figs)
        type(bench_row), intent(in) :: rows(:)
        type(entry_result), intent(in) :: ent(:)
        type(tsuji_result), intent(in) :: ts
        type(cli_buffer), intent(out) :: figs
        integer :: il
        do il = 1, size(ent)
            call law_figures(rows, ent(il), figs)
        end do
        if (ts%n > 0) call tsuji_figures(ts, figs)
    end subroutine figures

    !> The figures of one law: its entry points, their targets (issue 11), the speed-up
    !> against the iterative rows of the law, and the forward integrators at equal error.
    subroutine law_figures(rows, ent, figs)
        type(bench_row), intent(in) :: rows(:)
        type(entry_result), intent(in) :: ent
        type(cli_buffer), intent(inout) :: figs
        integer :: i_fit, i_eq, i_10, w, j, law
        real(wp) :: targets(2), t_rk, t_f, t_8, acc_fit, worst_c
        character(len=*), parameter :: target_names(2) = ['1e-8 ', '1e-10']
        character(len=:), allocatable :: q_rk, q_f, q_8, line, lname
        law = ent%law
        lname = hertzdamp_law_name(law) // ': '
        ! ---- entry points
        line = lname // 'entry points over ' // itoa(ent%n) // ' contacts, ns per contact (ratio to the module ' // &
               'scalar call):'
        do w = 1, n_ways
            line = line // ' ' // trim(way_name(w)) // ' ' // ftoa(ent%ns(w), '(f6.1)') // ' (' // &
                   fratio(ent%ns(w) / ent%ns(WAY_SCALAR)) // ')' // trim(merge(',', ' ', w < n_ways))
        end do
        call figs%add(line)
        if (all(ent%mismatches == 0)) then
            call figs%add(lname // 'entry points: k, d and status bit-identical to the module scalar call for ' // &
                          'every contact and every entry point (' // itoa(ent%failed) // ' contacts not ok)')
        else
            line = lname // 'entry points: NOT bit-identical to the module scalar call, contacts that differ:'
            do w = 2, n_ways
                line = line // ' ' // trim(way_name(w)) // ' ' // itoa(ent%mismatches(w))
            end do
            call figs%add(line)
        end if
        worst_c = max(ent%ns(WAY_C), ent%ns(WAY_LEGACY)) / ent%ns(WAY_SCALAR)
        call figs%add(lname // 'targets: legacy and C per contact at most 1.3 x the module scalar call: ' // &
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
        ! ---- against the iterative baselines of the law, at equal accuracy
        i_fit = find_row(rows, 'inverse', law, 'fit', '')
        if (i_fit > 0) then
            acc_fit = maxval(rows(i_fit)%err(3:5))
            call figs%add(lname // 'inverse: fit ' // ftoa(rows(i_fit)%ns, '(es9.2)') // ' ns per inverse over ' // &
                          'the inverse set, max error on alpha, k, d ' // ftoa(acc_fit, '(es9.2)') // &
                          '; iterative rows (secant over rk45' // trim(merge(' or GSL rk8pd', '             ', &
                          law == HD_DAMPING_LINEAR)) // ' at the accuracy asked): ' // iter_summary(rows, law))
            i_eq = fastest_iterative(rows, law, acc_fit)
            if (i_eq > 0) then
                call figs%add(lname // 'speed-up at equal accuracy: the fastest iterative row as accurate as the ' // &
                              'fit is ' // row_name(rows(i_eq)) // ' (' // ftoa(rows(i_eq)%ns, '(es9.2)') // &
                              ' ns, error ' // ftoa(maxval(rows(i_eq)%err(3:5)), '(es9.2)') // '): ' // &
                              speedups(rows(i_eq)%ns))
            else
                ! the most accurate rows (errors within 10 % of the smallest count as ties: the
                ! reference resolves no finer), the fastest of them
                i_eq = most_accurate_iterative(rows, law)
                if (i_eq > 0) i_eq = fastest_iterative(rows, law, 1.1_wp * maxval(rows(i_eq)%err(3:5)))
                if (i_eq > 0) call figs%add(lname // 'speed-up at equal accuracy: no iterative row reaches the ' // &
                                            'fit''s accuracy; against the fastest of the most accurate ones ' // &
                                            '(error within 10 % of the smallest), ' // row_name(rows(i_eq)) // &
                                            ' (' // ftoa(rows(i_eq)%ns, '(es9.2)') // ' ns, error ' // &
                                            ftoa(maxval(rows(i_eq)%err(3:5)), '(es9.2)') // ', the fit is more ' // &
                                            'accurate): ' // speedups(rows(i_eq)%ns))
            end if
            i_10 = fastest_iterative(rows, law, 1.0e-10_wp)
            if (i_10 > 0) call figs%add(lname // 'speed-up at accuracy 1e-10 (alpha, k, d; the fit is more ' // &
                                        'accurate): fastest iterative row ' // row_name(rows(i_10)) // ' (' // &
                                        ftoa(rows(i_10)%ns, '(es9.2)') // ' ns, error ' // &
                                        ftoa(maxval(rows(i_10)%err(3:5)), '(es9.2)') // '): ' // &
                                        speedups(rows(i_10)%ns))
        end if
        targets = [1.0e-8_wp, 1.0e-10_wp]
        do j = 1, size(targets)
            call time_at_error(rows, law, 'rk45', targets(j), t_rk, q_rk)
            call time_at_error(rows, law, 'gsl-rkf45', targets(j), t_f, q_f)
            call time_at_error(rows, law, 'gsl-rk8pd', targets(j), t_8, q_8)
            call figs%add(lname // 'forward at equal achieved error ' // trim(target_names(j)) // &
                          ' (max of e and tau_c errors; ns/call interpolated log-log between tolerances): rk45 ' // &
                          ns_text(q_rk, t_rk) // ', gsl-rk8pd ' // ns_text(q_8, t_8) // ' (' // ratio(t_8, t_rk) // &
                          '), gsl-rkf45 ' // ns_text(q_f, t_f) // ' (' // ratio(t_f, t_rk) // ')')
        end do
    contains
        !> Speed-up of every entry point of the law (and of the inverse-set fit row) against
        !> t_iter [ns], with the target of 1000.
        function speedups(t_iter) result(r)
            real(wp), intent(in) :: t_iter
            character(len=:), allocatable :: r
            integer :: k
            real(wp) :: worst
            r = ''
            worst = huge(1.0_wp)
            do k = 1, n_ways
                r = r // trim(way_name(k)) // ' ' // fratio(t_iter / ent%ns(k)) // ' x, '
                worst = min(worst, t_iter / ent%ns(k))
            end do
            r = r // 'fit on the inverse set ' // fratio(t_iter / rows(i_fit)%ns) // ' x'
            worst = min(worst, t_iter / rows(i_fit)%ns)
            r = r // ' (target at least 1000 x for every entry point: ' // &
                met(worst >= 1000.0_wp, 'short by ' // fratio(1000.0_wp / worst) // ' x') // ')'
        end function speedups
    end subroutine law_figures

    !> The figures of the tsuji comparison: what the fit's inverse costs against the
    !> closed form of the overlap end, and how far its results are from it.
    subroutine tsuji_figures(ts, figs)
        type(tsuji_result), intent(in) :: ts
        type(cli_buffer), intent(inout) :: figs
        call figs%add('tsuji: inverse against the closed form alpha = sqrt5 beta(e) (overlap end, ' // itoa(ts%n) // &
                      ' contacts, ns per contact): alpha alone ' // ftoa(ts%ns(TS_CLOSED_ALPHA), '(f6.1)') // &
                      ' (closed form) against ' // ftoa(ts%ns(TS_FIT_ALPHA), '(f6.1)') // ' (fit: alpha and tau_c), ' // &
                      'ratio ' // fratio(ts%ns(TS_FIT_ALPHA) / ts%ns(TS_CLOSED_ALPHA)) // '; over arrays ' // &
                      ftoa(ts%ns(TS_CLOSED_ALPHA_N), '(f6.1)') // ' against ' // ftoa(ts%ns(TS_FIT_ALPHA_N), '(f6.1)') // &
                      ', ratio ' // fratio(ts%ns(TS_FIT_ALPHA_N) / ts%ns(TS_CLOSED_ALPHA_N)) // &
                      '; the engines'' d = alpha sqrt(m k) for a given k ' // ftoa(ts%ns(TS_CLOSED_D), '(f6.1)') // &
                      ' (closed form) against ' // ftoa(ts%ns(TS_BOUND_D), '(f6.1)') // &
                      ' (hertzdamp_invert with k_phys = k), ratio ' // fratio(ts%ns(TS_BOUND_D) / ts%ns(TS_CLOSED_D)) // &
                      '; over arrays ' // ftoa(ts%ns(TS_CLOSED_D_N), '(f6.1)') // ' against ' // &
                      ftoa(ts%ns(TS_BOUND_D_N), '(f6.1)') // ', ratio ' // &
                      fratio(ts%ns(TS_BOUND_D_N) / ts%ns(TS_CLOSED_D_N)))
        call figs%add('tsuji: the fit''s alpha differs from the closed form by at most ' // &
                      ftoa(ts%err_alpha, '(es9.2)') // ' (relative), its bounded d from alpha sqrt(m k) by ' // &
                      ftoa(ts%err_d, '(es9.2)') // '; ' // itoa(ts%failed) // ' library results not ok, ' // &
                      itoa(ts%unbound) // ' contacts with the bound inactive, ' // itoa(ts%mismatches) // &
                      ' contacts where an array call differs from the one-contact call')
    end subroutine tsuji_figures

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

    !> 'name = what it calls' of every entry point, for the linear law and the others.
    function entry_legend() result(s)
        character(len=:), allocatable :: s
        integer :: w
        s = 'linear: ' // trim(way_name(1)) // ' = ' // trim(way_label(1, 1))
        do w = 2, n_ways
            s = s // '; ' // trim(way_name(w)) // ' = ' // trim(way_label(w, 1))
        end do
        s = s // '; the other laws: ' // trim(way_name(1)) // ' = ' // trim(way_label(1, 2))
        do w = 2, n_ways
            s = s // '; ' // trim(way_name(w)) // ' = ' // trim(way_label(w, 2))
        end do
    end function entry_legend

    !> 'name = what it computes' of every row of the tsuji comparison.
    function ts_legend() result(s)
        character(len=:), allocatable :: s
        integer :: w
        s = trim(ts_name(1)) // ' = ' // trim(ts_label(1))
        do w = 2, n_ts
            s = s // '; ' // trim(ts_name(w)) // ' = ' // trim(ts_label(w))
        end do
    end function ts_legend

    !> 'method setting' of a row.
    function row_name(r) result(s)
        type(bench_row), intent(in) :: r
        character(len=:), allocatable :: s
        s = r%method // ' ' // r%setting
    end function row_name

    !> An iterative inverse row of the law.
    logical function is_iterative(r, law)
        type(bench_row), intent(in) :: r
        integer, intent(in) :: law
        is_iterative = r%problem == 'inverse' .and. r%law == law .and. &
                       (r%method == 'iterative' .or. r%method == 'gsl-secant')
    end function is_iterative

    !> The fastest iterative row of the law whose max error on alpha, k and d is at most
    !> acc (0 if none).
    integer function fastest_iterative(rows, law, acc) result(k)
        type(bench_row), intent(in) :: rows(:)
        integer, intent(in) :: law
        real(wp), intent(in) :: acc
        integer :: i
        k = 0
        do i = 1, size(rows)
            if (.not. is_iterative(rows(i), law)) cycle
            if (.not. (maxval(rows(i)%err(3:5)) <= acc)) cycle
            if (k == 0) then
                k = i
            else if (rows(i)%ns < rows(k)%ns) then
                k = i
            end if
        end do
    end function fastest_iterative

    !> The iterative row of the law with the smallest max error on alpha, k and d (0 if none).
    integer function most_accurate_iterative(rows, law) result(k)
        type(bench_row), intent(in) :: rows(:)
        integer, intent(in) :: law
        integer :: i
        k = 0
        do i = 1, size(rows)
            if (.not. is_iterative(rows(i), law)) cycle
            if (k == 0) then
                k = i
            else if (maxval(rows(i)%err(3:5)) < maxval(rows(k)%err(3:5))) then
                k = i
            end if
        end do
    end function most_accurate_iterative

    !> 'method setting: ns, error' of every iterative row of the law.
    function iter_summary(rows, law) result(s)
        type(bench_row), intent(in) :: rows(:)
        integer, intent(in) :: law
        character(len=:), allocatable :: s
        integer :: i
        s = ''
        do i = 1, size(rows)
            if (.not. is_iterative(rows(i), law)) cycle
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
    subroutine time_at_error(rows, law, name, target, t, qual)
        type(bench_row), intent(in) :: rows(:)
        integer, intent(in) :: law
        character(len=*), intent(in) :: name
        real(wp), intent(in) :: target
        real(wp), intent(out) :: t
        character(len=:), allocatable, intent(out) :: qual
        real(wp), allocatable :: err(:), ns(:)
        integer :: i
        real(wp) :: w
        allocate (err(0), ns(0))
        do i = 1, size(rows)
            if (rows(i)%problem == 'forward' .and. rows(i)%law == law .and. rows(i)%method == name) then
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

    integer function find_row(rows, problem, law, method, setting) result(k)
        type(bench_row), intent(in) :: rows(:)
        character(len=*), intent(in) :: problem, method, setting
        integer, intent(in) :: law
        integer :: i
        k = 0
        do i = 1, size(rows)
            if (rows(i)%problem == problem .and. rows(i)%law == law .and. rows(i)%method == method .and. &
                rows(i)%setting == setting) k = i
        end do
    end function find_row

    ! ------------------------------------------------------------------ output

    subroutine build_table(rows, fmt, t)
        type(bench_row), intent(in) :: rows(:)
        integer, intent(in) :: fmt
        type(out_table), intent(out) :: t
        integer :: i, j
        if (fmt == FORMAT_TEXT) then
            call t%set_columns('problem,damping,method,setting,points,err_e,err_tau,err_alpha,err_k,err_d,' // &
                               'ns_per_call,steps,rejected,rhs_evals')
        else
            call t%set_columns('problem,damping,method,setting,max_rel_err_e,max_rel_err_tau,max_rel_err_alpha,' // &
                               'max_rel_err_k,max_rel_err_d,ns_per_call,rhs_evals')
        end if
        do i = 1, size(rows)
            call t%str(rows(i)%problem)
            call t%str(hertzdamp_law_name(rows(i)%law))
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
        call buf%add(pad('problem', 11) // ' ' // pad('damping', 13) // ' ' // pad('method', 14) // ' ' // &
                     pad('setting', 9) // ' ' // &
                     pad('points', -7) // ' ' // pad('err_e', -9) // ' ' // pad('err_tau', -9) // ' ' // &
                     pad('err_alpha', -9) // ' ' // pad('err_k', -9) // ' ' // pad('err_d', -9) // ' ' // &
                     pad('ns/call', -9) // ' ' // pad('steps', -7) // ' ' // pad('rejected', -8) // ' ' // &
                     pad('rhs_evals', -9))
        do i = 1, size(rows)
            line = pad(rows(i)%problem, 11) // ' ' // pad(hertzdamp_law_name(rows(i)%law), 13) // ' ' // &
                   pad(rows(i)%method, 14) // ' ' // &
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

    !> Work-precision diagram: forward (top) and inverse (bottom) panels, one column per
    !> damping law of the run.  Data and script go to temporary files; the PNG is written
    !> to FILE.tmp and renamed into place only when gnuplot succeeded.
    subroutine make_plot(rows, laws, file, terminal, quick)
        type(bench_row), intent(in) :: rows(:)
        integer, intent(in) :: laws(:)
        character(len=*), intent(in) :: file, terminal
        logical, intent(in) :: quick
        character(len=:), allocatable :: dat, gp, png_tmp
        type(cli_buffer) :: plots
        type(plot_scratch) :: sc
        character(len=:), allocatable :: cmd
        character(len=200) :: line
        integer :: u, p, f, i, il, nblock, blocks(2, size(laws), n_families)
        character(len=*), parameter :: pts(n_families) = ['7 ', '5 ', '9 ', '13', '11', '3 ', '2 ', '1 ', '4 ']
        character(len=*), parameter :: colors(n_families) = ['#1f77b4', '#ff7f0e', '#2ca02c', '#9467bd', &
                                                             '#8c564b', '#e377c2', '#d62728', '#7f7f7f', '#17becf']
        character(len=*), parameter :: problems(2) = ['forward', 'inverse']
        real(wp) :: y
        cmd = ''
        png_tmp = plot_temp_name()
        ! data and script are scratch files of hertzdamp_cli_plot: every write checked, all
        ! removed whatever happens, exit 4 with nothing left behind on failure
        call sc%open('bench', 'dat', u, dat)
        nblock = 0
        blocks = -1
        do p = 1, 2
            do il = 1, size(laws)
                do f = 1, n_families
                    if (.not. any([(in_panel(rows(i), p, il) .and. rows(i)%family == f, i=1, size(rows))])) cycle
                    blocks(p, il, f) = nblock
                    nblock = nblock + 1
                    do i = 1, size(rows)
                        if (.not. in_panel(rows(i), p, il) .or. rows(i)%family /= f) cycle
                        if (p == 1) then
                            y = max(rows(i)%err(1), rows(i)%err(2))
                        else
                            y = maxval(rows(i)%err(3:5))
                        end if
                        write (line, '(es14.6,1x,es14.6,1x,a)') rows(i)%ns, max(y, plot_floor), &
                            '"' // trim(rows(i)%setting) // '"'
                        call sc%write(u, trim(line))
                    end do
                    call sc%write(u, '')
                    call sc%write(u, '')
                end do
            end do
        end do
        call sc%close(u)

        call sc%open('bench', 'gp', u, gp)
        if (terminal == 'pngcairo') then
            call sc%write(u, 'set terminal pngcairo size ' // itoa(100 + 620 * size(laws)) // &
                ',1150 enhanced font "sans,10"')
        else
            call sc%write(u, 'set terminal png size ' // itoa(100 + 620 * size(laws)) // ',1150')
        end if
        call sc%write(u, 'set output ' // gp_string(png_tmp))
        call sc%write(u, 'set multiplot layout 2,' // itoa(size(laws)) // &
            ' title "hertzdamp bench: work-precision' // trim(merge(' (--quick)', '          ', quick)) // '"')
        call sc%write(u, 'set logscale xy')
        ! fixed decades wide enough for every method (no point on the frame), room for the key
        call sc%write(u, 'set xrange [3:3e7]')
        call sc%write(u, 'set yrange [1e-16:1e6]')
        call sc%write(u, 'set format x "10^{%L}"')
        call sc%write(u, 'set format y "10^{%L}"')
        call sc%write(u, 'set grid')
        call sc%write(u, 'set key top left horizontal maxcols 3 samplen 2')
        call sc%write(u, 'set xlabel "time per call [ns] (median)"')
        call sc%write(u, 'set ylabel "max relative error (floor 1e-17)"')
        do p = 1, 2
            do il = 1, size(laws)
                if (p == 1) then
                    call sc%write(u, 'set title "' // hertzdamp_law_name(laws(il)) // &
                        ', forward: alpha -> e, tau_c  (vs rk45 tol 1e-15)" noenhanced')
                else
                    call sc%write(u, 'set title "' // hertzdamp_law_name(laws(il)) // &
                        ', inverse: e, T_c, m, u_in -> alpha, k, d  (vs ' // inv_ref_text // ')" noenhanced')
                end if
                plots%n = 0
                do f = 1, n_families
                    if (blocks(p, il, f) < 0) cycle
                    call plots%add(gp_string(dat) // ' index ' // itoa(blocks(p, il, f)) // &
                                   ' using 1:2 with linespoints pt ' // trim(pts(f)) // ' ps 1.5 lc rgb "' // &
                                   colors(f) // '" title "' // trim(fam(f)) // '" noenhanced')
                end do
                if (plots%n == 0) then
                    call sc%write(u, 'set label 1 "no data" at graph 0.5, graph 0.5 center')
                    call sc%write(u, 'plot [1:10] [1:10] NaN notitle')
                    call sc%write(u, 'unset label 1')
                else
                    cmd = 'plot '
                    do i = 1, plots%n
                        cmd = cmd // plots%lines(i)%s
                        if (i < plots%n) cmd = cmd // ', '
                    end do
                    call sc%write(u, cmd)
                end if
            end do
        end do
        call sc%write(u, 'unset multiplot')
        call sc%write(u, 'set output')
        call sc%close(u)

        call sc%draw(gp, file)
    contains
        !> The row belongs to panel (problem p, law il).
        logical function in_panel(r, p, il)
            type(bench_row), intent(in) :: r
            integer, intent(in) :: p, il
            in_panel = r%problem == problems(p) .and. r%law == laws(il)
        end function in_panel
    end subroutine make_plot

    ! ------------------------------------------------------------------ small helpers

    !> x as an integer when it is one, else with one decimal.
    function short(x) result(s)
        real(wp), intent(in) :: x
        character(len=:), allocatable :: s
        if (abs(x) < 1.0e9_wp .and. x == aint(x)) then
            s = itoa(int(x))
        else
            s = ftoa(x, '(f0.1)')
        end if
    end function short

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
