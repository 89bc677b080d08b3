!> Pade approximants of the collision series (LAPACK dgesv) and their
!> measurement against jet-free reference solutions.
module hertzdamp_gen_pade
    use hertzdamp_gen_jets, only: gk
    use hertzdamp_gen_expand, only: expand_result
    use hertzdamp_gen_reference, only: reference_collision
    use, intrinsic :: iso_fortran_env, only: real64, output_unit
    implicit none (type, external)
    private

    integer, parameter :: dp = real64

    interface
        !> LAPACK: solve A X = B by LU with partial pivoting.
        subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
            import :: real64
            implicit none (type, external)
            integer, intent(in) :: n, nrhs, lda, ldb
            real(real64), intent(inout) :: a(lda, n), b(ldb, nrhs)
            integer, intent(out) :: ipiv(n), info
        end subroutine dgesv
    end interface

    public :: pade_study, pade_coeffs, pade_value

contains

    !> [l/m] Pade approximant p/q (q_0 = 1) of the series c(0:), by dgesv on
    !>   sum_{j=0..m} q_j c_{l+i-j} = 0,  i = 1..m;   p_i = sum_{j<=min(i,m)} q_j c_{i-j}.
    subroutine pade_coeffs(c, l, m, p, q, info)
        real(dp), intent(in) :: c(0:)     !! series coefficients, at least 0..l+m
        integer, intent(in) :: l, m       !! numerator and denominator degrees
        real(dp), intent(out) :: p(0:l)   !! numerator
        real(dp), intent(out) :: q(0:m)   !! denominator, q(0) = 1
        integer, intent(out) :: info      !! dgesv status (0 = ok)
        real(dp) :: a(max(m, 1), max(m, 1)), b(max(m, 1), 1)
        integer :: ipiv(max(m, 1)), i, j
        q = 0.0_dp
        q(0) = 1.0_dp
        info = 0
        if (m > 0) then
            do i = 1, m
                do j = 1, m
                    a(i, j) = cget(l + i - j)
                end do
                b(i, 1) = -cget(l + i)
            end do
            call dgesv(m, 1, a, m, ipiv, b, m, info)
            q(1:m) = b(1:m, 1)
        end if
        do i = 0, l
            p(i) = 0.0_dp
            do j = 0, min(i, m)
                p(i) = p(i) + q(j) * c(i - j)
            end do
        end do
    contains
        pure real(dp) function cget(k)
            integer, intent(in) :: k
            cget = 0.0_dp
            if (k >= 0) cget = c(k)
        end function cget
    end subroutine pade_coeffs

    !> Value of p(x)/q(x).
    pure real(dp) function pade_value(p, q, x)
        real(dp), intent(in) :: p(0:), q(0:), x  !! numerator, denominator, argument
        real(dp) :: np, nq
        integer :: k
        np = 0.0_dp
        do k = ubound(p, 1), 0, -1
            np = np * x + p(k)
        end do
        nq = 0.0_dp
        do k = ubound(q, 1), 0, -1
            nq = nq * x + q(k)
        end do
        pade_value = np / nq
    end function pade_value

    !> Build candidate approximants, measure them against reference solutions
    !> on [0, 0.8] (and, for information, up to 1.1), write the chosen ones to
    !> data/pade_coefficients.csv.
    subroutine pade_study(n, r, ee, ec, ez, et, outdir)
        integer, intent(in) :: n                     !! series degree
        type(expand_result), intent(in) :: r         !! coefficients
        real(gk), intent(in) :: ee(0:), ec(0:), ez(0:), et(0:)  !! coefficient errors
        character(len=*), intent(in) :: outdir       !! directory of the output CSV
        integer, parameter :: ng = 81, nx = 16       ! grid on [0,0.8]; extension to 1.1
        integer, parameter :: le = 12, l2 = 11, lz = 8, lz2 = 7  ! chosen degrees [l/l]
        integer, parameter :: ncol = 16
        real(gk) :: alq, req, rtq, rzq, rmq
        real(dp) :: x(ng + nx), ref(ng + nx, 4)
        real(dp) :: c(0:n, 4), cerr(0:n, 4)
        real(dp) :: tab(0:le, ncol), errmax(4), errest(4), errmax2(4), errx(4), qmin(4), v1, v2, xx
        integer :: ldeg(4), ldeg2(4)
        character(len=8), parameter :: qname(4) = [character(len=8) :: 'e', 'tau_c', &
            'z_max', 'tau_max']
        logical :: ok, allok
        integer :: i, k, iq, info, u
        allok = .true.
        do i = 1, ng + nx
            if (i <= ng) then
                x(i) = 0.8_dp * (i - 1) / (ng - 1)
            else
                x(i) = 0.8_dp + 0.3_dp * (i - ng) / nx
            end if
            alq = real(x(i), gk)
            call reference_collision(alq, req, rtq, rzq, rmq, ok)
            if (.not. ok) then
                write (output_unit, '(a,f8.4)') '  reference failed at alpha =', x(i)
                allok = .false.
            end if
            ref(i, :) = real([req, rtq, rzq, rmq], dp)
        end do
        c(:, 1) = real(r%e, dp); c(:, 2) = real(r%tau_c, dp)
        c(:, 3) = real(r%z_max, dp); c(:, 4) = real(r%tau_max, dp)
        cerr(:, 1) = real(ee, dp); cerr(:, 2) = real(ec, dp)
        cerr(:, 3) = real(ez, dp); cerr(:, 4) = real(et, dp)
        write (output_unit, &
            '(a)') 'truncated series vs reference (relative error of e, tau_c, z_max, tau_max):'
        do i = 1, ng, 10
            write (output_unit, '(f6.2,4es12.3)') x(i), (abs(poly(c(:, iq), x(i)) / ref(i, &
                iq) - 1), iq = 1, 4)
        end do
        write (output_unit, &
            '(a)') 'Pade [l/l] of the plain series in alpha, max relative error on [0, 0.8]:'
        write (output_unit, '(a)') '   l     e          tau_c      z_max      tau_max'
        do k = 5, n / 2
            write (output_unit, '(i4,4es11.2)') k, (maxerr(c(:, iq), k, ref(1:ng, iq), &
                x(1:ng)), iq = 1, 4)
        end do
        ! chosen approximants: primary [l/l], secondary [l-1/l-1] for the error estimate
        ldeg = [le, le, lz, lz]
        ldeg2 = [l2, l2, lz2, lz2]
        tab = 0.0_dp
        do iq = 1, 4
            call pade_coeffs(c(:, iq), ldeg(iq), ldeg(iq), tab(0:ldeg(iq), 4 * iq - 3), &
                             tab(0:ldeg(iq), 4 * iq - 2), info)
            if (info /= 0) write (output_unit, '(a,i0)') '  dgesv failed, info = ', info
            call pade_coeffs(c(:, iq), ldeg2(iq), ldeg2(iq), tab(0:ldeg2(iq), 4 * iq - 1), &
                             tab(0:ldeg2(iq), 4 * iq), info)
            if (info /= 0) write (output_unit, '(a,i0)') '  dgesv failed, info = ', info
            errmax(iq) = 0.0_dp
            errmax2(iq) = 0.0_dp
            errest(iq) = 0.0_dp
            errx(iq) = 0.0_dp
            do i = 1, ng + nx
                v1 = pade_value(tab(:, 4 * iq - 3), tab(:, 4 * iq - 2), x(i))
                v2 = pade_value(tab(:, 4 * iq - 1), tab(:, 4 * iq), x(i))
                if (i <= ng) then
                    errmax(iq) = max(errmax(iq), abs(v1 / ref(i, iq) - 1))
                    errmax2(iq) = max(errmax2(iq), abs(v2 / ref(i, iq) - 1))
                    errest(iq) = max(errest(iq), abs(v1 / v2 - 1))
                else
                    errx(iq) = max(errx(iq), abs(v1 / ref(i, iq) - 1))
                end if
            end do
            ! first sign change of either denominator on a fine grid of [0, 2]
            qmin(iq) = 2.0_dp
            do i = 0, 20000
                xx = 2.0_dp * i / 20000
                if (poly(tab(:, 4 * iq - 2), xx) <= 0.0_dp .or. poly(tab(:, 4 * iq), &
                    xx) <= 0.0_dp) then
                    qmin(iq) = xx
                    exit
                end if
            end do
        end do
        write (output_unit, &
            '(a)') 'chosen Pade approximants (max rel err on [0,0.8]; estimate; secondary; [0.8,1.1]; first pole):'
        do iq = 1, 4
            write (output_unit, '(a8,2(a,i0),5es11.2)') qname(iq), ' [', ldeg(iq), '/', ldeg(iq), &
                errmax(iq), errest(iq), errmax2(iq), errx(iq), qmin(iq)
        end do
        if (.not. allok) write (output_unit, '(a)') 'WARNING: some reference solutions failed'

        open (newunit=u, file=outdir // '/pade_coefficients.csv', status='replace', action='write')
        write (u, '(a)') '# Pade approximants P(alpha) = num(alpha)/den(alpha) = sum_k num_k alpha^k / sum_k den_k alpha^k'
        write (u, '(a)') '# of the overlap-definition series in data/series_coefficients.csv (den_0 = 1).'
        write (u, '(a)') '# Generated by hertzdamp-gen-series (gen/series/gen_series.f90): do not edit.'
        write (u, '(a)') '# Method: [l/l] from the Taylor coefficients 0..2l by LAPACK dgesv on the'
        write (u, '(a)') '#   linear system sum_j den_j c_{l+i-j} = 0 (i = 1..l), then num_i = sum_j den_j c_{i-j}.'
        write (u, '(a)') '# Columns <q>_num, <q>_den: primary [L/L]; <q>_num2, <q>_den2: secondary [L-1/L-1]'
        write (u, '(a)') '#   (their difference is the run-time error estimate).  Rows are k = 0..12, zero padded.'
        do iq = 1, 4
            write (u, '(a,a8,a,i0,a,i0,a,i0,a,i0,a,es9.2,a,es9.2,a,es9.2,a,es9.2)') '# ', &
                qname(iq), &
                ': [', ldeg(iq), '/', ldeg(iq), '] and [', ldeg2(iq), '/', ldeg2(iq), &
                '], max rel err vs reference on [0,0.8]: ', errmax(iq), ' (secondary ', &
                    errmax2(iq), &
                '), max |P1/P2-1| ', errest(iq), ', on [0.8,1.1]: ', errx(iq)
        end do
        write (u, '(a)') '# Reference: jet-free quad-precision Taylor integration with local series at both'
        write (u, '(a)') '#   ends (gen/series/hertzdamp_gen_reference.f90), alpha = 0, 0.01, ..., 0.8 and 16 points to 1.1.'
        write (u, '(a,4f7.3)') '# First positive zero of a denominator (e, tau_c, z_max, tau_max; 2 = none below 2):', qmin
        write (u, '(a)') 'k,e_num,e_den,e_num2,e_den2,tau_c_num,tau_c_den,tau_c_num2,tau_c_den2,' // &
            'z_max_num,z_max_den,z_max_num2,z_max_den2,tau_max_num,tau_max_den,tau_max_num2,tau_max_den2'
        do k = 0, le
            write (u, '(i0,16(",",es25.17))') k, tab(k, :)
        end do
        close (u)
        write (output_unit, '(a)') 'wrote ' // outdir // '/pade_coefficients.csv'
        if (.false.) write (output_unit, *) cerr(0, 1)
    contains
        pure real(dp) function poly(cc, xv)
            real(dp), intent(in) :: cc(0:), xv
            integer :: j
            poly = 0.0_dp
            do j = ubound(cc, 1), 0, -1
                poly = poly * xv + cc(j)
            end do
        end function poly
        real(dp) function maxerr(cc, l, rr, xs)
            real(dp), intent(in) :: cc(0:), rr(:), xs(:)
            integer, intent(in) :: l
            real(dp) :: p(0:l), q(0:l)
            integer :: j, inf
            call pade_coeffs(cc, l, l, p, q, inf)
            maxerr = 0.0_dp
            do j = 1, size(xs)
                maxerr = max(maxerr, abs(pade_value(p, q, xs(j)) / rr(j) - 1))
            end do
        end function maxerr
    end subroutine pade_study

end module hertzdamp_gen_pade
