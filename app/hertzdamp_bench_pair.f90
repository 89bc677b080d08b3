!> The per-pair measurements of `hertzdamp bench`: what the per-contact call of a DEM host
!> costs against the bare formula it replaces, and what the one-call inverse costs when
!> every contact has the same T_c and m (the broadcast forms).
!>
!> Over the entry contacts (T_c, m, u of hertzdamp_bench_entry), one material pair (linear
!> law, overlap end, e = 0.5, host none), timed side by side:
!> - bare: k = m r^(5/2) u^(-1/2), d = alpha m r with r = tau_c / T_c from the stored
!>   alpha, tau_c, written as a host writes it in its contact loop: one contact per
!>   iteration (no vector code: NOVECTOR), no checks;
!> - c-pair-kd: hertzdamp_c_pair_kd through its bind(C) name, one contact per call;
!> - pair-kd: hertzdamp_pair_kd, one contact per call;
!> - bare-vec: the bare formula over the arrays, vectorised by the compiler;
!> - pair-kd-array: hertzdamp_pair_kd on the rank-1 arrays;
!> - invert-each-tc-m: hertzdamp_invert, one contact per call, every contact with the same
!>   T_c and m (what an elemental call with scalar T_c, m did before its broadcast forms);
!> - invert-tc-m: hertzdamp_invert with scalar T_c and m over rank-1 arrays of e and u;
!> - invert-tc: hertzdamp_invert with a scalar T_c over rank-1 arrays of e, m and u;
!> - c-pair-kd-phase: hertzdamp_c_pair_kd_phase, one contact per call, with a pair's
!>   onset-phase table (mfix-euler, N = 10, e = 0.5, linear law, overlap end; issue 32) and
!>   an onset phase per contact;
!> - pair-kd-phase: hertzdamp_pair_kd_phase, the same, one contact per call.
!> And the time of one hertzdamp_pair_init with the table (mfix-euler, N = 10, e = 0.2 and
!> 0.5; median of 7).
!> The library's rows are compared bit for bit: C and array against the scalar pair-kd,
!> the broadcast forms against one call per contact.
module hertzdamp_bench_pair
    use hertzdamp, only: hertzdamp_rk, hertzdamp_pair_t, hertzdamp_pair_init, hertzdamp_pair_kd, hertzdamp_invert, &
                         HD_OK, HD_END_OVERLAP, HD_DAMPING_LINEAR, HD_HOST_NONE, HD_HOST_MFIX_EULER, &
                         hertzdamp_pair_kd_phase
    use hertzdamp_capi, only: hertzdamp_c_pair_kd, hertzdamp_c_pair_kd_phase
    use hertzdamp_bench_entry, only: entry_data
    use hertzdamp_bench_timer, only: bench_case, bench_slot, bench_rounds_all, median
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> The rows, in order.
    integer, parameter, public :: n_pw = 10
    integer, parameter, public :: PW_BARE = 1, PW_C = 2, PW_SCALAR = 3, PW_BARE_VEC = 4, PW_ARRAY = 5, &
                                  PW_INVERT_EACH = 6, PW_INVERT_TC_M = 7, PW_INVERT_TC = 8, PW_C_PHASE = 9, &
                                  PW_PHASE = 10
    character(len=*), parameter, public :: pw_name(n_pw) = [character(len=16) :: 'bare', 'c-pair-kd', 'pair-kd', &
        'bare-vec', 'pair-kd-array', 'invert-each-tc-m', 'invert-tc-m', 'invert-tc', 'c-pair-kd-phase', 'pair-kd-phase']
    character(len=*), parameter, public :: pw_label(n_pw) = [character(len=84) :: &
        'k = m r^(5/2) u^(-1/2), d = alpha m r, one contact per iteration (no vector code)', &
        'C hertzdamp_c_pair_kd, one contact per call', &
        'hertzdamp_pair_kd, one contact per call', &
        'the bare formula over the arrays (vectorised)', &
        'hertzdamp_pair_kd on rank-1 arrays', &
        'hertzdamp_invert, one contact per call, the same T_c and m for all', &
        'hertzdamp_invert, scalar T_c and m over rank-1 e, u', &
        'hertzdamp_invert, scalar T_c over rank-1 e, m, u', &
        'C hertzdamp_c_pair_kd_phase (onset-phase table, mfix-euler N = 10), one per call', &
        'hertzdamp_pair_kd_phase, one contact per call']
    !> The restitution of the pair, and the T_c and m of the broadcast rows.
    real(wp), parameter, public :: pair_e = 0.5_wp, bcast_tc = 1.0e-5_wp, bcast_m = 1.0e-3_wp

    !> One row over every contact.
    type, extends(bench_case) :: pair_case
        integer :: way = PW_BARE
        type(entry_data), pointer :: in => null()
        type(hertzdamp_pair_t) :: p
        type(hertzdamp_pair_t) :: pp        !! the pair with its onset-phase table
        real(wp), allocatable :: phi(:)     !! the onset phase of each contact
        real(wp), allocatable :: k(:), d(:)
        integer, allocatable :: status(:)
    contains
        procedure :: run => pair_run
    end type pair_case

    !> What the per-pair rows found.
    type, public :: pair_result
        integer :: n = 0                       !! contacts
        real(wp) :: ns(n_pw) = -1.0_wp         !! ns per contact of each row (median over the rounds)
        real(wp) :: c_ratio = -1.0_wp          !! C over bare: the median of the rounds' ratios
        real(wp) :: array_ratio = -1.0_wp      !! pair-kd-array over bare-vec, the same way
        real(wp) :: phase_ratio = -1.0_wp      !! c-pair-kd-phase over bare, the same way
        real(wp) :: init_ms(2) = -1.0_wp       !! pair_init with the table, N = 10, e = 0.2 and 0.5 [ms]
        integer :: rounds = 0                  !! rounds timed
        integer :: mismatches = 0              !! contacts whose library results differ between rows that must agree
        integer :: failed = 0                  !! contacts whose status is not ok (library rows)
    end type pair_result

    public :: pair_measure

contains

    !> The bare formula, one contact per iteration, as a host's contact loop computes it.
    pure subroutine bare_each(n, alpha, tau, tc, m, u, k, d)
        integer, intent(in) :: n
        real(wp), intent(in) :: alpha, tau, tc(n), m(n), u(n)
        real(wp), intent(out) :: k(n), d(n)
        real(wp) :: r
        integer :: i
        !GCC$ NOVECTOR
        do i = 1, n
            r = tau / tc(i)
            k(i) = m(i) * r * r * sqrt(r / u(i))
            d(i) = alpha * m(i) * r
        end do
    end subroutine bare_each

    !> The bare formula over the arrays (the compiler vectorises this loop).
    pure subroutine bare_vec(n, alpha, tau, tc, m, u, k, d)
        integer, intent(in) :: n
        real(wp), intent(in) :: alpha, tau, tc(n), m(n), u(n)
        real(wp), intent(out) :: k(n), d(n)
        real(wp) :: r
        integer :: i
        do i = 1, n
            r = tau / tc(i)
            k(i) = m(i) * r * r * sqrt(r / u(i))
            d(i) = alpha * m(i) * r
        end do
    end subroutine bare_vec

    !> hertzdamp_c_pair_kd once per contact, in a loop of the same form as bare_each (explicit-
    !> shape arrays: no array descriptor of the row reloaded around each call), so that the
    !> ratio of the two rows is the call's cost against the formula's, not the loops'.
    subroutine c_each(n, p, tc, m, u, k, d, status)
        integer, intent(in) :: n
        type(hertzdamp_pair_t), intent(in) :: p
        real(wp), intent(in) :: tc(n), m(n), u(n)
        real(wp), intent(out) :: k(n), d(n)
        integer, intent(out) :: status(n)
        integer :: i
        do i = 1, n
            status(i) = int(hertzdamp_c_pair_kd(p, tc(i), m(i), u(i), 0.0_wp, k(i), d(i)))
        end do
    end subroutine c_each

    !> hertzdamp_c_pair_kd_phase once per contact (as c_each).
    subroutine c_phase_each(n, p, tc, m, u, phi, k, d, status)
        integer, intent(in) :: n
        type(hertzdamp_pair_t), intent(in) :: p
        real(wp), intent(in) :: tc(n), m(n), u(n), phi(n)
        real(wp), intent(out) :: k(n), d(n)
        integer, intent(out) :: status(n)
        integer :: i
        do i = 1, n
            status(i) = int(hertzdamp_c_pair_kd_phase(p, tc(i), m(i), u(i), 0.0_wp, phi(i), k(i), d(i)))
        end do
    end subroutine c_phase_each

    !> Every contact once through one row's way.
    subroutine pair_run(self)
        class(pair_case), intent(inout) :: self
        integer :: i, n
        n = size(self%in%tc)
        associate (tc => self%in%tc, m => self%in%m, u => self%in%u, e => self%in%e)
            select case (self%way)
            case (PW_BARE)
                call bare_each(n, self%p%alpha, self%p%tau_c, tc, m, u, self%k, self%d)
            case (PW_C)
                call c_each(n, self%p, tc, m, u, self%k, self%d, self%status)
            case (PW_SCALAR)
                do i = 1, n
                    call hertzdamp_pair_kd(self%p, tc(i), m(i), u(i), self%k(i), self%d(i), self%status(i))
                end do
            case (PW_BARE_VEC)
                call bare_vec(n, self%p%alpha, self%p%tau_c, tc, m, u, self%k, self%d)
            case (PW_ARRAY)
                call hertzdamp_pair_kd(self%p, tc, m, u, self%k, self%d, self%status)
            case (PW_INVERT_EACH)
                do i = 1, n
                    call hertzdamp_invert(e(i), bcast_tc, bcast_m, u(i), HD_END_OVERLAP, self%k(i), self%d(i), &
                                          self%status(i))
                end do
            case (PW_INVERT_TC_M)
                call hertzdamp_invert(e, bcast_tc, bcast_m, u, HD_END_OVERLAP, self%k, self%d, self%status)
            case (PW_C_PHASE)
                call c_phase_each(n, self%pp, tc, m, u, self%phi, self%k, self%d, self%status)
            case (PW_PHASE)
                do i = 1, n
                    call hertzdamp_pair_kd_phase(self%pp, tc(i), m(i), u(i), 0.0_wp, self%phi(i), self%k(i), &
                                                 self%d(i), self%status(i))
                end do
            case default
                call hertzdamp_invert(e, bcast_tc, m, u, HD_END_OVERLAP, self%k, self%d, self%status)
            end select
        end associate
    end subroutine pair_run

    !> Contacts whose k, d (bit patterns) or status differ between two results.
    pure integer function count_differ(k1, d1, s1, k2, d2, s2)
        real(wp), intent(in) :: k1(:), d1(:), k2(:), d2(:)
        integer, intent(in) :: s1(:), s2(:)
        count_differ = count(transfer(k1, 0_int64, size(k1)) /= transfer(k2, 0_int64, size(k2)) .or. &
                             transfer(d1, 0_int64, size(d1)) /= transfer(d2, 0_int64, size(d2)) .or. s1 /= s2)
    end function count_differ

    !> Every row over the contacts of dat, timed side by side; then the library's rows
    !> compared bit for bit.
    subroutine pair_measure(dat, min_time, repeats, res)
        type(entry_data), target, intent(in) :: dat
        real(wp), intent(in) :: min_time
        integer, intent(in) :: repeats
        type(pair_result), intent(out) :: res
        type(bench_slot) :: slots(n_pw)
        type(hertzdamp_pair_t) :: p, pp
        real(wp) :: k(size(dat%e)), d(size(dat%e)), phi(size(dat%e))
        real(wp), allocatable :: t(:, :)
        integer :: w, n, st, i, sti(size(dat%e)), stp
        n = size(dat%e)
        call hertzdamp_pair_init(pair_e, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_NONE, 0.0_wp, p, st)
        call hertzdamp_pair_init(pair_e, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_MFIX_EULER, 10.0_wp, pp, stp, &
                                 phase=.true.)
        if (stp /= HD_OK) st = stp
        ! onset phases spread over (0, 1] (golden-ratio steps: no order the branch predictor learns)
        do i = 1, n
            phi(i) = 1.0_wp - modulo(real(i, wp) * 0.6180339887498949_wp, 1.0_wp)
        end do
        res%init_ms = [init_time(0.2_wp), init_time(pair_e)]
        do w = 1, n_pw
            allocate (slots(w)%c, source=pair_case(way=w, in=dat, p=p, pp=pp, phi=phi))
            select type (c => slots(w)%c)
            type is (pair_case)
                allocate (c%k(n), c%d(n), c%status(n))
                c%status = HD_OK
                call c%run()
            end select
        end do
        ! three times the rounds of the other tables: the ratio to the bare formula is the
        ! figure with a target, and the machines are shared
        t = bench_rounds_all(slots, min_time, 3 * repeats)
        res%n = n
        res%rounds = size(t, 1)
        do w = 1, n_pw
            res%ns(w) = 1.0e9_wp * median(t(:, w)) / n
        end do
        res%c_ratio = median(t(:, PW_C) / t(:, PW_BARE))
        res%array_ratio = median(t(:, PW_ARRAY) / t(:, PW_BARE_VEC))
        res%phase_ratio = median(t(:, PW_C_PHASE) / t(:, PW_BARE))
        res%failed = merge(0, n, st == HD_OK)
        ! the pair's rows against its scalar call; the broadcast forms against one call per contact
        res%mismatches = differ(PW_C, PW_SCALAR) + differ(PW_ARRAY, PW_SCALAR) + &
                         differ(PW_INVERT_TC_M, PW_INVERT_EACH) + differ(PW_C_PHASE, PW_PHASE)
        do i = 1, n
            call hertzdamp_invert(dat%e(i), bcast_tc, dat%m(i), dat%u(i), HD_END_OVERLAP, k(i), d(i), sti(i))
        end do
        select type (c => slots(PW_INVERT_TC)%c)
        type is (pair_case)
            res%mismatches = res%mismatches + count_differ(c%k, c%d, c%status, k, d, sti)
        end select
        do w = PW_C, n_pw
            if (w == PW_BARE_VEC) cycle
            select type (c => slots(w)%c)
            type is (pair_case)
                res%failed = res%failed + count(c%status /= HD_OK)
            end select
        end do
    contains
        !> One hertzdamp_pair_init with the onset-phase table (mfix-euler, N = 10, linear law,
        !> overlap end) at e, in ms: the median of 7.
        real(wp) function init_time(e) result(ms)
            real(wp), intent(in) :: e
            type(hertzdamp_pair_t) :: q
            integer(int64) :: c0, c1, rate
            real(wp) :: ts(7)
            integer :: j, sq
            do j = 1, 7
                call system_clock(c0, rate)
                call hertzdamp_pair_init(e, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_HOST_MFIX_EULER, 10.0_wp, q, sq, &
                                         phase=.true.)
                call system_clock(c1)
                ts(j) = 1.0e3_wp * real(c1 - c0, wp) / real(rate, wp)
            end do
            ms = median(ts)
        end function init_time

        !> Contacts whose k, d or status differ between two rows.
        integer function differ(w1, w2)
            integer, intent(in) :: w1, w2
            differ = 0
            select type (c1 => slots(w1)%c)
            type is (pair_case)
                select type (c2 => slots(w2)%c)
                type is (pair_case)
                    differ = count_differ(c1%k, c1%d, c1%status, c2%k, c2%d, c2%status)
                end select
            end select
        end function differ
    end subroutine pair_measure

end module hertzdamp_bench_pair
