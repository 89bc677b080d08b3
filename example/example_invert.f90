!> The adaptive collision time model from modern Fortran: stiffness and damping for a
!> whole array of contacts in one elemental call (doc/theory.md section 6), checked by the
!> forward problem.  Run with `fpm run --example example_invert`.
program example_invert
    use hertzdamp, only: hertzdamp_rk, hertzdamp_invert, hertzdamp_invert_options, hertzdamp_forward_dim, &
                         hertzdamp_message, HD_OK, HD_END_OVERLAP, HD_METHOD_FIT
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: n = 5
    !> The method used below: the machine-precision fit.
    integer, parameter :: method = HD_METHOD_FIT
    real(wp), parameter :: e_target = 0.7_wp          ! physical restitution
    real(wp), parameter :: dt = 1.0e-6_wp             ! DEM time step [s]
    real(wp), parameter :: tc = 10 * dt               ! resolve each contact by 10 steps
    real(wp), parameter :: k_phys = 3.0e8_wp          ! material stiffness bound [N m^-3/2]
    real(wp) :: m(n), u(n), k(n), d(n), alpha(n), e(n), t(n), a2(n), ts(n), zm(n)
    logical :: bound(n)
    integer :: status(n), status_f(n), i

    m = [1.0e-6_wp, 1.0e-6_wp, 4.0e-6_wp, 4.0e-6_wp, 1.0e-5_wp]   ! effective masses [kg]
    u = [0.01_wp, 1.0_wp, 0.1_wp, 5.0_wp, 2.0_wp]                 ! impact speeds [m/s]

    call hertzdamp_invert(e_target, tc, m, u, HD_END_OVERLAP, k, d, status, alpha=alpha, &
                          bound_active=bound, k_phys=k_phys, options=hertzdamp_invert_options(method=method))
    call hertzdamp_forward_dim(k, d, m, u, HD_END_OVERLAP, method, a2, ts, e, t, zm, status_f)

    write (*, '(a)') '        m [kg]      u [m/s]     k [N/m^1.5]    d [kg/s]       alpha   k_phys?' // &
        '        e      T_c/dt'
    do i = 1, n
        if (status(i) /= HD_OK .or. status_f(i) /= HD_OK) then
            write (*, '(a)') 'contact failed: ' // hertzdamp_message(max(status(i), status_f(i)))
            cycle
        end if
        write (*, '(5es13.5,l6,f12.8,f10.5)') m(i), u(i), k(i), d(i), alpha(i), bound(i), e(i), t(i) / dt
    end do
end program example_invert
