"""Command-line flags applied to a loaded config, checked by the config's own schema.

The flags are written into the tables a file would hold them in
(``--samples`` is ``simulation.samples``) and the result goes through
:class:`~simulator.config.schema.RunFile` like a file does, so a flag
obeys exactly the rule of its key; a message names the flag instead of the
key (``--samples: must be >= 1, got 0``).
"""

from __future__ import annotations

import os
from dataclasses import asdict, replace
from pathlib import Path

from pydantic_core import ValidationError

from simulator.config.errors import translate, user_error
from simulator.config.paths import resolve_path
from simulator.config.records import RunConfig
from simulator.config.schema import RunFile
from simulator.config.variants import parse_flag

__all__ = ["apply_overrides", "check_flags", "FLAGS"]

#: ``[simulation]`` key of each flag that sets one, and the flag
FLAGS = {
    "seed": "--seed",
    "samples": "--samples",
    "device": "--device",
    "method": "--method",
    "rel_error": "--rel-error",
    "confidence": "--confidence",
}


def check_flags(**values) -> dict:
    """``[simulation]`` flags checked by the schema's own rules, without a config.

    For commands that take a flag of a ``[simulation]`` key but no config of
    their own (``probesim bench --samples``): the flag obeys exactly the rule
    of its key, and a message names the flag. ``values`` maps keys of
    :data:`FLAGS` to values (None: not given).

    Returns
    -------
    dict
        The given values as the schema reads them.

    Raises
    ------
    UserError
        ``--samples: must be >= 1, got 0``.
    """
    flags = {key: v for key, v in values.items() if v is not None}
    unknown = sorted(set(flags) - set(FLAGS))
    if unknown:
        raise ValueError(f"not a [simulation] flag: {', '.join(unknown)}")
    table = {"stage": "-", "simulation": flags}
    try:
        doc = RunFile.model_validate(table)
    except ValidationError as exc:
        raise translate(exc, table, None, {f"simulation.{key}": flag for key, flag in FLAGS.items()}) from None
    return {key: getattr(doc.simulation, key) for key in flags}


def apply_overrides(
    cfg: RunConfig,
    *,
    seed: int | None = None,
    samples: int | None = None,
    device: str | None = None,
    csv: str | os.PathLike | None = None,
    method: str | None = None,
    rel_error: float | None = None,
    confidence: float | None = None,
    variants: list[str] | None = None,
    time: float | None = None,
) -> RunConfig:
    """Apply command-line flags to a config.

    Parameters
    ----------
    cfg : RunConfig
        A config from :func:`~simulator.config.loader.load_config`; left
        unchanged.
    seed : int, optional
        Replaces ``simulation.seed``; ``0 <= seed < 2**31``.
    samples : int, optional
        Replaces ``simulation.samples``; > 0.
    device : str, optional
        Replaces ``simulation.device``; one of
        :data:`~simulator.config.records.DEVICES`.
    csv : str or path-like, optional
        Replaces ``output.csv``; resolved against the current directory.
    method : str, optional
        Replaces ``simulation.method``; one of
        :data:`~simulator.config.records.METHODS`.
    rel_error : float, optional
        Replaces ``simulation.rel_error`` (makes the run adaptive); in (0, 1).
    confidence : float, optional
        Replaces ``simulation.confidence``; in (0.5, 1).
    variants : list of str, optional
        ``"set=variant"`` selections (``--variant``), added to the config's
        ``variants`` table and overriding the same set there, or
        ``"/prim/path:set=variant"`` (that prim only; see
        :mod:`simulator.config.variants`).
    time : float, optional
        Replaces ``time``, the USD time code the stage is read at.

    Returns
    -------
    RunConfig
        A new config; ``overrides`` records the flags given.

    Raises
    ------
    UserError
        A flag value is invalid; the one-line message names the flag
        (``--samples: must be >= 1, got 0``).
    """
    values = {"seed": seed, "samples": samples, "device": device, "method": method, "rel_error": rel_error,
              "confidence": confidence}  # fmt: skip
    flags = {key: v for key, v in values.items() if v is not None}
    chosen = {k: (dict(v) if isinstance(v, dict) else v) for k, v in cfg.variants.items()}
    for item in variants or ():
        parsed = parse_flag(item)
        if parsed is None:
            raise user_error(None, "--variant", f"expected SET=VARIANT or /PRIM/PATH:SET=VARIANT, got {item!r}")
        path, name, choice = parsed
        if path is None:
            chosen[name] = choice
        else:
            chosen.setdefault(path, {})[name] = choice

    kept = {k: v for k, v in asdict(cfg.simulation).items() if k != "samples_set"}
    table = {"stage": str(cfg.stage), "variants": chosen, "simulation": {**kept, **flags}}
    if time is not None:
        table["time"] = time
    elif cfg.time is not None:
        table["time"] = cfg.time
    if csv is not None:
        table["output"] = {"csv": os.fspath(csv)}
    rename = {f"simulation.{key}": flag for key, flag in FLAGS.items()}
    rename.update({"output.csv": "--csv", "variants": "--variant", "time": "--time"})
    rename.update({f"variants.{name}": "--variant" for name in chosen})
    rename.update({f"variants.{path}.{name}": "--variant" for path, sets in chosen.items() if isinstance(sets, dict)
                   for name in sets})
    try:
        doc = RunFile.model_validate(table)
    except ValidationError as exc:
        raise translate(exc, table, None, rename) from None

    simulation = replace(doc.simulation.to_record(), samples_set=cfg.simulation.samples_set or samples is not None)
    given = {key: getattr(simulation, key) for key in flags}
    if variants:
        given["variants"] = list(variants)
    if time is not None:
        given["time"] = doc.time
    output = cfg.output
    if csv is not None:
        output = replace(output, csv=resolve_path(Path.cwd(), doc.output.csv))
        given["csv"] = str(output.csv)
    return replace(
        cfg,
        simulation=simulation,
        output=output,
        variants=dict(doc.variants),
        time=doc.time,
        times=None if time is not None else getattr(cfg, "times", None),  # --time: one reading, that time
        overrides={**cfg.overrides, **given},
    )
