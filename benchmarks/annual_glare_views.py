"""The imageless annual glare against the glare view's full trace of the same hours.

    python benchmarks/annual_glare_views.py [STUDY.toml] [--per-kind 2] [--seed 7] [--out DIR] [--traced]

Runs (or resumes, in ``--out``) the annual study (default
``configs/studies/office_annual_shading.toml``), picks occupied hours of
four kinds per glare view: overcast (no direct sun), sunny with the sun out
of the view's sight, sunny with the sun in sight, and hours the shading rule
closed the shades (``--per-kind`` of each, spread over the year), and traces
each view on each such hour as an ordinary glare view (its patch sky as a
textured dome, the sun a 0.533° disk, a diffusing shade's cells at their
luminance of the hour; :func:`simulator.study.annual.glare.full_view`), to
DGP ± 0.005. Prints per hour the annual E_v and DGP against the full
view's, the full view's sources, and per kind the largest difference. The
figures the docs quote (docs/studies.md, "Annual glare") are its output.

``--traced``: the same study with ``sun_indirect = "traced"`` (a group
``sun`` holding ``--sun-light``, the stage's DistantLight, added), so the
eyes' interreflected sun comes from the traced sun bins.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def pick_hours(res, view: int, per_kind: int) -> list[tuple[str, int]]:
    """``(kind, hour)`` pairs: the kinds of the module docstring, ``per_kind`` each, spread over the year."""
    import numpy as np

    k = res.state if res.state is not None else np.zeros(len(res.rows), np.int64)
    years = res.detail["years"]
    seen = np.array([years[int(k[h])].suns[view].luminance[h] > 0 for h in range(len(res.rows))])
    occ = res.occupied & (res.skies.dhi_lx > 1000.0)
    sunny = res.skies.dni_lx > 10000.0
    kinds = {
        "overcast": occ & (res.skies.dni_lx == 0) & (k == 0),
        "sun out of sight": occ & sunny & ~seen & (k == 0),
        "sun in sight": occ & sunny & seen,
        "shades closed": occ & sunny & (k > 0),
    }
    out = []
    for name, m in kinds.items():
        ids = np.nonzero(m)[0]
        if len(ids):
            take = ids[np.linspace(0, len(ids) - 1, min(per_kind, len(ids))).round().astype(int)]
            out += [(name, int(h)) for h in sorted(set(take.tolist()))]
    return out


def traced_copy(path: Path, sun_light: str, folder: Path) -> Path:
    """A copy of the study file in ``folder`` with ``sun_indirect = "traced"`` and a ``sun`` group, its paths absolute."""
    import re

    text = path.read_text()
    text = re.sub(r'^(stage|weather) = "(?!/)([^"]+)"', lambda m: f'{m.group(1)} = "{(path.parent / m.group(2)).resolve().as_posix()}"',
                  text, flags=re.M)  # fmt: skip
    text = text.replace("[annual]\n", '[annual]\nsun_indirect = "traced"\nsun_group = "sun"\n', 1)
    text = text.replace("[[zone]]\n", f'[[group]]\nname = "sun"\nlights = ["{sun_light}"]\n\n[[zone]]\n', 1)
    out = folder / f"{path.stem}_traced.toml"
    out.write_text(text)
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("study", nargs="?", default=str(ROOT / "configs" / "studies" / "office_annual_shading.toml"))
    ap.add_argument("--per-kind", type=int, default=2)
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--out", default=None, help="the study's output folder (resumed); default: a folder under the system's temp")
    ap.add_argument("--traced", action="store_true", help="sun_indirect = \"traced\"")
    ap.add_argument("--sun-light", default="/Office/Sun", help="--traced: the stage's DistantLight")
    a = ap.parse_args(argv)
    import tempfile

    from simulator.study.annual.glare import full_view
    from simulator.study.annual.year import run_annual
    from simulator.study.schema import load_study

    path = Path(a.study).resolve()
    if a.traced:
        path = traced_copy(path, a.sun_light, Path(tempfile.mkdtemp(prefix="probesim-traced-")))
    study, p = load_study(path)
    out = Path(a.out) if a.out else Path(tempfile.gettempdir()) / f"probesim-{p.stem}{'-traced' if a.traced else ''}-glare-check"
    t0 = time.process_time()
    res = run_annual(study, p, out, log=lambda m: print(m, file=sys.stderr))
    g = res.glare
    if g is None:
        print("the study's stage has no glare views")
        return 1
    print(f"{p.name}: annual {time.process_time() - t0:.1f} s CPU; load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores")
    print(f"{'view':8} {'hour centre':25} {'state':6} {'kind':17} {'E_v annual':>10} {'E_v view':>14} {'ratio':>6} "
          f"{'DGP annual':>10} {'DGP view':>14} {'diff':>7} sources")  # fmt: skip
    worst: dict = {}
    for v, name in enumerate(g.views):
        for kind, h in pick_hours(res, v, a.per_kind):
            r = full_view(res, study, h, v, a.seed + h)
            e = r.estimate
            st = res.states[int(res.state[h])] if res.state is not None else "-"
            diff = g.index[h, v] - e.dgp
            srcs = ", ".join(("sun" if s.sun else f"{s.luminance_cd_m2:,.0f} cd/m² × {s.omega_sr:.3f} sr") for s in e.sources)
            print(f"{name:8} {str(res.weather.centre[res.rows[h]]):25} {st:6} {kind:17} {g.ev[h, v]:10.0f} "
                  f"{e.ev_lx:8.0f} ± {e.ev_stderr_lx:3.0f} {g.ev[h, v] / e.ev_lx:6.3f} {g.index[h, v]:10.3f} "
                  f"{e.dgp:7.3f} ± {e.dgp_stderr:.3f} {diff:+7.3f} {srcs}")  # fmt: skip
            w = worst.setdefault(kind, [0.0, 0.0])
            w[0] = max(w[0], abs(diff))
            w[1] = max(w[1], abs(g.ev[h, v] / e.ev_lx - 1.0))
    for kind, (dd, de) in worst.items():
        print(f"largest |DGP difference| {dd:.3f}, |E_v ratio − 1| {de:.3f}: {kind}")
    print(f"CPU {time.process_time() - t0:.1f} s in all")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
