!> A compact DEM engine for spheres with normal contact forces only, used to run the
!> scenes of `data/scenes/` (doc/theory.md section 6: the inverse rule at every contact).
!>
!> - Spheres in 3-D (a 1-D column is a scene whose particles lie on one line),
!>   plane walls, optional uniform gravity.  Tangential forces, friction and
!>   rotation are out of scope: every force acts along the line of centres.
!> - Time stepping: velocity Verlet at the scene's dt.  The damping force needs a
!>   velocity at the new positions; the extrapolation v + dt a_n + dt/2 (a_n - a_(n-1))
!>   is used (error O(dt^3); the plain v + dt a costs ten times more accuracy in e
!>   for strongly damped contacts, though both are second order).
!> - At each contact onset (pair or sphere-wall) the contact gets its own k and d
!>   from the inverse rule for its effective mass m and impact normal velocity u_in,
!>   bounded by the material pair's physical Hertz stiffness
!>   k_phys = (4/3) E* sqrt(R*); k and d are kept for the contact's duration.
!>   When the scene wants the restitution only, k = k_phys and only alpha(e) and
!>   d = alpha m^(3/5) k_phys^(2/5) u_in^(1/5) are computed.
!> - Force F = k zeta^(3/2) + d zeta' (repulsive when positive) while in contact.
!>   The contact ends by the scene's definition: overlap (zeta returns to 0) or
!>   force (F returns to 0; the contact is then released and exerts no force).  A
!>   released contact is closed when its overlap vanishes or when the bodies approach
!>   again (zeta' > 0 while still overlapping, as in a slow bounce under gravity);
!>   a renewed approach is then a new contact with its own k and d from the rule
!>   (its impact speed is small, so the rule gets rest_speed).
!> - The contact-start and contact-end instants fall inside a step.  The damping
!>   force jumps there, which would make the scheme first order; both instants are
!>   located by linear interpolation (of the overlap, or of the force) and the
!>   velocity update of that step gets the impulse correction of the part of the
!>   step actually in contact.  The Hertz force ~ (t - t_c)^(3/2) also makes the
!>   trapezoidal impulse of the first and last steps wrong by g(theta) k u^(3/2) dt^(5/2),
!>   theta the fraction of the step in contact; this term (a Hurwitz zeta value,
!>   `start_error`) is subtracted too.  The achieved restitution and contact time are
!>   then second order in dt: measured relative errors below 1/N^2 (e >= 0.5) and
!>   1.6/N^2 (e = 0.3) for N steps per contact; the scene report uses 2/N^2.
!> - Impact velocity u_in: the relative normal velocity interpolated to the onset
!>   instant.  The rule gets max(u_in, rest_speed): a contact that starts slower than
!>   the scene's rest speed (touching particles pushed together gently, as in a chain
!>   or a settling bed) is a resting contact and gets the damping of an impact at
!>   rest_speed (with u_in -> 0 the rule's d ~ u_in^(1/5) would vanish and such
!>   contacts would ring undamped).
!>
!> Material pairs: e = sqrt(e_a e_b) (for a material with itself: its own e).
!> All procedures are pure, keep no state, never print: failures come back as a
!> status (hertzdamp_status codes) and a message.
module hertzdamp_dem
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_OK, HD_NO_REBOUND, HD_BAD_ARGUMENT, HD_BAD_RESTITUTION, HD_END_OVERLAP, HD_END_FORCE, &
                                hertzdamp_message
    use hertzdamp_scaling, only: hertzdamp_expand, hertzdamp_reduce
    use hertzdamp_constants, only: hertzdamp_e1, hertzdamp_tau_c0
    use hertzdamp_rk45, only: hertzdamp_collision, hertzdamp_rk45_collide
    use hertzdamp_methods, only: HD_METHOD_SERIES, HD_METHOD_PADE, HD_METHOD_COMPACT, HD_METHOD_FIT, &
                                 HD_METHOD_ITERATIVE, HD_METHOD_FIRST_ORDER
    use hertzdamp_inverse, only: hertzdamp_invert, hertzdamp_invert_alpha
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Candidate rules of `--method auto`, cheapest first (the documented cost order);
    !> the first-order rule alpha = (1 - e)/e1, tau_c = tau_c(0) is valid for nearly
    !> elastic contacts only.
    integer, parameter, public :: hertzdamp_dem_cost_order(6) = [HD_METHOD_FIRST_ORDER, HD_METHOD_COMPACT, &
        HD_METHOD_SERIES, HD_METHOD_PADE, HD_METHOD_FIT, HD_METHOD_ITERATIVE]
    !> Most particles a scene may hold (the pair table is dense).
    integer, parameter, public :: hertzdamp_dem_max_particles = 2000
    !> Most time steps a scene may take.
    integer, parameter, public :: hertzdamp_dem_max_steps = 20000000
    !> Lower bound of the impact velocity passed to the rule [m s^-1].
    real(wp), parameter, public :: hertzdamp_dem_u_floor = 1.0e-9_wp

    !> One material.
    type, public :: hertzdamp_dem_material
        character(len=32) :: name = ''          !! name used by particles and walls
        real(wp) :: density = 0.0_wp            !! [kg m^-3]
        real(wp) :: youngs_modulus = 0.0_wp     !! [Pa]
        real(wp) :: poisson_ratio = 0.0_wp      !! [-], in (-1, 0.5]
        real(wp) :: restitution = 0.0_wp        !! target restitution, in (0, 1]
    end type hertzdamp_dem_material

    !> One plane wall: the particles stay on the side the normal points to.
    type, public :: hertzdamp_dem_wall
        integer :: material = 0                 !! index into the scene's materials
        real(wp) :: point(3) = 0.0_wp           !! a point of the plane [m]
        real(wp) :: normal(3) = [0.0_wp, 0.0_wp, 1.0_wp] !! unit normal
        integer :: line = 0                     !! source line (for messages)
    end type hertzdamp_dem_wall

    !> A scene: settings, materials, particles, walls.
    type, public :: hertzdamp_dem_scene
        character(len=:), allocatable :: title  !! free text
        real(wp) :: dt = 0.0_wp                 !! time step [s]
        integer :: steps_per_contact = 10       !! N: contact duration T_c = N dt
        real(wp) :: end_time = 0.0_wp           !! [s]
        logical :: gravity = .false.            !! gravity on/off
        real(wp) :: g(3) = [0.0_wp, 0.0_wp, -9.81_wp] !! gravity vector [m s^-2]
        integer :: iend = HD_END_OVERLAP        !! contact-end definition
        logical :: want_duration = .true.       !! report and impose the contact duration
        real(wp) :: accuracy = 1.0e-3_wp        !! relative accuracy wanted of e (and T_c)
        logical :: has_domain = .false.         !! a bounding box is given
        real(wp) :: domain_lo(3) = 0.0_wp       !! box lower corner [m]
        real(wp) :: domain_hi(3) = 0.0_wp       !! box upper corner [m]
        real(wp) :: rest_speed = 1.0e-3_wp      !! at rest when every speed is below; slowest impact given to the rule [m s^-1]
        integer :: samples = 1000               !! trace samples kept (for plots)
        type(hertzdamp_dem_material), allocatable :: mat(:)  !! materials
        integer, allocatable :: pmat(:)         !! material of each particle
        real(wp), allocatable :: radius(:)      !! radius of each particle [m]
        real(wp), allocatable :: x(:, :)        !! initial positions (3, n) [m]
        real(wp), allocatable :: v(:, :)        !! initial velocities (3, n) [m s^-1]
        integer, allocatable :: pline(:)        !! source line of each particle
        type(hertzdamp_dem_wall), allocatable :: wall(:) !! walls
    end type hertzdamp_dem_scene

    !> Record of one contact.
    type, public :: hertzdamp_dem_contact
        integer :: i = 0, j = 0                 !! particles; j < 0: wall -j
        real(wp) :: m = 0.0_wp                  !! effective mass [kg]
        real(wp) :: u_in = 0.0_wp               !! impact normal velocity [m s^-1]
        real(wp) :: u_rule = 0.0_wp             !! velocity given to the rule, max(u_in, rest_speed)
        real(wp) :: k = 0.0_wp                  !! stiffness used [N m^-3/2]
        real(wp) :: d = 0.0_wp                  !! damping used [kg s^-1]
        real(wp) :: k_phys = 0.0_wp             !! physical stiffness bound
        real(wp) :: e_target = 0.0_wp           !! target restitution of the material pair
        real(wp) :: tc_target = 0.0_wp          !! expected contact time [s] (N dt, or physical)
        logical :: bound_active = .false.       !! k = k_phys was used
        real(wp) :: t_start = 0.0_wp            !! onset instant [s]
        real(wp) :: t_end = -1.0_wp             !! end instant [s], < 0 while not ended
        real(wp) :: u_out = 0.0_wp              !! separation normal velocity [m s^-1]
        logical :: binary = .true.              !! no other contact on either body meanwhile
        integer :: state = 1                    !! 1 in contact, 2 released (force end), 3 ended
        real(wp) :: zeta_last = 0.0_wp          !! overlap at the last step
        real(wp) :: f_last = 0.0_wp             !! normal force at the last step
        real(wp) :: n_last(3) = 0.0_wp          !! normal at the last step
    end type hertzdamp_dem_contact

    !> Result of a run.
    type, public :: hertzdamp_dem_result
        integer :: status = HD_OK               !! HD_OK or the failure
        character(len=:), allocatable :: message !! what failed (empty on success)
        integer :: method = HD_METHOD_FIT       !! contact rule used
        integer :: steps = 0                    !! time steps taken
        integer :: ncontacts = 0                !! contacts started
        type(hertzdamp_dem_contact), allocatable :: contacts(:) !! every contact, in order of onset
        real(wp) :: energy0 = 0.0_wp            !! initial total energy [J]
        real(wp) :: energy_final = 0.0_wp       !! final total energy [J]
        real(wp) :: energy_rise = 0.0_wp        !! largest rise of the energy above its running minimum [J]
        real(wp) :: momentum0(3) = 0.0_wp       !! initial momentum [kg m s^-1]
        real(wp) :: momentum_drift = 0.0_wp     !! largest |P(t) - P(0)| [kg m s^-1]
        real(wp) :: momentum_scale = 0.0_wp     !! sum of m |v| at the start (scale of the drift)
        integer :: left_domain = 0              !! particles that left the box
        real(wp) :: max_speed_final = 0.0_wp    !! largest final speed [m s^-1]
        logical :: at_rest = .false.            !! max_speed_final < rest_speed
        integer :: axis = 3                     !! trace axis (1, 2, 3)
        real(wp), allocatable :: t_trace(:)     !! trace times [s]
        real(wp), allocatable :: x_trace(:, :)  !! (sample, particle) position along axis [m]
        real(wp), allocatable :: v_trace(:, :)  !! (sample, particle) velocity along axis [m s^-1]
        real(wp), allocatable :: x_final(:, :)  !! final positions (3, n)
        real(wp), allocatable :: v_final(:, :)  !! final velocities (3, n)
    end type hertzdamp_dem_result

    public :: hertzdamp_dem_check, hertzdamp_dem_run, hertzdamp_dem_rule, hertzdamp_dem_select
    public :: hertzdamp_dem_pair_e, hertzdamp_dem_pair_estar, hertzdamp_dem_pairs_met
    public :: hertzdamp_dem_mass

contains

    !> Mass of a sphere [kg].
    pure elemental real(wp) function hertzdamp_dem_mass(density, radius)
        real(wp), intent(in) :: density  !! [kg m^-3]
        real(wp), intent(in) :: radius   !! [m]
        hertzdamp_dem_mass = density * 4.0_wp / 3.0_wp * acos(-1.0_wp) * radius**3
    end function hertzdamp_dem_mass

    !> Target restitution of a material pair, sqrt(e_a e_b).
    pure real(wp) function hertzdamp_dem_pair_e(a, b)
        type(hertzdamp_dem_material), intent(in) :: a  !! first material
        type(hertzdamp_dem_material), intent(in) :: b  !! second material
        hertzdamp_dem_pair_e = sqrt(a%restitution * b%restitution)
    end function hertzdamp_dem_pair_e

    !> Effective modulus E* of a material pair, 1/E* = (1-nu_a^2)/E_a + (1-nu_b^2)/E_b.
    pure real(wp) function hertzdamp_dem_pair_estar(a, b)
        type(hertzdamp_dem_material), intent(in) :: a  !! first material
        type(hertzdamp_dem_material), intent(in) :: b  !! second material
        hertzdamp_dem_pair_estar = 1.0_wp / ((1.0_wp - a%poisson_ratio**2) / a%youngs_modulus + &
                                             (1.0_wp - b%poisson_ratio**2) / b%youngs_modulus)
    end function hertzdamp_dem_pair_estar

    !> The material pairs that can meet, decided from the layout before the run:
    !> (a, b) of two particles' materials (a = b needs two particles of a), and
    !> (particle material, wall material).  met(a, b) is symmetric.
    pure subroutine hertzdamp_dem_pairs_met(sc, met)
        type(hertzdamp_dem_scene), intent(in) :: sc  !! the scene
        logical, allocatable, intent(out) :: met(:, :) !! (nmat, nmat)
        integer :: nm, a, b, w
        integer, allocatable :: cnt(:)
        nm = size(sc%mat)
        allocate (met(nm, nm), cnt(nm))
        met = .false.
        do a = 1, nm
            cnt(a) = count(sc%pmat == a)
        end do
        do a = 1, nm
            do b = 1, nm
                if (a == b) then
                    met(a, b) = cnt(a) >= 2
                else
                    met(a, b) = cnt(a) >= 1 .and. cnt(b) >= 1
                end if
            end do
        end do
        do w = 1, size(sc%wall)
            b = sc%wall(w)%material
            do a = 1, nm
                if (cnt(a) >= 1) then
                    met(a, b) = .true.
                    met(b, a) = .true.
                end if
            end do
        end do
    end subroutine hertzdamp_dem_pairs_met

    !> Validate a scene: status HD_OK, or HD_BAD_ARGUMENT with a message naming the
    !> offending key and, for particles and walls, their source line.
    pure subroutine hertzdamp_dem_check(sc, status, message)
        type(hertzdamp_dem_scene), intent(in) :: sc       !! the scene
        integer, intent(out) :: status                     !! HD_OK or HD_BAD_ARGUMENT
        character(len=:), allocatable, intent(out) :: message !! empty on success
        integer :: i, j, n, w
        real(wp) :: dist, h
        character(len=24) :: b1, b2
        status = HD_BAD_ARGUMENT
        message = ''
        n = size(sc%radius)
        ! every real value finite first (NaN or Inf would reach the report)
        if (.not. finite(sc%dt)) then
            message = '&scene: dt must be finite'
        else if (.not. finite(sc%end_time)) then
            message = '&scene: end_time must be finite'
        else if (.not. finite(sc%accuracy)) then
            message = '&scene: accuracy must be finite'
        else if (.not. finite(sc%rest_speed)) then
            message = '&scene: rest_speed must be finite'
        else if (.not. all(finite(sc%g))) then
            message = '&scene: g must be finite'
        else if (sc%has_domain .and. .not. all(finite(sc%domain_lo))) then
            message = '&scene: domain_lo must be finite'
        else if (sc%has_domain .and. .not. all(finite(sc%domain_hi))) then
            message = '&scene: domain_hi must be finite'
        end if
        if (len(message) > 0) return
        do i = 1, size(sc%mat)
            associate (mt => sc%mat(i))
                if (.not. finite(mt%density)) then
                    message = 'material ' // trim(mt%name) // ': density must be finite'
                else if (.not. finite(mt%youngs_modulus)) then
                    message = 'material ' // trim(mt%name) // ': youngs_modulus must be finite'
                else if (.not. finite(mt%poisson_ratio)) then
                    message = 'material ' // trim(mt%name) // ': poisson_ratio must be finite'
                else if (.not. finite(mt%restitution)) then
                    message = 'material ' // trim(mt%name) // ': restitution must be finite'
                end if
            end associate
            if (len(message) > 0) return
        end do
        do i = 1, n
            write (b1, '(i0)') sc%pline(i)
            if (.not. finite(sc%radius(i))) then
                message = 'line ' // trim(b1) // ': &particle radius must be finite'
            else if (.not. all(finite(sc%x(:, i)))) then
                message = 'line ' // trim(b1) // ': &particle position must be finite'
            else if (.not. all(finite(sc%v(:, i)))) then
                message = 'line ' // trim(b1) // ': &particle velocity must be finite'
            end if
            if (len(message) > 0) return
        end do
        do w = 1, size(sc%wall)
            write (b2, '(i0)') sc%wall(w)%line
            if (.not. all(finite(sc%wall(w)%point))) then
                message = 'line ' // trim(b2) // ': &wall point must be finite'
            else if (.not. all(finite(sc%wall(w)%normal))) then
                message = 'line ' // trim(b2) // ': &wall normal must be finite'
            end if
            if (len(message) > 0) return
        end do
        if (.not. (sc%dt > 0.0_wp .and. sc%dt < huge(1.0_wp))) then
            message = '&scene: dt must be positive'
        else if (.not. (sc%end_time > 0.0_wp .and. sc%end_time < huge(1.0_wp))) then
            message = '&scene: end_time must be positive'
        else if (sc%end_time / sc%dt > real(hertzdamp_dem_max_steps, wp)) then
            message = '&scene: end_time/dt exceeds the step limit of the scene engine'
        else if (sc%steps_per_contact < 1) then
            message = '&scene: steps_per_contact must be at least 1'
        else if (.not. (sc%accuracy > 0.0_wp .and. sc%accuracy < 1.0_wp)) then
            message = '&scene: accuracy must lie in (0, 1)'
        else if (.not. (sc%rest_speed > 0.0_wp)) then
            message = '&scene: rest_speed must be positive'
        else if (sc%samples < 2) then
            message = '&scene: samples must be at least 2'
        else if (n < 1) then
            message = 'no &particle group: a scene needs at least one particle'
        else if (n > hertzdamp_dem_max_particles) then
            write (b1, '(i0)') hertzdamp_dem_max_particles
            message = 'too many particles (at most ' // trim(b1) // ')'
        end if
        if (len(message) > 0) return
        if (sc%has_domain) then
            if (any(sc%domain_hi <= sc%domain_lo)) then
                message = '&scene: domain_hi must exceed domain_lo in every coordinate'
                return
            end if
        end if
        do i = 1, size(sc%mat)
            associate (mt => sc%mat(i))
                if (.not. (mt%density > 0.0_wp)) then
                    message = 'material ' // trim(mt%name) // ': density must be positive'
                else if (.not. (mt%youngs_modulus > 0.0_wp)) then
                    message = 'material ' // trim(mt%name) // ': youngs_modulus must be positive'
                else if (.not. (mt%poisson_ratio > -1.0_wp .and. mt%poisson_ratio <= 0.5_wp)) then
                    message = 'material ' // trim(mt%name) // ': poisson_ratio must lie in (-1, 0.5]'
                else if (.not. (mt%restitution > 0.0_wp .and. mt%restitution <= 1.0_wp)) then
                    message = 'material ' // trim(mt%name) // ': restitution must lie in (0, 1]'
                end if
            end associate
            if (len(message) > 0) return
        end do
        do i = 1, n
            write (b1, '(i0)') sc%pline(i)
            if (.not. (sc%radius(i) > 0.0_wp .and. sc%radius(i) < huge(1.0_wp))) then
                message = 'line ' // trim(b1) // ': &particle radius must be positive'
                return
            end if
            if (sc%has_domain) then
                if (any(sc%x(:, i) < sc%domain_lo .or. sc%x(:, i) > sc%domain_hi)) then
                    message = 'line ' // trim(b1) // ': &particle position outside the domain'
                    return
                end if
            end if
        end do
        do w = 1, size(sc%wall)
            write (b2, '(i0)') sc%wall(w)%line
            h = norm2(sc%wall(w)%normal)
            if (.not. (abs(h - 1.0_wp) < 1.0e-12_wp)) then
                message = 'line ' // trim(b2) // ': &wall normal must be a unit vector'
                return
            end if
            do i = 1, n
                dist = dot_product(sc%x(:, i) - sc%wall(w)%point, sc%wall(w)%normal)
                if (dist < sc%radius(i) * (1.0_wp - 1.0e-12_wp)) then
                    write (b1, '(i0)') sc%pline(i)
                    message = 'line ' // trim(b1) // ': &particle overlaps the wall of line ' // trim(b2) // &
                              ' at the start'
                    return
                end if
            end do
        end do
        do j = 2, n
            do i = 1, j - 1
                dist = norm2(sc%x(:, j) - sc%x(:, i))
                if (dist < (sc%radius(i) + sc%radius(j)) * (1.0_wp - 1.0e-12_wp)) then
                    write (b1, '(i0)') sc%pline(i)
                    write (b2, '(i0)') sc%pline(j)
                    if (sc%pline(i) == sc%pline(j)) then
                        write (b2, '(i0,a,i0)') i, ' and ', j
                        message = 'line ' // trim(b1) // ': particles ' // trim(b2) // &
                                  ' of this &particle group overlap at the start'
                    else
                        message = 'line ' // trim(b2) // ': &particle overlaps the particle of line ' // &
                                  trim(b1) // ' at the start'
                    end if
                    return
                end if
            end do
        end do
        status = HD_OK
    end subroutine hertzdamp_dem_check

    !> True for a finite number (false for NaN and +-Inf).
    pure elemental logical function finite(x)
        real(wp), intent(in) :: x
        finite = abs(x) <= huge(1.0_wp)
    end function finite

    !> The contact rule: k and d for one contact from the target restitution e,
    !> the contact time tc = N dt (used when want_duration), effective mass m,
    !> impact velocity u and the physical stiffness kp (the bound).
    pure elemental subroutine hertzdamp_dem_rule(e, tc, m, u, kp, iend, method, want_duration, tol, &
                                                 k, d, tc_expected, bound, status)
        real(wp), intent(in) :: e               !! target restitution
        real(wp), intent(in) :: tc              !! wanted contact time [s]
        real(wp), intent(in) :: m               !! effective mass [kg]
        real(wp), intent(in) :: u               !! impact velocity [m s^-1]
        real(wp), intent(in) :: kp              !! physical stiffness [N m^-3/2]
        integer, intent(in) :: iend             !! contact-end definition
        integer, intent(in) :: method           !! HD_METHOD_*
        logical, intent(in) :: want_duration    !! impose tc (else k = kp)
        real(wp), intent(in) :: tol             !! tolerance of the iterative rule
        real(wp), intent(out) :: k              !! stiffness [N m^-3/2]
        real(wp), intent(out) :: d              !! damping [kg s^-1]
        real(wp), intent(out) :: tc_expected    !! contact time the parameters give [s]
        logical, intent(out) :: bound           !! k = kp
        integer, intent(out) :: status          !! HD_OK or the rule's failure
        real(wp) :: alpha, tau, ts, kk, dd
        k = 0.0_wp
        d = 0.0_wp
        tc_expected = 0.0_wp
        bound = .false.
        status = HD_OK
        if (want_duration) then
            ! (tol matters to the iterative rule only)
            call hertzdamp_invert(e, tc, m, u, iend, k, d, status, alpha=alpha, tau_c=tau, &
                                  bound_active=bound, k_phys=kp, method=method, tol=tol)
            if (status /= HD_OK) return
            tc_expected = tc
        else
            ! restitution only: the pair constants, then k = kp
            call hertzdamp_invert_alpha(e, iend, alpha, tau, status, method=method, tol=tol)
            if (status /= HD_OK) return
            bound = .true.
        end if
        if (bound) then
            ! physical stiffness: t* of kp (the reduction), then d = alpha m / t*
            ! (= alpha m^(3/5) kp^(2/5) u^(1/5)) from the same expansion the inverse uses
            call hertzdamp_reduce(kp, 0.0_wp, m, u, dd, ts, status)
            if (status == HD_OK) call hertzdamp_expand(alpha, ts, m, u, kk, d, status)
            k = kp
            tc_expected = ts * tau
            if (status /= HD_OK) then
                k = 0.0_wp
                d = 0.0_wp
                tc_expected = 0.0_wp
            end if
        end if
    end subroutine hertzdamp_dem_rule

    !> `--method auto`: the cheapest rule (in hertzdamp_dem_cost_order) whose error
    !> at the scene's targets meets the scene's accuracy.  For each candidate and each
    !> target e of the material pairs that meet, the candidate gives alpha_c (and its
    !> tau_c); one reference solve at alpha_c gives the achieved e and tau_c:
    !>     err = max |e_ref(alpha_c) - e| / e   [, |tau_ref(alpha_c) - tau_c| / tau_ref]
    !> (the second term only when the scene wants the contact duration).
    !> avail(c) is false when the library does not provide candidate c (any non-OK
    !> status of the inverse, typically HD_NOT_SUPPORTED).
    pure subroutine hertzdamp_dem_select(sc, chosen, err, avail, status)
        type(hertzdamp_dem_scene), intent(in) :: sc  !! the scene
        integer, intent(out) :: chosen               !! a method code, or -1 if none meets the accuracy
        real(wp), intent(out) :: err(6)              !! error of each candidate (cost order)
        logical, intent(out) :: avail(6)             !! candidate provided by the library
        integer, intent(out) :: status               !! HD_OK or a reference-solver failure
        logical, allocatable :: met(:, :)
        real(wp), allocatable :: targets(:)
        real(wp) :: e, alpha, tau, ec, tc
        integer :: a, b, c, it, st, meth
        type(hertzdamp_collision) :: r
        status = HD_OK
        chosen = -1
        err = huge(1.0_wp)
        avail = .false.
        call hertzdamp_dem_pairs_met(sc, met)
        allocate (targets(0))
        do a = 1, size(sc%mat)
            do b = a, size(sc%mat)
                if (.not. met(a, b)) cycle
                e = hertzdamp_dem_pair_e(sc%mat(a), sc%mat(b))
                if (.not. any(abs(targets - e) <= 4.0_wp * epsilon(e))) targets = [targets, e]
            end do
        end do
        do c = 1, 6
            meth = hertzdamp_dem_cost_order(c)
            avail(c) = .true.
            err(c) = 0.0_wp
            do it = 1, size(targets)
                e = targets(it)
                call hertzdamp_invert_alpha(e, sc%iend, alpha, tau, st, method=meth)
                if (st /= HD_OK) then
                    avail(c) = .false.
                    err(c) = huge(1.0_wp)
                    exit
                end if
                r = hertzdamp_rk45_collide(alpha, sc%iend)
                if (r%status /= HD_OK) then
                    ec = 0.0_wp   ! no rebound: e error 1
                    tc = huge(1.0_wp)
                    if (r%status /= HD_NO_REBOUND) then
                        status = r%status
                        return
                    end if
                else
                    ec = r%e
                    tc = r%tau_c
                end if
                err(c) = max(err(c), abs(ec - e) / e)
                if (sc%want_duration) err(c) = max(err(c), abs(tc - tau) / tc)
            end do
            if (avail(c) .and. chosen < 0 .and. err(c) <= sc%accuracy) chosen = meth
        end do
    end subroutine hertzdamp_dem_select

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

    !> Run a scene with a contact rule.  tol is the tolerance of the iterative rule.
    !> Not `pure` (its internal procedures update the work arrays of the run), but it
    !> keeps no state between calls and does no I/O: safe to call from threads.
    subroutine hertzdamp_dem_run(sc, method, tol, res)
        type(hertzdamp_dem_scene), intent(in) :: sc   !! a scene that passed hertzdamp_dem_check
        integer, intent(in) :: method                 !! HD_METHOD_*
        real(wp), intent(in) :: tol                   !! iterative rule tolerance
        type(hertzdamp_dem_result), intent(out) :: res !! contacts, checks, trace
        integer :: n, nw, nsteps, step, every, ns, isamp, ax, i, j, w, kk, c, nact, ip, ntrace
        real(wp), allocatable :: x(:, :), v(:, :), a(:, :), ap(:, :), aold(:, :), xo(:, :), vo(:, :), vh(:, :), vp(:, :), &
                                 f(:, :), dv(:, :), mass(:), rad(:), estar_pp(:, :), e_pp(:, :)
        integer, allocatable :: pair_c(:), wall_c(:, :), act(:), perm(:), nc(:), ended(:), nbi(:), nbj(:)
        real(wp), allocatable :: xb(:, :)
        real(wp) :: skin
        integer :: nnb
        logical, allocatable :: gone(:)
        real(wp) :: dt, t, g(3), zeta, zdot, nv(3), fn, phi, s, theta, u, energy, emin, p(3), rmax, &
                    zo, tcn, fh, epot
        integer :: nended
        character(len=48) :: buf
        character(len=200) :: mbuf

        n = size(sc%radius)
        nw = size(sc%wall)
        dt = sc%dt
        tcn = sc%steps_per_contact * dt
        nsteps = max(1, nint(sc%end_time / dt))
        res%method = method
        res%message = ''
        g = 0.0_wp
        if (sc%gravity) g = sc%g
        allocate (x(3, n), v(3, n), a(3, n), ap(3, n), aold(3, n), xo(3, n), vo(3, n), vh(3, n), vp(3, n), f(3, n), dv(3, n))
        allocate (mass(n), rad(n), pair_c(max(1, n * (n - 1) / 2)), wall_c(n, max(1, nw)), act(64), perm(n), &
                  nc(n), ended(64), gone(n))
        allocate (res%contacts(64))
        allocate (estar_pp(size(sc%mat), size(sc%mat)), e_pp(size(sc%mat), size(sc%mat)))
        do i = 1, size(sc%mat)
            do j = 1, size(sc%mat)
                estar_pp(i, j) = hertzdamp_dem_pair_estar(sc%mat(i), sc%mat(j))
                e_pp(i, j) = hertzdamp_dem_pair_e(sc%mat(i), sc%mat(j))
            end do
        end do
        x = sc%x
        v = sc%v
        rad = sc%radius
        rmax = maxval(rad)
        do i = 1, n
            mass(i) = hertzdamp_dem_mass(sc%mat(sc%pmat(i))%density, rad(i))
            a(:, i) = g
        end do
        ap = a
        pair_c = 0
        wall_c = 0
        nact = 0
        gone = .false.
        ! sweep axis: largest spread of the initial positions
        ax = maxloc(maxval(x, dim=2) - minval(x, dim=2), dim=1)
        perm = [(i, i=1, n)]
        skin = 0.2_wp * minval(rad)
        allocate (nbi(64), nbj(64), xb(3, n))
        call build_neighbours()
        ! trace axis: up (against gravity), else the axis with the largest initial velocities
        if (sc%gravity .and. norm2(g) > 0.0_wp) then
            res%axis = maxloc(abs(g), dim=1)
        else
            res%axis = maxloc(sum(abs(v), dim=2), dim=1)
        end if
        every = max(1, nsteps / sc%samples)
        ns = nsteps / every + 1
        ntrace = min(n, 200)
        allocate (res%t_trace(ns), res%x_trace(ns, ntrace), res%v_trace(ns, ntrace))
        isamp = 1
        res%t_trace(1) = 0.0_wp
        res%x_trace(1, :) = x(res%axis, 1:ntrace)
        res%v_trace(1, :) = v(res%axis, 1:ntrace)
        energy = total_energy()
        res%energy0 = energy
        emin = energy
        res%momentum0 = momentum()
        res%momentum_scale = sum(mass * norm2(v, dim=1))

        do step = 1, nsteps
            t = (step - 1) * dt
            xo = x
            vo = v
            aold = a
            vh = v + 0.5_wp * dt * a
            x = x + dt * vh
            vp = vh + 0.5_wp * dt * a + 0.5_wp * dt * (a - ap)
            f = 0.0_wp
            dv = 0.0_wp
            nc = 0
            nended = 0
            epot = 0.0_wp
            ! ---- contacts in progress
            kk = 1
            do while (kk <= nact)
                c = act(kk)
                call geometry(res%contacts(c)%i, res%contacts(c)%j, x, vp, zeta, zdot, nv)
                associate (ct => res%contacts(c))
                    if (ct%state == 2) then
                        ! released at the force zero: closed when the overlap vanishes or
                        ! when the bodies approach again (zeta' > 0, e.g. pulled back by
                        ! gravity before the overlap is gone); an approach then starts a
                        ! new contact below, with its own k and d from the rule.
                        if (zeta <= 0.0_wp .or. zdot > 0.0_wp) then
                            call close_contact(kk)
                            cycle
                        end if
                        kk = kk + 1
                        cycle
                    end if
                    if (zeta <= 0.0_wp) then
                        ! overlap gone (the overlap end; with the force end only when a step
                        ! jumps over the force zero).  In contact for the fraction phi of the
                        ! step: the damping part of the last force acts for phi dt, its Hertz
                        ! part (zeta -> 0 linearly) for 2/5 phi dt; the opening kick gave both dt/2.
                        phi = 0.0_wp
                        if (ct%zeta_last - zeta > 0.0_wp) phi = min(1.0_wp, max(0.0_wp, ct%zeta_last / (ct%zeta_last - zeta)))
                        fh = ct%k * max(ct%zeta_last, 0.0_wp)**1.5_wp
                        call add_impulse(ct%i, ct%j, ((ct%f_last - fh) * (phi - 0.5_wp) + fh * (0.4_wp * phi - 0.5_wp)) &
                                         * dt - start_error(phi) * ct%k * ((ct%zeta_last - zeta) / dt)**1.5_wp &
                                         * dt**2.5_wp, ct%n_last)
                        ct%t_end = t + phi * dt
                        ct%state = 3
                        call push_ended(c)
                        call close_contact(kk)
                        cycle
                    end if
                    fn = ct%k * zeta * sqrt(zeta) + ct%d * zdot
                    if (sc%iend == HD_END_FORCE .and. fn <= 0.0_wp) then
                        phi = 0.0_wp
                        if (ct%f_last - fn > 0.0_wp) phi = min(1.0_wp, max(0.0_wp, ct%f_last / (ct%f_last - fn)))
                        call add_impulse(ct%i, ct%j, ct%f_last * (phi - 1.0_wp) * 0.5_wp * dt, ct%n_last)
                        ct%t_end = t + phi * dt
                        ct%state = 2
                        call push_ended(c)
                        kk = kk + 1
                        cycle
                    end if
                    call apply_force(ct%i, ct%j, fn, nv)
                    epot = epot + 0.4_wp * ct%k * zeta**2 * sqrt(zeta)
                    ct%f_last = fn
                    ct%zeta_last = zeta
                    ct%n_last = nv
                end associate
                kk = kk + 1
            end do
            ! ---- new contacts: walls
            do w = 1, nw
                do i = 1, n
                    if (wall_c(i, w) /= 0) cycle
                    zeta = rad(i) - dot_product(x(:, i) - sc%wall(w)%point, sc%wall(w)%normal)
                    if (zeta > 0.0_wp) then
                        zo = rad(i) - dot_product(xo(:, i) - sc%wall(w)%point, sc%wall(w)%normal)
                        call onset(i, -w, zeta, zo)
                        if (res%status /= HD_OK) return
                    end if
                end do
            end do
            ! ---- new contacts: pairs of the neighbour list (rebuilt when a particle has
            ! moved by half the skin since the last build)
            if (maxval(sum((x - xb)**2, dim=1)) > (0.5_wp * skin)**2) call build_neighbours()
            do ip = 1, nnb
                i = nbi(ip)
                j = nbj(ip)
                if (pair_c(pidx(i, j)) /= 0) cycle
                zeta = rad(i) + rad(j) - norm2(x(:, j) - x(:, i))
                if (zeta > 0.0_wp) then
                    zo = rad(i) + rad(j) - norm2(xo(:, j) - xo(:, i))
                    call onset(i, j, zeta, zo)
                    if (res%status /= HD_OK) return
                end if
            end do
            ! ---- binary flags
            do kk = 1, nact
                associate (ct => res%contacts(act(kk)))
                    if (ct%state == 1) then
                        if (nc(ct%i) > 1) ct%binary = .false.
                        if (ct%j > 0) then
                            if (nc(ct%j) > 1) ct%binary = .false.
                        end if
                    end if
                end associate
            end do
            ! ---- closing half kick
            do i = 1, n
                a(:, i) = g + f(:, i) / mass(i)
            end do
            ap = aold
            v = vh + 0.5_wp * dt * a + dv
            do kk = 1, nended
                ! separation speed at the end instant: back from the step end by the
                ! remaining forces (gravity, other contacts)
                associate (ct => res%contacts(ended(kk)))
                    zo = t + dt - ct%t_end
                    if (ct%j > 0) then
                        ct%u_out = dot_product(v(:, ct%j) - zo * a(:, ct%j) - v(:, ct%i) + zo * a(:, ct%i), ct%n_last)
                    else
                        ct%u_out = -dot_product(v(:, ct%i) - zo * a(:, ct%i), ct%n_last)
                    end if
                end associate
            end do
            ! ---- checks and trace
            energy = total_energy() + epot
            res%energy_rise = max(res%energy_rise, energy - emin)
            emin = min(emin, energy)
            p = momentum()
            res%momentum_drift = max(res%momentum_drift, norm2(p - res%momentum0))
            if (sc%has_domain) then
                do i = 1, n
                    if (.not. gone(i)) then
                        if (any(x(:, i) < sc%domain_lo .or. x(:, i) > sc%domain_hi)) then
                            gone(i) = .true.
                            res%left_domain = res%left_domain + 1
                        end if
                    end if
                end do
            end if
            if (mod(step, every) == 0 .and. isamp < ns) then
                isamp = isamp + 1
                res%t_trace(isamp) = step * dt
                res%x_trace(isamp, :) = x(res%axis, 1:ntrace)
                res%v_trace(isamp, :) = v(res%axis, 1:ntrace)
            end if
        end do
        res%steps = nsteps
        res%energy_final = energy
        res%contacts = res%contacts(1:res%ncontacts)
        res%t_trace = res%t_trace(1:isamp)
        res%x_trace = res%x_trace(1:isamp, :)
        res%v_trace = res%v_trace(1:isamp, :)
        res%max_speed_final = maxval(norm2(v, dim=1))
        res%at_rest = res%max_speed_final < sc%rest_speed
        res%x_final = x
        res%v_final = v

    contains

        integer function pidx(i1, i2)
            integer, intent(in) :: i1, i2
            integer :: lo, hi
            lo = min(i1, i2)
            hi = max(i1, i2)
            pidx = (hi - 1) * (hi - 2) / 2 + lo
        end function pidx

        !> Overlap, its rate (with the predicted velocities) and the normal (from i to j,
        !> or out of the wall's side for a wall).
        subroutine geometry(i1, j1, xx, vv, z, zd, nn)
            integer, intent(in) :: i1, j1
            real(wp), intent(in) :: xx(:, :), vv(:, :)
            real(wp), intent(out) :: z, zd, nn(3)
            real(wp) :: dd
            if (j1 > 0) then
                nn = xx(:, j1) - xx(:, i1)
                dd = norm2(nn)
                nn = nn / dd
                z = rad(i1) + rad(j1) - dd
                zd = -dot_product(vv(:, j1) - vv(:, i1), nn)
            else
                nn = -sc%wall(-j1)%normal
                z = rad(i1) - dot_product(xx(:, i1) - sc%wall(-j1)%point, sc%wall(-j1)%normal)
                zd = dot_product(vv(:, i1), nn)
            end if
        end subroutine geometry

        !> Force fn (repulsive > 0) along nn: on j (or nothing, wall) +fn nn, on i -fn nn.
        subroutine apply_force(i1, j1, fnn, nn)
            integer, intent(in) :: i1, j1
            real(wp), intent(in) :: fnn, nn(3)
            f(:, i1) = f(:, i1) - fnn * nn
            nc(i1) = nc(i1) + 1
            if (j1 > 0) then
                f(:, j1) = f(:, j1) + fnn * nn
                nc(j1) = nc(j1) + 1
            end if
        end subroutine apply_force

        !> Impulse correction jn (repulsive > 0) along nn, added after the closing kick.
        subroutine add_impulse(i1, j1, jn, nn)
            integer, intent(in) :: i1, j1
            real(wp), intent(in) :: jn, nn(3)
            dv(:, i1) = dv(:, i1) - jn * nn / mass(i1)
            if (j1 > 0) dv(:, j1) = dv(:, j1) + jn * nn / mass(j1)
        end subroutine add_impulse

        subroutine push_ended(c1)
            integer, intent(in) :: c1
            integer, allocatable :: tmp(:)
            if (nended == size(ended)) then
                allocate (tmp(2 * size(ended)))
                tmp(1:nended) = ended(1:nended)
                call move_alloc(tmp, ended)
            end if
            nended = nended + 1
            ended(nended) = c1
        end subroutine push_ended

        !> Remove act(k1) from the active list and the lookup tables.
        subroutine close_contact(k1)
            integer, intent(in) :: k1
            integer :: c1
            c1 = act(k1)
            if (res%contacts(c1)%j > 0) then
                pair_c(pidx(res%contacts(c1)%i, res%contacts(c1)%j)) = 0
            else
                wall_c(res%contacts(c1)%i, -res%contacts(c1)%j) = 0
            end if
            act(k1) = act(nact)
            nact = nact - 1
        end subroutine close_contact

        !> A new contact between i1 and j1 (j1 < 0: wall) with overlap z now and zo
        !> at the start of the step.
        subroutine onset(i1, j1, z, zo1)
            integer, intent(in) :: i1, j1
            real(wp), intent(in) :: z, zo1
            type(hertzdamp_dem_contact), allocatable :: tmp(:)
            integer, allocatable :: itmp(:)
            type(hertzdamp_dem_contact) :: ct
            real(wp) :: z1, zd1, nn(3), va(3), kp, rs, fn1
            integer :: st, mb
            ! fraction of the step before the touch, and the velocities then
            if (zo1 >= 0.0_wp .or. z <= zo1) then
                s = 0.0_wp   ! touching at the start of the step already
            else
                s = min(1.0_wp, -zo1 / (z - zo1))
            end if
            theta = 1.0_wp - s
            ct%i = i1
            ct%j = j1
            if (j1 > 0) then
                ct%m = mass(i1) * mass(j1) / (mass(i1) + mass(j1))
                mb = sc%pmat(j1)
                rs = rad(i1) * rad(j1) / (rad(i1) + rad(j1))
                va = (vo(:, j1) + s * dt * a(:, j1)) - (vo(:, i1) + s * dt * a(:, i1))
            else
                ct%m = mass(i1)
                mb = sc%wall(-j1)%material
                rs = rad(i1)
                va = -(vo(:, i1) + s * dt * a(:, i1))
            end if
            call geometry(i1, j1, x, vp, z1, zd1, nn)
            u = -dot_product(va, nn)
            ct%u_in = u
            ct%u_rule = max(u, sc%rest_speed, hertzdamp_dem_u_floor)
            kp = 4.0_wp / 3.0_wp * estar_pp(sc%pmat(i1), mb) * sqrt(rs)
            ct%k_phys = kp
            ct%e_target = e_pp(sc%pmat(i1), mb)
            call hertzdamp_dem_rule(ct%e_target, tcn, ct%m, ct%u_rule, kp, sc%iend, method, sc%want_duration, tol, &
                                    ct%k, ct%d, ct%tc_target, ct%bound_active, st)
            if (st /= HD_OK) then
                res%status = st
                write (buf, '(es12.5)') t + s * dt
                if (j1 > 0) then
                    write (mbuf, '(a,i0,a,i0)') 'contact of particles ', i1, ' and ', j1
                else
                    write (mbuf, '(a,i0,a,i0)') 'contact of particle ', i1, ' with wall ', -j1
                end if
                res%message = trim(mbuf) // ' at t = ' // trim(adjustl(buf)) // ': ' // hertzdamp_message(st)
                return
            end if
            ct%t_start = t + s * dt
            ct%state = 1
            fn1 = ct%k * z1**1.5_wp + ct%d * zd1
            ! in contact for the fraction theta of this step only: the damping force
            ! acts for theta dt, the Hertz force (zeta growing linearly) for 2/5 theta dt;
            ! the closing kick gives both dt/2.
            call add_impulse(i1, j1, (ct%d * zd1 * (theta - 0.5_wp) + ct%k * z1**1.5_wp * (0.4_wp * theta - 0.5_wp)) &
                             * dt - start_error(theta) * ct%k * max(u, 0.0_wp)**1.5_wp * dt**2.5_wp, nn)
            call apply_force(i1, j1, fn1, nn)
            epot = epot + 0.4_wp * ct%k * z1**2 * sqrt(z1)
            ct%f_last = fn1
            ct%zeta_last = z1
            ct%n_last = nn
            if (res%ncontacts == size(res%contacts)) then
                allocate (tmp(2 * size(res%contacts)))
                tmp(1:res%ncontacts) = res%contacts(1:res%ncontacts)
                call move_alloc(tmp, res%contacts)
            end if
            res%ncontacts = res%ncontacts + 1
            res%contacts(res%ncontacts) = ct
            if (nact == size(act)) then
                allocate (itmp(2 * size(act)))
                itmp(1:nact) = act(1:nact)
                call move_alloc(itmp, act)
            end if
            nact = nact + 1
            act(nact) = res%ncontacts
            if (j1 > 0) then
                pair_c(pidx(i1, j1)) = res%ncontacts
            else
                wall_c(i1, -j1) = res%ncontacts
            end if
        end subroutine onset

        !> Neighbour list: the pairs closer than r_i + r_j + skin, found by a sweep
        !> along axis ax over the particles sorted by that coordinate.
        subroutine build_neighbours()
            integer :: p1, p2, i1, j1
            integer, allocatable :: tmp(:)
            call sort_perm()
            nnb = 0
            do p1 = 1, n - 1
                i1 = perm(p1)
                do p2 = p1 + 1, n
                    j1 = perm(p2)
                    if (x(ax, j1) - x(ax, i1) > rad(i1) + rmax + skin) exit
                    if (norm2(x(:, j1) - x(:, i1)) > rad(i1) + rad(j1) + skin) cycle
                    if (nnb == size(nbi)) then
                        allocate (tmp(2 * nnb))
                        tmp(1:nnb) = nbi(1:nnb)
                        call move_alloc(tmp, nbi)
                        allocate (tmp(2 * nnb))
                        tmp(1:nnb) = nbj(1:nnb)
                        call move_alloc(tmp, nbj)
                    end if
                    nnb = nnb + 1
                    nbi(nnb) = min(i1, j1)
                    nbj(nnb) = max(i1, j1)
                end do
            end do
            xb = x
        end subroutine build_neighbours

        !> Insertion sort of perm by position along ax (nearly sorted: linear time).
        subroutine sort_perm()
            integer :: i1, j1, key
            do i1 = 2, n
                key = perm(i1)
                j1 = i1 - 1
                do while (j1 >= 1)
                    if (x(ax, perm(j1)) <= x(ax, key)) exit
                    perm(j1 + 1) = perm(j1)
                    j1 = j1 - 1
                end do
                perm(j1 + 1) = key
            end do
        end subroutine sort_perm

        !> Kinetic + gravitational energy; the contact energy sum of 2/5 k zeta^(5/2)
        !> (epot) is added up in the force loop.
        real(wp) function total_energy() result(en)
            integer :: k1
            en = 0.0_wp
            do k1 = 1, n
                en = en + 0.5_wp * mass(k1) * sum(v(:, k1)**2) - mass(k1) * dot_product(g, x(:, k1))
            end do
        end function total_energy

        function momentum() result(pm)
            real(wp) :: pm(3)
            integer :: k1
            pm = 0.0_wp
            do k1 = 1, n
                pm = pm + mass(k1) * v(:, k1)
            end do
        end function momentum

    end subroutine hertzdamp_dem_run

end module hertzdamp_dem
