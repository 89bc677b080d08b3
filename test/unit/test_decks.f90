!> Tests of the deck readers' tools and of their cost (packages/text, the script
!> interpreter hertzdamp_lmpscript and the engines' deck readers):
!> - the expression evaluator against exact values in the LAMMPS, Python and MFiX
!>   syntaxes, and its errors naming the culprit;
!> - the hash map: every key found, probes per operation bounded;
!> - the readers' work is linear in the deck: decks of n and 4n words (LAMMPS, LIGGGHTS,
!>   MFiX, Yade, and key=value words) cost 4 times the work, within 10 % (the work counts
!>   characters, words and hash-map probes; a quadratic reader would cost 16 times);
!> - the deck files are read whole: a line without a line end, CR LF line ends.
program test_decks
    use hertzdamp, only: hertzdamp_rk, hertzdamp_pi
    use hertzdamp_check_model, only: PEER_LAMMPS, PEER_LIGGGHTS, PEER_MFIX, PEER_YADE
    use hertzdamp_text_list, only: text_string, text_list
    use hertzdamp_text_map, only: text_map
    use hertzdamp_text_expr, only: text_vars, text_eval, SYNTAX_LAMMPS, SYNTAX_PYTHON, SYNTAX_MFIX
    use hertzdamp_text_file, only: text_read_lines
    use hertzdamp_check_common, only: kv_list, split_pairs
    use hertzdamp_check_scene, only: peer_scene
    use hertzdamp_check_whole, only: peer_read_scene
    use hertzdamp_text_format, only: itoa
    use hertzdamp_testing, only: test_suite, new_suite
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    integer, parameter :: wp = hertzdamp_rk

    type(test_suite) :: s
    character(len=:), allocatable :: dir

    s = new_suite('test_decks')
    dir = temp_dir()
    call test_eval()
    call test_map()
    call test_lines()
    call test_linear(PEER_LAMMPS, 'lammps')
    call test_linear(PEER_LIGGGHTS, 'liggghts')
    call test_linear(PEER_MFIX, 'mfix')
    call test_linear(PEER_YADE, 'yade')
    call test_words()
    call s%finish()

contains

    function temp_dir() result(d)
        character(len=:), allocatable :: d
        character(len=256) :: t
        integer :: n, st
        call get_environment_variable('TMPDIR', t, n, st)
        if (st /= 0 .or. n == 0) t = '/tmp'
        d = trim(t) // '/test_decks_'
    end function temp_dir

    ! ------------------------------------------------------------------ expressions

    subroutine expect(text, syntax, want, vars)
        character(len=*), intent(in) :: text
        integer, intent(in) :: syntax
        real(wp), intent(in) :: want
        type(text_vars), intent(inout) :: vars
        real(wp) :: x
        character(len=:), allocatable :: msg
        call text_eval(text, syntax, vars, x, msg)
        call s%check(len(msg) == 0 .and. x == want, 'eval "' // text // '" = exact value (' // msg // ')')
    end subroutine expect

    subroutine expect_err(text, syntax, word, vars)
        character(len=*), intent(in) :: text, word
        integer, intent(in) :: syntax
        type(text_vars), intent(inout) :: vars
        real(wp) :: x
        character(len=:), allocatable :: msg
        call text_eval(text, syntax, vars, x, msg)
        call s%check(index(msg, word) > 0 .and. x == 0.0_wp, 'eval "' // text // '": error names ' // word // ' (' // &
                     msg // ')')
    end subroutine expect_err

    subroutine test_eval()
        type(text_vars) :: v
        call v%set_num('a', 3.0_wp)
        call v%set_text('s', '2.5e-1')
        call v%set_text('word', 'granular')
        call expect('2^3^2', SYNTAX_LAMMPS, 512.0_wp, v)
        call expect('-2^2', SYNTAX_LAMMPS, -4.0_wp, v)
        call expect('1+2*3-4/2', SYNTAX_LAMMPS, 5.0_wp, v)
        call expect('v_a*2', SYNTAX_LAMMPS, 6.0_wp, v)
        call expect('a*s', SYNTAX_LAMMPS, 0.75_wp, v)
        call expect('(1<2)&&(3>=3)||!1', SYNTAX_LAMMPS, 1.0_wp, v)
        call expect('2==2.0', SYNTAX_LAMMPS, 1.0_wp, v)
        call expect('sqrt(16)+ln(1)+abs(-2)+max(1,7,3)-min(4,a)', SYNTAX_LAMMPS, 10.0_wp, v)
        call expect('log(1)+floor(2.7)+ceil(2.1)+round(2.5)', SYNTAX_LAMMPS, 8.0_wp, v)
        call expect('PI', SYNTAX_LAMMPS, hertzdamp_pi, v)
        call expect('7%3', SYNTAX_LAMMPS, 1.0_wp, v)
        call expect('2**10', SYNTAX_PYTHON, 1024.0_wp, v)
        call expect('math.sqrt(4)*math.pi/pi', SYNTAX_PYTHON, 2.0_wp, v)
        call expect('radians(180)', SYNTAX_PYTHON, hertzdamp_pi, v)
        call expect('pow(2,3)+True', SYNTAX_PYTHON, 9.0_wp, v)
        call expect('1.0d2/4', SYNTAX_MFIX, 25.0_wp, v)
        call expect('2**3', SYNTAX_MFIX, 8.0_wp, v)
        call expect('.5e1', SYNTAX_LAMMPS, 5.0_wp, v)
        call expect_err('b+1', SYNTAX_LAMMPS, '"b"', v)
        call expect_err('word*2', SYNTAX_LAMMPS, 'no numeric value', v)
        call expect_err('1/0', SYNTAX_LAMMPS, 'division by zero', v)
        call expect_err('(1+2', SYNTAX_LAMMPS, 'missing )', v)
        call expect_err('sqrt(-1)', SYNTAX_LAMMPS, 'outside its domain', v)
        call expect_err('ramp(1,2)', SYNTAX_LAMMPS, 'ramp', v)
        call expect_err('2^3', SYNTAX_PYTHON, 'unexpected', v)
        call expect_err('1e5x', SYNTAX_LAMMPS, 'unexpected', v)
    end subroutine test_eval

    ! ------------------------------------------------------------------ hash map

    subroutine test_map()
        type(text_map) :: m
        integer :: i, n, bad, v, w
        n = 100000
        do i = 1, n
            call m%put('key' // itoa(i), i)
        end do
        call m%put('key7', 77)
        bad = 0
        do i = 1, n
            v = m%get('key' // itoa(i))
            if (i /= 7 .and. v /= i) bad = bad + 1
        end do
        v = m%get('key7')
        w = m%get('nokey')
        call s%check(bad == 0 .and. v == 77 .and. w == 0 .and. m%find('key9') == 9, &
                     'map: 1e5 keys found, a key set twice keeps the last value, an absent key gives 0')
        call s%check(m%n == n, 'map: 1e5 entries')
        call s%check(real(m%probes, wp) / (3 * n) < 4.0_wp, 'map: fewer than 4 probes per operation on average (' // &
                     itoa(int(m%probes)) // ' for ' // itoa(3 * n) // ')')
    end subroutine test_map

    ! ------------------------------------------------------------------ lines

    subroutine test_lines()
        type(text_list) :: lines
        character(len=:), allocatable :: msg, path
        integer(int64) :: work
        integer :: u
        path = dir // 'lines.txt'
        open (newunit=u, file=path, access='stream', form='unformatted', status='replace')
        write (u) 'one' // achar(13) // achar(10) // achar(10) // 'three'
        close (u)
        work = 0
        call text_read_lines(path, lines, msg, work)
        call s%check(len(msg) == 0 .and. lines%n == 3 .and. work == 11, 'lines: CR LF, an empty line, no final line end')
        if (lines%n == 3) call s%check(lines%item(1)%s == 'one' .and. lines%item(2)%s == '' .and. &
                                       lines%item(3)%s == 'three', 'lines: their text')
        call text_read_lines(dir // 'no such file', lines, msg, work)
        call s%check(index(msg, 'no such file') > 0, 'lines: a missing file is named')
        open (newunit=u, file=path, status='old')
        close (u, status='delete')
    end subroutine test_lines

    ! ------------------------------------------------------------------ linear work

    !> A deck of about n words in an engine's syntax (with n/4 definitions or
    !> assignments, so that lookups grow with the deck too).
    subroutine write_deck(peer, n, path)
        integer, intent(in) :: peer, n
        character(len=*), intent(in) :: path
        integer :: u, i
        open (newunit=u, file=path, status='replace', action='write')
        select case (peer)
        case (PEER_LAMMPS, PEER_LIGGGHTS)
            write (u, '(a)') 'units si'
            write (u, '(a)') 'create_box 1 box'
            write (u, '(a)') 'create_atoms 1 single 0 0 0'
            write (u, '(a)') 'variable v0 equal 1.0e-3'
            do i = 1, n / 4
                write (u, '(a)') 'variable v' // itoa(i) // ' equal ${v' // itoa(i - 1) // '}'
            end do
            if (peer == PEER_LAMMPS) then
                write (u, '(a)') 'set type 1 diameter ${v' // itoa(n / 4) // '}'
                write (u, '(a)') 'set type 1 density 2500'
                write (u, '(a)') 'pair_style granular'
                write (u, '(a)') 'pair_coeff * * hertz/material 1e8 0.5 0.3 damping tsuji'
            else
                write (u, '(a)') 'fix m1 all property/global youngsModulus peratomtype 5.e6'
                write (u, '(a)') 'fix m2 all property/global poissonsRatio peratomtype 0.45'
                write (u, '(a)') 'fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5'
                write (u, '(a)') 'pair_style gran model hertz tangential history'
                write (u, '(a)') 'fix p all particletemplate/sphere 15485863 atom_type 1 density constant 2500 ' // &
                                 'radius constant ${v' // itoa(n / 4) // '}'
            end if
            write (u, '(a)') 'timestep 1e-7'
        case (PEER_MFIX)
            write (u, '(a)') "MMAX = 1  SOLIDS_MODEL(1) = 'DEM'  D_P0(1) = 1e-3  RO_S0(1) = 2500"
            write (u, '(a)') "DES_COLL_MODEL = 'HERTZIAN'  E_YOUNG(1) = 1e7  V_POISSON(1) = 0.3"
            write (u, '(a)') "EW_YOUNG = 1e7  VW_POISSON = 0.3  DES_EN_INPUT(1) = 0.5  DES_ET_INPUT(1) = 0.5"
            write (u, '(a)') "DES_EN_WALL_INPUT(1) = 0.5"
            do i = 1, n / 4
                write (u, '(a)') '  IC_X_W(' // itoa(i) // ') = 0.0  IC_EP_G(' // itoa(i) // ') = 1.0'
            end do
        case default
            write (u, '(a)') 'mat = O.materials.append(FrictMat(young=1e7, poisson=0.3, density=2500))'
            write (u, '(a)') 'r0 = 1e-3'
            do i = 1, n / 4
                write (u, '(a)') 'r' // itoa(i) // ' = r' // itoa(i - 1) // ' * 1'
            end do
            write (u, '(a)') 'O.bodies.append(sphere((0, 0, 0), r' // itoa(n / 4) // ', material=mat))'
            write (u, '(a)') 'O.engines = [InteractionLoop([], [Ip2_FrictMat_FrictMat_MindlinPhys(en=0.5)], ' // &
                             '[Law2_ScGeom_MindlinPhys_Mindlin()]), NewtonIntegrator(damping=0)]'
            write (u, '(a)') 'O.dt = 1e-7'
        end select
        close (u)
    end subroutine write_deck

    !> The reader's work for decks of n and 4n words is in the ratio 4 (within 10 %);
    !> every deck is read (one contact at least).
    subroutine test_linear(peer, name)
        integer, intent(in) :: peer
        character(len=*), intent(in) :: name
        integer(int64) :: w(2)
        integer :: k, n, u
        type(peer_scene) :: scene
        character(len=:), allocatable :: msg, path
        path = dir // name // '.deck'
        do k = 1, 2
            n = 10000 * 4**(k - 1)
            call write_deck(peer, n, path)
            call peer_read_scene(peer, [text_string(path)], scene, msg)
            call s%check(len(msg) == 0 .and. scene%ncontacts >= 1, name // ': a deck of ' // itoa(n) // ' words is read (' // &
                         msg // ')')
            do u = 1, scene%notes%n      ! (MFiX counts its other keys in a note without a line)
                if (index(scene%notes%item(u)%s, path // ':') == 1) then
                    call s%check(.false., name // ': no line left uninterpreted, first: ' // scene%notes%item(u)%s)
                    exit
                end if
            end do
            w(k) = scene%work
        end do
        open (newunit=u, file=path, status='old')
        close (u, status='delete')
        print '(a, 2i12, f8.3)', name // ': work for 1e4 and 4e4 words, ratio ', w, real(w(2), wp) / real(w(1), wp)
        call s%check(abs(real(w(2), wp) / real(w(1), wp) - 4.0_wp) < 0.4_wp, name // ': work linear in the deck ' // &
                     '(ratio 4 within 10 % for 4 times the words)')
    end subroutine test_linear

    !> key=value words: the duplicate check and lookups by hash map (probes linear).
    subroutine test_words()
        type(kv_list) :: kv
        type(text_string), allocatable :: tok(:)
        character(len=:), allocatable :: msg
        integer(int64) :: p(2)
        integer :: k, n, i
        do k = 1, 2
            n = 10000 * 4**(k - 1)
            allocate (tok(n))
            do i = 1, n
                tok(i)%s = 'KEY' // itoa(i) // '=' // itoa(i)
            end do
            msg = ''
            call split_pairs(tok, .true., kv, msg)
            p(k) = kv%map%probes
            deallocate (tok)
        end do
        call s%check(len(msg) == 0 .and. abs(real(p(2), wp) / real(p(1), wp) - 4.0_wp) < 0.4_wp, &
                     'key=value words: duplicate check linear (probes ' // itoa(int(p(1))) // ', ' // itoa(int(p(2))) // ')')
    end subroutine test_words

end program test_decks
