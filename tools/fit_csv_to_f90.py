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
- every block has NAME_c(0:DEG, 0:NP-1), the coefficients of its pieces (for code that
  evaluates one block at a time, such as the derivatives of hertzdamp_calibrate_maps):
  its own array for a block in no map, a section of fit_F_c for a block of a map.

To add a fitted map (for instance for another damping law): let the generator write
its blocks to the CSV, add a line (family, map name, blocks) to MAPS, run
`make fit-source`, and give the new map index to the kernel in hertzdamp_fit (the
variable code of the map selects the transform of e or alpha the kernel applies).
"""
import sys

# family, map, blocks (the components of the family, in this order)
#   inv:  inverse maps, components alpha/L and tau_c as functions of a variable of L = -ln e
#   fwd:  forward maps of e and tau_c, components L/alpha (or L) and tau_c
#   turn: forward maps of the turning point, components z_max and tau_max
MAPS = [
    ('inv', 'ov_inv', ['ov_inv_a', 'ov_inv_t']),
    ('inv', 'fo_inv', ['fo_inv_a', 'fo_inv_t']),
    ('fwd', 'ov_fwd_a', ['ov_fwd_la', 'ov_fwd_ta']),
    ('fwd', 'ov_fwd_w', ['ov_fwd_lw', 'ov_fwd_tw']),
    ('fwd', 'fo_fwd', ['fo_fwd_la', 'fo_fwd_ta']),
    ('turn', 'ov_turn_a', ['ov_fwd_za', 'ov_fwd_ma']),
    ('turn', 'ov_turn_b', ['ov_fwd_zb', 'ov_fwd_mb']),
    ('turn', 'fo_turn', ['fo_fwd_za', 'fo_fwd_ma']),
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
    """family -> list of (map, [blocks]); checks that a map's blocks share one grid."""
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
    return fams, in_map


def main(argv):
    if len(argv) != 3:
        sys.stderr.write('usage: fit_csv_to_f90.py CSV F90\n')
        return 2
    src, dst = argv[1], argv[2]
    comments, params, blocks, order = read_csv(src)
    fams, in_map = families_of(blocks)
    out = []
    out.append('! Generated by tools/fit_csv_to_f90.py from data/fit_coefficients.csv; do not edit.')
    out.append('! Regenerate with `make fit-source` (CSV -> this file) after `make fit-data` (generator -> CSV).')
    out.append('! Layout (fitted maps, families, how to add one): see the docstring of tools/fit_csv_to_f90.py.')
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
        if name in in_map:
            continue
        values = []
        for i in range(npc):
            values.extend(lit(v) for v in b['pieces'][i])
        out.append('    real(wp), parameter, public :: %s_c(0:%d, 0:%d) = reshape([ &' % (name, deg, npc - 1))
        out.append(wrap_values(values, '        ') + '], [%d, %d])' % (deg + 1, npc))
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
        # every block of a map also under its own name, as a section of the family array
        # (the layout of a block outside a map: for code that evaluates one block)
        out.append('    !> the blocks of the maps one by one: NAME_c(0:DEG, 0:NP-1), sections of fit_%s_c' % fam)
        for (m, comps), f in zip(maps, first):
            for j, c in enumerate(comps):
                b = blocks[c]
                out.append('    real(wp), parameter, public :: %s_c(0:%d, 0:%d) = fit_%s_c(0:%d, %d, %d:%d)' % (
                    c, b['deg'], b['np'] - 1, fam, b['deg'], j + 1, f, f + b['np'] - 1))
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
