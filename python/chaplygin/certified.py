"""The certified method: orbits whose every double is the nearest to the
model's exact value (chaplygin_certified_orbit_*, "Certified orbits" in
<chaplygin.h>).

  CertifiedOrbit(sys, start, request='all')
      an orbit from a post-collision state given by doubles, taken as exact
      (chaplygin_certified_orbit_new);
  CertifiedOrbit.exact(L0, Delta, dir, E, H, theta=0.0, tau=0.0,
                       peg=(0.0, 0.0), request='all')
      from exact ratios of doubles (chaplygin_certified_orbit_new_exact):
      each of L0, Delta, E, H a number, a fractions.Fraction or a pair
      (numerator, denominator) of doubles, taken exactly;
  CertifiedOrbit.phase(sys, qplus, tau=0.0, peg=(0.0, 0.0), request='all')
      from a post-collision phase state [D+, V+, theta+, Omega+] of
      doubles, E and H formed from it exactly
      (chaplygin_certified_orbit_new_phase);
  CertifiedOrbit.phase_exact(L0, Delta, V, Omega, ...)
      from a phase state of exact ratios
      (chaplygin_certified_orbit_new_phase_exact);
  orbit.step()      the next collision: Result(out, ev, bounds), a
                    DiscreteState, a DiscreteEvent and a CertifiedBounds
                    (chaplygin_certified_orbit_step);
  orbit.state()     the current state, rounded: Result(out, bounds)
                    (chaplygin_certified_orbit_state);
  orbit.omega()     Omega = H/(1 + l^2) at its peg, rounded
                    (chaplygin_certified_orbit_omega);
  orbit.sample(D, leg)
                    dense output of the segment the last step ended:
                    Result(V, Omega, theta, tau) at the slot position D
                    (chaplygin_certified_orbit_sample);
  orbit.fate(max_collisions, reversal_cap=0)
                    Section 3.1.3's fate decided on the exact orbit, which
                    it advances (chaplygin_certified_orbit_fate);
  orbit.cap(max_bits), orbit.collisions(), orbit.close()
                    chaplygin_certified_orbit_cap, _collisions, _free.

The orbit keeps its energy and momentum as exact rationals and its heading,
time and peg as Arb balls, so nothing is rounded between collisions: after
n steps each double is the nearest to the exact model's value for the exact
start.  discrete.step(..., method='certified') (and discrete.orbit with it)
certifies one collision from the doubles given: along an orbit it starts
again from the rounded state at every collision.

An orbit holds C memory: close() (or a with block) releases it at once,
and the garbage collector does otherwise.  A closed orbit is the C null
orbit: stepping it raises InvalidArgumentError (CHAPLYGIN_EINVAL).  Calls
on one orbit from several threads are serialised by a lock.  An orbit
pickles as its exact start, its request, its cap and its number of
collisions; unpickling replays those collisions (the same exact state, the
same doubles from then on).  A status raises its exception: a step beyond
the cap CertificationCapError (CHAPLYGIN_ECAP), the orbit unchanged.

The module-level functions certified_orbit_new, certified_orbit_new_exact,
certified_orbit_new_phase, certified_orbit_cap, certified_orbit_step,
certified_orbit_state, certified_orbit_fate, certified_orbit_collisions and
certified_orbit_free (chaplygin.certified_orbit_new, ...) are the C
functions' names for the same calls.
"""

import fractions
import threading

import numpy as np

from . import _core
from ._core import (_ffi, _lib, _NULL, _fail, _as_int, _as_float, _as_struct,
                    _real, _request, _refuse_masked, _struct_class,
                    _enum_value, _REAL_TYPES)

__all__ = ['CertifiedOrbit', 'certified_orbit_new',
           'certified_orbit_new_exact', 'certified_orbit_new_phase',
           'certified_orbit_new_phase_exact',
           'certified_orbit_cap', 'certified_orbit_step',
           'certified_orbit_state', 'certified_orbit_fate',
           'certified_orbit_omega', 'certified_orbit_sample',
           'certified_orbit_collisions', 'certified_orbit_free',
           'method_available']

Discrete = _struct_class('chaplygin_discrete')
DiscreteState = _struct_class('chaplygin_discrete_state')
DiscreteEvent = _struct_class('chaplygin_discrete_event')
CertifiedBounds = _struct_class('chaplygin_certified_bounds')
Fate = _struct_class('chaplygin_fate')

_UINT = np.dtype(np.uintc)
_INT = np.dtype(np.intc)
_ULONG = _core._scalar_dtype('unsigned long')
# The largest cap chaplygin_certified_orbit_cap takes (its domain in the
# header: 64 <= max_bits <= 2^30): an unpickled orbit replays under it.
_CAP_MAX = 2 ** 30
_STEP_NAMES = ('out', 'ev', 'bounds')
_STATE_NAMES = ('out', 'bounds')
_CORBIT = 'chaplygin_certified_orbit *'


def _exact_double(name, x):
    """X (a real number) as the double equal to it; ValueError where none
    is (the C function would take a rounding, not X)."""
    _refuse_masked(name, x)
    if isinstance(x, np.ndarray) and x.ndim == 0:
        x = x[()]
    if not isinstance(x, _REAL_TYPES):
        raise TypeError('%s: a real number expected, not %s'
                        % (name, type(x).__name__))
    d = float(x)
    if d == d and d not in (float('inf'), float('-inf')) and \
            fractions.Fraction(d) != fractions.Fraction(x):
        raise ValueError('%s: %r is not a double (its nearest is %r): give '
                         'it as a ratio of doubles' % (name, x, d))
    return d


def _ratio(name, x):
    """The pair [numerator, denominator] of doubles of X: a pair (two
    numbers, each a double), a fractions.Fraction (numerator and
    denominator each a double) or a number (a double: X / 1)."""
    _refuse_masked(name, x)
    if isinstance(x, (list, tuple, np.ndarray)) and np.ndim(x) == 1:
        if len(x) != 2:
            raise TypeError('%s: a number or a pair (numerator, '
                            'denominator) expected, not %d values'
                            % (name, len(x)))
        return [_exact_double('%s[0]' % name, x[0]),
                _exact_double('%s[1]' % name, x[1])]
    if isinstance(x, fractions.Fraction):
        return [_exact_double('%s.numerator' % name, x.numerator),
                _exact_double('%s.denominator' % name, x.denominator)]
    return [_exact_double(name, x), 1.0]


def _pair(name, x):
    a = _as_float(name, x)
    if a.shape != (2,):
        raise TypeError('%s: two numbers expected, not shape %s'
                        % (name, a.shape))
    return [float(a[0]), float(a[1])]


def _integer(name, x, dtype=_UINT):
    a = _as_int(name, x, dtype)
    if a.ndim:
        raise TypeError('%s: one integer expected, not an array of shape %s'
                        % (name, a.shape))
    return int(a)


def _pair4(x):
    """The four numbers of a phase state."""
    try:
        q = list(x)
    except TypeError:
        raise TypeError('qplus: four numbers [D+, V+, theta+, Omega+] '
                        'expected, not %s' % type(x).__name__) from None
    if len(q) != 4:
        raise ValueError('qplus: four numbers [D+, V+, theta+, Omega+] '
                         'expected, not %d' % len(q))
    return q


def _one_struct(name, cls, x):
    a = _as_struct(name, cls._ctype, x)
    if a.shape != ():
        raise TypeError('%s: one %s expected, not an array of shape %s'
                        % (name, cls.__name__, a.shape))
    return cls.from_record(a)


class CertifiedOrbit:
    """CertifiedOrbit(sys, start, request='all')

    An orbit of the discrete skate followed by the certified method
    (chaplygin_certified_orbit_new): from the post-collision state START (a
    DiscreteState or a dict of its fields) of the system SYS (a Discrete),
    its dir, E, H, theta, tau and peg taken as exact (V is checked as
    discrete.step checks it, and not used).  request ('all', names among
    'theta', 'tau', 'peg', or 0) says which of heading, time and peg the
    orbit follows; E, H and dir always.  CertifiedOrbit.exact starts from
    exact ratios.

    Methods: step(), cap(max_bits), collisions(), close(); a context manager
    (close() on leaving).  See chaplygin.certified.

    C: int chaplygin_certified_orbit_new(const chaplygin_discrete *sys,
    const chaplygin_discrete_state *start, unsigned request,
    chaplygin_certified_orbit **orbit)
    """
    __slots__ = ('_p', '_lock', '_start', '_cap', '__weakref__')

    def __init__(self, sys, start, request='all'):
        self._p = _NULL
        self._lock = threading.Lock()
        if type(sys) is not Discrete:
            raise TypeError('sys: a chaplygin.Discrete expected (made by '
                            'chaplygin.discrete.init(L0, Delta)), not %s'
                            % type(sys).__name__)
        st = _one_struct('start', DiscreteState, start)
        req = _integer('request', _request(request))
        o = _ffi.new('chaplygin_certified_orbit **')
        rc = _lib.chaplygin_certified_orbit_new(sys._c, st._c, req, o)
        if rc:
            _fail(rc, 'chaplygin_certified_orbit_new')
        self._p = o[0]
        self._start = ('new', sys.copy(), st, req)
        self._cap = None

    @classmethod
    def exact(cls, L0, Delta, dir, E, H, theta=0.0, tau=0.0,
              peg=(0.0, 0.0), request='all'):
        """CertifiedOrbit.exact(L0, Delta, dir, E, H, theta=0.0, tau=0.0,
        peg=(0.0, 0.0), request='all')

        A certified orbit from exact rational inputs
        (chaplygin_certified_orbit_new_exact): each of L0, Delta, E and H
        is a number (a double: 0.1 is the double nearest to 1/10), a
        fractions.Fraction whose numerator and denominator are doubles
        (Fraction(1, 3): L0 = 1/3 exactly), or a pair (numerator,
        denominator) of doubles; a value that is no double (Fraction(1, 3)
        as a numerator, 2**53 + 1) raises ValueError.  dir (+1 or -1),
        theta, tau and peg as in a DiscreteState.

        C: int chaplygin_certified_orbit_new_exact(const double L0[2],
        const double Delta[2], int dir, const double E[2],
        const double H[2], double theta, double tau, const double peg[2],
        unsigned request, chaplygin_certified_orbit **orbit)
        """
        args = (_ratio('L0', L0), _ratio('Delta', Delta),
                _integer('dir', dir, _INT), _ratio('E', E), _ratio('H', H),
                _real('theta', theta), _real('tau', tau), _pair('peg', peg),
                _integer('request', _request(request)))
        return cls._made_exact(args)

    @classmethod
    def _made_exact(cls, args):
        self = object.__new__(cls)
        self._p = _NULL
        self._lock = threading.Lock()
        o = _ffi.new('chaplygin_certified_orbit **')
        rc = _lib.chaplygin_certified_orbit_new_exact(*(args + (o,)))
        if rc:
            _fail(rc, 'chaplygin_certified_orbit_new_exact')
        self._p = o[0]
        self._start = ('exact',) + tuple(args)
        self._cap = None
        return self

    @classmethod
    def phase(cls, sys, qplus, tau=0.0, peg=(0.0, 0.0), request='all'):
        """CertifiedOrbit.phase(sys, qplus, tau=0.0, peg=(0.0, 0.0),
        request='all')

        A certified orbit from the post-collision phase state qplus =
        [D+, V+, theta+, Omega+] of the system SYS, taken exactly
        (chaplygin_certified_orbit_new_phase): E = V^2/2 + (1 + l0^2)
        Omega^2/2 and H = (1 + l0^2) Omega are formed exactly, where
        discrete.state_from_phase rounds them.  D+ = 0 for V+ > 0, Delta
        for V+ < 0.

        C: int chaplygin_certified_orbit_new_phase(const chaplygin_discrete
        *sys, const double qplus[4], double tau, const double peg[2],
        unsigned request, chaplygin_certified_orbit **orbit)
        """
        if type(sys) is not Discrete:
            raise TypeError('sys: a chaplygin.Discrete expected (made by '
                            'chaplygin.discrete.init(L0, Delta)), not %s'
                            % type(sys).__name__)
        q = np.array([_real('qplus[%d]' % i, x)
                      for i, x in enumerate(_pair4(qplus))], dtype=float)
        args = (sys.copy(), q, _real('tau', tau), _pair('peg', peg),
                _integer('request', _request(request)))
        return cls._made_phase(args)

    @classmethod
    def _made_phase(cls, args):
        self = object.__new__(cls)
        self._p = _NULL
        self._lock = threading.Lock()
        sys, q, tau, peg, req = args
        o = _ffi.new('chaplygin_certified_orbit **')
        qc = _ffi.new('double[4]', [float(x) for x in q])
        rc = _lib.chaplygin_certified_orbit_new_phase(sys._c, qc, tau, peg,
                                                      req, o)
        if rc:
            _fail(rc, 'chaplygin_certified_orbit_new_phase')
        self._p = o[0]
        self._start = ('phase', sys, tuple(float(x) for x in q), tau,
                       tuple(peg), req)
        self._cap = None
        return self

    @classmethod
    def phase_exact(cls, L0, Delta, V, Omega, theta=0.0, tau=0.0,
                    peg=(0.0, 0.0), request='all'):
        """CertifiedOrbit.phase_exact(L0, Delta, V, Omega, theta=0.0,
        tau=0.0, peg=(0.0, 0.0), request='all')

        A certified orbit from a post-collision phase state given as exact
        ratios (chaplygin_certified_orbit_new_phase_exact): L0, Delta, V and
        Omega each as in CertifiedOrbit.exact; dir = sgn(V), the peg at the
        end V leaves, E and H by (3.3), (3.4) exactly.

        C: int chaplygin_certified_orbit_new_phase_exact(const double L0[2],
        const double Delta[2], const double V[2], const double Omega[2],
        double theta, double tau, const double peg[2], unsigned request,
        chaplygin_certified_orbit **orbit)
        """
        args = (_ratio('L0', L0), _ratio('Delta', Delta), _ratio('V', V),
                _ratio('Omega', Omega), _real('theta', theta),
                _real('tau', tau), _pair('peg', peg),
                _integer('request', _request(request)))
        return cls._made_phase_exact(args)

    @classmethod
    def _made_phase_exact(cls, args):
        self = object.__new__(cls)
        self._p = _NULL
        self._lock = threading.Lock()
        o = _ffi.new('chaplygin_certified_orbit **')
        rc = _lib.chaplygin_certified_orbit_new_phase_exact(*(args + (o,)))
        if rc:
            _fail(rc, 'chaplygin_certified_orbit_new_phase_exact')
        self._p = o[0]
        self._start = ('phase_exact',) + tuple(args)
        self._cap = None
        return self

    # -- the C functions ---------------------------------------------------

    def step(self, *, return_ev=True, return_bounds=True):
        """orbit.step(*, return_ev=True, return_bounds=True)

        (B.3) and (B.4), certified: advance the orbit by one collision
        (chaplygin_certified_orbit_step).  Returns Result(out, ev, bounds):
        the state after it (a DiscreteState: E, H, dir, V always; theta,
        tau, peg as the request says, 0 otherwise), the event (a
        DiscreteEvent; Vminus, Dc, dtheta, dtau certified likewise) and
        the enclosures (a CertifiedBounds: each field [lo, hi], the
        adjacent doubles around the exact value, equal where it is a
        double); return_ev=False, return_bounds=False leave those out.
        Every double is the nearest to the exact model's value after all
        the orbit's collisions.  A failure raises (CertificationCapError
        for CHAPLYGIN_ECAP, SpinError, RangeError, ...) and leaves the
        orbit as it was.

        C: int chaplygin_certified_orbit_step(chaplygin_certified_orbit
        *orbit, chaplygin_discrete_state *out, chaplygin_discrete_event
        *ev, chaplygin_certified_bounds *bounds)
        """
        out = _ffi.new('chaplygin_discrete_state *')
        ev = _ffi.new('chaplygin_discrete_event *') if return_ev else _NULL
        b = _ffi.new('chaplygin_certified_bounds *') if return_bounds \
            else _NULL
        with self._lock:
            rc = _lib.chaplygin_certified_orbit_step(self._p, out, ev, b)
        if rc:
            self._failed(rc, 'chaplygin_certified_orbit_step')
        vals = (DiscreteState._wrap(out),
                DiscreteEvent._wrap(ev) if return_ev else None,
                CertifiedBounds._wrap(b) if return_bounds else None)
        return _core._pick(_STEP_NAMES, (True, return_ev, return_bounds),
                           vals)

    def state(self, *, return_bounds=True):
        """orbit.state(*, return_bounds=True)

        The orbit's state after the collisions it has certified (the start
        before the first), rounded as step() rounds it: Result(out, bounds)
        (chaplygin_certified_orbit_state); V is V+ from the exact E and H.

        C: int chaplygin_certified_orbit_state(const
        chaplygin_certified_orbit *orbit, chaplygin_discrete_state *out,
        chaplygin_certified_bounds *bounds)
        """
        out = _ffi.new('chaplygin_discrete_state *')
        b = _ffi.new('chaplygin_certified_bounds *') if return_bounds \
            else _NULL
        with self._lock:
            rc = _lib.chaplygin_certified_orbit_state(self._p, out, b)
        if rc:
            self._failed(rc, 'chaplygin_certified_orbit_state')
        vals = (DiscreteState._wrap(out),
                CertifiedBounds._wrap(b) if return_bounds else None)
        return _core._pick(_STATE_NAMES, (True, return_bounds), vals)

    def fate(self, max_collisions, *, reversal_cap=0):
        """orbit.fate(max_collisions, *, reversal_cap=0)

        Section 3.1.3 and (B.10), certified: the fate of the orbit from its
        current state, every decision exact, E_final and V_final the
        nearest doubles (chaplygin_certified_orbit_fate).  The orbit is
        advanced to where the fate is certain (at most max_collisions
        collisions).  Returns a Fate; with reversal_cap > 0, (fate,
        reversal_at): the collisions (counted from the call) that end the
        first reversal_cap reversing segments.

        C: int chaplygin_certified_orbit_fate(chaplygin_certified_orbit
        *orbit, unsigned long max_collisions, unsigned long *reversal_at,
        size_t reversal_cap, chaplygin_fate *fate)
        """
        n = _integer('max_collisions', max_collisions, _ULONG)
        cap = _integer('reversal_cap', reversal_cap,
                       _core._scalar_dtype('size_t'))
        at = _ffi.new('unsigned long[]', max(cap, 1))
        f = _ffi.new('chaplygin_fate *')
        with self._lock:
            rc = _lib.chaplygin_certified_orbit_fate(self._p, n, at, cap, f)
        if rc:
            self._failed(rc, 'chaplygin_certified_orbit_fate')
        fate = Fate._wrap(f)
        if not cap:
            return fate
        k = min(cap, int(f.reversals))
        return _core._nt(('fate', 'reversal_at'))(
            fate, np.array(_ffi.unpack(at, k), dtype=_ULONG))

    def omega(self):
        """orbit.omega()

        The angular rate Omega = H/(1 + l^2) at the peg of the orbit's
        current state, the double nearest to the exact value
        (chaplygin_certified_orbit_omega).

        C: int chaplygin_certified_orbit_omega(const
        chaplygin_certified_orbit *orbit, double *Omega)
        """
        w = _ffi.new('double *')
        with self._lock:
            rc = _lib.chaplygin_certified_orbit_omega(self._p, w)
        if rc:
            self._failed(rc, 'chaplygin_certified_orbit_omega')
        return float(w[0])

    def sample(self, D, leg=0):
        """orbit.sample(D, leg=0)

        Dense output, certified: the state at the slot position D (a
        float, taken exactly) on the segment that ended at the orbit's
        last collision: Result(V, Omega, theta, tau), each the double
        nearest to the exact orbit's value there (theta and tau as the
        request has them, else 0).  leg: 0 the way out, 1 the way back of
        a segment that reversed, 2 its turning point (D not used).
        Before the first step, an invalid leg: ValueError; a D not on the
        leg: DomainError (chaplygin_certified_orbit_sample).

        C: int chaplygin_certified_orbit_sample(chaplygin_certified_orbit
        *orbit, double D, int leg, double *V, double *Omega, double
        *theta, double *tau)
        """
        D = _real('D', D)
        leg = _integer('leg', leg, _INT)
        out = _ffi.new('double[4]')
        with self._lock:
            rc = _lib.chaplygin_certified_orbit_sample(
                self._p, D, leg, out, out + 1, out + 2, out + 3)
        if rc:
            self._failed(rc, 'chaplygin_certified_orbit_sample')
        return _core._nt(('V', 'Omega', 'theta', 'tau'))(
            *(float(out[i]) for i in range(4)))

    def cap(self, max_bits):
        """orbit.cap(max_bits)

        Cap the working precision of the orbit's balls and the size in
        bits of its exact E and H (numerator plus denominator) at max_bits
        (64 <= max_bits <= 2**30; the library's default 1048576 holds
        several thousand collisions): a step that would need more raises
        CertificationCapError (chaplygin_certified_orbit_cap).

        C: int chaplygin_certified_orbit_cap(chaplygin_certified_orbit
        *orbit, unsigned long max_bits)
        """
        bits = _integer('max_bits', max_bits, _ULONG)
        with self._lock:
            rc = _lib.chaplygin_certified_orbit_cap(self._p, bits)
        if rc:
            self._failed(rc, 'chaplygin_certified_orbit_cap')
        self._cap = bits

    def collisions(self):
        """orbit.collisions()

        The number of collisions the orbit has certified
        (chaplygin_certified_orbit_collisions).

        C: int chaplygin_certified_orbit_collisions(const
        chaplygin_certified_orbit *orbit, unsigned long *n)
        """
        n = _ffi.new('unsigned long *')
        with self._lock:
            rc = _lib.chaplygin_certified_orbit_collisions(self._p, n)
        if rc:
            self._failed(rc, 'chaplygin_certified_orbit_collisions')
        return int(n[0])

    def close(self):
        """orbit.close()

        Release the orbit's C memory (chaplygin_certified_orbit_free); a
        second close() does nothing.  The orbit is then closed: its other
        methods raise InvalidArgumentError.

        C: int chaplygin_certified_orbit_free(chaplygin_certified_orbit
        *orbit)
        """
        with self._lock:
            p, self._p = self._p, _NULL
            _lib.chaplygin_certified_orbit_free(p)

    # -- Python's protocols --------------------------------------------------

    @property
    def closed(self):
        """Whether close() has released the orbit."""
        return self._p == _NULL

    def _failed(self, rc, function):
        _fail(rc, function,
              detail='the orbit is closed' if self.closed else None)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def __del__(self):
        try:
            p = self._p
        except AttributeError:          # __init__ failed before
            return
        if p != _NULL:
            self._p = _NULL
            try:
                _lib.chaplygin_certified_orbit_free(p)
            except Exception:           # an interpreter shutting down
                pass

    def _key(self):
        return (self._start, self._cap, self.closed,
                None if self.closed else self.collisions())

    def __eq__(self, other):
        """Equal: the same exact start, request and cap, and as many
        collisions (so the same state), or both closed from the same."""
        if type(other) is not type(self):
            return NotImplemented
        return self is other or self._key() == other._key()

    __hash__ = None

    def __reduce__(self):
        return (_rebuild_orbit, (type(self),) + self._key())

    def __repr__(self):
        if self.closed:
            return '<CertifiedOrbit (closed)>'
        return '<CertifiedOrbit: %d collisions>' % self.collisions()


def _rebuild_orbit(cls, start, cap, closed, n):
    """An orbit equal to the one pickled: made from its start, N
    collisions replayed (under the largest cap, which decides nothing:
    each succeeded before), then its cap."""
    if start[0] == 'new':
        _, sys, st, req = start
        o = cls(sys, st, req)
    elif start[0] == 'phase_exact':
        o = cls._made_phase_exact(tuple(start[1:]))
    elif start[0] == 'phase':
        _, sys, q, tau, peg, req = start
        o = cls._made_phase((sys, q, tau, peg, req))
    else:
        o = cls._made_exact(tuple(start[1:]))
    if closed:
        o.close()
        o._cap = cap
        return o
    if n:
        o.cap(_CAP_MAX)
        for _ in range(n):
            o.step(return_ev=False, return_bounds=False)
    if cap is not None:
        o.cap(cap)
    o._cap = cap
    return o


def _orbit(orbit):
    if not isinstance(orbit, CertifiedOrbit):
        raise TypeError('orbit: a chaplygin.CertifiedOrbit expected (made by '
                        'chaplygin.certified_orbit_new), not %s'
                        % type(orbit).__name__)
    return orbit


# ---------------------------------------------------------------------------
# The C functions by their names.

def certified_orbit_new(sys, start, request='all'):
    """certified_orbit_new(sys, start, request='all')

    A CertifiedOrbit of the system sys from the post-collision state
    start, taken as exact: CertifiedOrbit(sys, start, request).

    C: int chaplygin_certified_orbit_new(const chaplygin_discrete *sys,
    const chaplygin_discrete_state *start, unsigned request,
    chaplygin_certified_orbit **orbit)
    """
    return CertifiedOrbit(sys, start, request)


def certified_orbit_new_exact(L0, Delta, dir, E, H, theta=0.0, tau=0.0,
                              peg=(0.0, 0.0), request='all'):
    """certified_orbit_new_exact(L0, Delta, dir, E, H, theta=0.0, tau=0.0,
    peg=(0.0, 0.0), request='all')

    A CertifiedOrbit from exact ratios of doubles (L0, Delta, E, H each a
    number, a fractions.Fraction or a pair (numerator, denominator)):
    CertifiedOrbit.exact(...).

    C: int chaplygin_certified_orbit_new_exact(const double L0[2],
    const double Delta[2], int dir, const double E[2], const double H[2],
    double theta, double tau, const double peg[2], unsigned request,
    chaplygin_certified_orbit **orbit)
    """
    return CertifiedOrbit.exact(L0, Delta, dir, E, H, theta, tau, peg,
                                request)


def certified_orbit_new_phase(sys, qplus, tau=0.0, peg=(0.0, 0.0),
                              request='all'):
    """certified_orbit_new_phase(sys, qplus, tau=0.0, peg=(0.0, 0.0),
    request='all')

    A CertifiedOrbit from a post-collision phase state taken exactly:
    CertifiedOrbit.phase(...).

    C: int chaplygin_certified_orbit_new_phase(const chaplygin_discrete
    *sys, const double qplus[4], double tau, const double peg[2],
    unsigned request, chaplygin_certified_orbit **orbit)
    """
    return CertifiedOrbit.phase(sys, qplus, tau, peg, request)


def certified_orbit_new_phase_exact(L0, Delta, V, Omega, theta=0.0, tau=0.0,
                                    peg=(0.0, 0.0), request='all'):
    """certified_orbit_new_phase_exact(L0, Delta, V, Omega, theta=0.0,
    tau=0.0, peg=(0.0, 0.0), request='all')

    CertifiedOrbit.phase_exact(...).

    C: int chaplygin_certified_orbit_new_phase_exact(const double L0[2],
    const double Delta[2], const double V[2], const double Omega[2],
    double theta, double tau, const double peg[2], unsigned request,
    chaplygin_certified_orbit **orbit)
    """
    return CertifiedOrbit.phase_exact(L0, Delta, V, Omega, theta, tau, peg,
                                      request)


def certified_orbit_omega(orbit):
    """certified_orbit_omega(orbit)

    orbit.omega().

    C: int chaplygin_certified_orbit_omega(const chaplygin_certified_orbit
    *orbit, double *Omega)
    """
    return _orbit(orbit).omega()


def certified_orbit_sample(orbit, D, leg=0):
    """certified_orbit_sample(orbit, D, leg=0)

    orbit.sample(D, leg).

    C: int chaplygin_certified_orbit_sample(chaplygin_certified_orbit
    *orbit, double D, int leg, double *V, double *Omega, double *theta,
    double *tau)
    """
    return _orbit(orbit).sample(D, leg)


def certified_orbit_state(orbit, *, return_bounds=True):
    """certified_orbit_state(orbit, *, return_bounds=True)

    orbit.state(...).

    C: int chaplygin_certified_orbit_state(const chaplygin_certified_orbit
    *orbit, chaplygin_discrete_state *out, chaplygin_certified_bounds
    *bounds)
    """
    return _orbit(orbit).state(return_bounds=return_bounds)


def certified_orbit_fate(orbit, max_collisions, *, reversal_cap=0):
    """certified_orbit_fate(orbit, max_collisions, *, reversal_cap=0)

    orbit.fate(...).

    C: int chaplygin_certified_orbit_fate(chaplygin_certified_orbit *orbit,
    unsigned long max_collisions, unsigned long *reversal_at,
    size_t reversal_cap, chaplygin_fate *fate)
    """
    return _orbit(orbit).fate(max_collisions, reversal_cap=reversal_cap)


def certified_orbit_cap(orbit, max_bits):
    """certified_orbit_cap(orbit, max_bits)

    orbit.cap(max_bits): the orbit's precision and size cap in bits.

    C: int chaplygin_certified_orbit_cap(chaplygin_certified_orbit *orbit,
    unsigned long max_bits)
    """
    return _orbit(orbit).cap(max_bits)


def certified_orbit_step(orbit, *, return_ev=True, return_bounds=True):
    """certified_orbit_step(orbit, *, return_ev=True, return_bounds=True)

    orbit.step(): the next collision, Result(out, ev, bounds).

    C: int chaplygin_certified_orbit_step(chaplygin_certified_orbit *orbit,
    chaplygin_discrete_state *out, chaplygin_discrete_event *ev,
    chaplygin_certified_bounds *bounds)
    """
    return _orbit(orbit).step(return_ev=return_ev,
                              return_bounds=return_bounds)


def certified_orbit_collisions(orbit):
    """certified_orbit_collisions(orbit)

    orbit.collisions(): the collisions certified so far.

    C: int chaplygin_certified_orbit_collisions(const
    chaplygin_certified_orbit *orbit, unsigned long *n)
    """
    return _orbit(orbit).collisions()


def certified_orbit_free(orbit):
    """certified_orbit_free(orbit)

    orbit.close(): release the orbit (None is allowed, as the C null).

    C: int chaplygin_certified_orbit_free(chaplygin_certified_orbit *orbit)
    """
    if orbit is not None:
        _orbit(orbit).close()


for _f in (certified_orbit_new, certified_orbit_new_exact,
           certified_orbit_cap, certified_orbit_step,
           certified_orbit_collisions, certified_orbit_free):
    _f.__c_function__ = 'chaplygin_' + _f.__name__
    _f.__module__ = 'chaplygin'
del _f


# ---------------------------------------------------------------------------
# chaplygin_method_available: the generated wrapper, with method names.

def _with_names(generated):
    def method_available(method, *, errors='raise'):
        if isinstance(method, str):
            method = _enum_value('chaplygin_method', method, 'method')
        return generated(method, errors=errors)
    doc = generated.__doc__
    first, _, rest = doc.partition('\n')
    method_available.__doc__ = (
        first + '\n\n    method: a method name ("closed-form", "quadrature", '
        '"ode", "certified",\n    as the method= keywords take) or its '
        'value (chaplygin.Method.CERTIFIED).\n' + rest)
    method_available.__c_function__ = 'chaplygin_method_available'
    method_available.__module__ = 'chaplygin'
    return method_available


from ._generated import WRAPPED as _WRAPPED   # noqa: E402

method_available = _with_names(_WRAPPED['chaplygin_method_available'])
