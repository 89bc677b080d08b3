!> Help texts of the `hertzdamp` program and its commands, and its version.
!>
!> Help goes to stdout through the checked writer (a failed write exits 4, e.g.
!> `hertzdamp --help > /dev/full`).  doc/hertzdamp.1 carries the same commands and
!> options (test/docs/cli_docs.sh checks it).
module hertzdamp_cli_help
    use hertzdamp_cli, only: write_stdout, quit, EXIT_OK
    use hertzdamp, only: hertzdamp_law_listing, hertzdamp_end_listing, hertzdamp_host_listing, &
                         hertzdamp_method_listing, hertzdamp_law_choices, hertzdamp_end_choices, hertzdamp_host_choices, &
                         hertzdamp_method_choices, hertzdamp_tangential_listing, hertzdamp_lever_listing
    implicit none
    private
    public :: print_help, wants_help, hertzdamp_version, expand_help

    !> The program's version: the same as fpm.toml and CMakeLists.txt (test/docs/cli_docs.sh).
    character(len=*), parameter :: hertzdamp_version = '0.2.0'

    character(len=*), parameter :: nl = new_line('a')

    character(len=*), parameter :: list_syntax = &
        'LIST: comma-separated values and ranges, e.g. 0.9 or 0.5,0.9 or 0.01:5:20' // nl // &
        '(20 values from 0.01 to 5, evenly spaced; whole numbers exactly where the' // nl // &
        'points are whole, 1:23:23) or 0.01:5:log20 (evenly spaced in log); one row per' // nl // &
        'combination of the lists, at most 10000 rows.  CSV and JSON numbers read back' // nl // &
        'as the same double (16 significant digits, 17 where needed).'

    character(len=*), parameter :: quiet_help = &
        '  --quiet               no warnings on stderr about values outside what granular' // nl // &
        '                        materials have, most often a unit slip: E outside 1e5 to' // nl // &
        '                        1e13 Pa, R outside 1e-7 to 1 m, RHO outside 10 to 3e4' // nl // &
        '                        kg m^-3, impact speeds above 1e3 m s^-1 (the results are' // nl // &
        '                        printed all the same)'

    character(len=*), parameter :: contact_help = &
        'Contact (definitions: hertzdamp --help):' // nl // &
        '  --mass M              effective mass m* [kg]; or from the materials:' // nl // &
        '  --radius R            sphere 1 radius [m] (gives R*; with --density, m*)' // nl // &
        '  --density RHO         sphere 1 density [kg m^-3]' // nl // &
        '  --youngs-modulus E    sphere 1 Young''s modulus [Pa]    with --radius: k_phys' // nl // &
        '  --poisson-ratio NU    sphere 1 Poisson''s ratio [-]     = (4/3) E* sqrt(R*)' // nl // &
        '  --radius2 R2  --density2 RHO2  --youngs-modulus2 E2  --poisson-ratio2 NU2' // nl // &
        '                        sphere 2; each defaults to sphere 1''s (two equal spheres)' // nl // &
        '  --wall                body 2 is a wall: infinite radius and mass (m* = m,' // nl // &
        '                        R* = R); its E and NU from --youngs-modulus2 and' // nl // &
        '                        --poisson-ratio2, by default sphere 1''s' // nl // &
        '  --k-phys K            physical stiffness [N m^-3/2] instead of E and NU' // nl // &
        quiet_help

    character(len=*), parameter :: status_help = &
        'Status of a row: ok; no-rebound (a result: the overlap never returns to zero,' // nl // &
        'e = 0, contact time inf); bad-input (an invalid value, the message names the' // nl // &
        'option); outside-validity (outside the method''s range); inaccurate (the' // nl // &
        'method''s own error estimate exceeds --accuracy); out-of-range (not' // nl // &
        'representable in double precision); failed (the computation failed).  A row' // nl // &
        'without a result keeps its inputs; its results are empty (csv), null (json)' // nl // &
        'or - (text), as are quantities a method does not give.' // nl // &
        'Exit: 0 when every row has a result; 3 when some have none (all rows are' // nl // &
        'printed, and one line on stderr says how many and why), 4 if a computation of' // nl // &
        'one of them failed; when none has one, nothing on stdout, one line on stderr,' // nl // &
        'exit 2 (bad input), 3 or 4 (failed).'

    character(len=*), parameter :: method_help = &
        '  --damping LAW         damping force d zeta^q zeta'': {laws_help}; other' // nl // &
        '                        laws: methods fit and rk45 (inverse: fit, iterative).' // nl // &
        '                        doc/damping-laws.md' // nl // &
        '  --end {ends|}   contact end: {ends_help}' // nl // &
        '  --accuracy A          relative accuracy asked of series and pade (default' // nl // &
        '                        1e-10): beyond it the row is inaccurate' // nl // &
        '  --format F            text (default; for people: units in the header, 7' // nl // &
        '                        digits, what every row shares once above the table),' // nl // &
        '                        csv or json' // nl // &
        '  --progress            progress on stderr (default: on a terminal, after 2 s,' // nl // &
        '                        one line that an error replaces; into a file or pipe,' // nl // &
        '                        lines that precede an error, which comes last)' // nl // &
        '  --help                this text'

    character(len=*), parameter :: forward_methods_help = &
        '  --method M            {forward_methods_help}' // nl // &
        '  --order N             series truncation order, 0..24 (default 13: 1e-12 at' // nl // &
        '                        alpha <= 0.2)' // nl // &
        '  --tol T               rk45 tolerance, 1e-15 <= T <= 1e-2 (default 1e-13)'

    character(len=*), parameter :: inverse_methods_help = &
        '  --method M            {inverse_methods_help}' // nl // &
        '  --tol T               tolerance of --method iterative, 1e-15 <= T <= 1e-2' // nl // &
        '                        (default 1e-10)'

    character(len=*), parameter :: top = &
        'hertzdamp - damped Hertzian normal collision of spheres' // nl // &
        '' // nl // &
        'Model: m* zeta'''' = -d zeta'' - k zeta^(3/2), zeta(0) = 0, zeta''(0) = u_in, with' // nl // &
        'zeta the overlap.  Every collision depends on one parameter' // nl // &
        '  alpha = d m*^(-3/5) k^(-2/5) u_in^(-1/5),  time unit t* = (m*/(k u_in^(1/2)))^(2/5).' // nl // &
        '' // nl // &
        'Usage: hertzdamp COMMAND [options]      hertzdamp COMMAND --help' // nl // &
        '       hertzdamp --version' // nl // &
        '' // nl // &
        'Commands:' // nl // &
        '  invert     stiffness k and damping d (SI) from target e and contact time' // nl // &
        '  forward    e, contact time, deepest overlap (SI) from k, d, mass, velocity' // nl // &
        '  timestep   shortest physical contact and the time step that resolves it' // nl // &
        '  table      e, tau_c, z_max, tau_max (dimensionless) for a list of alpha' // nl // &
        '  constants  alpha_c, tau_c(0), z_max(0), e1 as computed by the library' // nl // &
        '  bench      work-precision report of every method (forward, inverse, throughput)' // nl // &
        '  scene      run a DEM scene file (namelist), the inverse rule at every contact' // nl // &
        '  check      what a peer engine''s deck really does: e, contact time, time step, a fix' // nl // &
        '  calibrate  k, d and the damping law fitted to measured e(u) and T_c(u) (CSV)' // nl // &
        '  oblique    oblique frictional impact: e_n, e_t, spin, physical or softened' // nl // &
        '' // nl // &
        'Definitions (SI units; body 1 and body 2 touch):' // nl // &
        '  effective mass m*     m1 m2 / (m1 + m2); against a wall, or a particle held' // nl // &
        '                        fixed, the moving particle''s own mass m1.  A sphere:' // nl // &
        '                        m = (4/3) pi rho R^3.' // nl // &
        '  effective radius R*   R1 R2 / (R1 + R2); against a flat wall R1.' // nl // &
        '  effective modulus E*  1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (a wall too).' // nl // &
        '  k_phys                the physical Hertz stiffness (4/3) E* sqrt(R*) [N m^-3/2].' // nl // &
        '  relative normal impact velocity u_in' // nl // &
        '                        the speed at which the two surfaces approach along the' // nl // &
        '                        line of centres when they first touch: (v1 - v2) . n' // nl // &
        '                        with n the unit vector from body 1 to body 2 [m s^-1].' // nl // &
        '  e                     restitution: normal separation speed / approach speed.' // nl // &
        '' // nl // &
        'Exit codes: 0 success, 2 bad usage, 3 no solution, 4 computation failed (also' // nl // &
        'when some rows of a table have a result and the computation of another failed).' // nl // &
        'Errors go to stderr as one line (the last, after the lines --progress writes' // nl // &
        'into a file or pipe); stdout is then empty, except for commands that print one' // nl // &
        'row per value, where rows with a result still print (see their --help).' // nl // &
        'Documentation: man hertzdamp, doc/cli.md, README.md, doc/theory.md.'

    character(len=*), parameter :: table = &
        'Usage: hertzdamp table [--alpha LIST] [--alpha-range A0:A1:N] [options]' // nl // &
        '' // nl // &
        'One row per alpha (dimensionless damping parameter): alpha, e (restitution),' // nl // &
        'tau_c (contact duration in units of t*), z_max (deepest overlap in units of' // nl // &
        'u_in t*), tau_max (time of deepest overlap, units of t*), status.  With' // nl // &
        'no-rebound e = 0 and tau_c = inf (JSON null).  compact gives no z_max, tau_max.' // nl // &
        'Without --alpha/--alpha-range: alpha = 0, 0.05, ..., 1.1, 1.12, 1.13.' // nl // &
        '' // nl // &
        '  --alpha LIST          alpha values' // nl // &
        '  --alpha-range A0:A1:N N equally spaced values from A0 to A1 (N >= 1)' // nl // &
        forward_methods_help // nl // method_help // nl // &
        '' // nl // list_syntax // nl // nl // status_help

    character(len=*), parameter :: forward = &
        'Usage: hertzdamp forward --k LIST --d LIST --velocity LIST' // nl // &
        '                         (--mass M | --radius R --density RHO ...) [options]' // nl // &
        '' // nl // &
        'What a stiffness k and damping d give: the restitution and contact time of a' // nl // &
        'contact with effective mass m* hit at relative normal velocity u_in.' // nl // &
        '' // nl // &
        '  --k LIST              Hertz stiffness k [N m^-3/2]; default with the elastic' // nl // &
        '                        constants: k = k_phys (the physical contact)' // nl // &
        '  --d LIST              linear damping coefficient d [kg s^-1], >= 0' // nl // &
        '  --velocity LIST       relative normal impact velocity u_in [m s^-1]' // nl // &
        contact_help // nl // &
        'Method:' // nl // forward_methods_help // nl // method_help // nl // &
        '' // nl // &
        'Columns: k, d, velocity, mass (m*), radius_eff (R*), k_phys, alpha [-],' // nl // &
        't_star [s], e [-], t_c (contact time) [s], zeta_max (deepest overlap) [m], status.' // nl // &
        'A damping so strong that alpha exceeds what the method takes (or double' // nl // &
        'precision) is no-rebound with the overlap end.' // nl // &
        '' // nl // list_syntax // nl // nl // status_help

    character(len=*), parameter :: constants = &
        'Usage: hertzdamp constants [--damping LAW] [--format text|csv|json]' // nl // &
        '' // nl // &
        '  alpha_c  critical damping of the overlap definition (no rebound for' // nl // &
        '           alpha >= alpha_c), by bisection on the integrator''s no-rebound test' // nl // &
        '           (linear; tsuji: sqrt(5); kuwabara-kono: none, empty)' // nl // &
        '  tau_c0   elastic contact duration (4/5)(5/4)^(2/5) B(2/5,1/2), units of t*' // nl // &
        '  z_max0   elastic deepest overlap (5/4)^(2/5), units of u_in t*' // nl // &
        '  e1       restitution slope: e = 1 - e1 alpha + O(alpha^2) (of the law)' // nl // &
        '' // nl // &
        '  --damping LAW  {laws} (default linear)' // nl // &
        '  --format F   text (aligned, default), csv or json' // nl // &
        '  --help       this text' // nl // &
        'CSV columns: name,value.'

    !> The --host option of invert and timestep.
    character(len=*), parameter :: host_help = &
        '  --host NAME           the DEM host''s time integrator (default none):' // nl // &
        '                        {hosts_help}:' // nl // &
        '                        alpha, tau_c make the achieved e and T_c of the host''s' // nl // &
        '                        N-step collision exact on average over the onset phase;' // nl // &
        '                        adds e_spread and tc_spread (their standard deviations' // nl // &
        '                        over the phase, relative).  N too small to reach e: the' // nl // &
        '                        row is outside-validity and says which N can'

    character(len=*), parameter :: invert = &
        'Usage: hertzdamp invert --e LIST (--tc LIST | --dt LIST --steps LIST)' // nl // &
        '                        --velocity LIST (--mass M | --radius R --density RHO ...)' // nl // &
        '                        [--k-phys K | --youngs-modulus E --poisson-ratio NU]' // nl // &
        '                        [--host NAME [--onset-phase LIST]] [--fixed] [options]' // nl // &
        '' // nl // &
        'The inverse rule of the adaptive collision time model: the stiffness k and' // nl // &
        'damping d that give a contact with effective mass m*, hit at relative normal' // nl // &
        'velocity u_in, the restitution e and the contact time T_c.  With a physical' // nl // &
        'stiffness (--k-phys, or k_phys = (4/3) E* sqrt(R*) from the materials) the bound' // nl // &
        'applies: if k_phys <= k, then k = k_phys and' // nl // &
        'd = alpha m*^(3/5) k_phys^(2/5) u_in^(1/5) (bound_active true), and the contact' // nl // &
        'lasts tc_actual > T_c.' // nl // &
        '' // nl // &
        'Target:' // nl // &
        '  --e LIST              restitution coefficients [-]' // nl // &
        '  --tc LIST             contact times T_c [s]' // nl // &
        '  --dt LIST             time step of the DEM code [s], with' // nl // &
        '  --steps LIST          time steps per contact N (whole numbers): T_c = N dt;' // nl // &
        '                        N dt beyond double precision: out-of-range' // nl // &
        '  --velocity LIST       relative normal impact velocity u_in [m s^-1]' // nl // &
        host_help // nl // &
        '                        (needs --dt and --steps; not with --fixed)' // nl // &
        '  --onset-phase LIST    with --host (not none): per-contact constants for the' // nl // &
        '                        onset phases phi in (0, 1] (the first overlap over' // nl // &
        '                        u_in dt): one row per phase with alpha, tau_c, k and d' // nl // &
        '                        that make that single contact''s e and T_c = N dt exact' // nl // &
        '                        in the host''s scheme.  Columns: e, tc, velocity, mass,' // nl // &
        '                        radius_eff, k_phys, onset_phase, alpha, tau_c, t_star, k,' // nl // &
        '                        d, bound_active, status.  Some phase unreachable at N:' // nl // &
        '                        outside-validity, saying which N can' // nl // &
        '  --fixed               one k and d for every contact, for engines that cannot set' // nl // &
        '                        them per contact: over the range of the --velocity list' // nl // &
        '                        the worst |e_fixed/e - 1| as small as one pair makes it' // nl // &
        '                        (equal and opposite at the slowest and fastest impact),' // nl // &
        '                        and the shortest contact of the range lasting T_c (every' // nl // &
        '                        contact then takes at least --steps steps of --dt); with' // nl // &
        '                        k_phys below that k, k = k_phys.  Uses the fitted forward' // nl // &
        '                        maps (rk45 beyond them): no --method, --tol, --accuracy.' // nl // &
        '                        Columns: e, tc, velocity, mass, radius_eff, k_phys, k, d,' // nl // &
        '                        bound_active, alpha, e_fixed, e_error (e_fixed/e - 1),' // nl // &
        '                        tc_fixed [s] (what the pair gives at that speed),' // nl // &
        '                        worst_e_error, status' // nl // &
        contact_help // nl // &
        'Method:' // nl // inverse_methods_help // nl // method_help // nl // &
        '' // nl // &
        'Columns: e, tc [s], velocity [m s^-1], mass (m*) [kg], radius_eff (R*) [m],' // nl // &
        'k_phys, alpha [-], tau_c [-], t_star [s] (time unit of the returned k), k' // nl // &
        '[N m^-3/2], d [kg s^-1], bound_active, tc_actual [s] (the contact time the' // nl // &
        'returned k and d give: t_star tau_c), with --host e_spread and tc_spread, status.' // nl // &
        '' // nl // list_syntax // nl // nl // status_help

    character(len=*), parameter :: timestep = &
        'Usage: hertzdamp timestep --e LIST --velocity LIST [--steps LIST]' // nl // &
        '                          (--mass M | --radius R --density RHO ...)' // nl // &
        '                          (--k-phys K | --youngs-modulus E --poisson-ratio NU)' // nl // &
        '                          [--host NAME] [options]' // nl // &
        '' // nl // &
        'The time step a DEM code needs for its physical contacts (k = k_phys, d from' // nl // &
        'e): the contact time t* tau_c(alpha(e)) falls as u_in^(-1/5), so the shortest' // nl // &
        'contact is the fastest impact of the velocity LIST.  The largest time step that' // nl // &
        'resolves it with N steps is dt_max = tc_damped / N.  Next to it, the elastic' // nl // &
        'Hertz estimate most DEM codes use, T_c = 2.868 (m*^2 / (R* E*^2 u_in))^(1/5) =' // nl // &
        'tau_c(0) t*: elastic_excess = tc_elastic / tc_damped - 1 says how much longer' // nl // &
        '(> 0) or shorter (< 0) it is than the damped contact.  With the spheres'' radii,' // nl // &
        'densities and elastic constants, also the Rayleigh time step of codes that do' // nl // &
        'not look at the impact speed (EDEM; LIGGGHTS fix check/timestep/gran):' // nl // &
        't_rayleigh = pi R / v_R, v_R = (0.1631 nu + 0.8766) sqrt(G/rho), G = E/(2(1+nu))' // nl // &
        '(the usual fit of the Rayleigh wave speed, within 0.3 % for 0 <= nu <= 0.5;' // nl // &
        'the smaller sphere''s), and dt_rayleigh = 0.2 t_rayleigh, the usual fraction' // nl // &
        '(EDEM: 20 %, range 10 to 40 %).' // nl // &
        '' // nl // &
        '  --e LIST              restitution coefficients of the material pair [-]' // nl // &
        '  --velocity LIST       relative normal impact velocities u_in [m s^-1]' // nl // &
        '  --steps LIST          time steps per contact N, whole numbers (default 10)' // nl // &
        host_help // nl // &
        '                        (needs --steps: the constants depend on N)' // nl // &
        contact_help // nl // &
        'Method:' // nl // inverse_methods_help // nl // method_help // nl // &
        '' // nl // &
        'Columns: e, steps, velocity_max [m s^-1], mass [kg], radius_eff [m], k_phys,' // nl // &
        'alpha, tau_c [-], tc_damped [s], tc_elastic [s], elastic_excess [-],' // nl // &
        'dt_max [s], dt_elastic [s] (tc_elastic / N), t_rayleigh [s], dt_rayleigh [s]' // nl // &
        '(empty without the materials), with --host e_spread and tc_spread, status.' // nl // &
        '' // nl // list_syntax // nl // nl // status_help

    character(len=*), parameter :: oblique = &
        'Usage: hertzdamp oblique --e E --velocity U --angle LIST --friction MU' // nl // &
        '                         --radius R --density RHO (--radius2 R2 --density2 RHO2 | --wall)' // nl // &
        '                         --youngs-modulus E --poisson-ratio NU [options]' // nl // &
        '' // nl // &
        'The oblique impact of sphere 1 (radius, density) at speed U and angle theta from' // nl // &
        'the normal on sphere 2 at rest or on a wall, neither spinning, in the plane of' // nl // &
        'impact (doc/oblique.md).  Normal force k delta^(3/2) + d delta^q delta'' of the' // nl // &
        'law; tangential force of LAMMPS pair_style granular: mindlin -k_t a xi - eta_t v_t' // nl // &
        '(a = sqrt(R* delta)) or linear_history -k_t xi - eta_t v_t, eta_t = x_gammat d,' // nl // &
        'Coulomb limit mu |F_n| (damping included), the history carried along the turning' // nl // &
        'tangent; solid spheres; the line of centres recomputed continuously.  The' // nl // &
        'physical contact has k = k_phys and d of e at the normal speed U cos(theta).' // nl // &
        'With --dt and --steps the softened contact of the adaptive rule instead: k, d of' // nl // &
        'T_c = N dt at U cos(theta) (k_phys when it is softer), and k_t adapted so that a' // nl // &
        'sphere on a wall (lever arm R) is a time-stretched copy of the physical contact:' // nl // &
        'mindlin k_t k/k_phys, linear_history k_t (k/k_phys)^(4/5).' // nl // &
        '' // nl // &
        '  --e E                 restitution coefficient of the normal contact [-]' // nl // &
        '  --velocity U          impact speed |v_in| [m s^-1] (its normal part U cos theta)' // nl // &
        '  --angle LIST          impact angles theta from the normal [degrees], 0 <= theta < 90' // nl // &
        '  --friction MU         Coulomb friction coefficient (0: frictionless)' // nl // &
        '  --tangential MODEL    {tangentials} (default mindlin)' // nl // &
        '  --kt KT               tangential stiffness (mindlin: default 8 G* from the moduli,' // nl // &
        '                        1/G* = 2(2-nu1)(1+nu1)/E1 + 2(2-nu2)(1+nu2)/E2 [N m^-2];' // nl // &
        '                        linear_history: required [N m^-1])' // nl // &
        '  --xgammat X           tangential damping eta_t = X d (default 0)' // nl // &
        '  --lever ARM           torque lever arm: {levers} (default: radius on a wall,' // nl // &
        '                        contact for two spheres, as LAMMPS)' // nl // &
        '  --dt DT --steps N     the softened contact, T_c = N dt [s]' // nl // &
        '  --tangential-stiffness adapted|physical' // nl // &
        '                        k_t of the softened contact (default adapted)' // nl // &
        '  --normal-correction   two spheres: the constants whose oblique e_n equals e' // nl // &
        '                        (a secant solve of the oblique contact per row)' // nl // &
        contact_help // nl // &
        '  --damping LAW, --end END, --format FMT    as invert' // nl // &
        '' // nl // &
        'Columns: angle [deg], e_n (line-of-centres velocity ratio at touch and release),' // nl // &
        'e_t (the contact point''s -v_c,out/v_c,in: -1 smooth, +1 rough), vt_ratio (the' // nl // &
        'centres'' v_t,out/v_t,in), rebound_angle [deg], omega [rad/s] (sphere 1), with' // nl // &
        '--dt/--steps the softened contact''s, then k, d, kt, eta_t (x_gammat d) it used' // nl // &
        'and diff_* (softened - physical); with --normal-correction e_target (the' // nl // &
        'corrected target of the normal rule); status.  At angle 0 e_t and vt_ratio are 0.' // nl // &
        '' // nl // status_help

    character(len=*), parameter :: bench = &
        'Usage: hertzdamp bench [--quick] [--damping LAW|all] [--format text|csv|json]' // nl // &
        '                       [--plot FILE.png] [--progress]' // nl // &
        '' // nl // &
        'Measures accuracy against time for every method the library provides, all in' // nl // &
        'one run, for every damping law (methods that report not-supported are left out):' // nl // &
        '  forward   alpha -> (e, tau_c) for a fixed set of alpha per law and contact end' // nl // &
        '            (overlap and force, down to e ~ 1e-4): rk45 and GSL rkf45/rk8pd at tol' // nl // &
        '            1e-4 ... 1e-12 (relative error control), fit; linear law also series' // nl // &
        '            N = 1, 2, 3, 5, 10, 20 and pade (overlap only), compact; errors against' // nl // &
        '            rk45 at tol 1e-15 (e relative to max(e, 1e-3))' // nl // &
        '  inverse   (e, T_c, m, u_in) -> (k, d) for e in [1e-3, 0.999] (overlap): fit,' // nl // &
        '            iterative (secant over rk45) at tol 1e-6 ... 1e-12; linear law also' // nl // &
        '            compact, series, pade and gsl-secant (secant over GSL rk8pd); errors of' // nl // &
        '            alpha, k, d against the iterative inverse at tol 1e-14' // nl // &
        '  entry     the fit inverse of each law through every entry point (module scalar' // nl // &
        '            and array calls, C, legacy) over 10^6 random contacts, side by side,' // nl // &
        '            checked bit for bit against the module scalar call' // nl // &
        '  closed-form  tsuji: its inverse against alpha = sqrt5 beta(e) of the overlap end' // nl // &
        '  pair      linear law: the per-contact call of a DEM host (hertzdamp_c_pair_kd,' // nl // &
        '            hertzdamp_pair_kd, scalar and array) against the bare formula' // nl // &
        '            k = m r^(5/2) u^(-1/2), d = alpha m r it replaces (target: C at most' // nl // &
        '            1.5 x), and hertzdamp_invert with T_c and m the same for every contact' // nl // &
        'Times are wall clock per call: the median of 5 batches of >= 0.1 s each' // nl // &
        '(--quick: fewer points, 3 batches of >= 0.01 s; about 10 s).' // nl // &
        'The text output ends with ''figure:'' lines: ratios measured side by side.' // nl // &
        '' // nl // &
        '  --quick         short run (smoke test, rough timings)' // nl // &
        '  --damping LAW   the rows of one law: {laws} (default all)' // nl // &
        '  --format F      text (default), csv or json' // nl // &
        '  --plot FILE     also write a work-precision diagram (PNG, gnuplot): error' // nl // &
        '                  against ns per call, forward and inverse panels per law.' // nl // &
        '                  Checked before benchmarking: no gnuplot -> exit 4, unwritable' // nl // &
        '                  -> exit 2.' // nl // &
        '  --progress      progress on stderr (default: on a terminal, after 2 s)' // nl // &
        '  --help          this text' // nl // &
        '' // nl // &
        'CSV columns: problem,damping,method,setting,max_rel_err_e,max_rel_err_tau,' // nl // &
        'max_rel_err_alpha,max_rel_err_k,max_rel_err_d,ns_per_call,rhs_evals (empty where' // nl // &
        'not applicable; rhs_evals is the mean per collision of the integrators).' // nl // &
        'problem is forward, inverse, entry, closed-form or pair; setting is the tolerance' // nl // &
        '(1e-10), the series order (N=10), the number of contacts (n=1000000) or empty.'
    character(len=*), parameter :: scene = &
        'Usage: hertzdamp scene FILE [--method M] [--damping LAW] [--format text|csv|json]' // nl // &
        '                            [--plot FILE.png] [--progress] [--no-compare]' // nl // &
        '                            [--host H --dt DT --steps N [--onset-phase]]' // nl // &
        '' // nl // &
        'Runs the DEM scene in FILE (Fortran namelist, see data/scenes/*.nml): spheres and' // nl // &
        'plane walls, normal forces only (tangential forces, friction and rotation are out' // nl // &
        'of scope), velocity Verlet at the scene''s dt.  At every contact onset the contact' // nl // &
        'gets k and d from the inverse rule for its effective mass and impact velocity, so' // nl // &
        'that it lasts T_c = N dt with the material pair''s restitution e = sqrt(e_a e_b);' // nl // &
        'the physical Hertz stiffness k_phys = (4/3) E* sqrt(R*) is the bound (k <= k_phys).' // nl // &
        'With report = ''restitution'' every contact keeps k = k_phys and only alpha(e) and d' // nl // &
        'are computed.  Contact force k zeta^(3/2) + d zeta^q zeta'', q of the damping law:' // nl // &
        '{laws_help}.' // nl // &
        '' // nl // &
        'Groups and keys (all SI units):' // nl // &
        '  &scene    title, dt, steps_per_contact (N), end_time, gravity (.true./.false.),' // nl // &
        '            g (3, default 0,0,-9.81), contact_end ({ends''}),' // nl // &
        '            damping ({laws''}, default linear),' // nl // &
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
        '               materials that can meet), is within the scene''s accuracy in e and' // nl // &
        '               in the contact duration tau_c (the report checks both).  Cost' // nl // &
        '               order: first-order < compact < series < pade < fit < iterative.' // nl // &
        '               Or one of first-order compact series pade fit iterative.' // nl // &
        '               compact, series and pade exist for the linear law only (skipped' // nl // &
        '               by auto, refused when asked for with another law).' // nl // &
        '  --damping LAW  {laws}: overrides the file''s damping key (the report states' // nl // &
        '               the law)' // nl // &
        '  --format F   text (default), csv (sections, each after a "# name" line), json' // nl // &
        '  --plot P     positions and velocities against time (gnuplot, PNG; never the' // nl // &
        '               scene file itself: exit 2)' // nl // &
        '  --progress   percentage and time left of each run on stderr (on a terminal' // nl // &
        '               without the option, once a run has taken 2 s)' // nl // &
        '  --no-compare skip the re-run with the iterative rule (no speed-up figures)' // nl // &
        '  --host H     none (default: the engine''s velocity Verlet, the rule of --method),' // nl // &
        '               {engine_hosts}: the contacts are integrated' // nl // &
        '               by that host''s scheme and get k, d from its per-pair constants' // nl // &
        '               (hertzdamp_pair_init at N; doc/host-schemes.md); needs --dt and' // nl // &
        '               --steps, which override the file''s dt and steps_per_contact' // nl // &
        '  --onset-phase  with --host: each contact gets its own k, d from its onset' // nl // &
        '               phase phi = first overlap / (u_in dt) (hertzdamp_pair_kd_phase;' // nl // &
        '               every contact''s e exact, not only the mean over the phase)' // nl // &
        '' // nl // &
        'Reports: the method choice; for every binary contact (no other contact on either' // nl // &
        'body meanwhile) the achieved restitution (separation/impact normal speed) and' // nl // &
        'contact duration against the targets; momentum (no walls, no gravity), energy,' // nl // &
        'domain and rest checks; run time, time in the contact rule, and the same scene' // nl // &
        'run with the iterative rule, with the speed-up.' // nl // &
        'Invalid scene (also values the engine cannot represent: masses, energies,' // nl // &
        'step counts, trace sizes): one line naming the line or key on stderr, exit 2,' // nl // &
        'no output.' // nl // &
        'A check that fails: the report on stdout, one line naming the failed checks on' // nl // &
        'stderr, exit 5.'

    character(len=*), parameter :: calibrate = &
        'Usage: hertzdamp calibrate FILE (--mass M | --radius R --density RHO [--wall])' // nl // &
        '                 [--k-phys K | --youngs-modulus E --poisson-ratio NU] [--damping D]' // nl // &
        '                 [options]' // nl // &
        '' // nl // &
        'Fits the damped-Hertz model m zeta'''' = -k zeta^(3/2) - d zeta^q zeta'' to measured' // nl // &
        'restitution coefficients e(u), and contact times T_c(u), at several impact speeds u' // nl // &
        '(nonlinear least squares, Levenberg-Marquardt with LAPACK, exact derivatives).' // nl // &
        '' // nl // &
        'FILE is CSV (RFC 4180: a field may be quoted; UTF-8, a byte-order mark at the' // nl // &
        'start is skipped; LF or CRLF line ends) with a header line naming the columns' // nl // &
        '(any order; lines starting with # and blank lines are skipped).  At most 100000' // nl // &
        'data rows and 4096 characters per line (longer: exit 2).  Columns:' // nl // &
        '  velocity   impact speed u [m s^-1] > 0                        (required)' // nl // &
        '  e          restitution coefficient, 0 < e <= 1                (required)' // nl // &
        '  tc         contact time [s] > 0 (an empty field: not measured)' // nl // &
        '  sigma_e    standard uncertainty of e' // nl // &
        '  sigma_tc   standard uncertainty of tc [s] (with sigma_e when tc is given)' // nl // &
        'At least two different speeds.  With e only the data identify the combination' // nl // &
        'c = d k^(-2(1+q)/5) (alpha = c m^((2q-3)/5) u^((4q-1)/5)), not k and d apart:' // nl // &
        'give contact times, or the stiffness (--k-phys or elastic constants), for both.' // nl // &
        '' // nl // &
        '  --mass M        effective mass m* [kg], or from the materials as in invert:' // nl // &
        '  --radius R --density RHO [--radius2 R2 --density2 RHO2 | --wall]' // nl // &
        '  --k-phys K      the physical stiffness [N m^-3/2], or from the elastic constants' // nl // &
        '  --youngs-modulus E --poisson-ratio NU [--youngs-modulus2 E2 --poisson-ratio2 NU2]' // nl // &
        '                  (with --radius): without contact times the fit takes k = k_phys' // nl // &
        '                  and gives d; with contact times k is fitted, k_phys shown beside' // nl // &
        '  --damping D     {laws_help}, or auto (default): every law, the one with the' // nl // &
        '                  smallest AIC chosen' // nl // &
        '                  (AIC = chi2 + 2p with sigmas, n ln(RSS/n) + 2p without; all laws' // nl // &
        '                  have the same p, so this is the smallest chi2 or RSS); a law' // nl // &
        '                  whose fit failed is passed over only where it already fits worse,' // nl // &
        '                  else none is chosen (exit 4)' // nl // &
        '  --end {ends|}   contact-end definition (default overlap)' // nl // &
        '  --method M      fit (default: machine-precision maps and their exact derivatives;' // nl // &
        '                  the reference integrator for measurements beyond the maps, e < 1e-5)' // nl // &
        '                  or rk45 (reference integrator in the loop, for checking; slow)' // nl // &
        '  --tol T         rk45 tolerance, 1e-15 <= T <= 1e-2 (default 1e-13)' // nl // &
        '  --format F      text (default: summary and residuals), csv (summary) or json' // nl // &
        '                  (the settings, every law under "laws", the data with each' // nl // &
        '                  fitted law''s values under "residuals")' // nl // &
        '  --plot FILE     the data with error bars and the fitted e(u), T_c(u) of each law' // nl // &
        '                  (PNG, gnuplot; checked before any work: no gnuplot -> exit 4,' // nl // &
        '                  not a regular file, not writable, or the data file -> exit 2)' // nl // &
        '  --quiet         no warnings about implausible R, RHO, E or file speeds (as invert)' // nl // &
        '  --help          this text' // nl // &
        '' // nl // &
        'Weights: 1/sigma when the sigma columns are given (then chi2/dof and its p-value);' // nl // &
        'otherwise e residuals absolute and T_c residuals relative, weighted equally, and' // nl // &
        'the uncertainties scaled by the RMS of the weighted residuals.' // nl // &
        'Uncertainties: standard (1 sigma), from the Jacobian at the optimum.' // nl // &
        '' // nl // &
        'CSV columns: damping,chosen,k,d,k_err,d_err,rms_residual_e,rms_residual_tc,c,c_err,' // nl // &
        'chi2_dof,p_value,delta_aic,status (one row per law, the chosen first; empty fields' // nl // &
        'for what the data do not identify).  Units: k [N m^-3/2], d [kg s^-1 m^-q],' // nl // &
        'rms_residual_tc [s], c [SI].' // nl // &
        'Exit codes: 2 invalid file or values (NaN, u <= 0, e outside (0, 1], ...), 3 the' // nl // &
        'data cannot determine the parameters (one speed only, e = 1 everywhere), 4 the fit' // nl // &
        'did not converge (without sigmas: Gauss-Newton correction above 1e-10) or the model' // nl // &
        'cannot be evaluated at the start (the message names why).'

    character(len=*), parameter :: check = &
        'Usage: hertzdamp check ENGINE FILE... [--velocity U] [--e E] [--release R] [--format F]' // nl // &
        '       hertzdamp check ENGINE DECK... --radius R --density RHO --velocity U [options]' // nl // &
        '       hertzdamp check --table [--format F]' // nl // &
        '' // nl // &
        'What a peer DEM engine does with its Hertz contact parameters: the damping law and' // nl // &
        'formula it applies (with its source file), the restitution e and contact time t_c it' // nl // &
        'achieves at each impact speed, what its own integrator gives at the deck''s time step,' // nl // &
        'and the value of the engine''s parameter that gives the e you want.  doc/peers.md.' // nl // &
        '' // nl // &
        'FILE...: a whole deck (lammps, liggghts: input scripts with include, variables, $x,' // nl // &
        '${name}, $(expr) and & continuation; mfix: mfix.dat or .mfx; yade: a Python script),' // nl // &
        'read the way the engine reads it.  Every type pair and every type against every wall' // nl // &
        'is a row per speed; what cannot be interpreted is listed with file:line.  Columns:' // nl // &
        'pair, velocity, e_target (the deck''s restitution input, or --e), e_model (the' // nl // &
        'continuous model), e_host and e_spread (mean and standard deviation over the onset' // nl // &
        'phase with the engine''s integrator at its time step), steps_per_contact (t_c/dt),' // nl // &
        't_c, dt_verdict (ok, coarse, unresolved, unchecked), corrected (the parameter that' // nl // &
        'makes e_host equal e_target), status.  Speeds in the deck''s own units (default 1).' // nl // &
        '' // nl // &
        'DECK...: one contact in the engine''s own terms (one quoted argument or several words):' // nl // &
        '  lammps      the arguments of pair_coeff for pair_style granular, e.g.' // nl // &
        '              "hertz/material 1e8 0.5 0.3 tangential linear_nohistory 0 0 damping tsuji"' // nl // &
        '              (normal hertz kn eta_n0 | hertz/material E eta_n0 nu; damping velocity |' // nl // &
        '              mass_velocity | viscoelastic (default) | tsuji | coeff_restitution;' // nl // &
        '              limit_damping); a leading "pair_coeff I J" is skipped;' // nl // &
        '              "fix ID group wall/gran granular ... zplane lo hi" checks a flat wall;' // nl // &
        '              "gran/hertz/history Kn Kt gamma_n gamma_t xmu dampflag" the classic style' // nl // &
        '  liggghts    model=hertz|hertz/stiffness limitForce=on|off youngsModulus=Y[,Y2]' // nl // &
        '              poissonsRatio=NU[,NU2] coefficientRestitution=E (hertz) kn= gamman=' // nl // &
        '              (hertz/stiffness)' // nl // &
        '  mercurydpm  setEffectiveElasticModulusAndRestitutionCoefficient=E,e | setDissipation=g' // nl // &
        '              | setEffectiveElasticModulus=E | setDensity=RHO; species=' // nl // &
        '              HertzianViscoelasticSpecies (Beta 2015): setElasticModulus=E' // nl // &
        '              setDissipation=d | setStiffnessAndRestitutionCoefficient=E,e,mass' // nl // &
        '  yade        young=E[,E2] poisson=NU[,NU2] en=e [vn=v] | betan=b density=RHO' // nl // &
        '              (with --wall: shape=Wall|Facet|Box hertzian=True|False)' // nl // &
        '  mfix        DES_COLL_MODEL=HERTZIAN E_YOUNG=E[,E2] V_POISSON=NU[,NU2] DES_EN_INPUT=e' // nl // &
        '              (with --wall: EW_YOUNG VW_POISSON DES_EN_WALL_INPUT) D_P0= RO_S0=' // nl // &
        '              DTSOLID_FACTOR= (keys case-insensitive; KEY(1)= KEY(2)= per phase,' // nl // &
        '              DES_EN_INPUT(k) in MFiX''s pair order 1-1, 1-2, 2-2)' // nl // &
        '  chrono      SetYoungModulus=E[,E2] SetPoissonRatio=NU[,NU2] SetRestitution=e[,e2]' // nl // &
        '              | UseMaterialProperties=false SetKn=kn SetGn=gn;' // nl // &
        '              SetCollisionSystemType=BULLET|MULTICORE; wallMass=M (with --wall)' // nl // &
        '' // nl // &
        '  --radius R       particle radius [m] (body 1; DECK only)' // nl // &
        '  --radius2 R2     radius of body 2 [m] (default: R)' // nl // &
        '  --density RHO    particle density [kg m^-3] (body 1)' // nl // &
        '  --density2 RHO2  density of body 2 (default: RHO)' // nl // &
        '  --wall           body 2 is a flat wall (LIGGGHTS, Yade, MFiX, Chrono: its' // nl // &
        '                   modulus is the second value of the modulus keys)' // nl // &
        '  --velocity U     impact speeds: 0.1,1,5 or A0:A1:N or A0:A1:logN ([m/s]; a deck: its' // nl // &
        '                   own velocity unit, default 1)' // nl // &
        '  --e E            the restitution coefficient you want (default: the one in the' // nl // &
        '                   deck, where the engine takes one)' // nl // &
        '  --steps N        time steps per contact for the time-step advice (default 10; DECK)' // nl // &
        '  --release R      LAMMPS formulas of 2021 (29 Sep 2021, Debian 12), 2023' // nl // &
        '                   (28 Mar 2023 - 29 Aug 2024) or current (default); Yade 2022' // nl // &
        '                   (2020.01a - 2022.01a), 2023 (2023.02a, Debian 12) or current' // nl // &
        '                   (2024.02a and later, default)' // nl // &
        '  --format F       text (default), csv or json' // nl // &
        '  --progress       progress on stderr (default: on a terminal, after 2 s)' // nl // &
        '  --quiet          no warnings about implausible R, RHO or U (as invert --help;' // nl // &
        '                   deck files: U only, and only for a deck in SI units)' // nl // &
        '  --table          the table of every engine''s formula and the e it achieves for' // nl // &
        '                   the targets 0.1 ... 0.9 (markdown; doc/peers.md)' // nl // &
        '' // nl // &
        'DECK columns: velocity, alpha, e, e_error (e/e_target - 1), t_c [s], t_attractive' // nl // &
        '(overlap end: when the total force turns attractive) [s], dt_max = t_c/N [s], t_hertz' // nl // &
        '(elastic Hertz time) [s], t_peer (the engine''s own estimate) [s], corrected (the' // nl // &
        'engine''s parameter for the target e at this speed), method (fit: the library''s' // nl // &
        'fitted maps; rk45: the reference integrator, beyond their range), status (ok,' // nl // &
        'no-rebound, out-of-range, outside-validity, failed).  Empty (text: -): does not' // nl // &
        'apply, or beyond double precision.  Exit 0 when every row has a result; else the' // nl // &
        'table, one line on stderr and exit 3 (4: a computation failed); no row with a' // nl // &
        'result: exit 3 or 4, no output.  A deck whose contacts cannot be read: exit 2.'

contains

    !> Print the help of a command ('' for the program) on stdout and exit 0.
    subroutine print_help(command)
        character(len=*), intent(in) :: command
        select case (command)
        case ('table'); call write_stdout(expand_help(table) // nl)
        case ('forward'); call write_stdout(expand_help(forward) // nl)
        case ('constants'); call write_stdout(expand_help(constants) // nl)
        case ('invert'); call write_stdout(expand_help(invert) // nl)
        case ('timestep'); call write_stdout(expand_help(timestep) // nl)
        case ('bench'); call write_stdout(expand_help(bench) // nl)
        case ('scene'); call write_stdout(expand_help(scene) // nl)
        case ('check'); call write_stdout(expand_help(check) // nl)
        case ('calibrate'); call write_stdout(expand_help(calibrate) // nl)
        case ('oblique'); call write_stdout(expand_help(oblique) // nl)
        case ('version'); call write_stdout('hertzdamp ' // hertzdamp_version // nl)
        case default; call write_stdout(expand_help(top) // nl)
        end select
        call quit(EXIT_OK)
    end subroutine print_help

    !> True if any argument after the command is --help or -h.
    logical function wants_help()
        integer :: i, l
        character(len=7) :: a
        wants_help = .false.
        do i = 2, command_argument_count()
            call get_command_argument(i, a, length=l)
            if (l <= 6 .and. (a == '--help' .or. a == '-h')) wants_help = .true.
        end do
    end function wants_help

    !> A help text with the registry's values in place of its tokens (so that no help text
    !> lists the laws, ends, hosts or methods by hand): {laws}, {ends}, {hosts}, {methods}
    !> as prose ('a, b or c'); {laws_help}, {ends_help}, {hosts_help} each with its phrase;
    !> {laws|}, {ends|}, {hosts|} the choices joined by |; {laws'} quoted; {engine_hosts} the
    !> hosts the scene engine runs (without none); {forward_methods_help},
    !> {inverse_methods_help} the methods of each problem with their phrases.  A block (a
    !> line and the lines indented under it) that held a token is wrapped again at 80 columns
    !> with its indents; every other line is kept as it is.
    function expand_help(text) result(out)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: out, joined, first
        integer, allocatable :: a(:), b(:)
        integer :: i, j, k, n, ind0, ci, dc
        logical :: tokens
        call line_bounds(text, a, b, n)
        out = ''
        first = ''
        joined = ''
        i = 1
        do while (i <= n)
            ind0 = lead(text(a(i):b(i)))
            dc = description_column(text(a(i):b(i)))
            ci = -1
            j = i
            ! the lines indented under it, as far as they go
            do while (j < n)
                k = lead(text(a(j + 1):b(j + 1)))
                if (b(j + 1) < a(j + 1) .or. k <= ind0 .or. (ci >= 0 .and. k /= ci)) exit
                ! an option's line of its own (options sit two blanks in; text under them deeper)
                if (text(a(j + 1) + k:a(j + 1) + k) == '-' .and. k <= ind0 + 2) exit
                ci = k
                j = j + 1
            end do
            tokens = .false.
            do k = i, j
                tokens = tokens .or. index(text(a(k):b(k)), '{') > 0
            end do
            if (.not. tokens) then
                do k = i, j
                    out = out // text(a(k):b(k)) // nl
                end do
            else
                if (ci < 0) ci = merge(dc, ind0, dc > 0)
                first = text(a(i):a(i) + max(dc, ind0) - 1)
                joined = trim(adjustl(text(a(i) + max(dc, ind0):b(i))))
                do k = i + 1, j
                    ! two blanks after a full stop, as the texts have them
                    if (joined(len(joined):) == '.') joined = joined // ' '
                    joined = joined // ' ' // trim(adjustl(text(a(k):b(k))))
                end do
                first = substitute(first)
                if (j == i .and. dc > 0) ci = len(first)
                out = out // wrap(first, substitute(joined), ci)
            end if
            i = j + 1
        end do
        if (len(out) > 0) out = out(1:len(out) - 1)
    end function expand_help

    !> The bounds a(i):b(i) of the lines of a text (new_line separated; b < a: empty).
    pure subroutine line_bounds(text, a, b, n)
        character(len=*), intent(in) :: text
        integer, allocatable, intent(out) :: a(:), b(:)
        integer, intent(out) :: n
        integer :: k, m
        n = 1
        do k = 1, len(text)
            if (text(k:k) == nl) n = n + 1
        end do
        allocate (a(n), b(n))
        m = 1
        a(1) = 1
        do k = 1, len(text)
            if (text(k:k) == nl) then
                b(m) = k - 1
                m = m + 1
                a(m) = k + 1
            end if
        end do
        b(n) = len(text)
    end subroutine line_bounds

    !> Number of leading blanks of a line.
    pure integer function lead(line)
        character(len=*), intent(in) :: line
        lead = verify(line, ' ') - 1
        if (lead < 0) lead = len(line)
    end function lead

    !> Where the description of an option line starts (the column after the first run of two
    !> or more blanks past the option), 0 for a line that is not an option's.
    pure integer function description_column(line)
        character(len=*), intent(in) :: line
        integer :: k, start
        description_column = 0
        start = lead(line)
        if (start == len(line)) return
        if (line(start + 1:start + 1) /= '-') return
        k = index(line(start + 1:), '  ')
        if (k == 0) return
        k = start + k
        description_column = verify(line(k:), ' ') + k - 2
    end function description_column

    !> The text with the registry tokens replaced (see expand_help).
    function substitute(text) result(s)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: s
        s = text
        call rep(s, '{laws_help}', hertzdamp_law_listing(with_help=.true.))
        call rep(s, '{ends_help}', hertzdamp_end_listing(with_help=.true.))
        call rep(s, '{hosts_help}', hertzdamp_host_listing(with_help=.true.))
        call rep(s, '{engine_hosts}', engine_hosts())
        call rep(s, '{forward_methods_help}', hertzdamp_method_listing(with_help=.true., which='forward'))
        call rep(s, '{inverse_methods_help}', hertzdamp_method_listing(with_help=.true., which='inverse'))
        call rep(s, '{laws}', hertzdamp_law_listing())
        call rep(s, '{ends}', hertzdamp_end_listing())
        call rep(s, '{hosts}', hertzdamp_host_listing())
        call rep(s, '{methods}', hertzdamp_method_listing())
        call rep(s, '{tangentials}', hertzdamp_tangential_listing(with_help=.true.))
        call rep(s, '{levers}', hertzdamp_lever_listing(with_help=.true.))
        call rep(s, '{laws|}', piped(hertzdamp_law_choices(), ''))
        call rep(s, '{ends|}', piped(hertzdamp_end_choices(), ''))
        call rep(s, '{hosts|}', piped(hertzdamp_host_choices(), ''))
        call rep(s, '{laws''}', piped(hertzdamp_law_choices(), ''''))
        call rep(s, '{ends''}', piped(hertzdamp_end_choices(), ''''))
    end function substitute

    !> The hosts the scene engine integrates with, without none, as prose.
    function engine_hosts() result(s)
        character(len=:), allocatable :: s, c
        integer :: k, n
        c = hertzdamp_host_choices(engine_only=.true.)
        ! drop 'none ' (the first): the engine's own scheme without a host
        c = c(index(c, ' ') + 1:)
        s = ''
        n = 0
        do k = 1, len(c)
            if (c(k:k) == ' ') n = n + 1
        end do
        do k = 1, n + 1
            if (k == 1) then
                s = word(c, k)
            else if (k == n + 1) then
                s = s // ' or ' // word(c, k)
            else
                s = s // ', ' // word(c, k)
            end if
        end do
    end function engine_hosts

    !> The k-th blank-separated word of s.
    pure function word(s, k) result(w)
        character(len=*), intent(in) :: s
        integer, intent(in) :: k
        character(len=:), allocatable :: w
        integer :: a, b, m
        a = 1
        do m = 1, k - 1
            a = a + index(s(a:), ' ')
        end do
        b = index(s(a:), ' ')
        if (b == 0) then
            w = s(a:)
        else
            w = s(a:a + b - 2)
        end if
    end function word

    !> Blank-separated choices joined by |, each between q and q.
    pure function piped(choices, q) result(s)
        character(len=*), intent(in) :: choices, q
        character(len=:), allocatable :: s
        integer :: k
        s = q
        do k = 1, len(choices)
            if (choices(k:k) == ' ') then
                s = s // q // '|' // q
            else
                s = s // choices(k:k)
            end if
        end do
        s = s // q
    end function piped

    !> Replace every occurrence of key in s by val.
    subroutine rep(s, key, val)
        character(len=:), allocatable, intent(inout) :: s
        character(len=*), intent(in) :: key, val
        integer :: k
        do
            k = index(s, key)
            if (k == 0) return
            s = s(1:k - 1) // val // s(k + len(key):)
        end do
    end subroutine rep

    !> Words of text wrapped at 80 columns: the first line after `first`, the others after
    !> `indent` blanks; every line ends with a new line.
    pure function wrap(first, text, indent) result(s)
        character(len=*), intent(in) :: first, text
        integer, intent(in) :: indent
        character(len=:), allocatable :: s, cur, sep
        integer, parameter :: width = 80
        integer :: a, b, blanks
        s = ''
        sep = ''
        cur = first
        a = 1
        blanks = 0
        do while (a <= len(text))
            if (text(a:a) == ' ') then
                blanks = blanks + 1
                a = a + 1
                cycle
            end if
            b = index(text(a:), ' ')
            if (b == 0) then
                b = len(text)
            else
                b = a + b - 2
            end if
            sep = repeat(' ', min(blanks, 2))
            if (len(cur) > max(len(first), indent) .and. len(cur) + len(sep) + (b - a + 1) > width) then
                s = s // cur // nl
                cur = repeat(' ', indent)
                sep = ''
            end if
            if (len(cur) == 0 .or. cur(len(cur):len(cur)) == ' ') sep = ''
            cur = cur // sep // text(a:b)
            blanks = 0
            a = b + 1
        end do
        s = s // cur // nl
    end function wrap

end module hertzdamp_cli_help
