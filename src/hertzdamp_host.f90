!> What a DEM host's own time integrator makes of the damped Hertz contact, and the
!> per-pair constants that make the host's phase-averaged e and T_c exact
!> (doc/host-schemes.md).
!>
!> A host integrates  z'' = a(z, z'),  a = -(alpha z^q z' + z^(3/2))  (z > 0, else 0;
!> force end: a = -max(0, alpha z^q z' + z^(3/2))) with a step h = dt / t* in the
!> similarity variables of doc/theory.md.  Its discrete collision depends only on alpha,
!> h, the law q, the contact end, the scheme and the onset phase phi in (0, 1]: the
!> first step with overlap has z_1 = phi h (approach speed 1), i.e. the touch happened
!> (1 - phi) h after the step before it.  The schemes (HD_HOST_*, doc/host-schemes.md
!> with the engine sources they were read from):
!> - `lammps`, `mfix-euler` (also LIGGGHTS, MercuryDPM, Yade, Chrono's default): the
!>   force from the position and the velocity that moved the body there, then
!>   w_(n+1) = w_n + h a(z_n, w_n), z_(n+1) = z_n + h w_(n+1) (velocity Verlet with the
!>   half-step velocity in the damping = MFiX's EULER = symplectic Euler);
!> - `mfix-ab2`: v_(n+1) = v_n + h (3 a_n - a_(n-1))/2, z_(n+1) = z_n + h (v_n + v_(n+1))/2,
!>   a_(n-1) = 0 before the contact, the last contact acceleration acting once more
!>   after the release;
!> - `verlet`: the scene engine of this repository (packages/dem/src/hertzdamp_dem_engine.f90):
!>   velocity Verlet with the extrapolated velocity in the damping and its onset and
!>   release impulse corrections;
!> - `lammps-phase`: `lammps` with the onset/release correction of the LAMMPS plugin
!>   (`phase yes`), hertzdamp_host_phase_force.
!>
!> Achieved e: the free-flight separation speed (units of the impact speed) once no
!> force acts.  Achieved tau_c: from the exact touch to the release; the overlap end
!> is interpolated linearly in the overlap between the last step with overlap and the
!> first without, the force end linearly in the unclipped total force between the last
!> step with a positive force and the first clipped one (the overlap end when the
!> overlap is gone first); `verlet` keeps the engine's own end instants.
!>
!> Phase statistics: e(phi) and tau_c(phi) are smooth between breakpoints where the
!> release (or the clip) moves to another step, with algebraic endpoint singularities
!> (powers phi^q, phi^(3/2) of a tiny first or last overlap).  The breakpoints are found
!> to round-off (the bracket moved by the discrete trajectory's signature: release step,
!> kind, number of force steps; its points by the Illinois method on the overlap or force
!> at the release step, else bisection) and each piece is integrated by tanh-sinh quadrature, which
!> converges double-exponentially despite endpoint singularities.  The collisions of a
!> quadrature level, of the coarse samples and of the proxy run four side by side
!> (run_many; hertzdamp_host_collide_phases), each to the bit as alone.
!>
!> Everything is pure, keeps no state and returns a status (hertzdamp_status).
module hertzdamp_host
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: HD_OK, HD_NO_REBOUND, HD_NO_CONVERGENCE, HD_BAD_ALPHA, HD_BAD_END, HD_BAD_ARGUMENT, &
                                HD_BAD_HOST, HD_BAD_STEPS, HD_HOST_UNREACHABLE
    use hertzdamp_registry, only: HD_END_OVERLAP, HD_END_FORCE, HD_HOST_NONE, HD_HOST_MFIX_AB2, HD_HOST_VERLET, &
                                  HD_HOST_LAMMPS_PHASE, hertzdamp_min_host, hertzdamp_max_host, hertzdamp_host_name, &
                                  hertzdamp_host_order
    use hertzdamp_constants, only: hertzdamp_pi
    use hertzdamp_registry, only: hertzdamp_law_q, HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO
    use hertzdamp_laws, only: hertzdamp_law_status
    use hertzdamp_fit, only: hertzdamp_fit_inverse
    use hertzdamp_rk45, only: hertzdamp_rk45_collide, hertzdamp_collision
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    ! The host codes, names and attributes (the order of their error, whether the scene
    ! engine runs them) are rows of data/registry.toml: hertzdamp_registry has them (and the
    ! umbrella exports them); the schemes' steppers below are dispatched by code.

    !> Smallest and largest number of steps per contact of hertzdamp_host_solve.
    real(wp), parameter, public :: hertzdamp_host_steps_min = 2.0_wp, hertzdamp_host_steps_max = 1.0e5_wp
    !> Smallest and largest dimensionless step h = dt / t* of the discrete collision.
    real(wp), parameter, public :: hertzdamp_host_h_min = 1.0e-5_wp, hertzdamp_host_h_max = 4.0_wp
    !> Largest damping parameter alpha of the discrete collision.
    real(wp), parameter, public :: hertzdamp_host_alpha_max = 1.0e4_wp

    !> Phase statistics of a host's discrete collision (dimensionless; sd = standard
    !> deviation over the onset phase phi uniform on (0, 1]; min and max over phi).
    type, public :: hertzdamp_host_stats
        real(wp) :: e_mean = 0.0_wp    !! mean restitution coefficient
        real(wp) :: e_sd = 0.0_wp      !! its standard deviation over the phase
        real(wp) :: e_min = 0.0_wp     !! smallest e over the phase
        real(wp) :: e_max = 0.0_wp     !! largest e over the phase
        real(wp) :: tau_mean = 0.0_wp  !! mean contact duration (units of t*)
        real(wp) :: tau_sd = 0.0_wp    !! its standard deviation over the phase
        real(wp) :: tau_min = 0.0_wp   !! shortest contact over the phase
        real(wp) :: tau_max = 0.0_wp   !! longest contact over the phase
    end type hertzdamp_host_stats

    public :: hertzdamp_host_status
    public :: hertzdamp_host_collide, hertzdamp_host_collide_phases, hertzdamp_host_mean, hertzdamp_host_solve
    public :: hertzdamp_host_min_steps
    public :: hertzdamp_host_alpha_for_e, hertzdamp_host_phase_force, hertzdamp_host_hurwitz

    !> One discrete collision: e, tau_c, its signature (release step, kind of release:
    !> 0 overlap, 1 force clip, 2 verlet's force zero past the overlap zero; number of
    !> steps with a contact force) and a status.
    type :: run_t
        real(wp) :: e = 0.0_wp
        real(wp) :: tau = 0.0_wp
        integer :: sig(3) = 0
        integer :: status = HD_OK
        !> the overlap and the (unclipped) force at the probe step asked for (huge: not reached)
        real(wp) :: gz = huge(1.0_wp), gf = huge(1.0_wp)
    end type run_t

    !> A piece (a, b) of the phase interval on which the collision has one signature;
    !> pref is a phase inside it with that signature.
    type :: piece_t
        real(wp) :: a = 0.0_wp, b = 1.0_wp, pref = 1.0_wp
        integer :: sig(3) = 0
    end type piece_t

    !> The state of the verlet scheme's collision between steps (run_verlet).
    type :: verlet_t
        real(wp) :: z = 0.0_wp, v = 0.0_wp, acc = 0.0_wp, acc_prev = 0.0_wp
        real(wp) :: zl = 0.0_wp, vl = 0.0_wp, fl = 0.0_wp, s = 0.0_wp
    end type verlet_t

    !> The collision whose phase statistics are computed.
    type :: ctx_t
        real(wp) :: alpha = 0.0_wp, h = 0.0_wp
        integer :: law = 0, iend = 0, host = 0
    end type ctx_t

    !> Phases of the stratified proxy of the phase means that the bracketing solve searches
    !> with (the midpoint rule: an error of about the jumps of e(phi) over n_proxy, 1e-3 of e
    !> in the regular cases; the solution is then polished with the exact means).
    integer, parameter :: n_proxy = 64
    !> Collisions that run_many advances side by side.
    integer, parameter :: lanes = 4
    !> Relative tolerance of the bracketing solve on the proxy means (its result is polished).
    real(wp), parameter :: proxy_tol = 1.0e-9_wp

    !> Running sums of the phase quadrature (integrals over the pieces done so far).
    type :: sums_t
        real(wp) :: ie = 0.0_wp, it = 0.0_wp, ie2 = 0.0_wp, it2 = 0.0_wp
        real(wp) :: e_ref = 0.0_wp, t_ref = 0.0_wp
        real(wp) :: e_min = huge(1.0_wp), e_max = -huge(1.0_wp), t_min = huge(1.0_wp), t_max = -huge(1.0_wp)
        integer :: runs = 0
    end type sums_t

    !> Longest discrete contact followed, in units of t* (beyond it: no rebound; the
    !> longest continuous contact of the fitted range is 50, kuwabara-kono at e = 1e-4).
    real(wp), parameter :: contact_time_max = 5.0e2_wp
    !> Coarse phase samples before the breakpoint search, and the most pieces.
    integer, parameter :: n_coarse = 8, max_pieces = 256
    !> Most discrete collisions run for one set of phase statistics (beyond it:
    !> HD_NO_CONVERGENCE; a regular case takes 200 to 500, the chaotic releases of
    !> alpha near alpha_c at two steps per contact 30000).
    integer, parameter :: max_runs = 200000
    !> The tanh-sinh quadrature takes abscissae t in [-t_max, t_max] (the weight beyond is below 1e-16 of the
    !> piece), levels of step 2^-l, l = 0 .. level_max; a level l >= level_min whose
    !> change from level l - 1 is below quad_tol (relative to the piece) ends the
    !> refinement: the error then falls like the square of that change (measured below
    !> 1e-14 of e and tau_c, test/unit/test_host.f90 checks the means against its own quadrature).
    real(wp), parameter :: ts_t_max = 3.2_wp
    integer, parameter :: level_min = 2, level_max = 7
    real(wp), parameter :: quad_tol = 1.0e-10_wp
    !> Relative tolerance of the solves (the means they match), and the most phase
    !> statistics Newton computes before the bracketing solve takes over (a regular solve
    !> takes 6 to 12).
    real(wp), parameter :: solve_tol = 2.0e-12_wp
    integer, parameter :: max_means = 60
    !> The budget of Newton's polish of the bracketing solve's result on the exact means.
    integer, parameter :: polish_means = 20
    !> The most steps per contact at which first_solves tries cliff_solve.
    real(wp), parameter :: cliff_steps_max = 3.0_wp
    !> A discrete collision with e above this gains energy: the step is unstable for the
    !> damping (the per-pair solve's bracketing does not follow such collisions).
    real(wp), parameter :: unstable_e = 1.5_wp
    !> The steps beyond N_min at which hertzdamp_host_min_steps also requires success.
    integer, parameter :: min_steps_window = 3
    !> Largest N that hertzdamp_host_min_steps tries.
    integer, parameter :: n_search_max = 1024
    !> The N up to which hertzdamp_host_min_steps keeps its solves (its window and the
    !> continuation's N + 1 beyond n_search_max included).
    integer, parameter :: n_cache = n_search_max + min_steps_window + 4

    !> hertzdamp_host_min_steps's record of the solves by N (status -1: not done yet): the
    !> status of first_solves and its solution, and the status of hertzdamp_host_solve.
    type :: steps_cache_t
        integer :: first_st(n_cache) = -1, solve_st(n_cache) = -1
        real(wp) :: first_x(2, n_cache) = 0.0_wp
    end type steps_cache_t

contains

    ! ================================================================ names and checks

    !> HD_OK for a valid host code, else HD_BAD_HOST.
    pure elemental integer function hertzdamp_host_status(host) result(status)
        integer, intent(in) :: host   !! HD_HOST_*
        status = HD_OK
        if (host < hertzdamp_min_host .or. host > hertzdamp_max_host) status = HD_BAD_HOST
    end function hertzdamp_host_status

    !> Status of the common arguments: host, law, contact end (in this order).
    pure integer function check_common(law, iend, host) result(status)
        integer, intent(in) :: law, iend, host
        status = hertzdamp_host_status(host)
        if (status == HD_OK) status = hertzdamp_law_status(law)
        if (status == HD_OK .and. iend /= HD_END_OVERLAP .and. iend /= HD_END_FORCE) status = HD_BAD_END
    end function check_common

    !> HD_OK for a damping parameter of the discrete collision (finite, 0 <= alpha <= alpha_max).
    pure integer function check_alpha(alpha) result(status)
        real(wp), intent(in) :: alpha
        status = HD_OK
        if (.not. (alpha >= 0.0_wp .and. alpha <= hertzdamp_host_alpha_max)) status = HD_BAD_ALPHA
    end function check_alpha

    !> HD_OK for a dimensionless step (finite, h_min <= h <= h_max), else HD_BAD_STEPS.
    pure integer function check_h(h) result(status)
        real(wp), intent(in) :: h
        status = HD_OK
        if (.not. (h >= hertzdamp_host_h_min .and. h <= hertzdamp_host_h_max)) status = HD_BAD_STEPS
    end function check_h

    ! ================================================================ the onset/release correction

    !> Hurwitz zeta function zeta(-p, a) = sum_(j >= 0) (a + j)^p (analytically continued)
    !> for p = 1/4, 1/2, 3/2 (by square roots) or any other 0 < p < 2 (by powers) and
    !> 0 <= a <= 1: eight terms, then the Euler-Maclaurin tail with six Bernoulli terms
    !> at a + 8 (truncation below 5e-15; the terms cancel against the tail, so the absolute
    !> error is below 1e-14 for p <= 1/2 and 1e-13 for p = 3/2, test/unit/test_host.f90).
    !> zeta(-p, 0) = zeta(-p, 1) = zeta(-p), Riemann's.
    !> zeta(0, a) = 1/2 - a.  0 for an a outside [0, 1] or a p outside (0, 2).
    pure elemental real(wp) function hertzdamp_host_hurwitz(p, a) result(z)
        real(wp), intent(in) :: p   !! exponent, 0 < p < 2
        real(wp), intent(in) :: a   !! shift, 0 <= a <= 1
        ! B_(2k) / (2k)!, k = 1 .. 6
        real(wp), parameter :: b2k(6) = [1.0_wp / 12.0_wp, -1.0_wp / 720.0_wp, 1.0_wp / 30240.0_wp, &
                                          -1.0_wp / 1209600.0_wp, 1.0_wp / 47900160.0_wp, &
                                          -691.0_wp / 1307674368000.0_wp]
        real(wp) :: x, xp, term, coef
        integer :: j, k
        z = 0.0_wp
        if (.not. (a >= 0.0_wp .and. a <= 1.0_wp .and. p > 0.0_wp .and. p < 2.0_wp)) return
        do j = 0, 7
            z = z + pow_p(a + real(j, wp))
        end do
        x = a + 8.0_wp
        xp = pow_p(x)
        z = z - x * xp / (p + 1.0_wp) + 0.5_wp * xp
        ! B_2k/(2k)! (-p)(1-p)...(2k-2-p) x^(p-2k+1)
        coef = -p
        term = xp / x
        do k = 1, 6
            z = z + b2k(k) * coef * term
            coef = coef * (real(2 * k - 1, wp) - p) * (real(2 * k, wp) - p)
            term = term / (x * x)
        end do
    contains
        pure real(wp) function pow_p(y)
            real(wp), intent(in) :: y
            if (p == 0.25_wp) then
                pow_p = sqrt(sqrt(y))
            else if (p == 0.5_wp) then
                pow_p = sqrt(y)
            else if (p == 1.5_wp) then
                pow_p = y * sqrt(y)
            else
                pow_p = y**p
            end if
        end function pow_p
    end function hertzdamp_host_hurwitz

    !> The onset/release phase correction of HD_HOST_LAMMPS_PHASE (LAMMPS plugin `phase
    !> yes`), a force to add (repulsive > 0) at the step that detects a contact's onset and,
    !> overlap end only, at the step that detects its end (doc/host-schemes.md):
    !>     f = -d zeta' |zeta' dt|^q zeta_H(-q, frac),
    !> zeta_H the Hurwitz zeta function.  The host applies the force of a step as an
    !> impulse over a cell of one step centred on it; for a damping force d zeta^q zeta'
    !> that starts (or ends) a fraction of a step away, the cells' impulse exceeds the true
    !> one by d |zeta'|^(1+q) dt^(1+q) zeta_H(-q, frac) (Euler-Maclaurin), which f removes.
    !> Linear law (q = 0): zeta_H(0, frac) = 1/2 - frac, f = d zeta' (frac - 1/2) exactly as
    !> the plugin computes it (the damping force jumps by d zeta' there); q > 0 (no jump, the
    !> force rises like s^q) the error is of order dt^(1+q) and the Hurwitz factor replaces
    !> 1/2 - frac.  Onset: zeta' = approach speed (> 0), frac = fraction of the detecting
    !> step already in contact; end: zeta' = overlap rate (< 0), frac = fraction of the last
    !> step still in contact.  frac is clamped to [0, 1] (NaN: 0); an invalid law gives 0.
    pure elemental real(wp) function hertzdamp_host_phase_force(d, zeta_dot, dt, frac, law) result(f)
        real(wp), intent(in) :: d          !! damping coefficient of the law (force d zeta^q zeta')
        real(wp), intent(in) :: zeta_dot   !! overlap rate zeta' at that step (approach > 0)
        real(wp), intent(in) :: dt         !! time step
        real(wp), intent(in) :: frac       !! fraction of the step in contact, in [0, 1]
        integer, intent(in) :: law         !! HD_DAMPING_*
        real(wp) :: fr, x
        fr = frac
        if (.not. (fr > 0.0_wp)) fr = 0.0_wp
        if (fr > 1.0_wp) fr = 1.0_wp
        x = abs(zeta_dot) * dt
        select case (law)
        case (HD_DAMPING_LINEAR)
            f = d * zeta_dot * (fr - 0.5_wp)
        case (HD_DAMPING_TSUJI)
            f = -(d * zeta_dot) * sqrt(sqrt(x)) * hertzdamp_host_hurwitz(0.25_wp, fr)
        case (HD_DAMPING_KUWABARA_KONO)
            f = -(d * zeta_dot) * sqrt(x) * hertzdamp_host_hurwitz(0.5_wp, fr)
        case default
            f = 0.0_wp
        end select
    end function hertzdamp_host_phase_force

    ! ================================================================ one discrete collision

    !> One discrete collision of a host: the achieved restitution e and contact duration
    !> tau_c (units of t*) for the onset phase phi (module header).  host = HD_HOST_NONE:
    !> the continuous model (reference integrator; h and phi are checked, not used).  Status HD_OK,
    !> HD_NO_REBOUND (the discrete overlap does not return within 2000 t*, or the bodies do
    !> not separate), or for a bad argument (checked in this order) HD_BAD_HOST, HD_BAD_LAW,
    !> HD_BAD_END, HD_BAD_ALPHA (not 0 <= alpha <= 1e4), HD_BAD_STEPS (h not in
    !> [1e-5, 4]), HD_BAD_ARGUMENT (phi not in (0, 1]); e = tau_c = 0 on failure.
    pure elemental subroutine hertzdamp_host_collide(alpha, h, phi, law, iend, host, e, tau_c, status)
        real(wp), intent(in) :: alpha    !! damping parameter
        real(wp), intent(in) :: h        !! dimensionless step dt / t*
        real(wp), intent(in) :: phi      !! onset phase in (0, 1]: the first overlap is phi h
        integer, intent(in) :: law       !! HD_DAMPING_*
        integer, intent(in) :: iend      !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: host      !! HD_HOST_*
        real(wp), intent(out) :: e       !! achieved restitution coefficient
        real(wp), intent(out) :: tau_c   !! achieved contact duration (units of t*)
        integer, intent(out) :: status   !! HD_OK or the failure
        type(run_t) :: r
        e = 0.0_wp
        tau_c = 0.0_wp
        status = check_common(law, iend, host)
        if (status == HD_OK) status = check_alpha(alpha)
        if (status == HD_OK) status = check_h(h)
        if (status == HD_OK .and. .not. (phi > 0.0_wp .and. phi <= 1.0_wp)) status = HD_BAD_ARGUMENT
        if (status /= HD_OK) return
        if (host == HD_HOST_NONE) then
            call continuous(alpha, law, iend, e, tau_c, status)
            return
        end if
        call run(alpha, h, phi, law, iend, host, r)
        status = r%status
        if (status == HD_OK) then
            e = r%e
            tau_c = r%tau
        end if
    end subroutine hertzdamp_host_collide

    !> hertzdamp_host_collide at each onset phase phi(j) of one collision's alpha, h, law,
    !> end and host, the collisions side by side as the phase statistics run them:
    !> e(j), tau_c(j), status(j) equal hertzdamp_host_collide's at phi(j) to the bit (the
    !> same operations in the same order).  A bad common argument gives its status at every
    !> phase; a phi(j) outside (0, 1] HD_BAD_ARGUMENT there.  e, tau_c, status: at least
    !> size(phi) long (else HD_BAD_ARGUMENT at every phase of status, nothing else written).
    pure subroutine hertzdamp_host_collide_phases(alpha, h, phi, law, iend, host, e, tau_c, status)
        real(wp), intent(in) :: alpha       !! damping parameter
        real(wp), intent(in) :: h           !! dimensionless step dt / t*
        real(wp), intent(in) :: phi(:)      !! onset phases, each in (0, 1]
        integer, intent(in) :: law          !! HD_DAMPING_*
        integer, intent(in) :: iend         !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: host         !! HD_HOST_*
        real(wp), intent(inout) :: e(:)     !! achieved restitution coefficients
        real(wp), intent(inout) :: tau_c(:) !! achieved contact durations (units of t*)
        integer, intent(inout) :: status(:) !! HD_OK or the failure, per phase
        type(run_t) :: rs(size(phi))
        real(wp) :: ok_phi(size(phi))
        integer :: idx(size(phi)), st, j, n, k, nd
        if (size(e) < size(phi) .or. size(tau_c) < size(phi) .or. size(status) < size(phi)) then
            status = HD_BAD_ARGUMENT
            return
        end if
        e(1:size(phi)) = 0.0_wp
        tau_c(1:size(phi)) = 0.0_wp
        st = check_common(law, iend, host)
        if (st == HD_OK) st = check_alpha(alpha)
        if (st == HD_OK) st = check_h(h)
        if (st /= HD_OK .or. host == HD_HOST_NONE) then
            do j = 1, size(phi)
                call hertzdamp_host_collide(alpha, h, phi(j), law, iend, host, e(j), tau_c(j), status(j))
            end do
            return
        end if
        ! the valid phases side by side; after a failed one, on from the next
        n = 0
        do j = 1, size(phi)
            status(j) = HD_BAD_ARGUMENT
            if (phi(j) > 0.0_wp .and. phi(j) <= 1.0_wp) then
                n = n + 1
                ok_phi(n) = phi(j)
                idx(n) = j
            end if
        end do
        k = 1
        do while (k <= n)
            call run_many(alpha, h, ok_phi(k:n), law, iend, host, rs(k:n), ndone=nd)
            k = k + nd
        end do
        do j = 1, n
            status(idx(j)) = rs(j)%status
            e(idx(j)) = rs(j)%e
            tau_c(idx(j)) = rs(j)%tau
        end do
    end subroutine hertzdamp_host_collide_phases

    !> The continuous collision (reference integrator at its default tolerance).
    pure subroutine continuous(alpha, law, iend, e, tau_c, status)
        real(wp), intent(in) :: alpha
        integer, intent(in) :: law, iend
        real(wp), intent(out) :: e, tau_c
        integer, intent(out) :: status
        type(hertzdamp_collision) :: c
        c = hertzdamp_rk45_collide(alpha, iend, law=law)
        status = c%status
        e = 0.0_wp
        tau_c = 0.0_wp
        if (status == HD_OK) then
            e = c%e
            tau_c = c%tau_c
        end if
    end subroutine continuous

    !> The discrete collision of a host (arguments checked by the caller).
    !> probe: a step whose overlap and force are kept in r%gz, r%gf (breakpoint).
    pure subroutine run(alpha, h, phi, law, iend, host, r, probe)
        real(wp), intent(in) :: alpha, h, phi
        integer, intent(in) :: law, iend, host
        type(run_t), intent(out) :: r
        integer, intent(in), optional :: probe
        integer :: nmax, m
        nmax = int(contact_time_max / h) + 16
        m = 0
        if (present(probe)) m = probe
        select case (host)
        case (HD_HOST_MFIX_AB2)
            call run_ab2(alpha, h, phi, law, iend, nmax, m, r)
        case (HD_HOST_VERLET)
            call run_verlet(alpha, h, phi, law, iend, nmax, m, r)
        case default
            call run_symplectic(alpha, h, phi, law, iend, host == HD_HOST_LAMMPS_PHASE, nmax, m, r)
        end select
        if (r%status == HD_OK .and. .not. (r%e > 0.0_wp)) r%status = HD_NO_REBOUND
        if (r%status /= HD_OK) then
            r%e = 0.0_wp
            r%tau = 0.0_wp
        end if
    end subroutine run

    !> The discrete collisions of a host at the phases phi(:) (arguments checked by the
    !> caller): r(j) exactly as run(alpha, h, phi(j), ..) gives it, up to the first failed
    !> one (those after it: status HD_NO_CONVERGENCE, not run).  The collisions advance side
    !> by side in groups of `lanes` (run_symplectic_lanes, run_ab2_lanes, run_verlet_lanes):
    !> a collision is a chain of dependent square roots and products, and independent
    !> chains side by side keep the processor busy.
    pure subroutine run_many(alpha, h, phi, law, iend, host, r, probe, ndone)
        real(wp), intent(in) :: alpha, h, phi(:)
        integer, intent(in) :: law, iend, host
        type(run_t), intent(out) :: r(:)
        integer, intent(in), optional :: probe
        integer, intent(out), optional :: ndone   !! the phases run (size(phi) unless one failed)
        integer :: i, j, j2, m
        m = 0
        if (present(probe)) m = probe
        if (present(ndone)) ndone = size(phi)
        do j = 1, size(phi), lanes
            j2 = min(j + lanes - 1, size(phi))
            if (host == HD_HOST_MFIX_AB2) then
                call run_ab2_lanes(alpha, h, phi(j:j2), law, iend, int(contact_time_max / h) + 16, m, r(j:j2))
            else if (host == HD_HOST_VERLET) then
                call run_verlet_lanes(alpha, h, phi(j:j2), law, iend, int(contact_time_max / h) + 16, m, r(j:j2))
            else
                call run_symplectic_lanes(alpha, h, phi(j:j2), law, iend, host == HD_HOST_LAMMPS_PHASE, &
                                          int(contact_time_max / h) + 16, m, r(j:j2))
            end if
            do i = j, j2
                if (r(i)%status == HD_OK .and. .not. (r(i)%e > 0.0_wp)) r(i)%status = HD_NO_REBOUND
                if (r(i)%status /= HD_OK) then
                    r(i)%e = 0.0_wp
                    r(i)%tau = 0.0_wp
                end if
            end do
            ! a failed collision ends the callers' use of the phases after it: those are
            ! not run (a collision without rebound runs to its longest contact)
            if (any(r(j:j2)%status /= HD_OK)) then
                r(j2 + 1:)%status = HD_NO_CONVERGENCE
                if (present(ndone)) ndone = j2
                return
            end if
        end do
    end subroutine run_many

    !> z^q of the law by square roots (1 for the linear law), z >= 0.
    pure real(wp) function zq(z, law)
        real(wp), intent(in) :: z
        integer, intent(in) :: law
        select case (law)
        case (HD_DAMPING_TSUJI)
            zq = sqrt(sqrt(z))
        case (HD_DAMPING_KUWABARA_KONO)
            zq = sqrt(z)
        case default
            zq = 1.0_wp
        end select
    end function zq

    !> Fill the result of a collision released at step n (kind, fraction frac of the step
    !> before the release) with separation velocity -w and nf force steps.
    pure subroutine finish_run(h, phi, n, kind, frac, w, nf, r)
        real(wp), intent(in) :: h, phi, frac, w
        integer, intent(in) :: n, kind, nf
        type(run_t), intent(inout) :: r
        r%e = -w
        ! release at t_(n-1) + frac h, touch at t_1 - phi h (t_k = k h)
        r%tau = h * (real(n - 2, wp) + frac + phi)
        r%sig = [n, kind, nf]
    end subroutine finish_run

    !> The lammps, mfix-euler and lammps-phase schemes: at step n the force from z_n and the velocity
    !> w_n that moved the body there, then w_(n+1) = w_n - h F_n, z_(n+1) = z_n + h w_(n+1).
    !> phase: the plugin's correction at the onset step and at the step detecting the
    !> overlap end (hertzdamp_host_phase_force).
    pure subroutine run_symplectic(alpha, h, phi, law, iend, phase, nmax, m, r)
        real(wp), intent(in) :: alpha, h, phi
        integer, intent(in) :: law, iend, nmax, m
        logical, intent(in) :: phase
        type(run_t), intent(inout) :: r
        type(run_t) :: rs(1)
        rs(1) = r
        call run_symplectic_lanes(alpha, h, [phi], law, iend, phase, nmax, m, rs)
        r = rs(1)
    end subroutine run_symplectic

    !> The lammps family's scheme (run_symplectic) for up to `lanes` phases side by side
    !> (run_many): each phase's operations those of a collision alone, in the same order.
    pure subroutine run_symplectic_lanes(alpha, h, phi, law, iend, phase, nmax, m, r)
        real(wp), intent(in) :: alpha, h, phi(:)
        integer, intent(in) :: law, iend, nmax, m
        logical, intent(in) :: phase
        type(run_t), intent(inout) :: r(:)
        real(wp) :: z(lanes), w(lanes), zp(lanes), fp(lanes), f, fa, frac
        logical :: live(lanes)
        integer :: n, j, nl, left
        nl = size(phi)
        z(1:nl) = phi * h
        w = 1.0_wp
        zp = 0.0_wp
        fp = 0.0_wp
        live = .false.
        live(1:nl) = .true.
        left = nl
        do n = 1, nmax
            do j = 1, nl
                if (.not. live(j)) cycle
                if (n == m) r(j)%gz = z(j)
                if (n > 1 .and. .not. (z(j) > 0.0_wp)) then
                    ! overlap gone at step n: no force; the plugin's release correction
                    frac = zp(j) / (zp(j) - z(j))
                    if (phase .and. iend == HD_END_OVERLAP) w(j) = w(j) - h * &
                        hertzdamp_host_phase_force(alpha, w(j), h, frac, law)
                    call finish_run(h, phi(j), n, 0, frac, w(j), n - 1, r(j))
                    live(j) = .false.
                    left = left - 1
                    cycle
                end if
                f = z(j) * sqrt(z(j)) + alpha * zq(z(j), law) * w(j)
                if (n == m) r(j)%gf = f
                if (iend == HD_END_FORCE .and. .not. (f > 0.0_wp)) then
                    ! force end (n > 1: the first force is positive): clipped from here on
                    call finish_run(h, phi(j), n, 1, fp(j) / (fp(j) - f), w(j), n - 1, r(j))
                    live(j) = .false.
                    left = left - 1
                    cycle
                end if
                fa = f
                if (phase .and. n == 1) fa = f + hertzdamp_host_phase_force(alpha, w(j), h, phi(j), law)
                w(j) = w(j) - h * fa
                zp(j) = z(j)
                fp(j) = f
                z(j) = z(j) + h * w(j)
            end do
            if (left == 0) return
        end do
        do j = 1, nl
            if (live(j)) r(j)%status = HD_NO_REBOUND
        end do
    end subroutine run_symplectic_lanes

    !> The mfix-ab2 scheme: a_n from (z_n, v_n) (clipped at the force end), v_(n+1) = v_n +
    !> h (3 a_n - a_(n-1))/2, z_(n+1) = z_n + h (v_n + v_(n+1))/2; a_0 = 0 (free flight
    !> before the contact).  The release is the first step without overlap (or with a
    !> clipped force); the free-flight speed is final once a_n = a_(n-1) = 0.  An overlap
    !> that comes back after it was gone (no separation): HD_NO_REBOUND.
    pure subroutine run_ab2(alpha, h, phi, law, iend, nmax, m, r)
        real(wp), intent(in) :: alpha, h, phi
        integer, intent(in) :: law, iend, nmax, m
        type(run_t), intent(inout) :: r
        type(run_t) :: rs(1)
        rs(1) = r
        call run_ab2_lanes(alpha, h, [phi], law, iend, nmax, m, rs)
        r = rs(1)
    end subroutine run_ab2

    !> The mfix-ab2 scheme (run_ab2) for up to `lanes` phases side by side (run_many): each
    !> phase's operations those of a collision alone, in the same order.
    pure subroutine run_ab2_lanes(alpha, h, phi, law, iend, nmax, m, r)
        real(wp), intent(in) :: alpha, h, phi(:)
        integer, intent(in) :: law, iend, nmax, m
        type(run_t), intent(inout) :: r(:)
        real(wp), dimension(lanes) :: z, v, aold, zp, fp, f, frac
        real(wp) :: vn, a, fa
        integer, dimension(lanes) :: nrel, kind, nf
        logical, dimension(lanes) :: released, gone, live
        integer :: n, j, nl, left
        nl = size(phi)
        z(1:nl) = phi * h
        v = 1.0_wp
        aold = 0.0_wp
        zp = 0.0_wp
        fp = 0.0_wp
        f = 0.0_wp
        frac = 0.0_wp
        nrel = 0
        kind = 0
        nf = 0
        released = .false.
        gone = .false.
        live = .false.
        live(1:nl) = .true.
        left = nl
        do n = 1, nmax
            do j = 1, nl
                if (.not. live(j)) cycle
                if (n == m) r(j)%gz = z(j)
                if (z(j) > 0.0_wp) then
                    if (gone(j)) then
                        r(j)%status = HD_NO_REBOUND
                        live(j) = .false.
                        left = left - 1
                        cycle
                    end if
                    f(j) = z(j) * sqrt(z(j)) + alpha * zq(z(j), law) * v(j)
                    if (n == m) r(j)%gf = f(j)
                    fa = f(j)
                    if (iend == HD_END_FORCE) fa = max(f(j), 0.0_wp)
                    if (.not. released(j) .and. iend == HD_END_FORCE .and. .not. (f(j) > 0.0_wp)) then
                        released(j) = .true.
                        nrel(j) = n
                        kind(j) = 1
                        frac(j) = fp(j) / (fp(j) - f(j))
                    end if
                else
                    fa = 0.0_wp
                    gone(j) = .true.
                    if (.not. released(j)) then
                        released(j) = .true.
                        nrel(j) = n
                        kind(j) = 0
                        frac(j) = zp(j) / (zp(j) - z(j))
                    end if
                end if
                if (.not. released(j)) then
                    zp(j) = z(j)
                    fp(j) = f(j)
                end if
                a = -fa
                if (fa /= 0.0_wp) nf(j) = nf(j) + 1
                if (released(j) .and. a == 0.0_wp .and. aold(j) == 0.0_wp) then
                    call finish_run(h, phi(j), nrel(j), kind(j), frac(j), v(j), nf(j), r(j))
                    live(j) = .false.
                    left = left - 1
                    cycle
                end if
                vn = v(j) + 0.5_wp * h * (3.0_wp * a - aold(j))
                z(j) = z(j) + 0.5_wp * h * (v(j) + vn)
                v(j) = vn
                aold(j) = a
            end do
            if (left == 0) return
        end do
        do j = 1, nl
            if (live(j)) r(j)%status = HD_NO_REBOUND
        end do
    end subroutine run_ab2_lanes

    !> The verlet scheme, the scene engine's sequence for one contact (packages/dem/src/hertzdamp_dem_engine.f90,
    !> doc/host-schemes.md): half kick, drift, the velocity v_pred = v_half + h/2 A +
    !> h/2 (A - A_prev) in the damping, the force, the closing half kick plus the impulse
    !> corrections of the onset step (the part of the step in contact, the Hertz and
    !> damping trapezoid errors g_p), of the overlap end (same, with the last force) and of
    !> the force end (the force zero on a model of its step).  The engine's end instants.
    pure subroutine run_verlet(alpha, h, phi, law, iend, nmax, m, r)
        real(wp), intent(in) :: alpha, h, phi
        integer, intent(in) :: law, iend, nmax, m
        type(run_t), intent(inout) :: r
        type(run_t) :: rs(1)
        rs(1) = r
        call run_verlet_lanes(alpha, h, [phi], law, iend, nmax, m, rs)
        r = rs(1)
    end subroutine run_verlet

    !> The verlet scheme (run_verlet) for up to `lanes` phases side by side (run_many): each
    !> phase's steps (verlet_onset, verlet_step) those of a collision alone.
    pure subroutine run_verlet_lanes(alpha, h, phi, law, iend, nmax, m, r)
        real(wp), intent(in) :: alpha, h, phi(:)
        integer, intent(in) :: law, iend, nmax, m
        type(run_t), intent(inout) :: r(:)
        type(verlet_t) :: st(lanes)
        real(wp) :: q
        integer :: n, j, nl, left
        logical :: live(lanes), done
        nl = size(phi)
        q = hertzdamp_law_q(law)
        do j = 1, nl
            call verlet_onset(alpha, h, phi(j), law, q, st(j))
        end do
        live = .false.
        live(1:nl) = .true.
        left = nl
        do n = 2, nmax
            do j = 1, nl
                if (.not. live(j)) cycle
                call verlet_step(alpha, h, phi(j), law, iend, q, n, m, st(j), r(j), done)
                if (done) then
                    live(j) = .false.
                    left = left - 1
                end if
            end do
            if (left == 0) return
        end do
        do j = 1, nl
            if (live(j)) r(j)%status = HD_NO_REBOUND
        end do
    end subroutine run_verlet_lanes

    !> The verlet scheme's onset step (step 1): free flight before it (acc = acc_prev = 0,
    !> v = 1), in contact for the fraction phi of the step; the impact speed is 1.
    pure subroutine verlet_onset(alpha, h, phi, law, q, st)
        real(wp), intent(in) :: alpha, h, phi, q
        integer, intent(in) :: law
        type(verlet_t), intent(out) :: st
        real(wp) :: fh, fd, jn, f
        st%s = 0.0_wp
        st%z = phi * h
        fh = st%z * sqrt(st%z)
        fd = alpha * zq(st%z, law)
        jn = (fd * (phi / (1.0_wp + q) - 0.5_wp) + fh * (0.4_wp * phi - 0.5_wp)) * h &
             - trapezoid_g(1.5_wp, phi) * h * h * sqrt(h)
        if (q > 0.0_wp) jn = jn - trapezoid_g(q, phi) * alpha * h * zq(h, law)
        f = fh + fd
        st%fl = f
        st%zl = st%z
        st%vl = 1.0_wp
        st%acc_prev = 0.0_wp
        st%acc = -f
        st%v = 1.0_wp + 0.5_wp * h * st%acc - jn
    end subroutine verlet_onset

    !> Step n >= 2 of the verlet scheme; done (and r filled) at the end instant.
    pure subroutine verlet_step(alpha, h, phi, law, iend, q, n, m, st, r, done)
        real(wp), intent(in) :: alpha, h, phi, q
        integer, intent(in) :: law, iend, n, m
        type(verlet_t), intent(inout) :: st
        type(run_t), intent(inout) :: r
        logical, intent(out) :: done
        real(wp) :: vh, vp, f, dv, fh, us, jn
        integer :: kind
        done = .false.
        vh = st%v + 0.5_wp * h * st%acc
        st%z = st%z + h * vh
        vp = vh + 0.5_wp * h * st%acc + 0.5_wp * h * (st%acc - st%acc_prev)
        if (n == m) r%gz = st%z
        dv = 0.0_wp
        f = 0.0_wp
        kind = -1
        if (.not. (st%z > 0.0_wp) .and. iend == HD_END_FORCE .and. alpha * vp < 0.0_wp) then
            ! force end, the step passed the force zero and the overlap zero
            st%s = force_zero(alpha, law, st%zl, st%vl, st%z, vp)
            dv = -st%fl * (st%s - 1.0_wp) * 0.5_wp * h
            kind = 2
        else if (.not. (st%z > 0.0_wp)) then
            ! overlap end: the last force for the part of the step in contact
            st%s = overlap_fraction(st%zl, st%z)
            us = max(st%zl - st%z, 0.0_wp) / h
            fh = max(st%zl, 0.0_wp) * sqrt(max(st%zl, 0.0_wp))
            jn = ((st%fl - fh) * (st%s / (1.0_wp + q) - 0.5_wp) + fh * (0.4_wp * st%s - 0.5_wp)) * h &
                 - trapezoid_g(1.5_wp, st%s) * us * sqrt(us) * h * h * sqrt(h)
            if (q > 0.0_wp) jn = jn + trapezoid_g(q, st%s) * alpha * us * zq(us, law) * h * zq(h, law)
            dv = -jn
            kind = 0
        else
            f = st%z * sqrt(st%z) + alpha * zq(st%z, law) * vp
            if (n == m) r%gf = f
            if (iend == HD_END_FORCE .and. .not. (f > 0.0_wp)) then
                st%s = force_zero(alpha, law, st%zl, st%vl, st%z, vp)
                dv = -st%fl * (st%s - 1.0_wp) * 0.5_wp * h
                f = 0.0_wp
                kind = 1
            else
                st%fl = f
                st%zl = st%z
                st%vl = vp
            end if
        end if
        st%acc_prev = st%acc
        st%acc = -f
        st%v = vh + 0.5_wp * h * st%acc + dv
        if (kind >= 0) then
            ! the separation speed at the end instant: no force acts after it
            call finish_run(h, phi, n, kind, st%s, st%v, n - 1, r)
            done = .true.
        end if
    end subroutine verlet_step

    !> The engine's trapezoid error g_p(theta) = zeta_H(-p, theta) + theta^(p+1)/(p+1) -
    !> theta^p/2 of a force c s^p starting (or ending) a fraction theta of a step away
    !> (packages/dem/src/hertzdamp_dem_engine.f90: start_error p = 3/2, trapezoid_error p = q).
    pure real(wp) function trapezoid_g(p, theta) result(g)
        real(wp), intent(in) :: p, theta
        real(wp) :: tp
        if (p == 1.5_wp) then
            tp = theta * sqrt(theta)
        else if (p == 0.5_wp) then
            tp = sqrt(theta)
        else
            tp = sqrt(sqrt(theta))
        end if
        g = hertzdamp_host_hurwitz(p, theta) + theta * tp / (p + 1.0_wp) - 0.5_wp * tp
    end function trapezoid_g

    !> The engine's overlap_fraction: the part of the step before the overlap falls from
    !> zl to 0 at ze, in [0, 1].
    pure real(wp) function overlap_fraction(zl, ze) result(s)
        real(wp), intent(in) :: zl, ze
        s = 0.0_wp
        if (zl - ze > 0.0_wp) s = min(1.0_wp, max(0.0_wp, zl / (zl - ze)))
    end function overlap_fraction

    !> The engine's force_zero_model: the zero in s of G(s) = max(z(s), 0)^(3/2 - q) +
    !> alpha v(s), z and v linear over the step from (zl, vl) to (ze, ve), on [0, 1] or up to
    !> the overlap zero; G(0) > 0.  Found here to round-off by the Illinois method (the
    !> engine bisects 60 times: the same zero to 1e-18).
    pure real(wp) function force_zero(alpha, law, zl, vl, ze, ve) result(s)
        real(wp), intent(in) :: alpha, zl, vl, ze, ve
        integer, intent(in) :: law
        real(wp) :: lo, hi, glo, ghi, gs
        integer :: it, side
        lo = 0.0_wp
        hi = 1.0_wp
        if (ze <= 0.0_wp .and. zl - ze > 0.0_wp) hi = zl / (zl - ze)
        ghi = g(hi)
        s = hi
        if (ghi > 0.0_wp) return
        glo = g(lo)
        side = 0
        do it = 1, 200
            s = illinois_point(lo, hi, glo, ghi)
            gs = g(s)
            call illinois_update(s, gs, lo, hi, glo, ghi, side)
            if (hi - lo <= 4.0_wp * spacing(hi) .or. gs == 0.0_wp) exit
        end do
    contains
        pure real(wp) function g(t)
            real(wp), intent(in) :: t
            real(wp) :: zz
            zz = max(zl + t * (ze - zl), 0.0_wp)
            g = zz * sqrt(zz) / zq(zz, law) + alpha * (vl + t * (ve - vl))
            if (zz == 0.0_wp) g = alpha * (vl + t * (ve - vl))
        end function g
    end function force_zero

    !> The next point of the Illinois method in a bracket (lo, hi) of a function falling
    !> through zero (glo > 0 >= ghi): the secant's zero, or the middle when the secant
    !> leaves the bracket.
    pure real(wp) function illinois_point(lo, hi, glo, ghi) result(s)
        real(wp), intent(in) :: lo, hi, glo, ghi
        s = lo + (hi - lo) * glo / (glo - ghi)
        if (.not. (s > lo .and. s < hi)) s = 0.5_wp * (lo + hi)
    end function illinois_point

    !> The bracket after the value gs at s: s replaces the end of the same sign; when the
    !> same end was replaced twice in a row, the other end's value is halved (side: -1 the
    !> low end was replaced last, 1 the high end, 0 none yet).
    pure subroutine illinois_update(s, gs, lo, hi, glo, ghi, side)
        real(wp), intent(in) :: s, gs
        real(wp), intent(inout) :: lo, hi, glo, ghi
        integer, intent(inout) :: side
        if (gs > 0.0_wp) then
            lo = s
            glo = gs
            if (side == -1) ghi = 0.5_wp * ghi
            side = -1
        else
            hi = s
            ghi = gs
            if (side == 1) glo = 0.5_wp * glo
            side = 1
        end if
    end subroutine illinois_update

    ! ================================================================ phase statistics

    !> Phase statistics of a host's discrete collision: mean, standard deviation, min and
    !> max of e and tau_c over the onset phase phi uniform on (0, 1] (module header; the
    !> means to about 1e-14).  host = HD_HOST_NONE: the continuous e and tau_c with zero
    !> spread (h checked, not used).  Status as hertzdamp_host_collide (HD_NO_REBOUND when
    !> some phase does not rebound; HD_NO_CONVERGENCE when the quadrature does not settle:
    !> more than 200000 collisions or 256 pieces, or a piece whose tanh-sinh levels do not
    !> agree by level 7, not met in the tested range); zero statistics on failure.
    pure subroutine hertzdamp_host_mean(alpha, h, law, iend, host, stats, status)
        real(wp), intent(in) :: alpha                     !! damping parameter
        real(wp), intent(in) :: h                         !! dimensionless step dt / t*
        integer, intent(in) :: law                        !! HD_DAMPING_*
        integer, intent(in) :: iend                       !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: host                       !! HD_HOST_*
        type(hertzdamp_host_stats), intent(out) :: stats  !! phase statistics
        integer, intent(out) :: status                    !! HD_OK or the failure
        real(wp) :: e, tau
        status = check_common(law, iend, host)
        if (status == HD_OK) status = check_alpha(alpha)
        if (status == HD_OK) status = check_h(h)
        if (status /= HD_OK) return
        if (host == HD_HOST_NONE) then
            call continuous(alpha, law, iend, e, tau, status)
            if (status == HD_OK) stats = point_stats(e, tau)
            return
        end if
        call phase_stats(alpha, h, law, iend, host, stats, status)
    end subroutine hertzdamp_host_mean

    !> Statistics of a collision without spread.
    pure type(hertzdamp_host_stats) function point_stats(e, tau) result(s)
        real(wp), intent(in) :: e, tau
        s = hertzdamp_host_stats(e, 0.0_wp, e, e, tau, 0.0_wp, tau, tau)
    end function point_stats

    !> The phase statistics of a host's discrete collision (arguments checked).
    pure subroutine phase_stats(alpha, h, law, iend, host, stats, status)
        real(wp), intent(in) :: alpha, h
        integer, intent(in) :: law, iend, host
        type(hertzdamp_host_stats), intent(out) :: stats
        integer, intent(out) :: status
        type(ctx_t) :: cx
        type(piece_t) :: pieces(max_pieces), pc
        type(run_t) :: rs(n_coarse)
        type(sums_t) :: acc
        real(wp) :: ps(n_coarse), xbad, b
        integer :: j, np, sbad(3)
        logical :: bad
        cx = ctx_t(alpha, h, law, iend, host)
        status = HD_OK
        ! coarse samples phi_j = j / M; the first one's values are the references of the
        ! variance sums
        ps = [(real(j, wp) / real(n_coarse, wp), j = 1, n_coarse)]
        call run_many(alpha, h, ps, law, iend, host, rs)
        do j = 1, n_coarse
            call count_sample(rs(j), acc)
            if (rs(j)%status /= HD_OK) then
                status = rs(j)%status
                return
            end if
        end do
        acc%e_ref = rs(1)%e
        acc%t_ref = rs(1)%tau
        ! the pieces between signature changes of the samples (a stack worked from its
        ! top; each piece knows a phase of its own signature)
        np = 0
        pc = piece_t(0.0_wp, 1.0_wp, ps(1), rs(1)%sig)
        do j = 2, n_coarse
            if (any(rs(j)%sig /= rs(j - 1)%sig)) then
                call breakpoint(cx, ps(j - 1), rs(j - 1)%sig, ps(j), rs(j)%sig, b, acc, status)
                if (status /= HD_OK) return
                pc%b = b
                call push(pieces, np, pc, status)
                pc = piece_t(b, 1.0_wp, ps(j), rs(j)%sig)
            end if
        end do
        call push(pieces, np, pc, status)
        if (status /= HD_OK) return
        do while (np > 0)
            pc = pieces(np)
            np = np - 1
            call integrate_piece(cx, pc, acc, bad, xbad, sbad, status)
            if (status /= HD_OK) return
            if (bad) then
                ! a phase inside the piece with another signature: split at the breakpoint
                ! between it and the piece's own phase, and do both parts again
                call breakpoint(cx, pc%pref, pc%sig, xbad, sbad, b, acc, status)
                if (status /= HD_OK) return
                if (xbad > pc%pref) then
                    call push(pieces, np, piece_t(pc%a, b, pc%pref, pc%sig), status)
                    call push(pieces, np, piece_t(b, pc%b, xbad, sbad), status)
                else
                    call push(pieces, np, piece_t(b, pc%b, pc%pref, pc%sig), status)
                    call push(pieces, np, piece_t(pc%a, b, xbad, sbad), status)
                end if
                if (status /= HD_OK) return
            end if
        end do
        stats%e_mean = acc%ie
        stats%tau_mean = acc%it
        stats%e_sd = sqrt(max(acc%ie2 - (acc%ie - acc%e_ref)**2, 0.0_wp))
        stats%tau_sd = sqrt(max(acc%it2 - (acc%it - acc%t_ref)**2, 0.0_wp))
        stats%e_min = acc%e_min
        stats%e_max = acc%e_max
        stats%tau_min = acc%t_min
        stats%tau_max = acc%t_max
        status = HD_OK
    end subroutine phase_stats

    !> The stratified proxy of the phase means (mean of e and tau_c at the midpoints
    !> phi = (j - 1/2) / n_proxy; spreads, min and max over them): the search's cheap means.
    !> Status HD_NO_REBOUND when a phase does not rebound.
    pure subroutine proxy_stats(alpha, h, law, iend, host, stats, status)
        real(wp), intent(in) :: alpha, h
        integer, intent(in) :: law, iend, host
        type(hertzdamp_host_stats), intent(out) :: stats
        integer, intent(out) :: status
        type(run_t) :: r, rs(n_proxy)
        real(wp) :: se, st, se2, st2
        integer :: j
        se = 0.0_wp; st = 0.0_wp; se2 = 0.0_wp; st2 = 0.0_wp
        stats%e_min = huge(1.0_wp)
        stats%e_max = -huge(1.0_wp)
        stats%tau_min = huge(1.0_wp)
        stats%tau_max = -huge(1.0_wp)
        call run_many(alpha, h, [((real(j, wp) - 0.5_wp) / real(n_proxy, wp), j = 1, n_proxy)], law, iend, host, rs)
        do j = 1, n_proxy
            r = rs(j)
            status = r%status
            if (status /= HD_OK) then
                stats = hertzdamp_host_stats()
                return
            end if
            se = se + r%e
            st = st + r%tau
            se2 = se2 + r%e**2
            st2 = st2 + r%tau**2
            stats%e_min = min(stats%e_min, r%e)
            stats%e_max = max(stats%e_max, r%e)
            stats%tau_min = min(stats%tau_min, r%tau)
            stats%tau_max = max(stats%tau_max, r%tau)
        end do
        stats%e_mean = se / n_proxy
        stats%tau_mean = st / n_proxy
        stats%e_sd = sqrt(max(se2 / n_proxy - stats%e_mean**2, 0.0_wp))
        stats%tau_sd = sqrt(max(st2 / n_proxy - stats%tau_mean**2, 0.0_wp))
    end subroutine proxy_stats

    !> One collision at phase p, its values kept for the min and max.
    pure subroutine sample(cx, p, r, acc, probe)
        type(ctx_t), intent(in) :: cx
        real(wp), intent(in) :: p
        type(run_t), intent(out) :: r
        type(sums_t), intent(inout) :: acc
        integer, intent(in), optional :: probe
        if (acc%runs >= max_runs) then
            acc%runs = acc%runs + 1
            r%status = HD_NO_CONVERGENCE
            return
        end if
        call run(cx%alpha, cx%h, p, cx%law, cx%iend, cx%host, r, probe)
        call count_sample(r, acc)
    end subroutine sample

    !> A collision run for the phase statistics counted (beyond max_runs its status is
    !> HD_NO_CONVERGENCE) and its values kept for the min and max.
    pure subroutine count_sample(r, acc)
        type(run_t), intent(inout) :: r
        type(sums_t), intent(inout) :: acc
        acc%runs = acc%runs + 1
        if (acc%runs > max_runs) then
            r%status = HD_NO_CONVERGENCE
            return
        end if
        if (r%status == HD_OK) then
            acc%e_min = min(acc%e_min, r%e)
            acc%e_max = max(acc%e_max, r%e)
            acc%t_min = min(acc%t_min, r%tau)
            acc%t_max = max(acc%t_max, r%tau)
        end if
    end subroutine count_sample

    !> Push a piece on the stack; status HD_NO_CONVERGENCE when it is full.
    pure subroutine push(pieces, np, p, status)
        type(piece_t), intent(inout) :: pieces(:)
        integer, intent(inout) :: np
        type(piece_t), intent(in) :: p
        integer, intent(inout) :: status
        if (np < size(pieces)) then
            np = np + 1
            pieces(np) = p
        else
            status = HD_NO_CONVERGENCE
        end if
    end subroutine push

    !> The breakpoint b between the phases p1 (signature s1) and p2 (another signature, s2),
    !> to round-off: the bracket moves by the signature (whatever differs from s1 counts as
    !> the other side, so with several breakpoints between them the one found is one of
    !> them).  Its points: the Illinois method on the release indicator (probe_of) where it
    !> has opposite signs at the ends, else (and once it disagrees with a signature)
    !> bisection.
    pure subroutine breakpoint(cx, p1, s1, p2, s2, b, acc, status)
        type(ctx_t), intent(in) :: cx
        real(wp), intent(in) :: p1, p2
        integer, intent(in) :: s1(3), s2(3)
        real(wp), intent(out) :: b
        type(sums_t), intent(inout) :: acc
        integer, intent(out) :: status
        real(wp) :: x1, x2, xm, g1, g2, gm
        integer :: it, m, which, side
        logical :: secant, one
        type(run_t) :: rm
        x1 = p1
        x2 = p2
        status = HD_OK
        call probe_of(s1, s2, m, which)
        secant = m > 0
        g1 = 0.0_wp
        g2 = 0.0_wp
        gm = 0.0_wp
        if (secant) then
            call sample(cx, x1, rm, acc, m)
            g1 = indicator(rm)
            call sample(cx, x2, rm, acc, m)
            g2 = indicator(rm)
            secant = abs(g1) < huge(1.0_wp) .and. abs(g2) < huge(1.0_wp) .and. ((g1 > 0.0_wp) .neqv. (g2 > 0.0_wp))
        end if
        side = 0
        do it = 1, 200
            xm = 0.5_wp * (x1 + x2)
            if (xm == x1 .or. xm == x2) exit
            if (abs(x2 - x1) <= 4.0_wp * spacing(max(abs(x1), abs(x2))) .and. secant) exit
            if (.not. secant) then
                ! bisection's work in steps of `lanes` points side by side (run_many): the
                ! bracket shrinks by lanes + 1 (the first point that is not of s1 closes it)
                call multisect(x1, x2, acc, status)
                if (status /= HD_OK) exit
                cycle
            end if
            if (secant) then
                xm = x1 + (x2 - x1) * (g1 / (g1 - g2))
                if (.not. (xm > min(x1, x2) .and. xm < max(x1, x2))) xm = 0.5_wp * (x1 + x2)
            end if
            call sample(cx, xm, rm, acc, m)
            if (rm%status /= HD_OK) then
                status = rm%status
                exit
            end if
            one = all(rm%sig == s1)
            if (secant) then
                gm = indicator(rm)
                ! the indicator's side must be the signature's
                secant = abs(gm) < huge(1.0_wp) .and. ((gm > 0.0_wp) .eqv. merge(g1 > 0.0_wp, g2 > 0.0_wp, one))
            end if
            if (one) then
                x1 = xm
                g1 = gm
                if (side == 1) g2 = 0.5_wp * g2
                side = 1
            else
                x2 = xm
                g2 = gm
                if (side == 2) g1 = 0.5_wp * g1
                side = 2
            end if
        end do
        b = 0.5_wp * (x1 + x2)
    contains
        !> lanes points spaced evenly inside (x1, x2) (those that round to an end left out);
        !> the bracket becomes the first of them not of signature s1 and the point before it.
        pure subroutine multisect(x1, x2, acc, sm)
            real(wp), intent(inout) :: x1, x2
            type(sums_t), intent(inout) :: acc
            integer, intent(out) :: sm
            real(wp) :: ys(lanes), y
            type(run_t) :: rys(lanes)
            integer :: i, ny
            ny = 0
            do i = 1, lanes
                y = x1 + (x2 - x1) * (real(i, wp) / real(lanes + 1, wp))
                if (y > x1 .and. y < x2 .and. (ny == 0 .or. y > ys(max(ny, 1)))) then
                    ny = ny + 1
                    ys(ny) = y
                end if
            end do
            sm = HD_OK
            if (ny == 0) then
                ys(1) = 0.5_wp * (x1 + x2)
                ny = 1
            end if
            call run_many(cx%alpha, cx%h, ys(1:ny), cx%law, cx%iend, cx%host, rys(1:ny), m)
            do i = 1, ny
                call count_sample(rys(i), acc)
                if (rys(i)%status /= HD_OK) then
                    sm = rys(i)%status
                    return
                end if
                if (all(rys(i)%sig == s1)) then
                    x1 = ys(i)
                else
                    x2 = ys(i)
                    return
                end if
            end do
        end subroutine multisect

        pure real(wp) function indicator(r)
            type(run_t), intent(in) :: r
            indicator = merge(r%gz, r%gf, which == 0)
        end function indicator
    end subroutine breakpoint

    !> The step m and quantity (which: 0 the overlap, 1 the force there) whose sign tells the
    !> signatures s1 and s2 apart next to a breakpoint between them: the earlier release
    !> step and its kind's quantity (the overlap for verlet's kind 2); at one release step,
    !> an overlap release against a force clip, the overlap.  m = 0: none (bisection).
    pure subroutine probe_of(s1, s2, m, which)
        integer, intent(in) :: s1(3), s2(3)
        integer, intent(out) :: m, which
        m = 0
        which = 0
        if (s1(1) /= s2(1)) then
            m = min(s1(1), s2(1))
            which = merge(s1(2), s2(2), s1(1) < s2(1))
            if (which == 2) which = 0
        else if (s1(2) /= s2(2) .and. min(s1(2), s2(2)) == 0 .and. max(s1(2), s2(2)) == 1) then
            m = s1(1)
        end if
    end subroutine probe_of

    !> tanh-sinh quadrature of e, tau_c, (e - e_ref)^2 and (tau_c - t_ref)^2 over one
    !> piece, levels of step 2^-l until two successive levels of e and tau_c agree to
    !> quad_tol (relative); the integrals are added to acc.  A node whose signature is not the
    !> piece's: bad, with its phase and signature (nothing added).
    pure subroutine integrate_piece(cx, p, acc, bad, xbad, sbad, status)
        type(ctx_t), intent(in) :: cx
        type(piece_t), intent(in) :: p
        type(sums_t), intent(inout) :: acc
        logical, intent(out) :: bad
        real(wp), intent(out) :: xbad
        integer, intent(out) :: sbad(3)
        integer, intent(out) :: status
        integer, parameter :: nodes_max = 2 * int(ts_t_max * 2**level_max) + 2
        real(wp) :: width, t, ht, u, em, dend, wgt, guard, s(4), prev(4), cur(4)
        real(wp) :: xs(nodes_max), ws(nodes_max)
        integer :: level, k, kstep, side, nn, i
        type(run_t) :: r, rs(nodes_max)
        bad = .false.
        xbad = 0.0_wp
        sbad = 0
        status = HD_OK
        width = p%b - p%a
        if (.not. (width > 0.0_wp)) return
        ! nodes closer to an end than this are that end (a breakpoint is known to
        ! round-off): left out, their weight is below 1e-15 of the piece
        guard = 4.0_wp * spacing(max(abs(p%a), abs(p%b)))
        s = 0.0_wp
        prev = 0.0_wp
        cur = 0.0_wp
        do level = 0, level_max
            ht = 2.0_wp**(-level)
            kstep = merge(1, 2, level == 0)
            k = merge(0, 1, level == 0)
            ! the level's nodes, their collisions side by side (run_many), then in order
            nn = 0
            do while (real(k, wp) * ht <= ts_t_max)
                t = real(k, wp) * ht
                u = 0.5_wp * hertzdamp_pi * sinh(t)
                em = exp(-2.0_wp * u)
                ! distance of the node from the nearer end, and dphi/dt there
                dend = width * em / (1.0_wp + em)
                wgt = width * hertzdamp_pi * cosh(t) * em / (1.0_wp + em)**2
                do side = -1, 1, 2
                    if (k == 0 .and. side == 1) cycle
                    if (dend <= guard) cycle
                    nn = nn + 1
                    xs(nn) = merge(p%a + dend, p%b - dend, side == -1)
                    ws(nn) = wgt
                end do
                k = k + kstep
            end do
            call run_many(cx%alpha, cx%h, xs(1:nn), cx%law, cx%iend, cx%host, rs(1:nn))
            do i = 1, nn
                call count_sample(rs(i), acc)
                r = rs(i)
                if (r%status /= HD_OK) then
                    status = r%status
                    return
                end if
                if (any(r%sig /= p%sig)) then
                    bad = .true.
                    xbad = xs(i)
                    sbad = r%sig
                    return
                end if
                s = s + ws(i) * [r%e, r%tau, (r%e - acc%e_ref)**2, (r%tau - acc%t_ref)**2]
            end do
            cur = s * ht
            ! converged: the change of the level below quad_tol of the piece, or (pieces a
            ! few doubles wide) below the weight of the nodes left out next to the ends
            if (level >= level_min) then
                if (abs(cur(1) - prev(1)) <= quad_tol * max(width, abs(cur(1))) + 16.0_wp * guard * &
                    max(1.0_wp, abs(cur(1)) / width) .and. abs(cur(2) - prev(2)) <= quad_tol * max(width, abs(cur(2))) &
                    + 16.0_wp * guard * max(1.0_wp, abs(cur(2)) / width)) exit
            end if
            if (level == level_max) status = HD_NO_CONVERGENCE
            prev = cur
        end do
        acc%ie = acc%ie + cur(1)
        acc%it = acc%it + cur(2)
        acc%ie2 = acc%ie2 + cur(3)
        acc%it2 = acc%it2 + cur(4)
    end subroutine integrate_piece

    ! ================================================================ per-pair constants

    !> The per-pair constants of a host (doc/host-schemes.md): alpha and tau_c such that
    !> with h = tau_c / steps the host's phase means are e_mean = e and tau_mean = tau_c,
    !> each to 2e-12 relative.  Newton's method on the phase means in (alpha, h), started from
    !> the continuous inverse of the law and end (newton_solve), and where it does not converge
    !> a bracketing solve that finds a solution wherever one exists on the branch where e_mean
    !> falls with alpha (nested_solve; an explicit scheme's e_mean rises again for strong
    !> damping at a coarse step).  stats: the phase statistics there.
    !> host = HD_HOST_NONE: exactly hertzdamp_fit_inverse (alpha(e), tau_c(alpha)) with
    !> zero spread (steps checked, not used).  steps is real (T_c = N dt need not be whole).  Status HD_OK; for bad
    !> input (in this order) HD_BAD_HOST, HD_BAD_LAW, HD_BAD_END, HD_BAD_RESTITUTION (e
    !> outside the fitted inverse's range), HD_BAD_STEPS (not 2 <= steps <= 1e5); HD_HOST_UNREACHABLE
    !> when no alpha >= 0 reaches e at this many steps (hertzdamp_host_min_steps); zero
    !> outputs on failure.
    pure subroutine hertzdamp_host_solve(e, law, iend, host, steps, alpha, tau_c, stats, status)
        real(wp), intent(in) :: e                         !! target restitution coefficient
        integer, intent(in) :: law                        !! HD_DAMPING_*
        integer, intent(in) :: iend                       !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: host                       !! HD_HOST_*
        real(wp), intent(in) :: steps                     !! steps per contact N = T_c / dt
        real(wp), intent(out) :: alpha                    !! damping parameter for the host
        real(wp), intent(out) :: tau_c                    !! contact duration (units of t*): t* = T_c / tau_c
        type(hertzdamp_host_stats), intent(out) :: stats  !! phase statistics at the solution
        integer, intent(out) :: status                    !! HD_OK or the failure
        real(wp) :: a0, t0, x(2)
        type(ctx_t) :: cx
        alpha = 0.0_wp
        tau_c = 0.0_wp
        status = check_common(law, iend, host)
        if (status /= HD_OK) return
        call hertzdamp_fit_inverse(e, iend, a0, t0, status, law)
        if (status == HD_OK) then
            if (.not. (steps >= hertzdamp_host_steps_min .and. steps <= hertzdamp_host_steps_max)) status = HD_BAD_STEPS
        end if
        if (status /= HD_OK) return
        if (host == HD_HOST_NONE) then
            alpha = a0
            tau_c = t0
            stats = point_stats(e, t0)
            return
        end if
        cx = ctx_t(0.0_wp, 0.0_wp, law, iend, host)
        call first_solves(cx, e, steps, a0, t0, x, stats, status)
        if (status /= HD_OK) call continuation_solve(cx, e, steps, a0, t0, x, stats, status)
        if (status == HD_OK) then
            alpha = x(1)
            tau_c = steps * x(2)
        else
            stats = hertzdamp_host_stats()
        end if
    end subroutine hertzdamp_host_solve

    !> The solve at steps from the continuous constants (a0, tau_c0 = t0): Newton on the
    !> phase means, and where it does not converge the bracketing solve on the proxy means
    !> polished by Newton on the exact ones.
    !> bracketing_first: the bracketing solve and its polish before Newton from the continuous
    !> constants (hertzdamp_host_min_steps: the same status, the routes' results joined by
    !> "or", and near a scheme's limit the bracketing solve on the proxy means and a short
    !> polish cost less than Newton from the continuous constants, whose residual in e starts
    !> at 8e3 relative for kuwabara-kono, e = 1e-4, N = 114: 30 phase statistics against 10).
    pure subroutine first_solves(cx, e, steps, a0, t0, x, stats, status, bracketing_first)
        type(ctx_t), intent(in) :: cx
        real(wp), intent(in) :: e, steps, a0, t0
        real(wp), intent(out) :: x(2)
        type(hertzdamp_host_stats), intent(out) :: stats
        integer, intent(out) :: status
        logical, intent(in), optional :: bracketing_first
        real(wp) :: xp(2), xc(2)
        logical :: bf
        bf = .false.
        if (present(bracketing_first)) bf = bracketing_first
        if (.not. bf) then
            call newton_solve(cx, e, steps, [a0, t0 / steps], max_means, x, stats, status)
            if (status == HD_OK) return
        end if
        call nested_solve(cx, e, steps, a0, t0 / steps, x, stats, status)
        xp = x
        if (status == HD_OK) call newton_solve(cx, e, steps, xp, polish_means, x, stats, status)
        if (status /= HD_OK .and. bf) then
            call newton_solve(cx, e, steps, [a0, t0 / steps], max_means, x, stats, status)
            if (status == HD_OK) return
        end if
        if (status /= HD_OK .and. steps <= cliff_steps_max) then
            call cliff_solve(cx, e, steps, a0, t0 / steps, .false., xp, status)
            if (status /= HD_OK) return
            xc = xp
            call newton_solve(cx, e, steps, xp, polish_means, x, stats, status)
            ! the proxy's answer too far for the polish: the same solve on the exact means
            ! from it (mfix-ab2, kuwabara-kono, force end, e = 0.02, N = 2)
            if (status /= HD_OK) call cliff_solve(cx, e, steps, xc(1), xc(2), .true., xp, status)
            if (status /= HD_OK) return
            call newton_solve(cx, e, steps, xp, polish_means, x, stats, status)
        end if
    end subroutine first_solves

    !> The last resort of first_solves at a few steps per contact (steps <= cliff_steps_max),
    !> the bracketing solve with the roles of e and tau_c swapped, on the proxy means: at two or
    !> three steps a solution can lie in the thin layer past the minimum of e_mean over alpha
    !> where the release moves to the first steps and tau_mean falls steeply (lammps, linear,
    !> force end, e = 0.001, N = 2: at alpha h = 1 - 1e-7, where the damping stops the body in
    !> one step), which the bracketing solve on the falling branch of e_mean does not reach.
    !> For h, alpha_tau(h) where tau_mean / (N h) = 1 (Illinois from a bracket grown by
    !> doubling alpha from a0); E(h) = e_mean / e - 1 there, on h = h0 times powers of sqrt(2)
    !> from 1/16 to 2 until it changes sign, then the Illinois method on h.  exact: on the
    !> exact phase means instead, h from h0 / 2 to 2 h0 (first_solves: from the proxy's
    !> answer where that is too far for the polish).  x: the start of the polish;
    !> HD_HOST_UNREACHABLE where nothing is found.
    pure subroutine cliff_solve(cx, e, steps, a0, h0, exact, x, status)
        type(ctx_t), intent(in) :: cx
        real(wp), intent(in) :: e, steps, a0, h0
        logical, intent(in) :: exact
        real(wp), intent(out) :: x(2)
        integer, intent(out) :: status
        real(wp) :: hlo, hhi, glo, ghi, alo, ahi, h, g, a, hm, am, gm, sg
        integer :: j, k, st, side, jlo
        status = HD_HOST_UNREACHABLE
        jlo = merge(-2, -8, exact)
        x = 0.0_wp
        hlo = 0.0_wp
        glo = 0.0_wp
        alo = 0.0_wp
        ahi = 0.0_wp
        hhi = 0.0_wp
        ghi = 0.0_wp
        do j = jlo, 2
            h = h0 * sqrt(2.0_wp)**j
            call e_at(h, a, g, st)
            if (st /= HD_OK) cycle
            if (j > jlo .and. alo > 0.0_wp .and. (g > 0.0_wp .neqv. glo > 0.0_wp)) then
                hhi = h
                ghi = g
                ahi = a
                exit
            end if
            hlo = h
            glo = g
            alo = a
        end do
        if (.not. (hhi > 0.0_wp)) return
        ! the Illinois method on sg E, positive at hlo
        sg = merge(1.0_wp, -1.0_wp, glo > 0.0_wp)
        glo = sg * glo
        ghi = sg * ghi
        side = 0
        am = alo
        hm = hlo
        do k = 1, 60
            hm = illinois_point(hlo, hhi, glo, ghi)
            call e_at(hm, am, gm, st)
            if (st /= HD_OK) return
            gm = sg * gm
            if (abs(gm) <= proxy_tol .or. hhi - hlo <= 4.0_wp * spacing(hhi)) exit
            call illinois_update(hm, gm, hlo, hhi, glo, ghi, side)
        end do
        x = [am, hm]
        status = HD_OK
    contains
        !> E(hh) = e_mean / e - 1 at alpha_tau(hh) (aa); sa /= HD_OK where there is none.
        pure subroutine e_at(hh, aa, gg, sa)
            real(wp), intent(in) :: hh
            real(wp), intent(out) :: aa, gg
            integer, intent(out) :: sa
            real(wp) :: lo, hi, tlo, thi, ta, ea
            integer :: i, sd
            aa = 0.0_wp
            gg = 0.0_wp
            sa = HD_HOST_UNREACHABLE
            if (check_h(hh) /= HD_OK) return
            lo = 0.0_wp
            call tau_at(lo, hh, tlo, ea, sd)
            if (sd /= HD_OK .or. .not. (tlo > 0.0_wp)) return
            hi = a0
            do i = 1, 30
                call tau_at(hi, hh, thi, ea, sd)
                if (sd == HD_OK .and. thi <= 0.0_wp) exit
                if (sd == HD_OK) then
                    lo = hi
                    tlo = thi
                end if
                hi = 2.0_wp * hi
                if (hi > hertzdamp_host_alpha_max) return
            end do
            if (.not. (thi <= 0.0_wp)) return
            sd = 0
            do i = 1, 100
                aa = illinois_point(lo, hi, tlo, thi)
                call tau_at(aa, hh, ta, ea, sa)
                if (sa /= HD_OK) return
                if (abs(ta) <= proxy_tol .or. hi - lo <= 4.0_wp * spacing(hi)) exit
                call illinois_update(aa, ta, lo, hi, tlo, thi, sd)
            end do
            gg = ea / e - 1.0_wp
        end subroutine e_at

        !> tau_mean / (N hh) - 1 and e_mean on the proxy at (aa, hh).
        pure subroutine tau_at(aa, hh, tt, ee, sa)
            real(wp), intent(in) :: aa, hh
            real(wp), intent(out) :: tt, ee
            integer, intent(out) :: sa
            type(hertzdamp_host_stats) :: sp
            tt = 0.0_wp
            ee = 0.0_wp
            if (exact) then
                call phase_stats(aa, hh, cx%law, cx%iend, cx%host, sp, sa)
            else
                call proxy_stats(aa, hh, cx%law, cx%iend, cx%host, sp, sa)
            end if
            if (sa /= HD_OK) return
            tt = sp%tau_mean / (steps * hh) - 1.0_wp
            ee = sp%e_mean
        end subroutine tau_at
    end subroutine cliff_solve

    !> Continuation in N where first_solves fails at steps: near a scheme's limit the phase
    !> means are steep (mfix-ab2, force end, e = 0.0053: tau_mean / (N h) runs from 3 to 0.4
    !> over 1e-4 of h), and a start from the continuous constants can miss a solution that
    !> exists.  The solution moves little from one N to the next, so Newton at steps starts
    !> from the solution that first_solves finds at steps + 1 or steps - 1 (within the valid
    !> N), with a budget of polish_means phase statistics.  HD_HOST_UNREACHABLE when neither
    !> leads to a solution.
    pure subroutine continuation_solve(cx, e, steps, a0, t0, x, stats, status)
        type(ctx_t), intent(in) :: cx
        real(wp), intent(in) :: e, steps, a0, t0
        real(wp), intent(out) :: x(2)
        type(hertzdamp_host_stats), intent(out) :: stats
        integer, intent(out) :: status
        integer, parameter :: shifts(2) = [1, -1]
        real(wp) :: sn, xn(2)
        integer :: i
        status = HD_HOST_UNREACHABLE
        x = 0.0_wp
        do i = 1, size(shifts)
            sn = steps + real(shifts(i), wp)
            if (sn < hertzdamp_host_steps_min .or. sn > hertzdamp_host_steps_max) cycle
            call first_solves(cx, e, sn, a0, t0, xn, stats, status)
            if (status /= HD_OK) cycle
            call newton_solve(cx, e, steps, xn, polish_means, x, stats, status)
            if (status == HD_OK) return
        end do
        status = HD_HOST_UNREACHABLE
    end subroutine continuation_solve

    !> The residual of the per-pair solve at x = (alpha, h): (e_mean - e, tau_mean / (N h) - 1)
    !> and the statistics there; sv /= HD_OK where the phase statistics fail.
    pure subroutine solve_residual(cx, e, steps, x, r, st, sv)
        type(ctx_t), intent(in) :: cx
        real(wp), intent(in) :: e, steps, x(2)
        real(wp), intent(out) :: r(2)
        type(hertzdamp_host_stats), intent(out) :: st
        integer, intent(out) :: sv
        r = huge(1.0_wp)
        sv = check_alpha(x(1))
        if (sv == HD_OK) sv = check_h(x(2))
        if (sv /= HD_OK) return
        call phase_stats(x(1), x(2), cx%law, cx%iend, cx%host, st, sv)
        if (sv /= HD_OK) return
        r(1) = st%e_mean - e
        r(2) = st%tau_mean / (steps * x(2)) - 1.0_wp
    end subroutine solve_residual

    !> Newton in x = (alpha, h) on the residual of solve_residual from x0: a forward
    !> difference Jacobian, Broyden updates while the residual falls fast, a trust region
    !> (alpha moves by at most half its size, h by at most 40 %) and step halving.  HD_OK with
    !> both residuals below solve_tol (e relative), else HD_HOST_UNREACHABLE (also after
    !> `budget` phase statistics).
    pure subroutine newton_solve(cx, e, steps, x0, budget, x, stats, status)
        type(ctx_t), intent(in) :: cx
        real(wp), intent(in) :: e, steps, x0(2)
        integer, intent(in) :: budget
        real(wp), intent(out) :: x(2)
        type(hertzdamp_host_stats), intent(out) :: stats
        integer, intent(out) :: status
        real(wp) :: r(2), xt(2), rt(2), jac(2, 2), dx(2), sc(2), det, lam, nrm, nrmt, f
        type(hertzdamp_host_stats) :: stt
        integer :: it, ls, sv, nev
        logical :: fresh, need_jac, ok
        status = HD_HOST_UNREACHABLE
        x = x0
        call solve_residual(cx, e, steps, x, r, stats, sv)
        nev = 1
        if (sv /= HD_OK) return
        nrm = rnorm(r)
        need_jac = .true.
        fresh = .false.
        jac = 0.0_wp
        nrmt = nrm
        do it = 1, 40
            if (abs(r(1)) <= solve_tol * e .and. abs(r(2)) <= solve_tol) then
                status = HD_OK
                return
            end if
            if (nev > budget) return
            if (need_jac) then
                call jacobian(x, r, jac, sv)
                nev = nev + 2
                if (sv /= HD_OK) return
                fresh = .true.
                need_jac = .false.
            end if
            det = jac(1, 1) * jac(2, 2) - jac(1, 2) * jac(2, 1)
            if (.not. (abs(det) > 0.0_wp)) return
            dx(1) = -(jac(2, 2) * r(1) - jac(1, 2) * r(2)) / det
            dx(2) = -(jac(1, 1) * r(2) - jac(2, 1) * r(1)) / det
            sc = [max(x(1), 0.05_wp), x(2)]
            f = max(abs(dx(1)) / (0.5_wp * sc(1)), abs(dx(2)) / (0.4_wp * sc(2)), 1.0_wp)
            dx = dx / f
            lam = 1.0_wp
            ok = .false.
            do ls = 1, 6
                xt = x + lam * dx
                xt(1) = max(xt(1), 0.0_wp)
                call solve_residual(cx, e, steps, xt, rt, stt, sv)
                nev = nev + 1
                if (sv == HD_OK) then
                    nrmt = rnorm(rt)
                    ok = nrmt < nrm
                end if
                if (ok .or. nev > budget) exit
                lam = 0.5_wp * lam
            end do
            if (.not. ok) then
                ! no progress along a fresh Newton direction: no solution near here;
                ! after Broyden updates, try once more with a new Jacobian
                if (fresh) return
                need_jac = .true.
                cycle
            end if
            ! Broyden's update (inner product scaled by sc); a new Jacobian next time when
            ! the residual fell by less than half
            dx = xt - x
            jac = jac + matmul(reshape(rt - r - matmul(jac, dx), [2, 1]), reshape(dx / sc**2, [1, 2])) &
                  / sum((dx / sc)**2)
            fresh = .false.
            need_jac = nrmt > 0.5_wp * nrm
            x = xt
            r = rt
            nrm = nrmt
            stats = stt
        end do
    contains
        !> Forward-difference Jacobian at xx (residual rr there).
        pure subroutine jacobian(xx, rr, jj, sv)
            real(wp), intent(in) :: xx(2), rr(2)
            real(wp), intent(out) :: jj(2, 2)
            integer, intent(out) :: sv
            real(wp) :: d, rd(2)
            type(hertzdamp_host_stats) :: sd
            jj = 0.0_wp
            d = 1.0e-7_wp * max(xx(1), 1.0e-3_wp)
            call solve_residual(cx, e, steps, [xx(1) + d, xx(2)], rd, sd, sv)
            jj(:, 1) = (rd - rr) / d
            if (sv /= HD_OK) return
            d = 1.0e-7_wp * xx(2)
            call solve_residual(cx, e, steps, [xx(1), xx(2) + d], rd, sd, sv)
            jj(:, 2) = (rd - rr) / d
        end subroutine jacobian

        pure real(wp) function rnorm(rr)
            real(wp), intent(in) :: rr(2)
            rnorm = max(abs(rr(1)) / min(e, 1.0_wp), abs(rr(2)))
        end function rnorm
    end subroutine newton_solve

    !> The bracketing solve of the per-pair constants: for a step h, alpha(h) is the damping
    !> on the falling branch of e_mean(alpha) with e_mean = e (fall_alpha; h is feasible where
    !> it exists); the contact-time residual g(h) = tau_mean / (N h) - 1 at (alpha(h), h)
    !> grows without bound as h -> 0 and falls with h.  Its zero is bracketed by steps of 25 %
    !> from the continuous h0 (bracket_h) and found by the Illinois method.  HD_HOST_UNREACHABLE
    !> when g stays positive up to h_max or up to the edge of the feasible steps (no solution
    !> with this N), or when the phase statistics fail.
    pure subroutine nested_solve(cx, e, steps, a0, h0, x, stats, status)
        type(ctx_t), intent(in) :: cx
        real(wp), intent(in) :: e, steps, a0, h0
        real(wp), intent(out) :: x(2)
        type(hertzdamp_host_stats), intent(out) :: stats
        integer, intent(out) :: status
        real(wp) :: hlo, hhi, glo, ghi, alo, ahi, hm, gm, am
        type(hertzdamp_host_stats) :: s
        integer :: it, st, side
        status = HD_HOST_UNREACHABLE
        x = 0.0_wp
        call bracket_h(cx, e, steps, a0, h0, hlo, hhi, glo, ghi, alo, ahi, s, st)
        if (st /= HD_OK) return
        if (ghi == 0.0_wp) then
            x = [ahi, hhi]
            stats = s
            status = HD_OK
            return
        end if
        side = 0
        do it = 1, 100
            hm = illinois_point(hlo, hhi, glo, ghi)
            am = merge(alo, ahi, hm - hlo < hhi - hm)
            call g_of_h(cx, e, steps, hm, am, gm, s, st)
            if (st /= HD_OK) return
            if (abs(gm) <= proxy_tol .or. hhi - hlo <= 4.0_wp * spacing(hhi)) then
                x = [am, hm]
                stats = s
                status = HD_OK
                return
            end if
            if (gm > 0.0_wp) then
                alo = am
            else
                ahi = am
            end if
            call illinois_update(hm, gm, hlo, hhi, glo, ghi, side)
        end do
    end subroutine nested_solve

    !> The contact-time residual g(h) = tau_mean / (N h) - 1 at (alpha(h), h), alpha(h) from
    !> fall_alpha with the guess a (replaced by alpha(h)); st /= HD_OK where h is infeasible.
    pure subroutine g_of_h(cx, e, steps, h, a, g, stats, st)
        type(ctx_t), intent(in) :: cx
        real(wp), intent(in) :: e, steps, h
        real(wp), intent(inout) :: a
        real(wp), intent(out) :: g
        type(hertzdamp_host_stats), intent(out) :: stats
        integer, intent(out) :: st
        call fall_alpha(cx, e, h, a, stats, st)
        g = 0.0_wp
        if (st == HD_OK) g = stats%tau_mean / (steps * h) - 1.0_wp
    end subroutine g_of_h

    !> A bracket hlo < hhi of the zero of g (g(hlo) > 0 >= g(hhi), both feasible; alo, ahi the
    !> alpha there; stats those at hhi): from h0, steps of 25 % up while g > 0 or down while
    !> g <= 0 or h is infeasible; where the steps meet the edge of the feasible steps with
    !> g > 0 on the feasible side, bisection towards the edge (16 halvings) for a feasible
    !> g <= 0.  HD_HOST_UNREACHABLE when there is none (or h leaves [h_min, h_max]).
    pure subroutine bracket_h(cx, e, steps, a0, h0, hlo, hhi, glo, ghi, alo, ahi, stats, status)
        type(ctx_t), intent(in) :: cx
        real(wp), intent(in) :: e, steps, a0, h0
        real(wp), intent(out) :: hlo, hhi, glo, ghi, alo, ahi
        type(hertzdamp_host_stats), intent(out) :: stats
        integer, intent(out) :: status
        real(wp) :: h, g, a, hf, af, hx
        type(hertzdamp_host_stats) :: s
        integer :: it, st
        logical :: have_hi, have_lo, have_bad
        status = HD_HOST_UNREACHABLE
        hlo = 0.0_wp; hhi = 0.0_wp; glo = 0.0_wp; ghi = 0.0_wp; alo = 0.0_wp; ahi = 0.0_wp
        have_hi = .false.
        have_lo = .false.
        have_bad = .false.   ! an infeasible step above the feasible ones seen (hx)
        hx = 0.0_wp
        h = min(max(h0, hertzdamp_host_h_min), hertzdamp_host_h_max)
        a = a0
        do it = 1, 80
            call g_of_h(cx, e, steps, h, a, g, s, st)
            if (st /= HD_OK) then
                ! infeasible: a finer step may reach e
                if (have_lo) exit
                have_bad = .true.
                hx = h
                h = 0.8_wp * h
                a = a0
            else if (g > 0.0_wp) then
                hlo = h
                glo = g
                alo = a
                have_lo = .true.
                if (have_hi .or. have_bad) exit
                h = 1.25_wp * h
            else
                hhi = h
                ghi = g
                ahi = a
                stats = s
                have_hi = .true.
                if (have_lo) exit
                h = 0.8_wp * h
            end if
            if (h < hertzdamp_host_h_min .or. h > hertzdamp_host_h_max) return
        end do
        if (have_lo .and. have_hi) then
            status = HD_OK
            return
        end if
        if (.not. (have_lo .and. have_bad)) return
        ! g > 0 at hlo, infeasible at hx > hlo: look for a feasible g <= 0 in between, unless
        ! g cannot get there: tau_mean changes little with h, so that 1 + g falls about like
        ! 1/h; beyond a margin of 20 % that would need, there is no zero
        if (st /= HD_OK .and. h > hlo) hx = h
        if ((1.0_wp + glo) * (hlo / hx) > 1.2_wp) return
        hf = hlo
        af = alo
        do it = 1, 10
            h = 0.5_wp * (hf + hx)
            a = af
            call g_of_h(cx, e, steps, h, a, g, s, st)
            if (st /= HD_OK) then
                hx = h
            else if (g > 0.0_wp) then
                hf = h
                af = a
                hlo = h
                glo = g
                alo = a
            else
                hhi = h
                ghi = g
                ahi = a
                stats = s
                status = HD_OK
                return
            end if
        end do
    end subroutine bracket_h

    !> At the step h, the damping alpha on the falling branch of e_mean(alpha) (from
    !> alpha = 0 up to its minimum, beyond which an explicit scheme's e_mean rises again) with
    !> e_mean = e to proxy_tol relative on the proxy means (proxy_stats), and their statistics; alpha holds a guess on
    !> entry.  A collision without rebound counts as e_mean = 0.  HD_HOST_UNREACHABLE when e
    !> lies below the branch's minimum or above e_mean(0), or the statistics fail.
    pure subroutine fall_alpha(cx, e, h, alpha, stats, status)
        type(ctx_t), intent(in) :: cx
        real(wp), intent(in) :: e, h
        real(wp), intent(inout) :: alpha
        type(hertzdamp_host_stats), intent(out) :: stats
        integer, intent(out) :: status
        real(wp) :: alo, ahi, elo, ehi, a, ea, ap, ep, step, aprev
        type(hertzdamp_host_stats) :: s
        integer :: it, st, found
        status = HD_HOST_UNREACHABLE
        call mean_of(0.0_wp, elo, stats, st)
        if (st /= HD_OK .or. elo < e) return
        alo = 0.0_wp
        ahi = 0.0_wp
        ehi = huge(1.0_wp)
        ! a point a on the falling branch (the guess, halved until e_mean falls there): above
        ! the target it is the low end of the bracket (found = 1), below it the high end
        ! (found = 2); a guess halved to 0 starts from alpha = 0 (found = 1)
        found = 0
        a = max(min(alpha, 0.5_wp * hertzdamp_host_alpha_max), 0.0_wp)
        do it = 1, 60
            if (a < 1.0e-6_wp) then
                found = 1
                exit
            end if
            call mean_of(a, ea, s, st)
            if (st == HD_OK) call mean_of(a * (1.0_wp - 1.0e-3_wp), ep, s, st)
            if (st /= HD_OK) return
            if (ea < e .and. (ep > ea .or. ea == 0.0_wp)) then
                ahi = a
                ehi = ea
                found = 2
                exit
            else if (ea >= e .and. ep > ea) then
                alo = a
                elo = ea
                found = 1
                exit
            end if
            a = 0.5_wp * a
        end do
        if (found == 1) then
            ! e_mean(alo) >= e on the branch: walk up, doubling the step, until it falls below
            ! e; found it stops falling first, e is below the branch's minimum
            step = max(0.25_wp * alo, 1.0e-2_wp)
            aprev = alo
            do it = 1, 60
                ap = min(alo + step, hertzdamp_host_alpha_max)
                call mean_of(ap, ep, s, st)
                if (st /= HD_OK) return
                if (ep < e) then
                    ahi = ap
                    ehi = ep
                    exit
                end if
                if (ep >= elo) then
                    ! e_mean rose again: its minimum lies in (aprev, ap); below e there?
                    call branch_minimum(aprev, ap, ahi, ehi)
                    exit
                end if
                if (ap >= hertzdamp_host_alpha_max) return
                aprev = alo
                alo = ap
                elo = ep
                step = 2.0_wp * step
            end do
        else if (found == 2) then
            ! e_mean(ahi) < e on the branch: halve until e_mean >= e (the branch falls from 0)
            alo = ahi
            do it = 1, 60
                alo = 0.5_wp * alo
                if (alo < 1.0e-6_wp) alo = 0.0_wp
                call mean_of(alo, elo, s, st)
                if (st /= HD_OK) return
                if (elo >= e) exit
                ahi = alo
                ehi = elo
            end do
        end if
        if (.not. (found > 0 .and. elo >= e .and. ehi < e)) return
        call illinois_on_mean(alo, ahi, elo, ehi, alpha, stats, status)
    contains
        !> The proxy e_mean at alpha (0 without rebound; a collision that gains energy at some
        !> phase, e > unstable_e, is an unstable step, off the branch: its largest e).
        pure subroutine mean_of(aa, ee, sa, sta)
            real(wp), intent(in) :: aa
            real(wp), intent(out) :: ee
            type(hertzdamp_host_stats), intent(out) :: sa
            integer, intent(out) :: sta
            ee = 0.0_wp
            sta = check_alpha(aa)
            if (sta /= HD_OK) return
            call proxy_stats(aa, h, cx%law, cx%iend, cx%host, sa, sta)
            if (sta == HD_NO_REBOUND) then
                sta = HD_OK
                sa = hertzdamp_host_stats()
            end if
            ee = sa%e_mean
            if (sa%e_max > unstable_e) ee = sa%e_max
        end subroutine mean_of

        !> Golden-section search of the minimum of e_mean on [lo, hi] (at most 30 steps, to
        !> 1e-6 of the interval): the point where it is below e if it gets there first (amin,
        !> emin < e), else the minimum (emin >= e: e out of reach), found early when e lies
        !> well below what the narrowing bracket can still reach.
        pure subroutine branch_minimum(lo, hi, amin, emin)
            real(wp), intent(in) :: lo, hi
            real(wp), intent(out) :: amin, emin
            real(wp), parameter :: gr = 0.6180339887498949_wp
            real(wp) :: x1, x2, f1, f2, l, r
            type(hertzdamp_host_stats) :: sg
            integer :: k, stg
            l = lo
            r = hi
            x1 = r - gr * (r - l)
            x2 = l + gr * (r - l)
            call mean_of(x1, f1, sg, stg)
            call mean_of(x2, f2, sg, stg)
            amin = x1
            emin = huge(1.0_wp)
            do k = 1, 30
                if (f1 < e) then
                    amin = x1
                    emin = f1
                    return
                else if (f2 < e) then
                    amin = x2
                    emin = f2
                    return
                end if
                ! a smooth minimum lies within a few |f1 - f2| of the better point: when e is
                ! further below, it is out of reach (after a few steps, once the bracket is
                ! narrow enough for that)
                if (k > 6 .and. min(f1, f2) - e > 8.0_wp * abs(f1 - f2)) exit
                if (f1 <= f2) then
                    r = x2
                    x2 = x1
                    f2 = f1
                    x1 = r - gr * (r - l)
                    call mean_of(x1, f1, sg, stg)
                else
                    l = x1
                    x1 = x2
                    f1 = f2
                    x2 = l + gr * (r - l)
                    call mean_of(x2, f2, sg, stg)
                end if
                if (stg /= HD_OK) return
            end do
            emin = min(f1, f2)
        end subroutine branch_minimum

        !> The Illinois method on e_mean - e in [lo, hi] (e_mean(lo) >= e > e_mean(hi)).
        pure subroutine illinois_on_mean(lo, hi, emlo, emhi, aout, sout, stout)
            real(wp), intent(inout) :: lo, hi, emlo, emhi
            real(wp), intent(inout) :: aout
            type(hertzdamp_host_stats), intent(inout) :: sout
            integer, intent(inout) :: stout
            real(wp) :: glo, ghi, am, em
            type(hertzdamp_host_stats) :: sm
            integer :: k, side, stm
            glo = emlo - e
            ghi = emhi - e
            if (glo == 0.0_wp) then
                call mean_of(lo, em, sout, stout)
                aout = lo
                return
            end if
            side = 0
            do k = 1, 200
                am = illinois_point(lo, hi, glo, ghi)
                call mean_of(am, em, sm, stm)
                if (stm /= HD_OK) return
                if (abs(em - e) <= proxy_tol * e .or. hi - lo <= 4.0_wp * spacing(hi)) then
                    aout = am
                    sout = sm
                    stout = HD_OK
                    return
                end if
                call illinois_update(am, em - e, lo, hi, glo, ghi, side)
            end do
        end subroutine illinois_on_mean
    end subroutine fall_alpha

    !> The smallest whole number of steps per contact N (>= 2) from which hertzdamp_host_solve
    !> succeeds: at N, N + 1, .., N + 3 (min_steps_window), while N - 1 fails (or is below 2).
    !> The reach of a scheme is not always monotone in N near its limit (verlet, e = 0.05,
    !> linear, overlap: N = 12 is reached, 13 not, 14 and up again), hence the window; beyond
    !> it the reach grows with N over the tested range (test_host checks N - 1 and
    !> N .. N + 8 over a grid of laws, ends, schemes and e).  For messages such as "N = 3 steps
    !> cannot reach e = 0.5 with lammps; N >= 6 can".  host none: 2.  A candidate is N = 2
    !> where the solve succeeds there, else it comes from the bracketing solve on the proxy
    !> means alone (N = 3, then growing by factors of about sqrt(2) up to 1024 until it
    !> succeeds, then bisection); it is confirmed and moved by hertzdamp_host_solve itself:
    !> up until the window succeeds, down while N - 1 succeeds.
    !> Status HD_OK, a bad-input status of hertzdamp_host_solve, or
    !> HD_HOST_UNREACHABLE when no N up to 1024 succeeds (n_min = 0).
    pure subroutine hertzdamp_host_min_steps(e, law, iend, host, n_min, status)
        real(wp), intent(in) :: e        !! target restitution coefficient
        integer, intent(in) :: law       !! HD_DAMPING_*
        integer, intent(in) :: iend      !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: host      !! HD_HOST_*
        integer, intent(out) :: n_min    !! smallest whole N that the solve reaches
        integer, intent(out) :: status   !! HD_OK or the failure
        integer :: lo, hi, mid, st, n, k
        real(wp) :: a0, t0
        type(steps_cache_t) :: c
        n_min = 0
        ! the first solves and the solves by N, computed once (unknown: -1): the solve at N
        ! is first_solves at N, else continuation from the first solves at N + 1, N - 1
        ! (hertzdamp_host_solve, whose steps are known valid here)
        ! the bad-input statuses first
        status = check_common(law, iend, host)
        if (status == HD_OK) call hertzdamp_fit_inverse(e, iend, a0, t0, status, law)
        if (status /= HD_OK) return
        if (host == HD_HOST_NONE) then
            n_min = 2
            return
        end if
        call try(c, 2, .false., st)
        if (st == HD_OK) then
            ! N = 2 succeeds: the window N + 1 .. N + min_steps_window as for any N
            n = 2
            k = 1
        else
            status = st
            ! the candidate: the fewest N the proxy search reaches
            lo = 2
            hi = 3
            do
                call try(c, hi, .true., st)
                if (st == HD_OK) exit
                lo = hi
                if (hi >= n_search_max) exit
                hi = min(max(hi + 1, nint(sqrt(2.0_wp) * real(hi, wp))), n_search_max)
            end do
            do while (hi - lo > 1)
                mid = (lo + hi) / 2
                call try(c, mid, .true., st)
                if (st == HD_OK) then
                    hi = mid
                else
                    lo = mid
                end if
            end do
            n = hi
            k = 0
        end if
        ! confirmed by the solve itself: the first N from the candidate up at which it
        ! succeeds (galloping, then bisection: a proxy candidate can lie far below), and
        ! again until it succeeds at N .. N + min_steps_window; then down while N - 1 succeeds
        do while (k <= min_steps_window)
            if (k == 0) then
                call first_success(c, n, st)
                if (st /= HD_OK) then
                    status = HD_HOST_UNREACHABLE
                    return
                end if
                k = 1
                cycle
            end if
            call try(c, n + k, .false., st)
            if (st == HD_OK) then
                k = k + 1
            else
                n = n + k + 1
                k = 0
            end if
        end do
        do while (n > 2)
            call try(c, n - 1, .false., st)
            if (st /= HD_OK) exit
            n = n - 1
        end do
        n_min = n
        status = HD_OK
    contains
        !> The least whole nn >= nn on entry at which the solve succeeds, if the solve fails
        !> at the one before (galloping up by 1, 2, 4, .. from nn, then bisection between the
        !> last failure and the first success); st = HD_HOST_UNREACHABLE beyond n_search_max.
        pure subroutine first_success(c, nn, st)
            type(steps_cache_t), intent(inout) :: c
            integer, intent(inout) :: nn
            integer, intent(out) :: st
            integer :: bad, good, stride, m
            if (nn > n_search_max) then
                st = HD_HOST_UNREACHABLE
                return
            end if
            call try(c, nn, .false., st)
            if (st == HD_OK) return
            bad = nn
            stride = 1
            do
                if (bad >= n_search_max) then
                    st = HD_HOST_UNREACHABLE
                    return
                end if
                good = min(bad + stride, n_search_max)
                call try(c, good, .false., st)
                if (st == HD_OK) exit
                bad = good
                stride = 2 * stride
            end do
            do while (good - bad > 1)
                m = (bad + good) / 2
                call try(c, m, .false., st)
                if (st == HD_OK) then
                    good = m
                else
                    bad = m
                end if
            end do
            nn = good
            st = HD_OK
        end subroutine first_success

        !> The solve at nn (proxy: the bracketing solve on the proxy means only), the same
        !> as hertzdamp_host_solve's from the cached first solves.
        pure subroutine try(c, nn, proxy, st)
            type(steps_cache_t), intent(inout) :: c
            integer, intent(in) :: nn
            logical, intent(in) :: proxy
            integer, intent(out) :: st
            integer, parameter :: shifts(2) = [1, -1]
            real(wp) :: x(2), xn(2)
            type(hertzdamp_host_stats) :: s
            integer :: i, sn
            if (proxy) then
                call nested_solve(ctx_t(0.0_wp, 0.0_wp, law, iend, host), e, real(nn, wp), a0, t0 / real(nn, wp), x, s, &
                                  st)
                return
            end if
            if (nn <= n_cache) then
                st = c%solve_st(nn)
                if (st >= 0) return
            end if
            call first_at(c, nn, x, st)
            do i = 1, size(shifts)
                if (st == HD_OK) exit
                sn = nn + shifts(i)
                if (sn < nint(hertzdamp_host_steps_min)) cycle
                call first_at(c, sn, xn, st)
                if (st == HD_OK) call newton_solve(ctx_t(0.0_wp, 0.0_wp, law, iend, host), e, real(nn, wp), xn, &
                                                   polish_means, x, s, st)
            end do
            if (st /= HD_OK) st = HD_HOST_UNREACHABLE
            if (nn <= n_cache) c%solve_st(nn) = st
        end subroutine try

        !> first_solves at nn (cached).
        pure subroutine first_at(c, nn, x, st)
            type(steps_cache_t), intent(inout) :: c
            integer, intent(in) :: nn
            real(wp), intent(out) :: x(2)
            integer, intent(out) :: st
            type(hertzdamp_host_stats) :: s
            if (nn <= n_cache) then
                if (c%first_st(nn) >= 0) then
                    st = c%first_st(nn)
                    x = c%first_x(:, nn)
                    return
                end if
            end if
            call first_solves(ctx_t(0.0_wp, 0.0_wp, law, iend, host), e, real(nn, wp), a0, t0, x, s, st, .true.)
            if (nn <= n_cache) then
                c%first_st(nn) = st
                c%first_x(:, nn) = x
            end if
        end subroutine first_at
    end subroutine hertzdamp_host_min_steps

    !> At a fixed dimensionless step h (a deck's k and dt fix t* and h), the damping alpha >= 0
    !> whose phase-mean e equals e (to 1e-10 relative), and the phase statistics there: the
    !> corrected coefficient of a deck.  host none: the continuous alpha(e) of the fit (h
    !> checked, not used).
    !> Status HD_OK; bad input as hertzdamp_host_solve (HD_BAD_STEPS for h outside [1e-5, 4]);
    !> HD_HOST_UNREACHABLE when no alpha >= 0 gives e at this h; zero outputs on failure.
    pure subroutine hertzdamp_host_alpha_for_e(e, h, law, iend, host, alpha, stats, status)
        real(wp), intent(in) :: e                         !! target restitution coefficient
        real(wp), intent(in) :: h                         !! dimensionless step dt / t*
        integer, intent(in) :: law                        !! HD_DAMPING_*
        integer, intent(in) :: iend                       !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: host                       !! HD_HOST_*
        real(wp), intent(out) :: alpha                    !! damping parameter
        type(hertzdamp_host_stats), intent(out) :: stats  !! phase statistics at alpha
        integer, intent(out) :: status                    !! HD_OK or the failure
        real(wp) :: a0, t0, alo, ahi, elo, ehi, glo, ghi, am, em, step
        type(hertzdamp_host_stats) :: s
        integer :: it, st, side
        alpha = 0.0_wp
        status = check_common(law, iend, host)
        if (status /= HD_OK) return
        call hertzdamp_fit_inverse(e, iend, a0, t0, status, law)
        if (status == HD_OK) status = check_h(h)
        if (status /= HD_OK) return
        if (host == HD_HOST_NONE) then
            alpha = a0
            stats = point_stats(e, t0)
            return
        end if
        ! bracket: e_mean falls with alpha; from the continuous alpha step outwards
        call mean_at(a0, em, s, st)
        if (st /= HD_OK) then
            status = HD_HOST_UNREACHABLE
            return
        end if
        alo = a0
        ahi = a0
        elo = em
        ehi = em
        step = max(0.25_wp * a0, 1.0e-3_wp)
        do it = 1, 200
            if (elo >= e .and. ehi <= e) exit
            if (elo < e) then
                ! too damped: smaller alpha (down to 0)
                if (alo == 0.0_wp) then
                    status = HD_HOST_UNREACHABLE
                    return
                end if
                ahi = alo
                ehi = elo
                alo = max(alo - step, 0.0_wp)
                call mean_at(alo, elo, s, st)
            else
                alo = ahi
                elo = ehi
                ahi = ahi + step
                call mean_at(ahi, ehi, s, st)
                if (st == HD_OK .and. ehi >= elo) st = HD_HOST_UNREACHABLE   ! no longer falling
            end if
            if (st /= HD_OK) then
                status = HD_HOST_UNREACHABLE
                return
            end if
            step = 2.0_wp * step
        end do
        ! Illinois method in the bracket on g = e_mean - e (g(alo) >= 0 >= g(ahi))
        glo = elo - e
        ghi = ehi - e
        side = 0
        status = HD_HOST_UNREACHABLE
        do it = 1, 200
            am = illinois_point(alo, ahi, glo, ghi)
            call mean_at(am, em, s, st)
            if (st /= HD_OK) return
            if (abs(em - e) <= solve_tol * e .or. ahi - alo <= 4.0_wp * spacing(ahi)) then
                alpha = am
                stats = s
                status = HD_OK
                return
            end if
            call illinois_update(am, em - e, alo, ahi, glo, ghi, side)
        end do
    contains
        pure subroutine mean_at(a, ea, sa, sta)
            real(wp), intent(in) :: a
            real(wp), intent(out) :: ea
            type(hertzdamp_host_stats), intent(out) :: sa
            integer, intent(out) :: sta
            sta = check_alpha(a)
            ea = 0.0_wp
            if (sta /= HD_OK) return
            call phase_stats(a, h, law, iend, host, sa, sta)
            ea = sa%e_mean
        end subroutine mean_at
    end subroutine hertzdamp_host_alpha_for_e

end module hertzdamp_host
