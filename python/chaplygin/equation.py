"""The paper's numbered equations by label, as `chaplygin eq` evaluates
them.

    r = chaplygin.eq('3.10', L0=1, Delta='1/3', dir=-1)
    r.sigma4                  # 1.1666666666666665, the value
    r['sigma4']               # the same
    r.outputs                 # {'sigma4': 1.1666666666666665}
    r.functions               # {'sigma4': 'chaplygin_discrete_sigma4'}
    chaplygin.eq('3.10', L0=1, Delta='1/3', dir=-1, certified=True).sigma4
                              # 1.1666666666666667, the nearest to 7/6
    chaplygin.eq('2.1', L=1, V=1, Omega=0.5).printed   # the printed forms
    chaplygin.labels()        # every label, in the paper's order

Labels, inputs and outputs are those of the registry of the paper's labels
(lib/labels.txt) that the scene engine evaluates (chaplygin_eq_eval): the
program and this function give the same numbers, bit for bit.  Inputs are
keywords: numbers (int, float: read back exactly), fractions.Fraction (as
p/q, exactly) or strings as `chaplygin eq` takes them ('1/3', 'quadrature');
dir is +1 or -1.  Every input given must be used by the label.

Outputs beyond the doubles: where V and Omega make a state whose E or H
would leave the doubles, the label is evaluated in the units of a velocity
scaling (r.inputs says so) and an output is x 2^e; in r.outputs (and
r.printed) it is the float ldexp(x, e), +-inf or 0.0 (or a subnormal)
where that leaves the doubles, as run_scene's columns are, with a
RuntimeWarning naming the outputs; r.exact (r.printed_exact) holds every
finite real output (printed form) exactly, as a fractions.Fraction (the
program prints its decimal, %.17g of the exact value).

Errors: an unknown label or inputs that do not fit it raise EquationError;
inputs the library rejects (outside the domain) and failures of the
library raise the exception of the library's status (DomainError, ...).
"""
import fractions
import math
import numbers
import warnings

import numpy as np

from ._core import _ffi, _lib, EquationError, error_class

__all__ = ['eq', 'labels', 'Equation', 'Label']

_KINDS = {0: 'real', 1: 'int', 2: 'word'}
_EINVAL, _ENOMEM = 1, 8


def _string(p):
    return _ffi.string(p).decode() if p != _ffi.NULL else None


class Label:
    """One label of the registry: label, title, inputs (usage), outputs,
    functions, errata (a tuple of ids), paper (the audit's verdict) and
    example (an example call, NAME=VALUE ...)."""

    __slots__ = ('label', 'title', 'inputs', 'outputs', 'functions',
                 'errata', 'paper', 'example')

    def __init__(self, **fields):
        for k in self.__slots__:
            setattr(self, k, fields[k])

    @classmethod
    def _of(cls, e):
        errata = _string(e.errata)
        return cls(label=_string(e.label), title=_string(e.title),
                   inputs=_string(e.inputs), outputs=_string(e.outputs),
                   functions=tuple(f.strip() for f in
                                   _string(e.functions).split(',')),
                   errata=() if errata == '-' else tuple(errata.split()),
                   paper=_string(e.paper), example=_string(e.example))

    def __reduce__(self):
        return (_label, (tuple(getattr(self, k) for k in self.__slots__),))

    def __eq__(self, other):
        return isinstance(other, Label) and all(
            getattr(self, k) == getattr(other, k) for k in self.__slots__)

    def __repr__(self):
        return 'Label(%r, %r)' % (self.label, self.title)


def _label(values):
    return Label(**dict(zip(Label.__slots__, values)))


def labels():
    """Every label of the registry, in the paper's order (Label objects)."""
    return [Label._of(_lib.chaplygin_eq_entry_at(i))
            for i in range(_lib.chaplygin_eq_count())]


class Equation:
    """The value of one label at given inputs: outputs (name -> value, in
    order), functions and methods (name -> the library function that
    computed it, and how), printed (name -> the printed form's value, None
    where it is undefined at these inputs; only outputs with a printed
    form), errata (name -> the erratum of that printed form), relative
    (name -> |printed - value|/|value|), exact and printed_exact (name ->
    the fractions.Fraction of a finite real output, of its printed form:
    exact also beyond the doubles), inputs (the inputs as read, as the
    program shows them), and the label's label, title, paper and note.
    An output is also an attribute and an item: r.sigma4, r['sigma4']."""

    def __init__(self, label, title, paper, note, inputs, outputs, functions,
                 methods, printed, errata, relative, exact=None,
                 printed_exact=None):
        self.label, self.title, self.paper, self.note = (label, title, paper,
                                                         note)
        self.inputs = inputs
        self.outputs, self.functions, self.methods = (outputs, functions,
                                                      methods)
        self.printed, self.errata, self.relative = printed, errata, relative
        self.exact = {} if exact is None else exact
        self.printed_exact = {} if printed_exact is None else printed_exact

    def __getitem__(self, name):
        return self.outputs[name]

    def __getattr__(self, name):
        outputs = self.__dict__.get('outputs', {})
        if name in outputs:
            return outputs[name]
        raise AttributeError(name)

    def __eq__(self, other):
        return isinstance(other, Equation) and self.__dict__ == other.__dict__

    def __repr__(self):
        return 'Equation(%r, %r)' % (self.label, self.outputs)


def _text(name, v):
    if isinstance(v, bool):
        raise TypeError('eq: %s: a number or a string expected, not bool'
                        % name)
    if isinstance(v, numbers.Integral):
        return str(int(v))
    if isinstance(v, fractions.Fraction):
        return '%d/%d' % (v.numerator, v.denominator)
    if isinstance(v, (float, np.floating)):
        return repr(float(v))
    if isinstance(v, str):
        if '\0' in v:
            raise ValueError('eq: %s: a value with NUL' % name)
        return v
    raise TypeError('eq: %s: a number or a string expected, not %s'
                    % (name, type(v).__name__))


def _real(x, e):
    """x 2^e: (the float, rounded to +-inf or 0 beyond the doubles, as
    run_scene's columns; the exact Fraction, None for a non-finite x)."""
    x, e = float(x), int(e)
    if not math.isfinite(x):
        return x, None
    q = fractions.Fraction(x) * fractions.Fraction(2) ** e
    try:
        return math.ldexp(x, e), q
    except OverflowError:
        return math.copysign(math.inf, x), q


def eq(label, *, certified=False, **inputs):
    """eq(label, *, certified=False, **inputs) -> Equation

    Evaluate the paper's equation LABEL ('3.10', '(A.2)', 'b.16') at the
    keyword INPUTS, as `chaplygin eq LABEL NAME=VALUE ...` does (see the
    module's documentation).  certified=True is `chaplygin eq --certified`
    (chaplygin_eq_eval_with, CHAPLYGIN_EQ_CERTIFIED): every input exact (a
    Fraction or 'p/q' that rational, a float the double it is), every
    output the double nearest to the exact value; a label without a
    certified evaluator raises EquationError."""
    if not isinstance(label, str):
        raise TypeError('eq: the label is a string such as "3.10", not %s'
                        % type(label).__name__)
    if not isinstance(certified, bool):
        raise TypeError('eq: certified is True or False, not %s'
                        % type(certified).__name__)
    names = [_ffi.new('char[]', k.encode()) for k in inputs]
    values = [_ffi.new('char[]', _text(k, v).encode())
              for k, v in inputs.items()]
    res = _ffi.new('chaplygin_eq_result *')
    rc = _lib.chaplygin_eq_eval_with(label.encode('utf-8', 'replace'),
                                     _lib.CHAPLYGIN_EQ_CERTIFIED if certified
                                     else 0, len(names),
                                     _ffi.new('char *[]',
                                              names or [_ffi.NULL]),
                                     _ffi.new('char *[]',
                                              values or [_ffi.NULL]),
                                     res)
    msg = _ffi.string(res.message).decode('utf-8', 'replace')
    if rc == _ENOMEM:
        raise MemoryError('eq: out of memory')
    if rc == _EINVAL:
        raise EquationError(None, None, detail='eq %s: %s' % (label, msg))
    if rc != 0:
        raise error_class(res.library_status)(res.library_status, None,
                                              detail='eq %s: %s'
                                              % (label, msg))
    outs = [res.out[i] for i in range(res.n_out)]
    value, exact, printed, printed_exact, errata, relative = ({}, {}, {}, {},
                                                              {}, {})
    beyond = []                 # outputs whose float is not their value
    for o in outs:
        name = _string(o.name)
        if o.kind == 0:
            value[name], q = _real(o.x, o.e)
            if q is not None:
                exact[name] = q
            if o.e:
                beyond.append(name)
        else:
            value[name] = int(o.n) if o.kind == 1 else _string(o.word)
        if o.printed == 0:
            continue
        if o.printed == 2:
            printed[name] = None
        elif o.kind == 1:
            printed[name] = int(o.pn)
        else:
            printed[name], q = _real(o.px, o.pe)
            if q is not None:
                printed_exact[name] = q
            if o.pe:
                beyond.append(name + ' (printed)')
        errata[name] = _string(o.perratum)
        if o.has_rel:
            relative[name] = float(o.rel)
    if beyond:
        warnings.warn('eq %s: %s beyond the doubles (evaluated in the units '
                      'of a velocity scaling), rounded to inf, 0 or a '
                      'subnormal; exact '
                      'values in .exact, .printed_exact'
                      % (label, ', '.join(beyond)), RuntimeWarning,
                      stacklevel=2)
    e = res.entry
    return Equation(
        label=_string(e.label), title=_string(e.title),
        paper=_string(e.paper),
        note=_string(res.note) if res.note != _ffi.NULL else None,
        inputs=[_ffi.string(res.shown[i]).decode()
                for i in range(res.n_shown)],
        outputs=value,
        functions={_string(o.name): _string(o.function) for o in outs},
        methods={_string(o.name): _string(o.method) for o in outs},
        printed=printed, errata=errata, relative=relative, exact=exact,
        printed_exact=printed_exact)
