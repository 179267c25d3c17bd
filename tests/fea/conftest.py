"""pytest setup for the FE reference tests: make fea/ importable, find the tools."""
import os
import sys

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FEA = os.path.join(REPO, "fea")
sys.path.insert(0, FEA)

from validation.curves import ellc_binary  # noqa: E402  (needs fea/ on the path)


def have_fe_tools() -> bool:
    try:
        import gmsh  # noqa: F401
    except ImportError:
        return False
    from ellc_fea.runner import find_ccx
    return find_ccx() is not None


@pytest.fixture
def needs_fe_tools():
    if not have_fe_tools():
        print("SKIP: gmsh (python3-gmsh) or CalculiX (ccx) not installed")
        pytest.skip("gmsh (python3-gmsh) or CalculiX (ccx) not installed")


@pytest.fixture
def repo():
    return REPO


@pytest.fixture(scope="module")
def cli():
    """The `ellc` CLI (ELLC_BIN, else build*/apps/ellc/ellc); skips the test without it."""
    binary = ellc_binary()
    if binary is None:
        print("SKIP: ellc CLI not built (set ELLC_BIN=/path/to/ellc)")
        pytest.skip("ellc CLI not built (set ELLC_BIN=/path/to/ellc)")
    return binary
