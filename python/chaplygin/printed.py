"""The paper's printed forms, for audit (chaplygin_printed_*): each
evaluates a formula as the paper prints it, beside the corrected function
(chaplygin_printed_smooth_field beside chaplygin_smooth_field, ...); see the
manual's errata.  Not the dynamics.

Named without the prefix: chaplygin_printed_discrete_f3 is
chaplygin.printed.discrete_f3.  Outputs the paper gives no formula for
(dtau of smooth_closed_form and discrete_heading) are not computed unless
asked for (return_dtau=True), and then the library refuses them
(InvalidArgumentError), as the header says.
"""
from ._groups import export

__all__ = []
export(globals(), 'printed')
