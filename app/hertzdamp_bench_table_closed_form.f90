!> The closed-form table of `hertzdamp bench`: for the tsuji law, the fit's inverse
!> against the closed form alpha = sqrt(5) beta(e) of its overlap end, and the bounded
!> d against alpha sqrt(m k) (hertzdamp_bench_entry measures them); its header line and
!> its figures.
module hertzdamp_bench_table_closed_form
    use hertzdamp, only: HD_DAMPING_TSUJI
    use hertzdamp_bench_entry, only: tsuji_result, n_ts, ts_name, ts_label, TS_CLOSED_ALPHA, TS_FIT_ALPHA, &
                                     TS_CLOSED_ALPHA_N, TS_FIT_ALPHA_N, TS_CLOSED_D, TS_BOUND_D, TS_CLOSED_D_N, &
                                     TS_BOUND_D_N
    use hertzdamp_bench_rows, only: bench_row, fratio, ftoa, FAMILY_FIT
    use hertzdamp_cli, only: cli_buffer
    use hertzdamp_cli_output, only: out_table
    use hertzdamp_cli_text, only: itoa
    implicit none
    private
    public :: closed_form_rows, closed_form_meta, closed_form_figures

contains

    !> The rows of the tsuji comparison (problem closed-form): the fit's alpha and the
    !> bound's d with their largest difference from the closed form.
    subroutine closed_form_rows(ts, rows)
        type(tsuji_result), intent(in) :: ts
        type(bench_row), allocatable, intent(inout) :: rows(:)
        type(bench_row) :: r
        integer :: w
        do w = 1, n_ts
            r = bench_row('closed-form', trim(ts_name(w)), 'n=' // itoa(ts%n), HD_DAMPING_TSUJI, FAMILY_FIT, ts%n, ts%n, &
                          ns=ts%ns(w))
            if (w == TS_FIT_ALPHA .or. w == TS_FIT_ALPHA_N) r%err(3) = ts%err_alpha
            if (w == TS_BOUND_D .or. w == TS_BOUND_D_N) r%err(5) = ts%err_d
            rows = [rows, r]
        end do
    end subroutine closed_form_rows

    !> The header line of the closed-form table.
    subroutine closed_form_meta(t)
        type(out_table), intent(inout) :: t
        call t%meta('closed-form', 'tsuji, overlap end, the entry contacts with k = k_phys half the ' // &
                    'stiffness of the unbounded inverse (bound active), timed side by side: ' // ts_legend() // &
                    '; err_alpha, err_d: largest relative difference from the closed form')
    end subroutine closed_form_meta

    !> The figures of the tsuji comparison: what the fit's inverse costs against the
    !> closed form of the overlap end, and how far its results are from it.
    subroutine closed_form_figures(ts, figs)
        type(tsuji_result), intent(in) :: ts
        type(cli_buffer), intent(inout) :: figs
        call figs%add('tsuji: inverse against the closed form alpha = sqrt5 beta(e) (overlap end, ' // itoa(ts%n) // &
                      ' contacts, ns per contact): alpha alone ' // ftoa(ts%ns(TS_CLOSED_ALPHA), '(f6.1)') // &
                      ' (closed form) against ' // ftoa(ts%ns(TS_FIT_ALPHA), '(f6.1)') // ' (fit: alpha and tau_c), ' // &
                      'ratio ' // fratio(ts%ns(TS_FIT_ALPHA) / ts%ns(TS_CLOSED_ALPHA)) // '; over arrays ' // &
                      ftoa(ts%ns(TS_CLOSED_ALPHA_N), '(f6.1)') // ' against ' // ftoa(ts%ns(TS_FIT_ALPHA_N), '(f6.1)') // &
                      ', ratio ' // fratio(ts%ns(TS_FIT_ALPHA_N) / ts%ns(TS_CLOSED_ALPHA_N)) // &
                      '; the engines'' d = alpha sqrt(m k) for a given k ' // ftoa(ts%ns(TS_CLOSED_D), '(f6.1)') // &
                      ' (closed form) against ' // ftoa(ts%ns(TS_BOUND_D), '(f6.1)') // &
                      ' (hertzdamp_invert with k_phys = k), ratio ' // fratio(ts%ns(TS_BOUND_D) / ts%ns(TS_CLOSED_D)) // &
                      '; over arrays ' // ftoa(ts%ns(TS_CLOSED_D_N), '(f6.1)') // ' against ' // &
                      ftoa(ts%ns(TS_BOUND_D_N), '(f6.1)') // ', ratio ' // &
                      fratio(ts%ns(TS_BOUND_D_N) / ts%ns(TS_CLOSED_D_N)))
        call figs%add('tsuji: the fit''s alpha differs from the closed form by at most ' // &
                      ftoa(ts%err_alpha, '(es9.2)') // ' (relative), its bounded d from alpha sqrt(m k) by ' // &
                      ftoa(ts%err_d, '(es9.2)') // '; ' // itoa(ts%failed) // ' library results not ok, ' // &
                      itoa(ts%unbound) // ' contacts with the bound inactive, ' // itoa(ts%mismatches) // &
                      ' contacts where an array call differs from the one-contact call')
    end subroutine closed_form_figures

    !> 'name = what it computes' of every row of the tsuji comparison.
    function ts_legend() result(s)
        character(len=:), allocatable :: s
        integer :: w
        s = trim(ts_name(1)) // ' = ' // trim(ts_label(1))
        do w = 2, n_ts
            s = s // '; ' // trim(ts_name(w)) // ' = ' // trim(ts_label(w))
        end do
    end function ts_legend

end module hertzdamp_bench_table_closed_form
