!> The output of `hertzdamp bench`: the rows as a table (text, CSV, JSON) and the
!> work-precision diagram (gnuplot).
module hertzdamp_bench_output
    use hertzdamp, only: hertzdamp_rk, hertzdamp_law_name
    use hertzdamp_bench_rows, only: bench_row, n_families, fam, plot_floor
    use hertzdamp_bench_table_inverse, only: inv_ref_text
    use hertzdamp_cli_plot, only: plot_scratch, plot_temp_name, gp_string
    use hertzdamp_cli, only: cli_buffer
    use hertzdamp_cli_output, only: out_table, FORMAT_TEXT, FORMAT_JSON
    use hertzdamp_cli_text, only: itoa
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    implicit none
    private
    public :: build_table, make_plot

    integer, parameter :: wp = hertzdamp_rk

contains

    subroutine build_table(rows, fmt, t)
        type(bench_row), intent(in) :: rows(:)
        integer, intent(in) :: fmt
        type(out_table), intent(out) :: t
        integer :: i, j
        if (fmt == FORMAT_TEXT) then
            call t%set_columns('problem,damping,method,setting,points,err_e,err_tau,err_alpha,err_k,err_d,' // &
                               'ns_per_call,steps,rejected,rhs_evals')
        else
            call t%set_columns('problem,damping,method,setting,max_rel_err_e,max_rel_err_tau,max_rel_err_alpha,' // &
                               'max_rel_err_k,max_rel_err_d,ns_per_call,rhs_evals')
        end if
        do i = 1, size(rows)
            call t%str(rows(i)%problem)
            call t%str(hertzdamp_law_name(rows(i)%law))
            call t%str(rows(i)%method)
            call t%str(blank_or(rows(i)%setting, fmt))
            if (fmt == FORMAT_TEXT) call t%str(itoa(rows(i)%npts) // '/' // itoa(rows(i)%ntot))
            do j = 1, 5
                call cell(rows(i)%err(j))
            end do
            call cell(rows(i)%ns)
            if (fmt == FORMAT_TEXT) then
                call cell(rows(i)%steps)
                call cell(rows(i)%rejected)
            end if
            call cell(rows(i)%rhs)
        end do
    contains
        !> A number, or the format's empty cell when negative (not applicable).
        subroutine cell(x)
            real(wp), intent(in) :: x
            if (x >= 0.0_wp) then
                call t%num(x)
            else if (fmt == FORMAT_JSON) then
                call t%num(ieee_value(x, ieee_quiet_nan))   ! rendered as null
            else if (fmt == FORMAT_TEXT) then
                call t%str('-')
            else
                call t%str('')
            end if
        end subroutine cell
    end subroutine build_table

    function blank_or(s, fmt) result(r)
        character(len=*), intent(in) :: s
        integer, intent(in) :: fmt
        character(len=:), allocatable :: r
        r = s
        if (len(s) == 0 .and. fmt == FORMAT_TEXT) r = '-'
    end function blank_or

    !> Work-precision diagram: forward (top) and inverse (bottom) panels, one column per
    !> damping law of the run.  Data and script go to temporary files; the PNG is written
    !> to FILE.tmp and renamed into place only when gnuplot succeeded.
    subroutine make_plot(rows, laws, file, terminal, quick)
        type(bench_row), intent(in) :: rows(:)
        integer, intent(in) :: laws(:)
        character(len=*), intent(in) :: file, terminal
        logical, intent(in) :: quick
        character(len=:), allocatable :: dat, gp, png_tmp
        type(cli_buffer) :: plots
        type(plot_scratch) :: sc
        character(len=:), allocatable :: cmd
        character(len=200) :: line
        integer :: u, p, f, i, il, nblock, blocks(2, size(laws), n_families)
        character(len=*), parameter :: pts(n_families) = ['7 ', '5 ', '9 ', '13', '11', '3 ', '2 ', '1 ', '4 ']
        character(len=*), parameter :: colors(n_families) = ['#1f77b4', '#ff7f0e', '#2ca02c', '#9467bd', &
                                                             '#8c564b', '#e377c2', '#d62728', '#7f7f7f', '#17becf']
        character(len=*), parameter :: problems(2) = ['forward', 'inverse']
        real(wp) :: y
        cmd = ''
        png_tmp = plot_temp_name()
        ! data and script are scratch files of hertzdamp_cli_plot: every write checked, all
        ! removed whatever happens, exit 4 with nothing left behind on failure
        call sc%open('bench', 'dat', u, dat)
        nblock = 0
        blocks = -1
        do p = 1, 2
            do il = 1, size(laws)
                do f = 1, n_families
                    if (.not. any([(in_panel(rows(i), p, il) .and. rows(i)%family == f, i=1, size(rows))])) cycle
                    blocks(p, il, f) = nblock
                    nblock = nblock + 1
                    do i = 1, size(rows)
                        if (.not. in_panel(rows(i), p, il) .or. rows(i)%family /= f) cycle
                        if (p == 1) then
                            y = max(rows(i)%err(1), rows(i)%err(2))
                        else
                            y = maxval(rows(i)%err(3:5))
                        end if
                        write (line, '(es14.6,1x,es14.6,1x,a)') rows(i)%ns, max(y, plot_floor), &
                            '"' // trim(rows(i)%setting) // '"'
                        call sc%write(u, trim(line))
                    end do
                    call sc%write(u, '')
                    call sc%write(u, '')
                end do
            end do
        end do
        call sc%close(u)

        call sc%open('bench', 'gp', u, gp)
        if (terminal == 'pngcairo') then
            call sc%write(u, 'set terminal pngcairo size ' // itoa(100 + 620 * size(laws)) // &
                ',1150 enhanced font "sans,10"')
        else
            call sc%write(u, 'set terminal png size ' // itoa(100 + 620 * size(laws)) // ',1150')
        end if
        call sc%write(u, 'set output ' // gp_string(png_tmp))
        call sc%write(u, 'set multiplot layout 2,' // itoa(size(laws)) // &
            ' title "hertzdamp bench: work-precision' // trim(merge(' (--quick)', '          ', quick)) // '"')
        call sc%write(u, 'set logscale xy')
        ! fixed decades wide enough for every method (no point on the frame), room for the key
        call sc%write(u, 'set xrange [3:3e7]')
        call sc%write(u, 'set yrange [1e-16:1e6]')
        call sc%write(u, 'set format x "10^{%L}"')
        call sc%write(u, 'set format y "10^{%L}"')
        call sc%write(u, 'set grid')
        call sc%write(u, 'set key top left horizontal maxcols 3 samplen 2')
        call sc%write(u, 'set xlabel "time per call [ns] (median)"')
        call sc%write(u, 'set ylabel "max relative error (floor 1e-17)"')
        do p = 1, 2
            do il = 1, size(laws)
                if (p == 1) then
                    call sc%write(u, 'set title "' // hertzdamp_law_name(laws(il)) // &
                        ', forward: alpha -> e, tau_c  (vs rk45 tol 1e-15)" noenhanced')
                else
                    call sc%write(u, 'set title "' // hertzdamp_law_name(laws(il)) // &
                        ', inverse: e, T_c, m, u_in -> alpha, k, d  (vs ' // inv_ref_text // ')" noenhanced')
                end if
                plots%n = 0
                do f = 1, n_families
                    if (blocks(p, il, f) < 0) cycle
                    call plots%add(gp_string(dat) // ' index ' // itoa(blocks(p, il, f)) // &
                                   ' using 1:2 with linespoints pt ' // trim(pts(f)) // ' ps 1.5 lc rgb "' // &
                                   colors(f) // '" title "' // trim(fam(f)) // '" noenhanced')
                end do
                if (plots%n == 0) then
                    call sc%write(u, 'set label 1 "no data" at graph 0.5, graph 0.5 center')
                    call sc%write(u, 'plot [1:10] [1:10] NaN notitle')
                    call sc%write(u, 'unset label 1')
                else
                    cmd = 'plot '
                    do i = 1, plots%n
                        cmd = cmd // plots%lines(i)%s
                        if (i < plots%n) cmd = cmd // ', '
                    end do
                    call sc%write(u, cmd)
                end if
            end do
        end do
        call sc%write(u, 'unset multiplot')
        call sc%write(u, 'set output')
        call sc%close(u)

        call sc%draw(gp, file)
    contains
        !> The row belongs to panel (problem p, law il).
        logical function in_panel(r, p, il)
            type(bench_row), intent(in) :: r
            integer, intent(in) :: p, il
            in_panel = r%problem == problems(p) .and. r%law == laws(il)
        end function in_panel
    end subroutine make_plot

end module hertzdamp_bench_output
