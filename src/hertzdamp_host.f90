!> STUB of the host-scheme module (branch `host` writes the real one): the interface
!> the deck checker codes against (docs: /work/briefs/host.md), with a plain
!> implementation for development only: the discrete collision of the schemes
!> `lammps`, `mfix-euler` and `mfix-ab2` is stepped as written in ENGINES.md and
!> averaged over 512 midpoint phases (no breakpoint handling, so means are good to about
!> 1e-4, not 1e-13).  THE LEAD DROPS THIS FILE when src/hertzdamp_host.f90 lands on main.
module hertzdamp_host
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_OK, HD_BAD_ARGUMENT, HD_NO_CONVERGENCE, HD_MAX_STEPS, HD_DAMPING_TSUJI, &
                                HD_DAMPING_KUWABARA_KONO, HD_END_FORCE
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    integer, parameter, public :: HD_HOST_NONE = 0, HD_HOST_LAMMPS = 1, HD_HOST_MFIX_EULER = 2, &
                                  HD_HOST_MFIX_AB2 = 3, HD_HOST_VERLET = 4, HD_HOST_LAMMPS_PHASE = 5
    integer, parameter :: nphase = 512

    !> Phase statistics of the discrete collision (dimensionless).
    type, public :: hertzdamp_host_stats
        real(wp) :: e_mean = 0.0_wp, e_sd = 0.0_wp, e_min = 0.0_wp, e_max = 0.0_wp
        real(wp) :: tau_mean = 0.0_wp, tau_sd = 0.0_wp, tau_min = 0.0_wp, tau_max = 0.0_wp
    end type hertzdamp_host_stats

    public :: hertzdamp_host_name, hertzdamp_host_mean, hertzdamp_host_alpha_for_e

contains

    !> Name of a host scheme.
    pure function hertzdamp_host_name(host) result(name)
        integer, intent(in) :: host
        character(len=:), allocatable :: name
        select case (host)
        case (HD_HOST_NONE); name = 'none'
        case (HD_HOST_LAMMPS); name = 'lammps'
        case (HD_HOST_MFIX_EULER); name = 'mfix-euler'
        case (HD_HOST_MFIX_AB2); name = 'mfix-ab2'
        case (HD_HOST_VERLET); name = 'verlet'
        case (HD_HOST_LAMMPS_PHASE); name = 'lammps-phase'
        case default; name = '?'
        end select
    end function hertzdamp_host_name

    !> a(z, v) of the law: -(alpha z^q v + z^(3/2)) for z > 0, clipped at 0 with the force end.
    pure real(wp) function accel(z, v, alpha, law, iend) result(a)
        real(wp), intent(in) :: z, v, alpha
        integer, intent(in) :: law, iend
        real(wp) :: zq
        a = 0.0_wp
        if (z <= 0.0_wp) return
        select case (law)
        case (HD_DAMPING_TSUJI); zq = z**0.25_wp
        case (HD_DAMPING_KUWABARA_KONO); zq = sqrt(z)
        case default; zq = 1.0_wp
        end select
        a = -(alpha * zq * v + z * sqrt(z))
        if (iend == HD_END_FORCE) a = min(a, 0.0_wp)
    end function accel

    !> One discrete collision at phase phi: e and the contact time (touch to the last step with overlap).
    pure subroutine collide(alpha, h, phi, law, iend, host, e, tau, status)
        real(wp), intent(in) :: alpha, h, phi
        integer, intent(in) :: law, iend, host
        real(wp), intent(out) :: e, tau
        integer, intent(out) :: status
        real(wp) :: z, v, a, a_old, vnew
        integer :: n, nmax, last
        logical :: touched
        z = (phi - 1.0_wp) * h
        v = 1.0_wp
        a = 0.0_wp
        a_old = 0.0_wp
        touched = .false.
        last = 0
        e = 0.0_wp
        tau = 0.0_wp
        status = HD_MAX_STEPS
        nmax = 200 + int(1000.0_wp / h)
        do n = 1, nmax
            select case (host)
            case (HD_HOST_MFIX_EULER)
                a = accel(z, v, alpha, law, iend)
                v = v + h * a
                z = z + h * v
            case (HD_HOST_MFIX_AB2)
                a = accel(z, v, alpha, law, iend)
                vnew = v + h * (1.5_wp * a - 0.5_wp * a_old)
                a_old = a
                z = z + 0.5_wp * h * (v + vnew)
                v = vnew
            case default
                v = v + 0.5_wp * h * a
                z = z + h * v
                a = accel(z, v, alpha, law, iend)
                v = v + 0.5_wp * h * a
            end select
            if (z > 0.0_wp) then
                touched = .true.
                last = n
            else if (touched .and. v < 0.0_wp .and. (host /= HD_HOST_MFIX_AB2 .or. a_old == 0.0_wp)) then
                e = -v
                tau = (real(last, wp) - 1.0_wp + phi) * h
                status = HD_OK
                return
            end if
        end do
    end subroutine collide

    !> Phase mean, sd, min and max of e (and tau) of the host scheme at h = dt/t*.
    pure subroutine hertzdamp_host_mean(alpha, h, law, iend, host, stats, status)
        real(wp), intent(in) :: alpha, h
        integer, intent(in) :: law, iend, host
        type(hertzdamp_host_stats), intent(out) :: stats
        integer, intent(out) :: status
        real(wp) :: e(nphase), tau(nphase)
        integer :: i, st
        status = HD_OK
        if (.not. (alpha >= 0.0_wp .and. h > 0.0_wp .and. h < 10.0_wp) .or. &
            .not. (host == HD_HOST_LAMMPS .or. host == HD_HOST_MFIX_EULER .or. host == HD_HOST_MFIX_AB2)) then
            status = HD_BAD_ARGUMENT
            return
        end if
        do i = 1, nphase
            call collide(alpha, h, (real(i, wp) - 0.5_wp) / nphase, law, iend, host, e(i), tau(i), st)
            if (st /= HD_OK) then
                status = st
                return
            end if
        end do
        stats%e_mean = sum(e) / nphase
        stats%e_sd = sqrt(max(0.0_wp, sum((e - stats%e_mean)**2) / nphase))
        stats%e_min = minval(e)
        stats%e_max = maxval(e)
        stats%tau_mean = sum(tau) / nphase
        stats%tau_sd = sqrt(max(0.0_wp, sum((tau - stats%tau_mean)**2) / nphase))
        stats%tau_min = minval(tau)
        stats%tau_max = maxval(tau)
    end subroutine hertzdamp_host_mean

    !> The alpha whose phase-mean e equals e at fixed h (bisection on alpha).
    pure subroutine hertzdamp_host_alpha_for_e(e, h, law, iend, host, alpha, stats, status)
        real(wp), intent(in) :: e, h
        integer, intent(in) :: law, iend, host
        real(wp), intent(out) :: alpha
        type(hertzdamp_host_stats), intent(out) :: stats
        integer, intent(out) :: status
        real(wp) :: lo, hi
        integer :: i
        alpha = 0.0_wp
        lo = 0.0_wp
        hi = 1.0_wp
        call hertzdamp_host_mean(hi, h, law, iend, host, stats, status)
        do while (status == HD_OK .and. stats%e_mean > e .and. hi < 1.0e3_wp)
            lo = hi
            hi = 2.0_wp * hi
            call hertzdamp_host_mean(hi, h, law, iend, host, stats, status)
        end do
        if (status /= HD_OK .or. stats%e_mean > e) then
            if (status == HD_OK) status = HD_NO_CONVERGENCE
            return
        end if
        do i = 1, 60
            alpha = 0.5_wp * (lo + hi)
            call hertzdamp_host_mean(alpha, h, law, iend, host, stats, status)
            if (status /= HD_OK) return
            if (stats%e_mean > e) then
                lo = alpha
            else
                hi = alpha
            end if
            if (hi - lo <= 1.0e-13_wp * hi) exit
        end do
        alpha = 0.5_wp * (lo + hi)
        call hertzdamp_host_mean(alpha, h, law, iend, host, stats, status)
    end subroutine hertzdamp_host_alpha_for_e

end module hertzdamp_host
