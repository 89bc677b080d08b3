!> Named numbers and strings (`text_vars`) and an expression evaluator for the
!> arithmetic the engines' inputs allow (`text_eval`): LAMMPS equal-style variables and
!> `$(...)`, Python assignments in Yade scripts, MFiX `@(...)`.  A recursive-descent
!> parser, in time linear in the expression; errors come back as a message naming the
!> culprit ('' when none), and a result is finite or an error.
module hertzdamp_text_expr
    use hertzdamp_text_list, only: text_string
    use hertzdamp_text_map, only: text_map
    use hertzdamp_text_parse, only: text_number
    use hertzdamp_text_format, only: lower
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use, intrinsic :: iso_fortran_env, only: real64
    implicit none
    private

    integer, parameter :: wp = real64
    real(wp), parameter :: pi = acos(-1.0_wp)

    !> Expression syntaxes of text_eval.
    integer, parameter, public :: SYNTAX_LAMMPS = 1  !! ^ power, v_name, PI, ln/log, && || !
    integer, parameter, public :: SYNTAX_PYTHON = 2  !! ** power, math.x, pi, log = ln
    integer, parameter, public :: SYNTAX_MFIX = 3    !! MFiX @(...): ** and ^ power, d exponents, pi

    !> Named numbers and strings for text_eval (the variables of a deck).
    type, public :: text_vars
        type(text_map) :: map
        real(wp), allocatable :: x(:)            !! value of a numeric variable
        logical, allocatable :: numeric(:)       !! x holds it (else text does)
        type(text_string), allocatable :: text(:)  !! a string value, or why there is no number
        integer :: n = 0
    contains
        procedure :: set_num => vars_set_num     !! name = number
        procedure :: set_text => vars_set_text   !! name = string (numeric when it reads as a number)
        procedure :: find => vars_find           !! index of a name, 0 if absent
    end type text_vars

    public :: text_eval

contains

    !> Index of a variable, appending it when new.
    integer function vars_slot(self, name) result(i)
        class(text_vars), intent(inout) :: self
        character(len=*), intent(in) :: name
        real(wp), allocatable :: x(:)
        logical, allocatable :: b(:)
        type(text_string), allocatable :: t(:)
        integer :: m
        i = self%map%get(name)
        if (i > 0) return
        if (.not. allocated(self%x)) allocate (self%x(8), self%numeric(8), self%text(8))
        if (self%n == size(self%x)) then
            m = 2 * size(self%x)
            allocate (x(m), b(m), t(m))
            x(1:self%n) = self%x(1:self%n)
            b(1:self%n) = self%numeric(1:self%n)
            t(1:self%n) = self%text(1:self%n)
            call move_alloc(x, self%x)
            call move_alloc(b, self%numeric)
            call move_alloc(t, self%text)
        end if
        self%n = self%n + 1
        i = self%n
        call self%map%put(name, i)
    end function vars_slot

    subroutine vars_set_num(self, name, x)
        class(text_vars), intent(inout) :: self
        character(len=*), intent(in) :: name
        real(wp), intent(in) :: x
        integer :: i
        i = vars_slot(self, name)
        self%x(i) = x
        self%numeric(i) = .true.
        self%text(i)%s = ''      ! a number: no text (text_g15 formats it where a deck substitutes it)
    end subroutine vars_set_num

    !> A string variable; it is numeric too when the whole string reads as a number.
    subroutine vars_set_text(self, name, s)
        class(text_vars), intent(inout) :: self
        character(len=*), intent(in) :: name, s
        integer :: i
        real(wp) :: x
        i = vars_slot(self, name)
        self%text(i)%s = s
        self%numeric(i) = text_number(s, x)
        self%x(i) = 0.0_wp
        if (self%numeric(i)) self%x(i) = x
    end subroutine vars_set_text

    integer function vars_find(self, name) result(i)
        class(text_vars), intent(inout) :: self
        character(len=*), intent(in) :: name
        i = self%map%get(name)
    end function vars_find

    ! ------------------------------------------------------------------ expressions

    !> Evaluate an arithmetic expression: numbers, variables (`vars`), + - * / and the
    !> power of the syntax, unary minus and plus, parentheses, comparisons and logic
    !> (result 1 or 0), and the functions sqrt exp ln log log10 abs sin cos tan asin acos
    !> atan atan2 floor ceil round min max pow radians degrees.  Names the deck has not
    !> defined give a message naming them; the result is finite or an error.
    subroutine text_eval(text, syntax, vars, x, msg)
        character(len=*), intent(in) :: text
        integer, intent(in) :: syntax             !! SYNTAX_*
        type(text_vars), intent(inout) :: vars
        real(wp), intent(out) :: x
        character(len=:), allocatable, intent(out) :: msg
        integer :: pos
        msg = ''
        pos = 1
        call parse_or(text, pos, syntax, vars, x, msg)
        if (len(msg) == 0) then
            call skip_blanks(text, pos)
            if (pos <= len(text)) msg = 'unexpected "' // text(pos:) // '" in "' // text // '"'
        end if
        if (len(msg) == 0 .and. .not. ieee_is_finite(x)) msg = '"' // text // '" is not a finite number'
        if (len(msg) > 0) x = 0.0_wp
    end subroutine text_eval

    subroutine skip_blanks(t, pos)
        character(len=*), intent(in) :: t
        integer, intent(inout) :: pos
        do while (pos <= len(t))
            if (t(pos:pos) /= ' ' .and. t(pos:pos) /= achar(9)) exit
            pos = pos + 1
        end do
    end subroutine skip_blanks

    !> Whether the text at pos starts with op (after blanks); consumes it if so.
    logical function accept(t, pos, op)
        character(len=*), intent(in) :: t, op
        integer, intent(inout) :: pos
        call skip_blanks(t, pos)
        accept = .false.
        if (pos + len(op) - 1 > len(t)) return
        if (t(pos:pos + len(op) - 1) /= op) return
        ! '*' is not '**', '<' not '<=', '=' alone is no operator
        if (op == '*' .or. op == '<' .or. op == '>' .or. op == '!') then
            if (pos + 1 <= len(t)) then
                if (op == '*' .and. t(pos + 1:pos + 1) == '*') return
                if (op /= '*' .and. t(pos + 1:pos + 1) == '=') return
            end if
        end if
        accept = .true.
        pos = pos + len(op)
    end function accept

    recursive subroutine parse_or(t, pos, syn, vars, x, msg)
        character(len=*), intent(in) :: t
        integer, intent(inout) :: pos
        integer, intent(in) :: syn
        type(text_vars), intent(inout) :: vars
        real(wp), intent(out) :: x
        character(len=:), allocatable, intent(inout) :: msg
        real(wp) :: y
        call parse_and(t, pos, syn, vars, x, msg)
        do while (len(msg) == 0)
            if (.not. accept(t, pos, '||')) exit
            call parse_and(t, pos, syn, vars, y, msg)
            x = merge(1.0_wp, 0.0_wp, x /= 0.0_wp .or. y /= 0.0_wp)
        end do
    end subroutine parse_or

    recursive subroutine parse_and(t, pos, syn, vars, x, msg)
        character(len=*), intent(in) :: t
        integer, intent(inout) :: pos
        integer, intent(in) :: syn
        type(text_vars), intent(inout) :: vars
        real(wp), intent(out) :: x
        character(len=:), allocatable, intent(inout) :: msg
        real(wp) :: y
        call parse_compare(t, pos, syn, vars, x, msg)
        do while (len(msg) == 0)
            if (.not. accept(t, pos, '&&')) exit
            call parse_compare(t, pos, syn, vars, y, msg)
            x = merge(1.0_wp, 0.0_wp, x /= 0.0_wp .and. y /= 0.0_wp)
        end do
    end subroutine parse_and

    recursive subroutine parse_compare(t, pos, syn, vars, x, msg)
        character(len=*), intent(in) :: t
        integer, intent(inout) :: pos
        integer, intent(in) :: syn
        type(text_vars), intent(inout) :: vars
        real(wp), intent(out) :: x
        character(len=:), allocatable, intent(inout) :: msg
        real(wp) :: y
        integer :: k
        character(len=2), parameter :: ops(6) = ['<=', '>=', '==', '!=', '< ', '> ']
        call parse_sum(t, pos, syn, vars, x, msg)
        do while (len(msg) == 0)
            do k = 1, size(ops)
                if (accept(t, pos, trim(ops(k)))) exit
            end do
            if (k > size(ops)) exit
            call parse_sum(t, pos, syn, vars, y, msg)
            select case (k)
            case (1); x = merge(1.0_wp, 0.0_wp, x <= y)
            case (2); x = merge(1.0_wp, 0.0_wp, x >= y)
            case (3); x = merge(1.0_wp, 0.0_wp, x == y)
            case (4); x = merge(1.0_wp, 0.0_wp, x /= y)
            case (5); x = merge(1.0_wp, 0.0_wp, x < y)
            case default; x = merge(1.0_wp, 0.0_wp, x > y)
            end select
        end do
    end subroutine parse_compare

    recursive subroutine parse_sum(t, pos, syn, vars, x, msg)
        character(len=*), intent(in) :: t
        integer, intent(inout) :: pos
        integer, intent(in) :: syn
        type(text_vars), intent(inout) :: vars
        real(wp), intent(out) :: x
        character(len=:), allocatable, intent(inout) :: msg
        real(wp) :: y
        call parse_product(t, pos, syn, vars, x, msg)
        do while (len(msg) == 0)
            if (accept(t, pos, '+')) then
                call parse_product(t, pos, syn, vars, y, msg)
                x = x + y
            else if (accept(t, pos, '-')) then
                call parse_product(t, pos, syn, vars, y, msg)
                x = x - y
            else
                exit
            end if
        end do
    end subroutine parse_sum

    recursive subroutine parse_product(t, pos, syn, vars, x, msg)
        character(len=*), intent(in) :: t
        integer, intent(inout) :: pos
        integer, intent(in) :: syn
        type(text_vars), intent(inout) :: vars
        real(wp), intent(out) :: x
        character(len=:), allocatable, intent(inout) :: msg
        real(wp) :: y
        call parse_unary(t, pos, syn, vars, x, msg)
        do while (len(msg) == 0)
            if (accept(t, pos, '*')) then
                call parse_unary(t, pos, syn, vars, y, msg)
                x = x * y
            else if (accept(t, pos, '/')) then
                call parse_unary(t, pos, syn, vars, y, msg)
                if (len(msg) == 0 .and. y == 0.0_wp) msg = 'division by zero in "' // t // '"'
                if (len(msg) == 0) x = x / y
            else if (accept(t, pos, '%')) then
                call parse_unary(t, pos, syn, vars, y, msg)
                if (len(msg) == 0 .and. y == 0.0_wp) msg = 'modulo by zero in "' // t // '"'
                if (len(msg) == 0) x = x - y * floor(x / y)
            else
                exit
            end if
        end do
    end subroutine parse_product

    !> Unary minus, plus and not bind looser than the power (-a^2 = -(a^2)).
    recursive subroutine parse_unary(t, pos, syn, vars, x, msg)
        character(len=*), intent(in) :: t
        integer, intent(inout) :: pos
        integer, intent(in) :: syn
        type(text_vars), intent(inout) :: vars
        real(wp), intent(out) :: x
        character(len=:), allocatable, intent(inout) :: msg
        if (accept(t, pos, '-')) then
            call parse_unary(t, pos, syn, vars, x, msg)
            x = -x
        else if (accept(t, pos, '+')) then
            call parse_unary(t, pos, syn, vars, x, msg)
        else if (accept(t, pos, '!')) then
            call parse_unary(t, pos, syn, vars, x, msg)
            x = merge(1.0_wp, 0.0_wp, x == 0.0_wp)
        else
            call parse_power(t, pos, syn, vars, x, msg)
        end if
    end subroutine parse_unary

    !> primary [pow unary]: right-associative (2^3^2 = 512).
    recursive subroutine parse_power(t, pos, syn, vars, x, msg)
        character(len=*), intent(in) :: t
        integer, intent(inout) :: pos
        integer, intent(in) :: syn
        type(text_vars), intent(inout) :: vars
        real(wp), intent(out) :: x
        character(len=:), allocatable, intent(inout) :: msg
        real(wp) :: y
        logical :: is_pow
        call parse_primary(t, pos, syn, vars, x, msg)
        if (len(msg) > 0) return
        is_pow = accept(t, pos, '**')
        if (.not. is_pow .and. syn /= SYNTAX_PYTHON) is_pow = accept(t, pos, '^')
        if (.not. is_pow) return
        call parse_unary(t, pos, syn, vars, y, msg)
        if (len(msg) > 0) return
        if (x < 0.0_wp .and. y /= aint(y)) then
            msg = 'negative number to a fractional power in "' // t // '"'
        else
            x = x**y
        end if
    end subroutine parse_power

    recursive subroutine parse_primary(t, pos, syn, vars, x, msg)
        character(len=*), intent(in) :: t
        integer, intent(inout) :: pos
        integer, intent(in) :: syn
        type(text_vars), intent(inout) :: vars
        real(wp), intent(out) :: x
        character(len=:), allocatable, intent(inout) :: msg
        integer :: start
        character(len=:), allocatable :: name
        x = 0.0_wp
        call skip_blanks(t, pos)
        if (pos > len(t)) then
            msg = 'incomplete expression "' // t // '"'
            return
        end if
        if (accept(t, pos, '(')) then
            call parse_or(t, pos, syn, vars, x, msg)
            if (len(msg) > 0) return
            if (.not. accept(t, pos, ')')) msg = 'missing ) in "' // t // '"'
            return
        end if
        start = pos
        if (is_digit(t(pos:pos)) .or. t(pos:pos) == '.') then
            call scan_number(t, pos, syn, x, msg)
            return
        end if
        do while (pos <= len(t))
            if (.not. (is_digit(t(pos:pos)) .or. is_letter(t(pos:pos)) .or. t(pos:pos) == '_' .or. &
                       t(pos:pos) == '.')) exit
            pos = pos + 1
        end do
        if (pos == start) then
            msg = 'unexpected "' // t(start:) // '" in "' // t // '"'
            return
        end if
        name = t(start:pos - 1)
        if (accept(t, pos, '(')) then
            call parse_call(t, pos, syn, vars, name, x, msg)
        else
            call lookup(name, syn, vars, t, x, msg)
        end if
    end subroutine parse_primary

    pure logical function is_digit(c)
        character, intent(in) :: c
        is_digit = c >= '0' .and. c <= '9'
    end function is_digit

    pure logical function is_letter(c)
        character, intent(in) :: c
        is_letter = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z')
    end function is_letter

    !> A number literal at pos (MFiX: d exponents too).
    subroutine scan_number(t, pos, syn, x, msg)
        character(len=*), intent(in) :: t
        integer, intent(inout) :: pos
        integer, intent(in) :: syn
        real(wp), intent(out) :: x
        character(len=:), allocatable, intent(inout) :: msg
        integer :: start
        character :: c
        start = pos
        do while (pos <= len(t))
            c = t(pos:pos)
            if (is_digit(c) .or. c == '.') then
                pos = pos + 1
            else if (c == 'e' .or. c == 'E' .or. (syn == SYNTAX_MFIX .and. (c == 'd' .or. c == 'D'))) then
                pos = pos + 1
                if (pos <= len(t)) then
                    if (t(pos:pos) == '+' .or. t(pos:pos) == '-') pos = pos + 1
                end if
            else
                exit
            end if
        end do
        if (.not. text_number(t(start:pos - 1), x, fortran_d=syn == SYNTAX_MFIX)) then
            msg = 'malformed number "' // t(start:pos - 1) // '" in "' // t // '"'
        end if
    end subroutine scan_number

    !> A name: a deck variable, or a constant of the syntax.
    subroutine lookup(name0, syn, vars, t, x, msg)
        character(len=*), intent(in) :: name0, t
        integer, intent(in) :: syn
        type(text_vars), intent(inout) :: vars
        real(wp), intent(out) :: x
        character(len=:), allocatable, intent(inout) :: msg
        character(len=:), allocatable :: name
        integer :: i
        x = 0.0_wp
        name = name0
        if (syn == SYNTAX_LAMMPS .and. len(name) > 2) then
            if (name(1:2) == 'v_') name = name(3:)
        end if
        if (syn == SYNTAX_PYTHON) name = python_name(name)
        i = vars%find(name)
        if (i > 0) then
            if (vars%numeric(i)) then
                x = vars%x(i)
            else
                msg = 'variable ' // name // ' has no numeric value (' // vars%text(i)%s // ')'
            end if
            return
        end if
        select case (name)
        case ('PI')
            if (syn == SYNTAX_LAMMPS) then
                x = pi
                return
            end if
        case ('pi')
            if (syn /= SYNTAX_LAMMPS) then
                x = pi
                return
            end if
        case ('True')
            if (syn == SYNTAX_PYTHON) then
                x = 1.0_wp
                return
            end if
        case ('False')
            if (syn == SYNTAX_PYTHON) then
                x = 0.0_wp
                return
            end if
        case default
        end select
        msg = 'unknown name "' // name0 // '" in "' // t // '"'
    end subroutine lookup

    !> A Python name without a module prefix (math.sqrt -> sqrt, numpy.pi -> pi).
    pure function python_name(name) result(r)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: r
        r = name
        if (index(r, 'math.') == 1) r = r(6:)
        if (index(r, 'numpy.') == 1) r = r(7:)
        if (index(r, 'np.') == 1) r = r(4:)
    end function python_name

    !> A function call name(args) (the '(' is consumed).
    recursive subroutine parse_call(t, pos, syn, vars, name0, x, msg)
        character(len=*), intent(in) :: t, name0
        integer, intent(inout) :: pos
        integer, intent(in) :: syn
        type(text_vars), intent(inout) :: vars
        real(wp), intent(out) :: x
        character(len=:), allocatable, intent(inout) :: msg
        real(wp) :: a(8)
        integer :: na
        character(len=:), allocatable :: name
        x = 0.0_wp
        name = name0
        if (syn == SYNTAX_PYTHON) name = python_name(name)
        na = 0
        if (.not. accept(t, pos, ')')) then
            do
                na = na + 1
                if (na > size(a)) then
                    msg = 'too many arguments to ' // name // ' in "' // t // '"'
                    return
                end if
                call parse_or(t, pos, syn, vars, a(na), msg)
                if (len(msg) > 0) return
                if (accept(t, pos, ')')) exit
                if (.not. accept(t, pos, ',')) then
                    msg = 'missing , or ) after an argument of ' // name // ' in "' // t // '"'
                    return
                end if
            end do
        end if
        call apply_function(lower(name), syn, a(1:na), t, x, msg)
    end subroutine parse_call

    subroutine apply_function(name, syn, a, t, x, msg)
        character(len=*), intent(in) :: name, t
        integer, intent(in) :: syn
        real(wp), intent(in) :: a(:)
        real(wp), intent(out) :: x
        character(len=:), allocatable, intent(inout) :: msg
        integer :: want
        x = 0.0_wp
        select case (name)
        case ('min', 'max')
            want = -1
        case ('atan2', 'pow')
            want = 2
        case ('sqrt', 'exp', 'ln', 'log', 'log10', 'abs', 'fabs', 'sin', 'cos', 'tan', 'asin', 'acos', 'atan', &
              'floor', 'ceil', 'round', 'radians', 'degrees', 'float')
            want = 1
        case default
            msg = 'function ' // name // '() is not evaluated here, in "' // t // '"'
            return
        end select
        if ((want > 0 .and. size(a) /= want) .or. (want < 0 .and. size(a) < 1)) then
            msg = 'wrong number of arguments to ' // name // '() in "' // t // '"'
            return
        end if
        if (name == 'log' .and. syn == SYNTAX_LAMMPS) then
            x = log(a(1))   ! LAMMPS log() is the natural logarithm, as ln()
        else
            x = function_value(name, a)
        end if
        if (.not. ieee_is_finite(x)) msg = name // '() of a value outside its domain in "' // t // '"'
    end subroutine apply_function

    real(wp) function function_value(name, a) result(x)
        character(len=*), intent(in) :: name
        real(wp), intent(in) :: a(:)
        x = 0.0_wp
        select case (name)
        case ('min'); x = minval(a)
        case ('max'); x = maxval(a)
        case ('atan2'); x = atan2(a(1), a(2))
        case ('pow'); x = a(1)**a(2)
        case ('sqrt'); x = sqrt(a(1))
        case ('exp'); x = exp(a(1))
        case ('ln', 'log'); x = log(a(1))
        case ('log10'); x = log10(a(1))
        case ('abs', 'fabs'); x = abs(a(1))
        case ('sin'); x = sin(a(1))
        case ('cos'); x = cos(a(1))
        case ('tan'); x = tan(a(1))
        case ('asin'); x = asin(a(1))
        case ('acos'); x = acos(a(1))
        case ('atan'); x = atan(a(1))
        case ('floor'); x = real(floor(a(1)), wp)
        case ('ceil'); x = real(ceiling(a(1)), wp)
        case ('round'); x = anint(a(1))
        case ('radians'); x = a(1) * pi / 180.0_wp
        case ('degrees'); x = a(1) * 180.0_wp / pi
        case ('float'); x = a(1)
        case default
        end select
    end function function_value

end module hertzdamp_text_expr
