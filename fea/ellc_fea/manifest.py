"""data/fea/manifest.json: one record per case (command, mesh, CalculiX version, run time, status)."""
from __future__ import annotations

import fcntl
import json
import os


def update_manifest(path: str, name: str, record: dict) -> None:
    """Insert or replace the record of case `name`, keeping the file sorted and readable."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "a+") as fh:
        fcntl.flock(fh, fcntl.LOCK_EX)
        fh.seek(0)
        text = fh.read()
        data = json.loads(text) if text.strip() else {}
        data[name] = record
        fh.seek(0)
        fh.truncate()
        json.dump(dict(sorted(data.items())), fh, indent=1)
        fh.write("\n")


def read_manifest(path: str) -> dict:
    if not os.path.exists(path):
        return {}
    with open(path) as fh:
        return json.load(fh)
