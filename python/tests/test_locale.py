"""A comma-decimal locale set in the Python process (de_DE.UTF-8, which
changes LC_NUMERIC for the C extension too): run_scene and eq give the
same numbers as under the C locale (issue 26: they were garbled, or every
decimal value was "not a number").  The locale is made with localedef
into a temporary directory (LOCPATH); without localedef and Debian's
locale sources (package locales) the test is skipped and says why."""
import locale
import os
import subprocess

import numpy as np
import pytest

import chaplygin as c
from conftest import src

SCENE = {'scene': {'model': 'discrete'},
         'parameters': {'L0': 1, 'Delta': '1/3'},
         'initial': {'V': 1.0, 'Omega': 0.5, 'theta': 0.25},
         'run': {'collisions': 8, 'method': 'quadrature',
                 'tolerance': 1e-10}}


@pytest.fixture
def german(tmp_path):
    r = subprocess.run(['localedef', '-i', 'de_DE', '-f', 'UTF-8',
                        str(tmp_path / 'de_DE.UTF-8')], capture_output=True)
    if r.returncode != 0:
        pytest.skip('no de_DE.UTF-8 here (localedef and the package '
                    'locales): %s' % r.stderr.decode(errors='replace')[:80])
    old_path = os.environ.get('LOCPATH')
    old = locale.setlocale(locale.LC_ALL)
    os.environ['LOCPATH'] = str(tmp_path)
    try:
        locale.setlocale(locale.LC_ALL, 'de_DE.UTF-8')
    except locale.Error as e:
        pytest.skip('de_DE.UTF-8 does not load: %s' % e)
    assert locale.localeconv()['decimal_point'] == ','
    try:
        yield
    finally:
        locale.setlocale(locale.LC_ALL, old)
        if old_path is None:
            del os.environ['LOCPATH']
        else:
            os.environ['LOCPATH'] = old_path


def runs():
    return (c.run_scene(SCENE), c.run_scene(src('scenes', 'fig6.ini')),
            c.eq('3.10', L0=1, Delta=0.5, dir=-1).sigma4,
            c.eq('3.5', L0=1, Delta='1/3', V=1, Omega=0.5, method='ode',
                 tol='1e-10').outputs)


def test_run_scene_and_eq_under_de_DE(german):
    a_dict, a_file, a_s4, a_35 = runs()
    locale.setlocale(locale.LC_ALL, 'C')
    b_dict, b_file, b_s4, b_35 = runs()
    for a, b in ((a_dict, b_dict), (a_file, b_file)):
        assert list(a) == list(b)
        for k in a:
            assert np.array_equal(a[k], b[k]), k
    assert a_s4 == b_s4 and a_35 == b_35
    # the numbers themselves: E of row 0 is (3.3) at the start
    E = c.discrete.energy(1, 0, 1, 0.5)
    assert a_dict['E'][0] == E and a_dict['theta'][0] == 0.25


def test_atlas_under_de_DE(german):
    """chaplygin.atlas: the scene's decimal numbers, its effective scene's
    text (which Dask tasks carry) and the values, as under the C locale."""
    pytest.importorskip('xarray')
    pytest.importorskip('dask')
    scene = {'scene': {'model': 'discrete'},
             'parameters': {'L0': -0.5, 'Delta': 1.0},
             'run': {'collisions': 1000},
             'sweep': {'kind': 'atlas', 'x': 'V', 'x_min': 0.05,
                       'x_max': 0.5, 'nx': 7, 'y': 'Omega', 'y_min': 0.25,
                       'y_max': 1.5, 'ny': 5}}
    a = c.atlas(scene), c.atlas(scene, chunks=(2, 3)).compute(
        scheduler='synchronous')
    locale.setlocale(locale.LC_ALL, 'C')
    b = c.atlas(scene)
    for x in a:
        assert x.attrs['scene'] == b.attrs['scene']
        assert 'x_min = 0.05' in x.attrs['scene']
        for k in list(x.variables):
            assert np.array_equal(x[k].values, b[k].values), k
