!> The rows of `hertzdamp bench` and what every table builder shares: one result row
!> (problem, law, method, setting, errors, time, work), the plot families the rows
!> belong to, and the number formats of the figures.  A builder (one module per table:
!> hertzdamp_bench_table_forward, _inverse, _entry, _closed_form) appends its rows to
!> the run's rows and adds its header lines and figures; hertzdamp_cmd_bench calls the
!> builders in order and renders the rows (hertzdamp_bench_output).
module hertzdamp_bench_rows
    use hertzdamp, only: hertzdamp_rk, HD_DAMPING_LINEAR
    use hertzdamp_cli_text, only: itoa
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private
    public :: bench_row, rel, row_name, find_row, met, fratio, short, ftoa

    integer, parameter :: wp = hertzdamp_rk

    !> Plot families (marker styles), in legend order.
    integer, parameter, public :: n_families = 9
    character(len=*), parameter, public :: fam(n_families) = [character(len=10) :: 'rk45', 'gsl-rkf45', &
        'gsl-rk8pd', 'series', 'pade', 'compact', 'fit', 'iterative', 'gsl-secant']
    !> The family codes of the rows (index into fam).
    integer, parameter, public :: FAMILY_RK45 = 1, FAMILY_GSL_RKF45 = 2, FAMILY_GSL_RK8PD = 3, FAMILY_SERIES = 4, &
                                  FAMILY_PADE = 5, FAMILY_COMPACT = 6, FAMILY_FIT = 7, FAMILY_ITERATIVE = 8, &
                                  FAMILY_GSL_SECANT = 9

    !> The damping laws, in the order of the rows (codes HD_DAMPING_* = 0, 1, 2).
    integer, parameter, public :: n_laws = 3

    !> Floor of the e error denominator: errors of e are relative to max(e, e_floor).
    real(wp), parameter, public :: e_floor = 1.0e-3_wp
    !> Errors below this are drawn at this value (log axis).
    real(wp), parameter, public :: plot_floor = 1.0e-17_wp

    !> One result row.
    type :: bench_row
        character(len=:), allocatable :: problem, method, setting
        integer :: law = HD_DAMPING_LINEAR
        integer :: family = 0
        integer :: npts = 0, ntot = 0
        real(wp) :: err(5) = -1.0_wp   !! e, tau, alpha, k, d; < 0: not applicable
        real(wp) :: ns = -1.0_wp
        real(wp) :: steps = -1.0_wp, rejected = -1.0_wp, rhs = -1.0_wp  !! means per collision; < 0: n/a
    end type bench_row

contains

    !> |got - want| relative to |want| (to the smallest normal number when want = 0).
    pure elemental real(wp) function rel(got, want)
        real(wp), intent(in) :: got, want
        rel = abs(got - want) / max(abs(want), tiny(1.0_wp))
    end function rel

    !> 'method setting' of a row.
    function row_name(r) result(s)
        type(bench_row), intent(in) :: r
        character(len=:), allocatable :: s
        s = r%method // ' ' // r%setting
    end function row_name

    !> The index of the last row of problem, law, method and setting (0 if none).
    integer function find_row(rows, problem, law, method, setting) result(k)
        type(bench_row), intent(in) :: rows(:)
        character(len=*), intent(in) :: problem, method, setting
        integer, intent(in) :: law
        integer :: i
        k = 0
        do i = 1, size(rows)
            if (rows(i)%problem == problem .and. rows(i)%law == law .and. rows(i)%method == method .and. &
                rows(i)%setting == setting) k = i
        end do
    end function find_row

    !> 'met' or the shortfall.
    function met(ok, shortfall) result(r)
        logical, intent(in) :: ok
        character(len=*), intent(in) :: shortfall
        character(len=:), allocatable :: r
        if (ok) then
            r = 'met'
        else
            r = shortfall
        end if
    end function met

    !> A ratio with 3 significant digits.
    function fratio(x) result(s)
        real(wp), intent(in) :: x
        character(len=:), allocatable :: s
        if (x >= 100.0_wp .or. x < 0.01_wp) then
            s = ftoa(x, '(es9.2)')
        else if (x >= 10.0_wp) then
            s = ftoa(x, '(f6.1)')
        else
            s = ftoa(x, '(f6.2)')
        end if
    end function fratio

    !> x as an integer when it is one, else with one decimal.
    function short(x) result(s)
        real(wp), intent(in) :: x
        character(len=:), allocatable :: s
        if (abs(x) < 1.0e9_wp .and. x == aint(x)) then
            s = itoa(int(x))
        else
            s = ftoa(x, '(f0.1)')
        end if
    end function short

    !> x written with format f, without blanks; 'n/a' when not finite.
    function ftoa(x, f) result(s)
        real(wp), intent(in) :: x
        character(len=*), intent(in) :: f
        character(len=:), allocatable :: s
        character(len=40) :: b
        if (.not. ieee_is_finite(x)) then
            s = 'n/a'
            return
        end if
        write (b, f) x
        s = trim(adjustl(b))
    end function ftoa

end module hertzdamp_bench_rows
