"""Figure 3 of Coleman & Holmes (1999): the basins of attraction of the
straight-line motions for L0/Delta = -1/2 (L0 = -1/2, Delta = 1), from
post-collision states with H = 1 (Omega+ = 4/5) and initial V+ from 0.0005
to 0.5.  Every motion ends in forward (V* > 0) or backward (V* < 0)
straight-line motion; above V+ = 1/sqrt(5) all end forward.

    python3 fig3.py [OUT.png]

prints the fates' summary and the boundaries, and draws OUT.png with
Matplotlib when it is installed (it is optional)."""
import sys

import numpy as np

import chaplygin
from chaplygin import discrete

sys_ = discrete.init(-0.5, 1.0)              # L0 = -1/2, Delta = 1
V = np.linspace(0.0005, 0.5, 4000)           # initial V+ (peg at D = 0)
qplus = np.stack([np.zeros_like(V), V, np.zeros_like(V),
                  np.full_like(V, 0.8)], axis=-1)    # [D+, V+, theta+, Omega+]
fates = discrete.fate_phase(sys_, qplus, 1000000)    # one C loop, 4000 fates

kind = fates['kind']
print('forward:', np.count_nonzero(kind == chaplygin.FateKind.FORWARD),
      'backward:', np.count_nonzero(kind == chaplygin.FateKind.BACKWARD),
      'spin:', np.count_nonzero(kind == chaplygin.FateKind.SPIN))
bounds = discrete.basin_boundaries(sys_, 0.8, V[0], V[-1], len(V), 1000000)
print('fate changes at V+ =', ' '.join('%.6f' % b for b in bounds[:8]),
      '...' if len(bounds) > 8 else '')

try:
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
except ImportError:
    print('(Matplotlib not installed: no plot)')
    sys.exit(0)
fig, ax = plt.subplots(figsize=(7, 3))
ax.plot(V, kind, '.', ms=2, color='#1f3b73')
for b in bounds:                             # where the fate changes
    ax.axvline(b, ls=':', color='#888888', lw=0.6)
ax.axvline(1 / np.sqrt(5), ls='--', color='black', lw=0.8)
ax.set_yticks([-1, 0, 1], ['V* < 0', 'spin', 'V* > 0'])
ax.set_ylim(-1.5, 1.5)
ax.set_xlabel('initial $V^+$')
ax.set_title('Fig. 3: basins of attraction, $L_0 = -1/2$, $\\Delta = 1$')
fig.tight_layout()
fig.savefig(sys.argv[1] if len(sys.argv) > 1 else 'fig3.png', dpi=120)
