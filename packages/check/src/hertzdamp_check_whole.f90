!> `hertzdamp check ENGINE FILE...`: a whole deck, evaluated contact by contact
!> (doc/peers.md section 11).  The engine's deck reader gives the contacts (every type
!> pair and every type against every wall), the time step and the integrator; each
!> contact is resolved by the engine's contact reader (hertzdamp_check_deck) and
!> evaluated at every impact speed:
!>
!> - e_target: the restitution coefficient the deck asks for (its restitution input; for
!>   Yade's en with vn, the Mueller-Poeschel e at each speed), or --e; empty where neither
!>   says;
!> - e_model, t_c: the continuous model with the deck's k and d (hertzdamp_check_model);
!> - e_host, e_spread: the mean and the standard deviation over the onset phase of the
!>   restitution coefficient the engine's own integrator gives at the deck's time step
!>   (hertzdamp_host: h = dt/t*); empty, with a note, where the integrator is not modeled;
!> - steps_per_contact = t_c/dt and the time-step verdict (dt_verdict);
!> - corrected: the engine's parameter that makes e_host (e_model where the integrator
!>   is not modeled) equal the target.
module hertzdamp_check_whole
    use hertzdamp, only: hertzdamp_rk, hertzdamp_message, hertzdamp_law_name, hertzdamp_end_name, hertzdamp_law_q, &
                         HD_OK, HD_NO_REBOUND, HD_BAD_ARGUMENT, HD_DAMPING_TSUJI, hertzdamp_host_mean, &
                         hertzdamp_host_alpha_for_e, hertzdamp_host_stats, hertzdamp_host_name, HD_HOST_NONE
    use hertzdamp_check_model, only: peer_deck, peer_point, peer_evaluate, peer_parameter, peer_time_estimate, &
                                     peer_spec_field, peer_pade_mp, peer_pade_mp_inverse, TSTEP_MFIX, COEF_D_YADE_VN
    use hertzdamp_check_deck, only: peer_read_deck, peer_parameter_problem
    use hertzdamp_check_engines, only: check_engine, check_engine_of
    use hertzdamp_check_scene, only: peer_scene, peer_contact
    use hertzdamp_check_report, only: peer_report
    use hertzdamp_check_single, only: peer_has_result, peer_row_reason, numbered, peer_release, peer_other_releases, &
                                      release_word
    use hertzdamp_text_list, only: text_string, text_list
    use hertzdamp_text_map, only: text_map
    use hertzdamp_text_format, only: itoa, fmt_short, ROUND_TRIP, lower
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> The time-step verdicts.
    character(len=*), parameter, public :: verdict_text = &
        'ok: the integrator changes e by at most 1 % of e_model and e_spread is at most 1 % of it; ' // &
        'coarse: more (the corrected coefficient makes the mean e_host equal the target); unresolved: fewer ' // &
        'than 3 steps per contact or no rebound; unchecked: no e_host (the integrator is not modeled, or the ' // &
        'header says why)'

    !> What the caller asks.
    type, public :: peer_check_options
        integer :: release = 3                   !! LAMMPS_* or YADE_* (3: current)
        real(wp), allocatable :: speeds(:)       !! impact speeds in the deck's velocity unit
        logical :: have_e = .false.              !! --e given
        real(wp) :: e_user = 0.0_wp              !! --e
    end type peer_check_options

    !> One row.
    type :: check_row
        real(wp) :: e_target = 0.0_wp, e_model = 0.0_wp, e_host = 0.0_wp, e_spread = 0.0_wp
        real(wp) :: steps = 0.0_wp, t_c = 0.0_wp, corrected = 0.0_wp
        logical :: have_target = .false., have_host = .false., have_steps = .false., have_corrected = .false.
        character(len=:), allocatable :: verdict
        character(len=:), allocatable :: why   !! why there is no corrected value ('' when none is asked or there is one)
        character(len=:), allocatable :: host_why  !! why there is no e_host though the integrator is modeled ('')
    end type check_row

    public :: peer_read_scene, peer_check_scene, peer_units, peer_units_si

contains

    !> A deck's unit of velocity (which = 1) or time (which = 2) for the header, from its
    !> unit system (LAMMPS's units command, MFiX's UNITS): '' for lj and unknown ones.
    pure function peer_units(system, which) result(u)
        character(len=*), intent(in) :: system
        integer, intent(in) :: which
        character(len=:), allocatable :: u
        character(len=*), parameter :: names(4) = [character(len=5) :: 'si', 'cgs', 'micro', 'nano']
        character(len=*), parameter :: vel(4) = [character(len=8) :: 'm/s', 'cm/s', 'um/us', 'nm/ns']
        character(len=*), parameter :: time(4) = [character(len=2) :: 's', 's', 'us', 'ns']
        integer :: i
        u = ''
        do i = 1, size(names)
            if (lower(system) /= trim(names(i))) cycle
            if (which == 1) u = trim(vel(i))
            if (which == 2) u = trim(time(i))
        end do
    end function peer_units

    !> True when the deck's numbers are SI (its speeds compare with hertzdamp's plausible ranges).
    pure logical function peer_units_si(system)
        character(len=*), intent(in) :: system
        peer_units_si = lower(system) == 'si'
    end function peer_units_si

    !> Read an engine's deck files into a scene (msg: a file that cannot be read, or an
    !> engine whose decks are programs: MercuryDPM, Chrono).
    subroutine peer_read_scene(peer, paths, scene, msg)
        integer, intent(in) :: peer                      !! PEER_*
        type(text_string), intent(in) :: paths(:)        !! the deck's files, in order
        type(peer_scene), intent(out) :: scene
        character(len=:), allocatable, intent(out) :: msg
        type(check_engine) :: e
        e = check_engine_of(peer)
        call e%read_deck(paths, scene, msg)
    end subroutine peer_read_scene

    !> Resolve and evaluate every contact of the scene at the speeds: the report (columns
    !> pair .. corrected; the program adds status).  status HD_BAD_ARGUMENT with msg when
    !> no contact can be checked.
    subroutine peer_check_scene(scene, opt, rep, status, msg)
        type(peer_scene), intent(inout) :: scene
        type(peer_check_options), intent(in) :: opt
        type(peer_report), intent(out) :: rep
        integer, intent(out) :: status
        character(len=:), allocatable, intent(out) :: msg
        type(peer_deck), allocatable :: decks(:)
        logical, allocatable :: ok(:)
        type(text_list) :: refused, host_notes
        integer :: i, nok
        msg = ''
        allocate (decks(scene%ncontacts), ok(scene%ncontacts))
        call rep%set_columns('pair,velocity,e_target,e_model,e_host,e_spread,steps_per_contact,t_c,dt_verdict,corrected', &
                             ',' // peer_units(scene%units, 1) // ',,,,,,' // peer_units(scene%units, 2) // ',,')
        call resolve_contacts(scene, opt, decks, ok)
        nok = count(ok)
        if (nok == 0) then
            status = HD_BAD_ARGUMENT
            msg = 'no contact of the deck can be checked'
            if (scene%skipped%n > 0) msg = msg // '; first: ' // scene%skipped%item(1)%s
            if (scene%notes%n > 0) msg = msg // '; first note: ' // scene%notes%item(1)%s
            return
        end if
        status = HD_OK
        if (scene%dt_from_tcoll) call mfix_dtsolid(scene, decks, ok)
        call header(scene, opt, decks, ok, rep)
        do i = 1, scene%ncontacts
            if (ok(i)) call contact_rows(scene, scene%contacts(i), decks(i), opt, rep, refused, host_notes)
        end do
        do i = 1, host_notes%n
            call rep%meta(numbered('e_host', i, host_notes%n), host_notes%item(i)%s)
        end do
        do i = 1, refused%n
            call rep%meta(numbered('corrected', i, refused%n), refused%item(i)%s)
        end do
    end subroutine peer_check_scene

    !> The contact reader on every contact; what fails is noted with file:line.
    subroutine resolve_contacts(scene, opt, decks, ok)
        type(peer_scene), intent(inout) :: scene
        type(peer_check_options), intent(in) :: opt
        type(peer_deck), intent(inout) :: decks(:)
        logical, intent(out) :: ok(:)
        character(len=:), allocatable :: msg
        integer :: i, st
        do i = 1, scene%ncontacts
            associate (c => scene%contacts(i))
                ok(i) = len(c%problem) == 0
                if (.not. ok(i)) then
                    call scene%skipped%push(c%where // ': contact ' // c%pair // ': ' // c%problem)
                    cycle
                end if
                call peer_read_deck(scene%peer, c%words, c%mat, opt%release, decks(i), st, msg)
                ok(i) = st == HD_OK
                if (.not. ok(i)) call scene%skipped%push(c%where // ': contact ' // c%pair // ': ' // msg)
            end associate
        end do
    end subroutine resolve_contacts

    !> MFiX: DTSOLID = min over the particle pairs of TCOLL / DTSOLID_FACTOR
    !> (check_solids_dem.f; wall contacts do not take part).
    subroutine mfix_dtsolid(scene, decks, ok)
        type(peer_scene), intent(inout) :: scene
        type(peer_deck), intent(in) :: decks(:)
        logical, intent(in) :: ok(:)
        real(wp) :: tcoll, t
        integer :: i
        tcoll = huge(1.0_wp)
        do i = 1, size(decks)
            if (.not. ok(i) .or. decks(i)%wall .or. decks(i)%tstep /= TSTEP_MFIX) cycle
            t = peer_time_estimate(decks(i), 1.0_wp)
            if (ieee_is_finite(t)) tcoll = min(tcoll, t)
        end do
        if (tcoll < huge(1.0_wp)) then
            scene%dt = tcoll / scene%dt_factor
            scene%dt_text = 'DTSOLID = TCOLL/DTSOLID_FACTOR = ' // fmt_short(tcoll, 6) // '/' // &
                            fmt_short(scene%dt_factor, ROUND_TRIP) // ' (check_solids_dem.f: TCOLL = pi/sqrt(k/m - ' // &
                            '(eta/m)^2/4), the smallest over the particle pairs; walls do not take part)'
            if (scene%dt_max > 0.0_wp .and. scene%dt_max < scene%dt) call scene%note('', 'DT = ' // &
                fmt_short(scene%dt_max, ROUND_TRIP) // ' is below DTSOLID: a fluid-coupled MFiX run steps the ' // &
                'particles with DT (des_time_march.f); the rows use DTSOLID')
        else
            scene%dt = 0.0_wp
            scene%dt_text = 'none: MFiX''s TCOLL is not defined for these pairs (negative radicand)'
        end if
    end subroutine mfix_dtsolid

    !> The header: engine, files, units, time step, integrator, every contact, the notes.
    subroutine header(scene, opt, decks, ok, rep)
        type(peer_scene), intent(in) :: scene
        type(peer_check_options), intent(in) :: opt
        type(peer_deck), intent(in) :: decks(:)
        logical, intent(in) :: ok(:)
        type(peer_report), intent(inout) :: rep
        character(len=:), allocatable :: s
        type(check_engine) :: e
        integer :: i
        e = check_engine_of(scene%peer)
        s = e%title
        if (len(e%releases) > 0) then
            do i = 1, size(decks)
                if (ok(i)) exit
            end do
            s = s // ', ' // decks(i)%version
        end if
        call rep%meta('engine', s)
        s = ''
        do i = 1, scene%files%n
            if (i > 1) s = s // ', '
            s = s // scene%files%item(i)%s
        end do
        call rep%meta('deck', s)
        call rep%meta('units', 'the deck''s own (' // scene%units // '): velocity, t_c and the time step in its ' // &
                      'velocity and time units')
        if (scene%dt > 0.0_wp) then
            call rep%meta('time step', 'dt = ' // fmt_short(scene%dt, ROUND_TRIP) // ': ' // scene%dt_text)
        else
            call rep%meta('time step', 'unknown: ' // scene%dt_text // ' (no e_host, steps_per_contact or verdict)')
        end if
        s = scene%host_text
        if (scene%host /= HD_HOST_NONE) s = s // '; modeled as the host scheme ' // hertzdamp_host_name(scene%host)
        call rep%meta('integrator', s)
        do i = 1, scene%ncontacts
            if (.not. ok(i)) cycle
            call rep%meta('contact ' // scene%contacts(i)%pair, contact_text(scene%contacts(i), decks(i)))
        end do
        do i = 1, scene%skipped%n
            call rep%meta(numbered('not checked', i, scene%skipped%n), scene%skipped%item(i)%s)
        end do
        do i = 1, scene%notes%n
            call rep%meta(numbered('not interpreted', i, scene%notes%n), scene%notes%item(i)%s)
        end do
        call contact_notes(scene, decks, ok, opt, rep)
        if (.not. opt%have_e) call rep%meta('target', 'e_target: the restitution coefficient the deck gives ' // &
                                            '(empty where it gives a damping coefficient; --e sets one)')
        if (opt%have_e) call rep%meta('target', 'e_target = ' // fmt_short(opt%e_user, ROUND_TRIP) // ' (--e)')
        call rep%meta('verdicts', verdict_text)
        call rep%meta('columns', 'e_model: the continuous model with the deck''s k and d; e_host, e_spread: mean ' // &
                      'and standard deviation over the onset phase with the engine''s integrator at dt; ' // &
                      'steps_per_contact = t_c/dt; corrected: the engine''s parameter that makes e_host (e_model ' // &
                      'where the integrator is not modeled) equal e_target')
    end subroutine header

    !> The contacts' own notes (version and geometry traps), each once; the note on
    !> LAMMPS's half-step velocity is left out: e_host models it.  Then, for the engines
    !> whose table row asks for it (LAMMPS), what the other releases give, once for the
    !> contacts they give the same.
    subroutine contact_notes(scene, decks, ok, opt, rep)
        type(peer_scene), intent(in) :: scene
        type(peer_deck), intent(in) :: decks(:)
        logical, intent(in) :: ok(:)
        type(peer_check_options), intent(in) :: opt
        type(peer_report), intent(inout) :: rep
        type(text_map) :: seen, seen_other
        type(text_list) :: notes, other, texts, pairs
        type(check_engine) :: e
        integer :: i, j, k
        e = check_engine_of(scene%peer)
        do i = 1, scene%ncontacts
            if (.not. ok(i)) cycle
            do j = 1, size(decks(i)%notes)
                if (index(decks(i)%notes(j)%s, 'half-step velocity') > 0) cycle
                if (seen%get(decks(i)%notes(j)%s) > 0) cycle
                call notes%push(decks(i)%notes(j)%s)
                call seen%put(decks(i)%notes(j)%s, notes%n)
            end do
        end do
        do i = 1, scene%ncontacts
            if (.not. (ok(i) .and. e%release_notes)) cycle
            call release_texts(scene, scene%contacts(i), decks(i), opt, texts)
            do j = 1, texts%n
                k = seen_other%get(texts%item(j)%s)
                if (k == 0) then
                    call other%push(texts%item(j)%s)
                    call pairs%push(scene%contacts(i)%pair)
                    call seen_other%put(texts%item(j)%s, other%n)
                else
                    pairs%item(k)%s = pairs%item(k)%s // ', ' // scene%contacts(i)%pair
                end if
            end do
        end do
        do k = 1, other%n
            call notes%push(trim(merge('contacts', 'contact ', index(pairs%item(k)%s, ',') > 0)) // ' ' // &
                            pairs%item(k)%s // ': ' // other%item(k)%s)
        end do
        do i = 1, notes%n
            call rep%meta(numbered('note', i, notes%n), notes%item(i)%s)
        end do
    end subroutine contact_notes

    !> What the engine's other releases give for a contact at the first speed with a
    !> result, where it differs: e_model, e_host (where the integrator is modeled) and t_c.
    subroutine release_texts(scene, c, deck, opt, texts)
        type(peer_scene), intent(in) :: scene
        type(peer_contact), intent(in) :: c
        type(peer_deck), intent(in) :: deck
        type(peer_check_options), intent(in) :: opt
        type(text_list), intent(out) :: texts
        type(peer_release), allocatable :: rs(:)
        type(peer_point) :: pt
        type(check_row) :: r
        character(len=:), allocatable :: s
        real(wp) :: et
        logical :: have_et
        integer :: i, k
        do i = 1, size(opt%speeds)
            call row_target(deck, opt, opt%speeds(i), et, have_et)
            pt = peer_evaluate(deck, opt%speeds(i), et)
            if (peer_has_result(pt%status)) exit
        end do
        if (i > size(opt%speeds)) return
        rs = peer_other_releases(c%words, c%mat, deck, pt, et)
        do k = 1, size(rs)
            s = rs(k)%deck%version // ' (--release ' // release_word(deck%peer, rs(k)%release) // ')'
            if (len(rs(k)%refusal) > 0) then
                call texts%push(s // ': ' // rs(k)%refusal)
                cycle
            end if
            call evaluate_row(scene, rs(k)%deck, rs(k)%pt, et, have_et, r)
            if (rs(k)%pt%status == HD_NO_REBOUND) then
                s = s // ' gives no rebound'
            else
                s = s // ' gives e_model = ' // fmt_short(rs(k)%pt%e, 6)
                if (r%have_host) s = s // ', e_host = ' // fmt_short(r%e_host, 6)
                s = s // ', t_c = ' // fmt_short(rs(k)%pt%tc, 6)
            end if
            call texts%push(s // ' at u = ' // fmt_short(pt%u, 6) // ' (' // &
                            peer_spec_field(rs(k)%deck%row, 'alpha_expr') // '; ' // rs(k)%deck%k_text // ')')
        end do
    end subroutine release_texts

    !> The target at impact speed u: --e, the deck's restitution input (Yade's en with vn:
    !> the Mueller-Poeschel e at u, Pade(V*(en) (u/vn)^(1/10))), or 0.5 where neither gives
    !> one (have false).
    subroutine row_target(deck, opt, u, et, have)
        type(peer_deck), intent(in) :: deck
        type(peer_check_options), intent(in) :: opt
        real(wp), intent(in) :: u
        real(wp), intent(out) :: et
        logical, intent(out) :: have
        have = opt%have_e .or. deck%e_deck > 0.0_wp
        et = 0.5_wp
        if (deck%e_deck > 0.0_wp) et = deck%e_deck
        if (opt%have_e) et = opt%e_user
        if (deck%coef == COEF_D_YADE_VN .and. .not. opt%have_e) et = peer_pade_mp(peer_pade_mp_inverse(deck%p) * &
                                                                                  (u / deck%vn)**0.1_wp)
    end subroutine row_target

    function contact_text(c, deck) result(s)
        type(peer_contact), intent(in) :: c
        type(peer_deck), intent(in) :: deck
        character(len=:), allocatable :: s
        s = deck%deck_text // ' (' // c%where // '); ' // hertzdamp_law_name(deck%law) // ' law, ' // &
            hertzdamp_end_name(deck%iend) // ' end, ' // trim(peer_spec_field(deck%row, 'alpha_expr')) // '; k = ' // &
            fmt_short(deck%k, 6) // ', m = ' // fmt_short(deck%m, 6) // ', R = ' // fmt_short(deck%radius, 6) // &
            '; ' // c%sizes
    end function contact_text

    !> The rows of one contact, one per speed.
    subroutine contact_rows(scene, c, deck, opt, rep, refused, host_notes)
        type(peer_scene), intent(in) :: scene
        type(peer_contact), intent(in) :: c
        type(peer_deck), intent(in) :: deck
        type(peer_check_options), intent(in) :: opt
        type(peer_report), intent(inout) :: rep
        type(text_list), intent(inout) :: refused     !! corrected values the engine refuses, why
        type(text_list), intent(inout) :: host_notes  !! why e_host is missing where the integrator is modeled
        type(peer_point) :: pt
        type(check_row) :: r
        real(wp) :: et
        logical :: have_et, have
        character(len=:), allocatable :: problem
        integer :: i
        problem = ''
        do i = 1, size(opt%speeds)
            call row_target(deck, opt, opt%speeds(i), et, have_et)
            pt = peer_evaluate(deck, opt%speeds(i), et)
            have = peer_has_result(pt%status)
            call rep%str(c%pair)
            call rep%num(pt%u)
            if (have) then
                call evaluate_row(scene, deck, pt, et, have_et, r)
            else
                r = check_row(verdict='', why='', host_why='')
            end if
            call rep%num_or_none(et, have_et)
            call rep%num_or_none(pt%e, have)
            call rep%num_or_none(r%e_host, r%have_host)
            call rep%num_or_none(r%e_spread, r%have_host)
            call rep%num_or_none(r%steps, r%have_steps)
            call rep%num_or_none(pt%tc, have)
            if (len(r%verdict) > 0) then
                call rep%str(r%verdict)
            else
                call rep%none()
            end if
            if (len(r%host_why) > 0) call host_notes%push('contact ' // c%pair // ' at u = ' // fmt_short(pt%u, 6) // &
                                                          ': e_host: ' // r%host_why)
            if (len(r%why) > 0) call refused%push('contact ' // c%pair // ' at u = ' // fmt_short(pt%u, 6) // &
                                                  ': no value of ' // deck%p_name // ' gives e_target: ' // r%why)
            if (r%have_corrected) then
                problem = peer_parameter_problem(deck, r%corrected)
                if (len(problem) > 0) then
                    call refused%push('contact ' // c%pair // ' at u = ' // fmt_short(pt%u, 6) // ': ' // &
                                      deck%p_name // ' = ' // fmt_short(r%corrected, 12) // ' would give the ' // &
                                      'target, but ' // problem)
                    r%have_corrected = .false.
                end if
            end if
            call rep%num_or_none(r%corrected, r%have_corrected)
            if (have) then
                call rep%end_row(pt%status, '')
            else
                call rep%end_row(pt%status, 'contact ' // c%pair // ': ' // peer_row_reason(deck, pt))
            end if
        end do
    end subroutine contact_rows

    !> e_host, e_spread, steps, verdict and corrected of a point with a result.
    subroutine evaluate_row(scene, deck, pt, et, have_et, r)
        type(peer_scene), intent(in) :: scene
        type(peer_deck), intent(in) :: deck
        type(peer_point), intent(in) :: pt
        real(wp), intent(in) :: et
        logical, intent(in) :: have_et
        type(check_row), intent(out) :: r
        type(hertzdamp_host_stats) :: stats
        real(wp) :: h
        integer :: st
        r%verdict = 'unchecked'
        r%why = ''
        r%host_why = ''
        if (have_et) then
            r%corrected = pt%p_corrected
            r%have_corrected = pt%status_corrected == HD_OK
            if (.not. r%have_corrected) r%why = 'the continuous model: ' // hertzdamp_message(pt%status_corrected)
        end if
        if (.not. (scene%dt > 0.0_wp .and. pt%status == HD_OK)) then
            if (pt%status == HD_NO_REBOUND) r%verdict = 'unresolved'
            return
        end if
        r%steps = pt%tc / scene%dt
        r%have_steps = ieee_is_finite(r%steps)
        if (r%have_steps .and. r%steps < 3.0_wp) then
            r%verdict = 'unresolved'
            return
        end if
        if (scene%host == HD_HOST_NONE) return
        h = scene%dt / pt%tstar
        call hertzdamp_host_mean(pt%alpha, h, deck%law, deck%iend, scene%host, stats, st)
        if (st /= HD_OK) then      ! (e.g. h = dt/t* outside the host module's range): no guess
            r%host_why = hertzdamp_message(st) // ' (h = dt/t* = ' // fmt_short(h, 6) // ')'
            return
        end if
        r%e_host = stats%e_mean
        r%e_spread = stats%e_sd
        r%have_host = .true.
        if (abs(r%e_host - pt%e) <= 0.01_wp * pt%e .and. r%e_spread <= 0.01_wp * pt%e) then
            r%verdict = 'ok'
        else
            r%verdict = 'coarse'
        end if
        r%have_corrected = .false.
        if (have_et) call host_corrected(scene, deck, pt, et, h, r)
    end subroutine evaluate_row

    !> The engine's parameter whose phase-mean e_host at this h is the target: alpha from
    !> hertzdamp_host_alpha_for_e, then the damping c (gamma, or d = alpha m/(t* (u t*)^q))
    !> and peer_parameter.
    subroutine host_corrected(scene, deck, pt, et, h, r)
        type(peer_scene), intent(in) :: scene
        type(peer_deck), intent(in) :: deck
        type(peer_point), intent(in) :: pt
        real(wp), intent(in) :: et, h
        type(check_row), intent(inout) :: r
        type(hertzdamp_host_stats) :: stats
        real(wp) :: alpha, c, q
        integer :: st
        r%why = ''
        call hertzdamp_host_alpha_for_e(et, h, deck%law, deck%iend, scene%host, alpha, stats, st)
        if (st /= HD_OK) then
            r%why = 'the integrator at this time step: ' // hertzdamp_message(st)
            return
        end if
        if (deck%law == HD_DAMPING_TSUJI) then
            c = alpha
        else
            q = hertzdamp_law_q(deck%law)
            c = alpha * deck%m / (pt%tstar * (pt%u * pt%tstar)**q)
        end if
        if (.not. ieee_is_finite(c)) then
            r%why = 'the damping is beyond double precision'
            return
        end if
        call peer_parameter(deck, c, r%corrected, st)
        r%have_corrected = st == HD_OK
        if (st /= HD_OK) r%why = 'the engine''s formula cannot produce alpha = ' // fmt_short(alpha, 6)
    end subroutine host_corrected

end module hertzdamp_check_whole
