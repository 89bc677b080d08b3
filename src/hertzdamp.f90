!> The umbrella module of hertzdamp, the damped Hertzian normal collision, forward and inverse.
!>
!> `use hertzdamp` gives the public API, an explicit list of 135 names, each defined in the
!> module it belongs to: kinds, status codes and messages, contact ends, damping laws,
!> closed forms, the dimensionless reduction, the reference integrator, series, the
!> forward problem by any method, the fitted and compact maps, the dimensionless inverse,
!> the host schemes, the per-pair API with the one-call inverse `hertzdamp_invert`, and
!> material data.  Helpers and internals (arithmetic kernels, safe exponentials, log forms,
!> solver options and statistics) stay in their modules: `use` those directly when needed.
!> The C and legacy entry points are in hertzdamp_capi (include/hertzdamp.h, hertzdamp.fi).
module hertzdamp
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: HD_OK, HD_NO_REBOUND, HD_MAX_STEPS, HD_STEP_UNDERFLOW, HD_BAD_ALPHA, &
                                HD_BAD_END, HD_BAD_TOL, HD_BAD_MASS, HD_BAD_VELOCITY, HD_BAD_STIFFNESS, &
                                HD_BAD_DAMPING, HD_BAD_TIME, HD_BAD_RESTITUTION, HD_OUT_OF_RANGE, &
                                HD_NOT_SUPPORTED, HD_NO_CONVERGENCE, HD_BAD_ORDER, HD_BAD_KPHYS, &
                                HD_BAD_ARGUMENT, HD_OUTSIDE_VALIDITY, HD_INACCURATE, HD_BAD_RADIUS, &
                                HD_BAD_DENSITY, HD_BAD_MODULUS, HD_BAD_POISSON, HD_BAD_LAW, HD_BAD_HOST, &
                                HD_BAD_STEPS, HD_HOST_UNREACHABLE, HD_BAD_PAIR, HD_PHASE_UNREACHABLE, &
                                HD_BAD_PHASE, HD_NO_PHASE_TABLE, HD_BAD_TANGENTIAL, HD_BAD_OBLIQUE, hertzdamp_message
    use hertzdamp_registry, only: HD_END_OVERLAP, HD_END_FORCE, hertzdamp_end_name
    use hertzdamp_laws, only: HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO, &
                              hertzdamp_max_law, hertzdamp_law_name, hertzdamp_law_code, hertzdamp_law_q, &
                              hertzdamp_law_status, hertzdamp_law_speed_exponent, &
                              hertzdamp_law_reversal_exponent, hertzdamp_law_has_alpha_c, hertzdamp_tsuji_e, &
                              hertzdamp_tsuji_l, hertzdamp_tsuji_alpha
    use hertzdamp_constants, only: hertzdamp_z_max0, hertzdamp_tau_c0, hertzdamp_e1, hertzdamp_pi
    use hertzdamp_scaling, only: hertzdamp_reduce, hertzdamp_expand
    use hertzdamp_rk45, only: hertzdamp_collision, hertzdamp_rk45_collide, hertzdamp_rk45_default_tol, &
                              hertzdamp_alpha_min, hertzdamp_alpha_max, hertzdamp_alpha_c, &
                              hertzdamp_law_alpha_c
    use hertzdamp_series, only: hertzdamp_series_eval, hertzdamp_pade_eval, hertzdamp_series_max_order, &
                                hertzdamp_series_default_order, hertzdamp_pade_alpha_max
    use hertzdamp_methods, only: HD_METHOD_RK45, HD_METHOD_SERIES, HD_METHOD_PADE, HD_METHOD_COMPACT, &
                                 HD_METHOD_FIT, HD_METHOD_ITERATIVE, HD_METHOD_FIRST_ORDER, &
                                 hertzdamp_default_accuracy, hertzdamp_forward_alpha, hertzdamp_forward_dim, &
                                 hertzdamp_method_name, hertzdamp_method_code
    use hertzdamp_fit, only: hertzdamp_fit_forward, hertzdamp_fit_forward_n, hertzdamp_fit_inverse, &
                             hertzdamp_fit_inverse_n, hertzdamp_fit_e_min_overlap, hertzdamp_fit_e_min_force, &
                             hertzdamp_fit_alpha_c, hertzdamp_fit_alpha_max_force
    use hertzdamp_fit_laws, only: hertzdamp_fit_law_forward, hertzdamp_fit_law_inverse, &
                                  hertzdamp_fit_law_e_min, hertzdamp_fit_forward_deriv
    use hertzdamp_fit_data, only: hertzdamp_fit_law_e_min_forward => fit_law_e_min_forward
    use hertzdamp_compact, only: hertzdamp_compact_forward, hertzdamp_compact_inverse, &
                                 hertzdamp_compact_e_min_overlap, hertzdamp_compact_e_min_force, &
                                 hertzdamp_compact_alpha_max_overlap, hertzdamp_compact_alpha_max_force
    use hertzdamp_inverse, only: hertzdamp_invert_alpha, hertzdamp_invert_options, &
                                 hertzdamp_invert_default_tol, hertzdamp_secant, hertzdamp_secant_start, &
                                 hertzdamp_secant_next
    use hertzdamp_host, only: HD_HOST_NONE, HD_HOST_LAMMPS, HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2, &
                              HD_HOST_VERLET, HD_HOST_LAMMPS_PHASE, hertzdamp_max_host, hertzdamp_host_steps_min, &
                              hertzdamp_host_steps_max, hertzdamp_host_name, hertzdamp_host_code, &
                              hertzdamp_host_status, hertzdamp_host_stats, hertzdamp_host_collide, &
                              hertzdamp_host_mean, hertzdamp_host_solve, hertzdamp_host_min_steps, &
                              hertzdamp_host_alpha_for_e, hertzdamp_host_phase_force
    use hertzdamp_pair, only: hertzdamp_pair_t, hertzdamp_pair_size, hertzdamp_pair_init, hertzdamp_pair_kd, &
                              hertzdamp_invert
    use hertzdamp_materials, only: hertzdamp_sphere_mass, hertzdamp_effective_mass, &
                                   hertzdamp_effective_radius, hertzdamp_effective_modulus, &
                                   hertzdamp_plane_strain_modulus, hertzdamp_hertz_stiffness, &
                                   hertzdamp_hertz_time, hertzdamp_pair_contact, hertzdamp_wall_contact, &
                                   hertzdamp_rayleigh_time, hertzdamp_rayleigh_fraction
    implicit none
    private

    ! the real kind (hertzdamp_kinds)
    public :: hertzdamp_rk
    ! status codes and their messages (hertzdamp_status)
    public :: HD_OK, HD_NO_REBOUND, HD_MAX_STEPS, HD_STEP_UNDERFLOW, HD_BAD_ALPHA, HD_BAD_END, HD_BAD_TOL, &
              HD_BAD_MASS, HD_BAD_VELOCITY, HD_BAD_STIFFNESS, HD_BAD_DAMPING, HD_BAD_TIME, HD_BAD_RESTITUTION, &
              HD_OUT_OF_RANGE, HD_NOT_SUPPORTED, HD_NO_CONVERGENCE, HD_BAD_ORDER, HD_BAD_KPHYS, &
              HD_BAD_ARGUMENT, HD_OUTSIDE_VALIDITY, HD_INACCURATE, HD_BAD_RADIUS, HD_BAD_DENSITY, &
              HD_BAD_MODULUS, HD_BAD_POISSON, HD_BAD_LAW, HD_BAD_HOST, HD_BAD_STEPS, HD_HOST_UNREACHABLE, &
              HD_BAD_PAIR, HD_PHASE_UNREACHABLE, HD_BAD_PHASE, HD_NO_PHASE_TABLE, HD_BAD_TANGENTIAL, HD_BAD_OBLIQUE, &
              hertzdamp_message
    ! the contact-end definitions (hertzdamp_ends)
    public :: HD_END_OVERLAP, HD_END_FORCE, hertzdamp_end_name
    ! the damping laws and their exact facts (hertzdamp_laws)
    public :: HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO, hertzdamp_max_law, &
              hertzdamp_law_name, hertzdamp_law_code, hertzdamp_law_q, hertzdamp_law_status, &
              hertzdamp_law_speed_exponent, hertzdamp_law_reversal_exponent, hertzdamp_law_has_alpha_c, &
              hertzdamp_tsuji_e, hertzdamp_tsuji_l, hertzdamp_tsuji_alpha
    ! closed forms of the elastic limit (hertzdamp_constants)
    public :: hertzdamp_z_max0, hertzdamp_tau_c0, hertzdamp_e1, hertzdamp_pi
    ! the dimensionless reduction (hertzdamp_scaling)
    public :: hertzdamp_reduce, hertzdamp_expand
    ! the reference integrator and the critical damping (hertzdamp_rk45)
    public :: hertzdamp_collision, hertzdamp_rk45_collide, hertzdamp_rk45_default_tol, hertzdamp_alpha_min, &
              hertzdamp_alpha_max, hertzdamp_alpha_c, hertzdamp_law_alpha_c
    ! the series in alpha and its Pade summation (hertzdamp_series)
    public :: hertzdamp_series_eval, hertzdamp_pade_eval, hertzdamp_series_max_order, &
              hertzdamp_series_default_order, hertzdamp_pade_alpha_max
    ! the forward problem by any method (hertzdamp_methods)
    public :: HD_METHOD_RK45, HD_METHOD_SERIES, HD_METHOD_PADE, HD_METHOD_COMPACT, HD_METHOD_FIT, &
              HD_METHOD_ITERATIVE, HD_METHOD_FIRST_ORDER, hertzdamp_default_accuracy, hertzdamp_forward_alpha, &
              hertzdamp_forward_dim, hertzdamp_method_name, hertzdamp_method_code
    ! the fitted maps (machine precision, no iteration) (hertzdamp_fit)
    public :: hertzdamp_fit_forward, hertzdamp_fit_forward_n, hertzdamp_fit_inverse, hertzdamp_fit_inverse_n, &
              hertzdamp_fit_e_min_overlap, hertzdamp_fit_e_min_force, hertzdamp_fit_alpha_c, &
              hertzdamp_fit_alpha_max_force
    ! the fitted maps of every law (hertzdamp_fit_laws)
    public :: hertzdamp_fit_law_forward, hertzdamp_fit_law_inverse, hertzdamp_fit_law_e_min, &
              hertzdamp_fit_forward_deriv
    ! the smallest e the fitted forward maps of the laws reach (hertzdamp_fit_data)
    public :: hertzdamp_fit_law_e_min_forward
    ! the compact engineering formula (hertzdamp_compact)
    public :: hertzdamp_compact_forward, hertzdamp_compact_inverse, hertzdamp_compact_e_min_overlap, &
              hertzdamp_compact_e_min_force, hertzdamp_compact_alpha_max_overlap, &
              hertzdamp_compact_alpha_max_force
    ! the dimensionless inverse by any method (hertzdamp_inverse)
    public :: hertzdamp_invert_alpha, hertzdamp_invert_options, hertzdamp_invert_default_tol, &
              hertzdamp_secant, hertzdamp_secant_start, hertzdamp_secant_next
    ! the host schemes (a DEM engine's time integrator) (hertzdamp_host)
    public :: HD_HOST_NONE, HD_HOST_LAMMPS, HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2, HD_HOST_VERLET, &
              HD_HOST_LAMMPS_PHASE, hertzdamp_max_host, hertzdamp_host_steps_min, hertzdamp_host_steps_max, &
              hertzdamp_host_name, hertzdamp_host_code, hertzdamp_host_status, hertzdamp_host_stats, &
              hertzdamp_host_collide, hertzdamp_host_mean, hertzdamp_host_solve, hertzdamp_host_min_steps, &
              hertzdamp_host_alpha_for_e, hertzdamp_host_phase_force
    ! the per-pair API and the one-call inverse (hertzdamp_pair)
    public :: hertzdamp_pair_t, hertzdamp_pair_size, hertzdamp_pair_init, hertzdamp_pair_kd, hertzdamp_invert
    ! material data to the contact (hertzdamp_materials)
    public :: hertzdamp_sphere_mass, hertzdamp_effective_mass, hertzdamp_effective_radius, &
              hertzdamp_effective_modulus, hertzdamp_plane_strain_modulus, hertzdamp_hertz_stiffness, &
              hertzdamp_hertz_time, hertzdamp_pair_contact, hertzdamp_wall_contact, hertzdamp_rayleigh_time, &
              hertzdamp_rayleigh_fraction
end module hertzdamp
