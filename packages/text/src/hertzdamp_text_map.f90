!> A map from strings to positive integers: open addressing with linear probing, an
!> FNV-1a hash, resized at half load.  Every lookup through `get` counts the slots it
!> looks at (`probes`), so that a test can show that a reader's work grows linearly
!> with its input.
module hertzdamp_text_map
    use hertzdamp_text_list, only: text_string
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    private

    !> A map from strings to positive integers.
    type, public :: text_map
        type(text_string), allocatable :: key(:)
        integer, allocatable :: val(:)        !! 0: empty slot
        integer :: n = 0
        integer(int64) :: probes = 0
    contains
        procedure :: put => map_put          !! set key -> value (value > 0)
        procedure :: get => map_get          !! the value of key, 0 if absent (counts probes)
        procedure :: find => map_find        !! the same without counting (pure)
    end type text_map

contains

    !> FNV-1a hash of a string, as a non-negative integer.
    pure integer function hash(s)
        character(len=*), intent(in) :: s
        integer(int64) :: h
        integer :: i
        h = 2166136261_int64
        do i = 1, len(s)
            h = ieor(h, int(iachar(s(i:i)), int64))
            h = mod(h * 16777619_int64, 4294967296_int64)
        end do
        hash = int(mod(h, 2147483647_int64))
    end function hash

    !> The slot of key: where it is, or the empty slot where it would go.
    integer function slot(self, key)
        class(text_map), intent(inout) :: self
        character(len=*), intent(in) :: key
        integer :: m
        m = size(self%val)
        slot = mod(hash(key), m) + 1
        do
            self%probes = self%probes + 1
            if (self%val(slot) == 0) return
            if (self%key(slot)%s == key) return
            slot = mod(slot, m) + 1
        end do
    end function slot

    subroutine map_put(self, key, v)
        class(text_map), intent(inout) :: self
        character(len=*), intent(in) :: key
        integer, intent(in) :: v      !! > 0
        type(text_string), allocatable :: oldk(:)
        integer, allocatable :: oldv(:)
        integer :: i, j
        if (.not. allocated(self%val)) then
            allocate (self%key(16), self%val(16))
            self%val = 0
        end if
        if (2 * (self%n + 1) > size(self%val)) then
            call move_alloc(self%key, oldk)
            call move_alloc(self%val, oldv)
            allocate (self%key(2 * size(oldv)), self%val(2 * size(oldv)))
            self%val = 0
            do i = 1, size(oldv)
                if (oldv(i) == 0) cycle
                j = slot(self, oldk(i)%s)
                self%key(j)%s = oldk(i)%s
                self%val(j) = oldv(i)
            end do
        end if
        j = slot(self, key)
        if (self%val(j) == 0) then
            self%n = self%n + 1
            self%key(j)%s = key
        end if
        self%val(j) = v
    end subroutine map_put

    !> The value of key without counting the probes (0 if absent).
    pure integer function map_find(self, key) result(v)
        class(text_map), intent(in) :: self
        character(len=*), intent(in) :: key
        integer :: j, m
        v = 0
        if (.not. allocated(self%val)) return
        m = size(self%val)
        j = mod(hash(key), m) + 1
        do
            if (self%val(j) == 0) return
            if (self%key(j)%s == key) then
                v = self%val(j)
                return
            end if
            j = mod(j, m) + 1
        end do
    end function map_find

    integer function map_get(self, key) result(v)
        class(text_map), intent(inout) :: self
        character(len=*), intent(in) :: key
        v = 0
        if (.not. allocated(self%val)) return
        v = self%val(slot(self, key))
    end function map_get

end module hertzdamp_text_map
