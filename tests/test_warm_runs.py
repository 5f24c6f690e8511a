"""Runs in one Python process: what is kept between ``simulator.run`` calls and when it is not.

The stage reading (:mod:`simulator.scene.stage_cache`), the plan
(:mod:`simulator.plan.cache`) and the exact estimator's geometric factors
(:mod:`simulator.engine.exact_memo`) are kept for later runs; a changed
file, variant, time, light or sensor must be read afresh. Every expected
reading is the corner-rectangle closed form of the visible part of the lamp
(``rect_irradiance_parallel``), independent of the contour code that reads it.

The stage: a RectLight 1 m (x) × 2 m (y) at height 2 m facing down, luminance
L (normalize off), and a black shade over x < 0 at z = 2 − 1e-4 m. A floor
receiver at (px, py, 0) sees the lamp's part x > px·(1 − 2/z_shade), z_shade the
float32 nearest 1.9999 (``point3f``).
"""

import csv
import io
import os
import time

import numpy as np
import pytest

import simulator
from simulator.config.overrides import apply_overrides
from simulator.engine import exact_memo
from simulator.plan import cache as plan_cache
from simulator.reference.closed_forms import rect_irradiance_parallel
from simulator.scene import stage_cache

H = 2.0
Z_SHADE = float(np.float32(1.9999))  # the shade's height as its point3f stores it
POINTS = ((0.0, 0.0), (0.3, -0.4), (-0.6, 0.5))
TOL = 1e-9  # relative: float64 contour sums against the closed form

STAGE = """#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
    defaultPrim = "World"
)

def Xform "World" (
    variants = {{ string lamp = "bright" }}
    prepend variantSets = "lamp"
)
{{
    def RectLight "Lamp"
    {{
        float inputs:intensity = {intensity}
        {samples}
        bool inputs:normalize = 0
        float inputs:width = 1
        float inputs:height = 2
        double3 xformOp:translate = ({dx}, 0, 2)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }}

    def Mesh "Shade"
    {{
        int[] faceVertexCounts = [4]
        int[] faceVertexIndices = [0, 1, 2, 3]
        point3f[] points = [(-2, -1.5, 1.9999), (0, -1.5, 1.9999), (0, 1.5, 1.9999), (-2, 1.5, 1.9999)]
        uniform bool doubleSided = 1
        color3f[] primvars:displayColor = [(0, 0, 0)]
    }}
    variantSet "lamp" = {{
        "bright" {{ }}
        "dim" {{
            over "Lamp"
            {{
                float inputs:exposure = -1
            }}
        }}
    }}
}}
"""


OVER = '#usda 1.0\nover "World"\n{{\n    over "Lamp"\n    {{\n        {}\n    }}\n}}\n'


def _expected_lx(px: float, py: float, luminance: float, dx: float = 0.0) -> float:
    """E_v at (px, py, 0): the part x ∈ [x_e, dx + 0.5], y ∈ [−1, 1] of the lamp (centred at x = dx)
    seen past the shade's edge, x_e the edge x = 0 projected from the receiver onto the lamp's plane."""
    x_e = max(dx - 0.5, px * (1.0 - H / Z_SHADE))
    return float(rect_irradiance_parallel(luminance, x_e - px, dx + 0.5 - px, -1.0 - py, 1.0 - py, H))


def _age(*paths):
    """Set the files' modification times 10 s back: settled files, whose reading the stage cache keeps
    (:data:`~simulator.scene.stage_cache.RACY_NS`); each call sets a new time, so an edit still shows."""
    t = time.time_ns() - 10_000_000_000
    for p in paths:
        os.utime(p, ns=(t, t))


def _write(folder, intensity=1000.0, samples="", points=POINTS, name="lamp.usda", sublayer=None, dx=0.0, age=True):
    stage = STAGE.format(intensity=intensity, samples=samples, dx=dx)
    if sublayer is not None:
        stage = stage.replace('defaultPrim = "World"', f'defaultPrim = "World"\n    subLayers = [@{sublayer}@]')
    (folder / name).write_text(stage)
    sensors = "\n".join(f'[[sensor]]\nname = "p{i}"\nkind = "irradiance"\nposition = [{x}, {y}, 0]\nnormal = [0, 0, 1]\n'
                        for i, (x, y) in enumerate(points))
    cfg = folder / f"{name}.toml"
    cfg.write_text(f'stage = "{name}"\n\n[simulation]\nsamples = 16\nseed = 1\n\n{sensors}\n'
                   f'[output]\ncsv = "out/{name}.csv"\n')
    if age:
        _age(folder / name)
    return cfg


def _lx(out) -> list[float]:
    return [r.values["illuminance_lx"] for r in out.rows]


def _check(out, luminance, points=POINTS, dx=0.0):
    assert {r.method for r in out.rows} == {"exact"}
    for got, (x, y) in zip(_lx(out), points):
        want = _expected_lx(x, y, luminance, dx)
        assert abs(got - want) <= TOL * want, (x, y, got, want)


@pytest.fixture(autouse=True)
def _fresh():
    stage_cache.clear()
    plan_cache.clear()
    exact_memo.clear()
    yield


def _run(cfg, **kw):
    return simulator.run(cfg, log=lambda *a: None, **kw)


def _csv_without_seconds(path) -> list[list[str]]:
    rows = list(csv.reader(io.StringIO(path.read_text())))
    k = rows[0].index("seconds")
    return [r[:k] + r[k + 1 :] for r in rows]


def test_a_warm_run_writes_the_cold_runs_bytes(tmp_path):
    """Same config twice in one process: the second is served from the caches, and its CSV (less the
    timing column) and run record's plan are the first's, byte for byte."""
    cfg = simulator.load_config(_write(tmp_path))
    cold = _run(apply_overrides(cfg, csv=str(tmp_path / "cold.csv")))
    hits = stage_cache.stats()["hits"]
    warm = _run(apply_overrides(cfg, csv=str(tmp_path / "warm.csv")))
    assert stage_cache.stats()["hits"] == hits + 1
    assert _csv_without_seconds(tmp_path / "cold.csv") == _csv_without_seconds(tmp_path / "warm.csv")
    plan = lambda p: p.read_text().split('"plan": ', 1)[1].split('\n  "', 1)[0]  # noqa: E731
    assert plan(tmp_path / "cold.run.json") == plan(tmp_path / "warm.run.json")
    assert cold.record["plan"] == warm.record["plan"]
    _check(warm, 1000.0)


def test_editing_the_stage_between_runs_is_read(tmp_path):
    """The lamp's intensity doubled in the file (same size): the next run reads it, and the exact
    factors (geometry unchanged) give exactly twice the light."""
    path = _write(tmp_path, intensity=1000)
    cfg = simulator.load_config(path)
    first = _lx(_run(cfg))
    assert stage_cache.stats()["entries"] == 1  # kept: the edit below must be seen, not just missed
    _write(tmp_path, intensity=2000)  # same byte count
    second = _run(cfg)
    _check(second, 2000.0)
    for a, b in zip(first, second.rows):
        assert abs(b.values["illuminance_lx"] - 2 * a) <= 1e-12 * 2 * a


def test_a_moved_lamp_is_read_afresh(tmp_path):
    """The lamp moved 0.25 m along x in the file: its visible part is recomputed (the exact factors are
    keyed by the lamp's corners), not scaled from the old one."""
    cfg = simulator.load_config(_write(tmp_path))
    _check(_run(cfg), 1000.0)
    assert stage_cache.stats()["entries"] == 1
    _write(tmp_path, dx=0.25)
    _check(_run(cfg), 1000.0, dx=0.25)


def test_an_edit_that_keeps_size_and_mtime_is_read(tmp_path):
    """An edit whose modification time is set back to the old one is still seen (change time, or the
    content of a recently modified file)."""
    path = _write(tmp_path, intensity=1000)
    cfg = simulator.load_config(path)
    _run(cfg)
    assert stage_cache.stats()["entries"] == 1
    stage = tmp_path / "lamp.usda"
    st = os.stat(stage)
    _write(tmp_path, intensity=3000)
    os.utime(stage, ns=(st.st_atime_ns, st.st_mtime_ns))
    _check(_run(cfg), 3000.0)


def test_a_just_modified_stage_is_used_but_not_kept(tmp_path):
    """A reading of files modified within RACY_NS of it is not kept (an edit during the reading could
    sit under the new times); once the files have settled, the next reading is kept and used."""
    cfg = simulator.load_config(_write(tmp_path, age=False))
    before = stage_cache.stats()
    _check(_run(cfg), 1000.0)
    _check(_run(cfg), 1000.0)
    after = stage_cache.stats()
    assert (after["reads"] - before["reads"], after["hits"] - before["hits"]) == (2, 0)
    _age(tmp_path / "lamp.usda")
    _run(cfg)
    _check(_run(cfg), 1000.0)
    assert stage_cache.stats()["hits"] == after["hits"] + 1


def test_an_edited_sublayer_is_read(tmp_path):
    """A layer the stage composes (a sublayer) is watched too: its stronger opinion is read after an edit."""
    (tmp_path / "over.usda").write_text(OVER.format("float inputs:intensity = 1000"))
    _age(tmp_path / "over.usda")
    cfg = simulator.load_config(_write(tmp_path, intensity=500, sublayer="./over.usda"))
    _check(_run(cfg), 500.0)  # the root layer is stronger than its sublayer
    assert stage_cache.stats()["entries"] == 1
    (tmp_path / "over.usda").write_text(OVER.format("float inputs:exposure = 1"))
    _age(tmp_path / "over.usda")
    _check(_run(cfg), 1000.0)  # exposure +1 from the sublayer: 2 × 500


def test_a_changed_variant_is_read(tmp_path):
    """Variant ``dim`` sets exposure −1 (half the light); the selection keys the kept reading."""
    cfg = simulator.load_config(_write(tmp_path))
    _check(_run(apply_overrides(cfg, variants=["lamp=dim"])), 500.0)
    _check(_run(apply_overrides(cfg, variants=["lamp=bright"])), 1000.0)
    _check(_run(apply_overrides(cfg, variants=["lamp=dim"])), 500.0)


def test_a_changed_time_is_read(tmp_path):
    """Intensity time samples 1: 1000, 2: 4000 (held, not interpolated, at the samples themselves)."""
    samples = "float inputs:intensity.timeSamples = { 1: 1000, 2: 4000 }"
    cfg = simulator.load_config(_write(tmp_path, samples=samples))
    _check(_run(apply_overrides(cfg, time=1.0)), 1000.0)
    _check(_run(apply_overrides(cfg, time=2.0)), 4000.0)


def test_moved_sensors_are_planned_and_read_afresh(tmp_path):
    """Same stage, other sensors: the plan and the exact factors are not the first config's."""
    _check(_run(simulator.load_config(_write(tmp_path))), 1000.0)
    moved = ((0.1, 0.2), (-0.3, -0.7), (0.45, 0.0))
    out = _run(simulator.load_config(_write(tmp_path, points=moved)))
    _check(out, 1000.0, moved)


def test_write_false_writes_nothing_and_reads_the_same(tmp_path):
    cfg = simulator.load_config(_write(tmp_path))
    bare = _run(cfg, write=False)
    assert not (tmp_path / "out").exists()
    assert bare.csv_path is None and bare.record_path is None and bare.record["maps"] == []
    written = _run(cfg)
    assert written.csv_path.exists()
    assert _lx(bare) == _lx(written)
    _check(bare, 1000.0)


def test_changing_the_scene_handed_out_does_not_change_the_next_run(tmp_path):
    cfg = simulator.load_config(_write(tmp_path))
    out = _run(cfg)
    out.scene.geometry.points += 5.0  # a caller's changes to its own copy: the shade moved away ...
    out.scene.lights.clear()  # ... and the lamp gone
    _check(_run(cfg), 1000.0)


def test_the_caches_are_bounded(tmp_path):
    for k in range(stage_cache.MAX_ENTRIES + 3):
        _run(simulator.load_config(_write(tmp_path, intensity=1000 + k, name=f"lamp{k}.usda")))
    assert stage_cache.stats()["entries"] <= stage_cache.MAX_ENTRIES
    assert len(plan_cache._entries) <= plan_cache.MAX_ENTRIES
    assert len(exact_memo._entries) <= exact_memo.MAX_ENTRIES


def test_the_records_stage_digest_follows_an_edit(tmp_path):
    """The run record's SHA-256 of the stage is the file's, before and after an edit between runs."""
    import hashlib

    cfg = simulator.load_config(_write(tmp_path, intensity=1000))
    stage = tmp_path / "lamp.usda"
    assert _run(cfg).record["stage"]["sha256"] == hashlib.sha256(stage.read_bytes()).hexdigest()
    _write(tmp_path, intensity=2000)
    assert _run(cfg).record["stage"]["sha256"] == hashlib.sha256(stage.read_bytes()).hexdigest()


def test_an_edited_ies_file_is_read(tmp_path):
    """The IES file a light's shaping names (read by Python, seen by the audit hook): its candela
    multiplier (the third number of the line after TILT) 1 → 2 doubles every reading of the point
    source's closed form (CIE 171:2006 case 5.2, I(θ) = 1000·cos θ cd, absolute)."""
    from simulator.bundled import configs_dir, stages_dir

    (tmp_path / "photometry").mkdir()
    ies = tmp_path / "photometry" / "cie171_lambert_1000cd.ies"
    text = (stages_dir() / "photometry" / "cie171_lambert_1000cd.ies").read_text()
    ies.write_text(text)
    (tmp_path / "cie171_5_2_ies.usda").write_text((stages_dir() / "cie171_5_2_ies.usda").read_text())
    _age(ies, tmp_path / "cie171_5_2_ies.usda")
    toml = (configs_dir() / "cie171_5_2_ies.toml").read_text().replace('"../stages/', '"')
    (tmp_path / "case.toml").write_text(toml)
    cfg = apply_overrides(simulator.load_config(tmp_path / "case.toml"), csv=str(tmp_path / "out.csv"))
    first = _lx(_run(cfg))
    assert stage_cache.stats()["entries"] == 1
    assert "\n1 -1 1 91 " in text
    ies.write_text(text.replace("\n1 -1 1 91 ", "\n1 -1 2 91 ", 1))
    _age(ies)
    second = _lx(_run(cfg))
    assert all(a > 0 for a in first)
    for a, b in zip(first, second):
        assert abs(b - 2 * a) <= 1e-12 * 2 * a


TEXTURED = """#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
)

def RectLight "Lamp"
{
    float inputs:intensity = 1000
    double3 xformOp:translate = (0, 0, 2)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}

def Material "M"
{
    token outputs:surface.connect = </M/S.outputs:surface>
    def Shader "S"
    {
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor.connect = </M/T.outputs:rgb>
        token outputs:surface
    }
    def Shader "T"
    {
        uniform token info:id = "UsdUVTexture"
        asset inputs:file = @wall.png@
        token inputs:sourceColorSpace = "raw"
        color3f outputs:rgb
    }
}

def Mesh "Wall" (
    prepend apiSchemas = ["MaterialBindingAPI"]
)
{
    int[] faceVertexCounts = [3]
    int[] faceVertexIndices = [0, 1, 2]
    point3f[] points = [(-1, -1, 1), (1, -1, 1), (0, 1, 1)]
    rel material:binding = </M>
}
"""


def test_an_edited_texture_is_read(tmp_path):
    """A UsdUVTexture file (read through USD's asset resolver, not Python's ``open``): its raw mean is
    the wall's albedo, 100/255, then 200/255 after the file is rewritten."""
    from simulator.io.map_png import png_bytes
    from simulator.pipeline import cached_scene

    png = tmp_path / "wall.png"
    png.write_bytes(png_bytes(np.full((4, 4, 3), 100, np.uint8)))
    (tmp_path / "wall.usda").write_text(TEXTURED)
    (tmp_path / "wall.toml").write_text('stage = "wall.usda"\n\n[[sensor]]\nname = "a"\nkind = "irradiance"\n'
                                        'position = [0, 0, 0]\nnormal = [0, 0, 1]\n')
    _age(png, tmp_path / "wall.usda")
    cfg = simulator.load_config(tmp_path / "wall.toml")
    scene, token = cached_scene(cfg)
    assert token is not None and str(png) in scene.sources
    assert abs(float(scene.geometry.albedo[0]) - 100 / 255) <= 1e-12
    png.write_bytes(png_bytes(np.full((4, 4, 3), 200, np.uint8)))
    _age(png)
    again, token2 = cached_scene(cfg)
    assert token2 != token
    assert abs(float(again.geometry.albedo[0]) - 200 / 255) <= 1e-12


def test_a_changed_planner_bound_is_planned_afresh(tmp_path, monkeypatch):
    """The plan is kept under the planner's bounds too: with the exact rule's cost bound set below
    what the lamp and its shade cost, the same stage and sensors are read by shadow rays, not from a
    kept plan."""
    from simulator.plan import exact_rule

    cfg = simulator.load_config(_write(tmp_path))
    _check(_run(cfg, write=False), 1000.0)
    monkeypatch.setattr(exact_rule, "EXACT_MAX_S", 1e-9)
    out = _run(cfg, write=False)
    assert {r.method for r in out.rows} == {"light"}
