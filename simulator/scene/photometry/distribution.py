"""A type C goniometric intensity distribution I(θ, φ), candela.

Angles (degrees), type C photometry (CIE 121:1996 §2; IES LM-63-2019 §5):
θ, the vertical angle, is 0° at the nadir (straight down the luminaire's
axis) and 180° at the zenith; φ, the horizontal angle, names the C-plane,
0° ≤ φ < 360°, counter-clockwise seen from above the luminaire. In a light's
frame (UsdLux ShapingAPI), θ = 0 is the light's −Z axis, φ = 0 its +X axis
and φ = 90° its +Y axis: :func:`angles_from_local` maps a direction there.

A file measures I on a grid of (θ, φ) and, through its symmetry, implies the
rest; the readers unfold the symmetry to a full grid φ ∈ [0°, 360°] (the
360° plane repeats the 0° plane) before building the distribution.

Interpolation: bilinear in (θ, φ) between measured angles — exact at the
measured angles, linear along each axis between them, periodic in φ
(the cell from the last measured plane to 360° interpolates toward the 0°
plane). Outside the measured θ range (a downlight file that stops at 90°)
the intensity is 0.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from simulator.errors import UserError, require_file

__all__ = ["GoniometricDistribution", "angles_from_local", "read_file_text", "unfold_type_c"]

#: angles closer than this (degrees) are the same measured angle
ANGLE_TOL_DEG = 1e-6


@dataclass
class GoniometricDistribution:
    """Luminous intensity on a full type C grid.

    Attributes
    ----------
    theta_deg : ndarray, shape (T,)
        Vertical angles, strictly increasing, within [0, 180].
    phi_deg : ndarray, shape (P,)
        Horizontal angles, strictly increasing, from 0 to 360 inclusive (the
        360° plane equals the 0° plane); P = 2 for a rotationally symmetric
        distribution (0° and 360°).
    candela : ndarray, shape (P, T)
        I(φ_j, θ_i) in cd, all multipliers of the file applied.
    rated_lumens : float or None
        Lamp lumens the file's candelas belong to (relative photometry), or
        None for absolute photometry (LM-63 lumens per lamp = −1).
    source : str
        The file it came from (for messages).
    symmetry : str
        The file's symmetry: ``"rotational"``, ``"quadrant"``,
        ``"bilateral"`` (about the 0–180° plane), ``"bilateral-90"`` (about
        the 90–270° plane) or ``"none"``.
    """

    theta_deg: np.ndarray
    phi_deg: np.ndarray
    candela: np.ndarray
    rated_lumens: float | None = None
    source: str = ""
    symmetry: str = "none"
    keywords: dict = field(default_factory=dict)

    def __post_init__(self):
        self.theta_deg = np.asarray(self.theta_deg, float)
        self.phi_deg = np.asarray(self.phi_deg, float)
        self.candela = np.asarray(self.candela, float)
        t, p = self.theta_deg, self.phi_deg
        where = self.source or "photometric data"
        if t.ndim != 1 or len(t) < 1 or np.any(np.diff(t) <= 0) or t[0] < -ANGLE_TOL_DEG or t[-1] > 180 + ANGLE_TOL_DEG:
            raise UserError(f"{where}: vertical angles must increase strictly within 0–180°")
        if p.ndim != 1 or len(p) < 2 or np.any(np.diff(p) <= 0) or abs(p[0]) > ANGLE_TOL_DEG or abs(p[-1] - 360) > ANGLE_TOL_DEG:
            raise UserError(f"{where}: horizontal angles must increase strictly from 0° to 360°")
        if self.candela.shape != (len(p), len(t)):
            raise UserError(f"{where}: candela table has shape {self.candela.shape}, expected {(len(p), len(t))}")
        if not np.all(np.isfinite(self.candela)) or np.any(self.candela < 0):
            raise UserError(f"{where}: candela values must be finite and ≥ 0")
        if np.max(np.abs(self.candela[0] - self.candela[-1])) > 1e-9 * max(1.0, float(np.max(self.candela))):
            raise UserError(f"{where}: the 360° plane differs from the 0° plane")

    # ------------------------------------------------------------ evaluation

    def candela_at(self, theta_deg, phi_deg) -> np.ndarray:
        """I(θ, φ), cd, by bilinear interpolation (see the module docstring).

        Parameters
        ----------
        theta_deg, phi_deg : array_like
            Vertical and horizontal angles, degrees, broadcast together; φ
            is taken modulo 360°.

        Returns
        -------
        ndarray
            Intensity, cd, of the broadcast shape; 0 outside the measured θ range.
        """
        th, ph = np.broadcast_arrays(np.asarray(theta_deg, float), np.asarray(phi_deg, float))
        ph = np.mod(ph, 360.0)
        t, p, c = self.theta_deg, self.phi_deg, self.candela
        inside = (th >= t[0] - ANGLE_TOL_DEG) & (th <= t[-1] + ANGLE_TOL_DEG)
        if len(t) == 1:
            it = np.zeros(th.shape, int)
            ft = np.zeros(th.shape)
            it1 = it
        else:
            it = np.clip(np.searchsorted(t, th, side="right") - 1, 0, len(t) - 2)
            ft = np.clip((th - t[it]) / (t[it + 1] - t[it]), 0.0, 1.0)
            it1 = it + 1
        jp = np.clip(np.searchsorted(p, ph, side="right") - 1, 0, len(p) - 2)
        fp = np.clip((ph - p[jp]) / (p[jp + 1] - p[jp]), 0.0, 1.0)
        v0 = c[jp, it] * (1 - ft) + c[jp, it1] * ft
        v1 = c[jp + 1, it] * (1 - ft) + c[jp + 1, it1] * ft
        return np.where(inside, v0 * (1 - fp) + v1 * fp, 0.0)

    #: the name the specification uses
    candela_fn = candela_at

    def __call__(self, theta_deg, phi_deg) -> np.ndarray:
        return self.candela_at(theta_deg, phi_deg)

    def candela_local(self, d_local: np.ndarray) -> np.ndarray:
        """I toward unit directions in the luminaire's frame (θ = 0 along −Z,
        φ = 0 along +X, φ = 90° along +Y), shape (..., 3) → (...)."""
        th, ph = angles_from_local(d_local)
        return self.candela_at(th, ph)

    # ------------------------------------------------------------ integrals

    def total_lumens(self) -> float:
        """Φ = ∫ I dΩ = ∫∫ I(θ, φ) sinθ dθ dφ over the sphere, lm.

        Notes
        -----
        Integrates the bilinear interpolant exactly: over a cell the
        interpolant is linear in φ (so its φ-integral is the trapezoid
        rule, exact), and for each φ linear in θ, f(θ) = f₀(θ₁ − θ)/h +
        f₁(θ − θ₀)/h, whose product with sinθ integrates in closed form with
        ∫ sinθ dθ = cosθ₀ − cosθ₁ and ∫ θ sinθ dθ = [sinθ − θ cosθ]. So the
        only error against a smooth true distribution is the interpolation
        error, ≤ (h²/8)·max|∂²I/∂θ²| + (k²/8)·max|∂²I/∂φ²| per point
        (h, k the steps in radians), which integrates to at most 4π times
        that; an isotropic or φ-independent distribution linear in θ is
        integrated exactly.
        """
        t = np.radians(self.theta_deg)
        p = np.radians(self.phi_deg)
        c = self.candela
        # φ-integral of each θ column (trapezoid, exact for the interpolant): shape (T,)
        col = np.sum(0.5 * (c[1:] + c[:-1]) * np.diff(p)[:, None], axis=0)
        if len(t) == 1:
            return 0.0
        t0, t1 = t[:-1], t[1:]
        h = t1 - t0
        s_int = np.cos(t0) - np.cos(t1)  # ∫ sinθ
        ts_int = (np.sin(t1) - t1 * np.cos(t1)) - (np.sin(t0) - t0 * np.cos(t0))  # ∫ θ sinθ
        w0 = (t1 * s_int - ts_int) / h  # ∫ (θ1 − θ)/h sinθ
        w1 = (ts_int - t0 * s_int) / h  # ∫ (θ − θ0)/h sinθ
        return float(np.sum(col[:-1] * w0 + col[1:] * w1))

    def max_candela(self) -> float:
        return float(np.max(self.candela))

    # ------------------------------------------------------------ kernel table

    def regular_table(self, max_cells: int = 1 << 20) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The distribution on a regular (θ, φ) grid that contains every
        measured angle, so that bilinear interpolation on it reproduces
        :meth:`candela_at` exactly.

        The θ grid spans 0–180° (zero outside the measured range, which then
        falls off linearly over one regular step past a measured end that
        is not 0° or 180°; the step is the largest one dividing every
        measured spacing, at least 0.1°); the φ grid spans 0–360° likewise.

        Returns
        -------
        theta_deg : ndarray, shape (T,)
        phi_deg : ndarray, shape (P,)
        table : ndarray, shape (P, T)
            Candela.
        """
        dt = _common_step(self.theta_deg, 180.0)
        dp = _common_step(self.phi_deg, 360.0)
        nt = int(round(180.0 / dt)) + 1
        np_ = int(round(360.0 / dp)) + 1
        if nt * np_ > max_cells:
            raise UserError(f"{self.source}: measured angles need a {nt}×{np_} table (over {max_cells} cells)")
        th = np.linspace(0.0, 180.0, nt)
        ph = np.linspace(0.0, 360.0, np_)
        table = self.candela_at(th[None, :], ph[:, None])
        return th, ph, table


def _common_step(angles: np.ndarray, span: float, floor: float = 0.1) -> float:
    """Largest step (degrees, ≥ ``floor``) that divides ``span`` and puts a
    grid node on every angle (within 1e-6°); ``floor`` if none does."""
    cands = sorted({span / n for n in range(1, int(span / floor) + 1)}, reverse=True)
    for s in cands:
        r = angles / s
        if np.all(np.abs(r - np.round(r)) < 1e-6 / s):
            return s
    return floor


def angles_from_local(d_local) -> tuple[np.ndarray, np.ndarray]:
    """(θ, φ) in degrees of unit directions in a luminaire's frame: θ from
    −Z (cosθ = −z), φ = atan2(y, x) in [0°, 360°)."""
    d = np.asarray(d_local, float)
    th = np.degrees(np.arccos(np.clip(-d[..., 2], -1.0, 1.0)))
    ph = np.mod(np.degrees(np.arctan2(d[..., 1], d[..., 0])), 360.0)
    return th, ph


def read_file_text(path) -> str:
    """The text of a photometric file, decoded as Latin-1 (any byte is a character).

    IES LM-63 and EULUMDAT files predate a stated encoding; Latin-1 reads
    every byte, so an odd character in a keyword never stops the read.

    Raises
    ------
    UserError
        One line naming ``path``: missing, not a file, or unreadable.
    """
    p = require_file(path)
    try:
        return p.read_bytes().decode("latin-1")
    except OSError as e:
        raise UserError(f"{path}: cannot read ({e.strerror})") from None


def unfold_type_c(theta_deg, phi_deg, candela, where: str) -> tuple[np.ndarray, np.ndarray, str]:
    """Unfold measured C-planes to the full 0–360° grid by their symmetry.

    Parameters
    ----------
    theta_deg : ndarray (T,)
    phi_deg : ndarray (P,)
        Measured horizontal angles: a single plane (rotational symmetry),
        0–90° (quadrant symmetry: mirrored about the 0–180° and 90–270°
        planes), 0–180° (bilateral about the 0–180° plane), 90–270°
        (bilateral about the 90–270° plane), or 0–360°/0–<360° (none).
    candela : ndarray (P, T)

    Returns
    -------
    phi_full : ndarray (P',), 0 … 360
    candela_full : ndarray (P', T)
    symmetry : str
    """
    p = np.asarray(phi_deg, float)
    c = np.asarray(candela, float)
    tol = 1e-6
    if len(p) == 1:
        return np.array([0.0, 360.0]), np.vstack([c[0], c[0]]), "rotational"
    if np.any(np.diff(p) <= 0):
        raise UserError(f"{where}: horizontal angles must increase strictly")
    first, last = p[0], p[-1]
    if abs(first) < tol and abs(last - 90) < tol:
        # I(180 − φ) = I(φ) gives 90–180°, then I(360 − φ) = I(φ) the rest
        half_p = np.concatenate([p, (180 - p[::-1])[1:]])
        half_c = np.vstack([c, c[::-1][1:]])
        return (*_mirror_0_180(half_p, half_c), "quadrant")
    if abs(first) < tol and abs(last - 180) < tol:
        return (*_mirror_0_180(p, c), "bilateral")
    if abs(first - 90) < tol and abs(last - 270) < tol:
        # mirror about the 90–270° plane: I(180 − φ) = I(φ) covers 270–360° and 0–90°
        ang = np.concatenate([p, np.mod(180 - p[1:-1], 360.0)])
        val = np.vstack([c, c[1:-1]])
        order = np.argsort(ang, kind="stable")
        ang, val = ang[order], val[order]
        if ang[0] > tol:  # 0° itself is the mirror of 180°, which is measured
            raise UserError(f"{where}: 90–270° planes do not reach 0°")
        ang[0] = 0.0
        return np.concatenate([ang, [360.0]]), np.vstack([val, val[:1]]), "bilateral-90"
    if abs(first) < tol and abs(last - 360) < tol:
        # A measured 360° plane is the 0° plane measured again; where the two
        # readings differ (measurement noise), both become their mean so
        # that I stays periodic in φ.
        c = c.copy()
        c[0] = c[-1] = 0.5 * (c[0] + c[-1])
        return p.copy(), c, "none"
    if abs(first) < tol and 180 < last < 360:
        return np.concatenate([p, [360.0]]), np.vstack([c, c[:1]]), "none"
    raise UserError(f"{where}: horizontal angles {first:g}–{last:g}° match no type C symmetry (0, 0–90, 0–180, 90–270, 0–360)")


def _mirror_0_180(p: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """0–180° planes → 0–360° by I(360 − φ) = I(φ)."""
    ang = np.concatenate([p, (360 - p[::-1])[1:]])
    val = np.vstack([c, c[::-1][1:]])
    return ang, val
