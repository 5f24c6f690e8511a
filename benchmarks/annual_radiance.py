"""Cross-check of probesim's annual daylight against Radiance's daylight-coefficient method (two-phase).

    python benchmarks/annual_radiance.py [configs/studies/office_annual.toml] [--ab 5] [--ad 4096]
        [--weather FILE.epw|FILE.csv] [--radiance-reads-epw]

Needs ``pyradiance`` (``pip install pyradiance``: its wheel ships the Radiance
binaries); it is an optional extra, not a test dependency.

What it does
------------
1. probesim: ``run_annual`` of the study (its ``[annual]`` table, its work-plane candidates).
2. Radiance: the same stage exported as polygons with grey ``plastic``
   materials of each triangle's reflectance; the same work-plane points; the
   weather file written as a ``.wea`` in photometric units (direct-normal and
   diffuse-horizontal illuminance, hour centres in local standard time, the
   same sun times as probesim); ``gendaymtx -m 1`` (Tregenza/Reinhart MF:1
   patches, ground reflectance as ``[annual] ground_reflectance``) and
   ``rcontrib -f reinhartb.cal`` daylight coefficients; the annual matrix
   product in numpy. Radiance's radiometric outputs are in its 179 lm/W
   units: illuminance = 179·(0.265 R + 0.670 G + 0.065 B).
3. For ASE, Radiance's direct sun alone: ``gendaymtx -d`` (the sun only) with
   coefficients of the same points in the stage made black (``-ab 1``: the
   patches seen directly, nothing reflected).
4. ``--weather`` runs both on another climate file (EPW or TMY3) in place of
   the study's ``[annual] weather``. With an EPW, ``--radiance-reads-epw``
   hands the EPW itself to gendaymtx instead of the ``.wea``: Radiance then
   places each record in time by its own reader (``loadEPW``: an hourly
   record at hour − 0.5) and derives the illuminances from the irradiances
   with the Perez (1990) efficacies, so probesim's year is run with
   ``illuminance = "efficacy"`` to match: an independent check of how the
   EPW's hours are read (gendaymtx averages the dew point over 3 hours,
   probesim takes each hour's, a small difference in the efficacies).
5. Prints the hourly RMS difference (lux, and relative to probesim's mean
   over occupied hours), the mean difference, and each zone's sDA and ASE
   from both.

Differences to expect: gendaymtx spreads the sun over the 4 patches nearest
it for all of its light (direct included), where probesim's direct sun is
exact per hour; Radiance's ambient cache and -ab limit bias its
interreflections; both use the Perez all-weather sky normalised to the
file's diffuse illuminance.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def _radiance():
    try:
        import pyradiance
    except ImportError:
        sys.exit("annual_radiance: needs pyradiance (pip install pyradiance), which ships the Radiance binaries")
    binpath = Path(pyradiance.__file__).parent / "bin"
    libpath = Path(pyradiance.__file__).parent / "lib"
    env = {**os.environ, "PATH": f"{binpath}{os.pathsep}{os.environ.get('PATH', '')}", "RAYPATH": f".{os.pathsep}{libpath}"}
    return env


def export_rad(scene, path: Path, black: bool = False) -> None:
    """Every triangle as a Radiance polygon, one grey plastic material per reflectance (all 0 with ``black``)."""
    g = scene.geometry
    pts = np.asarray(g.points, np.float64)
    lines = []
    mats = {}
    for t, tri in enumerate(np.asarray(g.triangles)):
        rho = 0.0 if black else round(float(g.albedo[t]), 6)
        if rho not in mats:
            mats[rho] = f"grey{len(mats)}"
            lines.append(f"void plastic {mats[rho]}\n0\n0\n5 {rho} {rho} {rho} 0 0\n")
        v = pts[tri]
        lines.append(f"{mats[rho]} polygon t{t}\n0\n0\n9 " + " ".join(f"{x:.9g}" for x in v.ravel()) + "\n")
    path.write_text("".join(lines))


def write_wea(weather, path: Path) -> None:
    """A .wea in photometric units (3): month day hour(centre) DN-illum DH-illum; Radiance's longitude is west-positive."""
    w = weather
    head = (f"place {w.site.replace(' ', '_') or 'site'}\nlatitude {w.latitude_deg:.4f}\nlongitude {-w.longitude_deg:.4f}\n"
            f"time_zone {-w.tz_h * 15.0:.1f}\nsite_elevation {w.altitude_m:.1f}\nweather_data_file_units 3\n")  # fmt: skip
    rows = []
    for k in range(len(w)):
        c = w.centre[k]
        rows.append(f"{c.month} {c.day} {c.hour + c.minute / 60.0:.3f} {w.dni_lx[k]:.0f} {w.dhi_lx[k]:.0f}")
    path.write_text(head + "\n".join(rows) + "\n")


def _matrix(text: bytes, ncols_rgb: int) -> np.ndarray:
    """An ASCII Radiance matrix without header → (rows, ncols_rgb, 3)."""
    v = np.array(text.split(), np.float64)
    return v.reshape(-1, ncols_rgb, 3)


def _lux(rgb: np.ndarray) -> np.ndarray:
    return 179.0 * (0.265 * rgb[..., 0] + 0.670 * rgb[..., 1] + 0.065 * rgb[..., 2])


def with_weather(study, path: Path, weather: str | None, radiance_reads_epw: bool = False):
    """The study with ``weather`` (made absolute) as its ``[annual] weather``, and the EPW gendaymtx should read
    itself (None: the ``.wea`` written from probesim's reading). ``radiance_reads_epw`` needs an EPW and sets
    the study's ``illuminance`` to ``"efficacy"`` (gendaymtx derives illuminances from an EPW's irradiances)."""
    upd = {}
    if weather is not None:
        upd["weather"] = str(Path(weather).resolve())
    native = None
    if radiance_reads_epw:
        w = Path(upd.get("weather", study.annual.weather))
        w = w if w.is_absolute() else (Path(path).parent / w).resolve()
        if w.suffix.lower() != ".epw":
            sys.exit(f"annual_radiance: --radiance-reads-epw needs an EPW weather file, not {w}")
        native, upd["illuminance"] = w, "efficacy"
    if upd:
        study = study.model_copy(update={"annual": study.annual.model_copy(update=upd)})
    return study, native


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("study", nargs="?", default=str(ROOT / "configs" / "studies" / "office_annual.toml"))
    ap.add_argument("--ab", type=int, default=5)
    ap.add_argument("--ad", type=int, default=4096)
    ap.add_argument("--lw", type=float, default=1e-4)
    ap.add_argument("--procs", type=int, default=2)
    ap.add_argument("--weather", help="an EPW (.epw) or TMY3 (.csv) file in place of the study's [annual] weather")
    ap.add_argument("--radiance-reads-epw", action="store_true",
                    help="gendaymtx reads the EPW itself (its own hour placement and efficacies; probesim uses illuminance = \"efficacy\")")
    a = ap.parse_args(argv)
    env = _radiance()

    from simulator.scene.usd import load_stage
    from simulator.study.annual.year import run_annual
    from simulator.study.inputs.candidates import build_candidates
    from simulator.study.runner import zone_members
    from simulator.study.annual.metrics import zone_metrics
    from simulator.study.schema import load_study

    study, p = load_study(a.study)
    study, native_epw = with_weather(study, p, a.weather, a.radiance_reads_epw)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        t0 = time.process_time()
        res = run_annual(study, p, tmp / "probesim", log=lambda m: None)
        print(f"probesim: {len(res.rows)} hours, CPU {time.process_time() - t0:.1f} s")
        scene = load_stage((p.parent / study.stage).resolve(), light_units="photometric", radiometric_spectrum="E")
        sets = build_candidates(scene, study.candidates, str(p))
        cands = [c for s in sets for c in s.candidates]
        zones = zone_members(study, sets, cands, str(p))
        wp = sorted({int(i) for ids in zones.values() for i in ids})
        export_rad(scene, tmp / "scene.rad")
        (tmp / "sky.rad").write_text("void glow groundglow\n0\n0\n4 1 1 1 0\ngroundglow source ground\n0\n0\n4 0 0 -1 180\n"
                                     "void glow skyglow\n0\n0\n4 1 1 1 0\nskyglow source skydome\n0\n0\n4 0 0 1 180\n")  # fmt: skip
        # (a source's angle is its diameter: 180 is a hemisphere)
        export_rad(scene, tmp / "black.rad", black=True)
        for rad, octree in (("scene.rad", "scene.oct"), ("black.rad", "black.oct")):
            with open(tmp / octree, "wb") as fh:
                subprocess.run(["oconv", "sky.rad", rad], cwd=tmp, env=env, check=True, stdout=fh)
        pts = "".join(f"{c.sensor.position[0]:.6f} {c.sensor.position[1]:.6f} {c.sensor.position[2]:.6f} "
                      f"{c.sensor.normal[0]:.6f} {c.sensor.normal[1]:.6f} {c.sensor.normal[2]:.6f}\n" for c in (cands[i] for i in wp))  # fmt: skip
        tape = "year.wea" if native_epw is None else "year.epw"
        if native_epw is None:
            write_wea(res.weather, tmp / tape)
        else:  # Radiance's own reading of the EPW's hours
            (tmp / tape).write_bytes(native_epw.read_bytes())
            print(f"gendaymtx reads {native_epw.name} itself; probesim's year uses illuminance = \"efficacy\"")
        rho = study.annual.ground_reflectance
        t1 = time.perf_counter()
        sky = subprocess.run(["gendaymtx", "-h", "-m", "1", "-g", str(rho), str(rho), str(rho), "-c", "1", "1", "1", tape],
                             cwd=tmp, env=env, check=True, capture_output=True).stdout  # fmt: skip
        sun = subprocess.run(["gendaymtx", "-h", "-m", "1", "-d", tape], cwd=tmp, env=env, check=True, capture_output=True).stdout
        skyonly = subprocess.run(["gendaymtx", "-h", "-m", "1", "-s", "-g", str(rho), str(rho), str(rho), "-c", "1", "1", "1", tape],
                                 cwd=tmp, env=env, check=True, capture_output=True).stdout  # fmt: skip
        n_h = len(res.weather)
        skym = np.array(sky.split(), np.float64).reshape(146, n_h, 3)
        sunm = np.array(sun.split(), np.float64).reshape(146, n_h, 3)
        skyom = np.array(skyonly.split(), np.float64).reshape(146, n_h, 3)
        # columns as gendaymtx's rows: the ground (the lower hemisphere, one bin), then 145 sky patches
        rc = ["rcontrib", "-h", "-I+", "-n", str(a.procs), "-lw", str(a.lw), "-f", "reinhartb.cal",  # MF = 1 there: Tregenza
              "-b", "0", "-bn", "1", "-m", "groundglow", "-b", "rbin", "-bn", "Nrbins", "-m", "skyglow"]  # fmt: skip
        dc = subprocess.run(rc + ["-ab", str(a.ab), "-ad", str(a.ad), "scene.oct"], cwd=tmp, env=env, check=True, input=pts.encode(),
                            capture_output=True).stdout  # fmt: skip
        # direct sky (and sun) alone: one ambient bounce in a black scene sees the patches and nothing reflected
        dd = subprocess.run(rc + ["-ab", "1", "-ad", str(a.ad), "black.oct"], cwd=tmp, env=env, check=True, input=pts.encode(), capture_output=True).stdout
        print(f"Radiance: gendaymtx and rcontrib -ab {a.ab} -ad {a.ad}, {time.perf_counter() - t1:.1f} s wall")
        dcm, ddm = _matrix(dc, 146), _matrix(dd, 146)  # (S, 146, 3)
        e_rad = _lux(np.einsum("spc,phc->hsc", dcm, skym))  # (H, S)
        e_sun = _lux(np.einsum("spc,phc->hsc", ddm, sunm))
        e_sky = _lux(np.einsum("spc,phc->hsc", dcm, skyom))
    rows = res.rows
    col = {i: k for k, i in enumerate(wp)}
    rad = e_rad[rows][:, [col[i] for i in wp]]
    rad_sun = e_sun[rows][:, [col[i] for i in wp]]
    ps = res.mean[:, wp]
    occ = res.occupied
    diff = (rad - ps)[occ]
    print(f"occupied hours {int(occ.sum())}, {len(wp)} work-plane sensors")
    print(f"hourly RMS difference (Radiance − probesim) {np.sqrt(np.mean(diff**2)):.1f} lx, mean {np.mean(diff):+.1f} lx; "
          f"probesim mean {np.mean(ps[occ]):.1f} lx (RMS {np.sqrt(np.mean(diff**2)) / np.mean(ps[occ]):.1%} of it); "
          f"median |relative difference| {np.median(np.abs(diff) / np.maximum(ps[occ], 1.0)):.1%}")  # fmt: skip
    co = res.coefficients
    ps_sky = (res.sky_levels @ (co.dir + co.ind).T)[:, wp]
    dsky = (e_sky[rows][:, [col[i] for i in wp]] - ps_sky)[occ]
    print(f"sky alone (no sun): RMS difference {np.sqrt(np.mean(dsky**2)):.1f} lx, mean {np.mean(dsky):+.1f} lx; probesim mean "
          f"{np.mean(ps_sky[occ]):.1f} lx; median |relative difference| {np.median(np.abs(dsky) / np.maximum(ps_sky[occ], 1.0)):.1%}")  # fmt: skip
    for z, ids in zones.items():
        k = [wp.index(int(i)) for i in ids]
        mr = zone_metrics(rad[:, k], rad_sun[:, k], occ, res.daylight, np.zeros(len(k)), study.annual, float(study.annual.step_h))
        mp = res.metrics[z]
        print(f"  {z}: sDA Radiance {mr['sDA']:.1f}% vs probesim {mp['sDA'][0]:.1f} ± {mp['sDA'][1]:.1f}% (Δ {mr['sDA'] - mp['sDA'][0]:+.1f}); "
              f"ASE Radiance {mr['ASE']:.1f}% vs probesim {mp['ASE'][0]:.1f}% (Δ {mr['ASE'] - mp['ASE'][0]:+.1f}); "
              f"DA300 {mr['DA']:.1f}% vs {mp['DA'][0]:.1f}%")  # fmt: skip
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
