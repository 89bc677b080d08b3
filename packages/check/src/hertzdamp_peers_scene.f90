!> A whole deck as the checker understands it (`peer_scene`): its contacts, each a type
!> pair or a type against a wall, written in the words of the engine's contact reader
!> (hertzdamp_peers_deck) with the bodies' sizes; the time step and the integrator the
!> engine would use; and everything the reader could not interpret, with file:line.
!> Filled by the engines' deck readers (hertzdamp_peers_script and its users, the MFiX
!> and Yade readers); evaluated by hertzdamp_peers_check.
!>
!> Also the deck files themselves: read whole and split into lines, in linear time.
module hertzdamp_peers_scene
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_peers, only: peer_text
    use hertzdamp_peers_common, only: peer_materials
    use hertzdamp_peers_text, only: peer_list
    use hertzdamp_host, only: HD_HOST_NONE
    use hertzdamp_apps_text, only: itoa
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> One contact of a deck.
    type, public :: peer_contact
        character(len=:), allocatable :: pair      !! '1-1', '1-2', '1-wall' ('1-wall:ID' when a deck has several walls)
        type(peer_text), allocatable :: words(:)   !! the contact in the words of the engine's contact reader
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
        type(peer_list) :: notes                  !! what the reader could not interpret, with file:line
        type(peer_list) :: skipped                !! contacts that cannot be checked, why, with file:line
        type(peer_list) :: files                  !! the files read
        integer(int64) :: work = 0                !! characters and words read, map probes (linear in the deck)
    contains
        procedure :: add_contact => scene_add_contact
        procedure :: note => scene_note
    end type peer_scene

    public :: peer_read_lines, peer_where

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
        character(len=*), intent(in) :: where, text
        if (len(where) > 0) then
            call self%notes%push(where // ': ' // text)
        else
            call self%notes%push(text)
        end if
    end subroutine scene_note

    !> 'file:line'.
    pure function peer_where(file, line) result(s)
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        character(len=:), allocatable :: s
        s = file // ':' // itoa(line)
    end function peer_where

    !> The lines of a text file (without their line ends; CR LF as LF), read whole.
    subroutine peer_read_lines(path, lines, msg, nchar)
        character(len=*), intent(in) :: path
        type(peer_list), intent(out) :: lines
        character(len=:), allocatable, intent(out) :: msg
        integer(int64), intent(inout) :: nchar     !! characters read, added
        character(len=:), allocatable :: text
        integer :: u, ios, n, i, j, k
        logical :: exists
        msg = ''
        inquire (file=path, exist=exists, size=n)
        if (.not. exists) then
            msg = path // ': no such file'
            return
        end if
        if (n < 0) then
            msg = path // ': not a regular file'
            return
        end if
        allocate (character(len=n) :: text)
        open (newunit=u, file=path, access='stream', form='unformatted', action='read', status='old', iostat=ios)
        if (ios == 0 .and. n > 0) read (u, iostat=ios) text
        if (ios == 0) then
            close (u)
        else
            msg = path // ': cannot be read'
            return
        end if
        nchar = nchar + n
        j = 1
        do i = 1, n + 1
            if (i <= n) then
                if (text(i:i) /= achar(10)) cycle
            end if
            if (i > n .and. j > n) exit
            k = i - 1
            if (k >= j) then
                if (text(k:k) == achar(13)) k = k - 1
            end if
            call lines%push(text(j:k))
            j = i + 1
        end do
    end subroutine peer_read_lines

end module hertzdamp_peers_scene
