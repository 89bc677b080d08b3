!> Timing support of `hertzdamp bench`: a wall clock, a median, and the measurement
!> loop for anything that extends `bench_case`.
!>
!> A measurement first calibrates: it runs the case 1, 8, 64, ... times until one batch
!> takes at least `min_time` seconds (this also warms caches and branch predictors),
!> then times `repeats` batches of that size and returns the median time per run.
!> `bench_measure_all` does this for several cases side by side: the rounds take one
!> batch of every case in turn, so that a change of the machine's load (the machines
!> are shared) hits all of them alike and their ratios stay meaningful.
module hertzdamp_bench_timer
    use hertzdamp, only: hertzdamp_rk
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

    !> One case of a list measured side by side (bench_measure_all).
    type, public :: bench_slot
        class(bench_case), allocatable :: c
    end type bench_slot

    public :: wall_seconds, median, bench_measure, bench_measure_all, bench_rounds_all

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
        real(wp) :: t(max(repeats, 1))
        integer :: n, r
        n = calibrate(c, min_time)
        do r = 1, size(t)
            t(r) = time_batch(c, n)
        end do
        t_run = median(t)
        if (present(batch)) batch = n
    end function bench_measure

    !> Median wall time of one `run` of each case [s], measured side by side: every
    !> case's batch size is calibrated first, then `repeats` rounds time one batch of
    !> each case in turn.
    function bench_measure_all(slots, min_time, repeats) result(t_run)
        type(bench_slot), intent(inout) :: slots(:)
        real(wp), intent(in) :: min_time
        integer, intent(in) :: repeats
        real(wp) :: t_run(size(slots))
        real(wp) :: t(max(repeats, 1), size(slots))
        integer :: j
        t = bench_rounds_all(slots, min_time, repeats)
        do j = 1, size(slots)
            t_run(j) = median(t(:, j))
        end do
    end function bench_measure_all

    !> The wall time of one `run` of each case [s] in every round (rounds x cases), as
    !> bench_measure_all takes them: for ratios taken round by round (the cases of one
    !> round run under the same load), whose median is steadier than the ratio of medians.
    function bench_rounds_all(slots, min_time, repeats) result(t)
        type(bench_slot), intent(inout) :: slots(:)
        real(wp), intent(in) :: min_time
        integer, intent(in) :: repeats
        real(wp) :: t(max(repeats, 1), size(slots))
        integer :: n(size(slots)), r, j
        do j = 1, size(slots)
            n(j) = calibrate(slots(j)%c, min_time)
        end do
        do r = 1, size(t, 1)
            do j = 1, size(slots)
                t(r, j) = time_batch(slots(j)%c, n(j))
            end do
        end do
    end function bench_rounds_all

    !> Runs per batch: the first count 1, 8, 64, ... (refined near the end) whose batch
    !> takes at least min_time (capped at 2^28 runs).
    function calibrate(c, min_time) result(n)
        class(bench_case), intent(inout) :: c
        real(wp), intent(in) :: min_time
        integer :: n
        real(wp) :: el
        n = 1
        do
            el = n * time_batch(c, n)
            if (el >= min_time .or. n >= 2**28) exit
            if (el > 0.05_wp * min_time) then
                n = max(n + 1, min(8 * n, ceiling(1.1_wp * n * min_time / el)))
            else
                n = 8 * n
            end if
        end do
    end function calibrate

    !> Wall time per run of a batch of n runs [s].
    function time_batch(c, n) result(t)
        class(bench_case), intent(inout) :: c
        integer, intent(in) :: n
        real(wp) :: t, t0
        integer :: i
        t0 = wall_seconds()
        do i = 1, n
            call c%run()
        end do
        t = (wall_seconds() - t0) / n
    end function time_batch

end module hertzdamp_bench_timer
