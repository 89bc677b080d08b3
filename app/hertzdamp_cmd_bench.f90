!> The command `bench`: the work-precision report of the library's methods, for every
!> damping law (or the one of --damping).
!>
!> Forward problem alpha -> (e, tau_c): every method against rk45 at tol 1e-15 (of the
!> same law).  Inverse problem (e, T_c, m, u_in) -> (k, d): every method against the
!> iterative inverse at tol 1e-14, including the iterative baselines (the library's
!> secant over rk45 for every law, and for the linear law the GSL peer's secant over
!> rk8pd, each at tolerances matched to the accuracy asked).  Entry points: the fit
!> inverse of each law through every way a user calls it (module scalar and array
!> calls, C functions through their bind(C) names, legacy externals), side by side over
!> the same 10^6 contacts, with their ratios to the module scalar call, a check that
!> they agree bit for bit, and the speed-up against the fastest iterative row at equal
!> accuracy; for the tsuji law also its inverse against the closed form of its overlap
!> end; for the linear law the per-pair API (the per-contact call of a DEM host against
!> the bare formula it replaces) and the one-call inverse with T_c and m broadcast.
!> Every number is measured in this run; methods the library does not (yet) provide are
!> left out.  Everything is computed (and the plot written) before anything is printed:
!> on failure stdout stays empty.
!>
!> One builder per table (hertzdamp_bench_table_forward, _inverse, _entry,
!> _closed_form, _pair): each appends its rows and adds its header lines and figures.
!> To add a table: write its builder module and call it in measure, describe and figures
!> below.
module hertzdamp_cmd_bench
    use hertzdamp, only: hertzdamp_law_choices, hertzdamp_rk, HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, &
                         HD_DAMPING_KUWABARA_KONO, hertzdamp_law_name
    use hertzdamp_bench_entry, only: entry_data, entry_result, tsuji_result, entry_contacts, entry_measure, &
                                     tsuji_measure
    use hertzdamp_bench_rows, only: bench_row, n_laws, ftoa
    use hertzdamp_bench_table_forward, only: forward_set, forward_set_of, forward_table, forward_meta, &
                                             forward_figures
    use hertzdamp_bench_table_inverse, only: inverse_set_of, inverse_table, inverse_meta, inverse_figures
    use hertzdamp_bench_table_entry, only: entry_rows, entry_meta, entry_figures
    use hertzdamp_bench_table_closed_form, only: closed_form_rows, closed_form_meta, closed_form_figures
    use hertzdamp_bench_pair, only: pair_result, pair_measure
    use hertzdamp_bench_table_pair, only: pair_rows, pair_meta, pair_figures
    use hertzdamp_bench_output, only: build_table, make_plot
    use hertzdamp_bench_timer, only: wall_seconds
    use hertzdamp_cli_plot, only: plot_check_target
    use hertzdamp_cli_progress, only: progress_reporter
    use hertzdamp_cli, only: cli_args, cli_buffer, parse_args, parse_choice, quit, EXIT_OK
    use hertzdamp_cli_output, only: out_table, format_choices, FORMAT_TEXT, FORMAT_CSV
    use hertzdamp_cli_help, only: print_help, wants_help
    use hertzdamp_cli_text, only: itoa
    implicit none
    private
    public :: cmd_bench

    integer, parameter :: wp = hertzdamp_rk

    !> What the command line asks for.
    type :: bench_options
        integer :: fmt = FORMAT_TEXT
        integer, allocatable :: laws(:)
        logical :: quick = .false., want_plot = .false., progress = .false.
        character(len=:), allocatable :: plot_file, terminal
        real(wp) :: min_time = 0.1_wp   !! wall-clock seconds of one timed batch at least
        integer :: repeats = 5          !! batches per time (their median)
        integer :: n_entry = 1000000    !! contacts of the entry-point and closed-form tables
    end type bench_options

    !> What the run measured: the rows of every table and what their headers and
    !> figures need.
    type :: bench_run
        type(bench_row), allocatable :: rows(:)
        type(forward_set) :: sets(n_laws)
        integer :: n_e = 0
        type(entry_result) :: ent(n_laws)
        type(tsuji_result) :: ts
        type(pair_result) :: pr
    end type bench_run

contains

    ! ------------------------------------------------------------------ the command

    subroutine cmd_bench()
        type(bench_options) :: o
        type(bench_run) :: run
        type(out_table) :: t
        type(cli_buffer) :: buf, figs
        real(wp) :: t_start
        integer :: i
        call options(o)
        t_start = wall_seconds()
        call measure(o, run)
        call figures(run, size(o%laws), figs)
        ! render
        call build_table(run%rows, o%fmt, t)
        if (o%fmt /= FORMAT_CSV) call describe(o, run, figs, t)
        if (o%fmt == FORMAT_TEXT) then
            call t%render(FORMAT_TEXT, buf)
            do i = 1, figs%n
                call buf%add('figure: ' // figs%lines(i)%s)
            end do
            call buf%add('# total bench time ' // ftoa(wall_seconds() - t_start, '(f0.1)') // ' s')
        else
            call t%render(o%fmt, buf)
        end if
        if (o%want_plot) call make_plot(run%rows, o%laws, o%plot_file, o%terminal, o%quick)
        call buf%flush_to_stdout()
        call quit(EXIT_OK)
    end subroutine cmd_bench

    !> The options of the command line (help and bad arguments end the program here,
    !> before any work; so does a plot target gnuplot cannot write).
    subroutine options(o)
        type(bench_options), intent(out) :: o
        type(cli_args) :: args
        integer :: sel
        o%plot_file = ''
        o%terminal = ''
        if (wants_help()) then
            call print_help('bench')
            call quit(EXIT_OK)
        end if
        call parse_args(2, '--format --plot --damping', '--quick --progress', args)
        o%fmt = parse_choice(args%get('--format', 'text'), format_choices, 'format (--format)')
        sel = parse_choice(args%get('--damping', 'all'), 'all ' // hertzdamp_law_choices(), 'damping law (--damping)')
        o%quick = args%has('--quick')
        o%want_plot = args%has('--plot')
        o%progress = args%has('--progress')
        if (o%want_plot) then
            o%plot_file = args%get('--plot', '')
            call plot_check_target(o%plot_file, o%terminal)
        end if
        if (sel == 1) then
            o%laws = [HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO]
        else
            o%laws = [sel - 2]
        end if
        if (o%quick) then
            o%min_time = 0.01_wp
            o%repeats = 3
            o%n_entry = 100000
        else
            o%min_time = 0.1_wp
            o%repeats = 5
            o%n_entry = 1000000
        end if
    end subroutine options

    !> Every table's rows, in the order of the output: forward and inverse law by law,
    !> then the entry points law by law, then the closed form (when tsuji is run).
    subroutine measure(o, run)
        type(bench_options), intent(in) :: o
        type(bench_run), intent(inout) :: run
        type(entry_data) :: dat
        type(progress_reporter) :: prog
        real(wp), allocatable :: e_set(:)
        real(wp) :: done
        integer :: il, nl
        nl = size(o%laws)
        allocate (run%rows(0))
        ! progress in phases: forward and inverse rows per law, the contacts, the entry
        ! points per law, the tsuji closed form
        call prog%start(real(3 * nl + 2, wp), 'bench', force=o%progress)
        done = 0.0_wp
        e_set = inverse_set_of(o%quick)
        run%n_e = size(e_set)
        do il = 1, nl
            run%sets(il) = forward_set_of(o%laws(il), o%quick)
            call forward_table(o%laws(il), run%sets(il), o%min_time, o%repeats, run%rows)
            call step_done()
            call inverse_table(o%laws(il), e_set, o%min_time, o%repeats, run%rows)
            call step_done()
        end do
        call entry_contacts(o%n_entry, dat)
        call step_done()
        do il = 1, nl
            call entry_measure(o%laws(il), dat, o%min_time, o%repeats, run%ent(il))
            call entry_rows(run%ent(il), run%rows)
            call step_done()
        end do
        if (any(o%laws == HD_DAMPING_TSUJI)) then
            call tsuji_measure(dat, o%min_time, o%repeats, run%ts)
            call closed_form_rows(run%ts, run%rows)
        end if
        if (any(o%laws == HD_DAMPING_LINEAR)) then
            call pair_measure(dat, o%min_time, o%repeats, run%pr)
            call pair_rows(run%pr, run%rows)
        end if
        call prog%finish()
    contains
        subroutine step_done()
            done = done + 1.0_wp
            call prog%update(done)
        end subroutine step_done
    end subroutine measure

    !> The 'figure' lines: ratios measured side by side in this run, law by law (of the
    !> nl laws run), then the closed form.
    subroutine figures(run, nl, figs)
        type(bench_run), intent(in) :: run
        integer, intent(in) :: nl
        type(cli_buffer), intent(out) :: figs
        integer :: il
        do il = 1, nl
            call entry_figures(run%ent(il), figs)
            call inverse_figures(run%rows, run%ent(il), figs)
            call forward_figures(run%rows, run%ent(il)%law, figs)
        end do
        if (run%ts%n > 0) call closed_form_figures(run%ts, figs)
        if (run%pr%n > 0) call pair_figures(run%pr, run%ent(1), figs)
    end subroutine figures

    !> The header (text and JSON): what was run, each table's lines, the figures.
    subroutine describe(o, run, figs, t)
        type(bench_options), intent(in) :: o
        type(bench_run), intent(in) :: run
        type(cli_buffer), intent(in) :: figs
        type(out_table), intent(inout) :: t
        integer :: i
        call t%meta('bench', 'work-precision of hertzdamp: forward alpha -> (e, tau_c), inverse (e, T_c, m, ' // &
                    'u_in) -> (k, d), for the damping laws ' // law_list(o%laws) // '; every number measured in ' // &
                    'this run')
        if (o%quick) then
            call t%meta('mode', 'quick: fewer alpha and e, each time the median of 3 batches of >= 0.01 s wall ' // &
                        'clock (full run: 5 batches of >= 0.1 s)')
        else
            call t%meta('mode', 'full: each time the median of 5 batches of >= 0.1 s wall clock (system_clock)')
        end if
        call forward_meta(t, o%laws, run%sets(1:size(o%laws)))
        call inverse_meta(t, run%n_e)
        call entry_meta(t, o%n_entry)
        if (any(o%laws == HD_DAMPING_TSUJI)) call closed_form_meta(t)
        if (any(o%laws == HD_DAMPING_LINEAR)) call pair_meta(t)
        call t%meta('tolerances', 'rk45 and GSL (rkf45, rk8pd) with relative error control: absolute ' // &
                    'tolerance 1e-30 tol; rhs_evals, steps, rejected are means per collision (GSL: rejected n/a)')
        call t%meta('omitted', 'methods that report not-supported, and points whose status is not ok ' // &
                    '(column points = used/total)')
        do i = 1, figs%n
            call t%meta('figure' // itoa(i), figs%lines(i)%s, text='')   ! text: below the table
        end do
    end subroutine describe

    !> 'linear, tsuji and kuwabara-kono' (the laws of the run).
    function law_list(laws) result(s)
        integer, intent(in) :: laws(:)
        character(len=:), allocatable :: s
        integer :: i
        s = hertzdamp_law_name(laws(1))
        do i = 2, size(laws)
            s = s // trim(merge(' and', ',   ', i == size(laws))) // ' ' // hertzdamp_law_name(laws(i))
        end do
    end function law_list

end module hertzdamp_cmd_bench
