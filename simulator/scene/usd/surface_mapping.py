"""What the MaterialX and MDL readers share: a surface's inputs read with their defaults, and the formulas.

:class:`SurfaceInputs` reads a surface shader's inputs (a :class:`.shading_graph.Node`)
against the model's defaults, and at the end names every input that was
authored away from its default but is not mapped (:meth:`SurfaceInputs.finish`):
nothing the author set is dropped without a word. The result of a mapping is
the dict ``{UsdPreviewSurface input name: (value, where)}`` that
:func:`simulator.scene.usd.materials._preview_surface_inputs` returns for a
UsdPreviewSurface; :func:`count_carried` counts, under the existing "ignored"
summary, the mapped inputs today's surfaces do not model yet.
"""

from __future__ import annotations

import math

import numpy as np

from simulator.units import luminance_grey
from simulator.scene.usd.context import _Context
from simulator.scene.usd.shading_graph import Node, NotUniform, Port, Value, as_array, port_value

#: UsdPreviewSurface inputs probesim does not model, with their fallbacks: an input authored (or
#: connected, or mapped from a MaterialX/MDL surface) away from its fallback is counted as ignored
IGNORED_PREVIEW_DEFAULTS = {
    "normal": (0.0, 0.0, 1.0),
    "displacement": 0.0,
    "occlusion": 1.0,
}

class SurfaceInputs:
    """A surface node's inputs, evaluated to uniform values, with the model's defaults.

    Parameters
    ----------
    ctx : _Context
        The reading context (warnings, textures).
    node : Node
        The surface shader node.
    defaults : dict
        Every input the model has that can change a reading, with its default
        (numbers, colours as tuples, booleans, ints).
    model : str
        The model's name for messages (``standard_surface``, ``OmniPBR``, ...).
    """

    def __init__(self, ctx: _Context, node: Node, defaults: dict, model: str) -> None:
        self.ctx, self.node, self.defaults, self.model = ctx, node, defaults, model
        self._read: set[str] = set()
        self._cache: dict[str, Value | None] = {}

    def _value(self, name: str) -> Value | None:
        """The authored value of ``name`` (None when not authored or not uniform, then named)."""
        if name not in self._cache:
            port = self.node.inputs.get(name)
            value = None
            if port is not None and (port.node is not None or port.value is not None):
                try:
                    value = port_value(self.ctx, port)
                except NotUniform as why:
                    self.ctx.ignored[f"inputs:{name} of {self.model} {why} (its default used)"] += 1
                else:
                    for note in value.notes:
                        self.ctx.ignored[note] += 1
                    if value.textured:
                        self.ctx.textured[name] += 1
            self._cache[name] = value
        return self._cache[name]

    def get(self, name: str) -> np.ndarray:
        """The uniform value of input ``name`` (a float array), its default where not authored or not uniform."""
        self._read.add(name)
        v = self._value(name)
        return v.value if v is not None else as_array(self.defaults[name])

    def scalar(self, name: str) -> float:
        """Input ``name`` as one number (a colour's BT.709 grey)."""
        v = self.get(name)
        return float(v[0]) if v.size == 1 else float(luminance_grey(v[:3]))

    def flag(self, name: str) -> bool:
        """A boolean input (authored as bool, int or float)."""
        self._read.add(name)
        port = self.node.inputs.get(name)
        value = port.value if port is not None and port.node is None and port.value is not None else self.defaults[name]
        return bool(np.asarray(value).ravel()[0]) if not isinstance(value, str) else value.lower() == "true"

    def token(self, name: str) -> str:
        """A token or string input (``opacityMode``, ...), its default where not authored."""
        self._read.add(name)
        port = self.node.inputs.get(name)
        value = port.value if port is not None and port.node is None and port.value is not None else self.defaults[name]
        return str(value)

    def asset(self, name: str) -> Port | None:
        """A file input (MDL ``texture_2d``) as its port, None when not authored or empty."""
        self._read.add(name)
        port = self.node.inputs.get(name)
        return port if port is not None and port.node is None and isinstance(port.value, str) and port.value else None

    def authored(self, name: str) -> bool:
        """Whether ``name`` is authored (a value or a connection) on the node."""
        port = self.node.inputs.get(name)
        return port is not None and (port.node is not None or port.value is not None)

    def where(self, name: str) -> str:
        """Where input ``name``'s value comes from (an attribute path, a texture, or "(default)")."""
        port = self.node.inputs.get(name)
        if port is not None and port.node is None and isinstance(port.value, str):
            return port.where  # a file or a token: no uniform number to evaluate
        v = self._value(name) if self.authored(name) else None
        return v.where if v is not None else f"{self.node.where}.inputs:{name} (default)"

    def is_default(self, name: str, tol: float = 1e-6) -> bool:
        """Whether ``name`` reads its default (not authored, or authored at it, or not uniform)."""
        if not self.authored(name):
            return True
        port = self.node.inputs[name]
        if port.node is None and not isinstance(port.value, (int, float, tuple, list, np.ndarray, bool)):
            return str(port.value) == str(self.defaults.get(name))
        v = self._value(name)
        if v is None:
            return True
        d = as_array(self.defaults[name]) if not isinstance(self.defaults[name], str) else None
        return d is not None and d.size == v.value.size and bool(np.allclose(v.value, d, rtol=0, atol=tol))

    def textured(self, name: str) -> bool:
        """Whether input ``name``'s value is (or holds) a texture mean."""
        v = self._value(name) if self.authored(name) else None
        return v is not None and v.textured

    def products(self, *pairs: tuple[str, str]) -> None:
        """Name each product the mapping forms of two textured inputs: ``mean(a·b)`` is ``mean(a)·mean(b)``
        only when the two textures are uncorrelated, so the reading is an approximation there."""
        for a, b in pairs:
            if self.textured(a) and self.textured(b):
                self.ctx.ignored[f"{self.model} {a} x {b} of two textures (read as the product of their means)"] += 1

    def inert(self, *names: str) -> None:
        """Mark inputs that change nothing here (emission inputs with emission off, a coat's roughness
        without a coat): read, so not named."""
        self._read.update(names)

    def not_mapped(self, name: str, why: str = "not mapped") -> None:
        """Name an input authored away from its default that the mapping cannot represent."""
        self._read.add(name)
        if not self.is_default(name):
            self.ctx.ignored[f"inputs:{name} of {self.model} ({why})"] += 1

    def finish(self) -> None:
        """Name every input authored away from its default that no mapping read (one count per input)."""
        for name, port in self.node.inputs.items():
            if name in self._read or name.startswith(("info:", "ui", "doc")):
                continue
            if name not in self.defaults:
                if port.node is not None or port.value is not None:
                    self.ctx.ignored[f"inputs:{name} of {self.model} (not mapped)"] += 1
                continue
            self.not_mapped(name)


def colour(v: np.ndarray) -> tuple[float, float, float]:
    """A value as an RGB tuple (a float broadcast to grey)."""
    v = np.asarray(v, float).ravel()
    return (float(v[0]),) * 3 if v.size == 1 else (float(v[0]), float(v[1]), float(v[2]))


def nits_in_light_units(ctx: _Context, nits: np.ndarray) -> np.ndarray:
    """A luminance in cd/m² as an ``emissiveColor`` in the stage's light units.

    With photometric light units ``emissiveColor`` *is* cd/m²; with radiometric
    ones it is W m⁻² sr⁻¹ of the run's emitter spectrum, ``L_e = L_v / K`` with
    ``K`` that spectrum's luminous efficacy (D65: 205.15 lm/W; equal energy:
    182.46 lm/W). ``ctx.emission(1)`` is ``(radiometric, photometric)`` of one
    unit, so one unit is ``ctx.emission(1)[1]`` cd/m².
    """
    return np.asarray(nits, float) / ctx.emission(1.0)[1]


def slab_transmittance(tau: float, ior: float) -> float:
    """Normal-incidence transmittance of an absorbing thin slab: ``(1 − R)² τ / (1 − R² τ²)``.

    ``R = ((n − 1)/(n + 1))²`` is one interface's normal reflectance and ``τ``
    the internal (one-pass) transmittance; the inner reflections are summed
    incoherently (docs/REFERENCES.md §Absorbing thin slab).
    """
    r = ((ior - 1.0) / (ior + 1.0)) ** 2
    return (1.0 - r) ** 2 * tau / (1.0 - (r * tau) ** 2)


def ior_of_f0(f0: float) -> float:
    """The index of refraction whose normal reflectance in air is ``f0``: ``n = (1 + √F0)/(1 − √F0)``."""
    s = math.sqrt(min(max(f0, 0.0), 0.999999))
    return (1.0 + s) / (1.0 - s)


def transmission(out: dict, ins: SurfaceInputs, weight_name: str, tint_name: str, ior: float) -> None:
    """Map a transmission weight and colour onto ``opacity`` (and ``probesim:transmittance``).

    UsdPreviewSurface in its transparent opacity mode scales the diffuse lobe
    by ``opacity`` and lets the rest through a dielectric of ``ior``, so a
    transmission weight ``t`` is ``opacity = 1 − t``. A tinted transmission
    (colour ``c``, grey ``τ = Y(c) < 1``) of a fully transmitting surface is the
    datasheet transmittance of a thin slab with internal transmittance ``τ``:
    ``probesim:transmittance = (1 − R)² τ / (1 − R² τ²)``
    (:func:`slab_transmittance`); a tint on a partial transmission is named.
    Call it after every other use of ``tint_name`` (without transmission the
    tint is marked as changing nothing).
    """
    weight = ins.scalar(weight_name)
    if weight <= 0.0:
        ins.inert(tint_name)  # a transmission colour without transmission changes nothing
        return
    out["opacity"] = (max(0.0, 1.0 - weight), f"1 - {ins.where(weight_name)}")
    tau = ins.scalar(tint_name)
    if tau < 1.0 - 1e-6:
        if weight >= 1.0 - 1e-6:
            out["probesim:transmittance"] = (slab_transmittance(max(tau, 0.0), ior),
                                             f"a thin slab of internal transmittance {tau:g} ({ins.where(tint_name)})")
        else:
            ins.not_mapped(tint_name, "a tint on a partial transmission")


def thin_walled(out: dict, ins: SurfaceInputs, name: str) -> None:
    """Map a thin-walled flag onto ``_thin_walled``: a glass (any transmission mapped to ``opacity``
    < 1) whose every face is a thin sheet, also on a closed mesh, where a solid (the flag's default)
    is a slab-like body entered once (:mod:`simulator.scene.surfaces`). Without transmission the
    flag changes nothing."""
    if ins.flag(name) and out.get("opacity", (1.0, ""))[0] < 1.0:
        out["_thin_walled"] = (True, ins.where(name))


def complete(ctx: _Context, inputs: dict, where: str) -> dict:
    """A mapping's inputs with UsdPreviewSurface's fallbacks for the three every surface reads
    (``diffuseColor`` 0.18, ``emissiveColor`` 0, ``opacity`` 1) where it set none, and the carried inputs
    counted (:func:`count_carried`)."""
    for name, value in (("diffuseColor", (0.18, 0.18, 0.18)), ("emissiveColor", (0.0, 0.0, 0.0)), ("opacity", 1.0)):
        inputs.setdefault(name, (value, f"{where} (default {name})"))
    count_carried(ctx, inputs)
    return inputs


def count_carried(ctx: _Context, inputs: dict) -> None:
    """Count, as "ignored", the mapped inputs the surfaces do not model (those UsdPreviewSurface's own
    reader counts: :data:`IGNORED_PREVIEW_DEFAULTS`), where they differ from the
    value that changes nothing. The cut-out and glazing inputs are modelled (:mod:`simulator.scene.surfaces`)."""
    for name, (value, _) in inputs.items():
        if name in IGNORED_PREVIEW_DEFAULTS:
            default = IGNORED_PREVIEW_DEFAULTS[name]
            if not np.allclose(np.asarray(value, float), np.asarray(default, float), rtol=0, atol=1e-6):
                ctx.ignored[f"inputs:{name}"] += 1
