!> The entry-point measurements of `hertzdamp bench`: the fit inverse of one damping law
!> through every way a DEM code calls it (module scalar and rank-1 calls, the C
!> functions through their bind(C) names, the legacy externals through
!> include/hertzdamp.fi), timed side by side over the same contacts and compared bit
!> for bit with the module scalar call; and, for the tsuji law, its inverse against the
!> closed form alpha = sqrt(5) beta(e) of the overlap end (hertzdamp_bench_closed).
!> The linear law is called through its own entry points (hertzdamp_invert,
!> hertzdamp_c_invert[_n], HERTZDAMP_INVERT[_N]), the others through the law ones
!> (law=, hertzdamp_c_invert_law[_n], HERTZDAMP_INVERT_LAW[_N]).
module hertzdamp_bench_entry
    use hertzdamp, only: hertzdamp_rk, hertzdamp_invert, hertzdamp_fit_inverse, hertzdamp_fit_inverse_n, HD_OK, &
                         HD_END_OVERLAP, HD_DAMPING_LINEAR, HD_DAMPING_TSUJI
    use hertzdamp_capi, only: hertzdamp_c_invert, hertzdamp_c_invert_n, hertzdamp_c_invert_law, &
                              hertzdamp_c_invert_law_n
    use hertzdamp_bench_legacy, only: legacy_invert_each, legacy_invert_all, legacy_invert_law_each, &
                                      legacy_invert_law_all
    use hertzdamp_bench_closed, only: closed_alpha, closed_d, closed_alpha_n, closed_d_n
    use hertzdamp_bench_timer, only: bench_case, bench_slot, bench_measure_all
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: iso_c_binding, only: c_int
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> The entry points, in the order of the rows.
    integer, parameter, public :: n_ways = 6
    integer, parameter, public :: WAY_SCALAR = 1, WAY_ARRAY = 2, WAY_C = 3, WAY_C_N = 4, WAY_LEGACY = 5, &
                                  WAY_LEGACY_N = 6
    character(len=*), parameter, public :: way_name(n_ways) = [character(len=13) :: 'module-scalar', &
                                                               'module-array', 'c', 'c-array', 'legacy', 'legacy-n']
    !> What each way calls, for the linear law and for the others.
    character(len=*), parameter, public :: way_label(n_ways, 2) = reshape([character(len=56) :: &
        'module hertzdamp_invert, one contact per call', 'module hertzdamp_invert on rank-1 arrays', &
        'C hertzdamp_c_invert, one contact per call', 'C hertzdamp_c_invert_n', &
        'legacy HERTZDAMP_INVERT, one contact per call', 'legacy HERTZDAMP_INVERT_N', &
        'module hertzdamp_invert with law=, one contact per call', 'module hertzdamp_invert with law= on arrays', &
        'C hertzdamp_c_invert_law, one contact per call', 'C hertzdamp_c_invert_law_n', &
        'legacy HERTZDAMP_INVERT_LAW, one contact per call', 'legacy HERTZDAMP_INVERT_LAW_N'], [n_ways, 2])

    !> The tsuji comparison (overlap end), in the order of the rows: alpha alone by the
    !> closed form and by the fit (hertzdamp_fit_inverse, which also gives tau_c), one
    !> contact per call and over arrays; the engines' d = alpha sqrt(m k) for a given k
    !> by the closed form and by hertzdamp_invert with k_phys = k (the bound active).
    integer, parameter, public :: n_ts = 8
    integer, parameter, public :: TS_CLOSED_ALPHA = 1, TS_FIT_ALPHA = 2, TS_CLOSED_ALPHA_N = 3, TS_FIT_ALPHA_N = 4, &
                                  TS_CLOSED_D = 5, TS_BOUND_D = 6, TS_CLOSED_D_N = 7, TS_BOUND_D_N = 8
    character(len=*), parameter, public :: ts_name(n_ts) = [character(len=16) :: 'closed-alpha', 'fit-alpha', &
        'closed-alpha-n', 'fit-alpha-n', 'closed-d', 'bound-d', 'closed-d-n', 'bound-d-n']
    character(len=*), parameter, public :: ts_label(n_ts) = [character(len=72) :: &
        'alpha = sqrt5 beta(e) (libm log, sqrt), one contact per call', &
        'hertzdamp_fit_inverse (alpha and tau_c), one contact per call', &
        'alpha = sqrt5 beta(e) in a loop over the arrays', &
        'hertzdamp_fit_inverse_n over the arrays', &
        'd = sqrt5 beta(e) sqrt(m k), one contact per call', &
        'hertzdamp_invert with k_phys = k (bound active), one contact per call', &
        'd = sqrt5 beta(e) sqrt(m k) in a loop over the arrays', &
        'hertzdamp_invert with k_phys = k on rank-1 arrays']

    !> The contacts of the entry-point rows (shared by every way of calling).
    type, public :: entry_data
        real(wp), allocatable :: e(:), tc(:), m(:), u(:)
        real(wp), allocatable :: kp(:)   !! stiffnesses below those of the inverse (tsuji rows: bound active)
    end type entry_data

    !> One way of calling the fit inverse of one law over all contacts of an entry_data.
    type, extends(bench_case) :: entry_case
        integer :: way = WAY_SCALAR
        integer :: law = HD_DAMPING_LINEAR
        type(entry_data), pointer :: in => null()
        real(wp), allocatable :: k(:), d(:)
        integer(c_int), allocatable :: status(:)
    contains
        procedure :: run => entry_run
    end type entry_case

    !> One row of the tsuji comparison over all contacts.
    type, extends(bench_case) :: tsuji_case
        integer :: way = TS_CLOSED_ALPHA
        type(entry_data), pointer :: in => null()
        real(wp), allocatable :: x(:), tau(:), k(:)   !! alpha or d; tau_c; k
        integer, allocatable :: status(:)
    contains
        procedure :: run => tsuji_run
    end type tsuji_case

    !> What the entry-point rows of one law found.
    type, public :: entry_result
        integer :: law = HD_DAMPING_LINEAR
        integer :: n = 0                   !! contacts
        real(wp) :: ns(n_ways) = -1.0_wp   !! ns per contact of each way
        integer :: mismatches(n_ways) = 0  !! contacts whose k, d or status differ from the module scalar call
        integer :: failed = 0              !! contacts whose status is not ok
    end type entry_result

    !> What the tsuji comparison found.
    type, public :: tsuji_result
        integer :: n = 0                     !! contacts
        real(wp) :: ns(n_ts) = -1.0_wp       !! ns per contact of each row
        real(wp) :: err_alpha = -1.0_wp      !! max relative difference of the fit's alpha from the closed form
        real(wp) :: err_d = -1.0_wp          !! max relative difference of the bound's d from the closed form
        integer :: failed = 0                !! contacts of the library rows whose status is not ok
        integer :: unbound = 0               !! contacts of bound-d where the bound was not active
        integer :: mismatches = 0            !! contacts where an array row differs from its one-contact row
    end type tsuji_result

    public :: entry_contacts, entry_measure, tsuji_measure

contains

    !> n contacts: e uniform in [0.05, 0.99]; m, u, T_c log-uniform over [1e-9, 1] kg,
    !> [1e-3, 10] m/s, [1e-7, 1e-3] s (a fixed seed: the same contacts in every run).
    subroutine entry_contacts(n, dat)
        integer, intent(in) :: n
        type(entry_data), intent(out) :: dat
        integer(int64) :: seed
        seed = 20261122_int64
        allocate (dat%e(n), dat%m(n), dat%u(n), dat%tc(n))
        dat%e(:) = 0.05_wp + 0.94_wp * lcg_uniform(seed, n)
        dat%m(:) = 10.0_wp**(-9.0_wp + 9.0_wp * lcg_uniform(seed, n))
        dat%u(:) = 10.0_wp**(-3.0_wp + 4.0_wp * lcg_uniform(seed, n))
        dat%tc(:) = 10.0_wp**(-7.0_wp + 4.0_wp * lcg_uniform(seed, n))
    end subroutine entry_contacts

    !> n uniform numbers in (0, 1) from the Park-Miller generator (reproducible everywhere).
    function lcg_uniform(seed, n) result(x)
        integer(int64), intent(inout) :: seed
        integer, intent(in) :: n
        real(wp) :: x(n)
        integer :: i
        integer(int64), parameter :: a = 16807_int64, modulus = 2147483647_int64
        do i = 1, n
            seed = mod(a * seed, modulus)
            x(i) = real(seed, wp) / real(modulus, wp)
        end do
    end function lcg_uniform

    !> Every contact once through one entry point (overlap end).
    subroutine entry_run(self)
        class(entry_case), intent(inout) :: self
        integer :: i, n
        integer(c_int) :: st, law, iend
        n = size(self%in%e)
        law = int(self%law, c_int)
        iend = int(HD_END_OVERLAP, c_int)
        if (self%law == HD_DAMPING_LINEAR) then
            select case (self%way)
            case (WAY_SCALAR)
                do i = 1, n
                    call hertzdamp_invert(self%in%e(i), self%in%tc(i), self%in%m(i), self%in%u(i), HD_END_OVERLAP, &
                                          self%k(i), self%d(i), self%status(i))
                end do
            case (WAY_ARRAY)
                call hertzdamp_invert(self%in%e, self%in%tc, self%in%m, self%in%u, HD_END_OVERLAP, self%k, self%d, &
                                      self%status)
            case (WAY_C)
                do i = 1, n
                    self%status(i) = hertzdamp_c_invert(self%in%e(i), self%in%tc(i), self%in%m(i), self%in%u(i), &
                                                        iend, self%k(i), self%d(i))
                end do
            case (WAY_C_N)
                st = hertzdamp_c_invert_n(int(n, c_int), self%in%e, self%in%tc, self%in%m, self%in%u, iend, self%k, &
                                          self%d, self%status)
            case (WAY_LEGACY)
                ! HERTZDAMP_INVERT once per contact, declared by include/hertzdamp.fi
                call legacy_invert_each(int(n, c_int), self%in%e, self%in%tc, self%in%m, self%in%u, iend, self%k, &
                                        self%d, self%status)
            case default
                call legacy_invert_all(int(n, c_int), self%in%e, self%in%tc, self%in%m, self%in%u, iend, self%k, &
                                       self%d, self%status)
            end select
        else
            select case (self%way)
            case (WAY_SCALAR)
                do i = 1, n
                    call hertzdamp_invert(self%in%e(i), self%in%tc(i), self%in%m(i), self%in%u(i), HD_END_OVERLAP, &
                                          self%k(i), self%d(i), self%status(i), law=self%law)
                end do
            case (WAY_ARRAY)
                call hertzdamp_invert(self%in%e, self%in%tc, self%in%m, self%in%u, HD_END_OVERLAP, self%k, self%d, &
                                      self%status, law=self%law)
            case (WAY_C)
                do i = 1, n
                    self%status(i) = hertzdamp_c_invert_law(self%in%e(i), self%in%tc(i), self%in%m(i), self%in%u(i), &
                                                            0.0_wp, law, iend, self%k(i), self%d(i))
                end do
            case (WAY_C_N)
                st = hertzdamp_c_invert_law_n(int(n, c_int), self%in%e, self%in%tc, self%in%m, self%in%u, law, iend, &
                                              self%k, self%d, self%status)
            case (WAY_LEGACY)
                call legacy_invert_law_each(int(n, c_int), self%in%e, self%in%tc, self%in%m, self%in%u, law, iend, &
                                            self%k, self%d, self%status)
            case default
                call legacy_invert_law_all(int(n, c_int), self%in%e, self%in%tc, self%in%m, self%in%u, law, iend, &
                                           self%k, self%d, self%status)
            end select
        end if
    end subroutine entry_run

    !> The fit inverse of `law` through every entry point over the contacts of dat, timed
    !> side by side; then every way's results against the module scalar call, bit for bit.
    subroutine entry_measure(law, dat, min_time, repeats, res)
        integer, intent(in) :: law
        type(entry_data), target, intent(in) :: dat
        real(wp), intent(in) :: min_time
        integer, intent(in) :: repeats
        type(entry_result), intent(out) :: res
        type(bench_slot) :: slots(n_ways)
        real(wp) :: t(n_ways)
        integer :: w, n
        n = size(dat%e)
        do w = 1, n_ways
            allocate (slots(w)%c, source=entry_case(way=w, law=law, in=dat))
            select type (c => slots(w)%c)
            type is (entry_case)
                allocate (c%k(n), c%d(n), c%status(n))
                call c%run()
            end select
        end do
        t = bench_measure_all(slots, min_time, repeats)
        res%law = law
        res%n = n
        res%ns = 1.0e9_wp * t / n
        select type (c1 => slots(1)%c)
        type is (entry_case)
            res%failed = count(c1%status /= HD_OK)
            do w = 1, n_ways
                select type (c => slots(w)%c)
                type is (entry_case)
                    res%mismatches(w) = count(transfer(c%k, 0_int64, n) /= transfer(c1%k, 0_int64, n) .or. &
                                              transfer(c%d, 0_int64, n) /= transfer(c1%d, 0_int64, n) .or. &
                                              c%status /= c1%status)
                end select
            end do
        end select
    end subroutine entry_measure

    !> One row of the tsuji comparison over every contact.
    subroutine tsuji_run(self)
        class(tsuji_case), intent(inout) :: self
        integer :: i, n
        n = size(self%in%e)
        select case (self%way)
        case (TS_CLOSED_ALPHA)
            do i = 1, n
                self%x(i) = closed_alpha(self%in%e(i))
            end do
        case (TS_FIT_ALPHA)
            do i = 1, n
                call hertzdamp_fit_inverse(self%in%e(i), HD_END_OVERLAP, self%x(i), self%tau(i), self%status(i), &
                                           law=HD_DAMPING_TSUJI)
            end do
        case (TS_CLOSED_ALPHA_N)
            call closed_alpha_n(n, self%in%e, self%x)
        case (TS_FIT_ALPHA_N)
            call hertzdamp_fit_inverse_n(n, self%in%e, HD_END_OVERLAP, self%x, self%tau, self%status, law=HD_DAMPING_TSUJI)
        case (TS_CLOSED_D)
            do i = 1, n
                self%x(i) = closed_d(self%in%e(i), self%in%m(i), self%in%kp(i))
            end do
        case (TS_BOUND_D)
            do i = 1, n
                call hertzdamp_invert(self%in%e(i), self%in%tc(i), self%in%m(i), self%in%u(i), HD_END_OVERLAP, &
                                      self%k(i), self%x(i), self%status(i), k_phys=self%in%kp(i), law=HD_DAMPING_TSUJI)
            end do
        case (TS_CLOSED_D_N)
            call closed_d_n(n, self%in%e, self%in%m, self%in%kp, self%x)
        case default
            call hertzdamp_invert(self%in%e, self%in%tc, self%in%m, self%in%u, HD_END_OVERLAP, self%k, self%x, &
                                  self%status, k_phys=self%in%kp, law=HD_DAMPING_TSUJI)
        end select
    end subroutine tsuji_run

    !> The tsuji comparison over the contacts of dat (overlap end), timed side by side:
    !> k_phys is half the stiffness of the unbounded inverse of each contact, so that the
    !> bound is active and the library's d is the engines' alpha sqrt(m k_phys).
    subroutine tsuji_measure(dat, min_time, repeats, res)
        type(entry_data), target, intent(inout) :: dat
        real(wp), intent(in) :: min_time
        integer, intent(in) :: repeats
        type(tsuji_result), intent(out) :: res
        type(bench_slot) :: slots(n_ts)
        real(wp) :: t(n_ts)
        real(wp), allocatable :: k(:), d(:)
        integer, allocatable :: st(:)
        integer :: w, n
        n = size(dat%e)
        allocate (k(n), d(n), st(n))
        call hertzdamp_invert(dat%e, dat%tc, dat%m, dat%u, HD_END_OVERLAP, k, d, st, law=HD_DAMPING_TSUJI)
        dat%kp = 0.5_wp * k
        do w = 1, n_ts
            allocate (slots(w)%c, source=tsuji_case(way=w, in=dat))
            select type (c => slots(w)%c)
            type is (tsuji_case)
                allocate (c%x(n), c%tau(n), c%k(n), c%status(n))
                c%status = HD_OK
                call c%run()
            end select
        end do
        t = bench_measure_all(slots, min_time, repeats)
        res%n = n
        res%ns = 1.0e9_wp * t / n
        res%failed = count(st /= HD_OK)
        select type (ca => slots(TS_CLOSED_ALPHA)%c)
        type is (tsuji_case)
            select type (fa => slots(TS_FIT_ALPHA)%c)
            type is (tsuji_case)
                res%err_alpha = maxval(abs(fa%x - ca%x) / ca%x)
                res%failed = res%failed + count(fa%status /= HD_OK)
            end select
        end select
        select type (cd => slots(TS_CLOSED_D)%c)
        type is (tsuji_case)
            select type (bd => slots(TS_BOUND_D)%c)
            type is (tsuji_case)
                res%err_d = maxval(abs(bd%x - cd%x) / cd%x)
                res%failed = res%failed + count(bd%status /= HD_OK)
                res%unbound = count(bd%k /= dat%kp)
            end select
        end select
        res%mismatches = differ(TS_FIT_ALPHA, TS_FIT_ALPHA_N) + differ(TS_BOUND_D, TS_BOUND_D_N)
    contains
        !> Contacts whose results (alpha or d, status) differ between two library rows.
        integer function differ(w1, w2)
            integer, intent(in) :: w1, w2
            differ = 0
            select type (c1 => slots(w1)%c)
            type is (tsuji_case)
                select type (c2 => slots(w2)%c)
                type is (tsuji_case)
                    differ = count(transfer(c1%x, 0_int64, n) /= transfer(c2%x, 0_int64, n) .or. &
                                   c1%status /= c2%status)
                end select
            end select
        end function differ
    end subroutine tsuji_measure

end module hertzdamp_bench_entry
