!> The fitted maps of the tsuji and kuwabara-kono laws (hertzdamp_fit_laws) against the
!> reference integrator at tolerance 1e-15, the tsuji ones also against their closed
!> forms, and the inverse rule of every law (d from alpha = d t* (u t*)^q / m, with and
!> without the physical bound) against the law-aware reduction.
program test_fit_laws
    use hertzdamp
    use hertzdamp_testing, only: test_suite, new_suite, rel_err
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: new_laws(2) = [HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO]
    type(test_suite) :: s
    integer :: il, iend

    s = new_suite('test_fit_laws')
    do il = 1, size(new_laws)
        do iend = HD_END_OVERLAP, HD_END_FORCE
            call against_reference(new_laws(il), iend)
            call limits_and_ranges(new_laws(il), iend)
        end do
    end do
    call tsuji_closed_forms()
    call linear_unchanged()
    call inverse_rule()
    do il = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
        do iend = HD_END_OVERLAP, HD_END_FORCE
            call forward_derivatives(il, iend)
        end do
    end do
    call derivative_edges()
    call s%finish()

contains

    !> Forward (e, tau_c, z_max, tau_max) and inverse (alpha, tau_c) of the fit within
    !> 1e-12 of rk45 at 1e-15, over the fitted ranges: inverse down to e = 1e-4, forward
    !> down to e = 1e-5.
    subroutine against_reference(law, iend)
        integer, intent(in) :: law, iend
        type(hertzdamp_collision) :: r
        real(wp) :: amax, afwd, a, e, tc, zm, tm, a2, tc2, x, err(3)
        integer :: i, st
        character(len=40) :: lab
        lab = ' ' // hertzdamp_law_name(law) // ' ' // hertzdamp_end_name(iend)
        call hertzdamp_fit_law_inverse(1.0e-4_wp, iend, law, amax, tc, st)
        call s%check(st == HD_OK .and. amax > 0.0_wp, 'inverse at e_min' // trim(lab))
        afwd = alpha_at(law, iend, 1.0e-5_wp)
        err = 0.0_wp
        do i = 1, 200
            x = (real(i, wp) - 0.5_wp) / 200.0_wp
            ! denser towards alpha = 0 for the force end (alpha^(1/n) terms)
            a = afwd * x**merge(1.0_wp, 2.0_wp, iend == HD_END_OVERLAP)
            r = hertzdamp_rk45_collide(a, iend, 1.0e-15_wp, law)
            call hertzdamp_fit_law_forward(a, iend, law, e, tc, st, zm, tm)
            call s%check(st == HD_OK .and. r%status == HD_OK, 'forward status' // trim(lab))
            err(1) = max(err(1), rel_err(e, r%e), rel_err(tc, r%tau_c))
            err(2) = max(err(2), rel_err(zm, r%z_max), rel_err(tm, r%tau_max))
            if (r%e >= 1.0e-4_wp) then
                call hertzdamp_fit_law_inverse(r%e, iend, law, a2, tc2, st)
                ! below alpha ~ 1e-2 the reference e (error ~1e-15 absolute) cannot resolve 1e-12 in alpha
                err(3) = max(err(3), abs(a2 - a) / (a + 1.0e-2_wp), rel_err(tc2, r%tau_c))
            end if
        end do
        call s%check(err(1) < 1.0e-12_wp, 'fit forward e, tau_c within 1e-12' // trim(lab))
        call s%check(err(2) < 1.0e-12_wp, 'fit forward z_max, tau_max within 1e-12' // trim(lab))
        call s%check(err(3) < 1.0e-12_wp, 'fit inverse alpha, tau_c within 1e-12' // trim(lab))
        print '(a,a,3es10.2)', 'max rel err fit fwd (e,tau_c), (z_max,tau_max), inverse (alpha,tau_c):', trim(lab), err
        ! relative error of alpha where alpha is small (e near 1): 121 alpha log-spaced in [0.01, 0.3]
        ! (the reference e, ~1e-15 absolute, resolves alpha there to ~1e-13 relative)
        err(3) = 0.0_wp
        do i = 0, 120
            a = 0.01_wp * 30.0_wp**(real(i, wp) / 120.0_wp)
            r = hertzdamp_rk45_collide(a, iend, 1.0e-15_wp, law)
            call hertzdamp_fit_law_inverse(r%e, iend, law, a2, tc2, st)
            err(3) = max(err(3), rel_err(a2, a))
        end do
        call s%check(err(3) < 1.0e-12_wp, 'fit inverse alpha within 1e-12 relative, alpha in [0.01, 0.3]' // trim(lab))
        print '(a,a,es10.2)', 'max rel err fit inverse alpha, alpha in [0.01, 0.3]:', trim(lab), err(3)
    end subroutine against_reference

    !> alpha with e(alpha) = e by bisection on rk45 (for the forward range of the test).
    real(wp) function alpha_at(law, iend, e) result(a)
        integer, intent(in) :: law, iend
        real(wp), intent(in) :: e
        real(wp) :: lo, hi
        type(hertzdamp_collision) :: r
        integer :: it
        lo = 0.0_wp
        hi = 1.0_wp
        do
            r = hertzdamp_rk45_collide(hi, iend, law=law)
            if (r%status /= HD_OK .or. r%e < e) exit
            lo = hi
            hi = 2.0_wp * hi
        end do
        do it = 1, 60
            a = 0.5_wp * (lo + hi)
            r = hertzdamp_rk45_collide(a, iend, law=law)
            if (r%status == HD_OK .and. r%e > e) then
                lo = a
            else
                hi = a
            end if
        end do
        a = lo
    end function alpha_at

    subroutine limits_and_ranges(law, iend)
        integer, intent(in) :: law, iend
        real(wp) :: a, tc, e, zm, tm
        integer :: st
        character(len=40) :: lab
        lab = ' ' // hertzdamp_law_name(law) // ' ' // hertzdamp_end_name(iend)
        call hertzdamp_fit_law_inverse(1.0_wp, iend, law, a, tc, st)
        call s%check(st == HD_OK .and. .not. (a /= 0.0_wp) .and. .not. (tc /= hertzdamp_tau_c0()), &
                     'e = 1: alpha = 0, tau_c = tau_c0 exactly' // trim(lab))
        call hertzdamp_fit_law_forward(0.0_wp, iend, law, e, tc, st, zm, tm)
        call s%check_close(e, 1.0_wp, 1.0e-15_wp, 'alpha = 0: e = 1' // trim(lab))
        call s%check_close(tc, hertzdamp_tau_c0(), 1.0e-14_wp, 'alpha = 0: tau_c0' // trim(lab))
        call s%check_close(zm, hertzdamp_z_max0(), 1.0e-14_wp, 'alpha = 0: z_max0' // trim(lab))
        call hertzdamp_fit_law_inverse(0.999_wp, iend, law, a, tc, st)
        call s%check_close(a, 0.001_wp / hertzdamp_e1(law), 5.0e-3_wp, 'slope e1(law) at e = 1' // trim(lab))
        call s%check_close(hertzdamp_fit_law_e_min(law, iend), 1.0e-4_wp, 1.0e-15_wp, 'e_min = 1e-4' // trim(lab))
        call hertzdamp_fit_law_inverse(0.9e-4_wp, iend, law, a, tc, st)
        call s%check(st == HD_BAD_RESTITUTION .and. .not. (a /= 0.0_wp), 'e below e_min' // trim(lab))
        call hertzdamp_fit_law_inverse(ieee_value(1.0_wp, ieee_quiet_nan), iend, law, a, tc, st)
        call s%check(st == HD_BAD_RESTITUTION, 'e NaN' // trim(lab))
        call hertzdamp_fit_law_forward(-0.1_wp, iend, law, e, tc, st)
        call s%check(st == HD_OUTSIDE_VALIDITY .and. .not. (e /= 0.0_wp), 'alpha < 0' // trim(lab))
        call hertzdamp_fit_law_forward(5.0e3_wp, iend, law, e, tc, st, zm, tm)
        if (law == HD_DAMPING_TSUJI .and. iend == HD_END_OVERLAP) then
            call s%check(st == HD_NO_REBOUND .and. .not. ieee_is_finite(tc), 'tsuji overlap beyond sqrt5: no rebound')
        else
            call s%check(st == HD_OUTSIDE_VALIDITY .and. .not. (e /= 0.0_wp) .and. .not. (zm /= 0.0_wp), &
                         'beyond the fitted range: outside validity' // trim(lab))
        end if
        call hertzdamp_fit_law_inverse(0.5_wp, 2, law, a, tc, st)
        call s%check(st == HD_BAD_END, 'bad end' // trim(lab))
    end subroutine limits_and_ranges

    !> tsuji: the fit's alpha(e) and e(alpha) are the closed forms; the forward and the
    !> inverse tau_c agree; beyond sqrt(5) no rebound; just below, e from the closed form
    !> and tau_c outside the fitted range.
    subroutine tsuji_closed_forms()
        real(wp) :: e, a, tc, ef, tcf, ex
        integer :: i, st
        do i = 0, 40
            e = 10.0_wp**(-0.1_wp * i)
            call hertzdamp_fit_law_inverse(e, HD_END_OVERLAP, HD_DAMPING_TSUJI, a, tc, st)
            call s%check_close(a, -sqrt(5.0_wp) * log(e) / sqrt(acos(-1.0_wp)**2 + log(e)**2), 4.0e-15_wp, &
                               'tsuji overlap alpha = sqrt5 beta(e)')
            call hertzdamp_fit_law_forward(a, HD_END_OVERLAP, HD_DAMPING_TSUJI, ef, tcf, st)
            call s%check_close(ef, e, 1.0e-13_wp, 'tsuji overlap forward e exact')
            call s%check_close(tcf, tc, 1.0e-13_wp, 'tsuji overlap forward tau_c = inverse tau_c')
            call hertzdamp_fit_law_inverse(e, HD_END_FORCE, HD_DAMPING_TSUJI, a, tc, st)
            call hertzdamp_tsuji_e(a, HD_END_FORCE, ex, st)
            call s%check_close(ex, e, 1.0e-12_wp, 'tsuji force: closed-form e of the fitted alpha(e)')
        end do
        call hertzdamp_fit_law_forward(2.2_wp, HD_END_OVERLAP, HD_DAMPING_TSUJI, ef, tcf, st)
        call s%check(st == HD_OUTSIDE_VALIDITY, 'tsuji overlap e < 1e-5: tau_c not fitted')
    end subroutine tsuji_closed_forms

    !> The law argument's default and explicit linear give the linear fit bit for bit.
    subroutine linear_unchanged()
        real(wp) :: a1, t1, a2, t2, e1_, e2_
        integer :: s1, s2, i, iend_
        logical :: ok
        ok = .true.
        do iend_ = HD_END_OVERLAP, HD_END_FORCE
            do i = 1, 50
                call hertzdamp_fit_inverse(0.02_wp * i, iend_, a1, t1, s1)
                call hertzdamp_fit_law_inverse(0.02_wp * i, iend_, HD_DAMPING_LINEAR, a2, t2, s2)
                ok = ok .and. s1 == s2 .and. .not. (a1 /= a2 .or. t1 /= t2)
                call hertzdamp_fit_forward(0.02_wp * i, iend_, e1_, t1, s1)
                call hertzdamp_fit_law_forward(0.02_wp * i, iend_, HD_DAMPING_LINEAR, e2_, t2, s2)
                ok = ok .and. s1 == s2 .and. .not. (e1_ /= e2_ .or. t1 /= t2)
            end do
        end do
        call s%check(ok, 'linear law through hertzdamp_fit_law_* = hertzdamp_fit_* bit for bit')
    end subroutine linear_unchanged

    !> hertzdamp_fit_forward_deriv: its e and tau_c are those of hertzdamp_fit_law_forward
    !> bit for bit; its de/dalpha and dtau_c/dalpha against differences of the fit itself
    !> (central, steps h and h/2 with Richardson extrapolation, h = 1e-3 of the distance
    !> to the nearest end of the law's range: 0, alpha_c; to 1e-8 plus the rounding of the
    !> differences: that of the values and of the fit's variable, which near alpha_c
    !> carries that of alpha/alpha_c) and of the reference integrator (rk45 at 1e-14, central,
    !> h = 1e-4 of that distance; to 1e-6), over the fitted forward range of each law and
    !> end (e >= 1e-5; linear force: alpha <= 52.5), denser towards alpha = 0.
    subroutine forward_derivatives(law, iend)
        integer, intent(in) :: law, iend
        real(wp) :: amax, ac, a, h, gap, e, tau, de, dtau, e0, t0, fd(2), worst(2), err
        integer :: nbad
        type(hertzdamp_collision) :: rp, rm
        integer :: i, st, st0
        logical :: same_values
        character(len=40) :: lab
        lab = ' ' // hertzdamp_law_name(law) // ' ' // hertzdamp_end_name(iend)
        amax = alpha_at(law, iend, 1.05e-5_wp)
        if (law == HD_DAMPING_LINEAR .and. iend == HD_END_FORCE) amax = min(amax, 0.999_wp * hertzdamp_fit_alpha_max_force)
        ac = huge(1.0_wp)
        if (iend == HD_END_OVERLAP) ac = hertzdamp_law_alpha_c(law)
        worst = 0.0_wp
        nbad = 0
        same_values = .true.
        do i = 1, 97
            a = amax * (real(i, wp) / 97.0_wp)**2
            call hertzdamp_fit_forward_deriv(a, iend, law, e, tau, de, dtau, st)
            call hertzdamp_fit_law_forward(a, iend, law, e0, t0, st0)
            same_values = same_values .and. st == HD_OK .and. st0 == HD_OK .and. .not. (e /= e0 .or. tau /= t0)
            if (st /= HD_OK) cycle
            gap = min(a, ac - a)
            h = 1.0e-3_wp * gap
            fd = richardson(law, iend, a, h)
            err = max(rel_err(de, fd(1)), rel_err(dtau, fd(2)))
            worst(1) = max(worst(1), err)
            ! 1e-8 and the rounding of the differences (relative to f'): that of f itself and
            ! that of the fit's variable (near alpha_c: of alpha/alpha_c), 100 eps (|f/f'| or alpha)/h
            if (.not. (rel_err(de, fd(1)) <= 1.0e-8_wp + 100.0_wp * epsilon(a) * (a + abs(e / de)) / h .and. &
                       rel_err(dtau, fd(2)) <= 1.0e-8_wp + 100.0_wp * epsilon(a) * (a + abs(tau / dtau)) / h)) then
                nbad = nbad + 1
                print '(a,4es12.4)', 'derivative against differences of the fit: alpha, error, de, dtau ', a, err, de, dtau
            end if
            h = 1.0e-4_wp * gap
            rp = hertzdamp_rk45_collide(a + h, iend, 1.0e-14_wp, law)
            rm = hertzdamp_rk45_collide(a - h, iend, 1.0e-14_wp, law)
            worst(2) = max(worst(2), rel_err(de, (rp%e - rm%e) / (2.0_wp * h)), &
                           rel_err(dtau, (rp%tau_c - rm%tau_c) / (2.0_wp * h)))
        end do
        print '(a,a,2es10.2)', 'derivatives de/dalpha, dtau_c/dalpha: max rel err against differences of the fit, ' // &
            'of rk45:', trim(lab), worst
        call s%check(same_values, 'derivative call: e, tau_c of the forward fit bit for bit' // trim(lab))
        call s%check(nbad == 0, 'derivatives = Richardson differences of the fit (1e-8 + rounding)' // trim(lab))
        call s%check(worst(2) < 1.0e-6_wp, 'derivatives = central differences of rk45 (1e-6)' // trim(lab))
    end subroutine forward_derivatives

    !> (4 D(h/2) - D(h))/3 of e and tau_c of the forward fit of a law and end at alpha.
    function richardson(law, iend, alpha, h) result(df)
        integer, intent(in) :: law, iend
        real(wp), intent(in) :: alpha, h
        real(wp) :: df(2), ee(-2:2), tt(-2:2)
        integer :: j, stj
        do j = -2, 2
            call hertzdamp_fit_law_forward(alpha + 0.5_wp * j * h, iend, law, ee(j), tt(j), stj)
            if (stj /= HD_OK) error stop 'forward_derivatives: the fit failed near alpha'
        end do
        df(1) = (4.0_wp * (ee(1) - ee(-1)) / h - (ee(2) - ee(-2)) / (2.0_wp * h)) / 3.0_wp
        df(2) = (4.0_wp * (tt(1) - tt(-1)) / h - (tt(2) - tt(-2)) / (2.0_wp * h)) / 3.0_wp
    end function richardson

    !> The derivatives at the ends of their range: at alpha = 0 (overlap end) de/dalpha is
    !> -e1(law), the first-order slope from its Beta-function closed form; towards alpha = 0
    !> at the force end too (the force end differs at order alpha^(5/(3-2q))), while
    !> alpha = 0 itself is HD_OUT_OF_RANGE there (dtau_c/dalpha is infinite); no rebound,
    !> beyond the fitted range, bad arguments: the status and zero outputs.
    subroutine derivative_edges()
        real(wp) :: e, tau, de, dtau
        integer :: law, st
        character(len=40) :: lab
        do law = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
            lab = ' ' // hertzdamp_law_name(law)
            call hertzdamp_fit_forward_deriv(0.0_wp, HD_END_OVERLAP, law, e, tau, de, dtau, st)
            call s%check(st == HD_OK, 'alpha = 0, overlap: status ok' // trim(lab))
            call s%check_close(-de, hertzdamp_e1(law), 1.0e-11_wp, 'alpha = 0, overlap: de/dalpha = -e1(law)' // trim(lab))
            call hertzdamp_fit_forward_deriv(1.0e-9_wp, HD_END_FORCE, law, e, tau, de, dtau, st)
            call s%check(st == HD_OK .and. abs(dtau) > 0.0_wp .and. abs(dtau) <= huge(dtau), &
                         'alpha = 1e-9, force: finite dtau_c/dalpha' // trim(lab))
            call s%check_close(-de, hertzdamp_e1(law), 1.0e-5_wp, 'alpha = 1e-9, force: de/dalpha -> -e1(law)' // trim(lab))
            call hertzdamp_fit_forward_deriv(0.0_wp, HD_END_FORCE, law, e, tau, de, dtau, st)
            call s%check(st == HD_OUT_OF_RANGE .and. .not. (e /= 0.0_wp .or. tau /= 0.0_wp .or. de /= 0.0_wp .or. &
                         dtau /= 0.0_wp), 'alpha = 0, force: HD_OUT_OF_RANGE and zeros' // trim(lab))
            call hertzdamp_fit_forward_deriv(-0.1_wp, HD_END_OVERLAP, law, e, tau, de, dtau, st)
            call s%check(st == HD_OUTSIDE_VALIDITY .and. .not. (de /= 0.0_wp), 'alpha < 0: outside validity' // trim(lab))
            call hertzdamp_fit_forward_deriv(5.0e3_wp, HD_END_FORCE, law, e, tau, de, dtau, st)
            call s%check(st == HD_OUTSIDE_VALIDITY .and. .not. (e /= 0.0_wp .or. dtau /= 0.0_wp), &
                         'beyond the fitted range: outside validity, zeros' // trim(lab))
            call hertzdamp_fit_forward_deriv(0.5_wp, 2, law, e, tau, de, dtau, st)
            call s%check(st == HD_BAD_END, 'bad end' // trim(lab))
        end do
        call hertzdamp_fit_forward_deriv(2.3_wp, HD_END_OVERLAP, HD_DAMPING_TSUJI, e, tau, de, dtau, st)
        call s%check(st == HD_NO_REBOUND .and. .not. (tau /= 0.0_wp .or. de /= 0.0_wp), &
                     'tsuji beyond sqrt5: no rebound, zeros')
        call hertzdamp_fit_forward_deriv(1.2_wp, HD_END_OVERLAP, HD_DAMPING_LINEAR, e, tau, de, dtau, st)
        call s%check(st == HD_NO_REBOUND .and. .not. (tau /= 0.0_wp), 'linear beyond alpha_c: no rebound, zeros')
        call hertzdamp_fit_forward_deriv(0.5_wp, HD_END_OVERLAP, 7, e, tau, de, dtau, st)
        call s%check(st == HD_BAD_LAW, 'bad law')
    end subroutine derivative_edges

    !> hertzdamp_invert with a law: the reduction of the returned (k, d) gives back alpha
    !> and the contact time T_c = t* tau_c; with the bound active, k = k_phys and
    !> d = alpha m^((3-2q)/5) k_phys^((2+2q)/5) u^((1-4q)/5) (tsuji: alpha sqrt(m k_phys));
    !> the iterative method agrees with the fit; extreme inputs take the log path.
    subroutine inverse_rule()
        real(wp), parameter :: m = 2.0e-3_wp, u = 1.7_wp, tc = 1.0e-4_wp
        real(wp) :: k, d, alpha, ts, tau, a2, ts2, q, kb, db, e
        integer :: i, st, iend_
        logical :: bound
        character(len=40) :: lab
        do i = 1, 3
            do iend_ = HD_END_OVERLAP, HD_END_FORCE
                lab = ' ' // hertzdamp_law_name(i - 1) // ' ' // hertzdamp_end_name(iend_)
                q = hertzdamp_law_q(i - 1)
                e = 0.4_wp
                call hertzdamp_invert(e, tc, m, u, iend_, k, d, st, alpha=alpha, tstar=ts, tau_c=tau, law=i - 1)
                call s%check(st == HD_OK, 'invert status' // trim(lab))
                call hertzdamp_reduce(k, d, m, u, a2, ts2, st, i - 1)
                call s%check_close(a2, alpha, 1.0e-14_wp, 'reduce(invert) gives alpha back' // trim(lab))
                call s%check_close(ts2 * tau, tc, 1.0e-14_wp, 'reduce(invert): contact time T_c' // trim(lab))
                call s%check_close(d, alpha * m / ts / (u * ts)**q, 1.0e-14_wp, 'd = alpha m/t* (u t*)^-q' // trim(lab))
                ! bound: a stiffness below k
                call hertzdamp_invert(e, tc, m, u, iend_, kb, db, st, bound_active=bound, k_phys=0.5_wp * k, law=i - 1)
                call s%check(st == HD_OK .and. bound .and. .not. (kb /= 0.5_wp * k), 'bound active: k = k_phys' // trim(lab))
                call s%check_close(db, alpha * m**((3.0_wp - 2.0_wp * q) / 5.0_wp) * kb**((2.0_wp + 2.0_wp * q) / 5.0_wp) &
                                   * u**((1.0_wp - 4.0_wp * q) / 5.0_wp), 1.0e-13_wp, 'bound: d formula' // trim(lab))
                call hertzdamp_reduce(kb, db, m, u, a2, ts2, st, i - 1)
                call s%check_close(a2, alpha, 1.0e-14_wp, 'bound: alpha kept' // trim(lab))
                call s%check(ts2 * tau > tc, 'bound: the softer k_phys gives a longer contact' // trim(lab))
                ! iterative (rk45) method agrees with the fit
                call hertzdamp_invert_alpha(e, iend_, a2, ts2, st, method=HD_METHOD_ITERATIVE, tol=1.0e-12_wp, law=i - 1)
                call s%check(st == HD_OK, 'iterative status' // trim(lab))
                call s%check_close(a2, alpha, 1.0e-11_wp, 'iterative alpha = fit alpha' // trim(lab))
                call s%check_close(ts2, tau, 1.0e-11_wp, 'iterative tau_c = fit tau_c' // trim(lab))
                ! log path (extreme decades) agrees with the direct path scaled
                call hertzdamp_invert(e, tc * 1.0e-40_wp, m * 1.0e-40_wp, u, iend_, kb, db, st, law=i - 1)
                call s%check(st == HD_OK, 'log path status' // trim(lab))
                call s%check_close(db, d * 10.0_wp**(40.0_wp * q), 1.0e-12_wp, 'log path: d scales as m^1 tc^-(1+q)... ' // &
                                   trim(lab))
            end do
        end do
        call hertzdamp_invert(0.5_wp, tc, m, u, HD_END_OVERLAP, k, d, st, law=4)
        call s%check(st == HD_BAD_LAW .and. .not. (k /= 0.0_wp), 'invert: bad law')
        call hertzdamp_invert_alpha(0.5_wp, HD_END_OVERLAP, a2, ts2, st, method=HD_METHOD_COMPACT, law=HD_DAMPING_TSUJI)
        call s%check(st == HD_NOT_SUPPORTED, 'compact: linear law only')
        call hertzdamp_invert_alpha(0.5_wp, HD_END_OVERLAP, a2, ts2, st, method=HD_METHOD_FIRST_ORDER, &
                                    law=HD_DAMPING_KUWABARA_KONO)
        call s%check_close(a2, 0.5_wp / hertzdamp_e1(HD_DAMPING_KUWABARA_KONO), 1.0e-15_wp, 'first order with e1(law)')
    end subroutine inverse_rule

end program test_fit_laws
