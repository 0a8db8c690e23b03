#!/usr/bin/env python3
"""gen.py -- generate the Python binding of libchaplygin from lib/chaplygin.h.

Run by the build (python/local.mk), never by hand:

    gen.py HEADER EXTRA_HEADERS OUTDIR PYOUT

reads the public header HEADER (lib/chaplygin.h) and the comma-separated
EXTRA_HEADERS (the scene engine's lib/scene/chaplygin-scene.h and the header
of the binding's own C functions python/src/chp_python.h), and writes

  OUTDIR/vec.h, OUTDIR/vec.c
      one C loop per function of HEADER that returns int,
        size_t chpv_NAME (size_t n, char *const *p, const ptrdiff_t *s,
                          int *status, int (*poll) (void))
      which calls NAME n times, argument k of call i taken from (value
      parameters) or pointing to (pointer parameters) p[k] + i s[k] (a
      pointer argument is NULL where p[k] is NULL), status[i] the status of
      call i; it returns the number of nonzero statuses.  It polls
      (python/src/poll.h): where POLL returns nonzero it stops (the caller
      raises the exception of a signal handler and drops the outputs).  The Python side
      chooses the strides (0 broadcasts one value), so that every function
      is vectorised over NumPy arrays with the loop in C;
  OUTDIR/module.c
      the CPython extension module chaplygin._chaplygin_cffi, written by cffi
      in API mode (cffi.FFI.emit_c_code: no compiler is run here) from a cdef
      made of HEADER, EXTRA_HEADER and vec.h with comments and preprocessor
      lines removed;
  PYOUT (python/chaplygin/_generated.py)
      one Python function per function of HEADER, with the Pythonic name
      (chaplygin_discrete_sigma4 -> discrete.sigma4), keyword arguments, the
      header's doc comment as docstring (its markup stripped to plain text),
      a scalar fast path calling the C function once and a vectorised path
      through the chpv_ loop; plus the table SPEC that describes every
      parameter (python/chaplygin/_core.py reads it).

How parameters become Python (from the C declaration alone):
  double / int / unsigned / unsigned long x      input x (scalar or array)
  const double x[N]                              input x, N numbers (or an
                                                 array of shape (..., N))
  double x[N]                                    output x (ndarray (N,);
                                                 x[16]: (4, 4))
  T *x, T a scalar type                          output x
  const S *x, S a struct typedef                 input x (an S object, or a
                                                 structured array, or a dict)
  S *x                                           output x (an S object)
  const chaplygin_options *opt                   keyword-only method=, tol=,
                                                 precision=
A function with a size_t parameter (a buffer length), a const pointer to a
scalar (an array of caller-chosen length), a parameter of any other type
(char *, a function pointer, a pointer to an opaque type such as
chaplygin_certified_orbit, declared `typedef struct T T;' without members,
...) or one annotated (inout) has no generated
wrapper (and no C loop if a parameter is of another type): python/chaplygin/*.py defines it by hand, and the test
python/tests/test_reachable.py fails until it does.

What the signature cannot say is annotated in the function's doc comment in
HEADER (the comment that starts with two stars right above the prototype),
one line per parameter, GObject-Introspection style:

    @NAME: (KEY=VALUE ...)

  (optional=True|False)  an output that may be NULL: keyword return_NAME=,
                         computed and returned by default or not
  (default=LITERAL)      an input's default (a Python literal); None: the
                         input may be NULL
  (if=FLAG)              an output written only when the output FLAG is
                         nonzero: None in a scalar call, NaN or 0 in a
                         vectorised one
  (count=N)              an output array of which only the first N (an
                         output) elements are written
  (inout)                read and written: the function is wrapped by hand

An annotation that names no parameter of the function it documents, one in a
doc comment that documents no function, an unknown key, or a key that does
not fit the parameter's kind is an error: gen.py stops (exit status 1).
"""

import keyword
import os
import re
import sys

# ---------------------------------------------------------------------------
# What the signatures cannot say: filled from the header's annotations
# (read_annotations), by function, then by parameter.

# Functions wrapped by hand (besides those with a size_t parameter or an
# array of caller-chosen length): a pointer argument is read and written
# (inout).
MANUAL = set()

# Outputs that may be NULL: a keyword return_NAME=default chooses whether
# they are computed (and returned).  An output the paper gives no formula
# for (the printed forms' dtau) must be NULL: default False.
OPTIONAL = {}

# Outputs written only when another output (a flag) is nonzero: None in a
# scalar call, NaN (floats) or 0 (integers) in a vectorised one, where the
# flag says so.
CONDITIONAL = {}

# Output arrays of which only the first COUNT elements are written: a
# scalar call returns those; a vectorised one NaN-pads the rest.
COUNTED = {}

# Defaults of inputs (Python literals); an input that may be NULL has None.
DEFAULTS = {}

# Python names for C parameter names that are Python keywords.
RENAME = {'in': 'state', 'lambda': 'lambda_'}

# The submodules: chaplygin_GROUP_rest -> chaplygin.GROUP.rest; any other
# chaplygin_rest -> chaplygin.rest.
GROUPS = ('smooth', 'discrete', 'massless', 'printed', 'sweep')

SCALARS = {
    'double': 'f8', 'int': 'i4', 'unsigned': 'u4', 'unsigned int': 'u4',
    'unsigned long': 'ul', 'long': 'l', 'size_t': 'zu',
    'unsigned char': 'u1',
}


def pyname(cname):
    """chaplygin_discrete_sigma4 -> ('discrete', 'sigma4')."""
    rest = cname[len('chaplygin_'):]
    head, _, tail = rest.partition('_')
    if head in GROUPS and tail:
        return head, tail
    return '', rest


def argname(name):
    name = RENAME.get(name, name)
    if keyword.iskeyword(name):
        name += '_'
    return name


# ---------------------------------------------------------------------------
# Reading the header.

def strip_cplusplus(text):
    return re.sub(r'#ifdef __cplusplus.*?#endif', '', text, flags=re.S)


def scan(text):
    """Split TEXT into top-level items: ('comment', body) and ('decl', text),
    preprocessor lines dropped; comments inside a declaration stay in it."""
    items = []
    i, n = 0, len(text)
    depth = 0
    decl = []
    at_line_start = True
    while i < n:
        c = text[i]
        if text.startswith('/*', i):
            j = text.index('*/', i + 2)
            body = text[i + 2:j]
            if depth == 0 and not ''.join(decl).strip():
                items.append(('comment', body))
            else:
                decl.append(' ')
            i = j + 2
            continue
        if at_line_start and c == '#':
            while True:
                j = text.find('\n', i)
                if j < 0:
                    j = n
                if text[j - 1] == '\\':
                    i = j + 1
                    continue
                break
            i = j
            continue
        if c == '\n':
            at_line_start = True
        elif not c.isspace():
            at_line_start = False
        if c == '{':
            depth += 1
        elif c == '}':
            depth -= 1
        decl.append(c)
        if c == ';' and depth == 0:
            items.append(('decl', ''.join(decl).strip()))
            decl = []
        i += 1
    return items


def cdef_text(text):
    """TEXT without comments, preprocessor lines and the C++ guards."""
    text = strip_cplusplus(text)
    return '\n'.join(t for kind, t in scan(text) if kind == 'decl') + '\n'


def int_defines(text):
    """The #define lines of TEXT that give a name an integer: cffi's cdef
    takes them (array lengths of the other headers' structures)."""
    return ''.join(m.group(0) + '\n' for m in re.finditer(
        r'^#define [A-Z][A-Z0-9_]* [0-9]+$', text, re.M))


class HeaderError(Exception):
    pass


ANNOTATION = re.compile(r'^@(\w+):\s*\((.*)\)\s*$')


def doc_comments(text):
    """{function name: (lines, line number)} of the doc comments of TEXT:
    a comment opened by two stars documents the declaration right below it
    (no blank line between), as doc/hdr2texi.pl reads them.  LINES: the
    comment's lines, the first after its opening, the others without the
    three columns of its margin.  A doc comment with annotations that
    documents no function is an error."""
    text = strip_cplusplus(text)
    docs = {}
    for m in re.finditer(r'/\*\*(?!\*)(.*?)\*/', text, re.S):
        line = text.count('\n', 0, m.start()) + 1
        col = m.start() - (text.rfind('\n', 0, m.start()) + 1)
        raw = m.group(1).split('\n')
        lines = [raw[0].strip()]
        for l in raw[1:]:
            l = l.rstrip()
            lines.append(l[col + 3:] if l[:col + 3].strip() == '' else l.strip())
        while lines and not lines[-1]:
            lines.pop()
        rest = text[m.end():]
        gap = re.match(r'[ \t]*\n?[ \t]*', rest).group(0)
        after = rest[len(gap):]
        decl = after[:after.find(';') + 1] if ';' in after else ''
        fm = re.match(r'(?:const\s+)?\w[\w\s]*?[\s*]\s*(chaplygin_\w+)\s*\(',
                      decl)
        if '\n' in gap and fm and not re.match(r'(typedef|enum|struct)\b',
                                              decl):
            docs[fm.group(1)] = (lines, line)
        elif any(ANNOTATION.match(l) for l in lines):
            raise HeaderError('line %d: annotations in a doc comment that '
                              'documents no function' % line)
    return docs


def read_annotations(funcs, docs):
    """Fill MANUAL, OPTIONAL, CONDITIONAL, COUNTED and DEFAULTS from the
    annotation lines of the doc comments DOCS of FUNCS."""
    byname = {f.cname: f for f in funcs}
    for cname, (lines, line) in docs.items():
        f = byname.get(cname)
        for l in lines:
            m = ANNOTATION.match(l)
            if not m:
                continue
            where = 'line %d (%s): @%s' % (line, cname, m.group(1))
            if f is None:
                raise HeaderError('%s: %s is not a function of the header'
                                  % (where, cname))
            params = {p.cname: p for p in f.params}
            p = params.get(m.group(1))
            if p is None:
                raise HeaderError('%s: %s has no parameter %s'
                                  % (where, cname, m.group(1)))
            items = m.group(2).split()
            if not items:
                raise HeaderError('%s: an empty annotation' % where)
            outs = ('out', 'out_array', 'out_struct')
            for item in items:
                key, eq, value = item.partition('=')
                if key == 'inout' and not eq:
                    MANUAL.add(cname)
                elif key == 'optional' and value in ('True', 'False'):
                    if p.kind not in outs:
                        raise HeaderError('%s: (optional) on an input'
                                          % where)
                    OPTIONAL.setdefault(cname, {})[p.cname] = value == 'True'
                elif key in ('if', 'count') and value:
                    if value not in params or params[value].kind != 'out':
                        raise HeaderError('%s: (%s=%s) names no scalar '
                                          'output of %s' % (where, key,
                                                            value, cname))
                    if key == 'count' and p.kind != 'out_array':
                        raise HeaderError('%s: (count) on a parameter that '
                                          'is no output array' % where)
                    if key == 'if' and p.kind not in outs:
                        raise HeaderError('%s: (if) on an input' % where)
                    table = CONDITIONAL if key == 'if' else COUNTED
                    table.setdefault(cname, {})[p.cname] = value
                elif key == 'default' and value:
                    if p.kind not in ('in', 'in_array', 'in_struct'):
                        raise HeaderError('%s: (default) on a parameter that '
                                          'is no input' % where)
                    DEFAULTS.setdefault(cname, {})[p.cname] = value
                else:
                    raise HeaderError('%s: unknown annotation %r (known: '
                                      'optional=True|False, default=LITERAL,'
                                      ' if=FLAG, count=N, inout)'
                                      % (where, item))


def _plain_inline(text):
    """The inline markup of the doc comment TEXT stripped to plain text."""
    text = text.replace('``', '"').replace("''", '"')

    def math(m):
        return re.sub(r'`([^`]*)`', r'\1', m.group(1)).replace('\\prime',
                                                               "'")
    text = re.sub(r'\$([^$]*)\$', math, text)
    text = re.sub(r'`([^`]*)`', r'\1', text)
    refs = {'pxref': 'see %s', 'xref': 'See %s', 'ref': '%s',
            'samp': "'%s'", 'dots': '...'}
    prev = None
    while prev != text:
        prev = text
        text = re.sub(r'@(\w+)\{([^{}]*)\}',
                      lambda m: refs.get(m.group(1), '%s') % m.group(2)
                      if m.group(1) != 'dots' else '...', text)
    text = re.sub(r'@(\w+)', lambda m: m.group(1), text)
    text = re.sub(r"@'(\w)", r'\1', text)
    text = text.replace('@:', '').replace('@.', '.')
    text = re.sub(r'@([{}@])', r'\1', text)
    return re.sub(r'(?<=\w)--(?=\w)', '-', text)


def plain_doc(lines):
    """The doc comment LINES as a docstring: plain text, without the
    annotations and the manual's index entries; examples (lines indented
    by 2 or more) as they are."""
    out, para = [], []

    def flush():
        if para:
            out.extend(_plain_inline('\n'.join(para)).split('\n'))
            del para[:]
    for l in lines:
        if l.startswith('  ') or not l.strip():
            flush()
            out.append(l if l.strip() else '')
            continue
        if ANNOTATION.match(l) or re.match(r'@(noindent|cindex|table|end)\b',
                                           l):
            flush()
            continue
        m = re.match(r'@(subheading|item)\s+(.*)', l)
        if m:
            flush()
            out.append(_plain_inline(m.group(2)))
            continue
        para.append(l)
    flush()
    text = re.sub(r'\n{3,}', '\n\n', '\n'.join(out)).strip('\n')
    return text


class Param:
    def __init__(self, cname, kind, ctype, dims=None, const=False):
        self.cname = cname
        self.name = argname(cname)
        self.kind = kind        # in, out, in_array, out_array, in_struct,
        #                         out_struct, opt, in_ptr (unbounded)
        self.ctype = ctype      # scalar type text or struct typedef name
        self.dims = dims        # array length
        self.const = const

    def c_type(self):
        """The C type of the argument as passed."""
        if self.kind == 'in':
            return self.ctype
        if self.kind in ('in_array', 'in_struct', 'opt', 'in_ptr'):
            return 'const %s *' % self.ctype
        return '%s *' % self.ctype


class Function:
    def __init__(self, cname, ret, params, doc, proto):
        self.cname = cname
        self.ret = ret
        self.params = params
        self.doc = doc
        self.proto = proto
        self.group, self.pyname = pyname(cname)


def type_name(node):
    from pycparser import c_ast
    while not isinstance(node, c_ast.TypeDecl):
        node = node.type
    t = node.type
    if isinstance(t, c_ast.IdentifierType):
        return ' '.join(t.names), 'const' in node.quals
    if isinstance(t, (c_ast.Struct, c_ast.Enum)):
        return ('struct ' if isinstance(t, c_ast.Struct) else 'enum ') + \
            t.name, 'const' in node.quals
    raise ValueError('unsupported type %r' % t)


def classify(p, structs, enums):
    """The Param of the parameter declaration P; kind 'unknown' for what
    the generator cannot wrap (the function is then wrapped by hand, and
    test_reachable.py fails until it is)."""
    from pycparser import c_ast
    name = getattr(p, 'name', None) or 'arg'
    try:
        t = p.type
        base, const = type_name(t)
    except (AttributeError, ValueError):
        return Param(name, 'unknown', 'void', None, False)
    kind, dims = 'unknown', None
    if isinstance(t, c_ast.TypeDecl):
        if base in SCALARS or base.startswith('enum ') or base in enums:
            kind = 'in'
    elif isinstance(t, c_ast.ArrayDecl):
        if isinstance(t.type, c_ast.TypeDecl) and base in SCALARS and \
                isinstance(t.dim, c_ast.Constant):
            dims = int(t.dim.value, 0)
            kind = 'in_array' if const else 'out_array'
    elif isinstance(t, c_ast.PtrDecl) and isinstance(t.type, c_ast.TypeDecl):
        if base == 'chaplygin_options':
            kind = 'opt' if const else 'unknown'
        elif base in structs:
            kind = 'in_struct' if const else 'out_struct'
        elif base in SCALARS:
            kind = 'in_ptr' if const else 'out'
    return Param(name, kind, base, dims, const)


def parse(header_text):
    """The functions, struct typedefs and enum types of the header."""
    from pycparser import c_ast, c_parser, c_generator
    text = strip_cplusplus(header_text)
    items = scan(text)
    docs = doc_comments(header_text)
    src = 'typedef unsigned long size_t;\n' + \
        '\n'.join(t for kind, t in items if kind == 'decl')
    ast = c_parser.CParser().parse(src)
    gen = c_generator.CGenerator()
    structs, enums, funcs = [], [], []
    for ext in ast.ext:
        if isinstance(ext, c_ast.Typedef):
            # an opaque type (typedef struct x x;, no members: the
            # certified orbit) is no struct class: a pointer to it is
            # classified 'unknown', and its functions are wrapped by hand
            if isinstance(ext.type.type, c_ast.Struct) and \
                    ext.type.type.decls is not None:
                structs.append(ext.name)
            elif isinstance(ext.type.type, c_ast.Enum):
                enums.append(ext.name)
            continue
        if isinstance(ext, c_ast.Decl) and isinstance(ext.type, c_ast.Enum):
            enums.append('enum ' + ext.type.name)
            continue
        if not (isinstance(ext, c_ast.Decl)
                and isinstance(ext.type, c_ast.FuncDecl)):
            continue
        fd = ext.type
        ret_t = fd.type
        try:
            base, const = type_name(ret_t)
        except ValueError:
            base, const = 'unknown', False
        if isinstance(ret_t, c_ast.PtrDecl):
            ret = 'string' if base == 'char' and const and \
                isinstance(ret_t.type, c_ast.TypeDecl) else 'unknown'
        else:
            ret = base
        params = []
        for p in fd.args.params if fd.args else []:
            if isinstance(p, c_ast.Typename) and \
                    isinstance(p.type, c_ast.TypeDecl) and \
                    type_name(p.type)[0] == 'void':     # (void)
                continue
            params.append(classify(p, structs, enums))
        proto = gen.visit(ext).replace('\n', ' ')
        doc = docs.get(ext.name)
        if doc is None:
            raise HeaderError('%s has no doc comment' % ext.name)
        funcs.append(Function(ext.name, ret, params,
                              plain_doc(doc[0]),
                              proto))
    read_annotations(funcs, docs)
    m = re.search(r'#define\s+CHAPLYGIN_OPTIONS_DEFAULT\s*\{([^}]*)\}',
                  header_text)
    options_default = [t.strip() for t in m.group(1).split(',')] if m else None
    return funcs, structs, enums, options_default


def looped(f):
    """Whether F gets a C loop (chpv_NAME): it returns int and every
    parameter is classified."""
    return f.ret == 'int' and all(p.kind != 'unknown' for p in f.params)


def generic(f):
    """Whether F gets a generated Python wrapper."""
    if f.cname in MANUAL or any(p.kind == 'unknown' for p in f.params):
        return False
    if f.ret == 'string':
        return all(p.kind == 'in' for p in f.params)
    if f.ret != 'int':
        return False
    for p in f.params:
        if p.ctype == 'size_t' or p.kind == 'in_ptr':
            return False
    return True


# ---------------------------------------------------------------------------
# C: the loops.

def c_loop(f):
    args = []
    for k, p in enumerate(f.params):
        if p.kind == 'in':
            args.append('*(const %s *) (p[%d] + k * s[%d])' % (p.ctype, k, k))
        else:
            t = p.c_type()
            args.append('(%s) (p[%d] ? p[%d] + k * s[%d] : NULL)'
                        % (t, k, k, k))
    call = '%s (%s)' % (f.cname, ',\n                    '.join(args))
    return '''size_t
chpv_%s (size_t n, char *const *p, const ptrdiff_t *s, int *status,
         int (*poll) (void))
{
  size_t nfail = 0;
  chp_py_poller pl;
  chp_py_poller_init (&pl, poll);
  for (size_t i = 0; i < n && !chp_py_poll_stop (&pl); i++)
    {
      const ptrdiff_t k = (ptrdiff_t) i;
      int rc = %s;
      status[i] = rc;
      nfail += rc != 0;
    }
  return nfail;
}
''' % (f.cname, call)


def c_proto(f):
    return ('size_t chpv_%s (size_t n, char *const *p, const ptrdiff_t *s, '
            'int *status, int (*poll) (void));' % f.cname)


# ---------------------------------------------------------------------------
# Python: the wrappers.

def py_repr(x):
    return repr(x)


def param_spec(f, p):
    """The SPEC entry of parameter P: (name, kind, ctype, dims, extra)."""
    extra = {}
    opt = OPTIONAL.get(f.cname, {})
    if p.cname in opt:
        extra['optional'] = opt[p.cname]
    cond = CONDITIONAL.get(f.cname, {})
    if p.cname in cond:
        extra['if'] = argname(cond[p.cname])
    cnt = COUNTED.get(f.cname, {})
    if p.cname in cnt:
        extra['count'] = argname(cnt[p.cname])
    d = DEFAULTS.get(f.cname, {})
    if p.cname in d and d[p.cname] == 'None':
        extra['nullable'] = True
    return (p.name, p.kind, p.ctype, p.dims, extra)


def indent(text, n):
    pad = ' ' * n
    return '\n'.join(pad + l if l.strip() else l for l in text.split('\n'))


def py_doc(f, sig, outs, optional):
    lines = ['%s' % sig, '']
    if f.doc:
        lines += f.doc.split('\n') + ['']
    lines.append('C: %s' % f.proto)
    if f.ret == 'string':
        lines.append('Returns: str.')
    else:
        ret = []
        for p in outs:
            what = {'out': 'scalar', 'out_array': 'ndarray of %d' % (p.dims or 0),
                    'out_struct': p.ctype}.get(p.kind, p.kind)
            s = '%s (%s)' % (p.name, what)
            if p.cname in CONDITIONAL.get(f.cname, {}):
                s += ' (None unless %s)' % CONDITIONAL[f.cname][p.cname]
            if p.cname in COUNTED.get(f.cname, {}):
                s += ' (its first %s)' % COUNTED[f.cname][p.cname]
            if p.cname in optional:
                s += ' if return_%s (default %s)' % (p.name,
                                                     optional[p.cname])
            ret.append(s)
        lines.append('Returns: ' + (', '.join(ret) if ret else 'None') +
                     ('; a named tuple if more than one.' if len(ret) > 1
                      else '.'))
        lines.append('Raises: a ChaplyginError subclass for a nonzero '
                     'status (errors="raise").')
        lines.append('Any input may be a NumPy array (broadcast together): '
                     'the loop runs in C and')
        lines.append('every result gains the broadcast shape; '
                     'errors="return" adds a status array')
        lines.append('instead of raising (chaplygin.vectorised explains).')
    return '\n'.join(lines)


_CTYPES = {}


def _ctype_const(text):
    """The name of a module constant holding ffi.typeof(TEXT)."""
    if text not in _CTYPES:
        _CTYPES[text] = '_C%d' % len(_CTYPES)
    return _CTYPES[text]


def py_wrapper(f, idx):
    """The source of the Python wrapper of F."""
    fname = '_f%d' % idx
    ins = [p for p in f.params if p.kind in ('in', 'in_array', 'in_struct')]
    outs = [p for p in f.params if p.kind in ('out', 'out_array',
                                              'out_struct')]
    has_opt = any(p.kind == 'opt' for p in f.params)
    optional = OPTIONAL.get(f.cname, {})
    defaults = DEFAULTS.get(f.cname, {})
    cond = CONDITIONAL.get(f.cname, {})
    counted = COUNTED.get(f.cname, {})
    args = []
    seen_default = False
    for p in ins:
        if p.cname in defaults:
            args.append('%s=%s' % (p.name, defaults[p.cname]))
            seen_default = True
        else:
            if seen_default:
                raise ValueError('%s: %s without default after one with'
                                 % (f.cname, p.cname))
            args.append(p.name)
    kw = []
    for p in outs:
        if p.cname in optional:
            kw.append('return_%s=%s' % (p.name, optional[p.cname]))
    if has_opt:
        kw += ['method=None', 'tol=None', 'precision=None']
    if f.ret != 'string':
        kw.append("errors='raise'")
    sig_args = ', '.join(args + (['*'] + kw if kw else []))
    pyfull = (f.group + '.' if f.group else '') + f.pyname
    sig = '%s(%s)' % (pyfull, sig_args)
    doc = py_doc(f, sig, outs, optional)
    body = []
    body.append('def %s(%s):' % (fname, sig_args))
    body.append('    """%s\n    """' % indent(doc.replace('\\', '\\\\')
                                             .replace('"""', '\\"\\"\\"'),
                                             4).lstrip())
    if f.ret == 'string':
        p = f.params[0]
        body.append('    return _ffi.string(_lib.%s(%s)).decode()'
                    % (f.cname, ', '.join(q.name for q in f.params)))
        return '\n'.join(body) + '\n', fname
    for p in ins:
        if p.cname == 'request':
            body.append('    %s = _request(%s)' % (p.name, p.name))
    if has_opt:
        body.append('    _opt = _options(method, tol, precision)')
    # the fast path
    conds = []
    for p in ins:
        nullable = defaults.get(p.cname) == 'None'
        if p.kind == 'in':
            c = '_T(%s) in _SC' % p.name
        elif p.kind == 'in_array':
            c = '(_T(%s) in _SQ and len(%s) == %d)' % (p.name, p.name, p.dims)
        else:
            c = '_T(%s) is _S_%s' % (p.name, p.ctype)
        if nullable:
            c = '(%s is None or %s)' % (p.name, c)
        conds.append(c)
    conds.append("errors == 'raise'")
    body.append('    if %s:' % ' and '.join(conds))
    cargs = []
    for k, p in enumerate(f.params):
        nullable = defaults.get(p.cname) == 'None'
        if p.kind in ('in', 'in_array'):
            a = p.name
            if nullable:
                a = '(_NULL if %s is None else %s)' % (p.name, p.name)
            cargs.append(a)
        elif p.kind == 'in_struct':
            cargs.append('%s._c' % p.name)
        elif p.kind == 'opt':
            cargs.append('_opt')
        else:
            if p.kind == 'out_array':
                t = _ctype_const('%s[%d]' % (p.ctype, p.dims))
            else:
                t = _ctype_const('%s *' % p.ctype)
            if p.cname in optional:
                body.append('        _o%d = _new(%s) if return_%s else _NULL'
                            % (k, t, p.name))
            else:
                body.append('        _o%d = _new(%s)' % (k, t))
            cargs.append('_o%d' % k)
    body.append('        _rc = _lib.%s(%s)' % (f.cname, ', '.join(cargs)))
    body.append('        if _rc:')
    body.append("            _fail(_rc, '%s')" % f.cname)
    # results
    res = []
    for k, p in enumerate(f.params):
        if p.kind not in ('out', 'out_array', 'out_struct'):
            continue
        if p.kind == 'out':
            v = '_o%d[0]' % k
        elif p.kind == 'out_array':
            if p.cname in counted:
                kc = [q.cname for q in f.params].index(counted[p.cname])
                v = '_arr(_o%d, _o%d[0])' % (k, kc)
            else:
                v = '_arr(_o%d, %d)' % (k, p.dims)
        else:
            v = '_S_%s._wrap(_o%d)' % (p.ctype, k)
        if p.cname in cond:
            kc = [q.cname for q in f.params].index(cond[p.cname])
            v = '(%s if _o%d[0] else None)' % (v, kc)
        res.append((p, v))
    names = [p.name for p, _ in res]
    # the outputs returned by default: explicitly (no _pick on the way)
    dflt = [(p, v) for p, v in res if optional.get(p.cname, True)]
    if len(dflt) == 1:
        ret = dflt[0][1]
    elif not dflt:
        ret = 'None'
    else:
        ret = '_R%d(%s)' % (idx, ', '.join(v for _, v in dflt))
    opt_res = [p for p, _ in res if p.cname in optional]
    if opt_res:
        same = ' and '.join(('return_%s' if optional[p.cname] else
                             'not return_%s') % p.name for p in opt_res)
        body.append('        if %s:' % same)
        body.append('            return %s' % ret)
        flags = ', '.join(('return_%s' % p.name) if p.cname in optional
                          else 'True' for p, _ in res)
        body.append('        return _pick(%r, (%s), (%s,))'
                    % (tuple(names), flags,
                       ', '.join('%s if return_%s else None' % (v, p.name)
                                 if p.cname in optional else v
                                 for p, v in res)))
    else:
        body.append('        return %s' % ret)
    # the vectorised path
    wants = []
    for p in f.params:
        if p.kind in ('out', 'out_array', 'out_struct'):
            wants.append('return_%s' % p.name if p.cname in optional
                         else 'True')
    vin = ', '.join(p.name for p in ins)
    if len(ins) == 1:
        vin += ','
    body.append('    return _vec(%r, (%s), (%s), %s, errors)'
                % (f.cname, vin, ', '.join(wants) + (',' if len(wants) == 1 else ''),
                   '_opt' if has_opt else 'None'))
    src = '\n'.join(body) + '\n'
    if len(dflt) > 1:
        src = '_R%d = _nt(%r)\n' % (idx, tuple(p.name for p, _ in dflt)) \
            + src
    return src, fname


def py_module(funcs, structs, enums, options_default):
    out = ['''# _generated.py -- generated by python/gen.py from lib/chaplygin.h;
# do not edit (edit python/gen.py, or wrap the function by hand).
# One wrapper per function of the header that python/gen.py can classify;
# _core.py supplies the helpers (_vec: the vectorised path, _fail: the
# exceptions, struct classes _S_*).
from ._core import (_ffi, _lib, _NULL, _new, _arr, _fail, _vec, _pick,
                    _options, _request, _nt, _SC, _SQ, _struct_class,
                    SPEC)

_T = type
''']
    out.append('STRUCTS = %r\n' % (tuple(structs),))
    out.append('ENUMS = %r\n' % (tuple(enums),))
    out.append('OPTIONS_DEFAULT = %r\n' % (tuple(options_default or ()),))
    for s in structs:
        out.append('_S_%s = _struct_class(%r)\n' % (s, s))
    out.append('\n# (name, kind, ctype, dims, extra) of every parameter, by '
               'function (SPEC is _core.SPEC); wrapped: generated here\n'
               'WRAPPED = {}\n'
               'FUNCTIONS = {}\n')
    for idx, f in enumerate(funcs):
        spec = tuple(param_spec(f, p) for p in f.params)
        out.append('SPEC[%r] = %r\n' % (f.cname, spec))
        out.append('FUNCTIONS[%r] = (%r, %r)\n' % (f.cname, f.group,
                                                  f.pyname))
    out.append('\n')
    wrappers = []
    for idx, f in enumerate(funcs):
        if generic(f):
            wrappers.append((f, py_wrapper(f, idx)))
    out.append('\n# the C types of the outputs, resolved once\n')
    for text, const in sorted(_CTYPES.items(), key=lambda x: int(x[1][2:])):
        out.append('%s = _ffi.typeof(%r)\n' % (const, text))
    for f, (src, fname) in wrappers:
        out.append('\n' + src)
        out.append('%s.__name__ = %s.__qualname__ = %r\n'
                   % (fname, fname, f.pyname))
        out.append('%s.__c_function__ = %r\n' % (fname, f.cname))
        out.append('WRAPPED[%r] = %s\n' % (f.cname, fname))
    return ''.join(out)


# ---------------------------------------------------------------------------

def _remove(*paths):
    for p in paths:
        try:
            os.unlink(p)
        except OSError:
            pass


def write_file(path, text):
    """TEXT into PATH through PATH.tmp, which replaces PATH only once it is
    written and closed: Python raises on a failed write or close (a full
    disk, a quota; EFBIG under a file-size limit, SIGXFSZ being ignored),
    and then PATH is as it was and PATH.tmp is gone."""
    tmp = path + '.tmp'
    try:
        with open(tmp, 'w') as fh:
            fh.write(text)
        os.replace(tmp, path)
    except BaseException:
        _remove(tmp)
        raise


def main(argv):
    header, extra, outdir, pyout = argv[1:5]
    version = argv[5] if len(argv) > 5 else 'unknown'
    with open(header) as fh:
        htext = fh.read()
    etext = ''
    for path in extra.split(','):       # the binding's other headers
        with open(path) as fh:
            etext += fh.read() + '\n'
    try:
        funcs, structs, enums, options_default = parse(htext)
    except HeaderError as e:
        sys.stderr.write('gen.py: %s: %s\n' % (header, e))
        return 1
    loops = [f for f in funcs if looped(f)]
    write = write_file

    vec_h = ('/* vec.h -- generated by python/gen.py from lib/chaplygin.h; '
             'do not edit. */\n#ifndef CHP_PY_VEC_H\n#define CHP_PY_VEC_H\n'
             '#include <stddef.h>\n' +
             '\n'.join(c_proto(f) for f in loops) + '\n#endif\n')
    vec_c = ('/* vec.c -- generated by python/gen.py from lib/chaplygin.h; '
             'do not edit.\n   One loop per function: see python/gen.py. */\n'
             '#include <stddef.h>\n#include "chaplygin.h"\n#include "poll.h"\n'
             '#include "vec.h"\n\n'
             + '\n'.join(c_loop(f) for f in loops))
    write(os.path.join(outdir, 'vec.h'), vec_h)
    write(os.path.join(outdir, 'vec.c'), vec_c)

    import cffi
    ffi = cffi.FFI()
    ffi.cdef(cdef_text(htext))
    ffi.cdef(int_defines(etext) + cdef_text(etext))
    ffi.cdef('\n'.join(c_proto(f) for f in loops))
    # the poll of every C loop (python/src/poll.h; _core.py defines it)
    ffi.cdef('extern "Python" int chp_py_poll (void);')
    ffi.set_source('chaplygin._chaplygin_cffi',
                   '#include "chaplygin.h"\n#include "chaplygin-scene.h"\n'
                   '#include "chp_python.h"\n#include "vec.h"\n')
    tmp = os.path.join(outdir, 'module.c.tmp')
    try:                        # cffi writes TMP through TMP.~PID
        ffi.emit_c_code(tmp)    # (and says "generating ...")
        os.replace(tmp, os.path.join(outdir, 'module.c'))
    except BaseException:
        _remove(tmp, '%s.~%d' % (tmp, os.getpid()))
        raise
    write(pyout, py_module(funcs, structs, enums, options_default)
          + '\nVERSION = %r\n' % version)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
