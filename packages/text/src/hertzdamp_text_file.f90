!> A text file as lines, in time linear in its size: a regular file is read whole in one
!> read; a pipe, a FIFO or a process substitution (`cat deck | ... /dev/stdin`,
!> `<(...)`), whose size the system gives as 0, is read byte by byte until its end.
!> Nothing prints or stops: a file that cannot be read gives a message naming it.  Also
!> the 'file:line' of messages.
module hertzdamp_text_file
    use hertzdamp_text_list, only: text_list
    use hertzdamp_text_format, only: itoa
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    private

    public :: text_read_lines, text_where

contains

    !> The lines of a text file, without their line ends (CR LF as LF).
    subroutine text_read_lines(path, lines, msg, nchar)
        character(len=*), intent(in) :: path                 !! the file
        type(text_list), intent(out) :: lines                !! its lines
        character(len=:), allocatable, intent(out) :: msg    !! '' or why the file cannot be read
        integer(int64), intent(inout) :: nchar               !! characters read, added
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
        if (ios /= 0) then
            msg = path // ': cannot be read'
            return
        end if
        if (n > 0) then
            read (u, iostat=ios) text
        else
            call read_stream(u, text, ios)   ! size 0: an empty file, or a stream of unknown size
            n = len(text)
        end if
        close (u)
        if (ios /= 0) then
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
    end subroutine text_read_lines

    !> Every byte of an open stream until its end (the buffer doubles: linear time).
    subroutine read_stream(u, text, ios)
        integer, intent(in) :: u                               !! the unit, opened for stream access
        character(len=:), allocatable, intent(out) :: text     !! what it holds
        integer, intent(out) :: ios                            !! 0, or the error of a read
        character(len=:), allocatable :: buf, old
        character :: c
        integer :: n
        allocate (character(len=4096) :: buf)
        n = 0
        do
            read (u, iostat=ios) c
            if (ios /= 0) exit
            if (n == len(buf)) then
                call move_alloc(buf, old)
                allocate (character(len=2 * len(old)) :: buf)
                buf(1:n) = old
            end if
            n = n + 1
            buf(n:n) = c
        end do
        if (is_iostat_end(ios)) ios = 0
        text = buf(1:n)
    end subroutine read_stream

    !> 'file:line', where a line of a file is named.
    pure function text_where(file, line) result(s)
        character(len=*), intent(in) :: file   !! the file
        integer, intent(in) :: line            !! the line
        character(len=:), allocatable :: s
        s = file // ':' // itoa(line)
    end function text_where

end module hertzdamp_text_file
