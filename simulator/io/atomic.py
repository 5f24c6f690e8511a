"""Files written whole or not at all, and output folders checked before any work.

Every file probesim writes (outputs, a study's chunks and manifest, its caches) is written to a
temporary sibling and renamed over its name, so a reader sees the old file or the whole new one, and
a write that fails leaves no temporary file behind. Several files written together (a run's CSV,
record and maps) are all staged before the first is renamed.
"""

from __future__ import annotations

import os
from pathlib import Path

from simulator.errors import UserError

__all__ = ["TEMP_SUFFIX", "check_folder", "ensure_folder", "remove_stale_temporaries", "write_all_atomic", "write_atomic"]

#: the suffix of every temporary file a write stages (``.<name>.<random><suffix>`` beside its file)
TEMP_SUFFIX = ".part"


def check_folder(folder: Path, what: str = "output folder") -> None:
    """A :class:`UserError` naming ``folder`` and why, where it could not be made or written in (a file in
    its place or on its path, no permission to write where it would be made); nothing is made, so a
    command can check its outputs' folder before any work and still write nothing when it fails later."""
    folder = Path(folder)
    whole = folder.absolute()
    here = whole
    while not here.exists() and here != here.parent:  # the nearest part of the path there already
        here = here.parent
    if not here.is_dir():
        why = "a file of that name is in the way" if here == whole else "a part of its path is a file, not a folder"
        raise UserError(f"{folder}: cannot make the {what}: {why}")
    if not os.access(here, os.W_OK | os.X_OK):
        raise UserError(f"{folder}: cannot {'write in' if here == whole else 'make'} the {what}: no permission to write in {here}")


def ensure_folder(folder: Path, what: str = "output folder", private: bool = False) -> None:
    """Make ``folder`` (and its parents) if it is missing; a :class:`UserError` naming it and why when it
    cannot be (a file in its place or on its path, no permission, a read-only disk). ``private``: a new
    folder is the owner's only (0700: caches)."""
    folder = Path(folder)
    try:
        folder.mkdir(parents=True, exist_ok=True, **({"mode": 0o700} if private else {}))
    except FileExistsError:  # mkdir's answer when a file stands where a folder is wanted
        raise UserError(f"{folder}: cannot make the {what}: a file of that name is in the way") from None
    except NotADirectoryError:
        raise UserError(f"{folder}: cannot make the {what}: a part of its path is a file, not a folder") from None
    except OSError as e:
        raise UserError(f"{folder}: cannot make the {what}: {e.strerror or e}") from None
    if not folder.is_dir():
        raise UserError(f"{folder}: cannot make the {what}: a file of that name is in the way")


def write_all_atomic(files: dict, *, durable: bool = False, private: bool = False) -> None:
    """Write every file of ``files`` (path → text, bytes, or a callable that writes the file at the
    temporary path it is given) to a temporary sibling, then rename them all into place.

    ``durable``: each file is flushed to the disk before its rename (a study's chunks, which a crash must
    not leave half-written under their final names). ``private``: the files keep mode 0600 and new
    folders 0700 (caches); otherwise files get the mode the umask allows, as any other program's
    outputs. A folder that cannot be made, or a file that cannot be written, is a :class:`UserError`
    naming its path; nothing is renamed into place then."""
    import tempfile  # only a process that writes pays for the import

    staged = []
    try:
        for path, content in files.items():
            path = Path(path)
            ensure_folder(path.parent, private=private)
            try:
                fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=TEMP_SUFFIX, dir=path.parent)
            except OSError as e:
                raise UserError(f"{path}: cannot write output: {e.strerror or e}") from None
            staged.append((tmp, path))
            if callable(content):
                os.close(fd)
                content(Path(tmp))
            else:
                with os.fdopen(fd, "wb") if isinstance(content, bytes) else os.fdopen(fd, "w", encoding="utf-8", newline="") as f:
                    f.write(content)
                    if durable:
                        f.flush()
                        os.fsync(f.fileno())
        if not private:  # mkstemp makes 0600 files: give outputs the usual mode the umask allows
            umask = os.umask(0)
            os.umask(umask)
            for tmp, _ in staged:
                os.chmod(tmp, 0o666 & ~umask)
        for tmp, path in staged:
            os.replace(tmp, path)
    except BaseException:
        for tmp, _ in staged:
            if os.path.exists(tmp):
                os.unlink(tmp)
        raise


def write_atomic(path: Path, data: bytes, *, durable: bool = False, private: bool = False) -> None:
    """Write ``data`` to ``path`` whole or not at all (:func:`write_all_atomic` for one file)."""
    write_all_atomic({Path(path): data}, durable=durable, private=private)


def remove_stale_temporaries(folder: Path, older_than_s: float) -> None:
    """Remove the temporary files (:data:`TEMP_SUFFIX`) in ``folder`` last modified more than
    ``older_than_s`` seconds ago: what a writer killed mid-write left (a live write's is recent). Files
    that vanish or cannot be removed meanwhile are left."""
    import time

    now = time.time()
    for e in os.scandir(folder):
        if e.name.startswith(".") and e.name.endswith(TEMP_SUFFIX):
            try:
                if now - e.stat().st_mtime > older_than_s:
                    os.unlink(e.path)
            except OSError:
                continue
