"""E_v at the glare views' eyes against Mitsuba 3: is probesim's vertical illuminance unbiased?

    python benchmarks/glare_ev_mitsuba.py [--replicas 8] [--views window,luminaires,sun]

Radiance's ``rtrace -I`` reads E_v 1.5–3.9% below probesim at the office's
glare views where interreflection matters (``benchmarks/glare_radiance.py``,
docs/comparisons.md). A third renderer settles which side is off: for each
view of ``glare_radiance.VIEWS`` (its eye, its direction, its lighting: the
office as authored, or the layer over it with the lamps alone) this writes a
config of one irradiance sensor at the eye facing the view direction (E_v is
that sensor's reading) and runs ``benchmarks/peer_mitsuba.py`` on it in its
replica mode (each renderer's pooled mean over ``--replicas`` independent
renders, compared with z = Δ/√(σ_p² + σ_m²)). ``--sky-split`` instead reads
the window view under the sky alone (sun and lamps off) in two parts: the
direct light (Mitsuba's path tracer at depth 2, probesim's ``exact``) and the
rest (Mitsuba's full depth less its direct part; probesim's ``indirect``
component), each Mitsuba figure the mean of 6 renders of 2²⁰ samples with its
standard error. Needs the optional extra ``peer`` and Dr.Jit's libLLVM (see
peer_mitsuba.py).
"""

from __future__ import annotations

import argparse
import math
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))


SKY_ONLY = """#usda 1.0
(
    subLayers = [@{office}@]
    defaultPrim = "Office"
    metersPerUnit = 1
    upAxis = "Z"
)
over "Office"
{{
    over "Sun" (active = false) {{}}
    over "Lights" (active = false) {{}}
}}
"""


def sky_split(tmp: Path) -> None:
    """The window view under the sky alone: direct and interreflected light from each renderer."""
    import mitsuba as mi
    import numpy as np
    import peer_mitsuba as P

    import glare_radiance as G
    from simulator.config import load_config
    from simulator.engine.driver import Engine
    from simulator.pipeline import collect_sensors, load_scene

    mi.set_variant("llvm_ad_mono")
    eye, d, _ = G.VIEWS["window"]
    stage = tmp / "sky_only.usda"
    stage.write_text(SKY_ONLY.format(office=(ROOT / "stages" / "office.usda").as_posix()))
    cfg = tmp / "sky.toml"
    cfg.write_text(f'stage = "{stage.as_posix()}"\n[[sensor]]\nname = "eye"\nkind = "irradiance"\n'
                   f'position = {list(eye)}\nnormal = {list(d)}\n')  # fmt: skip
    c = load_config(cfg)
    scene = load_scene(c)
    sensors = collect_sensors(c, scene)
    full = P.mitsuba_scene

    def mitsuba(depth: int) -> tuple[float, float]:
        P.mitsuba_scene = lambda *a, **k: {**full(*a, **k), "integrator": {"type": "path", "max_depth": depth}}
        try:
            v = [float(P.run_mitsuba(scene, sensors, 1 << 20, 0.005, 200 + s)[0][0]) for s in range(6)]
        finally:
            P.mitsuba_scene = full
        return float(np.mean(v)), float(np.std(v, ddof=1) / np.sqrt(len(v)))

    (md, md_se), (mt, mt_se) = mitsuba(2), mitsuba(-1)
    eng = Engine(scene, sensors)
    ex = eng.run("exact", samples=16, seed=3)
    ind = eng.run("path", samples=1 << 18, seed=3, component="indirect")
    print(f"window view, sky alone: direct Mitsuba {md:.1f} ± {md_se:.1f} lx, probesim exact {ex.mean[0, 1]:.2f} lx; "
          f"interreflected Mitsuba {mt - md:.1f} ± {np.hypot(mt_se, md_se):.1f} lx, probesim "
          f"{ind.mean[0, 1]:.1f} ± {ind.stderr[0, 1]:.1f} lx")  # fmt: skip


def main() -> int:
    import glare_radiance as G

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--replicas", type=int, default=8)
    ap.add_argument("--views", default="window,luminaires,sun")
    ap.add_argument("--probesim-samples", type=int, nargs=2, default=[65536, 262144])
    ap.add_argument("--mitsuba-spp", type=int, nargs=2, default=[262144, 1048576])
    ap.add_argument("--sky-split", action="store_true", help="the window view under the sky alone, in two parts")
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        if a.sky_split:
            sky_split(tmp)
            return 0
        for name in a.views.split(","):
            eye, d, lighting = G.VIEWS[name]
            if lighting.startswith("CIE"):
                print(f"{name}: skipped (a textured sky; the Mitsuba conversion reads uniform domes only)")
                continue
            stage = ROOT / "stages" / "office.usda"
            if lighting.startswith("lamps"):
                stage = tmp / f"{name}.usda"
                G.wrapper_stage(stage, lighting)
            n = math.sqrt(sum(x * x for x in d))
            cfg = tmp / f"{name}.toml"
            cfg.write_text(f'stage = "{stage.as_posix()}"\n[simulation]\nsamples = 1024\nseed = 1\n[[sensor]]\n'
                           f'name = "{name}_eye"\nkind = "irradiance"\nposition = {list(eye)}\n'
                           f'normal = {[x / n for x in d]}\n')  # fmt: skip
            print(f"== {name}: {lighting}", flush=True)
            subprocess.run([sys.executable, str(ROOT / "benchmarks" / "peer_mitsuba.py"), str(cfg), "--replicas",
                            str(a.replicas), "--probesim-samples", *map(str, a.probesim_samples), "--mitsuba-spp",
                            *map(str, a.mitsuba_spp), "--rms", "0.01"], check=True)  # fmt: skip
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
