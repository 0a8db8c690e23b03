"""Every row of tests/ref/eq.tsv through the Python package: the value of
each labelled equation's output at the row's inputs, computed with the
Python functions, is (1) bit for bit the value the C program prints
(`chaplygin eq LABEL ARGS --csv`, %.17g, which round-trips) and (2) within
the row's tolerance (units of 2^-52, relative) of the row's reference,
computed by another route (tests/ref/make_eq_refs.py: mpmath, exact
arithmetic).  The Python side of each label is written out below from the
paper's equation and the header, not from the program."""
import csv
import io
import math
import re
import subprocess
from fractions import Fraction

import pytest

import chaplygin as c
from chaplygin import discrete as d, smooth as s, massless as m, printed as p

from conftest import src


def num(text):
    """A number of the table (decimal or p/q), correctly rounded."""
    return float(Fraction(text))


def registry_labels():
    """The paper's labels, in its order: the records '@ LABEL' of the
    registry lib/labels.txt."""
    with open(src('lib', 'labels.txt')) as fh:
        return [line[2:].strip() for line in fh if line.startswith('@ ')]


REGISTRY = registry_labels()


def rows():
    with open(src('tests', 'ref', 'eq.tsv')) as fh:
        lines = fh.read().splitlines()
    head = lines[0].split('\t')
    out = []
    for line in lines[1:]:
        r = dict(zip(head, line.split('\t')))
        out.append(r)
    return out


ROWS = rows()


def args_of(text):
    a = {}
    for part in text.split():
        k, v = part.split('=', 1)
        a[k] = v
    return a


def dir_of(a, key='dir', V=None):
    if key in a:
        return int(a[key])
    return 1 if V > 0 else -1


def opts(a):
    """The options of a row: method, tol, prec (default: the library's)."""
    o = {}
    if 'method' in a:
        o['method'] = a['method']
    if 'tol' in a:
        o['tol'] = num(a['tol'])
    if 'prec' in a:
        o['precision'] = a['prec']
    return o


def post_state(a, L0, Delta):
    """(dir, E, H, V+) of a post-collision state: E, H, dir given (V+ = 0,
    unknown), or V, Omega converted at the peg's end (V+ = V kept in the
    state, as chaplygin eq does for the labels that step or linearise)."""
    if 'E' in a:
        return int(a['dir']), num(a['E']), num(a['H']), 0.0
    V, Om = num(a['V']), num(a['Omega'])
    dr = dir_of(a, V=V)
    D = 0.0 if dr > 0 else Delta
    return dr, d.energy(L0, D, V, Om), d.momentum(L0, D, Om), V


def post_eh(a, L0, Delta):
    """(dir, E, H) of a post-collision state, as post_state."""
    return post_state(a, L0, Delta)[:3]


# Each label: (value outputs, printed outputs), dicts by output name.
def eq_2_1(a):
    q = [num(a.get('S', '0')), num(a['V']), num(a.get('theta', '0')),
         num(a['Omega'])]
    names = ['dS/dtau', 'dV/dtau', 'dtheta/dtau', 'dOmega/dtau']
    v = s.field(num(a['L']), q)
    pr = p.smooth_field(num(a['L']), q)
    return dict(zip(names, v)), dict(zip(names, pr))


def eq_2_2(a):
    rho, v0 = num(a['rho']), num(a['v0'])
    if 'ell' in a:
        dim = c.SmoothDim(ell=num(a['ell']), s=num(a.get('s', '0')),
                          v=num(a.get('v', '0')),
                          theta=num(a.get('theta', '0')),
                          omega=num(a.get('omega', '0')),
                          t=num(a.get('t', '0')))
        nd = s.nondimensionalize(rho, v0, dim)
        return nd.as_dict(), {}
    nd = c.SmoothNondim(L=num(a['L']), S=num(a.get('S', '0')),
                        V=num(a.get('V', '0')),
                        theta=num(a.get('theta', '0')),
                        Omega=num(a.get('Omega', '0')),
                        tau=num(a.get('tau', '0')))
    return s.dimensionalize(rho, v0, nd).as_dict(), {}


def eq_2_3(a):
    return {'rho': c.radius_of_gyration(num(a['m']), num(a['I']))}, {}


def eq_2_4(a):
    Vs = num(a['Vstar'])
    q, E, H = s.steady(Vs, num(a.get('theta', '0')), num(a.get('tau', '0')))
    out = {'S': q[0], 'V': q[1], 'theta': q[2], 'Omega': q[3], 'E': E,
           'H_C': H}
    if 'L' in a:
        out['xi4'] = s.eigenvalue(num(a['L']), Vs)
    return out, {}


def eq_3_1(a):
    q = [num(a['D']), num(a['V']), num(a.get('theta', '0')), num(a['Omega'])]
    v = d.field(num(a['L0']), q)
    return dict(zip(['dD/dtau', 'dV/dtau', 'dtheta/dtau', 'dOmega/dtau'],
                    v)), {}


def eq_3_2(a):
    rho, v0 = num(a['rho']), num(a['v0'])
    if 'ell0' in a:
        dim = c.DiscreteDim(ell0=num(a['ell0']), delta=num(a['delta']),
                            d=num(a.get('d', '0')), v=num(a.get('v', '0')),
                            theta=num(a.get('theta', '0')),
                            omega=num(a.get('omega', '0')),
                            t=num(a.get('t', '0')))
        return d.nondimensionalize(rho, v0, dim).as_dict(), {}
    nd = c.DiscreteNondim(L0=num(a['L0']), Delta=num(a['Delta']),
                          D=num(a.get('D', '0')), V=num(a.get('V', '0')),
                          theta=num(a.get('theta', '0')),
                          Omega=num(a.get('Omega', '0')),
                          tau=num(a.get('tau', '0')))
    return d.dimensionalize(rho, v0, nd).as_dict(), {}


def eq_3_3(a):
    return {'E': d.energy(num(a['L0']), num(a['D']), num(a['V']),
                          num(a['Omega']))}, {}


def eq_3_4(a):
    return {'H': d.momentum(num(a['L0']), num(a['D']), num(a['Omega']))}, {}


def eq_3_5(a):
    L0, Delta = num(a['L0']), num(a['Delta'])
    sys_ = d.init(L0, Delta)
    V, Om = num(a['V']), num(a['Omega'])
    q = [0.0 if V > 0 else Delta, V, num(a.get('theta', '0')), Om]
    qn, dtau = d.poincare(sys_, q, **opts(a))
    return dict(zip(['D_next', 'V_next', 'theta_next', 'Omega_next'], qn),
                dtau=dtau), {}


def eq_3_6(a):
    L0, Delta = num(a['L0']), num(a['Delta'])
    V = num(a['V'])
    q = [Delta if V > 0 else 0.0, V, num(a.get('theta', '0')),
         num(a['Omega'])]
    qp = d.collide(L0, Delta, q)
    return dict(zip(['D_plus', 'V_plus', 'theta_plus', 'Omega_plus'],
                    qp)), {}


def eq_3_7(a):
    L0, Delta, D = num(a['L0']), num(a['Delta']), num(a['D'])
    if 'E' in a:
        E, H = num(a['E']), num(a['H'])
    else:
        V, Om = num(a['V']), num(a['Omega'])
        E, H = d.energy(L0, D, V, Om), d.momentum(L0, D, Om)
    pp = d.collide_eh(L0, Delta, [D, E, num(a.get('theta', '0')), H])
    return dict(zip(['D_plus', 'E_plus', 'theta_plus', 'H_plus'], pp)), {}


def eq_3_8(a):
    if 'L0' in a or 'Delta' in a:
        L0, Delta = num(a['L0']), num(a['Delta'])
        dr, E, H = post_eh(a, L0, Delta)
        return {'ratio': d.spin_ratio(E, H),
                'spins': d.spins(L0, Delta, dr, E, H)}, {}
    return {'ratio': d.spin_ratio(num(a['E']), num(a['H']))}, {}


def eq_3_9(a):
    L0, Delta = num(a['L0']), num(a['Delta'])
    dr, E, H, V = post_state(a, L0, Delta)
    J = d.jacobian(d.init(L0, Delta), c.DiscreteState(dir=dr, E=E, H=H, V=V))
    return {'J%d%d' % (i + 1, j + 1): J[i, j]
            for i in range(4) for j in range(4)}, {}


def eq_3_10(a):
    return {'sigma4': d.sigma4(num(a['L0']), num(a['Delta']),
                               dir=int(a['dir']))}, {}


def stable(a, dr):
    L0, Delta = num(a['L0']), num(a['Delta'])
    return ({'stable': d.stable(L0, Delta, dr)},
            {'stable': p.discrete_stable(L0, Delta, dr)})


def reversal_range(a, dr):
    r = d.reversal_range(num(a['L0']), num(a['Delta']),
                         int(a.get('dir', dr)))
    return r._asdict(), {}


def eq_3_15(a):
    return {'rmin': d.ratio_lower_bound(num(a['L0']), num(a['Delta']),
                                        int(a['dir']))}, {}


def eq_4_1(a):
    L0, Delta, Vs = num(a['L0']), num(a['Delta']), num(a['Vstar'])
    dr = 1 if Vs > 0 else -1
    cf = d.xi4_taylor(L0, dr)
    out = {'xi4': d.xi4(L0, Delta, Vs), 'c0': cf[0], 'c1': cf[1],
           'c2': cf[2]}
    try:
        pc = p.discrete_xi4_taylor(L0, dr)
    except c.DomainError:           # the paper gives V* > 0 only
        return out, {}
    return out, {'c0': pc[0], 'c1': pc[1], 'c2': pc[2]}


def eq_A_1(a):
    L = num(a['L'])
    q0 = [num(a.get('S', '0')), num(a['V']), 0.0, num(a['Omega'])]
    r = s.reversal(L, q0)
    pr = p.smooth_reversal(L, q0)
    return ({'reverses': r.reverses, 'Sc': r.Sc},
            {'reverses': pr.reverses, 'Sc': pr.Sc})


def smooth_q0(a, theta=True):
    return [num(a.get('S0', '0')), num(a['V0']),
            num(a.get('theta0', '0')) if theta else 0.0, num(a['Omega0'])]


def eq_A_2(a):
    L, S = num(a['L']), num(a['S'])
    q0 = smooth_q0(a)
    q, dtau = s.closed_form(L, q0, S)
    pq = p.smooth_closed_form(L, q0, S)
    return ({'V': q[1], 'theta': q[2], 'Omega': q[3], 'dtau': dtau},
            {'V': pq[1], 'theta': pq[2], 'Omega': pq[3]})


def eq_A_3(a):
    L, S = num(a['L']), num(a['S'])
    q0 = smooth_q0(a, theta=False)
    return ({'K': s.branch(L, q0, S)}, {'K': p.smooth_branch(L, q0, S)})


def smooth_eh0(a, L):
    if 'E0' in a:
        return num(a['E0']), num(a['H0']), int(a['dir0'])
    V0, Om0 = num(a['V0']), num(a['Omega0'])
    return (s.energy(L, V0, Om0), s.momentum(L, Om0),
            dir_of(a, 'dir0', V0))


def eq_A_4(a):
    L, S = num(a['L']), num(a['S'])
    E0, H0, dir0 = smooth_eh0(a, L)
    p0 = [num(a.get('S0', '0')), E0, num(a.get('theta0', '0')), H0]
    q = s.closed_form_eh(L, p0, dir0, S)
    pq = p.smooth_closed_form_eh(L, p0, dir0, S)
    v = {'E': q[1], 'theta': q[2], 'H_C': q[3]}
    if 'V0' in a:
        v.update(E0=E0, H0=H0)
    return v, {'E': pq[1], 'theta': pq[2], 'H_C': pq[3]}


def eq_A_5(a):
    E, H = s.steady_eh(num(a['Vstar']))
    return {'E': E, 'H_C': H}, {}


def eq_A_6(a):
    L = num(a['L'])
    E0, H0, dir0 = smooth_eh0(a, L)
    S0 = num(a.get('S0', '0'))
    r = s.reversal_eh(L, S0, E0, H0, dir0)
    pr = p.smooth_reversal_eh(L, S0, E0, H0, dir0)
    return r._asdict(), pr._asdict()


def leg(a):
    return (num(a['L0']), num(a['D0']), num(a['V0']), num(a['Omega0']),
            num(a['D']))


def eq_B_1(a):
    return d.flow(*leg(a))._asdict(), {}


def eq_B_2(a):
    h = d.heading(*leg(a), **opts(a))
    return h._asdict(), {'dtheta': p.discrete_heading(*leg(a), **opts(a))}


def step_case(a, reversal):
    L0, Delta = num(a['L0']), num(a['Delta'])
    sys_ = d.init(L0, Delta)
    dr, E, H, V = post_state(a, L0, Delta)
    st = c.DiscreteState(dir=dr, E=E, H=H, V=V,
                         theta=num(a.get('theta', '0')),
                         tau=num(a.get('tau', '0')))
    C1, C2 = d.coefficients(L0, Delta, 0.0 if dr > 0 else Delta, reversal)
    out, ev = d.step(sys_, st, request='theta,tau', **opts(a))
    v = {'C1': C1, 'C2': C2, 'reversal': ev.reversal, 'E_next': out.E,
         'H_next': out.H, 'dtheta': ev.dtheta, 'dtau': ev.dtau}
    if reversal and ev.reversal:
        v['Dc'] = ev.Dc
    pr = {}
    if not reversal:
        pr['dtheta'] = p.discrete_f3(sys_, dr, E, H, **opts(a))
    return v, pr


def eq_B_5(a):
    L0, Delta = num(a['L0']), num(a['Delta'])
    if 'E' in a:
        E, H = num(a['E']), num(a['H'])
    else:
        D, V, Om = num(a['D']), num(a['V']), num(a['Omega'])
        E, H = d.energy(L0, D, V, Om), d.momentum(L0, D, Om)
    t = d.turning_points(L0, Delta, E, H)
    out = {'n_real': t.n_real, 'n_in_slot': t.n_in_slot}
    for i, x in enumerate(t.Dc):
        out['Dc%d' % (i + 1)] = x
    return out, {}


def slot_state(a):
    L0, Delta = num(a['L0']), num(a['Delta'])
    dr, E, H = post_eh(a, L0, Delta)
    return d.init(L0, Delta), dr, E, H


def eq_B_6(a):
    sys_, dr, E, H = slot_state(a)
    r = d.collisions_before_reversal(sys_, dr, E, H)
    pr = p.discrete_collisions_before_reversal(sys_, dr, E, H)
    return ({'reverses': r.reverses, 'n': r.n},
            {'reverses': pr.reverses, 'n': pr.n})


def eq_B_7(a):
    return {'C3': d.c3(num(a['L0']), num(a['Delta']), int(a['dir']))}, {}


def eq_B_8(a):
    L0, Delta = num(a['L0']), num(a['Delta'])
    if 'E' in a:
        E, H = num(a['E']), num(a['H'])
    else:
        _, E, H = post_eh(a, L0, Delta)
    return ({'two': d.two_turning_points(L0, Delta, E, H)},
            {'two': p.discrete_two_turning_points(L0, Delta, E, H)})


def eq_B_9(a):
    sys_, dr, E, H = slot_state(a)
    n = int(a['n'])
    r = d.energy_after(sys_, dr, E, H, n)
    pr = p.discrete_energy_after(sys_, dr, E, H, n)
    return {'E_n': r.En, 'H_n': r.Hn}, {'E_n': pr.En}


def eq_B_10(a):
    sys_, dr, E, H = slot_state(a)
    return {'E_f': d.final_energy(sys_, dr, E, H)}, {}


def eq_B_11(a):
    return {'converges': d.energy_converges(num(a['L0']), num(a['Delta']),
                                            int(a['dir']))}, {}


def eq_B_12(a):
    L0, Delta = num(a['L0']), num(a['Delta'])
    if 'V' in a:
        V, Om = num(a['V']), num(a['Omega'])
    else:
        q = d.state_to_phase(d.init(L0, Delta), c.DiscreteState(
            dir=int(a['dir']), E=num(a['E']), H=num(a['H'])))
        V, Om = q[1], q[3]
    return {'V_f': d.final_velocity(L0, Delta, V, Om)}, {}


def eq_B_13(a):
    return {'V2_over_Omega2': d.spin_sequence(num(a['Delta']),
                                              int(a['n']))}, {}


def eq_B_14(a):
    L0, Delta = num(a['L0']), num(a['Delta'])
    sys_ = d.init(L0, Delta)
    st, tau_star = d.fixed_point(sys_, num(a['Vstar']),
                                 num(a.get('theta', '0')),
                                 num(a.get('tau', '0')))
    loss = d.collision_loss(sys_, st.dir, 0, num(a.get('H', '0')))
    return {'E': st.E, 'H': st.H, 'tau_star': tau_star, 'loss': loss}, {}


def eq_B_15(a):
    L0 = num(a['L0'])
    theta, tau = num(a.get('theta', '0')), num(a.get('tau', '0'))
    if 'E' in a:
        st = c.DiscreteState(dir=int(a['dir']), E=num(a['E']),
                             H=num(a['H']), theta=theta, tau=tau)
    else:
        V, Om = num(a['V']), num(a['Omega'])
        dr = dir_of(a, V=V)
        st = m.state_from_phase(L0, [0.0 if dr > 0 else 1.0, V, theta, Om],
                                tau)
    out, ev = m.step(L0, st)
    return {'E_next': out.E, 'H_next': out.H, 'dtheta': ev.dtheta,
            'dtau': ev.dtau, 'reversal': ev.reversal,
            'period2': m.period2(L0)}, {}


def eq_B_16(a):
    L0, Dp, rev = num(a['L0']), float(int(a['Dplus'])), int(a['reversal'])
    return ({'C2': m.coefficient(L0, Dp, rev)},
            {'C2': p.massless_coefficient(L0, Dp, rev)})


def eq_B_17(a):
    delta, v0 = num(a['delta']), num(a['v0'])
    if 'ell0' in a:
        dim = c.DiscreteDim(ell0=num(a['ell0']), delta=delta,
                            d=num(a.get('d', '0')), v=num(a.get('v', '0')),
                            theta=num(a.get('theta', '0')),
                            omega=num(a.get('omega', '0')),
                            t=num(a.get('t', '0')))
        return m.nondimensionalize(delta, v0, dim).as_dict(), {}
    nd = c.DiscreteNondim(L0=num(a['L0']), Delta=num(a.get('Delta', '1')),
                          D=num(a.get('D', '0')), V=num(a.get('V', '0')),
                          theta=num(a.get('theta', '0')),
                          Omega=num(a.get('Omega', '0')),
                          tau=num(a.get('tau', '0')))
    return m.dimensionalize(delta, v0, nd).as_dict(), {}


def eq_3_11(a):
    return stable(a, 1)


def eq_3_12(a):
    return stable(a, -1)


def eq_3_13(a):
    return reversal_range(a, -1)


def eq_3_14(a):
    return reversal_range(a, 1)


def eq_B_3(a):
    return step_case(a, 0)


def eq_B_4(a):
    return step_case(a, 1)


# The evaluator of label 3.10 is eq_3_10, of B.2 eq_B_2, ...
def evaluator_name(label):
    return 'eq_' + label.replace('.', '_')


LABELS = {label: globals()[evaluator_name(label)] for label in REGISTRY
          if evaluator_name(label) in globals()}

_PROGRAM_CACHE = {}


def program_values(program, label, args):
    key = (label, args)
    if key not in _PROGRAM_CACHE:
        r = subprocess.run([program, 'eq', label] + args.split() + ['--csv'],
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        _PROGRAM_CACHE[key] = {row['output']: row for row in
                               csv.DictReader(io.StringIO(r.stdout))}
    return _PROGRAM_CACHE[key]


def as_number(x):
    return float(x) if not isinstance(x, bool) else float(int(x))


def same(x, y):
    """Bit for bit (NaN with NaN, -0 apart from +0)."""
    return math.copysign(1, x) == math.copysign(1, y) and \
        (x == y or (math.isnan(x) and math.isnan(y)))


def test_every_label_mapped():
    """An evaluator for every label of the registry and for no other name,
    and rows of tests/ref/eq.tsv for every label and no other."""
    missing = [label for label in REGISTRY if label not in LABELS]
    assert not missing, missing
    names = {evaluator_name(label) for label in REGISTRY}
    extra = sorted(n for n in globals() if re.fullmatch(r'eq_[0-9A-Z]+_[0-9]+', n)
                   and n not in names)
    assert not extra, extra
    labels = {r['label'] for r in ROWS}
    assert labels == set(REGISTRY), (sorted(labels - set(REGISTRY)),
                                     sorted(set(REGISTRY) - labels))


@pytest.mark.parametrize('row', ROWS, ids=lambda r: '%s:%s:%s' % (
    r['label'], r['output'], r['which']))
def test_eq_row(row, program):
    a = args_of(row['args'])
    values, printed = LABELS[row['label']](a)
    got = (values if row['which'] == 'value' else printed)[row['output']]
    got = as_number(got)
    # (1) bit for bit the C program's number
    prog = program_values(program, row['label'], row['args'])[row['output']]
    want_c = float(prog[row['which'] if row['which'] == 'value'
                        else 'printed'])
    assert same(got, want_c), (got, want_c)
    # (2) within the row's tolerance of the reference
    ref = num(row['reference'])
    tol = int(row['tol_eps']) * 2.0 ** -52 * abs(ref)
    assert abs(got - ref) <= tol, (got, ref, row['tol_eps'])


def test_program_outputs_all_computed(program):
    """Every output the program prints for a row's inputs is computed by
    the Python mapping too (so the mapping is complete), bit for bit."""
    for (label, args) in {(r['label'], r['args']) for r in ROWS}:
        values, printed = LABELS[label](args_of(args))
        for name, row in program_values(program, label, args).items():
            if row['value'] in ('none',):
                assert values.get(name) is None, (label, name)
                continue
            assert name in values, (label, name)
            assert same(as_number(values[name]), float(row['value'])), \
                (label, name, values[name], row['value'])
            if row['printed'] == 'undefined':
                assert printed.get(name) is None, (label, name)
            elif row['printed'] != '':
                assert name in printed, (label, name)
                assert same(as_number(printed[name]),
                            float(row['printed'])), (label, name)
