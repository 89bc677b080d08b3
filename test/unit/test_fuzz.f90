!> Library fuzzer: more than 10^6 random inputs, many adversarial (subnormal, huge,
!> NaN, +-Inf, zero, negative), fed to the public procedures.  Asserts: no NaN or Inf
!> in any output whose status is success, every non-success status has a message,
!> and the run finishes (no crash, no hang: every rk45 call stays under its step
!> guard).  Fixed seed: a failure reproduces.
program test_fuzz
    use hertzdamp
    use hertzdamp_testing, only: test_suite, new_suite
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_negative_inf, ieee_is_finite
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    type(test_suite) :: s
    integer :: n_calls, n_bad_finite, n_no_message, max_rhs
    integer, allocatable :: seed(:)
    integer :: i, ns

    s = new_suite('test_fuzz')
    call random_seed(size=ns)
    allocate (seed(ns))
    seed = 20261122
    call random_seed(put=seed)
    n_calls = 0
    n_bad_finite = 0
    n_no_message = 0
    max_rhs = 0

    do i = 1, 200000
        call fuzz_scaling()
    end do
    do i = 1, 200000
        call fuzz_series()
    end do
    do i = 1, 200000
        call fuzz_dispatch_cheap()
    end do
    do i = 1, 300000
        call fuzz_fit_compact()
    end do
    do i = 1, 200000
        call fuzz_invert()
    end do
    do i = 1, 1000
        call fuzz_rk45()
    end do
    do i = 1, 200
        call fuzz_iterative()
    end do
    call fuzz_messages()

    print '(a,i0,a,i0)', '  calls: ', n_calls, '  largest rk45 rhs_evals: ', max_rhs
    call s%check(n_calls >= 1000000, 'at least 10^6 inputs')
    call s%check(n_bad_finite == 0, 'no NaN/Inf output with a success status')
    call s%check(n_no_message == 0, 'every non-success status has a message')
    call s%check(max_rhs <= 1000000, 'no rk45 call beyond 10^6 rhs evaluations')
    call s%finish()

contains

    !> A random double: ordinary values over many decades, and adversarial ones.
    real(wp) function adversarial() result(x)
        real(wp) :: r, u
        call random_number(r)
        call random_number(u)
        select case (int(r * 12))
        case (0); x = ieee_value(1.0_wp, ieee_quiet_nan)
        case (1); x = ieee_value(1.0_wp, ieee_positive_inf)
        case (2); x = ieee_value(1.0_wp, ieee_negative_inf)
        case (3); x = 0.0_wp
        case (4); x = tiny(1.0_wp) * u                          ! subnormal
        case (5); x = huge(1.0_wp) * u
        case (6); x = -10.0_wp**(60 * u - 30)
        case default; x = 10.0_wp**(60 * u - 30)                 ! 1e-30 .. 1e30
        end select
    end function adversarial

    !> A random alpha: mostly in the physical range, sometimes adversarial.
    real(wp) function random_alpha() result(a)
        real(wp) :: r
        call random_number(r)
        if (r < 0.6_wp) then
            call random_number(a)
            a = 2.4_wp * a - 0.2_wp
        else
            a = adversarial()
        end if
    end function random_alpha

    subroutine account(status, values)
        integer, intent(in) :: status
        real(wp), intent(in) :: values(:)
        n_calls = n_calls + 1
        if (status == HD_OK) then
            if (.not. all(ieee_is_finite(values))) then
                n_bad_finite = n_bad_finite + 1
                if (n_bad_finite <= 5) print '(a,*(es12.4))', '     non-finite output with success: ', values
            end if
        else
            if (len_trim(hertzdamp_message(status)) == 0 .or. hertzdamp_message(status) == 'unknown status code') then
              n_no_message = n_no_message + 1
            end if
            if (any(values /= values)) n_bad_finite = n_bad_finite + 1   ! never NaN, whatever the status
        end if
    end subroutine account

    subroutine fuzz_scaling()
        real(wp) :: alpha, tstar, k, d
        integer :: st
        call hertzdamp_reduce(adversarial(), adversarial(), adversarial(), adversarial(), alpha, tstar, st)
        call account(st, [alpha, tstar])
        call hertzdamp_expand(adversarial(), adversarial(), adversarial(), adversarial(), k, d, st)
        call account(st, [k, d])
    end subroutine fuzz_scaling

    subroutine fuzz_series()
        real(wp) :: e, tc, zm, tm, ee, et, r
        integer :: st, order
        call random_number(r)
        order = int(r * 30) - 2
        call hertzdamp_series_eval(random_alpha(), e, tc, zm, tm, order=order, err_e=ee, err_tau=et, status=st)
        n_calls = n_calls + 1
        if (st == HD_OK .and. .not. all(ieee_is_finite([e, tc, zm, tm, ee, et]))) then
          n_bad_finite = n_bad_finite + 1
        end if
        if (st /= HD_OK .and. len_trim(hertzdamp_message(st)) == 0) n_no_message = n_no_message + 1
        call hertzdamp_pade_eval(random_alpha(), e, tc, zm, tm, status=st)
        n_calls = n_calls + 1
        if (st == HD_OK .and. .not. all(ieee_is_finite([e, tc, zm, tm]))) n_bad_finite = n_bad_finite + 1
    end subroutine fuzz_series

    !> The method dispatch and the dimensional forward problem with the cheap methods.
    subroutine fuzz_dispatch_cheap()
        type(hertzdamp_collision) :: r
        real(wp) :: a, ts, e, tc, zm, u
        integer :: st, method, iend
        call random_number(u)
        method = merge(HD_METHOD_SERIES, HD_METHOD_PADE, u < 0.5_wp)
        call random_number(u)
        iend = int(3 * u) - 0    ! 0, 1 and the invalid 2
        r = hertzdamp_forward_alpha(random_alpha(), iend, method)
        call account(r%status, [r%e, r%tau_c, r%z_max, r%tau_max])
        call hertzdamp_forward_dim(adversarial(), adversarial(), adversarial(), adversarial(), iend, method, &
                                   a, ts, e, tc, zm, st)
        call account(st, [a, ts, e, tc, zm])
    end subroutine fuzz_dispatch_cheap

    !> The fitted and compact approximants, forward and inverse, both definitions.
    subroutine fuzz_fit_compact()
        real(wp) :: a, tc, zm, tm, u
        integer :: st, iend
        call random_number(u)
        iend = int(3 * u)
        call hertzdamp_fit_forward(random_alpha(), iend, a, tc, st, zm, tm)
        call account(st, [a, tc, zm, tm])
        call hertzdamp_fit_inverse(random_e(), iend, a, tc, st)
        call account(st, [a, tc])
        call hertzdamp_compact_forward(random_alpha(), iend, a, tc, st)
        call account(st, [a, tc])
        call hertzdamp_compact_inverse(random_e(), iend, a, tc, st)
        call account(st, [a, tc])
    end subroutine fuzz_fit_compact

    !> A random restitution target: mostly in (0, 1], sometimes adversarial.
    real(wp) function random_e() result(e)
        real(wp) :: r
        call random_number(r)
        if (r < 0.6_wp) then
            call random_number(e)
            e = 10.0_wp**(-5 * e)
        else if (r < 0.7_wp) then
            e = 1.0_wp - epsilon(1.0_wp) * r
        else
            e = adversarial()
        end if
    end function random_e

    !> The inverse rule with dimensional inputs over many decades and adversarial values.
    subroutine fuzz_invert()
        real(wp) :: k, d, a, ts, tau, u, kp
        integer :: st, iend, meth
        logical :: bound
        call random_number(u)
        iend = int(2.2_wp * u)
        call random_number(u)
        meth = merge(HD_METHOD_FIT, HD_METHOD_COMPACT, u < 0.8_wp)
        call random_number(u)
        if (u < 0.5_wp) then
            call hertzdamp_invert(random_e(), adversarial(), adversarial(), adversarial(), iend, k, d, st, &
                                  alpha=a, tstar=ts, tau_c=tau, bound_active=bound, &
                                  options=hertzdamp_invert_options(method=meth))
        else
            kp = adversarial()
            call hertzdamp_invert(random_e(), adversarial(), adversarial(), adversarial(), iend, k, d, st, &
                                  alpha=a, tstar=ts, tau_c=tau, bound_active=bound, k_phys=kp, &
                                  options=hertzdamp_invert_options(method=meth))
        end if
        call account(st, [k, d, a, ts, tau])
        if (st == HD_OK) then
            if (.not. (k > 0.0_wp .and. d >= 0.0_wp)) n_bad_finite = n_bad_finite + 1
        end if
    end subroutine fuzz_invert

    !> The iterative baseline (rk45 inside a secant iteration) on random targets.
    subroutine fuzz_iterative()
        real(wp) :: k, d, u
        integer :: st, iend
        call random_number(u)
        iend = int(2 * u)
        call hertzdamp_invert(random_e(), 10.0_wp**(-9 * u), 10.0_wp**(12 * u - 9), 10.0_wp**(4 * u - 3), iend, &
                              k, d, st, options=hertzdamp_invert_options(method=HD_METHOD_ITERATIVE, tol=1.0e-8_wp))
        call account(st, [k, d])
    end subroutine fuzz_iterative

    subroutine fuzz_rk45()
        type(hertzdamp_collision) :: r
        real(wp) :: u, tol
        integer :: iend
        call random_number(u)
        iend = merge(HD_END_OVERLAP, HD_END_FORCE, u < 0.5_wp)
        call random_number(u)
        tol = 10.0_wp**(-2 - 13 * u)
        r = hertzdamp_rk45_collide(random_alpha(), iend, tol)
        max_rhs = max(max_rhs, r%stats%rhs_evals)
        if (r%status == HD_NO_REBOUND) then
            n_calls = n_calls + 1      ! tau_c = +inf is the documented answer
            if (.not. (r%e == 0.0_wp .and. ieee_is_finite(r%z_max))) n_bad_finite = n_bad_finite + 1
        else
            call account(r%status, [r%e, r%tau_c, r%z_max, r%tau_max])
        end if
    end subroutine fuzz_rk45

    subroutine fuzz_messages()
        integer :: st
        do st = -5, 40
            n_calls = n_calls + 1
            if (len_trim(hertzdamp_message(st)) == 0) n_no_message = n_no_message + 1
        end do
    end subroutine fuzz_messages

end program test_fuzz
