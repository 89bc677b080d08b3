!> The tables of doc/peers.md section 7 (`hertzdamp check --table`): the e each engine
!> achieves when the user writes the target into its restitution input, and the speed
!> dependence of the laws whose e depends on the impact speed.  Markdown lines, or rows
!> as data (hertzdamp_check_report) for CSV and JSON.
module hertzdamp_check_table
    use hertzdamp, only: hertzdamp_rk, hertzdamp_end_name, hertzdamp_law_name, hertzdamp_law_speed_exponent, &
                         HD_OK, HD_NO_REBOUND, HD_NO_CONVERGENCE, HD_END_OVERLAP, HD_END_FORCE, HD_DAMPING_LINEAR, &
                         HD_DAMPING_KUWABARA_KONO
    use hertzdamp_check_model, only: peer_deck, peer_spec_field, peer_spec_count, peer_law_inverse, &
                               peer_law_forward, peer_beta, peer_damping, peer_row_law, peer_row_end, peer_row_coef, &
                               peer_nan, peer_float, COEF_GAMMA_P6, COEF_GAMMA_SQRT2_P6, COEF_GAMMA_SQRT5_BETA, &
                               COEF_GAMMA_2BETA, COEF_GAMMA_SQRT6, COEF_GAMMA_SQRT5_BETA_EPS, COEF_GAMMA_SQRT6_THORNTON
    use hertzdamp_check_report, only: peer_report
    use hertzdamp_text_list, only: text_string
    use hertzdamp_text_format, only: fmt_short, ROUND_TRIP
    implicit none
    private

    integer, parameter :: wp = hertzdamp_rk

    !> Targets of the documentation table.
    real(wp), parameter :: table_targets(5) = [0.1_wp, 0.3_wp, 0.5_wp, 0.7_wp, 0.9_wp]
    !> Speed ratios u/u0 of the speed-dependence table.
    real(wp), parameter :: table_ratios(5) = [0.01_wp, 0.1_wp, 1.0_wp, 10.0_wp, 100.0_wp]

    public :: peer_table_lines, peer_table_report

contains



    !> The rows whose damping parameter is a restitution coefficient (or Yade's betan,
    !> read as the linear damping ratio beta(e) of the target).
    logical function restitution_row(row)
        integer, intent(in) :: row
        select case (peer_row_coef(row))
        case (COEF_GAMMA_P6, COEF_GAMMA_SQRT2_P6, COEF_GAMMA_SQRT5_BETA, COEF_GAMMA_2BETA, COEF_GAMMA_SQRT6, &
              COEF_GAMMA_SQRT5_BETA_EPS, COEF_GAMMA_SQRT6_THORNTON)
            restitution_row = .true.
        case default
            restitution_row = .false.
        end select
    end function restitution_row

    !> e achieved by a restitution row when the user writes the target et.
    subroutine row_achieved(row, et, e, st)
        integer, intent(in) :: row
        real(wp), intent(in) :: et
        real(wp), intent(out) :: e
        integer, intent(out) :: st
        type(peer_deck) :: d
        real(wp) :: tau
        d%row = row
        d%coef = peer_row_coef(row)
        d%m = 1.0_wp
        d%m_damp = 1.0_wp
        d%p = et
        if (d%coef == COEF_GAMMA_SQRT6) d%p = peer_beta(et)
        if (d%coef == COEF_GAMMA_SQRT5_BETA_EPS) d%p = peer_float(et)
        call peer_law_forward(peer_row_law(row), peer_damping(d, d%p), peer_row_end(row), e, tau, st)
    end subroutine row_achieved

    !> e at u = ratio u0 for a speed-dependent law whose coefficient gives et exactly at u0.
    subroutine speed_achieved(law, iend, et, ratio, e, st)
        integer, intent(in) :: law, iend
        real(wp), intent(in) :: et, ratio
        real(wp), intent(out) :: e
        integer, intent(out) :: st
        real(wp) :: a0, tau, expo
        e = 0.0_wp
        call peer_law_inverse(law, et, iend, a0, st)
        if (st /= HD_OK) return
        expo = hertzdamp_law_speed_exponent(law)
        call peer_law_forward(law, a0 * ratio**expo, iend, e, tau, st)
    end subroutine speed_achieved

    function cell(e, st) result(s)
        real(wp), intent(in) :: e
        integer, intent(in) :: st
        character(len=:), allocatable :: s
        character(len=16) :: b
        select case (st)
        case (HD_OK)
            write (b, '(f6.4)') e
            s = trim(adjustl(b))
        case (HD_NO_REBOUND)
            s = 'no rebound'
        case default
            s = 'n/a'
        end select
    end function cell

    function used_by(law, iend) result(s)
        integer, intent(in) :: law, iend
        character(len=:), allocatable :: s
        integer :: row
        character(len=:), allocatable :: eng, opt
        s = ''
        do row = 1, peer_spec_count
            if (peer_row_law(row) /= law .or. peer_row_end(row) /= iend) cycle
            if (restitution_row(row)) cycle
            eng = peer_spec_field(row, 'engine')
            opt = short_option(row)
            if (index(s, eng // ' ' // opt) > 0) cycle
            if (len(s) > 0) s = s // '; '
            s = s // eng // ' ' // opt
        end do
    end function used_by

    !> A short name of a row's option for the tables.
    function short_option(row) result(s)
        integer, intent(in) :: row
        character(len=:), allocatable :: s
        character(len=:), allocatable :: id
        id = peer_spec_field(row, 'id')
        select case (id)
        case ('lammps-2021-velocity-overlap', 'lammps-2021-velocity-force', 'lammps-2023-velocity-overlap', &
              'lammps-2023-velocity-force'); s = '`velocity`'
        case ('lammps-2021-mass_velocity-overlap', 'lammps-2021-mass_velocity-force', &
              'lammps-2023-mass_velocity-overlap', 'lammps-2023-mass_velocity-force'); s = '`mass_velocity`'
        case ('lammps-2021-viscoelastic-overlap', 'lammps-2021-viscoelastic-force', &
              'lammps-2023-viscoelastic-overlap', 'lammps-2023-viscoelastic-force'); s = '`viscoelastic`'
        case ('lammps-2021-tsuji-overlap', 'lammps-2023-tsuji-overlap', 'lammps-current-tsuji-overlap'); s = '`tsuji`'
        case ('lammps-2021-tsuji-force', 'lammps-2023-tsuji-force', 'lammps-current-tsuji-force')
            s = '`tsuji` + `limit_damping`'
        case ('lammps-2024-coeff_restitution-overlap'); s = '`coeff_restitution`'
        case ('lammps-2024-coeff_restitution-force'); s = '`coeff_restitution` + `limit_damping`'
        case ('liggghts-hertz-overlap'); s = '`model hertz`'
        case ('liggghts-hertz-force'); s = '`model hertz`, `limitForce on`'
        case ('liggghts-hertz_stiffness-overlap', 'liggghts-hertz_stiffness-force'); s = '`model hertz/stiffness`'
        case ('mercurydpm-restitution-overlap'); s = '`setEffectiveElasticModulusAndRestitutionCoefficient`'
        case ('mercurydpm-dissipation-overlap'); s = '`setDissipation`'
        case ('mercurydpm2015-dissipation-overlap'); s = '`HertzianViscoelasticSpecies` `setDissipation`'
        case ('mercurydpm2015-stiffness_restitution-overlap'); s = '`setStiffnessAndRestitutionCoefficient`'
        case ('yade-en-force', 'yade2023-en-force'); s = '`en`'
        case ('yade2024-vn-force'); s = '`en` + `vn`'
        case ('lammps-hertz_history-overlap', 'lammps-hertz_history-force'); s = '`gran/hertz/history`'
        case ('yade-betan-force'); s = '`betan` = beta(e)'
        case ('mfix-hertzian-overlap'); s = '`HERTZIAN`'
        case ('chrono-material-force'); s = 'Hertz, material properties'
        case ('chrono-kn_gn-force'); s = 'Hertz, `UseMaterialProperties(false)`'
        case default; s = id
        end select
    end function short_option

    !> A row's version, short: by the first of these prefixes its id starts with.
    function short_version(row) result(s)
        integer, intent(in) :: row
        character(len=:), allocatable :: s
        character(len=*), parameter :: prefix(14) = [character(len=20) :: 'lammps-2021-', 'lammps-2023-', &
            'lammps-current-', 'lammps-2024-', 'liggghts', 'mercurydpm2015', 'mercurydpm', 'lammps-hertz_history', &
            'yade2023', 'yade2024', 'yade-betan-force', 'yade', 'mfix', 'chrono']
        character(len=*), parameter :: label(14) = [character(len=25) :: '29 Sep 2021', '28 Mar 2023 - 29 Aug 2024', &
            'current (07b704ca)', '27 Jun 2024 +', '3.8.0', 'Beta 2015', 'trunk 2018-2024', '29 Sep 2021 +', &
            '2023.02a +', '2024.02a +', '2020 trunk +', '2020-2022 trunk', '21.3.2', '9.0.1 - 2026']
        integer :: k
        s = ''
        do k = 1, size(prefix)
            if (index(peer_spec_field(row, 'id'), trim(prefix(k))) /= 1) cycle
            s = trim(label(k))
            return
        end do
    end function short_version

    !> The markdown tables of doc/peers.md (the text form of `check --table`).
    subroutine peer_table_lines(lines)
        type(text_string), allocatable, intent(out) :: lines(:)
        integer :: row, j, st, law, iend, k
        real(wp) :: e
        character(len=:), allocatable :: s
        integer, parameter :: laws(2) = [HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO]
        integer, parameter :: ends(2) = [HD_END_OVERLAP, HD_END_FORCE]
        allocate (lines(0))
        s = ''
        call add('Restitution coefficient achieved when the user writes the target e into the engine''s ' // &
                 'restitution input (`hertzdamp check --table`):')
        call add('')
        call add('| engine | version | option | law | end | gamma | e for 0.1 | 0.3 | 0.5 | 0.7 | 0.9 |')
        call add('| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |')
        do row = 1, peer_spec_count
            if (.not. restitution_row(row)) cycle
            s = '| ' // peer_spec_field(row, 'engine') // ' | ' // short_version(row) // ' | ' // short_option(row) // &
                ' | ' // hertzdamp_law_name(peer_row_law(row)) // ' | ' // peer_spec_field(row, 'end') // ' | `' // &
                peer_spec_field(row, 'alpha_expr') // '` |'
            do j = 1, size(table_targets)
                call row_achieved(row, table_targets(j), e, st)
                s = s // ' ' // cell(e, st) // ' |'
            end do
            call add(s)
        end do
        call add('')
        call add('Speed dependence of the other laws: the engine''s coefficient is chosen to give the target ' // &
                 'e exactly at u0; e at other impact speeds u (alpha ~ u^(-1/5) for ' // &
                 hertzdamp_law_name(HD_DAMPING_LINEAR) // ', u^(1/5) for ' // &
                 hertzdamp_law_name(HD_DAMPING_KUWABARA_KONO) // '):')
        call add('')
        call add('| law | end | used by | target e | u = u0/100 | u0/10 | u0 | 10 u0 | 100 u0 |')
        call add('| --- | --- | --- | --- | --- | --- | --- | --- | --- |')
        do k = 1, size(laws)
            law = laws(k)
            do iend = 1, size(ends)
                do j = 1, size(table_targets)
                    if (j == 1) then
                        s = '| ' // hertzdamp_law_name(law) // ' | ' // hertzdamp_end_name(ends(iend)) // ' | ' // &
                            used_by(law, ends(iend)) // ' | ' // fmt_short(table_targets(j), ROUND_TRIP) // ' |'
                    else
                        s = '| | | | ' // fmt_short(table_targets(j), ROUND_TRIP) // ' |'
                    end if
                    do row = 1, size(table_ratios)
                        call speed_achieved(law, ends(iend), table_targets(j), table_ratios(row), e, st)
                        s = s // ' ' // cell(e, st) // ' |'
                    end do
                    call add(s)
                end do
            end do
        end do
    contains
        subroutine add(line)
            character(len=*), intent(in) :: line
            lines = [lines, text_string(line)]
        end subroutine add
    end subroutine peer_table_lines

    !> The same tables as rows (for CSV and JSON): id, law, end, formula, target,
    !> speed_ratio, e (the program adds status).
    subroutine peer_table_report(t)
        type(peer_report), intent(out) :: t
        integer :: row, j, st, k, iend
        real(wp) :: e
        integer, parameter :: laws(2) = [HD_DAMPING_LINEAR, HD_DAMPING_KUWABARA_KONO]
        integer, parameter :: ends(2) = [HD_END_OVERLAP, HD_END_FORCE]
        call t%set_columns('id,law,end,formula,target,speed_ratio,e')
        call t%meta('table', 'e achieved: restitution rows at their target; speed-dependent laws at u = ratio u0 ' // &
                    'with the coefficient exact at u0')
        do row = 1, peer_spec_count
            if (.not. restitution_row(row)) cycle
            do j = 1, size(table_targets)
                call row_achieved(row, table_targets(j), e, st)
                call put(peer_spec_field(row, 'id'), peer_row_law(row), peer_row_end(row), &
                         peer_spec_field(row, 'alpha_expr'), table_targets(j), 1.0_wp, e, st)
            end do
        end do
        do k = 1, size(laws)
            do iend = 1, size(ends)
                do j = 1, size(table_targets)
                    do row = 1, size(table_ratios)
                        call speed_achieved(laws(k), ends(iend), table_targets(j), table_ratios(row), e, st)
                        call put(hertzdamp_law_name(laws(k)) // '-' // hertzdamp_end_name(ends(iend)), laws(k), ends(iend), &
                                 'calibrated at u0', table_targets(j), table_ratios(row), e, st)
                    end do
                end do
            end do
        end do
    contains
        subroutine put(id, law, iend, formula, target, ratio, e, st)
            character(len=*), intent(in) :: id, formula
            integer, intent(in) :: law, iend, st
            real(wp), intent(in) :: target, ratio, e
            call t%str(id)
            call t%str(hertzdamp_law_name(law))
            call t%str(hertzdamp_end_name(iend))
            call t%str(formula)
            call t%num(target)
            call t%num(ratio)
            if (st == HD_OK .or. st == HD_NO_REBOUND) then
                call t%num(e)
                call t%end_row(st, '')
            else
                call t%num(peer_nan())
                call t%end_row(HD_NO_CONVERGENCE, 'no result for ' // id)
            end if
        end subroutine put
    end subroutine peer_table_report

end module hertzdamp_check_table
