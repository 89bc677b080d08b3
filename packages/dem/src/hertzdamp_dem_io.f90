!> Reading a scene from a Fortran namelist file (the format of data/scenes/*.nml).
!>
!> The file holds namelist groups, each starting with `&name` and ending with `/`;
!> blank lines and lines starting with `!` or `#` may separate them:
!>
!>     &scene    title, dt, steps_per_contact, end_time, gravity, g, contact_end,
!>               damping, report, accuracy, domain_lo, domain_hi, rest_speed,
!>               samples /                                                       (once)
!>     &material name, density, youngs_modulus, poisson_ratio, restitution /     (repeated)
!>     &particle material, radius, position, velocity, count, spacing /          (repeated)
!>     &wall     material, point, normal /                                       (repeated)
!>
!> `count` > 1 repeats a particle at position + (i-1) spacing, i = 1..count.
!> `report` is 'restitution' or 'restitution duration'; `damping` is the damping law
!> of every contact, 'linear' (default), 'tsuji' or 'kuwabara-kono' (damping force
!> d zeta^q zeta', q = 0, 1/4, 1/2; doc/damping-laws.md).  Each group is read with
!> the Fortran namelist READ from its own lines, so the compiler's own message
!> names an unknown key; this module adds the line number.  Lines longer than 1024
!> characters and files of more than 1,000,000 lines are refused (an endless input
!> such as /dev/zero fails after its first 1025 characters).  Nothing is printed:
!> failures return HD_BAD_ARGUMENT and a one-line message.
module hertzdamp_dem_io
    use hertzdamp, only: hertzdamp_rk, HD_OK, HD_BAD_ARGUMENT, hertzdamp_law_code, hertzdamp_law_choices, &
                         hertzdamp_end_code, hertzdamp_end_choices
    use hertzdamp_text_format, only: lower, prose
    use hertzdamp_dem, only: hertzdamp_dem_scene, hertzdamp_dem_material, hertzdamp_dem_wall, &
                             hertzdamp_dem_max_particles
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk
    !> A key the file did not set keeps its marker.  Each group is read twice, with
    !> the markers of set A and of set B: a key is missing when it holds its marker in
    !> both reads, so that no value a file can give (-huge, +huge, -Inf, ...) is taken
    !> for a missing key.
    real(wp), parameter :: unset_a = -huge(1.0_wp), unset_b = huge(1.0_wp)
    integer, parameter :: iunset_a = -huge(1), iunset_b = huge(1)
    !> Longest line of a scene file [characters]; longer lines are refused.
    integer, parameter :: line_len = 1024
    !> Most lines of a scene file.
    integer, parameter :: max_lines = 1000000

    public :: hertzdamp_scene_read

contains

    !> True when a real key holds its marker in both reads (a from set A, b from B).
    pure elemental logical function missing(a, b)
        real(wp), intent(in) :: a, b
        missing = a == unset_a .and. b == unset_b
    end function missing

    !> True when an integer key holds its marker in both reads.
    pure elemental logical function missing_int(a, b)
        integer, intent(in) :: a, b
        missing_int = a == iunset_a .and. b == iunset_b
    end function missing_int

    !> Read and validate the syntax of a scene file (physical validity is checked by
    !> hertzdamp_dem_check).  status HD_OK, or HD_BAD_ARGUMENT with a message.
    subroutine hertzdamp_scene_read(path, sc, status, message)
        character(len=*), intent(in) :: path                  !! scene file
        type(hertzdamp_dem_scene), intent(out) :: sc           !! the scene
        integer, intent(out) :: status                         !! HD_OK or HD_BAD_ARGUMENT
        character(len=:), allocatable, intent(out) :: message  !! empty on success
        character(len=line_len), allocatable :: lines(:), grown(:)
        character(len=line_len) :: buf
        character(len=line_len + 1) :: rbuf
        character(len=256) :: iom
        character(len=32) :: gname
        integer :: u, ios, nl, i, first, last, nscene, sz
        logical :: done

        status = HD_BAD_ARGUMENT
        message = ''
        allocate (sc%mat(0), sc%pmat(0), sc%radius(0), sc%x(3, 0), sc%v(3, 0), sc%pline(0), sc%wall(0))
        sc%title = ''
        open (newunit=u, file=path, status='old', action='read', iostat=ios, iomsg=iom)
        if (ios /= 0) then
            message = 'cannot open scene file ' // path // ': ' // trim(iom)
            return
        end if
        ! lines into a buffer that doubles when full; a line longer than line_len
        ! characters (or endless input without a newline, such as /dev/zero) is
        ! refused after reading at most line_len characters of it
        allocate (lines(64))
        nl = 0
        do
            read (u, '(a)', advance='no', size=sz, iostat=ios, iomsg=iom) rbuf
            if (is_iostat_end(ios)) exit
            if (ios == 0) then
                close (u)
                write (iom, '(i0)') line_len
                message = at(nl + 1) // 'longer than ' // trim(iom) // ' characters'
                return
            end if
            if (.not. is_iostat_eor(ios)) then
                close (u)
                message = at(nl + 1) // 'cannot read: ' // trim(iom)
                return
            end if
            if (nl == max_lines) then
                close (u)
                write (iom, '(i0)') max_lines
                message = 'more than ' // trim(iom) // ' lines'
                return
            end if
            if (nl == size(lines)) then
                allocate (grown(2 * nl))
                grown(1:nl) = lines(1:nl)
                call move_alloc(grown, lines)
            end if
            nl = nl + 1
            lines(nl) = rbuf(1:sz)
        end do
        close (u)
        nscene = 0
        i = 1
        do while (i <= nl)
            buf = adjustl(lines(i))
            if (len_trim(buf) == 0 .or. buf(1:1) == '!' .or. buf(1:1) == '#') then
                i = i + 1
                cycle
            end if
            if (buf(1:1) /= '&') then
                message = at(i) // 'text outside a namelist group (groups start with &scene, &material, ' // &
                          '&particle or &wall)'
                return
            end if
            gname = group_name(buf)
            first = i
            call find_end(lines, first, nl, last, done)
            if (.not. done) then
                message = at(first) // '&' // trim(gname) // ' is not closed by /'
                return
            end if
            select case (trim(gname))
            case ('scene')
                nscene = nscene + 1
                if (nscene > 1) then
                    message = at(first) // 'second &scene group (only one is allowed)'
                    return
                end if
                call read_scene(lines(first:last), first, sc, message)
            case ('material')
                call read_material(lines(first:last), first, sc, message)
            case ('particle')
                call read_particle(lines(first:last), first, sc, message)
            case ('wall')
                call read_wall(lines(first:last), first, sc, message)
            case default
                message = at(first) // 'unknown group &' // trim(gname) // &
                          ' (expected &scene, &material, &particle or &wall)'
            end select
            if (len(message) > 0) return
            i = last + 1
        end do
        if (nscene == 0) then
            message = path // ': no &scene group'
            return
        end if
        status = HD_OK
    end subroutine hertzdamp_scene_read

    !> 'line N: '
    pure function at(line) result(s)
        integer, intent(in) :: line
        character(len=:), allocatable :: s
        character(len=16) :: b
        write (b, '(i0)') line
        s = 'line ' // trim(b) // ': '
    end function at

    !> The (lower-case) name after '&'.
    pure function group_name(text) result(name)
        character(len=*), intent(in) :: text
        character(len=32) :: name
        integer :: k, c
        name = ''
        do k = 2, min(len_trim(text), 33)
            c = iachar(text(k:k))
            if (.not. (text(k:k) >= 'a' .and. text(k:k) <= 'z' .or. text(k:k) >= 'A' .and. text(k:k) <= 'Z' &
                       .or. text(k:k) >= '0' .and. text(k:k) <= '9' .or. text(k:k) == '_')) exit
            if (c >= iachar('A') .and. c <= iachar('Z')) c = c + 32
            name(k - 1:k - 1) = achar(c)
        end do
    end function group_name

    !> The line holding the '/' that closes the group opened on line `first`
    !> ('/' inside quotes and after '!' do not count).
    pure subroutine find_end(lines, first, nl, last, done)
        character(len=*), intent(in) :: lines(:)
        integer, intent(in) :: first, nl
        integer, intent(out) :: last
        logical, intent(out) :: done
        integer :: i, k
        character :: q
        q = ' '
        done = .false.
        last = first
        do i = first, nl
            q = ' '
            do k = 1, len_trim(lines(i))
                associate (ch => lines(i)(k:k))
                    if (q /= ' ') then
                        if (ch == q) q = ' '
                    else if (ch == '''' .or. ch == '"') then
                        q = ch
                    else if (ch == '!') then
                        exit
                    else if (ch == '/') then
                        last = i
                        done = .true.
                        return
                    end if
                end associate
            end do
        end do
    end subroutine find_end

    !> Turn a namelist READ failure into 'line N: &group: message', with N the line
    !> of the offending key when the compiler's message names it.
    function nml_error(lines, first, group, iom) result(msg)
        character(len=*), intent(in) :: lines(:), group, iom
        integer, intent(in) :: first
        character(len=:), allocatable :: msg
        integer :: k, p, q, line, kind, from
        character(len=:), allocatable :: key, low, text, name
        line = first
        low = lower(iom)
        ! gfortran: "Cannot match namelist object name <token>".  The token is an
        ! unknown key when it stands where a key stands (after a separator, followed
        ! by '='); it is the rest of a malformed value when it follows '=' or is glued
        ! to a number (dt = abc, count = 1.5, radius = 1e-3x).
        p = index(low, 'object name ')
        if (p > 0) then
            key = trim(adjustl(low(p + 12:)))
            q = scan(key, ' (=')
            if (q > 0) key = key(1:q - 1)
            kind = 0
            name = ''
            if (len(key) > 0) then
                do k = 1, size(lines)
                    text = lower(lines(k))
                    from = 1
                    do
                        q = index(text(from:), key)
                        if (q == 0) exit
                        q = from + q - 1
                        call classify(text, q, q + len(key) - 1, kind, name)
                        if (kind /= 0) exit
                        from = q + 1
                        if (from > len(text)) exit
                    end do
                    if (kind /= 0) then
                        line = first + k - 1
                        exit
                    end if
                end do
            end if
            select case (kind)
            case (1)
                msg = at(line) // '&' // group // ': unknown key "' // key // '"'
            case (2)
                msg = at(line) // '&' // group // ': malformed value of ' // name // ' (near "' // key // '")'
            case default
                msg = at(line) // '&' // group // ': unknown key or malformed value near "' // key // '"'
            end select
        else if (index(low, 'bad data for namelist object ') > 0) then
            ! gfortran: "Bad data for namelist object <key>" (e.g. position = 0,0,x)
            p = index(low, 'bad data for namelist object ')
            key = trim(adjustl(low(p + 29:)))
            q = scan(key, ' (')
            if (q > 0) key = key(1:q - 1)
            msg = at(line) // '&' // group // ': malformed value of ' // key
        else
            msg = at(line) // '&' // group // ': ' // trim(iom)
        end if
    end function nml_error

    !> The token text(a:b) in a namelist line: 1 where a key stands (after a separator
    !> or at the start, followed by '='), 2 inside a value (after '=' or glued to a
    !> number; name = the key before the last '=' of the line), 0 neither.
    subroutine classify(text, a, b, kind, name)
        character(len=*), intent(in) :: text
        integer, intent(in) :: a, b
        integer, intent(out) :: kind
        character(len=:), allocatable, intent(inout) :: name
        integer :: pb, na, k, e
        character :: cp, cn
        kind = 0
        if (b < len(text)) then
            if (is_name_char(text(b + 1:b + 1))) return   ! only part of a longer word
        end if
        cp = ' '
        pb = a - 1
        do while (pb >= 1)
            if (text(pb:pb) /= ' ') exit
            pb = pb - 1
        end do
        if (pb >= 1) cp = text(pb:pb)
        cn = ' '
        na = b + 1
        do while (na <= len(text))
            if (text(na:na) /= ' ') exit
            na = na + 1
        end do
        if (na <= len(text)) cn = text(na:na)
        if (cn == '=' .and. cp /= '=' .and. (pb < 1 .or. cp == ',' .or. pb < a - 1)) then
            kind = 1
            return
        end if
        if (cp == '=' .or. (pb == a - 1 .and. (index('0123456789.+-', cp) > 0))) then
            ! the key: the name before the last '=' at or before pb
            e = index(text(1:max(pb, 1)), '=', back=.true.)
            name = ''
            if (e > 1) then
                k = e - 1
                do while (k >= 1)
                    if (text(k:k) /= ' ') exit
                    k = k - 1
                end do
                na = k
                do while (k >= 1)
                    if (.not. is_name_char(text(k:k))) exit
                    k = k - 1
                end do
                if (na > k) name = text(k + 1:na)
            end if
            if (len(name) == 0) name = 'a key'
            kind = 2
        end if
    end subroutine classify

    pure logical function is_name_char(c)
        character, intent(in) :: c
        is_name_char = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z') .or. (c >= '0' .and. c <= '9') &
                       .or. c == '_'
    end function is_name_char

    subroutine read_scene(lines, first, sc, msg)
        character(len=*), intent(in) :: lines(:)
        integer, intent(in) :: first
        type(hertzdamp_dem_scene), intent(inout) :: sc
        character(len=:), allocatable, intent(inout) :: msg
        character(len=256) :: title, contact_end, damping, report, iom
        real(wp) :: dt, end_time, g(3), accuracy, domain_lo(3), domain_hi(3), rest_speed
        real(wp) :: dt_b, end_time_b, domain_lo_b(3), domain_hi_b(3)
        integer :: steps_per_contact, samples, ios, steps_b
        logical :: gravity
        namelist /scene/ title, dt, steps_per_contact, end_time, gravity, g, contact_end, damping, report, accuracy, &
            domain_lo, domain_hi, rest_speed, samples
        call load(unset_b, iunset_b)
        if (len(msg) > 0) return
        dt_b = dt
        end_time_b = end_time
        steps_b = steps_per_contact
        domain_lo_b = domain_lo
        domain_hi_b = domain_hi
        call load(unset_a, iunset_a)
        if (len(msg) > 0) return
        if (missing(dt, dt_b)) then
            msg = at(first) // '&scene: dt missing (time step [s])'
        else if (missing(end_time, end_time_b)) then
            msg = at(first) // '&scene: end_time missing [s]'
        end if
        if (len(msg) > 0) return
        sc%title = trim(title)
        sc%dt = dt
        sc%end_time = end_time
        sc%gravity = gravity
        sc%g = g
        sc%accuracy = accuracy
        sc%rest_speed = rest_speed
        sc%samples = samples
        sc%iend = hertzdamp_end_code(trim(adjustl(lower(contact_end))))
        if (sc%iend < 0) then
            msg = at(first) // '&scene: contact_end must be ' // prose(hertzdamp_end_choices(), quote="'")
            return
        end if
        sc%law = hertzdamp_law_code(trim(adjustl(lower(damping))))
        if (sc%law < 0) then
            msg = at(first) // '&scene: damping must be ' // prose(hertzdamp_law_choices(), quote="'") // ' (got ''' // &
                  trim(adjustl(damping)) // ''')'
            return
        end if
        select case (trim(lower(report)))
        case ('restitution'); sc%want_duration = .false.
        case ('restitution duration', 'restitution,duration', 'restitution, duration'); sc%want_duration = .true.
        case default
            msg = at(first) // '&scene: report must be ''restitution'' or ''restitution duration'''
            return
        end select
        if (missing_int(steps_per_contact, steps_b)) then
            if (sc%want_duration) then
                msg = at(first) // '&scene: steps_per_contact missing (N, contact time N dt)'
                return
            end if
            steps_per_contact = 10
        end if
        sc%steps_per_contact = steps_per_contact
        if (any(missing(domain_lo, domain_lo_b)) .neqv. any(missing(domain_hi, domain_hi_b))) then
            msg = at(first) // '&scene: give both domain_lo and domain_hi, or neither'
            return
        end if
        if (all(missing(domain_lo, domain_lo_b)) .neqv. any(missing(domain_lo, domain_lo_b))) then
            msg = at(first) // '&scene: domain_lo needs 3 coordinates [m]'
            return
        end if
        if (all(missing(domain_hi, domain_hi_b)) .neqv. any(missing(domain_hi, domain_hi_b))) then
            msg = at(first) // '&scene: domain_hi needs 3 coordinates [m]'
            return
        end if
        sc%has_domain = .not. any(missing(domain_lo, domain_lo_b))
        if (sc%has_domain) then
            sc%domain_lo = domain_lo
            sc%domain_hi = domain_hi
        end if

    contains

        !> Defaults, the markers of one set for the keys without default, and the read.
        subroutine load(marker, imarker)
            real(wp), intent(in) :: marker
            integer, intent(in) :: imarker
            title = ''
            dt = marker
            end_time = marker
            steps_per_contact = imarker
            gravity = .false.
            g = [0.0_wp, 0.0_wp, -9.81_wp]
            contact_end = 'overlap'
            damping = 'linear'
            report = 'restitution duration'
            accuracy = 1.0e-3_wp
            domain_lo = marker
            domain_hi = marker
            rest_speed = 1.0e-3_wp
            samples = 1000
            read (lines, nml=scene, iostat=ios, iomsg=iom)
            if (ios /= 0) msg = nml_error(lines, first, 'scene', iom)
        end subroutine load

    end subroutine read_scene

    subroutine read_material(lines, first, sc, msg)
        character(len=*), intent(in) :: lines(:)
        integer, intent(in) :: first
        type(hertzdamp_dem_scene), intent(inout) :: sc
        character(len=:), allocatable, intent(inout) :: msg
        character(len=256) :: name, iom
        real(wp) :: density, youngs_modulus, poisson_ratio, restitution
        integer :: ios, k
        type(hertzdamp_dem_material) :: mt
        real(wp) :: density_b, youngs_modulus_b, poisson_ratio_b, restitution_b
        namelist /material/ name, density, youngs_modulus, poisson_ratio, restitution
        call load(unset_b)
        if (len(msg) > 0) return
        density_b = density
        youngs_modulus_b = youngs_modulus
        poisson_ratio_b = poisson_ratio
        restitution_b = restitution
        call load(unset_a)
        if (len(msg) > 0) return
        if (len_trim(name) == 0) then
            msg = at(first) // '&material: name missing'
        else if (len_trim(name) > len(mt%name)) then
            msg = at(first) // '&material: name longer than 32 characters'
        else if (missing(density, density_b)) then
            msg = at(first) // '&material: density missing [kg m^-3]'
        else if (missing(youngs_modulus, youngs_modulus_b)) then
            msg = at(first) // '&material: youngs_modulus missing [Pa]'
        else if (missing(poisson_ratio, poisson_ratio_b)) then
            msg = at(first) // '&material: poisson_ratio missing'
        else if (missing(restitution, restitution_b)) then
            msg = at(first) // '&material: restitution missing (target e)'
        end if
        if (len(msg) > 0) return
        do k = 1, size(sc%mat)
            if (sc%mat(k)%name == name) then
                msg = at(first) // '&material: name ''' // trim(name) // ''' defined twice'
                return
            end if
        end do
        ! the values' ranges: hertzdamp_dem_check, whose message names this line
        mt = hertzdamp_dem_material(name, density, youngs_modulus, poisson_ratio, restitution, first)
        sc%mat = [sc%mat, mt]

    contains

        subroutine load(marker)
            real(wp), intent(in) :: marker
            name = ''
            density = marker
            youngs_modulus = marker
            poisson_ratio = marker
            restitution = marker
            read (lines, nml=material, iostat=ios, iomsg=iom)
            if (ios /= 0) msg = nml_error(lines, first, 'material', iom)
        end subroutine load

    end subroutine read_material

    !> Index of a material by name, 0 if unknown.
    pure integer function find_material(sc, name) result(k)
        type(hertzdamp_dem_scene), intent(in) :: sc
        character(len=*), intent(in) :: name
        integer :: i
        k = 0
        do i = 1, size(sc%mat)
            if (sc%mat(i)%name == name) k = i
        end do
    end function find_material

    subroutine read_particle(lines, first, sc, msg)
        character(len=*), intent(in) :: lines(:)
        integer, intent(in) :: first
        type(hertzdamp_dem_scene), intent(inout) :: sc
        character(len=:), allocatable, intent(inout) :: msg
        character(len=256) :: material, iom
        real(wp) :: radius, position(3), velocity(3), spacing(3)
        integer :: count, ios, k, im, n0
        real(wp), allocatable :: xs(:, :), vs(:, :)
        real(wp) :: radius_b, position_b(3)
        namelist /particle/ material, radius, position, velocity, count, spacing
        call load(unset_b)
        if (len(msg) > 0) return
        radius_b = radius
        position_b = position
        call load(unset_a)
        if (len(msg) > 0) return
        im = find_material(sc, material)
        if (len_trim(material) == 0) then
            msg = at(first) // '&particle: material missing'
        else if (im == 0) then
            msg = at(first) // '&particle: unknown material ''' // trim(material) // &
                  ''' (define it in a &material group before the particles)'
        else if (missing(radius, radius_b)) then
            msg = at(first) // '&particle: radius missing [m]'
        else if (.not. (radius > 0.0_wp)) then
            msg = at(first) // '&particle: radius must be positive'
        else if (any(missing(position, position_b))) then
            msg = at(first) // '&particle: position missing (3 coordinates) [m]'
        else if (count < 1) then
            msg = at(first) // '&particle: count must be at least 1'
        else if (count > hertzdamp_dem_max_particles - size(sc%radius)) then
            msg = at(first) // '&particle: too many particles'
        end if
        if (len(msg) > 0) return
        n0 = size(sc%radius)
        allocate (xs(3, n0 + count), vs(3, n0 + count))
        xs(:, 1:n0) = sc%x
        vs(:, 1:n0) = sc%v
        do k = 1, count
            xs(:, n0 + k) = position + (k - 1) * spacing
            vs(:, n0 + k) = velocity
        end do
        call move_alloc(xs, sc%x)
        call move_alloc(vs, sc%v)
        sc%radius = [sc%radius, spread(radius, 1, count)]
        sc%pmat = [sc%pmat, spread(im, 1, count)]
        sc%pline = [sc%pline, spread(first, 1, count)]

    contains

        subroutine load(marker)
            real(wp), intent(in) :: marker
            material = ''
            radius = marker
            position = marker
            velocity = 0.0_wp
            count = 1
            spacing = 0.0_wp
            read (lines, nml=particle, iostat=ios, iomsg=iom)
            if (ios /= 0) msg = nml_error(lines, first, 'particle', iom)
        end subroutine load

    end subroutine read_particle

    subroutine read_wall(lines, first, sc, msg)
        character(len=*), intent(in) :: lines(:)
        integer, intent(in) :: first
        type(hertzdamp_dem_scene), intent(inout) :: sc
        character(len=:), allocatable, intent(inout) :: msg
        character(len=256) :: material, iom
        real(wp) :: point(3), normal(3)
        integer :: ios, im
        type(hertzdamp_dem_wall) :: w
        real(wp) :: point_b(3), normal_b(3)
        namelist /wall/ material, point, normal
        call load(unset_b)
        if (len(msg) > 0) return
        point_b = point
        normal_b = normal
        call load(unset_a)
        if (len(msg) > 0) return
        im = find_material(sc, material)
        if (len_trim(material) == 0) then
            msg = at(first) // '&wall: material missing'
        else if (im == 0) then
            msg = at(first) // '&wall: unknown material ''' // trim(material) // ''''
        else if (any(missing(point, point_b))) then
            msg = at(first) // '&wall: point missing (3 coordinates) [m]'
        else if (any(missing(normal, normal_b))) then
            msg = at(first) // '&wall: normal missing (3 components)'
        else if (.not. all(abs(normal) <= huge(1.0_wp))) then
            msg = at(first) // '&wall: normal must be finite'
        else if (.not. (norm2(normal) > 0.0_wp)) then
            msg = at(first) // '&wall: normal must not be zero'
        end if
        if (len(msg) > 0) return
        w%material = im
        w%point = point
        w%normal = normal / maxval(abs(normal))   ! scaled first: no overflow or underflow in norm2
        w%normal = w%normal / norm2(w%normal)
        w%line = first
        sc%wall = [sc%wall, w]

    contains

        subroutine load(marker)
            real(wp), intent(in) :: marker
            material = ''
            point = marker
            normal = marker
            read (lines, nml=wall, iostat=ios, iomsg=iom)
            if (ios /= 0) msg = nml_error(lines, first, 'wall', iom)
        end subroutine load

    end subroutine read_wall

end module hertzdamp_dem_io
