"""Where probesim keeps what it may reuse across processes (the stage readings of
:mod:`simulator.scene.stage_disk`, the Warp module hashes of :mod:`simulator.engine.kernel_hashes`),
and since when this process runs (what those trust only code modified before).

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

__all__ = ["ENV", "RACY_NS", "cache_folder", "cache_root", "process_started_ns", "settled_before_start"]

#: the environment variable that moves the folder (or, empty, turns keeping off)
ENV = "PROBESIM_CACHE_PATH"
#: a file is trusted to be what its times say only if it was last modified this long before it was read
#: (a coarse file-system clock can give an edit in the same tick the old times; the "racy" case git
#: guards its index against); the in-process stage cache uses the same bound
RACY_NS = 2_000_000_000


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


def cache_folder(name: str) -> Path | None:
    """The folder ``name`` under :func:`cache_root` (one per kind of entry), or None when keeping is off."""
    root = cache_root()
    return None if root is None else root / name


def _started_ns() -> int:
    """When this process began, in ns since the epoch, rounded down to the second before (Linux: from
    ``/proc``); elsewhere, or if that cannot be read, when probesim was imported."""
    try:
        with open("/proc/self/stat", "rb") as f:
            fields = f.read().rsplit(b")", 1)[1].split()
        ticks = int(fields[19])  # field 22, starttime: clock ticks after boot
        with open("/proc/stat", "rb") as f:
            btime = next(int(line.split()[1]) for line in f if line.startswith(b"btime "))
        return (btime - 1) * 1_000_000_000 + ticks * 1_000_000_000 // os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError, StopIteration, AttributeError):
        import simulator

        return simulator._LOADED_NS


_STARTED: list = []


def process_started_ns() -> int:
    """When this process began (ns since the epoch, never later than it did): every module it runs was
    read after it. Read once."""
    if not _STARTED:
        _STARTED.append(_started_ns())
    return _STARTED[0]


def settled_before_start(identities) -> bool:
    """Whether every ``(size, inode, mtime_ns, ctime_ns)`` in ``identities`` was last modified at least
    :data:`RACY_NS` before this process began: code the process read then is the code those times
    describe (a module edited while the process ran, or just before, is not trusted)."""
    settled = process_started_ns() - RACY_NS
    return all(v[2] <= settled for v in identities)
