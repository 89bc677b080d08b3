!> The forward table of `hertzdamp bench`: alpha -> (e, tau_c) of every method of one
!> damping law (rk45 at five tolerances; series, pade and compact for the linear law;
!> the fit; GSL rkf45 and rk8pd at five tolerances) against rk45 at tol 1e-15 of the
!> same law, over a set of alpha of both contact ends; its header lines and its figure
!> (time per call of the integrators at equal achieved error).
module hertzdamp_bench_table_forward
    use hertzdamp, only: hertzdamp_rk, hertzdamp_collision, hertzdamp_forward_alpha, hertzdamp_message, &
                         hertzdamp_law_name, HD_OK, HD_END_OVERLAP, HD_END_FORCE, HD_METHOD_RK45, HD_METHOD_SERIES, &
                         HD_METHOD_PADE, HD_METHOD_COMPACT, HD_METHOD_FIT, HD_DAMPING_LINEAR, HD_DAMPING_TSUJI
    use hertzdamp_gsl, only: hertzdamp_gsl_collide, HERTZDAMP_GSL_RKF45, HERTZDAMP_GSL_RK8PD
    use hertzdamp_bench_timer, only: bench_case, bench_measure
    use hertzdamp_bench_rows, only: bench_row, e_floor, plot_floor, fratio, short, ftoa, FAMILY_RK45, &
                                    FAMILY_GSL_RKF45, FAMILY_GSL_RK8PD, FAMILY_SERIES, FAMILY_PADE, FAMILY_COMPACT, &
                                    FAMILY_FIT
    use hertzdamp_cli, only: cli_buffer, fail, EXIT_FAILURE
    use hertzdamp_cli_output, only: out_table
    use hertzdamp_cli_text, only: itoa
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
    implicit none
    private
    public :: forward_set, forward_set_of, forward_table, forward_meta, forward_figures

    integer, parameter :: wp = hertzdamp_rk

    !> How a forward case computes: through hertzdamp_forward_alpha or GSL.
    integer, parameter :: ENGINE_LIB = 1, ENGINE_GSL = 2

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

    !> The alpha of the forward rows of one law: the first n_ov for the overlap end, the
    !> rest for the force end.
    type :: forward_set
        real(wp), allocatable :: alpha(:)
        integer, allocatable :: iend(:)
        integer :: n_ov = 0
        character(len=:), allocatable :: text   !! for the header
    end type forward_set

contains

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

    !> The alpha of the forward rows of one law: overlap alpha up to e ~ 1e-4 (linear:
    !> 1.1, tsuji: 2.1, kuwabara-kono: 13), force alpha up to e ~ 1e-4 .. 1e-5 (50, 200,
    !> 1000).
    function forward_set_of(law, quick) result(st)
        integer, intent(in) :: law
        logical, intent(in) :: quick
        type(forward_set) :: st
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
    end function forward_set_of

    !> The forward rows of the law over st: the reference (rk45 at tol 1e-15; the command
    !> fails if any point of it does), then every method against it.
    subroutine forward_table(law, st, min_time, repeats, rows)
        integer, intent(in) :: law
        type(forward_set), intent(in) :: st
        real(wp), intent(in) :: min_time
        integer, intent(in) :: repeats
        type(bench_row), allocatable, intent(inout) :: rows(:)
        type(fwd_case) :: fref
        integer :: i
        call fwd_init(fref, ENGINE_LIB, HD_METHOD_RK45, law, 1.0e-15_wp, -1, st%alpha, st%iend)
        call fref%run()
        do i = 1, size(st%alpha)
            if (fref%status(i) /= HD_OK) call fail(EXIT_FAILURE, 'forward reference (rk45, tol 1e-15, ' // &
                                                   hertzdamp_law_name(law) // ') failed: ' // &
                                                   hertzdamp_message(fref%status(i)))
        end do
        call forward_rows(law, st, fref, min_time, repeats, rows)
    end subroutine forward_table

    !> The rows of every forward method of the law over the set st, against fref.
    subroutine forward_rows(law, st, fref, min_time, repeats, rows)
        integer, intent(in) :: law
        type(forward_set), intent(in) :: st
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
            call one(ENGINE_LIB, HD_METHOD_RK45, tols(j), -1, 'rk45', trim(tol_names(j)), FAMILY_RK45, n)
        end do
        if (law == HD_DAMPING_LINEAR) then
            do j = 1, size(orders)
                call one(ENGINE_LIB, HD_METHOD_SERIES, 0.0_wp, orders(j), 'series', 'N=' // itoa(orders(j)), FAMILY_SERIES, &
                         st%n_ov)
            end do
            call one(ENGINE_LIB, HD_METHOD_PADE, 0.0_wp, -1, 'pade', '', FAMILY_PADE, st%n_ov)
            call one(ENGINE_LIB, HD_METHOD_COMPACT, 0.0_wp, -1, 'compact', '', FAMILY_COMPACT, n)
        end if
        call one(ENGINE_LIB, HD_METHOD_FIT, 0.0_wp, -1, 'fit', '', FAMILY_FIT, n)
        do j = 1, size(tols)
            call one(ENGINE_GSL, HERTZDAMP_GSL_RKF45, tols(j), -1, 'gsl-rkf45', trim(tol_names(j)), FAMILY_GSL_RKF45, n)
        end do
        do j = 1, size(tols)
            call one(ENGINE_GSL, HERTZDAMP_GSL_RK8PD, tols(j), -1, 'gsl-rk8pd', trim(tol_names(j)), FAMILY_GSL_RK8PD, n)
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

    !> The header lines of the forward table: the set of each law, the reference.
    subroutine forward_meta(t, laws, sets)
        type(out_table), intent(inout) :: t
        integer, intent(in) :: laws(:)
        type(forward_set), intent(in) :: sets(:)
        integer :: il
        do il = 1, size(laws)
            call t%meta('forward ' // hertzdamp_law_name(laws(il)), sets(il)%text)
        end do
        call t%meta('forward', 'reference rk45 at tol 1e-15 of the same law; error of e relative to ' // &
                    'max(e, 1e-3); series, pade and compact: linear law only (series and pade on the overlap ' // &
                    'alpha only)')
    end subroutine forward_meta

    !> The figures of the forward table for one law: the integrators at equal error.
    subroutine forward_figures(rows, law, figs)
        type(bench_row), intent(in) :: rows(:)
        integer, intent(in) :: law
        type(cli_buffer), intent(inout) :: figs
        integer :: j
        real(wp) :: targets(2), t_rk, t_f, t_8
        character(len=*), parameter :: target_names(2) = ['1e-8 ', '1e-10']
        character(len=:), allocatable :: q_rk, q_f, q_8, lname
        lname = hertzdamp_law_name(law) // ': '
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
    end subroutine forward_figures

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

end module hertzdamp_bench_table_forward
