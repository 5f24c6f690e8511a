"""Reading UsdLux PortalLights: the portal's world rectangle and facing, the
dome it serves (the DomeLight's ``portals`` relationship), and one-line
warnings or errors naming the prim for what cannot be used."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from simulator.errors import UserError
from simulator.plan.planner import make_plan, probe_method
from simulator.scene.model import Light, LightKind, Portal, Sensor, SensorKind
from simulator.scene.usd import load_stage

ROOT = Path(__file__).resolve().parent.parent


def stage(tmp_path: Path, body: str, name: str = "s.usda") -> Path:
    path = tmp_path / name
    path.write_text(f'#usda 1.0\n(\n    metersPerUnit = 0.01\n    upAxis = "Z"\n)\n\n{body}\n')
    return path


def dome(portals: str = "") -> str:
    rel = f"rel portals = [{portals}]" if portals else ""
    return f'def DomeLight "Sky"\n{{\n    float inputs:intensity = 100\n    {rel}\n}}\n'


def portal(name: str, extra: str = "", width: float = 200, height: float = 100) -> str:
    return (f'def PortalLight "{name}"\n{{\n    float inputs:width = {width}\n    float inputs:height = {height}\n    {extra}\n'
            '    double3 xformOp:translate = (0, 200, 160)\n    float3 xformOp:rotateXYZ = (90, 0, -90)\n'
            '    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]\n}\n')


def test_office_window_portal_is_read_onto_the_sky():
    """stages/office.usda: the sky's portal fills the window opening (x = 0,
    y 0.6…3.4 m, z 0.9…2.3 m) and passes light toward +X, into the room."""
    s = load_stage(ROOT / "stages" / "office.usda")
    sky = next(l for l in s.lights if l.kind == LightKind.DOME)
    (p,) = sky.portals
    np.testing.assert_allclose(p.corners()[[1, 3]], [[0, 0.6, 0.9], [0, 3.4, 2.3]], atol=1e-12)
    np.testing.assert_allclose(-p.frame[:, 2], [1, 0, 0], atol=1e-12)
    assert (p.width, p.height) == pytest.approx((2.8, 1.4))
    assert p.faces([3.0, 2.0, 0.8]) and not p.faces([-1.0, 2.0, 0.8])
    assert not any("Portal" in w for w in s.warnings), s.warnings


def test_portal_in_stage_units_with_its_scale(tmp_path):
    """Centimetre stage, a portal 200 × 100 cm scaled 1.5 along its X: 3 m × 1 m
    in world metres, centred at (0, 2, 1.6) m."""
    body = dome("</P>") + portal("P").replace('float3 xformOp:rotateXYZ = (90, 0, -90)',
                                             'float3 xformOp:rotateXYZ = (90, 0, -90)\n    float3 xformOp:scale = (1.5, 1, 1)'
                                             ).replace('"xformOp:rotateXYZ"]', '"xformOp:rotateXYZ", "xformOp:scale"]')
    s = load_stage(stage(tmp_path, body))
    (p,) = s.lights[0].portals
    assert (p.width, p.height) == pytest.approx((3.0, 1.0))
    np.testing.assert_allclose(p.position, [0, 2, 1.6], atol=1e-12)


def test_only_the_portals_a_dome_targets_are_its_own(tmp_path):
    """Two domes, two portals: each dome gets what its ``portals`` relationship
    names; a portal no dome names is ignored with a one-line warning naming it."""
    body = (dome("</P>") + dome().replace('"Sky"', '"Other"') + portal("P") + portal("Q"))
    s = load_stage(stage(tmp_path, body))
    by = {l.name: l for l in s.lights}
    assert [p.name for p in by["/Sky"].portals] == ["/P"] and by["/Other"].portals == ()
    assert [w for w in s.warnings if "/Q" in w] == [
        "/Q: PortalLight is in no DomeLight's portals relationship; ignored "
        "(a portal only guides a dome's sampling: add it to the dome's portals)"]


def test_zero_size_portal_is_warned_and_negative_size_refused(tmp_path):
    s = load_stage(stage(tmp_path, dome("</P>") + portal("P", width=0)))
    assert s.lights[0].portals == ()
    assert any(w.startswith("/P: PortalLight has zero size") for w in s.warnings), s.warnings
    with pytest.raises(UserError, match=r"s\.usda: /P: PortalLight height must be a non-negative number, not -1"):
        load_stage(stage(tmp_path, dome("</P>") + portal("P", height=-1)))


def test_portals_target_must_be_a_portal_light(tmp_path):
    body = dome("</Box>") + 'def Xform "Box"\n{\n}\n'
    with pytest.raises(UserError, match=r"s\.usda: /Sky: portals target /Box is a Xform, not a PortalLight"):
        load_stage(stage(tmp_path, body))
    with pytest.raises(UserError, match=r"s\.usda: /Sky: portals target /Gone is not on the stage"):
        load_stage(stage(tmp_path, dome("</Gone>")))


def test_portal_light_inputs_are_named_as_ignored(tmp_path):
    """A portal emits nothing itself: an authored intensity is counted in the summary warning."""
    s = load_stage(stage(tmp_path, dome("</P>") + portal("P", "float inputs:intensity = 3")))
    assert any("inputs:intensity of a PortalLight" in w for w in s.warnings), s.warnings


def test_portal_model_is_validated():
    frame = np.column_stack([[0, -1, 0], [0, 0, 1], [-1, 0, 0]])
    with pytest.raises(ValueError, match="width must be a positive"):
        Portal("/P", np.zeros(3), frame, 0.0, 1.0)
    with pytest.raises(ValueError, match="right-handed orthonormal"):
        Portal("/P", np.zeros(3), -frame, 1.0, 1.0)
    with pytest.raises(ValueError, match="only a DomeLight has portals"):
        Light("/R", LightKind.RECT, np.zeros(3), np.eye(3), (1.0, 1.0), portals=(Portal("/P", np.zeros(3), frame, 1.0, 1.0),))


def test_plan_reads_direct_light_of_a_portal_dome_with_mis():
    """A radiance meter reading direct light would get ``light``; with a
    portal dome the plan takes ``mis`` (light sampling draws that dome only
    through its portals), and an explicit ``light`` says so in its reason."""
    s = load_stage(ROOT / "stages" / "office.usda")
    meter = Sensor("m", SensorKind.RADIANCE, np.array([3.0, 2.0, 1.2]), np.array([0.0, 0.0, -1.0]))
    plan = make_plan(s, [meter], "auto", "direct")
    assert plan.sensors[0].method == "mis" and "portals" in plan.sensors[0].reason
    plan = make_plan(s, [meter], "light", "total")
    assert "only through its portals" in plan.sensors[0].reason
    assert "only through its portals" in probe_method(s, "light")[1]
