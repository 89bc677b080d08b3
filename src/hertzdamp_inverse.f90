!> The dimensionless inverse of doc/theory.md section 6: from a target restitution e to
!> the constants of a material pair, alpha(e) and tau_c(alpha(e)), by a chosen method:
!> the fitted approximant (default, ~1e-13 relative, no iteration), the compact formula
!> (~1e-5 on e in [0.05, 1]), the series or its Pade summation, the first-order law, or a
!> secant iteration over reference-integrator solves (the baseline; slow).
!>
!> The dimensional inverse (k and d of a contact from these constants, the physical
!> bound, `hertzdamp_invert`) is the per-pair API's, hertzdamp_pair: the one place of
!> the k, d and t* formulas.
!>
!> For the damping law q (argument `law`: 0 linear, the default; 1 tsuji, q = 1/4;
!> 2 kuwabara-kono, q = 1/2; doc/damping-laws.md) the fit, the iterative method and the
!> first-order law serve every law; compact, series and Pade the linear law only.
!>
!> Supported restitution: e_min <= e <= 1 with e_min = 1e-3 (overlap; e -> 0 has
!> no finite contact time) and 1e-4 (force), for every method; outside:
!> HD_BAD_RESTITUTION.  e = 1 gives alpha = 0, tau_c = tau_c(0).
module hertzdamp_inverse
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: HD_OK, HD_BAD_RESTITUTION, HD_BAD_END, HD_BAD_TOL, HD_BAD_ARGUMENT, HD_NOT_SUPPORTED, &
                                HD_NO_CONVERGENCE, HD_NO_REBOUND, HD_OUTSIDE_VALIDITY, HD_INACCURATE
    use hertzdamp_registry, only: HD_END_OVERLAP, HD_END_FORCE
    use hertzdamp_constants, only: hertzdamp_e1, hertzdamp_tau_c0
    use hertzdamp_rk45, only: hertzdamp_collision, hertzdamp_rk45_collide, hertzdamp_law_alpha_c
    use hertzdamp_registry, only: HD_METHOD_SERIES, HD_METHOD_PADE, HD_METHOD_COMPACT, HD_METHOD_FIT, &
                                  HD_METHOD_ITERATIVE, HD_METHOD_RK45, HD_METHOD_FIRST_ORDER
    use hertzdamp_methods, only: hertzdamp_forward_alpha, hertzdamp_default_accuracy
    use hertzdamp_fit, only: hertzdamp_fit_inverse
    use hertzdamp_fit_laws, only: hertzdamp_fit_law_e_min
    use hertzdamp_registry, only: HD_DAMPING_LINEAR
    use hertzdamp_laws, only: hertzdamp_law_status, hertzdamp_law_has_alpha_c
    use hertzdamp_compact, only: hertzdamp_compact_inverse, hertzdamp_compact_e_min_overlap, &
                                 hertzdamp_compact_e_min_force
    use hertzdamp_series, only: hertzdamp_pade_alpha_max
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Default tolerance of the iterative method (relative, on alpha).
    real(wp), parameter, public :: hertzdamp_invert_default_tol = 1.0e-10_wp

    !> How hertzdamp_invert computes the constants alpha(e), tau_c(alpha(e)): the method and
    !> its settings (those of hertzdamp_invert_alpha), in one argument instead of three
    !> optional ones.  `hertzdamp_invert_options()` is the default: the fit.
    type, public :: hertzdamp_invert_options
        integer :: method = HD_METHOD_FIT                       !! HD_METHOD_FIT, _COMPACT, _SERIES, _PADE,
                                                                !! _FIRST_ORDER, _ITERATIVE or _RK45
        real(wp) :: tol = hertzdamp_invert_default_tol          !! iterative/rk45: relative accuracy of alpha,
                                                                !! in [1e-15, 1e-2]
        real(wp) :: accuracy = hertzdamp_default_accuracy       !! series, Pade: relative accuracy asked
    end type hertzdamp_invert_options

    !> State of the iterative inverse (hertzdamp_secant_start, hertzdamp_secant_next).
    type, public :: hertzdamp_secant
        real(wp) :: lt = 0.0_wp          !! -ln e of the target
        real(wp) :: tol = 0.0_wp         !! relative accuracy asked of alpha
        real(wp) :: lo = 0.0_wp          !! bracket: e(lo) > e
        real(wp) :: hi = huge(1.0_wp)    !! bracket: e(hi) < e or no rebound (when have_hi)
        real(wp) :: a0 = 0.0_wp          !! previous trial
        real(wp) :: g0 = 0.0_wp          !! its residual ln e(a0) - ln e
        real(wp) :: a1 = 0.0_wp          !! current trial
        logical :: have_hi = .false.
        logical :: have_prev = .false.
        integer :: trials = 0            !! trials evaluated
    end type hertzdamp_secant

    public :: hertzdamp_invert_alpha, hertzdamp_secant_start, hertzdamp_secant_next

contains

    !> The dimensionless inverse e -> (alpha, tau_c) by the chosen method.
    !> These are the constants of a material pair: they depend on e, the contact end and
    !> the damping law only (hertzdamp_pair_init, HERTZDAMP_PAIR, hertzdamp_c_pair).  Every
    !> law: fit (default), iterative / rk45, first-order; compact, series and Pade: linear
    !> law only.  Checked in this order: law, contact end, e, method and law, tol.
    pure elemental subroutine hertzdamp_invert_alpha(e, iend, alpha, tau_c, status, method, tol, accuracy, law)
        real(wp), intent(in) :: e                !! restitution coefficient, e_min <= e <= 1
        integer, intent(in) :: iend              !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out) :: alpha           !! damping parameter
        real(wp), intent(out) :: tau_c           !! dimensionless contact duration
        integer, intent(out) :: status           !! HD_OK or an error code
        integer, intent(in), optional :: method  !! HD_METHOD_FIT (default), _COMPACT, _SERIES, _PADE,
                                                 !! _FIRST_ORDER, _ITERATIVE, _RK45
        real(wp), intent(in), optional :: tol    !! iterative tolerance (default 1e-10, within [1e-15, 1e-2])
        real(wp), intent(in), optional :: accuracy !! relative accuracy asked of series and Pade (default 1e-10)
        integer, intent(in), optional :: law     !! HD_DAMPING_* (default linear)
        type(hertzdamp_invert_options) :: opts
        real(wp) :: emin
        integer :: meth, law_
        alpha = 0.0_wp
        tau_c = 0.0_wp
        if (present(method)) opts%method = method
        if (present(tol)) opts%tol = tol
        if (present(accuracy)) opts%accuracy = accuracy
        meth = opts%method
        law_ = HD_DAMPING_LINEAR
        if (present(law)) law_ = law
        status = hertzdamp_law_status(law_)
        if (status /= HD_OK) return
        if (iend /= HD_END_OVERLAP .and. iend /= HD_END_FORCE) then
            status = HD_BAD_END
            return
        end if
        emin = hertzdamp_fit_law_e_min(law_, iend)
        if (.not. (e >= emin .and. e <= 1.0_wp)) then
            status = HD_BAD_RESTITUTION
            return
        end if
        if (law_ /= HD_DAMPING_LINEAR .and. (meth == HD_METHOD_COMPACT .or. meth == HD_METHOD_SERIES .or. &
                                             meth == HD_METHOD_PADE)) then
            status = HD_NOT_SUPPORTED
            return
        end if
        select case (meth)
        case (HD_METHOD_FIT)
            call hertzdamp_fit_inverse(e, iend, alpha, tau_c, status, law_)
        case (HD_METHOD_COMPACT)
            call hertzdamp_compact_inverse(e, iend, alpha, tau_c, status)
        case (HD_METHOD_FIRST_ORDER)
            ! e = 1 - e1 alpha + O(alpha^2), tau_c = tau_c(0) + O(alpha) (both ends)
            alpha = (1.0_wp - e) / hertzdamp_e1(law_)
            tau_c = hertzdamp_tau_c0()
        case (HD_METHOD_ITERATIVE, HD_METHOD_RK45)
            if (.not. (opts%tol >= 1.0e-15_wp .and. opts%tol <= 1.0e-2_wp)) then
                status = HD_BAD_TOL
                return
            end if
            call iterate(e, iend, law_, opts%tol, alpha, tau_c, status)
        case (HD_METHOD_SERIES, HD_METHOD_PADE)
            if (iend /= HD_END_OVERLAP) then
                status = HD_NOT_SUPPORTED   ! the force definition has no Taylor series
                return
            end if
            call series_inverse(e, meth, opts%accuracy, alpha, tau_c, status)
        case default
            status = HD_BAD_ARGUMENT
        end select
    end subroutine hertzdamp_invert_alpha

    !> Invert the truncated series (default order) or its Pade summation: a few Newton
    !> steps on ln e(alpha) = ln e with the derivative of the same formula (central
    !> difference), no ODE solves.  Valid where the formula is (series |alpha| < 1,
    !> Pade alpha <= 0.8), otherwise HD_OUTSIDE_VALIDITY; where the formula's own error
    !> estimate at the solution exceeds `accuracy` (relative), HD_INACCURATE.
    pure subroutine series_inverse(e, meth, accuracy, alpha, tau_c, status)
        real(wp), intent(in) :: e, accuracy
        integer, intent(in) :: meth
        real(wp), intent(out) :: alpha, tau_c
        integer, intent(out) :: status
        type(hertzdamp_collision) :: r
        real(wp) :: lt, a, g, gp, gm, h, step, ee, amax
        integer :: it
        alpha = 0.0_wp
        tau_c = hertzdamp_tau_c0()
        status = HD_OK
        lt = log(e)
        if (lt == 0.0_wp) return
        ! start from the first-order law, inside the range where the formula is valid
        ! (series: |alpha| < 1, Pade: alpha <= 0.8)
        amax = hertzdamp_pade_alpha_max
        if (meth == HD_METHOD_SERIES) amax = 0.999_wp
        a = min(-lt / hertzdamp_e1(), 0.99_wp * amax)
        do it = 1, 30
            call series_ln_e(a, meth, g, tau_c, status)
            if (status /= HD_OK) exit
            h = 1.0e-6_wp * max(a, 1.0e-3_wp)
            call series_ln_e(a + h, meth, gp, ee, status)
            if (status == HD_OK) call series_ln_e(max(a - h, 0.0_wp), meth, gm, ee, status)
            if (status /= HD_OK) exit
            step = (g - lt) * (a + h - max(a - h, 0.0_wp)) / (gp - gm)
            a = a - step
            if (.not. (a >= 0.0_wp)) a = 0.0_wp
            a = min(a, amax)
            if (abs(step) <= 4.0_wp * epsilon(1.0_wp) * a) exit
        end do
        if (status == HD_OK) then
            call series_ln_e(a, meth, g, tau_c, status)
            if (abs(g - lt) > 1.0e-12_wp * abs(lt)) status = HD_OUTSIDE_VALIDITY
        end if
        if (status == HD_OK) then
            ! the formula's own error estimate at the solution
            r = hertzdamp_forward_alpha(a, HD_END_OVERLAP, meth, accuracy=accuracy)
            if (r%status /= HD_OK) status = merge(HD_INACCURATE, HD_OUTSIDE_VALIDITY, r%status == HD_INACCURATE)
        else
            status = HD_OUTSIDE_VALIDITY
        end if
        if (status /= HD_OK) then
            alpha = 0.0_wp
            tau_c = 0.0_wp
            return
        end if
        alpha = a
    end subroutine series_inverse

    !> ln e and tau_c of the series or Pade formula at alpha (status HD_OK where the
    !> formula is defined, whatever its error estimate).
    pure subroutine series_ln_e(a, meth, lne, tau_c, status)
        real(wp), intent(in) :: a
        integer, intent(in) :: meth
        real(wp), intent(out) :: lne, tau_c
        integer, intent(out) :: status
        type(hertzdamp_collision) :: r
        r = hertzdamp_forward_alpha(a, HD_END_OVERLAP, meth, accuracy=1.0_wp)   ! no guard while iterating
        status = r%status
        tau_c = r%tau_c
        lne = 0.0_wp
        if (status == HD_OK) lne = log(r%e)
    end subroutine series_ln_e

    !> Start of the iterative inverse (see hertzdamp_secant): the first trial alpha for
    !> restitution e (0 < e < 1, -ln e >= 1e-10) and the state.  Written as a careful DEM
    !> developer would: for the linear law the compact rule where it is defined
    !> (e >= 0.05; alpha within ~1e-6 for the overlap end, ~1e-3 for the force end), else
    !> the first-order law alpha = -ln(e)/e1(law); for the overlap end of a law with a
    !> critical damping the bracket starts as [0, alpha_c] and the start is at most
    !> 0.9 alpha_c (no trial is wasted on alpha >= alpha_c, where nothing rebounds).
    pure subroutine hertzdamp_secant_start(e, iend, tol, state, alpha, law)
        real(wp), intent(in) :: e                         !! target restitution coefficient
        integer, intent(in) :: iend                       !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(in) :: tol                       !! relative accuracy asked of alpha
        type(hertzdamp_secant), intent(out) :: state      !! the iteration's state
        real(wp), intent(out) :: alpha                    !! first trial: solve e(alpha) there
        integer, intent(in), optional :: law              !! HD_DAMPING_* (default linear)
        real(wp) :: a, tau
        integer :: st, law_
        law_ = HD_DAMPING_LINEAR
        if (present(law)) law_ = law
        state%lt = -log(e)
        state%tol = tol
        alpha = state%lt / hertzdamp_e1(law_)
        if (iend == HD_END_OVERLAP .and. hertzdamp_law_has_alpha_c(law_)) then
            ! every rebound of the overlap end has alpha < alpha_c: the bracket's top
            state%hi = hertzdamp_law_alpha_c(law_)
            state%have_hi = .true.
            alpha = min(alpha, 0.9_wp * state%hi)
        end if
        if (law_ == HD_DAMPING_LINEAR .and. &
            e >= merge(hertzdamp_compact_e_min_overlap, hertzdamp_compact_e_min_force, iend == HD_END_OVERLAP)) then
            call hertzdamp_compact_inverse(e, iend, a, tau, st)
            if (st == HD_OK .and. a > 0.0_wp) alpha = a
        end if
        state%a1 = alpha
    end subroutine hertzdamp_secant_start

    !> One step of the iterative inverse, by reverse communication: the caller solves the
    !> collision at the trial alpha with any integrator and passes the outcome (e of the
    !> trial, or no_rebound); this returns the next trial, or done = .true. with alpha
    !> the answer (the last trial), or status HD_NO_CONVERGENCE after 100 trials.
    !> A secant on g(alpha) = ln e(alpha) - ln e, kept inside a bracket (bisection
    !> fallback; a no-rebound trial shrinks it); the second trial is the proportional
    !> step alpha ln e / ln e(alpha) (exact where ln e is linear in alpha).  It stops
    !> when the secant step is below tol/10 alpha or the residual below tol/10 |ln e|.
    !> Used by the iterative method (rk45) and by the GSL reference solver (packages/reference).
    pure subroutine hertzdamp_secant_next(state, e_trial, no_rebound, alpha, done, status)
        type(hertzdamp_secant), intent(inout) :: state    !! the iteration's state
        real(wp), intent(in) :: e_trial                   !! e(alpha) of the last trial (ignored without rebound)
        logical, intent(in) :: no_rebound                 !! the last trial did not rebound
        real(wp), intent(out) :: alpha                    !! next trial, or the answer when done
        logical, intent(out) :: done                      !! alpha is the answer
        integer, intent(out) :: status                    !! HD_OK or HD_NO_CONVERGENCE
        real(wp) :: g1, anew
        done = .false.
        status = HD_OK
        state%trials = state%trials + 1
        if (state%trials > 100) then
            status = HD_NO_CONVERGENCE
            alpha = state%a1
            return
        end if
        if (no_rebound) then
            state%hi = state%a1
            state%have_hi = .true.
            state%a1 = 0.5_wp * (state%lo + state%hi)
            alpha = state%a1
            return
        end if
        g1 = log(e_trial) + state%lt            ! ln e(alpha) - ln e_target, decreasing in alpha
        alpha = state%a1
        if (abs(g1) <= 0.1_wp * state%tol * state%lt) then
            done = .true.
            return
        end if
        if (g1 > 0.0_wp) then
            state%lo = state%a1
        else
            state%hi = state%a1
            state%have_hi = .true.
        end if
        if (state%have_prev .and. g1 /= state%g0) then
            anew = state%a1 - g1 * (state%a1 - state%a0) / (g1 - state%g0)
        else
            anew = state%a1 * state%lt / (state%lt - g1)   ! proportional step
        end if
        ! kept inside the bracket
        if (.not. state%have_hi) then
            if (.not. (anew > state%lo)) anew = 2.0_wp * state%lo
            if (anew > 4.0_wp * state%lo) anew = 4.0_wp * state%lo
        else if (.not. (anew > state%lo .and. anew < state%hi)) then
            anew = 0.5_wp * (state%lo + state%hi)
        end if
        if (abs(anew - state%a1) <= 0.1_wp * state%tol * state%a1) then
            done = .true.
            return
        end if
        state%a0 = state%a1
        state%g0 = g1
        state%have_prev = .true.
        state%a1 = anew
        alpha = anew
    end subroutine hertzdamp_secant_next

    !> The iterative baseline: hertzdamp_secant over rk45 solves of the law, each at a
    !> tolerance derived from the accuracy asked of alpha: rk45 tol = tol/10 min(1, |ln e|),
    !> since the relative error of alpha is about that of ln e, (delta e / e) / |ln e|
    !> (test/unit/test_inverse.f90 checks alpha within tol).  A trial without rebound, or with
    !> e below what rk45 resolves near alpha_c (HD_INACCURATE), shrinks the bracket from
    !> above.  tau_c is that of the last solve: its error is the error of alpha times
    !> d ln tau_c / d ln alpha, which grows towards alpha_c (7 tol at e = 1e-3, overlap);
    !> `hertzdamp bench` reports the errors of alpha, k and d it achieves.
    pure subroutine iterate(e, iend, law, tol, alpha, tau_c, status)
        real(wp), intent(in) :: e, tol
        integer, intent(in) :: iend, law
        real(wp), intent(out) :: alpha, tau_c
        integer, intent(out) :: status
        type(hertzdamp_collision) :: r
        type(hertzdamp_secant) :: state
        real(wp) :: lt, rtol, a
        logical :: done, no_rebound
        alpha = 0.0_wp
        tau_c = hertzdamp_tau_c0()
        status = HD_OK
        lt = -log(e)
        if (lt == 0.0_wp) return
        rtol = max(1.0e-15_wp, min(1.0e-3_wp, 0.1_wp * tol * min(1.0_wp, lt)))
        if (lt < 1.0e-10_wp) then
            ! 1 - e below what the reference integrator resolves (~1e-13): the first-order
            ! law ln e = -e1 alpha + O(alpha^2) is exact to O(alpha) ~ 1e-10 relative here
            alpha = lt / hertzdamp_e1(law)
            r = hertzdamp_rk45_collide(alpha, iend, rtol, law)
            status = r%status
            if (status == HD_OK) tau_c = r%tau_c
            return
        end if
        call hertzdamp_secant_start(e, iend, tol, state, a, law)
        do
            r = hertzdamp_rk45_collide(a, iend, rtol, law)
            no_rebound = r%status == HD_NO_REBOUND .or. r%status == HD_INACCURATE
            if (r%status /= HD_OK .and. .not. no_rebound) then
                status = r%status
                return
            end if
            if (r%status == HD_OK) then
                alpha = a
                tau_c = r%tau_c
            end if
            call hertzdamp_secant_next(state, r%e, no_rebound, a, done, status)
            if (done .or. status /= HD_OK) exit
        end do
    end subroutine iterate

end module hertzdamp_inverse
