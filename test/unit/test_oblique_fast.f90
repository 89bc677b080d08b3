!> The fast oblique normal correction (hertzdamp_oblique_correct without tol: fast solves,
!> a map-shaped secant start) against the full solve written here: a regula falsi
!> (Illinois) on the rule's target e' with every oblique contact solved by the reference
!> integrator at tol 1e-12, to |e_n - e| <= 1e-11.  Glass spheres (R = 1 mm, and an
!> unequal pair) and a glass wall; e 0.1-0.99, angles 0-85 deg, T_c of N = 20 at dt = 1 us
!> (5 and 1 m/s), 100 us (5 m/s), 10x and 100x the physical 7.8 us (1 m/s), and the
!> physical contact (bound k_phys active); frictionless and mu = 0.3
!> (x_gammat 0 and 0.5), mindlin and linear_history.  Asserted: the same status, e_n of
!> the fast constants (solved by the reference) within 2e-5 of e (the fast correction's
!> stated accuracy) and e' within 1e-4 of the full solve's; the maxima are printed
!> (doc/oblique.md section 4).
program test_oblique_fast
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_STEP_UNDERFLOW, HD_BAD_RESTITUTION, HD_END_OVERLAP, &
                         HD_DAMPING_LINEAR, HD_TANGENTIAL_LINEAR_HISTORY, HD_TANGENTIAL_MINDLIN, HD_LEVER_RADIUS, &
                         HD_LEVER_CONTACT, hertzdamp_pi, &
                         hertzdamp_oblique_t, hertzdamp_oblique_result, hertzdamp_oblique_impact, &
                         hertzdamp_tangential_kt, hertzdamp_oblique_correct, hertzdamp_invert
    use hertzdamp_testing, only: test_suite, new_suite
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    type(test_suite) :: s
    real(wp), parameter :: rad = 1.0e-3_wp, rho = 2500.0_wp, young = 63.0e9_wp, nu = 0.24_wp
    real(wp), parameter :: es(7) = [0.1_wp, 0.2_wp, 0.3_wp, 0.5_wp, 0.7_wp, 0.9_wp, 0.99_wp]
    real(wp), parameter :: angles(8) = [0.0_wp, 5.0_wp, 15.0_wp, 30.0_wp, 45.0_wp, 60.0_wp, 75.0_wp, 85.0_wp]
    real(wp), parameter :: speeds(6) = [5.0_wp, 1.0_wp, 5.0_wp, 5.0_wp, 1.0_wp, 1.0_wp], &
                           tcs(6) = [2.0e-5_wp, 2.0e-5_wp, 1.0e-4_wp, 1.0e-9_wp, 7.8e-5_wp, 7.8e-4_wp]
    real(wp) :: worst_x(3), worst_en(3), kt, k, d, et, xr, en
    type(hertzdamp_oblique_t) :: c, cc
    type(hertzdamp_oblique_result) :: r
    integer :: ig, im, ifr, iv, ie, ia, st, stref, ncase(3), nfail, nref
    character(len=*), parameter :: gname(3) = ['equal spheres  ', 'unequal spheres', 'wall           ']

    s = new_suite('test_oblique_fast')
    worst_x = 0.0_wp
    worst_en = 0.0_wp
    ncase = 0
    nfail = 0
    nref = 0
    do ig = 1, 3
        do im = HD_TANGENTIAL_LINEAR_HISTORY, HD_TANGENTIAL_MINDLIN
            do ifr = 1, 3
                c = contact(ig, im, ifr)
                do iv = 1, size(tcs)
                    do ie = 1, size(es)
                        do ia = 1, size(angles)
                            call hertzdamp_oblique_correct(c, es(ie), tcs(iv), speeds(iv), angles(ia), k, d, kt, et, st)
                            call full_solve(c, es(ie), tcs(iv), speeds(iv), angles(ia), 1.0e-12_wp, xr, stref)
                            ! (HD_STEP_UNDERFLOW in the reference before start_mode's forward
                            ! slip: mindlin, x_gammat 0.5, mu 0.3, from 35 deg; counted, asserted 0)
                            if (stref == HD_STEP_UNDERFLOW) nref = nref + 1
                            call s%check(st == stref, 'fast and full solve: the same status')
                            if (st /= stref) print '(2x,a,3i3,2es10.2,f6.2,f5.0,2i4)', 'status differs:', ig, im, ifr, &
                                speeds(iv), tcs(iv), es(ie), angles(ia), st, stref
                            if (st /= HD_OK .or. stref /= HD_OK) then
                                nfail = nfail + 1
                                cycle
                            end if
                            ncase(ig) = ncase(ig) + 1
                            cc = c
                            cc%k = k
                            cc%d = d
                            cc%kt = kt
                            call hertzdamp_oblique_impact(cc, speeds(iv), angles(ia), r, st)
                            en = r%e_n
                            worst_x(ig) = max(worst_x(ig), abs(et - xr))
                            worst_en(ig) = max(worst_en(ig), abs(en - es(ie)))
                        end do
                    end do
                end do
            end do
        end do
        print '(2x,a,a,i5,a,es9.2,a,es9.2)', gname(ig), ': cases', ncase(ig), ', max |e'' - full| ', worst_x(ig), &
            ', max |e_n - e| ', worst_en(ig)
        ! e' is less determined than e_n where e_n depends weakly on e' (100x stretches: up
        ! to 3.7e-5 measured); the stated accuracy is e_n's
        call s%check(worst_x(ig) <= 1.0e-4_wp, 'fast correction: e'' within 1e-4 of the full solve (' // &
                     trim(gname(ig)) // ')')
        call s%check(worst_en(ig) <= 2.0e-5_wp, 'fast correction: e_n within 2e-5 of e (' // trim(gname(ig)) // ')')
    end do
    print '(2x,a,i4)', 'cases without a correction (both solves fail alike): ', nfail
    print '(2x,a,i4)', 'cases the reference integrator cannot solve (HD_STEP_UNDERFLOW at tol 1e-12): ', nref
    call s%check(nref == 0, 'the reference integrator solves every case (no HD_STEP_UNDERFLOW)')
    call s%check(minval(ncase) > 0, 'the matrix has solved cases')
    call wall_exact()
    call s%finish()

contains

    !> Glass: two equal spheres, a sphere of 1.5 R (same density), or a wall; tangential
    !> model im; ifr = 1 frictionless, 2 mu 0.3, 3 mu 0.3 with x_gammat 0.5.  The physical
    !> k (the bound) and k_t (mindlin 8 G*, linear_history 8 G* sqrt(R* 1 um)).
    function contact(ig, im, ifr) result(c)
        integer, intent(in) :: ig, im, ifr
        type(hertzdamp_oblique_t) :: c
        real(wp) :: m, r2, rstar, gstar
        m = rho * 4.0_wp / 3.0_wp * hertzdamp_pi * rad**3
        gstar = young / (2.0_wp * 2.0_wp * (2.0_wp - nu) * (1.0_wp + nu))
        c = hertzdamp_oblique_t(m1=m, r1=rad, law=HD_DAMPING_LINEAR, iend=HD_END_OVERLAP, tangential=im, &
                                lever=HD_LEVER_CONTACT)
        r2 = 0.0_wp
        if (ig == 1) r2 = rad
        if (ig == 2) r2 = 1.5_wp * rad
        if (ig == 3) then
            rstar = rad
            c%lever = HD_LEVER_RADIUS
        else
            c%r2 = r2
            c%m2 = m * (r2 / rad)**3
            rstar = rad * r2 / (rad + r2)
        end if
        ! E* of two equal materials: E / (2 (1 - nu^2))
        c%k = 4.0_wp / 3.0_wp * young / (2.0_wp * (1.0_wp - nu**2)) * sqrt(rstar)
        c%kt = 8.0_wp * gstar
        if (im == HD_TANGENTIAL_LINEAR_HISTORY) c%kt = c%kt * sqrt(rstar * 1.0e-6_wp)
        if (ifr >= 2) c%mu = 0.3_wp
        if (ifr == 3) c%xgammat = 0.5_wp
    end function contact

    !> e_n - e of the rule's constants of target x (the reference integrator at 1e-12).
    subroutine residual(c, e, tc, u, th, tl, x, f, st)
        type(hertzdamp_oblique_t), intent(in) :: c
        real(wp), intent(in) :: e, tc, u, th, tl, x
        real(wp), intent(out) :: f
        integer, intent(out) :: st
        type(hertzdamp_oblique_t) :: cc
        type(hertzdamp_oblique_result) :: r
        real(wp) :: meff, k, d, kt
        f = 0.0_wp
        meff = c%m1
        if (c%m2 > 0.0_wp) meff = c%m1 * c%m2 / (c%m1 + c%m2)
        call hertzdamp_invert(x, tc, meff, u * cos(th * hertzdamp_pi / 180.0_wp), c%iend, k, d, st, k_phys=c%k, &
                              law=c%law)
        if (st /= HD_OK) return
        call hertzdamp_tangential_kt(c%tangential, c%kt, k, c%k, kt, st)
        if (st /= HD_OK) return
        cc = c
        cc%k = k
        cc%d = d
        cc%kt = kt
        call hertzdamp_oblique_impact(cc, u, th, r, st, tol=tl)
        f = r%e_n - e
    end subroutine residual

    !> The full solve: the target x with e_n(x) = e, by the Illinois method on a bracket
    !> grown from x = e inside (0, 1] (the shift is positive frictionless, either sign with friction).
    subroutine full_solve(c, e, tc, u, th, tl, x, st)
        type(hertzdamp_oblique_t), intent(in) :: c
        real(wp), intent(in) :: e, tc, u, th, tl
        real(wp), intent(out) :: x
        integer, intent(out) :: st
        real(wp) :: a, b, fa, fb, fx, step
        integer :: it, side, ih
        x = e
        call residual(c, e, tc, u, th, tl, e, fa, st)
        if (st /= HD_OK .or. abs(fa) <= 1.0e-11_wp) return
        a = e
        step = -2.0_wp * fa
        do it = 1, 40
            ! grow the bracket inside the rule's range (0, 1]
            b = a + step
            if (b <= 0.0_wp) b = 0.5_wp * a
            if (b > 1.0_wp) b = 0.5_wp * (a + 1.0_wp)
            call residual(c, e, tc, u, th, tl, b, fb, st)
            ! below the rule's range (e_min 0.05): halfway back, a few times
            do ih = 1, 6
                if (st /= HD_BAD_RESTITUTION .or. b >= a) exit
                b = 0.5_wp * (a + b)
                call residual(c, e, tc, u, th, tl, b, fb, st)
            end do
            if (st /= HD_OK) return
            if ((fb > 0.0_wp) .neqv. (fa > 0.0_wp)) exit
            a = b
            fa = fb
        end do
        side = 0
        do it = 1, 200
            x = (a * fb - b * fa) / (fb - fa)
            call residual(c, e, tc, u, th, tl, x, fx, st)
            if (st /= HD_OK) return
            if (abs(fx) <= 1.0e-11_wp .or. abs(b - a) <= 1.0e-13_wp) return
            if ((fx > 0.0_wp) .eqv. (fb > 0.0_wp)) then
                b = x
                fb = fx
                if (side == -1) fa = 0.5_wp * fa
                side = -1
            else
                a = x
                fa = fx
                if (side == 1) fb = 0.5_wp * fb
                side = 1
            end if
        end do
        st = -1
    end subroutine full_solve

    !> On a wall the correction is the normal rule itself: e' = e, and the constants are
    !> hertzdamp_invert's bits at e (with friction too).  The former correction (commit
    !> 39d5a6b) fails this from 35 deg (mindlin, mu 0.3, x_gammat 0.5): it solved the
    !> oblique contact, and the reference integrator returns HD_STEP_UNDERFLOW there.
    subroutine wall_exact()
        type(hertzdamp_oblique_t) :: c
        real(wp) :: k, d, kt, et, k0, d0, kt0, un
        integer :: st, st0, i
        c = contact(3, HD_TANGENTIAL_MINDLIN, 3)
        do i = 0, 17
            call hertzdamp_oblique_correct(c, 0.4_wp, 2.0e-5_wp, 3.0_wp, 5.0_wp * i, k, d, kt, et, st)
            un = 3.0_wp * cos(5.0_wp * i * hertzdamp_pi / 180.0_wp)
            call hertzdamp_invert(0.4_wp, 2.0e-5_wp, c%m1, un, c%iend, k0, d0, st0, k_phys=c%k, law=c%law)
            call hertzdamp_tangential_kt(c%tangential, c%kt, k0, c%k, kt0, st0)
            call s%check(st == HD_OK .and. st0 == HD_OK .and. et == 0.4_wp .and. k == k0 .and. d == d0 .and. &
                         kt == kt0, 'wall: e'' = e and the normal rule''s constants')
        end do
    end subroutine wall_exact

end program test_oblique_fast
