"""Chunks of a study: (trace group × sensor block) units of work, their store and resume.

A chunk traces the light groups of one trace group
(:class:`~simulator.study.inputs.scenarios.TraceGroup`) on one block of candidate
sensors, all its groups in one pass. Its seed derives from (study seed,
trace key, block) alone, so a chunk gives the same numbers wherever and whenever it runs.

The store is a folder: ``chunks/<id>.npz`` per finished chunk and
``manifest.json`` listing them with their SHA-256. Both are written
atomically (a temporary file in the same folder, flushed, then renamed), the
chunk before the manifest entry that names it, so an interrupted study
leaves only whole chunks behind. A chunk's id hashes everything its numbers
depend on (stage bytes, variants, sun, the group's lights, the sensors, the
trace settings, the seed, and the code that traces it: :func:`code_digest`); a
study started again loads every chunk whose id is in the manifest with a
matching file and computes only the rest. Chunks another build of probesim
traced are not reused (their numbers may differ within their errors, and a
study mixing them would not be the same bytes as one run whole): the study
removes them and says how many, once (:meth:`ChunkStore.drop_other_code`).
"""

from __future__ import annotations

import functools
import hashlib
import io
import json
import os
import socket
import time
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from simulator.io.atomic import write_atomic
from simulator.scene.model import LightKind, Sensor
from simulator.study.trace.groups import GroupReadings, derive_seed, level_of, patch_names, trace_groups
from simulator.study.inputs.sun import sun_direction, sun_frame

__all__ = ["ChunkSpec", "ChunkStore", "code_digest", "stale_chunks_note", "compute_chunk", "make_chunks", "StudyInterrupted"]

#: the chunk file's and manifest's layout (the code's own changes are in :func:`code_digest`)
CHUNK_FORMAT = 7

#: the package's files a chunk's numbers can depend on: its code, and the tables and settings it ships
_CODE_SUFFIXES = (".py", ".csv", ".toml")


class StudyInterrupted(Exception):
    """Raised by the test hook that stops a study after N chunks."""


@dataclass(frozen=True)
class ChunkSpec:
    """Everything a worker needs to compute one chunk (picklable, no scene)."""

    id: str
    trace_key: str
    block: int
    stage: str
    light_units: str
    variants: tuple[tuple[str, str], ...]
    sun: tuple[float, float] | None
    groups: tuple[tuple[str, tuple[str, ...]], ...]
    sensor_ids: tuple[int, ...]  #: indices into the study's candidate list
    sensors: tuple[Sensor, ...]
    sim: dict
    seed: int
    levels: tuple[tuple[tuple[str, float], ...], ...] = ()  #: the trace group's dimming vectors (adaptive targets)
    threads: int = 0
    sky_split: tuple[str, ...] = ()  #: groups whose sky is traced as Tregenza patches
    extra_lights: tuple = ()  #: lights added to the stage's (a diffusing shade's cells, :mod:`simulator.study.annual.diffusers`)
    code: str = ""  #: the build that planned it (:func:`code_digest`): a worker of another build refuses it


@functools.lru_cache(maxsize=1)
def code_digest() -> str:
    """SHA-256 (hex, 20 digits) of the code that traces a chunk: the probesim package's files
    (:func:`tree_digest`) and the versions of Warp and numpy. Any edit to the package counts, a
    comment included: a chunk is reused only by the build that traced it."""
    from importlib.metadata import PackageNotFoundError, version

    import simulator

    h = hashlib.sha256(tree_digest(Path(simulator.__file__).resolve().parent).encode())
    for dist in ("warp-lang", "numpy"):
        try:
            h.update(f";{dist}=={version(dist)}".encode())
        except PackageNotFoundError:
            h.update(f";{dist} not installed".encode())
    return h.hexdigest()[:20]


def tree_digest(root: Path) -> str:
    """SHA-256 (hex) of every source file, table and settings file under ``root`` (suffixes
    :data:`_CODE_SUFFIXES`, ``__pycache__`` left out): each one's path relative to ``root`` and its
    bytes, length-prefixed, in path order, so a file edited, added, removed or renamed changes it."""
    h = hashlib.sha256()
    files = sorted(p for p in root.rglob("*") if p.suffix in _CODE_SUFFIXES and p.is_file() and "__pycache__" not in p.parts)
    for p in files:
        rel = p.relative_to(root).as_posix().encode()
        data = p.read_bytes()
        h.update(b"%d:%s%d:" % (len(rel), rel, len(data)))
        h.update(data)
    return h.hexdigest()


def stale_chunks_note(out_dir, n: int) -> str:
    """The study's one-line note on the chunks in ``out_dir`` another build traced (:meth:`ChunkStore.drop_other_code`)."""
    return (f"{out_dir}: {n} finished chunk{'s' if n != 1 else ''} in this folder {'were' if n != 1 else 'was'} "
            "traced by another build of probesim: removed, and traced again where this study needs them")  # fmt: skip


def _sensor_text(s: Sensor) -> str:
    text = f"{s.name}|{int(s.kind)}|{s.position.tolist()}|{s.normal.tolist()}|{s.half_angle!r}"
    if "up" in s.spec.attributes and s.spec.name != "patch":  # a cylinder's axis
        text += f"|{s.up.tolist()}"
    if getattr(s, "optics", None) is not None:  # a sensor model's head: another head is another reading
        text += f"|optics {s.optics.digest()}"
    return text


def make_chunks(trace_groups, sensors: list[Sensor], groups: dict[str, list[str]], stage: Path, light_units: str,
                sim: dict, seed: int, block: int, sky_split: tuple[str, ...] = (), extra_lights: tuple = (),
                extra_ident: dict | None = None) -> list[ChunkSpec]:  # fmt: skip
    """One chunk per (trace group, block of ``block`` sensors), in a fixed order.

    ``sky_split``: groups traced as sky patches; their slots' levels
    (``group/pNNN``, ``group/ground``) join the dimming vectors.
    ``extra_lights``: lights added to the stage in every chunk (groups may name them).
    ``extra_ident``: more that the chunks' numbers depend on (their ids hash it; the seeds do not)."""
    from simulator.scene.usd.dependencies import stage_digest

    stage_sha = stage_digest(stage)  # every layer and asset the stage reads: a changed sublayer is a new chunk
    out = []
    for tg in trace_groups:
        if not tg.groups:
            continue
        gl = tuple((g, tuple(groups[g])) for g in tg.groups)
        split = tuple(g for g in tg.groups if g in sky_split)
        slots = [n for g in tg.groups for n in ([g] + (patch_names(g) if g in split else []))]
        levels = tuple(tuple((n, level_of(sc.levels, n)) for n in slots) for sc in tg.scenarios)
        for b, lo in enumerate(range(0, len(sensors), block)):
            ids = tuple(range(lo, min(lo + block, len(sensors))))
            cseed = derive_seed(seed, tg.key, b)
            ident = {
                "format": CHUNK_FORMAT, "stage": stage_sha, "light_units": light_units, "key": tg.key, "groups": gl,
                "sensors": [_sensor_text(sensors[i]) for i in ids], "sim": sim, "seed": cseed, "levels": levels,
                "code": code_digest(),
            }  # fmt: skip
            if split:
                ident["sky_split"] = split
            if extra_ident:
                ident.update(extra_ident)
            cid = hashlib.sha256(json.dumps(ident, sort_keys=True).encode()).hexdigest()[:20]
            out.append(ChunkSpec(cid, tg.key, b, str(stage), light_units, tuple(sorted(tg.variants.items())), tg.sun, gl, ids,
                                 tuple(sensors[i] for i in ids), sim, cseed, levels, sky_split=split,
                                 extra_lights=tuple(extra_lights), code=code_digest()))  # fmt: skip
    return out


@functools.lru_cache(maxsize=8)
def _stage(stage: str, light_units: str, variants: tuple):
    from simulator.scene.usd import load_stage

    return load_stage(stage, light_units=light_units, radiometric_spectrum="E", variants=dict(variants))


def chunk_scene(spec: ChunkSpec):
    """The scene of a chunk's trace group: the stage with its variants and extra lights, the sun turned to ``spec.sun``."""
    scene = _stage(spec.stage, spec.light_units, spec.variants)
    if spec.extra_lights:
        scene = replace(scene, lights=list(scene.lights) + list(spec.extra_lights))
    if spec.sun is None:
        return scene
    frame = sun_frame(sun_direction(*spec.sun))
    lights = [replace(l, frame=frame) if l.kind == LightKind.DISTANT else l for l in scene.lights]
    return replace(scene, lights=lights)


def compute_chunk(spec: ChunkSpec) -> dict:
    """Trace one chunk; returns plain arrays (see :meth:`ChunkStore.save`). A worker whose build of probesim
    is not the one that planned the chunk (another version, another Warp or numpy: a dask cluster's
    workers are installed apart from the study's machine) refuses it, so that no study mixes builds."""
    from simulator.config.loader import SimulationConfig
    from simulator.errors import UserError

    if spec.code and spec.code != code_digest():
        raise UserError(f"chunk {spec.id}: the worker on {socket.gethostname()} runs another build of probesim than the "
                        "study's (another version, or another Warp or numpy): install the same on every dask worker")  # fmt: skip
    t0 = time.perf_counter()
    scene = chunk_scene(spec)
    sim = SimulationConfig(**spec.sim)
    gr = trace_groups(scene, list(spec.sensors), {g: list(ls) for g, ls in spec.groups}, sim, spec.seed, threads=spec.threads,
                      scenarios=[dict(lv) for lv in spec.levels], sky_split=spec.sky_split)  # fmt: skip
    return {
        "id": spec.id, "names": gr.names, "mean": gr.mean, "stderr": gr.stderr, "cov": gr.cov, "samples": gr.samples,
        "trace_s": gr.trace_s, "trace_cpu_s": gr.trace_cpu_s, "methods": list(gr.methods), "wall_s": time.perf_counter() - t0, "host": socket.gethostname(), "pid": os.getpid(),
    }  # fmt: skip


def readings_of(result: dict) -> GroupReadings:
    return GroupReadings(list(result["names"]), result["mean"], result["stderr"], result["cov"], result["samples"], result["trace_s"],
                         float(result.get("trace_cpu_s", 0.0)), [str(m) for m in result.get("methods", [])])  # fmt: skip


class ChunkStore:
    """Finished chunks in ``<dir>/chunks`` and their manifest ``<dir>/manifest.json``."""

    def __init__(self, root: Path):
        self.root = Path(root)
        self.dir = self.root / "chunks"
        self.manifest_path = self.root / "manifest.json"
        self.entries: dict[str, dict] = {}
        if self.manifest_path.is_file():
            try:
                self.entries = json.loads(self.manifest_path.read_text()).get("chunks", {})
            except (OSError, ValueError):
                self.entries = {}  # unreadable manifest: recompute everything

    def drop_other_code(self) -> int:
        """Remove the finished chunks another build of probesim traced (an entry written before builds were
        recorded counts as another's), their files and manifest entries; how many. This build never loads
        them (their ids hash the build that traced them), so kept they would only be warned about again
        on every later resume."""
        me = code_digest()
        stale = [cid for cid, e in self.entries.items() if not isinstance(e, dict) or e.get("code") != me]
        for cid in stale:
            name = self.entries.pop(cid)
            try:
                (self.dir / name["file"]).unlink()
            except (OSError, KeyError, TypeError):  # gone already, or an entry that names no file
                pass
        if stale:
            self._write_manifest()
        return len(stale)

    def load(self, cid: str) -> dict | None:
        """A finished chunk's arrays, or None when it is missing or its file does not match the manifest."""
        e = self.entries.get(cid)
        if e is None:
            return None
        p = self.dir / e["file"]
        try:
            data = p.read_bytes()
        except OSError:
            return None
        if hashlib.sha256(data).hexdigest() != e["sha256"]:
            return None
        with np.load(io.BytesIO(data), allow_pickle=False) as z:
            out = {k: z[k] for k in z.files}
        out["names"] = [str(n) for n in out["names"]]
        out["methods"] = [str(m) for m in out.get("methods", [])]
        out["id"] = cid
        out.update({k: e[k] for k in ("wall_s", "host", "pid") if k in e})
        return out

    def save(self, result: dict) -> None:
        """Write a chunk, then its manifest entry, each atomically."""
        buf = io.BytesIO()
        np.savez(buf, names=np.array(result["names"]), mean=result["mean"], stderr=result["stderr"], cov=result["cov"],
                 samples=result["samples"], trace_s=result["trace_s"], trace_cpu_s=np.float64(result.get("trace_cpu_s", 0.0)),
                 methods=np.array(list(result.get("methods", [])), dtype=str))  # fmt: skip
        data = buf.getvalue()
        name = f"{result['id']}.npz"
        write_atomic(self.dir / name, data, durable=True)
        self.entries[result["id"]] = {
            "file": name, "sha256": hashlib.sha256(data).hexdigest(), "wall_s": float(result["wall_s"]),
            "host": result.get("host", ""), "pid": int(result.get("pid", 0)), "code": code_digest(),
        }  # fmt: skip
        self._write_manifest()

    def _write_manifest(self) -> None:
        data = json.dumps({"format": CHUNK_FORMAT, "chunks": self.entries}, indent=1, sort_keys=True).encode()
        write_atomic(self.manifest_path, data, durable=True)
