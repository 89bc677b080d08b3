!> Calibration: the stiffness k and damping d of a damped-Hertz law fitted to measured
!> restitution coefficients e(u), and optionally contact times T_c(u), at several
!> impact speeds u; and the choice among the damping laws that the data support.
!>
!> Model (law q, effective mass m):  e(u) = E_q(alpha(u)),  T_c(u) = t*(u) tau_q(alpha(u)),
!>     alpha(u) = A u^s,  s = (4q - 1)/5,  A = d m^((2q-3)/5) k^(-2(1+q)/5),
!>     t*(u) = m^(2/5) k^(-2/5) u^(-1/5).
!> The restitution depends on A alone, so e data identify A, i.e. the combination
!> c = d k^(-2(1+q)/5) = A m^((3-2q)/5), and nothing else: any k with d = c k^(2(1+q)/5)
!> gives the same e(u).  The contact time scales with k^(-2/5) at fixed A, so T_c data
!> identify k, and then d.  The fit therefore works in the parameters theta = (ln A, ln k)
!> (ln A only without contact times, or with a known k).
!>
!> Least squares: residuals r = (e - e_model)/sigma_e and (T_c - T_model)/sigma_tc with
!> the given standard uncertainties; without them e residuals are absolute and T_c
!> residuals relative, (T_c - T_model)/T_c, weighted equally, and one scale s is
!> estimated from the residuals.  Levenberg-Marquardt with Marquardt's column scaling:
!> each step solves the damped problem from the SVD of the scaled Jacobian (LAPACK
!> dgesvd); the Jacobian is exact (hertzdamp_calibrate_maps; beyond the fitted maps
!> the reference integrator and its differences).  Converged when the Gauss-Newton
!> correction J^+ r (the linearised distance to the optimum) is below xtol in every
!> ln-parameter, i.e. the parameters are known to xtol relative (1e-10 with the fit),
!> or, with the sigmas given, below 1e-4 of each parameter's standard uncertainty
!> (noisy data: near the optimum the sum of squares cannot tell two points apart in
!> double precision); that last correction is then applied as well.  Without sigmas
!> that uncertainty comes from the residuals and grows with a poor fit, so only xtol
!> counts; when no damped step lowers the sum of squares any more (its rounding, or
!> the reference integrator's noise), plain Gauss-Newton corrections below 1e-3, each
!> at most half the last, continue to xtol.  A fit that stops short is CAL_NO_CONVERGENCE.
!>
!> Uncertainties: covariance (J^T J)^(-1) of theta at the optimum, times s^2 = chi2/dof
!> when no sigmas were given; first-order propagation to k, d and c (in logarithms
!> where a product would over- or underflow: an uncertainty that fits a double is
!> computed, whatever the sigmas).  Goodness of fit:
!> chi2/dof and its p-value Q(dof/2, chi2/2) with sigmas, RMS residuals always.  Law
!> choice: the smallest AIC (chi2 + 2p with sigmas, n ln(chi2/n) + 2p without); every
!> law has the same p for the same data, so this is the smallest chi2 (BIC agrees);
!> never over a law whose fit failed where it might fit better (cal_auto).
!>
!> Nothing is printed and nothing stops: a status (CAL_*) and a one-line message.
module hertzdamp_calibrate
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_OUTSIDE_VALIDITY, HD_END_OVERLAP, HD_END_FORCE, &
                         hertzdamp_fit_forward_deriv, HD_METHOD_FIT, HD_METHOD_RK45, hertzdamp_rk45_default_tol, &
                         hertzdamp_invert_alpha, hertzdamp_reduce
    use hertzdamp_calibrate_maps, only: cal_forward, cal_law_name, cal_law_q, cal_law_speed_exponent, &
                                        cal_law_supported, cal_max_law
    use hertzdamp_text_format, only: fmt_short
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    integer, parameter, public :: CAL_OK = 0              !! success
    integer, parameter, public :: CAL_BAD_DATA = 1        !! invalid values (NaN, u <= 0, e outside (0, 1], ...)
    integer, parameter, public :: CAL_NOT_IDENTIFIED = 2  !! the data cannot determine the parameters
    integer, parameter, public :: CAL_NO_CONVERGENCE = 3  !! the least-squares iteration did not converge
    integer, parameter, public :: CAL_FAILED = 4          !! the forward map or LAPACK failed

    !> Largest |ln| of a parameter or of alpha the fit accepts (beyond: no physical meaning).
    real(wp), parameter :: ln_limit = 200.0_wp
    !> Relative size of the smallest singular value of the scaled Jacobian below which
    !> the parameters are not identified.
    real(wp), parameter :: rank_tol = 1.0e-8_wp
    !> Convergence relative to the statistics: the Gauss-Newton correction below this
    !> fraction of each parameter's standard uncertainty (then applied once more).
    real(wp), parameter :: stat_tol = 1.0e-4_wp
    !> Largest Gauss-Newton correction (in ln-parameters) applied without a decrease
    !> of the sum of squares, when no damped step decreases it any more.
    real(wp), parameter :: polish_max = 1.0e-3_wp
    !> Smallest sigma_e, and sigma_tc relative to tc: the squares of the weighted
    !> residuals of up to 1e5 rows stay below huge (a residual of e is at most 1).
    real(wp), parameter :: sigma_min = 1.0e-150_wp

    !> Measurements: one row per impact.
    type, public :: cal_data
        real(wp), allocatable :: u(:)         !! impact speeds [m/s]
        real(wp), allocatable :: e(:)         !! restitution coefficients
        real(wp), allocatable :: tc(:)        !! contact times [s] (read where has_tc)
        logical, allocatable :: has_tc(:)     !! row has a contact time
        real(wp), allocatable :: sigma_e(:)   !! standard uncertainty of e (read when weighted)
        real(wp), allocatable :: sigma_tc(:)  !! standard uncertainty of tc [s] (read when weighted)
        logical :: weighted = .false.         !! the sigmas are given
        integer, allocatable :: line(:)       !! line of each row in its file, for messages (optional)
    end type cal_data

    !> Settings of a fit.
    type, public :: cal_options
        real(wp) :: mass = 0.0_wp             !! effective mass m [kg], > 0
        real(wp) :: k_known = 0.0_wp          !! > 0: the stiffness is known and only d is fitted
        integer :: iend = HD_END_OVERLAP      !! contact-end definition
        integer :: method = HD_METHOD_FIT     !! HD_METHOD_FIT or HD_METHOD_RK45 (checking)
        real(wp) :: tol = hertzdamp_rk45_default_tol !! rk45 tolerance
        integer :: max_iter = 100             !! Levenberg-Marquardt iterations
        real(wp) :: xtol = 0.0_wp             !! convergence (GN correction in ln); 0: 1e-10 fit, 1e-9 rk45
        real(wp) :: a_start = 0.0_wp          !! > 0: start from this A instead of the data's inverse
        real(wp) :: k_start = 0.0_wp          !! > 0: start from this k instead of the data's inverse
    end type cal_options

    !> Result of the fit of one law.
    type, public :: cal_result
        integer :: law = 0                    !! CAL_LAW_*
        integer :: status = CAL_FAILED        !! CAL_OK or the failure
        character(len=:), allocatable :: message !! failure, '' on success
        character(len=:), allocatable :: note    !! warnings on success ('' if none)
        integer :: n_e = 0                    !! restitution values used
        integer :: n_tc = 0                   !! contact times used
        integer :: n_par = 0                  !! parameters fitted (1 or 2)
        integer :: dof = 0                    !! n_e + n_tc - n_par
        integer :: iterations = 0             !! Levenberg-Marquardt iterations done
        logical :: k_fitted = .false.         !! k estimated from the contact times
        logical :: kd_known = .false.         !! k and d both known (k fitted or given)
        real(wp) :: a = 0.0_wp                !! A = alpha at u = 1 m/s [(m/s)^(-s)]
        real(wp) :: a_err = 0.0_wp            !! its standard uncertainty
        real(wp) :: c = 0.0_wp                !! c = d k^(-2(1+q)/5) (SI units), what e identifies
        real(wp) :: c_err = 0.0_wp            !! its standard uncertainty
        real(wp) :: k = 0.0_wp                !! stiffness [N m^-3/2] (when kd_known)
        real(wp) :: k_err = 0.0_wp            !! its standard uncertainty (0 when given)
        real(wp) :: d = 0.0_wp                !! damping coefficient [kg s^-1 m^-q] (when kd_known)
        real(wp) :: d_err = 0.0_wp            !! its standard uncertainty
        real(wp) :: corr_kd = 0.0_wp          !! correlation of ln k and ln d
        real(wp) :: chi2 = 0.0_wp             !! sum of the squared weighted residuals
        real(wp) :: scale = 1.0_wp            !! s: 1 with sigmas, sqrt(chi2/dof) without
        real(wp) :: p_value = 0.0_wp          !! Q(dof/2, chi2/2) (with sigmas)
        real(wp) :: aic = 0.0_wp              !! Akaike information criterion
        real(wp) :: delta_aic = 0.0_wp        !! AIC - smallest AIC of the candidates (auto)
        real(wp) :: weight = 0.0_wp           !! Akaike weight among the candidates (auto)
        real(wp) :: rms_e = 0.0_wp            !! RMS of e - e_fit
        real(wp) :: rms_tc = 0.0_wp           !! RMS of tc - tc_fit [s] (0 without contact times)
        real(wp) :: gn_step = 0.0_wp          !! last Gauss-Newton correction (max over ln-parameters)
        real(wp), allocatable :: alpha(:)     !! fitted alpha at each row
        real(wp), allocatable :: e_fit(:)     !! fitted e at each row
        real(wp), allocatable :: tc_fit(:)    !! fitted T_c at each row [s] (0 when k unknown)
    end type cal_result

    interface
        !> LAPACK: singular value decomposition A = U diag(S) V^T.
        subroutine dgesvd(jobu, jobvt, m, n, a, lda, s, u, ldu, vt, ldvt, work, lwork, info)
            import :: wp
            implicit none
            character, intent(in) :: jobu, jobvt
            integer, intent(in) :: m, n, lda, ldu, ldvt, lwork
            real(wp), intent(inout) :: a(lda, n)
            real(wp), intent(out) :: s(n)
            real(wp), intent(out) :: u(ldu, n)
            real(wp), intent(out) :: vt(ldvt, n)
            real(wp), intent(out) :: work(lwork)
            integer, intent(out) :: info
        end subroutine dgesvd
    end interface

    public :: cal_make_data, cal_check, cal_fit, cal_auto, cal_model, cal_gamma_q

contains

    !> Measurements from arrays; tc, sigma_e and sigma_tc are optional (a tc that is
    !> not finite and > 0 stays a value and is refused by cal_check; pass has_tc to mark
    !> missing contact times).
    pure function cal_make_data(u, e, tc, sigma_e, sigma_tc, has_tc) result(dat)
        real(wp), intent(in) :: u(:)                  !! impact speeds [m/s]
        real(wp), intent(in) :: e(:)                  !! restitution coefficients
        real(wp), intent(in), optional :: tc(:)       !! contact times [s]
        real(wp), intent(in), optional :: sigma_e(:)  !! uncertainties of e
        real(wp), intent(in), optional :: sigma_tc(:) !! uncertainties of tc [s]
        logical, intent(in), optional :: has_tc(:)    !! which rows have a contact time
        type(cal_data) :: dat
        integer :: n
        n = size(u)
        dat%u = u
        dat%e = e
        allocate (dat%tc(n), dat%sigma_e(n), dat%sigma_tc(n), dat%has_tc(n))
        dat%tc = 0.0_wp
        dat%sigma_e = 1.0_wp
        dat%sigma_tc = 1.0_wp
        dat%has_tc = .false.
        if (present(tc)) then
            dat%tc = tc
            dat%has_tc = .true.
            if (present(has_tc)) dat%has_tc = has_tc
        end if
        dat%weighted = present(sigma_e)
        if (present(sigma_e)) dat%sigma_e = sigma_e
        if (present(sigma_tc)) dat%sigma_tc = sigma_tc
    end function cal_make_data

    !> "line N" (the file's line) or "row N".
    pure function at_row(dat, i) result(s)
        type(cal_data), intent(in) :: dat
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        character(len=16) :: b
        if (allocated(dat%line)) then
            write (b, '(i0)') dat%line(i)
            s = 'line ' // trim(b)
        else
            write (b, '(i0)') i
            s = 'row ' // trim(b)
        end if
    end function at_row

    pure logical function positive(x)
        real(wp), intent(in) :: x
        positive = ieee_is_finite(x) .and. x > 0.0_wp
    end function positive

    !> "line N: NAME must be finite and positive (got X)" when `applies` and x is not
    !> finite and positive, else ''.
    pure function not_positive(dat, i, name, x, applies) result(message)
        type(cal_data), intent(in) :: dat
        integer, intent(in) :: i
        character(len=*), intent(in) :: name
        real(wp), intent(in) :: x
        logical, intent(in) :: applies
        character(len=:), allocatable :: message
        message = ''
        if (applies .and. .not. positive(x)) message = at_row(dat, i) // ': ' // name // &
            ' must be finite and positive (got ' // fmt_short(x) // ')'
    end function not_positive

    !> Whether the data and options can be fitted at all, independently of the law:
    !> CAL_BAD_DATA for invalid values (non-finite, u <= 0, e outside (0, 1], tc or a
    !> sigma <= 0, mass <= 0, arrays of different sizes), CAL_NOT_IDENTIFIED when
    !> the data cannot determine the parameters (fewer than two distinct speeds, e = 1
    !> at every speed).
    pure subroutine cal_check(dat, opts, status, message)
        type(cal_data), intent(in) :: dat       !! measurements
        type(cal_options), intent(in) :: opts   !! settings
        integer, intent(out) :: status          !! CAL_OK, CAL_BAD_DATA or CAL_NOT_IDENTIFIED
        character(len=:), allocatable, intent(out) :: message !! '' on success
        integer :: i, n
        status = CAL_BAD_DATA
        message = ''
        if (.not. (allocated(dat%u) .and. allocated(dat%e) .and. allocated(dat%tc) .and. allocated(dat%has_tc) &
                   .and. allocated(dat%sigma_e) .and. allocated(dat%sigma_tc))) then
            message = 'incomplete data (use cal_make_data)'
            return
        end if
        n = size(dat%u)
        if (size(dat%e) /= n .or. size(dat%tc) /= n .or. size(dat%has_tc) /= n .or. size(dat%sigma_e) /= n &
            .or. size(dat%sigma_tc) /= n) then
            message = 'the data columns have different lengths'
            return
        end if
        if (allocated(dat%line)) then
            if (size(dat%line) /= n) then
                message = 'the line numbers do not match the data'
                return
            end if
        end if
        if (n == 0) then
            message = 'no measurements'
            return
        end if
        if (.not. positive(opts%mass)) then
            message = 'the effective mass must be finite and positive (got ' // fmt_short(opts%mass) // ')'
            return
        end if
        if (.not. (ieee_is_finite(opts%k_known) .and. opts%k_known >= 0.0_wp)) then
            message = 'the known stiffness must be finite and positive (got ' // fmt_short(opts%k_known) // ')'
            return
        end if
        if (opts%iend /= HD_END_OVERLAP .and. opts%iend /= HD_END_FORCE) then
            message = 'invalid contact-end definition'
            return
        end if
        do i = 1, n
            message = not_positive(dat, i, 'the impact speed', dat%u(i), .true.)
            if (len(message) > 0) return
            if (.not. positive(dat%e(i)) .or. dat%e(i) > 1.0_wp) then
                message = at_row(dat, i) // ': e = ' // fmt_short(dat%e(i)) // ' is outside (0, 1]'
                if (dat%e(i) > 1.0_wp .and. ieee_is_finite(dat%e(i))) message = message // &
                    ': a damped contact never returns more energy than it received'
                return
            end if
            message = not_positive(dat, i, 'the contact time', dat%tc(i), dat%has_tc(i))
            if (len(message) > 0) return
            message = not_positive(dat, i, 'sigma_e', dat%sigma_e(i), dat%weighted)
            if (len(message) > 0) return
            if (dat%weighted .and. dat%sigma_e(i) < sigma_min) then
                message = at_row(dat, i) // ': sigma_e = ' // fmt_short(dat%sigma_e(i)) // ' is too small: the ' // &
                          'weighted residuals (e - e_fit)/sigma_e would overflow double precision (sigma_e >= ' // &
                          fmt_short(sigma_min) // ')'
                return
            end if
            message = not_positive(dat, i, 'sigma_tc', dat%sigma_tc(i), dat%weighted .and. dat%has_tc(i))
            if (len(message) == 0 .and. dat%weighted .and. dat%has_tc(i)) then
                if (dat%sigma_tc(i) < sigma_min * dat%tc(i)) message = at_row(dat, i) // ': sigma_tc = ' // &
                    fmt_short(dat%sigma_tc(i)) // ' is too small: the weighted residuals (tc - tc_fit)/sigma_tc ' // &
                    'would overflow double precision (sigma_tc >= ' // fmt_short(sigma_min) // ' tc)'
            end if
            if (len(message) > 0) return
        end do
        status = CAL_NOT_IDENTIFIED
        if (.not. (maxval(dat%u) > minval(dat%u))) then
            message = 'every measurement is at one impact speed (' // fmt_short(dat%u(1)) // ' m/s): the speed ' // &
                      'dependence that tells the laws apart is not measured (for one speed use hertzdamp invert)'
            return
        end if
        if (all(dat%e >= 1.0_wp)) then
            message = 'e = 1 at every speed: the data show no damping, so d and the damping law cannot be fitted'
            return
        end if
        status = CAL_OK
    end subroutine cal_check

    !> Weights of the residuals: 1/sigma, or 1 for e and 1/tc for contact times.
    pure subroutine weights(dat, we, wt)
        type(cal_data), intent(in) :: dat
        real(wp), intent(out) :: we(:), wt(:)
        if (dat%weighted) then
            we = 1.0_wp / dat%sigma_e
            wt = merge(1.0_wp / dat%sigma_tc, 0.0_wp, dat%has_tc)
        else
            we = 1.0_wp
            wt = merge(1.0_wp / dat%tc, 0.0_wp, dat%has_tc)
        end if
    end subroutine weights

    !> Residuals and Jacobian at theta = (ln A[, ln k]).  Rows: e of every
    !> measurement, then tc of the rows that have one (when k is known or fitted).
    pure subroutine evaluate(dat, law, opts, use_tc, beyond, theta, lnk_fixed, we, wt, r, jac, alpha, efit, tcfit, &
                             status)
        type(cal_data), intent(in) :: dat
        integer, intent(in) :: law
        type(cal_options), intent(in) :: opts
        logical, intent(in) :: use_tc
        logical, intent(in) :: beyond(:)   !! per row: the reference integrator beyond the fitted maps
        real(wp), intent(in) :: theta(:), lnk_fixed, we(:), wt(:)
        real(wp), intent(out) :: r(:), jac(:, :), alpha(:), efit(:), tcfit(:)
        integer, intent(out) :: status
        real(wp) :: s, lnk, la, e, tau, de, dtau, tstar
        integer :: i, j, n, st
        n = size(dat%u)
        s = cal_law_speed_exponent(law)
        lnk = lnk_fixed
        if (size(theta) == 2) lnk = theta(2)
        r = 0.0_wp
        jac = 0.0_wp
        alpha = 0.0_wp
        efit = 0.0_wp
        tcfit = 0.0_wp
        status = CAL_FAILED
        if (any(abs(theta) > ln_limit)) return
        j = n
        do i = 1, n
            la = theta(1) + s * log(dat%u(i))
            if (abs(la) > ln_limit) return
            alpha(i) = exp(la)
            call cal_forward(law, opts%iend, opts%method, alpha(i), e, tau, de, dtau, st, opts%tol, beyond(i))
            if (st /= HD_OK) return
            efit(i) = e
            r(i) = (dat%e(i) - e) * we(i)
            jac(i, 1) = -de * alpha(i) * we(i)
            if (use_tc) then
                tstar = exp(0.4_wp * log(opts%mass) - 0.4_wp * lnk - 0.2_wp * log(dat%u(i)))
                tcfit(i) = tstar * tau
                if (dat%has_tc(i)) then
                    j = j + 1
                    r(j) = (dat%tc(i) - tcfit(i)) * wt(i)
                    jac(j, 1) = -tstar * dtau * alpha(i) * wt(i)
                    ! T = t* tau with t* ~ k^(-2/5): dT/dln k = -(2/5) T
                    if (size(theta) == 2) jac(j, 2) = 0.4_wp * tcfit(i) * wt(i)
                end if
            end if
        end do
        if (all(ieee_is_finite(r)) .and. all(ieee_is_finite(jac))) status = CAL_OK
    end subroutine evaluate

    !> alpha with e(alpha) = e_target for one law (a starting point): the library's
    !> algebraic inverse (hertzdamp_invert_alpha, method fit, machine precision) where
    !> it applies; below its range of e, geometric bisection to 1e-6 relative on the
    !> forward map from the first-order guess (1 - e)/2 and a geometric bracket (the
    !> largest alpha reached when e is below what the law reaches).  0 for e = 1.
    pure real(wp) function alpha_of_e(law, opts, e_target) result(alpha)
        integer, intent(in) :: law
        type(cal_options), intent(in) :: opts
        real(wp), intent(in) :: e_target
        real(wp) :: lo, hi, mid, tau
        integer :: it, method, st
        alpha = 0.0_wp
        if (e_target >= 1.0_wp) return
        call hertzdamp_invert_alpha(e_target, opts%iend, alpha, tau, st, HD_METHOD_FIT, law=law)
        if (st == HD_OK .and. alpha > 0.0_wp) return
        alpha = 0.0_wp
        method = opts%method
        lo = 0.0_wp
        hi = max(0.5_wp * (1.0_wp - e_target), 1.0e-12_wp)
        do it = 1, 200   ! bracket: e(lo) > e_target >= e(hi) (or hi beyond the law's range)
            if (.not. above(hi)) exit
            lo = hi
            hi = 2.0_wp * hi
        end do
        if (lo == 0.0_wp) then
            lo = hi
            do it = 1, 200
                lo = 0.5_wp * lo
                if (above(lo)) exit
            end do
        end if
        do it = 1, 60
            if (hi <= lo * (1.0_wp + 1.0e-6_wp)) exit
            mid = sqrt(lo * hi)
            if (above(mid)) then
                lo = mid
            else
                hi = mid
            end if
        end do
        alpha = lo
    contains
        !> The law rebounds at a with e(a) > e_target.
        pure logical function above(a)
            real(wp), intent(in) :: a
            real(wp) :: e, tau, de, dtau
            integer :: st
            call cal_forward(law, opts%iend, method, a, e, tau, de, dtau, st, opts%tol)
            above = st == HD_OK .and. e > e_target
        end function above
    end function alpha_of_e

    !> True when alpha, or up to twice it, lies beyond the fitted forward maps of the
    !> law and end (e < 1e-5, the force end beyond the fit's alpha): a measurement whose
    !> own alpha is there needs the reference integrator in the model.
    pure logical function beyond_maps(law, iend, alpha) result(beyond)
        integer, intent(in) :: law, iend
        real(wp), intent(in) :: alpha
        real(wp) :: e, tau, de, dtau
        integer :: j, st
        beyond = .false.
        if (.not. (alpha > 0.0_wp)) return
        do j = 0, 2
            call hertzdamp_fit_forward_deriv(alpha * (1.0_wp + 0.5_wp * j), iend, law, e, tau, de, dtau, st)
            beyond = beyond .or. st == HD_OUTSIDE_VALIDITY
        end do
    end function beyond_maps

    !> Why the model cannot be evaluated at the starting point theta: a parameter
    !> beyond what the fit accepts (|ln| <= ln_limit; the contact times set k, so
    !> contact times in the wrong unit show here), alpha beyond it at a measured speed,
    !> or residuals that are not finite.
    pure function start_failure(dat, law, theta, fit_k) result(message)
        type(cal_data), intent(in) :: dat
        integer, intent(in) :: law
        real(wp), intent(in) :: theta(:)
        logical, intent(in) :: fit_k
        character(len=:), allocatable :: message
        character(len=:), allocatable :: range
        real(wp) :: la(size(dat%u))
        integer :: i
        la = theta(1) + cal_law_speed_exponent(law) * log(dat%u)
        i = maxloc(abs(la), dim=1)
        range = fmt_short(ln_limit / log(10.0_wp))
        range = '(10^-' // range // ' < X < 10^' // range // ')'
        message = 'the model cannot be evaluated at the starting point'
        if (fit_k) then
            if (abs(theta(2)) > ln_limit) then
                message = 'the contact times give a stiffness k = 10^' // fmt_short(theta(2) / log(10.0_wp)) // &
                          ' N m^-3/2 at the start, beyond what the fit accepts ' // replace_x(range, 'k') // &
                          ': are the contact times in seconds?'
                return
            end if
        end if
        if (abs(la(i)) > ln_limit) message = 'the measured e give alpha = 10^' // fmt_short(la(i) / log(10.0_wp)) // &
            ' at ' // fmt_short(dat%u(i)) // ' m/s (' // at_row(dat, i) // '), beyond what the fit accepts ' // &
            replace_x(range, 'alpha') // ': are the speeds in m/s?'
    contains
        pure function replace_x(text, name) result(r)
            character(len=*), intent(in) :: text, name
            character(len=:), allocatable :: r
            integer :: j
            j = index(text, 'X')
            r = text(1:j - 1) // name // text(j + 1:)
        end function replace_x
    end function start_failure

    !> The starting point: ln A from the mean of ln(alpha_i u_i^-s) over the rows with
    !> e < 1 (alpha_i inverts e_i), ln k from the mean of the k that gives each contact
    !> time with that A (the algebraic inverse of hertzdamp invert).
    pure subroutine start_point(dat, law, opts, use_tc, fit_k, theta, beyond, status, message)
        type(cal_data), intent(in) :: dat
        integer, intent(in) :: law
        type(cal_options), intent(in) :: opts
        logical, intent(in) :: use_tc, fit_k
        real(wp), intent(out) :: theta(:)
        !> per row: the row's own alpha (or up to twice it) lies beyond the fitted maps, so
        !> the model uses the reference integrator there (method fit)
        logical, intent(out) :: beyond(:)
        integer, intent(out) :: status
        character(len=:), allocatable, intent(out) :: message  !! why there is none ('' with one)
        real(wp) :: s, sum_a, sum_k, a, e, tau, de, dtau, tstar
        integer :: i, na, nk, st, it
        logical :: ok
        s = cal_law_speed_exponent(law)
        theta = 0.0_wp
        status = CAL_FAILED
        message = 'no measured e that the law reaches'
        sum_a = 0.0_wp
        na = 0
        beyond = .false.
        do i = 1, size(dat%u)
            a = alpha_of_e(law, opts, dat%e(i))
            beyond(i) = beyond_maps(law, opts%iend, a)
            if (a > 0.0_wp) then
                sum_a = sum_a + log(a) - s * log(dat%u(i))
                na = na + 1
            end if
        end do
        if (na == 0) return
        theta(1) = sum_a / na
        if (opts%a_start > 0.0_wp) theta(1) = log(opts%a_start)
        ! every speed must rebound at the start: lower A until it does
        do it = 1, 60
            ok = .true.
            do i = 1, size(dat%u)
                call cal_forward(law, opts%iend, opts%method, exp(theta(1) + s * log(dat%u(i))), e, tau, de, dtau, &
                                 st, opts%tol, beyond(i))
                ok = ok .and. st == HD_OK
            end do
            if (ok) exit
            theta(1) = theta(1) - 0.5_wp
        end do
        message = 'no starting point where the model rebounds at every measured speed'
        if (.not. ok) return
        message = ''
        if (use_tc .and. fit_k .and. opts%k_start > 0.0_wp) then
            theta(2) = log(opts%k_start)
        else if (use_tc .and. fit_k) then
            sum_k = 0.0_wp
            nk = 0
            do i = 1, size(dat%u)
                if (.not. dat%has_tc(i)) cycle
                call cal_forward(law, opts%iend, opts%method, exp(theta(1) + s * log(dat%u(i))), e, tau, de, dtau, &
                                 st, opts%tol, beyond(i))
                tstar = dat%tc(i) / tau
                ! k = m t*^(-5/2) u^(-1/2)
                sum_k = sum_k + log(opts%mass) - 2.5_wp * log(tstar) - 0.5_wp * log(dat%u(i))
                nk = nk + 1
            end do
            theta(2) = sum_k / nk
        end if
        status = CAL_OK
    end subroutine start_point

    !> ln of the standard deviation of g^T theta, with cov(theta) = W W^T,
    !> W = scale diag(1/colnorm) V diag(1/sv) (first np of each), and the unit vector
    !> along W^T g (correlations are dot products of these).  Summed in logarithms:
    !> no intermediate overflows or underflows where the result itself fits a double.
    !> ln_sd = -huge and dir = 0 when the deviation is zero.
    pure subroutine log_sd(g, vt, sv, colnorm, np, scale, ln_sd, dir)
        real(wp), intent(in) :: g(:), vt(:, :), sv(:), colnorm(:), scale
        integer, intent(in) :: np
        real(wp), intent(out) :: ln_sd, dir(:)
        real(wp) :: lc(np), lmax, w(np), nw
        integer :: i
        ln_sd = -huge(1.0_wp)
        dir = 0.0_wp
        if (.not. (scale > 0.0_wp)) return
        lc = -huge(1.0_wp)
        do i = 1, np
            if (g(i) /= 0.0_wp) lc(i) = log(abs(g(i))) - log(colnorm(i))
        end do
        lmax = maxval(lc)
        w = 0.0_wp
        do i = 1, np
            if (g(i) /= 0.0_wp) w = w + sign(exp(lc(i) - lmax), g(i)) * vt(1:np, i) / sv(1:np)
        end do
        nw = norm2(w)
        if (.not. (nw > 0.0_wp)) return
        dir(1:np) = w / nw
        ln_sd = log(nw) + lmax + log(scale)
    end subroutine log_sd

    !> SVD of the column-scaled Jacobian: jac = U diag(sv) V^T diag(colnorm).
    subroutine scaled_svd(jac, colnorm, u, sv, vt, info)
        real(wp), intent(in) :: jac(:, :)
        real(wp), intent(out) :: colnorm(:), u(:, :), sv(:), vt(:, :)
        integer, intent(out) :: info
        real(wp), allocatable :: a(:, :), work(:)
        integer :: j, m, n, lwork
        m = size(jac, 1)
        n = size(jac, 2)
        a = jac
        do j = 1, n
            colnorm(j) = norm2(jac(:, j))
            if (.not. (colnorm(j) > 0.0_wp)) colnorm(j) = 1.0_wp
            a(:, j) = jac(:, j) / colnorm(j)
        end do
        lwork = max(3 * n + m, 5 * n)   ! the documented minimum of dgesvd for m >= n
        allocate (work(lwork))
        call dgesvd('S', 'A', m, n, a, m, sv, u, m, vt, n, work, lwork, info)
    end subroutine scaled_svd

    !> The checks of cal_fit's input (cal_check, then the law and method) and the default
    !> xtol (o%xtol <= 0: by the method).
    subroutine fit_check(dat, law, o, st, msg)
        type(cal_data), intent(in) :: dat
        integer, intent(in) :: law
        type(cal_options), intent(inout) :: o
        integer, intent(out) :: st
        character(len=:), allocatable, intent(out) :: msg
        call cal_check(dat, o, st, msg)
        if (st /= CAL_OK) return
        if (.not. (o%xtol > 0.0_wp)) o%xtol = merge(1.0e-10_wp, 1.0e-9_wp * max(1.0_wp, o%tol / 1.0e-13_wp), &
                                                     o%method == HD_METHOD_FIT)
        if (cal_law_supported(law, o%method) /= HD_OK) then
            st = CAL_BAD_DATA
            msg = 'unknown damping law or method'
        end if
    end subroutine fit_check

    !> Fit one law to the data.  res%status CAL_OK, or the failure with res%message.
    subroutine cal_fit(dat, law, opts, res)
        type(cal_data), intent(in) :: dat       !! measurements
        integer, intent(in) :: law              !! CAL_LAW_*
        type(cal_options), intent(in) :: opts   !! settings
        type(cal_result), intent(out) :: res    !! the fit
        type(cal_options) :: o
        real(wp), allocatable :: we(:), wt(:), r(:), jac(:, :), rn(:), jn(:, :), u(:, :), alpha(:), efit(:), tcfit(:)
        real(wp), allocatable :: an(:), en(:), tn(:), theta(:), tn_(:), g(:), step(:), gn(:), pred_r(:)
        real(wp) :: sv(2), vt(2, 2), colnorm(2), lambda, nu, cost, cost_new, pred, rho, lnk_fixed
        real(wp) :: stepmax, sd(2), gn_last
        integer :: n, nobs, np, st, info, it, inner, j
        logical :: use_tc, fit_k, accepted, polishing, full_rank, stalled
        logical, allocatable :: beyond(:)
        character(len=:), allocatable :: msg

        res%law = law
        res%message = ''
        res%note = ''
        o = opts
        call fit_check(dat, law, o, st, msg)
        if (st /= CAL_OK) then
            res%status = st
            res%message = msg
            return
        end if
        n = size(dat%u)
        fit_k = any(dat%has_tc) .and. .not. (o%k_known > 0.0_wp)
        use_tc = any(dat%has_tc) .and. (fit_k .or. o%k_known > 0.0_wp)
        lnk_fixed = 0.0_wp
        if (o%k_known > 0.0_wp) lnk_fixed = log(o%k_known)
        np = merge(2, 1, fit_k)
        nobs = n + merge(count(dat%has_tc), 0, use_tc)
        res = cal_result(law=law, message='', note='', n_e=n, n_tc=nobs - n, n_par=np, dof=nobs - np, k_fitted=fit_k, &
                         kd_known=fit_k .or. o%k_known > 0.0_wp)
        allocate (beyond(n), we(n), wt(n), r(nobs), jac(nobs, np), rn(nobs), jn(nobs, np), u(nobs, np), alpha(n), efit(n), &
                  tcfit(n), an(n), en(n), tn(n), theta(np), tn_(np), g(np), step(np), gn(np), pred_r(nobs))
        call weights(dat, we, wt)

        call start_point(dat, law, o, use_tc, fit_k, theta, beyond, st, msg)
        if (st == CAL_OK) then
            call evaluate(dat, law, o, use_tc, beyond, theta, lnk_fixed, we, wt, r, jac, alpha, efit, tcfit, st)
            if (st /= CAL_OK) msg = start_failure(dat, law, theta, fit_k)
        end if
        if (st /= CAL_OK) then
            res%status = CAL_FAILED
            res%message = 'the ' // cal_law_name(law) // ' law: ' // msg
            return
        end if
        cost = sum(r**2)
        lambda = 1.0e-3_wp
        nu = 2.0_wp
        res%status = CAL_NO_CONVERGENCE
        polishing = .false.
        stalled = .false.
        gn_last = huge(1.0_wp)
        do it = 1, o%max_iter
            res%iterations = it
            call scaled_svd(jac, colnorm(1:np), u, sv(1:np), vt(1:np, 1:np), info)
            if (info /= 0) then
                res%status = CAL_FAILED
                res%message = 'LAPACK dgesvd failed'
                return
            end if
            g = matmul(transpose(u), r)   ! U^T r
            full_rank = sv(np) > rank_tol * sv(1)
            if (full_rank) then
                gn = matmul(transpose(vt(1:np, 1:np)), g / sv(1:np)) / colnorm(1:np)
                res%gn_step = maxval(abs(gn))
                if (gauss_newton_converged()) exit
            end if
            accepted = .false.
            if (.not. polishing) accepted = damped_step()
            if (.not. accepted .and. full_rank) accepted = polish_step()
            stalled = .not. accepted
            if (stalled) exit
            call take_trial()
            cost = cost_new
        end do
        res%alpha = alpha
        res%e_fit = efit
        res%tc_fit = tcfit
        ! the sum of squares reached and its AIC, also when the fit failed (cal_auto)
        res%chi2 = cost
        res%aic = merge(cost, nobs * log(max(cost, tiny(1.0_wp)) / nobs), dat%weighted) + 2.0_wp * np
        if (res%status /= CAL_OK) then
            res%message = not_converged(law, res, o%xtol, stalled, sqrt(sum((dat%e - efit)**2) / n))
            return
        end if
        ! identifiability: the scaled Jacobian must have full rank
        if (.not. (sv(np) > rank_tol * sv(1))) then
            res%status = CAL_NOT_IDENTIFIED
            res%message = 'the data do not determine the parameters of the ' // cal_law_name(law) // &
                          ' law (the Jacobian is singular)'
            return
        end if

        call fit_uncertainties(dat, law, o%mass, o%k_known, np, fit_k, use_tc, theta, cost, sv, vt, colnorm, efit, tcfit, res)
        res%status = CAL_OK
    contains
        !> The Gauss-Newton correction J^+ r (ln-parameters): the distance to the optimum.
        !> Converged (done, res%status CAL_OK) when it is below xtol; with the given sigmas
        !> also when it is below stat_tol of every parameter's standard uncertainty (then the
        !> sum of squares cannot resolve it: its relative change is ~ stat_tol^2 / dof), and
        !> that last correction is applied as well.  Without sigmas that uncertainty is
        !> itself estimated from the residuals, so it grows with a poor fit: there only xtol.
        logical function gauss_newton_converged() result(done)
            done = .false.
            do j = 1, np
                sd(j) = sqrt(sum((vt(1:np, j) / sv(1:np))**2)) / colnorm(j)
            end do
            if (res%gn_step <= o%xtol .or. (dat%weighted .and. all(abs(gn) <= stat_tol * sd(1:np)))) then
                ! converged: apply the last Gauss-Newton correction too (the sum of
                ! squares may no longer resolve it, the correction itself is exact)
                tn_ = theta - gn
                call evaluate(dat, law, o, use_tc, beyond, tn_, lnk_fixed, we, wt, rn, jn, an, en, tn, st)
                if (st == CAL_OK) then
                    call scaled_svd(jn, colnorm(1:np), u, sv(1:np), vt(1:np, 1:np), info)
                    if (info == 0) then
                        call take_trial()
                        cost = sum(r**2)
                    else
                        call scaled_svd(jac, colnorm(1:np), u, sv(1:np), vt(1:np, 1:np), info)
                    end if
                end if
                res%status = CAL_OK
                done = .true.
            end if
        end function gauss_newton_converged

        !> Levenberg-Marquardt's damped step from theta: a trial point (tn_, rn, jn, ...)
        !> that lowers the sum of squares (ok), lambda and nu updated.
        logical function damped_step() result(ok)
            ok = .false.
            do inner = 1, 80
                ! damped step in the scaled variables: -V diag(sv/(sv^2 + lambda)) U^T r
                step = -matmul(transpose(vt(1:np, 1:np)), g * sv(1:np) / (sv(1:np)**2 + lambda)) / colnorm(1:np)
                stepmax = maxval(abs(step))
                if (stepmax > 2.0_wp) step = step * (2.0_wp / stepmax)   ! at most a factor e^2 per step
                tn_ = theta + step
                pred_r = r + matmul(jac, step)
                pred = cost - sum(pred_r**2)
                call evaluate(dat, law, o, use_tc, beyond, tn_, lnk_fixed, we, wt, rn, jn, an, en, tn, st)
                rho = -1.0_wp
                if (st == CAL_OK .and. pred > 0.0_wp) then
                    cost_new = sum(rn**2)
                    rho = (cost - cost_new) / pred
                end if
                if (rho > 1.0e-4_wp) then
                    ok = .true.
                    lambda = lambda * max(1.0_wp / 3.0_wp, 1.0_wp - (2.0_wp * rho - 1.0_wp)**3)
                    nu = 2.0_wp
                    exit
                end if
                lambda = lambda * nu
                nu = 2.0_wp * nu
                if (lambda > 1.0e30_wp) exit
            end do
        end function damped_step

        !> No step lowers the sum of squares any more, though the Gauss-Newton correction
        !> is above xtol.  Close to the optimum (a correction below polish_max) that is
        !> the rounding of the sum of squares, or the noise of the reference integrator in
        !> the model, not the optimum: continue with plain Gauss-Newton corrections,
        !> computed from J and r alone, as long as each is at most half the one before
        !> (then they converge to xtol, or the fit stops here, not converged).
        logical function polish_step() result(ok)
            ok = .false.
            if (res%gn_step < 0.5_wp * gn_last .and. res%gn_step <= polish_max) then
                tn_ = theta - gn
                call evaluate(dat, law, o, use_tc, beyond, tn_, lnk_fixed, we, wt, rn, jn, an, en, tn, st)
                ok = st == CAL_OK
                if (ok) cost_new = sum(rn**2)
                polishing = ok
                gn_last = res%gn_step
            end if
        end function polish_step

        !> The trial point (tn_ and what evaluate gave there) becomes the current one.
        subroutine take_trial()
            theta = tn_
            r = rn
            jac = jn
            alpha = an
            efit = en
            tcfit = tn
        end subroutine take_trial
    end subroutine cal_fit

    !> The message of a fit that did not converge after res%iterations (stalled: no step
    !> lowered the sum of squares, rms_e the RMS residual of e there).
    function not_converged(law, res, xtol, stalled, rms_e) result(msg)
        integer, intent(in) :: law
        type(cal_result), intent(in) :: res
        real(wp), intent(in) :: xtol, rms_e
        logical, intent(in) :: stalled
        character(len=:), allocatable :: msg
        character(len=32) :: b
        write (b, '(i0)') res%iterations
        msg = 'the fit of the ' // cal_law_name(law) // ' law did not converge after ' // trim(b) // &
              ' iterations (Gauss-Newton correction ' // fmt_short(res%gn_step) // ' > ' // fmt_short(xtol) // ')'
        if (stalled) msg = msg // ': no step lowers the sum of squares (RMS residual of e ' // &
                           fmt_short(rms_e) // '), yet the Gauss-Newton ' // &
                           'correction does not vanish: the law does not reproduce these data'
    end function not_converged

    !> The uncertainties of a converged fit (res%status set by the caller): the scale and
    !> p-value, the covariance of theta from the SVD (in logarithms where its products
    !> over- or underflow), a, c, k, d with their errors, the RMS residuals and the
    !> chi2 note.
    subroutine fit_uncertainties(dat, law, mass, k_known, np, fit_k, use_tc, theta, cost, sv, vt, colnorm, efit, tcfit, &
                                 res)
        type(cal_data), intent(in) :: dat
        integer, intent(in) :: law, np
        real(wp), intent(in) :: mass, k_known, theta(:), cost, sv(:), vt(:, :), colnorm(:), efit(:), tcfit(:)
        logical, intent(in) :: fit_k, use_tc
        type(cal_result), intent(inout) :: res
        real(wp) :: q, bm, bk, cov(2, 2), var_lnd, ln_sd(3), dir(2, 3)
        integer :: i, j, n
        n = size(dat%u)
        q = cal_law_q(law)
        bm = (3.0_wp - 2.0_wp * q) / 5.0_wp        ! d = A m^bm k^bk
        bk = 2.0_wp * (1.0_wp + q) / 5.0_wp
        if (dat%weighted) then
            res%scale = 1.0_wp
            res%p_value = cal_gamma_q(0.5_wp * res%dof, 0.5_wp * cost)
        else
            res%scale = sqrt(cost / res%dof)
            res%p_value = 0.0_wp
        end if
        ! covariance of theta: (J^T J)^-1 = D^-1 V diag(1/sv^2) V^T D^-1, times s^2
        cov = 0.0_wp
        do i = 1, np
            do j = 1, np
                cov(i, j) = sum(vt(1:np, i) * vt(1:np, j) / sv(1:np)**2) / (colnorm(i) * colnorm(j))
            end do
        end do
        cov(1:np, 1:np) = cov(1:np, 1:np) * res%scale**2
        res%a = exp(theta(1))
        res%a_err = res%a * sqrt(cov(1, 1))
        res%c = exp(theta(1) + bm * log(mass))
        res%c_err = res%c * sqrt(cov(1, 1))
        var_lnd = cov(1, 1)
        if (res%kd_known) then
            if (fit_k) then
                res%k = exp(theta(2))
                res%k_err = res%k * sqrt(cov(2, 2))
                var_lnd = cov(1, 1) + bk**2 * cov(2, 2) + 2.0_wp * bk * cov(1, 2)
                if (var_lnd > 0.0_wp .and. cov(2, 2) > 0.0_wp) then
                    res%corr_kd = (cov(1, 2) + bk * cov(2, 2)) / sqrt(var_lnd * cov(2, 2))
                end if
            else
                res%k = k_known
                res%k_err = 0.0_wp
            end if
            res%d = exp(theta(1) + bm * log(mass) + bk * log(res%k))
            res%d_err = res%d * sqrt(max(var_lnd, 0.0_wp))
        end if
        ! Where a product above over- or underflowed (sigmas of 1e300: J ~ 1e-300 and
        ! (J^T J)^-1 ~ 1e600), the same uncertainties in logarithms, s^2 (J^T J)^-1 = W W^T
        ! with W = s D^-1 V diag(1/sv): each exp(ln value + ln sd), finite whenever the
        ! uncertainty itself fits a double.
        if (.not. (all(ieee_is_finite(cov(1:np, 1:np))) .and. cov(1, 1) > 0.0_wp .and. ieee_is_finite(res%a_err) &
                   .and. ieee_is_finite(res%c_err) .and. ieee_is_finite(res%k_err) .and. ieee_is_finite(res%d_err) &
                   .and. res%scale > 0.0_wp)) then
            call log_sd([1.0_wp, 0.0_wp], vt, sv, colnorm, np, res%scale, ln_sd(1), dir(:, 1))
            res%a_err = exp(theta(1) + ln_sd(1))
            res%c_err = exp(theta(1) + bm * log(mass) + ln_sd(1))
            if (res%kd_known) then
                ln_sd(3) = ln_sd(1)
                if (fit_k) then
                    call log_sd([0.0_wp, 1.0_wp], vt, sv, colnorm, np, res%scale, ln_sd(2), dir(:, 2))
                    call log_sd([1.0_wp, bk], vt, sv, colnorm, np, res%scale, ln_sd(3), dir(:, 3))
                    res%k_err = exp(theta(2) + ln_sd(2))
                    res%corr_kd = dot_product(dir(1:np, 2), dir(1:np, 3))
                end if
                res%d_err = exp(theta(1) + bm * log(mass) + bk * log(res%k) + ln_sd(3))
            end if
        end if
        res%rms_e = sqrt(sum((dat%e - efit)**2) / n)
        if (use_tc) res%rms_tc = sqrt(sum(merge((dat%tc - tcfit)**2, 0.0_wp, dat%has_tc)) / res%n_tc)
        if (dat%weighted .and. res%p_value < 1.0e-3_wp) then
            call add_note(res, 'chi2/dof = ' // fmt_short(cost / res%dof) // ', p = ' // fmt_short(res%p_value) // &
                       ': the data are far from the ' // cal_law_name(law) // ' law (see the residuals)')
        end if
    end subroutine fit_uncertainties

    !> Fit every law and choose the one with the smallest AIC among the fits that
    !> converged.  A law whose fit failed is passed over only when the sum of squares
    !> it reached is already worse than the chosen law's optimum (its iteration
    !> stopped where the law fits the data worse, e.g. on the edge of its range where
    !> it no longer rebounds); otherwise, or when it could not be evaluated at all,
    !> no law is preferred to it: chosen = -1.  res(law) holds each fit (its message
    !> tells why one failed); chosen = the law, or -1.
    subroutine cal_auto(dat, opts, res, chosen)
        type(cal_data), intent(in) :: dat                 !! measurements
        type(cal_options), intent(in) :: opts             !! settings
        type(cal_result), intent(out) :: res(0:cal_max_law) !! one fit per law
        integer, intent(out) :: chosen                    !! CAL_LAW_* of the smallest AIC, -1 if none
        real(wp) :: amin, wsum
        integer :: law, second
        chosen = -1
        do law = 0, cal_max_law
            call cal_fit(dat, law, opts, res(law))
            if (res(law)%status /= CAL_OK) cycle
            if (chosen < 0) then
                chosen = law
            else if (res(law)%aic < res(chosen)%aic) then
                chosen = law
            end if
        end do
        if (chosen < 0) return
        do law = 0, cal_max_law
            if (res(law)%status == CAL_OK) cycle
            if (res(law)%iterations == 0 .or. .not. (res(law)%chi2 > res(chosen)%chi2)) then
                chosen = -1
                return
            end if
            call add_note(res(chosen), 'the ' // cal_law_name(law) // ' law is not compared: its fit failed ' // &
                          'where it fits the data worse (sum of squares ' // fmt_short(res(law)%chi2) // ' > ' // &
                          fmt_short(res(chosen)%chi2) // ')')
        end do
        amin = res(chosen)%aic
        wsum = 0.0_wp
        second = -1
        do law = 0, cal_max_law
            if (res(law)%status /= CAL_OK) cycle
            res(law)%delta_aic = res(law)%aic - amin
            res(law)%weight = exp(-0.5_wp * min(res(law)%delta_aic, 1400.0_wp))
            wsum = wsum + res(law)%weight
            if (law /= chosen) then
                if (second < 0) then
                    second = law
                else if (res(law)%aic < res(second)%aic) then
                    second = law
                end if
            end if
        end do
        do law = 0, cal_max_law
            if (res(law)%status == CAL_OK) res(law)%weight = res(law)%weight / wsum
        end do
        if (second >= 0) then
            if (res(second)%delta_aic < 2.0_wp) then
                call add_note(res(chosen), 'the data do not clearly prefer the ' // cal_law_name(chosen) // &
                              ' law: delta AIC of the ' // cal_law_name(second) // ' law is ' // &
                              fmt_short(res(second)%delta_aic) // ' < 2')
            end if
        end if
    end subroutine cal_auto

    !> The fitted model at impact speeds u: e, and T_c when k is known (tc = 0
    !> otherwise; t* from hertzdamp_reduce, in logarithms as the fit's).  status HD_OK or
    !> the failure of the forward map (then e = tc = 0 there) or of t* (then tc = 0).
    pure elemental subroutine cal_model(law, opts, a, k, u, e, tc, status)
        integer, intent(in) :: law              !! CAL_LAW_*
        type(cal_options), intent(in) :: opts   !! mass, end, method, tol
        real(wp), intent(in) :: a               !! A = alpha at 1 m/s
        real(wp), intent(in) :: k               !! stiffness [N m^-3/2], 0 when unknown
        real(wp), intent(in) :: u               !! impact speed [m/s]
        real(wp), intent(out) :: e              !! restitution coefficient
        real(wp), intent(out) :: tc             !! contact time [s] (0 when k = 0)
        integer, intent(out) :: status          !! HD_OK or the failure
        real(wp) :: tau, de, dtau, alpha0, tstar
        tc = 0.0_wp
        call cal_forward(law, opts%iend, opts%method, a * u**cal_law_speed_exponent(law), e, tau, de, dtau, status, &
                         opts%tol)
        if (status == HD_OK .and. k > 0.0_wp) then
            call hertzdamp_reduce(k, 0.0_wp, opts%mass, u, alpha0, tstar, status)
            if (status == HD_OK) tc = tstar * tau
        end if
    end subroutine cal_model

    !> Append a warning to the note of a result ('; ' between two).
    pure subroutine add_note(res, text)
        type(cal_result), intent(inout) :: res
        character(len=*), intent(in) :: text
        if (len(res%note) > 0) res%note = res%note // '; '
        res%note = res%note // text
    end subroutine add_note

    !> Regularized upper incomplete gamma function Q(a, x) = Gamma(a, x)/Gamma(a)
    !> (a > 0, x >= 0): the p-value of chi2 with nu degrees of freedom is Q(nu/2, chi2/2).
    !> Series of P = 1 - Q for x < a + 1, Legendre's continued fraction (modified
    !> Lentz) for Q beyond; relative accuracy about 1e-14.
    pure elemental real(wp) function cal_gamma_q(a, x) result(q)
        real(wp), intent(in) :: a   !! shape, > 0
        real(wp), intent(in) :: x   !! argument, >= 0
        real(wp), parameter :: eps = epsilon(1.0_wp), fpmin = tiny(1.0_wp) / eps
        real(wp) :: term, total, ap, b, c, d, h, an, del, pref
        integer :: i
        q = 0.0_wp
        if (.not. (a > 0.0_wp .and. x >= 0.0_wp)) return
        q = 1.0_wp
        if (x == 0.0_wp) return
        pref = exp(-x + a * log(x) - log_gamma(a))
        if (x < a + 1.0_wp) then
            ap = a
            term = 1.0_wp / a
            total = term
            do i = 1, 10000
                ap = ap + 1.0_wp
                term = term * x / ap
                total = total + term
                if (abs(term) < abs(total) * eps) exit
            end do
            q = max(0.0_wp, 1.0_wp - total * pref)
        else
            b = x + 1.0_wp - a
            c = 1.0_wp / fpmin
            d = 1.0_wp / b
            h = d
            do i = 1, 10000
                an = -i * (i - a)
                b = b + 2.0_wp
                d = an * d + b
                if (abs(d) < fpmin) d = fpmin
                c = b + an / c
                if (abs(c) < fpmin) c = fpmin
                d = 1.0_wp / d
                del = d * c
                h = h * del
                if (abs(del - 1.0_wp) < eps) exit
            end do
            q = pref * h
        end if
    end function cal_gamma_q

end module hertzdamp_calibrate
