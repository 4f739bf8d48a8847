"""OpenFOAM's files read whole, in either format: ``writeFormat ascii`` or ``binary`` (the header's ``arch``, e.g.
``"LSB;label=32;scalar=64"``, gives the byte order and the sizes of labels and scalars), each file plain or gzipped
(``writeCompression on`` writes ``<file>.gz``). A file's header is read into a :class:`FoamFile`, its lists of numbers
(:func:`read_list`) in one piece (``numpy.frombuffer`` when binary, one split when ascii), and its dictionaries
(:class:`FoamDictionary`) token by token; what the files mean (the polyMesh, the fields) is :mod:`wear.wall.foam`'s.

The reader is this module's, for both formats. foamlib 1.7.10 was measured in its place: it was 2 to 4 times slower
on ASCII quad faces, and its time grew as the square of the number of faces in an ASCII face list holding one face of
5 points or more (as snappyHexMesh meshes do: 1000 faces took 4 min).
"""

from __future__ import annotations

import gzip
import re
import zlib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

__all__ = ["COMMENTS", "FoamDictionary", "FoamFile", "existing_file", "open_foam_file", "read_list"]

_HEADER = re.compile(rb"FoamFile\s*\{(.*?)\}", re.S)
#: An OpenFOAM comment, ``/* ... */`` or ``// ...`` (bytes).
COMMENTS = re.compile(rb"/\*.*?\*/|//[^\n]*", re.S)
_BLANK = re.compile(rb"(?:\s+|//[^\n]*|/\*.*?\*/)*", re.S)
# a quoted string, a brace, parenthesis or ';', or a word (a '/' that opens no comment is part of a word)
_TOKEN = re.compile(rb'"(?:[^"\\]|\\.)*"|[{}();]|(?:[^\s{}();"/]|/(?![/*]))+')
_COUNT = re.compile(rb"\d+")
_PARENTHESES = re.compile(rb"[()]")
#: The numbers per item of the lists read, by OpenFOAM's type name.
_WIDTH = {"scalar": 1, "vector": 3, "sphericalTensor": 1, "symmTensor": 6, "tensor": 9, "label": 1}


@dataclass(frozen=True)
class FoamFile:
    """An OpenFOAM file read whole (gunzipped): its ``path``, its ``header`` entries, its bytes ``data`` and where
    the body ``start``s (past the header), whether it is ``binary``, and the dtypes of its labels and scalars."""

    path: Path
    header: dict[str, str]
    data: bytes
    start: int
    binary: bool
    label: np.dtype
    scalar: np.dtype


def existing_file(path: Path) -> Path | None:
    """``path``, or else ``path.gz`` (a case written with ``writeCompression on``), if either exists."""
    if path.exists():
        return path
    zipped = path.with_name(f"{path.name}.gz")
    return zipped if zipped.exists() else None


def open_foam_file(path: Path) -> FoamFile:
    """The OpenFOAM file ``path`` (or ``path.gz``) read whole: its header entries, its bytes and where its body
    starts, its format and the dtypes of its binary labels and scalars; a one-line ``ValueError`` when it cannot be."""
    p = existing_file(path)
    if p is None:
        raise ValueError(f"{path}: no such file (nor {path.name}.gz): give the file of the OpenFOAM case")
    try:
        data = gzip.decompress(p.read_bytes()) if p.suffix == ".gz" else p.read_bytes()
    except (OSError, EOFError, zlib.error) as err:  # gzip.BadGzipFile is an OSError
        raise ValueError(f"{p} cannot be read ({err}): give the file as OpenFOAM wrote it") from None
    match = _HEADER.search(data)
    if match is None:
        raise ValueError(f"{p} has no FoamFile header: give an OpenFOAM file")
    text = COMMENTS.sub(b" ", match[1]).decode("latin-1")
    header = {k: v.strip().strip('"') for k, v in re.findall(r'(\w+)\s+("[^"]*"|[^;]*);', text)}  # arch: "LSB;..."
    form = header.get("format", "ascii")
    if form not in ("ascii", "binary"):
        raise ValueError(f"{p} is written in format {form}: rerun foamFormatConvert with writeFormat ascii or binary")
    arch = header.get("arch", "LSB;label=32;scalar=64")  # OpenFOAM's default build, assumed when not written
    sizes = dict(re.findall(r"(label|scalar)\s*=\s*(\d+)", arch))
    label, scalar = sizes.get("label", "32"), sizes.get("scalar", "64")
    # an ascii file's numbers are text: its arch says nothing about them
    if form == "binary" and (label not in ("32", "64") or scalar not in ("32", "64")):
        raise ValueError(f"{p}: arch {arch!r}: only 32- and 64-bit labels and scalars are read; write it as ascii")
    order = ">" if "MSB" in arch else "<"
    return FoamFile(
        path=p,
        header=header,
        data=data,
        start=match.end(),
        binary=form == "binary",
        label=np.dtype(f"{order}i{int(label) // 8}"),
        scalar=np.dtype(f"{order}f{int(scalar) // 8}"),
    )


def read_list(
    f: FoamFile, pos: int, width: int | None, dtype: np.dtype, whole: bool = False
) -> tuple[int, np.ndarray, int]:
    """The count N and the values (flat) of the list ``N(...)`` or ``N{value}`` (N times one item) at byte ``pos``
    of ``f``, and the byte past it. ``width``: the numbers per item (None: any number, ascii only, e.g. a face list's
    ``k(p0 ... pk-1)``); ``dtype``: the binary items' numbers; ``whole``: the list is the file's last (its end is
    the file's last parenthesis: no counting of the nested ones of an ascii vector list)."""
    data = f.data
    pos = _BLANK.match(data, pos).end()
    count = _COUNT.match(data, pos)
    if count is None:
        raise ValueError(f"{f.path}: no list N(...) at byte {pos}: give the file as OpenFOAM wrote it")
    n = int(count[0])
    pos = _BLANK.match(data, count.end()).end()
    opening = data[pos : pos + 1]
    if opening not in (b"(", b"{"):
        raise ValueError(f"{f.path}: the list of {n} at byte {pos} does not open with ( or {{: give an OpenFOAM file")
    closing = b")" if opening == b"(" else b"}"
    items = n if opening == b"(" else 1
    kind = "binary" if f.binary else "ascii"
    if f.binary:
        if width is None:  # an old OpenFOAM's binary faceList: a list of lists, not read
            raise ValueError(f"{f.path}: a binary {f.header.get('class')}: rerun foamFormatConvert to write it ascii")
        end = pos + 1 + items * width * dtype.itemsize
        if data[end : end + 1] != closing:
            raise ValueError(
                f"{f.path}: the binary list of {n} does not end after its {n * width} numbers of {dtype.itemsize} "
                f"bytes (arch {f.header.get('arch', 'not given')}): give the whole file as OpenFOAM wrote it"
            )
        values = np.frombuffer(data, dtype, items * width, pos + 1)
    else:
        if whole:
            end = data.rfind(closing)
        elif width == 1 or closing == b"}":
            end = data.find(closing, pos + 1)
        else:
            end = _closing(data, pos)
        if end < pos:
            raise ValueError(f"{f.path}: the list of {n} at byte {pos} is not closed: give the whole file")
        text = data[pos + 1 : end]
        if b"/" in text:  # numbers hold no '/': only a comment does
            text = COMMENTS.sub(b" ", text)
        try:
            words = text.replace(b"(", b" ").replace(b")", b" ").split()
            values = np.array(words, dtype=np.int64 if dtype.kind == "i" else float)
        except ValueError as err:
            raise ValueError(
                f"{f.path}: the list of {n} at byte {pos} holds a word that is not a number ({err})"
            ) from None
    if width is not None and values.size != items * width:
        raise ValueError(
            f"{f.path}: the {kind} list of {n} at byte {pos} holds {values.size} numbers, not {items * width}"
        )
    values = values.astype(np.int64 if dtype.kind == "i" else float)
    if opening == b"{":
        values = np.tile(values, n)
    return n, values, end + 1


def _closing(data: bytes, pos: int) -> int:
    """The byte of the parenthesis that closes the one at ``pos`` (an ascii list of vectors or tensors)."""
    depth = 0
    for match in _PARENTHESES.finditer(data, pos):
        depth += 1 if match[0] == b"(" else -1
        if depth == 0:
            return match.start()
    return -1


class FoamDictionary:
    """The entries of an OpenFOAM dictionary file, scanned token by token from its body: keyword → a sub-dictionary
    (a dict) or the entry's tokens (bytes; a ``List<T>`` of numbers as one array, binary or ascii)."""

    def __init__(self, f: FoamFile) -> None:
        self.file = f
        self.pos = f.start

    def token(self) -> bytes | None:
        self.pos = _BLANK.match(self.file.data, self.pos).end()
        match = _TOKEN.match(self.file.data, self.pos)
        if match is None:
            return None
        self.pos = match.end()
        return match[0]

    def dictionary(self, closed: bool = False) -> dict[str, object]:
        """The entries up to the closing brace (``closed``) or the end of the file."""
        out: dict[str, object] = {}
        while (key := self.token()) not in (None, b"}"):
            if key == b";":
                continue
            name = key.decode("latin-1").strip('"')
            if name.startswith("#"):  # a directive (#include "file", #inputMode merge): one word, no ';'
                self.token()
                continue
            out[name] = self.entry()
        if (key is None) == closed:
            raise ValueError(
                f"{self.file.path}: unbalanced braces at byte {self.pos}: give the file as OpenFOAM wrote it"
            )
        return out

    def entry(self) -> dict[str, object] | list[bytes | np.ndarray]:
        values: list[bytes | np.ndarray] = []
        while (word := self.token()) != b";":
            if word is None or word == b"}":
                raise ValueError(f"{self.file.path}: an entry has no ';' before byte {self.pos}: give an OpenFOAM file")
            if word == b"{" and not values:
                return self.dictionary(closed=True)
            last = values[-1] if values else b""
            kind = last[5:-1].decode("latin-1") if isinstance(last, bytes) and last.startswith(b"List<") else ""
            if word.isdigit() and kind in _WIDTH:  # N(...) after List<T>: the list, read in one piece
                dtype = self.file.label if kind == "label" else self.file.scalar
                _, array, self.pos = read_list(self.file, self.pos - len(word), _WIDTH[kind], dtype)
                values.append(array)
            else:
                values.append(word)
        return values
