!> The dimensionless reduction of doc/theory.md section 2, and its inverse, for the damping
!> law q (0 linear, the default; 1/4 tsuji; 1/2 kuwabara-kono; doc/damping-laws.md):
!>
!>     t* = m^(2/5) k^(-2/5) u^(-1/5),   alpha = d t* (u t*)^q / m,
!>     k  = m t*^(-5/2) u^(-1/2),         d = alpha m t*^(-1) (u t*)^(-q).
!>
!> All powers are taken in the logarithmic domain so that no intermediate
!> overflows or underflows over the many decades DEM codes use (m down to 1e-20 kg,
!> k up to 1e15 N m^-3/2, ...); a result outside double precision gives
!> HD_OUT_OF_RANGE, never Inf or NaN.
!>
!> The logarithmic forms of t* (hertzdamp_log_tstar), of k (hertzdamp_log_k) and of d
!> (hertzdamp_scale_log_d) are written here once: hertzdamp_reduce and hertzdamp_expand
!> use them, and so does the per-pair API (hertzdamp_pair) for inputs outside the direct
!> range and for the stiffness bound.  (They sit here, below hertzdamp_pair, because the
!> forward maps that use hertzdamp_reduce sit below the host schemes that the pair
!> module calls.)
module hertzdamp_scaling
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: HD_OK, HD_BAD_MASS, HD_BAD_VELOCITY, HD_BAD_STIFFNESS, &
                                HD_BAD_DAMPING, HD_BAD_ALPHA, HD_BAD_TIME, HD_OUT_OF_RANGE
    use hertzdamp_registry, only: hertzdamp_law_q
    use hertzdamp_laws, only: hertzdamp_law_status
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk
    !> Largest and smallest logarithms whose exponential is a normal double.
    real(wp), parameter :: log_huge = log(huge(1.0_wp)) - 1.0_wp
    real(wp), parameter :: log_tiny = log(tiny(1.0_wp)) + 1.0_wp

    public :: hertzdamp_reduce, hertzdamp_expand, hertzdamp_check_positive, hertzdamp_safe_exp, &
              hertzdamp_safe_exp_or_zero
    public :: hertzdamp_log_tstar, hertzdamp_tstar_direct, hertzdamp_log_k, hertzdamp_scale_log_d

contains

    !> Status of a quantity that must be finite and positive: HD_OK or `bad`.
    pure elemental integer function hertzdamp_check_positive(x, bad) result(status)
        real(wp), intent(in) :: x     !! the quantity
        integer, intent(in) :: bad    !! status to return when it is not finite and > 0
        status = HD_OK
        if (.not. ieee_is_finite(x)) then
            status = bad
        else if (x <= 0.0_wp) then
            status = bad
        end if
    end function hertzdamp_check_positive

    !> exp(x) for a logarithm x, with HD_OUT_OF_RANGE instead of overflow or underflow.
    pure elemental subroutine hertzdamp_safe_exp(x, y, status)
        real(wp), intent(in) :: x        !! logarithm of the result
        real(wp), intent(out) :: y       !! exp(x), or 0 on failure
        integer, intent(inout) :: status !! set to HD_OUT_OF_RANGE when exp(x) is not a normal double
        y = 0.0_wp
        if (status /= HD_OK) return
        if (x > log_huge .or. x < log_tiny) then
            status = HD_OUT_OF_RANGE
        else
            y = exp(x)
        end if
    end subroutine hertzdamp_safe_exp

    !> exp(x) like hertzdamp_safe_exp, but a result below the normal range is 0 (not an
    !> error): for quantities where 0 is a valid answer (alpha, d: no damping).
    pure elemental subroutine hertzdamp_safe_exp_or_zero(x, y, status)
        real(wp), intent(in) :: x        !! logarithm of the result
        real(wp), intent(out) :: y       !! exp(x), 0 on underflow or failure
        integer, intent(inout) :: status !! set to HD_OUT_OF_RANGE when exp(x) overflows
        y = 0.0_wp
        if (status /= HD_OK) return
        if (x < log_tiny) return
        call hertzdamp_safe_exp(x, y, status)
    end subroutine hertzdamp_safe_exp_or_zero

    !> ln t* of a contact of mass m, stiffness k and impact speed u from their logarithms:
    !> t* = m^(2/5) k^(-2/5) u^(-1/5).  Two roundings of the one formula, each kept
    !> because public results depend on it bit for bit: grouped = .false.
    !> 0.4 ln m - 0.4 ln k - 0.2 ln u (hertzdamp_reduce, the forward maps); grouped = .true.
    !> 0.4 (ln m - ln k) - 0.2 ln u (the stiffness bound of the inverse).
    pure elemental real(wp) function hertzdamp_log_tstar(lm, lk, lu, grouped) result(lts)
        real(wp), intent(in) :: lm       !! ln m
        real(wp), intent(in) :: lk       !! ln k
        real(wp), intent(in) :: lu       !! ln u
        logical, intent(in) :: grouped   !! which rounding (see above)
        if (grouped) then
            lts = 0.4_wp * (lm - lk) - 0.2_wp * lu
        else
            lts = 0.4_wp * lm - 0.4_wp * lk - 0.2_wp * lu
        end if
    end function hertzdamp_log_tstar

    !> t* = (m / (k u^(1/2)))^(2/5) of a contact of mass m, stiffness k and impact speed u
    !> by the power, for m, k, u in the direct range [1e-30, 1e30] (no overflow there; the
    !> other magnitudes take hertzdamp_log_tstar): the Hertz time of hertzdamp_hertz_time.
    pure elemental real(wp) function hertzdamp_tstar_direct(m, k, u) result(ts)
        real(wp), intent(in) :: m    !! effective mass [kg]
        real(wp), intent(in) :: k    !! Hertz stiffness [N m^-3/2]
        real(wp), intent(in) :: u    !! impact speed [m s^-1]
        ts = (m / (k * sqrt(u)))**0.4_wp
    end function hertzdamp_tstar_direct

    !> ln k = ln m - (5/2) ln t* - (1/2) ln u: the stiffness whose time unit is t*.
    pure elemental real(wp) function hertzdamp_log_k(lts, lm, lu) result(lk)
        real(wp), intent(in) :: lts   !! ln t*
        real(wp), intent(in) :: lm    !! ln m
        real(wp), intent(in) :: lu    !! ln u
        lk = lm - 2.5_wp * lts - 0.5_wp * lu
    end function hertzdamp_log_k

    !> d = alpha m t*^(-1) (u t*)^(-q) by logarithms: 0 for alpha = 0 (no damping), and
    !> HD_OUT_OF_RANGE when d > 0 is not a normal double (an underflow to 0 would be an
    !> undamped contact: issue 30); nothing is done when status is already set.
    pure elemental subroutine hertzdamp_scale_log_d(lts, lm, lu, alpha, q, d, status)
        real(wp), intent(in) :: lts      !! ln t*
        real(wp), intent(in) :: lm       !! ln m
        real(wp), intent(in) :: lu       !! ln u
        real(wp), intent(in) :: alpha    !! damping parameter, >= 0
        real(wp), intent(in) :: q        !! exponent of the law
        real(wp), intent(out) :: d       !! damping coefficient [kg s^-1 m^-q]
        integer, intent(inout) :: status !! HD_OK, or HD_OUT_OF_RANGE
        d = 0.0_wp
        if (alpha > 0.0_wp) call hertzdamp_safe_exp(log(alpha) + lm - lts - q * (lu + lts), d, status)
    end subroutine hertzdamp_scale_log_d

    !> Exponent q of an optional law argument (0 when absent), or HD_BAD_LAW.
    pure subroutine law_exponent(law, q, status)
        integer, intent(in), optional :: law
        real(wp), intent(out) :: q
        integer, intent(out) :: status
        q = 0.0_wp
        status = HD_OK
        if (.not. present(law)) return
        status = hertzdamp_law_status(law)
        q = hertzdamp_law_q(law)
    end subroutine law_exponent

    !> From dimensional inputs to the similarity parameters: alpha and t* [s].
    pure elemental subroutine hertzdamp_reduce(k, d, m, u, alpha, tstar, status, law)
        real(wp), intent(in) :: k        !! Hertz stiffness [N m^-3/2]
        real(wp), intent(in) :: d        !! damping coefficient [kg s^-1 m^-q], >= 0
        real(wp), intent(in) :: m        !! effective mass [kg]
        real(wp), intent(in) :: u        !! impact velocity [m s^-1]
        real(wp), intent(out) :: alpha   !! damping parameter (dimensionless)
        real(wp), intent(out) :: tstar   !! time unit t* [s]
        integer, intent(out) :: status   !! HD_OK or the code naming the bad argument
        integer, intent(in), optional :: law !! HD_DAMPING_* (default linear)
        real(wp) :: ltstar, q
        alpha = 0.0_wp
        tstar = 0.0_wp
        call law_exponent(law, q, status)
        if (status /= HD_OK) return
        status = hertzdamp_check_positive(m, HD_BAD_MASS)
        if (status == HD_OK) status = hertzdamp_check_positive(u, HD_BAD_VELOCITY)
        if (status == HD_OK) status = hertzdamp_check_positive(k, HD_BAD_STIFFNESS)
        if (status == HD_OK) then
            if (.not. ieee_is_finite(d)) then
                status = HD_BAD_DAMPING
            else if (d < 0.0_wp) then
                status = HD_BAD_DAMPING
            end if
        end if
        if (status /= HD_OK) return
        ltstar = hertzdamp_log_tstar(log(m), log(k), log(u), .false.)
        call hertzdamp_safe_exp(ltstar, tstar, status)
        if (d > 0.0_wp) then
            if (q == 0.0_wp) then
                call hertzdamp_safe_exp_or_zero(log(d) + ltstar - log(m), alpha, status)
            else
                call hertzdamp_safe_exp_or_zero(log(d) + ltstar + q * (log(u) + ltstar) - log(m), alpha, status)
            end if
        end if
        if (status /= HD_OK) then
            alpha = 0.0_wp
            tstar = 0.0_wp
        end if
    end subroutine hertzdamp_reduce

    !> From the similarity parameters back to stiffness and damping.
    pure elemental subroutine hertzdamp_expand(alpha, tstar, m, u, k, d, status, law)
        real(wp), intent(in) :: alpha    !! damping parameter, >= 0
        real(wp), intent(in) :: tstar    !! time unit t* [s]
        real(wp), intent(in) :: m        !! effective mass [kg]
        real(wp), intent(in) :: u        !! impact velocity [m s^-1]
        real(wp), intent(out) :: k       !! Hertz stiffness [N m^-3/2]
        real(wp), intent(out) :: d       !! damping coefficient [kg s^-1 m^-q]
        integer, intent(out) :: status   !! HD_OK or the code naming the bad argument
        integer, intent(in), optional :: law !! HD_DAMPING_* (default linear)
        real(wp) :: q
        k = 0.0_wp
        d = 0.0_wp
        call law_exponent(law, q, status)
        if (status /= HD_OK) return
        status = hertzdamp_check_positive(m, HD_BAD_MASS)
        if (status == HD_OK) status = hertzdamp_check_positive(u, HD_BAD_VELOCITY)
        if (status == HD_OK) status = hertzdamp_check_positive(tstar, HD_BAD_TIME)
        if (status == HD_OK) then
            if (.not. ieee_is_finite(alpha)) then
                status = HD_BAD_ALPHA
            else if (alpha < 0.0_wp) then
                status = HD_BAD_ALPHA
            end if
        end if
        if (status /= HD_OK) return
        call hertzdamp_safe_exp(hertzdamp_log_k(log(tstar), log(m), log(u)), k, status)
        call hertzdamp_scale_log_d(log(tstar), log(m), log(u), alpha, q, d, status)
        if (status /= HD_OK) then
            k = 0.0_wp
            d = 0.0_wp
        end if
    end subroutine hertzdamp_expand

end module hertzdamp_scaling
