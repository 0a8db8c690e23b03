"""Every exception path: each status of the library provoked by a real call
(CHAPLYGIN_ENOMEM in a subprocess whose address space is limited), the
exception's class, status, name, message and function; the errors of the
Python layer (unknown names, errors=, types); vectorised failures; and
pickling."""
import os
import pickle
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import chaplygin as c
from chaplygin import discrete as d

NAN = float('nan')


def provoke_einval():
    d.heading(1, 0, 1, 0.5, 1 / 3, method=7)        # unknown method value


def provoke_edom():
    d.sigma4(NAN, 1 / 3, dir=1)


def provoke_estate():
    d.state_from_phase(d.init(1, 1 / 3), [0, 0, 0, 0.5])     # V = 0


def provoke_espin():
    d.final_energy(d.init(-0.5, 1), 1, 0.5, 1.0)


def provoke_erange():
    d.spin_ratio(1.0, 0.0)


def provoke_enoconv():
    d.basin_boundaries(d.init(-0.95, 1.0), 1 / 1.9025, 2.0, 2.8, 3, 60)


def provoke_ecap():
    # L0 = 1/3, Delta = 2/7, E = 5/11, H = -3/13 exactly: with a cap of 64
    # bits the exact E and H outgrow it within a few collisions
    o = c.CertifiedOrbit.exact((1, 3), (2, 7), 1, (5, 11), (-3, 13))
    o.cap(64)
    for _ in range(64):
        o.step()


CASES = [
    ('EINVAL', provoke_einval, c.InvalidArgumentError, ValueError,
     'chaplygin_discrete_heading'),
    ('EDOM', provoke_edom, c.DomainError, ValueError,
     'chaplygin_discrete_sigma4'),
    ('ESTATE', provoke_estate, c.StateError, ValueError,
     'chaplygin_discrete_state_from_phase'),
    ('ESPIN', provoke_espin, c.SpinError, c.ChaplyginError,
     'chaplygin_discrete_final_energy'),
    ('ERANGE', provoke_erange, c.RangeError, ArithmeticError,
     'chaplygin_discrete_spin_ratio'),
    ('ENOCONV', provoke_enoconv, c.NoConvergenceError, ArithmeticError,
     'chaplygin_discrete_basin_boundaries'),
    ('ECAP', provoke_ecap, c.CertificationCapError, ArithmeticError,
     'chaplygin_certified_orbit_step'),
]


@pytest.mark.parametrize('name,call,cls,base,function', CASES,
                         ids=[x[0] for x in CASES])
def test_status_raised(name, call, cls, base, function):
    if name == 'ECAP' and not c.method_available('certified'):
        pytest.skip('a build without Arb: no certified method, no ECAP '
                    '(test_ecap_without_arb)')
    with pytest.raises(cls) as info:
        call()
    e = info.value
    status = getattr(c, name)
    assert e.status == status == getattr(c.Status, name)
    assert e.name == 'CHAPLYGIN_' + name
    assert e.message == c.strerror(status)
    assert e.function == function
    assert isinstance(e, base) and isinstance(e, c.ChaplyginError)
    assert c.error_class(status) is cls
    assert function in str(e) and e.message in str(e)
    e2 = pickle.loads(pickle.dumps(e))
    assert type(e2) is cls and e2.status == e.status and str(e2) == str(e)


ENOMEM_SCRIPT = textwrap.dedent('''
    import resource, sys
    import chaplygin as c
    sys_ = c.discrete.init(-0.5, 1.0)
    n = 4000000
    for line in open('/proc/self/status'):
        if line.startswith('VmSize:'):
            vm = int(line.split()[1]) * 1024
    # room for the wrapper's buffer (16 n bytes), not the library's (8 n)
    resource.setrlimit(resource.RLIMIT_AS,
                       (vm + 16 * n + 16 * 2**20,
                        resource.getrlimit(resource.RLIMIT_AS)[1]))
    try:
        c.discrete.basin_boundaries(sys_, 0.8, 0.0005, 0.5, n, 1000)
    except c.OutOfMemoryError as e:
        assert e.status == c.ENOMEM and isinstance(e, MemoryError)
        assert e.function == 'chaplygin_discrete_basin_boundaries'
        print('ENOMEM')
    ''')


def test_status_enomem():
    """CHAPLYGIN_ENOMEM: the library's malloc fails under RLIMIT_AS."""
    if not os.path.exists('/proc/self/status'):
        pytest.skip('no /proc')
    r = subprocess.run([sys.executable, '-c', ENOMEM_SCRIPT],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == 'ENOMEM'


def test_every_status_covered():
    provoked = {x[0] for x in CASES} | {'ENOMEM'}
    assert provoked == {m.name for m in c.Status if m.value != 0}


def test_ecap_without_arb():
    """A build without Arb has no certified method: the orbit is refused
    (EINVAL) before any cap can be met."""
    if c.method_available('certified'):
        pytest.skip('this build has the certified method (test_status_raised)')
    with pytest.raises(c.InvalidArgumentError):
        provoke_ecap()


def test_more_library_statuses():
    with pytest.raises(c.InvalidArgumentError):
        d.heading(1, 0, 1, 0.5, 1 / 3, method='quadrature', tol=2.0)
    with pytest.raises(c.InvalidArgumentError):
        d.sigma4(1, 1 / 3, dir=2)
    with pytest.raises(c.InvalidArgumentError):
        d.coefficients(1, 1, 0, 2)
    # an output the paper gives no formula for must not be asked for
    with pytest.raises(c.InvalidArgumentError):
        c.printed.smooth_closed_form(0.7, [0, 1, 0, 0.5], 1.0,
                                     return_dtau=True)
    with pytest.raises(c.DomainError):
        d.init(1, -1)
    with pytest.raises(c.DomainError):
        c.Discrete(1, 0.0)                  # the constructor is init
    sys2 = d.init(-0.75, 1.2917)
    st = d.state_from_phase(sys2, [0, 15 / 32, 0, 0.5])
    with pytest.raises(c.SpinError):
        d.step(sys2, st)


def test_python_layer_errors():
    with pytest.raises(c.InvalidArgumentError) as info:
        d.heading(1, 0, 1, 0.5, 1 / 3, method='bogus')
    assert 'bogus' in str(info.value) and info.value.status == c.EINVAL
    with pytest.raises(c.InvalidArgumentError):
        d.heading(1, 0, 1, 0.5, 1 / 3, precision='quad')
    sys_ = d.init(1, 1 / 3)
    st = d.state_from_phase(sys_, [0, 1, 0, 0.5])
    with pytest.raises(c.InvalidArgumentError):
        d.step(sys_, st, request='theta,bogus')
    with pytest.raises(ValueError):
        d.sigma4(np.ones(3), 1 / 3, dir=1, errors='ignore')
    with pytest.raises(TypeError):
        d.sigma4('1', 1 / 3, dir=1)
    with pytest.raises(TypeError):
        d.sigma4(1, 1 / 3, dir=1.0)                 # dir is an integer
    with pytest.raises(TypeError):
        d.sigma4(1, 1 / 3, 1, 2)                    # too many arguments
    with pytest.raises(TypeError):
        d.step('not a system', st)
    with pytest.raises(TypeError):
        c.DiscreteState(bogus=1)
    with pytest.raises(OverflowError):
        d.sigma4(1, 1 / 3, dir=2 ** 40)
    with pytest.raises(OverflowError):
        d.energy_after(sys_, 1, 0.75, 1.0, -1)      # unsigned long


def test_vectorised_failure_policy():
    L0 = np.array([1.0, NAN, 2.0, np.inf])
    with pytest.raises(c.DomainError) as info:
        d.sigma4(L0, 1 / 3, dir=1)
    e = info.value
    assert e.index == (1,)
    assert list(e.statuses) == [0, c.EDOM, 0, c.EDOM]
    assert np.isnan(e.partial[1]) and e.partial[0] == d.sigma4(1, 1 / 3,
                                                              dir=1)
    r = d.sigma4(L0, 1 / 3, dir=1, errors='return')
    assert list(r.status) == [0, c.EDOM, 0, c.EDOM]
    assert r.sigma4[2] == d.sigma4(2.0, 1 / 3, dir=1)
    assert np.isnan(r.sigma4[1]) and np.isnan(r.sigma4[3])
    # a scalar with errors='return'
    r = d.sigma4(NAN, 1 / 3, dir=1, errors='return')
    assert r.status == c.EDOM and r.sigma4 is None or np.isnan(r.sigma4)
    # the first failure decides the class
    with pytest.raises(c.InvalidArgumentError):
        d.sigma4(np.array([1.0, 1.0, NAN]), 1 / 3, np.array([1, 3, 1]))


def test_scene_errors(tmp_path):
    bad = tmp_path / 'bad.ini'
    bad.write_text('[scene]\nmodel = discrete\n[parameters]\nL0 = 1\n'
                   'Delta = -1\n')
    with pytest.raises(c.SceneError) as info:
        c.run_scene(str(bad))
    assert str(bad) in str(info.value) and 'Delta' in str(info.value)
    assert isinstance(info.value, ValueError) and info.value.status is None
    with pytest.raises(c.SceneError):
        c.run_scene(str(tmp_path / 'missing.ini'))
    with pytest.raises(c.SceneError):
        c.run_scene({'scene': {'model': 'discrete', 'colour': 'red'}})
    # a run that ends in the spinning equilibrium: the rows before it
    spin = {'scene': {'model': 'discrete'},
            'parameters': {'L0': '-3/4', 'Delta': 1.2917},
            'initial': {'V': '15/32', 'Omega': '1/2'},
            'run': {'collisions': 5}}
    with pytest.raises(c.SpinError) as info:
        c.run_scene(spin)
    assert info.value.status == c.ESPIN
    assert list(info.value.partial['n']) == [0]
