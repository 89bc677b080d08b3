!> The reference integrator: adaptive Dormand-Prince 5(4) for one damped Hertz collision.
!>
!> Solves  z'' + alpha z^q z' + z^(3/2) = 0,  z(0) = 0, z'(0) = 1  for the damping law
!> q = 0 (linear, the default), 1/4 (tsuji) or 1/2 (kuwabara-kono) (doc/damping-laws.md)
!> and returns e, tau_c, z_max, tau_max for either contact-end definition.
!>
!> How the non-smooth points are handled (doc/theory.md section 5):
!> - Start: z^(3/2) and z^q are not smooth at z = 0, so the integration starts at
!>   tau0 = rho0^N / kappa^N from the local series z = tau sum_k p_k (kappa tau^(1/N))^k
!>   (hertzdamp_local_series; N = 2, or 4 for tsuji; kappa = max(1, |alpha|^(1/(N(1+q))));
!>   rho0^2 = 0.1), accurate to round-off there.  For the linear law tau0 = 0.1 min(1, 1/|alpha|).
!> - Steps: Dormand-Prince 5(4) with local extrapolation, Hairer's PI step-size
!>   controller, the 4th-order continuous extension as dense output.
!> - Events are found on the dense output of the accepted step by a bracketing
!>   root finder (Illinois), then polished: one Dormand-Prince sub-step from the
!>   start of the accepted step to the located time, and a Newton correction.
!> - End (overlap): the last part of the rebound is not integrated.  When the
!>   remaining time z/|z'| falls below sigma_sw, the state is matched to the local
!>   series of the time-reversed collision (damping -alpha, impact speed e) and the
!>   contact end follows from that match: no step ever crosses z = 0.
!> - End (force): the total force -alpha z^q z' - z^(3/2) returning to zero happens at
!>   z > 0; it is located on the dense output, or inside the matched end series
!>   when it happens after the switch.
!> - No rebound (overlap end), certified by a forward-invariant region on which z stays
!>   positive for all time (doc/damping-laws.md):
!>   linear:  0 < z <= alpha^4/36 and -(2/alpha) z^(3/2) <= z' <= 0;
!>   tsuji (alpha >= sqrt 5):  z > 0 and -(2 alpha/5) z^(5/4) <= z' <= 0;
!>   kuwabara-kono: none (the overlap returns for every alpha).
!> - Near alpha_c (linear, tsuji) the rebound decision and e are decided as documented
!>   at hertzdamp_rk45_solve: a fixed band below alpha_c reports HD_INACCURATE, so that
!>   the status is monotone in alpha.
module hertzdamp_rk45
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: HD_OK, HD_NO_REBOUND, HD_MAX_STEPS, HD_STEP_UNDERFLOW, HD_BAD_ALPHA, HD_BAD_END, &
                                HD_BAD_TOL, HD_NO_CONVERGENCE, HD_INACCURATE, HD_NOT_SUPPORTED, HD_BAD_LAW
    use hertzdamp_registry, only: HD_END_OVERLAP, HD_END_FORCE
    use hertzdamp_registry, only: HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO, hertzdamp_law_q
    use hertzdamp_laws, only: hertzdamp_law_status, hertzdamp_law_has_alpha_c, hertzdamp_alpha_c_tsuji, &
                              hertzdamp_tsuji_alpha
    use hertzdamp_fit_data, only: fit_alpha_c
    use hertzdamp_rk45_kernel, only: hertzdamp_rk45_stats, hertzdamp_local_series_t, HD_MODEL_HERTZ, &
                                     HD_MODEL_FORCE, HD_EVENT_TURN, HD_EVENT_FORCE, HD_EVENT_SWITCH, &
                                     hertzdamp_rhs, hertzdamp_zq, hertzdamp_dp_step, hertzdamp_local_series, &
                                     hertzdamp_series_state, hertzdamp_series_root, hertzdamp_series_kappa, &
                                     hertzdamp_event_value, hertzdamp_locate, hertzdamp_sub_step, &
                                     hertzdamp_polish, hertzdamp_kmax_series
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_positive_inf
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Default tolerance of the reference integrator (relative; the absolute one is 1e-30 of it).
    real(wp), parameter, public :: hertzdamp_rk45_default_tol = 1.0e-13_wp
    !> Smallest alpha accepted for the overlap definition (energy-injecting contacts).
    real(wp), parameter, public :: hertzdamp_alpha_min = -10.0_wp
    !> Largest alpha accepted (beyond it z_max ~ alpha^(-1/(1+q)) leaves the exponent range).
    real(wp), parameter, public :: hertzdamp_alpha_max = 1.0e100_wp
    !> Restitution below which the tsuji overlap end is reported as HD_INACCURATE instead
    !> of resolved: e = exp(-pi alpha / sqrt(5 - alpha^2)) vanishes like
    !> exp(-pi / sqrt(2 (1 - alpha/sqrt 5))), and the integrator follows it (relative
    !> error 1e-10 at e = 3e-31) down to about e = 1e-31 only (measured: doc/damping-laws.md).
    !> e = 1e-30 is alpha = sqrt(5) (1 - 1.03e-3).
    real(wp), parameter, public :: hertzdamp_rk45_e_floor_tsuji = 1.0e-30_wp

    public :: hertzdamp_rk45_stats

    !> Integrator settings.
    type, public :: hertzdamp_rk45_options
        real(wp) :: rtol = hertzdamp_rk45_default_tol         !! relative tolerance per step
        real(wp) :: atol = 1.0e-30_wp * hertzdamp_rk45_default_tol !! absolute tolerance per step (tiny: relative control)
        integer :: max_steps = 100000                          !! step guard (accepted + rejected)
    end type hertzdamp_rk45_options

    !> Result of one collision in similarity variables.
    type, public :: hertzdamp_collision
        real(wp) :: alpha = 0.0_wp     !! damping parameter
        integer :: iend = HD_END_OVERLAP !! contact-end definition used
        integer :: law = HD_DAMPING_LINEAR !! damping law used (HD_DAMPING_*)
        real(wp) :: e = 0.0_wp         !! restitution coefficient -z'(tau_c)
        real(wp) :: tau_c = 0.0_wp     !! contact duration
        real(wp) :: z_max = 0.0_wp     !! deepest overlap
        real(wp) :: tau_max = 0.0_wp   !! time of deepest overlap
        integer :: status = HD_OK      !! HD_OK, HD_NO_REBOUND or an error code
        type(hertzdamp_rk45_stats) :: stats  !! work done
    end type hertzdamp_collision

    public :: hertzdamp_rk45_collide, hertzdamp_rk45_solve, hertzdamp_alpha_c, hertzdamp_rk45_band
    public :: hertzdamp_rk45_tolerances, hertzdamp_law_alpha_c

    real(wp), parameter :: sigma_fraction = 0.1_wp  !! start / switch time, in units of min(1, 1/|alpha|) (N = 2)

    !> The state of one integration that the phases of solve_raw pass on.
    type :: rk45_state
        type(hertzdamp_local_series_t) :: ser  ! local series at the start
        integer :: kmax = 0                    ! its highest power (also of the end series)
        real(wp) :: tscale = 0.0_wp            ! start time, base of the switch time
        logical :: force = .false.             ! the contact ends at the zero of the force
        integer :: phase = 1                   ! 1 before the turning point, 2 after
        integer :: model = HD_MODEL_HERTZ      ! state (z, z') or, near the force end, (z, F)
        real(wp) :: sigma_sw = 0.0_wp          ! switch to the end series where z/|z'| < sigma_sw
        real(wp) :: t = 0.0_wp                 ! start of the current step
        real(wp) :: h = 0.0_wp                 ! its size
        real(wp) :: hnew = 0.0_wp              ! size of the next step (error control)
        real(wp) :: hmax = 0.0_wp              ! stiffness bound on the step size
        real(wp) :: lfacold = 0.0_wp           ! log of the last accepted error (PI controller)
        real(wp) :: y(2) = 0.0_wp              ! state at t
        real(wp) :: k1(2) = 0.0_wp             ! its derivative
        real(wp) :: ynew(2) = 0.0_wp           ! state at the end of the step
        real(wp) :: k7(2) = 0.0_wp             ! its derivative
        real(wp) :: cont(2, 5) = 0.0_wp        ! dense output of the step
        real(wp) :: theta_tp = 0.0_wp          ! turning point in the step (fraction of h), 0 if none
    end type rk45_state

contains

    !> Number of series terms for a tolerance.  At the start and switch times used here
    !> (kappa s^(1/N) <= 0.32) the terms p_k (kappa s^(1/N))^k of the N = 2 series fall by
    !> at least a factor 0.15 per power for 0 < e <= 50 (measured over alpha in [-3, 20]);
    !> keep terms down to 1e-3 tol.  The N = 4 series (tsuji) has every fifth term only,
    !> falling by at least 1e-3 per non-zero term: the same count of non-zero terms needs
    !> twice the index.
    pure integer function series_terms(tol, nroot) result(kmax)
        real(wp), intent(in) :: tol
        integer, intent(in) :: nroot
        kmax = min(40, max(12, ceiling(log(1.0e-3_wp * tol) / log(0.15_wp))))
        if (nroot == 4) kmax = min(hertzdamp_kmax_series, 2 * kmax)
    end function series_terms

    !> Start time of the integration (and base switch time to the end series).
    pure real(wp) function start_time(law, alpha) result(tscale)
        integer, intent(in) :: law
        real(wp), intent(in) :: alpha
        integer :: n
        real(wp) :: kappa
        if (law == HD_DAMPING_LINEAR) then
            tscale = sigma_fraction * min(1.0_wp, 1.0_wp / max(abs(alpha), tiny(1.0_wp)))
        else
            n = hertzdamp_series_root(law)
            kappa = hertzdamp_series_kappa(law, alpha)
            tscale = (sqrt(sigma_fraction) / kappa)**n
        end if
    end function start_time

    ! ------------------------------------------------------------------ driver

    !> Relative and absolute step tolerances that a user tolerance `tol` stands for.
    pure subroutine hertzdamp_rk45_tolerances(tol, opts)
        real(wp), intent(in) :: tol                      !! user tolerance
        type(hertzdamp_rk45_options), intent(out) :: opts !! rtol = tol, atol = 1e-30 tol
        opts%rtol = tol
        opts%atol = 1.0e-30_wp * tol
    end subroutine hertzdamp_rk45_tolerances

    !> One collision with the reference integrator (flat call).
    pure elemental function hertzdamp_rk45_collide(alpha, iend, tol, law) result(res)
        real(wp), intent(in) :: alpha             !! damping parameter
        integer, intent(in), optional :: iend     !! HD_END_OVERLAP (default) or HD_END_FORCE
        real(wp), intent(in), optional :: tol     !! tolerance (default hertzdamp_rk45_default_tol)
        integer, intent(in), optional :: law      !! HD_DAMPING_LINEAR (default), _TSUJI or _KUWABARA_KONO
        type(hertzdamp_collision) :: res
        type(hertzdamp_rk45_options) :: opts
        integer :: iend_
        iend_ = HD_END_OVERLAP
        if (present(iend)) iend_ = iend
        if (present(tol)) then
            if (.not. (tol >= 1.0e-15_wp .and. tol <= 1.0e-2_wp)) then
                res%alpha = alpha
                res%iend = iend_
                if (present(law)) res%law = law
                res%status = HD_BAD_TOL
                return
            end if
            call hertzdamp_rk45_tolerances(tol, opts)
        end if
        call hertzdamp_rk45_solve(alpha, iend_, opts, res, law)
    end function hertzdamp_rk45_collide

    !> Width of the band [alpha_c - w, alpha_c) below the critical damping of the overlap
    !> end in which hertzdamp_rk45_solve reports HD_INACCURATE, for relative tolerance
    !> rtol (0 for a law without alpha_c).  linear: e ~ 0.207 (alpha_c - alpha) near
    !> alpha_c, and the integrator's own rebound threshold (its numerical alpha_c) lies
    !> within 0.52 rtol of alpha_c (measured for rtol = 1e-2 ... 1e-12; below alpha_c at
    !> loose tolerances) and within 26 ulp for rtol <= 1e-13 (round-off): w = 4 rtol +
    !> 256 ulp(alpha_c) keeps a margin of 7.8 or more (doc/damping-laws.md).  tsuji: the
    !> band where the exact e is below hertzdamp_rk45_e_floor_tsuji.
    pure elemental real(wp) function hertzdamp_rk45_band(rtol, law) result(w)
        real(wp), intent(in) :: rtol              !! relative tolerance of the integrator
        integer, intent(in), optional :: law      !! HD_DAMPING_* (default linear)
        integer :: law_
        law_ = HD_DAMPING_LINEAR
        if (present(law)) law_ = law
        select case (law_)
        case (HD_DAMPING_LINEAR)
            w = 4.0_wp * rtol + 256.0_wp * spacing(hertzdamp_law_alpha_c(law_))
        case (HD_DAMPING_TSUJI)
            w = hertzdamp_alpha_c_tsuji - hertzdamp_tsuji_alpha(hertzdamp_rk45_e_floor_tsuji)
        case default
            w = 0.0_wp
        end select
    end function hertzdamp_rk45_band

    !> One collision with the reference integrator and explicit options.
    !>
    !> Overlap end of a law with a critical damping alpha_c (linear, tsuji): the rebound
    !> decision is made by alpha, so that it is monotone:
    !> - alpha >= alpha_c: HD_NO_REBOUND, e = 0, tau_c = +inf (z_max, tau_max computed);
    !> - alpha_c - w <= alpha < alpha_c, w = hertzdamp_rk45_band(rtol, law): HD_INACCURATE,
    !>   e = tau_c = 0: the collision rebounds, but with e below what the integrator
    !>   resolves (linear: e < 0.21 w, 9.5e-14 at the default tolerance; tsuji: e < 1e-30);
    !> - alpha < alpha_c - w: the integration decides (and rebounds); e and tau_c as computed.
    !> (linear: alpha_c is the generated constant hertzdamp_law_alpha_c; tsuji: sqrt 5.)
    pure subroutine hertzdamp_rk45_solve(alpha, iend, opts, res, law)
        real(wp), intent(in) :: alpha                    !! damping parameter
        integer, intent(in) :: iend                      !! HD_END_OVERLAP or HD_END_FORCE
        type(hertzdamp_rk45_options), intent(in) :: opts !! tolerances and step guard
        type(hertzdamp_collision), intent(out) :: res    !! e, tau_c, z_max, tau_max, status, stats
        integer, intent(in), optional :: law             !! HD_DAMPING_* (default linear)
        integer :: law_
        real(wp) :: ac
        law_ = HD_DAMPING_LINEAR
        if (present(law)) law_ = law
        call solve_raw(alpha, iend, opts, law_, res)
        if (res%status == HD_BAD_LAW .or. res%status == HD_BAD_END .or. res%status == HD_BAD_ALPHA .or. &
            res%status == HD_BAD_TOL) return
        if (iend /= HD_END_OVERLAP .or. .not. hertzdamp_law_has_alpha_c(law_) .or. alpha <= 0.0_wp) return
        ac = hertzdamp_law_alpha_c(law_)
        if (alpha >= ac) then
            res%status = HD_NO_REBOUND
            res%e = 0.0_wp
            res%tau_c = ieee_value(1.0_wp, ieee_positive_inf)
        else if (alpha >= ac - hertzdamp_rk45_band(opts%rtol, law_)) then
            res%status = HD_INACCURATE
            res%e = 0.0_wp
            res%tau_c = 0.0_wp
        end if
    end subroutine hertzdamp_rk45_solve

    !> The integration itself: the rebound decided by the trajectory (certificate or
    !> crossing), without the alpha_c rule of hertzdamp_rk45_solve.  Its phases: the
    !> argument checks, the start from the local series, then per step the Dormand-Prince
    !> step with its error control, the events of the accepted step (turning point, end of
    !> contact) and the move to the next step.
    pure subroutine solve_raw(alpha, iend, opts, law, res)
        real(wp), intent(in) :: alpha
        integer, intent(in) :: iend
        type(hertzdamp_rk45_options), intent(in) :: opts
        integer, intent(in) :: law
        type(hertzdamp_collision), intent(out) :: res
        type(rk45_state) :: s
        integer :: ntry
        logical :: accepted, done

        res%alpha = alpha
        res%iend = iend
        res%law = law
        res%status = arguments_status(alpha, iend, opts, law)
        if (res%status /= HD_OK) return
        call series_start(alpha, iend, opts%rtol, law, s, res%stats)
        ntry = 0
        do
            ntry = ntry + 1
            if (ntry > opts%max_steps) then
                res%status = HD_MAX_STEPS
                return
            end if
            if (s%h < 64.0_wp * epsilon(1.0_wp) * s%t) then
                res%status = HD_STEP_UNDERFLOW
                return
            end if
            call dp_step_controlled(alpha, opts, law, s, res%stats, accepted)
            if (.not. accepted) cycle
            call step_events(alpha, iend, law, s, res, done)
            if (done) return
            call next_step(alpha, law, s, res%stats)
        end do
    end subroutine solve_raw

    !> HD_OK, or why solve_raw cannot start: HD_BAD_LAW, HD_BAD_END, HD_BAD_ALPHA (not
    !> finite, outside [hertzdamp_alpha_min, hertzdamp_alpha_max], negative at the force
    !> end, tsuji at or below -sqrt(5)), HD_BAD_TOL (in this order).
    pure integer function arguments_status(alpha, iend, opts, law) result(status)
        real(wp), intent(in) :: alpha
        integer, intent(in) :: iend, law
        type(hertzdamp_rk45_options), intent(in) :: opts
        status = HD_OK
        if (hertzdamp_law_status(law) /= HD_OK) then
            status = HD_BAD_LAW
        else if (iend /= HD_END_OVERLAP .and. iend /= HD_END_FORCE) then
            status = HD_BAD_END
        else if (.not. ieee_is_finite(alpha)) then
            status = HD_BAD_ALPHA
        else if (alpha < hertzdamp_alpha_min .or. alpha > hertzdamp_alpha_max .or. &
                 (iend == HD_END_FORCE .and. alpha < 0.0_wp)) then
            status = HD_BAD_ALPHA
        else if (law == HD_DAMPING_TSUJI .and. alpha <= -hertzdamp_alpha_c_tsuji) then
            ! tsuji, alpha <= -sqrt(5): the energy-injecting contact never ends (the anti-damped
            ! oscillator of doc/damping-laws.md does not return; time reversal of alpha_c)
            status = HD_BAD_ALPHA
        else if (.not. (opts%rtol > 0.0_wp .and. opts%atol > 0.0_wp)) then
            status = HD_BAD_TOL
        end if
    end function arguments_status

    !> Phase 1 of solve_raw: the state at the start time tscale from the local series, the
    !> first step size and the bound that stiffness puts on it.
    pure subroutine series_start(alpha, iend, rtol, law, s, stats)
        real(wp), intent(in) :: alpha, rtol
        integer, intent(in) :: iend, law
        type(rk45_state), intent(out) :: s
        type(hertzdamp_rk45_stats), intent(inout) :: stats
        real(wp) :: q
        s%force = iend == HD_END_FORCE .and. alpha > 0.0_wp
        q = hertzdamp_law_q(law)
        s%kmax = series_terms(rtol, hertzdamp_series_root(law))
        s%tscale = start_time(law, alpha)
        call hertzdamp_local_series(law, alpha, 1.0_wp, s%kmax, s%ser)
        s%t = s%tscale
        s%y = hertzdamp_series_state(s%ser, s%t)
        s%k1 = hertzdamp_rhs(HD_MODEL_HERTZ, law, alpha, s%y)
        stats%rhs_evals = 1
        s%h = s%tscale
        ! Strong damping makes the problem stiff: keep h |lambda| inside the real stability
        ! interval of Dormand-Prince (about [-3.3, 0]), lambda = -alpha z^q the fast mode,
        ! so that it decays instead of being carried at the stability limit at loose
        ! tolerances.  z <= ((1+q)/alpha)^(1/(1+q)) bounds the overlap (the elastic force
        ! only shortens the compression), so alpha z^q <= alpha^(1/(1+q)) (1+q)^(q/(1+q)).
        s%hmax = huge(1.0_wp)
        if (alpha > 1.0_wp) then
            if (law == HD_DAMPING_LINEAR) then
                s%hmax = 2.0_wp / alpha
            else
                s%hmax = 2.0_wp / (alpha**(1.0_wp / (1.0_wp + q)) * (1.0_wp + q)**(q / (1.0_wp + q)))
            end if
        end if
        s%lfacold = log(1.0e-4_wp)
        s%phase = 1
        s%model = HD_MODEL_HERTZ
        s%sigma_sw = s%tscale
    end subroutine series_start

    !> One Dormand-Prince step of size s%h from s%t with its error control.  Accepted: the
    !> end state, its derivative and the dense output in s, the next step size in s%hnew
    !> (Hairer's PI controller).  Rejected: s%h reduced.
    pure subroutine dp_step_controlled(alpha, opts, law, s, stats, accepted)
        real(wp), intent(in) :: alpha
        type(hertzdamp_rk45_options), intent(in) :: opts
        integer, intent(in) :: law
        type(rk45_state), intent(inout) :: s
        type(hertzdamp_rk45_stats), intent(inout) :: stats
        logical, intent(out) :: accepted
        real(wp) :: errv(2), sc(2), err, lerr, fac11, fac
        call hertzdamp_dp_step(s%model, law, alpha, s%y, s%k1, s%h, s%ynew, s%k7, errv, s%cont)
        stats%rhs_evals = stats%rhs_evals + 6
        sc = opts%atol + opts%rtol * max(abs(s%y), abs(s%ynew))
        err = sqrt(0.5_wp * sum((errv / sc)**2))
        ! PI controller (Hairer's dopri5): h_new = h / (0.9^-1 err^0.17 / err_old^0.04),
        ! formed with one log and one exp per step instead of two powers
        lerr = log(max(err, 1.0e-300_wp))
        fac11 = exp(0.17_wp * lerr)
        accepted = .not. (err > 1.0_wp .or. .not. ieee_is_finite(err))
        if (.not. accepted) then
            stats%rejected = stats%rejected + 1
            if (.not. ieee_is_finite(err)) then
                s%h = 0.1_wp * s%h
            else
                s%h = s%h / min(5.0_wp, fac11 / 0.9_wp)
            end if
            return
        end if
        stats%steps = stats%steps + 1
        fac = exp(0.17_wp * lerr - 0.04_wp * s%lfacold)
        fac = max(0.1_wp, min(5.0_wp, fac / 0.9_wp))
        s%hnew = s%h / fac
        s%lfacold = max(lerr, log(1.0e-4_wp))
    end subroutine dp_step_controlled

    !> The events of an accepted step: the overlap growing without bound (kuwabara-kono,
    !> alpha < 0), the turning point (phase 1 -> 2), the end of contact (phase 2).  done
    !> when res is final.
    pure subroutine step_events(alpha, iend, law, s, res, done)
        real(wp), intent(in) :: alpha
        integer, intent(in) :: iend, law
        type(rk45_state), intent(inout) :: s
        type(hertzdamp_collision), intent(inout) :: res
        logical, intent(out) :: done
        done = .true.
        ! kuwabara-kono, alpha < 0: once z >= 16/alpha^4 and z' >= 2 z/|alpha| the overlap
        ! grows without bound (forward-invariant region, doc/damping-laws.md): the contact
        ! never ends (alpha below -1.3884, the time reversal of alpha -> infinity)
        if (s%phase == 1 .and. alpha < 0.0_wp .and. law == HD_DAMPING_KUWABARA_KONO) then
            if (s%ynew(1) >= 16.0_wp / alpha**4 .and. s%ynew(2) >= -2.0_wp * s%ynew(1) / alpha) then
                res%status = HD_BAD_ALPHA
                return
            end if
        end if
        s%theta_tp = 0.0_wp
        if (s%phase == 1 .and. s%ynew(2) <= 0.0_wp) then
            call turning_point(alpha, law, s, res)
            if (res%status /= HD_OK) return
        end if
        if (s%phase == 2) then
            call contact_end(alpha, iend, law, s, res, done)
            return
        end if
        done = .false.
    end subroutine step_events

    !> The turning point z' = 0 inside the accepted step: located on the dense output,
    !> polished, stored in res (tau_max, z_max); phase 2 begins, with the switch time to
    !> the end series.
    pure subroutine turning_point(alpha, law, s, res)
        real(wp), intent(in) :: alpha
        integer, intent(in) :: law
        type(rk45_state), intent(inout) :: s
        type(hertzdamp_collision), intent(inout) :: res
        real(wp) :: tp(3)
        integer :: status
        call hertzdamp_locate(HD_EVENT_TURN, s%model, law, s%cont, alpha, 0.0_wp, 0.0_wp, 1.0_wp, s%theta_tp, status)
        if (status == HD_OK) then
            call hertzdamp_polish(HD_EVENT_TURN, s%model, law, s%t, s%y, s%k1, s%h, s%theta_tp, alpha, tp, res%stats, &
                                  status)
        end if
        if (status /= HD_OK) then
            res%status = status
            return
        end if
        res%tau_max = tp(1)
        res%z_max = tp(2)
        s%phase = 2
        s%sigma_sw = s%tscale * min(1.0_wp, max(0.8_wp * tp(2)**2.5_wp, 1.0_wp)**(-0.1_wp))
    end subroutine turning_point

    !> Phase 2, the end of contact in the accepted step: the zero of the total force
    !> (force end) or the switch to the time-reversed local series, whichever comes first,
    !> located on the dense output; else (overlap end) the no-rebound certificate.  done
    !> when res is final.
    pure subroutine contact_end(alpha, iend, law, s, res, done)
        real(wp), intent(in) :: alpha
        integer, intent(in) :: iend, law
        type(rk45_state), intent(inout) :: s
        type(hertzdamp_collision), intent(inout) :: res
        logical, intent(out) :: done
        real(wp) :: th_g, th_f, yc(2)
        integer :: status
        done = .true.
        th_f = 2.0_wp
        th_g = 2.0_wp
        if (s%force) then
            if (hertzdamp_event_value(HD_EVENT_FORCE, s%model, law, s%ynew, alpha, 0.0_wp) >= 0.0_wp) then
                call hertzdamp_locate(HD_EVENT_FORCE, s%model, law, s%cont, alpha, 0.0_wp, s%theta_tp, 1.0_wp, &
                                      th_f, status)
                if (status /= HD_OK) then
                    res%status = status
                    return
                end if
            end if
        end if
        ! (z, F) state: for alpha >= 1 the force vanishes long before the switch
        ! (at z = sigma_sw |z'| the force is alpha z^(q+1)/sigma_sw - z^(3/2) > 0)
        if (s%model == HD_MODEL_HERTZ) then
            if (hertzdamp_event_value(HD_EVENT_SWITCH, s%model, law, s%ynew, alpha, s%sigma_sw) <= 0.0_wp) then
                call hertzdamp_locate(HD_EVENT_SWITCH, s%model, law, s%cont, alpha, s%sigma_sw, s%theta_tp, 1.0_wp, &
                                      th_g, status)
                if (status /= HD_OK) then
                    res%status = status
                    return
                end if
            end if
        end if
        if (th_f <= th_g .and. th_f <= 1.0_wp) then
            call end_at_force(s%model, law, s%t, s%y, s%k1, s%h, th_f, alpha, res)
            return
        else if (th_g <= 1.0_wp) then
            ! switch to the time-reversed local series for the end of contact
            call hertzdamp_sub_step(s%model, law, s%y, s%k1, th_g * s%h, alpha, yc, res%stats)
            call finish_from_series(s%t + th_g * s%h, yc, alpha, s%force, s%kmax, law, res)
            ! force event already passed in the matched region: locate it in the step
            if (res%status == HD_NO_CONVERGENCE .and. s%force) then
                ! only where the force really changes sign inside the step
                if (hertzdamp_event_value(HD_EVENT_FORCE, s%model, law, s%ynew, alpha, 0.0_wp) >= 0.0_wp) then
                    call hertzdamp_locate(HD_EVENT_FORCE, s%model, law, s%cont, alpha, 0.0_wp, s%theta_tp, 1.0_wp, &
                                          th_f, status)
                    if (status == HD_OK) then
                        call end_at_force(s%model, law, s%t, s%y, s%k1, s%h, th_f, alpha, res)
                    else
                        res%status = status
                    end if
                end if
            end if
            return
        else if (iend == HD_END_OVERLAP .and. alpha > 0.0_wp) then
            if (no_rebound_certified(s%ynew, alpha, law)) then
                res%status = HD_NO_REBOUND
                res%e = 0.0_wp
                res%tau_c = ieee_value(1.0_wp, ieee_positive_inf)
                return
            end if
        end if
        done = .false.
    end subroutine contact_end

    !> From the accepted step to the next: the (z, F) model once the force end is near
    !> (alpha >= 1), the state moved to the end of the step, the stiffness bound after the
    !> turning point, the step size.
    pure subroutine next_step(alpha, law, s, stats)
        real(wp), intent(in) :: alpha
        integer, intent(in) :: law
        type(rk45_state), intent(inout) :: s
        type(hertzdamp_rk45_stats), intent(inout) :: stats
        if (s%phase == 2 .and. s%force .and. alpha >= 1.0_wp .and. s%model == HD_MODEL_HERTZ) then
            s%model = HD_MODEL_FORCE
            s%ynew(2) = -alpha * hertzdamp_zq(law, s%ynew(1)) * s%ynew(2) - s%ynew(1) * sqrt(s%ynew(1))
            s%k7 = hertzdamp_rhs(s%model, law, alpha, s%ynew)
            stats%rhs_evals = stats%rhs_evals + 1
        end if
        s%t = s%t + s%h
        s%y = s%ynew
        s%k1 = s%k7
        ! after the turning point z only decreases (alpha > 0): the stiff rate alpha z^q
        ! at the step start bounds it for the whole step
        if (s%phase == 2 .and. alpha > 1.0_wp .and. law /= HD_DAMPING_LINEAR .and. s%model == HD_MODEL_HERTZ) then
            s%hmax = 2.0_wp / (alpha * hertzdamp_zq(law, s%y(1)))
        end if
        s%h = min(s%hnew, s%hmax)
    end subroutine next_step

    !> Contact end at the zero of the total force, located at theta of the step.
    pure subroutine end_at_force(model, law, t, y, k1, h, theta, alpha, res)
        integer, intent(in) :: model, law
        real(wp), intent(in) :: t, y(2), k1(2), h, theta, alpha
        type(hertzdamp_collision), intent(inout) :: res
        real(wp) :: ev(3)
        call hertzdamp_polish(HD_EVENT_FORCE, model, law, t, y, k1, h, theta, alpha, ev, res%stats, res%status)
        if (res%status == HD_OK) then
            res%tau_c = ev(1)
            res%e = -ev(3)
        end if
    end subroutine end_at_force

    !> True once the state is in the forward-invariant no-rebound region of the law (see
    !> the module header; derivation in doc/damping-laws.md).
    pure logical function no_rebound_certified(y, alpha, law)
        real(wp), intent(in) :: y(2), alpha
        integer, intent(in) :: law
        select case (law)
        case (HD_DAMPING_LINEAR)
            no_rebound_certified = y(1) > 0.0_wp .and. y(1) <= alpha**4 / 36.0_wp .and. &
                y(2) <= 0.0_wp .and. y(2) >= -(2.0_wp / alpha) * y(1) * sqrt(y(1))
        case (HD_DAMPING_TSUJI)
            ! wedge -lambda z^(5/4)/alpha <= z' <= 0 with lambda = 2 alpha^2/5, invariant for alpha >= sqrt 5
            no_rebound_certified = alpha >= hertzdamp_alpha_c_tsuji .and. y(1) > 0.0_wp .and. &
                y(2) <= 0.0_wp .and. y(2) >= -0.4_wp * alpha * y(1) * sqrt(sqrt(y(1)))
        case default
            no_rebound_certified = .false.
        end select
    end function no_rebound_certified

    !> Match (z, z') at time t near the end to the local series of the time-reversed
    !> collision, w'' - alpha w^q w' + w^(3/2) = 0, w(0) = 0, w'(0) = e, i.e.
    !> w(sigma) = z, w'(sigma) = -z', and read off the contact end.
    pure subroutine finish_from_series(t, y, alpha, force, kmax, law, res)
        real(wp), intent(in) :: t, y(2), alpha
        logical, intent(in) :: force
        integer, intent(in) :: kmax, law
        type(hertzdamp_collision), intent(inout) :: res
        type(hertzdamp_local_series_t) :: ser, dser
        real(wp) :: c, sigma, w(2), wc(2), r1, r2, dd, j11, j12, j21, j22, dc, ds, w1
        real(wp) :: x, lo, hi, phi, dphi, wx(2), q, zq
        integer :: it
        w1 = -y(2)
        q = hertzdamp_law_q(law)
        res%status = HD_NO_CONVERGENCE
        if (y(1) <= 0.0_wp .or. w1 <= 0.0_wp) return
        ! first guess: w' = c + alpha w^(1+q)/(1+q) + O(w^(5/2))
        if (law == HD_DAMPING_LINEAR) then
            c = max(w1 - alpha * y(1), 0.5_wp * w1)
        else
            c = max(w1 - alpha * y(1) * hertzdamp_zq(law, y(1)) / (1.0_wp + q), 0.5_wp * w1)
        end if
        sigma = y(1) / c
        do it = 1, 40
            call hertzdamp_local_series(law, -alpha, c, kmax, ser, dser)
            w = hertzdamp_series_state(ser, sigma)
            wc = hertzdamp_series_state(dser, sigma)
            r1 = w(1) - y(1)
            r2 = w(2) - w1
            ! Newton with the exact Jacobian: d/dsigma from the ODE, d/dc from dser
            j11 = w(2)
            if (law == HD_DAMPING_LINEAR) then
                j21 = alpha * w(2) - w(1) * sqrt(w(1))
            else
                j21 = alpha * hertzdamp_zq(law, w(1)) * w(2) - w(1) * sqrt(w(1))
            end if
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
                call hertzdamp_local_series(law, -alpha, c, kmax, ser)
                w = hertzdamp_series_state(ser, sigma)
                sigma = sigma - ((w(1) - y(1)) * j22 - (w(2) - w1) * j12) / dd
                c = c - (j11 * (w(2) - w1) - j21 * (w(1) - y(1))) / dd
                exit
            end if
        end do
        if (it > 40) return
        call hertzdamp_local_series(law, -alpha, c, kmax, ser)
        if (.not. force) then
            res%tau_c = t + sigma
            res%e = c
            res%status = HD_OK
            return
        end if
        ! force definition: alpha w^q w'(x) = w(x)^(3/2) for x in (0, sigma), safeguarded Newton
        lo = 0.0_wp
        hi = sigma
        wx = hertzdamp_series_state(ser, hi)
        if (alpha * hertzdamp_zq(law, wx(1)) * wx(2) - wx(1) * sqrt(wx(1)) > 0.0_wp) return  ! event before the switch
        ! first guess from w = c x: alpha c^(1+q) x^q = c^(3/2) x^(3/2)
        if (law == HD_DAMPING_LINEAR) then
            x = min(sigma, (alpha * c)**(2.0_wp / 3.0_wp) / c)
        else
            x = min(sigma, (alpha * c**(q - 0.5_wp))**(1.0_wp / (1.5_wp - q)))
        end if
        do it = 1, 100
            wx = hertzdamp_series_state(ser, x)
            zq = hertzdamp_zq(law, wx(1))
            phi = alpha * zq * wx(2) - wx(1) * sqrt(wx(1))
            if (phi > 0.0_wp) then
                lo = x
            else
                hi = x
            end if
            ! d/dx of alpha w^q w' - w^(3/2), with w'' = phi
            dphi = alpha * zq * phi - 1.5_wp * sqrt(wx(1)) * wx(2)
            if (law /= HD_DAMPING_LINEAR .and. wx(1) > 0.0_wp) dphi = dphi + alpha * q * (zq / wx(1)) * wx(2)**2
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
    !> without rebound.  linear: by bisection on the trajectory's own rebound decision
    !> (reference integrator at tolerance 1e-13: its decision threshold lies within a few
    !> ulp of alpha_c there, while tighter tolerances accumulate more round-off, 26 ulp
    !> at 1e-15; doc/damping-laws.md); tsuji: sqrt(5), exact
    !> (doc/damping-laws.md); kuwabara-kono: none, status HD_NOT_SUPPORTED, alpha_c = 0.
    pure subroutine hertzdamp_alpha_c(alpha_c, status, tol, law)
        real(wp), intent(out) :: alpha_c          !! critical damping parameter
        integer, intent(out) :: status            !! HD_OK, HD_NOT_SUPPORTED, HD_BAD_LAW or the integrator's failure
        real(wp), intent(in), optional :: tol     !! bisection width (default 1e-11), in [1e-15, 0.1]
        integer, intent(in), optional :: law      !! HD_DAMPING_* (default linear)
        real(wp) :: lo, hi, mid, w
        integer :: law_
        type(hertzdamp_collision) :: r
        type(hertzdamp_rk45_options) :: opts
        w = 1.0e-11_wp
        if (present(tol)) w = tol
        law_ = HD_DAMPING_LINEAR
        if (present(law)) law_ = law
        alpha_c = 0.0_wp
        if (.not. (w >= 1.0e-15_wp .and. w <= 0.1_wp)) then
            status = HD_BAD_TOL     ! (a width below round-off would never end the bisection)
            return
        end if
        status = hertzdamp_law_status(law_)
        if (status /= HD_OK) return
        if (law_ == HD_DAMPING_TSUJI) then
            alpha_c = hertzdamp_alpha_c_tsuji
            return
        else if (law_ /= HD_DAMPING_LINEAR) then
            status = HD_NOT_SUPPORTED
            return
        end if
        call hertzdamp_rk45_tolerances(hertzdamp_rk45_default_tol, opts)
        lo = 1.0_wp
        hi = 1.25_wp
        do while (hi - lo > w)
            mid = 0.5_wp * (lo + hi)
            call solve_raw(mid, HD_END_OVERLAP, opts, law_, r)
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

    !> Critical damping alpha_c of the overlap end: the smallest alpha without rebound.
    !> linear: 1.12798813552..., generated by gen/fit/gen_fit.f90 (hertzdamp_alpha_c's
    !> bisection on this integrator at tolerance 1e-15, data/fit_coefficients.csv); tsuji:
    !> sqrt(5) exactly; kuwabara-kono: none (the overlap always returns), huge(1.0).
    pure elemental real(wp) function hertzdamp_law_alpha_c(law) result(alpha_c)
        integer, intent(in) :: law   !! HD_DAMPING_*
        select case (law)
        case (HD_DAMPING_LINEAR)
            alpha_c = fit_alpha_c
        case (HD_DAMPING_TSUJI)
            alpha_c = hertzdamp_alpha_c_tsuji
        case default
            alpha_c = huge(1.0_wp)
        end select
    end function hertzdamp_law_alpha_c

end module hertzdamp_rk45
