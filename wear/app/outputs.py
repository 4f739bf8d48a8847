"""The run's output folder, written atomically.

Everything goes into a hidden temporary folder beside the target (same file system) and the
folder is renamed into place at the very end, so an interrupted or failed run leaves either the
previous complete output or nothing — never a complete-looking partial folder. A leftover
``.<name>.partial-*`` folder (from a killed process) is not an output and may be deleted.
"""

from __future__ import annotations

import csv
import json
import math
import os
import shutil
import tempfile
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from dataclasses import asdict, is_dataclass
from pathlib import Path
from typing import Any

import numpy as np

__all__ = ["atomic_output_dir", "to_jsonable", "write_json", "write_csv", "write_npz"]


@contextmanager
def atomic_output_dir(target: str | os.PathLike, *, overwrite: bool = True) -> Iterator[Path]:
    """Yield a temporary folder; on success it replaces ``target``, on any error it is removed.

    With ``overwrite=False`` an existing ``target`` is an error (checked before anything is written).
    The swap keeps the old folder until the new one is in place: rename old → trash, rename new →
    target, delete trash.
    """
    target = Path(target).resolve()
    if target.exists() and not target.is_dir():
        raise ValueError(f"out={str(target)!r} exists and is not a folder: give a folder path")
    if target.exists() and not overwrite:
        raise ValueError(f"out={str(target)!r} already exists: choose another folder or allow overwriting")
    target.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{target.name}.partial-", dir=target.parent))
    try:
        yield tmp
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    trash = None
    if target.exists():
        trash = Path(tempfile.mkdtemp(prefix=f".{target.name}.old-", dir=target.parent))
        os.replace(target, trash / "old")
    os.replace(tmp, target)
    if trash is not None:
        shutil.rmtree(trash, ignore_errors=True)


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


def write_json(path: str | os.PathLike, data: Any) -> None:
    """Write ``data`` as indented JSON (temp file in the same folder, then ``os.replace``)."""
    _atomic_write(Path(path), lambda f: json.dump(to_jsonable(data), f, indent=2, allow_nan=False), text=True)


def write_csv(path: str | os.PathLike, columns: Mapping[str, Any]) -> None:
    """Write equal-length 1-D ``columns`` (header = keys, which should carry units, e.g. ``time_s``)."""
    arrays = {k: np.asarray(v).ravel() for k, v in columns.items()}
    lengths = {v.size for v in arrays.values()}
    if len(lengths) > 1:
        raise ValueError(f"columns have different lengths {sorted(lengths)}: a CSV needs equal-length columns")

    def dump(f):
        writer = csv.writer(f)
        writer.writerow(list(arrays))
        for row in zip(*arrays.values(), strict=True):
            writer.writerow([f"{float(v):.10g}" for v in row])

    _atomic_write(Path(path), dump, text=True)


def write_npz(path: str | os.PathLike, arrays: Mapping[str, Any]) -> None:
    """Write ``arrays`` to a compressed ``.npz`` (temp file, then ``os.replace``)."""
    _atomic_write(Path(path), lambda f: np.savez_compressed(f, **{k: np.asarray(v) for k, v in arrays.items()}))


def _atomic_write(path: Path, dump, *, text: bool = False) -> None:
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w" if text else "wb", **({"newline": "", "encoding": "utf-8"} if text else {})) as f:
            dump(f)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
