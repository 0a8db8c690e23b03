"""The certified method from Python (chaplygin.CertifiedOrbit, the
certified_orbit_* functions, method='certified'), against routes written
here:
- E, H, dir, the reversal, V- and V+ of every collision from the exact
  map in fractions.Fraction: (3.7) E' = E + C1 H^2, H' = C2 H with
  C1 = -Delta^2/(2 (1 + b^2)^2 (1 + b'^2)), C2 = (1 + b b')/(1 + b^2),
  b = L0 + D at the end the peg leaves and b' the other end, the reversal
  decided by the sign of min over the path of 2E (1 + l^2) - H^2, and
  V^2 = 2E - H^2/(1 + l^2); each rounded by float(Fraction) (correctly
  rounded, ties to even) or by an exact square-root rounding;
- the time and the peg of straight motions at rational speeds (H = 0),
  exact rationals;
- the orbit's first step against discrete.step(method='certified') (the
  library's one-step route: a fresh orbit per call), bit for bit;
- heading and time within a few ulps of the closed form (another method).
The whole file is skipped in a build without Arb, where the method is
not available (test_method_available checks that claim against
config.h)."""
import ctypes
import gc
import math
import pickle
import threading
from fractions import Fraction as F

import numpy as np
import pytest

import chaplygin as c
from chaplygin import discrete as d
from conftest import build

AVAILABLE = c.method_available('certified') == 1
need_arb = pytest.mark.skipif(not AVAILABLE,
                              reason='a build without Arb: no certified '
                                     'method')


# ---- the exact route ------------------------------------------------------

def ref_step(L0, Delta, dir, E, H):
    """One collision of the exact map from the post-collision state (dir,
    E, H) of the slot (L0, Delta), all Fractions: (reversal, dir', E', H',
    Vminus^2, Vplus'^2)."""
    la, lb = (L0, L0 + Delta) if dir > 0 else (L0 + Delta, L0)
    lmin2 = F(0) if la * lb <= 0 else min(la * la, lb * lb)
    g = 2 * E * (1 + lmin2) - H * H     # min over the path of 2E(1+l^2)-H^2
    assert not (g == 0 and lmin2 == 0), 'the spinning state'
    rev = g <= 0                        # a turning point at the end: one
    b, bp = (la, lb) if rev else (lb, la)
    C1 = -Delta ** 2 / (2 * (1 + b * b) ** 2 * (1 + bp * bp))
    C2 = (1 + b * bp) / (1 + b * b)
    E1, H1 = E + C1 * H * H, C2 * H
    vm2 = 2 * E - H * H / (1 + b * b)
    vp2 = 2 * E1 - H1 * H1 / (1 + bp * bp)
    return rev, -dir if rev else dir, E1, H1, vm2, vp2


def nearest_sqrt(q):
    """The double nearest to sqrt(q) (q a nonnegative Fraction), ties to
    even, decided exactly: x is it when q lies between the squares of the
    midpoints of x and its neighbours."""
    x = math.sqrt(float(q))
    for _ in range(8):
        lo = (F(x) + F(math.nextafter(x, 0))) / 2
        hi = (F(x) + F(math.nextafter(x, math.inf))) / 2
        if q < lo * lo:
            x = math.nextafter(x, 0)
        elif q > hi * hi:
            x = math.nextafter(x, math.inf)
        else:
            if q == lo * lo or q == hi * hi:    # a tie: the even one
                m = lo if q == lo * lo else hi
                y = math.nextafter(x, 0 if m is lo else math.inf)
                if (struct_bits(x) & 1) and not (struct_bits(y) & 1):
                    x = y
            return x
    raise AssertionError('nearest_sqrt did not settle')


def test_nearest_sqrt():
    """The route's square root: exact squares, the neighbours of a
    midpoint's square, and midpoints themselves (ties to even: 1 + 2^-53
    lies between 1 and 1 + 2^-52, 1 + 3 2^-53 between 1 + 2^-52 and
    1 + 2^-51)."""
    assert nearest_sqrt(F(9, 4)) == 1.5 and nearest_sqrt(F(0)) == 0.0
    m = 1 + F(1, 2 ** 53)
    assert nearest_sqrt(m * m) == 1.0
    assert nearest_sqrt(m * m + F(1, 2 ** 200)) == 1 + 2.0 ** -52
    assert nearest_sqrt(m * m - F(1, 2 ** 200)) == 1.0
    m = 1 + F(3, 2 ** 53)
    assert nearest_sqrt(m * m) == 1 + 2.0 ** -51
    assert nearest_sqrt(F(2)) == math.sqrt(2)   # IEEE sqrt: correctly rounded


def struct_bits(x):
    return int.from_bytes(np.float64(x).tobytes(), 'little')


def same_bits(a, b):
    return np.asarray(a, np.float64).tobytes() == \
        np.asarray(b, np.float64).tobytes()


def check_rounded(x, exact, bounds, what, tight=True):
    """X is the double nearest to EXACT, and BOUNDS = (lo, hi) enclose EXACT
    with lo, hi each X or its neighbour; TIGHT (a value the library holds
    as an exact rational: E, H, a straight motion's time): lo and hi are
    the doubles next to EXACT, equal where EXACT is a double.  (A ball's
    bounds are its ends rounded outwards: they may be one double wider,
    as the header says: test_ball_bounds_at_a_double.)"""
    assert x == float(exact), '%s: %r, nearest %r' % (what, x, float(exact))
    lo, hi = bounds
    assert F(lo) <= exact <= F(hi), (what, bounds, exact)
    assert lo == x or math.nextafter(lo, math.inf) == x, (what, bounds)
    assert hi == x or math.nextafter(hi, -math.inf) == x, (what, bounds)
    if tight:
        assert F(math.nextafter(lo, math.inf)) > exact or F(lo) == exact, \
            (what, bounds)
        assert F(math.nextafter(hi, -math.inf)) < exact or F(hi) == exact, \
            (what, bounds)
        if F(x) == exact:
            assert lo == hi == x, (what, bounds)


def compare_with_exact(orbit, L0, Delta, dir, E, H, n):
    """N steps of ORBIT against the exact route from (L0, Delta, dir, E, H);
    returns the reversals seen."""
    reversals = 0
    for k in range(1, n + 1):
        out, ev, b = orbit.step()
        rev, dir, E, H, vm2, vp2 = ref_step(L0, Delta, dir, E, H)
        where = 'collision %d' % k
        assert ev.reversal == rev, where
        assert out.dir == dir, where
        check_rounded(out.E, E, b.E, 'E, ' + where)
        check_rounded(out.H, H, b.H, 'H, ' + where)
        assert ev.Vminus == dir * nearest_sqrt(vm2), where
        assert out.V == dir * nearest_sqrt(vp2), where
        assert orbit.collisions() == k
        reversals += rev
    return reversals


# ---- states ---------------------------------------------------------------

FIG3 = (-0.5, 1.0)


def phase_state(L0, Delta, V, Omega, theta=0.0, tau=0.0):
    sys_ = d.init(L0, Delta)
    return sys_, d.state_from_phase(sys_, [0.0 if V > 0 else Delta, V, theta,
                                           Omega], tau)


def random_states(n, seed=28):
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        L0, Delta = rng.uniform(-3, 3), rng.uniform(0.05, 3)
        V, Omega = rng.uniform(-2, 2), rng.uniform(-2.5, 2.5)
        if V == 0:
            continue
        out.append(phase_state(L0, Delta, V, Omega, rng.uniform(-4, 4),
                               0.25))
    return out


# ---- against the exact route ---------------------------------------------

@need_arb
def test_rational_start_against_fractions():
    """L0 = 1/3, Delta = 2/7, E = 5/11, H = -3/13 exactly (a Fraction, pairs
    and a number: three spellings of exact ratios), 8 collisions; from
    l = -7/5 towards 0 with H^2/(2E) - 1 = 65/32: reversals."""
    o = c.CertifiedOrbit.exact(F(1, 3), (2, 7), 1, (5, 11), F(-3, 13))
    compare_with_exact(o, F(1, 3), F(2, 7), 1, F(5, 11), F(-3, 13), 8)
    o = c.certified_orbit_new_exact((-7, 5), (2, 7), 1, 1, (9, 4))
    assert compare_with_exact(o, F(-7, 5), F(2, 7), 1, F(1), F(9, 4), 8) > 0


@need_arb
def test_turning_point_at_the_far_end():
    """L0 = 1, Delta = 1, from the rear (l = 2) towards l = 1 with E = 1,
    H = 2: 2E (1 + 1^2) = H^2, the turning point exactly at the far end,
    which counts as a reversal (Dc = 0); then 4 collisions against the
    exact route."""
    o = c.certified_orbit_new_exact(1, 1, -1, 1, 2)
    out, ev, b = o.step()
    assert ev.reversal == 1 and same_bits(ev.Dc, 0.0) and out.dir == 1
    assert ref_step(F(1), F(1), -1, F(1), F(2))[0]
    o = c.certified_orbit_new_exact(1, 1, -1, 1, 2)
    assert compare_with_exact(o, F(1), F(1), -1, F(1), F(2), 4) >= 1


@need_arb
@pytest.mark.parametrize('V,Omega,reverses', [(0.7, 0.8, False),
                                              (0.3, 0.8, True)])
def test_step_against_fractions(V, Omega, reverses):
    """A state of Figure 3's line (L0 = -1/2, Delta = 1) without a reversal
    and one with: the orbit's E, H, V after each of 12 collisions are the
    exact map's from the exact start (the doubles of the state) rounded,
    and the first is discrete.step(method='certified')'s."""
    sys_, st = phase_state(*FIG3, V, Omega)
    o = c.CertifiedOrbit(sys_, st)
    first = d.step(sys_, st, method='certified')
    rev, _, E1, H1, _, _ = ref_step(F(-0.5), F(1), st.dir, F(st.E), F(st.H))
    assert rev == reverses
    assert first.out.E == float(E1) and first.out.H == float(H1)
    assert first.ev.reversal == reverses
    compare_with_exact(o, F(-0.5), F(1), st.dir, F(st.E), F(st.H), 12)


@need_arb
def test_sample_against_fractions():
    """Dense output (orbit.sample): after the first collision of Figure 3's
    reversing state (V+ = 0.3), V at D on the way out, at the turning point
    and on the way back is the double nearest to sqrt(2E - H^2/(1 + l^2))
    of the exact start, Omega to H/(1 + l^2), decided in fractions; theta
    and tau at the start are the start's and the rest within 1e-13 of the
    closed form's segment flow; a D past the turning point is refused."""
    sys_, st = phase_state(*FIG3, 0.3, 0.8)
    o = c.CertifiedOrbit(sys_, st)
    E, H = F(st.E), F(st.H)
    with pytest.raises(ValueError):
        o.sample(0.0)                   # no segment yet
    step = o.step()
    assert step.ev.reversal
    Dc = step.ev.Dc
    for D, leg in ((0.0, 0), (Dc / 3, 0), (Dc / 2, 1), (0.0, 1), (Dc, 2)):
        s = o.sample(D, leg)
        l = F(-0.5) + F(D)
        one_l2 = 1 + l * l
        if leg == 2:
            assert s.V == 0.0
            one_l2 = H * H / (2 * E)    # 1 + lt^2 = 1 - q
        else:
            v2 = 2 * E - H * H / one_l2
            assert s.V == (1 if leg == 0 else -1) * nearest_sqrt(v2)
        assert s.Omega == float(H / one_l2)
        if leg != 2:
            flow = d.segment_flow(sys_, st, D, leg)
            assert abs(s.theta - flow.dtheta) <= 1e-13
            assert abs(s.tau - flow.dtau) <= 1e-13
    assert o.sample(0.0, 0).theta == st.theta and o.sample(0.0, 0).tau == 0.0
    with pytest.raises(c.DomainError):
        o.sample(min(2 * Dc, 1.0), 0)
    with pytest.raises(ValueError):
        o.sample(0.1, 3)


@need_arb
def test_random_orbits_against_fractions():
    """40 random starts, 1 to 5 collisions each: every E, H, V, reversal
    and direction the exact map's; reversals among them."""
    reversals = steps = 0
    for i, (sys_, st) in enumerate(random_states(40)):
        n = 1 + i % 5
        o = c.CertifiedOrbit(sys_, st, 0)
        reversals += compare_with_exact(o, F(sys_.L0), F(sys_.Delta), st.dir,
                                        F(st.E), F(st.H), n)
        steps += n
    assert steps > 100 and reversals > steps // 20


U = 2.0 ** -52          # the spacing of the doubles in [1, 2)


@need_arb
@pytest.mark.parametrize('E,want,other', [(2.0, 2 - 4 * U, 2 - 5 * U),
                                          (2 - U, 2 - 6 * U, 2 - 5 * U)])
def test_tie_in_energy(E, want, other):
    """E' exactly at a midpoint: L0 = 0, Delta = 1, H = 3 2^-25, so that
    C1 = -1/8 and E' = E - 9 2^-53.  From E = 2: 2 - 4.5 U, between 2 - 4 U
    (even, above) and 2 - 5 U; from E = 2 - U: 2 - 5.5 U, between 2 - 5 U
    and 2 - 6 U (even, below): ties to even, once up and once down (the
    exact route's float(Fraction) agrees)."""
    st = c.DiscreteState(dir=1, E=E, H=3 * 2.0 ** -25)
    sys_ = d.init(0.0, 1.0)
    assert float(ref_step(F(0), F(1), 1, F(E), F(3, 2 ** 25))[2]) == want
    assert d.step(sys_, st, 0, method='certified').out.E == want
    out, ev, b = c.CertifiedOrbit(sys_, st).step()
    assert out.E == want and out.H == 3 * 2.0 ** -26
    assert b.E == (min(want, other), max(want, other))
    assert b.H == (3 * 2.0 ** -26, 3 * 2.0 ** -26)      # exact: a double


@need_arb
def test_straight_motion_exact_time_and_peg():
    """H = 0 at the rational speed V = 3/5 (E = 9/50), Delta = 1/3 exactly:
    after k collisions tau = tau0 + 5k/9 and the peg at k/3 along theta = 0,
    rounded once (the orbit sums exactly: a sum of rounded increments, as
    discrete.orbit with method='certified' makes, drifts from it)."""
    tau0 = 0.1
    o = c.CertifiedOrbit.exact(0.25, F(1, 3), 1, F(9, 50), 0, 0.0, tau0)
    drift = 0
    tau_sum = tau0
    for k in range(1, 41):
        out, ev, b = o.step()
        tau = F(tau0) + F(5 * k, 9)
        check_rounded(out.tau, tau, b.tau, 'tau %d' % k)
        check_rounded(out.peg[0], F(k, 3), b.peg_x, 'peg %d' % k,
                      tight=False)
        assert out.peg[1] == 0.0 and out.theta == 0.0 and out.E == 9 / 50
        assert ev.dtau == float(F(5, 9)) and out.V == 0.6
        tau_sum += ev.dtau
        drift += tau_sum != out.tau
    assert drift > 0


@need_arb
@need_arb
def test_ball_bounds_at_a_double():
    """The header: a ball's bounds (heading, time, peg) are its ends rounded
    outwards: they enclose the exact value, each the result or its
    neighbour, and may be one double wider than the tightest pair where
    the value is a double, as here: the peg of the straight motion above
    after 3 collisions is at x = 3 (1/3) = 1 exactly, but Delta = 1/3 is
    held as a ball, so the sum cannot know it."""
    o = c.CertifiedOrbit.exact(0.25, F(1, 3), 1, F(9, 50), 0)
    for _ in range(3):
        out, ev, b = o.step()
    assert out.peg[0] == 1.0
    check_rounded(out.peg[0], F(1), b.peg_x, 'peg x', tight=False)
    assert b.peg_x == (math.nextafter(1.0, 0.0), math.nextafter(1.0, 2.0))


@need_arb
def test_the_orbit_does_not_round_between_collisions():
    """Along 12 collisions of Figure 3's line (L0 = -1/2, Delta = 1, from
    V+ = 0.31, Omega+ = 0.9), discrete.orbit with method='certified'
    certifies each collision from the rounded state before it (the exact
    map from each rounded state, rounded), the orbit from its exact start
    (the exact map iterated, rounded once): each agrees with its own route,
    and the two differ from the second collision on."""
    sys_, st = phase_state(*FIG3, 0.31, 0.9)
    states = d.orbit(sys_, st, 12, request=0, method='certified')
    o = c.CertifiedOrbit(sys_, st, 0)
    E, H, dir = F(st.E), F(st.H), st.dir
    differ = []
    for k in range(1, 13):
        prev = c.DiscreteState.from_record(states[k - 1])
        _, dir1, E1, H1, _, _ = ref_step(F(-0.5), F(1), prev.dir,
                                         F(prev.E), F(prev.H))
        assert (states[k]['dir'], states[k]['E'], states[k]['H']) == \
            (dir1, float(E1), float(H1)), k
        _, dir, E, H, _, _ = ref_step(F(-0.5), F(1), dir, E, H)
        out = o.step().out
        assert (out.dir, out.E, out.H) == (dir, float(E), float(H)), k
        if out.E != states[k]['E']:
            differ.append(k)
    assert differ == list(range(2, 13)), differ


# ---- against the library's one-step route ----------------------------------

STEP_FIELDS = ('dir', 'E', 'H', 'theta', 'tau', 'peg', 'V')
EVENT_FIELDS = ('reversal', 'Dc', 'Dminus', 'Dplus', 'Vminus', 'dtheta',
                'dtau')


@need_arb
def test_first_step_is_discrete_step():
    """The orbit's first step, every field, bit for bit, equals
    discrete.step(method='certified') from the same state (request all),
    for 24 random states; a start given as ratios x/1 is the same orbit;
    and near the closed form (the default method: a consistency check of
    two routes, within 2^-40, the closed form losing digits to
    cancellation near a turning point)."""
    for sys_, st in random_states(24, seed=5):
        a_out, a_ev = d.step(sys_, st, method='certified')
        o = c.certified_orbit_new(sys_, st)
        r = c.certified_orbit_step(o)
        for f in STEP_FIELDS:
            assert same_bits(getattr(r.out, f), getattr(a_out, f)), f
        for f in EVENT_FIELDS:
            assert same_bits(getattr(r.ev, f), getattr(a_ev, f)), f
        e = c.CertifiedOrbit.exact((sys_.L0, 1), (sys_.Delta, 1), st.dir,
                                   (st.E, 1), (st.H, 1), st.theta, st.tau,
                                   st.peg)
        assert e.step() == r
        cf_out, cf_ev = d.step(sys_, st)
        pairs = [(getattr(r.out, f), getattr(cf_out, f), f)
                 for f in ('E', 'H', 'theta', 'tau')]   # (V: 0 unknown)
        pairs += [(getattr(r.ev, f), getattr(cf_ev, f), f)
                  for f in ('dtheta', 'dtau', 'Vminus')]
        for x, y, f in pairs:
            assert abs(x - y) <= 2.0 ** -40 * max(abs(x), abs(y)), f


@need_arb
def test_request():
    """What the request leaves out is 0 in the orbit's state and bounds
    (discrete.step copies it from the input instead); E, H alike."""
    sys_, st = phase_state(*FIG3, 0.7, 0.8, theta=0.4, tau=1.5)
    full = c.CertifiedOrbit(sys_, st).step()
    part = c.CertifiedOrbit(sys_, st, 'tau').step()
    assert part.out.tau == full.out.tau and part.out.E == full.out.E
    assert part.out.theta == 0.0 and part.out.peg == (0.0, 0.0)
    assert part.bounds.theta == (0.0, 0.0) and part.bounds.tau == \
        full.bounds.tau
    step = d.step(sys_, st, 'tau', method='certified')
    assert step.out.theta == st.theta and step.out.tau == full.out.tau


@need_arb
def test_method_name_everywhere():
    """method='certified' (any spelling the other names take, or the enum)
    in discrete.step, vectorised (equal to scalar calls, bit for bit), and
    discrete.orbit (equal to chained steps)."""
    sys_, st = phase_state(*FIG3, 0.3, 0.8)
    one = d.step(sys_, st, method='certified')
    assert d.step(sys_, st, method='Certified') == one
    assert d.step(sys_, st, method=c.Method.CERTIFIED) == one
    assert d.step(sys_, st, method=c.CERTIFIED) == one
    sys_ = d.init(-0.5, 1.0)
    states = [phase_state(-0.5, 1.0, V, 0.8)[1] for V in (0.3, 0.7, -0.4)]
    vec = d.step(sys_, states, method='certified')
    for i, s in enumerate(states):
        r = d.step(sys_, s, method='certified')
        assert c.DiscreteState.from_record(vec.out[i]) == r.out
        assert c.DiscreteEvent.from_record(vec.ev[i]) == r.ev
    orb = d.orbit(sys_, states[0], 5, method='certified')
    s = states[0]
    for k in range(1, 6):
        s = d.step(sys_, s, method='certified', return_ev=False)
        assert c.DiscreteState.from_record(orb[k]) == s


# ---- errors ----------------------------------------------------------------

@need_arb
def test_cap():
    """With a cap of 64 bits the exact state outgrows it: ECAP raised as
    CertificationCapError, the orbit unchanged (its count, and its next
    step once the cap is raised equals a fresh orbit's)."""
    o = c.CertifiedOrbit.exact((1, 3), (2, 7), 1, (5, 11), (-3, 13))
    o.cap(64)
    done = 0
    with pytest.raises(c.CertificationCapError) as info:
        for _ in range(64):
            o.step()
            done += 1
    e = info.value
    assert 0 < done < 64 and o.collisions() == done
    assert e.status == c.ECAP == c.Status.ECAP and e.name == 'CHAPLYGIN_ECAP'
    assert e.function == 'chaplygin_certified_orbit_step'
    assert e.message == c.strerror(c.ECAP) and isinstance(e, ArithmeticError)
    assert c.error_class(c.ECAP) is c.CertificationCapError
    with pytest.raises(c.CertificationCapError):
        o.step()                         # again: still capped
    c.certified_orbit_cap(o, 2 ** 20)
    fresh = c.CertifiedOrbit.exact((1, 3), (2, 7), 1, (5, 11), (-3, 13))
    for _ in range(done):
        fresh.step()
    assert o.step() == fresh.step() and o.collisions() == done + 1
    for bits in (63, 2 ** 30 + 1):
        with pytest.raises(c.InvalidArgumentError):
            o.cap(bits)
    o.cap(2 ** 30)


@need_arb
def test_errors():
    """The statuses of the orbit's functions, as the package's exceptions."""
    sys_ = d.init(0.5, 1.0)
    new = c.CertifiedOrbit
    with pytest.raises(c.InvalidArgumentError):         # dir
        new(sys_, c.DiscreteState(dir=0, E=1.0, H=0.5))
    with pytest.raises(c.InvalidArgumentError):
        c.certified_orbit_new_exact(1, 1, 2, 1, 0.5)
    with pytest.raises(c.InvalidArgumentError):         # request bits
        new(sys_, c.DiscreteState(dir=1, E=1.0, H=0.5), 8)
    for E in (0.0, -1.0):                               # E <= 0
        with pytest.raises(c.StateError):
            new(sys_, c.DiscreteState(dir=1, E=E, H=0.5))
        with pytest.raises(c.StateError):
            c.certified_orbit_new_exact(1, 1, 1, E, 0.5)
        with pytest.raises(c.StateError):
            d.step(sys_, c.DiscreteState(dir=1, E=E, H=0.5),
                   method='certified')
    with pytest.raises(c.StateError):                   # (V+)^2 = 0 exactly
        c.certified_orbit_new_exact(1, 1, 1, 1, 2)
    with pytest.raises(c.StateError):                   # V of the wrong sign
        new(sys_, c.DiscreteState(dir=1, E=1.0, H=0.5, V=-1.0))
    with pytest.raises(c.DomainError):
        new(sys_, c.DiscreteState(dir=1, E=float('nan'), H=0.5))
    with pytest.raises(c.DomainError):                  # Delta <= 0
        c.certified_orbit_new_exact(1, (-1, 1), 1, 1, 0.5)
    with pytest.raises(c.DomainError):                  # a zero denominator
        c.certified_orbit_new_exact((1, 0), 1, 1, 1, 0.5)
    # the spinning state: 2E = H^2 on a path through l = 0
    o = c.certified_orbit_new_exact((-1, 2), 1, 1, 2, 2)
    with pytest.raises(c.SpinError):
        o.step()
    assert o.collisions() == 0
    # ratios that are no doubles are refused, not rounded
    for bad in ((F(1, 3), 1), 2 ** 53 + 1, F(2 ** 60 + 1, 3)):
        with pytest.raises(ValueError, match='not a double'):
            c.certified_orbit_new_exact(bad, 1, 1, 1, 0.5)
    with pytest.raises(TypeError):
        c.certified_orbit_new_exact((1, 2, 3), 1, 1, 1, 0.5)
    with pytest.raises(TypeError):
        new(sys_, [c.DiscreteState(dir=1, E=1.0, H=0.5)] * 2)   # one state
    with pytest.raises(TypeError):
        new((0.5, 1.0), c.DiscreteState(dir=1, E=1.0, H=0.5))
    for f in (c.certified_orbit_step, c.certified_orbit_collisions):
        with pytest.raises(TypeError):
            f(None)


@need_arb
def test_close_and_context():
    """close() releases the orbit (twice is fine); a closed orbit is the C
    null orbit: EINVAL from step, cap and collisions; a with block closes."""
    with c.CertifiedOrbit.exact(0, 1, 1, 2, 0.5) as o:
        o.step()
        assert not o.closed
    assert o.closed
    o.close()
    c.certified_orbit_free(o)
    c.certified_orbit_free(None)
    for call in (o.step, o.collisions, lambda: o.cap(100)):
        with pytest.raises(c.InvalidArgumentError, match='closed'):
            call()
    assert 'closed' in repr(o)


def malloc_in_use():
    """Bytes in use by malloc (glibc's mallinfo2), or None elsewhere."""
    try:
        libc = ctypes.CDLL(None)
        f = libc.mallinfo2
    except (OSError, AttributeError):
        return None

    class MallInfo2(ctypes.Structure):
        _fields_ = [(n, ctypes.c_size_t) for n in (
            'arena', 'ordblks', 'smblks', 'hblks', 'hblkhd', 'usmblks',
            'fsmblks', 'uordblks', 'fordblks', 'keepcost')]
    f.restype = MallInfo2
    m = f()
    return m.uordblks + m.hblkhd


@need_arb
@pytest.mark.skipif(malloc_in_use() is None, reason='no mallinfo2 (glibc)')
def test_del_frees():
    """Orbits dropped without close() are freed by __del__: 2000 orbits of
    3 collisions each leave malloc's bytes in use within 200 kB of where
    they were (an orbit not freed keeps about 580 bytes: 1.1 MB)."""
    def churn(n):
        for _ in range(n):
            o = c.CertifiedOrbit.exact((1, 3), (2, 7), 1, (5, 11), (-3, 13))
            for _ in range(3):
                o.step(return_ev=False, return_bounds=False)
            del o
        gc.collect()
    churn(200)                  # the caches, warmed
    before = malloc_in_use()
    churn(2000)
    assert malloc_in_use() - before < 200 * 1024, \
        malloc_in_use() - before


@need_arb
def test_threads_share_an_orbit():
    """Steps of one orbit from 4 threads are serialised: 60 collisions in
    all, each certified once, the states those of one thread's run."""
    o = c.CertifiedOrbit(*phase_state(*FIG3, 0.3, 0.8))
    got = []

    def work():
        for _ in range(15):
            got.append(o.step(return_ev=False, return_bounds=False))
    threads = [threading.Thread(target=work) for _ in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert o.collisions() == 60
    ref = c.CertifiedOrbit(*phase_state(*FIG3, 0.3, 0.8))
    want = [ref.step(return_ev=False, return_bounds=False) for _ in range(60)]
    assert sorted(got, key=lambda s: (s.tau, s.E)) == \
        sorted(want, key=lambda s: (s.tau, s.E))


# ---- pickling ---------------------------------------------------------------

@need_arb
def test_pickle_results_and_orbits():
    """The step's Result, its CertifiedBounds and the exceptions pickle to
    equal values; an orbit pickles as its start and count: the copy
    continues as the original, bit for bit, its cap kept; a closed one
    stays closed."""
    o = c.CertifiedOrbit(*phase_state(*FIG3, 0.3, 0.8), request='theta,tau')
    for _ in range(5):
        r = o.step()
    for proto in range(pickle.HIGHEST_PROTOCOL + 1):
        r2 = pickle.loads(pickle.dumps(r, protocol=proto))
        assert r2 == r and type(r2.bounds) is c.CertifiedBounds
        assert r2._fields == ('out', 'ev', 'bounds')
        assert r2.bounds.to_record().tobytes() == r.bounds.to_record()\
            .tobytes()
    o.cap(4096)
    o2 = pickle.loads(pickle.dumps(o))
    assert o2 == o and o2 is not o and o2.collisions() == 5
    assert [o2.step() for _ in range(3)] == [o.step() for _ in range(3)]
    assert o2 != c.CertifiedOrbit(*phase_state(*FIG3, 0.3, 0.8),
                                  request='theta,tau')
    # the cap travels: capped at 64, both fail at the same collision
    e = c.CertifiedOrbit.exact((1, 3), (2, 7), 1, (5, 11), (-3, 13))
    e.step()
    e.cap(64)
    e2 = pickle.loads(pickle.dumps(e))
    fails = []
    for orbit in (e, e2):
        with pytest.raises(c.CertificationCapError) as info:
            for _ in range(64):
                orbit.step()
        fails.append(orbit.collisions())
        err = pickle.loads(pickle.dumps(info.value))
        assert type(err) is c.CertificationCapError and \
            err.status == c.ECAP and str(err) == str(info.value)
    assert fails[0] == fails[1] > 0
    o.close()
    o3 = pickle.loads(pickle.dumps(o))
    assert o3.closed and o3 == o


# ---- method_available ----------------------------------------------------------

def test_method_available():
    """Every method by name and value; the certified one as config.h says
    (HAVE_ARB), and then discrete.step takes it, else refuses it
    (EINVAL); unknown methods raise; vectorised with statuses."""
    for name in ('closed-form', 'quadrature', 'ode', 'closed_form'):
        assert c.method_available(name) == 1
    with open(build('config.h')) as fh:
        have_arb = '#define HAVE_ARB 1' in fh.read()
    assert c.method_available('certified') == int(have_arb)
    assert c.method_available(c.Method.CERTIFIED) == int(have_arb)
    sys_, st = phase_state(*FIG3, 0.3, 0.8)
    if have_arb:
        d.step(sys_, st, method='certified')
    else:
        with pytest.raises(c.InvalidArgumentError):
            d.step(sys_, st, method='certified')
    with pytest.raises(c.InvalidArgumentError):
        c.method_available(9)
    with pytest.raises(c.InvalidArgumentError, match='bogus'):
        c.method_available('bogus')
    r = c.method_available(np.array([0, 1, 2, 3, -1]), errors='return')
    assert r.available.tolist() == [1, 1, 1, int(have_arb), 0]
    assert r.status.tolist() == [0, 0, 0, 0, c.EINVAL]


# ---- the generator -----------------------------------------------------------

def test_generator_leaves_opaque_types_to_hand_wrapping():
    """python/gen.py: a struct typedef without members (the certified
    orbit's) is no struct class, and a function taking a pointer to it (or
    to a pointer to it) gets no generated wrapper and no C loop; a struct
    with members stays a struct class."""
    from test_gen_write import gen_module
    gen = gen_module()
    header = '''
/** A struct. */
typedef struct
{
  double x;   /** x. */
} chaplygin_thing;

/** An opaque one. */
typedef struct chaplygin_box chaplygin_box;

/** Make one. */
int chaplygin_box_new (const chaplygin_thing *t, chaplygin_box **box);

/** Use one. */
int chaplygin_box_use (chaplygin_box *box, chaplygin_thing *out);

/** A thing. */
int chaplygin_thing_get (double x, chaplygin_thing *out);
'''
    funcs, structs, enums, _ = gen.parse(header)
    assert structs == ['chaplygin_thing']
    by = {f.cname: f for f in funcs}
    for name in ('chaplygin_box_new', 'chaplygin_box_use'):
        assert by[name].params[-1 if name.endswith('new') else 0].kind == \
            'unknown'
        assert not gen.generic(by[name]) and not gen.looped(by[name])
    assert gen.generic(by['chaplygin_thing_get'])
    assert by['chaplygin_thing_get'].params[1].kind == 'out_struct'


@need_arb
def test_phase_start_state_and_fate():
    """CertifiedOrbit.phase forms E and H from the phase doubles exactly
    (its state() is their nearest doubles, computed here in fractions);
    fate() decides Section 3.1.3's fate on the exact orbit: the kind,
    collisions and reversals of discrete.fate_phase along Figure 3's line,
    E_final the nearest double to (B.10) from the exact state after those
    collisions (the exact map here), V_final its sign times the nearest
    sqrt(2 E_final); the orbit is left where the fate is certain."""
    L0, Delta = FIG3
    sys_ = d.init(L0, Delta)
    for V in (0.05, 0.11, 0.2, 0.31, 0.5):
        q = [0.0, V, 0.0, 0.8]
        o = c.CertifiedOrbit.phase(sys_, q, request=0)
        n0 = 1 + F(L0) ** 2
        E, H = F(V) ** 2 / 2 + n0 * F(0.8) ** 2 / 2, n0 * F(0.8)
        st, b = o.state()
        check_rounded(st.E, E, b.E, 'E0')
        check_rounded(st.H, H, b.H, 'H0')
        assert st.V == V
        fate, at = o.fate(1000, reversal_cap=4)
        ref = d.fate_phase(sys_, q, 1000)
        assert (fate.kind, fate.collisions, fate.reversals) \
            == (ref.kind, ref.collisions, ref.reversals), V
        assert o.collisions() == fate.collisions
        dir_ = 1
        for k in range(fate.collisions):
            rev, dir_, E, H, _, _ = ref_step(F(L0), F(Delta), dir_, E, H)
        # (B.10) with the far end's coefficients: b = l1, b' = l0
        l0, l1 = (F(L0), F(L0) + 1) if dir_ > 0 else (F(L0) + 1, F(L0))
        C1 = -F(Delta) ** 2 / (2 * (1 + l1 * l1) ** 2 * (1 + l0 * l0))
        C2 = (1 + l1 * l0) / (1 + l1 * l1)
        Ef = E + C1 * H * H / (1 - C2 * C2)
        assert fate.kind == dir_
        assert fate.E_final == float(Ef), V
        assert fate.V_final == dir_ * nearest_sqrt(2 * Ef), V
        assert len(at) == min(4, fate.reversals)
        o2 = pickle.loads(pickle.dumps(o))
        assert o2.collisions() == o.collisions() and o2 == o
        assert o2.state().out.E == o.state().out.E
        o.close()
    with pytest.raises(c.CertificationCapError):
        o = c.CertifiedOrbit.phase(sys_, [0.0, 0.05, 0.0, 0.8], request=0)
        o.cap(64)
        o.fate(100)
    with pytest.raises(c.StateError):
        c.certified_orbit_new_phase(sys_, [1.0, 0.3, 0.0, 0.8])


@need_arb
def test_phase_exact_start():
    """CertifiedOrbit.phase_exact: V = 3/10 and Omega = 4/5 taken exactly
    (not the doubles 0.3, 0.8): its start's E and H are the nearest doubles
    to (3.3), (3.4) of those rationals, and it pickles."""
    o = c.certified_orbit_new_phase_exact(F(-1, 2), 1, F(3, 10), F(4, 5),
                                          request=0)
    n0 = 1 + F(1, 4)
    st, b = o.state()
    check_rounded(st.E, F(9, 100) / 2 + n0 * F(16, 25) / 2, b.E, 'E0')
    check_rounded(st.H, n0 * F(4, 5), b.H, 'H0')
    # Omega = H/(1 + L0^2) at the start: 4/5 exactly rounded
    assert o.omega() == float(F(4, 5))
    o.step()
    assert pickle.loads(pickle.dumps(o)) == o


@need_arb
def test_eq_certified():
    """chaplygin.eq(..., certified=True) is `chaplygin eq --certified`:
    sigma4 = 7/6 exactly at L0 = 1, Delta = 1/3 (a Fraction or 'p/q'),
    whose nearest double is 1.1666666666666667 (the closed form's
    1.1666666666666665 is not); the certified function is named; (2.1),
    like every label, has a certified evaluator; a non-bool flag is
    refused."""
    for Delta in (F(1, 3), '1/3'):
        r = c.eq('3.10', L0=1, Delta=Delta, dir=-1, certified=True)
        assert r.sigma4 == float(F(7, 6)) == 1.1666666666666667
        assert r.functions['sigma4'] == 'chaplygin_certified_sigma4'
    assert c.eq('3.10', L0=1, Delta='1/3', dir=-1).sigma4 != r.sigma4
    # every label has a certified evaluator: (2.1)'s field at exact inputs
    r = c.eq('2.1', L=1, V='1/3', Omega=F(1, 2), certified=True)
    assert r['dOmega/dtau'] == float(F(-1, 12))
    with pytest.raises(TypeError):
        c.eq('3.10', L0=1, Delta='1/3', dir=-1, certified=1)
