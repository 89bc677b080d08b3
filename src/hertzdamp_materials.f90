!> Contact properties from material data (doc/theory.md, section 1): the mass of a
!> sphere, the effective mass and radius of a contact, the effective modulus E*, the
!> physical Hertz stiffness k_phys = (4/3) E* sqrt(R*), and the elastic Hertz contact
!> time that DEM codes use to choose their time step.
!>
!>     m = (4/3) pi rho R^3                          sphere mass
!>     m* = m1 m2 / (m1 + m2)                        pair; a wall or a held particle: m* = m1
!>     R* = R1 R2 / (R1 + R2)                        pair; a wall (flat): R* = R1
!>     1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2        both bodies, a wall too
!>     k_phys = (4/3) E* sqrt(R*)
!>     T_Hertz = tau_c(0) (m* / (k_phys u^(1/2)))^(2/5) = 2.868 (m*^2 / (R* E*^2 u))^(1/5)
!>     T_Rayleigh = pi R / v_R, v_R = (0.1631 nu + 0.8766) sqrt(G/rho), G = E/(2 (1 + nu))
!>
!> Everything is `pure elemental` with a status (0 = success): a bad input gives the
!> status naming it (HD_BAD_RADIUS, HD_BAD_DENSITY, HD_BAD_MODULUS, HD_BAD_POISSON,
!> HD_BAD_MASS, HD_BAD_VELOCITY) and a result outside the normal double range gives
!> HD_OUT_OF_RANGE (a radius of 1e200 m, whose mass overflows, or of 1e-300 m, whose
!> mass underflows), never Inf, NaN or 0.  Ordinary magnitudes (1e-30 to 1e30) take
!> the direct formulas (correctly rounded to a few ulps), others the logarithms; the
!> harmonic combinations are min/(1 + min/max) and E* goes through the compliances,
!> so no intermediate overflows.  On failure every output is 0.
!>
!> To tell which body of a pair is wrong, call the building blocks per body
!> (hertzdamp_sphere_mass, hertzdamp_plane_strain_modulus) before combining them.
module hertzdamp_materials
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: HD_OK, HD_BAD_RADIUS, HD_BAD_DENSITY, HD_BAD_MODULUS, HD_BAD_POISSON, &
                                HD_BAD_MASS, HD_BAD_VELOCITY, HD_BAD_STIFFNESS, HD_OUT_OF_RANGE
    use hertzdamp_scaling, only: hertzdamp_safe_exp, hertzdamp_check_positive, hertzdamp_tstar_direct, hertzdamp_log_tstar
    use hertzdamp_constants, only: hertzdamp_tau_c0, pi => hertzdamp_pi, hertzdamp_direct_lo, hertzdamp_direct_hi
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> The fraction of the Rayleigh time DEM codes usually take as their time step
    !> (EDEM: 20 %, within 10 to 40 %; LIGGGHTS's example checks 10 %).
    real(wp), parameter, public :: hertzdamp_rayleigh_fraction = 0.2_wp

    public :: hertzdamp_sphere_mass, hertzdamp_effective_mass, hertzdamp_effective_radius, &
              hertzdamp_plane_strain_modulus, hertzdamp_effective_modulus, hertzdamp_hertz_stiffness, &
              hertzdamp_hertz_time, hertzdamp_pair_contact, hertzdamp_wall_contact, hertzdamp_rayleigh_time

contains

    !> Mass of a sphere, m = (4/3) pi rho R^3 [kg].
    pure elemental subroutine hertzdamp_sphere_mass(radius, density, mass, status)
        real(wp), intent(in) :: radius    !! sphere radius R [m]
        real(wp), intent(in) :: density   !! density rho [kg m^-3]
        real(wp), intent(out) :: mass     !! m [kg] (0 on failure)
        integer, intent(out) :: status    !! HD_OK, HD_BAD_RADIUS, HD_BAD_DENSITY or HD_OUT_OF_RANGE
        mass = 0.0_wp
        status = hertzdamp_check_positive(radius, HD_BAD_RADIUS)
        if (status == HD_OK) status = hertzdamp_check_positive(density, HD_BAD_DENSITY)
        if (status /= HD_OK) return
        if (ordinary(radius) .and. ordinary(density)) then
            mass = (4.0_wp * pi / 3.0_wp) * density * radius**3
        else
            call hertzdamp_safe_exp(log(4.0_wp * pi / 3.0_wp) + log(density) + 3.0_wp * log(radius), mass, status)
        end if
    end subroutine hertzdamp_sphere_mass

    !> Effective mass of two bodies, m1 m2 / (m1 + m2) [kg].  For a wall, or a particle
    !> held fixed, the effective mass is the moving particle's own mass: use m1.
    pure elemental subroutine hertzdamp_effective_mass(m1, m2, mass, status)
        real(wp), intent(in) :: m1, m2    !! masses of the two bodies [kg]
        real(wp), intent(out) :: mass     !! effective mass [kg] (0 on failure)
        integer, intent(out) :: status    !! HD_OK, HD_BAD_MASS or HD_OUT_OF_RANGE
        call combine(m1, m2, HD_BAD_MASS, mass, status)
    end subroutine hertzdamp_effective_mass

    !> Effective radius of two spheres, R1 R2 / (R1 + R2) [m].  Against a flat wall the
    !> effective radius is the sphere's own radius: use R1.
    pure elemental subroutine hertzdamp_effective_radius(r1, r2, radius, status)
        real(wp), intent(in) :: r1, r2    !! radii of the two spheres [m]
        real(wp), intent(out) :: radius   !! effective radius [m] (0 on failure)
        integer, intent(out) :: status    !! HD_OK, HD_BAD_RADIUS or HD_OUT_OF_RANGE
        call combine(r1, r2, HD_BAD_RADIUS, radius, status)
    end subroutine hertzdamp_effective_radius

    !> Plane-strain modulus of one body, E / (1 - nu^2) [Pa].
    pure elemental subroutine hertzdamp_plane_strain_modulus(youngs, poisson, modulus, status)
        real(wp), intent(in) :: youngs    !! Young's modulus E [Pa]
        real(wp), intent(in) :: poisson   !! Poisson's ratio nu, -1 < nu <= 0.5
        real(wp), intent(out) :: modulus  !! E / (1 - nu^2) [Pa] (0 on failure)
        integer, intent(out) :: status    !! HD_OK, HD_BAD_MODULUS, HD_BAD_POISSON or HD_OUT_OF_RANGE
        modulus = 0.0_wp
        status = check_elastic(youngs, poisson)
        if (status /= HD_OK) return
        ! 1 - nu^2 = (1 - nu)(1 + nu): accurate near nu = -1 too
        modulus = youngs / ((1.0_wp - poisson) * (1.0_wp + poisson))
        if (.not. (modulus <= huge(modulus))) then
            modulus = 0.0_wp
            status = HD_OUT_OF_RANGE
        end if
    end subroutine hertzdamp_plane_strain_modulus

    !> Effective modulus of a contact, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 [Pa].
    pure elemental subroutine hertzdamp_effective_modulus(youngs1, poisson1, youngs2, poisson2, e_star, status)
        real(wp), intent(in) :: youngs1, poisson1   !! body 1: Young's modulus [Pa], Poisson's ratio
        real(wp), intent(in) :: youngs2, poisson2   !! body 2 (or the wall): Young's modulus [Pa], Poisson's ratio
        real(wp), intent(out) :: e_star             !! E* [Pa] (0 on failure)
        integer, intent(out) :: status              !! HD_OK, HD_BAD_MODULUS, HD_BAD_POISSON or HD_OUT_OF_RANGE
        real(wp) :: c
        e_star = 0.0_wp
        status = check_elastic(youngs1, poisson1)
        if (status == HD_OK) status = check_elastic(youngs2, poisson2)
        if (status /= HD_OK) return
        ! compliances: a very stiff body adds a tiny (even subnormal) term, never an overflow
        c = (1.0_wp - poisson1) * (1.0_wp + poisson1) / youngs1 + (1.0_wp - poisson2) * (1.0_wp + poisson2) / youngs2
        if (c <= huge(c) .and. c >= 1.0_wp / huge(c)) e_star = 1.0_wp / c
        if (.not. (e_star >= tiny(e_star))) then
            e_star = 0.0_wp
            status = HD_OUT_OF_RANGE
        end if
    end subroutine hertzdamp_effective_modulus

    !> Physical Hertz stiffness k_phys = (4/3) E* sqrt(R*) [N m^-3/2].
    pure elemental subroutine hertzdamp_hertz_stiffness(e_star, radius, k_phys, status)
        real(wp), intent(in) :: e_star    !! effective modulus E* [Pa]
        real(wp), intent(in) :: radius    !! effective radius R* [m]
        real(wp), intent(out) :: k_phys   !! [N m^-3/2] (0 on failure)
        integer, intent(out) :: status    !! HD_OK, HD_BAD_MODULUS, HD_BAD_RADIUS or HD_OUT_OF_RANGE
        k_phys = 0.0_wp
        status = hertzdamp_check_positive(e_star, HD_BAD_MODULUS)
        if (status == HD_OK) status = hertzdamp_check_positive(radius, HD_BAD_RADIUS)
        if (status /= HD_OK) return
        if (ordinary(e_star) .and. ordinary(radius)) then
            k_phys = (4.0_wp / 3.0_wp) * e_star * sqrt(radius)
        else
            call hertzdamp_safe_exp(log(4.0_wp / 3.0_wp) + log(e_star) + 0.5_wp * log(radius), k_phys, status)
        end if
    end subroutine hertzdamp_hertz_stiffness

    !> Elastic (undamped) Hertz contact time tau_c(0) t* with t* = (m / (k u^(1/2)))^(2/5),
    !> i.e. 2.868 (m^2 / (R* E*^2 u))^(1/5) for k = k_phys [s].  Damping changes it: the
    !> overlap end lasts longer (tau_c(alpha) > tau_c(0)), the force end shorter.
    pure elemental subroutine hertzdamp_hertz_time(mass, k, u, tc, status)
        real(wp), intent(in) :: mass      !! effective mass [kg]
        real(wp), intent(in) :: k         !! Hertz stiffness [N m^-3/2]
        real(wp), intent(in) :: u         !! relative normal impact velocity [m s^-1]
        real(wp), intent(out) :: tc       !! elastic contact time [s] (0 on failure)
        integer, intent(out) :: status    !! HD_OK, HD_BAD_MASS, HD_BAD_STIFFNESS, HD_BAD_VELOCITY or HD_OUT_OF_RANGE
        tc = 0.0_wp
        status = hertzdamp_check_positive(mass, HD_BAD_MASS)
        if (status == HD_OK) status = hertzdamp_check_positive(k, HD_BAD_STIFFNESS)
        if (status == HD_OK) status = hertzdamp_check_positive(u, HD_BAD_VELOCITY)
        if (status /= HD_OK) return
        if (ordinary(mass) .and. ordinary(k) .and. ordinary(u)) then
            tc = hertzdamp_tau_c0() * hertzdamp_tstar_direct(mass, k, u)
        else
            ! t* by the one formula of its logarithm (the stiffness bound's, hertzdamp_pair)
            call hertzdamp_safe_exp(log(hertzdamp_tau_c0()) + hertzdamp_log_tstar(log(mass), log(k), log(u), .true.), tc, &
                                    status)
        end if
    end subroutine hertzdamp_hertz_time

    !> Rayleigh time of one sphere, T_R = pi R / v_R [s]: the time a Rayleigh surface
    !> wave takes to travel half way round it, the time-step criterion of DEM codes
    !> that do not look at the impact speed (EDEM, LIGGGHTS fix check/timestep/gran).
    !> v_R = (0.1631 nu + 0.8766) sqrt(G/rho) with G = E/(2 (1 + nu)) is the usual
    !> linear approximation of the root of the Rayleigh equation, within 0.3 % of it
    !> for 0 <= nu <= 0.5 (3.6 % as nu -> -1; test/unit/test_materials.f90 solves the
    !> equation).  DEM codes take a fraction of T_R as their time step: 0.2 T_R is the
    !> usual choice, 0.1 to 0.4 its range (hertzdamp_rayleigh_fraction).
    pure elemental subroutine hertzdamp_rayleigh_time(radius, density, youngs, poisson, t_r, status)
        real(wp), intent(in) :: radius    !! sphere radius R [m]
        real(wp), intent(in) :: density   !! density rho [kg m^-3]
        real(wp), intent(in) :: youngs    !! Young's modulus E [Pa]
        real(wp), intent(in) :: poisson   !! Poisson's ratio nu, -1 < nu <= 0.5
        real(wp), intent(out) :: t_r      !! Rayleigh time [s] (0 on failure)
        integer, intent(out) :: status    !! HD_OK, HD_BAD_RADIUS, HD_BAD_DENSITY, HD_BAD_MODULUS, HD_BAD_POISSON
                                          !! or HD_OUT_OF_RANGE
        real(wp) :: c
        t_r = 0.0_wp
        status = hertzdamp_check_positive(radius, HD_BAD_RADIUS)
        if (status == HD_OK) status = hertzdamp_check_positive(density, HD_BAD_DENSITY)
        if (status == HD_OK) status = check_elastic(youngs, poisson)
        if (status /= HD_OK) return
        c = 0.1631_wp * poisson + 0.8766_wp   ! v_R / v_S, 0.7135 to 0.95815
        ! rho / G = 2 (1 + nu) rho / E
        if (ordinary(radius) .and. ordinary(density) .and. ordinary(youngs)) then
            t_r = pi * radius * sqrt(2.0_wp * (1.0_wp + poisson) * density / youngs) / c
        else
            call hertzdamp_safe_exp(log(pi) + log(radius) + 0.5_wp * (log(2.0_wp * (1.0_wp + poisson)) + &
                                    log(density) - log(youngs)) - log(c), t_r, status)
        end if
    end subroutine hertzdamp_rayleigh_time

    !> Contact of two spheres from their material data: effective mass, effective
    !> radius, E* and k_phys.
    pure elemental subroutine hertzdamp_pair_contact(radius1, density1, youngs1, poisson1, &
                                                     radius2, density2, youngs2, poisson2, &
                                                     mass, radius, e_star, k_phys, status)
        real(wp), intent(in) :: radius1, density1, youngs1, poisson1  !! sphere 1: R [m], rho [kg m^-3], E [Pa], nu
        real(wp), intent(in) :: radius2, density2, youngs2, poisson2  !! sphere 2: R [m], rho [kg m^-3], E [Pa], nu
        real(wp), intent(out) :: mass     !! effective mass m* [kg]
        real(wp), intent(out) :: radius   !! effective radius R* [m]
        real(wp), intent(out) :: e_star   !! effective modulus E* [Pa]
        real(wp), intent(out) :: k_phys   !! (4/3) E* sqrt(R*) [N m^-3/2]
        integer, intent(out) :: status    !! HD_OK or the status of the first bad input
        real(wp) :: m1, m2
        mass = 0.0_wp
        radius = 0.0_wp
        e_star = 0.0_wp
        k_phys = 0.0_wp
        call hertzdamp_sphere_mass(radius1, density1, m1, status)
        if (status == HD_OK) call hertzdamp_sphere_mass(radius2, density2, m2, status)
        if (status == HD_OK) call hertzdamp_effective_mass(m1, m2, mass, status)
        if (status == HD_OK) call hertzdamp_effective_radius(radius1, radius2, radius, status)
        call finish_contact(youngs1, poisson1, youngs2, poisson2, mass, radius, e_star, k_phys, status)
    end subroutine hertzdamp_pair_contact

    !> Contact of a sphere with a wall (infinite radius and mass; its own elastic
    !> constants): m* = m, R* = R.
    pure elemental subroutine hertzdamp_wall_contact(radius1, density1, youngs1, poisson1, youngs_wall, &
                                                     poisson_wall, mass, radius, e_star, k_phys, status)
        real(wp), intent(in) :: radius1, density1, youngs1, poisson1  !! sphere: R [m], rho [kg m^-3], E [Pa], nu
        real(wp), intent(in) :: youngs_wall, poisson_wall             !! wall: E [Pa], nu
        real(wp), intent(out) :: mass     !! effective mass m* = m [kg]
        real(wp), intent(out) :: radius   !! effective radius R* = R [m]
        real(wp), intent(out) :: e_star   !! effective modulus E* [Pa]
        real(wp), intent(out) :: k_phys   !! (4/3) E* sqrt(R*) [N m^-3/2]
        integer, intent(out) :: status    !! HD_OK or the status of the first bad input
        mass = 0.0_wp
        radius = 0.0_wp
        e_star = 0.0_wp
        k_phys = 0.0_wp
        call hertzdamp_sphere_mass(radius1, density1, mass, status)
        if (status == HD_OK) radius = radius1
        call finish_contact(youngs1, poisson1, youngs_wall, poisson_wall, mass, radius, e_star, k_phys, status)
    end subroutine hertzdamp_wall_contact

    !> E* and k_phys once mass and radius are known; everything 0 on failure.
    pure elemental subroutine finish_contact(youngs1, poisson1, youngs2, poisson2, mass, radius, e_star, k_phys, status)
        real(wp), intent(in) :: youngs1, poisson1, youngs2, poisson2
        real(wp), intent(inout) :: mass, radius
        real(wp), intent(out) :: e_star, k_phys
        integer, intent(inout) :: status
        e_star = 0.0_wp
        k_phys = 0.0_wp
        if (status == HD_OK) call hertzdamp_effective_modulus(youngs1, poisson1, youngs2, poisson2, e_star, status)
        if (status == HD_OK) call hertzdamp_hertz_stiffness(e_star, radius, k_phys, status)
        if (status /= HD_OK) then
            mass = 0.0_wp
            radius = 0.0_wp
            e_star = 0.0_wp
            k_phys = 0.0_wp
        end if
    end subroutine finish_contact

    !> A magnitude for which the direct formulas cannot overflow or underflow (the
    !> logarithmic path, slightly less accurate, takes the others).
    pure elemental logical function ordinary(x)
        real(wp), intent(in) :: x
        ordinary = x >= hertzdamp_direct_lo .and. x <= hertzdamp_direct_hi
    end function ordinary

    !> HD_OK, HD_BAD_MODULUS or HD_BAD_POISSON for the elastic constants of one body.
    pure elemental integer function check_elastic(youngs, poisson) result(status)
        real(wp), intent(in) :: youngs, poisson
        status = hertzdamp_check_positive(youngs, HD_BAD_MODULUS)
        if (status == HD_OK .and. .not. (poisson > -1.0_wp .and. poisson <= 0.5_wp)) status = HD_BAD_POISSON
    end function check_elastic

    !> a b / (a + b) after checking that a and b are finite and positive (else `bad`).
    pure elemental subroutine combine(a, b, bad, c, status)
        real(wp), intent(in) :: a, b
        integer, intent(in) :: bad
        real(wp), intent(out) :: c
        integer, intent(out) :: status
        c = 0.0_wp
        status = hertzdamp_check_positive(a, bad)
        if (status == HD_OK) status = hertzdamp_check_positive(b, bad)
        if (status == HD_OK) call harmonic(a, b, c, status)
    end subroutine combine

    !> a b / (a + b) for finite positive a, b without overflow: min / (1 + min/max).
    !> HD_OUT_OF_RANGE when the result is below the normal range.
    pure elemental subroutine harmonic(a, b, c, status)
        real(wp), intent(in) :: a, b
        real(wp), intent(out) :: c
        integer, intent(inout) :: status
        c = min(a, b) / (1.0_wp + min(a, b) / max(a, b))
        if (c < tiny(c)) then
            c = 0.0_wp
            status = HD_OUT_OF_RANGE
        end if
    end subroutine harmonic

end module hertzdamp_materials
