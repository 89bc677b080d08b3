!> An evaluator of the `alpha_expr` expressions of data/peers/peers_spec.csv, written
!> for the tests from the grammar of doc/peers.md section 0 and independent of the
!> program's own formulas (hertzdamp_check_model): a recursive-descent parser over
!>
!>     expr    := term   { ("+" | "-") term }
!>     term    := unary  { ("*" | "/") unary }
!>     unary   := "-" unary | power
!>     power   := primary [ "^" unary ]          (right-associative)
!>     primary := number | name | func "(" expr { "," expr } ")" | "(" expr ")"
!>
!> with the functions sqrt, ln, abs, max, min, beta, P6, thornton, Vstar, the constants pi and eps_d,
!> the derived name tstar = (m/(k*sqrt(u)))^(2/5) and any names bound by the caller.
module hertzdamp_test_expr
    use hertzdamp, only: hertzdamp_rk
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk
    real(wp), parameter :: pi = acos(-1.0_wp)

    !> Named values.
    type, public :: expr_vars
        character(len=16) :: name(40) = ''
        real(wp) :: val(40) = 0.0_wp
        integer :: n = 0
    contains
        procedure :: set => vars_set
    end type expr_vars

    !> Parser state.
    type :: parser
        character(len=:), allocatable :: s
        integer :: i = 1
        logical :: ok = .true.
        character(len=:), allocatable :: err
    end type parser

    public :: expr_eval

contains

    subroutine vars_set(self, name, val)
        class(expr_vars), intent(inout) :: self
        character(len=*), intent(in) :: name
        real(wp), intent(in) :: val
        integer :: j
        do j = 1, self%n
            if (self%name(j) == name) then
                self%val(j) = val
                return
            end if
        end do
        self%n = self%n + 1
        self%name(self%n) = name
        self%val(self%n) = val
    end subroutine vars_set

    !> Value of the expression; ok = .false. (and err says why) on a syntax error or
    !> an unbound name.
    function expr_eval(text, vars, ok, err) result(x)
        character(len=*), intent(in) :: text
        type(expr_vars), intent(in) :: vars
        logical, intent(out) :: ok
        character(len=:), allocatable, intent(out) :: err
        real(wp) :: x
        type(parser) :: p
        p%s = text
        p%err = ''
        x = expr(p, vars)
        call skip(p)
        if (p%ok .and. p%i <= len(p%s)) call bad(p, 'trailing text at ' // p%s(p%i:))
        ok = p%ok
        err = p%err
    end function expr_eval

    subroutine bad(p, msg)
        type(parser), intent(inout) :: p
        character(len=*), intent(in) :: msg
        if (p%ok) p%err = msg
        p%ok = .false.
    end subroutine bad

    subroutine skip(p)
        type(parser), intent(inout) :: p
        do while (p%i <= len(p%s))
            if (p%s(p%i:p%i) /= ' ') exit
            p%i = p%i + 1
        end do
    end subroutine skip

    logical function at(p, c)
        type(parser), intent(inout) :: p
        character, intent(in) :: c
        call skip(p)
        at = .false.
        if (p%i <= len(p%s)) at = p%s(p%i:p%i) == c
    end function at

    recursive function expr(p, v) result(x)
        type(parser), intent(inout) :: p
        type(expr_vars), intent(in) :: v
        real(wp) :: x
        x = term(p, v)
        do while (p%ok)
            if (at(p, '+')) then
                p%i = p%i + 1
                x = x + term(p, v)
            else if (at(p, '-')) then
                p%i = p%i + 1
                x = x - term(p, v)
            else
                exit
            end if
        end do
    end function expr

    recursive function term(p, v) result(x)
        type(parser), intent(inout) :: p
        type(expr_vars), intent(in) :: v
        real(wp) :: x
        x = unary(p, v)
        do while (p%ok)
            if (at(p, '*')) then
                p%i = p%i + 1
                x = x * unary(p, v)
            else if (at(p, '/')) then
                p%i = p%i + 1
                x = x / unary(p, v)
            else
                exit
            end if
        end do
    end function term

    recursive function unary(p, v) result(x)
        type(parser), intent(inout) :: p
        type(expr_vars), intent(in) :: v
        real(wp) :: x
        if (at(p, '-')) then
            p%i = p%i + 1
            x = -unary(p, v)
        else
            x = power(p, v)
        end if
    end function unary

    recursive function power(p, v) result(x)
        type(parser), intent(inout) :: p
        type(expr_vars), intent(in) :: v
        real(wp) :: x
        x = primary(p, v)
        if (.not. p%ok) return
        if (at(p, '^')) then
            p%i = p%i + 1
            x = x**unary(p, v)
        end if
    end function power

    recursive function primary(p, v) result(x)
        type(parser), intent(inout) :: p
        type(expr_vars), intent(in) :: v
        real(wp) :: x
        character(len=:), allocatable :: name
        real(wp) :: args(4)
        integer :: j, na, ios
        x = 0.0_wp
        if (.not. p%ok) return
        call skip(p)
        if (p%i > len(p%s)) then
            call bad(p, 'unexpected end')
            return
        end if
        if (at(p, '(')) then
            p%i = p%i + 1
            x = expr(p, v)
            if (.not. at(p, ')')) then
                call bad(p, 'missing )')
                return
            end if
            p%i = p%i + 1
            return
        end if
        j = p%i
        if (is_digit(p%s(j:j)) .or. p%s(j:j) == '.') then
            do while (j <= len(p%s))
                if (.not. (is_digit(p%s(j:j)) .or. p%s(j:j) == '.')) exit
                j = j + 1
            end do
            if (j <= len(p%s)) then
                if (p%s(j:j) == 'e' .or. p%s(j:j) == 'E') then
                    j = j + 1
                    if (j <= len(p%s)) then
                        if (p%s(j:j) == '+' .or. p%s(j:j) == '-') j = j + 1
                    end if
                    do while (j <= len(p%s))
                        if (.not. is_digit(p%s(j:j))) exit
                        j = j + 1
                    end do
                end if
            end if
            read (p%s(p%i:j - 1), *, iostat=ios) x
            if (ios /= 0) call bad(p, 'bad number ' // p%s(p%i:j - 1))
            p%i = j
            return
        end if
        do while (j <= len(p%s))
            if (.not. is_name(p%s(j:j))) exit
            j = j + 1
        end do
        if (j == p%i) then
            call bad(p, 'unexpected ' // p%s(p%i:p%i))
            return
        end if
        name = p%s(p%i:j - 1)
        p%i = j
        if (at(p, '(')) then
            p%i = p%i + 1
            na = 0
            do
                na = na + 1
                if (na > size(args)) then
                    call bad(p, 'too many arguments')
                    return
                end if
                args(na) = expr(p, v)
                if (.not. p%ok) return
                if (at(p, ',')) then
                    p%i = p%i + 1
                    cycle
                end if
                exit
            end do
            if (.not. at(p, ')')) then
                call bad(p, 'missing ) after arguments of ' // name)
                return
            end if
            p%i = p%i + 1
            x = call_function(p, name, args(1:na))
        else
            x = lookup(p, name, v)
        end if
    end function primary

    function call_function(p, name, a) result(x)
        type(parser), intent(inout) :: p
        character(len=*), intent(in) :: name
        real(wp), intent(in) :: a(:)
        real(wp) :: x, l
        x = 0.0_wp
        select case (name)
        case ('sqrt'); x = sqrt(a(1))
        case ('ln'); x = log(a(1))
        case ('abs'); x = abs(a(1))
        case ('max'); x = maxval(a)
        case ('min'); x = minval(a)
        case ('beta')
            ! -ln x / sqrt(pi^2 + ln^2 x), beta(0) := 1 (doc/peers.md section 0)
            if (a(1) == 0.0_wp) then
                x = 1.0_wp
            else
                l = log(a(1))
                x = -l / sqrt(pi * pi + l * l)
            end if
        case ('P6')
            ! 1.2728 - 4.2783 x + 11.087 x^2 - 22.348 x^3 + 27.467 x^4 - 18.022 x^5 + 4.8218 x^6
            x = 4.8218_wp
            x = x * a(1) - 18.022_wp
            x = x * a(1) + 27.467_wp
            x = x * a(1) - 22.348_wp
            x = x * a(1) + 11.087_wp
            x = x * a(1) - 4.2783_wp
            x = x * a(1) + 1.2728_wp
        case ('thornton')
            ! sqrt(1/(1 - (1+e)^2 exp(a)) - 1), a = sum_i h_i e^i (Thornton et al. 2013, (B6)-(B7);
            ! doc/peers.md section 0), written as a plain power sum
            x = thornton(a(1))
        case ('Vstar')
            ! the V >= 0 with Pade(V) = e (doc/peers.md section 0): Newton from V = 0.5 as Yade's
            ! getVstar, on a power-sum Pade and its quotient-rule derivative
            x = vstar(a(1))
        case default
            call bad(p, 'unknown function ' // name)
        end select
    end function call_function

    real(wp) function thornton(e) result(x)
        real(wp), intent(in) :: e
        real(wp), parameter :: h(10) = [-6.918798_wp, -16.41105_wp, 146.8049_wp, -796.4559_wp, 2928.711_wp, &
                                        -7206.864_wp, 11494.29_wp, -11342.18_wp, 6276.757_wp, -1489.915_wp]
        real(wp) :: a
        integer :: i
        if (e == 1.0_wp) then
            x = 0.0_wp
            return
        end if
        a = 0.0_wp
        do i = 1, 10
            a = a + h(i) * e**i
        end do
        x = sqrt(1.0_wp / (1.0_wp - (1.0_wp + e)**2 * exp(a)) - 1.0_wp)
    end function thornton

    real(wp) function vstar(e) result(v)
        real(wp), intent(in) :: e
        real(wp), parameter :: ca(0:3) = [1.0_wp, 1.07232_wp, 0.574198_wp, 0.141552_wp]
        real(wp), parameter :: cb(0:6) = [1.0_wp, 1.07232_wp, 1.72765_wp, 1.37842_wp, 1.19449_wp, 0.467273_wp, &
                                          0.235585_wp]
        real(wp) :: pa, pb, da, db, step
        integer :: it, i
        v = 0.0_wp
        if (e == 1.0_wp) return
        v = 0.5_wp
        do it = 1, 200
            pa = 0.0_wp
            da = 0.0_wp
            do i = 0, 3
                pa = pa + ca(i) * v**i
                if (i > 0) da = da + i * ca(i) * v**(i - 1)
            end do
            pb = 0.0_wp
            db = 0.0_wp
            do i = 0, 6
                pb = pb + cb(i) * v**i
                if (i > 0) db = db + i * cb(i) * v**(i - 1)
            end do
            step = (pa / pb - e) / ((da * pb - pa * db) / pb**2)
            v = v - step
            if (abs(step) <= 1.0e-15_wp * max(1.0_wp, abs(v))) exit
        end do
    end function vstar

    recursive function lookup(p, name, v) result(x)
        type(parser), intent(inout) :: p
        character(len=*), intent(in) :: name
        type(expr_vars), intent(in) :: v
        real(wp) :: x
        integer :: j
        x = 0.0_wp
        select case (name)
        case ('pi')
            x = pi
            return
        case ('eps_d')
            x = 2.220446049250313e-16_wp
            return
        case ('tstar')
            ! (m / (k*sqrt(u)))^(2/5)
            x = (lookup(p, 'm', v) / (lookup(p, 'k', v) * sqrt(lookup(p, 'u', v))))**(2.0_wp / 5.0_wp)
            return
        case default
        end select
        do j = 1, v%n
            if (v%name(j) == name) then
                x = v%val(j)
                return
            end if
        end do
        call bad(p, 'unbound name ' // name)
    end function lookup

    pure logical function is_digit(c)
        character, intent(in) :: c
        is_digit = c >= '0' .and. c <= '9'
    end function is_digit

    pure logical function is_name(c)
        character, intent(in) :: c
        is_name = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z') .or. (c >= '0' .and. c <= '9') .or. c == '_'
    end function is_name

end module hertzdamp_test_expr
