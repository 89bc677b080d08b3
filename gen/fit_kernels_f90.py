#!/usr/bin/env python3
"""Write src/hertzdamp_fit_kernels.f90: the evaluation kernels of the fit, one named
procedure per instance, from the maps and degrees of data/fit_coefficients.csv.

Deterministic (same CSV -> same bytes), python3 standard library only.
Usage: fit_kernels_f90.py CSV F90     (F90 = '-' writes to stdout)
`make fit-source` runs it after gen/fit_csv_to_f90.py; test/docs/cli_sync_fit.sh checks
that the committed file is what it writes.

Why generated: a kernel is a loop whose body must be one straight piece of code (no call
the compiler could leave out of line, no branch) for the loop to vectorise, and the same
operations must run in every entry point so that they give the same bits.  The operations
are written once here, as Fortran text:
  ARITHMETIC          -ln x, x^(1/3), x^(1/5), exp(-x) in plain arithmetic (no libm),
  estrin_expr()       a polynomial of the fit's degree by Estrin's scheme,
  inverse_body()      the inverse e -> (alpha, tau_c) of one contact end and damping law,
  forward_body()      the forward map alpha -> (e, tau_c, z_max, tau_max) of one end,
and expanded into the instances below, each a named procedure that a reader can follow
from top to bottom (before, 14 fragments included into each other six deep expanded to
9,526 lines; the evaluation order of every operation is the same, so are the bits:
tools/fit_bits.sh).

Instances (the fewer, the faster the build; each choice keeps the bits):
- one masked loop per inverse kernel (INVERSE_KERNELS: linear, tsuji, kuwabara-kono x
  overlap, force) for the array calls, and the same body for one value (kernel_inverse_one)
  for the scalar calls: through the loop with n = 1 (a call more, the loop's set-up, the
  kernel chosen twice) a scalar inverse cost 14 % more than with the fused scalar code of
  f991267 (doc/performance.md); with its own instance it costs no more.  The two instances
  are the same text (inverse_body), so they give the same bits (test_entry_points).
  k and d are not here: hertzdamp_pair computes them for every entry point.
- one procedure per contact end for one value of the forward map, which skips the
  logarithm of w where alpha <= 0.6 and the turning point unless asked for; the array
  form calls it per value (not vectorised: its two loops were a quarter of the build).

To add an inverse kernel (another law or end): a line in INVERSE_KERNELS (its code, law,
contact end, e_min and its variable and maps), then `make fit-source`; hertzdamp_fit
chooses it in inverse_kernel.
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fit_csv_to_f90 import MAPS, read_csv, families_of, write_source  # noqa: E402

GENERATOR = 'gen/fit_kernels_f90.py'
WIDTH = 100   # longest expression line before the indentation of its block (fortitude: 132 in all)

# ------------------------------------------------------------------ the kernels
# code, name, law, end, e_min parameter, kind, maps:
#   kind 'two':   one map of two components (alpha/L, tau_c) in family fam of variable var
#   kind 'exact': tsuji overlap: alpha/L = sqrt(5) / sqrt(pi^2 + L^2) exactly, tau_c of L
#   kind 'split': tsuji force: alpha/L of L and tau_c of L^(1/5), two maps of family one
# var: 'L', 'cbrt' (L^(1/3)), 'sqrt' (L^(1/2)), 'root5' (L^(1/5))
INVERSE_KERNELS = [
    (1, 'linear_overlap', 'linear', 'overlap', 'fit_e_min_overlap', 'two', ('inv', 'ov_inv', 'L')),
    (2, 'linear_force', 'linear', 'force', 'fit_e_min_force', 'two', ('inv', 'fo_inv', 'cbrt')),
    (3, 'tsuji_overlap', 'tsuji', 'overlap', 'fit_law_e_min', 'exact', ('one', 'ts_ov_inv_t', 'L')),
    (4, 'tsuji_force', 'tsuji', 'force', 'fit_law_e_min', 'split',
     (('one', 'ts_fo_inv_a', 'L'), ('one', 'ts_fo_inv_t', 'root5'))),
    (5, 'kuwabara_kono_overlap', 'kuwabara-kono', 'overlap', 'fit_law_e_min', 'two', ('linv', 'kk_ov_inv', 'L')),
    (6, 'kuwabara_kono_force', 'kuwabara-kono', 'force', 'fit_law_e_min', 'two', ('linv', 'kk_fo_inv', 'sqrt')),
]
VAR_TEXT = {'L': 'L', 'cbrt': 'L^(1/3)', 'sqrt': 'L^(1/2)', 'root5': 'L^(1/5)'}

# ------------------------------------------------------------------ Fortran text
# Each arithmetic kernel maps {x} to {y} inside a block of its own (its locals), to about
# one ulp, for the domain its public function states.
ARITHMETIC = {
    'neg_log': ('{y} = -ln {x}', '''\
block
    integer(int64) :: ix, big
    real(wp) :: m, k, f, s, z, z2, z4, r
    ix = transfer({x}, 0_int64)
    big = shiftr(sqrt2_mant_bits - iand(ix, mant_bits), 63)      ! 1 when m would exceed sqrt(2)
    m = transfer(ior(iand(ix, mant_bits), one_bits - shiftl(big, 52)), 1.0_wp)
    k = transfer(ior(shiftr(ix, 52) + big, two52_bits), 1.0_wp) - (two52 + 1023.0_wp)
    f = m - 1.0_wp
    s = f / (2.0_wp + f)
    z = s * s
    z2 = z * z
    z4 = z2 * z2
    r = ((log_c(1) + log_c(2) * z) + z2 * (log_c(3) + log_c(4) * z)) &
        + z4 * (((log_c(5) + log_c(6) * z) + z2 * (log_c(7) + log_c(8) * z)) &
        + z4 * (log_c(9) + log_c(10) * z))
    r = r * z
    {y} = (0.0_wp - k * ln2_hi) - (k * ln2_lo + (f - s * (f - r)))
end block'''),
    'cbrt': ('{y} = {x}^(1/3)', '''\
block
    integer(int64) :: ix, nz
    real(wp) :: k, q, r, m, w, g, g3
    ix = iand(transfer({x}, 0_int64), huge(ix))             ! -0 as +0 (and no overflow in -ix)
    nz = shifta(-ix, 63)                                    ! all ones when the argument > 0
    ix = ior(iand(ix, nz), iand(one_bits, not(nz)))         ! 0 -> 1 (no exceptions)
    k = transfer(ior(shiftr(ix, 52), two52_bits), 1.0_wp) - two52      ! biased exponent
    q = (((k + 0.5_wp) * third - 0.5_wp) + shifter) - shifter           ! floor(k / 3)
    r = k - 3.0_wp * q                                      ! 0, 1 or 2
    m = transfer(ior(iand(ix, mant_bits), one_bits), 1.0_wp)
    w = m * (1.0_wp + r + 0.5_wp * r * (r - 1.0_wp))       ! m 2^r, exact
    g = (1.0_wp + (m - 1.0_wp) * (cb_d1 + (m - cb_x1) * cb_d2)) * (1.0_wp + r * (cr_d1 + (r - 1.0_wp) * cr_d2))
    g3 = g * g * g
    g = g + g * (w - g3) / (2.0_wp * g3 + w)
    g3 = g * g * g
    g = g + g * (w - g3) / (2.0_wp * g3 + w)
    ! times 2^(q - 341) (the biased exponent is 3q + r), from its exponent field
    g = g * transfer(shiftl(transfer(q + (two52 + 682.0_wp), 0_int64) - two52_bits, 52), 1.0_wp)
    {y} = transfer(iand(transfer(g, 0_int64), nz), 1.0_wp)   ! 0 gives +0
end block'''),
    'root5': ('{y} = {x}^(1/5)', '''\
block
    integer(int64) :: ix, nz
    real(wp) :: k, q, r, m, w, g, g2, g5
    ix = iand(transfer({x}, 0_int64), huge(ix))             ! -0 as +0 (and no overflow in -ix)
    nz = shifta(-ix, 63)                                    ! all ones when the argument > 0
    ix = ior(iand(ix, nz), iand(one_bits, not(nz)))         ! 0 -> 1 (no exceptions)
    k = transfer(ior(shiftr(ix, 52), two52_bits), 1.0_wp) - two52      ! biased exponent
    q = (((k + 2.5_wp) * fifth - 0.5_wp) + shifter) - shifter           ! floor((k + 2) / 5)
    r = (k + 2.0_wp) - 5.0_wp * q                           ! 0, 1, 2, 3 or 4
    m = transfer(ior(iand(ix, mant_bits), one_bits), 1.0_wp)
    w = m * transfer(shiftl(transfer(r + two52, 0_int64) - two52_bits + 1023_int64, 52), 1.0_wp)   ! m 2^r, exact
    g = (1.0_wp + (m - 1.0_wp) * (r5_d1 + (m - r5_x1) * r5_d2)) &
        * (1.0_wp + r * (p5_d(1) + (r - 1.0_wp) * (p5_d(2) + (r - 2.0_wp) * (p5_d(3) + (r - 3.0_wp) * p5_d(4)))))
    g2 = g * g
    g5 = g2 * g2 * g
    g = g + g * (w - g5) / (3.0_wp * g5 + 2.0_wp * w)
    g2 = g * g
    g5 = g2 * g2 * g
    g = g + g * (w - g5) / (3.0_wp * g5 + 2.0_wp * w)
    ! times 2^(q - 205), from its exponent field q + 818
    g = g * transfer(shiftl(transfer(q + (two52 + 818.0_wp), 0_int64) - two52_bits, 52), 1.0_wp)
    {y} = transfer(iand(transfer(g, 0_int64), nz), 1.0_wp)   ! 0 gives +0
end block'''),
    'exp_neg': ('{y} = exp(-{x})', '''\
block
    real(wp) :: xm, k, r, r2, r4, r8, p
    xm = 0.0_wp - {x}
    k = (xm * inv_ln2 + shifter) - shifter
    r = (xm - k * ln2_hi) - k * ln2_lo
    r2 = r * r
    r4 = r2 * r2
    r8 = r4 * r4
    p = (((exp_c(2) + exp_c(3) * r) + r2 * (exp_c(4) + exp_c(5) * r)) &
         + r4 * ((exp_c(6) + exp_c(7) * r) + r2 * (exp_c(8) + exp_c(9) * r))) &
        + r8 * ((exp_c(10) + exp_c(11) * r) + r2 * (exp_c(12) + exp_c(13) * r))
    p = 1.0_wp + (r + r2 * p)
    {y} = p * transfer(shiftl(transfer(k + shifter, 0_int64) - shifter_bits + 1023_int64, 52), 1.0_wp)
end block'''),
}

# The public functions of the arithmetic kernels: name, argument, result, domain, text.
ARITHMETIC_FUNCTIONS = [
    ('hertzdamp_fit_neg_log', 'neg_log', 'x', 'l', 'positive normal number',
     '-ln x of the fit kernels (x positive and normal; +0 at x = 1; about one ulp).'),
    ('hertzdamp_fit_cbrt', 'cbrt', 'x', 'y', '0 or a positive normal number',
     'x^(1/3) of the fit kernels (x = 0 or positive normal; about one ulp).'),
    ('hertzdamp_fit_root5', 'root5', 'x', 'y', '0 or a positive normal number',
     'x^(1/5) of the fit kernels (x = 0 or positive normal; about one ulp).'),
    ('hertzdamp_fit_exp_neg', 'exp_neg', 'l', 'y', '0 <= l <= 700',
     'exp(-l) of the fit kernels (0 <= l <= 700; about one ulp).'),
]

HEADER_DOC = '''\
!> The evaluation kernels of `hertzdamp_fit` (generated, see the header above): the loops
!> over n values that the compiler vectorises (SSE at -march=x86-64-v2, AVX2/AVX-512 with
!> -march=x86-64-v3/native) and that every entry point runs, so that a scalar call, an
!> elemental or array call, the C functions and the legacy externals give the same bits.
!>
!> No branch in a loop body: the piece of a fit is an index (`locate`), a fitted map is a
!> few loop-invariant numbers of hertzdamp_fit_data, invalid inputs are replaced by
!> harmless ones with integer masks (`outside`, `blend`) and flagged.  No call: the
!> logarithm, cube and fifth roots and exponential are the arithmetic kernels below, in
!> plain arithmetic, not libm's.  gfortran on glibc vectorises `log`, `exp` and `cbrt` in
!> such loops with libmvec (math-vector-fortran.h is pre-included), whose results differ
!> from the scalar libm in the last bit for about a quarter of the arguments: an array call
!> would then disagree with the scalar call.  The kernels are accurate to about one unit in
!> the last place (test/unit/test_fit.f90 checks them against quadruple precision), far below
!> the 1e-13 of the fits.  (sqrt is correctly rounded in scalar and vector form alike.)
!>
!> Procedures (each an instance of the text of gen/fit_kernels_f90.py):
!> - hertzdamp_fit_neg_log, _cbrt, _root5, _exp_neg: the arithmetic kernels alone;
!> - kernel_inverse_<law>_<end>(n, e, alpha, tau_c, status): the inverse e -> (alpha,
!>   tau_c), and kernel_inverse, which runs one by its code (kern_*);
!> - kernel_inverse_<law>_<end>_one(e, alpha, tau_c, status) and kernel_inverse_one: the
!>   same for one value (the same body text: the same bits), for the scalar calls;
!> - kernel_forward_<end>(alpha, turning, e, tau_c, status, z_max, tau_max): the forward
!>   map for one value.'''


def indent(text, n):
    """Every non-empty line of text indented by n spaces."""
    pad = ' ' * n
    return '\n'.join(pad + line if line else line for line in text.split('\n'))


def arithmetic(kind, x, y):
    """The block of an arithmetic kernel with its comment, from x to y (names that its
    block does not declare)."""
    what, text = ARITHMETIC[kind]
    declared = set()
    for line in text.split('\n'):
        if '::' in line:
            declared.update(n.strip() for n in line.split('::')[1].split(','))
    if x in declared or y in declared:
        raise SystemExit('arithmetic kernel %s: %s or %s is a local name of its block' % (kind, x, y))
    return '! ' + what.format(x=x, y=y) + '\n' + text.format(x=x, y=y)


def wrap(lhs, expr, width=WIDTH):
    """lhs = expr, continued over lines of at most `width` characters, each broken before
    the ' + ' of the fewest open parentheses that fits (the rightmost of those); the text,
    and so the order of evaluation, is unchanged."""
    first = lhs + ' = '
    cont = ' ' * len(first)
    lines, rest, lead = [], expr, first
    while len(lead) + len(rest) > width:
        best, depth = None, None
        level = 0
        for i, ch in enumerate(rest):
            if len(lead) + i > width:
                break
            if ch == '(':
                level += 1
            elif ch == ')':
                level -= 1
            elif rest.startswith(' + ', i) and i > 0 and (depth is None or level <= depth):
                best, depth = i, level
        if best is None:
            break
        lines.append(lead + rest[:best] + ' &')
        rest = rest[best + 1:]
        lead = cont
    lines.append(lead + rest)
    return '\n'.join(lines)


def estrin_expr(c, lo, hi):
    """sum_{j=lo}^{hi} c(j) t^(j-lo) by Estrin's scheme: the lower 2^k coefficients
    (2^k < hi - lo + 1 <= 2^(k+1)), plus t^(2^k) times the rest, each part in
    parentheses, recursively; c(j) is the text of coefficient j.  For 10 and 12
    coefficients this is the order of evaluation of the kernels before they were
    generated (issue 22), so the results keep their bits."""
    m = hi - lo + 1
    if m == 1:
        return c(lo)
    if m == 2:
        return '%s + %s * t' % (c(lo), c(lo + 1))
    p = 1
    while 2 * p < m:
        p *= 2
    return '(%s) + t%d * (%s)' % (estrin_expr(c, lo, lo + p - 1), p, estrin_expr(c, lo + p, hi))


def estrin(array, deg, comp, out):
    """out = the polynomial of degree deg of component comp of piece ip of `array`
    (array(0:deg, comp, ip)) at t, with the powers t2, t4, t8 declared by the caller."""
    return wrap(out, estrin_expr(lambda j: '%s(%d, %d, ip)' % (array, j, comp), 0, deg))


def powers(deg):
    """The powers of t that Estrin's scheme of degree deg uses, and their statements."""
    names, lines, p = [], [], 2
    while p <= deg:
        names.append('t%d' % p)
        lines.append('t%d = %s * %s' % (p, 't' if p == 2 else 't%d' % (p // 2), 't' if p == 2 else 't%d' % (p // 2)))
        p *= 2
    return names, lines


def polynomial(fam, deg, ncomp, outs, comment):
    """The block that evaluates the components of piece ip of family fam at t."""
    names, body = powers(deg)
    for k in range(ncomp):
        body.append(estrin('c_%s' % fam, deg, k + 1, outs[k]))
    return '! %s\nblock\n    real(wp) :: %s\n%s\nend block' % (comment, ', '.join(names), indent('\n'.join(body), 4))


def associated(text, fams):
    """text inside `associate (c_<fam> => fit_<fam>_c, ...)` for the coefficient families
    that its polynomials read: a reference to an element of a named constant array with a
    subscript that is not constant makes gfortran's front end expand the whole array
    constructor again (seconds of compile time for a few dozen references); through an
    associate name it does so once.  The same values, the same bits, no copy at run time."""
    names = ', '.join('c_%s => fit_%s_c' % (f, f) for f in fams)
    return 'associate (%s)\n%s\nend associate' % (names, indent(text, 4))


def locate(fam, m, v):
    """The call of locate for v on the grid of map m of family fam: piece ip, variable t."""
    return 'call locate(%s, fit_%s_x0(fit_map_%s), fit_%s_scale(fit_map_%s), &\n' \
           '            fit_%s_np(fit_map_%s), fit_%s_first(fit_map_%s), ip, t)' % (v, fam, m, fam, m, fam, m, fam, m)


# ------------------------------------------------------------------ inverse
def inverse_body(kernel, degs, sub='(i)'):
    """The body of an inverse kernel, e(i) -> alpha(i), tau_c(i), status(i) in the loop of
    the array form (sub '(i)'), e -> alpha, tau_c, status in the one-value form (sub '')."""
    code, name, law, end, emin, kind, maps = kernel
    out = ['! keep: all ones where e is valid (e_min <= e <= 1; NaN is not); an invalid e is',
           '! replaced by 0.5, its outputs by 0.  elastic: all ones at e = 1 exactly, where tau_c(0)',
           '! is returned (not the polynomial\'s value)',
           'keep = keep_mask(outside(e{i}, emin_bits, one_bits))',
           'elastic = -shiftr(iand(ieor(transfer(e{i}, 0_int64), one_bits), huge(keep)) - 1_int64, 63)',
           'x = blend(keep, e{i}, 0.5_wp)',
           arithmetic('neg_log', 'x', 'l')]
    if kind == 'two':
        fam, m, var = maps
        if var == 'L':
            out.append('v = l')
        elif var == 'cbrt':
            out.append(arithmetic('cbrt', 'l', 'v'))
        elif var == 'sqrt':
            out.append('v = sqrt(l)')
        else:
            raise SystemExit('unknown variable ' + var)
        out.append('! alpha/L and tau_c of %s (map %s)' % (VAR_TEXT[var], m))
        out.append(locate(fam, m, 'v'))
        out.append(polynomial(fam, degs[fam], 2, ['a', 'p2'], 'the two components of the piece'))
    elif kind == 'exact':
        fam, m, var = maps
        out.append('! alpha/L exactly: sqrt(5) / sqrt(pi^2 + L^2) (Antypov & Elliott 2011); tau_c of L (map %s)' % m)
        out.append('a = sqrt5 / sqrt(pi_sq + l * l)')
        out.append(locate(fam, m, 'l'))
        out.append(polynomial(fam, degs[fam], 1, ['p2'], 'tau_c'))
    elif kind == 'split':
        (fa, ma, va), (ft, mt, vt) = maps
        if va != 'L' or vt != 'root5':
            raise SystemExit('kernel %s: unexpected variables' % name)
        out.append('! alpha/L of L (map %s)' % ma)
        out.append(locate(fa, ma, 'l'))
        out.append(polynomial(fa, degs[fa], 1, ['a'], 'alpha/L'))
        out.append(arithmetic('root5', 'l', 'v'))
        out.append('! tau_c of L^(1/5) (map %s)' % mt)
        out.append(locate(ft, mt, 'v'))
        out.append(polynomial(ft, degs[ft], 1, ['p2'], 'tau_c'))
    else:
        raise SystemExit('unknown kernel kind ' + kind)
    out += ['alpha{i} = blend(keep, l * a, 0.0_wp)',
            'tau_c{i} = blend(keep, blend(elastic, tau_c0, p2), 0.0_wp)',
            'status{i} = int(iand(not(keep), int(HD_BAD_RESTITUTION, int64)))']
    return '\n'.join(out).replace('{i}', sub)


def inverse_procedure(kernel, degs, one=False):
    """The array form of an inverse kernel (a loop over n values), or with `one` its form
    for one value: the same body text (inverse_body), so the same operations and bits."""
    code, name, law, end, emin, kind, maps = kernel
    if kind == 'split':
        what = 'alpha/L of L, tau_c of L^(1/5)'
    elif kind == 'exact':
        what = 'alpha exact, tau_c of L'
    else:
        what = 'alpha/L and tau_c of %s' % VAR_TEXT[maps[2]]
    local = 'x, l, v, t, a, p2' if kind != 'exact' else 'x, l, t, a, p2'
    if one:
        head = '''\
!> Inverse kernel %d for one value (kernel_inverse_%s's body, the same bits).
pure elemental subroutine kernel_inverse_%s_one(e, alpha, tau_c, status)
    real(wp), intent(in) :: e           !! restitution coefficient
    real(wp), intent(out) :: alpha      !! damping parameter
    real(wp), intent(out) :: tau_c      !! dimensionless contact duration
    integer, intent(out) :: status      !! HD_OK or HD_BAD_RESTITUTION
    integer(int64), parameter :: emin_bits = transfer(%s, 0_int64)
    real(wp) :: %s
    integer(int64) :: keep, elastic
    integer :: ip
''' % (code, name, name, emin, local)
        body = inverse_body(kernel, degs, '')
        tail = '\nend subroutine kernel_inverse_%s_one' % name
    else:
        head = '''\
!> Inverse kernel %d: the %s law, %s end (%s; L = -ln e), for n
!> restitution coefficients: alpha, tau_c and HD_OK where %s <= e <= 1, else 0, 0 and
!> HD_BAD_RESTITUTION.
pure subroutine kernel_inverse_%s(n, e, alpha, tau_c, status)
    integer, intent(in) :: n            !! number of values
    real(wp), intent(in) :: e(n)        !! restitution coefficients
    real(wp), intent(out) :: alpha(n)   !! damping parameters
    real(wp), intent(out) :: tau_c(n)   !! dimensionless contact durations
    integer, intent(out) :: status(n)   !! HD_OK or HD_BAD_RESTITUTION
    integer(int64), parameter :: emin_bits = transfer(%s, 0_int64)
    real(wp) :: %s
    integer(int64) :: keep, elastic
    integer :: i, ip
''' % (code, law, end, what, emin, name, emin, local)
        body = 'do i = 1, n\n%s\nend do' % indent(inverse_body(kernel, degs), 4)
        tail = '\nend subroutine kernel_inverse_%s' % name
    fams = sorted({maps[0]} if kind != 'split' else {maps[0][0], maps[1][0]})
    return head + indent(associated(body, fams), 4) + tail


def inverse_dispatch(one=False):
    """kernel_inverse (n values) or kernel_inverse_one (one value): the kernel of a code."""
    if one:
        lines = ['!> The inverse kernel of code ikern for one value (kern_*; HD_BAD_END and zero outputs',
                 '!> for another code): the scalar calls\' entry, the same bits as kernel_inverse.',
                 'pure elemental subroutine kernel_inverse_one(ikern, e, alpha, tau_c, status)',
                 '    integer, intent(in) :: ikern        !! kernel code, kern_*',
                 '    real(wp), intent(in) :: e           !! restitution coefficient',
                 '    real(wp), intent(out) :: alpha      !! damping parameter',
                 '    real(wp), intent(out) :: tau_c      !! dimensionless contact duration',
                 '    integer, intent(out) :: status      !! HD_OK or HD_BAD_RESTITUTION']
        args, suffix, what = 'e, alpha, tau_c, status', '_one', 'kernel_inverse_one'
    else:
        lines = ['!> The inverse kernel of code ikern (kern_*; HD_BAD_END and zero outputs for another code).',
                 'pure subroutine kernel_inverse(ikern, n, e, alpha, tau_c, status)',
                 '    integer, intent(in) :: ikern        !! kernel code, kern_*',
                 '    integer, intent(in) :: n            !! number of values',
                 '    real(wp), intent(in) :: e(n)        !! restitution coefficients',
                 '    real(wp), intent(out) :: alpha(n)   !! damping parameters',
                 '    real(wp), intent(out) :: tau_c(n)   !! dimensionless contact durations',
                 '    integer, intent(out) :: status(n)   !! HD_OK or HD_BAD_RESTITUTION']
        args, suffix, what = 'n, e, alpha, tau_c, status', '', 'kernel_inverse'
    lines.append('    select case (ikern)')
    for code, name, *_ in INVERSE_KERNELS:
        lines.append('    case (kern_%s)' % name)
        lines.append('        call kernel_inverse_%s%s(%s)' % (name, suffix, args))
    lines += ['    case default',
              '        alpha = 0.0_wp',
              '        tau_c = 0.0_wp',
              '        status = HD_BAD_END',
              '    end select',
              'end subroutine %s' % what]
    return '\n'.join(lines)


# ------------------------------------------------------------------ fused with k, d
LAW_CODE = {'linear': 'HD_DAMPING_LINEAR', 'tsuji': 'HD_DAMPING_TSUJI', 'kuwabara-kono': 'HD_DAMPING_KUWABARA_KONO'}


def fused_procedure(kernel, degs):
    """Inverse kernel fused with the kd formula block, for a pass whose values are all valid
    (e_min <= e <= 1; T_c, m, u in the direct range): one loop e, T_c, m, u -> alpha, tau_c,
    status, k, d, flags, the body of inverse_body and then the two statements of the loop of
    hertzdamp_pair's contacts_kd, with the masks constant (keep all ones, flags 0: every
    blend the identity, so the same bits as the masked kernel followed by contacts_kd; the
    compiler folds the masks away).  A pass with an invalid value returns done = .false.
    and nothing else (the caller takes the masked kernel and contacts_kd)."""
    code, name, law, end, emin, kind, maps = kernel
    local = 'x, l, v, t, a, p2' if kind != 'exact' else 'x, l, t, a, p2'
    head = """\
!> Inverse kernel %d fused with the direct k, d formulas (direct_kd of
!> hertzdamp_kd_formula.inc, as hertzdamp_pair)
!> for n values all valid: alpha, tau_c, status as kernel_inverse_%s, then
!> k, d and the flags (0) of contacts_kd, in one loop; done = .false. and no outputs when a
!> value is invalid (e outside [e_min, 1], or T_c, m or u outside the direct range).
pure subroutine kernel_invert_kd_%s(n, e, tc, m, u, alpha, tau_c, status, k, d, flags, done)
    integer, intent(in) :: n            !! number of values
    real(wp), intent(in) :: e(n)        !! restitution coefficients
    real(wp), intent(in) :: tc(n)       !! contact times [s]
    real(wp), intent(in) :: m(n)        !! effective masses [kg]
    real(wp), intent(in) :: u(n)        !! impact velocities [m s^-1]
    real(wp), intent(out) :: alpha(n)   !! damping parameters
    real(wp), intent(out) :: tau_c(n)   !! dimensionless contact durations
    integer, intent(out) :: status(n)   !! HD_OK
    real(wp), intent(out) :: k(n)       !! stiffnesses of the direct formulas
    real(wp), intent(out) :: d(n)       !! damping coefficients of the direct formulas
    integer(int64), intent(out) :: flags(n) !! 0: every value served by the direct formulas
    logical, intent(out) :: done        !! every value valid, the outputs set
    integer(int64), parameter :: emin_bits = transfer(%s, 0_int64)
    real(wp) :: %s
    integer(int64) :: keep, elastic, valid
    integer :: i, ip
""" % (code, name, name, emin, local)
    body = inverse_body(kernel, degs) + '''
! k and d: the statements of the loop of hertzdamp_pair's contacts_kd (flags 0: all valid)
flags(i) = 0_int64
call direct_kd(%s, alpha(i), direct_harmless(tau_c(i), flags(i)), &
               direct_harmless(tc(i), flags(i)), direct_harmless(m(i), flags(i)), &
               direct_harmless(u(i), flags(i)), k(i), d(i))''' % LAW_CODE[law]
    mask_e = 'keep = keep_mask(outside(e(i), emin_bits, one_bits))'
    if body.count(mask_e) != 1:
        raise SystemExit('kernel %s: the mask of e not found' % name)
    body = body.replace(mask_e, 'keep = -1_int64   ! all valid')
    fams = sorted({maps[0]} if kind != 'split' else {maps[0][0], maps[1][0]})
    text = '\n'.join([
        '! the sign bit of the or of the masks of e and of contacts_kd: an invalid value',
        'valid = 0_int64',
        'do i = 1, n',
        '    valid = ior(valid, ior(outside(e(i), emin_bits, one_bits), direct_flags(0, tc(i), m(i), u(i))))',
        'end do',
        'done = valid >= 0_int64',
        'if (.not. done) return',
        'do i = 1, n\n%s\nend do' % indent(body, 4)])
    return head + indent(associated(text, fams), 4) + '\nend subroutine kernel_invert_kd_%s' % name


def fused_dispatch():
    """kernel_invert_kd: the fused kernel of a code (another code: done = .false.)."""
    lines = ['!> The fused kernel of code ikern for n values all valid (done = .false. and no outputs',
             '!> when a value is invalid, or for another code).',
             'pure subroutine kernel_invert_kd(ikern, n, e, tc, m, u, alpha, tau_c, status, k, d, flags, done)',
             '    integer, intent(in) :: ikern        !! kernel code, kern_*',
             '    integer, intent(in) :: n            !! number of values',
             '    real(wp), intent(in) :: e(n)        !! restitution coefficients',
             '    real(wp), intent(in) :: tc(n)       !! contact times [s]',
             '    real(wp), intent(in) :: m(n)        !! effective masses [kg]',
             '    real(wp), intent(in) :: u(n)        !! impact velocities [m s^-1]',
             '    real(wp), intent(out) :: alpha(n)   !! damping parameters',
             '    real(wp), intent(out) :: tau_c(n)   !! dimensionless contact durations',
             '    integer, intent(out) :: status(n)   !! HD_OK',
             '    real(wp), intent(out) :: k(n)       !! stiffnesses of the direct formulas',
             '    real(wp), intent(out) :: d(n)       !! damping coefficients of the direct formulas',
             '    integer(int64), intent(out) :: flags(n) !! 0: every value served by the direct formulas',
             '    logical, intent(out) :: done        !! every value valid, the outputs set',
             '    select case (ikern)']
    for code, name, *_ in INVERSE_KERNELS:
        lines.append('    case (kern_%s)' % name)
        lines.append('        call kernel_invert_kd_%s(n, e, tc, m, u, alpha, tau_c, status, k, d, flags, done)' % name)
    lines += ['    case default',
              '        done = .false.',
              '    end select',
              'end subroutine kernel_invert_kd']
    return '\n'.join(lines)

# ------------------------------------------------------------------ forward
def forward_body(end, degs):
    """The forward map of one contact end for one alpha -> e, tau_c, status, z_max,
    tau_max, skipping the logarithm of w where alpha <= 0.6 (overlap) and the turning point
    unless `turning` (skipped values are the ones the masks would discard: the same bits)."""
    ain, o = 'alpha', dict(e='e', t='tau_c', s='status', z='z_max', m='tau_max')
    fd, td = degs['fwd'], degs['turn']
    out = ['! status by priority: not finite (HD_BAD_ALPHA), negative but not -0 (HD_OUTSIDE_VALIDITY),',
           '! beyond the top of the range (beyond_code); keep: all ones where the map is evaluated',
           'mag = mag_bits(%s)' % ain,
           'beyond = not(le_mask(mag, top))',
           'bad = ior(iand(shifta(transfer(%s, 0_int64), 63), shifta(-mag, 63)), not(le_mask(mag, inf_bits - 1)))' % ain,
           '%s = int(iblend(bad, iblend(le_mask(mag, inf_bits - 1), int(HD_OUTSIDE_VALIDITY, int64), &' % o['s'],
           '                                 int(HD_BAD_ALPHA, int64)), iand(beyond, beyond_code)))',
           'keep = not(ior(bad, beyond))',
           'valid = not(bad)',
           'a = blend(keep, %s, 0.5_wp)' % ain]
    if end == 'overlap':
        # a branch, not the blend, where alpha is valid: its long chain (logarithm of w,
        # two polynomials) need not wait for the mask (measured: 6 % less time per call)
        out[-1:] = ['! (a branch where alpha is valid, the same value as the blend: the long chain that',
                    '! follows need not wait for the mask)',
                    'if (keep == -1_int64) then', '    a = %s' % ain, 'else',
                    '    a = blend(keep, %s, 0.5_wp)' % ain, 'end if']
    if end == 'force':
        out.append('! L/alpha and tau_c of alpha^(1/3) (map fo_fwd)')
        out.append(arithmetic('cbrt', 'a', 'v'))
        out.append(locate('fwd', 'fo_fwd', 'v'))
        out.append(polynomial('fwd', fd, 2, ['p1', 'p2'], 'the two components of the piece'))
        out.append('l = a * p1')
    else:
        out.append('! alpha <= x1 (sel): L/alpha and tau_c of alpha (map ov_fwd_a); beyond: L and tau_c of')
        out.append('! w = -ln(1 - alpha/alpha_c) (map ov_fwd_w), continued linearly beyond its fitted range')
        out.append('sel = le_mask(mag_bits(a), transfer(fit_fwd_x1(fit_map_ov_fwd_a), 0_int64))')
        x = 'x = 1.0_wp - a / fit_alpha_c\n' + arithmetic('neg_log', 'x', 'w')
        out.append('if (sel /= 0_int64) then')
        out.append('    w = 0.0_wp                           ! w is not used')
        out.append('else')
        out.append(indent(x, 4))
        out.append('end if')
        out.append('call locate(blend(sel, a, w), blend(sel, fit_fwd_x0(fit_map_ov_fwd_a), fit_fwd_x0(fit_map_ov_fwd_w)), &')
        out.append('            blend(sel, fit_fwd_scale(fit_map_ov_fwd_a), fit_fwd_scale(fit_map_ov_fwd_w)), &')
        out.append('            int(iblend(sel, int(fit_fwd_np(fit_map_ov_fwd_a), int64), int(fit_fwd_np(fit_map_ov_fwd_w), int64))), &')
        out.append('            int(iblend(sel, int(fit_fwd_first(fit_map_ov_fwd_a), int64), &')
        out.append('                       int(fit_fwd_first(fit_map_ov_fwd_w), int64))), ip, t)')
        out.append(polynomial('fwd', fd, 2, ['p1', 'p2'], 'the two components of the piece'))
        out.append('tail = not(le_mask(mag_bits(w), transfer(fit_fwd_x1(fit_map_ov_fwd_w), 0_int64)))')
        out.append('tw = w - fit_fwd_x1(fit_map_ov_fwd_w)')
        out.append('l = blend(sel, a * p1, blend(tail, fit_ov_fwd_lw_end + fit_ov_fwd_lw_slope * tw, p1))')
        out.append('p2 = blend(sel, p2, blend(tail, fit_ov_fwd_tw_end + fit_ov_fwd_tw_slope * tw, p2))')
    out.append('tau_f = p2')
    out.append('in_fit = valid')
    turn = ['! turning point: the force end where the forward map is valid; the overlap end for',
            '! every finite alpha >= 0 (also without rebound) up to the end of its fit (1.3).',
            '! Where the turning-point map has the grid of the forward map (force; overlap for',
            '! alpha <= 0.6) it takes the same piece and local variable.']
    if end == 'force':
        turn += ['valid = keep',
                 'ip = ip - fit_fwd_first(fit_map_fo_fwd) + fit_turn_first(fit_map_fo_turn)']
    else:
        turn += ['valid = iand(valid, le_mask(mag, transfer(fit_turn_x1(fit_map_ov_turn_b), 0_int64)))',
                 'a = blend(valid, %s, 0.5_wp)' % ain,
                 'sel = le_mask(mag_bits(a), transfer(fit_turn_x1(fit_map_ov_turn_a), 0_int64))',
                 'tw = t',
                 'kip = ip - fit_fwd_first(fit_map_ov_fwd_a) + fit_turn_first(fit_map_ov_turn_a)']
        loc = locate('turn', 'ov_turn_b', 'a')
        turn += ['if (sel == 0_int64) then', indent(loc, 4), 'end if']
        turn += ['t = blend(sel, tw, t)',
                 'ip = int(iblend(sel, int(kip, int64), int(ip, int64)))']
    turn.append(polynomial('turn', td, 2, ['p1', 'p2'], 'z_max and tau_max'))
    turn += ['%s = blend(valid, p1, 0.0_wp)' % o['z'],
             '%s = blend(valid, p2, 0.0_wp)' % o['m']]
    out += ['if (turning) then', indent('\n'.join(turn), 4), 'else',
            '    %s = 0.0_wp' % o['z'], '    %s = 0.0_wp' % o['m'], 'end if']
    out += ['x = min(l, 700.0_wp)',
            arithmetic('exp_neg', 'x', 'y'),
            '%s = blend(keep, y, 0.0_wp)' % o['e'],
            '! no rebound (overlap, alpha >= alpha_c): tau_c = +inf; other failures: 0',
            '%s = blend(keep, tau_f, blend(in_fit, pos_inf, 0.0_wp))' % o['t']]
    return '\n'.join(out)


FORWARD_RANGE = {
    'overlap': ('transfer(fit_alpha_c, 0_int64) - 1_int64', 'HD_NO_REBOUND',
                'alpha_c - 1 ulp, HD_NO_REBOUND beyond (e = 0, tau_c = +inf)'),
    'force': ('transfer(fit_alpha_max_force, 0_int64)', 'HD_OUTSIDE_VALIDITY',
              'alpha_max_force, HD_OUTSIDE_VALIDITY beyond'),
}


def forward_procedure(end, degs):
    top, code, text = FORWARD_RANGE[end]
    if end == 'force':
        locals_ = ('    real(wp) :: a, v, x, y, l, t, p1, p2, tau_f\n'
                   '    integer(int64) :: mag, beyond, bad, keep, valid, in_fit\n'
                   '    integer :: ip\n')
    else:
        locals_ = ('    real(wp) :: a, w, x, y, l, t, tw, p1, p2, tau_f\n'
                   '    integer(int64) :: mag, beyond, bad, keep, valid, sel, tail, in_fit\n'
                   '    integer :: ip, kip\n')
    params = ('    integer(int64), parameter :: top = %s\n'
              '    integer(int64), parameter :: beyond_code = %s\n' % (top, code))
    return '''\
!> The forward map of the %s end for one alpha, e, tau_c, status and, with `turning`,
!> z_max and tau_max (else 0); top of the range: %s.  Invalid alpha is
!> replaced by 0.5 and its outputs masked (no branch on it); skipped: the logarithm of w
!> where alpha <= 0.6 (overlap), the turning point unless `turning`.
pure subroutine kernel_forward_%s(alpha, turning, e, tau_c, status, z_max, tau_max)
    real(wp), intent(in) :: alpha         !! damping parameter
    logical, intent(in) :: turning        !! whether z_max and tau_max are wanted
    real(wp), intent(out) :: e            !! restitution coefficient
    real(wp), intent(out) :: tau_c        !! dimensionless contact duration
    integer, intent(out) :: status        !! HD_OK, HD_NO_REBOUND or an error
    real(wp), intent(out) :: z_max        !! deepest overlap (units of u_in t*)
    real(wp), intent(out) :: tau_max      !! time of deepest overlap (units of t*)
%s%s%s
end subroutine kernel_forward_%s''' % (end, text, end, params, locals_,
                                    indent(associated(forward_body(end, degs), ['fwd', 'turn']), 4), end)


# ------------------------------------------------------------------ fixed text
CONSTANTS = '''\
! ---- codes of the inverse kernels (kernel_inverse)
{codes}

! ---- IEEE double bit patterns (integer masks select values without branches)
integer(int64), parameter :: mant_bits = int(z'000FFFFFFFFFFFFF', int64)   ! fraction field
integer(int64), parameter :: one_bits = transfer(1.0_wp, 0_int64)
integer(int64), parameter :: inf_bits = int(z'7FF0000000000000', int64)   ! +infinity
integer(int64), parameter :: sqrt2_mant_bits = iand(transfer(sqrt(2.0_wp), 0_int64), mant_bits)
real(wp), parameter :: two52 = 2.0_wp**52
integer(int64), parameter :: two52_bits = transfer(two52, 0_int64)
real(wp), parameter :: shifter = 1.5_wp * two52   ! x + shifter - shifter rounds x to an integer
integer(int64), parameter :: shifter_bits = transfer(shifter, 0_int64)
real(wp), parameter :: pos_inf = transfer(inf_bits, 1.0_wp)

! ---- ln 2 in two parts: ln2_hi has 32 significant bits, so k ln2_hi is exact for |k| < 2^21
real(wp), parameter :: ln2 = log(2.0_wp)
real(wp), parameter :: ln2_hi = aint(ln2 * 2.0_wp**32) * 2.0_wp**(-32)
real(wp), parameter :: ln2_lo = real(log(2.0_real128) - real(ln2_hi, real128), wp)
real(wp), parameter :: inv_ln2 = 1.0_wp / ln2

integer :: j_
!> log(1 + f) = f - s (f - R(s^2)), s = f / (2 + f): R = s^2 sum_j 2/(2j + 1) s^(2j - 2),
!> the series of 2 atanh(s) - 2s; ten terms for |s| <= 3 - 2 sqrt(2) (f in
!> [sqrt(1/2) - 1, sqrt(2) - 1]), truncation below 2e-17 relative.
real(wp), parameter :: log_c(10) = [(2.0_wp / real(2 * j_ + 1, wp), j_ = 1, 10)]
!> exp(r) = 1 + r + sum_{j>=2} r^j / j!, |r| <= ln(2)/2: to j = 13, truncation below 5e-18.
real(wp), parameter :: exp_c(2:13) = [(1.0_wp / gamma(real(j_ + 1, wp)), j_ = 2, 13)]
!> First guess of m^(1/3) on [1, 2]: the quadratic through the exact cubes (1, 1),
!> (729/512, 9/8), (125/64, 5/4) in Newton form; times 2^(r/3), r = 0, 1, 2, from the
!> quadratic through (0, 1), (1, 2^(1/3)), (2, 2^(2/3)).  Relative error below 1e-3:
!> after two Halley steps only rounding is left.
real(wp), parameter :: cb_x1 = 729.0_wp / 512.0_wp, cb_x2 = 125.0_wp / 64.0_wp
real(wp), parameter :: cb_d1 = (1.125_wp - 1.0_wp) / (cb_x1 - 1.0_wp)
real(wp), parameter :: cb_d2 = ((1.25_wp - 1.125_wp) / (cb_x2 - cb_x1) - cb_d1) / (cb_x2 - 1.0_wp)
real(wp), parameter :: cbrt2 = 2.0_wp**(1.0_wp / 3.0_wp), cbrt4 = 4.0_wp**(1.0_wp / 3.0_wp)
real(wp), parameter :: cr_d1 = cbrt2 - 1.0_wp, cr_d2 = 0.5_wp * (cbrt4 - 2.0_wp * cbrt2 + 1.0_wp)
real(wp), parameter :: third = 1.0_wp / 3.0_wp
!> First guess of m^(1/5) on [1, 2]: the quadratic through the exact fifth powers (1, 1),
!> ((17/16)^5, 17/16), ((9/8)^5, 9/8) in Newton form; times 2^(r/5), r = 0 .. 4, from
!> the quartic through (j, 2^(j/5)) (its divided differences p5_d).  Relative error
!> below 1e-3: after two Halley steps only rounding is left.
real(wp), parameter :: r5_x1 = (17.0_wp / 16.0_wp)**5, r5_x2 = (9.0_wp / 8.0_wp)**5
real(wp), parameter :: r5_d1 = (17.0_wp / 16.0_wp - 1.0_wp) / (r5_x1 - 1.0_wp)
real(wp), parameter :: r5_d2 = ((9.0_wp / 8.0_wp - 17.0_wp / 16.0_wp) / (r5_x2 - r5_x1) - r5_d1) / (r5_x2 - 1.0_wp)
real(wp), parameter :: p5(0:4) = [(2.0_wp**(0.2_wp * j_), j_ = 0, 4)]
real(wp), parameter :: p5_d(4) = [p5(1) - p5(0), (p5(2) - 2.0_wp * p5(1) + p5(0)) / 2.0_wp, &
                                  (p5(3) - 3.0_wp * p5(2) + 3.0_wp * p5(1) - p5(0)) / 6.0_wp, &
                                  (p5(4) - 4.0_wp * p5(3) + 6.0_wp * p5(2) - 4.0_wp * p5(1) + p5(0)) / 24.0_wp]
real(wp), parameter :: fifth = 0.2_wp
!> alpha(e) of the tsuji overlap end: sqrt(5) L / sqrt(pi^2 + L^2) (Antypov & Elliott 2011)
real(wp), parameter :: sqrt5 = hertzdamp_alpha_c_tsuji, pi_sq = hertzdamp_pi**2'''

HELPERS = '''\
! ================================================================ masks and pieces

!> Sign bit set when x is outside [lo, hi] (0 < lo <= hi given by their bit
!> patterns); NaN, infinities and -0 are outside.  Integer arithmetic only (an
!> ordered floating-point comparison would keep the loops from vectorising under
!> the default -ftrapping-math), and no overflow: the sign bit is cleared first.
pure elemental integer(int64) function outside(x, lo_bits, hi_bits)
    real(wp), intent(in) :: x
    integer(int64), intent(in) :: lo_bits, hi_bits
    integer(int64) :: ix, dx
    ix = transfer(x, 0_int64)
    dx = iand(ix, huge(ix)) - lo_bits
    outside = ior(ix, ior(dx, (hi_bits - lo_bits) - dx))
end function outside

!> All ones where the sign bit of `flags` is clear, else zero.
pure elemental integer(int64) function keep_mask(flags)
    integer(int64), intent(in) :: flags
    keep_mask = not(shifta(flags, 63))
end function keep_mask

!> a where mask is all ones, b where it is zero (bitwise, no branch).
pure elemental real(wp) function blend(mask, a, b)
    integer(int64), intent(in) :: mask
    real(wp), intent(in) :: a, b
    blend = transfer(ior(iand(transfer(a, 0_int64), mask), iand(transfer(b, 0_int64), not(mask))), 1.0_wp)
end function blend

!> a where mask is all ones, b where it is zero (integers).
pure elemental integer(int64) function iblend(mask, a, b)
    integer(int64), intent(in) :: mask, a, b
    iblend = ior(iand(a, mask), iand(b, not(mask)))
end function iblend

!> All ones where x <= y, for x, y in [0, 2^63) (magnitudes of bit patterns).
pure elemental integer(int64) function le_mask(x, y)
    integer(int64), intent(in) :: x, y
    le_mask = not(shifta(y - x, 63))
end function le_mask

!> The magnitude of the bit pattern of x (-0 and +0 give 0).
pure elemental integer(int64) function mag_bits(x)
    real(wp), intent(in) :: x
    mag_bits = iand(transfer(x, 0_int64), huge(0_int64))
end function mag_bits

!> Global piece index and local variable t in [-1, 1] of v on a map's grid
!> (first piece, np pieces from x0 with np/(x1 - x0) = scale).  v beyond x1
!> extrapolates the last piece (t > 1), as the generator's convention implies.
pure elemental subroutine locate(v, x0, scale, np, first, ip, t)
    real(wp), intent(in) :: v, x0, scale
    integer, intent(in) :: np, first
    integer, intent(out) :: ip
    real(wp), intent(out) :: t
    real(wp) :: u
    integer :: i
    u = max(0.0_wp, (v - x0) * scale)
    i = int(min(u, real(np - 1, wp)))
    t = 2.0_wp * (u - real(i, wp)) - 1.0_wp
    ip = first + i
end subroutine locate'''


def arithmetic_functions():
    out = ['! ================================================================ arithmetic kernels',
           '! (-ln x, x^(1/3), x^(1/5), exp(-x): the text of the kernels below, as functions of',
           '! their own for the tests and the forward maps of hertzdamp_fit_laws)']
    for name, kind, x, y, domain, doc in ARITHMETIC_FUNCTIONS:
        out.append('')
        out.append('!> ' + doc)
        out.append('pure elemental real(wp) function %s(%s) result(%s)' % (name, x, y))
        out.append('    real(wp), intent(in) :: %s   !! %s' % (x, domain))
        out.append(indent(arithmetic(kind, x, y).split('\n', 1)[1], 4))
        out.append('end function %s' % name)
    return '\n'.join(out)


def check_maps(fams, blocks):
    """The kernels' assumptions about the maps: every map they name exists, in the family
    they read it from, and the turning-point maps that borrow the piece of a forward map
    have its grid."""
    where = {m: fam for fam, m, _ in MAPS}
    used = [('inv', 'ov_inv'), ('inv', 'fo_inv'), ('one', 'ts_ov_inv_t'), ('one', 'ts_fo_inv_a'),
            ('one', 'ts_fo_inv_t'), ('linv', 'kk_ov_inv'), ('linv', 'kk_fo_inv'), ('fwd', 'ov_fwd_a'),
            ('fwd', 'ov_fwd_w'), ('fwd', 'fo_fwd'), ('turn', 'ov_turn_a'), ('turn', 'ov_turn_b'),
            ('turn', 'fo_turn')]
    for fam, m in used:
        if where.get(m) != fam:
            raise SystemExit('map %s: not in family %s' % (m, fam))
    comps = {m: c for _, m, c in MAPS}
    for f, t in (('fo_fwd', 'fo_turn'), ('ov_fwd_a', 'ov_turn_a')):
        a, b = blocks[comps[f][0]], blocks[comps[t][0]]
        if (a['var'], float(a['x0']), float(a['x1']), a['np']) != (b['var'], float(b['x0']), float(b['x1']), b['np']):
            raise SystemExit('map %s does not have the grid of map %s (the forward kernels share its piece)' % (t, f))


def main(argv):
    if len(argv) != 3:
        sys.stderr.write('usage: fit_kernels_f90.py CSV F90\n')
        return 2
    src, dst = argv[1], argv[2]
    _, _, blocks, _ = read_csv(src)
    fams = families_of(blocks)
    check_maps(fams, blocks)
    degs = {fam: max(blocks[c]['deg'] for _, comps in maps for c in comps) for fam, maps in fams.items()}
    codes = '\n'.join('integer, parameter, public :: kern_%s = %d   !! %s law, %s end' % (k[1], k[0], k[2], k[3])
                      for k in INVERSE_KERNELS)
    out = ['! Generated by %s from %s (the maps and degrees of hertzdamp_fit_data); do not edit.' % (
               GENERATOR, os.path.relpath(src) if not os.path.isabs(src) else os.path.basename(src)),
           '! Regenerate with `make fit-source`; test/docs/cli_sync_fit.sh checks that this file is what it writes.',
           '! Settings: polynomials by Estrin\'s scheme, degrees %s; instances: one masked loop per' % (
               ', '.join('%s %d' % (f, degs[f]) for f in sorted(degs))),
           '! inverse kernel (%d) and its form for one value, one procedure per contact end for one value of the' % (
               len(INVERSE_KERNELS)),
           '! forward map.',
           '',
           HEADER_DOC,
           'module hertzdamp_fit_kernels',
           '    use hertzdamp_kinds, only: hertzdamp_rk',
           '    use hertzdamp_registry, only: HD_OK, HD_BAD_END, HD_BAD_ALPHA, HD_BAD_RESTITUTION, HD_OUTSIDE_VALIDITY, &',
           '                                HD_NO_REBOUND',
           '    use hertzdamp_constants, only: tau_c0 => hertzdamp_tau_c0_value, hertzdamp_pi, &',
           '                                   direct_lo => hertzdamp_direct_lo, direct_hi => hertzdamp_direct_hi',
           '    use hertzdamp_registry, only: HD_DAMPING_LINEAR, HD_DAMPING_TSUJI, HD_DAMPING_KUWABARA_KONO',
           '    use hertzdamp_laws, only: hertzdamp_alpha_c_tsuji',
           '    use hertzdamp_fit_data',
           '    use, intrinsic :: iso_fortran_env, only: int64, real128',
           '    implicit none',
           '    private',
           '',
           '    integer, parameter :: wp = hertzdamp_rk',
           '',
           indent(CONSTANTS.replace('{codes}', codes), 4),
           '',
           '    public :: hertzdamp_fit_neg_log, hertzdamp_fit_cbrt, hertzdamp_fit_root5, hertzdamp_fit_exp_neg',
           '    public :: kernel_inverse, kernel_inverse_one, kernel_invert_kd, kernel_forward_overlap, &',
           '              kernel_forward_force',
           '',
           'contains',
           '',
           indent(arithmetic_functions(), 4),
           '',
           indent(HELPERS, 4),
           '',
           '    ! ================================================================ inverse kernels',
           '']
    for k in INVERSE_KERNELS:
        out.append(indent(inverse_procedure(k, degs), 4))
        out.append('')
    out.append(indent(inverse_dispatch(), 4))
    out.append('')
    out.append('    ! ================================================================ inverse kernels for one value')
    out.append('')
    for k in INVERSE_KERNELS:
        out.append(indent(inverse_procedure(k, degs, one=True), 4))
        out.append('')
    out.append(indent(inverse_dispatch(one=True), 4))
    out.append('')
    out.append('    ! ================================================================ inverse kernels fused with k, d')
    out.append('')
    out.append("    include 'hertzdamp_kd_formula.inc'   ! direct_kd and the masks (one source with hertzdamp_pair)")
    out.append('')
    for k in INVERSE_KERNELS:
        out.append(indent(fused_procedure(k, degs), 4))
        out.append('')
    out.append(indent(fused_dispatch(), 4))
    out.append('')
    out.append('    ! ================================================================ forward kernels')
    for end in ('overlap', 'force'):
        out.append('')
        out.append(indent(forward_procedure(end, degs), 4))
    out.append('')
    out.append('end module hertzdamp_fit_kernels')
    text = '\n'.join(out) + '\n'
    # the names of hertzdamp_fit_data that the kernels read, listed in its use statement

    names = sorted(set(re.findall(r'\bfit_\w+', text.split('contains', 1)[1] + CONSTANTS)))
    lines, cur = [], '    use hertzdamp_fit_data, only: '
    for k, name in enumerate(names):
        item = name + (', ' if k < len(names) - 1 else '')
        if len(cur) + len(item) > 118:
            lines.append(cur.rstrip() + ' &')
            cur = ' ' * 34 + item
        else:
            cur += item
    lines.append(cur)
    text = text.replace('    use hertzdamp_fit_data\n', '\n'.join(lines) + '\n')
    write_source(text, dst)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
