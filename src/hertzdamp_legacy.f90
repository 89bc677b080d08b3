!> Legacy Fortran entry points: callable from fixed-form Fortran 77 through implicit
!> interfaces.  All reals are DOUBLE PRECISION, all integers default INTEGER; every
!> argument is passed by reference.  Their names and argument lists are stable across
!> versions.  They use the same method as the C API (`legacy_method` in
!> `hertzdamp_flat`) and need only the Fortran runtime: link with `-lhertzdamp`.
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
!>
!> Why a module with binding labels, and not external subroutines: gfortran saves and
!> restores the floating-point environment (`_gfortran_ieee_procedure_entry/exit`,
!> about 250 ns per call) around every procedure whose own scope sees a symbol of an
!> IEEE intrinsic module.  A `use` of any module of the library inside an external
!> subroutine brings such symbols along (every .mod that uses ieee_arithmetic, even
!> with `only:`, carries its derived types, and they travel through every module that
!> uses it), so external subroutines that `use hertzdamp_flat` paid it on each call.
!> Here every `use` is at module level, where it does not count for the procedures:
!> they are module procedures whose binding labels (`bind(c, name='hertzdamp_invert_')`,
!> the name gfortran gives an external HERTZDAMP_INVERT) keep the link names and the
!> calling convention (scalars and explicit-shape arrays by reference) of the externals.
!> test/integration/fpenv_symbols.sh fails if a legacy or C entry point calls those routines again.
module hertzdamp_legacy
    use, intrinsic :: iso_c_binding, only: c_double, c_int
    use hertzdamp_flat, only: flat_invert, flat_invert_bounded, flat_pair, flat_forward, flat_invert_n, flat_invert_law, &
                              flat_invert_law_n, flat_pair_law, flat_forward_law
    implicit none
    private

    public :: legacy_invert, legacy_invert_bounded, legacy_pair, legacy_forward, legacy_invert_n
    public :: legacy_invert_law, legacy_invert_law_n, legacy_pair_law, legacy_forward_law

contains

    !> HERTZDAMP_INVERT(E, TC, M, U, IEND, K, D, IERR): stiffness k and damping d that give
    !> restitution e and contact time tc to a contact of effective mass m hit at speed u.
    !> On failure k = d = 0, ierr /= 0.
    subroutine legacy_invert(e, tc, m, u, iend, k, d, ierr) bind(c, name='hertzdamp_invert_')
        real(c_double), intent(in) :: e     !! target restitution coefficient: 1e-3 <= e <= 1 (overlap), 1e-4 <= e <= 1 (force)
        real(c_double), intent(in) :: tc    !! target contact time [s]
        real(c_double), intent(in) :: m     !! effective mass [kg]
        real(c_double), intent(in) :: u     !! impact velocity [m/s]
        integer(c_int), intent(in) :: iend  !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: k    !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(out) :: d    !! linear damping coefficient [kg/s]
        integer(c_int), intent(out) :: ierr !! 0 on success, else a status code
        call flat_invert(e, tc, m, u, iend, k, d, ierr)
    end subroutine legacy_invert

    !> HERTZDAMP_INVERT_BOUNDED(E, TC, M, U, KPHYS, IEND, K, D, IERR): HERTZDAMP_INVERT with
    !> the physical-stiffness bound kphys = (4/3) E* sqrt(R*): where kphys <= k the contact
    !> keeps k = kphys and d = alpha m^(3/5) kphys^(2/5) u^(1/5) (it is then longer than
    !> tc, and the material's own stiffness is recovered once the time step is small
    !> enough).  On failure k = d = 0, ierr /= 0.
    subroutine legacy_invert_bounded(e, tc, m, u, kphys, iend, k, d, ierr) bind(c, name='hertzdamp_invert_bounded_')
        real(c_double), intent(in) :: e     !! target restitution coefficient
        real(c_double), intent(in) :: tc    !! target contact time [s]
        real(c_double), intent(in) :: m     !! effective mass [kg]
        real(c_double), intent(in) :: u     !! impact velocity [m/s]
        real(c_double), intent(in) :: kphys !! physical stiffness bound [N m^-3/2]
        integer(c_int), intent(in) :: iend  !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: k    !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(out) :: d    !! linear damping coefficient [kg/s]
        integer(c_int), intent(out) :: ierr !! 0 on success, else a status code
        call flat_invert_bounded(e, tc, m, u, kphys, iend, k, d, ierr)
    end subroutine legacy_invert_bounded

    !> HERTZDAMP_PAIR(E, IEND, ALPHA, TAUC, IERR): the constants of a material pair,
    !> alpha(e) and tau_c(alpha(e)), which depend on e and the contact end only.  Per
    !> contact (mass m, impact speed u, contact time tc):
    !>     k = m (tauc/tc)**2.5 / sqrt(u),   d = alpha m tauc/tc
    !> (d is the same for every contact of the pair with the same tc).  On failure
    !> alpha = tauc = 0, ierr /= 0.
    subroutine legacy_pair(e, iend, alpha, tauc, ierr) bind(c, name='hertzdamp_pair_')
        real(c_double), intent(in) :: e      !! target restitution coefficient
        integer(c_int), intent(in) :: iend   !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: alpha !! damping parameter alpha(e)
        real(c_double), intent(out) :: tauc  !! dimensionless contact duration tau_c(alpha)
        integer(c_int), intent(out) :: ierr  !! 0 on success, else a status code
        call flat_pair(e, iend, alpha, tauc, ierr)
    end subroutine legacy_pair

    !> HERTZDAMP_FORWARD(K, D, M, U, IEND, E, TC, IERR): restitution e and contact time tc
    !> of the contact (k, d, m, u).  Without rebound e = 0, tc = huge(1d0) and ierr = 1
    !> (HD_NO_REBOUND); on other failures e = tc = 0.
    subroutine legacy_forward(k, d, m, u, iend, e, tc, ierr) bind(c, name='hertzdamp_forward_')
        real(c_double), intent(in) :: k     !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(in) :: d     !! linear damping coefficient [kg/s]
        real(c_double), intent(in) :: m     !! effective mass [kg]
        real(c_double), intent(in) :: u     !! impact velocity [m/s]
        integer(c_int), intent(in) :: iend  !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: e    !! restitution coefficient
        real(c_double), intent(out) :: tc   !! contact time [s]
        integer(c_int), intent(out) :: ierr !! 0 on success, 1 no rebound, else a status code
        call flat_forward(k, d, m, u, iend, e, tc, ierr)
    end subroutine legacy_forward

    !> HERTZDAMP_INVERT_N(N, E, TC, M, U, IEND, K, D, IERR): HERTZDAMP_INVERT for n contacts
    !> at once (one contact-end definition for all), vectorised; the same results, bit for
    !> bit.  n <= 0 does nothing.
    subroutine legacy_invert_n(n, e, tc, m, u, iend, k, d, ierr) bind(c, name='hertzdamp_invert_n_')
        integer(c_int), intent(in) :: n           !! number of contacts
        real(c_double), intent(in) :: e(n)        !! target restitution coefficients (n)
        real(c_double), intent(in) :: tc(n)       !! target contact times [s] (n)
        real(c_double), intent(in) :: m(n)        !! effective masses [kg] (n)
        real(c_double), intent(in) :: u(n)        !! impact velocities [m/s] (n)
        integer(c_int), intent(in) :: iend        !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: k(n)       !! Hertz stiffnesses [N m^-3/2] (n)
        real(c_double), intent(out) :: d(n)       !! damping coefficients [kg/s] (n)
        integer(c_int), intent(out) :: ierr(n)    !! status of each contact (n)
        if (n <= 0) return
        call flat_invert_n(n, e, tc, m, u, iend, k, d, ierr)
    end subroutine legacy_invert_n

    !> HERTZDAMP_INVERT_LAW(E, TC, M, U, KPHYS, ILAW, IEND, K, D, IERR): HERTZDAMP_INVERT for
    !> the damping law ilaw (0 linear, 1 tsuji, 2 kuwabara-kono: damping force
    !> d zeta^q zeta', q = 0, 1/4, 1/2, d in kg s^-1 m^-q), with the physical-stiffness
    !> bound kphys when kphys > 0 (kphys = 0: no bound).  On failure k = d = 0, ierr /= 0.
    subroutine legacy_invert_law(e, tc, m, u, kphys, ilaw, iend, k, d, ierr) bind(c, name='hertzdamp_invert_law_')
        real(c_double), intent(in) :: e     !! target restitution coefficient
        real(c_double), intent(in) :: tc    !! target contact time [s]
        real(c_double), intent(in) :: m     !! effective mass [kg]
        real(c_double), intent(in) :: u     !! impact velocity [m/s]
        real(c_double), intent(in) :: kphys !! physical stiffness bound [N m^-3/2], 0 for none
        integer(c_int), intent(in) :: ilaw  !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), intent(in) :: iend  !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: k    !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(out) :: d    !! damping coefficient [kg s^-1 m^-q]
        integer(c_int), intent(out) :: ierr !! 0 on success, else a status code
        call flat_invert_law(e, tc, m, u, kphys, ilaw, iend, k, d, ierr)
    end subroutine legacy_invert_law

    !> HERTZDAMP_INVERT_LAW_N(N, E, TC, M, U, ILAW, IEND, K, D, IERR): HERTZDAMP_INVERT_LAW
    !> without the bound (KPHYS = 0) for n contacts at once (one damping law and contact
    !> end for all), vectorised; the same results, bit for bit.  n <= 0 does nothing.
    subroutine legacy_invert_law_n(n, e, tc, m, u, ilaw, iend, k, d, ierr) bind(c, name='hertzdamp_invert_law_n_')
        integer(c_int), intent(in) :: n           !! number of contacts
        real(c_double), intent(in) :: e(n)        !! target restitution coefficients (n)
        real(c_double), intent(in) :: tc(n)       !! target contact times [s] (n)
        real(c_double), intent(in) :: m(n)        !! effective masses [kg] (n)
        real(c_double), intent(in) :: u(n)        !! impact velocities [m/s] (n)
        integer(c_int), intent(in) :: ilaw        !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), intent(in) :: iend        !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: k(n)       !! Hertz stiffnesses [N m^-3/2] (n)
        real(c_double), intent(out) :: d(n)       !! damping coefficients [kg s^-1 m^-q] (n)
        integer(c_int), intent(out) :: ierr(n)    !! status of each contact (n)
        if (n <= 0) return
        call flat_invert_law_n(n, e, tc, m, u, ilaw, iend, k, d, ierr)
    end subroutine legacy_invert_law_n

    !> HERTZDAMP_PAIR_LAW(E, ILAW, IEND, ALPHA, TAUC, IERR): the material-pair constants of
    !> the damping law ilaw; per contact
    !>     tstar = tc/tauc,  k = m tstar**(-2.5) / sqrt(u),  d = alpha m / tstar / (u tstar)**q.
    subroutine legacy_pair_law(e, ilaw, iend, alpha, tauc, ierr) bind(c, name='hertzdamp_pair_law_')
        real(c_double), intent(in) :: e      !! target restitution coefficient
        integer(c_int), intent(in) :: ilaw   !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), intent(in) :: iend   !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: alpha !! damping parameter alpha(e)
        real(c_double), intent(out) :: tauc  !! dimensionless contact duration tau_c(alpha)
        integer(c_int), intent(out) :: ierr  !! 0 on success, else a status code
        call flat_pair_law(e, ilaw, iend, alpha, tauc, ierr)
    end subroutine legacy_pair_law

    !> HERTZDAMP_FORWARD_LAW(K, D, M, U, ILAW, IEND, E, TC, IERR): HERTZDAMP_FORWARD for the
    !> damping law ilaw (d in kg s^-1 m^-q).
    subroutine legacy_forward_law(k, d, m, u, ilaw, iend, e, tc, ierr) bind(c, name='hertzdamp_forward_law_')
        real(c_double), intent(in) :: k     !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(in) :: d     !! damping coefficient [kg s^-1 m^-q]
        real(c_double), intent(in) :: m     !! effective mass [kg]
        real(c_double), intent(in) :: u     !! impact velocity [m/s]
        integer(c_int), intent(in) :: ilaw  !! damping law: 0 linear, 1 tsuji, 2 kuwabara-kono
        integer(c_int), intent(in) :: iend  !! contact end: 0 overlap, 1 force
        real(c_double), intent(out) :: e    !! restitution coefficient
        real(c_double), intent(out) :: tc   !! contact time [s]
        integer(c_int), intent(out) :: ierr !! 0 on success, 1 no rebound, else a status code
        call flat_forward_law(k, d, m, u, ilaw, iend, e, tc, ierr)
    end subroutine legacy_forward_law

end module hertzdamp_legacy

!> HERTZDAMP_MESSAGE(IERR, TEXT): the message of a status code, copied into text
!> (truncated or blank-padded).  An external subroutine (a character argument has no
!> binding label form): it uses hertzdamp_status only, which sees no IEEE module.
subroutine hertzdamp_message(ierr, text)
    use hertzdamp_status, only: mod_message => hertzdamp_message
    implicit none
    integer, intent(in) :: ierr               !! a status code
    character(len=*), intent(out) :: text     !! receives the message
    text = mod_message(ierr)
end subroutine hertzdamp_message
