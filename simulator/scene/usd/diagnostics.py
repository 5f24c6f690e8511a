"""pxr's own diagnostics (Tf warnings and errors) caught while a stage is opened and read.

Left alone, OpenUSD prints each Tf warning to stderr as it happens (one
``Warning: in _ReportErrors at line 3326 of stage.cpp -- ...`` line per
unresolved reference, per unopened ``.mtlx``, ...), which buries probesim's
own messages. While a stage is read they are caught instead and summarised
in the stage's one summary warning line (a count and the first message).

``Tf.DiagnosticTrap`` (OpenUSD 24.11 on) catches them at the source: every
warning, status and error posted in its scope is held and, once read,
cleared so that nothing is reposted. Errors that pxr turns into Python
exceptions (``Tf.ErrorException``) are still raised as before. With an
older ``usd-core`` without the trap, file descriptor 2 is redirected to a
temporary file around the read (C++ writes there directly, past
``sys.stderr``), pxr's lines are taken from it and any other line is
written back to stderr unchanged.
"""

from __future__ import annotations

import os
import sys
import tempfile
from types import TracebackType

from pxr import Tf

__all__ = ["PxrDiagnostics"]

# how Tf begins each diagnostic it prints (TfDiagnosticMgr's default output)
_TF_PREFIXES = ("Warning:", "Coding Error:", "Runtime Error:", "Error:", "Fatal Error:", "Status:")


class PxrDiagnostics:
    """A context manager holding pxr's diagnostics posted in its scope; :meth:`collect` takes them.

    Anything not collected when the scope ends (a read that raised) is dropped: the reader's own
    one-line error is what the user sees then.
    """

    def __init__(self) -> None:
        self._trap_cm = None
        self._trap = None
        self._saved_fd: int | None = None
        self._file = None
        self._read = 0

    def __enter__(self) -> PxrDiagnostics:
        trap = getattr(Tf, "DiagnosticTrap", None)
        if trap is not None:
            self._trap_cm = trap()
            self._trap = self._trap_cm.__enter__()
        else:  # pragma: no cover - usd-core before the trap
            sys.stderr.flush()
            self._file = tempfile.TemporaryFile(mode="w+b")
            self._saved_fd = os.dup(2)
            os.dup2(self._file.fileno(), 2)
        return self

    def collect(self) -> list[str]:
        """The messages posted since the last call, in order (errors and warnings, then statuses)."""
        if self._trap is not None:
            found = [d.commentary for d in (*self._trap.GetErrors(), *self._trap.GetWarnings(),
                                            *self._trap.GetStatuses())]
            self._trap.Clear()
            return [" ".join(str(m).split()) for m in found]
        return self._collect_fd()  # pragma: no cover

    def _collect_fd(self) -> list[str]:  # pragma: no cover - usd-core before the trap
        sys.stderr.flush()
        self._file.seek(self._read)
        text = self._file.read().decode("utf-8", "replace")
        self._read = self._file.tell()
        found, other = [], []
        for line in text.splitlines():
            if line.startswith(_TF_PREFIXES):
                found.append(line.split(" -- ", 1)[-1].strip())
            elif line.strip():
                other.append(line)
        if other:  # not pxr's: give it back to stderr as it was
            os.write(self._saved_fd, ("\n".join(other) + "\n").encode())
        return found

    def __exit__(self, exc_type: type | None, exc: BaseException | None, tb: TracebackType | None) -> None:
        if self._trap is not None:
            self._trap.Clear()
            self._trap_cm.__exit__(exc_type, exc, tb)
            return
        if self._saved_fd is not None:  # pragma: no cover
            self._collect_fd()
            os.dup2(self._saved_fd, 2)
            os.close(self._saved_fd)
            self._file.close()
