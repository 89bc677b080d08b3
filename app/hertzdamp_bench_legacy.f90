!> The legacy externals as a fixed-form DEM calls them, for `hertzdamp bench`: declared
!> by the installed include file include/hertzdamp.fi (explicit interfaces of the
!> external names, REAL(8) and INTEGER(4) by reference: c_double and c_int here), in a
!> module of their own where no library module name hides them.
module hertzdamp_bench_legacy
    use, intrinsic :: iso_c_binding, only: c_double, c_int
    implicit none
    private

    public :: legacy_invert_each, legacy_invert_all, legacy_invert_law_each, legacy_invert_law_all

contains

    !> HERTZDAMP_INVERT once per contact.
    subroutine legacy_invert_each(n, e, tc, m, u, iend, k, d, ierr)
        include 'hertzdamp.fi'
        integer(c_int), intent(in) :: n                   !! number of contacts
        real(c_double), intent(in) :: e(n), tc(n), m(n), u(n) !! inputs of HERTZDAMP_INVERT
        integer(c_int), intent(in) :: iend                !! contact end
        real(c_double), intent(out) :: k(n), d(n)            !! outputs of HERTZDAMP_INVERT
        integer(c_int), intent(out) :: ierr(n)            !! statuses
        integer :: i
        do i = 1, n
            call hertzdamp_invert(e(i), tc(i), m(i), u(i), iend, k(i), d(i), ierr(i))
        end do
    end subroutine legacy_invert_each

    !> HERTZDAMP_INVERT_N over all contacts.
    subroutine legacy_invert_all(n, e, tc, m, u, iend, k, d, ierr)
        include 'hertzdamp.fi'
        integer(c_int), intent(in) :: n                   !! number of contacts
        real(c_double), intent(in) :: e(n), tc(n), m(n), u(n) !! inputs of HERTZDAMP_INVERT_N
        integer(c_int), intent(in) :: iend                !! contact end
        real(c_double), intent(out) :: k(n), d(n)            !! outputs of HERTZDAMP_INVERT_N
        integer(c_int), intent(out) :: ierr(n)            !! statuses
        call hertzdamp_invert_n(n, e, tc, m, u, iend, k, d, ierr)
    end subroutine legacy_invert_all

    !> HERTZDAMP_INVERT_LAW (no bound: KPHYS = 0) once per contact.
    subroutine legacy_invert_law_each(n, e, tc, m, u, ilaw, iend, k, d, ierr)
        include 'hertzdamp.fi'
        integer(c_int), intent(in) :: n                       !! number of contacts
        real(c_double), intent(in) :: e(n), tc(n), m(n), u(n) !! inputs of HERTZDAMP_INVERT_LAW
        integer(c_int), intent(in) :: ilaw, iend              !! damping law, contact end
        real(c_double), intent(out) :: k(n), d(n)             !! outputs of HERTZDAMP_INVERT_LAW
        integer(c_int), intent(out) :: ierr(n)                !! statuses
        integer :: i
        do i = 1, n
            call hertzdamp_invert_law(e(i), tc(i), m(i), u(i), 0.0_c_double, ilaw, iend, k(i), d(i), ierr(i))
        end do
    end subroutine legacy_invert_law_each

    !> HERTZDAMP_INVERT_LAW_N over all contacts.
    subroutine legacy_invert_law_all(n, e, tc, m, u, ilaw, iend, k, d, ierr)
        include 'hertzdamp.fi'
        integer(c_int), intent(in) :: n                       !! number of contacts
        real(c_double), intent(in) :: e(n), tc(n), m(n), u(n) !! inputs of HERTZDAMP_INVERT_LAW_N
        integer(c_int), intent(in) :: ilaw, iend              !! damping law, contact end
        real(c_double), intent(out) :: k(n), d(n)             !! outputs of HERTZDAMP_INVERT_LAW_N
        integer(c_int), intent(out) :: ierr(n)                !! statuses
        call hertzdamp_invert_law_n(n, e, tc, m, u, ilaw, iend, k, d, ierr)
    end subroutine legacy_invert_law_all

end module hertzdamp_bench_legacy
