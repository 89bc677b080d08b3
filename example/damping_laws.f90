!> The figures of doc/damping-laws.md, computed by the library (reference integrator
!> at tolerance 1e-13 unless stated) and printed as the markdown tables of the document:
!>
!>     fpm run --example damping_laws
!>
!> test/docs/laws_doc_sync.sh checks that doc/damping-laws.md holds these lines.
program damping_laws
    use hertzdamp
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    integer :: law, i, st
    real(wp) :: q, ac, a, ex, pforce, cforce
    type(hertzdamp_collision) :: r, r2
    character(len=16) :: acs

    ! ------------------------------------------------------------------ per law
    print '(a)', '| law | q | p in alpha ~ u^p | e1(q) | alpha_c (overlap end) | overlap end, alpha large | ' // &
        'force end: e alpha^(5/(2(1+q))) at alpha = 1e4 | (1+q)^((3/2-q)/(1+q)) |'
    print '(a)', '| --- | --- | --- | --- | --- | --- | --- | --- |'
    do law = HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO
        q = hertzdamp_law_q(law)
        if (law == HD_DAMPING_KUWABARA_KONO) then
            acs = 'none'
        else
            call hertzdamp_alpha_c(ac, st, law=law)
            write (acs, '(f14.11)') ac
        end if
        pforce = 2.5_wp / (1.0_wp + q)
        r = hertzdamp_rk45_collide(1.0e4_wp, HD_END_FORCE, law=law)
        cforce = r%e * 1.0e4_wp**pforce
        if (law == HD_DAMPING_KUWABARA_KONO) then
            r2 = hertzdamp_rk45_collide(256.0_wp, HD_END_OVERLAP, law=law)
            print '(a,a,a,f4.2,a,f5.2,a,f18.16,a,a,a,f6.4,a,f7.5,a,f7.5,a)', '| ', hertzdamp_law_name(law), ' | ', q, &
                ' | ', hertzdamp_law_speed_exponent(law), ' | ', hertzdamp_e1(law), ' | ', trim(adjustl(acs)), &
                ' | rebounds, e alpha^5 = ', r2%e * 256.0_wp**5, ' at alpha = 256 | ', cforce, ' | ', &
                (1.0_wp + q)**((1.5_wp - q) / (1.0_wp + q)), ' |'
        else
            print '(a,a,a,f4.2,a,f5.2,a,f18.16,a,a,a,f7.5,a,f7.5,a)', '| ', hertzdamp_law_name(law), ' | ', q, ' | ', &
                hertzdamp_law_speed_exponent(law), ' | ', hertzdamp_e1(law), ' | ', trim(adjustl(acs)), &
                ' | no rebound | ', cforce, ' | ', (1.0_wp + q)**((1.5_wp - q) / (1.0_wp + q)), ' |'
        end if
    end do
    print '(a)', ''

    ! ------------------------------------------------------------------ negative alpha
    ! the reversal of alpha -> infinity (tsuji: of alpha_c) bounds the energy-injecting
    ! contacts that end: alpha_- = -lim(alpha e^p) with p = (4q-1)/5
    r2 = hertzdamp_rk45_collide(256.0_wp, HD_END_OVERLAP, law=HD_DAMPING_KUWABARA_KONO)
    print '(a)', '| law | alpha_- (contact ends for alpha > alpha_-) | rk45 at 0.99 alpha_-: status, e | ' // &
        'rk45 at 1.01 alpha_-: status, work (rhs) |'
    print '(a)', '| --- | --- | --- | --- |'
    do law = HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO
        if (law == HD_DAMPING_TSUJI) then
            a = -sqrt(5.0_wp)
        else
            a = -(r2%e * 256.0_wp**5)**0.2_wp
        end if
        r = hertzdamp_rk45_collide(0.99_wp * a, law=law)
        r2 = hertzdamp_rk45_collide(1.01_wp * a, law=law)
        print '(a,a,a,f8.5,a,i0,a,es9.3,a,i0,a,i0,a)', '| ', hertzdamp_law_name(law), ' | ', a, ' | ', r%status, ', ', &
            r%e, ' | ', r2%status, ', ', r2%stats%rhs_evals, ' |'
        r2 = hertzdamp_rk45_collide(256.0_wp, HD_END_OVERLAP, law=HD_DAMPING_KUWABARA_KONO)
    end do
    print '(a)', ''

    ! ------------------------------------------------------------------ linear near alpha_c
    ac = hertzdamp_law_alpha_c(HD_DAMPING_LINEAR)
    print '(a)', '| alpha_c - alpha | e (tol 1e-13) | e / (alpha_c - alpha) | e(tol 1e-13) - e(tol 1e-15) |'
    print '(a)', '| --- | --- | --- | --- |'
    do i = 3, 11, 2
        a = ac - 10.0_wp**(-i)
        r = hertzdamp_rk45_collide(a)
        r2 = hertzdamp_rk45_collide(a, tol=1.0e-15_wp)
        print '(a,es7.0,a,es10.3,a,f7.4,a,es9.1,a)', '| ', 10.0_wp**(-i), ' | ', r%e, ' | ', r%e * 10.0_wp**i, ' | ', &
            r%e - r2%e, ' |'
    end do
    print '(a)', ''

    ! ------------------------------------------------------------------ tsuji near sqrt(5)
    print '(a)', '| 1 - alpha/sqrt5 | exact e | rk45 status | rk45 e, relative error | tau_c | rk45 work (rhs) |'
    print '(a)', '| --- | --- | --- | --- | --- | --- |'
    do i = 1, 6
        a = sqrt(5.0_wp) * (1.0_wp - 10.0_wp**(-0.5_wp * i))
        if (i == 6) a = sqrt(5.0_wp) * (1.0_wp - 1.05e-3_wp)
        r = hertzdamp_rk45_collide(a, law=HD_DAMPING_TSUJI)
        call hertzdamp_tsuji_e(a, HD_END_OVERLAP, ex, st)
        print '(a,es8.2,a,es9.3,a,i0,a,es8.1,a,es9.3,a,i0,a)', '| ', 1.0_wp - a / sqrt(5.0_wp), ' | ', ex, ' | ', &
            r%status, ' | ', abs(r%e - ex) / ex, ' | ', r%tau_c, ' | ', r%stats%rhs_evals, ' |'
    end do
    r = hertzdamp_rk45_collide(sqrt(5.0_wp) * (1.0_wp - 1.0e-3_wp), law=HD_DAMPING_TSUJI)
    print '(a,i0,a)', '| 1.00E-03 (band) | | ', r%status, ' | | | |'
    print '(a)', ''

    ! ------------------------------------------------------------------ kuwabara-kono, overlap at large alpha
    print '(a)', '| alpha | rk45 status | e | e alpha^5 | tau_c | rk45 work (rhs) |'
    print '(a)', '| --- | --- | --- | --- | --- | --- |'
    do i = 2, 10
        a = 2.0_wp**i
        r = hertzdamp_rk45_collide(a, law=HD_DAMPING_KUWABARA_KONO)
        print '(a,i0,a,i0,a,es9.3,a,f8.5,a,es9.3,a,i0,a)', '| ', nint(a), ' | ', r%status, ' | ', r%e, ' | ', &
            r%e * a**5, ' | ', r%tau_c, ' | ', r%stats%rhs_evals, ' |'
    end do
end program damping_laws
