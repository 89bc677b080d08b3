!> Thread safety: the library holds no mutable state, so an OpenMP-parallel loop
!> gives bit-identical results to the serial loop.  The parallel loops ask for
!> n_team threads and the test fails unless more than one thread ran them: built
!> without -fopenmp (the `!$` lines vanish) or limited to one thread, it proves nothing.
program test_threads
    use hertzdamp
    use hertzdamp_testing, only: test_suite, new_suite
    use, intrinsic :: iso_fortran_env, only: int64
    !$ use omp_lib, only: omp_get_thread_num, omp_get_num_threads
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: n_rk45 = 1000
    !> Threads asked of each parallel loop (more than this machine's cores is fine).
    integer, parameter :: n_team = 4
    type(test_suite) :: s
    real(wp), allocatable :: alpha(:)
    type(hertzdamp_collision), allocatable :: serial(:), parallel(:)
    integer :: i, team

    s = new_suite('test_threads')
    allocate (alpha(n_rk45), serial(n_rk45), parallel(n_rk45))
    do i = 1, n_rk45
        alpha(i) = 1.13_wp * real(i - 1, wp) / real(n_rk45 - 1, wp)
    end do
    do i = 1, n_rk45
        serial(i) = hertzdamp_rk45_collide(alpha(i), tol=1.0e-10_wp)
    end do
    team = 1
    !$omp parallel do schedule(dynamic, 7) num_threads(n_team) shared(team)
    do i = 1, n_rk45
        parallel(i) = hertzdamp_rk45_collide(alpha(i), tol=1.0e-10_wp)
        !$ if (i == 1) team = omp_get_num_threads()
    end do
    !$omp end parallel do
    call s%check(team > 1, 'rk45: the parallel loop ran in a team of more than one thread (got ' // &
                 achar(48 + min(team, 9)) // '; built with -fopenmp?)')
    call s%check(all(serial%status == parallel%status), 'rk45: same statuses serial and parallel')
    call s%check(all(bits(serial%e) == bits(parallel%e)), 'rk45: bit-identical e')
    call s%check(all(bits(serial%tau_c) == bits(parallel%tau_c)), 'rk45: bit-identical tau_c')
    call s%check(all(serial%stats%rhs_evals == parallel%stats%rhs_evals), 'rk45: same work')
    call s%check(count(serial%status == HD_NO_REBOUND) > 0 .and. count(serial%status == HD_OK) > 900, &
                 'rk45: both outcomes present')
    call inversions()
    call s%finish()

contains

    !> 10^5 fit inversions over random contacts: parallel equals serial, bit for bit.
    subroutine inversions()
        integer, parameter :: n = 100000
        real(wp), allocatable :: e(:), tc(:), m(:), u(:), k1(:), d1(:), k2(:), d2(:), r(:, :)
        integer, allocatable :: s1(:), s2(:), tid(:)
        integer :: j
        allocate (e(n), tc(n), m(n), u(n), k1(n), d1(n), k2(n), d2(n), s1(n), s2(n), r(n, 4), tid(n))
        call random_number(r)
        e = 10.0_wp**(-3 * r(:, 1))
        tc = 10.0_wp**(-9 + 8 * r(:, 2))
        m = 10.0_wp**(-15 + 18 * r(:, 3))
        u = 10.0_wp**(-4 + 6 * r(:, 4))
        do j = 1, n
            call hertzdamp_invert(e(j), tc(j), m(j), u(j), HD_END_OVERLAP, k1(j), d1(j), s1(j))
        end do
        tid = 0
        !$omp parallel do schedule(static, 97) num_threads(n_team)
        do j = 1, n
            call hertzdamp_invert(e(j), tc(j), m(j), u(j), HD_END_OVERLAP, k2(j), d2(j), s2(j))
            !$ tid(j) = omp_get_thread_num()
        end do
        !$omp end parallel do
        ! static chunks of 97 over 10^5 contacts: every thread of the team computes some
        call s%check(minval(tid) == 0 .and. maxval(tid) > 0, 'inverse: contacts computed by more than one thread')
        call s%check(all(s1 == HD_OK) .and. all(s1 == s2), 'inverse: statuses ok and equal')
        call s%check(all(bits(k1) == bits(k2)) .and. all(bits(d1) == bits(d2)), 'inverse: bit-identical k and d')
        ! and the elemental array call agrees too
        call hertzdamp_invert(e, tc, m, u, HD_END_OVERLAP, k2, d2, s2)
        call s%check(all(bits(k1) == bits(k2)) .and. all(bits(d1) == bits(d2)), 'inverse: elemental array call identical')
    end subroutine inversions

    elemental integer(int64) function bits(x)
        real(wp), intent(in) :: x
        bits = transfer(x, 0_int64)
    end function bits

end program test_threads
