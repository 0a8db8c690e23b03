"""Files written by Python code of the package (issue 27: a failed write
never replaces an existing file).  The package's functions write no files
(run_scene and eq return data, to_ini a string); python/gen.py writes the
generated sources at build time through write_file: onto a full disk (a
small tmpfs, as root) and under a file-size limit (RLIMIT_FSIZE in a child)
it raises, the existing file keeps its bytes and no temporary is left."""
import errno
import importlib.util
import os
import resource
import subprocess
import sys
import textwrap

import pytest

from conftest import src

OLD = 'previous generated text\n' * 10
BIG = 'x' * 200000          # more than the room left


def gen_module():
    spec = importlib.util.spec_from_file_location('gen', src('python',
                                                             'gen.py'))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_replaces_when_complete(tmp_path):
    target = tmp_path / 'vec.c'
    target.write_text(OLD)
    gen_module().write_file(str(target), 'new\n')
    assert target.read_text() == 'new\n'
    assert os.listdir(tmp_path) == ['vec.c']


@pytest.fixture
def full_disk(tmp_path):
    """A 256 KiB tmpfs holding the target (OLD) and a filler that leaves
    4 KiB free."""
    if os.geteuid() != 0:
        pytest.skip('mounting a tmpfs needs root (the file-size limit '
                    'test covers the unprivileged case)')
    d = tmp_path / 'mnt'
    d.mkdir()
    r = subprocess.run(['mount', '-t', 'tmpfs', '-o', 'size=256k', 'tmpfs',
                        str(d)], capture_output=True, text=True)
    if r.returncode:
        pytest.skip('cannot mount a tmpfs here: %s' % r.stderr.strip())
    try:
        (d / 'vec.c').write_text(OLD)
        with open(d / 'filler', 'wb', buffering=0) as fh:
            try:
                while True:
                    fh.write(b'\0' * 4096)
            except OSError as e:
                assert e.errno == errno.ENOSPC
        os.truncate(d / 'filler', os.path.getsize(d / 'filler') - 4096)
        yield d
    finally:
        subprocess.run(['umount', str(d)], check=True)


def test_full_disk(full_disk):
    target = full_disk / 'vec.c'
    with pytest.raises(OSError) as e:
        gen_module().write_file(str(target), BIG)
    assert e.value.errno == errno.ENOSPC
    assert target.read_text() == OLD
    assert sorted(os.listdir(full_disk)) == ['filler', 'vec.c']


def test_file_size_limit(tmp_path):
    """RLIMIT_FSIZE of 64 KiB in a child: EFBIG (Python ignores SIGXFSZ)."""
    target = tmp_path / 'vec.c'
    target.write_text(OLD)
    code = textwrap.dedent('''
        import importlib.util, sys
        spec = importlib.util.spec_from_file_location('gen', sys.argv[1])
        gen = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(gen)
        gen.write_file(sys.argv[2], 'x' * 200000)
        ''')

    def limit():
        resource.setrlimit(resource.RLIMIT_FSIZE, (65536, 65536))
    r = subprocess.run([sys.executable, '-c', code, src('python', 'gen.py'),
                        str(target)], preexec_fn=limit, capture_output=True,
                       text=True)
    assert r.returncode == 1 and 'File too large' in r.stderr, r.stderr
    assert target.read_text() == OLD
    assert os.listdir(tmp_path) == ['vec.c']
