!> Plausibility warnings: a material value or an impact speed that is valid but far
!> outside what granular materials have is most often a unit slip (`--youngs-modulus
!> 63` meant in GPa, `--radius 1` in mm).  One line on stderr per such option, naming
!> the option, the range and the likely slip; the results are still computed and
!> printed and the exit code is unchanged.  `--quiet` silences them.
!>
!>     option                      plausible range      likely slip below / above
!>     --youngs-modulus[2]  E      1e5 to 1e13 Pa       GPa, MPa / -
!>     --radius[2]          R      1e-7 to below 1 m    - / mm, micrometres
!>     --density[2]         rho    10 to 3e4 kg/m^3     g/cm^3 / g/m^3
!>     --velocity           u      up to 1e3 m/s        - / mm/s
!>
!> Interface: list `quiet_flag` among the command's flags and call
!> `warn_implausible(args)` once its options are parsed (bad values have exited
!> already); `warn_value` checks one value from elsewhere (a data file).
module hertzdamp_cli_plausible
    use hertzdamp, only: hertzdamp_rk
    use hertzdamp_cli, only: cli_args, parse_real, parse_sweep, error_line
    use hertzdamp_cli_text, only: fmt_short, itoa
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> The flag that silences the warnings.
    character(len=*), parameter, public :: quiet_flag = '--quiet'

    !> One kind of quantity: its plausible range and the unit slips that explain a
    !> value below or above it (a factor to SI and the unit's name, first match wins).
    type :: quantity
        character(len=:), allocatable :: unit       !! SI unit, for the message
        real(wp) :: lo = 0.0_wp, hi = 0.0_wp        !! plausible range [lo, hi] (hi excluded when open_hi)
        logical :: open_hi = .false.
        character(len=:), allocatable :: what_lo, what_hi   !! what lies beyond each end
        real(wp), allocatable :: f_lo(:), f_hi(:)   !! factors to SI of the slips below, above
        character(len=16), allocatable :: u_lo(:), u_hi(:)  !! their unit names
    end type quantity

    public :: warn_implausible, warn_value

contains

    !> The quantity an option gives ('' when it is none of these).
    function quantity_of(key) result(q)
        character(len=*), intent(in) :: key
        type(quantity) :: q
        select case (key)
        case ('--youngs-modulus', '--youngs-modulus2')
            q = quantity('Pa', 1.0e5_wp, 1.0e13_wp, .false., 'softer than granular materials (rubber: 1e6 Pa)', &
                         'stiffer than any solid (diamond: 1.2e12 Pa)', [1.0e9_wp, 1.0e6_wp], [real(wp) ::], &
                         [character(len=16) :: 'GPa', 'MPa'], [character(len=16) ::])
        case ('--radius', '--radius2')
            q = quantity('m', 1.0e-7_wp, 1.0_wp, .true., 'smaller than DEM particles (0.1 micrometre)', &
                         'a particle 2 m or more across', [real(wp) ::], [1.0e-3_wp, 1.0e-6_wp], &
                         [character(len=16) ::], [character(len=16) :: 'mm', 'micrometres'])
        case ('--density', '--density2')
            q = quantity('kg/m^3', 10.0_wp, 3.0e4_wp, .false., 'lighter than granular materials (aerogel: 10 kg/m^3)', &
                         'denser than any solid (osmium: 2.26e4 kg/m^3)', [1.0e3_wp], [1.0e-3_wp], &
                         [character(len=16) :: 'g/cm^3'], [character(len=16) :: 'g/m^3'])
        case ('--velocity')
            q = quantity('m/s', 0.0_wp, 1.0e3_wp, .false., '', 'faster than granular impacts', [real(wp) ::], &
                         [1.0e-3_wp], [character(len=16) ::], [character(len=16) :: 'mm/s'])
        case default
            q%unit = ''
        end select
    end function quantity_of

    !> Warn (stderr) about every implausible material option and the fastest impact
    !> speed of the command line, unless --quiet is given.
    subroutine warn_implausible(args)
        type(cli_args), intent(in) :: args
        character(len=*), parameter :: keys(7) = [character(len=17) :: '--youngs-modulus', '--youngs-modulus2', &
                                                  '--radius', '--radius2', '--density', '--density2', '--velocity']
        real(wp), allocatable :: u(:)
        integer :: i
        if (args%has(quiet_flag)) return
        do i = 1, size(keys)
            if (.not. args%has(trim(keys(i)))) cycle
            if (trim(keys(i)) == '--velocity') then
                u = parse_sweep(args%get('--velocity', ''), '--velocity')
                if (size(u) == 0) cycle
                call warn_value(trim(keys(i)), maxval(u), fmt_short(maxval(u)), .false., typed=.false.)
            else
                call warn_value(trim(keys(i)), parse_real(args%get(trim(keys(i)), ''), trim(keys(i))), &
                                args%get(trim(keys(i)), ''), .false.)
            end if
        end do
    end subroutine warn_implausible

    !> Warn (stderr) when `x`, given as `text` for option or column `key`, lies outside
    !> the plausible range of its quantity (nothing when `quiet`, or for other keys).
    subroutine warn_value(key, x, text, quiet, typed, name)
        character(len=*), intent(in) :: key    !! the option whose quantity the value is (--radius)
        real(wp), intent(in) :: x              !! the value, SI
        character(len=*), intent(in) :: text   !! the value as given
        logical, intent(in) :: quiet           !! --quiet was given
        logical, intent(in), optional :: typed !! text is what the user typed (default): the guess appends to it
        character(len=*), intent(in), optional :: name  !! what the message names instead of the option
        type(quantity) :: q
        character(len=:), allocatable :: s, t, who
        ! an invalid value (<= 0, NaN) is the commands' error, not a warning
        if (quiet .or. .not. x > 0.0_wp) return
        who = key
        if (present(name)) who = name
        t = text
        if (present(typed)) then
            if (.not. typed) t = ''
        end if
        q = quantity_of(key)
        if (len(q%unit) == 0) return
        if (x < q%lo) then
            s = who // ' ' // text // ': below ' // bound(q%lo) // ' ' // q%unit // ', ' // q%what_lo // &
                slip(x, t, q%f_lo, q%u_lo, q)
        else if (x > q%hi .or. (q%open_hi .and. x >= q%hi)) then
            s = who // ' ' // text // ': ' // trim(merge('at or above', 'above      ', q%open_hi)) // ' ' // &
                bound(q%hi) // ' ' // q%unit // ', ' // q%what_hi // slip(x, t, q%f_hi, q%u_hi, q)
        else
            return
        end if
        call error_line('warning: ' // s // ' (--quiet silences this)')
    end subroutine warn_value

    !> A bound as the table above writes it: 10, 1, 1e-7, 1e3, 3e4, 1e13.
    function bound(x) result(s)
        real(wp), intent(in) :: x
        character(len=:), allocatable :: s
        integer :: ex
        s = fmt_short(x)
        if (x < 100.0_wp) return
        ex = floor(log10(x) + 1.0e-9_wp)
        s = fmt_short(x / 10.0_wp**ex) // 'e' // itoa(ex)
    end function bound

    !> '; it looks like GPa: did you mean 63e9?' for the first unit whose factor
    !> brings `x` into the plausible range, '' when none does.
    function slip(x, text, f, names, q) result(s)
        real(wp), intent(in) :: x
        character(len=*), intent(in) :: text
        real(wp), intent(in) :: f(:)
        character(len=*), intent(in) :: names(:)
        type(quantity), intent(in) :: q
        character(len=:), allocatable :: s
        integer :: i
        s = ''
        do i = 1, size(f)
            if (.not. (x * f(i) >= q%lo .and. (x * f(i) < q%hi .or. (.not. q%open_hi .and. x * f(i) <= q%hi)))) cycle
            s = '; it looks like ' // trim(names(i)) // ': did you mean ' // scaled(x, text, f(i)) // '?'
            return
        end do
    end function slip

    !> x f as the user would type it: the typed plain decimal with the factor's
    !> exponent appended (63 -> 63e9, 1 -> 1e-3), else the number.
    function scaled(x, text, f) result(s)
        real(wp), intent(in) :: x, f
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: s
        if (len_trim(text) > 0 .and. scan(text, 'eE,:') == 0) then
            s = trim(adjustl(text)) // 'e' // itoa(nint(log10(f)))
        else
            s = fmt_short(x * f)
        end if
    end function scaled

end module hertzdamp_cli_plausible
