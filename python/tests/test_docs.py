"""The documentation works: the README's and the manual's commands, the
manual's worked example (it is python/examples/fig3.py, and it runs, with
Matplotlib when installed, without it otherwise), and every function has a
docstring naming it."""
import ast
import inspect
import os
import re
import subprocess
import sys
import types

import pytest

import chaplygin
from chaplygin import _generated
from conftest import src, child_env, public_functions

GROUPS = ('smooth', 'discrete', 'massless', 'printed', 'sweep')


def test_readme_command():
    """The README's import line prints 21/25 within 2 ulps."""
    with open(src('README')) as fh:
        readme = fh.read()
    m = re.search(r'python3 -c "(import chaplygin;[^"]*)"', readme)
    assert m, 'the README shows no python3 -c "import chaplygin; ..."'
    r = subprocess.run([sys.executable, '-c', m.group(1)], env=child_env(),
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


def texi_doctests(path):
    """The @example blocks of the Texinfo file PATH that are >>> sessions
    (Texinfo's @{ @} @@ unescaped)."""
    with open(path) as fh:
        text = fh.read()
    blocks = re.findall(r'@example\n(.*?)@end example', text, re.S)
    return [b.replace('@{', '{').replace('@}', '}').replace('@@', '@')
            for b in blocks if b.lstrip().startswith('>>>')]


def test_manual_sessions(monkeypatch):
    """The Python chapter's >>> sessions print what the manual shows, in
    order, from the source directory (scenes/example.ini)."""
    import doctest
    path = src('doc', 'python.texi')
    if not os.path.exists(path):
        pytest.skip('no doc/python.texi')
    blocks = texi_doctests(path)
    assert len(blocks) >= 3
    monkeypatch.chdir(src())
    test = doctest.DocTestParser().get_doctest(   # one session: the
        '\n'.join(blocks), {'chaplygin': chaplygin},  # names carry over
        'python.texi', path, 0)
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    out = []
    runner.run(test, out=out.append)
    assert runner.summarize(verbose=False).attempted >= 10
    assert not out, ''.join(out)


@pytest.mark.parametrize('name', ['fig3', 'fig2a'])
def test_examples_run(name, tmp_path):
    out = tmp_path / (name + '.png')
    r = subprocess.run([sys.executable, src('python', 'examples',
                                            name + '.py'), str(out)],
                       env=dict(child_env(), MPLBACKEND='Agg'), capture_output=True,
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


def doc_texts():
    """(where, text) of the docs that show calls: the package's and its
    modules' docstrings, every public function's, python/README and the
    Python chapter of the manual (Texinfo escapes undone)."""
    out = [('chaplygin', chaplygin.__doc__)]
    for name, mod in vars(chaplygin).items():
        if isinstance(mod, types.ModuleType) and \
                mod.__name__ == 'chaplygin.' + name:
            out.append((mod.__name__, mod.__doc__ or ''))
    for name, f in public_functions().items():
        out.append((name + '()', f.__doc__ or ''))
    for path in (src('python', 'README'), src('doc', 'python.texi')):
        if os.path.exists(path):
            with open(path) as fh:
                out.append((path, fh.read().replace('@{', '{').replace(
                    '@}', '}').replace('@@', '@')))
    return out


CALL = re.compile(r'(?<![\w.])((?:chaplygin\.)?(?:[a-z]+\.)?[a-z_0-9]+)'
                  r'\(([^()]*)\)')


def test_signatures_in_docs():
    """Every call of a public function that the docs show names real
    keyword parameters, and where it shows a parameter with a value in a
    signature (the positional arguments named as the first parameters:
    f(a, b, c=1)), the function has that default: a required parameter is
    never shown as optional (sweep.sigma4(x, y, dir=1) was, dir having no
    default)."""
    public = public_functions()
    seen, wrong = 0, []
    for where, text in doc_texts():
        for m in CALL.finditer(text):
            name = m.group(1)[len('chaplygin.'):] \
                if m.group(1).startswith('chaplygin.') else m.group(1)
            f = public.get(name)
            if f is None:
                continue
            try:
                call = ast.parse(m.group(0).replace(m.group(1), 'f', 1),
                                 mode='eval').body
            except SyntaxError:
                continue
            if not isinstance(call, ast.Call):
                continue
            params = inspect.signature(f).parameters
            # a signature: the positional arguments are the first
            # parameters by name (not a call such as step(sys, st))
            form = [getattr(a, 'id', None) for a in call.args] == \
                list(params)[:len(call.args)]
            anykw = any(p.kind == p.VAR_KEYWORD for p in params.values())
            seen += 1
            for kw in call.keywords:
                p = params.get(kw.arg)
                if p is None and kw.arg is not None and not anykw:
                    wrong.append('%s: %s: no parameter %s'
                                 % (where, m.group(0), kw.arg))
                elif form and isinstance(kw.value, ast.Constant) and \
                        p.default != kw.value.value:
                    wrong.append('%s: %s: %s has %s' % (
                        where, m.group(0), kw.arg,
                        'no default' if p.default is p.empty
                        else 'the default %r' % (p.default,)))
    assert seen > 40, seen
    assert not wrong, '\n'.join(wrong)
