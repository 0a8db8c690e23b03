#!/usr/bin/env python3
# scipy-ivp.py -- the SciPy row of `make bench': what a user would do
# without the library.  SciPy's solve_ivp (method DOP853) integrates the
# paper's equations (3.1) over ONE segment, from the post-collision states
# of bench/work-precision-states.txt to the next collision, at a ladder of
# relative tolerances; the time per segment and the errors of the heading
# and time increments against the Arb oracle's references
# (bench/work-precision-refs.txt, the same files as bench/work-precision)
# go to OUT, which `bench/work-precision --scipy OUT' turns into rows of
# the CSV, the manual's table, the diagram and the targets.
#
#   scipy-ivp.py STATES REFS OUT [--every K] [--reps R] [--atol A]
#
# The problem, as the library states it (lib/discrete.c,
# chaplygin_discrete_field, and chaplygin_discrete_state_to_phase):
#   q = (D, V, theta, Omega), l = L0 + D,
#   dD/dt = V, dV/dt = l Omega^2, dtheta/dt = Omega,
#   dOmega/dt = -2 l V Omega / (1 + l^2);
# a state "L0 Delta dir E H" starts at D = 0 (dir +1) or D = Delta (dir -1)
# with Omega = H/(1 + l^2), V = dir sqrt(2E - H Omega), theta = 0.  (The
# library forms 1 + l^2 with one fma; here it rounds twice: a difference of
# an ulp, far below every tolerance of the ladder.)
#
# The position is integrated as d = D - D0 from the starting end D0 (as
# the library does): with D itself, SciPy's minute first step (below) from
# D0 = Delta leaves D0 + V h = D0 after rounding, and the event at that end
# fires at t = 0.  The segment ends at a slot end: two terminal events,
# d = 0 (back at the start) and d = +-Delta (the far end), each with the
# direction of a crossing from inside the slot, so that the start is not an
# event at t = 0, and a reversal needs no event of its own: the motion
# turns back inside the slot and ends where it started, crossing from
# inside.  The heading increment is theta at the event, the time increment
# its t.
#
# Tolerances: rtol 1e-3 ... 1e-13 and atol 1e-30 by default ("tiny": the
# error control relative, as the library's ODE method's).  SciPy's starting
# step for a component that starts at 0 (D for dir +1, theta) is then
# minute, and its first steps grow from it: that is SciPy's own behaviour
# on this problem, timed as it is.
#
# Timing: every K-th state (default 16: 128 of 2048), R rounds (default 3)
# over all tolerances, each round one pass over those states per
# tolerance, timed with time.perf_counter_ns; the minimum and the median
# over the rounds of the time per segment.  The outputs of the first round
# are the ones whose errors are measured.  States the oracle did not answer
# (spin, bad, fail) are left out.
#
# OUT: a comment line naming the versions and settings, then one line per
# rtol:
#   rtol ns_min ns_median max_rel_err median_rel_err max_err_over_kappa_eps
#        failures reversal_mismatches states reps mean_nfev
# where the errors are the larger of the heading's and the time's relative
# error |x - (hi + lo)|/|hi| per state, and err/(kappa eps) divides each
# by eps max(1, kappa) with the oracle's condition numbers.

import math
import platform
import statistics
import sys
import time

RTOLS = (1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-12, 1e-13)
EPS = 2.0 ** -52
T_MAX = 1e6             # far beyond any segment of the benchmark's states


def usage():
    sys.stderr.write("usage: scipy-ivp.py STATES REFS OUT [--every K] "
                     "[--reps R] [--atol A]\n")
    sys.exit(2)


def read_input(states_path, refs_path):
    """The states the oracle answered: (L0, Delta, dir, E, H, ref), ref =
    (rev, theta_hi, theta_lo, tau_hi, tau_lo, kappa_theta, kappa_tau)."""
    out = []
    with open(states_path) as fs, open(refs_path) as fr:
        for line in fs:
            if not line.strip() or line.startswith('#'):
                continue
            w = line.split()
            r = fr.readline().split()
            if len(w) != 5 or not r:
                sys.exit("scipy-ivp.py: %s and %s do not match"
                         % (states_path, refs_path))
            if r[0] != 'ok':
                continue
            L0, Delta = float.fromhex(w[0]), float.fromhex(w[1])
            E, H = float.fromhex(w[3]), float.fromhex(w[4])
            v = [float.fromhex(x) if 'x' in x else float(x) for x in r[2:]]
            # E (2), H (2), theta (2), tau (2), kappa_theta, kappa_tau
            ref = (int(r[1]), v[4], v[5], v[6], v[7], v[8], v[9])
            out.append((L0, Delta, int(w[2]), E, H, ref))
    return out


def segment(solve_ivp, L0, Delta, direction, E, H, rtol, atol):
    """One segment by solve_ivp: (reversed, dtheta, dtau, nfev), or None
    when no slot end is reached."""
    D0 = 0.0 if direction > 0 else Delta
    l0 = L0 + D0
    Om = H / (1.0 + l0 * l0)
    V = direction * math.sqrt(2.0 * E - H * Om)
    far = direction * Delta         # the far end, as d = D - D0

    def field(t, q):
        d, V, th, Om = q
        l = l0 + d
        return [V, l * Om * Om, Om, -2.0 * l * V * Om / (1.0 + l * l)]

    def at_start(t, q):             # back at the starting end, from inside
        return q[0]
    at_start.terminal = True
    at_start.direction = -direction

    def at_far(t, q):               # the far end, from inside
        return q[0] - far
    at_far.terminal = True
    at_far.direction = direction

    s = solve_ivp(field, (0.0, T_MAX), [0.0, V, 0.0, Om], method='DOP853',
                  rtol=rtol, atol=atol, events=(at_start, at_far))
    if s.status != 1:
        return None
    k = 0 if len(s.t_events[0]) else 1
    return k == 0, s.y_events[k][0][2], s.t_events[k][0], s.nfev


def rel_err(x, hi, lo):
    d = abs((x - hi) - lo)
    return d / abs(hi) if hi != 0.0 else d


def main(argv):
    if len(argv) < 4:
        usage()
    states_path, refs_path, out_path = argv[1:4]
    every, reps, atol = 16, 3, 1e-30
    i = 4
    while i < len(argv):
        if i + 1 >= len(argv):
            usage()
        if argv[i] == '--every':
            every = int(argv[i + 1])
        elif argv[i] == '--reps':
            reps = int(argv[i + 1])
        elif argv[i] == '--atol':
            atol = float(argv[i + 1])
        else:
            usage()
        i += 2
    if every < 1 or reps < 1 or not atol > 0:
        usage()
    try:
        import numpy
        import scipy
        from scipy.integrate import solve_ivp
    except ImportError as e:
        sys.exit("scipy-ivp.py: %s (Debian: apt-get install python3-scipy)"
                 % e)

    states = read_input(states_path, refs_path)[::every]
    if not states:
        sys.exit("scipy-ivp.py: no state to time")
    # warm-up: imports, caches
    for st in states[:8]:
        segment(solve_ivp, *st[:5], 1e-6, atol)

    times = {rtol: [] for rtol in RTOLS}
    first = {}
    for rep in range(reps):
        for rtol in RTOLS:
            res = []
            t0 = time.perf_counter_ns()
            for st in states:
                try:
                    res.append(segment(solve_ivp, *st[:5], rtol, atol))
                except (ValueError, ArithmeticError):
                    res.append(None)
            t1 = time.perf_counter_ns()
            times[rtol].append((t1 - t0) / len(states))
            if rep == 0:
                first[rtol] = res
        sys.stderr.write("scipy-ivp.py: round %d of %d done\n"
                         % (rep + 1, reps))

    with open(out_path, 'w') as f:
        f.write("# scipy-ivp.py: SciPy %s, NumPy %s, Python %s; "
                "solve_ivp DOP853, atol %g, terminal events at D = 0 and "
                "D = Delta; %d states (every %d-th answered), %d rounds\n"
                % (scipy.__version__, numpy.__version__,
                   platform.python_version(), atol, len(states), every,
                   reps))
        for rtol in RTOLS:
            errs, kerrs, fails, mism, nfev = [], [], 0, 0, []
            for st, r in zip(states, first[rtol]):
                ref = st[5]
                if r is None or not (math.isfinite(r[1])
                                     and math.isfinite(r[2])):
                    fails += 1
                    continue
                rev, dth, dta, nf = r
                mism += int(rev) != ref[0]
                eth = rel_err(dth, ref[1], ref[2])
                eta = rel_err(dta, ref[3], ref[4])
                errs.append(max(eth, eta))
                kerrs.append(max(eth / (EPS * max(1.0, ref[5])),
                                 eta / (EPS * max(1.0, ref[6]))))
                nfev.append(nf)
            t = times[rtol]
            f.write("%.0e %.6g %.6g %.3g %.3g %.3g %d %d %d %d %.1f\n"
                    % (rtol, min(t), statistics.median(t),
                       max(errs) if errs else float('nan'),
                       statistics.median(errs) if errs else float('nan'),
                       max(kerrs) if kerrs else float('nan'), fails, mism,
                       len(states), reps,
                       statistics.mean(nfev) if nfev else float('nan')))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
