"""Glare views in a study: the stage's glare prims read in every scenario.

A prim of the study's stage with ``probesim:sensor:kind = "glare"`` (an eye
looking down its −Z, up its +Y; :mod:`simulator.glare`) is read in every
scenario of the study: DGP is not linear in the lights' levels (nor are
the glare sources found), so a view is not recombined from light groups
but traced once per scenario, on the scenario's scene:

- the trace group's stage (its variants, its sun turned to the scenario's);
- each light of a light group at the scenario's level (lights in no group
  off; emissive surfaces off, as in every scenario);
- a sky split into Tregenza patches (``sky = "tregenza"``) as a textured
  dome whose texels carry their patch's level (the CIE sky a scenario sets
  is piecewise constant over the patches, as its recombined readings are;
  256 × 128 texels, their centres assigned to patches).

In this process, after the chunks (not distributed, not resumed); each
(view, scenario) has a seed of its own derived from the study's.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from simulator.scene.model import LightKind, SensorKind

__all__ = ["GLARE_COLUMNS", "GlareViewRow", "views_of", "scenario_scene", "study_glare"]

#: texels of the dome that carries a split sky's patch levels
SKY_TEXELS = (256, 128)

GLARE_COLUMNS = ("view", "scenario", "ev_lx", "ev_stderr_lx", "dgp", "dgp_stderr", "dgps", "dgps_stderr", "ugr", "ugr_stderr",
                 "glare_sources", "passes")  # fmt: skip


@dataclass
class GlareViewRow:
    view: str
    scenario: str
    result: object  #: simulator.engine.glare.GlareResult


def views_of(scene) -> list:
    """The stage's glare prims (GLARE sensors), in stage order."""
    return [s for s in scene.sensors if s.kind == SensorKind.GLARE]


def _patch_dome(light, levels: dict, group: str):
    """``light`` (a DomeLight of a split sky group) with each texel × its patch's level."""
    from simulator.io.latlong import texel_centre_directions
    from simulator.study.inputs.sky_patches import GROUND, patch_index
    from simulator.study.trace.groups import level_of

    if light.texture_map is not None:
        h, w = light.texture_map.shape
        base = np.asarray(light.texture_map, np.float64)
    else:
        w, h = SKY_TEXELS
        base = np.ones((h, w))
    d = texel_centre_directions(w, h, light.frame).reshape(h, w, 3)
    p = patch_index(d)
    lv = np.array([level_of(levels, f"{group}/p{k:03d}") for k in range(GROUND)] + [level_of(levels, f"{group}/ground")])
    return replace(light, texture_map=base * lv[p])


def scenario_scene(tg_scene, scenario, groups: dict[str, list[str]], sky_split: tuple[str, ...]):
    """The scene of one scenario (module docstring)."""
    from simulator.study.trace.groups import group_scene

    group_of = {n: g for g, names in groups.items() for n in names}
    lights = []
    for l in tg_scene.lights:
        g = group_of.get(l.name)
        if g is None:
            continue
        if g in sky_split and l.kind == LightKind.DOME:
            lights.append(_patch_dome(l, scenario.levels, g))
            continue
        lv = float(scenario.levels.get(g, 0.0))
        if lv > 0.0:
            lights.append(replace(l, emission=(l.emission[0] * lv, l.emission[1] * lv)))
    return replace(group_scene(tg_scene, []), lights=lights)


def study_glare(study, stage, views: list, tgs: list, groups: dict, sky_split: tuple[str, ...], log=print) -> list[GlareViewRow]:
    """Every view in every scenario (module docstring)."""
    from simulator.engine.driver import Engine
    from simulator.engine.glare import run_glare
    from simulator.plan.planner import probe_method
    from simulator.study.trace.chunks import ChunkSpec, chunk_scene
    from simulator.study.trace.groups import derive_seed

    sim = study.simulation
    rows: list[GlareViewRow] = []
    for tg in tgs:
        spec = ChunkSpec("", tg.key, 0, str(stage), study.light_units, tuple(sorted(tg.variants.items())), tg.sun, (), (), (), {}, 0)
        tg_scene = chunk_scene(spec)
        for sc in tg.scenarios:
            scene = scenario_scene(tg_scene, sc, groups, sky_split)
            if not scene.lights:
                log(f"glare views: scenario {sc.name!r} lights nothing: not read")
                continue
            method, _ = probe_method(scene, sim.method, sim.component)
            for k, v in enumerate(views):
                (r,) = run_glare(scene, [v], method, lambda s, ss: Engine(s, ss, device=sim.device, threads=sim.threads),
                                 seed=derive_seed(study.seed, "glare", v.name, sc.name), max_depth=sim.max_depth)  # fmt: skip
                rows.append(GlareViewRow(v.name, sc.name, r))
    return rows
