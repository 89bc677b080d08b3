!> Internal building blocks of the reference integrator (hertzdamp_rk45): the
!> right-hand sides, one Dormand-Prince 5(4) step with its dense output, the local
!> series at a zero of the overlap for every damping law, and event location and
!> polishing on an accepted step.
!>
!> Not part of the public API: the umbrella module `hertzdamp` does not re-export
!> this module.  The tests use it directly (fixed-step order on a linear test
!> problem, the failure branches of `hertzdamp_locate` and `hertzdamp_polish`).
!>
!> The model family (doc/damping-laws.md):  z'' + alpha z^q z' + z^(3/2) = 0,
!> q = 0 (law 0, linear), 1/4 (law 1, tsuji), 1/2 (law 2, kuwabara-kono).
module hertzdamp_rk45_kernel
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: HD_OK, HD_NO_CONVERGENCE
    use hertzdamp_registry, only: HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO, hertzdamp_law_q
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Right-hand sides the stepper knows (no callbacks: the hot loop stays inlinable).
    integer, parameter, public :: HD_MODEL_HERTZ = 0   !! z'' + alpha |z|^q z' + sign(z)|z|^(3/2) = 0
    integer, parameter, public :: HD_MODEL_LINEAR = 1  !! z'' + alpha z' + z = 0 (test problem, exact solution known)
    !> The Hertz model in the state (z, F), F = -alpha z^q z' - z^(3/2) the total force, alpha > 0, z > 0.
    !> Used after the turning point for the force definition with alpha >= 1: the force
    !> is integrated rather than formed by cancellation, so its zero is well conditioned.
    integer, parameter, public :: HD_MODEL_FORCE = 2

    !> Event kinds: z' = 0 (turning point), total force = 0, switch to the end series.
    integer, parameter, public :: HD_EVENT_TURN = 1, HD_EVENT_FORCE = 2, HD_EVENT_SWITCH = 3

    !> Highest index of the stored local-series coefficients.
    integer, parameter, public :: hertzdamp_kmax_series = 80

    !> Work counters of one integration.
    type, public :: hertzdamp_rk45_stats
        integer :: steps = 0       !! accepted steps
        integer :: rejected = 0    !! rejected steps
        integer :: rhs_evals = 0   !! right-hand-side evaluations (including event polishing)
    end type hertzdamp_rk45_stats

    !> Local series at a zero of the overlap (see hertzdamp_local_series).
    type, public :: hertzdamp_local_series_t
        integer :: kmax = 0                   !! highest power kept
        integer :: nroot = 2                  !! the series is in r = s^(1/nroot)
        real(wp) :: kappa = 1.0_wp            !! scale of r in the powers
        real(wp) :: p(0:hertzdamp_kmax_series) = 0.0_wp  !! coefficients (only 0..kmax are set)
    end type hertzdamp_local_series_t

    public :: hertzdamp_rhs, hertzdamp_zq, hertzdamp_dp_step, hertzdamp_dp_dense
    public :: hertzdamp_local_series, hertzdamp_series_state, hertzdamp_series_root, hertzdamp_series_kappa
    public :: hertzdamp_event_value, hertzdamp_locate, hertzdamp_sub_step, hertzdamp_polish

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

contains

    ! ------------------------------------------------------------------ laws

    !> |z|^q of the law (1, |z|^(1/4), |z|^(1/2)), with sqrt only.
    pure elemental real(wp) function hertzdamp_zq(law, z) result(zq)
        integer, intent(in) :: law   !! HD_DAMPING_*
        real(wp), intent(in) :: z    !! overlap
        select case (law)
        case (HD_DAMPING_TSUJI)
            zq = sqrt(sqrt(abs(z)))
        case (HD_DAMPING_KUWABARA_KONO)
            zq = sqrt(abs(z))
        case default
            zq = 1.0_wp
        end select
    end function hertzdamp_zq

    !> The local series of law q is a power series in r = s^(1/N): N = 2 for q = 0 and
    !> q = 1/2, N = 4 for q = 1/4 (see hertzdamp_local_series).
    pure integer function hertzdamp_series_root(law) result(n)
        integer, intent(in) :: law   !! HD_DAMPING_*
        n = 2
        if (law == HD_DAMPING_TSUJI) n = 4
    end function hertzdamp_series_root

    !> Index shifts of the damping and elastic terms in the series recurrence:
    !> N (1 + q) and 5 N / 2.
    pure subroutine shifts(law, n, s1, s2)
        integer, intent(in) :: law
        integer, intent(out) :: n, s1, s2
        select case (law)
        case (HD_DAMPING_TSUJI)
            n = 4; s1 = 5; s2 = 10
        case (HD_DAMPING_KUWABARA_KONO)
            n = 2; s1 = 3; s2 = 5
        case default
            n = 2; s1 = 2; s2 = 5
        end select
    end subroutine shifts

    !> The scale kappa = max(1, |a|^(1/(N (1+q)))) of r = s^(1/N) in the local series:
    !> it makes the damping coefficient of the scaled recurrence +-1 for strong damping,
    !> so the scaled coefficients stay of order one.
    pure real(wp) function hertzdamp_series_kappa(law, a) result(kappa)
        integer, intent(in) :: law   !! HD_DAMPING_*
        real(wp), intent(in) :: a    !! damping coefficient of the ODE
        select case (law)
        case (HD_DAMPING_TSUJI)
            kappa = max(1.0_wp, abs(a)**0.2_wp)
        case (HD_DAMPING_KUWABARA_KONO)
            kappa = max(1.0_wp, abs(a)**(1.0_wp / 3.0_wp))
        case default
            kappa = max(1.0_wp, sqrt(abs(a)))
        end select
    end function hertzdamp_series_kappa

    ! ------------------------------------------------------------------ right-hand side

    !> Right-hand side of a model (see HD_MODEL_*) for the law.
    pure function hertzdamp_rhs(model, law, alpha, y) result(f)
        integer, intent(in) :: model      !! HD_MODEL_*
        integer, intent(in) :: law        !! HD_DAMPING_*
        real(wp), intent(in) :: alpha     !! damping parameter
        real(wp), intent(in) :: y(2)      !! state
        real(wp) :: f(2)
        real(wp) :: r, zq
        select case (model)
        case (HD_MODEL_HERTZ)
            f(1) = y(2)
            if (law == HD_DAMPING_LINEAR) then
                f(2) = -alpha * y(2) - y(1) * sqrt(abs(y(1)))
            else
                r = sqrt(abs(y(1)))
                zq = r
                if (law == HD_DAMPING_TSUJI) zq = sqrt(r)
                f(2) = -alpha * zq * y(2) - y(1) * r
            end if
        case (HD_MODEL_FORCE)
            ! state (z, F) with F = -alpha z^q z' - z^(3/2) the total contact force:
            ! z' = -(F + z^(3/2)) / (alpha z^q),  F' = -alpha z^q F - (3/2) z^(1/2) z' - alpha q z^(q-1) z'^2
            r = sqrt(abs(y(1)))
            if (law == HD_DAMPING_LINEAR) then
                f(1) = -(y(2) + y(1) * r) / alpha
                f(2) = -alpha * y(2) - 1.5_wp * r * f(1)
            else
                zq = r
                if (law == HD_DAMPING_TSUJI) zq = sqrt(r)
                f(1) = -(y(2) + y(1) * r) / (alpha * zq)
                f(2) = -alpha * zq * y(2) - 1.5_wp * r * f(1)
                if (y(1) > 0.0_wp) f(2) = f(2) - alpha * hertzdamp_law_q(law) * (zq / y(1)) * f(1)**2
            end if
        case default
            f(1) = y(2)
            f(2) = -alpha * y(2) - y(1)
        end select
    end function hertzdamp_rhs

    ! ------------------------------------------------------------------ one step

    !> One Dormand-Prince step of size h from (t, y) with k1 = f(y).  Returns the
    !> 5th-order solution, f at it (FSAL), the error estimate and the dense-output
    !> coefficients of the step.  Six right-hand-side evaluations.  h may be negative
    !> (a step backwards in time).
    pure subroutine hertzdamp_dp_step(model, law, alpha, y, k1, h, ynew, k7, err, cont)
        integer, intent(in) :: model      !! HD_MODEL_*
        integer, intent(in) :: law        !! HD_DAMPING_*
        real(wp), intent(in) :: alpha     !! damping parameter
        real(wp), intent(in) :: y(2)      !! state (z, z') at the start of the step
        real(wp), intent(in) :: k1(2)     !! right-hand side at y
        real(wp), intent(in) :: h         !! step size
        real(wp), intent(out) :: ynew(2)  !! 5th-order solution at t + h
        real(wp), intent(out) :: k7(2)    !! right-hand side at ynew
        real(wp), intent(out) :: err(2)   !! local error estimate (5th minus 4th order)
        real(wp), intent(out) :: cont(2, 5) !! dense-output coefficients (see hertzdamp_dp_dense)
        real(wp), dimension(2) :: k2, k3, k4, k5, k6, ydiff, bspl
        k2 = hertzdamp_rhs(model, law, alpha, y + h * a21 * k1)
        k3 = hertzdamp_rhs(model, law, alpha, y + h * (a31 * k1 + a32 * k2))
        k4 = hertzdamp_rhs(model, law, alpha, y + h * (a41 * k1 + a42 * k2 + a43 * k3))
        k5 = hertzdamp_rhs(model, law, alpha, y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4))
        k6 = hertzdamp_rhs(model, law, alpha, y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5))
        ynew = y + h * (a71 * k1 + a73 * k3 + a74 * k4 + a75 * k5 + a76 * k6)
        k7 = hertzdamp_rhs(model, law, alpha, ynew)
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

    !> Coefficients of the local series at a zero of u for the law q:
    !>     u'' + a u^q u' + u^(3/2) = 0,   u(0) = 0,  u'(0) = c > 0,
    !> has  u(s) = s sum_{k>=0} p_k (kappa r)^k,  r = s^(1/N)  (N = 2 for q = 0 and 1/2,
    !> N = 4 for q = 1/4), with the scale kappa = hertzdamp_series_kappa(law, a).
    !> Substituting, with P = sum p_k (kappa r)^k, D_k = (1 + k/N) p_k (u' = sum D_k (kappa r)^k),
    !> S = P^q * D (u^q u' = s^q S) and Y = P^(3/2) (u^(3/2) = s^(3/2) Y):
    !>     p_0 = c,   p_k (1 + k/N)(k/N) = -(a/kappa^s1) S_{k-s1} - Y_{k-s2} / kappa^s2,
    !> s1 = N (1 + q), s2 = 5N/2 (terms with a negative index are absent); the powers
    !> P^q and P^(3/2) follow from the power-series power rule
    !>     k p_0 X_k = sum_{j=1..k} (g j - (k - j)) p_j X_{k-j}   for X = P^g.
    !> For q = 1/4 only every fifth coefficient is non-zero (a series in s^(5/4)).
    pure subroutine hertzdamp_local_series(law, a, c, kmax, ser, dser)
        integer, intent(in) :: law         !! HD_DAMPING_*
        real(wp), intent(in) :: a          !! damping coefficient of the ODE
        real(wp), intent(in) :: c          !! velocity at the zero, > 0
        integer, intent(in) :: kmax        !! highest index computed (<= hertzdamp_kmax_series)
        type(hertzdamp_local_series_t), intent(out) :: ser !! the coefficients and the scale
        !> if present: the derivatives of the coefficients with respect to c (same scale),
        !> so that hertzdamp_series_state(dser, s) is d(u, u')/dc
        type(hertzdamp_local_series_t), intent(out), optional :: dser
        integer, parameter :: km = hertzdamp_kmax_series
        real(wp) :: y(0:km), dy(0:km), g(0:km), dg(0:km), sv(0:km), dsv(0:km)
        real(wp) :: acc, dacc, ak, ke, wj, q, fn
        integer :: k, j, m, kk, n, s1, s2
        logical :: deriv
        deriv = present(dser)
        call shifts(law, n, s1, s2)
        q = hertzdamp_law_q(law)
        fn = real(n, wp)
        kk = min(kmax, km)
        ser%kmax = kk
        ser%nroot = n
        ser%kappa = hertzdamp_series_kappa(law, a)
        ak = a / ser%kappa**s1
        ke = 1.0_wp / ser%kappa**s2
        ser%p(0:kk) = 0.0_wp
        y(0:kk) = 0.0_wp
        dy(0:kk) = 0.0_wp
        g(0:kk) = 0.0_wp
        dg(0:kk) = 0.0_wp
        sv(0:kk) = 0.0_wp
        dsv(0:kk) = 0.0_wp
        ser%p(0) = c
        y(0) = c * sqrt(c)
        g(0) = c**q
        sv(0) = g(0) * c
        if (deriv) then
            dser%kmax = kk
            dser%nroot = n
            dser%kappa = ser%kappa
            dser%p(0:kk) = 0.0_wp
            dser%p(0) = 1.0_wp
            dy(0) = 1.5_wp * sqrt(c)
            dg(0) = q * c**(q - 1.0_wp)
            dsv(0) = (1.0_wp + q) * g(0)
        end if
        do k = 1, kk
            ! coefficient k from the lower ones
            acc = 0.0_wp
            dacc = 0.0_wp
            if (k >= s1) then
                m = k - s1
                if (law == HD_DAMPING_LINEAR) then
                    acc = ak * ser%p(m) * (1.0_wp + 0.5_wp * m)
                    if (deriv) dacc = ak * dser%p(m) * (1.0_wp + 0.5_wp * m)
                else
                    acc = ak * sv(m)
                    if (deriv) dacc = ak * dsv(m)
                end if
            end if
            if (k >= s2) then
                acc = acc + y(k - s2) * ke
                if (deriv) dacc = dacc + dy(k - s2) * ke
            end if
            if (k >= min(s1, s2)) then
                ser%p(k) = -acc / (real((k + n) * k, wp) / fn**2)
                if (deriv) dser%p(k) = -dacc / (real((k + n) * k, wp) / fn**2)
            end if
            ! Y_k = (P^(3/2))_k by the power rule
            acc = 0.0_wp
            dacc = 0.0_wp
            do j = 1, k
                wj = 1.5_wp * j - (k - j)
                acc = acc + wj * ser%p(j) * y(k - j)
                if (deriv) dacc = dacc + wj * (dser%p(j) * y(k - j) + ser%p(j) * dy(k - j))
            end do
            y(k) = acc / (k * ser%p(0))
            if (deriv) dy(k) = (dacc - k * y(k)) / (k * ser%p(0))
            if (law /= HD_DAMPING_LINEAR) then
                ! G_k = (P^q)_k and S_k = (G * D)_k, D_j = (1 + j/N) p_j
                acc = 0.0_wp
                dacc = 0.0_wp
                do j = 1, k
                    wj = q * j - (k - j)
                    acc = acc + wj * ser%p(j) * g(k - j)
                    if (deriv) dacc = dacc + wj * (dser%p(j) * g(k - j) + ser%p(j) * dg(k - j))
                end do
                g(k) = acc / (k * ser%p(0))
                if (deriv) dg(k) = (dacc - k * g(k)) / (k * ser%p(0))
                acc = 0.0_wp
                dacc = 0.0_wp
                do j = 0, k
                    acc = acc + g(k - j) * (1.0_wp + j / fn) * ser%p(j)
                    if (deriv) dacc = dacc + (dg(k - j) * ser%p(j) + g(k - j) * dser%p(j)) * (1.0_wp + j / fn)
                end do
                sv(k) = acc
                if (deriv) dsv(k) = dacc
            end if
        end do
    end subroutine hertzdamp_local_series

    !> Value and first derivative of the local series at s >= 0: (u(s), u'(s)).
    pure function hertzdamp_series_state(ser, s) result(y)
        type(hertzdamp_local_series_t), intent(in) :: ser !! from hertzdamp_local_series
        real(wp), intent(in) :: s          !! time from the zero of u
        real(wp) :: y(2)
        real(wp) :: r, su, sd, fn
        integer :: k
        if (ser%nroot == 2) then
            r = ser%kappa * sqrt(s)
            su = ser%p(ser%kmax)
            sd = ser%p(ser%kmax) * (1.0_wp + 0.5_wp * ser%kmax)
            do k = ser%kmax - 1, 0, -1
                su = su * r + ser%p(k)
                sd = sd * r + ser%p(k) * (1.0_wp + 0.5_wp * k)
            end do
        else
            fn = real(ser%nroot, wp)
            r = ser%kappa * s**(1.0_wp / fn)
            su = ser%p(ser%kmax)
            sd = ser%p(ser%kmax) * (1.0_wp + ser%kmax / fn)
            do k = ser%kmax - 1, 0, -1
                su = su * r + ser%p(k)
                sd = sd * r + ser%p(k) * (1.0_wp + k / fn)
            end do
        end if
        y(1) = s * su
        y(2) = sd
    end function hertzdamp_series_state

    ! ------------------------------------------------------------------ events

    !> Event functions: HD_EVENT_TURN z'; HD_EVENT_FORCE the total force
    !> -alpha z^q z' - z^(3/2) (the state's F in the (z, F) model);
    !> HD_EVENT_SWITCH z - sigma_sw |z'| (switch to the end series).
    pure real(wp) function hertzdamp_event_value(kind, model, law, y, alpha, sigma_sw) result(g)
        integer, intent(in) :: kind, model, law
        real(wp), intent(in) :: y(2), alpha, sigma_sw
        select case (kind)
        case (HD_EVENT_TURN)
            g = y(2)
        case (HD_EVENT_FORCE)
            if (model == HD_MODEL_FORCE) then
                g = y(2)
            else if (law == HD_DAMPING_LINEAR) then
                g = -alpha * y(2) - y(1) * sqrt(abs(y(1)))
            else
                g = -alpha * hertzdamp_zq(law, y(1)) * y(2) - y(1) * sqrt(abs(y(1)))
            end if
        case default
            g = y(1) - sigma_sw * abs(y(2))
        end select
    end function hertzdamp_event_value

    !> Illinois (modified regula falsi) root of an event function on the dense output
    !> in [lo, hi].  status HD_OK: theta brackets the root to round-off (or hits it);
    !> HD_NO_CONVERGENCE: the event function has no sign change on [lo, hi] (theta = hi)
    !> or the iteration limit was reached before the bracket closed (theta = last iterate).
    pure subroutine hertzdamp_locate(kind, model, law, cont, alpha, sigma_sw, lo, hi, theta, status)
        integer, intent(in) :: kind, model, law
        real(wp), intent(in) :: cont(2, 5), alpha, sigma_sw, lo, hi
        real(wp), intent(out) :: theta     !! fraction of the step at the event
        integer, intent(out) :: status     !! HD_OK or HD_NO_CONVERGENCE
        real(wp) :: a, b, fa, fb, fc, c
        integer :: it, side
        a = lo
        b = hi
        fa = hertzdamp_event_value(kind, model, law, hertzdamp_dp_dense(cont, a), alpha, sigma_sw)
        fb = hertzdamp_event_value(kind, model, law, hertzdamp_dp_dense(cont, b), alpha, sigma_sw)
        theta = b
        status = HD_OK
        if (fa == 0.0_wp) then
            theta = a
            return
        end if
        if (fb == 0.0_wp) return
        if (sign(1.0_wp, fa) == sign(1.0_wp, fb)) then
            status = HD_NO_CONVERGENCE
            return
        end if
        side = 0
        do it = 1, 200
            c = (a * fb - b * fa) / (fb - fa)
            if (.not. (c > min(a, b) .and. c < max(a, b))) c = 0.5_wp * (a + b)
            fc = hertzdamp_event_value(kind, model, law, hertzdamp_dp_dense(cont, c), alpha, sigma_sw)
            theta = c
            if (fc == 0.0_wp .or. abs(b - a) < 4.0_wp * epsilon(1.0_wp)) return
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
            if (abs(b - a) < 1.0e-15_wp) return
        end do
        status = HD_NO_CONVERGENCE
    end subroutine hertzdamp_locate

    !> A Dormand-Prince step of size hs from y (backwards for hs < 0; y itself for hs = 0).
    pure subroutine hertzdamp_sub_step(model, law, y, k1, hs, alpha, ys, stats)
        integer, intent(in) :: model, law
        real(wp), intent(in) :: y(2), k1(2), hs, alpha
        real(wp), intent(out) :: ys(2)
        type(hertzdamp_rk45_stats), intent(inout) :: stats
        real(wp) :: k7(2), errv(2), cont(2, 5)
        if (hs == 0.0_wp) then
            ys = y
            return
        end if
        call hertzdamp_dp_step(model, law, alpha, y, k1, hs, ys, k7, errv, cont)
        stats%rhs_evals = stats%rhs_evals + 6
    end subroutine hertzdamp_sub_step

    !> Polish an event located at theta of the step (t, h): a Dormand-Prince sub-step
    !> from the step start to the trial time gives the event function g there; the trial
    !> time moves by a Newton step (first iteration, exact derivative from the ODE), then
    !> by secant steps on the computed g (they converge also where the sub-step is stiff,
    !> h |lambda| ~ 1, and the ODE's derivative is not that of the computed map), until
    !> the Newton correction is below 1e-6 h; then a second-order Taylor correction to
    !> the event.  out = (time, z, z') at the event.  kind HD_EVENT_TURN: z' = 0;
    !> HD_EVENT_FORCE: total force = 0.  The state and the time always belong together
    !> (a trial time before the step start is reached by a backward sub-step).
    !> status HD_OK, or HD_NO_CONVERGENCE (out = 0) when the correction is not below
    !> 1e-6 h after 12 iterations, a derivative vanishes, or the trial time leaves the
    !> step by more than half a step.
    pure subroutine hertzdamp_polish(kind, model, law, t, y, k1, h, theta, alpha, out, stats, status)
        integer, intent(in) :: kind, model, law
        real(wp), intent(in) :: t, y(2), k1(2), h, theta, alpha
        real(wp), intent(out) :: out(3)
        type(hertzdamp_rk45_stats), intent(inout) :: stats
        integer, intent(out) :: status
        real(wp) :: th, ys(2), f(2), g, dg, delta, zq, r, th_old, g_old, step
        integer :: it
        th = theta
        th_old = theta
        g_old = 0.0_wp
        status = HD_NO_CONVERGENCE
        out = 0.0_wp
        do it = 1, 12
            if (.not. (th >= -0.5_wp .and. th <= 1.5_wp)) return
            call hertzdamp_sub_step(model, law, y, k1, th * h, alpha, ys, stats)
            f = hertzdamp_rhs(model, law, alpha, ys)
            stats%rhs_evals = stats%rhs_evals + 1
            r = sqrt(abs(ys(1)))
            if (model == HD_MODEL_FORCE .or. kind == HD_EVENT_TURN) then
                g = ys(2)
                dg = f(2)
            else if (law == HD_DAMPING_LINEAR) then
                g = -alpha * ys(2) - ys(1) * r
                dg = -alpha * f(2) - 1.5_wp * r * ys(2)
            else
                ! d/dt of -alpha z^q z' - z^(3/2)
                zq = hertzdamp_zq(law, ys(1))
                g = -alpha * zq * ys(2) - ys(1) * r
                dg = -alpha * zq * f(2) - 1.5_wp * r * ys(2)
                if (ys(1) > 0.0_wp) dg = dg - alpha * hertzdamp_law_q(law) * (zq / ys(1)) * ys(2)**2
            end if
            if (dg == 0.0_wp .or. .not. (abs(dg) <= huge(dg))) return
            delta = -g / dg
            if (abs(delta) <= 1.0e-6_wp * abs(h)) then
                ! second-order Taylor correction to the exact event
                out(1) = t + th * h + delta
                out(2) = ys(1) + ys(2) * delta + 0.5_wp * f(2) * delta**2
                out(3) = ys(2) + f(2) * delta
                if (kind == HD_EVENT_TURN) out(3) = 0.0_wp
                if (model == HD_MODEL_FORCE) then
                    out(2) = ys(1) + f(1) * delta
                    ! z' on the zero-force curve: alpha z^q z' = -z^(3/2)
                    out(3) = -out(2) * sqrt(out(2)) / (alpha * hertzdamp_zq(law, out(2)))
                end if
                status = HD_OK
                return
            end if
            step = delta / h
            if (it > 1 .and. g /= g_old) step = -g * (th - th_old) / (g - g_old)
            th_old = th
            g_old = g
            th = th + step
        end do
    end subroutine hertzdamp_polish

end module hertzdamp_rk45_kernel
