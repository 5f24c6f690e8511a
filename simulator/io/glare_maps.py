"""A glare view's rows, record and pictures beside the CSV (writers only: numbers in, file contents out).

For every glare sensor of a run, beside ``<csv stem>.csv``:

``<csv stem>.<view>.hdr``
    The view as a 180° angular fisheye (Radiance ``VIEW= -vta -vp … -vd …
    -vu … -vh 180 -vv 180``), N × N pixels (N = 4 × the map's larger side,
    at most 1024), grey: R = G = B = L/179 (Radiance's units, luminance
    179·(0.265R + 0.670G + 0.065B) = L cd/m²). evalglare reads it as it is:
    ``evalglare -vf`` is not needed, the view is in the header.
``<csv stem>.<view>.exr``
    The same fisheye in cd/m²: ``R``, ``G``, ``B`` (= L), ``Lv_cd_m2``,
    ``Lv_stderr_cd_m2`` and ``source`` (the glare source's number, 1 for the
    first, 0 for none), with string metadata ``probesim:view`` (the VIEW
    line), ``probesim:dgp`` and the run's seed and method.
``<csv stem>.<view>.png``
    A false-colour picture of log luminance with the glare sources
    outlined, numbered as in the JSON, and the view's figures in the title.
``<csv stem>.glare.json``
    Every view's figures with their standard errors, its settings as
    evalglare options, and its sources (direction, solid angle, luminance
    with its standard error, position index, unbiased L²ω, E_v share).

Each fisheye pixel shows the traced map's pixel its centre direction falls
in (the map's pixels are a mean over their solid angle); each sun is drawn
as its disk (its mean luminance as seen over the pixels it covers, by a
16 × 16 sub-sample of each pixel near it), so the picture's E_v is the
view's.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from simulator.glare import view as V
from simulator.io.maps import output_names

__all__ = ["GLARE_COLUMNS", "glare_readings", "glare_lines", "view_line", "fisheye", "glare_outputs"]

#: the values of a glare row beyond E_v's four irradiance columns, in CSV order
GLARE_COLUMNS = ("dgp", "dgp_stderr", "dgps", "dgps_stderr", "ugr", "ugr_stderr", "background_luminance_cd_m2", "glare_sources")
#: fisheye sub-samples per pixel side where a sun's disk is drawn
SUN_SUBSAMPLES = 16


def glare_readings(results, method: str) -> list:
    """CSV rows of glare views: E_v (irradiance columns), then :data:`GLARE_COLUMNS` (UGR left empty where
    it is undefined); ``samples`` counts directions (map and sun meters)."""
    from simulator.io.results import Reading

    rows = []
    for r in results:
        e = r.estimate
        v = {"irradiance_W_m2": e.ev_W_m2, "irradiance_stderr_W_m2": e.ev_stderr_W_m2, "illuminance_lx": e.ev_lx,
             "illuminance_stderr_lx": e.ev_stderr_lx, "dgp": e.dgp, "dgp_stderr": e.dgp_stderr, "dgps": e.dgps,
             "dgps_stderr": e.dgps_stderr}  # fmt: skip
        if math.isfinite(e.ugr):
            v.update(ugr=e.ugr, ugr_stderr=e.ugr_stderr)
        v.update(background_luminance_cd_m2=e.background_cd_m2, glare_sources=float(len(e.sources)))
        rows.append(Reading(r.sensor, {k: float(x) for k, x in v.items()}, int(r.samples), float(r.seconds), method,
                            r.target_met))  # fmt: skip
    return rows


def glare_lines(rows) -> list[str]:
    """One console line per glare row: DGP, DGPs, UGR and the sources, each with its standard error."""
    out = []
    for r in rows:
        if r.sensor.spec.name != "glare" or "dgp" not in r.values:
            continue
        v = r.values
        ugr = f"UGR {v['ugr']:.1f} ± {v['ugr_stderr']:.2f}" if "ugr" in v else "UGR undefined"
        out.append(f"glare {r.sensor.name}: E_v {v['illuminance_lx']:.4g} ± {v['illuminance_stderr_lx']:.2g} lx, "
                   f"DGP {v['dgp']:.3f} ± {v['dgp_stderr']:.3f}, DGPs {v['dgps']:.3f}, {ugr}, "
                   f"{int(v['glare_sources'])} glare source(s)")  # fmt: skip
    return out


def view_line(position, frame: np.ndarray) -> str:
    """Radiance's view line of the 180° angular fisheye: ``-vta -vp … -vd … -vu … -vh 180 -vv 180``."""
    f = lambda v: " ".join(f"{float(x):.9g}" for x in v)  # noqa: E731
    return f"-vta -vp {f(position)} -vd {f(frame[:, 2])} -vu {f(frame[:, 1])} -vh 180 -vv 180 -vo 0 -va 0 -vs 0 -vl 0"


def fisheye(result, n: int | None = None) -> dict[str, np.ndarray]:
    """The view as an N × N angular fisheye: ``{"L", "L_stderr", "source", "inside"}`` (module docstring)."""
    w, h = result.sensor.resolution
    n = int(n or min(1024, 4 * max(w, h)))
    frame = result.frame
    d, inside = V.fisheye_directions(n, frame)
    row, col, _ = V.pixel_of_directions(d, w, h, frame)
    lum = np.where(inside, result.luminance[row, col], 0.0)
    lum_se = np.where(inside, result.luminance_stderr[row, col], 0.0)
    labels = result.estimate.labels
    n_pix = w * h
    source = np.where(inside, labels[:n_pix].reshape(h, w)[row, col] + 1, 0)
    visible = [s for s in result.suns if s.visible]
    for j, s in enumerate(visible):
        cover = _disk_cover(n, frame, s.direction, math.acos(1.0 - s.omega_sr / (2.0 * math.pi)))
        lum = lum + float(s.mean[1]) * cover
        k = int(labels[n_pix + j]) if n_pix + j < len(labels) else -1
        if k >= 0:
            source = np.where(cover >= 0.5, k + 1, source)
    return {"L": lum, "L_stderr": lum_se, "source": source.astype(np.int64), "inside": inside,
            "L_map_max": float(result.luminance.max()) if result.luminance.size else 0.0}


def _disk_cover(n: int, frame: np.ndarray, centre: np.ndarray, radius: float) -> np.ndarray:
    """Share of each fisheye pixel inside the disk of angular ``radius`` about ``centre`` (N, N)."""
    cover = np.zeros((n, n))
    view, up, right = frame[:, 2], frame[:, 1], -frame[:, 0]
    theta = math.acos(max(-1.0, min(1.0, float(centre @ view))))
    r = theta / (0.5 * math.pi)
    perp = centre - (centre @ view) * view
    norm = float(np.linalg.norm(perp))
    a, b = (float(perp @ right) / norm * r, float(perp @ up) / norm * r) if norm > 0 else (0.0, 0.0)
    x, y = (a + 1.0) * 0.5 * n - 0.5, (1.0 - b) * 0.5 * n - 0.5  # pixel coordinates of the centre
    reach = radius / (0.5 * math.pi) * 0.5 * n + 2.0
    x0, x1 = max(0, int(x - reach)), min(n - 1, int(x + reach) + 1)
    y0, y1 = max(0, int(y - reach)), min(n - 1, int(y + reach) + 1)
    k = SUN_SUBSAMPLES
    cosr = math.cos(radius)
    for py in range(y0, y1 + 1):
        for px in range(x0, x1 + 1):
            sub = (np.arange(k) + 0.5) / k
            aa = 2.0 * (px + sub[None, :]) / n - 1.0
            bb = 1.0 - 2.0 * (py + sub[:, None]) / n
            rr = np.hypot(aa, bb)
            th = 0.5 * math.pi * np.minimum(rr, 1.0)
            with np.errstate(invalid="ignore", divide="ignore"):
                ca = np.where(rr > 0, aa / np.where(rr > 0, rr, 1.0), 0.0)
                cb = np.where(rr > 0, bb / np.where(rr > 0, rr, 1.0), 0.0)
            dd = np.cos(th)[..., None] * view + np.sin(th)[..., None] * (ca[..., None] * right + cb[..., None] * up)
            cover[py, px] = float(np.mean((dd @ centre >= cosr) & (rr <= 1.0)))
    return cover


def _record(r, files: dict[str, str]) -> dict:
    e = r.estimate
    s = r.settings
    return {
        "position_m": [float(x) for x in r.sensor.position], "direction": [float(x) for x in r.frame[:, 2]],
        "up": [float(x) for x in r.frame[:, 1]], "resolution": list(r.sensor.resolution), "passes": r.passes,
        "samples": r.samples, "target_met": r.target_met,
        "evalglare_options": s.evalglare_options(),
        "task": None if s.task_direction is None else {"direction": [float(x) for x in s.task_direction], "angle_deg": s.task_angle_deg},
        "low_light_correction": s.low_light, "low_light_factor": e.low_light_factor,
        "ev_lx": e.ev_lx, "ev_stderr_lx": e.ev_stderr_lx, "dgp": e.dgp, "dgp_stderr": e.dgp_stderr, "dgp_capped": e.dgp_capped,
        "dgps": e.dgps, "dgps_stderr": e.dgps_stderr, "ugr": e.ugr if math.isfinite(e.ugr) else None, "ugr_stderr": e.ugr_stderr,
        "background_luminance_cd_m2": e.background_cd_m2, "direct_ev_lx": e.direct_ev_lx, "mean_luminance_cd_m2": e.mean_cd_m2,
        "threshold_cd_m2": e.threshold_cd_m2, "task_luminance_cd_m2": e.task_cd_m2, "glare_term": e.glare_term,
        "sources": [{
            "number": i + 1, "direction": [float(x) for x in g.direction], "solid_angle_sr": g.omega_sr,
            "luminance_cd_m2": g.luminance_cd_m2, "luminance_stderr_cd_m2": g.luminance_stderr_cd_m2,
            "position_index": g.position_index, "l2w": g.l2w, "ev_lx": g.ev_lx, "sun": g.sun or None, "peak": g.peak,
            "pixels": g.pixels,
        } for i, g in enumerate(e.sources)],  # fmt: skip
        "suns": [{"light": s_.name, "direction": [float(x) for x in s_.direction], "solid_angle_sr": s_.omega_sr,
                  "mean_luminance_cd_m2": float(s_.mean[1]), "mean_luminance_stderr_cd_m2": float(s_.mean_stderr[1])}
                 for s_ in r.suns],  # fmt: skip
        "stderr_jackknife": dict(e.jackknife), "notes": list(e.notes), "files": files,
    }


def glare_outputs(csv_path: Path, results: list, meta: dict) -> tuple[dict, dict]:
    """``({path: content}, {view: its record})`` for the run's glare views (module docstring)."""
    from simulator.io.exr import write_channels
    from simulator.io.hdr import encode_rgbe
    from simulator.io.glare_png import fisheye_png

    files: dict = {}
    record: dict = {}
    names = output_names(csv_path, [r.sensor.name for r in results])
    for r in results:
        stem = names[r.sensor.name]
        img = fisheye(r)
        vline = view_line(r.sensor.position, r.frame)
        e = r.estimate
        head = [f"SOFTWARE= probesim glare view {r.sensor.name}", f"VIEW= {vline}"]
        hdr = encode_rgbe(np.repeat((img["L"] / 179.0)[..., None], 3, axis=-1))
        hdr = hdr.replace(b"#?RADIANCE\n", ("#?RADIANCE\n" + "\n".join(head) + "\n").encode("ascii"), 1)
        base = lambda ext: csv_path.parent / f"{stem}.{ext}"  # noqa: E731
        files[base("hdr")] = hdr
        channels = {"R": img["L"], "G": img["L"], "B": img["L"], "Lv_cd_m2": img["L"], "Lv_stderr_cd_m2": img["L_stderr"],
                    "source": img["source"].astype(np.float32)}  # fmt: skip
        header = {"probesim:kind": "glare", "probesim:sensor": r.sensor.name, "probesim:view": vline, "probesim:units": "cd/m2",
                  "probesim:dgp": f"{e.dgp:.4f}", "probesim:seed": str(meta.get("seed", "")),
                  "probesim:method": str(meta.get("method", "")), "probesim:stage": str(meta.get("stage", ""))}  # fmt: skip
        files[base("exr")] = (lambda ch, hd: (lambda p: write_channels(p, ch, hd)))(channels, header)
        files[base("png")] = fisheye_png(img, r.sensor.name, e)
        record[r.sensor.name] = _record(r, {k: base(k).name for k in ("hdr", "exr", "png")})
    if results:
        path = csv_path.with_name(csv_path.stem + ".glare.json")
        files[path] = json.dumps(record, indent=2, sort_keys=True) + "\n"
    return files, record
