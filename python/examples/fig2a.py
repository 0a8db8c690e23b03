"""Figure 2(a) of Coleman & Holmes (1999): the eigenvalue sigma4 (3.10) of
the period-1 fixed point with V* > 0 against L0/Delta, for several values
of (1/Delta)^2; |sigma4| < 1 is stable.

    python3 fig2a.py [OUT.png]     (Matplotlib optional)"""
import sys

import numpy as np

import chaplygin

x = np.linspace(-4, 2, 1201)                 # L0/Delta
ys = [0.01, 0.1, 0.25, 0.5, 1.0]             # (1/Delta)^2
s4 = chaplygin.sweep.sigma4(x, ys, 1)        # shape (5, 1201), loop in C
for y, row in zip(ys, s4):
    stable = np.abs(row) < 1
    edges = x[1:][np.diff(stable) != 0]      # where |sigma4| crosses 1
    print('(1/Delta)^2 = %-4g stability changes at L0/Delta ~ %s'
          % (y, ', '.join('%.3f' % e for e in edges)))
try:
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
except ImportError:
    print('(Matplotlib not installed: no plot)')
    sys.exit(0)
fig, ax = plt.subplots(figsize=(6, 4))
for y, row in zip(ys, s4):
    ax.plot(x, row, label='$(1/\\Delta)^2 = %g$' % y)
for h in (1, -1):
    ax.axhline(h, ls=':', color='black', lw=0.8)
ax.set_ylim(-3, 3)
ax.set_xlabel('$L_0/\\Delta$')
ax.set_ylabel('$\\sigma_4$')
ax.legend(loc='upper left')
fig.tight_layout()
fig.savefig(sys.argv[1] if len(sys.argv) > 1 else 'fig2a.png', dpi=120)
