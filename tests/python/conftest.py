"""pytest configuration of the Python tests: the helpers beside this file
(turning_vehicle.py, itf1788_adapter.py) are importable by every test module,
whatever pytest's import mode. The contractor test kit is sillage.testing."""
import os
import signal
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


@pytest.fixture
def sigint_raises():
    """SIGINT raises KeyboardInterrupt during the test, as in an interactive session, even when the
    suite was started with SIGINT ignored (a background job of a non-interactive shell inherits
    that, and Python then installs no handler): the Ctrl-C tests send themselves SIGINT."""
    old = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, old)


@pytest.fixture(scope="session")
def dask_client():
    """A Client of a real local Dask cluster, 2 worker processes of one thread (tests of
    sillage.distributed), started once for the session and shut down after it; skipped where
    Dask distributed is not installed."""
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=":0") as cluster, distributed.Client(cluster) as client:
        yield client
