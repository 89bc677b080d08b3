!> `hertzdamp`: the command-line front end.  Parsing and printing only; every number
!> comes from the library.  One dispatch line per command.
program main
    use hertzdamp_cli, only: fail, cli_start, did_you_mean, EXIT_USAGE
    use hertzdamp_cli_help, only: print_help
    use hertzdamp_cmd_basic, only: cmd_table, cmd_forward, cmd_constants
    use hertzdamp_cmd_invert, only: cmd_invert, cmd_timestep
    use hertzdamp_cmd_scene, only: cmd_scene
    use hertzdamp_cmd_bench, only: cmd_bench
    use hertzdamp_cmd_check, only: cmd_check
    use hertzdamp_cmd_calibrate, only: cmd_calibrate
    use hertzdamp_cmd_oblique, only: cmd_oblique
    implicit none
    character(len=:), allocatable :: command
    integer :: l

    call cli_start()
    if (command_argument_count() == 0) call print_help('')
    call get_command_argument(1, length=l)
    allocate (character(len=l) :: command)
    call get_command_argument(1, command)
    select case (command)
    case ('--help', '-h', 'help'); call print_help('')
    case ('--version', 'version'); call print_help('version')
    case ('table'); call cmd_table()
    case ('forward'); call cmd_forward()
    case ('constants'); call cmd_constants()
    case ('invert'); call cmd_invert()
    case ('timestep'); call cmd_timestep()
    case ('bench'); call cmd_bench()
    case ('scene'); call cmd_scene()
    case ('check'); call cmd_check()
    case ('calibrate'); call cmd_calibrate()
    case ('oblique'); call cmd_oblique()
    case default
        call fail(EXIT_USAGE, 'unknown command "' // command // '"' // did_you_mean(command, 'invert forward ' // &
                  'timestep table constants bench scene check calibrate oblique help version --help --version') // &
                  ' (see hertzdamp --help)')
    end select
end program main
