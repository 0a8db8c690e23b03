# conftest.py -- shared fixtures of the Python tests, and TAP output for
# the automake test harness (CHAPLYGIN_TAP=1, set by python/run-pytest).
import os
import subprocess
import types

import pytest

SRCDIR = os.environ.get('CHAPLYGIN_SRCDIR') or \
    os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..'))
BUILDDIR = os.environ.get('CHAPLYGIN_BUILDDIR') or SRCDIR


def src(*parts):
    return os.path.join(SRCDIR, *parts)


def build(*parts):
    return os.path.join(BUILDDIR, *parts)


def child_env():
    """The environment of a child Python that imports the build tree's
    package first."""
    e = dict(os.environ)
    e['PYTHONPATH'] = os.pathsep.join(
        [build('python')] + [p for p in e.get('PYTHONPATH', '').split(
            os.pathsep) if p])
    return e


@pytest.fixture(scope='session')
def srcdir():
    return SRCDIR


@pytest.fixture(scope='session')
def program():
    """The command-line program of the build tree."""
    path = build('tools', 'chaplygin')
    if not os.access(path, os.X_OK):
        pytest.skip('tools/chaplygin not built')
    return path


@pytest.fixture(scope='session')
def cvalues():
    """The values of the C functions at the reference tables' inputs, from
    python/tests/cvalues (C, linked with the library): {table: [row]},
    row a dict of floats (exact: printed as hex floats)."""
    path = build('python', 'tests', 'cvalues')
    if not os.access(path, os.X_OK):
        pytest.skip('python/tests/cvalues not built')
    out = subprocess.run([path], check=True, capture_output=True,
                         text=True).stdout
    tables = {}
    for line in out.splitlines():
        table, *fields = line.split()
        row = {}
        for f in fields:
            k, v = f.split('=', 1)
            row[k] = float.fromhex(v) if ('p' in v or 'n' in v) \
                else int(v)
        tables.setdefault(table, []).append(row)
    return tables


# ---- TAP ---------------------------------------------------------------

_TAP = []


def pytest_runtest_logreport(report):
    if not os.environ.get('CHAPLYGIN_TAP'):
        return
    if report.when == 'call' or (report.when == 'setup' and
                                 (report.failed or report.skipped)) or \
            (report.when == 'teardown' and report.failed):
        name = report.nodeid.split('::', 1)[-1].replace('#', '_')
        if report.skipped:
            reason = report.longrepr[2] if isinstance(report.longrepr, tuple)\
                else ''
            _TAP.append('ok %%d - %s # SKIP %s' % (name, reason))
        elif report.failed:
            _TAP.append('not ok %%d - %s%s' % (
                name, '' if report.when == 'call' else ' (%s)' % report.when))
        else:
            _TAP.append('ok %%d - %s' % name)


def pytest_unconfigure(config):
    if not os.environ.get('CHAPLYGIN_TAP'):
        return
    lines = ['1..%d' % len(_TAP)] + [l.replace('%d', str(i + 1), 1)
                                     for i, l in enumerate(_TAP)]
    if not _TAP:
        lines = ['1..0 # SKIP no tests ran']
    print('\n' + '\n'.join(lines), flush=True)


def public_functions():
    """{name: function}: the public callables of chaplygin and of its
    public modules (their __all__; classes and modules aside), each once."""
    import chaplygin as c
    mods = [('', c)] + [(n, m) for n, m in vars(c).items()
                        if isinstance(m, types.ModuleType)
                        and m.__name__ == 'chaplygin.' + n   # not lib
                        and not n.startswith('_')]
    out, seen = {}, set()
    for prefix, mod in mods:
        for n in getattr(mod, '__all__', []) if prefix else dir(mod):
            f = getattr(mod, n)
            if n.startswith('_') or isinstance(f, (type, types.ModuleType)) \
                    or not callable(f) or id(f) in seen \
                    or not getattr(f, '__module__', '').startswith(
                        'chaplygin'):
                continue
            seen.add(id(f))
            out[prefix + '.' + n if prefix else n] = f
    return out
