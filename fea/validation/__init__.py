"""Validation write-up tools: compare the contact law with the FE reference.

TEST ORACLE ONLY. `law_oracle` re-states the Becker-Kamlah formulas of
docs/model.md in Python so that the FE data can be checked and plotted
before the C++ library (the one production implementation) is available.  Nothing outside
fea/validation and tests/fea may import it; the comparison prefers `ellc curve` when ELLC_BIN
points at the built CLI (see curves.py).
"""
