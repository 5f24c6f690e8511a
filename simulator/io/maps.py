"""Image outputs beside the CSV: grid maps (EXR + PNG) and probe maps (EXR + JSON).

Writers only: plain numbers in, file contents out (no Warp, no USD). Each
function returns ``{path: content}`` where content is ``str`` (text),
``bytes``, or a callable that writes the file at the path it is given; the
caller (:func:`simulator.io.results.write_outputs`) stages every file under a
temporary name and renames them all together with the CSV.

Grid maps, for every ``[[grid]]`` of a run
------------------------------------------
``<csv stem>.<grid>.exr``: one pixel per cell, float32 channels

=================  =====  ============================================
channel            unit   value
=================  =====  ============================================
``E_W_m2``         W/m²   irradiance of the cell's sensor
``E_stderr_W_m2``  W/m²   its standard error
``Ev_lx``          lx     illuminance
``Ev_stderr_lx``   lx     its standard error
=================  =====  ============================================

Column i is cell i along the grid's ``right`` axis; row 0 (top) is the cell
row farthest along ``up`` (j = ny − 1), so the image shows the grid as seen
from the side its sensors face, ``up`` pointing up. String metadata:
``probesim:kind`` (``grid``), ``probesim:grid``, ``probesim:units``,
``probesim:seed``, ``probesim:method``, ``probesim:light_units``,
``probesim:centre_m``, ``probesim:right``, ``probesim:up``,
``probesim:normal``, ``probesim:size_m``, ``probesim:cells``,
``probesim:cell_size_m``, ``probesim:layout``, ``probesim:stage``.

``<csv stem>.<grid>.png``: a false-colour map of illuminance with a colour
bar in lx, axes in metres from the grid centre, and the grid's minimum,
mean, maximum and uniformity (min/mean) in the title.

With sensor responses (:mod:`simulator.spectra`), each response's
irradiance column and its standard error are more EXR channels named as the
CSV columns (``ppfd_umol_m2_s``, ``ppfd_stderr_umol_m2_s``), its min/mean/max
and uniformity are in the header (``probesim:par_uniformity``), and
``<csv stem>.<grid>.<response>.png`` maps it the same way.

Probe maps, for every probe of a run
------------------------------------
``<csv stem>.<probe>.exr``: a lat-long map of incident radiance (see
:mod:`simulator.io.latlong` for the convention, :mod:`simulator.engine.probes`
for the frame), float32 channels

=====================  ========  ==================================================
channel                unit      value
=====================  ========  ==================================================
``R``, ``G``, ``B``    (note)    mean radiance in the stage's light units: cd/m²
                                 for ``photometric``, W m⁻² sr⁻¹ for
                                 ``radiometric`` (R = G = B; a grey run with
                                 ``[spectra]`` × its emitters' colour), so that the
                                 file is a DomeLight ``texture:file`` at intensity 1
``L_W_m2_sr``          W/m²/sr   mean radiance over the pixel
``L_stderr_W_m2_sr``   W/m²/sr   its standard error
``Lv_cd_m2``           cd/m²     mean luminance
``Lv_stderr_cd_m2``    cd/m²     its standard error
=====================  ========  ==================================================

The file carries OpenEXR's standard ``envmap`` attribute (lat-long) and
string metadata ``probesim:kind`` (``probe``), ``probesim:sensor``,
``probesim:units``, ``probesim:seed``, ``probesim:method``,
``probesim:light_units``, ``probesim:position_m``, ``probesim:frame``,
``probesim:convention``, ``probesim:passes``, ``probesim:samples``,
``probesim:delta_lights``, ``probesim:stage``. Delta lights (point lights,
angle-0 distant lights) do not appear in the map (no direction sees them);
they are in the integrals.

``<csv stem>.probes.json``: every probe's integrals with standard errors
(scalar irradiance, the six faces, vector irradiance and mean direction, nine
SH coefficients), in W/m² and lx; see :func:`probe_record`.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path
from typing import Callable

import numpy as np

__all__ = [
    "GRID_CHANNELS",
    "PROBE_CHANNELS",
    "sanitise_name",
    "output_names",
    "grid_arrays",
    "grid_outputs",
    "grid_png",
    "probe_record",
    "probe_outputs",
]

#: grid EXR channel → unit
GRID_CHANNELS = {"E_W_m2": "W/m2", "E_stderr_W_m2": "W/m2", "Ev_lx": "lx", "Ev_stderr_lx": "lx"}
#: probe EXR channel → unit (R, G, B: the stage's light units, see the module docstring)
PROBE_CHANNELS = {
    "L_W_m2_sr": "W/m2/sr", "L_stderr_W_m2_sr": "W/m2/sr", "Lv_cd_m2": "cd/m2", "Lv_stderr_cd_m2": "cd/m2",
}  # fmt: skip

Content = str | bytes | Callable[[Path], None]


def sanitise_name(name: str) -> str:
    """A file-name-safe form of a sensor or grid name: letters, digits, ``.``,
    ``_`` and ``-`` kept, runs of anything else become one ``_``; no leading
    or trailing ``_`` or ``.``; ``"sensor"`` if nothing is left."""
    s = re.sub(r"[^A-Za-z0-9._-]+", "_", str(name)).strip("._")
    return s or "sensor"


def output_names(csv_path: Path, names: list[str]) -> dict[str, str]:
    """Unique file stems ``<csv stem>.<sanitised name>`` for ``names``, in order.

    Two names that sanitise alike (or that would collide with the CSV's own
    side files, ``run`` and ``probes``) get ``_2``, ``_3``, … appended.
    """
    taken = {f"{csv_path.stem}.run", f"{csv_path.stem}.probes"}
    out: dict[str, str] = {}
    for n in names:
        base = f"{csv_path.stem}.{sanitise_name(n)}"
        stem, k = base, 1
        while stem in taken:
            k += 1
            stem = f"{base}_{k}"
        taken.add(stem)
        out[n] = stem
    return out


def _vec(v) -> str:
    return " ".join(f"{float(x):.9g}" for x in np.asarray(v, float).reshape(-1))


# --------------------------------------------------------------------------- grids


def grid_arrays(grid, values: dict[str, dict[str, float]], extra: tuple[str, ...] = ()) -> dict[str, np.ndarray]:
    """The grid's readings as images, shape (ny, nx), row 0 = cell row j = ny − 1.

    Parameters
    ----------
    grid : simulator.config.loader.GridConfig
    values : dict
        Sensor name → its CSV values (``irradiance_W_m2``, …).
    extra : tuple of str
        More CSV columns to map, each becoming a channel of its own name
        (response columns such as ``ppfd_umol_m2_s``).

    Returns
    -------
    dict of str to ndarray
        :data:`GRID_CHANNELS` (and ``extra``) → float64 images.
    """
    keys = {
        "E_W_m2": "irradiance_W_m2", "E_stderr_W_m2": "irradiance_stderr_W_m2",
        "Ev_lx": "illuminance_lx", "Ev_stderr_lx": "illuminance_stderr_lx",
        **{c: c for c in extra},
    }  # fmt: skip
    cells = [values[grid.cell_name(i, j)] for j in range(grid.ny) for i in range(grid.nx)]  # row j, then column i
    # gathered per channel as whole images (a store per cell and channel cost ~3 ms for 1,024 cells)
    return {c: np.array([v[k] for v in cells], np.float64).reshape(grid.ny, grid.nx)[::-1].copy() for c, k in keys.items()}


def _stats(lx: np.ndarray) -> tuple[float, float, float, float]:
    """min, mean, max and uniformity min/mean (NaN when the mean is 0)."""
    lo, mean, hi = float(lx.min()), float(lx.mean()), float(lx.max())
    return lo, mean, hi, (lo / mean if mean > 0 else math.nan)


def grid_png(grid, images: dict[str, np.ndarray], channel: str = "Ev_lx", title: str = "illuminance",
             unit: str = "lx") -> bytes:
    """PNG bytes of the grid's false-colour map of one channel (illuminance by default).

    The colour bar is in ``unit``; axes are metres along ``right`` and ``up``
    from the grid centre; the title gives min, mean, max and uniformity.
    """
    from simulator.io.map_png import map_png

    lx = images[channel]
    lo, mean, hi, uni = _stats(lx)
    w, h = grid.size
    lines = [f"{grid.name}: {title}, {grid.nx} x {grid.ny} cells",
             f"min / mean / max: {lo:.4g} / {mean:.4g} / {hi:.4g} {unit}", f"uniformity (min/mean): {uni:.3f}"]
    # row 0 is the far end along up: drawn on top
    return map_png(lx, (w, h), lines, f"{title} ({unit})", "along right (m)", "along up (m)")


def grid_outputs(csv_path: Path, grids: list, rows: list, meta: dict[str, str],
                 responses: list[dict] | tuple = ()) -> dict[Path, Content]:
    """EXR and PNG maps of every grid.

    Parameters
    ----------
    csv_path : Path
    grids : list of simulator.config.loader.GridConfig
    rows : list of simulator.io.results.Reading
        The run's rows (the grids' cells among them).
    meta : dict of str to str
        Run-wide metadata: ``seed``, ``method``, ``light_units``, ``stage``.
    responses : list of dict, optional
        Response maps (:func:`simulator.spectra.posthoc.response_channels`):
        each ``{"channel", "stderr_channel", "unit", "title", "name"}`` adds
        its two channels (named as the CSV columns) to the grid's EXR and a
        PNG ``<csv stem>.<grid>.<name>.png`` with its uniformity.

    Returns
    -------
    dict of Path to content
    """
    values = {r.sensor.name: r.values for r in rows}
    stems = output_names(csv_path, [g.name for g in grids])
    extra = tuple(c for r in responses for c in (r["channel"], r["stderr_channel"]))
    units = {**GRID_CHANNELS, **{c: r["unit"].replace("µ", "u") for r in responses for c in (r["channel"], r["stderr_channel"])}}
    files: dict[Path, Content] = {}
    for g in grids:
        images = grid_arrays(g, values, extra)
        lo, mean, hi, uni = _stats(images["Ev_lx"])
        header = {
            "probesim:kind": "grid",
            "probesim:grid": g.name,
            "probesim:units": "; ".join(f"{c}: {u}" for c, u in units.items()),
            "probesim:seed": str(meta.get("seed", "")),
            "probesim:method": str(meta.get("method", "")),
            "probesim:light_units": str(meta.get("light_units", "")),
            "probesim:stage": str(meta.get("stage", "")),
            "probesim:centre_m": _vec(g.centre),
            "probesim:right": _vec(g.right),
            "probesim:up": _vec(g.up),
            "probesim:normal": _vec(g.normal),
            "probesim:size_m": _vec(g.size),
            "probesim:cells": f"{g.nx} {g.ny}",
            "probesim:cell_size_m": _vec(g.cell_size),
            "probesim:layout": (
                "pixel (row r, column i) = cell (i, j = ny - 1 - r), centred at centre + "
                "((i + 0.5)/nx - 0.5)*width*right + ((j + 0.5)/ny - 0.5)*height*up"
            ),
            "probesim:illuminance_min_mean_max_lx": f"{lo:.9g} {mean:.9g} {hi:.9g}",
            "probesim:uniformity": f"{uni:.9g}",
        }
        for r in responses:
            r_lo, r_mean, r_hi, r_uni = _stats(images[r["channel"]])
            header[f"probesim:{r['name']}_min_mean_max"] = f"{r_lo:.9g} {r_mean:.9g} {r_hi:.9g}"
            header[f"probesim:{r['name']}_uniformity"] = f"{r_uni:.9g}"
        stem = stems[g.name]
        files[csv_path.with_name(stem + ".exr")] = _exr_writer(images, header)
        files[csv_path.with_name(stem + ".png")] = grid_png(g, images)
        for r in responses:
            files[csv_path.with_name(f"{stem}.{sanitise_name(r['name'])}.png")] = grid_png(
                g, images, r["channel"], r["title"], r["unit"])
    return files


def _exr_writer(channels: dict[str, np.ndarray], header: dict[str, str], latlong: bool = False):
    from simulator.io.exr import write_channels

    def write(path: Path) -> None:
        if latlong:
            write_channels(path, channels, header, envmap="latlong")
        else:
            write_channels(path, channels, header)

    return write


# --------------------------------------------------------------------------- probes


def _pair(value, stderr, unit_r: str, unit_p: str) -> dict:
    return {
        unit_r: float(value[0]), f"stderr_{unit_r}": float(stderr[0]),
        unit_p: float(value[1]), f"stderr_{unit_p}": float(stderr[1]),
    }  # fmt: skip


def probe_record(result, map_file: str) -> dict:
    """A probe's integrals as a JSON-ready dict (W/m² and lx, each with ``stderr_``).

    Keys: ``sensor``, ``source``, ``position_m``, ``resolution``,
    ``map_file``, ``frame`` (world axes of the map's x, y, z), ``passes``,
    ``samples``, ``scalar_irradiance``, ``faces`` (``+X`` … ``-Z``),
    ``vector_irradiance`` (``x``, ``y``, ``z``), ``mean_direction``
    (radiometric and photometric unit vectors with their angular standard
    errors in degrees), ``spherical_harmonics`` (``order`` of (l, m) and the
    coefficient lists ``W_m2``, ``stderr_W_m2``, ``lx``, ``stderr_lx``), and
    ``delta_lights`` (the exact part of each integral that point and angle-0
    distant lights gave, same layout as above without errors).
    """
    from simulator.engine.probes import FACE_NAMES, SH_NAMES

    I, S, D = result.integrals, result.integrals_stderr, result.delta
    md_r, md_r_se = result.mean_direction(0)
    md_p, md_p_se = result.mean_direction(1)

    def clean(x):
        return None if not math.isfinite(x) else x

    return {
        "sensor": result.sensor.name,
        "source": result.sensor.source,
        "position_m": [float(x) for x in result.sensor.position],
        "resolution": [int(result.sensor.resolution[0]), int(result.sensor.resolution[1])],
        "map_file": map_file,
        "frame": [[float(x) for x in result.frame[:, k]] for k in range(3)],
        "passes": int(result.passes),
        "samples": int(result.samples),
        "scalar_irradiance": _pair(I[0], S[0], "W_m2", "lx"),
        "faces": {n: _pair(I[1 + k], S[1 + k], "W_m2", "lx") for k, n in enumerate(FACE_NAMES)},
        "vector_irradiance": {a: _pair(I[7 + k], S[7 + k], "W_m2", "lx") for k, a in enumerate("xyz")},
        "mean_direction": {
            "radiometric": [clean(float(x)) for x in md_r], "stderr_deg_radiometric": clean(md_r_se),
            "photometric": [clean(float(x)) for x in md_p], "stderr_deg_photometric": clean(md_p_se),
        },  # fmt: skip
        "spherical_harmonics": {
            "order": [f"{n}" for n in SH_NAMES],
            "W_m2": [float(x) for x in I[10:19, 0]], "stderr_W_m2": [float(x) for x in S[10:19, 0]],
            "lx": [float(x) for x in I[10:19, 1]], "stderr_lx": [float(x) for x in S[10:19, 1]],
        },  # fmt: skip
        "delta_lights": {
            "scalar_irradiance": {"W_m2": float(D[0, 0]), "lx": float(D[0, 1])},
            "faces": {n: {"W_m2": float(D[1 + k, 0]), "lx": float(D[1 + k, 1])} for k, n in enumerate(FACE_NAMES)},
            "vector_irradiance": {a: {"W_m2": float(D[7 + k, 0]), "lx": float(D[7 + k, 1])} for k, a in enumerate("xyz")},
            "spherical_harmonics": {"W_m2": [float(x) for x in D[10:19, 0]], "lx": [float(x) for x in D[10:19, 1]]},
        },
    }


def _stated_colour(r, k: int, photometric: bool) -> np.ndarray:
    """Channel k of a spectrally traced probe's sRGB map in the stage's light units: the traced
    luminance-based colour (cd/m²), times L_W / L_v per pixel for radiometric units (0 where dark)."""
    c = np.asarray(r.colour[..., k], float)
    if photometric:
        return c
    lv, le = r.radiance[..., 1], r.radiance[..., 0]
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(lv > 0, c * le / lv, 0.0)


def probe_outputs(csv_path: Path, results: list, meta: dict[str, str]) -> tuple[dict[Path, Content], dict[str, str]]:
    """EXR maps of every probe and the ``<csv stem>.probes.json`` side file.

    Parameters
    ----------
    csv_path : Path
    results : list of simulator.engine.probes.ProbeResult
    meta : dict of str to str
        Run-wide metadata: ``seed``, ``method``, ``light_units``, ``stage``,
        and optionally ``taken`` (grid names, whose files come first) and
        ``rgb`` ``(spectrum name, linear sRGB per unit luminance (3,))``: a
        grey scene whose emitters share that spectrum, so every radiance has
        its chromaticity and R, G, B are the stated radiance × that colour
        (BT.709 Y of it is 1 to 1e-4, so a DomeLight reading the file sees
        the same grey); without it R = G = B.

    Returns
    -------
    files : dict of Path to content
    map_files : dict of str to str
        Probe name → its EXR file name.
    """
    if not results:
        return {}, {}
    names = list(meta.get("taken", [])) + [r.sensor.name for r in results]
    stems = output_names(csv_path, names)
    photometric = meta.get("light_units", "photometric") == "photometric"
    files: dict[Path, Content] = {}
    map_files: dict[str, str] = {}
    records = []
    for r in results:
        path = csv_path.with_name(stems[r.sensor.name] + ".exr")
        map_files[r.sensor.name] = path.name
        grey = r.radiance[..., 1 if photometric else 0]
        rgb = meta.get("rgb")
        colour = np.ones(3) if rgb is None else np.asarray(rgb[1], float)
        maps = [grey * colour[k] for k in range(3)]
        if getattr(r, "colour", None) is not None:  # traced spectrally: each pixel's own colour
            maps = [_stated_colour(r, k, photometric) for k in range(3)]
        channels = {
            "R": maps[0], "G": maps[1], "B": maps[2],
            "L_W_m2_sr": r.radiance[..., 0], "L_stderr_W_m2_sr": r.radiance_stderr[..., 0],
            "Lv_cd_m2": r.radiance[..., 1], "Lv_stderr_cd_m2": r.radiance_stderr[..., 1],
        }  # fmt: skip
        rgb_unit = "cd/m2 (light_units photometric)" if photometric else "W/m2/sr (light_units radiometric)"
        delta = "none"
        if np.any(r.delta[0] > 0):
            delta = (f"point or angle-0 distant lights give {r.delta[0, 0]:.9g} W/m2 ({r.delta[0, 1]:.9g} lx) of scalar "
                     "irradiance that the map cannot show (no direction sees them); see the probes JSON")  # fmt: skip
        header = {
            "probesim:kind": "probe",
            "probesim:sensor": r.sensor.name,
            "probesim:units": "; ".join([f"R, G, B: {rgb_unit}"] + [f"{c}: {u}" for c, u in PROBE_CHANNELS.items()]),
            "probesim:seed": str(meta.get("seed", "")),
            "probesim:method": str(meta.get("method", "")),
            "probesim:light_units": str(meta.get("light_units", "")),
            "probesim:stage": str(meta.get("stage", "")),
            "probesim:position_m": _vec(r.sensor.position),
            "probesim:frame": "; ".join(_vec(r.frame[:, k]) for k in range(3)),
            "probesim:convention": (
                "OpenEXR lat-long in the frame above (world axes of the map's x; y; z): "
                "d = cos(lat) sin(lon) x + sin(lat) y + cos(lat) cos(lon) z, lon = pi (1 - 2u), "
                "lat = pi (1/2 - v), u = (column + 1/2)/width, v = (row + 1/2)/height at pixel centres, "
                "row 0 on top; each pixel holds the mean radiance over its solid angle. The frame is that of an "
                "untransformed DomeLight in the stage, so this file is that DomeLight's texture:file at intensity 1"
            ),
            "probesim:passes": str(r.passes),
            "probesim:samples": str(r.samples),
            "probesim:delta_lights": delta,
        }
        if getattr(r, "colour", None) is not None:
            header["probesim:rgb"] = ("R, G, B: linear sRGB of each pixel's traced spectrum (hero wavelengths; "
                                      "M K_m integral of L times the CIE 1931 colour matching functions, cd/m2)"
                                      + ("" if photometric else ", scaled by the pixel's W/m2/sr per cd/m2"))
        elif rgb is not None:
            header["probesim:rgb"] = (f"R, G, B: the stated radiance x the linear sRGB of {rgb[0]} per unit luminance "
                                      f"({_vec(colour)}); the scene is grey, so every radiance has that chromaticity")
        files[path] = _exr_writer(channels, header, latlong=True)
        records.append(probe_record(r, path.name))
    doc = {
        "units": "W_m2: W/m2 (radiometric); lx: lux (photometric); stderr_*: standard error; SH coefficients "
        "are integrals of radiance times real spherical harmonics over the sphere, world frame (Z up)",
        "seed": meta.get("seed"),
        "method": meta.get("method"),
        "light_units": meta.get("light_units"),
        "probes": records,
    }
    files[csv_path.with_name(f"{csv_path.stem}.probes.json")] = json.dumps(doc, indent=2) + "\n"
    return files, map_files
