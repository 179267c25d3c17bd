"""Load committed FE results: the CSV and the case it came from (via data/fea/manifest.json)."""
from __future__ import annotations

import os
import shlex
from dataclasses import dataclass, replace

import numpy as np

from ellc_fea.case import Case, load_case
from ellc_fea.curve import read_csv
from ellc_fea.manifest import read_manifest

from .law_oracle import Contact, make_contact

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATA = os.path.join(REPO, "data", "fea")


@dataclass
class Run:
    name: str
    case: Case
    record: dict
    overlap: np.ndarray
    force: np.ndarray
    table: dict

    @property
    def case_file(self) -> str:
        """The case TOML, relative to the repository (from the recorded command)."""
        return case_file_of(self.record)

    def contact(self, exact: bool = False, constants: dict | None = None) -> Contact:
        m, semi = self.case.material, (lambda b: (b.a, b.b, b.c))
        return make_contact(semi(self.case.body_i), semi(self.case.body_j), m.youngs_modulus,
                            m.poisson_ratio, m.yield_stress, exact=exact, constants=constants)


def case_file_of(record: dict) -> str:
    return shlex.split(record["command"])[1]


def load_run(name: str, data_dir: str = DATA, status: str = "complete") -> Run | None:
    """The run `name` with that manifest status ("complete": NAME.csv; "incomplete": the converged
    increments of a stopped run, NAME.incomplete.csv), or None if there is no such CSV."""
    record = read_manifest(os.path.join(data_dir, "manifest.json")).get(name)
    suffix = ".csv" if status == "complete" else ".incomplete.csv"
    csv = os.path.join(data_dir, f"{name}{suffix}")
    if record is None or record.get("status") != status or not os.path.exists(csv):
        return None
    case = replace(load_case(os.path.join(REPO, case_file_of(record))), name=name,
                   points_per_segment=record["points_per_segment"])
    table = read_csv(csv)
    return Run(name, case, record, table["overlap"], table["force"], table)


def complete_runs(prefix: str, data_dir: str = DATA) -> list[Run]:
    names = sorted(read_manifest(os.path.join(data_dir, "manifest.json")))
    runs = [load_run(n, data_dir) for n in names if n.startswith(prefix)]
    return [r for r in runs if r is not None]
