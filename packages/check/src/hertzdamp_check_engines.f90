!> The six peer engines as one type, `check_engine` (names, keys, releases, and the
!> readers of a contact and of a deck), and their table, `check_engines`, in the order
!> of the PEER_* codes: adding an engine is a row here, its readers and its rows of
!> data/peers/peers_spec.csv.
!>
!> The readers are procedure components: LAMMPS reads its own words (`words_reader`),
!> the others `key=value` words (`keys_reader`, after the one split and the one check
!> that every key was used, here); an engine without `deck_reader` has decks that are
!> programs (MercuryDPM, Chrono).
module hertzdamp_check_engines
    use hertzdamp_check_model, only: peer_deck, PEER_LAMMPS, PEER_LIGGGHTS, PEER_MERCURYDPM, PEER_YADE, PEER_MFIX, &
                                     PEER_CHRONO
    use hertzdamp_check_common, only: peer_materials, kv_list, split_pairs, check_all_used
    use hertzdamp_check_scene, only: peer_scene
    use hertzdamp_check_lammps, only: read_lammps, lammps_keys, lammps_releases, lammps_starts
    use hertzdamp_check_liggghts, only: read_liggghts, liggghts_keys
    use hertzdamp_check_mercury, only: read_mercury, mercury_keys
    use hertzdamp_check_yade, only: read_yade, yade_keys, yade_releases
    use hertzdamp_check_mfix, only: read_mfix, mfix_keys
    use hertzdamp_check_chrono, only: read_chrono, chrono_keys
    use hertzdamp_check_lammps_deck, only: read_lammps_deck
    use hertzdamp_check_liggghts_deck, only: read_liggghts_deck
    use hertzdamp_check_mfix_deck, only: read_mfix_deck
    use hertzdamp_check_yade_deck, only: read_yade_deck
    use hertzdamp_text_list, only: text_string
    use hertzdamp_text_format, only: lower
    implicit none
    private

    abstract interface
        !> A contact from the engine's own words.
        subroutine words_iface(tok, mat, deck, msg)
            import :: text_string, peer_materials, peer_deck
            implicit none
            type(text_string), intent(in) :: tok(:)
            type(peer_materials), intent(in) :: mat
            type(peer_deck), intent(inout) :: deck
            character(len=:), allocatable, intent(inout) :: msg
        end subroutine words_iface
        !> A contact from key=value words (marking the keys it uses).
        subroutine keys_iface(kv, mat, deck, msg)
            import :: kv_list, peer_materials, peer_deck
            implicit none
            type(kv_list), intent(inout) :: kv
            type(peer_materials), intent(in) :: mat
            type(peer_deck), intent(inout) :: deck
            character(len=:), allocatable, intent(inout) :: msg
        end subroutine keys_iface
        !> A whole deck's files.
        subroutine deck_iface(paths, scene, msg)
            import :: text_string, peer_scene
            implicit none
            type(text_string), intent(in) :: paths(:)
            type(peer_scene), intent(out) :: scene
            character(len=:), allocatable, intent(out) :: msg
        end subroutine deck_iface
    end interface

    !> One engine.
    type, public :: check_engine
        integer :: code = 0                         !! PEER_*
        character(len=:), allocatable :: name       !! as the command line takes it ('lammps', ...)
        character(len=:), allocatable :: title      !! as the engine writes it ('LAMMPS', ...)
        character(len=:), allocatable :: keys       !! the keys (LAMMPS: pair_coeff keywords), space-separated
        character(len=:), allocatable :: releases   !! the words of --release, oldest first, the last the
                                                    !! default ('': the formulas do not depend on it)
        character(len=:), allocatable :: starts     !! the words its contact words start with ('': key=value)
        logical :: upper_keys = .false.             !! the keys are case-insensitive (upper-cased)
        logical :: release_notes = .false.          !! reports note what its other releases give
        procedure(words_iface), pointer, nopass :: words_reader => null()   !! its own words
        procedure(keys_iface), pointer, nopass :: keys_reader => null()     !! key=value words
        procedure(deck_iface), pointer, nopass :: deck_reader => null()     !! a deck (null: none)
    contains
        procedure :: read_contact => engine_read_contact   !! a contact from the command line's words
        procedure :: read_deck => engine_read_deck         !! a whole deck's files
        procedure :: takes_words => engine_takes_words     !! whether an argument is its contact words
    end type check_engine

    public :: check_engines, check_engine_of, peer_code, peer_name, peer_releases, peer_engine_list

contains

    !> The table of the engines, in the order of the PEER_* codes.
    function check_engines() result(t)
        type(check_engine) :: t(PEER_CHRONO)
        t(PEER_LAMMPS) = check_engine(code=PEER_LAMMPS, name='lammps', title='LAMMPS', keys=lammps_keys, &
                                      releases=lammps_releases, starts=lammps_starts, release_notes=.true., &
                                      words_reader=read_lammps, deck_reader=read_lammps_deck)
        t(PEER_LIGGGHTS) = check_engine(code=PEER_LIGGGHTS, name='liggghts', title='LIGGGHTS', keys=liggghts_keys, &
                                        releases='', starts='', keys_reader=read_liggghts, &
                                        deck_reader=read_liggghts_deck)
        t(PEER_MERCURYDPM) = check_engine(code=PEER_MERCURYDPM, name='mercurydpm', title='MercuryDPM', &
                                          keys=mercury_keys, releases='', starts='', keys_reader=read_mercury)
        t(PEER_YADE) = check_engine(code=PEER_YADE, name='yade', title='Yade', keys=yade_keys, releases=yade_releases, &
                                    starts='', keys_reader=read_yade, deck_reader=read_yade_deck)
        t(PEER_MFIX) = check_engine(code=PEER_MFIX, name='mfix', title='MFiX', keys=mfix_keys, releases='', &
                                    starts='', upper_keys=.true., keys_reader=read_mfix, deck_reader=read_mfix_deck)
        t(PEER_CHRONO) = check_engine(code=PEER_CHRONO, name='chrono', title='Chrono', keys=chrono_keys, &
                                      releases='', starts='', keys_reader=read_chrono)
    end function check_engines

    !> The engine of a PEER_* code (code 0, no readers and name '?' when unknown).
    function check_engine_of(peer) result(e)
        integer, intent(in) :: peer   !! PEER_*
        type(check_engine) :: e
        type(check_engine) :: t(PEER_CHRONO)
        if (peer >= 1 .and. peer <= PEER_CHRONO) then
            t = check_engines()
            e = t(peer)
        else
            e = check_engine(name='?', title='?', keys='', releases='', starts='')
        end if
    end function check_engine_of

    !> The PEER_* code of an engine name (case-insensitive), 0 if unknown.
    integer function peer_code(name) result(code)
        character(len=*), intent(in) :: name   !! lammps, liggghts, mercurydpm, yade, mfix, chrono
        type(check_engine) :: t(PEER_CHRONO)
        integer :: j
        t = check_engines()
        code = 0
        do j = 1, size(t)
            if (t(j)%name == lower(name)) code = j
        end do
    end function peer_code

    !> Name of an engine as the command line takes it or, with `title`, as the engine
    !> writes it; '?' if unknown.
    function peer_name(peer, title) result(name)
        integer, intent(in) :: peer              !! PEER_*
        logical, intent(in), optional :: title   !! the engine's own spelling
        character(len=:), allocatable :: name
        type(check_engine) :: e
        e = check_engine_of(peer)
        name = e%name
        if (present(title)) then
            if (title) name = e%title
        end if
    end function peer_name

    !> The releases an engine's formulas depend on (the words of --release, oldest
    !> first, the last is the default), '' when they do not.
    function peer_releases(peer) result(words)
        integer, intent(in) :: peer   !! PEER_*
        character(len=:), allocatable :: words
        type(check_engine) :: e
        e = check_engine_of(peer)
        words = e%releases
    end function peer_releases

    !> The engines' names for messages: 'lammps, liggghts, ... or chrono'.
    function peer_engine_list() result(s)
        character(len=:), allocatable :: s
        type(check_engine) :: t(PEER_CHRONO)
        integer :: j
        t = check_engines()
        s = t(1)%name
        do j = 2, size(t)
            s = s // trim(merge(' or', ',  ', j == size(t))) // ' ' // t(j)%name
        end do
    end function peer_engine_list

    !> Read a contact from the command line's words: the engine's own reader, or the
    !> key=value words split (a key given twice is an error), read, and every key used.
    subroutine engine_read_contact(self, tokens, mat, deck, msg)
        class(check_engine), intent(in) :: self
        type(text_string), intent(in) :: tokens(:)           !! the words
        type(peer_materials), intent(in) :: mat              !! the bodies
        type(peer_deck), intent(inout) :: deck               !! deck%release set
        character(len=:), allocatable, intent(inout) :: msg  !! why it cannot be read ('' when it can)
        type(kv_list) :: kv
        if (associated(self%words_reader)) then
            call self%words_reader(tokens, mat, deck, msg)
        else if (associated(self%keys_reader)) then
            call split_pairs(tokens, self%upper_keys, kv, msg)
            if (len(msg) == 0) call self%keys_reader(kv, mat, deck, msg)
            if (len(msg) == 0) call check_all_used(kv, self%keys, self%title, msg)
        else
            msg = 'unknown engine'
        end if
    end subroutine engine_read_contact

    !> Read a whole deck; msg says why not (a file that cannot be read, an engine whose
    !> decks are programs).
    subroutine engine_read_deck(self, paths, scene, msg)
        class(check_engine), intent(in) :: self
        type(text_string), intent(in) :: paths(:)            !! the deck's files, in order
        type(peer_scene), intent(out) :: scene
        character(len=:), allocatable, intent(out) :: msg
        if (associated(self%deck_reader)) then
            call self%deck_reader(paths, scene, msg)
        else
            msg = self%name // ' decks are C++ or Python programs: give the species or material calls ' // &
                  'as key=value words (hertzdamp check --help)'
        end if
    end subroutine engine_read_deck

    !> Whether a command-line argument is the engine's contact words rather than a file
    !> name: it holds a key=value word, or its first word is one of `starts`.
    pure logical function engine_takes_words(self, arg) result(words)
        class(check_engine), intent(in) :: self
        character(len=*), intent(in) :: arg    !! the argument
        character(len=:), allocatable :: first
        integer :: k
        words = index(arg, '=') > 0
        if (words .or. len(self%starts) == 0) return
        first = adjustl(arg)
        k = scan(first, ' ' // achar(9))
        if (k > 0) first = first(1:k - 1)
        words = len_trim(first) > 0 .and. index(' ' // self%starts // ' ', ' ' // trim(first) // ' ') > 0
    end function engine_takes_words

end module hertzdamp_check_engines
