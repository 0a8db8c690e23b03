"""Scenes from Python: run_scene gives the columns of `chaplygin run`, the
same names and the same numbers (the program's CSV, %.17g, read back
exactly), for every scene of scenes/, from the file and from a dict; and
the scenes' numbers equal the package's own vectorised calls (orbits,
fates, sweeps)."""
import configparser
import csv
import glob
import io
import math
import os
import subprocess

import numpy as np
import pytest

import chaplygin as c
from chaplygin import discrete as d
from conftest import src

SCENES = sorted(glob.glob(src('scenes', '*.ini')))


def program_csv(program, path, compare=False):
    r = subprocess.run([program, 'run', path] + (['--compare'] if compare
                                                  else []),
                       capture_output=True, text=True,
                       env=dict(os.environ, CHAPLYGIN_NO_PROGRESS='1'))
    assert r.returncode == 0, r.stderr
    # the provenance lines ('#') are comments
    rows = list(csv.reader(line for line in io.StringIO(r.stdout)
                           if not line.startswith('#')))
    return rows[0], rows[1:]


def scene_dict(path):
    cp = configparser.ConfigParser(inline_comment_prefixes=(';',))
    cp.optionxform = str
    cp.read(path)
    return {sec: dict(cp[sec]) for sec in cp.sections()}


def check_same(cols, header, rows):
    assert list(cols) == header
    for j, name in enumerate(header):
        col = cols[name]
        assert len(col) == len(rows)
        for i, row in enumerate(rows):
            text = row[j]
            if text == '':
                assert np.ma.is_masked(col[i]), (name, i)
                continue
            got = col[i]
            if name == 'status':
                # the program prints the name, run_scene the number
                assert col.dtype == np.int64 and got == c.Status[text]
            elif name in c.scene.INTEGER_COLUMNS:
                assert col.dtype == np.int64 and got == int(text)
            else:
                want = float(text)
                assert got == want or (math.isnan(got) and math.isnan(want))


@pytest.mark.parametrize('path', SCENES, ids=os.path.basename)
def test_scene_file_equals_program(path, program):
    header, rows = program_csv(program, path)
    check_same(c.run_scene(path), header, rows)


@pytest.mark.parametrize('path', SCENES, ids=os.path.basename)
def test_scene_dict_equals_file(path):
    a = c.run_scene(path)
    b = c.run_scene(scene_dict(path))
    assert list(a) == list(b)
    for k in a:
        assert np.array_equal(np.ma.getdata(a[k]), np.ma.getdata(b[k]),
                              equal_nan=True)


def test_compare_companion(program):
    for path in SCENES:
        if 'compare' not in open(path).read():
            continue
        header, rows = program_csv(program, path, compare=True)
        check_same(c.run_scene(path, compare=True), header, rows)
        break
    else:
        pytest.skip('no scene with compare = smooth')


def test_example_scene_equals_orbit():
    cols = c.run_scene(src('scenes', 'example.ini'))
    sc = scene_dict(src('scenes', 'example.ini'))
    L0 = float(sc['parameters']['L0'])
    from fractions import Fraction
    Delta = float(Fraction(sc['parameters']['Delta']))
    sys_ = d.init(L0, Delta)
    V, Om = float(sc['initial']['V']), float(sc['initial']['Omega'])
    st = d.state_from_phase(sys_, [0.0 if V > 0 else Delta, V, 0.0, Om])
    orb = d.orbit(sys_, st, int(sc['run']['collisions']))
    o = c.as_columns(orb)
    for name in ('E', 'H', 'theta', 'tau', 'peg_x', 'peg_y'):
        assert np.array_equal(cols[name], o[name]), name
    assert np.array_equal(cols['D'], np.where(o['dir'] > 0, 0.0, Delta))


def test_fig3_equals_fate_phase():
    cols = c.run_scene(src('scenes', 'fig3.ini'))
    sc = scene_dict(src('scenes', 'fig3.ini'))
    sys_ = d.init(float(sc['parameters']['L0']),
                  float(sc['parameters']['Delta']))
    V = cols['V0']
    q = np.stack([np.where(V > 0, 0.0, sys_.Delta), V, np.zeros_like(V),
                  np.full_like(V, float(sc['initial']['Omega']))], axis=1)
    f = d.fate_phase(sys_, q, int(sc['run']['collisions']))
    assert np.array_equal(f['kind'], cols['fate'])
    assert np.array_equal(f['collisions'], cols['collisions'])
    assert np.array_equal(f['reversals'], cols['reversals'])
    assert np.array_equal(f['E_final'], cols['E_final'])
    assert np.array_equal(f['V_final'], cols['V_final'])
    # and the library's own grid loop
    b = d.basins(sys_, float(sc['initial']['Omega']), V[0], V[-1], len(V),
                 int(sc['run']['collisions']))
    assert np.array_equal(b['kind'], cols['fate'])
    assert np.array_equal(b['E_final'], cols['E_final'])


def test_fig2_equals_sweeps():
    a = c.run_scene(src('scenes', 'fig2a.ini'))
    ys = np.unique(a['y'])
    x = a['x'][a['y'] == ys[0]]
    sc = scene_dict(src('scenes', 'fig2a.ini'))
    s4 = c.sweep.sigma4(x, ys, int(sc['sweep']['dir']))
    assert np.array_equal(s4.reshape(-1), np.ma.getdata(a['sigma4']))
    b = c.run_scene(src('scenes', 'fig2b.ini'))
    xs = b['x'][:np.argmax(b['y'] != b['y'][0])]
    yb = np.unique(b['y'])
    region = c.sweep.stability(xs, yb)
    assert np.array_equal(region.reshape(-1), b['region'])


def test_to_ini_and_values():
    text = c.scene.to_ini({'scene': {'model': 'discrete'},
                           'parameters': {'L0': 1, 'Delta': 1 / 3},
                           'run': {'outputs': ['E', 'H']}})
    assert 'Delta = 0.3333333333333333\n' in text
    assert 'outputs = E,H\n' in text
    with pytest.raises(ValueError):
        c.scene.to_ini({'scene': {'model': 'discrete\n[run]'}})
    with pytest.raises(ValueError):
        c.scene.to_ini({'sce]ne': {}})
    with pytest.raises(TypeError):
        c.scene.to_ini({'scene': {'model': object()}})
    with pytest.raises(TypeError):
        c.run_scene(42)
    with pytest.raises(ValueError):
        c.run_scene('a\0b')
    # exact values: 1/3 as text and as the double give the same run
    base = {'scene': {'model': 'discrete'},
            'parameters': {'L0': 1, 'Delta': '1/3'},
            'initial': {'V': 1, 'Omega': 0.5}, 'run': {'collisions': 3}}
    r1 = c.run_scene(base)
    base['parameters']['Delta'] = 1 / 3
    r2 = c.run_scene(base)
    assert all(np.array_equal(r1[k], r2[k]) for k in r1)


def test_bounds():
    """A scene's bounds hold in run_scene as in the program: a stop
    condition ends a run of 1e9 collisions at once, a run beyond max_rows
    is refused."""
    sc = {'scene': {'model': 'discrete'},
          'parameters': {'L0': 1, 'Delta': '1/3'},
          'initial': {'V': 1, 'Omega': 0.5},
          'run': {'collisions': '1e9', 'stop_H': '1e-9', 'every': 10,
                  'outputs': ['E', 'H']}}
    cols = c.run_scene(sc)
    n, E, H = cols['n'], cols['E'], cols['H']
    assert n[0] == 0 and all(n[1:-1] % 10 == 0)
    assert abs(H[-1]) < 1e-9 * np.sqrt(2 * E[-1])
    assert abs(H[-2]) >= 1e-9 * np.sqrt(2 * E[-2])
    del sc['run']['stop_H']
    with pytest.raises(c.SceneError, match='max_rows'):
        c.run_scene(sc)


@pytest.mark.parametrize('model,V,Omega,K', [
    ('discrete', 1e-300, 1e-300, 996), ('discrete', 1e200, 1e200, -664),
    ('massless', 1e-300, 1e-300, 996), ('smooth', 1e-300, 1e-300, 996)])
def test_tiny_and_huge_states(model, V, Omega, K, program, tmp_path):
    """Issue 16: a tiny or huge state runs; run_scene gives the program's
    columns (a number beyond the doubles as float() reads it, with a
    RuntimeWarning), and the columns that are in range agree within 4 eps
    with those of the run with V, Omega times 2^K, scaled back exactly
    (the program's own test, tools/test-scaled.sh, compares every column,
    E too, with MPFR)."""
    def scene(v, om, duration):
        sc = {'scene': {'model': model},
              'parameters': {'L': 1} if model == 'smooth'
              else {'L0': -0.3, 'Delta': 1},
              'initial': {'V': v, 'Omega': om},
              'run': {'outputs': 'E,H,theta,tau,V,Omega'}}
        if model == 'smooth':
            sc['run']['duration'] = duration
            sc['run']['samples'] = 4
        else:
            sc['run']['collisions'] = 6
        if model == 'massless':
            del sc['parameters']['Delta']
        return sc
    a = scene(V, Omega, 1e9)
    path = tmp_path / 'a.ini'
    path.write_text(c.scene.to_ini(a))
    header, rows = program_csv(program, str(path))
    with pytest.warns(RuntimeWarning, match='E'):
        cols = c.run_scene(a)
    check_same(cols, header, rows)
    b = c.run_scene(scene(math.ldexp(V, K), math.ldexp(Omega, K),
                          math.ldexp(1e9, -K)))
    degree = {'V': 1, 'Omega': 1, 'H': 1, 'E': 2, 'tau': -1}
    for name in ('H', 'theta', 'tau', 'V', 'Omega'):
        want = np.ldexp(b[name], -degree.get(name, 0) * K)
        # 4 eps, as tools/test-scaled.sh (the two runs round alike)
        assert np.allclose(cols[name], want, rtol=4 * 2.0 ** -52, atol=0), \
            name
