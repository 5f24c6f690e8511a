"""How targets and placement scores are named and read: shared by the CSVs and report.html."""

from __future__ import annotations

from simulator.study.figures.objectives import TARGET_FIGURES

__all__ = ["target_keys", "placement_unit", "score_value", "score_text"]


def target_keys(res) -> list[str]:
    """Every target any zone sets, in ``TARGET_FIGURES`` order."""
    used = {k for z in res.study.zone for k in z.targets}
    return [k for k in TARGET_FIGURES if k in used]


def placement_unit(objective: str) -> str:
    """How a placement score reads: a correlation, or a relative error in percent."""
    return "correlation" if objective == "correlation" else "%"


def score_value(objective: str, v: float) -> float:
    """A placement score (or gain) as reported: correlations as they are, relative errors × 100 (percent)."""
    return float(v) if objective == "correlation" else 100.0 * float(v)


def score_text(objective: str, v: float, se: float) -> str:
    """``0.973 ± 0.004`` for a correlation, ``4.21 ± 0.35 %`` for a relative error
    (:func:`simulator.io.numbers.with_error`: the error to 2 significant digits, the value to match)."""
    from simulator.io.numbers import with_error

    if objective == "correlation":
        return with_error(v, se)
    return with_error(100 * v, 100 * se, "%")
