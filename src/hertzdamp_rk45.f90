!> The reference integrator: adaptive Dormand-Prince 5(4) for one damped Hertz collision.
!>
!> Solves  z'' + alpha z' + z^(3/2) = 0,  z(0) = 0, z'(0) = 1  (doc/theory.md section 2)
!> and returns e, tau_c, z_max, tau_max for either contact-end definition.
!>
!> How the non-smooth points are handled (doc/theory.md section 5):
!> - Start: z^(3/2) is not smooth at z = 0, so the integration starts at
!>   tau0 = 0.1 min(1, 1/|alpha|) from the local series z = tau sum_k p_k tau^(k/2)
!>   (`local_series`), accurate to round-off there.
!> - Steps: Dormand-Prince 5(4) with local extrapolation, Hairer's PI step-size
!>   controller, the 4th-order continuous extension as dense output.
!> - Events are found on the dense output of the accepted step by a bracketing
!>   root finder (Illinois), then polished: one Dormand-Prince sub-step from the
!>   start of the accepted step to the located time, and a Newton correction.
!> - End (overlap): the last part of the rebound is not integrated.  When the
!>   remaining time z/|z'| falls below sigma_sw, the state is matched to the local
!>   series of the time-reversed collision (damping -alpha, impact speed e) and the
!>   contact end follows from that match: no step ever crosses z = 0.
!> - End (force): the total force -alpha z' - z^(3/2) returning to zero happens at
!>   z > 0; it is located on the dense output, or inside the matched end series
!>   when it happens after the switch.
!> - No rebound (overlap, alpha >= alpha_c): once 0 < z <= alpha^4/36 and
!>   -(2/alpha) z^(3/2) <= z' <= 0, the region is invariant and z' >= -(2/alpha) z^(3/2)
!>   keeps z > 0 for all time: status HD_NO_REBOUND in bounded work.
module hertzdamp_rk45
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_OK, HD_NO_REBOUND, HD_MAX_STEPS, HD_STEP_UNDERFLOW, &
                                HD_BAD_ALPHA, HD_BAD_END, HD_BAD_TOL, HD_NO_CONVERGENCE, &
                                HD_END_OVERLAP, HD_END_FORCE
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_positive_inf
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Default tolerance of the reference integrator (relative; the absolute one is 1e-30 of it).
    real(wp), parameter, public :: hertzdamp_rk45_default_tol = 1.0e-13_wp
    !> Smallest alpha accepted for the overlap definition (energy-injecting contacts).
    real(wp), parameter, public :: hertzdamp_alpha_min = -10.0_wp
    !> Largest alpha accepted (beyond it z_max ~ 1/alpha leaves the exponent range).
    real(wp), parameter, public :: hertzdamp_alpha_max = 1.0e100_wp

    !> Right-hand sides the stepper knows (no callbacks: the hot loop stays inlinable).
    integer, parameter, public :: HD_MODEL_HERTZ = 0   !! z'' + alpha z' + sign(z)|z|^(3/2) = 0
    integer, parameter, public :: HD_MODEL_LINEAR = 1  !! z'' + alpha z' + z = 0 (test problem, exact solution known)
    !> The Hertz model in the state (z, F), F = -alpha z' - z^(3/2) the total force, alpha > 0.
    !> Used after the turning point for the force definition with alpha >= 1: the force
    !> is integrated rather than formed by cancellation, so its zero is well conditioned.
    integer, parameter, public :: HD_MODEL_FORCE = 2

    !> Work counters of one integration.
    type, public :: hertzdamp_rk45_stats
        integer :: steps = 0       !! accepted steps
        integer :: rejected = 0    !! rejected steps
        integer :: rhs_evals = 0   !! right-hand-side evaluations (including event polishing)
    end type hertzdamp_rk45_stats

    !> Integrator settings.
    type, public :: hertzdamp_rk45_options
        real(wp) :: rtol = hertzdamp_rk45_default_tol         !! relative tolerance per step
        real(wp) :: atol = 1.0e-30_wp * hertzdamp_rk45_default_tol !! absolute tolerance per step (tiny: relative control)
        integer :: max_steps = 100000                          !! step guard (accepted + rejected)
    end type hertzdamp_rk45_options

    !> Local series at a zero of the overlap (see hertzdamp_local_series).
    type, public :: hertzdamp_local_series_t
        integer :: kmax                       !! highest power kept
        real(wp) :: kappa                     !! scale of sqrt(s) in the powers
        real(wp) :: p(0:40)                   !! coefficients (only 0..kmax are set)
    end type hertzdamp_local_series_t

    !> Result of one collision in similarity variables.
    type, public :: hertzdamp_collision
        real(wp) :: alpha = 0.0_wp     !! damping parameter
        integer :: iend = HD_END_OVERLAP !! contact-end definition used
        real(wp) :: e = 0.0_wp         !! restitution coefficient -z'(tau_c)
        real(wp) :: tau_c = 0.0_wp     !! contact duration
        real(wp) :: z_max = 0.0_wp     !! deepest overlap
        real(wp) :: tau_max = 0.0_wp   !! time of deepest overlap
        integer :: status = HD_OK      !! HD_OK, HD_NO_REBOUND or an error code
        type(hertzdamp_rk45_stats) :: stats  !! work done
    end type hertzdamp_collision

    public :: hertzdamp_rk45_collide, hertzdamp_rk45_solve, hertzdamp_alpha_c
    public :: hertzdamp_rk45_tolerances
    public :: hertzdamp_local_series, hertzdamp_series_state
    public :: hertzdamp_dp_step, hertzdamp_dp_dense

    ! Dormand-Prince 5(4) coefficients (Dormand & Prince 1980; Hairer, Norsett & Wanner, Table II.5.2).
    real(wp), parameter :: c2 = 1.0_wp/5, c3 = 3.0_wp/10, c4 = 4.0_wp/5, c5 = 8.0_wp/9
    real(wp), parameter :: a21 = 1.0_wp/5
    real(wp), parameter :: a31 = 3.0_wp/40, a32 = 9.0_wp/40
    real(wp), parameter :: a41 = 44.0_wp/45, a42 = -56.0_wp/15, a43 = 32.0_wp/9
    real(wp), parameter :: a51 = 19372.0_wp/6561, a52 = -25360.0_wp/2187, a53 = 64448.0_wp/6561, &
                           a54 = -212.0_wp/729
    real(wp), parameter :: a61 = 9017.0_wp/3168, a62 = -355.0_wp/33, a63 = 46732.0_wp/5247, &
                           a64 = 49.0_wp/176, a65 = -5103.0_wp/18656
    real(wp), parameter :: a71 = 35.0_wp/384, a73 = 500.0_wp/1113, a74 = 125.0_wp/192, &
                           a75 = -2187.0_wp/6784, a76 = 11.0_wp/84
    ! error coefficients b - bhat
    real(wp), parameter :: e1 = 71.0_wp/57600, e3 = -71.0_wp/16695, e4 = 71.0_wp/1920, &
                           e5 = -17253.0_wp/339200, e6 = 22.0_wp/525, e7 = -1.0_wp/40
    ! dense output (Hairer's dopri5 contd5)
    real(wp), parameter :: d1 = -12715105075.0_wp/11282082432.0_wp, d3 = 87487479700.0_wp/32700410799.0_wp, &
                           d4 = -10690763975.0_wp/1880347072.0_wp, d5 = 701980252875.0_wp/199316789632.0_wp, &
                           d6 = -1453857185.0_wp/822651844.0_wp, d7 = 69997945.0_wp/29380423.0_wp

    integer, parameter :: kmax_series = 40  !! highest power of sqrt(tau) kept in the local series
    real(wp), parameter :: sigma_fraction = 0.1_wp  !! start / switch time, in units of min(1, 1/|alpha|)

contains

    ! ------------------------------------------------------------------ right-hand side

    pure function rhs(model, alpha, y) result(f)
        integer, intent(in) :: model
        real(wp), intent(in) :: alpha, y(2)
        real(wp) :: f(2)
        real(wp) :: r
        select case (model)
        case (HD_MODEL_HERTZ)
            f(1) = y(2)
            f(2) = -alpha * y(2) - y(1) * sqrt(abs(y(1)))
        case (HD_MODEL_FORCE)
            ! state (z, F) with F = -alpha z' - z^(3/2) the total contact force
            r = sqrt(abs(y(1)))
            f(1) = -(y(2) + y(1) * r) / alpha
            f(2) = -alpha * y(2) - 1.5_wp * r * f(1)
        case default
            f(1) = y(2)
            f(2) = -alpha * y(2) - y(1)
        end select
    end function rhs

    ! ------------------------------------------------------------------ one step

    !> One Dormand-Prince step of size h from (t, y) with k1 = f(y).  Returns the
    !> 5th-order solution, f at it (FSAL), the error estimate and the dense-output
    !> coefficients of the step.  Six right-hand-side evaluations.
    pure subroutine hertzdamp_dp_step(model, alpha, y, k1, h, ynew, k7, err, cont)
        integer, intent(in) :: model      !! HD_MODEL_HERTZ or HD_MODEL_LINEAR
        real(wp), intent(in) :: alpha     !! damping parameter
        real(wp), intent(in) :: y(2)      !! state (z, z') at the start of the step
        real(wp), intent(in) :: k1(2)     !! right-hand side at y
        real(wp), intent(in) :: h         !! step size
        real(wp), intent(out) :: ynew(2)  !! 5th-order solution at t + h
        real(wp), intent(out) :: k7(2)    !! right-hand side at ynew
        real(wp), intent(out) :: err(2)   !! local error estimate (5th minus 4th order)
        real(wp), intent(out) :: cont(2, 5) !! dense-output coefficients (see hertzdamp_dp_dense)
        real(wp), dimension(2) :: k2, k3, k4, k5, k6, ydiff, bspl
        k2 = rhs(model, alpha, y + h * a21 * k1)
        k3 = rhs(model, alpha, y + h * (a31 * k1 + a32 * k2))
        k4 = rhs(model, alpha, y + h * (a41 * k1 + a42 * k2 + a43 * k3))
        k5 = rhs(model, alpha, y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4))
        k6 = rhs(model, alpha, y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5))
        ynew = y + h * (a71 * k1 + a73 * k3 + a74 * k4 + a75 * k5 + a76 * k6)
        k7 = rhs(model, alpha, ynew)
        err = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7)
        ydiff = ynew - y
        bspl = h * k1 - ydiff
        cont(:, 1) = y
        cont(:, 2) = ydiff
        cont(:, 3) = bspl
        cont(:, 4) = ydiff - h * k7 - bspl
        cont(:, 5) = h * (d1 * k1 + d3 * k3 + d4 * k4 + d5 * k5 + d6 * k6 + d7 * k7)
    end subroutine hertzdamp_dp_step

    !> Dense output of an accepted step at fraction theta in [0, 1] of the step.
    pure function hertzdamp_dp_dense(cont, theta) result(y)
        real(wp), intent(in) :: cont(2, 5)  !! coefficients from hertzdamp_dp_step
        real(wp), intent(in) :: theta       !! (t - t_n) / h
        real(wp) :: y(2)
        real(wp) :: th1
        th1 = 1.0_wp - theta
        y = cont(:, 1) + theta * (cont(:, 2) + th1 * (cont(:, 3) + theta * (cont(:, 4) + th1 * cont(:, 5))))
    end function hertzdamp_dp_dense

    ! ------------------------------------------------------------------ local series

    !> Coefficients of the local series at a zero of u:  u'' + a u' + u^(3/2) = 0,
    !> u(0) = 0, u'(0) = c > 0 has  u(s) = s sum_{k>=0} p_k (kappa sqrt(s))^k  with the
    !> scale kappa = max(1, sqrt|a|) (keeps the p_k of order one for strong damping).
    !> p_0 = c, p_1 = 0 and, with q = p^(3/2) (power-series power rule),
    !> p_{m+2} = -((a/kappa^2) p_m (1 + m/2) + q_{m-3} / kappa^5) / (((m+4)/2) ((m+2)/2)).
    pure subroutine hertzdamp_local_series(a, c, kmax, ser, dser)
        real(wp), intent(in) :: a          !! damping coefficient of the ODE
        real(wp), intent(in) :: c          !! velocity at the zero, > 0
        integer, intent(in) :: kmax        !! highest index computed (<= 40)
        type(hertzdamp_local_series_t), intent(out) :: ser !! the coefficients and the scale
        !> if present: the derivatives of the coefficients with respect to c (same scale),
        !> so that hertzdamp_series_state(dser, s) is d(u, u')/dc
        type(hertzdamp_local_series_t), intent(out), optional :: dser
        real(wp) :: q(0:kmax_series), dq(0:kmax_series), acc, dacc, ak, k5, wj
        integer :: k, j, m, kk
        logical :: deriv
        deriv = present(dser)
        kk = min(kmax, kmax_series)
        ser%kmax = kk
        ser%kappa = max(1.0_wp, sqrt(abs(a)))
        ak = a / ser%kappa**2
        k5 = 1.0_wp / ser%kappa**5
        ser%p(0:kk) = 0.0_wp
        q(0:kk) = 0.0_wp
        dq(0:kk) = 0.0_wp
        ser%p(0) = c
        q(0) = c * sqrt(c)
        if (deriv) then
            dser%kmax = kk
            dser%kappa = ser%kappa
            dser%p(0:kk) = 0.0_wp
            dser%p(0) = 1.0_wp
            dq(0) = 1.5_wp * sqrt(c)
        end if
        do k = 1, kk
            m = k - 2
            if (k >= 2) then
                acc = ak * ser%p(m) * (1.0_wp + 0.5_wp * m)
                if (k >= 5) acc = acc + q(max(k - 5, 0)) * k5
                ser%p(k) = -acc / (0.25_wp * (k + 2) * k)
                if (deriv) then
                    dacc = ak * dser%p(m) * (1.0_wp + 0.5_wp * m)
                    if (k >= 5) dacc = dacc + dq(max(k - 5, 0)) * k5
                    dser%p(k) = -dacc / (0.25_wp * (k + 2) * k)
                end if
            end if
            acc = 0.0_wp
            dacc = 0.0_wp
            do j = 1, k
                wj = 1.5_wp * j - (k - j)
                acc = acc + wj * ser%p(j) * q(k - j)
                if (deriv) dacc = dacc + wj * (dser%p(j) * q(k - j) + ser%p(j) * dq(k - j))
            end do
            q(k) = acc / (k * ser%p(0))
            if (deriv) dq(k) = (dacc - k * q(k)) / (k * ser%p(0))
        end do
    end subroutine hertzdamp_local_series

    !> Value and first derivative of the local series at s >= 0: (u(s), u'(s)).
    pure function hertzdamp_series_state(ser, s) result(y)
        type(hertzdamp_local_series_t), intent(in) :: ser !! from hertzdamp_local_series
        real(wp), intent(in) :: s          !! time from the zero of u
        real(wp) :: y(2)
        real(wp) :: r, su, sd
        integer :: k
        r = ser%kappa * sqrt(s)
        su = ser%p(ser%kmax)
        sd = ser%p(ser%kmax) * (1.0_wp + 0.5_wp * ser%kmax)
        do k = ser%kmax - 1, 0, -1
            su = su * r + ser%p(k)
            sd = sd * r + ser%p(k) * (1.0_wp + 0.5_wp * k)
        end do
        y(1) = s * su
        y(2) = sd
    end function hertzdamp_series_state

    !> Number of series terms for a tolerance.  At the start and switch times used here
    !> (kappa sqrt(s) <= 0.32) the terms p_k (kappa sqrt s)^k fall by at least a factor
    !> 0.15 per power for 0 < e <= 50 (measured over alpha in [-3, 20]); keep terms
    !> down to 1e-3 tol.
    pure integer function series_terms(tol) result(kmax)
        real(wp), intent(in) :: tol
        kmax = min(kmax_series, max(12, ceiling(log(1.0e-3_wp * tol) / log(0.15_wp))))
    end function series_terms

    ! ------------------------------------------------------------------ driver

    !> Relative and absolute step tolerances that a user tolerance `tol` stands for.
    pure subroutine hertzdamp_rk45_tolerances(tol, opts)
        real(wp), intent(in) :: tol                      !! user tolerance
        type(hertzdamp_rk45_options), intent(out) :: opts !! rtol = tol, atol = 1e-30 tol
        opts%rtol = tol
        opts%atol = 1.0e-30_wp * tol
    end subroutine hertzdamp_rk45_tolerances

    !> One collision with the reference integrator (flat call).
    pure elemental function hertzdamp_rk45_collide(alpha, iend, tol) result(res)
        real(wp), intent(in) :: alpha             !! damping parameter
        integer, intent(in), optional :: iend     !! HD_END_OVERLAP (default) or HD_END_FORCE
        real(wp), intent(in), optional :: tol     !! tolerance (default hertzdamp_rk45_default_tol)
        type(hertzdamp_collision) :: res
        type(hertzdamp_rk45_options) :: opts
        integer :: iend_
        iend_ = HD_END_OVERLAP
        if (present(iend)) iend_ = iend
        if (present(tol)) then
            if (.not. (tol >= 1.0e-15_wp .and. tol <= 1.0e-2_wp)) then
                res%alpha = alpha
                res%iend = iend_
                res%status = HD_BAD_TOL
                return
            end if
            call hertzdamp_rk45_tolerances(tol, opts)
        end if
        call hertzdamp_rk45_solve(alpha, iend_, opts, res)
    end function hertzdamp_rk45_collide

    !> One collision with the reference integrator and explicit options.
    pure subroutine hertzdamp_rk45_solve(alpha, iend, opts, res)
        real(wp), intent(in) :: alpha                    !! damping parameter
        integer, intent(in) :: iend                      !! HD_END_OVERLAP or HD_END_FORCE
        type(hertzdamp_rk45_options), intent(in) :: opts !! tolerances and step guard
        type(hertzdamp_collision), intent(out) :: res    !! e, tau_c, z_max, tau_max, status, stats

        type(hertzdamp_local_series_t) :: ser
        real(wp) :: t, h, hnew, hmax, y(2), k1(2), ynew(2), k7(2), errv(2), cont(2, 5)
        real(wp) :: sc(2), err, lerr, lfacold, fac11, fac, tscale, sigma_sw, theta_tp, th_g, th_f
        real(wp) :: tp(3), yc(2)
        integer :: kmax, phase, ntry, status, model
        logical :: force

        res%alpha = alpha
        res%iend = iend
        if (iend /= HD_END_OVERLAP .and. iend /= HD_END_FORCE) then
            res%status = HD_BAD_END
            return
        end if
        if (.not. ieee_is_finite(alpha)) then
            res%status = HD_BAD_ALPHA
            return
        end if
        if (alpha < hertzdamp_alpha_min .or. alpha > hertzdamp_alpha_max .or. &
            (iend == HD_END_FORCE .and. alpha < 0.0_wp)) then
            res%status = HD_BAD_ALPHA
            return
        end if
        if (.not. (opts%rtol > 0.0_wp .and. opts%atol > 0.0_wp)) then
            res%status = HD_BAD_TOL
            return
        end if
        force = iend == HD_END_FORCE .and. alpha > 0.0_wp

        ! start from the local series
        kmax = series_terms(opts%rtol)
        tscale = sigma_fraction * min(1.0_wp, 1.0_wp / max(abs(alpha), tiny(1.0_wp)))
        call hertzdamp_local_series(alpha, 1.0_wp, kmax, ser)
        t = tscale
        y = hertzdamp_series_state(ser, t)
        k1 = rhs(HD_MODEL_HERTZ, alpha, y)
        res%stats%rhs_evals = 1
        h = tscale
        ! Strong damping makes the problem stiff: keep alpha h inside the real stability
        ! interval of Dormand-Prince (about [-3.3, 0]) so that the fast mode decays
        ! instead of being carried at the stability limit at loose tolerances.
        hmax = huge(1.0_wp)
        if (alpha > 1.0_wp) hmax = 2.0_wp / alpha
        lfacold = log(1.0e-4_wp)
        phase = 1
        model = HD_MODEL_HERTZ
        sigma_sw = tscale

        ntry = 0
        do
            ntry = ntry + 1
            if (ntry > opts%max_steps) then
                res%status = HD_MAX_STEPS
                return
            end if
            if (h < 64.0_wp * epsilon(1.0_wp) * t) then
                res%status = HD_STEP_UNDERFLOW
                return
            end if
            call hertzdamp_dp_step(model, alpha, y, k1, h, ynew, k7, errv, cont)
            res%stats%rhs_evals = res%stats%rhs_evals + 6
            sc = opts%atol + opts%rtol * max(abs(y), abs(ynew))
            err = sqrt(0.5_wp * sum((errv / sc)**2))
            ! PI controller (Hairer's dopri5): h_new = h / (0.9^-1 err^0.17 / err_old^0.04),
            ! formed with one log and one exp per step instead of two powers
            lerr = log(max(err, 1.0e-300_wp))
            fac11 = exp(0.17_wp * lerr)
            if (err > 1.0_wp .or. .not. ieee_is_finite(err)) then
                res%stats%rejected = res%stats%rejected + 1
                if (.not. ieee_is_finite(err)) then
                    h = 0.1_wp * h
                else
                    h = h / min(5.0_wp, fac11 / 0.9_wp)
                end if
                cycle
            end if
            res%stats%steps = res%stats%steps + 1
            fac = exp(0.17_wp * lerr - 0.04_wp * lfacold)
            fac = max(0.1_wp, min(5.0_wp, fac / 0.9_wp))
            hnew = h / fac
            lfacold = max(lerr, log(1.0e-4_wp))

            theta_tp = 0.0_wp
            if (phase == 1 .and. ynew(2) <= 0.0_wp) then
                ! turning point inside this step
                theta_tp = locate(1, model, cont, alpha, 0.0_wp, 0.0_wp, 1.0_wp)
                call polish(1, model, t, y, k1, h, theta_tp, alpha, tp, res%stats, status)
                if (status /= HD_OK) then
                    res%status = status
                    return
                end if
                res%tau_max = tp(1)
                res%z_max = tp(2)
                phase = 2
                sigma_sw = tscale * min(1.0_wp, max(0.8_wp * tp(2)**2.5_wp, 1.0_wp)**(-0.1_wp))
            end if

            if (phase == 2) then
                th_f = 2.0_wp
                th_g = 2.0_wp
                if (force) then
                    if (event_value(2, model, ynew, alpha, 0.0_wp) >= 0.0_wp) then
                      th_f = locate(2, model, cont, alpha, 0.0_wp, theta_tp, 1.0_wp)
                    end if
                end if
                ! (z, F) state: for alpha >= 1 the force vanishes long before the switch
                ! (z <= sigma_sw |z'| with alpha |z'| < z^(3/2) needs z >= 100 alpha^4)
                if (model == HD_MODEL_HERTZ) then
                    if (event_value(3, model, ynew, alpha, sigma_sw) <= 0.0_wp) then
                      th_g = locate(3, model, cont, alpha, sigma_sw, theta_tp, 1.0_wp)
                    end if
                end if
                if (th_f <= th_g .and. th_f <= 1.0_wp) then
                    call end_at_force(model, t, y, k1, h, th_f, alpha, res)
                    return
                else if (th_g <= 1.0_wp) then
                    ! switch to the time-reversed local series for the end of contact
                    call sub_step(model, y, k1, th_g * h, alpha, yc, res%stats)
                    call finish_from_series(t + th_g * h, yc, alpha, force, kmax, res)
                    ! force event already passed in the matched region: locate it in the step
                    if (res%status == HD_NO_CONVERGENCE .and. force) then
                        ! only where the force really changes sign inside the step
                        if (event_value(2, model, ynew, alpha, 0.0_wp) >= 0.0_wp) then
                          call end_at_force(model, t, y, k1, h, locate(2, model, cont, alpha, 0.0_wp, theta_tp, 1.0_wp), &
                                              alpha, res)
                        end if
                    end if
                    return
                else if (iend == HD_END_OVERLAP .and. alpha > 0.0_wp) then
                    if (no_rebound_certified(ynew, alpha)) then
                        res%status = HD_NO_REBOUND
                        res%e = 0.0_wp
                        res%tau_c = ieee_value(1.0_wp, ieee_positive_inf)
                        return
                    end if
                end if
            end if

            if (phase == 2 .and. force .and. alpha >= 1.0_wp .and. model == HD_MODEL_HERTZ) then
                model = HD_MODEL_FORCE
                ynew(2) = -alpha * ynew(2) - ynew(1) * sqrt(ynew(1))
                k7 = rhs(model, alpha, ynew)
                res%stats%rhs_evals = res%stats%rhs_evals + 1
            end if
            t = t + h
            y = ynew
            k1 = k7
            h = min(hnew, hmax)
        end do
    end subroutine hertzdamp_rk45_solve

    !> Contact end at the zero of the total force, located at theta of the step.
    pure subroutine end_at_force(model, t, y, k1, h, theta, alpha, res)
        integer, intent(in) :: model
        real(wp), intent(in) :: t, y(2), k1(2), h, theta, alpha
        type(hertzdamp_collision), intent(inout) :: res
        real(wp) :: ev(3)
        call polish(2, model, t, y, k1, h, theta, alpha, ev, res%stats, res%status)
        if (res%status == HD_OK) then
            res%tau_c = ev(1)
            res%e = -ev(3)
        end if
    end subroutine end_at_force

    !> True once the state is in the invariant no-rebound region (see module header).
    pure logical function no_rebound_certified(y, alpha)
        real(wp), intent(in) :: y(2), alpha
        no_rebound_certified = y(1) > 0.0_wp .and. y(1) <= alpha**4 / 36.0_wp .and. &
            y(2) <= 0.0_wp .and. y(2) >= -(2.0_wp / alpha) * y(1) * sqrt(y(1))
    end function no_rebound_certified

    !> Event functions: 1 turning point z'; 2 total force -alpha z' - z^(3/2);
    !> 3 switch to the end series z - sigma_sw |z'|.
    pure real(wp) function event_value(kind, model, y, alpha, sigma_sw) result(g)
        integer, intent(in) :: kind, model
        real(wp), intent(in) :: y(2), alpha, sigma_sw
        select case (kind)
        case (1)
            g = y(2)
        case (2)
            if (model == HD_MODEL_FORCE) then
                g = y(2)
            else
                g = -alpha * y(2) - y(1) * sqrt(abs(y(1)))
            end if
        case default
            g = y(1) - sigma_sw * abs(y(2))
        end select
    end function event_value

    !> Illinois (modified regula falsi) root of an event function on the dense output,
    !> bracketed in [lo, hi] (the event function changes sign there).
    pure real(wp) function locate(kind, model, cont, alpha, sigma_sw, lo, hi) result(theta)
        integer, intent(in) :: kind, model
        real(wp), intent(in) :: cont(2, 5), alpha, sigma_sw, lo, hi
        real(wp) :: a, b, fa, fb, fc, c
        integer :: it, side
        a = lo
        b = hi
        fa = event_value(kind, model, hertzdamp_dp_dense(cont, a), alpha, sigma_sw)
        fb = event_value(kind, model, hertzdamp_dp_dense(cont, b), alpha, sigma_sw)
        theta = b
        if (fa == 0.0_wp) then
            theta = a
            return
        end if
        if (sign(1.0_wp, fa) == sign(1.0_wp, fb)) return
        side = 0
        do it = 1, 100
            c = (a * fb - b * fa) / (fb - fa)
            if (.not. (c > min(a, b) .and. c < max(a, b))) c = 0.5_wp * (a + b)
            fc = event_value(kind, model, hertzdamp_dp_dense(cont, c), alpha, sigma_sw)
            if (fc == 0.0_wp .or. abs(b - a) < 4.0_wp * epsilon(1.0_wp)) then
                theta = c
                return
            end if
            if (sign(1.0_wp, fc) == sign(1.0_wp, fb)) then
                b = c
                fb = fc
                if (side == -1) fa = 0.5_wp * fa
                side = -1
            else
                a = c
                fa = fc
                if (side == 1) fb = 0.5_wp * fb
                side = 1
            end if
            theta = c
            if (abs(b - a) < 1.0e-15_wp) return
        end do
    end function locate

    !> A Dormand-Prince step of size hs from (t, y): full accuracy at a located event.
    pure subroutine sub_step(model, y, k1, hs, alpha, ys, stats)
        integer, intent(in) :: model
        real(wp), intent(in) :: y(2), k1(2), hs, alpha
        real(wp), intent(out) :: ys(2)
        type(hertzdamp_rk45_stats), intent(inout) :: stats
        real(wp) :: k7(2), errv(2), cont(2, 5)
        if (hs <= 0.0_wp) then
            ys = y
            return
        end if
        call hertzdamp_dp_step(model, alpha, y, k1, hs, ys, k7, errv, cont)
        stats%rhs_evals = stats%rhs_evals + 6
    end subroutine sub_step

    !> Polish an event located at theta of the step (t, h): sub-steps plus Newton
    !> corrections until the correction is far below the step.  Returns
    !> out = (time, z, z') at the event.  kind 1: z' = 0; kind 2: total force = 0.
    pure subroutine polish(kind, model, t, y, k1, h, theta, alpha, out, stats, status)
        integer, intent(in) :: kind, model
        real(wp), intent(in) :: t, y(2), k1(2), h, theta, alpha
        real(wp), intent(out) :: out(3)
        type(hertzdamp_rk45_stats), intent(inout) :: stats
        integer, intent(out) :: status
        real(wp) :: th, ys(2), f(2), g, dg, delta
        integer :: it
        th = theta
        status = HD_NO_CONVERGENCE
        out = 0.0_wp
        do it = 1, 6
            call sub_step(model, y, k1, th * h, alpha, ys, stats)
            f = rhs(model, alpha, ys)
            stats%rhs_evals = stats%rhs_evals + 1
            if (model == HD_MODEL_FORCE) then
                g = ys(2)
                dg = f(2)
            else if (kind == 1) then
                g = ys(2)
                dg = f(2)
            else
                g = -alpha * ys(2) - ys(1) * sqrt(abs(ys(1)))
                dg = -alpha * f(2) - 1.5_wp * sqrt(abs(ys(1))) * ys(2)
            end if
            if (dg == 0.0_wp) then
                delta = 0.0_wp
            else
                delta = -g / dg
            end if
            if (abs(delta) <= 1.0e-6_wp * h .or. it == 6) then
                ! second-order Taylor correction to the exact event
                out(1) = t + th * h + delta
                out(2) = ys(1) + ys(2) * delta + 0.5_wp * f(2) * delta**2
                out(3) = ys(2) + f(2) * delta
                if (kind == 1) out(3) = 0.0_wp
                if (model == HD_MODEL_FORCE) then
                    out(2) = ys(1) + f(1) * delta
                    out(3) = -out(2) * sqrt(out(2)) / alpha
                end if
                status = HD_OK
                return
            end if
            th = th + delta / h
        end do
    end subroutine polish

    !> Match (z, z') at time t near the end to the local series of the time-reversed
    !> collision, w'' - alpha w' + w^(3/2) = 0, w(0) = 0, w'(0) = e, i.e.
    !> w(sigma) = z, w'(sigma) = -z', and read off the contact end.
    pure subroutine finish_from_series(t, y, alpha, force, kmax, res)
        real(wp), intent(in) :: t, y(2), alpha
        logical, intent(in) :: force
        integer, intent(in) :: kmax
        type(hertzdamp_collision), intent(inout) :: res
        type(hertzdamp_local_series_t) :: ser, dser
        real(wp) :: c, sigma, w(2), wc(2), r1, r2, dd, j11, j12, j21, j22, dc, ds, w1
        real(wp) :: x, lo, hi, phi, dphi, wx(2)
        integer :: it
        w1 = -y(2)
        res%status = HD_NO_CONVERGENCE
        if (y(1) <= 0.0_wp .or. w1 <= 0.0_wp) return
        c = max(w1 - alpha * y(1), 0.5_wp * w1)
        sigma = y(1) / c
        do it = 1, 40
            call hertzdamp_local_series(-alpha, c, kmax, ser, dser)
            w = hertzdamp_series_state(ser, sigma)
            wc = hertzdamp_series_state(dser, sigma)
            r1 = w(1) - y(1)
            r2 = w(2) - w1
            ! Newton with the exact Jacobian: d/dsigma from the ODE, d/dc from dser
            j11 = w(2)
            j21 = alpha * w(2) - w(1) * sqrt(w(1))
            j12 = wc(1)
            j22 = wc(2)
            dd = j11 * j22 - j12 * j21
            if (dd == 0.0_wp) return
            ds = (r1 * j22 - r2 * j12) / dd
            dc = (j11 * r2 - j21 * r1) / dd
            sigma = sigma - ds
            c = c - dc
            if (c <= 0.0_wp .or. sigma <= 0.0_wp) return
            if (abs(ds) <= 8.0_wp * epsilon(1.0_wp) * sigma .and. abs(dc) <= 8.0_wp * epsilon(1.0_wp) * c) exit
            ! quadratic convergence: once the corrections are tiny, one more step reaches round-off
            if (it > 1 .and. abs(ds) <= 1.0e-9_wp * sigma .and. abs(dc) <= 1.0e-9_wp * c) then
                call hertzdamp_local_series(-alpha, c, kmax, ser)
                w = hertzdamp_series_state(ser, sigma)
                sigma = sigma - ((w(1) - y(1)) * j22 - (w(2) - w1) * j12) / dd
                c = c - (j11 * (w(2) - w1) - j21 * (w(1) - y(1))) / dd
                exit
            end if
        end do
        if (it > 40) return
        call hertzdamp_local_series(-alpha, c, kmax, ser)
        if (.not. force) then
            res%tau_c = t + sigma
            res%e = c
            res%status = HD_OK
            return
        end if
        ! force definition: alpha w'(x) = w(x)^(3/2) for x in (0, sigma), safeguarded Newton
        lo = 0.0_wp
        hi = sigma
        wx = hertzdamp_series_state(ser, hi)
        if (alpha * wx(2) - wx(1) * sqrt(wx(1)) > 0.0_wp) return  ! event before the switch point
        x = min(sigma, (alpha * c)**(2.0_wp / 3.0_wp) / c)
        do it = 1, 100
            wx = hertzdamp_series_state(ser, x)
            phi = alpha * wx(2) - wx(1) * sqrt(wx(1))
            if (phi > 0.0_wp) then
                lo = x
            else
                hi = x
            end if
            dphi = alpha * (alpha * wx(2) - wx(1) * sqrt(wx(1))) - 1.5_wp * sqrt(wx(1)) * wx(2)
            if (dphi /= 0.0_wp) then
                dd = x - phi / dphi
            else
                dd = 0.5_wp * (lo + hi)
            end if
            if (.not. (dd > lo .and. dd < hi)) dd = 0.5_wp * (lo + hi)
            if (abs(dd - x) <= 4.0_wp * epsilon(1.0_wp) * max(x, tiny(1.0_wp)) .or. hi - lo <= epsilon(1.0_wp) * hi) then
                x = dd
                exit
            end if
            x = dd
        end do
        wx = hertzdamp_series_state(ser, x)
        res%tau_c = t + sigma - x
        res%e = wx(2)
        res%status = HD_OK
    end subroutine finish_from_series

    !> The critical damping alpha_c of the overlap definition: the smallest alpha
    !> without rebound, by bisection on the no-rebound test of the reference integrator.
    pure subroutine hertzdamp_alpha_c(alpha_c, status, tol)
        real(wp), intent(out) :: alpha_c          !! critical damping parameter
        integer, intent(out) :: status            !! HD_OK, or the integrator's failure
        real(wp), intent(in), optional :: tol     !! bisection width (default 1e-11)
        real(wp) :: lo, hi, mid, w
        type(hertzdamp_collision) :: r
        type(hertzdamp_rk45_options) :: opts
        w = 1.0e-11_wp
        if (present(tol)) w = tol
        alpha_c = 0.0_wp
        if (.not. (w >= 1.0e-14_wp .and. w <= 0.1_wp)) then
            status = HD_BAD_TOL     ! (a width below round-off would never end the bisection)
            return
        end if
        call hertzdamp_rk45_tolerances(1.0e-13_wp, opts)
        lo = 1.0_wp
        hi = 1.25_wp
        status = HD_OK
        do while (hi - lo > w)
            mid = 0.5_wp * (lo + hi)
            call hertzdamp_rk45_solve(mid, HD_END_OVERLAP, opts, r)
            select case (r%status)
            case (HD_OK)
                lo = mid
            case (HD_NO_REBOUND)
                hi = mid
            case default
                status = r%status
                exit
            end select
        end do
        alpha_c = 0.5_wp * (lo + hi)
    end subroutine hertzdamp_alpha_c

end module hertzdamp_rk45
