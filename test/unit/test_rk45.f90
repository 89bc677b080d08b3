!> The reference integrator against exact facts (doc/theory.md section 4), its own
!> convergence order, and its statuses.
program test_rk45
    use hertzdamp
    use hertzdamp_rk45_kernel, only: hertzdamp_dp_step, hertzdamp_dp_dense, HD_MODEL_LINEAR, hertzdamp_locate, &
                                     hertzdamp_polish, hertzdamp_rk45_stats, HD_EVENT_TURN
    use hertzdamp_testing, only: test_suite, new_suite, rel_err
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    type(test_suite) :: s

    s = new_suite('test_rk45')
    call elastic_limit()
    call first_order_slope()
    call time_reversal()
    call monotonicity()
    call critical_damping()
    call fixed_step_order()
    call dense_output_order()
    call tolerance_proportionality()
    call force_definition()
    call statuses()
    call scaling_round_trip()
    call event_failures()
    call s%finish()

contains

    subroutine elastic_limit()
        type(hertzdamp_collision) :: r
        r = hertzdamp_rk45_collide(0.0_wp)
        call s%check(r%status == HD_OK, 'alpha=0 status')
        call s%check_close(r%e, 1.0_wp, 1.0e-12_wp, 'alpha=0: e = 1')
        call s%check_close(r%tau_c, hertzdamp_tau_c0(), 1.0e-12_wp, 'alpha=0: tau_c = tau_c(0)')
        call s%check_close(r%z_max, hertzdamp_z_max0(), 1.0e-12_wp, 'alpha=0: z_max = (5/4)^(2/5)')
        call s%check_close(r%tau_max, 0.5_wp * hertzdamp_tau_c0(), 1.0e-12_wp, 'alpha=0: tau_max = tau_c/2')
        ! the force definition coincides with the overlap one at alpha = 0
        r = hertzdamp_rk45_collide(0.0_wp, HD_END_FORCE)
        call s%check_close(r%tau_c, hertzdamp_tau_c0(), 1.0e-12_wp, 'alpha=0 force: tau_c = tau_c(0)')
        ! tiny alpha stays on the elastic values
        r = hertzdamp_rk45_collide(1.0e-300_wp)
        call s%check_close(r%e, 1.0_wp, 1.0e-12_wp, 'alpha=1e-300: e = 1')
        r = hertzdamp_rk45_collide(1.0e-12_wp)
        call s%check_close(r%e, 1.0_wp - hertzdamp_e1() * 1.0e-12_wp, 1.0e-12_wp, 'alpha=1e-12: e = 1 - e1 alpha')
    end subroutine elastic_limit

    !> (1 - e(alpha))/alpha = e1 - c2 alpha + c3 alpha^2 - ...; Richardson on three
    !> alphas removes the alpha and alpha^2 terms: error O(alpha^3) + rounding/alpha.
    subroutine first_order_slope()
        real(wp) :: a, s1, s2, s4, est
        a = 1.0e-3_wp
        s1 = slope(a)
        s2 = slope(2 * a)
        s4 = slope(4 * a)
        est = (8 * s1 - 6 * s2 + s4) / 3
        call s%check_close(est, hertzdamp_e1(), 1.0e-8_wp, 'first-order slope e1 (Richardson)')
    end subroutine first_order_slope

    real(wp) function slope(a)
        real(wp), intent(in) :: a
        type(hertzdamp_collision) :: r
        r = hertzdamp_rk45_collide(a, tol=1.0e-14_wp)
        slope = (1.0_wp - r%e) / a
    end function slope

    !> e(alpha) e(-alpha e^(-1/5)) = 1 and the matching tau_c and z_max relations.
    subroutine time_reversal()
        real(wp), parameter :: alphas(6) = [0.05_wp, 0.2_wp, 0.5_wp, 0.8_wp, 1.0_wp, 1.1_wp]
        type(hertzdamp_collision) :: r, b
        real(wp) :: ab
        integer :: i
        character(len=32) :: lab
        do i = 1, size(alphas)
            write (lab, '(a,f5.2)') ' alpha=', alphas(i)
            r = hertzdamp_rk45_collide(alphas(i))
            ab = -alphas(i) * r%e**(-0.2_wp)
            b = hertzdamp_rk45_collide(ab)
            call s%check(r%status == HD_OK .and. b%status == HD_OK, 'reversal status' // lab)
            call s%check_close(r%e * b%e, 1.0_wp, 1.0e-11_wp, 'e(a) e(-a e^-1/5) = 1' // lab)
            call s%check_close(r%tau_max + r%e**(-0.2_wp) * b%tau_max, r%tau_c, 1.0e-11_wp, &
                               'tau_c = tau_max + e^-1/5 tau_max(reversed)' // lab)
            call s%check_close(r%e**0.8_wp * b%z_max, r%z_max, 1.0e-11_wp, 'z_max = e^4/5 z_max(reversed)' // lab)
            ! reversed run reaches the same end: its own e is 1/e
            call s%check(b%e > 1.0_wp, 'energy-injecting contact has e > 1' // lab)
        end do
    end subroutine time_reversal

    subroutine monotonicity()
        type(hertzdamp_collision) :: r(57)
        integer :: i
        r = hertzdamp_rk45_collide([(0.02_wp * i, i=0, 56)])
        call s%check(all(r%status == HD_OK), 'grid 0..1.12 rebounds')
        call s%check(all(r(2:)%e < r(:56)%e), 'e strictly decreasing in alpha (overlap)')
        call s%check(all(r(2:)%tau_c > r(:56)%tau_c), 'tau_c strictly increasing in alpha (overlap)')
        call s%check(all(r(2:)%z_max < r(:56)%z_max), 'z_max decreasing in alpha')
        r = hertzdamp_rk45_collide([(0.5_wp * i, i=0, 56)], HD_END_FORCE)
        call s%check(all(r%status == HD_OK), 'force grid 0..28 rebounds')
        call s%check(all(r(2:)%e < r(:56)%e), 'force: e strictly decreasing')
        call s%check(all(r%e > 0.0_wp), 'force: e > 0 for every alpha')
    end subroutine monotonicity

    subroutine critical_damping()
        real(wp) :: ac
        integer :: st
        type(hertzdamp_collision) :: r
        call hertzdamp_alpha_c(ac, st)
        call s%check(st == HD_OK, 'alpha_c bisection status')
        call s%check(abs(ac - 1.12799_wp) < 1.0e-5_wp, &
                     'alpha_c = 1.12799 to the 6 digits doc/theory.md quotes (10 digits: test_rk45_vs_gsl)')
        r = hertzdamp_rk45_collide(ac - 1.0e-6_wp)
        call s%check(r%status == HD_OK .and. r%e > 0.0_wp .and. r%e < 1.0e-4_wp, 'just below alpha_c: small rebound')
        call s%check(r%tau_c > 10.0_wp, 'just below alpha_c: long contact')
        r = hertzdamp_rk45_collide(ac + 1.0e-6_wp)
        call s%check(r%status == HD_NO_REBOUND .and. r%e == 0.0_wp .and. r%tau_c > huge(1.0_wp), &
                     'just above alpha_c: no rebound, e = 0, tau_c = inf')
        r = hertzdamp_rk45_collide(ac + 1.0e-9_wp)    ! 100 bisection widths above alpha_c
        call s%check(r%status == HD_NO_REBOUND, 'alpha_c + 1e-9: no rebound')
        call s%check(r%stats%rhs_evals < 1000000, 'alpha_c + 1e-9: bounded work')
        r = hertzdamp_rk45_collide(100.0_wp)
        call s%check(r%status == HD_NO_REBOUND .and. r%stats%rhs_evals < 100000, 'alpha=100 overlap: no rebound quickly')
    end subroutine critical_damping

    !> Fixed steps on z'' + a z' + z = 0 (exact solution known): global error ~ h^5.
    subroutine fixed_step_order()
        real(wp) :: e1_, e2_, order
        e1_ = linear_error(40)
        e2_ = linear_error(80)
        order = log(e1_ / e2_) / log(2.0_wp)
        call s%check(order > 4.8_wp .and. order < 5.3_wp, 'Dormand-Prince global order 5 (fixed steps)')
        if (.not. (order > 4.8_wp .and. order < 5.3_wp)) print *, '     observed order', order
    end subroutine fixed_step_order

    real(wp) function linear_error(n) result(err)
        integer, intent(in) :: n
        real(wp), parameter :: a = 0.3_wp, tend = 4.0_wp
        real(wp) :: y(2), k1(2), ynew(2), k7(2), ev(2), cont(2, 5), h
        integer :: i
        h = tend / n
        y = [0.0_wp, 1.0_wp]
        k1 = [y(2), -a * y(2) - y(1)]
        do i = 1, n
            call hertzdamp_dp_step(HD_MODEL_LINEAR, HD_DAMPING_LINEAR, a, y, k1, h, ynew, k7, ev, cont)
            y = ynew
            k1 = k7
        end do
        err = maxval(abs(y - linear_exact(a, tend)))
    end function linear_error

    pure function linear_exact(a, t) result(y)
        real(wp), intent(in) :: a, t
        real(wp) :: y(2), w
        w = sqrt(1.0_wp - 0.25_wp * a * a)
        y(1) = exp(-0.5_wp * a * t) * sin(w * t) / w
        y(2) = exp(-0.5_wp * a * t) * (cos(w * t) - 0.5_wp * a * sin(w * t) / w)
    end function linear_exact

    !> One step from the exact state: the step end has local error ~ h^6, the
    !> continuous extension inside the step ~ h^5.
    subroutine dense_output_order()
        real(wp) :: ed(2), es(2), od, os
        integer :: i
        real(wp) :: h
        do i = 1, 2
            h = 0.2_wp / i
            call one_step(h, ed(i), es(i))
        end do
        od = log(ed(1) / ed(2)) / log(2.0_wp)
        os = log(es(1) / es(2)) / log(2.0_wp)
        call s%check(od > 4.7_wp .and. od < 5.5_wp, 'dense output local order 5 (4th-order interpolant)')
        call s%check(os > 5.7_wp .and. os < 6.5_wp, 'step local order 6 (5th-order method)')
        if (.not. (od > 4.7_wp .and. od < 5.5_wp .and. os > 5.7_wp .and. os < 6.5_wp)) print *, '     orders', od, os
    end subroutine dense_output_order

    subroutine one_step(h, ed, es)
        real(wp), intent(in) :: h
        real(wp), intent(out) :: ed, es
        real(wp), parameter :: a = 0.3_wp, t0 = 0.7_wp
        real(wp) :: y(2), k1(2), ynew(2), k7(2), ev(2), cont(2, 5)
        y = linear_exact(a, t0)
        k1 = [y(2), -a * y(2) - y(1)]
        call hertzdamp_dp_step(HD_MODEL_LINEAR, HD_DAMPING_LINEAR, a, y, k1, h, ynew, k7, ev, cont)
        es = maxval(abs(ynew - linear_exact(a, t0 + h)))
        ed = maxval(abs(hertzdamp_dp_dense(cont, 0.4_wp) - linear_exact(a, t0 + 0.4_wp * h)))
    end subroutine one_step

    !> Adaptive integration of the collision: error against a tight run falls about
    !> in proportion to the tolerance (global error ~ tol for per-step control).
    subroutine tolerance_proportionality()
        real(wp), parameter :: tols(3) = [1.0e-6_wp, 1.0e-8_wp, 1.0e-10_wp]
        real(wp) :: err(3), slope_
        type(hertzdamp_collision) :: ref, r
        integer :: i
        ref = hertzdamp_rk45_collide(0.5_wp, tol=1.0e-15_wp)
        do i = 1, 3
            r = hertzdamp_rk45_collide(0.5_wp, tol=tols(i))
            err(i) = max(rel_err(r%e, ref%e), rel_err(r%tau_c, ref%tau_c))
        end do
        slope_ = log(err(1) / err(3)) / log(tols(1) / tols(3))
        call s%check(slope_ > 0.75_wp .and. slope_ < 1.3_wp, 'error ~ tol^1 as the tolerance tightens')
        call s%check(all(err < 10 * tols), 'error below 10 x tol')
        if (.not. (slope_ > 0.75_wp .and. slope_ < 1.3_wp)) print *, '     errors', err, 'slope', slope_
    end subroutine tolerance_proportionality

    subroutine force_definition()
        type(hertzdamp_collision) :: ro, rf
        integer :: i
        real(wp), parameter :: alphas(4) = [0.1_wp, 0.5_wp, 1.0_wp, 2.0_wp]
        do i = 1, size(alphas)
            ro = hertzdamp_rk45_collide(min(alphas(i), 1.1_wp))
            rf = hertzdamp_rk45_collide(alphas(i), HD_END_FORCE)
            call s%check(rf%status == HD_OK, 'force status')
            call s%check(rf%tau_c > rf%tau_max, 'force: contact ends after the turning point')
            if (alphas(i) <= 1.1_wp) then
                call s%check(rf%e > ro%e, 'force: separation before the overlap is gone gives larger e')
                call s%check(rf%tau_c < ro%tau_c, 'force: shorter contact than overlap')
                call s%check_close(rf%z_max, ro%z_max, 1.0e-13_wp, 'same turning point for both ends')
            end if
        end do
        ! strongly damped: bounded work (stiff relative to the contact duration)
        rf = hertzdamp_rk45_collide(1.0e4_wp, HD_END_FORCE)
        call s%check(rf%status == HD_OK .and. rf%e > 0.0_wp .and. rf%stats%rhs_evals < 1000000, &
                     'force alpha=1e4 finishes in bounded work')
        ! asymptotics of strong damping: e ~ z^(3/2)/alpha with z ~ 1/alpha
        call s%check(rf%e > 0.5e-10_wp .and. rf%e < 2.0e-10_wp, 'force alpha=1e4: e ~ alpha^(-5/2)')
    end subroutine force_definition

    subroutine statuses()
        type(hertzdamp_collision) :: r
        real(wp) :: zero
        zero = 0.0_wp
        r = hertzdamp_rk45_collide(zero / zero)
        call s%check(r%status == HD_BAD_ALPHA, 'NaN alpha -> HD_BAD_ALPHA')
        r = hertzdamp_rk45_collide(1.0_wp / zero)
        call s%check(r%status == HD_BAD_ALPHA, 'Inf alpha -> HD_BAD_ALPHA')
        r = hertzdamp_rk45_collide(-0.5_wp, HD_END_FORCE)
        call s%check(r%status == HD_BAD_ALPHA, 'negative alpha with force end -> HD_BAD_ALPHA')
        r = hertzdamp_rk45_collide(-11.0_wp)
        call s%check(r%status == HD_BAD_ALPHA, 'alpha below -10 -> HD_BAD_ALPHA')
        r = hertzdamp_rk45_collide(0.5_wp, 7)
        call s%check(r%status == HD_BAD_END, 'bad end -> HD_BAD_END')
        r = hertzdamp_rk45_collide(0.5_wp, tol=0.5_wp)
        call s%check(r%status == HD_BAD_TOL, 'bad tol -> HD_BAD_TOL')
        call s%check(len(hertzdamp_message(HD_NO_REBOUND)) > 10, 'message for no rebound')
        call s%check(hertzdamp_message(HD_OK) == 'success', 'message for success')
    end subroutine statuses

    subroutine scaling_round_trip()
        real(wp) :: alpha, tstar, k, d
        integer :: st
        call hertzdamp_reduce(2.0e9_wp, 3.0_wp, 1.0e-3_wp, 0.7_wp, alpha, tstar, st)
        call s%check(st == HD_OK, 'reduce status')
        call s%check_close(tstar, (1.0e-3_wp / (2.0e9_wp * sqrt(0.7_wp)))**0.4_wp, 1.0e-14_wp, 't* formula')
        call s%check_close(alpha, 3.0_wp * tstar / 1.0e-3_wp, 1.0e-14_wp, 'alpha = d t*/m')
        call hertzdamp_expand(alpha, tstar, 1.0e-3_wp, 0.7_wp, k, d, st)
        call s%check_close(k, 2.0e9_wp, 1.0e-13_wp, 'expand gives k back')
        call s%check_close(d, 3.0_wp, 1.0e-13_wp, 'expand gives d back')
        ! extreme decades: no overflow in the powers
        call hertzdamp_reduce(1.0e15_wp, 1.0e6_wp, 1.0e-20_wp, 1.0e-8_wp, alpha, tstar, st)
        call s%check(st == HD_OK .and. alpha > 0.0_wp .and. tstar > 0.0_wp, 'extreme inputs reduce')
        call hertzdamp_expand(alpha, tstar, 1.0e-20_wp, 1.0e-8_wp, k, d, st)
        call s%check_close(k, 1.0e15_wp, 1.0e-12_wp, 'extreme round trip k')
        call s%check_close(d, 1.0e6_wp, 1.0e-12_wp, 'extreme round trip d')
        call hertzdamp_reduce(-1.0_wp, 0.0_wp, 1.0_wp, 1.0_wp, alpha, tstar, st)
        call s%check(st == HD_BAD_STIFFNESS, 'negative k -> HD_BAD_STIFFNESS')
        call hertzdamp_reduce(1.0_wp, -1.0_wp, 1.0_wp, 1.0_wp, alpha, tstar, st)
        call s%check(st == HD_BAD_DAMPING, 'negative d -> HD_BAD_DAMPING')
        call hertzdamp_reduce(1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, alpha, tstar, st)
        call s%check(st == HD_BAD_MASS, 'zero mass -> HD_BAD_MASS')
        call hertzdamp_reduce(1.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, alpha, tstar, st)
        call s%check(st == HD_BAD_VELOCITY, 'zero velocity -> HD_BAD_VELOCITY')
        call hertzdamp_expand(1.0_wp, 1.0e-300_wp, 1.0e300_wp, 1.0e-300_wp, k, d, st)
        call s%check(st == HD_OUT_OF_RANGE .and. k == 0.0_wp, 'overflowing k -> HD_OUT_OF_RANGE')
    end subroutine scaling_round_trip

    !> The event routines report failure instead of a silent answer (issue 13):
    !> hertzdamp_locate without a sign change, hertzdamp_polish when Newton leaves the
    !> step; and a polished event before the step start comes with its own state.
    !> Test problem z'' + a z' + z = 0 (exact solution), turning point at
    !> t_tp = atan(w / (a/2)) / w, w = sqrt(1 - a^2/4).
    subroutine event_failures()
        real(wp), parameter :: a = 0.3_wp
        real(wp) :: y(2), k1(2), ynew(2), k7(2), ev(2), cont(2, 5), theta, out(3), w, ttp, t0, h, ytp(2)
        integer :: st
        type(hertzdamp_rk45_stats) :: stats
        w = sqrt(1.0_wp - 0.25_wp * a * a)
        ttp = atan(w / (0.5_wp * a)) / w
        ! a step that does not contain the turning point: no sign change of z'
        y = linear_exact(a, 0.2_wp)
        k1 = [y(2), -a * y(2) - y(1)]
        call hertzdamp_dp_step(HD_MODEL_LINEAR, HD_DAMPING_LINEAR, a, y, k1, 0.1_wp, ynew, k7, ev, cont)
        call hertzdamp_locate(HD_EVENT_TURN, HD_MODEL_LINEAR, HD_DAMPING_LINEAR, cont, a, 0.0_wp, 0.0_wp, 1.0_wp, theta, st)
        call s%check(st == HD_NO_CONVERGENCE, 'locate: no sign change is a failure, not the step end')
        call hertzdamp_polish(HD_EVENT_TURN, HD_MODEL_LINEAR, HD_DAMPING_LINEAR, 0.2_wp, y, k1, 0.1_wp, 0.5_wp, a, out, &
                              stats, st)
        call s%check(st == HD_NO_CONVERGENCE .and. all(out == 0.0_wp), 'polish: Newton leaving the step is a failure')
        ! a step that contains it: located and polished to the exact time
        t0 = ttp - 0.04_wp
        h = 0.1_wp
        y = linear_exact(a, t0)
        k1 = [y(2), -a * y(2) - y(1)]
        call hertzdamp_dp_step(HD_MODEL_LINEAR, HD_DAMPING_LINEAR, a, y, k1, h, ynew, k7, ev, cont)
        call hertzdamp_locate(HD_EVENT_TURN, HD_MODEL_LINEAR, HD_DAMPING_LINEAR, cont, a, 0.0_wp, 0.0_wp, 1.0_wp, theta, st)
        call s%check(st == HD_OK .and. abs(t0 + theta * h - ttp) < 1.0e-8_wp, 'locate: turning point on the dense output')
        call hertzdamp_polish(HD_EVENT_TURN, HD_MODEL_LINEAR, HD_DAMPING_LINEAR, t0, y, k1, h, theta, a, out, stats, st)
        call s%check(st == HD_OK, 'polish converges')
        call s%check_close(out(1), ttp, 1.0e-11_wp, 'polish: exact turning time')
        ytp = linear_exact(a, ttp)
        call s%check_close(out(2), ytp(1), 1.0e-11_wp, 'polish: the state at that time')
        ! started from a trial point inside the step after the event: the polished time
        ! is before the step start, and the state is that of the polished time
        t0 = ttp + 0.01_wp
        y = linear_exact(a, t0)
        k1 = [y(2), -a * y(2) - y(1)]
        call hertzdamp_polish(HD_EVENT_TURN, HD_MODEL_LINEAR, HD_DAMPING_LINEAR, t0, y, k1, h, 0.05_wp, a, out, stats, st)
        call s%check(st == HD_OK .and. out(1) < t0, 'polish: event before the step start found')
        call s%check_close(out(1), ttp, 1.0e-11_wp, 'polish before the step start: exact time')
        call s%check_close(out(2), ytp(1), 1.0e-11_wp, 'polish before the step start: state matches the time')
    end subroutine event_failures

end program test_rk45
