"""Hero-wavelength transport in the kernels: a coloured furnace read by a whole run, the grey reduction's
error measured on it, and grey scenes left to one channel.

The furnace (stages/furnace.usda, docs/REFERENCES.md §Furnace): a closed box
whose walls all emit L_e(λ) and reflect diffusely with albedo ρ(λ); inside it
the radiance is L_e(λ)/(1 − ρ(λ)) everywhere (the Neumann series
Σ_n ρⁿ L_e, wavelength by wavelength), so for a response with quadrature
vector q (simulator.spectra.responses)::

    irradiance  R_E = π ∫ q(λ) L_e(λ) / (1 − ρ(λ)) dλ,
    radiance    R_L =   ∫ q(λ) L_e(λ) / (1 − ρ(λ)) dλ,
    patch flux  Φ   = A · R_E.

Here ρ = uplift(0.8, 0.2, 0.2) (Mallett & Yuksel 2019, a saturated red) and
L_e is D65 scaled to 1 W m⁻² sr⁻¹ over 380–780 nm. One channel (the grey
reduction, ρ_g = BT.709 grey = 0.32756) reads π R[L_e]/(1 − ρ_g) instead:
−20.6 % illuminance, −30.0 % PPFD, +17.6 % melanopic EDI
(tests/test_spectra_furnace.py computes these from the closed form).
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest

from simulator.config.loader import load_config
from simulator.pipeline import run
from simulator.spectra import reflectance, responses as R, sources
from simulator.units import luminance_grey

ROOT = Path(__file__).resolve().parents[1]
RED = (0.8, 0.2, 0.2)
NAMES = ("photopic", "par", "melanopic_edi")
PATCH_AREA_M2 = 4.0 * 3.0


def _stage(tmp_path: Path, rgb) -> Path:
    """stages/furnace.usda with the rho_0_5 variant's diffuseColor set to ``rgb``."""
    text = (ROOT / "stages" / "furnace.usda").read_text()
    grey = "color3f inputs:diffuseColor = (0.5, 0.5, 0.5)"
    assert text.count(grey) == 1
    p = tmp_path / "furnace_coloured.usda"
    p.write_text(text.replace(grey, f"color3f inputs:diffuseColor = ({rgb[0]}, {rgb[1]}, {rgb[2]})"))
    return p


def _config(tmp_path: Path, rgb, samples: int, seed: int = 5, extra: str = "") -> Path:
    p = tmp_path / "furnace.toml"
    p.write_text(f'''stage = "{_stage(tmp_path, rgb).as_posix()}"
light_units = "radiometric"
radiometric_spectrum = "D65"
variants = {{ reflectance = "rho_0_5" }}

[simulation]
method = "path"
samples = {samples}
seed = {seed}

[[sensor]]
name = "up"
kind = "irradiance"
position = [0, 0, 1.25]
normal = [0, 0, 1]

[[sensor]]
name = "meter"
kind = "radiance"
position = [0.5, 0.2, 1.0]
direction = [0, 1, 0]
half_angle_deg = 5.0

[[sensor]]
name = "floor"
kind = "patch"
position = [0, 0, 0]
normal = [0, 0, 1]
size = [4, 3]
up = [0, 1, 0]
{extra}
[output]
csv = "out/furnace.csv"
responses = ["par", "melanopic_edi"]
''')
    return p


def _truth(name: str, rgb) -> float:
    """∫ q L_e/(1 − ρ) dλ (radiance; × π for irradiance), on the grid (trapezoid rule)."""
    d65 = sources.cie_illuminant("D65")
    le = d65.values / d65.radiometric
    return float(R.response(name).of(le / (1.0 - reflectance.uplift(rgb))))


def _grey_reduction(name: str, rgb) -> float:
    """What one channel reads (radiance): R[L_e]/(1 − grey(rgb))."""
    d65 = sources.cie_illuminant("D65")
    return float(R.response(name).of(d65.values / d65.radiometric)) / (1.0 - luminance_grey(rgb))


@pytest.fixture(scope="module")
def red_run(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("red_furnace")
    out = run(load_config(_config(tmp, RED, samples=6000)), log=lambda *a: None)
    with open(out.csv_path, newline="") as f:
        return out, {r["sensor"]: r for r in csv.DictReader(f)}


def _read(row: dict, name: str, quantity: str) -> tuple[float, float]:
    col, col_se = R.response(name).columns(quantity)
    if name == "photopic":
        col, col_se = {"irradiance": ("illuminance_lx", "illuminance_stderr_lx"),
                       "radiance": ("luminance_cd_m2", "luminance_stderr_cd_m2"),
                       "flux": ("luminous_flux_lm", "luminous_flux_stderr_lm")}[quantity]
    return float(row[col]), float(row[col_se])


def test_the_coloured_furnace_reads_the_spectral_closed_form(red_run):
    """Illuminance, PPFD and melanopic EDI (and their radiance and flux
    twins) of the red furnace, traced by a whole run (``simulator.run``, 6000
    samples, seed 5), lie within 4 standard errors of ∫ q L_e/(1 − ρ) dλ (× π
    for irradiance, × π A for the patch's flux); the grey reduction's
    value lies more than 20 standard errors away from each."""
    out, rows = red_run
    assert out.record["plan"]["transport"] == "spectral"
    cases = (("up", "irradiance", math.pi), ("meter", "radiance", 1.0), ("floor", "flux", math.pi * PATCH_AREA_M2))
    for sensor, quantity, factor in cases:
        for name in NAMES:
            mean, se = _read(rows[sensor], name, quantity)
            truth = factor * _truth(name, RED)
            assert se > 0
            assert abs(mean - truth) <= 4 * se + 1e-6 * truth, (sensor, name, mean, truth, se)
            assert abs(factor * _grey_reduction(name, RED) - truth) > 20 * se, (sensor, name)


def test_the_grey_reduction_error_measured_on_the_red_furnace(red_run, tmp_path):
    """The same stage traced with one channel (the engine without hero tables:
    colours reduced to their luminance grey, as runs did before spectral
    transport) reads the grey closed form, and so misses the spectral one by
    −20.6 % (illuminance), −30.0 % (PPFD) and +17.6 % (melanopic EDI):
    measured here within 4 standard errors of those closed-form errors."""
    from simulator.engine.driver import Engine
    from simulator.spectra.posthoc import posthoc_ratio

    out, rows = red_run
    sensors = [s for s in load_config(_config(tmp_path, RED, 4000)).sensors if s.name == "up"]
    grey = Engine(out.scene, sensors, device="cpu").run("path", samples=4000, seed=7)
    e, e_se = grey.mean[0, 0], grey.stderr[0, 0]  # W/m², one channel
    d65 = sources.cie_illuminant("D65").values
    expected = {"photopic": -0.206, "par": -0.300, "melanopic_edi": 0.176}
    for name in NAMES:
        reading, se = e * posthoc_ratio(R.response(name), d65), e_se * posthoc_ratio(R.response(name), d65)
        truth = math.pi * _truth(name, RED)
        closed_error = _grey_reduction(name, RED) / _truth(name, RED) - 1.0
        assert closed_error == pytest.approx(expected[name], abs=5e-4)
        assert abs(reading / truth - 1.0 - closed_error) <= 4 * se / truth, (name, reading / truth - 1.0)
        spectral, s_se = _read(rows["up"], name, "irradiance")
        assert abs(spectral / truth - 1.0) <= 4 * s_se / truth


def test_a_grey_furnace_traced_spectrally_agrees_with_one_channel(tmp_path):
    """Grey walls (0.5, 0.5, 0.5): the plan keeps one channel (the run is
    not traced spectrally), and hero wavelengths forced on the same scene
    agree with it within 4 combined standard errors for W, lux and (post
    hoc on the one channel) PPFD; both read π L_e/(1 − ρ) = 2π W/m²."""
    from simulator.engine.driver import Engine
    from simulator.spectra.hero import hero_tables
    from simulator.spectra.posthoc import posthoc_ratio

    out = run(load_config(_config(tmp_path, (0.5, 0.5, 0.5), samples=64)), log=lambda *a: None)
    assert out.record["plan"]["transport"] == "grey" and out.record["spectra"]["path"].startswith("post-hoc")
    sensors = [s for s in load_config(_config(tmp_path, (0.5, 0.5, 0.5), 64)).sensors if s.name == "up"]
    one = Engine(out.scene, sensors, device="cpu").run("path", samples=4000, seed=3)
    assert one.responses is None
    eng = Engine(out.scene, sensors, device="cpu")
    eng.set_hero_tables(hero_tables(out.scene, "radiometric", "D65", [R.response("par")]))
    hero = eng.run("path", samples=4000, seed=3)
    assert hero.responses == ["radiometric", "photopic", "par"]
    for c in range(2):
        assert np.allclose(hero.mean[0, c], hero.response_mean[0, c], rtol=1e-5)
        combined = math.hypot(one.stderr[0, c], hero.stderr[0, c])
        assert abs(one.mean[0, c] - hero.mean[0, c]) <= 4 * combined, c
    assert abs(one.mean[0, 0] - 2 * math.pi) <= 4 * one.stderr[0, 0]
    ratio = posthoc_ratio(R.response("par"), sources.cie_illuminant("D65").values)
    combined = math.hypot(one.stderr[0, 0] * ratio, hero.response_stderr[0, 2])
    assert abs(one.mean[0, 0] * ratio - hero.response_mean[0, 2]) <= 4 * combined


def test_hero_nodes_follow_the_trapezoid_weights():
    """The kernel's hero sampler (``estimators.hero_nodes``) draws each lane's
    grid node i with probability w_i/400 (w the trapezoid weights: ½ at 380
    and 780 nm, 1 between), the pdf that ``spectra.hero.response_weights``
    (400·q/w) divides out: chi-square over the 401 nodes, lanes pooled, from
    200,000 uniforms (seed 9), p > 1e-3; and the 4 lanes of one sample lie
    100 nm apart (mod 400)."""
    import warp as wp
    from scipy import stats

    from simulator.engine.device import warp
    from simulator.kernels import spectral
    from simulator.spectra.grid import trapezoid_weights

    warp()
    n = 200_000
    u = np.random.default_rng(9).random(n).astype(np.float32)
    nodes = wp.empty(n, dtype=wp.vec4i, device="cpu")
    wp.launch(_hero_nodes_kernel, dim=n, inputs=[wp.array(u, dtype=float, device="cpu")], outputs=[nodes], device="cpu")
    h = nodes.numpy()
    assert h.min() >= 0 and h.max() <= 400
    gaps = np.mod(np.diff(h, axis=1), 400)
    assert np.all(np.abs(gaps - 100) <= 1)  # each lane rounds on its own: 99–101
    counts = np.bincount(h.ravel(), minlength=401)
    expected = 4 * n * trapezoid_weights() / 400.0
    assert stats.chisquare(counts, expected).pvalue > 1e-3
    assert spectral.N_HERO == 4


def _make_hero_kernel():
    import warp as wp

    from simulator.kernels.spectral import hero_nodes

    @wp.kernel
    def draw(u: wp.array(dtype=float), out: wp.array(dtype=wp.vec4i)):
        t = wp.tid()
        out[t] = hero_nodes(u[t])

    return draw


_hero_nodes_kernel = _make_hero_kernel()


def test_a_probe_in_the_red_furnace_maps_its_colour(tmp_path):
    """A probe traced spectrally: in the furnace every direction sees the
    radiance L(λ) = L_e(λ)/(1 − ρ(λ)), so every pixel of its lat-long EXR
    reads the linear sRGB ``M K_m ∫ L (x̄, ȳ, z̄) dλ`` (cd/m², CIE 1931 2°,
    IEC 61966-2-1 M; here × L_W/L_v per pixel for the stage's radiometric
    units), and its scalar illuminance 4π K_m ∫ V L dλ: the pixels' mean
    colour and the scalar illuminance each within 4 standard errors (8 × 4
    pixels, 200 passes, seed 5; the pixels' spread gives the mean's stderr:
    each pixel has the same expectation). The red walls make it red: R > G, B."""
    import OpenEXR

    from simulator.spectra.hero import colour_weights
    from simulator.spectra.grid import trapezoid_weights

    probe = '[[sensor]]\nname = "ball"\nkind = "probe"\nposition = [0, 0, 1.25]\nresolution = [8, 4]\n'
    cfg = load_config(_config(tmp_path, RED, samples=32 * 200, extra=probe))
    out = run(cfg, log=lambda *a: None)
    row = next(r for r in out.rows if r.sensor.name == "ball")
    truth_lx = 4 * math.pi * _truth("photopic", RED)
    v, se = row.values["scalar_illuminance_lx"], row.values["scalar_illuminance_stderr_lx"]
    assert abs(v - truth_lx) <= 4 * se, (v, truth_lx, se)
    d65 = sources.cie_illuminant("D65")
    radiance = d65.values / d65.radiometric / (1.0 - reflectance.uplift(RED))  # W m⁻² sr⁻¹ nm⁻¹
    rgb_truth = colour_weights() / 400.0 @ (trapezoid_weights() * radiance)  # cd/m²
    exr = OpenEXR.File(str(tmp_path / "out" / "furnace.ball.exr"), separate_channels=True)
    ch = {k: c.pixels.astype(float) for k, c in exr.channels().items()}
    assert "traced spectrum" in exr.header()["probesim:rgb"]
    for k, c in enumerate("RGB"):
        pix = ch[c] * ch["Lv_cd_m2"] / ch["L_W_m2_sr"]  # back to cd/m²: the map's R, G, B are × L_W/L_v
        assert abs(pix.mean() - rgb_truth[k]) <= 4 * pix.std(ddof=1) / math.sqrt(pix.size), (c, pix.mean(), rgb_truth[k])
    assert rgb_truth[0] > rgb_truth[1] and rgb_truth[0] > rgb_truth[2]


_TWO_LAMPS = """#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
    defaultPrim = "World"
)

def Xform "World"
{
    def SphereLight "Warm"
    {
        float inputs:intensity = 400
        bool inputs:normalize = 1
        float inputs:radius = 0.05
        bool inputs:enableColorTemperature = 1
        float inputs:colorTemperature = 2700
        bool treatAsPoint = 1
        double3 xformOp:translate = (0, 0, 3)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def SphereLight "Daylight"
    {
        float inputs:intensity = 800
        bool inputs:normalize = 1
        float inputs:radius = 0.05
        bool treatAsPoint = 1
        double3 xformOp:translate = (2, 0, 2)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
"""


def test_lamps_of_two_spectra_read_their_sum(tmp_path):
    """A grey scene whose two point lights differ in spectrum (2700 K and
    D65): the plan says per-emitter, the readings are traced with hero
    wavelengths, and the sensor's closed-form lux (planner: analytic) keep
    E = Σ I_l cosθ_l/d_l² (100 cd at 3 m overhead, 200 cd at (2, 0, 2):
    11.111 + 200·(2/√8)/8 = 28.79 lx) while its PPFD, estimated by
    direct-light sampling, reads Σ E_l · (PAR per lux of S_l) within 4
    standard errors (CIE S 026 / McCree weights on the grid)."""
    stage = tmp_path / "two_lamps.usda"
    stage.write_text(_TWO_LAMPS)
    cfg = tmp_path / "two.toml"
    cfg.write_text(f'stage = "{stage.as_posix()}"\nlight_units = "photometric"\n\n[simulation]\nsamples = 4000\n'
                   'seed = 2\n\n[[sensor]]\nname = "below"\nkind = "irradiance"\nposition = [0, 0, 0]\n'
                   'normal = [0, 0, 1]\n\n[output]\ncsv = "out/two.csv"\nresponses = ["par"]\n')
    out = run(load_config(cfg), log=lambda *a: None)
    assert out.record["plan"]["transport"] == "per-emitter"
    row = out.rows[0]
    e_l = np.array([100.0 / 9.0, 200.0 * (2.0 / math.sqrt(8.0)) / 8.0])  # lx
    assert row.values["illuminance_lx"] == pytest.approx(e_l.sum(), rel=1e-5)
    per_lux = [R.response("par").of(s.values) / R.response("photopic").of(s.values)
               for s in (sources.blackbody(2700.0), sources.cie_illuminant("D65"))]
    truth = float(e_l @ np.array(per_lux))
    v, se = row.values["ppfd_umol_m2_s"], row.values["ppfd_stderr_umol_m2_s"]
    assert se > 0 and abs(v - truth) <= 4 * se, (v, truth, se)
    assert any("direct-light sampling" in w for w in out.record["warnings"])


def test_the_cost_measurement_runs_and_sees_the_green_walls(capsys):
    """``python benchmarks/spectral_cost.py`` on a short run (1,000 samples,
    one repeat) prints a line per response; the one channel's PPFD on the
    green-walled room is biased high (its D65 ratio ignores the green
    interreflections, which carry fewer photons per lumen than D65): the
    mean bias over the five sensors exceeds 4 % where its noise is ~1 %."""
    import importlib.util

    script = Path(__file__).resolve().parent.parent / "benchmarks" / "spectral_cost.py"
    spec = importlib.util.spec_from_file_location("spectral_cost", script)
    cost = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(cost)
    NAMES, main, measure = cost.NAMES, cost.main, cost.measure

    assert main(["--samples", "1000", "--repeats", "1"]) == 0
    text = capsys.readouterr().out
    assert all(n in text for n in NAMES) and "time to equal error" in text
    m = measure(1000, "cpu", (0.2, 0.7, 0.3), repeats=1)
    bias = m["one channel"]["mean"][:, 1] / m["hero"]["mean"][:, 1] - 1.0
    assert bias.mean() > 0.04, bias


def test_every_command_traces_a_coloured_room_as_a_run_does(tmp_path):
    """``probesim bench`` and ``probesim chart`` build their engine with
    :func:`simulator.pipeline.config_engine`, as ``probesim run`` does: a
    coloured room gets the hero tables (so the red furnace's lux is the
    spectral value, not the grey reduction 20% off), a grey one none."""
    from simulator.pipeline import collect_sensors, config_engine, load_scene

    for rgb, spectral in ((RED, True), ((0.5, 0.5, 0.5), False)):
        cfg = load_config(_config(tmp_path, rgb, samples=16))
        scene = load_scene(cfg)
        engine = config_engine(cfg, scene, collect_sensors(cfg, scene))
        assert (engine.hero_tables is not None) == spectral, rgb
