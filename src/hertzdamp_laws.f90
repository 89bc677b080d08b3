!> The damping laws of the model family (doc/damping-laws.md):
!>
!>     m zeta'' = - k zeta^(3/2) - d zeta^q zeta',   q = 0, 1/4, 1/2,
!>
!> named `linear` (q = 0, constant damping), `tsuji` (q = 1/4) and `kuwabara-kono`
!> (q = 1/2).  In similarity variables (the same t* = (m / (k u^(1/2)))^(2/5) for every
!> law) this is  z'' + alpha z^q z' + z^(3/2) = 0  with  alpha = d t* (u t*)^q / m,
!> so alpha ~ u^((4q - 1)/5): u^(-1/5) (linear), independent of u (tsuji), u^(1/5)
!> (kuwabara-kono).
!>
!> This module holds the law codes, their names and exponents, and the exact facts
!> of each law that need no integration (whether the overlap end has a critical damping,
!> the tsuji closed forms); it depends on no generated data (the generated alpha_c of the
!> linear law: hertzdamp_law_alpha_c in hertzdamp_rk45).  Everything is pure, no module
!> state.
module hertzdamp_laws
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_registry, only: HD_OK, HD_BAD_LAW, HD_NOT_SUPPORTED, HD_END_OVERLAP, HD_DAMPING_LINEAR, &
                                  HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO, hertzdamp_min_law, hertzdamp_max_law, &
                                  hertzdamp_law_name, hertzdamp_law_code, hertzdamp_law_q
    use hertzdamp_constants, only: hertzdamp_pi
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    ! The law codes, names and exponents are rows of data/registry.toml: hertzdamp_registry
    ! has them (and the umbrella exports them); the laws' exact facts follow.

    !> Critical damping of the tsuji law with the overlap end: alpha_c = sqrt(5) exactly
    !> (the law maps onto a linear oscillator of damping ratio alpha/sqrt(5)).
    real(wp), parameter, public :: hertzdamp_alpha_c_tsuji = sqrt(5.0_wp)

    public :: hertzdamp_law_status
    public :: hertzdamp_law_speed_exponent, hertzdamp_law_reversal_exponent, hertzdamp_law_has_alpha_c
    public :: hertzdamp_tsuji_e, hertzdamp_tsuji_l, hertzdamp_tsuji_alpha

contains

    !> HD_OK for a valid law code, else HD_BAD_LAW.
    pure elemental integer function hertzdamp_law_status(law) result(status)
        integer, intent(in) :: law   !! HD_DAMPING_*
        status = HD_OK
        if (law < hertzdamp_min_law .or. law > hertzdamp_max_law) status = HD_BAD_LAW
    end function hertzdamp_law_status

    !> Exponent of the impact speed in alpha at fixed k, d, m: alpha ~ u^((4q - 1)/5)
    !> (-1/5 linear, 0 tsuji, 1/5 kuwabara-kono).
    pure elemental real(wp) function hertzdamp_law_speed_exponent(law) result(p)
        integer, intent(in) :: law   !! HD_DAMPING_*
        p = (4.0_wp * hertzdamp_law_q(law) - 1.0_wp) / 5.0_wp
    end function hertzdamp_law_speed_exponent

    !> Exponent of the time-reversal map: the reversed collision of (alpha, e) has
    !> damping -alpha e^p with p = (4q - 1)/5, so e(alpha) e(-alpha e(alpha)^p) = 1
    !> (overlap end).  It equals the speed exponent: reversal is an impact at speed e.
    pure elemental real(wp) function hertzdamp_law_reversal_exponent(law) result(p)
        integer, intent(in) :: law   !! HD_DAMPING_*
        p = hertzdamp_law_speed_exponent(law)
    end function hertzdamp_law_reversal_exponent

    !> True when the overlap end of the law has a critical damping alpha_c beyond which
    !> the overlap never returns (linear: alpha_c = 1.12799..., tsuji: sqrt(5));
    !> kuwabara-kono has none: its overlap returns for every alpha (doc/damping-laws.md).
    pure elemental logical function hertzdamp_law_has_alpha_c(law) result(has)
        integer, intent(in) :: law   !! HD_DAMPING_*
        has = law == HD_DAMPING_LINEAR .or. law == HD_DAMPING_TSUJI
    end function hertzdamp_law_has_alpha_c

    !> Exact restitution of the tsuji law (q = 1/4) for either contact end:
    !> e = exp(-L) with L of hertzdamp_tsuji_l (the one closed form of the law).
    !> Status HD_OK; HD_NOT_SUPPORTED with e = 0 for the overlap end at alpha >= sqrt(5)
    !> (no rebound) and for alpha < 0 with the force end.
    pure elemental subroutine hertzdamp_tsuji_e(alpha, iend, e, status)
        real(wp), intent(in) :: alpha    !! damping parameter (overlap: any sign below sqrt(5))
        integer, intent(in) :: iend      !! 0 overlap, 1 force
        real(wp), intent(out) :: e       !! restitution coefficient
        integer, intent(out) :: status   !! HD_OK, or HD_NOT_SUPPORTED where there is no value
        real(wp) :: l
        call hertzdamp_tsuji_l(alpha, iend, l, status)
        e = 0.0_wp
        if (status == HD_OK) e = exp(-l)
    end subroutine hertzdamp_tsuji_e

    !> L = -ln e of the tsuji law (q = 1/4) for either contact end, in closed form, and
    !> optionally dL/dalpha.
    !>
    !> With x = z^(5/4) the phase-plane orbit v(x) of  z'' + alpha z^(1/4) z' + z^(3/2) = 0
    !> is that of the linear oscillator X'' + 2 a X' + w^2 X = 0 with w^2 = 4/5,
    !> a = 2 alpha / 5 (damping ratio zeta = alpha / sqrt(5)), and both contact ends are
    !> curves of that oscillator: the overlap end X = 0, the force end X'' = 0.  With
    !> W^2 = w^2 - a^2:
    !>   overlap: L = pi a / W for alpha < sqrt(5) (no rebound beyond),
    !>   force:   L = 2 a atan(W / a) / W  (atanh and |W| for alpha > sqrt(5),
    !>            2 at alpha = sqrt(5)); e ~ 5 / (4 alpha^2) for alpha -> infinity.
    !> Derivative (doc/damping-laws.md section 4): overlap dL/dalpha = (2/5) (4/5) pi / W^3;
    !> force L = 2 f(x) with x = W^2/a^2 = (4/5)/a^2 - 1 and f(x) = atan(sqrt x)/sqrt x
    !> (atanh(sqrt(-x))/sqrt(-x) for x < 0), dL/dalpha = 2 f'(x) dx/dalpha,
    !> dx/dalpha = -(16/25)/a^3, f'(x) = (1/(1 + x) - f(x))/(2x) (its series for
    !> |x| < 0.1); near alpha = 0, with zeta = alpha/sqrt(5), L = pi zeta - 2 zeta^2 + O(zeta^3).
    !> Status HD_OK; HD_NOT_SUPPORTED with L = 0 (and dL/dalpha = 0) for the overlap end at
    !> alpha >= sqrt(5) (no rebound) and for alpha < 0 with the force end.
    pure elemental subroutine hertzdamp_tsuji_l(alpha, iend, l, status, dl)
        real(wp), intent(in) :: alpha    !! damping parameter (overlap: any sign below sqrt(5))
        integer, intent(in) :: iend      !! 0 overlap, 1 force
        real(wp), intent(out) :: l       !! L = -ln e
        integer, intent(out) :: status   !! HD_OK, or HD_NOT_SUPPORTED where there is no value
        real(wp), intent(out), optional :: dl !! dL/dalpha (force end: alpha > 0)
        real(wp) :: a, w2, w, r
        l = 0.0_wp
        if (present(dl)) dl = 0.0_wp
        status = HD_OK
        a = 0.4_wp * alpha
        ! W^2 = 4/5 - 4 alpha^2/25 = (4/25) (sqrt5 - alpha)(sqrt5 + alpha): formed from the
        ! factor (sqrt5 - alpha) so that it keeps its relative accuracy near alpha_c
        w2 = 0.16_wp * (hertzdamp_alpha_c_tsuji - alpha) * (hertzdamp_alpha_c_tsuji + alpha)
        if (iend == HD_END_OVERLAP) then
            if (.not. (w2 > 0.0_wp)) then
                status = HD_NOT_SUPPORTED
                return
            end if
            l = hertzdamp_pi * a / sqrt(w2)
            if (present(dl)) dl = 0.32_wp * hertzdamp_pi / (w2 * sqrt(w2))
        else
            if (alpha < 0.0_wp) then
                status = HD_NOT_SUPPORTED
                return
            end if
            if (a == 0.0_wp) then
                l = 0.0_wp
            else if (w2 > 0.0_wp) then
                w = sqrt(w2)
                l = 2.0_wp * a * atan2(w, a) / w
            else if (w2 < 0.0_wp) then
                ! overdamped: atanh(r), r = |W|/a < 1; for r > 1/2 in the cancellation-free
                ! form atanh(r) = ln((a + |W|)/w) (a^2 - |W|^2 = w^2 = 4/5)
                w = sqrt(-w2)
                r = w / a
                if (r <= 0.5_wp) then
                    l = 2.0_wp * a * atanh(r) / w
                else
                    l = 2.0_wp * a * log((a + w) / sqrt(0.8_wp)) / w
                end if
            else
                l = 2.0_wp
            end if
            if (present(dl)) dl = tsuji_dl_force(alpha, a, w2)
        end if
    end subroutine hertzdamp_tsuji_l

    !> dL/dalpha of the tsuji force end (hertzdamp_tsuji_l), alpha >= 0; a = 2 alpha/5,
    !> w2 = W^2 as there.
    pure real(wp) function tsuji_dl_force(alpha, a, w2) result(dl)
        real(wp), intent(in) :: alpha, a, w2
        real(wp) :: x, f, fp, xn, r
        integer :: n
        if (alpha < 1.0e-8_wp) then
            dl = (hertzdamp_pi - 4.0_wp * alpha / hertzdamp_alpha_c_tsuji) / hertzdamp_alpha_c_tsuji
            return
        end if
        x = w2 / (a * a)
        if (abs(x) < 0.1_wp) then
            ! f(x) = sum_n (-x)^n / (2n + 1): f'(x) = sum_{n >= 1} (-1)^n n x^(n-1) / (2n + 1)
            fp = 0.0_wp
            xn = 1.0_wp
            do n = 1, 30
                fp = fp + real((-1)**n * n, wp) * xn / real(2 * n + 1, wp)
                xn = xn * x
            end do
        else
            if (x > 0.0_wp) then
                r = sqrt(x)
                f = atan(r) / r
            else
                ! atanh(|W|/a) = ln((a + |W|)/sqrt(4/5)), free of cancellation
                r = sqrt(-w2)
                f = a * log((a + r) / sqrt(0.8_wp)) / r
            end if
            fp = (1.0_wp / (1.0_wp + x) - f) / (2.0_wp * x)
        end if
        dl = 2.0_wp * fp * (-0.64_wp / (a * a * a))
    end function tsuji_dl_force

    !> Exact inverse of the tsuji overlap end: alpha = sqrt(5) beta(e),
    !> beta = -ln e / sqrt(pi^2 + ln^2 e) (Antypov & Elliott 2011), for 0 < e.
    !> e >= 1 gives alpha <= 0 (energy injection, e > 1); e <= 0 gives sqrt(5) (the limit).
    pure elemental real(wp) function hertzdamp_tsuji_alpha(e) result(alpha)
        real(wp), intent(in) :: e   !! restitution coefficient of the overlap end
        real(wp) :: l
        if (.not. (e > 0.0_wp)) then
            alpha = hertzdamp_alpha_c_tsuji
            return
        end if
        l = log(e)
        alpha = -hertzdamp_alpha_c_tsuji * l / sqrt(hertzdamp_pi**2 + l * l)
    end function hertzdamp_tsuji_alpha

end module hertzdamp_laws
