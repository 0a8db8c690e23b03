"""The hand-written wrappers of the smooth sleigh's path
(smooth.path_advance, smooth.path): their semantics, and C against an
independent quadrature in Python (composite Gauss-Legendre of V (cos theta,
sin theta) from smooth.at_time, NumPy's nodes, another rule and partition
than the library's Gauss-Kronrod)."""
import math

import numpy as np
import pytest

import chaplygin as c

MOTIONS = [(0.5, [0.0, 1.0, 0.0, 1.0]),        # reverses? spins, recedes
           (-1.3, [0.2, -0.7, 0.4, 2.0]),      # through a reversal
           (2.0, [0.0, 0.3, 1.0, -0.1]),
           (0.5, [0.0, 1.5, 0.3, 0.0])]        # Omega = 0: a line


def reference_path(m, taus, panels=400, nodes=20):
    """C(tau) by composite Gauss-Legendre on [0, tau_max], the panels
    summed exactly (math.fsum)."""
    x, w = np.polynomial.legendre.leggauss(nodes)
    edges = np.linspace(0.0, taus[-1], panels + 1)
    out = []
    for t in taus:
        parts = []
        for a, b in zip(edges[:-1], edges[1:]):
            if a >= t:
                break
            b = min(b, t)
            ts = 0.5 * (b - a) * x + 0.5 * (a + b)
            q = np.array([c.smooth.at_time(m, s) for s in ts])
            v = q[:, 1]
            parts.append(0.5 * (b - a) * np.array(
                [np.dot(w, v * np.cos(q[:, 2])), np.dot(w, v * np.sin(q[:, 2]))]))
        out.append([math.fsum(p[0] for p in parts),
                    math.fsum(p[1] for p in parts)])
    return np.array(out)


@pytest.mark.parametrize('L,q0', MOTIONS)
def test_path_against_gauss_legendre(L, q0):
    m = c.smooth.motion_init(L, q0)
    taus = np.array([0.0, 0.25, 1.0, 2.5, 4.0])
    C, G = c.smooth.path(m, taus)
    ref = reference_path(m, taus)
    # the library promises 2.2 eps of the arc length (C tests); the
    # reference is converged to rounding (20 nodes on panels of at most
    # 0.01 of an analytic integrand), each panel rounded to ~1 eps and the
    # panels summed exactly: 4.5 eps of max(1, |C|) holds both (measured
    # 0.9 eps at most)
    scale = max(1.0, float(np.max(np.abs(ref))))
    assert np.max(np.abs(C - ref)) <= 1e-15 * scale
    th = np.array([c.smooth.at_time(m, t)[2] for t in taus])
    assert np.allclose(G, C + L * np.c_[np.cos(th), np.sin(th)],
                       rtol=0, atol=1e-15 * scale)


def test_line():
    # Omega = 0: C = V0 tau (cos theta0, sin theta0) exactly in exact
    # arithmetic (the library's closed form for the line)
    m = c.smooth.motion_init(0.5, [0.0, 1.5, 0.3, 0.0])
    C, _ = c.smooth.path(m, [2.0])
    assert C[0] == pytest.approx([3.0 * np.cos(0.3), 3.0 * np.sin(0.3)],
                                 rel=4e-16)


def test_advance_is_the_walk_and_leaves_its_input():
    m = c.smooth.motion_init(-1.3, [0.2, -0.7, 0.4, 2.0])
    p0 = c.smooth.path_init(0.0, [1.0, -2.0])
    keep = p0.copy()
    p, rows = p0, []
    for t in (0.5, 1.0, 3.0):
        p, G = c.smooth.path_advance(m, p, t)
        rows.append((p.C, G))
    assert p0 == keep
    C, G = c.smooth.path(m, [0.5, 1.0, 3.0], C0=(1.0, -2.0))
    for i, (Ci, Gi) in enumerate(rows):
        assert tuple(C[i]) == Ci and tuple(G[i]) == tuple(Gi)


def test_errors():
    m = c.smooth.motion_init(0.5, [0.0, 1.0, 0.0, 1.0])
    p, _ = c.smooth.path_advance(m, c.smooth.path_init(), 1.0)
    with pytest.raises(c.ChaplyginError):
        c.smooth.path_advance(m, p, 0.5)       # backwards in time
    r = c.smooth.path_advance(m, p, 0.5, errors='return')
    assert r.status != 0 and r.path == p and np.all(np.isnan(r.G))
    r = c.smooth.path(m, [1.0, 0.5, 2.0], errors='return')
    assert r.status != 0 and not np.isnan(r.C[0, 0])
    assert np.all(np.isnan(r.C[1:])) and np.all(np.isnan(r.G[1:]))
    with pytest.raises(TypeError):
        c.smooth.path_advance(p, m, 1.0)
    with pytest.raises(TypeError):
        c.smooth.path_advance(m, p, np.array([1.0, 2.0]))
    with pytest.raises(ValueError):
        c.smooth.path(m, [1.0], C0=(1.0, 2.0, 3.0))
    with pytest.raises(ValueError):
        c.smooth.path(m, [[1.0]])
