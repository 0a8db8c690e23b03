"""chaplygin -- Python access to libchaplygin, the executable edition of

    M. J. Coleman and P. Holmes, "Motions and stability of a piecewise
    holonomic system: the discrete Chaplygin sleigh", Regular and Chaotic
    Dynamics 4(2), 1999.

Every public function of the C library <chaplygin.h> is here, named after
it without the prefix and sorted by system:

    chaplygin_discrete_sigma4      chaplygin.discrete.sigma4(L0, Delta, dir)
    chaplygin_smooth_closed_form   chaplygin.smooth.closed_form(L, q0, S)
    chaplygin_massless_step        chaplygin.massless.step(L0, state)
    chaplygin_printed_discrete_f3  chaplygin.printed.discrete_f3(sys, ...)
    chaplygin_sweep_sigma4         chaplygin.sweep.sigma4(x, y, dir)
    chaplygin_strerror             chaplygin.strerror(status)

with the C parameter names as keyword arguments, outputs returned (several
as a named tuple), C structs as classes (DiscreteState, Fate, Discrete,
...), the options as keywords (method="quadrature", tol=1e-12,
precision="double"), and every nonzero status raised as a subclass of
ChaplyginError (DomainError for CHAPLYGIN_EDOM, SpinError for
CHAPLYGIN_ESPIN, ...) carrying the status and the library's message.

Every function is also vectorised: give NumPy arrays for any inputs and the
loop runs in C over their broadcast (chaplygin.vectorised says how, and
what happens to failing elements).  discrete.orbit and massless.orbit
iterate the return map along many orbits, discrete.fate / fate_phase /
basins classify final motions, sweep.sigma4 / sweep.stability are the
sweeps of Fig. 2, atlas computes a fate atlas as an xarray.Dataset (on a
Dask cluster with chunks), and run_scene runs a scene file (or a dict with the same
sections and keys) as `chaplygin run` does and returns its columns, and
eq evaluates any of the paper's numbered equations by label as `chaplygin
eq` does (labels lists them).  CertifiedOrbit follows an orbit by the
certified method, every double the nearest to the model's exact value
(chaplygin.certified; method="certified" certifies a single step).

The numbers are the C library's, bit for bit: the package only converts
arguments and results.  lib and ffi (cffi) reach the C functions directly.
"""

from . import _core
from ._core import (ChaplyginError, InvalidArgumentError, DomainError,
                    StateError, SpinError, RangeError, NoConvergenceError,
                    OutOfMemoryError, CertificationCapError, SceneError,
                    EquationError, Struct,
                    error_class,
                    ERRORS, as_columns)
from . import _generated

ffi = _core._ffi
lib = _core._lib
__version__ = _generated.VERSION

for _ctype in _generated.ENUMS:
    _core._make_enum(_ctype)
for _ctype, _cls in _core.ENUM_CLASSES.items():
    globals()[_cls.__name__] = _cls
# The C constants without their prefix: EDOM, WANT_THETA, CLOSED_FORM, ...
for _ctype in _generated.ENUMS:
    for _name, _value in ffi.typeof(_ctype).relements.items():
        globals()[_name[len('CHAPLYGIN_'):]] = _value
for _ctype in _generated.STRUCTS:
    _cls = _core._struct_class(_ctype)
    globals()[_cls.__name__] = _cls

from ._groups import export as _export
_export(globals(), '')

from . import discrete, smooth, massless, printed, sweep, scene, vectorised
from . import certified
from .certified import (CertifiedOrbit, certified_orbit_new,
                        certified_orbit_new_exact, certified_orbit_new_phase,
                        certified_orbit_new_phase_exact,
                        certified_orbit_cap, certified_orbit_step,
                        certified_orbit_state, certified_orbit_fate,
                        certified_orbit_omega, certified_orbit_sample,
                        certified_orbit_collisions, certified_orbit_free,
                        method_available)
from .scene import run_scene
from .dataset import atlas
from .equation import eq, labels
from .sweep import grid_point

del _ctype, _cls, _name, _value
