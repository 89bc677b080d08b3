!> Compact engineering formulas (doc/compact.md): closed forms with 4 fitted constants
!> per quantity, exact at e = 1 (alpha = 0), typeable in a spreadsheet.
!>
!> Overlap definition, with L = -ln e, x = L^2 (time reversal: alpha e^(-1/10) is odd
!> in L, tau_c e^(1/10) even):
!>     alpha = e^(1/10) L/e1 (1 + a1 x + a2 x^2)/(1 + a3 x + a4 x^2)
!>     tau_c = e^(-1/10) tau_c0 (1 + b1 x + b2 x^2)/(1 + b3 x + b4 x^2)
!> and forward, with s = alpha/alpha_c:
!>     L     = e1 alpha (1 + p1 alpha)/(1 + p2 alpha + p3 alpha^2) - p4 (ln(1 - s) + s),  e = exp(-L)
!>     tau_c = tau_c0 (1 + q1 alpha + q2 alpha^2)/(1 + q3 alpha) - q4 (ln(1 - s) + s)
!> Force definition, with sigma = L^(1/3) (inverse) or alpha^(1/3) (forward):
!>     alpha/L = (1 + a1 sigma^2 + a2 sigma^3)/(e1 (1 + a3 sigma^2 + a4 sigma^3)),
!>     tau_c = tau_c0 (1 + b1 sigma^2 + b2 sigma^3)/(1 + b3 sigma^2 + b4 sigma^3),
!>     L/alpha = e1 (1 + p1 sigma^2 + p2 sigma^3)/(1 + p3 sigma^2 + p4 sigma^3), tau_c likewise.
!> e1 and tau_c0 come from hertzdamp_constants; the constants from the generator
!> (data/fit_coefficients.csv, `compact` rows).  Accuracy (measured on e in [0.05, 1]):
!> see doc/compact.md.  Range accepted, the range on which the constants were fitted
!> and the accuracy is stated (generated: fit_e_min_compact and the alpha of that e):
!> inverse e >= 0.05 for both definitions (below, the overlap rational has a pole near
!> e = 0.018); forward alpha <= alpha(0.05) = 0.979 (overlap; HD_NO_REBOUND from
!> alpha_c on) and 2.85 (force); outside: HD_BAD_RESTITUTION / HD_OUTSIDE_VALIDITY.
module hertzdamp_compact
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: HD_OK, HD_NO_REBOUND, HD_BAD_END, HD_BAD_ALPHA, HD_BAD_RESTITUTION, &
                                HD_OUTSIDE_VALIDITY
    use hertzdamp_registry, only: HD_END_OVERLAP, HD_END_FORCE
    use hertzdamp_constants, only: hertzdamp_e1, hertzdamp_tau_c0
    use hertzdamp_fit_data
    use hertzdamp_fit, only: hertzdamp_approx_alpha_status
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Smallest e accepted by the compact inverse, overlap: the lower end of the fitted
    !> range (generated), where the stated accuracy holds (doc/compact.md).
    real(wp), parameter, public :: hertzdamp_compact_e_min_overlap = fit_e_min_compact
    !> Smallest e accepted by the compact inverse, force (the same fitted range).
    real(wp), parameter, public :: hertzdamp_compact_e_min_force = fit_e_min_compact
    !> Largest alpha accepted by the compact forward map, overlap: alpha(e_min) (generated).
    real(wp), parameter, public :: hertzdamp_compact_alpha_max_overlap = fit_compact_alpha_max_overlap
    !> Largest alpha accepted by the compact forward map, force: alpha(e_min) (generated).
    real(wp), parameter, public :: hertzdamp_compact_alpha_max_force = fit_compact_alpha_max_force

    !> Relative accuracy of the generated range ends alpha(e_min) (reference integrator).
    real(wp), parameter :: range_tol = 1.0e-12_wp

    public :: hertzdamp_compact_inverse, hertzdamp_compact_forward

contains

    !> Inverse compact rule e -> (alpha, tau_c).  HD_BAD_RESTITUTION for e outside
    !> [e_min, 1] (e_min = 0.05 for both definitions: the fitted range).
    pure elemental subroutine hertzdamp_compact_inverse(e, iend, alpha, tau_c, status)
        real(wp), intent(in) :: e          !! restitution coefficient
        integer, intent(in) :: iend        !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out) :: alpha     !! damping parameter
        real(wp), intent(out) :: tau_c     !! dimensionless contact duration
        integer, intent(out) :: status     !! HD_OK, HD_BAD_RESTITUTION or HD_BAD_END
        real(wp) :: l, x, s, g
        alpha = 0.0_wp
        tau_c = 0.0_wp
        status = HD_OK
        if (iend == HD_END_OVERLAP) then
            if (.not. (e >= hertzdamp_compact_e_min_overlap .and. e <= 1.0_wp)) then
                status = HD_BAD_RESTITUTION
                return
            end if
            l = 0.0_wp - log(e)   ! +0 at e = 1 (-log(1) is -0)
            x = l * l
            g = e**0.1_wp
            alpha = g * l / hertzdamp_e1() * (1.0_wp + fit_cov_inv_a_1 * x + fit_cov_inv_a_2 * x * x) &
                    / (1.0_wp + fit_cov_inv_a_3 * x + fit_cov_inv_a_4 * x * x)
            tau_c = hertzdamp_tau_c0() / g * (1.0_wp + fit_cov_inv_t_1 * x + fit_cov_inv_t_2 * x * x) &
                    / (1.0_wp + fit_cov_inv_t_3 * x + fit_cov_inv_t_4 * x * x)
        else if (iend == HD_END_FORCE) then
            if (.not. (e >= hertzdamp_compact_e_min_force .and. e <= 1.0_wp)) then
                status = HD_BAD_RESTITUTION
                return
            end if
            l = 0.0_wp - log(e)   ! +0 at e = 1 (-log(1) is -0)
            s = l**(1.0_wp / 3)
            alpha = l * (1.0_wp + fit_cfo_inv_a_1 * s**2 + fit_cfo_inv_a_2 * s**3) &
                    / (hertzdamp_e1() * (1.0_wp + fit_cfo_inv_a_3 * s**2 + fit_cfo_inv_a_4 * s**3))
            tau_c = hertzdamp_tau_c0() * (1.0_wp + fit_cfo_inv_t_1 * s**2 + fit_cfo_inv_t_2 * s**3) &
                    / (1.0_wp + fit_cfo_inv_t_3 * s**2 + fit_cfo_inv_t_4 * s**3)
        else
            status = HD_BAD_END
        end if
    end subroutine hertzdamp_compact_inverse

    !> Forward compact rule alpha -> (e, tau_c).  Overlap: HD_NO_REBOUND (e = 0,
    !> tau_c = +inf) for alpha >= alpha_c; force: HD_OUTSIDE_VALIDITY beyond alpha = 2.9.
    pure elemental subroutine hertzdamp_compact_forward(alpha, iend, e, tau_c, status)
        real(wp), intent(in) :: alpha      !! damping parameter
        integer, intent(in) :: iend        !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out) :: e         !! restitution coefficient
        real(wp), intent(out) :: tau_c     !! dimensionless contact duration
        integer, intent(out) :: status     !! HD_OK, HD_NO_REBOUND or an error
        real(wp) :: s, lg, l
        e = 0.0_wp
        tau_c = 0.0_wp
        status = hertzdamp_approx_alpha_status(alpha, iend)
        if (status /= HD_OK) then
            continue
        else if (iend == HD_END_OVERLAP) then
            if (alpha >= fit_alpha_c) then
                status = HD_NO_REBOUND
                tau_c = ieee_value(1.0_wp, ieee_positive_inf)
                return
            end if
            ! e < e_min: beyond the fitted range (36 % off near alpha_c); the end itself is
            ! known to the reference integrator's 1e-12
            if (alpha > hertzdamp_compact_alpha_max_overlap * (1.0_wp + range_tol)) then
                status = HD_OUTSIDE_VALIDITY
                return
            end if
            s = alpha / fit_alpha_c
            lg = log(1.0_wp - s) + s
            l = hertzdamp_e1() * alpha * (1.0_wp + fit_cov_fwd_l_1 * alpha) &
                / (1.0_wp + fit_cov_fwd_l_2 * alpha + fit_cov_fwd_l_3 * alpha * alpha) - fit_cov_fwd_l_4 * lg
            e = exp(-l)
            tau_c = hertzdamp_tau_c0() * (1.0_wp + fit_cov_fwd_t_1 * alpha + fit_cov_fwd_t_2 * alpha * alpha) &
                    / (1.0_wp + fit_cov_fwd_t_3 * alpha) - fit_cov_fwd_t_4 * lg
        else
            if (alpha > hertzdamp_compact_alpha_max_force * (1.0_wp + range_tol)) then
                status = HD_OUTSIDE_VALIDITY
                return
            end if
            s = alpha**(1.0_wp / 3)
            l = hertzdamp_e1() * alpha * (1.0_wp + fit_cfo_fwd_l_1 * s**2 + fit_cfo_fwd_l_2 * s**3) &
                / (1.0_wp + fit_cfo_fwd_l_3 * s**2 + fit_cfo_fwd_l_4 * s**3)
            e = exp(-l)
            tau_c = hertzdamp_tau_c0() * (1.0_wp + fit_cfo_fwd_t_1 * s**2 + fit_cfo_fwd_t_2 * s**3) &
                    / (1.0_wp + fit_cfo_fwd_t_3 * s**2 + fit_cfo_fwd_t_4 * s**3)
        end if
    end subroutine hertzdamp_compact_forward

end module hertzdamp_compact
