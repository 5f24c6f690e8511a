"""Stage readings kept on disk, so that a new process running an unchanged stage skips the reader
(and importing ``pxr``): docs/DESIGN.md §Start-up of a small run.

:mod:`simulator.scene.stage_cache` keeps a reading in memory for the process's
later runs; what it keeps it also writes here (:func:`save`), and a process
that has no reading in memory asks here first (:func:`load`). An entry is
used only while all of these still hold:

- its *selection* and *context* are the same: stage path, light units,
  radiometric spectrum, variants and time code; the Python version and
  executable, the working folder and the environment variables that steer
  USD's asset resolution and plugins (``PXR_*``, ``TF_*``, ``USD_*``, ``AR_*``,
  ``PLUG_*``, ``MATERIALX*``, ``MTLX*``, ``OCIO*``) and probesim's own
  (``PROBESIM_*``, the cache's folder left out);
- every file the reading depended on stats the same (size, inode,
  modification and change times in nanoseconds: the files of the
  in-process cache, every layer, texture and photometric file);
- every file of the code that produced it stats the same: each module the
  process had loaded when it wrote the entry (the stage reader and the
  rest of probesim, ``pxr``, numpy, the standard library), so an edit to the
  reader, a new probesim or another USD makes a new reading;
- its bytes are whole: a SHA-256 of the entry is checked before it is
  read, and it is read by an unpickler that builds nothing but numpy arrays,
  plain containers and probesim's own record classes (dataclasses, enums,
  named tuples), so a foreign or damaged file is ignored, never run.

An entry is written only for a reading the in-process cache keeps (its files
settled :data:`~simulator.scene.stage_cache.RACY_NS` before the reading
began) and only if every code file was last modified that long before the
process began (on Linux its start time; elsewhere when probesim was
imported): a module edited while the process ran is not the code the
process ran. Entries are written whole (a temporary file, then an atomic
rename); none over :data:`MAX_ENTRY_BYTES`, at most :data:`MAX_BYTES` in all
(the least recently used go first). Where it lives: :mod:`simulator.cache_path`.
Any failure to read or write the folder is silent: the stage is read as
before.
"""

from __future__ import annotations

import dataclasses
import enum
import hashlib
import io
import json
import os
import pickle
import sys

__all__ = ["MAX_ENTRY_BYTES", "MAX_BYTES", "FORMAT", "file_identity", "folder", "load", "save"]

#: an entry bigger than this is not written (bytes)
MAX_ENTRY_BYTES = 1 << 26
#: the entries kept in all (bytes); the least recently used are removed beyond it
MAX_BYTES = 1 << 28
#: the entry layout's version: an entry of another is ignored
FORMAT = 1
#: the entries' folder under the cache root
SUBDIR = "stages"
#: seconds after which a temporary file a writer left behind (a process killed mid-write) is removed
STALE_PART_S = 3600

_MAGIC = b"probesim stage reading\n"
_SUFFIX = ".stage"
_ENV_PREFIXES = ("PXR_", "TF_", "USD_", "AR_", "PLUG_", "MATERIALX", "MTLX", "OCIO", "PROBESIM_")
#: numpy's pickle helpers that rebuild an array or a scalar (numpy 2 and 1 names)
_NUMPY = frozenset({
    ("numpy", "dtype"), ("numpy", "ndarray"),
    ("numpy._core.numeric", "_frombuffer"), ("numpy.core.numeric", "_frombuffer"),
    ("numpy._core.multiarray", "_reconstruct"), ("numpy.core.multiarray", "_reconstruct"),
    ("numpy._core.multiarray", "scalar"), ("numpy.core.multiarray", "scalar"),
})  # fmt: skip
_BUILTINS = frozenset({"set", "frozenset", "complex", "slice", "bytearray"})


def file_identity(path: str) -> tuple | None:
    """``(size, inode, mtime_ns, ctime_ns)`` of a file, or None if it cannot be stat'ed."""
    try:
        st = os.stat(path)
    except OSError:
        return None
    return (st.st_size, st.st_ino, st.st_mtime_ns, st.st_ctime_ns)


def folder():
    """The entries' folder (``<cache root>/stages``), or None when keeping across processes is off."""
    from simulator.cache_path import cache_folder

    return cache_folder(SUBDIR)


def _context(selection: str) -> str:
    """The selection with everything besides the files that could change what the reader makes of it."""
    from simulator.cache_path import ENV

    env = {k: v for k, v in os.environ.items() if k.startswith(_ENV_PREFIXES) and k != ENV}
    return json.dumps([FORMAT, selection, sys.version, sys.executable, os.getcwd(), env], sort_keys=True)


def _entry_path(dirpath, context: str):
    return dirpath / (hashlib.sha256(context.encode()).hexdigest()[:40] + _SUFFIX)


class _Reader(pickle.Unpickler):
    """Builds only what a stage reading is made of: numpy arrays, plain containers and probesim's record
    classes (dataclasses, enums, named tuples) from modules outside the stage reader."""

    def find_class(self, module: str, name: str):
        if (module, name) in _NUMPY or (module == "builtins" and name in _BUILTINS):
            return super().find_class(module, name)
        if module.startswith("simulator.") and not module.startswith("simulator.scene.usd"):
            obj = super().find_class(module, name)
            if isinstance(obj, type) and (dataclasses.is_dataclass(obj) or issubclass(obj, enum.Enum)
                                          or (issubclass(obj, tuple) and hasattr(obj, "_fields"))):
                return obj
        raise pickle.UnpicklingError(f"{module}.{name} is not part of a stage reading")


def _loads(data: bytes):
    return _Reader(io.BytesIO(data)).load()


def _same(identity: dict) -> bool:
    return all(file_identity(p) == tuple(v) for p, v in identity.items())


def load(selection: str):
    """``(scene, identity, usd_version)`` kept for ``selection`` if its entry is whole and every file
    it depends on (the stage's and the code's) stats as it did; else None. ``identity`` maps the stage's
    files to their :func:`file_identity` (what the in-process cache watches)."""
    try:
        return _load(selection)
    except Exception:  # a folder or working folder gone, any other failure: the stage is read instead
        return None


def _load(selection: str):
    d = folder()
    if d is None:
        return None
    context = _context(selection)
    path = _entry_path(d, context)
    try:
        with open(path, "rb") as f:
            blob = f.read()
    except OSError:  # none kept
        return None
    n = len(_MAGIC)
    if blob[:n] != _MAGIC or hashlib.sha256(blob[n + 32 :]).digest() != blob[n : n + 32]:
        return None  # not an entry, or not whole
    fmt, ctx, identity, code, usd_version, scene_bytes = _loads(blob[n + 32 :])
    if fmt != FORMAT or ctx != context or not _same(identity) or not _same(code):
        return None  # another layout or selection, or a file of the stage or of the code changed
    from simulator.scene.model import Scene

    scene = _loads(scene_bytes)
    if not isinstance(scene, Scene) or not isinstance(usd_version, str):
        return None
    try:
        os.utime(path)  # recently used: eviction removes the least recently used first
    except OSError:
        pass
    return scene, {p: tuple(v) for p, v in identity.items()}, usd_version


def _code_identity() -> dict | None:
    """The identity of every module file the process has loaded (its source, or the archive it came
    from); None if one cannot be stat'ed."""
    out = {}
    for m in list(sys.modules.values()):
        try:
            f = getattr(m, "__file__", None)
        except Exception:  # a module object whose attributes raise
            continue
        if not isinstance(f, str) or not f:
            continue
        p = os.path.abspath(f)
        ident = file_identity(p)
        while ident is None and os.path.dirname(p) != p:  # a module inside an archive: the archive
            p = os.path.dirname(p)
            ident = file_identity(p) if os.path.isfile(p) else None
        if ident is None:
            return None
        out[p] = ident
    return out


def save(selection: str, scene, identity: dict, usd_version: str) -> bool:
    """Write ``scene`` (read for ``selection``; its files' ``identity``) as an entry; whether it was
    written. Nothing is written if the folder is off or cannot be written, if a code file changed within
    :data:`simulator.cache_path.RACY_NS` before the process began, or if the entry would exceed
    :data:`MAX_ENTRY_BYTES`."""
    try:
        return _save(selection, scene, identity, usd_version)
    except Exception:  # a folder that cannot be written, a working folder gone: kept in memory only
        return False


def _save(selection: str, scene, identity: dict, usd_version: str) -> bool:
    d = folder()
    if d is None:
        return False
    code = _code_identity()
    if code is None:
        return False
    from simulator.cache_path import settled_before_start
    from simulator.io.atomic import write_atomic

    if not settled_before_start(code.values()):
        return False
    context = _context(selection)
    scene_bytes = pickle.dumps(scene, protocol=5)  # a reading pickle cannot write raises: kept in memory only
    body = pickle.dumps((FORMAT, context, identity, code, usd_version, scene_bytes), protocol=5)
    if len(body) > MAX_ENTRY_BYTES:
        return False
    path = _entry_path(d, context)
    write_atomic(path, _MAGIC + hashlib.sha256(body).digest() + body, private=True)  # whole or not at all
    _evict(d)
    return True


def _evict(d) -> None:
    """Remove the least recently used entries while they exceed :data:`MAX_BYTES`, and temporary files
    a killed writer left."""
    from simulator.io.atomic import remove_stale_temporaries

    remove_stale_temporaries(d, STALE_PART_S)
    entries = []
    for e in os.scandir(d):
        if not e.name.endswith(_SUFFIX):
            continue
        try:
            st = e.stat()
        except OSError:
            continue
        entries.append((st.st_mtime_ns, st.st_size, e.path))
    total = sum(s for _, s, _ in entries)
    for _, size, path in sorted(entries):
        if total <= MAX_BYTES:
            break
        try:
            os.unlink(path)
            total -= size
        except OSError:
            pass
