"""A sensor head's angular response r(θ, φ): how it answers a collimated beam, relative to normal incidence.

A modelled sensor reads ``∫ L(ω) r(ω) dω`` over its hemisphere (an ideal
cosine head, r = cos θ, reads the irradiance). Three ways to state r:

- ``cos_power = n``: r = cosⁿ θ (n = 1: the ideal cosine);
- ``half_power_angle_deg = θ½``: the same power with r(θ½) = ½, so
  n = ln ½ / ln cos θ½ (θ½ = 60°: the cosine);
- ``table = "head.csv"``: a datasheet curve, linear in θ between rows (and
  in azimuth between columns), normalised to 1 at normal incidence, 0 past
  its last angle::

      # comment lines start with '#'
      angle_deg,response                       (rotationally symmetric)
      angle_deg,response_0,response_90,...     (columns at azimuths 0°, 90°, ...)

  Angles in [0°, 90°], strictly increasing from 0°; responses ≥ 0, > 0 at
  0°; azimuths in [0°, 360°), increasing, measured in the sensor's plane from
  its azimuth reference.

:class:`AngularResponse` evaluates r on the host (numpy), integrates it
exactly, gives the CIE f2 index and builds the device record's tables
(:mod:`simulator.kernels.optics` draws directions by them).

References
----------
ISO/CIE 19476:2014 (CIE S 023/E:2013), "Characterization of the performance
of illuminance meters and luminance meters", directional response f2;
docs/REFERENCES.md §Sensor models.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from simulator.errors import UserError, require_file

__all__ = ["AngularResponse", "cos_power", "half_power", "read_table", "F2_LIMIT_DEG", "SAMPLING_ROWS",
           "AZIMUTH_COLS", "table_from_arrays"]

#: the upper limit of f2's integral over the angle of incidence, degrees (ISO/CIE 19476: 85°)
F2_LIMIT_DEG = 85.0
#: θ bins of the device's sampling table, over [0, last angle]
SAMPLING_ROWS = 256
#: φ bins of the sampling table of a head with azimuth columns (5° each)
AZIMUTH_COLS = 72


@dataclass(frozen=True)
class AngularResponse:
    """r(θ, φ), relative to normal incidence.

    Attributes
    ----------
    name : str
        What it is, for records: ``"cos^2"``, ``"half-power 30°"``, a file name.
    kind : {"power", "table"}
    exponent : float
        ``power``: n of cosⁿ θ.
    theta_deg : ndarray, shape (m,)
        ``table``: the angles of incidence, degrees, from 0, increasing, ≤ 90.
    phi_deg : ndarray, shape (k,)
        ``table``: the azimuths of its columns, degrees in [0, 360); ``(0,)`` for a symmetric head.
    values : ndarray, shape (k, m)
        ``table``: r at (phi_deg[i], theta_deg[j]), 1 at normal incidence.
    notes : tuple of str
    """

    name: str
    kind: str
    exponent: float = 1.0
    theta_deg: np.ndarray = field(default_factory=lambda: np.zeros(0))
    phi_deg: np.ndarray = field(default_factory=lambda: np.zeros(1))
    values: np.ndarray = field(default_factory=lambda: np.zeros((1, 0)))
    notes: tuple[str, ...] = ()

    def digest(self) -> str:
        """SHA-256 (hex, 16 digits) of what r is: its kind, exponent, angles, azimuths and values (a study's
        chunk store keys readings by it)."""
        import hashlib

        h = hashlib.sha256(f"{self.kind}|{self.exponent!r}".encode())
        for a in (self.theta_deg, self.phi_deg, self.values):
            h.update(np.ascontiguousarray(a, np.float64).tobytes())
        return h.hexdigest()[:16]

    @property
    def symmetric(self) -> bool:
        """Whether r depends on θ only."""
        return self.kind == "power" or len(self.phi_deg) == 1

    @property
    def is_cosine(self) -> bool:
        """An ideal cosine head (r = cos θ exactly): today's irradiance."""
        return self.kind == "power" and self.exponent == 1.0

    # ---------------------------------------------------------------- evaluation

    def _column(self, k: int, theta_deg: np.ndarray) -> np.ndarray:
        out = np.interp(theta_deg, self.theta_deg, self.values[k])
        return np.where(theta_deg > self.theta_deg[-1], 0.0, out)

    def response(self, theta_deg, phi_deg=0.0) -> np.ndarray:
        """r at angles of incidence ``theta_deg`` and azimuths ``phi_deg`` (degrees, broadcast); 0 past 90°."""
        th = np.asarray(theta_deg, float)
        ph = np.mod(np.asarray(phi_deg, float), 360.0)
        th, ph = np.broadcast_arrays(th, ph)
        if self.kind == "power":
            c = np.cos(np.radians(np.clip(th, 0.0, 90.0)))
            return np.where(th < 90.0, np.maximum(c, 0.0) ** self.exponent, 0.0)
        if self.symmetric:
            return self._column(0, th)
        # linear in φ between columns, periodic
        knots = np.append(self.phi_deg, self.phi_deg[0] + 360.0)
        cols = [self._column(k, th) for k in range(len(self.phi_deg))]
        cols.append(cols[0])
        cols = np.stack(cols)  # (k + 1, ...)
        ph = np.where(ph < self.phi_deg[0], ph + 360.0, ph)
        i = np.clip(np.searchsorted(knots, ph, side="right") - 1, 0, len(knots) - 2)
        f = (ph - knots[i]) / (knots[i + 1] - knots[i])
        r0 = np.take_along_axis(cols, i[None], 0)[0]
        r1 = np.take_along_axis(cols, (i + 1)[None], 0)[0]
        return r0 + f * (r1 - r0)

    def _theta_integral(self, k: int) -> float:
        """∫₀^{π/2} r(θ, φ_k) sin θ dθ, exact for r linear in θ on each interval:
        ∫ (a + bθ) sin θ dθ = −(a + bθ) cos θ + b sin θ."""
        t = np.radians(self.theta_deg)
        v = self.values[k]
        t0, t1, v0, v1 = t[:-1], t[1:], v[:-1], v[1:]
        b = (v1 - v0) / (t1 - t0)
        a = v0 - b * t0
        prim = lambda x: -(a + b * x) * np.cos(x) + b * np.sin(x)  # noqa: E731
        return float(np.sum(prim(t1) - prim(t0)))

    def integral_sr(self) -> float:
        """∫ r dω over the hemisphere, sr: 2π/(n + 1) for cosⁿ; exact for a table (linear in θ, and in φ
        the trapezoid rule, which is exact for r linear in φ between columns). The cosine's is π."""
        if self.kind == "power":
            return 2.0 * math.pi / (self.exponent + 1.0)
        cols = np.array([self._theta_integral(k) for k in range(len(self.phi_deg))])
        if self.symmetric:
            return 2.0 * math.pi * float(cols[0])
        phi = np.radians(np.append(self.phi_deg, self.phi_deg[0] + 360.0))
        c = np.append(cols, cols[0])
        return float(np.sum(0.5 * (c[1:] + c[:-1]) * np.diff(phi)))

    def f2(self) -> float:
        """The directional response index f2 (ISO/CIE 19476 §5.5.4), as a fraction:
        ``∫₀^{85°} |r(ε)/(r(0)·cos ε) − 1| sin 2ε dε`` along each azimuth of the table, the largest
        (a symmetric head: its one value). Midpoint rule on 0.001° steps (error under 1e-7)."""
        n = int(F2_LIMIT_DEG * 1000)
        eps = (np.arange(n) + 0.5) * (F2_LIMIT_DEG / n)
        d = math.radians(F2_LIMIT_DEG / n)
        w = np.sin(2.0 * np.radians(eps)) * d
        out = 0.0
        for phi in ([0.0] if self.symmetric else self.phi_deg):
            r = self.response(eps, phi)
            r0 = float(self.response(0.0, phi))
            out = max(out, float(np.sum(np.abs(r / (r0 * np.cos(np.radians(eps))) - 1.0) * w)))
        return out

    # ---------------------------------------------------------------- device tables

    def sampling_tables(self, rows: int = SAMPLING_ROWS) -> dict:
        """The piecewise-constant table :func:`simulator.kernels.optics.sample_optics` draws a table head's
        directions from.

        Row j covers θ ∈ [j, j + 1)·Δθ, Δθ = (last angle)/rows, column i φ ∈ [i, i + 1)·2π/cols (one column
        for a symmetric head). A bin's weight is its mean r (a 5 × 5 grid with its edges) times its solid
        angle, at least a thousandth of its largest r (at its corners and the table's knots inside it,
        where a bilinear r peaks) times the solid angle, so every direction with r > 0 can be drawn.

        Returns
        -------
        dict
            ``d_theta`` (rad), ``rows``, ``cols``, ``marg`` (rows + 1), ``cond`` (rows × (cols + 1)),
            ``row_mu`` (rows: cos of each row's top), ``row_dmu`` (rows: cos θ_j − cos θ_{j+1}), float64.
        """
        cols = 1 if self.symmetric else AZIMUTH_COLS
        top = float(self.theta_deg[-1])
        edges = np.linspace(0.0, top, rows + 1)
        phi_edges = np.linspace(0.0, 360.0, cols + 1)
        t_rad = np.radians(edges)
        # cos θ_j − cos θ_{j+1} = 2 sin((θ_{j+1} + θ_j)/2) sin((θ_{j+1} − θ_j)/2), without cancellation
        dmu = 2.0 * np.sin(0.5 * (t_rad[1:] + t_rad[:-1])) * np.sin(0.5 * (t_rad[1:] - t_rad[:-1]))
        w = np.zeros((rows, cols))
        f = np.linspace(0.0, 1.0, 5)
        for j in range(rows):
            th = edges[j] + f * (edges[j + 1] - edges[j])
            inside = self.theta_deg[(self.theta_deg > edges[j]) & (self.theta_deg < edges[j + 1])]
            th_peak = np.concatenate([edges[j:j + 2], inside])
            for i in range(cols):
                ph = phi_edges[i] + f * (phi_edges[i + 1] - phi_edges[i])
                r = self.response(th[:, None], ph[None, :])
                ph_in = (self.phi_deg[(self.phi_deg > phi_edges[i]) & (self.phi_deg < phi_edges[i + 1])]
                         if not self.symmetric else np.zeros(0))
                peak = float(np.max(self.response(th_peak[:, None], np.concatenate([phi_edges[i:i + 2], ph_in])[None, :])))
                w[j, i] = dmu[j] * max(float(r.mean()), 1e-3 * peak)
        row_w = w.sum(axis=1)
        total = row_w.sum()
        if not total > 0:
            raise ValueError(f"{self.name}: the response is 0 everywhere")
        marg = np.concatenate([[0.0], np.cumsum(row_w) / total])
        marg[-1] = 1.0
        cond = np.zeros((rows, cols + 1))
        for j in range(rows):
            if row_w[j] > 0:
                cond[j, 1:] = np.cumsum(w[j]) / row_w[j]
            else:  # never drawn: any valid CDF
                cond[j, 1:] = np.arange(1, cols + 1) / cols
            cond[j, -1] = 1.0
        return {"d_theta": math.radians(top) / rows, "rows": rows, "cols": cols, "marg": marg, "cond": cond,
                "row_mu": np.cos(t_rad[:-1]), "row_dmu": dmu}


def cos_power(n: float, name: str | None = None) -> AngularResponse:
    """r = cosⁿ θ, n > 0 (n = 1: the ideal cosine)."""
    n = float(n)
    if not (math.isfinite(n) and n > 0):
        raise ValueError(f"cos_power must be a positive number, not {n!r}")
    return AngularResponse(name or ("cosine" if n == 1.0 else f"cos^{n:g}"), "power", exponent=n)


def half_power(angle_deg: float) -> AngularResponse:
    """cosⁿ θ with r(θ½) = ½: n = ln ½ / ln cos θ½, 0 < θ½ < 90° (60°: the cosine)."""
    a = float(angle_deg)
    if not (math.isfinite(a) and 0.0 < a < 90.0):
        raise ValueError(f"half_power_angle_deg must be between 0 and 90, not {angle_deg!r}")
    n = math.log(0.5) / math.log(math.cos(math.radians(a)))
    return AngularResponse(f"half-power {a:g}° (cos^{n:.4g})", "power", exponent=n)


def _azimuth(header: str, path, line: int) -> float:
    """The azimuth of a ``response_<deg>`` column header."""
    body = header[len("response_"):]
    try:
        phi = float(body)
    except ValueError:
        raise UserError(f"{path}:{line}: column {header!r}: expected 'response' or 'response_<azimuth in degrees>'") from None
    if not (math.isfinite(phi) and 0.0 <= phi < 360.0):
        raise UserError(f"{path}:{line}: column {header!r}: the azimuth must be in [0, 360) degrees")
    return phi


def read_table(path) -> AngularResponse:
    """An angular response table from a CSV (see module docstring).

    Raises
    ------
    UserError
        One line naming the file and row: a missing file, a bad header, a row that is not all finite
        numbers, an angle outside [0°, 90°] or not above the previous row's, a first angle other than 0°,
        a negative response, a response of 0 at normal incidence, azimuth columns not increasing, fewer
        than two rows.
    """
    p = require_file(path)
    try:
        text = p.read_text(encoding="utf-8-sig")
    except (OSError, UnicodeDecodeError) as e:
        raise UserError(f"{path}: cannot read the angular response file: {e}") from None
    header: list[str] | None = None
    phis: list[float] = []
    rows: list[list[float]] = []
    angles: list[float] = []
    for n, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        cells = [c.strip().strip('"').strip() for c in line.split(",")]
        while len(cells) > 2 and cells[-1] == "":
            cells.pop()
        if header is None:
            if len(cells) < 2 or cells[0] != "angle_deg":
                raise UserError(f"{path}:{n}: angular response header must be 'angle_deg,response' or "
                                f"'angle_deg,response_<azimuth>,...', not {line!r}")
            if len(cells) == 2 and cells[1] == "response":
                phis = [0.0]
            else:
                for c in cells[1:]:
                    if not c.startswith("response_"):
                        raise UserError(f"{path}:{n}: column {c!r}: expected 'response' or 'response_<azimuth in degrees>'")
                phis = [_azimuth(c, path, n) for c in cells[1:]]
                if any(b <= a for a, b in zip(phis, phis[1:])):
                    raise UserError(f"{path}:{n}: the azimuth columns must increase ({', '.join(cells[1:])})")
            header = cells
            continue
        if len(cells) != len(header):
            raise UserError(f"{path}:{n}: expected {len(header)} values ({', '.join(header)}), got {len(cells)}")
        try:
            vals = [float(c) for c in cells]
        except ValueError:
            raise UserError(f"{path}:{n}: not a number in {line!r}") from None
        if not all(math.isfinite(v) for v in vals):
            raise UserError(f"{path}:{n}: values must be finite, got {line!r}")
        a = vals[0]
        if a < 0.0 or a > 90.0:
            raise UserError(f"{path}:{n}: angle {a:g}° is outside 0–90°: a head's response is over its hemisphere")
        if angles and a <= angles[-1]:
            raise UserError(f"{path}:{n}: angle {a:g}° is not above the previous row's ({angles[-1]:g}°): "
                            "angles must increase")
        if not angles and a != 0.0:
            raise UserError(f"{path}:{n}: the first angle must be 0° (normal incidence), not {a:g}°")
        for h, v in zip(header[1:], vals[1:]):
            if v < 0.0:
                raise UserError(f"{path}:{n}: {h} {v:g} is negative")
        if not angles and any(v <= 0.0 for v in vals[1:]):
            raise UserError(f"{path}:{n}: the response at normal incidence is 0: the relative response "
                            "is normalised there, so it must be positive")
        angles.append(a)
        rows.append(vals[1:])
    if header is None:
        raise UserError(f"{path}: empty angular response file (expected an 'angle_deg,response' header and rows)")
    if len(angles) < 2:
        raise UserError(f"{path}: the angular response needs at least 2 rows, has {len(angles)}")
    values = np.array(rows, float).T  # (k, m)
    r0 = values[:, 0]
    notes = []
    if np.ptp(r0) > 0.01 * r0.mean():
        notes.append(f"{p.name}: the azimuth columns differ at 0° ({r0.min():g}–{r0.max():g}); each is "
                     "normalised by their mean")
    values = values / r0.mean()
    if angles[-1] < 90.0 and float(values[:, -1].max()) > 0.01:
        notes.append(f"{p.name} ends at {angles[-1]:g}° with a response of {float(values[:, -1].max()):.3g}; "
                     "read as 0 beyond it")
    return AngularResponse(p.name, "table", theta_deg=np.array(angles), phi_deg=np.array(phis), values=values,
                           notes=tuple(notes))


def table_from_arrays(name: str, theta_deg, values, phi_deg=(0.0,)) -> AngularResponse:
    """A table response from arrays (bundled models and tests), checked as a file would be."""
    th = np.asarray(theta_deg, float)
    v = np.atleast_2d(np.asarray(values, float))
    ph = np.asarray(phi_deg, float)
    if th[0] != 0.0 or np.any(np.diff(th) <= 0) or th[-1] > 90.0 or v.shape != (len(ph), len(th)):
        raise ValueError(f"{name}: angles must rise from 0 to at most 90°, one value per angle and azimuth")
    if np.any(v < 0) or np.any(v[:, 0] <= 0):
        raise ValueError(f"{name}: responses must be ≥ 0 and positive at 0°")
    return AngularResponse(name, "table", theta_deg=th, phi_deg=ph, values=v / v[:, 0].mean())
