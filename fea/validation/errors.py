"""Force-error measures between the law and an FE curve (definitions used in validation.md)."""
from __future__ import annotations

import numpy as np


def force_errors(law: np.ndarray, fe: np.ndarray, floor: float = 0.1) -> dict:
    """mean/max of |F_law - F_FE| / F_FE over points with F_FE > floor * max F_FE, and
    mean/max of |F_law - F_FE| / max F_FE over all points (fair near separation)."""
    law, fe = np.asarray(law, float), np.asarray(fe, float)
    peak = float(fe.max())
    sel = fe > floor * peak
    rel = np.abs(law[sel] - fe[sel]) / fe[sel]
    norm = np.abs(law - fe) / peak
    return {"mean_rel": float(rel.mean()), "max_rel": float(rel.max()),
            "mean_of_peak": float(norm.mean()), "max_of_peak": float(norm.max()), "points": int(sel.sum())}
