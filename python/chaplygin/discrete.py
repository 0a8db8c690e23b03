"""The discrete skate: Section 3, Appendices B.1, B.2 (chaplygin_discrete_*).

Generated wrappers of every chaplygin_discrete_* function (help() of each
shows the header's comment and the C prototype), and by hand:

  orbit(sys, state, n)        the return map along n collisions from one
                              or many post-collision states (a C loop)
  step_eh_n(sys, state, n)    n E,H-only steps (the library's fast path)
  fate, fate_phase            the final motion, from one or many states
  basins, basin_boundaries    Figure 3's grid of fates and its boundaries
  fates_phase(sys, V, Omega, n)  the fates of many (V+, Omega+) at once
                              (the batch kernel of the atlas)

A system is made once: sys = chaplygin.discrete.init(L0, Delta) (or
chaplygin.Discrete(L0, Delta)).
"""

import numpy as np

from . import _core
from ._core import (_ffi, _lib, _NULL, _fail, _as_int, _as_struct, _flat,
                    _ptr, _options, _request, _struct_class, _nt, _SC,
                    _check_errors, _scalar_dtype, _polled, _real,
                    _refuse_masked, _as_float)
from ._groups import export

__all__ = []
export(globals(), 'discrete')

Discrete = _struct_class('chaplygin_discrete')
DiscreteState = _struct_class('chaplygin_discrete_state')
DiscreteEvent = _struct_class('chaplygin_discrete_event')
Fate = _struct_class('chaplygin_fate')
_UL = _scalar_dtype('unsigned long')

__all__ += ['orbit', 'step_eh_n', 'fate', 'fate_phase', 'basins',
            'fates_phase', 'basin_boundaries', 'Discrete', 'DiscreteState',
            'DiscreteEvent', 'Fate']


def _system(sys, what='sys'):
    if type(sys) is not Discrete:
        raise TypeError('%s: a chaplygin.Discrete expected (made by '
                        'chaplygin.discrete.init(L0, Delta)), not %s'
                        % (what, type(sys).__name__))
    return sys


def _count(name, n):
    return int(_as_int(name, n, _UL))


# ---------------------------------------------------------------------------

def step_eh_n(sys, state, n, *, errors='raise'):
    """discrete.step_eh_n(sys, state, n, *, errors='raise')

    n steps of (B.3)/(B.4) for E and H only (default options): bit for bit
    n calls of chaplygin_discrete_step with request 0, validated once.
    Returns the state after n collisions (theta, tau, peg unchanged), a
    DiscreteState, or for arrays of states (and/or n) a structured array.
    On a failure (errors='raise') the exception carries partial (the state
    after the last successful step) and done (the steps made);
    errors='return' returns (state, done, status) arrays instead.

    C: int chaplygin_discrete_step_eh_n(const chaplygin_discrete *sys,
    chaplygin_discrete_state *st, unsigned long n, unsigned long *done)
    """
    _system(sys)
    _check_errors(errors)
    a = _as_struct('state', 'chaplygin_discrete_state', state)
    nn = _as_int('n', n, _UL)
    shape = np.broadcast_shapes(a.shape, nn.shape)
    out = np.array(np.broadcast_to(a, shape), order='C')
    nn, n_stride = _flat(nn, shape, 0)
    done = np.zeros(shape, _UL)
    status = np.empty(shape, np.intc)
    nfail = _polled(_lib.chp_py_discrete_step_eh_n, sys._c, out.size,
                    _ffi.cast('chaplygin_discrete_state *', _ptr(out)),
                    _ffi.cast('unsigned long *', _ptr(nn)), n_stride,
                    _ffi.cast('unsigned long *', _ptr(done)),
                    _ffi.cast('int *', _ptr(status)))
    return _finish(out, done, status, nfail, errors,
                   'chaplygin_discrete_step_eh_n', ('state', 'done'))


def _finish(out, done, status, nfail, errors, cname, names):
    if out.ndim == 0:
        out = DiscreteState.from_record(out)
        done = done.item()
        status = status.item()
    if nfail and errors == 'raise':
        st = status if np.ndim(status) == 0 else \
            int(status.reshape(-1)[np.flatnonzero(status.reshape(-1))[0]])
        kw = {'partial': out, 'done': done}
        if np.ndim(status):
            kw['statuses'] = status
            kw['index'] = np.unravel_index(
                int(np.flatnonzero(status.reshape(-1))[0]), status.shape)
        _fail(st, cname, **kw)
    if errors == 'return':
        return _nt(names + ('status',))(out, done, status)
    return out


# ---------------------------------------------------------------------------

def _orbit(cname, call, state, n, request, keep, events, errors, opt=None):
    _check_errors(errors)
    if keep not in ('all', 'last'):
        raise ValueError("keep must be 'all' or 'last', not %r" % (keep,))
    if events and keep != 'all':
        raise ValueError("events=True needs keep='all'")
    n = _count('n', n)
    request = _request(request)
    request = int(_as_int('request', request, np.dtype(np.uintc)))
    a = _as_struct('state', 'chaplygin_discrete_state', state)
    shape = a.shape
    m = int(np.prod(shape, dtype=np.int64)) if shape else 1
    a, stride = _flat(a, shape, 0)
    keep_all = keep == 'all'
    rows = (n + 1) if keep_all else None
    dt = DiscreteState.dtype
    if keep_all:
        if m and n + 1 > np.iinfo(np.intp).max // (m * dt.itemsize):
            raise MemoryError('orbit: %d states of %d collisions' % (m, n))
        out = np.empty(shape + (rows,), dt)
    else:
        out = np.empty(shape, dt)
    ev = np.empty(shape + (n,), DiscreteEvent.dtype) if events else None
    status = np.empty(shape, np.intc)
    done = np.empty(shape, _UL)
    nfail = _polled(call, m, _ptr(a), stride, n, request, keep_all, out, ev,
                    status, done)
    if nfail:
        bad = status != 0
        if keep_all:
            k = np.arange(rows)
            lost = k[(None,) * len(shape)] > done[..., None]
            _core._fill_failed(out, lost)
            if events:
                _core._fill_failed(ev, k[:n][(None,) * len(shape)]
                                   >= done[..., None])
        else:
            _core._fill_failed(out, bad)
    result = (out, ev) if events else out
    if shape == ():
        status = status.item()
        done = done.item()
    if nfail and errors == 'raise':
        flat = np.flatnonzero(np.reshape(status, -1))
        first = int(flat[0])
        st = int(np.reshape(status, -1)[first])
        kw = {'partial': result, 'done': done, 'statuses': status}
        if shape:
            kw['index'] = np.unravel_index(first, shape)
        _fail(st, cname, detail='%d of %d orbits failed' % (nfail, m), **kw)
    if errors == 'return':
        names = ('states', 'events') if events else ('states',)
        return _nt(names + ('done', 'status'))(*(result if events
                                                 else (result,)),
                                                done, status)
    return result


def orbit(sys, state, n, *, request='all', method=None, tol=None,
          precision=None, keep='all', events=False, errors='raise'):
    """discrete.orbit(sys, state, n, *, request='all', method=None, tol=None,
    precision=None, keep='all', events=False, errors='raise')

    The return map (B.3)/(B.4) along n collisions from the post-collision
    state(s) STATE (a DiscreteState, a structured array of
    DiscreteState.dtype of any shape S, or a dict of its fields), one
    chaplygin_discrete_step per collision, the loop in C.

    request: what is computed beyond E, H, dir ('all', or names among
    'theta', 'tau', 'peg', or 0 for E and H alone); method, tol, precision:
    the options of the heading and time.  keep='all' returns the states of
    shape S + (n + 1,) (index 0 the initial state, k the state just after
    collision k); keep='last' only the states after n collisions, shape S
    (with request 0 by chaplygin_discrete_step_eh_n, bit for bit the same).
    events=True (keep='all') also returns the events (DiscreteEvent.dtype,
    shape S + (n,)): (states, events).

    A failing orbit stops at its first failing collision: errors='raise'
    raises the status's exception (partial, done, statuses attached);
    errors='return' returns (states, [events,] done, status), the states
    after the failure NaN (dir 0) and done the collisions made.
    chaplygin.as_columns(states) gives the CSV's column names.
    """
    _system(sys)
    opt = _options(method, tol, precision)

    def call(m, init, stride, n, request, keep_all, out, ev, status, done,
             poll):
        return _lib.chp_py_discrete_orbit(
            sys._c, m, init, stride, n, request, opt, keep_all,
            _ffi.cast('chaplygin_discrete_state *', _ptr(out)),
            _NULL if ev is None else
            _ffi.cast('chaplygin_discrete_event *', _ptr(ev)),
            _ffi.cast('int *', _ptr(status)),
            _ffi.cast('unsigned long *', _ptr(done)), poll)
    return _orbit('chaplygin_discrete_step', call, state, n, request, keep,
                  events, errors)


# ---------------------------------------------------------------------------

def _fate(cname, sys, init_kind, init, max_collisions, reversal_cap, errors):
    _system(sys)
    _check_errors(errors)
    cap = int(_as_int('reversal_cap', reversal_cap,
                      _scalar_dtype('size_t')))
    scalar = type(max_collisions) in _SC and (
        type(init) is DiscreteState if init_kind == 'state'
        else (type(init) in (list, tuple) and len(init) == 4))
    if scalar:
        if init_kind != 'state':
            _refuse_masked('qplus', init)
        f = _ffi.new('chaplygin_fate *')
        rev = _ffi.new('unsigned long[]', cap) if cap else _NULL
        rc = getattr(_lib, cname)(sys._c, init._c if init_kind == 'state'
                                  else init, max_collisions, rev, cap, f)
        fate = Fate._wrap(f)
        if rc:
            if errors == 'raise':
                _fail(rc, cname)
            fate = None
        if not cap:
            return _nt(('fate', 'status'))(fate, rc) \
                if errors == 'return' else fate
        ra = np.array(_ffi.unpack(rev, min(cap, f.reversals)), dtype=_UL) \
            if not rc else None
        if errors == 'return':
            return _nt(('fate', 'reversal_at', 'status'))(fate, ra, rc)
        return _nt(('fate', 'reversal_at'))(fate, ra)
    spec = list(_core.SPEC[cname])
    name, kind, ctype, dims, extra = spec[3]
    spec[3] = (name, 'out_array', ctype, cap, {'prefill': True})
    r = _core._vec(cname, (sys, init, max_collisions, cap),
                   (bool(cap), True), None, errors, spec=tuple(spec))
    if not cap:
        return r
    if errors == 'return':
        return _nt(('fate', 'reversal_at', 'status'))(r.fate, r.reversal_at,
                                                      r.status)
    return _nt(('fate', 'reversal_at'))(r.fate, r.reversal_at)


def fate(sys, init, max_collisions, *, reversal_cap=0, errors='raise'):
    """discrete.fate(sys, init, max_collisions, *, reversal_cap=0,
    errors='raise')

    Where the motion from the post-collision state INIT ends (Section 3.1.3,
    Appendix B.2.2): a Fate (kind: FateKind.BACKWARD, SPIN, FORWARD or
    UNDECIDED, collisions, reversals, last_reversal, E_final, V_final).
    With reversal_cap > 0 also the collision numbers ending the first
    reversal_cap reversing segments: (fate, reversal_at).  INIT may be a
    structured array of DiscreteState.dtype (or a dict of its fields) and
    max_collisions an array: then a structured array of Fate.dtype (and
    reversal_at of shape (..., reversal_cap), 0 beyond fate.reversals); see
    chaplygin.vectorised for errors.

    C: int chaplygin_discrete_fate(const chaplygin_discrete *sys,
    const chaplygin_discrete_state *init, unsigned long max_collisions,
    unsigned long *reversal_at, size_t reversal_cap, chaplygin_fate *fate)
    """
    return _fate('chaplygin_discrete_fate', sys, 'state', init,
                 max_collisions, reversal_cap, errors)


def fate_phase(sys, qplus, max_collisions, *, reversal_cap=0,
               errors='raise'):
    """discrete.fate_phase(sys, qplus, max_collisions, *, reversal_cap=0,
    errors='raise')

    discrete.fate from a post-collision phase state qplus = [D+, V+, theta+,
    Omega+] (D+ = 0 if V+ > 0, Delta if V+ < 0): V+ is used as given, not
    through E.  qplus may be an array of shape (..., 4): one fate per row,
    the loop in C (a structured array of Fate.dtype).

    C: int chaplygin_discrete_fate_phase(const chaplygin_discrete *sys,
    const double qplus[4], unsigned long max_collisions,
    unsigned long *reversal_at, size_t reversal_cap, chaplygin_fate *fate)
    """
    return _fate('chaplygin_discrete_fate_phase', sys, 'phase', qplus,
                 max_collisions, reversal_cap, errors)


def basins(sys, Omega0, V_lo, V_hi, n, max_collisions, *, errors='raise'):
    """discrete.basins(sys, Omega0, V_lo, V_hi, n, max_collisions, *,
    errors='raise')

    Figure 3: the fates of the n post-collision states {D+, V_i, 0, Omega0}
    on the library's grid V_i = V_lo + (V_hi - V_lo) i/(n - 1) (the ends
    exact; also where V_hi - V_lo overflows), as a structured array of
    Fate.dtype of shape (n,); the loop is the library's, each point in the
    units of its velocity scaling and its fate in the physical ones.  A
    point that fails (V_i = 0: StateError; a final energy beyond the
    doubles: RangeError) fails alone: its row is zero.  errors='raise'
    raises the first failure's exception (statuses and partial attached);
    errors='return' returns (fates, status).

    C: int chaplygin_discrete_basins(const chaplygin_discrete *sys,
    double Omega0, double V_lo, double V_hi, size_t n,
    unsigned long max_collisions, chaplygin_fate *fates, int *status,
    int *scale)
    """
    _check_errors(errors)
    _system(sys)
    n = int(_as_int('n', n, _scalar_dtype('size_t')))
    Omega0, V_lo, V_hi = (_real('Omega0', Omega0), _real('V_lo', V_lo),
                          _real('V_hi', V_hi))
    max_collisions = _count('max_collisions', max_collisions)
    out = np.zeros(n, Fate.dtype)
    status = np.zeros(n, np.intc)
    rc = _polled(_lib.chp_py_discrete_basins,
                 sys._c, Omega0, V_lo, V_hi, n, max_collisions,
                 _ffi.cast('chaplygin_fate *', _ptr(out)) if n else _NULL,
                 _ffi.cast('int *', _ptr(status)) if n else _NULL)
    if rc and (not n or not status.any()):
        status[...] = rc            # a failure of the call as a whole
    if rc and errors == 'raise':
        flat = np.flatnonzero(status)
        _fail(rc, 'chaplygin_discrete_basins', statuses=status, partial=out,
              index=int(flat[0]) if flat.size else None)
    if errors == 'return':
        return _nt(('fates', 'status'))(out, status)
    return out


# Points per call of fates_phase: a few ms (the interpreter runs signal
# handlers between the calls: Ctrl-C interrupts it).
_FATES_BLOCK = 1 << 16


def fates_phase(sys, V, Omega, max_collisions, *, errors='raise'):
    """discrete.fates_phase(sys, V, Omega, max_collisions, *,
    errors='raise')

    The fates of the post-collision states {D+, V[i], 0, Omega[i]} (V and
    Omega broadcast together; D+ = 0 for V > 0, Delta for V < 0), each bit
    for bit what discrete.basins gives for the one-point grid V[i] at
    Omega0 = Omega[i], as a structured array of Fate.dtype of the broadcast
    shape (a Fate for two numbers): the library's batch kernel, the skate's
    coefficients formed once and several orbits iterated at once.  A point
    that fails (V = 0: StateError; a non-finite one: DomainError; a final
    energy beyond the doubles: RangeError) fails alone: its row is zero.
    errors='raise' raises the first failure's exception (statuses and
    partial attached); errors='return' returns (fates, status).

    C: int chaplygin_discrete_fates_phase(const chaplygin_discrete *sys,
    size_t n, const double *V, const double *Omega,
    unsigned long max_collisions, chaplygin_fate *fates, int *status,
    int *scale)
    """
    _check_errors(errors)
    _system(sys)
    Va, Oa = np.broadcast_arrays(_as_float('V', V), _as_float('Omega',
                                                              Omega))
    max_collisions = _count('max_collisions', max_collisions)
    shape = Va.shape
    Vf = np.ascontiguousarray(Va).reshape(-1)
    Of = np.ascontiguousarray(Oa).reshape(-1)
    n = Vf.size
    out = np.zeros(n, Fate.dtype)
    status = np.zeros(n, np.intc)
    first = 0
    for j in range(0, n, _FATES_BLOCK):
        k = min(_FATES_BLOCK, n - j)
        rc = _lib.chaplygin_discrete_fates_phase(
            sys._c, k, _ffi.cast('double *', _ptr(Vf)) + j,
            _ffi.cast('double *', _ptr(Of)) + j, max_collisions,
            _ffi.cast('chaplygin_fate *', _ptr(out)) + j,
            _ffi.cast('int *', _ptr(status)) + j, _NULL)
        if rc and not first:
            first = rc
    out, status = out.reshape(shape), status.reshape(shape)
    if first and errors == 'raise':
        flat = np.flatnonzero(status.reshape(-1))
        _fail(first, 'chaplygin_discrete_fates_phase', statuses=status,
              partial=out, index=np.unravel_index(int(flat[0]), shape)
              if shape else None)
    if not shape:
        out = Fate.from_record(out[()])
        status = int(status)
    if errors == 'return':
        return _nt(('fates', 'status'))(out, status)
    return out


def basin_boundaries(sys, Omega0, V_lo, V_hi, n_grid, max_collisions):
    """discrete.basin_boundaries(sys, Omega0, V_lo, V_hi, n_grid,
    max_collisions)

    The basin boundaries on the grid of discrete.basins (n_grid points): an
    array of the V+ values (every grid point whose motion spins, and the V+
    where the fate changes between neighbours, refined by bisection to
    adjacent doubles), in grid order.

    C: int chaplygin_discrete_basin_boundaries(const chaplygin_discrete *sys,
    double Omega0, double V_lo, double V_hi, size_t n_grid,
    unsigned long max_collisions, double *V_boundary, size_t cap,
    size_t *count)
    """
    _system(sys)
    n_grid = int(_as_int('n_grid', n_grid, _scalar_dtype('size_t')))
    Omega0, V_lo, V_hi = (_real('Omega0', Omega0), _real('V_lo', V_lo),
                          _real('V_hi', V_hi))
    max_collisions = _count('max_collisions', max_collisions)
    cap = 2 * n_grid + 1
    while True:
        out = np.empty(cap, np.float64)
        count = _ffi.new('size_t *')
        rc = _lib.chaplygin_discrete_basin_boundaries(
            sys._c, Omega0, V_lo, V_hi, n_grid, max_collisions,
            _ffi.cast('double *', _ptr(out)), cap, count)
        if rc:
            _fail(rc, 'chaplygin_discrete_basin_boundaries')
        if count[0] <= cap:
            return out[:count[0]].copy()
        cap = count[0]
