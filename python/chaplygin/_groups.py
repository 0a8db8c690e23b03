# _groups.py -- puts the generated wrappers into their modules.
from . import _generated


def export(namespace, group):
    """Define in NAMESPACE (a module's globals) the generated wrapper of
    every function chaplygin_GROUP_* (GROUP '': the top-level ones)."""
    module = 'chaplygin' + ('.' + group if group else '')
    names = namespace.setdefault('__all__', [])
    for cname, (g, pyname) in _generated.FUNCTIONS.items():
        if g != group or cname not in _generated.WRAPPED:
            continue
        fn = _generated.WRAPPED[cname]
        fn.__module__ = module
        namespace[pyname] = fn
        names.append(pyname)
