!> The DEM engine: spheres with normal contact forces only, run step by step around
!> a state type (doc/theory.md section 6: the inverse rule at every contact).
!>
!> - Spheres in 3-D (a 1-D column is a scene whose particles lie on one line),
!>   plane walls, optional uniform gravity.  Tangential forces, friction and
!>   rotation are out of scope: every force acts along the line of centres.
!> - Time stepping (sc%scheme): by default (HD_HOST_VERLET) velocity Verlet at the scene's dt.  The damping force needs a
!>   velocity at the new positions; the extrapolation v + dt a_n + dt/2 (a_n - a_(n-1))
!>   is used (error O(dt^3); the plain v + dt a costs ten times more accuracy in e
!>   for strongly damped contacts, though both are second order).
!> - Host schemes (sc%scheme, doc/host-schemes.md section 2, one step each, a = g + F/m):
!>   HD_HOST_LAMMPS v_h = v + dt/2 a; x += dt v_h; F(x, v_h); v = v_h + dt/2 a_new;
!>   HD_HOST_MFIX_EULER v += dt a; x += dt v; F(x, v);  HD_HOST_MFIX_AB2 v_new = v +
!>   dt (3 a - a_old)/2; x += dt (v + v_new)/2; F(x, v_new) -- without the onset and end
!>   corrections below.  A contact ends at the first step without overlap (its instant
!>   interpolated linearly in the overlap) or, force end, at the first step whose force
!>   is not positive (interpolated linearly in the force; no force from then on); its
!>   separation speed is the velocity once no contact force acts (mfix-ab2: after the
!>   step that still applies the last contact acceleration through a_old).  With
!>   sc%host /= HD_HOST_NONE every contact gets k and d from the per-pair constants
!>   of that host (hertzdamp_pair_init at N = steps_per_contact, hertzdamp_pair_kd); with
!>   sc%onset_phase each contact its own from its onset phase, the first overlap over
!>   u_rule dt (hertzdamp_onset_phase, hertzdamp_pair_kd_phase; issue 32).
!> - At each contact onset (pair or sphere-wall) the contact gets its own k and d
!>   from the inverse rule for its effective mass m and impact normal velocity u_in,
!>   bounded by the material pair's physical Hertz stiffness
!>   k_phys = (4/3) E* sqrt(R*); k and d are kept for the contact's duration.
!>   When the scene wants the restitution only, k = k_phys and only alpha(e) and
!>   d = alpha m t*^-1 (u_in t*)^-q (t* of k_phys) are computed: linear
!>   alpha m^(3/5) k_phys^(2/5) u_in^(1/5), tsuji alpha sqrt(m k_phys).
!> - Force F = k zeta^(3/2) + d zeta^q zeta' (repulsive when positive) while in
!>   contact, q of the scene's damping law: 0 linear, 1/4 tsuji, 1/2 kuwabara-kono
!>   (doc/damping-laws.md; the rule, its alpha and tau_c are the law's).
!>   The contact ends by the scene's definition: overlap (zeta returns to 0) or
!>   force (F returns to 0; the contact is then released and exerts no force).  A
!>   released contact is closed when its overlap vanishes or when the bodies approach
!>   again (zeta' > 0 while still overlapping, as in a slow bounce under gravity);
!>   a renewed approach is then a new contact with its own k and d from the rule
!>   (its impact speed is small, so the rule gets rest_speed).
!> - The contact-start and contact-end instants fall inside a step.  The damping
!>   force d (u s)^q u (s the time from the touch, or to the release) jumps there
!>   (q = 0) or has an infinite slope (q > 0), which would make the scheme of order
!>   1 + q; the touch and the overlap end are located by linear interpolation of the
!>   overlap, and the velocity update of that step gets the impulse correction of
!>   the part of the step actually in contact (the damping force acts for
!>   theta/(1+q) of a step, the Hertz force for 2/5 theta).  Then the trapezoidal
!>   impulse of the following (or preceding) steps of a force c s^p is wrong by
!>   g_p(theta) c dt^(p+1), theta the fraction of the step in contact, g_p a Hurwitz
!>   zeta value (`trapezoid_error`): Hertz p = 3/2, c = k u^(3/2) (`start_error`),
!>   and for q > 0 damping p = q, c = d u^(1+q); both terms are subtracted.  The
!>   force zero (force end) is found on a model of its step: overlap and overlap
!>   rate linear in time, the zero of k zeta^(3/2-q) + d zeta' (`force_zero_model`;
!>   near the end of a nearly elastic contact the force itself is far from linear
!>   over a step).  The achieved restitution and contact time are then second order
!>   in dt for every law and end: largest relative errors over four touch phases at
!>   N = 10, 20, 40 steps per contact up to 1.2/N^2 for e >= 0.5 and 3.2/N^2 for
!>   e = 0.3 (test_scene prints them); the scene report uses 2/N^2.
!> - Impact velocity u_in: the relative normal velocity interpolated to the onset
!>   instant.  The rule gets the speed floor max(u_in, rest_speed, 1e-9 m/s): a
!>   contact that starts slower than the scene's rest speed (touching particles
!>   pushed together gently, as in a chain or a settling bed), or with a zero or
!>   receding normal velocity, is a resting contact and gets the damping of an impact
!>   at rest_speed (with u_in -> 0 the linear rule's d ~ u_in^(1/5) would vanish and
!>   such contacts would ring undamped).  Its alpha at the real u_in is then the
!>   law's alpha(e) (u_in/u_rule)^((4q-1)/5): tsuji keeps the target e (alpha =
!>   d/sqrt(m k) does not depend on the speed), linear is more damped, kuwabara-kono
!>   less.
!> - Coincident centres (a pair whose centres meet in one step): the contact normal
!>   is the contact's normal of the previous step; at onset, the direction between
!>   the centres at the start of the step, else +x.  Every division of the engine has
!>   such a defined outcome, so no NaN arises in any build; a quantity that still
!>   overflows ends the run with HD_OUT_OF_RANGE and a message.
!>
!> One step is a sequence of named phases on the state (`hertzdamp_dem_state`):
!> drift (opening half kick and new positions), forces of the contacts in progress
!> (with their release bookkeeping), onsets (new contacts with walls, then the
!> neighbour search, then new pair contacts), binary flags, the closing kick (with the
!> impulse corrections and the separation speeds of the contacts that ended), and
!> the monitors (energy, momentum, domain, finiteness) and trace sampling.  Every
!> phase takes the state and the result as arguments; nothing is shared otherwise.
!>
!> A run can be made in one call (`hertzdamp_dem_run`) or in pieces
!> (`hertzdamp_dem_start`, `hertzdamp_dem_advance` any number of steps at a time,
!> `hertzdamp_dem_finish`), so that a caller can report progress between pieces.
!> All procedures are pure, keep no state of their own, never print: failures come
!> back as a status (hertzdamp_status codes) and a message.
module hertzdamp_dem_engine
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_OUT_OF_RANGE, HD_HOST_UNREACHABLE, hertzdamp_message, HD_END_FORCE, &
                         HD_HOST_NONE, HD_HOST_LAMMPS, HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2, HD_HOST_VERLET, &
                         hertzdamp_host_name, hertzdamp_host_min_steps, hertzdamp_host_stats, hertzdamp_pair_t, &
                         hertzdamp_pair_init, hertzdamp_law_q, hertzdamp_sphere_mass, hertzdamp_effective_mass, &
                         hertzdamp_effective_radius, hertzdamp_effective_modulus, hertzdamp_hertz_stiffness, &
                         hertzdamp_onset_phase
    use hertzdamp_dem_types, only: hertzdamp_dem_scene, hertzdamp_dem_contact, hertzdamp_dem_result, &
                                   hertzdamp_dem_pair_e, hertzdamp_dem_nsteps, hertzdamp_dem_trace_size, hertzdamp_dem_u_floor, &
                                   hertzdamp_dem_pairs_met, HD_CONTACT_ACTIVE, HD_CONTACT_RELEASED, HD_CONTACT_CLOSED
    use hertzdamp_dem_rules, only: hertzdamp_dem_rule, hertzdamp_dem_host_rule
    use hertzdamp_dem_types, only: int_text => hertzdamp_dem_int_text
    use hertzdamp_text_format, only: fmt_short
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Everything a run changes from step to step.  Built by hertzdamp_dem_start for
    !> one scene; pass that same scene to every later call.
    type, public :: hertzdamp_dem_state
        private
        ! settings of the run
        integer :: n = 0                         ! particles
        integer :: nsteps = 0                    ! steps of the whole run
        integer :: step = 0                      ! steps done
        integer :: method = 0                    ! HD_METHOD_* of the rule
        real(wp) :: q = 0.0_wp                   ! exponent of the damping law: force d zeta^q zeta'
        real(wp) :: tol = 0.0_wp                 ! tolerance of the iterative rule
        real(wp) :: dt = 0.0_wp                  ! time step [s]
        real(wp) :: tc_wanted = 0.0_wp           ! N dt [s]
        real(wp) :: g(3) = 0.0_wp                ! gravity (0 when off) [m s^-2]
        real(wp), allocatable :: mass(:)         ! particle masses [kg]
        real(wp), allocatable :: rad(:)          ! particle radii [m]
        real(wp), allocatable :: estar(:, :)     ! E* of each material pair [Pa]
        real(wp), allocatable :: e_pair(:, :)    ! target e of each material pair
        integer :: scheme = HD_HOST_VERLET       ! HD_HOST_* time integrator of the contacts
        logical :: host_rule = .false.           ! k, d from the per-pair constants of sc%host
        type(hertzdamp_pair_t), allocatable :: pair(:, :)  ! per-pair constants of each material pair (host_rule)
        ! kinematics: x, v, acc at the step points; the rest inside one step
        real(wp), allocatable :: x(:, :)         ! positions [m]
        real(wp), allocatable :: v(:, :)         ! velocities [m s^-1]
        real(wp), allocatable :: acc(:, :)       ! accelerations a_n [m s^-2]
        real(wp), allocatable :: acc_prev(:, :)  ! accelerations a_(n-1)
        real(wp), allocatable :: x_start(:, :)   ! positions at the start of the step
        real(wp), allocatable :: v_start(:, :)   ! velocities at the start of the step
        real(wp), allocatable :: v_half(:, :)    ! velocities after the opening half kick
        real(wp), allocatable :: v_pred(:, :)    ! velocities predicted at the new positions (damping)
        real(wp), allocatable :: force(:, :)     ! contact forces of the step [N]
        real(wp), allocatable :: dv(:, :)        ! impulse corrections of the step (velocity) [m s^-1]
        integer, allocatable :: ncontact(:)      ! contacts acting on each particle in the step
        ! contacts: active list and lookup tables (0 = no contact)
        integer :: nactive = 0
        integer, allocatable :: active(:)        ! indices into res%contacts
        integer, allocatable :: pair_contact(:)  ! contact of each particle pair (triangular index)
        integer, allocatable :: wall_contact(:, :) ! contact of each (particle, wall)
        integer :: nended = 0
        integer, allocatable :: ended(:)         ! contacts that ended in this step
        ! neighbour list: sweep along `axis` over particles sorted by that coordinate
        integer :: axis = 1
        real(wp) :: skin = 0.0_wp                ! list margin [m]
        real(wp) :: rmax = 0.0_wp                ! largest radius [m]
        integer :: nneighbours = 0
        integer, allocatable :: perm(:)          ! particles sorted along axis
        integer, allocatable :: nb_i(:), nb_j(:) ! pairs of the list (i < j)
        real(wp), allocatable :: x_built(:, :)   ! positions at the last build
        ! monitors and trace
        real(wp) :: epot = 0.0_wp                ! contact energy sum 2/5 k zeta^(5/2) of the step [J]
        real(wp) :: energy = 0.0_wp              ! total energy at the last step point [J]
        real(wp) :: energy_min = 0.0_wp          ! running minimum of the energy [J]
        logical, allocatable :: gone(:)          ! particle has left the domain
        integer :: every = 1                     ! steps between trace samples
        integer :: nsamples = 0                  ! samples taken
        integer :: ntraced = 0                   ! particles traced
    end type hertzdamp_dem_state

    public :: hertzdamp_dem_run, hertzdamp_dem_start, hertzdamp_dem_advance, hertzdamp_dem_finish
    public :: hertzdamp_dem_steps_done, hertzdamp_dem_steps_total

contains

    !> Run a scene with a contact rule in one call.  tol is the tolerance of the
    !> iterative rule.  Keeps no state between calls and does no I/O: safe to call
    !> from threads.
    pure subroutine hertzdamp_dem_run(sc, method, tol, res)
        type(hertzdamp_dem_scene), intent(in) :: sc   !! a scene that passed hertzdamp_dem_check
        integer, intent(in) :: method                 !! HD_METHOD_*
        real(wp), intent(in) :: tol                   !! iterative rule tolerance
        type(hertzdamp_dem_result), intent(out) :: res !! contacts, checks, trace
        type(hertzdamp_dem_state) :: st
        call hertzdamp_dem_start(sc, method, tol, st, res)
        call hertzdamp_dem_advance(sc, st, res, hertzdamp_dem_steps_total(st))
        call hertzdamp_dem_finish(sc, st, res)
    end subroutine hertzdamp_dem_run

    !> Steps done so far.
    pure integer function hertzdamp_dem_steps_done(st)
        type(hertzdamp_dem_state), intent(in) :: st  !! state of the run
        hertzdamp_dem_steps_done = st%step
    end function hertzdamp_dem_steps_done

    !> Steps of the whole run.
    pure integer function hertzdamp_dem_steps_total(st)
        type(hertzdamp_dem_state), intent(in) :: st  !! state of the run
        hertzdamp_dem_steps_total = st%nsteps
    end function hertzdamp_dem_steps_total

    !> Set up a run: the state at t = 0 and the first trace sample.
    pure subroutine hertzdamp_dem_start(sc, method, tol, st, res)
        type(hertzdamp_dem_scene), intent(in) :: sc    !! a scene that passed hertzdamp_dem_check
        integer, intent(in) :: method                  !! HD_METHOD_*
        real(wp), intent(in) :: tol                    !! iterative rule tolerance
        type(hertzdamp_dem_state), intent(out) :: st   !! the state at t = 0
        type(hertzdamp_dem_result), intent(out) :: res !! the result so far (status set when the scene cannot start)
        integer :: n, nw, nm, i, j, nsamples
        integer, allocatable :: status(:)
        n = size(sc%radius)
        nw = size(sc%wall)
        nm = size(sc%mat)
        st%n = n
        st%method = method
        st%q = hertzdamp_law_q(sc%law)
        st%tol = tol
        st%dt = sc%dt
        st%tc_wanted = sc%steps_per_contact * sc%dt
        st%scheme = sc%scheme
        st%host_rule = sc%host /= HD_HOST_NONE
        st%nsteps = hertzdamp_dem_nsteps(sc)
        st%step = 0
        if (sc%gravity) st%g = sc%g
        res%method = method
        res%message = ''
        allocate (st%mass(n), st%rad(n), st%estar(nm, nm), st%e_pair(nm, nm), status(n))
        ! masses and E* from the core (hertzdamp_materials); a scene that passed
        ! hertzdamp_dem_check gets HD_OK, any other failure stops the run before its start
        do i = 1, nm
            do j = 1, nm
                call hertzdamp_effective_modulus(sc%mat(i)%youngs_modulus, sc%mat(i)%poisson_ratio, &
                                                 sc%mat(j)%youngs_modulus, sc%mat(j)%poisson_ratio, st%estar(i, j), &
                                                 status(1))
                if (status(1) /= HD_OK .and. res%status == HD_OK) then
                    res%status = status(1)
                    res%message = 'material pair ' // trim(sc%mat(i)%name) // ' - ' // trim(sc%mat(j)%name) // &
                                  ': E*: ' // hertzdamp_message(status(1))
                end if
                st%e_pair(i, j) = hertzdamp_dem_pair_e(sc%mat(i), sc%mat(j))
            end do
        end do
        if (st%host_rule) call host_pairs(sc, st, res)
        st%rad = sc%radius
        st%rmax = maxval(st%rad)
        call hertzdamp_sphere_mass(st%rad, sc%mat(sc%pmat)%density, st%mass, status)
        if (any(status /= HD_OK) .and. res%status == HD_OK) then
            i = findloc(status /= HD_OK, .true., dim=1)
            res%status = status(i)
            res%message = 'particle ' // int_text(i) // ': mass: ' // hertzdamp_message(status(i))
        end if
        st%x = sc%x
        st%v = sc%v
        allocate (st%acc(3, n))
        do i = 1, n
            st%acc(:, i) = st%g
        end do
        st%acc_prev = st%acc
        allocate (st%x_start(3, n), st%v_start(3, n), st%v_half(3, n), st%v_pred(3, n), st%force(3, n), &
                  st%dv(3, n), st%ncontact(n))
        allocate (st%active(64), st%ended(64), st%pair_contact(max(1, n * (n - 1) / 2)), st%wall_contact(n, max(1, nw)))
        st%pair_contact = 0
        st%wall_contact = 0
        st%nactive = 0
        allocate (st%gone(n))
        st%gone = .false.
        allocate (res%contacts(64))
        ! neighbour list: sweep axis = largest spread of the initial positions
        st%axis = maxloc(maxval(st%x, dim=2) - minval(st%x, dim=2), dim=1)
        st%perm = [(i, i=1, n)]
        st%skin = 0.2_wp * minval(st%rad)
        allocate (st%nb_i(64), st%nb_j(64), st%x_built(3, n))
        call build_neighbours(st)
        ! trace axis: up (against gravity), else the axis with the largest initial velocities
        if (sc%gravity .and. norm2(st%g) > 0.0_wp) then
            res%axis = maxloc(abs(st%g), dim=1)
        else
            res%axis = maxloc(sum(abs(st%v), dim=2), dim=1)
        end if
        call hertzdamp_dem_trace_size(sc, st%every, nsamples, st%ntraced)
        allocate (res%t_trace(nsamples), res%x_trace(nsamples, st%ntraced), res%v_trace(nsamples, st%ntraced))
        st%nsamples = 1
        res%t_trace(1) = 0.0_wp
        res%x_trace(1, :) = st%x(res%axis, 1:st%ntraced)
        res%v_trace(1, :) = st%v(res%axis, 1:st%ntraced)
        st%energy = total_energy(st)
        res%energy0 = st%energy
        st%energy_min = st%energy
        res%momentum0 = momentum(st)
        res%momentum_scale = sum(st%mass * norm2(st%v, dim=1))
    end subroutine hertzdamp_dem_start

    !> Advance a run by up to max_steps steps (fewer at its end or on a failure,
    !> which sets res%status and res%message).
    pure subroutine hertzdamp_dem_advance(sc, st, res, max_steps)
        type(hertzdamp_dem_scene), intent(in) :: sc      !! the scene given to hertzdamp_dem_start
        type(hertzdamp_dem_state), intent(inout) :: st   !! state of the run
        type(hertzdamp_dem_result), intent(inout) :: res !! result so far
        integer, intent(in) :: max_steps                 !! most steps to take now
        integer :: last
        if (res%status /= HD_OK) return
        last = st%step + min(max(max_steps, 0), st%nsteps - st%step)
        do while (st%step < last)
            call one_step(sc, st, res)
            if (res%status /= HD_OK) return
        end do
    end subroutine hertzdamp_dem_advance

    !> Close a run: final state, energy and the trace trimmed to the samples taken.
    pure subroutine hertzdamp_dem_finish(sc, st, res)
        type(hertzdamp_dem_scene), intent(in) :: sc      !! the scene given to hertzdamp_dem_start
        type(hertzdamp_dem_state), intent(in) :: st      !! state of the run
        type(hertzdamp_dem_result), intent(inout) :: res !! completed result
        res%steps = st%step
        res%energy_final = st%energy
        res%contacts = res%contacts(1:res%ncontacts)
        res%t_trace = res%t_trace(1:st%nsamples)
        res%x_trace = res%x_trace(1:st%nsamples, :)
        res%v_trace = res%v_trace(1:st%nsamples, :)
        res%max_speed_final = maxval(norm2(st%v, dim=1))
        res%at_rest = res%max_speed_final < sc%rest_speed
        res%x_final = st%x
        res%v_final = st%v
    end subroutine hertzdamp_dem_finish

    !> One time step: the phases in order.
    pure subroutine one_step(sc, st, res)
        type(hertzdamp_dem_scene), intent(in) :: sc
        type(hertzdamp_dem_state), intent(inout) :: st
        type(hertzdamp_dem_result), intent(inout) :: res
        real(wp) :: t
        t = st%step * st%dt
        call drift(st)
        call contact_forces(sc, st, res, t)
        call wall_onsets(sc, st, res, t)
        if (res%status /= HD_OK) return
        call neighbour_search(st)
        call pair_onsets(sc, st, res, t)
        if (res%status /= HD_OK) return
        call binary_flags(st, res)
        call closing_kick(st, res, t)
        st%step = st%step + 1
        call monitors(sc, st, res)
        if (res%status /= HD_OK) return
        call sample(st, res)
    end subroutine one_step

    ! ------------------------------------------------------------------ phases

    !> Opening half kick and drift; the velocities predicted at the new positions
    !> for the damping force; the step's accumulators cleared.
    pure subroutine drift(st)
        type(hertzdamp_dem_state), intent(inout) :: st
        real(wp) :: dt
        dt = st%dt
        st%x_start = st%x
        st%v_start = st%v
        select case (st%scheme)
        case (HD_HOST_LAMMPS)
            st%v_half = st%v + 0.5_wp * dt * st%acc
            st%x = st%x + dt * st%v_half
            st%v_pred = st%v_half
        case (HD_HOST_MFIX_EULER)
            st%v_half = st%v + dt * st%acc
            st%x = st%x + dt * st%v_half
            st%v_pred = st%v_half
        case (HD_HOST_MFIX_AB2)
            st%v_half = st%v + 0.5_wp * dt * (3.0_wp * st%acc - st%acc_prev)
            st%x = st%x + 0.5_wp * dt * (st%v + st%v_half)
            st%v_pred = st%v_half
        case default
            st%v_half = st%v + 0.5_wp * dt * st%acc
            st%x = st%x + dt * st%v_half
            st%v_pred = st%v_half + 0.5_wp * dt * st%acc + 0.5_wp * dt * (st%acc - st%acc_prev)
        end select
        st%force = 0.0_wp
        st%dv = 0.0_wp
        st%ncontact = 0
        st%nended = 0
        st%epot = 0.0_wp
    end subroutine drift

    !> Forces of the contacts in progress, and their end: a contact whose overlap is
    !> gone closes (with the impulse correction of the part of the step in contact);
    !> with the force end, a contact whose force reaches zero is released; a released
    !> contact closes when its overlap vanishes or the bodies approach again.
    pure subroutine contact_forces(sc, st, res, t)
        type(hertzdamp_dem_scene), intent(in) :: sc
        type(hertzdamp_dem_state), intent(inout) :: st
        type(hertzdamp_dem_result), intent(inout) :: res
        real(wp), intent(in) :: t                  !! time at the start of the step [s]
        integer :: kk, c
        real(wp) :: zeta, zdot, nv(3), fn, phi, fh, dt, us
        dt = st%dt
        kk = 1
        do while (kk <= st%nactive)
            c = st%active(kk)
            associate (ct => res%contacts(c))
                call geometry(sc, st, ct%i, ct%j, st%x, st%v_pred, ct%n_last, zeta, zdot, nv)
                if (ct%state == HD_CONTACT_RELEASED) then
                    ! released at the force zero: closed when the overlap vanishes or
                    ! when the bodies approach again (zeta' > 0, e.g. pulled back by
                    ! gravity before the overlap is gone); an approach then starts a
                    ! new contact below, with its own k and d from the rule.
                    if (zeta <= 0.0_wp .or. zdot > 0.0_wp) then
                        call close_contact(st, res, kk)
                        cycle
                    end if
                    kk = kk + 1
                    cycle
                end if
                if (st%scheme /= HD_HOST_VERLET) then
                    ! a host scheme: no impulse corrections; the end instants interpolated
                    ! linearly in the overlap or in the force between the last two steps
                    if (zeta <= 0.0_wp) then
                        call mark_ended(st, ct, c, t + overlap_fraction(ct%zeta_last, zeta, 0.0_wp) * dt, &
                                        HD_CONTACT_CLOSED)
                        call close_contact(st, res, kk)
                        cycle
                    end if
                    fn = ct%k * zeta * sqrt(zeta) + ct%d * law_power(zeta, st%q) * zdot
                    if (sc%iend == HD_END_FORCE .and. fn <= 0.0_wp) then
                        call mark_ended(st, ct, c, t + ct%f_last / (ct%f_last - fn) * dt, HD_CONTACT_RELEASED)
                        kk = kk + 1
                        cycle
                    end if
                end if
                if (zeta <= 0.0_wp .and. sc%iend == HD_END_FORCE .and. ct%d * zdot < 0.0_wp) then
                    ! force end, and the step jumped over the force zero and the overlap
                    ! zero: the contact ended at the force zero, before the overlap zero
                    call end_at_force_zero(st, ct, c, force_zero_model(ct%k, ct%d, st%q, ct%zeta_last, ct%zdot_last, &
                                                                       zeta, zdot), t, HD_CONTACT_CLOSED)
                    call close_contact(st, res, kk)
                    cycle
                end if
                if (zeta <= 0.0_wp) then
                    ! overlap gone (the overlap end; with the force end when a step jumps
                    ! over the overlap zero with a force still positive).  In contact for
                    ! the fraction phi of the step: the damping part of the last force
                    ! (~ zeta^q, zeta -> 0 linearly) acts for phi/(1+q) dt, its Hertz part
                    ! for 2/5 phi dt; the opening kick gave both dt/2.  Then the error of
                    ! the trapezoidal impulse of the earlier steps, which depends on phi:
                    ! Hertz and, for q > 0, damping (trapezoid_error).
                    phi = overlap_fraction(ct%zeta_last, zeta, 0.0_wp)
                    us = max(ct%zeta_last - zeta, 0.0_wp) / dt   ! separation speed
                    fh = ct%k * max(ct%zeta_last, 0.0_wp)**1.5_wp
                    call add_impulse(st, ct%i, ct%j, ((ct%f_last - fh) * (phi / (1.0_wp + st%q) - 0.5_wp) &
                                                      + fh * (0.4_wp * phi - 0.5_wp)) &
                                     * dt - start_error(phi) * ct%k * us**1.5_wp * dt**2.5_wp, ct%n_last)
                    ! the damping force -d (us s)^q us, s the time left to the end
                    if (st%q > 0.0_wp) call add_impulse(st, ct%i, ct%j, trapezoid_error(st%q, phi) * ct%d &
                                                        * us * law_power(us, st%q) * dt * law_power(dt, st%q), ct%n_last)
                    call mark_ended(st, ct, c, t + phi * dt, HD_CONTACT_CLOSED)
                    call close_contact(st, res, kk)
                    cycle
                end if
                fn = ct%k * zeta * sqrt(zeta) + ct%d * law_power(zeta, st%q) * zdot
                if (sc%iend == HD_END_FORCE .and. fn <= 0.0_wp) then
                    call end_at_force_zero(st, ct, c, force_zero_model(ct%k, ct%d, st%q, ct%zeta_last, ct%zdot_last, &
                                                                       zeta, zdot), t, HD_CONTACT_RELEASED)
                    kk = kk + 1
                    cycle
                end if
                call apply_force(st, ct%i, ct%j, fn, nv)
                st%epot = st%epot + 0.4_wp * ct%k * zeta**2 * sqrt(zeta)
                ct%f_last = fn
                ct%zeta_last = zeta
                ct%zdot_last = zdot
                ct%n_last = nv
            end associate
            kk = kk + 1
        end do
    end subroutine contact_forces

    !> Fraction of the step before the force zero of a contact, with the overlap and its
    !> rate linear in time over the step (zl, vl at its start, ze, ve at its end): the
    !> zero of G(s) = k z(s)^(3/2 - q) + d v(s) = F/z^q, found by bisection (60 halvings).
    !> Near the end of a nearly elastic contact the force zero falls close to the overlap
    !> zero, where F ~ k (u s)^(3/2) - d (u s)^q u is far from linear over a step; z and v
    !> are smooth there, and G is F without its factor z^q, which vanishes at the
    !> overlap zero.  G(0) > 0 (the last force was positive); at the end of the search
    !> interval (the step end, or the overlap zero when the step passes it) G < 0.
    pure real(wp) function force_zero_model(k, d, q, zl, vl, ze, ve) result(phi)
        real(wp), intent(in) :: k, d, q, zl, vl, ze, ve
        real(wp) :: lo, hi, mid
        integer :: it
        lo = 0.0_wp
        hi = 1.0_wp
        if (ze <= 0.0_wp .and. zl - ze > 0.0_wp) hi = zl / (zl - ze)
        if (g(hi) > 0.0_wp) then   ! no sign change (round-off): the end of the interval
            phi = hi
            return
        end if
        do it = 1, 60
            mid = 0.5_wp * (lo + hi)
            if (g(mid) > 0.0_wp) then
                lo = mid
            else
                hi = mid
            end if
        end do
        phi = 0.5_wp * (lo + hi)
    contains
        pure real(wp) function g(s)
            real(wp), intent(in) :: s
            g = k * max(zl + s * (ze - zl), 0.0_wp)**(1.5_wp - q) + d * (vl + s * (ve - vl))
        end function g
    end function force_zero_model

    !> Fraction of the step before the overlap falls to z0, interpolated linearly
    !> between zeta_last (start of the step) and zeta (its end), within [0, 1].
    pure real(wp) function overlap_fraction(zeta_last, zeta, z0) result(phi)
        real(wp), intent(in) :: zeta_last, zeta, z0
        phi = 0.0_wp
        if (zeta_last - zeta > 0.0_wp) phi = min(1.0_wp, max(0.0_wp, (zeta_last - z0) / (zeta_last - zeta)))
    end function overlap_fraction

    !> End contact c at the force zero, a fraction phi of the step after its start,
    !> with the impulse correction (the opening kick gave the last force for dt/2; it
    !> acted, falling linearly, for phi dt); the contact goes to new_state and into the
    !> list of contacts ended in the step.
    pure subroutine end_at_force_zero(st, ct, c, phi, t, new_state)
        type(hertzdamp_dem_state), intent(inout) :: st
        type(hertzdamp_dem_contact), intent(inout) :: ct
        integer, intent(in) :: c, new_state
        real(wp), intent(in) :: phi, t
        call add_impulse(st, ct%i, ct%j, ct%f_last * (phi - 1.0_wp) * 0.5_wp * st%dt, ct%n_last)
        call mark_ended(st, ct, c, t + phi * st%dt, new_state)
    end subroutine end_at_force_zero

    !> Contact c ended at t_end: it goes to new_state and into the list of contacts ended
    !> in the step (their separation speeds are taken by the closing kick).
    pure subroutine mark_ended(st, ct, c, t_end, new_state)
        type(hertzdamp_dem_state), intent(inout) :: st
        type(hertzdamp_dem_contact), intent(inout) :: ct
        integer, intent(in) :: c, new_state
        real(wp), intent(in) :: t_end
        ct%t_end = t_end
        ct%state = new_state
        call push(st%ended, st%nended, c)
    end subroutine mark_ended

    !> New contacts of particles with walls.
    pure subroutine wall_onsets(sc, st, res, t)
        type(hertzdamp_dem_scene), intent(in) :: sc
        type(hertzdamp_dem_state), intent(inout) :: st
        type(hertzdamp_dem_result), intent(inout) :: res
        real(wp), intent(in) :: t
        integer :: w, i
        real(wp) :: zeta, zeta_prev
        do w = 1, size(sc%wall)
            do i = 1, st%n
                if (st%wall_contact(i, w) /= 0) cycle
                zeta = st%rad(i) - dot_product(st%x(:, i) - sc%wall(w)%point, sc%wall(w)%normal)
                if (zeta > 0.0_wp) then
                    zeta_prev = st%rad(i) - dot_product(st%x_start(:, i) - sc%wall(w)%point, sc%wall(w)%normal)
                    call start_contact(sc, st, res, t, i, -w, zeta, zeta_prev)
                    if (res%status /= HD_OK) return
                end if
            end do
        end do
    end subroutine wall_onsets

    !> The neighbour list is rebuilt when a particle has moved by half the skin
    !> since the last build.
    pure subroutine neighbour_search(st)
        type(hertzdamp_dem_state), intent(inout) :: st
        if (maxval(sum((st%x - st%x_built)**2, dim=1)) > (0.5_wp * st%skin)**2) call build_neighbours(st)
    end subroutine neighbour_search

    !> New contacts of the pairs of the neighbour list.
    pure subroutine pair_onsets(sc, st, res, t)
        type(hertzdamp_dem_scene), intent(in) :: sc
        type(hertzdamp_dem_state), intent(inout) :: st
        type(hertzdamp_dem_result), intent(inout) :: res
        real(wp), intent(in) :: t
        integer :: p, i, j
        real(wp) :: zeta, zeta_prev
        do p = 1, st%nneighbours
            i = st%nb_i(p)
            j = st%nb_j(p)
            if (st%pair_contact(pair_index(i, j)) /= 0) cycle
            zeta = st%rad(i) + st%rad(j) - norm2(st%x(:, j) - st%x(:, i))
            if (zeta > 0.0_wp) then
                zeta_prev = st%rad(i) + st%rad(j) - norm2(st%x_start(:, j) - st%x_start(:, i))
                call start_contact(sc, st, res, t, i, j, zeta, zeta_prev)
                if (res%status /= HD_OK) return
            end if
        end do
    end subroutine pair_onsets

    !> A contact acting in this step is not binary when either body has another.
    pure subroutine binary_flags(st, res)
        type(hertzdamp_dem_state), intent(in) :: st
        type(hertzdamp_dem_result), intent(inout) :: res
        integer :: kk
        do kk = 1, st%nactive
            associate (ct => res%contacts(st%active(kk)))
                if (ct%state == HD_CONTACT_ACTIVE) then
                    if (st%ncontact(ct%i) > 1) ct%binary = .false.
                    if (ct%j > 0) then
                        if (st%ncontact(ct%j) > 1) ct%binary = .false.
                    end if
                end if
            end associate
        end do
    end subroutine binary_flags

    !> Closing half kick with the new accelerations and the impulse corrections; the
    !> separation speed of each contact that ended in this step, taken back from the
    !> step end to its end instant by the remaining forces (gravity, other contacts).
    pure subroutine closing_kick(st, res, t)
        type(hertzdamp_dem_state), intent(inout) :: st
        type(hertzdamp_dem_result), intent(inout) :: res
        real(wp), intent(in) :: t
        integer :: i, kk
        real(wp) :: lag, ahead
        real(wp), allocatable :: vf(:, :)
        st%acc_prev = st%acc
        do i = 1, st%n
            st%acc(:, i) = st%g + st%force(:, i) / st%mass(i)
        end do
        select case (st%scheme)
        case (HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2)
            st%v = st%v_half   ! the kick of this step's force comes with the next drift
        case (HD_HOST_LAMMPS)
            st%v = st%v_half + 0.5_wp * st%dt * st%acc
        case default
            st%v = st%v_half + 0.5_wp * st%dt * st%acc + st%dv
        end select
        if (st%nended == 0) return
        ! the velocities once no force of the ended contacts acts any more (mfix-ab2: after
        ! the next step's kick, which still has the last contact acceleration in a_old),
        ! and from when
        ahead = 0.0_wp
        vf = st%v
        if (st%scheme == HD_HOST_MFIX_AB2) then
            ahead = st%dt
            vf = st%v + 0.5_wp * st%dt * (3.0_wp * st%acc - st%acc_prev)
        end if
        do kk = 1, st%nended
            associate (ct => res%contacts(st%ended(kk)), v => vf, a => st%acc)
                lag = t + st%dt + ahead - ct%t_end   ! from the end instant to when v holds [s]
                if (ct%j > 0) then
                    ct%u_out = dot_product(v(:, ct%j) - lag * a(:, ct%j) - v(:, ct%i) + lag * a(:, ct%i), ct%n_last)
                else
                    ct%u_out = -dot_product(v(:, ct%i) - lag * a(:, ct%i), ct%n_last)
                end if
            end associate
        end do
    end subroutine closing_kick

    !> Energy (and its largest rise above the running minimum), momentum drift,
    !> particles leaving the domain; a run whose energy, momentum or positions stop
    !> being finite ends with HD_OUT_OF_RANGE.
    pure subroutine monitors(sc, st, res)
        type(hertzdamp_dem_scene), intent(in) :: sc
        type(hertzdamp_dem_state), intent(inout) :: st
        type(hertzdamp_dem_result), intent(inout) :: res
        integer :: i
        real(wp) :: p(3)
        character(len=24) :: b1, b2
        st%energy = total_energy(st) + st%epot
        res%energy_rise = max(res%energy_rise, st%energy - st%energy_min)
        st%energy_min = min(st%energy_min, st%energy)
        p = momentum(st)
        res%momentum_drift = max(res%momentum_drift, norm2(p - res%momentum0))
        if (.not. (abs(st%energy) <= huge(1.0_wp) .and. all(abs(p) <= huge(1.0_wp)) .and. &
                   all(abs(st%x) <= huge(1.0_wp)))) then
            res%status = HD_OUT_OF_RANGE
            write (b1, '(i0)') st%step
            write (b2, '(es12.5)') st%step * st%dt
            res%message = 'step ' // trim(b1) // ' (t = ' // trim(adjustl(b2)) // ' s): the energy, momentum or ' // &
                          'positions are no longer finite: ' // hertzdamp_message(HD_OUT_OF_RANGE)
            return
        end if
        if (sc%has_domain) then
            do i = 1, st%n
                if (.not. st%gone(i)) then
                    if (any(st%x(:, i) < sc%domain_lo .or. st%x(:, i) > sc%domain_hi)) then
                        st%gone(i) = .true.
                        res%left_domain = res%left_domain + 1
                    end if
                end if
            end do
        end if
    end subroutine monitors

    !> A trace sample every `every` steps.
    pure subroutine sample(st, res)
        type(hertzdamp_dem_state), intent(inout) :: st
        type(hertzdamp_dem_result), intent(inout) :: res
        if (mod(st%step, st%every) == 0 .and. st%nsamples < size(res%t_trace)) then
            st%nsamples = st%nsamples + 1
            res%t_trace(st%nsamples) = st%step * st%dt
            res%x_trace(st%nsamples, :) = st%x(res%axis, 1:st%ntraced)
            res%v_trace(st%nsamples, :) = st%v(res%axis, 1:st%ntraced)
        end if
    end subroutine sample

    ! ------------------------------------------------------------------ contact onset

    !> A new contact between particle i and j (j < 0: wall -j) whose overlap is
    !> zeta at the end of the step and zeta_prev at its start: the touch instant,
    !> the impact velocity there, k and d from the rule, the first force with the
    !> impulse correction of the part of the step in contact; the contact is
    !> recorded in res%contacts and entered in the active list and lookup tables.
    pure subroutine start_contact(sc, st, res, t, i, j, zeta, zeta_prev)
        type(hertzdamp_dem_scene), intent(in) :: sc
        type(hertzdamp_dem_state), intent(inout) :: st
        type(hertzdamp_dem_result), intent(inout) :: res
        real(wp), intent(in) :: t                    !! time at the start of the step [s]
        integer, intent(in) :: i, j                  !! bodies (j < 0: wall -j)
        real(wp), intent(in) :: zeta, zeta_prev      !! overlap at the end and at the start of the step [m]
        type(hertzdamp_dem_contact) :: ct
        real(wp) :: before, in_contact, z, zdot, nv(3), va(3), r_eff, fn, fh, fd, u, dt, phi
        integer :: status, mb
        dt = st%dt
        ! fraction of the step before the touch, and the velocities then
        if (zeta_prev >= 0.0_wp .or. zeta <= zeta_prev) then
            before = 0.0_wp   ! touching at the start of the step already
        else
            before = min(1.0_wp, -zeta_prev / (zeta - zeta_prev))
        end if
        in_contact = 1.0_wp - before
        ct%i = i
        ct%j = j
        ! effective mass and radius, k_phys from the core (hertzdamp_materials)
        if (j > 0) then
            call hertzdamp_effective_mass(st%mass(i), st%mass(j), ct%m, status)
            if (status == HD_OK) call hertzdamp_effective_radius(st%rad(i), st%rad(j), r_eff, status)
            mb = sc%pmat(j)
            va = (st%v_start(:, j) + before * dt * st%acc(:, j)) - (st%v_start(:, i) + before * dt * st%acc(:, i))
        else
            ct%m = st%mass(i)
            r_eff = st%rad(i)
            status = HD_OK
            mb = sc%wall(-j)%material
            va = -(st%v_start(:, i) + before * dt * st%acc(:, i))
        end if
        if (status == HD_OK) call hertzdamp_hertz_stiffness(st%estar(sc%pmat(i), mb), r_eff, ct%k_phys, status)
        call geometry(sc, st, i, j, st%x, st%v_pred, onset_normal(sc, st, i, j), z, zdot, nv)
        u = -dot_product(va, nv)
        ct%u_in = u
        ct%u_rule = max(u, sc%rest_speed, hertzdamp_dem_u_floor)
        ct%e_target = st%e_pair(sc%pmat(i), mb)
        if (status == HD_OK) then
            if (st%host_rule .and. sc%onset_phase) then
                ! the contact's onset phase: its first overlap over one step of approach
                call hertzdamp_onset_phase(z, ct%u_rule, dt, phi, status)
                if (status == HD_OK) call hertzdamp_dem_host_rule(st%pair(sc%pmat(i), mb), st%tc_wanted, ct%m, &
                                                                  ct%u_rule, ct%k_phys, ct%k, ct%d, ct%tc_target, &
                                                                  ct%bound_active, status, phi=phi)
            else if (st%host_rule) then
                call hertzdamp_dem_host_rule(st%pair(sc%pmat(i), mb), st%tc_wanted, ct%m, ct%u_rule, ct%k_phys, ct%k, &
                                             ct%d, ct%tc_target, ct%bound_active, status)
            else
                call hertzdamp_dem_rule(ct%e_target, st%tc_wanted, ct%m, ct%u_rule, ct%k_phys, sc%iend, sc%law, &
                                        st%method, sc%want_duration, st%tol, ct%k, ct%d, ct%tc_target, &
                                        ct%bound_active, status)
            end if
        end if
        if (status /= HD_OK) then
            res%status = status
            res%message = contact_name(i, j) // ' at t = ' // real_text(t + before * dt) // ': ' // hertzdamp_message(status)
            return
        end if
        ct%t_start = t + before * dt
        ct%state = HD_CONTACT_ACTIVE
        fh = ct%k * z**1.5_wp
        fd = ct%d * law_power(z, st%q) * zdot
        fn = fh + fd
        ! in contact for the fraction in_contact of this step only: the damping force
        ! (~ zeta^q, zeta growing linearly) acts for in_contact/(1+q) dt, the Hertz
        ! force for 2/5 in_contact dt; the closing kick gives both dt/2.  Then the
        ! error of the trapezoidal impulse of the later steps, which depends on
        ! in_contact: Hertz and, for q > 0, damping d (u s)^q u (trapezoid_error).
        if (st%scheme == HD_HOST_VERLET) then
            call add_impulse(st, i, j, (fd * (in_contact / (1.0_wp + st%q) - 0.5_wp) + fh * (0.4_wp * in_contact &
                             - 0.5_wp)) * dt - start_error(in_contact) * ct%k * max(u, 0.0_wp)**1.5_wp * dt**2.5_wp, nv)
            if (st%q > 0.0_wp) call add_impulse(st, i, j, -trapezoid_error(st%q, in_contact) * ct%d * max(u, 0.0_wp) &
                                                * law_power(max(u, 0.0_wp), st%q) * dt * law_power(dt, st%q), nv)
        end if
        call apply_force(st, i, j, fn, nv)
        st%epot = st%epot + 0.4_wp * ct%k * z**2 * sqrt(z)
        ct%f_last = fn
        ct%zeta_last = z
        ct%zdot_last = zdot
        ct%n_last = nv
        call push_contact(res, ct)
        call push(st%active, st%nactive, res%ncontacts)
        if (j > 0) then
            st%pair_contact(pair_index(i, j)) = res%ncontacts
        else
            st%wall_contact(i, -j) = res%ncontacts
        end if
    end subroutine start_contact

    !> The per-pair constants of sc%host for every material pair that can meet
    !> (hertzdamp_pair_init at N = steps_per_contact); a failure ends the run before its
    !> start with a message naming the pair (and, when N is too small, the N that can).
    pure subroutine host_pairs(sc, st, res)
        type(hertzdamp_dem_scene), intent(in) :: sc
        type(hertzdamp_dem_state), intent(inout) :: st
        type(hertzdamp_dem_result), intent(inout) :: res
        logical, allocatable :: met(:, :)
        integer :: a, b, status, nmin, st_min
        type(hertzdamp_host_stats) :: stats
        call hertzdamp_dem_pairs_met(sc, met)
        allocate (st%pair(size(sc%mat), size(sc%mat)))
        do a = 1, size(sc%mat)
            do b = a, size(sc%mat)
                if (.not. met(a, b)) cycle
                call hertzdamp_pair_init(st%e_pair(a, b), sc%law, sc%iend, sc%host, real(sc%steps_per_contact, wp), &
                                         st%pair(a, b), status, stats, phase=sc%onset_phase)
                st%pair(b, a) = st%pair(a, b)
                if (status == HD_OK) then
                    res%host_e_dev = max(res%host_e_dev, (stats%e_max - stats%e_mean) / stats%e_mean, &
                                         (stats%e_mean - stats%e_min) / stats%e_mean)
                    res%host_tc_dev = max(res%host_tc_dev, (stats%tau_max - stats%tau_mean) / stats%tau_mean, &
                                          (stats%tau_mean - stats%tau_min) / stats%tau_mean)
                end if
                if (status == HD_OK .or. res%status /= HD_OK) cycle
                res%status = status
                res%message = 'material pair ' // trim(sc%mat(a)%name) // ' - ' // trim(sc%mat(b)%name) // &
                              ', host ' // hertzdamp_host_name(sc%host) // ': ' // hertzdamp_message(status)
                if (status /= HD_HOST_UNREACHABLE) cycle
                call hertzdamp_host_min_steps(st%e_pair(a, b), sc%law, sc%iend, sc%host, nmin, st_min)
                if (st_min /= HD_OK) cycle
                res%message = 'material pair ' // trim(sc%mat(a)%name) // ' - ' // trim(sc%mat(b)%name) // ': N = ' // &
                              int_text(sc%steps_per_contact) // ' steps cannot reach e = ' // &
                              fmt_short(st%e_pair(a, b)) // ' with ' // hertzdamp_host_name(sc%host) // '; N >= ' // &
                              int_text(nmin) // ' can'
            end do
        end do
    end subroutine host_pairs

    !> Normal used at onset when the centres coincide at the end of the step: the
    !> direction between the centres at the start of the step, else +x.
    pure function onset_normal(sc, st, i, j) result(nv)
        type(hertzdamp_dem_scene), intent(in) :: sc
        type(hertzdamp_dem_state), intent(in) :: st
        integer, intent(in) :: i, j
        real(wp) :: nv(3)
        real(wp) :: dd
        if (j > 0) then
            nv = st%x_start(:, j) - st%x_start(:, i)
            dd = norm2(nv)
            if (dd > 0.0_wp) then
                nv = nv / dd
            else
                nv = [1.0_wp, 0.0_wp, 0.0_wp]
            end if
        else
            nv = -sc%wall(-j)%normal
        end if
    end function onset_normal

    !> 'contact of particles i and j' or 'contact of particle i with wall w'.
    pure function contact_name(i, j) result(s)
        integer, intent(in) :: i, j
        character(len=:), allocatable :: s
        character(len=80) :: b
        if (j > 0) then
            write (b, '(a,i0,a,i0)') 'contact of particles ', i, ' and ', j
        else
            write (b, '(a,i0,a,i0)') 'contact of particle ', i, ' with wall ', -j
        end if
        s = trim(b)
    end function contact_name

    pure function real_text(x) result(s)
        real(wp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=24) :: b
        write (b, '(es12.5)') x
        s = trim(adjustl(b))
    end function real_text

    ! ------------------------------------------------------------------ helpers

    !> Overlap z, its rate zd (with the velocities vv) and the normal nn (from i to
    !> j, or out of the wall's side for a wall).  Centres that coincide get the
    !> normal `fallback`.
    pure subroutine geometry(sc, st, i, j, xx, vv, fallback, z, zd, nn)
        type(hertzdamp_dem_scene), intent(in) :: sc
        type(hertzdamp_dem_state), intent(in) :: st
        integer, intent(in) :: i, j
        real(wp), intent(in) :: xx(:, :), vv(:, :), fallback(3)
        real(wp), intent(out) :: z, zd, nn(3)
        real(wp) :: dd
        if (j > 0) then
            nn = xx(:, j) - xx(:, i)
            dd = norm2(nn)
            if (dd > 0.0_wp) then
                nn = nn / dd
            else
                nn = fallback
            end if
            z = st%rad(i) + st%rad(j) - dd
            zd = -dot_product(vv(:, j) - vv(:, i), nn)
        else
            nn = -sc%wall(-j)%normal
            z = st%rad(i) - dot_product(xx(:, i) - sc%wall(-j)%point, sc%wall(-j)%normal)
            zd = dot_product(vv(:, i), nn)
        end if
    end subroutine geometry

    !> Force fn (repulsive > 0) along nn: on j (or nothing, wall) +fn nn, on i -fn nn.
    pure subroutine apply_force(st, i, j, fn, nn)
        type(hertzdamp_dem_state), intent(inout) :: st
        integer, intent(in) :: i, j
        real(wp), intent(in) :: fn, nn(3)
        st%force(:, i) = st%force(:, i) - fn * nn
        st%ncontact(i) = st%ncontact(i) + 1
        if (j > 0) then
            st%force(:, j) = st%force(:, j) + fn * nn
            st%ncontact(j) = st%ncontact(j) + 1
        end if
    end subroutine apply_force

    !> Impulse correction jn (repulsive > 0) along nn, added after the closing kick.
    pure subroutine add_impulse(st, i, j, jn, nn)
        type(hertzdamp_dem_state), intent(inout) :: st
        integer, intent(in) :: i, j
        real(wp), intent(in) :: jn, nn(3)
        st%dv(:, i) = st%dv(:, i) - jn * nn / st%mass(i)
        if (j > 0) st%dv(:, j) = st%dv(:, j) + jn * nn / st%mass(j)
    end subroutine add_impulse

    !> Remove active(k) from the active list and the lookup tables.
    pure subroutine close_contact(st, res, k)
        type(hertzdamp_dem_state), intent(inout) :: st
        type(hertzdamp_dem_result), intent(in) :: res
        integer, intent(in) :: k
        integer :: c
        c = st%active(k)
        if (res%contacts(c)%j > 0) then
            st%pair_contact(pair_index(res%contacts(c)%i, res%contacts(c)%j)) = 0
        else
            st%wall_contact(res%contacts(c)%i, -res%contacts(c)%j) = 0
        end if
        st%active(k) = st%active(st%nactive)
        st%nactive = st%nactive - 1
    end subroutine close_contact

    !> Append value to list(1:n), doubling the list when full.
    pure subroutine push(list, n, value)
        integer, allocatable, intent(inout) :: list(:)
        integer, intent(inout) :: n
        integer, intent(in) :: value
        integer, allocatable :: grown(:)
        if (n == size(list)) then
            allocate (grown(2 * max(n, 1)))
            grown(1:n) = list(1:n)
            call move_alloc(grown, list)
        end if
        n = n + 1
        list(n) = value
    end subroutine push

    !> Append a contact to res%contacts, doubling the array when full.
    pure subroutine push_contact(res, ct)
        type(hertzdamp_dem_result), intent(inout) :: res
        type(hertzdamp_dem_contact), intent(in) :: ct
        type(hertzdamp_dem_contact), allocatable :: grown(:)
        if (res%ncontacts == size(res%contacts)) then
            allocate (grown(2 * max(res%ncontacts, 1)))
            grown(1:res%ncontacts) = res%contacts(1:res%ncontacts)
            call move_alloc(grown, res%contacts)
        end if
        res%ncontacts = res%ncontacts + 1
        res%contacts(res%ncontacts) = ct
    end subroutine push_contact

    !> Index of the particle pair (i, j), i /= j, in a packed triangular table.
    pure integer function pair_index(i, j)
        integer, intent(in) :: i, j
        integer :: lo, hi
        lo = min(i, j)
        hi = max(i, j)
        pair_index = (hi - 1) * (hi - 2) / 2 + lo
    end function pair_index

    !> Neighbour list: the pairs closer than r_i + r_j + skin, found by a sweep
    !> along the axis over the particles sorted by that coordinate.
    pure subroutine build_neighbours(st)
        type(hertzdamp_dem_state), intent(inout) :: st
        integer :: p1, p2, i, j, ax
        ax = st%axis
        call sort_along_axis(st)
        st%nneighbours = 0
        do p1 = 1, st%n - 1
            i = st%perm(p1)
            do p2 = p1 + 1, st%n
                j = st%perm(p2)
                if (st%x(ax, j) - st%x(ax, i) > st%rad(i) + st%rmax + st%skin) exit
                if (norm2(st%x(:, j) - st%x(:, i)) > st%rad(i) + st%rad(j) + st%skin) cycle
                call push_pair(st, min(i, j), max(i, j))
            end do
        end do
        st%x_built = st%x
    end subroutine build_neighbours

    !> Append the pair (i, j) to the neighbour list, doubling it when full.
    pure subroutine push_pair(st, i, j)
        type(hertzdamp_dem_state), intent(inout) :: st
        integer, intent(in) :: i, j
        integer :: n
        n = st%nneighbours
        call push(st%nb_i, n, i)
        n = st%nneighbours
        call push(st%nb_j, n, j)
        st%nneighbours = n
    end subroutine push_pair

    !> Insertion sort of perm by position along the axis (nearly sorted: linear time).
    pure subroutine sort_along_axis(st)
        type(hertzdamp_dem_state), intent(inout) :: st
        integer :: i, j, key, ax
        ax = st%axis
        do i = 2, st%n
            key = st%perm(i)
            j = i - 1
            do while (j >= 1)
                if (st%x(ax, st%perm(j)) <= st%x(ax, key)) exit
                st%perm(j + 1) = st%perm(j)
                j = j - 1
            end do
            st%perm(j + 1) = key
        end do
    end subroutine sort_along_axis

    !> Kinetic + gravitational energy; the contact energy sum of 2/5 k zeta^(5/2)
    !> (epot) is added by the caller.
    pure real(wp) function total_energy(st) result(en)
        type(hertzdamp_dem_state), intent(in) :: st
        integer :: i
        en = 0.0_wp
        do i = 1, st%n
            en = en + 0.5_wp * st%mass(i) * sum(st%v(:, i)**2) - st%mass(i) * dot_product(st%g, st%x(:, i))
        end do
    end function total_energy

    pure function momentum(st) result(pm)
        type(hertzdamp_dem_state), intent(in) :: st
        real(wp) :: pm(3)
        integer :: i
        pm = 0.0_wp
        do i = 1, st%n
            pm = pm + st%mass(i) * st%v(:, i)
        end do
    end function momentum

    !> x^q of the damping law by square roots (q = 0, 1/4, 1/2; 1 for q = 0), x >= 0.
    pure elemental real(wp) function law_power(x, q) result(y)
        real(wp), intent(in) :: x, q
        if (q == 0.0_wp) then
            y = 1.0_wp
        else
            y = sqrt(x)
            if (q == 0.25_wp) y = sqrt(y)
        end if
    end function law_power

    !> Error of the trapezoidal impulse of a force c s^p that starts (or ends) a
    !> fraction theta of a step away from a step point (s the time from the touch, or
    !> to the release), in units of c dt^(p+1), when the partial step itself is
    !> integrated exactly:
    !>     g_p(theta) = zeta(-p, theta) + theta^(p+1)/(p+1) - theta^p/2
    !> (zeta(s, a) the Hurwitz zeta function; Euler-Maclaurin for s^p on the grid).
    !> The damping force of the law q near a touch is d (u s)^q u: p = q.  g_0 = 0
    !> (the linear law's damping force is a step, integrated exactly); the Hertz force
    !> is p = 3/2 (start_error, kept as it was so that the linear law's runs stay the
    !> same bit for bit).  g_(1/4)(theta) runs from zeta(-1/4) = -0.3205 (theta -> 0) to
    !> -0.0205 (theta = 1), g_(1/2) from zeta(-1/2) = -0.2079 to -0.0412 (these values to
    !> 1e-10).  The subtracted term is of order dt^(1+q): without it the achieved e and
    !> T_c would converge at order 1 + q only (from this error term; not measured by a
    !> test, the engine has no switch to drop the correction).
    pure elemental real(wp) function trapezoid_error(p, theta) result(gt)
        real(wp), intent(in) :: p       !! exponent of the force, 0 < p < 2
        real(wp), intent(in) :: theta   !! fraction of the step, in [0, 1]
        real(wp) :: a, z
        integer :: j
        z = 0.0_wp
        do j = 0, 7
            z = z + (theta + j)**p
        end do
        a = theta + 8.0_wp
        ! zeta(-p, a) by its Euler-Maclaurin (Bernoulli) expansion at large a: the
        ! terms B_2k/(2k)! (-p)(1-p)...(2k-2-p) a^(p+1-2k), k = 1, 2, 3
        z = z - a**(p + 1.0_wp) / (p + 1.0_wp) + 0.5_wp * a**p - p / 12.0_wp * a**(p - 1.0_wp) &
            + p * (1.0_wp - p) * (2.0_wp - p) / 720.0_wp * a**(p - 3.0_wp) &
            - p * (1.0_wp - p) * (2.0_wp - p) * (3.0_wp - p) * (4.0_wp - p) / 30240.0_wp * a**(p - 5.0_wp)
        gt = z + theta**(p + 1.0_wp) / (p + 1.0_wp) - 0.5_wp * theta**p
    end function trapezoid_error

    !> Error of the trapezoidal (velocity Verlet) impulse of a Hertz force that starts
    !> (or ends) a fraction theta of a step away from a step point, in units of
    !> k u^(3/2) dt^(5/2), when the partial step itself is integrated exactly:
    !>     g(theta) = zeta(-3/2, theta) + (2/5) theta^(5/2) - (1/2) theta^(3/2)
    !> with zeta(s, a) the Hurwitz zeta function (Euler-Maclaurin applied to
    !> (t - t_c)^(3/2) on the grid; -0.0255 at theta -> 0, -0.1255 at theta = 1).
    !> Subtracting g at the contact's start and end removes the O(dt^(5/2)) error term
    !> that depends on where the touch falls inside a step.
    pure elemental real(wp) function start_error(theta) result(gt)
        real(wp), intent(in) :: theta   !! fraction of the step, in [0, 1]
        real(wp) :: a, z
        integer :: j
        z = 0.0_wp
        do j = 0, 7
            z = z + (theta + j)**1.5_wp
        end do
        a = theta + 8.0_wp
        ! zeta(-3/2, a) by its Euler-Maclaurin (Bernoulli) expansion at large a
        z = z - a**2.5_wp / 2.5_wp + 0.5_wp * a**1.5_wp - 0.125_wp * sqrt(a) - 0.375_wp / 720.0_wp * a**(-1.5_wp) &
            + 1.40625_wp / 30240.0_wp * a**(-3.5_wp)
        gt = z + 0.4_wp * theta**2.5_wp - 0.5_wp * theta**1.5_wp
    end function start_error

end module hertzdamp_dem_engine
