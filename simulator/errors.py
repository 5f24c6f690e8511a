"""User-facing errors.

A :class:`UserError` is a mistake in the user's input (config, stage, flags).
The CLI prints its message on one line and exits with status 2; no traceback,
no output file.
"""

from pathlib import Path

__all__ = ["UserError", "require_file"]


class UserError(Exception):
    """A problem with the user's input, reported as one line, exit status 2.

    The message must name the file, prim or key at fault and say what is wrong,
    e.g. ``"configs/a.toml: sensor[2].normal: zero-length vector"``.
    """

    exit_code = 2


def require_file(path) -> Path:
    """``path`` as a Path, or a UserError if it is missing or not a regular file."""
    p = Path(path)
    if not p.exists():
        raise UserError(f"{path}: no such file")
    if not p.is_file():
        raise UserError(f"{path}: not a file")
    return p
