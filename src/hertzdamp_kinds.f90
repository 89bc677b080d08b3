!> Kinds used throughout hertzdamp.
module hertzdamp_kinds
    use, intrinsic :: iso_fortran_env, only: real64
    implicit none
    private

    !> Real kind of every floating-point quantity in the library (IEEE double).
    integer, parameter, public :: hertzdamp_rk = real64
end module hertzdamp_kinds
