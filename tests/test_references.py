"""Every citation of the project's own references names a section that exists.

Code, tests, configs, stages and docs cite ``docs/REFERENCES.md §<section>``
(or a list, ``docs/REFERENCES.md §A, §B and §C``). The sections are the
file's ``##`` headings, read here, so sections added later are picked up
without touching this test. A section name is written on one line and ends
at a line end or at one of ``) , ; " ] ` §``, ``: ``, ``. `` or `` — `` (a
final ``.`` is dropped).
"""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
REFERENCES = ROOT / "docs" / "REFERENCES.md"

#: where citations may be, and the files read there
_SCANNED = ("simulator", "tests", "configs", "stages", "docs")
_SUFFIXES = {".py", ".toml", ".usda", ".md", ".txt"}
_TOP_FILES = ("README.md", "setup.py", "pyproject.toml")

_CITE = "docs/REFERENCES.md"
#: between the file name (or a previous section) and the next "§": blanks,
#: comment markers, list separators
_GAP = re.compile(r"(?:\s|#|,|;|\band\b|\bor\b)*§")
_NAME = re.compile(r"[^\n),;\"\]`§]*")
_NAME_ENDS = (": ", ". ", " — ")
#: the references themselves, and this test (its examples are not citations)
_SELF = (REFERENCES, Path(__file__).resolve())


def sections() -> set[str]:
    """The ``##`` (and deeper) headings of docs/REFERENCES.md."""
    text = REFERENCES.read_text(encoding="utf-8")
    return {m.group(1).strip() for m in re.finditer(r"^#{2,6}\s+(.+?)\s*#*\s*$", text, re.MULTILINE)}


def _files():
    for top in _TOP_FILES:
        if (ROOT / top).is_file():
            yield ROOT / top
    for folder in _SCANNED:
        for p in sorted((ROOT / folder).rglob("*")):
            if p.suffix in _SUFFIXES and p.is_file() and "__pycache__" not in p.parts and p not in _SELF:
                yield p


def _section_name(text: str, start: int) -> str:
    name = _NAME.match(text, start).group(0)
    for end in _NAME_ENDS:
        name = name.split(end, 1)[0]
    name = name.strip()
    for tail in (" and", " or"):
        if name.endswith(tail):
            name = name[: -len(tail)].rstrip()
    return name.rstrip(".").rstrip()


def citations(text: str) -> list[str]:
    """Section names cited in ``text`` (placeholders such as ``<section>`` skipped)."""
    found = []
    for m in re.finditer(re.escape(_CITE), text):
        pos = m.end()
        while (gap := _GAP.match(text, pos)) is not None:
            name = _section_name(text, gap.end())
            if not name.startswith("<"):
                found.append(name)
            pos = gap.end() + len(_NAME.match(text, gap.end()).group(0))
    return found


def test_the_parser_reads_citations_as_written():
    """Single, wrapped, listed and placeholder citations, with their terminators."""
    text = (
        "law, docs/REFERENCES.md §Point source). Patch\n"
        "(Howell; docs/REFERENCES.md\n    §Uniform sphere). x\n"
        "# (docs/REFERENCES.md §CIE 171:2006 case 5.2); published\n"
        "see docs/REFERENCES.md §Furnace, §Integrating sphere\nand §CIE 171:2006 case 5.8):\n"
        ".. [1] docs/REFERENCES.md §Photometry.\n"
        "(docs/REFERENCES.md §Integrating sphere: Φ/(4πR²)\n"
        "docs/REFERENCES.md §Luminance of a colour. The weights\n"
        "cite it as `docs/REFERENCES.md §<section name>`; the file docs/REFERENCES.md itself.\n"
    )
    assert citations(text) == [
        "Point source", "Uniform sphere", "CIE 171:2006 case 5.2", "Furnace", "Integrating sphere",
        "CIE 171:2006 case 5.8", "Photometry", "Integrating sphere", "Luminance of a colour",
    ]  # fmt: skip


def test_every_cited_section_exists():
    """Walk the project's text files; each ``docs/REFERENCES.md §X`` names a
    heading of docs/REFERENCES.md, and every mention of the file outside
    markdown uses its path from the project root (no bare ``REFERENCES.md``)."""
    known = sections()
    assert len(known) >= 10
    missing, bare, count = [], [], 0
    for path in _files():
        text = path.read_text(encoding="utf-8", errors="replace")
        rel = path.relative_to(ROOT)
        for name in citations(text):
            count += 1
            if name not in known:
                missing.append(f"{rel}: §{name}")
        if path.suffix == ".md":
            continue  # markdown links are relative to their file: [REFERENCES.md](REFERENCES.md)
        for m in re.finditer(r"REFERENCES\.md", text):
            if text[max(0, m.start() - 5) : m.start()] != "docs/":
                bare.append(f"{rel}:{text.count(chr(10), 0, m.start()) + 1}")
    assert count >= 30, f"only {count} citations found: is the parser still reading them?"
    assert not missing, "cited sections missing from docs/REFERENCES.md:\n" + "\n".join(missing)
    assert not bare, "REFERENCES.md named without its docs/ path at:\n" + "\n".join(bare)
