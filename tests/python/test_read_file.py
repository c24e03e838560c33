"""The size limit of the files sillage reads: a file past it, a device or a
pipe that never ends are refused with an error naming the file, its size and
the limit; sillage.set_max_file_bytes and SILLAGE_MAX_FILE_BYTES change it."""
import os
import subprocess
import sys
import time

import pytest

import sillage as sl

HINT = "; raise it with SILLAGE_MAX_FILE_BYTES=<bytes> or set_max_file_bytes(bytes) (0: no limit)"


@pytest.fixture
def limit():
    """Sets the limit inside the test, the default after it."""
    yield sl.set_max_file_bytes
    sl.set_max_file_bytes(sl.DEFAULT_MAX_FILE_BYTES)


def test_default_limit():
    assert sl.DEFAULT_MAX_FILE_BYTES == 2**31 and sl.max_file_bytes() == 2**31


def test_a_file_past_the_limit_names_itself_its_size_and_the_limit(tmp_path, limit):
    csv = tmp_path / "ranges.csv"
    csv.write_text("t,r\n0,1\n1,2\n")  # 12 bytes
    tube = tmp_path / "x.tube"
    sl.save_tube(sl.Tube(sl.TDomain(0.0, 1.0, 0.5), sl.Interval(0, 1)), str(tube))
    limit(11)
    with pytest.raises(sl.Error) as e:
        sl.CsvTable.read(str(csv))
    assert str(e.value) == f"CsvTable::read: '{csv}' is 12 bytes, more than the limit of 11 bytes" + HINT
    with pytest.raises(sl.Error, match=r"^load tube: '.*x\.tube' is 136 bytes, more than the limit of 11 bytes"):
        sl.load_tube(str(tube))
    limit(0)  # no limit
    assert sl.CsvTable.read(str(csv)).nb_rows() == 2 and sl.max_file_bytes() == 0


def test_a_device_is_refused_at_once():
    start = time.monotonic()
    with pytest.raises(sl.Error, match=r"^CsvTable::read: '/dev/zero' is a device, not a CSV file"):
        sl.CsvTable.read("/dev/zero")
    with pytest.raises(sl.Error, match=r"^load tube: '/dev/zero' is a device, not a tube file"):
        sl.load_tube("/dev/zero")
    assert time.monotonic() - start < 1


def test_a_pipe_is_read_up_to_the_limit_only(tmp_path):
    """`yes` never ends: the reader stops past the limit (set for the process by the environment)."""
    script = "import sillage as sl\ntry:\n    sl.CsvTable.read('/dev/stdin')\nexcept sl.Error as e:\n    print(e)\n"
    yes = subprocess.Popen(["yes", "1,2"], stdout=subprocess.PIPE)
    env = dict(os.environ, SILLAGE_MAX_FILE_BYTES="100000")
    out = subprocess.run([sys.executable, "-c", script], stdin=yes.stdout, env=env, capture_output=True, text=True,
                         timeout=60)
    yes.kill()
    yes.wait()
    assert out.stdout == "CsvTable::read: '/dev/stdin' holds more than 100000 bytes (97.7 KiB), the limit" + HINT + "\n"


def test_a_bad_environment_value_is_an_error():
    script = "import sillage as sl\ntry:\n    sl.max_file_bytes()\nexcept sl.Error as e:\n    print(e)\n"
    env = dict(os.environ, SILLAGE_MAX_FILE_BYTES="2GB")
    out = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True, timeout=60)
    assert out.stdout == "SILLAGE_MAX_FILE_BYTES = '2GB' is not a number of bytes (0: no limit)\n"
