#!/usr/bin/env python3
"""bench.py -- `make bench-python': what a vectorised call of the Python
package costs per element against the same loop in C, and what a scalar
call costs.

Method.  For each case, the inputs (N = 100000 by default, fixed seed) are
written to a file that python/bench/cbench (C, linked with the same
libchaplygin) reads; then, in ROUNDS alternating rounds, cbench times its
plain C loop over the library's function REPEATS times and this script
times the vectorised Python call REPEATS times on the same inputs (the
Python time includes everything the call does: argument conversion, output
allocation, the C loop with its status array).  Reported: the minimum and
the median over all repeats, in ns per element, and their ratios
Python/C (the target is <= 1.2).  The scalar calls are timed with timeit
(100000 calls per repeat) against one C call timed by cbench, in the same
run; math.hypot is the yardstick of a minimal Python call on this machine.
The machine's cores may be shared: ratios from the same run are the
numbers to compare, absolute times vary.

The cost of polling for signals (Ctrl-C, python/src/poll.h): each long
call timed with polling on and off (chaplygin._core._POLLING), and where
the binding's loop replaces one call of the library (step_eh_n in chunks,
basins point by point) that call too, in alternating repeats of the same
run; minimum and median ratios.

    PYTHONPATH=python python3 python/bench/bench.py --cbench python/bench/cbench
"""
import argparse
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time
import timeit

import numpy as np

import chaplygin
from chaplygin import discrete as d


def cases(n, rng):
    """(name, what, cbench kind, rows, extra args, python call)."""
    out = []
    L0 = rng.uniform(-3, 3, n)
    Delta = rng.uniform(0.1, 3, n)
    out.append(('sigma4', 'discrete.sigma4 (3.10)', 'sigma4',
                np.stack([L0, Delta], 1), [],
                lambda: d.sigma4(L0, Delta, dir=1)))

    m = 4 * n
    legs = np.stack([rng.uniform(-2, 2, m), np.zeros(m),
                     rng.uniform(0.5, 2, m), rng.uniform(-1, 1, m),
                     rng.uniform(0.05, 0.3, m)], 1)
    ok = d.heading(*legs.T, errors='return').status == 0
    legs = np.ascontiguousarray(legs[ok][:n])
    cols = [np.ascontiguousarray(c) for c in legs.T]
    out.append(('heading', 'discrete.heading (B.2), closed form', 'heading',
                legs, [], lambda: d.heading(*cols)))

    sys_ = d.init(1.0, 1 / 3)
    V = rng.uniform(0.3, 2, n) * rng.choice([-1.0, 1.0], n)
    q = np.stack([np.where(V > 0, 0.0, 1 / 3), V, np.zeros(n),
                  rng.uniform(-1, 1, n)], 1)
    st = d.state_from_phase(sys_, q)
    rows = np.stack([st['dir'].astype(float), st['E'], st['H']], 1)
    out.append(('step', 'discrete.step (B.3)/(B.4), request all', 'step',
                rows, ['1', repr(1 / 3)], lambda: d.step(sys_, st)))
    out.append(('ehn', 'discrete.orbit, 16 collisions, E and H only',
                'ehn', rows, ['1', repr(1 / 3)],
                lambda: d.orbit(sys_, st, 16, request=0, keep='last')))

    sys3 = d.init(-0.5, 1.0)
    Vf = rng.uniform(0.0005, 0.5, n)
    qf = np.stack([np.zeros(n), Vf, np.zeros(n), np.full(n, 0.8)], 1)
    out.append(('fate', 'discrete.fate_phase (Fig. 3 states)', 'fate',
                np.stack([Vf, np.full(n, 0.8)], 1), ['-0.5', '1'],
                lambda: d.fate_phase(sys3, qf, 100000)))
    return out


def poll_cases(rng):
    """(name, call, lib) of calls that poll, one per kind of loop; lib: the
    library's own function over the same work (no poll), or None."""
    ffi, lib = chaplygin.ffi, chaplygin.lib
    sys_ = d.init(1.0, 1 / 3)
    st = d.state_from_phase(sys_, [0, 1, 0, 0.5])
    L0 = rng.uniform(-3, 3, 10**6)
    fig3 = d.init(-0.5, 1.0)
    fates = np.zeros(100000, chaplygin.Fate.dtype)
    status = np.zeros(100000, np.intc)
    run = {'scene': {'model': 'discrete'},
           'parameters': {'L0': 1, 'Delta': '1/3'},
           'initial': {'V': 1, 'Omega': 0.5},
           'run': {'collisions': 200000, 'every': 1000, 'outputs': 'E,H'}}

    def lib_eh_n():
        s = st.copy()
        lib.chaplygin_discrete_step_eh_n(sys_._c, s._c, 10**7,
                                         ffi.new('unsigned long *'))

    def lib_basins():
        lib.chaplygin_discrete_basins(
            fig3._c, 0.8, 0.0005, 0.5, 100000, 10**6,
            ffi.cast('chaplygin_fate *', fates.ctypes.data),
            ffi.cast('int *', status.ctypes.data), ffi.NULL)
    return [
        ('discrete.sigma4, 10^6 elements (generated loop)',
         lambda: d.sigma4(L0, 1 / 3, dir=1), None),
        ('discrete.orbit, 2 10^5 collisions, request all',
         lambda: d.orbit(sys_, st, 200000, keep='last'), None),
        ('discrete.step_eh_n, 10^7 steps (chunks)',
         lambda: d.step_eh_n(sys_, st, 10**7), lib_eh_n),
        ('discrete.basins, 10^5 points (point by point)', lambda: d.basins(
            fig3, 0.8, 0.0005, 0.5, 100000, 10**6), lib_basins),
        ('run_scene, 2 10^5 collisions', lambda: chaplygin.run_scene(run),
         None),
    ]


def poll_overhead(rounds, repeats, rng):
    """Minimum and median ratios of each call's time with polling on
    against off and against the library's own function, alternating."""
    core = chaplygin._core
    print('\npolling for signals: time with polling on, off (ms), and of '
          'the library\'s\nown unpolled function; ratios on/off and '
          'on/library, min and median')
    print('%-48s %8s %8s %8s %6s %6s %6s %6s' % (
        'call', 'off min', 'on min', 'lib min', 'min', 'med', 'min', 'med'))
    for name, call, ref in poll_cases(rng):
        t = {'on': [], 'off': [], 'lib': []}
        runs = [('off', call), ('on', call)] + ([('lib', ref)] if ref
                                               else [])
        call()
        for _ in range(rounds * repeats):
            for what, fn in runs:
                core._POLLING = what == 'on'
                t0 = time.perf_counter_ns()
                fn()
                t[what].append((time.perf_counter_ns() - t0) / 1e6)
        core._POLLING = True

        def ratios(ref):
            if not t[ref]:
                return '%6s %6s' % ('-', '-')
            return '%6.3f %6.3f' % (
                min(t['on']) / min(t[ref]),
                statistics.median(t['on']) / statistics.median(t[ref]))
        print('%-48s %s %s %s %s %s' % (
            name, fmt(min(t['off'])), fmt(min(t['on'])),
            fmt(min(t['lib'])) if t['lib'] else '%8s' % '-',
            ratios('off'), ratios('lib')))


def run_c(cbench, kind, path, n, repeats, extra):
    r = subprocess.run([cbench, kind, path, str(n), str(repeats)] + extra,
                       capture_output=True, text=True, check=True)
    return [float(x) for x in r.stdout.split()]


def run_py(call, n, repeats):
    call()                      # warm up
    t = []
    for _ in range(repeats):
        t0 = time.perf_counter_ns()
        call()
        t.append((time.perf_counter_ns() - t0) / n)
    return t


def fmt(x):
    return '%8.2f' % x


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--cbench', required=True)
    ap.add_argument('--n', type=int, default=100000)
    ap.add_argument('--repeats', type=int, default=7)
    ap.add_argument('--rounds', type=int, default=3)
    ap.add_argument('--only', default=None)
    ap.add_argument('--poll-only', action='store_true',
                    help='only the cost of polling for signals')
    args = ap.parse_args()
    rng = np.random.default_rng(20260)
    print('chaplygin %s, Python %s, NumPy %s, %d elements, %d rounds x %d '
          'repeats' % (chaplygin.__version__, sys.version.split()[0],
                       np.__version__, args.n, args.rounds, args.repeats))
    poll_overhead(args.rounds, args.repeats, rng)
    if args.poll_only:
        return 0
    print('\nvectorised call vs the same loop in C (ns per element)')
    print('%-8s %-42s %8s %8s %8s %8s %6s %6s' % (
        'case', 'call', 'C min', 'C med', 'Py min', 'Py med', 'min', 'med'))
    worst = 0.0
    with tempfile.TemporaryDirectory() as tmp:
        for name, what, kind, rows, extra, call in cases(args.n, rng):
            if args.only and name not in args.only.split(','):
                continue
            path = os.path.join(tmp, name + '.bin')
            np.ascontiguousarray(rows, dtype=np.float64).tofile(path)
            n = len(rows)
            reps = args.repeats if name != 'fate' else max(3, args.repeats // 2)
            tc, tp = [], []
            for _ in range(args.rounds):
                tc += run_c(args.cbench, kind, path, n, reps, extra)
                tp += run_py(call, n, reps)
            cmin, cmed = min(tc), statistics.median(tc)
            pmin, pmed = min(tp), statistics.median(tp)
            worst = max(worst, pmin / cmin)
            print('%-8s %-42s %s %s %s %s %6.3f %6.3f' % (
                name, what, fmt(cmin), fmt(cmed), fmt(pmin), fmt(pmed),
                pmin / cmin, pmed / cmed))
        # scalar calls
        print('\nscalar call (ns per call; timeit, 100000 calls per repeat)')
        sys_ = d.init(1.0, 1 / 3)
        st = d.state_from_phase(sys_, [0, 1, 0, 0.5])
        lib, ffi = chaplygin.lib, chaplygin.ffi
        p = ffi.new('double *')
        stmts = [
            ('math.hypot(1.0, 1/3)  [a minimal Python call]',
             lambda: math.hypot(1.0, 1 / 3)),
            ('lib.chaplygin_discrete_sigma4 [raw cffi]',
             lambda: lib.chaplygin_discrete_sigma4(1.0, 1 / 3, 1, p,
                                                   ffi.NULL)),
            ('discrete.sigma4(1.0, 1/3, dir=1)',
             lambda: d.sigma4(1.0, 1 / 3, dir=1)),
            ('discrete.heading(1, 0, 1, 0.5, 1/3)',
             lambda: d.heading(1.0, 0.0, 1.0, 0.5, 1 / 3)),
            ('discrete.step(sys, state)', lambda: d.step(sys_, st)),
        ]
        tc = []
        res = {s: [] for s, _ in stmts}
        for _ in range(args.rounds):
            tc += run_c(args.cbench, 'scalar', os.devnull, 1000000,
                        args.repeats, [])
            for s, f in stmts:
                res[s] += [t / 100000 * 1e9 for t in
                           timeit.repeat(f, number=100000,
                                         repeat=args.repeats)]
        cmin, cmed = min(tc), statistics.median(tc)
        print('%-48s %8s %8s' % ('call', 'min', 'median'))
        print('%-48s %s %s' % ('C: chaplygin_discrete_sigma4', fmt(cmin),
                               fmt(cmed)))
        hyp = min(res[stmts[0][0]])
        for s, _ in stmts:
            t = res[s]
            print('%-48s %s %s   (%.1f x math.hypot)' % (
                s, fmt(min(t)), fmt(statistics.median(t)), min(t) / hyp))
        s4 = res[stmts[2][0]]
        print('\noverhead of a scalar call of discrete.sigma4 over C: '
              'min %.0f ns, median %.0f ns'
              % (min(s4) - cmin, statistics.median(s4) - cmed))
    print('\nworst vectorised ratio (min/min): %.3f (target <= 1.2)' % worst)
    return 0


if __name__ == '__main__':
    sys.exit(main())
