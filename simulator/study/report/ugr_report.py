"""UGR at the EN 12464-1 areas' observers: ``ugr.csv`` and report.html's section (:mod:`simulator.study.figures.ugr`).

``ugr.csv``: one row per (area, observer, scenario), :data:`~simulator.study.figures.ugr.UGR_COLUMNS`.
The report's section gives, per area and scenario, the worst observer's UGR with its standard error
against the area's UGR_L and the verdict, then every observer; registered after the areas' section.
"""

from __future__ import annotations

import csv
import io
import math

from simulator.io.numbers import plain, with_error
from simulator.study.report.page import Section, esc, register_section, table_html, verdict_cell

__all__ = ["ugr_csv", "ugr_section"]

_ORDER = {"fail": 0, "unsure": 1, "pass": 2}


def _g(x: float) -> str:
    return "" if not math.isfinite(x) else f"{x:.6g}"


def ugr_csv(res) -> str:
    """The study's ``ugr.csv``."""
    from simulator.study.figures.ugr import UGR_COLUMNS

    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(UGR_COLUMNS)
    for r in res.ugr:
        o = r.observer
        w.writerow([r.area, o.name, *(_g(float(v)) for v in o.position), *(_g(float(v)) for v in o.direction), r.scenario,
                    _g(r.ugr), _g(r.ugr_stderr), _g(r.limit), r.verdict, _g(r.background_cd_m2), _g(r.indirect_lx),
                    _g(r.indirect_stderr_lx), r.luminaires])  # fmt: skip
    return buf.getvalue()


def ugr_section(res) -> Section | None:
    rows_in = getattr(res, "ugr", [])
    if not rows_in:
        return None
    worst: dict = {}
    for r in rows_in:
        k = (r.area, r.scenario)
        if k not in worst or (_ORDER[r.verdict], -r.ugr) < (_ORDER[worst[k].verdict], -worst[k].ugr):
            worst[k] = r
    summary = [[a, sc, r.observer.name, with_error(r.ugr, r.ugr_stderr) if math.isfinite(r.ugr) else "—", f"≤ {plain(r.limit)}",
                verdict_cell(r.verdict)] for (a, sc), r in worst.items()]  # fmt: skip
    detail = [[r.area, r.observer.name, ", ".join(f"{v:.2f}" for v in r.observer.position),
               ", ".join(f"{v:.2f}" for v in r.observer.direction), r.scenario,
               with_error(r.ugr, r.ugr_stderr) if math.isfinite(r.ugr) else "—", r.luminaires,
               with_error(r.indirect_lx, r.indirect_stderr_lx, "lx"), verdict_cell(r.verdict)] for r in rows_in]  # fmt: skip
    body = ("<p>Unified glare rating of the lamps at each area's observers (CIE 117: 8·log10(0.25/L_b·Σ L²ω/P²), "
            "the luminaires as seen from the eye, L_b the indirect illuminance at the eye over π, daylight left out), "
            "against the area's UGR_L (EN 12464-1). Per area and scenario, the worst observer:</p>"
            + table_html(["area", "scenario", "observer", "UGR", "UGR_L", "verdict"], summary, "num")
            + "<p>Every observer (eye position and view direction in metres; luminaires in sight; the indirect "
            "illuminance at the eye, which sets the background):</p>"
            + table_html(["area", "observer", "eye (m)", "looking", "scenario", "UGR", "lamps seen", "E_ind", "verdict"],
                         detail, "num")
            + f"<p>{esc('pass: below UGR_L by more than 2 standard errors; fail: above it by more; else unsure.')}</p>")  # fmt: skip
    return Section("ugr", "UGR at the areas' observers (EN 12464-1)", body)


register_section("ugr", ugr_section, after="areas")
