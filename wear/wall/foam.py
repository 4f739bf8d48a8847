"""OpenFOAM's polyMesh and field files as a case writes them: ``writeFormat ascii`` or ``binary`` (the header's
``arch``, e.g. ``"LSB;label=32;scalar=64"``, gives the byte order and the sizes of labels and scalars), each file
plain or gzipped (``writeCompression on`` writes ``<file>.gz``; v1912 writes binary files uncompressed whatever it is
told). Read: the polyMesh of a case as a :class:`wear.wall.mesh.Wall` of its wall patches, and a
``volScalarField``'s values on them (e.g. the ``<cloud>Q`` field (m³) of the ``particleErosion`` cloud function).
From the polyMesh: ``points`` (m), ``faces`` (point labels: a ``faceList``, or the ``faceCompactList`` of a binary
mesh; a boundary face's normal points out of its owner cell, i.e. out of the fluid: the wall's convention, so the
``owner`` file adds nothing to the wall and is not read), ``boundary`` (each patch's ``type``, ``nFaces``,
``startFace``). A decomposed case (``processor*`` folders without the mesh or field asked for) is refused, naming
the OpenFOAM command that reconstructs it. Tried with v1912 (Debian's ``openfoam`` 1912.200626): its own ascii,
compressed and binary (``foamFormatConvert``) writes of one mesh and field read the same.

The reader is this module's, for both formats: a file's dictionaries are scanned token by token, its lists of
numbers read in one piece (``numpy.frombuffer`` when binary, one split when ascii). foamlib 1.7.10 was measured in
its place: it was 2 to 4 times slower on ASCII quad faces, and its time grew as the square of the number of faces
in an ASCII face list holding one face of 5 points or more (as snappyHexMesh meshes do: 1000 faces took 4 min).
"""

from __future__ import annotations

import gzip
import re
import zlib
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from wear.wall.mesh import Wall

__all__ = ["read_polymesh", "read_patch_field", "polymesh_folder", "foam_patches", "DecomposedCaseError"]

_HEADER = re.compile(rb"FoamFile\s*\{(.*?)\}", re.S)
_COMMENTS = re.compile(rb"/\*.*?\*/|//[^\n]*", re.S)
_BLANK = re.compile(rb"(?:\s+|//[^\n]*|/\*.*?\*/)*", re.S)
# a quoted string, a brace, parenthesis or ';', or a word (a '/' that opens no comment is part of a word)
_TOKEN = re.compile(rb'"(?:[^"\\]|\\.)*"|[{}();]|(?:[^\s{}();"/]|/(?![/*]))+')
_COUNT = re.compile(rb"\d+")
_PARENTHESES = re.compile(rb"[()]")
_PROCESSOR = re.compile(r"processor\d+|processors\d+(?:_\d+-\d+)?")
#: The numbers per item of the lists read, by OpenFOAM's type name.
_WIDTH = {"scalar": 1, "vector": 3, "sphericalTensor": 1, "symmTensor": 6, "tensor": 9, "label": 1}


class DecomposedCaseError(ValueError):
    """A decomposed OpenFOAM case (its mesh only in ``processor*`` folders): the message names the command that
    reconstructs it."""


@dataclass(frozen=True)
class _File:
    """An OpenFOAM file read whole (gunzipped): its ``path``, its ``header`` entries, its bytes ``data`` and where
    the body ``start``s (past the header), whether it is ``binary``, and the dtypes of its labels and scalars."""

    path: Path
    header: dict[str, str]
    data: bytes
    start: int
    binary: bool
    label: np.dtype
    scalar: np.dtype


def _existing(path: Path) -> Path | None:
    """``path``, or else ``path.gz`` (a case written with ``writeCompression on``), if either exists."""
    if path.exists():
        return path
    zipped = path.with_name(f"{path.name}.gz")
    return zipped if zipped.exists() else None


def _open(path: Path) -> _File:
    p = _existing(path)
    if p is None:
        raise ValueError(f"{path}: no such file (nor {path.name}.gz): give the file of the OpenFOAM case")
    try:
        data = gzip.decompress(p.read_bytes()) if p.suffix == ".gz" else p.read_bytes()
    except (OSError, EOFError, zlib.error) as err:  # gzip.BadGzipFile is an OSError
        raise ValueError(f"{p} cannot be read ({err}): give the file as OpenFOAM wrote it") from None
    match = _HEADER.search(data)
    if match is None:
        raise ValueError(f"{p} has no FoamFile header: give an OpenFOAM file")
    text = _COMMENTS.sub(b" ", match[1]).decode("latin-1")
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
    return _File(
        path=p,
        header=header,
        data=data,
        start=match.end(),
        binary=form == "binary",
        label=np.dtype(f"{order}i{int(label) // 8}"),
        scalar=np.dtype(f"{order}f{int(scalar) // 8}"),
    )


def _block(f: _File, pos: int, width: int | None, dtype: np.dtype, whole: bool = False) -> tuple[int, np.ndarray, int]:
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
            text = _COMMENTS.sub(b" ", text)
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


def _processor_folders(case: Path) -> list[Path]:
    """The ``processor<N>`` (or collated ``processors<N>``) folders of a decomposed ``case``, by name."""
    if not case.is_dir():
        return []
    return sorted(p for p in case.iterdir() if p.is_dir() and _PROCESSOR.fullmatch(p.name))


def polymesh_folder(path: str | Path) -> Path:
    """The polyMesh folder of ``path``: itself, its ``polyMesh`` or its ``constant/polyMesh`` (a ``boundary`` or
    ``boundary.gz`` file in it). A decomposed case (``processor*`` folders, no polyMesh) raises
    :class:`DecomposedCaseError`."""
    p = Path(path)
    for candidate in (p, p / "polyMesh", p / "constant" / "polyMesh"):
        if _existing(candidate / "boundary") is not None:
            return candidate
    case = p.parent if p.name == "constant" else p
    parts = _processor_folders(case)
    if parts:
        raise DecomposedCaseError(
            f"wall={str(p)!r} is a decomposed OpenFOAM case ({len(parts)} processor folders, no constant/polyMesh): "
            f"reconstruct its mesh first (cd {case} && reconstructParMesh -constant)"
        )
    raise ValueError(f"wall={str(p)!r} holds no OpenFOAM polyMesh (boundary, points, faces; plain or .gz)")


def foam_patches(folder: Path) -> dict[str, dict[str, str]]:
    """The patches of a polyMesh ``boundary`` file, in order: name → entries (``type``, ``nFaces``, ...)."""
    f = _open(Path(folder) / "boundary")
    # the boundary file is a dictionary list, text in either format
    body = _COMMENTS.sub(b" ", f.data[f.start :]).decode("latin-1")
    match = re.search(r"(\d+)\s*\(", body)
    end = body.rfind(")")
    if match is None or end < match.end():
        raise ValueError(f"{f.path} holds no list N(...) of patches: give the polyMesh's boundary file")
    return {
        name: {k: v.strip() for k, v in re.findall(r"(\w+)\s+([^;]*);", entries)}
        for name, entries in re.findall(r"([\w.:\-]+)\s*\{([^}]*)\}", body[match.end() : end])
    }


def read_polymesh(path: str | Path, patches: Sequence[str] | None = None) -> Wall:
    """The wall of an OpenFOAM case: ``patches`` (names; default every patch of type ``wall``) of the polyMesh in
    ``path`` (the case, its ``constant``, or the polyMesh folder), faces in patch order then patch face order, each
    face labelled with its global mesh face label (patch face i of a patch is label ``startFace + i``); only the
    points of those faces are kept."""
    folder = polymesh_folder(path)
    entries = foam_patches(folder)
    boundary = _existing(folder / "boundary")
    if patches is None:
        names = [name for name, e in entries.items() if e.get("type") == "wall"]
        if not names:
            raise ValueError(f"{boundary} has no patch of type wall: name the wall patches")
    else:
        names = list(patches)
        if not names:
            raise ValueError("patches=[]: name at least one patch of the wall")
        twice = next((name for name in names if names.count(name) > 1), None)
        if twice is not None:  # its faces would be counted twice: twice the area, half the depth
            raise ValueError(f"patches={names}: the patch {twice!r} is named twice: name each patch once")
        unknown = [name for name in names if name not in entries]
        if unknown:
            raise ValueError(f"patches={unknown} are not in {boundary}: its patches are {list(entries)}")
    for name in names:
        if not all(entries[name].get(k, "").isdigit() for k in ("startFace", "nFaces")):
            raise ValueError(f"{boundary}: patch {name!r} has no startFace and nFaces: give the polyMesh's boundary")
    labels = np.concatenate(
        [int(entries[n]["startFace"]) + np.arange(int(entries[n]["nFaces"]), dtype=np.int64) for n in names]
    )
    patch = np.concatenate([np.full(int(entries[n]["nFaces"]), i, np.int64) for i, n in enumerate(names)])
    sizes, flat = _faces(folder, labels, boundary)
    used, inverse = np.unique(flat, return_inverse=True)
    others = tuple(  # the records on these are counted, not refused as another mesh's
        (name, int(e["startFace"]), int(e["nFaces"]))
        for name, e in entries.items()
        if name not in names and e.get("startFace", "").isdigit() and e.get("nFaces", "").isdigit()
    )
    points = _points(folder)
    if len(used) and (used[0] < 0 or used[-1] >= len(points)):
        bad = used[0] if used[0] < 0 else used[-1]
        raise ValueError(f"{folder}: a face names point {bad} of {len(points)} points: give the whole polyMesh")
    return Wall(
        points=points[used],
        face_points=inverse.reshape(-1),
        face_offsets=np.concatenate([[0], np.cumsum(sizes)]),
        patch=patch,
        patch_names=tuple(names),
        labels=labels,
        other_patches=others,
    )


def _points(folder: Path) -> np.ndarray:
    f = _open(folder / "points")
    n, values, _ = _block(f, f.start, 3, f.scalar, whole=True)
    values = values.reshape(n, 3)
    bad = np.flatnonzero(~np.isfinite(values).all(axis=1))
    if len(bad):  # named here, with the file: the wall's own check knows no file
        raise ValueError(
            f"{f.path}, point {bad[0]}: ({' '.join(f'{v:.6g}' for v in values[bad[0]])}) is not a finite "
            "position (m): give every point of the mesh as numbers"
        )
    return values


def _faces(folder: Path, labels: np.ndarray, boundary: Path | None) -> tuple[np.ndarray, np.ndarray]:
    """Sizes and flat point labels of the mesh faces ``labels``: a ``faceList`` (``k(p0 ... pk-1)`` per face) or a
    ``faceCompactList`` (the N + 1 offsets of the faces in the flat list of their points, then that list)."""
    f = _open(folder / "faces")
    if f.header.get("class") == "faceCompactList":
        _, offsets, pos = _block(f, f.start, 1, f.label)
        _, points, _ = _block(f, pos, 1, f.label)
        n = len(offsets) - 1
        if n < 0 or offsets[0] != 0 or offsets[-1] != len(points) or np.any(np.diff(offsets) < 0):
            raise ValueError(f"{f.path}: the offsets of the faceCompactList do not index its point list")
        starts, counts = offsets[:-1], np.diff(offsets)
    else:
        n, tokens, _ = _block(f, f.start, None, f.label, whole=True)
        k = tokens[0] if len(tokens) else 0
        if k > 0 and len(tokens) == n * (k + 1) and np.all(tokens[:: k + 1] == k):  # all of k points (hex mesh)
            starts = np.arange(n, dtype=np.int64) * (k + 1) + 1
        else:
            starts = np.empty(n, np.int64)
            i = 0
            for face in range(n):  # each face's size precedes its points: the starts follow one another
                if i >= len(tokens):
                    raise ValueError(f"{f.path}: the face list ends at face {face} of {n}: give the whole file")
                starts[face] = i + 1
                i += tokens[i] + 1
            if i != len(tokens):
                raise ValueError(f"{f.path}: the face list does not hold {n} faces")
        counts, points = tokens[starts - 1], tokens
        if np.any(counts < 0):
            raise ValueError(f"{f.path}: face {np.argmax(counts < 0)} has a negative number of points")
    if len(labels) and labels.max() >= n:
        raise ValueError(f"{boundary} names face {labels.max()} but {f.path} has {n} faces")
    sizes = counts[labels]
    first = np.repeat(starts[labels], sizes)
    offset = np.arange(sizes.sum()) - np.repeat(np.cumsum(sizes) - sizes, sizes)
    return sizes, points[first + offset]


class _Dictionary:
    """The entries of an OpenFOAM dictionary file, scanned token by token from its body: keyword → a sub-dictionary
    (a dict) or the entry's tokens (bytes; a ``List<T>`` of numbers as one array, binary or ascii)."""

    def __init__(self, f: _File) -> None:
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
                _, array, self.pos = _block(self.file, self.pos - len(word), _WIDTH[kind], dtype)
                values.append(array)
            else:
                values.append(word)
        return values


def read_patch_field(path: str | Path, wall: Wall) -> np.ndarray:
    """The boundary values of a ``volScalarField`` file ``path`` (or ``path.gz``) on the faces of ``wall`` (as
    :func:`read_polymesh` built it), in wall face order: each patch's ``value`` (``uniform X`` or ``nonuniform
    List<scalar> N(...)``, ascii or binary)."""
    p = Path(path)
    if _existing(p) is None:
        raise _missing_field(p)
    f = _open(p)
    if f.header.get("class") != "volScalarField":
        raise ValueError(f"{f.path} is a {f.header.get('class')}, not a volScalarField")
    boundary = _Dictionary(f).dictionary().get("boundaryField")
    if not isinstance(boundary, dict):
        raise ValueError(f"{f.path} has no boundaryField")
    out = np.empty(len(wall))
    for i, name in enumerate(wall.patch_names):
        entries = boundary.get(name)
        if not isinstance(entries, dict):
            raise ValueError(f"{f.path} has no patch {name!r} in its boundaryField")
        faces = wall.patch == i
        value = entries.get("value")
        if isinstance(value, list) and len(value) == 2 and value[0] == b"uniform" and isinstance(value[1], bytes):
            try:
                out[faces] = float(value[1])
            except ValueError:
                raise ValueError(
                    f"{f.path}: patch {name!r} has value uniform {value[1].decode()}: not a scalar"
                ) from None
        elif isinstance(value, list) and len(value) == 3 and isinstance(value[2], np.ndarray) and value[2].ndim == 1:
            if len(value[2]) != faces.sum():
                raise ValueError(f"{f.path}: patch {name!r} has {len(value[2])} values for {faces.sum()} faces")
            out[faces] = value[2]
        else:
            raise ValueError(f"{f.path}: patch {name!r} has no scalar value")
    return out


def _missing_field(p: Path) -> ValueError:
    """The refusal of a field file that does not exist: a decomposed case holds it in its processor folders."""
    name = p.name.removesuffix(".gz")
    time, case = p.parent.name, p.parent.parent
    parts = _processor_folders(case)
    if parts and _existing(parts[0] / time / name) is not None:
        mesh = "" if _existing(case / "constant" / "polyMesh" / "boundary") else "reconstructParMesh -constant && "
        return ValueError(
            f"{p}: no such file, but the decomposed case {case} holds it in {parts[0].name}/{time}: reconstruct it "
            f"first (cd {case} && {mesh}reconstructPar -time {time})"
        )
    return ValueError(f"{p}: no such file (nor {name}.gz): give a field file of a time folder of the case")
