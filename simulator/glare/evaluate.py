"""A view's E_v, DGP, DGPs, UGR and glare sources from its pixel statistics, each with its standard error.

Inputs
------
- The traced map's pixels (:mod:`.view`): solid angle ω_p, centre direction
  d_p, and per pixel the mean over its passes of the luminance L and of the
  E_v integrand e = L·(d·v) (the kernel's L·ω components projected on the
  view direction: exact, not the pixel centre's cosine), with the variance
  of each mean. Pixels are independent (each has its own random stream).
- Each sun in front of the eye, as the probe kernel's delta mode read it
  (:mod:`simulator.engine.glare`): the normal illuminance E_l reaching the
  eye along the disk's centre, through glazing at its transmittance. The
  disk is a source of luminance L = E_l/(π·sin²α) over Ω = 2π(1 − cos α):
  L·ω = Ω·L, L²ω = Ω·L², no variance.
- The delta lights' exact E_v (point lights, angle-0 distant lights: no
  size, so no source).

Estimates
---------
- E_v = Σ_p ω_p·ē_p + Σ_suns E_l·(s·v) + E_delta, its variance the map's
  (the rest is exact).
- Sources (:func:`.sources.find_sources`) on the pixel means and the suns.
- A source's L²ω. With S = Σ ω_p·L̂_p (its L·ω), (Ŝ)² overestimates S² by
  Var(Ŝ) = Σ ω_p²·Var(L̂_p): pixel noise alone raises every source's L²ω.
  The estimate used is (Ŝ² − V̂)/ω, V̂ = Σ ω_p²·s_p²/n_p, unbiased for
  S²/ω given the source's pixels (E[L̂²] − Var L̂ = L² pixel by pixel;
  products of different pixels are independent). Which pixels are a source
  is decided on the same means; that selection is not corrected (a pixel
  near the threshold joins a source when its noise is up): it is measured
  in docs/DESIGN.md §Glare.
- G = Σ_k T_k/P_k², T_k the unbiased L²ω; DGP, DGPs and UGR from the
  formulas of :mod:`.indices`; the background luminance L_b = (E_v − E_dir)/π,
  E_dir the E_v of the source pixels (CIE 117 and evalglare's default).
- UGR's sources are lamps of one luminance, and a map pixel that a lamp's
  edge covers only in part reads below the threshold and is left out of
  the source (at 1.4° pixels a luminaire's L²ω read 6% low, UGR 0.4–0.7
  low against a fine picture). UGR therefore reads each map source with a
  core (pixels whose eight neighbours are in it) by its parts
  (:func:`_partial_pixels`): its core's luminance L_c, the local
  background L_g (the ring of free pixels two steps out), its covered
  solid angle Ω' = Σ ω·(L − L_g)/(L_c − L_g) over its pixels and the
  free ring around them, and L²ω = L_c²·Ω'; the ring's light above L_g
  joins E_dir. A uniform source is read the same at any pixel size; DGP
  keeps evalglare's S²/ω (daylight sources are not uniform).
- Standard errors by the delta method: each figure linearised in the pixel
  means, then summed over independent pixels. Within a pixel the covariance
  of L̂ and ē is taken as cos θ_p·Var(L̂) (θ_p at the pixel centre: the
  cosine varies by less than the pixel across it). UGR's two parts (source
  pixels in G, the others in L_b) are disjoint, so independent.

Pure numpy.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from simulator.glare import indices as ix
from simulator.glare.sources import GlareSettings, Sources, find_sources

__all__ = ["PixelStats", "pixel_stats", "SunReading", "GlareSource", "GlareEstimate", "evaluate"]

_LN10 = math.log(10.0)
#: the share of a sun's luminance that must reach the eye for its disk to count as seen
SUN_SEEN = 1e-3


@dataclass
class PixelStats:
    """Per pixel, both channels (radiometric, photometric): means and the variances of the means.

    Attributes
    ----------
    lum, lum_var : ndarray, shape (P, 2)
        Mean radiance (W m⁻² sr⁻¹, cd/m²) over the pixel, and the variance of that mean.
    ev, ev_var : ndarray, shape (P, 2)
        Mean of L·(d·v) (the pixel's E_v per sr) and its variance of the mean.
    count : ndarray, shape (P,)
        Passes drawn.
    """

    lum: np.ndarray
    lum_var: np.ndarray
    ev: np.ndarray
    ev_var: np.ndarray
    count: np.ndarray


def pixel_stats(count: np.ndarray, mean: np.ndarray, m2: np.ndarray, view: np.ndarray) -> PixelStats:
    """:class:`PixelStats` from a probe's running statistics (columns 2q + c of the probe kernel:
    q 0 the radiance, 7–9 L·ω, 19–21 the pair sums whose variances give the covariances of 7–9).

    Parameters
    ----------
    count : ndarray, shape (P,)
    mean, m2 : ndarray, shape (P, K)
    view : ndarray, shape (3,)
        Unit view direction (world frame).
    """
    n = count.astype(np.float64)[:, None]
    with np.errstate(invalid="ignore", divide="ignore"):
        var_sample = np.where(n > 1, m2 / np.maximum(n - 1.0, 1.0), 0.0)  # per-sample variance, (P, K)

    def col(q):
        return slice(2 * q, 2 * q + 2)

    lum = mean[:, col(0)]
    lum_var = var_sample[:, col(0)] / n
    comp = np.stack([mean[:, col(7 + a)] for a in range(3)], axis=-1)  # (P, 2, 3)
    ev = comp @ view
    var = [var_sample[:, col(7 + a)] for a in range(3)]
    cov = {}
    for q, (a, b) in zip((19, 20, 21), ((0, 1), (0, 2), (1, 2))):
        cov[(a, b)] = 0.5 * (var_sample[:, col(q)] - var[a] - var[b])
    ev_var_sample = sum(view[a] ** 2 * var[a] for a in range(3))
    ev_var_sample = ev_var_sample + sum(2.0 * view[a] * view[b] * c for (a, b), c in cov.items())
    return PixelStats(lum=lum, lum_var=lum_var, ev=ev, ev_var=np.maximum(ev_var_sample, 0.0) / n, count=count.copy())


@dataclass
class SunReading:
    """A sun disk as the eye sees it: its luminance at its centre (through glazing), over its whole disk.

    Attributes
    ----------
    name : str
        The DistantLight's prim path.
    direction : ndarray, shape (3,)
        Unit direction toward its centre.
    omega_sr : float
        The disk's solid angle Ω = 2π(1 − cos α).
    mean, mean_stderr : ndarray, shape (2,)
        The disk's radiance as seen (W m⁻² sr⁻¹, cd/m²), and its standard error (0: read exactly).
    mean_square : ndarray, shape (2,)
        The mean square of the radiance over the disk (its square, for a uniform disk).
    disk_cd_m2 : float
        The disk's own luminance (the light's).
    """

    name: str
    direction: np.ndarray
    omega_sr: float
    mean: np.ndarray
    mean_stderr: np.ndarray
    mean_square: np.ndarray
    disk_cd_m2: float = math.inf

    @property
    def cos_weighted_sr(self) -> float:
        """∫cos θ dω over the disk about its centre, π·sin²α: E_v of the disk is its luminance × this × cos σ
        (σ its angle from the view direction; exact while the disk lies wholly in front of the eye)."""
        cos_a = 1.0 - self.omega_sr / (2.0 * math.pi)
        return math.pi * (1.0 - cos_a) * (1.0 + cos_a)

    @property
    def angular_radius(self) -> float:
        """α, radians."""
        return math.acos(max(-1.0, 1.0 - self.omega_sr / (2.0 * math.pi)))

    @property
    def visible(self) -> bool:
        """The eye sees the disk: more than :data:`SUN_SEEN` of its luminance reaches it (through panes)."""
        return bool(self.mean[1] > SUN_SEEN * self.disk_cd_m2) and bool(self.mean[1] > 0.0)

    def effective(self) -> tuple[float, float]:
        """``(ω, L)`` of the disk's part in sight, photometric: L = E[x²]/x̄, ω = Ω·x̄²/E[x²]
        (so that L·ω = Ω·x̄ and L²·ω = Ω·E[x²])."""
        m, q = float(self.mean[1]), float(self.mean_square[1])
        if not m > 0.0 or not q > 0.0:
            return 0.0, 0.0
        return self.omega_sr * m * m / q, q / m


@dataclass
class GlareSource:
    """One glare source as reported: where, how large, how bright, and its share of the glare."""

    direction: np.ndarray  #: unit, world frame
    omega_sr: float
    luminance_cd_m2: float
    luminance_stderr_cd_m2: float
    position_index: float
    l2w: float  #: unbiased L²ω, cd²·m⁻⁴·sr
    ev_lx: float  #: its E_v
    sun: str = ""  #: the DistantLight it is, "" for pixels of the map
    peak: bool = False  #: split off by peak extraction
    pixels: int = 0


@dataclass
class GlareEstimate:
    """A view's figures (photometric) and E_v's radiometric twin, each with its standard error."""

    ev_lx: float
    ev_stderr_lx: float
    ev_W_m2: float
    ev_stderr_W_m2: float
    dgp: float
    dgp_stderr: float
    dgps: float
    dgps_stderr: float
    ugr: float
    ugr_stderr: float
    background_cd_m2: float
    direct_ev_lx: float  #: E_v of the sources (E_dir)
    mean_cd_m2: float  #: the view's mean luminance
    threshold_cd_m2: float
    task_cd_m2: float
    sources: list[GlareSource]
    labels: np.ndarray  #: (P + suns,): each map pixel's (then each sun's) source index, -1 for none
    dgp_capped: bool = False
    low_light_factor: float = 1.0
    notes: list[str] = field(default_factory=list)
    #: the jackknife's standard errors where they were taken (:mod:`simulator.engine.glare`), by field name
    jackknife: dict = field(default_factory=dict)

    @property
    def glare_term(self) -> float:
        """Σ L²ω/P² over the sources (cd²·m⁻⁴·sr)."""
        return float(sum(s.l2w / s.position_index**2 for s in self.sources))


def _pixel_half_sizes(shape: tuple[int, int], n: int) -> np.ndarray:
    """Each map pixel's angular half-diagonal, radians (the half map of :mod:`.view`; a one-row map of
    ``n`` pixels without a layout: 0)."""
    h, w = shape
    if h * w != n or h == 1:
        return np.zeros(n)
    dlon, dlat = math.pi / w, math.pi / h
    lat = 0.5 * math.pi - (np.arange(h) + 0.5) * dlat
    half = 0.5 * np.sqrt((dlon * np.cos(lat)) ** 2 + dlat**2)
    return np.repeat(half, w)


def _not_lone_noise(pix: PixelStats, shape: tuple[int, int], settings: GlareSettings, omega, dirs) -> np.ndarray:
    """Map pixels that may be source pixels: all but those above the threshold with no neighbour above it
    (8-neighbours in the map grid) and not above it by NOISE_Z standard errors (:mod:`.sources`, step 2)."""
    from simulator.glare.sources import NOISE_Z, threshold_cd_m2

    h, w = shape
    lum = pix.lum[:, 1]
    thr, _ = threshold_cd_m2(settings, dirs, omega, lum)
    hot = (lum > thr).reshape(h, w)
    pad = np.pad(hot, 1)
    near = np.zeros_like(hot)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            if dy or dx:
                near |= pad[1 + dy:1 + dy + h, 1 + dx:1 + dx + w]
    lone = (hot & ~near).reshape(-1)
    return ~lone | (lum - thr > NOISE_Z * np.sqrt(pix.lum_var[:, 1]))


def _dilate(m: np.ndarray) -> np.ndarray:
    """``m`` (H, W) grown by one pixel toward its 8 neighbours."""
    h, w = m.shape
    pad = np.pad(m, 1)
    out = np.zeros_like(m)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            out |= pad[1 + dy:1 + dy + h, 1 + dx:1 + dx + w]
    return out


def _partial_pixels(labels: np.ndarray, lum: np.ndarray, omega: np.ndarray, ev_pix: np.ndarray, shape: tuple[int, int],
                    k: int, skip: set) -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
    """UGR's L²ω of each map source read by its parts (module docstring), and the E_v of the light its free
    ring holds above the background.

    Parameters
    ----------
    labels, lum, omega, ev_pix : ndarray, shape (P,)
        Each map pixel's source (−1 for none), mean luminance (cd/m²), solid angle (sr) and E_v (lx).
    shape : (int, int)
        The map's (height, width).
    k : int
        Sources.
    skip : set of int
        Sources read as they are (those holding a sun disk).

    Returns
    -------
    (l2w, ev_ring) : ndarray (k,), ndarray (k,)
        NaN where a source has no core, no free ring two pixels out, or a core no brighter than that ring
        (then its L²ω is the usual one); 0 E_v there.
    """
    h, w = shape
    t = np.full(k, np.nan)
    e_ring = np.zeros(k)
    if h * w != len(lum) or h == 1:
        return t, e_ring
    lab, L, om, ev = labels.reshape(h, w), lum.reshape(h, w), omega.reshape(h, w), ev_pix.reshape(h, w)
    free = lab < 0
    for j in range(k):
        m = lab == j
        if j in skip or not m.any():
            continue
        grown = _dilate(m)
        core = m & ~_dilate(~m)
        ring = grown & ~m & free
        ring2 = _dilate(grown) & ~grown & free
        if not core.any() or not ring2.any():
            continue
        l_g = float((L[ring2] * om[ring2]).sum() / om[ring2].sum())
        l_c = float((L[core] * om[core]).sum() / om[core].sum())
        if l_c <= l_g:
            continue
        reg = m | ring
        covered = max(float(((L[reg] - l_g) * om[reg]).sum()), 0.0) / (l_c - l_g)
        t[j] = l_c * l_c * covered
        with np.errstate(invalid="ignore", divide="ignore"):
            e_ring[j] = float(np.sum(np.where(L[ring] > 0, ev[ring] * (L[ring] - l_g) / L[ring], 0.0)))
    return t, e_ring


def evaluate(pix: PixelStats, omega: np.ndarray, dirs: np.ndarray, frame: np.ndarray, suns: list[SunReading],
             delta_ev: np.ndarray, settings: GlareSettings, shape: tuple[int, int] | None = None) -> GlareEstimate:  # fmt: skip
    """The view's estimate (module docstring).

    Parameters
    ----------
    pix : PixelStats
        P map pixels.
    omega : ndarray, shape (P,)
    dirs : ndarray, shape (P, 3)
        Pixel centre directions.
    frame : ndarray, shape (3, 3)
        The view frame (left, up, view) as columns (:func:`.view.view_frame`).
    suns : list of SunReading
        Suns in front of the eye.
    delta_ev : ndarray, shape (2,)
        The delta lights' E_v (W/m², lx), exact.
    settings : GlareSettings
    shape : (int, int), optional
        The map's (height, width), for the pixels' neighbours; default one row.
    """
    up, view = frame[:, 1], frame[:, 2]
    shape = (1, len(omega)) if shape is None else shape
    c = 1  # photometric channel
    omega = np.asarray(omega, np.float64)
    ev_pix = omega[:, None] * pix.ev  # (P, 2)
    ev_pix_var = omega[:, None] ** 2 * pix.ev_var
    sun_list = [s for s in suns if s.visible]
    sun_cos = np.array([max(0.0, float(s.direction @ view)) for s in sun_list])
    sun_ev = np.array([s.cos_weighted_sr * s.mean * k for s, k in zip(sun_list, sun_cos)]).reshape(-1, 2)
    sun_ev_var = np.array([(s.cos_weighted_sr * s.mean_stderr * k) ** 2 for s, k in zip(sun_list, sun_cos)]).reshape(-1, 2)
    ev = ev_pix.sum(axis=0) + sun_ev.sum(axis=0) + np.asarray(delta_ev, np.float64)
    ev_se = np.sqrt(ev_pix_var.sum(axis=0) + sun_ev_var.sum(axis=0))

    # sources on the pixel means and the suns' visible parts
    eff = [s.effective() for s in sun_list]
    all_d = np.concatenate([dirs, np.array([s.direction for s in sun_list]).reshape(-1, 3)])
    all_w = np.concatenate([omega, np.array([e[0] for e in eff])])
    all_l = np.concatenate([pix.lum[:, c], np.array([e[1] for e in eff])])
    all_se = np.concatenate([np.sqrt(pix.lum_var[:, c]), np.array([float(s.mean_stderr[c]) for s in sun_list])])
    eligible = np.concatenate([_not_lone_noise(pix, shape, settings, all_w[:len(omega)], all_d[:len(omega)]),
                               np.ones(len(sun_list), bool)])
    half = np.concatenate([_pixel_half_sizes(shape, len(omega)), np.array([s.angular_radius for s in sun_list])])
    src: Sources = find_sources(all_d, all_w, all_l, view, up, settings, all_se, eligible, half)
    n_pix = len(omega)
    lab_pix = src.label[:n_pix]

    # per source: S = Σ ω L̂ (L·ω), V = Var(Ŝ), T = unbiased L²ω, its E_v
    k = len(src)
    S = np.zeros(k)
    V = np.zeros(k)
    T = np.zeros(k)
    E = np.zeros(k)
    n_in = np.zeros(k, np.int64)
    in_src = lab_pix >= 0
    if in_src.any():
        lab = lab_pix[in_src]
        np.add.at(S, lab, omega[in_src] * pix.lum[in_src, c])
        np.add.at(V, lab, omega[in_src] ** 2 * pix.lum_var[in_src, c])
        np.add.at(E, lab, ev_pix[in_src, c])
        np.add.at(n_in, lab, 1)
    sun_of = {}
    for j, s in enumerate(sun_list):
        kk = int(src.label[n_pix + j])
        if kk < 0:
            continue
        sun_of[kk] = s.name
        S[kk] += s.omega_sr * float(s.mean[c])
        V[kk] += (s.omega_sr * float(s.mean_stderr[c])) ** 2
        E[kk] += float(sun_ev[j, c])
    # a source is uniform at its mean luminance (evalglare): L²ω = S²/ω, ω including a sun's visible part
    # ω_eff = Ω·x̄²/E[x²] (so that a sun alone gives Ω·E[x²]); S² less its variance is unbiased
    with np.errstate(invalid="ignore", divide="ignore"):
        T = np.where(src.omega_sr > 0, (S * S - V) / np.where(src.omega_sr > 0, src.omega_sr, 1.0), 0.0)
    T = np.maximum(T, 0.0)
    P = src.position_index
    G = float(np.sum(T / P**2)) if k else 0.0

    # DGP and its gradient
    ev_lx = float(ev[c])
    a = ix.DGP_EV_EXPONENT
    notes: list[str] = []
    if ev_lx > 0.0:
        X = G / ev_lx**a
        d0 = ix.DGP_C1 * ev_lx + ix.DGP_C2 * math.log10(1.0 + X) + ix.DGP_C3
        g_e = ix.DGP_C1 - ix.DGP_C2 / _LN10 * a * X / ((1.0 + X) * ev_lx)
        g_g = ix.DGP_C2 / _LN10 / ((1.0 + X) * ev_lx**a)
    else:
        d0, g_e, g_g = ix.DGP_C3, ix.DGP_C1, 0.0
        notes.append("no light reaches the eye: E_v is 0")
    f = 1.0
    if settings.low_light:
        f = ix.low_light_factor(ev_lx)
        g_e = f * g_e + (0.024 * f * (1.0 - f) * d0 if ev_lx < 1000.0 else 0.0)
        g_g = f * g_g
    d_raw = f * d0
    dS = np.zeros(k)
    with np.errstate(invalid="ignore", divide="ignore"):
        dS = np.where(src.omega_sr > 0, 2.0 * S / (np.where(src.omega_sr > 0, src.omega_sr, 1.0) * P**2), 0.0) if k else dS
    # per map pixel: δD = g_e·ω·δē + g_g·dS_k·ω·δL̂, Cov(ē, L̂) ≈ cos θ·Var(L̂)
    cos_p = np.clip(dirs @ view, 0.0, 1.0)
    dS_pix = dS[np.maximum(lab_pix, 0)] if k else np.zeros(len(omega))
    b = np.where(in_src, g_g * dS_pix, 0.0)
    var_d = (g_e**2 * ev_pix_var[:, c] + (b * omega) ** 2 * pix.lum_var[:, c]
             + 2.0 * g_e * b * cos_p * omega**2 * pix.lum_var[:, c])  # fmt: skip
    var_dgp = float(np.maximum(var_d, 0.0).sum())
    for j, s in enumerate(sun_list):
        kk = int(src.label[n_pix + j])
        coef = g_e * s.cos_weighted_sr * sun_cos[j] + (g_g * dS[kk] * s.omega_sr if kk >= 0 else 0.0)
        var_dgp += (coef * float(s.mean_stderr[c])) ** 2
    dgp_se = math.sqrt(var_dgp)
    capped = d_raw > 1.0
    dgp_val = min(1.0, d_raw)
    if capped:
        notes.append(f"DGP {d_raw:.3f} before its cap at 1")
        dgp_se = 0.0 if d_raw - 4.0 * dgp_se > 1.0 else dgp_se

    # UGR: L_b from the pixels outside the sources (and the delta lights), G from the source pixels, each map
    # source with a core read by its parts (partly covered edge pixels included)
    t_u, e_ring = _partial_pixels(lab_pix, pix.lum[:, c], omega, ev_pix[:, c], shape, k, set(sun_of))
    parts = np.isfinite(t_u)
    T_u = np.where(parts, np.nan_to_num(t_u), T)
    G_u = float(np.sum(T_u / P**2)) if k else 0.0
    e_dir = float(E.sum())
    lb = max(0.0, (ev_lx - e_dir - float(e_ring.sum()))) / math.pi
    ugr = ix.ugr(lb, G_u)
    ugr_se = 0.0
    if k and G_u > 0 and lb > 0:
        with np.errstate(invalid="ignore", divide="ignore"):
            scale = np.where(T > 0, T_u / np.where(T > 0, T, 1.0), 1.0)  # the gradient of G_u ≈ G's, source by source
        dS_u = dS_pix * scale[np.maximum(lab_pix, 0)]
        vg = float(np.sum((np.where(in_src, dS_u, 0.0) * omega) ** 2 * pix.lum_var[:, c]))
        for j, s in enumerate(sun_list):
            kk = int(src.label[n_pix + j])
            if kk >= 0:
                vg += (dS[kk] * s.omega_sr * float(s.mean_stderr[c])) ** 2
        vb = float(ev_pix_var[~in_src, c].sum())
        for j, s in enumerate(sun_list):
            if int(src.label[n_pix + j]) < 0:
                vb += float(sun_ev_var[j, c])
        ugr_se = 8.0 / _LN10 * math.sqrt(vg / G_u**2 + vb / (math.pi * lb) ** 2)
    elif k and lb <= 0:
        notes.append("no background luminance: UGR is undefined")

    sources = []
    for i in range(k):
        sources.append(GlareSource(
            direction=src.direction[i], omega_sr=float(src.omega_sr[i]), luminance_cd_m2=float(S[i] / src.omega_sr[i]),
            luminance_stderr_cd_m2=float(math.sqrt(max(V[i], 0.0)) / src.omega_sr[i]), position_index=float(P[i]),
            l2w=float(T[i]), ev_lx=float(E[i]), sun=sun_of.get(i, ""), peak=bool(src.peaks[i]) if len(src.peaks) else False,
            pixels=int(n_in[i]),
        ))  # fmt: skip
    labels = np.concatenate([lab_pix, np.array([src.label[n_pix + j] for j in range(len(sun_list))], np.int64)])
    return GlareEstimate(
        ev_lx=ev_lx, ev_stderr_lx=float(ev_se[c]), ev_W_m2=float(ev[0]), ev_stderr_W_m2=float(ev_se[0]),
        dgp=dgp_val, dgp_stderr=dgp_se, dgps=ix.dgps(ev_lx), dgps_stderr=ix.DGPS_SLOPE * float(ev_se[c]) if ix.dgps(ev_lx) < 1.0 else 0.0,
        ugr=ugr, ugr_stderr=ugr_se, background_cd_m2=lb, direct_ev_lx=e_dir,
        mean_cd_m2=float((all_w * all_l).sum() / all_w.sum()) if all_w.sum() > 0 else 0.0,
        threshold_cd_m2=src.threshold_cd_m2, task_cd_m2=src.task_cd_m2, sources=sources, labels=labels,
        dgp_capped=capped, low_light_factor=f, notes=notes,
    )  # fmt: skip
