"""A narrow-field sensor against an ideal cosine one at the same point: samples to ±1 %.

``python benchmarks/narrow_field.py [--samples N] [--method path|guided|mis] [--seed S]`` (from a
checkout, or anywhere with probesim installed) reads, at each point of the bundled quickstart room and
office (stages/quickstart.usda, stages/office.usda) and of the uniform sky (stages/dome.usda), an ideal
cosine sensor, two 10° heads: a half-power angle of 10° (cos^45.3 θ) and a sharp cone (response 1 to
10°, 0 from 10.5°), their directions drawn by their responses (simulator.kernels.optics), and the
engine's radiance meter over the same 10° cone (what a narrow field costs the engine's own estimator:
the cone head should need no more samples than it). For each it
prints the relative variance per sample v = n·stderr²/reading² (seeded and exact to the digits shown:
load-independent) and the samples a 95 % half-width of ±1 % needs, n₁ % = (1.96/0.01)²·v, and the ratio
of a narrow head's to the cosine's. The estimator is the same for all (``--method``; ``path`` by
default, the engine's plain paths: the guide's pilot would otherwise be learnt from the first sensors).

``--decompose`` splits each narrow head's variance per sample, one path a sample (no split), in three.
The head's sample is D + I: D its direct light (its light samples, drawn toward r within its field, and
the emitters its first direction meets, combined by MIS), I the light reflected on the way (read with
``component = "direct"`` and ``"indirect"``, ``--samples`` each). With that direction drawn by r
(p = r/∫r dω) I = ∫r dω · L̂_r(ω), L̂_r the path's estimate of the reflected radiance L_r arriving along
ω, so Var I = (∫r dω)²·(Var_p L_r(ω) + E_p Var(L̂_r | ω)): the first part is all that a better choice of
the head's first direction could remove from I; the second is the paths' own after their first hit,
which a narrow head, its single first hit the whole estimate, pays in full. Var_p L_r is measured by
``--directions`` directions drawn by r on the host and the engine's one-direction radiance meter along
each (``--dir-samples`` samples), less the emitters along each (the same meter over the stage with
black surfaces): their spread less their mean squared standard error. The rest of Var I is the paths'.
Each part is printed over the head's reading squared, so the three add up to one path's relative
variance; ``v_run`` is the head's as run (with the engine's split, K paths a sample).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:  # run from a checkout: the package sits beside this folder
    sys.path.insert(0, str(ROOT))

#: (stage, position, normal): work-plane points, a wall, a ceiling point looking down, the open sky
POINTS = (
    ("quickstart.usda", (2.5, 2.0, 0.8), (0, 0, 1)),
    ("quickstart.usda", (1.0, 1.0, 0.8), (0, 0, 1)),
    ("quickstart.usda", (4.99, 2.0, 1.5), (-1, 0, 0)),
    ("quickstart.usda", (2.5, 2.0, 2.69), (0, 0, -1)),
    ("office.usda", (2.0, 2.5, 0.8), (0, 0, 1)),
    ("office.usda", (4.0, 1.5, 0.8), (0, 0, 1)),
    ("dome.usda", (0.0, 0.0, 0.0), (0, 0, 1)),
)
Z95 = 1.959963984540054


def heads():
    from simulator.sensor_models.angular import half_power, table_from_arrays

    return {"half-power 10°": half_power(10.0),
            "cone 10°": table_from_arrays("cone 10°", [0.0, 10.0, 10.5], [1.0, 1.0, 0.0])}


def measure(samples: int, method: str, seed: int) -> list[dict]:
    """Per point and head: (reading lx, relative variance per sample, samples to ±1 %, rays per sample).
    Each head's sensors run as their own group, as a run's optics twins do (their own split and
    roulette pilots)."""
    from simulator.engine.driver import Engine
    from simulator.scene.model import Sensor, SensorKind
    from simulator.scene.usd import load_stage

    out = []
    names = ["cosine", *heads(), "meter 10°"]
    for stage in dict.fromkeys(p[0] for p in POINTS):
        scene = load_stage(ROOT / "stages" / stage, light_units="photometric")
        pts = [p for p in POINTS if p[0] == stage]
        sensors = []
        for name in names:
            for k, (_, pos, n) in enumerate(pts):
                p, nv = np.array(pos, float), np.array(n, float) / np.linalg.norm(n)
                if name == "meter 10°":  # the engine's radiance meter over the same cone (its mean radiance)
                    sensors.append(Sensor(f"{k}:{name}", SensorKind.RADIANCE, p, nv, half_angle=np.radians(10.0)))
                else:
                    sensors.append(Sensor(f"{k}:{name}", SensorKind.IRRADIANCE, p, nv,
                                          optics=None if name == "cosine" else heads()[name]))
        engine = Engine(scene, sensors)
        results = {}
        for j, name in enumerate(names):
            ids = np.arange(j * len(pts), (j + 1) * len(pts))
            engine.rays_traced = 0
            res = engine.run(method, samples=samples, seed=seed, sensor_ids=ids, count_rays=True)
            rays = engine.rays_traced / max(1, int(res.samples[ids].sum()))
            for k, i in enumerate(ids):
                m, se, cnt = res.mean[i, 1], res.stderr[i, 1], res.samples[i]
                v = cnt * se**2 / m**2 if m > 0 else float("nan")
                results[(k, name)] = (m, v, (Z95 / 0.01) ** 2 * v, rays)
        for k, (_, pos, n) in enumerate(pts):
            out.append({"stage": stage, "position": pos, "normal": n, **{nm: results[(k, nm)] for nm in names}})
    return out


def _directions(resp, n: int, rng) -> np.ndarray:
    """``n`` unit directions about +Z drawn with density r/∫r dω (cosⁿ exactly; a table head by rejection
    from the uniform cone of its last angle)."""
    out = []
    while len(out) < n:
        if resp.kind == "power":
            mu = rng.random(n) ** (1.0 / (resp.exponent + 1.0))
            keep = np.ones(n, bool)
        else:
            top = np.cos(np.radians(resp.theta_deg[-1]))
            mu = 1.0 - rng.random(n) * (1.0 - top)
            keep = rng.random(n) < resp.response(np.degrees(np.arccos(np.clip(mu, -1.0, 1.0)))) / resp.values.max()
        phi = 2 * np.pi * rng.random(n)
        st = np.sqrt(np.maximum(0.0, 1.0 - mu * mu))
        d = np.stack([st * np.cos(phi), st * np.sin(phi), mu], -1)[keep]
        out += list(d)
    return np.array(out[:n])


def decompose(rows: list[dict], method: str, seed: int, samples: int, directions: int, dir_samples: int) -> list[dict]:
    """Per point and narrow head, its one-path variance per sample split in three (module docstring): the
    direct part (the head's own light samples and the emitters its drawn directions meet), the indirect
    part's first direction (Var_p of the reflected radiance L_r(ω) over the field), and the indirect paths'
    own after their first hit. Each is a variance per sample over the head's reading squared (so the three
    add up to the relative variance of one sample without the split)."""
    from dataclasses import replace

    from simulator.engine.driver import Engine
    from simulator.scene.model import Sensor, SensorKind
    from simulator.scene.usd import load_stage

    out = []
    rng = np.random.default_rng(seed)
    for stage in dict.fromkeys(r["stage"] for r in rows):
        scene = load_stage(ROOT / "stages" / stage, light_units="photometric")
        # the same stage with black surfaces: a meter there reads only the emitters along its direction, L_e(ω)
        black = replace(scene, geometry=replace(scene.geometry, albedo=np.zeros_like(scene.geometry.albedo)))
        pts = [r for r in rows if r["stage"] == stage]
        for name, resp in heads().items():
            sensors = [Sensor(f"{k}", SensorKind.IRRADIANCE, np.array(r["position"], float),
                              np.array(r["normal"], float) / np.linalg.norm(r["normal"]), optics=resp)
                       for k, r in enumerate(pts)]
            eng = Engine(scene, sensors)
            parts = {c: eng.run(method, samples=samples, seed=seed, component=c) for c in ("direct", "indirect")}
            for k, r in enumerate(pts):
                n = np.array(r["normal"], float) / np.linalg.norm(r["normal"])
                t = np.cross(n, [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0])
                t /= np.linalg.norm(t)
                frame = np.column_stack([t, np.cross(n, t), n])
                d = _directions(resp, directions, rng) @ frame.T
                meters = [Sensor(f"d{j}", SensorKind.RADIANCE, np.array(r["position"], float), d[j]) for j in range(len(d))]
                tot = Engine(scene, meters).run(method, samples=dir_samples, seed=seed)
                emi = Engine(black, meters).run(method, samples=64, seed=seed)
                lr = tot.mean[:, 1] - emi.mean[:, 1]  # the reflected radiance along each direction, cd/m²
                se2 = tot.stderr[:, 1] ** 2 + emi.stderr[:, 1] ** 2
                kk = resp.integral_sr()
                m = r[name][0]
                var = {c: parts[c].samples[k] * parts[c].stderr[k, 1] ** 2 for c in parts}
                first = kk * kk * max(0.0, float(np.var(lr, ddof=1) - np.mean(se2)))
                first_se = kk * kk * float(np.std((lr - lr.mean()) ** 2, ddof=1)) / np.sqrt(len(lr))
                out.append({"stage": stage, "position": r["position"], "head": name, "reading": m,
                            "direct": parts["direct"].mean[k, 1], "indirect": parts["indirect"].mean[k, 1],
                            "indirect_dirs": kk * float(lr.mean()),
                            "v_direct": var["direct"] / m**2, "v_first": first / m**2, "v_first_se": first_se / m**2,
                            "v_paths": max(0.0, var["indirect"] - first) / m**2, "v_indirect": var["indirect"] / m**2,
                            "v_run": r[name][1]})
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--samples", type=int, default=1 << 15)
    ap.add_argument("--method", default="path", choices=("path", "guided", "mis", "light"))
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--decompose", action="store_true", help="also split each narrow head's variance (module docstring)")
    ap.add_argument("--directions", type=int, default=256)
    ap.add_argument("--dir-samples", type=int, default=1024)
    args = ap.parse_args(argv)
    rows = measure(args.samples, args.method, args.seed)
    names = ["cosine", *heads(), "meter 10°"]
    print(f"method {args.method}, {args.samples} samples per sensor, seed {args.seed}; v: relative variance per sample; "
          "n: samples to a 95% half-width of ±1%; rays: per sample (each head's group its own split pilot)")
    print(f"{'stage':<16} {'point':<18} {'normal':<12} " + " ".join(f"{n:>39}" for n in names)
          + "   samples, rays to ±1% (each head / cosine)")
    worst = 0.0
    for r in rows:
        cells, ratios = [], []
        for n in names:
            m, v, need, rays = r[n]
            unit = "cd/m²" if n == "meter 10°" else "lx"
            cells.append(f"{m:>9.4g} {unit:<5} v {v:>6.3f} n {need:>7.0f} rays {rays:>5.2f}")
            if n not in ("cosine", "meter 10°"):
                c = r["cosine"]
                if c[1] > 1e-9:  # the cosine's reading has a variance: a ratio means something
                    ratios.append((need / c[2], need * rays / (c[2] * c[3])))
                    worst = max(worst, need / c[2])
                else:
                    ratios.append((float("nan"), float("nan")))
        print(f"{r['stage']:<16} {str(r['position']):<18} {str(r['normal']):<12} " + " ".join(f"{c:>39}" for c in cells)
              + "   " + ", ".join(f"{a:.2f}, {b:.2f}" for a, b in ratios))
    print(f"largest samples ratio: {worst:.2f}")
    if args.decompose:
        print(f"\none path's relative variance per sample (no split), in three: direct (the head's light samples and "
              f"the emitters its directions meet; {args.samples} samples), the indirect part's first direction "
              f"(Var_p L_r over {args.directions} directions drawn by r, {args.dir_samples} samples each) and its "
              "paths after the first hit; v_run: the head's as run (the split's K paths a sample)")
        for d in decompose(rows, args.method, args.seed, args.samples, args.directions, args.dir_samples):
            print(f"{d['stage']:<16} {str(d['position']):<18} {d['head']:<15} reading {d['reading']:>9.4g} lx = direct "
                  f"{d['direct']:>9.4g} + indirect {d['indirect']:>9.4g} (from the directions {d['indirect_dirs']:>9.4g}); "
                  f"v direct {d['v_direct']:>7.3f}  first direction {d['v_first']:>7.3f} ± {d['v_first_se']:.3f}  "
                  f"paths {d['v_paths']:>7.3f}  (indirect {d['v_indirect']:>7.3f}; v_run {d['v_run']:>7.3f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
