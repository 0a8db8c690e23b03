"""The sweeps of Figure 2 (chaplygin_sweep_*): x = L0/Delta,
y = (1/Delta)^2 >= 0.

  sigma4(x, y, dir)   Fig. 2(a): sigma4 (3.10) over x for each y
  stability(x, y)     Fig. 2(b): the stability regions on the grid x by y

Both call the library's own array functions, on blocks of at most _BLOCK
points (the interpreter runs signal handlers between the calls: Ctrl-C
interrupts a sweep); grid_point (also chaplygin.grid_point) is the grid of
every sweep.
"""
import numpy as np

from ._core import (_ffi, _lib, _NULL, _fail, _as_float, _ptr, _nt,
                    _check_errors, _real, _as_int, _scalar_dtype,
                    _refuse_masked)

__all__ = ['sigma4', 'stability', 'grid_point']

# Points per call of a sweep function: about 1 ms.
_BLOCK = 1 << 16


def _blocks(n):
    """(start, count) of the blocks of N points (one empty block for N = 0:
    the call still checks its other arguments)."""
    return [(j, min(_BLOCK, n - j)) for j in range(0, n, _BLOCK)] or [(0, 0)]


def sigma4(x, y, dir, *, errors='raise'):
    """sweep.sigma4(x, y, dir, *, errors='raise')

    Fig. 2(a): sigma4[i] of (3.10) for the direction dir at
    y = (1/Delta)^2 >= 0 and each x[i] = L0/Delta.  x: an array of any
    shape; y: a number (result of x's shape) or a 1-D array (result of
    shape (len(y),) + x.shape, row i at y[i]).  Points that fail (x
    non-finite, y = 0 with x = -1 (dir +1) or 0 (dir -1)) are NaN with
    their status: errors='raise' raises the first failure's exception
    (statuses and partial attached); errors='return' returns
    (sigma4, status).

    C: int chaplygin_sweep_sigma4(int dir, double y, size_t n,
    const double *x, double *sigma4, int *status)
    """
    _check_errors(errors)
    xa = np.ascontiguousarray(_as_float('x', x))
    ya = _as_float('y', y)
    if ya.ndim > 1:
        raise ValueError('y: a number or a 1-D array expected')
    ys = ya.reshape(-1)
    shape = (xa.shape if ya.ndim == 0 else (ys.size,) + xa.shape)
    out = np.empty((ys.size,) + xa.shape, np.float64)
    status = np.zeros((ys.size,) + xa.shape, np.intc)
    n = xa.size
    first = 0
    xp = _ffi.cast('double *', _ptr(xa) if n else 0)
    for i, yv in enumerate(ys):
        o, st = out[i].reshape(-1), status[i].reshape(-1)
        op = _ffi.cast('double *', _ptr(o) if n else 0)
        sp = _ffi.cast('int *', _ptr(st) if n else 0)
        for j, k in _blocks(n):
            rc = _lib.chaplygin_sweep_sigma4(dir, float(yv), k, xp + j,
                                             op + j, sp + j)
            if rc and not (n and st[j:j + k].any()):
                st[j:j + k] = rc        # a failure of the call as a whole
            if rc and not first:
                first = rc
    bad = status != 0
    out[bad] = np.nan
    out = out.reshape(shape)
    status = status.reshape(shape)
    if first and errors == 'raise':
        flat = np.flatnonzero(status.reshape(-1))
        index = np.unravel_index(int(flat[0]), shape) if flat.size else None
        _fail(first, 'chaplygin_sweep_sigma4', statuses=status,
              partial=out, index=index)
    if errors == 'return':
        return _nt(('sigma4', 'status'))(out if shape else out.item(),
                                         status if shape else status.item())
    return out if shape else out.item()


def stability(x, y):
    """sweep.stability(x, y)

    Fig. 2(b): region[i, j] = (1 if V* > 0 is stable by (3.11)) + (2 if
    V* < 0 is stable by (3.12)) at (x[j], y[i]), x and y 1-D arrays (y >= 0),
    as a uint8 array of shape (len(y), len(x)).  A non-finite x or y, or
    y < 0, raises DomainError (nothing is computed).

    C: int chaplygin_sweep_stability(size_t nx, const double *x, size_t ny,
    const double *y, unsigned char *region)
    """
    xa = np.ascontiguousarray(_as_float('x', x)).reshape(-1)
    ya = np.ascontiguousarray(_as_float('y', y)).reshape(-1)
    region = np.zeros((ya.size, xa.size), np.uint8)
    if region.size == 0:
        return region
    nx = xa.size
    xp = _ffi.cast('double *', _ptr(xa))
    yp = _ffi.cast('double *', _ptr(ya))
    rp = _ffi.cast('unsigned char *', _ptr(region))
    rows = max(1, _BLOCK // nx)             # whole rows, or one in blocks
    for i in range(0, ya.size, rows):
        ny = min(rows, ya.size - i)
        for j, k in _blocks(nx) if rows == 1 else [(0, nx)]:
            rc = _lib.chaplygin_sweep_stability(k, xp + j, ny, yp + i,
                                                rp + i * nx + j)
            if rc:
                _fail(rc, 'chaplygin_sweep_stability')
    return region


def grid_point(lo, hi, n, i):
    """grid_point(lo, hi, n, i)

    The i-th of the n points of the library's uniform grid from lo to hi
    (the grid of every sweep and of discrete.basins): lo, lo + (hi - lo)
    i/(n - 1), ..., hi, the ends exact (also where hi - lo overflows).  i
    may be an array of indices: an array of the points (the loop in
    Python, one C call per point).  DomainError for lo or hi not finite,
    InvalidArgumentError for n = 0 or i outside 0 .. n-1.

    C: int chaplygin_grid_point(double lo, double hi, size_t n, size_t i,
    double *v)
    """
    lo, hi = _real('lo', lo), _real('hi', hi)
    n = int(_as_int('n', n, _scalar_dtype('size_t')))
    _refuse_masked('i', i)
    idx = np.asarray(i)
    if idx.dtype.kind not in 'iu':
        raise TypeError('grid_point: i is an integer or an array of them')
    if (idx < 0).any():
        _fail(_lib.CHAPLYGIN_EINVAL, 'chaplygin_grid_point')
    v = _ffi.new('double *')
    out = np.empty(idx.shape, np.float64)
    for k, ik in np.ndenumerate(idx):
        rc = _lib.chaplygin_grid_point(lo, hi, n, int(ik), v)
        if rc:
            _fail(rc, 'chaplygin_grid_point')
        out[k] = v[0]
    return out if idx.ndim else float(out)
