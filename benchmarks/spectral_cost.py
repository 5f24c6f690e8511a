"""What spectral tracing costs against one channel: time and variance per sample → time to equal error.

``python benchmarks/spectral_cost.py [--samples N] [--device cpu|cuda] [--wall R,G,B]`` (from a
checkout, or anywhere with probesim installed) reads the
quickstart room (stages/quickstart.usda) with its walls' ``diffuseColor`` set to ``--wall``
(default a green (0.2, 0.7, 0.3), BT.709 grey 0.565) at four workplane points and the east
wall, with method ``path``, twice on the same scene: one channel (the grey reduction) and 4
hero wavelengths (illuminance, PPFD, melanopic EDI per sample). Per response it prints the
time per sample t (CPU time of all threads on ``cpu``, which a loaded machine disturbs less than
wall time; wall time on a GPU; fastest of ``--repeats`` alternating runs) and rays per sample, the
variance per sample v = n·stderr² (relative to the reading²), and the
time to equal standard error, ``(t_s v_s)/(t_1 v_1)``; and the one channel's bias against the
spectral reading (its PPFD and EDI are the post-hoc D65 ratios of its watts).
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:  # run from a checkout: the package sits beside this folder
    sys.path.insert(0, str(ROOT))
POINTS = ((1.0, 1.0, 0.8, 0, 0, 1), (2.5, 2.0, 0.8, 0, 0, 1), (4.0, 3.0, 0.8, 0, 0, 1), (1.5, 3.2, 0.8, 0, 0, 1),
          (4.99, 2.0, 1.5, -1, 0, 0))
NAMES = ("photopic", "par", "melanopic_edi")


def coloured_room(folder: Path, wall) -> Path:
    """stages/quickstart.usda with the Wall material's diffuseColor set to ``wall``."""
    text = (ROOT / "stages" / "quickstart.usda").read_text()
    grey = "color3f inputs:diffuseColor = (0.7, 0.7, 0.7)"
    if text.count(grey) != 1:
        raise RuntimeError("quickstart.usda: the Wall material's diffuseColor changed")
    p = folder / "quickstart_coloured.usda"
    p.write_text(text.replace(grey, "color3f inputs:diffuseColor = ({}, {}, {})".format(*wall)))
    return p


def measure(samples: int, device: str, wall, seed: int = 1, repeats: int = 3) -> dict:
    """Per response: (t per sample s, relative variance per sample) for one channel and hero
    wavelengths, their means over the sensors, and the one channel's mean bias. Each is timed
    ``repeats`` times, alternating, and its fastest time kept."""
    from simulator.engine.driver import Engine
    from simulator.scene.model import Sensor, SensorKind
    from simulator.scene.usd import load_stage
    from simulator.spectra import responses as R
    from simulator.spectra.hero import hero_tables
    from simulator.spectra.posthoc import posthoc_ratio
    from simulator.spectra.sources import cie_illuminant

    with tempfile.TemporaryDirectory() as tmp:
        scene = load_stage(coloured_room(Path(tmp), wall), light_units="photometric")
    sensors = [Sensor(name=f"p{i}", kind=SensorKind.IRRADIANCE, position=np.array(p[:3], float),
                      normal=np.array(p[3:], float)) for i, p in enumerate(POINTS)]
    d65 = cie_illuminant("D65").values
    engines = {}
    for mode in ("one channel", "hero"):
        eng = Engine(scene, sensors, device=device)
        if mode == "hero":
            eng.set_hero_tables(hero_tables(scene, "photometric", "D65", [R.response("par"), R.response("melanopic_edi")]))
        eng.run("path", samples=256, seed=seed + 100)  # compile and warm up
        engines[mode] = eng
    best = {mode: np.inf for mode in engines}
    results = {}
    for _ in range(repeats):  # alternate the two, keep each one's fastest: the machine's load varies
        for mode, eng in engines.items():
            t0 = time.process_time() if device == "cpu" else time.perf_counter()
            results[mode] = eng.run("path", samples=samples, seed=seed)
            t1 = time.process_time() if device == "cpu" else time.perf_counter()
            best[mode] = min(best[mode], (t1 - t0) / (samples * len(sensors)))
    out = {}
    for mode, eng in engines.items():
        res = results[mode]
        eng.run("path", samples=max(256, samples // 8), seed=seed, count_rays=True)
        rays = eng.rays_traced / (max(256, samples // 8) * len(sensors))
        if mode == "hero":
            mean, se = res.response_mean[:, [1, 2, 3]], res.response_stderr[:, [1, 2, 3]]
        else:
            k = np.array([posthoc_ratio(R.response(n), d65) for n in NAMES])
            mean, se = res.mean[:, :1] * k, res.stderr[:, :1] * k
        out[mode] = {"t_s": best[mode], "rays": rays, "mean": mean, "rel_var": samples * (se / mean) ** 2}
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="benchmarks/spectral_cost.py", description=__doc__.splitlines()[0])
    ap.add_argument("--samples", type=int, default=20000)
    ap.add_argument("--device", default="cpu")
    ap.add_argument("--wall", default="0.2,0.7,0.3")
    ap.add_argument("--repeats", type=int, default=3)
    a = ap.parse_args(argv)
    wall = tuple(float(x) for x in a.wall.split(","))
    m = measure(a.samples, a.device, wall, repeats=a.repeats)
    one, hero = m["one channel"], m["hero"]
    print(f"walls {wall}, {a.samples} samples x {len(POINTS)} sensors on {a.device}, fastest of {a.repeats}")
    print(f"time per sample: one channel {one['t_s'] * 1e6:.2f} us, hero {hero['t_s'] * 1e6:.2f} us "
          f"(x{hero['t_s'] / one['t_s']:.2f}); rays per sample {one['rays']:.2f} and {hero['rays']:.2f}")
    for j, name in enumerate(NAMES):
        v1, vs = one["rel_var"][:, j].mean(), hero["rel_var"][:, j].mean()
        bias = (one["mean"][:, j] / hero["mean"][:, j] - 1.0).mean()
        print(f"{name:14s} rel. variance/sample: one {v1:.4f}, hero {vs:.4f} (x{vs / v1:.2f}); "
              f"time to equal error x{hero['t_s'] * vs / (one['t_s'] * v1):.2f}; one channel's bias {bias:+.1%}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
