"""A lamp-only scenario in a shared trace against a plain run of its lamps, at equal samples.

``python benchmarks/lamp_scenario.py [--samples N] [--seeds K] [--spacing M] [--level L]``

The office (``stages/office.usda``) with the groups of ``configs/studies/office_study.toml``:
window row, corridor row, the sky and the sun in one pass (``trace_groups``), serving the
scenarios ``lamps`` (both rows at ``--level``, 1.7 by default, sky and sun at 0), ``overcast``
(sky 1, corridor 0.5) and ``afternoon`` (sky 0.6, sun 1, corridor 0.5). Each scenario is also
run plainly: a stage holding only its lit lights, their emission scaled by their level,
read as ``probesim run`` reads it (``run_plan``, the engine's defaults: method ``auto``,
indirect split ``auto``). Work-plane sensors at 0.8 m on a ``--spacing`` grid.

Per scenario it prints the median and root-mean-square over sensors of the ratio of the
pass's variance per sample to the plain run's (σ²·n, photometric channel, the same samples
so the ratio of σ²), over ``--seeds`` seed pairs, and the largest |difference|/combined σ.
Variance per sample is a load-free figure: it does not depend on the machine's other work.
"""

from __future__ import annotations

import argparse
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.append(str(ROOT))  # a PYTHONPATH given first wins (another tree to compare with)

SCENARIOS = {
    "lamps": {"window_row": 1.7, "corridor_row": 1.7},
    "overcast": {"sky": 1.0, "corridor_row": 0.5},
    "afternoon": {"sky": 0.6, "sun": 1.0, "corridor_row": 0.5},
}


def office(spacing_m: float):
    """The office stage, its work-plane sensors and the study's four groups."""
    from simulator.scene.usd import load_stage
    from simulator.study.inputs.candidates import build_candidates
    from simulator.study.schema import CandidateSpec

    sc = load_stage(str(ROOT / "stages" / "office.usda"), light_units="photometric", radiometric_spectrum="E")
    (cs,) = build_candidates(sc, [CandidateSpec(name="wp", on=["/Office/Room/Floor"], height_m=0.8, spacing_m=spacing_m)], "t")
    names = [l.name for l in sc.lights]
    groups = {"window_row": [n for n in names if "WindowRow" in n], "corridor_row": [n for n in names if "CorridorRow" in n],
              "sky": ["/Office/Sky"], "sun": ["/Office/Sun"]}  # fmt: skip
    return sc, [c.sensor for c in cs.candidates], groups


def plain_run(sc, sensors, levels, groups, n, seed, split="auto"):
    """``probesim run`` of a stage holding only the lights ``levels`` lights, each emission × its level:
    photometric (mean, stderr), each (S,)."""
    from simulator.config.loader import SimulationConfig
    from simulator.engine.driver import Engine
    from simulator.pipeline import run_plan
    from simulator.plan.planner import make_plan
    from simulator.study.trace.groups import group_scene

    lights = []
    for l in sc.lights:
        lv = next((levels.get(g, 0.0) for g, ls in groups.items() if l.name in ls), 0.0)
        if lv > 0:
            lights.append(replace(l, emission=(l.emission[0] * lv, l.emission[1] * lv)))
    sub = replace(group_scene(sc, []), lights=lights)
    eng = Engine(sub, sensors)
    eng.split_indirect = split
    res = run_plan(eng, make_plan(sub, sensors, "auto", "total"), SimulationConfig(samples=n, seed=seed))
    return res.mean[:, 1], res.stderr[:, 1]


def shared_pass(sc, sensors, groups, n, seed, scenarios=SCENARIOS):
    """The one pass over every group, recombined per scenario: {name: (mean, stderr)} photometric."""
    from simulator.config.loader import SimulationConfig
    from simulator.study.trace.groups import trace_groups

    from simulator.engine import driver

    run = driver.Engine.run

    def recorded(self, method, **kw):  # keep the pass's split pilot record
        r = run(self, method, **kw)
        sp = self.split_pilot or {}
        _PASS_SPLIT.append((sp.get("k"), sp.get("k_of_scenarios")))
        return r

    driver.Engine.run = recorded
    try:
        gr = trace_groups(sc, sensors, groups, SimulationConfig(samples=n, seed=seed), seed, scenarios=list(scenarios.values()))
    finally:
        driver.Engine.run = run
    out = {"cpu_s": gr.trace_cpu_s}
    for name, lv in scenarios.items():
        m, se = gr.combine(lv)
        out[name] = (m[:, 1], se[:, 1])
    return out


_PASS_SPLIT = []


def split_of_pass():
    """The K the latest pass drew and each scenario's own (the split pilot's record)."""
    return _PASS_SPLIT[-1] if _PASS_SPLIT else None


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--samples", type=int, default=1024)
    ap.add_argument("--seeds", type=int, default=2)
    ap.add_argument("--spacing", type=float, default=1.5)
    ap.add_argument("--level", type=float, default=1.7)
    ap.add_argument("--split", default="auto", help="the plain run's indirect split: auto or an integer K")
    ap.add_argument("--scenarios", default=",".join(SCENARIOS), help="the pass's scenarios, comma-separated")
    a = ap.parse_args(argv)
    for name in set(SCENARIOS) - set(a.scenarios.split(",")):
        del SCENARIOS[name]
    SCENARIOS["lamps"] = {"window_row": a.level, "corridor_row": a.level}
    split = a.split if a.split == "auto" else int(a.split)
    sc, sensors, groups = office(a.spacing)
    ratios = {k: [] for k in SCENARIOS}
    cpu = []
    worst = {k: 0.0 for k in SCENARIOS}
    for s in range(a.seeds):
        got = shared_pass(sc, sensors, groups, a.samples, 11 + 2 * s)
        cpu.append(got.pop("cpu_s"))
        print("split pilot of the pass (K, each scenario's K):", split_of_pass())
        for name, lv in SCENARIOS.items():
            pm, pse = plain_run(sc, sensors, lv, groups, a.samples, 12 + 2 * s, split)
            m, se = got[name]
            ok = pse > 0
            ratios[name] += list((se[ok] / pse[ok]) ** 2)
            worst[name] = max(worst[name], float(np.max(np.abs(m - pm) / np.hypot(se, pse))))
    print(f"office, {len(sensors)} work-plane sensors, {a.samples} samples, {a.seeds} seed pairs, lamps at {a.level}")
    print(f"pass CPU seconds (process, all threads; contended machine): {', '.join(f'{c:.1f}' for c in cpu)}")
    print("scenario    median var ratio   rms var ratio   max |diff|/sigma")
    for name, r in ratios.items():
        r = np.asarray(r)
        print(f"{name:10s}  {np.median(r):16.3f}  {np.sqrt(np.mean(r**2)):14.3f}  {worst[name]:16.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
