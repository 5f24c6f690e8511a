"""A study's chunk ids follow every file its stage is read from.

Chunks are kept on disk and reused by id (a resumed or repeated study traces
only what changed). The id hashes the stage: if it hashed the root layer's
bytes alone, editing a sublayer (``office.usda`` under
``office_shading.usda``), a referenced file or an IES profile would serve the
old readings under the new stage — a silent wrong number. These tests edit
each kind of dependency and expect new ids; a one-file stage keeps the ids it
always had (the digest of its bytes), so chunks traced before stay valid.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np

from simulator.scene.model import Sensor, SensorKind
from simulator.scene.usd.dependencies import stage_digest, stage_files
from simulator.study.inputs.scenarios import Scenario, TraceGroup
from simulator.study.trace.chunks import make_chunks

ROOT = Path(__file__).resolve().parents[1]

BASE = """#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
)
def Xform "Room"
{
    def RectLight "Panel"
    {
        float inputs:intensity = %s
        float inputs:width = 1
        float inputs:height = 1
        double3 xformOp:translate = (0, 0, 2)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
"""

TOP = """#usda 1.0
(
    subLayers = [@./base.usda@]
    metersPerUnit = 1
    upAxis = "Z"
)
"""

REF = """#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
)
def Xform "World" (
    prepend references = @./base.usda@</Room>
)
{
}
"""


def _ids(stage: Path) -> list[str]:
    sc = Scenario("on", {"panel": 1.0}, None, ())
    tg = TraceGroup("variants:-;sun:stage", {}, None, [sc], ["panel"])
    sensors = [Sensor("s", SensorKind.IRRADIANCE, np.zeros(3), np.array([0.0, 0.0, 1.0]))]
    return [c.id for c in make_chunks([tg], sensors, {"panel": ["/Room/Panel"]}, stage, "photometric", {"samples": 64}, 1, 8)]


def test_a_one_file_stage_keeps_the_digest_of_its_bytes():
    """office.usda reads no other file: its digest is sha256 of its bytes, as chunk ids always hashed it."""
    stage = ROOT / "stages" / "office.usda"
    assert stage_files(stage) == [stage.resolve()]
    assert stage_digest(stage) == hashlib.sha256(stage.read_bytes()).hexdigest()


def test_the_bundled_shading_stage_depends_on_the_office_below_it():
    assert [p.name for p in stage_files(ROOT / "stages" / "office_shading.usda")] == ["office_shading.usda", "office.usda"]


def test_editing_a_sublayer_or_a_referenced_layer_gives_new_chunk_ids(tmp_path):
    """The root layer's bytes stay the same; the layer under it changes the panel's intensity: the
    chunks' ids must change (and change back with the edit undone: the id is a function of the files)."""
    base = tmp_path / "base.usda"
    for name, text in (("top.usda", TOP), ("ref.usda", REF)):
        base.write_text(BASE % "100")
        stage = tmp_path / name
        stage.write_text(text)
        before = _ids(stage)
        base.write_text(BASE % "200")
        after = _ids(stage)
        assert before != after, name
        base.write_text(BASE % "100")
        assert _ids(stage) == before, name


def test_editing_an_ies_file_gives_new_chunk_ids(tmp_path):
    """An asset a light names (its IES profile) is part of the stage: a changed candela table is a new chunk."""
    src = ROOT / "stages" / "asymmetric_luminaire.usda"
    ies = [p for p in stage_files(src) if p.suffix == ".ies"]
    assert len(ies) == 1
    stage = tmp_path / src.name
    stage.write_text(src.read_text())
    copy = tmp_path / ies[0].relative_to(src.parent)
    copy.parent.mkdir(parents=True, exist_ok=True)
    copy.write_bytes(ies[0].read_bytes())
    before = stage_digest(stage)
    assert copy.resolve() in stage_files(stage)
    copy.write_bytes(ies[0].read_bytes() + b"\n")
    assert stage_digest(stage) != before
