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
renders, compared with z = Δ/√(σ_p² + σ_m²)). Needs the optional extra
``peer`` and Dr.Jit's libLLVM (see peer_mitsuba.py).
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


def main() -> int:
    import glare_radiance as G

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--replicas", type=int, default=8)
    ap.add_argument("--views", default="window,luminaires,sun")
    ap.add_argument("--probesim-samples", type=int, nargs=2, default=[65536, 262144])
    ap.add_argument("--mitsuba-spp", type=int, nargs=2, default=[262144, 1048576])
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
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
