!> Oblique contacts (doc/oblique.md): a glass sphere on a glass wall at 1 m/s, mu = 0.3,
!> e = 0.5, physical and softened 100x in time with the adapted k_t
!> (hertzdamp_tangential_kt), and the per-contact cost of the k_t rule and of the two-sphere
!> normal correction (fast, and with tol = 1e-12 the former full solve) against the bare
!> k, d formula (medians of 7 repeats in one process; the corrections: the mean over the
!> angles 5-85 deg; state the load from `uptime` with the figures); with x_gammat = 1 (the
!> LAMMPS pour deck's mindlin) too, and the corrected e' and e_n per angle there.
!>
!>     fpm run --example oblique_contacts --flag "-O3 -march=x86-64-v2 -funroll-loops -fPIC"
program oblique_contacts
    use, intrinsic :: iso_fortran_env, only: int64
    use hertzdamp, only: hertzdamp_rk, hertzdamp_pi, hertzdamp_oblique_t, hertzdamp_oblique_result, &
                         hertzdamp_oblique_impact, hertzdamp_tangential_kt, hertzdamp_oblique_correct, &
                         hertzdamp_invert, hertzdamp_mindlin_kt, HD_TANGENTIAL_MINDLIN, HD_LEVER_CONTACT
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    real(wp), parameter :: rad = 1.0e-3_wp, rho = 2500.0_wp, ym = 63.0e9_wp, nu = 0.24_wp
    type(hertzdamp_oblique_t) :: c, cs, cf, cw, cx
    type(hertzdamp_oblique_result) :: r, rs
    real(wp) :: m, kphys, kt, k, d, kts, th, un, t(10, 7), acc, et
    integer :: st, i, rep
    integer(int64) :: c0, c1, rate
    character(len=46), parameter :: rows(3:10) = [character(len=46) :: &
        'hertzdamp_oblique_impact (two spheres, 45)', &
        'hertzdamp_oblique_correct, two spheres, mu 0', &
        'hertzdamp_oblique_correct, two spheres, mu 0.3', &
        'hertzdamp_oblique_correct, wall, mu 0.3', &
        ' the same, tol 1e-12 (former), mu 0', &
        ' the same, tol 1e-12 (former), mu 0.3', &
        'hertzdamp_oblique_correct, pair, mu .3, xgt 1', &
        ' the same, tol 1e-12, mu 0.3, x_gammat 1']
    m = rho * 4.0_wp / 3.0_wp * hertzdamp_pi * rad**3
    kphys = 4.0_wp / 3.0_wp * ym / (2.0_wp * (1.0_wp - nu**2)) * sqrt(rad)
    call hertzdamp_mindlin_kt(ym, nu, ym, nu, kt, st)
    print '(a)', 'angle      e_n      e_t (physical)  e_t (100x, adapted k_t)  e_t (100x, physical k_t)'
    do i = 1, 8
        th = 10.0_wp * i
        un = cos(th * hertzdamp_pi / 180.0_wp)
        call hertzdamp_invert(0.5_wp, 1.0e-9_wp, m, un, 0, k, d, st, k_phys=kphys)
        c = hertzdamp_oblique_t(m1=m, r1=rad, k=k, d=d, tangential=HD_TANGENTIAL_MINDLIN, kt=kt, mu=0.3_wp)
        call hertzdamp_oblique_impact(c, 1.0_wp, th, r, st)
        cs = c
        cs%k = k * 100.0_wp**(-2.5_wp)
        cs%d = d / 100.0_wp
        call hertzdamp_tangential_kt(HD_TANGENTIAL_MINDLIN, kt, cs%k, k, kts, st)
        cs%kt = kts
        call hertzdamp_oblique_impact(cs, 1.0_wp, th, rs, st)
        write (*, '(f5.0, f9.5, f12.6, f20.6)', advance='no') th, r%e_n, r%e_t, rs%e_t
        cs%kt = kt
        call hertzdamp_oblique_impact(cs, 1.0_wp, th, rs, st)
        print '(f24.6)', rs%e_t
    end do
    ! cost per contact: each row's mean over its calls, median of 7 repeats, side by side
    acc = 0.0_wp
    call system_clock(count_rate=rate)
    c = hertzdamp_oblique_t(m1=m, r1=rad, m2=m, r2=rad, k=kphys * sqrt(0.5_wp), kt=kt, lever=HD_LEVER_CONTACT)
    cf = c
    cf%mu = 0.3_wp
    cw = hertzdamp_oblique_t(m1=m, r1=rad, k=kphys, kt=kt, mu=0.3_wp)
    cx = cf
    cx%xgammat = 1.0_wp
    ! the correction with x_gammat 1: e' and the e_n of its constants (reference solve)
    print '(a)', 'x_gammat 1, two spheres: angle  status  e''       e_n - e (fast)   e''       e_n - e (tol 1e-12)'
    do i = 0, 8
        th = 10.0_wp * i + 5.0_wp
        write (*, '(f29.0)', advance='no') th
        call hertzdamp_oblique_correct(cx, 0.5_wp, 2.0e-5_wp, 5.0_wp, th, k, d, kts, et, st)
        call corrected_en(st, et)
        call hertzdamp_oblique_correct(cx, 0.5_wp, 2.0e-5_wp, 5.0_wp, th, k, d, kts, et, st, tol=1.0e-12_wp)
        call corrected_en(st, et)
        print '(a)', ''
    end do
    do rep = 1, 7
        call system_clock(c0)
        do i = 1, 100000
            call hertzdamp_invert(0.5_wp, 1.0e-5_wp, m, 1.0_wp + 1.0e-6_wp * i, 0, k, d, st, k_phys=kphys)
            acc = acc + k
        end do
        call system_clock(c1)
        t(1, rep) = real(c1 - c0, wp) / rate / 1.0e5_wp
        call system_clock(c0)
        do i = 1, 100000
            call hertzdamp_invert(0.5_wp, 1.0e-5_wp, m, 1.0_wp + 1.0e-6_wp * i, 0, k, d, st, k_phys=kphys)
            call hertzdamp_tangential_kt(HD_TANGENTIAL_MINDLIN, kt, k, kphys, kts, st)
            acc = acc + k + kts
        end do
        call system_clock(c1)
        t(2, rep) = real(c1 - c0, wp) / rate / 1.0e5_wp
        call system_clock(c0)
        do i = 1, 20
            call hertzdamp_oblique_impact(c, 5.0_wp, 45.0_wp + 1.0e-3_wp * i, r, st)
            acc = acc + r%e_n
        end do
        call system_clock(c1)
        t(3, rep) = real(c1 - c0, wp) / rate / 20.0_wp
        t(4, rep) = correct_time(c, 900, .false.)
        t(5, rep) = correct_time(cf, 900, .false.)
        t(6, rep) = correct_time(cw, 90000, .false.)
        t(7, rep) = correct_time(c, 180, .true.)
        t(8, rep) = correct_time(cf, 180, .true.)
        t(9, rep) = correct_time(cx, 900, .false.)
        t(10, rep) = correct_time(cx, 180, .true.)
    end do
    print '(a)', 'per contact (median of 7)                          time       / bare k, d'
    print '(a, es10.3, a, f10.2)', 'hertzdamp_invert (bare k, d)                  ', median(t(1, :)), ' s', 1.0_wp
    print '(a, es10.3, a, f10.2)', ' + hertzdamp_tangential_kt                    ', median(t(2, :)), ' s', &
        median(t(2, :)) / median(t(1, :))
    do i = 3, 10
        print '(a, es10.3, a, f10.0)', rows(i), median(t(i, :)), ' s', median(t(i, :)) / median(t(1, :))
    end do
    if (.not. acc > 0.0_wp) print '(a)', '(unexpected)'
contains
    !> Write the status, e' and e_n - e of the constants k, d, kts just corrected.
    subroutine corrected_en(stt, ee)
        integer, intent(in) :: stt
        real(wp), intent(in) :: ee
        type(hertzdamp_oblique_t) :: cc
        type(hertzdamp_oblique_result) :: rr
        integer :: s2
        cc = cx
        cc%k = k
        cc%d = d
        cc%kt = kts
        call hertzdamp_oblique_impact(cc, 5.0_wp, th, rr, s2)
        write (*, '(i5, f10.5, es12.2)', advance='no') stt, ee, rr%e_n - 0.5_wp
    end subroutine corrected_en

    !> The mean time of one hertzdamp_oblique_correct of contact cc over ncalls calls at
    !> the angles 5, 15, ..., 85 deg in turn (5 m/s, e = 0.5, T_c = 20 us); with reference,
    !> tol = 1e-12 (reference solves to |e_n - e| <= 1e-10, the former correction).
    real(wp) function correct_time(cc, ncalls, reference) result(tm)
        type(hertzdamp_oblique_t), intent(in) :: cc
        integer, intent(in) :: ncalls
        logical, intent(in) :: reference
        integer(int64) :: a0, a1, rt
        real(wp) :: kk, dd, kk_t, ee, th
        integer :: j, stt
        call system_clock(count_rate=rt)
        call system_clock(a0)
        do j = 1, ncalls
            th = 10.0_wp * mod(j - 1, 9) + 5.0_wp
            if (reference) then
                call hertzdamp_oblique_correct(cc, 0.5_wp, 2.0e-5_wp, 5.0_wp, th, kk, dd, kk_t, ee, stt, tol=1.0e-12_wp)
            else
                call hertzdamp_oblique_correct(cc, 0.5_wp, 2.0e-5_wp, 5.0_wp, th, kk, dd, kk_t, ee, stt)
            end if
            acc = acc + kk
        end do
        call system_clock(a1)
        tm = real(a1 - a0, wp) / rt / ncalls
    end function correct_time

    pure real(wp) function median(x)
        real(wp), intent(in) :: x(:)
        real(wp) :: y(size(x)), v
        integer :: i, j
        y = x
        do i = 2, size(y)
            v = y(i)
            j = i - 1
            do while (j >= 1)
                if (y(j) <= v) exit
                y(j + 1) = y(j)
                j = j - 1
            end do
            y(j + 1) = v
        end do
        median = y((size(y) + 1) / 2)
    end function median
end program oblique_contacts
