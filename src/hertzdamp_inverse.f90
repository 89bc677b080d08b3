!> The inverse problem of doc/theory.md section 6 (adaptive collision time model): from a
!> target restitution e and contact time T_c, for a contact with effective mass m and
!> impact velocity u_in, the Hertz stiffness k and damping d
!>
!>     alpha = alpha(e),  tau = tau_c(alpha),  t* = T_c / tau,
!>     k = m t*^(-5/2) u^(-1/2),  d = alpha m / t*,
!>
!> with the physical bound: if k_phys <= k, then k = k_phys and
!> d = alpha m^(3/5) k_phys^(2/5) u^(1/5) (the contact is then longer than T_c).
!>
!> For the damping law q (argument `law`: 0 linear, the default; 1 tsuji, q = 1/4;
!> 2 kuwabara-kono, q = 1/2; doc/damping-laws.md) alpha = d t* (u t*)^q / m, so
!>     d = alpha m t*^(-1) (u t*)^(-q),
!> and with the bound d = alpha m^((3-2q)/5) k_phys^((2+2q)/5) u^((1-4q)/5)
!> (tsuji: alpha sqrt(m k_phys), independent of u).
!>
!> alpha(e) and tau_c(alpha(e)) come from the fitted approximant (default, ~1e-13
!> relative, no iteration), the compact formula (~1e-5 on e in [0.05, 1]) or a
!> secant iteration over reference-integrator solves (the baseline; slow).
!>
!> Supported restitution: e_min <= e <= 1 with e_min = 1e-3 (overlap; e -> 0 has
!> no finite contact time) and 1e-4 (force), for every method; outside:
!> HD_BAD_RESTITUTION.  e = 1 gives alpha = 0, d = 0, tau_c = tau_c(0).
!> Inputs whose powers could overflow go through the logarithmic path of
!> hertzdamp_scaling; a result outside double precision gives HD_OUT_OF_RANGE.
module hertzdamp_inverse
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_OK, HD_BAD_RESTITUTION, HD_BAD_TIME, HD_BAD_MASS, HD_BAD_VELOCITY, &
                                HD_BAD_KPHYS, HD_BAD_END, HD_BAD_TOL, HD_BAD_ARGUMENT, HD_NOT_SUPPORTED, &
                                HD_NO_CONVERGENCE, HD_NO_REBOUND, HD_OUT_OF_RANGE, HD_END_OVERLAP, HD_END_FORCE, &
                                HD_OUTSIDE_VALIDITY, HD_INACCURATE
    use hertzdamp_scaling, only: hertzdamp_safe_exp, hertzdamp_safe_exp_or_zero
    use hertzdamp_constants, only: hertzdamp_e1, hertzdamp_tau_c0
    use hertzdamp_rk45, only: hertzdamp_collision, hertzdamp_rk45_collide
    use hertzdamp_methods, only: HD_METHOD_RK45, HD_METHOD_SERIES, HD_METHOD_PADE, HD_METHOD_COMPACT, &
                                 HD_METHOD_FIT, HD_METHOD_ITERATIVE, HD_METHOD_FIRST_ORDER, hertzdamp_forward_alpha, &
                                 hertzdamp_default_accuracy
    use hertzdamp_fit, only: hertzdamp_fit_inverse
    use hertzdamp_fit_laws, only: hertzdamp_fit_law_inverse, hertzdamp_fit_law_e_min
    use hertzdamp_laws, only: HD_DAMPING_LINEAR, hertzdamp_law_q, hertzdamp_law_status
    use hertzdamp_compact, only: hertzdamp_compact_inverse
    use hertzdamp_series, only: hertzdamp_pade_alpha_max
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Default tolerance of the iterative method (relative, on alpha).
    real(wp), parameter, public :: hertzdamp_invert_default_tol = 1.0e-10_wp
    !> Inputs m, u, T_c in [safe_lo, safe_hi] take the direct (power-free) path.
    real(wp), parameter :: safe_lo = 1.0e-30_wp, safe_hi = 1.0e30_wp

    public :: hertzdamp_invert, hertzdamp_invert_alpha

contains

    !> k and d such that the collision has restitution e and contact time tc.
    pure elemental subroutine hertzdamp_invert(e, tc, m, u, iend, k, d, status, alpha, tstar, tau_c, &
                                               bound_active, k_phys, method, tol, accuracy, law)
        real(wp), intent(in) :: e                      !! target restitution coefficient, e_min <= e <= 1
        real(wp), intent(in) :: tc                     !! target contact time T_c [s]
        real(wp), intent(in) :: m                      !! effective mass [kg]
        real(wp), intent(in) :: u                      !! impact velocity u_in [m s^-1]
        integer, intent(in) :: iend                    !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out) :: k                     !! stiffness [N m^-3/2] (0 on error)
        real(wp), intent(out) :: d                     !! damping coefficient [kg s^-1 m^-q] (0 on error)
        integer, intent(out) :: status                 !! HD_OK or an error code
        real(wp), intent(out), optional :: alpha       !! damping parameter alpha(e)
        real(wp), intent(out), optional :: tstar       !! time unit of the returned k [s] (contact time = tstar tau_c)
        real(wp), intent(out), optional :: tau_c       !! dimensionless contact duration tau_c(alpha)
        logical, intent(out), optional :: bound_active !! true when k = k_phys was used
        real(wp), intent(in), optional :: k_phys       !! physical stiffness bound [N m^-3/2]
        integer, intent(in), optional :: method        !! HD_METHOD_FIT (default), _COMPACT, _ITERATIVE or _RK45
        real(wp), intent(in), optional :: tol          !! tolerance of the iterative method (default 1e-10)
        real(wp), intent(in), optional :: accuracy     !! relative accuracy asked of series and Pade (default 1e-10)
        integer, intent(in), optional :: law           !! HD_DAMPING_* (default linear): damping force d zeta^q zeta'
        real(wp) :: a, tau, ts, lk, lts, q
        logical :: bound
        integer :: meth, law_
        k = 0.0_wp
        d = 0.0_wp
        a = 0.0_wp
        tau = 0.0_wp
        ts = 0.0_wp
        bound = .false.
        meth = HD_METHOD_FIT
        if (present(method)) meth = method
        law_ = HD_DAMPING_LINEAR
        if (present(law)) law_ = law
        q = hertzdamp_law_q(law_)
        status = hertzdamp_law_status(law_)
        if (.not. (tc > 0.0_wp .and. tc <= huge(tc))) status = HD_BAD_TIME
        if (.not. (m > 0.0_wp .and. m <= huge(m))) status = HD_BAD_MASS
        if (.not. (u > 0.0_wp .and. u <= huge(u))) status = HD_BAD_VELOCITY
        if (present(k_phys)) then
            if (.not. (k_phys > 0.0_wp .and. k_phys <= huge(k_phys))) status = HD_BAD_KPHYS
        end if
        if (status == HD_OK) then
            if (meth == HD_METHOD_FIT .and. law_ == HD_DAMPING_LINEAR) then
                ! the hot path of DEM codes: straight to the approximant (it checks e and iend)
                call hertzdamp_fit_inverse(e, iend, a, tau, status)
            else if (meth == HD_METHOD_FIT) then
                call hertzdamp_fit_law_inverse(e, iend, law_, a, tau, status)
            else
                call hertzdamp_invert_alpha(e, iend, a, tau, status, meth, tol, accuracy, law_)
            end if
        end if
        if (status == HD_OK) then
            ts = tc / tau
            if (min(m, u, tc) >= safe_lo .and. max(m, u, tc) <= safe_hi) then
                ! direct path: every intermediate is a normal double here
                k = m / (ts * ts * sqrt(ts * u))
                if (present(k_phys)) then
                    if (k_phys <= k) then
                        bound = .true.
                        lts = 0.4_wp * (log(m) - log(k_phys)) - 0.2_wp * log(u)
                        call hertzdamp_safe_exp(lts, ts, status)
                        k = k_phys
                    end if
                end if
                ! d = alpha m t*^-1 (u t*)^-q
                d = a * m / ts
                if (q > 0.0_wp) d = d / law_power(u * ts, law_)
            else
                ! logarithmic path (extreme inputs)
                lts = log(tc) - log(tau)
                lk = log(m) - 2.5_wp * lts - 0.5_wp * log(u)
                if (present(k_phys)) then
                    if (log(k_phys) <= lk) then
                        bound = .true.
                        lk = log(k_phys)
                        lts = 0.4_wp * (log(m) - lk) - 0.2_wp * log(u)
                    end if
                end if
                call hertzdamp_safe_exp(lts, ts, status)
                call hertzdamp_safe_exp(lk, k, status)
                if (a > 0.0_wp) call hertzdamp_safe_exp_or_zero(log(a) + log(m) - lts - q * (log(u) + lts), d, status)
            end if
            if (status == HD_OK) then
                if (.not. (ieee_is_finite(d) .and. d < huge(d))) status = HD_OUT_OF_RANGE
            end if
        end if
        if (status /= HD_OK) then
            k = 0.0_wp
            d = 0.0_wp
            a = 0.0_wp
            tau = 0.0_wp
            ts = 0.0_wp
            bound = .false.
        end if
        if (present(alpha)) alpha = a
        if (present(tstar)) tstar = ts
        if (present(tau_c)) tau_c = tau
        if (present(bound_active)) bound_active = bound
    end subroutine hertzdamp_invert

    !> (u t*)^q of the law, by square roots (q = 1/4 or 1/2).
    pure real(wp) function law_power(x, law) result(y)
        real(wp), intent(in) :: x
        integer, intent(in) :: law
        y = sqrt(x)
        if (hertzdamp_law_q(law) == 0.25_wp) y = sqrt(y)
    end function law_power

    !> The dimensionless inverse e -> (alpha, tau_c) by the chosen method.
    !> These are the constants of a material pair: they depend on e, the contact end and
    !> the damping law only (HERTZDAMP_PAIR, hertzdamp_c_pair).  Every law: fit (default),
    !> iterative / rk45, first-order; compact, series and Pade: linear law only.
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
        real(wp) :: emin, tol_, acc
        integer :: meth, law_
        alpha = 0.0_wp
        tau_c = 0.0_wp
        meth = HD_METHOD_FIT
        if (present(method)) meth = method
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
            call hertzdamp_fit_law_inverse(e, iend, law_, alpha, tau_c, status)
        case (HD_METHOD_COMPACT)
            call hertzdamp_compact_inverse(e, iend, alpha, tau_c, status)
        case (HD_METHOD_FIRST_ORDER)
            ! e = 1 - e1 alpha + O(alpha^2), tau_c = tau_c(0) + O(alpha) (both ends)
            alpha = (1.0_wp - e) / hertzdamp_e1(law_)
            tau_c = hertzdamp_tau_c0()
        case (HD_METHOD_ITERATIVE, HD_METHOD_RK45)
            tol_ = hertzdamp_invert_default_tol
            if (present(tol)) tol_ = tol
            if (.not. (tol_ >= 1.0e-15_wp .and. tol_ <= 1.0e-2_wp)) then
                status = HD_BAD_TOL
                return
            end if
            call iterate(e, iend, law_, tol_, alpha, tau_c, status)
        case (HD_METHOD_SERIES, HD_METHOD_PADE)
            if (iend /= HD_END_OVERLAP) then
                status = HD_NOT_SUPPORTED   ! the force definition has no Taylor series
                return
            end if
            acc = hertzdamp_default_accuracy
            if (present(accuracy)) acc = accuracy
            call series_inverse(e, meth, acc, alpha, tau_c, status)
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

    !> Safeguarded secant (bracketing, bisection fallback) on g(alpha) = ln e(alpha) - ln e
    !> with one reference solve per trial.  No rebound, and e below what rk45 resolves near
    !> alpha_c (HD_INACCURATE), bracket from above.
    pure subroutine iterate(e, iend, law, tol, alpha, tau_c, status)
        real(wp), intent(in) :: e, tol
        integer, intent(in) :: iend, law
        real(wp), intent(out) :: alpha, tau_c
        integer, intent(out) :: status
        type(hertzdamp_collision) :: r
        real(wp) :: lt, lo, hi, a0, g0, a1, g1, anew, rtol
        integer :: it
        logical :: have_hi
        alpha = 0.0_wp
        tau_c = hertzdamp_tau_c0()
        status = HD_OK
        lt = -log(e)
        if (lt == 0.0_wp) return
        rtol = min(1.0e-13_wp, max(1.0e-15_wp, 1.0e-3_wp * tol))
        if (lt < 1.0e-10_wp) then
            ! 1 - e below what the reference integrator resolves (~1e-13): the first-order
            ! law ln e = -e1 alpha + O(alpha^2) is exact to O(alpha) ~ 1e-10 relative here
            alpha = lt / hertzdamp_e1(law)
            r = hertzdamp_rk45_collide(alpha, iend, rtol, law)
            status = r%status
            if (status == HD_OK) tau_c = r%tau_c
            return
        end if
        lo = 0.0_wp
        have_hi = .false.
        hi = huge(1.0_wp)
        a0 = 0.0_wp
        g0 = lt
        a1 = lt / hertzdamp_e1(law)          ! first-order guess
        if (iend == HD_END_OVERLAP .and. law == HD_DAMPING_LINEAR) a1 = min(a1, 1.0_wp)
        do it = 1, 200
            r = hertzdamp_rk45_collide(a1, iend, rtol, law)
            if (r%status == HD_NO_REBOUND .or. r%status == HD_INACCURATE) then
                hi = a1
                have_hi = .true.
                a1 = 0.5_wp * (lo + hi)
                cycle
            else if (r%status /= HD_OK) then
                status = r%status
                return
            end if
            g1 = -log(r%e) - lt
            g1 = -g1                      ! g = ln e(alpha) - ln e_target, decreasing in alpha
            alpha = a1
            tau_c = r%tau_c
            if (abs(g1) <= 4.0e-15_wp) return
            if (g1 > 0.0_wp) then
                lo = a1
            else
                hi = a1
                have_hi = .true.
            end if
            ! secant through the last two points, kept inside the bracket
            if (g1 /= g0) then
                anew = a1 - g1 * (a1 - a0) / (g1 - g0)
            else
                anew = a1
            end if
            if (.not. have_hi) then
                if (.not. (anew > lo)) anew = 2.0_wp * lo
                if (anew > 4.0_wp * lo) anew = 4.0_wp * lo
            else if (.not. (anew > lo .and. anew < hi)) then
                anew = 0.5_wp * (lo + hi)
            end if
            if (abs(anew - a1) <= tol * a1) then
                if (abs(anew - a1) <= 1.0e-2_wp * tol * a1) return
                a0 = a1
                g0 = g1
                a1 = anew
                r = hertzdamp_rk45_collide(a1, iend, rtol, law)
                if (r%status == HD_OK) then
                    alpha = a1
                    tau_c = r%tau_c
                end if
                return
            end if
            a0 = a1
            g0 = g1
            a1 = anew
        end do
        status = HD_NO_CONVERGENCE
    end subroutine iterate

end module hertzdamp_inverse
