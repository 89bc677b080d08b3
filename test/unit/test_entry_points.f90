!> Every way of calling the fit inverse gives the same bits (issue 11), for every damping
!> law (issue 15): the module's scalar call, its elemental call on a rank-2 array, its
!> rank-1 (vectorised) call, the per-pair API (hertzdamp_pair_init + hertzdamp_pair_kd),
!> the C functions (hertzdamp_c_invert, hertzdamp_c_invert_n, hertzdamp_c_invert_bounded;
!> hertzdamp_c_invert_law,
!> hertzdamp_c_invert_law_n) through their bind(C) names, and the legacy externals
!> (HERTZDAMP_INVERT, HERTZDAMP_INVERT_N, HERTZDAMP_INVERT_BOUNDED; HERTZDAMP_INVERT_LAW,
!> HERTZDAMP_INVERT_LAW_N), on a grid that takes each argument through its edge cases
!> (e = 1, e_min and one ulp beyond, 0, -0, NaN, Inf; T_c, m, u at the ends of the direct
!> range [1e-30, 1e30] and beyond, 0, negative, NaN, Inf; k_phys soft, stiff, invalid;
!> bad contact ends and laws).  The linear law through the law entry points gives the
!> bits of the linear ones.  Also the dimensionless kernels (scalar against n at once,
!> every law) and the forward map.
program test_entry_points
    use hertzdamp, only: hertzdamp_rk, hertzdamp_invert, hertzdamp_invert_options, hertzdamp_fit_inverse, &
                         hertzdamp_fit_inverse_n, hertzdamp_fit_forward, hertzdamp_fit_forward_n, &
                         hertzdamp_fit_alpha_c, HD_OK, HD_END_OVERLAP, HD_END_FORCE, HD_METHOD_FIT, HD_BAD_LAW, &
                         HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO, hertzdamp_law_name, hertzdamp_pair_t, &
                         hertzdamp_pair_init, hertzdamp_pair_kd, HD_HOST_NONE, HD_BAD_PAIR
    use hertzdamp_capi, only: hertzdamp_c_invert, hertzdamp_c_invert_n, hertzdamp_c_invert_bounded, &
                              hertzdamp_c_invert_law, hertzdamp_c_invert_law_n
    use hertzdamp_testing, only: test_suite, new_suite
    use, intrinsic :: iso_c_binding, only: c_int, c_double
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
    implicit none

    interface
        subroutine hertzdamp_invert_legacy(e, tc, m, u, iend, k, d, ierr) bind(c, name='hertzdamp_invert_')
            import :: c_double, c_int
            implicit none
            real(c_double), intent(in) :: e, tc, m, u
            integer(c_int), intent(in) :: iend
            real(c_double), intent(out) :: k, d
            integer(c_int), intent(out) :: ierr
        end subroutine hertzdamp_invert_legacy
        subroutine hertzdamp_invert_n_legacy(n, e, tc, m, u, iend, k, d, ierr) bind(c, name='hertzdamp_invert_n_')
            import :: c_double, c_int
            implicit none
            integer(c_int), intent(in) :: n
            real(c_double), intent(in) :: e(n), tc(n), m(n), u(n)
            integer(c_int), intent(in) :: iend
            real(c_double), intent(out) :: k(n), d(n)
            integer(c_int), intent(out) :: ierr(n)
        end subroutine hertzdamp_invert_n_legacy
        subroutine hertzdamp_invert_bounded_legacy(e, tc, m, u, kphys, iend, k, d, ierr) &
                bind(c, name='hertzdamp_invert_bounded_')
            import :: c_double, c_int
            implicit none
            real(c_double), intent(in) :: e, tc, m, u, kphys
            integer(c_int), intent(in) :: iend
            real(c_double), intent(out) :: k, d
            integer(c_int), intent(out) :: ierr
        end subroutine hertzdamp_invert_bounded_legacy
        subroutine hertzdamp_invert_law_legacy(e, tc, m, u, kphys, ilaw, iend, k, d, ierr) &
                bind(c, name='hertzdamp_invert_law_')
            import :: c_double, c_int
            implicit none
            real(c_double), intent(in) :: e, tc, m, u, kphys
            integer(c_int), intent(in) :: ilaw, iend
            real(c_double), intent(out) :: k, d
            integer(c_int), intent(out) :: ierr
        end subroutine hertzdamp_invert_law_legacy
        subroutine hertzdamp_invert_law_n_legacy(n, e, tc, m, u, ilaw, iend, k, d, ierr) &
                bind(c, name='hertzdamp_invert_law_n_')
            import :: c_double, c_int
            implicit none
            integer(c_int), intent(in) :: n
            real(c_double), intent(in) :: e(n), tc(n), m(n), u(n)
            integer(c_int), intent(in) :: ilaw, iend
            real(c_double), intent(out) :: k(n), d(n)
            integer(c_int), intent(out) :: ierr(n)
        end subroutine hertzdamp_invert_law_n_legacy
    end interface

    integer, parameter :: wp = hertzdamp_rk
    type(test_suite) :: s
    real(wp), allocatable :: es(:), xs(:), e(:), tc(:), m(:), u(:), kp(:)
    real(wp) :: nan, inf
    integer :: iend, law

    s = new_suite('test_entry_points')
    nan = ieee_value(1.0_wp, ieee_quiet_nan)
    inf = ieee_value(1.0_wp, ieee_positive_inf)
    ! edge cases of e (both ends' e_min) and of the dimensional arguments
    es = [1.0_wp, nearest(1.0_wp, -1.0_wp), 0.999_wp, 0.9_wp, 0.5_wp, 0.05_wp, 1.0e-2_wp, 1.0e-3_wp, &
          nearest(1.0e-3_wp, -1.0_wp), 5.0e-4_wp, 1.0e-4_wp, nearest(1.0e-4_wp, -1.0_wp), 0.0_wp, -0.0_wp, -0.5_wp, &
          nearest(1.0_wp, 2.0_wp), 2.0_wp, nan, inf, -inf]
    xs = [1.0_wp, 1.0e-3_wp, 1.0e-30_wp, nearest(1.0e-30_wp, -1.0_wp), 1.0e30_wp, nearest(1.0e30_wp, 2.0_wp), &
          1.0e-35_wp, 1.0e35_wp, tiny(1.0_wp), huge(1.0_wp), 0.0_wp, -1.0_wp, nan, inf]
    call make_grid(es, xs, e, tc, m, u)
    call soft_and_stiff(e, tc, m, u, kp)

    do iend = -1, 2
        call compare_inverse(iend)
        call compare_bounded(iend)
        do law = -1, HD_DAMPING_KUWABARA_KONO + 1
            call compare_law(iend, law)
            call compare_law_bounded(iend, law)
        end do
    end do
    call compare_kernels()
    call s%finish()

contains

    !> All combinations of es with one of tc, m, u taken from xs (the others 1e-4 s,
    !> 1e-3 kg, 1 m/s), then random contacts over 1e-20 .. 1e20, then random valid ones.
    subroutine make_grid(es, xs, e, tc, m, u)
        real(wp), intent(in) :: es(:), xs(:)
        real(wp), allocatable, intent(out) :: e(:), tc(:), m(:), u(:)
        real(wp) :: r(4)
        integer :: i, j, which
        allocate (e(0), tc(0), m(0), u(0))
        do i = 1, size(es)
            do which = 0, 3
                do j = 1, size(xs)
                    e = [e, es(i)]
                    tc = [tc, merge(xs(j), 1.0e-4_wp, which == 1)]
                    m = [m, merge(xs(j), 1.0e-3_wp, which == 2)]
                    u = [u, merge(xs(j), 1.0_wp, which == 3)]
                end do
            end do
        end do
        do i = 1, 2000
            call random_number(r)
            e = [e, 10.0_wp**(-4.2_wp * r(1))]
            tc = [tc, 10.0_wp**(-20.0_wp + 40.0_wp * r(2))]
            m = [m, 10.0_wp**(-20.0_wp + 40.0_wp * r(3))]
            u = [u, 10.0_wp**(-20.0_wp + 40.0_wp * r(4))]
        end do
        ! then 768 contacts all valid for every law and end (e in [1e-3, 1], T_c, m, u in the
        ! direct range, its ends among them): whole passes of 256 that the array forms serve
        ! by the fused kernel (the passes above hold invalid contacts)
        do i = 1, 768
            call random_number(r)
            e = [e, merge(1.0_wp, 10.0_wp**(-3.0_wp * r(1)), mod(i, 97) == 0)]
            tc = [tc, merge(1.0e-30_wp, 10.0_wp**(-20.0_wp + 40.0_wp * r(2)), mod(i, 89) == 0)]
            m = [m, merge(1.0e30_wp, 10.0_wp**(-20.0_wp + 40.0_wp * r(3)), mod(i, 83) == 0)]
            u = [u, merge(1.0e-30_wp, 10.0_wp**(-20.0_wp + 40.0_wp * r(4)), mod(i, 79) == 0)]
        end do
        e(size(e)) = 1.0e-3_wp
    end subroutine make_grid

    !> k_phys for the bounded calls: alternately soft (bound active), stiff, and the
    !> invalid values 0, -1, NaN, Inf.
    subroutine soft_and_stiff(e, tc, m, u, kp)
        real(wp), intent(in) :: e(:), tc(:), m(:), u(:)
        real(wp), allocatable, intent(out) :: kp(:)
        real(wp) :: k, d
        integer :: i, st
        allocate (kp(size(e)))
        do i = 1, size(e)
            call hertzdamp_invert(e(i), tc(i), m(i), u(i), HD_END_OVERLAP, k, d, st)
            if (st /= HD_OK) k = 1.0e6_wp
            select case (mod(i, 8))
            case (0, 1, 2)
                kp(i) = 0.5_wp * k
            case (3, 4)
                kp(i) = 2.0_wp * k
            case (5)
                kp(i) = 0.0_wp
            case (6)
                kp(i) = -1.0_wp
            case default
                kp(i) = merge(nan, inf, mod(i, 16) == 7)
            end select
        end do
    end subroutine soft_and_stiff

    !> Bit patterns (NaN-safe, -0 distinct from +0).
    elemental integer(int64) function bits(x)
        real(wp), intent(in) :: x
        bits = transfer(x, 0_int64)
    end function bits

    subroutine compare_inverse(iend)
        integer, intent(in) :: iend
        real(wp), dimension(size(e)) :: k0, d0, a0, t0, s0, k, d, a, t, ts
        real(wp), allocatable :: e2(:, :), tc2(:, :), m2(:, :), u2(:, :), k2(:, :), d2(:, :)
        integer, dimension(size(e)) :: st0, st
        integer(c_int), dimension(size(e)) :: stc
        integer(c_int) :: sc
        integer, allocatable :: st2(:, :)
        integer :: i, n, nbad(8)
        character(len=3) :: cend
        write (cend, '(i0)') iend
        n = size(e)
        ! reference: the module's scalar call, one contact at a time
        do i = 1, n
            call hertzdamp_invert(e(i), tc(i), m(i), u(i), iend, k0(i), d0(i), st0(i), alpha=a0(i), tau_c=t0(i), &
                                  tstar=s0(i))
        end do
        nbad = 0
        ! rank-1 (vectorised) call with every optional output
        call hertzdamp_invert(e, tc, m, u, iend, k, d, st, alpha=a, tau_c=t, tstar=ts)
        nbad(1) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. st /= st0 .or. bits(a) /= bits(a0) &
                        .or. bits(t) /= bits(t0) .or. bits(ts) /= bits(s0))
        ! elemental call on rank-2 arrays
        e2 = reshape(e(1:2 * (n / 2)), [2, n / 2])
        tc2 = reshape(tc(1:2 * (n / 2)), [2, n / 2])
        m2 = reshape(m(1:2 * (n / 2)), [2, n / 2])
        u2 = reshape(u(1:2 * (n / 2)), [2, n / 2])
        allocate (k2(2, n / 2), d2(2, n / 2), st2(2, n / 2))
        call hertzdamp_invert(e2, tc2, m2, u2, iend, k2, d2, st2)
        nbad(2) = count(bits(reshape(k2, [2 * (n / 2)])) /= bits(k0(1:2 * (n / 2))) .or. &
                        bits(reshape(d2, [2 * (n / 2)])) /= bits(d0(1:2 * (n / 2))) .or. &
                        reshape(st2, [2 * (n / 2)]) /= st0(1:2 * (n / 2)))
        ! the per-pair API: one pair per contact, then its k and d (one call per contact, and
        ! elemental over arrays of pairs)
        do i = 1, n
            call via_pair(e(i), tc(i), m(i), u(i), iend, HD_DAMPING_LINEAR, k(i), d(i), st(i))
        end do
        nbad(3) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. st /= st0)
        call via_pairs(e, tc, m, u, iend, HD_DAMPING_LINEAR, k, d, st, a, t, ts)
        nbad(4) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. st /= st0 .or. bits(ts) /= bits(s0))
        ! C: one contact per call, and n at once
        do i = 1, n
            stc(i) = hertzdamp_c_invert(e(i), tc(i), m(i), u(i), int(iend, c_int), k(i), d(i))
        end do
        nbad(5) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. stc /= st0)
        sc = hertzdamp_c_invert_n(int(n, c_int), e, tc, m, u, int(iend, c_int), k, d, stc)
        nbad(6) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. stc /= st0)
        call s%check(sc == first_failure(st0), 'C invert_n returns the first non-zero status, end ' // cend)
        ! legacy externals
        do i = 1, n
            call hertzdamp_invert_legacy(e(i), tc(i), m(i), u(i), int(iend, c_int), k(i), d(i), stc(i))
        end do
        nbad(7) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. stc /= st0)
        call hertzdamp_invert_n_legacy(int(n, c_int), e, tc, m, u, int(iend, c_int), k, d, stc)
        nbad(8) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. stc /= st0)
        call s%check(nbad(1) == 0, 'rank-1 call (with alpha, tau_c, tstar) = scalar calls, bit for bit, end ' // cend)
        call s%check(nbad(2) == 0, 'elemental rank-2 call = scalar calls, end ' // cend)
        call s%check(nbad(3) == 0, 'hertzdamp_pair_init + hertzdamp_pair_kd = module, end ' // cend)
        call s%check(nbad(4) == 0, 'pair_init + pair_kd elemental over arrays of pairs (with tstar) = module, end ' // &
                     cend)
        call s%check(nbad(5) == 0, 'hertzdamp_c_invert = module, end ' // cend)
        call s%check(nbad(6) == 0, 'hertzdamp_c_invert_n = module, end ' // cend)
        call s%check(nbad(7) == 0, 'HERTZDAMP_INVERT = module, end ' // cend)
        call s%check(nbad(8) == 0, 'HERTZDAMP_INVERT_N = module, end ' // cend)
        if (any(nbad /= 0)) print '(a, 8i6)', 'mismatches per entry point: ', nbad
        ! the grid reaches the fast path and the general one
        if (iend == HD_END_OVERLAP .or. iend == HD_END_FORCE) then
            call s%check(count(st0 == HD_OK) > n / 2 .and. count(st0 /= HD_OK) > 100, &
                         'grid covers successes and failures, end ' // cend)
        end if
    end subroutine compare_inverse

    integer function first_failure(st)
        integer, intent(in) :: st(:)
        integer :: i
        first_failure = HD_OK
        do i = 1, size(st)
            if (st(i) /= HD_OK) then
                first_failure = st(i)
                return
            end if
        end do
    end function first_failure

    subroutine compare_bounded(iend)
        integer, intent(in) :: iend
        real(wp), dimension(size(e)) :: k0, d0, k, d
        integer, dimension(size(e)) :: st0, st
        integer(c_int), dimension(size(e)) :: stc
        logical, dimension(size(e)) :: b0, b
        integer :: i, n, nbad(4)
        character(len=3) :: cend
        write (cend, '(i0)') iend
        n = size(e)
        do i = 1, n
            call hertzdamp_invert(e(i), tc(i), m(i), u(i), iend, k0(i), d0(i), st0(i), bound_active=b0(i), &
                                  k_phys=kp(i), options=hertzdamp_invert_options(method=HD_METHOD_FIT))
        end do
        call hertzdamp_invert(e, tc, m, u, iend, k, d, st, bound_active=b, k_phys=kp)
        nbad(1) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. st /= st0 .or. (b .neqv. b0))
        do i = 1, n
            call via_pair(e(i), tc(i), m(i), u(i), iend, HD_DAMPING_LINEAR, k(i), d(i), st(i), kp(i), b(i))
        end do
        nbad(2) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. st /= st0 .or. (b .neqv. b0))
        do i = 1, n
            stc(i) = hertzdamp_c_invert_bounded(e(i), tc(i), m(i), u(i), kp(i), int(iend, c_int), k(i), d(i))
        end do
        nbad(3) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. stc /= st0)
        do i = 1, n
            call hertzdamp_invert_bounded_legacy(e(i), tc(i), m(i), u(i), kp(i), int(iend, c_int), k(i), d(i), stc(i))
        end do
        nbad(4) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. stc /= st0)
        call s%check(nbad(1) == 0, 'bounded: rank-1 call = scalar calls, end ' // cend)
        call s%check(nbad(2) == 0, 'bounded: pair_init + pair_kd with k_phys = module, end ' // cend)
        call s%check(nbad(3) == 0, 'bounded: hertzdamp_c_invert_bounded = module, end ' // cend)
        call s%check(nbad(4) == 0, 'bounded: HERTZDAMP_INVERT_BOUNDED = module, end ' // cend)
        if (iend == HD_END_OVERLAP) call s%check(count(b0) > 300 .and. count(.not. b0 .and. st0 == HD_OK) > 300, &
                                                 'bounded: the bound is active on part of the grid, not all')
    end subroutine compare_bounded

    !> 'law L, end E' for the labels (laws outside the range by their code).
    function law_tag(iend, law) result(tag)
        integer, intent(in) :: iend, law
        character(len=:), allocatable :: tag
        character(len=8) :: c
        if (law >= HD_DAMPING_LINEAR .and. law <= HD_DAMPING_KUWABARA_KONO) then
            tag = 'law ' // hertzdamp_law_name(law)
        else
            write (c, '(i0)') law
            tag = 'law code ' // trim(c)
        end if
        write (c, '(i0)') iend
        tag = tag // ', end ' // trim(c)
    end function law_tag

    !> The inverse of a damping law (no bound) through every entry point against the
    !> module's scalar call with `law`; for the linear law also against the linear calls.
    subroutine compare_law(iend, law)
        integer, intent(in) :: iend, law
        real(wp), dimension(size(e)) :: k0, d0, a0, t0, s0, k, d, a, t, ts
        real(wp), allocatable :: e2(:, :), tc2(:, :), m2(:, :), u2(:, :), k2(:, :), d2(:, :)
        integer, dimension(size(e)) :: st0, st
        integer(c_int), dimension(size(e)) :: stc
        integer(c_int) :: sc
        integer, allocatable :: st2(:, :)
        integer :: i, n, nbad(9)
        character(len=:), allocatable :: tag
        tag = law_tag(iend, law)
        n = size(e)
        do i = 1, n
            call hertzdamp_invert(e(i), tc(i), m(i), u(i), iend, k0(i), d0(i), st0(i), alpha=a0(i), tau_c=t0(i), &
                                  tstar=s0(i), law=law)
        end do
        nbad = 0
        call hertzdamp_invert(e, tc, m, u, iend, k, d, st, alpha=a, tau_c=t, tstar=ts, law=law)
        nbad(1) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. st /= st0 .or. bits(a) /= bits(a0) &
                        .or. bits(t) /= bits(t0) .or. bits(ts) /= bits(s0))
        e2 = reshape(e(1:2 * (n / 2)), [2, n / 2])
        tc2 = reshape(tc(1:2 * (n / 2)), [2, n / 2])
        m2 = reshape(m(1:2 * (n / 2)), [2, n / 2])
        u2 = reshape(u(1:2 * (n / 2)), [2, n / 2])
        allocate (k2(2, n / 2), d2(2, n / 2), st2(2, n / 2))
        call hertzdamp_invert(e2, tc2, m2, u2, iend, k2, d2, st2, law=law)
        nbad(2) = count(bits(reshape(k2, [2 * (n / 2)])) /= bits(k0(1:2 * (n / 2))) .or. &
                        bits(reshape(d2, [2 * (n / 2)])) /= bits(d0(1:2 * (n / 2))) .or. &
                        reshape(st2, [2 * (n / 2)]) /= st0(1:2 * (n / 2)))
        do i = 1, n
            call via_pair(e(i), tc(i), m(i), u(i), iend, law, k(i), d(i), st(i))
        end do
        nbad(3) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. st /= st0)
        call via_pairs(e, tc, m, u, iend, law, k, d, st, a, t, ts)
        nbad(4) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. st /= st0 .or. bits(ts) /= bits(s0))
        do i = 1, n
            stc(i) = hertzdamp_c_invert_law(e(i), tc(i), m(i), u(i), 0.0_wp, int(law, c_int), int(iend, c_int), &
                                            k(i), d(i))
        end do
        nbad(5) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. stc /= st0)
        sc = hertzdamp_c_invert_law_n(int(n, c_int), e, tc, m, u, int(law, c_int), int(iend, c_int), k, d, stc)
        nbad(6) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. stc /= st0)
        call s%check(sc == first_failure(st0), 'C invert_law_n returns the first non-zero status, ' // tag)
        do i = 1, n
            call hertzdamp_invert_law_legacy(e(i), tc(i), m(i), u(i), 0.0_wp, int(law, c_int), int(iend, c_int), &
                                             k(i), d(i), stc(i))
        end do
        nbad(7) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. stc /= st0)
        call hertzdamp_invert_law_n_legacy(int(n, c_int), e, tc, m, u, int(law, c_int), int(iend, c_int), k, d, stc)
        nbad(8) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. stc /= st0)
        if (law == HD_DAMPING_LINEAR) then
            ! the linear calls: the same bits as the law calls with law = linear
            call hertzdamp_invert(e, tc, m, u, iend, k, d, st, alpha=a, tau_c=t, tstar=ts)
            nbad(9) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. st /= st0 .or. bits(a) /= bits(a0) &
                            .or. bits(t) /= bits(t0) .or. bits(ts) /= bits(s0))
            call s%check(nbad(9) == 0, 'linear calls = law calls with the linear law, ' // tag)
        end if
        call s%check(nbad(1) == 0, 'rank-1 call (with alpha, tau_c, tstar) = scalar calls, ' // tag)
        call s%check(nbad(2) == 0, 'elemental rank-2 call = scalar calls, ' // tag)
        call s%check(nbad(3) == 0, 'hertzdamp_pair_init + hertzdamp_pair_kd = module, ' // tag)
        call s%check(nbad(4) == 0, 'pair_init + pair_kd elemental over arrays of pairs (with tstar) = module, ' // tag)
        call s%check(nbad(5) == 0, 'hertzdamp_c_invert_law = module, ' // tag)
        call s%check(nbad(6) == 0, 'hertzdamp_c_invert_law_n = module, ' // tag)
        call s%check(nbad(7) == 0, 'HERTZDAMP_INVERT_LAW = module, ' // tag)
        call s%check(nbad(8) == 0, 'HERTZDAMP_INVERT_LAW_N = module, ' // tag)
        if (any(nbad /= 0)) print '(a, 9i6)', 'mismatches per entry point (' // tag // '): ', nbad
        if (law < HD_DAMPING_LINEAR .or. law > HD_DAMPING_KUWABARA_KONO) then
            ! (a bad T_c, m or u is reported before the law, as every argument check)
            call s%check(all(st0 /= HD_OK) .and. count(st0 == HD_BAD_LAW) > n / 2 .and. all(bits(k0) == 0_int64) &
                         .and. all(bits(d0) == 0_int64), 'invalid law: no success, HD_BAD_LAW, zeros, ' // tag)
        else if (iend == HD_END_OVERLAP .or. iend == HD_END_FORCE) then
            call s%check(count(st0 == HD_OK) > n / 2 .and. count(st0 /= HD_OK) > 100, &
                         'grid covers successes and failures, ' // tag)
        end if
    end subroutine compare_law

    !> The inverse of a damping law with the physical bound: the module's calls with
    !> k_phys and `law` against the per-pair API (k_phys as given) and the law entry points
    !> of C and legacy, whose k_phys = 0 means no bound (there: against the unbounded
    !> module call).
    subroutine compare_law_bounded(iend, law)
        integer, intent(in) :: iend, law
        real(wp), dimension(size(e)) :: k0, d0, k, d, ku, du
        integer, dimension(size(e)) :: st0, st, stu
        integer(c_int), dimension(size(e)) :: stc
        logical, dimension(size(e)) :: b0, b, none
        integer :: i, n, nbad(4)
        character(len=:), allocatable :: tag
        tag = law_tag(iend, law)
        n = size(e)
        do i = 1, n
            call hertzdamp_invert(e(i), tc(i), m(i), u(i), iend, k0(i), d0(i), st0(i), bound_active=b0(i), &
                                  k_phys=kp(i), law=law, options=hertzdamp_invert_options(method=HD_METHOD_FIT))
            call hertzdamp_invert(e(i), tc(i), m(i), u(i), iend, ku(i), du(i), stu(i), law=law)
        end do
        call hertzdamp_invert(e, tc, m, u, iend, k, d, st, bound_active=b, k_phys=kp, law=law)
        nbad(1) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. st /= st0 .or. (b .neqv. b0))
        do i = 1, n
            call via_pair(e(i), tc(i), m(i), u(i), iend, law, k(i), d(i), st(i), kp(i), b(i))
        end do
        nbad(2) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. st /= st0 .or. (b .neqv. b0))
        ! the C and legacy law entry points: k_phys = 0 is no bound
        none = kp == 0.0_wp
        where (none)
            k0 = ku
            d0 = du
            st0 = stu
        end where
        do i = 1, n
            stc(i) = hertzdamp_c_invert_law(e(i), tc(i), m(i), u(i), kp(i), int(law, c_int), int(iend, c_int), &
                                            k(i), d(i))
        end do
        nbad(3) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. stc /= st0)
        do i = 1, n
            call hertzdamp_invert_law_legacy(e(i), tc(i), m(i), u(i), kp(i), int(law, c_int), int(iend, c_int), &
                                             k(i), d(i), stc(i))
        end do
        nbad(4) = count(bits(k) /= bits(k0) .or. bits(d) /= bits(d0) .or. stc /= st0)
        call s%check(nbad(1) == 0, 'bounded: rank-1 call = scalar calls, ' // tag)
        call s%check(nbad(2) == 0, 'bounded: pair_init + pair_kd with k_phys = module, ' // tag)
        call s%check(nbad(3) == 0, 'bounded: hertzdamp_c_invert_law = module, ' // tag)
        call s%check(nbad(4) == 0, 'bounded: HERTZDAMP_INVERT_LAW = module, ' // tag)
        if (any(nbad /= 0)) print '(a, 4i6)', 'bounded mismatches per entry point (' // tag // '): ', nbad
        if (iend == HD_END_OVERLAP .and. law >= HD_DAMPING_LINEAR .and. law <= HD_DAMPING_KUWABARA_KONO) then
            call s%check(count(b0) > 300 .and. count(.not. b0 .and. st0 == HD_OK) > 300, &
                         'bounded: the bound is active on part of the grid, not all, ' // tag)
        end if
    end subroutine compare_law_bounded

    !> k and d of one contact through the per-pair API (host none): hertzdamp_pair_init, then
    !> hertzdamp_pair_kd; where the init failed, kd reports HD_BAD_PAIR unless an argument
    !> of the contact is bad, and hertzdamp_invert reports the init's reason instead.
    subroutine via_pair(e, tc, m, u, iend, law, k, d, st, kp, bound)
        real(wp), intent(in) :: e, tc, m, u
        integer, intent(in) :: iend, law
        real(wp), intent(out) :: k, d
        integer, intent(out) :: st
        real(wp), intent(in), optional :: kp
        logical, intent(out), optional :: bound
        type(hertzdamp_pair_t) :: p
        integer :: st_init
        call hertzdamp_pair_init(e, law, iend, HD_HOST_NONE, 0.0_wp, p, st_init)
        call hertzdamp_pair_kd(p, tc, m, u, k, d, st, k_phys=kp, bound_active=bound)
        if (st == HD_BAD_PAIR) st = st_init
    end subroutine via_pair

    !> via_pair for every contact at once: elemental init over the arrays (one pair per
    !> contact), elemental kd over the pairs (with t*).
    subroutine via_pairs(e, tc, m, u, iend, law, k, d, st, a, tau, ts)
        real(wp), intent(in) :: e(:), tc(:), m(:), u(:)
        integer, intent(in) :: iend, law
        real(wp), intent(out) :: k(:), d(:), a(:), tau(:), ts(:)
        integer, intent(out) :: st(:)
        type(hertzdamp_pair_t) :: p(size(e))
        integer :: st_init(size(e))
        call hertzdamp_pair_init(e, law, iend, HD_HOST_NONE, 0.0_wp, p, st_init)
        call hertzdamp_pair_kd(p, tc, m, u, k, d, st, tstar=ts)
        where (st == HD_BAD_PAIR) st = st_init
        a = p%alpha
        tau = p%tau_c
    end subroutine via_pairs

    !> The dimensionless kernels and the forward map: one value per call against n at once.
    subroutine compare_kernels()
        real(wp), allocatable :: al(:), a(:), t(:), a1(:), t1(:), k(:), d(:), k1(:), d1(:), z(:), zm(:), z1(:), zm1(:)
        integer, allocatable :: st(:), st1(:)
        integer :: i, iend, n, law
        character(len=3) :: cend
        ! alpha: the regimes and their ends (0.6, alpha_c, 1.3, 52.5) and invalid values
        n = 19 + 4000
        allocate (al(n))
        al(1:19) = [0.0_wp, -0.0_wp, tiny(1.0_wp), 1.0e-10_wp, 0.3_wp, 0.6_wp, nearest(0.6_wp, 2.0_wp), 1.0_wp, &
                    1.12_wp, nearest(hertzdamp_fit_alpha_c, -1.0_wp), hertzdamp_fit_alpha_c, 1.3_wp, &
                    nearest(1.3_wp, 2.0_wp), 2.0_wp, 52.5_wp, 53.0_wp, -1.0_wp, nan, inf]
        do i = 20, n
            al(i) = 0.011_wp * (i - 19)
        end do
        allocate (a(n), t(n), a1(n), t1(n), k(n), d(n), k1(n), d1(n), z(n), zm(n), z1(n), zm1(n), st(n), st1(n))
        do iend = -1, 2
            write (cend, '(i0)') iend
            call hertzdamp_fit_forward_n(n, al, iend, a, t, st, z, zm)
            do i = 1, n
                call hertzdamp_fit_forward(al(i), iend, a1(i), t1(i), st1(i), z1(i), zm1(i))
            end do
            call s%check(all(bits(a) == bits(a1) .and. bits(t) == bits(t1) .and. st == st1 .and. bits(z) == bits(z1) &
                             .and. bits(zm) == bits(zm1)), 'forward: n at once = one at a time, end ' // cend)
            do law = -1, HD_DAMPING_KUWABARA_KONO + 1
                call hertzdamp_fit_inverse_n(size(e), e, iend, a(1:size(e)), t(1:size(e)), st(1:size(e)), law)
                do i = 1, size(e)
                    call hertzdamp_fit_inverse(e(i), iend, a1(i), t1(i), st1(i), law)
                end do
                call s%check(all(bits(a(1:size(e))) == bits(a1(1:size(e))) .and. bits(t(1:size(e))) == &
                                 bits(t1(1:size(e))) .and. st(1:size(e)) == st1(1:size(e))), &
                             'fit inverse: n at once = one at a time, ' // law_tag(iend, law))
            end do
        end do
        deallocate (a, t, a1, t1, k, d, k1, d1, st, st1)
        n = size(e)
        allocate (a(n), t(n), a1(n), t1(n), k(n), d(n), k1(n), d1(n), st(n), st1(n))
        do iend = -1, 2
            do law = -1, HD_DAMPING_KUWABARA_KONO + 1
                ! (the dimensional fit hertzdamp_fit_invert(_n) is gone: its k and d are
                ! hertzdamp_invert's, whose array form runs the fit's loop and the scalar form
                ! its form for one value)
                call hertzdamp_invert(e, tc, m, u, iend, k, d, st, alpha=a, tau_c=t, law=law)
                do i = 1, n
                    call hertzdamp_invert(e(i), tc(i), m(i), u(i), iend, k1(i), d1(i), st1(i), alpha=a1(i), &
                                          tau_c=t1(i), law=law)
                end do
                call s%check(all(bits(k) == bits(k1) .and. bits(d) == bits(d1) .and. bits(a) == bits(a1) .and. &
                                 bits(t) == bits(t1) .and. st == st1), 'fit invert: n at once = one at a time, ' &
                             // law_tag(iend, law))
            end do
        end do
    end subroutine compare_kernels

end program test_entry_points
