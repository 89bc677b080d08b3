!> A string of any length (`text_string`), a list of strings that grows by doubling
!> (`text_list`, amortised constant time per push) and their join, in time linear in
!> their length.
module hertzdamp_text_list
    implicit none
    private

    !> A string: one line, one word.
    type, public :: text_string
        character(len=:), allocatable :: s
    end type text_string

    !> A list of strings that grows by doubling.
    type, public :: text_list
        type(text_string), allocatable :: item(:)
        integer :: n = 0
    contains
        procedure :: push => list_push       !! append a string
        procedure :: note => list_note       !! append a remark with the file:line it is about
        procedure :: items => list_items     !! the strings, item(1:n)
    end type text_list

    public :: text_join

contains

    subroutine list_push(self, s)
        class(text_list), intent(inout) :: self
        character(len=*), intent(in) :: s   !! the string
        type(text_string), allocatable :: tmp(:)
        if (.not. allocated(self%item)) allocate (self%item(8))
        if (self%n == size(self%item)) then
            allocate (tmp(2 * size(self%item)))
            tmp(1:self%n) = self%item(1:self%n)
            call move_alloc(tmp, self%item)
        end if
        self%n = self%n + 1
        self%item(self%n)%s = s
    end subroutine list_push

    !> Append `where: text`, or `text` when where is ''.
    subroutine list_note(self, where, text)
        class(text_list), intent(inout) :: self
        character(len=*), intent(in) :: where   !! file:line ('' for none)
        character(len=*), intent(in) :: text    !! the remark
        if (len(where) > 0) then
            call self%push(where // ': ' // text)
        else
            call self%push(text)
        end if
    end subroutine list_note

    function list_items(self) result(t)
        class(text_list), intent(in) :: self
        type(text_string), allocatable :: t(:)
        if (self%n == 0) then
            allocate (t(0))
        else
            t = self%item(1:self%n)
        end if
    end function list_items

    !> The strings joined by `sep` (default one blank), in linear time: the length is
    !> counted first.
    pure function text_join(t, sep) result(s)
        type(text_string), intent(in) :: t(:)             !! the strings
        character(len=*), intent(in), optional :: sep     !! the separator ('' for none)
        character(len=:), allocatable :: s
        character(len=:), allocatable :: b
        integer :: i, n, k
        b = ' '
        if (present(sep)) b = sep
        n = max(0, size(t) - 1) * len(b)
        do i = 1, size(t)
            n = n + len(t(i)%s)
        end do
        allocate (character(len=n) :: s)
        k = 0
        do i = 1, size(t)
            if (i > 1) then
                s(k + 1:k + len(b)) = b
                k = k + len(b)
            end if
            s(k + 1:k + len(t(i)%s)) = t(i)%s
            k = k + len(t(i)%s)
        end do
    end function text_join

end module hertzdamp_text_list
