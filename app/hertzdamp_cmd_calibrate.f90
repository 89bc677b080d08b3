!> The command `calibrate`: k and d (or the combination e identifies) fitted to
!> measured restitution coefficients, and contact times, at several impact speeds;
!> with `--damping auto`, the damping law the data support.  Parsing, reading the
!> CSV and printing only: the fit is hertzdamp_calibrate (packages/calibrate).
module hertzdamp_cmd_calibrate
    use hertzdamp, only: hertzdamp_rk, hertzdamp_end_name, HD_METHOD_FIT, HD_METHOD_RK45, HD_OK, HD_END_OVERLAP, &
                         hertzdamp_law_choices, hertzdamp_law_name, hertzdamp_law_q, hertzdamp_min_law, &
                         hertzdamp_max_law
    use hertzdamp_calibrate, only: cal_data, cal_options, cal_result, cal_check, cal_fit, cal_auto, cal_model, &
                                   CAL_OK, CAL_BAD_DATA, CAL_NOT_IDENTIFIED, CAL_NO_CONVERGENCE
    use hertzdamp_calibrate_maps, only: cal_law_name, cal_law_q, cal_max_law, CAL_LAW_LINEAR, CAL_LAW_TSUJI
    use hertzdamp_cli, only: cli_args, cli_buffer, cli_line, parse_args, parse_real, parse_choice, fail, quit, &
                             EXIT_USAGE, EXIT_OK, EXIT_NO_SOLUTION, EXIT_FAILURE
    use hertzdamp_cli_output, only: out_table, format_choices, FORMAT_TEXT, FORMAT_CSV, FORMAT_JSON
    use hertzdamp_cli_plot, only: plot_check_target, plot_scratch, plot_temp_name, gp_string
    use hertzdamp_cli_help, only: print_help, wants_help
    use hertzdamp_cli_text, only: g => fmt_text_short, itoa, one_line
    use hertzdamp_cli_materials, only: cli_contact, parse_contact, require_mass, contact_options, contact_flags
    use hertzdamp_cli_model, only: damping_unit, parse_end
    use hertzdamp_cli_plausible, only: warn_implausible, warn_value, quiet_flag
    implicit none
    private
    public :: cmd_calibrate

    integer, parameter :: wp = hertzdamp_rk

    !> Longest line of a data file, and most data rows.
    integer, parameter :: max_line = 4096, max_rows = 100000
    !> The columns a data file may have (velocity and e are required).
    character(len=*), parameter :: known_columns = 'velocity e tc sigma_e sigma_tc'
    !> The UTF-8 byte-order mark.
    character(len=*), parameter :: bom = char(239) // char(187) // char(191)
    !> Speeds at which the fitted curves are drawn.
    integer, parameter :: n_curve = 200

contains

    !> Exit code of a calibration status.
    integer function exit_of(status) result(code)
        integer, intent(in) :: status
        select case (status)
        case (CAL_OK); code = EXIT_OK
        case (CAL_NOT_IDENTIFIED); code = EXIT_NO_SOLUTION
        case (CAL_NO_CONVERGENCE); code = EXIT_FAILURE
        case (CAL_BAD_DATA); code = EXIT_USAGE
        case default; code = EXIT_FAILURE
        end select
    end function exit_of

    subroutine cmd_calibrate()
        type(cli_args) :: args
        type(cal_data) :: dat
        type(cal_options) :: o
        type(cli_contact) :: ct
        type(cal_result) :: res(0:cal_max_law)
        character(len=:), allocatable :: file, plot, terminal, dname, msg
        integer :: law, chosen, fmt, st, i
        integer, allocatable :: order(:)
        type(cli_buffer) :: buf
        if (wants_help()) call print_help('calibrate')
        call parse_args(2, '--damping --end --method --tol --format --plot ' // contact_options, &
                        contact_flags // ' ' // quiet_flag, args, allow_positional=.true.)
        if (.not. allocated(args%positional)) call fail(EXIT_USAGE, 'missing data file (see --help)')
        file = args%positional
        call parse_contact(args, ct)
        call require_mass(ct)
        o%mass = ct%mass
        dname = args%get('--damping', 'auto')
        law = parse_choice(dname, hertzdamp_law_choices() // ' auto', 'damping law (--damping)') - 1
        if (law > cal_max_law) law = -1   ! auto
        o%iend = parse_end(args%get('--end', hertzdamp_end_name(HD_END_OVERLAP)))
        o%method = merge(HD_METHOD_FIT, HD_METHOD_RK45, &
                         parse_choice(args%get('--method', 'fit'), 'fit rk45', 'method (--method)') == 1)
        if (args%has('--tol')) then
            if (o%method /= HD_METHOD_RK45) call fail(EXIT_USAGE, '--tol applies to --method rk45 only')
            o%tol = parse_real(args%get('--tol', ''), '--tol')
            if (.not. (o%tol >= 1.0e-15_wp .and. o%tol <= 1.0e-2_wp)) then
                call fail(EXIT_USAGE, '--tol must lie in [1e-15, 1e-2]')
            end if
        end if
        fmt = parse_choice(args%get('--format', 'text'), format_choices, 'format (--format)')
        plot = args%get('--plot', '')
        if (args%has('--plot')) call plot_check_target(plot, terminal, [file])

        call read_data(file, dat)
        ! the physical stiffness is the known k when the data have no contact times
        if (ct%has_kphys .and. .not. any(dat%has_tc)) o%k_known = ct%k_phys
        call cal_check(dat, o, st, msg)
        if (st /= CAL_OK) call fail(exit_of(st), file // ': ' // msg)
        call warn_implausible(args)
        call warn_value('--velocity', maxval(dat%u), g(maxval(dat%u)), args%has(quiet_flag), typed=.false., &
                        name=file // ': velocity')

        if (law < 0) then
            call cal_auto(dat, o, res, chosen)
            ! no law could be fitted (say why the first failed), or a law that may fit
            ! best could not be: choose none
            if (chosen < 0) then
                if (all(res(:)%status /= CAL_OK)) call fail(exit_of(res(0)%status), res(0)%message)
                i = findloc(res(:)%status /= CAL_OK, .true., dim=1) - 1
                call fail(exit_of(res(i)%status), res(i)%message // '; so --damping auto cannot tell which law ' // &
                          'the data support (fit one law with --damping LAW)')
            end if
            order = [chosen, pack([(i, i=0, cal_max_law)], [(i /= chosen, i=0, cal_max_law)])]
        else
            call cal_fit(dat, law, o, res(law))
            if (res(law)%status /= CAL_OK) call fail(exit_of(res(law)%status), res(law)%message)
            chosen = law
            order = [law]
        end if

        select case (fmt)
        case (FORMAT_CSV)
            call summary_table(res, order, chosen, law < 0, dat%weighted, fmt, buf)
        case (FORMAT_JSON)
            call write_json(file, dat, o, ct, res, order, chosen, law < 0, buf)
        case default
            call write_text(file, dat, o, ct, res, order, chosen, law < 0, buf)
        end select
        if (args%has('--plot')) call write_plot(dat, o, res, order, plot, terminal)
        call buf%flush_to_stdout()
        call quit(EXIT_OK)
    end subroutine cmd_calibrate

    ! ------------------------------------------------------------------ reading

    !> Read the CSV data file (exit 2 with the line named on any problem).
    subroutine read_data(file, dat)
        character(len=*), intent(in) :: file
        type(cal_data), intent(out) :: dat
        character(len=:), allocatable :: line, where
        type(cli_line), allocatable :: head(:), fields(:)
        integer :: u, ios, lineno, n, j, col(5), k
        real(wp), allocatable :: u_(:), e(:), tc(:), se(:), st(:)
        logical, allocatable :: has(:)
        integer, allocatable :: lines(:)
        logical :: eof
        character(len=256) :: iom
        character(len=16) :: b
        ! a directory opens and reads as an empty file: say what it is (FILE/. exists only then)
        inquire (file=file // '/.', exist=eof)
        if (eof) call fail(EXIT_USAGE, 'the data file "' // file // '" is a directory')
        open (newunit=u, file=file, status='old', action='read', iostat=ios, iomsg=iom)
        if (ios /= 0) call fail(EXIT_USAGE, 'cannot open the data file "' // file // '": ' // trim(iom))
        allocate (u_(64), e(64), tc(64), se(64), st(64), has(64), lines(64))
        where = file
        n = 0
        lineno = 0
        col = 0
        do
            call read_line(u, file, lineno, line, eof)
            if (eof) exit
            ! a UTF-8 byte-order mark (spreadsheet exports) at the start of the file
            if (lineno == 1 .and. len(line) >= 3) then
                if (line(1:3) == bom) line = line(4:)
            end if
            line = trim(adjustl(line))
            if (len(line) == 0) cycle
            if (line(1:1) == '#') cycle
            write (b, '(i0)') lineno
            where = file // ' line ' // trim(b)
            call split(line, where, fields)
            if (.not. allocated(head)) then
                head = fields
                do j = 1, size(head)
                    k = parse_column(head(j)%s, where)
                    if (col(k) /= 0) call fail(EXIT_USAGE, where // ': column "' // head(j)%s // '" given twice')
                    col(k) = j
                end do
                if (col(1) == 0 .or. col(2) == 0) call fail(EXIT_USAGE, where // &
                    ': the header must name the columns velocity and e (see --help)')
                if (col(4) /= 0 .and. col(3) /= 0 .and. col(5) == 0) call fail(EXIT_USAGE, where // &
                    ': sigma_e is given, so the contact times need sigma_tc too')
                if (col(5) /= 0 .and. (col(4) == 0 .or. col(3) == 0)) call fail(EXIT_USAGE, where // &
                    ': sigma_tc needs the columns tc and sigma_e')
                cycle
            end if
            if (size(fields) /= size(head)) then
                write (iom, '(i0,a,i0)') size(fields), ' fields, the header has ', size(head)
                call fail(EXIT_USAGE, where // ': ' // trim(iom))
            end if
            if (n == max_rows) then
                write (b, '(i0)') max_rows
                call fail(EXIT_USAGE, file // ': more than ' // trim(b) // ' data rows')
            end if
            if (n == size(u_)) call grow(u_, e, tc, se, st, has, lines)
            n = n + 1
            lines(n) = lineno
            u_(n) = value(fields, col(1), 'velocity', where, .true.)
            e(n) = value(fields, col(2), 'e', where, .true.)
            has(n) = .false.
            tc(n) = 0.0_wp
            if (col(3) /= 0) then
                has(n) = len(fields(col(3))%s) > 0
                if (has(n)) tc(n) = value(fields, col(3), 'tc', where, .true.)
            end if
            se(n) = 1.0_wp
            if (col(4) /= 0) se(n) = value(fields, col(4), 'sigma_e', where, .true.)
            st(n) = 1.0_wp
            if (col(5) /= 0) then
                if (has(n)) then
                    st(n) = value(fields, col(5), 'sigma_tc', where, .true.)
                else if (len(fields(col(5))%s) > 0) then
                    call fail(EXIT_USAGE, where // ': sigma_tc without a contact time')
                end if
            end if
        end do
        close (u)
        if (.not. allocated(head)) call fail(EXIT_USAGE, file // ': no header line (see --help)')
        if (n == 0) call fail(EXIT_USAGE, file // ': no data rows')
        dat%u = u_(1:n)
        dat%e = e(1:n)
        dat%tc = tc(1:n)
        dat%has_tc = has(1:n)
        dat%sigma_e = se(1:n)
        dat%sigma_tc = st(1:n)
        dat%weighted = col(4) /= 0
        dat%line = lines(1:n)
    end subroutine read_data

    !> Index of a column name in known_columns (exit 2 for others).
    integer function parse_column(name, where) result(k)
        character(len=*), intent(in) :: name, where
        select case (name)
        case ('velocity'); k = 1
        case ('e'); k = 2
        case ('tc'); k = 3
        case ('sigma_e'); k = 4
        case ('sigma_tc'); k = 5
        case default
            call fail(EXIT_USAGE, where // ': unknown column "' // name // '" (the columns are ' // known_columns // ')')
            k = 0
        end select
    end function parse_column

    !> A field as a number (strict: no nan, inf or trailing characters; exit 2).
    real(wp) function value(fields, j, name, where, required) result(x)
        type(cli_line), intent(in) :: fields(:)
        integer, intent(in) :: j
        character(len=*), intent(in) :: name, where
        logical, intent(in) :: required
        x = 0.0_wp
        if (len(fields(j)%s) == 0) then
            if (required) call fail(EXIT_USAGE, where // ': empty field ' // name)
            return
        end if
        x = parse_real(fields(j)%s, where // ', column ' // name)
    end function value

    !> Double the row arrays.
    subroutine grow(u, e, tc, se, st, has, lines)
        real(wp), allocatable, intent(inout) :: u(:), e(:), tc(:), se(:), st(:)
        logical, allocatable, intent(inout) :: has(:)
        integer, allocatable, intent(inout) :: lines(:)
        integer :: n
        n = size(u)
        u = [u, spread(0.0_wp, 1, n)]
        e = [e, spread(0.0_wp, 1, n)]
        tc = [tc, spread(0.0_wp, 1, n)]
        se = [se, spread(0.0_wp, 1, n)]
        st = [st, spread(0.0_wp, 1, n)]
        has = [has, spread(.false., 1, n)]
        lines = [lines, spread(0, 1, n)]
    end subroutine grow

    !> One line of any length up to max_line (exit 2 beyond); a final CR is dropped.
    subroutine read_line(u, file, lineno, line, eof)
        integer, intent(in) :: u
        character(len=*), intent(in) :: file
        integer, intent(inout) :: lineno
        character(len=:), allocatable, intent(out) :: line
        logical, intent(out) :: eof
        character(len=256) :: chunk
        character(len=16) :: b
        integer :: ios, sz
        line = ''
        eof = .false.
        lineno = lineno + 1
        do
            read (u, '(a)', advance='no', size=sz, iostat=ios) chunk
            line = line // chunk(1:sz)
            if (len(line) > max_line) then
                write (b, '(i0)') lineno
                call fail(EXIT_USAGE, file // ' line ' // trim(b) // ': longer than 4096 characters')
            end if
            if (is_iostat_eor(ios)) exit
            if (is_iostat_end(ios)) then
                eof = len(line) == 0
                exit
            end if
            if (ios /= 0) then
                write (b, '(i0)') lineno
                call fail(EXIT_USAGE, file // ' line ' // trim(b) // ': cannot read')
            end if
        end do
        if (len(line) > 0) then
            if (line(len(line):len(line)) == achar(13)) line = line(1:len(line) - 1)
        end if
    end subroutine read_line

    !> Comma-separated fields (RFC 4180), each trimmed of blanks; a field in double
    !> quotes may hold commas and doubled quotes ("" for "), and only blanks may follow
    !> its closing quote (else exit 2 naming `where`).
    subroutine split(line, where, fields)
        character(len=*), intent(in) :: line, where
        type(cli_line), allocatable, intent(out) :: fields(:)
        character(len=:), allocatable :: f
        integer :: i, n
        logical :: quoted
        allocate (fields(0))
        n = len(line)
        i = 1
        do
            do while (i <= n)               ! blanks before the field
                if (line(i:i) /= ' ') exit
                i = i + 1
            end do
            f = ''
            quoted = .false.
            if (i <= n) quoted = line(i:i) == '"'
            if (quoted) then
                i = i + 1
                do
                    if (i > n) call fail(EXIT_USAGE, where // ': a quoted field has no closing quote')
                    if (line(i:i) == '"') then
                        if (i < n) then
                            if (line(i + 1:i + 1) == '"') then
                                f = f // '"'
                                i = i + 2
                                cycle
                            end if
                        end if
                        i = i + 1
                        exit
                    end if
                    f = f // line(i:i)
                    i = i + 1
                end do
                do while (i <= n)           ! blanks after the closing quote, then the comma
                    if (line(i:i) == ',') exit
                    if (line(i:i) /= ' ') call fail(EXIT_USAGE, where // ': characters after a quoted field')
                    i = i + 1
                end do
                f = trim(adjustl(f))
            else
                do while (i <= n)
                    if (line(i:i) == ',') exit
                    f = f // line(i:i)
                    i = i + 1
                end do
                f = trim(f)
            end if
            fields = [fields, cli_line(f)]
            if (i > n) exit
            i = i + 1                       ! past the comma: a field follows (maybe empty)
        end do
    end subroutine split

    ! ------------------------------------------------------------------ output

    !> "d k^-0.4": the combination c that e identifies, for law q.
    function c_definition(law) result(s)
        integer, intent(in) :: law
        character(len=:), allocatable :: s
        select case (law)
        case (CAL_LAW_LINEAR); s = 'd k^(-2/5)'
        case (CAL_LAW_TSUJI); s = 'd k^(-1/2)'
        case default; s = 'd k^(-3/5)'
        end select
    end function c_definition

    function status_name(res) result(s)
        type(cal_result), intent(in) :: res
        character(len=:), allocatable :: s
        select case (res%status)
        case (CAL_OK); s = 'ok'
        case (CAL_NO_CONVERGENCE); s = 'no-convergence'
        case (CAL_NOT_IDENTIFIED); s = 'not-identified'
        case default; s = 'failed'
        end select
    end function status_name

    !> The summary: one row per law in `order`.
    subroutine summary_table(res, order, chosen, auto, wtd, fmt, buf)
        type(cal_result), intent(in) :: res(0:)
        integer, intent(in) :: order(:), chosen, fmt
        logical, intent(in) :: auto   !! several laws: delta AIC
        logical, intent(in) :: wtd    !! sigmas given: chi2/dof and p-value
        type(cli_buffer), intent(inout) :: buf
        type(out_table) :: t
        integer :: i, l
        logical :: ok
        character(len=:), allocatable :: du
        du = 'kg s^-1 m^-q'   ! d zeta^q zeta' with q of each law, or the unit of the one law shown
        if (size(order) == 1) du = damping_unit(order(1))
        call t%set_columns('damping,chosen,k,d,k_err,d_err,rms_residual_e,rms_residual_tc,c,c_err,chi2_dof,' // &
                           'p_value,delta_aic,status', ',,N m^-3/2,' // du // ',N m^-3/2,' // du // ',,s,SI,SI,,,,')
        do i = 1, size(order)
            l = order(i)
            ok = res(l)%status == CAL_OK
            call t%str(cal_law_name(l))
            call t%str(trim(merge('true ', 'false', l == chosen)))
            call t%num_or_none(res(l)%k, ok .and. res(l)%kd_known)
            call t%num_or_none(res(l)%d, ok .and. res(l)%kd_known)
            call t%num_or_none(res(l)%k_err, ok .and. res(l)%k_fitted)
            call t%num_or_none(res(l)%d_err, ok .and. res(l)%kd_known)
            call t%num_or_none(res(l)%rms_e, ok)
            call t%num_or_none(res(l)%rms_tc, ok .and. res(l)%n_tc > 0)
            call t%num_or_none(res(l)%c, ok)
            call t%num_or_none(res(l)%c_err, ok)
            call t%num_or_none(res(l)%chi2 / max(res(l)%dof, 1), ok .and. wtd)
            call t%num_or_none(res(l)%p_value, ok .and. wtd)
            call t%num_or_none(res(l)%delta_aic, ok .and. auto)
            call t%str(status_name(res(l)))
        end do
        call t%render(fmt, buf)
    end subroutine summary_table

    subroutine write_text(file, dat, o, ct, res, order, chosen, auto, buf)
        character(len=*), intent(in) :: file
        type(cal_data), intent(in) :: dat
        type(cal_options), intent(in) :: o
        type(cli_contact), intent(in) :: ct
        type(cal_result), intent(in) :: res(0:)
        integer, intent(in) :: order(:), chosen
        logical, intent(in) :: auto
        type(cli_buffer), intent(inout) :: buf
        type(out_table) :: t
        integer :: i, l
        character(len=:), allocatable :: s
        l = chosen
        call buf%add('# hertzdamp calibrate ' // one_line(file))
        s = '# ' // itoa(size(dat%u)) // ' restitution coefficients'
        if (count(dat%has_tc) > 0) s = s // ' and ' // itoa(count(dat%has_tc)) // ' contact times'
        s = s // ' at speeds ' // g(minval(dat%u)) // ' to ' // g(maxval(dat%u)) // ' m/s, '
        s = s // trim(merge('weighted by the given sigmas', 'no sigmas given (unweighted)', dat%weighted))
        call buf%add(s)
        s = '# mass ' // g(o%mass) // ' kg (' // ct%description // '); end ' // hertzdamp_end_name(o%iend) // &
            '; method ' // &
            trim(merge('fit ', 'rk45', o%method == HD_METHOD_FIT))
        call buf%add(s)
        if (res(l)%k_fitted) then
            call buf%add('# fitted: k and d (e identifies c = d k^(-2(1+q)/5), the contact times k)')
        else if (res(l)%kd_known) then
            call buf%add('# fitted: d, with k = k_phys = ' // g(o%k_known) // ' (no contact times to fit k)')
        else
            call buf%add('# fitted: c = d k^(-2(1+q)/5) only: without contact times or a known stiffness ' // &
                         '(--k-phys, or --youngs-modulus and --poisson-ratio), e cannot tell k')
        end if
        if (auto) then
            call buf%add('# criterion: smallest AIC; every law has the same number of parameters (' // &
                         itoa(res(l)%n_par) // ') here, so the smallest ' // trim(merge('chi2', 'RSS ', dat%weighted)) // &
                         ' (BIC agrees)')
        end if
        call buf%add('# uncertainties: standard (1 sigma); q of each law: ' // law_q_listing())
        call summary_table(res, order, chosen, auto, dat%weighted, FORMAT_TEXT, buf)
        do i = 1, size(order)
            if (res(order(i))%status /= CAL_OK) then
                call buf%add('# ' // cal_law_name(order(i)) // ': ' // res(order(i))%message)
            else if (len(res(order(i))%note) > 0) then
                call buf%add('# ' // cal_law_name(order(i)) // ': ' // res(order(i))%note)
            end if
        end do
        call buf%add('# ' // cal_law_name(l) // ': c = ' // c_definition(l) // ' = ' // g(res(l)%c) // ' +- ' // &
                     g(res(l)%c_err) // '; alpha at 1 m/s = ' // g(res(l)%a) // ' +- ' // g(res(l)%a_err) // &
                     '; ' // itoa(res(l)%iterations) // ' iterations')
        if (dat%weighted) then
            call buf%add('# ' // cal_law_name(l) // ': chi2 = ' // g(res(l)%chi2) // ', dof = ' // itoa(res(l)%dof) // &
                         ', chi2/dof = ' // g(res(l)%chi2 / max(res(l)%dof, 1)) // ', p-value = ' // g(res(l)%p_value))
        else
            call buf%add('# ' // cal_law_name(l) // ': RMS of the weighted residuals ' // g(res(l)%scale) // &
                         ' (the uncertainties are scaled by it)')
        end if
        if (res(l)%k_fitted) call buf%add('# ' // cal_law_name(l) // ': correlation of k and d ' // g(res(l)%corr_kd))
        if (res(l)%k_fitted .and. ct%has_kphys) call buf%add('# ' // cal_law_name(l) // ': fitted k / k_phys = ' // &
                                                              g(res(l)%k / ct%k_phys) // ' (k_phys = ' // &
                                                              g(ct%k_phys) // ')')
        call buf%add('# residuals of the ' // cal_law_name(l) // ' law:')
        call residual_table(dat, res(l), t)
        call t%render(FORMAT_TEXT, buf)
    end subroutine write_text

    !> Per measurement: data, fitted values and residuals of one law.
    subroutine residual_table(dat, r, t)
        type(cal_data), intent(in) :: dat
        type(cal_result), intent(in) :: r
        type(out_table), intent(out) :: t
        integer :: i
        logical :: tcs
        tcs = r%n_tc > 0
        if (any(dat%has_tc)) then
            call t%set_columns('velocity,e,e_fit,residual_e,tc,tc_fit,residual_tc', 'm/s,,,,s,s,s')
        else
            call t%set_columns('velocity,e,e_fit,residual_e', 'm/s,,,')
        end if
        do i = 1, size(dat%u)
            call t%num(dat%u(i))
            call t%num(dat%e(i))
            call t%num(r%e_fit(i))
            call t%num(dat%e(i) - r%e_fit(i))
            if (.not. any(dat%has_tc)) cycle
            call t%num_or_none(dat%tc(i), dat%has_tc(i))
            call t%num_or_none(r%tc_fit(i), r%kd_known .and. tcs)
            call t%num_or_none(dat%tc(i) - r%tc_fit(i), dat%has_tc(i) .and. tcs)
        end do
    end subroutine residual_table

    !> JSON: the run as metadata, one row per law under "laws" (the chosen first) and
    !> the data with every fitted law's values under "residuals" (one row per law and
    !> measurement, for the laws that were fitted).
    subroutine write_json(file, dat, o, ct, res, order, chosen, auto, buf)
        character(len=*), intent(in) :: file
        type(cal_data), intent(in) :: dat
        type(cal_options), intent(in) :: o
        type(cli_contact), intent(in) :: ct
        type(cal_result), intent(in) :: res(0:)
        integer, intent(in) :: order(:), chosen
        logical, intent(in) :: auto
        type(cli_buffer), intent(inout) :: buf
        type(out_table) :: t, r(1)
        integer :: i, l, j
        logical :: ok
        call t%set_columns('damping,q,chosen,status,message,note,k,k_err,d,d_err,corr_kd,c_definition,c,c_err,' // &
                           'alpha_1ms,alpha_1ms_err,chi2,dof,p_value,aic,delta_aic,akaike_weight,rms_residual_e,' // &
                           'rms_residual_tc,iterations')
        t%rows_key = 'laws'
        call t%meta('command', 'calibrate')
        call t%meta('file', file)
        call t%meta_num('mass', o%mass)
        call t%meta('contact', ct%description)
        call t%meta_num('k_phys', ct%k_phys, ct%has_kphys)
        call t%meta_bool('k_fixed', o%k_known > 0.0_wp)
        call t%meta('end', hertzdamp_end_name(o%iend))
        call t%meta('method', trim(merge('fit ', 'rk45', o%method == HD_METHOD_FIT)))
        if (auto) then
            call t%meta('damping', 'auto')
        else
            call t%meta('damping', cal_law_name(chosen))
        end if
        call t%meta_bool('weighted', dat%weighted)
        call t%meta('criterion', 'smallest AIC (chi2 + 2p with sigmas, n ln(RSS/n) + 2p without)')
        call t%meta('chosen', cal_law_name(chosen))
        call r(1)%set_columns('damping,velocity,e,e_fit,tc,tc_fit')
        r(1)%rows_key = 'residuals'
        do i = 1, size(order)
            l = order(i)
            ok = res(l)%status == CAL_OK
            call t%str(cal_law_name(l))
            call t%num(cal_law_q(l))
            call t%bool(l == chosen)
            call t%str(status_name(res(l)))
            call t%str(res(l)%message)
            call t%str(res(l)%note)
            call t%num_or_none(res(l)%k, ok .and. res(l)%kd_known)
            call t%num_or_none(res(l)%k_err, ok .and. res(l)%k_fitted)
            call t%num_or_none(res(l)%d, ok .and. res(l)%kd_known)
            call t%num_or_none(res(l)%d_err, ok .and. res(l)%kd_known)
            call t%num_or_none(res(l)%corr_kd, ok .and. res(l)%k_fitted)
            call t%str(c_definition(l))
            call t%num_or_none(res(l)%c, ok)
            call t%num_or_none(res(l)%c_err, ok)
            call t%num_or_none(res(l)%a, ok)
            call t%num_or_none(res(l)%a_err, ok)
            call t%num_or_none(res(l)%chi2, ok)
            call t%int(res(l)%dof)
            call t%num_or_none(res(l)%p_value, ok .and. dat%weighted)
            call t%num_or_none(res(l)%aic, ok)
            call t%num_or_none(res(l)%delta_aic, ok .and. auto)
            call t%num_or_none(res(l)%weight, ok .and. auto)
            call t%num_or_none(res(l)%rms_e, ok)
            call t%num_or_none(res(l)%rms_tc, ok .and. res(l)%n_tc > 0)
            call t%int(res(l)%iterations)
            if (.not. ok) cycle
            do j = 1, size(dat%u)
                call r(1)%str(cal_law_name(l))
                call r(1)%num(dat%u(j))
                call r(1)%num(dat%e(j))
                call r(1)%num(res(l)%e_fit(j))
                call r(1)%num_or_none(dat%tc(j), dat%has_tc(j))
                call r(1)%num_or_none(res(l)%tc_fit(j), res(l)%kd_known .and. res(l)%n_tc > 0)
            end do
        end do
        call t%render(FORMAT_JSON, buf, r)
    end subroutine write_json

    ! ------------------------------------------------------------------ plot

    !> The data (with error bars when the sigmas are given) and the fitted e(u) and
    !> T_c(u) of every law that was fitted; T_c panel when the file has contact times.
    !> Data, curves and script are scratch files of hertzdamp_cli_plot (every write
    !> checked; all removed, whatever happens).
    subroutine write_plot(dat, o, res, order, plot, terminal)
        type(cal_data), intent(in) :: dat
        type(cal_options), intent(in) :: o
        type(cal_result), intent(in) :: res(0:)
        integer, intent(in) :: order(:)
        character(len=*), intent(in) :: plot, terminal
        type(plot_scratch) :: s
        character(len=:), allocatable :: dat_file, cur_file, gp, pe, pt, line, col
        integer :: u, i, j, l, st
        real(wp) :: umin, umax, x, e, tc
        character(len=25 * 5) :: b5
        character(len=50) :: b2
        logical :: tcs
        call s%open('calibrate', 'dat', u, dat_file)
        do i = 1, size(dat%u)
            write (b5, '(5(es24.15e3,1x))') dat%u(i), dat%e(i), merge(dat%sigma_e(i), 0.0_wp, dat%weighted), &
                merge(dat%tc(i), -1.0_wp, dat%has_tc(i)), merge(dat%sigma_tc(i), 0.0_wp, dat%weighted .and. dat%has_tc(i))
            call s%write(u, trim(b5))
        end do
        call s%close(u)
        call s%open('calibrate', 'cur', u, cur_file)
        umin = minval(dat%u) / 1.2_wp
        umax = maxval(dat%u) * 1.2_wp
        do i = 0, n_curve
            x = umin * (umax / umin)**(real(i, wp) / n_curve)
            write (b2, '(es24.15e3)') x
            line = trim(b2)
            do j = 1, size(order)
                l = order(j)
                e = -1.0_wp
                tc = -1.0_wp
                if (res(l)%status == CAL_OK) then
                    call cal_model(l, o, res(l)%a, merge(res(l)%k, 0.0_wp, res(l)%kd_known), x, e, tc, st)
                    if (st /= HD_OK) e = -1.0_wp
                    if (st /= HD_OK .or. .not. res(l)%kd_known) tc = -1.0_wp
                end if
                write (b2, '(2(1x,es24.15e3))') e, tc
                line = line // trim(b2)
            end do
            call s%write(u, line)
        end do
        call s%close(u)
        call s%open('calibrate', 'gp', u, gp)
        tcs = any(dat%has_tc)
        call s%write(u, 'set terminal ' // terminal // ' size 900,' // trim(merge('900', '500', tcs)) // ' noenhanced')
        call s%write(u, 'set output ' // gp_string(plot_temp_name()))
        if (tcs) call s%write(u, 'set multiplot layout 2,1')
        call s%write(u, 'set logscale x')
        call s%write(u, 'set grid')
        call s%write(u, 'set key bottom right')
        call s%write(u, 'set xlabel "impact speed u [m/s]"')
        call s%write(u, 'set ylabel "restitution e"')
        pe = 'plot ' // gp_string(dat_file) // ' using 1:2' // trim(merge(':3 with yerrorbars', '   with points    ', &
             dat%weighted)) // ' pt 7 title "measured"'
        pt = 'plot ' // gp_string(dat_file) // ' using 1:($4 < 0 ? NaN : $4)' // &
             trim(merge(':5 with yerrorbars', '   with points    ', dat%weighted)) // ' pt 7 title "measured"'
        do j = 1, size(order)
            l = order(j)
            if (res(l)%status /= CAL_OK) cycle
            col = itoa(2 * j)
            pe = pe // ', ' // gp_string(cur_file) // ' using 1:($' // col // ' < 0 ? NaN : $' // col // &
                 ') with lines lw 2 title ' // gp_string(cal_law_name(l))
            if (res(l)%kd_known) then
                col = itoa(2 * j + 1)
                pt = pt // ', ' // gp_string(cur_file) // ' using 1:($' // col // ' < 0 ? NaN : $' // col // &
                     ') with lines lw 2 title ' // gp_string(cal_law_name(l))
            end if
        end do
        call s%write(u, pe)
        if (tcs) then
            call s%write(u, 'set ylabel "contact time T_c [s]"')
            call s%write(u, 'set format y "%.2e"')
            call s%write(u, 'set key top right')
            call s%write(u, pt)
            call s%write(u, 'unset multiplot')
        end if
        call s%write(u, 'set output')
        call s%close(u)
        call s%draw(gp, plot)
    end subroutine write_plot

    !> 'q1 law1, q2 law2, ...' from the registry, each q as a fraction of quarters (0, 1/4,
    !> 1/2: the exponents the laws have).
    function law_q_listing() result(s)
        character(len=:), allocatable :: s
        integer :: l, n, den
        s = ''
        do l = hertzdamp_min_law, hertzdamp_max_law
            n = nint(4.0_wp * hertzdamp_law_q(l))
            den = 4
            do while (n > 0 .and. mod(n, 2) == 0 .and. den > 1)
                n = n / 2
                den = den / 2
            end do
            if (l > hertzdamp_min_law) s = s // ', '
            if (n == 0 .or. den == 1) then
                s = s // itoa(n) // ' ' // hertzdamp_law_name(l)
            else
                s = s // itoa(n) // '/' // itoa(den) // ' ' // hertzdamp_law_name(l)
            end if
        end do
    end function law_q_listing

end module hertzdamp_cmd_calibrate
