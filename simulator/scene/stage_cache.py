"""The stages a Python process has read, kept for its next runs (``simulator.run`` in a loop).

A run reads its stage through :func:`cached_stage`. The reading is kept
under the stage's *selection* — its path, light units, radiometric spectrum,
variant selections and time code — together with the *identity* of every
file the reading depended on (:attr:`simulator.scene.model.Scene.sources`,
plus every file Python opened while reading, seen by an audit hook): its
path, size, inode, modification and change times in nanoseconds. A later
run with the same selection gets the kept scene only while every one of
those files still stats the same; an edited, replaced, touched or removed
file makes it read the stage afresh.

A reading is kept only if none of its files was modified later than
:data:`RACY_NS` before the reading began: a file edited while it was being
read, or just before on a file system whose clock ticks coarsely, could
otherwise state the new times beside the old content (the "racy" case git
guards its index against). Such a reading is used once; the next run reads
again and keeps that reading once its files have settled.

Each use hands out a deep copy, so a caller that changes the scene it was
given cannot change what later runs read. The cache holds the
:data:`MAX_ENTRIES` most recently used stages (at most :data:`MAX_BYTES` of
arrays in all; none bigger than :data:`MAX_ENTRY_BYTES`); :func:`clear`
empties it.

A reading it keeps is also written to disk (:mod:`simulator.scene.stage_disk`),
validated there as strictly and besides by the code that made it, so that the
first run of a new process skips the reader when nothing changed; a process
with no reading in memory asks there before reading.
"""

from __future__ import annotations

import copy
import hashlib
import json
import os
import sys
import threading
import time
from dataclasses import dataclass
from itertools import count

import numpy as np

from simulator import cache_path
from simulator.memo import Kept
from simulator.scene import stage_disk
from simulator.scene.stage_disk import file_identity

__all__ = ["MAX_ENTRIES", "MAX_BYTES", "MAX_ENTRY_BYTES", "RACY_NS", "cached_stage", "clear", "stats", "file_identity",
           "file_sha256", "usd_version"]

#: stages kept (least recently used dropped first)
MAX_ENTRIES = 4
#: array bytes kept in all (geometry, texture maps)
MAX_BYTES = 1 << 29
#: a stage with more array bytes than this is read but not kept (a one-off run of a big stage is
#: not charged a second copy)
MAX_ENTRY_BYTES = 1 << 28
#: a reading is kept only if every file it read was last modified this many nanoseconds before it began
#: (one bound with the caches kept across processes, :data:`simulator.cache_path.RACY_NS`)
RACY_NS = cache_path.RACY_NS

_entries = Kept(MAX_ENTRIES, MAX_BYTES)  # selection -> _Entry, sized by its array bytes
_serial = count(1)
_counts = {"hits": 0, "reads": 0, "disk_hits": 0}
_opened = threading.local()  # .files: the paths Python opened while this thread reads a stage


@dataclass
class _Entry:
    scene: object
    token: int  #: unique per reading: what later caches (the plan) key on
    identity: dict  #: path -> (size, inode, mtime_ns, ctime_ns)


def _audit(event: str, args: tuple) -> None:
    """Audit hook: note each path opened while a stage is read on this thread."""
    files = getattr(_opened, "files", None)
    if files is None or event != "open":
        return
    path = args[0]
    if isinstance(path, (str, bytes, os.PathLike)):
        path = os.fsdecode(path)
        if not path.endswith(_CODE_SUFFIXES):  # modules imported on the way are not the stage's
            files.add(os.path.abspath(path))


_hooked = False
_CODE_SUFFIXES = (".py", ".pyc", ".so", ".pyd", ".pth")


def _ensure_hook() -> None:
    global _hooked
    if not _hooked:
        sys.addaudithook(_audit)
        _hooked = True


def _selection(path, light_units, radiometric_spectrum, variants, time_code) -> str:
    return json.dumps([os.path.abspath(os.fspath(path)), light_units, repr(radiometric_spectrum),
                       variants or {}, None if time_code is None else float(time_code)], sort_keys=True, default=repr)


def _array_bytes(scene) -> int:
    g = scene.geometry
    n = sum(v.nbytes for v in vars(g).values() if isinstance(v, np.ndarray))
    return n + sum(l.texture_map.nbytes for l in scene.lights if getattr(l, "texture_map", None) is not None)


def _still_valid(e: _Entry) -> bool:
    return all(file_identity(path) == ident for path, ident in e.identity.items())


def cached_stage(read, path, light_units: str, radiometric_spectrum, variants: dict | None, time_code) -> tuple:
    """``(scene, token)``: the stage read by ``read()`` (a :class:`~simulator.scene.model.Scene`), or a
    copy of the one kept for this selection if none of its files changed.

    Parameters
    ----------
    read : callable
        Reads the stage afresh (the stage reader with these arguments).
    path, light_units, radiometric_spectrum, variants, time_code
        The selection the reading is kept under.

    Returns
    -------
    (Scene, int or None)
        ``token`` is the same for every copy of one reading and new with each
        reading; None when the reading is not kept (its file list is not
        known whole, or it is too big).
    """
    key = _selection(path, light_units, radiometric_spectrum, variants, time_code)
    e = _entries.get(key, valid=_still_valid)  # an entry whose files changed is dropped
    if e is not None:
        _counts["hits"] += 1
        return copy.deepcopy(e.scene), e.token
    on_disk = stage_disk.load(key)
    if on_disk is not None:
        scene, identity, read_by = on_disk
        _counts["disk_hits"] += 1
        _read_by["usd"] = read_by
        e = _Entry(copy.deepcopy(scene), next(_serial), identity)
        _entries.put(key, e, size=_array_bytes(scene))
        return scene, e.token
    _ensure_hook()
    began_ns = time.time_ns()
    _opened.files = set()
    try:
        scene = read()
        opened = _opened.files
    finally:
        _opened.files = None
    _counts["reads"] += 1
    if scene.sources is None:
        return scene, None
    files = sorted(set(scene.sources) | {p for p in opened if os.path.isfile(p)})
    identity = {p: file_identity(p) for p in files}
    if any(v is None or v[2] > began_ns - RACY_NS for v in identity.values()):
        return scene, None  # gone, or modified too recently to trust its times: used once, not kept
    nbytes = _array_bytes(scene)
    if nbytes > MAX_ENTRY_BYTES:
        return scene, None
    e = _Entry(copy.deepcopy(scene), next(_serial), identity)
    _entries.put(key, e, size=nbytes)
    stage_disk.save(key, scene, identity, usd_version())
    return scene, e.token


_digests = Kept(4 * MAX_ENTRIES)  # path -> (identity, SHA-256 hex)


def file_sha256(path) -> str:
    """SHA-256 (hex) of a file's bytes, kept while the file stats the same and was not modified within
    :data:`RACY_NS` of being hashed (the run record's stage digest: a big stage is not hashed again by
    every run)."""
    path = os.path.abspath(os.fspath(path))
    ident = file_identity(path)
    kept = _digests.get(path)
    if kept is not None and ident is not None and kept[0] == ident:
        return kept[1]
    stat_ns = time.time_ns()
    with open(path, "rb") as f:
        digest = hashlib.sha256(f.read()).hexdigest()
    if ident is not None and ident == file_identity(path) and stat_ns - ident[2] >= RACY_NS:
        _digests.put(path, (ident, digest))
    return digest


_read_by = {}  # "usd": the OpenUSD version that made the reading taken from disk


def usd_version() -> str:
    """The OpenUSD version of the stage reader: asked of ``pxr`` once it is loaded; before that, the
    version that made a reading taken from disk (the same ``pxr`` files: the entry checks them), so a
    run whose stage came from disk does not import ``pxr`` for its run record."""
    if "pxr" not in sys.modules and "usd" in _read_by:
        return _read_by["usd"]
    from simulator.scene.usd import usd_version as asked

    return asked()


def clear() -> None:
    """Forget every kept stage and file digest."""
    _entries.clear()
    _digests.clear()


def stats() -> dict:
    """``{"hits", "reads", "disk_hits", "entries"}``: uses of a kept stage, fresh readings, readings taken
    from disk (:mod:`simulator.scene.stage_disk`), stages kept now."""
    return {**_counts, "entries": len(_entries)}
