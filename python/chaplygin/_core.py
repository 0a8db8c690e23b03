# _core.py -- the machinery under the generated wrappers (_generated.py):
# the extension module, exceptions, struct classes, enums, options, and the
# vectorised path (_vec) that runs the C loops of python/gen.py over NumPy
# arrays.  Nothing here computes a number of the model: every number comes
# from a function of libchaplygin.
"""Internal machinery of the chaplygin package (see chaplygin.vectorised)."""

import collections
import decimal
import math
import numbers
import operator
import threading

import numpy as np

from ._chaplygin_cffi import ffi as _ffi, lib as _lib

_NULL = _ffi.NULL
_new = _ffi.new
_namedtuple = collections.namedtuple

# Filled by _generated.py: the parameters of every function (gen.py).
SPEC = {}

# Types that take the scalar fast path (anything else goes through _vec,
# which converts with NumPy and checks).
_SC = frozenset([int, float, bool, np.float64, np.float32, np.float16,
                 np.int8, np.int16, np.int32, np.int64, np.uint8, np.uint16,
                 np.uint32, np.uint64, np.bool_])
_SQ = frozenset([list, tuple])

# ---------------------------------------------------------------------------
# Signals during long calls.  Every C loop of the binding (the generated
# chpv_ loops, python/src) takes a poll, which it calls every 50 ms
# (python/src/poll.h): chp_py_poll, a cffi callback.  cffi takes the GIL
# to call it and the interpreter runs the pending signal handlers on
# entering it; the exception one raises (KeyboardInterrupt) goes to
# _poll_raised, which keeps it for _polled to raise and stops the loop.
# Only Python's main thread runs signal handlers: other threads pass no
# poll (and so never wait for the GIL).

_RAISED = []        # one slot per polled call in progress, innermost last
_POLLING = True     # False: no poll (python/bench/bench.py's reference)


def _poll_raised(exc_type, exc, tb):
    if _RAISED and _RAISED[-1] is None:
        _RAISED[-1] = exc
    return 1


@_ffi.def_extern(onerror=_poll_raised)
def chp_py_poll():
    """The poll of the C loops: the signal handlers run on entry."""
    return 0


_POLL = _lib.chp_py_poll
_get_ident = threading.get_ident
_main_thread = threading.main_thread


def _polled(fn, *args):
    """fn(*args, poll): a C loop of the binding, polling from the main
    thread; the exception a signal handler raised during it is raised."""
    if not _POLLING or _get_ident() != _main_thread().ident:
        return fn(*args, _NULL)
    _RAISED.append(None)
    try:
        r = fn(*args, _POLL)
    finally:
        exc = _RAISED.pop()
    if exc is not None:
        raise exc
    return r


# ---------------------------------------------------------------------------
# C types as NumPy dtypes


def _int_dtype(cname):
    size = _ffi.sizeof(cname)
    unsigned = cname.startswith('unsigned') or cname == 'size_t'
    return np.dtype(('u' if unsigned else 'i') + str(size))


_DTYPES = {}


def _scalar_dtype(cname):
    dt = _DTYPES.get(cname)
    if dt is None:
        dt = _DTYPES[cname] = _scalar_dtype_of(cname)
    return dt


def _scalar_dtype_of(cname):
    if cname in ('double',):
        return np.dtype(np.float64)
    if cname == 'float':
        return np.dtype(np.float32)
    t = _ffi.typeof(cname)
    if t.kind == 'enum':
        return _int_dtype('int') if _ffi.sizeof(t) == _ffi.sizeof('int') \
            else _int_dtype('long')
    return _int_dtype(cname)


def _ctype_dtype(t):
    """The NumPy dtype of the cffi type T (primitive, enum, array, struct)."""
    if t.kind == 'array':
        return np.dtype((_ctype_dtype(t.item), (t.length,)))
    if t.kind == 'struct':
        names, formats, offsets = [], [], []
        for name, field in t.fields:
            names.append(name)
            formats.append(_ctype_dtype(field.type))
            offsets.append(field.offset)
        return np.dtype({'names': names, 'formats': formats,
                         'offsets': offsets, 'itemsize': _ffi.sizeof(t)})
    return _scalar_dtype(t.cname)


# ---------------------------------------------------------------------------
# Enumerations: IntEnum classes named after the C enum types.

import enum as _enum

ENUM_CLASSES = {}
_ENUM_NAMES = {}    # C enum type -> {lower-case name: value}


def _enum_class_name(ctype):
    base = ctype.replace('enum ', '')
    base = base[len('chaplygin_'):] if base.startswith('chaplygin_') else base
    return ''.join(w.capitalize() for w in base.split('_'))


def _make_enum(ctype):
    rel = _ffi.typeof(ctype).relements          # name -> value, aliases kept
    names = [n[len('CHAPLYGIN_'):] if n.startswith('CHAPLYGIN_') else n
             for n in rel]
    prefix = ''
    if len(names) > 1:
        common = names[0]
        for n in names[1:]:
            while not n.startswith(common):
                common = common[:-1]
        prefix = common[:common.rfind('_') + 1] if '_' in common else ''
    members = []
    for cname, short in zip(rel, names):
        member = short[len(prefix):]
        if not member or member[0].isdigit():
            member = short
        members.append((member, rel[cname]))
    cls = _enum.IntEnum(_enum_class_name(ctype), members,
                        module='chaplygin')
    ENUM_CLASSES[ctype] = cls
    _ENUM_NAMES[ctype] = {m.lower().replace('_', '-'): v for m, v in members}
    return cls


def _enum_value(ctype, x, what):
    """X (a name such as 'closed-form', or an integer) as a value of the C
    enum CTYPE."""
    if isinstance(x, str):
        names = _ENUM_NAMES[ctype]
        key = x.strip().lower().replace('_', '-')
        if key not in names:
            raise InvalidArgumentError(
                _lib.CHAPLYGIN_EINVAL, None,
                detail='unknown %s %r (one of %s)'
                % (what, x, ', '.join(sorted(names))))
        return names[key]
    return operator.index(x)


# ---------------------------------------------------------------------------
# Exceptions: one class per status code.

class ChaplyginError(Exception):
    """A nonzero status of libchaplygin.

    Attributes: status (the int status, None for an error of a scene that is
    not a status of the library), name ('CHAPLYGIN_EDOM'), message
    (chaplygin_strerror(status)), function (the C function), detail (more
    text, or None).  A vectorised call adds statuses (the array of statuses),
    index (the index of the first failure) and partial (the results, NaN or 0
    where a call failed); a failed orbit or scene adds partial likewise.
    """

    def __init__(self, status, function=None, detail=None, **extra):
        self.status = status
        self.function = function
        self.detail = detail
        self.name = _STATUS_NAMES.get(status) if status is not None else None
        self.message = (_ffi.string(_lib.chaplygin_strerror(status)).decode()
                        if status is not None else None)
        for k, v in extra.items():
            setattr(self, k, v)
        super().__init__(str(self))

    def __str__(self):
        parts = []
        if self.function:
            parts.append(self.function)
        if self.name:
            parts.append(self.name)
        if self.message:
            parts.append(self.message)
        if self.detail:
            parts.append(self.detail)
        return ': '.join(parts)

    def __reduce__(self):
        extra = {k: v for k, v in self.__dict__.items()
                 if k not in ('status', 'function', 'detail', 'name',
                              'message')}
        return (_rebuild_error, (type(self), self.status, self.function,
                                 self.detail, extra))


def _rebuild_error(cls, status, function, detail, extra):
    return cls(status, function, detail, **extra)


class InvalidArgumentError(ChaplyginError, ValueError):
    """CHAPLYGIN_EINVAL: null pointer, unknown method, flag or tolerance."""


class DomainError(ChaplyginError, ValueError):
    """CHAPLYGIN_EDOM: NaN or infinite argument, or a parameter outside its
    domain."""


class StateError(ChaplyginError, ValueError):
    """CHAPLYGIN_ESTATE: a state inconsistent with the model."""


class SpinError(ChaplyginError):
    """CHAPLYGIN_ESPIN: the motion ends in the spinning equilibrium (3.8)."""


class RangeError(ChaplyginError, ArithmeticError):
    """CHAPLYGIN_ERANGE: the result is not representable in double."""


class NoConvergenceError(ChaplyginError, ArithmeticError):
    """CHAPLYGIN_ENOCONV: quadrature or ODE integration did not reach the
    requested tolerance."""


class OutOfMemoryError(ChaplyginError, MemoryError):
    """CHAPLYGIN_ENOMEM: memory allocation failed."""


class CertificationCapError(ChaplyginError, ArithmeticError):
    """CHAPLYGIN_ECAP: the certified method would need more than its
    precision or size cap to prove the result (the orbit is left as it
    was; CertifiedOrbit.cap raises the cap)."""


class SceneError(ChaplyginError, ValueError):
    """A scene that does not parse or that the model rejects (the program's
    exit status 2); message: the program's message."""


class EquationError(ChaplyginError, ValueError):
    """chaplygin.eq: an unknown label, or inputs that do not fit it
    (missing, unknown, unused, not a number); message: the program's."""


_ERROR_CLASSES = {
    'EINVAL': InvalidArgumentError, 'EDOM': DomainError,
    'ESTATE': StateError, 'ESPIN': SpinError, 'ERANGE': RangeError,
    'ENOCONV': NoConvergenceError, 'ENOMEM': OutOfMemoryError,
    'ECAP': CertificationCapError,
}

Status = _make_enum('enum chaplygin_status')
ERRORS = {}                 # status -> exception class
_STATUS_NAMES = {}
for _member in Status:
    _STATUS_NAMES[int(_member)] = 'CHAPLYGIN_' + _member.name
    if _member.value == 0:
        continue
    _cls = _ERROR_CLASSES.get(_member.name)
    if _cls is None:        # a status this file does not know yet
        _cls = type(_member.name + 'Error', (ChaplyginError,),
                    {'__doc__': 'CHAPLYGIN_%s.' % _member.name,
                     '__module__': 'chaplygin'})
    ERRORS[_member.value] = _cls
for _c in list(_ERROR_CLASSES.values()) + [ChaplyginError, SceneError]:
    _c.__module__ = 'chaplygin'


def error_class(status):
    """The exception class of STATUS (ChaplyginError for an unknown one)."""
    return ERRORS.get(status, ChaplyginError)


def _fail(rc, function, **extra):
    raise error_class(rc)(rc, function, **extra)


# ---------------------------------------------------------------------------
# Struct classes: one per struct typedef of the header, holding the C
# struct itself (passed to C without copying).

STRUCT_CLASSES = {}


class Struct:
    """Base of the classes of the header's structs (DiscreteState, Fate,
    ...): a C struct with its fields as attributes.  Construct with the
    fields as positional or keyword arguments (others are 0); a struct with
    an init function in the header (chaplygin_discrete_init) is constructed
    by it: Discrete(L0, Delta).  Array fields read as tuples.  dtype is the
    NumPy dtype of the struct: the vectorised functions take and return
    structured arrays of it; from_record and to_record convert."""
    __slots__ = ('_c',)
    _ctype = None
    _fields = ()
    _array_fields = frozenset()
    dtype = None
    _init = None

    def __init__(self, *args, **kw):
        self._c = _new(self._ctype + ' *')
        if self._init is not None:
            rc = self._init(self._c, *args, **kw)
            if rc:
                _fail(rc, self._init_name)
            return
        if len(args) > len(self._fields):
            raise TypeError('%s takes at most %d fields'
                            % (type(self).__name__, len(self._fields)))
        for name, value in zip(self._fields, args):
            if name in kw:
                raise TypeError('%s: field %s given twice'
                                % (type(self).__name__, name))
            setattr(self, name, value)
        for name, value in kw.items():
            if name not in self._fields:
                raise TypeError('%s has no field %r'
                                % (type(self).__name__, name))
            setattr(self, name, value)

    @classmethod
    def _wrap(cls, cdata):
        obj = object.__new__(cls)
        obj._c = cdata
        return obj

    @classmethod
    def from_record(cls, record):
        """The struct from a record (an element of a structured array of
        dtype, or a 0-d one)."""
        arr = np.asarray(record)
        if arr.dtype != cls.dtype:
            raise TypeError('%s.from_record: dtype %s, not %s'
                            % (cls.__name__, arr.dtype, cls.dtype))
        obj = object.__new__(cls)
        obj._c = _new(cls._ctype + ' *')
        _ffi.memmove(obj._c, np.ascontiguousarray(arr).reshape(()).tobytes(),
                     cls.dtype.itemsize)
        return obj

    def to_record(self):
        """A 0-d structured array (dtype) holding a copy of the struct."""
        return np.frombuffer(_ffi.buffer(self._c), dtype=self.dtype)\
            .reshape(()).copy()

    def as_dict(self):
        """The fields as a dict."""
        return {name: getattr(self, name) for name in self._fields}

    def copy(self):
        obj = object.__new__(type(self))
        obj._c = _new(self._ctype + ' *', self._c[0])
        return obj

    __copy__ = copy

    def __deepcopy__(self, memo):
        return self.copy()

    def __reduce__(self):
        return (_rebuild_struct, (type(self), self.to_record().tobytes()))

    def __repr__(self):
        return '%s(%s)' % (type(self).__name__, ', '.join(
            '%s=%r' % (name, getattr(self, name)) for name in self._fields))

    def __eq__(self, other):
        if type(other) is not type(self):
            return NotImplemented
        return all(getattr(self, n) == getattr(other, n)
                   for n in self._fields)

    __hash__ = None


def _rebuild_struct(cls, data):
    obj = object.__new__(cls)
    obj._c = _new(cls._ctype + ' *')
    _ffi.memmove(obj._c, data, cls.dtype.itemsize)
    return obj


def _struct_property(name, ftype):
    if ftype.kind == 'array':
        n = ftype.length

        def get(self):
            return tuple(getattr(self._c, name)[0:n])

        def set_(self, value):
            value = tuple(value)
            if len(value) != n:
                raise ValueError('field %s takes %d values' % (name, n))
            setattr(self._c, name, value)
    elif ftype.kind == 'enum':
        ctype = ftype.cname

        def get(self):
            v = getattr(self._c, name)
            cls = ENUM_CLASSES.get(ctype)
            try:
                return cls(v) if cls else v
            except ValueError:
                return v

        def set_(self, value):
            setattr(self._c, name, _enum_value(ctype, value, name))
    else:
        def get(self):
            return getattr(self._c, name)

        def set_(self, value):
            setattr(self._c, name, value)
    return property(get, set_, doc='The field %s.' % name)


def _struct_class(ctype):
    """The class of the struct typedef CTYPE (made once)."""
    if ctype in STRUCT_CLASSES:
        return STRUCT_CLASSES[ctype]
    t = _ffi.typeof(ctype)
    for _, field in t.fields:
        if field.type.kind == 'enum' and field.type.cname not in ENUM_CLASSES:
            _make_enum(field.type.cname)
    ns = {'__slots__': (), '_ctype': ctype,
          '_fields': tuple(name for name, _ in t.fields),
          'dtype': _ctype_dtype(t), '__module__': 'chaplygin',
          '__doc__': 'The C struct %s (fields: %s).  See Struct.'
          % (ctype, ', '.join(name for name, _ in t.fields))}
    for name, field in t.fields:
        ns[name] = _struct_property(name, field.type)
    # CTYPE_init constructs when the struct is its first parameter
    # (chaplygin_discrete_init (sys, L0, Delta)); an init returning the
    # struct last (chaplygin_smooth_motion_init) is an ordinary function
    init = ctype + '_init'
    if hasattr(_lib, init) and \
            _ffi.typeof(getattr(_lib, init)).args[0] == _ffi.typeof(ctype + ' *'):
        ns['_init'] = staticmethod(getattr(_lib, init))
        ns['_init_name'] = init
    cls = type(_enum_class_name(ctype), (Struct,), ns)
    STRUCT_CLASSES[ctype] = cls
    return cls


# ---------------------------------------------------------------------------
# Options and requests

_OPTIONS_CACHE = {}
_OPTIONS_DEFAULT = None


def _options_default():
    global _OPTIONS_DEFAULT
    if _OPTIONS_DEFAULT is None:
        from ._generated import OPTIONS_DEFAULT
        vals = []
        for tok in OPTIONS_DEFAULT:
            vals.append(getattr(_lib, tok) if tok.startswith('CHAPLYGIN_')
                        else float(tok))
        _OPTIONS_DEFAULT = tuple(vals)
    return _OPTIONS_DEFAULT


def _options(method, tol, precision):
    """The chaplygin_options of the keywords (NULL: all None, the library's
    default); a name such as 'quadrature' or an enum value for method and
    precision.  The C function validates the values."""
    if method is None and tol is None and precision is None:
        return _NULL
    key = (method, tol, precision)
    try:
        return _OPTIONS_CACHE[key]
    except (KeyError, TypeError):
        pass
    d_method, d_tol, d_precision = _options_default()
    opt = _new('chaplygin_options *')
    opt.method = d_method if method is None else \
        _enum_value('chaplygin_method', method, 'method')
    opt.tol = d_tol if tol is None else tol
    opt.precision = d_precision if precision is None else \
        _enum_value('chaplygin_precision', precision, 'precision')
    if len(_OPTIONS_CACHE) > 256:
        _OPTIONS_CACHE.clear()
    try:
        _OPTIONS_CACHE[key] = opt
    except TypeError:
        pass
    return opt


def _request(x):
    """A request (enum chaplygin_request) from 'all', 'theta,tau', a
    sequence of names, or an integer."""
    if isinstance(x, str):
        names = _ENUM_NAMES['enum chaplygin_request']
        value = 0
        for part in x.replace('|', ',').split(','):
            part = part.strip().lower()
            if not part or part == 'none':
                continue
            if part not in names:
                raise InvalidArgumentError(
                    _lib.CHAPLYGIN_EINVAL, None,
                    detail='unknown request %r (one of %s)'
                    % (part, ', '.join(sorted(names))))
            value |= names[part]
        return value
    if isinstance(x, (list, tuple, set, frozenset)) and \
            all(isinstance(p, str) for p in x):
        return _request(','.join(x))
    return x


# ---------------------------------------------------------------------------
# Results

_NT_CACHE = {}


def _nt(fields):
    """The named tuple class 'Result' of FIELDS (made once).  Its instances
    pickle as (FIELDS, values), rebuilt by _result: the class itself is not
    importable (one per tuple of fields)."""
    cls = _NT_CACHE.get(fields)
    if cls is None:
        cls = _NT_CACHE[fields] = _namedtuple('Result', fields,
                                              rename=True)
        cls.__module__ = __name__
        cls.__reduce__ = lambda self: (_result, (fields, tuple(self)))
    return cls


def _result(fields, values):
    """A Result of FIELDS (unpickling)."""
    return _nt(fields)(*values)


def _pick(names, flags, values):
    """The values whose flag is set: one alone, several as a named tuple."""
    sel = [i for i, f in enumerate(flags) if f]
    if len(sel) == 1:
        return values[sel[0]]
    if not sel:
        return None
    return _nt(tuple(names[i] for i in sel))(*(values[i] for i in sel))


def _arr(cdata, n):
    """The first N elements of a C array as a NumPy array (16: 4 x 4)."""
    a = np.array(_ffi.unpack(cdata, n))
    if n == 16:
        a = a.reshape(4, 4)
    return a


# ---------------------------------------------------------------------------
# The vectorised path

def _ptr(arr):
    """A char * to the data of the NumPy array ARR (which must stay alive
    while it is used)."""
    if arr.flags.c_contiguous:
        return _ffi.cast('char *', _ffi.from_buffer(arr))
    return _ffi.cast('char *', arr.__array_interface__['data'][0])


_F8 = np.dtype(np.float64)
_INT_LIMITS = {}


def _limits(dtype):
    lim = _INT_LIMITS.get(dtype)
    if lim is None:
        info = np.iinfo(dtype)
        lim = _INT_LIMITS[dtype] = (int(info.min), int(info.max))
    return lim


# Argument conversion: every number and array a wrapper takes passes
# _as_float, _as_int, _as_struct or _real, which raise TypeError for what is
# not a number (None, str, bytes, objects: NumPy would make None NaN and
# '1.5' 1.5) and refuse masked arrays (np.asarray drops the mask: masked
# points would be computed and returned unmasked).

_REAL_TYPES = (numbers.Real, decimal.Decimal)


def _holds_masked(seq):
    """Whether the (nested) list or tuple SEQ holds numpy.ma.masked, which
    np.asarray would make NaN with a warning."""
    return any(v is np.ma.masked
               or (type(v) in (list, tuple) and _holds_masked(v))
               for v in seq)


def _refuse_masked(name, x):
    if isinstance(x, np.ma.MaskedArray) or (
            type(x) in (list, tuple) and _holds_masked(x)):
        raise TypeError(
            '%s: a masked array (numpy.ma) is not taken, its mask would be '
            'ignored: pass x.filled(np.nan) (masked points then fail alone, '
            'errors="return" gives their status) or x.compressed()' % name)


def _as_float(name, x):
    if type(x) is np.ndarray and x.dtype is _F8:
        return x
    _refuse_masked(name, x)
    a = np.asarray(x)
    kind = a.dtype.kind
    if a.dtype == _F8:
        return a
    if kind in 'biuf':
        return a.astype(np.float64)
    if kind == 'O':
        for v in a.flat:
            if not isinstance(v, _REAL_TYPES) or \
                    isinstance(v, np.ma.MaskedArray):
                raise TypeError('%s: real numbers expected, not %s'
                                % (name, type(v).__name__))
        return a.astype(np.float64)
    raise TypeError('%s: real numbers expected, not %s' % (name, a.dtype))


def _real(name, x):
    """One real number X as a float (TypeError otherwise)."""
    if type(x) is float or type(x) is int:
        return float(x)
    a = _as_float(name, x)
    if a.ndim:
        raise TypeError('%s: one number expected, not an array of shape %s'
                        % (name, a.shape))
    return float(a)


def _as_int(name, x, dtype):
    if type(x) is int:
        lo, hi = _limits(dtype)
        if not lo <= x <= hi:
            raise OverflowError('%s: %d out of the range of C %s'
                                % (name, x, dtype))
        return np.asarray(x, dtype)
    _refuse_masked(name, x)
    a = np.asarray(x)
    kind = a.dtype.kind
    if kind == 'O':
        try:
            a = np.array([operator.index(v) for v in a.flat],
                         dtype=object).reshape(a.shape)
        except TypeError:
            raise TypeError('%s: integers expected' % name) from None
        if a.size:
            lo, hi = min(a.flat), max(a.flat)
        else:
            lo = hi = 0
    elif kind in 'biu':
        if a.size:
            lo, hi = int(a.min()), int(a.max())
        else:
            lo = hi = 0
    else:
        raise TypeError('%s: integers expected, not %s' % (name, a.dtype))
    imin, imax = _limits(dtype)
    if lo < imin or hi > imax:
        raise OverflowError('%s: %d..%d out of the range of C %s'
                            % (name, lo, hi, dtype))
    return a.astype(dtype, copy=False)


def _as_struct(name, ctype, x):
    cls = _struct_class(ctype)
    dt = cls.dtype
    if isinstance(x, cls):
        return np.frombuffer(_ffi.buffer(x._c), dtype=dt).reshape(())
    _refuse_masked(name, x)
    if isinstance(x, np.ndarray) and x.dtype == dt:
        return x
    if isinstance(x, np.ndarray) and x.dtype.names:
        fields = {n: x[n] for n in x.dtype.names}
        return _struct_from_fields(name, cls, fields, x.shape)
    if isinstance(x, collections.abc.Mapping):
        return _struct_from_fields(name, cls, x, None)
    if isinstance(x, (list, tuple)) and all(isinstance(v, cls) for v in x):
        out = np.empty(len(x), dt)
        for i, v in enumerate(x):
            out[i] = np.frombuffer(_ffi.buffer(v._c), dtype=dt)[0]
        return out
    raise TypeError('%s: a %s, a structured array of %s.dtype or a dict of '
                    'its fields expected, not %s'
                    % (name, cls.__name__, cls.__name__, type(x).__name__))


def _struct_from_fields(name, cls, fields, shape):
    dt = cls.dtype
    unknown = set(fields) - set(dt.names)
    if unknown:
        raise TypeError('%s: %s has no field %s'
                        % (name, cls.__name__, ', '.join(sorted(unknown))))
    arrays = {}
    shapes = []
    for f, v in fields.items():
        fdt = dt.fields[f][0]
        sub = fdt.shape
        base = fdt.base
        if base.kind == 'f':
            a = _as_float('%s[%r]' % (name, f), v)
        else:
            a = _as_int('%s[%r]' % (name, f), v, base)
        if sub:
            if a.shape[a.ndim - len(sub):] != sub:
                raise ValueError('%s[%r]: trailing shape %s expected'
                                 % (name, f, sub))
            shapes.append(a.shape[:a.ndim - len(sub)])
        else:
            shapes.append(a.shape)
        arrays[f] = a
    if shape is None:
        shape = np.broadcast_shapes(*shapes) if shapes else ()
    out = np.zeros(shape, dt)
    for f, a in arrays.items():
        out[f] = a
    return out


def _flat(arr, shape, inner):
    """(array, byte stride) such that element i of the broadcast SHAPE
    (C order) of the batch dimensions of ARR is at data + i stride; copies
    ARR only where no single stride fits.  INNER trailing dimensions belong
    to one element and are kept contiguous."""
    bnd = arr.ndim - inner
    bshape = arr.shape[:bnd]
    elem = arr.itemsize * (math.prod(arr.shape[bnd:]) if inner else 1)
    inner_ok = (not inner or arr[(0,) * bnd].flags.c_contiguous
                if arr.size else True)
    if arr.flags.aligned and inner_ok:
        if math.prod(bshape) == 1:
            return arr, 0
        if tuple(bshape) == tuple(shape):
            dims = [(n, s) for n, s in zip(bshape, arr.strides[:bnd])
                    if n != 1]
            ok = all(dims[j][1] == dims[j + 1][1] * dims[j + 1][0]
                     for j in range(len(dims) - 1))
            if ok and dims:
                return arr, dims[-1][1]
    full = tuple(shape) + tuple(arr.shape[bnd:])
    out = np.ascontiguousarray(np.broadcast_to(arr, full))
    return out, elem


_MAX_ELEMENTS = np.iinfo(np.intp).max // 64


def _broadcast(shapes):
    """np.broadcast_shapes, quickly where all shapes are equal or ()."""
    shape = ()
    for sh in shapes:
        if sh == shape or not sh:
            continue
        shape = sh if not shape else np.broadcast_shapes(shape, sh)
    return shape


def _fill_failed(out, bad):
    """NaN into the float fields, 0 into the others, where BAD."""
    if out.dtype.names:
        for f in out.dtype.names:
            _fill_failed_field(out[f], bad)
    else:
        _fill_failed_field(out, bad)


def _fill_failed_field(a, bad):
    a[bad] = np.nan if a.dtype.kind == 'f' else 0


def _blank(dtype, shape):
    """An output array prefilled with NaN (floats) and 0 (others)."""
    if dtype.names:
        a = np.zeros(shape, dtype)
        for f in dtype.names:
            if dtype.fields[f][0].base.kind == 'f':
                a[f] = np.nan
        return a
    return np.full(shape, np.nan if dtype.kind == 'f' else 0, dtype)


def _scalar_out(kind, ctype, dims, a, count=None):
    if kind == 'out':
        return a.item()
    if kind == 'out_array':
        a = a.copy()
        if count is not None:
            a = a[:count]
        elif dims == 16:
            a = a.reshape(4, 4)
        return a
    return _struct_class(ctype).from_record(a)


_ERRORS_POLICIES = ('raise', 'return')


def _check_errors(errors):
    if errors not in _ERRORS_POLICIES:
        raise ValueError("errors must be 'raise' or 'return', not %r"
                         % (errors,))


def _vec(cname, inputs, wants, opt, errors, spec=None):
    """Call the C loop chpv_CNAME over the broadcast of INPUTS (see
    chaplygin.vectorised); SPEC replaces SPEC[CNAME] (a hand-written
    wrapper's reading of the parameters)."""
    _check_errors(errors)
    if spec is None:
        spec = SPEC[cname]
    loop = getattr(_lib, 'chpv_' + cname)
    it_in = iter(inputs)
    it_want = iter(wants)
    prepared = []
    shapes = []
    for name, kind, ctype, dims, extra in spec:
        if kind in ('in', 'in_array', 'in_struct'):
            x = next(it_in)
            if x is None and extra.get('nullable'):
                prepared.append(None)
                continue
            if kind == 'in':
                dt = _scalar_dtype(ctype) if not ctype.startswith('enum') \
                    else _int_dtype('int')
                a = _as_float(name, x) if dt.kind == 'f' \
                    else _as_int(name, x, dt)
                inner = 0
            elif kind == 'in_array':
                a = _as_float(name, x)
                if a.ndim < 1 or a.shape[-1] != dims:
                    raise ValueError('%s: an array of shape (..., %d) '
                                     'expected, not %s'
                                     % (name, dims, a.shape))
                inner = 1
            else:
                a = _as_struct(name, ctype, x)
                inner = 0
            shapes.append(a.shape[:a.ndim - inner])
            prepared.append((a, inner))
        elif kind == 'opt':
            prepared.append(opt)
        else:
            prepared.append(next(it_want))
    shape = _broadcast(shapes)
    n = math.prod(shape)
    if n > _MAX_ELEMENTS:
        raise MemoryError('%s: %d elements' % (cname, n))
    ptrs, strides, keep, outs = [], [], [], []
    flags = {}
    for (name, kind, ctype, dims, extra), prep in zip(spec, prepared):
        if kind in ('in', 'in_array', 'in_struct'):
            if prep is None:
                ptrs.append(_NULL)
                strides.append(0)
                continue
            a, stride = _flat(prep[0], shape, prep[1])
            keep.append(a)
            ptrs.append(_ptr(a))
            strides.append(stride)
        elif kind == 'opt':
            ptrs.append(_ffi.cast('char *', prep))
            strides.append(0)
        else:
            if not prep:
                ptrs.append(_NULL)
                strides.append(0)
                outs.append(None)
                continue
            if kind == 'out_struct':
                dt = _struct_class(ctype).dtype
                oshape = shape
            else:
                dt = _scalar_dtype(ctype)
                oshape = shape + ((dims,) if kind == 'out_array' else ())
            if 'if' in extra or 'count' in extra or extra.get('prefill'):
                a = _blank(dt, oshape)
            else:
                a = np.empty(oshape, dt)
            outs.append((name, kind, ctype, dims, extra, a))
            flags[name] = a
            ptrs.append(_ptr(a))
            strides.append(a.itemsize * (dims if kind == 'out_array' else 1))
    status = np.empty(shape, np.intc)
    c_ptrs = _ffi.new('char *[]', ptrs) if ptrs else _NULL
    c_strides = _ffi.new('ptrdiff_t[]', strides) if strides else _NULL
    nfail = _polled(loop, n, c_ptrs, c_strides,
                    _ffi.cast('int *', _ptr(status)))
    del keep
    if nfail:
        bad = status != 0
        for o in outs:
            if o is not None:
                _fill_failed(o[5], bad)
    names = [o[0] for o in outs if o is not None]
    if shape == ():
        vals = []
        for o in outs:
            if o is None:
                continue
            name, kind, ctype, dims, extra, a = o
            count = flags[extra['count']].item() if 'count' in extra else None
            v = _scalar_out(kind, ctype, dims, a, count)
            if 'if' in extra and not flags[extra['if']].item():
                v = None
            vals.append(v)
        st = int(status.item())
        if st and errors == 'raise':
            _fail(st, cname)
        if errors == 'return':
            return _nt(tuple(names) + ('status',))(*vals, st)
        return _pick(names, [True] * len(vals), vals)
    vals = [o[5].reshape(shape + (4, 4))
            if o[1] == 'out_array' and o[3] == 16 else o[5]
            for o in outs if o is not None]
    if nfail and errors == 'raise':
        first = int(np.flatnonzero(status.reshape(-1))[0])
        index = np.unravel_index(first, shape)
        st = int(status.reshape(-1)[first])
        result = _pick(names, [True] * len(vals), vals)
        _fail(st, cname, index=index, statuses=status, partial=result,
              detail='%d of %d elements failed, the first at index %s'
              % (nfail, n, tuple(int(i) for i in index)))
    if errors == 'return':
        return _nt(tuple(names) + ('status',))(*vals, status)
    return _pick(names, [True] * len(vals), vals)




def as_columns(arr):
    """A dict of plain arrays from a structured array (a result of a
    vectorised call): one entry per field, an array field of 2 split into
    NAME_x and NAME_y (as the program's CSV names peg_x, peg_y), of other
    lengths into NAME_0, NAME_1, ..."""
    arr = np.asarray(arr)
    if not arr.dtype.names:
        raise TypeError('as_columns: a structured array expected')
    out = {}
    for name in arr.dtype.names:
        col = arr[name]
        sub = arr.dtype.fields[name][0].shape
        if not sub:
            out[name] = col
        elif sub == (2,):
            out[name + '_x'] = col[..., 0]
            out[name + '_y'] = col[..., 1]
        else:
            for i in range(sub[0]):
                out['%s_%d' % (name, i)] = col[..., i]
    return out
