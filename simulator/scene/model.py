"""The scene as the engine sees it: numpy arrays and small records, in metres.

Everything here is in the *probesim world frame*: metres, right-handed, Z up.
The stage reader converts each stage (``metersPerUnit``, ``upAxis``) into this
frame, so a config's sensor coordinates mean the same thing whatever units and
up axis the stage was authored in.

Emission is carried as a pair of numbers per emitter: the radiometric value
(watts) and its photometric twin (lumens): where materials are grey the two
integrals are all a reading needs (no spectrum is traced where nothing is
coloured). Albedos are carried as their luminance grey and, for spectral
transport, the linear sRGB it came from (``Geometry.albedo_rgb``), and so
is a coloured ``emissiveColor`` (``Geometry.emission_rgb``); lights
name their spectral shape and colour (``Light.spectrum``, ``Light.color``).
What the pair measures depends on the light kind; see :class:`Light`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import IntEnum
from typing import NamedTuple

import numpy as np

__all__ = [
    "LightKind", "Light", "LightShaping", "Portal", "Geometry", "SensorKind", "ColumnGroup", "SensorKindSpec", "SENSOR_SPECS", "SENSOR_KINDS",
    "DEFAULT_PROBE_RESOLUTION", "DEFAULT_GLARE_RESOLUTION", "MAX_PROBE_PIXELS", "patch_width_axis", "Sensor", "Scene",
]  # fmt: skip


class LightKind(IntEnum):
    """Light types; the integer is what the Warp kernels switch on.

    Each kind's device code (sampler and pdf, hits, closed form, upload)
    lives in one file of :mod:`simulator.kernels.lights`, which generates the
    kernels' dispatch from these members.
    """

    POINT = 0  #: delta source; emission = intensity (W/sr, cd)
    SPHERE = 1  #: radius > 0; emission = radiance (W m^-2 sr^-1, cd/m^2), outward
    RECT = 2  #: width x height; emission = radiance, one-sided along local -Z
    DISK = 3  #: radius; emission = radiance, one-sided along local -Z
    DISTANT = 4  #: half-angle > 0: emission = radiance; half-angle 0 (delta): normal irradiance (W/m^2, lx)
    DOME = 5  #: environment; emission = radiance (× texture_map[texel] when textured)
    CYLINDER = 6  #: radius, length along local X; emission = radiance, outward from the side
    EMISSIVE = 7  #: emissive geometry: one engine-made record for all emitting triangles (no UsdLux light)


#: kinds that are delta distributions: no direction sample can hit them.
DELTA_KINDS = frozenset({LightKind.POINT})


@dataclass
class Light:
    """One UsdLux light, resolved to world space and emission units.

    Attributes
    ----------
    name : str
        Prim path.
    kind : LightKind
    position : ndarray, shape (3,)
        Centre, metres.
    frame : ndarray, shape (3, 3)
        Columns are the light's unit X, Y, Z axes in the world frame. Rect and
        Disk lights emit toward ``-frame[:, 2]``; a DistantLight shines along
        ``-frame[:, 2]`` (so the direction *toward* it is ``+frame[:, 2]``).
    emission : tuple of float
        ``(radiometric, photometric)``: radiance (W m^-2 sr^-1, cd/m^2) for
        area, sphere, cylinder, dome and distant lights with an angle;
        intensity (W/sr, cd) for point lights; normal irradiance (W/m^2, lx)
        for a distant light with ``half_angle == 0``.
    width, height : float
        Rect size along local X and Y, metres.
    radius : float
        Sphere, disk and cylinder radius, metres.
    length : float
        Cylinder length along local X, metres.
    half_angle : float
        Distant light cone half-angle, radians (0 = delta direction).
    """

    name: str
    kind: LightKind
    position: np.ndarray
    frame: np.ndarray
    emission: tuple[float, float]
    width: float = 0.0
    height: float = 0.0
    radius: float = 0.0
    length: float = 0.0
    half_angle: float = 0.0
    texture: str = ""  #: DomeLight lat-long EXR (resolved path), "" if untextured
    #: textured DomeLight: the map as luminance grey, shape (H, W), float64, row 0
    #: at the pole ``frame[:, 1]`` (the convention of :mod:`simulator.io.latlong`);
    #: radiance along a direction = ``emission × texture_map[texel]``. None if untextured.
    texture_map: np.ndarray | None = None
    #: UsdLuxShapingAPI of a point, sphere, disk or rect light (None: unshaped)
    shaping: "LightShaping | None" = None
    #: the emitter's spectral shape as the stage reader named it (an illuminant
    #: name or a temperature, see :func:`simulator.spectra.sources.emitter_spectrum`);
    #: None: the run's default
    spectrum: str | float | None = None
    #: True when ``spectrum`` is the prim's ``probesim:spectrum``: it then overrides a run's ``[spectra] lights``
    spectrum_authored: bool = False
    #: linear sRGB ``color`` input (``emission`` holds its BT.709 grey), for spectral transport
    color: tuple[float, float, float] = (1.0, 1.0, 1.0)
    #: what the stage stated of its output, for the run record: ``{"flux_lm": ...}`` (or with ``power_W`` and
    #: ``efficacy_lm_per_W``) where it gave lumens, else its ``intensity``, ``exposure``, ``normalize`` and
    #: ``color_grey``; empty for a light not read from a stage
    authored: dict = field(default_factory=dict)
    #: DomeLight only: the UsdLux PortalLights that guide its sampling (see :class:`Portal`)
    portals: tuple["Portal", ...] = ()

    def __post_init__(self):
        self.portals = tuple(self.portals)
        if self.portals and self.kind != LightKind.DOME:
            raise ValueError(f"{self.name}: only a DomeLight has portals, not a {self.kind.name} light")
        for p in self.portals:
            if not isinstance(p, Portal):
                raise TypeError(f"{self.name}: a portal must be a Portal, not {type(p).__name__}")

    @property
    def is_delta(self) -> bool:
        """True for lights no sampled direction can hit (pdf is a delta)."""
        return self.kind == LightKind.POINT or (
            self.kind == LightKind.DISTANT and self.half_angle == 0.0
        )


@dataclass(frozen=True)
class Portal:
    """A UsdLux PortalLight: a rectangle through which a dome's light is
    sampled (a *sampling* hint: a dome with portals emits exactly what it
    emits without them, so no reading depends on its portals).

    The rectangle is ``width × height`` along ``frame[:, 0]`` and
    ``frame[:, 1]`` about ``position``; it passes the dome's light toward
    ``-frame[:, 2]`` (UsdLux: a portal emits along its local −Z), so it
    guides receivers on that side of its plane.

    Attributes
    ----------
    name : str
        Prim path.
    position : ndarray, shape (3,)
        Centre, metres.
    frame : ndarray, shape (3, 3)
        Columns: unit X, Y, Z axes in the world frame, orthonormal and right-handed.
    width, height : float
        World size along X and Y, metres (> 0).

    Raises
    ------
    ValueError
        A size that is not a positive finite number, a position that is not
        finite, or a frame that is not a right-handed orthonormal basis.
    """

    name: str
    position: np.ndarray
    frame: np.ndarray
    width: float
    height: float

    def __post_init__(self):
        pos = np.asarray(self.position, np.float64).reshape(-1)
        frame = np.asarray(self.frame, np.float64)
        if pos.shape != (3,) or not np.all(np.isfinite(pos)):
            raise ValueError(f"portal {self.name}: position must be 3 finite numbers, not {self.position!r}")
        if frame.shape != (3, 3) or not np.all(np.isfinite(frame)):
            raise ValueError(f"portal {self.name}: frame must be a finite 3 x 3 matrix")
        if not np.allclose(frame.T @ frame, np.eye(3), atol=1e-9) or np.linalg.det(frame) < 0:
            raise ValueError(f"portal {self.name}: frame must be a right-handed orthonormal basis")
        for what in ("width", "height"):
            v = getattr(self, what)
            if not (isinstance(v, (int, float, np.floating)) and np.isfinite(v) and v > 0):
                raise ValueError(f"portal {self.name}: {what} must be a positive number of metres, not {v!r}")
        object.__setattr__(self, "position", pos)
        object.__setattr__(self, "frame", frame)
        object.__setattr__(self, "width", float(self.width))
        object.__setattr__(self, "height", float(self.height))

    def corners(self) -> np.ndarray:
        """The four corners, shape (4, 3), metres, counter-clockwise about +Z."""
        hx = 0.5 * self.width * self.frame[:, 0]
        hy = 0.5 * self.height * self.frame[:, 1]
        return self.position + np.array([-hx - hy, hx - hy, hx + hy, -hx + hy])

    def faces(self, p) -> bool:
        """Whether point p (metres) lies on the side the portal passes light
        toward (strictly in front of its plane along −Z)."""
        return float((np.asarray(p, float) - self.position) @ self.frame[:, 2]) < 0.0


@dataclass
class LightShaping:
    """How a light's emission varies with the emission direction ω (UsdLux
    ShapingAPI; OpenUSD user guide, "ShapingAPI"): the radiance (or a point
    light's intensity) toward ω is ``emission × factor(ω)``.

    With θ the angle between ω and the light's −Z axis, and (θ, φ) the IES
    angles in the light's frame (θ from −Z, φ from +X toward +Y):

        factor = cone(θ) · focus(θ) · ies_scale · I_file(θ, φ)

    - cone (not applied when an IES profile is: UsdLux says the cone "does
      not affect IES profiles"): 0 for θ > ``cone_angle_rad``; with softness s (clamped to
      [0, 1]), 1 − smoothstep(θ_c·(1 − s), θ_c, θ), so 1 inside θ_c(1 − s)
      and the whole cone at s = 0;
    - focus: tint + (1 − tint)·|cos θ|^focus (focus ≤ 0: 1), tint the grey of
      ``shaping:focusTint``; θ is taken from the light's axis for every kind
      (UsdLux measures it from the emitting surface's normal, the same for
      rect and disk lights but not for a SphereLight of finite radius);
    - IES: ``ies_scale × I_file`` (omitted without a file): relative mode
      ``1 / max I_file`` (the authored intensity is the peak), with
      ``shaping:ies:normalize`` ``4π / Φ_file`` (the profile's mean over the
      sphere is 1, which keeps a point light's total flux; an area light's
      cosθ weighting makes that approximate); absolute mode (``probesim:ies:absolute``,
      point lights only) makes the light emit the file's candelas × the
      light loss factor, ignoring its intensity (emission is set to 1 cd).

    Attributes
    ----------
    cone_angle_rad : float
    cone_softness : float
    focus : float
    focus_tint : float
    ies : GoniometricDistribution or None
    ies_scale : float
        Multiplier of I_file (cd⁻¹, or dimensionless × cd⁻¹·cd in absolute mode).
    absolute : bool
    light_loss_factor : float
    """

    cone_angle_rad: float = float(np.pi / 2)
    cone_softness: float = 0.0
    focus: float = 0.0
    focus_tint: float = 0.0
    ies: object | None = None
    ies_scale: float = 0.0
    absolute: bool = False
    light_loss_factor: float = 1.0

    def factor(self, theta_rad, phi_rad) -> np.ndarray:
        """The factor toward emission directions at (θ, φ), radians (numpy twin of the kernel's)."""
        th = np.asarray(theta_rad, float)
        f = np.ones_like(th)
        s = min(max(self.cone_softness, 0.0), 1.0)
        if self.ies is None:  # UsdLux: the cone "does not affect IES profiles"
            f = np.where(th > self.cone_angle_rad, 0.0, 1.0)
        if s > 0 and self.ies is None:
            a = self.cone_angle_rad * (1 - s)
            t = np.clip((th - a) / (self.cone_angle_rad - a), 0.0, 1.0)
            f = f * (1 - t * t * (3 - 2 * t))
        if self.focus > 0:
            f = f * (self.focus_tint + (1 - self.focus_tint) * np.abs(np.cos(th)) ** self.focus)
        if self.ies is not None:
            f = f * self.ies_scale * self.ies.candela_at(np.degrees(th), np.degrees(phi_rad))
        return f


@dataclass
class Geometry:
    """All surfaces as one triangle soup in world metres.

    Triangles are wound so that their geometric normal
    ``cross(p1 - p0, p2 - p0)`` is the front face (left-handed prims are
    re-wound by the reader).

    Attributes
    ----------
    points : ndarray, shape (P, 3), float64
    triangles : ndarray, shape (T, 3), int32
    albedo : ndarray, shape (T,), float64
        Lambertian albedo in [0, 1); both faces reflect.
    emission : ndarray, shape (T, 2), float64
        Emitted radiance ``(W m^-2 sr^-1, cd/m^2)`` from the front face.
    two_sided : ndarray, shape (T,), bool
        Emits from both faces (``doubleSided``).
    prim : ndarray, shape (T,), int32
        Index into ``prim_names`` of the prim each triangle came from.
    prim_names : list of str
    albedo_rgb : ndarray, shape (T, 3), float64, or None
        The linear sRGB ``diffuseColor`` each ``albedo`` is the BT.709 grey
        of, for spectral transport (reflectance uplift); None: grey
        (``(a, a, a)``) everywhere.
    reflectance_id : ndarray, shape (T,), int32, or None
        Index into ``reflectances`` of each triangle's measured reflectance
        (a material's ``probesim:reflectance``), -1 where there is none
        (the uplift of ``albedo_rgb``); None: none anywhere.
    reflectances : list of (str, ndarray (401,))
        The measured reflectances: file name and ρ(λ) on the 380–780 nm grid;
        ``albedo`` of their triangles is their luminance-weighted grey.
    emissive_spectrum : str, float or None
        The spectrum every emitting triangle's stage names (a mesh light's
        ``probesim:spectrum`` or ``colorTemperature``, as
        :func:`simulator.spectra.sources.emitter_spectrum` reads it); None:
        the run's default (or the triangles name several; their efficacies
        then differ and the hero tables note it).
    emissive_spectrum_authored : bool
        ``emissive_spectrum`` came from ``probesim:spectrum``, which a run's
        ``[spectra] lights`` does not override.
    emission_rgb : ndarray, shape (T, 3), float64, or None
        The linear sRGB ``emissiveColor`` each emitting triangle's
        ``emission`` is the BT.709 grey of, (1, 1, 1) where it is grey; for
        spectral transport (the emissive spectrum × its uplift,
        :func:`simulator.spectra.sources.colour_emission`). None: grey
        everywhere.
    surface_id : ndarray, shape (T,), int32, or None
        Index into ``surfaces`` of each triangle's material beyond Lambert
        (coverage, a dielectric pane; :mod:`simulator.scene.surfaces`), -1
        for a matte face; None: every face matte (the kernels then run their
        matte code only).
    surfaces : list of Surface
        The per-material table ``surface_id`` indexes.
    solid_side : ndarray, shape (T,), int8, or None
        Pane faces only: 0 on an open pane (a thin slab), +1 / −1 on a face
        of a closed pane mesh whose front / back faces outward
        (:func:`simulator.scene.surfaces.solid_sides`); None without panes.
    coverage_textures : list of CoverageTexture
        The opacity textures read per texel
        (:class:`simulator.scene.surfaces.CoverageTexture`).
    texture_id : ndarray, shape (T,), int32, or None
        Per triangle: its index into ``coverage_textures``, -1 where none
        (or the face has no texture coordinates: its row's ``coverage``);
        None: no texture anywhere.
    texture_uv : ndarray, shape (T, 3, 2), float64, or None
        Per triangle corner: the texture's ``st`` (after its st transform),
        zero where ``texture_id`` is -1; None with ``texture_id``.
    shading_normals : ndarray, shape (T, 3, 3), float32, or None
        Per triangle corner: the unit normal of the curved surface the
        triangle stands for (an authored ``normals`` primvar, a subdivision
        cage's smooth normals, an implicit gprim's own;
        :mod:`simulator.scene.usd.normals`), kept on glossy, mirror and pane
        faces, zero on a flat face or a matte one (its face normal); None
        where no such face has them. The kernels shade glossy and mirror
        faces by it (:mod:`simulator.kernels.glossy`), matte faces and panes
        by their face normal.
    """

    points: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    triangles: np.ndarray = field(default_factory=lambda: np.zeros((0, 3), np.int32))
    albedo: np.ndarray = field(default_factory=lambda: np.zeros(0))
    emission: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))
    two_sided: np.ndarray = field(default_factory=lambda: np.zeros(0, bool))
    prim: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int32))
    prim_names: list[str] = field(default_factory=list)
    albedo_rgb: np.ndarray | None = None
    reflectance_id: np.ndarray | None = None
    reflectances: list = field(default_factory=list)
    emissive_spectrum: str | float | None = None
    emissive_spectrum_authored: bool = False
    emission_rgb: np.ndarray | None = None
    surface_id: np.ndarray | None = None
    surfaces: list = field(default_factory=list)
    solid_side: np.ndarray | None = None
    coverage_textures: list = field(default_factory=list)
    texture_id: np.ndarray | None = None
    texture_uv: np.ndarray | None = None
    shading_normals: np.ndarray | None = None

    @property
    def has_surfaces(self) -> bool:
        """Whether any face needs more than the matte kernels (a modelled :class:`Surface`)."""
        return self.surface_id is not None and bool(np.any(self.surface_id >= 0))

    def reflecting(self) -> np.ndarray:
        """Per triangle: whether it sends light on (albedo > 0, or a modelled surface), shape (T,)."""
        out = self.albedo > 0
        if self.has_surfaces:
            out = out | (self.surface_id >= 0)
        return out

    @property
    def n_triangles(self) -> int:
        return int(self.triangles.shape[0])


class SensorKind(IntEnum):
    """Sensor types; the integer is what the Warp kernels switch on."""

    IRRADIANCE = 0  #: point receiver; irradiance on the side ``normal`` faces
    RADIANCE = 1  #: mean radiance arriving from a cone around ``direction``
    PATCH = 2  #: rectangle; flux through it from the side it faces
    PROBE = 3  #: full-sphere light probe
    CYLINDRICAL = 4  #: mean irradiance on a small cylinder's curved surface about the axis ``up``
    SEMICYLINDRICAL = 5  #: the same over the half cylinder facing ``normal``
    GLARE = 6  #: an eye looking along ``normal`` (up ``up``): E_v, DGP, DGPs, UGR and the glare sources


#: lat-long map size ``(width, height)`` of a probe that does not say
DEFAULT_PROBE_RESOLUTION = (64, 32)
#: half-map size ``(width, height)`` of a glare view that does not say (1.4° pixels)
DEFAULT_GLARE_RESOLUTION = (128, 128)
#: most pixels in a probe map (1024 × 512): each pixel keeps float64 running
#: sums of 22 integrands in 2 channels (about 700 B)
MAX_PROBE_PIXELS = 1 << 19



class ColumnGroup(NamedTuple):
    """Four CSV columns of one quantity: value and standard error,
    radiometric then photometric (for a probe's mean direction: x, y, z and
    the angular standard error). ``factor`` on the sensor's mean reading:
    ``"1"``, or ``"area"`` (× the patch area); units for summaries."""

    columns: tuple[str, str, str, str]
    factor: str = "1"
    unit: str = ""
    photometric_unit: str = ""


_IRRADIANCE = ColumnGroup(("irradiance_W_m2", "irradiance_stderr_W_m2", "illuminance_lx", "illuminance_stderr_lx"), "1", "W/m²", "lx")
_RADIANCE = ColumnGroup(("radiance_W_m2_sr", "radiance_stderr_W_m2_sr", "luminance_cd_m2", "luminance_stderr_cd_m2"), "1", "W/m²/sr", "cd/m²")
_FLUX = ColumnGroup(("flux_W", "flux_stderr_W", "luminous_flux_lm", "luminous_flux_stderr_lm"), "area", "W", "lm")
_SCALAR = ColumnGroup(
    ("scalar_irradiance_W_m2", "scalar_irradiance_stderr_W_m2", "scalar_illuminance_lx", "scalar_illuminance_stderr_lx"), "1", "W/m²", "lx"
)
_CYLINDRICAL = ColumnGroup(
    ("cylindrical_irradiance_W_m2", "cylindrical_irradiance_stderr_W_m2", "cylindrical_illuminance_lx", "cylindrical_illuminance_stderr_lx"),
    "1", "W/m²", "lx",
)  # fmt: skip
_SEMICYLINDRICAL = ColumnGroup(
    ("semicylindrical_irradiance_W_m2", "semicylindrical_irradiance_stderr_W_m2", "semicylindrical_illuminance_lx",
     "semicylindrical_illuminance_stderr_lx"), "1", "W/m²", "lx",
)  # fmt: skip
_DIRECTION = ColumnGroup(("mean_direction_x", "mean_direction_y", "mean_direction_z", "mean_direction_stderr_deg"))
#: a glare view's indices: DGP and DGPs each with its standard error; UGR with its standard error, and its background
_DGP = ColumnGroup(("dgp", "dgp_stderr", "dgps", "dgps_stderr"))
_UGR = ColumnGroup(("ugr", "ugr_stderr", "background_luminance_cd_m2", "glare_sources"))


@dataclass(frozen=True)
class SensorKindSpec:
    """Everything outside the kernels that one sensor kind declares.

    Attributes
    ----------
    kind : SensorKind
    name : str
        How configs and ``probesim:sensor:kind`` spell it.
    attributes : tuple of str
        :class:`Sensor` fields the kind reads beyond ``position`` and
        ``normal`` (``up``, ``size``, ``half_angle``, ``resolution``).
    reader : str
        ``"estimate"``: read by :meth:`simulator.engine.driver.Engine.run`
        through the estimator kernel (its per-sample entry is registered in
        :mod:`simulator.kernels.estimators`); ``"probe"``: by
        :meth:`~simulator.engine.driver.Engine.run_probes`; ``"glare"``: by
        :func:`simulator.engine.glare.run_glare`.
    columns : tuple of ColumnGroup
        CSV value columns it fills. A probe's are filled from its sphere
        integrals (``simulator.io.results.probe_readings``).
    headline : int
        The group a one-line summary shows.
    culls_lights : bool
        Its first path vertex is the sensor itself, so lights the plan
        proved wholly behind it may be skipped there.
    directed : bool
        Its ``normal`` is a direction the CSV reports (``dx, dy, dz``).
    extra_columns : bool
        Its value columns are written only by a run that holds such a sensor,
        after the standard ones (:func:`simulator.io.results.extra_columns`),
        so that the CSVs of runs without one keep their header.
    """

    kind: SensorKind
    name: str
    attributes: tuple[str, ...]
    reader: str
    columns: tuple[ColumnGroup, ...]
    culls_lights: bool
    headline: int = 0
    directed: bool = True
    extra_columns: bool = False


#: every sensor kind, in ``SensorKind`` order
SENSOR_SPECS = (
    SensorKindSpec(SensorKind.IRRADIANCE, "irradiance", (), "estimate", (_IRRADIANCE,), culls_lights=True),
    SensorKindSpec(SensorKind.RADIANCE, "radiance", ("half_angle",), "estimate", (_RADIANCE,), culls_lights=False),
    SensorKindSpec(SensorKind.PATCH, "patch", ("up", "size"), "estimate", (_IRRADIANCE, _FLUX), culls_lights=True, headline=1),
    SensorKindSpec(SensorKind.PROBE, "probe", ("resolution",), "probe", (_SCALAR, _DIRECTION), culls_lights=False, directed=False),
    SensorKindSpec(SensorKind.CYLINDRICAL, "cylindrical", ("up",), "estimate", (_CYLINDRICAL,), culls_lights=False, extra_columns=True),
    SensorKindSpec(SensorKind.SEMICYLINDRICAL, "semicylindrical", ("up",), "estimate", (_SEMICYLINDRICAL,), culls_lights=False,
                   extra_columns=True),
    SensorKindSpec(SensorKind.GLARE, "glare", ("up", "resolution"), "glare", (_IRRADIANCE, _DGP, _UGR), culls_lights=False,
                   extra_columns=True),
)  # fmt: skip
assert [int(s.kind) for s in SENSOR_SPECS] == list(range(len(SensorKind)))

#: sensor kind names, as configs and ``probesim:sensor:kind`` spell them
SENSOR_KINDS = {s.name: s.kind for s in SENSOR_SPECS}

#: the kinds that take a sensor model (:mod:`simulator.sensor_models`): a head's angular response r(ω)
#: replaces a cosine at a flat receiver's own vertex, a point's (irradiance) or every point drawn on a
#: rectangle (patch: a photometer head's area average). Not the others: a cylinder's reading is defined
#: by the cosine over its curved surface, a radiance meter's field is its cone, a probe is a map.
MODEL_KINDS = (SensorKind.IRRADIANCE, SensorKind.PATCH)


def patch_width_axis(up: np.ndarray, normal: np.ndarray) -> np.ndarray:
    """A patch's unit width axis, ``normalize(cross(up, normal))``: with
    ``up`` the height axis, (width, up, normal) is right-handed."""
    right = np.cross(up, normal)
    right /= np.linalg.norm(right)
    return right


@dataclass
class Sensor:
    """One virtual sensor in the world frame.

    Attributes
    ----------
    name : str
    kind : SensorKind
    position : ndarray, shape (3,)
        Metres (the centre, for a patch).
    normal : ndarray, shape (3,)
        Unit vector the sensor faces: toward the light it measures. For a
        radiance meter this is the look direction (rays leave along it).
    up : ndarray, shape (3,)
        Patch: unit direction of the height side, orthogonal to normal.
        Cylindrical and semi-cylindrical: the cylinder's axis (``normal``,
        orthogonal to it, is where a semi-cylinder faces; for a whole
        cylinder only the origin of its azimuths).
    size : tuple of float
        Patch only: ``(width, height)`` in metres.
    half_angle : float
        Radiance only: cone half-angle in radians (0 = one direction).
    resolution : tuple of int
        Probe: lat-long map ``(width, height)`` in pixels; glare: the half map in front of the eye.
    glare : GlareSettings or None
        Glare only: how it finds its sources and when it stops (:class:`simulator.glare.sources.GlareSettings`).
    grid : str or None
        Name of the ``[[grid]]`` this sensor was expanded from.
    source : str
        Where it was defined (config key or prim path), for messages.
    model : SensorModel or None
        The sensor model it names (:mod:`simulator.sensor_models`): the run reads it as today (the
        ideal quantity) and also through the model (optics, device). None: an ideal sensor.
    optics : AngularResponse or None
        Set only on the engine's optics twin of a modelled sensor
        (:func:`simulator.sensor_models.readings.optics_twins`): its first vertex weighs by this response
        instead of the cosine. None: the cosine.
    azimuth_ref : ndarray, shape (3,), or None
        The in-plane direction of azimuth 0 of a model with azimuth columns (made orthogonal to
        ``normal``); None: any (a symmetric head).
    gain : float, "auto" or None
        A modelled sensor's gain (one of its part's); None: the part's default (auto-ranging where it
        ranges, else its reference gain).
    integration_ms : float or None
        A modelled sensor's integration time, ms (one of its part's); None: the part's choice.
    """

    name: str
    kind: SensorKind
    position: np.ndarray
    normal: np.ndarray
    up: np.ndarray = field(default_factory=lambda: np.zeros(3))
    size: tuple[float, float] = (0.0, 0.0)
    half_angle: float = 0.0
    resolution: tuple[int, int] = (0, 0)
    grid: str | None = None
    source: str = ""
    model: object | None = None
    optics: object | None = None
    azimuth_ref: np.ndarray | None = None
    gain: float | str | None = None
    integration_ms: float | None = None
    glare: object | None = None

    @property
    def spec(self) -> SensorKindSpec:
        """The declaration of this sensor's kind."""
        return SENSOR_SPECS[self.kind]


@dataclass
class Scene:
    """What the stage reader hands on: geometry, lights and authored sensors."""

    geometry: Geometry
    lights: list[Light]
    sensors: list[Sensor]
    path: str = ""
    meters_per_unit: float = 1.0
    up_axis: str = "Z"
    warnings: list[str] = field(default_factory=list)
    #: every USD collection on the stage (``/prim.collection:name``) → the light prim paths it includes
    collections: dict[str, tuple[str, ...]] = field(default_factory=dict)
    #: the USD time code the stage was read at; None: each attribute's earliest time sample
    time_code: float | None = None
    #: prims read whose values vary in time, found when no time code was given (prim paths)
    animated: tuple[str, ...] = ()
    #: the files the reader depended on (every layer the stage composed, textures and MaterialX documents
    #: read by path; absolute paths), or None where that list is not known to be whole (a composition
    #: error: a reference that did not resolve may resolve later). Keys the in-process stage cache.
    sources: tuple[str, ...] | None = None

    @property
    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Axis-aligned box (metres) around geometry, lights and sensors."""
        pts = [self.geometry.points.reshape(-1, 3)]
        pts += [l.position[None, :] for l in self.lights if l.kind not in (LightKind.DOME, LightKind.DISTANT)]
        pts += [s.position[None, :] for s in self.sensors]
        allp = np.concatenate(pts) if pts else np.zeros((1, 3))
        if allp.size == 0:
            allp = np.zeros((1, 3))
        return allp.min(axis=0), allp.max(axis=0)
