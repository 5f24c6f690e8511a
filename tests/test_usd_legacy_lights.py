"""UsdLux attributes under their legacy (pre-``inputs:``) names read as their ``inputs:`` twins.

Stages written before UsdLux's connectable inputs (USD 21.05) author
``intensity``, ``radius``, ``shaping:cone:angle``, ``texture:file``, ...
without the prefix. Each light here is written twice, once with the legacy
names and once with the ``inputs:`` names: the two must read the same
light (emission, sizes, angles, shaping, texture), which for most of them
differs from the schema defaults by orders of magnitude. Where both names
are authored the ``inputs:`` one wins. The summary line names the legacy
attributes once, with counts.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np

from simulator.io import exr
from simulator.scene.usd import load_stage

IES = Path(__file__).resolve().parent / "data" / "photometry" / "asymmetric_2002_crlf.ies"

# (type, attributes without the prefix, apiSchemas)
LIGHTS = [
    ("SphereLight", ["float intensity = 500", "float exposure = 2", "color3f color = (0.8, 0.8, 0.8)",
                     "float radius = 0.25", "bool normalize = 1", "bool enableColorTemperature = 1",
                     "float colorTemperature = 3200"], ""),
    ("RectLight", ["float intensity = 40", "float width = 2", "float height = 0.5"], ""),
    ("DiskLight", ["float intensity = 7", "float radius = 0.3", "bool normalize = 1"], ""),
    ("CylinderLight", ["float intensity = 9", "float radius = 0.05", "float length = 1.5"], ""),
    ("DistantLight", ["float intensity = 3", "float angle = 4", "bool normalize = 1"], ""),
    ("DomeLight", ["float intensity = 2", "asset texture:file = @./sky.exr@", 'token texture:format = "latlong"'], ""),
    ("SphereLight", ["float intensity = 300", "float radius = 0", "bool normalize = 1",
                     "float shaping:cone:angle = 40", "float shaping:cone:softness = 0.2", "float shaping:focus = 3",
                     "color3f shaping:focusTint = (0.1, 0.1, 0.1)", f"asset shaping:ies:file = @{IES}@",
                     "bool shaping:ies:normalize = 1"], "ShapingAPI"),
]


def _stage(tmp_path: Path, prefix: str, name: str) -> Path:
    exr.write_channels(tmp_path / "sky.exr", {"Y": np.arange(1.0, 33.0).reshape(4, 8)})
    prims = []
    for k, (typ, attrs, api) in enumerate(LIGHTS):
        schema = f' (\n    prepend apiSchemas = ["{api}"]\n)' if api else ""
        body = "\n    ".join(a.replace(" ", f" {prefix}", 1) for a in attrs)
        prims.append(f'def {typ} "L{k}"{schema}\n{{\n    {body}\n    double3 xformOp:translate = (0, 0, {k + 1})\n'
                     '    uniform token[] xformOpOrder = ["xformOp:translate"]\n}')
    path = tmp_path / name
    path.write_text('#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n\n' + "\n\n".join(prims) + "\n")
    return path


def _fields(light) -> dict:
    d = {f.name: getattr(light, f.name) for f in dataclasses.fields(light)}
    if d.get("shaping") is not None:
        sh = d.pop("shaping")
        d["shaping"] = {f.name: getattr(sh, f.name) for f in dataclasses.fields(sh) if f.name != "ies"}
        d["ies_total_lm"] = sh.ies.total_lumens() if sh.ies is not None else None
    return d


def _same(a, b) -> bool:
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(_same(a[k], b[k]) for k in a)
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.array_equal(np.asarray(a), np.asarray(b))
    return a == b


def test_legacy_names_read_as_their_inputs_twin(tmp_path):
    new = load_stage(_stage(tmp_path, "inputs:", "new.usda"))
    old = load_stage(_stage(tmp_path, "", "old.usda"))
    assert len(old.lights) == len(new.lights) == len(LIGHTS)
    for a, b in zip(old.lights, new.lights):
        fa, fb = _fields(a), _fields(b)
        fa.pop("texture"), fb.pop("texture")  # both the same resolved file
        bad = [k for k in fa if not _same(fa[k], fb[k])]
        assert not bad, (a.name, {k: (fa[k], fb[k]) for k in bad})
    assert old.lights[0].spectrum == 3200.0 and old.lights[0].radius == 0.25  # not the defaults (D65, 0.5)
    assert old.lights[1].width == 2.0 and old.lights[4].half_angle > 0
    assert old.lights[5].texture_map is not None and old.lights[6].shaping.ies is not None
    summary = [w for w in old.warnings if "legacy UsdLux attributes" in w]
    assert len(summary) == 1 and "4 x radius" in summary[0] and "7 x intensity" in summary[0], old.warnings
    assert not any("legacy" in w for w in new.warnings)


def test_inputs_name_wins_where_both_are_authored(tmp_path):
    path = tmp_path / "both.usda"
    path.write_text('#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n\ndef SphereLight "L"\n{\n'
                    "    float intensity = 500\n    float inputs:intensity = 20\n    float radius = 2\n}\n")
    s = load_stage(path)
    (light,) = s.lights
    twin = load_stage(_write(tmp_path, "float inputs:intensity = 20\n    float inputs:radius = 2"))
    assert light.emission == twin.lights[0].emission and light.radius == 2.0
    summary = [w for w in s.warnings if "legacy UsdLux attributes" in w]
    assert len(summary) == 1 and "1 x radius" in summary[0] and "intensity" not in summary[0]


def _write(tmp_path, attrs):
    p = tmp_path / "twin.usda"
    p.write_text(f'#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n\ndef SphereLight "L"\n{{\n    {attrs}\n}}\n')
    return p
