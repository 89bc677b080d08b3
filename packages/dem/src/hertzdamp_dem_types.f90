!> The data of the DEM engine: a scene (settings, materials, particles, walls), the
!> record of one contact, the result of a run, the engine's limits, and the small
!> pure formulas of the scene's material pairs (pair restitution, which pairs can
!> meet).  Masses, effective masses and radii, E* and k_phys come from the core
!> (hertzdamp_materials).  No procedure here changes anything but its own result.
module hertzdamp_dem_types
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_END_OVERLAP, HD_DAMPING_LINEAR, HD_METHOD_FIT, HD_HOST_NONE, &
                         HD_HOST_VERLET
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Most particles a scene may hold (the pair table is dense).
    integer, parameter, public :: hertzdamp_dem_max_particles = 2000
    !> Most time steps a scene may take.
    integer, parameter, public :: hertzdamp_dem_max_steps = 20000000
    !> Most particles whose trace is kept (the first ones of the scene).
    integer, parameter, public :: hertzdamp_dem_max_traced = 200
    !> Most trace samples a scene may ask for.
    integer, parameter, public :: hertzdamp_dem_max_samples = 1000000
    !> Most trace values (samples times traced particles) a run may keep: with a
    !> position and a velocity of 8 bytes each, 64 MB.
    integer, parameter, public :: hertzdamp_dem_max_trace_values = 4000000
    !> Lower bound of the impact velocity passed to the rule [m s^-1]: the rule gets
    !> max(u_in, rest_speed, hertzdamp_dem_u_floor).
    real(wp), parameter, public :: hertzdamp_dem_u_floor = 1.0e-9_wp
    !> Magnitude window of the quantities a scene may put into the engine (SI units):
    !> masses, stiffnesses and moduli within [1/big, big], energies, momenta, speeds,
    !> coordinates and accelerations at most big.  The engine forms products of two
    !> such quantities, which stay finite in double precision.
    real(wp), parameter, public :: hertzdamp_dem_big = 1.0e150_wp

    !> One material.
    type, public :: hertzdamp_dem_material
        character(len=32) :: name = ''          !! name used by particles and walls
        real(wp) :: density = 0.0_wp            !! [kg m^-3]
        real(wp) :: youngs_modulus = 0.0_wp     !! [Pa]
        real(wp) :: poisson_ratio = 0.0_wp      !! [-], in (-1, 0.5]
        real(wp) :: restitution = 0.0_wp        !! target restitution, in (0, 1]
        integer :: line = 0                     !! source line (for messages; 0: not from a file)
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
        integer :: law = HD_DAMPING_LINEAR      !! damping law HD_DAMPING_*: damping force d zeta^q zeta'
        logical :: want_duration = .true.       !! report and impose the contact duration
        real(wp) :: accuracy = 1.0e-3_wp        !! relative accuracy wanted of e (and T_c)
        logical :: has_domain = .false.         !! a bounding box is given
        real(wp) :: domain_lo(3) = 0.0_wp       !! box lower corner [m]
        real(wp) :: domain_hi(3) = 0.0_wp       !! box upper corner [m]
        real(wp) :: rest_speed = 1.0e-3_wp      !! at rest when every speed is below; slowest impact given to the rule [m s^-1]
        integer :: samples = 1000               !! trace samples kept (for plots)
        integer :: host = HD_HOST_NONE          !! HD_HOST_* whose per-pair constants give k, d (none: the rule of the method)
        logical :: onset_phase = .false.        !! with a host: each contact's k, d from its onset phase (issue 32)
        integer :: scheme = HD_HOST_VERLET      !! HD_HOST_* time integrator of the contacts (verlet: the engine's own)
        type(hertzdamp_dem_material), allocatable :: mat(:)  !! materials
        integer, allocatable :: pmat(:)         !! material of each particle
        real(wp), allocatable :: radius(:)      !! radius of each particle [m]
        real(wp), allocatable :: x(:, :)        !! initial positions (3, n) [m]
        real(wp), allocatable :: v(:, :)        !! initial velocities (3, n) [m s^-1]
        integer, allocatable :: pline(:)        !! source line of each particle
        type(hertzdamp_dem_wall), allocatable :: wall(:) !! walls
    end type hertzdamp_dem_scene

    !> Contact states.
    integer, parameter, public :: HD_CONTACT_ACTIVE = 1    !! in contact, force acting
    integer, parameter, public :: HD_CONTACT_RELEASED = 2  !! force end reached while still overlapping: no force
    integer, parameter, public :: HD_CONTACT_CLOSED = 3    !! ended (overlap gone)

    !> Record of one contact.
    type, public :: hertzdamp_dem_contact
        integer :: i = 0, j = 0                 !! particles; j < 0: wall -j
        real(wp) :: m = 0.0_wp                  !! effective mass [kg]
        real(wp) :: u_in = 0.0_wp               !! impact normal velocity [m s^-1]
        real(wp) :: u_rule = 0.0_wp             !! velocity given to the rule, max(u_in, rest_speed)
        real(wp) :: k = 0.0_wp                  !! stiffness used [N m^-3/2]
        real(wp) :: d = 0.0_wp                  !! damping used [kg s^-1 m^-q] (q of the scene's law)
        real(wp) :: k_phys = 0.0_wp             !! physical stiffness bound
        real(wp) :: e_target = 0.0_wp           !! target restitution of the material pair
        real(wp) :: tc_target = 0.0_wp          !! expected contact time [s] (N dt, or physical)
        logical :: bound_active = .false.       !! k = k_phys was used
        real(wp) :: t_start = 0.0_wp            !! onset instant [s]
        real(wp) :: t_end = -1.0_wp             !! end instant [s], < 0 while not ended
        real(wp) :: u_out = 0.0_wp              !! separation normal velocity [m s^-1]
        logical :: binary = .true.              !! no other contact on either body meanwhile
        integer :: state = HD_CONTACT_ACTIVE    !! HD_CONTACT_*
        real(wp) :: zeta_last = 0.0_wp          !! overlap at the last step
        real(wp) :: zdot_last = 0.0_wp          !! overlap rate at the last step (as used in its force)
        real(wp) :: f_last = 0.0_wp             !! normal force at the last step
        real(wp) :: n_last(3) = 0.0_wp          !! normal at the last step
    end type hertzdamp_dem_contact

    !> Result of a run.
    type, public :: hertzdamp_dem_result
        integer :: status = HD_OK               !! HD_OK or the failure
        character(len=:), allocatable :: message !! what failed (empty on success)
        integer :: method = HD_METHOD_FIT       !! contact rule used
        real(wp) :: host_e_dev = 0.0_wp         !! host constants: largest |e(phi)/e - 1| over the onset phase and pairs
        real(wp) :: host_tc_dev = 0.0_wp        !! host constants: largest |T_c(phi)/T_c - 1| over the phase and pairs
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

    public :: hertzdamp_dem_pair_e, hertzdamp_dem_pairs_met
    public :: hertzdamp_dem_nsteps, hertzdamp_dem_trace_size, hertzdamp_dem_int_text

contains

    !> Target restitution of a material pair, sqrt(e_a e_b).
    pure real(wp) function hertzdamp_dem_pair_e(a, b)
        type(hertzdamp_dem_material), intent(in) :: a  !! first material
        type(hertzdamp_dem_material), intent(in) :: b  !! second material
        hertzdamp_dem_pair_e = sqrt(a%restitution * b%restitution)
    end function hertzdamp_dem_pair_e

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

    !> Time steps of a run: end_time/dt rounded, at least 1 (the scene passed
    !> hertzdamp_dem_check, so end_time/dt is within hertzdamp_dem_max_steps).
    pure integer function hertzdamp_dem_nsteps(sc) result(nsteps)
        type(hertzdamp_dem_scene), intent(in) :: sc  !! the scene
        nsteps = max(1, nint(sc%end_time / sc%dt))
    end function hertzdamp_dem_nsteps

    !> Shape of the trace a run keeps: `every` steps between samples, `nsamples`
    !> samples (the start included) of `ntraced` particles.
    pure subroutine hertzdamp_dem_trace_size(sc, every, nsamples, ntraced)
        type(hertzdamp_dem_scene), intent(in) :: sc  !! the scene
        integer, intent(out) :: every                !! steps between samples
        integer, intent(out) :: nsamples             !! samples kept
        integer, intent(out) :: ntraced              !! particles traced
        integer :: nsteps
        nsteps = hertzdamp_dem_nsteps(sc)
        every = max(1, nsteps / max(1, sc%samples))
        nsamples = nsteps / every + 1
        ntraced = min(size(sc%radius), hertzdamp_dem_max_traced)
    end subroutine hertzdamp_dem_trace_size

    !> An integer as text, for messages.
    pure function hertzdamp_dem_int_text(i) result(s)
        integer, intent(in) :: i       !! the integer
        character(len=:), allocatable :: s  !! its decimal digits
        character(len=16) :: b
        write (b, '(i0)') i
        s = trim(b)
    end function hertzdamp_dem_int_text

end module hertzdamp_dem_types
