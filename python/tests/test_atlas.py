"""chaplygin.atlas: a fate atlas as an xarray.Dataset equals the program's
rows (`chaplygin sweep`, parsed from its CSV: a different route, text) bit
for bit, for every chunking and scheduler, a two-worker
dask.distributed.LocalCluster included; it pickles and survives to_netcdf
and to_zarr."""
import csv
import io
import os
import pickle
import subprocess

import numpy as np
import pytest

import chaplygin as c
from chaplygin.scene import to_ini

xr = pytest.importorskip('xarray')
dask = pytest.importorskip('dask')

# V from -1/2 to 1/2 in 40 steps: V = 0 exactly at j = 20 (status ESTATE,
# no fate); Omega+ across Figure 3's 4/5.
SCENE = {'scene': {'model': 'discrete', 'title': 'test atlas'},
         'parameters': {'L0': -0.5, 'Delta': 1},
         'run': {'collisions': 100000},
         'sweep': {'kind': 'atlas', 'x': 'V', 'x_min': -0.5, 'x_max': 0.5,
                   'nx': 41, 'y': 'Omega', 'y_min': 0.1, 'y_max': 2,
                   'ny': 23}}
# the skate changes from point to point: L0 and V+ (Figure 2(b)'s bistable
# band at Delta = 1 lies in -1 < L0 < 0)
SKATES = {'scene': {'model': 'discrete'},
          'parameters': {'Delta': 1}, 'initial': {'Omega': 0.8},
          'run': {'collisions': 1000},
          'sweep': {'kind': 'atlas', 'x': 'L0', 'x_min': -1.5, 'x_max': 0.5,
                    'nx': 17, 'y': 'V', 'y_min': 0.05, 'y_max': 1,
                    'ny': 9}}
NAMES = ('fate', 'collisions', 'reversals', 'E_final', 'V_final', 'status')


def same(a, b):
    """Datasets A and B hold the same bits (NaN included), coordinates and
    dimensions."""
    assert a.dims == b.dims
    for name in a.coords:
        assert np.array_equal(a[name].values.view(np.uint8),
                              b[name].values.view(np.uint8)), name
    for name in NAMES:
        x, y = np.ascontiguousarray(a[name].values), \
            np.ascontiguousarray(b[name].values)
        assert x.dtype == y.dtype and x.shape == y.shape, name
        assert np.array_equal(x.view(np.uint8), y.view(np.uint8)), name
    return True


def program_rows(program, scene, tmp_path):
    path = tmp_path / 'atlas.ini'
    path.write_text(to_ini(scene))
    out = subprocess.run([program, 'sweep', str(path), '--no-provenance'],
                         check=True, capture_output=True, text=True).stdout
    return list(csv.reader(io.StringIO(out)))


@pytest.fixture(scope='module')
def eager():
    return c.atlas(SCENE)


def test_the_program_bit_for_bit(program, tmp_path, eager):
    rows = program_rows(program, SCENE, tmp_path)
    assert rows[0] == ['k', 'V', 'Omega'] + list(NAMES)
    nx = eager.sizes['V']
    assert len(rows) - 1 == eager.sizes['Omega'] * nx
    missing = {'fate': -128, 'collisions': -1, 'reversals': -1}
    for row in rows[1:]:
        k = int(row[0])
        i, j = divmod(k, nx)
        point = eager.isel(Omega=i, V=j)
        assert float(row[1]) == point['V'].item()
        assert float(row[2]) == point['Omega'].item()
        for name, text in zip(NAMES, row[3:]):
            v = point[name].item()
            if name == 'status':
                assert v == getattr(c, text), (k, text)
            elif text == '':
                assert (np.isnan(v) if name in ('E_final', 'V_final')
                        else v == missing[name]), (k, name)
            elif name in ('E_final', 'V_final'):
                # %.17g reads back as the same double
                assert np.float64(text).view(np.int64) == \
                    np.float64(v).view(np.int64), (k, name)
            else:
                assert int(text) == v, (k, name)


def test_failed_points(eager):
    """V = 0 is not a state just after a collision: ESTATE, no fate."""
    col = eager.isel(V=20)
    assert col['V'].item() == 0.0
    assert (col['status'] == c.ESTATE).all()
    assert (col['fate'] == c.dataset.NO_FATE).all()
    assert (col['collisions'] == -1).all() and (col['reversals'] == -1).all()
    assert np.isnan(col['E_final']).all() and np.isnan(col['V_final']).all()
    rest = eager.drop_isel(V=20)
    assert (rest['status'] == c.SUCCESS).all()
    assert set(np.unique(rest['fate'].values)) <= {-1, 0, 1, 2}
    # both straight motions occur: the basins interleave
    assert {-1, 1} <= set(np.unique(rest['fate'].values))


@pytest.mark.parametrize('chunks', [(7, 13), ((23,), (41,)), (1, 41),
                                    'auto', ((5, 18), (40, 1))])
@pytest.mark.parametrize('scheduler', ['synchronous', 'threads'])
def test_chunkings_and_schedulers(eager, chunks, scheduler):
    lazy = c.atlas(SCENE, chunks=chunks)
    assert lazy['fate'].chunks is not None
    assert same(eager, lazy.compute(scheduler=scheduler))


def test_skate_per_point(program, tmp_path):
    """An atlas over L0 (a skate per point) as the program gives it, also
    chunked."""
    eager = c.atlas(SKATES)
    assert eager['fate'].dims == ('V', 'L0')
    rows = program_rows(program, SKATES, tmp_path)
    fate = [int(r[3]) for r in rows[1:]]
    assert fate == eager['fate'].values.reshape(-1).tolist()
    assert same(eager, c.atlas(SKATES, chunks=(4, 5)).compute(
        scheduler='synchronous'))


def test_distributed_two_workers(eager):
    """A LocalCluster of two worker processes (the same code as a real
    cluster: the tasks carry the scene's text): two chunkings, the same
    bits as the eager atlas (itself the program's)."""
    distributed = pytest.importorskip('distributed')
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1,
                                  processes=True, dashboard_address=None,
                                  silence_logs=50) as cluster, \
            distributed.Client(cluster) as client:
        assert len(client.scheduler_info()['workers']) == 2
        for chunks in [(6, 10), (23, 3)]:
            lazy = c.atlas(SCENE, chunks=chunks)
            futures = client.compute(lazy)
            assert same(eager, futures.result())
        # both workers computed chunks
        who = client.run(lambda dask_worker: len(dask_worker.log))
        assert len(who) == 2


def test_pickles(eager):
    for ds in (eager, c.atlas(SCENE, chunks=(8, 8))):
        # protocols 0 and 1 cannot pickle xarray's objects (__slots__
        # without __getstate__); process pools use the highest
        for protocol in range(2, pickle.HIGHEST_PROTOCOL + 1):
            back = pickle.loads(pickle.dumps(ds, protocol))
            assert back.attrs == ds.attrs
            assert same(ds.compute(scheduler='synchronous'),
                        back.compute(scheduler='synchronous'))


def test_netcdf_and_zarr(eager, tmp_path):
    pytest.importorskip('netCDF4')
    path = tmp_path / 'atlas.nc'
    eager.to_netcdf(path)
    with xr.open_dataset(path, mask_and_scale=False) as raw:
        assert same(eager, raw.load())
        assert raw.attrs['scene'] == eager.attrs['scene']
    with xr.open_dataset(path) as decoded:
        # the _FillValue of the points without a fate reads back masked
        assert np.isnan(decoded['fate'].isel(V=20)).all()
        assert (decoded['fate'].isel(V=0) == eager['fate'].isel(V=0)).all()
    zarr = pytest.importorskip('zarr')
    assert zarr
    store = tmp_path / 'atlas.zarr'
    c.atlas(SCENE, chunks=(7, 13)).to_zarr(store)
    with xr.open_zarr(store, mask_and_scale=False) as back:
        assert same(eager, back.compute(scheduler='synchronous'))


def test_provenance_scene_runs_again(eager, tmp_path):
    """attrs['scene'], the effective scene, is a scene file of the same
    atlas."""
    path = tmp_path / 'again.ini'
    path.write_text(eager.attrs['scene'])
    assert same(eager, c.atlas(str(path)))
    assert eager.attrs['title'] == 'test atlas'
    assert eager.attrs['function'] == 'chaplygin_discrete_basins'
    assert eager.attrs['x'] == 'V' and eager.attrs['y'] == 'Omega'


def test_threads_do_not_matter(eager):
    assert same(eager, c.atlas(SCENE, threads=1))
    assert same(eager, c.atlas(SCENE, threads=2))


def test_errors(tmp_path):
    basins = {'scene': {'model': 'discrete'},
              'parameters': {'L0': -0.5, 'Delta': 1},
              'initial': {'Omega': 0.8}, 'run': {'collisions': 10},
              'sweep': {'kind': 'basins', 'x_min': 0.1, 'x_max': 0.5,
                        'nx': 3}}
    with pytest.raises(c.SceneError, match='not an atlas'):
        c.atlas(basins)
    with pytest.raises(c.SceneError, match=r"\[sweep\] x: value 'theta'"):
        c.atlas(dict(SCENE, sweep=dict(SCENE['sweep'], x='theta')))
    with pytest.raises(c.SceneError, match='cannot open'):
        c.atlas(str(tmp_path / 'no-such.ini'))
    with pytest.raises(TypeError):
        c.atlas(3)
    with pytest.raises(ValueError):
        c.atlas(SCENE, threads=-1)
    with pytest.raises(ValueError):
        c.atlas(SCENE, chunks=(0, 5))
    # the row limit applies to the grid, or to each chunk
    small = dict(SCENE, run=dict(SCENE['run'], max_rows=100))
    with pytest.raises(c.SceneError, match='max_rows = 100'):
        c.atlas(small)
    lazy = c.atlas(small, chunks=(4, 20))
    assert lazy['fate'].shape == (23, 41)
    assert same(c.atlas(SCENE), lazy.compute(scheduler='synchronous'))
    with pytest.raises(c.SceneError, match='max_rows = 100'):
        c.atlas(small, chunks=(10, 41)).compute(scheduler='synchronous')


# ---------------------------------------------------------------------------
# The science scenes of the manual (scenes/atlas-*.ini)

def b13_fates(V, Omega, Delta=1.0):
    """Fates of the symmetric skate L0 = -Delta/2 predicted by (B.13) (a
    different route: the closed form of the sequence, not the iterated
    map): above c_0 = V^2/Omega^2 of the n = 0 member forward, then
    alternating between consecutive members (erratum E15)."""
    members = []
    n = 0
    ratio = (np.asarray(V) / np.asarray(Omega)) ** 2
    while True:
        cn = c.discrete.spin_sequence(Delta, n)
        members.append(cn)
        if cn < ratio.min() / 4:
            break
        n += 1
    above = (np.array(members) > ratio[..., None]).sum(axis=-1)
    return np.where(above % 2 == 0, 1, -1), len(members)


def test_similar_results_for_other_angular_velocities(srcdir):
    """Figure 3's skate over (V+, Omega+): every one of the 160000 fates is
    (B.13)'s (the basins are wedges V+/Omega+ between members): the
    paper's 'similar results hold for different initial angular
    velocities', exactly."""
    ds = c.atlas(os.path.join(srcdir, 'scenes', 'atlas-omega.ini'))
    V, Om = np.meshgrid(ds['V'].values, ds['Omega'].values)
    pred, members = b13_fates(V, Om)
    assert members > 10
    assert (ds['status'] == c.SUCCESS).all()
    assert np.array_equal(ds['fate'].values, pred)
    # wedges through the origin: both fates along every row whose V+/Omega+
    # reaches below c_0, and forward above it, V+/Omega+ > sqrt(5)/4 (the
    # caption's 1/sqrt(5) at Omega+ = 4/5)
    rows = ds['Omega'].values > 0.01
    assert (np.diff(ds['fate'].values[rows], axis=1) != 0).any(axis=1).all()
    assert (ds['fate'].values[V / Om > np.sqrt(5) / 4 * (1 + 1e-12)] == 1).all()


def test_bistable_band(srcdir):
    """Over (L0/Delta, V+) at Delta = 1, Omega+ = 4/5: the column L0 = -1/2
    is Figure 3 ((B.13)); a motion with 2E/H^2 > 1 never reverses for
    L0 >= -1/2, and does, ending backward, in a band of L0 < -1/2 (the
    skate's r* > 1 there: erratum E14)."""
    ds = c.atlas(os.path.join(srcdir, 'scenes', 'atlas-bistable.ini'))
    L0, V = ds['L0'].values, ds['V'].values
    fate, rev = ds['fate'].values, ds['reversals'].values
    assert (ds['status'] == c.SUCCESS).all()
    assert set(np.unique(fate)) == {-1, 1}
    j = int(np.flatnonzero(L0 == -0.5)[0])
    assert np.array_equal(fate[:, j], b13_fates(V, 0.8)[0])
    n0 = 1 + L0[None, :] ** 2       # the peg at D = 0: l0 = L0
    r = (V[:, None] ** 2 + n0 * 0.8 ** 2) / (n0 ** 2 * 0.8 ** 2)
    e14 = (r > 1 + 1e-12) & (rev > 0)
    assert not e14[:, L0 >= -0.5].any()
    assert e14.sum() > 1000 and (fate[e14] == -1).all()
    assert L0[e14.any(axis=0)].max() < -0.6
    # the interleaved basins: only in a band around the symmetric skate
    both = (fate == 1).any(axis=0) & (fate == -1).any(axis=0)
    assert L0[both].min() == -0.735 and L0[both].max() == -0.38
    assert (fate[:, L0 < -0.735] == -1).all()
    assert (fate[:, L0 > -0.38] == 1).all()


def test_certified_decides_the_near_tie(srcdir, tmp_path):
    """The one point of the bistable atlas the doubles cannot follow: L0 =
    -3/4, V+ = 3/4, where 2E/H^2 = 1 but for the rounding of Omega+ = 0.8
    (a hair above 4/5): its first segment reverses with V = 0 at l = 0
    to within ~1e-17.  The certified method, on the one Dask chunk that
    holds it, decides: one reversal, then backward with E_final the
    nearest double to the exact value computed here in fractions."""
    from fractions import Fraction as F
    path = tmp_path / 'certified.ini'
    text = open(os.path.join(srcdir, 'scenes', 'atlas-bistable.ini')).read()
    path.write_text(text.replace('[run]\n', '[run]\nmethod = certified\n'))
    lazy = c.atlas(str(path), chunks=(20, 20))
    point = lazy.sel(L0=-0.75, V=0.75).compute(scheduler='synchronous')
    closed = c.atlas(os.path.join(srcdir, 'scenes', 'atlas-bistable.ini')) \
        .sel(L0=-0.75, V=0.75)
    # exact: u = V^2 = 9/16, H = (1 + l0^2) Omega = 25/16 Omega; the
    # reversal (B.4) keeps u and multiplies H by C2 = 13/25; the way back
    # from l = 1/4 to -3/4 then passes for good, u_final = u + k H'^2
    # with k = 400/969 (fate.c's k), E_final = u_final/2
    Om = F(0.8)
    assert Om > F(4, 5)
    H1 = F(13, 25) * F(25, 16) * Om
    E_final = (F(9, 16) + F(400, 969) * H1 ** 2) / 2
    assert point['fate'].item() == -1
    assert (point['collisions'].item(), point['reversals'].item()) == (1, 1)
    assert point['E_final'].item() == float(E_final)
    # the doubles end backward too, but after a detour (two collisions)
    # and with another final energy
    assert closed['fate'].item() == -1
    assert closed['collisions'].item() == 2
    assert abs(closed['E_final'].item() - float(E_final)) > 0.1


def test_fates_phase_is_basins_point_by_point():
    """discrete.fates_phase, the batch kernel of the atlas, against
    discrete.basins on the one-point grid of each point: the same fates bit
    for bit, failures alone (V = 0, NaN)."""
    sys_ = c.discrete.init(-0.5, 1.0)
    rng = np.random.default_rng(29)
    V = np.concatenate([rng.uniform(-1, 1, 300), [0.0, np.nan, 1e-300,
                                                   1e200, -0.75]])
    Om = np.concatenate([rng.uniform(-2, 2, 300), [0.8, 0.8, 1e-300, 1e200,
                                                    0.8]])
    got, status = c.discrete.fates_phase(sys_, V, Om, 10**5,
                                         errors='return')
    for i in range(V.size):
        one, st = c.discrete.basins(sys_, Om[i], V[i], V[i], 1, 10**5,
                                    errors='return') \
            if np.isfinite(V[i]) else (None, [c.EDOM])
        assert status[i] == st[0], i
        if st[0] == 0:         # field by field: padding is no value
            for name in c.Fate.dtype.names:
                assert got[i][name].tobytes() == one[0][name].tobytes(), i
    assert status[300] == c.ESTATE and status[301] == c.EDOM
    with pytest.raises(c.StateError):
        c.discrete.fates_phase(sys_, [0.3, 0.0], 0.8, 10)
    f = c.discrete.fates_phase(sys_, 0.3, 0.8, 10**5)
    assert isinstance(f, c.Fate) and f.kind == -1
