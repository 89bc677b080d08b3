!> Tests of the overlap-definition series and Pade formulas (hertzdamp_series):
!> closed forms at alpha = 0, the first-order restitution coefficient, the
!> time-reversal identity term by term, the odd parity of ln e in
!> beta = alpha e^(-1/10), and the truncated series / Pade values against an
!> independent reference computed here (RK4 with Richardson extrapolation,
!> local series at both ends of the contact).
module test_series_support
    use hertzdamp, only: hertzdamp_rk
    implicit none (type, external)
    private
    integer, parameter :: wp = hertzdamp_rk

    public :: jmul, jpow, jexp, jlog, jcompose, jshift
    public :: tr_residual, beta_ln_e, beta_tce, sensitivity_tolerance
    public :: reference_rk4

    abstract interface
        !> A map from a coefficient vector to a coefficient vector of equal length.
        pure function jet_map(c) result(r)
            import :: wp
            implicit none
            real(wp), intent(in) :: c(0:)
            real(wp) :: r(0:ubound(c, 1))
        end function jet_map
    end interface
    public :: jet_map

contains

    ! ---- truncated power series in double precision -------------------------

    !> Product of two jets.
    pure function jmul(a, b) result(c)
        real(wp), intent(in) :: a(0:), b(0:)
        real(wp) :: c(0:ubound(a, 1))
        integer :: k
        do k = 0, ubound(a, 1)
            c(k) = sum(a(0:k) * b(k:0:-1))
        end do
    end function jmul

    !> Multiplication by the series variable.
    pure function jshift(a) result(c)
        real(wp), intent(in) :: a(0:)
        real(wp) :: c(0:ubound(a, 1))
        c(0) = 0.0_wp
        c(1:) = a(0:ubound(a, 1) - 1)
    end function jshift

    !> Power a**g of a jet with a(0) > 0.
    pure function jpow(a, g) result(q)
        real(wp), intent(in) :: a(0:), g
        real(wp) :: q(0:ubound(a, 1))
        integer :: k, j
        q(0) = a(0)**g
        do k = 1, ubound(a, 1)
            q(k) = 0.0_wp
            do j = 1, k
                q(k) = q(k) + (g * j - (k - j)) * a(j) * q(k - j)
            end do
            q(k) = q(k) / (k * a(0))
        end do
    end function jpow

    !> Exponential of a jet.
    pure function jexp(a) result(r)
        real(wp), intent(in) :: a(0:)
        real(wp) :: r(0:ubound(a, 1))
        integer :: k, j
        r(0) = exp(a(0))
        do k = 1, ubound(a, 1)
            r(k) = 0.0_wp
            do j = 1, k
                r(k) = r(k) + j * a(j) * r(k - j)
            end do
            r(k) = r(k) / k
        end do
    end function jexp

    !> Logarithm of a jet with a(0) > 0.
    pure function jlog(a) result(l)
        real(wp), intent(in) :: a(0:)
        real(wp) :: l(0:ubound(a, 1))
        integer :: k, j
        l(0) = log(a(0))
        do k = 1, ubound(a, 1)
            l(k) = k * a(k)
            do j = 1, k - 1
                l(k) = l(k) - j * l(j) * a(k - j)
            end do
            l(k) = l(k) / (k * a(0))
        end do
    end function jlog

    !> f(g(x)) for a series f and a jet g with g(0) = 0.
    pure function jcompose(f, g) result(r)
        real(wp), intent(in) :: f(0:), g(0:)
        real(wp) :: r(0:ubound(g, 1))
        integer :: k
        r = 0.0_wp
        do k = ubound(f, 1), 0, -1
            r = jmul(r, g)
            r(0) = r(0) + f(k)
        end do
    end function jcompose

    !> Coefficients of e(a) e(-a e(a)^(-1/5)) - 1 (time reversal: all vanish).
    pure function tr_residual(c) result(r)
        real(wp), intent(in) :: c(0:)
        real(wp) :: r(0:ubound(c, 1))
        real(wp) :: w(0:ubound(c, 1))
        w = -jshift(jpow(c, -0.2_wp))
        r = jmul(c, jcompose(c, w))
        r(0) = r(0) - 1.0_wp
    end function tr_residual

    !> Coefficients of ln e as a series in beta = alpha e^(-1/10).
    pure function beta_ln_e(c) result(r)
        real(wp), intent(in) :: c(0:)
        real(wp) :: r(0:ubound(c, 1))
        real(wp) :: g(0:ubound(c, 1)), al(0:ubound(c, 1))
        integer :: it
        g = jlog(c)
        al = 0.0_wp
        do it = 1, ubound(c, 1) + 2          ! alpha(beta) = beta exp(g(alpha)/10)
            al = jshift(jexp(jcompose(g, al) / 10))
        end do
        r = jcompose(g, al)
    end function beta_ln_e

    !> tau_c e^(1/10) as a series in beta = alpha e^(-1/10); c holds the e
    !> coefficients in its first half and the tau_c coefficients in its second.
    pure function beta_tce(c) result(r)
        real(wp), intent(in) :: c(0:)
        real(wp) :: r(0:ubound(c, 1))
        integer :: n, it
        real(wp) :: g(0:(ubound(c, 1) - 1) / 2), al(0:(ubound(c, 1) - 1) / 2)
        n = (ubound(c, 1) - 1) / 2
        g = jlog(c(0:n))
        al = 0.0_wp
        do it = 1, n + 2
            al = jshift(jexp(jcompose(g, al) / 10))
        end do
        r = 0.0_wp
        r(0:n) = jcompose(jmul(c(n + 1:2 * n + 1), jexp(g / 10)), al)
    end function beta_tce

    !> Tolerance for the coefficients of f(c) that should vanish: linear
    !> propagation of the stated coefficient errors, times 4, plus a rounding
    !> allowance of 8 eps |c_k| per coefficient (the terms summed in double have
    !> the size sum_k |df_n/dc_k| |c_k|).
    function sensitivity_tolerance(f, c, cerr) result(tol)
        procedure(jet_map) :: f
        real(wp), intent(in) :: c(0:), cerr(0:)
        real(wp) :: tol(0:ubound(c, 1))
        real(wp) :: base(0:ubound(c, 1)), cp(0:ubound(c, 1)), h
        integer :: k
        base = f(c)
        tol = 0.0_wp
        do k = 0, ubound(c, 1)
            h = 1.0e-6_wp * max(abs(c(k)), 1.0e-3_wp)
            cp = c
            cp(k) = cp(k) + h
            tol = tol + abs(f(cp) - base) / h * (cerr(k) + 8 * epsilon(1.0_wp) * abs(c(k)))
        end do
        tol = 4 * tol + 8 * epsilon(1.0_wp) * maxval(abs(base))
    end function sensitivity_tolerance

    ! ---- independent reference: RK4 + Richardson, local series at both ends --

    !> u, u' at t of the local series of u'' + a u' + u^{3/2} = 0, u(0)=0, u'(0)=c.
    pure subroutine local_series(a, c, t, u, du)
        real(wp), intent(in) :: a, c, t
        real(wp), intent(out) :: u, du
        integer, parameter :: m = 44
        real(wp) :: p(0:m), q(0:m), s, sk
        integer :: k, j, mm
        p = 0.0_wp
        q = 0.0_wp
        p(0) = c
        q(0) = c**1.5_wp
        do mm = 0, m - 2
            k = mm - 3
            if (k >= 1) then
                do j = 1, k
                    q(k) = q(k) + (1.5_wp * j - (k - j)) * p(j) * q(k - j)
                end do
                q(k) = q(k) / (k * c)
            end if
            p(mm + 2) = -a * p(mm) * (1 + 0.5_wp * mm)
            if (k >= 0) p(mm + 2) = p(mm + 2) - q(k)
            p(mm + 2) = p(mm + 2) / (0.25_wp * (mm + 4) * (mm + 2))
        end do
        s = sqrt(t)
        u = 0.0_wp
        du = 0.0_wp
        sk = 1.0_wp
        do k = 0, m
            u = u + t * p(k) * sk
            du = du + 0.5_wp * (k + 2) * p(k) * sk
            sk = sk * s
        end do
    end subroutine local_series

    !> Right-hand side (z', z'') of the contact ODE.
    pure function rhs(a, y) result(f)
        real(wp), intent(in) :: a, y(2)
        real(wp) :: f(2)
        f(1) = y(2)
        f(2) = -a * y(2) - max(y(1), 0.0_wp)**1.5_wp
    end function rhs

    !> nstep classical RK4 steps of size h, compensated summation.
    pure subroutine rk4(a, y, h, nstep)
        real(wp), intent(in) :: a, h
        real(wp), intent(inout) :: y(2)
        integer, intent(in) :: nstep
        real(wp) :: k1(2), k2(2), k3(2), k4(2), comp(2), incr(2), ynew(2)
        integer :: i
        comp = 0.0_wp               ! compensated (Kahan) summation of the increments
        do i = 1, nstep
            k1 = rhs(a, y)
            k2 = rhs(a, y + 0.5_wp * h * k1)
            k3 = rhs(a, y + 0.5_wp * h * k2)
            k4 = rhs(a, y + h * k3)
            incr = h / 6 * (k1 + 2 * k2 + 2 * k3 + k4) - comp
            ynew = y + incr
            comp = (ynew - y) - incr
            y = ynew
        end do
    end subroutine rk4

    !> State at t1 from t0 with RK4 at n, 2n, 4n steps, Richardson to order 6.
    pure subroutine rk4_richardson(a, y0, t0, t1, n, y, err)
        real(wp), intent(in) :: a, y0(2), t0, t1
        integer, intent(in) :: n
        real(wp), intent(out) :: y(2), err
        real(wp) :: ya(2), yb(2), yc(2), r1(2), r2(2)
        ya = y0
        call rk4(a, ya, (t1 - t0) / n, n)
        yb = y0
        call rk4(a, yb, (t1 - t0) / (2 * n), 2 * n)
        yc = y0
        call rk4(a, yc, (t1 - t0) / (4 * n), 4 * n)
        r1 = (16 * yb - ya) / 15
        r2 = (16 * yc - yb) / 15
        y = (32 * r2 - r1) / 31
        err = maxval(abs(y - r2))
    end subroutine rk4_richardson

    !> Reference e, tau_c, z_max, tau_max for damping a; err: estimated
    !> absolute error (Richardson difference, propagated crudely).
    subroutine reference_rk4(a, e, tau_c, z_max, tau_max, err)
        real(wp), intent(in) :: a
        real(wp), intent(out) :: e, tau_c, z_max, tau_max, err
        real(wp), parameter :: t0 = 0.1_wp
        real(wp) :: y0(2), y(2), yt(2), t, ta, t1, h, d, c, sig, f(2), fc(2), fs(2), jac(2, 2), det
        real(wp) :: dc, ds, errs
        integer :: it
        call local_series(a, 1.0_wp, t0, y0(1), y0(2))
        ! coarse pass: time before the turning point and the matching time
        y = y0
        t = t0
        h = 0.01_wp
        ta = -1.0_wp
        t1 = -1.0_wp
        do it = 1, 100000
            if (ta < 0.0_wp .and. y(2) < 0.0_wp) ta = t - 2 * h
            if (y(2) < 0.0_wp .and. y(1) < 0.1_wp * abs(y(2))) then
                t1 = t
                exit
            end if
            call rk4(a, y, h, 1)
            t = t + h
        end do
        ! turning point: Richardson state at ta, then Newton on v with RK4 substeps
        call rk4_richardson(a, y0, t0, ta, 800, yt, err)
        d = 0.0_wp
        do it = 1, 30
            y = yt
            if (d > 0.0_wp) call rk4(a, y, d / 16, 16)
            d = d - y(2) / (-a * y(2) - y(1)**1.5_wp)
        end do
        y = yt
        call rk4(a, y, d / 16, 16)
        tau_max = ta + d
        z_max = y(1)
        ! end of contact: Richardson state at t1, matched to the backward series
        call rk4_richardson(a, y0, t0, t1, 3000, y, errs)
        err = max(err, errs)
        c = abs(y(2))
        sig = y(1) / abs(y(2))
        do it = 1, 40
            f = resid(c, sig)
            fc = resid(c * (1 + 1.0e-7_wp), sig)
            fs = resid(c, sig * (1 + 1.0e-7_wp))
            jac(:, 1) = (fc - f) / (c * 1.0e-7_wp)
            jac(:, 2) = (fs - f) / (sig * 1.0e-7_wp)
            det = jac(1, 1) * jac(2, 2) - jac(1, 2) * jac(2, 1)
            dc = (f(1) * jac(2, 2) - f(2) * jac(1, 2)) / det
            ds = (jac(1, 1) * f(2) - jac(2, 1) * f(1)) / det
            c = c - dc
            sig = sig - ds
        end do
        e = c
        tau_c = t1 + sig
    contains
        function resid(cc, ss) result(r)
            real(wp), intent(in) :: cc, ss
            real(wp) :: r(2), u, du
            call local_series(-a, cc, ss, u, du)
            r(1) = u - y(1)
            r(2) = du + y(2)
        end function resid
    end subroutine reference_rk4

end module test_series_support

program test_series
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_testing, only: test_suite, new_suite
    use hertzdamp, only: hertzdamp_series_eval, hertzdamp_pade_eval, hertzdamp_series_default_order, &
                         hertzdamp_series_max_order, HD_OK, HD_INACCURATE, HD_OUTSIDE_VALIDITY, HD_BAD_ORDER, &
                         hertzdamp_message
    use hertzdamp_series_data, only: series_e, series_e_err, series_tau_c, series_tau_c_err, &
                                     series_z_max, series_tau_max
    use test_series_support, only: tr_residual, beta_ln_e, beta_tce, sensitivity_tolerance, &
                                   reference_rk4
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_finite
    implicit none (type, external)
    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: nmax = hertzdamp_series_max_order
    type(test_suite) :: s
    real(wp) :: zmax0, tauc0, e1, res(0:nmax), tol(0:nmax)
    real(wp) :: both(0:2 * nmax + 1), both_err(0:2 * nmax + 1), res2(0:2 * nmax + 1), tol2(0:2 * nmax + 1)
    real(wp) :: al, re, rt, rz, rm, rerr, e, tc, zm, tm, ee, et, nan
    real(wp) :: ea(3), ta(3)
    real(wp), parameter :: alphas(3) = [0.05_wp, 0.1_wp, 0.2_wp]
    real(wp), parameter :: alphas_pade(4) = [0.3_wp, 0.5_wp, 0.7_wp, 0.8_wp]
    integer, parameter :: orders(3) = [8, hertzdamp_series_default_order, nmax]
    integer :: k, i, j, st, sta(3)
    character(len=80) :: lab

    s = new_suite('series')

    ! --- closed forms at alpha = 0 and first order (Fortran gamma intrinsic)
    zmax0 = 1.25_wp**0.4_wp
    tauc0 = 0.8_wp * zmax0 * gamma(0.4_wp) * gamma(0.5_wp) / gamma(0.9_wp)
    e1 = 0.8_wp * zmax0 * gamma(0.4_wp) * gamma(1.5_wp) / gamma(1.9_wp)
    call s%check_close(series_z_max(0), zmax0, 4 * epsilon(1.0_wp), 'z_max(0) = (5/4)^(2/5)')
    call s%check_close(series_tau_c(0), tauc0, 4 * epsilon(1.0_wp), &
        'tau_c(0) = (4/5)(5/4)^(2/5) B(2/5,1/2)')
    call s%check_close(series_tau_max(0), tauc0 / 2, 4 * epsilon(1.0_wp), 'tau_max(0) = tau_c(0)/2')
    call s%check_close(series_e(0), 1.0_wp, 0.0_wp, 'e(0) = 1')
    call s%check_close(series_e(1), -e1, 4 * epsilon(1.0_wp), 'e_1 = -(4/5)(5/4)^(2/5) B(2/5,3/2)')
    call s%check(series_e(1) < 0.0_wp .and. series_tau_c(1) > 0.0_wp, &
        'e decreases, tau_c increases at 0')

    ! --- time reversal e(a) e(-a e(a)^(-1/5)) = 1, order by order
    res = tr_residual(series_e)
    tol = sensitivity_tolerance(tr_residual, series_e, series_e_err)
    do k = 1, nmax
        write (lab, '(a,i0,a,es9.2)') 'time reversal, order ', k, ', tol ', tol(k)
        call s%check(abs(res(k)) <= tol(k), trim(lab))
    end do
    call s%check(abs(res(0)) <= 4 * epsilon(1.0_wp), 'time reversal, order 0')

    ! --- ln e is odd in beta = alpha e^(-1/10): even coefficients vanish
    res = beta_ln_e(series_e)
    tol = sensitivity_tolerance(beta_ln_e, series_e, series_e_err)
    do k = 0, nmax, 2
        write (lab, '(a,i0,a,es9.2)') 'ln e odd in beta, order ', k, ', tol ', tol(k)
        call s%check(abs(res(k)) <= tol(k), trim(lab))
    end do
    call s%check_close(res(1), -e1, 8 * epsilon(1.0_wp), 'ln e = -e1 beta + O(beta^3)')

    ! --- tau_c e^(1/10) is even in beta: odd coefficients vanish
    both = [series_e, series_tau_c]
    both_err = [series_e_err, series_tau_c_err]
    res2 = beta_tce(both)
    tol2 = sensitivity_tolerance(beta_tce, both, both_err)
    do k = 1, nmax, 2
        write (lab, '(a,i0,a,es9.2)') 'tau_c e^(1/10) even in beta, order ', k, ', tol ', tol2(k)
        call s%check(abs(res2(k)) <= tol2(k), trim(lab))
    end do

    ! --- truncated series against the independent RK4 reference
    do i = 1, size(alphas)
        al = alphas(i)
        call reference_rk4(al, re, rt, rz, rm, rerr)
        do j = 1, size(orders)
            call hertzdamp_series_eval(al, e, tc, z_max=zm, tau_max=tm, order=orders(j), &
                                       err_e=ee, err_tau=et, status=st)
            write (lab, '(a,f5.2,a,i0)') 'series alpha = ', al, ', order ', orders(j)
            call s%check(st == HD_OK, trim(lab) // ': status')
            call s%check_close(e, re, 0.0_wp, trim(lab) // ': e', atol=ee + 10 * rerr + 1.0e-15_wp)
            call s%check_close(tc, rt, 0.0_wp, trim(lab) // ': tau_c', &
                atol=et + 10 * rerr + 4.0e-15_wp)
            if (abs(tc - rt) > 1.0e-13_wp) then
                call s%check(et <= 100 * abs(tc - rt), &
                    trim(lab) // ': tau_c error estimate not too loose')
            end if
            if (orders(j) == nmax) then
                call s%check_close(zm, rz, 0.0_wp, trim(lab) // ': z_max', &
                    atol=10 * rerr + 1.0e-14_wp)
                call s%check_close(tm, rm, 0.0_wp, trim(lab) // ': tau_max', &
                    atol=10 * rerr + 1.0e-13_wp)
            end if
        end do
        ! the default order is accurate to 1e-12 here (its stated purpose)
        call hertzdamp_series_eval(al, e, tc, status=st)
        call s%check_close(e, re, 1.0e-12_wp, 'default order, e, 1e-12')
        call s%check_close(tc, rt, 1.0e-12_wp, 'default order, tau_c, 1e-12')
        call hertzdamp_pade_eval(al, e, tc, z_max=zm, tau_max=tm, err_e=ee, err_tau=et, status=st)
        call s%check(st == HD_OK, 'pade status')
        call s%check_close(e, re, 1.0e-12_wp, 'pade e small alpha', atol=ee + 10 * rerr)
        call s%check_close(tc, rt, 1.0e-12_wp, 'pade tau_c small alpha', atol=et + 10 * rerr)
    end do

    ! --- Pade up to alpha = 0.8 (target 1e-6; generator measured < 1e-10)
    do i = 1, size(alphas_pade)
        al = alphas_pade(i)
        call reference_rk4(al, re, rt, rz, rm, rerr)
        call hertzdamp_pade_eval(al, e, tc, z_max=zm, tau_max=tm, err_e=ee, err_tau=et, status=st)
        write (lab, '(a,f5.2)') 'pade alpha = ', al
        call s%check(st == HD_OK, trim(lab) // ': status')
        call s%check_close(e, re, 1.0e-9_wp, trim(lab) // ': e 1e-9', atol=10 * rerr)
        call s%check_close(tc, rt, 1.0e-9_wp, trim(lab) // ': tau_c 1e-9', atol=10 * rerr)
        call s%check_close(zm, rz, 1.0e-12_wp, trim(lab) // ': z_max', atol=10 * rerr)
        call s%check_close(tm, rm, 1.0e-11_wp, trim(lab) // ': tau_max', atol=10 * rerr)
        call s%check(abs(e - re) <= ee + 10 * rerr + 1.0e-14_wp, &
            trim(lab) // ': e error estimate holds')
        call s%check(abs(tc - rt) <= et + 10 * rerr + 1.0e-14_wp, &
            trim(lab) // ': tau_c error estimate holds')
        ! the full-order series here: its error estimate must hold as well
        call hertzdamp_series_eval(al, e, tc, order=nmax, err_e=ee, err_tau=et)
        call s%check(abs(e - re) <= ee + 10 * rerr + 1.0e-14_wp, &
            trim(lab) // ': series e estimate holds')
        call s%check(abs(tc - rt) <= et + 10 * rerr + 1.0e-14_wp, &
            trim(lab) // ': series tau_c estimate holds')
    end do

    ! --- status handling, elemental use
    nan = ieee_value(1.0_wp, ieee_quiet_nan)
    call hertzdamp_series_eval(nan, e, tc, err_e=ee, status=st)
    call s%check(st == HD_OUTSIDE_VALIDITY .and. abs(e) + abs(tc) < tiny(1.0_wp), &
        'NaN alpha: status 2, zeros')
    call hertzdamp_series_eval(0.9_wp, e, tc, status=st)
    call s%check(st == HD_INACCURATE .and. ieee_is_finite(e), &
        'alpha 0.9: status inaccurate')
    call hertzdamp_series_eval(1.2_wp, e, tc, status=st)
    call s%check(st == HD_OUTSIDE_VALIDITY, 'alpha 1.2: out of range')
    call hertzdamp_series_eval(0.1_wp, e, tc, order=nmax + 1, status=st)
    call s%check(st == HD_BAD_ORDER, 'order too high: bad order')
    call hertzdamp_pade_eval(0.81_wp, e, tc, status=st)
    call s%check(st == HD_OUTSIDE_VALIDITY, 'pade alpha 0.81: out of range')
    call hertzdamp_pade_eval(-0.1_wp, e, tc, status=st)
    call s%check(st == HD_OUTSIDE_VALIDITY, 'pade alpha < 0: out of range')
    call s%check(len(hertzdamp_message(HD_OUTSIDE_VALIDITY)) > 0, 'status message')
    call hertzdamp_series_eval(-0.3_wp, e, tc, status=st)
    call s%check(st == HD_OK .and. e > 1.0_wp, 'negative alpha: e > 1')
    call hertzdamp_series_eval([0.1_wp, 0.2_wp, 0.3_wp], ea, ta, status=sta)
    call s%check(all(sta == 0) .and. ea(1) > ea(2) .and. ea(2) > ea(3) &
                 .and. ta(1) < ta(2) .and. ta(2) < ta(3), &
                 'elemental call: e decreasing, tau_c increasing')

    call s%finish()
end program test_series
