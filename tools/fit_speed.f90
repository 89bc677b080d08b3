!> Nanoseconds per value of the fit's entry points (tools/fit_speed.sh runs it for two
!> trees side by side): the inverse (the fit's alpha, tau_c and hertzdamp_invert's k, d, one
!> value per call and over arrays) for every law at the overlap end, and the forward map of both ends (one
!> value per call with and without the turning point, and over arrays).  Each figure is the
!> shortest of `rounds` batches (the least disturbed by other jobs on a shared machine)
!> over the same 100000 values (e uniform in [0.05, 0.99]; alpha uniform in [0, 1.1]
!> (overlap) or [0, 50] (force); T_c, m, u log-uniform).
!> Prints one line per entry point: its name and ns per value.
program fit_speed
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: HD_END_OVERLAP, HD_END_FORCE
    use hertzdamp_fit, only: hertzdamp_fit_inverse, hertzdamp_fit_inverse_n, hertzdamp_fit_forward, &
                             hertzdamp_fit_forward_n
    use hertzdamp_pair, only: hertzdamp_invert
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    integer, parameter :: wp = hertzdamp_rk, n = 100000, rounds = 15
    !> the entry points, in the order printed
    character(len=*), parameter :: names(8) = [character(len=24) :: 'inverse scalar law', 'inverse_n law', &
        'invert scalar law', 'invert array law', 'forward scalar', 'forward scalar turning', 'forward_n', &
        'forward_n turning']
    real(wp), allocatable :: e(:), tc(:), m(:), u(:), ao(:), af(:)
    real(wp), allocatable :: k(:), d(:), a(:), t(:), z(:), x(:)
    integer, allocatable :: s(:)
    real(wp) :: sink
    integer :: law, i, ep

    allocate (e(n), tc(n), m(n), u(n), ao(n), af(n), k(n), d(n), a(n), t(n), z(n), x(n), s(n))
    do i = 1, n
        e(i) = 0.05_wp + 0.94_wp * frac(i, 1)
        tc(i) = 10.0_wp**(-7.0_wp + 4.0_wp * frac(i, 2))
        m(i) = 10.0_wp**(-9.0_wp + 9.0_wp * frac(i, 3))
        u(i) = 10.0_wp**(-3.0_wp + 4.0_wp * frac(i, 4))
        ao(i) = 1.1_wp * frac(i, 5)
        af(i) = 50.0_wp * frac(i, 6)
    end do
    sink = 0.0_wp
    do law = 0, 2
        do ep = 1, 4
            write (*, '(a, 1x, i0, t40, f8.2)') trim(names(ep)), law, best(ep, law, HD_END_OVERLAP, ao)
        end do
    end do
    do ep = 5, 8
        write (*, '(a, t40, f8.2)') trim(names(ep)) // ' overlap', best(ep, 0, HD_END_OVERLAP, ao)
    end do
    do ep = 5, 8
        write (*, '(a, t40, f8.2)') trim(names(ep)) // ' force', best(ep, 0, HD_END_FORCE, af)
    end do
    if (sink == 42.0_wp) print *, sink

contains

    !> ns per value of an entry point: the shortest of `rounds` batches over the n values.
    real(wp) function best(ep, law, iend, al)
        integer, intent(in) :: ep, law, iend
        real(wp), intent(in) :: al(:)
        real(wp) :: times(rounds)
        integer :: r
        do r = 1, rounds
            times(r) = now()
            call batch(ep, law, iend, al)
            times(r) = now() - times(r)
            sink = sink + a(n) + k(n) + z(n)
        end do
        best = 1.0e9_wp * minval(times) / real(n, wp)
    end function best

    !> One batch of an entry point over the n values.
    subroutine batch(ep, law, iend, al)
        integer, intent(in) :: ep, law, iend
        real(wp), intent(in) :: al(:)
        integer :: i
        select case (ep)
        case (1)
            do i = 1, n
                call hertzdamp_fit_inverse(e(i), iend, a(i), t(i), s(i), law)
            end do
        case (2)
            call hertzdamp_fit_inverse_n(n, e, iend, a, t, s, law)
        case (3)
            do i = 1, n
                call hertzdamp_invert(e(i), tc(i), m(i), u(i), iend, k(i), d(i), s(i), law=law)
            end do
        case (4)
            call hertzdamp_invert(e, tc, m, u, iend, k, d, s, law=law)
        case (5)
            do i = 1, n
                call hertzdamp_fit_forward(al(i), iend, a(i), t(i), s(i))
            end do
        case (6)
            do i = 1, n
                call hertzdamp_fit_forward(al(i), iend, a(i), t(i), s(i), z(i), x(i))
            end do
        case (7)
            call hertzdamp_fit_forward_n(n, al, iend, a, t, s)
        case default
            call hertzdamp_fit_forward_n(n, al, iend, a, t, s, z, x)
        end select
    end subroutine batch

    !> A number in [0, 1) from a fixed integer hash of (i, k).
    real(wp) function frac(i, k)
        integer, intent(in) :: i, k
        integer(int64) :: h
        h = int(i, int64) * 2654435761_int64 + int(k, int64) * 40503_int64
        h = iand(ieor(h, shiftr(h, 13)) * 1274126177_int64, int(z'7FFFFFFF', int64))
        frac = real(h, wp) / 2147483648.0_wp
    end function frac

    real(wp) function now()
        integer(int64) :: c, rate
        call system_clock(c, rate)
        now = real(c, wp) / real(rate, wp)
    end function now

end program fit_speed
