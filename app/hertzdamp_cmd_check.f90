!> The command `check`: what a peer DEM engine's input deck really does.
!>
!>     hertzdamp check ENGINE DECK... --radius R --density RHO --velocity SWEEP [options]
!>     hertzdamp check --table
!>
!> The engine's parameters are read by hertzdamp_peers_deck, evaluated by
!> hertzdamp_peers (numbers from the library); this module parses and prints only.
module hertzdamp_cmd_check
    use hertzdamp, only: hertzdamp_rk, hertzdamp_message, hertzdamp_end_name, hertzdamp_law_name, &
                         hertzdamp_law_has_alpha_c, hertzdamp_law_alpha_c, hertzdamp_law_speed_exponent, &
                         hertzdamp_method_name, hertzdamp_fit_law_e_min, hertzdamp_alpha_max, &
                         HD_METHOD_FIT, HD_METHOD_RK45, &
                         HD_OK, HD_NO_REBOUND, HD_END_OVERLAP, HD_END_FORCE, HD_OUTSIDE_VALIDITY, HD_OUT_OF_RANGE, &
                         HD_BAD_RESTITUTION, HD_NOT_SUPPORTED, HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, &
                         HD_DAMPING_KUWABARA_KONO
    use hertzdamp_peers, only: peer_deck, peer_point, peer_text, peer_evaluate, peer_spec_field, peer_spec_count, &
                               peer_law_inverse, peer_law_forward, peer_beta, peer_beta_inverse, &
                               peer_damping, peer_row_law, peer_row_end, peer_row_coef, &
                               peer_nan, peer_float, peer_name, &
                               PEER_LAMMPS, PEER_LIGGGHTS, PEER_MERCURYDPM, PEER_YADE, PEER_MFIX, PEER_CHRONO, &
                               TSTEP_NONE, TSTEP_LIGGGHTS, TSTEP_MERCURY, TSTEP_MFIX, COEF_GAMMA_P6, COEF_GAMMA_SQRT2_P6, &
                               COEF_GAMMA_SQRT5_BETA, COEF_GAMMA_2BETA, COEF_GAMMA_SQRT6, COEF_GAMMA_SQRT5_BETA_EPS
    use hertzdamp_peers_deck, only: peer_materials, peer_read_deck, peer_code, peer_parameter_problem, &
                                    LAMMPS_2021, LAMMPS_2023, LAMMPS_CURRENT, lammps_releases
    use hertzdamp_cli_plausible, only: warn_implausible, quiet_flag
    use hertzdamp_cli, only: cli_args, cli_line, cli_buffer, parse_args, parse_real, parse_int, parse_choice, &
                             required_sweep, fail, quit, EXIT_USAGE, EXIT_OK
    use hertzdamp_cli_text, only: itoa, fmt_short, ROUND_TRIP
    use hertzdamp_cli_output, only: out_table, format_choices, FORMAT_TEXT
    use hertzdamp_cli_help, only: print_help, wants_help
    use hertzdamp_cli_materials, only: cli_contact, parse_contact
    use hertzdamp_cli_model, only: law_text
    use hertzdamp_cli_rows, only: row_log, row_kind, row_word, row_has_result
    use hertzdamp_cli_progress, only: progress_reporter
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private
    public :: cmd_check, check_table_lines

    integer, parameter :: wp = hertzdamp_rk

    !> Targets of the documentation table.
    real(wp), parameter :: table_targets(5) = [0.1_wp, 0.3_wp, 0.5_wp, 0.7_wp, 0.9_wp]
    !> Speed ratios u/u0 of the speed-dependence table.
    real(wp), parameter :: table_ratios(5) = [0.01_wp, 0.1_wp, 1.0_wp, 10.0_wp, 100.0_wp]

    !> The contact options of `check` (hertzdamp_cli_materials reads and checks them; the
    !> deck may give the radius and density instead, e.g. MFiX D_P0 and RO_S0).
    character(len=*), parameter :: material_options = '--radius --radius2 --density --density2'

    !> What `check` was asked (the options but the deck).
    type :: check_request
        integer :: release = LAMMPS_CURRENT  !! LAMMPS_*
        integer :: steps = 10                !! time steps per contact of the advice
        integer :: fmt = FORMAT_TEXT         !! FORMAT_*
        logical :: have_e = .false.          !! --e given
        logical :: progress = .false.        !! --progress
        real(wp) :: e_user = 0.0_wp          !! --e
        real(wp), allocatable :: speeds(:)   !! --velocity
    end type check_request

contains

    subroutine cmd_check()
        type(cli_args) :: args
        type(cli_line), allocatable :: words(:)
        type(cli_contact) :: ct
        type(check_request) :: rq
        type(peer_text), allocatable :: tokens(:)
        type(peer_materials) :: mat
        character(len=:), allocatable :: v
        integer :: i, peer
        if (wants_help()) call print_help('check')
        call parse_args(2, '--velocity --e --steps --release --format ' // material_options, &
                        '--table --wall --progress ' // quiet_flag, args, positionals=words)
        rq%fmt = parse_choice(args%get('--format', 'text'), format_choices, 'format (--format)')
        if (args%has('--table')) then
            if (size(words) > 0 .or. size(args%opts) > merge(2, 1, args%has('--format'))) then
                call fail(EXIT_USAGE, '--table takes no engine and no option but --format')
            end if
            call print_table(rq%fmt)
            call quit(EXIT_OK)
        end if
        if (size(words) == 0) call fail(EXIT_USAGE, 'missing the engine: lammps, liggghts, mercurydpm, yade, ' // &
                                        'mfix or chrono (see hertzdamp check --help)')
        peer = peer_code(words(1)%s)
        if (peer == 0) call fail(EXIT_USAGE, 'unknown engine "' // words(1)%s // &
                                 '": choose lammps, liggghts, mercurydpm, yade, mfix or chrono')
        allocate (tokens(0))
        do i = 2, size(words)
            call split_words(words(i)%s, tokens)
        end do
        ! the bodies: checked as every command checks them (a wall has no --radius2, ...)
        call parse_contact(args, ct)
        mat%wall = ct%wall
        mat%radius(1) = optional_value('--radius')
        mat%radius(2) = optional_value('--radius2')
        mat%density(1) = optional_value('--density')
        mat%density(2) = optional_value('--density2')
        if (args%has('--release')) then
            if (peer /= PEER_LAMMPS) call fail(EXIT_USAGE, '--release applies to lammps only')
            rq%release = parse_choice(args%get('--release', ''), lammps_releases, 'LAMMPS release (--release)')
        end if
        rq%speeds = required_sweep(args, '--velocity')
        do i = 1, size(rq%speeds)
            if (.not. rq%speeds(i) > 0.0_wp) call fail(EXIT_USAGE, '--velocity ' // fmt_short(rq%speeds(i), ROUND_TRIP) // &
                                                       ': impact speeds must be positive')
        end do
        rq%have_e = args%has('--e')
        if (rq%have_e) then
            v = args%get('--e', '')
            rq%e_user = parse_real(v, '--e')
            if (.not. (rq%e_user > 0.0_wp .and. rq%e_user <= 1.0_wp)) then
                call fail(EXIT_USAGE, '--e ' // v // ': the target restitution must be in (0, 1]')
            end if
        end if
        if (args%has('--steps')) then
            rq%steps = parse_int(args%get('--steps', ''), '--steps')
            if (rq%steps < 1) call fail(EXIT_USAGE, '--steps must be >= 1')
        end if
        rq%progress = args%has('--progress')
        call warn_implausible(args)
        call run_check(peer, tokens, mat, rq)
    contains
        !> The value of a material option, 0 when absent (parse_contact has checked it).
        real(wp) function optional_value(key) result(x)
            character(len=*), intent(in) :: key
            x = 0.0_wp
            if (args%has(key)) x = parse_real(args%get(key, ''), key)
        end function optional_value
    end subroutine cmd_check

    ! ------------------------------------------------------------------ one deck

    subroutine run_check(peer, tokens, mat, rq)
        integer, intent(in) :: peer
        type(peer_text), intent(in) :: tokens(:)
        type(peer_materials), intent(in) :: mat
        type(check_request), intent(in) :: rq
        type(peer_deck) :: deck
        type(peer_point), allocatable :: pt(:)
        type(out_table) :: t
        type(row_log) :: rows
        type(progress_reporter) :: progress
        type(peer_text), allocatable :: warn(:), note(:)
        character(len=:), allocatable :: msg, s
        real(wp) :: et
        integer :: status, i, kind, nfail, first_fail
        logical :: have
        call peer_read_deck(peer, tokens, mat, rq%release, deck, status, msg)
        if (status /= HD_OK) call fail(EXIT_USAGE, peer_name(peer) // ': ' // msg)
        if (rq%have_e) then
            et = rq%e_user
        else if (deck%e_deck > 0.0_wp) then
            et = deck%e_deck
        else
            call fail(EXIT_USAGE, 'missing --e (the restitution coefficient you want: this ' // peer_name(peer) // &
                      ' deck sets ' // deck%p_name // ', not e)')
        end if
        allocate (pt(size(rq%speeds)))
        call progress%start(real(size(pt), wp), 'check', force=rq%progress)
        do i = 1, size(pt)
            pt(i) = peer_evaluate(deck, rq%speeds(i), et)
            call progress%update(real(i, wp))
        end do
        call progress%finish()
        call t%set_columns('velocity,alpha,e,e_error,t_c,t_attractive,dt_max,t_hertz,t_peer,corrected,method,status', &
                           'm/s,,,,s,s,s,s,s,,,')
        nfail = 0
        first_fail = 0
        do i = 1, size(pt)
            if (row_has_result(row_kind(pt(i)%status))) cycle
            nfail = nfail + 1
            if (first_fail == 0) first_fail = i
        end do
        if (nfail == size(pt)) then
            ! no row has a result: one line on stderr, nothing on stdout (the rows decide the code)
            do i = 1, size(pt)
                call rows%add(row_kind(pt(i)%status), row_reason(deck, pt(i)))
            end do
            call rows%emit(t, rq%fmt)
        end if
        allocate (warn(0), note(0))
        call t%meta('engine', trim(peer_spec_field(deck%row, 'engine')) // ': ' // peer_spec_field(deck%row, 'option'))
        if (peer == PEER_LAMMPS) then
            call t%meta('version', deck%version // ' (--release ' // release_word(rq%release) // '); ' // &
                        peer_spec_field(deck%row, 'version'))
        else
            call t%meta('version', peer_spec_field(deck%row, 'version'))
        end if
        call t%meta('deck', deck%deck_text)
        call t%meta('law', law_text(deck%law))
        call t%meta('contact end', end_text(deck%iend))
        call t%meta('formula', formula_text(deck))
        call t%meta('source', peer_spec_field(deck%row, 'source_path') // ' (' // &
                    peer_spec_field(deck%row, 'source_lines') // ')')
        call t%meta('stiffness', deck%k_text // ': k = ' // fmt_short(deck%k, 6) // ' N m^-3/2')
        s = 'm = ' // fmt_short(deck%m, 6) // ' kg, R = ' // fmt_short(deck%radius, 6) // ' m'
        if (deck%wall) then
            s = s // ' (particle against a flat wall)'
        else
            s = s // ' (effective mass and radius of the pair)'
        end if
        call t%meta('contact', s)
        if (rq%have_e) then
            call t%meta('target', 'e = ' // fmt_short(et, ROUND_TRIP) // ' (--e)')
        else
            call t%meta('target', 'e = ' // fmt_short(et, ROUND_TRIP) // ' (the ' // deck%p_name // ')')
        end if
        call t%meta('achieved', achieved_text(pt, et))
        call t%meta('corrected', corrected_text(deck, pt, et))
        call time_step_texts(deck, pt, rq%steps, t)
        call t%meta('method', method_text(pt))
        call collect_warnings(deck, pt, warn)
        do i = 1, size(deck%notes)
            note = [note, deck%notes(i)]
        end do
        if (peer == PEER_LAMMPS) call release_notes(tokens, mat, rq%release, deck, pt, et, note)
        if (nfail > 0) warn = [warn, peer_text(itoa(nfail) // ' of ' // itoa(size(pt)) // &
                               ' speeds have no result; first: ' // row_reason(deck, pt(first_fail)))]
        do i = 1, size(warn)
            call t%meta(numbered('warning', i, size(warn)), warn(i)%s)
        end do
        do i = 1, size(note)
            call t%meta(numbered('note', i, size(note)), note(i)%s)
        end do
        call t%meta('units', 'velocity [m/s]; t_c, t_attractive (overlap end: when the total force turns ' // &
                    'attractive), dt_max = t_c/' // itoa(rq%steps) // ', t_hertz (elastic Hertz time), t_peer ' // &
                    '(the engine''s own estimate) [s]; e_error = e/e_target - 1; corrected: ' // deck%p_name // &
                    '; method: what gave e and t_c')
        do i = 1, size(pt)
            kind = row_kind(pt(i)%status)
            have = row_has_result(kind)
            call t%num(pt(i)%u)
            call t%num_or_none(pt(i)%alpha, have)
            call t%num_or_none(pt(i)%e, have)
            call t%num_or_none(pt(i)%e_error, have)
            call t%num_or_none(pt(i)%tc, have)
            call t%num_or_none(pt(i)%t_force, have)
            call t%num_or_none(pt(i)%tc / rq%steps, pt(i)%status == HD_OK)
            call t%num_or_none(pt(i)%t_hertz, have)
            call t%num_or_none(pt(i)%t_peer, have)
            call t%num_or_none(pt(i)%p_corrected, have .and. pt(i)%status_corrected == HD_OK)
            if (have .and. pt(i)%method > 0) then
                call t%str(hertzdamp_method_name(pt(i)%method))
            else
                call t%none()
            end if
            call t%str(row_word(kind))
            if (have) then
                call rows%add(kind, '')
            else
                call rows%add(kind, row_reason(deck, pt(i)))
            end if
        end do
        call rows%emit(t, rq%fmt)
    end subroutine run_check

    !> Why a speed has no result, naming --velocity and its value.
    function row_reason(deck, pt) result(s)
        type(peer_deck), intent(in) :: deck
        type(peer_point), intent(in) :: pt
        character(len=:), allocatable :: s
        s = '--velocity ' // fmt_short(pt%u, ROUND_TRIP) // ': '
        if (ieee_is_finite(pt%alpha)) s = s // 'alpha = ' // fmt_short(pt%alpha, 6)
        if (pt%method == HD_METHOD_RK45) s = s // ' (rk45: beyond the fitted range)'
        if (ieee_is_finite(pt%alpha)) s = s // ': '
        select case (pt%status)
        case (HD_OUT_OF_RANGE)
            s = s // pt%beyond // ' is outside the double-precision range'
        case (HD_OUTSIDE_VALIDITY)
            if (pt%alpha > hertzdamp_alpha_max) then
                s = s // 'beyond ' // fmt_short(hertzdamp_alpha_max, ROUND_TRIP) // ', the largest alpha any method takes'
            else
                s = s // law_message(deck, pt%status)
            end if
        case default
            s = s // law_message(deck, pt%status)
        end select
    end function row_reason

    !> Which method gave e and t_c: the library's fitted maps, its reference integrator
    !> beyond their range (the column method says it per speed).
    function method_text(pt) result(s)
        type(peer_point), intent(in) :: pt(:)
        character(len=:), allocatable :: s
        integer :: nfit, nrk
        nfit = count(pt%method == HD_METHOD_FIT)
        nrk = count(pt%method == HD_METHOD_RK45)
        s = ''
        if (nfit > 0) s = 'fit (the library''s fitted maps of the law and end) at ' // itoa(nfit) // ' of ' // &
                          itoa(size(pt)) // ' speeds'
        if (nrk > 0) then
            if (len(s) > 0) s = s // '; '
            s = s // 'rk45 (the reference integrator) at ' // itoa(nrk) // ' of ' // itoa(size(pt)) // &
                ' speeds, where alpha is beyond the fitted range'
        end if
        if (nfit + nrk < size(pt)) then
            if (len(s) > 0) s = s // '; '
            s = s // 'none at ' // itoa(size(pt) - nfit - nrk) // ' of ' // itoa(size(pt)) // &
                ' speeds (alpha beyond double precision and alpha_c: no rebound; or no result)'
        end if
    end function method_text

    !> 'warning', or 'warning 2' ... when there are several.
    function numbered(word, i, n) result(s)
        character(len=*), intent(in) :: word
        integer, intent(in) :: i, n
        character(len=:), allocatable :: s
        s = word
        if (n > 1) s = word // ' ' // itoa(i)
    end function numbered

    function release_word(release) result(s)
        integer, intent(in) :: release
        character(len=:), allocatable :: s
        select case (release)
        case (LAMMPS_2021); s = '2021'
        case (LAMMPS_2023); s = '2023'
        case default; s = 'current'
        end select
    end function release_word

    function law_message(deck, status) result(s)
        type(peer_deck), intent(in) :: deck
        integer, intent(in) :: status
        character(len=:), allocatable :: s
        if (status == HD_NOT_SUPPORTED) then
            s = 'the ' // hertzdamp_law_name(deck%law) // ' damping law with the ' // hertzdamp_end_name(deck%iend) // &
                ' end is not available in this build of the library'
        else
            s = hertzdamp_message(status)
        end if
    end function law_message

    function end_text(iend) result(s)
        integer, intent(in) :: iend
        character(len=:), allocatable :: s
        if (iend == HD_END_OVERLAP) then
            s = 'overlap: the contact lasts until the overlap returns to zero; the total force is not clipped'
        else
            s = 'force: the total normal force is clipped at zero; the contact ends when it would turn attractive'
        end if
    end function end_text

    function formula_text(deck) result(s)
        type(peer_deck), intent(in) :: deck
        character(len=:), allocatable :: s
        if (deck%law == HD_DAMPING_TSUJI) then
            s = 'gamma = ' // peer_spec_field(deck%row, 'alpha_expr')
            if (deck%m_damp /= deck%m) s = s // ' times sqrt(M_w/(m + M_w)) (the wall body''s mass)'
            s = s // ' = ' // fmt_short(peer_damping(deck, deck%p), 10) // ' (alpha = gamma)'
        else
            s = 'alpha = ' // peer_spec_field(deck%row, 'alpha_expr') // ' with tstar = (m/(k sqrt(u)))^(2/5)'
        end if
        s = s // '; ' // trim(deck%p_name) // ' = ' // fmt_short(deck%p, ROUND_TRIP)
    end function formula_text

    !> e over the speeds against the target (the rows with a result; there is one).
    function achieved_text(pt, et) result(s)
        type(peer_point), intent(in) :: pt(:)
        real(wp), intent(in) :: et
        character(len=:), allocatable :: s
        integer :: i, ilo, ihi
        ilo = 0
        ihi = 0
        do i = 1, size(pt)
            if (.not. (pt(i)%status == HD_OK .or. pt(i)%status == HD_NO_REBOUND)) cycle
            if (ilo == 0) then
                ilo = i
                ihi = i
            end if
            if (pt(i)%e < pt(ilo)%e) ilo = i
            if (pt(i)%e > pt(ihi)%e) ihi = i
        end do
        if (abs(pt(ihi)%e - pt(ilo)%e) <= 1.0e-12_wp * pt(ihi)%e) then
            s = 'e = ' // fmt_short(pt(ilo)%e, 6) // ' at every speed (' // pct(pt(ilo)%e_error) // &
                ' against the target ' // fmt_short(et, ROUND_TRIP) // ')'
        else
            s = 'e from ' // fmt_short(pt(ilo)%e, 6) // ' (u = ' // fmt_short(pt(ilo)%u, 6) // ' m/s, ' // &
                pct(pt(ilo)%e_error) // ') to ' // fmt_short(pt(ihi)%e, 6) // ' (u = ' // &
                fmt_short(pt(ihi)%u, 6) // ' m/s, ' // pct(pt(ihi)%e_error) // '); target ' // fmt_short(et, ROUND_TRIP)
        end if
    end function achieved_text

    !> Whether a relative difference is below what the reports state (5e-7 in
    !> magnitude, 'within 1e-6').
    pure logical function negligible(x)
        real(wp), intent(in) :: x
        negligible = abs(x) < 5.0e-7_wp
    end function negligible

    !> A relative difference x (finite) as a signed percentage, '+23.22 %', '-1.5e-3 %',
    !> '+5e+301 %'; 'within 1e-6' when negligible.
    function pct(x, unsigned) result(s)
        real(wp), intent(in) :: x
        logical, intent(in), optional :: unsigned   !! no + sign
        character(len=:), allocatable :: s
        character(len=32) :: b
        integer :: ex, ios
        if (negligible(x)) then
            s = 'within 1e-6'
            return
        end if
        if (abs(x) < 0.00005_wp) then
            write (b, '(sp,es9.2)') 100.0_wp * x
            s = trim(adjustl(b)) // ' %'
        else if (abs(x) < 1.0e6_wp) then
            write (b, '(sp,f16.2)') 100.0_wp * x
            s = trim(adjustl(b)) // ' %'
        else
            ! 100 x may overflow: the digits of x (d.ddd) with its exponent raised by 2
            write (b, '(sp,es12.3e3)') x
            read (b(9:12), *, iostat=ios) ex
            if (ios /= 0) ex = -2   ! (not reached: es12.3e3 always writes the exponent there)
            s = trim(adjustl(b(1:7))) // 'e' // itoa(ex + 2) // ' %'
        end if
        if (present(unsigned)) then
            if (unsigned .and. s(1:1) == '+') s = s(2:)
        end if
    end function pct

    !> The corrected parameter, in the engine's terms.
    function corrected_text(deck, pt, et) result(s)
        type(peer_deck), intent(in) :: deck
        type(peer_point), intent(in) :: pt(:)
        real(wp), intent(in) :: et
        character(len=:), allocatable :: s, problem
        real(wp) :: alpha, lo, hi, ealt
        integer :: i, ilo, ihi, st
        ilo = 0
        ihi = 0
        do i = 1, size(pt)
            if (pt(i)%status_corrected /= HD_OK) cycle
            if (ilo == 0) then
                ilo = i
                ihi = i
            end if
            if (pt(i)%p_corrected < pt(ilo)%p_corrected) ilo = i
            if (pt(i)%p_corrected > pt(ihi)%p_corrected) ihi = i
        end do
        if (ilo == 0) then
            ! the reason at the first speed with a result (there is one)
            i = 1
            do while (.not. row_has_result(row_kind(pt(i)%status)))
                i = i + 1
            end do
            s = 'no value of ' // deck%p_name // ' gives e = ' // fmt_short(et, ROUND_TRIP) // ': '
            select case (pt(i)%status_corrected)
            case (HD_OUTSIDE_VALIDITY)
                s = s // 'the engine''s formula cannot produce alpha = ' // fmt_short(pt(i)%alpha_target, 6)
            case (HD_BAD_RESTITUTION)
                s = s // 'the target is below e = ' // fmt_short(hertzdamp_fit_law_e_min(deck%law, deck%iend), ROUND_TRIP) // &
                    ', the end of the library''s fitted inverse for this law and contact end'
            case (HD_OUT_OF_RANGE)
                s = s // 'the value is outside the double-precision range (u = ' // fmt_short(pt(i)%u, 6) // ' m/s)'
            case default
                s = s // law_message(deck, pt(i)%status_corrected)
            end select
            return
        end if
        lo = pt(ilo)%p_corrected
        hi = pt(ihi)%p_corrected
        if (deck%law == HD_DAMPING_TSUJI) then
            s = subst(deck%p_template, fmt_short(lo, 12)) // ' gives e = ' // fmt_short(et, ROUND_TRIP) // ' (alpha = ' // &
                fmt_short(pt(ilo)%alpha_target, 10) // ')'
            problem = peer_parameter_problem(deck, lo)
            if (len(problem) > 0) s = s // '; but ' // problem
        else
            if (ilo == ihi) then
                s = subst(deck%p_template, fmt_short(lo, 12)) // ' gives e = ' // fmt_short(et, ROUND_TRIP) // ' at u = ' // &
                    fmt_short(pt(ilo)%u, 6) // ' m/s only (alpha depends on u)'
            else
                s = 'no single value of ' // deck%p_name // ' gives e = ' // fmt_short(et, ROUND_TRIP) // ' at every speed ' // &
                    '(alpha depends on u); per speed in the column corrected, from ' // fmt_short(lo, 6) // &
                    ' (u = ' // fmt_short(pt(ilo)%u, 6) // ' m/s) to ' // fmt_short(hi, 6) // ' (u = ' // &
                    fmt_short(pt(ihi)%u, 6) // ' m/s): ' // subst(deck%p_template, fmt_short(lo, 12)) // ' ... ' // &
                    subst(deck%p_template, fmt_short(hi, 12))
            end if
            if (deck%peer == PEER_LAMMPS) then
                ! the zeta^(1/4) law is speed-independent: coeff_restitution with the e that gives the target
                call peer_law_inverse(HD_DAMPING_TSUJI, et, deck%iend, alpha, st)
                if (st == HD_OK .and. alpha < sqrt(5.0_wp)) then
                    ealt = peer_beta_inverse(alpha / sqrt(5.0_wp))
                    s = s // '. Speed-independent instead (LAMMPS 27 Jun 2024 and later): damping coeff_restitution ' // &
                        'with e = ' // fmt_short(ealt, 12)
                end if
            end if
        end if
    end function corrected_text

    function subst(template, v) result(s)
        character(len=*), intent(in) :: template, v
        character(len=:), allocatable :: s
        integer :: j
        j = index(template, '{}')
        if (j == 0) then
            s = template // ' ' // v
        else
            s = template(1:j - 1) // v // template(j + 2:)
        end if
    end function subst

    !> The time step the deck needs, against the elastic Hertz time and the engine's own estimate.
    subroutine time_step_texts(deck, pt, steps, t)
        type(peer_deck), intent(in) :: deck
        type(peer_point), intent(in) :: pt(:)
        integer, intent(in) :: steps
        type(out_table), intent(inout) :: t
        character(len=:), allocatable :: s
        integer :: i, ib
        real(wp) :: dt_mfix, x
        ib = 0
        do i = 1, size(pt)
            if (pt(i)%status /= HD_OK) cycle
            if (ib == 0) ib = i
            if (pt(i)%tc < pt(ib)%tc) ib = i
        end do
        if (ib == 0) then
            call t%meta('time step', 'no speed rebounds: no contact time')
            return
        end if
        s = itoa(steps) // ' steps per contact need dt <= ' // fmt_short(pt(ib)%tc / steps, 6) // ' s (u = ' // &
            fmt_short(pt(ib)%u, 6) // ' m/s gives the shortest contact, t_c = ' // fmt_short(pt(ib)%tc, 6) // &
            ' s); the elastic Hertz time there is ' // fmt_short(pt(ib)%t_hertz, 6) // ' s, so the contact lasts '
        x = pt(ib)%tc / pt(ib)%t_hertz - 1.0_wp
        if (negligible(x)) then
            s = s // 'as long as the elastic estimate (' // pct(x) // ')'
        else if (x > 0.0_wp) then
            s = s // pct(x, unsigned=.true.) // ' longer than the elastic estimate'
        else
            s = s // pct(-x, unsigned=.true.) // ' shorter than the elastic estimate'
        end if
        call t%meta('time step', s)
        if (deck%tstep /= TSTEP_NONE .and. .not. ieee_is_finite(pt(ib)%t_peer)) then
            call t%meta('engine time step', engine_estimate_missing(deck))
            return
        end if
        select case (deck%tstep)
        case (TSTEP_LIGGGHTS)
            s = 'LIGGGHTS fix check/timestep/gran estimates 2.87 (m_p^2/(r/2 Y*^2 v))^(1/5) = ' // &
                fmt_short(pt(ib)%t_peer, 6) // ' s at v = ' // trim(merge('2u', 'u ', deck%wall)) // &
                ' (whole particle mass m_p, r/2): ' // against(pt(ib)%t_peer, pt(ib)%tc) // ' against t_c'
        case (TSTEP_MERCURY)
            s = 'MercuryDPM getCollisionTime(2r, rho, u) = 2.214 (rho^2/(E^2 u))^(1/5) 2r = ' // &
                fmt_short(pt(ib)%t_peer, 6) // ' s (elastic, identical spheres): ' // &
                against(pt(ib)%t_peer, pt(ib)%tc) // ' against t_c'
        case (TSTEP_MFIX)
            dt_mfix = pt(ib)%t_peer / deck%dt_factor
            x = pt(ib)%tc / dt_mfix
            s = 'MFiX sets DTSOLID = TCOLL/DTSOLID_FACTOR with TCOLL = pi/sqrt(k/m - (eta/m)^2/4) = ' // &
                fmt_short(pt(ib)%t_peer, 6) // ' s (a linear-spring period with the Hertz k and eta: the ' // &
                'units do not match); DTSOLID = ' // fmt_short(dt_mfix, 6) // ' s gives '
            if (ieee_is_finite(x) .and. x > 0.0_wp) then
                s = s // fmt_short(x, 4) // ' steps per contact at u = ' // fmt_short(pt(ib)%u, 6) // ' m/s'
            else
                s = s // 'a number of steps per contact beyond double precision at u = ' // fmt_short(pt(ib)%u, 6) // &
                    ' m/s'
            end if
        case default
            s = 'the engine has no contact-time estimate of its own (doc/peers.md)'
        end select
        call t%meta('engine time step', s)
    end subroutine time_step_texts

    !> Why the engine's own contact-time estimate is missing (NaN) for this deck.
    function engine_estimate_missing(deck) result(s)
        type(peer_deck), intent(in) :: deck
        character(len=:), allocatable :: s
        real(wp) :: g
        select case (deck%tstep)
        case (TSTEP_LIGGGHTS); s = 'LIGGGHTS fix check/timestep/gran estimates 2.87 (m_p^2/(r/2 Y*^2 v))^(1/5)'
        case (TSTEP_MERCURY); s = 'MercuryDPM getCollisionTime(2r, rho, u) = 2.214 (rho^2/(E^2 u))^(1/5) 2r'
        case default; s = 'MFiX TCOLL = pi/sqrt(k/m - (eta/m)^2/4)'
        end select
        g = peer_damping(deck, deck%p)
        if (deck%tstep == TSTEP_MFIX .and. .not. 0.25_wp * g**2 < 1.0_wp) then
            s = s // ' is not defined for this deck (zero or negative radicand): MFiX''s DTSOLID would be NaN'
        else
            s = s // ': outside the double-precision range for this deck'
        end if
    end function engine_estimate_missing

    !> a against b as a signed percentage of a/b - 1 (both finite and positive).
    function against(a, b) result(s)
        real(wp), intent(in) :: a, b
        character(len=:), allocatable :: s
        real(wp) :: x
        x = a / b - 1.0_wp
        if (ieee_is_finite(x)) then
            s = pct(x)
        else
            s = 'a ratio beyond double precision'
        end if
    end function against

    subroutine collect_warnings(deck, pt, warn)
        type(peer_deck), intent(in) :: deck
        type(peer_point), intent(in) :: pt(:)
        type(peer_text), allocatable, intent(inout) :: warn(:)
        integer :: i, nno, iworst
        real(wp) :: umax, frac, worst, ac
        character(len=:), allocatable :: s
        nno = 0
        umax = 0.0_wp
        iworst = 0
        worst = 0.0_wp
        do i = 1, size(pt)
            if (pt(i)%status == HD_NO_REBOUND) then
                nno = nno + 1
                umax = max(umax, pt(i)%u)
            end if
            if (pt(i)%status == HD_OK .and. ieee_is_finite(pt(i)%t_force)) then
                frac = 1.0_wp - pt(i)%t_force / pt(i)%tc
                if (frac > worst) then
                    worst = frac
                    iworst = i
                end if
            end if
        end do
        if (nno > 0) then
            s = 'no rebound at ' // itoa(nno) // ' of ' // itoa(size(pt)) // ' speeds (up to u = ' // &
                fmt_short(umax, 6) // ' m/s): the overlap never returns to zero'
            if (hertzdamp_law_has_alpha_c(deck%law) .and. deck%iend == HD_END_OVERLAP) then
                ac = hertzdamp_law_alpha_c(deck%law)
                s = s // ' (alpha >= alpha_c = ' // fmt_short(ac, 6) // ')'
            end if
            warn = [warn, peer_text(s)]
        end if
        if (iworst > 0) then
            s = 'the total force turns attractive before the particles separate: for the last ' // &
                fmt_short(100.0_wp * worst, 3) // ' % of the contact (u = ' // fmt_short(pt(iworst)%u, 6) // &
                ' m/s); the engine does not clip it'
            select case (deck%peer)
            case (PEER_LAMMPS); s = s // ' (limit_damping clips it: the force end)'
            case (PEER_LIGGGHTS); s = s // ' (limitForce on clips it: the force end)'
            case default
            end select
            warn = [warn, peer_text(s)]
        end if
    end subroutine collect_warnings

    !> LAMMPS: what the other releases give for the same deck, where it differs.
    subroutine release_notes(tokens, mat, release, deck, pt, et, note)
        type(peer_text), intent(in) :: tokens(:)
        type(peer_materials), intent(in) :: mat
        integer, intent(in) :: release
        type(peer_deck), intent(in) :: deck
        type(peer_point), intent(in) :: pt(:)
        real(wp), intent(in) :: et
        type(peer_text), allocatable, intent(inout) :: note(:)
        type(peer_deck) :: other
        type(peer_point) :: q
        integer :: r, st, i
        character(len=:), allocatable :: msg
        ! at the first speed with a result (there is one)
        i = 1
        do while (.not. row_has_result(row_kind(pt(i)%status)))
            i = i + 1
        end do
        do r = LAMMPS_2021, LAMMPS_CURRENT
            if (r == release) cycle
            call peer_read_deck(PEER_LAMMPS, tokens, mat, r, other, st, msg)
            if (st /= HD_OK) then
                note = [note, peer_text(other%version // ': ' // msg)]
                cycle
            end if
            if (other%row == deck%row .and. other%k == deck%k) cycle
            q = peer_evaluate(other, pt(i)%u, et)
            if (q%status /= HD_OK .and. q%status /= HD_NO_REBOUND) cycle
            if (q%status == pt(i)%status) then
                if (q%status == HD_NO_REBOUND) cycle
                if (abs(q%e - pt(i)%e) <= 1.0e-12_wp .and. abs(q%tc - pt(i)%tc) <= 1.0e-12_wp * pt(i)%tc) cycle
            end if
            if (q%status == HD_NO_REBOUND) then
                msg = ' gives no rebound'
            else
                msg = ' gives e = ' // fmt_short(q%e, 6) // ', t_c = ' // fmt_short(q%tc, 6) // ' s'
            end if
            note = [note, peer_text(other%version // msg // ' at u = ' // fmt_short(pt(i)%u, 6) // &
                                    ' m/s for this deck (' // peer_spec_field(other%row, 'alpha_expr') // &
                                    '; ' // other%k_text // ')')]
        end do
    end subroutine release_notes

    ! ------------------------------------------------------------------ the documentation table

    !> `hertzdamp check --table`: markdown (text), CSV or JSON.
    subroutine print_table(fmt)
        integer, intent(in) :: fmt
        type(cli_buffer) :: buf
        type(peer_text), allocatable :: lines(:)
        integer :: i
        if (fmt == FORMAT_TEXT) then
            call check_table_lines(lines)
            do i = 1, size(lines)
                call buf%add(lines(i)%s)
            end do
        else
            call table_data(fmt, buf)
        end if
        call buf%flush_to_stdout()
    end subroutine print_table

    !> The rows whose damping parameter is a restitution coefficient (or Yade's betan,
    !> read as the linear damping ratio beta(e) of the target).
    logical function restitution_row(row)
        integer, intent(in) :: row
        select case (peer_row_coef(row))
        case (COEF_GAMMA_P6, COEF_GAMMA_SQRT2_P6, COEF_GAMMA_SQRT5_BETA, COEF_GAMMA_2BETA, COEF_GAMMA_SQRT6, &
              COEF_GAMMA_SQRT5_BETA_EPS)
            restitution_row = .true.
        case default
            restitution_row = .false.
        end select
    end function restitution_row

    !> e achieved by a restitution row when the user writes the target et.
    subroutine row_achieved(row, et, e, st)
        integer, intent(in) :: row
        real(wp), intent(in) :: et
        real(wp), intent(out) :: e
        integer, intent(out) :: st
        type(peer_deck) :: d
        real(wp) :: tau
        d%row = row
        d%coef = peer_row_coef(row)
        d%m = 1.0_wp
        d%m_damp = 1.0_wp
        d%p = et
        if (d%coef == COEF_GAMMA_SQRT6) d%p = peer_beta(et)
        if (d%coef == COEF_GAMMA_SQRT5_BETA_EPS) d%p = peer_float(et)
        call peer_law_forward(peer_row_law(row), peer_damping(d, d%p), peer_row_end(row), e, tau, st)
    end subroutine row_achieved

    !> e at u = ratio u0 for a speed-dependent law whose coefficient gives et exactly at u0.
    subroutine speed_achieved(law, iend, et, ratio, e, st)
        integer, intent(in) :: law, iend
        real(wp), intent(in) :: et, ratio
        real(wp), intent(out) :: e
        integer, intent(out) :: st
        real(wp) :: a0, tau, expo
        e = 0.0_wp
        call peer_law_inverse(law, et, iend, a0, st)
        if (st /= HD_OK) return
        expo = hertzdamp_law_speed_exponent(law)
        call peer_law_forward(law, a0 * ratio**expo, iend, e, tau, st)
    end subroutine speed_achieved

    function cell(e, st) result(s)
        real(wp), intent(in) :: e
        integer, intent(in) :: st
        character(len=:), allocatable :: s
        character(len=16) :: b
        select case (st)
        case (HD_OK)
            write (b, '(f6.4)') e
            s = trim(adjustl(b))
        case (HD_NO_REBOUND)
            s = 'no rebound'
        case default
            s = 'n/a'
        end select
    end function cell

    function used_by(law, iend) result(s)
        integer, intent(in) :: law, iend
        character(len=:), allocatable :: s
        integer :: row
        character(len=:), allocatable :: eng, opt
        s = ''
        do row = 1, peer_spec_count
            if (peer_row_law(row) /= law .or. peer_row_end(row) /= iend) cycle
            if (restitution_row(row)) cycle
            eng = peer_spec_field(row, 'engine')
            opt = short_option(row)
            if (index(s, eng // ' ' // opt) > 0) cycle
            if (len(s) > 0) s = s // '; '
            s = s // eng // ' ' // opt
        end do
    end function used_by

    !> A short name of a row's option for the tables.
    function short_option(row) result(s)
        integer, intent(in) :: row
        character(len=:), allocatable :: s
        character(len=:), allocatable :: id
        id = peer_spec_field(row, 'id')
        select case (id)
        case ('lammps-2021-velocity-overlap', 'lammps-2021-velocity-force', 'lammps-2023-velocity-overlap', &
              'lammps-2023-velocity-force'); s = '`velocity`'
        case ('lammps-2021-mass_velocity-overlap', 'lammps-2021-mass_velocity-force', &
              'lammps-2023-mass_velocity-overlap', 'lammps-2023-mass_velocity-force'); s = '`mass_velocity`'
        case ('lammps-2021-viscoelastic-overlap', 'lammps-2021-viscoelastic-force', &
              'lammps-2023-viscoelastic-overlap', 'lammps-2023-viscoelastic-force'); s = '`viscoelastic`'
        case ('lammps-2021-tsuji-overlap', 'lammps-2023-tsuji-overlap', 'lammps-current-tsuji-overlap'); s = '`tsuji`'
        case ('lammps-2021-tsuji-force', 'lammps-2023-tsuji-force', 'lammps-current-tsuji-force')
            s = '`tsuji` + `limit_damping`'
        case ('lammps-2024-coeff_restitution-overlap'); s = '`coeff_restitution`'
        case ('lammps-2024-coeff_restitution-force'); s = '`coeff_restitution` + `limit_damping`'
        case ('liggghts-hertz-overlap'); s = '`model hertz`'
        case ('liggghts-hertz-force'); s = '`model hertz`, `limitForce on`'
        case ('liggghts-hertz_stiffness-overlap', 'liggghts-hertz_stiffness-force'); s = '`model hertz/stiffness`'
        case ('mercurydpm-restitution-overlap'); s = '`setEffectiveElasticModulusAndRestitutionCoefficient`'
        case ('mercurydpm-dissipation-overlap'); s = '`setDissipation`'
        case ('mercurydpm2015-dissipation-overlap'); s = '`HertzianViscoelasticSpecies` `setDissipation`'
        case ('mercurydpm2015-stiffness_restitution-overlap'); s = '`setStiffnessAndRestitutionCoefficient`'
        case ('yade-en-force'); s = '`en`'
        case ('yade-betan-force'); s = '`betan` = beta(e)'
        case ('mfix-hertzian-overlap'); s = '`HERTZIAN`'
        case ('chrono-material-force'); s = 'Hertz, material properties'
        case ('chrono-kn_gn-force'); s = 'Hertz, `UseMaterialProperties(false)`'
        case default; s = id
        end select
    end function short_option

    !> A row's version, short.
    function short_version(row) result(s)
        integer, intent(in) :: row
        character(len=:), allocatable :: s
        character(len=:), allocatable :: id
        id = peer_spec_field(row, 'id')
        if (index(id, 'lammps-2021-') == 1) then
            s = '29 Sep 2021'
        else if (index(id, 'lammps-2023-') == 1) then
            s = '28 Mar 2023 - 29 Aug 2024'
        else if (index(id, 'lammps-current-') == 1) then
            s = 'current (07b704ca)'
        else if (index(id, 'lammps-2024-') == 1) then
            s = '27 Jun 2024 +'
        else if (index(id, 'liggghts') == 1) then
            s = '3.8.0'
        else if (index(id, 'mercurydpm2015') == 1) then
            s = 'Beta 2015'
        else if (index(id, 'mercurydpm') == 1) then
            s = 'trunk 2018-2024'
        else if (index(id, 'yade') == 1) then
            s = '2020-2022 trunk'
        else if (index(id, 'mfix') == 1) then
            s = '21.3.2'
        else if (index(id, 'chrono') == 1) then
            s = '9.0.1 - 2026'
        else
            s = ''
        end if
    end function short_version

    !> The markdown tables of doc/peers.md (the text form of `check --table`).
    subroutine check_table_lines(lines)
        type(peer_text), allocatable, intent(out) :: lines(:)
        integer :: row, j, st, law, iend, k
        real(wp) :: e
        character(len=:), allocatable :: s
        integer, parameter :: laws(2) = [HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO]
        integer, parameter :: ends(2) = [HD_END_OVERLAP, HD_END_FORCE]
        allocate (lines(0))
        s = ''
        call add('Restitution coefficient achieved when the user writes the target e into the engine''s ' // &
                 'restitution input (`hertzdamp check --table`):')
        call add('')
        call add('| engine | version | option | law | end | gamma | e for 0.1 | 0.3 | 0.5 | 0.7 | 0.9 |')
        call add('| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |')
        do row = 1, peer_spec_count
            if (.not. restitution_row(row)) cycle
            s = '| ' // peer_spec_field(row, 'engine') // ' | ' // short_version(row) // ' | ' // short_option(row) // &
                ' | ' // hertzdamp_law_name(peer_row_law(row)) // ' | ' // peer_spec_field(row, 'end') // ' | `' // &
                peer_spec_field(row, 'alpha_expr') // '` |'
            do j = 1, size(table_targets)
                call row_achieved(row, table_targets(j), e, st)
                s = s // ' ' // cell(e, st) // ' |'
            end do
            call add(s)
        end do
        call add('')
        call add('Speed dependence of the other laws: the engine''s coefficient is chosen to give the target ' // &
                 'e exactly at u0; e at other impact speeds u (alpha ~ u^(-1/5) for linear, u^(1/5) for ' // &
                 'kuwabara-kono):')
        call add('')
        call add('| law | end | used by | target e | u = u0/100 | u0/10 | u0 | 10 u0 | 100 u0 |')
        call add('| --- | --- | --- | --- | --- | --- | --- | --- | --- |')
        do k = 1, size(laws)
            law = laws(k)
            do iend = 1, size(ends)
                do j = 1, size(table_targets)
                    if (j == 1) then
                        s = '| ' // hertzdamp_law_name(law) // ' | ' // hertzdamp_end_name(ends(iend)) // ' | ' // &
                            used_by(law, ends(iend)) // ' | ' // fmt_short(table_targets(j), ROUND_TRIP) // ' |'
                    else
                        s = '| | | | ' // fmt_short(table_targets(j), ROUND_TRIP) // ' |'
                    end if
                    do row = 1, size(table_ratios)
                        call speed_achieved(law, ends(iend), table_targets(j), table_ratios(row), e, st)
                        s = s // ' ' // cell(e, st) // ' |'
                    end do
                    call add(s)
                end do
            end do
        end do
    contains
        subroutine add(line)
            character(len=*), intent(in) :: line
            lines = [lines, peer_text(line)]
        end subroutine add
    end subroutine check_table_lines

    !> The same tables as CSV or JSON rows.
    subroutine table_data(fmt, buf)
        integer, intent(in) :: fmt
        type(cli_buffer), intent(inout) :: buf
        type(out_table) :: t
        integer :: row, j, st, k, iend
        real(wp) :: e
        integer, parameter :: laws(2) = [HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO]
        integer, parameter :: ends(2) = [HD_END_OVERLAP, HD_END_FORCE]
        call t%set_columns('id,law,end,formula,target,speed_ratio,e,status')
        call t%meta('table', 'e achieved: restitution rows at their target; speed-dependent laws at u = ratio u0 ' // &
                    'with the coefficient exact at u0')
        do row = 1, peer_spec_count
            if (.not. restitution_row(row)) cycle
            do j = 1, size(table_targets)
                call row_achieved(row, table_targets(j), e, st)
                call put(peer_spec_field(row, 'id'), peer_row_law(row), peer_row_end(row), &
                         peer_spec_field(row, 'alpha_expr'), table_targets(j), 1.0_wp, e, st)
            end do
        end do
        do k = 1, size(laws)
            do iend = 1, size(ends)
                do j = 1, size(table_targets)
                    do row = 1, size(table_ratios)
                        call speed_achieved(laws(k), ends(iend), table_targets(j), table_ratios(row), e, st)
                        call put(hertzdamp_law_name(laws(k)) // '-' // hertzdamp_end_name(ends(iend)), laws(k), ends(iend), &
                                 'calibrated at u0', table_targets(j), table_ratios(row), e, st)
                    end do
                end do
            end do
        end do
        call t%render(fmt, buf)
    contains
        subroutine put(id, law, iend, formula, target, ratio, e, st)
            character(len=*), intent(in) :: id, formula
            integer, intent(in) :: law, iend, st
            real(wp), intent(in) :: target, ratio, e
            call t%str(id)
            call t%str(hertzdamp_law_name(law))
            call t%str(hertzdamp_end_name(iend))
            call t%str(formula)
            call t%num(target)
            call t%num(ratio)
            if (st == HD_OK .or. st == HD_NO_REBOUND) then
                call t%num(e)
            else
                call t%num(peer_nan())
            end if
            select case (st)
            case (HD_OK); call t%str('ok')
            case (HD_NO_REBOUND); call t%str('no-rebound')
            case default; call t%str('failed')
            end select
        end subroutine put
    end subroutine table_data

    ! ------------------------------------------------------------------ parsing helpers

    !> Append the blank-separated words of s (a quoted deck line is one argument).
    subroutine split_words(s, words)
        character(len=*), intent(in) :: s
        type(peer_text), allocatable, intent(inout) :: words(:)
        integer :: i, j
        i = 1
        do while (i <= len(s))
            if (s(i:i) == ' ' .or. s(i:i) == achar(9)) then
                i = i + 1
                cycle
            end if
            j = i
            do while (j <= len(s))
                if (s(j:j) == ' ' .or. s(j:j) == achar(9)) exit
                j = j + 1
            end do
            words = [words, peer_text(s(i:j - 1))]
            i = j
        end do
    end subroutine split_words

end module hertzdamp_cmd_check
