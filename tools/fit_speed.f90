!> Nanoseconds per value of the fit's entry points (tools/fit_speed.sh runs it for two
!> trees side by side): the inverse (dimensionless and dimensional, one value per call and
!> over arrays) for every law at the overlap end, and the forward map of both ends (one
!> value per call with and without the turning point, and over arrays).  Each figure is the
!> median of `rounds` batches over the same 100000 values (e uniform in [0.05, 0.99];
!> alpha uniform in [0, 1.1] (overlap) or [0, 50] (force); T_c, m, u log-uniform).
!> Prints one line per entry point: its name and ns per value.
program fit_speed
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_END_OVERLAP, HD_END_FORCE
    use hertzdamp_fit, only: hertzdamp_fit_inverse, hertzdamp_fit_inverse_n, hertzdamp_fit_invert, &
                             hertzdamp_fit_invert_n, hertzdamp_fit_forward, hertzdamp_fit_forward_n
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    integer, parameter :: wp = hertzdamp_rk, n = 100000, rounds = 15
    real(wp), allocatable :: e(:), tc(:), m(:), u(:), ao(:), af(:)
    real(wp), allocatable :: k(:), d(:), a(:), t(:), z(:), x(:)
    integer, allocatable :: s(:)
    real(wp) :: times(rounds), sink
    character(len=32) :: arg
    integer :: law, r, i

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
    call get_command_argument(1, arg)

    do law = 0, 2
        do r = 1, rounds
            times(r) = now()
            do i = 1, n
                call hertzdamp_fit_inverse(e(i), HD_END_OVERLAP, a(i), t(i), s(i), law)
            end do
            times(r) = now() - times(r)
            sink = sink + a(n)
        end do
        call report('inverse scalar law', law, times)
        do r = 1, rounds
            times(r) = now()
            call hertzdamp_fit_inverse_n(n, e, HD_END_OVERLAP, a, t, s, law)
            times(r) = now() - times(r)
            sink = sink + a(n)
        end do
        call report('inverse_n law', law, times)
        do r = 1, rounds
            times(r) = now()
            do i = 1, n
                call hertzdamp_fit_invert(e(i), tc(i), m(i), u(i), HD_END_OVERLAP, k(i), d(i), a(i), t(i), s(i), law)
            end do
            times(r) = now() - times(r)
            sink = sink + k(n)
        end do
        call report('invert scalar law', law, times)
        do r = 1, rounds
            times(r) = now()
            call hertzdamp_fit_invert_n(n, e, tc, m, u, HD_END_OVERLAP, k, d, a, t, s, law)
            times(r) = now() - times(r)
            sink = sink + k(n)
        end do
        call report('invert_n law', law, times)
    end do
    call forward(HD_END_OVERLAP, ao, 'overlap')
    call forward(HD_END_FORCE, af, 'force')
    if (sink == 42.0_wp) print *, sink

contains

    subroutine forward(iend, al, name)
        integer, intent(in) :: iend
        real(wp), intent(in) :: al(:)
        character(len=*), intent(in) :: name
        do r = 1, rounds
            times(r) = now()
            do i = 1, n
                call hertzdamp_fit_forward(al(i), iend, a(i), t(i), s(i))
            end do
            times(r) = now() - times(r)
            sink = sink + a(n)
        end do
        call report('forward scalar ' // name, -1, times)
        do r = 1, rounds
            times(r) = now()
            do i = 1, n
                call hertzdamp_fit_forward(al(i), iend, a(i), t(i), s(i), z(i), x(i))
            end do
            times(r) = now() - times(r)
            sink = sink + z(n)
        end do
        call report('forward scalar turning ' // name, -1, times)
        do r = 1, rounds
            times(r) = now()
            call hertzdamp_fit_forward_n(n, al, iend, a, t, s)
            times(r) = now() - times(r)
            sink = sink + a(n)
        end do
        call report('forward_n ' // name, -1, times)
        do r = 1, rounds
            times(r) = now()
            call hertzdamp_fit_forward_n(n, al, iend, a, t, s, z, x)
            times(r) = now() - times(r)
            sink = sink + z(n)
        end do
        call report('forward_n turning ' // name, -1, times)
    end subroutine forward

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

    subroutine report(what, law, tm)
        character(len=*), intent(in) :: what
        integer, intent(in) :: law
        real(wp), intent(in) :: tm(:)
        real(wp) :: v(size(tm)), w
        integer :: p, q
        v = tm
        do p = 2, size(v)
            w = v(p)
            q = p - 1
            do while (q >= 1)
                if (v(q) <= w) exit
                v(q + 1) = v(q)
                q = q - 1
            end do
            v(q + 1) = w
        end do
        if (law >= 0) then
            write (*, '(a, 1x, i0, t40, f8.2)') what, law, 1.0e9_wp * v(1) / real(n, wp)
        else
            write (*, '(a, t40, f8.2)') what, 1.0e9_wp * v(1) / real(n, wp)
        end if
    end subroutine report

end program fit_speed
