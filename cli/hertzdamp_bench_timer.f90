!> Timing support of `hertzdamp bench`: a wall clock, a median, and the measurement
!> loop for anything that extends `bench_case`.
!>
!> A measurement first calibrates: it runs the case 1, 2, 4, ... times until one batch
!> takes at least `min_time` seconds (this also warms caches and branch predictors),
!> then times `repeats` batches of that size and returns the median time per run.
module hertzdamp_bench_timer
    use hertzdamp_kinds, only: hertzdamp_rk
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Something to time: `run` does the work once and keeps its results in the object
    !> (so that the compiler cannot drop the work).
    type, abstract, public :: bench_case
    contains
        procedure(run_iface), deferred :: run
    end type bench_case

    abstract interface
        subroutine run_iface(self)
            import :: bench_case
            implicit none
            class(bench_case), intent(inout) :: self
        end subroutine run_iface
    end interface

    public :: wall_seconds, median, bench_measure

contains

    !> Wall-clock time in seconds from an arbitrary origin (system_clock, 64-bit).
    function wall_seconds() result(t)
        real(wp) :: t
        integer(int64) :: count, rate
        call system_clock(count, rate)
        t = real(count, wp) / real(max(rate, 1_int64), wp)
    end function wall_seconds

    !> Median of a small array (insertion sort of a copy).
    pure function median(x) result(xm)
        real(wp), intent(in) :: x(:)
        real(wp) :: xm
        real(wp) :: y(size(x)), v
        integer :: i, j, n
        n = size(x)
        xm = 0.0_wp
        if (n == 0) return
        y = x
        do i = 2, n
            v = y(i)
            j = i - 1
            do while (j >= 1)
                if (y(j) <= v) exit
                y(j + 1) = y(j)
                j = j - 1
            end do
            y(j + 1) = v
        end do
        if (mod(n, 2) == 1) then
            xm = y((n + 1) / 2)
        else
            xm = 0.5_wp * (y(n / 2) + y(n / 2 + 1))
        end if
    end function median

    !> Median wall time of one `run` of `c` [s], batches of at least `min_time` seconds,
    !> `repeats` batches.  `batch` returns the number of runs per batch.
    function bench_measure(c, min_time, repeats, batch) result(t_run)
        class(bench_case), intent(inout) :: c
        real(wp), intent(in) :: min_time
        integer, intent(in) :: repeats
        integer, intent(out), optional :: batch
        real(wp) :: t_run
        real(wp) :: t(max(repeats, 1)), t0, el
        integer :: n, i, r
        n = 1
        do
            t0 = wall_seconds()
            do i = 1, n
                call c%run()
            end do
            el = wall_seconds() - t0
            if (el >= min_time .or. n >= 2**28) exit
            if (el > 0.05_wp * min_time) then
                n = max(n + 1, min(8 * n, ceiling(1.1_wp * n * min_time / el)))
            else
                n = 8 * n
            end if
        end do
        do r = 1, size(t)
            t0 = wall_seconds()
            do i = 1, n
                call c%run()
            end do
            t(r) = (wall_seconds() - t0) / n
        end do
        t_run = median(t)
        if (present(batch)) batch = n
    end function bench_measure

end module hertzdamp_bench_timer
