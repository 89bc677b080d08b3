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
module hertzdamp_scaling
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_OK, HD_BAD_MASS, HD_BAD_VELOCITY, HD_BAD_STIFFNESS, &
                                HD_BAD_DAMPING, HD_BAD_ALPHA, HD_BAD_TIME, HD_OUT_OF_RANGE
    use hertzdamp_laws, only: hertzdamp_law_q, hertzdamp_law_status
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk
    !> Largest and smallest logarithms whose exponential is a normal double.
    real(wp), parameter :: log_huge = log(huge(1.0_wp)) - 1.0_wp
    real(wp), parameter :: log_tiny = log(tiny(1.0_wp)) + 1.0_wp

    public :: hertzdamp_reduce, hertzdamp_expand, hertzdamp_check_positive, hertzdamp_safe_exp, &
              hertzdamp_safe_exp_or_zero

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
        ltstar = 0.4_wp * log(m) - 0.4_wp * log(k) - 0.2_wp * log(u)
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
        call hertzdamp_safe_exp(log(m) - 2.5_wp * log(tstar) - 0.5_wp * log(u), k, status)
        if (alpha > 0.0_wp) then
            if (q == 0.0_wp) then
                call hertzdamp_safe_exp_or_zero(log(alpha) + log(m) - log(tstar), d, status)
            else
                call hertzdamp_safe_exp_or_zero(log(alpha) + log(m) - log(tstar) - q * (log(u) + log(tstar)), d, &
                                                status)
            end if
        end if
        if (status /= HD_OK) then
            k = 0.0_wp
            d = 0.0_wp
        end if
    end subroutine hertzdamp_expand

end module hertzdamp_scaling
