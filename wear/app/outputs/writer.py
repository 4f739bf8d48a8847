"""The one writer of every output file: each file is written to a temporary file in its folder and renamed into
place (output folders: :mod:`wear.app.outputs.folder`).

An interrupted or failed write leaves either the previous complete file or nothing — never a complete-looking partial
one. Temporary names carry the writing process's id (``.<name>.<pid>.<random>.tmp<suffix>``, and for folders
``.<name>.partial-<pid>-<random>``), so that :func:`remove_stale_temps` can delete those a killed process left. Files
get the permissions of the user's umask (:func:`permissions`), as ``open`` would give them.
"""

from __future__ import annotations

import csv
import errno
import json
import math
import os
import platform
import re
import shutil
import tempfile
from collections.abc import Callable, Iterable, Mapping
from dataclasses import asdict, is_dataclass
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import IO, Any

import meshio
import numpy as np

from wear.app.outputs.fields import named_mesh

__all__ = [
    "SCHEMA_VERSION",
    "WRITE_ERRORS",
    "atomic_write",
    "is_temporary",
    "permissions",
    "remove_stale_temps",
    "to_jsonable",
    "versions",
    "write_csv",
    "write_json",
    "write_mesh",
    "write_npz",
    "write_pvd",
    "write_rows",
    "write_summary",
    "write_text",
]


#: The errors of a write the file system refuses (not a fault of the program): a full disk, a quota, a file too
#: large, a read-only file system, a forbidden folder.
WRITE_ERRORS = frozenset({errno.ENOSPC, errno.EDQUOT, errno.EFBIG, errno.EROFS, errno.EACCES, errno.EPERM})


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


# read once, at import: os.umask can only be read by setting it, which is not safe once threads run
_UMASK = _umask()


def permissions() -> tuple[int, int]:
    """(file mode, folder mode) the user's umask gives new files and folders (e.g. 0o644, 0o755 for umask 022)."""
    return 0o666 & ~_UMASK, 0o777 & ~_UMASK


def atomic_write(
    path: str | os.PathLike,
    dump: Callable[[IO], Any] | Callable[[str], Any],
    *,
    mode: str = "text",
    fsync: bool = False,
) -> Path:
    """Write ``path`` through a temporary file in its folder, renamed into place when ``dump`` returns.

    ``mode``: "text" (``dump(f)`` gets a UTF-8 text file, newline translation off), "binary" (a binary file) or
    "path" (``dump(name)`` gets the temporary file's name, ending in ``path``'s suffix, for writers that open the
    file themselves). ``fsync``: flush to disk before the rename (files a resumed run trusts)."""
    path = Path(path)
    # the suffix is kept only for writers that open the file themselves and may read the format from it: a temporary
    # name ending in the target's suffix would match a reader's glob of the finished files (e.g. "*.json")
    suffix = f".tmp{path.suffix}" if mode == "path" else ".tmp"
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.{os.getpid()}.", suffix=suffix, dir=path.parent)
    try:
        if mode == "path":
            os.close(fd)
            dump(tmp)
        else:
            opened = os.fdopen(fd, "w", encoding="utf-8", newline="") if mode == "text" else os.fdopen(fd, "wb")
            with opened as f:
                dump(f)
                if fsync:
                    f.flush()
                    os.fsync(f.fileno())
        os.chmod(tmp, permissions()[0])
        os.replace(tmp, path)
    except BaseException as exc:
        Path(tmp).unlink(missing_ok=True)
        if isinstance(exc, OSError) and exc.filename is None:
            exc.filename = os.fspath(path)  # a failed write names the file, as a failed open does
        raise
    return path


def to_jsonable(value: Any) -> Any:
    """Plain JSON types from dataclasses, numpy scalars/arrays, paths, tuples; non-finite floats → None."""
    if is_dataclass(value) and not isinstance(value, type):
        return to_jsonable(asdict(value))
    if isinstance(value, Mapping):
        return {str(k): to_jsonable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [to_jsonable(v) for v in value]
    if isinstance(value, np.ndarray):
        return to_jsonable(value.tolist())
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        x = float(value)
        return x if math.isfinite(x) else None
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    if value is None or isinstance(value, str):
        return value
    return str(value)


def write_text(path: str | os.PathLike, text: str, fsync: bool = False) -> Path:
    """Write ``text`` (UTF-8)."""
    return atomic_write(path, lambda f: f.write(text), fsync=fsync)


def write_json(path: str | os.PathLike, data: Any, fsync: bool = False) -> Path:
    """Write ``data`` as indented JSON (non-finite floats as null)."""
    return write_text(path, json.dumps(to_jsonable(data), indent=2, allow_nan=False) + "\n", fsync=fsync)


#: The version of the layout of the output folders: the summary every command writes (``summary.json``;
#: ``calibration.json`` of ``impactwear calibrate``), whose first field ``schema_version`` it is, and the fields of
#: the other files (mesh data, table columns, arrays: :mod:`wear.app.outputs.fields`). Raised when a field is renamed
#: or removed or changes its meaning or units; a new field keeps it. 2: the units in every field name of the meshes,
#: tables and arrays.
SCHEMA_VERSION = 2


def write_summary(path: str | os.PathLike, summary: Mapping[str, Any]) -> dict:
    """Write a command's ``summary`` as JSON with :data:`SCHEMA_VERSION` as its first field; returns what was
    written (what ``--json`` prints)."""
    record = {"schema_version": SCHEMA_VERSION, **summary}
    write_json(path, record)
    return record


def write_rows(path: str | os.PathLike, header: list[str], rows: Iterable[Iterable[Any]]) -> Path:
    """Write a CSV with a ``header`` row (names with units, e.g. ``time_s``) and ``rows`` as given."""

    def dump(f: IO) -> None:
        writer = csv.writer(f)
        writer.writerow(header)
        writer.writerows(rows)

    return atomic_write(path, dump)


def write_csv(path: str | os.PathLike, columns: Mapping[str, Any]) -> Path:
    """Write equal-length 1-D ``columns`` (header = keys, which carry units): numbers with 10 significant digits,
    texts (a column of strings) as they are."""
    arrays = {k: np.asarray(v).ravel() for k, v in columns.items()}
    lengths = {v.size for v in arrays.values()}
    if len(lengths) > 1:
        raise ValueError(f"columns have different lengths {sorted(lengths)}: a CSV needs equal-length columns")
    text = [v.dtype.kind in "US" for v in arrays.values()]
    rows = (
        [str(v) if t else f"{float(v):.10g}" for v, t in zip(row, text, strict=True)]
        for row in zip(*arrays.values(), strict=True)
    )
    return write_rows(path, list(arrays), rows)


def write_npz(path: str | os.PathLike, arrays: Mapping[str, Any]) -> Path:
    """Write ``arrays`` to a compressed ``.npz``."""
    return atomic_write(
        path, lambda f: np.savez_compressed(f, **{k: np.asarray(v) for k, v in arrays.items()}), mode="binary"
    )


def write_mesh(path: str | os.PathLike, mesh: meshio.Mesh) -> Path:
    """Write a meshio mesh (format from ``path``'s suffix, e.g. ``.vtu``), its fields under their file names with
    units (:func:`wear.app.outputs.fields.named_mesh`)."""
    file_format = meshio.extension_to_filetypes[Path(path).suffix][0]
    named = named_mesh(mesh)
    return atomic_write(path, lambda name: meshio.write(name, named, file_format=file_format), mode="path")


def write_pvd(path: str | os.PathLike, entries: list[tuple[float, str]]) -> Path:
    """Write a ParaView collection of (time s, .vtu path relative to ``path``'s folder)."""
    lines = [
        '<?xml version="1.0"?>',
        '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">',
        "  <Collection>",
    ]
    lines += [f'    <DataSet timestep="{t:.9g}" group="" part="0" file="{f}"/>' for t, f in entries]
    lines += ["  </Collection>", "</VTKFile>", ""]
    return write_text(path, "\n".join(lines))


def versions() -> dict[str, str]:
    """Versions of impactwear, Python and the numerical libraries (for summary.json)."""
    out = {"python": platform.python_version()}
    for name in ("impactwear", "numpy", "scipy", "numba", "scikit-fem", "meshio", "matplotlib", "pyvista"):
        try:
            out[name] = version(name)
        except PackageNotFoundError:
            out[name] = "not installed"
    return out


_TEMP = re.compile(r"^\.(?P<name>.+)\.(?:(?P<pid>\d+)\.[A-Za-z0-9_]+\.tmp(?:\.\w+)?|partial-(?P<dir_pid>\d+)-\w+)$")


def is_temporary(name: str) -> bool:
    """Whether ``name`` is a temporary file or folder name of this writer."""
    return _TEMP.match(name) is not None


def remove_stale_temps(folder: str | os.PathLike, name: str | None = None) -> list[Path]:
    """Delete the temporary files and folders in ``folder`` that this writer's processes left when killed (their
    process no longer runs), only those of the entry ``name`` if given; returns what was deleted. Another running
    process's temporaries are kept."""
    removed = []
    for p in Path(folder).glob(".*"):
        m = _TEMP.match(p.name)
        if m is None or (name is not None and m["name"] != name):
            continue
        pid = int(m["pid"] or m["dir_pid"])
        try:
            os.kill(pid, 0)
            continue  # still running (ours or another live writer)
        except ProcessLookupError:
            pass
        except PermissionError:
            continue  # another user's live process
        if p.is_dir():
            shutil.rmtree(p, ignore_errors=True)
        else:
            p.unlink(missing_ok=True)
        removed.append(p)
    return removed
