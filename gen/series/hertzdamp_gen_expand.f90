!> Taylor coefficients in alpha of the collision quantities (overlap definition).
!>
!> 1. local series in sqrt(t) (jets in alpha) from contact start to t0;
!> 2. Taylor steps in t (jets in alpha) from t0 to t* = tau_max(0);
!> 3. time series of z about t* with jet coefficients; Newton on jets for the
!>    turning point v(t* + delta(alpha)) = 0, giving tau_max and z_max;
!> 4. time reversal  z_max(a) = e^{4/5} z_max(-a e^{-1/5})  solved for ln e by
!>    fixed-point iteration on jets (one order per sweep), then
!>    tau_c(a) = tau_max(a) + e^{-1/5} tau_max(-a e^{-1/5}).
module hertzdamp_gen_expand
    use hertzdamp_gen_jets, only: gk, jmul, jdiv, jexp, jlog, jcompose, jhorner, jshift, jconst
    use hertzdamp_gen_ode, only: start_series, time_coefficients, integrate_fixed
    implicit none (type, external)
    private

    !> Settings of one expansion run.
    type, public :: expand_settings
        integer :: n = 24             !! degree in alpha
        real(gk) :: t0 = 0.1_gk       !! end of the local start series
        integer :: m_start = 60       !! terms of the start series (powers of sqrt(t))
        real(gk) :: rho = 0.2_gk      !! step / t
        real(gk) :: hmax = 0.1_gk     !! largest step
        integer :: k_time = 40        !! Taylor order in time of the steps
    end type expand_settings

    !> Result of one expansion run: coefficients 0..n of each quantity.
    type, public :: expand_result
        real(gk), allocatable :: z_max(:), tau_max(:), e(:), tau_c(:)
        real(gk), allocatable :: ln_e(:)          !! ln e in alpha
        real(gk), allocatable :: ln_e_beta(:)     !! ln e in beta = alpha e^{-1/10}
        real(gk), allocatable :: tce_beta(:)      !! tau_c e^{1/10} in beta
        real(gk) :: start_tail = 0.0_gk           !! size of last start-series terms
        real(gk) :: turn_residual = 0.0_gk        !! max |v| of the turning-point jet
        real(gk) :: reversal_residual = 0.0_gk    !! max residual of the ln e iteration
        integer :: nsteps = 0                     !! Taylor steps taken
    end type expand_result

    public :: expand, closed_forms

contains

    !> Elastic closed forms: z_max(0), tau_c(0), e1 (Fortran gamma intrinsic).
    pure subroutine closed_forms(zmax0, tauc0, e1)
        real(gk), intent(out) :: zmax0  !! (5/4)^{2/5}
        real(gk), intent(out) :: tauc0  !! (4/5)(5/4)^{2/5} B(2/5,1/2)
        real(gk), intent(out) :: e1     !! (4/5)(5/4)^{2/5} B(2/5,3/2)
        zmax0 = 1.25_gk**0.4_gk
        tauc0 = 0.8_gk * zmax0 * gamma(0.4_gk) * gamma(0.5_gk) / gamma(0.9_gk)
        e1 = 0.8_gk * zmax0 * gamma(0.4_gk) * gamma(1.5_gk) / gamma(1.9_gk)
    end subroutine closed_forms

    !> Run the expansion with settings s.
    subroutine expand(s, r)
        type(expand_settings), intent(in) :: s  !! settings
        type(expand_result), intent(out) :: r   !! coefficients and diagnostics
        integer :: n, k, it
        real(gk) :: a(0:s%n), z(0:s%n), v(0:s%n), one(0:s%n)
        real(gk) :: zc(0:s%n, 0:s%n + 4), vc(0:s%n, 0:s%n + 3), dvc(0:s%n, 0:s%n + 2)
        real(gk) :: d(0:s%n), zm(0:s%n), tm(0:s%n), lz(0:s%n), g(0:s%n), w(0:s%n)
        real(gk) :: gnew(0:s%n), tc(0:s%n), al(0:s%n), tce(0:s%n)
        real(gk) :: zmax0, tauc0, e1, tstar
        n = s%n
        one = jconst(1.0_gk, n)
        a = jshift(one)                       ! the jet variable alpha
        call closed_forms(zmax0, tauc0, e1)
        tstar = tauc0 / 2
        ! 1-2: start series, then Taylor steps to t*
        call start_series(a, 1.0_gk, s%m_start, s%t0, z, v, r%start_tail)
        call integrate_fixed(a, z, v, s%t0, tstar, s%rho, s%hmax, s%k_time, r%nsteps)
        ! 3: turning point  v(t* + d) = 0,  Newton on jets
        zc = time_coefficients(a, z, v, n + 4)
        do k = 0, n + 3
            vc(:, k) = (k + 1) * zc(:, k + 1)
        end do
        do k = 0, n + 2
            dvc(:, k) = (k + 1) * vc(:, k + 1)
        end do
        d = 0.0_gk
        do it = 1, 12
            d = d - jdiv(jhorner(vc, d), jhorner(dvc, d))
        end do
        r%turn_residual = maxval(abs(jhorner(vc, d)))
        tm = tstar * one + d
        zm = jhorner(zc, d)
        ! 4: time reversal for g = ln e:  g = (5/4) [ln zm(a) - ln zm(-a e^{-g/5})]
        lz = jlog(zm)
        g = 0.0_gk
        do it = 1, n + 3
            w = -jshift(jexp(-g / 5))
            gnew = 1.25_gk * (lz - jcompose(lz, w))
            r%reversal_residual = maxval(abs(gnew - g))
            g = gnew
        end do
        w = -jshift(jexp(-g / 5))
        tc = tm + jmul(jexp(-g / 5), jcompose(tm, w))
        ! beta = a e^{-1/10}: invert to a(beta) = beta e^{g(a(beta))/10}
        al = 0.0_gk
        do it = 1, n + 3
            al = jshift(jexp(jcompose(g, al) / 10))
        end do
        tce = jmul(tc, jexp(g / 10))
        allocate (r%z_max(0:n), r%tau_max(0:n), r%ln_e(0:n), r%e(0:n), r%tau_c(0:n), &
                  r%ln_e_beta(0:n), r%tce_beta(0:n))
        r%z_max = zm
        r%tau_max = tm
        r%ln_e = g
        r%e = jexp(g)
        r%tau_c = tc
        r%ln_e_beta = jcompose(g, al)
        r%tce_beta = jcompose(tce, al)
    end subroutine expand

end module hertzdamp_gen_expand
