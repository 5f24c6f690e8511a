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
renders, compared with z = Δ/√(σ_p² + σ_m²)). ``--split`` instead reads
the window view under one light group alone (``--split sky``, ``sun`` or ``lamps``) in two parts:
the direct light (Mitsuba's path tracer at depth 2, probesim's ``exact``) and the
rest (Mitsuba's full depth less its direct part; probesim's ``indirect``
component), each Mitsuba figure the mean of 6 renders of 2²⁰ samples with its
standard error. ``--sun-check`` reads the converted sun on the outdoor ground against its
closed form, at three distances of its disc and five sample counts in one render. Needs the optional extra ``peer`` and Dr.Jit's libLLVM (see
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


ALONE = """#usda 1.0
(
    subLayers = [@{office}@]
    defaultPrim = "Office"
    metersPerUnit = 1
    upAxis = "Z"
)
over "Office"
{{
{off}
}}
"""
#: the office's light prims each split keeps (the others are deactivated)
SPLITS = {"sky": ("Sky", "WindowPortal"), "sun": ("Sun",), "lamps": ("Lights",)}


def light_split(tmp: Path, alone: str) -> None:
    """The window view under one light group alone (``SPLITS``): direct and interreflected light from each
    renderer."""
    import mitsuba as mi
    import numpy as np
    import peer_mitsuba as P

    import glare_radiance as G
    from simulator.config import load_config
    from simulator.engine.driver import Engine
    from simulator.pipeline import collect_sensors, load_scene

    mi.set_variant("llvm_ad_mono")
    eye, d, _ = G.VIEWS["window"]
    stage = tmp / f"{alone}_only.usda"
    off = "\n".join(f'    over "{p}" (active = false) {{}}' for k, keep in SPLITS.items() if k != alone for p in keep
                    if p not in SPLITS[alone])  # fmt: skip
    stage.write_text(ALONE.format(office=(ROOT / "stages" / "office.usda").as_posix(), off=off))
    cfg = tmp / f"{alone}.toml"
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
    # the sky's direct light computed (exact); the sun's and the lamps' sampled with their standard error
    ex = eng.run("exact", samples=16, seed=3) if alone == "sky" else eng.run("path", samples=1 << 18, seed=3, component="direct")
    ind = eng.run("path", samples=1 << 21, seed=3, component="indirect")
    print(f"window view, {alone} alone: direct Mitsuba {md:.1f} ± {md_se:.1f} lx, probesim {ex.mean[0, 1]:.2f} ± "
          f"{ex.stderr[0, 1]:.2f} lx; "
          f"interreflected Mitsuba {mt - md:.1f} ± {np.hypot(mt_se, md_se):.1f} lx, probesim "
          f"{ind.mean[0, 1]:.1f} ± {ind.stderr[0, 1]:.1f} lx")  # fmt: skip


def sun_check(tmp: Path) -> None:
    """The sun alone on the office's outdoor ground, 15 m out from the wall (irradiance sensor facing up, 1 mm
    above it), Mitsuba at depth 2 against the closed form E⊥·sin(elevation) = 80,000 lx · sin 30° = 40,000 lx:
    at each distance of the sun's disc (the conversion's parallax) and at each sample count in one render
    (the film's float32 sums)."""
    import mitsuba as mi
    import peer_mitsuba as P

    from simulator.config import load_config
    from simulator.pipeline import collect_sensors, load_scene

    mi.set_variant("llvm_ad_mono")
    stage = tmp / "sun_only.usda"
    off = "\n".join(f'    over "{p}" (active = false) {{}}' for k, keep in SPLITS.items() if k != "sun" for p in keep)
    stage.write_text(ALONE.format(office=(ROOT / "stages" / "office.usda").as_posix(), off=off))
    cfg = tmp / "ground.toml"
    cfg.write_text(f'stage = "{stage.as_posix()}"\n[[sensor]]\nname = "ground"\nkind = "irradiance"\n'
                   'position = [-15.0, 2.0, 0.001]\nnormal = [0.0, 0.0, 1.0]\n')  # fmt: skip
    c = load_config(cfg)
    scene = load_scene(c)
    sensors = collect_sensors(c, scene)
    full, far0, pass0 = P.mitsuba_scene, P.SUN_DISTANCE_M, P.MAX_PASS_SPP
    P.mitsuba_scene = lambda *a, **k: {**full(*a, **k), "integrator": {"type": "path", "max_depth": 2}}
    try:
        for far in (1.0e3, 1.0e5, 1.0e6):
            P.SUN_DISTANCE_M = far
            v = P.run_mitsuba(scene, sensors, 1 << 16, 0.005, 600)[0][0]
            print(f"sun disc {far / 1000:,.0f} km off, 2^16 samples: {v:,.1f} lx, {v / 40000.0 - 1:+.3%} against 40,000 lx")
        P.SUN_DISTANCE_M, P.MAX_PASS_SPP = far0, 1 << 30
        for e in (14, 16, 18, 20, 22):
            v = P.run_mitsuba(scene, sensors, 1 << e, 0.005, 600)[0][0]
            print(f"one render of 2^{e} samples: {v:,.1f} lx, {v / 40000.0 - 1:+.3%}")
    finally:
        P.mitsuba_scene, P.SUN_DISTANCE_M, P.MAX_PASS_SPP = full, far0, pass0


def main() -> int:
    import glare_radiance as G

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--replicas", type=int, default=8)
    ap.add_argument("--views", default="window,luminaires,sun")
    ap.add_argument("--probesim-samples", type=int, nargs=2, default=[65536, 262144])
    ap.add_argument("--mitsuba-spp", type=int, nargs=2, default=[262144, 1048576])
    ap.add_argument("--split", choices=sorted(SPLITS), help="the window view under this light group alone, in two parts")
    ap.add_argument("--sun-check", action="store_true", help="the conversion's sun on the outdoor ground against its closed form")
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        if a.sun_check:
            sun_check(tmp)
            return 0
        if a.split:
            light_split(tmp, a.split)
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
