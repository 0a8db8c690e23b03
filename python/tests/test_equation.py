"""chaplygin.eq and chaplygin.labels: every label of the registry evaluated
at its example inputs gives the program's `chaplygin eq LABEL ... --csv`
outputs, names and values bit for bit (the CSV's %.17g reads back
exactly), with the same printed forms; and results pickle, errors are
the right exceptions, the labels are the registry's."""
import csv
import decimal
import io
import math
import pickle
import subprocess
from fractions import Fraction

import pytest

import chaplygin as c
from conftest import src


def registry():
    """The registry's labels and example calls (lib/labels.txt)."""
    out, label = [], None
    with open(src('lib', 'labels.txt')) as fh:
        for line in fh:
            if line.startswith('@ '):
                label = line[2:].strip()
            elif line.startswith('eq.example: '):
                out.append((label, line[len('eq.example: '):].strip()))
    return out


EXAMPLES = registry()


def program_rows(program, label, args):
    r = subprocess.run([program, 'eq', label] + args + ['--csv'],
                       capture_output=True, text=True, check=True)
    return list(csv.DictReader(io.StringIO(r.stdout)))


def value_of(text):
    try:
        return int(text)
    except ValueError:
        try:
            return float(text)
        except ValueError:
            return text


@pytest.mark.parametrize('label,example', EXAMPLES, ids=[e[0] for e in EXAMPLES])
def test_eq_equals_program(label, example, program):
    args = example.split()
    rows = program_rows(program, label, args)
    r = c.eq(label, **dict(a.split('=', 1) for a in args))
    assert list(r.outputs) == [row['output'] for row in rows]
    for row in rows:
        name = row['output']
        got, want = r.outputs[name], value_of(row['value'])
        assert got == want or (isinstance(got, float) and math.isnan(got)
                               and math.isnan(want)), (name, got, want)
        assert r.functions[name] == row['function']
        assert r.methods[name] == row['method']
        if row['printed'] == '':
            assert name not in r.printed
        elif row['printed'] == 'undefined':
            assert r.printed[name] is None
        else:
            assert r.printed[name] == value_of(row['printed'])
            assert r.errata[name] == row['erratum']


def test_labels_are_the_registry():
    assert [l.label for l in c.labels()] == [e[0] for e in EXAMPLES]
    first = c.labels()[0]
    assert first.label == '2.1' and 'chaplygin_smooth_field' in first.functions
    assert first.errata == ('E1',)
    assert pickle.loads(pickle.dumps(first)) == first


def test_the_issue_example(program):
    """chaplygin.eq("3.10", L0=1, Delta="1/3", dir=-1) gives the program's
    value (the issue's example), and sigma4 of (3.10) directly."""
    r = c.eq('3.10', L0=1, Delta='1/3', dir=-1)
    want = float(program_rows(program, '3.10',
                              ['L0=1', 'Delta=1/3', 'dir=-1'])[0]['value'])
    assert r.sigma4 == r['sigma4'] == want
    assert r.sigma4 == c.discrete.sigma4(1, 1 / 3, dir=-1)
    # exact inputs in any spelling: Fraction, float, text
    assert c.eq('3.10', L0=1, Delta=Fraction(1, 3), dir=-1) == r
    assert c.eq('(3.10)', L0=1.0, Delta=1 / 3, dir=-1).sigma4 == r.sigma4
    assert pickle.loads(pickle.dumps(r)) == r
    assert r.label == '3.10' and r.inputs[1] == 'Delta = 0.33333333333333331'


def test_printed_forms():
    """(2.1) as printed (E1): dS/dtau = V; its relative difference from
    |V| is 2 at V = -1e308 (formed without overflow)."""
    r = c.eq('2.1', L=1, V=-1e308, Omega=0.5)
    assert r.outputs['dS/dtau'] == 1e308 and r.printed['dS/dtau'] == -1e308
    assert r.relative['dS/dtau'] == 2.0 and r.errata['dS/dtau'] == 'E1'


def decimal17(q):
    """The Fraction Q rounded to 17 significant digits (what %.17g prints
    of the exact value), as a Decimal."""
    with decimal.localcontext() as ctx:
        ctx.prec = 17
        return decimal.Decimal(q.numerator) / decimal.Decimal(q.denominator)


BEYOND = [   # (label, inputs, the outputs beyond the doubles)
    ('B.3', {'L0': 1e200, 'Delta': 1, 'V': 1, 'Omega': 1},
     ['E_next', 'H_next']),                         # E ~ 5e399: inf
    ('B.9', {'L0': 1, 'Delta': '1/3', 'V': '1e-200', 'Omega': '1e-200',
             'n': 3}, ['E_n', 'E_n (printed)']),    # E ~ 1.5e-400: 0
]


@pytest.mark.parametrize('label,inputs,beyond', BEYOND,
                         ids=[b[0] for b in BEYOND])
def test_outputs_beyond_the_doubles(label, inputs, beyond, program):
    """An output x 2^e of an evaluation in a velocity scaling's units: the
    float is its rounding (inf, 0), with a RuntimeWarning naming it, and
    exact (printed_exact) is its exact value, which the program prints:
    %.17g of the exact value, against the Fraction rounded by decimal."""
    with pytest.warns(RuntimeWarning) as w:
        r = c.eq(label, **inputs)
    assert len(w) == 1 and ', '.join(beyond) in str(w[0].message)
    rows = program_rows(program, label,
                        ['%s=%s' % kv for kv in inputs.items()])
    assert list(r.outputs) == [row['output'] for row in rows]
    for row in rows:
        name, text = row['output'], row['value']
        if name in r.exact:
            assert decimal17(r.exact[name]) == decimal.Decimal(text), name
        # float() of the decimal: correctly rounded, inf beyond the doubles
        assert r.outputs[name] == value_of(text), (name, text)
        if row['printed'] not in ('', 'undefined'):
            assert decimal17(r.printed_exact[name]) == \
                decimal.Decimal(row['printed'])
            assert r.printed[name] == value_of(row['printed'])
            assert r.relative[name] == pytest.approx(
                float(row['relative_difference']), rel=5e-3)
    for name in beyond:
        v = (r.printed[name.split()[0]] if name.endswith('(printed)')
             else r.outputs[name])
        assert v in (0.0, math.inf), name
    assert pickle.loads(pickle.dumps(r)) == r


def test_errors():
    with pytest.raises(c.EquationError, match='unknown equation label'):
        c.eq('9.9')
    with pytest.raises(c.EquationError, match='missing input dir'):
        c.eq('3.10', L0=1, Delta=1)
    with pytest.raises(c.EquationError, match="unknown input 'x'"):
        c.eq('3.10', L0=1, Delta=1, dir=1, x=2)
    with pytest.raises(c.EquationError, match='not a number'):
        c.eq('3.10', L0='one', Delta=1, dir=1)
    with pytest.raises(c.DomainError):
        c.eq('3.10', L0=1, Delta=-1, dir=1)
    with pytest.raises(TypeError):
        c.eq('3.10', L0=None, Delta=1, dir=1)
    with pytest.raises(TypeError):
        c.eq('3.10', L0=True, Delta=1, dir=1)
    with pytest.raises(TypeError):
        c.eq(3.10, L0=1)
    e = pytest.raises(c.EquationError, c.eq, '3.10').value
    assert pickle.loads(pickle.dumps(e)).detail == e.detail
