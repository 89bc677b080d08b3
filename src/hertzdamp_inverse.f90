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
!> `hertzdamp_invert` is generic: scalars (or arrays of any rank, elementally) and
!> rank-1 arrays.  Both run the fit of every damping law through hertzdamp_fit_invert_n,
!> the vectorised kernels that also serve the C and legacy entry points, so every way
!> of calling gives the same bits; the rank-1 form runs them over whole arrays (SIMD)
!> and takes only the contacts that need more (extreme inputs, the physical bound,
!> errors, other methods) through the scalar path.  A fitted map of another law gets
!> the same fast path by a kernel of its own in hertzdamp_fit (see there and
!> gen/fit_csv_to_f90.py) and its q in the direct formulas of
!> hertzdamp_fit_invert_out.inc.
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
    use hertzdamp_constants, only: hertzdamp_e1, hertzdamp_tau_c0, safe_lo => hertzdamp_direct_lo, &
                                   safe_hi => hertzdamp_direct_hi
    use hertzdamp_rk45, only: hertzdamp_collision, hertzdamp_rk45_collide
    use hertzdamp_methods, only: HD_METHOD_RK45, HD_METHOD_SERIES, HD_METHOD_PADE, HD_METHOD_COMPACT, &
                                 HD_METHOD_FIT, HD_METHOD_ITERATIVE, HD_METHOD_FIRST_ORDER, hertzdamp_forward_alpha, &
                                 hertzdamp_default_accuracy
    use hertzdamp_fit, only: hertzdamp_fit_inverse, hertzdamp_fit_invert, hertzdamp_fit_invert_n
    use hertzdamp_fit_laws, only: hertzdamp_fit_law_e_min
    use hertzdamp_laws, only: HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, hertzdamp_law_q, hertzdamp_law_status, hertzdamp_law_alpha_c, &
                              hertzdamp_law_has_alpha_c
    use hertzdamp_compact, only: hertzdamp_compact_inverse, hertzdamp_compact_e_min_overlap, &
                                 hertzdamp_compact_e_min_force
    use hertzdamp_series, only: hertzdamp_pade_alpha_max
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Default tolerance of the iterative method (relative, on alpha).
    real(wp), parameter, public :: hertzdamp_invert_default_tol = 1.0e-10_wp
    !> Inputs m, u, T_c in [safe_lo, safe_hi] take the direct (power-free) path.
    !> Contacts per pass of the rank-1 form (buffers on the stack).
    integer, parameter :: chunk = 256

    !> k and d such that the collision has restitution e and contact time tc: for
    !> scalars (elemental: also arrays of any rank) or rank-1 arrays (vectorised).
    interface hertzdamp_invert
        module procedure invert_scalar
        module procedure invert_array
    end interface hertzdamp_invert

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

    public :: hertzdamp_invert, hertzdamp_invert_alpha, hertzdamp_secant_start, hertzdamp_secant_next
    public :: hertzdamp_invert_fit_rest

contains

    !> k and d such that the collision has restitution e and contact time tc.
    pure elemental subroutine invert_scalar(e, tc, m, u, iend, k, d, status, alpha, tstar, tau_c, &
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
        real(wp) :: a, tau, ts, kp
        logical :: bound
        integer :: meth, law_
        meth = HD_METHOD_FIT
        if (present(method)) meth = method
        law_ = HD_DAMPING_LINEAR
        if (present(law)) law_ = law
        kp = 0.0_wp
        if (present(k_phys)) kp = k_phys
        ts = 0.0_wp
        bound = .false.
        status = -1
        if (meth == HD_METHOD_FIT) then
            ! the kernel of every fit entry point (bit-identical to the rank-1 form)
            call hertzdamp_fit_invert(e, tc, m, u, iend, k, d, a, tau, status, law_)
            if (status == HD_OK) then
                if (present(tstar)) ts = tc / tau
                if (present(k_phys)) call apply_bound(a, m, u, kp, law_, present(tstar), k, d, ts, bound, status)
            end if
        end if
        if (status /= HD_OK) then
            call invert_general(e, tc, m, u, iend, present(k_phys), kp, meth, law_, tol, accuracy, k, d, status, a, &
                                ts, tau, bound)
        end if
        if (present(alpha)) alpha = a
        if (present(tstar)) tstar = ts
        if (present(tau_c)) tau_c = tau
        if (present(bound_active)) bound_active = bound
    end subroutine invert_scalar

    !> invert_scalar for rank-1 arrays (all of the size of e): the fit runs vectorised
    !> over whole arrays, the remaining contacts go one by one through the scalar path.
    !> Results are those of the scalar calls, bit for bit.
    pure subroutine invert_array(e, tc, m, u, iend, k, d, status, alpha, tstar, tau_c, bound_active, k_phys, &
                                 method, tol, accuracy, law)
        real(wp), intent(in), contiguous :: e(:)                 !! target restitution coefficients
        real(wp), intent(in), contiguous :: tc(:)                !! target contact times [s]
        real(wp), intent(in), contiguous :: m(:)                 !! effective masses [kg]
        real(wp), intent(in), contiguous :: u(:)                 !! impact velocities [m s^-1]
        integer, intent(in) :: iend                              !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out), contiguous :: k(:)                !! stiffnesses [N m^-3/2] (0 on error)
        real(wp), intent(out), contiguous :: d(:)                !! damping coefficients [kg s^-1] (0 on error)
        integer, intent(out), contiguous :: status(:)            !! HD_OK or an error code, per contact
        real(wp), intent(out), optional, contiguous :: alpha(:)  !! damping parameters alpha(e)
        real(wp), intent(out), optional, contiguous :: tstar(:)  !! time units of the returned k [s]
        real(wp), intent(out), optional, contiguous :: tau_c(:)  !! dimensionless contact durations
        logical, intent(out), optional, contiguous :: bound_active(:) !! true where k = k_phys was used
        real(wp), intent(in), optional, contiguous :: k_phys(:)  !! physical stiffness bounds [N m^-3/2]
        integer, intent(in), optional :: method                  !! as for the scalar form
        real(wp), intent(in), optional :: tol                    !! as for the scalar form
        real(wp), intent(in), optional :: accuracy               !! as for the scalar form
        integer, intent(in), optional :: law                     !! as for the scalar form
        real(wp) :: ab(chunk), tb(chunk), sb_ts(chunk), kp
        integer :: i0, nc, j, i, meth, law_
        logical :: bb(chunk)
        meth = HD_METHOD_FIT
        if (present(method)) meth = method
        law_ = HD_DAMPING_LINEAR
        if (present(law)) law_ = law
        do i0 = 0, size(e) - 1, chunk
            nc = min(chunk, size(e) - i0)
            if (meth == HD_METHOD_FIT) then
                call hertzdamp_fit_invert_n(nc, e(i0 + 1:i0 + nc), tc(i0 + 1:i0 + nc), m(i0 + 1:i0 + nc), &
                                            u(i0 + 1:i0 + nc), iend, k(i0 + 1:i0 + nc), d(i0 + 1:i0 + nc), ab, tb, &
                                            status(i0 + 1:i0 + nc), law_)
            else
                status(i0 + 1:i0 + nc) = -1
            end if
            bb(1:nc) = .false.
            sb_ts(1:nc) = 0.0_wp
            if (present(tstar)) then
                ! only where the kernel served the contact (tb is not set, or 0, elsewhere)
                where (status(i0 + 1:i0 + nc) == HD_OK) sb_ts(1:nc) = tc(i0 + 1:i0 + nc) / tb(1:nc)
            end if
            ! one contact at a time only where needed: the bound, and the contacts the
            ! kernel does not serve (the same code as the scalar form)
            if (present(k_phys) .or. any(status(i0 + 1:i0 + nc) /= HD_OK)) then
                do j = 1, nc
                    i = i0 + j
                    if (status(i) == HD_OK .and. present(k_phys)) then
                        call apply_bound(ab(j), m(i), u(i), k_phys(i), law_, present(tstar), k(i), d(i), sb_ts(j), &
                                         bb(j), status(i))
                    end if
                    if (status(i) /= HD_OK) then
                        kp = 0.0_wp
                        if (present(k_phys)) kp = k_phys(i)
                        call invert_general(e(i), tc(i), m(i), u(i), iend, present(k_phys), kp, meth, law_, tol, &
                                            accuracy, k(i), d(i), status(i), ab(j), sb_ts(j), tb(j), bb(j))
                    end if
                end do
            end if
            if (present(alpha)) alpha(i0 + 1:i0 + nc) = ab(1:nc)
            if (present(tstar)) tstar(i0 + 1:i0 + nc) = sb_ts(1:nc)
            if (present(tau_c)) tau_c(i0 + 1:i0 + nc) = tb(1:nc)
            if (present(bound_active)) bound_active(i0 + 1:i0 + nc) = bb(1:nc)
        end do
    end subroutine invert_array

    !> The physical bound on a contact of the fast path (k from the direct formulas): a
    !> valid k_phys <= k replaces k, with t* = (m/k_phys)^(2/5) u^(-1/5) and
    !> d = alpha m t*^(-1) (u t*)^(-q) (tsuji: alpha sqrt(m k_phys), which needs no t*:
    !> t* only when want_ts); an invalid k_phys gives HD_BAD_KPHYS and zero outputs.
    pure elemental subroutine apply_bound(a, m, u, k_phys, law, want_ts, k, d, ts, bound, status)
        real(wp), intent(in) :: a, m, u, k_phys
        integer, intent(in) :: law
        logical, intent(in) :: want_ts
        real(wp), intent(inout) :: k, d, ts
        logical, intent(out) :: bound
        integer, intent(inout) :: status
        real(wp) :: lts
        bound = .false.
        if (.not. (k_phys > 0.0_wp .and. k_phys <= huge(k_phys))) then
            status = HD_BAD_KPHYS
            k = 0.0_wp
            d = 0.0_wp
            ts = 0.0_wp
        else if (k_phys <= k) then
            bound = .true.
            k = k_phys
            if (law == HD_DAMPING_TSUJI) then
                d = a * (sqrt(m) * sqrt(k_phys))
                if (.not. want_ts) return
            end if
            lts = 0.4_wp * (log(m) - log(k_phys)) - 0.2_wp * log(u)
            call hertzdamp_safe_exp(lts, ts, status)
            if (law == HD_DAMPING_LINEAR) then
                d = a * m / ts
            else if (law /= HD_DAMPING_TSUJI) then
                d = a * m / ts / law_power(u * ts, law)
            end if
        end if
    end subroutine apply_bound

    !> The contacts the fit's kernel (hertzdamp_fit_invert) does not serve, without the
    !> physical bound: what hertzdamp_invert with method = HD_METHOD_FIT and no k_phys
    !> does after its kernel failed, the same bits, without running the kernel again.
    !> For callers that have run the kernel themselves (the flat C and legacy entry
    !> points); on failure k = d = 0 and status names the bad argument.
    pure elemental subroutine hertzdamp_invert_fit_rest(e, tc, m, u, iend, law, k, d, status)
        real(wp), intent(in) :: e        !! target restitution coefficient
        real(wp), intent(in) :: tc       !! target contact time [s]
        real(wp), intent(in) :: m        !! effective mass [kg]
        real(wp), intent(in) :: u        !! impact velocity [m s^-1]
        integer, intent(in) :: iend      !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: law       !! HD_DAMPING_*
        real(wp), intent(out) :: k       !! stiffness [N m^-3/2] (0 on error)
        real(wp), intent(out) :: d       !! damping coefficient [kg s^-1 m^-q] (0 on error)
        integer, intent(out) :: status   !! HD_OK or an error code
        real(wp) :: a, ts, tau
        logical :: bound
        call invert_general(e, tc, m, u, iend, .false., 0.0_wp, HD_METHOD_FIT, law, k=k, d=d, status=status, a=a, &
                            ts=ts, tau=tau, bound=bound)
    end subroutine hertzdamp_invert_fit_rest

    !> Every contact the fast path does not serve: the argument checks in their order
    !> (the law, T_c, m, u, k_phys, then e and iend by the method), the dimensionless
    !> inverse by any method and law, the direct formulas of hertzdamp_fit_invert_n where
    !> T_c, m, u allow (so that every method scales alike) and logarithms elsewhere, the
    !> bound, and d = alpha m t*^(-1) (u t*)^(-q) for the law's q.
    pure elemental subroutine invert_general(e, tc, m, u, iend, has_kphys, k_phys, meth, law, tol, accuracy, k, d, &
                                             status, a, ts, tau, bound)
        real(wp), intent(in) :: e, tc, m, u, k_phys
        integer, intent(in) :: iend, meth, law
        logical, intent(in) :: has_kphys
        real(wp), intent(in), optional :: tol, accuracy
        real(wp), intent(out) :: k, d, a, ts, tau
        integer, intent(out) :: status
        logical, intent(out) :: bound
        real(wp) :: lk, lts, q
        k = 0.0_wp
        d = 0.0_wp
        a = 0.0_wp
        tau = 0.0_wp
        ts = 0.0_wp
        bound = .false.
        q = hertzdamp_law_q(law)
        status = hertzdamp_law_status(law)
        if (.not. (tc > 0.0_wp .and. tc <= huge(tc))) status = HD_BAD_TIME
        if (.not. (m > 0.0_wp .and. m <= huge(m))) status = HD_BAD_MASS
        if (.not. (u > 0.0_wp .and. u <= huge(u))) status = HD_BAD_VELOCITY
        if (has_kphys) then
            if (.not. (k_phys > 0.0_wp .and. k_phys <= huge(k_phys))) status = HD_BAD_KPHYS
        end if
        if (status == HD_OK) then
            if (meth == HD_METHOD_FIT) then
                call hertzdamp_fit_inverse(e, iend, a, tau, status, law)
            else
                call hertzdamp_invert_alpha(e, iend, a, tau, status, meth, tol, accuracy, law)
            end if
        end if
        if (status == HD_OK) then
            ts = tc / tau
            if (min(m, u, tc) >= safe_lo .and. max(m, u, tc) <= safe_hi) then
                ! direct path: the formulas of the fast path (every intermediate a normal double)
                call direct_scale(tc, m, u, a, tau, law, k, d)
                if (has_kphys) call apply_bound(a, m, u, k_phys, law, .true., k, d, ts, bound, status)
            else
                ! logarithmic path (extreme inputs)
                lts = log(tc) - log(tau)
                lk = log(m) - 2.5_wp * lts - 0.5_wp * log(u)
                if (has_kphys) then
                    if (log(k_phys) <= lk) then
                        bound = .true.
                        lk = log(k_phys)
                        lts = 0.4_wp * (log(m) - lk) - 0.2_wp * log(u)
                    end if
                end if
                call hertzdamp_safe_exp(lts, ts, status)
                if (bound) then
                    k = k_phys            ! exactly the bound, as on the direct path (not exp(log(k_phys)))
                else
                    call hertzdamp_safe_exp(lk, k, status)
                end if
                if (a > 0.0_wp) call hertzdamp_safe_exp_or_zero(log(a) + log(m) - lts - q * (log(u) + lts), d, status)
            end if
            if (status == HD_OK) then
                if (.not. (abs(d) < huge(d))) status = HD_OUT_OF_RANGE
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
    end subroutine invert_general

    !> k and d from alpha and tau_c by the direct formulas, those of the fit's kernel
    !> (hertzdamp_fit_invert_out.inc, the same operations): r = tau_c / T_c = 1/t*,
    !> s = (r/u)^(1/2), k = m r^2 s, d = alpha m r (r/u)^q.  For T_c, m, u in
    !> [1e-30, 1e30] every intermediate is a normal double.
    pure elemental subroutine direct_scale(tc, m, u, a, tau, law, k, d)
        real(wp), intent(in) :: tc, m, u, a, tau
        integer, intent(in) :: law
        real(wp), intent(out) :: k, d
        real(wp) :: r, s
        r = tau * (1.0_wp / tc)
        s = sqrt(tau * (1.0_wp / (tc * u)))
        k = m * (r * r) * s
        if (law == HD_DAMPING_LINEAR) then
            d = a * m * r
        else if (law == HD_DAMPING_TSUJI) then
            d = a * m * r * sqrt(s)
        else
            d = a * m * r * s
        end if
    end subroutine direct_scale

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
            call hertzdamp_fit_inverse(e, iend, alpha, tau_c, status, law_)
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
