"""The stage's glare views in a study: ``glare.csv``, their fisheyes, and report.html's glare section.

``glare.csv``: one row per (view, scenario), :data:`~simulator.study.figures.glare_views.GLARE_COLUMNS`
(E_v, DGP, DGPs and UGR, each with its standard error; the glare sources found; the passes drawn).
Per (view, scenario): ``glare_<view>_<scenario>.hdr``, the 180° angular fisheye in Radiance's format with
its view in the header (evalglare reads it), and ``glare_<view>_<scenario>.png``, the false-colour
picture with the sources outlined (:mod:`simulator.io.glare_maps`). The report's section: per view, a
table of the scenarios' figures and the pictures side by side; registered after the areas' section.
"""

from __future__ import annotations

import csv
import io
import math

import numpy as np

from simulator.io.numbers import with_error
from simulator.study.report.page import Section, esc, png_img, register_section, table_html

__all__ = ["glare_csv", "glare_files", "glare_section"]


def _g(x: float) -> str:
    return "" if not math.isfinite(x) else f"{x:.6g}"


def _safe(name: str) -> str:
    return "".join(ch if ch.isalnum() or ch in "-_." else "_" for ch in name)


def glare_csv(res) -> str:
    """The study's ``glare.csv``."""
    from simulator.study.figures.glare_views import GLARE_COLUMNS

    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(GLARE_COLUMNS)
    for row in res.glare:
        e = row.result.estimate
        w.writerow([row.view, row.scenario, _g(e.ev_lx), _g(e.ev_stderr_lx), _g(e.dgp), _g(e.dgp_stderr), _g(e.dgps),
                    _g(e.dgps_stderr), _g(e.ugr), _g(e.ugr_stderr), len(e.sources), row.result.passes])  # fmt: skip
    return buf.getvalue()


def _pictures(row) -> tuple[bytes, bytes]:
    """(HDR, PNG) of one view in one scenario."""
    from simulator.io.glare_maps import fisheye, view_line
    from simulator.io.glare_png import fisheye_png
    from simulator.io.hdr import encode_rgbe

    r = row.result
    img = fisheye(r)
    head = f"#?RADIANCE\nSOFTWARE= probesim glare view {row.view}, scenario {row.scenario}\nVIEW= {view_line(r.sensor.position, r.frame)}\n"
    hdr = encode_rgbe(np.repeat((img["L"] / 179.0)[..., None], 3, axis=-1)).replace(b"#?RADIANCE\n", head.encode("ascii", "replace"), 1)
    return hdr, fisheye_png(img, f"{row.view} ({row.scenario})", r.estimate)


def glare_files(res) -> dict:
    """``{path: bytes}``: ``glare.csv`` and every view's pictures (module docstring)."""
    d = res.out_dir
    files = {d / "glare.csv": glare_csv(res).encode()}
    res.glare_png = {}
    for row in res.glare:
        hdr, png = _pictures(row)
        stem = f"glare_{_safe(row.view)}_{_safe(row.scenario)}"
        files[d / f"{stem}.hdr"] = hdr
        files[d / f"{stem}.png"] = png
        res.glare_png[(row.view, row.scenario)] = png
    return files


def glare_section(res) -> Section | None:
    rows = getattr(res, "glare", [])
    if not rows:
        return None
    pngs = getattr(res, "glare_png", {})
    parts = ["<p>Each glare view of the stage (a prim with probesim:sensor:kind = \"glare\") traced in every scenario: "
             "the vertical illuminance at the eye, DGP (Wienold and Christoffersen 2006, evalglare's constants), DGPs, "
             "UGR (CIE 117, the background the light not from the sources) and the glare sources found as evalglare "
             "finds them, each figure with its standard error; the 180° fisheye with the sources outlined.</p>"]
    for view in dict.fromkeys(r.view for r in rows):
        mine = [r for r in rows if r.view == view]
        table = [[r.scenario, with_error(r.result.estimate.ev_lx, r.result.estimate.ev_stderr_lx, "lx"),
                  with_error(r.result.estimate.dgp, r.result.estimate.dgp_stderr),
                  with_error(r.result.estimate.dgps, r.result.estimate.dgps_stderr),
                  with_error(r.result.estimate.ugr, r.result.estimate.ugr_stderr) if math.isfinite(r.result.estimate.ugr) else "—",
                  len(r.result.estimate.sources)] for r in mine]  # fmt: skip
        figs = "".join(f'<figure class="plan">{png_img(pngs[(view, r.scenario)], f"fisheye of {view}, {r.scenario}")}'
                       f"<figcaption><b>{esc(r.scenario)}</b></figcaption></figure>" for r in mine if (view, r.scenario) in pngs)  # fmt: skip
        parts.append(f"<h3>View {esc(view)}</h3>" + table_html(["scenario", "E_v", "DGP", "DGPs", "UGR", "sources"], table, "num")
                     + f'<div class="plans">{figs}</div>')  # fmt: skip
    return Section("glare", "Glare at the stage's views", "".join(parts))


register_section("glare", glare_section, after="areas")
