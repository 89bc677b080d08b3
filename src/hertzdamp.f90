!> The umbrella module of hertzdamp, the damped Hertzian normal collision, forward and inverse.
!>
!> `use hertzdamp` gives the whole public API: kinds, status codes and messages,
!> the dimensionless reduction, the damping laws, the reference integrator, the named constants, the
!> fitted and compact approximants and the inverse rule `hertzdamp_invert`.
module hertzdamp
    use hertzdamp_kinds
    use hertzdamp_status
    use hertzdamp_scaling
    use hertzdamp_constants
    use hertzdamp_laws
    use hertzdamp_rk45
    use hertzdamp_series
    use hertzdamp_methods
    use hertzdamp_fit
    use hertzdamp_fit_laws
    use hertzdamp_compact
    use hertzdamp_inverse
    use hertzdamp_host
    use hertzdamp_pair
    use hertzdamp_materials
    implicit none
    public
end module hertzdamp
