"""OpenEXR in and out, as plain numpy arrays (no Warp, no USD).

What probesim needs, in four calls:

* :func:`read_rgb` reads an image (a DomeLight's lat-long ``texture:file``)
  as float32 linear RGB, shape ``(H, W, 3)``, row 0 at the top
  (``dataWindow.min.y``);
* :func:`read_channels` reads every channel by name, :func:`read_header`
  the header attributes (to compare maps);
* :func:`write_channels` writes named float32 channels (probe and grid maps)
  with string metadata (and OpenEXR's ``envmap`` attribute for lat-long
  maps), atomically: a reader never sees half a file, and a failed write
  leaves no file behind.

Lat-long maps follow :mod:`simulator.io.latlong` (the OpenEXR orientation).

Only the first part of a multi-part file is read. Half and uint channels are
converted to float32. Problems with a file are :class:`~simulator.errors.UserError`
naming it.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path

import numpy as np

from simulator.errors import UserError, require_file

__all__ = ["read_rgb", "read_header", "read_channels", "write_channels", "RESERVED_HEADER_KEYS"]

#: header attributes that OpenEXR owns; :func:`write_channels` refuses them as metadata
RESERVED_HEADER_KEYS = frozenset({
    "channels", "compression", "dataWindow", "displayWindow", "lineOrder", "pixelAspectRatio",
    "screenWindowCenter", "screenWindowWidth", "type", "tiles", "name", "version", "chunkCount", "envmap",
})


def _open(path: str | os.PathLike, header_only: bool = False):
    import OpenEXR

    p = require_file(path)
    try:
        if not OpenEXR.isOpenExrFile(str(p)):
            raise UserError(f"{path}: not an OpenEXR file")
        return OpenEXR.File(str(p), separate_channels=True, header_only=header_only)
    except UserError:
        raise
    except Exception as exc:  # RuntimeError from the library: truncated, deep, ...
        raise UserError(f"{path}: not a readable OpenEXR file ({' '.join(str(exc).split())[:200]})") from None


def read_header(path: str | os.PathLike) -> dict:
    """The first part's header attributes, ``{name: value}`` (pixels are not read)."""
    return dict(_open(path, header_only=True).header())


def read_channels(path: str | os.PathLike) -> dict[str, np.ndarray]:
    """Every channel of the first part as float32, ``{name: (H, W) array}``.

    A packed ``RGB``/``RGBA`` entry (how the library groups R, G, B and A)
    is split into its single channels.
    """
    f = _open(path)
    try:
        raw = {name: np.asarray(ch.pixels) for name, ch in f.channels().items()}
    except Exception as exc:
        raise UserError(f"{path}: cannot read pixels ({' '.join(str(exc).split())[:200]})") from None
    out: dict[str, np.ndarray] = {}
    for name, px in raw.items():
        if px.ndim == 3 and len(name) == px.shape[2]:
            out.update({c: px[..., k].astype(np.float32) for k, c in enumerate(name)})
        else:
            out[name] = px.astype(np.float32)
    return out


def read_rgb(path: str | os.PathLike) -> np.ndarray:
    """Read an image as linear RGB.

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    ndarray, shape (H, W, 3), float32
        Channels R, G, B (A and others ignored); a grey image (channel ``Y``
        only) is replicated into all three. Row 0 is the top of the image.

    Raises
    ------
    UserError
        The file is missing, is not a readable OpenEXR image, or has neither
        R, G, B nor Y channels; the message names the file.
    """
    channels = read_channels(path)
    if all(c in channels for c in "RGB"):
        rgb = np.stack([channels[c] for c in "RGB"], axis=-1)
    elif "Y" in channels:
        rgb = np.repeat(np.asarray(channels["Y"])[..., None], 3, axis=-1)
    else:
        found = ", ".join(sorted(channels)) or "none"
        raise UserError(f"{path}: needs channels R, G, B (or Y), found {found}")
    rgb = np.asarray(rgb, dtype=np.float32)
    if rgb.ndim != 3 or rgb.shape[0] < 1 or rgb.shape[1] < 1:
        raise UserError(f"{path}: image has no pixels")
    return rgb


def write_channels(path: str | os.PathLike, channels: dict[str, np.ndarray], header: dict[str, str] | None = None,
                   envmap: str | None = None) -> None:
    """Write float32 channels and string metadata to an OpenEXR file, atomically.

    Parameters
    ----------
    path : str or os.PathLike
        Destination; its folder must exist. An existing file is replaced.
    channels : dict of str to ndarray, each shape (H, W)
        Channel name -> values (converted to float32). Names like ``R``,
        ``G``, ``B``, ``Y`` or ``irradiance.R`` (layers) are all fine.
    header : dict of str to str, optional
        Metadata stored as OpenEXR string attributes (e.g. units, the map
        convention, the run seed). Keys OpenEXR reserves
        (:data:`RESERVED_HEADER_KEYS`) are refused.

    Notes
    -----
    The image is written to a temporary file in the destination folder and
    renamed over ``path`` (``os.replace`` is atomic on one file system).
    ZIP compression (lossless). ``envmap="latlong"`` sets OpenEXR's standard
    ``envmap`` attribute, which marks the image as a lat-long environment map.
    """
    import OpenEXR

    if not channels:
        raise ValueError("write_channels: no channels")
    arrays = {str(k): np.ascontiguousarray(v, dtype=np.float32) for k, v in channels.items()}
    shapes = {a.shape for a in arrays.values()}
    if len(shapes) != 1 or len(next(iter(shapes))) != 2:
        raise ValueError(f"write_channels: channels must share one 2-D shape (H, W), got {sorted(shapes)}")
    meta = dict(header or {})
    bad = [k for k in meta if k in RESERVED_HEADER_KEYS]
    if bad:
        raise ValueError(f"write_channels: header keys reserved by OpenEXR: {bad}")
    if not all(isinstance(k, str) and isinstance(v, str) for k, v in meta.items()):
        raise ValueError("write_channels: header keys and values must be strings")
    hdr = {"compression": OpenEXR.ZIP_COMPRESSION, "type": OpenEXR.scanlineimage, **meta}
    if envmap is not None:
        if envmap != "latlong":
            raise ValueError(f"write_channels: envmap must be 'latlong' or None, not {envmap!r}")
        hdr["envmap"] = OpenEXR.ENVMAP_LATLONG
    dest = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{dest.name}.", suffix=".tmp", dir=dest.parent)
    os.close(fd)
    try:
        OpenEXR.File(hdr, arrays).write(tmp)
        umask = os.umask(0)  # mkstemp makes 0600 files; give the usual mode the umask allows
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, dest)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise

