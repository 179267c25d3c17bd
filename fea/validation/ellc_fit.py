"""Run the C++ `ellc fit` on the committed grid data, when the CLI has it."""
from __future__ import annotations

import os
import subprocess
import tempfile
import tomllib

from .curves import REPO, ellc_binary


def ellc_fit(runs, extra: tuple[str, ...] = ()) -> dict | None:
    """[model] constants from `ellc fit DATA.csv:CASE.toml ...`, or None without the CLI."""
    binary = ellc_binary()
    if binary is None or len(runs) < 3:
        return None
    data = [f"{os.path.join(REPO, 'data', 'fea', r.name + '.csv')}:{os.path.join(REPO, r.case_file)}"
            for r in runs]
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "model.toml")
        proc = subprocess.run([binary, "fit", *data, "-o", out, *extra], capture_output=True, text=True)
        if proc.returncode != 0:
            return None
        with open(out, "rb") as fh:
            model = tomllib.load(fh)["model"]
    return {k: float(model[k]) for k in ("m", "o", "p", "s", "t", "u", "n")}

