!> A whole deck as the checker understands it (`peer_scene`): its contacts, each a type
!> pair or a type against a wall, written in the words of the engine's contact reader
!> (hertzdamp_check_deck) with the bodies' sizes; the time step and the integrator the
!> engine would use; and everything the reader could not interpret, with file:line.
!> Filled by the engines' deck readers (the LAMMPS and LIGGGHTS readers through the
!> script interpreter hertzdamp_lmpscript, the MFiX and Yade readers); evaluated by
!> hertzdamp_check_whole.
module hertzdamp_check_scene
    use hertzdamp, only: hertzdamp_rk, HD_HOST_NONE
    use hertzdamp_check_common, only: peer_materials
    use hertzdamp_text_list, only: text_string, text_list
    use hertzdamp_lmpscript, only: lmp_script
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> One contact of a deck.
    type, public :: peer_contact
        character(len=:), allocatable :: pair      !! '1-1', '1-2', '1-wall' ('1-wall:ID' when a deck has several walls)
        type(text_string), allocatable :: words(:)   !! the contact in the words of the engine's contact reader
        type(peer_materials) :: mat                !! the bodies (a wall: mat%wall)
        character(len=:), allocatable :: where     !! file:line of the command that defines the contact
        character(len=:), allocatable :: sizes     !! where the bodies' sizes come from
        character(len=:), allocatable :: problem   !! why the contact cannot be checked ('' when it can)
    end type peer_contact

    !> A deck: its contacts, time step, integrator and what was not interpreted.
    type, public :: peer_scene
        integer :: peer = 0                       !! PEER_*
        character(len=:), allocatable :: units    !! unit system of the deck (all numbers are in it)
        real(wp) :: dt = 0.0_wp                   !! the engine's time step (0: unknown)
        character(len=:), allocatable :: dt_text  !! where the time step comes from
        logical :: dt_from_tcoll = .false.        !! MFiX: DTSOLID = min TCOLL / dt_factor over the particle pairs
        real(wp) :: dt_factor = 50.0_wp           !! MFiX DTSOLID_FACTOR
        real(wp) :: dt_max = 0.0_wp               !! MFiX: the fluid step DT caps DTSOLID (0: none)
        integer :: host = HD_HOST_NONE            !! the engine's integrator as a host scheme
        character(len=:), allocatable :: host_text  !! the integrator, or why it is not modeled
        type(peer_contact), allocatable :: contacts(:)
        integer :: ncontacts = 0
        type(text_list) :: notes                  !! what the reader could not interpret, with file:line
        type(text_list) :: skipped                !! contacts that cannot be checked, why, with file:line
        type(text_list) :: files                  !! the files read
        integer(int64) :: work = 0                !! characters and words read, map probes (linear in the deck)
    contains
        procedure :: add_contact => scene_add_contact
        procedure :: note => scene_note
    end type peer_scene

    public :: peer_scene_from_script

contains

    subroutine scene_add_contact(self, c)
        class(peer_scene), intent(inout) :: self
        type(peer_contact), intent(in) :: c
        type(peer_contact), allocatable :: tmp(:)
        if (.not. allocated(self%contacts)) allocate (self%contacts(8))
        if (self%ncontacts == size(self%contacts)) then
            allocate (tmp(2 * size(self%contacts)))
            tmp(1:self%ncontacts) = self%contacts(1:self%ncontacts)
            call move_alloc(tmp, self%contacts)
        end if
        self%ncontacts = self%ncontacts + 1
        self%contacts(self%ncontacts) = c
    end subroutine scene_add_contact

    !> Something the reader did not interpret (or a remark), prefixed with file:line.
    subroutine scene_note(self, where, text)
        class(peer_scene), intent(inout) :: self
        character(len=*), intent(in) :: where   !! file:line ('' for none)
        character(len=*), intent(in) :: text    !! what
        call self%notes%note(where, text)
    end subroutine scene_note

    !> What a LAMMPS or LIGGGHTS script sets for every engine (units, time step,
    !> integrator, notes, files, work) into the scene of its contacts.
    subroutine peer_scene_from_script(st, peer, scene)
        type(lmp_script), intent(in) :: st       !! the script read
        integer, intent(in) :: peer              !! PEER_*
        type(peer_scene), intent(inout) :: scene !! its contacts
        scene%peer = peer
        scene%units = st%units
        scene%dt = st%dt
        scene%dt_text = st%dt_text
        scene%host = st%host
        scene%host_text = st%host_text
        scene%notes = st%notes
        scene%files = st%files
        scene%work = st%work
    end subroutine peer_scene_from_script

end module hertzdamp_check_scene
