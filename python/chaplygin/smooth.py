"""The smooth Chaplygin sleigh: Section 2 and Appendix A (chaplygin_smooth_*).

Generated wrappers of every chaplygin_smooth_* function; q = [S, V, theta,
Omega] (phase form), p = [S, E, theta, H_C] (energy-momentum form).
help(chaplygin.smooth.closed_form) shows the header's comment.

By hand (the path is read and written):
  path_advance(m, path, tau)   C and G at a later time, from the previous
                               sample
  path(m, taus, C0)            C and G at increasing times, one walk
"""
import numpy as np

from ._core import _ffi, _lib, _fail, _check_errors, _nt, _SC, \
    _struct_class, _as_float, _real
from ._groups import export

__all__ = []
export(globals(), 'smooth')

SmoothDim = _struct_class('chaplygin_smooth_dim')
SmoothNondim = _struct_class('chaplygin_smooth_nondim')
SmoothMotion = _struct_class('chaplygin_smooth_motion')
SmoothPath = _struct_class('chaplygin_smooth_path')
__all__ += ['SmoothDim', 'SmoothNondim', 'SmoothMotion', 'SmoothPath',
            'path_advance', 'path']


def _typed(x, cls, what, made_by):
    if type(x) is not cls:
        raise TypeError('%s: a chaplygin.smooth.%s expected (made by %s), '
                        'not %s' % (what, cls.__name__, made_by,
                                    type(x).__name__))
    return x


def _time(tau):
    if type(tau) not in _SC and not (isinstance(tau, np.ndarray)
                                     and tau.shape == ()):
        raise TypeError('tau: one number expected, not %s (a walk is '
                        'sequential: smooth.path takes many times)'
                        % type(tau).__name__)
    return _real('tau', tau)


def path_advance(m, path, tau, *, errors='raise'):
    """smooth.path_advance(m, path, tau, *, errors='raise')

    Advance the path of the motion m to time tau >= path.tau: C(tau) by
    adaptive Gauss-Kronrod quadrature of dC/dtau = V (cos theta, sin theta)
    (exact for a line or a circle), and the mass centre G = C + L (cos
    theta, sin theta) at tau.  path is not changed: the advanced path is
    returned, to pass to the next call (a walk is sequential, so this
    function takes one motion and one time; smooth.path walks many times).

    C: int chaplygin_smooth_path_advance(const chaplygin_smooth_motion *m,
    chaplygin_smooth_path *path, double tau, double G[2])
    Returns: (path, G): the advanced SmoothPath and G (ndarray of 2).
    Raises: a ChaplyginError subclass for a nonzero status (errors='raise');
    errors='return' returns (path, G, status), path and G unchanged (the
    input path, NaN) on a failure.
    """
    _typed(m, SmoothMotion, 'm', 'chaplygin.smooth.motion_init(L, q0)')
    _typed(path, SmoothPath, 'path', 'chaplygin.smooth.path_init(tau, C)')
    _check_errors(errors)
    tau = _time(tau)
    out = path.copy()
    G = _ffi.new('double[2]', [float('nan')] * 2)
    rc = _lib.chaplygin_smooth_path_advance(m._c, out._c, tau, G)
    if rc and errors == 'raise':
        _fail(rc, 'chaplygin_smooth_path_advance')
    g = np.array([G[0], G[1]])
    if errors == 'return':
        return _nt(('path', 'G', 'status'))(path.copy() if rc else out, g,
                                             rc)
    return out, g


path_advance.__c_function__ = 'chaplygin_smooth_path_advance'


def path(m, taus, C0=None, *, errors='raise'):
    """smooth.path(m, taus, C0=None, *, errors='raise')

    The contact point C and the mass centre G of the motion m at the times
    taus (non-decreasing, >= 0), one walk from C0 (default the origin) at
    tau = 0: chaplygin_smooth_path_init, then chaplygin_smooth_path_advance
    from each sample to the next (C's rounding errors carried, so many
    short steps add no rounding).
    Returns: (C, G), ndarrays of shape (len(taus), 2).
    Raises: a ChaplyginError subclass at the first failing time
    (errors='raise'); errors='return' returns (C, G, status): rows from
    the first failure on are NaN and status is that failure's (0 if none).
    """
    _typed(m, SmoothMotion, 'm', 'chaplygin.smooth.motion_init(L, q0)')
    _check_errors(errors)
    t = _as_float('taus', taus)
    if t.ndim != 1:
        raise ValueError('taus: a 1-d sequence of times expected')
    Cv = np.full((t.size, 2), np.nan)
    Gv = np.full((t.size, 2), np.nan)
    p = SmoothPath()
    c0 = _ffi.NULL if C0 is None else _as_float('C0', C0)
    if C0 is not None and c0.shape != (2,):
        raise ValueError('C0: two numbers (x, y) expected')
    if C0 is not None:
        c0 = _ffi.new('double[2]', c0.tolist())
    rc = _lib.chaplygin_smooth_path_init(0.0, c0, p._c)
    G = _ffi.new('double[2]')
    for i in range(t.size):
        if rc:
            break
        rc = _lib.chaplygin_smooth_path_advance(m._c, p._c, t[i], G)
        if not rc:
            Cv[i] = (p._c.C[0], p._c.C[1])
            Gv[i] = (G[0], G[1])
    if rc and errors == 'raise':
        _fail(rc, 'chaplygin_smooth_path_advance')
    if errors == 'return':
        return _nt(('C', 'G', 'status'))(Cv, Gv, rc)
    return Cv, Gv


path.__c_function__ = 'chaplygin_smooth_path_advance'
