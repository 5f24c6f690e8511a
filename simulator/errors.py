"""User-facing errors.

A :class:`UserError` is a mistake in the user's input (config, stage, flags).
The CLI prints its message on one line and exits with status 2; no traceback,
no output file.
"""

__all__ = ["UserError"]


class UserError(Exception):
    """A problem with the user's input, reported as one line, exit status 2.

    The message must name the file, prim or key at fault and say what is wrong,
    e.g. ``"configs/a.toml: sensor[2].normal: zero-length vector"``.
    """

    exit_code = 2
