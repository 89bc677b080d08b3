!> TEMPORARY stand-in, dropped on merge.
!>
!> Only here so that the `bench` branch compiles before the real inverse module lands
!> (another branch implements it).  It has the interface of the real
!> `hertzdamp_invert`, but every method is the same slow baseline: a bracketed
!> secant (Illinois) iteration on alpha, each trial an rk45 solve, then
!> t* = T_c / tau_c, k = m t*^(-5/2) u^(-1/2), d = alpha m / t* (THEORY.md section 6).
!> Timings measured with this file in place say nothing about the fit, compact,
!> series or pade inverses.
module hertzdamp_inverse
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_OK, HD_NO_REBOUND, HD_BAD_RESTITUTION, HD_BAD_TIME, HD_BAD_END, &
                                HD_NO_CONVERGENCE, HD_BAD_TOL, HD_END_OVERLAP, HD_END_FORCE
    use hertzdamp_scaling, only: hertzdamp_expand, hertzdamp_check_positive
    use hertzdamp_rk45, only: hertzdamp_collision, hertzdamp_rk45_collide
    use hertzdamp_methods, only: HD_METHOD_ITERATIVE
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    public :: hertzdamp_invert

contains

    !> k and d that give restitution e and contact time tc (stand-in: rk45 secant).
    pure elemental subroutine hertzdamp_invert(e, tc, m, u, iend, k, d, status, alpha, tstar, tau_c, &
                                               bound_active, k_phys, method, tol)
        real(wp), intent(in) :: e                  !! restitution coefficient, (0, 1]
        real(wp), intent(in) :: tc                 !! target contact time [s]
        real(wp), intent(in) :: m                  !! effective mass [kg]
        real(wp), intent(in) :: u                  !! impact velocity [m s^-1]
        integer, intent(in) :: iend                !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out) :: k                 !! stiffness [N m^-3/2]
        real(wp), intent(out) :: d                 !! damping coefficient [kg s^-1]
        integer, intent(out) :: status             !! HD_OK or an error
        real(wp), intent(out), optional :: alpha   !! damping parameter
        real(wp), intent(out), optional :: tstar   !! time unit [s]
        real(wp), intent(out), optional :: tau_c   !! dimensionless contact time
        logical, intent(out), optional :: bound_active !! k_phys used
        real(wp), intent(in), optional :: k_phys   !! physical stiffness bound
        integer, intent(in), optional :: method    !! HD_METHOD_*
        real(wp), intent(in), optional :: tol      !! iteration tolerance (iterative method)
        real(wp) :: tol_, a, ts, tau, lo, hi, flo, fhi, fm, am
        type(hertzdamp_collision) :: r
        integer :: it, side
        logical :: ba

        k = 0.0_wp
        d = 0.0_wp
        a = 0.0_wp
        ts = 0.0_wp
        tau = 0.0_wp
        ba = .false.
        hi = 0.0_wp
        fhi = 0.0_wp
        tol_ = 1.0e-13_wp
        if (present(method)) then
            if (method == HD_METHOD_ITERATIVE .and. present(tol)) tol_ = tol
        end if
        status = HD_OK
        if (iend /= HD_END_OVERLAP .and. iend /= HD_END_FORCE) status = HD_BAD_END
        if (status == HD_OK .and. .not. (e > 0.0_wp .and. e <= 1.0_wp)) status = HD_BAD_RESTITUTION
        if (status == HD_OK) status = hertzdamp_check_positive(tc, HD_BAD_TIME)
        if (status == HD_OK .and. .not. (tol_ >= 1.0e-15_wp .and. tol_ <= 1.0e-2_wp)) status = HD_BAD_TOL
        if (status == HD_OK) then
            lo = 0.0_wp
            r = hertzdamp_rk45_collide(lo, iend, tol_)
            flo = r%e - e
            tau = r%tau_c
            a = lo
            if (e < 1.0_wp .and. r%status == HD_OK) then
                hi = merge(1.13_wp, 1.0_wp, iend == HD_END_OVERLAP)
                do it = 1, 60
                    r = hertzdamp_rk45_collide(hi, iend, tol_)
                    if (r%status /= HD_OK .and. r%status /= HD_NO_REBOUND) exit
                    fhi = r%e - e
                    if (fhi < 0.0_wp .or. hi > 1.0e4_wp) exit
                    lo = hi
                    flo = fhi
                    hi = 2.0_wp * hi
                end do
                status = r%status
                if (status == HD_NO_REBOUND) status = HD_OK
                if (status == HD_OK .and. fhi >= 0.0_wp) status = HD_NO_CONVERGENCE
                side = 0
                it = 0
                do while (status == HD_OK)
                    it = it + 1
                    if (it > 300) then
                        status = HD_NO_CONVERGENCE
                        exit
                    end if
                    am = (lo * fhi - hi * flo) / (fhi - flo)
                    if (.not. (am > lo .and. am < hi)) am = 0.5_wp * (lo + hi)
                    r = hertzdamp_rk45_collide(am, iend, tol_)
                    if (r%status /= HD_OK .and. r%status /= HD_NO_REBOUND) then
                        status = r%status
                        exit
                    end if
                    fm = r%e - e
                    if (fm < 0.0_wp) then
                        hi = am
                        fhi = fm
                        if (side == -1) flo = 0.5_wp * flo
                        side = -1
                    else
                        lo = am
                        flo = fm
                        if (side == 1) fhi = 0.5_wp * fhi
                        side = 1
                        a = am
                        tau = r%tau_c
                    end if
                    if (abs(fm) <= tol_ * e) then
                        a = am        ! converged on |e(alpha) - e| (the trial rebounds: e(am) > 0)
                        tau = r%tau_c
                        exit
                    end if
                    if (hi - lo <= tol_ * hi) exit   ! bracket closed: keep the rebounding end lo

                end do
            end if
        end if
        if (status == HD_OK) then
            ts = tc / tau
            call hertzdamp_expand(a, ts, m, u, k, d, status)
            if (status == HD_OK .and. present(k_phys)) then
                if (k_phys <= k) then
                    k = k_phys
                    d = a * m**0.6_wp * k_phys**0.4_wp * u**0.2_wp
                    ba = .true.
                end if
            end if
        end if
        if (present(alpha)) alpha = a
        if (present(tstar)) tstar = ts
        if (present(tau_c)) tau_c = tau
        if (present(bound_active)) bound_active = ba
    end subroutine hertzdamp_invert

end module hertzdamp_inverse
