"""Wrong types raise TypeError, masked arrays are refused (issue 27, item
12): for every public function, found by walking the package, and every
parameter that takes numbers, None, a string, bytes, an object, a list
holding None (NumPy would make None NaN and '1.5' 1.5: a DomainError or
a silent number) and a numpy.ma array (np.asarray would drop its mask)
raise TypeError; integer parameters refuse 2.5 too.  Generated functions
take their parameters from SPEC, with valid values for the others from
test_vectorised's pools; hand-written ones are in HAND, which must name
every one of them (or EXEMPT, with the reason)."""
import numpy as np
import pytest

import chaplygin as c
from chaplygin import _core, _generated, discrete as d
from conftest import public_functions
from test_vectorised import draw

SYS = d.init(1.0, 1 / 3)
ST = d.state_from_phase(SYS, [0, 1, 0, 0.5])
FIG3 = d.init(-0.5, 1.0)
MOTION = c.smooth.motion_init(1.0, [0, 1, 0, 0.5])
MST = c.massless.state_from_phase(-0.4137, [0, 0.6, 0.3, 0.7])
# a certified orbit where the build has the method (Arb); elsewhere a
# stand-in: the type checks come before the C call either way
ORBIT = c.CertifiedOrbit(SYS, ST) if c.method_available('certified') \
    else object.__new__(c.CertifiedOrbit)


def masked(v, shape=(2,)):
    """A masked array of V's values, the first masked."""
    a = np.ma.masked_array(np.broadcast_to(np.asarray(v), shape).copy())
    a[(0,) * a.ndim] = np.ma.masked
    return a


REAL_BAD = [None, '1.5', b'1', object(), [None], {'x': 1}]
INT_BAD = [None, '3', b'3', object(), [None], 2.5]

# Hand-written functions: {name: [(kind, call of the bad value)]}, kind
# 'real', 'int', 'array4' (four numbers), 'reals' (an array of numbers),
# 'pair' (two numbers, or None), 'state', 'enum' (an integer or a name:
# no strings), 'orbit' (a CertifiedOrbit).
HAND = {
    'discrete.orbit': [('int', lambda v: d.orbit(SYS, ST, v)),
                       ('state', lambda v: d.orbit(SYS, v, 2))],
    'discrete.step_eh_n': [('int', lambda v: d.step_eh_n(SYS, ST, v)),
                           ('state', lambda v: d.step_eh_n(SYS, v, 2))],
    'discrete.fate': [('int', lambda v: d.fate(SYS, ST, v)),
                      ('int', lambda v: d.fate(SYS, ST, 9, reversal_cap=v)),
                      ('state', lambda v: d.fate(SYS, v, 9))],
    'discrete.fate_phase': [
        ('int', lambda v: d.fate_phase(FIG3, [0, 0.3, 0, 0.8], v)),
        ('array4', lambda v: d.fate_phase(FIG3, v, 9))],
    'discrete.basins': [
        ('real', lambda v: d.basins(FIG3, v, 0.1, 0.5, 3, 9)),
        ('real', lambda v: d.basins(FIG3, 0.8, v, 0.5, 3, 9)),
        ('real', lambda v: d.basins(FIG3, 0.8, 0.1, v, 3, 9)),
        ('int', lambda v: d.basins(FIG3, 0.8, 0.1, 0.5, v, 9)),
        ('int', lambda v: d.basins(FIG3, 0.8, 0.1, 0.5, 3, v))],
    'discrete.fates_phase': [
        ('reals', lambda v: d.fates_phase(FIG3, v, 0.8, 9)),
        ('reals', lambda v: d.fates_phase(FIG3, 0.3, v, 9)),
        ('int', lambda v: d.fates_phase(FIG3, 0.3, 0.8, v))],
    'discrete.basin_boundaries': [
        ('real', lambda v: d.basin_boundaries(FIG3, v, 0.1, 0.5, 3, 9)),
        ('real', lambda v: d.basin_boundaries(FIG3, 0.8, v, 0.5, 3, 9)),
        ('real', lambda v: d.basin_boundaries(FIG3, 0.8, 0.1, v, 3, 9)),
        ('int', lambda v: d.basin_boundaries(FIG3, 0.8, 0.1, 0.5, v, 9)),
        ('int', lambda v: d.basin_boundaries(FIG3, 0.8, 0.1, 0.5, 3, v))],
    'smooth.path': [('reals', lambda v: c.smooth.path(MOTION, v)),
                    ('pair', lambda v: c.smooth.path(MOTION, [1.0], v))],
    'smooth.path_advance': [('real', lambda v: c.smooth.path_advance(
        MOTION, c.smooth.path_init(0), v))],
    'massless.orbit': [
        ('real', lambda v: c.massless.orbit(v, MST, 2)),
        ('int', lambda v: c.massless.orbit(-0.4137, MST, v)),
        ('state', lambda v: c.massless.orbit(-0.4137, v, 2))],
    'sweep.sigma4': [('reals', lambda v: c.sweep.sigma4(v, 0.5, 1)),
                     ('reals', lambda v: c.sweep.sigma4([0.5], v, 1)),
                     ('int', lambda v: c.sweep.sigma4([0.5], 0.5, v))],
    'sweep.stability': [('reals', lambda v: c.sweep.stability(v, [0.5])),
                        ('reals', lambda v: c.sweep.stability([0.5], v))],
    'sweep.grid_point': [
        ('real', lambda v: c.sweep.grid_point(v, 1, 3, 1)),
        ('real', lambda v: c.sweep.grid_point(0, v, 3, 1)),
        ('int', lambda v: c.sweep.grid_point(0, 1, v, 1)),
        ('int', lambda v: c.sweep.grid_point(0, 1, 3, v))],
    'certified_orbit_new': [
        ('state', lambda v: c.certified_orbit_new(SYS, v)),
        ('enum', lambda v: c.certified_orbit_new(SYS, ST, v))],
    'certified_orbit_new_exact': [
        ('real', lambda v: c.certified_orbit_new_exact(v, 1, 1, 1, 0.5)),
        ('real', lambda v: c.certified_orbit_new_exact(1, v, 1, 1, 0.5)),
        ('int', lambda v: c.certified_orbit_new_exact(1, 1, v, 1, 0.5)),
        ('real', lambda v: c.certified_orbit_new_exact(1, 1, 1, v, 0.5)),
        ('real', lambda v: c.certified_orbit_new_exact(1, 1, 1, 1, v)),
        ('pair', lambda v: c.certified_orbit_new_exact(1, 1, 1, (1, 1), v)),
        ('real', lambda v: c.certified_orbit_new_exact(1, 1, 1, 1, 0.5,
                                                       theta=v)),
        ('real', lambda v: c.certified_orbit_new_exact(1, 1, 1, 1, 0.5,
                                                       tau=v)),
        ('pair', lambda v: c.certified_orbit_new_exact(1, 1, 1, 1, 0.5,
                                                       peg=v)),
        ('enum', lambda v: c.certified_orbit_new_exact(1, 1, 1, 1, 0.5,
                                                       request=v))],
    'certified_orbit_new_phase': [
        ('array4', lambda v: c.certified_orbit_new_phase(SYS, v)),
        ('real', lambda v: c.certified_orbit_new_phase(SYS, [0, 1, 0, 0.5],
                                                       v)),
        ('pair', lambda v: c.certified_orbit_new_phase(SYS, [0, 1, 0, 0.5],
                                                       peg=v)),
        ('enum', lambda v: c.certified_orbit_new_phase(SYS, [0, 1, 0, 0.5],
                                                       request=v))],
    'certified_orbit_new_phase_exact': [
        ('real', lambda v: c.certified_orbit_new_phase_exact(v, 1, 1, 0.5)),
        ('real', lambda v: c.certified_orbit_new_phase_exact(1, v, 1, 0.5)),
        ('real', lambda v: c.certified_orbit_new_phase_exact(1, 1, v, 0.5)),
        ('real', lambda v: c.certified_orbit_new_phase_exact(1, 1, 1, v)),
        ('enum', lambda v: c.certified_orbit_new_phase_exact(1, 1, 1, 0.5,
                                                             request=v))],
    'certified_orbit_omega': [
        ('orbit', lambda v: c.certified_orbit_omega(v))],
    'certified_orbit_sample': [
        ('orbit', lambda v: c.certified_orbit_sample(v, 0.0)),
        ('real', lambda v: c.certified_orbit_sample(ORBIT, v)),
        ('int', lambda v: c.certified_orbit_sample(ORBIT, 0.0, v))],
    'certified_orbit_state': [
        ('orbit', lambda v: c.certified_orbit_state(v))],
    'certified_orbit_fate': [
        ('int', lambda v: c.certified_orbit_fate(ORBIT, v)),
        ('int', lambda v: c.certified_orbit_fate(ORBIT, 0, reversal_cap=v)),
        ('orbit', lambda v: c.certified_orbit_fate(v, 0))],
    'certified_orbit_cap': [('int', lambda v: c.certified_orbit_cap(ORBIT,
                                                                    v)),
                            ('orbit', lambda v: c.certified_orbit_cap(v,
                                                                      100))],
    'certified_orbit_step': [('orbit', lambda v: c.certified_orbit_step(v))],
    'certified_orbit_collisions': [
        ('orbit', lambda v: c.certified_orbit_collisions(v))],
    'certified_orbit_free': [('orbit', lambda v: c.certified_orbit_free(v))],
    'method_available': [('enum', lambda v: c.method_available(v))],
}
EXEMPT = {
    'scene.run_scene': 'scene values are text by design (the file\'s); '
                       'test_scene checks its TypeErrors',
    'scene.to_ini': 'as run_scene',
    'dataset.atlas': 'a scene, as run_scene; test_atlas checks its '
                     'TypeError and ValueErrors (threads, chunks)',
    'equation.eq': 'inputs are numbers or text by design; test_equation '
                   'checks None and bool',
    'equation.labels': 'no parameters',
    'error_class': 'a status: any key (unknown ones give ChaplyginError)',
    'as_columns': 'a result, not an input of the library',
}


def bad_values(kind):
    if kind == 'int':
        return INT_BAD + [masked(3), [3, np.ma.masked]]
    if kind == 'real':
        return REAL_BAD + [masked(0.5), np.ma.masked_array(0.5, mask=True)]
    if kind == 'array4':
        return [None, [None, 0, 0, 0.8], ['0', '0.3', '0', '0.8'],
                masked([0, 0.3, 0, 0.8], (4,)), [0, 0.3, np.ma.masked, 0.8]]
    if kind == 'reals':
        # numpy.ma.masked in a list: np.asarray would make it NaN
        return [None, [None], ['1.5'], [object()], masked([0.5, 1.0]),
                [0.5, np.ma.masked], [[0.5], [np.ma.masked]]]
    if kind == 'pair':          # None: the default
        return [[None, 1.0], ['1', '2'], masked([0.5, 1.0]),
                (np.ma.masked, 1.0)]
    if kind == 'enum':          # a name is taken: no strings
        return [v for v in INT_BAD if not isinstance(v, str)] + \
            [masked(3), [3, np.ma.masked]]
    if kind == 'orbit':         # not None: free takes it (C's null)
        return ['1', object(), ST, SYS, [ORBIT]]
    if kind == 'state':
        return [None, '1', object(), np.ma.masked_array(
            np.zeros(2, c.DiscreteState.dtype))]
    raise KeyError(kind)


def generated_cases():
    """(cname, parameter name, kind, call of a bad value) for every input
    of every generated function."""
    out = []
    for cname in sorted(_generated.WRAPPED):
        f = _generated.WRAPPED[cname]
        params = [p for p in _core.SPEC[cname]
                  if p[1] in ('in', 'in_array', 'in_struct')]
        rng = np.random.default_rng(12)
        good = [None if extra.get('nullable') else
                draw(rng, name, ctype, kind, dims, ())
                for name, kind, ctype, dims, extra in params]
        for k, (name, kind, ctype, dims, extra) in enumerate(params):
            if kind == 'in_struct':
                what = 'state'
            elif kind == 'in_array':
                what = 'array%d' % dims
            elif ctype == 'double':
                what = 'real'
            elif ctype.startswith(('int', 'unsigned', 'size_t', 'long')) \
                    and name != 'request':
                what = 'int'
            else:
                what = 'enum'         # takes names too ('theta,tau'): no text

            def call(v, k=k, f=f, good=good):
                args = list(good)
                args[k] = v
                return f(*args)
            out.append(('%s:%s' % (cname, name), what, extra, call))
    return out


GEN = generated_cases()


def bad_for(what, extra):
    if what.startswith('array'):
        n = int(what[5:])
        vals = [[None] * n, ['1'] * n, masked([0.5] * n, (n,))]
        return vals if extra.get('nullable') else [None] + vals
    if what == 'enum':
        return [v for v in bad_values('int') if not isinstance(v, str)]
    return bad_values(what)


@pytest.mark.parametrize('case', GEN, ids=[g[0] for g in GEN])
def test_generated_type_errors(case):
    name, what, extra, call = case
    for v in bad_for(what, extra):
        with pytest.raises(TypeError):
            call(v)


def hand_ids():
    return [(n, i) for n, calls in HAND.items() for i in range(len(calls))]


@pytest.mark.parametrize('name,i', hand_ids())
def test_hand_type_errors(name, i):
    kind, call = HAND[name][i]
    for v in bad_values(kind):
        with pytest.raises(TypeError):
            call(v)


def test_every_function_checked():
    """The walk finds every public function: generated, or in HAND or
    EXEMPT (and nothing there that the package lacks)."""
    public = public_functions()
    generated = {id(f) for f in _generated.WRAPPED.values()}
    hand = {n for n, f in public.items() if id(f) not in generated}
    assert len(hand) >= len(HAND) and len(GEN) > 150
    for n in hand:
        assert any(k == n or k.endswith('.' + n) for k in
                   list(HAND) + list(EXEMPT)), 'not checked: %s' % n
    for k in list(HAND) + list(EXEMPT):
        assert any(k == n or k.endswith('.' + n) for n in hand), k


def test_the_issue_examples():
    """sigma4(None, 1/3) and friends: TypeError, not DomainError; a masked
    array's message says what to do."""
    with pytest.raises(TypeError, match='real numbers expected'):
        d.sigma4(None, 1 / 3, dir=1)
    with pytest.raises(TypeError):
        d.sigma4(np.array([1.0, None]), 1 / 3, dir=1)
    # peg is optional (the header's default None: the state's own origin)
    a = d.scaled_state(SYS, [0, 1, 0, 0.5], 0.0, None)
    b = d.scaled_state(SYS, [0, 1, 0, 0.5], peg=[0.0, 0.0])
    assert a.st == b.st and a.m == b.m == d.scaled_state(SYS, [0, 1, 0, 0.5]).m
    with pytest.raises(TypeError):
        d.scaled_state(SYS, [0, 1, 0, 0.5], None)
    with pytest.raises(TypeError, match=r'masked array.*filled\(np.nan\)'):
        d.sigma4(masked([1.0, 2.0]), 1 / 3, dir=1)
    # numbers of other kinds are numbers: Fraction, Decimal, NumPy's, bool
    from decimal import Decimal
    from fractions import Fraction
    want = d.sigma4(1.0, 1 / 3, dir=1)
    assert d.sigma4(Fraction(1), Fraction(1, 3), dir=1) == want
    assert d.sigma4(Decimal(1), np.float32(1) / 3, dir=1) == \
        d.sigma4(1.0, float(np.float32(1) / 3), dir=1)
    assert d.sigma4(np.array([1, 1], dtype=object), 1 / 3,
                    dir=1).tolist() == [want, want]
    # a masked array's data, filled: the masked points fail alone
    r = d.sigma4(masked([1.0, 1.0]).filled(np.nan), 1 / 3, dir=1,
                 errors='return')
    assert r.status.tolist() == [c.EDOM, 0] and r.sigma4[1] == want
