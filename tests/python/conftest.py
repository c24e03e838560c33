"""pytest configuration of the Python tests: the contractor test kit
(contractor_kit.py, beside this file) is importable by every test module,
whatever pytest's import mode."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
