"""Variant selections: the config's ``variants`` table and the stage reader applying it.

A config's ``variants = { set = "variant" }`` selects that variant on every
prim of the stage that has the variant set, before the stage is read, so one
stage serves a whole sweep (stages/furnace.usda: rho_0_5, rho_0_9, rho_0_95).
"""

from __future__ import annotations

import csv
import json
import math
import textwrap
from pathlib import Path

import pytest

from simulator.commands.cli import main
from simulator.config.loader import load_config
from simulator.errors import UserError
from simulator.pipeline import load_scene
from simulator.scene.usd import load_stage

ROOT = Path(__file__).resolve().parents[1]
FURNACE = ROOT / "stages" / "furnace.usda"


def _config(tmp_path: Path, body: str, stage: Path = FURNACE) -> Path:
    p = tmp_path / "run.toml"
    p.write_text(f'stage = "{stage.as_posix()}"\n' + textwrap.dedent(body))
    return p


def _config_error(path: Path) -> str:
    with pytest.raises(UserError) as info:
        load_config(path)
    msg = str(info.value)
    assert "\n" not in msg and msg.startswith(f"{path}: "), msg
    return msg


# --------------------------------------------------------------------------- config


def test_config_reads_variants(tmp_path):
    """``variants`` is a table of strings; it lands in RunConfig.variants as given."""
    cfg = load_config(_config(tmp_path, 'variants = { reflectance = "rho_0_9", look = "dark" }\n'))
    assert cfg.variants == {"reflectance": "rho_0_9", "look": "dark"}


def test_config_without_variants_is_empty(tmp_path):
    """No ``variants`` key: no selections (the stage's own are used)."""
    assert load_config(_config(tmp_path, "")).variants == {}


@pytest.mark.parametrize(
    "body, key, words",
    [
        ('variants = "rho_0_9"\n', "variants", "expected a table, got string"),
        ("variants = { reflectance = 0.9 }\n", "variants.reflectance", "expected a string, got float"),
        ('variants = { reflectance = ["rho_0_9"] }\n', "variants.reflectance", "expected a string, got array"),
        ('variants = { reflectance = "" }\n', "variants.reflectance", "empty variant name"),
        ('variants = { "" = "rho_0_9" }\n', "variants.", "empty variant set name"),
        ('[variants]\nreflectance = { a = "b" }\n', "variants.reflectance", "expected a string, got table"),
    ],
)
def test_config_variant_type_errors(tmp_path, body, key, words):
    """Wrong types are one-line errors naming the config file and the key."""
    msg = _config_error(_config(tmp_path, body))
    assert f": {key}: " in msg and words in msg, msg


# --------------------------------------------------------------------------- stage reader


def test_selection_takes_effect():
    """The furnace's walls read albedo 0.5 by default (its authored selection)
    and 0.9 / 0.95 with the matching variant selected; emission is unchanged."""
    default = load_stage(FURNACE, light_units="radiometric")
    assert set(default.geometry.albedo) == {0.5}
    for name, rho in (("rho_0_9", 0.9), ("rho_0_95", 0.95), ("rho_0_5", 0.5)):
        scene = load_stage(FURNACE, light_units="radiometric", variants={"reflectance": name})
        assert set(scene.geometry.albedo) == {rho}, name
        assert set(scene.geometry.emission[:, 0]) == {1.0}


def test_selection_through_config_and_run(tmp_path):
    """run.load_scene passes the config's variants to the reader."""
    cfg = load_config(_config(tmp_path, 'light_units = "radiometric"\nvariants = { reflectance = "rho_0_95" }\n'))
    assert set(load_scene(cfg).geometry.albedo) == {0.95}


def test_unknown_variant_set_lists_the_sets_offered():
    """A set no prim has: the message names the key and lists the stage's sets."""
    with pytest.raises(UserError) as info:
        load_stage(FURNACE, variants={"reflectivity": "rho_0_9"})
    msg = str(info.value)
    assert "\n" not in msg and msg.startswith(f"{FURNACE}: variants.reflectivity: "), msg
    assert "offers: reflectance" in msg, msg


def test_unknown_selection_lists_the_variants_offered():
    """A variant the set lacks: the message names the key, the prim and every variant offered."""
    with pytest.raises(UserError) as info:
        load_stage(FURNACE, variants={"reflectance": "rho_0_7"})
    msg = str(info.value)
    assert msg.startswith(f"{FURNACE}: variants.reflectance: /World "), msg
    assert "rho_0_5, rho_0_9, rho_0_95" in msg, msg


_SHADE_SET = """variantSet "shade" = {
    "dark" {
        color3f[] primvars:displayColor = [(0.1, 0.1, 0.1)]
    }
    "light" {
        color3f[] primvars:displayColor = [(0.7, 0.7, 0.7)]
    }
}
"""


def _quad(z: float) -> str:
    return (
        "int[] faceVertexCounts = [4]\nint[] faceVertexIndices = [0, 1, 2, 3]\n"
        f"point3f[] points = [(0, 0, {z}), (1, 0, {z}), (1, 1, {z}), (0, 1, {z})]\n"
    )


def _mesh(name: str, selection: str, sets: str, z: float, extra: str = "") -> str:
    body = _quad(z) + _SHADE_SET + extra
    return (
        f'def Mesh "{name}" (\n    variants = {{\n        string shade = "{selection}"\n    }}\n'
        f"    prepend variantSets = {sets}\n)\n{{\n" + textwrap.indent(body, "    ") + "}\n"
    )


def _two_prim_stage(tmp_path: Path) -> Path:
    """Two meshes, each with its own "shade" variant set (dark 0.1 / light 0.7),
    /A's authored selection "dark", /B's "light"; /A also has a "finish" set
    whose "matte" variant holds a third mesh, /A/Inner, with "shade" too."""
    finish = (
        'variantSet "finish" = {\n    "gloss" {\n    }\n    "matte" {\n'
        + textwrap.indent(_mesh("Inner", "dark", '"shade"', 2.0), "        ")
        + "    }\n}\n"
    )
    text = (
        '#usda 1.0\n(\n    upAxis = "Z"\n    metersPerUnit = 1\n)\n\n'
        + _mesh("A", "dark", '["shade", "finish"]', 0.0, finish)
        + "\n"
        + _mesh("B", "light", '"shade"', 1.0)
    )
    p = tmp_path / "two.usda"
    p.write_text(text)
    return p


def _albedo_by_prim(scene) -> dict[str, float]:
    """Albedo of each prim's triangles (displayColor is float32: compare with approx)."""
    g = scene.geometry
    return {name: float(g.albedo[g.prim == k][0]) for k, name in enumerate(g.prim_names)}


def test_selection_applies_to_every_prim_with_the_set(tmp_path):
    """Selecting shade = light switches both meshes (B already authored it);
    shade = dark switches B away from its authored selection: the in-memory
    override layer's selection is the strongest opinion."""
    stage = _two_prim_stage(tmp_path)
    assert _albedo_by_prim(load_stage(stage)) == pytest.approx({"/A": 0.1, "/B": 0.7})
    assert _albedo_by_prim(load_stage(stage, variants={"shade": "light"})) == pytest.approx({"/A": 0.7, "/B": 0.7})
    assert _albedo_by_prim(load_stage(stage, variants={"shade": "dark"})) == pytest.approx({"/A": 0.1, "/B": 0.1})


def test_nested_variant_set_is_selected_too(tmp_path):
    """A prim that only exists inside another set's selected variant
    (/A/Inner, in finish = matte) gets the shade selection as well, and
    the file on disk is not changed by the selections."""
    stage = _two_prim_stage(tmp_path)
    before = stage.read_bytes()
    scene = load_stage(stage, variants={"finish": "matte", "shade": "light"})
    assert _albedo_by_prim(scene) == pytest.approx({"/A": 0.7, "/A/Inner": 0.7, "/B": 0.7})
    assert "/A/Inner" not in load_stage(stage).geometry.prim_names
    assert stage.read_bytes() == before


def test_cli_unknown_variant_exits_2_and_writes_nothing(tmp_path, capsys):
    """``probesim run`` with a variant the stage lacks: exit 2, one line on
    stderr naming the key and the variants offered, no CSV written."""
    csv = tmp_path / "out.csv"
    cfg = _config(
        tmp_path,
        f"""variants = {{ reflectance = "rho_0_99" }}
        [[sensor]]
        name = "s"
        kind = "irradiance"
        position = [0, 0, 1]
        normal = [0, 0, 1]
        [output]
        csv = "{csv.as_posix()}"
        """,
    )
    assert main(["run", str(cfg), "-q"]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "variants.reflectance" in err and "rho_0_5, rho_0_9, rho_0_95" in err, err
    assert not csv.exists()


def test_variant_flag_overrides_the_config(tmp_path):
    """`--variant reflectance=rho_0_5` replaces the furnace config's own
    rho_0_95 selection: the run reads the ρ = 0.5 furnace (E = 2π·L_e, within
    4 standard errors) and its run record names the selection it used."""
    root = Path(__file__).resolve().parents[1]
    out = tmp_path / "f.csv"
    assert main(["run", str(root / "configs" / "furnace.toml"), "--variant", "reflectance=rho_0_5",
                 "--samples", "4096", "-o", str(out), "-q"]) == 0  # fmt: skip
    rec = json.loads(out.with_name("f.run.json").read_text())
    assert rec["stage"]["variants"] == {"reflectance": "rho_0_5"}
    row = next(r for r in csv.DictReader(out.open()) if r["sensor"] == "centre_up")
    e, se = float(row["irradiance_W_m2"]), float(row["irradiance_stderr_W_m2"])
    assert abs(e - 2 * math.pi) <= 4 * se
