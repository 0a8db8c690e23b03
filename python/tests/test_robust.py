"""Bad input never crashes and never leaks: wrong types, wrong shapes, NaN,
non-contiguous arrays and huge sizes raise Python exceptions (or return
statuses); the reference counts of the arguments are unchanged after many
calls, failing ones included; memory does not grow with repeated calls."""
import gc
import sys
import tracemalloc

import numpy as np
import pytest

import chaplygin as c
from chaplygin import discrete as d, smooth as s

NAN = float('nan')
SYS = d.init(1.0, 1 / 3)
STATE = d.state_from_phase(SYS, [0, 1, 0, 0.5])

BAD_SCALARS = [None, 'x', b'1', 1j, {'a': 1}, object(),
               np.array(['a']), np.datetime64('2020-01-01')]


@pytest.mark.parametrize('bad', BAD_SCALARS, ids=repr)
def test_bad_scalar_types(bad):
    with pytest.raises((TypeError, ValueError)):
        d.sigma4(1.0, bad, dir=1)
    with pytest.raises((TypeError, ValueError, OverflowError)):
        d.sigma4(1.0, 1 / 3, dir=bad)
    with pytest.raises((TypeError, ValueError)):
        d.heading(1, 0, bad, 0.5, 1 / 3)
    with pytest.raises((TypeError, ValueError)):
        s.field(0.7, bad)
    with pytest.raises(TypeError):
        d.step(SYS, bad)
    with pytest.raises(TypeError):
        d.step(bad, STATE)


def test_bad_shapes():
    with pytest.raises(ValueError):
        s.field(0.7, [1.0, 2.0, 3.0])                 # q has 4 numbers
    with pytest.raises(ValueError):
        s.field(0.7, np.zeros((5, 3)))
    with pytest.raises(ValueError):
        s.field(0.7, np.float64(1.0))
    with pytest.raises(ValueError):
        d.sigma4(np.zeros(3), np.zeros(4), dir=1)      # no broadcast
    with pytest.raises(ValueError):
        d.fixed_point(SYS, 1.0, peg=[1.0])
    with pytest.raises(TypeError):
        d.step(SYS, np.zeros(3))                        # not a state
    with pytest.raises(TypeError):
        d.step(SYS, {'dir': 1, 'bogus': 2.0})
    with pytest.raises(ValueError):
        d.step(SYS, {'dir': 1, 'E': 0.75, 'H': 1.0, 'peg': [1.0, 2.0, 3.0]})
    with pytest.raises(ValueError):
        c.DiscreteState(peg=(1.0,))
    with pytest.raises(TypeError):
        c.DiscreteState.from_record(np.zeros(1))


def test_nan_and_inf_everywhere():
    vals = [NAN, np.inf, -np.inf, 0.0, -0.0, 1e308, -1e-308, 5e-324]
    for v in vals:
        r = d.heading(v, 0, 1, 0.5, 1 / 3, errors='return')
        assert r.status != 0 or np.isfinite(r.dtheta)
        r = d.sigma4(v, v, dir=1, errors='return')
        assert r.status != 0 or not np.isnan(r.sigma4)
    # NaN in a state: a status, never a NaN result without one
    r = d.step(SYS, {'dir': 1, 'E': [0.75, NAN], 'H': [1.0, 1.0]},
               errors='return')
    assert r.status[0] == 0 and r.status[1] == c.EDOM
    assert not np.isnan(r.out['E'][0]) and np.isnan(r.out['E'][1])


def test_huge_sizes():
    huge = np.broadcast_to(np.float64(1.0), (2 ** 40,))
    with pytest.raises(MemoryError):
        d.sigma4(huge, 1 / 3, dir=1)
    with pytest.raises((MemoryError, ValueError)):
        d.sigma4(np.broadcast_to(1.0, (2 ** 31, 2 ** 31)), 1 / 3, dir=1)
    with pytest.raises(MemoryError):
        d.orbit(SYS, np.broadcast_to(STATE.to_record(), (2 ** 20,)),
                2 ** 40)
    with pytest.raises((MemoryError, ValueError, OverflowError)):
        d.fate_phase(SYS, [0, 1, 0, 0.5], 10, reversal_cap=2 ** 62)
    with pytest.raises((MemoryError, ValueError, OverflowError)):
        d.basins(SYS, 0.5, 0.1, 1.0, 2 ** 62, 10)
    with pytest.raises(OverflowError):
        d.basins(SYS, 0.5, 0.1, 1.0, -1, 10)
    with pytest.raises(OverflowError):
        d.orbit(SYS, STATE, -1)
    with pytest.raises(OverflowError):
        d.energy_after(SYS, 1, 0.75, 1.0, 2 ** 64)


def test_noncontiguous_structs():
    big = d.orbit(SYS, STATE, 9)                  # (10,) states
    every_other = big[::2]
    assert not every_other.flags.c_contiguous
    a, _ = d.step(SYS, every_other)
    b, _ = d.step(SYS, every_other.copy())
    for f in a.dtype.names:                 # (padding bytes differ)
        assert a[f].tobytes() == b[f].tobytes()
    sys_arr = d.init(np.array([1.0, 2.0, 3.0, 4.0])[::2], 1 / 3)
    assert sys_arr.shape == (2,)
    eh = STATE.copy()
    eh.V = 0.0          # E and H alone: STATE's own V+ is L0 = 1's
    out, _ = d.step(sys_arr, eh)
    one, _ = d.step(d.init(3.0, 1 / 3), eh)
    assert out['E'][1] == one.E


def calls(x, arr, q):
    d.sigma4(x, 1 / 3, dir=1)
    d.sigma4(arr, 1 / 3, dir=1)
    d.sigma4(arr, 1 / 3, dir=1, errors='return')
    d.heading(1.0, 0.0, 1.0, 0.5, 1 / 3, method='quadrature', tol=1e-12)
    s.field(0.7, q)
    d.step(SYS, STATE)
    d.orbit(SYS, STATE, 3)
    for bad in (lambda: d.sigma4(NAN, 1 / 3, dir=1),
                lambda: d.sigma4(arr * NAN, 1 / 3, dir=1),
                lambda: d.sigma4('x', 1 / 3, dir=1),
                lambda: s.field(0.7, q[:3]),
                lambda: d.heading(1, 0, 1, 0.5, 1 / 3, method='bogus'),
                lambda: c.run_scene({'scene': {'model': 'bogus'}})):
        try:
            bad()
        except (c.ChaplyginError, TypeError, ValueError):
            pass


def test_no_reference_leaks():
    x = 1.2345678
    arr = np.linspace(-1, 1, 17)
    q = [0.0, 1.0, 0.0, 0.5]
    objs = [x, arr, q, SYS, STATE]
    calls(x, arr, q)
    gc.collect()
    before = [sys.getrefcount(o) for o in objs]
    for _ in range(300):
        calls(x, arr, q)
    gc.collect()
    after = [sys.getrefcount(o) for o in objs]
    assert before == after


def test_no_memory_growth():
    x = 0.75
    arr = np.linspace(-1, 1, 17)
    q = [0.0, 1.0, 0.0, 0.5]
    for _ in range(50):
        calls(x, arr, q)
    gc.collect()
    tracemalloc.start()
    try:
        for _ in range(50):
            calls(x, arr, q)
        gc.collect()
        first, _ = tracemalloc.get_traced_memory()
        for _ in range(500):
            calls(x, arr, q)
        gc.collect()
        second, _ = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert second - first < 64 * 1024, (first, second)
    n_before = len(gc.get_objects())
    for _ in range(200):
        calls(x, arr, q)
    gc.collect()
    assert len(gc.get_objects()) - n_before < 100


def test_struct_objects():
    st = c.DiscreteState(1, 0.75, 1.0, peg=(0.5, 0.25))
    assert st.peg == (0.5, 0.25) and st.dir == 1
    cp = st.copy()
    cp.E = 2.0
    assert st.E == 0.75
    import pickle
    st2 = pickle.loads(pickle.dumps(st))
    assert st2 == st and st2 is not st
    assert repr(st).startswith('DiscreteState(dir=1, E=0.75')
    with pytest.raises(TypeError):
        hash(st)
    with pytest.raises(TypeError):
        st.E = 'x'
    with pytest.raises(OverflowError):
        st.dir = 2 ** 40
    with pytest.raises(TypeError):
        c.DiscreteState(1, 2, 3, 4, 5, (0, 0), 7, 8)
    with pytest.raises(TypeError):
        c.DiscreteState(1, dir=1)
    o = c.Options(method='quadrature', tol=1e-12)
    assert o.method == c.Method.QUADRATURE
    with pytest.raises(c.InvalidArgumentError):
        c.Options(method='bogus')
    assert c.Discrete(1, 1 / 3) == SYS
