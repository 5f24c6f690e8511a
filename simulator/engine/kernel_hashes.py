"""Warp module hashes kept across processes, so that loading a cached trace module does not hash it again.

Warp finds a module's object file in its kernel cache by the module's
content hash, and computes that hash in every process before it loads
the module: a SHA-256 over each kernel's and each function it calls (key,
source, argument types, the values of the constants and ``wp.static``
expressions it refers to, the built-ins it calls) and the module's options.
For a trace module that is about 0.05 s of CPU per run, every run, to find
the same answer (docs/DESIGN.md §Start-up of a small run).

What goes into that hash comes from three places: the Python source of
probesim's kernels and of whatever they import (the constants they
read), Warp itself (its built-ins and its hashing), and the options the
module resolves (Warp's configuration as probesim sets it, or a user
did). So a hash is kept under a key made of

- the identity (size, inode, modification and change times in ns) of
  every ``.py`` file of the probesim package and of Warp's package (its
  top folder and ``_src``), so any edit there makes a new key;
- Warp's, numpy's and Python's versions;
- the module's name, the block size it is loaded with, its resolved
  options (as Warp hashes them), and its kernels' keys and options;
- the values its kernels capture from the functions that built them, and
  that the Warp functions they capture capture in turn (a kernel a factory
  builds from a value known only at run time: the trace variants' flag);

and is used (:func:`restore`) only where Warp's own layout is the one it
was taken from: it is written (:func:`keep`) only from a hash Warp itself
computed, by a Warp whose hasher has exactly the fields :func:`restore`
fills, for a module of plain (not generic) kernels with distinct keys and
nothing left unresolved. A kept hash is never used to compile: where the
kernel cache lacks the object file under it, the caller drops it
(:func:`forget`) and Warp hashes the module as always. A key is written
only when every file in it was last modified
:data:`simulator.cache_path.RACY_NS` before the process began.

Entries live in ``<cache root>/warp`` (:mod:`simulator.cache_path`), one
small JSON file each, at most :data:`MAX_ENTRIES` (the least recently
written go first). A damaged or foreign entry is ignored.
"""

from __future__ import annotations

import hashlib
import json
import os
import sys
import weakref

from .device import CHECKED_WARP, warp

__all__ = ["FORMAT", "MAX_ENTRIES", "WARP_VERSIONS", "restore", "keep", "forget", "restored"]

#: the entries' layout version
FORMAT = 1
#: entries kept in the folder
MAX_ENTRIES = 64
SUBDIR = "warp"

#: the Warp versions whose hashing :func:`restore` reproduces (what a hash sets besides the hash itself:
#: each kernel's hash, grid stride, ``wp.tid()`` dimension and launch-extent gate; tests/test_kernel_hashes.py
#: checks it against Warp's own); another Warp hashes every module itself until checked
WARP_VERSIONS = CHECKED_WARP
#: the fields of Warp's ModuleHasher that restore() fills; a Warp whose hasher has others is not served
_HASHER_FIELDS = frozenset({"kernel_hashes", "function_hashes", "functions_in_progress", "unique_kernels", "hash"})

_restored = weakref.WeakSet()  # hashers made by restore() (not computed by Warp in this process)
_tree_ids: dict = {}  # package folder -> its files' identities, read once per process


def _folder():
    from simulator.cache_path import cache_folder

    return cache_folder(SUBDIR)


def _tree(top: str, subdirs: tuple | None) -> list:
    """``[(path, size, inode, mtime_ns, ctime_ns)]`` of the ``.py`` files under ``top`` (its files and,
    recursively, those of ``subdirs``; every folder where ``subdirs`` is None)."""
    kept = _tree_ids.get((top, subdirs))
    if kept is not None:
        return kept
    out = []
    stack = [top]
    while stack:
        d = stack.pop()
        with os.scandir(d) as it:
            for e in it:
                if e.is_dir(follow_symlinks=False):
                    if e.name != "__pycache__" and (subdirs is None or d != top or e.name in subdirs):
                        stack.append(e.path)
                elif e.name.endswith(".py"):
                    st = e.stat()
                    out.append((e.path, st.st_size, st.st_ino, st.st_mtime_ns, st.st_ctime_ns))
    out.sort()
    _tree_ids[(top, subdirs)] = out
    return out


def _code() -> list:
    """The identities of probesim's and Warp's Python files (the code a module hash depends on)."""
    import numpy

    import simulator

    wp = warp()
    return [wp.config.version, numpy.__version__, sys.version,
            _tree(os.path.dirname(os.path.abspath(simulator.__file__)), None),
            _tree(os.path.dirname(os.path.abspath(wp.__file__)), ("_src",))]  # fmt: skip


_PLAIN = (bool, int, float, str, bytes, type(None))


def _captured(kernels: list) -> list:
    """The values the kernels capture from the functions that made them, and those the Warp functions
    they capture capture in turn (closure cells, recursively): a kernel or function a factory builds
    from a value known only at run time hashes differently for another value, with the same source.
    Plain values by ``repr``, anything else by its type's name (its source is in the key)."""
    out, seen = [], set()
    stack = [k.func for k in kernels]
    while stack:
        f = stack.pop()
        if id(f) in seen or not hasattr(f, "__code__"):
            continue
        seen.add(id(f))
        for name, cell in zip(f.__code__.co_freevars, f.__closure__ or ()):
            try:
                v = cell.cell_contents
            except ValueError:  # not yet bound
                continue
            if getattr(v, "adj", None) is not None and callable(getattr(v, "func", None)):  # a Warp function
                stack.append(v.func)
                out.append((f.__qualname__, name, "function", getattr(v, "key", "")))
            elif isinstance(v, _PLAIN) or (isinstance(v, tuple) and all(isinstance(x, _PLAIN) for x in v)):
                out.append((f.__qualname__, name, "value", repr(v)))
            else:
                if callable(v) and hasattr(v, "__code__"):
                    stack.append(v)
                out.append((f.__qualname__, name, "object", type(v).__qualname__))
    return sorted(out)


def _key(module, block_dim: int, options: dict, kernels: list, code: list) -> str:
    desc = [FORMAT, module.name, block_dim, [f"{k}:{options[k]}" for k in sorted(options)],
            sorted([k.key, [f"{o}:{k.options[o]}" for o in sorted(k.options)]] for k in kernels), _captured(kernels),
            code]  # fmt: skip
    return hashlib.sha256(json.dumps(desc, default=repr).encode()).hexdigest()


def _servable(module) -> list | None:
    """The module's kernels if a kept hash may stand for Warp's own: a Warp whose hashing this was
    checked against (:data:`WARP_VERSIONS`), plain kernels, distinct keys, no ``wp.static`` expression
    left to resolve; else None."""
    if not warp().config.version.startswith(WARP_VERSIONS):
        return None
    if module.has_unresolved_static_expressions or module.options.get("strip_hash"):
        return None
    kernels = module._get_live_kernels()
    keys = [k.key for k in kernels]
    if not kernels or len(set(keys)) != len(keys) or any(k.is_generic for k in kernels):
        return None
    return kernels


def restore(module, block_dim: int) -> bool:
    """Give ``module`` its hash for ``block_dim`` from the kept entry, if there is one for exactly this
    code, Warp and configuration; whether it did. Nothing happens where Warp has hashed it already."""
    try:
        if block_dim in module.hashers:
            return False
        d = _folder()
        kernels = _servable(module) if d is not None else None
        if kernels is None:
            return False
        wp = warp()
        options = module.resolve_options(wp.config, block_dim=block_dim)
        key = _key(module, block_dim, options, kernels, _code())
        try:
            with open(d / f"{key[:40]}.json", encoding="utf-8") as f:
                entry = json.load(f)
        except (OSError, ValueError):
            return False
        if entry.get("format") != FORMAT or entry.get("key") != key or set(entry["kernels"]) != {k.key for k in kernels}:
            return False
        module_hash = bytes.fromhex(entry["hash"])
        kernel_hashes = {k: bytes.fromhex(entry["kernels"][k.key]) for k in kernels}
        from warp._src.codegen import resolve_grid_stride
        from warp._src.context import ModuleHasher

        h = ModuleHasher.__new__(ModuleHasher)
        h.kernel_hashes = weakref.WeakKeyDictionary()
        h.function_hashes = {}
        h.functions_in_progress = set()
        unique = {}
        for k, kh in kernel_hashes.items():  # what ModuleHasher.hash_kernel records per kernel
            k.adj.get_references()  # sets what a launch reads of it: its wp.tid() dimension, the extent gate
            k.hash = kh
            k.grid_stride = resolve_grid_stride(k.options, options.get("default_grid_stride", False))
            h.kernel_hashes[k] = kh
            unique[kh] = k
        h.unique_kernels = dict(sorted(unique.items()))
        h.hash = module_hash
    except Exception:  # another Warp's layout, a damaged entry: Warp hashes the module as always
        return False
    module.hashers[block_dim] = h
    module.resolved_options[block_dim] = options
    _restored.add(h)
    return True


def restored(module, block_dim: int) -> bool:
    """Whether ``module``'s hash for ``block_dim`` is one :func:`restore` gave it."""
    h = module.hashers.get(block_dim)
    return h is not None and h in _restored


def forget(module) -> None:
    """Drop a restored hash (Warp hashes the module again when next asked)."""
    module.mark_modified()


def keep(module, block_dim: int) -> bool:
    """Write the hash Warp computed for ``module`` at ``block_dim`` for later processes; whether it did."""
    try:
        h = module.hashers.get(block_dim)
        d = _folder()
        if h is None or h in _restored or d is None or set(vars(h)) != _HASHER_FIELDS:
            return False
        kernels = _servable(module)
        if kernels is None or any(h.kernel_hashes.get(k) is None for k in kernels):
            return False
        from simulator.cache_path import settled_before_start
        from simulator.io.atomic import write_atomic

        code = _code()
        if not settled_before_start(ident[1:] for tree in code[3:] for ident in tree):
            return False
        key = _key(module, block_dim, module.resolved_options[block_dim], kernels, code)
        entry = {"format": FORMAT, "key": key, "module": module.name, "hash": h.hash.hex(),
                 "kernels": {k.key: h.kernel_hashes[k].hex() for k in kernels}}  # fmt: skip
        write_atomic(d / f"{key[:40]}.json", json.dumps(entry).encode("utf-8"), private=True)
        _evict(d)
    except Exception:  # a folder that cannot be written: nothing kept, nothing else changes
        return False
    return True


def _evict(d) -> None:
    """Keep the :data:`MAX_ENTRIES` most recently written entries; remove temporary files a killed writer
    left (as the stage cache does, :data:`simulator.scene.stage_disk.STALE_PART_S`)."""
    from simulator.io.atomic import remove_stale_temporaries
    from simulator.scene.stage_disk import STALE_PART_S

    remove_stale_temporaries(d, STALE_PART_S)
    entries = []
    for e in os.scandir(d):
        if e.name.endswith(".json"):
            try:
                entries.append((e.stat().st_mtime_ns, e.path))
            except OSError:
                continue
    for _, path in sorted(entries)[: max(0, len(entries) - MAX_ENTRIES)]:
        try:
            os.unlink(path)
        except OSError:
            pass
