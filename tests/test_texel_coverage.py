"""Coverage read per texel: an opacity texture (UsdUVTexture into ``inputs:opacity``) at each hit.

Closed forms (written out here, independent of the code under test):

- UsdUVTexture's ``linear`` filter is bilinear between texel centres
  ((i + ½)/w, row 0 at t = 1): at a texel's centre it reads that texel; a
  sensor under a zero-angle zenith sun sees the sheet at its own (x, y), so
  under an open texel it reads E and under a shut one 0, exactly;
- a patch under the sheet collects E·A·(1 − ō), ō the mean opacity over its
  footprint (a presence sheet passes 1 − o at each point), or E·A·f with f
  the footprint's share where o < opacityThreshold;
- over whole periods of a repeating texture the bilinear filter keeps the
  texels' mean (each texel's tent weight integrates to one texel); for a
  ramp of w texels t_i = i/(w − 1) in s with ``clamp``,
  o(s) = clamp(s·w − ½, 0, w − 1)/(w − 1), so o < θ where s < (θ(w − 1) + ½)/w
  and ∫₀^½ o ds = (w/2 − ½)²/(2w(w − 1));
- under a uniform sky of luminance L, a black presence sheet whose pattern
  repeats far finer than its height passes (1 − ō)·πL.

Monte Carlo readings are held within 4 standard errors at fixed seeds.
"""

from __future__ import annotations

import math
import struct
import zlib
from pathlib import Path

import numpy as np
import pytest

from simulator.commands.cli import main
from simulator.engine.driver import Engine
from simulator.errors import UserError
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.usd import load_stage

E_SUN = 1000.0  # lx
L_DOME = 100.0  # cd/m²


def png_grey(path: Path, v: np.ndarray) -> None:
    """An 8-bit greyscale PNG (colour type 0) from an (H, W) uint8 array, written from the PNG specification."""
    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    h, w = v.shape
    raw = b"".join(b"\x00" + v[j].astype(np.uint8).tobytes() for j in range(h))
    ihdr = struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0)
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw))
                     + chunk(b"IEND", b""))


def checker(n: int = 8) -> np.ndarray:
    """n × n texels, 255 (opaque) where row + column is odd, 0 (open) where even."""
    return ((np.arange(n)[:, None] + np.arange(n)[None, :]) % 2 * 255).astype(np.uint8)


def material(file: str, mode: str = "presence", threshold: float = 0.0, wrap: str = "repeat", rho: float = 0.5,
             transform: str = "", space: str = "raw", output: str = "r") -> str:
    st = "</M/X.outputs:result>" if transform else "</M/R.outputs:result>"
    xform = f"""
    def Shader "X"
    {{
        uniform token info:id = "UsdTransform2d"
        float2 inputs:in.connect = </M/R.outputs:result>
        {transform}
        float2 outputs:result
    }}""" if transform else ""
    return f"""
def Material "M"
{{
    token outputs:surface.connect = </M/S.outputs:surface>
    def Shader "S"
    {{
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor = ({rho}, {rho}, {rho})
        float inputs:opacity.connect = </M/T.outputs:{output}>
        token inputs:opacityMode = "{mode}"
        float inputs:opacityThreshold = {threshold}
        token outputs:surface
    }}
    def Shader "T"
    {{
        uniform token info:id = "UsdUVTexture"
        asset inputs:file = @{file}@
        float2 inputs:st.connect = {st}
        token inputs:wrapS = "{wrap}"
        token inputs:wrapT = "{wrap}"
        token inputs:sourceColorSpace = "{space}"
        float outputs:{output}
    }}
    def Shader "R"
    {{
        uniform token info:id = "UsdPrimvarReader_float2"
        string inputs:varname = "st"
        float2 outputs:result
    }}{xform}
}}
"""


def sheet(z: float = 1.0, half: float = 1.0, interp: str = "faceVarying") -> str:
    h = half
    st = "[(0, 0), (1, 0), (1, 1), (0, 1)]"
    return f"""
def Mesh "Sheet" (
    prepend apiSchemas = ["MaterialBindingAPI"]
)
{{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(-{h}, -{h}, {z}), ({h}, -{h}, {z}), ({h}, {h}, {z}), (-{h}, {h}, {z})]
    texCoord2f[] primvars:st = {st} (interpolation = "{interp}")
    rel material:binding = </M>
}}
"""


SUN = f"""
def DistantLight "Sun"
{{
    float inputs:intensity = {E_SUN}
    float inputs:angle = 0
}}
"""
DOME = f'def DomeLight "Sky"\n{{\n    float inputs:intensity = {L_DOME}\n}}\n'


def stage(tmp_path: Path, body: str, name: str = "s.usda") -> Path:
    path = tmp_path / name
    path.write_text(f'#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n\n{body}\n')
    return path


def point(x: float, y: float) -> Sensor:
    return Sensor(name=f"p{x:g},{y:g}", kind=SensorKind.IRRADIANCE, position=np.array([x, y, 0.0]),
                  normal=np.array([0.0, 0.0, 1.0]))


def patch(x0: float, x1: float, y0: float, y1: float) -> Sensor:
    """An up-facing patch over [x0, x1] × [y0, y1] at z = 0 (its reading is the mean illuminance on it)."""
    return Sensor(name="patch", kind=SensorKind.PATCH, position=np.array([(x0 + x1) / 2, (y0 + y1) / 2, 0.0]),
                  normal=np.array([0.0, 0.0, 1.0]), up=np.array([0.0, 1.0, 0.0]), size=(x1 - x0, y1 - y0))


def run(path: Path, sensors, method: str, samples: int, seed: int = 7):
    res = Engine(load_stage(path), sensors).run(method, samples=samples, seed=seed)
    return res.mean[:, 1], res.stderr[:, 1]


def texel_centre(col: int, row: int, n: int, half: float = 1.0) -> tuple[float, float]:
    """World (x, y) under texel (col, row from the top) of an n × n texture on the sheet (st (0, 0) at −half)."""
    s, t = (col + 0.5) / n, 1.0 - (row + 0.5) / n
    return -half + 2 * half * s, -half + 2 * half * t


# --------------------------------------------------------------------------- #
# reading
# --------------------------------------------------------------------------- #


def test_reader_keeps_the_texels_and_the_corner_st(tmp_path):
    """The sheet's row keeps the texture (opacity per texel, its wraps) and each triangle corner's st; the
    opacity is not named as a texture mean. A UsdTransform2d (scale (2, 1), rotation 90°, translation
    (0.5, 0)) maps st to R(90°)(2s, t) + (0.5, 0) = (0.5 − t, 2s)."""
    png_grey(tmp_path / "c.png", checker())
    g = load_stage(stage(tmp_path, material("c.png") + sheet() + SUN)).geometry
    assert g.surfaces[0].opacity_texture == 0 and g.texture_id.tolist() == [0, 0]
    tex = g.coverage_textures[0]
    assert tex.opacity.shape == (8, 8) and tex.wrap == ("repeat", "repeat") and tex.primvar == "st"
    np.testing.assert_array_equal(tex.opacity, checker() / 255.0)
    corners = {(float(p[0]), float(p[1])): tuple(uv) for tri, uvs in zip(g.triangles, g.texture_uv)
               for p, uv in zip(g.points[tri], uvs)}
    assert corners[(-1.0, -1.0)] == (0.0, 0.0) and corners[(1.0, 1.0)] == (1.0, 1.0)
    xf = 'float2 inputs:scale = (2, 1)\n        float inputs:rotation = 90\n        float2 inputs:translation = (0.5, 0)'
    s = load_stage(stage(tmp_path, material("c.png", transform=xf) + sheet() + SUN, "x.usda"))
    assert not any("texture's mean" in w for w in s.warnings), s.warnings
    for tri, uvs in zip(s.geometry.triangles, s.geometry.texture_uv):
        for p, uv in zip(s.geometry.points[tri], uvs):
            st = ((p[0] + 1) / 2, (p[1] + 1) / 2)
            np.testing.assert_allclose(uv, (0.5 - st[1], 2 * st[0]), atol=1e-12)


def test_vertex_interpolated_st_reads_the_same(tmp_path):
    """``vertex`` interpolation (one st per point) gives the same corners as ``faceVarying`` here."""
    png_grey(tmp_path / "c.png", checker())
    a = load_stage(stage(tmp_path, material("c.png") + sheet() + SUN)).geometry
    b = load_stage(stage(tmp_path, material("c.png") + sheet(interp="vertex") + SUN, "v.usda")).geometry
    np.testing.assert_array_equal(a.texture_uv, b.texture_uv)


def test_a_prim_without_st_keeps_the_mean_and_says_so(tmp_path):
    """A textured opacity on a mesh that authors no primvars:st: the texture's mean, named once."""
    png_grey(tmp_path / "c.png", checker())
    body = material("c.png") + sheet().replace('texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1), (0, 1)] '
                                               '(interpolation = "faceVarying")', "")
    s = load_stage(stage(tmp_path, body + SUN))
    assert s.geometry.texture_id is None and s.geometry.surfaces[0].coverage == pytest.approx(0.5)
    assert any("without primvars:st (its mean used)" in w for w in s.warnings), s.warnings


def test_missing_opacity_texture_is_one_line_exit_2_nothing_written(tmp_path, capsys):
    """An opacity texture that is not there decides what blocks light: one line naming the texture's
    prim, its file and the input it feeds, exit 2, no output."""
    path = stage(tmp_path, material("nowhere.png") + sheet() + SUN)
    with pytest.raises(UserError, match=r"/M/T: inputs:file @nowhere\.png@ \(feeding /M/S\.inputs:opacity\): "
                                        r"not found or unreadable"):
        load_stage(path)
    cfg = tmp_path / "run.toml"
    cfg.write_text(f'stage = "{path.as_posix()}"\n[simulation]\nsamples = 64\n[[sensor]]\nkind = "irradiance"\n'
                   'position = [0, 0, 0]\nnormal = [0, 0, 1]\n[output]\ncsv = "out/run.csv"\n')
    code = main(["run", str(cfg), "-q"])
    err = capsys.readouterr().err.strip()
    assert code == 2 and err.count("\n") == 0 and "nowhere.png" in err and "/M/T" in err, err
    assert not (tmp_path / "out").exists()


# --------------------------------------------------------------------------- #
# presence, per texel
# --------------------------------------------------------------------------- #


@pytest.mark.parametrize("method", ["light", "path"])
def test_checkerboard_texels_are_open_or_shut_under_the_sun(tmp_path, method):
    """Under each texel's centre: E where the checker is open (row + column even), 0 where it is shut,
    exactly (a shadow ray's expected visibility at that point). The corners pin the orientation: row 0
    of the image is the top (t = 1), column 0 the left (s = 0)."""
    png_grey(tmp_path / "c.png", checker())
    cells = [(0, 0), (1, 0), (0, 7), (7, 7), (3, 4), (4, 4), (6, 1)]
    sensors = [point(*texel_centre(c, r, 8)) for c, r in cells]
    v, se = run(stage(tmp_path, material("c.png") + sheet() + SUN), sensors, method, 64)
    truth = [E_SUN * (1 - checker()[r, c] / 255) for c, r in cells]
    np.testing.assert_allclose(v, truth, atol=2e-6 * E_SUN)
    assert np.all(se == 0.0)


def test_a_patch_under_the_checkerboard_collects_half_the_sun(tmp_path):
    """A patch under the whole sheet (whole periods of a repeating checker, mean opacity ½): E/2 on
    average, within 4 standard errors (the patch's points are the only randomness)."""
    png_grey(tmp_path / "c.png", checker())
    v, se = run(stage(tmp_path, material("c.png") + sheet() + SUN), [patch(-1, 1, -1, 1)], "light", 20000)
    assert se[0] > 0 and abs(v[0] - 0.5 * E_SUN) <= 4 * se[0], (v, se)


def ramp(w: int = 256) -> np.ndarray:
    """One row of w texels t_i = i/(w − 1) (8-bit values i for w = 256), read raw."""
    return np.arange(w, dtype=np.uint8)[None, :]


@pytest.mark.parametrize("method", ["light", "path"])
def test_grey_presence_passes_one_minus_the_footprints_mean(tmp_path, method):
    """A grey ramp in s (clamp): a patch over s ∈ [0, ½] collects E(1 − 2∫₀^½ o ds) =
    E(1 − (w/2 − ½)²/(w(w − 1))), w = 256: 0.750977 E, within 4 standard errors."""
    png_grey(tmp_path / "r.png", ramp())
    w = 256
    truth = E_SUN * (1 - (w / 2 - 0.5) ** 2 / (w * (w - 1)))
    v, se = run(stage(tmp_path, material("r.png", wrap="clamp") + sheet() + SUN), [patch(-1, 0, -1, 1)], method,
                20000)
    assert se[0] > 0 and abs(v[0] - truth) <= 4 * se[0], (v, se, truth)


def test_fine_presence_pattern_passes_its_mean_of_the_sky_to_direction_samples(tmp_path):
    """A black presence sheet at 1 m whose checker repeats every 1 cm (st scaled by 10⁴ through a
    UsdTransform2d over a 100 m sheet), under a uniform sky: cosine directions pass with probability
    1 − o at the point they cross, drawn from each path's random stream: (1 − ½)πL within 4 standard
    errors (the sky beyond the sheet's edge passes whole: at most cos²(atan 50) = 4e-4 of it, the
    share outside the inscribed circle of radius 50 m, taken as the truth's second term, within 2e-4 πL
    of the square's and far inside the bound)."""
    png_grey(tmp_path / "c.png", checker())
    body = material("c.png", rho=0.0, transform="float2 inputs:scale = (10000, 10000)") + sheet(half=50.0) + DOME
    v, se = run(stage(tmp_path, body), [point(0.0, 0.0)], "bsdf", 20000)
    truth = 0.5 * math.pi * L_DOME + 0.5 * math.pi * L_DOME / (1 + 50.0**2)
    assert se[0] > 0 and abs(v[0] - truth) <= 4 * se[0], (v, se, truth)


# --------------------------------------------------------------------------- #
# opacityThreshold, per texel
# --------------------------------------------------------------------------- #


@pytest.mark.parametrize("threshold", [0.3, 0.8])
def test_threshold_cuts_the_ramp_where_it_crosses(tmp_path, threshold):
    """opacityThreshold θ on the ramp: open where the filtered o < θ, i.e. s < (θ·255 + ½)/256, shut
    beyond. Point sensors 1 mm either side of the edge read E and 0 exactly; a patch under the sheet
    collects E times that share of s, within 4 standard errors. θ = 0.8 is above the texture's mean
    (½): the sheet is not left out, as a uniform opacity ½ would be."""
    png_grey(tmp_path / "r.png", ramp())
    edge_s = (threshold * 255 + 0.5) / 256
    x = -1 + 2 * edge_s
    path = stage(tmp_path, material("r.png", mode="transparent", threshold=threshold, wrap="clamp") + sheet() + SUN)
    v, se = run(path, [point(x - 1e-3, 0.3), point(x + 1e-3, -0.2)], "light", 64)
    np.testing.assert_allclose(v, [E_SUN, 0.0], atol=2e-6 * E_SUN)
    v, se = run(path, [patch(-1, 1, -1, 1)], "light", 20000)
    assert se[0] > 0 and abs(v[0] - E_SUN * edge_s) <= 4 * se[0], (v, se, edge_s)


def test_untextured_coverage_keeps_its_reading(tmp_path):
    """A uniform presence opacity 0.3 beside (no texture): 0.7 E as before, and no texture uploaded."""
    body = material("c.png").replace("float inputs:opacity.connect = </M/T.outputs:r>", "float inputs:opacity = 0.3")
    s = load_stage(stage(tmp_path, body + sheet() + SUN))
    assert s.geometry.texture_id is None and s.geometry.surfaces[0].opacity_texture == -1
    v, se = run(stage(tmp_path, body + sheet() + SUN), [point(0.1, 0.2)], "light", 64)
    assert abs(v[0] - 0.7 * E_SUN) <= 2e-6 * E_SUN and se[0] == 0.0


def test_plan_names_the_texture(tmp_path):
    """probesim plan: the sheet's line says its coverage is read per texel, from which texture."""
    from simulator.plan.planner import make_plan

    png_grey(tmp_path / "c.png", checker())
    plan = make_plan(load_stage(stage(tmp_path, material("c.png") + sheet() + SUN)), [point(0.0, 0.0)])
    line = next(l for l in plan.surfaces if "/Sheet" in l or "/M" in l)
    assert "coverage per texel (presence)" in line and "c.png" in line and "8 x 8 texels" in line, line


def test_cut_emitters_carry_their_st():
    """An emitting triangle cut for the emitter pieces: each sub-triangle corner's st is the original's
    st at that corner (linear over the triangle), here st = (x, y)/4 on a 4 m right triangle."""
    from simulator.scene.emitters import split_emitters
    from simulator.scene.model import Geometry

    g = Geometry(points=np.array([[0, 0, 0], [4, 0, 0], [0, 4, 0.0]]), triangles=np.array([[0, 1, 2]], np.int32),
                 albedo=np.zeros(1), emission=np.array([[1.0, 1.0]]), two_sided=np.zeros(1, bool),
                 prim=np.zeros(1, np.int32), prim_names=["a"], texture_id=np.zeros(1, np.int32),
                 texture_uv=np.array([[[0, 0], [1, 0], [0, 1.0]]]))
    s, _ = split_emitters(g, 1.0)
    assert s.n_triangles == 36 and s.texture_id.tolist() == [0] * 36  # m = ⌈4√2 m / 1 m⌉ = 6: 6² pieces
    np.testing.assert_allclose(s.texture_uv, s.points[s.triangles][..., :2] / 4, atol=1e-12)


@pytest.mark.parametrize("how", ["leftHanded", "mirrored"])
def test_rewound_sheets_keep_their_texels_in_place(tmp_path, how):
    """A leftHanded sheet (its triangles re-wound) reads the checker as before; the sheet mirrored in x by
    its transform (scale (−1, 1, 1), re-wound too) shows texel column c at world column 7 − c, which on
    an 8 × 8 checker swaps open and shut: E where the plain sheet reads 0 and back, exactly."""
    png_grey(tmp_path / "c.png", checker())
    extra = ('uniform token orientation = "leftHanded"' if how == "leftHanded" else
             'float3 xformOp:scale = (-1, 1, 1)\n    uniform token[] xformOpOrder = ["xformOp:scale"]')
    body = material("c.png") + sheet().replace("rel material:binding", f"{extra}\n    rel material:binding") + SUN
    cells = [(0, 0), (1, 0), (3, 4), (6, 1)]
    v, _ = run(stage(tmp_path, body), [point(*texel_centre(c, r, 8)) for c, r in cells], "light", 64)
    open_ = [1 - checker()[r, c] / 255 for c, r in cells]
    truth = [E_SUN * (o if how == "leftHanded" else 1 - o) for o in open_]
    np.testing.assert_allclose(v, truth, atol=2e-6 * E_SUN)

