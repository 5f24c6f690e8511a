"""The source tree carries no unresolved merge: no conflict markers in any tracked text file."""

import re
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MARKER = re.compile(r"^(<{7} |>{7} |={7}$)", re.MULTILINE)


def _tracked_text_files():
    try:
        out = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True).stdout
        names = out.split()
    except (OSError, subprocess.CalledProcessError):
        names = [str(p.relative_to(ROOT)) for p in ROOT.rglob("*") if p.is_file() and ".git" not in p.parts]
    for n in names:
        if n.endswith((".py", ".md", ".toml", ".usda", ".csv", ".txt", ".cfg", ".in", ".sh")) or n.startswith(".ci/"):
            yield ROOT / n


def test_no_file_holds_a_merge_conflict_marker():
    """A line starting '<<<<<<< ', '>>>>>>> ' or exactly '=======' is a merge left half done
    (one such block sat in docs/DESIGN.md once); none may be committed."""
    bad = []
    for p in _tracked_text_files():
        if not p.is_file():
            continue
        text = p.read_text(encoding="utf-8", errors="replace")
        for m in MARKER.finditer(text):
            bad.append(f"{p.relative_to(ROOT)}:{text.count(chr(10), 0, m.start()) + 1}")
    assert not bad, "conflict markers at " + ", ".join(bad)
