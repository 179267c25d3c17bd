"""Markdown tables for docs/validation.md."""
from __future__ import annotations


def markdown_table(header: list[str], align: str, rows: list[list[str]]) -> list[str]:
    """align: one character per column, 'l' or 'r'."""
    rule = ["---:" if a == "r" else "---" for a in align]
    return ["| " + " | ".join(r) + " |" for r in [header, rule, *rows]]


def pct(value: float, digits: int = 2, sign: bool = False) -> str:
    return f"{100 * value:{'+' if sign else ''}.{digits}f} %"
