"""What an expected-value function sees, and how a case's config is read."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from simulator.config.loader import RunConfig, load_config
from simulator.errors import UserError
from simulator.scene.model import Light, LightKind, Scene, Sensor

__all__ = ["CaseContext", "ExpectedFn", "NoteFn", "one_light", "no_closed_form", "read_config"]


@dataclass
class CaseContext:
    """A case's config and scene, as read, its sensors, and a way to read
    another config's scene (a case that must match another)."""

    cfg: RunConfig
    scene: Scene
    configs_dir: Path
    sensors: list[Sensor] = field(default_factory=list)
    _refs: dict = field(default_factory=dict)

    def reference_scene(self, config_name: str) -> Scene:
        """The scene of another bundled config, read in this case's light units."""
        key = (config_name, self.cfg.light_units)
        if key not in self._refs:
            from simulator.pipeline import load_scene

            ref = load_config(self.configs_dir / config_name)
            self._refs[key] = load_scene(dataclasses.replace(ref, light_units=self.cfg.light_units))
        return self._refs[key]


#: (context, sensor, channel) → expected reading, the quantity the kernel
#: estimates: irradiance (W/m², lx), radiance (W m⁻² sr⁻¹, cd/m²) or, for a
#: patch, its mean irradiance; channel 0 radiometric, 1 photometric
ExpectedFn = Callable[[CaseContext, Sensor, int], float]
#: (context, sensor, channel) → a short comment for a table ("" for none)
NoteFn = Callable[[CaseContext, Sensor, int], str]


def one_light(scene: Scene, kind: LightKind) -> Light:
    """The scene's only light of ``kind`` (UserError if there is not exactly one)."""
    lights = [l for l in scene.lights if l.kind == kind]
    if len(lights) != 1:
        raise UserError(f"{scene.path}: the reference case expects exactly one {kind.name} light, found {len(lights)}")
    return lights[0]


def no_closed_form(ctx: CaseContext, s: Sensor, why: str) -> UserError:
    """The error for a receiver a case has no closed form for."""
    return UserError(f"{ctx.cfg.path}: {s.name}: no closed form for this receiver ({why})")


def read_config(path: Path, light_units: str | None = None, variants: tuple[tuple[str, str], ...] = ()):
    """``(cfg, scene, sensors)`` of a config, with its light units and variant selections overridden."""
    from simulator.pipeline import collect_sensors, load_scene

    cfg = load_config(path)
    if light_units is not None:
        cfg = dataclasses.replace(cfg, light_units=light_units)
    if variants:
        cfg = dataclasses.replace(cfg, variants={**cfg.variants, **dict(variants)})
    scene = load_scene(cfg)
    return cfg, scene, collect_sensors(cfg, scene)
