"""Parse the CalculiX .dat file written by the deck of `deck.py`.

Each converged increment prints, in order: U of PILOTI and PILOTJ, RF totals of XI and XJ,
U of the symmetry-line sets, then the contact stress at active slave integration points.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

import numpy as np

_HEADER = re.compile(r"^\s*(?P<what>.+?) for (?:set (?P<set>\S+)|all contact elements) and time\s+(?P<time>\S+)")


@dataclass
class Increment:
    time: float                                        # step time of the increment
    u: dict[str, np.ndarray] = field(default_factory=dict)   # set -> (n, 4): node, ux, uy, uz
    rf: dict[str, np.ndarray] = field(default_factory=dict)  # set -> (3,) total force
    pressure: np.ndarray = field(default_factory=lambda: np.zeros(0))  # active contact pressures


def _blocks(lines: list[str]):
    """Yield (what, set or None, time, rows of floats)."""
    current = None
    for line in lines:
        m = _HEADER.match(line)
        if m:
            if current:
                yield current
            current = (m["what"], m["set"], float(m["time"]), [])
        elif current and line.strip():
            current[3].append([float(v) for v in line.split()])
    if current:
        yield current


def parse_dat(path: str) -> list[Increment]:
    with open(path) as fh:
        lines = fh.readlines()
    incs: list[Increment] = []
    for what, name, time, rows in _blocks(lines):
        if name == "PILOTI":
            incs.append(Increment(time=time))
        if not incs:
            continue
        inc = incs[-1]
        if what.startswith("displacements"):
            inc.u[name] = np.asarray(rows, dtype=float).reshape(-1, 4)
        elif what.startswith("total force"):
            inc.rf[name] = np.asarray(rows[0], dtype=float)
        elif what.startswith("contact stress"):
            arr = np.asarray(rows, dtype=float).reshape(-1, 5)
            inc.pressure = arr[:, 2]
    # the last increment may have been cut off mid-write: keep only complete ones
    return [i for i in incs if "PILOTJ" in i.u and "XI" in i.rf]
