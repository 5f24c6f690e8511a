"""Files written whole or not at all (simulator.io.atomic), and output folders checked before any work.

Every file probesim writes goes to a temporary sibling and is renamed over its name: a reader sees
the old file or the whole new one, a write that fails leaves no temporary file, and files written
together are all staged before the first is renamed. An output or study folder that cannot be made
is one line naming it and why, before any tracing (it had been a traceback from the study's first
chunk, or an error after the whole trace of a run).
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest

from simulator.commands.cli import main
from simulator.errors import UserError
from simulator.io.atomic import check_folder, ensure_folder, write_all_atomic, write_atomic

ROOT = Path(__file__).resolve().parents[1]


def _mode(p: Path) -> int:
    return stat.S_IMODE(p.stat().st_mode)


def _leftovers(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name.startswith("."))


def test_a_write_replaces_the_file_whole_with_the_umask_mode(tmp_path):
    p = tmp_path / "sub" / "a.bin"
    write_atomic(p, b"first")
    write_atomic(p, b"second", durable=True)
    assert p.read_bytes() == b"second" and _leftovers(p.parent) == []
    umask = os.umask(0)
    os.umask(umask)
    assert _mode(p) == 0o666 & ~umask


def test_a_private_write_keeps_the_file_and_a_new_folder_to_the_owner(tmp_path):
    p = tmp_path / "cache" / "entry"
    write_atomic(p, b"x", private=True)
    assert _mode(p) == 0o600 and _mode(p.parent) == 0o700


def test_a_failed_write_renames_nothing_and_leaves_no_temporary_file(tmp_path):
    """Two files staged together; the second's writer fails: the first keeps its old content."""
    a, b = tmp_path / "a.csv", tmp_path / "b.png"
    a.write_text("old")

    def fails(path):
        Path(path).write_bytes(b"half")
        raise RuntimeError("the writer failed")

    with pytest.raises(RuntimeError, match="the writer failed"):
        write_all_atomic({a: "new", b: fails})
    assert a.read_text() == "old" and not b.exists() and _leftovers(tmp_path) == []


def test_text_bytes_and_writers_are_all_written(tmp_path):
    files = {tmp_path / "t.txt": "é\n", tmp_path / "b.bin": b"\x00\x01", tmp_path / "w.dat": lambda p: Path(p).write_text("w")}
    write_all_atomic(files)
    assert (tmp_path / "t.txt").read_bytes() == "é\n".encode() and (tmp_path / "b.bin").read_bytes() == b"\x00\x01"
    assert (tmp_path / "w.dat").read_text() == "w"


def test_a_folder_that_cannot_be_made_is_one_line_naming_it(tmp_path):
    (tmp_path / "file").write_text("")
    with pytest.raises(UserError, match=r"file: cannot make the output folder: a file of that name is in the way$"):
        ensure_folder(tmp_path / "file")
    with pytest.raises(UserError, match=r"file/out: cannot make the study folder: a part of its path is a file, not a folder$"):
        ensure_folder(tmp_path / "file" / "out", "study folder")
    with pytest.raises(UserError, match=r"file: cannot make the output folder: a file of that name is in the way$"):
        write_atomic(tmp_path / "file" / "x.csv", b"")


def test_a_folder_is_checked_without_being_made(tmp_path):
    """check_folder says what ensure_folder would, and makes nothing: a command checks its outputs'
    folder before any work and still writes nothing if a later mistake stops it."""
    (tmp_path / "file").write_text("")
    with pytest.raises(UserError, match=r"file: cannot make the output folder: a file of that name is in the way$"):
        check_folder(tmp_path / "file")
    with pytest.raises(UserError, match=r"file/a/b: cannot make the study folder: a part of its path is a file, not a folder$"):
        check_folder(tmp_path / "file" / "a" / "b", "study folder")
    check_folder(tmp_path / "new" / "deeper")
    check_folder(tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["file"]


def test_a_study_says_so_before_any_chunk(tmp_path, capsys):
    """``probesim study -o`` into a path through a file: exit 2, one line on stderr naming the folder,
    before any chunk is traced (``probesim run``'s twin: tests/test_cli.py)."""
    (tmp_path / "file").write_text("")
    assert main(["study", str(ROOT / "configs" / "studies" / "office_study.toml"), "-o", str(tmp_path / "file" / "out")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"probesim: error: {tmp_path / 'file' / 'out'}: cannot make the study folder: a part of its path is a file, "
                   "not a folder"]  # fmt: skip


def test_a_killed_writers_temporary_file_is_recognised_and_removed_once_stale(tmp_path):
    """Every staged file carries TEMP_SUFFIX, so the caches can clear what a writer killed mid-write
    left (remove_stale_temporaries): an old one goes, a recent one (a live write) and other files stay."""
    import time

    from simulator.io.atomic import TEMP_SUFFIX, remove_stale_temporaries

    seen = []
    write_all_atomic({tmp_path / "a.png": lambda p: (seen.append(Path(p).name), Path(p).write_bytes(b"x"))})
    assert seen[0].startswith(".a.png.") and seen[0].endswith(TEMP_SUFFIX)
    old, live = tmp_path / f".e.stage.abc{TEMP_SUFFIX}", tmp_path / f".f.stage.def{TEMP_SUFFIX}"
    for p in (old, live, tmp_path / "kept.stage", tmp_path / f"visible{TEMP_SUFFIX}"):
        p.write_bytes(b"")
    hour_ago = time.time() - 3600
    os.utime(old, (hour_ago, hour_ago))
    remove_stale_temporaries(tmp_path, 60)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(["a.png", live.name, "kept.stage", f"visible{TEMP_SUFFIX}"])
