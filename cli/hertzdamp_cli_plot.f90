!> Plots for the CLI (`bench --plot`, `scene --plot`): checks done before any work,
!> gnuplot run on a script, the PNG written under a temporary name and renamed into
!> place only when gnuplot succeeded.  Errors are one line on stderr (exit 2 for a bad
!> target, 4 when gnuplot is missing or fails); nothing is left half-written.
module hertzdamp_cli_plot
    use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
    use hertzdamp_cli, only: fail, EXIT_USAGE, EXIT_FAILURE
    implicit none
    private
    public :: plot_check_target, plot_run, plot_temp_name, gp_string, sh_quote, remove_file

    interface
        function c_rename(old, new) bind(C, name='rename') result(rc)
            import :: c_int, c_char
            implicit none
            character(kind=c_char), intent(in) :: old(*), new(*)
            integer(c_int) :: rc
        end function c_rename
    end interface

contains

    !> The temporary name the PNG is drawn under.
    function plot_temp_name(file) result(tmp)
        character(len=*), intent(in) :: file
        character(len=:), allocatable :: tmp
        tmp = file // '.hertzdamp-tmp'
    end function plot_temp_name

    !> Before any work: gnuplot exists (else exit 4), the target is not a directory, an
    !> existing target is writable, its directory takes a new file (else exit 2).
    !> Returns the PNG terminal gnuplot offers (pngcairo or png).
    subroutine plot_check_target(file, terminal)
        character(len=*), intent(in) :: file
        character(len=:), allocatable, intent(out) :: terminal
        integer :: es, cs, u, ios
        logical :: exists
        if (len_trim(file) == 0) call fail(EXIT_USAGE, 'option --plot needs a file name')
        es = 1
        cs = 0
        call execute_command_line('command -v gnuplot >/dev/null 2>&1', exitstat=es, cmdstat=cs)
        if (cs /= 0 .or. es /= 0) call fail(EXIT_FAILURE, '--plot needs gnuplot, which was not found ' // &
                                              '(Debian: apt-get install gnuplot-nox)')
        es = 1
        call execute_command_line('gnuplot -e "set terminal pngcairo" >/dev/null 2>&1', exitstat=es, cmdstat=cs)
        terminal = 'png'
        if (cs == 0 .and. es == 0) terminal = 'pngcairo'
        inquire (file=file // '/.', exist=exists)
        if (exists) call fail(EXIT_USAGE, 'the plot file "' // file // '" is a directory')
        inquire (file=file, exist=exists)
        if (exists) then
            ! must be a writable regular file (opening for append writes nothing)
            open (newunit=u, file=file, status='old', action='write', position='append', iostat=ios)
            if (ios /= 0) call fail(EXIT_USAGE, 'cannot write the plot file "' // file // '"')
            close (u)
        end if
        inquire (file=plot_temp_name(file), exist=exists)
        if (exists) call fail(EXIT_USAGE, 'the temporary file "' // plot_temp_name(file) // '" is in the way')
        open (newunit=u, file=plot_temp_name(file), status='new', action='write', iostat=ios)
        if (ios /= 0) call fail(EXIT_USAGE, 'cannot write the plot file "' // file // '" (directory not writable?)')
        close (u, status='delete')
    end subroutine plot_check_target

    !> Run gnuplot on `script` (which draws into plot_temp_name(target)), then rename
    !> the PNG into place.  `scratch` files are removed whatever happens.
    subroutine plot_run(script, png_tmp, target, scratch)
        character(len=*), intent(in) :: script, png_tmp, target
        character(len=*), intent(in) :: scratch(:)
        integer :: es, cs, i
        integer :: sz
        character(len=12) :: buf
        call execute_command_line('gnuplot ' // sh_quote(script) // ' >/dev/null 2>&1', exitstat=es, cmdstat=cs)
        sz = -1
        inquire (file=png_tmp, size=sz)
        call remove_file(script)
        do i = 1, size(scratch)
            call remove_file(trim(scratch(i)))
        end do
        if (cs /= 0 .or. es /= 0 .or. sz <= 0) then
            call remove_file(png_tmp)
            write (buf, '(i0)') es
            call fail(EXIT_FAILURE, 'gnuplot failed (exit ' // trim(buf) // '): no plot written')
        end if
        if (c_rename(c_str(png_tmp), c_str(target)) /= 0) then
            call remove_file(png_tmp)
            call fail(EXIT_FAILURE, 'cannot rename the plot into place: ' // target)
        end if
    end subroutine plot_run

    subroutine remove_file(file)
        character(len=*), intent(in) :: file
        integer :: u, ios
        logical :: exists
        inquire (file=file, exist=exists)
        if (.not. exists) return
        open (newunit=u, file=file, status='old', iostat=ios)
        if (ios == 0) close (u, status='delete')
    end subroutine remove_file

    function c_str(s) result(c)
        character(len=*), intent(in) :: s
        character(kind=c_char) :: c(len(s) + 1)
        integer :: i
        do i = 1, len(s)
            c(i) = s(i:i)
        end do
        c(len(s) + 1) = c_null_char
    end function c_str

    !> A POSIX shell single-quoted word.
    function sh_quote(s) result(r)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: r
        integer :: i
        r = ''''
        do i = 1, len(s)
            if (s(i:i) == '''') then
                r = r // '''\'''''
            else
                r = r // s(i:i)
            end if
        end do
        r = r // ''''
    end function sh_quote

    !> A gnuplot single-quoted string ('' stands for one quote).
    function gp_string(s) result(r)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: r
        integer :: i
        r = ''''
        do i = 1, len(s)
            if (s(i:i) == '''') r = r // ''''
            r = r // s(i:i)
        end do
        r = r // ''''
    end function gp_string

end module hertzdamp_cli_plot
