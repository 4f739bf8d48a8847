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

The files are read, in either format, by :mod:`wear.wall.foam_file`; this module knows the polyMesh and the fields.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from wear.wall.foam_file import COMMENTS, FoamDictionary, existing_file, open_foam_file, read_list
from wear.wall.mesh import Wall

__all__ = ["read_polymesh", "read_patch_field", "polymesh_folder", "foam_patches", "DecomposedCaseError"]

_PROCESSOR = re.compile(r"processor\d+|processors\d+(?:_\d+-\d+)?")


class DecomposedCaseError(ValueError):
    """A decomposed OpenFOAM case (its mesh only in ``processor*`` folders): the message names the command that
    reconstructs it."""


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
        if existing_file(candidate / "boundary") is not None:
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
    f = open_foam_file(Path(folder) / "boundary")
    # the boundary file is a dictionary list, text in either format
    body = COMMENTS.sub(b" ", f.data[f.start :]).decode("latin-1")
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
    boundary = existing_file(folder / "boundary")
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
    f = open_foam_file(folder / "points")
    n, values, _ = read_list(f, f.start, 3, f.scalar, whole=True)
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
    f = open_foam_file(folder / "faces")
    if f.header.get("class") == "faceCompactList":
        _, offsets, pos = read_list(f, f.start, 1, f.label)
        _, points, _ = read_list(f, pos, 1, f.label)
        n = len(offsets) - 1
        if n < 0 or offsets[0] != 0 or offsets[-1] != len(points) or np.any(np.diff(offsets) < 0):
            raise ValueError(f"{f.path}: the offsets of the faceCompactList do not index its point list")
        starts, counts = offsets[:-1], np.diff(offsets)
    else:
        n, tokens, _ = read_list(f, f.start, None, f.label, whole=True)
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


def read_patch_field(path: str | Path, wall: Wall) -> np.ndarray:
    """The boundary values of a ``volScalarField`` file ``path`` (or ``path.gz``) on the faces of ``wall`` (as
    :func:`read_polymesh` built it), in wall face order: each patch's ``value`` (``uniform X`` or ``nonuniform
    List<scalar> N(...)``, ascii or binary)."""
    p = Path(path)
    if existing_file(p) is None:
        raise _missing_field(p)
    f = open_foam_file(p)
    if f.header.get("class") != "volScalarField":
        raise ValueError(f"{f.path} is a {f.header.get('class')}, not a volScalarField")
    boundary = FoamDictionary(f).dictionary().get("boundaryField")
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
    if parts and existing_file(parts[0] / time / name) is not None:
        mesh = "" if existing_file(case / "constant" / "polyMesh" / "boundary") else "reconstructParMesh -constant && "
        return ValueError(
            f"{p}: no such file, but the decomposed case {case} holds it in {parts[0].name}/{time}: reconstruct it "
            f"first (cd {case} && {mesh}reconstructPar -time {time})"
        )
    return ValueError(f"{p}: no such file (nor {name}.gz): give a field file of a time folder of the case")
