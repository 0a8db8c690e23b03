#!/usr/bin/env python3
"""Reference values for the tests of `chaplygin eq`, by routes independent of lib/.

Run from the top of the tree:  python3 tests/ref/make_eq_refs.py
Needs mpmath (Debian: python3-mpmath).  Writes tests/ref/eq.tsv, one row per
(evaluation, output) checked:

    label  args  output  which  reference  tol_eps  route

`args` are the arguments of `chaplygin eq LABEL ...` as NAME=VALUE; every
value is a short decimal or p/q whose correctly rounded double is what the
program sees, and every reference is computed for exactly that double
(mpf(float(...)), exact).  `which` is `value` (the library's corrected
output) or `printed` (the paper's printed form, evaluated here from the
form doc/errata.texi quotes, never from lib/).  The test passes iff
|x - reference| <= tol_eps 2^-52 |reference| (0: exact equality).

Independence (as tests/ref/make_refs.py): nothing here transcribes lib/.
The references come from the mechanics or from a different formula, at 50
significant digits (60 for the B.13 bisection):
  fields      Newton-Euler of the rigid body in Cartesian coordinates (the
              acceleration of G, the constraint force and its moment solved
              as a linear system), not the printed right-hand sides;
  invariants  kinetic energy and angular momentum of the body in the plane;
  collisions  the impulse at the new peg in Cartesian coordinates (a 4x4
              linear system: momentum, moment of momentum, the new pin
              constraint), exact in rationals (Fraction) where the state is
              rational, else at 50 digits;
  smooth      mpmath odefun (Taylor series) on (2.1) with the signed
              displacement, reversal and arc lengths located by findroot;
  legs        mpmath odefun on (3.1) to the requested D (B.1, B.2), checked
              against the quadrature of make_refs.py;
  segments    the quadrature of make_refs.py (segment_ref) for heading and
              time, the turning point by root-finding on V^2, then the
              Cartesian collision;
  series      direct iteration of that map at 50 digits ((B.6), (B.9),
              (B.10), (B.12)); (B.13) by bisection on the initial state of
              the iterated map;
  massless    the straight-line motion of the point mass and its angular
              momentum about the pegs (elementary plane geometry);
  units       exact rational arithmetic.
Printed forms are evaluated at 50 digits from the formulas of doc/errata.texi
("Paper" part), with the printed K of (A.3) and the printed S_c of (A.1).

Tolerances: for algebraic formulas the number of roundings r of a plain
evaluation (first-order bound r/2 eps, doubled), at points chosen without
cancellation; for the elliptic closed forms max(16, 8 kappa) with kappa the
condition number with respect to all the inputs the library sees, computed
here by central differences of the reference route; quadrature at tol 1e-14
(1e-13 (1 + kappa) relative, as tests/test_flow.c), ODE at tol 1e-13
(1e-10 (1 + kappa)); derived inputs (V, Omega for E, H) add the condition
number of the conversion.  Deterministic: fixed points, no randomness.
"""
import math
import os
import sys
from fractions import Fraction

from mpmath import (mp, mpf, sqrt, log, exp, asin, atan2, cos, sin, quad,
                    findroot, odefun, sign, diff, taylor, floor, matrix, eig)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_refs  # noqa: E402  (this project's own reference routes)

OUT = "tests/ref/eq.tsv"
# The paper's labels in its order: the registry's records "@ LABEL".
REGISTRY = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "lib", "labels.txt")
DPS = 50
EPS = mpf(2) ** -52
ROWS = []


# ------------------------------------------------------------------ rows
class Args:
    """eq arguments: NAME=VALUE strings and the exact doubles they denote."""

    def __init__(self, *pairs):
        self.items = []
        self.v = {}
        for name, text in pairs:
            text = str(text)
            if "/" in text:
                p, q = text.split("/")
                d = float(Fraction(int(p), int(q)))   # correctly rounded
            else:
                d = float(text)
            self.items.append((name, text))
            self.v[name] = d

    def __getitem__(self, k):
        return mpf(self.v[k])

    def f(self, k):
        return Fraction(self.v[k])      # the exact double as a rational

    def get(self, k, default):
        return mpf(self.v[k]) if k in self.v else mpf(default)

    def i(self, k):
        return int(self.v[k])

    def text(self):
        return " ".join("%s=%s" % nt for nt in self.items)


def fmt(ref):
    if isinstance(ref, (int, bool)) and not isinstance(ref, float):
        return str(int(ref))
    if isinstance(ref, Fraction):
        return "%.17g" % float(ref)     # float(Fraction) is correctly rounded
    return "%.17g" % float(ref)


def row(label, a, output, ref, tol, route, which="value"):
    if not isinstance(ref, (int, bool)):
        assert ref != 0 or tol == 0, (label, output, "zero reference needs tol 0")
    tol = int(math.ceil(float(tol))) if tol else 0
    ROWS.append((label, a.text(), output, which, fmt(ref), str(tol), route))


def tol_kappa(kappa, floor_eps=16, mult=8):
    return max(floor_eps, mult * kappa)


def kappas(fn, xs, rel=mpf("1e-10")):
    """Condition numbers sum_i |x_i df/dx_i|/|f| of each component of the
    vector function fn at xs, by central differences at 30 digits (two
    significant digits of kappa are all a tolerance needs)."""
    with mp.workdps(30):
        return _kappas(fn, xs, mpf(rel))


def _kappas(fn, xs, rel):
    f0 = fn(xs)
    acc = [mpf(0)] * len(f0)
    for i, x in enumerate(xs):
        if x == 0:
            continue
        h = abs(x) * rel
        xp = list(xs)
        xm = list(xs)
        xp[i] = x + h
        xm[i] = x - h
        fp, fm = fn(xp), fn(xm)
        for k in range(len(f0)):
            acc[k] += abs(x * (fp[k] - fm[k]) / (2 * h))
    return [acc[k] / abs(f0[k]) if f0[k] != 0 else mpf(0) for k in range(len(f0))]


# ----------------------------------------------------- linear algebra
def solve(A, b):
    """Gaussian elimination with pivoting; works for Fraction and mpf."""
    n = len(b)
    M = [list(A[i]) + [b[i]] for i in range(n)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(M[r][c]))
        M[c], M[p] = M[p], M[c]
        for r in range(n):
            if r != c and M[r][c] != 0:
                f = M[r][c] / M[c][c]
                M[r] = [M[r][k] - f * M[c][k] for k in range(n + 1)]
    return [M[i][n] / M[i][i] for i in range(n)]


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def axes(theta, like=Fraction(0)):
    """Slot (skate) axis e and its normal n; theta = 0 exactly gives exact
    axes in the number type of `like` (Fraction: exact rationals)."""
    if theta == 0:
        zero = like * 0
        one = zero + 1
        return (one, zero), (zero, one)
    c, s = cos(theta), sin(theta)
    return (c, s), (-s, c)


# --------------------------------------- rigid body (rho = 1, m = 1, I = 1)
def body(L0, D, V, Om, theta):
    """Peg P at the origin; G = P + l e; v_G = V e + l Omega n (the body
    slides along the slot through the fixed peg)."""
    e, n = axes(theta, V + Om)
    l = L0 + D
    G = (l * e[0], l * e[1])
    vG = (V * e[0] + l * Om * n[0], V * e[1] + l * Om * n[1])
    return G, vG, e, n


def kinetic(vG, Om):
    return (dot(vG, vG) + Om * Om) / 2


def ang_mom(Q, G, vG, Om):
    """Angular momentum about the point Q: I Omega + (G - Q) x m v_G."""
    return Om + cross((G[0] - Q[0], G[1] - Q[1]), vG)


def collide_cart(L0, Delta, Dm, V, Om, theta=0):
    """The collision at the new peg, from the impulse: the peg leaves the
    slot end Dm, the new peg enters the body at slot coordinate Delta - Dm.
    Unknowns dv_x, dv_y, dOmega, J (impulse J n at the new peg):
      m dv = J n,  I dOmega = (P' - G) x J n,
      (v_G + dv + (Omega + dOmega) k x (P' - G)) . n = 0  (the new pin).
    Returns D+, V+, Omega+, E+, H+ (H+ about the new peg)."""
    G, vG, e, n = body(L0, Dm, V, Om, theta)
    Dp = Delta - Dm
    lp = L0 + Dp
    Pn = (G[0] - lp * e[0], G[1] - lp * e[1])
    r = (Pn[0] - G[0], Pn[1] - G[1])
    rn = cross(r, n)
    z = 0 * V
    one = z + 1
    # rows: dv_x - J n_x = 0; dv_y - J n_y = 0; dOm - J rn = 0;
    #       (dv + dOm k x r) . n = -(v_G + Om k x r) . n,  k x r = (-r_y, r_x)
    A = [[one, z, z, -n[0]],
         [z, one, z, -n[1]],
         [z, z, one, -rn],
         [n[0], n[1], -r[1] * n[0] + r[0] * n[1], z]]
    b = [z, z, z, -(vG[0] * n[0] + vG[1] * n[1] + Om * (-r[1] * n[0] + r[0] * n[1]))]
    dvx, dvy, dOm, J = solve(A, b)
    vG1 = (vG[0] + dvx, vG[1] + dvy)
    Om1 = Om + dOm
    V1 = dot(vG1, e)
    return Dp, V1, Om1, kinetic(vG1, Om1), ang_mom(Pn, G, vG1, Om1)


def state_at(L0, D, E, H, s):
    """Phase state at slot coordinate D from E and H about the peg (the
    conservation laws), V with sign s."""
    l = L0 + D
    Om = H / (1 + l * l)
    V2 = 2 * E - H * Om
    return s * sqrt(V2), Om


def eh_of(L0, D, V, Om):
    G, vG, e, n = body(L0, D, V, Om, 0)
    return kinetic(vG, Om), ang_mom((0, 0), G, vG, Om)


def coefficients_cart(L0, Delta, dir, reversal):
    """C1, C2 of a segment from the Cartesian collision, exact rationals:
    state at the end the peg leaves with V = 1, Omega = 1/3 (any state)."""
    Dplus = Fraction(0) if dir > 0 else Delta
    Dm = (Delta - Dplus) if not reversal else Dplus
    V, Om = Fraction(1), Fraction(1, 3)
    E, H = eh_of(L0, Dm, V, Om)
    _, _, _, E1, H1 = collide_cart(L0, Delta, Dm, V, Om)
    return (E1 - E) / (H * H), H1 / H


# ------------------------------------------------------ segment map
def path_min_absl(L0, Delta):
    lo, hi = L0, L0 + Delta
    if lo <= 0 <= hi:
        return 0 * L0
    return min(abs(lo), abs(hi))


def seg_reverses(L0, Delta, d, E, H):
    """V^2 = 2E - H^2/(1 + l^2) vanishes on the path from the start end
    (moving with direction d) to the far end: the largest 1/(1 + l^2) on the
    path is at the smallest |l| passed (a scan of V^2 over the path agrees;
    ties are avoided by the choice of points)."""
    if H == 0:
        return False
    m = path_min_absl(L0, Delta)
    return 2 * E * (1 + m * m) <= H * H


def seg_step(L0, Delta, d, E, H):
    """One segment of the return map in (dir, E, H): reversal by V^2 on
    the path, collision by the Cartesian impulse.  Returns rev, d', E', H'."""
    rev = seg_reverses(L0, Delta, d, E, H)
    Dstart = 0 * L0 if d > 0 else Delta
    Dfar = Delta - Dstart
    Dm = Dstart if rev else Dfar
    s = -d if rev else d
    V, Om = state_at(L0, Dm, E, H, s)
    _, V1, Om1, E1, H1 = collide_cart(L0, Delta, Dm, V, Om)
    return rev, (1 if V1 > 0 else -1), E1, H1


# ------------------------------------------------- ODE on (3.1), legs
def leg_ode(L0, D0, V0, Om0, D):
    """odefun on (3.1) from (D0, V0, Omega0) until the peg reaches D (no
    turning point on the way).  Returns V^2, Omega, dtheta, dtau."""
    f = odefun(lambda t, y: [y[1], (L0 + y[0]) * y[3] ** 2, y[3],
                             -2 * (L0 + y[0]) * y[1] * y[3] / (1 + (L0 + y[0]) ** 2)],
               0, [D0, V0, mpf(0), Om0])
    s = sign(D - D0)
    t, step = mpf(0), mpf(1) / 8
    while (f(t + step)[0] - D) * s < 0:
        t += step
    tc = findroot(lambda u: f(u)[0] - D, (t, t + step), solver="anderson")
    y = f(tc)
    return y[1] ** 2, y[3], y[2], tc


# ---------------------------------------------- smooth sleigh, (2.1)
def smooth_ode(L, V0, Om0, sigmas):
    """odefun on (2.1) with the signed displacement x (dx/dtau = V), arc
    length |x| before the reversal, |x_c| + |x_c - x| after.  Returns for
    each arc length sigma beyond the start (V, Omega, dtheta, dtau), and the
    reversal arc length sigma_c or None."""
    f = odefun(lambda t, y: [y[1], L * y[3] ** 2, y[3], -L / (1 + L * L) * y[1] * y[3]],
               0, [mpf(0), V0, mpf(0), Om0])
    s0 = sign(V0)
    tc = xc = None
    if L * V0 < 0 and Om0 != 0:
        t = mpf(0)
        while f(t + mpf(1) / 8)[1] * s0 > 0:
            t += mpf(1) / 8
        tc = findroot(lambda u: f(u)[1], (t, t + mpf(1) / 8), solver="anderson")
        xc = f(tc)[0]

    def arclen(t):
        x = f(t)[0]
        if tc is not None and t > tc:
            return abs(xc) + abs(xc - x)
        return abs(x)

    out = []
    for sg in sigmas:
        t, step = mpf(0), mpf(1) / 8
        while arclen(t + step) < sg:
            t += step
        tt = findroot(lambda u: arclen(u) - sg, (t, t + step), solver="anderson")
        y = f(tt)
        out.append((y[1], y[3], y[2], tt))
    return out, (abs(xc) if xc is not None else None)


# ----------------------------------------------- massless skate geometry
def massless_step(L0, d, E, H, theta=0):
    """rho = 0: the point mass G moves on a straight line at constant
    velocity (no force can act on it); the slot always passes through the
    peg P (origin) and G, so l = s |G|, s = sgn l constant while H != 0.
    The segment ends where D = s|G| - L0 first reaches 0 or 1 after the
    start; the new peg is the slot point Delta - D- (Delta = 1); H' is the
    angular momentum of the point mass about it.  Returns
    rev, dir', E', H', dtheta, dtau."""
    Dstart = mpf(0) if d > 0 else mpf(1)
    l0 = L0 + Dstart
    e0 = (cos(theta), sin(theta))
    n0 = (-e0[1], e0[0])
    G0 = (l0 * e0[0], l0 * e0[1])
    w = H / l0                            # l Omega, from H = l^2 Omega
    V0 = d * sqrt(2 * E - w * w)
    v = (V0 * e0[0] + w * n0[0], V0 * e0[1] + w * n0[1])
    s = sign(l0)
    vv = dot(v, v)
    cands = []
    for Dend in (mpf(0), mpf(1)):
        c = L0 + Dend
        if c != 0 and sign(c) != s:
            continue
        # |G0 + v t|^2 = c^2
        A, B, C = vv, 2 * dot(G0, v), dot(G0, G0) - c * c
        disc = B * B - 4 * A * C
        if disc < 0:
            continue
        for t in ((-B - sqrt(disc)) / (2 * A), (-B + sqrt(disc)) / (2 * A)):
            if t > mpf(10) ** (-DPS + 10):
                cands.append((t, Dend))
    t, Dm = min(cands)
    rev = 1 if Dm == Dstart else 0
    G = (G0[0] + v[0] * t, G0[1] + v[1] * t)
    rG = sqrt(dot(G, G))
    e1 = (s * G[0] / rG, s * G[1] / rG)
    lp = L0 + (1 - Dm)
    Pn = (G[0] - lp * e1[0], G[1] - lp * e1[1])
    H1 = cross((G[0] - Pn[0], G[1] - Pn[1]), v)
    E1 = vv / 2
    V1 = dot(v, e1)
    dth = atan2(cross(e0, e1), dot(e0, e1))
    return rev, (1 if V1 > 0 else -1), E1, H1, dth, t


def massless_period2(L0):
    """Period-2 motions: every state returns after two collisions (H, E and
    direction), tested on three states."""
    for (d, E, H) in ((1, mpf("0.8"), mpf("0.07")), (-1, mpf("0.6"), mpf("-0.05")),
                      (1, mpf("1.3"), mpf("-0.11"))):
        s1 = massless_step(L0, d, E, H)
        s2 = massless_step(L0, s1[1], s1[2], s1[3])
        if not (s2[1] == d and abs(s2[3] - H) < mpf(10) ** -40 * abs(H)):
            return 0
    return 1


# ============================================================ labels
# ---- (2.1), (3.1): fields by Newton-Euler
def newton_euler(l, V, Om, theta, discrete):
    """Solve m a_G = F n, I dOmega = (P - G) x F n for (dV, dOmega, F), with
    a_G = dV e + l dOmega n + kinematic terms: the contact (or peg) point
    P = G - l e; for the smooth sleigh v_C = V e, for the discrete skate
    v_G = V e + l Omega n with dl/dtau = V."""
    e, n = axes(theta, V + Om)
    # velocity-dependent part of a_G
    if discrete:     # d/dt (V e + l Om n) = dV e + V Om n + V Om n + l dOm n - l Om^2 e
        k = (2 * V * Om * n[0] - l * Om * Om * e[0], 2 * V * Om * n[1] - l * Om * Om * e[1])
    else:            # d/dt (V e + l Om n), l constant
        k = (V * Om * n[0] - l * Om * Om * e[0], V * Om * n[1] - l * Om * Om * e[1])
    r = (-l * e[0], -l * e[1])          # P - G
    z = 0 * V
    # unknowns dV, dOm, F:  dV e + dOm l n - F n = -k ;  dOm - F (r x n) = 0
    A = [[e[0], l * n[0], -n[0]],
         [e[1], l * n[1], -n[1]],
         [z, z + 1, -cross(r, n)]]
    b = [-k[0], -k[1], z]
    dV, dOm, F = solve(A, b)
    return dV, dOm


def do_2_1():
    route = "Newton-Euler of the rigid body in the plane (linear solve, 50 digits); dS/dtau = |V| (arc length)"
    for (L, V, Om, S, th, printed_agrees) in (("0.7321", "-1.4137", "0.5813", "0.2741", "0.3719", False),
                                              ("-1.2917", "0.8629", "-0.6183", "0", "-1.0923", True)):
        a = Args(("L", L), ("V", V), ("Omega", Om), ("S", S), ("theta", th))
        dV, dOm = newton_euler(a["L"], a["V"], a["Omega"], a["theta"], False)
        row("2.1", a, "dS/dtau", abs(a["V"]), 0, route)
        row("2.1", a, "dV/dtau", dV, 2, route)
        row("2.1", a, "dtheta/dtau", a["Omega"], 0, route)
        row("2.1", a, "dOmega/dtau", dOm, 6, route)
        # E1: printed dS/dtau = V; differs for V < 0
        assert (a["V"] == abs(a["V"])) == printed_agrees
        row("2.1", a, "dS/dtau", a["V"], 0, "printed form of E1 (dS/dtau = V)", "printed")


def do_3_1():
    route = "Newton-Euler of the rigid body with the pin in the slot (linear solve, 50 digits)"
    for (L0, D, V, Om, th) in (("0.7321", "0.2741", "-0.8629", "0.5813", "0.3719"),
                               ("-2.1173", "0.4137", "1.0923", "-0.6183", "2.4137")):
        a = Args(("L0", L0), ("D", D), ("V", V), ("Omega", Om), ("theta", th))
        l = a["L0"] + a["D"]
        dV, dOm = newton_euler(l, a["V"], a["Omega"], a["theta"], True)
        row("3.1", a, "dD/dtau", a["V"], 0, route)
        row("3.1", a, "dV/dtau", dV, 3, route)
        row("3.1", a, "dtheta/dtau", a["Omega"], 0, route)
        row("3.1", a, "dOmega/dtau", dOm, 7, route)


# ---- units
def do_units():
    route = "exact rational arithmetic"
    # (2.2) nondimensionalize
    a = Args(("rho", "0.6183"), ("v0", "1.7331"), ("ell", "0.9157"), ("s", "2.1173"),
             ("v", "-0.5417"), ("theta", "0.3719"), ("omega", "1.0923"), ("t", "3.1427"))
    rho, v0 = a.f("rho"), a.f("v0")
    row("2.2", a, "L", a.f("ell") / rho, 1, route)
    row("2.2", a, "S", a.f("s") / rho, 1, route)
    row("2.2", a, "V", a.f("v") / v0, 1, route)
    row("2.2", a, "theta", a.f("theta"), 0, route)
    row("2.2", a, "Omega", a.f("omega") * rho / v0, 2, route)
    row("2.2", a, "tau", a.f("t") * v0 / rho, 2, route)
    a = Args(("rho", "0.6183"), ("v0", "1.7331"), ("L", "-1.4137"), ("S", "0.2741"),
             ("V", "0.8629"), ("theta", "-0.4137"), ("Omega", "0.5813"), ("tau", "1.2917"))
    rho, v0 = a.f("rho"), a.f("v0")
    row("2.2", a, "ell", a.f("L") * rho, 1, route)
    row("2.2", a, "s", a.f("S") * rho, 1, route)
    row("2.2", a, "v", a.f("V") * v0, 1, route)
    row("2.2", a, "theta", a.f("theta"), 0, route)
    row("2.2", a, "omega", a.f("Omega") * v0 / rho, 2, route)
    row("2.2", a, "t", a.f("tau") * rho / v0, 2, route)
    # (2.3)
    a = Args(("m", "1.7331"), ("I", "0.5813"))
    row("2.3", a, "rho", sqrt(a["I"] / a["m"]), 1, "exact: I = m rho^2 solved at 50 digits")
    # (3.2)
    a = Args(("rho", "0.6183"), ("v0", "1.7331"), ("ell0", "-0.9157"), ("delta", "0.4137"),
             ("d", "0.2741"), ("v", "0.8629"), ("theta", "0.3719"), ("omega", "-1.0923"),
             ("t", "3.1427"))
    rho, v0 = a.f("rho"), a.f("v0")
    row("3.2", a, "L0", a.f("ell0") / rho, 1, route)
    row("3.2", a, "Delta", a.f("delta") / rho, 1, route)
    row("3.2", a, "D", a.f("d") / rho, 1, route)
    row("3.2", a, "V", a.f("v") / v0, 1, route)
    row("3.2", a, "theta", a.f("theta"), 0, route)
    row("3.2", a, "Omega", a.f("omega") * rho / v0, 2, route)
    row("3.2", a, "tau", a.f("t") * v0 / rho, 2, route)
    a = Args(("rho", "0.6183"), ("v0", "1.7331"), ("L0", "-1.4137"), ("Delta", "0.7321"),
             ("D", "0.5417"), ("V", "-0.8629"), ("theta", "0.2913"), ("Omega", "0.5813"),
             ("tau", "1.2917"))
    rho, v0 = a.f("rho"), a.f("v0")
    row("3.2", a, "ell0", a.f("L0") * rho, 1, route)
    row("3.2", a, "delta", a.f("Delta") * rho, 1, route)
    row("3.2", a, "d", a.f("D") * rho, 1, route)
    row("3.2", a, "v", a.f("V") * v0, 1, route)
    row("3.2", a, "theta", a.f("theta"), 0, route)
    row("3.2", a, "omega", a.f("Omega") * v0 / rho, 2, route)
    row("3.2", a, "t", a.f("tau") * rho / v0, 2, route)
    # (B.17): lengths in units of the slot length delta
    a = Args(("delta", "0.6183"), ("v0", "1.7331"), ("ell0", "-0.9157"), ("d", "0.2741"),
             ("v", "0.8629"), ("theta", "0.3719"), ("omega", "1.0923"), ("t", "3.1427"))
    dl, v0 = a.f("delta"), a.f("v0")
    row("B.17", a, "L0", a.f("ell0") / dl, 1, route)
    row("B.17", a, "Delta", Fraction(1), 0, route)
    row("B.17", a, "D", a.f("d") / dl, 1, route)
    row("B.17", a, "V", a.f("v") / v0, 1, route)
    row("B.17", a, "theta", a.f("theta"), 0, route)
    row("B.17", a, "Omega", a.f("omega") * dl / v0, 2, route)
    row("B.17", a, "tau", a.f("t") * v0 / dl, 2, route)
    a = Args(("delta", "0.6183"), ("v0", "1.7331"), ("L0", "-1.4137"), ("D", "0.4137"),
             ("V", "-0.5417"), ("theta", "0.2913"), ("Omega", "0.5813"), ("tau", "1.2917"))
    dl, v0 = a.f("delta"), a.f("v0")
    row("B.17", a, "ell0", a.f("L0") * dl, 1, route)
    row("B.17", a, "delta", dl, 0, route)
    row("B.17", a, "d", a.f("D") * dl, 1, route)
    row("B.17", a, "v", a.f("V") * v0, 1, route)
    row("B.17", a, "theta", a.f("theta"), 0, route)
    row("B.17", a, "omega", a.f("Omega") * v0 / dl, 2, route)
    row("B.17", a, "t", a.f("tau") * dl / v0, 2, route)


# ---- (2.4), (A.5): steady solutions
def smooth_field_vec(L, y):
    """(2.1) right side from Newton-Euler (theta = 0.3 arbitrary: the field
    does not depend on it), with dS/dtau = |V|."""
    dV, dOm = newton_euler(L, y[1], y[3], mpf("0.3"), False)
    return [abs(y[1]), dV, y[3], dOm]


def do_2_4():
    route_lin = "eigenvalues (mpmath eig) of the Jacobian (mpmath diff) of the Newton-Euler field at q*"
    for (Vs, L, th, tau) in (("-0.8629", "0.7321", "0.3719", "1.2917"),
                             ("1.4137", "-0.5417", None, None)):
        pairs = [("Vstar", Vs), ("L", L)]
        if th:
            pairs += [("theta", th), ("tau", tau)]
        a = Args(*pairs)
        Vs_, th_, tau_ = a["Vstar"], a.get("theta", 0), a.get("tau", 0)
        r = "exact rational arithmetic: the straight-line motion E = V*^2/2, H_C = (1 + L^2) Omega"
        if tau_ != 0:
            row("2.4", a, "S", abs(a.f("Vstar")) * a.f("tau"), 1, r)
        row("2.4", a, "V", Vs_, 0, r)
        if th_ != 0:
            row("2.4", a, "theta", th_, 0, r)
        row("2.4", a, "Omega", 0, 0, r)
        row("2.4", a, "E", a.f("Vstar") ** 2 / 2, 1, r)
        row("2.4", a, "H_C", 0, 0, r)
        Lm = a["L"]
        q = [mpf(0), Vs_, mpf(0), mpf(0)]
        J = matrix(4, 4)
        for j in range(4):
            for i in range(4):
                J[i, j] = diff(lambda x: smooth_field_vec(Lm, q[:j] + [x] + q[j + 1:])[i], q[j])
        ev = eig(J, left=False, right=False)
        nz = [x for x in ev if abs(x) > mpf(10) ** -30]
        assert len(nz) == 1
        row("2.4", a, "xi4", nz[0].real, 4, route_lin)
    a = Args(("Vstar", "-1.0923"))
    r = "exact rational arithmetic: all energy translational"
    row("A.5", a, "E", a.f("Vstar") ** 2 / 2, 1, r)
    row("A.5", a, "H_C", 0, 0, r)


# ---- (3.3), (3.4): invariants from the body in the plane
def do_3_3_3_4():
    for (L0, D, V, Om) in (("-1.4137", "0.2741", "0.8629", "-0.5813"),
                           ("0.7321", "1.0923", "-0.3719", "1.2917")):
        a = Args(("L0", L0), ("D", D), ("V", V), ("Omega", Om))
        G, vG, e, n = body(a["L0"], a["D"], a["V"], a["Omega"], mpf("0.9157"))
        row("3.3", a, "E", kinetic(vG, a["Omega"]), 4,
            "kinetic energy (|v_G|^2 + Omega^2)/2 of the body at heading 0.9157, 50 digits")
        a = Args(("L0", L0), ("D", D), ("Omega", Om))
        G, vG, e, n = body(a["L0"], a["D"], mpf("0.37"), a["Omega"], mpf("0.9157"))
        row("3.4", a, "H", ang_mom((0, 0), G, vG, a["Omega"]), 3,
            "angular momentum I Omega + (G - P) x v_G about the peg, 50 digits")


# ---- (3.6), (3.7): collisions
def do_3_6_3_7():
    route = "Cartesian impulse at the new peg (4x4 linear system), 50 digits"
    for (L0, Dl, V, Om, th) in (("0.7321", "0.4137", "0.8629", "0.5813", "0.3719"),
                                ("-2.1173", "0.6183", "-0.8629", "-0.2741", "-1.0923")):
        a = Args(("L0", L0), ("Delta", Dl), ("V", V), ("Omega", Om), ("theta", th))
        Dm = a["Delta"] if a["V"] > 0 else mpf(0)
        Dp, V1, Om1, E1, H1 = collide_cart(a["L0"], a["Delta"], Dm, a["V"], a["Omega"], a["theta"])
        row("3.6", a, "D_plus", Dp, 0, route)
        row("3.6", a, "V_plus", V1, 0, route)
        row("3.6", a, "theta_plus", a["theta"], 0, route)
        row("3.6", a, "Omega_plus", Om1, 6, route)
    for (L0, Dl, D, E, H, th) in (("0.7321", "0.4137", "0.4137", "0.9157", "0.5813", "0.3719"),
                                  ("-2.1173", "0.6183", "0", "0.6183", "-1.0923", "-1.0923")):
        a = Args(("L0", L0), ("Delta", Dl), ("D", D), ("E", E), ("H", H), ("theta", th))
        Dm = a["D"]
        s = 1 if Dm != 0 else -1           # the peg leaves the end it moves to
        V, Om = state_at(a["L0"], Dm, a["E"], a["H"], s)
        Dp, V1, Om1, E1, H1 = collide_cart(a["L0"], a["Delta"], Dm, V, Om, a["theta"])
        r = "Cartesian impulse at the new peg from the state (V, Omega) that E, H give at D-, 50 digits"
        row("3.7", a, "D_plus", Dp, 0, r)
        row("3.7", a, "E_plus", E1, 8, r)
        row("3.7", a, "theta_plus", a["theta"], 0, r)
        row("3.7", a, "H_plus", H1, 6, r)


# ---- (3.8)
def do_3_8():
    a = Args(("E", "0.9157"), ("H", "-1.2917"))
    row("3.8", a, "ratio", 2 * a.f("E") / a.f("H") ** 2, 2, "exact rational arithmetic")
    # exactly spinning: L0 = -3/4, V = 15/32, Omega = 1/2 at D = 0: E = 625/2048,
    # H = 25/32, 2E = H^2: V^2 = 2E - H^2/(1 + l^2) vanishes exactly at l = 0
    for (L0, Dl, d, V, Om, spins) in (("-3/4", "1.2917", "1", "15/32", "1/2", 1),
                                      ("-1.4137", "0.7321", "-1", "-0.5813", "0.8629", 0)):
        a = Args(("L0", L0), ("Delta", Dl), ("dir", d), ("V", V), ("Omega", Om))
        D = Fraction(0) if a.i("dir") > 0 else a.f("Delta")
        E, H = eh_of(a.f("L0"), D, a.f("V"), a.f("Omega"))
        r = 2 * E / (H * H)
        # spinning: V^2(l) = 2E - H^2/(1 + l^2) has its zero at l = 0 and l = 0 is on the path
        l_s = a.f("L0") + D
        l_f = a.f("L0") + a.f("Delta") - D
        on_path = min(l_s, l_f) <= 0 <= max(l_s, l_f)
        sp = int(r == 1 and on_path)
        assert sp == spins
        route = "exact rational arithmetic: E, H of the body, zero of V^2 at l = 0 on the path"
        row("3.8", a, "ratio", r, 0 if r == 1 else 6, route)
        row("3.8", a, "spins", sp, 0, route)


# ---- (3.9): Jacobian
def f3_derivs(L0, Delta, E, H):
    """df3/dE, df3/dH by quadrature of the E- and H-derivatives of the
    heading integrand H/(sqrt(1 + l^2) sqrt(g)), g = 2E (1 + l^2) - H^2,
    over the l of the path (no turning point on it):
      d/dE: -H sqrt(1 + l^2) g^(-3/2),   d/dH: 2E sqrt(1 + l^2) g^(-3/2)."""
    lo, hi = min(L0, L0 + Delta), max(L0, L0 + Delta)
    pts = [lo, hi] if not (lo < 0 < hi) else [lo, mpf(0), hi]
    g = lambda l: 2 * E * (1 + l * l) - H * H
    dE = quad(lambda l: -H * sqrt(1 + l * l) / g(l) ** mpf(1.5), pts)
    dH = quad(lambda l: 2 * E * sqrt(1 + l * l) / g(l) ** mpf(1.5), pts)
    return dE, dH


def do_3_9():
    route_c = "mpmath diff of the Cartesian collision map (E, H) -> (E', H'), 50 digits"
    route_f = "quadrature of the E-/H-derivative of the heading integrand over the path"
    for pairs in ((("L0", "0.7321"), ("Delta", "0.4137"), ("dir", "1"), ("E", "0.9157"), ("H", "0.5813")),
                  (("L0", "-2.1173"), ("Delta", "0.6183"), ("dir", "-1"), ("E", "0.6183"), ("H", "-0.3719")),
                  (("L0", "1.0923"), ("Delta", "0.2741"), ("dir", "-1"), ("V", "-0.8629"), ("Omega", "0.4137"))):
        a = Args(*pairs)
        L0, Dl, d = a["L0"], a["Delta"], a.i("dir")
        derived = "V" in a.v
        if derived:
            E, H = eh_of(L0, mpf(0) if d > 0 else Dl, a["V"], a["Omega"])
        else:
            E, H = a["E"], a["H"]
        assert not seg_reverses(L0, Dl, d, E, H)

        def emap(x):
            return seg_step(L0, Dl, d, x[0], x[1])[2:4]
        J22 = diff(lambda e: emap([e, H])[0], E)
        J24 = diff(lambda h: emap([E, h])[0], H)
        J44 = diff(lambda h: emap([E, h])[1], H)
        J42 = diff(lambda e: emap([e, H])[1], E)
        dE, dH = f3_derivs(L0, Dl, E, H)
        # conversion of derived inputs: the library's E, H carry ~3 and ~2
        # eps; the entries' sensitivity to them
        if derived:
            kc = kappas(lambda x: list(f3_derivs(L0, Dl, x[0], x[1])), [E, H])
            extra = [2, 3 * kc[0], 3 * kc[1]]
        else:
            extra = [0, 0, 0]
        row("3.9", a, "J11", 0, 0, "exact: D+ is the same end after every segment without reversal")
        row("3.9", a, "J22", J22, 0 if abs(J22 - 1) < mpf(10) ** -40 else 2, route_c)
        row("3.9", a, "J24", J24, 8 + extra[0], route_c)
        row("3.9", a, "J42", 0, 0, route_c)
        row("3.9", a, "J44", J44, 6, route_c)
        row("3.9", a, "J32", dE, 16 + extra[1], route_f)
        row("3.9", a, "J33", 1, 0, "exact: theta' = theta + f3(E, H)")
        row("3.9", a, "J34", dH, 16 + extra[2], route_f)
        assert abs(J42) < mpf(10) ** -40


# ---- (3.10)-(3.15)
def do_stability():
    route = "exact rational arithmetic: H'/H of the Cartesian impulse at the new peg (theta = 0)"
    for (L0, Dl, d) in (("0.7321", "0.4137", 1), ("0.7321", "0.4137", -1),
                        ("-2.1173", "1.0923", -1), ("-0.3719", "1.2917", 1)):
        a = Args(("L0", L0), ("Delta", Dl), ("dir", d))
        C1, C2 = coefficients_cart(a.f("L0"), a.f("Delta"), d, 0)
        row("3.10", a, "sigma4", C2, 4, route)
    route = "exact rational arithmetic: |sigma4| < 1, sigma4 = H'/H of the Cartesian collision"

    def chained(x, y, d):
        if d > 0:
            mid = -Fraction(1, 2) * (1 + 2 * x) * (1 + x)
            return int(x > -1 and y > mid and mid > 0)
        mid = -Fraction(1, 2) * x * (1 + 2 * x)
        return int(x < 0 and y > mid and mid > 0)

    for (lab, d, pts) in (("3.11", 1, (("0.7321", "0.4137", False), ("-0.5813", "0.7321", True),
                                      ("-1.4137", "0.4137", True), ("-3.9688", "5.2917", True))),
                          ("3.12", -1, (("0.7321", "0.4137", True), ("-0.3719", "1.2917", True),
                                       ("-1.0923", "1.4137", False)))):
        for (L0, Dl, agree) in pts:
            a = Args(("L0", L0), ("Delta", Dl))
            C1, C2 = coefficients_cart(a.f("L0"), a.f("Delta"), d, 0)
            st = int(abs(C2) < 1)
            x, y = a.f("L0") / a.f("Delta"), 1 / a.f("Delta") ** 2
            pr = chained(x, y, d)
            assert (pr == st) == agree, (lab, L0, Dl, st, pr)
            row(lab, a, "stable", st, 0, route)
            row(lab, a, "stable", pr, 0, "printed form of E12 read as a chain, exact rationals", "printed")
    # (3.13)-(3.15): V^2 = H^2 (r - 1/(1 + l^2)) on the path
    route = ("exact rational arithmetic: r for which V^2 = H^2 (r - 1/(1 + l^2)) is > 0 at the start "
             "and vanishes on the path (largest 1/(1 + l^2) on it)")
    for (lab, L0, Dl, d) in (("3.13", "0.7321", "0.4137", None), ("3.13", "0.7321", "0.4137", 1),
                             ("3.14", "-2.1173", "0.6183", None), ("3.14", "-2.1173", "0.6183", -1)):
        pairs = [("L0", L0), ("Delta", Dl)] + ([("dir", str(d))] if d else [])
        a = Args(*pairs)
        dd = d if d else (-1 if lab == "3.13" else 1)
        L0f, Dlf = a.f("L0"), a.f("Delta")
        ls = L0f if dd > 0 else L0f + Dlf
        lf = L0f + Dlf if dd > 0 else L0f
        # largest 1/(1 + l^2) over the path from ls to lf
        cand = [ls, lf] + ([Fraction(0)] if min(ls, lf) <= 0 <= max(ls, lf) else [])
        rmax = max(1 / (1 + l * l) for l in cand)
        rlo = 1 / (1 + ls * ls)
        nonempty = int(rmax > rlo)
        row(lab, a, "rlo", rlo, 3, route)
        row(lab, a, "rhi", rmax if nonempty else rlo, 3, route)
        row(lab, a, "nonempty", nonempty, 0, route)
    for d in (1, -1):
        a = Args(("L0", "-0.3719"), ("Delta", "1.2917"), ("dir", str(d)))
        ls = a.f("L0") if d > 0 else a.f("L0") + a.f("Delta")
        row("3.15", a, "rmin", 1 / (1 + ls * ls), 2 if d > 0 else 3,
            "exact rational arithmetic: V+^2 = 2E - H^2/(1 + l_s^2) > 0")


# ---- (4.1)
def sigma4_mp(L0, Delta, d):
    """sigma4 = H'/H of the Cartesian collision at a fixed point of
    direction d, as a function of real Delta (for mpmath.taylor)."""
    Dm = Delta if d > 0 else mpf(0)
    V, Om = mpf(1), mpf(1) / 3
    E, H = eh_of(L0, Dm, V, Om)
    return collide_cart(L0, Delta, Dm, V, Om)[4] / H


def do_4_1():
    for (L0, Dl, Vs, which) in (("0.7321", "0.4137", "0.8629", "differs"),
                                ("0.7321", "0.4137", "-1.2917", None),
                                ("0", "0.2741", "1.0923", "agrees"),
                                ("-0.2913", "0.5813", "0.6183", "differs")):
        a = Args(("L0", L0), ("Delta", Dl), ("Vstar", Vs))
        L0m, Dm, Vm = a["L0"], a["Delta"], a["Vstar"]
        d = 1 if Vm > 0 else -1
        C1, C2 = coefficients_cart(a.f("L0"), a.f("Delta"), d, 0)
        tau_star = Dm / abs(Vm)
        xi4 = log(mpf(C2.numerator) / C2.denominator) / tau_star
        row("4.1", a, "xi4", xi4, 6,
            "log(sigma4)/tau*, sigma4 = H'/H of the Cartesian collision (exact), tau* = Delta/|V*|")
        co = taylor(lambda x: log(sigma4_mp(L0m, x, d)), 0, 3)
        c = [d * co[1], d * co[2], d * co[3]]
        route = "mpmath taylor in Delta of log(sigma4) of the Cartesian collision"
        for k, tl in ((0, 4), (1, 6), (2, 8)):
            if c[k] == 0 or abs(c[k]) < mpf(10) ** -40:
                row("4.1", a, "c%d" % k, 0, 0, route)
            else:
                row("4.1", a, "c%d" % k, c[k], tl, route)
        if which:
            pc2 = -(L0m * (L0m ** 2 - 2)) / (3 * (1 + L0m ** 2) ** 3)
            assert (abs(pc2 - c[2]) < mpf(10) ** -30) == (which == "agrees")
            row("4.1", a, "c2", pc2 if pc2 != 0 else 0, 0 if pc2 == 0 else 8,
                "printed formula of E13 at 50 digits", "printed")


# ---- Appendix A: the smooth sleigh
def printed_Sc(L, S0, V0, Om0):
    """(A.1) as printed."""
    return S0 - (1 + L * L) / (2 * L) * log(1 + V0 ** 2 / (Om0 ** 2 * (1 + L * L)))


def printed_K(L, S, Sc):
    """(A.3) as printed (defined for V0 > 0; applied as written)."""
    if L > 0:
        return 1
    return 1 if S < Sc else -1


def printed_A2(L, V0, Om0, S, S0, th0):
    """(A.2) as printed (E4's parenthesis placed), with the printed K and S_c."""
    Sc = printed_Sc(L, S0, V0, Om0) if L < 0 else None
    K = printed_K(L, S, Sc)
    a = L / (1 + L * L)
    V = K * sqrt(V0 ** 2 + Om0 ** 2 * (1 + L * L) * (1 - exp(-K * 2 * a * (S - S0))))
    k = 1 / sqrt(V0 ** 2 / (Om0 ** 2 * (1 + L * L)) + 1)
    th = th0 + K * sqrt(1 + L * L) / L * (asin(k) - asin(k * exp(-K * a * (S - S0))))
    Om = Om0 * exp(-K * a * (S - S0))
    return V, th, Om


def printed_A4(L, E0, H0, S, S0, th0, V0sign):
    """(A.4) as printed, the printed K with the printed S_c of (A.6)."""
    Sc = S0 - (1 + L * L) / (2 * L) * log(2 * E0 * (1 + L * L) / H0 ** 2) if L < 0 else None
    K = printed_K(L, S, Sc)
    a = L / (1 + L * L)
    R = sqrt(2 * E0 * (1 + L * L) / H0 ** 2)
    th = th0 + K * sqrt(1 + L * L) / L * (asin(1 / R) - asin(exp(-K * a * (S - S0)) / R))
    return th, H0 * exp(-K * a * (S - S0))


def smooth_phase_from_eh(L, E0, H0, dir0):
    Om0 = H0 / (1 + L * L)
    return dir0 * sqrt(2 * E0 - H0 * Om0), Om0


def do_smooth():
    rode = "mpmath odefun on (2.1) (signed displacement), reversal by findroot, 50 digits"
    # (A.1)
    for (L, V, Om, S0, printed) in (("0.7321", "-1.0923", "0.4137", "0.2741", "differs"),
                                    ("-1.2917", "0.8629", "-0.5813", "0.3719", "agrees"),
                                    ("0.7321", "0.8629", "0.5813", None, None)):
        pairs = [("L", L), ("V", V), ("Omega", Om)] + ([("S", S0)] if S0 else [])
        a = Args(*pairs)
        Lm, V0, Om0, S0m = a["L"], a["V"], a["Omega"], a.get("S", 0)
        _, sc = smooth_ode(Lm, V0, Om0, [])
        row("A.1", a, "reverses", int(sc is not None), 0, rode)
        if sc is not None:
            Sc = S0m + sc
            row("A.1", a, "Sc", Sc, 8, rode)
            p = printed_Sc(Lm, S0m, V0, Om0)
            assert (abs(p - Sc) < mpf(10) ** -30) == (printed == "agrees")
            row("A.1", a, "Sc", p, 8, "printed formula of E3 (A.1) at 50 digits", "printed")
    # (A.2), (A.3)
    for (L, V0, Om0, S, S0, th0, printed) in (
            ("-1.2917", "0.8629", "0.5813", "2.1173", "0.3719", "0.2741", "differs"),  # E5
            ("0.7321", "0.8629", "-0.5813", "1.4137", None, "-0.2741", "theta"),       # E6
            ("0.7321", "0.8629", "0.5813", "1.0923", None, None, "agrees"),
            ("0.7321", "-1.0923", "0.4137", "3.1427", None, None, None)):
        pairs = [("L", L), ("V0", V0), ("Omega0", Om0), ("S", S)]
        pairs += ([("S0", S0)] if S0 else []) + ([("theta0", th0)] if th0 else [])
        a = Args(*pairs)
        Lm, V0m, Om0m, Sm = a["L"], a["V0"], a["Omega0"], a["S"]
        S0m, th0m = a.get("S0", 0), a.get("theta0", 0)
        xs = [Lm, V0m, Om0m, Sm, S0m, th0m]

        def fn(x):
            (V, Om, dth, dtau), = smooth_ode(x[0], x[1], x[2], [x[3] - x[4]])[0]
            return [V, x[5] + dth, Om, dtau]
        ref = fn(xs)
        kap = kappas(fn, xs)
        names = ["V", "theta", "Omega", "dtau"]
        for k in range(4):
            row("A.2", a, names[k], ref[k], tol_kappa(kap[k]), rode)
        if printed:
            pv = printed_A2(Lm, V0m, Om0m, Sm, S0m, th0m)
            for k in range(3):
                same = abs(pv[k] - ref[k]) < mpf(10) ** -30 * abs(ref[k])
                if printed == "agrees":
                    assert same
                if printed == "theta":
                    assert same == (k != 1)
                if printed == "differs":
                    assert not same
                row("A.2", a, names[k], pv[k], 16,
                    "printed (A.2) with the printed K of (A.3) and S_c of (A.1), 50 digits", "printed")
    for (L, V0, Om0, S, S0, printed) in (("0.7321", "-1.0923", "0.4137", "3.1427", None, "differs"),
                                         ("-1.2917", "0.8629", "0.5813", "2.1173", "0.3719", "agrees"),
                                         ("-1.2917", "0.8629", "0.5813", "0.6183", "0.3719", "agrees")):
        pairs = [("L", L), ("V0", V0), ("Omega0", Om0), ("S", S)] + ([("S0", S0)] if S0 else [])
        a = Args(*pairs)
        Lm, V0m, Om0m, Sm, S0m = a["L"], a["V0"], a["Omega0"], a["S"], a.get("S0", 0)
        (V, Om, dth, dtau), = smooth_ode(Lm, V0m, Om0m, [Sm - S0m])[0]
        K = int(sign(V / V0m))
        row("A.3", a, "K", K, 0, "sign of V(S)/V0 from " + rode)
        Scp = printed_Sc(Lm, S0m, V0m, Om0m) if Lm < 0 else None
        pK = printed_K(Lm, Sm, Scp)
        assert (pK == K) == (printed == "agrees")
        row("A.3", a, "K", pK, 0, "printed definition of K (A.3), E7", "printed")
    # (A.4)
    for (pairs, printed) in (
            ((("L", "-1.2917"), ("S", "2.1173"), ("E0", "0.7321"), ("H0", "0.9157"), ("dir0", "1"),
              ("S0", "0.2741"), ("theta0", "0.3719")), "differs"),
            ((("L", "0.7321"), ("S", "1.0923"), ("E0", "0.6183"), ("H0", "-0.4137"), ("dir0", "1"),
              ("theta0", "-0.2913")), "theta"),
            ((("L", "0.7321"), ("S", "1.0923"), ("E0", "0.6183"), ("H0", "0.4137"), ("dir0", "1")), "agrees"),
            ((("L", "0.7321"), ("S", "1.2917"), ("V0", "-0.8629"), ("Omega0", "0.5813")), None)):
        a = Args(*pairs)
        Lm, Sm, S0m, th0m = a["L"], a["S"], a.get("S0", 0), a.get("theta0", 0)
        derived = "V0" in a.v
        if derived:
            V0m, Om0m = a["V0"], a["Omega0"]
            E0 = (V0m ** 2 + (1 + Lm ** 2) * Om0m ** 2) / 2
            H0 = (1 + Lm ** 2) * Om0m
            dir0 = int(sign(V0m))
        else:
            E0, H0, dir0 = a["E0"], a["H0"], a.i("dir0")

        def fn(x):
            V0, Om0 = smooth_phase_from_eh(x[0], x[2], x[3], dir0)
            (V, Om, dth, dtau), = smooth_ode(x[0], V0, Om0, [x[1] - x[4]])[0]
            return [x[5] + dth, (1 + x[0] ** 2) * Om]
        xs = [Lm, Sm, E0, H0, S0m, th0m]
        ref = fn(xs)
        kap = kappas(fn, xs)
        if derived:
            row("A.4", a, "E", E0, 4, "kinetic energy of (V0, Omega0), 50 digits")
        else:
            row("A.4", a, "E", E0, 0, "conservation of energy")
        row("A.4", a, "theta", ref[0], tol_kappa(kap[0]), rode + ", from V0, Omega0 of E0, H0")
        row("A.4", a, "H_C", ref[1], tol_kappa(kap[1]), rode + ", from V0, Omega0 of E0, H0")
        if printed:
            pth, pH = printed_A4(Lm, E0, H0, Sm, S0m, th0m, dir0)
            sth = abs(pth - ref[0]) < mpf(10) ** -30 * abs(ref[0])
            sH = abs(pH - ref[1]) < mpf(10) ** -30 * abs(ref[1])
            assert (sth, sH) == {"differs": (False, False), "theta": (False, True),
                                 "agrees": (True, True)}[printed]
            r = "printed (A.4) with the printed K of (A.3) and S_c of (A.6), 50 digits"
            row("A.4", a, "E", E0, 0, r, "printed")
            row("A.4", a, "theta", pth, 16, r, "printed")
            row("A.4", a, "H_C", pH, 16, r, "printed")
    # (A.6)
    for (pairs, printed) in (
            ((("L", "0.7321"), ("E0", "0.9157"), ("H0", "0.5813"), ("dir0", "-1"), ("S0", "0.2741")), "differs"),
            ((("L", "-1.2917"), ("E0", "0.7321"), ("H0", "0.9157"), ("dir0", "1"), ("S0", "0.3719")), "agrees"),
            ((("L", "-0.5417"), ("V0", "1.4137"), ("Omega0", "-0.6183")), None),
            ((("L", "0.7321"), ("E0", "0.9157"), ("H0", "0.5813"), ("dir0", "1")), None)):
        a = Args(*pairs)
        Lm, S0m = a["L"], a.get("S0", 0)
        if "V0" in a.v:
            V0m, Om0m = a["V0"], a["Omega0"]
            E0 = (V0m ** 2 + (1 + Lm ** 2) * Om0m ** 2) / 2
            H0 = (1 + Lm ** 2) * Om0m
            # E0, H0 rounded by the conversion (3 and 2 eps) move the log by
            # 7 eps absolute: 7 eps (1 + L^2)/(2|L|)/Sc relative, < 8 eps here
            tol_extra = 8
        else:
            E0, H0 = a["E0"], a["H0"]
            V0m, Om0m = smooth_phase_from_eh(Lm, E0, H0, a.i("dir0"))
            tol_extra = 0
        _, sc = smooth_ode(Lm, V0m, Om0m, [])
        row("A.6", a, "reverses", int(sc is not None), 0, rode + ", from V0, Omega0 of E0, H0")
        if sc is not None:
            Sc = S0m + sc
            row("A.6", a, "Sc", Sc, 8 + tol_extra, rode + ", from V0, Omega0 of E0, H0")
            if printed:
                p = S0m - (1 + Lm * Lm) / (2 * Lm) * log(2 * E0 * (1 + Lm * Lm) / H0 ** 2)
                assert (abs(p - Sc) < mpf(10) ** -30) == (printed == "agrees")
                row("A.6", a, "Sc", p, 8, "printed formula of E3 (A.6) at 50 digits", "printed")


# ---- (B.1), (B.2): one leg
def do_B_1_B_2():
    rode = "mpmath odefun on (3.1) to the given D, findroot in time, 50 digits"
    for (L0, D0, V0, Om0, D) in (("0.7321", "0", "0.8629", "0.5813", "0.2741"),
                                 ("-2.1173", "0.6183", "-1.0923", "-0.4137", "0.3719")):
        a = Args(("L0", L0), ("D0", D0), ("V0", V0), ("Omega0", Om0), ("D", D))
        V2, Om, th, ta = leg_ode(a["L0"], a["D0"], a["V0"], a["Omega0"], a["D"])
        # terms of V^2 of one sign, Omega a ratio: ~10 and ~6 roundings
        row("B.1", a, "V2", V2, 8, rode)
        row("B.1", a, "Omega", Om, 6, rode)
    for (pairs, printed) in (
            ((("L0", "0.7321"), ("D0", "0.0917"), ("V0", "0.8629"), ("Omega0", "0.5813"), ("D", "0.6183")), "agrees"),
            ((("L0", "-2.1173"), ("D0", "0.9157"), ("V0", "-1.0923"), ("Omega0", "0.4137"), ("D", "0.2741")), "differs"),
            ((("L0", "-2.1173"), ("D0", "0.9157"), ("V0", "-1.0923"), ("Omega0", "0.4137"), ("D", "0.2741"),
              ("method", "quadrature"), ("tol", "1e-14")), None),
            ((("L0", "0.7321"), ("D0", "0.0917"), ("V0", "0.8629"), ("Omega0", "0.5813"), ("D", "0.6183"),
              ("method", "ode"), ("tol", "1e-13")), None)):
        a = Args(*[p for p in pairs if p[0] != "method"])
        a.items = [(n, t) for (n, t) in pairs]
        method = dict(pairs).get("method", "closed-form")
        xs = [a["L0"], a["D0"], a["V0"], a["Omega0"], a["D"]]
        V2, Om, th, ta = leg_ode(*xs)
        th2, ta2 = make_refs.leg_ref(*xs)
        assert abs(th - th2) < mpf(10) ** -35 * abs(th) and abs(ta - ta2) < mpf(10) ** -35 * ta
        kap = kappas(lambda x: list(make_refs.leg_ref(*x)), xs)
        tols = {"closed-form": [tol_kappa(k) for k in kap],
                "quadrature": [mpf("1e-13") * (1 + k) / EPS for k in kap],
                "ode": [mpf("1e-10") * (1 + k) / EPS for k in kap]}[method]
        route = rode + " (agrees with quadrature in D to 1e-35)"
        row("B.2", a, "dtheta", th, tols[0], route)
        row("B.2", a, "dtau", ta, tols[1], route)
        if printed:
            p = sign(a["D"] - a["D0"]) * abs(th)
            assert (p == th) == (printed == "agrees")
            row("B.2", a, "dtheta", p, tols[0], "printed form of E9: sgn(D - D0)|dtheta|", "printed")


# ---- (3.5), (B.3), (B.4): the segment map
def segment_full(L0, Dl, d, E, H, Vstart=None):
    """Heading and time by make_refs.segment_ref (quadrature in D, turning
    point by root-finding on V^2); the collision by the Cartesian impulse.
    Returns dict with rev, dir1, E1, H1, dtheta, dtau, Dc, Dm, V1, Om1."""
    rev, nd, _, _, th, ta, root = make_refs.segment_ref(L0, Dl, d, E, H)
    Dstart = mpf(0) if d > 0 else Dl
    Dm = Dstart if rev else Dl - Dstart
    s = -d if rev else d
    V, Om = state_at(L0, Dm, E, H, s)
    Dp, V1, Om1, E1, H1 = collide_cart(L0, Dl, Dm, V, Om)
    return dict(rev=rev, dir1=(1 if V1 > 0 else -1), E1=E1, H1=H1, dtheta=th, dtau=ta,
                Dc=root, Dm=Dm, Dp=Dp, V1=V1, Om1=Om1)


def do_3_5():
    route = ("quadrature in D (make_refs.segment_ref) from E, H of the phase state, "
             "Cartesian impulse at the new peg, 50 digits")
    for pairs in ((("L0", "0.7321"), ("Delta", "0.4137"), ("V", "0.8629"), ("Omega", "0.5813"), ("theta", "0.3719")),
                  (("L0", "0.7321"), ("Delta", "1.2917"), ("V", "-0.8137"), ("Omega", "0.9157"), ("theta", "0.2741")),
                  (("L0", "0.7321"), ("Delta", "0.4137"), ("V", "0.8629"), ("Omega", "0.5813"), ("theta", "0.3719"),
                   ("method", "quadrature"), ("tol", "1e-14")),
                  (("L0", "0.7321"), ("Delta", "1.2917"), ("V", "-0.8137"), ("Omega", "0.9157"), ("theta", "0.2741"),
                   ("method", "ode"), ("tol", "1e-13"))):
        a = Args(*[p for p in pairs if p[0] != "method"])
        a.items = list(pairs)
        method = dict(pairs).get("method", "closed-form")
        L0, Dl, V, Om, th0 = a["L0"], a["Delta"], a["V"], a["Omega"], a["theta"]

        def fn(x):
            d = 1 if x[2] > 0 else -1
            E, H = eh_of(x[0], mpf(0) if d > 0 else x[1], x[2], x[3])
            r = segment_full(x[0], x[1], d, E, H)
            return [r["V1"], x[4] + r["dtheta"], r["Om1"], r["dtau"]]
        xs = [L0, Dl, V, Om, th0]
        ref = fn(xs)
        d = 1 if V > 0 else -1
        E, H = eh_of(L0, mpf(0) if d > 0 else Dl, V, Om)
        r = segment_full(L0, Dl, d, E, H)
        kap = kappas(fn, xs)
        base = [8, 16, 8, 16]
        if method == "closed-form":
            tols = [tol_kappa(k, b) for k, b in zip(kap, base)]
        elif method == "quadrature":
            tols = [mpf("1e-13") * (1 + k) / EPS if b == 16 else tol_kappa(k, b) for k, b in zip(kap, base)]
        else:
            tols = [mpf("1e-10") * (1 + k) / EPS for k in kap]
        row("3.5", a, "D_next", r["Dp"], 0, route)
        for name, val, t in zip(("V_next", "theta_next", "Omega_next", "dtau"), ref, tols):
            row("3.5", a, name, val, t, route + (" (reversal)" if r["rev"] else ""))


def do_B_3_B_4():
    route = ("quadrature in D (make_refs.segment_ref), turning point by root-finding on V^2, "
             "Cartesian impulse at the new peg, 50 digits")
    rc = "Cartesian impulse at the new peg: C1 = (E' - E)/H^2, C2 = H'/H, exact rationals"
    cases = (
        ("B.3", (("L0", "0.7321"), ("Delta", "0.4137"), ("dir", "1"), ("E", "0.9157"), ("H", "0.5813"),
                 ("theta", "0.3719"), ("tau", "1.0923")), "agrees"),
        ("B.3", (("L0", "-2.1173"), ("Delta", "0.6183"), ("dir", "-1"), ("E", "0.6183"), ("H", "0.3719")), "differs"),
        ("B.3", (("L0", "1.0923"), ("Delta", "0.2741"), ("dir", "-1"), ("V", "-0.8629"), ("Omega", "0.4137")), "differs"),
        ("B.3", (("L0", "0.7321"), ("Delta", "0.4137"), ("dir", "1"), ("E", "0.9157"), ("H", "0.5813"),
                 ("method", "quadrature"), ("tol", "1e-14")), None),
        ("B.3", (("L0", "-2.1173"), ("Delta", "0.6183"), ("dir", "-1"), ("E", "0.6183"), ("H", "0.3719"),
                 ("method", "ode"), ("tol", "1e-13")), None),
        ("B.4", (("L0", "0.7321"), ("Delta", "1.2917"), ("dir", "-1"), ("E", "0.2741"), ("H", "1.0923"),
                 ("theta", "0.3719")), None),
        ("B.4", (("L0", "-2.1173"), ("Delta", "0.6183"), ("dir", "1"), ("E", "0.2473"), ("H", "1.4137")), None),
        ("B.4", (("L0", "-0.6183"), ("Delta", "0.9157"), ("dir", "1"), ("V", "0.1917"), ("Omega", "0.4137")), None),
        ("B.4", (("L0", "0.7321"), ("Delta", "1.2917"), ("dir", "-1"), ("E", "0.2741"), ("H", "1.0923"),
                 ("method", "quadrature"), ("tol", "1e-14")), None),
    )
    for (lab, pairs, printed) in cases:
        a = Args(*[p for p in pairs if p[0] != "method"])
        a.items = list(pairs)
        method = dict(pairs).get("method", "closed-form")
        L0, Dl, d = a["L0"], a["Delta"], a.i("dir")
        derived = "V" in a.v
        if derived:
            E, H = eh_of(L0, mpf(0) if d > 0 else Dl, a["V"], a["Omega"])
        else:
            E, H = a["E"], a["H"]
        r = segment_full(L0, Dl, d, E, H)
        assert r["rev"] == (lab == "B.4"), (lab, pairs)
        C1, C2 = coefficients_cart(a.f("L0"), a.f("Delta"), d, r["rev"])
        row(lab, a, "C1", C1, 8, rc)
        row(lab, a, "C2", C2, 4, rc)
        row(lab, a, "reversal", r["rev"], 0, route)

        def fn(x):
            rr = segment_full(x[0], x[1], d, x[2], x[3])
            out = [rr["E1"], rr["H1"], rr["dtheta"], rr["dtau"]]
            if lab == "B.4":
                out.append(rr["Dc"])
            return out
        xs = [L0, Dl, E, H]
        kap = kappas(fn, xs)
        ref = [r["E1"], r["H1"], r["dtheta"], r["dtau"]] + ([r["Dc"]] if lab == "B.4" else [])
        names = ["E_next", "H_next", "dtheta", "dtau", "Dc"]
        base = [8, 6, 16, 16, 16]
        for k in range(len(ref)):
            if method == "closed-form" or (method == "quadrature" and base[k] != 16):
                t = tol_kappa(kap[k], base[k])
            elif method == "quadrature":
                t = mpf("1e-13") * (1 + kap[k]) / EPS
            else:
                t = mpf("1e-10") * (1 + kap[k]) / EPS
            row(lab, a, names[k], ref[k], t, route)
        if printed:
            p = sign(Dl - 2 * (mpf(0) if d > 0 else Dl)) * abs(r["dtheta"])
            assert (p == r["dtheta"]) == (printed == "agrees")
            row(lab, a, "dtheta", p, tol_kappa(kap[2]), "printed f3 of E10: sgn(Delta - 2 D+)|dtheta|", "printed")


# ---- (B.5), (B.8): turning points by root-finding on V^2(D)
def v2_roots(L0, E, H):
    """Real zeros of V^2(D) = 2E - H^2/(1 + (L0 + D)^2): sign changes on a
    grid over |l| <= |H|/sqrt(2E) + 1, refined by findroot (bisection)."""
    R = abs(H) / sqrt(2 * E) + 1
    N = 4000
    f = lambda D: 2 * E - H * H / (1 + (L0 + D) ** 2)
    xs = [-L0 - R + 2 * R * mpf(k) / N for k in range(N + 1)]
    roots = []
    for x0, x1 in zip(xs, xs[1:]):
        if f(x0) * f(x1) < 0:
            roots.append(findroot(f, (x0, x1), solver="bisect"))
    return roots


def do_B_5_B_8():
    route = "root-finding on V^2(D) = 2E - H^2/(1 + (L0 + D)^2) (grid scan, bisection), 50 digits"
    for pairs in ((("L0", "-1.0923"), ("Delta", "2.1173"), ("E", "0.2726"), ("H", "0.8629")),
                  (("L0", "0.7321"), ("Delta", "0.4137"), ("E", "0.9157"), ("H", "1.4137")),
                  (("L0", "0.7321"), ("Delta", "0.4137"), ("E", "0.9157"), ("H", "0.5813")),
                  (("L0", "-1.0923"), ("Delta", "2.1173"), ("D", "0.2741"), ("V", "0.4137"), ("Omega", "0.5813"))):
        a = Args(*pairs)
        L0, Dl = a["L0"], a["Delta"]
        if "V" in a.v:
            E, H = eh_of(L0, a["D"], a["V"], a["Omega"])
        else:
            E, H = a["E"], a["H"]
        roots = v2_roots(L0, E, H)
        row("B.5", a, "n_real", len(roots), 0, route)
        row("B.5", a, "n_in_slot", sum(1 for x in roots if 0 <= x <= Dl), 0, route)
        if roots:
            def fn(x):
                return v2_roots(x[0], x[1], x[2])
            kap = kappas(fn, [L0, E, H])
            for k, x in enumerate(roots):
                row("B.5", a, "Dc%d" % (k + 1), x, tol_kappa(kap[k]), route)
    # (B.8): both turning points in (0, Delta)
    for (pairs, printed) in (((("L0", "-1.0923"), ("Delta", "2.1173"), ("E", "0.1971"), ("H", "0.9157")), "differs"),
                             ((("L0", "-1.0923"), ("Delta", "2.1173"), ("E", "0.2726"), ("H", "0.8629")), "agrees"),
                             ((("L0", "-1.0923"), ("Delta", "2.1173"), ("E", "0.9157"), ("H", "0.5813")), "agrees")):
        a = Args(*pairs)
        roots = v2_roots(a["L0"], a["E"], a["H"])
        two = int(len(roots) == 2 and all(0 < x < a["Delta"] for x in roots))
        row("B.8", a, "two", two, 0, route + "; both in (0, Delta)")
        L0f, Dlf = a.f("L0"), a.f("Delta")
        r = 2 * a.f("E") / a.f("H") ** 2
        p = int(min(1 / (1 + L0f ** 2), 1 / (1 + (L0f + Dlf) ** 2)) < r < 1)
        assert (p == two) == (printed == "agrees")
        row("B.8", a, "two", p, 0, "printed (B.8) with MIN (E21), exact rationals", "printed")


# ---- (B.6), (B.7), (B.9)-(B.12): iteration of the map
def iterate_until_reversal(L0, Dl, d, E, H, nmax=100000):
    """n = collisions without reversal before the reversing segment, by
    direct iteration (None if the state provably never reverses: moving
    away from l = 0 in a direction that keeps it, with |C2| < 1)."""
    for n in range(nmax):
        rev, d1, E1, H1 = seg_step(L0, Dl, d, E, H)
        if rev:
            return n
        # never again: |l| grows along the path and does so forever
        ls = L0 if d > 0 else L0 + Dl
        lf = L0 + Dl if d > 0 else L0
        if abs(lf) > abs(ls) and ls * lf > 0:
            return None
        assert d1 == d
        E, H = E1, H1
    raise AssertionError("no reversal found")


def printed_B6(L0, Dl, d, E, H):
    """(B.6) as printed, with C2 of (B.3) from the Cartesian collision and
    C3 as printed in (B.7)."""
    C1, C2 = coefficients_cart(Fraction(float(L0)), Fraction(float(Dl)), d, 0)
    C2 = mpf(C2.numerator) / C2.denominator
    Dplus = 0 if d > 0 else Dl
    lf = L0 + Dl - Dplus
    C3 = d * Dl * (2 * L0 + Dl) / (1 + lf ** 2)
    arg = 1 + (1 - C2 ** 2) / C3 * (2 * E / H ** 2 * (1 + (L0 + Dplus) ** 2) - 1)
    if arg <= 0:
        return None
    return int(floor(log(arg) / log(C2 ** 2)))


# (B.6) inside the slot, where the printed count is wrong: found by scanning
# a grid of (L0, Delta, dir, E, H) with decimals of four digits for a state
# whose printed count is defined, >= 0 and not the iterated one (here 3
# against 2: the printed form overcounts).  Margins: r_2 = 0.982 against the
# threshold 1, the printed ratio of logarithms 3.019.
B6_DIFFERS = (("L0", "-0.5813"), ("Delta", "0.7321"), ("dir", "1"), ("E", "1.0923"), ("H", "1.2917"))


def do_B_6():
    route = "direct iteration of the map (reversal by V^2 on the path, Cartesian collisions), 50 digits"
    for (pairs, printed) in (
            ((("L0", "0.7321"), ("Delta", "0.4137"), ("dir", "-1"), ("E", "1.0923"), ("H", "1.0217")), "agrees"),
            (B6_DIFFERS, "differs"),
            ((("L0", "0.7321"), ("Delta", "0.4137"), ("dir", "1"), ("E", "0.9157"), ("H", "0.5813")), None),
            ((("L0", "-2.1173"), ("Delta", "0.6183"), ("dir", "1"), ("V", "0.2741"), ("Omega", "0.2913")), "agrees")):
        a = Args(*pairs)
        L0, Dl, d = a["L0"], a["Delta"], a.i("dir")
        if "V" in a.v:
            E, H = eh_of(L0, mpf(0) if d > 0 else Dl, a["V"], a["Omega"])
        else:
            E, H = a["E"], a["H"]
        n = iterate_until_reversal(L0, Dl, d, E, H)
        row("B.6", a, "reverses", int(n is not None), 0, route)
        if n is not None:
            row("B.6", a, "n", n, 0, route)
        if printed:
            p = printed_B6(L0, Dl, d, E, H)
            assert p is not None and (p == n) == (printed == "agrees"), (pairs, p, n)
            row("B.6", a, "n", p, 0, "printed floor formula of E20 (B.6) at 50 digits", "printed")


def do_B_7():
    route = ("exact rational arithmetic: C3 = C2^2 Y' - Y, Y = (1 + l_s^2) V^2/H^2, "
             "V at the far end by conservation of E and H")
    for (L0, Dl, d) in (("0.7321", "0.4137", 1), ("-0.3719", "1.2917", -1)):
        a = Args(("L0", L0), ("Delta", Dl), ("dir", str(d)))
        L0f, Dlf = a.f("L0"), a.f("Delta")
        Ds = Fraction(0) if d > 0 else Dlf
        Df = Dlf - Ds
        Vs, Om = Fraction(3, 2), Fraction(2, 5)
        E, H = eh_of(L0f, Ds, Vs, Om)
        lf = L0f + Df
        Vf2 = 2 * E - H * H / (1 + lf * lf)
        ls = L0f + Ds
        C3 = (1 + ls * ls) * (Vf2 - Vs * Vs) / (H * H)
        row("B.7", a, "C3", C3, 6, route)


def do_B_9_to_B_12():
    route = "direct iteration of the map (Cartesian collisions), no reversal checked, 50 digits"
    for (pairs, printed) in (
            ((("L0", "0.7321"), ("Delta", "0.4137"), ("dir", "1"), ("E", "0.9157"), ("H", "0.5813"), ("n", "3")), "differs"),
            ((("L0", "-2.1173"), ("Delta", "0.6183"), ("dir", "-1"), ("E", "0.6183"), ("H", "0.3719"), ("n", "5")), "differs"),
            ((("L0", "0.7321"), ("Delta", "0.4137"), ("dir", "1"), ("E", "0.9157"), ("H", "0"), ("n", "2")), "agrees"),
            ((("L0", "-2.1173"), ("Delta", "0.6183"), ("dir", "-1"), ("V", "-0.8629"), ("Omega", "0.2741"), ("n", "2")), None)):
        a = Args(*pairs)
        L0, Dl, d, n = a["L0"], a["Delta"], a.i("dir"), a.i("n")
        derived = "V" in a.v
        if derived:
            E, H = eh_of(L0, mpf(0) if d > 0 else Dl, a["V"], a["Omega"])
        else:
            E, H = a["E"], a["H"]
        En, Hn = E, H
        for k in range(n):
            rev, d1, En, Hn = seg_step(L0, Dl, d, En, Hn)
            assert not rev and d1 == d
        C1, C2 = coefficients_cart(a.f("L0"), a.f("Delta"), d, 0)
        C1, C2 = mpf(C1.numerator) / C1.denominator, mpf(C2.numerator) / C2.denominator
        # condition of E + C1 H^2 S_n (S_n = n terms) and of C2^n H
        Sn = sum(C2 ** (2 * j) for j in range(n))
        cond = (E + abs(C1) * H * H * Sn) / En
        tolE = (8 + 2 * n) * cond + (6 * cond if derived else 0)
        if H == 0:
            row("B.9", a, "E_n", En, 0, route)
            row("B.9", a, "H_n", 0, 0, route)
        else:
            row("B.9", a, "E_n", En, tolE, route)
            row("B.9", a, "H_n", Hn, 4 + 3 * n, route)
        if printed:
            p = E + C1 * H * H * sum(C2 ** (2 * j) for j in range(n + 1))
            assert (abs(p - En) <= mpf(10) ** -40 * En) == (printed == "agrees")
            row("B.9", a, "E_n", p, 0 if H == 0 else tolE, "printed sum of E22 (n + 1 terms) at 50 digits",
                "printed")
    # (B.10): E_f as the limit of the iterated map
    for pairs in ((("L0", "0.7321"), ("Delta", "0.4137"), ("dir", "1"), ("E", "0.9157"), ("H", "0.5813")),
                  (("L0", "-2.1173"), ("Delta", "0.6183"), ("dir", "-1"), ("V", "-0.8629"), ("Omega", "0.2741"))):
        a = Args(*pairs)
        L0, Dl, d = a["L0"], a["Delta"], a.i("dir")
        derived = "V" in a.v
        if derived:
            E, H = eh_of(L0, mpf(0) if d > 0 else Dl, a["V"], a["Omega"])
        else:
            E, H = a["E"], a["H"]
        En, Hn = E, H
        while Hn * Hn > mpf(10) ** -60 * En:
            rev, d1, En, Hn = seg_step(L0, Dl, d, En, Hn)
            assert not rev and d1 == d
        cond = (E + (E - En)) / En
        row("B.10", a, "E_f", En, 8 * cond + (6 * cond if derived else 0),
            "limit of the iterated map (Cartesian collisions) until H^2 < 1e-60 E, 50 digits")
    # (B.11): |C2| < 1
    for (L0, Dl, d) in (("0.7321", "0.4137", 1), ("0.7321", "0.4137", -1), ("-0.3719", "1.2917", -1),
                        ("-3.9688", "5.2917", 1)):
        a = Args(("L0", L0), ("Delta", Dl), ("dir", str(d)))
        C1, C2 = coefficients_cart(a.f("L0"), a.f("Delta"), d, 0)
        row("B.11", a, "converges", int(abs(C2) < 1), 0,
            "exact rational arithmetic: |H'/H| < 1 of the Cartesian collision")
    # (B.12): V_f from the phase state, by iterating the phase map
    for pairs in ((("L0", "0.7321"), ("Delta", "0.4137"), ("V", "0.8629"), ("Omega", "0.5813")),
                  (("L0", "-2.1173"), ("Delta", "0.6183"), ("V", "-0.8629"), ("Omega", "0.2741"))):
        a = Args(*pairs)
        L0, Dl, V, Om = a["L0"], a["Delta"], a["V"], a["Omega"]
        d = 1 if V > 0 else -1
        D = mpf(0) if d > 0 else Dl
        Dfar = Dl - D
        # phase map: flow to the far end (V there from E, H of the body), collide
        while abs(Om) > mpf(10) ** -30 * abs(V):
            E, H = eh_of(L0, D, V, Om)
            assert not seg_reverses(L0, Dl, d, E, H)
            Vm, Omm = state_at(L0, Dfar, E, H, d)
            D, V, Om, _, _ = collide_cart(L0, Dl, Dfar, Vm, Omm)
        # V^2 changes by O(Om^2) = 1e-60 V^2 beyond this point
        cond = (a["V"] ** 2 + abs(V ** 2 - a["V"] ** 2)) / V ** 2
        row("B.12", a, "V_f", V, max(4, 4 * cond), "limit of the iterated phase map (Cartesian collisions), 50 digits")


def do_B_13():
    """Symmetric skate L0 = -Delta/2: the initial ratio X = V^2/Omega^2 (peg
    at D = 0, Omega = 1) whose motion reaches 2E/H^2 = 1 just after the n-th
    collision, by bisection on X of the iterated map (each segment must
    reverse on the way), at 60 digits."""
    route = "bisection on V^2/Omega^2 of the iterated map (Cartesian collisions) landing on 2E/H^2 = 1, 60 digits"
    for (Dl, n) in (("0.7321", "0"), ("1.4137", "3"), ("2.1173", "5")):
        a = Args(("Delta", Dl), ("n", n))
        with mp.workdps(60):
            Dlm = a["Delta"]
            L0 = -Dlm / 2
            N = a.i("n")

            def r_after(X):
                E, H = eh_of(L0, mpf(0), sqrt(X), mpf(1))
                d = 1
                for k in range(N):
                    rev, d, E, H = seg_step(L0, Dlm, d, E, H)
                return 2 * E / H ** 2

            lo, hi = mpf(0), (1 + L0 ** 2) ** 2      # r_0 <= 1 + ... brackets
            while r_after(hi) < 1:
                hi *= 2
            for _ in range(220):
                mid = (lo + hi) / 2
                if r_after(mid) < 1:
                    lo = mid
                else:
                    hi = mid
            X = (lo + hi) / 2
            # every segment on the way reverses (the sequence of (B.13))
            E, H = eh_of(L0, mpf(0), sqrt(X), mpf(1))
            d = 1
            for k in range(N):
                assert seg_reverses(L0, Dlm, d, E, H)
                rev, d, E, H = seg_step(L0, Dlm, d, E, H)
            # C2 of the symmetric skate enters 2n times
            row("B.13", a, "V2_over_Omega2", X, 6 + 4 * N, route)


def do_B_14():
    for (pairs, loss_zero) in (((("L0", "0.7321"), ("Delta", "0.4137"), ("Vstar", "-1.0923"), ("theta", "0.3719"),
                                 ("tau", "0.2741"), ("H", "0.5813")), False),
                               ((("L0", "-0.3719"), ("Delta", "1.2917"), ("Vstar", "0.8629")), True)):
        a = Args(*pairs)
        Vs = a.f("Vstar")
        d = 1 if Vs > 0 else -1
        r = "exact rational arithmetic: the straight-line motion (H* = 0)"
        row("B.14", a, "E", Vs * Vs / 2, 1, r)
        row("B.14", a, "H", 0, 0, r)
        row("B.14", a, "tau_star", a.f("Delta") / abs(Vs), 1, r + ", time Delta/|V*| between collisions")
        # the energy the collision takes at the given H: Cartesian impulse,
        # state at the end the peg leaves with that H and V = 1
        H = a.f("H") if "H" in a.v else Fraction(0)
        L0f, Dlf = a.f("L0"), a.f("Delta")
        Dm = Dlf if d > 0 else Fraction(0)
        l = L0f + Dm
        Om = H / (1 + l * l)
        E0, _ = eh_of(L0f, Dm, Fraction(1), Om)
        _, _, _, E1, _ = collide_cart(L0f, Dlf, Dm, Fraction(1), Om)
        loss = E0 - E1
        assert (loss == 0) == loss_zero
        row("B.14", a, "loss", loss, 0 if loss == 0 else 10,
            "exact rational arithmetic: kinetic energy lost in the Cartesian impulse at that H")


def do_B_15_B_16():
    route = ("rho = 0: straight-line motion of the point mass, its angular momentum about the new peg "
             "(plane geometry, 50 digits)")
    for pairs in ((("L0", "-0.4137"), ("dir", "1"), ("E", "0.6183"), ("H", "0.2913"), ("theta", "0.3719"),
                   ("tau", "1.0923")),
                  (("L0", "0.7321"), ("dir", "-1"), ("E", "0.9157"), ("H", "0.5813")),
                  (("L0", "-2.1173"), ("dir", "1"), ("E", "0.6183"), ("H", "-1.7331")),
                  (("L0", "-0.6183"), ("dir", "-1"), ("V", "-0.8629"), ("Omega", "0.5417"))):
        a = Args(*pairs)
        L0, d = a["L0"], a.i("dir")
        derived = "V" in a.v
        if derived:
            l = L0 + (0 if d > 0 else 1)
            E = (a["V"] ** 2 + (l * a["Omega"]) ** 2) / 2
            H = l * l * a["Omega"]
        else:
            E, H = a["E"], a["H"]
        th0 = a.get("theta", 0)
        rev, d1, E1, H1, dth, dtau = massless_step(L0, d, E, H, th0)
        # conversion of V, Omega to E, H (3 and 2 roundings) in the derived row
        kap = kappas(lambda x: list(massless_step(L0, d, x[0], x[1], th0)[3:6]), [E, H]) if derived else [0, 0, 0]
        row("B.15", a, "E_next", E1, 4 if derived else 0, route)
        row("B.15", a, "H_next", H1, 2 + 3 * kap[0], route)
        row("B.15", a, "dtheta", dth, 4 + 3 * kap[1], route)
        row("B.15", a, "dtau", dtau, 4 + 3 * kap[2], route)
        row("B.15", a, "reversal", rev, 0, route)
        row("B.15", a, "period2", massless_period2(L0), 0,
            "two steps of the point-mass geometry return E, H and direction (3 states)")
    # (B.16): angular momentum of the point mass about the new and old pegs
    for (L0, Dp, rev, printed) in (("-0.4137", "0", "1", "differs"), ("-0.4137", "1", "0", "agrees"),
                                   ("0.7321", "0", "0", "agrees"), ("0.7321", "1", "1", "differs")):
        a = Args(("L0", L0), ("Dplus", Dp), ("reversal", rev))
        L0f, Dpf, rv = a.f("L0"), a.f("Dplus"), a.i("reversal")
        Dm = Dpf if rv else 1 - Dpf           # the end the peg leaves
        # theta = 0: G = (L0 + Dm, 0) from the old peg at the origin, any v
        v = (Fraction(3, 7), Fraction(5, 11))
        lm = L0f + Dm
        G = (lm, Fraction(0))
        Pn = (G[0] - (L0f + 1 - Dm), Fraction(0))
        Hm = cross(G, v)
        Hp = cross((G[0] - Pn[0], G[1] - Pn[1]), v)
        C2 = Hp / Hm
        row("B.16", a, "C2", C2, 3,
            "exact rational arithmetic: angular momentum of the point mass about the new and old pegs")
        p = L0f * (L0f + 1) / (L0f + (1 - Dpf)) ** 2
        assert (p == C2) == (printed == "agrees")
        row("B.16", a, "C2", p, 4, "printed (B.16) of E17, exact rationals", "printed")


def main():
    mp.dps = DPS
    steps = [do_2_1, do_units, do_2_4, do_3_1, do_3_3_3_4, do_3_6_3_7, do_3_8, do_3_9,
             do_stability, do_4_1, do_smooth, do_B_1_B_2, do_3_5, do_B_3_B_4, do_B_5_B_8,
             do_B_6, do_B_7, do_B_9_to_B_12, do_B_13, do_B_14, do_B_15_B_16]
    only = sys.argv[1:]
    for st in steps:
        if only and st.__name__ not in only:
            continue
        st()
        mp.dps = DPS
    with open(REGISTRY) as f:
        order = [line[2:].strip() for line in f if line.startswith("@ ")]
    ROWS.sort(key=lambda r: order.index(r[0]))          # stable within a label
    out = OUT if not only else OUT + ".partial"
    with open(out, "w") as f:
        f.write("label\targs\toutput\twhich\treference\ttol_eps\troute\n")
        for r in ROWS:
            assert len(r) == 7 and all("\t" not in x and "\n" not in x for x in r)
            f.write("\t".join(r) + "\n")
    labels = set(r[0] for r in ROWS)
    if not only:
        missing = [l for l in order if l not in labels]
        assert not missing, missing
    print("%s: %d rows, %d labels" % (out, len(ROWS), len(labels)))


if __name__ == "__main__":
    main()
