"""``probesim compare A.exr B.exr``: how far map A is from reference map B.

One quantity per file is compared: ``--channel NAME`` if given; otherwise
the luminance-weighted grey of R, G, B (Rec. 709 Y = 0.2126 R + 0.7152 G +
0.0722 B, which is the value itself for grey maps such as probe maps) when
both files have R, G and B; otherwise the first channel, in name order, that
both files have and that is not a standard error (``*stderr*``).

Figures (B is the reference):

- relative RMS error ‖A − B‖₂ / ‖B‖₂ over pixels (unweighted);
- the largest absolute error, its pixel (row from the top, column) and, for
  a lat-long map, the direction of that pixel's centre (simulator.io.latlong
  convention; in the world frame when the file records ``probesim:frame``);
- PSNR and SSIM (scikit-image) of log10 values, each floored at 10⁻⁶ × the
  largest |B| so that black pixels stay finite; the data range is that of
  log10 B. SSIM uses a 7-pixel window (smaller odd windows for small maps;
  none under 3 pixels);
- when both files carry the quantity's standard error (``L_W_m2_sr`` →
  ``L_stderr_W_m2_sr``), the standardised residuals z = (A − B)/√(σ_A² + σ_B²):
  the fraction with |z| > 4 and χ²/dof = mean(z²) over pixels with σ > 0.

Mismatched sizes or unreadable files are one-line :class:`UserError`.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass

import numpy as np

from simulator.errors import UserError
from simulator.units import luminance_grey

__all__ = ["Comparison", "compare_files", "compare_arrays", "format_comparison"]

#: log floor relative to the largest |B|
LOG_FLOOR = 1e-6


@dataclass
class Comparison:
    """Figures of one comparison (see the module docstring)."""

    path_a: str
    path_b: str
    quantity: str
    shape: tuple[int, int]
    rel_rms: float
    rms: float
    rms_b: float
    max_abs_error: float
    max_pixel: tuple[int, int]
    value_a: float
    value_b: float
    direction: tuple[float, float, float] | None
    lon_lat_deg: tuple[float, float] | None
    psnr_db: float
    ssim: float | None
    beyond_4sigma: float | None = None
    chi2_per_dof: float | None = None
    dof: int = 0


def _stderr_name(name: str) -> str | None:
    head, sep, rest = name.partition("_")
    return f"{head}_stderr_{rest}" if sep else None


def _pick(a: dict, b: dict, channel: str | None, path_a: str, path_b: str) -> tuple[str, np.ndarray, np.ndarray, str | None]:
    if channel is not None:
        for path, ch in ((path_a, a), (path_b, b)):
            if channel not in ch:
                raise UserError(f"{path}: no channel {channel!r} (channels: {', '.join(sorted(ch))})")
        return channel, a[channel], b[channel], _stderr_name(channel)
    if all(c in a and c in b for c in "RGB"):

        def y(ch):
            return luminance_grey(np.stack([ch[c] for c in "RGB"], axis=-1))

        return "Y (from R, G, B)", y(a), y(b), None
    common = sorted(c for c in a if c in b and "stderr" not in c)
    if not common:
        raise UserError(
            f"{path_b}: no channel in common with {path_a} "
            f"({', '.join(sorted(a)) or 'none'} vs {', '.join(sorted(b)) or 'none'})"
        )
    return common[0], a[common[0]], b[common[0]], _stderr_name(common[0])


def _is_latlong(header: dict, shape: tuple[int, int]) -> bool:
    env = header.get("envmap")
    if env is not None and "LATLONG" in str(env).upper():
        return True
    return "probesim:convention" in header or shape[1] == 2 * shape[0]


def _frame(header: dict) -> np.ndarray | None:
    text = header.get("probesim:frame")
    if not isinstance(text, str):
        return None
    try:
        cols = [list(map(float, part.split())) for part in text.split(";")]
        f = np.array(cols, float).T
        return f if f.shape == (3, 3) and np.all(np.isfinite(f)) else None
    except ValueError:
        return None


def compare_arrays(a: np.ndarray, b: np.ndarray, sa: np.ndarray | None = None, sb: np.ndarray | None = None) -> dict:
    """Figures of A against reference B, both shape (H, W); see the module docstring.

    Returns a dict with ``rel_rms``, ``rms``, ``rms_b``, ``max_abs_error``,
    ``max_pixel`` (row, column), ``psnr_db``, ``ssim`` (None under 3 pixels a
    side) and, with standard errors ``sa``, ``sb``, ``beyond_4sigma``,
    ``chi2_per_dof`` and ``dof``.
    """
    from skimage.metrics import peak_signal_noise_ratio, structural_similarity

    a = np.asarray(a, np.float64)
    b = np.asarray(b, np.float64)
    if a.shape != b.shape:
        raise ValueError(f"shapes differ: {a.shape} vs {b.shape}")
    diff = a - b
    rms = float(np.sqrt(np.mean(diff**2)))
    rms_b = float(np.sqrt(np.mean(b**2)))
    rel = rms / rms_b if rms_b > 0 else (0.0 if rms == 0 else math.inf)
    k = int(np.argmax(np.abs(diff)))
    pix = np.unravel_index(k, a.shape)
    top = float(np.max(np.abs(b)))
    floor = LOG_FLOOR * top if top > 0 else 1e-30
    la = np.log10(np.maximum(a, floor))
    lb = np.log10(np.maximum(b, floor))
    rng = float(lb.max() - lb.min()) or 1.0
    if np.array_equal(la, lb):
        psnr = math.inf
    else:
        psnr = float(peak_signal_noise_ratio(lb, la, data_range=rng))
    side = min(a.shape)
    win = min(7, side if side % 2 else side - 1)
    ssim = float(structural_similarity(lb, la, data_range=rng, win_size=win)) if win >= 3 else None
    out = {
        "rel_rms": rel, "rms": rms, "rms_b": rms_b, "max_abs_error": float(abs(diff[pix])),
        "max_pixel": (int(pix[0]), int(pix[1])), "value_a": float(a[pix]), "value_b": float(b[pix]),
        "psnr_db": psnr, "ssim": ssim,
    }  # fmt: skip
    if sa is not None and sb is not None:
        var = np.asarray(sa, np.float64) ** 2 + np.asarray(sb, np.float64) ** 2
        ok = var > 0
        if ok.any():
            z = diff[ok] / np.sqrt(var[ok])
            out.update(beyond_4sigma=float(np.mean(np.abs(z) > 4.0)), chi2_per_dof=float(np.mean(z**2)), dof=int(ok.sum()))
    return out


def compare_files(path_a: str | os.PathLike, path_b: str | os.PathLike, channel: str | None = None) -> Comparison:
    """Compare two EXR maps; B is the reference.

    Raises
    ------
    UserError
        A file is missing or unreadable, the channel is absent, or the
        images differ in size.
    """
    from simulator.io.exr import read_channels, read_header

    pa, pb = os.fspath(path_a), os.fspath(path_b)
    a, b = read_channels(pa), read_channels(pb)
    name, qa, qb, se_name = _pick(a, b, channel, pa, pb)
    if qa.shape != qb.shape:
        raise UserError(
            f"{pb}: size {qb.shape[1]} x {qb.shape[0]} differs from {pa} ({qa.shape[1]} x {qa.shape[0]}); "
            "resample one map first"
        )
    sa = a.get(se_name) if se_name else None
    sb = b.get(se_name) if se_name else None
    f = compare_arrays(qa, qb, sa, sb)
    ha, hb = read_header(pa), read_header(pb)
    direction = lonlat = None
    if _is_latlong(ha, qa.shape) or _is_latlong(hb, qb.shape):
        from simulator.io.latlong import latlong_uv_to_direction

        h, w = qa.shape
        r, c = f["max_pixel"]
        uv = np.array([(c + 0.5) / w, (r + 0.5) / h])
        lonlat = (math.degrees(math.pi * (1.0 - 2.0 * uv[0])), math.degrees(math.pi * (0.5 - uv[1])))
        frame = _frame(ha)
        frame = _frame(hb) if frame is None else frame
        direction = tuple(float(x) for x in latlong_uv_to_direction(uv, frame))
    return Comparison(
        path_a=pa, path_b=pb, quantity=name, shape=qa.shape, rel_rms=f["rel_rms"], rms=f["rms"], rms_b=f["rms_b"],
        max_abs_error=f["max_abs_error"], max_pixel=f["max_pixel"], value_a=f["value_a"], value_b=f["value_b"],
        direction=direction, lon_lat_deg=lonlat, psnr_db=f["psnr_db"], ssim=f["ssim"],
        beyond_4sigma=f.get("beyond_4sigma"), chi2_per_dof=f.get("chi2_per_dof"), dof=f.get("dof", 0),
    )  # fmt: skip


def format_comparison(c: Comparison) -> str:
    """The figures as a few lines of text."""
    h, w = c.shape
    lines = [
        f"A: {c.path_a}",
        f"B: {c.path_b} (reference)",
        f"quantity: {c.quantity}, {w} x {h} pixels",
        f"relative RMS error: {c.rel_rms:.4g} (RMS error {c.rms:.4g}, RMS of B {c.rms_b:.4g})",
    ]
    where = f"pixel (row {c.max_pixel[0]}, column {c.max_pixel[1]})"
    rel = f", {100 * c.max_abs_error / abs(c.value_b):.3g}% of B" if c.value_b else ""
    lines.append(f"largest error: {c.max_abs_error:.4g} at {where}: A {c.value_a:.4g}, B {c.value_b:.4g}{rel}")
    if c.direction is not None:
        d = c.direction
        lines.append(
            f"  direction ({d[0]:+.4f}, {d[1]:+.4f}, {d[2]:+.4f}), longitude {c.lon_lat_deg[0]:.2f} deg, "
            f"latitude {c.lon_lat_deg[1]:.2f} deg"
        )
    ssim = "n/a (map under 3 pixels a side)" if c.ssim is None else f"{c.ssim:.4f}"
    lines.append(f"log10 values (floored at {LOG_FLOOR:g} x max |B|): PSNR {c.psnr_db:.2f} dB, SSIM {ssim}")
    if c.chi2_per_dof is not None:
        lines.append(
            f"standardised residuals (A - B)/sqrt(sA^2 + sB^2): {100 * c.beyond_4sigma:.2f}% beyond 4 sigma, "
            f"chi2/dof {c.chi2_per_dof:.3f} over {c.dof} pixels"
        )
    return "\n".join(lines)
