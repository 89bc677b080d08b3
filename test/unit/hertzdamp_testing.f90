!> A small test harness: every test program counts its checks with a `test_suite`
!> and ends with `call suite%finish()`, which prints `<name>: P passed, F failed`
!> and exits non-zero when any check failed.  (test-drive cannot be fetched here.)
module hertzdamp_testing
    use hertzdamp, only: hertzdamp_rk
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
    use, intrinsic :: iso_fortran_env, only: output_unit
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Counts passed and failed checks of one test program.
    type, public :: test_suite
        character(len=:), allocatable :: name   !! program name printed in the summary
        integer :: passed = 0                   !! checks that passed
        integer :: failed = 0                   !! checks that failed
    contains
        procedure :: check          !! assert a logical condition
        procedure :: check_close    !! assert |got - want| <= rtol*|want| (+ optional atol)
        procedure :: finish         !! print the summary, exit 1 on failure
    end type test_suite

    public :: new_suite, rel_err

contains

    !> A new, empty suite called `name`.
    function new_suite(name) result(s)
        character(len=*), intent(in) :: name  !! name printed in the summary line
        type(test_suite) :: s
        s%name = name
    end function new_suite

    !> Relative error |got-want|/max(|want|, floor) (floor defaults to tiny).
    pure elemental real(wp) function rel_err(got, want, floor)
        real(wp), intent(in) :: got            !! computed value
        real(wp), intent(in) :: want           !! reference value
        real(wp), intent(in), optional :: floor !! lower bound of the denominator
        real(wp) :: den
        den = abs(want)
        if (present(floor)) den = max(den, floor)
        den = max(den, tiny(1.0_wp))
        rel_err = abs(got - want) / den
        ! NaN anywhere is the largest error there is (max() and maxval() would drop it)
        if (ieee_is_nan(got) .or. ieee_is_nan(want)) rel_err = huge(1.0_wp)
    end function rel_err

    !> Record one check; a failure is printed with its label.
    subroutine check(self, condition, label)
        class(test_suite), intent(inout) :: self
        logical, intent(in) :: condition        !! must be true
        character(len=*), intent(in) :: label   !! what is checked
        if (condition) then
            self%passed = self%passed + 1
        else
            self%failed = self%failed + 1
            write (output_unit, '(a)') 'FAIL ' // self%name // ': ' // label
        end if
    end subroutine check

    !> Check |got - want| <= rtol*|want| + atol; prints both values on failure.
    subroutine check_close(self, got, want, rtol, label, atol)
        class(test_suite), intent(inout) :: self
        real(wp), intent(in) :: got             !! computed value
        real(wp), intent(in) :: want            !! reference value
        real(wp), intent(in) :: rtol            !! relative tolerance
        character(len=*), intent(in) :: label   !! what is checked
        real(wp), intent(in), optional :: atol  !! absolute tolerance (default 0)
        real(wp) :: a
        logical :: ok
        a = 0.0_wp
        if (present(atol)) a = atol
        ok = ieee_is_finite(got) .and. abs(got - want) <= rtol * abs(want) + a
        if (got == want) ok = .true.   ! equal, also both infinite (never true for a NaN)
        if (ieee_is_nan(got) .or. ieee_is_nan(want)) ok = .false.
        call self%check(ok, label)
        if (.not. ok) write (output_unit, '(a,es24.16,a,es24.16,a,es10.2)') &
            '     got ', got, ' want ', want, ' rel ', rel_err(got, want)
    end subroutine check_close

    !> Print `<name>: P passed, F failed`; exit status 1 if any check failed.
    subroutine finish(self)
        class(test_suite), intent(in) :: self
        character(len=32) :: p, f
        write (p, '(i0)') self%passed
        write (f, '(i0)') self%failed
        write (output_unit, '(a)') self%name // ': ' // trim(p) // ' passed, ' // trim(f) // ' failed'
        flush (output_unit)
        if (self%failed > 0 .or. self%passed == 0) error stop 1
    end subroutine finish

end module hertzdamp_testing
