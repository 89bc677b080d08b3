!> The per-pair API of the inverse problem (doc/theory.md section 6, issue 26), and the
!> one place where the stiffness k, the damping d, the time unit t* and the physical
!> stiffness bound of a contact are computed.
!>
!> A DEM host stores the constants of a material pair once (`hertzdamp_pair_init`: e, the
!> damping law, the contact end, the host's time integrator and the steps per contact)
!> and forms k and d at every contact onset from the contact's target time T_c, effective
!> mass m and impact speed u (`hertzdamp_pair_kd`).  With r = tau_c / T_c = 1/t*:
!>
!>     k = m r^2 (r/u)^(1/2),   d = alpha m r (r/u)^q     (q = 0, 1/4, 1/2 by the law),
!>
!> computed as r = tau_c (1/T_c), s = sqrt(tau_c (1/(T_c u))), k = m r^2 s and
!> d = alpha m r (linear), alpha m r sqrt(s) (tsuji), alpha m r s (kuwabara-kono) when
!> T_c, m and u lie in [1e-30, 1e30] (no power of them can overflow there), and by
!> logarithms (hertzdamp_scaling) elsewhere; a result outside double precision gives
!> HD_OUT_OF_RANGE.
!>
!> Physical bound: when the material's own stiffness k_phys <= k, the contact keeps
!> k = k_phys (it is then longer than T_c) with t* = (m/k_phys)^(2/5) u^(-1/5) and
!> d = alpha m t*^(-1) (u t*)^(-q) (tsuji: alpha sqrt(m k_phys)).  With a host scheme the
!> contact then lasts more than N steps: its dimensionless step h' = dt/t* is below the
!> h_N = tau_N/N the constants were solved for, and alpha_N over-corrects.  The host's
!> error in the phase-mean e is of order p in h (p = 1: lammps, mfix-euler, lammps-phase;
!> p = 2: mfix-ab2, verlet; doc/host-schemes.md), and the alpha that makes it exact goes
!> from alpha(e) at h = 0 to alpha_N at h_N like h^p, so
!>
!>     alpha_eff = alpha(e) + (alpha_N - alpha(e)) (h'/h_N)^p,   h'/h_N = (T_c/tau_N) / t*
!>
!> (dt = T_c/N).  Measured with hertzdamp_host_mean at h' = h_N/2, /4, /8 (e = 0.5, N = 20,
!> every host, law and end; test/unit/test_pair.f90 prints it): the mean achieved e within
!> 2.5e-3 of e, where alpha(e) misses by up to 1.1e-2 and alpha_N by up to 1.2e-2; summed
!> over that grid the error is 1/9 of alpha(e)'s and 1/25 of alpha_N's.  (The first-order
!> schemes' remainder is of order h_N h'.)  Host none keeps alpha (today's bits).
!>
!> `hertzdamp_invert` is the one-call form: the constants by any method
!> (hertzdamp_invert_alpha), then the same k, d and bound code, for one contact
!> (elemental) or rank-1 arrays (vectorised: the fit's kernel over the array, then the
!> loop of k and d here), with T_c and m also as scalars broadcast over the arrays.
!> Every entry point (module, C, legacy) runs this code: the same bits everywhere.
module hertzdamp_pair
    use, intrinsic :: iso_c_binding, only: c_double, c_int
    use, intrinsic :: iso_fortran_env, only: int64
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: hertzdamp_pair_size, hertzdamp_pair_oblique_size, hertzdamp_pair_phase_size
    use hertzdamp_registry, only: HD_OK, HD_BAD_TIME, HD_BAD_MASS, HD_BAD_VELOCITY, HD_BAD_KPHYS, HD_OUT_OF_RANGE, &
                                HD_BAD_PAIR, HD_BAD_ARGUMENT, HD_BAD_PHASE, HD_NO_PHASE_TABLE
    use hertzdamp_registry, only: HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO, hertzdamp_law_q, &
                                  hertzdamp_max_law
    use hertzdamp_constants, only: direct_lo => hertzdamp_direct_lo, direct_hi => hertzdamp_direct_hi
    use hertzdamp_scaling, only: hertzdamp_safe_exp, hertzdamp_log_tstar, hertzdamp_log_k, hertzdamp_scale_log_d
    use hertzdamp_registry, only: HD_METHOD_FIT
    use hertzdamp_fit, only: hertzdamp_fit_inverse, hertzdamp_fit_inverse_n, hertzdamp_fit_invert_kd_n
    use hertzdamp_inverse, only: hertzdamp_invert_alpha, hertzdamp_invert_options
    use hertzdamp_registry, only: HD_HOST_NONE, hertzdamp_host_order, hertzdamp_max_host
    use hertzdamp_host, only: hertzdamp_host_stats, hertzdamp_host_solve, hertzdamp_host_steps_min, &
                              hertzdamp_host_steps_max
    use hertzdamp_phase, only: hertzdamp_phase_build, hertzdamp_phase_table_ok, hertzdamp_phase_header, &
                               hertzdamp_phase_half_max
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> The constants of a material pair: hertzdamp_pair_size doubles, so that it is the C
    !> `hertzdamp_pair_t` and the legacy `REAL(8) PAIR(HERTZDAMP_PAIR_SIZE)` (the same memory).
    !> The header (the first eight) holds the mean-exact constants that hertzdamp_pair_kd
    !> reads; the oblique block and the onset-phase table follow, each with a marker of its
    !> own, and are read only by the per-contact forms that need them.  Set only by
    !> hertzdamp_pair_init; every per-contact call refuses (HD_BAD_PAIR) a pair that was not
    !> set, whose init failed, or of which a field it reads was changed since: the marker,
    !> a keyed hash of the seven header fields, no longer matches, or a field is out of range.
    type, bind(c), public :: hertzdamp_pair_t
        real(c_double) :: alpha = 0.0_c_double       !! alpha of the k, d formulas (a host: alpha_N)
        real(c_double) :: tau_c = 0.0_c_double       !! tau_c of the k, d formulas (a host: tau_N)
        real(c_double) :: alpha_cont = 0.0_c_double  !! alpha(e) of the continuous model (the bound's)
        real(c_double) :: steps = 0.0_c_double       !! steps per contact N (as given to init)
        real(c_double) :: law = 0.0_c_double         !! HD_DAMPING_* of the pair
        real(c_double) :: iend = 0.0_c_double        !! HD_END_* of the pair
        real(c_double) :: host = 0.0_c_double        !! HD_HOST_* of the pair
        real(c_double) :: marker = 0.0_c_double      !! validity marker, a keyed hash of the seven above
        !> the oblique-contact block (its own marker last; zero when not built)
        real(c_double) :: oblique(hertzdamp_pair_oblique_size) = 0.0_c_double
        !> the onset-phase table (its own markers; zero when not built)
        real(c_double) :: phase(hertzdamp_pair_phase_size) = 0.0_c_double
    end type hertzdamp_pair_t

    !> Contacts per pass of the array forms (buffers on the stack).
    integer, parameter :: chunk = 256

    ! The marker: a hash of the seven header fields' bit patterns x_i, linear over GF(2) and
    ! without integer arithmetic (nothing can overflow): each pattern xored with itself rotated
    ! by an amount of its own, the seven results xored, the top 12 bits
    ! folded onto the low ones, and those 52 bits put into the fraction of a number in [1, 2)
    ! (a finite double).  The rotations (tools/marker_rotations.py finds and checks them)
    ! were chosen so that the 448 bits of the seven
    ! fields map to 448 distinct patterns of at least two bits each: any one or two flipped
    ! bits of the header (the marker included) change the marker or break its match
    ! (test_pair flips every one and two bits of three pairs); a swap of two fields x, y
    ! changes it unless the bits in which they differ form a pattern that the difference of
    ! their rotations maps onto itself (test_pair swaps alpha and tau_c, law and host).  The
    ! amounts are public: the marker detects changes, not a forger who recomputes it, for
    ! which the range checks remain.  With the range checks of the fields the
    ! per-contact path reads (header_valid) about 40 integer operations, no branch and no
    ! multiplication, off the floating-point units that the k, d formulas use.
    ! (the amounts, field by field: alpha 51, tau_c 46, alpha_cont 24, steps 48, law 42,
    ! iend 21, host 35: written out in marker_of)
    integer(int64), parameter :: fraction_bits = int(z'000FFFFFFFFFFFFF', int64)
    !> The constant the onset-phase table's marker starts from (phase_marker_of).
    integer(int64), parameter :: phase_key = int(z'20B428DB', int64)
    !> The constants the markers of a table's half records and of its rest start from
    !> (half_marker_of, rest_marker_of).
    integer(int64), parameter :: half_key = int(z'5C3A91E7', int64), rest_key = int(z'6E1D47B3', int64)
    integer(int64), parameter :: one_bits = transfer(1.0_wp, 0_int64)
    !> Largest tau_c and alpha a valid pair holds (the range checks of the header).
    real(wp), parameter :: pair_tau_max = 1.0e4_wp, pair_alpha_max = 1.0e4_wp

    !> k and d of contacts from the constants of a pair: one contact (elemental) or rank-1
    !> arrays of T_c, m, u (vectorised), T_c and/or m also as scalars.
    interface hertzdamp_pair_kd
        module procedure pair_kd_one
        module procedure pair_kd_array
        module procedure pair_kd_array_tc
        module procedure pair_kd_array_m
        module procedure pair_kd_array_tc_m
    end interface hertzdamp_pair_kd

    !> k and d such that the collision has restitution e and contact time T_c: one
    !> contact (elemental: also arrays of any rank), or rank-1 arrays of e and u
    !> (vectorised) with T_c and m as arrays or scalars.
    interface hertzdamp_invert
        module procedure invert_one
        module procedure invert_array
        module procedure invert_array_tc
        module procedure invert_array_m
        module procedure invert_array_tc_m
    end interface hertzdamp_invert

    public :: hertzdamp_pair_init, hertzdamp_pair_kd, hertzdamp_invert, hertzdamp_pair_status
    public :: hertzdamp_pair_kd_phase, hertzdamp_pair_phase_status, hertzdamp_pair_phase_constants
    public :: hertzdamp_pair_size, hertzdamp_pair_oblique_size, hertzdamp_pair_phase_size
    ! the C entry of the per-contact call (see there; hertzdamp_capi re-exports it), and the
    ! one-contact inverse without optional arguments that the binding layer calls
    public :: hertzdamp_c_pair_kd, hertzdamp_c_pair_kd_phase, hertzdamp_invert_contact

contains

    ! ================================================================ the pair

    !> The constants of a material pair for restitution e, the damping law, the contact
    !> end and the host's time integrator at `steps` steps per contact.
    !> host = HD_HOST_NONE: alpha(e) and tau_c(alpha(e)) of the fit (the continuous model;
    !> steps is not used); another host: the host-exact constants (alpha_N, tau_N) of
    !> hertzdamp_host_solve, which make the phase-averaged e and contact time of the host's
    !> discrete collision exact at T_c = N dt.  The status names the bad argument (law,
    !> contact end, e, then host and steps), or HD_HOST_UNREACHABLE when the host cannot
    !> reach e at so few steps (hertzdamp_host_min_steps tells which N can); on failure the
    !> pair is invalid (hertzdamp_pair_kd returns HD_BAD_PAIR) and stats are zero.
    !> phase = .true.: also the onset-phase table (hertzdamp_phase_build: per-contact
    !> constants alpha(phi), tau(phi) that make each contact's e and contact time exact,
    !> read by hertzdamp_pair_kd_phase; the header stays the mean-exact constants, so that
    !> hertzdamp_pair_kd gives the same bits with or without it); HD_PHASE_UNREACHABLE when
    !> some onset phase has no such constants at this N (hertzdamp_phase_min_steps tells
    !> which N can).  Host none: an empty table (the continuous model has no phase).
    pure elemental subroutine hertzdamp_pair_init(e, law, iend, host, steps, pair, status, stats, phase)
        real(wp), intent(in) :: e                    !! target restitution coefficient
        integer, intent(in) :: law                   !! HD_DAMPING_*
        integer, intent(in) :: iend                  !! HD_END_OVERLAP or HD_END_FORCE
        integer, intent(in) :: host                  !! HD_HOST_*
        real(wp), intent(in) :: steps                !! steps per contact N = T_c / dt (not used by host none)
        type(hertzdamp_pair_t), intent(out) :: pair    !! the pair's constants
        integer, intent(out) :: status               !! HD_OK or an error code
        type(hertzdamp_host_stats), intent(out), optional :: stats !! the host's phase statistics of e and
                                                                   !! the contact time (host none: no spread)
        logical, intent(in), optional :: phase       !! also build the onset-phase table (default .false.)
        type(hertzdamp_host_stats) :: st
        real(wp) :: a, tau, a_cont, tau_cont, tab(hertzdamp_pair_phase_size)
        logical :: want
        call hertzdamp_fit_inverse(e, iend, a_cont, tau_cont, status, law)
        a = a_cont
        tau = tau_cont
        if (status == HD_OK) then
            if (host == HD_HOST_NONE) then
                st = hertzdamp_host_stats(e, 0.0_wp, e, e, tau, 0.0_wp, tau, tau)
            else
                call hertzdamp_host_solve(e, law, iend, host, steps, a, tau, st, status)
            end if
        end if
        want = .false.
        if (present(phase)) want = phase
        if (status == HD_OK .and. want) call hertzdamp_phase_build(e, law, iend, host, steps, a, tau, tab, status)
        if (status == HD_OK) then
            call set_pair(a, tau, a_cont, steps, law, iend, host, pair)
            if (want) then
                pair%phase = tab
                call set_phase_markers(pair)
            end if
        else
            st = hertzdamp_host_stats()
        end if
        if (present(stats)) stats = st
    end subroutine hertzdamp_pair_init

    !> The markers of a pair's onset-phase table (layout: hertzdamp_phase): the table's
    !> (entry 1, phase_marker_of), then each half's record's (half_marker_of) and the rest's
    !> (entry 3, rest_marker_of), which hash the table's marker too.
    pure subroutine set_phase_markers(pair)
        type(hertzdamp_pair_t), intent(inout) :: pair
        integer :: hb
        pair%phase(1) = transfer(phase_marker_of(pair), 1.0_wp)
        if (pair%phase(2) == 4.0_wp) then
            do hb = 11, 29, 6
                pair%phase(hb + 5) = transfer(half_marker_of(pair, hb), 1.0_wp)
            end do
        end if
        pair%phase(3) = transfer(rest_marker_of(pair), 1.0_wp)
    end subroutine set_phase_markers

    !> The marker of a pair's onset-phase table (bit pattern; hertzdamp_phase_marker.inc: the
    !> header's marker, the law and the table's entries 2, 4, 5, 6, each rotated by its own
    !> amount, xor-ed with a key and each other, folded to the fraction of a number in
    !> [1, 2)).  Any change of one entry changes it.  No multiplication (no integer overflow)
    !> and no dependent chain.
    pure integer(int64) function phase_marker_of(pair) result(bits)
        type(hertzdamp_pair_t), intent(in) :: pair
        integer(int64) :: phase_bits
        include 'hertzdamp_phase_marker.inc'
        bits = phase_bits
    end function phase_marker_of

    !> The marker of the record of one half (its first index hb: 11, 17, 23, 29) of a pair's
    !> onset-phase table (hertzdamp_phase_half_marker.inc: the table's marker, the record's
    !> five entries and hb).
    pure integer(int64) function half_marker_of(pair, hb) result(bits)
        type(hertzdamp_pair_t), intent(in) :: pair
        integer, intent(in) :: hb
        integer(int64) :: half_bits
        include 'hertzdamp_phase_half_marker.inc'
        bits = half_bits
    end function half_marker_of

    !> The marker of the table's entries that no per-contact path reads (7 .. 10: N, the
    !> root, phi_b, N_1) and of the table's marker: checked by hertzdamp_pair_phase_status.
    pure integer(int64) function rest_marker_of(pair) result(bits)
        type(hertzdamp_pair_t), intent(in) :: pair
        integer(int64) :: h
        h = ieor(ieor(ieor(bits_of(pair%phase(1)), rest_key), ishftc(bits_of(pair%phase(7)), 11)), &
                 ieor(ieor(ishftc(bits_of(pair%phase(8)), 22), ishftc(bits_of(pair%phase(9)), 33)), &
                      ishftc(bits_of(pair%phase(10)), 44)))
        h = ieor(h, shiftr(h, 29))
        bits = ior(iand(ieor(h, shiftr(h, 52)), fraction_bits), one_bits)
    end function rest_marker_of

    ! phase_eval: the per-contact lookup of the table, one text for this module (inlined into
    ! the entry points) and hertzdamp_phase (the check of the table at init)
    include 'hertzdamp_phase_eval.inc'

    !> The status of a pair's onset-phase table: HD_BAD_PAIR when the header is not valid
    !> (hertzdamp_pair_status) or the table's marker does not match; HD_NO_PHASE_TABLE when
    !> the pair was initialised without it (its marker 0); else HD_OK.
    pure elemental integer function hertzdamp_pair_phase_status(pair) result(status)
        type(hertzdamp_pair_t), intent(in) :: pair   !! constants of the material pair
        integer :: hb
        status = hertzdamp_pair_status(pair)
        if (status /= HD_OK) return
        if (pair%phase(1) == 0.0_wp) then
            status = HD_NO_PHASE_TABLE
        else if (ieor(bits_of(pair%phase(1)), phase_marker_of(pair)) /= 0_int64 .or. &
                 ieor(bits_of(pair%phase(3)), rest_marker_of(pair)) /= 0_int64 .or. &
                 .not. hertzdamp_phase_table_ok(pair%phase)) then
            status = HD_BAD_PAIR
        else if (pair%phase(2) == 4.0_wp) then
            do hb = 11, 29, 6
                if (ieor(bits_of(pair%phase(hb + 5)), half_marker_of(pair, hb)) /= 0_int64) status = HD_BAD_PAIR
            end do
        end if
    end function hertzdamp_pair_phase_status

    !> The per-contact constants of onset phase phi from a pair's table: alpha(phi) and
    !> tau(phi) (host none: the pair's own alpha and tau_c).  Status as
    !> hertzdamp_pair_phase_status, then HD_BAD_PHASE (phi not in (0, 1]); 0 on failure.
    pure elemental subroutine hertzdamp_pair_phase_constants(pair, phi, alpha, tau_c, status)
        type(hertzdamp_pair_t), intent(in) :: pair   !! constants of the material pair (with its table)
        real(wp), intent(in) :: phi                  !! onset phase in (0, 1] (hertzdamp_onset_phase)
        real(wp), intent(out) :: alpha               !! alpha(phi)
        real(wp), intent(out) :: tau_c               !! tau(phi): t* = T_c / tau(phi)
        integer, intent(out) :: status               !! HD_OK or the failure
        alpha = 0.0_wp
        tau_c = 0.0_wp
        status = hertzdamp_pair_phase_status(pair)
        if (status == HD_OK .and. .not. (phi > 0.0_wp .and. phi <= 1.0_wp)) status = HD_BAD_PHASE
        if (status /= HD_OK) return
        if (pair%phase(2) == 0.0_wp) then
            alpha = pair%alpha
            tau_c = pair%tau_c
        else
            call phase_eval(pair%phase, int(pair%law), phi, alpha, tau_c)
            ! the node values are not hashed: constants outside the header's ranges (tau_c in
            ! (0, 1e4], |alpha| <= 1e4; NaN included) come only from a changed table
            if (.not. (tau_c > 0.0_wp .and. tau_c <= pair_tau_max .and. abs(alpha) <= pair_alpha_max)) then
                alpha = 0.0_wp
                tau_c = 0.0_wp
                status = HD_BAD_PAIR
            end if
        end if
    end subroutine hertzdamp_pair_phase_constants

    !> k and d of one contact with onset phase phi (hertzdamp_onset_phase) from the pair's
    !> onset-phase table (hertzdamp_pair_init with phase = .true.): the formulas of
    !> hertzdamp_pair_kd with alpha(phi) and tau(phi) in place of the mean-exact alpha_N,
    !> tau_N, so that this contact's e and contact time in the host are the targets.
    !> k_phys > 0: the physical stiffness bound (<= 0: none); where k_phys <= k the contact
    !> keeps k = k_phys and lasts longer than N steps, and d takes alpha_eff = alpha(e) +
    !> (alpha(phi) - alpha(e)) (h'/h_phi)^p as hertzdamp_pair_kd does (continuous at
    !> k_phys = k; the phase's share fades with the step ratio as the host's error does).
    !> (The usual contact forms k = K(phi) m T_c^(-5/2) u^(-1/2), d = A(phi) m T_c^(-1-q) u^(-q)
    !> from the table's K = tau^(5/2), A = alpha tau^(1+q): the same values to rounding.)
    !> Status: the bad argument of T_c, m, u, k_phys (the last one wins), else that of
    !> hertzdamp_pair_phase_constants; k = d = 0 on failure.  The usual contact checks the
    !> fields it reads (hertzdamp_phase_fast.inc); every other one the full
    !> hertzdamp_pair_phase_status.
    pure elemental subroutine hertzdamp_pair_kd_phase(pair, tc, m, u, k_phys, phi, k, d, status)
        type(hertzdamp_pair_t), intent(in) :: pair   !! constants of the material pair (with its table)
        real(wp), intent(in) :: tc                   !! target contact time T_c = N dt [s]
        real(wp), intent(in) :: m                    !! effective mass [kg]
        real(wp), intent(in) :: u                    !! impact velocity [m s^-1]
        real(wp), intent(in) :: k_phys               !! physical stiffness bound [N m^-3/2]; <= 0: none
        real(wp), intent(in) :: phi                  !! onset phase in (0, 1]
        real(wp), intent(out) :: k                   !! Hertz stiffness [N m^-3/2]
        real(wp), intent(out) :: d                   !! damping coefficient [kg s^-1 m^-q]
        integer, intent(out) :: status               !! HD_OK or an error code
        real(wp) :: k_, d_
        logical :: ok
        ! the usual contact inline (hertzdamp_phase_fast.inc), every other one out of line
        include 'hertzdamp_phase_fast.inc'
        if (ok) then
            k = k_
            d = d_
            status = HD_OK
        else
            call kd_phase_rest(pair, tc, m, u, k_phys, phi, k, d, status)
        end if
    end subroutine hertzdamp_pair_kd_phase

    !> hertzdamp_pair_kd_phase for every contact: the statuses, the bound, the logarithmic path.
    pure subroutine kd_phase_rest(pair, tc, m, u, k_phys, phi, k, d, status)
        type(hertzdamp_pair_t), intent(in) :: pair
        real(wp), value :: tc, m, u, k_phys, phi
        real(wp), intent(out) :: k, d
        integer, intent(out) :: status
        real(wp) :: a, tau, ts
        integer :: given, law, host
        logical :: bound
        call hertzdamp_pair_phase_constants(pair, phi, a, tau, given)
        law = HD_DAMPING_LINEAR
        host = HD_HOST_NONE
        if (given == HD_OK) then
            law = int(pair%law)
            host = int(pair%host)
        end if
        call contact_rest(a, tau, pair%alpha_cont, law, host, given, tc, m, u, .not. (k_phys <= 0.0_wp), k_phys, &
                          .false., k, d, ts, bound, status)
    end subroutine kd_phase_rest

    !> `int hertzdamp_c_pair_kd_phase(const hertzdamp_pair_t *p, double tc, double m,
    !> double u, double k_phys, double phi, double *k, double *d)`: k and d of one contact
    !> with onset phase phi (hertzdamp_pair_kd_phase); k_phys <= 0: no bound.  A pair without
    !> its table gives HD_NO_PHASE_TABLE, phi outside (0, 1] HD_BAD_PHASE, NULL
    !> HD_BAD_ARGUMENT; on failure *k = *d = 0.  Defined here, as hertzdamp_c_pair_kd, so that
    !> the table and k, d code inline into it (hertzdamp_capi re-exports it).
    integer(c_int) function hertzdamp_c_pair_kd_phase(p, tc, m, u, k_phys, phi, k, d) &
            bind(c, name='hertzdamp_c_pair_kd_phase') result(status)
        type(hertzdamp_pair_t), intent(in), optional :: p !! the pair (hertzdamp_c_pair_init_phase)
        real(c_double), value, intent(in) :: tc         !! target contact time N dt [s]
        real(c_double), value, intent(in) :: m          !! effective mass [kg]
        real(c_double), value, intent(in) :: u          !! impact velocity [m/s]
        real(c_double), value, intent(in) :: k_phys     !! physical stiffness bound [N m^-3/2], <= 0 for none
        real(c_double), value, intent(in) :: phi        !! onset phase in (0, 1]
        real(c_double), intent(out), optional :: k      !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(out), optional :: d      !! damping coefficient [kg s^-1 m^-q]
        real(wp) :: k_, d_
        integer :: st
        logical :: ok
        status = HD_BAD_ARGUMENT
        if (.not. (present(p) .and. present(k) .and. present(d))) return
        ! the usual contact inline, straight-line (hertzdamp_phase_fast.inc: no call on its
        ! way), every other one out of line (kd_phase_rest: the statuses, the bound, the logarithms)
        associate (pair => p)
            include 'hertzdamp_phase_fast.inc'
        end associate
        if (ok) then
            k = k_
            d = d_
            status = HD_OK
            return
        end if
        call kd_phase_rest(p, tc, m, u, k_phys, phi, k_, d_, st)
        k = k_
        d = d_
        status = int(st, c_int)
    end function hertzdamp_c_pair_kd_phase

    !> A valid pair of the given constants (the caller has checked them).  steps is kept
    !> when it is a valid N (host none does not use it, but hertzdamp_c_pair_stats runs the
    !> pair at its N), else 0.
    pure subroutine set_pair(a, tau, a_cont, steps, law, iend, host, pair)
        real(wp), intent(in) :: a, tau, a_cont, steps
        integer, intent(in) :: law, iend, host
        type(hertzdamp_pair_t), intent(out) :: pair
        real(wp) :: n
        n = 0.0_wp
        if (steps >= hertzdamp_host_steps_min .and. steps <= hertzdamp_host_steps_max) n = steps
        pair = hertzdamp_pair_t(alpha=a, tau_c=tau, alpha_cont=a_cont, steps=n, law=real(law, wp), &
                                iend=real(iend, wp), host=real(host, wp))
        pair%marker = transfer(marker_of(pair), 1.0_wp)
    end subroutine set_pair

    !> The marker that a valid pair with these seven header fields carries (bit pattern).
    pure integer(int64) function marker_of(pair) result(bits)
        type(hertzdamp_pair_t), intent(in) :: pair
        integer(int64) :: marker_bits
        include 'hertzdamp_pair_marker.inc'
        bits = marker_bits
    end function marker_of

    !> The bit pattern of a double.
    pure elemental integer(int64) function bits_of(x)
        real(c_double), intent(in) :: x
        bits_of = transfer(x, 0_int64)
    end function bits_of

    !> hi's bit pattern minus x's: negative when x > hi (NaN and infinities included), for
    !> x >= 0 (bit patterns order non-negative doubles as their values).
    pure elemental integer(int64) function above(x, hi)
        real(c_double), intent(in) :: x, hi
        above = transfer(hi, 0_int64) - transfer(x, 0_int64)
    end function above

    !> Whether the header of a pair is valid: its marker matches (no field changed) and every
    !> field is in range (law, end and host valid codes; alpha and alpha(e) in [0, 1e4]; tau_c
    !> in (0, 1e4]; steps in [0, 1e5]).  The check of every per-contact call, in integer
    !> arithmetic on the bit patterns, without a branch: the sign bit of their or is set when
    !> a field is negative, that of a difference `above` when it exceeds its bound.
    pure logical function header_valid(pair) result(ok)
        type(hertzdamp_pair_t), intent(in) :: pair
        logical :: header_ok
        include 'hertzdamp_pair_header.inc'
        ok = header_ok
    end function header_valid

    !> HD_OK for a pair set by hertzdamp_pair_init whose header was not changed since (the
    !> marker matches and every field is in range, header_valid), else HD_BAD_PAIR.
    pure elemental integer function hertzdamp_pair_status(pair) result(status)
        type(hertzdamp_pair_t), intent(in) :: pair
        status = merge(HD_OK, HD_BAD_PAIR, header_valid(pair))
    end function hertzdamp_pair_status

    ! ================================================================ k, d of one contact

    !> k and d of one contact from the constants of its pair (see the module note).
    !> A host-exact pair's constants hold only for tc = N dt, with N the pair's steps and dt
    !> the step the host integrates this contact with (a host that changes dt initialises
    !> the pair again).  The status names the bad argument (checked in this order, the last one wins: T_c,
    !> m, u, k_phys) or HD_BAD_PAIR; on failure k = d = 0 (tstar = 0, bound_active false).
    pure elemental subroutine pair_kd_one(pair, tc, m, u, k, d, status, k_phys, bound_active, tstar)
        type(hertzdamp_pair_t), intent(in) :: pair          !! constants of the material pair
        real(wp), intent(in) :: tc                        !! target contact time T_c = N dt [s]
        real(wp), intent(in) :: m                         !! effective mass [kg]
        real(wp), intent(in) :: u                         !! impact velocity [m s^-1]
        real(wp), intent(out) :: k                        !! Hertz stiffness [N m^-3/2]
        real(wp), intent(out) :: d                        !! damping coefficient [kg s^-1 m^-q]
        integer, intent(out) :: status                    !! HD_OK or an error code
        real(wp), intent(in), optional :: k_phys          !! physical stiffness bound [N m^-3/2]: finite, > 0
        logical, intent(out), optional :: bound_active    !! true when k = k_phys was used
        real(wp), intent(out), optional :: tstar          !! time unit of the returned k [s]
        real(wp) :: kp, ts
        logical :: bound
        integer :: valid, law, host
        valid = hertzdamp_pair_status(pair)
        law = HD_DAMPING_LINEAR
        host = HD_HOST_NONE
        if (valid == HD_OK) then
            law = int(pair%law)
            host = int(pair%host)
        end if
        kp = 0.0_wp
        if (present(k_phys)) kp = k_phys
        call contact_kd(pair%alpha, pair%tau_c, pair%alpha_cont, law, host, valid, tc, m, u, present(k_phys), kp, &
                        present(tstar), k, d, ts, bound, status)
        if (present(bound_active)) bound_active = bound
        if (present(tstar)) tstar = ts
    end subroutine pair_kd_one

    !> `int hertzdamp_c_pair_kd(const hertzdamp_pair_t *p, double tc, double m, double u,
    !> double k_phys, double *k, double *d)`: k and d of one contact (hertzdamp_pair_kd);
    !> k_phys <= 0: no bound.  On failure *k = *d = 0; NULL gives HD_BAD_ARGUMENT.
    !> Part of the binding layer (hertzdamp_capi re-exports it), but defined here: the
    !> per-contact call of a DEM host, where the k, d code must inline into the entry point
    !> itself (a call from another module costs about half the bare formula again).
    integer(c_int) function hertzdamp_c_pair_kd(p, tc, m, u, k_phys, k, d) &
            bind(c, name='hertzdamp_c_pair_kd') result(status)
        type(hertzdamp_pair_t), intent(in), optional :: p !! the pair's constants (hertzdamp_c_pair_init)
        real(c_double), value, intent(in) :: tc         !! target contact time N dt [s]
        real(c_double), value, intent(in) :: m          !! effective mass [kg]
        real(c_double), value, intent(in) :: u          !! impact velocity [m/s]
        real(c_double), value, intent(in) :: k_phys     !! physical stiffness bound [N m^-3/2], <= 0 for none
        real(c_double), intent(out), optional :: k      !! Hertz stiffness [N m^-3/2]
        real(c_double), intent(out), optional :: d      !! damping coefficient [kg s^-1 m^-q]
        real(wp) :: k_, d_
        status = HD_BAD_ARGUMENT
        if (.not. (present(p) .and. present(k) .and. present(d))) return
        ! the usual contact (a valid pair, T_c, m, u in the direct range, no bound met) here,
        ! every other one out of line: the entry point keeps no stack frame for the rest
        if (header_valid(p) .and. direct(tc, m, u)) then
            call direct_kd(int(p%law), p%alpha, p%tau_c, tc, m, u, k_, d_)
            if (k_phys <= 0.0_wp .or. (k_phys <= huge(k_phys) .and. k_phys > k_)) then
                k = k_
                d = d_
                status = HD_OK
                return
            end if
        end if
        status = int(c_pair_kd_rest(p, tc, m, u, k_phys, k, d), c_int)
    end function hertzdamp_c_pair_kd

    !> hertzdamp_c_pair_kd for every contact (contact_kd), out of line.
    integer function c_pair_kd_rest(p, tc, m, u, k_phys, k, d) result(status)
        type(hertzdamp_pair_t), intent(in) :: p
        real(wp), value :: tc, m, u, k_phys
        real(wp), intent(out) :: k, d
        real(wp) :: ts
        integer :: valid, law, host
        logical :: bound
        valid = hertzdamp_pair_status(p)
        law = HD_DAMPING_LINEAR
        host = HD_HOST_NONE
        if (valid == HD_OK) then
            law = int(p%law)
            host = int(p%host)
        end if
        call contact_kd(p%alpha, p%tau_c, p%alpha_cont, law, host, valid, tc, m, u, .not. (k_phys <= 0.0_wp), &
                        k_phys, .false., k, d, ts, bound, status)
    end function c_pair_kd_rest

    !> Whether T_c, m and u all lie in the direct range [1e-30, 1e30] (the usual contact).
    pure logical function direct(tc, m, u)
        real(wp), intent(in) :: tc, m, u
        direct = tc >= direct_lo .and. tc <= direct_hi .and. m >= direct_lo .and. m <= direct_hi .and. &
                 u >= direct_lo .and. u <= direct_hi
    end function direct

    !> The status of the arguments of one contact: HD_OK or the last bad one of T_c, m, u,
    !> k_phys (when has_kp).
    pure elemental integer function argument_status(tc, m, u, has_kp, kp) result(status)
        real(wp), intent(in) :: tc, m, u, kp
        logical, intent(in) :: has_kp
        status = HD_OK
        if (.not. (tc > 0.0_wp .and. tc <= huge(tc))) status = HD_BAD_TIME
        if (.not. (m > 0.0_wp .and. m <= huge(m))) status = HD_BAD_MASS
        if (.not. (u > 0.0_wp .and. u <= huge(u))) status = HD_BAD_VELOCITY
        if (has_kp) then
            if (.not. (kp > 0.0_wp .and. kp <= huge(kp))) status = HD_BAD_KPHYS
        end if
    end function argument_status

    !> k and d of one contact from the constants (a, tau, a_cont) of its pair: every entry
    !> point ends here.  `given` is the status of the constants (HD_OK, or why there are
    !> none: it is reported when the arguments of the contact are valid).  The usual
    !> contact (constants, T_c, m, u in the direct range, no bound met) takes the few lines
    !> below; every other one contact_rest, which gives the same bits for the usual one.
    pure elemental subroutine contact_kd(a, tau, a_cont, law, host, given, tc, m, u, has_kp, kp, want_ts, k, d, ts, &
                                         bound, status)
        real(wp), intent(in) :: a, tau, a_cont   ! alpha, tau_c, continuous alpha(e)
        integer, intent(in) :: law, host, given
        real(wp), intent(in) :: tc, m, u, kp
        logical, intent(in) :: has_kp, want_ts   ! a bound is given; t* is wanted
        real(wp), intent(out) :: k, d, ts
        logical, intent(out) :: bound
        integer, intent(out) :: status
        if (given == HD_OK .and. direct(tc, m, u)) then
            call direct_kd(law, a, tau, tc, m, u, k, d)
            ts = 0.0_wp
            if (want_ts) ts = tc / tau
            bound = .false.
            status = HD_OK
            if (.not. has_kp) return
            if (kp > 0.0_wp .and. kp <= huge(kp) .and. kp > k) return
        end if
        call contact_rest(a, tau, a_cont, law, host, given, tc, m, u, has_kp, kp, want_ts, k, d, ts, bound, status)
    end subroutine contact_kd

    !> contact_kd for every contact: the argument checks, the bound, the logarithmic path.
    !> (Called from two places, so that the compiler keeps it out of line and contact_kd,
    !> the usual contact's few lines, inlines into every entry point.)
    pure subroutine contact_rest(a, tau, a_cont, law, host, given, tc, m, u, has_kp, kp, want_ts, k, d, ts, bound, &
                                 status)
        real(wp), value :: a, tau, a_cont
        integer, value :: law, host, given
        real(wp), value :: tc, m, u, kp
        logical, value :: has_kp, want_ts
        real(wp), intent(out) :: k, d, ts
        logical, intent(out) :: bound
        integer, intent(out) :: status
        k = 0.0_wp
        d = 0.0_wp
        ts = 0.0_wp
        bound = .false.
        if (direct(tc, m, u)) then
            status = HD_OK
            if (has_kp) then
                if (.not. (kp > 0.0_wp .and. kp <= huge(kp))) status = HD_BAD_KPHYS
            end if
            if (status == HD_OK) status = given
            if (status /= HD_OK) return
            call direct_kd(law, a, tau, tc, m, u, k, d)
            if (want_ts) ts = tc / tau
            if (has_kp) then
                if (kp <= k) call bound_direct(a, tau, a_cont, law, host, tc, m, u, kp, want_ts, k, d, ts, bound, &
                                               status)
            end if
        else
            status = argument_status(tc, m, u, has_kp, kp)
            if (status == HD_OK) status = given
            if (status /= HD_OK) return
            call log_kd(a, tau, a_cont, law, host, tc, m, u, has_kp, kp, k, d, ts, bound, status)
        end if
        if (status /= HD_OK) then
            k = 0.0_wp
            d = 0.0_wp
            ts = 0.0_wp
            bound = .false.
        end if
    end subroutine contact_rest

    ! the direct k, d formulas and the masks of the array forms (also included by the
    ! fused kernels of hertzdamp_fit_kernels)
    include 'hertzdamp_kd_formula.inc'

    !> The bound on the direct path (k_phys <= k): k = k_phys, t* = (m/k_phys)^(2/5) u^(-1/5),
    !> d = alpha_eff m t*^(-1) (u t*)^(-q) (tsuji: alpha_eff sqrt(m k_phys), which needs no t*
    !> for host none: t* only when wanted).  alpha_eff: see the module note.
    pure subroutine bound_direct(a, tau, a_cont, law, host, tc, m, u, kp, want_ts, k, d, ts, bound, status)
        real(wp), intent(in) :: a, tau, a_cont, tc, m, u, kp
        integer, intent(in) :: law, host
        logical, intent(in) :: want_ts
        real(wp), intent(inout) :: k, d, ts
        logical, intent(out) :: bound
        integer, intent(inout) :: status
        real(wp) :: ae
        bound = .true.
        k = kp
        ae = a
        if (want_ts .or. law /= HD_DAMPING_TSUJI .or. host /= HD_HOST_NONE) then
            call hertzdamp_safe_exp(hertzdamp_log_tstar(log(m), log(kp), log(u), .true.), ts, status)
            if (host /= HD_HOST_NONE) ae = interpolated_alpha(a, a_cont, host, (tc / tau) / ts)
        end if
        if (law == HD_DAMPING_TSUJI) then
            d = ae * (sqrt(m) * sqrt(kp))
        else if (law == HD_DAMPING_LINEAR) then
            d = ae * m / ts
        else
            d = ae * m / ts / sqrt(u * ts)
        end if
    end subroutine bound_direct

    !> alpha for a contact of a host whose step is the fraction ratio = h'/h_N <= 1 of the
    !> step the pair's constants were solved for: alpha(e) + (alpha_N - alpha(e)) ratio^p,
    !> p the order of the host's error (see the module note).
    pure real(wp) function interpolated_alpha(a, a_cont, host, ratio) result(ae)
        real(wp), intent(in) :: a, a_cont, ratio
        integer, intent(in) :: host
        ae = a_cont + (a - a_cont) * ratio**hertzdamp_host_order(host)
    end function interpolated_alpha

    !> k and d by logarithms (T_c, m or u outside the direct range), with the bound.
    pure subroutine log_kd(a, tau, a_cont, law, host, tc, m, u, has_kp, kp, k, d, ts, bound, status)
        real(wp), intent(in) :: a, tau, a_cont, tc, m, u, kp
        integer, intent(in) :: law, host
        logical, intent(in) :: has_kp
        real(wp), intent(out) :: k, d, ts
        logical, intent(out) :: bound
        integer, intent(inout) :: status
        real(wp) :: lm, lu, lts, ltsn, ae
        lm = log(m)
        lu = log(u)
        ltsn = log(tc) - log(tau)     ! ln t* of the target T_c
        lts = ltsn
        bound = .false.
        if (has_kp) bound = log(kp) <= hertzdamp_log_k(ltsn, lm, lu)
        if (bound) lts = hertzdamp_log_tstar(lm, log(kp), lu, .true.)
        call hertzdamp_safe_exp(lts, ts, status)
        if (bound) then
            k = kp            ! exactly the bound, as on the direct path (not exp(log(k_phys)))
        else
            call hertzdamp_safe_exp(hertzdamp_log_k(lts, lm, lu), k, status)
        end if
        ae = a
        if (bound .and. host /= HD_HOST_NONE) ae = interpolated_alpha(a, a_cont, host, exp(ltsn - lts))
        call hertzdamp_scale_log_d(lts, lm, lu, ae, hertzdamp_law_q(law), d, status)
        if (status == HD_OK) then
            if (.not. (abs(d) < huge(d))) status = HD_OUT_OF_RANGE
        end if
    end subroutine log_kd

    ! ================================================================ many contacts

    !> k and d of nc contacts (one pass of the array forms): the direct formulas run
    !> vectorised over every contact (inputs outside the direct range, or without
    !> constants, replaced by harmless ones and flagged); the flagged contacts, and those
    !> that meet the bound, then go one by one through contact_kd (the same bits as one
    !> call per contact).  No result may share memory with an input (the C layer copies
    !> overlapping inputs first).
    pure subroutine contacts_kd(nc, law, host, a, tau, a_cont, given, tc, m, u, has_kp, kp, want_ts, k, d, ts, &
                                bound, status)
        integer, intent(in) :: nc, law, host
        real(wp), intent(in) :: a(nc), tau(nc), a_cont(nc), tc(nc), m(nc), u(nc), kp(nc)
        integer, intent(in) :: given(nc)
        logical, intent(in) :: has_kp, want_ts
        real(wp), intent(out) :: k(nc), d(nc), ts(nc)
        logical, intent(out) :: bound(nc)
        integer, intent(out) :: status(nc)
        integer(int64) :: flags(chunk)
        integer :: j
        ! one loop per law (the law a constant in each: no branch in the loop body); the
        ! masks in integer arithmetic (an ordered floating-point comparison keeps a loop from
        ! vectorising under the default -ftrapping-math)
        select case (law)
        case (HD_DAMPING_LINEAR)
            do j = 1, nc
                flags(j) = direct_flags(given(j), tc(j), m(j), u(j))
                call direct_kd(HD_DAMPING_LINEAR, a(j), direct_harmless(tau(j), flags(j)), direct_harmless(tc(j), flags(j)), &
                               direct_harmless(m(j), flags(j)), direct_harmless(u(j), flags(j)), k(j), d(j))
            end do
        case (HD_DAMPING_TSUJI)
            do j = 1, nc
                flags(j) = direct_flags(given(j), tc(j), m(j), u(j))
                call direct_kd(HD_DAMPING_TSUJI, a(j), direct_harmless(tau(j), flags(j)), direct_harmless(tc(j), flags(j)), &
                               direct_harmless(m(j), flags(j)), direct_harmless(u(j), flags(j)), k(j), d(j))
            end do
        case default
            do j = 1, nc
                flags(j) = direct_flags(given(j), tc(j), m(j), u(j))
                call direct_kd(HD_DAMPING_KUWABARA_KONO, a(j), direct_harmless(tau(j), flags(j)), &
                               direct_harmless(tc(j), flags(j)), direct_harmless(m(j), flags(j)), &
                               direct_harmless(u(j), flags(j)), k(j), d(j))
            end do
        end select
        call contacts_rest(nc, law, host, a, tau, a_cont, given, tc, m, u, has_kp, kp, want_ts, k, d, ts, bound, &
                           status, flags)
    end subroutine contacts_kd

    !> The rest of contacts_kd after the direct formulas (k, d and flags of direct_flags and direct_kd,
    !> from contacts_kd or the fit's fused kernel): t* where wanted, the bound, and the
    !> flagged contacts one by one through contact_rest.
    pure subroutine contacts_rest(nc, law, host, a, tau, a_cont, given, tc, m, u, has_kp, kp, want_ts, k, d, ts, &
                                  bound, status, flags)
        integer, intent(in) :: nc, law, host
        real(wp), intent(in) :: a(nc), tau(nc), a_cont(nc), tc(nc), m(nc), u(nc), kp(nc)
        integer, intent(in) :: given(nc)
        logical, intent(in) :: has_kp, want_ts
        real(wp), intent(inout) :: k(nc), d(nc)
        real(wp), intent(out) :: ts(nc)
        logical, intent(out) :: bound(nc)
        integer, intent(out) :: status(nc)
        integer(int64), intent(inout) :: flags(nc)
        integer :: j
        if (want_ts) then
            do j = 1, nc
                ts(j) = direct_harmless(tc(j), flags(j)) / direct_harmless(tau(j), flags(j))
            end do
        end if
        if (has_kp) then
            do j = 1, nc
                if (.not. (kp(j) > 0.0_wp .and. kp(j) <= huge(kp(j)) .and. kp(j) > k(j))) flags(j) = -1_int64
            end do
        end if
        status = HD_OK
        bound = .false.
        if (any(flags(1:nc) < 0_int64)) then
            do j = 1, nc
                if (flags(j) < 0_int64) call contact_rest(a(j), tau(j), a_cont(j), law, host, given(j), tc(j), m(j), u(j), &
                                                    has_kp, kp(j), want_ts, k(j), d(j), ts(j), bound(j), status(j))
            end do
        end if
    end subroutine contacts_rest

    !> hertzdamp_pair_kd over arrays (the core of the array forms: passes of `chunk`
    !> contacts); tc and m hold one value per contact, or `chunk` copies of one value (a
    !> broadcast, see start).
    pure subroutine pair_kd_n(pair, tc, m, u, k, d, status, k_phys, bound_active, tstar)
        type(hertzdamp_pair_t), intent(in) :: pair
        real(wp), intent(in) :: tc(:), m(:), u(:)
        real(wp), intent(out) :: k(:), d(:)
        integer, intent(out) :: status(:)
        real(wp), intent(in), optional :: k_phys(:)
        logical, intent(out), optional :: bound_active(:)
        real(wp), intent(out), optional :: tstar(:)
        real(wp) :: ab(chunk), tb(chunk), acb(chunk), kpb(chunk), tsb(chunk)
        integer :: gb(chunk)
        logical :: bb(chunk)
        integer :: i0, nc, valid, law, host, n, jt, jm
        n = size(u)
        valid = hertzdamp_pair_status(pair)
        law = HD_DAMPING_LINEAR
        host = HD_HOST_NONE
        if (valid == HD_OK) then
            law = int(pair%law)
            host = int(pair%host)
        end if
        ab = pair%alpha
        tb = pair%tau_c
        acb = pair%alpha_cont
        gb = valid
        kpb = 0.0_wp
        do i0 = 0, n - 1, chunk
            nc = min(chunk, n - i0)
            jt = start(tc, n, i0)
            jm = start(m, n, i0)
            if (present(k_phys)) kpb(1:nc) = k_phys(i0 + 1:i0 + nc)
            call contacts_kd(nc, law, host, ab, tb, acb, gb, tc(jt + 1:jt + nc), m(jm + 1:jm + nc), u(i0 + 1:i0 + nc), &
                             present(k_phys), kpb, present(tstar), k(i0 + 1:i0 + nc), d(i0 + 1:i0 + nc), tsb, bb, &
                             status(i0 + 1:i0 + nc))
            if (present(bound_active)) bound_active(i0 + 1:i0 + nc) = bb(1:nc)
            if (present(tstar)) tstar(i0 + 1:i0 + nc) = tsb(1:nc)
        end do
    end subroutine pair_kd_n

    !> Where the values of the pass from contact i0 + 1 start in x: x holds one value per
    !> contact (size n), or `chunk` copies of one value (a broadcast: every pass reads the
    !> first nc, no copy per pass).
    pure integer function start(x, n, i0)
        real(wp), intent(in) :: x(:)
        integer, intent(in) :: n, i0
        start = merge(i0, 0, size(x) == n)
    end function start

    !> hertzdamp_pair_kd for rank-1 arrays of T_c, m, u (all of the size of u).
    pure subroutine pair_kd_array(pair, tc, m, u, k, d, status, k_phys, bound_active, tstar)
        type(hertzdamp_pair_t), intent(in) :: pair                        !! constants of the material pair
        real(wp), intent(in), contiguous :: tc(:)                       !! target contact times [s]
        real(wp), intent(in), contiguous :: m(:)                        !! effective masses [kg]
        real(wp), intent(in), contiguous :: u(:)                        !! impact velocities [m s^-1]
        real(wp), intent(out), contiguous :: k(:)                       !! Hertz stiffnesses [N m^-3/2]
        real(wp), intent(out), contiguous :: d(:)                       !! damping coefficients [kg s^-1 m^-q]
        integer, intent(out), contiguous :: status(:)                   !! HD_OK or an error code, per contact
        real(wp), intent(in), optional, contiguous :: k_phys(:)         !! physical stiffness bounds [N m^-3/2]
        logical, intent(out), optional, contiguous :: bound_active(:)   !! true where k = k_phys was used
        real(wp), intent(out), optional, contiguous :: tstar(:)         !! time units of the returned k [s]
        call pair_kd_n(pair, tc, m, u, k, d, status, k_phys, bound_active, tstar)
    end subroutine pair_kd_array

    !> hertzdamp_pair_kd for one T_c and rank-1 arrays of m, u.
    pure subroutine pair_kd_array_tc(pair, tc, m, u, k, d, status, k_phys, bound_active, tstar)
        type(hertzdamp_pair_t), intent(in) :: pair                        !! constants of the material pair
        real(wp), intent(in) :: tc                                      !! target contact time of every contact [s]
        real(wp), intent(in), contiguous :: m(:)                        !! effective masses [kg]
        real(wp), intent(in), contiguous :: u(:)                        !! impact velocities [m s^-1]
        real(wp), intent(out), contiguous :: k(:)                       !! Hertz stiffnesses [N m^-3/2]
        real(wp), intent(out), contiguous :: d(:)                       !! damping coefficients [kg s^-1 m^-q]
        integer, intent(out), contiguous :: status(:)                   !! HD_OK or an error code, per contact
        real(wp), intent(in), optional, contiguous :: k_phys(:)         !! physical stiffness bounds [N m^-3/2]
        logical, intent(out), optional, contiguous :: bound_active(:)   !! true where k = k_phys was used
        real(wp), intent(out), optional, contiguous :: tstar(:)         !! time units of the returned k [s]
        call pair_kd_n(pair, spread(tc, 1, chunk), m, u, k, d, status, k_phys, bound_active, tstar)
    end subroutine pair_kd_array_tc

    !> hertzdamp_pair_kd for one m and rank-1 arrays of T_c, u.
    pure subroutine pair_kd_array_m(pair, tc, m, u, k, d, status, k_phys, bound_active, tstar)
        type(hertzdamp_pair_t), intent(in) :: pair                        !! constants of the material pair
        real(wp), intent(in), contiguous :: tc(:)                       !! target contact times [s]
        real(wp), intent(in) :: m                                       !! effective mass of every contact [kg]
        real(wp), intent(in), contiguous :: u(:)                        !! impact velocities [m s^-1]
        real(wp), intent(out), contiguous :: k(:)                       !! Hertz stiffnesses [N m^-3/2]
        real(wp), intent(out), contiguous :: d(:)                       !! damping coefficients [kg s^-1 m^-q]
        integer, intent(out), contiguous :: status(:)                   !! HD_OK or an error code, per contact
        real(wp), intent(in), optional, contiguous :: k_phys(:)         !! physical stiffness bounds [N m^-3/2]
        logical, intent(out), optional, contiguous :: bound_active(:)   !! true where k = k_phys was used
        real(wp), intent(out), optional, contiguous :: tstar(:)         !! time units of the returned k [s]
        call pair_kd_n(pair, tc, spread(m, 1, chunk), u, k, d, status, k_phys, bound_active, tstar)
    end subroutine pair_kd_array_m

    !> hertzdamp_pair_kd for one T_c and one m, and a rank-1 array of u.
    pure subroutine pair_kd_array_tc_m(pair, tc, m, u, k, d, status, k_phys, bound_active, tstar)
        type(hertzdamp_pair_t), intent(in) :: pair                        !! constants of the material pair
        real(wp), intent(in) :: tc                                      !! target contact time of every contact [s]
        real(wp), intent(in) :: m                                       !! effective mass of every contact [kg]
        real(wp), intent(in), contiguous :: u(:)                        !! impact velocities [m s^-1]
        real(wp), intent(out), contiguous :: k(:)                       !! Hertz stiffnesses [N m^-3/2]
        real(wp), intent(out), contiguous :: d(:)                       !! damping coefficients [kg s^-1 m^-q]
        integer, intent(out), contiguous :: status(:)                   !! HD_OK or an error code, per contact
        real(wp), intent(in), optional, contiguous :: k_phys(:)         !! physical stiffness bounds [N m^-3/2]
        logical, intent(out), optional, contiguous :: bound_active(:)   !! true where k = k_phys was used
        real(wp), intent(out), optional, contiguous :: tstar(:)         !! time units of the returned k [s]
        call pair_kd_n(pair, spread(tc, 1, chunk), spread(m, 1, chunk), u, k, d, status, k_phys, bound_active, tstar)
    end subroutine pair_kd_array_tc_m

    ! ================================================================ the one-call inverse

    !> k and d such that the collision has restitution e and contact time tc (doc/theory.md
    !> section 6): the constants alpha(e), tau_c(alpha(e)) by the method of `options` (the
    !> fit by default), then k, d and the bound as hertzdamp_pair_kd computes them.  The
    !> status names the bad argument: T_c, m, u, k_phys (the last bad one), then the law,
    !> the contact end, e and the method's own (hertzdamp_invert_alpha).  On failure every
    !> output is 0 (bound_active false).
    pure elemental subroutine invert_one(e, tc, m, u, iend, k, d, status, alpha, tstar, tau_c, bound_active, &
                                         k_phys, law, options)
        real(wp), intent(in) :: e                      !! target restitution coefficient, e_min <= e <= 1
        real(wp), intent(in) :: tc                     !! target contact time T_c [s]
        real(wp), intent(in) :: m                      !! effective mass [kg]
        real(wp), intent(in) :: u                      !! impact velocity u_in [m s^-1]
        integer, intent(in) :: iend                    !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out) :: k                     !! stiffness [N m^-3/2] (0 on error)
        real(wp), intent(out) :: d                     !! damping coefficient [kg s^-1 m^-q] (0 on error)
        integer, intent(out) :: status                 !! HD_OK or an error code
        real(wp), intent(out), optional :: alpha       !! damping parameter alpha(e)
        real(wp), intent(out), optional :: tstar       !! time unit of the returned k [s] (contact time = tstar tau_c)
        real(wp), intent(out), optional :: tau_c       !! dimensionless contact duration tau_c(alpha)
        logical, intent(out), optional :: bound_active !! true when k = k_phys was used
        real(wp), intent(in), optional :: k_phys       !! physical stiffness bound [N m^-3/2]
        integer, intent(in), optional :: law           !! HD_DAMPING_* (default linear): damping force d zeta^q zeta'
        type(hertzdamp_invert_options), intent(in), optional :: options !! method and settings (default: the fit)
        real(wp) :: a, tau, kp, ts
        integer :: law_, given
        logical :: bound
        law_ = HD_DAMPING_LINEAR
        if (present(law)) law_ = law
        kp = 0.0_wp
        if (present(k_phys)) kp = k_phys
        call pair_constants(e, iend, law_, options, tc, m, u, present(k_phys), kp, a, tau, given)
        call contact_kd(a, tau, a, law_, HD_HOST_NONE, given, tc, m, u, present(k_phys), kp, present(tstar), k, d, ts, &
                        bound, status)
        if (status /= HD_OK) then
            a = 0.0_wp
            tau = 0.0_wp
        end if
        if (present(alpha)) alpha = a
        if (present(tstar)) tstar = ts
        if (present(tau_c)) tau_c = tau
        if (present(bound_active)) bound_active = bound
    end subroutine invert_one

    !> hertzdamp_invert of one contact by the fit, without optional arguments: what the C and
    !> legacy entry points call (the same bits as hertzdamp_invert).  k_phys is the bound
    !> when has_kp (then it must be finite and positive).  Through the elemental form with
    !> its optional arguments the C call cost 1.5 x the module call (the fit's own scalar
    !> kernel, measured with the branch that generates it); through this one 1.0 x.
    integer function hertzdamp_invert_contact(e, tc, m, u, has_kp, k_phys, law, iend, k, d) result(status)
        real(wp), value :: e          !! target restitution coefficient
        real(wp), value :: tc         !! target contact time [s]
        real(wp), value :: m          !! effective mass [kg]
        real(wp), value :: u          !! impact velocity [m s^-1]
        logical, value :: has_kp      !! whether the bound applies
        real(wp), value :: k_phys     !! physical stiffness bound [N m^-3/2] (when has_kp)
        integer, value :: law         !! HD_DAMPING_*
        integer, value :: iend        !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out) :: k    !! Hertz stiffness [N m^-3/2] (0 on error)
        real(wp), intent(out) :: d    !! damping coefficient [kg s^-1 m^-q] (0 on error)
        real(wp) :: a, tau, ts
        integer :: given
        logical :: bound
        call hertzdamp_fit_inverse(e, iend, a, tau, given, law)
        call contact_kd(a, tau, a, law, HD_HOST_NONE, given, tc, m, u, has_kp, k_phys, .false., k, d, ts, bound, &
                        status)
    end function hertzdamp_invert_contact

    !> alpha(e), tau_c(alpha(e)) of a contact end and law by the method of options (the
    !> fit when absent) and their status; a slow method is not run for a contact whose
    !> arguments (T_c, m, u, k_phys) are invalid anyway.
    pure elemental subroutine pair_constants(e, iend, law, options, tc, m, u, has_kp, kp, a, tau, status)
        real(wp), intent(in) :: e, tc, m, u, kp
        integer, intent(in) :: iend, law
        type(hertzdamp_invert_options), intent(in), optional :: options
        logical, intent(in) :: has_kp
        real(wp), intent(out) :: a, tau
        integer, intent(out) :: status
        logical :: fit
        fit = .true.
        if (present(options)) fit = options%method == HD_METHOD_FIT
        if (fit) then
            call hertzdamp_fit_inverse(e, iend, a, tau, status, law)
            return
        end if
        a = 0.0_wp
        tau = 0.0_wp
        status = argument_status(tc, m, u, has_kp, kp)
        if (status == HD_OK) call hertzdamp_invert_alpha(e, iend, a, tau, status, options%method, options%tol, &
                                                         options%accuracy, law)
    end subroutine pair_constants

    !> hertzdamp_invert over arrays; tc, m of size 1 are broadcast (the core of the array
    !> forms): a pass of `chunk` contacts all valid takes the fit's kernel fused with the
    !> direct formulas (alpha, tau_c, k and d in one loop), then contacts_rest; another
    !> pass the fit's vectorised kernel (other methods: one contact at a time) for alpha
    !> and tau_c, then contacts_kd for k and d (the same bits either way).
    pure subroutine invert_n(e, tc, m, u, iend, k, d, status, alpha, tstar, tau_c, bound_active, k_phys, law, options)
        real(wp), intent(in) :: e(:), tc(:), m(:), u(:)
        integer, intent(in) :: iend
        real(wp), intent(out) :: k(:), d(:)
        integer, intent(out) :: status(:)
        real(wp), intent(out), optional :: alpha(:), tstar(:), tau_c(:)
        logical, intent(out), optional :: bound_active(:)
        real(wp), intent(in), optional :: k_phys(:)
        integer, intent(in), optional :: law
        type(hertzdamp_invert_options), intent(in), optional :: options
        real(wp) :: ab(chunk), tb(chunk), kpb(chunk), tsb(chunk)
        integer :: gb(chunk)
        logical :: bb(chunk), fit, done
        integer(int64) :: flags(chunk)
        integer :: i0, nc, j, law_, n, jt, jm
        n = size(e)
        law_ = HD_DAMPING_LINEAR
        if (present(law)) law_ = law
        fit = .true.
        if (present(options)) fit = options%method == HD_METHOD_FIT
        kpb = 0.0_wp
        do i0 = 0, n - 1, chunk
            nc = min(chunk, n - i0)
            jt = start(tc, n, i0)
            jm = start(m, n, i0)
            if (present(k_phys)) kpb(1:nc) = k_phys(i0 + 1:i0 + nc)
            done = .false.
            if (fit) then
                ! contacts all valid: the fit's kernel fused with the direct formulas (one loop)
                call hertzdamp_fit_invert_kd_n(nc, e(i0 + 1:i0 + nc), iend, law_, tc(jt + 1:jt + nc), &
                                               m(jm + 1:jm + nc), u(i0 + 1:i0 + nc), ab, tb, gb, k(i0 + 1:i0 + nc), &
                                               d(i0 + 1:i0 + nc), flags, done)
                if (.not. done) call hertzdamp_fit_inverse_n(nc, e(i0 + 1:i0 + nc), iend, ab, tb, gb, law_)
            else
                do j = 1, nc
                    call pair_constants(e(i0 + j), iend, law_, options, tc(jt + j), m(jm + j), u(i0 + j), &
                                        present(k_phys), kpb(j), ab(j), tb(j), gb(j))
                end do
            end if
            if (done) then
                call contacts_rest(nc, law_, HD_HOST_NONE, ab, tb, ab, gb, tc(jt + 1:jt + nc), m(jm + 1:jm + nc), &
                                   u(i0 + 1:i0 + nc), present(k_phys), kpb, present(tstar), k(i0 + 1:i0 + nc), &
                                   d(i0 + 1:i0 + nc), tsb, bb, status(i0 + 1:i0 + nc), flags)
            else
                call contacts_kd(nc, law_, HD_HOST_NONE, ab, tb, ab, gb, tc(jt + 1:jt + nc), m(jm + 1:jm + nc), &
                                 u(i0 + 1:i0 + nc), present(k_phys), kpb, present(tstar), k(i0 + 1:i0 + nc), &
                                 d(i0 + 1:i0 + nc), tsb, bb, status(i0 + 1:i0 + nc))
            end if
            if (present(alpha)) alpha(i0 + 1:i0 + nc) = merge(ab(1:nc), 0.0_wp, status(i0 + 1:i0 + nc) == HD_OK)
            if (present(tau_c)) tau_c(i0 + 1:i0 + nc) = merge(tb(1:nc), 0.0_wp, status(i0 + 1:i0 + nc) == HD_OK)
            if (present(tstar)) tstar(i0 + 1:i0 + nc) = tsb(1:nc)
            if (present(bound_active)) bound_active(i0 + 1:i0 + nc) = bb(1:nc)
        end do
    end subroutine invert_n

    !> hertzdamp_invert for rank-1 arrays (all of the size of e): the results of one call
    !> per contact, bit for bit.
    pure subroutine invert_array(e, tc, m, u, iend, k, d, status, alpha, tstar, tau_c, bound_active, k_phys, law, &
                                 options)
        real(wp), intent(in), contiguous :: e(:)                 !! target restitution coefficients
        real(wp), intent(in), contiguous :: tc(:)                !! target contact times [s]
        real(wp), intent(in), contiguous :: m(:)                 !! effective masses [kg]
        real(wp), intent(in), contiguous :: u(:)                 !! impact velocities [m s^-1]
        integer, intent(in) :: iend                              !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out), contiguous :: k(:)                !! stiffnesses [N m^-3/2] (0 on error)
        real(wp), intent(out), contiguous :: d(:)                !! damping coefficients [kg s^-1 m^-q] (0 on error)
        integer, intent(out), contiguous :: status(:)            !! HD_OK or an error code, per contact
        real(wp), intent(out), optional, contiguous :: alpha(:)  !! damping parameters alpha(e)
        real(wp), intent(out), optional, contiguous :: tstar(:)  !! time units of the returned k [s]
        real(wp), intent(out), optional, contiguous :: tau_c(:)  !! dimensionless contact durations
        logical, intent(out), optional, contiguous :: bound_active(:) !! true where k = k_phys was used
        real(wp), intent(in), optional, contiguous :: k_phys(:)  !! physical stiffness bounds [N m^-3/2]
        integer, intent(in), optional :: law                     !! as for one contact
        type(hertzdamp_invert_options), intent(in), optional :: options !! as for one contact
        call invert_n(e, tc, m, u, iend, k, d, status, alpha, tstar, tau_c, bound_active, k_phys, law, options)
    end subroutine invert_array

    !> hertzdamp_invert for one T_c and rank-1 arrays of e, m, u (the vectorised path).
    pure subroutine invert_array_tc(e, tc, m, u, iend, k, d, status, alpha, tstar, tau_c, bound_active, k_phys, law, &
                                    options)
        real(wp), intent(in), contiguous :: e(:)                 !! target restitution coefficients
        real(wp), intent(in) :: tc                               !! target contact time of every contact [s]
        real(wp), intent(in), contiguous :: m(:)                 !! effective masses [kg]
        real(wp), intent(in), contiguous :: u(:)                 !! impact velocities [m s^-1]
        integer, intent(in) :: iend                              !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out), contiguous :: k(:)                !! stiffnesses [N m^-3/2] (0 on error)
        real(wp), intent(out), contiguous :: d(:)                !! damping coefficients [kg s^-1 m^-q] (0 on error)
        integer, intent(out), contiguous :: status(:)            !! HD_OK or an error code, per contact
        real(wp), intent(out), optional, contiguous :: alpha(:)  !! damping parameters alpha(e)
        real(wp), intent(out), optional, contiguous :: tstar(:)  !! time units of the returned k [s]
        real(wp), intent(out), optional, contiguous :: tau_c(:)  !! dimensionless contact durations
        logical, intent(out), optional, contiguous :: bound_active(:) !! true where k = k_phys was used
        real(wp), intent(in), optional, contiguous :: k_phys(:)  !! physical stiffness bounds [N m^-3/2]
        integer, intent(in), optional :: law                     !! as for one contact
        type(hertzdamp_invert_options), intent(in), optional :: options !! as for one contact
        call invert_n(e, spread(tc, 1, chunk), m, u, iend, k, d, status, alpha, tstar, tau_c, bound_active, k_phys, &
                      law, options)
    end subroutine invert_array_tc

    !> hertzdamp_invert for one m and rank-1 arrays of e, T_c, u (the vectorised path).
    pure subroutine invert_array_m(e, tc, m, u, iend, k, d, status, alpha, tstar, tau_c, bound_active, k_phys, law, &
                                   options)
        real(wp), intent(in), contiguous :: e(:)                 !! target restitution coefficients
        real(wp), intent(in), contiguous :: tc(:)                !! target contact times [s]
        real(wp), intent(in) :: m                                !! effective mass of every contact [kg]
        real(wp), intent(in), contiguous :: u(:)                 !! impact velocities [m s^-1]
        integer, intent(in) :: iend                              !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out), contiguous :: k(:)                !! stiffnesses [N m^-3/2] (0 on error)
        real(wp), intent(out), contiguous :: d(:)                !! damping coefficients [kg s^-1 m^-q] (0 on error)
        integer, intent(out), contiguous :: status(:)            !! HD_OK or an error code, per contact
        real(wp), intent(out), optional, contiguous :: alpha(:)  !! damping parameters alpha(e)
        real(wp), intent(out), optional, contiguous :: tstar(:)  !! time units of the returned k [s]
        real(wp), intent(out), optional, contiguous :: tau_c(:)  !! dimensionless contact durations
        logical, intent(out), optional, contiguous :: bound_active(:) !! true where k = k_phys was used
        real(wp), intent(in), optional, contiguous :: k_phys(:)  !! physical stiffness bounds [N m^-3/2]
        integer, intent(in), optional :: law                     !! as for one contact
        type(hertzdamp_invert_options), intent(in), optional :: options !! as for one contact
        call invert_n(e, tc, spread(m, 1, chunk), u, iend, k, d, status, alpha, tstar, tau_c, bound_active, k_phys, &
                      law, options)
    end subroutine invert_array_m

    !> hertzdamp_invert for one T_c and one m, and rank-1 arrays of e, u (the vectorised path).
    pure subroutine invert_array_tc_m(e, tc, m, u, iend, k, d, status, alpha, tstar, tau_c, bound_active, k_phys, law, &
                                      options)
        real(wp), intent(in), contiguous :: e(:)                 !! target restitution coefficients
        real(wp), intent(in) :: tc                               !! target contact time of every contact [s]
        real(wp), intent(in) :: m                                !! effective mass of every contact [kg]
        real(wp), intent(in), contiguous :: u(:)                 !! impact velocities [m s^-1]
        integer, intent(in) :: iend                              !! HD_END_OVERLAP or HD_END_FORCE
        real(wp), intent(out), contiguous :: k(:)                !! stiffnesses [N m^-3/2] (0 on error)
        real(wp), intent(out), contiguous :: d(:)                !! damping coefficients [kg s^-1 m^-q] (0 on error)
        integer, intent(out), contiguous :: status(:)            !! HD_OK or an error code, per contact
        real(wp), intent(out), optional, contiguous :: alpha(:)  !! damping parameters alpha(e)
        real(wp), intent(out), optional, contiguous :: tstar(:)  !! time units of the returned k [s]
        real(wp), intent(out), optional, contiguous :: tau_c(:)  !! dimensionless contact durations
        logical, intent(out), optional, contiguous :: bound_active(:) !! true where k = k_phys was used
        real(wp), intent(in), optional, contiguous :: k_phys(:)  !! physical stiffness bounds [N m^-3/2]
        integer, intent(in), optional :: law                     !! as for one contact
        type(hertzdamp_invert_options), intent(in), optional :: options !! as for one contact
        call invert_n(e, spread(tc, 1, chunk), spread(m, 1, chunk), u, iend, k, d, status, alpha, tstar, tau_c, &
                      bound_active, k_phys, law, options)
    end subroutine invert_array_tc_m

end module hertzdamp_pair
