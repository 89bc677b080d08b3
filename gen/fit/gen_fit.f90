!> hertzdamp-gen-fit: generator of the approximants of `hertzdamp_fit` and the
!> constants of `hertzdamp_compact`, for every damping law (doc/damping-laws.md).
!>
!> Usage: hertzdamp-gen-fit [CSV]
!> Writes data/fit_coefficients.csv (or CSV): the blocks of the linear law and the
!> compact constants, then the blocks of the tsuji and kuwabara-kono laws (the linear
!> rows are the same whether or not the laws follow).  Every number in it comes from
!> the reference integrator
!> `hertzdamp_rk45_collide` at tolerance 1e-15 and from LAPACK least squares (dgels);
!> nothing is typed in.
!>
!> Variables of the new laws (the force end is not analytic at alpha = 0: its
!> quantities are series in alpha^(1/n) with n = 3 (linear), 5 (tsuji), 2
!> (kuwabara-kono), from the exponent 5/(3 - 2q) of the first non-analytic term;
!> doc/damping-laws.md):
!> - tsuji: e(alpha) is exact (both ends) and so is alpha(e) for the overlap end, so
!>   only tau_c(L) (overlap: of L; force: of L^(1/5)), alpha(e)/L of L (force: e(alpha)
!>   is analytic) and z_max, tau_max of alpha^(1/5) are fitted; the forward tau_c is
!>   tau_c(L(alpha)) with the exact L.
!> - kuwabara-kono: overlap of L and alpha (analytic), force of L^(1/2) and alpha^(1/2);
!>   z_max, tau_max of alpha^(1/2) for both ends.
!>
!> Approximants ("blocks").  Each block approximates one quantity y as a piecewise
!> polynomial of one variable x on [x0, x1], cut into np pieces of equal width; on
!> piece i the local variable is t = 2 (u - i) - 1 in [-1, 1] with
!> u = (x - x0) np / (x1 - x0), and y = sum_j c_j t^j (Horner).  The fit of each
!> piece is a weighted least-squares fit in the Chebyshev basis on ~3 (deg + 1)
!> points near the Chebyshev nodes, converted to monomials; the weights make the
!> residual the relative error of the final result (alpha, tau_c or e).  The error
!> is then measured, with the same Horner evaluation, on fresh points between the
!> fitting points (validation set) against new reference solutions.
!>
!> Compact formulas: see doc/compact.md; the constants are fitted by Gauss-Newton
!> on the relative error (dgels per step) followed by Lawson's iteratively
!> reweighted least squares towards minimax.
program gen_fit
    use hertzdamp, only: hertzdamp_rk, hertzdamp_rk45_collide, hertzdamp_collision, hertzdamp_alpha_c, &
                         hertzdamp_e1, hertzdamp_tau_c0, HD_OK, HD_NO_REBOUND, HD_END_OVERLAP, HD_END_FORCE, &
                         HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO, hertzdamp_tsuji_alpha, &
                         hertzdamp_tsuji_e, hertzdamp_law_name
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    implicit none

    integer, parameter :: wp = hertzdamp_rk
    real(wp), parameter :: ref_tol = 1.0e-15_wp
    !> Absolute error of the reference L = -ln e near e = 1 (observed: e(0) = 1 - 1.4e-15).
    real(wp), parameter :: sigma_l = 2.0e-15_wp
    !> Validation ignores points where the reference noise exceeds this (relative).
    real(wp), parameter :: nu_max = 1.0e-14_wp

    ! variables x (ROOT: the nroot-th root of L or alpha)
    integer, parameter :: VAR_L = 1, VAR_ROOT_L = 2, VAR_ALPHA = 3, VAR_W = 4, VAR_ROOT_ALPHA = 5, &
                          VAR_LOG_ROOT_ALPHA = 7
    character(len=*), parameter :: var_names(7) = [character(len=40) :: &
        'L = -ln e', 'L**(1/n)', 'alpha', 'w = -ln(1 - alpha/alpha_c)', 'alpha**(1/n)', 'ln alpha', &
        'ln(1 + alpha**(1/n))']
    ! quantities y
    integer, parameter :: Q_ALPHA_OVER_L = 1, Q_TAU_C = 2, Q_L_OVER_ALPHA = 3, Q_L = 4, Q_Z_MAX = 5, Q_TAU_MAX = 6
    character(len=*), parameter :: q_names(6) = [character(len=24) :: 'alpha/L', 'tau_c', 'L/alpha', 'L', &
                                                  'z_max', 'tau_max']

    type :: block_spec
        character(len=32) :: name
        integer :: iend, var, q
        real(wp) :: x0, x1
        integer :: np, deg
        integer :: law = HD_DAMPING_LINEAR   !! damping law of the block
        integer :: nroot = 3                 !! n of the ROOT variables
    end type block_spec

    ! the inversion table alpha <-> L of each definition and law
    integer, parameter :: ntab = 3000
    real(wp) :: tab_a(ntab, 0:1, 0:2), tab_l(ntab, 0:1, 0:2), tab_t(ntab, 0:1, 0:2)

    real(wp) :: alpha_c, e1, tc0, lmax_ov, lmax_fo, amax_ov, amax_fo, wmax_ov
    real(wp) :: e_min_ov, e_min_fo
    integer :: status, u, nb, ib, j, ilw, itw
    real(wp) :: end_val(40, 0:1), h1
    integer :: im
    real(wp) :: cc(4, 8), cerr(8)
    real(wp), parameter :: e_compact = 0.05_wp
    character(len=*), parameter :: cm_names(8) = [character(len=16) :: 'cov_inv_a', 'cov_inv_t', 'cov_fwd_l', &
        'cov_fwd_t', 'cfo_inv_a', 'cfo_inv_t', 'cfo_fwd_l', 'cfo_fwd_t']
    character(len=256) :: path
    type(block_spec), allocatable :: blocks(:)
    real(wp), allocatable :: coef(:, :)
    real(wp) :: maxerr
    character(len=:), allocatable :: body, summary, law_body, law_summary, law_params

    interface
        !> LAPACK: least-squares solution of an overdetermined system by QR.
        subroutine dgels(trans, m, n, nrhs, a, lda, b, ldb, work, lwork, info)
            import :: wp
            implicit none
            character, intent(in) :: trans
            integer, intent(in) :: m, n, nrhs, lda, ldb, lwork
            real(wp), intent(inout) :: a(lda, *), b(ldb, *)
            real(wp), intent(inout) :: work(*)
            integer, intent(out) :: info
        end subroutine dgels
    end interface

    path = 'data/fit_coefficients.csv'
    if (command_argument_count() >= 1) call get_command_argument(1, path)

    e1 = hertzdamp_e1()
    tc0 = hertzdamp_tau_c0()
    call hertzdamp_alpha_c(alpha_c, status, 1.0e-15_wp)
    if (status /= HD_OK) call die('alpha_c failed')
    call law_fits()
    call linear_fits()

contains

    !> The linear law (blocks and compact constants), and the CSV with the rows of
    !> every law.
    subroutine linear_fits()

    e_min_ov = 1.0e-3_wp
    e_min_fo = 1.0e-4_wp
    lmax_ov = -log(e_min_ov)
    lmax_fo = -log(e_min_fo)

    call make_table(HD_DAMPING_LINEAR, HD_END_OVERLAP)
    call make_table(HD_DAMPING_LINEAR, HD_END_FORCE)
    amax_ov = alpha_of_l(HD_DAMPING_LINEAR, HD_END_OVERLAP, lmax_ov)
    amax_fo = alpha_of_l(HD_DAMPING_LINEAR, HD_END_FORCE, lmax_fo)
    ! forward ranges reach a little beyond alpha(e_min): alpha(e_min/2)
    amax_ov = alpha_of_l(HD_DAMPING_LINEAR, HD_END_OVERLAP, log(1.0e5_wp))   ! overlap forward: down to e = 1e-5
    amax_fo = alpha_of_l(HD_DAMPING_LINEAR, HD_END_FORCE, lmax_fo + log(2.0_wp))
    wmax_ov = -log(1.0_wp - amax_ov / alpha_c)

    if (allocated(blocks)) deallocate (blocks)
    allocate (blocks(16))   ! explicit: allocation on assignment trips -Wuninitialized
    blocks(:) = [ &
        block_spec('ov_inv_a', HD_END_OVERLAP, VAR_L, Q_ALPHA_OVER_L, 0.0_wp, lmax_ov, 8, 9), &
        block_spec('ov_inv_t', HD_END_OVERLAP, VAR_L, Q_TAU_C, 0.0_wp, lmax_ov, 8, 9), &
        block_spec('fo_inv_a', HD_END_FORCE, VAR_ROOT_L, Q_ALPHA_OVER_L, 0.0_wp, lmax_fo**(1.0_wp/3), 16, 9), &
        block_spec('fo_inv_t', HD_END_FORCE, VAR_ROOT_L, Q_TAU_C, 0.0_wp, lmax_fo**(1.0_wp/3), 16, 9), &
        block_spec('ov_fwd_la', HD_END_OVERLAP, VAR_ALPHA, Q_L_OVER_ALPHA, 0.0_wp, 0.6_wp, 4, 11), &
        block_spec('ov_fwd_ta', HD_END_OVERLAP, VAR_ALPHA, Q_TAU_C, 0.0_wp, 0.6_wp, 4, 11), &
        block_spec('ov_fwd_lw', HD_END_OVERLAP, VAR_W, Q_L, -log(1.0_wp - 0.6_wp / alpha_c), wmax_ov, 16, 11), &
        block_spec('ov_fwd_tw', HD_END_OVERLAP, VAR_W, Q_TAU_C, -log(1.0_wp - 0.6_wp / alpha_c), wmax_ov, 16, 11), &
        block_spec('fo_fwd_la', HD_END_FORCE, VAR_ROOT_ALPHA, Q_L_OVER_ALPHA, 0.0_wp, amax_fo**(1.0_wp/3), 16, 11), &
        block_spec('fo_fwd_ta', HD_END_FORCE, VAR_ROOT_ALPHA, Q_TAU_C, 0.0_wp, amax_fo**(1.0_wp/3), 16, 11), &
        block_spec('ov_fwd_za', HD_END_OVERLAP, VAR_ALPHA, Q_Z_MAX, 0.0_wp, 0.6_wp, 4, 11), &
        block_spec('ov_fwd_ma', HD_END_OVERLAP, VAR_ALPHA, Q_TAU_MAX, 0.0_wp, 0.6_wp, 4, 11), &
        block_spec('ov_fwd_zb', HD_END_OVERLAP, VAR_ALPHA, Q_Z_MAX, 0.6_wp, 1.3_wp, 8, 11), &
        block_spec('ov_fwd_mb', HD_END_OVERLAP, VAR_ALPHA, Q_TAU_MAX, 0.6_wp, 1.3_wp, 8, 11), &
        block_spec('fo_fwd_za', HD_END_FORCE, VAR_ROOT_ALPHA, Q_Z_MAX, 0.0_wp, amax_fo**(1.0_wp/3), 16, 11), &
        block_spec('fo_fwd_ma', HD_END_FORCE, VAR_ROOT_ALPHA, Q_TAU_MAX, 0.0_wp, amax_fo**(1.0_wp/3), 16, 11) ]

    nb = size(blocks)
    ilw = 0
    itw = 0
    body = ''
    summary = ''
    do ib = 1, nb
        call fit_and_record(blocks(ib))
        if (blocks(ib)%name == 'ov_fwd_lw') ilw = ib
        if (blocks(ib)%name == 'ov_fwd_tw') itw = ib
    end do

    ! compact formulas (doc/compact.md): 4 constants each, overlap and force, e in [0.05, 1]
    do im = 1, 8
        call fit_compact(im, cc(:, im), cerr(im))
        write (error_unit, '(a,i2,a,4es12.4,a,es10.2)') 'compact model ', im, ' c =', cc(:, im), '  max err ', cerr(im)
        summary = summary // '# compact ' // trim(cm_names(im)) // ': 4 constants, measured max relative error ' // &
            g(cerr(im)) // ' over e in [' // g(e_compact) // ', 1]' // new_line('a')
    end do

    open (newunit=u, file=trim(path), status='replace', action='write')
    write (u, '(a)') '# hertzdamp fit coefficients: generated by gen/fit/gen_fit.f90 (fpm run hertzdamp-gen-fit,' // &
        ' make fit-data); do not edit.'
    write (u, '(a)') '# Reference: hertzdamp_rk45_collide at tolerance ' // g(ref_tol) // ' (relative error control).'
    write (u, '(a)') '# Fit: LAPACK dgels weighted least squares per piece, Chebyshev basis, stored as monomials.'
    write (u, '(a)') '# Piece i of a block covers u = (x - x0) np / (x1 - x0) in [i, i+1]; t = 2 (u - i) - 1;' // &
        ' y = sum_j c_j t^j.'
    write (u, '(a)') '# Ranges: overlap e in [' // g(e_min_ov) // ', 1], force e in [' // g(e_min_fo) // &
        ', 1]; forward alpha up to alpha(e_min/2) (force), alpha(1e-5) (overlap).'
    write (u, '(a)', advance='no') summary
    write (u, '(a)', advance='no') law_summary
    write (u, '(a)') '# rows: param,name,value | block,name,variable,x0,x1,np,deg | coef,name,piece,c_0,...,c_deg'
    write (u, '(a)') 'param,alpha_c,' // r2s(alpha_c)
    write (u, '(a)') 'param,e_min_overlap,' // r2s(e_min_ov)
    write (u, '(a)') 'param,e_min_force,' // r2s(e_min_fo)
    write (u, '(a)') 'param,alpha_max_overlap,' // r2s(amax_ov)
    write (u, '(a)') 'param,alpha_max_force,' // r2s(amax_fo)
    write (u, '(a)') 'param,ov_fwd_lw_end,' // r2s(end_val(ilw, 0))
    write (u, '(a)') 'param,ov_fwd_lw_slope,' // r2s(end_val(ilw, 1))
    write (u, '(a)') 'param,ov_fwd_tw_end,' // r2s(end_val(itw, 0))
    write (u, '(a)') 'param,ov_fwd_tw_slope,' // r2s(end_val(itw, 1))
    do im = 1, 8
        do j = 1, 4
            write (u, '(a)') 'param,' // trim(cm_names(im)) // '_' // i2s(j) // ',' // r2s(cc(j, im))
        end do
    end do
    write (u, '(a)') 'param,e_min_compact,' // r2s(e_compact)
    ! the forward maps of the compact formulas are stated on the same range: alpha up to alpha(e_compact)
    write (u, '(a)') 'param,compact_alpha_max_overlap,' // r2s(alpha_at_l(0, HD_END_OVERLAP, -log(e_compact)))
    write (u, '(a)') 'param,compact_alpha_max_force,' // r2s(alpha_at_l(0, HD_END_FORCE, -log(e_compact)))
    write (u, '(a)', advance='no') law_params
    write (u, '(a)', advance='no') body
    write (u, '(a)', advance='no') law_body
    close (u)
    write (output_unit, '(a)') 'wrote ' // trim(path)
    end subroutine linear_fits

    !> Fit one block and append its summary lines and CSV rows; value and slope d/dx
    !> at x1 of the last piece go to end_val (for the linear extrapolation in w).
    subroutine fit_and_record(b)
        type(block_spec), intent(in) :: b
        integer :: k
        character(len=:), allocatable :: vname
        call fit_block(b, coef, maxerr)
        h1 = (b%x1 - b%x0) / b%np
        end_val(ib, 0) = sum(coef(:, b%np))
        end_val(ib, 1) = sum([(k * coef(k, b%np), k=1, b%deg)]) * 2.0_wp / h1
        vname = trim(var_names(b%var))
        if (b%var == VAR_ROOT_L .or. b%var == VAR_ROOT_ALPHA) vname = vname(1:len(vname) - 2) // i2s(b%nroot) // ')'
        if (b%var == VAR_LOG_ROOT_ALPHA) vname = vname(1:len(vname) - 3) // i2s(b%nroot) // '))'
        summary = summary // '# block ' // trim(b%name) // ': ' // trim(q_names(b%q)) // &
            ' of ' // vname // ', x in [' // g(b%x0) // ', ' // &
            g(b%x1) // '], ' // i2s(b%np) // ' pieces of degree ' // i2s(b%deg) // &
            new_line('a') // '#     measured max relative error of the result ' // g(maxerr) // new_line('a')
        write (error_unit, '(a,a12,a,es10.2)') 'block ', trim(b%name), '  max rel err ', maxerr
        body = body // 'block,' // trim(b%name) // ',' // i2s(b%var) // ',' // &
            r2s(b%x0) // ',' // r2s(b%x1) // ',' // i2s(b%np) // ',' // &
            i2s(b%deg) // new_line('a')
        do k = 1, b%np
            body = body // 'coef,' // trim(b%name) // ',' // i2s(k - 1) // ',' // &
                join(coef(:, k)) // new_line('a')
        end do
    end subroutine fit_and_record

    !> The tsuji and kuwabara-kono laws: their summary lines, params and rows (written
    !> with the linear ones).  Inverse ranges e in [1e-4, 1], forward ranges down to
    !> e = 1e-5 (both ends).
    subroutine law_fits()
        real(wp), parameter :: e_min_law = 1.0e-4_wp, e_fwd_law = 1.0e-5_wp
        real(wp) :: lmin, lfwd, a_t_fo, a_k_ov, a_k_fo, a_t_ov
        lmin = -log(e_min_law)
        lfwd = -log(e_fwd_law)
        call make_table(HD_DAMPING_TSUJI, HD_END_FORCE)
        call make_table(HD_DAMPING_KUWABARA_KONO, HD_END_OVERLAP)
        call make_table(HD_DAMPING_KUWABARA_KONO, HD_END_FORCE)
        a_t_ov = hertzdamp_tsuji_alpha(e_fwd_law)
        a_t_fo = alpha_of_l(HD_DAMPING_TSUJI, HD_END_FORCE, lfwd)
        a_k_ov = alpha_of_l(HD_DAMPING_KUWABARA_KONO, HD_END_OVERLAP, lfwd)
        a_k_fo = alpha_of_l(HD_DAMPING_KUWABARA_KONO, HD_END_FORCE, lfwd)
        if (allocated(blocks)) deallocate (blocks)
        allocate (blocks(15))
        blocks(:) = [ &
            block_spec('ts_ov_inv_t', HD_END_OVERLAP, VAR_L, Q_TAU_C, 0.0_wp, lfwd, 16, 11, HD_DAMPING_TSUJI), &
            ! alpha(e) of the force end is analytic in L (its e(alpha) is): in L^(1/5) it would
            ! be exp(x^5/2)-steep at large L, so it keeps its own grid
            block_spec('ts_fo_inv_a', HD_END_FORCE, VAR_L, Q_ALPHA_OVER_L, 0.0_wp, lfwd, 16, 11, HD_DAMPING_TSUJI), &
            block_spec('ts_fo_inv_t', HD_END_FORCE, VAR_ROOT_L, Q_TAU_C, 0.0_wp, lfwd**0.2_wp, 16, 11, &
                       HD_DAMPING_TSUJI, 5), &
            block_spec('ts_fwd_z', HD_END_FORCE, VAR_ROOT_ALPHA, Q_Z_MAX, 0.0_wp, a_t_fo**0.2_wp, 16, 11, &
                       HD_DAMPING_TSUJI, 5), &
            block_spec('ts_fwd_m', HD_END_FORCE, VAR_ROOT_ALPHA, Q_TAU_MAX, 0.0_wp, a_t_fo**0.2_wp, 16, 11, &
                       HD_DAMPING_TSUJI, 5), &
            block_spec('kk_ov_inv_a', HD_END_OVERLAP, VAR_L, Q_ALPHA_OVER_L, 0.0_wp, lmin, 16, 11, &
                       HD_DAMPING_KUWABARA_KONO), &
            block_spec('kk_ov_inv_t', HD_END_OVERLAP, VAR_L, Q_TAU_C, 0.0_wp, lmin, 16, 11, HD_DAMPING_KUWABARA_KONO), &
            block_spec('kk_fo_inv_a', HD_END_FORCE, VAR_ROOT_L, Q_ALPHA_OVER_L, 0.0_wp, sqrt(lmin), 16, 11, &
                       HD_DAMPING_KUWABARA_KONO, 2), &
            block_spec('kk_fo_inv_t', HD_END_FORCE, VAR_ROOT_L, Q_TAU_C, 0.0_wp, sqrt(lmin), 16, 11, &
                       HD_DAMPING_KUWABARA_KONO, 2), &
            block_spec('kk_ov_fwd_la', HD_END_OVERLAP, VAR_ALPHA, Q_L_OVER_ALPHA, 0.0_wp, a_k_ov, 32, 11, &
                       HD_DAMPING_KUWABARA_KONO), &
            block_spec('kk_ov_fwd_ta', HD_END_OVERLAP, VAR_ALPHA, Q_TAU_C, 0.0_wp, a_k_ov, 32, 11, &
                       HD_DAMPING_KUWABARA_KONO), &
            block_spec('kk_fo_fwd_la', HD_END_FORCE, VAR_LOG_ROOT_ALPHA, Q_L_OVER_ALPHA, 0.0_wp, &
                       log(1.0_wp + sqrt(a_k_fo)), 16, 11, HD_DAMPING_KUWABARA_KONO, 2), &
            block_spec('kk_fo_fwd_ta', HD_END_FORCE, VAR_LOG_ROOT_ALPHA, Q_TAU_C, 0.0_wp, log(1.0_wp + sqrt(a_k_fo)), &
                       16, 11, HD_DAMPING_KUWABARA_KONO, 2), &
            block_spec('kk_fwd_z', HD_END_FORCE, VAR_LOG_ROOT_ALPHA, Q_Z_MAX, 0.0_wp, log(1.0_wp + sqrt(a_k_fo)), &
                       16, 11, HD_DAMPING_KUWABARA_KONO, 2), &
            block_spec('kk_fwd_m', HD_END_FORCE, VAR_LOG_ROOT_ALPHA, Q_TAU_MAX, 0.0_wp, log(1.0_wp + sqrt(a_k_fo)), &
                       16, 11, HD_DAMPING_KUWABARA_KONO, 2) ]
        body = ''
        summary = ''
        do ib = 1, size(blocks)
            call fit_and_record(blocks(ib))
        end do
        law_summary = '# Damping laws tsuji and kuwabara-kono (doc/damping-laws.md): inverse e in [' // g(e_min_law) // &
            ', 1],' // new_line('a') // '# forward down to e = ' // g(e_fwd_law) // &
            ' (both ends); tsuji e(alpha) of both ends and alpha(e) of the overlap end are exact (no block).' // &
            new_line('a') // summary
        law_body = body
        law_params = 'param,law_e_min,' // r2s(e_min_law) // new_line('a') // &
            'param,law_e_min_forward,' // r2s(e_fwd_law) // new_line('a') // &
            'param,ts_alpha_max_overlap,' // r2s(a_t_ov) // new_line('a') // &
            'param,ts_alpha_max_force,' // r2s(a_t_fo) // new_line('a') // &
            'param,kk_alpha_max_overlap,' // r2s(a_k_ov) // new_line('a') // &
            'param,kk_alpha_max_force,' // r2s(a_k_fo) // new_line('a')
    end subroutine law_fits

    subroutine die(msg)
        character(len=*), intent(in) :: msg
        write (error_unit, '(a)') 'hertzdamp-gen-fit: ' // msg
        error stop 1
    end subroutine die

    !> alpha with L(alpha) = l on the reference integrator: secant steps from the
    !> table's interpolation to a relative step of 1e-14 (the range ends of a method).
    real(wp) function alpha_at_l(law, iend, l) result(a)
        integer, intent(in) :: law, iend
        real(wp), intent(in) :: l
        real(wp) :: a0, l0, l1, e, tc, an
        integer :: it
        a0 = alpha_of_l(law, iend, l)
        a = a0 * (1.0_wp + 1.0e-6_wp)
        call ref(a0, law, iend, e, tc, l0)
        do it = 1, 50
            call ref(a, law, iend, e, tc, l1)
            if (l1 == l0) exit
            an = a - (l1 - l) * (a - a0) / (l1 - l0)
            a0 = a
            l0 = l1
            a = an
            if (abs(a - a0) <= 1.0e-14_wp * a) exit
        end do
    end function alpha_at_l

    !> Reference e, tau_c, L = -ln e at alpha.
    subroutine ref(alpha, law, iend, e, tc, l, zm, tm)
        real(wp), intent(in) :: alpha
        integer, intent(in) :: law, iend
        real(wp), intent(out) :: e, tc, l
        real(wp), intent(out), optional :: zm, tm
        type(hertzdamp_collision) :: r
        r = hertzdamp_rk45_collide(alpha, iend, ref_tol, law)
        if (present(zm)) zm = r%z_max
        if (present(tm)) tm = r%tau_max
        if (r%status /= HD_OK .and. .not. (r%status == HD_NO_REBOUND .and. present(zm))) then
          call die('reference failed at alpha = ' // g(alpha) // ' law ' // hertzdamp_law_name(law))
        end if
        e = r%e
        tc = r%tau_c
        l = 0.0_wp
        if (e > 0.0_wp .and. alpha > 0.0_wp) l = -log(e)
    end subroutine ref

    !> Dense table alpha -> L used only to place the sample points of the inverse fits.
    subroutine make_table(law, iend)
        integer, intent(in) :: law, iend
        integer :: i
        real(wp) :: s, e, wtop, a
        do i = 1, ntab
            s = real(i - 1, wp) / real(ntab - 1, wp)
            if (law == HD_DAMPING_LINEAR .and. iend == HD_END_OVERLAP) then
                ! uniform in w = -ln(1 - alpha/alpha_c) up to e ~ 1e-5
                wtop = 12.0_wp
                a = alpha_c * (1.0_wp - exp(-wtop * s))
            else if (law == HD_DAMPING_LINEAR) then
                ! uniform in alpha^(1/3) up to alpha = 300 (e ~ 1e-6)
                a = (s * 300.0_wp**(1.0_wp / 3))**3
            else if (law == HD_DAMPING_TSUJI) then
                ! force end, uniform in alpha^(1/5) up to alpha = 2000 (e ~ 3e-7)
                a = (s * 2000.0_wp**0.2_wp)**5
            else if (iend == HD_END_OVERLAP) then
                ! kuwabara-kono overlap, uniform in alpha up to 20 (e ~ 2e-6)
                a = 20.0_wp * s
            else
                ! kuwabara-kono force, uniform in alpha^(1/2) up to alpha = 3000 (e ~ 2e-6)
                a = (s * sqrt(3000.0_wp))**2
            end if
            tab_a(i, iend, law) = a
            call ref(a, law, iend, e, tab_t(i, iend, law), tab_l(i, iend, law))
        end do
    end subroutine make_table

    !> alpha with L(alpha) ~ l, by linear interpolation in the table (approximate);
    !> exact for the tsuji overlap end (closed form).
    real(wp) function alpha_of_l(law, iend, l) result(a)
        integer, intent(in) :: law, iend
        real(wp), intent(in) :: l
        integer :: lo, hi, mid
        lo = 1
        hi = ntab
        if (l <= 0.0_wp) then
            a = 0.0_wp
            return
        end if
        if (law == HD_DAMPING_TSUJI .and. iend == HD_END_OVERLAP) then
            a = hertzdamp_tsuji_alpha(exp(-l))
            return
        end if
        if (l >= tab_l(ntab, iend, law)) call die('L beyond the table')
        do while (hi - lo > 1)
            mid = (lo + hi) / 2
            if (tab_l(mid, iend, law) <= l) then
                lo = mid
            else
                hi = mid
            end if
        end do
        a = tab_a(lo, iend, law) + (tab_a(hi, iend, law) - tab_a(lo, iend, law)) * (l - tab_l(lo, iend, law)) / &
            (tab_l(hi, iend, law) - tab_l(lo, iend, law))
    end function alpha_of_l

    !> One exact sample of block b near the variable value x: returns the exact
    !> variable xs, quantity y, and the weight w (1/sensitivity of the final relative error).
    subroutine sample(b, x, xs, y, w, nu)
        type(block_spec), intent(in) :: b
        real(wp), intent(in) :: x
        real(wp), intent(out) :: xs, y, w
        real(wp), intent(out) :: nu   !! relative noise of the reference in the final result
        real(wp) :: a, l, e, tc, zm, tm
        integer :: st
        select case (b%var)
        case (VAR_L)
            a = alpha_of_l(b%law, b%iend, x)
        case (VAR_ROOT_L)
            a = alpha_of_l(b%law, b%iend, x**b%nroot)
        case (VAR_ALPHA)
            a = x
        case (VAR_W)
            a = alpha_c * (1.0_wp - exp(-x))
        case (VAR_ROOT_ALPHA)
            a = x**b%nroot
        case (VAR_LOG_ROOT_ALPHA)
            a = (exp(x) - 1.0_wp)**b%nroot
        case default
            a = exp(x)
        end select
        if (b%q == Q_Z_MAX .or. b%q == Q_TAU_MAX) then
            call ref(a, b%law, b%iend, e, tc, l, zm, tm)
        else
            call ref(a, b%law, b%iend, e, tc, l)
        end if
        if (b%law == HD_DAMPING_TSUJI .and. a > 0.0_wp) then
            ! the exact L (closed form) is the variable the library evaluates with
            call hertzdamp_tsuji_e(a, b%iend, e, st)
            l = -log(e)
        end if
        select case (b%var)
        case (VAR_L); xs = l
        case (VAR_ROOT_L); xs = l**(1.0_wp / b%nroot)
        case (VAR_ALPHA); xs = a
        case (VAR_W); xs = -log(1.0_wp - a / alpha_c)
        case (VAR_ROOT_ALPHA); xs = a**(1.0_wp / b%nroot)
        case (VAR_LOG_ROOT_ALPHA); xs = log(1.0_wp + a**(1.0_wp / b%nroot))
        case default; xs = log(a)
        end select
        nu = 0.0_wp
        select case (b%q)
        case (Q_ALPHA_OVER_L)
            y = a / l
            w = 1.0_wp / y
            nu = sigma_l / l
        case (Q_TAU_C)
            y = tc
            w = 1.0_wp / y
            if (b%var == VAR_ROOT_L) nu = sigma_l / l * abs(tc - tc0) / tc
        case (Q_Z_MAX)
            y = zm
            w = 1.0_wp / y
        case (Q_TAU_MAX)
            y = tm
            w = 1.0_wp / y
        case (Q_L_OVER_ALPHA)
            y = l / a
            w = a          ! error in e = alpha * error in L/alpha
        case default
            y = l
            w = 1.0_wp
        end select
    end subroutine sample

    !> Weighted least-squares fit of every piece of block b; coef(0:deg, np) monomial
    !> coefficients in t; maxerr the validation error.
    subroutine fit_block(b, coef, maxerr)
        type(block_spec), intent(in) :: b
        real(wp), allocatable, intent(out) :: coef(:, :)
        real(wp), intent(out) :: maxerr
        integer :: ip, m, k, n, info, lwork, nval
        real(wp) :: h, xa, xb, xt, xs, y, w, t, yf, nu, perr
        real(wp), allocatable :: a(:, :), rhs(:, :), work(:), cheb(:), mono(:)
        n = b%deg + 1
        m = 3 * n
        nval = 4 * n
        h = (b%x1 - b%x0) / b%np
        allocate (coef(0:b%deg, b%np), a(m + 1, n), rhs(m + 1, 1), cheb(0:b%deg), mono(0:b%deg))
        lwork = 64 * (m + n)
        allocate (work(lwork))
        maxerr = 0.0_wp
        do ip = 1, b%np
            perr = 0.0_wp
            xa = b%x0 + (ip - 1) * h
            xb = xa + h
            do k = 1, m
                ! Chebyshev nodes of the first kind (endpoints excluded, x = 0 avoided)
                t = -cos((real(k, wp) - 0.5_wp) * acos(-1.0_wp) / m)
                xt = 0.5_wp * (xa + xb) + 0.5_wp * (xb - xa) * t
                call sample(b, xt, xs, y, w, nu)
                w = w / (1.0_wp + nu / nu_max)
                t = (2.0_wp * (xs - xa) / h) - 1.0_wp
                call cheb_row(t, b%deg, a(k, :))
                a(k, :) = a(k, :) * w
                rhs(k, 1) = y * w
            end do
            if (ip == 1 .and. b%x0 == 0.0_wp) then
                ! the exact limit at x = 0 (alpha = 0, e = 1) as a heavily weighted row
                y = limit_at_zero(b%q, b%law)
                w = 10.0_wp / y
                if (b%q == Q_L_OVER_ALPHA) w = 0.0_wp
                call cheb_row(-1.0_wp, b%deg, a(m + 1, :))
                a(m + 1, :) = a(m + 1, :) * w
                rhs(m + 1, 1) = y * w
            else
                a(m + 1, :) = 0.0_wp
                rhs(m + 1, 1) = 0.0_wp
            end if
            call dgels('N', m + 1, n, 1, a, m + 1, rhs, m + 1, work, lwork, info)
            if (info /= 0) call die('dgels failed')
            cheb = rhs(1:n, 1)
            call cheb_to_mono(cheb, mono)
            coef(:, ip) = mono
            ! validation between and beyond the fitting nodes, endpoints included
            do k = 0, nval
                t = -cos(real(k, wp) * acos(-1.0_wp) / nval)
                xt = 0.5_wp * (xa + xb) + 0.5_wp * (xb - xa) * t
                if (b%x0 == 0.0_wp .and. ip == 1 .and. k == 0) xt = 1.0e-3_wp * h
                call sample(b, xt, xs, y, w, nu)
                if (nu > nu_max) cycle
                t = (2.0_wp * (xs - xa) / h) - 1.0_wp
                if (abs(t) > 1.0_wp + 1.0e-9_wp) cycle
                yf = horner(mono, t)
                perr = max(perr, abs(yf - y) * w)
            end do
            if (ip == 1 .and. b%x0 == 0.0_wp .and. b%q /= Q_L_OVER_ALPHA) then
                y = limit_at_zero(b%q, b%law)
                perr = max(perr, abs(horner(mono, -1.0_wp) - y) / y)
            end if
            write (error_unit, '(a,i3,es10.2)') '   piece', ip, perr
            maxerr = max(maxerr, perr)
        end do
    end subroutine fit_block

    !> Compact model im with constants c at a data point: the value of the fitted
    !> quantity (alpha/L, tau_c, L/alpha or tau_c; see doc/compact.md).
    pure real(wp) function compact_model(im, c, a, l) result(y)
        integer, intent(in) :: im
        real(wp), intent(in) :: c(4), a, l
        real(wp) :: x, s
        select case (im)
        case (1)   ! overlap alpha/L = e^(1/10)/e1 (1 + c1 x + c2 x^2)/(1 + c3 x + c4 x^2), x = L^2
            x = l * l
            y = exp(-0.1_wp * l) / e1 * (1.0_wp + c(1) * x + c(2) * x * x) / (1.0_wp + c(3) * x + c(4) * x * x)
        case (2)   ! overlap tau_c = tau_c0 e^(-1/10) (1 + c1 x + c2 x^2)/(1 + c3 x + c4 x^2)
            x = l * l
            y = exp(0.1_wp * l) * tc0 * (1.0_wp + c(1) * x + c(2) * x * x) / (1.0_wp + c(3) * x + c(4) * x * x)
        case (3)   ! overlap L/alpha = e1 (1 + c1 a)/(1 + c2 a + c3 a^2) - c4 (ln(1 - a/alpha_c) + a/alpha_c)/a
            s = a / alpha_c
            y = e1 * (1.0_wp + c(1) * a) / (1.0_wp + c(2) * a + c(3) * a * a) - c(4) * (log(1.0_wp - s) + s) / a
        case (4)   ! overlap tau_c = tau_c0 (1 + c1 a + c2 a^2)/(1 + c3 a) - c4 (ln(1 - a/alpha_c) + a/alpha_c)
            s = a / alpha_c
            y = tc0 * (1.0_wp + c(1) * a + c(2) * a * a) / (1.0_wp + c(3) * a) - c(4) * (log(1.0_wp - s) + s)
        case (5)   ! force alpha/L = (1 + c1 s^2 + c2 s^3)/(e1 (1 + c3 s^2 + c4 s^3)), s = L^(1/3)
            s = l**(1.0_wp / 3)
            y = (1.0_wp + c(1) * s**2 + c(2) * s**3) / (e1 * (1.0_wp + c(3) * s**2 + c(4) * s**3))
        case (6)   ! force tau_c = tau_c0 (1 + c1 s^2 + c2 s^3)/(1 + c3 s^2 + c4 s^3)
            s = l**(1.0_wp / 3)
            y = tc0 * (1.0_wp + c(1) * s**2 + c(2) * s**3) / (1.0_wp + c(3) * s**2 + c(4) * s**3)
        case (7)   ! force L/alpha = e1 (1 + c1 s^2 + c2 s^3)/(1 + c3 s^2 + c4 s^3), s = alpha^(1/3)
            s = a**(1.0_wp / 3)
            y = e1 * (1.0_wp + c(1) * s**2 + c(2) * s**3) / (1.0_wp + c(3) * s**2 + c(4) * s**3)
        case default  ! force tau_c = tau_c0 (1 + c1 s^2 + c2 s^3)/(1 + c3 s^2 + c4 s^3)
            s = a**(1.0_wp / 3)
            y = tc0 * (1.0_wp + c(1) * s**2 + c(2) * s**3) / (1.0_wp + c(3) * s**2 + c(4) * s**3)
        end select
    end function compact_model

    !> Fit the 4 constants of compact model im to the table (e >= e_compact, alpha >= 1e-3):
    !> Levenberg-Marquardt on the relative error of the result, then Lawson reweighting
    !> towards the minimax; returns the best constants and their max relative error.
    subroutine fit_compact(im, c, maxerr)
        integer, intent(in) :: im
        real(wp), intent(out) :: c(4)
        real(wp), intent(out) :: maxerr
        integer :: iend, n, i, it, k, info, lawson
        real(wp), allocatable :: a(:), l(:), y(:), sc(:), wt(:), r(:), jac(:, :), rhs(:, :), rn(:)
        real(wp) :: work(4096), lam, f0, f1, ct(4), hstep, best(4), bestmax, rm
        iend = merge(HD_END_OVERLAP, HD_END_FORCE, im <= 4)
        n = count(tab_l(:, iend, 0) <= -log(e_compact) .and. tab_a(:, iend, 0) >= 1.0e-3_wp)
        allocate (a(n), l(n), y(n), sc(n), wt(n), r(n), rn(n), jac(n + 4, 4), rhs(n + 4, 1))
        a = pack(tab_a(:, iend, 0), tab_l(:, iend, 0) <= -log(e_compact) .and. tab_a(:, iend, 0) >= 1.0e-3_wp)
        l = pack(tab_l(:, iend, 0), tab_l(:, iend, 0) <= -log(e_compact) .and. tab_a(:, iend, 0) >= 1.0e-3_wp)
        y = pack(tab_t(:, iend, 0), tab_l(:, iend, 0) <= -log(e_compact) .and. tab_a(:, iend, 0) >= 1.0e-3_wp)
        select case (im)
        case (1, 5)
            y = a / l
            sc = 1.0_wp / y           ! relative error of alpha
        case (3, 7)
            y = l / a
            sc = a                    ! relative error of e = absolute error of L
        case default
            sc = 1.0_wp / y           ! relative error of tau_c
        end select
        c = 0.0_wp
        best = c
        bestmax = huge(1.0_wp)
        wt = 1.0_wp
        do lawson = 1, 60
            lam = 1.0e-3_wp
            do it = 1, 60
                do i = 1, n
                    r(i) = (compact_model(im, c, a(i), l(i)) - y(i)) * sc(i) * wt(i)
                end do
                f0 = sum(r**2)
                do k = 1, 4
                    ct = c
                    hstep = 1.0e-7_wp * max(1.0_wp, abs(c(k)))
                    ct(k) = c(k) + hstep
                    do i = 1, n
                        jac(i, k) = (compact_model(im, ct, a(i), l(i)) - y(i)) * sc(i) * wt(i)
                    end do
                    ct(k) = c(k) - hstep
                    do i = 1, n
                        jac(i, k) = (jac(i, k) - (compact_model(im, ct, a(i), l(i)) - y(i)) * sc(i) * wt(i)) &
                                    / (2.0_wp * hstep)
                    end do
                end do
                do
                    jac(n + 1:n + 4, :) = 0.0_wp
                    do k = 1, 4
                        jac(n + k, k) = sqrt(lam) * max(1.0e-3_wp, sqrt(sum(jac(1:n, k)**2)))
                    end do
                    rhs(1:n, 1) = -r
                    rhs(n + 1:, 1) = 0.0_wp
                    block
                        real(wp) :: jc(n + 4, 4)
                        jc = jac
                        call dgels('N', n + 4, 4, 1, jc, n + 4, rhs, n + 4, work, size(work), info)
                    end block
                    ct = c + rhs(1:4, 1)
                    do i = 1, n
                        rn(i) = (compact_model(im, ct, a(i), l(i)) - y(i)) * sc(i) * wt(i)
                    end do
                    f1 = sum(rn**2)
                    if (f1 <= f0 .and. f1 == f1) then
                        c = ct
                        lam = max(1.0e-12_wp, lam / 10)
                        exit
                    end if
                    lam = lam * 10
                    if (lam > 1.0e12_wp) exit
                end do
                if (lam > 1.0e12_wp .or. f0 - f1 <= 1.0e-14_wp * f0) exit
            end do
            do i = 1, n
                r(i) = abs(compact_model(im, c, a(i), l(i)) - y(i)) * sc(i)
            end do
            rm = maxval(r)
            if (rm < bestmax) then
                bestmax = rm
                best = c
            end if
            ! Lawson: weights grow where the error is large
            wt = wt * sqrt(r / rm + 1.0e-3_wp)
            wt = wt / maxval(wt)
        end do
        c = best
        maxerr = bestmax
    end subroutine fit_compact

    !> sum_j c_j t^j by Horner's rule (the evaluation of hertzdamp_fit).
    pure real(wp) function horner(c, t) result(y)
        real(wp), intent(in) :: c(0:), t
        integer :: j
        y = c(ubound(c, 1))
        do j = ubound(c, 1) - 1, 0, -1
            y = y * t + c(j)
        end do
    end function horner

    !> Exact value of a quantity at alpha = 0.
    real(wp) function limit_at_zero(q, law) result(y)
        integer, intent(in) :: q, law
        select case (q)
        case (Q_ALPHA_OVER_L); y = 1.0_wp / hertzdamp_e1(law)
        case (Q_TAU_C); y = tc0
        case (Q_Z_MAX); y = 1.25_wp**0.4_wp
        case (Q_TAU_MAX); y = 0.5_wp * tc0
        case (Q_L_OVER_ALPHA); y = hertzdamp_e1(law)
        case default; y = 0.0_wp
        end select
    end function limit_at_zero

    pure subroutine cheb_row(t, deg, row)
        real(wp), intent(in) :: t
        integer, intent(in) :: deg
        real(wp), intent(out) :: row(0:deg)
        integer :: j
        row(0) = 1.0_wp
        if (deg >= 1) row(1) = t
        do j = 2, deg
            row(j) = 2.0_wp * t * row(j - 1) - row(j - 2)
        end do
    end subroutine cheb_row

    !> Chebyshev coefficients to monomial coefficients on the same variable.
    pure subroutine cheb_to_mono(cheb, mono)
        real(wp), intent(in) :: cheb(0:)
        real(wp), intent(out) :: mono(0:)
        real(wp) :: tm1(0:size(cheb) - 1), t0(0:size(cheb) - 1), tn(0:size(cheb) - 1)
        integer :: n, j
        n = size(cheb) - 1
        mono = 0.0_wp
        tm1 = 0.0_wp
        t0 = 0.0_wp
        tm1(0) = 1.0_wp                 ! T_0
        mono = cheb(0) * tm1
        if (n == 0) return
        t0(1) = 1.0_wp                  ! T_1
        mono = mono + cheb(1) * t0
        do j = 2, n
            tn = 0.0_wp
            tn(1:n) = 2.0_wp * t0(0:n - 1)
            tn = tn - tm1
            mono = mono + cheb(j) * tn
            tm1 = t0
            t0 = tn
        end do
    end subroutine cheb_to_mono

    function g(x) result(s)
        real(wp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=32) :: buf
        write (buf, '(es10.3)') x
        s = trim(adjustl(buf))
    end function g

    function r2s(x) result(s)
        real(wp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=40) :: buf
        write (buf, '(es25.17e3)') x
        s = trim(adjustl(buf))
    end function r2s

    function i2s(i) result(s)
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        character(len=16) :: buf
        write (buf, '(i0)') i
        s = trim(buf)
    end function i2s

    function join(x) result(s)
        real(wp), intent(in) :: x(:)
        character(len=:), allocatable :: s
        integer :: i
        s = r2s(x(1))
        do i = 2, size(x)
            s = s // ',' // r2s(x(i))
        end do
    end function join

end program gen_fit
