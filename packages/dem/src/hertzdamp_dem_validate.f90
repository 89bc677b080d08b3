!> Validation of a scene before it runs: every value finite and in its range, the
!> quantities the engine forms representable, the layout free of overlaps.  A scene
!> that passes runs without overflow: no NaN or Inf reaches a result.
!>
!> What "representable" means here (SI units, big = hertzdamp_dem_big = 1e150): every
!> particle mass, density, Young's modulus and each meeting pair's physical stiffness
!> k_phys lie within [1/big, big]; coordinates, speeds, g, rest_speed, dt and
!> end_time at most big; the scene's kinetic-energy, momentum and gravitational
!> energy scales at most big, counting what gravity can add in the run; the longest
!> physical contact (at rest_speed) fewer than 2^31 - 1 steps, and with k = k_phys at
!> every contact (restitution only) the shortest (the fastest impact) at least one
!> step; each meeting pair's e within the range of the damping law's rule (the
!> law's smallest e for the contact end); the contact rule of the scene's damping law
!> gives finite k and d at the extreme masses and speeds of each meeting pair (tsuji:
!> alpha and d = alpha sqrt(m k) at the pair's extreme masses); the trace
!> within hertzdamp_dem_max_samples and hertzdamp_dem_max_trace_values.  The engine
!> forms products of two such quantities at most, which stay far inside double
!> precision.  Magnitudes are compared through their logarithms, so the checks
!> themselves never overflow.
module hertzdamp_dem_validate
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_BAD_ARGUMENT, hertzdamp_message, hertzdamp_end_name, HD_METHOD_FIT, &
                         hertzdamp_tau_c0, hertzdamp_pi, hertzdamp_invert_alpha, hertzdamp_law_status, &
                         hertzdamp_law_name, HD_HOST_NONE, hertzdamp_host_name, hertzdamp_host_in_engine, &
                         hertzdamp_host_choices, hertzdamp_law_choices
    use hertzdamp_text_format, only: prose
    use hertzdamp, only: hertzdamp_fit_law_e_min, hertzdamp_sphere_mass, hertzdamp_effective_mass, &
                         hertzdamp_effective_radius, hertzdamp_effective_modulus
    use hertzdamp_dem_types, only: hertzdamp_dem_scene, hertzdamp_dem_material, hertzdamp_dem_max_particles, &
                                   hertzdamp_dem_max_steps, hertzdamp_dem_max_samples, hertzdamp_dem_max_trace_values, &
                                   hertzdamp_dem_big, hertzdamp_dem_u_floor, hertzdamp_dem_pair_e, hertzdamp_dem_pairs_met, &
                                   hertzdamp_dem_nsteps, hertzdamp_dem_trace_size
    use hertzdamp_dem_rules, only: hertzdamp_dem_rule
    use hertzdamp_dem_types, only: int_text => hertzdamp_dem_int_text
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk
    !> log10 of the magnitude window.
    real(wp), parameter :: lg_big = 150.0_wp

    public :: hertzdamp_dem_check

contains

    !> Validate a scene: status HD_OK, or HD_BAD_ARGUMENT with a message naming the
    !> offending key (damping, restitution, ...) and, for particles and walls, their
    !> source line.
    pure subroutine hertzdamp_dem_check(sc, status, message)
        type(hertzdamp_dem_scene), intent(in) :: sc       !! the scene
        integer, intent(out) :: status                     !! HD_OK or HD_BAD_ARGUMENT
        character(len=:), allocatable, intent(out) :: message !! empty on success
        status = HD_BAD_ARGUMENT
        message = finite_values(sc)
        if (len(message) == 0) message = materials(sc)
        if (len(message) == 0) message = settings(sc)
        if (len(message) == 0) message = particles(sc)
        if (len(message) == 0) message = magnitudes(sc)
        if (len(message) == 0) message = pair_limits(sc)
        if (len(message) == 0) message = layout(sc)
        if (len(message) == 0) status = HD_OK
    end subroutine hertzdamp_dem_check

    !> True for a finite number (false for NaN and +-Inf).
    pure elemental logical function finite(x)
        real(wp), intent(in) :: x
        finite = abs(x) <= huge(1.0_wp)
    end function finite

    !> log10 |x| (a value below every double for x = 0).
    pure elemental real(wp) function lg(x)
        real(wp), intent(in) :: x
        if (x == 0.0_wp) then
            lg = -1000.0_wp
        else
            lg = log10(abs(x))
        end if
    end function lg

    !> log10(10^a + 10^b) without overflow.
    pure elemental real(wp) function lg_add(a, b)
        real(wp), intent(in) :: a, b
        lg_add = max(a, b) + log10(1.0_wp + 10.0_wp**(min(a, b) - max(a, b)))
    end function lg_add

    !> 10^l as text ('1.2e+600'), for any l.
    pure function pow10_text(l) result(s)
        real(wp), intent(in) :: l
        character(len=:), allocatable :: s
        character(len=32) :: b
        integer :: ex
        real(wp) :: mant
        ex = floor(l)
        mant = 10.0_wp**(l - ex)
        if (mant >= 9.95_wp) then
            mant = 1.0_wp
            ex = ex + 1
        end if
        write (b, '(f3.1,a,i0)') mant, 'e', ex
        s = trim(b)
    end function pow10_text

    !> 'line N: '
    pure function line_text(line) result(s)
        integer, intent(in) :: line
        character(len=:), allocatable :: s
        s = 'line ' // int_text(line) // ': '
    end function line_text

    !> 'material NAME: ', after 'line N: ' for a material read from a file.
    pure function material_text(mt) result(s)
        type(hertzdamp_dem_material), intent(in) :: mt
        character(len=:), allocatable :: s
        s = 'material ' // trim(mt%name) // ': '
        if (mt%line > 0) s = line_text(mt%line) // '&' // s
    end function material_text

    !> Every real value finite (NaN or Inf would reach the report).
    pure function finite_values(sc) result(message)
        type(hertzdamp_dem_scene), intent(in) :: sc
        character(len=:), allocatable :: message
        integer :: i, w
        message = ''
        if (.not. finite(sc%dt)) then
            message = '&scene: dt must be finite'
        else if (.not. finite(sc%end_time)) then
            message = '&scene: end_time must be finite'
        else if (.not. finite(sc%accuracy)) then
            message = '&scene: accuracy must be finite'
        else if (.not. finite(sc%rest_speed)) then
            message = '&scene: rest_speed must be finite'
        else if (.not. all(finite(sc%g))) then
            message = '&scene: g must be finite'
        else if (sc%has_domain .and. .not. all(finite(sc%domain_lo))) then
            message = '&scene: domain_lo must be finite'
        else if (sc%has_domain .and. .not. all(finite(sc%domain_hi))) then
            message = '&scene: domain_hi must be finite'
        end if
        if (len(message) > 0) return
        do i = 1, size(sc%mat)
            associate (mt => sc%mat(i))
                if (.not. finite(mt%density)) then
                    message = material_text(mt) // 'density must be finite'
                else if (.not. finite(mt%youngs_modulus)) then
                    message = material_text(mt) // 'youngs_modulus must be finite'
                else if (.not. finite(mt%poisson_ratio)) then
                    message = material_text(mt) // 'poisson_ratio must be finite'
                else if (.not. finite(mt%restitution)) then
                    message = material_text(mt) // 'restitution must be finite'
                end if
            end associate
            if (len(message) > 0) return
        end do
        do i = 1, size(sc%radius)
            if (.not. finite(sc%radius(i))) then
                message = line_text(sc%pline(i)) // '&particle radius must be finite'
            else if (.not. all(finite(sc%x(:, i)))) then
                message = line_text(sc%pline(i)) // '&particle position must be finite'
            else if (.not. all(finite(sc%v(:, i)))) then
                message = line_text(sc%pline(i)) // '&particle velocity must be finite'
            end if
            if (len(message) > 0) return
        end do
        do w = 1, size(sc%wall)
            if (.not. all(finite(sc%wall(w)%point))) then
                message = line_text(sc%wall(w)%line) // '&wall point must be finite'
            else if (.not. all(finite(sc%wall(w)%normal))) then
                message = line_text(sc%wall(w)%line) // '&wall normal must be finite'
            end if
            if (len(message) > 0) return
        end do
    end function finite_values

    !> The &scene settings in their ranges.
    pure function settings(sc) result(message)
        type(hertzdamp_dem_scene), intent(in) :: sc
        character(len=:), allocatable :: message
        integer :: n, every, nsamples, ntraced
        message = ''
        n = size(sc%radius)
        if (hertzdamp_law_status(sc%law) /= HD_OK) then
            message = '&scene: damping must be ' // prose(hertzdamp_law_choices(), quote="'")
        else if (.not. hertzdamp_host_in_engine(sc%scheme)) then
            message = 'scheme: the engine integrates with ' // prose(hertzdamp_host_choices(engine_only=.true.)) // &
                      ' (HD_HOST_*), not ' // hertzdamp_host_name(sc%scheme)
        else if (.not. (sc%host == HD_HOST_NONE .or. hertzdamp_host_in_engine(sc%host))) then
            message = 'host: the per-pair constants of ' // &
                      prose(hertzdamp_host_name(HD_HOST_NONE) // ' ' // hertzdamp_host_choices(engine_only=.true.)) // &
                      ' (HD_HOST_*), not ' // hertzdamp_host_name(sc%host)
        else if (sc%onset_phase .and. sc%host == HD_HOST_NONE) then
            message = 'onset_phase: the per-contact constants of the onset phase need a host'
        else if (.not. (sc%dt > 0.0_wp)) then
            message = '&scene: dt must be positive'
        else if (.not. (sc%end_time > 0.0_wp)) then
            message = '&scene: end_time must be positive'
        else if (sc%end_time / sc%dt > real(hertzdamp_dem_max_steps, wp)) then
            message = '&scene: end_time/dt exceeds the step limit of the scene engine (' // &
                      int_text(hertzdamp_dem_max_steps) // ' steps)'
        else if (sc%steps_per_contact < 1) then
            message = '&scene: steps_per_contact must be at least 1'
        else if (.not. (sc%accuracy > 0.0_wp .and. sc%accuracy < 1.0_wp)) then
            message = '&scene: accuracy must lie in (0, 1)'
        else if (.not. (sc%rest_speed > 0.0_wp)) then
            message = '&scene: rest_speed must be positive'
        else if (sc%samples < 2) then
            message = '&scene: samples must be at least 2'
        else if (sc%samples > hertzdamp_dem_max_samples) then
            message = '&scene: samples must be at most ' // int_text(hertzdamp_dem_max_samples)
        else if (n < 1) then
            message = 'no &particle group: a scene needs at least one particle'
        else if (n > hertzdamp_dem_max_particles) then
            message = 'too many particles (at most ' // int_text(hertzdamp_dem_max_particles) // ')'
        end if
        if (len(message) > 0) return
        if (sc%has_domain) then
            if (any(sc%domain_hi <= sc%domain_lo)) then
                message = '&scene: domain_hi must exceed domain_lo in every coordinate'
                return
            end if
        end if
        ! trace memory: samples of a position and a velocity of each traced particle
        call hertzdamp_dem_trace_size(sc, every, nsamples, ntraced)
        if (real(nsamples, wp) * ntraced > real(hertzdamp_dem_max_trace_values, wp)) then
            message = '&scene: samples must be at most ' // &
                      int_text(max(2, hertzdamp_dem_max_trace_values / ntraced - 1)) // ' for a trace of ' // &
                      int_text(ntraced) // ' particles (at most ' // int_text(hertzdamp_dem_max_trace_values) // &
                      ' trace values)'
        end if
    end function settings

    !> Material values in their ranges.
    pure function materials(sc) result(message)
        type(hertzdamp_dem_scene), intent(in) :: sc
        character(len=:), allocatable :: message
        integer :: i
        message = ''
        do i = 1, size(sc%mat)
            associate (mt => sc%mat(i))
                if (.not. (mt%density > 0.0_wp)) then
                    message = material_text(mt) // 'density must be positive'
                else if (.not. (mt%youngs_modulus > 0.0_wp)) then
                    message = material_text(mt) // 'youngs_modulus must be positive'
                else if (.not. (mt%poisson_ratio > -1.0_wp .and. mt%poisson_ratio <= 0.5_wp)) then
                    message = material_text(mt) // 'poisson_ratio must lie in (-1, 0.5]'
                else if (.not. (mt%restitution > 0.0_wp .and. mt%restitution <= 1.0_wp)) then
                    message = material_text(mt) // 'restitution must lie in (0, 1]'
                else if (abs(lg(mt%density)) > lg_big) then
                    message = material_text(mt) // 'density must lie within [1e-150, 1e150] kg/m^3'
                else if (abs(lg(mt%youngs_modulus)) > lg_big) then
                    message = material_text(mt) // 'youngs_modulus must lie within [1e-150, 1e150] Pa'
                end if
            end associate
            if (len(message) > 0) return
        end do
    end function materials

    !> Particle radii positive, positions inside the domain.
    pure function particles(sc) result(message)
        type(hertzdamp_dem_scene), intent(in) :: sc
        character(len=:), allocatable :: message
        integer :: i
        message = ''
        do i = 1, size(sc%radius)
            if (.not. (sc%radius(i) > 0.0_wp)) then
                message = line_text(sc%pline(i)) // '&particle radius must be positive'
                return
            end if
            if (sc%has_domain) then
                if (any(sc%x(:, i) < sc%domain_lo .or. sc%x(:, i) > sc%domain_hi)) then
                    message = line_text(sc%pline(i)) // '&particle position outside the domain'
                    return
                end if
            end if
        end do
    end function particles

    !> Magnitudes of the values and of the scales the engine forms (see the module
    !> documentation).
    pure function magnitudes(sc) result(message)
        type(hertzdamp_dem_scene), intent(in) :: sc
        character(len=:), allocatable :: message
        real(wp) :: lm(size(sc%radius)), lspeed, lfall, lgrav, lx, ltot_m, lsum, lrun
        integer :: i, w
        character(len=:), allocatable :: at
        message = ''
        if (lg(sc%dt) > lg_big .or. lg(sc%dt) < -lg_big) then
            message = '&scene: dt must lie within [1e-150, 1e150] s'
        else if (lg(sc%end_time) > lg_big) then
            message = '&scene: end_time must be at most 1e150 s'
        else if (norm2(sc%g / hertzdamp_dem_big) > 1.0_wp) then
            message = '&scene: g must be at most 1e150 m/s^2 in magnitude'
        else if (sc%rest_speed > hertzdamp_dem_big) then
            message = '&scene: rest_speed must be at most 1e150 m/s'
        else if (sc%has_domain .and. any(abs([sc%domain_lo, sc%domain_hi]) > hertzdamp_dem_big)) then
            message = '&scene: domain_lo and domain_hi must lie within +-1e150 m'
        end if
        if (len(message) > 0) return
        do w = 1, size(sc%wall)
            if (any(abs(sc%wall(w)%point) > hertzdamp_dem_big)) then
                message = line_text(sc%wall(w)%line) // '&wall point must lie within +-1e150 m'
                return
            end if
        end do
        ! masses (through logarithms: density r^3 may overflow or underflow)
        do i = 1, size(sc%radius)
            at = line_text(sc%pline(i)) // '&particle '
            lm(i) = lg(sc%mat(sc%pmat(i))%density) + lg(4.0_wp / 3.0_wp * hertzdamp_pi) + 3.0_wp * lg(sc%radius(i))
            if (abs(lm(i)) > lg_big) then
                message = at // 'radius: the mass density 4/3 pi radius^3 = ' // pow10_text(lm(i)) // &
                          ' kg lies outside [1e-150, 1e150] kg'
            else if (any(abs(sc%x(:, i)) > hertzdamp_dem_big)) then
                message = at // 'position must lie within +-1e150 m'
            else if (norm2(sc%v(:, i) / hertzdamp_dem_big) > 1.0_wp) then
                message = at // 'velocity must be at most 1e150 m/s in magnitude'
            end if
            if (len(message) > 0) return
        end do
        ! scales over the run (the time run, T = steps dt, at least one step): speeds
        ! up to |v| + |g| T, travel up to that times T, energy 1/2 m speed^2, momentum
        ! m speed, gravity m |g| |x|
        lrun = lg(run_time(sc))
        ltot_m = maxval(lm) + lg(real(size(lm), wp))
        lfall = lg(norm2(sc%g)) + lrun
        lx = lg(maxval(abs(sc%x)))
        if (sc%has_domain) lx = max(lx, lg(maxval(abs([sc%domain_lo, sc%domain_hi]))))
        do i = 1, size(sc%radius)
            lspeed = lg_add(lg(norm2(sc%v(:, i))), lfall)
            lsum = lg_add(lx, lspeed + lrun)
            lgrav = ltot_m + lg(norm2(sc%g)) + lsum
            at = line_text(sc%pline(i)) // '&particle velocity: '
            if (lspeed + lrun > lg_big) then
                message = at // 'the distance travelled in the run, about ' // pow10_text(lspeed + lrun) // &
                          ' m, exceeds 1e150 m'
            else if (ltot_m + 2.0_wp * lspeed > lg_big) then
                message = at // 'the kinetic energy scale 1/2 sum(m) |v|^2, about ' // &
                          pow10_text(ltot_m + 2.0_wp * lspeed) // ' J, exceeds 1e150 J'
            else if (ltot_m + lspeed > lg_big) then
                message = at // 'the momentum scale sum(m) |v|, about ' // pow10_text(ltot_m + lspeed) // &
                          ' kg m/s, exceeds 1e150 kg m/s'
            else if (sc%gravity .and. lgrav > lg_big) then
                message = '&scene: g: the gravitational energy scale sum(m) |g| |x|, about ' // pow10_text(lgrav) // &
                          ' J, exceeds 1e150 J'
            end if
            if (len(message) > 0) return
        end do
    end function magnitudes

    !> For every material pair that can meet: k_phys within the window, its e within
    !> the damping law's range, the longest physical contact (at rest_speed) fewer than
    !> 2^31 - 1 steps, and the contact rule of the law finite at the extreme masses and
    !> speeds of the pair.
    pure function pair_limits(sc) result(message)
        type(hertzdamp_dem_scene), intent(in) :: sc
        character(len=:), allocatable :: message
        logical, allocatable :: met(:, :)
        integer :: a, b, nm, im, iu, st
        real(wp) :: estar, e, alpha, tau, lkp(2), lm(2), lts, lsteps, lu(2), mm(2), kk, dd, tce
        real(wp), allocatable :: mlo(:), mhi(:), rlo(:), rhi(:)
        logical :: bound
        character(len=:), allocatable :: pair
        message = ''
        pair = ''
        nm = size(sc%mat)
        call hertzdamp_dem_pairs_met(sc, met)
        allocate (mlo(nm), mhi(nm), rlo(nm), rhi(nm))
        do a = 1, nm
            if (count(sc%pmat == a) == 0) cycle
            rlo(a) = minval(sc%radius, mask=sc%pmat == a)
            rhi(a) = maxval(sc%radius, mask=sc%pmat == a)
            call hertzdamp_sphere_mass(rlo(a), sc%mat(a)%density, mlo(a), st)   ! within the window: HD_OK
            call hertzdamp_sphere_mass(rhi(a), sc%mat(a)%density, mhi(a), st)
        end do
        ! slowest speed the rule gets, and the fastest impact: the speed scale
        lu(1) = max(sc%rest_speed, hertzdamp_dem_u_floor)
        lu(2) = max(lu(1), 2.0_wp * (maxval(norm2(sc%v, dim=1)) + norm2(sc%g) * run_time(sc)))
        do a = 1, nm
            do b = a, nm
                if (.not. met(a, b)) cycle
                pair = 'material pair ''' // trim(sc%mat(a)%name) // ''' - ''' // trim(sc%mat(b)%name) // ''': '
                call hertzdamp_effective_modulus(sc%mat(a)%youngs_modulus, sc%mat(a)%poisson_ratio, &
                                                 sc%mat(b)%youngs_modulus, sc%mat(b)%poisson_ratio, estar, st)
                if (st /= HD_OK) then
                    message = pair // 'youngs_modulus, poisson_ratio: E*: ' // hertzdamp_message(st)
                    return
                end if
                call ranges(a, b, estar, mm, lkp)
                lm = lg(mm)
                if (any(abs(lkp) > lg_big)) then
                    message = pair // 'youngs_modulus: the physical stiffness (4/3) E* sqrt(R*), ' // &
                              pow10_text(merge(lkp(1), lkp(2), abs(lkp(1)) > lg_big)) // &
                              ', lies outside [1e-150, 1e150] N/m^1.5'
                    return
                end if
                ! the pair's restitution within the range of the damping law's rule
                e = hertzdamp_dem_pair_e(sc%mat(a), sc%mat(b))
                if (e < hertzdamp_fit_law_e_min(sc%law, sc%iend)) then
                    message = pair // 'restitution: the pair''s e = sqrt(e_a e_b) = ' // pow10_text(lg(e)) // &
                              ' is below ' // pow10_text(lg(hertzdamp_fit_law_e_min(sc%law, sc%iend))) // &
                              ', the smallest e of the damping law ''' // hertzdamp_law_name(sc%law) // &
                              ''' with contact_end ''' // hertzdamp_end_name(sc%iend) // ''''
                    return
                end if
                ! longest physical contact: t* = (m^2 / (k_phys^2 u))^(1/5) at the
                ! largest mass, smallest stiffness and slowest speed, times tau_c
                call hertzdamp_invert_alpha(e, sc%iend, alpha, tau, st, method=HD_METHOD_FIT, law=sc%law)
                if (st /= HD_OK) tau = hertzdamp_tau_c0()
                lts = (2.0_wp * lm(2) - 2.0_wp * lkp(1) - lg(lu(1))) / 5.0_wp + lg(tau)
                lsteps = lts - lg(sc%dt)
                if (lsteps >= lg(real(huge(1), wp))) then
                    message = pair // 'youngs_modulus: the physical contact time at rest_speed, about ' // &
                              pow10_text(lts) // ' s, is more than ' // int_text(huge(1)) // &
                              ' steps of dt (youngs_modulus too small for dt)'
                    return
                end if
                ! shortest physical contact (restitution only: k = k_phys at every
                ! contact): at the smallest mass, largest stiffness and fastest speed; a
                ! contact shorter than one step cannot be integrated (the force
                ! overshoots and the run overflows)
                lts = (2.0_wp * lm(1) - 2.0_wp * lkp(2) - lg(lu(2))) / 5.0_wp + lg(tau)
                if (.not. sc%want_duration .and. lts < lg(sc%dt)) then
                    message = pair // 'dt: the shortest physical contact (impact at ' // pow10_text(lg(lu(2))) // &
                              ' m/s) lasts about ' // pow10_text(lts) // ' s, less than one step dt = ' // &
                              pow10_text(lg(sc%dt)) // ' s (dt too large, or youngs_modulus or density out of scale)'
                    return
                end if
                ! the rule of the scene's damping law at the corners (mass, stiffness) x
                ! (slowest, fastest speed): k and d finite (tsuji: d = alpha sqrt(m k),
                ! kuwabara-kono: d ~ u^(-1/5) with the physical stiffness)
                do im = 1, 2
                    do iu = 1, 2
                        call hertzdamp_dem_rule(e, sc%steps_per_contact * sc%dt, mm(im), lu(iu), 10.0_wp**lkp(im), &
                                                sc%iend, sc%law, HD_METHOD_FIT, sc%want_duration, 1.0e-8_wp, kk, dd, &
                                                tce, bound, st)
                        if (st /= HD_OK) then
                            message = pair // 'the contact rule fails at mass ' // pow10_text(lg(mm(im))) // &
                                      ' kg and speed ' // pow10_text(lg(lu(iu))) // ' m/s: ' // hertzdamp_message(st) // &
                                      ' (check dt, steps_per_contact, the velocities and the materials)'
                            return
                        end if
                    end do
                end do
            end do
        end do

    contains

        !> Effective mass (smallest, largest) and log10 k_phys (smallest, largest)
        !> of the contacts of materials a and b: two particles, or a particle of one
        !> against a wall of the other.
        pure subroutine ranges(a, b, estar, mm, lkp)
            integer, intent(in) :: a, b
            real(wp), intent(in) :: estar
            real(wp), intent(out) :: mm(2), lkp(2)
            real(wp) :: m_lo, m_hi, r_lo, r_hi
            integer :: na, nb, side, p, q, st
            na = count(sc%pmat == a)
            nb = count(sc%pmat == b)
            m_lo = huge(1.0_wp)
            m_hi = 0.0_wp
            r_lo = huge(1.0_wp)
            r_hi = 0.0_wp
            if (na > 0 .and. nb > 0 .and. (a /= b .or. na >= 2)) then
                ! m1 m2/(m1 + m2) and r1 r2/(r1 + r2) grow with each of m1, m2 (r1, r2)
                call hertzdamp_effective_mass(mlo(a), mlo(b), m_lo, st)   ! within the window: HD_OK
                call hertzdamp_effective_mass(mhi(a), mhi(b), m_hi, st)
                call hertzdamp_effective_radius(rlo(a), rlo(b), r_lo, st)
                call hertzdamp_effective_radius(rhi(a), rhi(b), r_hi, st)
            end if
            do side = 1, 2
                p = merge(a, b, side == 1)   ! particles of p against a wall of q
                q = merge(b, a, side == 1)
                if (count(sc%pmat == p) == 0 .or. .not. any(sc%wall%material == q)) cycle
                m_lo = min(m_lo, mlo(p))
                m_hi = max(m_hi, mhi(p))
                r_lo = min(r_lo, rlo(p))
                r_hi = max(r_hi, rhi(p))
            end do
            mm = [m_lo, m_hi]
            lkp = lg(4.0_wp / 3.0_wp * estar) + 0.5_wp * lg([r_lo, r_hi])
        end subroutine ranges

    end function pair_limits

    !> Time the run covers: its steps times dt (at least one step) [s].
    pure real(wp) function run_time(sc)
        type(hertzdamp_dem_scene), intent(in) :: sc
        run_time = hertzdamp_dem_nsteps(sc) * sc%dt
    end function run_time

    !> Walls: unit normals, no particle in a wall at the start; no two particles
    !> overlapping at the start.
    pure function layout(sc) result(message)
        type(hertzdamp_dem_scene), intent(in) :: sc
        character(len=:), allocatable :: message
        integer :: i, j, n, w
        real(wp) :: dist, h
        character(len=24) :: b1, b2
        message = ''
        n = size(sc%radius)
        do w = 1, size(sc%wall)
            write (b2, '(i0)') sc%wall(w)%line
            h = norm2(sc%wall(w)%normal)
            if (.not. (abs(h - 1.0_wp) < 1.0e-12_wp)) then
                message = 'line ' // trim(b2) // ': &wall normal must be a unit vector'
                return
            end if
            do i = 1, n
                dist = dot_product(sc%x(:, i) - sc%wall(w)%point, sc%wall(w)%normal)
                if (dist < sc%radius(i) * (1.0_wp - 1.0e-12_wp)) then
                    write (b1, '(i0)') sc%pline(i)
                    message = 'line ' // trim(b1) // ': &particle overlaps the wall of line ' // trim(b2) // &
                              ' at the start'
                    return
                end if
            end do
        end do
        do j = 2, n
            do i = 1, j - 1
                dist = norm2(sc%x(:, j) - sc%x(:, i))
                if (dist < (sc%radius(i) + sc%radius(j)) * (1.0_wp - 1.0e-12_wp)) then
                    write (b1, '(i0)') sc%pline(i)
                    write (b2, '(i0)') sc%pline(j)
                    if (sc%pline(i) == sc%pline(j)) then
                        write (b2, '(i0,a,i0)') i, ' and ', j
                        message = 'line ' // trim(b1) // ': particles ' // trim(b2) // &
                                  ' of this &particle group overlap at the start'
                    else
                        message = 'line ' // trim(b2) // ': &particle overlaps the particle of line ' // &
                                  trim(b1) // ' at the start'
                    end if
                    return
                end if
            end do
        end do
    end function layout

end module hertzdamp_dem_validate
