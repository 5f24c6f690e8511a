"""Light probes on the engine's device: lat-long maps and sphere integrals.

A probe estimates the radiance arriving at a point from every direction
(see :mod:`simulator.kernels.probe` for the estimator) and reports

- a lat-long map of incident radiance: each pixel the mean radiance over its
  solid angle, with its standard error;
- integrals over the sphere, each with its standard error: scalar irradiance
  (fluence rate) ∫L dω, the irradiance on the six axis-aligned faces
  ∫L·max(0, ±ω·axis) dω, the vector irradiance ∫L·ω dω and its direction,
  and the nine real spherical-harmonic coefficients ∫L·Y_lm dω (l ≤ 2).

Estimator. Every *pass* draws one direction in each pixel, uniform in
solid angle within it, so a pass gives every integral as the stratified sum
I_q = Σ_pixels Ω_p·f_q(ω_p)·L(ω_p). With n passes, pixel p's mean μ_pq of
f_q·L and its sample variance s²_pq, the estimate and its standard error are

    I_q = Σ_p Ω_p·μ_pq + D_q,     se(I_q) = √(Σ_p Ω_p²·s²_pq / n),

where D_q is the exact contribution of delta lights (point lights and
angle-0 distant lights: no direction sample can see them), added by
next-event estimation with a shadow ray when the method samples lights
(light, mis, path; method bsdf is blind to them, as for every sensor). The
map never shows a delta light: it holds what direction sampling sees.

Frame. Directions in the map follow the OpenEXR lat-long convention
(:mod:`simulator.io.latlong`) in the frame an *untransformed* DomeLight of the
same stage has: the world frame for a Z-up stage, the Y-up stage's axes for
a Y-up one. So the map can be given straight back to that stage as a
DomeLight's ``texture:file``. The integrals are in the world frame (Z up).

This module holds what only a probe needs: the map layout, the probe's
device record, and the reductions of per-pixel statistics to the map and the
integrals. The driver (:meth:`simulator.engine.driver.Engine.run_probes`)
launches the passes and decides when to stop.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from simulator.engine.stats import RunningStats
from simulator.scene.model import MAX_PROBE_PIXELS, Sensor  # noqa: F401  (MAX_PROBE_PIXELS re-exported)

__all__ = [
    "FACE_NAMES",
    "SH_NAMES",
    "MIN_PASSES",
    "MAX_PROBE_PIXELS",
    "N_QUANTITIES",
    "N_CHANNELS",
    "N_COLOUR",
    "probe_width",
    "ProbeResult",
    "latlong_layout",
    "pixel_solid_angles",
    "probe_frame",
    "probe_record",
    "stream_key",
    "integrals",
    "probe_result",
]

#: the six faces of the "cube" sensor, in integrand order
FACE_NAMES = ("+X", "-X", "+Y", "-Y", "+Z", "-Z")
#: real SH coefficients (l, m) in integrand order
SH_NAMES = ("0,0", "1,-1", "1,0", "1,1", "2,-2", "2,-1", "2,0", "2,1", "2,2")
#: fewest passes (directions per pixel) a probe draws: its per-pixel standard
#: errors come from the spread between passes
MIN_PASSES = 8
#: integrands per sample, see simulator.kernels.probe (19 reported + 3 for covariances)
N_QUANTITIES = 22
#: channels: radiometric, photometric
N_CHANNELS = 2

#: spectral transport: linear sRGB radiance columns (cd/m²) after the integrands
N_COLOUR = 3
_Q = N_QUANTITIES
_C = N_CHANNELS


def probe_width(spectral: bool) -> int:
    """Statistics per pixel: the 22 integrands × 2 channels, and the 3 sRGB columns when spectral."""
    return _Q * _C + (N_COLOUR if spectral else 0)


# --------------------------------------------------------------------------- layout (numpy)


def probe_frame(up_axis: str) -> np.ndarray:
    """World axes (columns) of the map frame: an untransformed DomeLight's frame.

    Parameters
    ----------
    up_axis : str
        The stage's ``upAxis``, ``"Z"`` or ``"Y"``.

    Returns
    -------
    ndarray, shape (3, 3)
        Identity for a Z-up stage; for a Y-up stage the stage's axes in the
        world frame, ``(x, y, z)_Yup -> (x, -z, y)``.
    """
    if str(up_axis).upper() == "Y":
        return np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
    return np.eye(3)


def _lonlat(d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """OpenEXR longitude and latitude of map-frame directions (x, y, z):
    d = (sin lon·cos lat, sin lat, cos lon·cos lat)."""
    return np.arctan2(d[..., 0], d[..., 2]), np.arcsin(np.clip(d[..., 1], -1.0, 1.0))


def latlong_layout(width: int, height: int) -> tuple[float, float, float, float]:
    """Longitude and latitude of pixel edges in the shared lat-long convention.

    Reads the convention off :func:`simulator.io.latlong.latlong_uv_to_direction`
    (u across the width, v down the height, both in [0, 1]) so that the
    probe's pixels are exactly the pixels a textured DomeLight reads.

    Returns
    -------
    lon0, dlon, lat0, dlat : float
        Pixel (i, j) spans longitudes ``[lon0 + i·dlon, lon0 + (i+1)·dlon]``
        and latitudes ``[lat0 + j·dlat, lat0 + (j+1)·dlat]``, radians.
    """
    from simulator.io.latlong import latlong_uv_to_direction

    def lonlat(u, v):
        return _lonlat(np.asarray(latlong_uv_to_direction(np.array([u, v], float)), float))

    # slopes from interior points (lon is continuous on (0, 1); its ±π seam is at the edges)
    (l25, _), (l75, _) = lonlat(0.25, 0.5), lonlat(0.75, 0.5)
    slope_lon = (l75 - l25) / 0.5
    lon0 = float(l25 - 0.25 * slope_lon)
    (_, b25), (_, b75) = lonlat(0.5, 0.25), lonlat(0.5, 0.75)
    slope_lat = (b75 - b25) / 0.5
    lat0 = float(b25 - 0.25 * slope_lat)
    if not (abs(abs(slope_lon) - 2 * math.pi) < 1e-9 and abs(abs(slope_lat) - math.pi) < 1e-9):
        raise AssertionError("simulator.io.latlong is not an equirectangular map over the whole sphere")
    return lon0, float(slope_lon) / width, lat0, float(slope_lat) / height


def pixel_solid_angles(width: int, height: int) -> np.ndarray:
    """Solid angle of every lat-long pixel, sr, shape (height, width).

    Ω = |Δlon|·|sin lat_b − sin lat_a| (:func:`simulator.io.latlong.texel_solid_angles`);
    the pixels tile the sphere (Σ = 4π).
    """
    from simulator.io.latlong import texel_solid_angles

    return np.repeat(texel_solid_angles(width, height)[:, None], width, axis=1)


# --------------------------------------------------------------------------- results


@dataclass
class ProbeResult:
    """One probe's estimates.

    Attributes
    ----------
    sensor : Sensor
    frame : ndarray, shape (3, 3)
        World axes (columns) of the map frame, see :func:`probe_frame`.
    radiance, radiance_stderr : ndarray, shape (H, W, 2)
        Mean radiance per pixel and its standard error: channel 0 W m⁻² sr⁻¹,
        channel 1 cd/m². Row 0 is the top of the map.
    solid_angle_sr : ndarray, shape (H, W)
    integrals, integrals_stderr : ndarray, shape (19, 2)
        The sphere integrals in integrand order (fluence, six faces, vector
        x/y/z, nine SH), W/m² (channel 0) and lx (channel 1).
    vector_cov : ndarray, shape (2, 3, 3)
        Covariance matrix of the vector irradiance estimate per channel,
        (W/m²)² and lx².
    delta : ndarray, shape (19, 2)
        The part of ``integrals`` that delta lights gave (exact).
    passes : int
        Directions drawn per pixel.
    samples : int
        Directions drawn in all (passes × pixels).
    seconds : float
    non_finite : int
        Samples that came out NaN or Inf (counted as 0).
    target_met : bool or None
        Adaptive runs: whether scalar irradiance reached the error target.
    colour, colour_stderr : ndarray, shape (H, W, 3), or None
        Spectral transport only: mean linear sRGB radiance per pixel in
        cd/m² (luminance-based: ``M · K_m ∫ L (x̄, ȳ, z̄) dλ``, CIE 1931 2°,
        IEC 61966-2-1 ``M``) and its standard error.
    interrupted : bool
        Stopped by a stop request (Ctrl-C) before its passes or target were
        reached; ``target_met`` is then False.
    """

    sensor: Sensor
    frame: np.ndarray
    radiance: np.ndarray
    radiance_stderr: np.ndarray
    solid_angle_sr: np.ndarray
    integrals: np.ndarray
    integrals_stderr: np.ndarray
    vector_cov: np.ndarray
    delta: np.ndarray
    passes: int
    samples: int
    seconds: float
    non_finite: int = 0
    target_met: bool | None = None
    warnings: list[str] = field(default_factory=list)
    interrupted: bool = False
    colour: np.ndarray | None = None
    colour_stderr: np.ndarray | None = None

    @property
    def scalar_irradiance(self) -> tuple[np.ndarray, np.ndarray]:
        """(value, stderr), each shape (2,): W/m² and lx."""
        return self.integrals[0], self.integrals_stderr[0]

    @property
    def faces(self) -> tuple[np.ndarray, np.ndarray]:
        """(value, stderr), each shape (6, 2), faces in :data:`FACE_NAMES` order."""
        return self.integrals[1:7], self.integrals_stderr[1:7]

    @property
    def vector(self) -> tuple[np.ndarray, np.ndarray]:
        """Vector irradiance ∫L·ω dω: (value, stderr), each shape (3, 2)."""
        return self.integrals[7:10], self.integrals_stderr[7:10]

    @property
    def sh(self) -> tuple[np.ndarray, np.ndarray]:
        """SH coefficients: (value, stderr), each shape (9, 2), :data:`SH_NAMES` order."""
        return self.integrals[10:19], self.integrals_stderr[10:19]

    def mean_direction(self, channel: int = 0) -> tuple[np.ndarray, float]:
        """Unit mean direction of arrival and its angular standard error, degrees.

        The direction is m = v/|v| for the vector irradiance v. Its error is
        the delta-method RMS angle √(tr(P·Σ·P))/|v|, with Σ the covariance
        of v (:attr:`vector_cov`) and P = I − m·mᵀ the projection across m:
        the spread of v perpendicular to its direction. NaN where v = 0.
        """
        v = self.integrals[7:10, channel]
        norm = float(np.linalg.norm(v))
        if not norm > 0.0:
            return np.full(3, np.nan), math.nan
        m = v / norm
        p = np.eye(3) - np.outer(m, m)
        ang = math.sqrt(max(0.0, float(np.trace(p @ self.vector_cov[channel] @ p)))) / norm
        return m, math.degrees(ang)


# --------------------------------------------------------------------------- records and reductions


def probe_record(r, sensor: Sensor, frame: np.ndarray, key: int):
    """Fill the kernels' ``ProbeRec`` ``r`` for ``sensor``: position, map
    frame (columns of ``frame``), pixel layout and random-stream ``key``."""
    from simulator.engine.device import warp

    wp = warp()
    w, h = sensor.resolution
    lon0, dlon, lat0, dlat = latlong_layout(w, h)
    r.position = wp.vec3(*map(float, sensor.position))
    r.ex = wp.vec3(*map(float, frame[:, 0]))
    r.ey = wp.vec3(*map(float, frame[:, 1]))
    r.ez = wp.vec3(*map(float, frame[:, 2]))
    r.width, r.height = int(w), int(h)
    r.lon0, r.dlon, r.lat0, r.dlat = lon0, dlon, lat0, dlat
    r.key = int(key)
    return r


def stream_key(seed: int, sensor_index: int) -> int:
    """``sensor_stream_key`` of simulator.kernels.sampling, in numpy (same bits)."""

    def h(x: int) -> int:
        x &= 0xFFFFFFFF
        state = (x * 747796405 + 2891336453) & 0xFFFFFFFF
        word = (((state >> ((state >> 28) + 4)) ^ state) * 277803737) & 0xFFFFFFFF
        return ((word >> 22) ^ word) & 0xFFFFFFFF

    return h((seed & 0xFFFFFFFF) ^ h(sensor_index + 0x9E3779B9)) >> 1


def integrals(stats: RunningStats, omega: np.ndarray, delta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Stratified sphere integrals and their standard errors, each (22, 2).

    Parameters
    ----------
    stats : RunningStats
        Per pixel (P rows), the 22 × 2 integrands' statistics.
    omega : ndarray, shape (P,)
        Pixel solid angles, sr.
    delta : ndarray, shape (22, 2)
        The delta lights' exact part.
    """
    n = stats.count.astype(np.float64)[:, None]
    mean = stats.mean[:, : _Q * _C]
    with np.errstate(invalid="ignore", divide="ignore"):
        var_mean = np.where(n > 1, stats.m2[:, : _Q * _C] / (n * (n - 1.0)), np.inf)
    val = (omega[:, None] * mean).sum(axis=0).reshape(_Q, _C) + delta
    se = np.sqrt((omega[:, None] ** 2 * var_mean).sum(axis=0)).reshape(_Q, _C)
    return val, se


def probe_result(sensor: Sensor, frame: np.ndarray, stats: RunningStats, omega: np.ndarray, delta: np.ndarray,
                 passes: int, seconds: float, bad: int, target_met: bool | None) -> ProbeResult:  # fmt: skip
    """A finished probe's :class:`ProbeResult` from its per-pixel statistics
    (see :func:`integrals`); the vector irradiance's covariances come from
    the pair sums, Cov(v_i, v_j) = (Var(v_i + v_j) − Var v_i − Var v_j)/2."""
    w, h = sensor.resolution
    n_pix = int(w) * int(h)
    val, se = integrals(stats, omega, delta)
    var = se**2
    cov = np.zeros((_C, 3, 3))
    for a in range(3):
        cov[:, a, a] = var[7 + a]
    for q, (a, b) in zip((19, 20, 21), ((0, 1), (0, 2), (1, 2))):
        cov[:, a, b] = cov[:, b, a] = 0.5 * (var[q] - var[7 + a] - var[7 + b])
    se_all = stats.stderr()
    mean = stats.mean[:, : _Q * _C].reshape(n_pix, _Q, _C)[:, 0, :]
    pse = se_all[:, : _Q * _C].reshape(n_pix, _Q, _C)[:, 0, :]
    colour = colour_se = None
    if stats.mean.shape[1] > _Q * _C:
        colour = stats.mean[:, _Q * _C:].reshape(h, w, N_COLOUR).copy()
        colour_se = se_all[:, _Q * _C:].reshape(h, w, N_COLOUR).copy()
    warnings = []
    if bad:
        warnings.append(f"probe {sensor.name}: {bad} non-finite samples were counted as 0")
    return ProbeResult(
        sensor=sensor,
        frame=frame,
        radiance=mean.reshape(h, w, _C).copy(),
        radiance_stderr=pse.reshape(h, w, _C).copy(),
        solid_angle_sr=omega.reshape(h, w),
        integrals=val[:19],
        integrals_stderr=se[:19],
        vector_cov=cov,
        delta=delta[:19],
        passes=passes,
        samples=passes * n_pix,
        seconds=seconds,
        non_finite=bad,
        target_met=target_met,
        warnings=warnings,
        colour=colour,
        colour_stderr=colour_se,
    )
