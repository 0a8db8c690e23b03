"""Scenes from Python: `chaplygin run` without a CSV file.

run_scene(scene, compare=False) runs a scene -- a file name, or a dict with
the same sections and keys as the file -- with the library's scene engine
(libchaplygin-scene, the program's own), and returns the columns of
`chaplygin run` as a dict of NumPy arrays in column order: the same
columns, names and numbers, taken from the engine's rows as doubles and
integers (no text is written or parsed on the way).

    run_scene('scenes/fig6.ini')
    run_scene({'scene': {'model': 'discrete'},
               'parameters': {'L0': 1, 'Delta': '1/3'},
               'initial': {'V': 1, 'Omega': 0.5},
               'run': {'collisions': 20, 'outputs': ['E', 'H', 'theta']}})

Values of a dict: numbers (int as itself, float by repr, which reads back
as the same double), strings (as in the file: '1/3', 'closed-form', 'E,H'),
or lists (joined with commas: outputs, y).  Each value is one key's value
as the engine reads it: no comment, no continuation, no INI syntax.  The
integer columns (n, k, reversal, fate, collisions, reversals, status,
region, forward, backward) are int64, the others float64; status is the
library's status number (the program's CSV names it: SUCCESS, ERANGE,
...).  A column with missing cells (a sweep's point that failed: its status
column says why) is a numpy.ma.MaskedArray, masked there.  Numbers are read
and written in the C locale whatever the process's locale.

Tiny and huge states (V = Omega = 1e-300, 1e+200): the engine runs them in
the units of the library's exact velocity scaling and gives the physical
values, a number beyond the doubles (E = 1.1249999999999999e-600) as a
double with a power of two; in a float64 column it becomes its rounding,
0.0 (or a subnormal) or +-inf; run_scene then warns (RuntimeWarning,
naming the columns).  Run the scene with V and Omega scaled by a power of
two (chaplygin.velocity_scaling) to keep those columns in range.

Errors: a scene that does not parse, that the model rejects or that is
beyond its row limit raises SceneError with the engine's message; a
library failure during the run raises the exception of its status
(SpinError, ...), with partial = the columns of the rows before it.
"""
import os
import warnings
from collections.abc import Mapping

import numpy as np

from ._core import (_ffi, _lib, SceneError, error_class, _polled)

__all__ = ['run_scene', 'to_ini', 'INTEGER_COLUMNS']

INTEGER_COLUMNS = frozenset(['n', 'k', 'reversal', 'fate', 'collisions',
                             'reversals', 'status', 'region', 'forward',
                             'backward'])

_REAL = 1                       # CHAPLYGIN_COLUMN_REAL
_SCENE_STATUS = {'OK': 0, 'EINVAL': 1, 'EIO': 2, 'ESCENE': 3, 'EMODEL': 4,
                 'ELIMIT': 5, 'ERUN': 6, 'ESTOPPED': 7, 'ENOMEM': 8}


def _value(section, key, v):
    if isinstance(v, bool):
        raise TypeError('[%s] %s: a number or a string expected, not bool'
                        % (section, key))
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        return repr(float(v))
    if isinstance(v, str):
        return v
    if isinstance(v, (list, tuple)):
        return ','.join(_value(section, key, x) for x in v)
    raise TypeError('[%s] %s: a number, a string or a list expected, not %s'
                    % (section, key, type(v).__name__))


def _triples(scene):
    """The (section, key, value) texts of the scene dict SCENE."""
    if not isinstance(scene, Mapping):
        raise TypeError('a scene dict {section: {key: value}} expected')
    out = []
    for section, keys in scene.items():
        if not isinstance(section, str) or not isinstance(keys, Mapping):
            raise TypeError('scene: {section: {key: value}} expected at %r'
                            % (section,))
        for key, v in keys.items():
            if not isinstance(key, str):
                raise TypeError('scene: [%s] a key is a string, not %s'
                                % (section, type(key).__name__))
            out.append((section, key, _value(section, key, v)))
    return out


def to_ini(scene):
    """The scene file of SCENE, a dict {section: {key: value}}."""
    lines, last = [], None
    triples = _triples(scene)
    for section in scene:
        if any(c in section for c in '[]\n\r\0;#='):
            raise ValueError('scene: bad section name %r' % section)
    for section, key, text in triples:
        if any(c in key for c in '[]\n\r\0;#='):
            raise ValueError('scene: [%s] bad key %r' % (section, key))
        if any(c in text for c in '\n\r\0'):
            raise ValueError('[%s] %s: a value may not contain a line break '
                             'or NUL' % (section, key))
        if section != last:
            lines.append('[%s]' % section)
            last = section
        lines.append('%s = %s' % (key, text))
    return '\n'.join(lines) + '\n'


def _text(s, what):
    b = s.encode('utf-8', 'surrogateescape') if isinstance(s, str) else s
    if b'\0' in b:
        raise ValueError('run_scene: %s with NUL' % what)
    return b


def _columns(table):
    """The columns of the engine's TABLE as NumPy arrays, by name."""
    x = _ffi.new('double **')
    n = _ffi.new('long long **')
    e = _ffi.new('int **')
    m = _ffi.new('unsigned char **')
    rows = _lib.chp_py_table_rows(table)
    out, lost = {}, []
    for j in range(_lib.chp_py_table_columns(table)):
        name = _ffi.string(_lib.chp_py_table_name(table, j)).decode()
        _lib.chp_py_table_data(table, j, x, n, e, m)
        if _lib.chp_py_table_kind(table, j) == _REAL:
            vals = np.frombuffer(_ffi.buffer(x[0], rows * 8),
                                 np.float64).copy() if rows else \
                np.zeros(0, np.float64)
            if e[0] != _ffi.NULL and rows:
                exp = np.frombuffer(_ffi.buffer(e[0], rows * 4), np.intc)
                beyond = exp != 0
                with np.errstate(over='ignore', under='ignore'):
                    vals[beyond] = np.ldexp(vals[beyond], exp[beyond])
                if beyond.any():
                    lost.append(name)
        else:
            vals = np.frombuffer(_ffi.buffer(n[0], rows * 8),
                                 np.int64).copy() if rows else \
                np.zeros(0, np.int64)
        missing = np.frombuffer(_ffi.buffer(m[0], rows), np.uint8) \
            .astype(bool) if rows else np.zeros(0, bool)
        if missing.any():
            vals = np.ma.masked_array(vals, mask=missing)
        out[name] = vals
    if lost:
        warnings.warn('run_scene: column(s) %s hold numbers beyond the '
                      'doubles (a velocity-scaled run), read as 0 or inf'
                      % ', '.join(lost), RuntimeWarning, stacklevel=3)
    return out


def run_scene(scene, compare=False):
    """run_scene(scene, compare=False) -> dict of arrays

    Run SCENE (a file name, or a dict {section: {key: value}} with the keys
    of a scene file) as `chaplygin run SCENE` does (compare=True: `chaplygin
    run --compare`, the smooth companion), and return the columns by name,
    in order (see the module's documentation).
    """
    table = _ffi.new('chp_py_table **')
    rep = _ffi.new('chaplygin_scene_report *')
    if isinstance(scene, Mapping):
        triples = _triples(scene)
        cells = [[_ffi.new('char[]', _text(t, 'a key or value'))
                  for t in row] for row in triples]
        sec = _ffi.new('char *[]', [c[0] for c in cells] or [_ffi.NULL])
        key = _ffi.new('char *[]', [c[1] for c in cells] or [_ffi.NULL])
        val = _ffi.new('char *[]', [c[2] for c in cells] or [_ffi.NULL])
        args = (_ffi.NULL, len(triples), sec, key, val, b'<dict>')
    elif isinstance(scene, (str, bytes, os.PathLike)):
        path = _text(os.fsencode(scene), 'a file name')
        args = (path, 0, _ffi.NULL, _ffi.NULL, _ffi.NULL, _ffi.NULL)
    else:
        raise TypeError('run_scene: a file name or a dict expected, not %s'
                        % type(scene).__name__)
    try:
        rc = _polled(_lib.chp_py_scene_run, *args, bool(compare), table, rep)
        columns = _columns(table[0]) if table[0] != _ffi.NULL else {}
    finally:
        _lib.chp_py_table_free(table[0])
    msg = _ffi.string(rep.message).decode('utf-8', 'replace')
    if rc == _SCENE_STATUS['OK']:
        return columns
    if rc == _SCENE_STATUS['ENOMEM']:
        raise MemoryError('run_scene: out of memory')
    if rc == _SCENE_STATUS['ERUN']:
        status = rep.library_status
        raise error_class(status)(status, None, detail=msg, partial=columns)
    raise SceneError(None, None, detail=msg)
