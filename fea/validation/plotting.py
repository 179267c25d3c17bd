"""Matplotlib set-up shared by the validation figures (Agg backend, one style)."""
from __future__ import annotations

import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
IMG = os.path.join(REPO, "docs", "img", "validation")


def figure(ncols: int = 1, width: float = 5.5, height: float = 4.0):
    fig, axes = plt.subplots(1, ncols, figsize=(width * ncols, height), squeeze=False)
    return fig, axes[0]


def save(fig, name: str) -> str:
    os.makedirs(IMG, exist_ok=True)
    path = os.path.join(IMG, name)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return os.path.relpath(path, REPO)
