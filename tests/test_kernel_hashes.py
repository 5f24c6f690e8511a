"""Warp module hashes kept across processes (simulator.engine.kernel_hashes): a restored hash is
Warp's own, bit for bit, with everything a launch reads of the kernels; it is never used where the
kernel cache lacks its object file, and a changed key or a damaged entry is not used at all.

The module is the all-matte trace module (cached by Warp once any test has run a matte stage). Each
test keeps its entries in a folder of its own (``PROBESIM_CACHE_PATH``).
"""

from __future__ import annotations

import json
import time

import pytest

from simulator import cache_path
from simulator.engine import kernel_hashes as KH
from simulator.engine import kernel_modules as KM
from simulator.engine.device import warp

wp = warp()
DIM = 1  # the block size a CPU launch loads a module with


@pytest.fixture
def loaded(tmp_path, monkeypatch):
    """The all-matte trace module, loaded, its hash computed by Warp; entries in this test's folder."""
    monkeypatch.setenv(cache_path.ENV, str(tmp_path / "cache"))
    km = KM.trace_module(False)
    KM.load([km])
    km.module.mark_modified()
    km.module.get_module_hash(DIM)  # Warp's own
    return km


@pytest.fixture
def matte(loaded, monkeypatch):
    """:func:`loaded`, the package's files counted as settled (they may have been edited just before the
    test run: the racy rule is tested apart)."""
    monkeypatch.setattr(cache_path, "settled_before_start", lambda identities: True)
    return loaded


def _state(m) -> dict:
    """What Warp's hashing leaves on the module and its kernels, that loading and launching read."""
    h = m.hashers[DIM]
    return {
        "module": h.hash,
        "unique": list(h.unique_kernels),
        "options": m.resolved_options[DIM],
        "kernels": {k.key: (k.hash, h.kernel_hashes[k], k.grid_stride, k.adj.kernel_dim, k.adj.tid_extent_limit_candidate)
                    for k in m._get_live_kernels()},  # fmt: skip
    }


def test_a_restored_hash_is_warps_own(matte):
    """Kept, then restored after the module forgot it: the module's hash, each kernel's hash, grid stride,
    ``wp.tid()`` dimension and launch gate, the unique kernels and the resolved options are Warp's; the
    hasher has exactly the fields restore() fills (a Warp that adds one is not served)."""
    m = matte.module
    warps = _state(m)
    assert set(vars(m.hashers[DIM])) == KH._HASHER_FIELDS
    assert KH.keep(m, DIM) and not KH.restored(m, DIM)
    m.mark_modified()
    for k in m._get_live_kernels():  # nothing left over from Warp's hashing
        k.hash = None
        del k.adj.kernel_dim, k.adj.tid_extent_limit_candidate
    assert KH.restore(m, DIM) and KH.restored(m, DIM)
    assert _state(m) == warps
    assert KM.is_cached(matte)


def test_a_kept_hash_without_its_object_file_is_not_used(matte, tmp_path):
    """An entry naming a hash the kernel cache has no object file for (here a wrong one): the module is
    still found cached, under the hash Warp computes, and the entry is rewritten with that hash."""
    m = matte.module
    real = m.hashers[DIM].hash
    assert KH.keep(m, DIM)
    (entry,) = (tmp_path / "cache" / KH.SUBDIR).glob("*.json")
    data = json.loads(entry.read_text())
    data["hash"] = "00" * 32
    entry.write_text(json.dumps(data))
    m.unload()  # as in a new process: not loaded, no hash
    assert KM.is_cached(matte)
    assert m.get_module_hash(DIM) == real and not KH.restored(m, DIM)
    assert json.loads(entry.read_text())["hash"] == real.hex()


@pytest.mark.parametrize("damage", ["garbage", "other kernels", "other key"])
def test_a_damaged_or_foreign_entry_is_not_used(matte, tmp_path, damage):
    """Bytes that are not JSON, an entry for other kernels, or one for another key: not restored."""
    m = matte.module
    assert KH.keep(m, DIM)
    (entry,) = (tmp_path / "cache" / KH.SUBDIR).glob("*.json")
    data = json.loads(entry.read_text())
    if damage == "garbage":
        entry.write_bytes(b"\x00not json")
    elif damage == "other kernels":
        data["kernels"] = {"another_kernel": "00" * 32}
        entry.write_text(json.dumps(data))
    else:
        data["key"] = "0" * 64
        entry.write_text(json.dumps(data))
    m.mark_modified()
    assert not KH.restore(m, DIM)


def test_the_key_follows_code_options_and_kernels(matte):
    """Any file's identity, the resolved options or a kernel's options give another key."""
    m = matte.module
    kernels = m._get_live_kernels()
    options = m.resolve_options(wp.config, block_dim=DIM)
    code = KH._code()
    key = KH._key(m, DIM, options, kernels, code)
    assert key == KH._key(m, DIM, dict(options), list(reversed(kernels)), KH._code())  # order does not matter
    touched = [*code[:3], [(p, s, i, mt + 1, ct) if n == 0 else (p, s, i, mt, ct) for n, (p, s, i, mt, ct) in enumerate(code[3])],
               code[4]]  # fmt: skip
    assert KH._key(m, DIM, options, kernels, touched) != key
    assert KH._key(m, DIM, {**options, "optimization_level": 3}, kernels, code) != key
    assert KH._key(m, DIM + 1, options, kernels, code) != key
    assert KH._key(m, DIM, options, kernels[:-1], code) != key
    assert KH._key(m, DIM, options, kernels, [code[0] + "x", *code[1:]]) != key  # another Warp


def test_another_warp_version_is_not_served(matte, monkeypatch):
    """A Warp whose hashing restore() was not checked against hashes every module itself."""
    m = matte.module
    assert KH.keep(m, DIM)
    m.mark_modified()
    monkeypatch.setattr(KH, "WARP_VERSIONS", ("0.0.",))
    assert not KH.restore(m, DIM) and not KH.keep(m, DIM)


def test_code_modified_after_the_process_began_is_not_kept(loaded, monkeypatch):
    """With the racy rule: a package file last modified less than RACY_NS before the process began keeps
    the hash from being written; one modified long before does not (the process start fixed here, the
    package's files replaced by one of known times)."""
    now = time.time_ns()
    monkeypatch.setattr(cache_path, "process_started_ns", lambda: now)
    code = KH._code()
    for age_ns, kept in ((cache_path.RACY_NS // 2, False), (2 * cache_path.RACY_NS, True)):
        tree = [("module.py", 10, 1, now - age_ns, now - age_ns)]
        monkeypatch.setattr(KH, "_code", lambda tree=tree: [*code[:3], tree, []])
        assert KH.keep(loaded.module, DIM) is kept


def test_an_empty_cache_path_keeps_nothing(matte, monkeypatch):
    monkeypatch.setenv(cache_path.ENV, "")
    assert not KH.keep(matte.module, DIM)
    matte.module.mark_modified()
    assert not KH.restore(matte.module, DIM)


def test_the_key_follows_what_the_kernels_capture(matte, monkeypatch):
    """A value a factory built the kernels from (the variant's flag, captured by the trace functions)
    is in the key: the two variants' captures differ only by it, and another value is another key."""
    m = matte.module
    kernels = m._get_live_kernels()
    captured = KH._captured(kernels)
    flags = {c[3] for c in captured if c[1] == "surfaces"}
    assert flags == {"False"}
    full = KH._captured(KM.trace_module(True).module._get_live_kernels())
    assert [c for c in full if c[1] != "surfaces"] == [c for c in captured if c[1] != "surfaces"]
    options = m.resolve_options(wp.config, block_dim=DIM)
    code = KH._code()
    key = KH._key(m, DIM, options, kernels, code)
    flipped = [(*c[:3], "True") if c[1] == "surfaces" else c for c in captured]
    monkeypatch.setattr(KH, "_captured", lambda ks: flipped)
    assert KH._key(m, DIM, options, kernels, code) != key


def test_the_kernels_read_nothing_but_their_source():
    """The key holds the kernels' source, not the environment: no kernel module reads an environment
    variable (a constant taken from one would change the code under the same key)."""
    import re
    from pathlib import Path

    kernels = Path(KM.__file__).resolve().parents[1] / "kernels"
    reads = re.compile(r"\bos\.environ\b|\bgetenv\s*\(|\bfrom os import\b")
    readers = [p.name for p in kernels.rglob("*.py") if reads.search(p.read_text())]
    assert len(list(kernels.rglob("*.py"))) > 20 and readers == []
