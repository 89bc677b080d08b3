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
                         HD_OK, HD_NO_REBOUND, HD_END_OVERLAP, HD_END_FORCE, HD_OUTSIDE_VALIDITY, &
                         HD_BAD_RESTITUTION, HD_NOT_SUPPORTED, HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, &
                         HD_DAMPING_KUWABARA_KONO
    use hertzdamp_peers, only: peer_deck, peer_point, peer_text, peer_evaluate, peer_spec_field, peer_spec_count, &
                               peer_law_inverse, peer_law_forward, peer_beta, peer_beta_inverse, &
                               peer_damping, peer_fmt, peer_itoa, peer_row_law, peer_row_end, peer_row_coef, &
                               peer_nan, peer_float, peer_name, &
                               PEER_LAMMPS, PEER_LIGGGHTS, PEER_MERCURYDPM, PEER_YADE, PEER_MFIX, PEER_CHRONO, &
                               TSTEP_LIGGGHTS, TSTEP_MERCURY, TSTEP_MFIX, COEF_GAMMA_P6, COEF_GAMMA_SQRT2_P6, &
                               COEF_GAMMA_SQRT5_BETA, COEF_GAMMA_2BETA, COEF_GAMMA_SQRT6, COEF_GAMMA_SQRT5_BETA_EPS
    use hertzdamp_peers_deck, only: peer_materials, peer_read_deck, peer_code, peer_parameter_problem, &
                                    LAMMPS_2021, LAMMPS_2023, LAMMPS_CURRENT, lammps_releases
    use hertzdamp_cli, only: cli_buffer, parse_real, parse_int, parse_choice, fail, quit, EXIT_USAGE, EXIT_OK, &
                             exit_code_of, get_arg, parse_sweep
    use hertzdamp_cli_output, only: out_table, format_choices, FORMAT_TEXT
    use hertzdamp_cli_help, only: print_help, wants_help
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private
    public :: cmd_check, check_table_lines

    integer, parameter :: wp = hertzdamp_rk

    !> Targets of the documentation table.
    real(wp), parameter :: table_targets(5) = [0.1_wp, 0.3_wp, 0.5_wp, 0.7_wp, 0.9_wp]
    !> Speed ratios u/u0 of the speed-dependence table.
    real(wp), parameter :: table_ratios(5) = [0.01_wp, 0.1_wp, 1.0_wp, 10.0_wp, 100.0_wp]

contains

    subroutine cmd_check()
        character(len=:), allocatable :: a, key, val, peer_name, release_text
        type(peer_text), allocatable :: tokens(:), opts_seen(:)
        type(peer_materials) :: mat
        real(wp), allocatable :: speeds(:)
        real(wp) :: e_user
        logical :: table, have_e, have_v, have_val
        integer :: i, n, j, steps, fmt, release, peer
        if (wants_help()) then
            call print_help('check')
            call quit(EXIT_OK)
        end if
        allocate (tokens(0), opts_seen(0), speeds(0))
        table = .false.
        have_e = .false.
        have_v = .false.
        e_user = 0.0_wp
        steps = 10
        fmt = FORMAT_TEXT
        release = LAMMPS_CURRENT
        release_text = ''
        peer_name = ''
        n = command_argument_count()
        i = 2
        do while (i <= n)
            a = get_arg(i)
            i = i + 1
            if (len(a) >= 2) then
                if (a(1:2) == '--') then
                    j = index(a, '=')
                    have_val = j > 0
                    if (have_val) then
                        key = a(1:j - 1)
                        val = a(j + 1:)
                    else
                        key = a
                        val = ''
                    end if
                    do j = 1, size(opts_seen)
                        if (opts_seen(j)%s == key) call fail(EXIT_USAGE, 'option ' // key // ' given more than once')
                    end do
                    opts_seen = [opts_seen, peer_text(key)]
                    select case (key)
                    case ('--table', '--wall')
                        if (have_val) call fail(EXIT_USAGE, 'option ' // key // ' takes no value')
                        if (key == '--table') table = .true.
                        if (key == '--wall') mat%wall = .true.
                        cycle
                    case ('--radius', '--radius2', '--density', '--density2', '--velocity', '--e', '--steps', &
                          '--release', '--format')
                        if (.not. have_val) then
                            if (i > n) call fail(EXIT_USAGE, 'option ' // key // ' needs a value')
                            val = get_arg(i)
                            i = i + 1
                        end if
                    case default
                        call fail(EXIT_USAGE, 'unknown option ' // key // ' (see hertzdamp check --help)')
                    end select
                    select case (key)
                    case ('--radius'); mat%radius(1) = positive(val, key)
                    case ('--radius2'); mat%radius(2) = positive(val, key)
                    case ('--density'); mat%density(1) = positive(val, key)
                    case ('--density2'); mat%density(2) = positive(val, key)
                    case ('--velocity')
                        speeds = parse_speeds(val)
                        have_v = .true.
                    case ('--e')
                        e_user = parse_real(val, '--e')
                        if (.not. (e_user > 0.0_wp .and. e_user <= 1.0_wp)) then
                            call fail(EXIT_USAGE, '--e ' // val // ': the target restitution must be in (0, 1]')
                        end if
                        have_e = .true.
                    case ('--steps')
                        steps = parse_int(val, '--steps')
                        if (steps < 1) call fail(EXIT_USAGE, '--steps must be >= 1')
                    case ('--release')
                        release = parse_choice(val, lammps_releases, 'LAMMPS release (--release)')
                        release_text = val
                    case ('--format')
                        fmt = parse_choice(val, format_choices, 'format (--format)')
                    case default
                    end select
                    cycle
                end if
            end if
            if (len(peer_name) == 0) then
                peer_name = a
            else
                call split_words(a, tokens)
            end if
        end do
        if (table) then
            if (len(peer_name) > 0 .or. size(opts_seen) > 1 + merge(1, 0, any_key(opts_seen, '--format'))) then
                call fail(EXIT_USAGE, '--table takes no engine and no option but --format')
            end if
            call print_table(fmt)
            call quit(EXIT_OK)
        end if
        if (len(peer_name) == 0) call fail(EXIT_USAGE, 'missing the engine: lammps, liggghts, mercurydpm, yade, ' // &
                                           'mfix or chrono (see hertzdamp check --help)')
        peer = peer_code(peer_name)
        if (peer == 0) call fail(EXIT_USAGE, 'unknown engine "' // peer_name // &
                                 '": choose lammps, liggghts, mercurydpm, yade, mfix or chrono')
        if (len(release_text) > 0 .and. peer /= PEER_LAMMPS) call fail(EXIT_USAGE, '--release applies to lammps only')
        if (.not. have_v) call fail(EXIT_USAGE, 'missing --velocity (impact speeds [m/s]: a list 0.1,1,5 or a range ' // &
                                    '0.01:5:log20)')
        call run_check(peer, tokens, mat, release, speeds, have_e, e_user, steps, fmt)
    end subroutine cmd_check

    logical function any_key(list, key)
        type(peer_text), intent(in) :: list(:)
        character(len=*), intent(in) :: key
        integer :: i
        any_key = .false.
        do i = 1, size(list)
            if (list(i)%s == key) any_key = .true.
        end do
    end function any_key

    ! ------------------------------------------------------------------ one deck

    subroutine run_check(peer, tokens, mat, release, speeds, have_e, e_user, steps, fmt)
        integer, intent(in) :: peer, release, steps, fmt
        type(peer_text), intent(in) :: tokens(:)
        type(peer_materials), intent(in) :: mat
        real(wp), intent(in) :: speeds(:), e_user
        logical, intent(in) :: have_e
        type(peer_deck) :: deck
        type(peer_point), allocatable :: pt(:)
        type(out_table) :: t
        type(cli_buffer) :: buf
        type(peer_text), allocatable :: warn(:), note(:)
        character(len=:), allocatable :: msg, s
        real(wp) :: et
        integer :: status, i, ngood, nfail, first_fail
        call peer_read_deck(peer, tokens, mat, release, deck, status, msg)
        if (status /= HD_OK) call fail(EXIT_USAGE, peer_name(peer) // ': ' // msg)
        if (have_e) then
            et = e_user
        else if (deck%e_deck > 0.0_wp) then
            et = deck%e_deck
        else
            call fail(EXIT_USAGE, 'missing --e (the restitution coefficient you want: this ' // peer_name(peer) // &
                      ' deck sets ' // deck%p_name // ', not e)')
        end if
        allocate (pt(size(speeds)))
        ngood = 0
        nfail = 0
        first_fail = 0
        do i = 1, size(speeds)
            pt(i) = peer_evaluate(deck, speeds(i), et)
            if (pt(i)%status == HD_OK .or. pt(i)%status == HD_NO_REBOUND) then
                ngood = ngood + 1
            else
                nfail = nfail + 1
                if (first_fail == 0) first_fail = i
            end if
        end do
        if (ngood == 0) call fail(exit_code_of(pt(first_fail)%status), 'u = ' // peer_fmt(speeds(first_fail)) // &
                                  ': ' // law_message(deck, pt(first_fail)%status))
        allocate (warn(0), note(0))
        call t%set_columns('velocity,alpha,e,e_error,t_c,t_attractive,dt_max,t_hertz,t_peer,corrected,status')
        call t%meta('engine', trim(peer_spec_field(deck%row, 'engine')) // ': ' // peer_spec_field(deck%row, 'option'))
        if (peer == PEER_LAMMPS) then
            call t%meta('version', deck%version // ' (--release ' // release_word(release) // '); ' // &
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
        call t%meta('stiffness', deck%k_text // ': k = ' // peer_fmt(deck%k, 6) // ' N m^-3/2')
        s = 'm = ' // peer_fmt(deck%m, 6) // ' kg, R = ' // peer_fmt(deck%radius, 6) // ' m'
        if (deck%wall) then
            s = s // ' (particle against a flat wall)'
        else
            s = s // ' (effective mass and radius of the pair)'
        end if
        call t%meta('contact', s)
        if (have_e) then
            call t%meta('target', 'e = ' // peer_fmt(et) // ' (--e)')
        else
            call t%meta('target', 'e = ' // peer_fmt(et) // ' (the ' // deck%p_name // ')')
        end if
        call t%meta('achieved', achieved_text(pt, et))
        call t%meta('corrected', corrected_text(deck, pt, et))
        call time_step_texts(deck, pt, steps, t)
        call collect_warnings(deck, pt, warn)
        do i = 1, size(deck%notes)
            note = [note, deck%notes(i)]
        end do
        if (peer == PEER_LAMMPS) call release_notes(tokens, mat, release, deck, pt, et, note)
        if (nfail > 0) warn = [warn, peer_text(peer_itoa(nfail) // ' of ' // peer_itoa(size(pt)) // &
                               ' speeds have no result: ' // law_message(deck, pt(first_fail)%status))]
        do i = 1, size(warn)
            call t%meta(numbered('warning', i, size(warn)), warn(i)%s)
        end do
        do i = 1, size(note)
            call t%meta(numbered('note', i, size(note)), note(i)%s)
        end do
        call t%meta('units', 'velocity [m/s]; t_c, t_attractive (overlap end: when the total force turns ' // &
                    'attractive), dt_max = t_c/' // peer_itoa(steps) // ', t_hertz (elastic Hertz time), t_peer ' // &
                    '(the engine''s own estimate) [s]; e_error = e/e_target - 1; corrected: ' // deck%p_name)
        do i = 1, size(pt)
            call t%num(pt(i)%u)
            call t%num(pt(i)%alpha)
            call t%num(pt(i)%e)
            call t%num(pt(i)%e / et - 1.0_wp)
            call t%num(pt(i)%tc)
            call t%num(pt(i)%t_force)
            if (pt(i)%status == HD_OK) then
                call t%num(pt(i)%tc / steps)
            else
                call t%num(peer_nan())
            end if
            call t%num(pt(i)%t_hertz)
            call t%num(pt(i)%t_peer)
            call t%num(pt(i)%p_corrected)
            select case (pt(i)%status)
            case (HD_OK); call t%str('ok')
            case (HD_NO_REBOUND); call t%str('no-rebound')
            case default; call t%str('failed')
            end select
        end do
        call t%render(fmt, buf)
        call buf%flush_to_stdout()
        call quit(merge(EXIT_OK, exit_code_of(pt(max(first_fail, 1))%status), nfail == 0))
    end subroutine run_check

    !> 'warning', or 'warning 2' ... when there are several.
    function numbered(word, i, n) result(s)
        character(len=*), intent(in) :: word
        integer, intent(in) :: i, n
        character(len=:), allocatable :: s
        s = word
        if (n > 1) s = word // ' ' // peer_itoa(i)
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

    function law_text(law) result(s)
        integer, intent(in) :: law
        character(len=:), allocatable :: s
        select case (law)
        case (HD_DAMPING_LINEAR)
            s = 'linear: damping force d zeta'' (q = 0); alpha = d t*/m falls with speed as u^(-1/5)'
        case (HD_DAMPING_TSUJI)
            s = 'tsuji: damping force d zeta^(1/4) zeta'' (q = 1/4) with d = gamma sqrt(m k); alpha = gamma, ' // &
                'the same at every speed'
        case default
            s = 'kuwabara-kono: damping force d zeta^(1/2) zeta'' (q = 1/2); alpha = d t* (u t*)^(1/2)/m rises ' // &
                'with speed as u^(1/5)'
        end select
    end function law_text

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
            s = s // ' = ' // peer_fmt(peer_damping(deck, deck%p), 10) // ' (alpha = gamma)'
        else
            s = 'alpha = ' // peer_spec_field(deck%row, 'alpha_expr') // ' with tstar = (m/(k sqrt(u)))^(2/5)'
        end if
        s = s // '; ' // trim(deck%p_name) // ' = ' // peer_fmt(deck%p)
    end function formula_text

    !> e over the speeds against the target.
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
            s = 'e = ' // peer_fmt(pt(ilo)%e, 6) // ' at every speed (' // pct(pt(ilo)%e / et - 1.0_wp) // &
                ' against the target ' // peer_fmt(et) // ')'
        else
            s = 'e from ' // peer_fmt(pt(ilo)%e, 6) // ' (u = ' // peer_fmt(pt(ilo)%u, 6) // ' m/s, ' // &
                pct(pt(ilo)%e / et - 1.0_wp) // ') to ' // peer_fmt(pt(ihi)%e, 6) // ' (u = ' // &
                peer_fmt(pt(ihi)%u, 6) // ' m/s, ' // pct(pt(ihi)%e / et - 1.0_wp) // '); target ' // peer_fmt(et)
        end if
    end function achieved_text

    !> A relative error as a signed percentage.
    function pct(x, unsigned) result(s)
        real(wp), intent(in) :: x
        logical, intent(in), optional :: unsigned   !! no + sign
        character(len=:), allocatable :: s
        character(len=24) :: b
        if (abs(x) < 5.0e-7_wp) then
            s = 'exact to 1e-6'
        else
            write (b, '(sp,f16.2)') 100.0_wp * x
            if (abs(100.0_wp * x) < 0.005_wp) write (b, '(sp,es9.2)') 100.0_wp * x
            s = trim(adjustl(b)) // ' %'
            if (present(unsigned)) then
                if (unsigned .and. s(1:1) == '+') s = s(2:)
            end if
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
            s = 'no value of ' // deck%p_name // ' gives e = ' // peer_fmt(et) // ': '
            select case (pt(1)%status_corrected)
            case (HD_OUTSIDE_VALIDITY)
                s = s // 'the engine''s formula cannot produce alpha = ' // peer_fmt(pt(1)%alpha_target, 6)
            case (HD_BAD_RESTITUTION)
                s = s // 'the target is outside the inverse''s range (e >= 1e-3 overlap, 1e-4 force)'
            case default
                s = s // law_message(deck, pt(1)%status_corrected)
            end select
            return
        end if
        lo = pt(ilo)%p_corrected
        hi = pt(ihi)%p_corrected
        if (deck%law == HD_DAMPING_TSUJI) then
            s = subst(deck%p_template, peer_fmt(lo, 12)) // ' gives e = ' // peer_fmt(et) // ' (alpha = ' // &
                peer_fmt(pt(ilo)%alpha_target, 10) // ')'
            problem = peer_parameter_problem(deck, lo)
            if (len(problem) > 0) s = s // '; but ' // problem
        else
            if (ilo == ihi) then
                s = subst(deck%p_template, peer_fmt(lo, 12)) // ' gives e = ' // peer_fmt(et) // ' at u = ' // &
                    peer_fmt(pt(ilo)%u, 6) // ' m/s only (alpha depends on u)'
            else
                s = 'no single value of ' // deck%p_name // ' gives e = ' // peer_fmt(et) // ' at every speed ' // &
                    '(alpha depends on u); per speed in the column corrected, from ' // peer_fmt(lo, 6) // &
                    ' (u = ' // peer_fmt(pt(ilo)%u, 6) // ' m/s) to ' // peer_fmt(hi, 6) // ' (u = ' // &
                    peer_fmt(pt(ihi)%u, 6) // ' m/s): ' // subst(deck%p_template, peer_fmt(lo, 12)) // ' ... ' // &
                    subst(deck%p_template, peer_fmt(hi, 12))
            end if
            if (deck%peer == PEER_LAMMPS) then
                ! the zeta^(1/4) law is speed-independent: coeff_restitution with the e that gives the target
                call peer_law_inverse(HD_DAMPING_TSUJI, et, deck%iend, alpha, st)
                if (st == HD_OK .and. alpha < sqrt(5.0_wp)) then
                    ealt = peer_beta_inverse(alpha / sqrt(5.0_wp))
                    s = s // '. Speed-independent instead (LAMMPS 27 Jun 2024 and later): damping coeff_restitution ' // &
                        'with e = ' // peer_fmt(ealt, 12)
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
        real(wp) :: dt_mfix
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
        s = peer_itoa(steps) // ' steps per contact need dt <= ' // peer_fmt(pt(ib)%tc / steps, 6) // ' s (u = ' // &
            peer_fmt(pt(ib)%u, 6) // ' m/s gives the shortest contact, t_c = ' // peer_fmt(pt(ib)%tc, 6) // &
            ' s); the elastic Hertz time there is ' // peer_fmt(pt(ib)%t_hertz, 6) // ' s, so the contact lasts ' // &
            pct(abs(pt(ib)%tc / pt(ib)%t_hertz - 1.0_wp), unsigned=.true.)
        if (pt(ib)%tc >= pt(ib)%t_hertz) then
            s = s // ' longer than the elastic estimate'
        else
            s = s // ' shorter than the elastic estimate'
        end if
        call t%meta('time step', s)
        select case (deck%tstep)
        case (TSTEP_LIGGGHTS)
            s = 'LIGGGHTS fix check/timestep/gran estimates 2.87 (m_p^2/(r/2 Y*^2 v))^(1/5) = ' // &
                peer_fmt(pt(ib)%t_peer, 6) // ' s at v = ' // trim(merge('2u', 'u ', deck%wall)) // &
                ' (whole particle mass m_p, r/2): ' // pct(pt(ib)%t_peer / pt(ib)%tc - 1.0_wp) // ' against t_c'
        case (TSTEP_MERCURY)
            s = 'MercuryDPM getCollisionTime(2r, rho, u) = 2.214 (rho^2/(E^2 u))^(1/5) 2r = ' // &
                peer_fmt(pt(ib)%t_peer, 6) // ' s (elastic, identical spheres): ' // &
                pct(pt(ib)%t_peer / pt(ib)%tc - 1.0_wp) // ' against t_c'
        case (TSTEP_MFIX)
            if (ieee_is_finite(pt(ib)%t_peer)) then
                dt_mfix = pt(ib)%t_peer / deck%dt_factor
                s = 'MFiX sets DTSOLID = TCOLL/DTSOLID_FACTOR with TCOLL = pi/sqrt(k/m - (eta/m)^2/4) = ' // &
                    peer_fmt(pt(ib)%t_peer, 6) // ' s (a linear-spring period with the Hertz k and eta: the ' // &
                    'units do not match); DTSOLID = ' // peer_fmt(dt_mfix, 6) // ' s gives ' // &
                    peer_fmt(pt(ib)%tc / dt_mfix, 4) // ' steps per contact at u = ' // peer_fmt(pt(ib)%u, 6) // ' m/s'
            else
                s = 'MFiX TCOLL = pi/sqrt(k/m - (eta/m)^2/4) is not defined for this deck (zero or negative radicand): ' // &
                    'MFiX''s DTSOLID would be NaN'
            end if
        case default
            s = 'the engine has no contact-time estimate of its own (doc/peers.md)'
        end select
        call t%meta('engine time step', s)
    end subroutine time_step_texts

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
            s = 'no rebound at ' // peer_itoa(nno) // ' of ' // peer_itoa(size(pt)) // ' speeds (up to u = ' // &
                peer_fmt(umax, 6) // ' m/s): the overlap never returns to zero'
            if (hertzdamp_law_has_alpha_c(deck%law) .and. deck%iend == HD_END_OVERLAP) then
                ac = hertzdamp_law_alpha_c(deck%law)
                s = s // ' (alpha >= alpha_c = ' // peer_fmt(ac, 6) // ')'
            end if
            warn = [warn, peer_text(s)]
        end if
        if (iworst > 0) then
            s = 'the total force turns attractive before the particles separate: for the last ' // &
                peer_fmt(100.0_wp * worst, 3) // ' % of the contact (u = ' // peer_fmt(pt(iworst)%u, 6) // &
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
        i = 1
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
            note = [note, peer_text(other%version // ' gives e = ' // peer_fmt(q%e, 6) // ', t_c = ' // &
                                    peer_fmt(q%tc, 6) // ' s at u = ' // peer_fmt(pt(i)%u, 6) // &
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
                            used_by(law, ends(iend)) // ' | ' // peer_fmt(table_targets(j)) // ' |'
                    else
                        s = '| | | | ' // peer_fmt(table_targets(j)) // ' |'
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

    real(wp) function positive(text, what) result(x)
        character(len=*), intent(in) :: text, what
        x = parse_real(text, what)
        if (.not. x > 0.0_wp) call fail(EXIT_USAGE, what // ' ' // text // ': must be positive')
    end function positive

    !> Impact speeds: a sweep (numbers, A0:A1:N, A0:A1:logN), each positive.
    function parse_speeds(text) result(u)
        character(len=*), intent(in) :: text
        real(wp), allocatable :: u(:)
        integer :: i
        u = parse_sweep(text, '--velocity')
        do i = 1, size(u)
            if (.not. u(i) > 0.0_wp) call fail(EXIT_USAGE, '--velocity ' // peer_fmt(u(i)) // &
                                               ': impact speeds must be positive')
        end do
    end function parse_speeds

end module hertzdamp_cmd_check
