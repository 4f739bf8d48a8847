"""OpenFOAM's ASCII files (gzipped or not, as a case writes them with ``writeCompression on``): the polyMesh of a
case as a :class:`wear.wall.mesh.Wall` of its wall patches, and a ``volScalarField``'s values on them (e.g. the
``<cloud>Q`` field of the ``particleErosion`` cloud function). Read: ``points`` (m), ``faces`` (point labels; a
boundary face's normal points out of its owner cell, i.e. out of the fluid: the wall's convention, so the
``owner`` file adds nothing to the wall and is not read), ``boundary`` (each patch's ``type``, ``nFaces``,
``startFace``). Tried with v1912 (Debian's ``openfoam`` 1912.200626); binary files are refused."""

from __future__ import annotations

import gzip
import re
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from wear.wall.mesh import Wall

__all__ = ["read_foam_text", "read_polymesh", "read_patch_field", "polymesh_folder", "foam_patches"]

_COMMENTS = re.compile(r"/\*.*?\*/|//[^\n]*", re.S)
_HEADER = re.compile(r"FoamFile\s*\{(.*?)\}", re.S)


def read_foam_text(path: str | Path) -> tuple[dict[str, str], str]:
    """The ``FoamFile`` header entries and the body (comments removed) of an OpenFOAM file ``path`` or
    ``path.gz``."""
    p = Path(path)
    if not p.exists() and Path(f"{p}.gz").exists():
        p = Path(f"{p}.gz")
    if not p.exists():
        raise ValueError(f"{p}: no such file (nor {p.name}.gz)")
    try:
        raw = gzip.decompress(p.read_bytes()) if p.suffix == ".gz" else p.read_bytes()
        text = _COMMENTS.sub(" ", raw.decode("utf-8"))
    except (OSError, UnicodeDecodeError, EOFError) as err:
        raise ValueError(f"{p} is not an OpenFOAM ASCII file ({err})") from None
    match = _HEADER.search(text)
    if match is None:
        raise ValueError(f"{p} has no FoamFile header: give an OpenFOAM file")
    header = dict(re.findall(r"(\w+)\s+([^;]*);", match.group(1)))
    if header.get("format", "ascii").strip() != "ascii":
        raise ValueError(f"{p} is written in format {header['format']}: rerun foamFormatConvert to write ascii")
    return header, text[match.end() :]


def _list_body(body: str, path: Path) -> tuple[int, str]:
    """The length and the text inside the outer parentheses of the first list ``N ( ... )`` of ``body``."""
    match = re.search(r"(\d+)\s*\(", body)
    end = body.rfind(")")
    if match is None or end < match.end():
        raise ValueError(f"{path} holds no list N ( ... ): give an OpenFOAM list file")
    return int(match.group(1)), body[match.end() : end]


def polymesh_folder(path: str | Path) -> Path:
    """The polyMesh folder of ``path``: itself, its ``polyMesh`` or its ``constant/polyMesh``."""
    p = Path(path)
    for candidate in (p, p / "polyMesh", p / "constant" / "polyMesh"):
        if (candidate / "boundary").exists():
            return candidate
    raise ValueError(f"wall={str(p)!r} holds no OpenFOAM polyMesh (boundary, points, faces)")


def foam_patches(folder: Path) -> dict[str, dict[str, str]]:
    """The patches of a polyMesh ``boundary`` file, in order: name → entries (``type``, ``nFaces``, ...)."""
    _, body = read_foam_text(folder / "boundary")
    _, inner = _list_body(body, folder / "boundary")
    return {
        name: dict(re.findall(r"(\w+)\s+([^;]*);", entries))
        for name, entries in re.findall(r"([\w.:\-]+)\s*\{([^}]*)\}", inner)
    }


def read_polymesh(path: str | Path, patches: Sequence[str] | None = None) -> Wall:
    """The wall of an OpenFOAM case: ``patches`` (names; default every patch of type ``wall``) of the polyMesh in
    ``path`` (the case, its ``constant``, or the polyMesh folder), faces in patch order then patch face order, each
    face labelled with its global mesh face label (patch face i of a patch is label ``startFace + i``); only the
    points of those faces are kept."""
    folder = polymesh_folder(path)
    entries = foam_patches(folder)
    if patches is None:
        names = [name for name, e in entries.items() if e.get("type", "").strip() == "wall"]
        if not names:
            raise ValueError(f"{folder / 'boundary'} has no patch of type wall: name the wall patches")
    else:
        names = list(patches)
        if not names:
            raise ValueError("patches=[]: name at least one patch of the wall")
        twice = next((name for name in names if names.count(name) > 1), None)
        if twice is not None:  # its faces would be counted twice: twice the area, half the depth
            raise ValueError(f"patches={names}: the patch {twice!r} is named twice: name each patch once")
        unknown = [name for name in names if name not in entries]
        if unknown:
            raise ValueError(f"patches={unknown} are not in {folder / 'boundary'}: its patches are {list(entries)}")
    labels = np.concatenate(
        [int(entries[n]["startFace"]) + np.arange(int(entries[n]["nFaces"]), dtype=np.int64) for n in names]
    )
    patch = np.concatenate([np.full(int(entries[n]["nFaces"]), i, np.int64) for i, n in enumerate(names)])
    sizes, flat = _faces(folder, labels)
    used, inverse = np.unique(flat, return_inverse=True)
    others = tuple(  # the records on these are counted, not refused as another mesh's
        (name, int(e["startFace"]), int(e["nFaces"]))
        for name, e in entries.items()
        if name not in names and "startFace" in e and "nFaces" in e
    )
    return Wall(
        points=_points(folder)[used],
        face_points=inverse.reshape(-1),
        face_offsets=np.concatenate([[0], np.cumsum(sizes)]),
        patch=patch,
        patch_names=tuple(names),
        labels=labels,
        other_patches=others,
    )


def _points(folder: Path) -> np.ndarray:
    _, body = read_foam_text(folder / "points")
    n, inner = _list_body(body, folder / "points")
    values = np.array(inner.replace("(", " ").replace(")", " ").split(), dtype=float)
    if values.size != 3 * n:
        raise ValueError(f"{folder / 'points'}: {values.size} numbers for {n} points")
    values = values.reshape(n, 3)
    bad = np.flatnonzero(~np.isfinite(values).all(axis=1))
    if len(bad):  # named here, with the file: the wall's own check knows no file
        raise ValueError(
            f"{folder / 'points'}, point {bad[0]}: ({' '.join(f'{v:.6g}' for v in values[bad[0]])}) is not a finite "
            "position (m): give every point of the mesh as numbers"
        )
    return values


def _faces(folder: Path, labels: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Sizes and flat point labels of the mesh faces ``labels`` (faceList: ``k(p0 ... pk-1)`` per face)."""
    _, body = read_foam_text(folder / "faces")
    n, inner = _list_body(body, folder / "faces")
    tokens = np.array(inner.replace("(", " ").replace(")", " ").split(), dtype=np.int64)
    starts = np.empty(n, np.int64)
    i = 0
    for f in range(n):  # each face's size precedes its points: the starts follow one another
        starts[f] = i
        i += tokens[i] + 1
    if i != len(tokens):
        raise ValueError(f"{folder / 'faces'}: the face list does not hold {n} faces")
    if labels.max() >= n:
        raise ValueError(f"{folder / 'boundary'} names face {labels.max()} but {folder / 'faces'} has {n} faces")
    sizes = tokens[starts[labels]]
    first = np.repeat(starts[labels] + 1, sizes)
    offset = np.arange(sizes.sum()) - np.repeat(np.cumsum(sizes) - sizes, sizes)
    return sizes, tokens[first + offset]


def read_patch_field(path: str | Path, wall: Wall) -> np.ndarray:
    """The boundary values of a ``volScalarField`` file ``path`` on the faces of ``wall`` (as
    :func:`read_polymesh` built it), in wall face order: each patch's ``value`` (``uniform X`` or ``nonuniform
    List<scalar> N (...)``)."""
    p = Path(path)
    header, body = read_foam_text(p)
    if header.get("class", "").strip() != "volScalarField":
        raise ValueError(f"{p} is a {header.get('class')}, not a volScalarField")
    start = body.find("boundaryField")
    if start < 0:
        raise ValueError(f"{p} has no boundaryField")
    out = np.empty(len(wall))
    for i, name in enumerate(wall.patch_names):
        match = re.search(rf"\b{re.escape(name)}\s*\{{(.*?)\}}", body[start:], re.S)
        if match is None:
            raise ValueError(f"{p} has no patch {name!r} in its boundaryField")
        faces = wall.patch == i
        value = re.search(r"value\s+(uniform\s+([^;\s]+)|nonuniform\s+List<scalar>\s*(\d+)\s*\(([^)]*)\))", match[1])
        if value is None:
            raise ValueError(f"{p}: patch {name!r} has no scalar value")
        if value[2] is not None:
            out[faces] = float(value[2])
        else:
            values = np.array(value[4].split(), dtype=float)
            if len(values) != faces.sum():
                raise ValueError(f"{p}: patch {name!r} has {len(values)} values for {faces.sum()} faces")
            out[faces] = values
    return out
