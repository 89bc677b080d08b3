!> Legacy Fortran entry points: external subroutines outside any module, callable
!> from fixed-form Fortran 77 through implicit interfaces.  All reals are DOUBLE
!> PRECISION, all integers default INTEGER; every argument is passed by reference.
!> Their names and argument lists are stable across versions.  They use the same
!> method as the C API (`legacy_method` in `hertzdamp_flat`) and need only the
!> Fortran runtime: link with `-lhertzdamp`.
!>
!>       DOUBLE PRECISION E, TC, M, U, K, D
!>       INTEGER IEND, IERR
!>       CHARACTER*80 TEXT
!>       CALL HERTZDAMP_INVERT(E, TC, M, U, IEND, K, D, IERR)
!>       IF (IERR .NE. 0) CALL HERTZDAMP_MESSAGE(IERR, TEXT)
!>
!> `include/hertzdamp.fi` declares them all with explicit interfaces (`INCLUDE
!> 'hertzdamp.fi'` in fixed or free form): a REAL*4 argument, or DOUBLE PRECISION
!> promoted by -fdefault-real-8, is then a compile error instead of garbage.
!> The status codes are those of `hertzdamp_status` (0 = success, 1 = no rebound).

!> Stiffness k and damping d that give restitution e and contact time tc to a
!> contact of effective mass m hit at speed u.  On failure k = d = 0, ierr /= 0.
subroutine hertzdamp_invert(e, tc, m, u, iend, k, d, ierr)
    use hertzdamp_flat, only: flat_invert
    implicit none
    double precision, intent(in) :: e     !! target restitution coefficient: 1e-3 <= e <= 1 (overlap), 1e-4 <= e <= 1 (force)
    double precision, intent(in) :: tc    !! target contact time [s]
    double precision, intent(in) :: m     !! effective mass [kg]
    double precision, intent(in) :: u     !! impact velocity [m/s]
    integer, intent(in) :: iend           !! contact end: 0 overlap, 1 force
    double precision, intent(out) :: k    !! Hertz stiffness [N m^-3/2]
    double precision, intent(out) :: d    !! linear damping coefficient [kg/s]
    integer, intent(out) :: ierr          !! 0 on success, else a status code
    call flat_invert(e, tc, m, u, iend, k, d, ierr)
end subroutine hertzdamp_invert

!> hertzdamp_invert with the physical-stiffness bound kphys = (4/3) E* sqrt(R*): where
!> kphys <= k the contact keeps k = kphys and d = alpha m^(3/5) kphys^(2/5) u^(1/5)
!> (it is then longer than tc, and the material's own stiffness is recovered once
!> the time step is small enough).  On failure k = d = 0, ierr /= 0.
subroutine hertzdamp_invert_bounded(e, tc, m, u, kphys, iend, k, d, ierr)
    use hertzdamp_flat, only: flat_invert_bounded
    implicit none
    double precision, intent(in) :: e     !! target restitution coefficient
    double precision, intent(in) :: tc    !! target contact time [s]
    double precision, intent(in) :: m     !! effective mass [kg]
    double precision, intent(in) :: u     !! impact velocity [m/s]
    double precision, intent(in) :: kphys !! physical stiffness bound [N m^-3/2]
    integer, intent(in) :: iend           !! contact end: 0 overlap, 1 force
    double precision, intent(out) :: k    !! Hertz stiffness [N m^-3/2]
    double precision, intent(out) :: d    !! linear damping coefficient [kg/s]
    integer, intent(out) :: ierr          !! 0 on success, else a status code
    call flat_invert_bounded(e, tc, m, u, kphys, iend, k, d, ierr)
end subroutine hertzdamp_invert_bounded

!> The constants of a material pair: alpha(e) and tau_c(alpha(e)), which depend on e
!> and the contact end only.  Per contact (mass m, impact speed u, contact time tc):
!>     k = m (tauc/tc)**2.5 / sqrt(u),   d = alpha m tauc/tc
!> (d is the same for every contact of the pair with the same tc).  On failure
!> alpha = tauc = 0, ierr /= 0.
subroutine hertzdamp_pair(e, iend, alpha, tauc, ierr)
    use hertzdamp_flat, only: flat_pair
    implicit none
    double precision, intent(in) :: e      !! target restitution coefficient
    integer, intent(in) :: iend            !! contact end: 0 overlap, 1 force
    double precision, intent(out) :: alpha !! damping parameter alpha(e)
    double precision, intent(out) :: tauc  !! dimensionless contact duration tau_c(alpha)
    integer, intent(out) :: ierr           !! 0 on success, else a status code
    call flat_pair(e, iend, alpha, tauc, ierr)
end subroutine hertzdamp_pair

!> Restitution e and contact time tc of the contact (k, d, m, u).  Without rebound
!> e = 0, tc = huge(1d0) and ierr = 1 (HD_NO_REBOUND); on other failures e = tc = 0.
subroutine hertzdamp_forward(k, d, m, u, iend, e, tc, ierr)
    use hertzdamp_flat, only: flat_forward
    implicit none
    double precision, intent(in) :: k     !! Hertz stiffness [N m^-3/2]
    double precision, intent(in) :: d     !! linear damping coefficient [kg/s]
    double precision, intent(in) :: m     !! effective mass [kg]
    double precision, intent(in) :: u     !! impact velocity [m/s]
    integer, intent(in) :: iend           !! contact end: 0 overlap, 1 force
    double precision, intent(out) :: e    !! restitution coefficient
    double precision, intent(out) :: tc   !! contact time [s]
    integer, intent(out) :: ierr          !! 0 on success, 1 no rebound, else a status code
    call flat_forward(k, d, m, u, iend, e, tc, ierr)
end subroutine hertzdamp_forward

!> hertzdamp_invert for n contacts at once (one contact-end definition for all).
!> n <= 0 does nothing.
subroutine hertzdamp_invert_n(n, e, tc, m, u, iend, k, d, ierr)
    use hertzdamp_flat, only: flat_invert
    implicit none
    integer, intent(in) :: n                  !! number of contacts
    double precision, intent(in) :: e(n)      !! target restitution coefficients (n)
    double precision, intent(in) :: tc(n)     !! target contact times [s] (n)
    double precision, intent(in) :: m(n)      !! effective masses [kg] (n)
    double precision, intent(in) :: u(n)      !! impact velocities [m/s] (n)
    integer, intent(in) :: iend               !! contact end: 0 overlap, 1 force
    double precision, intent(out) :: k(n)     !! Hertz stiffnesses [N m^-3/2] (n)
    double precision, intent(out) :: d(n)     !! damping coefficients [kg/s] (n)
    integer, intent(out) :: ierr(n)           !! status of each contact (n)
    call flat_invert(e, tc, m, u, iend, k, d, ierr)
end subroutine hertzdamp_invert_n

!> hertzdamp_invert for the damping law ilaw (0 linear, 1 tsuji, 2 kuwabara-kono:
!> damping force d zeta^q zeta', q = 0, 1/4, 1/2, d in kg s^-1 m^-q), with the
!> physical-stiffness bound kphys when kphys > 0 (kphys = 0: no bound).  On failure
!> k = d = 0, ierr /= 0.
subroutine hertzdamp_invert_law(e, tc, m, u, kphys, ilaw, iend, k, d, ierr)
    use hertzdamp_flat, only: flat_invert_law
    implicit none
    double precision, intent(in) :: e     !! target restitution coefficient
    double precision, intent(in) :: tc    !! target contact time [s]
    double precision, intent(in) :: m     !! effective mass [kg]
    double precision, intent(in) :: u     !! impact velocity [m/s]
    double precision, intent(in) :: kphys !! physical stiffness bound [N m^-3/2], 0 for none
    integer, intent(in) :: ilaw           !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
    integer, intent(in) :: iend           !! contact end: 0 overlap, 1 force
    double precision, intent(out) :: k    !! Hertz stiffness [N m^-3/2]
    double precision, intent(out) :: d    !! damping coefficient [kg s^-1 m^-q]
    integer, intent(out) :: ierr          !! 0 on success, else a status code
    call flat_invert_law(e, tc, m, u, kphys, ilaw, iend, k, d, ierr)
end subroutine hertzdamp_invert_law

!> The material-pair constants of the damping law ilaw; per contact
!>     tstar = tc/tauc,  k = m tstar**(-2.5) / sqrt(u),  d = alpha m / tstar / (u tstar)**q.
subroutine hertzdamp_pair_law(e, ilaw, iend, alpha, tauc, ierr)
    use hertzdamp_flat, only: flat_pair_law
    implicit none
    double precision, intent(in) :: e      !! target restitution coefficient
    integer, intent(in) :: ilaw            !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
    integer, intent(in) :: iend            !! contact end: 0 overlap, 1 force
    double precision, intent(out) :: alpha !! damping parameter alpha(e)
    double precision, intent(out) :: tauc  !! dimensionless contact duration tau_c(alpha)
    integer, intent(out) :: ierr           !! 0 on success, else a status code
    call flat_pair_law(e, ilaw, iend, alpha, tauc, ierr)
end subroutine hertzdamp_pair_law

!> hertzdamp_forward for the damping law ilaw (d in kg s^-1 m^-q).
subroutine hertzdamp_forward_law(k, d, m, u, ilaw, iend, e, tc, ierr)
    use hertzdamp_flat, only: flat_forward_law
    implicit none
    double precision, intent(in) :: k     !! Hertz stiffness [N m^-3/2]
    double precision, intent(in) :: d     !! damping coefficient [kg s^-1 m^-q]
    double precision, intent(in) :: m     !! effective mass [kg]
    double precision, intent(in) :: u     !! impact velocity [m/s]
    integer, intent(in) :: ilaw           !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
    integer, intent(in) :: iend           !! contact end: 0 overlap, 1 force
    double precision, intent(out) :: e    !! restitution coefficient
    double precision, intent(out) :: tc   !! contact time [s]
    integer, intent(out) :: ierr          !! 0 on success, 1 no rebound, else a status code
    call flat_forward_law(k, d, m, u, ilaw, iend, e, tc, ierr)
end subroutine hertzdamp_forward_law

!> The message of a status code, copied into text (truncated or blank-padded).
subroutine hertzdamp_message(ierr, text)
    use hertzdamp_status, only: mod_message => hertzdamp_message
    implicit none
    integer, intent(in) :: ierr               !! a status code
    character(len=*), intent(out) :: text     !! receives the message
    text = mod_message(ierr)
end subroutine hertzdamp_message
