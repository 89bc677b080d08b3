!> hertzdamp: the damped Hertzian normal collision, forward and inverse.
!>
!> `use hertzdamp` gives the whole public API: kinds, status codes and messages,
!> the dimensionless reduction, the reference integrator and the named constants.
module hertzdamp
    use hertzdamp_kinds
    use hertzdamp_status
    use hertzdamp_scaling
    use hertzdamp_constants
    use hertzdamp_rk45
    use hertzdamp_methods
    use hertzdamp_fit
    implicit none
    public
end module hertzdamp
