"""The hand-written vectorised functions: orbits (discrete and massless),
step_eh_n, fates with reversal lists, basins and their boundaries, and the
sweeps, each equal to a loop of scalar calls of the library's functions,
bit for bit, with their failure policies."""
import numpy as np
import pytest

import chaplygin as c
from chaplygin import discrete as d, massless as m


def states(sys_, V, Omega):
    q = np.stack([np.where(V > 0, 0.0, sys_.Delta), V, np.zeros_like(V),
                  np.broadcast_to(Omega, V.shape)], axis=-1)
    return d.state_from_phase(sys_, q)


def same_struct(a, b):
    for f in a.dtype.names:
        x, y = np.asarray(a[f]), np.asarray(b[f])
        if x.dtype.kind == 'f':
            if not np.array_equal(x, y, equal_nan=True):
                return False
        elif not np.array_equal(x, y):
            return False
    return True


@pytest.mark.parametrize('method', ['closed-form', 'quadrature', 'ode'])
def test_orbit_equals_steps(method):
    sys_ = d.init(1.0, 1 / 3)
    st = states(sys_, np.linspace(0.5, 2.0, 6), 0.5)
    n = 12 if method != 'ode' else 4
    orb, ev = d.orbit(sys_, st, n, method=method, events=True)
    assert orb.shape == (6, n + 1) and ev.shape == (6, n)
    for i in range(6):
        s = c.DiscreteState.from_record(st[i])
        assert same_struct(orb[i, 0], s.to_record())
        for k in range(n):
            s, e = d.step(sys_, s, method=method)
            assert same_struct(orb[i, k + 1], s.to_record())
            assert same_struct(ev[i, k], e.to_record())
    last = d.orbit(sys_, st, n, method=method, keep='last')
    assert same_struct(last, orb[:, -1])


def test_orbit_eh_only_is_step_eh_n():
    sys_ = d.init(-0.5, 1.0)
    st = states(sys_, np.linspace(0.6, 3.0, 50), 0.8)
    a = d.orbit(sys_, st, 200, request=0, keep='last')
    b = d.orbit(sys_, st, 200, request=0, keep='all')[:, -1]
    e = d.step_eh_n(sys_, st, 200)
    assert same_struct(a, b) and same_struct(a, e)
    for i in (0, 25, 49):
        s = c.DiscreteState.from_record(st[i])
        for _ in range(200):
            s, _ = d.step(sys_, s, request=0)
        assert same_struct(a[i], s.to_record())
        one = d.step_eh_n(sys_, c.DiscreteState.from_record(st[i]), 200)
        assert one == s


def test_orbit_shapes_and_scalar():
    sys_ = d.init(1.0, 1 / 3)
    st = d.state_from_phase(sys_, [0, 1, 0, 0.5])
    o = d.orbit(sys_, st, 5)
    assert o.shape == (6,)
    o2 = d.orbit(sys_, {'dir': 1, 'E': np.full((2, 3), st.E), 'H': st.H,
                        'V': st.V}, 5)
    assert o2.shape == (2, 3, 6)
    assert same_struct(o2[1, 2], o)
    assert d.orbit(sys_, st, 0).shape == (1,)
    with pytest.raises(ValueError):
        d.orbit(sys_, st, 3, keep='first')
    with pytest.raises(ValueError):
        d.orbit(sys_, st, 3, keep='last', events=True)


def test_orbit_failure():
    """An orbit that ends in the spinning equilibrium stops there."""
    sys_ = d.init(-0.75, 1.2917)
    good = d.state_from_phase(sys_, [0, 1.0, 0, 0.5])
    spin = d.state_from_phase(sys_, [0, 15 / 32, 0, 0.5])
    both = np.array([good.to_record(), spin.to_record()])
    with pytest.raises(c.SpinError) as info:
        d.orbit(sys_, both, 4)
    assert info.value.index == (1,)
    assert list(info.value.done) == [4, 0]
    r = d.orbit(sys_, both, 4, errors='return')
    assert list(r.status) == [0, c.ESPIN] and list(r.done) == [4, 0]
    assert same_struct(r.states[1, 0], spin.to_record())
    assert np.all(np.isnan(r.states[1, 1:]['E']))
    assert np.all(r.states[1, 1:]['dir'] == 0)
    assert same_struct(r.states[0], d.orbit(sys_, good, 4))


def test_massless_orbit():
    L0 = -0.4137
    st0 = m.state_from_phase(L0, [0, 0.6, 0.3, 0.7])
    sts = {'dir': 1, 'E': np.linspace(0.3, 1.0, 5), 'H': 0.2913}
    orb = m.orbit(L0, sts, 7)
    for i in range(5):
        s = c.DiscreteState(dir=1, E=sts['E'][i], H=0.2913)
        for k in range(7):
            s, _ = m.step(L0, s)
            assert same_struct(orb[i, k + 1], s.to_record())
    o1, e1 = m.orbit(L0, st0, 3, events=True)
    s, e = m.step(L0, st0)
    assert same_struct(o1[1], s.to_record()) and same_struct(e1[0],
                                                             e.to_record())


def test_step_eh_n_policy():
    sys_ = d.init(-0.75, 1.2917)
    spin = d.state_from_phase(sys_, [0, 15 / 32, 0, 0.5])
    with pytest.raises(c.SpinError) as info:
        d.step_eh_n(sys_, spin, 3)
    assert info.value.done == 0 and info.value.partial == spin
    r = d.step_eh_n(sys_, spin, 3, errors='return')
    assert r.status == c.ESPIN and r.done == 0
    v = d.step_eh_n(sys_, np.array([spin.to_record()] * 2), [0, 3],
                    errors='return')
    assert list(v.status) == [0, c.ESPIN] and list(v.done) == [0, 0]


def test_fate_vectorised_with_reversals():
    sys_ = d.init(-0.5, 1.0)
    V = np.linspace(0.0005, 0.5, 64)
    q = np.stack([np.zeros(64), V, np.zeros(64), np.full(64, 0.8)], axis=1)
    f, ra = d.fate_phase(sys_, q, 10000, reversal_cap=8)
    assert f.dtype == c.Fate.dtype and ra.shape == (64, 8)
    st = states(sys_, V, 0.8)
    g, rb = d.fate(sys_, st, 10000, reversal_cap=8)
    for i in range(64):
        one, r1 = d.fate_phase(sys_, list(q[i]), 10000, reversal_cap=8)
        assert same_struct(f[i], one.to_record())
        k = min(8, one.reversals)
        assert list(ra[i, :k]) == list(r1) and np.all(ra[i, k:] == 0)
        two, r2 = d.fate(sys_, c.DiscreteState.from_record(st[i]), 10000,
                         reversal_cap=8)
        assert same_struct(g[i], two.to_record()) and list(r2) == \
            list(rb[i, :min(8, two.reversals)])
    plain = d.fate_phase(sys_, q, 10000)
    assert same_struct(plain, f)
    assert isinstance(d.fate_phase(sys_, list(q[0]), 10000), c.Fate)


def test_basins_and_boundaries():
    sys_ = d.init(-0.5, 1.0)
    b = d.basins(sys_, 0.8, 0.0005, 0.5, 200, 100000)
    assert b.shape == (200,) and b.dtype == c.Fate.dtype
    V = 0.0005 + (0.5 - 0.0005) * np.arange(200) / 199
    V[-1] = 0.5
    q = np.stack([np.zeros(200), V, np.zeros(200), np.full(200, 0.8)], axis=1)
    f = d.fate_phase(sys_, q, 100000)
    assert np.array_equal(b['kind'], f['kind'])
    bd = d.basin_boundaries(sys_, 0.8, 0.0005, 0.5, 200, 100000)
    kinds = b['kind']
    changes = np.count_nonzero((kinds[1:] != kinds[:-1]) &
                               (kinds[1:] != 0) & (kinds[:-1] != 0))
    assert len(bd) >= changes and np.all(np.diff(bd) >= 0)
    assert len(d.basins(sys_, 0.8, 0.1, 0.2, 0, 10)) == 0
    with pytest.raises(c.StateError):
        d.basins(sys_, 0.8, -0.5, 0.5, 3, 10)       # a grid point is 0


def test_sweeps():
    x = np.linspace(-4, 2, 121)
    s4 = c.sweep.sigma4(x, 0.25, 1)
    Delta = 2.0                              # y = 1/Delta^2 = 0.25
    direct = d.sigma4(x * Delta, Delta, dir=1)
    assert np.allclose(s4, direct, rtol=1e-14, atol=1e-15)
    grid = c.sweep.sigma4(x, [0.01, 0.25, 1.0], 1)
    assert grid.shape == (3, 121) and np.array_equal(grid[1], s4)
    assert c.sweep.sigma4(0.5, 0.25, -1) == \
        c.sweep.sigma4(np.array([0.5]), 0.25, -1)[0]
    with pytest.raises(c.RangeError) as info:
        c.sweep.sigma4([0.5, -1.0], 0.0, 1)
    assert list(info.value.statuses) == [0, c.ERANGE]
    r = c.sweep.sigma4([0.5, -1.0, np.nan], 0.0, 1, errors='return')
    assert list(r.status) == [0, c.ERANGE, c.EDOM] and np.isnan(r.sigma4[1])
    with pytest.raises(c.DomainError):
        c.sweep.sigma4(x, -1.0, 1)
    with pytest.raises(c.InvalidArgumentError):
        c.sweep.sigma4(x, 0.5, 3)
    reg = c.sweep.stability(x, [0.0, 0.5, 1.0])
    assert reg.shape == (3, 121) and reg.dtype == np.uint8
    for j in (0, 60, 120):
        st = d.stable(x[j] * 1.0, 1.0, 1) + 2 * d.stable(x[j] * 1.0, 1.0, -1)
        assert reg[2, j] == st
    with pytest.raises(c.DomainError):
        c.sweep.stability(x, [np.nan])
    assert c.sweep.stability([], [1.0]).shape == (1, 0)
