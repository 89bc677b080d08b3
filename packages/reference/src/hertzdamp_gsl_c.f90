!> The C interfaces of GSL used by the GSL peer (hertzdamp_gsl, hertzdamp_gsl_secant):
!> the odeiv2 system type, the step types, the stepper, control and evolve routines,
!> the special functions Gamma and Beta.  Declarations only (bind(C)); no state.
!> Test reference and benchmark peer only: never part of the core library.
module hertzdamp_gsl_c
    use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_funptr
    implicit none
    private

    ! GSL return codes used by the peer
    integer(c_int), parameter, public :: gsl_success = 0, gsl_ebadfunc = 9

    !> GSL's `gsl_odeiv2_system` (layout of the C struct).
    type, bind(C), public :: gsl_odeiv2_system
        type(c_funptr) :: function            !! int (*)(double t, const double y[], double dydt[], void *params)
        type(c_funptr) :: jacobian            !! unused here (explicit steppers): NULL
        integer(c_size_t) :: dimension        !! number of equations (2)
        type(c_ptr) :: params                 !! points to a `rhs_params`
    end type gsl_odeiv2_system

    ! Step types: global `const gsl_odeiv2_step_type *` variables of libgsl.  They must
    ! be public: gfortran gives private bind(C) variables hidden visibility, which turns
    ! them into (null) local definitions instead of references to libgsl's variables.
    ! `protected` keeps them read-only outside this module.
    !> GSL's step type `gsl_odeiv2_step_rkf45` (read-only).
    type(c_ptr), bind(C, name='gsl_odeiv2_step_rkf45'), public, protected :: gsl_odeiv2_step_rkf45
    !> GSL's step type `gsl_odeiv2_step_rk8pd` (read-only).
    type(c_ptr), bind(C, name='gsl_odeiv2_step_rk8pd'), public, protected :: gsl_odeiv2_step_rk8pd

    public :: gsl_sf_gamma, gsl_sf_beta, gsl_set_error_handler_off, gsl_odeiv2_step_alloc, &
              gsl_odeiv2_step_reset, gsl_odeiv2_step_apply, gsl_odeiv2_step_free, gsl_odeiv2_control_y_new, &
              gsl_odeiv2_control_free, gsl_odeiv2_evolve_alloc, gsl_odeiv2_evolve_apply, gsl_odeiv2_evolve_reset, &
              gsl_odeiv2_evolve_free

    interface
        !> GSL's Gamma function (gsl_sf_gamma).
        function gsl_sf_gamma(x) bind(C, name='gsl_sf_gamma') result(g)
            import :: c_double
            implicit none
            real(c_double), value :: x     !! argument (not a non-positive integer)
            real(c_double) :: g
        end function gsl_sf_gamma

        !> GSL's Beta function B(a, b) (gsl_sf_beta).
        function gsl_sf_beta(a, b) bind(C, name='gsl_sf_beta') result(bab)
            import :: c_double
            implicit none
            real(c_double), value :: a     !! first argument
            real(c_double), value :: b     !! second argument
            real(c_double) :: bab
        end function gsl_sf_beta

        function gsl_set_error_handler_off() bind(C, name='gsl_set_error_handler_off') &
                result(old)
            import :: c_funptr
            implicit none
            type(c_funptr) :: old
        end function gsl_set_error_handler_off

        function gsl_odeiv2_step_alloc(steptype, dim) bind(C, name='gsl_odeiv2_step_alloc') &
                result(s)
            import :: c_ptr, c_size_t
            implicit none
            type(c_ptr), value :: steptype
            integer(c_size_t), value :: dim
            type(c_ptr) :: s
        end function gsl_odeiv2_step_alloc

        function gsl_odeiv2_step_reset(s) bind(C, name='gsl_odeiv2_step_reset') result(rc)
            import :: c_ptr, c_int
            implicit none
            type(c_ptr), value :: s
            integer(c_int) :: rc
        end function gsl_odeiv2_step_reset

        function gsl_odeiv2_step_apply(s, t, h, y, yerr, dydt_in, dydt_out, sys) &
                bind(C, name='gsl_odeiv2_step_apply') result(rc)
            import :: c_ptr, c_double, c_int, gsl_odeiv2_system
            implicit none
            type(c_ptr), value :: s
            real(c_double), value :: t, h
            real(c_double), intent(inout) :: y(2)
            real(c_double), intent(out) :: yerr(2)
            real(c_double), intent(in) :: dydt_in(2)
            real(c_double), intent(out) :: dydt_out(2)
            type(gsl_odeiv2_system), intent(in) :: sys
            integer(c_int) :: rc
        end function gsl_odeiv2_step_apply

        subroutine gsl_odeiv2_step_free(s) bind(C, name='gsl_odeiv2_step_free')
            import :: c_ptr
            implicit none
            type(c_ptr), value :: s
        end subroutine gsl_odeiv2_step_free

        function gsl_odeiv2_control_y_new(eps_abs, eps_rel) &
                bind(C, name='gsl_odeiv2_control_y_new') result(c)
            import :: c_ptr, c_double
            implicit none
            real(c_double), value :: eps_abs, eps_rel
            type(c_ptr) :: c
        end function gsl_odeiv2_control_y_new

        subroutine gsl_odeiv2_control_free(c) bind(C, name='gsl_odeiv2_control_free')
            import :: c_ptr
            implicit none
            type(c_ptr), value :: c
        end subroutine gsl_odeiv2_control_free

        function gsl_odeiv2_evolve_alloc(dim) bind(C, name='gsl_odeiv2_evolve_alloc') result(e)
            import :: c_ptr, c_size_t
            implicit none
            integer(c_size_t), value :: dim
            type(c_ptr) :: e
        end function gsl_odeiv2_evolve_alloc

        function gsl_odeiv2_evolve_apply(e, con, step, sys, t, t1, h, y) &
                bind(C, name='gsl_odeiv2_evolve_apply') result(rc)
            import :: c_ptr, c_double, c_int, gsl_odeiv2_system
            implicit none
            type(c_ptr), value :: e, con, step
            type(gsl_odeiv2_system), intent(in) :: sys
            real(c_double), intent(inout) :: t
            real(c_double), value :: t1
            real(c_double), intent(inout) :: h
            real(c_double), intent(inout) :: y(2)   ! the state of this 2-D system
            integer(c_int) :: rc
        end function gsl_odeiv2_evolve_apply

        function gsl_odeiv2_evolve_reset(e) bind(C, name='gsl_odeiv2_evolve_reset') result(rc)
            import :: c_ptr, c_int
            implicit none
            type(c_ptr), value :: e
            integer(c_int) :: rc
        end function gsl_odeiv2_evolve_reset

        subroutine gsl_odeiv2_evolve_free(e) bind(C, name='gsl_odeiv2_evolve_free')
            import :: c_ptr
            implicit none
            type(c_ptr), value :: e
        end subroutine gsl_odeiv2_evolve_free
    end interface

end module hertzdamp_gsl_c
