!> STUB of module hertzdamp_host (the host branch writes the real src/hertzdamp_host.f90):
!> the interface of the core branch's brief, so that hertzdamp_pair compiles and its
!> tests run before that branch lands.  Drop this file at the merge.
!>
!> The constants it returns for a host other than none are NOT the host-exact ones: a
!> deterministic stand-in (alpha_N = alpha (1 + 1/N), tau_N = tau_c (1 + 1/N)) that lets
!> the per-pair code be exercised; hertzdamp_host_mean returns HD_NOT_SUPPORTED.
module hertzdamp_host
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_OK, HD_BAD_HOST, HD_BAD_STEPS, HD_HOST_UNREACHABLE, HD_NOT_SUPPORTED
    use hertzdamp_fit, only: hertzdamp_fit_inverse
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    integer, parameter, public :: HD_HOST_NONE = 0          !! the continuous model (no host correction)
    integer, parameter, public :: HD_HOST_LAMMPS = 1        !! velocity Verlet of fix nve/sphere (also LIGGGHTS)
    integer, parameter, public :: HD_HOST_MFIX_EULER = 2    !! MFiX DES_INTG_METHOD EULER
    integer, parameter, public :: HD_HOST_MFIX_AB2 = 3      !! MFiX DES_INTG_METHOD ADAMS_BASHFORTH
    integer, parameter, public :: HD_HOST_VERLET = 4        !! the scheme of this repository's scene engine
    integer, parameter, public :: HD_HOST_LAMMPS_PHASE = 5  !! lammps with the plugin's onset correction

    !> Phase statistics of a host's discrete collision (dimensionless).
    type, public :: hertzdamp_host_stats
        real(wp) :: e_mean = 0.0_wp   !! mean achieved e over the onset phase
        real(wp) :: e_sd = 0.0_wp     !! its standard deviation
        real(wp) :: e_min = 0.0_wp    !! smallest achieved e
        real(wp) :: e_max = 0.0_wp    !! largest achieved e
        real(wp) :: tau_mean = 0.0_wp !! mean achieved contact time (units of t*)
        real(wp) :: tau_sd = 0.0_wp   !! its standard deviation
        real(wp) :: tau_min = 0.0_wp  !! shortest
        real(wp) :: tau_max = 0.0_wp  !! longest
    end type hertzdamp_host_stats

    public :: hertzdamp_host_name, hertzdamp_host_solve, hertzdamp_host_min_steps, hertzdamp_host_mean

contains

    !> Name of a host code ('none', 'lammps', ...; 'unknown' for others).
    pure function hertzdamp_host_name(host) result(name)
        integer, intent(in) :: host   !! HD_HOST_*
        character(len=:), allocatable :: name
        select case (host)
        case (HD_HOST_NONE); name = 'none'
        case (HD_HOST_LAMMPS); name = 'lammps'
        case (HD_HOST_MFIX_EULER); name = 'mfix-euler'
        case (HD_HOST_MFIX_AB2); name = 'mfix-ab2'
        case (HD_HOST_VERLET); name = 'verlet'
        case (HD_HOST_LAMMPS_PHASE); name = 'lammps-phase'
        case default; name = 'unknown'
        end select
    end function hertzdamp_host_name

    !> STUB: per-pair constants (see the module note).  N < 3 is unreachable, N < 1 bad.
    pure subroutine hertzdamp_host_solve(e, law, iend, host, steps, alpha, tau_c, stats, status)
        real(wp), intent(in) :: e          !! target restitution
        integer, intent(in) :: law         !! HD_DAMPING_*
        integer, intent(in) :: iend        !! HD_END_*
        integer, intent(in) :: host        !! HD_HOST_*
        real(wp), intent(in) :: steps      !! steps per contact N
        real(wp), intent(out) :: alpha     !! alpha_N
        real(wp), intent(out) :: tau_c     !! tau_N
        type(hertzdamp_host_stats), intent(out) :: stats !! phase statistics at (alpha_N, tau_N / N)
        integer, intent(out) :: status     !! HD_OK or an error
        alpha = 0.0_wp
        tau_c = 0.0_wp
        if (host < HD_HOST_NONE .or. host > HD_HOST_LAMMPS_PHASE) then
            status = HD_BAD_HOST
            return
        end if
        call hertzdamp_fit_inverse(e, iend, alpha, tau_c, status, law)
        if (status /= HD_OK .or. host == HD_HOST_NONE) then
            stats = hertzdamp_host_stats(e, 0.0_wp, e, e, tau_c, 0.0_wp, tau_c, tau_c)
            return
        end if
        if (.not. (steps >= 1.0_wp .and. steps <= huge(steps))) then
            status = HD_BAD_STEPS
        else if (steps < 3.0_wp) then
            status = HD_HOST_UNREACHABLE
        end if
        if (status /= HD_OK) then
            alpha = 0.0_wp
            tau_c = 0.0_wp
            return
        end if
        alpha = alpha * (1.0_wp + 1.0_wp / steps)
        tau_c = tau_c * (1.0_wp + 1.0_wp / steps)
        stats = hertzdamp_host_stats(e, 0.01_wp * e, 0.98_wp * e, 1.02_wp * e, tau_c, 0.01_wp * tau_c, &
                                     0.98_wp * tau_c, 1.02_wp * tau_c)
    end subroutine hertzdamp_host_solve

    !> STUB: the smallest N the stub's solve accepts (3).
    pure subroutine hertzdamp_host_min_steps(e, law, iend, host, n_min, status)
        real(wp), intent(in) :: e          !! target restitution
        integer, intent(in) :: law         !! HD_DAMPING_*
        integer, intent(in) :: iend        !! HD_END_*
        integer, intent(in) :: host        !! HD_HOST_*
        integer, intent(out) :: n_min      !! smallest whole N that reaches e
        integer, intent(out) :: status     !! HD_OK or an error
        real(wp) :: a, t
        n_min = 0
        call hertzdamp_fit_inverse(e, iend, a, t, status, law)
        if (status /= HD_OK) return
        if (host < HD_HOST_NONE .or. host > HD_HOST_LAMMPS_PHASE) then
            status = HD_BAD_HOST
            return
        end if
        n_min = merge(1, 3, host == HD_HOST_NONE)
    end subroutine hertzdamp_host_min_steps

    !> STUB: not available before the host branch lands.
    pure subroutine hertzdamp_host_mean(alpha, h, law, iend, host, stats, status)
        real(wp), intent(in) :: alpha      !! damping parameter
        real(wp), intent(in) :: h          !! dimensionless step dt/t*
        integer, intent(in) :: law         !! HD_DAMPING_*
        integer, intent(in) :: iend        !! HD_END_*
        integer, intent(in) :: host        !! HD_HOST_*
        type(hertzdamp_host_stats), intent(out) :: stats !! phase statistics
        integer, intent(out) :: status     !! HD_NOT_SUPPORTED
        stats = hertzdamp_host_stats()
        status = HD_NOT_SUPPORTED
        if (alpha < 0.0_wp .or. h < 0.0_wp .or. law < 0 .or. iend < 0 .or. host < 0) status = HD_NOT_SUPPORTED
    end subroutine hertzdamp_host_mean

end module hertzdamp_host
