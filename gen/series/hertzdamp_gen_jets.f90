!> Truncated power series ("jets") in one variable, in quadruple precision.
!>
!> A jet of degree n is an array `a(0:n)` holding the Taylor coefficients
!> a_0 + a_1 x + ... + a_n x^n; every operation is exact up to x^n (no
!> truncation error, only rounding).  Used by the series generator only.
module hertzdamp_gen_jets
    implicit none (type, external)
    private

    !> Real kind of the generator: IEEE quadruple precision (113-bit mantissa).
    integer, parameter, public :: gk = selected_real_kind(30)

    public :: jmul, jdiv, jpow, jexp, jlog, jcompose, jhorner, jshift, jconst

contains

    !> Constant jet of degree n with value c.
    pure function jconst(c, n) result(r)
        real(gk), intent(in) :: c   !! constant value
        integer, intent(in) :: n    !! degree
        real(gk) :: r(0:n)
        r = 0.0_gk
        r(0) = c
    end function jconst

    !> Product of two jets of the same degree.
    pure function jmul(a, b) result(c)
        real(gk), intent(in) :: a(0:)  !! first factor
        real(gk), intent(in) :: b(0:)  !! second factor (same degree)
        real(gk) :: c(0:ubound(a, 1))
        integer :: k, n
        n = ubound(a, 1)
        do k = 0, n
            c(k) = sum(a(0:k) * b(k:0:-1))
        end do
    end function jmul

    !> Multiplication by the variable x (shift up, truncating at degree n).
    pure function jshift(a) result(c)
        real(gk), intent(in) :: a(0:)  !! jet
        real(gk) :: c(0:ubound(a, 1))
        integer :: n
        n = ubound(a, 1)
        c(0) = 0.0_gk
        if (n > 0) c(1:n) = a(0:n - 1)
    end function jshift

    !> Quotient a/b of two jets (b_0 /= 0).
    pure function jdiv(a, b) result(c)
        real(gk), intent(in) :: a(0:)  !! numerator
        real(gk), intent(in) :: b(0:)  !! denominator, b(0) /= 0
        real(gk) :: c(0:ubound(a, 1))
        integer :: k
        do k = 0, ubound(a, 1)
            c(k) = (a(k) - sum(b(1:k) * c(k - 1:0:-1))) / b(0)
        end do
    end function jdiv

    !> Power a**g of a jet with a_0 > 0:  k a_0 q_k = sum_{j=1..k} (g j - (k-j)) a_j q_{k-j}.
    pure function jpow(a, g) result(q)
        real(gk), intent(in) :: a(0:)  !! base, a(0) > 0
        real(gk), intent(in) :: g      !! exponent
        real(gk) :: q(0:ubound(a, 1))
        integer :: k, j
        real(gk) :: s
        q(0) = a(0)**g
        do k = 1, ubound(a, 1)
            s = 0.0_gk
            do j = 1, k
                s = s + (g * j - (k - j)) * a(j) * q(k - j)
            end do
            q(k) = s / (k * a(0))
        end do
    end function jpow

    !> Exponential of a jet:  k e_k = sum_{j=1..k} j a_j e_{k-j}.
    pure function jexp(a) result(r)
        real(gk), intent(in) :: a(0:)  !! exponent
        real(gk) :: r(0:ubound(a, 1))
        integer :: k, j
        real(gk) :: s
        r(0) = exp(a(0))
        do k = 1, ubound(a, 1)
            s = 0.0_gk
            do j = 1, k
                s = s + j * a(j) * r(k - j)
            end do
            r(k) = s / k
        end do
    end function jexp

    !> Natural logarithm of a jet with a_0 > 0:  k a_0 l_k = k a_k - sum_{j=1..k-1} j l_j a_{k-j}.
    pure function jlog(a) result(l)
        real(gk), intent(in) :: a(0:)  !! argument, a(0) > 0
        real(gk) :: l(0:ubound(a, 1))
        integer :: k, j
        real(gk) :: s
        l(0) = log(a(0))
        do k = 1, ubound(a, 1)
            s = k * a(k)
            do j = 1, k - 1
                s = s - j * l(j) * a(k - j)
            end do
            l(k) = s / (k * a(0))
        end do
    end function jlog

    !> Composition f(g(x)) of a scalar power series f (coefficients f(0:n))
    !> with a jet g; exact to degree n when g(0) = 0.
    pure function jcompose(f, g) result(r)
        real(gk), intent(in) :: f(0:)  !! coefficients of the outer series
        real(gk), intent(in) :: g(0:)  !! inner jet
        real(gk) :: r(0:ubound(g, 1))
        integer :: k
        r = 0.0_gk
        do k = ubound(f, 1), 0, -1
            r = jmul(r, g)
            r(0) = r(0) + f(k)
        end do
    end function jcompose

    !> Horner evaluation of sum_k c(:,k) d^k where the coefficients c(:,k)
    !> and the argument d are jets (a series in t whose coefficients are jets in x).
    pure function jhorner(c, d) result(r)
        real(gk), intent(in) :: c(0:, 0:)  !! c(:,k): jet coefficient of t^k
        real(gk), intent(in) :: d(0:)      !! jet substituted for t
        real(gk) :: r(0:ubound(d, 1))
        integer :: k
        r = 0.0_gk
        do k = ubound(c, 2), 0, -1
            r = jmul(r, d) + c(:, k)
        end do
    end function jhorner

end module hertzdamp_gen_jets
