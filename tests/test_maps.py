"""Grid maps (EXR + PNG) and probe maps (EXR + JSON) written beside the CSV.

The end-to-end run uses stages/point.usda: a point light of I = 100 cd at
(0, 0, 3) m, so every grid cell facing up reads E = I·h/d³ exactly (zero
variance, float32 precision), and a probe reads scalar irradiance I/d².
"""

from __future__ import annotations

import csv
import json
import math
import textwrap
from pathlib import Path

import numpy as np
import OpenEXR
import pytest

from simulator.reference import closed_forms as cf
from simulator.config.loader import GridConfig, load_config
from simulator.io.maps import GRID_CHANNELS, PROBE_CHANNELS, grid_arrays, output_names, sanitise_name
from simulator.pipeline import run

ROOT = Path(__file__).resolve().parents[1]
SEED = 7


def _config(tmp_path: Path) -> Path:
    cfg = tmp_path / "maps.toml"
    cfg.write_text(textwrap.dedent(f'''\
        stage = "{(ROOT / 'stages' / 'point.usda').as_posix()}"
        [simulation]
        samples = 2048
        seed = {SEED}
        method = "light"
        [[sensor]]
        name = "centre probe"
        kind = "probe"
        position = [0.5, 0.25, 1.0]
        resolution = [16, 8]
        [[grid]]
        name = "floor"
        position = [0.2, -0.1, 0]
        normal = [0, 0, 1]
        size = [3, 2]
        up = [0, 1, 0]
        spacing = 0.5
        [output]
        csv = "out/maps.csv"
        '''))  # fmt: skip
    return cfg


def _header(path: Path) -> dict:
    return dict(OpenEXR.File(str(path), header_only=True).header())


def _channels(path: Path) -> dict[str, np.ndarray]:
    f = OpenEXR.File(str(path), separate_channels=True)
    return {k: np.asarray(v.pixels) for k, v in f.channels().items()}


@pytest.fixture(scope="module")
def outputs(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("maps")
    cfg = load_config(_config(tmp))
    out = run(cfg, log=lambda m: None)
    return cfg, out, tmp / "out"


def test_files_beside_the_csv(outputs):
    """A run with one grid and one probe writes the CSV, the run record, the
    grid's EXR and PNG, the probe's EXR (name sanitised: "centre probe" →
    centre_probe) and the probes JSON, and leaves no temporary files."""
    _, out, folder = outputs
    names = sorted(p.name for p in folder.iterdir())
    assert names == sorted([
        "maps.csv", "maps.run.json", "maps.floor.exr", "maps.floor.png", "maps.centre_probe.exr", "maps.probes.json",
    ])  # fmt: skip
    assert out.record["probe_maps"] == {"centre probe": "maps.centre_probe.exr"}


def test_grid_exr_channels_metadata_and_layout(outputs):
    """The grid EXR has channels E_W_m2, E_stderr_W_m2, Ev_lx, Ev_stderr_lx
    (ny rows × nx columns), metadata naming units, grid, seed and axes, and
    pixel (row r, column i) holds cell (i, ny − 1 − r): its illuminance is
    the point-light closed form I·cosξ/d² to float32 precision with zero
    standard error."""
    cfg, out, folder = outputs
    (grid,) = cfg.grids
    path = folder / "maps.floor.exr"
    hdr = _header(path)
    ch = _channels(path)
    assert set(ch) == set(GRID_CHANNELS)
    assert all(a.shape == (grid.ny, grid.nx) and a.dtype == np.float32 for a in ch.values())
    assert hdr["probesim:kind"] == "grid" and hdr["probesim:grid"] == "floor"
    assert hdr["probesim:seed"] == str(SEED)
    for c, unit in GRID_CHANNELS.items():
        assert f"{c}: {unit}" in hdr["probesim:units"]
    assert np.allclose([float(x) for x in hdr["probesim:centre_m"].split()], grid.centre)
    for key, vec in (("right", grid.right), ("up", grid.up), ("normal", grid.normal)):
        assert np.allclose([float(x) for x in hdr[f"probesim:{key}"].split()], vec)
    rows = {r.sensor.name: r.values for r in out.rows}
    for r in range(grid.ny):
        for i in range(grid.nx):
            j = grid.ny - 1 - r
            v = rows[grid.cell_name(i, j)]
            assert ch["Ev_lx"][r, i] == np.float32(v["illuminance_lx"])
            assert ch["E_W_m2"][r, i] == np.float32(v["irradiance_W_m2"])
            truth = cf.point_irradiance(100.0, [0, 0, 3], grid.cell_centre(i, j), [0, 0, 1])
            assert abs(ch["Ev_lx"][r, i] - truth) <= 2e-6 * truth
            assert ch["Ev_stderr_lx"][r, i] == 0.0


def test_grid_png_and_its_statistics(outputs):
    """The PNG is an image; the statistics it shows (also in the EXR header)
    are the grid's min, mean and max illuminance and uniformity min/mean."""
    import matplotlib.image

    _, out, folder = outputs
    png = folder / "maps.floor.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    img = matplotlib.image.imread(png)
    assert img.ndim == 3 and img.shape[0] > 100 and img.shape[1] > 100
    lx = np.array([r.values["illuminance_lx"] for r in out.rows if r.sensor.grid == "floor"])
    hdr = _header(folder / "maps.floor.exr")
    lo, mean, hi = map(float, hdr["probesim:illuminance_min_mean_max_lx"].split())
    assert np.allclose([lo, mean, hi], [lx.min(), lx.mean(), lx.max()], rtol=1e-8)
    assert math.isclose(float(hdr["probesim:uniformity"]), lx.min() / lx.mean(), rel_tol=1e-8)


def test_probe_exr_json_and_csv_row(outputs):
    """The probe EXR is a lat-long map (OpenEXR envmap attribute) with
    channels R, G, B (= luminance in cd/m², the stage being photometric),
    L_W_m2_sr, Lv_cd_m2 and their standard errors, and metadata naming
    units, sensor and seed. The point light is a delta light: the map is
    black, and the probe's CSV row and JSON say scalar irradiance I/d²
    exactly, mean direction toward the light; other kinds' columns are
    empty in its row."""
    _, out, folder = outputs
    path = folder / "maps.centre_probe.exr"
    hdr = _header(path)
    ch = _channels(path)
    assert set(ch) == {"R", "G", "B", *PROBE_CHANNELS}
    assert all(a.shape == (8, 16) for a in ch.values())
    assert "LATLONG" in str(hdr["envmap"]).upper()
    assert hdr["probesim:sensor"] == "centre probe" and hdr["probesim:seed"] == str(SEED)
    assert "cd/m2" in hdr["probesim:units"] and "L_W_m2_sr: W/m2/sr" in hdr["probesim:units"]
    assert np.array_equal(ch["R"], ch["Lv_cd_m2"]) and np.all(ch["R"] == 0.0)
    assert "point or angle-0" in hdr["probesim:delta_lights"]

    d = np.array([0, 0, 3.0]) - np.array([0.5, 0.25, 1.0])
    e = 100.0 / float(d @ d)
    with open(folder / "maps.csv", newline="") as f:
        row = next(r for r in csv.DictReader(f) if r["kind"] == "probe")
    assert row["sensor"] == "centre probe"
    assert abs(float(row["scalar_illuminance_lx"]) - e) <= 2e-6 * e and float(row["scalar_illuminance_stderr_lx"]) == 0.0
    m = np.array([float(row[f"mean_direction_{a}"]) for a in "xyz"])
    assert np.allclose(m, d / np.linalg.norm(d), atol=1e-6)
    for col in ("irradiance_W_m2", "illuminance_lx", "radiance_W_m2_sr", "flux_W", "dx"):
        assert row.get(col, "") == ""  # another kind's column: empty where the run has that kind, else absent
    doc = json.loads((folder / "maps.probes.json").read_text())
    (p,) = doc["probes"]
    assert doc["seed"] == SEED and p["map_file"] == "maps.centre_probe.exr"
    assert p["scalar_irradiance"]["lx"] == pytest.approx(float(row["scalar_illuminance_lx"]), rel=1e-8)
    assert set(p["faces"]) == {"+X", "-X", "+Y", "-Y", "+Z", "-Z"}
    w = d / np.linalg.norm(d)
    for k, (face, ax) in enumerate(zip(("+X", "-X", "+Y", "-Y", "+Z", "-Z"), np.vstack([np.eye(3), -np.eye(3)])[[0, 3, 1, 4, 2, 5]])):
        assert p["faces"][face]["lx"] == pytest.approx(e * max(0.0, float(ax @ w)), rel=2e-6, abs=1e-9)
    assert len(p["spherical_harmonics"]["lx"]) == 9 and p["spherical_harmonics"]["order"][0] == "0,0"
    assert p["delta_lights"]["scalar_irradiance"]["lx"] == pytest.approx(e, rel=2e-6)


def test_outputs_are_written_together_or_not_at_all(tmp_path, monkeypatch):
    """If writing a map fails, the run leaves nothing behind: no CSV, no run
    record, no other map, no temporary file."""
    import simulator.io.exr

    def broken(*args, **kwargs):
        raise OSError("disk full")

    monkeypatch.setattr(simulator.io.exr, "write_channels", broken)
    cfg = load_config(_config(tmp_path))
    with pytest.raises(OSError, match="disk full"):
        run(cfg, log=lambda m: None)
    assert not (tmp_path / "out").exists() or list((tmp_path / "out").iterdir()) == []


def test_names_are_sanitised_and_unique():
    """Sensor and grid names become safe file stems; names that sanitise
    alike, or would clash with the CSV's own side files, get _2, _3, …"""
    assert sanitise_name("/World/Probe A") == "World_Probe_A"
    assert sanitise_name("..") == "sensor"
    assert sanitise_name("a-b.c_d") == "a-b.c_d"
    stems = output_names(Path("out/run.csv"), ["a b", "a_b", "run", "probes", "x"])
    assert stems == {"a b": "run.a_b", "a_b": "run.a_b_2", "run": "run.run_2", "probes": "run.probes_2", "x": "run.x"}


def test_grid_image_orientation():
    """Row 0 of a grid image is the cell row farthest along ``up`` and column
    i is cell i along ``right``: the grid as seen from the side it faces."""
    g = GridConfig(name="g", source="grid[0]", nx=3, ny=2, centre=np.zeros(3), normal=np.array([0, 0, 1.0]),
                   right=np.array([1.0, 0, 0]), up=np.array([0, 1.0, 0]), size=(3.0, 2.0), spacing=(1.0, 1.0))  # fmt: skip
    keys = ("irradiance_W_m2", "irradiance_stderr_W_m2", "illuminance_lx", "illuminance_stderr_lx")
    values = {g.cell_name(i, j): {k: 10 * i + j for k in keys} for i in range(3) for j in range(2)}
    img = grid_arrays(g, values)["Ev_lx"]
    assert img.tolist() == [[1, 11, 21], [0, 10, 20]]
