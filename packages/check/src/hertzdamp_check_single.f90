!> The report of one contact given in the engine's words on the command line (the
!> form of `hertzdamp check ENGINE WORDS...` since version 0.2): the header (engine,
!> version, formula, source, stiffness, target, achieved and corrected e, time step,
!> warnings and notes) and one row per impact speed with alpha, e, e_error, t_c,
!> t_attractive, dt_max, t_hertz, t_peer, corrected and method (doc/peers.md section 11).
!> Built as data (hertzdamp_check_report); the command-line program prints it.
module hertzdamp_check_single
    use hertzdamp, only: hertzdamp_rk, hertzdamp_message, hertzdamp_end_name, hertzdamp_law_name, &
                         hertzdamp_law_has_alpha_c, hertzdamp_law_alpha_c, hertzdamp_method_name, &
                         hertzdamp_fit_law_e_min, hertzdamp_alpha_max, HD_METHOD_RK45, HD_METHOD_FIT, &
                         HD_OK, HD_NO_REBOUND, HD_END_OVERLAP, HD_OUTSIDE_VALIDITY, HD_OUT_OF_RANGE, &
                         HD_BAD_RESTITUTION, HD_NOT_SUPPORTED, HD_DAMPING_TSUJI
    use hertzdamp_check_model, only: peer_deck, peer_point, peer_evaluate, peer_spec_field, peer_law_inverse, &
                                     peer_beta_inverse, peer_damping, PEER_LAMMPS, PEER_LIGGGHTS, TSTEP_NONE, &
                                     TSTEP_LIGGGHTS, TSTEP_MERCURY, TSTEP_MFIX
    use hertzdamp_check_common, only: peer_materials
    use hertzdamp_check_deck, only: peer_read_deck, peer_parameter_problem
    use hertzdamp_check_engines, only: check_engine, check_engine_of, peer_releases
    use hertzdamp_check_report, only: peer_report
    use hertzdamp_text_list, only: text_string, text_list
    use hertzdamp_text_parse, only: text_words
    use hertzdamp_text_format, only: itoa, fmt_short, ROUND_TRIP
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> What another release of the engine gives for the same contact words.
    type, public :: peer_release
        integer :: release = 0                        !! its index in the engine's releases
        character(len=:), allocatable :: refusal      !! why it refuses the words ('' when it reads them)
        type(peer_deck) :: deck                       !! the contact with its formulas
        type(peer_point) :: pt                        !! at the speed compared
    end type peer_release

    public :: peer_single_report, peer_has_result, peer_row_reason, pct, negligible, subst, law_message, end_text
    public :: numbered, peer_other_releases, release_word

contains

    !> Whether a point's status carries a result (ok, no-rebound).
    pure logical function peer_has_result(status)
        integer, intent(in) :: status   !! a library status
        peer_has_result = status == HD_OK .or. status == HD_NO_REBOUND
    end function peer_has_result

    !> The report of one contact evaluated at the speeds (pt from peer_evaluate at e_target
    !> et): columns velocity .. method (the program adds status); the header only when a
    !> row has a result.  The 'law' line is left empty for the program's law_text(deck%law).
    subroutine peer_single_report(deck, pt, et, have_e, steps, release, tokens, mat, t)
        type(peer_deck), intent(in) :: deck
        type(peer_point), intent(in) :: pt(:)
        real(wp), intent(in) :: et                  !! the target
        logical, intent(in) :: have_e               !! the target is --e (else the deck's restitution input)
        integer, intent(in) :: steps                !! --steps
        integer, intent(in) :: release              !! --release
        type(text_string), intent(in) :: tokens(:)    !! the deck's words (for the other releases)
        type(peer_materials), intent(in) :: mat
        type(peer_report), intent(out) :: t
        integer :: i, nfail, first_fail
        logical :: have
        call t%set_columns('velocity,alpha,e,e_error,t_c,t_attractive,dt_max,t_hertz,t_peer,corrected,method', &
                           'm/s,,,,s,s,s,s,s,,')
        nfail = 0
        first_fail = 0
        do i = 1, size(pt)
            if (peer_has_result(pt(i)%status)) cycle
            nfail = nfail + 1
            if (first_fail == 0) first_fail = i
        end do
        if (nfail < size(pt)) call single_header(deck, pt, et, have_e, steps, release, tokens, mat, nfail, first_fail, t)
        do i = 1, size(pt)
            have = peer_has_result(pt(i)%status)
            call t%num(pt(i)%u)
            call t%num_or_none(pt(i)%alpha, have)
            call t%num_or_none(pt(i)%e, have)
            call t%num_or_none(pt(i)%e_error, have)
            call t%num_or_none(pt(i)%tc, have)
            call t%num_or_none(pt(i)%t_force, have)
            call t%num_or_none(pt(i)%tc / steps, pt(i)%status == HD_OK)
            call t%num_or_none(pt(i)%t_hertz, have)
            call t%num_or_none(pt(i)%t_peer, have)
            call t%num_or_none(pt(i)%p_corrected, have .and. pt(i)%status_corrected == HD_OK)
            if (have .and. pt(i)%method > 0) then
                call t%str(hertzdamp_method_name(pt(i)%method))
            else
                call t%none()
            end if
            if (have) then
                call t%end_row(pt(i)%status, '')
            else
                call t%end_row(pt(i)%status, peer_row_reason(deck, pt(i)))
            end if
        end do
    end subroutine peer_single_report

    subroutine single_header(deck, pt, et, have_e, steps, release, tokens, mat, nfail, first_fail, t)
        type(peer_deck), intent(in) :: deck
        type(peer_point), intent(in) :: pt(:)
        real(wp), intent(in) :: et
        logical, intent(in) :: have_e
        integer, intent(in) :: steps, release, nfail, first_fail
        type(text_string), intent(in) :: tokens(:)
        type(peer_materials), intent(in) :: mat
        type(peer_report), intent(inout) :: t
        type(text_string), allocatable :: warn(:), note(:)
        type(check_engine) :: e
        character(len=:), allocatable :: s
        integer :: i
        allocate (warn(0), note(0))
        call t%meta('engine', trim(peer_spec_field(deck%row, 'engine')) // ': ' // peer_spec_field(deck%row, 'option'))
        if (len(peer_releases(deck%peer)) > 0 .and. len(deck%version) > 0) then
            call t%meta('version', deck%version // ' (--release ' // release_word(deck%peer, release) // '); ' // &
                        peer_spec_field(deck%row, 'version'))
        else
            call t%meta('version', peer_spec_field(deck%row, 'version'))
        end if
        call t%meta('deck', deck%deck_text)
        call t%meta('law', '')
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
        if (have_e) then
            call t%meta('target', 'e = ' // fmt_short(et, ROUND_TRIP) // ' (--e)')
        else
            call t%meta('target', 'e = ' // fmt_short(et, ROUND_TRIP) // ' (the ' // deck%p_name // ')')
        end if
        call t%meta('achieved', achieved_text(pt, et))
        call t%meta('corrected', corrected_text(deck, pt, et))
        call time_step_texts(deck, pt, steps, t)
        call t%meta('method', method_text(pt))
        call collect_warnings(deck, pt, warn)
        do i = 1, size(deck%notes)
            note = [note, deck%notes(i)]
        end do
        e = check_engine_of(deck%peer)
        if (e%release_notes) call release_notes(tokens, mat, deck, pt, et, note)
        if (nfail > 0) warn = [warn, text_string(itoa(nfail) // ' of ' // itoa(size(pt)) // &
                               ' speeds have no result; first: ' // peer_row_reason(deck, pt(first_fail)))]
        do i = 1, size(warn)
            call t%meta(numbered('warning', i, size(warn)), warn(i)%s)
        end do
        do i = 1, size(note)
            call t%meta(numbered('note', i, size(note)), note(i)%s)
        end do
        call t%meta('units', 'velocity [m/s]; t_c, t_attractive (overlap end: when the total force turns ' // &
                    'attractive), dt_max = t_c/' // itoa(steps) // ', t_hertz (elastic Hertz time), t_peer ' // &
                    '(the engine''s own estimate) [s]; e_error = e/e_target - 1; corrected: ' // deck%p_name // &
                    '; method: what gave e and t_c')
    end subroutine single_header

    !> Why a speed has no result: its --velocity, alpha and the status in words.
    function peer_row_reason(deck, pt) result(s)
        type(peer_deck), intent(in) :: deck
        type(peer_point), intent(in) :: pt
        character(len=:), allocatable :: s
        s = '--velocity ' // fmt_short(pt%u, ROUND_TRIP) // ': '
        if (ieee_is_finite(pt%alpha)) s = s // 'alpha = ' // fmt_short(pt%alpha, 6)
        if (pt%method == HD_METHOD_RK45) s = s // ' (' // hertzdamp_method_name(HD_METHOD_RK45) // &
                                             ': beyond the fitted range)'
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
    end function peer_row_reason

    !> Which method gave e and t_c: the library's fitted maps, its reference integrator
    !> beyond their range (the column method says it per speed).
    function method_text(pt) result(s)
        type(peer_point), intent(in) :: pt(:)
        character(len=:), allocatable :: s
        integer :: nfit, nrk
        nfit = count(pt%method == HD_METHOD_FIT)
        nrk = count(pt%method == HD_METHOD_RK45)
        s = ''
        if (nfit > 0) s = hertzdamp_method_name(HD_METHOD_FIT) // ' (the library''s fitted maps of the law ' // &
                          'and end) at ' // itoa(nfit) // ' of ' // itoa(size(pt)) // ' speeds'
        if (nrk > 0) then
            if (len(s) > 0) s = s // '; '
            s = s // hertzdamp_method_name(HD_METHOD_RK45) // ' (the reference integrator) at ' // itoa(nrk) // &
                ' of ' // itoa(size(pt)) // ' speeds, where alpha is beyond the fitted range'
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

    !> The --release word of a release of the engine ('' if it has no such release).
    function release_word(peer, release) result(s)
        integer, intent(in) :: peer      !! PEER_*
        integer, intent(in) :: release   !! the release's index among the engine's releases
        character(len=:), allocatable :: s
        type(text_list) :: words
        call text_words(peer_releases(peer), words)
        s = ''
        if (release >= 1 .and. release <= words%n) s = words%item(release)%s
    end function release_word

    !> A status in words, naming the law and end where the build lacks them.
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

    !> The contact end in words.
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
        integer :: ilo, ihi
        call extremes(pt%e, pt%status == HD_OK .or. pt%status == HD_NO_REBOUND, ilo, ihi)
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
        call extremes(pt%p_corrected, pt%status_corrected == HD_OK, ilo, ihi)
        if (ilo == 0) then
            ! the reason at the first speed with a result (there is one)
            i = 1
            do while (.not. peer_has_result(pt(i)%status))
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

    !> The first index of the smallest and of the largest x where mask holds (0 and 0
    !> where it holds nowhere).
    pure subroutine extremes(x, mask, ilo, ihi)
        real(wp), intent(in) :: x(:)
        logical, intent(in) :: mask(:)
        integer, intent(out) :: ilo, ihi
        ilo = 0
        ihi = 0
        if (.not. any(mask)) return
        ilo = minloc(x, 1, mask)
        ihi = maxloc(x, 1, mask)
    end subroutine extremes

    !> A template with v in place of {} (appended when there is none).
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
        type(peer_report), intent(inout) :: t
        character(len=:), allocatable :: s
        integer :: ib, ihi
        real(wp) :: dt_mfix, x
        call extremes(pt%tc, pt%status == HD_OK, ib, ihi)
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
        type(text_string), allocatable, intent(inout) :: warn(:)
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
            warn = [warn, text_string(s)]
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
            warn = [warn, text_string(s)]
        end if
    end subroutine collect_warnings

    !> What the engine's other releases give for the same contact words at speed u, where
    !> it differs from `deck`'s result `pt` (or where a release refuses the words): one
    !> entry per such release, oldest first.
    function peer_other_releases(tokens, mat, deck, pt, et) result(rs)
        type(text_string), intent(in) :: tokens(:)   !! the contact's words
        type(peer_materials), intent(in) :: mat      !! its bodies
        type(peer_deck), intent(in) :: deck          !! the contact with the chosen release
        type(peer_point), intent(in) :: pt           !! its result at the speed compared (one with a result)
        real(wp), intent(in) :: et                   !! the target
        type(peer_release), allocatable :: rs(:)
        type(peer_release) :: r
        type(text_list) :: words
        integer :: k, st
        allocate (rs(0))
        call text_words(peer_releases(deck%peer), words)
        do k = 1, words%n
            if (k == deck%release) cycle
            r%release = k
            call peer_read_deck(deck%peer, tokens, mat, k, r%deck, st, r%refusal)
            if (st == HD_OK) then
                if (r%deck%row == deck%row .and. r%deck%k == deck%k) cycle
                r%pt = peer_evaluate(r%deck, pt%u, et)
                if (r%pt%status /= HD_OK .and. r%pt%status /= HD_NO_REBOUND) cycle
                if (r%pt%status == pt%status) then
                    if (r%pt%status == HD_NO_REBOUND) cycle
                    if (abs(r%pt%e - pt%e) <= 1.0e-12_wp .and. abs(r%pt%tc - pt%tc) <= 1.0e-12_wp * pt%tc) cycle
                end if
            end if
            rs = [rs, r]
        end do
    end function peer_other_releases

    !> What the other releases give for the same deck, where it differs (the engines
    !> whose table row asks for it: LAMMPS).
    subroutine release_notes(tokens, mat, deck, pt, et, note)
        type(text_string), intent(in) :: tokens(:)
        type(peer_materials), intent(in) :: mat
        type(peer_deck), intent(in) :: deck
        type(peer_point), intent(in) :: pt(:)
        real(wp), intent(in) :: et
        type(text_string), allocatable, intent(inout) :: note(:)
        type(peer_release), allocatable :: rs(:)
        character(len=:), allocatable :: msg
        integer :: i, k
        ! at the first speed with a result (there is one)
        i = 1
        do while (.not. peer_has_result(pt(i)%status))
            i = i + 1
        end do
        rs = peer_other_releases(tokens, mat, deck, pt(i), et)
        do k = 1, size(rs)
            associate (other => rs(k)%deck, q => rs(k)%pt)
                if (len(rs(k)%refusal) > 0) then
                    note = [note, text_string(other%version // ': ' // rs(k)%refusal)]
                    cycle
                end if
                if (q%status == HD_NO_REBOUND) then
                    msg = ' gives no rebound'
                else
                    msg = ' gives e = ' // fmt_short(q%e, 6) // ', t_c = ' // fmt_short(q%tc, 6) // ' s'
                end if
                note = [note, text_string(other%version // msg // ' at u = ' // fmt_short(pt(i)%u, 6) // &
                                          ' m/s for this deck (' // peer_spec_field(other%row, 'alpha_expr') // &
                                          '; ' // other%k_text // ')')]
            end associate
        end do
    end subroutine release_notes


end module hertzdamp_check_single
