!> The per-pair API (src/hertzdamp_pair.f90): hertzdamp_pair_init and hertzdamp_pair_kd.
!>
!> - host none: the constants are the fit's alpha(e), tau_c(alpha(e)) bit for bit, and k, d
!>   those of hertzdamp_invert bit for bit (every law and contact end, the direct and the
!>   logarithmic path, with and without the bound, t* and bound_active);
!> - k and d against the closed forms written here with ** (k = m r^(5/2) u^(-1/2),
!>   d = alpha m r (r/u)^q; bound: d = alpha m^((3-2q)/5) k_phys^((2+2q)/5) u^((1-4q)/5));
!> - the array forms (T_c and m as arrays or scalars, broadcast) and hertzdamp_invert's
!>   broadcast forms give the bits of one call per contact, across pass boundaries;
!> - every bad argument of init and kd gives its status and zero outputs; a pair not set
!>   by init (default, garbage, a failed init, one field changed) gives HD_BAD_PAIR;
!> - the C functions and the legacy externals (through their binding labels, the legacy
!>   ones declared as a fixed-form caller sees them: DOUBLE PRECISION PAIR(8)) give the
!>   module's bits;
!> - with a host scheme and the bound active, alpha_eff = alpha(e) + (alpha_N - alpha(e))
!>   (h'/h_N)^p with h' and h_N computed here from their definitions, and the mean e the
!>   host achieves with it (hertzdamp_host_mean) against the target.
program test_pair
    use hertzdamp, only: hertzdamp_rk, hertzdamp_max_host, HD_OK, HD_BAD_LAW, HD_BAD_END, HD_BAD_RESTITUTION, &
                         HD_BAD_TIME, HD_BAD_MASS, HD_BAD_VELOCITY, HD_BAD_KPHYS, HD_BAD_PAIR, HD_BAD_HOST, &
                         HD_BAD_STEPS, HD_HOST_UNREACHABLE, HD_BAD_ARGUMENT, HD_END_OVERLAP, HD_END_FORCE, &
                         HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO, hertzdamp_law_q, &
                         hertzdamp_law_name, HD_METHOD_COMPACT, HD_METHOD_FIRST_ORDER, hertzdamp_fit_inverse, &
                         hertzdamp_invert_options, hertzdamp_pair_t, hertzdamp_pair_init, hertzdamp_pair_kd, &
                         hertzdamp_invert, HD_HOST_NONE, HD_HOST_LAMMPS, HD_HOST_MFIX_AB2, HD_HOST_VERLET, &
                         HD_HOST_LAMMPS_PHASE, hertzdamp_host_stats, hertzdamp_host_solve, hertzdamp_host_min_steps, &
                         hertzdamp_host_name, hertzdamp_host_mean
    use hertzdamp_capi, only: hertzdamp_c_pair_init, hertzdamp_c_pair_kd, hertzdamp_c_invert_law, &
                              hertzdamp_c_pair_stats, hertzdamp_c_host_min_steps
    use hertzdamp_testing, only: test_suite, new_suite, rel_err
    use, intrinsic :: iso_c_binding, only: c_double, c_int
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
    implicit none

    interface
        ! as a fixed-form caller declares them (include/hertzdamp.fi)
        subroutine legacy_pair_init(e, ilaw, iend, ihost, steps, pair, ierr) bind(c, name='hertzdamp_pair_init_')
            import :: c_double, c_int
            implicit none
            real(c_double), intent(in) :: e, steps
            integer(c_int), intent(in) :: ilaw, iend, ihost
            real(c_double), intent(out) :: pair(8)
            integer(c_int), intent(out) :: ierr
        end subroutine legacy_pair_init
        subroutine legacy_pair_kd(pair, tc, m, u, kphys, k, d, ierr) bind(c, name='hertzdamp_pair_kd_')
            import :: c_double, c_int
            implicit none
            real(c_double), intent(in) :: pair(8), tc, m, u, kphys
            real(c_double), intent(out) :: k, d
            integer(c_int), intent(out) :: ierr
        end subroutine legacy_pair_kd
    end interface

    integer, parameter :: wp = hertzdamp_rk
    type(test_suite) :: s
    real(wp) :: nan, inf
    real(wp), allocatable :: e(:), tc(:), m(:), u(:)
    integer :: law, iend

    s = new_suite('test_pair')
    nan = ieee_value(1.0_wp, ieee_quiet_nan)
    inf = ieee_value(1.0_wp, ieee_positive_inf)
    call make_contacts(e, tc, m, u)
    do law = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
        do iend = HD_END_OVERLAP, HD_END_FORCE
            call host_none_constants(law, iend)
            call host_none_kd(law, iend)
            call closed_forms(law, iend)
            call arrays(law, iend)
            call bindings(law, iend)
            call host_bound(law, iend)
        end do
    end do
    call invert_broadcast()
    call host_bound_mean()
    call bad_init()
    call bad_kd()
    call invalid_pairs()
    call c_stats_and_min_steps()
    call s%finish()

contains

    !> Bit patterns (NaN-safe, -0 distinct from +0).
    elemental integer(int64) function bits(x)
        real(wp), intent(in) :: x
        bits = transfer(x, 0_int64)
    end function bits

    !> 'law, end' for labels.
    function tag(law, iend) result(t)
        integer, intent(in) :: law, iend
        character(len=:), allocatable :: t
        t = hertzdamp_law_name(law) // merge(', overlap', ', force  ', iend == HD_END_OVERLAP)
    end function tag

    !> Contacts: a decade grid (the direct range and beyond it, both sides) and random ones.
    subroutine make_contacts(e, tc, m, u)
        real(wp), allocatable, intent(out) :: e(:), tc(:), m(:), u(:)
        real(wp) :: r(4)
        integer :: i
        allocate (e(0), tc(0), m(0), u(0))
        do i = -40, 40, 5
            e = [e, 0.5_wp, 0.5_wp, 0.5_wp]
            tc = [tc, 10.0_wp**i, 1.0e-4_wp, 1.0e-4_wp]
            m = [m, 1.0e-3_wp, 10.0_wp**i, 1.0e-3_wp]
            u = [u, 1.0_wp, 1.0_wp, 10.0_wp**i]
        end do
        e = [e, 1.0_wp, 1.0e-4_wp, 1.0e-3_wp, 0.999_wp]
        tc = [tc, 1.0e-30_wp, 1.0e30_wp, 1.0e-4_wp, 1.0e-4_wp]
        m = [m, 1.0e30_wp, 1.0e-30_wp, 1.0_wp, 1.0_wp]
        u = [u, 1.0e-30_wp, 1.0e30_wp, 1.0_wp, 1.0_wp]
        do i = 1, 700
            call random_number(r)
            e = [e, 10.0_wp**(-4.0_wp * r(1))]
            tc = [tc, 10.0_wp**(-8.0_wp + 6.0_wp * r(2))]
            m = [m, 10.0_wp**(-12.0_wp + 12.0_wp * r(3))]
            u = [u, 10.0_wp**(-4.0_wp + 6.0_wp * r(4))]
        end do
    end subroutine make_contacts

    !> host none: alpha, tau_c of the fit, bit for bit; no spread.
    subroutine host_none_constants(law, iend)
        integer, intent(in) :: law, iend
        type(hertzdamp_pair_t) :: p
        type(hertzdamp_host_stats) :: st
        real(wp) :: a, tau
        integer :: i, status, sf, nbad
        nbad = 0
        do i = 1, size(e)
            call hertzdamp_pair_init(e(i), law, iend, HD_HOST_NONE, 0.0_wp, p, status, st)
            call hertzdamp_fit_inverse(e(i), iend, a, tau, sf, law)
            if (status /= sf .or. bits(p%alpha) /= bits(a) .or. bits(p%tau_c) /= bits(tau) .or. &
                bits(p%alpha_cont) /= bits(a)) nbad = nbad + 1
            if (status == HD_OK) then
                if (.not. (st%e_mean == e(i) .and. st%e_sd == 0.0_wp .and. st%tau_mean == tau .and. &
                           st%tau_sd == 0.0_wp .and. st%e_min == st%e_max)) nbad = nbad + 1
            end if
        end do
        call s%check(nbad == 0, 'host none: alpha, tau_c = hertzdamp_fit_inverse bit for bit, no spread, ' // &
                     tag(law, iend))
    end subroutine host_none_constants

    !> host none: pair_kd = hertzdamp_invert, bit for bit, with every output.
    subroutine host_none_kd(law, iend)
        integer, intent(in) :: law, iend
        type(hertzdamp_pair_t) :: p
        real(wp) :: k0, d0, ts0, k, d, ts, kp
        integer :: i, j, st0, st, sti, nbad, nbound
        logical :: b0, b
        real(wp), parameter :: factors(3) = [0.5_wp, 2.0_wp, 1.0e-3_wp]
        nbad = 0
        nbound = 0
        do i = 1, size(e)
            call hertzdamp_pair_init(e(i), law, iend, HD_HOST_NONE, 0.0_wp, p, sti)
            call hertzdamp_invert(e(i), tc(i), m(i), u(i), iend, k0, d0, st0, tstar=ts0, law=law)
            call hertzdamp_pair_kd(p, tc(i), m(i), u(i), k, d, st, tstar=ts)
            if (st == HD_BAD_PAIR) st = sti
            if (bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. bits(ts) /= bits(ts0) .or. st /= st0) nbad = nbad + 1
            do j = 1, 3
                kp = factors(j) * merge(k0, 1.0_wp, st0 == HD_OK)
                call hertzdamp_invert(e(i), tc(i), m(i), u(i), iend, k0, d0, st0, tstar=ts0, bound_active=b0, &
                                      k_phys=kp, law=law)
                call hertzdamp_pair_kd(p, tc(i), m(i), u(i), k, d, st, k_phys=kp, bound_active=b, tstar=ts)
                if (st == HD_BAD_PAIR) st = sti
                if (bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. bits(ts) /= bits(ts0) .or. st /= st0 .or. &
                    (b .neqv. b0)) nbad = nbad + 1
                if (b) nbound = nbound + 1
                ! without t*: the tsuji bound takes the path that needs none
                call hertzdamp_invert(e(i), tc(i), m(i), u(i), iend, k0, d0, st0, k_phys=kp, law=law)
                call hertzdamp_pair_kd(p, tc(i), m(i), u(i), k, d, st, k_phys=kp)
                if (st == HD_BAD_PAIR) st = sti
                if (bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. st /= st0) nbad = nbad + 1
            end do
        end do
        call s%check(nbad == 0, 'host none: pair_kd = hertzdamp_invert bit for bit (k, d, status, tstar, '// &
                     'bound_active; with and without k_phys), ' // tag(law, iend))
        call s%check(nbound > size(e), 'the bound is active on part of the grid, ' // tag(law, iend))
    end subroutine host_none_kd

    !> k and d against the closed forms, evaluated here with **.
    subroutine closed_forms(law, iend)
        integer, intent(in) :: law, iend
        type(hertzdamp_pair_t) :: p
        real(wp) :: k, d, q, r, kp, kref, dref, errk, errd, errb
        integer :: i, st
        logical :: b
        q = hertzdamp_law_q(law)
        errk = 0.0_wp
        errd = 0.0_wp
        errb = 0.0_wp
        do i = 1, size(e)
            if (e(i) >= 1.0_wp) cycle
            call hertzdamp_pair_init(e(i), law, iend, HD_HOST_NONE, 0.0_wp, p, st)
            if (st /= HD_OK) cycle
            call hertzdamp_pair_kd(p, tc(i), m(i), u(i), k, d, st)
            if (st /= HD_OK) cycle
            r = p%tau_c / tc(i)
            kref = m(i) * r**2.5_wp / sqrt(u(i))
            dref = p%alpha * m(i) * r * (r / u(i))**q
            errk = max(errk, rel_err(k, kref))
            errd = max(errd, rel_err(d, dref))
            kp = 0.25_wp * k
            call hertzdamp_pair_kd(p, tc(i), m(i), u(i), k, d, st, k_phys=kp, bound_active=b)
            if (st /= HD_OK .or. .not. b .or. k /= kp) then
                errb = huge(1.0_wp)
                cycle
            end if
            dref = p%alpha * m(i)**((3.0_wp - 2.0_wp * q) / 5.0_wp) * kp**((2.0_wp + 2.0_wp * q) / 5.0_wp) * &
                   u(i)**((1.0_wp - 4.0_wp * q) / 5.0_wp)
            errb = max(errb, rel_err(d, dref))
        end do
        ! (** on 1e-40 .. 1e40 arguments loses ~ |ln x| eps relative: 1e-13 covers it)
        call s%check(errk < 1.0e-13_wp, 'k = m r^(5/2) u^(-1/2), ' // tag(law, iend))
        call s%check(errd < 1.0e-13_wp, 'd = alpha m r (r/u)^q, ' // tag(law, iend))
        call s%check(errb < 1.0e-13_wp, 'bound: k = k_phys, d = alpha m^((3-2q)/5) k_phys^((2+2q)/5) ' // &
                     'u^((1-4q)/5), ' // tag(law, iend))
    end subroutine closed_forms

    !> The array forms of pair_kd, T_c and m as arrays or scalars, across pass boundaries.
    subroutine arrays(law, iend)
        integer, intent(in) :: law, iend
        type(hertzdamp_pair_t) :: p
        integer, parameter :: sizes(5) = [0, 1, 256, 257, 700]
        real(wp), parameter :: tc_one = 2.0e-5_wp, m_one = 3.0e-4_wp
        real(wp), allocatable :: k0(:), d0(:), ts0(:), k(:), d(:), ts(:), kp(:), tcs(:), ms(:)
        integer, allocatable :: st0(:), st(:)
        logical, allocatable :: b0(:), b(:)
        integer :: j, n, i, form, sti, nbad
        call hertzdamp_pair_init(0.3_wp, law, iend, HD_HOST_NONE, 0.0_wp, p, sti)
        nbad = 0
        do j = 1, size(sizes)
            n = sizes(j)
            allocate (k0(n), d0(n), ts0(n), k(n), d(n), ts(n), kp(n), st0(n), st(n), b0(n), b(n))
            do form = 0, 3
                tcs = tc(1:n)
                ms = m(1:n)
                if (form == 1 .or. form == 3) tcs = tc_one
                if (form >= 2) ms = m_one
                ! references: one call per contact
                do i = 1, n
                    call hertzdamp_pair_kd(p, tcs(i), ms(i), u(i), k0(i), d0(i), st0(i), tstar=ts0(i))
                end do
                kp = merge(0.5_wp, 2.0_wp, mod([(i, i = 1, n)], 3) == 0) * merge(k0, 1.0_wp, st0 == HD_OK)
                if (n > 5) kp(5) = -1.0_wp
                select case (form)
                case (0)
                    call hertzdamp_pair_kd(p, tcs, ms, u(1:n), k, d, st, tstar=ts)
                case (1)
                    call hertzdamp_pair_kd(p, tc_one, ms, u(1:n), k, d, st, tstar=ts)
                case (2)
                    call hertzdamp_pair_kd(p, tcs, m_one, u(1:n), k, d, st, tstar=ts)
                case default
                    call hertzdamp_pair_kd(p, tc_one, m_one, u(1:n), k, d, st, tstar=ts)
                end select
                if (any(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. bits(ts) /= bits(ts0) .or. st /= st0)) then
                    nbad = nbad + 1
                end if
                do i = 1, n
                    call hertzdamp_pair_kd(p, tcs(i), ms(i), u(i), k0(i), d0(i), st0(i), k_phys=kp(i), &
                                           bound_active=b0(i))
                end do
                select case (form)
                case (0)
                    call hertzdamp_pair_kd(p, tcs, ms, u(1:n), k, d, st, k_phys=kp, bound_active=b)
                case (1)
                    call hertzdamp_pair_kd(p, tc_one, ms, u(1:n), k, d, st, k_phys=kp, bound_active=b)
                case (2)
                    call hertzdamp_pair_kd(p, tcs, m_one, u(1:n), k, d, st, k_phys=kp, bound_active=b)
                case default
                    call hertzdamp_pair_kd(p, tc_one, m_one, u(1:n), k, d, st, k_phys=kp, bound_active=b)
                end select
                if (any(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. st /= st0 .or. (b .neqv. b0))) then
                    nbad = nbad + 1
                end if
            end do
            deallocate (k0, d0, ts0, k, d, ts, kp, st0, st, b0, b)
        end do
        call s%check(nbad == 0, 'pair_kd on arrays (T_c, m arrays or scalars; n = 0, 1, 256, 257, 700) = one ' // &
                     'call per contact, with and without k_phys, ' // tag(law, iend))
    end subroutine arrays

    !> hertzdamp_invert with T_c and/or m as scalars over arrays of e, u (the vectorised
    !> path) = one call per contact, for the fit and a method of its own.
    subroutine invert_broadcast()
        integer, parameter :: n = 600
        real(wp) :: k0(n), d0(n), a0(n), t0(n), s0(n), k(n), d(n), a(n), t(n), ts(n), kp(n)
        integer :: st0(n), st(n), form, i, nbad, law, meth
        logical :: b0(n), b(n)
        type(hertzdamp_invert_options) :: o
        real(wp), parameter :: tc1 = 1.0e-4_wp, m1 = 2.0e-3_wp
        nbad = 0
        do law = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
            do meth = 0, 1
                o = hertzdamp_invert_options()
                if (meth == 1) o%method = merge(HD_METHOD_COMPACT, HD_METHOD_FIRST_ORDER, law == HD_DAMPING_LINEAR)
                do form = 1, 3
                    do i = 1, n
                        call hertzdamp_invert(e(i), merge(tc1, tc(i), form /= 2), merge(m1, m(i), form >= 2), u(i), &
                                              HD_END_OVERLAP, k0(i), d0(i), st0(i), a0(i), s0(i), t0(i), b0(i), &
                                              law=law, options=o)
                    end do
                    select case (form)
                    case (1)
                        call hertzdamp_invert(e(1:n), tc1, m(1:n), u(1:n), HD_END_OVERLAP, k, d, st, a, ts, t, b, &
                                              law=law, options=o)
                    case (2)
                        call hertzdamp_invert(e(1:n), tc(1:n), m1, u(1:n), HD_END_OVERLAP, k, d, st, a, ts, t, b, &
                                              law=law, options=o)
                    case default
                        call hertzdamp_invert(e(1:n), tc1, m1, u(1:n), HD_END_OVERLAP, k, d, st, a, ts, t, b, &
                                              law=law, options=o)
                    end select
                    if (any(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. st /= st0 .or. bits(a) /= bits(a0) &
                            .or. bits(t) /= bits(t0) .or. bits(ts) /= bits(s0) .or. (b .neqv. b0))) nbad = nbad + 1
                    kp = 0.5_wp * merge(k0, 1.0_wp, st0 == HD_OK)
                    kp(1:n:2) = 2.0_wp * kp(1:n:2)
                    do i = 1, n
                        call hertzdamp_invert(e(i), merge(tc1, tc(i), form /= 2), merge(m1, m(i), form >= 2), u(i), &
                                              HD_END_FORCE, k0(i), d0(i), st0(i), bound_active=b0(i), k_phys=kp(i), &
                                              law=law, options=o)
                    end do
                    select case (form)
                    case (1)
                        call hertzdamp_invert(e(1:n), tc1, m(1:n), u(1:n), HD_END_FORCE, k, d, st, bound_active=b, &
                                              k_phys=kp, law=law, options=o)
                    case (2)
                        call hertzdamp_invert(e(1:n), tc(1:n), m1, u(1:n), HD_END_FORCE, k, d, st, bound_active=b, &
                                              k_phys=kp, law=law, options=o)
                    case default
                        call hertzdamp_invert(e(1:n), tc1, m1, u(1:n), HD_END_FORCE, k, d, st, bound_active=b, &
                                              k_phys=kp, law=law, options=o)
                    end select
                    if (any(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. st /= st0 .or. (b .neqv. b0))) then
                        nbad = nbad + 1
                    end if
                    call s%check(count(st0 == HD_OK) > n / 4, 'invert broadcast: a quarter of the contacts ' // &
                                 'succeeds at least (compact: e >= 0.05)')
                end do
            end do
        end do
        call s%check(nbad == 0, 'hertzdamp_invert with T_c and/or m scalars over arrays = one call per contact ' // &
                     '(fit and another method, every law, every output, with and without k_phys)')
    end subroutine invert_broadcast

    !> The C functions and the legacy externals against the module, bit for bit.
    subroutine bindings(law, iend)
        integer, intent(in) :: law, iend
        type(hertzdamp_pair_t) :: p, pc
        real(c_double) :: pl(8)
        real(wp) :: k0, d0, k, d, kl, dl, kp
        integer :: i, j, st0, sti
        integer(c_int) :: st, stl
        integer :: nbad
        real(wp), parameter :: kps(3) = [0.0_wp, 1.0e3_wp, -2.0_wp]
        nbad = 0
        do i = 1, size(e), 3
            call hertzdamp_pair_init(e(i), law, iend, HD_HOST_NONE, 0.0_wp, p, sti)
            st = hertzdamp_c_pair_init(e(i), int(law, c_int), int(iend, c_int), int(HD_HOST_NONE, c_int), 0.0_wp, pc)
            call legacy_pair_init(e(i), int(law, c_int), int(iend, c_int), int(HD_HOST_NONE, c_int), 0.0_wp, pl, stl)
            if (st /= sti .or. stl /= sti .or. any(bits(transfer(pc, pl)) /= bits(transfer(p, pl))) .or. &
                any(bits(pl) /= bits(transfer(p, pl)))) nbad = nbad + 1
            do j = 1, 3
                kp = kps(j)
                if (kp > 0.0_wp) then
                    call hertzdamp_pair_kd(p, tc(i), m(i), u(i), k0, d0, st0, k_phys=kp)
                else
                    call hertzdamp_pair_kd(p, tc(i), m(i), u(i), k0, d0, st0)
                end if
                st = hertzdamp_c_pair_kd(pc, tc(i), m(i), u(i), kp, k, d)
                call legacy_pair_kd(pl, tc(i), m(i), u(i), kp, kl, dl, stl)
                if (st /= st0 .or. stl /= st0 .or. bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. &
                    bits(kl) /= bits(k0) .or. bits(dl) /= bits(d0)) nbad = nbad + 1
            end do
            ! host none through C: the numbers of hertzdamp_c_invert_law
            st = hertzdamp_c_pair_kd(pc, tc(i), m(i), u(i), 0.0_wp, k, d)
            stl = hertzdamp_c_invert_law(e(i), tc(i), m(i), u(i), 0.0_wp, int(law, c_int), int(iend, c_int), k0, d0)
            if (st == HD_BAD_PAIR) st = int(sti, c_int)
            if (st /= stl .or. bits(k) /= bits(k0) .or. bits(d) /= bits(d0)) nbad = nbad + 1
        end do
        call s%check(nbad == 0, 'C hertzdamp_c_pair_init/_kd and legacy HERTZDAMP_PAIR_INIT/_KD (PAIR(8)) = ' // &
                     'module bit for bit (k_phys <= 0: no bound), ' // tag(law, iend))
    end subroutine bindings

    !> With a host scheme: without the bound, d = alpha_N m r (r/u)^q with the host's
    !> constants; with it, alpha_eff = alpha(e) + (alpha_N - alpha(e)) (h'/h_N)^p, where
    !> h' = dt/t*_phys, h_N = tau_N/N, dt = T_c/N, t*_phys = (m/k_phys)^(2/5) u^(-1/5), p = 1
    !> for lammps, 2 for verlet.
    subroutine host_bound(law, iend)
        integer, intent(in) :: law, iend
        integer, parameter :: hosts(2) = [HD_HOST_LAMMPS, HD_HOST_VERLET]
        integer :: ih
        do ih = 1, 2
            call host_bound_of(hosts(ih), ih, law, iend)
        end do
    end subroutine host_bound

    subroutine host_bound_of(host, order, law, iend)
        integer, intent(in) :: host, order, law, iend
        type(hertzdamp_pair_t) :: p
        type(hertzdamp_host_stats) :: stats
        real(wp) :: steps, k, d, q, r, kp, tsp, hp, hn, ae, dref, err, errc, an, taun
        integer :: i, st, sth
        logical :: b
        q = hertzdamp_law_q(law)
        steps = 20.0_wp
        err = 0.0_wp
        errc = 0.0_wp
        call hertzdamp_pair_init(0.5_wp, law, iend, host, steps, p, st, stats)
        call hertzdamp_host_solve(0.5_wp, law, iend, host, steps, an, taun, stats, sth)
        call s%check(st == HD_OK .and. sth == HD_OK .and. bits(p%alpha) == bits(an) .and. &
                     bits(p%tau_c) == bits(taun), 'host ' // hertzdamp_host_name(host) // ': the constants of ' // &
                     'hertzdamp_host_solve, ' // tag(law, iend))
        if (st /= HD_OK) return
        do i = 1, size(e)
            call hertzdamp_pair_kd(p, tc(i), m(i), u(i), k, d, st)
            if (st /= HD_OK) cycle
            r = p%tau_c / tc(i)
            errc = max(errc, rel_err(d, p%alpha * m(i) * r * (r / u(i))**q))
            kp = 0.3_wp * k
            call hertzdamp_pair_kd(p, tc(i), m(i), u(i), k, d, st, k_phys=kp, bound_active=b)
            if (st /= HD_OK .or. .not. b) then
                err = huge(1.0_wp)
                cycle
            end if
            tsp = (m(i) / kp)**0.4_wp * u(i)**(-0.2_wp)
            hp = (tc(i) / steps) / tsp
            hn = p%tau_c / steps
            ae = p%alpha_cont + (p%alpha - p%alpha_cont) * (hp / hn)**order
            dref = ae * m(i) / tsp / (u(i) * tsp)**q
            err = max(err, rel_err(d, dref))
        end do
        call s%check(errc < 1.0e-13_wp, 'host ' // hertzdamp_host_name(host) // ', no bound: d = alpha_N m r ' // &
                     '(r/u)^q, ' // tag(law, iend))
        call s%check(err < 1.0e-12_wp, 'host ' // hertzdamp_host_name(host) // ', bound: alpha_eff = alpha(e) + ' // &
                     '(alpha_N - alpha(e)) (h''/h_N)^p, ' // tag(law, iend))
        ! at k_phys = k the contact has N steps: alpha_eff = alpha_N
        call hertzdamp_pair_kd(p, 1.0e-4_wp, 1.0e-3_wp, 1.0_wp, k, d, st)
        call hertzdamp_pair_kd(p, 1.0e-4_wp, 1.0e-3_wp, 1.0_wp, kp, dref, st, k_phys=k, bound_active=b)
        call s%check(b .and. rel_err(dref, d) < 1.0e-14_wp, 'host bound at k_phys = k: the unbounded d, ' // &
                     tag(law, iend))
    end subroutine host_bound_of

    !> The bound with a host against the host's own phase mean (hertzdamp_host_mean): a
    !> contact with k = k_phys lasts more than N steps (h' = h_N/2, /4, /8); alpha_eff brings
    !> the mean achieved e to within 3e-3 of the target (measured 2.5e-3) for every host, law
    !> and end, and over the whole grid its error is below a fifth of what alpha(e) and alpha_N
    !> give.
    subroutine host_bound_mean()
        real(wp), parameter :: e0 = 0.5_wp, steps = 20.0_wp, tc = 1.0e-5_wp, m = 1.0e-3_wp, u = 1.0_wp
        type(hertzdamp_pair_t) :: p
        type(hertzdamp_host_stats) :: s_eff, s_n, s_cont
        real(wp) :: k, d, kb, db, tsp, hp, hn, ae, err_eff, sum_eff, sum_n, sum_cont
        integer :: host, law, iend, j, st, st1, st2, st3, nbad, order
        logical :: b
        nbad = 0
        err_eff = 0.0_wp
        sum_eff = 0.0_wp
        sum_n = 0.0_wp
        sum_cont = 0.0_wp
        do host = HD_HOST_LAMMPS, HD_HOST_LAMMPS_PHASE
            order = merge(2, 1, host == HD_HOST_MFIX_AB2 .or. host == HD_HOST_VERLET)
            do law = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
                do iend = HD_END_OVERLAP, HD_END_FORCE
                    call hertzdamp_pair_init(e0, law, iend, host, steps, p, st)
                    call hertzdamp_pair_kd(p, tc, m, u, k, d, st1)
                    if (st /= HD_OK .or. st1 /= HD_OK) then
                        nbad = nbad + 1
                        cycle
                    end if
                    do j = 1, 3
                        ! k_phys = k 2^(-5j/2): t* grows by 2^j, h' = h_N / 2^j
                        call hertzdamp_pair_kd(p, tc, m, u, kb, db, st, k_phys=k * 2.0_wp**(-2.5_wp * j), &
                                               bound_active=b)
                        tsp = (m / kb)**0.4_wp * u**(-0.2_wp)
                        hp = (tc / steps) / tsp
                        hn = p%tau_c / steps
                        ae = p%alpha_cont + (p%alpha - p%alpha_cont) * (hp / hn)**order
                        call hertzdamp_host_mean(ae, hp, law, iend, host, s_eff, st1)
                        call hertzdamp_host_mean(p%alpha, hp, law, iend, host, s_n, st2)
                        call hertzdamp_host_mean(p%alpha_cont, hp, law, iend, host, s_cont, st3)
                        if (st /= HD_OK .or. .not. b .or. st1 /= HD_OK .or. st2 /= HD_OK .or. st3 /= HD_OK .or. &
                            abs(hp / hn - 2.0_wp**(-j)) > 1.0e-12_wp) then
                            nbad = nbad + 1
                            cycle
                        end if
                        err_eff = max(err_eff, abs(s_eff%e_mean / e0 - 1.0_wp))
                        sum_eff = sum_eff + abs(s_eff%e_mean / e0 - 1.0_wp)
                        sum_n = sum_n + abs(s_n%e_mean / e0 - 1.0_wp)
                        sum_cont = sum_cont + abs(s_cont%e_mean / e0 - 1.0_wp)
                    end do
                end do
            end do
        end do
        call s%check(nbad == 0, 'host bound: every pair, contact and phase mean computed, h''/h_N = 1/2, 1/4, 1/8')
        call s%check(err_eff < 3.0e-3_wp, 'host bound: alpha_eff gives the mean e within 3e-3 of e for every host, ' // &
                     'law and end at h'' < h_N')
        call s%check(sum_eff < 0.2_wp * sum_n .and. sum_eff < 0.2_wp * sum_cont, 'host bound: over the grid, ' // &
                     'alpha_eff''s error is below a fifth of alpha_N''s and of alpha(e)''s')
        write (*, '(a, es10.2, a, 3es10.2)') 'host bound: max |e_mean/e - 1| ', err_eff, &
            '; sums eff, alpha_N, alpha(e) ', sum_eff, sum_n, sum_cont
    end subroutine host_bound_mean

    !> Every bad argument of hertzdamp_pair_init: its status, and an invalid pair.
    subroutine bad_init()
        type(hertzdamp_pair_t) :: p
        type(hertzdamp_host_stats) :: stats
        real(wp) :: k, d
        integer :: st, stk, nmin, i
        call expect(0.5_wp, -1, HD_END_OVERLAP, HD_HOST_NONE, 0.0_wp, HD_BAD_LAW, 'law -1')
        call expect(0.5_wp, 3, HD_END_OVERLAP, HD_HOST_NONE, 0.0_wp, HD_BAD_LAW, 'law 3')
        call expect(0.5_wp, 0, 2, HD_HOST_NONE, 0.0_wp, HD_BAD_END, 'end 2')
        call expect(0.5_wp, 0, -1, HD_HOST_LAMMPS, 20.0_wp, HD_BAD_END, 'end -1 (host lammps)')
        call expect(1.5_wp, 0, HD_END_OVERLAP, HD_HOST_NONE, 0.0_wp, HD_BAD_RESTITUTION, 'e 1.5')
        call expect(1.0e-4_wp, 0, HD_END_OVERLAP, HD_HOST_NONE, 0.0_wp, HD_BAD_RESTITUTION, 'e 1e-4 (linear overlap)')
        call expect(0.0_wp, 1, HD_END_FORCE, HD_HOST_NONE, 0.0_wp, HD_BAD_RESTITUTION, 'e 0')
        call expect(nan, 0, HD_END_OVERLAP, HD_HOST_LAMMPS, 20.0_wp, HD_BAD_RESTITUTION, 'e NaN')
        call expect(0.5_wp, 0, HD_END_OVERLAP, -1, 20.0_wp, HD_BAD_HOST, 'host -1')
        call expect(0.5_wp, 0, HD_END_OVERLAP, hertzdamp_max_host + 1, 20.0_wp, HD_BAD_HOST, 'host max + 1')
        call expect(0.5_wp, 0, HD_END_OVERLAP, HD_HOST_LAMMPS, 0.0_wp, HD_BAD_STEPS, 'steps 0')
        call expect(0.5_wp, 0, HD_END_OVERLAP, HD_HOST_LAMMPS, -5.0_wp, HD_BAD_STEPS, 'steps -5')
        call expect(0.5_wp, 0, HD_END_OVERLAP, HD_HOST_LAMMPS, nan, HD_BAD_STEPS, 'steps NaN')
        call expect(0.5_wp, 0, HD_END_OVERLAP, HD_HOST_LAMMPS, inf, HD_BAD_STEPS, 'steps Inf')
        ! host none does not use steps
        call hertzdamp_pair_init(0.5_wp, 0, HD_END_OVERLAP, HD_HOST_NONE, nan, p, st)
        call s%check(st == HD_OK, 'host none: steps not used (NaN accepted)')
        ! the fewest steps that reach e, and one fewer
        do i = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
            call hertzdamp_host_min_steps(0.5_wp, i, HD_END_OVERLAP, HD_HOST_LAMMPS, nmin, st)
            call s%check(st == HD_OK .and. nmin >= 1, 'hertzdamp_host_min_steps succeeds, ' // hertzdamp_law_name(i))
            if (st /= HD_OK) cycle
            call hertzdamp_pair_init(0.5_wp, i, HD_END_OVERLAP, HD_HOST_LAMMPS, real(nmin, wp), p, st, stats)
            call s%check(st == HD_OK, 'N = n_min reaches e, ' // hertzdamp_law_name(i))
            if (nmin > 1) then
                call hertzdamp_pair_init(0.5_wp, i, HD_END_OVERLAP, HD_HOST_LAMMPS, real(nmin - 1, wp), p, st, stats)
                call hertzdamp_pair_kd(p, 1.0e-4_wp, 1.0_wp, 1.0_wp, k, d, stk)
                call s%check((st == HD_HOST_UNREACHABLE .or. st == HD_BAD_STEPS) .and. stk == HD_BAD_PAIR .and. &
                             stats%e_mean == 0.0_wp, 'N = n_min - 1: unreachable, invalid pair, zero stats, ' // &
                             hertzdamp_law_name(i))
            end if
        end do
    end subroutine bad_init

    !> init with these arguments gives `want`, a pair that kd refuses, and the C and
    !> legacy forms give the same status.
    subroutine expect(e, law, iend, host, steps, want, what)
        real(wp), intent(in) :: e, steps
        integer, intent(in) :: law, iend, host, want
        character(len=*), intent(in) :: what
        type(hertzdamp_pair_t) :: p
        real(c_double) :: pl(8)
        real(wp) :: k, d
        integer :: st, stk
        integer(c_int) :: stc, stl
        call hertzdamp_pair_init(e, law, iend, host, steps, p, st)
        call hertzdamp_pair_kd(p, 1.0e-4_wp, 1.0_wp, 1.0_wp, k, d, stk)
        stc = hertzdamp_c_pair_init(e, int(law, c_int), int(iend, c_int), int(host, c_int), steps, p)
        call legacy_pair_init(e, int(law, c_int), int(iend, c_int), int(host, c_int), steps, pl, stl)
        call s%check(st == want .and. stk == HD_BAD_PAIR .and. k == 0.0_wp .and. d == 0.0_wp .and. stc == want &
                     .and. stl == want, 'init, ' // what // ': its status, kd refuses the pair')
    end subroutine expect

    !> Every bad argument of hertzdamp_pair_kd: its status (the last bad one of T_c, m, u,
    !> k_phys; then the pair), k = d = 0.
    subroutine bad_kd()
        type(hertzdamp_pair_t) :: p, bad_pair
        real(wp) :: k, d, ts, bads(5)
        integer :: st, i
        integer(c_int) :: stc
        logical :: b
        bads = [0.0_wp, -1.0_wp, nan, inf, -inf]
        call hertzdamp_pair_init(0.5_wp, 0, HD_END_OVERLAP, HD_HOST_NONE, 0.0_wp, p, st)
        do i = 1, size(bads)
            call hertzdamp_pair_kd(p, bads(i), 1.0_wp, 1.0_wp, k, d, st, tstar=ts, bound_active=b)
            call s%check(st == HD_BAD_TIME .and. k == 0.0_wp .and. d == 0.0_wp .and. ts == 0.0_wp .and. .not. b, &
                         'kd: bad T_c -> HD_BAD_TIME, zeros')
            call hertzdamp_pair_kd(p, 1.0e-4_wp, bads(i), 1.0_wp, k, d, st)
            call s%check(st == HD_BAD_MASS .and. k == 0.0_wp .and. d == 0.0_wp, 'kd: bad m -> HD_BAD_MASS')
            call hertzdamp_pair_kd(p, 1.0e-4_wp, 1.0_wp, bads(i), k, d, st)
            call s%check(st == HD_BAD_VELOCITY .and. k == 0.0_wp .and. d == 0.0_wp, 'kd: bad u -> HD_BAD_VELOCITY')
            call hertzdamp_pair_kd(p, 1.0e-4_wp, 1.0_wp, 1.0_wp, k, d, st, k_phys=bads(i))
            call s%check(st == HD_BAD_KPHYS .and. k == 0.0_wp .and. d == 0.0_wp, 'kd: bad k_phys -> HD_BAD_KPHYS')
            call hertzdamp_pair_kd(p, 1.0e-4_wp, 1.0e300_wp, 1.0e-300_wp, k, d, st, k_phys=bads(i))
            call s%check(st == HD_BAD_KPHYS .and. k == 0.0_wp, 'kd, log path: bad k_phys -> HD_BAD_KPHYS')
        end do
        call hertzdamp_pair_kd(p, -1.0_wp, nan, 1.0_wp, k, d, st)
        call s%check(st == HD_BAD_MASS, 'kd: bad T_c and m -> HD_BAD_MASS (the last one checked)')
        call hertzdamp_pair_kd(bad_pair, -1.0_wp, 1.0_wp, 1.0_wp, k, d, st)
        call s%check(st == HD_BAD_TIME, 'kd: the arguments are checked before the pair')
        call hertzdamp_pair_kd(p, 1.0e-300_wp, 1.0e300_wp, 1.0_wp, k, d, st)
        call s%check(st /= HD_OK .and. k == 0.0_wp .and. d == 0.0_wp, 'kd: a k beyond double precision is a status')
        ! C: NULL pointers; k_phys <= 0 is no bound there
        stc = hertzdamp_c_pair_kd(p, 1.0e-4_wp, 1.0_wp, 1.0_wp, 0.0_wp, k)
        call s%check(stc == HD_BAD_ARGUMENT, 'C kd: d = NULL -> HD_BAD_ARGUMENT')
        stc = hertzdamp_c_pair_kd(tc=1.0e-4_wp, m=1.0_wp, u=1.0_wp, k_phys=0.0_wp, k=k, d=d)
        call s%check(stc == HD_BAD_ARGUMENT, 'C kd: p = NULL -> HD_BAD_ARGUMENT')
        stc = hertzdamp_c_pair_init(0.5_wp, 0_c_int, 0_c_int, 0_c_int, 0.0_wp)
        call s%check(stc == HD_BAD_ARGUMENT, 'C init: p = NULL -> HD_BAD_ARGUMENT')
        stc = hertzdamp_c_pair_kd(p, 1.0e-4_wp, 1.0_wp, 1.0_wp, nan, k, d)
        call s%check(stc == HD_BAD_KPHYS, 'C kd: k_phys NaN -> HD_BAD_KPHYS (only <= 0 means none)')
    end subroutine bad_kd

    !> Pairs that init did not set: HD_BAD_PAIR, k = d = 0.
    subroutine invalid_pairs()
        type(hertzdamp_pair_t) :: p, q, fresh
        real(wp) :: k, d, v(8), r
        integer :: st, i, j, nbad
        real(c_double) :: pl(8)
        call hertzdamp_pair_kd(fresh, 1.0e-4_wp, 1.0_wp, 1.0_wp, k, d, st)
        call s%check(st == HD_BAD_PAIR .and. k == 0.0_wp .and. d == 0.0_wp, 'a pair never set: HD_BAD_PAIR')
        call hertzdamp_pair_init(0.5_wp, HD_DAMPING_TSUJI, HD_END_FORCE, HD_HOST_NONE, 0.0_wp, p, st)
        q = p
        call hertzdamp_pair_kd(q, 1.0e-4_wp, 1.0_wp, 1.0_wp, k, d, st)
        call s%check(st == HD_OK, 'a copy of a valid pair is valid')
        ! each field changed: by one ulp, to zero, to the value of another pair
        nbad = 0
        v = [p%alpha, p%tau_c, p%alpha_cont, p%steps, p%law, p%iend, p%host, p%marker]
        do i = 1, 8
            do j = 1, 3
                pl = v
                select case (j)
                case (1)
                    pl(i) = nearest(v(i), 1.0_wp)
                case (2)
                    pl(i) = merge(1.0_wp, 0.0_wp, v(i) == 0.0_wp)
                case default
                    pl(i) = v(i) + 1.0_wp
                end select
                q = header(pl, p)
                call hertzdamp_pair_kd(q, 1.0e-4_wp, 1.0_wp, 1.0_wp, k, d, st)
                if (st /= HD_BAD_PAIR .or. k /= 0.0_wp .or. d /= 0.0_wp) nbad = nbad + 1
            end do
        end do
        call s%check(nbad == 0, 'every field of a pair changed (1 ulp, 0, +1): HD_BAD_PAIR, zeros')
        ! random bit patterns
        nbad = 0
        do i = 1, 1000
            do j = 1, 8
                call random_number(r)
                pl(j) = transfer(int(r * 2.0_wp**62, int64) * 3_int64 + 12345_int64 * i, 1.0_wp)
            end do
            q = header(pl, p)
            call hertzdamp_pair_kd(q, 1.0e-4_wp, 1.0_wp, 1.0_wp, k, d, st)
            if (st /= HD_BAD_PAIR) nbad = nbad + 1
        end do
        call s%check(nbad == 0, '1000 random bit patterns: HD_BAD_PAIR')
        call tampered_pairs()
    end subroutine invalid_pairs

    !> Issue 30, defect 1: changes that an exclusive-or marker cannot see (two fields swapped,
    !> two bits of one field flipped, both signs flipped) are refused; and a pair forged with a
    !> matching marker (computed here by the keyed hash the module documents, written again
    !> independently) is still refused when a field is out of range (law 7, alpha NaN or
    !> negative, steps -1 or 1e6, tau_c 0, host 99).
    subroutine tampered_pairs()
        type(hertzdamp_pair_t) :: p, q
        real(wp) :: k, d, nan
        integer :: st, i, nbad
        integer(int64) :: b
        nan = ieee_value(1.0_wp, ieee_quiet_nan)
        ! law 1 and host 3 (differ, so that swapping them is a change)
        call hertzdamp_pair_init(0.5_wp, HD_DAMPING_TSUJI, HD_END_FORCE, HD_HOST_MFIX_AB2, 20.0_wp, p, st)
        call s%check(st == HD_OK, 'the pair the tampering starts from is valid')
        q = p
        q%alpha = p%tau_c
        q%tau_c = p%alpha
        call expect_bad(q, 'alpha and tau_c swapped')
        q = p
        q%law = p%host
        q%host = p%law
        call expect_bad(q, 'law and host swapped')
        q = p
        q%alpha_cont = p%steps
        q%steps = p%alpha_cont
        call expect_bad(q, 'alpha(e) and steps swapped')
        q = p
        q%alpha = -p%alpha
        q%tau_c = -p%tau_c
        call expect_bad(q, 'alpha and tau_c both negated')
        q = p
        q%alpha = 0.5_wp * p%alpha
        call expect_bad(q, 'alpha halved')
        nbad = 0
        do i = 0, 31
            q = p
            b = transfer(p%alpha, b)
            q%alpha = transfer(ieor(b, ior(shiftl(1_int64, i), shiftl(1_int64, i + 32))), 1.0_wp)
            call hertzdamp_pair_kd(q, 1.0e-4_wp, 1.0_wp, 1.0_wp, k, d, st)
            if (st /= HD_BAD_PAIR) nbad = nbad + 1
            q = p
            b = transfer(p%tau_c, b)
            q%tau_c = transfer(ieor(b, ior(shiftl(1_int64, i), shiftl(1_int64, i + 20))), 1.0_wp)
            call hertzdamp_pair_kd(q, 1.0e-4_wp, 1.0_wp, 1.0_wp, k, d, st)
            if (st /= HD_BAD_PAIR) nbad = nbad + 1
        end do
        call s%check(nbad == 0, 'two bits of alpha (i, i + 32) or tau_c (i, i + 20) flipped, i = 0..31: HD_BAD_PAIR')
        call every_flip()
        ! forged with a matching marker: the range checks
        q = p
        call seal(q)
        call hertzdamp_pair_kd(q, 1.0e-4_wp, 1.0_wp, 1.0_wp, k, d, st)
        call s%check(st == HD_OK .and. q%marker == p%marker, 'the test''s own keyed hash reproduces the marker')
        q = p
        q%law = 7.0_wp
        call forged(q, 'law 7')
        q = p
        q%alpha = nan
        call forged(q, 'alpha NaN')
        q = p
        q%alpha = -p%alpha
        q%tau_c = -p%tau_c
        call forged(q, 'alpha and tau_c negated')
        q = p
        q%steps = -1.0_wp
        call forged(q, 'steps -1')
        q = p
        q%steps = 1.0e6_wp
        call forged(q, 'steps 1e6')
        q = p
        q%iend = 2.0_wp
        call forged(q, 'end 2')
        q = p
        q%alpha_cont = huge(1.0_wp)
        call forged(q, 'alpha(e) huge')
        q = p
        q%tau_c = 0.0_wp
        call forged(q, 'tau_c 0')
        q = p
        q%host = 99.0_wp
        call forged(q, 'host 99')
    end subroutine tampered_pairs

    !> Every one- and two-bit flip of the eight header doubles (the marker included: 512
    !> bits, 131,328 flips per pair), for pairs whose fields are partly zero (law, end and
    !> host 0: the adversarial round found the first marker accepting flips of bits 31 and 32
    !> of one such field, the additive one flips of two fields' high exponent bits):
    !> hertzdamp_pair_kd refuses every one (HD_BAD_PAIR).
    subroutine every_flip()
        type(hertzdamp_pair_t) :: p, q
        real(wp) :: k, d, f(8), g(8)
        integer :: st, i, j, c, nacc
        integer, parameter :: laws(3) = [HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO]
        integer, parameter :: ends(3) = [HD_END_OVERLAP, HD_END_FORCE, HD_END_OVERLAP]
        integer, parameter :: hosts(3) = [HD_HOST_NONE, HD_HOST_LAMMPS, HD_HOST_MFIX_AB2]
        real(wp), parameter :: es(3) = [0.9_wp, 0.5_wp, 0.2_wp], ns(3) = [10.0_wp, 10.0_wp, 11.0_wp]
        nacc = 0
        do c = 1, 3
            call hertzdamp_pair_init(es(c), laws(c), ends(c), hosts(c), ns(c), p, st)
            call s%check(st == HD_OK, 'every_flip: the pair is valid')
            f = [p%alpha, p%tau_c, p%alpha_cont, p%steps, p%law, p%iend, p%host, p%marker]
            do i = 0, 511
                do j = i, 511
                    g = f
                    g(shiftr(i, 6) + 1) = transfer(ieor(transfer(g(shiftr(i, 6) + 1), 0_int64), &
                                                        shiftl(1_int64, iand(i, 63))), 1.0_wp)
                    if (j > i) g(shiftr(j, 6) + 1) = transfer(ieor(transfer(g(shiftr(j, 6) + 1), 0_int64), &
                                                                  shiftl(1_int64, iand(j, 63))), 1.0_wp)
                    q = p
                    q%alpha = g(1); q%tau_c = g(2); q%alpha_cont = g(3); q%steps = g(4)
                    q%law = g(5); q%iend = g(6); q%host = g(7); q%marker = g(8)
                    call hertzdamp_pair_kd(q, 1.0e-5_wp, 1.0e-3_wp, 1.0_wp, k, d, st)
                    if (st /= HD_BAD_PAIR) nacc = nacc + 1
                end do
            end do
        end do
        call s%check(nacc == 0, 'every one- and two-bit flip of the header of three pairs: HD_BAD_PAIR')
        if (nacc /= 0) print '(a, i0)', '  flips accepted: ', nacc
    end subroutine every_flip

    !> The pair pp with its eight header fields replaced by h.
    pure type(hertzdamp_pair_t) function header(h, pp) result(q)
        real(wp), intent(in) :: h(8)
        type(hertzdamp_pair_t), intent(in) :: pp
        q = pp
        q%alpha = h(1)
        q%tau_c = h(2)
        q%alpha_cont = h(3)
        q%steps = h(4)
        q%law = h(5)
        q%iend = h(6)
        q%host = h(7)
        q%marker = h(8)
    end function header

    !> A tampered pair gives HD_BAD_PAIR and k = d = 0.
    subroutine expect_bad(pp, what)
        type(hertzdamp_pair_t), intent(in) :: pp
        character(len=*), intent(in) :: what
        real(wp) :: k, d
        integer :: st
        call hertzdamp_pair_kd(pp, 1.0e-4_wp, 1.0_wp, 1.0_wp, k, d, st)
        call s%check(st == HD_BAD_PAIR .and. k == 0.0_wp .and. d == 0.0_wp, 'tampered pair (' // what // &
                     '): HD_BAD_PAIR, k = d = 0')
    end subroutine expect_bad

    !> A pair forged with a matching marker (seal) and one field out of range: refused by the
    !> module and the C call.
    subroutine forged(pp, what)
        type(hertzdamp_pair_t), intent(inout) :: pp
        character(len=*), intent(in) :: what
        real(wp) :: kk, dd
        integer(c_int) :: stc
        call seal(pp)
        call expect_bad(pp, 'forged with a matching marker, ' // what)
        stc = hertzdamp_c_pair_kd(pp, 1.0e-4_wp, 1.0_wp, 1.0_wp, 0.0_wp, kk, dd)
        call s%check(stc == HD_BAD_PAIR .and. kk == 0.0_wp .and. dd == 0.0_wp, &
                     'C hertzdamp_c_pair_kd: forged pair (' // what // '): HD_BAD_PAIR')
    end subroutine forged

    !> The marker of the module note, written again here: each of the seven header fields'
    !> bit patterns xored with itself rotated by the field's amount (51, 46, 24, 48, 42, 21,
    !> 35), the seven xored, the top 12 bits folded onto the low ones; the low 52 bits as the
    !> fraction of a number in [1, 2).
    subroutine seal(pp)
        type(hertzdamp_pair_t), intent(inout) :: pp
        integer, parameter :: r(7) = [51, 46, 24, 48, 42, 21, 35]
        real(wp) :: f(7)
        integer(int64) :: h, x
        integer :: j
        f = [pp%alpha, pp%tau_c, pp%alpha_cont, pp%steps, pp%law, pp%iend, pp%host]
        h = 0_int64
        do j = 1, 7
            x = transfer(f(j), x)
            h = ieor(h, ieor(x, ishftc(x, r(j))))
        end do
        h = ieor(h, shiftr(h, 52))
        pp%marker = transfer(ior(iand(h, int(z'000FFFFFFFFFFFFF', int64)), transfer(1.0_wp, h)), 1.0_wp)
    end subroutine seal

    !> The C functions a host's log uses: hertzdamp_c_pair_stats of a host-exact pair in
    !> its own scheme gives the target (phase means e and T_c/(N dt) = 1, the identity the
    !> constants are solved for), and in the continuous model (host none) no spread;
    !> hertzdamp_c_host_min_steps equals the module's hertzdamp_host_min_steps; bad pairs
    !> and NULL arguments give their statuses and zero outputs.
    subroutine c_stats_and_min_steps()
        integer, parameter :: hosts(3) = [HD_HOST_LAMMPS, HD_HOST_MFIX_AB2, HD_HOST_LAMMPS_PHASE]
        real(wp), parameter :: es(2) = [0.2_wp, 0.9_wp]
        type(hertzdamp_pair_t) :: p
        real(c_double) :: st8(8)
        integer(c_int) :: stc, nc
        integer :: ih, ie, lw, ie2, nm, st, nbad_stats, nbad_none, nbad_min
        nbad_stats = 0; nbad_none = 0; nbad_min = 0
        do lw = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
            do ie2 = HD_END_OVERLAP, HD_END_FORCE
                do ih = 1, size(hosts)
                    do ie = 1, size(es)
                        stc = hertzdamp_c_pair_init(es(ie), int(lw, c_int), int(ie2, c_int), int(hosts(ih), c_int), &
                                                    20.0_wp, p)
                        if (stc /= HD_OK) then
                            nbad_stats = nbad_stats + 1
                            cycle
                        end if
                        stc = hertzdamp_c_pair_stats(p, int(hosts(ih), c_int), st8)
                        if (stc /= HD_OK .or. abs(st8(1) / es(ie) - 1.0_wp) > 1.0e-9_wp .or. &
                            abs(st8(5) - 1.0_wp) > 1.0e-9_wp .or. .not. (st8(3) <= st8(1) .and. st8(1) <= st8(4)) &
                            .or. st8(2) <= 0.0_wp) nbad_stats = nbad_stats + 1
                        stc = hertzdamp_c_pair_stats(p, int(HD_HOST_NONE, c_int), st8)
                        if (stc /= HD_OK .or. st8(2) /= 0.0_wp .or. st8(6) /= 0.0_wp .or. st8(3) /= st8(4)) then
                            nbad_none = nbad_none + 1
                        end if
                        call hertzdamp_host_min_steps(es(ie), lw, ie2, hosts(ih), nm, st)
                        stc = hertzdamp_c_host_min_steps(es(ie), int(lw, c_int), int(ie2, c_int), &
                                                         int(hosts(ih), c_int), nc)
                        if (stc /= st .or. nc /= nm) nbad_min = nbad_min + 1
                    end do
                end do
            end do
        end do
        call s%check(nbad_stats == 0, 'C hertzdamp_c_pair_stats of a host-exact pair (N = 20, every law, end, ' // &
                     'lammps/mfix-ab2/lammps-phase, e = 0.2, 0.9): phase means e and T_c/(N dt) equal the target ' // &
                     'to 1e-9, min <= mean <= max, spread > 0')
        call s%check(nbad_none == 0, 'C hertzdamp_c_pair_stats with host none: no spread')
        call s%check(nbad_min == 0, 'C hertzdamp_c_host_min_steps = hertzdamp_host_min_steps (status and N)')
        p = hertzdamp_pair_t()
        st8 = 1.0_wp
        stc = hertzdamp_c_pair_stats(p, int(HD_HOST_LAMMPS, c_int), st8)
        call s%check(stc == HD_BAD_PAIR .and. all(st8 == 0.0_wp), 'C hertzdamp_c_pair_stats: a pair not set by ' // &
                     'init gives HD_BAD_PAIR and zero stats')
        stc = hertzdamp_c_pair_stats(stats=st8, host=int(HD_HOST_LAMMPS, c_int))
        call s%check(stc == HD_BAD_ARGUMENT, 'C hertzdamp_c_pair_stats: NULL pair gives HD_BAD_ARGUMENT')
        stc = hertzdamp_c_host_min_steps(0.5_wp, 0_c_int, 0_c_int, int(HD_HOST_LAMMPS, c_int))
        call s%check(stc == HD_BAD_ARGUMENT, 'C hertzdamp_c_host_min_steps: NULL n_min gives HD_BAD_ARGUMENT')
        stc = hertzdamp_c_host_min_steps(0.5_wp, 0_c_int, 0_c_int, -1_c_int, nc)
        call s%check(stc == HD_BAD_HOST .and. nc == 0, 'C hertzdamp_c_host_min_steps: host -1 gives HD_BAD_HOST, 0')
    end subroutine c_stats_and_min_steps

end program test_pair
