!> The options that choose the model and the method, shared by the commands:
!> `--damping`, `--end`, `--method`, `--tol`, `--order`, `--accuracy`, `--format`.
!>
!> A command lists `model_options` among its valued options, calls
!> `parse_model(args, c, inverse)` and passes `c%law`, `c%iend`, `c%method`, `c%tol`,
!> `c%order`, `c%accuracy` to the library.  A new model option is one name in
!> `model_options`, one field in `model_opts` and one line in `parse_model`.
!>
!> The messages of this module say what a method accepts and which method to use
!> instead: for the forward commands fit or rk45, for the inverse fit or iterative.
module hertzdamp_cli_model
    use hertzdamp, only: hertzdamp_rk, hertzdamp_rk45_default_tol, hertzdamp_default_accuracy, &
                         hertzdamp_series_default_order, hertzdamp_series_max_order, hertzdamp_invert_default_tol, &
                         hertzdamp_fit_e_min_overlap, hertzdamp_fit_e_min_force, hertzdamp_compact_e_min_overlap, &
                         hertzdamp_compact_e_min_force, hertzdamp_pade_alpha_max, hertzdamp_fit_alpha_max_force, &
                         hertzdamp_compact_alpha_max_force, hertzdamp_compact_alpha_max_overlap, &
                         hertzdamp_forward_alpha, hertzdamp_collision, hertzdamp_alpha_min, hertzdamp_alpha_max, &
                         hertzdamp_method_code, hertzdamp_law_code, hertzdamp_fit_law_e_min, &
                         HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_END_OVERLAP, HD_METHOD_RK45, HD_METHOD_SERIES, HD_METHOD_PADE, &
                         HD_METHOD_COMPACT, HD_METHOD_FIT, HD_METHOD_ITERATIVE, HD_OK, hertzdamp_law_name, &
                         hertzdamp_end_name, hertzdamp_end_code, hertzdamp_method_name, hertzdamp_law_choices, &
                         hertzdamp_end_choices, hertzdamp_method_choices, hertzdamp_law_summary, &
                         fit_law_e_min_forward => hertzdamp_fit_law_e_min_forward
    use hertzdamp_cli, only: cli_args, parse_real, parse_int, parse_choice, fail, EXIT_USAGE
    use hertzdamp_cli_text, only: fmt_short, itoa
    use hertzdamp_cli_output, only: format_choices
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> The valued options parse_model reads (list them in parse_args).
    character(len=*), parameter, public :: model_options = '--damping --end --method --tol --order --accuracy --format'

    !> The parsed model options.
    type, public :: model_opts
        integer :: law = HD_DAMPING_LINEAR                        !! HD_DAMPING_*
        character(len=:), allocatable :: law_name                 !! as given
        integer :: iend = HD_END_OVERLAP                          !! HD_END_*
        integer :: method = HD_METHOD_RK45                        !! HD_METHOD_*
        character(len=:), allocatable :: method_name              !! as given
        logical :: inverse = .false.                              !! the inverse methods apply
        integer :: fmt = 1                                        !! FORMAT_*
        real(wp) :: tol = hertzdamp_rk45_default_tol              !! rk45 / iterative tolerance
        integer :: order = hertzdamp_series_default_order         !! series order
        real(wp) :: accuracy = hertzdamp_default_accuracy         !! accuracy asked of series and Pade
        character(len=:), allocatable :: tol_text, accuracy_text  !! as given (for the metadata)
    end type model_opts

    public :: parse_model, method_accepts, instead, e_range_message, damping_unit, law_text, parse_law, parse_end

contains

    !> Read --damping, --end, --method, --tol, --order, --accuracy, --format; exit 2
    !> naming the option on a bad value or one that does not apply to the method.
    subroutine parse_model(args, c, inverse)
        type(cli_args), intent(in) :: args
        type(model_opts), intent(out) :: c
        logical, intent(in) :: inverse   !! inverse methods (fit default) instead of forward (rk45 default)
        character(len=:), allocatable :: tol_for
        integer :: k
        c%inverse = inverse
        c%law_name = args%get('--damping', hertzdamp_law_name(HD_DAMPING_LINEAR))
        c%law = parse_law(c%law_name, '--damping')
        c%iend = parse_end(args%get('--end', hertzdamp_end_name(HD_END_OVERLAP)))
        c%fmt = parse_choice(args%get('--format', 'text'), format_choices, 'format (--format)')
        if (inverse) then
            c%method_name = args%get('--method', hertzdamp_method_name(HD_METHOD_FIT))
            k = parse_choice(c%method_name, hertzdamp_method_choices('inverse'), 'method (--method)')
            c%tol = hertzdamp_invert_default_tol
            tol_for = hertzdamp_method_name(HD_METHOD_ITERATIVE)
        else
            c%method_name = args%get('--method', hertzdamp_method_name(HD_METHOD_RK45))
            k = parse_choice(c%method_name, hertzdamp_method_choices('forward'), 'method (--method)')
            tol_for = hertzdamp_method_name(HD_METHOD_RK45)
        end if
        c%method = hertzdamp_method_code(c%method_name)
        c%tol_text = args%get('--tol', fmt_short(c%tol))
        if (args%has('--tol')) then
            c%tol = parse_real(c%tol_text, '--tol')
            if (.not. (c%tol >= 1.0e-15_wp .and. c%tol <= 1.0e-2_wp)) then
                call fail(EXIT_USAGE, '--tol ' // c%tol_text // ': the tolerance must lie in [1e-15, 1e-2]')
            end if
            if (c%method /= HD_METHOD_RK45 .and. c%method /= HD_METHOD_ITERATIVE) then
                call fail(EXIT_USAGE, '--tol applies to --method ' // tol_for // ' only')
            end if
        end if
        if (args%has('--order')) then
            c%order = parse_int(args%get('--order', ''), '--order')
            if (c%order > hertzdamp_series_max_order) call fail(EXIT_USAGE, '--order ' // itoa(c%order) // &
                ': the series is stored up to order ' // itoa(hertzdamp_series_max_order))
            if (c%method /= HD_METHOD_SERIES) call fail(EXIT_USAGE, '--order applies to --method series only')
            if (inverse) call fail(EXIT_USAGE, '--order applies to the forward commands only ' // &
                                   '(the inverse uses the default order ' // itoa(hertzdamp_series_default_order) // ')')
        end if
        c%accuracy_text = args%get('--accuracy', fmt_short(c%accuracy))
        if (args%has('--accuracy')) then
            c%accuracy = parse_real(c%accuracy_text, '--accuracy')
            if (.not. (c%accuracy > 0.0_wp .and. c%accuracy <= 1.0_wp)) then
                call fail(EXIT_USAGE, '--accuracy ' // c%accuracy_text // ': must lie in (0, 1] (relative error)')
            end if
            if (c%method /= HD_METHOD_SERIES .and. c%method /= HD_METHOD_PADE) then
                call fail(EXIT_USAGE, '--accuracy applies to --method series and pade only ' // &
                          '(the other methods have a fixed accuracy, see --help)')
            end if
        end if
        if (c%law /= HD_DAMPING_LINEAR .and. (c%method == HD_METHOD_SERIES .or. c%method == HD_METHOD_PADE .or. &
                                              c%method == HD_METHOD_COMPACT)) then
            call fail(EXIT_USAGE, '--method ' // c%method_name // ' exists for --damping linear only; ' // &
                      'use --method ' // hertzdamp_method_name(HD_METHOD_FIT) // ' (or ' // &
                      hertzdamp_method_name(merge(HD_METHOD_ITERATIVE, HD_METHOD_RK45, inverse)) // ') with --damping ' // &
                      c%law_name)
        end if
        if ((c%method == HD_METHOD_SERIES .or. c%method == HD_METHOD_PADE) .and. c%iend /= HD_END_OVERLAP) then
            call fail(EXIT_USAGE, '--method ' // c%method_name // ' supports --end overlap only: ' // &
                      'the force definition is not analytic at alpha = 0 (see doc/series.md); use --method fit')
        end if
    end subroutine parse_model

    !> Unit of the damping coefficient d of the law (damping force d zeta^q zeta').
    function damping_unit(law) result(s)
        integer, intent(in) :: law   !! HD_DAMPING_*
        character(len=:), allocatable :: s
        select case (law)
        case (HD_DAMPING_LINEAR); s = 'kg/s'
        case default; s = 'kg s^-1 m^-' // merge('1/4', '1/2', law == HD_DAMPING_TSUJI)
        end select
    end function damping_unit

    !> The damping law as the reports of `check` and `scene` state it: name, damping
    !> force, and how its alpha depends on the impact speed.
    function law_text(law) result(s)
        integer, intent(in) :: law   !! HD_DAMPING_*
        character(len=:), allocatable :: s
        s = hertzdamp_law_summary(law)
    end function law_text

    !> The law code of a name given for an option (exit 2 naming it and the choices if it is none).
    function parse_law(name, option) result(law)
        character(len=*), intent(in) :: name, option
        integer :: law, k
        k = parse_choice(name, hertzdamp_law_choices(), 'damping law (' // option // ')')
        law = hertzdamp_law_code(name)
    end function parse_law

    !> The contact-end code of a --end value (exit 2 naming --end and the choices if it is none).
    function parse_end(name) result(iend)
        character(len=*), intent(in) :: name
        integer :: iend, k
        k = parse_choice(name, hertzdamp_end_choices(), 'contact-end definition (--end)')
        iend = hertzdamp_end_code(name)
    end function parse_end

    !> The alpha range a forward method accepts, as text.
    function method_accepts(c) result(s)
        type(model_opts), intent(in) :: c
        character(len=:), allocatable :: s
        select case (c%method)
        case (HD_METHOD_RK45)
            s = fmt_short(hertzdamp_alpha_min) // ' <= alpha <= ' // fmt_short(hertzdamp_alpha_max) // ' (overlap), ' // &
                '0 <= alpha <= ' // fmt_short(hertzdamp_alpha_max) // ' (force)'
        case (HD_METHOD_FIT)
            if (c%law == HD_DAMPING_LINEAR) then
                s = 'alpha >= 0 (overlap), 0 <= alpha <= ' // fmt_short(hertzdamp_fit_alpha_max_force) // ' (force)'
            else
                s = 'the alpha of e >= ' // fmt_short(fit_law_e_min_forward) // ' with --damping ' // c%law_name // &
                    ' (its fitted range)'
            end if
        case (HD_METHOD_COMPACT)
            s = '0 <= alpha <= ' // fmt_short(hertzdamp_compact_alpha_max_overlap) // ' (overlap; no rebound from ' // &
                'alpha_c on), 0 <= alpha <= ' // fmt_short(hertzdamp_compact_alpha_max_force) // ' (force): e >= ' // &
                fmt_short(hertzdamp_compact_e_min_overlap)
        case (HD_METHOD_SERIES)
            s = '|alpha| < 1, overlap only, where its error estimate meets --accuracy ' // fmt_short(c%accuracy)
        case (HD_METHOD_PADE)
            s = '0 <= alpha <= ' // fmt_short(hertzdamp_pade_alpha_max) // ', overlap only, where its error ' // &
                'estimate meets --accuracy ' // fmt_short(c%accuracy)
        case default
            s = 'see --help'
        end select
    end function method_accepts

    !> What to use instead of the chosen method, for this command: fit and rk45 for
    !> the forward commands, fit and iterative for the inverse (not the one in use).
    function instead(c) result(s)
        type(model_opts), intent(in) :: c
        character(len=:), allocatable :: s
        if (c%inverse) then
            s = merge('use --method iterative', 'use --method fit      ', c%method == HD_METHOD_FIT)
            if (c%method /= HD_METHOD_FIT .and. c%method /= HD_METHOD_ITERATIVE) s = 'use --method fit (or iterative)'
        else
            s = merge('use --method fit ', 'use --method rk45', c%method == HD_METHOD_RK45)
            if (c%method /= HD_METHOD_FIT .and. c%method /= HD_METHOD_RK45) s = 'use --method fit or rk45'
        end if
        s = trim(s)
    end function instead

    !> Why restitution `e` has no inverse with the chosen method, naming --e and the range.
    function e_range_message(c, e, e_text) result(s)
        type(model_opts), intent(in) :: c
        real(wp), intent(in) :: e
        character(len=*), intent(in) :: e_text   !! e as the user sees it
        character(len=:), allocatable :: s
        real(wp) :: emin
        type(hertzdamp_collision) :: r
        if (.not. (e >= 0.0_wp .and. e <= 1.0_wp)) then
            s = '--e ' // e_text // ': a restitution coefficient lies in [0, 1]'
            return
        end if
        select case (c%method)
        case (HD_METHOD_COMPACT)
            emin = merge(hertzdamp_compact_e_min_overlap, hertzdamp_compact_e_min_force, c%iend == HD_END_OVERLAP)
        case (HD_METHOD_PADE)
            ! the e at the end of the Pade range, by the fit
            r = hertzdamp_forward_alpha(hertzdamp_pade_alpha_max, HD_END_OVERLAP, HD_METHOD_FIT)
            emin = merge(r%e, 1.0_wp, r%status == HD_OK)
            s = '--e ' // e_text // ': --method pade is valid for alpha <= ' // fmt_short(hertzdamp_pade_alpha_max) // &
                ', i.e. e >= ' // fmt_short(emin) // ' (and where its error estimate meets --accuracy ' // &
                fmt_short(c%accuracy) // '); ' // instead(c)
            return
        case (HD_METHOD_SERIES)
            s = '--e ' // e_text // ': --method series does not reach this e within --accuracy ' // &
                fmt_short(c%accuracy) // ' (it converges for alpha < 1); ' // instead(c)
            return
        case default
            emin = hertzdamp_fit_law_e_min(c%law, c%iend)
        end select
        s = '--e ' // e_text // ': --method ' // c%method_name // ' accepts ' // fmt_short(emin) // ' <= e <= 1 for ' // &
            '--end ' // hertzdamp_end_name(c%iend)
        s = trim(s)
        if (e < emin .and. c%iend == HD_END_OVERLAP .and. c%method /= HD_METHOD_COMPACT) then
            s = s // ' (e -> 0 has no finite contact time)'
        else if (e < emin .and. c%method == HD_METHOD_COMPACT) then
            s = s // '; use --method fit for e >= ' // &
                fmt_short(merge(hertzdamp_fit_e_min_overlap, hertzdamp_fit_e_min_force, c%iend == HD_END_OVERLAP))
        end if
    end function e_range_message

end module hertzdamp_cli_model
