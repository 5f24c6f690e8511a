"""Paths in a config or on the command line, made absolute."""

from __future__ import annotations

import os
from pathlib import Path

__all__ = ["resolve_path"]


def resolve_path(base: Path, text: str | os.PathLike) -> Path:
    """``text`` (``~`` expanded) as an absolute path; a relative one is taken from folder ``base``."""
    p = Path(text).expanduser()
    if not p.is_absolute():
        p = base / p
    return p.resolve()
