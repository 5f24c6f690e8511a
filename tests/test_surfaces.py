"""Surfaces beyond Lambert: reading UsdPreviewSurface's other inputs, coverage and dielectric panes.

Closed forms (independent of the code under test, written out here):

- a thin slab of index n, per polarisation with r the Fresnel reflectance of
  one interface, T = (1 − r)/(1 + r), R = 2r/(1 + r) (clear), and with an
  internal transmittance τ per pass T = (1 − r)²τ/(1 − r²τ²), R = r + (1 −
  r)²rτ²/(1 − r²τ²), averaged over s and p (Born & Wolf §1.5;
  docs/REFERENCES.md §Thin slab);
- under a zero-angle sun of normal illuminance E at zenith angle θ, an
  up-facing sensor under a pane reads E cosθ T(θ) exactly (light sampling
  through the pane: a shadow ray and its transmittance, zero variance);
- under a uniform dome of luminance L, an up-facing sensor under a sheet
  that lets a fraction f of every direction pass reads f πL; under a clear
  pane it reads 2πL ∫ T(θ) cosθ sinθ dθ.

Monte Carlo readings are held within 4 standard errors at fixed seeds.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from simulator.engine.driver import Engine
from simulator.errors import UserError
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.usd import load_stage

E_SUN = 1000.0  # lx
L_DOME = 100.0  # cd/m²


def fresnel(c, n):
    """(r_s, r_p) at incidence cosine c from air into index n (Fresnel's equations)."""
    s = math.sqrt(max(0.0, 1.0 - c * c))
    ct = math.sqrt(1.0 - (s / n) ** 2)
    return ((c - n * ct) / (c + n * ct)) ** 2, ((n * c - ct) / (n * c + ct)) ** 2


def slab(c, n, tau0=1.0):
    """Unpolarised (R, T) of a plane-parallel slab, written independently of simulator.scene.surfaces."""
    s = math.sqrt(max(0.0, 1.0 - c * c))
    ct = math.sqrt(1.0 - (s / n) ** 2)
    tau = tau0 ** (1.0 / ct)
    R = T = 0.0
    for r in fresnel(c, n):
        T += 0.5 * (1 - r) ** 2 * tau / (1 - (r * tau) ** 2)
        R += 0.5 * (r + (1 - r) ** 2 * r * tau * tau / (1 - (r * tau) ** 2))
    return R, T


def stage(tmp_path: Path, body: str, name: str = "s.usda") -> Path:
    path = tmp_path / name
    path.write_text(f'#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n\n{body}\n')
    return path


def material(name: str, extra: str = "", rho: float = 0.5, material_extra: str = "") -> str:
    return f"""
def Material "{name}"
{{
    token outputs:surface.connect = </{name}/S.outputs:surface>
    {material_extra}
    def Shader "S"
    {{
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor = ({rho}, {rho}, {rho})
        {extra}
        token outputs:surface
    }}
}}
"""


def quad(name: str, z: float, bind: str, half: float = 5.0) -> str:
    h = half
    return f"""
def Mesh "{name}"
{{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(-{h}, -{h}, {z}), ({h}, -{h}, {z}), ({h}, {h}, {z}), (-{h}, {h}, {z})]
    rel material:binding = </{bind}>
}}
"""


def box(name: str, z0: float, z1: float, bind: str, half: float = 5.0) -> str:
    """A closed box (outward normals) from z0 to z1, ±half in x and y."""
    h = half
    pts = [(-h, -h, z0), (h, -h, z0), (h, h, z0), (-h, h, z0), (-h, -h, z1), (h, -h, z1), (h, h, z1), (-h, h, z1)]
    faces = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    return f"""
def Mesh "{name}"
{{
    int[] faceVertexCounts = [4, 4, 4, 4, 4, 4]
    int[] faceVertexIndices = [{", ".join(str(i) for f in faces for i in f)}]
    point3f[] points = [{", ".join(f"({x}, {y}, {z})" for x, y, z in pts)}]
    rel material:binding = </{bind}>
}}
"""


def sun(zenith_deg: float) -> str:
    return f"""
def DistantLight "Sun"
{{
    float inputs:intensity = {E_SUN}
    float inputs:angle = 0
    float3 xformOp:rotateXYZ = ({zenith_deg}, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]
}}
"""


DOME = f'def DomeLight "Sky"\n{{\n    float inputs:intensity = {L_DOME}\n}}\n'


def up(z: float = 0.0) -> list[Sensor]:
    return [Sensor(name="up", kind=SensorKind.IRRADIANCE, position=np.array([0.0, 0.0, z]),
                   normal=np.array([0.0, 0.0, 1.0]))]


def run(path: Path, sensors, method: str, samples: int, seed: int = 7):
    res = Engine(load_stage(path), sensors).run(method, samples=samples, seed=seed)
    return res.mean[:, 1], res.stderr[:, 1]


# --------------------------------------------------------------------------- #
# reading
# --------------------------------------------------------------------------- #


def test_all_matte_stage_has_no_surface_table(tmp_path):
    """Inputs at their fallbacks (and none authored) leave every face matte: no table, the matte kernels."""
    body = material("M", "float inputs:roughness = 0.5\n        float inputs:ior = 1.5") + quad("Floor", 0, "M")
    g = load_stage(stage(tmp_path, body)).geometry
    assert g.surface_id is None and not g.has_surfaces


def test_inputs_are_read_per_material_into_one_table(tmp_path):
    """Two panes bound to one material share one row; a presence sheet has its own; the floor is matte."""
    body = (material("Glass", "float inputs:opacity = 0\n        float inputs:ior = 1.52\n"
                              "        float inputs:roughness = 0.1\n        float inputs:metallic = 0.25")
            + material("Mesh", 'float inputs:opacity = 0.3\n        token inputs:opacityMode = "presence"')
            + material("Matte") + quad("A", 1, "Glass") + quad("B", 2, "Glass") + quad("C", 3, "Mesh")
            + quad("Floor", 0, "Matte"))
    s = load_stage(stage(tmp_path, body))
    g = s.geometry
    rows = {g.prim_names[g.prim[t]]: int(g.surface_id[t]) for t in range(g.n_triangles)}
    assert rows["/A"] == rows["/B"] >= 0 and rows["/C"] >= 0 and rows["/C"] != rows["/A"] and rows["/Floor"] == -1
    glass, sheet = g.surfaces[rows["/A"]], g.surfaces[rows["/C"]]
    assert glass.pane and glass.ior == pytest.approx(1.52) and glass.coverage == 1.0
    assert glass.roughness == pytest.approx(0.1) and glass.metallic == pytest.approx(0.25)
    assert not sheet.pane and sheet.coverage == pytest.approx(0.3)
    # roughness and metallic are read but not modelled yet: named once each in the summary line
    assert any("1 x inputs:metallic" in w and "1 x inputs:roughness" in w for w in s.warnings), s.warnings


def test_opacity_mode_on_the_material_is_read(tmp_path):
    """Some exporters author opacityMode on the Material, not its shader: it is read there too."""
    body = material("M", "float inputs:opacity = 0.4", material_extra='token inputs:opacityMode = "presence"')
    g = load_stage(stage(tmp_path, body + quad("A", 1, "M"))).geometry
    assert g.surfaces[0].coverage == pytest.approx(0.4) and not g.surfaces[0].pane


@pytest.mark.parametrize("opacity, kept", [(0.4, False), (0.6, True)])
def test_opacity_threshold_cuts_out(tmp_path, opacity, kept):
    """opacityThreshold 0.5: opacity below it is not there (left out, a warning), at or above it opaque."""
    body = material("M", f"float inputs:opacity = {opacity}\n        float inputs:opacityThreshold = 0.5")
    s = load_stage(stage(tmp_path, body + quad("A", 1, "M") + quad("Wall", 0, "M2") + material("M2")))
    assert ("/A" in s.geometry.prim_names) == kept
    if kept:
        assert s.geometry.surface_id is None  # wholly opaque: matte
    else:
        assert any("/A" in w and "opacityThreshold" in w for w in s.warnings)


@pytest.mark.parametrize("extra, what", [
    ("float inputs:roughness = 1.2", "inputs:roughness 1.2"),
    ("float inputs:metallic = -0.1", "inputs:metallic -0.1"),
    ("float inputs:opacity = 1.5", "inputs:opacity 1.5"),
    ("float inputs:clearcoat = 2", "inputs:clearcoat 2"),
    ("float inputs:ior = 0.9", "inputs:ior 0.9"),
    ('token inputs:opacityMode = "cutout"', "inputs:opacityMode 'cutout'"),
    ("float probesim:transmittance = 0", "probesim:transmittance 0"),
    ("float probesim:transmittance = 1.2", "probesim:transmittance 1.2"),
    ("float probesim:transmittance = 0.95\n        float inputs:ior = 1.52", "above the 0.9183"),
])
def test_bad_inputs_are_one_line_naming_prim_and_input(tmp_path, extra, what):
    body = material("M", extra) + quad("A", 1, "M")
    with pytest.raises(UserError) as e:
        load_stage(stage(tmp_path, body))
    msg = str(e.value)
    assert "\n" not in msg and "/A" in msg and what in msg, msg


def test_bad_input_exits_2_and_writes_nothing(tmp_path):
    """The CLI: exit status 2, one line on stderr, no CSV."""
    import subprocess
    import sys

    path = stage(tmp_path, material("M", "float inputs:roughness = -1") + quad("A", 1, "M"))
    cfg = tmp_path / "c.toml"
    out = tmp_path / "out.csv"
    cfg.write_text(f'stage = "{path.name}"\n[simulation]\nmethod = "light"\nsamples = 4\n'
                   '[[sensor]]\nname = "s"\nkind = "irradiance"\nposition = [0, 0, 0]\nnormal = [0, 0, 1]\n'
                   f'[output]\ncsv = "{out.name}"\n')
    root = Path(__file__).resolve().parents[1]
    r = subprocess.run([sys.executable, "-m", "simulator", "run", str(cfg), "-q"], cwd=root, capture_output=True,
                       text=True, env={"PYTHONPATH": str(root), "PATH": "/usr/bin:/bin"})
    assert r.returncode == 2, r.stderr
    lines = [l for l in r.stderr.splitlines() if l.strip() and not l.startswith("Warning")]
    assert len(lines) == 1 and "inputs:roughness" in lines[0] and "/A" in lines[0], r.stderr
    assert not out.exists()


def test_datasheet_transmittance_is_an_absorbing_slab(tmp_path):
    """probesim:transmittance 0.70 on the Material: a pane whose slab transmits 0.70 at normal incidence."""
    from simulator.scene.surfaces import slab_rt

    body = material("M", "float inputs:ior = 1.52", material_extra="float probesim:transmittance = 0.7")
    g = load_stage(stage(tmp_path, body + quad("A", 1, "M"))).geometry
    row = g.surfaces[0]
    assert row.pane and row.transmittance == pytest.approx(0.7) and row.tau < 1
    assert float(slab_rt(1.0, row.ior, row.tau)[1]) == pytest.approx(0.7, rel=1e-12)
    assert slab(1.0, 1.52, row.tau)[1] == pytest.approx(0.7, rel=1e-12)


def test_closed_pane_mesh_is_found_with_its_orientation(tmp_path):
    """A box pane is closed with its front outward (+1); flipped winding gives −1; a sheet is open (0)."""
    body = material("G", "float inputs:opacity = 0") + box("Box", 1.0, 1.008, "G") + quad("Sheet", 3, "G")
    body += box("Flipped", 5.0, 5.008, "G").replace('def Mesh "Flipped"\n{', 'def Mesh "Flipped"\n{\n    uniform token orientation = "leftHanded"')
    g = load_stage(stage(tmp_path, body)).geometry
    side = {g.prim_names[g.prim[t]]: int(g.solid_side[t]) for t in range(g.n_triangles)}
    assert side == {"/Box": 1, "/Sheet": 0, "/Flipped": -1}


# --------------------------------------------------------------------------- #
# coverage
# --------------------------------------------------------------------------- #


@pytest.mark.parametrize("method", ["light", "path"])
def test_presence_sheet_passes_its_share_of_the_sun(tmp_path, method):
    """opacityMode presence, opacity 0.3: 70% of the sun's 1000 lx under it, exactly (expected visibility)."""
    body = material("M", 'float inputs:opacity = 0.3\n        token inputs:opacityMode = "presence"')
    v, se = run(stage(tmp_path, body + quad("Sheet", 1.0, "M") + sun(0)), up(), method, 64)
    assert abs(v[0] - 0.7 * E_SUN) <= 2e-6 * E_SUN and se[0] == 0.0


def test_presence_sheet_passes_its_share_of_sky_to_direction_samples(tmp_path):
    """Cosine directions under a black presence sheet (opacity 0.3) and a uniform sky: they pass with
    probability 0.7, unbiased: 0.7 πL within 4 standard errors."""
    body = material("M", 'float inputs:opacity = 0.3\n        token inputs:opacityMode = "presence"', rho=0.0)
    v, se = run(stage(tmp_path, body + quad("Sheet", 1.0, "M", half=1e3) + DOME), up(), "bsdf", 20000)
    truth = 0.7 * math.pi * L_DOME
    assert se[0] > 0 and abs(v[0] - truth) <= 4 * se[0], (v, se, truth)


# --------------------------------------------------------------------------- #
# panes
# --------------------------------------------------------------------------- #


@pytest.mark.parametrize("zenith", [0.0, 30.0, 60.0])
@pytest.mark.parametrize("method", ["light", "path"])
def test_clear_pane_passes_e_cos_t(tmp_path, zenith, method):
    """A clear pane (opacity 0, ior 1.52) under a delta sun: E cosθ T(θ) of the thin slab."""
    body = material("G", "float inputs:opacity = 0\n        float inputs:ior = 1.52") + quad("Pane", 1.0, "G")
    v, _ = run(stage(tmp_path, body + sun(zenith)), up(), method, 64)
    c = math.cos(math.radians(zenith))
    truth = E_SUN * c * slab(c, 1.52)[1]
    assert abs(v[0] - truth) <= 2e-6 * truth, (v, truth)


@pytest.mark.parametrize("zenith", [0.0, 30.0, 60.0])
def test_clear_pane_reflects_r(tmp_path, zenith):
    """A radiance meter looking at a clear pane at θ from its normal, a black floor beneath, a uniform
    sky above: it sees the sky reflected, R(θ)·L (direction samples reflect with probability R)."""
    th = math.radians(zenith)
    d = (0.0, math.sin(th), -math.cos(th))
    meter = [Sensor(name="m", kind=SensorKind.RADIANCE, position=np.array([0.0, -2.0 * d[1], 2.0]),
                    normal=np.array(d))]
    body = (material("G", "float inputs:opacity = 0\n        float inputs:ior = 1.52") + material("Black", rho=0.0)
            + quad("Pane", 0.0, "G", half=50) + quad("Floor", -0.5, "Black", half=1e3) + DOME)
    v, se = run(stage(tmp_path, body), meter, "path", 40000)
    truth = slab(math.cos(th), 1.52)[0] * L_DOME
    assert abs(v[0] - truth) <= 4 * se[0] + 1e-6 * truth, (v, se, truth)


@pytest.mark.parametrize("zenith", [0.0, 60.0])
def test_datasheet_pane_passes_its_transmittance(tmp_path, zenith):
    """probesim:transmittance 0.70: 0.70 E at normal incidence; at 60° the absorbing slab's T(θ)."""
    body = material("G", "float inputs:ior = 1.52\n        float probesim:transmittance = 0.7")
    v, _ = run(stage(tmp_path, body + quad("Pane", 1.0, "G") + sun(zenith)), up(), "light", 16)
    g = load_stage(stage(tmp_path, body + quad("Pane", 1.0, "G") + sun(zenith), "t.usda")).geometry
    c = math.cos(math.radians(zenith))
    truth = E_SUN * c * slab(c, 1.52, g.surfaces[0].tau)[1]
    if zenith == 0.0:
        assert truth == pytest.approx(0.7 * E_SUN, rel=1e-9)
    assert abs(v[0] - truth) <= 2e-6 * truth, (v, truth)


@pytest.mark.parametrize("thickness", [0.006, 0.010])
def test_box_pane_reads_as_the_sheet(tmp_path, thickness):
    """A pane exported as a closed thin box (6 and 10 mm) reads as the same pane as one sheet: the sun
    exactly, and a uniform sky (direction samples, inner reflections followed) within 1% and 4 σ."""
    mats = material("G", "float inputs:opacity = 0\n        float inputs:ior = 1.52")
    for light, method, n in ((sun(30), "light", 16), (DOME, "bsdf", 20000)):
        sheet, se_s = run(stage(tmp_path, mats + quad("Pane", 1.0, "G", half=200) + light, "a.usda"), up(), method, n)
        boxed, se_b = run(stage(tmp_path, mats + box("Pane", 1.0, 1.0 + thickness, "G", half=200) + light, "b.usda"),
                          up(), method, n, seed=8)
        se = math.hypot(se_s[0], se_b[0])
        assert abs(boxed[0] - sheet[0]) <= min(0.01 * sheet[0], 4 * se + 2e-6 * sheet[0]), (light[:12], sheet, boxed, se)


def test_clear_pane_passes_the_sky(tmp_path):
    """Under a clear pane and a uniform sky, with the sky sampled by light and cosine directions (MIS):
    2πL ∫ T(θ) cosθ sinθ dθ (adaptive quadrature of the slab formula)."""
    from scipy.integrate import quad as integrate

    body = material("G", "float inputs:opacity = 0\n        float inputs:ior = 1.52")
    v, se = run(stage(tmp_path, body + quad("Pane", 1.0, "G", half=1e3) + DOME), up(), "mis", 20000)
    truth = 2 * math.pi * L_DOME * integrate(lambda t: slab(math.cos(t), 1.52)[1] * math.cos(t) * math.sin(t),
                                             0, math.pi / 2, epsabs=1e-12)[0]
    assert abs(v[0] - truth) <= 4 * se[0], (v, se, truth)


def test_plan_names_the_surfaces_and_why(tmp_path):
    """probesim plan: one line per surface beyond Lambert, what it needs and why; none for a matte stage."""
    from simulator.plan.planner import format_plan, make_plan

    body = (material("G", "float inputs:opacity = 0\n        float inputs:roughness = 0.2")
            + material("M", 'float inputs:opacity = 0.3\n        token inputs:opacityMode = "presence"')
            + quad("Pane", 1.0, "G") + box("Box", 2.0, 2.008, "G") + quad("Sheet", 3.0, "M") + sun(0))
    scene = load_stage(stage(tmp_path, body))
    plan = make_plan(scene, up())
    text = format_plan(plan)
    assert plan.sensors[0].method != "exact"
    pane = next(l for l in plan.surfaces if "dielectric slab" in l)
    assert "opacity 0 in transparent mode" in pane and "12 on closed meshes" in pane and "roughness" in pane
    assert any("coverage 0.3" in l and "presence mode" in l for l in plan.surfaces)
    assert text.count("\nsurface ") == 2
    matte = load_stage(stage(tmp_path, material("X") + quad("F", 0, "X") + sun(0), "m.usda"))
    assert make_plan(matte, up()).surfaces == []
