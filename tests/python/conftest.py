"""pytest configuration of the Python tests: the contractor test kit
(contractor_kit.py, beside this file) is importable by every test module,
whatever pytest's import mode."""
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
