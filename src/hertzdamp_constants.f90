!> Closed-form constants of the elastic limit (doc/theory.md section 4), computed from
!> the Fortran `gamma` intrinsic, never typed in.
module hertzdamp_constants
    use hertzdamp_kinds, only: hertzdamp_rk
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    public :: hertzdamp_z_max0, hertzdamp_tau_c0, hertzdamp_e1, hertzdamp_beta

    ! The closed forms, evaluated once by the compiler (log_gamma is allowed in
    ! constant expressions), so that the functions below cost nothing in hot loops.
    real(wp), parameter :: z_max0 = 1.25_wp**0.4_wp
    real(wp), parameter :: tau_c0 = 0.8_wp * z_max0 * exp(log_gamma(0.4_wp) + log_gamma(0.5_wp) - log_gamma(0.9_wp))
    real(wp), parameter :: e1 = 0.8_wp * z_max0 * exp(log_gamma(0.4_wp) + log_gamma(1.5_wp) - log_gamma(1.9_wp))

contains

    !> Euler's beta function B(a, b) = Gamma(a) Gamma(b) / Gamma(a + b).
    pure elemental real(wp) function hertzdamp_beta(a, b)
        real(wp), intent(in) :: a  !! first argument, > 0
        real(wp), intent(in) :: b  !! second argument, > 0
        hertzdamp_beta = exp(log_gamma(a) + log_gamma(b) - log_gamma(a + b))
    end function hertzdamp_beta

    !> Deepest overlap of the elastic collision, z_max(0) = (5/4)^(2/5).
    pure real(wp) function hertzdamp_z_max0()
        hertzdamp_z_max0 = z_max0
    end function hertzdamp_z_max0

    !> Elastic contact duration, tau_c(0) = (4/5) (5/4)^(2/5) B(2/5, 1/2).
    pure real(wp) function hertzdamp_tau_c0()
        hertzdamp_tau_c0 = tau_c0
    end function hertzdamp_tau_c0

    !> First-order restitution slope, e = 1 - e1 alpha + O(alpha^2),
    !> e1 = (4/5) (5/4)^(2/5) B(2/5, 3/2).
    pure real(wp) function hertzdamp_e1()
        hertzdamp_e1 = e1
    end function hertzdamp_e1

end module hertzdamp_constants
