!> The contact options shared by the commands that need a mass and a stiffness bound
!> (`invert`, `forward`, `timestep`, and any later command such as calibration):
!>
!>     --mass M                      effective mass [kg], or from the materials:
!>     --radius R --density RHO      body 1 (sphere radius [m], density [kg m^-3])
!>     --youngs-modulus E --poisson-ratio NU      body 1 elastic constants [Pa], [-]
!>     --radius2 --density2 --youngs-modulus2 --poisson-ratio2   body 2 (default:
!>                                   the same as body 1, i.e. two equal spheres)
!>     --wall                        body 2 is a wall: infinite radius and mass; its
!>                                   elastic constants from the 2-suffixed options or,
!>                                   by default, body 1's
!>     --k-phys K                    physical stiffness [N m^-3/2], or from the
!>                                   materials: k_phys = (4/3) E* sqrt(R*)
!>
!> Interface: list `contact_options` among the command's valued options and
!> `contact_flags` among its flags (parse_args), then `call parse_contact(args, ct)`.
!> A command that needs the mass then calls `require_mass(ct)`.
!> `ct%has_mass`, `ct%has_radius`, `ct%has_kphys`, `ct%has_rayleigh` say which of
!> `ct%mass`, `ct%radius`, `ct%k_phys` (and `ct%e_star` with has_kphys from
!> materials), `ct%t_rayleigh` are known.  Every bad value exits 2 with one line naming the option; a mass or
!> stiffness that double precision cannot hold (a radius of 1e200 m) too.  The
!> numbers come from the library module hertzdamp_materials.
module hertzdamp_cli_materials
    use hertzdamp, only: hertzdamp_rk, hertzdamp_sphere_mass, hertzdamp_effective_mass, hertzdamp_effective_radius, &
                         hertzdamp_plane_strain_modulus, hertzdamp_effective_modulus, hertzdamp_hertz_stiffness, &
                         hertzdamp_rayleigh_time, hertzdamp_message, hertzdamp_end_name, HD_OK, HD_OUT_OF_RANGE, &
                         HD_BAD_DENSITY, HD_BAD_POISSON, hertzdamp_mindlin_kt
    use hertzdamp_cli, only: cli_args, parse_real, fail, EXIT_USAGE
    use hertzdamp_cli_output, only: out_table
    use hertzdamp_cli_model, only: model_opts
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Valued options read by parse_contact.
    character(len=*), parameter, public :: contact_options = '--mass --k-phys --radius --density --youngs-modulus ' // &
        '--poisson-ratio --radius2 --density2 --youngs-modulus2 --poisson-ratio2'
    !> Flags read by parse_contact.
    character(len=*), parameter, public :: contact_flags = '--wall'

    !> What the contact options give.
    type, public :: cli_contact
        logical :: has_mass = .false.       !! mass known (--mass or radii and densities)
        logical :: has_radius = .false.     !! effective radius known (--radius)
        logical :: has_kphys = .false.      !! k_phys known (--k-phys or radius and elastic constants)
        logical :: from_materials = .false. !! some quantity came from material data
        logical :: wall = .false.           !! body 2 is a wall
        real(wp) :: mass = 0.0_wp           !! effective mass m* [kg]
        real(wp) :: radius = 0.0_wp         !! effective radius R* [m]
        real(wp) :: e_star = 0.0_wp         !! effective modulus E* [Pa] (0 when k_phys was given)
        real(wp) :: k_phys = 0.0_wp         !! physical stiffness (4/3) E* sqrt(R*) [N m^-3/2]
        logical :: has_rayleigh = .false.   !! t_rayleigh known (radii, densities and elastic constants)
        real(wp) :: t_rayleigh = 0.0_wp     !! the shorter Rayleigh time of the spheres (not of a wall) [s]
        character(len=:), allocatable :: description   !! e.g. 'two spheres', 'sphere and wall'
        logical :: has_bodies = .false.     !! each body's mass and radius known (--radius, --density)
        real(wp) :: m1 = 0.0_wp, r1 = 0.0_wp !! body 1's mass [kg] and radius [m]
        real(wp) :: m2 = 0.0_wp, r2 = 0.0_wp !! body 2's (a wall: 0, 0)
        logical :: has_mindlin = .false.    !! Mindlin's 8 G* known (the elastic constants)
        real(wp) :: kt_mindlin = 0.0_wp     !! 8 G* [N/m^2] (hertzdamp_mindlin_kt)
    end type cli_contact

    public :: parse_contact, require_mass, contact_table

contains

    !> Exit 2 when the contact options gave no mass (the message names --mass).
    subroutine require_mass(ct)
        type(cli_contact), intent(in) :: ct
        if (.not. ct%has_mass) call fail(EXIT_USAGE, 'missing option --mass (or --radius with --density) (see --help)')
    end subroutine require_mass

    !> Read the contact options into `ct`; exit 2 naming the option on any bad value
    !> or combination.
    subroutine parse_contact(args, ct)
        type(cli_args), intent(in) :: args
        type(cli_contact), intent(out) :: ct
        real(wp) :: r1, r2, rho1, rho2, ym1, ym2, nu1, nu2, m1, m2, a
        integer :: st
        character(len=:), allocatable :: sfx
        ct%wall = args%has('--wall')
        ct%description = merge('sphere and wall', 'two spheres    ', ct%wall)
        ct%description = trim(ct%description)
        call needs(args, '--radius2', '--radius')
        call needs(args, '--density2', '--density')
        call needs(args, '--youngs-modulus2', '--youngs-modulus')
        call needs(args, '--poisson-ratio2', '--poisson-ratio')
        call needs(args, '--youngs-modulus', '--poisson-ratio')
        call needs(args, '--poisson-ratio', '--youngs-modulus')
        if (ct%wall .and. (args%has('--radius2') .or. args%has('--density2'))) then
            call fail(EXIT_USAGE, '--wall: body 2 has infinite radius and mass, so --radius2 and --density2 do not apply')
        end if

        ! mass: --mass, or the spheres' radii and densities
        if (args%has('--mass')) then
            if (args%has('--density')) call fail(EXIT_USAGE, 'give either --mass or --radius with --density, not both')
            ct%mass = value(args, '--mass')
            if (.not. (ct%mass > 0.0_wp)) call fail(EXIT_USAGE, '--mass ' // args%get('--mass', '') // &
                                                    ': the effective mass must be finite and positive')
            ct%has_mass = .true.
        else if (args%has('--density')) then
            call needs(args, '--density', '--radius')
            r1 = value(args, '--radius')
            rho1 = value(args, '--density')
            call hertzdamp_sphere_mass(r1, rho1, m1, st)
            call check(args, st, '--radius', '--density', ' sphere mass (4/3) pi rho R^3')
            ct%has_bodies = .true.
            ct%m1 = m1
            ct%r1 = r1
            if (ct%wall) then
                ct%mass = m1
            else
                r2 = value(args, '--radius2', r1)
                rho2 = value(args, '--density2', rho1)
                call hertzdamp_sphere_mass(r2, rho2, m2, st)
                call check(args, st, '--radius2', '--density2', ' sphere mass (4/3) pi rho R^3')
                call hertzdamp_effective_mass(m1, m2, ct%mass, st)
                call check(args, st, '--radius', '--density', ' effective mass')
                ct%m2 = m2
                ct%r2 = r2
            end if
            ct%has_mass = .true.
            ct%from_materials = .true.
        end if

        ! effective radius: the spheres' radii (a wall is flat)
        if (args%has('--radius')) then
            r1 = value(args, '--radius')
            if (ct%wall) then
                call hertzdamp_effective_radius(r1, r1, a, st)   ! validates r1
                ct%radius = r1
            else
                call hertzdamp_effective_radius(r1, value(args, '--radius2', r1), ct%radius, st)
            end if
            call check(args, st, '--radius', '--radius2', ' effective radius')
            ct%has_radius = .true.
        end if

        ! stiffness bound: --k-phys, or (4/3) E* sqrt(R*) from the elastic constants
        if (args%has('--k-phys')) then
            if (args%has('--youngs-modulus')) then
                call fail(EXIT_USAGE, 'give either --k-phys or --youngs-modulus with --poisson-ratio, not both')
            end if
            ct%k_phys = value(args, '--k-phys')
            if (.not. (ct%k_phys > 0.0_wp)) call fail(EXIT_USAGE, '--k-phys ' // args%get('--k-phys', '') // &
                                                      ': the physical stiffness must be finite and positive')
            ct%has_kphys = .true.
        else if (args%has('--youngs-modulus')) then
            if (.not. ct%has_radius) call fail(EXIT_USAGE, '--youngs-modulus needs --radius: ' // &
                                               'k_phys = (4/3) E* sqrt(R*)')
            ym1 = value(args, '--youngs-modulus')
            nu1 = value(args, '--poisson-ratio')
            ym2 = value(args, '--youngs-modulus2', ym1)
            nu2 = value(args, '--poisson-ratio2', nu1)
            call hertzdamp_plane_strain_modulus(ym1, nu1, a, st)
            if (st /= HD_OUT_OF_RANGE) call check(args, st, '--youngs-modulus', '--poisson-ratio', '')
            call hertzdamp_plane_strain_modulus(ym2, nu2, a, st)
            if (st /= HD_OUT_OF_RANGE) call check(args, st, '--youngs-modulus2', '--poisson-ratio2', '')
            ! E* is set by the more compliant body: a value out of range is its doing
            sfx = ''
            if (more_compliant(ym2, nu2, ym1, nu1) .and. (args%has('--youngs-modulus2') .or. &
                                                        args%has('--poisson-ratio2'))) sfx = '2'
            call hertzdamp_effective_modulus(ym1, nu1, ym2, nu2, ct%e_star, st)
            call check(args, st, '--youngs-modulus' // sfx, '--poisson-ratio' // sfx, ' effective modulus E*')
            call hertzdamp_hertz_stiffness(ct%e_star, ct%radius, ct%k_phys, st)
            call check(args, st, '--youngs-modulus' // sfx, '--radius', ' stiffness k_phys = (4/3) E* sqrt(R*)')
            ct%has_kphys = .true.
            ct%from_materials = .true.
            call hertzdamp_mindlin_kt(ym1, nu1, ym2, nu2, ct%kt_mindlin, st)
            ct%has_mindlin = st == HD_OK
            if (args%has('--density')) call rayleigh(args, ct, ym1, nu1, ym2, nu2)
        end if
        if (.not. (ct%wall .or. ct%has_radius)) ct%description = 'effective mass given'
    end subroutine parse_contact

    !> The Rayleigh time of the contact: the shorter of the spheres' (a wall has none).
    !> Not representable (a radius of 1e300 m): left unknown, the row says nothing.
    subroutine rayleigh(args, ct, ym1, nu1, ym2, nu2)
        type(cli_args), intent(in) :: args
        type(cli_contact), intent(inout) :: ct
        real(wp), intent(in) :: ym1, nu1, ym2, nu2   !! the elastic constants of the bodies
        real(wp) :: r1, t1, t2
        integer :: st1, st2
        r1 = value(args, '--radius')
        call hertzdamp_rayleigh_time(r1, value(args, '--density'), ym1, nu1, t1, st1)
        t2 = t1
        st2 = st1
        if (.not. ct%wall) call hertzdamp_rayleigh_time(value(args, '--radius2', r1), &
                                                        value(args, '--density2', value(args, '--density')), &
                                                        ym2, nu2, t2, st2)
        ct%has_rayleigh = st1 == HD_OK .and. st2 == HD_OK
        if (ct%has_rayleigh) ct%t_rayleigh = min(t1, t2)
    end subroutine rayleigh

    !> Start a table of a command on a contact: its columns with their units (the
    !> text header), and as metadata the contact end, the method, the kind of contact
    !> and the units (JSON; the text output has them in its header).
    subroutine contact_table(t, c, ct, columns, units, column_units)
        type(out_table), intent(inout) :: t
        type(model_opts), intent(in) :: c
        type(cli_contact), intent(in) :: ct
        character(len=*), intent(in) :: columns        !! comma-separated column names
        character(len=*), intent(in) :: units          !! the units of the columns, one line (JSON)
        character(len=*), intent(in) :: column_units   !! comma-separated, one per column ('' for none)
        call t%set_columns(columns, column_units)
        call t%meta('damping', c%law_name)
        call t%meta('end', hertzdamp_end_name(c%iend))
        call t%meta('method', c%method_name)
        call t%meta('contact', ct%description)
        call t%meta('units', units, text='')
    end subroutine contact_table

    !> True when body a's compliance (1 - nu^2)/E exceeds body b's (compared in logs:
    !> either may be beyond double precision; the moduli and ratios are valid).
    pure logical function more_compliant(ya, nua, yb, nub)
        real(wp), intent(in) :: ya, nua, yb, nub
        more_compliant = log((1.0_wp - nua) * (1.0_wp + nua)) - log(ya) > &
                         log((1.0_wp - nub) * (1.0_wp + nub)) - log(yb)
    end function more_compliant

    !> Exit 2 when `opt` is given without `other`.
    subroutine needs(args, opt, other)
        type(cli_args), intent(in) :: args
        character(len=*), intent(in) :: opt, other
        if (args%has(opt) .and. .not. args%has(other)) call fail(EXIT_USAGE, opt // ' needs ' // other)
    end subroutine needs

    !> The number given to `key`, or `default` (required when absent without default).
    real(wp) function value(args, key, default) result(x)
        type(cli_args), intent(in) :: args
        character(len=*), intent(in) :: key
        real(wp), intent(in), optional :: default
        if (.not. args%has(key) .and. present(default)) then
            x = default
        else
            x = parse_real(args%get(key, ''), key)
        end if
    end function value

    !> Exit 2 on a bad status, naming the option and its value (`key` for the first
    !> kind of input, `key2` for the second: density, Poisson's ratio, ...).
    subroutine check(args, status, key, key2, what)
        type(cli_args), intent(in) :: args
        integer, intent(in) :: status
        character(len=*), intent(in) :: key, key2, what
        character(len=:), allocatable :: k
        if (status == HD_OK) return
        if (status == HD_OUT_OF_RANGE) then
            call fail(EXIT_USAGE, shown(args, key) // ' with ' // shown(args, key2) // ': the' // what // &
                      ' is outside the double-precision range')
        end if
        k = key
        if (status == HD_BAD_DENSITY .or. status == HD_BAD_POISSON) k = key2
        call fail(EXIT_USAGE, shown(args, k) // ': ' // hertzdamp_message(status))
    end subroutine check

    !> `--key value` as given (`--key2 (= --key)` when it defaults to body 1).
    recursive function shown(args, key) result(s)
        type(cli_args), intent(in) :: args
        character(len=*), intent(in) :: key
        character(len=:), allocatable :: s
        if (args%has(key)) then
            s = key // ' ' // args%get(key, '')
        else if (key(len(key):) == '2') then
            s = key // ' (= ' // shown(args, key(1:len(key) - 1)) // ')'
        else
            s = key
        end if
    end function shown

end module hertzdamp_cli_materials
