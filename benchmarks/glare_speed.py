"""A glare view's cost on the bundled office: CPU time to a DGP standard error of 0.005.

    python benchmarks/glare_speed.py [--target 0.005] [--repeat 3] [--resolution 128]
    python benchmarks/glare_speed.py --bias [--seeds 12]

Runs three views of stages/office.usda (toward the window with the sun out
of sight and the lamps on; toward the window from the desk by it, the sun
in sight; toward the corridor wall, lamps and reflections only) each as one
``kind = "glare"`` sensor of a run config, ``dgp_stderr = --target``, after
one warm-up run (kernels loaded, stage read), and prints per view the
passes drawn, the samples, DGP and its standard error, and the CPU time
(user + system, this process and its threads) and wall time of the run,
the median of ``--repeat`` runs, with the load average beside them: the
machine may be shared, and CPU time is the figure to compare.

``--bias``: what the sources found at few passes do to the figures. Each
view read at 4 passes (the first batch) with ``--seeds`` seeds, against one
read at 64 passes: the mean difference of DGP and UGR with its standard
error (the spread over the seeds / √seeds). The unbiased L²ω removes the
pixel noise's own bias; this measures what is left, the choice of pixels.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

VIEWS = {
    "window": ((4.5, 2.0, 1.2), (-1.0, 0.0, 0.0)),
    "desk_by_window": ((1.6, 1.5, 1.2), (-1.0, 0.0, 0.0)),
    "corridor_wall": ((3.0, 2.0, 1.2), (1.0, 0.0, 0.0)),
}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--target", type=float, default=0.005)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--resolution", type=int, default=128)
    ap.add_argument("--bias", action="store_true")
    ap.add_argument("--seeds", type=int, default=12)
    a = ap.parse_args(argv)
    import simulator

    if a.bias:
        return bias(a)

    stage = (ROOT / "stages" / "office.usda").resolve()
    with tempfile.TemporaryDirectory() as tmp:
        print(f"glare views of the office, half map {a.resolution} x {a.resolution}, DGP to ± {a.target:g}; "
              f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores")  # fmt: skip
        for name, (eye, d) in VIEWS.items():
            cfg_path = Path(tmp) / f"{name}.toml"
            cfg_path.write_text(f'stage = "{stage}"\n[[sensor]]\nname = "{name}"\nkind = "glare"\n'
                                f'position = [{", ".join(map(str, eye))}]\ndirection = [{", ".join(map(str, d))}]\n'
                                f"resolution = [{a.resolution}, {a.resolution}]\ndgp_stderr = {a.target}\n")  # fmt: skip
            cfg = simulator.load_config(cfg_path)
            simulator.run(cfg, log=lambda m: None, write=False)  # warm: kernels loaded, stage read
            cpu, wall = [], []
            for _ in range(a.repeat):
                c0, w0 = time.process_time(), time.perf_counter()
                out = simulator.run(cfg, log=lambda m: None, write=False)
                cpu.append(time.process_time() - c0)
                wall.append(time.perf_counter() - w0)
            v = out.rows[0].values
            print(f"  {name:<15} {out.rows[0].samples:>8,} samples, DGP {v['dgp']:.3f} ± {v['dgp_stderr']:.4f}, "
                  f"UGR {v.get('ugr', float('nan')):.1f}: CPU {statistics.median(cpu):.2f} s, wall {statistics.median(wall):.2f} s "
                  f"(load {os.getloadavg()[0]:.2f})")  # fmt: skip
    return 0


def bias(a) -> int:
    """``--bias`` (module docstring)."""
    import numpy as np

    from simulator.engine.driver import Engine
    from simulator.engine.glare import run_glare
    from simulator.glare.sources import GlareSettings
    from simulator.scene.model import Sensor, SensorKind
    from simulator.scene.usd import load_stage

    scene = load_stage(ROOT / "stages" / "office.usda", light_units="photometric", radiometric_spectrum="E")
    print(f"glare views of the office, half map {a.resolution} x {a.resolution}: 4 passes x {a.seeds} seeds against 64 passes")
    for name, (eye, d) in VIEWS.items():
        d = np.asarray(d, float)
        view = Sensor(name, SensorKind.GLARE, np.asarray(eye, float), d / np.linalg.norm(d), up=np.array([0.0, 0.0, 1.0]),
                      resolution=(a.resolution, a.resolution), glare=GlareSettings(dgp_stderr=1e-9))  # fmt: skip

        def read(seed, passes):
            (r,) = run_glare(scene, [view], "path", lambda sc, ss: Engine(sc, ss), seed=seed, max_passes=passes)
            return r.estimate

        ref = read(1000, 64)
        few = [read(s, 4) for s in range(a.seeds)]
        for what in ("dgp", "ugr"):
            x = np.array([getattr(e, what) for e in few]) - getattr(ref, what)
            se = np.array([getattr(e, what + "_stderr") for e in few])
            print(f"  {name:<15} {what}: 64 passes {getattr(ref, what):.4f} ± {getattr(ref, what + '_stderr'):.4f}; "
                  f"4 passes − that: {x.mean():+.4f} ± {x.std(ddof=1) / np.sqrt(len(x)):.4f} (reported ± {np.sqrt(np.mean(se**2)):.4f})")  # fmt: skip
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
