!> Validation of a scene before it runs: every value finite and in its range, the
!> layout free of overlaps.
module hertzdamp_dem_validate
    use hertzdamp_kinds, only: hertzdamp_rk
    use hertzdamp_status, only: HD_OK, HD_BAD_ARGUMENT
    use hertzdamp_dem_types, only: hertzdamp_dem_scene, hertzdamp_dem_max_particles, hertzdamp_dem_max_steps
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    public :: hertzdamp_dem_check

contains

    !> Validate a scene: status HD_OK, or HD_BAD_ARGUMENT with a message naming the
    !> offending key and, for particles and walls, their source line.
    pure subroutine hertzdamp_dem_check(sc, status, message)
        type(hertzdamp_dem_scene), intent(in) :: sc       !! the scene
        integer, intent(out) :: status                     !! HD_OK or HD_BAD_ARGUMENT
        character(len=:), allocatable, intent(out) :: message !! empty on success
        status = HD_BAD_ARGUMENT
        message = finite_values(sc)
        if (len(message) == 0) message = settings(sc)
        if (len(message) == 0) message = materials(sc)
        if (len(message) == 0) message = particles(sc)
        if (len(message) == 0) message = layout(sc)
        if (len(message) == 0) status = HD_OK
    end subroutine hertzdamp_dem_check

    !> True for a finite number (false for NaN and +-Inf).
    pure elemental logical function finite(x)
        real(wp), intent(in) :: x
        finite = abs(x) <= huge(1.0_wp)
    end function finite

    !> 'line N: '
    pure function line_text(line) result(s)
        integer, intent(in) :: line
        character(len=:), allocatable :: s
        s = 'line ' // int_text(line) // ': '
    end function line_text

    pure function int_text(i) result(s)
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        character(len=16) :: b
        write (b, '(i0)') i
        s = trim(b)
    end function int_text

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
                    message = 'material ' // trim(mt%name) // ': density must be finite'
                else if (.not. finite(mt%youngs_modulus)) then
                    message = 'material ' // trim(mt%name) // ': youngs_modulus must be finite'
                else if (.not. finite(mt%poisson_ratio)) then
                    message = 'material ' // trim(mt%name) // ': poisson_ratio must be finite'
                else if (.not. finite(mt%restitution)) then
                    message = 'material ' // trim(mt%name) // ': restitution must be finite'
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
        integer :: n
        message = ''
        n = size(sc%radius)
        if (.not. (sc%dt > 0.0_wp)) then
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
                    message = 'material ' // trim(mt%name) // ': density must be positive'
                else if (.not. (mt%youngs_modulus > 0.0_wp)) then
                    message = 'material ' // trim(mt%name) // ': youngs_modulus must be positive'
                else if (.not. (mt%poisson_ratio > -1.0_wp .and. mt%poisson_ratio <= 0.5_wp)) then
                    message = 'material ' // trim(mt%name) // ': poisson_ratio must lie in (-1, 0.5]'
                else if (.not. (mt%restitution > 0.0_wp .and. mt%restitution <= 1.0_wp)) then
                    message = 'material ' // trim(mt%name) // ': restitution must lie in (0, 1]'
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
            if (.not. (sc%radius(i) > 0.0_wp .and. sc%radius(i) < huge(1.0_wp))) then
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
