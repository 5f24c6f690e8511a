"""Variant selections by prim path: two wheels carrying a variant set of the same name.

A by-set selection (``wheelStyle = "sport"``) selects on every prim with the
set; a selection keyed by prim path (``"/Car/WheelFL" = { wheelStyle =
"sport" }``, or ``--variant /Car/WheelFL:wheelStyle=sport``) on that prim
only. Each wheel's variant is a triangle of a different albedo, so the
albedos read tell which variant each wheel got.
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from simulator.config.loader import apply_overrides, load_config
from simulator.errors import UserError
from simulator.pipeline import load_scene
from simulator.scene.usd import load_stage


def _wheel(name: str) -> str:
    def variant(vname: str, albedo: float) -> str:
        return f'''
            "{vname}" {{
                def Mesh "Tyre"
                {{
                    int[] faceVertexCounts = [3]
                    int[] faceVertexIndices = [0, 1, 2]
                    point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
                    color3f[] primvars:displayColor = [({albedo}, {albedo}, {albedo})]
                }}
            }}'''
    return f'''
    def Xform "{name}" (
        variants = {{ string wheelStyle = "classic" }}
        prepend variantSets = "wheelStyle"
    )
    {{
        variantSet "wheelStyle" = {{{variant("classic", 0.2)}{variant("sport", 0.7)}
        }}
    }}'''


@pytest.fixture
def car(tmp_path: Path) -> Path:
    p = tmp_path / "car.usda"
    p.write_text('#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n\ndef Xform "Car"\n{'
                 + _wheel("WheelFL") + _wheel("WheelFR") + '\n}\n\ndef SphereLight "L"\n{\n}\n')
    return p


def _albedos(scene) -> dict[str, float]:
    g = scene.geometry
    return {g.prim_names[g.prim[t]]: round(float(g.albedo[t]), 6) for t in range(g.n_triangles)}  # float32 colours


def test_a_prim_path_selects_on_that_prim_only(car):
    assert _albedos(load_stage(car)) == {"/Car/WheelFL/Tyre": 0.2, "/Car/WheelFR/Tyre": 0.2}
    assert _albedos(load_stage(car, variants={"wheelStyle": "sport"})) == {
        "/Car/WheelFL/Tyre": 0.7, "/Car/WheelFR/Tyre": 0.7}  # by set: both wheels
    only = load_stage(car, variants={"/Car/WheelFL": {"wheelStyle": "sport"}})
    assert _albedos(only) == {"/Car/WheelFL/Tyre": 0.7, "/Car/WheelFR/Tyre": 0.2}
    # the path wins over the set on its prim
    both = load_stage(car, variants={"wheelStyle": "sport", "/Car/WheelFR": {"wheelStyle": "classic"}})
    assert _albedos(both) == {"/Car/WheelFL/Tyre": 0.7, "/Car/WheelFR/Tyre": 0.2}


def test_config_table_and_flag(car, tmp_path):
    cfg_path = tmp_path / "run.toml"
    cfg_path.write_text(textwrap.dedent(f'''\
        stage = "{car.as_posix()}"
        [variants]
        "/Car/WheelFR" = {{ wheelStyle = "sport" }}
        '''))
    cfg = load_config(cfg_path)
    assert cfg.variants == {"/Car/WheelFR": {"wheelStyle": "sport"}}
    assert _albedos(load_scene(cfg)) == {"/Car/WheelFL/Tyre": 0.2, "/Car/WheelFR/Tyre": 0.7}
    flagged = apply_overrides(cfg, variants=["/Car/WheelFL:wheelStyle=sport", "/Car/WheelFR:wheelStyle=classic"])
    assert flagged.variants == {"/Car/WheelFR": {"wheelStyle": "classic"}, "/Car/WheelFL": {"wheelStyle": "sport"}}
    assert cfg.variants == {"/Car/WheelFR": {"wheelStyle": "sport"}}  # the config itself is left unchanged
    assert _albedos(load_scene(flagged)) == {"/Car/WheelFL/Tyre": 0.7, "/Car/WheelFR/Tyre": 0.2}


@pytest.mark.parametrize("variants, words", [
    ({"/Car/WheelRL": {"wheelStyle": "sport"}}, "variants./Car/WheelRL: no prim at that path in the stage"),
    ({"/Car/WheelFL": {"rimColour": "red"}},
     "variants./Car/WheelFL.rimColour: /Car/WheelFL has no variant set 'rimColour' (it has: wheelStyle)"),
    ({"/Car/WheelFL": {"wheelStyle": "rally"}},
     "variants./Car/WheelFL.wheelStyle: /Car/WheelFL offers no variant 'rally' (its variant set 'wheelStyle' offers: "
     "classic, sport)"),
])
def test_stage_errors_name_prim_set_and_variant(car, variants, words):
    with pytest.raises(UserError) as info:
        load_stage(car, variants=variants)
    msg = str(info.value)
    assert "\n" not in msg and msg == f"{car}: {words}", msg


@pytest.mark.parametrize("body, key, words", [
    ('"/Car/Wheel FL" = { wheelStyle = "sport" }', "variants./Car/Wheel FL", "not a prim path"),
    ('"/Car/WheelFL" = "sport"', "variants./Car/WheelFL", "expected a table of variant set = variant"),
    ('"/Car/WheelFL" = { wheelStyle = 3 }', "variants./Car/WheelFL.wheelStyle", "expected a string, got integer"),
    ('"/Car/WheelFL" = { wheelStyle = "" }', "variants./Car/WheelFL.wheelStyle", "empty variant name"),
    ('"/Car/WheelFL" = {}', "variants./Car/WheelFL", "no selections"),
])
def test_config_errors_are_one_line_naming_the_key(tmp_path, car, body, key, words):
    p = tmp_path / "run.toml"
    p.write_text(f'stage = "{car.as_posix()}"\n[variants]\n{body}\n')
    with pytest.raises(UserError) as info:
        load_config(p)
    msg = str(info.value)
    assert "\n" not in msg and msg.startswith(f"{p}: {key}: ") and words in msg, msg


def test_flag_errors(car, tmp_path):
    p = tmp_path / "run.toml"
    p.write_text(f'stage = "{car.as_posix()}"\n')
    with pytest.raises(UserError) as info:
        apply_overrides(load_config(p), variants=["/Car/WheelFL=sport"])
    assert str(info.value) == "--variant: expected SET=VARIANT or /PRIM/PATH:SET=VARIANT, got '/Car/WheelFL=sport'"
    with pytest.raises(UserError) as info:
        apply_overrides(load_config(p), variants=["/Car/WheelFL:wheelStyle="])
    assert str(info.value) == "--variant: empty variant name"
