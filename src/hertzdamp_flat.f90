!> The flat entry points behind the legacy Fortran (`hertzdamp_legacy.f90`) and C
!> (`hertzdamp_capi`) interfaces: one place that fixes the method they use and how a
!> failure is reported, so that both interfaces give bit-identical numbers (and the
!> same as the module API: hertzdamp_invert with method = HD_METHOD_FIT).
!> Callers must `use` this module at module level, never inside a procedure: see
!> hertzdamp_legacy.f90 on the floating-point environment.
!>
!> Everything here needs only the Fortran runtime (no GSL, no LAPACK).
module hertzdamp_flat
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_OK, HD_NO_REBOUND
    use hertzdamp_methods, only: hertzdamp_forward_dim, HD_METHOD_FIT
    use hertzdamp_inverse, only: mod_invert => hertzdamp_invert, hertzdamp_invert_alpha, hertzdamp_invert_fit_rest
    use hertzdamp_laws, only: HD_DAMPING_LINEAR
    use hertzdamp_fit, only: hertzdamp_fit_invert
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> The method of every legacy and C entry point (forward and inverse): the fit,
    !> which needs nothing but the Fortran runtime.
    integer, parameter, public :: legacy_method = HD_METHOD_FIT

    public :: flat_invert, flat_invert_n, flat_invert_bounded, flat_pair, flat_forward
    public :: flat_invert_law, flat_invert_law_n, flat_pair_law, flat_forward_law

contains

    !> k and d for target restitution e and contact time tc (doc/theory.md section 6).
    !> On failure k = d = 0 and status names the bad argument.
    pure elemental subroutine flat_invert(e, tc, m, u, iend, k, d, status)
        real(wp), intent(in) :: e        !! target restitution coefficient: 1e-3 <= e <= 1 (overlap), 1e-4 <= e <= 1 (force)
        real(wp), intent(in) :: tc       !! target contact time [s]
        real(wp), intent(in) :: m        !! effective mass [kg]
        real(wp), intent(in) :: u        !! impact velocity [m s^-1]
        integer, intent(in) :: iend      !! 0 overlap, 1 force
        real(wp), intent(out) :: k       !! Hertz stiffness [N m^-3/2]
        real(wp), intent(out) :: d       !! damping coefficient [kg s^-1]
        integer, intent(out) :: status   !! HD_OK or an error code
        real(wp) :: a, tau
        ! what hertzdamp_invert does for the fit without optional arguments, without the
        ! layer of its optional arguments: the fit's kernel, then the general path for the
        ! contacts the kernel does not serve (the kernel is not run again)
        call hertzdamp_fit_invert(e, tc, m, u, iend, k, d, a, tau, status)
        if (status /= HD_OK) call hertzdamp_invert_fit_rest(e, tc, m, u, iend, HD_DAMPING_LINEAR, k, d, status)
        if (status /= HD_OK) then
            k = 0.0_wp
            d = 0.0_wp
        end if
    end subroutine flat_invert

    !> flat_invert for n contacts: the rank-1 form of hertzdamp_invert (the fit runs
    !> vectorised over the arrays); the results of n calls of flat_invert, bit for bit.
    pure subroutine flat_invert_n(n, e, tc, m, u, iend, k, d, status)
        integer, intent(in) :: n          !! number of contacts (>= 0)
        real(wp), intent(in) :: e(n)      !! target restitution coefficients
        real(wp), intent(in) :: tc(n)     !! target contact times [s]
        real(wp), intent(in) :: m(n)      !! effective masses [kg]
        real(wp), intent(in) :: u(n)      !! impact velocities [m s^-1]
        integer, intent(in) :: iend       !! 0 overlap, 1 force
        real(wp), intent(out) :: k(n)     !! Hertz stiffnesses [N m^-3/2] (0 on failure)
        real(wp), intent(out) :: d(n)     !! damping coefficients [kg s^-1] (0 on failure)
        integer, intent(out) :: status(n) !! HD_OK or an error code, per contact
        call mod_invert(e, tc, m, u, iend, k, d, status, method=legacy_method)
    end subroutine flat_invert_n

    !> flat_invert with the physical-stiffness bound k_phys: where k_phys <= k the
    !> contact keeps k = k_phys and d = alpha m^(3/5) k_phys^(2/5) u^(1/5) (it is then
    !> longer than tc: k_phys is softer).  On failure k = d = 0 and status names the bad argument.
    pure elemental subroutine flat_invert_bounded(e, tc, m, u, k_phys, iend, k, d, status)
        real(wp), intent(in) :: e        !! target restitution coefficient
        real(wp), intent(in) :: tc       !! target contact time [s]
        real(wp), intent(in) :: m        !! effective mass [kg]
        real(wp), intent(in) :: u        !! impact velocity [m s^-1]
        real(wp), intent(in) :: k_phys   !! physical stiffness (4/3) E* sqrt(R*) [N m^-3/2]
        integer, intent(in) :: iend      !! 0 overlap, 1 force
        real(wp), intent(out) :: k       !! Hertz stiffness [N m^-3/2]
        real(wp), intent(out) :: d       !! damping coefficient [kg s^-1]
        integer, intent(out) :: status   !! HD_OK or an error code
        call mod_invert(e, tc, m, u, iend, k, d, status, k_phys=k_phys, method=legacy_method)
        if (status /= HD_OK) then
            k = 0.0_wp
            d = 0.0_wp
        end if
    end subroutine flat_invert_bounded

    !> The per-material-pair constants alpha(e) and tau_c(alpha(e)): a host stores them
    !> once per pair and forms, per contact, k = m (tau_c/T_c)^(5/2) u^(-1/2) and
    !> d = alpha m tau_c/T_c.  On failure alpha = tau_c = 0.
    pure elemental subroutine flat_pair(e, iend, alpha, tau_c, status)
        real(wp), intent(in) :: e        !! target restitution coefficient
        integer, intent(in) :: iend      !! 0 overlap, 1 force
        real(wp), intent(out) :: alpha   !! damping parameter alpha(e)
        real(wp), intent(out) :: tau_c   !! dimensionless contact duration tau_c(alpha)
        integer, intent(out) :: status   !! HD_OK or an error code
        call flat_pair_law(e, 0, iend, alpha, tau_c, status)
    end subroutine flat_pair

    !> Restitution and contact time of a contact (k, d, m, u).  Without rebound
    !> e = 0, tc = huge(1.0_wp) and status = HD_NO_REBOUND; on any other failure
    !> e = tc = 0.
    pure elemental subroutine flat_forward(k, d, m, u, iend, e, tc, status)
        real(wp), intent(in) :: k        !! Hertz stiffness [N m^-3/2]
        real(wp), intent(in) :: d        !! damping coefficient [kg s^-1]
        real(wp), intent(in) :: m        !! effective mass [kg]
        real(wp), intent(in) :: u        !! impact velocity [m s^-1]
        integer, intent(in) :: iend      !! 0 overlap, 1 force
        real(wp), intent(out) :: e       !! restitution coefficient
        real(wp), intent(out) :: tc      !! contact time [s]
        integer, intent(out) :: status   !! HD_OK, HD_NO_REBOUND or an error code
        call flat_forward_law(k, d, m, u, 0, iend, e, tc, status)
    end subroutine flat_forward

    !> flat_invert for the damping law `law` (0 linear, 1 tsuji, 2 kuwabara-kono;
    !> damping force d zeta^q zeta', d in kg s^-1 m^-q), with the physical-stiffness
    !> bound k_phys when k_phys > 0 (k_phys = 0: no bound; negative or not finite:
    !> HD_BAD_KPHYS).  On failure k = d = 0 and status names the bad argument.
    pure elemental subroutine flat_invert_law(e, tc, m, u, k_phys, law, iend, k, d, status)
        real(wp), intent(in) :: e        !! target restitution coefficient: [1e-3 or 1e-4, 1] (see hertzdamp_fit_law_e_min)
        real(wp), intent(in) :: tc       !! target contact time [s]
        real(wp), intent(in) :: m        !! effective mass [kg]
        real(wp), intent(in) :: u        !! impact velocity [m s^-1]
        real(wp), intent(in) :: k_phys   !! physical stiffness bound [N m^-3/2], or 0 for none
        integer, intent(in) :: law       !! 0 linear, 1 tsuji, 2 kuwabara-kono
        integer, intent(in) :: iend      !! 0 overlap, 1 force
        real(wp), intent(out) :: k       !! Hertz stiffness [N m^-3/2]
        real(wp), intent(out) :: d       !! damping coefficient [kg s^-1 m^-q]
        integer, intent(out) :: status   !! HD_OK or an error code
        real(wp) :: a, tau
        if (k_phys == 0.0_wp) then
            ! as flat_invert: the fit's kernel of the law, then the general path
            call hertzdamp_fit_invert(e, tc, m, u, iend, k, d, a, tau, status, law)
            if (status /= HD_OK) call hertzdamp_invert_fit_rest(e, tc, m, u, iend, law, k, d, status)
        else
            ! the bound; an invalid k_phys gets HD_BAD_KPHYS in the module's order of the checks
            call mod_invert(e, tc, m, u, iend, k, d, status, k_phys=k_phys, method=legacy_method, law=law)
        end if
        if (status /= HD_OK) then
            k = 0.0_wp
            d = 0.0_wp
        end if
    end subroutine flat_invert_law

    !> flat_invert_law for n contacts without the physical bound: the rank-1 form of
    !> hertzdamp_invert with `law` (the fit runs vectorised over the arrays); the results
    !> of n calls of flat_invert_law with k_phys = 0, bit for bit.
    pure subroutine flat_invert_law_n(n, e, tc, m, u, law, iend, k, d, status)
        integer, intent(in) :: n          !! number of contacts (>= 0)
        real(wp), intent(in) :: e(n)      !! target restitution coefficients
        real(wp), intent(in) :: tc(n)     !! target contact times [s]
        real(wp), intent(in) :: m(n)      !! effective masses [kg]
        real(wp), intent(in) :: u(n)      !! impact velocities [m s^-1]
        integer, intent(in) :: law        !! 0 linear, 1 tsuji, 2 kuwabara-kono
        integer, intent(in) :: iend       !! 0 overlap, 1 force
        real(wp), intent(out) :: k(n)     !! Hertz stiffnesses [N m^-3/2] (0 on failure)
        real(wp), intent(out) :: d(n)     !! damping coefficients [kg s^-1 m^-q] (0 on failure)
        integer, intent(out) :: status(n) !! HD_OK or an error code, per contact
        call mod_invert(e, tc, m, u, iend, k, d, status, method=legacy_method, law=law)
    end subroutine flat_invert_law_n

    !> flat_pair for the damping law `law`.  Per contact (mass m, speed u, contact time
    !> T_c): t* = T_c / tau_c, k = m t*^(-5/2) u^(-1/2), d = alpha m t*^(-1) (u t*)^(-q).
    pure elemental subroutine flat_pair_law(e, law, iend, alpha, tau_c, status)
        real(wp), intent(in) :: e        !! target restitution coefficient
        integer, intent(in) :: law       !! 0 linear, 1 tsuji, 2 kuwabara-kono
        integer, intent(in) :: iend      !! 0 overlap, 1 force
        real(wp), intent(out) :: alpha   !! damping parameter alpha(e)
        real(wp), intent(out) :: tau_c   !! dimensionless contact duration tau_c(alpha)
        integer, intent(out) :: status   !! HD_OK or an error code
        call hertzdamp_invert_alpha(e, iend, alpha, tau_c, status, method=legacy_method, law=law)
        if (status /= HD_OK) then
            alpha = 0.0_wp
            tau_c = 0.0_wp
        end if
    end subroutine flat_pair_law

    !> flat_forward for the damping law `law` (d in kg s^-1 m^-q).
    pure elemental subroutine flat_forward_law(k, d, m, u, law, iend, e, tc, status)
        real(wp), intent(in) :: k        !! Hertz stiffness [N m^-3/2]
        real(wp), intent(in) :: d        !! damping coefficient [kg s^-1 m^-q]
        real(wp), intent(in) :: m        !! effective mass [kg]
        real(wp), intent(in) :: u        !! impact velocity [m s^-1]
        integer, intent(in) :: law       !! 0 linear, 1 tsuji, 2 kuwabara-kono
        integer, intent(in) :: iend      !! 0 overlap, 1 force
        real(wp), intent(out) :: e       !! restitution coefficient
        real(wp), intent(out) :: tc      !! contact time [s]
        integer, intent(out) :: status   !! HD_OK, HD_NO_REBOUND or an error code
        real(wp) :: alpha, tstar
        ! without zeta_max: the fit skips the turning point (the same e, tc and status)
        call hertzdamp_forward_dim(k, d, m, u, iend, legacy_method, alpha, tstar, e, tc, status=status, law=law)
        select case (status)
        case (HD_OK)
        case (HD_NO_REBOUND)
            e = 0.0_wp
            tc = huge(1.0_wp)
        case default
            e = 0.0_wp
            tc = 0.0_wp
        end select
    end subroutine flat_forward_law

end module hertzdamp_flat
