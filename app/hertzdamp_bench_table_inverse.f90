!> The inverse table of `hertzdamp bench`: (e, T_c, m, u_in) -> (alpha, k, d) of every
!> method of one damping law (the fit; compact, series and pade for the linear law;
!> the iterative inverse at five accuracies; for the linear law the GSL reference
!> solver's secant over rk8pd) against the iterative inverse at tol 1e-14 of the same
!> law, over a set of e at a fixed contact; its header line and its figures (the fit
!> and every entry point against the iterative rows at equal accuracy).
module hertzdamp_bench_table_inverse
    use hertzdamp, only: hertzdamp_rk, hertzdamp_message, hertzdamp_law_name, HD_OK, HD_END_OVERLAP, &
                         HD_METHOD_SERIES, HD_METHOD_PADE, HD_METHOD_COMPACT, HD_METHOD_FIT, HD_METHOD_ITERATIVE, &
                         HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, hertzdamp_tsuji_alpha, hertzdamp_invert, &
                         hertzdamp_expand, hertzdamp_invert_options
    use hertzdamp_gsl_secant, only: hertzdamp_gsl_secant_invert
    use hertzdamp_bench_timer, only: bench_case, bench_measure
    use hertzdamp_bench_entry, only: entry_result, n_ways, way_name
    use hertzdamp_bench_rows, only: bench_row, rel, row_name, find_row, met, fratio, ftoa, FAMILY_SERIES, &
                                    FAMILY_PADE, FAMILY_COMPACT, FAMILY_FIT, FAMILY_ITERATIVE, FAMILY_GSL_SECANT
    use hertzdamp_cli, only: cli_buffer, fail, EXIT_FAILURE
    use hertzdamp_cli_output, only: out_table
    use hertzdamp_cli_text, only: itoa
    implicit none
    private
    public :: inverse_set_of, inverse_table, inverse_meta, inverse_figures, inv_ref_text

    integer, parameter :: wp = hertzdamp_rk

    ! Inverse problem: fixed contact (SI units).
    real(wp), parameter :: inv_m = 1.0e-2_wp, inv_u = 1.0_wp, inv_tc = 1.0e-4_wp
    !> Tolerance of the iterative inverse that serves as the reference of the inverse rows.
    real(wp), parameter :: inv_ref_tol = 1.0e-14_wp
    character(len=*), parameter :: inv_ref_text = 'iterative at tol 1e-14'

    !> One inverse sweep over a set of e (fixed m, u_in, T_c).
    type, extends(bench_case) :: inv_case
        integer :: method = HD_METHOD_FIT
        integer :: law = HD_DAMPING_LINEAR
        real(wp) :: tol = 1.0e-10_wp
        real(wp), allocatable :: e(:), tc(:), m(:), u(:)
        real(wp), allocatable :: k(:), d(:), alpha(:), tstar(:), tau(:)
        integer, allocatable :: status(:)
        logical, allocatable :: bound(:)
    contains
        procedure :: run => inv_run
    end type inv_case

    !> The iterative inverse of the GSL peer (secant over rk8pd, linear law) over a set
    !> of e; k and d by the direct formulas from its alpha and tau_c.
    type, extends(bench_case) :: gsl_inv_case
        real(wp) :: tol = 1.0e-10_wp
        real(wp), allocatable :: e(:), tc(:), m(:), u(:)
        real(wp), allocatable :: k(:), d(:), alpha(:), tau(:)
        integer, allocatable :: status(:), solves(:), rhs(:)
    contains
        procedure :: run => gsl_inv_run
    end type gsl_inv_case

contains

    subroutine inv_run(self)
        class(inv_case), intent(inout) :: self
        integer :: i
        do i = 1, size(self%e)
            call hertzdamp_invert(self%e(i), self%tc(i), self%m(i), self%u(i), HD_END_OVERLAP, self%k(i), self%d(i), &
                                  self%status(i), alpha=self%alpha(i), tstar=self%tstar(i), tau_c=self%tau(i), &
                                  bound_active=self%bound(i), law=self%law, &
                                  options=hertzdamp_invert_options(method=self%method, tol=self%tol))
        end do
    end subroutine inv_run

    subroutine gsl_inv_run(self)
        class(gsl_inv_case), intent(inout) :: self
        integer :: i, st
        do i = 1, size(self%e)
            call hertzdamp_gsl_secant_invert(self%e(i), HD_END_OVERLAP, self%tol, self%alpha(i), self%tau(i), &
                                             self%status(i), self%solves(i), self%rhs(i))
            ! k and d of the library's scaling from alpha and t* = T_c / tau_c (no copy of its formulas)
            call hertzdamp_expand(self%alpha(i), self%tc(i) / self%tau(i), self%m(i), self%u(i), self%k(i), self%d(i), st)
            if (self%status(i) == HD_OK) self%status(i) = st
        end do
    end subroutine gsl_inv_run

    subroutine inv_init(c, method, law, tol, e, tc, m, u)
        type(inv_case), intent(out) :: c
        integer, intent(in) :: method, law
        real(wp), intent(in) :: tol, e(:), tc(:), m(:), u(:)
        integer :: n
        n = size(e)
        c%method = method
        c%law = law
        c%tol = tol
        c%e = e
        c%tc = tc
        c%m = m
        c%u = u
        allocate (c%k(n), c%d(n), c%alpha(n), c%tstar(n), c%tau(n), c%status(n), c%bound(n))
        c%k = 0.0_wp
        c%d = 0.0_wp
        c%alpha = 0.0_wp
        c%tstar = 0.0_wp
        c%tau = 0.0_wp
        c%status = HD_OK
        c%bound = .false.
    end subroutine inv_init

    !> The e of the inverse rows, in [1e-3, 0.999] for every law.
    function inverse_set_of(quick) result(e)
        logical, intent(in) :: quick
        real(wp), allocatable :: e(:)
        if (quick) then
            e = [1.0e-3_wp, 1.0e-2_wp, 0.1_wp, 0.5_wp, 0.9_wp, 0.99_wp]
        else
            e = [1.0e-3_wp, 2.0e-3_wp, 5.0e-3_wp, 1.0e-2_wp, 2.0e-2_wp, 5.0e-2_wp, 0.1_wp, 0.2_wp, 0.3_wp, &
                 0.4_wp, 0.5_wp, 0.6_wp, 0.7_wp, 0.8_wp, 0.9_wp, 0.95_wp, 0.99_wp, 0.999_wp]
        end if
    end function inverse_set_of

    !> The inverse rows of the law over the e of e_set at the fixed contact: the
    !> reference (the iterative inverse at inv_ref_tol; the command fails if any point of
    !> it does; tsuji: with the exact alpha of its closed form), then every method.
    subroutine inverse_table(law, e_set, min_time, repeats, rows)
        integer, intent(in) :: law
        real(wp), intent(in) :: e_set(:)
        real(wp), intent(in) :: min_time
        integer, intent(in) :: repeats
        type(bench_row), allocatable, intent(inout) :: rows(:)
        type(inv_case) :: iref
        integer :: i
        call inv_init(iref, HD_METHOD_ITERATIVE, law, inv_ref_tol, e_set, spread(inv_tc, 1, size(e_set)), &
                      spread(inv_m, 1, size(e_set)), spread(inv_u, 1, size(e_set)))
        call iref%run()
        do i = 1, size(e_set)
            if (iref%status(i) /= HD_OK) call fail(EXIT_FAILURE, 'inverse reference (' // inv_ref_text // ', ' // &
                                                   hertzdamp_law_name(law) // ') failed: ' // &
                                                   hertzdamp_message(iref%status(i)))
        end do
        if (law == HD_DAMPING_TSUJI) then
            ! the exact alpha of the overlap end (closed form) instead of the iterative one,
            ! whose error grows like that of rk45's e over -ln e as e -> 1; d is proportional to it
            iref%d = iref%d * (hertzdamp_tsuji_alpha(iref%e) / iref%alpha)
            iref%alpha = hertzdamp_tsuji_alpha(iref%e)
        end if
        call inverse_rows(law, iref, min_time, repeats, rows)
    end subroutine inverse_table

    !> The rows of every inverse method of the law against iref.
    subroutine inverse_rows(law, iref, min_time, repeats, rows)
        integer, intent(in) :: law
        type(inv_case), intent(in) :: iref
        real(wp), intent(in) :: min_time
        integer, intent(in) :: repeats
        type(bench_row), allocatable, intent(inout) :: rows(:)
        integer :: j
        real(wp), parameter :: tols(5) = [1.0e-6_wp, 1.0e-8_wp, 1.0e-10_wp, 1.0e-11_wp, 1.0e-12_wp]
        character(len=*), parameter :: tol_names(5) = ['1e-6 ', '1e-8 ', '1e-10', '1e-11', '1e-12']
        call one(HD_METHOD_FIT, 0.0_wp, 'fit', '', FAMILY_FIT)
        if (law == HD_DAMPING_LINEAR) then
            call one(HD_METHOD_COMPACT, 0.0_wp, 'compact', '', FAMILY_COMPACT)
            call one(HD_METHOD_SERIES, 0.0_wp, 'series', '', FAMILY_SERIES)
            call one(HD_METHOD_PADE, 0.0_wp, 'pade', '', FAMILY_PADE)
        end if
        do j = 1, size(tols)
            call one(HD_METHOD_ITERATIVE, tols(j), 'iterative', trim(tol_names(j)), FAMILY_ITERATIVE)
        end do
        if (law == HD_DAMPING_LINEAR) then
            do j = 1, size(tols)
                call one_gsl(tols(j), trim(tol_names(j)))
            end do
        end if
    contains
        !> The GSL reference solver's iterative inverse at accuracy tol (every point must succeed).
        subroutine one_gsl(tol, setting)
            real(wp), intent(in) :: tol
            character(len=*), intent(in) :: setting
            type(gsl_inv_case) :: c
            type(bench_row) :: r
            integer :: n
            n = size(iref%e)
            c%tol = tol
            c%e = iref%e
            c%tc = iref%tc
            c%m = iref%m
            c%u = iref%u
            allocate (c%k(n), c%d(n), c%alpha(n), c%tau(n), c%status(n), c%solves(n), c%rhs(n))
            call c%run()
            if (any(c%status /= HD_OK)) return
            r%problem = 'inverse'
            r%law = law
            r%method = 'gsl-secant'
            r%setting = setting
            r%family = FAMILY_GSL_SECANT
            r%npts = n
            r%ntot = n
            r%ns = 1.0e9_wp * bench_measure(c, min_time, repeats) / n
            r%err(3) = maxval(rel(c%alpha, iref%alpha))
            r%err(4) = maxval(rel(c%k, iref%k))
            r%err(5) = maxval(rel(c%d, iref%d))
            r%steps = sum(real(c%solves, wp)) / n      ! solves per inverse
            r%rhs = sum(real(c%rhs, wp)) / n
            rows = [rows, r]
        end subroutine one_gsl

        subroutine one(method, tol, name, setting, family)
            integer, intent(in) :: method, family
            real(wp), intent(in) :: tol
            character(len=*), intent(in) :: name, setting
            type(inv_case) :: c
            type(bench_row) :: r
            integer, allocatable :: idx(:)
            integer :: i, n
            real(wp) :: tol_
            n = size(iref%e)
            tol_ = tol
            if (tol_ <= 0.0_wp) tol_ = 1.0e-10_wp
            call inv_init(c, method, law, tol_, iref%e, iref%tc, iref%m, iref%u)
            call c%run()
            idx = pack([(i, i=1, n)], c%status == HD_OK)
            if (size(idx) == 0) return
            if (size(idx) < n) call inv_init(c, method, law, tol_, iref%e(idx), iref%tc(idx), iref%m(idx), iref%u(idx))
            r%problem = 'inverse'
            r%law = law
            r%method = name
            r%setting = setting
            r%family = family
            r%npts = size(idx)
            r%ntot = n
            r%ns = 1.0e9_wp * bench_measure(c, min_time, repeats) / size(idx)
            if (any(c%status /= HD_OK)) return
            r%err(3) = maxval(rel(c%alpha, iref%alpha(idx)))
            r%err(4) = maxval(rel(c%k, iref%k(idx)))
            r%err(5) = maxval(rel(c%d, iref%d(idx)))
            rows = [rows, r]
        end subroutine one
    end subroutine inverse_rows

    !> The header line of the inverse table (n_e: the size of the set of e).
    subroutine inverse_meta(t, n_e)
        type(out_table), intent(inout) :: t
        integer, intent(in) :: n_e
        call t%meta('inverse', itoa(n_e) // ' e in [1e-3, 0.999] (overlap), m = 1e-2 kg, ' // &
                    'u_in = 1 m/s, T_c = 1e-4 s; reference ' // inv_ref_text // ' of the same law (tsuji: ' // &
                    'with the exact alpha = sqrt5 beta(e)); iterative = ' // &
                    'secant over rk45, gsl-secant = secant over GSL rk8pd (linear law only), each solve at ' // &
                    'tol/10 min(1, |ln e|), setting = accuracy asked of alpha')
    end subroutine inverse_meta

    !> The figures of the inverse table for the law of ent: the fit's time and accuracy,
    !> the iterative rows, and the speed-up of every entry point (ent) and of the fit at
    !> equal accuracy.
    subroutine inverse_figures(rows, ent, figs)
        type(bench_row), intent(in) :: rows(:)
        type(entry_result), intent(in) :: ent
        type(cli_buffer), intent(inout) :: figs
        integer :: i_fit, i_eq, i_10, law
        real(wp) :: acc_fit
        character(len=:), allocatable :: lname
        law = ent%law
        lname = hertzdamp_law_name(law) // ': '
        ! ---- against the iterative baselines of the law, at equal accuracy
        i_fit = find_row(rows, 'inverse', law, 'fit', '')
        if (i_fit > 0) then
            acc_fit = maxval(rows(i_fit)%err(3:5))
            call figs%add(lname // 'inverse: fit ' // ftoa(rows(i_fit)%ns, '(es9.2)') // ' ns per inverse over ' // &
                          'the inverse set, max error on alpha, k, d ' // ftoa(acc_fit, '(es9.2)') // &
                          '; iterative rows (secant over rk45' // trim(merge(' or GSL rk8pd', '             ', &
                          law == HD_DAMPING_LINEAR)) // ' at the accuracy asked): ' // iter_summary(rows, law))
            i_eq = fastest_iterative(rows, law, acc_fit)
            if (i_eq > 0) then
                call figs%add(lname // 'speed-up at equal accuracy: the fastest iterative row as accurate as the ' // &
                              'fit is ' // row_name(rows(i_eq)) // ' (' // ftoa(rows(i_eq)%ns, '(es9.2)') // &
                              ' ns, error ' // ftoa(maxval(rows(i_eq)%err(3:5)), '(es9.2)') // '): ' // &
                              speedups(rows(i_eq)%ns))
            else
                ! the most accurate rows (errors within 10 % of the smallest count as ties: the
                ! reference resolves no finer), the fastest of them
                i_eq = most_accurate_iterative(rows, law)
                if (i_eq > 0) i_eq = fastest_iterative(rows, law, 1.1_wp * maxval(rows(i_eq)%err(3:5)))
                if (i_eq > 0) call figs%add(lname // 'speed-up at equal accuracy: no iterative row reaches the ' // &
                                            'fit''s accuracy; against the fastest of the most accurate ones ' // &
                                            '(error within 10 % of the smallest), ' // row_name(rows(i_eq)) // &
                                            ' (' // ftoa(rows(i_eq)%ns, '(es9.2)') // ' ns, error ' // &
                                            ftoa(maxval(rows(i_eq)%err(3:5)), '(es9.2)') // ', the fit is more ' // &
                                            'accurate): ' // speedups(rows(i_eq)%ns))
            end if
            i_10 = fastest_iterative(rows, law, 1.0e-10_wp)
            if (i_10 > 0) call figs%add(lname // 'speed-up at accuracy 1e-10 (alpha, k, d; the fit is more ' // &
                                        'accurate): fastest iterative row ' // row_name(rows(i_10)) // ' (' // &
                                        ftoa(rows(i_10)%ns, '(es9.2)') // ' ns, error ' // &
                                        ftoa(maxval(rows(i_10)%err(3:5)), '(es9.2)') // '): ' // &
                                        speedups(rows(i_10)%ns))
        end if
    contains
        !> Speed-up of every entry point of the law (and of the inverse-set fit row) against
        !> t_iter [ns], with the target of 1000.
        function speedups(t_iter) result(r)
            real(wp), intent(in) :: t_iter
            character(len=:), allocatable :: r
            integer :: k
            real(wp) :: worst
            r = ''
            worst = huge(1.0_wp)
            do k = 1, n_ways
                r = r // trim(way_name(k)) // ' ' // fratio(t_iter / ent%ns(k)) // ' x, '
                worst = min(worst, t_iter / ent%ns(k))
            end do
            r = r // 'fit on the inverse set ' // fratio(t_iter / rows(i_fit)%ns) // ' x'
            worst = min(worst, t_iter / rows(i_fit)%ns)
            r = r // ' (target at least 1000 x for every entry point: ' // &
                met(worst >= 1000.0_wp, 'short by ' // fratio(1000.0_wp / worst) // ' x') // ')'
        end function speedups
    end subroutine inverse_figures

    !> An iterative inverse row of the law.
    logical function is_iterative(r, law)
        type(bench_row), intent(in) :: r
        integer, intent(in) :: law
        is_iterative = r%problem == 'inverse' .and. r%law == law .and. &
                       (r%method == 'iterative' .or. r%method == 'gsl-secant')
    end function is_iterative

    !> The fastest iterative row of the law whose max error on alpha, k and d is at most
    !> acc (0 if none).
    integer function fastest_iterative(rows, law, acc) result(k)
        type(bench_row), intent(in) :: rows(:)
        integer, intent(in) :: law
        real(wp), intent(in) :: acc
        integer :: i
        k = 0
        do i = 1, size(rows)
            if (.not. is_iterative(rows(i), law)) cycle
            if (.not. (maxval(rows(i)%err(3:5)) <= acc)) cycle
            if (k == 0) then
                k = i
            else if (rows(i)%ns < rows(k)%ns) then
                k = i
            end if
        end do
    end function fastest_iterative

    !> The iterative row of the law with the smallest max error on alpha, k and d (0 if none).
    integer function most_accurate_iterative(rows, law) result(k)
        type(bench_row), intent(in) :: rows(:)
        integer, intent(in) :: law
        integer :: i
        k = 0
        do i = 1, size(rows)
            if (.not. is_iterative(rows(i), law)) cycle
            if (k == 0) then
                k = i
            else if (maxval(rows(i)%err(3:5)) < maxval(rows(k)%err(3:5))) then
                k = i
            end if
        end do
    end function most_accurate_iterative

    !> 'method setting: ns, error' of every iterative row of the law.
    function iter_summary(rows, law) result(s)
        type(bench_row), intent(in) :: rows(:)
        integer, intent(in) :: law
        character(len=:), allocatable :: s
        integer :: i
        s = ''
        do i = 1, size(rows)
            if (.not. is_iterative(rows(i), law)) cycle
            if (len(s) > 0) s = s // '; '
            s = s // row_name(rows(i)) // ' ' // ftoa(rows(i)%ns, '(es9.2)') // ' ns, error ' // &
                ftoa(maxval(rows(i)%err(3:5)), '(es9.2)')
        end do
    end function iter_summary

end module hertzdamp_bench_table_inverse
