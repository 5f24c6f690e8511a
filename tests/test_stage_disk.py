"""Stage readings kept on disk (simulator.scene.stage_disk): used by a later process only while every
file the reading and its code depended on is unchanged, ignored when damaged or foreign.

Every expected reading is a closed form: the stage is a RectLight 1 m × 2 m of luminance L
(normalize off) 2 m above a floor sensor at its centre, E_v = ``rect_irradiance_parallel`` (the
corner-rectangle formula, docs/REFERENCES.md §Parallel rectangle), and a
UsdUVTexture wall whose albedo is the texture's raw mean (100/255, then 200/255). Each test has a
cache folder of its own (``PROBESIM_CACHE_PATH``); the in-process cache is emptied before each
reading that must come from disk.
"""

from __future__ import annotations

import csv
import io
import os
import pickle
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import simulator
from simulator import cache_path
from simulator.plan import cache as plan_cache
from simulator.reference.closed_forms import rect_irradiance_parallel
from simulator.scene import stage_cache, stage_disk
from test_warm_runs import TEXTURED  # a wall whose albedo is a texture file

ROOT = Path(__file__).resolve().parents[1]
TOL = 1e-9  # relative: the exact estimator's float64 sums against the closed form

LAMP = """#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
    defaultPrim = "World"
    {sublayers}
)

def Xform "World"
{{
    def RectLight "Lamp"
    {{
        float inputs:intensity = {intensity}
        bool inputs:normalize = 0
        float inputs:width = 1
        float inputs:height = 2
        double3 xformOp:translate = (0, 0, 2)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }}
}}
"""

OVER = '#usda 1.0\nover "World"\n{{\n    over "Lamp"\n    {{\n        {}\n    }}\n}}\n'

CONFIG = """stage = "{stage}"

[simulation]
samples = 16
seed = 1

[[sensor]]
name = "floor"
kind = "irradiance"
position = [0, 0, 0]
normal = [0, 0, 1]
"""


def _age(*paths):
    """Modification times 10 s back: settled files, whose reading is kept (stage_cache.RACY_NS); a new
    time at each call, so an edit still shows."""
    t = time.time_ns() - 10_000_000_000
    for p in paths:
        os.utime(p, ns=(t, t))


def _expected_lx(luminance: float) -> float:
    """E_v under the centre of the 1 m × 2 m lamp 2 m up (corner-rectangle closed form)."""
    return float(rect_irradiance_parallel(luminance, -0.5, 0.5, -1.0, 1.0, 2.0))


@pytest.fixture
def disk(tmp_path, monkeypatch):
    """A cache folder of this test's own, the in-process caches empty, and the code counted as settled
    (the package's files may have been edited just before the test run: the racy rule is tested apart)."""
    folder = tmp_path / "cache"
    monkeypatch.setenv(cache_path.ENV, str(folder))
    monkeypatch.setattr(cache_path, "settled_before_start", lambda identities: True)
    stage_cache.clear()
    plan_cache.clear()
    yield folder / stage_disk.SUBDIR
    stage_cache.clear()


def _stage(folder: Path, intensity=1000.0, sublayer=None) -> Path:
    subs = f"subLayers = [@{sublayer}@]" if sublayer else ""
    (folder / "lamp.usda").write_text(LAMP.format(intensity=intensity, sublayers=subs))
    cfg = folder / "lamp.toml"
    cfg.write_text(CONFIG.format(stage="lamp.usda"))
    _age(folder / "lamp.usda")
    return cfg


def _lx(cfg) -> float:
    out = simulator.run(simulator.load_config(cfg), log=lambda *a: None, write=False)
    return float(out.rows[0].values["illuminance_lx"])


def _fresh_process_reading(cfg) -> float:
    """The reading a new process would get: the in-process caches emptied first."""
    stage_cache.clear()
    plan_cache.clear()
    return _lx(cfg)


def test_a_new_process_takes_the_reading_from_disk(tmp_path, disk):
    """The second reading comes from disk (no stage read), and is the closed form 1000 cd/m² gives."""
    cfg = _stage(tmp_path)
    assert abs(_lx(cfg) - _expected_lx(1000.0)) <= TOL * _expected_lx(1000.0)
    assert len(list(disk.glob("*.stage"))) == 1
    before = stage_cache.stats()
    again = _fresh_process_reading(cfg)
    after = stage_cache.stats()
    assert (after["disk_hits"] - before["disk_hits"], after["reads"] - before["reads"]) == (1, 0)
    assert abs(again - _expected_lx(1000.0)) <= TOL * _expected_lx(1000.0)


def test_an_edited_stage_is_read_afresh(tmp_path, disk):
    """The stage file rewritten (500 cd/m²): its entry no longer matches, the new value is read."""
    cfg = _stage(tmp_path)
    _lx(cfg)
    _stage(tmp_path, intensity=500.0)
    reads = stage_cache.stats()["reads"]
    got = _fresh_process_reading(cfg)
    assert stage_cache.stats()["reads"] == reads + 1
    assert abs(got - _expected_lx(500.0)) <= TOL * _expected_lx(500.0)


def test_an_edited_sublayer_is_read_afresh(tmp_path, disk):
    """A sublayer's opinion (exposure 0, then +1: 2¹ × the root layer's 500 cd/m²) is seen after the
    sublayer alone is edited."""
    (tmp_path / "over.usda").write_text(OVER.format("float inputs:exposure = 0"))
    _age(tmp_path / "over.usda")
    cfg = _stage(tmp_path, intensity=500.0, sublayer="./over.usda")
    assert abs(_lx(cfg) - _expected_lx(500.0)) <= TOL * _expected_lx(500.0)
    (tmp_path / "over.usda").write_text(OVER.format("float inputs:exposure = 1"))
    _age(tmp_path / "over.usda")
    got = _fresh_process_reading(cfg)
    assert abs(got - _expected_lx(1000.0)) <= TOL * _expected_lx(1000.0)


def test_an_edited_texture_is_read_afresh(tmp_path, disk):
    """A texture (opened by USD's C++ reader, not Python): the wall's albedo is its raw mean, 100/255
    from the entry, then 200/255 once the file is rewritten."""
    from simulator.io.map_png import png_bytes
    from simulator.pipeline import cached_scene

    png = tmp_path / "wall.png"
    png.write_bytes(png_bytes(np.full((4, 4, 3), 100, np.uint8)))
    (tmp_path / "wall.usda").write_text(TEXTURED)
    (tmp_path / "wall.toml").write_text(CONFIG.format(stage="wall.usda"))
    _age(png, tmp_path / "wall.usda")
    cfg = simulator.load_config(tmp_path / "wall.toml")
    cached_scene(cfg)
    stage_cache.clear()
    hits = stage_cache.stats()["disk_hits"]
    scene, _ = cached_scene(cfg)
    assert stage_cache.stats()["disk_hits"] == hits + 1
    assert abs(float(scene.geometry.albedo[0]) - 100 / 255) <= 1e-12
    png.write_bytes(png_bytes(np.full((4, 4, 3), 200, np.uint8)))
    _age(png)
    stage_cache.clear()
    again, _ = cached_scene(cfg)
    assert stage_cache.stats()["disk_hits"] == hits + 1
    assert abs(float(again.geometry.albedo[0]) - 200 / 255) <= 1e-12


def _entry(disk) -> Path:
    (path,) = disk.glob("*.stage")
    return path


@pytest.mark.parametrize("damage", ["flip", "truncate", "garbage", "empty", "foreign"])
def test_a_damaged_or_foreign_entry_is_ignored(tmp_path, disk, damage, capsys):
    """A flipped byte, a cut-off file, bytes of something else, an empty file, or a whole entry (right
    magic and checksum) whose pickle asks for a function: the stage is read afresh, the reading is the
    closed form, nothing is run and nothing is printed."""
    cfg = _stage(tmp_path)
    _lx(cfg)
    path = _entry(disk)
    blob = path.read_bytes()
    if damage == "flip":
        i = len(blob) - 100
        blob = blob[:i] + bytes([blob[i] ^ 0x40]) + blob[i + 1 :]
    elif damage == "truncate":
        blob = blob[: len(blob) // 2]
    elif damage == "garbage":
        blob = os.urandom(len(blob))
    elif damage == "empty":
        blob = b""
    else:
        import hashlib

        class Boom:
            def __reduce__(self):
                return (os.system, ("echo ran",))

        context = stage_disk._context(_selections(disk)[0])  # the right selection, no files to check
        body = pickle.dumps((stage_disk.FORMAT, context, {}, {}, "0", pickle.dumps(Boom())))
        blob = stage_disk._MAGIC + hashlib.sha256(body).digest() + body
    path.write_bytes(blob)
    reads = stage_cache.stats()["reads"]
    got = _fresh_process_reading(cfg)
    assert stage_cache.stats()["reads"] == reads + 1
    assert abs(got - _expected_lx(1000.0)) <= TOL * _expected_lx(1000.0)
    assert "ran" not in capsys.readouterr().out


def test_the_unpickler_builds_only_records_and_arrays():
    """numpy arrays and probesim's record classes load; a function (``os.system``) or a class outside
    them (``subprocess.Popen``) does not."""
    from simulator.scene.model import LightKind

    arr = np.arange(6.0).reshape(2, 3)[:, ::2]  # not contiguous: numpy's other reconstruction
    got = stage_disk._loads(pickle.dumps((arr, LightKind.RECT, {1, 2}), protocol=5))
    assert np.array_equal(got[0], arr) and got[1] is LightKind.RECT and got[2] == {1, 2}
    for bad in (os.system, subprocess.Popen):
        with pytest.raises(pickle.UnpicklingError):
            stage_disk._loads(pickle.dumps(bad))


def test_an_edited_module_of_the_code_invalidates_the_entry(tmp_path, disk, monkeypatch):
    """The entry records every loaded module's file: a module rewritten afterwards (a stand-in for the
    reader, loaded from a folder of this test) makes the entry unusable."""
    mod_dir = tmp_path / "code"
    mod_dir.mkdir()
    (mod_dir / "reader_stand_in.py").write_text("VALUE = 1\n")
    _age(mod_dir / "reader_stand_in.py")
    monkeypatch.syspath_prepend(str(mod_dir))
    import reader_stand_in  # noqa: F401

    try:
        cfg = _stage(tmp_path)
        _lx(cfg)
        stage_cache.clear()
        assert stage_disk.load(next(iter(_selections(disk)))) is not None
        (mod_dir / "reader_stand_in.py").write_text("VALUE = 2\n")
        _age(mod_dir / "reader_stand_in.py")
        assert stage_disk.load(next(iter(_selections(disk)))) is None
    finally:
        sys.modules.pop("reader_stand_in", None)


def _selections(disk) -> list[str]:
    """The selection each entry was written for (read from the entries themselves)."""
    import json

    out = []
    for path in disk.glob("*.stage"):
        blob = path.read_bytes()
        body = stage_disk._loads(blob[len(stage_disk._MAGIC) + 32 :])
        out.append(json.loads(body[1])[1])
    return out


def test_code_edited_while_the_process_ran_is_not_trusted(tmp_path, monkeypatch):
    """With the racy rule in force: a code file modified after the process began keeps the entry from
    being written (the process may have run the older code)."""
    monkeypatch.setenv(cache_path.ENV, str(tmp_path / "cache"))
    fresh = tmp_path / "fresh_module.py"
    fresh.write_text("X = 1\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    import fresh_module  # noqa: F401

    try:
        stage_cache.clear()
        cfg = _stage(tmp_path)
        _lx(cfg)
        assert stage_cache.stats()["entries"] == 1  # kept in memory: the stage's own files are settled
        assert list((tmp_path / "cache" / stage_disk.SUBDIR).glob("*.stage")) == []
    finally:
        sys.modules.pop("fresh_module", None)
        stage_cache.clear()


def test_an_empty_cache_path_keeps_nothing(tmp_path, monkeypatch):
    """``PROBESIM_CACHE_PATH=""``: nothing is written and every new process reads the stage."""
    monkeypatch.setenv(cache_path.ENV, "")
    monkeypatch.setattr(cache_path, "settled_before_start", lambda identities: True)
    assert cache_path.cache_root() is None and stage_disk.folder() is None
    cfg = _stage(tmp_path)
    _lx(cfg)
    reads = stage_cache.stats()["reads"]
    _fresh_process_reading(cfg)
    assert stage_cache.stats()["reads"] == reads + 1


def test_another_asset_search_path_is_another_entry(tmp_path, disk, monkeypatch):
    """USD's search path (``PXR_AR_DEFAULT_SEARCH_PATH``) can change what a layer's asset paths
    resolve to: with another one the entry is not used."""
    cfg = _stage(tmp_path)
    _lx(cfg)
    monkeypatch.setenv("PXR_AR_DEFAULT_SEARCH_PATH", str(tmp_path))
    reads = stage_cache.stats()["reads"]
    _fresh_process_reading(cfg)
    assert stage_cache.stats()["reads"] == reads + 1


def test_the_folder_is_bounded(tmp_path, disk, monkeypatch):
    """With room for about one entry, writing a second removes the least recently used first."""
    cfg = _stage(tmp_path)
    _lx(cfg)
    size = _entry(disk).stat().st_size
    monkeypatch.setattr(stage_disk, "MAX_BYTES", int(size * 1.5))
    other = tmp_path / "other"
    other.mkdir()
    _lx(_stage(other))
    entries = list(disk.glob("*.stage"))
    assert len(entries) == 1 and entries[0].stat().st_size <= int(size * 1.5)
    assert stage_disk.load(_selections(disk)[0]) is not None


def _settle_package():
    """Wait until every file of the package was last modified well before now: a new process writes
    entries only for code modified at least RACY_NS before it began (edited files wait a few seconds)."""
    newest = max(p.stat().st_mtime for p in (ROOT / "simulator").rglob("*.py"))
    wait = newest + 2 * cache_path.RACY_NS / 1e9 + 1.5 - time.time()
    if wait > 0:
        time.sleep(wait)


def test_whole_runs_read_the_same_bytes_with_and_without_the_caches(tmp_path):
    """``probesim run`` of the office's desk sensor (traced) in new processes: caches off, then a first run
    with them that writes them, then one that uses them (``pxr`` never imported, the trace module's kept
    hash used: its entry not written again). The CSV is the same bytes in all three but for ``seconds``."""
    _settle_package()
    cfg = tmp_path / "desk.toml"
    cfg.write_text(CONFIG.format(stage=(ROOT / "stages" / "office.usda").as_posix())
                   .replace("position = [0, 0, 0]", "position = [2.0, 2.0, 0.8]").replace("samples = 16", "samples = 64"))
    env = {k: v for k, v in os.environ.items()}
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT), env.get("PYTHONPATH", "")])
    cache = tmp_path / "cache"

    def run(name: str, folder: str) -> tuple[list, bool]:
        out = tmp_path / f"{name}.csv"
        proc = subprocess.run([sys.executable, "-X", "importtime", "-m", "simulator", "run", str(cfg), "-o", str(out), "-q"],
                              env={**env, cache_path.ENV: folder}, capture_output=True, text=True, check=True,
                              cwd=tmp_path)  # fmt: skip
        rows = list(csv.reader(io.StringIO(out.read_text())))
        k = rows[0].index("seconds")
        imported = {line.rsplit("|", 1)[-1].strip() for line in proc.stderr.splitlines() if line.startswith("import time:")}
        return [r[:k] + r[k + 1 :] for r in rows], "pxr" in imported

    off, pxr_off = run("off", "")
    first, pxr_first = run("first", str(cache))
    (entry,) = (cache / "warp").glob("*.json")
    written = entry.stat()
    second, pxr_second = run("second", str(cache))
    assert pxr_off and pxr_first and not pxr_second
    again = entry.stat()
    assert (again.st_ino, again.st_mtime_ns) == (written.st_ino, written.st_mtime_ns)
    assert off == first == second
