"""probesim and Mitsuba 3 side by side on the same stage, to the same RMS error.

Converts a probesim run config's scene to Mitsuba 3 (triangles with their
Lambertian albedo, both faces reflecting; RectLights as area-emitting
rectangles; a uniform DomeLight as a constant emitter; a DistantLight as a
directional emitter of its normal illuminance, or with an angle as an emitting
disc 1,000 km off that subtends it; emissive triangles as area emitters) and each irradiance sensor to a small white Lambertian disk proxy
(radius ``--proxy-m``, :data:`PROXY_M`) seen by a ``radiancemeter`` 1 mm above it (E = π·L),
all meters in one ``batch`` sensor, so one render reads every sensor. Both are read at a ladder of
budgets against the config's stored reference (configs/references/NAME.csv,
in lx); the RMS relative error has the reference's own variance subtracted,
as ``probesim bench`` does. Prints the wall time each takes to reach each
``--rms`` target (interpolated on the 1/√t line between the two budgets
that bracket it), with the machine and its load.

Needs the optional extra ``peer`` (``pip install mitsuba``; its LLVM
backend, variant ``llvm_ad_mono``, needs a libLLVM recent enough for Dr.Jit:
LLVM 14 and 15 fail to select ``fmaximum``, 19 works; point Dr.Jit at it
with ``DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1``).

    PYTHONPATH=. python benchmarks/peer_mitsuba.py configs/office_bench.toml --rms 0.01 0.003

``--stage`` reads the config's sensors on another stage (e.g.
stages/office_emissive.usda: the office with its window and luminaires as
emissive geometry, which Mitsuba samples as area emitters, where the dome of
office.usda is a constant emitter it samples over the whole sphere). With
``--replicas R`` no stored reference is needed: each renderer draws R
independent renders at each budget; one render's error per sensor is the
spread of the R (its variance s², relative to the pooled mean), the time to a
target follows from the largest budget by the 1/√t law of an unbiased estimator, t·(rms/target)²,
and the two renderers' pooled means at the largest budgets are compared sensor by sensor
(z = Δ/√(σ_p² + σ_m²)), so a bias in either would show:

    PYTHONPATH=. python benchmarks/peer_mitsuba.py --stage stages/office_emissive.usda --replicas 4 --rms 0.01 0.003
"""

from __future__ import annotations

import argparse
import csv
import os
import platform
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def _write_ply(path: Path, points: np.ndarray, tris: np.ndarray) -> None:
    """A binary little-endian PLY of one triangle mesh."""
    head = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(points)}\nproperty float x\n"
            f"property float y\nproperty float z\nelement face {len(tris)}\n"
            "property list uchar int vertex_indices\nend_header\n")  # fmt: skip
    faces = np.zeros(len(tris), dtype=[("n", "u1"), ("v", "<i4", 3)])
    faces["n"], faces["v"] = 3, tris
    with open(path, "wb") as f:
        f.write(head.encode())
        f.write(points.astype("<f4").tobytes())
        f.write(faces.tobytes())


def mitsuba_scene(scene, sensors, spp: int, proxy_m: float, tmp: Path, bsdf_of=None):
    """The Mitsuba scene dict (photometric channel: radiance in cd/m², readings in lx).

    ``bsdf_of(surface, albedo)``, given a face group's ``Surface`` row (None
    for a matte face) and its albedo (diffuseColor's grey), returns the Mitsuba BSDF dict to use for it, or None for
    the Lambertian conversion; radiance sensors become bare radiance meters
    along their direction (cd/m²)."""
    import mitsuba as mi

    from simulator.scene.model import SensorKind

    T = mi.ScalarTransform4f
    g = scene.geometry
    d = {"type": "scene", "integrator": {"type": "path", "max_depth": -1}}
    emits = np.any(g.emission > 0, axis=1)
    sid = g.surface_id if g.surface_id is not None else np.full(g.n_triangles, -1)
    keys = np.round(g.albedo, 6) + 10.0 * emits + 100.0 * (sid + 1)  # one mesh per albedo, emitter, surface row
    for k, key in enumerate(np.unique(keys)):
        sel = np.flatnonzero(keys == key)
        used, inv = np.unique(g.triangles[sel].ravel(), return_inverse=True)
        ply = tmp / f"mesh_{k}.ply"
        _write_ply(ply, g.points[used], inv.reshape(-1, 3))
        row = g.surfaces[sid[sel[0]]] if sid[sel[0]] >= 0 else None
        bsdf = bsdf_of(row, float(g.albedo[sel[0]])) if bsdf_of else None
        shape = {"type": "ply", "filename": str(ply), "face_normals": True,
                 "bsdf": bsdf or {"type": "twosided", "bsdf": {"type": "diffuse", "reflectance": {"type": "spectrum", "value": float(g.albedo[sel[0]])}}}}  # fmt: skip
        if emits[sel[0]]:
            shape["emitter"] = {"type": "area", "radiance": {"type": "spectrum", "value": float(g.emission[sel[0], 1])}}
        d[f"mesh_{k}"] = shape
    for j, l in enumerate(scene.lights):
        kind = int(l.kind)
        if kind == 2:  # rect: emits toward its −Z; Mitsuba's rectangle emits toward +Z over [-1, 1]²
            m = np.eye(4)
            m[:3, 0], m[:3, 1], m[:3, 2] = l.frame[:, 0] * l.width / 2, -l.frame[:, 1] * l.height / 2, -l.frame[:, 2]
            m[:3, 3] = l.position
            # a null BSDF: paths pass through it as through a RectLight, which is not geometry
            # (shadow rays still stop on it: Mitsuba's path integrator tests every shape)
            d[f"light_{j}"] = {"type": "rectangle", "to_world": T(m.tolist()), "bsdf": {"type": "null"},
                               "emitter": {"type": "area", "radiance": {"type": "spectrum", "value": float(l.emission[1])}}}  # fmt: skip
        elif kind == 5 and not l.texture:  # uniform dome
            d[f"light_{j}"] = {"type": "constant", "radiance": {"type": "spectrum", "value": float(l.emission[1])}}
        elif kind == 4 and l.half_angle <= 0:  # delta distant: its normal illuminance, toward −ez
            d[f"light_{j}"] = {"type": "directional", "direction": (-l.frame[:, 2]).tolist(),
                               "irradiance": {"type": "spectrum", "value": float(l.emission[1])}}  # fmt: skip
        elif kind == 4:  # a sun's disc: an emitting disk 1,000 km off toward +ez subtending its angle (its penumbrae)
            far = SUN_DISTANCE_M
            centre = g.points.mean(axis=0) + far * l.frame[:, 2]
            disc = T().look_at(origin=centre.tolist(), target=(centre - l.frame[:, 2]).tolist(),
                               up=[0, 0, 1] if abs(l.frame[2, 2]) < 0.9 else [0, 1, 0]) @ T().scale(float(far * np.tan(l.half_angle)))
            d[f"light_{j}"] = {"type": "disk", "to_world": disc, "bsdf": {"type": "null"},
                               "emitter": {"type": "area", "radiance": {"type": "spectrum", "value": float(l.emission[1])}}}  # fmt: skip
        else:
            raise SystemExit(f"{l.name}: light kind {l.kind.name} is not converted")
    # each sensor: a white Lambertian proxy disk (reflectance 1) facing along its normal and a
    # radiance meter 1 mm above its centre looking at it: L = E/π, E the irradiance there with every
    # light by next-event estimation (an irradiance meter's own rays can never meet a delta sun)
    meters = {"type": "batch", "film": {"type": "hdrfilm", "width": len(sensors), "height": 1,
                                        "pixel_format": "luminance", "rfilter": {"type": "box"}},
              "sampler": {"type": "independent", "sample_count": spp}}  # fmt: skip
    for i, s in enumerate(sensors):
        if s.kind == SensorKind.RADIANCE:
            meters[f"meter_{i:05d}"] = {
                "type": "radiancemeter", "origin": s.position.tolist(), "direction": s.normal.tolist(),
                "film": {"type": "hdrfilm", "width": 1, "height": 1, "pixel_format": "luminance", "rfilter": {"type": "box"}},
            }  # fmt: skip
            continue
        up = [0, 0, 1] if abs(s.normal[2]) < 0.9 else [0, 1, 0]
        to_world = T().look_at(origin=s.position.tolist(), target=(s.position + s.normal).tolist(), up=up) @ T().scale(float(proxy_m))
        d[f"proxy_{i:05d}"] = {"type": "disk", "to_world": to_world,
                               "bsdf": {"type": "diffuse", "reflectance": {"type": "spectrum", "value": 1.0}}}  # fmt: skip
        meters[f"meter_{i:05d}"] = {
            "type": "radiancemeter", "origin": (s.position + 1e-3 * s.normal).tolist(), "direction": (-s.normal).tolist(),
            "film": {"type": "hdrfilm", "width": 1, "height": 1, "pixel_format": "luminance", "rfilter": {"type": "box"}},
        }  # fmt: skip
    d["meters"] = meters
    return d


#: how far off the sun's disc stands: far enough that its parallax is negligible (a point d m from the scene's
#: centre sees the disc d/far rad off the sun's direction; the office's outdoor ground under its 40,000 lx
#: sun, Mitsuba at depth 2 against that closed form: +4.4% at 1 km, +0.04% at 100 km, −0.009% at 1,000 km,
#: ``benchmarks/glare_ev_mitsuba.py --sun-check``)
SUN_DISTANCE_M = 1.0e6

#: most samples per pixel in one Mitsuba render: its film sums a pixel's samples in float32, which read a
#: 40,000 lx sun on the ground −0.009% off at 2^14 and 2^16 samples, +0.05% at 2^18, −0.10% at 2^20 and
#: −2.0% at 2^22 (``glare_ev_mitsuba.py --sun-check``); larger budgets are rendered in passes of at most
#: this many, averaged in float64
MAX_PASS_SPP = 1 << 16


#: the proxy disks' radius (m). Every sensor's disk is in the one scene, and each reflects all the light it
#: meets back into the room, so the disks add light: 1,464 disks of 5 mm (0.115 m² of white) read the
#: office's work plane 0.10–0.12% high (pooled means' mean z −0.17 to −0.25), 0.5 mm disks 0.00–0.04%
#: (−0.01 to −0.08; docs/comparisons.md). The meter's one ray meets the disk's centre whatever its size.
PROXY_M = 5e-4


def run_mitsuba(scene, sensors, spp: int, proxy_m: float, seed: int, bsdf_of=None) -> tuple[np.ndarray, float]:
    """(readings in lx, cd/m² for radiance sensors; wall seconds of the renders) at ``spp`` samples per sensor
    (``spp`` a multiple of :data:`MAX_PASS_SPP` above it)."""
    import mitsuba as mi

    from simulator.scene.model import SensorKind

    passes = -(-spp // MAX_PASS_SPP)
    with tempfile.TemporaryDirectory() as tmp:
        ms = mi.load_dict(mitsuba_scene(scene, sensors, spp // passes, proxy_m, Path(tmp), bsdf_of))
        t0 = time.perf_counter()
        img = np.zeros(len(sensors))
        for k in range(passes):  # every meter in each pass; the passes averaged in float64
            img += np.asarray(mi.render(ms, spp=spp // passes, seed=seed * 65536 + k), dtype=np.float64).reshape(-1)[: len(sensors)]
        img /= passes
        wall = time.perf_counter() - t0
    scale = np.array([1.0 if s.kind == SensorKind.RADIANCE else np.pi for s in sensors])  # E = π·L off the proxy
    return scale * img, wall


def run_probesim(cfg, scene, sensors, samples: int, seed: int, engine, plan=None) -> tuple[np.ndarray, float]:
    """(readings in lx, wall seconds) of the config's plan at ``samples`` per sensor, warm (kernels
    loaded, guide and pilots kept), its computed direct light computed afresh each time (as a fresh
    process computes it: the exact factors kept by the process are dropped first)."""
    from dataclasses import replace

    from simulator.engine import exact_memo
    from simulator.pipeline import run_plan
    from simulator.plan.planner import make_plan

    sim = replace(cfg.simulation, samples=samples, seed=seed, rel_error=None)
    plan = plan or make_plan(scene, sensors, sim.method, sim.component)
    exact_memo.clear()
    t0 = time.perf_counter()
    res = run_plan(engine, plan, sim)
    return res.mean[:, 1], time.perf_counter() - t0


def rms(values: np.ndarray, ref: np.ndarray, ref_se: np.ndarray) -> float:
    """Relative RMS error over the sensors, the reference's own variance subtracted."""
    r2 = np.mean(((values - ref) / ref) ** 2) - np.mean((ref_se / ref) ** 2)
    return float(np.sqrt(max(r2, 0.0)))


def time_to(points: list[tuple[float, float]], target: float) -> tuple[float, bool]:
    """Seconds to reach ``target`` RMS from (seconds, rms) budgets, and whether a budget reached
    it: on the line (log-log) through the first budget at or under it and the one before; if none
    did, extrapolated from the last budget on the 1/√t line of an unbiased estimator."""
    for k, (t, e) in enumerate(points):
        if e <= target:
            if k == 0:
                return t * (e / target) ** 2, True
            t0, e0 = points[k - 1]
            slope = np.log(e / e0) / np.log(t / t0) if t > t0 and e0 > 0 and e > 0 else -0.5
            return (float(t0 * (target / e0) ** (1.0 / slope)) if slope < 0 else t), True
    t, e = points[-1]
    return t * (e / target) ** 2, False


def replica_errors(runs: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray, float]:
    """(pooled mean, its standard error, one render's relative RMS error) from R independent renders
    (R, S): s² the unbiased spread per sensor, one render's relative error √mean_s(s²/mean²)."""
    x = np.asarray(runs)
    mean = x.mean(axis=0)
    var = x.var(axis=0, ddof=1)
    ok = mean > 0
    return mean, np.sqrt(var / len(x)), float(np.sqrt(np.mean(var[ok] / mean[ok] ** 2)))


def replica_comparison(a, cfg, scene, sensors) -> None:
    """Both renderers at each budget, R seeds each, their renders alternating (one probesim render,
    one Mitsuba render, ...) so that both meet the same load: time to each target from one render's
    spread, warm and whole process (each renderer's start-up added: probesim's stage reading, plan,
    engine, kernel load from the cache, pilots and guide; Mitsuba's scene load and kernel compile)."""
    if a.replicas < 2:
        raise SystemExit("--replicas: at least 2 independent renders are needed for a spread")
    from simulator.engine.driver import load_kernels
    from simulator.pipeline import config_engine, load_scene
    from simulator.plan.planner import make_plan

    print(f"{platform.processor() or platform.machine()}, {os.cpu_count()} CPUs, load {os.getloadavg()[0]:.2f} at start; "
          f"{len(sensors)} sensors, {scene.geometry.n_triangles} triangles on {Path(cfg.stage).name}; "
          f"{a.replicas} renders per budget, no reference")  # fmt: skip
    # probesim's start-up, as a run has it (its kernels already compiled, cached by Warp)
    t0 = time.perf_counter()
    scene_p = load_scene(cfg)
    plan = make_plan(scene_p, sensors, cfg.simulation.method, cfg.simulation.component)
    load_kernels(cfg.simulation.device)
    engine = config_engine(cfg, scene_p, sensors)
    run_probesim(cfg, scene_p, sensors, 8, 7, engine, plan)  # pilots and guide, once per engine
    setup_p = time.perf_counter() - t0
    print(f"probesim start-up (stage, plan, kernels from the cache, pilots, guide): {setup_p:.2f} s; plan "
          + ", ".join(f"{m} {len(ix)}" for m, ix in plan.groups().items()))
    t0 = time.perf_counter()
    run_mitsuba(scene, sensors, 4, a.proxy_m, 1)
    setup_m = time.perf_counter() - t0
    print(f"mitsuba start-up (scene, kernel compile at 4 spp): {setup_m:.2f} s")
    rows, pooled = {"probesim": [], "mitsuba": []}, {}
    for n, spp in zip(a.probesim_samples, a.mitsuba_spp):
        runs = {"probesim": [], "mitsuba": []}
        walls = {"probesim": [], "mitsuba": []}
        for r in range(a.replicas):
            v, t = run_probesim(cfg, scene_p, sensors, n, 101 + r, engine, plan)
            runs["probesim"].append(v)
            walls["probesim"].append(t)
            v, t = run_mitsuba(scene, sensors, spp, a.proxy_m, 101 + r)
            runs["mitsuba"].append(v)
            walls["mitsuba"].append(t)
        for who, k in (("probesim", n), ("mitsuba", spp)):
            mean, se, one = replica_errors(runs[who])
            t = float(np.median(walls[who]))
            rows[who].append((t, one))
            pooled[who] = (mean, se)
            print(f"{who:8s} {k:6d} per sensor: {t:8.2f} s a render, one render's RMS {one:.3%}; load "
                  f"{os.getloadavg()[0]:.2f}", flush=True)
    (mp, sp), (mm, sm) = pooled["probesim"], pooled["mitsuba"]
    z = (mp - mm) / np.sqrt(sp**2 + sm**2)
    print(f"pooled means at the top budgets: Mitsuba/probesim - 1 = {np.mean(mm) / np.mean(mp) - 1:+.3%} (mean over "
          f"sensors), RMS z {np.sqrt(np.mean(z**2)):.2f}, |z| > 4 at {int(np.sum(np.abs(z) > 4))} of {len(z)} sensors")
    if a.z_csv:  # every sensor's pooled means, their errors and z, to find where the two part
        with open(a.z_csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["sensor", "x", "y", "z", "probesim_lx", "probesim_stderr_lx", "mitsuba_lx", "mitsuba_stderr_lx", "z_score"])
            for s, a_p, e_p, a_m, e_m, zs in zip(sensors, mp, sp, mm, sm, z):
                w.writerow([s.name, *(f"{c:.4f}" for c in s.position), f"{a_p:.6g}", f"{e_p:.4g}", f"{a_m:.6g}", f"{e_m:.4g}", f"{zs:.3f}"])
    for target in a.rms:
        (t_p, e_p), (t_m, e_m) = rows["probesim"][-1], rows["mitsuba"][-1]  # the largest budgets
        tp, tm = t_p * (e_p / target) ** 2, t_m * (e_m / target) ** 2
        print(f"to {target:.2%} RMS: warm probesim {tp:.1f} s, mitsuba {tm:.1f} s ({tp / tm:.2f}x); whole process "
              f"probesim {tp + setup_p:.1f} s, mitsuba {tm + setup_m:.1f} s ({(tp + setup_p) / (tm + setup_m):.2f}x); "
              f"load {os.getloadavg()[0]:.2f} at end")  # fmt: skip


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("config", nargs="?", default=str(ROOT / "configs" / "office_bench.toml"))
    ap.add_argument("--rms", type=float, nargs="+", default=[0.01])
    ap.add_argument("--probesim-samples", type=int, nargs="+", default=[256, 1024, 4096])
    ap.add_argument("--mitsuba-spp", type=int, nargs="+", default=[1024, 4096, 16384])
    ap.add_argument("--proxy-m", type=float, default=PROXY_M)
    ap.add_argument("--stage", help="read the config's sensors on this stage instead of its own")
    ap.add_argument("--z-csv", metavar="PATH", help="with --replicas: write every sensor's pooled means, errors and z here")
    ap.add_argument("--replicas", type=int, default=0,
                    help="R >= 2: errors from R independent renders per budget, no stored reference")
    a = ap.parse_args()

    import mitsuba as mi

    from simulator.config import load_config
    from simulator.engine.driver import Engine, load_kernels
    from simulator.pipeline import load_scene

    mi.set_variant("llvm_ad_mono")
    cfg = load_config(a.config)
    if a.stage:
        from dataclasses import replace

        cfg = replace(cfg, stage=Path(a.stage).resolve())
    scene = load_scene(cfg)
    from simulator.pipeline import collect_sensors

    sensors = [x for x in collect_sensors(cfg, scene) if x.kind.name != "PROBE"]
    if a.replicas:
        return replica_comparison(a, cfg, scene, sensors)
    ref_rows = {r["sensor"]: r for r in csv.DictReader((ROOT / "configs" / "references" / f"{Path(a.config).stem}.csv").open())}
    ref = np.array([float(ref_rows[s.name]["illuminance_lx"]) for s in sensors])
    ref_se = np.array([float(ref_rows[s.name]["illuminance_stderr_lx"]) for s in sensors])
    print(f"{platform.processor() or platform.machine()}, {os.cpu_count()} CPUs, load {os.getloadavg()[0]:.2f} at start; "
          f"{len(sensors)} sensors, {scene.geometry.n_triangles} triangles; reference RMS stderr "
          f"{np.sqrt(np.mean((ref_se / ref) ** 2)):.2%}")  # fmt: skip
    load_kernels(cfg.simulation.device)
    engine = Engine(scene, sensors, device=cfg.simulation.device)
    run_probesim(cfg, scene, sensors, 8, 7, engine)  # pilots and guide, once per engine (kept out of the times)
    rows = {"probesim": [], "mitsuba": []}
    for n in a.probesim_samples:
        v, t = run_probesim(cfg, scene, sensors, n, 11, engine)
        rows["probesim"].append((t, rms(v, ref, ref_se)))
        print(f"probesim {n:6d} samples/sensor: {t:8.2f} s  RMS {rows['probesim'][-1][1]:.3%}", flush=True)
    run_mitsuba(scene, sensors[:2], 4, a.proxy_m, 1)  # compile the kernels once (kept out of the times)
    for spp in a.mitsuba_spp:
        v, t = run_mitsuba(scene, sensors, spp, a.proxy_m, 11)
        rows["mitsuba"].append((t, rms(v, ref, ref_se)))
        print(f"mitsuba  {spp:6d} spp:            {t:8.2f} s  RMS {rows['mitsuba'][-1][1]:.3%}", flush=True)
    for target in a.rms:
        (tp, rp), (tm, rm) = time_to(rows["probesim"], target), time_to(rows["mitsuba"], target)
        print(f"to {target:.2%} RMS: probesim {tp:.1f} s{'' if rp else ' (extrapolated)'}, mitsuba {tm:.1f} s"
              f"{'' if rm else ' (extrapolated)'}, probesim/mitsuba {tp / tm:.2f}x; load {os.getloadavg()[0]:.2f} at end")  # fmt: skip


if __name__ == "__main__":
    main()
