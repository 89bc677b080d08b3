!> Tests of `hertzdamp check` (hertzdamp_check_model, hertzdamp_check_deck):
!> - every row of data/peers/peers_spec.csv: a deck written in the engine's keywords
!>   gives the alpha (or gamma) of the row's alpha_expr, evaluated by the independent
!>   evaluator hertzdamp_test_expr, and the stiffness k of doc/peers.md (transcribed
!>   here), for random materials, speeds and coefficients;
!> - linear damping: the achieved e is the library's forward map (fit, and the
!>   dimensional forward problem with d from the deck);
!> - zeta^(1/4) damping with the overlap end and gamma = sqrt(5) beta(e): e = target
!>   to 1e-10 (the closed form of Antypov & Elliott 2011);
!> - the corrected parameter, fed back as a deck, gives the target e;
!> - the engines' own contact-time estimates against the exact elastic Hertz time, also
!>   where E^2 alone would overflow;
!> - the maps check uses (the library's fitted maps, rk45 beyond them) against the
!>   reference integrator at tol 1e-14, for every law and end; the fit wherever e >= 1e-4;
!> - an overdamped deck whose alpha double precision cannot hold: no rebound exactly
!>   where the law has alpha_c and the overlap end;
!> - decks scaled by up to 1e+-300: no infinity and no NaN result (only the contact time
!>   of a point without rebound is infinite; a value beyond range is a status);
!> - bad decks give an error naming the key.
program test_peers
    use hertzdamp
    use hertzdamp_check_model
    use hertzdamp_check_deck
    use hertzdamp_text_list, only: text_string
    use hertzdamp_test_expr, only: expr_vars, expr_eval
    use hertzdamp_testing, only: test_suite, new_suite, rel_err
    use, intrinsic :: iso_fortran_env, only: real32, int64
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    real(wp), parameter :: pi = hertzdamp_pi

    !> One generated case: the deck tokens and what the test expects.
    type :: case_t
        type(text_string), allocatable :: tok(:)
        type(peer_materials) :: mat
        integer :: peer = 0
        integer :: release = LAMMPS_CURRENT
        type(expr_vars) :: vars      ! bindings for alpha_expr (m, R, k, u and the coefficient)
        real(wp) :: k = 0.0_wp       ! expected stiffness
        real(wp) :: ktol = 1.0e-13_wp
        real(wp) :: gfac = 1.0_wp    ! factor on the row's gamma (Chrono wall body mass)
        character(len=:), allocatable :: label
    end type case_t

    !> What a random case draws: bodies, materials and the speed.
    type :: draw
        real(wp) :: r1, r2, m1, m, r, u, ymod, nu, y2, nu2
        logical :: wall, limit
    end type draw

    type(test_suite) :: s
    integer :: seed = 12345
    logical :: reached(64)

    s = new_suite('test_peers')
    reached = .false.
    call test_evaluator()
    call test_formulas()
    call test_linear_forward()
    call test_closed_form()
    call test_corrected()
    call test_time_estimates()
    call test_maps()
    call test_overdamped()
    call test_extremes()
    call test_bad_decks()
    call test_yade_pade()
    call s%finish()

contains

    ! ------------------------------------------------------------------ random numbers

    real(wp) function rnd()
        ! Park-Miller minimal standard generator: reproducible, no intrinsic state
        seed = int(mod(int(seed, int64) * 48271_int64, 2147483647_int64))
        rnd = real(seed, wp) / 2147483647.0_wp
    end function rnd

    real(wp) function log_uniform(a, b)
        real(wp), intent(in) :: a, b
        log_uniform = exp(log(a) + (log(b) - log(a)) * rnd())
    end function log_uniform

    function num(x) result(t)
        real(wp), intent(in) :: x
        character(len=:), allocatable :: t
        character(len=32) :: b
        write (b, '(es25.17e3)') x
        t = trim(adjustl(b))
    end function num

    subroutine add(c, text)
        type(case_t), intent(inout) :: c
        character(len=*), intent(in) :: text
        integer :: i, j
        i = 1
        do while (i <= len(text))
            if (text(i:i) == ' ') then
                i = i + 1
                cycle
            end if
            j = index(text(i:), ' ')
            if (j == 0) then
                j = len(text) + 1
            else
                j = i + j - 1
            end if
            c%tok = [c%tok, text_string(text(i:j - 1))]
            i = j
        end do
    end subroutine add

    ! ------------------------------------------------------------------ the evaluator itself

    subroutine test_evaluator()
        type(expr_vars) :: v
        logical :: ok
        character(len=:), allocatable :: err
        real(wp) :: x
        call v%set('a', 2.0_wp)
        x = expr_eval('2^3^2', v, ok, err)
        call s%check(ok .and. x == 512.0_wp, 'evaluator: ^ is right-associative')
        x = expr_eval('-a^2', v, ok, err)
        call s%check(ok .and. x == -4.0_wp, 'evaluator: ^ binds tighter than unary minus')
        x = expr_eval('1+2*3-4/2', v, ok, err)
        call s%check(ok .and. x == 5.0_wp, 'evaluator: precedence of + - * /')
        x = expr_eval('max(1,a,3)-min(a,5)+abs(-1)', v, ok, err)
        call s%check(ok .and. x == 2.0_wp, 'evaluator: max, min, abs')
        x = expr_eval('beta(0)', v, ok, err)
        call s%check(ok .and. x == 1.0_wp, 'evaluator: beta(0) = 1')
        x = expr_eval('beta(exp1)', v, ok, err)
        call s%check(.not. ok, 'evaluator: an unbound name is an error')
        call v%set('x', exp(-pi))
        x = expr_eval('beta(x)', v, ok, err)
        call s%check_close(x, 1.0_wp / sqrt(2.0_wp), 1.0e-15_wp, 'evaluator: beta(exp(-pi)) = 1/sqrt(2)')
        x = expr_eval('P6(1)', v, ok, err)
        call s%check_close(x, 3.0e-4_wp, 1.0e-9_wp, 'evaluator: P6(1) = 3e-4 (doc/peers.md)')
        x = expr_eval('(2*(a+1)', v, ok, err)
        call s%check(.not. ok, 'evaluator: a missing ) is an error')
    end subroutine test_evaluator

    ! ------------------------------------------------------------------ decks of every row

    !> A random case of a row: the deck tokens in the engine's keywords and the expected
    !> bindings.  `coef` > 0 sets the damping coefficient (else a random one).
    subroutine make_case(id, c, coef)
        character(len=*), intent(in) :: id
        type(case_t), intent(out) :: c
        real(wp), intent(in), optional :: coef
        real(wp) :: r1, r2, rho1, rho2, m1, m2, m, r, u, ymod, nu, y2, nu2
        logical :: wall, limit
        type(draw) :: d
        allocate (c%tok(0))
        c%label = id
        r1 = log_uniform(1.0e-4_wp, 1.0e-1_wp)
        r2 = log_uniform(1.0e-4_wp, 1.0e-1_wp)
        rho1 = log_uniform(500.0_wp, 1.0e4_wp)
        rho2 = log_uniform(500.0_wp, 1.0e4_wp)
        u = log_uniform(1.0e-3_wp, 10.0_wp)
        ymod = log_uniform(1.0e6_wp, 1.0e11_wp)
        y2 = log_uniform(1.0e6_wp, 1.0e11_wp)
        nu = 0.49_wp * rnd()
        nu2 = 0.49_wp * rnd()
        wall = rnd() < 0.3_wp
        limit = index(id, '-force') > 0
        c%mat%radius = [r1, r2]
        c%mat%density = [rho1, rho2]
        c%mat%wall = wall
        m1 = (4.0_wp / 3.0_wp) * pi * rho1 * r1**3
        m2 = (4.0_wp / 3.0_wp) * pi * rho2 * r2**3
        if (wall) then
            m = m1
            r = r1
        else
            m = m1 * m2 / (m1 + m2)
            r = r1 * r2 / (r1 + r2)
        end if
        call c%vars%set('u', u)
        d = draw(r1, r2, m1, m, r, u, ymod, nu, y2, nu2, wall, limit)
        if (index(id, 'lammps-hertz_history-') == 1) then
            call case_lammps_classic(d, c, coef)
        else if (index(id, 'lammps-') == 1) then
            call case_lammps(id, d, c, coef)
        else if (index(id, 'liggghts-') == 1) then
            call case_liggghts(id, d, c, coef)
        else if (index(id, 'mercurydpm-') == 1) then
            call case_mercury(id, d, c, coef)
        else if (index(id, 'mercurydpm2015-') == 1) then
            call case_mercury2015(id, d, c, coef)
        else if (index(id, 'yade') == 1) then
            call case_yade(id, d, c, coef)
        else if (index(id, 'mfix-') == 1) then
            call case_mfix(d, c, coef)
        else if (index(id, 'chrono-') == 1) then
            call case_chrono(id, d, c, coef)
        end if
    end subroutine make_case
    subroutine case_lammps_classic(d, c, coef)
        type(draw), intent(in) :: d
        type(case_t), intent(inout) :: c
        real(wp), intent(in), optional :: coef
        real(wp) :: m, r, kn, x
        logical :: wall, limit
        m = d%m
        r = d%r
        wall = d%wall
        limit = d%limit
        ! section 1, classic style: k = Kn sqrt(R), d = gamma_n m sqrt(R)
        c%peer = PEER_LAMMPS
        c%mat%wall = .false.
        c%release = LAMMPS_2021 + int(2.999_wp * rnd())   ! 2021, 2023 or current
        kn = log_uniform(1.0e5_wp, 1.0e11_wp)
        x = log_uniform(1.0e-6_wp, 1.0e3_wp)
        if (present(coef)) x = coef
        call c%vars%set('gamma_n', x)
        if (wall) then
            call add(c, 'fix 1 all wall/gran hertz/history ' // num(kn) // ' NULL ' // num(x) // ' NULL 0.5 1')
            if (limit) call add(c, 'limit_damping')
            call add(c, 'zplane 0 NULL')
        else
            call add(c, 'gran/hertz/history ' // num(kn) // ' NULL ' // num(x) // ' 0.5 0.4 1')
            if (limit) call add(c, 'limit_damping')
        end if
        c%k = kn * sqrt(r)
        call c%vars%set('m', m)
        call c%vars%set('R', r)
        call c%vars%set('k', c%k)
    end subroutine case_lammps_classic

    subroutine case_lammps(id, d, c, coef)
        character(len=*), intent(in) :: id
        type(draw), intent(in) :: d
        type(case_t), intent(inout) :: c
        real(wp), intent(in), optional :: coef
        real(wp) :: m, r, ymod, nu, kn, x, x2
        logical :: wall, hertz, limit
        character(len=:), allocatable :: rel, damp
        m = d%m
        r = d%r
        ymod = d%ymod
        nu = d%nu
        wall = d%wall
        limit = d%limit
        ! doc/peers.md section 1: k = kn sqrt(R); hertz/material kn = (4/3) E/(2(1-nu^2)),
        ! the 2021 wall (4/3) E/(2(1-nu))
        c%peer = PEER_LAMMPS
        c%mat%wall = .false.
        rel = id(8:index(id(8:), '-') + 6)
        damp = id(9 + len(rel):index(id, '-', back=.true.) - 1)
        select case (rel)
        case ('2021'); c%release = LAMMPS_2021
        case ('2023')
            x = rnd()
            c%release = merge(LAMMPS_2023, LAMMPS_CURRENT, x < 0.5_wp .or. damp == 'tsuji')
        case ('2024'); c%release = merge(LAMMPS_2023, LAMMPS_CURRENT, rnd() < 0.5_wp)
        case default; c%release = LAMMPS_CURRENT
        end select
        if (damp == 'tsuji' .or. damp == 'coeff_restitution') then
            x = 0.01_wp + 0.99_wp * rnd()
            if (present(coef)) x = coef
            call c%vars%set('e', x)
        else
            x = log_uniform(1.0e-6_wp, 1.0e3_wp)
            if (present(coef)) x = coef
            call c%vars%set('eta_n0', x)
        end if
        hertz = rnd() < 0.5_wp
        if (wall) call add(c, 'fix 1 all wall/gran granular')
        x2 = rnd()
        if (.not. wall .and. x2 < 0.5_wp) call add(c, 'pair_coeff * *')
        if (hertz) then
            kn = log_uniform(1.0e5_wp, 1.0e11_wp)
            call add(c, 'hertz ' // num(kn) // ' ' // num(x))
            c%k = kn * sqrt(r)
        else
            call add(c, 'hertz/material ' // num(ymod) // ' ' // num(x) // ' ' // num(nu))
            if (wall .and. c%release == LAMMPS_2021) then
                c%k = (4.0_wp / 3.0_wp) * ymod / (2.0_wp * (1.0_wp - nu)) * sqrt(r)
            else
                c%k = (4.0_wp / 3.0_wp) * ymod / (2.0_wp * (1.0_wp - nu**2)) * sqrt(r)
            end if
        end if
        if (rnd() < 0.7_wp) call add(c, 'tangential linear_nohistory 0 0.5')
        if (rnd() < 0.3_wp) call add(c, 'rolling sds 1e3 10 0.1 twisting marshall')
        x2 = rnd()
        if (damp /= 'viscoelastic' .or. x2 < 0.5_wp) call add(c, 'damping ' // damp)
        if (limit) call add(c, 'limit_damping')
        if (wall) call add(c, 'zplane 0 NULL')
        call c%vars%set('m', m)
        call c%vars%set('R', r)
        call c%vars%set('k', c%k)
    end subroutine case_lammps

    subroutine case_liggghts(id, d, c, coef)
        character(len=*), intent(in) :: id
        type(draw), intent(in) :: d
        type(case_t), intent(inout) :: c
        real(wp), intent(in), optional :: coef
        real(wp) :: m, r, ymod, nu, y2, nu2, es, kn, x
        logical :: limit
        m = d%m
        r = d%r
        ymod = d%ymod
        nu = d%nu
        y2 = d%y2
        nu2 = d%nu2
        limit = d%limit
        ! section 2: k = (4/3) Y* sqrt(R); hertz/stiffness k = kn sqrt(R)
        c%peer = PEER_LIGGGHTS
        call add(c, 'limitForce=' // merge('on ', 'off', limit))
        if (index(id, 'stiffness') > 0) then
            kn = log_uniform(1.0e5_wp, 1.0e11_wp)
            x = log_uniform(1.0e-3_wp, 1.0e6_wp)
            if (present(coef)) x = coef
            call add(c, 'model=hertz/stiffness kn=' // num(kn) // ' gamman=' // num(x))
            call c%vars%set('gamma_n', x)
            c%k = kn * sqrt(r)
        else
            x = 0.06_wp + 0.94_wp * rnd()
            if (present(coef)) x = coef
            if (rnd() < 0.5_wp) call add(c, 'model=hertz')
            call add(c, 'youngsModulus=' // num(ymod) // ',' // num(y2) // ' poissonsRatio=' // num(nu) // ',' // &
                     num(nu2) // ' coefficientRestitution=' // num(x) // ' tangential=history')
            call c%vars%set('e', x)
            es = 1.0_wp / ((1.0_wp - nu**2) / ymod + (1.0_wp - nu2**2) / y2)
            c%k = (4.0_wp / 3.0_wp) * es * sqrt(r)
        end if
        call c%vars%set('m', m)
        call c%vars%set('R', r)
        call c%vars%set('k', c%k)
    end subroutine case_liggghts

    subroutine case_mercury(id, d, c, coef)
        character(len=*), intent(in) :: id
        type(draw), intent(in) :: d
        type(case_t), intent(inout) :: c
        real(wp), intent(in), optional :: coef
        real(wp) :: m, r, ymod, x
        m = d%m
        r = d%r
        ymod = d%ymod
        ! section 3a: k = (4/3) E_eff sqrt(R)
        c%peer = PEER_MERCURYDPM
        c%k = (4.0_wp / 3.0_wp) * ymod * sqrt(r)
        if (index(id, 'restitution') > 0) then
            x = rnd()
            if (present(coef)) x = coef
            call add(c, 'setEffectiveElasticModulusAndRestitutionCoefficient=' // num(ymod) // ',' // num(x))
            call c%vars%set('e', x)
        else
            x = 3.0_wp * rnd()
            if (present(coef)) x = coef
            call add(c, 'setEffectiveElasticModulus=' // num(ymod) // ' setDissipation=' // num(x))
            call c%vars%set('g', x)
        end if
        call c%vars%set('m', m)
        call c%vars%set('R', r)
        call c%vars%set('k', c%k)
    end subroutine case_mercury

    subroutine case_mercury2015(id, d, c, coef)
        character(len=*), intent(in) :: id
        type(draw), intent(in) :: d
        type(case_t), intent(inout) :: c
        real(wp), intent(in), optional :: coef
        real(wp) :: m1, m, r, ymod, x
        m1 = d%m1
        m = d%m
        r = d%r
        ymod = d%ymod
        ! section 3b: k = (4/3) sqrt(2) E sqrt(R)
        c%peer = PEER_MERCURYDPM
        c%k = (4.0_wp / 3.0_wp) * sqrt(2.0_wp) * ymod * sqrt(r)
        call add(c, 'species=HertzianViscoelasticSpecies')
        if (index(id, 'stiffness') > 0) then
            x = 0.01_wp + 0.99_wp * rnd()
            if (present(coef)) x = coef
            call add(c, 'setStiffnessAndRestitutionCoefficient=' // num(ymod) // ',' // num(x) // ',' // num(m1))
            call c%vars%set('e', x)
            call c%vars%set('mass_arg', m1)
            call c%vars%set('E', ymod)
        else
            x = log_uniform(1.0e-8_wp, 1.0e2_wp)
            if (present(coef)) x = coef
            call add(c, 'setElasticModulus=' // num(ymod) // ' setDissipation=' // num(x))
            call c%vars%set('d', x)
        end if
        call c%vars%set('m', m)
        call c%vars%set('R', r)
        call c%vars%set('k', c%k)
    end subroutine case_mercury2015

    subroutine case_yade(id, d, c, coef)
        character(len=*), intent(in) :: id
        type(draw), intent(in) :: d
        type(case_t), intent(inout) :: c
        real(wp), intent(in), optional :: coef
        real(wp) :: r1, m, r, ymod, nu, y2, nu2, es, x, x2, ref
        logical :: wall
        r1 = d%r1
        m = d%m
        r = d%r
        ymod = d%ymod
        nu = d%nu
        y2 = d%y2
        nu2 = d%nu2
        wall = d%wall
        ! section 4: k = (4/3) E* sqrt(R); walls: R = refR1 r/(refR1 + r), refR1 = r (Wall),
        ! 2r (Facet), 1e8 r (hertzian=True); en by release: yade-en up to 2022.01a,
        ! yade2023-en (Thornton) from 2023.02a, yade2024-vn (en with vn) from 2024.02a
        c%peer = PEER_YADE
        select case (id)
        case ('yade-en-force'); c%release = YADE_2022
        case ('yade2023-en-force'); c%release = merge(YADE_2023, YADE_CURRENT, rnd() < 0.5_wp)
        case ('yade2024-vn-force'); c%release = YADE_CURRENT
        case default; c%release = YADE_2022 + int(2.999_wp * rnd())   ! 2022, 2023 or current
        end select
        call add(c, 'young=' // num(ymod) // ',' // num(y2) // ' poisson=' // num(nu) // ',' // num(nu2))
        es = 1.0_wp / ((1.0_wp - nu**2) / ymod + (1.0_wp - nu2**2) / y2)
        if (wall) then
            x = rnd()
            if (x < 0.33_wp) then
                ref = r1
                call add(c, 'shape=Wall')
            else if (x < 0.66_wp) then
                ref = 2.0_wp * r1
                call add(c, 'shape=Facet')
            else
                ref = 1.0e8_wp * r1
                call add(c, 'hertzian=True')
            end if
            r = ref * r1 / (ref + r1)
        end if
        c%k = (4.0_wp / 3.0_wp) * es * sqrt(r)
        if (index(id, 'betan') > 0) then
            x = rnd()
            if (present(coef)) x = coef
            call add(c, 'betan=' // num(x))
            call c%vars%set('betan', x)
        else
            x = 0.001_wp + 0.999_wp * rnd()
            if (present(coef)) x = coef
            call add(c, 'en=' // num(x))
            call c%vars%set('e', x)
            if (index(id, '-vn-') > 0) then
                x2 = log_uniform(1.0e-2_wp, 1.0e2_wp)
                call add(c, 'vn=' // num(x2))
                call c%vars%set('vn', x2)
            end if
        end if
        call c%vars%set('m', m)
        call c%vars%set('R', r)
        call c%vars%set('k', c%k)
    end subroutine case_yade

    subroutine case_mfix(d, c, coef)
        type(draw), intent(in) :: d
        type(case_t), intent(inout) :: c
        real(wp), intent(in), optional :: coef
        real(wp) :: m, r, ymod, nu, y2, nu2, es, x
        logical :: wall
        m = d%m
        r = d%r
        ymod = d%ymod
        nu = d%nu
        y2 = d%y2
        nu2 = d%nu2
        wall = d%wall
        ! section 5: k = HERT_KN = (4/3) sqrt(R) E*
        c%peer = PEER_MFIX
        x = rnd()
        if (rnd() < 0.1_wp) x = 0.0_wp
        if (present(coef)) x = coef
        call add(c, 'des_coll_model=''HERTZIAN'' E_YOUNG(1)=' // num(ymod) // ' V_POISSON=' // num(nu))
        if (wall) then
            call add(c, 'EW_YOUNG=' // num(y2) // ' VW_POISSON=' // num(nu2) // ' DES_EN_WALL_INPUT=' // num(x))
        else
            call add(c, 'E_YOUNG(2)=' // num(y2) // ' DES_EN_INPUT=' // num(x))
            nu2 = nu
        end if
        es = 1.0_wp / ((1.0_wp - nu**2) / ymod + (1.0_wp - nu2**2) / y2)
        c%k = (4.0_wp / 3.0_wp) * sqrt(r) * es
        call c%vars%set('e', x)
        call c%vars%set('m', m)
        call c%vars%set('R', r)
        call c%vars%set('k', c%k)
    end subroutine case_mfix

    subroutine case_chrono(id, d, c, coef)
        character(len=*), intent(in) :: id
        type(draw), intent(in) :: d
        type(case_t), intent(inout) :: c
        real(wp), intent(in), optional :: coef
        real(wp) :: m, r, ymod, nu, y2, nu2, es, kn, x, mw
        logical :: wall
        m = d%m
        r = d%r
        ymod = d%ymod
        nu = d%nu
        y2 = d%y2
        nu2 = d%nu2
        wall = d%wall
        ! section 6: material k = (4/3) E* sqrt(R) (E*, e single precision), kn/gn: k = kn R;
        ! BULLET: R = 0.1; wall body of mass M_w: gamma times sqrt(M_w/(m + M_w))
        c%peer = PEER_CHRONO
        if (rnd() < 0.5_wp) then
            call add(c, 'SetCollisionSystemType=MULTICORE')
        else
            call add(c, 'SetCollisionSystemType=BULLET')
            r = 0.1_wp
        end if
        if (wall) then
            mw = log_uniform(1.0e-3_wp, 1.0e3_wp)
            call add(c, 'wallMass=' // num(mw))
            c%gfac = sqrt(mw / (m + mw))
        end if
        if (index(id, 'kn_gn') > 0) then
            kn = log_uniform(1.0e5_wp, 1.0e11_wp)
            x = log_uniform(1.0e-3_wp, 1.0e6_wp)
            if (present(coef)) x = coef
            call add(c, 'UseMaterialProperties=false SetKn=' // num(kn) // ' SetGn=' // num(x))
            c%k = real(real(kn, real32), wp) * r   ! Chrono stores kn as a float
            call c%vars%set('gn', real(real(x, real32), wp))
            c%gfac = 1.0_wp
            if (wall) c%gfac = mw / (m + mw)   ! d = gn m_damp R, m_damp = m M_w/(m + M_w)
        else
            x = rnd()
            if (present(coef)) x = coef
            call add(c, 'SetYoungModulus=' // num(ymod) // ',' // num(y2) // ' SetPoissonRatio=' // num(nu) // &
                     ',' // num(nu2) // ' SetRestitution=' // num(x))
            es = 1.0_wp / ((1.0_wp - nu**2) / ymod + (1.0_wp - nu2**2) / y2)
            c%k = (4.0_wp / 3.0_wp) * es * sqrt(r)
            c%ktol = 1.0e-6_wp
            call c%vars%set('e', real(real(x, real32), wp))
        end if
        call c%vars%set('m', m)
        call c%vars%set('R', r)
        call c%vars%set('k', c%k)
    end subroutine case_chrono

    subroutine read_case(c, deck, st, msg)
        type(case_t), intent(in) :: c
        type(peer_deck), intent(out) :: deck
        integer, intent(out) :: st
        character(len=:), allocatable, intent(out) :: msg
        call peer_read_deck(c%peer, c%tok, c%mat, c%release, deck, st, msg)
    end subroutine read_case

    subroutine test_formulas()
        type(case_t) :: c
        type(peer_deck) :: deck
        integer :: row, i, st, nbad_a, nbad_k, nbad_read, nrow_bad
        real(wp) :: a_code, tstar, a_spec, u, worst_a, worst_k
        character(len=:), allocatable :: msg, err, id
        logical :: ok
        nrow_bad = 0
        do row = 1, peer_spec_count
            id = peer_spec_field(row, 'id')
            call s%check(peer_row_coef(row) > 0, id // ': has a formula (peer_row_coef)')
            nbad_a = 0
            nbad_k = 0
            nbad_read = 0
            worst_a = 0.0_wp
            worst_k = 0.0_wp
            do i = 1, 60
                call make_case(id, c)
                call read_case(c, deck, st, msg)
                if (st /= HD_OK) then
                    nbad_read = nbad_read + 1
                    if (nbad_read == 1) print '(a)', '  ' // id // ': ' // msg
                    cycle
                end if
                if (deck%row /= row) then
                    nbad_read = nbad_read + 1
                    if (nbad_read == 1) print '(a)', '  ' // id // ': deck read as ' // peer_spec_field(deck%row, 'id')
                    cycle
                end if
                reached(row) = .true.
                u = getv(c, 'u')
                call peer_alpha(deck, u, a_code, tstar, st)
                a_spec = expr_eval(peer_spec_field(row, 'alpha_expr'), c%vars, ok, err)
                if (.not. ok) then
                    print '(a)', '  ' // id // ': alpha_expr: ' // err
                    nbad_a = nbad_a + 1
                    cycle
                end if
                a_spec = a_spec * c%gfac
                worst_a = max(worst_a, rel_err(a_code, a_spec))
                worst_k = max(worst_k, rel_err(deck%k, c%k))
                ! relative 1e-12, and absolute 1e-13: P6 near e = 1 is 3e-4 from terms of size 90
                if (.not. abs(a_code - a_spec) <= 1.0e-12_wp * abs(a_spec) + 1.0e-13_wp) nbad_a = nbad_a + 1
                if (rel_err(deck%k, c%k) > c%ktol) nbad_k = nbad_k + 1
            end do
            call s%check(nbad_read == 0, id // ': decks in the engine''s keywords are read as this row')
            call s%check(nbad_a == 0, id // ': alpha equals alpha_expr (60 random decks)')
            call s%check(nbad_k == 0, id // ': k equals doc/peers.md')
            if (nbad_a + nbad_k + nbad_read > 0) then
                nrow_bad = nrow_bad + 1
                print '(a,2es10.2)', '  ' // id // ': worst rel err alpha, k', worst_a, worst_k
            end if
            ! the law and end of the deck are the row's
            call s%check(deck%law == peer_row_law(row) .and. deck%iend == peer_row_end(row), id // ': law and end')
        end do
        call s%check(all(reached(1:peer_spec_count)), 'every row of the specification is reached by a deck')
        print '(a,i0,a,i0)', 'formulas: rows ', peer_spec_count, ', rows with a mismatch ', nrow_bad
    end subroutine test_formulas

    ! ------------------------------------------------------------------ achieved e

    !> A bound value of a case.
    real(wp) function getv(c, name) result(x)
        type(case_t), intent(in) :: c
        character(len=*), intent(in) :: name
        integer :: j
        x = 0.0_wp
        do j = 1, c%vars%n
            if (c%vars%name(j) == name) x = c%vars%val(j)
        end do
    end function getv

    !> LAMMPS `velocity` (q = 0): e equals the library's forward map at the same alpha,
    !> and the dimensional forward problem with k and d = eta_n0 from the deck.
    subroutine test_linear_forward()
        type(case_t) :: c
        type(peer_deck) :: deck
        type(peer_point) :: pt
        type(hertzdamp_collision) :: r
        integer :: i, st, iend, nbad, nbad_dim, saved
        real(wp) :: u, eta, a, ts, e2, tc2, zm, worst, tstar
        character(len=:), allocatable :: msg, id
        do iend = HD_END_OVERLAP, HD_END_FORCE
            id = 'lammps-2021-velocity-' // trim(merge('overlap', 'force  ', iend == HD_END_OVERLAP))
            nbad = 0
            nbad_dim = 0
            worst = 0.0_wp
            do i = 1, 40
                saved = seed
                call make_case(id, c)
                u = getv(c, 'u')
                tstar = (getv(c, 'm') / (getv(c, 'k') * sqrt(u)))**0.4_wp
                ! the same materials with eta = alpha m / t*, alpha in (0.02, 1.1) (overlap) or (0.02, 20)
                eta = (0.02_wp + merge(1.08_wp, 20.0_wp, iend == HD_END_OVERLAP) * rnd()) * getv(c, 'm') / tstar
                seed = saved
                call make_case(id, c, coef=eta)
                call read_case(c, deck, st, msg)
                pt = peer_evaluate(deck, u, 0.5_wp)
                r = hertzdamp_forward_alpha(pt%alpha, iend, HD_METHOD_FIT)
                worst = max(worst, rel_err(pt%e, r%e))
                if (rel_err(pt%e, r%e) > 1.0e-12_wp .or. rel_err(pt%tc, pt%tstar * r%tau_c) > 1.0e-12_wp) nbad = nbad + 1
                call hertzdamp_forward_dim(deck%k, eta, deck%m, u, iend, HD_METHOD_RK45, a, ts, e2, tc2, zm, st)
                if (rel_err(pt%e, e2) > 1.0e-12_wp .or. rel_err(pt%tc, tc2) > 1.0e-12_wp .or. &
                    rel_err(pt%alpha, a) > 1.0e-13_wp) nbad_dim = nbad_dim + 1
            end do
            print '(a,es10.2)', 'linear ' // hertzdamp_end_name(iend) // ': worst rel err of e against the fit', worst
            call s%check(nbad == 0, 'lammps velocity (' // hertzdamp_end_name(iend) // &
                         '): e and t_c equal the library''s fitted forward map to 1e-12')
            call s%check(nbad_dim == 0, 'lammps velocity (' // hertzdamp_end_name(iend) // &
                         '): e, t_c, alpha equal hertzdamp_forward_dim(k, d = eta_n0, m, u)')
        end do
    end subroutine test_linear_forward

    !> gamma = sqrt(5) beta(e) with the overlap end (LAMMPS coeff_restitution, LIGGGHTS
    !> hertz, MercuryDPM): e = target to 1e-10 at every speed (Antypov & Elliott 2011).
    subroutine test_closed_form()
        character(len=40), parameter :: ids(3) = [character(len=40) :: 'lammps-2024-coeff_restitution-overlap', &
                                                  'liggghts-hertz-overlap', 'mercurydpm-restitution-overlap']
        type(case_t) :: c
        type(peer_deck) :: deck
        type(peer_point) :: pt
        integer :: j, i, st, nbad
        real(wp) :: et, worst
        character(len=:), allocatable :: msg
        do j = 1, size(ids)
            nbad = 0
            worst = 0.0_wp
            do i = 1, 25
                et = 0.06_wp**(real(i - 1, wp) / 24.0_wp)   ! 0.06 ... 1
                call make_case(trim(ids(j)), c, coef=et)
                call read_case(c, deck, st, msg)
                pt = peer_evaluate(deck, getv(c, 'u'), et)
                if (pt%status /= HD_OK) then
                    nbad = nbad + 1
                    cycle
                end if
                worst = max(worst, abs(pt%e - et))
                if (abs(pt%e - et) > 1.0e-10_wp) nbad = nbad + 1
            end do
            print '(a,es10.2)', trim(ids(j)) // ': worst |e - target| ', worst
            call s%check(nbad == 0, trim(ids(j)) // ': gamma = sqrt(5) beta(e), overlap end: e = target to 1e-10')
        end do
    end subroutine test_closed_form

    !> The corrected parameter fed back as a deck (the same materials and speed) gives
    !> the target e.
    subroutine test_corrected()
        type(case_t) :: c
        type(peer_deck) :: deck
        type(peer_point) :: pt, pt2
        integer :: row, i, st, nbad, ntried, saved, after, nrefused
        real(wp) :: et, u, tol
        character(len=:), allocatable :: msg, id, problem
        do row = 1, peer_spec_count
            id = peer_spec_field(row, 'id')
            nbad = 0
            ntried = 0
            nrefused = 0
            tol = 1.0e-10_wp
            if (index(id, 'chrono') == 1) tol = 1.0e-6_wp   ! Chrono stores e and gn as floats
            do i = 1, 10
                et = 0.1_wp + 0.85_wp * rnd()
                saved = seed
                call make_case(id, c)
                call read_case(c, deck, st, msg)
                u = getv(c, 'u')
                pt = peer_evaluate(deck, u, et)
                if (pt%status_corrected /= HD_OK) cycle
                ntried = ntried + 1
                after = seed
                problem = peer_parameter_problem(deck, pt%p_corrected)
                seed = saved
                call make_case(id, c, coef=pt%p_corrected)
                seed = after
                call read_case(c, deck, st, msg)
                if (len(problem) > 0) then
                    ! the check says the engine refuses the value: so does the deck reader
                    nrefused = nrefused + 1
                    if (st == HD_OK) nbad = nbad + 1
                    cycle
                end if
                if (st /= HD_OK) then
                    nbad = nbad + 1
                    print '(a)', '  ' // id // ': corrected deck refused: ' // msg
                    cycle
                end if
                pt2 = peer_evaluate(deck, u, et)
                if (.not. abs(pt2%e - et) <= tol * et) then
                    nbad = nbad + 1
                    print '(a,3es12.4)', '  ' // id // ': target, corrected p, e', et, pt%p_corrected, pt2%e
                end if
            end do
            call s%check(nbad == 0 .and. ntried > nrefused, id // ': the corrected parameter gives the target e (' // &
                         trim(merge('1e-6 ', '1e-10', tol > 1.0e-8_wp)) // '), or the engine refuses it as reported')
        end do
    end subroutine test_corrected

    ! ------------------------------------------------------------------ time estimates

    subroutine test_time_estimates()
        type(case_t) :: c
        type(peer_deck) :: deck
        type(peer_point) :: pt
        integer :: st, i
        real(wp) :: ce, g
        character(len=:), allocatable :: msg
        ! exact elastic Hertz time: T = tau_c(0) (m/(k sqrt(v)))^(2/5) = ce (m^2/(R E*^2 v))^(1/5)
        ce = hertzdamp_tau_c0() * 0.75_wp**0.4_wp
        do i = 1, 5
            ! MercuryDPM getCollisionTime: identical spheres -> 2.214 / (ce (pi^2/36)^(1/5)) times the Hertz time
            call make_case('mercurydpm-restitution-overlap', c)
            c%mat%radius(2) = c%mat%radius(1)
            c%mat%density(2) = c%mat%density(1)
            c%mat%wall = .false.
            call read_case(c, deck, st, msg)
            pt = peer_evaluate(deck, getv(c, 'u'), 0.5_wp)
            call s%check_close(pt%t_peer / pt%t_hertz, 2.214_wp / (ce * (pi**2 / 36.0_wp)**0.2_wp), 1.0e-12_wp, &
                               'MercuryDPM getCollisionTime is the elastic Hertz time of identical spheres')
            ! LIGGGHTS check/timestep/gran: whole particle mass and r/2, v = u (pair) or 2u (wall)
            call make_case('liggghts-hertz-overlap', c)
            c%mat%radius(2) = c%mat%radius(1)
            c%mat%density(2) = c%mat%density(1)
            call read_case(c, deck, st, msg)
            pt = peer_evaluate(deck, getv(c, 'u'), 0.5_wp)
            if (c%mat%wall) then
                ! m_p = m, r/2 = R/2, v = 2u: ratio (2.87/ce) (2/2)^(1/5) = 2.87/ce... (m^2/(R/2 v2u))
                g = 2.87_wp / ce * (1.0_wp / (0.5_wp * 2.0_wp))**0.2_wp
            else
                ! m_p = 2 m, r/2 = R: ratio (2.87/ce) 4^(1/5) (doc/peers.md section 8: 1.32)
                g = 2.87_wp / ce * 4.0_wp**0.2_wp
            end if
            call s%check_close(pt%t_peer / pt%t_hertz, g, 1.0e-12_wp, &
                               'LIGGGHTS fix check/timestep/gran against the elastic Hertz time')
        end do
        ! the same with E* 1e296 times smaller and larger (E*^2 alone is beyond double precision)
        do i = -1, 1, 2
            call s%check_close(scaled_ratio('mercurydpm-restitution-overlap', 10.0_wp**(296 * i)), &
                               2.214_wp / (ce * (pi**2 / 36.0_wp)**0.2_wp), 1.0e-12_wp, &
                               'MercuryDPM getCollisionTime with E* scaled by 1e' // trim(merge('+296', '-296', i > 0)))
            call s%check_close(scaled_ratio('liggghts-hertz-overlap', 10.0_wp**(296 * i)), 2.87_wp / ce * 4.0_wp**0.2_wp, &
                               1.0e-12_wp, 'LIGGGHTS check/timestep/gran with E* scaled by 1e' // &
                               trim(merge('+296', '-296', i > 0)))
        end do
        call s%check_close(2.87_wp / ce * 4.0_wp**0.2_wp, 1.32_wp, 5.0e-3_wp, &
                           'LIGGGHTS estimate is 1.32 times the Hertz time for a pair (doc/peers.md)')
        ! MFiX TCOLL = pi / sqrt(k/m - (eta/m)^2/4), eta = 2 beta(e) sqrt(k m)
        call make_case('mfix-hertzian-overlap', c, coef=0.5_wp)
        call read_case(c, deck, st, msg)
        pt = peer_evaluate(deck, getv(c, 'u'), 0.5_wp)
        g = log(0.5_wp) / sqrt(pi**2 + log(0.5_wp)**2)
        call s%check_close(pt%t_peer, pi / sqrt(deck%k / deck%m * (1.0_wp - g**2)), 1.0e-13_wp, &
                           'MFiX TCOLL with DES_ETAN = 2 beta(e) sqrt(k m)')
    end subroutine test_time_estimates

    !> t_peer/t_hertz of a deck of two equal spheres of row `id` with E* and k scaled by f.
    real(wp) function scaled_ratio(id, f) result(ratio)
        character(len=*), intent(in) :: id
        real(wp), intent(in) :: f
        type(case_t) :: c
        type(peer_deck) :: deck
        type(peer_point) :: pt
        integer :: st
        character(len=:), allocatable :: msg
        call make_case(id, c)
        c%mat%radius(2) = c%mat%radius(1)
        c%mat%density(2) = c%mat%density(1)
        c%mat%wall = .false.
        call read_case(c, deck, st, msg)
        deck%e_star = deck%e_star * f
        deck%k = deck%k * f
        pt = peer_evaluate(deck, getv(c, 'u'), 0.5_wp)
        ratio = pt%t_peer / pt%t_hertz
    end function scaled_ratio

    ! ------------------------------------------------------------------ the maps of check

    !> peer_law_forward (fit, rk45 beyond the fitted range) and peer_law_inverse (fit)
    !> against the reference integrator at tol 1e-14, every law and contact end.
    subroutine test_maps()
        integer, parameter :: laws(3) = [HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO]
        real(wp), parameter :: alphas(17) = [0.0_wp, 1.0e-3_wp, 0.05_wp, 0.3_wp, 0.7_wp, 1.0_wp, 1.12_wp, &
                                             1.1279_wp, 1.12797_wp, 1.5_wp, 2.2_wp, 3.0_wp, 8.0_wp, 14.0_wp, 40.0_wp, &
                                             300.0_wp, 1500.0_wp]
        real(wp), parameter :: targets(10) = [1.0e-4_wp, 1.0e-3_wp, 0.01_wp, 0.1_wp, 0.3_wp, 0.5_wp, 0.7_wp, &
                                              0.9_wp, 0.999_wp, 1.0_wp]
        type(hertzdamp_collision) :: r
        real(wp) :: e, tau, a, tau_i
        integer :: k, iend, j, st, meth, nbad, nfit_bad, nrk, nbad_inv, ninv
        character(len=:), allocatable :: label
        do k = 1, size(laws)
            do iend = HD_END_OVERLAP, HD_END_FORCE
                label = hertzdamp_law_name(laws(k)) // ' ' // hertzdamp_end_name(iend)
                nbad = 0
                nfit_bad = 0
                nrk = 0
                do j = 1, size(alphas)
                    call peer_law_forward(laws(k), alphas(j), iend, e, tau, st, meth)
                    r = hertzdamp_rk45_collide(alphas(j), iend, tol=1.0e-14_wp, law=laws(k))
                    if (meth == HD_METHOD_RK45) nrk = nrk + 1
                    if (st /= r%status) then
                        nbad = nbad + 1
                        print '(a,es10.3,2(1x,i0))', '  ' // label // ': status differs at alpha', alphas(j), st, r%status
                    else if (st == HD_OK) then
                        if (abs(e - r%e) > 1.0e-10_wp * max(r%e, 1.0e-3_wp) .or. rel_err(tau, r%tau_c) > 1.0e-10_wp) then
                            nbad = nbad + 1
                            print '(a,es10.3,2es12.4)', '  ' // label // ': e, tau_c differ at alpha', alphas(j), &
                                e - r%e, tau - r%tau_c
                        end if
                        ! e >= 1e-4 lies inside every fitted forward range (doc/damping-laws.md)
                        if (r%e >= 1.0e-4_wp .and. meth /= HD_METHOD_FIT) nfit_bad = nfit_bad + 1
                    else if (st == HD_NO_REBOUND) then
                        if (.not. (e == 0.0_wp .and. tau > huge(tau))) nbad = nbad + 1
                    end if
                end do
                call s%check(nbad == 0, label // ': check''s forward map = rk45 at tol 1e-14 (e to 1e-10 of ' // &
                             'max(e, 1e-3), tau_c to 1e-10, the same status) for alpha 0 ... 1500')
                call s%check(nfit_bad == 0, label // ': the fitted map wherever e >= 1e-4')
                print '(a,i0,a)', '  ' // label // ': ', nrk, ' of 17 alphas beyond the fitted range (rk45)'
                ! the inverse: e(alpha(e)) = e on the reference integrator; the fit's range as documented
                nbad_inv = 0
                ninv = 0
                do j = 1, size(targets)
                    call peer_law_inverse(laws(k), targets(j), iend, a, st)
                    if (targets(j) < hertzdamp_fit_law_e_min(laws(k), iend)) then
                        if (st /= HD_BAD_RESTITUTION) nbad_inv = nbad_inv + 1
                        cycle
                    end if
                    ninv = ninv + 1
                    r = hertzdamp_rk45_collide(a, iend, tol=1.0e-14_wp, law=laws(k))
                    call hertzdamp_invert_alpha(targets(j), iend, e, tau_i, st, law=laws(k))
                    if (st /= HD_OK .or. r%status /= HD_OK .or. &
                        abs(r%e - targets(j)) > 1.0e-10_wp * max(targets(j), 1.0e-3_wp)) then
                        nbad_inv = nbad_inv + 1
                        print '(a,2es12.4)', '  ' // label // ': target, e(alpha(target)) on rk45', targets(j), r%e
                    end if
                end do
                call s%check(nbad_inv == 0 .and. ninv >= 8, label // ': e(alpha(e)) = e on rk45 at tol 1e-14 ' // &
                             '(1e-10 of max(e, 1e-3)), targets below the fit''s e_min refused')
            end do
        end do
    end subroutine test_maps

    !> alpha beyond double precision: no rebound (e = 0, t_c = +inf) exactly for the
    !> laws with alpha_c (linear, tsuji) at the overlap end (alpha >= alpha_c: the overlap
    !> never returns, doc/theory.md section 3); otherwise no result, never an error of the input.
    subroutine test_overdamped()
        type(case_t) :: c
        type(peer_deck) :: deck
        type(peer_point) :: pt
        integer :: st, iend
        character(len=:), allocatable :: msg, id
        real(wp) :: u
        do iend = HD_END_OVERLAP, HD_END_FORCE
            ! linear: LAMMPS velocity with eta_n0 = 1e300 at u = 1e-300 (alpha ~ 1e360)
            id = 'lammps-2021-velocity-' // trim(merge('overlap', 'force  ', iend == HD_END_OVERLAP))
            call make_case(id, c, coef=1.0e300_wp)
            call read_case(c, deck, st, msg)
            u = 1.0e-300_wp
            pt = peer_evaluate(deck, u, 0.5_wp)
            if (iend == HD_END_OVERLAP) then
                call s%check(pt%status == HD_NO_REBOUND .and. pt%e == 0.0_wp .and. pt%tc > huge(1.0_wp) .and. &
                             ieee_is_nan(pt%alpha), 'linear overlap, alpha ~ 1e360: no rebound, alpha not representable')
            else
                call s%check(pt%status == HD_OUT_OF_RANGE .and. ieee_is_nan(pt%e) .and. ieee_is_nan(pt%tc), &
                             'linear force, alpha ~ 1e360: out of range (the force end always rebounds)')
            end if
            ! linear, alpha = 1e150 (representable, beyond every method): the fit's no rebound / outside
            call make_case(id, c, coef=1.0_wp)
            call read_case(c, deck, st, msg)
            deck%p = 1.0e150_wp * deck%m / (deck%m / (deck%k * sqrt(1.0_wp)))**0.4_wp
            pt = peer_evaluate(deck, 1.0_wp, 0.5_wp)
            call s%check_close(pt%alpha, 1.0e150_wp, 1.0e-12_wp, 'linear, eta_n0 for alpha = 1e150')
            if (iend == HD_END_OVERLAP) then
                call s%check(pt%status == HD_NO_REBOUND .and. pt%method == HD_METHOD_FIT, &
                             'linear overlap, alpha = 1e150: no rebound (fit: alpha >= alpha_c)')
            else
                call s%check(pt%status == HD_OUTSIDE_VALIDITY, &
                             'linear force, alpha = 1e150: outside every method (not an input error)')
            end if
            ! kuwabara-kono (no alpha_c): never no rebound
            id = 'lammps-2021-viscoelastic-' // trim(merge('overlap', 'force  ', iend == HD_END_OVERLAP))
            call make_case(id, c, coef=1.0e300_wp)
            call read_case(c, deck, st, msg)
            pt = peer_evaluate(deck, 1.0e300_wp, 0.5_wp)
            call s%check(pt%status == HD_OUT_OF_RANGE, 'kuwabara-kono ' // hertzdamp_end_name(iend) // &
                         ', alpha beyond double precision: out of range (the law has no alpha_c)')
        end do
    end subroutine test_overdamped

    !> Every row, decks scaled by up to 1e+-300 (mass, stiffness, radius, modulus, density,
    !> the damping input), speeds 1e-300 ... 1e300, targets down to 1e-320: every number
    !> of the point is finite or NaN (t_c = +inf only without rebound), and a point with a
    !> result has its results; a value beyond range is said (beyond, status_corrected).
    subroutine test_extremes()
        type(case_t) :: c
        type(peer_deck) :: deck
        type(peer_point) :: pt
        integer :: row, i, st, nbad, nres, nout, nnr
        real(wp) :: f, et
        character(len=:), allocatable :: msg, id
        nres = 0
        nout = 0
        nnr = 0
        do row = 1, peer_spec_count
            id = peer_spec_field(row, 'id')
            nbad = 0
            do i = 1, 40
                call make_case(id, c)
                call read_case(c, deck, st, msg)
                if (st /= HD_OK) cycle
                f = 10.0_wp**(600.0_wp * rnd() - 300.0_wp)
                deck%m = deck%m * 10.0_wp**(200.0_wp * rnd() - 100.0_wp)
                deck%m_damp = deck%m
                deck%k = deck%k * f
                deck%e_star = deck%e_star * f
                deck%mass1 = deck%mass1 * 10.0_wp**(200.0_wp * rnd() - 100.0_wp)
                deck%radius1 = deck%radius1 * 10.0_wp**(200.0_wp * rnd() - 100.0_wp)
                deck%radius = deck%radius * 10.0_wp**(200.0_wp * rnd() - 100.0_wp)
                deck%density1 = deck%density1 * 10.0_wp**(200.0_wp * rnd() - 100.0_wp)
                select case (deck%coef)
                case (COEF_D, COEF_D_MASS, COEF_D_MASS_SQRT_R, COEF_D_MASS_R, COEF_GAMMA, COEF_GAMMA_SQRT6)
                    deck%p = deck%p * 10.0_wp**(400.0_wp * rnd() - 200.0_wp)
                case default
                end select
                et = merge(10.0_wp**(-320.0_wp * rnd()), rnd(), rnd() < 0.3_wp)
                if (.not. et > 0.0_wp) et = 0.5_wp
                pt = peer_evaluate(deck, 10.0_wp**(600.0_wp * rnd() - 300.0_wp), et)
                if (.not. point_ok(pt)) then
                    nbad = nbad + 1
                    print '(a,i0,a,5es11.3)', '  ' // id // ': status ', pt%status, ' alpha, e, tc, t_peer, p', &
                        pt%alpha, pt%e, pt%tc, pt%t_peer, pt%p_corrected
                end if
                if (pt%status == HD_OK) nres = nres + 1
                if (pt%status == HD_NO_REBOUND) nnr = nnr + 1
                if (pt%status == HD_OUT_OF_RANGE) nout = nout + 1
            end do
            call s%check(nbad == 0, id // ': decks scaled by 1e+-300: no infinity, no NaN result, statuses said')
        end do
        print '(a,3(i0,a))', 'extreme decks: ', nres, ' ok, ', nnr, ' no rebound, ', nout, ' out of range'
        call s%check(nres > 0 .and. nnr > 0 .and. nout > 0, 'extreme decks reach ok, no rebound and out of range')
    end subroutine test_extremes

    !> The invariants of a point: finite or NaN, +inf only as the contact time of no rebound.
    logical function point_ok(pt) result(ok)
        type(peer_point), intent(in) :: pt
        real(wp) :: v(11)
        logical :: have
        v = [pt%u, pt%alpha, pt%tstar, pt%e, pt%e_error, pt%t_force, pt%t_hertz, pt%t_peer, pt%alpha_target, &
             pt%p_corrected, pt%tc]
        ok = all(ieee_is_finite(v(1:10)) .or. ieee_is_nan(v(1:10)))
        have = pt%status == HD_OK .or. pt%status == HD_NO_REBOUND
        if (pt%status == HD_NO_REBOUND) then
            ok = ok .and. pt%tc > huge(1.0_wp) .and. pt%e == 0.0_wp .and. pt%e_error == -1.0_wp
        else
            ok = ok .and. (ieee_is_finite(pt%tc) .or. ieee_is_nan(pt%tc))
        end if
        if (pt%status == HD_OK) then
            ok = ok .and. all(ieee_is_finite([pt%alpha, pt%tstar, pt%e, pt%e_error, pt%tc, pt%t_hertz])) .and. &
                 pt%e >= 0.0_wp .and. pt%e <= 1.0_wp .and. pt%tc > 0.0_wp
        end if
        if (.not. have) ok = ok .and. ieee_is_nan(pt%e) .and. ieee_is_nan(pt%tc) .and. pt%status_corrected /= HD_OK
        if (pt%status == HD_OUT_OF_RANGE) ok = ok .and. allocated(pt%beyond)
        if (pt%status_corrected == HD_OK) ok = ok .and. ieee_is_finite(pt%p_corrected) .and. have
    end function point_ok

    ! ------------------------------------------------------------------ bad decks

    subroutine expect_error(peer, text, key, label, wall, release)
        integer, intent(in) :: peer
        character(len=*), intent(in) :: text, key, label
        logical, intent(in), optional :: wall
        integer, intent(in), optional :: release
        type(case_t) :: c
        type(peer_deck) :: deck
        integer :: st
        character(len=:), allocatable :: msg
        allocate (c%tok(0))
        c%peer = peer
        c%mat%radius = [1.0e-3_wp, 0.0_wp]
        c%mat%density = [2500.0_wp, 0.0_wp]
        if (present(wall)) c%mat%wall = wall
        if (present(release)) c%release = release
        call add(c, text)
        call read_case(c, deck, st, msg)
        call s%check(st /= HD_OK .and. index(msg, key) > 0, 'bad deck (' // label // '): error names ' // key)
        if (.not. (st /= HD_OK .and. index(msg, key) > 0)) print '(a)', '     message: ' // msg
    end subroutine expect_error

    subroutine test_bad_decks()
        call expect_error(PEER_LAMMPS, 'hertz/material -1e8 0.5 0.3 damping tsuji', 'E', 'negative modulus')
        call expect_error(PEER_LAMMPS, 'hertz/material 1e8 0.5 1.2', 'nu', 'Poisson ratio')
        call expect_error(PEER_LAMMPS, 'hertz/material 1e8 0.5', 'hertz/material', 'missing value')
        call expect_error(PEER_LAMMPS, 'hertz/material 1e8 0.5 0.3 damping foo', 'foo', 'unknown damping model')
        call expect_error(PEER_LAMMPS, 'hertz/material 1e8 0.5 0.3 frobnicate 1', 'frobnicate', 'unknown keyword')
        call expect_error(PEER_LAMMPS, 'damping tsuji', 'normal model', 'no normal model')
        call expect_error(PEER_LAMMPS, 'hooke 1e5 0.5', 'hooke', 'linear normal model')
        call expect_error(PEER_LAMMPS, 'hertz 1e5 1.5 damping tsuji', 'restitution', 'tsuji e > 1')
        call expect_error(PEER_LAMMPS, 'hertz 1e5 0.5 damping coeff_restitution', 'coeff_restitution', &
                          'coeff_restitution in 2021', release=LAMMPS_2021)
        call expect_error(PEER_LAMMPS, 'hertz 1e5x 0.5', '1e5x', 'malformed number')
        call expect_error(PEER_LAMMPS, 'fix 1 all wall/gran granular hertz 1e5 0.5 zcylinder 1', 'zcylinder', &
                          'curved wall')
        call expect_error(PEER_LIGGGHTS, 'youngsModulus=5e6 poissonsRatio=0.45 coefficientRestitution=0.03', &
                          'coefficientRestitution', 'LIGGGHTS e range')
        call expect_error(PEER_LIGGGHTS, 'youngsModulus=5e6 poissonsRatio=0.45', 'coefficientRestitution', 'missing key')
        call expect_error(PEER_LIGGGHTS, 'youngsModulus=5e6 poissonsRatio=0.45 coefficientRestitution=0.5 foo=1', &
                          'foo', 'unknown key')
        call expect_error(PEER_LIGGGHTS, 'youngsModulus=-5e6 poissonsRatio=0.45 coefficientRestitution=0.5', &
                          'youngsModulus', 'negative modulus')
        call expect_error(PEER_MERCURYDPM, 'setDissipation=0.5', 'elastic modulus', 'MercuryDPM without modulus')
        call expect_error(PEER_MERCURYDPM, 'setEffectiveElasticModulusAndRestitutionCoefficient=1e9', &
                          'setEffectiveElasticModulusAndRestitutionCoefficient', 'wrong argument count')
        call expect_error(PEER_YADE, 'young=1e9 poisson=0.3 en=0.5 betan=0.2', 'betan', 'en and betan')
        call expect_error(PEER_YADE, 'young=1e9 poisson=0.3 en=0', 'en', 'Yade en = 0')
        call expect_error(PEER_YADE, 'young=1e9 poisson=0.3 en=0.5 shape=Facet', 'shape', 'shape without --wall')
        call expect_error(PEER_MFIX, 'E_YOUNG=1e9 V_POISSON=0.3 DES_EN_INPUT=0.9', 'DES_COLL_MODEL', 'MFiX model')
        call expect_error(PEER_MFIX, 'DES_COLL_MODEL=HERTZIAN KN=1e5 DES_EN_INPUT=0.9', 'KN', 'MFiX KN')
        call expect_error(PEER_MFIX, 'DES_COLL_MODEL=HERTZIAN E_YOUNG=1e9 V_POISSON=0.3 DES_EN_INPUT=0.9', &
                          'EW_YOUNG', 'MFiX wall without EW_YOUNG', wall=.true.)
        ! issue 21 item 5: three values of a two-body key are refused before anything is written
        ! (this test ran into -fcheck=bounds before the fix)
        call expect_error(PEER_MFIX, 'DES_COLL_MODEL=HERTZIAN E_YOUNG=1e9 V_POISSON=0.3 DES_EN_INPUT=0.9 RO_S0=1,2,3', &
                          'RO_S0: at most 2 values', 'MFiX RO_S0 with three values')
        call expect_error(PEER_MFIX, 'DES_COLL_MODEL=HERTZIAN E_YOUNG=1e9 V_POISSON=0.3 DES_EN_INPUT=0.9 D_P0=1,2,3', &
                          'D_P0: at most 2 values', 'MFiX D_P0 with three values')
        ! issue 21 item 8: DES_EN_INPUT(k) is the pair k in MFiX's order 1-1, 1-2, 2-2
        call expect_error(PEER_MFIX, 'DES_COLL_MODEL=HERTZIAN E_YOUNG=1e9,2e9 V_POISSON=0.3 DES_EN_INPUT(1)=0.9', &
                          'DES_EN_INPUT(2)', 'MFiX two phases: the 1-2 pair is DES_EN_INPUT(2)')
        call expect_error(PEER_YADE, 'young=1e9 poisson=0.3 en=0.5 vn=1', 'vn', 'Yade vn before 2024.02a', &
                          release=YADE_2023)
        call expect_error(PEER_YADE, 'young=1e9 poisson=0.3 vn=1', 'vn needs en', 'Yade vn without en')
        call expect_error(PEER_LAMMPS, 'gran/hertz/history 1e5 NULL', 'gran/hertz/history', 'classic style too short')
        call expect_error(PEER_LAMMPS, 'gran/hooke/history 1e5 NULL 10 NULL 0.5 1', 'linear spring', 'classic hooke')
        call mfix_indexed()
        call expect_error(PEER_CHRONO, 'SetYoungModulus=1e9 SetPoissonRatio=0.3 SetRestitution=0.5 SetKn=1e5', &
                          'SetKn', 'Chrono keys of the other mode')
        call expect_error(PEER_CHRONO, 'SetYoungModulus=1e9 SetPoissonRatio=0.3 SetRestitution=0.5 SetYoungModulus=2e9', &
                          'SetYoungModulus', 'repeated key')
    end subroutine test_bad_decks

    !> Yade's vn: alpha = V*^2 (u/vn)^(1/5), so at u = vn the force-end Kuwabara-Kono e of
    !> the reference integrator at alpha = V*^2 must be the Mueller-Poeschel Pade of V*, to
    !> the accuracy of their fit (measured: 6.4e-4 at most for 0.05 <= V* <= 3).
    subroutine test_yade_pade()
        type(hertzdamp_collision) :: r
        real(wp) :: v, worst
        integer :: i
        worst = 0.0_wp
        do i = 1, 60
            v = 0.05_wp * i
            r = hertzdamp_forward_alpha(v * v, HD_END_FORCE, HD_METHOD_RK45, law=HD_DAMPING_KUWABARA_KONO)
            worst = max(worst, abs(r%e - peer_pade_mp(v)))
            call s%check(r%status == HD_OK, 'Yade vn: rk45 at alpha = V*^2')
        end do
        call s%check(worst < 1.0e-3_wp, 'Yade vn: Pade(V*) = force-end Kuwabara-Kono e(V*^2) within 1e-3')
        print '(a, es10.2)', 'Yade vn: worst |Pade(V*) - e_force(V*^2)| ', worst
        call s%check(abs(peer_pade_mp(peer_pade_mp_inverse(0.37_wp)) - 0.37_wp) < 1.0e-14_wp, &
                     'Yade vn: the Pade inverse')
        call s%check(abs(peer_thornton(peer_thornton_inverse_e(0.8_wp)) - 0.8_wp) < 1.0e-12_wp, &
                     'Yade en: the Thornton inverse')
    end subroutine test_yade_pade

    real(wp) function peer_thornton_inverse_e(b) result(e)
        real(wp), intent(in) :: b
        integer :: st
        call peer_thornton_inverse(b, e, st)
    end function peer_thornton_inverse_e

    !> issue 21 item 8: `check mfix DES_EN_INPUT(1)=0.5` reads the 1-1 pair (it said
    !> DES_EN_INPUT is missing); DES_EN_INPUT(2) the 1-2 pair of two phases; the wall
    !> DES_EN_WALL_INPUT(1).
    subroutine mfix_indexed()
        type(case_t) :: c
        type(peer_deck) :: deck
        integer :: st
        character(len=:), allocatable :: msg
        allocate (c%tok(0))
        c%peer = PEER_MFIX
        c%mat%radius = [1.0e-3_wp, 0.0_wp]
        c%mat%density = [2500.0_wp, 0.0_wp]
        call add(c, 'DES_COLL_MODEL=HERTZIAN E_YOUNG=1e9 V_POISSON=0.3 DES_EN_INPUT(1)=0.5')
        call read_case(c, deck, st, msg)
        call s%check(st == HD_OK .and. deck%e_deck == 0.5_wp, 'MFiX DES_EN_INPUT(1)=0.5: the 1-1 pair''s e (' // msg // ')')
        c%tok = c%tok(1:0)
        call add(c, 'DES_COLL_MODEL=HERTZIAN E_YOUNG=1e9,2e9 V_POISSON=0.3 DES_EN_INPUT(2)=0.6')
        call read_case(c, deck, st, msg)
        call s%check(st == HD_OK .and. deck%e_deck == 0.6_wp, 'MFiX two phases DES_EN_INPUT(2)=0.6: the 1-2 pair (' // &
                     msg // ')')
        c%tok = c%tok(1:0)
        c%mat%wall = .true.
        call add(c, 'DES_COLL_MODEL=HERTZIAN E_YOUNG=1e9 V_POISSON=0.3 EW_YOUNG=2e9 VW_POISSON=0.3 DES_EN_WALL_INPUT(1)=0.7')
        call read_case(c, deck, st, msg)
        call s%check(st == HD_OK .and. deck%e_deck == 0.7_wp, 'MFiX DES_EN_WALL_INPUT(1)=0.7 (' // msg // ')')
    end subroutine mfix_indexed

end program test_peers
