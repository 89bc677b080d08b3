!> Per-contact constants from the onset phase (issue 32, doc/host-schemes.md section 6).
!>
!> A host that sets k and d at the contact onset knows the first overlap delta_1 and the
!> approach speed u, so the onset phase phi = delta_1 / (u dt) in (0, 1]
!> (hertzdamp_onset_phase).  For a given phi the host's discrete collision
!> (hertzdamp_host_collide) is deterministic, and two constants, alpha(phi) and
!> tau(phi) (that is k and d), make that one contact's e and contact time exact:
!>
!>     e_host(alpha, h; phi) = e,   tau_host(alpha, h; phi) = N h,   tau(phi) = N h.
!>
!> hertzdamp_phase_point solves these two equations at one phase (Newton in (alpha, h)
!> with a forward-difference Jacobian from a guess; where it does not converge, a nested
!> bracketing solve: alpha for e at fixed h by bisection, inside the Illinois method on h
!> for the contact time).
!>
!> The table (hertzdamp_phase_build, the pair's `phase` block): with the contact time
!> pinned to N steps, the release happens at the same step for every phase except at the
!> tie phi_b = N - floor(N) (1 for a whole N), where the release lands on a step boundary:
!> just below phi_b the last step with overlap has a tiny one, at phi_b and above the host's
!> own test (`overlap > 0`: an overlap of exactly 0 is no contact) releases a step earlier.
!> Near the tie the release step is decided by round-off and by the table's interpolation
!> error (issue 32: e off by 13 % at phi = 1, mfix-euler, e = 0.5, N = 10), so the table
!> keeps every release at least tie_band steps (2e-5) off a step boundary, on the side the
!> host's test puts the tie: two pieces (0, P] and (P, 1], P = phi_b - tie_band, the first
!> solved for a contact of N_1 steps, the second for one of N_1 - 2 tie_band steps (released
!> the step before the boundary, tie_band to 2 tie_band steps early); N_1 = N, or for a whole
!> N (or one within 1.5 tie_band above a whole number) floor(N) - tie_band/2, so that the tie
!> is at phi_b = 1 - tie_band/2 and the phases near 0 too release tie_band/2 steps off the
!> boundary.  The contact time is then within 2.5 tie_band/N of N steps; e is exact.
!> The constants are smooth on each piece with algebraic singularities where a first or
!> last overlap is tiny (phi -> 0: powers phi^(3/2), phi^q, ...; the first piece's last
!> overlap at phi -> phi_b: (phi_b - phi)^q, ..., q in {0, 1/4, 1/2}, all multiples of 1/4).
!> Each piece is cut at its middle into two halves; in each half the variable
!> t = (distance to the half's centre / half length)^(1/r) (the centre: 0, phi_b, P and 1
!> for the four halves; r = 4 for tsuji, whose powers are multiples of 1/4; r = 2 for q = 0
!> and 1/2, multiples of 1/2) makes those powers polynomials; alpha and tau are solved at
!> equidistant t_j from t_0 (1e-3; for the second half (tie_band/half length)^(1/r)) to 1,
!> and the nodes' K = tau^(5/2) and A = alpha tau^(1+q) (q = 0, 1/4, 1/2 by the law) are
!> interpolated by the cubic through the four nearest nodes (Lagrange; hertzdamp_pair
!> evaluates it per contact: k = K m T_c^(-5/2) u^(-1/2), d = A m T_c^(-1-q) u^(-q), so
!> that the factors of T_c, m, u are formed beside the lookup and no root follows it).
!> The second piece has no tiny overlap at either end (smooth): a whole N's (3 tie_band
!> long) takes 6 nodes per half and its first piece's halves 45; otherwise 31 per half of
!> the first piece and 20 of the second.  At init every cell middle (but those next to
!> extrapolated end nodes) and the phases at and around the tie and the ends are checked
!> (tau = K^(2/5), alpha = A / tau^(1+q)): e and the contact time within 1e-4
!> (check_table).
!>
!> Layout of the table (hertzdamp_pair_phase_size = 240 doubles): (1) the marker (set by
!> hertzdamp_pair: a hash of the header's marker, the law and the entries 2, 4, 5, 6);
!> (2) number of halves (0: host none, no phase dependence; else 4); (3) the marker of the
!> rest (entries 7 .. 10, checked by hertzdamp_pair_phase_status only); (4) P; (5) P/2;
!> (6) (P + 1)/2; (7) N; (8) the root r; (9) phi_b; (10) N_1; (11 .. 34) per half a record
!> of six: its centre c, (nodes - 1)^r / ((1 - t_0)^r length), -t_0 (nodes - 1)/(1 - t_0) - 1.5
!> (so that the node coordinate less 1.5 is (|phi - c| times the second)^(1/r) plus the third),
!> nodes - 4, the offset of its nodes, and the record's marker (a hash of the table's marker,
!> the five and the record's index); from (35): per half, per node, K then A (tau = N h: the
!> host's step h = dt/t* is tau/N).
module hertzdamp_phase
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: HD_OK, HD_PHASE_UNREACHABLE, HD_BAD_PHASE, HD_BAD_VELOCITY, HD_BAD_TIME, &
                                HD_BAD_STEPS, HD_HOST_UNREACHABLE, hertzdamp_pair_phase_size
    use hertzdamp_registry, only: HD_DAMPING_TSUJI, HD_HOST_NONE, hertzdamp_law_q
    use hertzdamp_host, only: hertzdamp_host_collide, hertzdamp_host_solve, hertzdamp_host_stats, &
                              hertzdamp_host_steps_min, hertzdamp_host_steps_max, hertzdamp_host_h_min, &
                              hertzdamp_host_h_max, hertzdamp_host_alpha_max
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    public :: hertzdamp_onset_phase, hertzdamp_phase_point, hertzdamp_phase_build
    public :: hertzdamp_phase_min_steps, hertzdamp_phase_table_ok

    !> Size of the table header (doubles before the nodes).
    integer, parameter, public :: hertzdamp_phase_header = 34
    !> The most nodes of one half (the 206 doubles after the header hold 103 pairs (K, A;
    !> hertzdamp_phase: the layout); the halves take 45 + 45 + 6 + 6 or 31 + 31 + 20 + 20).
    integer, parameter, public :: hertzdamp_phase_half_max = 45
    !> First node's t (the ends of a piece are limits, not phases).
    real(wp), parameter :: t_first = 1.0e-3_wp
    !> Below this t (a phase within 5e-5 of the half length from a piece end) a node whose
    !> solve fails is the cubic extrapolation of the four nodes above it.
    real(wp), parameter :: t_extrapolate = 0.1_wp
    !> Relative tolerance of the per-phase solve (both residuals), and the floor it accepts
    !> when round-off keeps Newton from going lower (long contacts).
    real(wp), parameter :: point_tol = 1.0e-13_wp, point_floor = 1.0e-10_wp
    !> The largest relative error of e and of the contact time that the check of a new table
    !> accepts at the middles of its cells.
    real(wp), parameter :: check_tol = 1.0e-4_wp
    !> The least distance, in steps, at which the table keeps the release from a step
    !> boundary (module note: the tie).
    real(wp), parameter, public :: hertzdamp_phase_tie_band = 2.0e-5_wp
    !> Largest N of hertzdamp_phase_min_steps.
    integer, parameter :: n_search_max = 1024

contains

    !> The onset phase phi = delta1 / (u dt) of a contact first seen with the overlap delta1
    !> after a step dt at the approach speed u (one step before, the overlap was
    !> (phi - 1) u dt).  A contact detected late (phi > 1: the overlap is deeper than one
    !> step of approach, e.g. a neighbour list rebuilt too seldom) gets phi = 1, the
    !> earliest touch the table knows, and HD_OK: the steps already missed cannot be
    !> corrected by k and d, and refusing the contact would leave the host without constants.
    !> Status HD_BAD_PHASE when delta1 is not finite and positive (no overlap yet),
    !> HD_BAD_VELOCITY (u), HD_BAD_TIME (dt) when not finite and positive (checked in the
    !> order delta1, u, dt; the last bad one wins); phi = 0 on failure.
    pure elemental subroutine hertzdamp_onset_phase(delta1, u, dt, phi, status)
        real(wp), intent(in) :: delta1   !! first positive overlap [m]
        real(wp), intent(in) :: u        !! approach speed at the onset [m s^-1]
        real(wp), intent(in) :: dt       !! time step [s]
        real(wp), intent(out) :: phi     !! onset phase in (0, 1]
        integer, intent(out) :: status   !! HD_OK or the bad argument
        status = HD_OK
        if (.not. (delta1 > 0.0_wp .and. delta1 <= huge(delta1))) status = HD_BAD_PHASE
        if (.not. (u > 0.0_wp .and. u <= huge(u))) status = HD_BAD_VELOCITY
        if (.not. (dt > 0.0_wp .and. dt <= huge(dt))) status = HD_BAD_TIME
        phi = 0.0_wp
        if (status /= HD_OK) return
        phi = delta1 / (u * dt)
        ! u dt may underflow to 0 (phi = +inf) or phi itself to 0 (a first overlap below
        ! 1e-308 of a step): clamp into (0, 1]
        phi = min(phi, 1.0_wp)
        if (.not. (phi > 0.0_wp)) phi = tiny(1.0_wp)
    end subroutine hertzdamp_onset_phase

    ! ================================================================ one phase

    !> The residual of the per-phase equations at x = (alpha, h): ((e_host - e)/e,
    !> tau_host/(N h) - 1); st /= HD_OK where the collision fails.
    pure subroutine residual(e, law, iend, host, steps, phi, x, r, st)
        real(wp), intent(in) :: e, steps, phi, x(2)
        integer, intent(in) :: law, iend, host
        real(wp), intent(out) :: r(2)
        integer, intent(out) :: st
        real(wp) :: ee, tt
        r = huge(1.0_wp)
        if (.not. (x(1) >= 0.0_wp .and. x(1) <= hertzdamp_host_alpha_max .and. x(2) >= hertzdamp_host_h_min .and. &
                   x(2) <= hertzdamp_host_h_max)) then
            st = HD_HOST_UNREACHABLE
            return
        end if
        call hertzdamp_host_collide(x(1), x(2), phi, law, iend, host, ee, tt, st)
        if (st /= HD_OK) return
        r(1) = (ee - e) / e
        r(2) = tt / (steps * x(2)) - 1.0_wp
    end subroutine residual

    !> The per-phase constants alpha(phi) and tau(phi) = N h of one onset phase phi in (0, 1]
    !> (module note): the host's discrete collision at (alpha, h = tau/N, phi) has the
    !> restitution e and lasts N steps (its contact time, measured as hertzdamp_host_collide
    !> does, is tau), both to 1e-13 relative (1e-10 where round-off stops Newton, 1e-9 where it
    !> cannot polish the bracketing result).
    !> guess = (alpha, tau) to start from (e.g. the mean-exact constants of
    !> hertzdamp_host_solve).  Status HD_OK, HD_BAD_PHASE (phi outside (0, 1]), or
    !> HD_PHASE_UNREACHABLE (no constants found: too few steps for this phase).  The other
    !> arguments are assumed valid (checked by hertzdamp_host_solve first).
    pure subroutine hertzdamp_phase_point(e, law, iend, host, steps, phi, guess, alpha, tau, status)
        real(wp), intent(in) :: e          !! target restitution coefficient
        integer, intent(in) :: law         !! HD_DAMPING_*
        integer, intent(in) :: iend        !! HD_END_*
        integer, intent(in) :: host        !! HD_HOST_* (not none)
        real(wp), intent(in) :: steps      !! steps per contact N
        real(wp), intent(in) :: phi        !! onset phase
        real(wp), intent(in) :: guess(2)   !! (alpha, tau) to start from
        real(wp), intent(out) :: alpha     !! damping parameter for this phase
        real(wp), intent(out) :: tau       !! contact duration (units of t*) for this phase
        integer, intent(out) :: status     !! HD_OK or the failure
        real(wp) :: x(2), x0(2)
        integer :: st
        alpha = 0.0_wp
        tau = 0.0_wp
        status = HD_BAD_PHASE
        if (.not. (phi > 0.0_wp .and. phi <= 1.0_wp)) return
        x0 = [guess(1), guess(2) / steps]
        call newton(e, law, iend, host, steps, phi, x0, x, status)
        if (status /= HD_OK) then
            call nested(e, law, iend, host, steps, phi, x0, x, status)
            if (status == HD_OK) then
                ! polish; where Newton cannot (an infinite slope of e near a tiny last
                ! overlap), the bracketing result (both residuals below 1e-9) stands
                x0 = x
                call newton(e, law, iend, host, steps, phi, x0, x, st)
                if (st /= HD_OK) x = x0
            end if
        end if
        if (status == HD_OK) then
            alpha = x(1)
            tau = steps * x(2)
        else
            status = HD_PHASE_UNREACHABLE
        end if
    end subroutine hertzdamp_phase_point

    !> Newton in x = (alpha, h) on the residual, from x0: forward-difference Jacobian, a trust
    !> region (alpha by at most half of max(alpha, 0.05), h by at most 20 %), step halving.
    pure subroutine newton(e, law, iend, host, steps, phi, x0, x, status)
        real(wp), intent(in) :: e, steps, phi, x0(2)
        integer, intent(in) :: law, iend, host
        real(wp), intent(out) :: x(2)
        integer, intent(out) :: status
        real(wp) :: r(2), rt(2), xt(2), jac(2, 2), dx(2), det, f, lam, nrm, nrmt
        integer :: it, ls, st
        logical :: ok
        status = HD_PHASE_UNREACHABLE
        x = x0
        call residual(e, law, iend, host, steps, phi, x, r, st)
        if (st /= HD_OK) return
        nrm = maxval(abs(r))
        do it = 1, 30
            if (nrm <= point_tol) exit
            call column([1.0e-8_wp * max(x(1), 1.0e-2_wp), 0.0_wp], jac(:, 1), st)
            if (st /= HD_OK) return
            call column([0.0_wp, 1.0e-8_wp * x(2)], jac(:, 2), st)
            if (st /= HD_OK) return
            det = jac(1, 1) * jac(2, 2) - jac(1, 2) * jac(2, 1)
            if (.not. (abs(det) > 0.0_wp)) return
            dx(1) = -(jac(2, 2) * r(1) - jac(1, 2) * r(2)) / det
            dx(2) = -(jac(1, 1) * r(2) - jac(2, 1) * r(1)) / det
            f = max(abs(dx(1)) / (0.5_wp * max(x(1), 0.05_wp)), abs(dx(2)) / (0.2_wp * x(2)), 1.0_wp)
            dx = dx / f
            lam = 1.0_wp
            ok = .false.
            do ls = 1, 8
                xt = x + lam * dx
                xt(1) = max(xt(1), 0.0_wp)
                call residual(e, law, iend, host, steps, phi, xt, rt, st)
                if (st == HD_OK) then
                    nrmt = maxval(abs(rt))
                    ok = nrmt < nrm
                end if
                if (ok) exit
                lam = 0.5_wp * lam
            end do
            if (.not. ok) exit
            x = xt
            r = rt
            nrm = nrmt
        end do
        if (nrm <= point_floor) status = HD_OK
    contains
        !> A column of the Jacobian by a forward difference along dv, or the backward one
        !> when the forward one jumps (the release moved to another step: near a piece end
        !> the last overlap is tiny and e jumps for the linear law, or rises like a root).
        pure subroutine column(dv, c, sc)
            real(wp), intent(in) :: dv(2)
            real(wp), intent(out) :: c(2)
            integer, intent(out) :: sc
            real(wp) :: rf(2), rb(2)
            integer :: sb
            c = 0.0_wp
            call residual(e, law, iend, host, steps, phi, x + dv, rf, sc)
            if (sc == HD_OK) then
                if (maxval(abs(rf - r)) <= 1.0e-5_wp) then
                    c = (rf - r) / sum(dv)
                    return
                end if
            end if
            call residual(e, law, iend, host, steps, phi, x - dv, rb, sb)
            if (sb == HD_OK) then
                if (sc /= HD_OK .or. maxval(abs(rb - r)) < maxval(abs(rf - r))) then
                    c = (r - rb) / sum(dv)
                    sc = HD_OK
                    return
                end if
            end if
            if (sc == HD_OK) c = (rf - r) / sum(dv)
        end subroutine column
    end subroutine newton

    !> The nested bracketing solve from x0: at a step h, alpha(h) with e_host = e (bisection
    !> on alpha from 0, where e_host >= e, up to where e_host < e or no rebound), and the
    !> contact-time residual g(h) = tau_host/(N h) - 1 there, bracketed from h0 by steps of
    !> 25 % and found by the Illinois method.  HD_OK when both residuals end below 1e-9
    !> (Newton polishes the result), else HD_PHASE_UNREACHABLE.
    pure subroutine nested(e, law, iend, host, steps, phi, x0, x, status)
        real(wp), intent(in) :: e, steps, phi, x0(2)
        integer, intent(in) :: law, iend, host
        real(wp), intent(out) :: x(2)
        integer, intent(out) :: status
        real(wp) :: hlo, hhi, glo, ghi, h, g, a, alo, ahi, hm, gm, am, re
        integer :: it, st, side
        logical :: have_lo, have_hi
        status = HD_PHASE_UNREACHABLE
        x = x0
        have_lo = .false.
        have_hi = .false.
        h = x0(2)
        a = x0(1)
        hlo = 0.0_wp; hhi = 0.0_wp; glo = 0.0_wp; ghi = 0.0_wp; alo = 0.0_wp; ahi = 0.0_wp
        do it = 1, 60
            if (h < hertzdamp_host_h_min .or. h > hertzdamp_host_h_max) return
            call g_of_h(h, a, g, re, st)
            if (st == HD_OK) then
                if (g > 0.0_wp) then
                    hlo = h; glo = g; alo = a; have_lo = .true.
                    if (have_hi) exit
                    h = 1.25_wp * h
                else
                    hhi = h; ghi = g; ahi = a; have_hi = .true.
                    if (have_lo) exit
                    h = 0.8_wp * h
                end if
            else
                ! no alpha reaches e at this step: a finer step may
                if (have_lo) return
                h = 0.8_wp * h
                a = x0(1)
            end if
        end do
        if (.not. (have_lo .and. have_hi)) return
        side = 0
        do it = 1, 200
            hm = hlo + (hhi - hlo) * glo / (glo - ghi)
            if (.not. (hm > min(hlo, hhi) .and. hm < max(hlo, hhi))) hm = 0.5_wp * (hlo + hhi)
            am = merge(alo, ahi, abs(hm - hlo) < abs(hhi - hm))
            call g_of_h(hm, am, gm, re, st)
            if (st /= HD_OK) return
            if (abs(gm) <= 1.0e-12_wp .and. abs(re) <= 1.0e-12_wp) exit
            if (abs(hhi - hlo) <= 4.0_wp * spacing(hhi)) exit
            if (gm > 0.0_wp) then
                hlo = hm; glo = gm; alo = am
                if (side == -1) ghi = 0.5_wp * ghi
                side = -1
            else
                hhi = hm; ghi = gm; ahi = am
                if (side == 1) glo = 0.5_wp * glo
                side = 1
            end if
        end do
        x = [am, hm]
        if (abs(gm) <= 1.0e-9_wp .and. abs(re) <= 1.0e-9_wp) status = HD_OK
    contains
        !> alpha(hh) by bisection (aa: the guess in, the result out), its e residual re and g.
        pure subroutine g_of_h(hh, aa, gg, re, sta)
            real(wp), intent(in) :: hh
            real(wp), intent(inout) :: aa
            real(wp), intent(out) :: gg, re
            integer, intent(out) :: sta
            real(wp) :: lo, hi, rr(2), rl(2)
            integer :: k, s2
            gg = 0.0_wp
            re = huge(1.0_wp)
            sta = HD_PHASE_UNREACHABLE
            lo = 0.0_wp
            call residual(e, law, iend, host, steps, phi, [lo, hh], rl, s2)
            if (s2 /= HD_OK) return
            if (rl(1) < 0.0_wp) return
            hi = max(aa, 1.0e-2_wp)
            do k = 1, 40
                call residual(e, law, iend, host, steps, phi, [hi, hh], rr, s2)
                if (s2 /= HD_OK .or. rr(1) < 0.0_wp) exit
                lo = hi
                rl = rr
                hi = min(2.0_wp * hi, hertzdamp_host_alpha_max)
                if (k == 40) return
            end do
            do k = 1, 200
                aa = 0.5_wp * (lo + hi)
                if (aa <= lo .or. aa >= hi) exit
                call residual(e, law, iend, host, steps, phi, [aa, hh], rr, s2)
                if (s2 == HD_OK .and. rr(1) >= 0.0_wp) then
                    lo = aa
                    rl = rr
                else
                    hi = aa
                end if
                if (hi - lo <= 1.0e-15_wp * hi) exit
            end do
            aa = lo
            gg = rl(2)
            re = rl(1)
            sta = HD_OK
        end subroutine g_of_h
    end subroutine nested

    ! ================================================================ the table

    !> The onset-phase table of (e, law, iend, host, N) from the mean-exact constants
    !> (alpha_n, tau_n) of hertzdamp_host_solve (the guess of each piece's middle): the
    !> nodes solved by hertzdamp_phase_point from the middle of each half towards its end,
    !> each from the previous node's constants, for the piece's contact of N_1 or
    !> N_1 - 2 tie_band steps (module note).  tab(1) (the marker) is left 0.  host none:
    !> the empty table (2nd entry 0: no phase dependence).  Status HD_OK, HD_BAD_STEPS (N
    !> not in [2, 1e5]), or HD_PHASE_UNREACHABLE when some node has no constants or the
    !> check fails (table zero then).
    pure subroutine hertzdamp_phase_build(e, law, iend, host, steps, alpha_n, tau_n, tab, status)
        real(wp), intent(in) :: e                   !! target restitution coefficient
        integer, intent(in) :: law                  !! HD_DAMPING_*
        integer, intent(in) :: iend                 !! HD_END_*
        integer, intent(in) :: host                 !! HD_HOST_*
        real(wp), intent(in) :: steps               !! steps per contact N
        real(wp), intent(in) :: alpha_n, tau_n      !! the mean-exact constants
        real(wp), intent(out) :: tab(hertzdamp_pair_phase_size)  !! the table (layout: module note)
        integer, intent(out) :: status              !! HD_OK or the failure
        real(wp), parameter :: b = hertzdamp_phase_tie_band
        real(wp) :: pb, n1, np, guess(2), t, phi, a, ta, mid(2), ln, lay(4, 5)
        integer :: nn, p, s, j, base, i, jx(4), nh(4)
        tab = 0.0_wp
        status = HD_OK
        jx = 0
        if (host == HD_HOST_NONE) return
        if (.not. (steps >= hertzdamp_host_steps_min .and. steps <= hertzdamp_host_steps_max)) then
            status = HD_BAD_STEPS
            return
        end if
        n1 = steps
        if (steps - aint(steps) < 1.5_wp * b) n1 = aint(steps) - 0.5_wp * b
        pb = n1 - aint(n1)
        ! nodes per half (module note)
        nh = merge([45, 45, 6, 6], [31, 31, 20, 20], pb > 1.0_wp - 2.0_wp * b)
        tab(2) = 4.0_wp
        tab(4) = pb - b
        tab(5) = 0.5_wp * tab(4)
        tab(6) = 0.5_wp * (tab(4) + 1.0_wp)
        tab(7) = steps
        ! the root of t: 4 for tsuji (powers of phi^(1/4)), 2 for q = 0 and 1/2 (powers of
        ! phi^(1/2) only: one square root per contact less)
        tab(8) = merge(4.0_wp, 2.0_wp, law == HD_DAMPING_TSUJI)
        tab(9) = pb
        tab(10) = n1
        ! the halves: centres, one over their lengths, t_0, nodes per unit t (lay), and
        ! their records in the table (module note)
        lay(:, 1) = [0.0_wp, pb, tab(4), 1.0_wp]
        lay(:, 2) = 1.0_wp / [tab(5), pb - tab(5), tab(6) - tab(4), 1.0_wp - tab(6)]
        lay(:, 3) = [t_first, (b * lay(2, 2))**(1.0_wp / tab(8)), t_first, t_first]
        lay(:, 4) = real(nh - 1, wp) / (1.0_wp - lay(:, 3))
        lay(:, 5) = real(hertzdamp_phase_header, wp)
        do s = 2, 4
            lay(s, 5) = lay(s - 1, 5) + real(2 * nh(s - 1), wp)
        end do
        do s = 1, 4
            i = 5 + 6 * s
            tab(i:i + 4) = [lay(s, 1), lay(s, 2) * lay(s, 4)**nint(tab(8)), -lay(s, 3) * lay(s, 4) - 1.5_wp, &
                            real(nh(s) - 4, wp), lay(s, 5)]
        end do
        do p = 1, 2
            ! the piece's contact in steps (module note); tau is stored as N h
            np = merge(n1, n1 - 2.0_wp * b, p == 1)
            ! the middle of the piece first (shared by its two halves)
            phi = tab(4 + p)
            call hertzdamp_phase_point(e, law, iend, host, np, phi, [alpha_n, tau_n * np / steps], a, ta, status)
            if (status /= HD_OK) exit
            mid = [a, ta]
            do s = 2 * p - 1, 2 * p
                base = nint(lay(s, 5))
                nn = nh(s)
                guess = mid
                do j = nn - 1, 0, -1
                    t = lay(s, 3) + real(j, wp) / lay(s, 4)
                    phi = node_phase(tab, lay, s, t)
                    if (j == nn - 1) then
                        a = mid(1)
                        ta = mid(2)
                    else
                        call hertzdamp_phase_point(e, law, iend, host, np, phi, guess, a, ta, status)
                        ! from the previous node's constants first, then from the mean-exact ones
                        if (status /= HD_OK) call hertzdamp_phase_point(e, law, iend, host, np, phi, &
                                                                        [alpha_n, tau_n * np / steps], a, ta, status)
                        if (status /= HD_OK .and. t < t_extrapolate .and. j + 4 < nn) then
                            ! near a singular end (a first or last overlap below 1e-4 of a
                            ! step), where e has an infinite slope next to the solution: the
                            ! cubic through the four nodes above
                            i = base + 2 * j
                            ln = np / steps
                            a = 4.0_wp * (tab(i + 3) + tab(i + 7)) - 6.0_wp * tab(i + 5) - tab(i + 9)
                            ta = ln * (4.0_wp * (tab(i + 4) + tab(i + 8)) - 6.0_wp * tab(i + 6) - tab(i + 10))
                            status = HD_OK
                            jx(s) = max(jx(s), j)
                        end if
                        if (status /= HD_OK) exit
                    end if
                    tab(base + 2 * j + 1) = a
                    tab(base + 2 * j + 2) = ta * steps / np
                    guess = [a, ta]
                end do
                if (status /= HD_OK) exit
            end do
            if (status /= HD_OK) exit
        end do
        if (status == HD_OK) then
            ! the nodes as K = tau^(5/2) and A = alpha tau^(1+q) (what the per-contact path
            ! multiplies by its factors of T_c, m and u)
            do i = hertzdamp_phase_header + 1, nint(lay(4, 5)) + 2 * nh(4), 2
                tab(i:i + 1) = [tab(i + 1)**2.5_wp, tab(i) * tab(i + 1)**(1.0_wp + hertzdamp_law_q(law))]
            end do
            call check_table(e, law, iend, host, steps, tab, lay, jx, status)
        end if
        if (status /= HD_OK) then
            tab = 0.0_wp
            status = HD_PHASE_UNREACHABLE
        end if
    end subroutine hertzdamp_phase_build

    !> The check of a built table: at the middle of every cell of a half (the cell j between
    !> t_j and t_(j+1)) but those next to the end whose cubic reads an extrapolated node
    !> (j <= jx + 1, jx the highest extrapolated node of the half), and at the phases at and
    !> around the tie and the ends (1e-15, P -+ 1e-12, P, phi_b, 1 - 1e-15, 1), the collision
    !> with the interpolated constants has e and the contact time within check_tol of the
    !> targets (relative); HD_PHASE_UNREACHABLE otherwise (a phase between the nodes the host
    !> cannot serve at this N, or an interpolation error beyond it).
    pure subroutine check_table(e, law, iend, host, steps, tab, lay, jx, status)
        real(wp), intent(in) :: e, steps, tab(hertzdamp_pair_phase_size), lay(4, 5)
        integer, intent(in) :: law, iend, host, jx(4)
        integer, intent(out) :: status
        real(wp) :: t, phi, ph(7)
        integer :: s, j, nn
        status = HD_OK
        do s = 1, 4
            nn = nint(tab(8 + 6 * s)) + 4
            do j = merge(jx(s) + 2, 0, jx(s) > 0), nn - 2
                t = lay(s, 3) + (real(j, wp) + 0.5_wp) / lay(s, 4)
                phi = node_phase(tab, lay, s, t)
                if (.not. good(phi)) status = HD_PHASE_UNREACHABLE
                if (status /= HD_OK) return
            end do
        end do
        ph = [1.0e-15_wp, tab(4) - 1.0e-12_wp, tab(4), tab(4) + 1.0e-12_wp, tab(9), 1.0_wp - 1.0e-15_wp, 1.0_wp]
        do j = 1, size(ph)
            if (ph(j) > 0.0_wp .and. ph(j) <= 1.0_wp) then
                if (.not. good(ph(j))) status = HD_PHASE_UNREACHABLE
            end if
            if (status /= HD_OK) return
        end do
    contains
        !> Whether the contact of one phase meets the targets.
        pure logical function good(phi)
            real(wp), intent(in) :: phi
            real(wp) :: a, ta, ee, tt
            integer :: st
            call phase_eval(tab, law, phi, a, ta)
            call hertzdamp_host_collide(a, ta / steps, phi, law, iend, host, ee, tt, st)
            good = st == HD_OK .and. abs(ee - e) <= check_tol * e .and. abs(tt - ta) <= check_tol * ta
        end function good
    end subroutine check_table

    !> The phase of the point t of half s of a table under construction (lay: the halves'
    !> centres, one over their lengths; hertzdamp_phase_build): the centre plus or minus the
    !> half length times t^r; the piece's middle at t = 1.
    pure real(wp) function node_phase(tab, lay, s, t) result(phi)
        real(wp), intent(in) :: tab(:), lay(4, 5), t
        integer, intent(in) :: s
        real(wp) :: d
        d = t**nint(tab(8)) / lay(s, 2)
        if (mod(s, 2) == 1) then
            phi = lay(s, 1) + d
        else
            phi = lay(s, 1) - d
        end if
        if (t >= 1.0_wp) phi = merge(tab(5), tab(6), s <= 2)
    end function node_phase

    !> Whether the layout entries of a table (2 .. 34 but the markers 3 and 16, 22, 28, 34)
    !> are consistent as hertzdamp_phase_build writes them (the full check of
    !> hertzdamp_pair_phase_status beside the markers): the halves' node counts, offsets
    !> (each half right after the one before, the last one inside the block), the phases and
    !> scales in range; and the node values finite, K > 0.
    pure logical function hertzdamp_phase_table_ok(tab) result(ok)
        real(wp), intent(in) :: tab(hertzdamp_pair_phase_size)  !! the table
        real(wp) :: jm(4), off(4)
        integer :: last
        ok = tab(2) == 0.0_wp
        if (ok .or. .not. tab(2) == 4.0_wp) return
        jm = tab(14:32:6)
        off = tab(15:33:6)
        ok = all(jm >= 0.0_wp) .and. all(jm <= real(hertzdamp_phase_half_max - 4, wp)) .and. all(jm == aint(jm)) .and. &
             off(1) == real(hertzdamp_phase_header, wp) .and. all(off(2:4) == off(1:3) + 2.0_wp * (jm(1:3) + 4.0_wp)) .and. &
             off(4) + 2.0_wp * (jm(4) + 4.0_wp) <= real(hertzdamp_pair_phase_size, wp) .and. &
             tab(4) > 0.0_wp .and. tab(4) < 1.0_wp .and. tab(5) > 0.0_wp .and. tab(5) < tab(4) .and. &
             tab(6) > tab(4) .and. tab(6) < 1.0_wp .and. (tab(8) == 2.0_wp .or. tab(8) == 4.0_wp) .and. &
             tab(9) > tab(4) .and. tab(9) <= 1.0_wp .and. tab(7) >= hertzdamp_host_steps_min .and. &
             tab(7) <= hertzdamp_host_steps_max .and. all(tab(11:29:6) >= 0.0_wp) .and. all(tab(11:29:6) <= 1.0_wp) .and. &
             all(tab(12:30:6) > 0.0_wp) .and. all(tab(12:30:6) <= huge(1.0_wp)) .and. &
             all(tab(13:31:6) <= -1.5_wp) .and. all(tab(13:31:6) >= -1.5_wp - real(hertzdamp_phase_half_max, wp))
        ! the nodes: K finite and positive, A finite (a changed node value is not seen by the
        ! markers; this keeps a NaN or an infinity out of every k, d)
        if (ok) then
            last = nint(off(4) + 2.0_wp * (jm(4) + 4.0_wp))
            ok = all(tab(hertzdamp_phase_header + 1:last:2) > 0.0_wp) .and. &
                 all(tab(hertzdamp_phase_header + 1:last:2) <= huge(1.0_wp)) .and. &
                 all(abs(tab(hertzdamp_phase_header + 2:last:2)) <= huge(1.0_wp))
        end if
    end function hertzdamp_phase_table_ok

    ! ================================================================ fewest steps

    !> The fewest whole N at which the onset-phase table of (e, law, iend, host) builds, i.e.
    !> every phase (every node of the table) has constants: N and the next three succeed, N - 1
    !> fails.  Every N from 2 to 64, then doubling up to 1024 and bisection.  Status HD_OK, the
    !> bad-input statuses of hertzdamp_host_solve, or HD_PHASE_UNREACHABLE when none up to 1024
    !> does.
    pure subroutine hertzdamp_phase_min_steps(e, law, iend, host, n_min, status)
        real(wp), intent(in) :: e        !! target restitution coefficient
        integer, intent(in) :: law       !! HD_DAMPING_*
        integer, intent(in) :: iend      !! HD_END_*
        integer, intent(in) :: host      !! HD_HOST_*
        integer, intent(out) :: n_min    !! fewest steps per contact
        integer, intent(out) :: status   !! HD_OK or the failure
        integer :: n, lo, hi, mid, k, st
        n_min = 0
        call try(2, st)
        if (st /= HD_OK .and. st /= HD_PHASE_UNREACHABLE .and. st /= HD_HOST_UNREACHABLE) then
            status = st
            return
        end if
        status = HD_PHASE_UNREACHABLE
        n = 0
        if (st == HD_OK) then
            n = 2
        else
            do k = 3, 64
                call try(k, st)
                if (st == HD_OK) then
                    n = k
                    exit
                end if
            end do
            if (n == 0) then
                lo = 64
                hi = 128
                do
                    call try(hi, st)
                    if (st == HD_OK) exit
                    lo = hi
                    if (hi >= n_search_max) return
                    hi = min(2 * hi, n_search_max)
                end do
                do while (hi - lo > 1)
                    mid = (lo + hi) / 2
                    call try(mid, st)
                    if (st == HD_OK) then
                        hi = mid
                    else
                        lo = mid
                    end if
                end do
                n = hi
            end if
        end if
        ! confirm N + 1 .. N + 3: a failure at N + k moves N past it, to N + k + 1, which is
        ! then tried too (k = 0)
        k = 1
        do while (k <= 3)
            call try(n + k, st)
            if (st == HD_OK) then
                k = k + 1
            else
                n = n + k + 1
                if (n >= n_search_max) return
                k = 0
            end if
        end do
        n_min = n
        status = HD_OK
    contains
        !> The mean solve and the table at nn steps.
        pure subroutine try(nn, st)
            integer, intent(in) :: nn
            integer, intent(out) :: st
            real(wp) :: a, t, tab(hertzdamp_pair_phase_size)
            type(hertzdamp_host_stats) :: s
            call hertzdamp_host_solve(e, law, iend, host, real(nn, wp), a, t, s, st)
            if (st == HD_OK) call hertzdamp_phase_build(e, law, iend, host, real(nn, wp), a, t, tab, st)
        end subroutine try
    end subroutine hertzdamp_phase_min_steps

    include 'hertzdamp_phase_eval.inc'

end module hertzdamp_phase
