!> Closed-form constants of the elastic limit (doc/theory.md section 4), computed from
!> the Fortran `gamma` intrinsic, never typed in.
module hertzdamp_constants
    use hertzdamp_kinds, only: hertzdamp_rk
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    public :: hertzdamp_z_max0, hertzdamp_tau_c0, hertzdamp_e1, hertzdamp_beta

    !> pi, for every module of the package and its applications (one definition).
    real(wp), parameter, public :: hertzdamp_pi = acos(-1.0_wp)

    !> Magnitudes (of T_c, m, u, material data) for which the direct, power-free
    !> formulas cannot overflow or underflow; others take a logarithmic path.
    real(wp), parameter, public :: hertzdamp_direct_lo = 1.0e-30_wp, hertzdamp_direct_hi = 1.0e30_wp

    ! The closed forms, evaluated once by the compiler (log_gamma is allowed in
    ! constant expressions), so that the functions below cost nothing in hot loops.
    real(wp), parameter :: z_max0 = 1.25_wp**0.4_wp
    real(wp), parameter :: tau_c0 = 0.8_wp * z_max0 * exp(log_gamma(0.4_wp) + log_gamma(0.5_wp) - log_gamma(0.9_wp))
    !> tau_c(0) as a named constant (hertzdamp_tau_c0 as a function): for the fit kernels,
    !> where a call per contact would cost time.
    real(wp), parameter, public :: hertzdamp_tau_c0_value = tau_c0
    real(wp), parameter :: e1 = 0.8_wp * z_max0 * exp(log_gamma(0.4_wp) + log_gamma(1.5_wp) - log_gamma(1.9_wp))
    ! First-order slopes of the laws q = 0, 1/4, 1/2 (doc/damping-laws.md):
    ! e1(q) = (4/5) z_max0^(1+q) B(2(1+q)/5, 3/2).  Index = law code; q = 0 is e1 above.
    real(wp), parameter :: e1_q(0:2) = [e1, &
        0.8_wp * z_max0**1.25_wp * exp(log_gamma(0.5_wp) + log_gamma(1.5_wp) - log_gamma(2.0_wp)), &
        0.8_wp * z_max0**1.5_wp * exp(log_gamma(0.6_wp) + log_gamma(1.5_wp) - log_gamma(2.1_wp))]

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

    !> First-order restitution slope, e = 1 - e1 alpha + O(alpha^2) (both contact ends):
    !> the energy dissipated along the elastic path.  For the damping law q,
    !> e1(q) = (4/5) z_max0^(1+q) B(2(1+q)/5, 3/2): linear (default) (4/5)(5/4)^(2/5) B(2/5, 3/2),
    !> tsuji pi/sqrt(5), kuwabara-kono (4/5)(5/4)^(3/5) B(3/5, 3/2).  0 for an invalid law.
    pure real(wp) function hertzdamp_e1(law)
        integer, intent(in), optional :: law   !! HD_DAMPING_* (default linear)
        hertzdamp_e1 = e1
        if (present(law)) then
            hertzdamp_e1 = 0.0_wp
            if (law >= lbound(e1_q, 1) .and. law <= ubound(e1_q, 1)) hertzdamp_e1 = e1_q(law)
        end if
    end function hertzdamp_e1

end module hertzdamp_constants
