!> An iterative inverse over GSL: the baseline a careful DEM developer would write
!> with a good library integrator, for `hertzdamp bench`.
!>
!> alpha(e) by the secant of the core (hertzdamp_secant_start/_next: compact or
!> first-order start, proportional second step, bracket), each trial one collision
!> solved with GSL odeiv2's rk8pd (Prince-Dormand 8(9)) under relative error control
!> at the tolerance the core's iterative method uses for the same accuracy,
!> tol/10 min(1, |ln e|).  The end of contact is found on each accepted step from a
!> quintic Hermite interpolant of the step (z, z', z'' at both ends), then refined by
!> secant iterations on exact single rk8pd steps from the step's start, so that the
!> event carries the integrator's accuracy and costs a few steps, not a re-integration.
!>
!> It solves z'' + alpha z' + z^{3/2} = 0, z(0) = 0, z'(0) = 1 from tau0 on, with the
!> start values of the local series z = (1 - exp(-alpha tau))/alpha - (4/35) tau^(7/2)
!> + (23/315) alpha tau^(9/2) + O(tau^(11/2)) (z^{3/2} is not smooth at 0).  The
!> force end is where z'' = -alpha z' - z^{3/2} returns to zero.  A trial that has not
!> ended by tau = 200 counts as no rebound (tau_c < 15 for every e >= 1e-3 of the
!> overlap end).
!>
!> Test reference and benchmark peer only: it needs libgsl and is no part of the core.
!> No module state: each solve allocates its own GSL objects.
module hertzdamp_gsl_secant
    use, intrinsic :: iso_c_binding, only: c_int, c_long, c_double, c_size_t, c_ptr, c_funptr, c_null_ptr, &
                                           c_null_funptr, c_funloc, c_loc, c_f_pointer, c_associated
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_NO_REBOUND, HD_MAX_STEPS, HD_BAD_ARGUMENT, HD_BAD_END, HD_BAD_TOL, &
                         HD_BAD_RESTITUTION, HD_NO_CONVERGENCE, HD_END_OVERLAP, HD_END_FORCE, hertzdamp_tau_c0, &
                         hertzdamp_e1, hertzdamp_secant, hertzdamp_secant_start, hertzdamp_secant_next, &
                         hertzdamp_fit_e_min_overlap, hertzdamp_fit_e_min_force
    use hertzdamp_gsl_c, only: gsl_odeiv2_system, gsl_odeiv2_step_rk8pd, gsl_set_error_handler_off, &
        gsl_odeiv2_step_alloc, gsl_odeiv2_step_apply, gsl_odeiv2_step_free, gsl_odeiv2_control_y_new, &
        gsl_odeiv2_control_free, gsl_odeiv2_evolve_alloc, gsl_odeiv2_evolve_apply, gsl_odeiv2_evolve_free
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    public :: hertzdamp_gsl_secant_invert, hertzdamp_gsl_rk8pd_collision

    !> Largest number of accepted steps of one solve.
    integer, parameter :: max_steps = 200000
    !> A trial that has not ended by this time did not rebound.
    real(wp), parameter :: t_no_rebound = 200.0_wp
    !> Start of the integration (the local series is exact to ~1e-22 there).
    real(wp), parameter :: tau0 = 1.0e-4_wp


    !> What the right-hand side receives through `params`.
    type, bind(C) :: ode_params
        real(c_double) :: alpha = 0.0_c_double
        integer(c_long) :: nevals = 0_c_long
    end type ode_params


contains

    !> z' = v, v' = -alpha v - z^{3/2} (odd continuation for z < 0, where only the
    !> stages of the step that ends the contact look).
    function ode_rhs(t, y, dydt, params) bind(C) result(rc)
        real(c_double), value :: t
        real(c_double), intent(in) :: y(2)
        real(c_double), intent(out) :: dydt(2)
        type(c_ptr), value :: params
        integer(c_int) :: rc
        type(ode_params), pointer :: p
        call c_f_pointer(params, p)
        p%nevals = p%nevals + 1
        dydt(1) = y(2)
        dydt(2) = -p%alpha * y(2) - sign(abs(y(1)) * sqrt(abs(y(1))), y(1))
        rc = 0_c_int
        ! (autonomous: t only checked) GSL_EBADFUNC on anything not finite
        if (.not. (abs(t) <= huge(t) .and. abs(dydt(1)) <= huge(t) .and. abs(dydt(2)) <= huge(t))) rc = 9_c_int
    end function ode_rhs

    !> The event function: z (overlap end) or z'' (force end); > 0 before the end.
    pure real(wp) function event_g(force, alpha, y)
        logical, intent(in) :: force
        real(wp), intent(in) :: alpha, y(2)
        if (force) then
            event_g = alpha * y(2) + sign(abs(y(1)) * sqrt(abs(y(1))), y(1))     ! -z''
        else
            event_g = y(1)
        end if
    end function event_g

    !> The quintic Hermite interpolant of a step [t0, t0 + h] from z, z', z'' at both
    !> ends, evaluated at s = (t - t0)/h in [0, 1]: z and z'.
    pure subroutine hermite5(s, h, y0, a0, y1, a1, z, v)
        real(wp), intent(in) :: s, h, y0(2), a0, y1(2), a1
        real(wp), intent(out) :: z, v
        real(wp) :: s2, s3, s4, s5, h00, h10, h20, h01, h11, h21, d00, d10, d20, d01, d11, d21
        s2 = s * s
        s3 = s2 * s
        s4 = s3 * s
        s5 = s4 * s
        ! quintic Hermite basis (value, first and second derivative at 0 and 1)
        h00 = 1.0_wp - 10.0_wp * s3 + 15.0_wp * s4 - 6.0_wp * s5
        h10 = s - 6.0_wp * s3 + 8.0_wp * s4 - 3.0_wp * s5
        h20 = 0.5_wp * (s2 - 3.0_wp * s3 + 3.0_wp * s4 - s5)
        h01 = 10.0_wp * s3 - 15.0_wp * s4 + 6.0_wp * s5
        h11 = -4.0_wp * s3 + 7.0_wp * s4 - 3.0_wp * s5
        h21 = 0.5_wp * (s3 - 2.0_wp * s4 + s5)
        d00 = -30.0_wp * s2 + 60.0_wp * s3 - 30.0_wp * s4
        d10 = 1.0_wp - 18.0_wp * s2 + 32.0_wp * s3 - 15.0_wp * s4
        d20 = 0.5_wp * (2.0_wp * s - 9.0_wp * s2 + 12.0_wp * s3 - 5.0_wp * s4)
        d01 = 30.0_wp * s2 - 60.0_wp * s3 + 30.0_wp * s4
        d11 = -12.0_wp * s2 + 28.0_wp * s3 - 15.0_wp * s4
        d21 = 0.5_wp * (3.0_wp * s2 - 8.0_wp * s3 + 5.0_wp * s4)
        z = h00 * y0(1) + h * h10 * y0(2) + h * h * h20 * a0 + h01 * y1(1) + h * h11 * y1(2) + h * h * h21 * a1
        v = (d00 * y0(1) + h * d10 * y0(2) + h * h * d20 * a0 + d01 * y1(1) + h * d11 * y1(2) &
             + h * h * d21 * a1) / h
    end subroutine hermite5

    !> One collision by rk8pd under relative error control at `tol` (absolute tolerance
    !> 1e-30 tol): e = -z'(tau_c) and tau_c.  status HD_OK, HD_NO_REBOUND, HD_MAX_STEPS or
    !> HD_NO_CONVERGENCE (a GSL failure); rhs_evals counts every evaluation.
    subroutine hertzdamp_gsl_rk8pd_collision(alpha, iend, tol, e, tau_c, status, rhs_evals)
        real(wp), intent(in) :: alpha      !! damping parameter, >= 0
        integer, intent(in) :: iend        !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(in) :: tol        !! relative tolerance of the integrator
        real(wp), intent(out) :: e         !! restitution coefficient
        real(wp), intent(out) :: tau_c     !! dimensionless contact duration
        integer, intent(out) :: status     !! HD_OK or the reason
        integer, intent(out) :: rhs_evals  !! right-hand-side evaluations
        type(ode_params), target :: par
        type(gsl_odeiv2_system) :: sys
        type(c_ptr) :: step, control, evolve
        type(c_funptr) :: old_handler
        real(c_double) :: t, h, y(2), t0, y0(2), f0(2), f1(2), yerr(2), ys(2), fs(2)
        real(wp) :: g0, g1, s, slo, shi, z, v, gs, ta, ga, tb, gb, tn
        integer :: nsteps, it
        logical :: force
        integer(c_int) :: rc
        e = 0.0_wp
        tau_c = 0.0_wp
        rhs_evals = 0
        status = HD_NO_CONVERGENCE
        force = iend == HD_END_FORCE
        old_handler = gsl_set_error_handler_off()
        par%alpha = real(alpha, c_double)
        sys%function = c_funloc(ode_rhs)
        sys%jacobian = c_null_funptr
        sys%dimension = 2_c_size_t
        sys%params = c_loc(par)
        step = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2_c_size_t)
        control = gsl_odeiv2_control_y_new(real(1.0e-30_wp * tol, c_double), real(tol, c_double))
        evolve = gsl_odeiv2_evolve_alloc(2_c_size_t)
        if (c_associated(step) .and. c_associated(control) .and. c_associated(evolve)) then
            ! start values from the local series at tau0
            t = tau0
            y(1) = -expm1_over(alpha, tau0) - 4.0_wp / 35.0_wp * tau0**3.5_wp &
                   + 23.0_wp / 315.0_wp * alpha * tau0**4.5_wp
            y(2) = exp(-alpha * tau0) - 0.4_wp * tau0**2.5_wp + 23.0_wp / 70.0_wp * alpha * tau0**3.5_wp
            h = tau0
            nsteps = 0
            march: do
                if (nsteps >= max_steps) then
                    status = HD_MAX_STEPS
                    exit march
                end if
                t0 = t
                y0 = y
                rc = gsl_odeiv2_evolve_apply(evolve, control, step, sys, t, real(t_no_rebound, c_double), h, y)
                nsteps = nsteps + 1
                if (rc /= 0_c_int) exit march
                g1 = event_g(force, alpha, y)
                ! the overlap end only after the turning point (z' < 0)
                if (g1 <= 0.0_wp .and. (force .or. y(2) < 0.0_wp)) then
                    ! bracket [t0, t]: quintic Hermite estimate, then exact steps from t0
                    rc = ode_rhs(t0, y0, f0, c_loc(par))
                    rc = ode_rhs(t, y, f1, c_loc(par))
                    g0 = event_g(force, alpha, y0)
                    slo = 0.0_wp
                    shi = 1.0_wp
                    s = g0 / (g0 - g1)
                    do it = 1, 60
                        call hermite5(s, t - t0, y0, f0(2), y, f1(2), z, v)
                        gs = event_g(force, alpha, [z, v])
                        if (gs > 0.0_wp) then
                            slo = s
                        else
                            shi = s
                        end if
                        if (shi - slo <= 1.0e-15_wp) exit
                        s = 0.5_wp * (slo + shi)
                    end do
                    ! secant on exact single steps of length ta - t0 (within the accepted step)
                    ta = t0 + s * (t - t0)
                    ga = exact_g(ta)
                    tb = t
                    gb = g1
                    do it = 1, 20
                        if (abs(ga) <= 1.0e-16_wp .or. ga == gb) exit
                        tn = ta - ga * (ta - tb) / (ga - gb)
                        if (.not. (tn > t0 .and. tn <= t)) tn = 0.5_wp * (t0 + t)
                        tb = ta
                        gb = ga
                        ta = tn
                        ga = exact_g(ta)
                        if (abs(ta - tb) <= 1.0e-15_wp * ta) exit
                    end do
                    tau_c = ta
                    e = -ys(2)
                    status = HD_OK
                    exit march
                end if
                if (t >= t_no_rebound) then
                    status = merge(HD_MAX_STEPS, HD_NO_REBOUND, force)
                    exit march
                end if
            end do march
        end if
        if (c_associated(evolve)) call gsl_odeiv2_evolve_free(evolve)
        if (c_associated(control)) call gsl_odeiv2_control_free(control)
        if (c_associated(step)) call gsl_odeiv2_step_free(step)
        rhs_evals = int(par%nevals)
    contains
        !> The event function after one exact rk8pd step from (t0, y0) to tt; the state in ys.
        real(wp) function exact_g(tt)
            real(wp), intent(in) :: tt
            ys = y0
            rc = ode_rhs(t0, y0, f0, c_loc(par))
            rc = gsl_odeiv2_step_apply(step, t0, tt - t0, ys, yerr, f0, fs, sys)
            exact_g = event_g(force, alpha, ys)
        end function exact_g
    end subroutine hertzdamp_gsl_rk8pd_collision

    !> -(1 - exp(-alpha t))/alpha without cancellation (t at small alpha).
    pure real(wp) function expm1_over(alpha, t)
        real(wp), intent(in) :: alpha, t
        if (abs(alpha * t) < 1.0e-8_wp) then
            expm1_over = -t * (1.0_wp - 0.5_wp * alpha * t)
        else
            expm1_over = -(1.0_wp - exp(-alpha * t)) / alpha
        end if
    end function expm1_over

    !> alpha(e) and tau_c by the secant of the core over rk8pd solves (see the module).
    !> status as hertzdamp_invert_alpha; solves and rhs_evals count the work.
    subroutine hertzdamp_gsl_secant_invert(e, iend, tol, alpha, tau_c, status, solves, rhs_evals)
        real(wp), intent(in) :: e          !! target restitution coefficient
        integer, intent(in) :: iend        !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(in) :: tol        !! relative accuracy asked of alpha, in [1e-14, 1e-2]
        real(wp), intent(out) :: alpha     !! damping parameter
        real(wp), intent(out) :: tau_c     !! dimensionless contact duration
        integer, intent(out) :: status     !! HD_OK or an error code
        integer, intent(out) :: solves     !! collisions solved
        integer, intent(out) :: rhs_evals  !! right-hand-side evaluations in all
        type(hertzdamp_secant) :: state
        real(wp) :: lt, rtol, a, ee, tt
        integer :: st, nrhs
        logical :: done
        alpha = 0.0_wp
        tau_c = 0.0_wp
        solves = 0
        rhs_evals = 0
        status = HD_OK
        if (iend /= HD_END_OVERLAP .and. iend /= HD_END_FORCE) then
            status = HD_BAD_END
            return
        end if
        if (.not. (e >= merge(hertzdamp_fit_e_min_overlap, hertzdamp_fit_e_min_force, iend == HD_END_OVERLAP) &
                   .and. e <= 1.0_wp)) then
            status = HD_BAD_RESTITUTION
            return
        end if
        if (.not. (tol >= 1.0e-14_wp .and. tol <= 1.0e-2_wp)) then
            status = HD_BAD_TOL
            return
        end if
        lt = -log(e)
        if (lt < 1.0e-10_wp) then
            ! the elastic limit within the resolution of any integrator
            alpha = lt / hertzdamp_e1()
            tau_c = hertzdamp_tau_c0()
            return
        end if
        rtol = max(1.0e-15_wp, min(1.0e-3_wp, 0.1_wp * tol * min(1.0_wp, lt)))
        call hertzdamp_secant_start(e, iend, tol, state, a)
        do
            call hertzdamp_gsl_rk8pd_collision(a, iend, rtol, ee, tt, st, nrhs)
            solves = solves + 1
            rhs_evals = rhs_evals + nrhs
            if (st /= HD_OK .and. st /= HD_NO_REBOUND) then
                status = st
                return
            end if
            if (st == HD_OK) then
                alpha = a
                tau_c = tt
            end if
            call hertzdamp_secant_next(state, ee, st == HD_NO_REBOUND, a, done, status)
            if (done .or. status /= HD_OK) exit
        end do
        if (status /= HD_OK) then
            alpha = 0.0_wp
            tau_c = 0.0_wp
        end if
    end subroutine hertzdamp_gsl_secant_invert

end module hertzdamp_gsl_secant
