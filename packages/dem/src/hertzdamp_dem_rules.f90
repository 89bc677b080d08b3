!> The contact rule of the DEM engine (k and d of one contact from the inverse) and
!> the choice of the rule for a scene (`--method auto`).
module hertzdamp_dem_rules
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_NO_REBOUND, HD_DAMPING_LINEAR, hertzdamp_collision, &
                         hertzdamp_rk45_collide, HD_METHOD_SERIES, HD_METHOD_PADE, HD_METHOD_COMPACT, HD_METHOD_FIT, &
                         HD_METHOD_ITERATIVE, HD_METHOD_FIRST_ORDER, hertzdamp_invert_alpha, &
                         hertzdamp_invert_options, hertzdamp_invert, hertzdamp_pair_t, hertzdamp_pair_kd, &
                         hertzdamp_pair_kd_phase, hertzdamp_pair_phase_constants
    use hertzdamp_dem_types, only: hertzdamp_dem_scene, hertzdamp_dem_pairs_met, hertzdamp_dem_pair_e
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Candidate rules of `--method auto`, cheapest first (the documented cost order);
    !> the first-order rule alpha = (1 - e)/e1, tau_c = tau_c(0) is valid for nearly
    !> elastic contacts only.
    integer, parameter, public :: hertzdamp_dem_cost_order(6) = [HD_METHOD_FIRST_ORDER, HD_METHOD_COMPACT, &
        HD_METHOD_SERIES, HD_METHOD_PADE, HD_METHOD_FIT, HD_METHOD_ITERATIVE]

    public :: hertzdamp_dem_rule, hertzdamp_dem_host_rule, hertzdamp_dem_select, hertzdamp_dem_targets, hertzdamp_dem_supports

contains

    !> The contact rule: k and d for one contact from the target restitution e,
    !> the contact time tc = N dt (used when want_duration), effective mass m,
    !> impact velocity u and the physical stiffness kp (the bound).
    pure elemental subroutine hertzdamp_dem_rule(e, tc, m, u, kp, iend, law, method, want_duration, tol, &
                                                 k, d, tc_expected, bound, status)
        real(wp), intent(in) :: e               !! target restitution
        real(wp), intent(in) :: tc              !! wanted contact time [s]
        real(wp), intent(in) :: m               !! effective mass [kg]
        real(wp), intent(in) :: u               !! impact velocity [m s^-1]
        real(wp), intent(in) :: kp              !! physical stiffness [N m^-3/2]
        integer, intent(in) :: iend             !! contact-end definition
        integer, intent(in) :: law              !! damping law HD_DAMPING_* (damping force d zeta^q zeta')
        integer, intent(in) :: method           !! HD_METHOD_*
        logical, intent(in) :: want_duration    !! impose tc (else k = kp)
        real(wp), intent(in) :: tol             !! tolerance of the iterative rule
        real(wp), intent(out) :: k              !! stiffness [N m^-3/2]
        real(wp), intent(out) :: d              !! damping [kg s^-1 m^-q]
        real(wp), intent(out) :: tc_expected    !! contact time the parameters give [s]
        logical, intent(out) :: bound           !! k = kp
        integer, intent(out) :: status          !! HD_OK or the rule's failure
        real(wp) :: alpha, tau, ts
        ! restitution only: k = kp, which the per-pair API's bound gives for a target
        ! contact time below any physical one (the bound applies for every m, u, kp the
        ! engine accepts); k, d, t* and the bound are computed there only
        call hertzdamp_invert(e, merge(tc, tiny(1.0_wp), want_duration), m, u, iend, k, d, status, alpha=alpha, &
                              tau_c=tau, tstar=ts, bound_active=bound, k_phys=kp, law=law, &
                              options=hertzdamp_invert_options(method=method, tol=tol))   ! (tol: iterative rule)
        tc_expected = 0.0_wp
        if (status /= HD_OK) return
        tc_expected = tc
        if (bound) tc_expected = ts * tau
    end subroutine hertzdamp_dem_rule

    !> The contact rule of a host scheme: k and d of one contact from the per-pair
    !> constants of the host (hertzdamp_pair_init at the scene's N), the contact time
    !> tc = N dt, effective mass m, impact velocity u and the bound kp (hertzdamp_pair_kd);
    !> with the onset phase phi (the pair's onset-phase table) that contact's own constants
    !> (hertzdamp_pair_kd_phase).  tc_expected: tc, or t*(kp) tau when the bound applies.
    pure elemental subroutine hertzdamp_dem_host_rule(pair, tc, m, u, kp, k, d, tc_expected, bound, status, phi)
        type(hertzdamp_pair_t), intent(in) :: pair   !! constants of the material pair
        real(wp), intent(in) :: tc              !! wanted contact time N dt [s]
        real(wp), intent(in) :: m               !! effective mass [kg]
        real(wp), intent(in) :: u               !! impact velocity [m s^-1]
        real(wp), intent(in) :: kp              !! physical stiffness [N m^-3/2]
        real(wp), intent(out) :: k              !! stiffness [N m^-3/2]
        real(wp), intent(out) :: d              !! damping [kg s^-1 m^-q]
        real(wp), intent(out) :: tc_expected    !! contact time the parameters give [s]
        logical, intent(out) :: bound           !! k = kp
        integer, intent(out) :: status          !! HD_OK or the failure
        real(wp), intent(in), optional :: phi   !! onset phase in (0, 1] (hertzdamp_onset_phase)
        real(wp) :: ts, a, tau
        integer :: s2
        if (present(phi)) then
            call hertzdamp_pair_kd_phase(pair, tc, m, u, kp, phi, k, d, status)
            tc_expected = 0.0_wp
            bound = .false.
            if (status /= HD_OK) return
            tc_expected = tc
            bound = kp > 0.0_wp .and. k >= kp
            if (bound) then
                call hertzdamp_pair_phase_constants(pair, phi, a, tau, s2)
                tc_expected = (m / (k * sqrt(u)))**0.4_wp * tau
            end if
            return
        end if
        call hertzdamp_pair_kd(pair, tc, m, u, k, d, status, k_phys=kp, bound_active=bound, tstar=ts)
        tc_expected = 0.0_wp
        if (status /= HD_OK) return
        tc_expected = tc
        if (bound) tc_expected = ts * pair%tau_c
    end subroutine hertzdamp_dem_host_rule

    !> True when the library provides the contact rule `method` for the damping law:
    !> fit, iterative and first-order (with the law's e1) for every law; compact,
    !> series and Pade for the linear law only (doc/damping-laws.md section 9).
    pure elemental logical function hertzdamp_dem_supports(method, law) result(ok)
        integer, intent(in) :: method   !! HD_METHOD_*
        integer, intent(in) :: law      !! HD_DAMPING_*
        ok = law == HD_DAMPING_LINEAR .or. .not. any(method == [HD_METHOD_COMPACT, HD_METHOD_SERIES, HD_METHOD_PADE])
    end function hertzdamp_dem_supports

    !> The distinct target restitutions of the material pairs that can meet.
    pure subroutine hertzdamp_dem_targets(sc, targets)
        type(hertzdamp_dem_scene), intent(in) :: sc  !! the scene
        real(wp), allocatable, intent(out) :: targets(:) !! distinct sqrt(e_a e_b)
        logical, allocatable :: met(:, :)
        real(wp) :: e
        integer :: a, b
        call hertzdamp_dem_pairs_met(sc, met)
        allocate (targets(0))
        do a = 1, size(sc%mat)
            do b = a, size(sc%mat)
                if (.not. met(a, b)) cycle
                e = hertzdamp_dem_pair_e(sc%mat(a), sc%mat(b))
                if (.not. any(abs(targets - e) <= 4.0_wp * epsilon(e))) targets = [targets, e]
            end do
        end do
    end subroutine hertzdamp_dem_targets

    !> `--method auto`: the cheapest rule (in hertzdamp_dem_cost_order) whose error
    !> at the scene's targets meets the scene's accuracy in every check the report
    !> makes.  For each candidate and each target e of the material pairs that meet,
    !> the candidate gives alpha_c and its tau_c; one reference solve at alpha_c gives
    !> the achieved e and tau_c:
    !>     err = max(|e_ref(alpha_c) - e| / e, |tau_ref(alpha_c) - tau_c| / tau_ref)
    !> The duration term counts in every scene: the report checks the achieved
    !> contact time against the rule's expected time (N dt, or t*(k_phys) tau_c when
    !> the physical stiffness applies, as in restitution-only scenes, where tau_c is
    !> the rule's own).
    !> Every damping law (sc%law): the candidates, the inverse and the reference solve
    !> are those of the law; compact, series and Pade exist for the linear law only
    !> (hertzdamp_dem_supports) and are skipped for the others.
    !> avail(c) is false when the library does not provide candidate c for the scene
    !> (the law's rules, then any non-OK status of the inverse, typically HD_NOT_SUPPORTED).
    pure subroutine hertzdamp_dem_select(sc, chosen, err, avail, status)
        type(hertzdamp_dem_scene), intent(in) :: sc  !! the scene
        integer, intent(out) :: chosen               !! a method code, or -1 if none meets the accuracy
        real(wp), intent(out) :: err(6)              !! error of each candidate (cost order)
        logical, intent(out) :: avail(6)             !! candidate provided by the library
        integer, intent(out) :: status               !! HD_OK or a reference-solver failure
        real(wp), allocatable :: targets(:)
        real(wp) :: e, alpha, tau, ec, tc
        integer :: c, it, st, meth
        type(hertzdamp_collision) :: r
        status = HD_OK
        chosen = -1
        err = huge(1.0_wp)
        avail = .false.
        call hertzdamp_dem_targets(sc, targets)
        do c = 1, 6
            meth = hertzdamp_dem_cost_order(c)
            if (.not. hertzdamp_dem_supports(meth, sc%law)) cycle
            avail(c) = .true.
            err(c) = 0.0_wp
            do it = 1, size(targets)
                e = targets(it)
                call hertzdamp_invert_alpha(e, sc%iend, alpha, tau, st, method=meth, law=sc%law)
                if (st /= HD_OK) then
                    avail(c) = .false.
                    err(c) = huge(1.0_wp)
                    exit
                end if
                r = hertzdamp_rk45_collide(alpha, sc%iend, law=sc%law)
                if (r%status /= HD_OK) then
                    if (r%status /= HD_NO_REBOUND) then
                        status = r%status
                        return
                    end if
                    err(c) = max(err(c), 1.0_wp)   ! no rebound: e error 1
                    cycle
                end if
                ec = r%e
                tc = r%tau_c
                err(c) = max(err(c), abs(ec - e) / e, abs(tc - tau) / tc)
            end do
            if (avail(c) .and. chosen < 0 .and. err(c) <= sc%accuracy) chosen = meth
        end do
    end subroutine hertzdamp_dem_select

end module hertzdamp_dem_rules
