!> What a peer DEM engine's Hertz contact does with the parameters it is given.
!>
!> Six engines (LAMMPS, LIGGGHTS, MercuryDPM, Yade, MFiX, Chrono) build a damped Hertz
!> contact  m zeta'' = -k zeta^(3/2) - d zeta^q zeta'  from their own input keywords
!> (doc/peers.md; one row per engine, version, option and contact end in
!> data/peers/peers_spec.csv, embedded as hertzdamp_check_data).  This module holds,
!> for each row, the engine's formula for its damping parameter (`peer_damping`, one
!> COEF_* case per formula, each citing its source), its inverse (`peer_parameter`),
!> and the evaluation of a resolved deck (`peer_deck`, filled by hertzdamp_check_deck)
!> at an impact speed: alpha, e, T_c, the time at which the total force turns
!> attractive, the elastic Hertz time, the engine's own contact-time estimate, and the
!> value of the engine's parameter that gives a target e (`peer_evaluate`).
!>
!> The law q and the contact end of a row are read from the specification, never
!> restated here; the test test/unit/test_peers.f90 checks every COEF_* formula against the
!> row's `alpha_expr`, evaluated by an independent expression evaluator.
!>
!> The numbers come from the library: its fitted maps of every law and contact end,
!> e(alpha), tau_c(alpha) (`peer_law_forward`; the reference integrator beyond the
!> fitted range) and alpha(e) (`peer_law_inverse`).  A quantity that double precision
!> cannot hold is never returned as inf: the point gets HD_OUT_OF_RANGE (its own
!> results) or NaN with a status (the engine's estimate, the corrected parameter).
module hertzdamp_check_model
    use hertzdamp, only: hertzdamp_rk, hertzdamp_collision, hertzdamp_forward_alpha, hertzdamp_invert_alpha, &
                         hertzdamp_tau_c0, hertzdamp_law_q, hertzdamp_law_has_alpha_c, hertzdamp_law_alpha_c, &
                         hertzdamp_pi, &
                         HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO, HD_METHOD_FIT, HD_METHOD_RK45, &
                         HD_OK, HD_NO_REBOUND, HD_BAD_ARGUMENT, HD_BAD_ALPHA, &
                         HD_OUT_OF_RANGE, HD_OUTSIDE_VALIDITY, HD_END_OVERLAP, HD_END_FORCE, hertzdamp_end_name, &
                         hertzdamp_fit_law_e_min_forward
    use hertzdamp_check_data, only: peer_spec_field, peer_spec_row, peer_spec_count
    use hertzdamp_text_list, only: text_string
    use hertzdamp_text_format, only: fmt_short, ROUND_TRIP
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, ieee_is_finite
    use, intrinsic :: iso_fortran_env, only: real32
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk
    real(wp), parameter :: pi = hertzdamp_pi

    !> The engines (their names, keys and readers: hertzdamp_check_engines).
    integer, parameter, public :: PEER_LAMMPS = 1, PEER_LIGGGHTS = 2, PEER_MERCURYDPM = 3, PEER_YADE = 4, &
                                  PEER_MFIX = 5, PEER_CHRONO = 6

    !> How the deck's damping parameter p gives the damping of the model.  For the
    !> q = 1/4 kinds the result is gamma (d = gamma sqrt(m k), so alpha = gamma); for the
    !> others it is d [kg s^-1, or the units that make d zeta^q zeta' a force].
    integer, parameter, public :: COEF_D = 1               !! d = p
    integer, parameter, public :: COEF_D_MASS = 2          !! d = p m
    integer, parameter, public :: COEF_D_MASS_SQRT_R = 3   !! d = p m sqrt(R)
    integer, parameter, public :: COEF_D_MASS_R = 4        !! d = p m R
    integer, parameter, public :: COEF_D_BETA_MASSARG = 5  !! d = beta(p) sqrt(2 mass_arg E)
    integer, parameter, public :: COEF_GAMMA = 6           !! gamma = p
    integer, parameter, public :: COEF_GAMMA_P6 = 7        !! gamma = P6(p)
    integer, parameter, public :: COEF_GAMMA_SQRT2_P6 = 8  !! gamma = sqrt(2) P6(p)
    integer, parameter, public :: COEF_GAMMA_SQRT5_BETA = 9 !! gamma = sqrt(5) beta(p)
    integer, parameter, public :: COEF_GAMMA_2BETA = 10    !! gamma = 2 beta(p)
    integer, parameter, public :: COEF_GAMMA_SQRT6 = 11    !! gamma = sqrt(6) p
    integer, parameter, public :: COEF_GAMMA_SQRT5_BETA_EPS = 12 !! gamma = sqrt(5) beta(max(p, eps_d))
    integer, parameter, public :: COEF_GAMMA_SQRT6_THORNTON = 13 !! gamma = sqrt(6) betan_T(p), Thornton et al. 2013
    integer, parameter, public :: COEF_D_YADE_VN = 14      !! d = V*(p)^2 vn^(-1/5) k^(3/5) m^(2/5), Pade(V*) = p

    !> The decreasing functions bisect_decreasing inverts.
    integer, parameter :: FN_P6 = 1, FN_THORNTON = 2, FN_PADE = 3

    !> The engines' own contact-time estimates (doc/peers.md).
    integer, parameter, public :: TSTEP_NONE = 0
    integer, parameter, public :: TSTEP_LIGGGHTS = 1  !! fix check/timestep/gran: 2.87 (m_p^2/(r/2 Y*^2 v))^(1/5)
    integer, parameter, public :: TSTEP_MERCURY = 2   !! getCollisionTime: 2.214 (rho^2/(E^2 v))^(1/5) D
    integer, parameter, public :: TSTEP_MFIX = 3      !! TCOLL = pi / sqrt(k/m - (eta/m)^2/4)

    !> A peer's contact resolved to the model: filled by hertzdamp_check_deck.
    type, public :: peer_deck
        integer :: peer = 0                 !! PEER_*
        integer :: release = 0              !! the engine's release whose formulas apply (LAMMPS_*, YADE_*)
        integer :: row = 0                  !! row of the specification (hertzdamp_check_data)
        integer :: law = HD_DAMPING_LINEAR    !! PEER_LAW_*, from the row's q
        integer :: iend = HD_END_OVERLAP    !! from the row's end
        integer :: coef = 0                 !! COEF_*
        real(wp) :: p = 0.0_wp              !! the deck's damping parameter, as the engine stores it
        character(len=:), allocatable :: p_name  !! its name in the engine's terms
        character(len=:), allocatable :: p_template !! the deck's damping input with {} for the value
        real(wp) :: mass_arg = 0.0_wp       !! COEF_D_BETA_MASSARG: the mass argument
        real(wp) :: modulus_arg = 0.0_wp    !! COEF_D_BETA_MASSARG: the modulus passed as a stiffness
        real(wp) :: vn = 0.0_wp             !! COEF_D_YADE_VN: Yade's vn, the speed at which e = en
        real(wp) :: e_deck = -1.0_wp        !! restitution coefficient written in the deck (< 0: none)
        real(wp) :: m = 0.0_wp              !! effective mass of the dynamics [kg]
        real(wp) :: m_damp = 0.0_wp         !! effective mass the damping formula uses [kg] (Chrono wall)
        real(wp) :: radius = 0.0_wp         !! effective radius the stiffness uses [m]
        real(wp) :: k = 0.0_wp              !! Hertz stiffness, F = k zeta^(3/2) [N m^-3/2]
        real(wp) :: e_star = 0.0_wp         !! effective modulus of the engine, when it uses one [Pa]
        real(wp) :: mass1 = 0.0_wp          !! mass of body 1 [kg]
        real(wp) :: radius1 = 0.0_wp        !! radius of body 1 [m]
        real(wp) :: density1 = 0.0_wp       !! density of body 1 [kg m^-3]
        logical :: wall = .false.           !! body 2 is a wall
        integer :: tstep = TSTEP_NONE       !! the engine's contact-time estimate, TSTEP_*
        real(wp) :: dt_factor = 0.0_wp      !! MFiX DTSOLID_FACTOR
        character(len=:), allocatable :: version  !! release label (LAMMPS) or ''
        character(len=:), allocatable :: deck_text !! the deck as understood, one line
        character(len=:), allocatable :: k_text   !! how the engine builds k
        type(text_string), allocatable :: notes(:)  !! remarks on the deck (version, geometry, ...)
    end type peer_deck

    !> The deck at one impact speed.  Quantities that do not apply, or that double
    !> precision cannot hold, are NaN; every other value is finite but tc = +inf of a
    !> point without rebound.
    type, public :: peer_point
        real(wp) :: u = 0.0_wp          !! impact speed [m s^-1]
        real(wp) :: alpha = 0.0_wp      !! damping parameter of the model
        real(wp) :: tstar = 0.0_wp      !! time unit t* [s]
        real(wp) :: e = 0.0_wp          !! achieved restitution coefficient
        real(wp) :: e_error = 0.0_wp    !! e/e_target - 1
        real(wp) :: tc = 0.0_wp         !! contact time [s] (+inf: no rebound)
        real(wp) :: t_force = 0.0_wp    !! overlap end: time at which the total force turns attractive [s]
        real(wp) :: t_hertz = 0.0_wp    !! elastic Hertz contact time tau_c(0) t* [s]
        real(wp) :: t_peer = 0.0_wp     !! the engine's own contact-time estimate [s]
        real(wp) :: alpha_target = 0.0_wp !! alpha that gives the target e
        real(wp) :: p_corrected = 0.0_wp !! the engine's parameter that gives the target e
        integer :: method = 0           !! HD_METHOD_FIT or HD_METHOD_RK45: what gave e and tc (0: neither)
        integer :: status = HD_OK       !! HD_OK, HD_NO_REBOUND or why the point has no result
                                        !! (HD_OUT_OF_RANGE: alpha, t*, tc, t_hertz or e_error
                                        !! beyond double precision; an error of the forward map)
        integer :: status_corrected = HD_OK !! HD_OK, or why there is no corrected parameter
        character(len=:), allocatable :: beyond  !! HD_OUT_OF_RANGE: the quantity beyond double precision
    end type peer_point

    public :: peer_law_forward, peer_law_inverse
    public :: peer_beta, peer_beta_inverse, peer_p6, peer_p6_inverse, peer_thornton, peer_thornton_inverse
    public :: peer_pade_mp, peer_pade_mp_inverse
    public :: peer_damping, peer_parameter, peer_alpha, peer_evaluate, peer_time_estimate
    public :: peer_row_law, peer_row_end, peer_row_coef, peer_nan, peer_float
    public :: peer_spec_field, peer_spec_row, peer_spec_count

contains

    ! ------------------------------------------------------------------ laws

    !> The law of a specification row, from its q column; -1 if the row is unknown.
    pure integer function peer_row_law(row) result(law)
        integer, intent(in) :: row   !! row of the specification
        select case (peer_spec_field(row, 'q'))
        case ('0'); law = HD_DAMPING_LINEAR
        case ('1/4'); law = HD_DAMPING_TSUJI
        case ('1/2'); law = HD_DAMPING_KUWABARA_KONO
        case default; law = -1
        end select
    end function peer_row_law

    !> The contact end of a specification row, from its end column; -1 if unknown.
    pure integer function peer_row_end(row) result(iend)
        integer, intent(in) :: row   !! row of the specification
        do iend = HD_END_OVERLAP, HD_END_FORCE
            if (peer_spec_field(row, 'end') == hertzdamp_end_name(iend)) return
        end do
        iend = -1
    end function peer_row_end

    !> The formula (COEF_*) of a specification row: how the engine's damping parameter
    !> gives gamma or d.  This table and peer_damping implement the rows' alpha_expr;
    !> test/unit/test_peers.f90 checks them against it.  0 for an unknown row.
    pure integer function peer_row_coef(row) result(coef)
        integer, intent(in) :: row   !! row of the specification
        select case (peer_spec_field(row, 'id'))
        case ('lammps-2021-velocity-overlap', 'lammps-2021-velocity-force', 'lammps-2023-velocity-overlap', &
              'lammps-2023-velocity-force', 'mercurydpm2015-dissipation-overlap')
            coef = COEF_D
        case ('lammps-2021-mass_velocity-overlap', 'lammps-2021-mass_velocity-force', &
              'lammps-2023-mass_velocity-overlap', 'lammps-2023-mass_velocity-force')
            coef = COEF_D_MASS
        case ('lammps-2021-viscoelastic-overlap', 'lammps-2021-viscoelastic-force', 'lammps-2023-viscoelastic-overlap', &
              'lammps-2023-viscoelastic-force', 'liggghts-hertz_stiffness-overlap', 'liggghts-hertz_stiffness-force', &
              'lammps-hertz_history-overlap', 'lammps-hertz_history-force')
            coef = COEF_D_MASS_SQRT_R
        case ('chrono-kn_gn-force')
            coef = COEF_D_MASS_R
        case ('mercurydpm2015-stiffness_restitution-overlap')
            coef = COEF_D_BETA_MASSARG
        case ('mercurydpm-dissipation-overlap')
            coef = COEF_GAMMA
        case ('lammps-2021-tsuji-overlap', 'lammps-2021-tsuji-force', 'lammps-2023-tsuji-overlap', &
              'lammps-2023-tsuji-force')
            coef = COEF_GAMMA_P6
        case ('lammps-current-tsuji-overlap', 'lammps-current-tsuji-force')
            coef = COEF_GAMMA_SQRT2_P6
        case ('lammps-2024-coeff_restitution-overlap', 'lammps-2024-coeff_restitution-force', &
              'liggghts-hertz-overlap', 'liggghts-hertz-force', 'mercurydpm-restitution-overlap', 'yade-en-force')
            coef = COEF_GAMMA_SQRT5_BETA
        case ('mfix-hertzian-overlap')
            coef = COEF_GAMMA_2BETA
        case ('yade-betan-force')
            coef = COEF_GAMMA_SQRT6
        case ('chrono-material-force')
            coef = COEF_GAMMA_SQRT5_BETA_EPS
        case ('yade2023-en-force')
            coef = COEF_GAMMA_SQRT6_THORNTON
        case ('yade2024-vn-force')
            coef = COEF_D_YADE_VN
        case default
            coef = 0
        end select
    end function peer_row_coef

    !> e(alpha) and tau_c(alpha) of a law and contact end: the library's fitted forward
    !> map (hertzdamp_forward_alpha with HD_METHOD_FIT), and its reference integrator
    !> (HD_METHOD_RK45) beyond the fitted range (the fit gives HD_OUTSIDE_VALIDITY there,
    !> or, linear overlap end, e below 1e-5 from its extrapolation towards alpha_c).
    !> alpha beyond what any method takes (hertzdamp_alpha_max): HD_OUTSIDE_VALIDITY.
    pure subroutine peer_law_forward(law, alpha, iend, e, tau_c, status, method)
        integer, intent(in) :: law       !! HD_DAMPING_*
        real(wp), intent(in) :: alpha    !! damping parameter, >= 0
        integer, intent(in) :: iend      !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out) :: e       !! restitution coefficient (0: no rebound)
        real(wp), intent(out) :: tau_c   !! contact duration in units of t* (+inf: no rebound)
        integer, intent(out) :: status   !! HD_OK, HD_NO_REBOUND or an error
        integer, intent(out), optional :: method  !! HD_METHOD_FIT or HD_METHOD_RK45: the one used
        type(hertzdamp_collision) :: r
        integer :: used
        used = HD_METHOD_FIT
        r = hertzdamp_forward_alpha(alpha, iend, HD_METHOD_FIT, law=law)
        if (r%status == HD_OUTSIDE_VALIDITY .or. (r%status == HD_OK .and. r%e < hertzdamp_fit_law_e_min_forward)) then
            used = HD_METHOD_RK45
            r = hertzdamp_forward_alpha(alpha, iend, HD_METHOD_RK45, law=law)
        end if
        status = r%status
        ! a finite alpha the integrator refuses (beyond hertzdamp_alpha_max): no method has it
        if (status == HD_BAD_ALPHA .and. alpha >= 0.0_wp .and. alpha <= huge(alpha)) status = HD_OUTSIDE_VALIDITY
        e = r%e
        tau_c = r%tau_c
        if (present(method)) method = used
    end subroutine peer_law_forward

    !> alpha(e) of a law and contact end: the library's fitted inverse
    !> (hertzdamp_invert_alpha with HD_METHOD_FIT and the law).  Targets outside its
    !> range (hertzdamp_fit_law_e_min) give HD_BAD_RESTITUTION.
    pure subroutine peer_law_inverse(law, e, iend, alpha, status)
        integer, intent(in) :: law       !! HD_DAMPING_*
        real(wp), intent(in) :: e        !! target restitution coefficient
        integer, intent(in) :: iend      !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out) :: alpha   !! damping parameter
        integer, intent(out) :: status   !! HD_OK or an error (HD_BAD_RESTITUTION: e outside the range)
        real(wp) :: tau
        call hertzdamp_invert_alpha(e, iend, alpha, tau, status, method=HD_METHOD_FIT, law=law)
    end subroutine peer_law_inverse

    ! ------------------------------------------------------------------ formulas of the engines

    !> beta(e) = -ln e / sqrt(pi^2 + ln^2 e) for 0 < e <= 1; beta(0) = 1 (the limit).
    pure elemental real(wp) function peer_beta(e) result(b)
        real(wp), intent(in) :: e   !! restitution coefficient, 0 <= e <= 1
        real(wp) :: l
        if (e <= 0.0_wp) then
            b = 1.0_wp
        else
            l = -log(e)
            b = l / sqrt(pi**2 + l**2)
        end if
    end function peer_beta

    !> The e with beta(e) = b, 0 <= b <= 1: e = exp(-pi b / sqrt(1 - b^2)) (b = 1: e = 0).
    pure elemental real(wp) function peer_beta_inverse(b) result(e)
        real(wp), intent(in) :: b   !! beta value, 0 <= b <= 1
        if (b >= 1.0_wp) then
            e = 0.0_wp
        else
            e = exp(-pi * b / sqrt((1.0_wp - b) * (1.0_wp + b)))
        end if
    end function peer_beta_inverse

    !> LAMMPS's `tsuji` polynomial (Marshall 2009, eq. 53, as coded in
    !> src/GRANULAR/pair_granular.cpp:986-992 of LAMMPS 29 Sep 2021).
    pure elemental real(wp) function peer_p6(e) result(p)
        real(wp), intent(in) :: e   !! restitution coefficient
        p = 1.2728_wp - 4.2783_wp * e + 11.087_wp * e**2 - 22.348_wp * e**3 + 27.467_wp * e**4 &
            - 18.022_wp * e**5 + 4.8218_wp * e**6
    end function peer_p6

    !> The e in [0, 1] with P6(e) = g (P6 falls strictly on [0, 1], from 1.2728 to 3e-4);
    !> status HD_OUTSIDE_VALIDITY when g lies outside [P6(1), P6(0)].
    pure subroutine peer_p6_inverse(g, e, status)
        real(wp), intent(in) :: g       !! value of the polynomial
        real(wp), intent(out) :: e      !! its root in [0, 1]
        integer, intent(out) :: status  !! HD_OK or HD_OUTSIDE_VALIDITY
        e = 0.0_wp
        status = HD_OK
        if (.not. (g <= peer_p6(0.0_wp) .and. g >= peer_p6(1.0_wp))) then
            status = HD_OUTSIDE_VALIDITY
            return
        end if
        e = bisect_decreasing(FN_P6, g, 0.0_wp, 1.0_wp)
    end subroutine peer_p6_inverse

    !> The x in [lo, hi] where a decreasing function (FN_*) equals y, by bisection to
    !> the last bit.
    pure real(wp) function bisect_decreasing(fn, y, lo0, hi0) result(x)
        integer, intent(in) :: fn         !! FN_P6, FN_THORNTON or FN_PADE
        real(wp), intent(in) :: y, lo0, hi0
        real(wp) :: lo, hi, mid, f
        integer :: i
        lo = lo0
        hi = hi0
        do i = 1, 400
            mid = 0.5_wp * (lo + hi)
            if (mid <= lo .or. mid >= hi) exit
            select case (fn)
            case (FN_P6); f = peer_p6(mid)
            case (FN_THORNTON); f = peer_thornton(mid)
            case default; f = peer_pade_mp(mid)
            end select
            if (f > y) then
                lo = mid
            else
                hi = mid
            end if
        end do
        x = 0.5_wp * (lo + hi)
    end function bisect_decreasing

    !> Yade's betan from en since 2023.02a: Thornton et al. (2013), eq. (B6) with the fit
    !> (B7) of their Table 2 (HertzMindlin.cpp, Ip2_FrictMat_FrictMat_MindlinPhys::go):
    !> betan = sqrt(1/(1 - (1+e)^2 exp(a)) - 1), a = e (h1 + e (h2 + ... + e h10));
    !> betan(1) = 0.  Defined for 0 < e <= 1 (+huge where the radicand's denominator is 0).
    pure elemental real(wp) function peer_thornton(e) result(b)
        real(wp), intent(in) :: e   !! restitution coefficient, 0 < e <= 1
        real(wp), parameter :: h(10) = [-6.918798_wp, -16.41105_wp, 146.8049_wp, -796.4559_wp, 2928.711_wp, &
                                        -7206.864_wp, 11494.29_wp, -11342.18_wp, 6276.757_wp, -1489.915_wp]
        real(wp) :: a, w
        integer :: i
        if (e >= 1.0_wp) then
            b = 0.0_wp
            return
        end if
        a = h(10)
        do i = 9, 1, -1
            a = h(i) + e * a
        end do
        a = e * a
        w = 1.0_wp - (1.0_wp + e)**2 * exp(a)
        if (w > 0.0_wp) then
            b = sqrt(max(0.0_wp, 1.0_wp / w - 1.0_wp))
        else
            b = huge(1.0_wp)
        end if
    end function peer_thornton

    !> The e in (0, 1] with peer_thornton(e) = b, by bisection (betan falls from +inf at
    !> e -> 0 to 0 at e = 1); HD_OUTSIDE_VALIDITY for b < 0.
    pure subroutine peer_thornton_inverse(b, e, status)
        real(wp), intent(in) :: b       !! betan, >= 0
        real(wp), intent(out) :: e      !! en
        integer, intent(out) :: status  !! HD_OK or HD_OUTSIDE_VALIDITY
        e = 1.0_wp
        status = HD_OK
        if (.not. b >= 0.0_wp) then
            status = HD_OUTSIDE_VALIDITY
            return
        end if
        if (b == 0.0_wp) return
        e = bisect_decreasing(FN_THORNTON, b, 0.0_wp, 1.0_wp)
        if (.not. e > 0.0_wp) status = HD_OUTSIDE_VALIDITY
    end subroutine peer_thornton_inverse

    !> The Mueller-Poeschel (2011) [3/6] Pade of the restitution coefficient of
    !> viscoelastic (Kuwabara-Kono) spheres, as Yade codes it (HertzMindlin.cpp,
    !> restitutionCoefficient): e = A(v)/B(v) with v = V* (u/vn)^(1/10).
    pure elemental real(wp) function peer_pade_mp(v) result(e)
        real(wp), intent(in) :: v   !! the normalised speed V*, >= 0
        real(wp), parameter :: a(0:3) = [1.0_wp, 1.07232_wp, 0.574198_wp, 0.141552_wp]
        real(wp), parameter :: b(0:6) = [1.0_wp, 1.07232_wp, 1.72765_wp, 1.37842_wp, 1.19449_wp, 0.467273_wp, &
                                         0.235585_wp]
        real(wp) :: pa, pb
        integer :: i
        pa = a(3)
        do i = 2, 0, -1
            pa = a(i) + v * pa
        end do
        pb = b(6)
        do i = 5, 0, -1
            pb = b(i) + v * pb
        end do
        e = pa / pb
    end function peer_pade_mp

    !> The V* >= 0 with peer_pade_mp(V*) = e (Yade's getVstar solves the same equation by
    !> Newton's method), by bisection on the decreasing Pade; 0 for e >= 1, +huge for e <= 0.
    pure elemental real(wp) function peer_pade_mp_inverse(e) result(v)
        real(wp), intent(in) :: e   !! restitution coefficient
        real(wp) :: hi
        v = 0.0_wp
        if (e >= 1.0_wp) return
        v = huge(1.0_wp)
        if (.not. e > 0.0_wp) return
        hi = 1.0_wp
        do while (peer_pade_mp(hi) > e .and. hi < 1.0e100_wp)
            hi = 2.0_wp * hi
        end do
        v = bisect_decreasing(FN_PADE, e, 0.0_wp, hi)
    end function peer_pade_mp_inverse

    !> A value as an engine that stores it in single precision (C++ float) sees it.
    pure elemental real(wp) function peer_float(x) result(y)
        real(wp), intent(in) :: x   !! the value given
        y = real(real(x, real32), wp)
    end function peer_float

    !> A quiet NaN (for quantities that do not apply; printed as nan / null).
    pure real(wp) function peer_nan()
        peer_nan = ieee_value(0.0_wp, ieee_quiet_nan)
    end function peer_nan

    !> The damping the engine builds from its parameter p: gamma for the q = 1/4 kinds,
    !> d for the others (see COEF_*).  Formulas and sources: doc/peers.md and the
    !> alpha_expr of each row of data/peers/peers_spec.csv.
    pure real(wp) function peer_damping(deck, p) result(c)
        type(peer_deck), intent(in) :: deck   !! the resolved deck (m_damp, radius, mass_arg, ...)
        real(wp), intent(in) :: p             !! the engine's damping parameter
        select case (deck%coef)
        case (COEF_D)
            ! LAMMPS `velocity`: F = -eta_n0 v_n (pair_granular.cpp:363-364, 2021);
            ! MercuryDPM 2015 setDissipation(d): F = ... - d v_n (HertzianViscoelasticInteraction.cc:86-88)
            c = p
        case (COEF_D_MASS)
            ! LAMMPS `mass_velocity`: F = -eta_n0 m v_n (pair_granular.cpp:365-366, 2021)
            c = p * deck%m_damp
        case (COEF_D_MASS_SQRT_R)
            ! LAMMPS `viscoelastic`: F = -eta_n0 m sqrt(R delta) v_n (pair_granular.cpp:351,367-368);
            ! LIGGGHTS hertz/stiffness: F = -sqrt(R delta) m gamma_n v_n (normal_model_hertz_stiffness.h:137-144)
            c = p * deck%m_damp * sqrt(deck%radius)
        case (COEF_D_MASS_R)
            ! Chrono UseMaterialProperties(false): gn_eff = R sqrt(delta) m gn (ChContactSMC.cpp:105-111)
            c = p * deck%m_damp * deck%radius
        case (COEF_D_BETA_MASSARG)
            ! MercuryDPM 2015 setStiffnessAndRestitutionCoefficient(k_, e, mass):
            ! dissipation_ = -sqrt(2 mass k_/(pi^2 + ln^2 e)) ln e (HertzianViscoelasticSpecies.cc:168-173)
            c = peer_beta(p) * sqrt(2.0_wp * deck%mass_arg * deck%modulus_arg)
        case (COEF_GAMMA)
            ! MercuryDPM setDissipation(g): F = ... - g sqrt(m k sqrt(delta)) v_n (HertzianViscoelasticInteraction.cc:125)
            c = p * sqrt(deck%m_damp / deck%m)
        case (COEF_GAMMA_P6)
            ! LAMMPS `tsuji` (2021 .. 2024-09): damp = P6(e), F = -damp sqrt(m kn a) v_n (pair_granular.cpp:986-992, 369-370)
            c = peer_p6(p) * sqrt(deck%m_damp / deck%m)
        case (COEF_GAMMA_SQRT2_P6)
            ! LAMMPS current `tsuji`: damp = sqrt(2) P6(e) (gran_sub_mod_damping.cpp @07b704ca:141-148)
            c = sqrt(2.0_wp) * peer_p6(p) * sqrt(deck%m_damp / deck%m)
        case (COEF_GAMMA_SQRT5_BETA)
            ! LAMMPS `coeff_restitution` sqrt(3/2) 2 sqrt(5/6) beta (gran_sub_mod_damping.cpp:162-172, 2024-09);
            ! LIGGGHTS 2 sqrt(5/6) beta sqrt(S_n m), S_n = (3/2) k delta^(1/2) (normal_model_hertz.h:231-237);
            ! MercuryDPM sqrt(5 ln^2 e/(ln^2 e + pi^2)) (HertzianViscoelasticNormalSpecies.cc:109-138);
            ! Yade en: 2 sqrt(5/6) beta sqrt(2 E sqrt(R)) sqrt(m) delta^(1/4) (HertzMindlin.cpp:76-80, 341-350)
            c = sqrt(5.0_wp) * peer_beta(p) * sqrt(deck%m_damp / deck%m)
        case (COEF_GAMMA_2BETA)
            ! MFiX DES_ETAN = 2 sqrt(k m) |ln e|/sqrt(pi^2 + ln^2 e), e = 0: 2 sqrt(k m)
            ! (check_solids_dem.f:904-911), applied as DES_ETAN delta^(1/4) (calc_force_dem.f:224-242)
            c = 2.0_wp * peer_beta(p) * sqrt(deck%m_damp / deck%m)
        case (COEF_GAMMA_SQRT6)
            ! Yade betan: cn = 2 betan sqrt(m (3/2) Kno delta^(1/2)) (HertzMindlin.cpp:309, 323-336)
            c = sqrt(6.0_wp) * p * sqrt(deck%m_damp / deck%m)
        case (COEF_GAMMA_SQRT5_BETA_EPS)
            ! Chrono: e < DBL_EPSILON -> ln(DBL_EPSILON); gn = -2 sqrt(5/6) beta sqrt(Sn m) (ChContactSMC.cpp:94-104)
            c = sqrt(5.0_wp) * peer_beta(max(p, epsilon(1.0_wp))) * sqrt(deck%m_damp / deck%m)
        case (COEF_GAMMA_SQRT6_THORNTON)
            ! Yade 2023.02a+ en: betan = Thornton (2013) eq. (B6)-(B7), cn = 2 betan sqrt(m (3/2) Kno delta^(1/2))
            ! (HertzMindlin.cpp, Ip2_FrictMat_FrictMat_MindlinPhys::go and Law2_ScGeom_MindlinPhys_Mindlin::go)
            c = sqrt(6.0_wp) * peer_thornton(p) * sqrt(deck%m_damp / deck%m)
        case (COEF_D_YADE_VN)
            ! Yade 2024.02a+ en with vn: beta = V*^2 vn^(-1/5), cn = (2/3) beta (Kno/m)^(-2/5) kn with
            ! kn = (3/2) Kno delta^(1/2): d = beta Kno^(3/5) m^(2/5) on delta^(1/2) delta' (HertzMindlin.cpp)
            c = peer_pade_mp_inverse(p)**2 * exp(-0.2_wp * log(deck%vn) + 0.6_wp * log(deck%k) + &
                                                 0.4_wp * log(deck%m_damp))
        case default
            c = 0.0_wp
        end select
    end function peer_damping

    !> The engine's parameter p that gives the damping c (gamma or d, see peer_damping):
    !> the inverse of peer_damping.  status HD_OUTSIDE_VALIDITY when no value of p does,
    !> HD_OUT_OF_RANGE when the value is beyond double precision (infinite, or zero for
    !> a positive c).
    pure subroutine peer_parameter(deck, c, p, status)
        type(peer_deck), intent(in) :: deck   !! the resolved deck
        real(wp), intent(in) :: c             !! gamma (q = 1/4 kinds) or d, finite, >= 0
        real(wp), intent(out) :: p            !! the engine's parameter
        integer, intent(out) :: status        !! HD_OK, HD_OUTSIDE_VALIDITY or HD_OUT_OF_RANGE
        real(wp) :: g, f
        p = 0.0_wp
        status = HD_OK
        f = sqrt(deck%m_damp / deck%m)
        g = c / f     ! the gamma the engine's formula must produce
        select case (deck%coef)
        case (COEF_D)
            p = c
        case (COEF_D_MASS)
            p = c / deck%m_damp
        case (COEF_D_MASS_SQRT_R)
            p = c / (deck%m_damp * sqrt(deck%radius))
        case (COEF_D_MASS_R)
            p = c / (deck%m_damp * deck%radius)
        case (COEF_D_BETA_MASSARG)
            call beta_root(c / sqrt(2.0_wp * deck%mass_arg * deck%modulus_arg), p, status)
        case (COEF_GAMMA)
            p = g
        case (COEF_GAMMA_P6)
            call peer_p6_inverse(g, p, status)
        case (COEF_GAMMA_SQRT2_P6)
            call peer_p6_inverse(g / sqrt(2.0_wp), p, status)
        case (COEF_GAMMA_SQRT5_BETA, COEF_GAMMA_SQRT5_BETA_EPS)
            call beta_root(g / sqrt(5.0_wp), p, status)
        case (COEF_GAMMA_2BETA)
            call beta_root(g / 2.0_wp, p, status)
        case (COEF_GAMMA_SQRT6)
            p = g / sqrt(6.0_wp)
        case (COEF_GAMMA_SQRT6_THORNTON)
            call peer_thornton_inverse(g / sqrt(6.0_wp), p, status)
        case (COEF_D_YADE_VN)
            p = peer_pade_mp(sqrt(c * exp(0.2_wp * log(deck%vn) - 0.6_wp * log(deck%k) - 0.4_wp * log(deck%m_damp))))
            if (.not. p > 0.0_wp) status = HD_OUTSIDE_VALIDITY
        case default
            status = HD_BAD_ARGUMENT
        end select
        ! the scaled kinds (p proportional to c): an overflow, or an underflow to no damping
        if (status == HD_OK .and. .not. (ieee_is_finite(p) .and. (p > 0.0_wp .or. .not. c > 0.0_wp))) then
            p = 0.0_wp
            status = HD_OUT_OF_RANGE
        end if
    contains
        pure subroutine beta_root(b, e, st)
            real(wp), intent(in) :: b
            real(wp), intent(out) :: e
            integer, intent(out) :: st
            e = 0.0_wp
            st = HD_OK
            if (.not. (b >= 0.0_wp .and. b <= 1.0_wp)) then
                st = HD_OUTSIDE_VALIDITY
            else
                e = peer_beta_inverse(b)
            end if
        end subroutine beta_root
    end subroutine peer_parameter

    !> alpha of the deck at impact speed u, and the time unit t* = (m/(k u^(1/2)))^(2/5).
    !> q = 1/4: alpha = gamma (independent of u); otherwise alpha = d t* (u t*)^q / m.
    !> HD_OUT_OF_RANGE when alpha or t* is beyond double precision; `log_alpha`, ln alpha
    !> from the logarithms of the inputs (-huge for alpha = 0, and when the damping d
    !> itself overflows: unknown), tells an overdamped deck (no rebound) from one that is
    !> only beyond range.
    pure subroutine peer_alpha(deck, u, alpha, tstar, status, log_alpha)
        type(peer_deck), intent(in) :: deck  !! the resolved deck
        real(wp), intent(in) :: u            !! impact speed [m s^-1]
        real(wp), intent(out) :: alpha       !! damping parameter
        real(wp), intent(out) :: tstar       !! time unit [s]
        integer, intent(out) :: status       !! HD_OK or HD_OUT_OF_RANGE
        real(wp), intent(out), optional :: log_alpha  !! ln alpha
        real(wp) :: c, lt, q, la
        integer :: st
        lt = 0.4_wp * (log(deck%m) - log(deck%k)) - 0.2_wp * log(u)
        tstar = exp(lt)
        c = peer_damping(deck, deck%p)
        q = hertzdamp_law_q(deck%law)
        if (.not. (c > 0.0_wp .and. c <= huge(c))) then
            la = -huge(1.0_wp)
        else if (deck%law == HD_DAMPING_TSUJI) then
            la = log(c)
        else
            la = log(c) + lt + q * (log(u) + lt) - log(deck%m)
        end if
        if (deck%law == HD_DAMPING_TSUJI) then
            alpha = c
        else
            alpha = c * tstar * (u * tstar)**q / deck%m
        end if
        call from_log(alpha, la, c > 0.0_wp, st)
        status = HD_OK
        if (st /= HD_OK .or. .not. (ieee_is_finite(tstar) .and. tstar > 0.0_wp)) status = HD_OUT_OF_RANGE
        if (present(log_alpha)) log_alpha = la
    end subroutine peer_alpha

    !> A positive quantity computed directly (`x`) and as a logarithm (`lx`): when the
    !> direct form overflowed or underflowed in an intermediate, exp(lx) where double
    !> precision holds it; HD_OUT_OF_RANGE (x = NaN) where it does not.
    pure subroutine from_log(x, lx, positive, status)
        real(wp), intent(inout) :: x      !! the value computed directly
        real(wp), intent(in) :: lx        !! its logarithm
        logical, intent(in) :: positive   !! the exact value is > 0 (else x = 0 stands)
        integer, intent(out) :: status    !! HD_OK or HD_OUT_OF_RANGE
        status = HD_OK
        if (ieee_is_finite(x) .and. (x > 0.0_wp .or. .not. positive)) return
        if (lx < log(huge(1.0_wp)) .and. lx > log(tiny(1.0_wp))) then
            x = exp(lx)
        else
            x = peer_nan()
            status = HD_OUT_OF_RANGE
        end if
    end subroutine from_log

    !> The engine's own estimate of the contact time at impact speed u (NaN when the
    !> engine has none, or when double precision cannot hold it).  LIGGGHTS fix
    !> check/timestep/gran (fix_check_timestep_gran.cpp: 318-348): 2.87 (m_p^2/(r/2 Y*^2
    !> v))^(1/5) with the particle's whole mass m_p and radius r, v = max(2 v_max, v_max +
    !> v_mesh): u for two particles meeting at u, 2u for a particle hitting a resting wall
    !> at u.  MercuryDPM getCollisionTime(D, rho, v) (HertzianViscoelasticNormalSpecies.cc:
    !> 290-300): 2.214 (rho^2/(E^2 v))^(1/5) D.  MFiX TCOLL = pi/sqrt(k/m - (eta/m)^2/4)
    !> with its Hertz k and eta = gamma sqrt(m k) (check_solids_dem.f: 924-926, 990-991;
    !> independent of u; NaN where the root is imaginary), here as pi sqrt(m/k)/sqrt(1 -
    !> gamma^2/4).  The powers are taken of logarithms: E^2 and m_p^2 alone may overflow.
    pure real(wp) function peer_time_estimate(deck, u) result(t)
        type(peer_deck), intent(in) :: deck  !! the resolved deck
        real(wp), intent(in) :: u            !! impact speed [m s^-1]
        real(wp) :: v, g, w
        t = peer_nan()
        select case (deck%tstep)
        case (TSTEP_LIGGGHTS)
            v = merge(2.0_wp * u, u, deck%wall)
            t = 2.87_wp * exp(0.2_wp * (2.0_wp * log(deck%mass1) - log(0.5_wp) - log(deck%radius1) - &
                                        2.0_wp * log(deck%e_star) - log(v)))
        case (TSTEP_MERCURY)
            t = 2.214_wp * 2.0_wp * exp(0.4_wp * (log(deck%density1) - log(deck%e_star)) - 0.2_wp * log(u) + &
                                        log(deck%radius1))
        case (TSTEP_MFIX)
            g = peer_damping(deck, deck%p)
            w = 1.0_wp - 0.25_wp * g**2
            if (w > 0.0_wp) t = pi * exp(0.5_wp * (log(deck%m) - log(deck%k))) / sqrt(w)
        case default
        end select
        if (.not. (ieee_is_finite(t) .and. t > 0.0_wp)) t = peer_nan()
    end function peer_time_estimate

    !> The deck at impact speed u: what the engine achieves, and the value of its
    !> parameter that would give e_target (NaN with status_corrected /= HD_OK when
    !> none does).  An overdamped deck whose alpha double precision cannot hold has no
    !> rebound where the law has alpha_c and the contact ends with the overlap;
    !> otherwise a result beyond double precision gives HD_OUT_OF_RANGE.
    pure function peer_evaluate(deck, u, e_target) result(pt)
        type(peer_deck), intent(in) :: deck  !! the resolved deck
        real(wp), intent(in) :: u            !! impact speed [m s^-1], > 0
        real(wp), intent(in) :: e_target     !! the restitution coefficient the user wants, > 0
        type(peer_point) :: pt
        real(wp) :: tau, ef, tauf, la
        integer :: st
        pt%u = u
        pt%e = peer_nan()
        pt%e_error = peer_nan()
        pt%tc = peer_nan()
        pt%t_force = peer_nan()
        pt%t_hertz = peer_nan()
        pt%alpha_target = peer_nan()
        pt%p_corrected = peer_nan()
        pt%t_peer = peer_time_estimate(deck, u)
        call peer_alpha(deck, u, pt%alpha, pt%tstar, pt%status, la)
        if (pt%status == HD_OK) then
            call peer_law_forward(deck%law, pt%alpha, deck%iend, pt%e, tau, pt%status, pt%method)
        else if (hertzdamp_law_has_alpha_c(deck%law) .and. deck%iend == HD_END_OVERLAP .and. &
                 la > log(hertzdamp_law_alpha_c(deck%law)) + 1.0e-6_wp) then
            pt%status = HD_NO_REBOUND   ! alpha or t* beyond double precision, alpha beyond alpha_c
        end if
        if (.not. ieee_is_finite(pt%alpha)) pt%alpha = peer_nan()
        if (ieee_is_finite(pt%tstar) .and. pt%tstar > 0.0_wp) then
            pt%t_hertz = hertzdamp_tau_c0() * pt%tstar
        else
            pt%tstar = peer_nan()
        end if
        select case (pt%status)
        case (HD_OUT_OF_RANGE)
            pt%beyond = 'alpha or the time unit t* = (m/(k u^(1/2)))^(2/5)'
        case (HD_OK)
            pt%tc = pt%tstar * tau
            pt%e_error = pt%e / e_target - 1.0_wp
            if (.not. ieee_is_finite(pt%t_hertz)) then
                pt%beyond = 'the elastic Hertz time tau_c(0) t*'
            else if (.not. ieee_is_finite(pt%tc)) then
                pt%beyond = 'the contact time t_c = tau_c t*'
            else if (.not. ieee_is_finite(pt%e_error)) then
                pt%beyond = 'e/e_target - 1 (e = ' // fmt_short(pt%e, 6) // ', e_target = ' // &
                            fmt_short(e_target, ROUND_TRIP) // ')'
            end if
            if (allocated(pt%beyond)) pt%status = HD_OUT_OF_RANGE
        case (HD_NO_REBOUND)
            pt%e = 0.0_wp
            pt%e_error = -1.0_wp
            pt%tc = ieee_value(1.0_wp, ieee_positive_inf)
        case default
        end select
        if (pt%status /= HD_OK .and. pt%status /= HD_NO_REBOUND) then
            pt%e = peer_nan()
            pt%e_error = peer_nan()
            pt%tc = peer_nan()
            pt%status_corrected = pt%status
            return
        end if
        if (deck%iend == HD_END_OVERLAP .and. pt%alpha > 0.0_wp .and. ieee_is_finite(pt%t_hertz)) then
            ! the total force -d zeta^q zeta' - k zeta^(3/2) turns attractive where the
            ! force-end contact ends (the same trajectory up to that instant)
            call peer_law_forward(deck%law, pt%alpha, HD_END_FORCE, ef, tauf, st)
            if (st == HD_OK) pt%t_force = pt%tstar * tauf
            if (.not. ieee_is_finite(pt%t_force)) pt%t_force = peer_nan()
        end if
        call corrected(deck, u, e_target, pt)
    end function peer_evaluate

    !> The engine's parameter that gives e_target at the point's speed: alpha_target
    !> from the fitted inverse, the damping c = alpha_target (q = 1/4: gamma) or
    !> alpha_target m / (t* (u t*)^q) (d), then peer_parameter; HD_OUT_OF_RANGE when c or
    !> the parameter is beyond double precision.
    pure subroutine corrected(deck, u, e_target, pt)
        type(peer_deck), intent(in) :: deck       !! the resolved deck
        real(wp), intent(in) :: u, e_target       !! impact speed, target restitution
        type(peer_point), intent(inout) :: pt     !! the point (alpha_target, p_corrected, status_corrected)
        real(wp) :: c, q, lt
        integer :: st
        call peer_law_inverse(deck%law, e_target, deck%iend, pt%alpha_target, st)
        pt%status_corrected = st
        if (st /= HD_OK) then
            pt%alpha_target = peer_nan()
            return
        end if
        if (deck%law == HD_DAMPING_TSUJI) then
            c = pt%alpha_target
        else if (ieee_is_finite(pt%tstar)) then
            q = hertzdamp_law_q(deck%law)
            lt = log(pt%tstar)
            c = pt%alpha_target * deck%m / (pt%tstar * (u * pt%tstar)**q)
            if (pt%alpha_target > 0.0_wp) then
                call from_log(c, log(pt%alpha_target) + log(deck%m) - lt - q * (log(u) + lt), .true., st)
            end if
        else
            st = HD_OUT_OF_RANGE
        end if
        if (st == HD_OK) call peer_parameter(deck, c, pt%p_corrected, st)
        pt%status_corrected = st
        if (st /= HD_OK) pt%p_corrected = peer_nan()
    end subroutine corrected

end module hertzdamp_check_model
