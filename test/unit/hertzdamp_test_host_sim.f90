!> This test's own simulation of the host schemes (doc/host-schemes.md), sharing no code
!> with the library: each scheme stepped as the engines write it (LAMMPS as velocity Verlet
!> with two half kicks, MFiX's EULER and ADAMS_BASHFORTH in MFiX's form, the scene engine's
!> sequence with its corrections, the plugin's phase force with an own Hurwitz zeta), and
!> the phase means by an own breakpoint search and graded Gauss-Legendre quadrature.
!> Used by test_host and test_host_sweep.
module hertzdamp_test_host_sim
    use hertzdamp, only: hertzdamp_rk, hertzdamp_law_q, HD_DAMPING_LINEAR, HD_END_OVERLAP, HD_END_FORCE, &
                         HD_HOST_LAMMPS, HD_HOST_LAMMPS_PHASE, HD_HOST_MFIX_EULER, HD_HOST_MFIX_AB2
    implicit none
    private
    integer, parameter :: wp = hertzdamp_rk
    real(wp), parameter :: pi = acos(-1.0_wp)

    !> One discrete collision of this module's steppers.
    type, public :: coll_t
        real(wp) :: e = 0.0_wp, tau = 0.0_wp
        integer :: sig(3) = 0
        logical :: ok = .false.
    end type coll_t

    public :: zeta_h, collide, own_mean, gauss_legendre

contains

    !> zeta(-p, a) = sum (a + j)^p by 12 terms and the Euler-Maclaurin tail with six
    !> Bernoulli terms at a + 12 (this program's own, by powers; the coefficients
    !> B_2k/(2k)! (-p)(1-p)...(2k-2-p) formed term by term).
    pure real(wp) function zeta_h(p, a)
        real(wp), intent(in) :: p, a
        real(wp), parameter :: bern(6) = [1.0_wp / 6.0_wp, -1.0_wp / 30.0_wp, 1.0_wp / 42.0_wp, -1.0_wp / 30.0_wp, &
                                           5.0_wp / 66.0_wp, -691.0_wp / 2730.0_wp]
        real(wp) :: x, c, fact
        integer :: j, k, i
        zeta_h = 0.0_wp
        do j = 0, 11
            zeta_h = zeta_h + (a + j)**p
        end do
        x = a + 12.0_wp
        zeta_h = zeta_h - x**(p + 1.0_wp) / (p + 1.0_wp) + 0.5_wp * x**p
        do k = 1, 6
            c = 1.0_wp
            do i = 0, 2 * k - 2
                c = c * (real(i, wp) - p)
            end do
            fact = 1.0_wp
            do i = 2, 2 * k
                fact = fact * i
            end do
            zeta_h = zeta_h + bern(k) / fact * c * x**(p + 1.0_wp - 2 * k)
        end do
    end function zeta_h

    ! ================================================================ this program's steppers

    !> z^q for q = 0, 1/4, 1/2 by powers.
    pure real(wp) function zpow(z, law)
        real(wp), intent(in) :: z
        integer, intent(in) :: law
        zpow = 1.0_wp
        if (law /= HD_DAMPING_LINEAR) zpow = z**hertzdamp_law_q(law)
    end function zpow

    !> One discrete collision stepped by this program (the schemes as the engines write them).
    pure function collide(alpha, h, phi, law, iend, host) result(c)
        real(wp), intent(in) :: alpha, h, phi
        integer, intent(in) :: law, iend, host
        type(coll_t) :: c
        select case (host)
        case (HD_HOST_LAMMPS, HD_HOST_LAMMPS_PHASE)
            c = verlet_half_step(alpha, h, phi, law, iend, host == HD_HOST_LAMMPS_PHASE)
        case (HD_HOST_MFIX_EULER)
            c = mfix(alpha, h, phi, law, iend, .false.)
        case (HD_HOST_MFIX_AB2)
            c = mfix(alpha, h, phi, law, iend, .true.)
        case default
            c = scene_engine(alpha, h, phi, law, iend)
        end select
    end function collide

    !> LAMMPS fix nve/sphere: v += h/2 a; x += h v; force from x and that v (the pair
    !> style); v += h/2 a.  The overlap rises from (phi - 1) h (free flight, speed 1).
    !> phase: the plugin's correction d zeta' (frac - 1/2) (Hurwitz form for q > 0).
    pure function verlet_half_step(alpha, h, phi, law, iend, phase) result(c)
        real(wp), intent(in) :: alpha, h, phi
        integer, intent(in) :: law, iend
        logical, intent(in) :: phase
        type(coll_t) :: c
        real(wp) :: x, v, a, f, fu, xl, fl, q
        integer :: n, nf
        logical :: touching, released
        q = hertzdamp_law_q(law)
        x = (phi - 1.0_wp) * h
        v = 1.0_wp
        a = 0.0_wp
        xl = 0.0_wp
        fl = 0.0_wp
        nf = 0
        touching = .false.
        released = .false.
        do n = 1, 100000
            v = v + 0.5_wp * h * a
            x = x + h * v
            f = 0.0_wp
            if (x > 0.0_wp .and. .not. released) then
                fu = x**1.5_wp + alpha * zpow(x, law) * v
                if (iend == HD_END_FORCE .and. fu <= 0.0_wp) then
                    released = .true.
                    c%tau = h * (real(n - 2, wp) + fl / (fl - fu) + phi)
                    c%sig = [n, 1, nf]
                else
                    f = fu
                    if (.not. touching .and. phase) f = f - alpha * v * (v * h)**q * zeta_h0(q, x / (v * h))
                    touching = .true.
                    nf = nf + 1
                    xl = x
                    fl = fu
                end if
            else if (touching .and. .not. released) then
                ! the overlap is gone: the plugin's release force (overlap end)
                released = .true.
                c%tau = h * (real(n - 2, wp) + xl / (xl - x) + phi)
                c%sig = [n, 0, nf]
                if (phase .and. iend == HD_END_OVERLAP) f = -alpha * v * abs(v * h)**q * zeta_h0(q, xl / (xl - x))
            else if (released) then
                c%e = -v
                c%ok = c%e > 0.0_wp
                return
            end if
            a = -f
            v = v + 0.5_wp * h * a
        end do
    end function verlet_half_step

    !> zeta(-q, frac) with zeta(0, frac) = 1/2 - frac.
    pure real(wp) function zeta_h0(q, fr)
        real(wp), intent(in) :: q, fr
        if (q == 0.0_wp) then
            zeta_h0 = 0.5_wp - fr
        else
            zeta_h0 = zeta_h(q, fr)
        end if
    end function zeta_h0

    !> MFiX (cfnewvalues.f): forces from the positions and velocities at the start of the
    !> step; EULER v += h a, x += h v; ADAMS_BASHFORTH v_new = v + h (3 a - a_old)/2,
    !> x += h (v + v_new)/2, a_old = a (0 before the contact).
    pure function mfix(alpha, h, phi, law, iend, ab2) result(c)
        real(wp), intent(in) :: alpha, h, phi
        integer, intent(in) :: law, iend
        logical, intent(in) :: ab2
        type(coll_t) :: c
        real(wp) :: x, v, a, aold, vn, fu, xl, fl
        integer :: n, nf
        logical :: released
        x = phi * h
        v = 1.0_wp
        aold = 0.0_wp
        xl = 0.0_wp
        fl = 0.0_wp
        nf = 0
        released = .false.
        do n = 1, 100000
            a = 0.0_wp
            if (x > 0.0_wp) then
                fu = x**1.5_wp + alpha * zpow(x, law) * v
                if (iend == HD_END_FORCE .and. fu <= 0.0_wp) then
                    if (.not. released) then
                        released = .true.
                        c%tau = h * (real(n - 2, wp) + fl / (fl - fu) + phi)
                        c%sig(1:2) = [n, 1]
                    end if
                else
                    a = -fu
                    nf = nf + 1
                    if (.not. released) then
                        xl = x
                        fl = fu
                    end if
                end if
            else if (.not. released) then
                released = .true.
                c%tau = h * (real(n - 2, wp) + xl / (xl - x) + phi)
                c%sig(1:2) = [n, 0]
            end if
            if (released .and. a == 0.0_wp .and. (aold == 0.0_wp .or. .not. ab2)) then
                c%e = -v
                c%sig(3) = nf
                c%ok = c%e > 0.0_wp
                return
            end if
            if (ab2) then
                vn = v + 0.5_wp * h * (3.0_wp * a - aold)
                x = x + 0.5_wp * h * (v + vn)
                v = vn
                aold = a
            else
                v = v + h * a
                x = x + h * v
            end if
        end do
    end function mfix

    !> The scene engine (packages/dem/src/hertzdamp_dem_engine.f90) for one contact, in its own
    !> order: drift with the opening half kick, the extrapolated velocity, the force and
    !> its end (overlap: impulse of the partial step and the trapezoid errors; force:
    !> bisection for the force zero on the step's linear model), the onset with its
    !> corrections, the closing kick.
    pure function scene_engine(alpha, h, phi, law, iend) result(c)
        real(wp), intent(in) :: alpha, h, phi
        integer, intent(in) :: law, iend
        type(coll_t) :: c
        real(wp) :: x, v, acc, acc_prev, vhalf, vpred, dv, f, fh, fd, zl, zdl, fl, q, fr, us, jn, xs
        integer :: n, kend
        logical :: active
        q = hertzdamp_law_q(law)
        x = (phi - 1.0_wp) * h
        v = 1.0_wp
        acc = 0.0_wp
        acc_prev = 0.0_wp
        active = .false.
        zl = 0.0_wp
        zdl = 0.0_wp
        fl = 0.0_wp
        fr = 0.0_wp
        vhalf = 0.0_wp
        dv = 0.0_wp
        kend = -1
        do n = 1, 100000
            xs = x
            vhalf = v + 0.5_wp * h * acc
            x = x + h * vhalf
            vpred = vhalf + 0.5_wp * h * acc + 0.5_wp * h * (acc - acc_prev)
            f = 0.0_wp
            dv = 0.0_wp
            if (active) then
                if (x <= 0.0_wp .and. iend == HD_END_FORCE .and. alpha * vpred < 0.0_wp) then
                    fr = force_zero_bisect(q, alpha, zl, zdl, x, vpred)
                    dv = -fl * (fr - 1.0_wp) * 0.5_wp * h
                    kend = 2
                    exit
                else if (x <= 0.0_wp) then
                    fr = 0.0_wp
                    if (zl - x > 0.0_wp) fr = min(1.0_wp, max(0.0_wp, zl / (zl - x)))
                    us = max(zl - x, 0.0_wp) / h
                    fh = max(zl, 0.0_wp)**1.5_wp
                    jn = ((fl - fh) * (fr / (1.0_wp + q) - 0.5_wp) + fh * (0.4_wp * fr - 0.5_wp)) * h &
                         - trap(1.5_wp, fr) * us**1.5_wp * h**2.5_wp
                    if (q > 0.0_wp) jn = jn + trap(q, fr) * alpha * us * us**q * h * h**q
                    dv = -jn
                    kend = 0
                    exit
                end if
                f = x**1.5_wp + alpha * zpow(x, law) * vpred
                if (iend == HD_END_FORCE .and. f <= 0.0_wp) then
                    fr = force_zero_bisect(q, alpha, zl, zdl, x, vpred)
                    dv = -fl * (fr - 1.0_wp) * 0.5_wp * h
                    kend = 1
                    exit
                end if
                zl = x
                zdl = vpred
                fl = f
            else if (x > 0.0_wp) then
                ! onset: in contact for the fraction phi of the step, impact speed 1
                active = .true.
                fr = x / (x - xs)
                fh = x**1.5_wp
                fd = alpha * zpow(x, law) * vpred
                jn = (fd * (fr / (1.0_wp + q) - 0.5_wp) + fh * (0.4_wp * fr - 0.5_wp)) * h - trap(1.5_wp, fr) * h**2.5_wp
                if (q > 0.0_wp) jn = jn - trap(q, fr) * alpha * h * h**q
                dv = -jn
                f = fh + fd
                zl = x
                zdl = vpred
                fl = f
            end if
            acc_prev = acc
            acc = -f
            v = vhalf + 0.5_wp * h * acc + dv
        end do
        if (kend < 0) return
        ! no force after the end: the separation speed is the step's closing velocity
        c%e = -(vhalf + dv)
        c%tau = h * (real(n - 2, wp) + fr + phi)
        c%sig = [n, kend, n - 1]
        c%ok = c%e > 0.0_wp
    end function scene_engine

    !> g_p(theta) = zeta(-p, theta) + theta^(p+1)/(p+1) - theta^p/2.
    pure real(wp) function trap(p, theta)
        real(wp), intent(in) :: p, theta
        trap = zeta_h(p, theta) + theta**(p + 1.0_wp) / (p + 1.0_wp) - 0.5_wp * theta**p
    end function trap

    !> The zero of max(z, 0)^(3/2 - q) + alpha v on the step's linear model, by 80 halvings.
    pure real(wp) function force_zero_bisect(q, alpha, zl, vl, ze, ve) result(fr)
        real(wp), intent(in) :: q, alpha, zl, vl, ze, ve
        real(wp) :: lo, hi, mid
        integer :: it
        lo = 0.0_wp
        hi = 1.0_wp
        if (ze <= 0.0_wp .and. zl - ze > 0.0_wp) hi = zl / (zl - ze)
        do it = 1, 80
            mid = 0.5_wp * (lo + hi)
            if (max(zl + mid * (ze - zl), 0.0_wp)**(1.5_wp - q) + alpha * (vl + mid * (ve - vl)) > 0.0_wp) then
                lo = mid
            else
                hi = mid
            end if
        end do
        fr = 0.5_wp * (lo + hi)
    end function force_zero_bisect

    ! ================================================================ own phase quadrature

    !> Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n from the Chebyshev guesses).
    pure subroutine gauss_legendre(n, x, w)
        integer, intent(in) :: n
        real(wp), intent(out) :: x(n), w(n)
        real(wp) :: z, p0, p1, p2, dp
        integer :: i, j, it
        do i = 1, n
            z = cos(pi * (real(i, wp) - 0.25_wp) / (real(n, wp) + 0.5_wp))
            do it = 1, 100
                p0 = 1.0_wp
                p1 = z
                do j = 2, n
                    p2 = ((2 * j - 1) * z * p1 - (j - 1) * p0) / j
                    p0 = p1
                    p1 = p2
                end do
                dp = n * (z * p1 - p0) / (z * z - 1.0_wp)
                z = z - p1 / dp
                if (abs(p1 / dp) < 1.0e-16_wp) exit
            end do
            x(i) = z
            w(i) = 2.0_wp / ((1.0_wp - z * z) * dp * dp)
        end do
    end subroutine gauss_legendre

    !> Phase means of e and tau_c by this program: its steppers, breakpoints where the
    !> signature changes between ordered samples (256 to start with; bisection to adjacent
    !> doubles), and on each piece 16-point Gauss-Legendre on panels graded by 1/4 towards
    !> both ends (28 levels).  A node whose signature is not its piece's reveals a piece the
    !> samples missed: up to 16 such nodes join the samples and everything is done again
    !> (at most 20 times).  nmiss: such nodes left at the end (none expected).
    subroutine own_mean(alpha, h, law, iend, host, em, tm, nmiss)
        real(wp), intent(in) :: alpha, h
        integer, intent(in) :: law, iend, host
        real(wp), intent(out) :: em, tm
        integer, intent(out) :: nmiss
        integer, parameter :: ng = 16, nlev = 28, nmax = 400
        real(wp) :: xg(ng), wg(ng), ps(nmax), bp(0:nmax), lo, hi, mid, a, b, pa, pb, xmiss(nmax)
        integer :: sg(3, nmax), sp(3), ns, nb, j, i, lev, side, k, round, nx
        type(coll_t) :: r
        call gauss_legendre(ng, xg, wg)
        ns = 256
        do j = 1, ns
            ps(j) = (real(j, wp) - 0.5_wp) / ns
        end do
        do round = 1, 20
            do j = 1, ns
                r = collide(alpha, h, ps(j), law, iend, host)
                sg(:, j) = r%sig
            end do
            ! breakpoints, and each piece's signature (that of the samples inside it)
            nb = 0
            bp(0) = 0.0_wp
            do j = 2, ns
                if (all(sg(:, j) == sg(:, j - 1))) cycle
                lo = ps(j - 1)
                hi = ps(j)
                do
                    mid = 0.5_wp * (lo + hi)
                    if (mid == lo .or. mid == hi) exit
                    r = collide(alpha, h, mid, law, iend, host)
                    if (all(r%sig == sg(:, j - 1))) then
                        lo = mid
                    else
                        hi = mid
                    end if
                end do
                nb = nb + 1
                bp(nb) = 0.5_wp * (lo + hi)
            end do
            nb = nb + 1
            bp(nb) = 1.0_wp
            em = 0.0_wp
            tm = 0.0_wp
            nx = 0
            j = 1
            do i = 1, nb
                a = bp(i - 1)
                b = bp(i)
                do while (j < ns .and. ps(j) < a)
                    j = j + 1
                end do
                sp = sg(:, j)
                do side = -1, 1, 2
                    do lev = 0, nlev - 1
                        ! panel between the distances (b - a)/2 * 4^-(lev+1) and 4^-lev from the end
                        pa = 0.5_wp * (b - a) * 0.25_wp**(lev + 1)
                        pb = 0.5_wp * (b - a) * 0.25_wp**lev
                        if (lev == nlev - 1) pa = 0.0_wp
                        do k = 1, ng
                            mid = 0.5_wp * (pa + pb) + 0.5_wp * (pb - pa) * xg(k)
                            mid = merge(a + mid, b - mid, side == -1)
                            if (mid <= a .or. mid >= b) cycle
                            r = collide(alpha, h, mid, law, iend, host)
                            if (any(r%sig /= sp)) then
                                if (abs(mid - a) > 1.0e-13_wp .and. abs(mid - b) > 1.0e-13_wp .and. nx < 16) then
                                    nx = nx + 1
                                    xmiss(nx) = mid
                                end if
                                cycle
                            end if
                            em = em + 0.5_wp * (pb - pa) * wg(k) * r%e
                            tm = tm + 0.5_wp * (pb - pa) * wg(k) * r%tau
                        end do
                    end do
                end do
            end do
            nmiss = nx
            if (nx == 0 .or. ns + nx > nmax) return
            nmiss = 0
            ! the missed phases join the samples (kept in order)
            ps(ns + 1:ns + nx) = xmiss(1:nx)
            ns = ns + nx
            call sort(ps(1:ns))
        end do
    end subroutine own_mean

    !> Insertion sort.
    pure subroutine sort(x)
        real(wp), intent(inout) :: x(:)
        real(wp) :: t
        integer :: i, j
        do i = 2, size(x)
            t = x(i)
            j = i - 1
            do while (j >= 1)
                if (x(j) <= t) exit
                x(j + 1) = x(j)
                j = j - 1
            end do
            x(j + 1) = t
        end do
    end subroutine sort

end module hertzdamp_test_host_sim
