!> Accuracy of the truncated series and of Pade summation against the reference
!> integrator: maximum relative error of e and tau_c over alpha in [0, A] for
!> A = 0.3, 0.6, 1.0 (the table in README.md).  Run: fpm run --example series_accuracy
program series_accuracy
    use hertzdamp
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: orders(6) = [1, 2, 3, 5, 10, 20], npts = 101
    real(wp), parameter :: amax(3) = [0.3_wp, 0.6_wp, 1.0_wp]
    real(wp) :: alpha(npts), e, tc, zm, tm, err(3, 2)
    type(hertzdamp_collision) :: ref(npts)
    integer :: i, j, k, st
    character(len=16) :: cells(3, 2)
    character(len=16) :: name

    do i = 1, npts
        alpha(i) = 0.99_wp * real(i - 1, wp) / real(npts - 1, wp)   ! |alpha| < 1 for the series
    end do
    alpha(npts) = 0.999_wp
    ref = hertzdamp_rk45_collide(alpha, tol=1.0e-14_wp)
    print '(a)', '| method | [0, 0.3] e | [0, 0.3] τ_c | [0, 0.6] e | [0, 0.6] τ_c | [0, 1.0) e | [0, 1.0) τ_c |'
    print '(a)', '|---|---|---|---|---|---|---|'
    do k = 1, size(orders)
        err = 0.0_wp
        do i = 1, npts
            call hertzdamp_series_eval(alpha(i), e, tc, zm, tm, order=orders(k), status=st)
            do j = 1, 3
                if (alpha(i) <= amax(j)) err(j, :) = max(err(j, :), [abs(e / ref(i)%e - 1), abs(tc / ref(i)%tau_c - 1)])
            end do
        end do
        call cellfmt(err, cells)
        write (name, '(a,i0)') 'series N=', orders(k)
        call print_row(trim(name), cells)
    end do
    err = 0.0_wp
    do i = 1, npts
        call hertzdamp_pade_eval(alpha(i), e, tc, zm, tm, status=st)
        if (st /= HD_OK) cycle
        do j = 1, 3
            if (alpha(i) <= amax(j)) err(j, :) = max(err(j, :), [abs(e / ref(i)%e - 1), abs(tc / ref(i)%tau_c - 1)])
        end do
    end do
    call cellfmt(err, cells)
    cells(3, :) = 'n/a (> 0.8)'
    call print_row('Padé', cells)

contains

    !> One markdown row: | name | e | tau_c | e | tau_c | e | tau_c |
    subroutine print_row(label, cells)
        character(len=*), intent(in) :: label
        character(len=16), intent(in) :: cells(3, 2)
        character(len=:), allocatable :: line
        integer :: a
        line = '| ' // label
        do a = 1, 3
            line = line // ' | ' // trim(adjustl(cells(a, 1))) // ' | ' // trim(adjustl(cells(a, 2)))
        end do
        print '(a)', line // ' |'
    end subroutine print_row

    subroutine cellfmt(err, cells)
        real(wp), intent(in) :: err(3, 2)
        character(len=16), intent(out) :: cells(3, 2)
        integer :: a, b
        do a = 1, 3
            do b = 1, 2
                write (cells(a, b), '(es9.1)') err(a, b)
            end do
        end do
    end subroutine cellfmt

end program series_accuracy
