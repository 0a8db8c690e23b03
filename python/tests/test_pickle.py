"""Every result of the package pickles and unpickles to an equal value
(issue 27, item 5: process pools and schedulers send results between
processes).  The functions are the package's public callables, found by
walking it: a generated function is called with test_vectorised's inputs
(one vectorised call with errors='return' and one with 'raise', a scalar
call that succeeds and one that fails), a hand-written one with the calls
in HAND, which must name every one of them.  Each result (or the exception
raised) goes through pickle at every protocol and must come back equal:
same types, field names, dtypes and bits (NaN included), exceptions with
their attributes.  Then a smoke test through a ProcessPoolExecutor with
fresh interpreters (spawn)."""
import concurrent.futures
import multiprocessing
import pickle
import struct
import warnings

import numpy as np
import pytest

import chaplygin as c
from chaplygin import _generated, discrete as d
from conftest import public_functions
from test_vectorised import inputs_of, GENERATED

SYS = d.init(1.0, 1 / 3)
ST = d.state_from_phase(SYS, [0, 1, 0, 0.5])
FIG3 = d.init(-0.5, 1.0)
SCENE = {'scene': {'model': 'discrete'},
         'parameters': {'L0': 1, 'Delta': '1/3'},
         'initial': {'V': 1, 'Omega': 0.5},
         'run': {'collisions': 5}}
SWEEP = {'scene': {'model': 'discrete'},          # V = 0 fails: masked
         'parameters': {'L0': -0.5, 'Delta': 1},
         'initial': {'Omega': 0.8}, 'run': {'collisions': 1000},
         'sweep': {'kind': 'basins', 'x_min': -0.1, 'x_max': 0.1, 'nx': 3}}
ATLAS = {'scene': {'model': 'discrete'},          # V = 0: no fate
         'parameters': {'L0': -0.5, 'Delta': 1}, 'run': {'collisions': 100},
         'sweep': {'kind': 'atlas', 'x': 'V', 'x_min': -0.1, 'x_max': 0.1,
                   'nx': 3, 'y': 'Omega', 'y_min': 0.5, 'y_max': 1,
                   'ny': 4}}
MOTION = c.smooth.motion_init(1.0, [0, 1, 0, 0.5])
BAD = c.DiscreteState(dir=1, E=float('nan'), H=0.2)   # fails at once


def stepped(orbit, n, cap=None):
    """ORBIT after N certified collisions, then capped at CAP."""
    for _ in range(n):
        orbit.step()
    if cap is not None:
        orbit.cap(cap)
    return orbit


def closed(orbit):
    orbit.close()
    return orbit


def exact_orbit():
    return c.CertifiedOrbit.exact((1, 3), (2, 7), 1, (5, 11), (-3, 13))


def capped_out(orbit):
    """ORBIT capped at 64 bits, stepped until that fails (ECAP)."""
    orbit.cap(64)
    for _ in range(64):
        orbit.step()

# The hand-written functions' calls (results and failures).
HAND = {
    'discrete.orbit': [
        lambda: d.orbit(SYS, ST, 4),
        lambda: d.orbit(SYS, [ST, ST], 3, keep='last', errors='return'),
        lambda: d.orbit(SYS, ST, 3, request='theta,tau', events=True),
        lambda: d.orbit(SYS, BAD, 3)],
    'discrete.step_eh_n': [
        lambda: d.step_eh_n(SYS, ST, 10),
        lambda: d.step_eh_n(SYS, [ST, BAD], 10, errors='return'),
        lambda: d.step_eh_n(SYS, BAD, 10)],
    'discrete.fate': [
        lambda: d.fate(FIG3, d.state_from_phase(FIG3, [0, 0.3, 0, 0.8]),
                       10**5, reversal_cap=4),
        lambda: d.fate(FIG3, BAD, 10, errors='return')],
    'discrete.fate_phase': [
        lambda: d.fate_phase(FIG3, [[0, 0.3, 0, 0.8], [0, 0, 0, 0.8]],
                             10**5, errors='return'),
        lambda: d.fate_phase(FIG3, [0, 0, 0, 0.8], 10**5)],
    'discrete.basins': [
        lambda: d.basins(FIG3, 0.8, -0.1, 0.1, 3, 1000, errors='return'),
        lambda: d.basins(FIG3, 0.8, -0.1, 0.1, 3, 1000)],
    'discrete.fates_phase': [
        lambda: d.fates_phase(FIG3, [0.3, 0.0, -0.5], 0.8, 1000,
                              errors='return'),
        lambda: d.fates_phase(FIG3, 0.3, 0.8, 1000),
        lambda: d.fates_phase(FIG3, [0.3, 0.0], 0.8, 1000)],
    'discrete.basin_boundaries': [
        lambda: d.basin_boundaries(FIG3, 0.8, 0.0005, 0.5, 200, 10**5)],
    'smooth.path': [
        lambda: c.smooth.path(MOTION, [0, 1, 2]),
        lambda: c.smooth.path(MOTION, [0, 1, -1], errors='return'),
        lambda: c.smooth.path(MOTION, [0, -1])],
    'smooth.path_advance': [
        lambda: c.smooth.path_advance(MOTION, c.smooth.path_init(0), 1.5),
        lambda: c.smooth.path_advance(MOTION, c.smooth.path_init(1), 0.5,
                                      errors='return')],
    'massless.orbit': [
        lambda: c.massless.orbit(-0.4137, c.massless.state_from_phase(
            -0.4137, [0, 0.6, 0.3, 0.7]), 3, events=True),
        lambda: c.massless.orbit(-0.4137, BAD, 3, errors='return')],
    'sweep.sigma4': [
        lambda: c.sweep.sigma4([0.5, np.nan], [0, 0.5], 1, errors='return'),
        lambda: c.sweep.sigma4([0.5, np.nan], 0.5, 1)],
    'sweep.stability': [lambda: c.sweep.stability([-1, 0.5], [0, 0.5])],
    'sweep.grid_point': [lambda: c.sweep.grid_point(0, 1, 3, 1),
                         lambda: c.sweep.grid_point(0, 1, 3, 5)],
    'scene.run_scene': [
        lambda: c.run_scene(SCENE), lambda: c.run_scene(SWEEP),
        lambda: c.run_scene({'scene': {'model': 'none'}})],
    'scene.to_ini': [lambda: c.scene.to_ini(SCENE)],
    'dataset.atlas': [
        lambda: c.atlas(ATLAS), lambda: c.atlas(ATLAS, chunks=(2, 3)),
        lambda: c.atlas({'scene': {'model': 'none'}})],
    'equation.eq': [
        lambda: c.eq('3.10', L0=1, Delta='1/3', dir=-1),
        lambda: c.eq('B.3', L0=1e200, Delta=1, V=1, Omega=1),
        lambda: c.eq('B.9', L0=1, Delta='1/3', V=1, Omega=0.5, n=3),
        lambda: c.eq('9.9'), lambda: c.eq('3.10', L0=1, Delta=-1, dir=1)],
    'equation.labels': [lambda: c.labels()],
    'certified_orbit_new': [
        lambda: c.certified_orbit_new(SYS, ST),
        lambda: stepped(c.certified_orbit_new(SYS, ST, 'theta'), 3, 200),
        lambda: closed(c.certified_orbit_new(SYS, ST)),
        lambda: c.certified_orbit_new(SYS, BAD)],
    'certified_orbit_new_exact': [
        lambda: stepped(exact_orbit(), 2),
        lambda: c.certified_orbit_new_exact(1, (-1, 1), 1, 1, 1)],
    'certified_orbit_step': [
        lambda: c.certified_orbit_step(exact_orbit()),
        lambda: c.certified_orbit_step(exact_orbit(), return_ev=False),
        lambda: capped_out(exact_orbit())],
    'certified_orbit_cap': [
        lambda: c.certified_orbit_cap(exact_orbit(), 100),
        lambda: c.certified_orbit_cap(exact_orbit(), 63)],
    'certified_orbit_collisions': [
        lambda: c.certified_orbit_collisions(stepped(exact_orbit(), 2)),
        lambda: c.certified_orbit_collisions(closed(exact_orbit()))],
    'certified_orbit_free': [lambda: c.certified_orbit_free(exact_orbit())],
    'certified_orbit_new_phase': [
        lambda: stepped(c.certified_orbit_new_phase(SYS, [0, 1, 0.1, 0.5]), 2),
        lambda: c.certified_orbit_new_phase(SYS, [1, 1, 0, 0.5])],
    'certified_orbit_new_phase_exact': [
        lambda: stepped(c.certified_orbit_new_phase_exact(
            (-1, 2), 1, (3, 10), (4, 5)), 2),
        lambda: c.certified_orbit_new_phase_exact(1, 1, 0, 1)],
    'certified_orbit_state': [
        lambda: c.certified_orbit_state(stepped(exact_orbit(), 2)),
        lambda: c.certified_orbit_state(exact_orbit(), return_bounds=False),
        lambda: c.certified_orbit_state(closed(exact_orbit()))],
    'certified_orbit_omega': [
        lambda: c.certified_orbit_omega(stepped(exact_orbit(), 1)),
        lambda: c.certified_orbit_omega(closed(exact_orbit()))],
    'certified_orbit_sample': [
        lambda: c.certified_orbit_sample(stepped(exact_orbit(), 1), 0.0),
        lambda: c.certified_orbit_sample(exact_orbit(), 0.0)],
    'certified_orbit_fate': [
        lambda: c.certified_orbit_fate(exact_orbit(), 100),
        lambda: c.certified_orbit_fate(c.certified_orbit_new_phase_exact(
            (-1, 2), 1, (3, 10), (4, 5)), 100, reversal_cap=3),
        lambda: c.certified_orbit_fate(closed(exact_orbit()), 1)],
    'method_available': [
        lambda: c.method_available('certified'),
        lambda: c.method_available([0, 3, 9], errors='return'),
        lambda: c.method_available(9)],
    'error_class': [lambda: c.error_class(2)],
    'as_columns': [lambda: c.as_columns(d.orbit(SYS, ST, 2))],
}


PUBLIC = public_functions()
GENERATED_FN = {id(_generated.WRAPPED[cname]): cname
                for cname in _generated.WRAPPED}


def same(a, b):
    """Equal values: same types and bits, recursively."""
    if type(a) is not type(b):
        return False
    if type(a).__name__ == 'Dataset':          # chaplygin.atlas: xarray's
        a, b = a.compute(), b.compute()
        return (a.identical(b) and list(a.variables) == list(b.variables)
                and all(same(a[v].values, b[v].values) for v in a.variables))
    if isinstance(a, np.ma.MaskedArray):
        return (same(a.data, b.data) and np.array_equal(
            np.ma.getmaskarray(a), np.ma.getmaskarray(b)))
    if isinstance(a, (np.ndarray, np.generic)):
        if a.dtype != b.dtype or a.shape != b.shape:
            return False
        if a.dtype.names:           # by field: padding bytes are no value
            return all(same(a[f], b[f]) for f in a.dtype.names)
        return a.tobytes() == b.tobytes()
    if isinstance(a, c.Struct):
        return same(a.to_record(), b.to_record())
    if isinstance(a, float):
        return struct.pack('<d', a) == struct.pack('<d', b)
    if isinstance(a, tuple):
        return (getattr(a, '_fields', None) == getattr(b, '_fields', None)
                and len(a) == len(b) and all(map(same, a, b)))
    if isinstance(a, list):
        return len(a) == len(b) and all(map(same, a, b))
    if isinstance(a, dict):
        return list(a) == list(b) and all(same(a[k], b[k]) for k in a)
    if isinstance(a, BaseException):
        return str(a) == str(b) and same(a.args, b.args) and \
            same(vars(a), vars(b))
    if isinstance(a, c.equation.Label):
        return all(same(getattr(a, k), getattr(b, k)) for k in a.__slots__)
    if isinstance(a, c.equation.Equation):
        return same(vars(a), vars(b))
    return a == b


def outcome(call):
    try:
        return call()
    except c.ChaplyginError as e:
        return e


def round_trips(x):
    # xarray's objects (chaplygin.atlas) pickle from protocol 2 on (their
    # __slots__ have no __getstate__); every process pool uses the highest
    first = 2 if type(x).__name__ == 'Dataset' else 0
    for proto in range(first, pickle.HIGHEST_PROTOCOL + 1):
        y = pickle.loads(pickle.dumps(x, protocol=proto))
        assert same(x, y), (proto, x, y)


def generated_calls(cname):
    """Calls of the generated function CNAME: vectorised (return and
    raise), a scalar call that succeeds and one that fails, where the
    inputs give them."""
    f = _generated.WRAPPED[cname]
    if cname == 'chaplygin_strerror':
        return [lambda: f(2)]
    rng = np.random.default_rng(27)
    args = inputs_of(cname, rng, (48,))
    vec = f(*args, errors='return')
    calls = [lambda: f(*args, errors='return'), lambda: f(*args)]
    for want_ok in (True, False):
        idx = np.flatnonzero((vec.status == 0) == want_ok)
        if idx.size:
            i = idx[0]
            one = [a[i] if isinstance(a, np.ndarray) and a.dtype.names is None
                   else c._core._struct_class(struct_of(a.dtype))
                   .from_record(a[i]) if isinstance(a, np.ndarray)
                   else a for a in args]
            calls.append(lambda one=one: f(*one))
    return calls


def struct_of(dtype):
    return next(t for t, cls in c._core.STRUCT_CLASSES.items()
                if cls.dtype == dtype)


def test_walk_finds_the_package():
    """The walk sees the generated and the hand-written functions, and
    every function is either generated or in HAND."""
    assert 'discrete.sigma4' in PUBLIC and 'run_scene' in PUBLIC
    assert len(PUBLIC) >= len(GENERATED) + len(HAND)
    missing = [n for n, f in PUBLIC.items()
               if id(f) not in GENERATED_FN
               and n not in HAND and n.split('.')[-1] not in HAND
               and not any(k.endswith('.' + n) for k in HAND)]
    assert not missing, 'no calls for %s in HAND' % missing


@pytest.mark.parametrize('name', sorted(PUBLIC))
def test_results_pickle(name):
    f = PUBLIC[name]
    if id(f) in GENERATED_FN:
        calls = generated_calls(GENERATED_FN[id(f)])
    else:
        key = name if name in HAND else next(
            k for k in HAND if k == name or k.endswith('.' + name))
        calls = HAND[key]
    kinds = set()
    for call in calls:
        x = outcome(call)
        kinds.add(type(x).__name__)
        round_trips(x)
    assert kinds


def test_issue_example():
    """The issue's example: a Result of two structs."""
    r = d.step(d.init(1.0, 1 / 3), c.DiscreteState(dir=1, E=0.5, H=0.2),
               request='theta,tau')
    assert type(r).__name__ == 'Result'
    s = pickle.loads(pickle.dumps(r))
    assert s == r and s._fields == r._fields and type(s) is type(r)


def test_kinds_covered():
    """The walk met every kind of result: Result tuples, structs,
    structured and plain arrays, masked arrays, equations, labels and
    errors with partial results."""
    seen = set()

    def visit(x):
        seen.add(type(x).__name__ if not isinstance(x, c.Struct)
                 else 'Struct')
        if isinstance(x, (tuple, list)):
            for y in x:
                visit(y)
        elif isinstance(x, dict):
            for y in x.values():
                visit(y)
        elif isinstance(x, c.ChaplyginError):
            visit(vars(x))
    for name, f in PUBLIC.items():
        calls = (generated_calls(GENERATED_FN[id(f)]) if id(f) in GENERATED_FN
                 else HAND[next(k for k in HAND
                                if k == name or k.endswith('.' + name))])
        for call in calls:
            visit(outcome(call))
    for kind in ('Result', 'Struct', 'ndarray', 'MaskedArray', 'Equation',
                 'Label', 'DomainError', 'SceneError', 'EquationError',
                 'StateError', 'float', 'int', 'str', 'type', 'NoneType',
                 'Dataset'):
        assert kind in seen, kind
    if c.method_available('certified'):     # a build with Arb
        assert {'CertifiedOrbit', 'CertificationCapError'} <= seen


def remote_calls():
    return [(d.step, (SYS, ST), {'request': 'theta,tau'}),
            (d.orbit, (SYS, ST, 3), {'events': True, 'errors': 'return'}),
            (d.sigma4, (np.array([1.0, np.nan]), 1 / 3), {'dir': 1}),
            (c.run_scene, (SWEEP,), {}),
            (c.eq, ('B.3',), {'L0': 1e200, 'Delta': 1, 'V': 1, 'Omega': 1}),
            (d.fate, (FIG3, BAD, 10), {})]


def test_process_pool():
    """Results and exceptions sent back from fresh interpreters equal the
    local ones."""
    ctx = multiprocessing.get_context('spawn')
    with concurrent.futures.ProcessPoolExecutor(2, mp_context=ctx) as ex:
        futures = [ex.submit(f, *a, **k) for f, a, k in remote_calls()]
        got = [fu.exception() or fu.result() for fu in futures]
    for (f, a, k), g in zip(remote_calls(), got):
        with warnings.catch_warnings():
            warnings.simplefilter('ignore')         # eq B.3's
            want = outcome(lambda: f(*a, **k))
        assert same(g, want), (f.__name__, g, want)

