"""The surface guide of guided paths, built once per engine from a pilot.

A short pilot of plain ``path`` samples over the sensors (its own seed
stream) tallies, per surface patch (:mod:`simulator.scene.patches`), every
next-event contribution made at a path vertex on it (depth ≥ 1, not the
sensor itself) to the sensor's reading: tally_j = Σ weight·w_MIS·L·cosθ/pdf,
i.e. importance × radiance, so a sunlit wall no sensor sees gets nothing.
Patch j is then drawn with probability P_j ∝ tally_j (0 where the pilot
found no light), a point uniform on it: the guide strategy of
:func:`simulator.kernels.estimators.vertex_irradiance`, used with
probability :data:`GUIDE_C` at path vertices of depth ≥ :data:`GUIDE_FIRST`.

Tallies are kept per *table* (row): row 0 holds what was reached from a
path's first vertex, row 1 (or one row per prim, :data:`ROWS_PER_PRIM`)
what was reached from surfaces. A table whose light is spread about as
evenly as the area (:func:`~simulator.scene.patches.concentration` <
:data:`MIN_CONCENTRATION`) is left empty: there cosine sampling is already
near ideal and the mixture's weights only add variance.

The pilot's samples are discarded, not pooled into the readings: they are
a small fixed cost (:data:`PILOT_SAMPLES` per sensor), pooling would save
at most that fraction of a run, and leaving them out keeps every reading
one estimator's samples (so its standard error is that estimator's). The
pilot draws from a seed stream of its own, so the guide is independent of
the readings' samples and they stay unbiased whatever it learnt.

Measured choices (docs/DESIGN.md, "Surface guide"): c = 0.3; the guide
from depth 1 on (a work-plane sensor faces the ceiling, which no light
reaches directly, so the guide's patches are rarely visible from it); one
table for all surfaces (per-prim tables measured no better on the office).

References
----------
J. Vorba, O. Karlík, M. Šik, T. Ritschel, J. Křivánek, "On-line learning of
parametric mixture models for light transport simulation", ACM TOG 33(4),
2014 (learning a sampling density from pilot paths).
T. Müller, M. Gross, J. Novák, "Practical path guiding for efficient
light-transport simulation", Computer Graphics Forum 36(4), 2017.
E. Veach, "Robust Monte Carlo Methods for Light Transport Simulation", PhD
thesis, Stanford, 1997, §9.2.4 (one-sample MIS).
"""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass

import numpy as np

from simulator.scene.patches import concentration, patch_distribution_rows

#: samples one kernel thread draws (the driver's BLOCK, repeated here: this module imports no Warp)
BLOCK = 32

__all__ = [
    "GUIDE_C", "GUIDE_FIRST", "GUIDE_DEPTH", "PILOT_SAMPLES", "PILOT_MIN_TOTAL", "PILOT_BLOCKS", "GuideInfo", "pilot_chunks",
    "pilot_seed", "build_guide", "scenario_tally",
]  # fmt: skip

#: probability c of the guide strategy at a vertex (see docs/DESIGN.md for the measurement)
GUIDE_C = 0.3
#: the guide is used at vertices of depth ≥ GUIDE_FIRST ...
GUIDE_FIRST = 1
#: ... and < GUIDE_DEPTH (−1: no upper bound)
GUIDE_DEPTH = -1
#: one guide table per prim a vertex lies on (else one for all surfaces)
ROWS_PER_PRIM = False
#: a guide table whose pilot light is spread more evenly than this
#: (:func:`~simulator.scene.patches.concentration`) is left empty, and its
#: vertices sample cosine directions only: measured D = 16 on the office
#: (the guide gains there), 1.9 on the quickstart room (no gain), 1.0–1.3 in
#: the furnace and CIE 171 case 5.8 (where a guide costs 10× in variance)
MIN_CONCENTRATION = 4.0
#: pilot samples per sensor ...
PILOT_SAMPLES = 32
#: ... and at least this many in all (a lone sensor still gets a usable guide)
PILOT_MIN_TOTAL = 16384
#: the pilot's tallies are kept per block of consecutive kernel threads (each
#: block summed in float32 on one worker, in index order; the blocks then in
#: float64, in order): at most this many blocks (so at most this many CPU
#: workers share a pilot; memory: blocks × rows × patches × 8 bytes, 16 MiB
#: at 16,384 patches and 2 rows) ...
PILOT_BLOCKS = 64
#: ... of at least this many kernel threads (of BLOCK samples each)
PILOT_CHUNK_MIN = 8


@dataclass
class GuideInfo:
    """What a run record says about the guide.

    Attributes
    ----------
    seconds : float
        Wall time of the pilot and the upload.
    pilot_samples : int
        Pilot path samples drawn (all sensors).
    patches : int
        Patches in the layout.
    sampled : int
        Patches the guide can draw (P_j > 0, in any table).
    concentration : list of float
        Each table's :func:`~simulator.scene.patches.concentration` D (a
        table with D < MIN_CONCENTRATION is left empty).
    reason : str
        One line: the layout, and whether the guide is used.
    """

    seconds: float
    pilot_samples: int
    patches: int
    sampled: int
    concentration: list
    reason: str

    def to_record(self) -> dict:
        return asdict(self)


def pilot_chunks(n_threads: int) -> tuple[int, int]:
    """``(chunk, blocks)``: the pilot's ``n_threads`` kernel threads tally in
    ``blocks`` blocks of ``chunk`` consecutive threads each (the last one
    shorter), at least :data:`PILOT_CHUNK_MIN` threads and at most
    :data:`PILOT_BLOCKS` blocks. A function of the pilot's size alone, so
    the tallies, and the guide, are the same whatever the thread count."""
    chunk = max(PILOT_CHUNK_MIN, -(-int(n_threads) // PILOT_BLOCKS))
    return chunk, max(1, -(-int(n_threads) // chunk))


def pilot_seed(seed: int) -> int:
    """The pilot's seed: a stream of its own, apart from the run's (seed + 1 is
    another run's, so it is not used)."""
    return int((int(seed) * 0x9E3779B1 + 0x5BD1E995) & 0x7FFFFFFF)


def scenario_tally(tallies: np.ndarray, levels: np.ndarray) -> np.ndarray:
    """One guide tally that serves several dimming scenarios: (rows, N) from per-group tallies.

    Parameters
    ----------
    tallies : ndarray, shape (G, rows, N)
        The pilot's tally of each light group lit alone (at its authored emission).
    levels : ndarray, shape (J, G)
        Each scenario's level of each group.

    Notes
    -----
    The tally is linear in emission, so scenario j's is T_j = Σ_g d_jg T_g. Each row is
    normalised to its sum and the patches take the largest share any scenario gives them,
    T = max_j T_j / ΣT_j: every scenario's patches keep at least 1/Z of the guide's picks
    they would get from a guide of their own (Z = Σ_patches max_j of the shares, as for the
    scenario-aware light pick, :mod:`simulator.engine.scenario_pick`). A guide learnt on
    every group at its authored level instead sends a lamp-only scenario's guided
    directions toward the sun patch on the floor (measured on the office: 1.5× a plain
    run's variance per sample).
    """
    t = np.einsum("jg,grn->jrn", np.asarray(levels, np.float64), np.asarray(tallies, np.float64))
    s = t.sum(axis=2, keepdims=True)
    share = np.where(s > 0, t / np.where(s > 0, s, 1.0), 0.0)
    return share.max(axis=0)


def build_guide(engine, seed: int, sensor_ids: np.ndarray, max_depth: int = -1, lit: np.ndarray | None = None,
                levels: np.ndarray | None = None) -> GuideInfo:  # fmt: skip
    """Run the pilot over ``sensor_ids`` and upload the guide to ``engine``'s device.

    Parameters
    ----------
    engine : simulator.engine.driver.Engine
    seed : int
        The run's seed (the pilot draws from :func:`pilot_seed` of it).
    sensor_ids : ndarray of int
        Sensors the pilot samples.
    max_depth : int
        Bounce limit, as for the run (−1: unbounded).
    lit : ndarray, shape (G, L), optional
        For a pass that serves dimming scenarios: per light group, each light record's emission
        scale in its own pilot (1 in the group, 0 elsewhere); the pilot's samples per sensor are
        shared among the groups, so the pilot costs what one pilot does.
    levels : ndarray, shape (J, G), optional
        The scenarios' levels of those groups (:func:`scenario_tally`).
    """
    dev = engine._dev  # the scene on the device first: its upload is the setup's, not the guide's
    t0 = time.perf_counter()
    lay = dev.layout
    ids = np.asarray(sensor_ids, np.int64)
    n_pilot = 0
    if lay.usable and len(ids):
        per = max(PILOT_SAMPLES, -(-PILOT_MIN_TOTAL // len(ids)))
        params = engine.trace_params("path", pilot_seed(seed), max_depth, "total")
        params.tally = 1
        chunk, blocks = pilot_chunks(len(ids) * -(-per // BLOCK))
        params.tally_chunk = chunk
        if lit is None:
            dev.tally_rows(blocks)
            engine._launch(params, ids, np.zeros(len(ids), np.int64), np.full(len(ids), per, np.int64))
            n_pilot = per * len(ids)
            tally = dev.read_tally(blocks)  # (guide rows, N, 2), the blocks summed in order in float64
            channel = 0 if tally[..., 0].sum() > 0 else 1
            tally = tally[..., channel].copy()
        else:
            each = BLOCK * max(1, -(-per // (BLOCK * len(lit))))  # the pilot's samples shared among the groups
            chunk, blocks = pilot_chunks(len(ids) * -(-each // BLOCK))
            params.tally_chunk = chunk
            parts = []
            try:
                for scale in lit:
                    dev.set_light_scale(scale)
                    dev.tally_rows(blocks)
                    engine._launch(params, ids, np.zeros(len(ids), np.int64), np.full(len(ids), each, np.int64))
                    parts.append(dev.read_tally(blocks))
            finally:
                dev.set_light_scale(None)
            n_pilot = each * len(ids) * len(lit)
            parts = np.asarray(parts)  # (G, rows, N, 2)
            channel = 0 if parts[..., 0].sum() > 0 else 1
            tally = scenario_tally(parts[..., channel], levels)
        conc = [concentration(t, lay) for t in tally]
        for r, d in enumerate(conc):
            if d < MIN_CONCENTRATION or (r == 0 and GUIDE_FIRST > 0):  # row 0 serves depth 0 only
                tally[r] = 0.0  # evenly spread light: cosine directions alone do better
        pid, cdf, row_start, density = patch_distribution_rows(tally, lay)
        dev.set_guide(pid, cdf, row_start, density)
        sampled = len(np.unique(pid))
    else:
        conc, sampled = [], 0
    used = "used" if sampled else f"not used (light spread evenly: concentration < {MIN_CONCENTRATION:g})"
    reason = lay.reason if not lay.usable else f"{lay.reason}; {used}"
    return GuideInfo(time.perf_counter() - t0, n_pilot, lay.n_patches, sampled, [round(d, 3) for d in conc], reason)
