!> HERTZDAMP_MESSAGE(IERR, TEXT): the message of a status code, copied into text
!> (truncated or blank-padded).  The one legacy entry point that is an external
!> subroutine: a character argument has no binding-label form.  It uses
!> hertzdamp_registry only, which sees no IEEE module (see hertzdamp_capi on the
!> floating-point environment).  Every other legacy entry point (HERTZDAMP_INVERT ...)
!> is a module procedure of hertzdamp_capi with the external's link name.
subroutine hertzdamp_message(ierr, text)
    use hertzdamp_registry, only: mod_message => hertzdamp_message
    implicit none
    integer, intent(in) :: ierr               !! a status code
    character(len=*), intent(out) :: text     !! receives the message
    text = mod_message(ierr)
end subroutine hertzdamp_message
