"""Where probesim keeps what it may reuse across processes (the stage readings of
:mod:`simulator.scene.stage_disk`).

As Warp does for its kernel cache (``WARP_CACHE_PATH``), the folder is the
user's cache folder unless an environment variable names another:

- ``PROBESIM_CACHE_PATH`` set to a folder: that folder; set to an empty
  string: nothing is kept across processes;
- otherwise ``$XDG_CACHE_HOME/probesim`` (``~/.cache/probesim`` where that is
  unset) on Linux and other Unix systems, ``~/Library/Caches/probesim`` on
  macOS, ``%LOCALAPPDATA%\\probesim\\Cache`` on Windows.

Nothing here creates the folder: its user does, when it first writes there.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

__all__ = ["ENV", "cache_root"]

#: the environment variable that moves the folder (or, empty, turns keeping off)
ENV = "PROBESIM_CACHE_PATH"


def cache_root() -> Path | None:
    """The folder probesim's cross-process caches live under, or None when ``PROBESIM_CACHE_PATH`` is
    set empty (or no home folder can be found)."""
    named = os.environ.get(ENV)
    if named is not None:
        return Path(named).expanduser().absolute() if named.strip() else None
    try:
        home = Path.home()
    except (RuntimeError, KeyError):  # no home folder known (a bare service account)
        return None
    if sys.platform == "win32":
        base = os.environ.get("LOCALAPPDATA")
        return (Path(base) if base else home / "AppData" / "Local") / "probesim" / "Cache"
    if sys.platform == "darwin":
        return home / "Library" / "Caches" / "probesim"
    xdg = os.environ.get("XDG_CACHE_HOME")
    return (Path(xdg) if xdg and os.path.isabs(xdg) else home / ".cache") / "probesim"
