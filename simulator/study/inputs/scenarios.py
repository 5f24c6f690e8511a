"""Scenarios: named dimming vectors over the light groups, with a sun and variant selections.

A ``[[scenario]]`` whose levels hold lists expands into the product of
them (``name[window_row=0.5,corridor_row=1]``). Scenarios that share the
same variant selections and sun direction form a *trace group*: one scene
whose light groups are traced once and recombined for each scenario of the
group (:mod:`simulator.study.trace.groups`). A sun at or below the horizon
contributes nothing: its level is set to 0 in that scenario (and said so).

A scenario's ``sky`` on a group split into sky patches (``[[group]] sky =
"tregenza"``) sets each patch's level ``group/pNNN`` to the group's level
times L_p / L_dome, the patch's mean luminance in the CIE sky over the
dome's authored luminance (:func:`simulator.study.inputs.sky_patches.sky_weights`),
and the ground slot ``group/ground`` to the group's level times ``ground``.
The sky's sun only shapes the sky's luminance: it does not enter the trace
key, so skies of any sun position share one trace of the patches (a
scenario's own ``sun`` still turns the DistantLight, as without a sky).
"""

from __future__ import annotations

import itertools
import math
from pathlib import Path
from dataclasses import dataclass, field

import numpy as np

from simulator.errors import UserError
from simulator.scene.model import LightKind, Scene
from simulator.study.inputs.candidates import match_prims
from simulator.study.schema import GroupSpec, ScenarioSpec, SkySpec, SunSpec
from simulator.study.inputs.sun import solar_position, sun_direction

__all__ = ["Scenario", "TraceGroup", "expand_scenarios", "resolve_groups", "trace_groups_of", "sky_levels", "check_split_groups",
           "dark_scenarios"]


@dataclass(frozen=True)
class Scenario:
    """One dimming vector under one sky and one set of variant selections.

    Attributes
    ----------
    levels : dict of str to float
        Every group's level (0 = off).
    sun : tuple of float or None
        ``(azimuth_deg, elevation_deg)``, None for the stage's own sun.
    variants : tuple of (str, str)
        Sorted variant selections.
    """

    name: str
    levels: dict
    sun: tuple[float, float] | None
    variants: tuple[tuple[str, str], ...]
    notes: tuple[str, ...] = ()

    @property
    def trace_key(self) -> str:
        sun = "stage" if self.sun is None else f"{self.sun[0]:.6f},{self.sun[1]:.6f}"
        var = ",".join(f"{a}={b}" for a, b in self.variants) or "-"
        return f"variants:{var};sun:{sun}"


@dataclass
class TraceGroup:
    """Scenarios traced on one scene; ``groups`` are the light groups any of them lights."""

    key: str
    variants: dict
    sun: tuple[float, float] | None
    scenarios: list[Scenario] = field(default_factory=list)
    groups: list[str] = field(default_factory=list)


def _fmt_level(x: float) -> str:
    return f"{x:g}"


def _sun_of(spec: SunSpec, key: str) -> tuple[float, float]:
    if spec.azimuth_deg is not None:
        return float(spec.azimuth_deg), float(spec.elevation_deg)
    return solar_position(spec.latitude_deg, spec.longitude_deg, spec.time, key)


def sky_levels(sky: SkySpec, sun: tuple[float, float] | None, scene: Scene | None, groups: dict[str, list[str]] | None,
               key: str) -> tuple[dict[str, float], str]:  # fmt: skip
    """Patch levels ``group/pNNN`` and ``group/ground`` of a scenario's sky (per unit of the group's level), and a note.

    The sky's sun: ``sky.sun``, else the scenario's ``sun``, else the stage's
    DistantLight. Raises UserError for a sky that needs a sun and has none, or
    a split group that is not one DomeLight."""
    from simulator.study.inputs import sky_patches as SP
    from simulator.study.trace.groups import patch_names

    if sky.sun is not None:
        sun = _sun_of(sky.sun, f"{key}.sun")
    direction = None
    if sun is not None:
        direction = sun_direction(*sun)
    elif scene is not None:
        distant = [l for l in scene.lights if l.kind == LightKind.DISTANT]
        if len(distant) == 1:
            direction = np.asarray(distant[0].frame, float)[:, 2]
    needs_sun = sky.cie not in ("overcast", "uniform") and (SP.CIE_TYPES[int(sky.cie)][2] != 0.0 or SP.CIE_TYPES[int(sky.cie)][4] != 0.0)
    if needs_sun and direction is None:
        raise UserError(f"{key}: CIE sky type {sky.cie} depends on the sun: give sky.sun or the scenario's sun "
                        "(the stage has no single DistantLight)")  # fmt: skip
    scale = math.pi
    if sky.horizontal_lx is not None:
        dome = _split_dome(scene, groups, sky.group, key) if scene is not None else None
        if dome is None or dome.emission[1] <= 0:
            raise UserError(f"{key}.horizontal_lx: group {sky.group!r} has no DomeLight with a luminance to scale")
        scale = float(sky.horizontal_lx) / float(dome.emission[1])
    w = SP.sky_weights(sky.cie, direction, scale)
    names = patch_names(sky.group)
    levels = {n: float(x) for n, x in zip(names[:-1], w)}
    levels[names[-1]] = float(sky.ground)
    what = "uniform sky" if sky.cie == "uniform" else ("CIE overcast sky" if sky.cie == "overcast" else f"CIE sky type {sky.cie}")
    note = f"{what} on {sky.group!r} (Tregenza patches)"
    if needs_sun and sun is not None:
        note += f", sun at azimuth {sun[0]:.1f} deg, elevation {sun[1]:.1f} deg"
    return levels, note


def _split_dome(scene: Scene, groups: dict[str, list[str]] | None, group: str, key: str):
    """The one DomeLight of a split sky group (UserError otherwise)."""
    names = (groups or {}).get(group, [])
    domes = [l for l in scene.lights if l.name in names and l.kind == LightKind.DOME]
    if len(names) != 1 or len(domes) != 1:
        raise UserError(f"{key}: group {group!r} has sky = \"tregenza\" and must hold exactly one DomeLight, "
                        f"holds {', '.join(names) or 'none'}")  # fmt: skip
    return domes[0]


def check_split_groups(scene: Scene, specs: list[GroupSpec], groups: dict[str, list[str]], file_label: str) -> tuple[str, ...]:
    """Names of the groups whose sky is split into patches, each checked to be one DomeLight."""
    out = []
    for k, g in enumerate(specs):
        if g.sky is not None:
            _split_dome(scene, groups, g.name, f"{file_label}: group[{k}]")
            out.append(g.name)
    return tuple(out)


def expand_scenarios(specs: list[ScenarioSpec], group_names: list[str], file_label: str, log=print, scene: Scene | None = None,
                     groups: dict[str, list[str]] | None = None) -> list[Scenario]:  # fmt: skip
    """Every scenario, list-valued levels expanded into their product, in file order.

    ``scene`` and ``groups`` are needed only by a scenario's ``sky`` with
    ``horizontal_lx`` (the dome's luminance) or without a sun of its own (the stage's)."""
    out: list[Scenario] = []
    seen: set[str] = set()
    for k, sp in enumerate(specs):
        sun = None
        notes: list[str] = []
        if sp.sun is not None:
            sun = _sun_of(sp.sun, f"{file_label}: scenario[{k}].sun")
        patch = {}
        if sp.sky is not None:
            patch, note = sky_levels(sp.sky, sun, scene, groups, f"{file_label}: scenario[{k}].sky")
            notes.append(note)
        listed = [(g, v) for g, v in sp.levels.items() if isinstance(v, list)]
        fixed = {g: float(v) for g, v in sp.levels.items() if not isinstance(v, list)}
        combos = itertools.product(*[v for _, v in listed]) if listed else [()]
        for combo in combos:
            levels = {g: 0.0 for g in group_names}
            levels.update(fixed)
            levels.update({g: float(x) for (g, _), x in zip(listed, combo)})
            if patch:
                lv = levels.get(sp.sky.group, 0.0)
                levels.update({n: lv * x for n, x in patch.items()})
            name = sp.name if not listed else f"{sp.name}[{','.join(f'{g}={_fmt_level(x)}' for (g, _), x in zip(listed, combo))}]"
            if name in seen:
                raise UserError(f"{file_label}: scenario[{k}]: scenario name {name!r} is used twice")
            seen.add(name)
            out.append(Scenario(name, levels, sun, tuple(sorted(sp.variants.items())), tuple(notes)))
    return out


def _collection_members(scene: Scene, spec: GroupSpec, names: list[str], key: str, file_label: str) -> list[int]:
    """Indices into ``names`` of the lights the group's USD collection includes (resolved by the stage reader)."""
    c = spec.collection
    if c not in scene.collections:
        have = ", ".join(scene.collections) or "none"
        raise UserError(f"{file_label}: {key}: no collection {c!r} in the stage {Path(scene.path).name} (collections: {have})")
    members = set(scene.collections[c])
    ids = [i for i, n in enumerate(names) if n in members]
    if not ids:
        raise UserError(f"{file_label}: {key}: collection {c!r} includes no light")
    return ids


def resolve_groups(scene: Scene, specs: list[GroupSpec], file_label: str) -> tuple[dict[str, list[str]], list[str]]:
    """Light prim paths per group, and the scene's lights in no group.

    A group's ``lights`` are prim paths or fnmatch patterns; its
    ``collection`` a USD collection, ``/prim.collection:name``, whose
    membership the stage reader resolved (``Scene.collections``).

    Raises
    ------
    UserError
        A pattern that matches no light, a collection the stage does not
        have or that includes no light, or a light in two groups.
    """
    names = [l.name for l in scene.lights]
    owner: dict[str, str] = {}
    out: dict[str, list[str]] = {}
    for k, g in enumerate(specs):
        lights: list[str] = []
        found = []
        for j, pat in enumerate(g.lights):
            ids = match_prims(names, pat)
            if not ids:
                raise UserError(f"{file_label}: group[{k}].lights[{j}]: no light matches {pat!r} "
                                f"(lights: {', '.join(names) or 'none'})")  # fmt: skip
            found.append((f"group[{k}].lights[{j}]", ids))
        if g.collection is not None:
            found.append((f"group[{k}].collection", _collection_members(scene, g, names, f"group[{k}].collection", file_label)))
        for key, ids in found:
            for i in ids:
                if names[i] in owner and owner[names[i]] != g.name:
                    raise UserError(f"{file_label}: {key}: {names[i]} is already in group {owner[names[i]]!r}")
                owner[names[i]] = g.name
                if names[i] not in lights:
                    lights.append(names[i])
        out[g.name] = lights
    return out, [n for n in names if n not in owner]


def trace_groups_of(scenarios: list[Scenario], scene: Scene, groups: dict[str, list[str]], file_label: str) -> list[TraceGroup]:
    """Scenarios gathered by trace key (first-use order), a sun below the horizon switched off.

    Raises
    ------
    UserError
        A scenario gives a sun but the stage has no DistantLight, or more than one.
    """
    distant = [l.name for l in scene.lights if l.kind == LightKind.DISTANT]
    tgs: dict[str, TraceGroup] = {}
    fixed: list[Scenario] = []
    for sc in scenarios:
        if sc.sun is not None:
            if len(distant) != 1:
                raise UserError(f"{file_label}: scenario {sc.name!r}: a sun position needs exactly one DistantLight in the stage, "
                                f"found {len(distant)}")  # fmt: skip
            if sc.sun[1] <= 0.0:
                sun_groups = [g for g, ls in groups.items() if distant[0] in ls]
                levels = dict(sc.levels)
                for g in sun_groups:
                    levels[g] = 0.0
                sc = Scenario(sc.name, levels, sc.sun, sc.variants, sc.notes + (f"sun below the horizon (elevation {sc.sun[1]:.1f} deg): off",))
        fixed.append(sc)
        tg = tgs.setdefault(sc.trace_key, TraceGroup(sc.trace_key, dict(sc.variants), sc.sun))
        tg.scenarios.append(sc)
    for tg in tgs.values():
        tg.groups = [g for g in groups if any(s.levels.get(g, 0.0) > 0.0 for s in tg.scenarios)]
    scenarios[:] = fixed
    return list(tgs.values())


def dark_scenarios(scenarios: list[Scenario], scene: Scene, groups: dict[str, list[str]]) -> list[str]:
    """One warning per scenario in which nothing is lit: every group's level is 0 (or the sun below the
    horizon turned its group off), or the groups it lights hold only lights that emit 0. Its readings are
    all 0, and a zone's "pass" on them means nothing."""
    emits = {l.name for l in scene.lights if max(l.emission) > 0.0}
    out = []
    for sc in scenarios:
        plain = {g: v for g, v in sc.levels.items() if "/" not in g}  # not a sky's patch slots
        lit = [g for g, v in plain.items() if v > 0.0]
        if any(n in emits for g in lit for n in groups.get(g, [])):
            continue
        why = ("every level is 0" if not lit else
               f"its lit group(s) {', '.join(repr(g) for g in lit)} hold only lights that emit 0")
        off = [n for n in sc.notes if "below the horizon" in n]
        out.append(f"scenario {sc.name!r}: nothing is lit ({why}{'; ' + off[0] if off else ''}): every reading is 0")
    return out
