"""Scenarios: named dimming vectors over the light groups, with a sun and variant selections.

A ``[[scenario]]`` whose levels hold lists expands into the product of
them (``name[window_row=0.5,corridor_row=1]``). Scenarios that share the
same variant selections and sun direction form a *trace group*: one scene
whose light groups are traced once and recombined for each scenario of the
group (:mod:`simulator.study.groups`). A sun at or below the horizon
contributes nothing: its level is set to 0 in that scenario (and said so).
"""

from __future__ import annotations

import itertools
from pathlib import Path
from dataclasses import dataclass, field


from simulator.errors import UserError
from simulator.scene.model import LightKind, Scene
from simulator.study.candidates import match_prims
from simulator.study.schema import GroupSpec, ScenarioSpec
from simulator.study.sun import solar_position

__all__ = ["Scenario", "TraceGroup", "expand_scenarios", "resolve_groups", "trace_groups_of"]


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


def expand_scenarios(specs: list[ScenarioSpec], group_names: list[str], file_label: str, log=print) -> list[Scenario]:
    """Every scenario, list-valued levels expanded into their product, in file order."""
    out: list[Scenario] = []
    seen: set[str] = set()
    for k, sp in enumerate(specs):
        sun = None
        notes: list[str] = []
        if sp.sun is not None:
            if sp.sun.azimuth_deg is not None:
                sun = (float(sp.sun.azimuth_deg), float(sp.sun.elevation_deg))
            else:
                sun = solar_position(sp.sun.latitude_deg, sp.sun.longitude_deg, sp.sun.time, f"{file_label}: scenario[{k}].sun")
        listed = [(g, v) for g, v in sp.levels.items() if isinstance(v, list)]
        fixed = {g: float(v) for g, v in sp.levels.items() if not isinstance(v, list)}
        combos = itertools.product(*[v for _, v in listed]) if listed else [()]
        for combo in combos:
            levels = {g: 0.0 for g in group_names}
            levels.update(fixed)
            levels.update({g: float(x) for (g, _), x in zip(listed, combo)})
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
