!> The legacy Fortran entry points (src/hertzdamp_capi.f90, and the external HERTZDAMP_MESSAGE of
!> src/hertzdamp_legacy.f90) against the module API.
!>
!> fpm compiles tests with -Werror=implicit-interface (implicit-external = false), so
!> this program declares the external subroutines in an interface block written
!> exactly as a Fortran 77 caller sees them (double precision and default integer
!> by reference, a character argument of any length).  The truly implicit calls from
!> fixed-form code are exercised by example/legacy_dem, built and run by
!> test/integration/install_consumers.sh.
program test_legacy
    use hertzdamp, only: hertzdamp_rk, mod_invert => hertzdamp_invert, hertzdamp_forward_dim, hertzdamp_invert_alpha, &
                         mod_message => hertzdamp_message, HD_OK, HD_NO_REBOUND, HD_BAD_RESTITUTION, &
                         HD_BAD_MASS, HD_BAD_END, HD_BAD_TIME, HD_BAD_VELOCITY, HD_BAD_STIFFNESS, &
                         HD_BAD_DAMPING, HD_BAD_KPHYS, HD_END_OVERLAP, HD_END_FORCE, HD_BAD_LAW, hertzdamp_law_q, &
                         HD_METHOD_FIT
    use hertzdamp_testing, only: test_suite, new_suite
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    implicit none

    interface
        subroutine hertzdamp_invert(e, tc, m, u, iend, k, d, ierr)
            implicit none
            double precision, intent(in) :: e, tc, m, u
            integer, intent(in) :: iend
            double precision, intent(out) :: k, d
            integer, intent(out) :: ierr
        end subroutine hertzdamp_invert
        subroutine hertzdamp_invert_bounded(e, tc, m, u, kphys, iend, k, d, ierr)
            implicit none
            double precision, intent(in) :: e, tc, m, u, kphys
            integer, intent(in) :: iend
            double precision, intent(out) :: k, d
            integer, intent(out) :: ierr
        end subroutine hertzdamp_invert_bounded
        subroutine hertzdamp_pair(e, iend, alpha, tauc, ierr)
            implicit none
            double precision, intent(in) :: e
            integer, intent(in) :: iend
            double precision, intent(out) :: alpha, tauc
            integer, intent(out) :: ierr
        end subroutine hertzdamp_pair
        subroutine hertzdamp_forward(k, d, m, u, iend, e, tc, ierr)
            implicit none
            double precision, intent(in) :: k, d, m, u
            integer, intent(in) :: iend
            double precision, intent(out) :: e, tc
            integer, intent(out) :: ierr
        end subroutine hertzdamp_forward
        subroutine hertzdamp_invert_n(n, e, tc, m, u, iend, k, d, ierr)
            implicit none
            integer, intent(in) :: n
            double precision, intent(in) :: e(n), tc(n), m(n), u(n)
            integer, intent(in) :: iend
            double precision, intent(out) :: k(n), d(n)
            integer, intent(out) :: ierr(n)
        end subroutine hertzdamp_invert_n
        subroutine hertzdamp_invert_law(e, tc, m, u, kphys, ilaw, iend, k, d, ierr)
            implicit none
            double precision, intent(in) :: e, tc, m, u, kphys
            integer, intent(in) :: ilaw, iend
            double precision, intent(out) :: k, d
            integer, intent(out) :: ierr
        end subroutine hertzdamp_invert_law
        subroutine hertzdamp_pair_law(e, ilaw, iend, alpha, tauc, ierr)
            implicit none
            double precision, intent(in) :: e
            integer, intent(in) :: ilaw, iend
            double precision, intent(out) :: alpha, tauc
            integer, intent(out) :: ierr
        end subroutine hertzdamp_pair_law
        subroutine hertzdamp_forward_law(k, d, m, u, ilaw, iend, e, tc, ierr)
            implicit none
            double precision, intent(in) :: k, d, m, u
            integer, intent(in) :: ilaw, iend
            double precision, intent(out) :: e, tc
            integer, intent(out) :: ierr
        end subroutine hertzdamp_forward_law
        subroutine hertzdamp_message(ierr, text)
            implicit none
            integer, intent(in) :: ierr
            character(len=*), intent(out) :: text
        end subroutine hertzdamp_message
    end interface

    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: nc = 5
    type(test_suite) :: suite
    real(wp), parameter :: es(nc) = [1.0_wp, 0.9_wp, 0.5_wp, 0.2_wp, 0.05_wp]
    real(wp), parameter :: tcs(nc) = [1.0e-4_wp, 5.0e-5_wp, 2.0e-3_wp, 1.0e-6_wp, 3.0e-4_wp]
    real(wp), parameter :: ms(nc) = [1.0e-3_wp, 2.0e-2_wp, 5.0_wp, 1.0e-9_wp, 0.3_wp]
    real(wp), parameter :: us(nc) = [1.0_wp, 0.01_wp, 3.0_wp, 20.0_wp, 0.5_wp]
    real(wp) :: k, d, km, dm, e, tc, em, tcm, alpha, tstar, zmax, nan, tauc, am, taum, kb, db, kp
    real(wp) :: kn(nc + 1), dn(nc + 1)
    integer :: ierr, st, i, iend, ierrn(nc + 1)
    character(len=20) :: short, want_short
    character(len=300) :: long
    character(len=2) :: cend

    suite = new_suite('test_legacy')
    nan = ieee_value(1.0_wp, ieee_quiet_nan)

    do iend = HD_END_OVERLAP, HD_END_FORCE
        write (cend, '(i0)') iend
        do i = 1, nc
            call hertzdamp_invert(es(i), tcs(i), ms(i), us(i), iend, k, d, ierr)
            call mod_invert(es(i), tcs(i), ms(i), us(i), iend, km, dm, st)
            call suite%check(ierr == HD_OK .and. st == HD_OK, 'invert status, end ' // cend)
            call suite%check(.not. (abs(k - km) > 0.0_wp .or. abs(d - dm) > 0.0_wp), &
                             'invert k, d bit-identical to the module API, end ' // cend)
            ! round trip through the legacy forward problem
            call hertzdamp_forward(k, d, ms(i), us(i), iend, e, tc, ierr)
            call suite%check(ierr == HD_OK, 'forward status after invert, end ' // cend)
            ! the fit's stated round-trip accuracy (doc/accuracy.md: e 8.8e-13, T_c 1.7e-13 at worst)
            call suite%check_close(e, es(i), 1.0e-12_wp, 'round trip e, end ' // cend)
            call suite%check_close(tc, tcs(i), 1.0e-12_wp, 'round trip tc, end ' // cend)
            call hertzdamp_forward_dim(k, d, ms(i), us(i), iend, HD_METHOD_FIT, alpha, tstar, em, tcm, zmax, st)
            call suite%check(.not. (abs(e - em) > 0.0_wp .or. abs(tc - tcm) > 0.0_wp), &
                             'forward e, tc bit-identical to the module API, end ' // cend)
        end do

        ! the pair constants and the bounded entry point
        do i = 1, nc
            call mod_invert(es(i), tcs(i), ms(i), us(i), iend, km, dm, st)
            call hertzdamp_pair(es(i), iend, alpha, tauc, ierr)
            call hertzdamp_invert_alpha(es(i), iend, am, taum, st)
            call suite%check(ierr == HD_OK .and. .not. (abs(alpha - am) > 0.0_wp .or. abs(tauc - taum) > 0.0_wp), &
                             'pair: alpha, tau_c bit-identical to the module API, end ' // cend)
            ! the two documented per-contact formulas reproduce HERTZDAMP_INVERT
            call suite%check_close(ms(i) * (tauc / tcs(i))**2.5_wp / sqrt(us(i)), km, 1.0e-14_wp, &
                                   'pair: k = m (tau_c/T_c)^(5/2) u^(-1/2), end ' // cend)
            call suite%check_close(alpha * ms(i) * tauc / tcs(i), dm, 1.0e-14_wp, &
                                   'pair: d = alpha m tau_c/T_c, end ' // cend)
            ! bounded: a soft k_phys is kept, with d = alpha m^(3/5) k_phys^(2/5) u^(1/5)
            kp = 0.25_wp * km
            call hertzdamp_invert_bounded(es(i), tcs(i), ms(i), us(i), kp, iend, kb, db, ierr)
            call mod_invert(es(i), tcs(i), ms(i), us(i), iend, k, d, st, k_phys=kp)
            call suite%check(ierr == HD_OK .and. .not. (abs(kb - k) > 0.0_wp .or. abs(db - d) > 0.0_wp), &
                             'bounded: bit-identical to the module API with k_phys, end ' // cend)
            call suite%check(.not. (abs(kb - kp) > 0.0_wp), 'bounded: k = k_phys when k_phys < k, end ' // cend)
            call suite%check_close(db, alpha * ms(i)**0.6_wp * kp**0.4_wp * us(i)**0.2_wp, 1.0e-14_wp, &
                                   'bounded: d = alpha m^(3/5) k_phys^(2/5) u^(1/5), end ' // cend, atol=1.0e-300_wp)
            ! a stiff k_phys is not used: the unbounded k, d bit for bit
            call hertzdamp_invert_bounded(es(i), tcs(i), ms(i), us(i), 4.0_wp * km, iend, kb, db, ierr)
            call suite%check(ierr == HD_OK .and. .not. (abs(kb - km) > 0.0_wp .or. abs(db - dm) > 0.0_wp), &
                             'bounded: stiff k_phys leaves k, d unchanged, end ' // cend)
        end do
        call hertzdamp_invert_bounded(0.5_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, -1.0_wp, iend, kb, db, ierr)
        call suite%check(ierr == HD_BAD_KPHYS .and. .not. (abs(kb) > 0.0_wp .or. abs(db) > 0.0_wp), &
                         'bounded: k_phys < 0 gives HD_BAD_KPHYS, k = d = 0')
        call hertzdamp_pair(1.5_wp, iend, alpha, tauc, ierr)
        call suite%check(ierr == HD_BAD_RESTITUTION .and. .not. (abs(alpha) > 0.0_wp .or. abs(tauc) > 0.0_wp), &
                         'pair: e > 1 gives HD_BAD_RESTITUTION, alpha = tau_c = 0')

        ! the array version, with one bad contact at the end
        call hertzdamp_invert_n(nc + 1, [es, 1.5_wp], [tcs, 1.0e-4_wp], [ms, 1.0_wp], [us, 1.0_wp], &
                                iend, kn, dn, ierrn)
        do i = 1, nc
            call mod_invert(es(i), tcs(i), ms(i), us(i), iend, km, dm, st)
            call suite%check(ierrn(i) == HD_OK .and. .not. (abs(kn(i) - km) > 0.0_wp .or. &
                             abs(dn(i) - dm) > 0.0_wp), 'invert_n element equals the module API, end ' // cend)
        end do
        call suite%check(ierrn(nc + 1) == HD_BAD_RESTITUTION, 'invert_n: bad element flagged')
        call suite%check(.not. (abs(kn(nc + 1)) > 0.0_wp .or. abs(dn(nc + 1)) > 0.0_wp), &
                         'invert_n: bad element gives k = d = 0')
    end do
    ! n = 0 touches nothing
    kn = -1.0_wp
    ierrn = -1
    call hertzdamp_invert_n(0, es, tcs, ms, us, 0, kn, dn, ierrn)
    call suite%check(all(ierrn == -1) .and. all(kn < 0.0_wp), 'invert_n with n = 0 does nothing')

    ! bad input: a status, k = d = 0, and a message
    call expect_invert_error(1.5_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, 0, HD_BAD_RESTITUTION, 'e > 1')
    call expect_invert_error(0.0_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, 0, HD_BAD_RESTITUTION, 'e = 0')
    call expect_invert_error(0.5_wp, nan, 1.0_wp, 1.0_wp, 0, HD_BAD_TIME, 'tc NaN')
    call expect_invert_error(0.5_wp, -1.0e-4_wp, 1.0_wp, 1.0_wp, 0, HD_BAD_TIME, 'tc < 0')
    call expect_invert_error(0.5_wp, 1.0e-4_wp, -1.0_wp, 1.0_wp, 0, HD_BAD_MASS, 'm < 0')
    call expect_invert_error(0.5_wp, 1.0e-4_wp, 1.0_wp, 0.0_wp, 0, HD_BAD_VELOCITY, 'u = 0')
    call expect_invert_error(0.5_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, 3, HD_BAD_END, 'iend = 3')

    ! forward without rebound: alpha = 2 > alpha_c (overlap); the force end rebounds
    call alpha_two(km, dm)
    call hertzdamp_forward(km, dm, 1.0_wp, 1.0_wp, HD_END_OVERLAP, e, tc, ierr)
    call suite%check(ierr == HD_NO_REBOUND, 'no rebound: ierr = 1')
    call suite%check(.not. (abs(e) > 0.0_wp), 'no rebound: e = 0')
    call suite%check(.not. (abs(tc - huge(1.0d0)) > 0.0_wp), 'no rebound: tc = huge(1d0)')
    call hertzdamp_message(ierr, long)
    call suite%check(long == mod_message(HD_NO_REBOUND), 'no rebound: message')
    call hertzdamp_forward(km, dm, 1.0_wp, 1.0_wp, HD_END_FORCE, e, tc, ierr)
    call suite%check(ierr == HD_OK .and. e > 0.0_wp .and. e < 1.0_wp .and. tc > 0.0_wp .and. &
                     tc < huge(1.0_wp), 'force end at alpha = 2 rebounds')

    ! forward errors
    call hertzdamp_forward(0.0_wp, 1.0_wp, 1.0_wp, 1.0_wp, 0, e, tc, ierr)
    call suite%check(ierr == HD_BAD_STIFFNESS .and. .not. (abs(e) > 0.0_wp .or. abs(tc) > 0.0_wp), &
                     'forward: k = 0 gives HD_BAD_STIFFNESS, e = tc = 0')
    call hertzdamp_forward(1.0_wp, -1.0_wp, 1.0_wp, 1.0_wp, 0, e, tc, ierr)
    call suite%check(ierr == HD_BAD_DAMPING, 'forward: d < 0 gives HD_BAD_DAMPING')
    call hertzdamp_forward(1.0_wp, 1.0_wp, 1.0_wp, 1.0_wp, -1, e, tc, ierr)
    call suite%check(ierr == HD_BAD_END, 'forward: iend = -1 gives HD_BAD_END')

    ! messages: truncated into a short variable, blank-padded into a long one
    do i = -1, 20
        call hertzdamp_message(i, short)
        call hertzdamp_message(i, long)
        want_short = mod_message(i)
        call suite%check(short == want_short, 'message truncated')
        call suite%check(long == mod_message(i) .and. len_trim(long) == len(mod_message(i)), &
                         'message padded')
    end do
    call hertzdamp_message(HD_OK, short)
    call suite%check(short == 'success', 'message of 0 is "success"')

    call damping_laws()
    call suite%finish()

contains

    !> HERTZDAMP_INVERT_LAW / _PAIR_LAW / _FORWARD_LAW against the module API with the
    !> law, bit for bit; the per-contact formulas of the pair; the bound of every law.
    subroutine damping_laws()
        integer :: law, j
        real(wp) :: q
        character(len=24) :: lab
        do law = 0, 2
            q = hertzdamp_law_q(law)
            do iend = HD_END_OVERLAP, HD_END_FORCE
                write (lab, '(a,i0,a,i0)') ' law ', law, ' end ', iend
                do j = 2, nc
                    call hertzdamp_invert_law(es(j), tcs(j), ms(j), us(j), 0.0_wp, law, iend, k, d, ierr)
                    call mod_invert(es(j), tcs(j), ms(j), us(j), iend, km, dm, st, law=law)
                    call suite%check(ierr == HD_OK .and. st == HD_OK .and. .not. (k /= km .or. d /= dm), &
                                     'invert_law bit-identical to the module API' // trim(lab))
                    call hertzdamp_forward_law(k, d, ms(j), us(j), law, iend, e, tc, ierr)
                    call suite%check_close(e, es(j), 1.0e-12_wp, 'round trip e' // trim(lab))
                    call suite%check_close(tc, tcs(j), 1.0e-12_wp, 'round trip tc' // trim(lab))
                    call hertzdamp_pair_law(es(j), law, iend, alpha, tauc, ierr)
                    tstar = tcs(j) / tauc
                    call suite%check_close(ms(j) * tstar**(-2.5_wp) / sqrt(us(j)), k, 1.0e-14_wp, &
                                           'pair_law: k formula' // trim(lab))
                    call suite%check_close(alpha * ms(j) / tstar / (us(j) * tstar)**q, d, 1.0e-14_wp, &
                                           'pair_law: d formula' // trim(lab))
                    kp = 0.25_wp * k
                    call hertzdamp_invert_law(es(j), tcs(j), ms(j), us(j), kp, law, iend, kb, db, ierr)
                    call suite%check(ierr == HD_OK .and. .not. (kb /= kp), 'invert_law bound: k = k_phys' // trim(lab))
                    call suite%check_close(db, alpha * ms(j)**((3.0_wp - 2.0_wp * q) / 5.0_wp) * &
                                           kp**((2.0_wp + 2.0_wp * q) / 5.0_wp) * us(j)**((1.0_wp - 4.0_wp * q) / 5.0_wp), &
                                           1.0e-13_wp, 'invert_law bound: d formula' // trim(lab))
                end do
            end do
        end do
        call hertzdamp_invert_law(0.5_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, 0.0_wp, 3, 0, k, d, ierr)
        call suite%check(ierr == HD_BAD_LAW .and. .not. (k /= 0.0_wp .or. d /= 0.0_wp), 'invert_law: bad law')
        call hertzdamp_invert_law(0.5_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, nan, 1, 0, k, d, ierr)
        call suite%check(ierr == HD_BAD_KPHYS, 'invert_law: NaN k_phys')
        call hertzdamp_pair_law(0.5_wp, -1, 0, alpha, tauc, ierr)
        call suite%check(ierr == HD_BAD_LAW, 'pair_law: bad law')
    end subroutine damping_laws

    !> Check that hertzdamp_invert fails with `want`, k = d = 0 and a message.
    subroutine expect_invert_error(e_, tc_, m_, u_, iend_, want, label)
        real(wp), intent(in) :: e_, tc_, m_, u_
        integer, intent(in) :: iend_, want
        character(len=*), intent(in) :: label
        real(wp) :: k_, d_
        integer :: ierr_
        character(len=200) :: text
        call hertzdamp_invert(e_, tc_, m_, u_, iend_, k_, d_, ierr_)
        call suite%check(ierr_ == want, 'bad input (' // label // '): status')
        call suite%check(.not. (abs(k_) > 0.0_wp .or. abs(d_) > 0.0_wp), 'bad input (' // label // '): k = d = 0')
        call hertzdamp_message(ierr_, text)
        call suite%check(text == mod_message(want) .and. text /= mod_message(HD_OK), &
                         'bad input (' // label // '): message')
    end subroutine expect_invert_error

    !> k and d with m = u = 1 and alpha = 2: t* = 1 for k = 1, so d = alpha.
    subroutine alpha_two(k_, d_)
        real(wp), intent(out) :: k_, d_
        k_ = 1.0_wp
        d_ = 2.0_wp
    end subroutine alpha_two

end program test_legacy
