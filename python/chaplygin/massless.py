"""The massless skate, rho = 0: Appendix B.3 (chaplygin_massless_*).

Generated wrappers of every chaplygin_massless_* function, and by hand
orbit(L0, state, n): the return map (B.15) along n collisions from one or
many post-collision states, the loop in C (as chaplygin.discrete.orbit).
"""
from ._core import _ffi, _lib, _NULL, _ptr, _real
from ._groups import export
from . import discrete as _discrete

__all__ = []
export(globals(), 'massless')
__all__ += ['orbit']


def orbit(L0, state, n, *, request='all', keep='all', events=False,
          errors='raise'):
    """massless.orbit(L0, state, n, *, request='all', keep='all',
    events=False, errors='raise')

    The return map (B.15) of the massless skate with mass position L0 along
    n collisions from the post-collision state(s) STATE, one
    chaplygin_massless_step per collision; shapes, keep, events and errors
    as chaplygin.discrete.orbit.
    """
    L0 = _real('L0', L0)

    def call(m, init, stride, n, request, keep_all, out, ev, status, done,
             poll):
        return _lib.chp_py_massless_orbit(
            L0, m, init, stride, n, request, keep_all,
            _ffi.cast('chaplygin_discrete_state *', _ptr(out)),
            _NULL if ev is None else
            _ffi.cast('chaplygin_discrete_event *', _ptr(ev)),
            _ffi.cast('int *', _ptr(status)),
            _ffi.cast('unsigned long *', _ptr(done)), poll)
    return _discrete._orbit('chaplygin_massless_step', call, state, n,
                            request, keep, events, errors)
