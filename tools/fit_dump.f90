!> Bit dump of every public result of the fit (tools/fit_bits.sh compiles it against two
!> trees and compares the dumps): hertzdamp_fit_inverse(_n),
!> hertzdamp_fit_forward(_n), hertzdamp_fit_e, _tau_c, _alpha, _tau_c_of_e, the arithmetic
!> kernels and the maps of hertzdamp_fit_laws, for every law and contact end (and invalid
!> ones), scalar and array, on dense grids with the edges: piece boundaries and the ends
!> of the fitted and direct ranges (and one ulp either side), 0, -0, NaN, +-inf,
!> negatives, subnormals, huge.  Also the reference integrator (hertzdamp_rk45_solve with
!> its statistics, hertzdamp_alpha_c) on a grid of alpha, every law, end and three
!> tolerances.  One line per input: a tag, the index, the outputs' bits in hexadecimal.
!> Writes to the file named by its first argument.
program fit_dump
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: HD_END_OVERLAP, HD_END_FORCE
    use hertzdamp_fit, only: hertzdamp_fit_inverse, hertzdamp_fit_inverse_n, &
                             hertzdamp_fit_forward, hertzdamp_fit_forward_n, hertzdamp_fit_e, &
                             hertzdamp_fit_tau_c, hertzdamp_fit_alpha, hertzdamp_fit_tau_c_of_e, hertzdamp_fit_neg_log, &
                             hertzdamp_fit_cbrt, hertzdamp_fit_exp_neg, hertzdamp_fit_root5, hertzdamp_fit_alpha_c, &
                             hertzdamp_fit_alpha_max_force, hertzdamp_fit_e_min_overlap, hertzdamp_fit_e_min_force, &
                             hertzdamp_approx_alpha_status
    use hertzdamp_rk45, only: hertzdamp_rk45_solve, hertzdamp_rk45_options, hertzdamp_collision, hertzdamp_alpha_c, &
                              hertzdamp_rk45_tolerances
    use hertzdamp_fit_laws, only: hertzdamp_fit_law_inverse, hertzdamp_fit_law_forward, hertzdamp_fit_law_e_min, &
                                  hertzdamp_fit_forward_deriv
    use hertzdamp_fit_data, only: fit_inv_x0, fit_inv_x1, fit_inv_np, fit_fwd_x0, fit_fwd_x1, fit_fwd_np, fit_turn_x0, &
                                  fit_turn_x1, fit_turn_np, fit_linv_x0, fit_linv_x1, fit_linv_np, fit_one_x0, &
                                  fit_one_x1, fit_one_np, fit_map_ov_fwd_w, fit_law_e_min
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, ieee_negative_inf
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    integer, parameter :: ends(3) = [HD_END_OVERLAP, HD_END_FORCE, 7], laws(5) = [0, 1, 2, -1, 3]
    real(wp), allocatable :: es(:), as(:), xs(:)
    real(wp) :: nan, inf, specials(18)
    character(len=4096) :: path
    integer :: out, ie, il

    call get_command_argument(1, path)
    open (newunit=out, file=trim(path), status='replace', action='write')
    nan = ieee_value(1.0_wp, ieee_quiet_nan)
    inf = ieee_value(1.0_wp, ieee_positive_inf)
    specials = [0.0_wp, -0.0_wp, nan, -nan, inf, ieee_value(1.0_wp, ieee_negative_inf), tiny(1.0_wp), &
                1.0e-310_wp, 4.9e-324_wp, -1.0e-310_wp, huge(1.0_wp), -huge(1.0_wp), -1.0_wp, -1.0e-300_wp, &
                1.0e-300_wp, 2.0_wp, 1.0e300_wp, -0.5_wp]

    call build_e_grid(es)
    call build_alpha_grid(as)
    call build_x_grid(xs)

    call dump_arithmetic(xs)
    ! valid ends and laws on the whole grids, invalid ones on every 41st value
    do ie = 1, size(ends)
        do il = 1, size(laws)
            if (ie <= 2 .and. il <= 3) then
                call dump_inverse(es, ends(ie), laws(il))
                call dump_law_forward(as, ends(ie), laws(il))
            else
                call dump_inverse(es(::41), ends(ie), laws(il))
                call dump_law_forward(as(::41), ends(ie), laws(il))
            end if
        end do
        call dump_rk45(ends(ie))
        if (ie <= 2) then
            call dump_linear_inverse(es, ends(ie))
            call dump_forward(as, ends(ie))
        else
            call dump_linear_inverse(es(::41), ends(ie))
            call dump_forward(as(::41), ends(ie))
        end if
    end do
    close (out)

contains

    !> x and its neighbours k ulps away, k = -2 .. 2.
    subroutine add_ulps(v, x)
        real(wp), allocatable, intent(inout) :: v(:)
        real(wp), intent(in) :: x
        integer(int64) :: b
        integer :: k
        b = transfer(x, 0_int64)
        do k = -2, 2
            v = [v, transfer(b + k, 1.0_wp)]
        end do
    end subroutine add_ulps

    !> Restitution coefficients: a uniform grid beyond [0, 1], a logarithmic one, the ends
    !> of the ranges and the piece boundaries of every inverse map (in e), with their ulps.
    subroutine build_e_grid(v)
        real(wp), allocatable, intent(out) :: v(:)
        integer :: i, j
        v = [(real(i, wp) / 20000.0_wp, i = -3, 20003)]
        v = [v, (10.0_wp**(-8.0_wp + 8.0_wp * real(i, wp) / 8000.0_wp), i = 0, 8000)]
        v = [v, specials]
        call add_ulps(v, 1.0_wp)
        call add_ulps(v, hertzdamp_fit_e_min_overlap)
        call add_ulps(v, hertzdamp_fit_e_min_force)
        call add_ulps(v, fit_law_e_min)
        call add_ulps(v, 0.5_wp)
        ! inverse maps of L (overlap, kuwabara-kono overlap, tsuji), of L^(1/3), L^(1/2), L^(1/5)
        do j = 1, size(fit_inv_np)
            do i = 0, fit_inv_np(j)
                call add_ulps(v, exp(-piece_end(fit_inv_x0(j), fit_inv_x1(j), fit_inv_np(j), i)**merge(1, 3, j == 1)))
            end do
        end do
        do j = 1, size(fit_linv_np)
            do i = 0, fit_linv_np(j)
                call add_ulps(v, exp(-piece_end(fit_linv_x0(j), fit_linv_x1(j), fit_linv_np(j), i)**merge(1, 2, j == 1)))
            end do
        end do
        do j = 1, size(fit_one_np)
            do i = 0, fit_one_np(j)
                call add_ulps(v, exp(-piece_end(fit_one_x0(j), fit_one_x1(j), fit_one_np(j), i)**merge(1, 5, j < 3)))
            end do
        end do
    end subroutine build_e_grid

    !> Damping parameters: uniform grids over the overlap and force ranges, a logarithmic
    !> grid over 1e-300 .. 1e300, the ends of the ranges and the piece boundaries of every
    !> forward and turning-point map (in alpha), with their ulps.
    subroutine build_alpha_grid(v)
        real(wp), allocatable, intent(out) :: v(:)
        integer :: i, j
        v = [(real(i, wp) * 1.0e-4_wp, i = -2, 13002)]
        v = [v, (real(i, wp) * 5.0e-3_wp, i = 0, 12001)]
        v = [v, (10.0_wp**(-300.0_wp + 600.0_wp * real(i, wp) / 6000.0_wp), i = 0, 6000)]
        v = [v, (real(i, wp) * 0.5_wp, i = 0, 2500)]
        v = [v, specials]
        call add_ulps(v, 0.0_wp)
        call add_ulps(v, hertzdamp_fit_alpha_c)
        call add_ulps(v, hertzdamp_fit_alpha_max_force)
        call add_ulps(v, sqrt(5.0_wp))
        call add_ulps(v, 0.6_wp)
        call add_ulps(v, 1.3_wp)
        ! w = -ln(1 - alpha/alpha_c) at the end of its map
        call add_ulps(v, hertzdamp_fit_alpha_c * (1.0_wp - exp(-fit_fwd_x1(fit_map_ov_fwd_w))))
        do j = 1, size(fit_fwd_np)
            do i = 0, fit_fwd_np(j)
                call add_ulps(v, piece_end(fit_fwd_x0(j), fit_fwd_x1(j), fit_fwd_np(j), i))
                call add_ulps(v, piece_end(fit_fwd_x0(j), fit_fwd_x1(j), fit_fwd_np(j), i)**3)
                call add_ulps(v, hertzdamp_fit_alpha_c * (1.0_wp - exp(-piece_end(fit_fwd_x0(j), fit_fwd_x1(j), &
                                                                                   fit_fwd_np(j), i))))
                call add_ulps(v, (exp(piece_end(fit_fwd_x0(j), fit_fwd_x1(j), fit_fwd_np(j), i)) - 1.0_wp)**2)
            end do
        end do
        do j = 1, size(fit_turn_np)
            do i = 0, fit_turn_np(j)
                call add_ulps(v, piece_end(fit_turn_x0(j), fit_turn_x1(j), fit_turn_np(j), i))
                call add_ulps(v, piece_end(fit_turn_x0(j), fit_turn_x1(j), fit_turn_np(j), i)**3)
                call add_ulps(v, piece_end(fit_turn_x0(j), fit_turn_x1(j), fit_turn_np(j), i)**5)
                call add_ulps(v, (exp(piece_end(fit_turn_x0(j), fit_turn_x1(j), fit_turn_np(j), i)) - 1.0_wp)**2)
            end do
        end do
    end subroutine build_alpha_grid

    !> Arguments of the arithmetic kernels: logarithmic grids over the whole positive
    !> range, a uniform one over [0, 800], the specials.
    subroutine build_x_grid(v)
        real(wp), allocatable, intent(out) :: v(:)
        integer :: i
        v = [(10.0_wp**(-307.0_wp + 614.0_wp * real(i, wp) / 30000.0_wp), i = 0, 30000)]
        v = [v, (real(i, wp) * 0.02_wp, i = 0, 40000)]
        v = [v, (1.0_wp + real(i, wp) * 2.0_wp**(-20), i = -3000, 3000)]
        v = [v, specials]
        do i = -1074, 1023, 7
            call add_ulps(v, 2.0_wp**i)
        end do
    end subroutine build_x_grid

    real(wp) function piece_end(x0, x1, np, i)
        real(wp), intent(in) :: x0, x1
        integer, intent(in) :: np, i
        piece_end = x0 + (x1 - x0) * real(i, wp) / real(np, wp)
    end function piece_end

    subroutine put(tag, i, r, s)
        character(len=*), intent(in) :: tag
        integer, intent(in) :: i
        real(wp), intent(in) :: r(:)
        integer, intent(in) :: s(:)
        write (out, '(a, 1x, i0, *(1x, z16.16))') tag, i, transfer(r, 0_int64, size(r)), int(s, int64)
    end subroutine put

    subroutine dump_arithmetic(x)
        real(wp), intent(in) :: x(:)
        integer :: i
        real(wp) :: l
        do i = 1, size(x)
            ! each kernel on its documented domain (positive normal, or 0; exp_neg on [0, 700])
            if (x(i) >= tiny(1.0_wp) .and. x(i) <= huge(1.0_wp)) then
                call put('neg_log', i, [hertzdamp_fit_neg_log(x(i))], [integer ::])
            end if
            if (x(i) == 0.0_wp .or. (x(i) >= tiny(1.0_wp) .and. x(i) <= huge(1.0_wp))) then
                call put('cbrt', i, [hertzdamp_fit_cbrt(x(i)), hertzdamp_fit_root5(x(i))], [integer ::])
            end if
            l = x(i)
            if (l >= 0.0_wp .and. l <= 700.0_wp) call put('exp_neg', i, [hertzdamp_fit_exp_neg(l)], [integer ::])
        end do
        ! elemental on an array against the scalar calls above
        call put('neg_log_array', 0, hertzdamp_fit_neg_log(pack(x, x >= tiny(1.0_wp) .and. x <= huge(1.0_wp))), &
                 [integer ::])
        call put('cbrt_array', 0, hertzdamp_fit_cbrt(pack(x, x >= tiny(1.0_wp) .and. x <= huge(1.0_wp))), [integer ::])
        call put('root5_array', 0, hertzdamp_fit_root5(pack(x, x >= tiny(1.0_wp) .and. x <= huge(1.0_wp))), &
                 [integer ::])
        call put('exp_neg_array', 0, hertzdamp_fit_exp_neg(pack(x, x >= 0.0_wp .and. x <= 700.0_wp)), [integer ::])
    end subroutine dump_arithmetic

    !> The reference integrator: every law (and invalid ones) at alpha on a grid over
    !> [-12, 1e3] with the edges (0, +-0, alpha_c, sqrt(5), NaN, inf, the range limits),
    !> tolerances 1e-6, 1e-10, 1e-13: e, tau_c, z_max, tau_max, status and the work done;
    !> then alpha_c of each law.
    subroutine dump_rk45(iend)
        integer, intent(in) :: iend
        type(hertzdamp_rk45_options) :: opts
        type(hertzdamp_collision) :: r
        real(wp), allocatable :: al(:)
        real(wp), parameter :: tols(3) = [1.0e-6_wp, 1.0e-10_wp, 1.0e-13_wp]
        real(wp) :: ac
        integer :: i, il, it, st
        character(len=24) :: tag
        al = [(-12.0_wp + 0.37_wp * real(i, wp), i = 0, 60), (10.0_wp**(-3.0_wp + 0.1_wp * real(i, wp)), i = 0, 60), &
              0.0_wp, -0.0_wp, nan, inf, -inf, hertzdamp_fit_alpha_c, nearest(hertzdamp_fit_alpha_c, -1.0_wp), &
              sqrt(5.0_wp), nearest(sqrt(5.0_wp), -1.0_wp), -sqrt(5.0_wp), -10.0_wp, nearest(-10.0_wp, -1.0_wp), &
              1.0e100_wp, 1.5e100_wp, -1.3884_wp, -1.5_wp, 1.0e-300_wp]
        do il = 1, size(laws)
            do it = 1, size(tols)
                call hertzdamp_rk45_tolerances(tols(it), opts)
                write (tag, '(a, i0, a, i0, a, i0)') 'rk45_end', iend, '_law', laws(il), '_tol', it
                do i = 1, size(al)
                    call hertzdamp_rk45_solve(al(i), iend, opts, r, laws(il))
                    call put(trim(tag), i, [r%e, r%tau_c, r%z_max, r%tau_max], [r%status, r%stats%steps, &
                             r%stats%rejected, r%stats%rhs_evals])
                end do
            end do
            if (iend == HD_END_OVERLAP) then
                call hertzdamp_alpha_c(ac, st, law=laws(il))
                call put('alpha_c', laws(il), [ac], [st])
            end if
        end do
    end subroutine dump_rk45

    !> The law-less linear entry points (alpha, tau_c of e; inverse without `law`).
    subroutine dump_linear_inverse(e, iend)
        real(wp), intent(in) :: e(:)
        integer, intent(in) :: iend
        real(wp) :: a(size(e)), t(size(e))
        integer :: s(size(e)), i
        character(len=16) :: tag
        write (tag, '(a, i0)') 'lin_inv_end', iend
        do i = 1, size(e)
            call hertzdamp_fit_inverse(e(i), iend, a(i), t(i), s(i))
            call put(trim(tag), i, [a(i), t(i), hertzdamp_fit_alpha(e(i), iend), hertzdamp_fit_tau_c_of_e(e(i), iend)], &
                     [s(i)])
        end do
        call hertzdamp_fit_inverse_n(size(e), e, iend, a, t, s)
        call put(trim(tag) // '_n', 0, [a, t], s)
        call put(trim(tag) // '_elem', 0, [hertzdamp_fit_alpha(e, iend), hertzdamp_fit_tau_c_of_e(e, iend)], [integer ::])
    end subroutine dump_linear_inverse

    !> The dimensionless inverse of a law: scalar calls, the array call over the whole
    !> grid (mixed valid and invalid), and over its valid values alone (whole chunks valid).
    subroutine dump_inverse(e, iend, law)
        real(wp), intent(in) :: e(:)
        integer, intent(in) :: iend, law
        real(wp) :: a(size(e)), t(size(e)), la, lt
        real(wp), allocatable :: ev(:), av(:), tv(:)
        integer :: s(size(e)), ls, i
        integer, allocatable :: sv(:)
        character(len=24) :: tag
        write (tag, '(a, i0, a, i0)') 'inv_end', iend, '_law', law
        do i = 1, size(e)
            call hertzdamp_fit_inverse(e(i), iend, a(i), t(i), s(i), law)
            call hertzdamp_fit_law_inverse(e(i), iend, law, la, lt, ls)
            call put(trim(tag), i, [a(i), t(i), la, lt, hertzdamp_fit_law_e_min(law, iend)], [s(i), ls])
        end do
        call hertzdamp_fit_inverse_n(size(e), e, iend, a, t, s, law)
        call put(trim(tag) // '_n', 0, [a, t], s)
        ev = pack(e, e >= 1.0e-3_wp .and. e <= 1.0_wp)
        allocate (av(size(ev)), tv(size(ev)), sv(size(ev)))
        call hertzdamp_fit_inverse_n(size(ev), ev, iend, av, tv, sv, law)
        call put(trim(tag) // '_valid_n', 0, [av, tv], sv)
        do i = 1, size(ev), 101
            call hertzdamp_fit_inverse_n(min(7, size(ev) - i + 1), ev(i:), iend, av(i:), tv(i:), sv(i:), law)
        end do
        call put(trim(tag) // '_short_n', 0, [av, tv], sv)
    end subroutine dump_inverse

    !> The linear forward map: scalar calls with each set of optional outputs, the array
    !> call with each set, the elemental e and tau_c, the status helper.
    subroutine dump_forward(al, iend)
        real(wp), intent(in) :: al(:)
        integer, intent(in) :: iend
        real(wp), dimension(size(al)) :: e, t, z, m, e2, t2
        real(wp) :: e1, t1, z1, m1, ea, ta, eb, tb, zb, mb
        integer :: s(size(al)), s2(size(al)), i, s1, sa, sb
        character(len=16) :: tag
        write (tag, '(a, i0)') 'fwd_end', iend
        do i = 1, size(al)
            call hertzdamp_fit_forward(al(i), iend, e1, t1, s1, z1, m1)
            call hertzdamp_fit_forward(al(i), iend, ea, ta, sa)
            call hertzdamp_fit_forward(al(i), iend, eb, tb, sb, z_max=zb)
            call hertzdamp_fit_forward(al(i), iend, e2(i), t2(i), s2(i), tau_max=mb)
            call put(trim(tag), i, [e1, t1, z1, m1, ea, ta, eb, tb, zb, mb, e2(i), t2(i), hertzdamp_fit_e(al(i), iend), &
                                    hertzdamp_fit_tau_c(al(i), iend)], [s1, sa, sb, s2(i), &
                                    hertzdamp_approx_alpha_status(al(i), iend)])
        end do
        call hertzdamp_fit_forward_n(size(al), al, iend, e, t, s, z, m)
        call put(trim(tag) // '_n', 0, [e, t, z, m], s)
        call hertzdamp_fit_forward_n(size(al), al, iend, e, t, s)
        call put(trim(tag) // '_n0', 0, [e, t], s)
        call hertzdamp_fit_forward_n(size(al), al, iend, e, t, s, z_max=z)
        call put(trim(tag) // '_nz', 0, [e, t, z], s)
        call hertzdamp_fit_forward_n(size(al), al, iend, e, t, s, tau_max=m)
        call put(trim(tag) // '_nm', 0, [e, t, m], s)
        do i = 1, size(al), 89
            call hertzdamp_fit_forward_n(min(3, size(al) - i + 1), al(i:), iend, e(i:), t(i:), s(i:), z(i:), m(i:))
        end do
        call put(trim(tag) // '_short_n', 0, [e, t, z, m], s)
        call put(trim(tag) // '_elem', 0, [hertzdamp_fit_e(al, iend), hertzdamp_fit_tau_c(al, iend)], [integer ::])
    end subroutine dump_forward

    !> The forward maps of hertzdamp_fit_laws, with and without the turning point, and
    !> their derivatives.
    subroutine dump_law_forward(al, iend, law)
        real(wp), intent(in) :: al(:)
        integer, intent(in) :: iend, law
        real(wp) :: e1, t1, z1, m1, e2, t2, e3, t3, de, dt
        integer :: s1, s2, s3, i
        character(len=24) :: tag
        write (tag, '(a, i0, a, i0)') 'lawfwd_end', iend, '_law', law
        do i = 1, size(al)
            call hertzdamp_fit_law_forward(al(i), iend, law, e1, t1, s1, z1, m1)
            call hertzdamp_fit_law_forward(al(i), iend, law, e2, t2, s2)
            call hertzdamp_fit_forward_deriv(al(i), iend, law, e3, t3, de, dt, s3)
            call put(trim(tag), i, [e1, t1, z1, m1, e2, t2, e3, t3, de, dt], [s1, s2, s3])
        end do
    end subroutine dump_law_forward

end program fit_dump
