"""``[[sensor]]`` entries: one schema model per sensor kind, chosen by ``kind``.

Each kind's model lists the keys that kind takes (beside ``name``, ``kind``
and ``position``, which every kind has) and builds its
:class:`~simulator.scene.model.Sensor`. :data:`SensorEntry` is the
discriminated union of them on ``kind``; a new kind is one more model in
:data:`SENSOR_ENTRIES`.

::

    [[sensor]]            # irradiance | radiance | patch | probe | cylindrical | semicylindrical | glare
    name = "desk"         # default: "sensor[<index>]"
    kind = "irradiance"
    position = [0, 0, 0.75]   # metres
    normal = [0, 0, 1]
"""

from __future__ import annotations

import math
from typing import Annotated, Any, ClassVar, Literal, Union, get_args

import numpy as np
from pydantic import AfterValidator, BeforeValidator, ConfigDict, Field, ValidationInfo
from pydantic_core import PydanticCustomError

from simulator.config.errors import MISSING, expected, rule, unknown_key
from simulator.config.fields import (
    PARALLEL_SIN, Direction, Number, Point, Positive, Resolution, Size, Text, UpDirection, interval, nonblank, one_of,
)  # fmt: skip
from simulator.config.table import Table
from simulator.scene.model import DEFAULT_GLARE_RESOLUTION, DEFAULT_PROBE_RESOLUTION, SensorKind, Sensor

__all__ = [
    "SensorFields",
    "IrradianceEntry",
    "RadianceEntry",
    "PatchEntry",
    "ProbeEntry",
    "CylindricalEntry",
    "SemicylindricalEntry",
    "GlareEntry",
    "SENSOR_ENTRIES",
    "SENSOR_KEYS",
    "SensorEntry",
]


class SensorFields(Table):
    """Keys every sensor kind has.

    Attributes
    ----------
    name : str or None
        None: the sensor is named after its config key, ``sensor[<index>]``.
    kind : str
        The kind's name (each kind narrows it to its own literal).
    position : ndarray, shape (3,)
        Metres (the centre, for a patch).
    """

    # validated only inside RunFile: no validator of their own to compile
    model_config = ConfigDict(defer_build=True)

    #: the sensor kind built
    KIND: ClassVar[SensorKind]

    name: Annotated[Text, nonblank("empty name")] | None = Field(
        None, description="the CSV row's name (default: sensor[<index>])"
    )
    kind: str = Field(description="irradiance | radiance | patch | probe | cylindrical | semicylindrical | glare")
    position: Annotated[
        Point, Field(description="where the sensor is (a patch's centre)", json_schema_extra={"unit": "m"})
    ]

    @classmethod
    def key_not_allowed(cls, key: str) -> PydanticCustomError:
        """A key of another kind: ``not valid for kind 'irradiance' (keys for irradiance: ...)``."""
        (kind,) = get_args(cls.model_fields["kind"].annotation)
        return rule(f"not valid for kind {kind!r} (keys for {kind}: {', '.join(cls.model_fields)})", key=key)

    def to_sensor(self, name: str, source: str) -> Sensor:
        """The :class:`Sensor` this entry describes, named ``name``, defined at config key ``source``."""
        raise NotImplementedError


#: a sensor model a ``[[sensor]]`` or ``[[grid]]`` names (checked against its file by the loader)
ModelName = Annotated[Text, nonblank("empty model name")]
MODEL_NAME = Field(None, description="a sensor model, bundled (probesim sensor --list) or a .toml file: the row "
                   "adds the reading through its optics and electronics (docs/sensors.md)")
#: the part's gain: one of its list, or "auto" (checked against the model by the loader)
MODEL_GAIN = Field(None, json_schema_extra={"type": 'number or "auto"'},
                   description='with a model: the part\'s gain, one of its list, or "auto" (default: auto where the part '
                   "ranges, else its reference)")
MODEL_INTEGRATION = Field(None, description="with a model: the integration time, one of the part's (default: the "
                          "part's choice)")


class IrradianceEntry(SensorFields):
    """A point receiver: irradiance on the side ``normal`` faces; with ``model``, also a real head's reading."""

    KIND = SensorKind.IRRADIANCE
    kind: Literal["irradiance"]
    normal: Annotated[Direction, Field(description="the side it faces (toward the light it measures)")]
    model: ModelName | None = MODEL_NAME
    gain: Any = MODEL_GAIN
    integration_ms: Positive | None = MODEL_INTEGRATION
    azimuth_ref: Direction | None = Field(
        None, json_schema_extra={"type": "[x, y, z]"},
        description="with a model with azimuth columns: its azimuth 0 (in the sensor's plane)")

    def to_sensor(self, name: str, source: str) -> Sensor:
        return Sensor(name=name, kind=self.KIND, position=self.position, normal=self.normal, source=source,
                      azimuth_ref=_in_plane(self.azimuth_ref, self.normal), gain=self.gain,
                      integration_ms=self.integration_ms)


def _in_plane(ref, normal: np.ndarray):
    """``ref`` made orthogonal to ``normal`` and unit, or None (none given, or parallel to the normal)."""
    if ref is None:
        return None
    v = ref - float(np.dot(ref, normal)) * normal
    n = float(np.linalg.norm(v))
    return v / n if n > PARALLEL_SIN else None


class RadianceEntry(SensorFields):
    """A radiance meter: mean radiance from a cone of ``half_angle_deg`` about ``direction``."""

    KIND = SensorKind.RADIANCE
    kind: Literal["radiance"]
    direction: Annotated[Direction, Field(description="the direction it looks (toward the light it measures)")]
    half_angle_deg: Annotated[Number, interval(0.0, 90.0, closed_lo=True, unit="degrees")] = Field(
        0.0, description="half angle of the cone it averages over; 0: one direction")

    def to_sensor(self, name: str, source: str) -> Sensor:
        return Sensor(
            name=name, kind=self.KIND, position=self.position, normal=self.direction,
            half_angle=math.radians(self.half_angle_deg), source=source,
        )  # fmt: skip


class PatchEntry(SensorFields):
    """A rectangle ``size`` (metres) facing ``normal``, its height side along ``up``."""

    KIND = SensorKind.PATCH
    kind: Literal["patch"]
    normal: Direction
    size: Annotated[Size, Field(description="width, height of the rectangle", json_schema_extra={"unit": "m"})]
    up: Annotated[UpDirection, Field(description="direction of the height side (glare: up in the view; default +Z)")]
    # a photometer head's area average: the model's angular response at every point drawn on the rectangle
    # (its azimuth 0 along the width side)
    model: ModelName | None = MODEL_NAME
    gain: Any = MODEL_GAIN
    integration_ms: Positive | None = MODEL_INTEGRATION

    def to_sensor(self, name: str, source: str) -> Sensor:
        return Sensor(
            name=name, kind=self.KIND, position=self.position, normal=self.normal, up=self.up, size=self.size,
            source=source, gain=self.gain, integration_ms=self.integration_ms,
        )  # fmt: skip


class ProbeEntry(SensorFields):
    """A full-sphere light probe with a lat-long map of ``resolution`` (width, height) pixels."""

    KIND = SensorKind.PROBE
    kind: Literal["probe"]
    resolution: Resolution = Field(DEFAULT_PROBE_RESOLUTION, description="lat-long map width, height in pixels "
                                                                         "(glare: of the half in front, [128, 128])")

    def to_sensor(self, name: str, source: str) -> Sensor:
        # a probe has no facing; normal and up are placeholders (the map's
        # frame is the world's, see simulator.engine.probes)
        return Sensor(
            name=name, kind=self.KIND, position=self.position, normal=np.array([0.0, 0.0, 1.0]),
            up=np.array([0.0, 1.0, 0.0]), resolution=self.resolution, source=source,
        )  # fmt: skip


def _z_axis() -> np.ndarray:
    return np.array([0.0, 0.0, 1.0])


def _perpendicular(a: np.ndarray) -> np.ndarray:
    """A unit vector orthogonal to unit ``a`` (the origin of a whole cylinder's azimuths)."""
    helper = np.array([1.0, 0.0, 0.0]) if abs(a[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    v = np.cross(a, helper)
    return v / np.linalg.norm(v)


def _facing_beside_axis(facing: np.ndarray, info: ValidationInfo) -> np.ndarray:
    axis = info.data.get("axis")
    if axis is None:
        return facing
    ortho = facing - float(np.dot(facing, axis)) * axis
    length = float(np.linalg.norm(ortho))
    if length < PARALLEL_SIN:
        raise rule("parallel to {sibling}; a semi-cylinder faces across its axis", sibling="axis")
    return ortho / length


class CylindricalEntry(SensorFields):
    """Cylindrical illuminance: the mean irradiance on the curved surface of a small cylinder about ``axis``
    (EN 12464-1's E_z with the default vertical axis)."""

    KIND = SensorKind.CYLINDRICAL
    kind: Literal["cylindrical"]
    axis: Direction = Field(default_factory=_z_axis, description="the cylinder's axis")

    def to_sensor(self, name: str, source: str) -> Sensor:
        return Sensor(name=name, kind=self.KIND, position=self.position, normal=_perpendicular(self.axis), up=self.axis,
                      source=source)  # fmt: skip


class SemicylindricalEntry(SensorFields):
    """Semi-cylindrical illuminance: the mean irradiance on the curved half of a small cylinder about ``axis``
    that faces ``facing`` (made orthogonal to the axis)."""

    KIND = SensorKind.SEMICYLINDRICAL
    kind: Literal["semicylindrical"]
    axis: Direction = Field(default_factory=_z_axis)
    facing: Annotated[Direction, AfterValidator(_facing_beside_axis), Field(
        description="the way the half cylinder faces (made orthogonal to axis)")]

    def to_sensor(self, name: str, source: str) -> Sensor:
        return Sensor(name=name, kind=self.KIND, position=self.position, normal=self.facing, up=self.axis, source=source)


def _up_beside_direction(up: np.ndarray, info: ValidationInfo) -> np.ndarray:
    view = info.data.get("direction")
    if view is None:
        return up
    ortho = up - float(np.dot(up, view)) * view
    length = float(np.linalg.norm(ortho))
    if length < PARALLEL_SIN:
        raise rule("parallel to {sibling}; up must point above the line of sight", sibling="direction")
    return ortho / length


def _evalglare(text: str) -> dict:
    from simulator.glare.sources import parse_evalglare_options

    try:
        return parse_evalglare_options(text)
    except ValueError as e:
        raise rule(str(e)) from None


class GlareEntry(SensorFields):
    """An eye at ``position`` looking along ``direction``: E_v, DGP, DGPs, UGR and the glare sources
    (:mod:`simulator.glare`)."""

    KIND = SensorKind.GLARE
    kind: Literal["glare"]
    direction: Direction
    up: Annotated[Direction, AfterValidator(_up_beside_direction)] = Field(
        default_factory=lambda: [0.0, 0.0, 1.0], validate_default=True, description="up in the view (made orthogonal to direction)")
    resolution: Resolution = Field(DEFAULT_GLARE_RESOLUTION)
    evalglare: Annotated[Text, AfterValidator(_evalglare)] = Field(
        "", description="source finding as evalglare options: -b threshold (cd/m², or ≤ 100: × task or mean "
                        "luminance; 2000), -r radius (0.2), -y/-x/-Y lum (peak extraction, 50000), -C l+ (low-light "
                        "correction; off), -t dx dy dz angle_deg (the task zone as a direction)")
    dgp_stderr: Annotated[Number, interval(0.0, 1.0)] = Field(
        0.005, description="the view traces until DGP's standard error is at most this")

    def to_sensor(self, name: str, source: str) -> Sensor:
        from simulator.glare.sources import GlareSettings

        opts = dict(self.evalglare) if isinstance(self.evalglare, dict) else {}
        return Sensor(name=name, kind=self.KIND, position=self.position, normal=self.direction, up=self.up,
                      resolution=self.resolution, source=source, glare=GlareSettings(dgp_stderr=self.dgp_stderr, **opts))


#: the model of each kind, by the name configs use (the order of
#: :data:`simulator.scene.model.SENSOR_KINDS`)
SENSOR_ENTRIES: dict[str, type[SensorFields]] = {
    "irradiance": IrradianceEntry,
    "radiance": RadianceEntry,
    "patch": PatchEntry,
    "probe": ProbeEntry,
    "cylindrical": CylindricalEntry,
    "semicylindrical": SemicylindricalEntry,
    "glare": GlareEntry,
}
#: every key some kind takes, in a stable order
SENSOR_KEYS: tuple[str, ...] = tuple(dict.fromkeys(k for m in SENSOR_ENTRIES.values() for k in m.model_fields))


def _kind_first(value: Any) -> Any:
    """Before the union picks a model: keys no kind takes, then ``kind`` itself."""
    if not isinstance(value, dict):
        return value
    for key in value:
        if key not in SENSOR_KEYS:
            raise unknown_key(key, SENSOR_KEYS)
    if "kind" not in value:
        raise rule(MISSING, key="kind")
    kind = value["kind"]
    if not isinstance(kind, str):
        raise rule(expected("a string", kind), key="kind")
    one_of(kind, tuple(SENSOR_ENTRIES), "sensor kind", key="kind")
    return value


#: one ``[[sensor]]`` table: the model of its kind
SensorEntry = Annotated[
    Union[tuple(SENSOR_ENTRIES.values())],
    Field(discriminator="kind"),
    BeforeValidator(_kind_first),
]
