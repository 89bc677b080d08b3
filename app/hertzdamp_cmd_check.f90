!> The command `check`: what a peer DEM engine's input really does.
!>
!>     hertzdamp check ENGINE FILE... [--velocity LIST] [--e E] [--release R] [--format F]
!>     hertzdamp check ENGINE WORDS... --radius R --density RHO --velocity SWEEP [options]
!>     hertzdamp check --table
!>
!> Whole decks (the arguments are files) are read and evaluated by hertzdamp_check_whole;
!> one contact in the engine's words by hertzdamp_check_deck and hertzdamp_check_single;
!> the table by hertzdamp_check_table.  This module parses the command line and prints.
!>
!> Files or words: an argument after the engine is the engine's contact words when it
!> holds a key=value word, or (LAMMPS) when it names no file and its first word is one
!> a LAMMPS contact starts with (pair_coeff, fix, gran/hertz/history, hertz/material,
!> damping, ...); any other argument is a deck file, which must exist (exit 2 naming it).
module hertzdamp_cmd_check
    use hertzdamp, only: hertzdamp_rk, HD_OK
    use hertzdamp_check_model, only: peer_deck, peer_point, peer_evaluate
    use hertzdamp_check_deck, only: peer_materials, peer_read_deck
    use hertzdamp_check_engines, only: check_engine, check_engine_of, peer_code, peer_name, peer_releases, &
                                       peer_engine_list
    use hertzdamp_text_list, only: text_string, text_list
    use hertzdamp_text_parse, only: text_words
    use hertzdamp_check_scene, only: peer_scene
    use hertzdamp_check_whole, only: peer_check_options, peer_read_scene, peer_check_scene, peer_units_si
    use hertzdamp_check_single, only: peer_single_report
    use hertzdamp_check_table, only: peer_table_lines, peer_table_report
    use hertzdamp_check_report, only: peer_report, PEER_CELL_NUM, PEER_CELL_STR
    use hertzdamp_cli, only: cli_args, cli_line, cli_buffer, parse_args, parse_real, parse_int, parse_choice, &
                             required_sweep, fail, quit, EXIT_USAGE, EXIT_OK
    use hertzdamp_cli_text, only: fmt_short, ROUND_TRIP
    use hertzdamp_cli_output, only: out_table, format_choices, FORMAT_TEXT
    use hertzdamp_cli_help, only: print_help, wants_help
    use hertzdamp_cli_materials, only: cli_contact, parse_contact
    use hertzdamp_cli_model, only: law_text
    use hertzdamp_cli_rows, only: row_log, row_kind, row_word
    use hertzdamp_cli_progress, only: progress_reporter
    use hertzdamp_cli_plausible, only: warn_implausible, quiet_flag
    implicit none
    private
    public :: cmd_check

    integer, parameter :: wp = hertzdamp_rk

    !> The contact options of `check` with words (hertzdamp_cli_materials reads and checks
    !> them; the deck may give the radius and density instead, e.g. MFiX D_P0 and RO_S0).
    character(len=*), parameter :: material_options = '--radius --radius2 --density --density2'

    !> What `check` was asked (the options but the deck).
    type :: check_request
        integer :: release = 3               !! LAMMPS_* or YADE_* (3: current)
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
        type(check_request) :: rq
        type(text_string), allocatable :: files(:)
        integer :: peer
        if (wants_help()) call print_help('check')
        call parse_args(2, '--velocity --e --steps --release --format ' // material_options, &
                        '--table --wall --progress ' // quiet_flag, args, positionals=words)
        rq%fmt = parse_choice(args%get('--format', 'text'), format_choices, 'format (--format)')
        if (args%has('--table')) then
            if (size(words) > 0 .or. size(args%opts) > merge(2, 1, args%has('--format'))) then
                call fail(EXIT_USAGE, '--table takes no engine and no option but --format')
            end if
            call print_table(rq%fmt)
        end if
        if (size(words) == 0) call fail(EXIT_USAGE, 'missing the engine: ' // peer_engine_list() // &
                                        ' (see hertzdamp check --help)')
        peer = peer_code(words(1)%s)
        if (peer == 0) call fail(EXIT_USAGE, 'unknown engine "' // words(1)%s // '": choose ' // peer_engine_list())
        call common_options(args, peer, rq)
        if (deck_files(peer, words, files)) then
            call check_files(args, peer, files, rq)
        else
            call check_words(args, peer, words, rq)
        end if
    end subroutine cmd_check

    !> --release, --e, --progress (every form).
    subroutine common_options(args, peer, rq)
        type(cli_args), intent(in) :: args
        integer, intent(in) :: peer
        type(check_request), intent(inout) :: rq
        character(len=:), allocatable :: v
        if (args%has('--release')) then
            if (len(peer_releases(peer)) == 0) call fail(EXIT_USAGE, '--release applies to lammps and yade only')
            rq%release = parse_choice(args%get('--release', ''), peer_releases(peer), &
                                      peer_name(peer, title=.true.) // ' release (--release)')
        end if
        rq%have_e = args%has('--e')
        if (rq%have_e) then
            v = args%get('--e', '')
            rq%e_user = parse_real(v, '--e')
            if (.not. (rq%e_user > 0.0_wp .and. rq%e_user <= 1.0_wp)) then
                call fail(EXIT_USAGE, '--e ' // v // ': the target restitution must be in (0, 1]')
            end if
        end if
        rq%progress = args%has('--progress')
    end subroutine common_options

    !> Whether the arguments after the engine are deck files (else the engine's contact
    !> words): the first is the engine's words when it holds a key=value word, or when it
    !> names no file and starts with a word of a contact of the engine (LAMMPS:
    !> check_engine%takes_words); otherwise every argument must name an existing file
    !> (exit 2 naming the first that does not).  No file system call per word: a contact
    !> of 40,000 words stays fast.
    logical function deck_files(peer, words, files) result(is_deck)
        integer, intent(in) :: peer
        type(cli_line), intent(in) :: words(:)
        type(text_string), allocatable, intent(out) :: files(:)
        type(check_engine) :: e
        logical :: exists
        integer :: i
        allocate (files(0))
        is_deck = .false.
        if (size(words) < 2) return
        if (index(words(2)%s, '=') > 0) return
        e = check_engine_of(peer)
        inquire (file=words(2)%s, exist=exists)
        if (.not. exists .and. e%takes_words(words(2)%s)) return
        is_deck = .true.
        deallocate (files)
        allocate (files(size(words) - 1))
        do i = 2, size(words)
            inquire (file=words(i)%s, exist=exists)
            if (exists .and. index(words(i)%s, '=') == 0) then
                files(i - 1)%s = words(i)%s
            else if (i > 2 .and. (index(words(i)%s, '=') > 0 .or. e%takes_words(words(i)%s))) then
                call fail(EXIT_USAGE, 'give either deck files or the engine''s words, not both ("' // words(2)%s // &
                          '" is a file, "' // words(i)%s // '" is not)')
            else if (len(e%starts) > 0) then
                call fail(EXIT_USAGE, words(i)%s // ': no such deck file (' // e%title // '''s own words start ' // &
                          'with pair_coeff, fix, a granular pair style or a pair_coeff keyword such as hertz/material)')
            else
                call fail(EXIT_USAGE, words(i)%s // ': no such deck file (' // e%title // '''s own words are ' // &
                          'key=value)')
            end if
        end do
    end function deck_files

    ! ------------------------------------------------------------------ a whole deck

    subroutine check_files(args, peer, files, rq)
        type(cli_args), intent(in) :: args
        integer, intent(in) :: peer
        type(text_string), intent(in) :: files(:)
        type(check_request), intent(inout) :: rq
        type(peer_scene) :: scene
        type(peer_check_options) :: opt
        type(peer_report) :: rep
        character(len=:), allocatable :: msg
        integer :: st
        if (args%has('--steps') .or. args%has('--wall') .or. args%has('--radius') .or. args%has('--radius2') .or. &
            args%has('--density') .or. args%has('--density2')) call fail(EXIT_USAGE, &
            'a deck gives its own sizes, walls and time step: --radius, --radius2, --density, --density2, ' // &
            '--wall and --steps apply to the engine''s words, not to deck files')
        if (args%has('--velocity')) then
            opt%speeds = speeds(args)
        else
            opt%speeds = [1.0_wp]
        end if
        call peer_read_scene(peer, files, scene, msg)
        if (len(msg) > 0) call fail(EXIT_USAGE, peer_name(peer) // ': ' // msg)
        ! the plausible ranges are SI: a cgs or lj deck's speeds are not compared with them
        if (peer_units_si(scene%units)) call warn_implausible(args)
        opt%release = rq%release
        opt%have_e = rq%have_e
        opt%e_user = rq%e_user
        call peer_check_scene(scene, opt, rep, st, msg)
        if (st /= HD_OK) call fail(EXIT_USAGE, peer_name(peer) // ': ' // msg)
        if (.not. args%has('--velocity')) call rep%meta('velocity', '1 in the deck''s velocity unit ' // &
                                                        '(--velocity sets the impact speeds)')
        call emit(rep, -1, rq%fmt)
    end subroutine check_files

    !> --velocity, checked positive.
    function speeds(args) result(u)
        type(cli_args), intent(in) :: args
        real(wp), allocatable :: u(:)
        integer :: i
        u = required_sweep(args, '--velocity')
        do i = 1, size(u)
            if (.not. u(i) > 0.0_wp) call fail(EXIT_USAGE, '--velocity ' // fmt_short(u(i), ROUND_TRIP) // &
                                               ': impact speeds must be positive')
        end do
    end function speeds

    ! ------------------------------------------------------------------ one contact in words

    subroutine check_words(args, peer, words, rq)
        type(cli_args), intent(in) :: args
        integer, intent(in) :: peer
        type(cli_line), intent(in) :: words(:)
        type(check_request), intent(inout) :: rq
        type(cli_contact) :: ct
        type(peer_materials) :: mat
        type(text_list) :: w
        type(text_string), allocatable :: tokens(:)
        type(peer_deck) :: deck
        type(peer_point), allocatable :: pt(:)
        type(peer_report) :: rep
        type(progress_reporter) :: progress
        character(len=:), allocatable :: msg
        real(wp) :: et
        integer :: i, status
        do i = 2, size(words)
            call text_words(words(i)%s, w)
        end do
        tokens = w%items()
        ! the bodies: checked as every command checks them (a wall has no --radius2, ...)
        call parse_contact(args, ct)
        mat%wall = ct%wall
        mat%radius(1) = optional_value('--radius')
        mat%radius(2) = optional_value('--radius2')
        mat%density(1) = optional_value('--density')
        mat%density(2) = optional_value('--density2')
        rq%speeds = speeds(args)
        if (args%has('--steps')) then
            rq%steps = parse_int(args%get('--steps', ''), '--steps')
            if (rq%steps < 1) call fail(EXIT_USAGE, '--steps must be >= 1')
        end if
        call warn_implausible(args)
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
        call peer_single_report(deck, pt, et, rq%have_e, rq%steps, rq%release, tokens, mat, rep)
        call emit(rep, deck%law, rq%fmt)
    contains
        !> The value of a material option, 0 when absent (parse_contact has checked it).
        real(wp) function optional_value(key) result(x)
            character(len=*), intent(in) :: key
            x = 0.0_wp
            if (args%has(key)) x = parse_real(args%get(key, ''), key)
        end function optional_value
    end subroutine check_words

    ! ------------------------------------------------------------------ printing

    !> Print a report with its status column, the exit code decided by its rows
    !> (hertzdamp_cli_rows); `law` (>= 0) fills the header's empty 'law' line.
    subroutine emit(rep, law, fmt)
        type(peer_report), intent(in) :: rep
        integer, intent(in) :: law, fmt
        type(out_table) :: t
        type(row_log) :: rows
        call to_table(rep, law, t)
        call rows_of(rep, rows)
        call rows%emit(t, fmt)
    end subroutine emit

    subroutine to_table(rep, law, t)
        type(peer_report), intent(in) :: rep
        integer, intent(in) :: law
        type(out_table), intent(out) :: t
        integer :: i, j
        call t%set_columns(rep%columns // ',status', rep%units // ',')
        do i = 1, rep%keys%n
            if (rep%keys%item(i)%s == 'law' .and. len(rep%values%item(i)%s) == 0 .and. law >= 0) then
                call t%meta('law', law_text(law))
            else
                call t%meta(rep%keys%item(i)%s, rep%values%item(i)%s)
            end if
        end do
        do i = 1, rep%nrow
            do j = 1, rep%ncol
                select case (rep%cells(j, i)%kind)
                case (PEER_CELL_NUM); call t%num(rep%cells(j, i)%x)
                case (PEER_CELL_STR); call t%str(rep%cells(j, i)%s)
                case default; call t%none()
                end select
            end do
            call t%str(row_word(row_kind(rep%status(i))))
        end do
    end subroutine to_table

    subroutine rows_of(rep, rows)
        type(peer_report), intent(in) :: rep
        type(row_log), intent(inout) :: rows
        integer :: i
        do i = 1, rep%nrow
            call rows%add(row_kind(rep%status(i)), rep%reason(i)%s)
        end do
    end subroutine rows_of

    !> `hertzdamp check --table`: markdown (text), CSV or JSON; exit 0.
    subroutine print_table(fmt)
        integer, intent(in) :: fmt
        type(cli_buffer) :: buf
        type(text_string), allocatable :: lines(:)
        type(peer_report) :: rep
        type(out_table) :: t
        integer :: i
        if (fmt == FORMAT_TEXT) then
            call peer_table_lines(lines)
            do i = 1, size(lines)
                call buf%add(lines(i)%s)
            end do
        else
            call peer_table_report(rep)
            call to_table(rep, -1, t)
            call t%render(fmt, buf)
        end if
        call buf%flush_to_stdout()
        call quit(EXIT_OK)
    end subroutine print_table

end module hertzdamp_cmd_check
