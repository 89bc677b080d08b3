#!/usr/bin/env python3
"""Turn data/fit_coefficients.csv into the Fortran module src/hertzdamp_fit_data.f90.

Deterministic (same CSV -> same bytes), python3 standard library only.
Usage: fit_csv_to_f90.py CSV F90     (F90 = '-' writes to stdout)

The CSV (written by gen/fit/gen_fit.f90) has '#' comment lines (copied into the
module as comments) and rows
  param,NAME,VALUE
  block,NAME,VARIABLE,X0,X1,NP,DEG
  coef,NAME,PIECE,C_0,...,C_DEG
A block is one piecewise polynomial: piece i covers u = (x - X0) NP / (X1 - X0) in
[i, i+1], t = 2 (u - i) - 1, y = sum_j C_j t^j.

Layout of the module (what the SIMD kernels of src/hertzdamp_fit.f90 read):
- every param:  real(wp), parameter :: fit_NAME
- every block:  NAME_np, NAME_deg, NAME_x0, NAME_x1, NAME_scale = NP / (X1 - X0)
- a FITTED MAP is a set of blocks on one grid (same variable, X0, X1, NP) that are
  evaluated with one piece index: the alpha/L and tau_c blocks of one inverse, the
  L and tau_c blocks of one forward regime, ...  The maps of one FAMILY (the table
  MAPS below) are stored in one array
      fit_F_c(0:fit_F_deg, fit_F_ncomp, 0:fit_F_npieces - 1)
  with the components of a piece side by side and the pieces of all maps one after
  the other, so that a kernel reaches every coefficient of a contact through one
  piece index (a gather for the vectorised loops) and a map is only a few
  loop-invariant numbers:
      fit_map_M                  index of map M in its family
      fit_F_var(:), fit_F_first(:), fit_F_np(:), fit_F_x0(:), fit_F_x1(:), fit_F_scale(:)
  (variable code, first global piece, pieces, grid; one entry per map).  A family
  has one degree: blocks of lower degree are padded with zero coefficients, which
  changes no result (Horner or Estrin with leading zeros is exact).
- every block of the CSV belongs to a map (the conversion stops otherwise): code
  that evaluates a block reaches it through its map, never through a copy of its
  own (the derivatives of the maps are hertzdamp_fit_forward_deriv in the core).

The variable code of a block (column 3 of its CSV row) does not say which root a
'root' variable takes (code 2: L^(1/n), 5: alpha^(1/n); n = 3 linear, 5 tsuji,
2 kuwabara-kono, gen/fit/gen_fit.f90): the kernel that evaluates a map knows it
(the comments of MAPS name the variable of each map).

To add a fitted map (for instance for another damping law): let the generator write
its blocks to the CSV, add a line (family, map name, blocks) to MAPS (a new map
goes after the maps already in its family, so that their indices and pieces stay),
run `make fit-source`, and give the new map index to a kernel in hertzdamp_fit:
the inverse kernels are chosen by `inverse_kernel` (contact end and law), get a
case in hertzdamp_fit_invert_dispatch.inc and are written once in
hertzdamp_fit_inverse.inc (the variable of e and the map per kernel), with the law's
q in hertzdamp_fit_invert_out.inc; forward maps of the laws are evaluated (with
their derivatives) in hertzdamp_fit_laws.
"""
import sys

# family, map, blocks (the components of the family, in this order)
#   inv:  inverse maps of the linear law, components alpha/L and tau_c as functions of
#         L = -ln e (overlap) or L^(1/3) (force); degree 9
#   fwd:  forward maps of e and tau_c, components L/alpha (or L) and tau_c
#   turn: forward maps of the turning point, components z_max and tau_max
#   linv: inverse maps of the laws with both components on one grid: alpha/L and tau_c
#   one:  maps of one component (the tsuji inverse: its alpha/L and tau_c have different
#         variables, and alpha(e) of its overlap end is exact)
MAPS = [
    ('inv', 'ov_inv', ['ov_inv_a', 'ov_inv_t']),                   # linear overlap, of L
    ('inv', 'fo_inv', ['fo_inv_a', 'fo_inv_t']),                   # linear force, of L^(1/3)
    ('fwd', 'ov_fwd_a', ['ov_fwd_la', 'ov_fwd_ta']),               # linear overlap, of alpha <= 0.6
    ('fwd', 'ov_fwd_w', ['ov_fwd_lw', 'ov_fwd_tw']),               # linear overlap, of w = -ln(1 - alpha/alpha_c)
    ('fwd', 'fo_fwd', ['fo_fwd_la', 'fo_fwd_ta']),                 # linear force, of alpha^(1/3)
    ('turn', 'ov_turn_a', ['ov_fwd_za', 'ov_fwd_ma']),             # linear overlap, of alpha <= 0.6
    ('turn', 'ov_turn_b', ['ov_fwd_zb', 'ov_fwd_mb']),             # linear overlap, of alpha in [0.6, 1.3]
    ('turn', 'fo_turn', ['fo_fwd_za', 'fo_fwd_ma']),               # linear force, of alpha^(1/3)
    ('fwd', 'kk_ov_fwd', ['kk_ov_fwd_la', 'kk_ov_fwd_ta']),        # kuwabara-kono overlap, of alpha
    ('fwd', 'kk_fo_fwd', ['kk_fo_fwd_la', 'kk_fo_fwd_ta']),        # kuwabara-kono force, of ln(1 + alpha^(1/2))
    ('turn', 'ts_turn', ['ts_fwd_z', 'ts_fwd_m']),                 # tsuji, of alpha^(1/5)
    ('turn', 'kk_turn', ['kk_fwd_z', 'kk_fwd_m']),                 # kuwabara-kono, of ln(1 + alpha^(1/2))
    ('linv', 'kk_ov_inv', ['kk_ov_inv_a', 'kk_ov_inv_t']),         # kuwabara-kono overlap, of L
    ('linv', 'kk_fo_inv', ['kk_fo_inv_a', 'kk_fo_inv_t']),         # kuwabara-kono force, of L^(1/2)
    ('one', 'ts_ov_inv_t', ['ts_ov_inv_t']),                       # tsuji overlap tau_c, of L
    ('one', 'ts_fo_inv_a', ['ts_fo_inv_a']),                       # tsuji force alpha/L, of L
    ('one', 'ts_fo_inv_t', ['ts_fo_inv_t']),                       # tsuji force tau_c, of L^(1/5)
]


PART = 600   # values per parameter statement (200 lines of 3)


def lit(text):
    """A Fortran double literal that reproduces the CSV value exactly."""
    return '%.17e_wp' % float(text)


def wrap_values(values, indent, per_line=3):
    """Comma-separated values, `per_line` per continuation line."""
    lines = []
    for i in range(0, len(values), per_line):
        lines.append(indent + ', '.join(values[i:i + per_line]))
    return (', &\n').join(lines)


def read_csv(src):
    comments, params, blocks, order = [], [], {}, []
    with open(src, encoding='ascii') as f:
        for raw in f:
            line = raw.rstrip('\n')
            if not line:
                continue
            if line.startswith('#'):
                comments.append(line[1:].strip())
                continue
            cols = line.split(',')
            if cols[0] == 'param':
                params.append((cols[1], cols[2]))
            elif cols[0] == 'block':
                name = cols[1]
                blocks[name] = {'var': int(cols[2]), 'x0': cols[3], 'x1': cols[4],
                                'np': int(cols[5]), 'deg': int(cols[6]), 'pieces': {}}
                order.append(name)
            elif cols[0] == 'coef':
                b = blocks[cols[1]]
                coefs = cols[3:]
                if len(coefs) != b['deg'] + 1:
                    raise SystemExit('wrong number of coefficients in block ' + cols[1])
                b['pieces'][int(cols[2])] = coefs
            else:
                raise SystemExit('unknown row kind ' + cols[0])
    for name in order:
        if sorted(blocks[name]['pieces']) != list(range(blocks[name]['np'])):
            raise SystemExit('missing pieces in block ' + name)
    return comments, params, blocks, order


def families_of(blocks):
    """family -> list of (map, [blocks]); checks that a map's blocks share one grid and
    that every block is in a map."""
    fams, in_map = {}, set()
    for fam, name, comps in MAPS:
        missing = [c for c in comps if c not in blocks]
        if missing:
            raise SystemExit('map %s: blocks %s not in the CSV' % (name, ', '.join(missing)))
        grid = [(blocks[c]['var'], float(blocks[c]['x0']), float(blocks[c]['x1']), blocks[c]['np'])
                for c in comps]
        if len(set(grid)) != 1:
            raise SystemExit('map %s: its blocks are not on one grid' % name)
        if fam in fams and len(fams[fam][0][1]) != len(comps):
            raise SystemExit('map %s: family %s has another number of components' % (name, fam))
        fams.setdefault(fam, []).append((name, comps))
        in_map.update(comps)
    lost = [b for b in blocks if b not in in_map]
    if lost:
        raise SystemExit('blocks in no map (add them to MAPS): ' + ', '.join(lost))
    return fams


def main(argv):
    if len(argv) != 3:
        sys.stderr.write('usage: fit_csv_to_f90.py CSV F90\n')
        return 2
    src, dst = argv[1], argv[2]
    comments, params, blocks, order = read_csv(src)
    fams = families_of(blocks)
    out = []
    out.append('! Generated by gen/fit_csv_to_f90.py from data/fit_coefficients.csv; do not edit.')
    out.append('! Regenerate with `make fit-source` (CSV -> this file) after `make fit-data` (generator -> CSV).')
    out.append('! Layout (fitted maps, families, how to add one): see the docstring of gen/fit_csv_to_f90.py.')
    out.append('!')
    for c in comments:
        out.append('! ' + c if c else '!')
    out.append('')
    out.append('!> Coefficients of the approximants of hertzdamp_fit and the constants of hertzdamp_compact')
    out.append('!> (generated; see the header above and gen/fit/gen_fit.f90).')
    out.append('module hertzdamp_fit_data')
    out.append('    use hertzdamp_kinds, only: hertzdamp_rk')
    out.append('    implicit none')
    out.append('    private')
    out.append('')
    out.append('    integer, parameter :: wp = hertzdamp_rk')
    out.append('')
    for name, value in params:
        out.append('    !> generated constant %s' % name)
        out.append('    real(wp), parameter, public :: fit_%s = %s' % (name, lit(value)))
    for name in order:
        b = blocks[name]
        npc, deg = b['np'], b['deg']
        out.append('')
        out.append('    !> block %s: variable code %d, %d pieces of degree %d' % (name, b['var'], npc, deg))
        out.append('    integer, parameter, public :: %s_np = %d, %s_deg = %d' % (name, npc, name, deg))
        out.append('    real(wp), parameter, public :: %s_x0 = %s, %s_x1 = %s' % (name, lit(b['x0']), name, lit(b['x1'])))
        out.append('    real(wp), parameter, public :: %s_scale = %d / (%s_x1 - %s_x0)' % (name, npc, name, name))
    for fam in sorted(fams, key=lambda f: [m[0] for m in MAPS].index(f)):
        maps = fams[fam]
        ncomp = len(maps[0][1])
        deg = max(blocks[c]['deg'] for _, comps in maps for c in comps)
        first, values = [], []
        npieces = 0
        for _, comps in maps:
            first.append(npieces)
            npc = blocks[comps[0]]['np']
            for i in range(npc):
                for c in comps:
                    coefs = [lit(v) for v in blocks[c]['pieces'][i]]
                    values.extend(coefs + ['0.0_wp'] * (deg + 1 - len(coefs)))
            npieces += npc
        g = [blocks[comps[0]] for _, comps in maps]
        out.append('')
        out.append('    ! ---- family %s' % fam)
        for m, comps in maps:
            out.append('    !      map %s: blocks %s' % (m, ', '.join(comps)))
        out.append('    !> family %s: %d maps, %d pieces, %d components of degree <= %d' % (
            fam, len(maps), npieces, ncomp, deg))
        out.append('    integer, parameter, public :: fit_%s_nmaps = %d, fit_%s_npieces = %d, fit_%s_ncomp = %d, '
                   'fit_%s_deg = %d' % (fam, len(maps), fam, npieces, fam, ncomp, fam, deg))
        for k, (m, _) in enumerate(maps):
            out.append('    integer, parameter, public :: fit_map_%s = %d   !! map %s in family %s' % (m, k + 1, m, fam))
        out.append('    !> per map: variable code, first piece, number of pieces, grid [x0, x1] and np / (x1 - x0)')
        out.append('    integer, parameter, public :: fit_%s_var(%d) = [%s]' % (fam, len(maps), ', '.join(
            str(b['var']) for b in g)))
        out.append('    integer, parameter, public :: fit_%s_first(%d) = [%s]' % (fam, len(maps), ', '.join(
            str(x) for x in first)))
        out.append('    integer, parameter, public :: fit_%s_np(%d) = [%s]' % (fam, len(maps), ', '.join(
            str(b['np']) for b in g)))
        for key in ('x0', 'x1'):
            out.append('    real(wp), parameter, public :: fit_%s_%s(%d) = [ &' % (fam, key, len(maps)))
            out.append(wrap_values([lit(b[key]) for b in g], '        ') + ']')
        out.append('    real(wp), parameter, public :: fit_%s_scale(%d) = real(fit_%s_np, wp) / (fit_%s_x1 - fit_%s_x0)'
                   % (fam, len(maps), fam, fam, fam))
        # parts of at most PART values, so that no statement exceeds the 255 continuation
        # lines of the standard
        parts = [values[i:i + PART] for i in range(0, len(values), PART)]
        names = []
        for k, part in enumerate(parts):
            names.append('fit_%s_part%d' % (fam, k + 1))
            out.append('    real(wp), parameter :: %s(%d) = [ &' % (names[-1], len(part)))
            out.append(wrap_values(part, '        ') + ']')
        out.append('    !> coefficients: (power, component, piece)')
        out.append('    real(wp), parameter, public :: fit_%s_c(0:%d, %d, 0:%d) = reshape([ &' % (
            fam, deg, ncomp, npieces - 1))
        out.append('        %s], [%d, %d, %d])' % (', '.join(names), deg + 1, ncomp, npieces))
    out.append('')
    out.append('end module hertzdamp_fit_data')
    text = '\n'.join(out) + '\n'
    if dst == '-':
        sys.stdout.write(text)
    else:
        with open(dst, 'w', encoding='ascii', newline='\n') as f:
            f.write(text)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
