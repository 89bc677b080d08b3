!> The tsuji closed form as a DEM engine evaluates it, for `hertzdamp bench`: alpha(e) of
!> the overlap end, alpha = sqrt(5) beta(e), beta = -ln e / sqrt(pi^2 + ln^2 e)
!> (Antypov & Elliott 2011), and the engines' damping coefficient d = alpha sqrt(m k)
!> for a given stiffness k (doc/damping-laws.md sections 1 and 4), with the compiler's
!> libm.  In a file of its own, so that the bench calls the one-contact forms as a
!> host calls a library (no inlining across files) and the array forms run a loop the
!> compiler may vectorise (glibc's libmvec for `log`).
module hertzdamp_bench_closed
    use hertzdamp, only: hertzdamp_rk
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk
    real(wp), parameter :: sqrt5 = sqrt(5.0_wp), pi_sq = acos(-1.0_wp)**2

    public :: closed_alpha, closed_d, closed_alpha_n, closed_d_n

contains

    !> alpha = sqrt(5) beta(e) of one contact.
    pure elemental real(wp) function closed_alpha(e) result(alpha)
        real(wp), intent(in) :: e   !! restitution coefficient, 0 < e <= 1
        real(wp) :: l
        l = log(e)
        alpha = -sqrt5 * l / sqrt(pi_sq + l * l)
    end function closed_alpha

    !> d = alpha sqrt(m k) of one contact.
    pure elemental real(wp) function closed_d(e, m, k) result(d)
        real(wp), intent(in) :: e   !! restitution coefficient, 0 < e <= 1
        real(wp), intent(in) :: m   !! effective mass [kg]
        real(wp), intent(in) :: k   !! Hertz stiffness [N m^-3/2]
        real(wp) :: l
        l = log(e)
        d = -sqrt5 * l / sqrt(pi_sq + l * l) * sqrt(m * k)
    end function closed_d

    !> closed_alpha over n contacts in one loop.
    pure subroutine closed_alpha_n(n, e, alpha)
        integer, intent(in) :: n
        real(wp), intent(in) :: e(n)
        real(wp), intent(out) :: alpha(n)
        real(wp) :: l
        integer :: i
        do i = 1, n
            l = log(e(i))
            alpha(i) = -sqrt5 * l / sqrt(pi_sq + l * l)
        end do
    end subroutine closed_alpha_n

    !> closed_d over n contacts in one loop.
    pure subroutine closed_d_n(n, e, m, k, d)
        integer, intent(in) :: n
        real(wp), intent(in) :: e(n), m(n), k(n)
        real(wp), intent(out) :: d(n)
        real(wp) :: l
        integer :: i
        do i = 1, n
            l = log(e(i))
            d(i) = -sqrt5 * l / sqrt(pi_sq + l * l) * sqrt(m(i) * k(i))
        end do
    end subroutine closed_d_n

end module hertzdamp_bench_closed
