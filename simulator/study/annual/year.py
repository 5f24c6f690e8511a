"""A year of daylight: one trace of the sky's patches, every hour a recombination with its error, the sun exact.

Method
------
1. The climate file (:mod:`simulator.study.annual.climate`) gives each hour's sky
   and sun; the sky is the Perez all-weather model over Tregenza's patches,
   scaled to the hour's diffuse horizontal illuminance
   (:mod:`simulator.study.annual.perez`), the dome below the horizon a uniform
   ground of luminance ρ_g (E_dh + E_n sin h)/π.
2. The split sky group (``[annual] sky_group``) is traced twice per sensor
   block, once for its *direct* light and once for its *interreflected*
   light (``component = "direct"`` / ``"indirect"``, independent seeds), each
   as 146 daylight coefficients with their covariance
   (:mod:`simulator.study.trace.groups`). The lamp groups that ``[[control]]``
   dims are traced once more, as ordinary light groups.
3. Each hour's reading is

   .. math:: E_h = d_h^\\top c^{dir} + (d_h + q_h)^\\top c^{ind} + E^{sun}_h,
             \\qquad \\sigma_h^2 = d_h^\\top C^{dir} d_h + (d_h + q_h)^\\top C^{ind} (d_h + q_h),

   with d_h the hour's patch levels L_p/L_dome, E^sun_h the sun's direct
   light computed exactly by a shadow ray per sensor and hour
   (:mod:`simulator.study.annual.sunlight`), and q_h the sun's light put into the
   ``sun_patches`` patches nearest the sun (weights 1/(1.002 − cos ψ), ψ the
   angle to a patch's centre, as Radiance's gendaymtx spreads it), at
   luminance w_p E_n / Ω_p: the sun's *interreflected* light comes from
   the indirect coefficients of the patches around it, its direct light is
   never approximated. A cone photosensor's direct coefficients hold the
   surfaces it sees lit directly (a radiance meter's direct component is
   its first hit's light), so for it q_h enters them too:
   E_h += q_hᵀ c^{dir}, and only a sun inside its cone is left to E^sun.
   With ``sun_indirect = "traced"`` q_h = 0 and the stage's DistantLight is
   traced at the mean sun of each bin of the year's sun positions
   (:func:`sun_bins`); its exact direct light at that position is taken off
   the bin's coefficient t_b, and hour h adds (E_n,h / E_n,authored)·t_b of
   its bin (variance scaled alike).
4. Annual metrics (:mod:`simulator.study.annual.metrics`) and control
   (:mod:`simulator.study.annual.control`) are functions of the hourly series. An
   hour's readings of one sensor share its coefficients, so errors are
   correlated across hours: each figure's standard error is its standard
   deviation over ``replicates`` whole years recombined from coefficient
   vectors redrawn from N(ĉ, C) per sensor (a parametric bootstrap; sensors
   are independent, each has its own random stream).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from simulator.errors import UserError
from simulator.study.annual import heads as AH
from simulator.study.inputs import sky_patches as SP
from simulator.study.annual.coefficients import Coefficients, _sqrt_psd, hourly, replicate_years
from simulator.study.trace.groups import derive_seed

__all__ = ["AnnualResult", "GlareYear", "run_annual", "sun_patch_levels", "Coefficients", "hourly", "replicate_years"]

#: CIE overcast sky horizontal illuminance the daylight factor is read at (any value: DF is a ratio)
_DF_SKY_LX = 10000.0


def sun_patch_levels(sun_dir: np.ndarray, sun_lx: np.ndarray, k: int, l_dome: float) -> np.ndarray:
    """Patch levels q_h (H, 146) carrying the sun's light for the interreflected part (see the module's Notes)."""
    cent = np.stack([SP.patch_direction(p) for p in range(SP.N_PATCHES)])
    omega = np.array([SP.patch_solid_angle(p) for p in range(SP.N_PATCHES)])
    out = np.zeros((len(sun_dir), SP.N_PATCHES + 1))
    cosp = sun_dir @ cent.T
    near = np.argsort(-cosp, axis=1, kind="stable")[:, :k]
    w = 1.0 / (1.002 - np.take_along_axis(cosp, near, axis=1))
    w /= w.sum(axis=1, keepdims=True)
    rows = np.arange(len(sun_dir))[:, None]
    out[rows, near] = w * (np.asarray(sun_lx)[:, None] / (omega[near] * l_dome))
    out[np.asarray(sun_lx) <= 0] = 0.0
    return out


def sky_levels_of(skies, l_dome: float, ground_reflectance: float) -> np.ndarray:
    """Patch levels d_h (H, 146): the Perez patches over L_dome and the ground slot."""
    d = np.zeros((len(skies.dhi_lx), SP.N_PATCHES + 1))
    d[:, : SP.N_PATCHES] = skies.patch_cd_m2 / l_dome
    d[:, SP.N_PATCHES] = ground_reflectance * skies.global_lx / math.pi / l_dome
    return d


def sun_bins(sun_dir: np.ndarray, lit: np.ndarray, bin_deg: float) -> tuple[np.ndarray, list]:
    """Each lit hour's sun-position bin (−1 where unlit) and each bin's traced sun ``(azimuth, elevation)``.

    Bins: altitude bands ``bin_deg`` high from the horizon, each cut into
    ``max(1, round(360·cos(mid-altitude)/bin_deg))`` equal azimuth bins; a
    bin's sun is the normalised mean direction of its hours (so the traced
    sun lies among them, at most about ``bin_deg``/√2 from any)."""
    alt = np.degrees(np.arcsin(np.clip(sun_dir[:, 2], -1.0, 1.0)))
    az = np.mod(np.degrees(np.arctan2(sun_dir[:, 0], sun_dir[:, 1])), 360.0)
    band = np.clip((alt // bin_deg).astype(np.int64), 0, None)
    n_az = np.maximum(1, np.round(360.0 * np.cos(np.radians((band + 0.5) * bin_deg)) / bin_deg)).astype(np.int64)
    cell = band * 100000 + np.floor(az / (360.0 / n_az)).astype(np.int64) % n_az
    keys = sorted(set(cell[lit].tolist()))
    index = {k: i for i, k in enumerate(keys)}
    out = np.full(len(sun_dir), -1, np.int64)
    out[lit] = [index[c] for c in cell[lit]]
    suns = []
    for i in range(len(keys)):
        m = sun_dir[out == i].mean(axis=0)
        m /= np.linalg.norm(m)
        suns.append((float(np.mod(np.degrees(np.arctan2(m[0], m[1])), 360.0)), float(np.degrees(np.arcsin(m[2])))))
    return out, suns


@dataclass
class AnnualResult:
    """Everything the annual outputs hold."""

    weather: object
    rows: np.ndarray  #: weather rows analysed
    occupied: np.ndarray
    daylight: np.ndarray
    skies: object
    sensors: list  #: Candidate, study order
    mean: np.ndarray  #: (H, S) lux (cd/m² for cone meters)
    stderr: np.ndarray
    sun_direct: np.ndarray
    df: np.ndarray  #: (S,) daylight factor (fraction)
    df_se: np.ndarray
    metrics: dict  #: zone -> {metric: (value, stderr)}
    controls: list  #: dicts, one per [[control]] (chosen photosensor and every candidate's figures)
    timings_s: dict = field(default_factory=dict)
    cpu_s: dict = field(default_factory=dict)
    notes: list = field(default_factory=list)
    chunks_total: int = 0
    chunks_computed: int = 0
    coefficients: Coefficients | None = None
    sky_levels: np.ndarray | None = None  #: (H, 146) d_h
    zones: dict = field(default_factory=dict)  #: zone -> candidate indices
    scene: object | None = None  #: the stage as read (the report's plans); not in any output file
    annual_spec: object | None = None  #: the study's [annual] table
    states: list = field(default_factory=list)  #: the shading states' names ([] without [shading])
    state: np.ndarray | None = None  #: (H,) each hour's state (index into ``states``), None without [shading]
    shading: object | None = None  #: the study's [shading] table
    extra: dict = field(default_factory=dict)  #: (zone, view or window group, metric) -> (value, stderr) beyond a plain year's
    glare: "GlareYear | None" = None  #: the views' hourly E_v and index, None without glare views
    traces: dict = field(default_factory=dict)  #: state -> {purpose: trace groups}
    detail: dict = field(default_factory=dict)  #: "states", "plans", "years" (ShadeState, StatePlan, StateYear): for checks, in no file
    sensor_models: dict = field(default_factory=dict)  #: modelled candidates: each model's sets, spectra and F per light


@dataclass
class GlareYear:
    """The glare views' hours with the chosen shading states: E_v (lx) and DGP (or DGPs), each (H, V) with its standard error."""

    views: list
    index_name: str  #: "dgp" or "dgps"
    ev: np.ndarray
    ev_se: np.ndarray
    index: np.ndarray
    index_se: np.ndarray
    metric_defs: dict


def _coefficients(specs_dir, specs_ind, specs_lamp, results, n_s: int, lamp_names: list) -> Coefficients:
    """The candidates' coefficients (the first ``n_s`` sensors of the sky's chunks; a diffusing shade's outer
    sensors after them are read by :func:`simulator.study.annual.plan.read_coefficients`)."""
    from simulator.study.trace.chunks import readings_of

    g = SP.N_PATCHES + 1
    out = Coefficients(np.zeros((n_s, g)), np.zeros((n_s, g, g)), np.zeros((n_s, g)), np.zeros((n_s, g, g)),
                       np.zeros((n_s, len(lamp_names))), np.zeros((n_s, len(lamp_names), len(lamp_names))), lamp_names,
                       np.zeros(n_s, np.int64))  # fmt: skip
    for specs, mean, cov in ((specs_dir, out.dir, out.dir_cov), (specs_ind, out.ind, out.ind_cov), (specs_lamp, out.lamp, out.lamp_cov)):
        for s in specs:
            gr = readings_of(results[s.id])
            ids = np.asarray(s.sensor_ids)
            keep = ids < n_s
            if not keep.all():
                gm, gc, gs, ids = gr.mean[:, keep], gr.cov[keep], gr.samples[0][keep], ids[keep]
            else:
                gm, gc, gs = gr.mean, gr.cov, gr.samples[0]
            mean[ids] = gm[:, :, 1].T
            cov[ids] = gc[:, 1]
            out.samples[ids] += gs
    return out


def _control_pools(study, cands, names_index: dict, label: str) -> list[list[int]]:
    """Each [[control]]'s photosensor candidates: the one named, or every candidate of the named set."""
    out = []
    for i, c in enumerate(study.control):
        if c.photosensor in names_index:
            pool = [names_index[c.photosensor]]
        else:
            pool = [k for k, cd in enumerate(cands) if cd.set_name == c.photosensor]
            if not pool:
                raise UserError(f"{label}: control[{i}].photosensor: no candidate or [[candidates]] set named {c.photosensor!r}")
        out.append(pool)
    return out


def _annual_heads(study, base, cands, groups: dict, label: str):
    """The modelled candidates' spectral factors per group and for the sun (None: no candidate names a model)."""
    from simulator.study.inputs.heads import head_factors

    if not any(getattr(c.sensor, "model", None) is not None for c in cands):
        return None
    return head_factors(study, base, cands, groups, label, {AH.SUN: AH.sun_spectrum(study, base, groups, label)})


def _sky_share(skies) -> np.ndarray:
    """Each hour's share of sky light in the ground's luminance ρ(E_dh + E_n sin h)/π (1 where it is dark)."""
    g = skies.global_lx
    return np.divide(skies.dhi_lx, g, out=np.ones_like(g), where=g > 0)


def _devices(heads, cands, pools, seed: int, occupied_rows: np.ndarray, n_rows: int) -> dict:
    """The photosensor candidates whose model has electronics: candidate → (its head's index, its hours'
    noise draws (H, C))."""
    dev_seed = derive_seed(seed, "annual", "device")
    at = {int(i): j for j, i in enumerate(heads.index)}
    out = {}
    for k in sorted({k for pool in pools for k in pool}):
        j = at.get(k)
        if j is not None and heads.models[j].electronics is not None:
            out[k] = (j, AH.hour_noise(dev_seed, cands[k].sensor.name, occupied_rows, n_rows, len(heads.models[j].channels)))
    return out


def _saturated(o) -> tuple:
    """``(hours saturated,)`` of a device's outcome, () of any other."""
    h = getattr(o, "saturated_hours", None)
    return () if h is None else (h,)


def _select(arrays: list, choice: np.ndarray):
    """Row h of ``arrays[choice[h]]`` for every h; the array itself where one state holds every hour."""
    ks = np.unique(choice)
    if len(ks) == 1:
        return arrays[int(ks[0])]
    out = np.array(arrays[0], copy=True)
    for k in ks[ks > 0]:
        m = choice == k
        out[m] = arrays[int(k)][m]
    return out


def _redraw(mean: np.ndarray, root: np.ndarray, rng) -> np.ndarray:
    """``mean`` (N, G) redrawn from N(mean, A·Aᵀ) per row, ``root`` the (N, G, G) A's."""
    if mean.size == 0:
        return mean
    return mean + np.einsum("ngk,nk->ng", root, rng.standard_normal(mean.shape))


@dataclass
class StateYear:
    """One shading state's year: its coefficients and hourly readings (H hours, S candidates, C cells, V views)."""

    co: Coefficients
    sun: np.ndarray  #: (H, S) exact direct sun
    mean: np.ndarray  #: (H, S)
    stderr: np.ndarray
    shade: object = None  #: simulator.study.annual.plan.ShadeCoefficients, or None
    outer_sun: np.ndarray | None = None  #: (H, C) the cells' outer faces' direct sun
    lum_cells: np.ndarray | None = None  #: (H, C) L_c(h), cd/m²
    views: list = field(default_factory=list)  #: ViewSky per view
    suns: list = field(default_factory=list)  #: SunTerms per view
    ev: np.ndarray | None = None  #: (H, V) E_v
    ev_se: np.ndarray | None = None
    g: np.ndarray | None = None  #: (H, V) Σ L²ω/P²
    index: np.ndarray | None = None  #: (H, V) DGP (or DGPs)
    index_se: np.ndarray | None = None
    eye_sun: np.ndarray | None = None  #: (H, V) traced bins: the eyes' interreflected sun
    eye_sun_var: np.ndarray | None = None
    eye_bins: np.ndarray | None = None  #: (V, B) traced bins: the eyes' interreflected sun per bin, for the authored sun
    eye_bins_var: np.ndarray | None = None


def _cells_luminance(sh, plan, d, q_patch, outer_sun, stderr: bool = True):
    """L_c(h) = τ·E_c(h)/π of every cell (H, C) and, with ``stderr``, its variance."""
    dq = d + q_patch
    e = d @ sh.outer_dir.T + dq @ sh.outer_ind.T + outer_sun
    lum = e * (plan.tau / math.pi)
    if not stderr:
        return lum, None
    var = np.zeros_like(e)
    for c in range(e.shape[1]):
        var[:, c] = np.sum((d @ sh.outer_dir_cov[c]) * d, axis=1) + np.sum((dq @ sh.outer_ind_cov[c]) * dq, axis=1)
    return lum, var * (plan.tau / math.pi) ** 2


def _state_year(plan, study, results, sensors, lamp_groups, d, q, q_patch, l_dome, cone, sun_bin, sun_scale, bin_suns,
                e_auth, skies, views, timing: dict) -> StateYear:  # fmt: skip
    """Coefficients and hourly readings of one state (see :mod:`simulator.study.annual.plan`)."""
    from simulator.study.annual.glare import glare_term, sun_terms, view_sky
    from simulator.study.annual.plan import SKY, ShadeCoefficients, read_coefficients
    from simulator.study.annual.rays import ray_scene
    from simulator.study.annual.sunlight import direct_sun
    from simulator.study.inputs.sun import sun_direction
    from simulator.study.trace.chunks import readings_of

    st = plan.state
    n_s = len(sensors)
    co = _coefficients(plan.sky_dir, plan.sky_ind, plan.lamps, results, n_s, lamp_groups)
    if sun_bin is not None:
        co.sun = np.zeros((n_s, len(plan.sun_bins)))
        co.sun_var = np.zeros_like(co.sun)
        eye_sun = np.zeros((len(plan.eyes), len(plan.sun_bins)))
        eye_sun_var = np.zeros_like(eye_sun)
        for b, lst in enumerate(plan.sun_bins):
            for s_ in lst:
                gr = readings_of(results[s_.id])
                ids = np.asarray(s_.sensor_ids)
                room = ids < n_s  # the glare views' eyes follow the candidates
                co.sun[ids[room], b] = gr.mean[0, room, 1]
                co.sun_var[ids[room], b] = gr.stderr[0, room, 1] ** 2
                eye_sun[ids[~room] - n_s, b] = gr.mean[0, ~room, 1]
                eye_sun_var[ids[~room] - n_s, b] = gr.stderr[0, ~room, 1] ** 2
        # the passes trace the whole sun; its exact direct part at the bin's own sun comes off (it is added per hour)
        bin_dirs = np.stack([sun_direction(az, el) for az, el in bin_suns])
        co.sun -= direct_sun(sensors, st.scene, bin_dirs, np.full(len(bin_suns), e_auth)).T
        if plan.eyes:
            eye_sun -= direct_sun(plan.eyes, st.scene, bin_dirs, np.full(len(bin_suns), e_auth)).T
    c_sun = time.process_time()
    sun = direct_sun(sensors, st.scene, skies.sun_dir, skies.dni_lx)
    timing["sun_shadow_rays"] = timing.get("sun_shadow_rays", 0.0) + time.process_time() - c_sun
    mean, stderr = hourly(co, d, q, sun, sun_bin=sun_bin, sun_scale=sun_scale, cone=cone if sun_bin is None else None)
    y = StateYear(co, sun, mean, stderr)
    n_c = len(plan.cells)
    n_slots = SKY + n_c
    if not n_c and not views:
        return y
    out_dir_m, out_dir_c, _ = read_coefficients(plan.sky_dir, results, n_s + len(plan.outer), SKY)
    out_ind_m, out_ind_c, _ = read_coefficients(plan.sky_ind, results, n_s + len(plan.outer), SKY)
    sh_m, sh_c, _ = read_coefficients(plan.shade, results, n_s, n_c)
    eye_m, eye_c, _ = read_coefficients(plan.glare, results, len(plan.eyes), n_slots)
    y.shade = ShadeCoefficients(out_dir_m[n_s:], out_dir_c[n_s:], out_ind_m[n_s:], out_ind_c[n_s:], sh_m, sh_c, eye_m, eye_c)
    lum_c = np.zeros((len(d), 0))
    if n_c:
        y.outer_sun = direct_sun(plan.outer, st.scene, skies.sun_dir, skies.dni_lx)
        lum_c, lum_var = _cells_luminance(y.shade, plan, d, q_patch, y.outer_sun)
        y.lum_cells = lum_c
        x = lum_c / plan.l_auth
        x_var = lum_var / plan.l_auth**2
        var = stderr**2 + x_var @ (sh_m**2).T
        for s in range(n_s):
            var[:, s] += np.sum((x @ sh_c[s]) * x, axis=1)
        y.mean = mean + x @ sh_m.T
        y.stderr = np.sqrt(np.maximum(var, 0.0))
    if views:
        c_view = time.process_time()
        rs = ray_scene(st.scene)
        base_slot, cell_base = SKY, []
        for dd in st.diffusers:
            cell_base.append(base_slot)
            base_slot += dd.n_cells
        lum = np.concatenate([d * l_dome, lum_c], axis=1)
        traced = sun_bin is not None  # the eyes' interreflected sun from the traced bins, else from the patches
        xe = np.concatenate([d + (q if traced else q_patch), lum_c / plan.l_auth if n_c else lum_c], axis=1)
        n_h, n_v = len(d), len(views)
        if traced:
            y.eye_bins, y.eye_bins_var = eye_sun, eye_sun_var
            y.eye_sun, y.eye_sun_var = _bins_hourly(eye_sun, sun_bin, sun_scale), _bins_hourly(eye_sun_var, sun_bin, sun_scale**2)
        y.ev, y.ev_se, y.g = np.zeros((n_h, n_v)), np.zeros((n_h, n_v)), np.zeros((n_h, n_v))
        y.index, y.index_se = np.zeros((n_h, n_v)), np.zeros((n_h, n_v))
        for v, view in enumerate(views):
            vs = view_sky(view, rs, st.diffusers, cell_base, n_slots)
            su = sun_terms(vs, rs, skies.sun_dir, skies.dni_lx)
            y.views.append(vs)
            y.suns.append(su)
            y.ev[:, v] = lum @ vs.a + xe @ eye_m[v] + su.ev + (y.eye_sun[:, v] if traced else 0.0)
            y.ev_se[:, v] = np.sqrt(np.maximum(np.sum((xe @ eye_c[v]) * xe, axis=1) + (y.eye_sun_var[:, v] if traced else 0.0), 0.0))
            y.g[:, v] = glare_term(vs, lum, su)
        _index_of(y, views, study.annual.glare_index)
        timing["views"] = timing.get("views", 0.0) + time.process_time() - c_view
    return y


def _bins_hourly(per_bin: np.ndarray, sun_bin: np.ndarray, scale: np.ndarray) -> np.ndarray:
    """(V, B) values per sun bin → (H, V) per hour: the hour's bin × its scale (0 where the sun is down)."""
    out = np.zeros((len(sun_bin), per_bin.shape[0]))
    on = sun_bin >= 0
    out[on] = per_bin[:, sun_bin[on]].T * scale[on, None]
    return out


def _index_of(y: StateYear, views: list, which: str, ev: np.ndarray | None = None):
    """DGP (or DGPs) of every hour and view from ``ev`` (default ``y.ev``) and ``y.g``: sets ``y.index``/``index_se``
    when ``ev`` is None, else returns the index."""
    from simulator.glare.sources import GlareSettings
    from simulator.study.annual.glare import dgp_hourly, dgps_hourly

    e = y.ev if ev is None else ev
    out = np.zeros_like(e)
    slope = np.zeros_like(e)
    for v, view in enumerate(views):
        s = view.glare if view.glare is not None else GlareSettings()
        out[:, v], slope[:, v] = dgps_hourly(e[:, v]) if which == "dgps" else dgp_hourly(e[:, v], y.g[:, v], s.low_light)
    if ev is not None:
        return out
    y.index, y.index_se = out, np.abs(slope) * y.ev_se
    return None


def _replicate_state(y: StateYear, plan, rc: Coefficients, roots: dict, rng, d, q, q_patch, l_dome, sun_bin, sun_scale, cone,
                     views, which: str):  # fmt: skip
    """One replicate year of a state: the candidates' readings (H, S) and the views' index (H, V) or None."""
    e_r, _ = hourly(rc, d, q, y.sun, stderr=False, sun_bin=sun_bin, sun_scale=sun_scale, cone=cone if sun_bin is None else None)
    if y.shade is None:
        return e_r, None
    sh = y.shade
    lum_c = np.zeros((len(d), 0))
    if y.lum_cells is not None:
        from types import SimpleNamespace

        o = SimpleNamespace(outer_dir=_redraw(sh.outer_dir, roots["outer_dir"], rng),
                            outer_ind=_redraw(sh.outer_ind, roots["outer_ind"], rng))  # fmt: skip
        lum_c, _ = _cells_luminance(o, plan, d, q_patch, y.outer_sun, stderr=False)
        e_r = e_r + (lum_c / plan.l_auth) @ _redraw(sh.shade, roots["shade"], rng).T
    if not views:
        return e_r, None
    eye = _redraw(sh.eye, roots["eye"], rng)
    lum = np.concatenate([d * l_dome, lum_c], axis=1)
    traced = y.eye_sun is not None
    xe = np.concatenate([d + (q if traced else q_patch), lum_c / plan.l_auth if lum_c.shape[1] else lum_c], axis=1)
    ev = np.stack([lum @ vs.a + xe @ eye[v] + su.ev for v, (vs, su) in enumerate(zip(y.views, y.suns))], axis=1)
    if traced:  # each bin's traced sun redrawn once for the whole year (its hours share it)
        bins = y.eye_bins + np.sqrt(np.maximum(y.eye_bins_var, 0.0)) * rng.standard_normal(y.eye_bins.shape)
        ev = ev + _bins_hourly(bins, sun_bin, sun_scale)
    return e_r, _index_of(y, views, which, ev)


def run_annual(study, path: Path, out_dir: Path, *, log=print, mode: str | None = None, workers: int | None = None,
               scheduler: str | None = None) -> AnnualResult:  # fmt: skip
    """Run (or resume) the ``[annual]`` part of a study; outputs are written by :mod:`simulator.study.annual.outputs`."""
    from simulator.scene.model import LightKind, SensorKind
    from simulator.scene.usd import load_stage
    from simulator.study.annual import control as CT
    from simulator.study.annual import shading as SH
    from simulator.study.annual.glare import GLARE_METRICS, annual_views, glare_metrics
    from simulator.study.annual.plan import plan_state
    from simulator.study.annual.rays import textured_faces
    from simulator.study.figures.glare_views import views_of
    from simulator.study.inputs.candidates import build_candidates, candidate_warnings
    from simulator.study.trace.chunks import ChunkStore, stale_chunks_note
    from simulator.study.annual.climate import daylight_mask, hour_of_day, read_weather
    from simulator.study.trace.distributed import choose_mode, run_chunks
    from simulator.study.annual.metrics import zone_metrics
    from simulator.study.annual.perez import hour_skies
    from simulator.study.runner import _sim_dict, zone_members
    from simulator.study.inputs.scenarios import check_split_groups, resolve_groups

    a = study.annual
    label = str(path)
    t0, c0 = time.perf_counter(), time.process_time()
    if study.light_units != "photometric":
        raise UserError(f"{label}: annual: needs light_units = \"photometric\" (climate files give illuminances in lux)")
    stage = (path.parent / study.stage).resolve() if not Path(study.stage).is_absolute() else Path(study.stage)
    wpath = (path.parent / a.weather).resolve() if not Path(a.weather).is_absolute() else Path(a.weather)
    weather = read_weather(wpath, f"{label}: annual.weather")
    if a.illuminance == "file" and weather.dhi_lx is None:
        raise UserError(f"{label}: annual.illuminance: the weather file has no illuminance fields: use \"efficacy\"")
    base = load_stage(stage, light_units=study.light_units, radiometric_spectrum="E")
    sets = build_candidates(base, study.candidates, label)
    misplaced = candidate_warnings(base, study.candidates, sets, label)
    for w in misplaced:
        log(f"warning: {w}")
    cands = [c for s in sets for c in s.candidates]
    sensors = [c.sensor for c in cands]
    groups, _ = resolve_groups(base, study.group, label)
    sky_split = check_split_groups(base, study.group, groups, label)
    zones = zone_members(study, sets, cands, label)
    dome = next(l for l in base.lights if l.name in groups[a.sky_group] and l.kind == LightKind.DOME)
    l_dome = float(dome.emission[1])
    if l_dome <= 0:
        raise UserError(f"{label}: annual.sky_group: the DomeLight {dome.name} has no luminance to scale")
    names_index = {c.sensor.name: k for k, c in enumerate(cands)}
    pools = _control_pools(study, cands, names_index, label)
    heads = _annual_heads(study, base, cands, groups, label)
    notes = list(weather.notes) + [f"warning: {w}" for w in weather.warnings + misplaced]
    for w in weather.warnings:  # the weather's doubts, on the console as they are found and in the record
        log(f"warning: {w}")
    if any(l.kind == LightKind.DISTANT for l in base.lights):
        notes.append("the stage's DistantLight is not used: each hour's sun comes from the weather file")
    if heads is not None:
        notes += [f"warning: {w}" for w in heads.notes]
        for w in heads.notes:
            log(f"warning: {w}")

    # shading states (each its own stage) and the glare views read every hour
    sh = study.shading
    if sh is not None and heads is not None:
        named = next(c.sensor for c in cands if getattr(c.sensor, "model", None) is not None)
        raise UserError(f"{label}: candidate {named.name!r} names a sensor model, which a study with [shading] does not "
                        "read yet (a head's response to the shades' own light); leave the model out of this study")  # fmt: skip
    states = SH.shading_states(study, stage, base, label)
    all_views = views_of(base)
    views, skipped = annual_views(all_views)
    for w in skipped:
        log(f"warning: {w}")
    notes += [f"warning: {w}" for w in skipped]
    judged = list(range(len(views)))
    if sh is not None and sh.rule == "glare":
        if not views:
            raise UserError(f"{label}: shading.rule: \"glare\" needs glare views on the stage (prims with "
                            "probesim:sensor:kind = \"glare\" and an absolute evalglare -b); it has none")  # fmt: skip
        names, every = [v.name for v in views], [v.name for v in all_views]
        for j, n in enumerate(sh.views):
            if n in every and n not in names:
                raise UserError(f"{label}: shading.views[{j}]: glare view {n!r} has a relative evalglare -b (a multiple "
                                "of the task or mean luminance), which a year without pictures cannot read")  # fmt: skip
            if n not in names:
                raise UserError(f"{label}: shading.views[{j}]: no glare view named {n!r} on the stage (it has: {', '.join(every)})")
        judged = [names.index(n) for n in sh.views] if sh.views else judged
    if any(textured_faces(st.scene) for st in states):
        notes.append("the host's rays (direct sun, the views' sky) read an opacity texture at its mean coverage")
    if any(st.diffusers for st in states):
        notes.append("diffusing shades: " + "; ".join(sorted({f"{dd.prim} (transmittance {dd.transmittance:g}, "
                                                              f"{dd.cells[0]} x {dd.cells[1]} cells)" for st in states
                                                              for dd in st.diffusers})))  # fmt: skip

    # hours: daylight (sun above the horizon at the centre, or diffuse light) and occupied hours
    hod = hour_of_day(weather)
    occ_all = (hod >= a.occupied_h[0]) & (hod < a.occupied_h[1])
    rows = np.nonzero(daylight_mask(weather) | occ_all)[0][:: a.step_h]
    skies = hour_skies(weather, rows, a.illuminance)
    occupied = occ_all[rows]
    daylight = weather.sun_elevation_deg[rows] > 0.0
    t_weather = time.perf_counter()

    # traces: per state, the sky's direct and interreflected coefficients, the controlled lamps, the shades, the eyes
    sim = _sim_dict(study)
    lamp_groups = sorted({g for c in study.control for g in c.groups}, key=list(groups).index)
    sun_bin = sun_scale = bin_suns = None
    e_auth = 0.0
    if a.sun_indirect == "traced":
        distant = [l for l in base.lights if l.kind == LightKind.DISTANT]
        if len(distant) != 1 or groups[a.sun_group] != [distant[0].name]:
            raise UserError(f"{label}: annual.sun_group: group {a.sun_group!r} must hold the stage's one DistantLight "
                            f"(the stage has {len(distant)})")  # fmt: skip
        sl = distant[0]
        e_auth = float(sl.emission[1]) if sl.half_angle == 0.0 else float(sl.emission[1]) * math.pi * math.sin(sl.half_angle) ** 2
        lit_h = skies.dni_lx > 0
        sun_bin, bin_suns = sun_bins(skies.sun_dir, lit_h, a.sun_bin_deg)
        sun_scale = skies.dni_lx / e_auth
        notes.append(f"interreflected sun traced at {len(bin_suns)} sun positions (bins of {a.sun_bin_deg:g} deg)")
    block = study.compute.sensor_block
    if block == "auto":  # from the study's size alone, as the scenario runner does (simulator.study.trace.blocks)
        from simulator.study.trace.blocks import auto_block

        block = auto_block(len(sensors), study.simulation.samples)
    plans = [plan_state(st, study, sensors, groups, stage, sim, block, tuple(sky_split), lamp_groups, bin_suns, views, dome)
             for st in states]  # fmt: skip
    specs = [s for p in plans for s in p.specs()]
    store = ChunkStore(out_dir)
    if (stale := store.drop_other_code()) > 0:
        notes.append(f"warning: {stale_chunks_note(out_dir, stale)}")
        log(f"warning: {stale_chunks_note(out_dir, stale)}")
    results = {s.id: r for s in specs if (r := store.load(s.id)) is not None}
    todo = [s for s in specs if s.id not in results]
    used_mode, n_workers = choose_mode(mode or study.compute.mode, scheduler or study.compute.scheduler, len(todo),
                                       workers if workers is not None else study.compute.workers)  # fmt: skip
    computed = 0
    for res in run_chunks(todo, used_mode, n_workers, scheduler or study.compute.scheduler, study.compute.retries, log=log):
        store.save(res)
        results[res["id"]] = res
        computed += 1
    t_traced = time.perf_counter()
    trace_cpu = sum(float(results[s.id].get("trace_cpu_s", 0.0)) for s in specs)

    # every hour, every state
    d = sky_levels_of(skies, l_dome, a.ground_reflectance)
    q_patch = sun_patch_levels(skies.sun_dir, skies.dni_lx, a.sun_patches, l_dome)
    q = q_patch if sun_bin is None else np.zeros_like(d)
    cone = np.array([c.sensor.kind == SensorKind.RADIANCE for c in cands])
    timing: dict = {}
    years = [_state_year(p, study, results, sensors, lamp_groups, d, q, q_patch, l_dome, cone, sun_bin, sun_scale, bin_suns,
                         e_auth, skies, views, timing) for p in plans]  # fmt: skip
    co = years[0].co
    sun = years[0].sun
    ov = np.zeros(SP.N_PATCHES + 1)
    ov[: SP.N_PATCHES] = SP.sky_weights("overcast", None, _DF_SKY_LX / l_dome)

    def df_of(c: Coefficients) -> np.ndarray:
        return (c.dir + c.ind) @ ov / _DF_SKY_LX

    df = df_of(co)
    df_se = np.sqrt(np.maximum(np.einsum("p,spq,q->s", ov, co.dir_cov + co.ind_cov, ov), 0.0)) / _DF_SKY_LX

    # each hour's state
    analysis = np.unique(np.concatenate([zones[z] for z in (sh.zones if sh is not None and sh.zones else zones)])) if zones else None
    wc = weather.centre[rows]
    month = np.asarray(wc.month)
    hod_rows = hod[rows]

    def choose(sun_by_state, index_by_state):
        if sh is None or len(states) == 1:
            return np.zeros(len(rows), np.int64)
        if sh.rule == "lm83":
            return SH.lm83_choice([s_[:, analysis] for s_ in sun_by_state], a.ase_lx, sh.share)
        if sh.rule == "glare":
            return SH.glare_choice([g_[:, judged] for g_ in index_by_state], sh.dgp_limit)
        return SH.schedule_choice(list(sh.states), sh.schedule, month, hod_rows)

    choice = choose([y.sun for y in years], [y.index for y in years])
    mean = _select([y.mean for y in years], choice)
    stderr = _select([y.stderr for y in years], choice)
    head_year = None
    if heads is not None:  # modelled candidates (one state: no [shading]): what their heads report, group by group
        head_year = AH.YearLight(d, q, sun, _sky_share(skies), sun_bin, sun_scale)
        chans, val, se = AH.head_hourly(heads, a.sky_group, co, head_year)
        AH.apply_heads(heads, mean, val, stderr, se)
        df_h = AH.overcast_readings(heads, a.sky_group, df, _DF_SKY_LX)
        df_se = df_se * np.divide(df_h, df, out=np.ones_like(df), where=df > 0)
        df = df_h
        sun = AH.head_sun(heads, sun)  # the metrics' direct sun as the heads report it (head_year keeps the true one)
    t_hourly = time.perf_counter()

    # metrics and control, on the estimate and on each replicate year
    def figures(e: np.ndarray, cs: list, ch: np.ndarray, dfs: np.ndarray, hc=None):
        m = {z: zone_metrics(e[:, ids], sun[:, ids], occupied, daylight, dfs[ids], a, float(a.step_h)) for z, ids in zones.items()}
        ch_occ = ch[occupied]
        one = np.unique(ch_occ)
        one = int(one[0]) if len(one) == 1 else None
        ctl = []
        for ci, spec in enumerate(study.control):
            ids = zones[spec.zone]
            target = float(spec.target_lx if spec.target_lx is not None else dict(study.zone[[z.name for z in study.zone].index(spec.zone)].targets)["mean"])
            gsel = [lamp_groups.index(g) for g in spec.groups]
            lamps_s = [AH.lamp_readings(heads, c.lamp, lamp_groups, gsel) for c in cs]  # full output, as each sensor reads it
            e_zones = [float(np.mean(ls[ids])) for ls in lamps_s]
            e_zone = e_zones[one] if one is not None else np.asarray(e_zones)[ch_occ]
            day = e[occupied][:, ids].mean(axis=1)
            d_ov = float(np.mean(dfs[ids])) * _DF_SKY_LX
            per = []
            for k in pools[ci]:
                if k in devices:  # a modelled photosensor with electronics (one state): the control reads its device
                    per.append(_device_outcome(spec, k, cs[0], hc, gsel, d_ov, day, e_zone, target))
                    continue
                s_day = e[occupied][:, k]
                s_lamps = [float(ls[k]) for ls in lamps_s]
                s_lamp = s_lamps[one] if one is not None else np.asarray(s_lamps)[ch_occ]
                s_ov = float(dfs[k]) * _DF_SKY_LX
                gain = d_ov / s_ov if s_ov > 0 else 0.0
                u = CT.levels(spec.model, s_day, s_lamp, e_zone, target, spec.min_level, spec.deadband, gain)
                per.append(CT.outcome(u, day, e_zone, target))
            ctl.append((target, e_zones[0], per))
        return m, ctl

    def extras(e_by_state: list, ch: np.ndarray, idx_by_state: list):
        """The rows beyond a plain year's: the zones with the shades open all year and the operated ASE, the
        hours in each state, the views' glare figures."""
        out = {}
        if sh is not None:
            sun_ch = _select([y.sun for y in years], ch)
            for z, ids in zones.items():
                mo = zone_metrics(e_by_state[0][:, ids], sun[:, ids], occupied, daylight, df[ids], a, float(a.step_h))
                mc = zone_metrics(e_by_state[0][:, ids], sun_ch[:, ids], occupied, daylight, df[ids], a, float(a.step_h))
                out[(z, "DA_open")], out[(z, "sDA_open")], out[(z, "ASE_operated")] = mo["DA"], mo["sDA"], mc["ASE"]
            hrs = SH.state_hours(ch, occupied, len(states), float(a.step_h))
            for k, st in enumerate(states):
                out[(sh.variant_set, f"hours_{st.name}")] = float(hrs[k])
        if views:
            idx = _select(idx_by_state, ch)
            for v, view in enumerate(views):
                for key, val in glare_metrics(idx[:, v], occupied, a.glare_limit, float(a.step_h)).items():
                    out[(view.name, key)] = val
                if sh is not None:
                    out[(view.name, "GA_open")] = glare_metrics(idx_by_state[0][:, v], occupied, a.glare_limit, float(a.step_h))["GA"]
        return out

    devices = {} if heads is None else _devices(heads, cands, pools, study.seed, rows[occupied], len(weather))

    def _device_outcome(spec, k, c, hc, gsel, d_ov, day, e_zone, target):
        j, z = devices[k]
        m_, i_ = heads.models[j], int(heads.index[j])
        lamp_ch = AH.lamp_channels(heads, j, c.lamp[i_], lamp_groups, gsel)
        ov_ch = AH.overcast_channels(heads, j, a.sky_group, float(df_of(c)[i_]) * _DF_SKY_LX)
        o, _ = AH.control_outcome(spec, m_, AH.setting_of(cands[k].sensor), hc[j][:, occupied], lamp_ch, ov_ch, d_ov, day,
                                  e_zone, target, z)  # fmt: skip
        return o

    m0, ctl0 = figures(mean, [y.co for y in years], choice, df, None if heads is None else chans)
    x0 = extras([y.mean for y in years], choice, [y.index for y in years])
    reps_m = {z: {k: [] for k in m0[z]} for z in m0}
    reps_x = {k: [] for k in x0}
    reps_c = [[[] for _ in pools[i]] for i in range(len(study.control))]
    gens = [replicate_years(y.co, a.replicates, derive_seed(study.seed, "annual", "replicates", *([st.name] if k else [])))
            for k, (y, st) in enumerate(zip(years, states))]  # fmt: skip
    roots = [{k: _sqrt_psd(v) for k, v in (("outer_dir", y.shade.outer_dir_cov), ("outer_ind", y.shade.outer_ind_cov),
                                          ("shade", y.shade.shade_cov), ("eye", y.shade.eye_cov))} if y.shade is not None else {}
             for y in years]  # fmt: skip
    rngs = [np.random.default_rng(derive_seed(study.seed, "annual", "replicates", "shades and views", st.name)) for st in states]
    for _ in range(a.replicates):
        rcs = [next(g) for g in gens]
        e_rs, i_rs = [], []
        for k, (y, p) in enumerate(zip(years, plans)):
            e_k, i_k = _replicate_state(y, p, rcs[k], roots[k], rngs[k], d, q, q_patch, l_dome, sun_bin, sun_scale, cone, views,
                                        a.glare_index)  # fmt: skip
            e_rs.append(e_k)
            i_rs.append(i_k)
        ch_r = choose([y.sun for y in years], i_rs) if (sh is not None and sh.rule == "glare") else choice
        e_r = _select(e_rs, ch_r)
        if heads is None:
            m_r, c_r = figures(e_r, rcs, ch_r, df_of(rcs[0]))
        else:  # one state
            e_r = np.array(e_r, copy=True)
            hc_r, val_r, _ = AH.head_hourly(heads, a.sky_group, rcs[0], head_year, stderr=False)
            AH.apply_heads(heads, e_r, val_r)
            m_r, c_r = figures(e_r, rcs, ch_r, AH.overcast_readings(heads, a.sky_group, df_of(rcs[0]), _DF_SKY_LX), hc_r)
        for z in m_r:
            for k, v in m_r[z].items():
                reps_m[z][k].append(v)
        for i, (_, _, per) in enumerate(c_r):
            for j, o in enumerate(per):
                reps_c[i][j].append((o.relative_energy, o.hours_below, o.score) + _saturated(o))
        if x0:
            for k, v in extras(e_rs, ch_r, i_rs).items():
                reps_x[k].append(v)
    metrics = {z: {k: (v, float(np.std(reps_m[z][k], ddof=1))) for k, v in m0[z].items()} for z in m0}
    extra = {k: (v, float(np.std(reps_x[k], ddof=1))) for k, v in x0.items()}
    controls = []
    for i, spec in enumerate(study.control):
        target, e_zone, per = ctl0[i]
        rows_c = []
        for j, o in enumerate(per):
            r = np.asarray(reps_c[i][j])
            rows_c.append({"photosensor": cands[pools[i][j]].sensor.name, "relative_energy": o.relative_energy,
                           "relative_energy_stderr": float(np.std(r[:, 0], ddof=1)), "hours_below": o.hours_below,
                           "hours_below_stderr": float(np.std(r[:, 1], ddof=1)), "score": o.score,
                           "score_stderr": float(np.std(r[:, 2], ddof=1)), "scores": r[:, 2]})  # fmt: skip
            if _saturated(o):  # a device: the hours it saturated
                rows_c[-1].update(hours_saturated=o.saturated_hours, hours_saturated_stderr=float(np.std(r[:, 3], ddof=1)),
                                  target_tolerance_lx=o.target_tolerance_lx)
        best = min(range(len(rows_c)), key=lambda j: (rows_c[j]["score"], j))
        runner = min((j for j in range(len(rows_c)) if j != best), key=lambda j: (rows_c[j]["score"], j), default=None)
        lead = lead_se = None
        if runner is not None:
            diff = rows_c[runner]["scores"] - rows_c[best]["scores"]
            lead, lead_se = rows_c[runner]["score"] - rows_c[best]["score"], float(np.std(diff, ddof=1))
        for rc_ in rows_c:
            rc_.pop("scores")
        controls.append({"zone": spec.zone, "model": spec.model, "groups": list(spec.groups), "target_lx": target,
                         "lamps_zone_lx": e_zone, "occupied_hours": int(occupied.sum()), "chosen": rows_c[best]["photosensor"],
                         "runner_up": None if runner is None else rows_c[runner]["photosensor"], "lead": lead, "lead_stderr": lead_se,
                         "separable": runner is None or (lead is not None and lead > 2.0 * (lead_se or 0.0)),
                         "candidates": rows_c, "level": per[best].level})  # fmt: skip
    glare = None
    if views:
        glare = GlareYear([v.name for v in views], a.glare_index, _select([y.ev for y in years], choice),
                          _select([y.ev_se for y in years], choice), _select([y.index for y in years], choice),
                          _select([y.index_se for y in years], choice), GLARE_METRICS)  # fmt: skip
    t_end = time.perf_counter()
    return AnnualResult(weather, rows, occupied, daylight, skies, cands, mean, stderr, sun, df, df_se, metrics, controls,
                        timings_s={"weather_and_skies": t_weather - t0, "chunks": t_traced - t_weather, "hourly": t_hourly - t_traced,
                                   "metrics_and_control": t_end - t_hourly, "total": t_end - t0},
                        cpu_s={"total": time.process_time() - c0, "trace_in_chunks": trace_cpu,
                               "sun_shadow_rays": timing.get("sun_shadow_rays", 0.0), **({"views": timing["views"]} if "views" in timing else {})},
                        notes=notes, chunks_total=len(specs), chunks_computed=computed, coefficients=co, sky_levels=d,
                        zones=zones, scene=base, annual_spec=a, states=[st.name for st in states] if sh is not None else [],
                        state=choice if sh is not None else None, shading=sh, extra=extra, glare=glare,
                        traces={(st.name or "stage"): p.traces() for st, p in zip(states, plans)},
                        detail={"states": states, "plans": plans, "years": years, "dome": dome},
                        sensor_models={} if heads is None else heads.record(cands))  # fmt: skip
