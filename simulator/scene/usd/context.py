"""What every part of the stage reader shares: the reading context and attribute values.

:class:`_Context` carries the file name for messages, the time code, the
stage -> world map, the light units and the warnings gathered so far;
:func:`_get` reads an attribute's value the way the stage states it.
"""

from __future__ import annotations

import os
from collections import Counter
from dataclasses import dataclass, field

import numpy as np
from pxr import Usd, UsdGeom

from simulator.errors import UserError
from simulator.units import NAMED_EFFICACY, emission_pair

# How many prim paths a summary warning names before "and N more".
_MAX_NAMED = 10


@dataclass
class _Context:
    """What every helper needs: the file name for messages, time, world map, units."""

    path: str
    time: Usd.TimeCode
    to_world: np.ndarray  # 3x3: metersPerUnit * (up-axis rotation)
    light_units: str
    default_spectrum: str | float
    xforms: UsdGeom.XformCache | None = None
    warnings: list[str] = field(default_factory=list)
    coloured: dict[str, None] = field(default_factory=dict)  # ordered set of prim paths
    materials: dict[str, dict] = field(default_factory=dict)  # material path -> raw inputs
    #: prims not read, by type name ("3 BasisCurves"): one summary warning at the end
    not_read: Counter = field(default_factory=Counter)
    #: attributes that would change the reading but are ignored, by name ("5 x inputs:roughness")
    ignored: Counter = field(default_factory=Counter)
    #: textured inputs read as their texture's mean, by input name; texture files read
    textured: Counter = field(default_factory=Counter)
    textures: dict[str, object] = field(default_factory=dict)  # resolved texture path -> mean RGB or None
    #: prims with albedo exactly 1 (ordered set of paths)
    white: dict[str, None] = field(default_factory=dict)
    #: meshes with an authored subdivisionScheme other than none, read as their cage
    subdivided: Counter = field(default_factory=Counter)
    #: measured reflectances read (``probesim:reflectance``): (file name, ρ on the grid); by resolved path
    reflectances: list = field(default_factory=list)
    reflectance_index: dict[str, int] = field(default_factory=dict)
    #: spectra of emitting triangles, ``(spectrum or None for the default, authored)`` (ordered set)
    emissive_spectra: dict = field(default_factory=dict)
    #: legacy (pre-``inputs:``) UsdLux attributes read, legacy name -> prims (ordered set), see :mod:`.legacy`
    legacy: dict = field(default_factory=dict)
    #: the stage's composition errors (unresolved references, ...), one message each
    composition_errors: list = field(default_factory=list)
    #: pxr's own diagnostics caught while the stage was read (:mod:`.diagnostics`)
    pxr_messages: list = field(default_factory=list)
    #: the run gave a time code (``time`` / ``--time``); False: each attribute's earliest sample
    time_given: bool = False
    #: prims read whose reading changes with time, when no time was given (ordered set, :mod:`.animation`)
    animated: dict = field(default_factory=dict)
    moving: dict = field(default_factory=dict)  # prim path -> its transform (or an ancestor's) may vary
    #: UsdSkel: one ``UsdSkel.Cache`` and, per SkelRoot path, its skinning targets (:mod:`.skinning`)
    skel_cache: object | None = None
    skel_roots: dict = field(default_factory=dict)

    #: surfaces beyond Lambert (:class:`simulator.scene.surfaces.Surface`), one per material; by material key
    surfaces: list = field(default_factory=list)
    surface_index: dict = field(default_factory=dict)
    #: opacity textures read per texel (:class:`simulator.scene.surfaces.CoverageTexture`); by what reads them
    coverage_textures: list = field(default_factory=list)
    coverage_texture_index: dict = field(default_factory=dict)

    def summary_parts(self) -> list[str]:
        """Parts of the stage's one summary warning line beyond what was not read or ignored."""
        parts = []
        if self.legacy:
            names = ", ".join(f"{len(prims)} x {name}" for name, prims in sorted(self.legacy.items()))
            parts.append(f"legacy UsdLux attributes (no inputs: prefix) read: {names}")
        if self.animated:
            names = list(self.animated)
            parts.append(f"{len(names)} animated prim(s) read at each attribute's earliest time sample, not one "
                         f"frame ({_name_list(names)}): give the time code to read in the config (time = ...) "
                         "or with --time")
        if self.composition_errors:
            n = len(self.composition_errors)
            parts.append(f"{n} composition error{'s' * (n > 1)} (first: {_clip(self.composition_errors[0])})")
        # pxr reports each composition error as a warning too: count only the others
        others = [m for m in self.pxr_messages if not any(c in m for c in self.composition_errors)]
        if others:
            n = len(others)
            parts.append(f"{n} pxr diagnostic{'s' * (n > 1)} (first: {_clip(others[0])})")
        return parts

    def warn(self, message: str) -> None:
        if message not in self.warnings:
            self.warnings.append(message)

    def error(self, prim: Usd.Prim | str, message: str) -> UserError:
        return UserError(f"{self.path}: {prim if isinstance(prim, str) else prim.GetPath()}: {message}")

    def emission(self, value: float, spectrum: str | float | None = None) -> tuple[float, float]:
        """``(radiometric, photometric)`` pair of an emission ``value`` in the stage's light units.

        ``spectrum`` defaults to the run's (D65 photometric, else
        ``radiometric_spectrum``); a value that is not positive emits
        nothing, ``(0, 0)``.
        """
        spectrum = self.default_spectrum if spectrum is None else spectrum
        if value <= 0:
            return (0.0, 0.0)
        if isinstance(spectrum, str) and spectrum not in NAMED_EFFICACY:  # an illuminant or SPD file
            from simulator.spectra.sources import emitter_spectrum

            k = emitter_spectrum(spectrum).efficacy_lm_W
            return (value / k, value) if self.light_units == "photometric" else (value, value * k)
        return emission_pair(value, self.light_units, spectrum)


def _layer_relative(attr: Usd.Attribute, authored: str) -> str:
    """A path an attribute states, resolved against the folder of the layer that authors its strongest
    opinion (an asset path the resolver did not find, or a string); absolute paths are kept."""
    if os.path.isabs(authored):
        return authored
    for spec in attr.GetPropertyStack(Usd.TimeCode.Default()):
        if spec.layer is not None and spec.layer.realPath:
            return os.path.normpath(os.path.join(os.path.dirname(spec.layer.realPath), authored))
    return os.path.abspath(authored)


def _get(ctx: _Context, attr: Usd.Attribute):
    """An attribute's value with ``float`` (32-bit) numbers read as the decimals authored.

    ``float inputs:width = 1.2`` is stored as 1.2000000476837158; the shortest
    decimal that round-trips in float32 (numpy's ``str``) gives back 1.2, so
    closed-form checks see the numbers the stage states. Other types pass
    through unchanged (tuples for vectors).
    """
    value = attr.Get(ctx.time)
    if value is None:
        return None
    is_f32 = attr.GetTypeName().scalarType.type.typeName in ("float", "GfVec2f", "GfVec3f", "GfVec4f")
    if hasattr(value, "__len__") and not isinstance(value, str):
        return tuple(_decimal_f32(v) if is_f32 else v for v in value)
    return _decimal_f32(value) if is_f32 else value


def _decimal_f32(v) -> float:
    # the shortest decimal that round-trips in float32; format_float_positional
    # with unique=True ignores numpy's global print options (which other
    # packages may switch to a 6-digit legacy mode)
    return float(np.format_float_positional(np.float32(v), unique=True, trim="-"))


def _not_uniform(spread: float, largest: float) -> bool:
    """True when values spread (max - min) by more than 1e-6 of the largest: a real difference, not float noise.

    Used for colours (a colour that is not grey) and axis scales (a round
    shape scaled non-uniformly); the 1e-300 floor keeps all-zero values uniform.
    """
    return spread > 1e-6 * max(largest, 1e-300)


def _clip(message: str, limit: int = 240) -> str:
    """A message cut to ``limit`` characters for a summary line."""
    return message if len(message) <= limit else message[: limit - 3] + "..."


def _name_list(names: list[str]) -> str:
    shown = ", ".join(names[:_MAX_NAMED])
    more = len(names) - _MAX_NAMED
    return shown + (f" and {more} more" if more > 0 else "")
