"""pytest setup for the FE reference tests: make fea/ importable, find the tools."""
import os
import sys

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FEA = os.path.join(REPO, "fea")
sys.path.insert(0, FEA)


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
