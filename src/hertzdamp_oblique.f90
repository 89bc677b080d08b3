!> The oblique frictional contact: a sphere on a wall or on a second sphere, in the plane
!> of impact (doc/oblique.md).
!>
!> Normal force (every law and both ends of hertzdamp):  F_n = k delta^(3/2) + d delta^q delta'.
!> Tangential force, the models of LAMMPS `pair_style granular` (HD_TANGENTIAL_*):
!>   linear_history  F_t = -k_t xi - eta_t v_t,
!>   mindlin         F_t = -k_t a xi - eta_t v_t,  a = sqrt(R* delta),
!> with eta_t = x_gammat d delta^q (x_gammat times the normal damping coefficient), the
!> history xi carried along as the tangent plane turns (its length kept: in the plane of
!> impact its component along the tangent t is kept), d xi/dt = v_t while the contact
!> sticks, and the Coulomb limit |F_t| <= mu |F_n| on the total normal force (damping
!> included): while it slides, F_t = sigma mu |F_n| and the history is the one that gives
!> that force (LAMMPS's rescaling), xi = -(sigma mu |F_n| + eta_t v_t) / K.  v_t is the
!> relative tangential velocity of the contact point, v.t - (omega_1 R_1 + omega_2 R_2),
!> with the radii (as LAMMPS); the torque's lever arm is R (HD_LEVER_RADIUS) or R - delta/2
!> (HD_LEVER_CONTACT, LAMMPS's pairs).  Solid spheres: I = (2/5) m R^2.
!>
!> The relative motion is integrated in polar form (overlap delta, angle of the line of
!> centres phi, the relative velocity's normal and tangential parts), so that the line of
!> centres is recomputed continuously and no overlap is formed as a difference of
!> positions: with rho = R_1 + R_2 - delta,
!>   delta' = -u_n,  phi' = u_t / rho,  u_n' = F_n/m + u_t^2/rho,  u_t' = F_t/m - u_n u_t/rho,
!> (a wall: rho infinite).  Units: t* = (m / (k u_n^(1/2)))^(2/5) and u_n (the impact's
!> normal speed), so that the normal stiffness is 1 and the damping is alpha.
!>
!> Integrator: Dormand-Prince 5(4) with error control on every component; the events (the
!> release, the switches stick -> slip when |F_t| reaches mu |F_n| and slip -> stick when
!> the slip rate that keeps |F_t| = mu |F_n| changes sign) are located by the Illinois
!> method on exact sub-steps from the start of the accepted step (no dense output), and
!> the mode is switched there.  The slip rate is formed from the time derivatives of
!> mu |F_n|, K and eta_t v_t along the sliding motion (closed forms).  When the damping
!> alone exceeds the limit at the touch, mindlin (q < 1/2) starts in the forward slip,
!> the limit of LAMMPS's step as it vanishes (start_mode).  Error: see
!> doc/oblique.md (convergence study in the tolerance, and test/unit/test_oblique.f90
!> against an independent fixed-step solution).
!>
!> Everything is pure, no module state.
module hertzdamp_oblique
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: HD_OK, HD_NO_REBOUND, HD_MAX_STEPS, HD_BAD_TOL, HD_BAD_MASS, HD_BAD_VELOCITY, &
                                  HD_BAD_STIFFNESS, HD_BAD_DAMPING, HD_BAD_RADIUS, HD_BAD_LAW, HD_BAD_END, &
                                  HD_BAD_TANGENTIAL, HD_BAD_OBLIQUE, HD_NO_CONVERGENCE, HD_STEP_UNDERFLOW, &
                                  HD_END_OVERLAP, HD_END_FORCE, hertzdamp_min_end, hertzdamp_max_end, &
                                  HD_TANGENTIAL_LINEAR_HISTORY, HD_TANGENTIAL_MINDLIN, hertzdamp_min_tangential, &
                                  hertzdamp_max_tangential, HD_LEVER_RADIUS, HD_LEVER_CONTACT, &
                                  hertzdamp_min_lever, hertzdamp_max_lever, hertzdamp_law_q, HD_DAMPING_LINEAR
    use hertzdamp_laws, only: hertzdamp_law_status
    use hertzdamp_registry, only: HD_BAD_KPHYS, HD_BAD_MODULUS, HD_BAD_POISSON, HD_BAD_RESTITUTION
    use hertzdamp_constants, only: hertzdamp_pi
    use hertzdamp_pair, only: hertzdamp_invert
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Default relative and absolute tolerance of the oblique integrator (per step, in the
    !> units t*, u_n).
    real(wp), parameter, public :: hertzdamp_oblique_default_tol = 1.0e-12_wp

    !> An oblique contact: sphere 1 (the impacting one) on sphere 2, or on a wall when
    !> m2 = 0 and r2 = 0.  SI units.
    type, public :: hertzdamp_oblique_t
        real(wp) :: m1 = 0.0_wp       !! mass of sphere 1 [kg]
        real(wp) :: r1 = 0.0_wp       !! radius of sphere 1 [m]
        real(wp) :: m2 = 0.0_wp       !! mass of sphere 2 [kg] (0 with r2 = 0: a wall)
        real(wp) :: r2 = 0.0_wp       !! radius of sphere 2 [m] (0 with m2 = 0: a wall)
        real(wp) :: k = 0.0_wp        !! normal Hertz stiffness [N m^-3/2]
        real(wp) :: d = 0.0_wp        !! normal damping [kg s^-1 m^-q]
        integer :: law = HD_DAMPING_LINEAR          !! HD_DAMPING_*
        integer :: iend = HD_END_OVERLAP            !! HD_END_OVERLAP or HD_END_FORCE
        integer :: tangential = HD_TANGENTIAL_MINDLIN !! HD_TANGENTIAL_*
        real(wp) :: kt = 0.0_wp       !! tangential stiffness [N/m linear_history, N/m^2 mindlin]
        real(wp) :: xgammat = 0.0_wp  !! eta_t = xgammat * (normal damping coefficient)
        real(wp) :: mu = 0.0_wp       !! friction coefficient (0: frictionless)
        integer :: lever = HD_LEVER_RADIUS          !! HD_LEVER_*
    end type hertzdamp_oblique_t

    !> The outcome of an oblique impact (relative motion of sphere 1 against sphere 2).
    type, public :: hertzdamp_oblique_result
        real(wp) :: e_n = 0.0_wp            !! -u_n,out / u_n,in along the line of centres at touch / release
        real(wp) :: e_t = 0.0_wp            !! -v_c,out / v_c,in of the contact point (0 at a 0 angle)
        real(wp) :: vt_ratio = 0.0_wp       !! u_t,out / u_t,in of the centres (0 at a 0 angle)
        real(wp) :: rebound_angle = 0.0_wp  !! atan(u_t,out / u_n,out) [degrees]
        real(wp) :: omega1 = 0.0_wp         !! angular velocity of sphere 1 at release [rad/s]
        real(wp) :: omega2 = 0.0_wp         !! angular velocity of sphere 2 at release [rad/s] (wall: 0)
        real(wp) :: slide_fraction = 0.0_wp !! fraction of the contact time spent sliding
        real(wp) :: t_c = 0.0_wp            !! contact duration [s]
        real(wp) :: turn = 0.0_wp           !! angle the line of centres turned [degrees]
        integer :: switches = 0             !! stick-slip switches
        integer :: steps = 0                !! accepted steps
    end type hertzdamp_oblique_result

    ! the contact in the units t*, u_n, m (private)
    type :: scaled_t
        real(wp) :: alpha, q, ktp, xg, mu, rsum, r1, r2, i1, i2
        real(wp) :: etol = 0.0_wp   ! event location: bracket width where it stops (0: round-off)
        integer :: model, lever, iend
        logical :: wall
    end type scaled_t

    integer, parameter :: nst = 7
    integer, parameter :: stick = 1, slip = 2, frictionless = 3
    integer, parameter :: max_steps = 200000, max_switches = 1000
    ! the largest step (in t*) of the reference, and of the fast solves of the normal
    ! correction (tolerance fast_tol, events located to a bracket of fast_etol t*, the
    ! iteration stopped at |e_n - e| <= fast_stop; doc/oblique.md section 4)
    real(wp), parameter :: hmax_reference = 0.05_wp, hmax_fast = 0.5_wp
    real(wp), parameter :: fast_tol = 1.0e-6_wp, fast_stop = 1.0e-5_wp, fast_etol = 1.0e-7_wp

    public :: hertzdamp_oblique_impact, hertzdamp_oblique_status, hertzdamp_tangential_kt, hertzdamp_oblique_correct
    public :: hertzdamp_mindlin_kt

contains

    !> HD_OK for a valid contact, else the status naming the bad argument: HD_BAD_MASS,
    !> HD_BAD_RADIUS (a wall is m2 = r2 = 0), HD_BAD_STIFFNESS, HD_BAD_DAMPING, HD_BAD_LAW,
    !> HD_BAD_END, HD_BAD_TANGENTIAL (model, k_t, x_gammat, mu, lever arm).
    pure elemental integer function hertzdamp_oblique_status(c) result(status)
        type(hertzdamp_oblique_t), intent(in) :: c   !! the contact
        status = HD_OK
        if (.not. (c%m1 > 0.0_wp .and. c%m1 < huge(1.0_wp)) .or. &
            .not. (c%m2 >= 0.0_wp .and. c%m2 < huge(1.0_wp))) then
            status = HD_BAD_MASS
        else if (.not. (c%r1 > 0.0_wp .and. c%r1 < huge(1.0_wp)) .or. &
                 .not. (c%r2 >= 0.0_wp .and. c%r2 < huge(1.0_wp)) .or. &
                 ((c%m2 == 0.0_wp) .neqv. (c%r2 == 0.0_wp))) then
            status = HD_BAD_RADIUS
        else if (.not. (c%k > 0.0_wp .and. c%k < huge(1.0_wp))) then
            status = HD_BAD_STIFFNESS
        else if (.not. (c%d >= 0.0_wp .and. c%d < huge(1.0_wp))) then
            status = HD_BAD_DAMPING
        else if (hertzdamp_law_status(c%law) /= HD_OK) then
            status = HD_BAD_LAW
        else if (c%iend < hertzdamp_min_end .or. c%iend > hertzdamp_max_end) then
            status = HD_BAD_END
        else if (c%tangential < hertzdamp_min_tangential .or. c%tangential > hertzdamp_max_tangential .or. &
                 c%lever < hertzdamp_min_lever .or. c%lever > hertzdamp_max_lever .or. &
                 .not. (c%kt > 0.0_wp .and. c%kt < huge(1.0_wp)) .or. &
                 .not. (c%xgammat >= 0.0_wp .and. c%xgammat < huge(1.0_wp)) .or. &
                 .not. (c%mu >= 0.0_wp .and. c%mu < huge(1.0_wp))) then
            status = HD_BAD_TANGENTIAL
        end if
    end function hertzdamp_oblique_status

    !> The oblique impact of sphere 1 at `speed` and `angle` (degrees from the normal) on a
    !> wall or a sphere at rest, both without spin: its outcome, or a status (the contact's,
    !> HD_BAD_VELOCITY, HD_BAD_OBLIQUE for an angle outside [0, 90), HD_BAD_TOL outside
    !> [1e-14, 1e-3], HD_NO_REBOUND when the contact does not end (overlap end beyond the
    !> critical damping), HD_MAX_STEPS, HD_STEP_UNDERFLOW, HD_NO_CONVERGENCE for more than
    !> 1000 stick-slip switches).  On failure res is the zero result.
    pure elemental subroutine hertzdamp_oblique_impact(c, speed, angle, res, status, tol)
        type(hertzdamp_oblique_t), intent(in) :: c       !! the contact
        real(wp), intent(in) :: speed                    !! impact speed |v_in| [m/s]
        real(wp), intent(in) :: angle                    !! impact angle from the normal [degrees]
        type(hertzdamp_oblique_result), intent(out) :: res !! the outcome
        integer, intent(out) :: status                   !! HD_OK or an error code
        real(wp), intent(in), optional :: tol            !! tolerance (default hertzdamp_oblique_default_tol)
        real(wp) :: tl
        tl = hertzdamp_oblique_default_tol
        if (present(tol)) tl = tol
        call impact(c, speed, angle, tl, hmax_reference, 0.0_wp, res, status)
    end subroutine hertzdamp_oblique_impact

    !> hertzdamp_oblique_impact with the tolerance tl, the largest step hmax and the
    !> events located to a bracket of etol (in t*; 0: to round-off).
    pure subroutine impact(c, speed, angle, tl, hmax, etol, res, status)
        type(hertzdamp_oblique_t), intent(in) :: c
        real(wp), intent(in) :: speed, angle, tl, hmax, etol
        type(hertzdamp_oblique_result), intent(out) :: res
        integer, intent(out) :: status
        type(scaled_t) :: p
        real(wp) :: th, un, ut, tstar, meff
        real(wp) :: y(nst)
        res = hertzdamp_oblique_result()
        status = hertzdamp_oblique_status(c)
        if (status /= HD_OK) return
        if (.not. (speed > 0.0_wp .and. speed < huge(1.0_wp))) then
            status = HD_BAD_VELOCITY
            return
        end if
        if (.not. (angle >= 0.0_wp .and. angle < 90.0_wp)) then
            status = HD_BAD_OBLIQUE
            return
        end if
        if (.not. (tl >= 1.0e-14_wp .and. tl <= 1.0e-3_wp)) then
            status = HD_BAD_TOL
            return
        end if
        th = angle * hertzdamp_pi / 180.0_wp
        un = speed * cos(th)
        ut = speed * sin(th)
        call scale_contact(c, un, p, tstar, meff)
        p%etol = etol
        y = 0.0_wp
        y(3) = -1.0_wp
        y(4) = ut / un
        call integrate(p, y, tl, hmax, res, status)
        if (status /= HD_OK) then
            res = hertzdamp_oblique_result()
            return
        end if
        res%t_c = res%t_c * tstar
        res%omega1 = y(5) / (p%r1 * tstar)
        if (.not. p%wall) res%omega2 = y(6) / (p%r2 * tstar)
    end subroutine impact

    !> The contact in the units t* = (m / (k u_n^(1/2)))^(2/5), L = u_n t*, m (the effective mass).
    pure subroutine scale_contact(c, un, p, tstar, meff)
        type(hertzdamp_oblique_t), intent(in) :: c
        real(wp), intent(in) :: un
        type(scaled_t), intent(out) :: p
        real(wp), intent(out) :: tstar, meff
        real(wp) :: l, rstar
        p%wall = c%m2 == 0.0_wp
        if (p%wall) then
            meff = c%m1
            rstar = c%r1
        else
            meff = c%m1 * c%m2 / (c%m1 + c%m2)
            rstar = c%r1 * c%r2 / (c%r1 + c%r2)
        end if
        tstar = (meff / (c%k * sqrt(un)))**0.4_wp
        l = un * tstar
        p%q = hertzdamp_law_q(c%law)
        p%alpha = c%d * tstar * l**p%q / meff
        if (c%tangential == HD_TANGENTIAL_MINDLIN) then
            p%ktp = c%kt * sqrt(rstar * l) * tstar**2 / meff
        else
            p%ktp = c%kt * tstar**2 / meff
        end if
        p%model = c%tangential
        p%lever = c%lever
        p%iend = c%iend
        p%xg = c%xgammat
        p%mu = c%mu
        p%r1 = c%r1 / l
        ! i = m R^2 / I in units of meff: (omega R)' = -(lever / R) F_t i (the surface speed
        ! omega R is the state)
        p%i1 = meff / (0.4_wp * c%m1)
        if (p%wall) then
            p%r2 = 0.0_wp
            p%i2 = 0.0_wp
            p%rsum = huge(1.0_wp)
        else
            p%r2 = c%r2 / l
            p%i2 = meff / (0.4_wp * c%m2)
            p%rsum = p%r1 + p%r2
        end if
    end subroutine scale_contact

    !> The right-hand side in mode `mode` (stick, slip with sign sigma, frictionless), and
    !> the event functions ev = [release (> 0 in contact), |F_t| - mu |F_n| (stick),
    !> slip rate times sigma K (slip; >= 0 while it slides), F_n (its zero is the kink of
    !> mu |F_n|: a step ends there)], and the force F_t.
    !> State y = [delta, phi, u_n, u_t, omega_1 R_1, omega_2 R_2, xi].
    pure subroutine rhs(p, mode, sigma, y, dy, ev, ft)
        type(scaled_t), intent(in) :: p
        integer, intent(in) :: mode
        real(wp), intent(in) :: sigma, y(nst)
        real(wp), intent(out) :: dy(nst), ev(4), ft
        real(wp) :: z, zd, zq, fn, fc, curv, vt, kk, eta, l1, l2, zdd, fnp, fcp, kpk, etap, vtp, zqm
        z = max(y(1), 0.0_wp)
        zd = -y(3)
        zq = 1.0_wp
        zqm = 0.0_wp
        if (p%q > 0.0_wp) then
            zq = z**p%q
            if (z > 0.0_wp) zqm = p%q * zq / z
        end if
        fn = z * sqrt(z) + p%alpha * zq * zd
        fc = p%mu * abs(fn)
        curv = 0.0_wp
        if (.not. p%wall) curv = 1.0_wp / (p%rsum - y(1))
        vt = y(4) - (y(5) + y(6))
        kk = p%ktp
        if (p%model == HD_TANGENTIAL_MINDLIN) kk = p%ktp * sqrt(z)
        eta = p%xg * p%alpha * zq
        select case (mode)
        case (stick)
            ft = -kk * y(7) - eta * vt
        case (slip)
            ft = sigma * fc
        case default
            ft = 0.0_wp
        end select
        ! lever arm over radius (the state is the surface speed omega R)
        l1 = 1.0_wp
        l2 = 1.0_wp
        if (p%lever == HD_LEVER_CONTACT) then
            l1 = 1.0_wp - 0.5_wp * z / p%r1
            if (.not. p%wall) l2 = 1.0_wp - 0.5_wp * z / p%r2
        end if
        dy(1) = -y(3)
        dy(2) = y(4) * curv
        dy(3) = fn + y(4) * y(4) * curv
        dy(4) = ft - y(3) * y(4) * curv
        dy(5) = -l1 * ft * p%i1
        dy(6) = -l2 * ft * p%i2
        dy(7) = 0.0_wp
        if (mode == stick) dy(7) = vt
        ev(1) = y(1)
        if (p%iend == HD_END_FORCE) ev(1) = fn
        ev(2) = abs(ft) - fc
        ev(3) = 0.0_wp
        ev(4) = fn
        if (mode == slip) then
            ! d/dt of mu |F_n|, of K (as K'/K) and of eta_t v_t along the sliding motion
            zdd = -dy(3)
            fnp = 1.5_wp * sqrt(z) * zd + p%alpha * (zqm * zd * zd + zq * zdd)
            fcp = p%mu * sign(1.0_wp, fn) * fnp
            kpk = 0.0_wp
            if (p%model == HD_TANGENTIAL_MINDLIN .and. z > 0.0_wp) kpk = 0.5_wp * zd / z
            etap = p%xg * p%alpha * zqm * zd
            vtp = dy(4) - (dy(5) + dy(6))
            ev(3) = sigma * (-(sigma * fcp + etap * vt + eta * vtp) + (sigma * fc + eta * vt) * kpk - kk * vt)
        end if
    end subroutine rhs

    !> One Dormand-Prince 5(4) step of size h from y: the 5th-order solution and the
    !> error estimate (difference of the embedded pair).
    pure subroutine dp_step(p, mode, sigma, y, h, ynew, err)
        type(scaled_t), intent(in) :: p
        integer, intent(in) :: mode
        real(wp), intent(in) :: sigma, y(nst), h
        real(wp), intent(out) :: ynew(nst), err(nst)
        real(wp) :: k1(nst), k2(nst), k3(nst), k4(nst), k5(nst), k6(nst), k7(nst), ev(4), ft
        call rhs(p, mode, sigma, y, k1, ev, ft)
        call rhs(p, mode, sigma, y + h * (k1 / 5.0_wp), k2, ev, ft)
        call rhs(p, mode, sigma, y + h * (3.0_wp / 40 * k1 + 9.0_wp / 40 * k2), k3, ev, ft)
        call rhs(p, mode, sigma, y + h * (44.0_wp / 45 * k1 - 56.0_wp / 15 * k2 + 32.0_wp / 9 * k3), k4, ev, ft)
        call rhs(p, mode, sigma, y + h * (19372.0_wp / 6561 * k1 - 25360.0_wp / 2187 * k2 + &
                 64448.0_wp / 6561 * k3 - 212.0_wp / 729 * k4), k5, ev, ft)
        call rhs(p, mode, sigma, y + h * (9017.0_wp / 3168 * k1 - 355.0_wp / 33 * k2 + 46732.0_wp / 5247 * k3 + &
                 49.0_wp / 176 * k4 - 5103.0_wp / 18656 * k5), k6, ev, ft)
        ynew = y + h * (35.0_wp / 384 * k1 + 500.0_wp / 1113 * k3 + 125.0_wp / 192 * k4 - &
                        2187.0_wp / 6784 * k5 + 11.0_wp / 84 * k6)
        call rhs(p, mode, sigma, ynew, k7, ev, ft)
        err = h * ((35.0_wp / 384 - 5179.0_wp / 57600) * k1 + (500.0_wp / 1113 - 7571.0_wp / 16695) * k3 + &
                   (125.0_wp / 192 - 393.0_wp / 640) * k4 + (-2187.0_wp / 6784 + 92097.0_wp / 339200) * k5 + &
                   (11.0_wp / 84 - 187.0_wp / 2100) * k6 - 1.0_wp / 40 * k7)
    end subroutine dp_step

    !> The mode at the touch: the trial force of a sticking start against mu |F_n| a short
    !> time eps = 1e-7 t* after the touch (both vanish at the touch for most laws; their
    !> ratio has a limit there).
    !> When the damping alone exceeds the limit there (eta_t |v_t| > mu |F_n|, i.e.
    !> x_gammat |v_t| > mu u_n at the touch) with mindlin and q < 1/2, the contact slips
    !> FORWARD (sigma = sign v_t) from the touch: the sliding history
    !> xi = -(sigma mu |F_n| + eta_t v_t) / K of a backward slip is finite while K = k_t a
    !> grows from 0, so that K xi grows as a^1 = delta^(1/2) against mu |F_n| and eta_t,
    !> which grow as delta^q: it crosses from the backward to the forward limit between
    !> the overlaps delta_1 and r^(1/(1/2 - q)) delta_1, r = (x_gammat |v_t| + mu u_n) /
    !> (x_gammat |v_t| - mu u_n), for any first overlap delta_1 (LAMMPS's first step), i.e.
    !> at the touch in the limit of a vanishing step; once forward, the growing K xi keeps
    !> it there (doc/oblique.md section 3).  Integrating that layer from delta_1 -> 0 takes
    !> steps down to round-off (HD_STEP_UNDERFLOW before).  With q >= 1/2 the backward
    !> slip is the consistent one (K xi shrinks relative to the limit).
    pure subroutine start_mode(p, y, mode, sigma)
        type(scaled_t), intent(in) :: p
        real(wp), intent(in) :: y(nst)
        integer, intent(out) :: mode
        real(wp), intent(out) :: sigma
        real(wp), parameter :: eps = 1.0e-7_wp
        real(wp) :: yy(nst), dy(nst), ev(4), ft, vt, eta
        sigma = 1.0_wp
        if (p%mu == 0.0_wp) then
            mode = frictionless
            return
        end if
        yy = y
        yy(1) = eps
        yy(7) = (y(4) - y(5) - y(6)) * eps
        call rhs(p, stick, sigma, yy, dy, ev, ft)
        mode = stick
        if (ev(2) > 0.0_wp) then
            mode = slip
            sigma = sign(1.0_wp, ft)
            ! the damping alone over the limit (ev(2) + |F_t| = mu |F_n|)
            vt = yy(4) - (yy(5) + yy(6))
            eta = p%xg * p%alpha * yy(1)**p%q
            if (p%model == HD_TANGENTIAL_MINDLIN .and. p%q < 0.5_wp .and. eta * abs(vt) > abs(ft) - ev(2)) then
                sigma = sign(1.0_wp, vt)
            end if
        end if
    end subroutine start_mode

    !> Integrate from the touch to the release; fill res (dimensionless t_c) and leave the
    !> release state in y.
    pure subroutine integrate(p, y, tol, hmax, res, status)
        type(scaled_t), intent(in) :: p
        real(wp), intent(inout) :: y(nst)
        real(wp), intent(in) :: tol, hmax   ! hmax: the largest step (t*)
        type(hertzdamp_oblique_result), intent(inout) :: res
        integer, intent(out) :: status
        real(wp), parameter :: tmax = 2000.0_wp
        real(wp) :: t, h, ynew(nst), err(nst), en, sigma, ev0(4), ev1(4), dy(nst), ft, tslide, ut0, vc0, tau, hs
        integer :: mode, kind, nstep
        logical :: released
        status = HD_OK
        ut0 = y(4)
        vc0 = y(4) - y(5) - y(6)
        call start_mode(p, y, mode, sigma)
        t = 0.0_wp
        h = 1.0e-4_wp
        tslide = 0.0_wp
        nstep = 0
        released = .false.
        do while (.not. released)
            if (nstep >= max_steps) then
                status = HD_MAX_STEPS
                return
            end if
            if (t > tmax) then
                status = HD_NO_REBOUND
                return
            end if
            call dp_step(p, mode, sigma, y, h, ynew, err)
            en = maxval(abs(err) / (tol + tol * max(abs(y), abs(ynew))))
            if (.not. (en <= 1.0_wp)) then
                h = h * max(0.1_wp, 0.9_wp * en**(-0.2_wp))
                if (h < 1.0e-15_wp * max(t, 1.0_wp)) then
                    status = HD_STEP_UNDERFLOW
                    return
                end if
                cycle
            end if
            nstep = nstep + 1
            call rhs(p, mode, sigma, y, dy, ev0, ft)
            call rhs(p, mode, sigma, ynew, dy, ev1, ft)
            call first_event(p, mode, sigma, y, h, t, ev0, ev1, tau, kind)
            hs = h
            if (kind > 0) then
                hs = tau
                if (tau < h) call dp_step(p, mode, sigma, y, tau, ynew, err)
            end if
            if (mode /= stick) tslide = tslide + hs
            t = t + hs
            y = ynew
            select case (kind)
            case (1)
                released = .true.
            case (2)
                call rhs(p, mode, sigma, y, dy, ev1, ft)
                sigma = sign(1.0_wp, ft)
                mode = slip
                res%switches = res%switches + 1
            case (3)
                call to_stick(p, sigma, y)
                mode = stick
                res%switches = res%switches + 1
            case default
                ! no event, or F_n = 0 (the step only stops there)
            end select
            if (res%switches > max_switches) then
                status = HD_NO_CONVERGENCE
                return
            end if
            h = min(hmax, hs * min(5.0_wp, max(0.2_wp, 0.9_wp * max(en, 1.0e-10_wp)**(-0.2_wp))))
            if (kind > 0) h = min(hmax, max(h, 1.0e-6_wp))
        end do
        res%steps = nstep
        res%t_c = t
        res%slide_fraction = tslide / t
        res%e_n = y(3)
        res%turn = y(2) * 180.0_wp / hertzdamp_pi
        res%rebound_angle = atan2(y(4), y(3)) * 180.0_wp / hertzdamp_pi
        if (ut0 /= 0.0_wp) then
            res%vt_ratio = y(4) / ut0
            res%e_t = -(y(4) - y(5) - y(6)) / vc0
        end if
    end subroutine integrate

    !> The history that gives the sliding force sigma mu |F_n| at the slip -> stick switch.
    pure subroutine to_stick(p, sigma, y)
        type(scaled_t), intent(in) :: p
        real(wp), intent(in) :: sigma
        real(wp), intent(inout) :: y(nst)
        real(wp) :: z, zq, fn, kk, eta, vt
        z = max(y(1), 0.0_wp)
        zq = 1.0_wp
        if (p%q > 0.0_wp) zq = z**p%q
        fn = z * sqrt(z) - p%alpha * zq * y(3)
        kk = p%ktp
        if (p%model == HD_TANGENTIAL_MINDLIN) kk = p%ktp * sqrt(z)
        eta = p%xg * p%alpha * zq
        vt = y(4) - (y(5) + y(6))
        y(7) = 0.0_wp
        if (kk > 0.0_wp) y(7) = -(sigma * p%mu * abs(fn) + eta * vt) / kk
    end subroutine to_stick

    !> The earliest event in the accepted step [t, t + h] (kind 0: none; 1 release,
    !> 2 stick -> slip, 3 slip -> stick, 4 F_n = 0) and its offset tau in (0, h]; on a tie
    !> the lower kind.
    pure subroutine first_event(p, mode, sigma, y, h, t, ev0, ev1, tau, kind)
        type(scaled_t), intent(in) :: p
        integer, intent(in) :: mode
        real(wp), intent(in) :: sigma, y(nst), h, t, ev0(4), ev1(4)
        real(wp), intent(out) :: tau
        integer, intent(out) :: kind
        real(wp) :: tk, hh, e1(4), yy(nst), ee(nst), dy(nst), ft
        integer :: k
        kind = 0
        tau = h
        hh = h
        e1 = ev1
        do k = 1, 4
            if (.not. crossed(k)) cycle
            tk = locate(k)
            if (kind == 0 .or. tk < tau) then
                kind = k
                tau = tk
            end if
        end do
        ! the stick -> slip limit |F_t| - mu |F_n| changes sign twice in a step that crosses
        ! F_n = 0 (mu |F_n| vanishes there): when the step ends at F_n = 0 (the kink, or the
        ! force end's release), look for it on [0, tau]
        if (mode == stick .and. (kind == 4 .or. (kind == 1 .and. p%iend == HD_END_FORCE))) then
            hh = tau
            call dp_step(p, mode, sigma, y, hh, yy, ee)
            call rhs(p, mode, sigma, yy, dy, e1, ft)
            if (crossed(2)) then
                tk = locate(2)
                if (tk <= tau) then
                    kind = 2
                    tau = tk
                end if
            end if
        end if
    contains
        pure logical function crossed(kk)
            integer, intent(in) :: kk
            select case (kk)
            case (1)
                crossed = e1(1) <= 0.0_wp .and. (ev0(1) > 0.0_wp .or. t > 0.0_wp)
            case (2)
                crossed = mode == stick .and. e1(2) > 0.0_wp
            case (3)
                crossed = mode == slip .and. e1(3) < 0.0_wp
            case default
                ! the kink of mu |F_n| (slip force, stick -> slip limit): no step crosses it
                crossed = mode /= frictionless .and. ((ev0(4) > 0.0_wp) .neqv. (e1(4) > 0.0_wp))
            end select
        end function crossed
        !> Illinois on f(s) = event kk of the sub-step of size s from y (bracket [0, h]).
        pure real(wp) function locate(kk) result(s)
            integer, intent(in) :: kk
            real(wp) :: a, b, fa, fb, fs, yy(nst), ee(nst), dy(nst), ev(4), ft
            integer :: it, side
            a = 0.0_wp
            b = hh
            fa = ev0(kk)
            fb = e1(kk)
            s = b
            if (fa == 0.0_wp .and. kk == 1) fa = tiny(1.0_wp)
            side = 0
            do it = 1, 200
                if (fb == fa) exit
                s = (a * fb - b * fa) / (fb - fa)
                if (.not. (s > a .and. s < b)) s = 0.5_wp * (a + b)
                call dp_step(p, mode, sigma, y, s, yy, ee)
                call rhs(p, mode, sigma, yy, dy, ev, ft)
                fs = ev(kk)
                if (fs == 0.0_wp) then
                    b = s
                    exit
                end if
                if ((fs > 0.0_wp) .eqv. (fb > 0.0_wp)) then
                    b = s
                    fb = fs
                    if (side == -1) fa = 0.5_wp * fa
                    side = -1
                else
                    a = s
                    fa = fs
                    if (side == 1) fb = 0.5_wp * fb
                    side = 1
                end if
                if (b - a <= max(4.0_wp * epsilon(1.0_wp) * (t + b), p%etol)) exit
            end do
            s = b
        end function locate
    end subroutine first_event

    ! ================================================================ softened contacts

    !> Mindlin's tangential stiffness from the moduli, k_t = 8 G* (LAMMPS `mindlin NULL`),
    !> 1/G* = 2 (2 - nu1)(1 + nu1)/E1 + 2 (2 - nu2)(1 + nu2)/E2 [N/m^2; times the contact
    !> radius a, N/m].  Status HD_BAD_MODULUS (E not finite and positive) or HD_BAD_POISSON
    !> (nu outside (-1, 0.5]); kt = 0 then.
    pure elemental subroutine hertzdamp_mindlin_kt(e1, nu1, e2, nu2, kt, status)
        real(wp), intent(in) :: e1, nu1    !! body 1: Young's modulus [Pa], Poisson's ratio
        real(wp), intent(in) :: e2, nu2    !! body 2 (or the wall)
        real(wp), intent(out) :: kt        !! 8 G* [N/m^2]
        integer, intent(out) :: status     !! HD_OK or an error code
        kt = 0.0_wp
        status = HD_OK
        if (.not. (e1 > 0.0_wp .and. e1 < huge(1.0_wp) .and. e2 > 0.0_wp .and. e2 < huge(1.0_wp))) then
            status = HD_BAD_MODULUS
        else if (.not. (nu1 > -1.0_wp .and. nu1 <= 0.5_wp .and. nu2 > -1.0_wp .and. nu2 <= 0.5_wp)) then
            status = HD_BAD_POISSON
        else
            kt = 8.0_wp / (2.0_wp * (2.0_wp - nu1) * (1.0_wp + nu1) / e1 + 2.0_wp * (2.0_wp - nu2) * (1.0_wp + nu2) / e2)
        end if
    end subroutine hertzdamp_mindlin_kt

    !> The tangential stiffness of a softened contact (normal stiffness k instead of the
    !> physical k_phys) whose outcome is a time-stretched copy of the physical contact's:
    !>   mindlin         k_t = k_t,phys (k / k_phys),
    !>   linear_history  k_t = k_t,phys (k / k_phys)^(4/5).
    !> Exact for a sphere on a wall with the lever arm R (the stretched contact is the
    !> physical one with time and overlap scaled by s = (k_phys/k)^(2/5)): the normal force
    !> scales as 1/s, the history as s and the contact radius as s^(1/2).  eta_t needs no
    !> change: x_gammat times the softened d scales with d.  With the lever arm R - delta/2,
    !> or two spheres (the line of centres turns), it is not exact (doc/oblique.md).
    !> Status HD_BAD_TANGENTIAL (model, k_t,phys), HD_BAD_STIFFNESS (k) or HD_BAD_KPHYS;
    !> kt = 0 then.
    pure elemental subroutine hertzdamp_tangential_kt(tangential, kt_phys, k, k_phys, kt, status)
        integer, intent(in) :: tangential   !! HD_TANGENTIAL_*
        real(wp), intent(in) :: kt_phys     !! the physical contact's k_t
        real(wp), intent(in) :: k           !! the softened normal stiffness [N m^-3/2]
        real(wp), intent(in) :: k_phys      !! the physical normal stiffness [N m^-3/2]
        real(wp), intent(out) :: kt         !! the softened contact's k_t
        integer, intent(out) :: status      !! HD_OK or an error code
        kt = 0.0_wp
        status = HD_OK
        if (tangential < hertzdamp_min_tangential .or. tangential > hertzdamp_max_tangential .or. &
            .not. (kt_phys > 0.0_wp .and. kt_phys < huge(1.0_wp))) then
            status = HD_BAD_TANGENTIAL
        else if (.not. (k > 0.0_wp .and. k < huge(1.0_wp))) then
            status = HD_BAD_STIFFNESS
        else if (.not. (k_phys > 0.0_wp .and. k_phys < huge(1.0_wp))) then
            status = HD_BAD_KPHYS
        else if (tangential == HD_TANGENTIAL_MINDLIN) then
            kt = kt_phys * (k / k_phys)
        else
            kt = kt_phys * (k / k_phys)**0.8_wp
        end if
    end subroutine hertzdamp_tangential_kt

    !> The oblique normal correction of one contact, by a solve of the oblique contact: the
    !> k, d of the target e' (at the same T_c, from hertzdamp_invert with the bound k_phys)
    !> for which the oblique contact's e_n equals e, and the tangential k_t scaled to that
    !> k (hertzdamp_tangential_kt).  c holds the masses, radii, law, end, tangential model,
    !> the PHYSICAL k (c%k, the bound and the scale of k_t) and k_t (c%kt), x_gammat, mu and
    !> lever arm; c%d is not used.
    !> - A wall, or a head-on impact: e' = e with no oblique solve (the normal motion on a
    !>   wall is the normal contact's whatever the tangential force does; exact).
    !> - Two spheres: a secant iteration on e' from e' = e whose second point solves
    !>   e' + r g(e') = e, with g a fitted map of the frictionless shift (map_shift) and r
    !>   its size measured by the first solve, until |e_n - e| <= 1e-5 (fast_stop).  The
    !>   oblique solves are fast ones: tolerance 1e-6, steps up to 0.5 t*, events located
    !>   to 1e-7 t* (fast_tol, hmax_fast, fast_etol).  e_n within 2e-5 of e (measured
    !>   1.2e-5; e' within 3.7e-5 of the full solve; doc/oblique.md section 4,
    !>   test_oblique_fast).
    !> With tol present the solves are the reference's (hertzdamp_oblique_impact at tol)
    !> and the iteration stops at |e_n - e| <= 100 tol.  With the bound active (k_phys
    !> softer than the T_c asks) k = k_phys and only d is corrected.  Status: those of
    !> hertzdamp_oblique_impact and hertzdamp_invert (HD_BAD_RESTITUTION also when no e'
    !> in the rule's range reaches e), HD_NO_CONVERGENCE; zero outputs then.
    pure elemental subroutine hertzdamp_oblique_correct(c, e, tc, speed, angle, k, d, kt, e_target, status, tol)
        type(hertzdamp_oblique_t), intent(in) :: c  !! the contact (c%k, c%kt: physical)
        real(wp), intent(in) :: e          !! the target restitution e_n
        real(wp), intent(in) :: tc         !! the target contact time [s]
        real(wp), intent(in) :: speed      !! impact speed [m/s]
        real(wp), intent(in) :: angle      !! impact angle from the normal [degrees]
        real(wp), intent(out) :: k         !! corrected normal stiffness [N m^-3/2]
        real(wp), intent(out) :: d         !! corrected damping [kg s^-1 m^-q]
        real(wp), intent(out) :: kt        !! tangential stiffness scaled to k
        real(wp), intent(out) :: e_target  !! the corrected target e' of the normal rule
        integer, intent(out) :: status     !! HD_OK or an error code
        real(wp), intent(in), optional :: tol !! tolerance of reference oblique solves (default: the fast solves)
        real(wp) :: x0, x1, f0, f1, x2, un, ut, meff, tl, hm, et, stop_at, lam
        integer :: it, nhalf
        tl = fast_tol
        hm = hmax_fast
        et = fast_etol
        stop_at = fast_stop
        if (present(tol)) then
            tl = tol
            hm = hmax_reference
            et = 0.0_wp
            stop_at = 100.0_wp * tol
        end if
        call zero4(k, d, kt, e_target)
        status = hertzdamp_oblique_status(c)
        if (status /= HD_OK) return
        if (.not. (angle >= 0.0_wp .and. angle < 90.0_wp)) then
            status = HD_BAD_OBLIQUE
        else if (.not. (speed > 0.0_wp .and. speed < huge(1.0_wp))) then
            status = HD_BAD_VELOCITY
        else if (.not. (tl >= 1.0e-14_wp .and. tl <= 1.0e-3_wp)) then
            status = HD_BAD_TOL
        end if
        if (status /= HD_OK) return
        un = speed * cos(angle * hertzdamp_pi / 180.0_wp)
        ut = speed * sin(angle * hertzdamp_pi / 180.0_wp)
        meff = c%m1
        if (c%m2 > 0.0_wp) meff = c%m1 * c%m2 / (c%m1 + c%m2)
        if (c%m2 == 0.0_wp .or. ut == 0.0_wp) then
            call hertzdamp_invert(e, tc, meff, un, c%iend, k, d, status, k_phys=c%k, law=c%law)
            if (status == HD_OK) call hertzdamp_tangential_kt(c%tangential, c%kt, k, c%k, kt, status)
            if (status == HD_OK) e_target = e
            if (status /= HD_OK) call zero4(k, d, kt, e_target)
            return
        end if
        lam = ut * ut * tc / (un * (c%r1 + c%r2))
        x0 = e
        call oblique_residual(c, e, tc, meff, un, speed, angle, tl, hm, et, x0, f0, k, d, kt, status)
        if (status /= HD_OK) then
            call zero4(k, d, kt, e_target)
            return
        end if
        if (abs(f0) <= stop_at) then
            e_target = e
            return
        end if
        ! the iterates stay at or below 1 (the rule's largest e'); one below the rule's range
        ! is moved halfway back to the last one (at most 16 times: a root near the range's
        ! low end takes more than 8, e.g. e' = 1.0e-3 for e = 0.2 at 75 deg, lambda 1.4,
        ! mindlin with x_gammat 0.5; test_oblique_fast)
        x1 = min(map_start(e, lam, f0), 1.0_wp)
        nhalf = 0
        do it = 1, 40
            call oblique_residual(c, e, tc, meff, un, speed, angle, tl, hm, et, x1, f1, k, d, kt, status)
            if (status == HD_BAD_RESTITUTION .and. x1 < x0 .and. nhalf < 16) then
                x1 = 0.5_wp * (x0 + x1)
                nhalf = nhalf + 1
                cycle
            end if
            if (status == HD_OK .and. abs(f1) <= stop_at) exit
            ! e_n < e at e' = 1: no e' reaches e
            if (status == HD_OK .and. x1 == 1.0_wp .and. f1 < 0.0_wp) status = HD_BAD_RESTITUTION
            if (status == HD_OK .and. f1 == f0) status = HD_NO_CONVERGENCE
            if (status /= HD_OK) then
                call zero4(k, d, kt, e_target)
                return
            end if
            x2 = min(x1 - f1 * (x1 - x0) / (f1 - f0), 1.0_wp)
            x0 = x1
            f0 = f1
            x1 = x2
        end do
        if (it > 40) then
            status = HD_NO_CONVERGENCE
            call zero4(k, d, kt, e_target)
            return
        end if
        ! k, d, kt are those of the last residual evaluated, x1's
        e_target = x1
    end subroutine hertzdamp_oblique_correct

    pure subroutine zero4(a, b, c, d)
        real(wp), intent(out) :: a, b, c, d
        a = 0.0_wp
        b = 0.0_wp
        c = 0.0_wp
        d = 0.0_wp
    end subroutine zero4

    !> The frictionless shift e_n - e' of two spheres at the rule's target e' (a rough fit to
    !> hertzdamp_oblique_impact at lambda = v_t^2 T_c / (u_n (R1 + R2)) up to 0.6, e' 0.1-0.99;
    !> only its shape in e' is used, by map_start).
    pure real(wp) function map_shift(x, lam) result(g)
        real(wp), intent(in) :: x, lam
        real(wp) :: w
        w = 1.0_wp - x
        g = w * (0.384_wp + 0.056_wp * w) * lam / (1.0_wp + (0.35_wp + 0.5_wp * w * w) * lam)
    end function map_shift

    !> The second point of the secant: the e' with e' + r map_shift(e') = e, where
    !> r = f0 / map_shift(e) scales the map to the shift f0 measured at e' = e (friction
    !> lowers the shift; the map's shape in e' stays close).  Three Newton steps from e - f0.
    pure real(wp) function map_start(e, lam, f0) result(x)
        real(wp), intent(in) :: e, lam, f0
        real(wp) :: g0, r, h, hp, dx
        integer :: i
        x = e - f0
        g0 = map_shift(e, lam)
        if (.not. g0 > 1.0e-12_wp) return
        r = f0 / g0
        dx = 1.0e-6_wp
        do i = 1, 3
            h = x + r * map_shift(x, lam) - e
            hp = 1.0_wp + r * (map_shift(x + dx, lam) - map_shift(x - dx, lam)) / (2.0_wp * dx)
            if (.not. hp > 0.0_wp) exit
            x = x - h / hp
        end do
    end function map_start

    !> e_n - e of the oblique contact c with the constants of target x at T_c = tc (the
    !> bound and k_t's scale: the physical c%k, c%kt), and those constants; the oblique
    !> solve at tolerance tol with steps up to hm and events located to et.
    pure subroutine oblique_residual(c, e, tc, meff, un, speed, angle, tol, hm, et, x, f, k, d, kt, status)
        type(hertzdamp_oblique_t), intent(in) :: c
        real(wp), intent(in) :: e, tc, meff, un, speed, angle, tol, hm, et, x
        real(wp), intent(out) :: f, k, d, kt
        integer, intent(out) :: status
        type(hertzdamp_oblique_t) :: cc
        type(hertzdamp_oblique_result) :: r
        f = 0.0_wp
        kt = 0.0_wp
        call hertzdamp_invert(x, tc, meff, un, c%iend, k, d, status, k_phys=c%k, law=c%law)
        if (status /= HD_OK) return
        call hertzdamp_tangential_kt(c%tangential, c%kt, k, c%k, kt, status)
        if (status /= HD_OK) return
        cc = c
        cc%k = k
        cc%d = d
        cc%kt = kt
        call impact(cc, speed, angle, tol, hm, et, r, status)
        f = r%e_n - e
    end subroutine oblique_residual

end module hertzdamp_oblique
