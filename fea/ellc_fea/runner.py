"""Run CalculiX on a deck and tell whether it finished every step."""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import time
from dataclasses import dataclass

CCX_NAMES = ("ccx", "ccx_2.20", "ccx_2.21", "ccx_2.19")


def find_ccx() -> str | None:
    for name in CCX_NAMES:
        path = shutil.which(name)
        if path:
            return path
    return None


def ccx_version(ccx: str) -> str:
    try:
        out = subprocess.run([ccx, "-v"], capture_output=True, text=True, timeout=30).stdout
    except (OSError, subprocess.TimeoutExpired):
        return "unknown"
    m = re.search(r"Version\s+(\S+)", out)
    return f"CalculiX {m.group(1)}" if m else "unknown"


@dataclass
class RunResult:
    returncode: int
    seconds: float
    finished: bool      # ccx reported "Job finished"
    error: str          # first *ERROR line, if any


def run_ccx(ccx: str, workdir: str, job: str, threads: int = 1) -> RunResult:
    """Run `ccx -i job` in workdir with stdout/stderr to job.log."""
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), CCX_NPROC_EQUATION_SOLVER=str(threads))
    start = time.monotonic()
    with open(os.path.join(workdir, f"{job}.log"), "w") as log:
        proc = subprocess.run([ccx, "-i", job], cwd=workdir, stdout=log, stderr=subprocess.STDOUT,
                              env=env)
    return read_log(workdir, job, proc.returncode, time.monotonic() - start)


def read_log(workdir: str, job: str, returncode: int = 0, seconds: float = float("nan")) -> RunResult:
    """Judge a finished (or earlier) ccx run from its log."""
    with open(os.path.join(workdir, f"{job}.log"), errors="replace") as log:
        text = log.read()
    errors = [ln.strip() for ln in text.splitlines() if "*ERROR" in ln]
    return RunResult(returncode, seconds, "Job finished" in text, errors[0] if errors else "")
