!> The entry-point table of `hertzdamp bench`: the fit inverse of one damping law
!> through every way a user calls it (hertzdamp_bench_entry measures them side by side
!> over the same contacts), one row per entry point; its header lines and its figures
!> (time per contact, bit-identity with the module scalar call, the targets).
module hertzdamp_bench_table_entry
    use hertzdamp, only: hertzdamp_rk, hertzdamp_law_name
    use hertzdamp_bench_entry, only: entry_result, n_ways, way_name, way_label, WAY_SCALAR, WAY_ARRAY, WAY_C, &
                                     WAY_LEGACY
    use hertzdamp_bench_rows, only: bench_row, met, fratio, ftoa, FAMILY_FIT
    use hertzdamp_cli, only: cli_buffer
    use hertzdamp_cli_output, only: out_table
    use hertzdamp_cli_text, only: itoa
    implicit none
    private
    public :: entry_rows, entry_meta, entry_figures

    integer, parameter :: wp = hertzdamp_rk

contains

    !> The rows of the entry points of one law.
    subroutine entry_rows(ent, rows)
        type(entry_result), intent(in) :: ent
        type(bench_row), allocatable, intent(inout) :: rows(:)
        type(bench_row) :: r
        integer :: w
        do w = 1, n_ways
            r = bench_row('entry', trim(way_name(w)), 'n=' // itoa(ent%n), ent%law, FAMILY_FIT, ent%n - ent%failed, ent%n, &
                          ns=ent%ns(w))
            rows = [rows, r]
        end do
    end subroutine entry_rows

    !> The header lines of the entry-point table (n_entry: the contacts).
    subroutine entry_meta(t, n_entry)
        type(out_table), intent(inout) :: t
        integer, intent(in) :: n_entry
        call t%meta('entry', itoa(n_entry) // ' contacts (overlap), e uniform in [0.05, 0.99], m in ' // &
                    '[1e-9, 1] kg, u_in in [1e-3, 10] m/s, T_c in [1e-7, 1e-3] s (log-uniform), the same for ' // &
                    'every law; the entry points of one law timed side by side (rounds of one batch each); ' // &
                    'ns_per_call = per contact')
        call t%meta('entry points', entry_legend())
    end subroutine entry_meta

    !> The figures of the entry points of one law and their targets (issue 11).
    subroutine entry_figures(ent, figs)
        type(entry_result), intent(in) :: ent
        type(cli_buffer), intent(inout) :: figs
        integer :: w
        real(wp) :: worst_c
        character(len=:), allocatable :: line, lname
        lname = hertzdamp_law_name(ent%law) // ': '
        line = lname // 'entry points over ' // itoa(ent%n) // ' contacts, ns per contact (ratio to the module ' // &
               'scalar call):'
        do w = 1, n_ways
            line = line // ' ' // trim(way_name(w)) // ' ' // ftoa(ent%ns(w), '(f6.1)') // ' (' // &
                   fratio(ent%ns(w) / ent%ns(WAY_SCALAR)) // ')' // trim(merge(',', ' ', w < n_ways))
        end do
        call figs%add(line)
        if (all(ent%mismatches == 0)) then
            call figs%add(lname // 'entry points: k, d and status bit-identical to the module scalar call for ' // &
                          'every contact and every entry point (' // itoa(ent%failed) // ' contacts not ok)')
        else
            line = lname // 'entry points: NOT bit-identical to the module scalar call, contacts that differ:'
            do w = 2, n_ways
                line = line // ' ' // trim(way_name(w)) // ' ' // itoa(ent%mismatches(w))
            end do
            call figs%add(line)
        end if
        worst_c = max(ent%ns(WAY_C), ent%ns(WAY_LEGACY)) / ent%ns(WAY_SCALAR)
        call figs%add(lname // 'targets: legacy and C per contact at most 1.3 x the module scalar call: ' // &
                      fratio(ent%ns(WAY_LEGACY) / ent%ns(WAY_SCALAR)) // ' and ' // &
                      fratio(ent%ns(WAY_C) / ent%ns(WAY_SCALAR)) // ' (' // &
                      met(worst_c <= 1.3_wp, 'short by ' // fratio(worst_c / 1.3_wp) // ' x') // &
                      '); module scalar at most 40 ns: ' // ftoa(ent%ns(WAY_SCALAR), '(f6.1)') // ' ns (' // &
                      met(ent%ns(WAY_SCALAR) <= 40.0_wp, 'short by ' // &
                      ftoa(ent%ns(WAY_SCALAR) - 40.0_wp, '(f6.1)') // ' ns') // &
                      '); array at least 2.5 x cheaper than the scalar call: ' // &
                      fratio(ent%ns(WAY_SCALAR) / ent%ns(WAY_ARRAY)) // ' x (' // &
                      met(ent%ns(WAY_SCALAR) / ent%ns(WAY_ARRAY) >= 2.5_wp, 'short by ' // &
                      fratio(2.5_wp * ent%ns(WAY_ARRAY) / ent%ns(WAY_SCALAR)) // ' x') // &
                      '); array at most 15 ns per contact: ' // ftoa(ent%ns(WAY_ARRAY), '(f6.1)') // ' ns (' // &
                      met(ent%ns(WAY_ARRAY) <= 15.0_wp, 'short by ' // &
                      ftoa(ent%ns(WAY_ARRAY) - 15.0_wp, '(f6.1)') // ' ns') // ')')
    end subroutine entry_figures

    !> 'name = what it calls' of every entry point, for the linear law and the others.
    function entry_legend() result(s)
        character(len=:), allocatable :: s
        integer :: w
        s = 'linear: ' // trim(way_name(1)) // ' = ' // trim(way_label(1, 1))
        do w = 2, n_ways
            s = s // '; ' // trim(way_name(w)) // ' = ' // trim(way_label(w, 1))
        end do
        s = s // '; the other laws: ' // trim(way_name(1)) // ' = ' // trim(way_label(1, 2))
        do w = 2, n_ways
            s = s // '; ' // trim(way_name(w)) // ' = ' // trim(way_label(w, 2))
        end do
    end function entry_legend

end module hertzdamp_bench_table_entry
