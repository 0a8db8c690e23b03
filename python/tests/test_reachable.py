"""Every function, struct and constant of lib/chaplygin.h is reachable from
Python, read from the header itself (not from what python/gen.py made of
it): a function added to the header without a Python wrapper -- one that
python/gen.py cannot classify, e.g. with a size_t buffer length -- fails
here until it has one."""
import re

import pytest

import chaplygin
from conftest import src

GROUPS = ('smooth', 'discrete', 'massless', 'printed', 'sweep')


def header():
    with open(src('lib', 'chaplygin.h')) as fh:
        text = fh.read()
    text = re.sub(r'/\*.*?\*/', ' ', text, flags=re.S)
    return text


def header_functions():
    return sorted(set(re.findall(r'\b(chaplygin_[a-z0-9_]+)\s*\(', header())))


def python_object(cname):
    rest = cname[len('chaplygin_'):]
    head, _, tail = rest.partition('_')
    if head in GROUPS and tail:
        return getattr(getattr(chaplygin, head), tail, None)
    return getattr(chaplygin, rest, None)


FUNCTIONS = header_functions()


def test_header_read():
    assert len(FUNCTIONS) >= 89
    assert 'chaplygin_discrete_sigma4' in FUNCTIONS


@pytest.mark.parametrize('cname', FUNCTIONS)
def test_function_reachable(cname):
    assert hasattr(chaplygin.lib, cname), 'not in the extension module'
    obj = python_object(cname)
    assert obj is not None, 'no Python wrapper for %s' % cname
    assert callable(obj)
    # the wrapper says which C function it calls
    doc = obj.__doc__ or ''
    assert ('C: int %s(' % cname in doc or 'C: int %s (' % cname in doc
            or 'C: const char *%s(' % cname in doc), doc[:200]
    assert getattr(obj, '__c_function__', cname) == cname


def test_structs_and_enums():
    text = header()
    for name in re.findall(r'}\s*(chaplygin_[a-z_]+)\s*;', text):
        if chaplygin.ffi.typeof(name).kind == 'struct':
            cls = chaplygin._core.STRUCT_CLASSES[name]
            assert getattr(chaplygin, cls.__name__) is cls
    for const in re.findall(r'\b(CHAPLYGIN_[A-Z0-9_]+)\s*=', text):
        assert getattr(chaplygin, const[len('CHAPLYGIN_'):]) == \
            getattr(chaplygin.lib, const), const


def test_every_status_has_an_exception():
    text = header()
    body = re.search(r'enum chaplygin_status\s*{(.*?)}', text, re.S).group(1)
    names = re.findall(r'CHAPLYGIN_([A-Z]+)\s*=', body)
    assert 'EDOM' in names
    for name in names:
        status = getattr(chaplygin.lib, 'CHAPLYGIN_' + name)
        if status == 0:
            continue
        cls = chaplygin.error_class(status)
        assert issubclass(cls, chaplygin.ChaplyginError)
        assert cls is not chaplygin.ChaplyginError, name
        e = cls(status, 'f')
        assert e.status == status and e.name == 'CHAPLYGIN_' + name
        assert e.message == chaplygin.strerror(status)
