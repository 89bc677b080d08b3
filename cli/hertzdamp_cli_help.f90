!> Help texts of the `hertzdamp` program and its commands.
module hertzdamp_cli_help
    use, intrinsic :: iso_fortran_env, only: output_unit
    implicit none
    private
    public :: print_help, wants_help

    character(len=*), parameter :: nl = new_line('a')

    character(len=*), parameter :: common_opts = &
        '  --end overlap|force   contact-end definition: overlap returns to zero (default),' // nl // &
        '                        or the total contact force returns to zero' // nl // &
        '  --method M            rk45 (reference integrator, default), fit (machine-precision' // nl // &
        '                        approximant, ~1e-13), compact (closed form, ~1e-5),' // nl // &
        '                        series (Taylor series in alpha, overlap only, |alpha| < 1),' // nl // &
        '                        pade (Pade summation, overlap only, 0 <= alpha <= 0.8)' // nl // &
        '  --order N             series truncation order, 0..24 (default 13: 1e-12 at' // nl // &
        '                        alpha <= 0.2)' // nl // &
        '  --tol T               rk45 tolerance, 1e-15 <= T <= 1e-2 (default 1e-13)' // nl // &
        '  --format F            text (aligned, default), csv or json' // nl // &
        '  --help                this text'

    character(len=*), parameter :: top = &
        'hertzdamp - damped Hertzian normal collision of spheres' // nl // &
        '' // nl // &
        'Model: m zeta'''' = -d zeta'' - k zeta^(3/2), zeta(0) = 0, zeta''(0) = u_in.' // nl // &
        'In similarity variables every collision depends on one parameter' // nl // &
        '  alpha = d m^(-3/5) k^(-2/5) u_in^(-1/5)   (time unit t* = (m/(k u_in^(1/2)))^(2/5)).' // nl // &
        '' // nl // &
        'Usage: hertzdamp COMMAND [options]      hertzdamp COMMAND --help' // nl // &
        '' // nl // &
        'Commands:' // nl // &
        '  table      e, tau_c, z_max, tau_max (dimensionless) for a list of alpha' // nl // &
        '  forward    e, contact time, deepest overlap (SI) from k, d, m, u_in' // nl // &
        '  constants  alpha_c, tau_c(0), z_max(0), e1 as computed by the library' // nl // &
        '  invert     stiffness k and damping d (SI) from target e and contact time' // nl // &
        '  bench      work-precision report of every method (forward, inverse, throughput)' // nl // &
        '  scene      run a DEM scene file (namelist) with the inverse rule at every contact' // nl // &
        '  calibrate  k, d and the damping law fitted to measured e(u) and T_c(u) (CSV)' // nl // &
        '' // nl // &
        'Exit codes: 0 success, 2 bad usage, 3 no solution, 4 computation failed.' // nl // &
        'Errors go to stderr as one line; stdout is then empty.'

    character(len=*), parameter :: table = &
        'Usage: hertzdamp table [--alpha A1,A2,...] [--alpha-range A0:A1:N] [options]' // nl // &
        '' // nl // &
        'One row per alpha (dimensionless damping parameter): alpha, e (restitution),' // nl // &
        'tau_c (contact duration in units of t*), z_max (deepest overlap in units of' // nl // &
        'u_in t*), tau_max (time of deepest overlap, units of t*), status (ok or' // nl // &
        'no-rebound: then e = 0 and tau_c = inf; JSON writes null for inf).' // nl // &
        'Without --alpha/--alpha-range: alpha = 0, 0.05, ..., 1.1, 1.12, 1.13 (overlap).' // nl // &
        '' // nl // &
        '  --alpha LIST          comma-separated alpha values' // nl // &
        '  --alpha-range A0:A1:N N equally spaced values from A0 to A1 (N >= 1)' // nl // &
        common_opts

    character(len=*), parameter :: forward = &
        'Usage: hertzdamp forward --k K --d D --mass M --velocity U [options]' // nl // &
        '' // nl // &
        '  --k K          Hertz stiffness k [N m^-3/2], k = (4/3) E* sqrt(R*)' // nl // &
        '  --d D          linear damping coefficient d [kg s^-1], >= 0' // nl // &
        '  --mass M       effective mass m [kg]' // nl // &
        '  --velocity U   normal impact velocity u_in [m s^-1]' // nl // &
        common_opts // nl // &
        '' // nl // &
        'Prints alpha [-], t_star [s], e [-], t_c (contact time) [s], zeta_max' // nl // &
        '(deepest overlap) [m] and status (ok or no-rebound: e = 0, t_c = inf).'

    character(len=*), parameter :: constants = &
        'Usage: hertzdamp constants [--format text|csv|json]' // nl // &
        '' // nl // &
        '  alpha_c  critical damping of the overlap definition (no rebound for' // nl // &
        '           alpha >= alpha_c), by bisection on the integrator''s no-rebound test' // nl // &
        '  tau_c0   elastic contact duration (4/5)(5/4)^(2/5) B(2/5,1/2), units of t*' // nl // &
        '  z_max0   elastic deepest overlap (5/4)^(2/5), units of u_in t*' // nl // &
        '  e1       restitution slope: e = 1 - e1 alpha + O(alpha^2)' // nl // &
        'CSV columns: name,value.'

    character(len=*), parameter :: invert = &
        'Usage: hertzdamp invert --e E[,E2,...] (--tc TC | --dt DT --steps N) --mass M' // nl // &
        '                        --velocity U [--k-phys K] [options]' // nl // &
        '' // nl // &
        'The inverse rule of the adaptive collision time model: k and d such that a' // nl // &
        'contact of mass M hit at velocity U has restitution E and contact time TC.' // nl // &
        '' // nl // &
        '  --e LIST       target restitution coefficients [-], comma-separated;' // nl // &
        '                 1e-3 <= e <= 1 (overlap) or 1e-4 <= e <= 1 (force)' // nl // &
        '  --tc TC        target contact time T_c [s]' // nl // &
        '  --dt DT        DEM time step [s], with --steps N: T_c = N DT' // nl // &
        '  --steps N      time steps per collision (integer >= 1)' // nl // &
        '  --mass M       effective mass m [kg]' // nl // &
        '  --velocity U   normal impact velocity u_in [m s^-1]' // nl // &
        '  --k-phys K     physical stiffness bound [N m^-3/2]: if K <= k, k = K and' // nl // &
        '                 d = alpha m^(3/5) K^(2/5) u^(1/5) (bound_active = true)' // nl // &
        '  --end overlap|force   contact-end definition (default overlap)' // nl // &
        '  --method M     fit (default, ~1e-13), compact (closed form, ~1e-5, e >= 0.05),' // nl // &
        '                 series / pade (Newton on the series / Pade formula, overlap' // nl // &
        '                 only, series alpha < 1, pade alpha <= 0.8) or iterative' // nl // &
        '                 (secant over reference-integrator solves)' // nl // &
        '  --tol T        tolerance of --method iterative, 1e-15 <= T <= 1e-2 (default 1e-10)' // nl // &
        '  --format F     text (aligned, default), csv or json' // nl // &
        '  --help         this text' // nl // &
        '' // nl // &
        'Columns: e, tc [s], mass [kg], velocity [m s^-1], alpha [-], tau_c [-],' // nl // &
        't_star [s] (time unit of k: contact time = t_star tau_c), k [N m^-3/2],' // nl // &
        'd [kg s^-1], bound_active, status.  Exit 3 when e is outside the range.'
    character(len=*), parameter :: bench = &
        'Usage: hertzdamp bench [--quick] [--format text|csv|json] [--plot FILE.png]' // nl // &
        '' // nl // &
        'Measures accuracy against time for every method the library provides, all in' // nl // &
        'one run (methods that report not-supported are left out):' // nl // &
        '  forward   alpha -> (e, tau_c) for a fixed set of alpha in [0, 1.1] (overlap) and' // nl // &
        '            [0, 50] (force): rk45 and GSL rkf45/rk8pd at tol 1e-4 ... 1e-12 (relative' // nl // &
        '            error control), series N = 1, 2, 3, 5, 10, 20 and pade (overlap only),' // nl // &
        '            compact, fit; errors against rk45 at tol 1e-15 (e relative to max(e, 1e-3))' // nl // &
        '  inverse   (e, T_c, m, u_in) -> (k, d) for e in [1e-3, 0.999]: fit, compact, series,' // nl // &
        '            pade, iterative at tol 1e-6, 1e-8, 1e-10; errors of alpha, k, d against' // nl // &
        '            the iterative inverse at tol 1e-13' // nl // &
        '  throughput  the elemental fit inverse over 10^6 random contacts' // nl // &
        'Times are wall clock per call: the median of 5 batches of >= 0.1 s each' // nl // &
        '(--quick: fewer points, 3 batches of >= 0.01 s; well under 30 s).' // nl // &
        'The text output ends with ''figure:'' lines: ratios measured side by side.' // nl // &
        '' // nl // &
        '  --quick         short run (smoke test, rough timings)' // nl // &
        '  --format F      text (default), csv or json' // nl // &
        '  --plot FILE     also write a work-precision diagram (PNG, gnuplot): error' // nl // &
        '                  against ns per call, forward and inverse panels.  Checked' // nl // &
        '                  before benchmarking: no gnuplot -> exit 4, unwritable -> exit 2.' // nl // &
        '  --help          this text' // nl // &
        '' // nl // &
        'CSV columns: problem,method,setting,max_rel_err_e,max_rel_err_tau,' // nl // &
        'max_rel_err_alpha,max_rel_err_k,max_rel_err_d,ns_per_call,rhs_evals (empty where' // nl // &
        'not applicable; rhs_evals is the mean per collision of the integrators).' // nl // &
        'problem is forward, inverse or throughput; setting is the tolerance (1e-10),' // nl // &
        'the series order (N=10), the array size (n=1000000) or empty.'
    character(len=*), parameter :: scene = &
        'Usage: hertzdamp scene FILE [--method M] [--format text|csv|json] [--plot FILE.png]' // nl // &
        '' // nl // &
        'Runs the DEM scene in FILE (Fortran namelist, see data/scenes/*.nml): spheres and' // nl // &
        'plane walls, normal forces only (tangential forces, friction and rotation are out' // nl // &
        'of scope), velocity Verlet at the scene''s dt.  At every contact onset the contact' // nl // &
        'gets k and d from the inverse rule for its effective mass and impact velocity, so' // nl // &
        'that it lasts T_c = N dt with the material pair''s restitution e = sqrt(e_a e_b);' // nl // &
        'the physical Hertz stiffness k_phys = (4/3) E* sqrt(R*) is the bound (k <= k_phys).' // nl // &
        'With report = ''restitution'' every contact keeps k = k_phys and only alpha(e) and d' // nl // &
        'are computed.' // nl // &
        '' // nl // &
        'Groups and keys (all SI units):' // nl // &
        '  &scene    title, dt, steps_per_contact (N), end_time, gravity (.true./.false.),' // nl // &
        '            g (3, default 0,0,-9.81), contact_end (''overlap''|''force''),' // nl // &
        '            report (''restitution''|''restitution duration''), accuracy (default 1e-3),' // nl // &
        '            domain_lo, domain_hi (3 each, optional box), rest_speed (default 1e-3),' // nl // &
        '            samples (trace points, default 1000)                       once' // nl // &
        '  &material name, density, youngs_modulus, poisson_ratio, restitution       repeated' // nl // &
        '  &particle material, radius, position (3), velocity (3, default 0),' // nl // &
        '            count (default 1), spacing (3): count copies at position + i*spacing' // nl // &
        '  &wall     material, point (3), normal (3; particles stay on its side)       repeated' // nl // &
        '' // nl // &
        '  --method M   auto (default): the cheapest rule whose error, measured against the' // nl // &
        '               reference integrator at the scene''s target e values (pairs of' // nl // &
        '               materials that can meet), is within the scene''s accuracy.  Cost' // nl // &
        '               order: first-order < compact < series < pade < fit < iterative.' // nl // &
        '               Or one of first-order compact series pade fit iterative.' // nl // &
        '  --format F   text (default), csv (sections, each after a "# name" line), json' // nl // &
        '  --plot P     positions and velocities against time (gnuplot, PNG)' // nl // &
        '' // nl // &
        'Reports: the method choice; for every binary contact (no other contact on either' // nl // &
        'body meanwhile) the achieved restitution (separation/impact normal speed) and' // nl // &
        'contact duration against the targets; momentum (no walls, no gravity), energy,' // nl // &
        'domain and rest checks; run time, time in the contact rule, and the same scene' // nl // &
        'run with the iterative rule, with the speed-up.' // nl // &
        'Invalid scene: one line naming the line or key on stderr, exit 2, no output.'

contains

    !> Print the help of a command ('' for the program).
    subroutine print_help(command)
        character(len=*), intent(in) :: command
        select case (command)
        case ('table'); write (output_unit, '(a)') table
        case ('forward'); write (output_unit, '(a)') forward
        case ('constants'); write (output_unit, '(a)') constants
        case ('invert'); write (output_unit, '(a)') invert
        case ('bench'); write (output_unit, '(a)') bench
        case ('scene'); write (output_unit, '(a)') scene
        case default; write (output_unit, '(a)') top
        end select
        flush (output_unit)
    end subroutine print_help

    !> True if any argument after the command is --help or -h.
    logical function wants_help()
        integer :: i
        character(len=16) :: a
        wants_help = .false.
        do i = 2, command_argument_count()
            call get_command_argument(i, a)
            if (a == '--help' .or. a == '-h') wants_help = .true.
        end do
    end function wants_help

end module hertzdamp_cli_help
