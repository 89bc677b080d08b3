!> Thread safety: the library holds no mutable state, so an OpenMP-parallel loop
!> gives bit-identical results to the serial loop.
program test_threads
    use hertzdamp
    use hertzdamp_testing, only: test_suite, new_suite
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: n_rk45 = 1000
    type(test_suite) :: s
    real(wp), allocatable :: alpha(:)
    type(hertzdamp_collision), allocatable :: serial(:), parallel(:)
    integer :: i

    s = new_suite('test_threads')
    allocate (alpha(n_rk45), serial(n_rk45), parallel(n_rk45))
    do i = 1, n_rk45
        alpha(i) = 1.13_wp * real(i - 1, wp) / real(n_rk45 - 1, wp)
    end do
    do i = 1, n_rk45
        serial(i) = hertzdamp_rk45_collide(alpha(i), tol=1.0e-10_wp)
    end do
    !$omp parallel do schedule(dynamic, 7)
    do i = 1, n_rk45
        parallel(i) = hertzdamp_rk45_collide(alpha(i), tol=1.0e-10_wp)
    end do
    !$omp end parallel do
    call s%check(all(serial%status == parallel%status), 'rk45: same statuses serial and parallel')
    call s%check(all(bits(serial%e) == bits(parallel%e)), 'rk45: bit-identical e')
    call s%check(all(bits(serial%tau_c) == bits(parallel%tau_c)), 'rk45: bit-identical tau_c')
    call s%check(all(serial%stats%rhs_evals == parallel%stats%rhs_evals), 'rk45: same work')
    call s%check(count(serial%status == HD_NO_REBOUND) > 0 .and. count(serial%status == HD_OK) > 900, &
                 'rk45: both outcomes present')
    call s%finish()

contains

    elemental integer(int64) function bits(x)
        real(wp), intent(in) :: x
        bits = transfer(x, 0_int64)
    end function bits

end program test_threads
