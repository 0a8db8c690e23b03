"""Scenes from Python: `chaplygin run` without the CSV file.

run_scene(scene, compare=False) runs a scene -- a file name, or a dict with
the same sections and keys as the file -- with the program's own code
(tools/scene.c reads it, tools/run.c and tools/sweep.c run it, compiled into
this package), and returns the CSV columns of `chaplygin run` as a dict of
NumPy arrays in column order: the same columns, names and numbers (the CSV's
%.17g round-trips every double exactly).

    run_scene('scenes/fig6.ini')
    run_scene({'scene': {'model': 'discrete'},
               'parameters': {'L0': 1, 'Delta': '1/3'},
               'initial': {'V': 1, 'Omega': 0.5},
               'run': {'collisions': 20, 'outputs': ['E', 'H', 'theta']}})

Values of a dict: numbers (written with repr, which round-trips), strings
(as in the file: '1/3', 'closed-form', 'E,H'), or lists (joined with
commas: outputs, y).  The integer columns (n, k, reversal, fate, collisions,
reversals, status, region, forward, backward) are int64, the others
float64; status is the library's status number (the program's CSV names
it: SUCCESS, ERANGE, ...).  A column with empty fields (a sweep's point that failed: its
status column says why) is a numpy.ma.MaskedArray, masked there.

Tiny and huge states (V = Omega = 1e-300, 1e+200): the program runs them in
the units of the library's exact velocity scaling and prints the physical
values, a number beyond the doubles (E = 1.1249999999999999e-600) as its
exact decimal.  In a float64 column such a number is what float() makes of
it, 0.0 (or a subnormal) or +-inf, as numpy.loadtxt and other readers into
doubles give it; run_scene then warns (RuntimeWarning, naming the columns).
Run the scene with V and Omega scaled by a power of two
(chaplygin.velocity_scaling) to keep those columns in range.

Errors: a scene that does not parse or that the model rejects raises
SceneError with the program's message; a library failure during the run
raises the exception of its status (SpinError, ...) when the message names
one (ChaplyginError otherwise), with partial = the columns of the rows
written before it.
"""
import os
import warnings
from collections.abc import Mapping

import numpy as np

from ._core import (_ffi, _lib, ChaplyginError, SceneError, error_class,
                    ERRORS, Status)

__all__ = ['run_scene', 'to_ini', 'INTEGER_COLUMNS']

INTEGER_COLUMNS = frozenset(['n', 'k', 'reversal', 'fate', 'collisions',
                             'reversals', 'status', 'region', 'forward',
                             'backward'])


def _value(section, key, v):
    if isinstance(v, bool):
        raise TypeError('[%s] %s: a number or a string expected, not bool'
                        % (section, key))
    if isinstance(v, (int, np.integer)):
        text = str(int(v))
    elif isinstance(v, (float, np.floating)):
        text = repr(float(v))
    elif isinstance(v, str):
        text = v
    elif isinstance(v, (list, tuple)):
        text = ','.join(_value(section, key, x) for x in v)
    else:
        raise TypeError('[%s] %s: a number, a string or a list expected, '
                        'not %s' % (section, key, type(v).__name__))
    if any(c in text for c in '\n\r\0'):
        raise ValueError('[%s] %s: a value may not contain a line break or '
                         'NUL' % (section, key))
    return text


def to_ini(scene):
    """The scene file of SCENE, a dict {section: {key: value}}."""
    if not isinstance(scene, Mapping):
        raise TypeError('a scene dict {section: {key: value}} expected')
    lines = []
    for section, keys in scene.items():
        if not isinstance(section, str) or not isinstance(keys, Mapping):
            raise TypeError('scene: {section: {key: value}} expected at %r'
                            % (section,))
        if any(c in section for c in '[]\n\r\0;#='):
            raise ValueError('scene: bad section name %r' % section)
        lines.append('[%s]' % section)
        for key, v in keys.items():
            if not isinstance(key, str) or \
                    any(c in key for c in '[]\n\r\0;#='):
                raise ValueError('scene: [%s] bad key %r' % (section, key))
            lines.append('%s = %s' % (key, _value(section, key, v)))
    return '\n'.join(lines) + '\n'


def _columns(text):
    lines = text.split('\n')
    if lines and lines[-1] == '':
        lines.pop()
    if not lines:
        return {}
    names = lines[0].split(',')
    rows = [l.split(',') for l in lines[1:]]
    out = {}
    lost = []
    for j, name in enumerate(names):
        fields = [r[j] if j < len(r) else '' for r in rows]
        missing = [f == '' for f in fields]
        if name == 'status':
            # a name (SUCCESS, ERANGE, ...), or a number the program has no
            # name for
            vals = np.array([0 if not f else int(f) if f.lstrip('-').isdigit()
                             else Status[f] for f in fields], dtype=np.int64)
        elif name in INTEGER_COLUMNS:
            vals = np.array([int(f) if f else 0 for f in fields],
                            dtype=np.int64)
        else:
            vals = np.array([float(f) if f else np.nan for f in fields],
                            dtype=np.float64)
            # a number beyond the doubles (printed exactly by the program)
            # read as 0 or inf
            for i in np.flatnonzero((vals == 0) | np.isinf(vals)):
                mant = fields[i].lower().partition('e')[0]
                if np.isinf(vals[i]) or any(ch in mant for ch in '123456789'):
                    lost.append(name)
                    break
        if any(missing):
            vals = np.ma.masked_array(vals, mask=missing)
        out[name] = vals
    if lost:
        warnings.warn('run_scene: column(s) %s hold numbers beyond the '
                      'doubles (a velocity-scaled run), read as 0 or inf'
                      % ', '.join(lost), RuntimeWarning, stacklevel=3)
    return out


def _status_of(message):
    """The status whose chaplygin_strerror text MESSAGE contains."""
    for status in sorted(ERRORS):
        text = _ffi.string(_lib.chaplygin_strerror(status)).decode()
        if text and text in message:
            return status
    return None


def run_scene(scene, compare=False):
    """run_scene(scene, compare=False) -> dict of arrays

    Run SCENE (a file name, or a dict {section: {key: value}} with the keys
    of a scene file) as `chaplygin run SCENE` does (compare=True: `chaplygin
    run --compare`, the smooth companion), and return the CSV columns by
    name, in order (see the module's documentation).
    """
    csv = _ffi.new('char **')
    csv_len = _ffi.new('size_t *')
    err = _ffi.new('char **')
    if isinstance(scene, Mapping):
        text = to_ini(scene).encode()
        name = b'<dict>'
        rc = _lib.chp_py_scene_run(name, text, len(text), bool(compare),
                                   csv, csv_len, err)
    elif isinstance(scene, (str, bytes, os.PathLike)):
        path = os.fsencode(scene)
        if b'\0' in path:
            raise ValueError('run_scene: a file name with NUL')
        rc = _lib.chp_py_scene_run(path, _ffi.NULL, 0, bool(compare), csv,
                                   csv_len, err)
    else:
        raise TypeError('run_scene: a file name or a dict expected, not %s'
                        % type(scene).__name__)
    try:
        out = _ffi.string(csv[0], csv_len[0]).decode() if csv[0] else ''
        msg = _ffi.string(err[0]).decode(errors='replace').strip() \
            if err[0] else ''
    finally:
        _lib.chp_py_free(csv[0])
        _lib.chp_py_free(err[0])
    if rc == -1:
        raise MemoryError('run_scene: out of memory')
    if rc == 2:
        raise SceneError(None, None, detail=msg)
    columns = _columns(out)
    if rc != 0:
        status = _status_of(msg)
        cls = error_class(status) if status is not None else ChaplyginError
        raise cls(status, None, detail=msg, partial=columns)
    return columns
