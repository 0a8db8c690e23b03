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
# (--atol A: a fixed atol instead of 1e-3 rtol.)
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
# event at t = 0.  What reversals need: a third terminal event, V = 0.
# solve_ivp finds an event where its function changes sign between the
# ends of a step, so a step that leaves through the far end, turns (at a
# turning point just beyond it) and comes back inside shows no crossing of
# the far end, and the motion would return to the start: a wrong branch
# (1 of the 128 states at rtol 1e-3, another at 1e-5 and 1e-7, atol
# 1e-30, with the two end events alone).  The turn is seen (V changes sign
# in that step); if it lies inside the slot, the integration goes on from
# it to an end; if beyond the far end, the crossing is located by brentq
# on the dense output of the same steps (solve_ivp again, up to the turn).
# The heading increment is theta at the event, the time increment its t.
#
# Tolerances: rtol 1e-3 ... 1e-13 and, by default, atol = 1e-3 rtol: tiny
# next to the components (of order 1 at these states), so that the error
# control is relative, as the library's ODE method's.  A fixed atol far
# below that (--atol 1e-30) makes SciPy's first step minute, since d and
# theta start at 0 (its starting-step rule divides by atol there), and
# its first steps grow from it: at rtol 1e-12 three times the time for
# about the same error (measured on these states: 6.05 ms against 1.98 ms
# a segment, 4.8e-12 against 5.6e-12).
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

brentq = None           # scipy.optimize.brentq, once imported
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

    def turn(t, q):                 # a turning point, V = 0
        return q[1]
    turn.terminal = True

    def ivp(t0, y0, t1, events, dense=False):
        return solve_ivp(field, (t0, t1), y0, method='DOP853', rtol=rtol,
                         atol=atol, events=events, dense_output=dense)

    y0 = [0.0, V, 0.0, Om]
    s = ivp(0.0, y0, T_MAX, (at_start, at_far, turn))
    if s.status != 1:
        return None
    nfev = s.nfev
    if len(s.t_events[0]) or len(s.t_events[1]):
        k = 0 if len(s.t_events[0]) else 1
        return k == 0, s.y_events[k][0][2], s.t_events[k][0], nfev
    tt, yt = s.t_events[2][0], s.y_events[2][0]
    if direction * (yt[0] - far) < 0.0:
        # a reversal inside the slot: on from the turning point
        s = ivp(tt, yt, T_MAX, (at_start, at_far))
        if s.status != 1:
            return None
        k = 0 if len(s.t_events[0]) else 1
        return k == 0, s.y_events[k][0][2], s.t_events[k][0], nfev + s.nfev
    # the turning point lies beyond the far end: the step out and back
    # crossed the far end twice, and the events, which compare the ends of
    # a step, saw neither crossing.  The crossing, located on the dense
    # output of the same steps up to the turn.
    s = ivp(0.0, y0, tt, (), dense=True)
    i = max(j for j in range(len(s.t)) if direction * (s.y[0][j] - far) < 0)
    tc = brentq(lambda t: s.sol(t)[0] - far, s.t[i], tt, xtol=1e-300,
                rtol=4 * EPS)
    return False, s.sol(tc)[2], tc, nfev + s.nfev


def rel_err(x, hi, lo):
    d = abs((x - hi) - lo)
    return d / abs(hi) if hi != 0.0 else d


def main(argv):
    if len(argv) < 4:
        usage()
    states_path, refs_path, out_path = argv[1:4]
    every, reps, atol = 16, 3, None
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
    if every < 1 or reps < 1 or not (atol is None or atol > 0):
        usage()
    try:
        import numpy
        import scipy
        from scipy.integrate import solve_ivp
        global brentq
        from scipy.optimize import brentq
    except ImportError as e:
        sys.exit("scipy-ivp.py: %s (Debian: apt-get install python3-scipy)"
                 % e)

    states = read_input(states_path, refs_path)[::every]
    if not states:
        sys.exit("scipy-ivp.py: no state to time")
    # warm-up: imports, caches
    for st in states[:8]:
        segment(solve_ivp, *st[:5], 1e-6, atol or 1e-9)

    times = {rtol: [] for rtol in RTOLS}
    first = {}
    for rep in range(reps):
        for rtol in RTOLS:
            res = []
            t0 = time.perf_counter_ns()
            for st in states:
                try:
                    res.append(segment(solve_ivp, *st[:5], rtol,
                                       atol or 1e-3 * rtol))
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
                "solve_ivp DOP853, atol %s, terminal events at D = 0 and "
                "D = Delta and V = 0; %d states (every %d-th answered), %d rounds\n"
                % (scipy.__version__, numpy.__version__,
                   platform.python_version(),
                   "1e-3 rtol" if atol is None else "%g" % atol,
                   len(states), every,
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
