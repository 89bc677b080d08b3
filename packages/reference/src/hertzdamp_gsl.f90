!> Independent peer solver of the damped Hertz collision built on GSL's odeiv2
!> explicit Runge-Kutta steppers (rkf45 and rk8pd), called through hand-written
!> `bind(C)` interfaces.
!>
!> It solves the similarity form (doc/theory.md section 2; doc/damping-laws.md)
!>
!>     z'' + alpha z^q z' + z^{3/2} = 0,   z(0) = 0,  z'(0) = 1,
!>
!> for the damping laws q = 0 (linear), 1/4 (tsuji), 1/2 (kuwabara-kono), starting at a
!> small tau0 > 0 from the local series in r = tau^{1/N} (N = 2, or 4 for q = 1/4; the
!> right-hand side is not smooth at z = 0), stepping with `gsl_odeiv2_evolve_apply`, and locating
!> every event inside an accepted step by Illinois regula falsi, where each trial value
!> re-integrates from the step start with the same stepper and tolerance (GSL has no
!> dense output for these steppers).
!>
!> This module is a test reference and a benchmark peer: it needs libgsl and is not
!> part of the core a DEM code links.  It keeps no module-level mutable state; every
!> call allocates its own GSL objects and passes alpha and the evaluation counter
!> through the `params` pointer of the GSL system.  (It switches GSL's global error
!> handler off on every call, which is idempotent.)
!>
!> Limits (measured): within about 1e-9 of alpha_c = 1.1279881355 (overlap, linear) the
!> march hits the step limit (status 2) instead of deciding; the same happens for tsuji
!> close to sqrt(5), and for kuwabara-kono (overlap) at large alpha (a stiff slow phase).  For the force definition at
!> large alpha, tau_c is ill-conditioned (the force z'' crosses zero with slope
!> 1.5 z^{1/2} z' ~ e ~ alpha^{-5/2}): e, z_max, tau_max stay accurate, but tau_c
!> converges only slowly with tol for alpha >~ 200.
module hertzdamp_gsl
    use, intrinsic :: iso_c_binding, only: c_int, c_long, c_double, c_size_t, c_ptr, &
        c_funptr, c_null_ptr, c_null_funptr, c_funloc, c_loc, c_f_pointer, c_associated
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_is_finite, &
        ieee_is_nan
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_NO_REBOUND, HD_MAX_STEPS, HD_BAD_ARGUMENT, HD_NO_CONVERGENCE, &
                         HD_BAD_LAW, HD_END_OVERLAP, HD_END_FORCE
    use hertzdamp_gsl_c, only: gsl_success, gsl_ebadfunc, gsl_odeiv2_system, gsl_odeiv2_step_rkf45, &
        gsl_odeiv2_step_rk8pd, gsl_sf_gamma, gsl_sf_beta, gsl_set_error_handler_off, gsl_odeiv2_step_alloc, &
        gsl_odeiv2_step_reset, gsl_odeiv2_step_free, gsl_odeiv2_control_y_new, gsl_odeiv2_control_free, &
        gsl_odeiv2_evolve_alloc, gsl_odeiv2_evolve_apply, gsl_odeiv2_evolve_reset, gsl_odeiv2_evolve_free
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    public :: hertzdamp_gsl_collide
    public :: gsl_sf_gamma, gsl_sf_beta   ! re-exported for the tests (closed forms)
    public :: gsl_odeiv2_step_rk8pd

    ! Statuses are those of the library (hertzdamp_status): HD_OK (rebound found),
    ! HD_NO_REBOUND (overlap definition, certified: e = 0, tau_c = +Inf), HD_MAX_STEPS
    ! (step limit reached before the collision ended), HD_BAD_ARGUMENT (alpha, iend, tol
    ! or method invalid), HD_NO_CONVERGENCE (a GSL routine failed: allocation, step
    ! size underflow, non-finite state).

    !> `method` value: GSL's embedded Runge-Kutta-Fehlberg 4(5).
    integer, parameter, public :: HERTZDAMP_GSL_RKF45 = 0
    !> `method` value: GSL's embedded Runge-Kutta Prince-Dormand 8(9).
    integer, parameter, public :: HERTZDAMP_GSL_RK8PD = 1

    !> Largest number of accepted steps of the main march.
    integer, parameter :: max_steps = 100000
    !> Largest number of evolve calls while re-integrating one trial point.
    integer, parameter :: max_sub_steps = 10000
    !> Largest number of root-finder iterations for one event.
    integer, parameter :: max_root_iter = 200
    !> Number of terms of the start series in r = tau^{1/N}.
    integer, parameter :: n_series = 120

    !> Event kinds (each normalised so that g > 0 before and g <= 0 after the event).
    integer, parameter :: ev_turn = 1, ev_overlap = 2, ev_force = 3


    !> What the right-hand side receives through `params`.
    type, bind(C) :: rhs_params
        real(c_double) :: alpha = 0.0_c_double    !! damping parameter
        real(c_double) :: q = 0.0_c_double        !! exponent of the damping law
        integer(c_long) :: nevals = 0_c_long      !! right-hand-side evaluations so far
    end type rhs_params

    !> One solve's GSL objects and system (local to each call: thread-safe).
    type :: solver_ctx
        type(rhs_params) :: par
        type(gsl_odeiv2_system) :: sys
        type(c_ptr) :: step = c_null_ptr
        type(c_ptr) :: control = c_null_ptr
        type(c_ptr) :: evolve = c_null_ptr
        real(wp) :: alpha = 0.0_wp
        real(wp) :: q = 0.0_wp
    end type solver_ctx



contains

    !> Solve one damped Hertz collision with a GSL odeiv2 stepper.
    !>
    !> On status 0 all outputs are set.  On status 1 (overlap definition, alpha >=
    !> alpha_c): e = 0, tau_c = +Inf, z_max and tau_max are set.  On status >= 2: e = 0,
    !> tau_c = 0, and z_max, tau_max are set only if the turning point was reached (else 0).
    !> No output is ever NaN.  Never prints, never stops.
    subroutine hertzdamp_gsl_collide(alpha, iend, tol, method, e, tau_c, z_max, tau_max, &
            status, rhs_evals, steps, atol, law)
        real(wp), intent(in) :: alpha      !! damping parameter (any sign for overlap, >= 0 for force)
        integer, intent(in) :: iend        !! contact end: 0 = overlap, 1 = force
        real(wp), intent(in) :: tol        !! absolute and relative local tolerance, in (0, 1)
        integer, intent(in) :: method      !! 0 = rkf45, 1 = rk8pd
        real(wp), intent(out) :: e         !! restitution coefficient -z'(tau_c)
        real(wp), intent(out) :: tau_c     !! contact duration
        real(wp), intent(out) :: z_max     !! largest overlap, z at the turning point
        real(wp), intent(out) :: tau_max   !! time of the turning point (z' = 0)
        integer, intent(out) :: status     !! 0 ok, 1 no rebound, 2 step limit, 3 bad input, 4 GSL failure
        integer, intent(out) :: rhs_evals  !! right-hand-side evaluations, root finding included
        integer, intent(out) :: steps      !! accepted steps of the main march (root finding excluded)
        real(wp), intent(in), optional :: atol !! absolute tolerance if not tol (tiny: relative control)
        integer, intent(in), optional :: law   !! damping law: 0 linear (default), 1 tsuji, 2 kuwabara-kono

        type(solver_ctx), target :: ctx
        real(wp) :: q
        real(c_double) :: t, h, y(2)
        integer :: kind_end, law_

        e = 0.0_wp
        tau_c = 0.0_wp
        z_max = 0.0_wp
        tau_max = 0.0_wp
        rhs_evals = 0
        steps = 0
        call check_input(alpha, iend, tol, method, law, law_, status)
        if (status /= HD_OK) return
        q = 0.25_wp * law_
        call open_solver(ctx, alpha, q, method, tol, atol, status)
        if (status /= HD_OK) return
        if (iend == HD_END_OVERLAP) then
            kind_end = ev_overlap
        else
            kind_end = ev_force
        end if
        call start(alpha, law_, q, t, h, y)
        call march_to_turn(ctx, iend, t, h, y, steps, z_max, tau_max, status)
        if (status == HD_OK) call march_to_end(ctx, iend, kind_end, t, h, y, steps, e, tau_c, status)
        call settle(status, e, tau_c, z_max, tau_max)
        rhs_evals = int(min(ctx%par%nevals, int(huge(rhs_evals), c_long)))
        call free_ctx(ctx)
    end subroutine hertzdamp_gsl_collide

    ! ---------------------------------------------------------------- phases of a solve

    !> The arguments of hertzdamp_gsl_collide checked: status HD_OK, HD_BAD_ARGUMENT or
    !> HD_BAD_LAW; law_ is the law (0 when absent).
    subroutine check_input(alpha, iend, tol, method, law, law_, status)
        real(wp), intent(in) :: alpha, tol
        integer, intent(in) :: iend, method
        integer, intent(in), optional :: law
        integer, intent(out) :: law_, status
        law_ = 0
        status = HD_BAD_ARGUMENT
        if (.not. ieee_is_finite(alpha) .or. ieee_is_nan(tol)) return
        if (.not. (tol > 0.0_wp .and. tol < 1.0_wp)) return
        if (iend /= HD_END_OVERLAP .and. iend /= HD_END_FORCE) return
        if (iend == HD_END_FORCE .and. alpha < 0.0_wp) return
        if (method /= HERTZDAMP_GSL_RKF45 .and. method /= HERTZDAMP_GSL_RK8PD) return
        if (abs(alpha) > 1.0e8_wp) return
        if (present(law)) law_ = law
        if (law_ < 0 .or. law_ > 2) then
            status = HD_BAD_LAW
            return
        end if
        status = HD_OK
    end subroutine check_input

    !> GSL's error handler off, the stepper, control (absolute tolerance atol if present,
    !> else tol; relative tol) and evolve objects of one solve, and its system.  Status
    !> HD_OK, or HD_NO_CONVERGENCE with nothing left allocated.
    subroutine open_solver(ctx, alpha, q, method, tol, atol, status)
        type(solver_ctx), target, intent(inout) :: ctx
        real(wp), intent(in) :: alpha, q, tol
        integer, intent(in) :: method
        real(wp), intent(in), optional :: atol
        integer, intent(out) :: status
        type(c_funptr) :: old_handler
        type(c_ptr) :: steptype
        real(wp) :: atol_
        old_handler = gsl_set_error_handler_off()
        if (method == HERTZDAMP_GSL_RKF45) then
            steptype = gsl_odeiv2_step_rkf45
        else
            steptype = gsl_odeiv2_step_rk8pd
        end if
        status = HD_NO_CONVERGENCE
        if (.not. c_associated(steptype)) return
        ctx%alpha = alpha
        ctx%q = q
        ctx%par%alpha = real(alpha, c_double)
        ctx%par%q = real(q, c_double)
        ctx%par%nevals = 0_c_long
        ctx%sys%function = c_funloc(hertz_rhs)
        ctx%sys%jacobian = c_null_funptr
        ctx%sys%dimension = 2_c_size_t
        ctx%sys%params = c_loc(ctx%par)
        ctx%step = gsl_odeiv2_step_alloc(steptype, 2_c_size_t)
        atol_ = tol
        if (present(atol)) atol_ = atol
        ctx%control = gsl_odeiv2_control_y_new(real(atol_, c_double), real(tol, c_double))
        ctx%evolve = gsl_odeiv2_evolve_alloc(2_c_size_t)
        if (.not. (c_associated(ctx%step) .and. c_associated(ctx%control) &
            .and. c_associated(ctx%evolve))) then
            call free_ctx(ctx)
            return
        end if
        status = HD_OK
    end subroutine open_solver

    !> The start of the march: the local series at tau0 (alpha tau0^{1+q} <= 0.05), and
    !> the first step size.
    subroutine start(alpha, law, q, t, h, y)
        real(wp), intent(in) :: alpha, q
        integer, intent(in) :: law
        real(c_double), intent(out) :: t, h, y(2)
        real(wp) :: tau0
        tau0 = 0.05_wp / max(1.0_wp, abs(alpha))**(1.0_wp / (1.0_wp + q))
        call series_start(alpha, law, tau0, y(1), y(2))
        t = tau0
        h = 0.1_wp * tau0
    end subroutine start

    !> One accepted step of the march from (t, y), which it keeps in (ta, ya).  Status
    !> HD_OK, HD_MAX_STEPS (max_steps taken already) or HD_NO_CONVERGENCE.
    subroutine advance(ctx, t, h, y, ta, ya, steps, status)
        type(solver_ctx), intent(inout) :: ctx
        real(c_double), intent(inout) :: t, h, y(2)
        real(c_double), intent(out) :: ta, ya(2)
        integer, intent(inout) :: steps
        integer, intent(out) :: status
        real(c_double), parameter :: t_far = 1.0e30_c_double
        integer(c_int) :: rc
        ta = t
        ya = y
        if (steps >= max_steps) then
            status = HD_MAX_STEPS
            return
        end if
        rc = gsl_odeiv2_evolve_apply(ctx%evolve, ctx%control, ctx%step, ctx%sys, &
            t, t_far, h, y)
        if (rc /= gsl_success .or. .not. all(ieee_is_finite(y))) then
            status = HD_NO_CONVERGENCE
            return
        end if
        steps = steps + 1
        status = HD_OK
    end subroutine advance

    !> Phase 1: march to the turning point (z' = 0) and restart from it.  Status HD_OK
    !> (go on to the end), HD_NO_REBOUND, or a failure of advance or locate.
    subroutine march_to_turn(ctx, iend, t, h, y, steps, z_max, tau_max, status)
        type(solver_ctx), intent(inout) :: ctx
        integer, intent(in) :: iend
        real(c_double), intent(inout) :: t, h, y(2)
        integer, intent(inout) :: steps
        real(wp), intent(out) :: z_max, tau_max
        integer, intent(out) :: status
        real(c_double) :: ta, ya(2), tr, yr(2)
        integer(c_int) :: rc
        logical :: ok
        z_max = 0.0_wp
        tau_max = 0.0_wp
        do
            call advance(ctx, t, h, y, ta, ya, steps, status)
            if (status /= HD_OK) return
            if (event_g(ev_turn, ctx%alpha, ctx%q, y) <= 0.0_wp) exit
        end do
        call locate(ctx, ev_turn, ta, ya, t, y, tr, yr, ok)
        if (.not. ok) then
            status = HD_NO_CONVERGENCE
            return
        end if
        tau_max = tr
        z_max = yr(1)
        ! Restart the march from the turning point.
        t = tr
        y = yr
        rc = gsl_odeiv2_evolve_reset(ctx%evolve)
        if (no_rebound(iend, ctx%alpha, ctx%q, y)) status = HD_NO_REBOUND
    end subroutine march_to_turn

    !> Phase 2: march from the turning point to the contact end kind_end (e = -z' there).
    !> Status HD_OK, HD_NO_REBOUND, or a failure of advance or locate.
    subroutine march_to_end(ctx, iend, kind_end, t, h, y, steps, e, tau_c, status)
        type(solver_ctx), intent(inout) :: ctx
        integer, intent(in) :: iend, kind_end
        real(c_double), intent(inout) :: t, h, y(2)
        integer, intent(inout) :: steps
        real(wp), intent(out) :: e, tau_c
        integer, intent(out) :: status
        real(c_double) :: ta, ya(2), tr, yr(2)
        logical :: ok
        e = 0.0_wp
        tau_c = 0.0_wp
        do
            call advance(ctx, t, h, y, ta, ya, steps, status)
            if (status /= HD_OK) return
            if (event_g(kind_end, ctx%alpha, ctx%q, y) <= 0.0_wp) exit
            if (no_rebound(iend, ctx%alpha, ctx%q, y)) then
                status = HD_NO_REBOUND
                return
            end if
        end do
        call locate(ctx, kind_end, ta, ya, t, y, tr, yr, ok)
        if (.not. ok) then
            status = HD_NO_CONVERGENCE
            return
        end if
        tau_c = tr
        e = -yr(2)
    end subroutine march_to_end

    !> The outputs of a solve that did not end with status HD_OK: e = 0, tau_c = +Inf
    !> (no rebound) or 0; z_max and tau_max 0 unless finite.
    subroutine settle(status, e, tau_c, z_max, tau_max)
        integer, intent(in) :: status
        real(wp), intent(inout) :: e, tau_c, z_max, tau_max
        if (status == HD_NO_REBOUND) then
            e = 0.0_wp
            tau_c = ieee_value(1.0_wp, ieee_positive_inf)
        else if (status /= HD_OK) then
            e = 0.0_wp
            tau_c = 0.0_wp
        end if
        if (.not. ieee_is_finite(z_max) .or. .not. ieee_is_finite(tau_max)) then
            z_max = 0.0_wp
            tau_max = 0.0_wp
        end if
    end subroutine settle

    ! ---------------------------------------------------------------- internals

    !> Right-hand side y = (z, z'): (z', -alpha |z|^q z' - sign(z)|z|^{3/2}) (odd extension,
    !> so that a step may cross z = 0).  Counts its calls in params%nevals.
    function hertz_rhs(t, y, dydt, params) bind(C) result(rc)
        real(c_double), value :: t
        real(c_double), intent(in) :: y(2)
        real(c_double), intent(out) :: dydt(2)
        type(c_ptr), value :: params
        integer(c_int) :: rc
        type(rhs_params), pointer :: p
        call c_f_pointer(params, p)
        p%nevals = p%nevals + 1_c_long
        dydt(1) = y(2)
        dydt(2) = -p%alpha * y(2) - sign(abs(y(1)) * sqrt(abs(y(1))), y(1))
        if (p%q > 0.0_c_double) dydt(2) = -p%alpha * abs(y(1))**p%q * y(2) - sign(abs(y(1))**1.5_c_double, y(1))
        rc = gsl_success
        if (ieee_is_nan(t) .or. .not. all(ieee_is_finite(dydt))) rc = gsl_ebadfunc
    end function hertz_rhs

    !> |z|^q (1 for q = 0).
    pure real(wp) function zpow(z, q)
        real(wp), intent(in) :: z, q
        zpow = 1.0_wp
        if (q > 0.0_wp) zpow = abs(z)**q
    end function zpow

    !> Event function, normalised to g > 0 before and g <= 0 after the event.
    pure real(wp) function event_g(kind, alpha, q, y) result(g)
        integer, intent(in) :: kind
        real(wp), intent(in) :: alpha, q, y(2)
        select case (kind)
        case (ev_turn)
            g = y(2)                                   ! z'
        case (ev_overlap)
            g = y(1)                                   ! z
        case default
            ! z^{3/2} - alpha z^q |z'| (z' < 0 after the turning point), odd in z
            g = sign(abs(y(1)) * sqrt(abs(y(1))), y(1)) + alpha * zpow(y(1), q) * y(2)
        end select
    end function event_g

    !> Time derivative of `event_g` along the solution, exact from the state.
    pure real(wp) function event_dg(kind, alpha, q, y) result(dg)
        integer, intent(in) :: kind
        real(wp), intent(in) :: alpha, q, y(2)
        real(wp) :: zpp
        zpp = -alpha * zpow(y(1), q) * y(2) - sign(abs(y(1)) * sqrt(abs(y(1))), y(1))
        select case (kind)
        case (ev_turn)
            dg = zpp
        case (ev_overlap)
            dg = y(2)
        case default
            dg = 1.5_wp * sqrt(abs(y(1))) * y(2) + alpha * zpow(y(1), q) * zpp
            if (q > 0.0_wp .and. y(1) > 0.0_wp) dg = dg + alpha * q * y(1)**(q - 1.0_wp) * y(2)**2
        end select
    end function event_dg

    !> Certificate of no rebound (overlap definition, alpha > 0): a forward-invariant set
    !> in which z stays positive for all time.  q = 0: 0 < z <= alpha^4/36,
    !> -(2/alpha) z^{3/2} <= z' <= 0 (z^{-1/2} grows at most like tau/alpha).  q = 1/4,
    !> alpha >= sqrt(5): z > 0, -lambda z^{5/4}/alpha <= z' <= 0 with lambda = 2 alpha^2/5
    !> (on the lower edge d(z' + lambda z^{5/4}/alpha)/dtau = z^{3/2} (lambda/2 - 1) >= 0).
    !> q = 1/2: none (the overlap always returns).
    pure logical function no_rebound(iend, alpha, q, y)
        integer, intent(in) :: iend
        real(wp), intent(in) :: alpha, q, y(2)
        no_rebound = .false.
        if (iend /= HD_END_OVERLAP .or. alpha <= 0.0_wp) return
        if (q == 0.0_wp) then
            if (.not. (y(1) > 0.0_wp .and. y(1) <= alpha**4 / 36.0_wp)) return
            no_rebound = y(2) <= 0.0_wp .and. &
                y(2) >= -(2.0_wp / alpha) * y(1) * sqrt(y(1))
        else if (q == 0.25_wp) then
            if (.not. (alpha**2 >= 5.0_wp .and. y(1) > 0.0_wp)) return
            no_rebound = y(2) <= 0.0_wp .and. y(2) >= -(2.0_wp * alpha / 5.0_wp) * y(1)**1.25_wp
        end if
    end function no_rebound

    !> z(tau0), z'(tau0) from the local series in r = tau^{1/N}:
    !> z = tau sum_k p_k r^k, p_0 = 1, N = 2 (q = 0, 1/2) or 4 (q = 1/4), and
    !> p_j (1 + j/N)(j/N) = -alpha S_{j - s1} - Y_{j - s2},  s1 = N(1+q), s2 = 5N/2,
    !> with Y = P^{3/2}, S = P^q * D, D_k = (1 + k/N) p_k (z^q z' = tau^q S), P = sum p_k r^k;
    !> the powers X = P^g by the recurrence k p_0 X_k = sum_{j=1..k} (g j - (k-j)) p_j X_{k-j}.
    !> Scaled coefficients a_k = p_k r0^k (the power recurrence is invariant under this
    !> scaling; r0^{s1} = tau0^{1+q}, r0^{s2} = tau0^{5/2}) avoid overflow for large alpha.
    pure subroutine series_start(alpha, law, tau0, z, zp)
        real(wp), intent(in) :: alpha, tau0
        integer, intent(in) :: law
        real(wp), intent(out) :: z, zp
        real(wp) :: a(0:n_series), b(0:n_series), g(0:n_series), sd(0:n_series), q, fn, acc
        integer :: j, k, n, s1, s2
        select case (law)
        case (1)
            n = 4; s1 = 5; s2 = 10; q = 0.25_wp
        case (2)
            n = 2; s1 = 3; s2 = 5; q = 0.5_wp
        case default
            n = 2; s1 = 2; s2 = 5; q = 0.0_wp
        end select
        fn = real(n, wp)
        a = 0.0_wp
        b = 0.0_wp
        g = 0.0_wp
        sd = 0.0_wp
        a(0) = 1.0_wp
        b(0) = 1.0_wp
        g(0) = 1.0_wp
        sd(0) = 1.0_wp
        do j = 1, n_series
            acc = 0.0_wp
            if (j >= s1) acc = acc + alpha * tau0**(1.0_wp + q) * sd(j - s1)
            if (j >= s2) acc = acc + tau0**2.5_wp * b(j - s2)
            a(j) = -acc / ((1.0_wp + j / fn) * (j / fn))
            ! the powers and the product at index j, from a(0..j)
            acc = 0.0_wp
            do k = 1, j
                acc = acc + (1.5_wp * k - (j - k)) * a(k) * b(j - k)
            end do
            b(j) = acc / (j * a(0))
            acc = 0.0_wp
            do k = 1, j
                acc = acc + (q * k - (j - k)) * a(k) * g(j - k)
            end do
            g(j) = acc / (j * a(0))
            acc = 0.0_wp
            do k = 0, j
                acc = acc + g(j - k) * (1.0_wp + k / fn) * a(k)
            end do
            sd(j) = acc
            ! stop once a full period of the recurrence (s2 indices) is negligible (for
            ! alpha = 0 only every s2-th coefficient is nonzero); this also avoids underflow
            if (j >= 2 * s2) then
                if (maxval(abs(a(j - s2 + 1:j))) < 1.0e-3_wp * epsilon(1.0_wp)) exit
            end if
        end do
        z = 0.0_wp
        zp = 0.0_wp
        do k = n_series, 0, -1
            z = z + a(k)
            zp = zp + (1.0_wp + k / fn) * a(k)
        end do
        z = tau0 * z
    end subroutine series_start

    !> Re-integrate from (ta, ya) to tt with the solve's stepper and tolerance.
    subroutine integrate_to(ctx, ta, ya, tt, yt, ok)
        type(solver_ctx), intent(inout) :: ctx
        real(c_double), intent(in) :: ta, ya(2), tt
        real(c_double), intent(out) :: yt(2)
        logical, intent(out) :: ok
        real(c_double) :: t, h
        integer(c_int) :: rc
        integer :: k
        yt = ya
        ok = .true.
        if (tt <= ta) return
        rc = gsl_odeiv2_evolve_reset(ctx%evolve)
        rc = gsl_odeiv2_step_reset(ctx%step)
        t = ta
        h = 2.0_c_double * (tt - ta)     ! longer than the interval: the first try ends at tt
        do k = 1, max_sub_steps
            if (t >= tt) exit
            rc = gsl_odeiv2_evolve_apply(ctx%evolve, ctx%control, ctx%step, ctx%sys, &
                t, tt, h, yt)
            if (rc /= gsl_success .or. .not. all(ieee_is_finite(yt))) then
                ok = .false.
                exit
            end if
        end do
        if (t < tt) ok = .false.
    end subroutine integrate_to

    !> Locate an event inside the accepted step [ta, tb] (g(ya) > 0 >= g(yb)).
    !> Trial points are re-integrated from (ta, ya).  Each iteration takes a Newton
    !> step from the bracket end with the smaller |g| (g' is exact from the state),
    !> safeguarded by Illinois regula falsi when Newton leaves the bracket.  Returns the
    !> last Newton base point once the Newton correction is below a few ulps (or the
    !> after-side bracket end when the bracket collapses).
    subroutine locate(ctx, kind, ta, ya, tb, yb, tr, yr, ok)
        type(solver_ctx), intent(inout) :: ctx
        integer, intent(in) :: kind
        real(c_double), intent(in) :: ta, ya(2), tb, yb(2)
        real(c_double), intent(out) :: tr, yr(2)
        logical, intent(out) :: ok
        real(wp) :: a, b, c, fa, fb, ga, gb, fc, d, t0, f0, y0(2), yla(2), ylb(2), yc(2)
        integer :: it, side
        a = ta
        b = tb
        yla = ya
        ylb = yb
        ga = event_g(kind, ctx%alpha, ctx%q, ya)     ! true values, for Newton
        gb = event_g(kind, ctx%alpha, ctx%q, yb)
        fa = ga                               ! Illinois-scaled values, for the fallback
        fb = gb
        side = 0
        ok = .true.
        tr = b
        yr = ylb
        do it = 1, max_root_iter
            if (gb >= 0.0_wp) exit            ! exactly on the root
            if (b - a <= 4.0_wp * epsilon(1.0_wp) * max(abs(a), abs(b))) exit
            if (abs(ga) < abs(gb)) then
                t0 = a
                f0 = ga
                y0 = yla
            else
                t0 = b
                f0 = gb
                y0 = ylb
            end if
            d = event_dg(kind, ctx%alpha, ctx%q, y0)
            c = a - 1.0_wp
            if (abs(d) > 0.0_wp) c = t0 - f0 / d
            if (abs(c - t0) <= 2.0_wp * epsilon(1.0_wp) * abs(t0)) then
                tr = t0
                yr = y0
                return
            end if
            if (.not. (c > a .and. c < b)) then
                c = a + (b - a) * (fa / (fa - fb))
                if (.not. (c > a .and. c < b)) c = 0.5_wp * (a + b)
                if (.not. (c > a .and. c < b)) exit
            end if
            call integrate_to(ctx, ta, ya, c, yc, ok)
            if (.not. ok) return
            fc = event_g(kind, ctx%alpha, ctx%q, yc)
            if (fc <= 0.0_wp) then
                b = c
                gb = fc
                fb = fc
                ylb = yc
                if (side == 1) fa = 0.5_wp * fa
                side = 1
            else
                a = c
                ga = fc
                fa = fc
                yla = yc
                if (side == -1) fb = 0.5_wp * fb
                side = -1
            end if
        end do
        tr = b
        yr = ylb
    end subroutine locate

    !> Free whatever GSL objects were allocated.
    subroutine free_ctx(ctx)
        type(solver_ctx), intent(inout) :: ctx
        if (c_associated(ctx%evolve)) call gsl_odeiv2_evolve_free(ctx%evolve)
        if (c_associated(ctx%control)) call gsl_odeiv2_control_free(ctx%control)
        if (c_associated(ctx%step)) call gsl_odeiv2_step_free(ctx%step)
    end subroutine free_ctx

end module hertzdamp_gsl
