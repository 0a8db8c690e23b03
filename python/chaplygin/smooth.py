"""The smooth Chaplygin sleigh: Section 2 and Appendix A (chaplygin_smooth_*).

Generated wrappers of every chaplygin_smooth_* function; q = [S, V, theta,
Omega] (phase form), p = [S, E, theta, H_C] (energy-momentum form).
help(chaplygin.smooth.closed_form) shows the header's comment.
"""
from ._groups import export
from ._core import _struct_class

__all__ = []
export(globals(), 'smooth')

SmoothDim = _struct_class('chaplygin_smooth_dim')
SmoothNondim = _struct_class('chaplygin_smooth_nondim')
__all__ += ['SmoothDim', 'SmoothNondim']
