"""The documentation works: the README's and the manual's commands, the
manual's worked example (it is python/examples/fig3.py, and it runs, with
Matplotlib when installed, without it otherwise), and every function has a
docstring naming it."""
import os
import re
import subprocess
import sys

import pytest

import chaplygin
from chaplygin import _generated
from conftest import src, build

GROUPS = ('smooth', 'discrete', 'massless', 'printed', 'sweep')


def env():
    e = dict(os.environ)
    e['PYTHONPATH'] = os.pathsep.join(
        [build('python')] + [p for p in e.get('PYTHONPATH', '').split(
            os.pathsep) if p])
    return e


def test_readme_command():
    """The README's import line prints 21/25 within 2 ulps."""
    with open(src('README')) as fh:
        readme = fh.read()
    m = re.search(r'python3 -c "(import chaplygin;[^"]*)"', readme)
    assert m, 'the README shows no python3 -c "import chaplygin; ..."'
    r = subprocess.run([sys.executable, '-c', m.group(1)], env=env(),
                       capture_output=True, text=True, cwd='/')
    assert r.returncode == 0, r.stderr
    v = float(r.stdout.strip())
    assert abs(v - 21 / 25) <= 2 * 2 ** -52 * (21 / 25)


def texi_example(path, after):
    with open(path) as fh:
        text = fh.read()
    i = text.index(after)
    j = text.index('@example\n', i) + len('@example\n')
    k = text.index('@end example', j)
    code = text[j:k]
    return code.replace('@{', '{').replace('@}', '}').replace('@@', '@')


def test_manual_example_is_the_file():
    path = src('doc', 'python.texi')
    if not os.path.exists(path):
        pytest.skip('no doc/python.texi')
    with open(src('python', 'examples', 'fig3.py')) as fh:
        assert texi_example(path, '@node Python example') == fh.read()


@pytest.mark.parametrize('name', ['fig3', 'fig2a'])
def test_examples_run(name, tmp_path):
    out = tmp_path / (name + '.png')
    r = subprocess.run([sys.executable, src('python', 'examples',
                                            name + '.py'), str(out)],
                       env=dict(env(), MPLBACKEND='Agg'), capture_output=True,
                       text=True, cwd=str(tmp_path), timeout=300)
    assert r.returncode == 0, r.stderr
    try:
        import matplotlib  # noqa: F401
        assert out.exists() and out.stat().st_size > 1000
    except ImportError:
        assert 'Matplotlib not installed' in r.stdout
    if name == 'fig3':
        assert r.stdout.startswith('forward: 1764 backward: 2236 spin: 0')


def test_docstrings():
    for cname, (group, pyname) in _generated.FUNCTIONS.items():
        mod = getattr(chaplygin, group) if group else chaplygin
        f = getattr(mod, pyname)
        doc = f.__doc__ or ''
        first = doc.split('\n', 1)[0]
        assert first.startswith((group + '.' if group else '') + pyname +
                                '('), (cname, first)
        assert cname in doc
    for mod in [chaplygin] + [getattr(chaplygin, g) for g in GROUPS] + \
            [chaplygin.scene, chaplygin.vectorised]:
        assert mod.__doc__ and len(mod.__doc__) > 100, mod
    assert 'errors=' in chaplygin.vectorised.__doc__
