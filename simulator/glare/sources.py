"""Glare sources in a luminance map, found as evalglare (3.05) finds them by default.

The map is a list of "pixels": a unit direction, a solid angle and a
luminance each (the traced map's pixels, and each sun as one more pixel of
its disk's solid angle). With ``settings`` a :class:`GlareSettings`:

1. **Threshold.** ``threshold`` above 100 is an absolute luminance, cd/m²
   (evalglare's default 2000, its ``-b``); at most 100 it is a multiple of the
   task luminance, the mean luminance within ``task_angle_deg``/2 of
   ``task_direction`` (evalglare ``-t``; its angle is that full opening), or
   without a task of the mean luminance of the whole view (Σ ω·L / Σ ω). A
   pixel is a source pixel when its luminance is above the threshold.
2. **Merging.** evalglare joins a source pixel to a source within its search
   radius ``search_radius`` (``-r``, default 0.2) and then merges sources that
   come within it of each other, until nothing changes; it compares twice
   the angle between two pixel directions with the radius, so pixels merge
   within ``search_radius / 2`` radians (5.7° by default). The end result is
   the connected groups of source pixels linked by steps of at most that
   angle; that is what :func:`find_sources` computes, measuring a step
   between the pixels' nearest points (a traced map's pixels, 1.4° by
   default, are coarser than a picture's: between centres, a gap would read
   up to a pixel wider than a fine picture shows it). On a traced map a
   pixel of a surface below the threshold whose few paths happened to find
   a light can read above it: such noise is left out twice. A pixel above
   the threshold with no neighbour above it (in the map's grid) counts only
   when it is above by more than :data:`NOISE_Z` of its standard errors
   (``eligible``, decided by the caller who knows the grid), and a group
   whose mean luminance is not above the threshold by that many standard
   errors is left out. Both rules fade as the passes grow (the errors
   shrink), leaving evalglare's.
3. **Peak extraction** (``peak_extraction``, default on; evalglare ``-y``, off
   with ``-x``): when some pixel is brighter than ``peak_cd_m2`` (``-Y``,
   default 50,000 cd/m²), each source's pixels at or above it are taken out
   of it and grouped (same merging angle) into sources of their own: a sun
   disk becomes its own source instead of raising a window's mean luminance.
4. **Each source**: its solid angle ω = Σ ω_p, its mean luminance
   L = Σ ω_p·L_p / ω, its direction the ω·L-weighted mean of its pixel
   directions (evalglare weighs pixel positions by ω·L since 2.12; a
   direction is the same thing without the image's projection) and the
   position index there (:func:`simulator.glare.indices.position_index`).

Pure numpy, with scipy's k-d tree for the pairs of pixels within the
merging angle (scipy comes with scikit-image).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from simulator.glare.indices import position_index

__all__ = ["NOISE_Z", "GlareSettings", "Sources", "parse_evalglare_options", "threshold_cd_m2", "find_sources"]

#: a group of source pixels of a traced map must be this many standard errors above the threshold
NOISE_Z = 2.0


@dataclass(frozen=True)
class GlareSettings:
    """How a glare view finds its sources and reports DGP (evalglare's options in brackets).

    Attributes
    ----------
    threshold : float
        > 100: absolute luminance, cd/m² [-b, default 2000]; ≤ 100: a multiple of the task or mean luminance.
    task_direction : ndarray, shape (3,), or None
        Unit direction of the task zone [-t]; None: the whole view's mean.
    task_angle_deg : float
        Full opening angle of the task zone, degrees.
    search_radius : float
        evalglare's -r (radians, default 0.2): pixels merge within half of it.
    peak_extraction : bool
        Split pixels at or above ``peak_cd_m2`` into sources of their own [-y; -x off].
    peak_cd_m2 : float
        [-Y, default 50000].
    low_light : bool
        DGP's low-light correction below 1000 lx [-C l+; off by default since evalglare 2.14].
    dgp_stderr : float
        The standard error of DGP at which a view stops tracing.
    """

    threshold: float = 2000.0
    task_direction: np.ndarray | None = None
    task_angle_deg: float = 0.0
    search_radius: float = 0.2
    peak_extraction: bool = True
    peak_cd_m2: float = 50000.0
    low_light: bool = False
    dgp_stderr: float = 0.005

    def evalglare_options(self) -> str:
        """The options that find the same sources (``-t``: the task zone as a direction, where evalglare takes a pixel)."""
        opts = [f"-b {self.threshold:g}", f"-r {self.search_radius:g}"]
        opts.append(f"-Y {self.peak_cd_m2:g}" if self.peak_extraction else "-x")
        if self.low_light:
            opts.append("-C l+")
        if self.task_direction is not None:
            opts.append("-t " + " ".join(f"{x:.6g}" for x in self.task_direction) + f" {self.task_angle_deg:g}")
        return " ".join(opts)


def parse_evalglare_options(text: str) -> dict:
    """The source-finding options of an evalglare command line, as :class:`GlareSettings` fields.

    Understood: ``-b threshold``, ``-r search_radius``, ``-y`` (peak extraction on, the default), ``-x``
    (off), ``-Y peak_luminance`` (on, at that luminance), ``-C l+`` / ``-C l-`` / ``-C 0`` (low-light
    correction on / off / every correction off), ``-4`` (low-light correction off) and ``-t dx dy dz
    angle_deg``: the task zone a threshold of at most 100 multiplies, as a view direction and its full
    opening angle in degrees (evalglare's ``-t`` takes a pixel position and an angle in radians).

    Raises
    ------
    ValueError
        An option evalglare has but a glare view does not take, a missing or bad value; the message
        names it.
    """
    out: dict = {}
    words = str(text).split()
    i = 0

    def number(flag: str) -> float:
        nonlocal i
        if i + 1 >= len(words):
            raise ValueError(f"{flag} needs a value")
        try:
            v = float(words[i + 1])
        except ValueError:
            raise ValueError(f"{flag} needs a number, not {words[i + 1]!r}") from None
        if not (math.isfinite(v) and v > 0):
            raise ValueError(f"{flag} must be a number > 0, not {words[i + 1]}")
        i += 1
        return v

    while i < len(words):
        w = words[i]
        if w == "-b":
            out["threshold"] = number(w)
        elif w == "-r":
            out["search_radius"] = number(w)
        elif w == "-y":
            out["peak_extraction"] = True
        elif w == "-x":
            out["peak_extraction"] = False
        elif w == "-Y":
            out["peak_extraction"], out["peak_cd_m2"] = True, number(w)
        elif w == "-4":
            out["low_light"] = False
        elif w == "-t":
            if i + 4 >= len(words):
                raise ValueError("-t needs a direction and an angle: -t dx dy dz angle_deg")
            try:
                v = [float(x) for x in words[i + 1:i + 5]]
            except ValueError:
                raise ValueError("-t needs four numbers: dx dy dz angle_deg") from None
            d = np.array(v[:3])
            n = float(np.linalg.norm(d))
            if not (n > 0 and math.isfinite(n)):
                raise ValueError("-t: the task's direction has zero length")
            if not 0.0 < v[3] <= 180.0:
                raise ValueError(f"-t: the task's opening angle must be in (0, 180] degrees, not {v[3]:g}")
            out["task_direction"], out["task_angle_deg"] = d / n, v[3]
            i += 4
        elif w == "-C":
            if i + 1 >= len(words) or words[i + 1] not in ("l+", "l-", "0"):
                raise ValueError("-C takes l+, l- or 0")
            out["low_light"] = words[i + 1] == "l+"
            i += 1
        else:
            raise ValueError(f"{w!r} is not an option a glare view takes (-b, -r, -y, -x, -Y, -C, -4, -t)")
        i += 1
    return out


@dataclass
class Sources:
    """The sources of one map.

    Attributes
    ----------
    label : ndarray of int, shape (N,)
        Source index of each pixel, -1 for none.
    omega_sr, luminance_cd_m2 : ndarray, shape (K,)
    direction : ndarray, shape (K, 3)
        Unit ω·L-weighted mean direction.
    position_index : ndarray, shape (K,)
    threshold_cd_m2 : float
        The luminance a source pixel exceeds.
    task_cd_m2 : float
        The task (or mean) luminance a relative threshold multiplies.
    """

    label: np.ndarray
    omega_sr: np.ndarray
    luminance_cd_m2: np.ndarray
    direction: np.ndarray
    position_index: np.ndarray
    threshold_cd_m2: float
    task_cd_m2: float
    peaks: np.ndarray = field(default_factory=lambda: np.zeros(0, bool))  #: (K,): the source came from peak extraction

    def __len__(self) -> int:
        return len(self.omega_sr)


def threshold_cd_m2(settings: GlareSettings, d: np.ndarray, omega: np.ndarray, lum: np.ndarray) -> tuple[float, float]:
    """``(threshold, task)``: the luminance a source pixel must exceed, and the task (or mean) luminance
    behind a relative threshold (module docstring, step 1)."""
    if settings.task_direction is not None:
        half = 0.5 * math.radians(settings.task_angle_deg)
        inside = d @ np.asarray(settings.task_direction, np.float64) >= math.cos(half)
        w = omega[inside]
        task = float((w * lum[inside]).sum() / w.sum()) if w.sum() > 0 else 0.0
    else:
        total = float(omega.sum())
        task = float((omega * lum).sum() / total) if total > 0 else 0.0
    if settings.threshold > 100.0:
        return float(settings.threshold), task
    return float(settings.threshold) * task, task


def _significant(m: np.ndarray, omega: np.ndarray, lum: np.ndarray, se: np.ndarray, thr: float) -> bool:
    """Whether the group ``m``'s mean luminance is above the threshold by more than NOISE_Z standard errors."""
    w = omega[m]
    total = float(w.sum())
    mean = float((w * lum[m]).sum()) / total
    err = math.sqrt(float((w * w * se[m] ** 2).sum())) / total
    return mean - thr > NOISE_Z * err


def _components(d: np.ndarray, angle: float, half: np.ndarray | None = None) -> np.ndarray:
    """Connected groups of unit directions linked by steps of at most ``angle`` radians: a label each.

    ``half``: each pixel's angular half-size (radians); two pixels are linked when their centres are
    within ``angle`` plus both half-sizes (their nearest points within ``angle``), as a fine picture of the
    same regions would link them."""
    n = len(d)
    if n == 0:
        return np.zeros(0, np.int64)
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    reach = angle + (0.0 if half is None else 2.0 * float(np.max(half)))
    chord = 2.0 * math.sin(0.5 * min(reach, math.pi)) * (1.0 + 1e-12)
    pairs = cKDTree(d).query_pairs(chord, output_type="ndarray")
    if half is not None and len(pairs):
        gap = np.arccos(np.clip(np.einsum("ij,ij->i", d[pairs[:, 0]], d[pairs[:, 1]]), -1.0, 1.0))
        pairs = pairs[gap - half[pairs[:, 0]] - half[pairs[:, 1]] <= angle * (1.0 + 1e-12)]
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n)) if len(pairs) else coo_matrix((n, n))
    _, labels = connected_components(graph, directed=False)
    return labels


def find_sources(d: np.ndarray, omega: np.ndarray, lum: np.ndarray, view: np.ndarray, up: np.ndarray,
                 settings: GlareSettings, lum_stderr: np.ndarray | None = None,
                 eligible: np.ndarray | None = None, half_size: np.ndarray | None = None) -> Sources:  # fmt: skip
    """The glare sources among N pixels (module docstring).

    Parameters
    ----------
    d : ndarray, shape (N, 3)
        Unit pixel directions (world frame).
    omega : ndarray, shape (N,)
        Solid angles, sr.
    lum : ndarray, shape (N,)
        Luminances, cd/m².
    view, up : ndarray, shape (3,)
        The view's unit direction and up vector (orthogonal to it).
    settings : GlareSettings
    lum_stderr : ndarray, shape (N,), optional
        Standard errors of the luminances (a traced map): a group of source pixels whose mean luminance
        is not above the threshold by more than :data:`NOISE_Z` of its standard errors is noise, not a
        source (module docstring, step 2).
    eligible : ndarray of bool, shape (N,), optional
        Pixels that may be source pixels (default all).
    half_size : ndarray, shape (N,), optional
        Each pixel's angular half-size, radians (default 0: points): pixels merge when their nearest
        points are within the merging angle (a traced map's pixels are larger than a picture's).
    """
    d = np.asarray(d, np.float64)
    omega = np.asarray(omega, np.float64)
    lum = np.asarray(lum, np.float64)
    thr, task = threshold_cd_m2(settings, d, omega, lum)
    label = np.full(len(lum), -1, np.int64)
    hot = np.flatnonzero((lum > thr) & (True if eligible is None else np.asarray(eligible, bool)))
    merge = 0.5 * settings.search_radius
    groups: list[np.ndarray] = []
    peaks: list[bool] = []
    if len(hot):
        hs = None if half_size is None else np.asarray(half_size, np.float64)
        comp = _components(d[hot], merge, None if hs is None else hs[hot])
        members = [hot[comp == c] for c in range(comp.max() + 1)]
        if lum_stderr is not None:
            members = [m for m in members if _significant(m, omega, lum, np.asarray(lum_stderr, np.float64), thr)]
            hot = np.concatenate(members) if members else hot[:0]
        split = settings.peak_extraction and len(hot) > 0 and float(lum[hot].max()) > settings.peak_cd_m2
        for m in members:
            if split and float(lum[m].max()) >= settings.peak_cd_m2:
                high = m[lum[m] >= settings.peak_cd_m2]
                rest = m[lum[m] < settings.peak_cd_m2]
                if len(rest):
                    groups.append(rest)
                    peaks.append(False)
                sub = _components(d[high], merge, None if hs is None else hs[high])
                for c in range(sub.max() + 1):
                    groups.append(high[sub == c])
                    peaks.append(True)
            else:
                groups.append(m)
                peaks.append(False)
    k = len(groups)
    w = np.zeros(k)
    mean_l = np.zeros(k)
    dirs = np.zeros((k, 3))
    for i, g in enumerate(groups):
        label[g] = i
        w[i] = omega[g].sum()
        flux = omega[g] * lum[g]
        mean_l[i] = flux.sum() / w[i]
        c = (flux[:, None] * d[g]).sum(axis=0)
        nc = float(np.linalg.norm(c))
        dirs[i] = c / nc if nc > 0 else d[g].mean(axis=0) / np.linalg.norm(d[g].mean(axis=0))
    pidx = position_index(dirs, view, up) if k else np.zeros(0)
    return Sources(label, w, mean_l, dirs, pidx, thr, task, np.array(peaks, bool))
