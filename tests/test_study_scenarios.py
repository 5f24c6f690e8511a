"""Scenarios: list levels expand into a product, the sun from place and time, a sun below the horizon is off."""

import math

import numpy as np
import pytest

from simulator.errors import UserError
from simulator.study.inputs.scenarios import expand_scenarios, resolve_groups, trace_groups_of
from simulator.study.schema import GroupSpec, ScenarioSpec
from simulator.study.inputs.sun import solar_position, sun_direction, sun_frame


def test_noon_elevation_at_the_june_solstice():
    """Solar noon elevation h = 90° − φ + δ with δ = 23.44° at the June solstice
    (Munich, φ = 48.14° N: 65.30°); the day's highest pvlib elevation (refraction
    adds about 0.01° there) agrees within 0.1°, due south (azimuth 180° ± 2°)."""
    best = max((solar_position(48.14, 11.58, f"2026-06-21T{h:02d}:{m:02d}:00+02:00") for h in (13,) for m in range(0, 60, 2)),
               key=lambda p: p[1])  # fmt: skip
    assert abs(best[1] - (90 - 48.14 + 23.44)) < 0.1
    assert abs(best[0] - 180.0) < 2.0


def test_sun_direction_convention():
    """Azimuth clockwise from north (+Y): 90° is east (+X); the frame's +Z points at the sun."""
    assert np.allclose(sun_direction(90.0, 0.0), [1, 0, 0], atol=1e-12)
    assert np.allclose(sun_direction(180.0, 30.0), [0, -math.cos(math.radians(30)), 0.5], atol=1e-12)
    f = sun_frame(sun_direction(250.0, 30.0))
    assert np.allclose(f.T @ f, np.eye(3), atol=1e-12) and np.isclose(np.linalg.det(f), 1.0)
    assert np.allclose(f[:, 2], sun_direction(250.0, 30.0))


def test_time_needs_its_offset():
    with pytest.raises(UserError, match="give the UTC offset"):
        solar_position(48.0, 11.0, "2026-06-21T12:00:00")


def _office():
    from simulator.scene.usd import load_stage

    return load_stage("stages/office.usda", light_units="photometric", radiometric_spectrum="E")


def test_product_expansion_and_night_sun():
    scene = _office()
    groups, unassigned = resolve_groups(scene, [GroupSpec(name="rows", lights=["/Office/Lights"]), GroupSpec(name="sun", lights=["/Office/Sun"])], "s.toml")
    assert len(groups["rows"]) == 6 and unassigned == ["/Office/Sky"]
    specs = [ScenarioSpec(name="dim", levels={"rows": [0.2, 0.6]}),
             ScenarioSpec(name="night", levels={"rows": 1.0, "sun": 1.0}, sun={"azimuth_deg": 0.0, "elevation_deg": -10.0})]  # fmt: skip
    sc = expand_scenarios(specs, list(groups), "s.toml")
    assert [s.name for s in sc] == ["dim[rows=0.2]", "dim[rows=0.6]", "night"]
    assert sc[0].levels == {"rows": 0.2, "sun": 0.0}
    tgs = trace_groups_of(sc, scene, groups, "s.toml")
    assert len(tgs) == 2 and tgs[0].groups == ["rows"]
    assert sc[2].levels["sun"] == 0.0 and "below the horizon" in sc[2].notes[0]
    assert tgs[1].groups == ["rows"]  # the sun is not traced where it is down


def test_group_errors():
    scene = _office()
    with pytest.raises(UserError, match=r"s.toml: group\[1\].lights\[0\]: /Office/Lights/WindowRow/Luminaire_1 is already in group 'a'"):
        resolve_groups(scene, [GroupSpec(name="a", lights=["/Office/Lights"]), GroupSpec(name="b", lights=["/Office/Lights/WindowRow/*"])], "s.toml")


def test_groups_from_usd_collections():
    """A group may name a UsdCollectionAPI collection (stages/office.usda): ``rowEnds``
    includes both rows and excludes each row's Luminaire_2; ``windowSide`` includes the
    WindowRow scope (expandPrims: its three luminaires), and with patterns the group is
    their union; a light that two groups' collections hold is refused, naming the key."""
    scene = _office()
    lum = "/Office/Lights/{}/Luminaire_{}".format
    groups, unassigned = resolve_groups(scene, [GroupSpec(name="ends", collection="/Office/Lights.collection:rowEnds")], "s.toml")
    assert groups["ends"] == [lum(r, i) for r in ("WindowRow", "CorridorRow") for i in (1, 3)]
    assert lum("WindowRow", 2) in unassigned and lum("CorridorRow", 2) in unassigned
    groups, _ = resolve_groups(scene, [GroupSpec(name="w", lights=["/Office/Sky"], collection="/Office/Lights.collection:windowSide")], "s.toml")
    assert groups["w"] == ["/Office/Sky"] + [lum("WindowRow", i) for i in (1, 2, 3)]
    with pytest.raises(UserError, match=r"s.toml: group\[1\].collection: /Office/Lights/WindowRow/Luminaire_1 is already in group 'ends'"):
        resolve_groups(scene, [GroupSpec(name="ends", collection="/Office/Lights.collection:rowEnds"),
                               GroupSpec(name="w", collection="/Office/Lights.collection:windowSide")], "s.toml")  # fmt: skip
