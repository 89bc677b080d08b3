!> The DEM application of hertzdamp: one `use hertzdamp_dem` gives the scene and
!> result types, validation, the contact rule and its choice, and the engine.
!>
!> - hertzdamp_dem_types: scene, material, wall, contact, result; limits; pair formulas
!> - hertzdamp_dem_validate: hertzdamp_dem_check (values, representable magnitudes, layout)
!> - hertzdamp_dem_rules: hertzdamp_dem_rule (k, d of one contact, every damping law), hertzdamp_dem_host_rule
!>   (k, d from a host's per-pair constants),
!>   hertzdamp_dem_select (auto), hertzdamp_dem_supports (the rules of a law)
!> - hertzdamp_dem_checks: the checks of a run (values, bounds, outcomes) that the report prints
!> - hertzdamp_dem_engine: the state type and the phases of a step; hertzdamp_dem_run, or
!>   hertzdamp_dem_start / _advance / _finish for a run in pieces (progress reports)
module hertzdamp_dem
    use hertzdamp_dem_types, only: hertzdamp_dem_scene, hertzdamp_dem_material, hertzdamp_dem_wall, &
                                   hertzdamp_dem_contact, hertzdamp_dem_result, hertzdamp_dem_max_particles, &
                                   hertzdamp_dem_max_steps, hertzdamp_dem_max_traced, hertzdamp_dem_max_samples, &
                                   hertzdamp_dem_max_trace_values, hertzdamp_dem_u_floor, hertzdamp_dem_big, &
                                   HD_CONTACT_ACTIVE, HD_CONTACT_RELEASED, HD_CONTACT_CLOSED, &
                                   hertzdamp_dem_pair_e, hertzdamp_dem_pairs_met, hertzdamp_dem_nsteps, hertzdamp_dem_trace_size
    use hertzdamp_dem_validate, only: hertzdamp_dem_check
    use hertzdamp_dem_checks, only: hertzdamp_dem_check_row, hertzdamp_dem_checks_of, hertzdamp_dem_steps_min, &
                                    hertzdamp_dem_verlet_energy, hertzdamp_dem_ratio, hertzdamp_dem_checked, &
                                    hertzdamp_dem_min_resolved, HD_CHECK_PASS, HD_CHECK_FAIL, HD_CHECK_INFO, &
                                    HD_CHECK_GRAVITY
    use hertzdamp_dem_rules, only: hertzdamp_dem_rule, hertzdamp_dem_host_rule, hertzdamp_dem_select, hertzdamp_dem_targets, &
                                   hertzdamp_dem_cost_order, hertzdamp_dem_supports
    use hertzdamp_dem_engine, only: hertzdamp_dem_state, hertzdamp_dem_run, hertzdamp_dem_start, &
                                    hertzdamp_dem_advance, hertzdamp_dem_finish, hertzdamp_dem_steps_done, &
                                    hertzdamp_dem_steps_total
    implicit none
    public
end module hertzdamp_dem
