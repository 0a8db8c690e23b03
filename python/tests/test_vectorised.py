"""Vectorised calls equal a loop of scalar calls, for every generated
function of the package: inputs drawn from pools of typical values (some
invalid, so that statuses are exercised too), in one call with
errors='return', then element by element; every output and status must be
the same, bit for bit.  Then the same through strided, broadcast,
multi-dimensional and read-only arrays."""

import numpy as np
import pytest

import chaplygin as c
from chaplygin import _core, _generated
from chaplygin import discrete as d

NAN = float('nan')
POOLS = {
    'L0': [1.0, -0.5, 0.7321, -1.4137, 2.0, -0.25, 0.0],
    'L': [0.7321, -1.2917, 1.0, 0.0],
    'Delta': [1 / 3, 1.0, 0.4137, 2.1173, -1.0],
    'E': [0.75, 0.9157, 2.0, 0.2726, -1.0],
    'E0': [0.7321, 0.9157, 2.0],
    'H': [1.0, 0.5813, -0.3, 0.0],
    'H0': [0.9157, 0.5813, -0.4],
    'V': [1.0, -0.8629, 0.5, 0.0],
    'V0': [0.8629, -1.0923, 1.0],
    'Vstar': [1.0, -1.0923, 0.8629],
    'Omega': [0.5, -0.3, 0.5813],
    'Omega0': [0.5813, -0.4137, 0.5],
    'D': [0.0, 0.1, 0.2741, 1 / 3],
    'D0': [0.0, 0.0917],
    'Dplus': [0.0, 1.0, 1 / 3],
    'S': [0.5, 2.1173, 3.0],
    'S0': [0.0, 0.2741],
}
INT_POOLS = {'dir': [1, -1, 1, 0], 'dir0': [1, -1], 'reversal': [0, 1],
             'n': [0, 1, 3], 'request': [0, 7, 3, 1],
             'method': [0, 1, 2, 3, 9]}
DEFAULT_POOL = [0.5, 1.25, -0.75, 0.3719, NAN]
N = 48


def pool(name, kind):
    if name in INT_POOLS:
        return INT_POOLS[name]
    if kind == 'int':
        return [0, 1, 2]
    return POOLS.get(name, DEFAULT_POOL)


def draw(rng, name, ctype, kind, dims, shape):
    if kind == 'in_struct':
        cls = _core._struct_class(ctype)
        if ctype == 'chaplygin_discrete':
            return d.init(rng.choice(POOLS['L0'][:5], shape),
                          rng.choice([1 / 3, 1.0, 0.4137], shape))
        fields = {}
        for f in cls.dtype.names:
            fd = cls.dtype.fields[f][0]
            if fd.base.kind == 'f':
                fields[f] = rng.choice(pool(f, 'f'), shape + fd.shape)
            else:
                fields[f] = rng.choice(pool(f, 'int'), shape + fd.shape)
        if ctype == 'chaplygin_discrete_state':
            fields['dir'] = rng.choice([1, -1], shape)
            fields['E'] = rng.choice([0.75, 0.9157, 2.0, 0.2726], shape)
            fields['H'] = rng.choice([1.0, 0.5813, -0.3, 0.1], shape)
        return _core._struct_from_fields(name, cls, fields, shape)
    if kind == 'in_array':
        return rng.choice(pool(name, 'f') if name not in ('q', 'q0', 'p0',
                                                          'qplus', 'qminus',
                                                          'pminus')
                          else [0.0, 0.5813, 1.0, -0.8629, 0.2741],
                          shape + (dims,))
    if ctype == 'double':
        return rng.choice(pool(name, 'f'), shape)
    vals = pool(name, 'int')
    if ctype.startswith('unsigned'):
        vals = [v for v in vals if v >= 0]
    return np.array(rng.choice(vals, shape), dtype=np.int64)


def element(x, i):
    if isinstance(x, np.ndarray):
        if x.dtype.names:
            return _core._struct_class(struct_of(x.dtype)).from_record(x[i])
        v = x[i]
        return v.tolist() if isinstance(v, np.ndarray) else v.item()
    return x


def struct_of(dtype):
    for ctype, cls in _core.STRUCT_CLASSES.items():
        if cls.dtype == dtype:
            return ctype
    raise KeyError(dtype)


def same(a, b):
    """Bit for bit, recursively (None as NaN/0, structs by field)."""
    if isinstance(b, c.Struct):
        rec = b.to_record()
        return all(same(a[f], rec[f]) for f in rec.dtype.names)
    if b is None:
        a = np.asarray(a)
        return bool(np.all(np.isnan(a))) if a.dtype.kind == 'f' \
            else bool(np.all(a == 0))
    a, b = np.asarray(a), np.asarray(b)
    if a.dtype.names:
        return all(same(a[f], b[f]) for f in a.dtype.names)
    if a.shape != b.shape:
        if b.size < a.size:                  # counted outputs (Dc)
            a = a.reshape(-1)[:b.size].reshape(b.shape)
        else:
            return False
    if a.dtype.kind == 'f' or b.dtype.kind == 'f':
        a, b = a.astype(float), b.astype(float)
        return bool(np.all((a == b) & (np.signbit(a) == np.signbit(b))
                           | (np.isnan(a) & np.isnan(b))))
    return bool(np.all(a == b))


GENERATED = sorted(cname for cname in _generated.WRAPPED
                   if _generated.FUNCTIONS[cname] and
                   _core.SPEC[cname] and cname != 'chaplygin_strerror')


def inputs_of(cname, rng, shape):
    args = []
    for name, kind, ctype, dims, extra in _core.SPEC[cname]:
        if kind in ('in', 'in_array', 'in_struct'):
            if extra.get('nullable'):
                args.append(None)
                continue
            args.append(draw(rng, name, ctype, kind, dims, shape))
    return args


@pytest.mark.parametrize('cname', GENERATED)
def test_vector_equals_scalar_loop(cname):
    f = _generated.WRAPPED[cname]
    rng = np.random.default_rng(abs(hash(cname)) % 2 ** 32)
    args = inputs_of(cname, rng, (N,))
    vec = f(*args, errors='return')
    assert vec.status.shape == (N,)
    outs = [n for n in vec._fields if n != 'status']
    ok = 0
    for i in range(N):
        a_i = [element(a, i) for a in args]
        try:
            r = f(*a_i)
            st = 0
        except c.ChaplyginError as e:
            st = e.status
        assert vec.status[i] == st, (cname, i, a_i)
        if st:
            continue
        ok += 1
        if len(outs) == 1:
            r = (r,)
        for name, got in zip(outs, r):
            assert same(getattr(vec, name)[i], got), (cname, name, i, a_i)
    # a failed element's float outputs are NaN, with its status
    for name in outs:
        arr = np.asarray(getattr(vec, name))
        if arr.dtype.kind == 'f':
            assert np.all(np.isnan(arr[vec.status != 0]))


def test_some_succeed():
    """The pools are not all invalid: most functions succeed somewhere."""
    good = 0
    for cname in GENERATED:
        f = _generated.WRAPPED[cname]
        rng = np.random.default_rng(1)
        r = f(*inputs_of(cname, rng, (N,)), errors='return')
        good += bool(np.any(r.status == 0))
    assert good >= len(GENERATED) - 3


def test_layouts():
    """Strided, reversed, broadcast, 2-D, read-only, unaligned, big-endian
    and Fortran-ordered inputs give the same numbers as contiguous ones."""
    rng = np.random.default_rng(7)
    L0 = rng.uniform(-2, 2, 800)
    V0 = rng.uniform(0.5, 2, 800)
    Om = rng.uniform(-1, 1, 800)
    D = rng.uniform(0.05, 0.3, 800)
    good = d.heading(L0, 0.0, V0, Om, D, errors='return').status == 0
    L0, V0, Om, D = (a[good][:200] for a in (L0, V0, Om, D))
    D0 = np.zeros(200)
    ref = d.heading(L0, D0, V0, Om, D)
    big = np.empty(400)
    big[::2] = L0
    strided = big[::2]
    assert not strided.flags.c_contiguous
    r = d.heading(strided, D0, V0, Om, D)
    assert np.array_equal(r.dtheta, ref.dtheta)
    rev = L0[::-1].copy()[::-1]
    r = d.heading(rev, 0.0, V0, Om, D)
    assert np.array_equal(r.dtau, ref.dtau)
    ro = L0.copy()
    ro.setflags(write=False)
    assert np.array_equal(d.heading(ro, D0, V0, Om, D).dtheta, ref.dtheta)
    raw = np.zeros(200 * 8 + 1, np.uint8)
    una = np.frombuffer(raw.data, dtype=np.float64, count=200, offset=1)
    assert not una.flags.aligned
    raw[1:] = np.frombuffer(L0.tobytes(), np.uint8)
    assert np.array_equal(d.heading(una, D0, V0, Om, D).dtheta, ref.dtheta)
    be = L0.astype('>f8')
    assert np.array_equal(d.heading(be, D0, V0, Om, D).dtheta, ref.dtheta)
    # 2-D, C and Fortran order, against the flat result
    r2 = d.heading(L0.reshape(10, 20), 0.0, V0.reshape(10, 20),
                   Om.reshape(10, 20), D.reshape(10, 20))
    assert r2.dtheta.shape == (10, 20)
    assert np.array_equal(r2.dtheta.reshape(-1), ref.dtheta)
    F = np.asfortranarray(L0.reshape(10, 20))
    r3 = d.heading(F, 0.0, V0.reshape(10, 20), Om.reshape(10, 20),
                   D.reshape(10, 20))
    assert np.array_equal(r3.dtau, r2.dtau)
    T = L0.reshape(20, 10).T          # a transposed view
    r4 = d.heading(T, 0.0, V0.reshape(20, 10).T, Om.reshape(20, 10).T,
                   D.reshape(20, 10).T)
    assert np.array_equal(r4.dtau, ref.dtau.reshape(20, 10).T)
    # broadcasting: a row of L0 against a column of V0
    rb = d.heading(L0[:5][None, :], 0.0, V0[:3][:, None], 0.5, 0.1)
    assert rb.dtheta.shape == (3, 5)
    for i in range(3):
        for j in range(5):
            assert rb.dtheta[i, j] == d.heading(L0[j], 0.0, V0[i], 0.5,
                                                0.1).dtheta
    # fixed-size array inputs: q of shape (..., 4), strided rows
    q = np.stack([np.zeros(200), V0, np.zeros(200), Om], axis=1)
    sys_ = d.init(1.0, 1 / 3)
    qn, dt = d.poincare(sys_, q)
    qs = np.asfortranarray(q)
    qn2, dt2 = d.poincare(sys_, qs)
    assert np.array_equal(qn, qn2) and np.array_equal(dt, dt2)
    for i in (0, 17, 199):
        a, b = d.poincare(sys_, list(q[i]))
        assert np.array_equal(qn[i], a) and dt[i] == b


def test_empty_and_zero_d():
    r = d.sigma4(np.array([]), 1 / 3, dir=1)
    assert r.shape == (0,) and r.dtype == np.float64
    r = d.sigma4(np.empty((3, 0)), 1 / 3, dir=1)
    assert r.shape == (3, 0)
    v = d.sigma4(np.float64(1.0), np.array(1 / 3), dir=np.int32(1))
    assert v == d.sigma4(1, 1 / 3, dir=1)
    from fractions import Fraction
    assert d.sigma4(Fraction(1), Fraction(1, 3), dir=1) == \
        d.sigma4(1, 1 / 3, dir=1)


def test_structured_inputs_and_columns():
    sys_ = d.init(1, 1 / 3)
    V = np.linspace(0.5, 2, 7)
    q = np.stack([np.zeros(7), V, np.zeros(7), np.full(7, 0.5)], axis=1)
    st = d.state_from_phase(sys_, q)
    assert st.dtype == c.DiscreteState.dtype and st.shape == (7,)
    out, ev = d.step(sys_, st)
    for i in range(7):
        o, e = d.step(sys_, c.DiscreteState.from_record(st[i]))
        assert same(out[i], o) and same(ev[i], e)
    cols = c.as_columns(out)
    assert list(cols) == ['dir', 'E', 'H', 'theta', 'tau', 'peg_x',
                          'peg_y', 'V']
    # a dict of fields, broadcast
    out2, _ = d.step(sys_, {'dir': 1, 'E': st['E'], 'H': st['H']})
    assert np.array_equal(out2['E'], out['E'])
    # a list of objects
    objs = [c.DiscreteState.from_record(x) for x in st]
    out3, _ = d.step(sys_, objs)
    assert np.array_equal(out3['theta'], out['theta'])
