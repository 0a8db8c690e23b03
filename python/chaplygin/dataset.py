"""chaplygin.dataset -- fate atlases (chaplygin.atlas): the fates of the discrete skate over two quantities at once,
as an xarray.Dataset, on one machine or on a Dask cluster.

atlas(scene, chunks=None) runs a scene with [sweep] kind = atlas (a file
name, or a dict with the sections and keys of the file: chaplygin.scene)
through the scene engine, `chaplygin sweep`'s own, and returns

    <xarray.Dataset>
    Dimensions:     (Omega: ny, V: nx)          # y, then x, by name
    Coordinates:    V (V), Omega (Omega)        # the grids, both ends exact
    Data variables: fate, collisions, reversals, E_final, V_final, status

with the numbers of the program's rows bit for bit (row k = i nx + j is
point [i, j]).  fate is -1 backward, 0 spin, 1 forward, 2 undecided (int8);
where status (the library's status number, int32) is not SUCCESS the point
has no fate: fate -128, collisions and reversals -1, E_final and V_final
NaN (declared as the _FillValue of each, so that a file written by
to_netcdf or to_zarr reads back masked there).  The attributes hold the
provenance: the effective scene (every key in use, defaults included:
written to a file, `chaplygin sweep` or atlas recompute the same numbers),
the method and the library function, the package's version.

chunks=None computes the whole grid at once, in the calling process, with
the engine's threads (threads=N: N of them; 0, the default: OpenMP's
default), within the scene's row limit ([run] max_rows, as `chaplygin
sweep`).  With chunks (anything dask.array.core.normalize_chunks takes for
the shape (ny, nx): (100, 1000), 'auto', ((ny,), (nx // 2, nx - nx // 2)))
the Dataset is backed by Dask arrays, one task per chunk computing a
window of the grid (chaplygin_sweep_window) with one thread: nothing is
computed until .compute(), .to_zarr() or .to_netcdf(), which run on
whatever Dask scheduler is active (dask.distributed included: the tasks
carry the scene as text, and each worker needs only this package).  Each
point's row depends on the point alone, so the values are the same bits
for every chunking and every scheduler; the row limit applies to each
chunk, and a worker holds one chunk's arrays (19 bytes a point) at a time.
"""
import collections

import numpy as np

from ._core import _ffi, _lib, SceneError, _polled
from . import scene as _scene

__all__ = ['atlas', 'VARIABLES', 'NO_FATE']

# The variables, their dtypes and the value of a point without a fate.
VARIABLES = (('fate', np.int8, -128), ('collisions', np.int64, -1),
             ('reversals', np.int64, -1), ('E_final', np.float64, np.nan),
             ('V_final', np.float64, np.nan), ('status', np.int32, None))
NO_FATE = _lib.CHP_PY_ATLAS_NO_FATE

_SCENE_TEXT_MAX = 1 << 20
_LONG_NAME = {
    'fate': 'the final motion: -1 straight line backward, 0 spinning, '
            '1 forward, 2 undecided after [run] collisions',
    'collisions': 'collisions iterated until the fate is certain',
    'reversals': 'velocity reversals on the way',
    'E_final': 'final energy (B.10) (undecided: E after the collisions)',
    'V_final': 'final velocity (spin: 0; undecided: V+ after the '
               'collisions)',
    'status': "the library's status at this point (chaplygin_status)"}


def _require():
    try:
        import xarray
        return xarray
    except ImportError as e:           # pragma: no cover - CI installs it
        raise ImportError('chaplygin.atlas needs xarray (Debian: '
                          'python3-xarray; chunks: python3-dask)') from e


def _report_error(rc, rep):
    msg = _ffi.string(rep.message).decode('utf-8', 'replace')
    if rc == _scene._SCENE_STATUS['ENOMEM']:
        raise MemoryError('atlas: out of memory')
    raise SceneError(None, None, detail=msg)


def _read(scene):
    """The scene SCENE (file name, dict or scene text) read by the engine:
    (scene object, its name)."""
    sc = _ffi.gc(_lib.chaplygin_scene_new(), _lib.chaplygin_scene_free)
    if sc == _ffi.NULL:
        raise MemoryError('atlas: out of memory')
    rep = _ffi.new('chaplygin_scene_report *')
    if isinstance(scene, dict):
        triples = _scene._triples(scene)
        cells = [[_ffi.new('char[]', _scene._text(t, 'a key or value'))
                  for t in row] for row in triples]
        sec = _ffi.new('char *[]', [c[0] for c in cells] or [_ffi.NULL])
        key = _ffi.new('char *[]', [c[1] for c in cells] or [_ffi.NULL])
        val = _ffi.new('char *[]', [c[2] for c in cells] or [_ffi.NULL])
        name = '<dict>'
        rc = _lib.chaplygin_scene_read_pairs(sc, len(triples), sec, key, val,
                                             name.encode(), rep)
    elif isinstance(scene, _SceneText):
        data = scene.text.encode()
        name = scene.name
        rc = _lib.chaplygin_scene_read_text(sc, data, len(data),
                                            name.encode('utf-8',
                                                        'surrogateescape'),
                                            rep)
    else:
        import os
        if not isinstance(scene, (str, bytes, os.PathLike)):
            raise TypeError('atlas: a file name or a dict expected, not %s'
                            % type(scene).__name__)
        path = _scene._text(os.fsencode(scene), 'a file name')
        name = os.fsdecode(path)
        rc = _lib.chaplygin_scene_read_file(sc, path, rep)
    if rc:
        _report_error(rc, rep)
    return sc, name


# An effective scene's text and the name of its source: what a Dask task
# carries to a worker.
_SceneText = collections.namedtuple('_SceneText', 'text name')


def _text_of(sc, key):
    buf = _ffi.new('char[]', _SCENE_TEXT_MAX)
    if _lib.chaplygin_scene_text(sc, key.encode(), buf, _SCENE_TEXT_MAX):
        return None
    return _ffi.string(buf).decode()


def _number_of(sc, key):
    x = _ffi.new('double *')
    if _lib.chaplygin_scene_number(sc, key.encode(), x):
        raise SceneError(None, None, detail='%s: [sweep] %s missing'
                         % (_ffi.string(_lib.chaplygin_scene_name(sc))
                            .decode('utf-8', 'replace'), key))
    return x[0]


def _scene_text(sc):
    buf = _ffi.new('char[]', _SCENE_TEXT_MAX)
    n = _lib.chp_py_scene_write_text(sc, buf, _SCENE_TEXT_MAX)
    if n < 0:                           # pragma: no cover - 1 MiB of scene
        raise MemoryError('atlas: the effective scene does not fit')
    return _ffi.string(buf, n).decode('utf-8', 'surrogateescape')


def _grid(lo, hi, n):
    out = np.empty(n, np.float64)
    rc = _lib.chp_py_grid_fill(lo, hi, n, _ffi.cast('double *',
                                                   out.ctypes.data))
    if rc:                              # pragma: no cover - a valid scene
        raise SceneError(None, None, detail='atlas: grid %r..%r' % (lo, hi))
    return out


class _Plan:
    """What atlas needs of a scene: its effective text, the grids, names."""

    def __init__(self, scene):
        sc, name = _read(scene)
        if _text_of(sc, 'kind') != 'atlas':
            raise SceneError(None, None, detail='%s: not an atlas (a scene '
                             'with [sweep] kind = atlas)' % name)
        self.scene = _SceneText(_scene_text(sc), name)
        self.x, self.y = _text_of(sc, 'x'), _text_of(sc, 'y')
        self.nx, self.ny = int(_number_of(sc, 'nx')), int(_number_of(sc, 'ny'))
        self.xs = _grid(_number_of(sc, 'x_min'), _number_of(sc, 'x_max'),
                        self.nx)
        self.ys = _grid(_number_of(sc, 'y_min'), _number_of(sc, 'y_max'),
                        self.ny)
        self.title = _text_of(sc, 'title') or ''
        self.method = _text_of(sc, 'method') or 'closed-form'


def _window(scene, i0, ni, j0, nj, threads):
    """The fate arrays (a dict by variable) of the window of NI x NJ points
    at row I0, column J0 of the atlas SCENE (a _SceneText)."""
    sc, _ = _read(scene)
    out = {name: np.empty((ni, nj), dtype) for name, dtype, _ in VARIABLES}
    a = _ffi.new('chp_py_atlas_arrays *')
    a.fate = _ffi.cast('signed char *', out['fate'].ctypes.data)
    a.collisions = _ffi.cast('long long *', out['collisions'].ctypes.data)
    a.reversals = _ffi.cast('long long *', out['reversals'].ctypes.data)
    a.E_final = _ffi.cast('double *', out['E_final'].ctypes.data)
    a.V_final = _ffi.cast('double *', out['V_final'].ctypes.data)
    a.status = _ffi.cast('int *', out['status'].ctypes.data)
    rep = _ffi.new('chaplygin_scene_report *')
    rc = _polled(_lib.chp_py_atlas_window, sc, i0, ni, j0, nj, threads, a,
                 rep)
    if rc:
        _report_error(rc, rep)
    if a.beyond:
        import warnings
        warnings.warn('atlas: E_final or V_final of a velocity-scaled point '
                      'lies beyond the doubles, read as 0 or inf',
                      RuntimeWarning, stacklevel=3)
    return out


def _dask_variables(plan, chunks):
    """The variables as Dask arrays, one task per chunk."""
    import dask
    import dask.array as da
    try:
        rows, cols = da.core.normalize_chunks(chunks, shape=(plan.ny,
                                                             plan.nx),
                                              dtype=np.float64)
    except (ValueError, TypeError, ZeroDivisionError) as e:
        raise ValueError('atlas: chunks %r for the grid of %d x %d points: '
                         '%s' % (chunks, plan.ny, plan.nx, e)) from None
    if min(rows + cols) < 1:
        raise ValueError('atlas: chunks %r: an empty chunk' % (chunks,))
    blocks = {name: [] for name, _, _ in VARIABLES}
    i0 = 0
    for ni in rows:
        line = {name: [] for name, _, _ in VARIABLES}
        j0 = 0
        for nj in cols:
            task = dask.delayed(_window, pure=True)(plan.scene, i0, ni, j0,
                                                    nj, 1)
            for name, dtype, _ in VARIABLES:
                line[name].append(da.from_delayed(task[name], (ni, nj),
                                                  dtype=dtype))
            j0 += nj
        for name in line:
            blocks[name].append(line[name])
        i0 += ni
    return {name: da.block(b) for name, b in blocks.items()}


def atlas(scene, chunks=None, *, threads=0):
    """atlas(scene, chunks=None, *, threads=0) -> xarray.Dataset

    The fate atlas of SCENE (a file name or a dict; [sweep] kind = atlas):
    see the module's documentation.  chunks=None: computed now (threads:
    the engine's OpenMP threads, 0 its default); else a Dask-backed
    Dataset of those chunks, computed by the active Dask scheduler.
    Errors: SceneError (a scene that does not parse, is not an atlas, or
    is beyond its row limit), ValueError (chunks that are not a chunking of
    the grid, threads), ImportError without xarray (or dask, with
    chunks).
    """
    xr = _require()
    plan = _Plan(scene)
    if isinstance(threads, bool) or not isinstance(threads, int) \
            or not 0 <= threads <= 4096:
        raise ValueError('atlas: threads is an integer 0..4096')
    if chunks is None:
        data = _window(plan.scene, 0, plan.ny, 0, plan.nx, threads)
    else:
        data = _dask_variables(plan, chunks)
    dims = (plan.y, plan.x)
    variables = {}
    for name, _, fill in VARIABLES:
        v = xr.Variable(dims, data[name], attrs={'long_name':
                                                 _LONG_NAME[name]})
        if fill is not None:
            v.encoding['_FillValue'] = fill
        variables[name] = v
    variables['fate'].attrs.update(
        flag_values=np.array([-1, 0, 1, 2], np.int8),
        flag_meanings='backward spin forward undecided')
    from . import __version__
    certified = plan.method == 'certified'
    attrs = {
        'title': plan.title,
        'source': 'chaplygin %s, chaplygin.atlas' % __version__,
        'scene': plan.scene.text,
        'method': 'certified: the exact return map on (E, H), every fate '
                  'decided exactly' if certified else
                  'closed-form: the return map on (V+^2, H)',
        'function': 'chaplygin_certified_orbit_fate' if certified else
                    'chaplygin_discrete_basins',
        'x': plan.x, 'y': plan.y,
        'k': 'k = i nx + j for the point [i, j] (chaplygin sweep\'s rows)'}
    coords = {plan.x: (plan.x, plan.xs), plan.y: (plan.y, plan.ys)}
    return xr.Dataset(variables, coords=coords, attrs=attrs)
