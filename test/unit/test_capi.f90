!> The C entry points (module hertzdamp_capi, bind(c)) called from Fortran: numbers
!> bit-identical to the module API with the same method, NULL result pointers, and
!> hertzdamp_strerror equal to hertzdamp_message for every code.
program test_capi
    use, intrinsic :: iso_c_binding, only: c_double, c_int, c_char, c_ptr, c_f_pointer, c_associated, &
                                           c_null_char
    use hertzdamp, only: hertzdamp_rk, hertzdamp_invert, hertzdamp_forward_dim, hertzdamp_message, &
                         HD_OK, HD_NO_REBOUND, HD_BAD_ARGUMENT, HD_BAD_RESTITUTION, HD_BAD_END, &
                         HD_END_OVERLAP, HD_END_FORCE, HD_BAD_LAW, HD_BAD_KPHYS, hertzdamp_law_q, HD_METHOD_FIT
    use hertzdamp_capi, only: hertzdamp_c_invert, hertzdamp_c_forward, hertzdamp_c_strerror, hertzdamp_c_invert_law, &
                              hertzdamp_c_pair_law, hertzdamp_c_forward_law
    use hertzdamp_testing, only: test_suite, new_suite
    implicit none

    integer, parameter :: wp = hertzdamp_rk
    type(test_suite) :: suite
    real(c_double) :: k, d, e, tc
    real(wp) :: km, dm, em, tcm, alpha, tstar, zmax
    integer(c_int) :: st
    integer :: stm, i, iend
    real(wp), parameter :: es(3) = [0.95_wp, 0.6_wp, 0.1_wp]
    real(wp), parameter :: ms(3) = [2.0e-3_wp, 1.0_wp, 4.0e-7_wp]
    real(wp), parameter :: us(3) = [0.3_wp, 2.0_wp, 15.0_wp]

    suite = new_suite('test_capi')

    do iend = HD_END_OVERLAP, HD_END_FORCE
        do i = 1, 3
            st = hertzdamp_c_invert(es(i), 1.0e-4_wp, ms(i), us(i), int(iend, c_int), k, d)
            call hertzdamp_invert(es(i), 1.0e-4_wp, ms(i), us(i), iend, km, dm, stm)
            call suite%check(st == HD_OK .and. stm == HD_OK, 'invert status')
            call suite%check(.not. (abs(k - km) > 0.0_wp .or. abs(d - dm) > 0.0_wp), &
                             'invert bit-identical to the module API')
            st = hertzdamp_c_forward(k, d, ms(i), us(i), int(iend, c_int), e, tc)
            call hertzdamp_forward_dim(km, dm, ms(i), us(i), iend, HD_METHOD_FIT, alpha, tstar, em, tcm, zmax, stm)
            call suite%check(st == HD_OK .and. .not. (abs(e - em) > 0.0_wp .or. abs(tc - tcm) > 0.0_wp), &
                             'forward bit-identical to the module API')
            ! the fit's stated round-trip accuracy (doc/accuracy.md: e 8.8e-13, T_c 1.7e-13 at worst)
            call suite%check_close(e, es(i), 1.0e-12_wp, 'round trip e')
            call suite%check_close(tc, 1.0e-4_wp, 1.0e-12_wp, 'round trip tc')
        end do
    end do

    st = hertzdamp_c_invert(1.2_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, 0_c_int, k, d)
    call suite%check(st == HD_BAD_RESTITUTION .and. .not. (abs(k) > 0.0_wp .or. abs(d) > 0.0_wp), &
                     'bad e: status, k = d = 0')
    st = hertzdamp_c_invert(0.5_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, 7_c_int, k, d)
    call suite%check(st == HD_BAD_END, 'bad end: status')
    st = hertzdamp_c_forward(1.0_wp, 2.0_wp, 1.0_wp, 1.0_wp, 0_c_int, e, tc)
    call suite%check(st == HD_NO_REBOUND .and. .not. (abs(e) > 0.0_wp) .and. &
                     .not. (abs(tc - huge(1.0_c_double)) > 0.0_wp), 'no rebound: status 1, e = 0, tc = DBL_MAX')

    ! NULL result pointers (absent optional arguments of the bind(c) procedures)
    st = hertzdamp_c_invert(0.5_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, 0_c_int, k)
    call suite%check(st == HD_BAD_ARGUMENT, 'invert with d = NULL')
    st = hertzdamp_c_forward(1.0_wp, 0.1_wp, 1.0_wp, 1.0_wp, 0_c_int, tc=tc)
    call suite%check(st == HD_BAD_ARGUMENT, 'forward with e = NULL')

    call damping_laws()

    ! every message, including unknown codes, equals hertzdamp_message
    do i = -3, 40
        call suite%check(c_string(hertzdamp_c_strerror(int(i, c_int))) == hertzdamp_message(i), &
                         'strerror equals hertzdamp_message')
    end do

    call suite%finish()

contains

    !> The law entry points: bit-identical to the module API with the law, the round
    !> trip through the forward call, the pair constants with the per-contact formulas,
    !> law 0 = the linear entry points, and the argument checks.
    subroutine damping_laws()
        real(c_double) :: kl, dl, el, tcl, a, t, kb, db, tstar
        real(wp) :: kmm, dmm
        integer :: law, j, stmm
        character(len=24) :: lab
        do law = 0, 2
            do iend = HD_END_OVERLAP, HD_END_FORCE
                write (lab, '(a,i0,a,i0)') ' law ', law, ' end ', iend
                do j = 1, 3
                    st = hertzdamp_c_invert_law(es(j), 1.0e-4_wp, ms(j), us(j), 0.0_wp, int(law, c_int), &
                                                int(iend, c_int), kl, dl)
                    call hertzdamp_invert(es(j), 1.0e-4_wp, ms(j), us(j), iend, kmm, dmm, stmm, &
                                          law=law)
                    call suite%check(st == HD_OK .and. stmm == HD_OK .and. .not. (abs(kl - kmm) > 0.0_wp .or. &
                                     abs(dl - dmm) > 0.0_wp), 'invert_law bit-identical to the module API' // trim(lab))
                    st = hertzdamp_c_forward_law(kl, dl, ms(j), us(j), int(law, c_int), int(iend, c_int), el, tcl)
                    call suite%check_close(el, es(j), 1.0e-12_wp, 'invert_law/forward_law round trip e' // trim(lab))
                    call suite%check_close(tcl, 1.0e-4_wp, 1.0e-12_wp, 'round trip tc' // trim(lab))
                    ! pair constants and the per-contact formulas
                    st = hertzdamp_c_pair_law(es(j), int(law, c_int), int(iend, c_int), a, t)
                    tstar = 1.0e-4_wp / t
                    call suite%check_close(ms(j) * tstar**(-2.5_wp) / sqrt(us(j)), kl, 1.0e-14_wp, &
                                           'pair_law: k = m t*^-5/2 u^-1/2' // trim(lab))
                    call suite%check_close(a * ms(j) / tstar / (us(j) * tstar)**hertzdamp_law_q(law), dl, 1.0e-14_wp, &
                                           'pair_law: d = alpha m t*^-1 (u t*)^-q' // trim(lab))
                    ! a bound far above changes nothing; law 0 is the linear entry point
                    st = hertzdamp_c_invert_law(es(j), 1.0e-4_wp, ms(j), us(j), 1.0e6_wp * kl, int(law, c_int), &
                                                int(iend, c_int), kb, db)
                    call suite%check(st == HD_OK .and. .not. (kb /= kl .or. db /= dl), 'far bound: unchanged' // trim(lab))
                    if (law == 0) then
                        st = hertzdamp_c_invert(es(j), 1.0e-4_wp, ms(j), us(j), int(iend, c_int), kb, db)
                        call suite%check(.not. (kb /= kl .or. db /= dl), 'law 0 = hertzdamp_c_invert')
                    end if
                end do
            end do
        end do
        st = hertzdamp_c_invert_law(0.5_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, 0.0_wp, 3_c_int, 0_c_int, kl, dl)
        call suite%check(st == HD_BAD_LAW .and. .not. (kl /= 0.0_wp .or. dl /= 0.0_wp), 'invert_law: bad law')
        st = hertzdamp_c_invert_law(0.5_wp, 1.0e-4_wp, 1.0_wp, 1.0_wp, -1.0_wp, 1_c_int, 0_c_int, kl, dl)
        call suite%check(st == HD_BAD_KPHYS, 'invert_law: negative k_phys')
        st = hertzdamp_c_pair_law(0.5_wp, 1_c_int, 0_c_int, a)
        call suite%check(st == HD_BAD_ARGUMENT, 'pair_law with tau_c = NULL')
        st = hertzdamp_c_forward_law(1.0_wp, 0.1_wp, 1.0_wp, 1.0_wp, 2_c_int, 0_c_int, tc=tcl)
        call suite%check(st == HD_BAD_ARGUMENT, 'forward_law with e = NULL')
        ! tsuji overlap, alpha = 1.01 sqrt(5) (d = 1.01 sqrt(5 m k)): no rebound
        st = hertzdamp_c_forward_law(1.0e6_wp, 1.01_wp * sqrt(5.0_wp * 1.0e6_wp * 1.0e-3_wp), 1.0e-3_wp, 2.0_wp, 1_c_int, 0_c_int, &
                                     el, tcl)
        call suite%check(st == HD_NO_REBOUND .and. .not. (el /= 0.0_wp) .and. .not. (tcl /= huge(1.0_c_double)), &
                         'forward_law tsuji at alpha_c: no rebound')
    end subroutine damping_laws

    !> The Fortran string of a NUL-terminated C string.
    function c_string(p) result(s)
        type(c_ptr), intent(in) :: p
        character(len=:), allocatable :: s
        character(kind=c_char), pointer :: chars(:)
        integer :: n
        if (.not. c_associated(p)) then
            s = ''
            return
        end if
        call c_f_pointer(p, chars, [1000])
        n = 0
        do while (chars(n + 1) /= c_null_char)
            n = n + 1
            if (n == 1000) exit
        end do
        allocate (character(len=n) :: s)
        s = transfer(chars(1:n), s)
    end function c_string

end program test_capi
