!> The per-pair table of `hertzdamp bench` (hertzdamp_bench_pair measures it): the
!> per-contact call of a DEM host against the bare formula, the array forms, and the
!> one-call inverse with T_c and m broadcast; its header line and its figures.
module hertzdamp_bench_table_pair
    use hertzdamp, only: hertzdamp_rk, HD_DAMPING_LINEAR
    use hertzdamp_bench_pair, only: pair_result, n_pw, pw_name, pw_label, pair_e, bcast_tc, bcast_m, PW_BARE, PW_C, &
                                    PW_SCALAR, PW_BARE_VEC, PW_ARRAY, PW_INVERT_EACH, PW_INVERT_TC_M, PW_INVERT_TC, &
                                    PW_C_PHASE, PW_PHASE
    use hertzdamp_bench_entry, only: entry_result, WAY_SCALAR, WAY_ARRAY
    use hertzdamp_bench_rows, only: bench_row, met, fratio, ftoa, FAMILY_FIT
    use hertzdamp_cli, only: cli_buffer
    use hertzdamp_cli_output, only: out_table
    use hertzdamp_cli_text, only: itoa, fmt_short
    implicit none
    private
    public :: pair_rows, pair_meta, pair_figures

    integer, parameter :: wp = hertzdamp_rk

    !> The per-contact C call may cost at most this multiple of the bare formula.
    real(wp), parameter :: c_target = 1.5_wp
    !> The per-contact phase form (issue 32) may cost at most this multiple of the bare
    !> formula, and pair_init with its table at N = 10 at most this many ms.
    real(wp), parameter :: phase_target = 2.0_wp, init_target_ms = 5.0_wp

contains

    !> The rows of the per-pair table (problem pair, linear law).
    subroutine pair_rows(pr, rows)
        type(pair_result), intent(in) :: pr
        type(bench_row), allocatable, intent(inout) :: rows(:)
        type(bench_row) :: r
        integer :: w
        do w = 1, n_pw
            r = bench_row('pair', trim(pw_name(w)), 'n=' // itoa(pr%n), HD_DAMPING_LINEAR, FAMILY_FIT, pr%n, pr%n, &
                          ns=pr%ns(w))
            rows = [rows, r]
        end do
    end subroutine pair_rows

    !> The header line of the per-pair table.
    subroutine pair_meta(t)
        type(out_table), intent(inout) :: t
        call t%meta('pair', 'the entry contacts (T_c, m, u_in), one material pair (linear law, overlap end, e = ' // &
                    fmt_short(pair_e) // ', host none; broadcast rows: T_c = ' // fmt_short(bcast_tc) // ' s, m = ' // &
                    fmt_short(bcast_m) // ' kg, e and u_in of the contacts), timed side by side: ' // legend())
    end subroutine pair_meta

    !> The figures: the per-contact C call against the bare formula (target at most 1.5 x),
    !> the Fortran forms, the broadcast inverse against the array and per-contact calls.
    subroutine pair_figures(pr, ent, figs)
        type(pair_result), intent(in) :: pr
        type(entry_result), intent(in) :: ent     !! the linear law's entry points (the array call)
        type(cli_buffer), intent(inout) :: figs
        real(wp) :: rc
        rc = pr%c_ratio
        call figs%add('pair: ns per contact over ' // itoa(pr%n) // ' contacts (medians of ' // itoa(pr%rounds) // &
                      ' rounds; ratios: the median of the rounds'' ratios): bare formula ' // &
                      ftoa(pr%ns(PW_BARE), '(f6.1)') // ' (one contact per iteration), C hertzdamp_c_pair_kd ' // &
                      ftoa(pr%ns(PW_C), '(f6.1)') // ' (' // fratio(rc) // ' x the bare formula; target at most ' // &
                      fratio(c_target) // ' x: ' // met(rc <= c_target, 'short by ' // fratio(rc / c_target) // ' x') // &
                      '), Fortran hertzdamp_pair_kd ' // ftoa(pr%ns(PW_SCALAR), '(f6.1)') // ' (' // &
                      fratio(pr%ns(PW_SCALAR) / pr%ns(PW_BARE)) // ' x); over arrays: bare (vectorised) ' // &
                      ftoa(pr%ns(PW_BARE_VEC), '(f6.1)') // ', hertzdamp_pair_kd ' // ftoa(pr%ns(PW_ARRAY), '(f6.1)') // &
                      ' (' // fratio(pr%array_ratio) // ' x)')
        call figs%add('pair: hertzdamp_invert with the same T_c and m for every contact: one call per contact ' // &
                      ftoa(pr%ns(PW_INVERT_EACH), '(f6.1)') // ' ns, scalar T_c and m over arrays ' // &
                      ftoa(pr%ns(PW_INVERT_TC_M), '(f6.1)') // ' ns (' // &
                      fratio(pr%ns(PW_INVERT_EACH) / pr%ns(PW_INVERT_TC_M)) // ' x faster), scalar T_c ' // &
                      ftoa(pr%ns(PW_INVERT_TC), '(f6.1)') // ' ns; the all-array call of the entry table ' // &
                      ftoa(ent%ns(WAY_ARRAY), '(f6.1)') // ' ns, its one call per contact ' // &
                      ftoa(ent%ns(WAY_SCALAR), '(f6.1)') // ' ns')
        call figs%add('pair: the onset-phase form (issue 32): C hertzdamp_c_pair_kd_phase ' // &
                      ftoa(pr%ns(PW_C_PHASE), '(f6.1)') // ' ns (' // fratio(pr%phase_ratio) // ' x the bare formula; ' // &
                      'target at most ' // fratio(phase_target) // ' x: ' // &
                      met(pr%phase_ratio <= phase_target, 'short by ' // fratio(pr%phase_ratio / phase_target) // ' x') // &
                      '), Fortran hertzdamp_pair_kd_phase ' // ftoa(pr%ns(PW_PHASE), '(f6.1)') // ' ns; ' // &
                      'hertzdamp_pair_init with the table (mfix-euler, N = 10) ' // ftoa(pr%init_ms(1), '(f6.2)') // &
                      ' ms at e = 0.2, ' // ftoa(pr%init_ms(2), '(f6.2)') // ' ms at e = 0.5 (target at most ' // &
                      ftoa(init_target_ms, '(f4.1)') // ' ms: ' // met(maxval(pr%init_ms) <= init_target_ms, &
                      'short by ' // fratio(maxval(pr%init_ms) / init_target_ms) // ' x') // ')')
        if (pr%mismatches == 0) then
            call figs%add('pair: C, scalar and array pair_kd bit-identical, the broadcast inverse bit-identical to one ' // &
                          'call per contact (' // itoa(pr%failed) // ' results not ok)')
        else
            call figs%add('pair: NOT bit-identical: ' // itoa(pr%mismatches) // ' contacts differ between rows that ' // &
                          'must agree')
        end if
    end subroutine pair_figures

    !> 'name = what it computes' of every row.
    function legend() result(s)
        character(len=:), allocatable :: s
        integer :: w
        s = trim(pw_name(1)) // ' = ' // trim(pw_label(1))
        do w = 2, n_pw
            s = s // '; ' // trim(pw_name(w)) // ' = ' // trim(pw_label(w))
        end do
    end function legend

end module hertzdamp_bench_table_pair
