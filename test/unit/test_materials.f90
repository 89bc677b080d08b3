!> Contact properties from material data (hertzdamp_materials): the glass-bead values
!> of issue 12 (m* = 5.236e-6 kg, k_phys = 9.965e8 N m^-3/2 for two 2 mm beads), the
!> identities of equal spheres and of a wall, the textbook elastic contact time
!> 2.868 (m*^2/(R* E*^2 u))^(1/5) against the reference integrator with d = 0, the
!> Rayleigh time against the exact root of the Rayleigh equation (solved here), and a
!> status (never Inf, NaN or 0) for every bad or extreme input.
program test_materials
    use hertzdamp, only: hertzdamp_rk, hertzdamp_sphere_mass, hertzdamp_effective_mass, hertzdamp_effective_radius, &
                         hertzdamp_plane_strain_modulus, hertzdamp_effective_modulus, hertzdamp_hertz_stiffness, &
                         hertzdamp_hertz_time, hertzdamp_pair_contact, hertzdamp_wall_contact, hertzdamp_forward_dim, &
                         hertzdamp_rayleigh_time, hertzdamp_rayleigh_fraction, &
                         hertzdamp_message, HD_OK, HD_BAD_RADIUS, HD_BAD_DENSITY, HD_BAD_MODULUS, HD_BAD_POISSON, &
                         HD_BAD_MASS, HD_BAD_VELOCITY, HD_BAD_STIFFNESS, HD_OUT_OF_RANGE, HD_END_OVERLAP, HD_METHOD_RK45
    use hertzdamp_testing, only: test_suite, new_suite
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
    implicit none

    integer, parameter :: wp = hertzdamp_rk
    real(wp), parameter :: pi = acos(-1.0_wp)
    ! issue 12: 2 mm glass beads
    real(wp), parameter :: r = 1.0e-3_wp, rho = 2500.0_wp, ym = 63.0e9_wp, nu = 0.24_wp
    type(test_suite) :: s
    real(wp) :: m, ms, rs, es, kp, m1, a, tc, alpha, tstar, e, tce, zmax, nan, inf, tr, xi, worst, g, pnu
    integer :: st, i
    real(wp) :: bad_r(6)

    s = new_suite('test_materials')
    nan = ieee_value(1.0_wp, ieee_quiet_nan)
    inf = ieee_value(1.0_wp, ieee_positive_inf)

    ! the figures quoted in issue 12, to the 4 digits given there
    call hertzdamp_pair_contact(r, rho, ym, nu, r, rho, ym, nu, ms, rs, es, kp, st)
    call s%check(st == HD_OK, 'glass pair: status ok')
    call s%check(abs(ms - 5.236e-6_wp) <= 0.0005e-6_wp, 'glass pair: m* = 5.236e-6 kg')
    call s%check(abs(kp - 9.965e8_wp) <= 0.0005e8_wp, 'glass pair: k_phys = 9.965e8 N m^-3/2')
    ! equal spheres: m* = m/2, R* = R/2, E* = E/(2(1 - nu^2)) (exact identities, to rounding)
    call hertzdamp_sphere_mass(r, rho, m, st)
    call s%check(st == HD_OK, 'sphere mass: status ok')
    call s%check_close(m, rho * 4.0_wp / 3.0_wp * pi * r**3, 1.0e-15_wp, 'sphere mass = (4/3) pi rho R^3')
    call hertzdamp_sphere_mass(1.0e40_wp, 1.0e-90_wp, m1, st)
    call s%check(st == HD_OK .and. abs(m1 / (4.0_wp / 3.0_wp * pi * 1.0e30_wp) - 1.0_wp) < 1.0e-13_wp, &
                 'sphere mass, logarithmic path (R = 1e40, rho = 1e-90)')
    call s%check_close(ms, m / 2.0_wp, 4.0e-16_wp, 'equal spheres: m* = m/2')
    call s%check_close(rs, r / 2.0_wp, 4.0e-16_wp, 'equal spheres: R* = R/2')
    call s%check_close(es, ym / (2.0_wp * (1.0_wp - nu**2)), 4.0e-16_wp, 'equal spheres: E* = E/(2(1-nu^2))')
    call s%check_close(kp, 4.0_wp / 3.0_wp * es * sqrt(rs), 4.0e-16_wp, 'k_phys = (4/3) E* sqrt(R*)')
    ! the wall: infinite radius and mass, m* = m, R* = R; same material: the same E*
    call hertzdamp_wall_contact(r, rho, ym, nu, ym, nu, m1, a, es, kp, st)
    call s%check(st == HD_OK, 'wall: status ok')
    call s%check(m1 == m, 'wall: m* = m')
    call s%check(a == r, 'wall: R* = R')
    call s%check_close(es, ym / (2.0_wp * (1.0_wp - nu**2)), 4.0e-16_wp, 'wall of the same material: E*')
    ! a rigid wall (E -> huge): E* -> E/(1 - nu^2)
    call hertzdamp_effective_modulus(ym, nu, 1.0e300_wp, 0.3_wp, es, st)
    call s%check(st == HD_OK, 'rigid wall: status ok')
    call s%check_close(es, ym / (1.0_wp - nu**2), 1.0e-15_wp, 'rigid wall: E* = E/(1 - nu^2)')
    ! symmetry: swapping the bodies changes nothing (bit for bit)
    call hertzdamp_pair_contact(2.0e-3_wp, 7800.0_wp, 2.0e11_wp, 0.3_wp, r, rho, ym, nu, ms, rs, es, kp, st)
    call hertzdamp_pair_contact(r, rho, ym, nu, 2.0e-3_wp, 7800.0_wp, 2.0e11_wp, 0.3_wp, m1, a, tc, e, i)
    call s%check(st == HD_OK .and. i == HD_OK .and. ms == m1 .and. rs == a .and. es == tc .and. kp == e, &
                 'pair: symmetric in the two bodies')
    ! unequal pair against the textbook forms
    call hertzdamp_sphere_mass(2.0e-3_wp, 7800.0_wp, m1, st)
    call s%check_close(ms, m * m1 / (m + m1), 1.0e-15_wp, 'pair: m* = m1 m2/(m1 + m2)')
    call s%check_close(rs, r * 2.0e-3_wp / (r + 2.0e-3_wp), 1.0e-15_wp, 'pair: R* = R1 R2/(R1 + R2)')
    call s%check_close(es, 1.0_wp / ((1.0_wp - 0.09_wp) / 2.0e11_wp + (1.0_wp - nu**2) / ym), 1.0e-15_wp, &
                       'pair: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2')

    ! elastic Hertz contact time: the textbook 2.868 (m^2/(R* E*^2 u))^(1/5) (4 digits), and the
    ! reference integrator's contact time with d = 0 (12 digits)
    call hertzdamp_pair_contact(r, rho, ym, nu, r, rho, ym, nu, ms, rs, es, kp, st)
    call hertzdamp_hertz_time(ms, kp, 0.7_wp, tc, st)
    call s%check(st == HD_OK, 'hertz time: status ok')
    call s%check(abs(tc / (2.868_wp * (ms**2 / (rs * es**2 * 0.7_wp))**0.2_wp) - 1.0_wp) < 2.0e-4_wp, &
                 'hertz time = 2.868 (m*^2/(R* E*^2 u))^(1/5)')
    call hertzdamp_forward_dim(kp, 0.0_wp, ms, 0.7_wp, HD_END_OVERLAP, HD_METHOD_RK45, alpha, tstar, e, tce, zmax, st)
    call s%check(st == HD_OK, 'rk45 elastic contact: status ok')
    call s%check_close(tc, tce, 1.0e-12_wp, 'hertz time = rk45 contact time with d = 0')

    ! Rayleigh time pi R / v_R: the formula to rounding, and its fit of v_R against the
    ! exact root of the Rayleigh equation, (2 - xi^2)^2 = 4 sqrt(1 - xi^2) sqrt(1 - kappa^2 xi^2),
    ! xi = v_R/v_S, kappa^2 = (1 - 2 nu)/(2 (1 - nu)): within 0.3 % for 0 <= nu <= 0.5
    ! (2.97e-3 at nu = 0.5, the worst of the grid) and 3.7 % down to nu = -0.99
    g = ym / (2.0_wp * (1.0_wp + nu))
    call hertzdamp_rayleigh_time(r, rho, ym, nu, tr, st)
    call s%check(st == HD_OK, 'rayleigh time: status ok')
    call s%check_close(tr, pi * r * sqrt(rho / g) / (0.1631_wp * nu + 0.8766_wp), 4.0e-16_wp, &
                       'rayleigh time = pi R sqrt(rho/G)/(0.1631 nu + 0.8766)')
    call s%check(abs(tr - 1.0762e-6_wp) < 0.00005e-6_wp, 'rayleigh time of a 2 mm glass bead: 1.0762e-6 s')
    call s%check(hertzdamp_rayleigh_fraction == 0.2_wp, 'rayleigh fraction: 20 %')
    worst = 0.0_wp
    do i = 0, 50
        pnu = 0.01_wp * i
        call hertzdamp_rayleigh_time(r, rho, ym, pnu, tr, st)
        xi = rayleigh_root(pnu)
        worst = max(worst, abs(tr / (pi * r * sqrt(rho * 2.0_wp * (1.0_wp + pnu) / ym) / xi) - 1.0_wp))
    end do
    call s%check(worst <= 3.0e-3_wp, 'rayleigh time within 0.3 % of the exact root for 0 <= nu <= 0.5')
    call s%check(worst >= 2.9e-3_wp, 'rayleigh fit: the 0.3 % is reached (nu = 0, 0.5), the bound is tight')
    worst = 0.0_wp
    do i = 1, 99
        pnu = -0.01_wp * i
        call hertzdamp_rayleigh_time(r, rho, ym, pnu, tr, st)
        worst = max(worst, abs(tr / (pi * r * sqrt(rho * 2.0_wp * (1.0_wp + pnu) / ym) / rayleigh_root(pnu)) - 1.0_wp))
    end do
    call s%check(worst <= 3.7e-2_wp, 'rayleigh time within 3.7 % of the exact root for -0.99 <= nu < 0')
    ! the logarithmic path scales as the direct one: t_R ~ R sqrt(rho/E)
    call hertzdamp_rayleigh_time(r * 1.0e40_wp, rho * 1.0e-60_wp, ym, nu, tce, st)
    call hertzdamp_rayleigh_time(r, rho, ym, nu, tr, i)
    call s%check(st == HD_OK .and. i == HD_OK .and. abs(tce / (tr * 1.0e10_wp) - 1.0_wp) < 1.0e-13_wp, &
                 'rayleigh time, logarithmic path (R 1e40 times, rho 1e-60 times)')
    call hertzdamp_rayleigh_time(1.0e300_wp, 1.0e300_wp, 1.0e-300_wp, nu, tr, st)
    call s%check(st == HD_OUT_OF_RANGE .and. tr == 0.0_wp, 'rayleigh time beyond double: out of range')
    call hertzdamp_rayleigh_time(r, rho, ym, 0.7_wp, tr, st)
    call s%check(st == HD_BAD_POISSON .and. tr == 0.0_wp, 'rayleigh time: bad Poisson ratio -> HD_BAD_POISSON')

    ! bad inputs: the status names the input, every output is 0
    bad_r = [0.0_wp, -1.0e-3_wp, nan, inf, -inf, -0.0_wp]
    do i = 1, size(bad_r)
        call hertzdamp_sphere_mass(bad_r(i), rho, m, st)
        call s%check(st == HD_BAD_RADIUS .and. m == 0.0_wp, 'bad radius -> HD_BAD_RADIUS')
        call hertzdamp_sphere_mass(r, bad_r(i), m, st)
        call s%check(st == HD_BAD_DENSITY .and. m == 0.0_wp, 'bad density -> HD_BAD_DENSITY')
        call hertzdamp_effective_modulus(bad_r(i), nu, ym, nu, es, st)
        call s%check(st == HD_BAD_MODULUS .and. es == 0.0_wp, 'bad modulus -> HD_BAD_MODULUS')
        call hertzdamp_effective_mass(1.0_wp, bad_r(i), m, st)
        call s%check(st == HD_BAD_MASS .and. m == 0.0_wp, 'bad mass -> HD_BAD_MASS')
        call hertzdamp_effective_radius(bad_r(i), 1.0_wp, m, st)
        call s%check(st == HD_BAD_RADIUS .and. m == 0.0_wp, 'bad radius of a pair -> HD_BAD_RADIUS')
        call hertzdamp_hertz_time(1.0_wp, bad_r(i), 1.0_wp, tc, st)
        call s%check(st == HD_BAD_STIFFNESS .and. tc == 0.0_wp, 'bad stiffness -> HD_BAD_STIFFNESS')
        call hertzdamp_hertz_time(1.0_wp, 1.0_wp, bad_r(i), tc, st)
        call s%check(st == HD_BAD_VELOCITY .and. tc == 0.0_wp, 'bad velocity -> HD_BAD_VELOCITY')
        call hertzdamp_rayleigh_time(bad_r(i), rho, ym, nu, tr, st)
        call s%check(st == HD_BAD_RADIUS .and. tr == 0.0_wp, 'rayleigh time: bad radius -> HD_BAD_RADIUS')
        call hertzdamp_rayleigh_time(r, bad_r(i), ym, nu, tr, st)
        call s%check(st == HD_BAD_DENSITY .and. tr == 0.0_wp, 'rayleigh time: bad density -> HD_BAD_DENSITY')
        call hertzdamp_rayleigh_time(r, rho, bad_r(i), nu, tr, st)
        call s%check(st == HD_BAD_MODULUS .and. tr == 0.0_wp, 'rayleigh time: bad modulus -> HD_BAD_MODULUS')
    end do
    bad_r(1:5) = [0.6_wp, -1.0_wp, -2.0_wp, nan, 0.5000000000000001_wp]
    do i = 1, 5
        call hertzdamp_effective_modulus(ym, nu, ym, bad_r(i), es, st)
        call s%check(st == HD_BAD_POISSON .and. es == 0.0_wp, 'bad Poisson ratio -> HD_BAD_POISSON')
    end do
    call hertzdamp_plane_strain_modulus(ym, 0.5_wp, es, st)
    call s%check(st == HD_OK .and. abs(es / (ym / 0.75_wp) - 1.0_wp) < 1.0e-15_wp, 'nu = 0.5 is accepted')
    ! the pair routine reports the first bad input and zeroes everything
    call hertzdamp_pair_contact(r, rho, ym, nu, r, -rho, ym, nu, ms, rs, es, kp, st)
    call s%check(st == HD_BAD_DENSITY .and. ms == 0.0_wp .and. rs == 0.0_wp .and. es == 0.0_wp .and. kp == 0.0_wp, &
                 'pair: bad density of body 2 -> HD_BAD_DENSITY, outputs 0')
    call hertzdamp_wall_contact(r, rho, ym, nu, ym, 0.7_wp, ms, rs, es, kp, st)
    call s%check(st == HD_BAD_POISSON .and. ms == 0.0_wp .and. rs == 0.0_wp, 'wall: bad wall ratio, outputs 0')

    ! extreme inputs: a status, never Inf or 0 (issue 17: radius 1e200 and 2.2e-308)
    call hertzdamp_sphere_mass(1.0e200_wp, rho, m, st)
    call s%check(st == HD_OUT_OF_RANGE .and. m == 0.0_wp, 'radius 1e200: mass out of range')
    call hertzdamp_sphere_mass(2.2e-308_wp, rho, m, st)
    call s%check(st == HD_OUT_OF_RANGE .and. m == 0.0_wp, 'radius 2.2e-308: mass out of range')
    call hertzdamp_pair_contact(1.0e200_wp, rho, ym, nu, r, rho, ym, nu, ms, rs, es, kp, st)
    call s%check(st == HD_OUT_OF_RANGE .and. ms == 0.0_wp .and. kp == 0.0_wp, 'pair with radius 1e200: out of range')
    call hertzdamp_effective_mass(huge(1.0_wp), huge(1.0_wp), m, st)
    call s%check(st == HD_OK .and. abs(m / (0.5_wp * huge(1.0_wp)) - 1.0_wp) < 1.0e-15_wp, &
                 'effective mass of two huge masses: no overflow')
    call hertzdamp_effective_modulus(1.0e308_wp, -0.9999999_wp, ym, nu, es, st)
    call s%check(st == HD_OK .and. abs(es / (ym / (1.0_wp - nu**2)) - 1.0_wp) < 1.0e-9_wp, &
                 'modulus 1e308 with nu near -1: E* by the other body, no overflow')
    call hertzdamp_plane_strain_modulus(1.0e308_wp, -0.9999999_wp, es, st)
    call s%check(st == HD_OUT_OF_RANGE .and. es == 0.0_wp, 'plane-strain modulus beyond double: out of range')
    call hertzdamp_hertz_stiffness(1.0e300_wp, 1.0e300_wp, kp, st)
    call s%check(st == HD_OUT_OF_RANGE .and. kp == 0.0_wp, 'k_phys beyond double: out of range')
    call hertzdamp_hertz_stiffness(tiny(1.0_wp), tiny(1.0_wp), kp, st)
    call s%check(st == HD_OUT_OF_RANGE .and. kp == 0.0_wp, 'k_phys below double: out of range')
    call s%check(len(hertzdamp_message(HD_BAD_POISSON)) > 0 .and. index(hertzdamp_message(HD_BAD_POISSON), 'Poisson') > 0, &
                 'message names Poisson''s ratio')
    call s%finish()

contains

    !> The root xi = v_R/v_S in (0, 1) of the Rayleigh equation
    !> (2 - xi^2)^2 - 4 sqrt(1 - xi^2) sqrt(1 - kappa^2 xi^2) = 0, kappa^2 = (1 - 2 nu)/(2 (1 - nu)),
    !> by bisection on [0.5, 1] (negative below the root for every -1 < nu <= 0.5, 1 at xi = 1).
    real(wp) function rayleigh_root(pnu) result(x)
        real(wp), intent(in) :: pnu
        real(wp) :: lo, hi, k2
        integer :: it
        k2 = (1.0_wp - 2.0_wp * pnu) / (2.0_wp * (1.0_wp - pnu))
        lo = 0.5_wp
        hi = 1.0_wp
        do it = 1, 100
            x = 0.5_wp * (lo + hi)
            if ((2.0_wp - x * x)**2 - 4.0_wp * sqrt(1.0_wp - x * x) * sqrt(1.0_wp - k2 * x * x) < 0.0_wp) then
                lo = x
            else
                hi = x
            end if
        end do
        x = 0.5_wp * (lo + hi)
    end function rayleigh_root
end program test_materials
