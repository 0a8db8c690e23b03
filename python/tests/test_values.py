"""The Python package computes the C library's numbers, bit for bit.

python/tests/cvalues (C, linked with libchaplygin) evaluates the library at
the inputs of the reference tables of tests/ (ref_map.h, ref_flow.h,
ref_smooth.h, ref_poincare.h, ref_stability.h) and prints the results as
hex floats; here the same calls through the package -- one scalar call per
row, and the whole table in one vectorised call -- must give the same bits,
and both must agree with the tables' references (computed by other routes,
tests/ref/make_refs.py) as closely as the C unit tests require (those use
finer, per-case tolerances; equal bits mean the Python results pass them
too)."""
import math

import numpy as np

import chaplygin as c
from chaplygin import discrete as d, smooth as s

METHODS = {'cf': dict(method='closed-form'),
           'quad': dict(method='quadrature', tol=1e-13),
           'ode': dict(method='ode', tol=1e-12)}
# agreement with the references, relative (absolute below 1e-3)
REF_TOL = {'cf': 1e-13, 'quad': 1e-12, 'ode': 1e-9}


def same(x, y):
    x, y = float(x), float(y)
    return math.copysign(1, x) == math.copysign(1, y) and \
        (x == y or (math.isnan(x) and math.isnan(y)))


def close(x, ref, tol):
    return abs(x - ref) <= tol * max(abs(ref), 1e-3)


def test_map_scalar(cvalues):
    for row in cvalues['map']:
        sys_ = d.init(row['L0'], row['Delta'])
        st = c.DiscreteState(dir=row['dir'], E=row['E'], H=row['H'],
                             theta=0.125, tau=2.0, peg=(0.5, -0.25))
        for m, kw in METHODS.items():
            out, ev = d.step(sys_, st, request='all', **kw)
            assert row[m + '_st'] == 0
            assert out.dir == row[m + '_dir1']
            for name, got in [('E1', out.E), ('H1', out.H),
                              ('theta1', out.theta), ('tau1', out.tau),
                              ('pegx', out.peg[0]), ('pegy', out.peg[1]),
                              ('Dc', ev.Dc), ('dtheta', ev.dtheta),
                              ('dtau', ev.dtau)]:
                assert same(got, row[m + '_' + name]), (m, name, row)
            assert ev.reversal == row[m + '_reversal']
            assert ev.reversal == row['ref_reversal']
            assert out.dir == row['ref_dir1']
            for name, got in [('E1', out.E), ('H1', out.H),
                              ('dtheta', ev.dtheta), ('dtau', ev.dtau)]:
                assert close(got, row['ref_' + name], REF_TOL[m]), \
                    (m, name, got, row['ref_' + name])
            if ev.reversal:
                assert close(ev.Dc, row['ref_Dc'], 1e-8)


def test_map_vectorised(cvalues):
    """The whole table in one call per method: systems and states as
    structured arrays."""
    rows = cvalues['map']
    sys_ = d.init(np.array([r['L0'] for r in rows]),
                  np.array([r['Delta'] for r in rows]))
    assert sys_.dtype == c.Discrete.dtype and sys_.shape == (len(rows),)
    st = {'dir': [r['dir'] for r in rows], 'E': [r['E'] for r in rows],
          'H': [r['H'] for r in rows], 'theta': 0.125, 'tau': 2.0,
          'peg': (0.5, -0.25)}
    for m, kw in METHODS.items():
        out, ev = d.step(sys_, st, **kw)
        for i, r in enumerate(rows):
            assert out['dir'][i] == r[m + '_dir1']
            for name, got in [('E1', out['E'][i]), ('H1', out['H'][i]),
                              ('theta1', out['theta'][i]),
                              ('tau1', out['tau'][i]),
                              ('pegx', out['peg'][i, 0]),
                              ('pegy', out['peg'][i, 1]),
                              ('dtheta', ev['dtheta'][i]),
                              ('dtau', ev['dtau'][i]), ('Dc', ev['Dc'][i])]:
                assert same(got, r[m + '_' + name]), (m, name, i)


def test_flow(cvalues):
    rows = cvalues['flow']
    cols = {k: np.array([r[k] for r in rows])
            for k in ('L0', 'D0', 'V0', 'Omega0', 'D')}
    for m, kw in METHODS.items():
        vec = d.heading(cols['L0'], cols['D0'], cols['V0'], cols['Omega0'],
                        cols['D'], **kw)
        for i, r in enumerate(rows):
            h = d.heading(r['L0'], r['D0'], r['V0'], r['Omega0'], r['D'],
                          **kw)
            assert r[m + '_st'] == 0
            assert same(h.dtheta, r[m + '_dtheta'])
            assert same(h.dtau, r[m + '_dtau'])
            assert same(vec.dtheta[i], r[m + '_dtheta'])
            assert same(vec.dtau[i], r[m + '_dtau'])
            assert close(h.dtheta, r['ref_dtheta'], REF_TOL[m])
            assert close(h.dtau, r['ref_dtau'], REF_TOL[m])
    for r in rows:
        f = d.flow(r['L0'], r['D0'], r['V0'], r['Omega0'], r['D'])
        assert same(f.V2, r['V2']) and same(f.Omega, r['Omega'])


def test_smooth(cvalues):
    rows = cvalues['smooth']
    q0 = np.array([[0.0, r['V0'], 0.0, r['Omega0']] for r in rows])
    L = np.array([r['L'] for r in rows])
    S = np.array([r['S'] for r in rows])
    qv, tv = s.closed_form(L, q0, S)
    for i, r in enumerate(rows):
        q, tau = s.closed_form(r['L'], [0.0, r['V0'], 0.0, r['Omega0']],
                               r['S'])
        for k in range(4):
            assert same(q[k], r['q%d' % k]) and same(qv[i, k], r['q%d' % k])
        assert same(tau, r['tau']) and same(tv[i], r['tau'])
        for name, got in [('V', q[1]), ('Omega', q[3]), ('dtheta', q[2]),
                          ('dtau', tau)]:
            assert close(got, r['ref_' + name], 1e-13)


def test_poincare(cvalues):
    for r in cvalues['poincare']:
        sys_ = d.init(r['L0'], r['Delta'])
        q = [0.0 if r['V'] > 0 else r['Delta'], r['V'], 0.0, r['Omega']]
        qn, dtau = d.poincare(sys_, q)
        for k in range(4):
            assert same(qn[k], r['q%d' % k])
        assert same(dtau, r['dtau'])
        assert close(qn[2], r['ref_dtheta'], 1e-13)
        assert close(dtau, r['ref_dtau'], 1e-13)
        assert abs(qn[1] - r['ref_V1']) <= 1e-13 * abs(r['ref_V1'])
        assert abs(qn[3] - r['ref_Omega1']) <= 1e-13 * abs(r['ref_Omega1'])


def test_stability_tables(cvalues):
    rows = cvalues['sigma4']
    vec = d.sigma4(np.array([r['L0'] for r in rows]),
                   np.array([r['Delta'] for r in rows]),
                   np.array([r['dir'] for r in rows]))
    for i, r in enumerate(rows):
        got = d.sigma4(r['L0'], r['Delta'], dir=r['dir'])
        assert same(got, r['sigma4']) and same(vec[i], r['sigma4'])
        assert abs(got - r['ref_sigma4']) <= 1e-12 * max(1, abs(r['ref_sigma4']))
    for r in cvalues['jacobian']:
        J = d.jacobian(d.init(r['L0'], r['Delta']),
                       c.DiscreteState(dir=r['dir'], E=r['E'], H=r['H']))
        assert J.shape == (4, 4)
        for k in range(16):
            assert same(J.flat[k], r['J%d' % k])
    for r in cvalues['xi4']:
        got = d.xi4(r['L0'], r['Delta'], r['V'])
        assert same(got, r['xi4'])
        assert abs(got - r['ref_xi4']) <= 1e-12 * abs(r['ref_xi4'])
    for r in cvalues['taylor']:
        cf = d.xi4_taylor(r['L0'], r['dir'])
        for k in range(3):
            assert same(cf[k], r['c%d' % k])
            assert abs(cf[k] - r['ref_c%d' % k]) <= \
                1e-13 * max(1, abs(r['ref_c%d' % k]))


def test_headline_value():
    """The README's example: sigma4(1, 1/3, +1) = 21/25 within 2 ulps."""
    v = d.sigma4(1, 1 / 3, dir=1)
    assert abs(v - 21 / 25) <= 2 * math.ulp(21 / 25)
    assert d.sigma4(L0=1, Delta=1 / 3, dir=+1) == v
