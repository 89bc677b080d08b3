!> The checks of a scene run: what the report states, with its bound and outcome.
!> Every value and bound is computed without overflow and is finite; a value that
!> cannot be formed (no contact to measure, a zero scale) gives no row.
!>
!> - e and T_c of the binary contacts (no other contact on either body meanwhile)
!>   within accuracy + 2/N^2, N the fewest steps per contact in the run (velocity
!>   Verlet with the onset and end corrections is second order for every damping law
!>   and contact end; measured constants up to 1.2/N^2 for e >= 0.5, up to 3.2/N^2 at
!>   e = 0.3, over four touch phases, test_scene).  Contacts that started slower than the speed floor
!>   (rest_speed) get the damping of an impact at rest_speed by design, so their e is
!>   not the target and they are not checked.  With gravity the bound does not apply
!>   (gravity acts during the contacts): the rows are information, and a second pair
!>   of rows checks the contacts with g T_c/u_in < 0.01 against the bound + 2.5e-3.
!> - Resolution: N >= hertzdamp_dem_min_resolved steps per contact (below, the O(1/N^2)
!>   model is not relied on: an asymptotic bound needs a resolved contact; a design
!>   choice, no test measures the errors at N < 4).
!> - Momentum drift to round-off (1e-12 of sum m |v|) without walls and gravity.
!> - Energy: no rise above its running minimum beyond the velocity Verlet energy
!>   fluctuation inside a Hertz contact, c_V/N^2 of the energy scale, plus the gain the
!>   e bound allows for the most elastic pair, max(0, (e_max (1 + b))^2 - 1) with b the
!>   e bound.  c_V comes from the modified energy of velocity Verlet,
!>   H~ = H + h^2 (p^2 V''/(12 m^2) - V'^2/(24 m)) + O(h^4): for V = (2/5) k z^(5/2)
!>   the discrete energy H = H~ - h^2 (...) swings by
!>       c_V/N^2,  c_V = tau_c0^2 (5/4)^(1/5) (f(x0) + 5/48),  f(x) = x^(1/2)/4 - (17/48) x^3,
!>   x0 = (2/17)^(2/5), relative to the contact's energy (c_V = 2.598; an undamped
!>   contact integrated with plain velocity Verlet gives 2.598 for N = 160).
!> - Particles left the domain (none), and with gravity the final rest.
!> - A host scheme (sc%scheme other than the engine's velocity Verlet, or the per-pair
!>   constants of a host, doc/host-schemes.md): each contact's e and T_c lie in the range
!>   the host's discrete collision spans over the onset phase, so the bound of e and of
!>   T_c is accuracy plus the largest relative deviation from the mean over the phase
!>   (res%host_e_dev, res%host_tc_dev); e gets 2.5e-3 more when a checked contact has the
!>   physical stiffness (the per-pair API's measured error there, src/hertzdamp_pair.f90), and
!>   T_c is then information only (the contact is longer than N dt by design).  The mean
!>   relative errors of e and T_c over the checked contacts are information (they
!>   approach 0 as the contacts sample the phase).  The energy row is information: the
!>   host schemes are first order, or not symplectic (mfix-ab2).
module hertzdamp_dem_checks
    use hertzdamp, only: hertzdamp_rk, hertzdamp_tau_c0
    use hertzdamp_dem_types, only: hertzdamp_dem_scene, hertzdamp_dem_result, hertzdamp_dem_u_floor
    use hertzdamp_dem_rules, only: hertzdamp_dem_targets
    use hertzdamp, only: HD_HOST_NONE, HD_HOST_VERLET
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Outcome of a check.
    integer, parameter, public :: HD_CHECK_PASS = 0      !! within its bound
    integer, parameter, public :: HD_CHECK_FAIL = 1      !! beyond its bound
    integer, parameter, public :: HD_CHECK_INFO = 2      !! a value without a bound
    integer, parameter, public :: HD_CHECK_GRAVITY = 3   !! the bound does not apply: gravity acts during the contacts

    !> Fewest steps per contact for which the time-step bound is claimed.
    real(wp), parameter, public :: hertzdamp_dem_min_resolved = 4.0_wp

    !> One row of the checks.
    type, public :: hertzdamp_dem_check_row
        character(len=48) :: name = ''           !! what is checked
        real(wp) :: value = 0.0_wp               !! measured value (finite)
        logical :: has_bound = .false.           !! a bound applies
        real(wp) :: bound = 0.0_wp               !! the bound (finite), when has_bound
        integer :: outcome = HD_CHECK_INFO       !! HD_CHECK_*
    end type hertzdamp_dem_check_row

    public :: hertzdamp_dem_checks_of, hertzdamp_dem_steps_min, hertzdamp_dem_verlet_energy, hertzdamp_dem_ratio
    public :: hertzdamp_dem_checked

contains

    !> a/b when it is a finite number, with ok = .true.; else 0 and ok = .false.
    pure elemental subroutine hertzdamp_dem_ratio(a, b, q, ok)
        real(wp), intent(in) :: a      !! numerator
        real(wp), intent(in) :: b      !! denominator
        real(wp), intent(out) :: q     !! a/b, or 0
        logical, intent(out) :: ok     !! a/b is finite
        q = 0.0_wp
        ok = .false.
        if (.not. (abs(a) <= huge(1.0_wp) .and. abs(b) <= huge(1.0_wp))) return
        if (b == 0.0_wp) then
            ok = a == 0.0_wp
            return
        end if
        if (abs(b) >= 1.0_wp) then
            q = a / b
        else if (abs(a) <= abs(b) * huge(1.0_wp)) then
            q = a / b
        else
            return
        end if
        ok = abs(q) <= huge(1.0_wp)
    end subroutine hertzdamp_dem_ratio

    !> c_V: the swing of the velocity Verlet energy inside an undamped Hertz contact
    !> is c_V/N^2 of the contact's energy for N steps per contact (see the module notes).
    pure real(wp) function hertzdamp_dem_verlet_energy() result(cv)
        real(wp) :: x0, fmax
        x0 = (2.0_wp / 17.0_wp)**0.4_wp
        fmax = sqrt(x0) / 4.0_wp - 17.0_wp / 48.0_wp * x0**3
        cv = hertzdamp_tau_c0()**2 * 1.25_wp**0.2_wp * (fmax + 5.0_wp / 48.0_wp)
    end function hertzdamp_dem_verlet_energy

    !> Fewest steps per expected contact duration among the contacts (the scene's N
    !> when none); huge when a ratio is beyond the real range.
    pure real(wp) function hertzdamp_dem_steps_min(sc, res) result(n)
        type(hertzdamp_dem_scene), intent(in) :: sc    !! the scene
        type(hertzdamp_dem_result), intent(in) :: res  !! its run
        real(wp) :: q
        logical :: ok
        integer :: c
        n = real(sc%steps_per_contact, wp)
        if (res%ncontacts == 0) return
        n = huge(1.0_wp)
        do c = 1, res%ncontacts
            call hertzdamp_dem_ratio(res%contacts(c)%tc_target, sc%dt, q, ok)
            if (ok) n = min(n, q)
        end do
    end function hertzdamp_dem_steps_min

    !> The contacts whose e and T_c are checked: binary, ended, started at or above the
    !> speed floor, with a finite achieved e.
    pure function hertzdamp_dem_checked(sc, res) result(mask)
        type(hertzdamp_dem_scene), intent(in) :: sc    !! the scene
        type(hertzdamp_dem_result), intent(in) :: res  !! its run
        logical :: mask(res%ncontacts)                 !! contact is checked
        real(wp) :: q
        logical :: ok
        integer :: c
        do c = 1, res%ncontacts
            associate (ct => res%contacts(c))
                call hertzdamp_dem_ratio(ct%u_out, ct%u_in, q, ok)
                mask(c) = ct%binary .and. ct%t_end >= 0.0_wp .and. ok .and. &
                          ct%u_in >= max(sc%rest_speed, hertzdamp_dem_u_floor)
            end associate
        end do
    end function hertzdamp_dem_checked

    !> The checks of a run, in report order; failed counts the rows that fail.
    pure subroutine hertzdamp_dem_checks_of(sc, res, rows, failed)
        type(hertzdamp_dem_scene), intent(in) :: sc                     !! the scene
        type(hertzdamp_dem_result), intent(in) :: res                   !! its run
        type(hertzdamp_dem_check_row), allocatable, intent(out) :: rows(:) !! the checks
        integer, intent(out) :: failed                                  !! rows with HD_CHECK_FAIL
        logical :: mask(res%ncontacts)
        real(wp) :: nmin, nb, bound, ebound, x, escale, e_max, q
        real(wp), allocatable :: targets(:)
        logical :: ok
        allocate (rows(0))
        nmin = hertzdamp_dem_steps_min(sc, res)
        nb = min(max(nmin, 1.0e-50_wp), 1.0e100_wp)   ! for the bounds: 1/N^2 and its square without overflow
        bound = sc%accuracy + 2.0_wp / nb**2
        mask = hertzdamp_dem_checked(sc, res)
        ! how many contacts the e and T_c rows below stand on (0: there are no such rows)
        rows = [rows, hertzdamp_dem_check_row('contacts with e, tc checked', real(count(mask), wp), .false., 0.0_wp, &
                                              HD_CHECK_INFO)]
        if (any(mask) .and. host_run(sc)) then
            call host_errors(rows, res, mask, sc%accuracy, sc%gravity)
        else if (any(mask)) then
            call add_errors(rows, res, 'binary contacts', mask, bound, sc%gravity)
        end if
        if (sc%gravity) then
            ! gravity changes e by an amount of order e g T_c/u_in (test_scene's drop
            ! asserts |e_eff/e - 1| <= 0.25 g T_c/u_in + 2/N^2): check the contacts
            ! where g T_c/u_in is below 1e-2, with 0.25 g T_c/u_in <= 2.5e-3 added
            mask = mask .and. norm2(sc%g) * res%contacts%tc_target < 1.0e-2_wp * res%contacts%u_in
            if (any(mask) .and. .not. host_run(sc)) then
                call add_errors(rows, res, 'binary, g tc/u_in < 0.01', mask, bound + 2.5e-3_wp, .false.)
            end if
        end if
        call add(rows, 'min_steps_per_contact', nmin, hertzdamp_dem_min_resolved, nmin >= hertzdamp_dem_min_resolved)
        if (.not. sc%gravity .and. size(sc%wall) == 0) then
            call hertzdamp_dem_ratio(res%momentum_drift, res%momentum_scale, x, ok)
            if (ok) call add(rows, 'momentum_drift / sum m|v|', x, 1.0e-12_wp, x <= 1.0e-12_wp)
        end if
        escale = abs(res%energy0)
        if (sc%gravity) escale = max(escale, abs(res%energy0 - res%energy_final))
        call hertzdamp_dem_ratio(res%energy_rise, escale, x, ok)
        if (ok) then
            call hertzdamp_dem_targets(sc, targets)
            e_max = 0.0_wp
            if (size(targets) > 0) e_max = maxval(targets)
            ebound = hertzdamp_dem_verlet_energy() / nb**2 + max(0.0_wp, (e_max * (1.0_wp + bound))**2 - 1.0_wp)
            call add(rows, 'energy_rise / energy scale', x, ebound, x <= ebound)
            if (host_run(sc)) rows(size(rows))%outcome = HD_CHECK_INFO
        end if
        call hertzdamp_dem_ratio(res%energy_final, res%energy0, q, ok)
        if (ok .and. res%energy0 /= 0.0_wp) then
            rows = [rows, hertzdamp_dem_check_row('energy_final / energy0', q, .false., 0.0_wp, HD_CHECK_INFO)]
        end if
        if (sc%has_domain) call add(rows, 'particles_left_domain', real(res%left_domain, wp), 0.0_wp, res%left_domain == 0)
        if (sc%gravity) call add(rows, 'max_final_speed [m/s] (at rest)', res%max_speed_final, sc%rest_speed, res%at_rest)
        failed = count(rows%outcome == HD_CHECK_FAIL)
    end subroutine hertzdamp_dem_checks_of

    !> True when the contacts are integrated by a host scheme or get a host's constants.
    pure logical function host_run(sc)
        type(hertzdamp_dem_scene), intent(in) :: sc
        host_run = sc%scheme /= HD_HOST_VERLET .or. sc%host /= HD_HOST_NONE
    end function host_run

    !> The rows of a host run (see the module notes): the mean relative errors of e and
    !> T_c (information), the largest against the phase range of the host's collision.
    pure subroutine host_errors(rows, res, mask, accuracy, info_only)
        type(hertzdamp_dem_check_row), allocatable, intent(inout) :: rows(:)
        type(hertzdamp_dem_result), intent(in) :: res
        logical, intent(in) :: mask(:)
        real(wp), intent(in) :: accuracy
        logical, intent(in) :: info_only
        real(wp) :: se, st, q, e
        logical :: ok, physical
        integer :: c, n
        se = 0.0_wp
        st = 0.0_wp
        n = 0
        physical = .false.
        do c = 1, res%ncontacts
            if (.not. mask(c)) cycle
            associate (ct => res%contacts(c))
                call hertzdamp_dem_ratio(ct%u_out, ct%u_in, e, ok)
                call hertzdamp_dem_ratio(e - ct%e_target, ct%e_target, q, ok)
                se = se + q
                call hertzdamp_dem_ratio(ct%t_end - ct%t_start - ct%tc_target, ct%tc_target, q, ok)
                st = st + q
                n = n + 1
                physical = physical .or. ct%bound_active
            end associate
        end do
        rows = [rows, hertzdamp_dem_check_row('mean_e_rel_err (binary contacts)', se / n, .false., 0.0_wp, &
                                              HD_CHECK_INFO)]
        rows = [rows, hertzdamp_dem_check_row('mean_tc_rel_err (binary contacts)', st / n, .false., 0.0_wp, &
                                              HD_CHECK_INFO)]
        call add_errors(rows, res, 'binary contacts', mask, accuracy + res%host_e_dev + merge(2.5e-3_wp, 0.0_wp, &
                        physical), info_only, accuracy + res%host_tc_dev)
        if (physical) rows(size(rows))%outcome = HD_CHECK_INFO
    end subroutine host_errors

    !> Append a check with a bound.
    pure subroutine add(rows, name, value, bound, pass)
        type(hertzdamp_dem_check_row), allocatable, intent(inout) :: rows(:)
        character(len=*), intent(in) :: name
        real(wp), intent(in) :: value, bound
        logical, intent(in) :: pass
        rows = [rows, hertzdamp_dem_check_row(name, value, .true., bound, merge(HD_CHECK_PASS, HD_CHECK_FAIL, pass))]
    end subroutine add

    !> Largest relative errors of e and T_c over the contacts in mask, against bound
    !> (or as information only, when gravity acts during the contacts).
    pure subroutine add_errors(rows, res, label, mask, bound, info_only, bound_tc)
        type(hertzdamp_dem_check_row), allocatable, intent(inout) :: rows(:)
        type(hertzdamp_dem_result), intent(in) :: res
        character(len=*), intent(in) :: label
        logical, intent(in) :: mask(:)
        real(wp), intent(in) :: bound
        logical, intent(in) :: info_only
        real(wp), intent(in), optional :: bound_tc   !! the bound of T_c when it differs from that of e
        real(wp) :: xe, xt, q, bt
        logical :: ok
        integer :: c
        xe = 0.0_wp
        xt = 0.0_wp
        do c = 1, res%ncontacts
            if (.not. mask(c)) cycle
            associate (ct => res%contacts(c))
                call hertzdamp_dem_ratio(ct%u_out, ct%u_in, q, ok)
                call hertzdamp_dem_ratio(abs(q - ct%e_target), ct%e_target, q, ok)
                xe = max(xe, merge(q, huge(1.0_wp), ok))
                call hertzdamp_dem_ratio(abs(ct%t_end - ct%t_start - ct%tc_target), ct%tc_target, q, ok)
                xt = max(xt, merge(q, huge(1.0_wp), ok))
            end associate
        end do
        call add(rows, 'max_e_rel_err (' // label // ')', xe, bound, xe <= bound)
        if (info_only) rows(size(rows))%outcome = HD_CHECK_GRAVITY
        bt = bound
        if (present(bound_tc)) bt = bound_tc
        call add(rows, 'max_tc_rel_err (' // label // ')', xt, bt, xt <= bt)
        if (info_only) rows(size(rows))%outcome = HD_CHECK_GRAVITY
    end subroutine add_errors

end module hertzdamp_dem_checks
