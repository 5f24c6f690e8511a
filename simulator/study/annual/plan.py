"""The traces of a year, per shading state: which trace groups, on which sensors, with which lights.

Every state (:mod:`simulator.study.annual.shading`; a study without
``[shading]`` has one, the stage as it is) is traced once for the year:

- the split sky, ``component = "direct"`` and ``"indirect"`` (trace keys
  ``annual;sky;direct`` and ``annual;sky;indirect``), on the candidates and,
  where the state has diffusing shades, their cells' outer sensors
  (:mod:`simulator.study.annual.diffusers`);
- the lamp groups ``[[control]]`` dims (``annual;lamps``);
- the diffusing shades' cells, each a light group of its own (``annual;shade``);
- with ``sun_indirect = "traced"``, the sun at each bin (``annual;sun;<az>,<el>``),
  on the candidates and the glare views' eyes;
- with glare views on the stage, the sky and the cells at an irradiance sensor
  at each eye facing its view direction, ``component = "indirect"``
  (``annual;glare``): the one trace annual glare adds per state
  (:mod:`simulator.study.annual.glare`).

The first state keeps these keys, so a study whose shades never move traces
what it traced without them, with the same seeds; every other state's keys
end in ``;state=<name>``. A state's variant selection enters its chunks'
ids (a resumed study never reads another state's chunks).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["StatePlan", "plan_state", "read_coefficients", "ShadeCoefficients"]

#: the sky's slots: 145 patches and the ground
SKY = 146


@dataclass
class StatePlan:
    """A state's traces (module docstring) and what they are read for."""

    state: object  #: ShadeState
    sky_dir: list = field(default_factory=list)  #: ChunkSpec lists
    sky_ind: list = field(default_factory=list)
    lamps: list = field(default_factory=list)
    shade: list = field(default_factory=list)
    sun_bins: list = field(default_factory=list)  #: one list per bin
    glare: list = field(default_factory=list)
    outer: list = field(default_factory=list)  #: the cells' outer sensors, after the candidates in the sky traces
    cells: list = field(default_factory=list)  #: the cells' RectLights
    cell_groups: list = field(default_factory=list)  #: their light groups, in slot order
    tau: np.ndarray = field(default_factory=lambda: np.zeros(0))  #: each cell's diffuse transmittance
    l_auth: float = 0.0  #: the cells' authored luminance, cd/m²
    eyes: list = field(default_factory=list)  #: an irradiance sensor per glare view

    def specs(self) -> list:
        return [s for lst in (self.sky_dir, self.sky_ind, self.lamps, self.shade, *self.sun_bins, self.glare) for s in lst]

    def traces(self) -> dict:
        """Trace groups by purpose: how many passes over the stage this state costs."""
        out = {"sky_direct": 1, "sky_indirect": 1}
        for k, lst in (("lamps", self.lamps), ("shade", self.shade), ("glare", self.glare)):
            if lst:
                out[k] = 1
        if self.sun_bins:
            out["sun_bins"] = len(self.sun_bins)
        return out


def plan_state(state, study, sensors: list, groups: dict, stage, sim: dict, block: int, sky_split: tuple,
               lamp_groups: list, bin_suns: list | None, views: list, dome) -> StatePlan:  # fmt: skip
    """Every chunk of one state (module docstring)."""
    from simulator.study.annual.diffusers import cell_lights, lights_digest, outer_sensors
    from simulator.study.annual.glare import eye_sensor
    from simulator.study.inputs.scenarios import TraceGroup
    from simulator.study.trace.chunks import make_chunks

    a = study.annual
    sfx, var = state.suffix, dict(state.variants)
    plan = StatePlan(state)
    for d in state.diffusers:
        plan.outer += outer_sensors(d)
    if state.diffusers:
        # an authored luminance near the shade's under the authored sky (its pick weighs it like the sky's patches)
        plan.l_auth = float(dome.emission[1]) * 0.5 * max(d.transmittance for d in state.diffusers)
        for d in state.diffusers:
            plan.cells += cell_lights(d, plan.l_auth, dome)
            plan.tau = np.concatenate([plan.tau, np.full(d.n_cells, d.transmittance)])
        plan.cell_groups = [f"shade:{k}" for k in range(len(plan.cells))]
    ggroups = {**groups, **{g: [l.name for l in plan.cells][k:k + 1] for k, g in enumerate(plan.cell_groups)}}
    ident = {}
    if var:
        ident["variants"] = sorted(var.items())
    lit = dict(ident, lights=lights_digest(plan.cells)) if plan.cells else ident

    def chunks(key, sens, grp, sd, lights=(), sun=None):
        tg = TraceGroup(key + sfx, var, sun, [], grp)
        return make_chunks([tg], sens, ggroups, stage, study.light_units, sd, study.seed, block, sky_split, tuple(lights),
                           (lit if lights else ident) or None)  # fmt: skip

    sky_sensors = list(sensors) + plan.outer
    plan.sky_dir = chunks("annual;sky;direct", sky_sensors, [a.sky_group], {**sim, "component": "direct"})
    plan.sky_ind = chunks("annual;sky;indirect", sky_sensors, [a.sky_group], {**sim, "component": "indirect"})
    if lamp_groups:
        plan.lamps = chunks("annual;lamps", sensors, lamp_groups, sim)
    if plan.cells:
        plan.shade = chunks("annual;shade", sensors, plan.cell_groups, sim, plan.cells)
    plan.eyes = [eye_sensor(v) for v in views]
    for az, el in bin_suns or []:  # the eyes too: their interreflected sun from the same passes
        plan.sun_bins.append(chunks(f"annual;sun;{az:.6f},{el:.6f}", list(sensors) + plan.eyes, [a.sun_group], sim, sun=(az, el)))
    if views:
        gsim = {**sim, "component": "indirect"}
        if gsim["method"] in ("light", "bsdf", "mis"):  # direct-light estimators read no reflected light
            gsim["method"] = "path"
        plan.glare = chunks("annual;glare", plan.eyes, [a.sky_group] + plan.cell_groups, gsim, plan.cells)
    return plan


@dataclass
class ShadeCoefficients:
    """The extra coefficients of one state (each (N, G) with covariances (N, G, G)).

    ``outer_dir``/``outer_ind``: the cells' outer sensors on the sky's 146 slots; ``shade``: the candidates
    on the cells' groups; ``eye``: the eyes on the sky's slots then the cells' (component indirect)."""

    outer_dir: np.ndarray
    outer_dir_cov: np.ndarray
    outer_ind: np.ndarray
    outer_ind_cov: np.ndarray
    shade: np.ndarray
    shade_cov: np.ndarray
    eye: np.ndarray
    eye_cov: np.ndarray


def read_coefficients(specs: list, results: dict, n: int, g: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(mean (n, g), cov (n, g, g), samples (n,))`` of the photometric channel from a trace's chunks."""
    from simulator.study.trace.chunks import readings_of

    mean, cov, samples = np.zeros((n, g)), np.zeros((n, g, g)), np.zeros(n, np.int64)
    for s in specs:
        gr = readings_of(results[s.id])
        ids = np.asarray(s.sensor_ids)
        mean[ids] = gr.mean[:, :, 1].T
        cov[ids] = gr.cov[:, 1]
        samples[ids] = gr.samples[0]
    return mean, cov, samples
