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


def versions() -> dict[str, str]:
    """Versions of impactwear, Python and the numerical libraries (for summary.json)."""
    import platform
    from importlib.metadata import PackageNotFoundError, version

    out = {"python": platform.python_version()}
    for name in ("impactwear", "numpy", "scipy", "numba", "scikit-fem", "meshio", "matplotlib", "pyvista"):
        try:
            out[name] = version(name)
        except PackageNotFoundError:
            out[name] = "not installed"
    return out


def _history_columns(history) -> dict[str, np.ndarray]:
    names = {
        "t": "time_s",
        "overlap": "overlap_m",
        "normal_force": "normal_force_N",
        "tangential_force": "tangential_force_N",
        "tangential_displacement": "tangential_displacement_m",
        "contact_radius": "contact_radius_m",
        "peak_pressure": "peak_pressure_Pa",
        "slip_velocity": "slip_velocity_m_per_s",
        "sliding": "sliding",
        "center_x": "center_x_m",
        "contact_x": "contact_x_m",
        "omega": "spin_rad_per_s",
        "normal_velocity": "normal_velocity_m_per_s",
        "tangential_velocity": "tangential_velocity_m_per_s",
    }
    return {label: np.asarray(getattr(history, attr), dtype=float) for attr, label in names.items()}


def write_run(result, out: str | os.PathLike, progress=None) -> dict:
    """Write the whole output folder of a :class:`wear.pipeline.RunResult` atomically; returns the summary.

    Files: ``summary.json`` (case, versions, results, stage times), ``history.csv`` (impact histories, units in
    the column names), ``pressure.npz`` (p(r, t) table of the wear stage, and the FE table if any),
    ``surface.vtu``, ``plate.vtu``, ``plate_fe.vtu`` (with an FE plate), the PNG figures and ``surface_3d.png``.
    ``progress(stage)`` is called at "meshes", "figures", "render".
    """
    import time

    import meshio

    from wear.surface import deform_plate_mesh, plate_block_mesh, surface_mesh

    notify = progress or (lambda stage: None)
    case = result.case
    times = dict(result.stage_times)
    notes: list[str] = []
    with atomic_output_dir(out) as tmp:
        notify("meshes")
        t0 = time.perf_counter()
        write_csv(tmp / "history.csv", _history_columns(result.impact.history))
        ph = result.pressure
        arrays = {"time_s": ph.time, "contact_x_m": ph.contact_x, "extent_m": ph.extent, "pressure_Pa": ph.pressure,
                  "s": ph.s, "source": np.array(ph.source)}  # fmt: skip
        if result.coupling is not None:
            ft, fr, fp = result.coupling.pressure_table
            arrays.update(fe_time_s=ft, fe_surface_r_m=fr, fe_pressure_Pa=fp)
        write_npz(tmp / "pressure.npz", arrays)
        surf_mesh = surface_mesh(result.surface)
        surf_mesh.write(tmp / "surface.vtu")
        if case.output.plate_mesh:
            try:
                user = meshio.read(case.output.plate_mesh)
            except Exception as exc:  # meshio raises many types for unreadable files
                raise ValueError(
                    f"output.plate_mesh={case.output.plate_mesh!r} cannot be read by meshio: {exc}"
                ) from None
            deform_plate_mesh(user, result.surface).write(tmp / "plate.vtu")
        else:
            plate_block_mesh(result.surface, case.output.block_thickness).write(tmp / "plate.vtu")
        if result.fe is not None and hasattr(result.fe, "write"):
            _write_plate_fe(result, tmp / "plate_fe.vtu")
        times["meshes"] = time.perf_counter() - t0
        if case.output.figures:
            notify("figures")
            t0 = time.perf_counter()
            from .figures.run import write_run_figures

            write_run_figures(result, tmp)
            times["figures"] = time.perf_counter() - t0
        if case.output.render:
            notify("render")
            t0 = time.perf_counter()
            from .render import render_surface, rendering_available

            ok, why = rendering_available()
            if ok:
                render_surface(surf_mesh, tmp / "surface_3d.png", title="dent + wear")
            else:
                notes.append(why)
            times["render"] = time.perf_counter() - t0
        summary = result.summary()
        summary["stage_times_s"] = times
        summary["versions"] = versions()
        summary["notes"] = notes
        summary["files"] = sorted(p.name for p in tmp.iterdir()) + ["summary.json"]
        write_json(tmp / "summary.json", summary)
    return summary


def _write_plate_fe(result, path: Path) -> None:
    """The FE plate after the impact (``fe.write``: points (r, z, 0) m, point data ``u`` m, ``pressure`` Pa, cell
    data ``von_mises`` Pa, ``equivalent_plastic_strain``); for a normal impact its surface nodes are also moved
    down by the axisymmetric wear depth h(r) (point data ``wear_depth``, m)."""
    import meshio

    from wear.integrate import axisymmetric_wear_depth
    from wear.pressure import sliding_speed

    result.fe.write(path)
    mesh = meshio.read(path)
    pts = np.asarray(mesh.points, dtype=float)
    u = np.asarray(mesh.point_data["u"], dtype=float)
    undeformed_z = pts[:, 1] - u[:, 1]
    on_surface = np.abs(undeformed_z) <= 1e-9 * float(np.ptp(pts[:, 0]))
    wear = np.zeros(pts.shape[0])
    if result.case.impact.angle == 0.0:
        h = axisymmetric_wear_depth(result.pressure, sliding_speed(result.impact, result.case.wear.speed),
                                    result.case.wear.law(), undeformed_r := pts[:, 0] - u[:, 0])  # fmt: skip
        wear = np.where(on_surface & (undeformed_r >= 0), h, 0.0)
    pts[:, 1] -= wear
    point_data = dict(mesh.point_data)
    point_data["wear_depth"] = wear
    meshio.Mesh(pts, mesh.cells, point_data=point_data, cell_data=dict(mesh.cell_data)).write(path)
