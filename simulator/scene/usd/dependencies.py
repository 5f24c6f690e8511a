"""The files a stage is read from, and one digest of them all.

A study keeps its traced chunks on disk under ids that hash what they
depend on. The root layer alone is not enough: a stage that sublayers,
references or pays load another file (``office_shading.usda`` over
``office.usda``), or names an IES profile or a texture, reads differently
when that file changes, and a chunk keyed by the root layer's bytes would be
served stale. :func:`stage_digest` hashes every layer and asset the stage
depends on (``UsdUtils.ComputeAllDependencies``), each by its path relative
to the root layer's folder and its bytes.
"""

from __future__ import annotations

import hashlib
import os
from pathlib import Path

__all__ = ["stage_files", "stage_digest"]


def stage_files(stage: Path) -> list[Path]:
    """Every local file the stage at ``stage`` is read from: its layers (sublayers, references, payloads)
    and the assets they name (IES files, textures), the root layer first, then sorted; files that do not
    resolve to a local path (unresolved or in-memory layers) are left out."""
    from pxr import UsdUtils

    from simulator.scene.usd.diagnostics import PxrDiagnostics

    root = Path(stage).resolve()
    with PxrDiagnostics():  # an unresolved file is the stage reader's to name (its summary warning), not pxr's stderr
        layers, assets, _unresolved = UsdUtils.ComputeAllDependencies(str(root))
    found = {Path(lay.realPath).resolve() for lay in layers if getattr(lay, "realPath", "")}
    found |= {Path(a).resolve() for a in assets if a}
    found.discard(root)
    return [root] + sorted(p for p in found if p.is_file())


def stage_digest(stage: Path) -> str:
    """SHA-256 (hex) of the stage's files. A stage of one file keeps the digest of its bytes alone (ids of
    chunks traced before stay valid); a stage of several hashes each file's path relative to the root
    layer's folder, with its bytes' digest."""
    files = stage_files(stage)
    if len(files) == 1:
        return hashlib.sha256(files[0].read_bytes()).hexdigest()
    folder = files[0].parent
    h = hashlib.sha256()
    for f in files:
        h.update(os.path.relpath(f, folder).replace(os.sep, "/").encode() + b"\0")
        h.update(hashlib.sha256(f.read_bytes()).digest())
    return h.hexdigest()
