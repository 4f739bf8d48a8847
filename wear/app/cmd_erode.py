"""``impactwear erode [CASE.toml] [--out DIR] [--angles 0,15,30,...]``: erosion of a plate patch by a particle stream.

The case uses the tables of :mod:`wear.app.case`: ``[ball]`` is the particle (radius, material), ``[plate]`` the
plate, ``[impact]`` the stream speed, angle (deg from the plate normal), friction and contact models; this module
registers an ``[erosion]`` table (stream concentration or mass flux, exposure, wear law, patch, table
resolution, seed). Output folder (every file written atomically: temporary file, then ``os.replace``):

- ``erosion.csv``: time_s, impacts, particle_mass_kg, mass_loss_kg, mass_loss_per_area_kg_m2, erosion_rate
  (kg/kg, cumulative), interval_erosion_rate (kg/kg since the previous row), max_depth_m, rms_slope;
  ``erosion.png`` (mass loss and rates against time);
- ``surface.vtu`` (final surface: a structured quad grid, z = −depth, point data ``depth``, ``wear`` in m),
  ``frames/surface_NNNN.vtu`` and ``erosion.pvd`` (the series, time in s; open in ParaView); ``surface.png``;
- ``response_table.csv`` (the footprint table: normal speed, local angle, volumes, contact radius) and
  ``summary.json`` (case, number of impacts, patch, table resolution, results, timings).

With ``--angles`` one erosion per angle (the case's other keys unchanged) goes into ``angle_<deg>/``
(``erosion.csv``, ``surface.vtu``, ``summary.json``), and ``erosion_vs_angle.csv`` (angle_deg, erosion_rate,
mass_loss_kg) and ``erosion_vs_angle.png`` into the folder. SI units; angles in degrees from the plate normal.
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import math
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from . import case as case_module
from .case import Key

HELP = "erode a plate patch by a stream of particles (surface feedback); mass loss and erosion rate vs time or angle"

ERODE_TABLE = {
    "concentration": Key(float, 0.464, "particle mass concentration of the stream", "kg/m^3", low=0.0, low_open=True),
    "mass_flux": Key(
        float,
        None,
        "mass flux through a plane normal to the stream (replaces concentration)",
        "kg/(m^2 s)",
        low=0.0,
        low_open=True,
    ),
    "exposure_time": Key(float, 3120.0, "exposure time", "s", low=0.0, low_open=True, high=1e10),
    "azimuth": Key(float, 0.0, "stream direction in the patch, from the grid x axis", "deg", low=-360.0, high=360.0),
    "K": Key(float, 1e-11, "wear coefficient of Eq. 15 (units m^(1-beta) s^(beta-1) Pa^(-alpha))", low=0.0),
    "alpha": Key(float, 1.0, "pressure exponent of Eq. 15", low=0.0, high=4.0),
    "beta": Key(float, 0.3, "sliding-speed exponent of Eq. 15", low=0.0, high=4.0),
    "pressure": Key(str, "hertz", "contact pressure source of the wear law", choices=("hertz", "paper", "thornton")),
    "speed_model": Key(str, "sliding", "sliding speed of the wear law", choices=("sliding", "kinematic")),
    "deformation_wear": Key(bool, False, "add Bitter's (1963) deformation wear"),
    "deformation_wear_factor": Key(
        float, None, "Bitter's deformation wear factor epsilon", "J/m^3", low=1e3, high=1e15
    ),
    "deformation_threshold": Key(
        float, None, "elastic-limit normal speed (absent: Bitter's formula)", "m/s", low=0.0, high=1000.0
    ),
    "grid": Key(int, 512, "grid nodes per side of the patch", low=16, high=8192),
    "patch_size": Key(
        float,
        None,
        "side of the periodic patch (absent: grid x contact radius / 4)",
        "m",
        low=0.0,
        low_open=True,
        high=10.0,
    ),
    "seed": Key(int, 0, "random seed of the impact points", low=0, high=2**63 - 1),
    "frames": Key(int, 10, "surfaces saved in the .pvd series", low=1, high=1000),
    "samples": Key(int, 100, "rows of the mass-loss time series", low=1, high=100000),
    "angle_margin": Key(
        float, 20.0, "response table: local angles covered around the stream angle", "deg", low=0.0, high=45.0
    ),
    "angle_step": Key(float, 2.5, "response table: local angle step", "deg", low=0.1, high=15.0),
    "table_speeds": Key(int, 5, "response table: number of normal speeds", low=2, high=50),
    "points_per_length": Key(int, 12, "response table: footprint points per contact radius", low=4, high=64),
}
case_module.register_table("erosion", ERODE_TABLE)
#: Default grid spacing: the nominal contact radius / this (as wear.erosion.erode).
CELLS_PER_RADIUS = 4.0


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "case",
        nargs="?",
        metavar="CASE.toml",
        help="case file ([ball] = particle, [plate], "
        "[impact] = stream speed/angle/friction, [erosion]); default: the embedded default case",
    )
    parser.add_argument("--out", default="erosion", metavar="DIR", help="output folder (default: ./erosion)")
    parser.add_argument("--angles", metavar="A,B,...", help="run one erosion per stream angle (deg from the normal)")
    parser.add_argument("--seed", type=int, metavar="N", help="random seed [erosion.seed]")
    parser.add_argument(
        "--set",
        dest="overrides",
        action="append",
        default=[],
        metavar="TABLE.KEY=VALUE",
        help="override any case key (TOML value, e.g. --set erosion.grid=256); repeatable",
    )
    parser.add_argument("--quiet", action="store_true", help="no progress bar or summary lines")
    parser.add_argument("--print-defaults", action="store_true", help="print the documented default case (TOML)")


def build_case(args: argparse.Namespace) -> dict:
    """The checked case from CASE.toml (or the defaults), ``--set`` and ``--seed``."""
    case = case_module.load_case(args.case) if args.case else case_module.default_case()
    for item in args.overrides:
        case_module.apply_override(case, item)
    if args.seed is not None:
        case_module.set_value(case, "erosion.seed", args.seed)
    return case


def parse_angles(text: str) -> list[float]:
    """Angles (deg) from ``"0,15,30"``; ValueError naming ``--angles`` otherwise."""
    try:
        angles = [float(a) for a in text.split(",") if a.strip()]
    except ValueError:
        raise ValueError(f"--angles={text!r} is not a comma-separated list of numbers (deg)") from None
    if not angles:
        raise ValueError(f"--angles={text!r} is empty: give e.g. 0,15,30,45,60,75")
    for a in angles:
        if not 0.0 <= a <= 85.0:
            raise ValueError(
                f"--angles: angle={a:g} is out of range: stream angle from the normal must be in [0, 85] deg"
            )
    return angles


def stream_setup(case: dict, angle: float | None = None):
    """(ImpactResponse, Stream, table axes, erode keywords) of a checked case (``angle`` overrides impact.angle)."""
    from contact import Material
    from wear import WearLaw
    from wear.erosion import Stream
    from wear.response import ImpactResponse, table_axes

    args = case_module.impact_arguments(case)
    ero, imp = case["erosion"], case["impact"]
    theta = imp["angle"] if angle is None else angle
    if theta > 85.0:
        raise ValueError(f"impact.angle={theta:g} is out of range: a stream angle must be in [0, 85] deg")
    if not isinstance(args["ball"], Material) or math.isinf(args["ball"].density):
        raise ValueError("ball: the particle needs a finite density (kg/m^3)")
    law = WearLaw(K=ero["K"], alpha=ero["alpha"], beta=ero["beta"])
    response = ImpactResponse(
        radius=args["radius"],
        ball=args["ball"],
        plate=args["plate"],
        friction=imp["friction"],
        law=law,
        pressure=ero["pressure"],
        speed_model=ero["speed_model"],
        restitution=imp["restitution"],
        normal_model=imp["normal_model"],
        tangential_model=imp["tangential_model"],
        deformation_wear=ero["deformation_wear"],
        deformation_wear_factor=ero["deformation_wear_factor"],
        deformation_threshold=ero["deformation_threshold"],
    )
    if ero["mass_flux"] is not None:
        stream = Stream(imp["speed"], theta, ero["exposure_time"], mass_flux=ero["mass_flux"], azimuth=ero["azimuth"])
    else:
        stream = Stream(
            imp["speed"], theta, ero["exposure_time"], concentration=ero["concentration"], azimuth=ero["azimuth"]
        )
    axes = table_axes(
        imp["speed"], theta, angle_margin=ero["angle_margin"], angle_step=ero["angle_step"], speeds=ero["table_speeds"]
    )
    kwargs = dict(
        grid=ero["grid"], patch_size=ero["patch_size"], seed=ero["seed"], frames=ero["frames"], samples=ero["samples"]
    )
    return response, stream, axes, kwargs


def _atomic_write(path: Path, writer, mode: str = "w") -> Path:
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
    try:
        with os.fdopen(fd, mode, **({"newline": ""} if "b" not in mode else {})) as f:
            writer(f)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def write_csv(path: Path, header: list[str], rows) -> Path:
    """CSV with a header row, written atomically."""

    def writer(f: io.TextIOBase) -> None:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)

    return _atomic_write(path, writer)


def write_surface_vtu(path: Path, x, y, surface, wear=None) -> Path:
    """The surface as a structured quad grid in a .vtu (z = −depth, m; point data ``depth`` and ``wear``, m)."""
    import meshio

    nx, ny = len(x), len(y)
    xx, yy = np.meshgrid(x, y)
    points = np.column_stack([xx.ravel(), yy.ravel(), -np.asarray(surface).ravel()])
    node = np.arange(nx * ny).reshape(ny, nx)
    quads = np.column_stack(
        [node[:-1, :-1].ravel(), node[:-1, 1:].ravel(), node[1:, 1:].ravel(), node[1:, :-1].ravel()]
    )
    data = {"depth": np.asarray(surface).ravel()}
    if wear is not None:
        data["wear"] = np.asarray(wear).ravel()
    mesh = meshio.Mesh(points, [("quad", quads)], point_data=data)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".vtu", dir=path.parent)
    os.close(fd)
    try:
        meshio.write(tmp, mesh, file_format="vtu")
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def write_pvd(path: Path, entries: list[tuple[float, str]]) -> Path:
    """ParaView collection of (time s, relative .vtu path)."""
    lines = [
        '<?xml version="1.0"?>',
        '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">',
        "  <Collection>",
    ]
    lines += [f'    <DataSet timestep="{t:.9g}" group="" part="0" file="{f}"/>' for t, f in entries]
    lines += ["  </Collection>", "</VTKFile>", ""]
    return _atomic_write(path, lambda f: f.write("\n".join(lines)))


def _summary(case, result, table, seconds) -> dict:
    area = result.patch_size**2
    return {
        "case": case,
        "stream": {
            "speed_m_s": result.stream.speed,
            "angle_deg": result.stream.angle,
            "flux_kg_m2_s": result.stream.flux,
            "plate_flux_kg_m2_s": result.stream.plate_flux,
            "exposure_time_s": result.stream.exposure_time,
        },
        "patch": {
            "size_m": result.patch_size,
            "grid": int(result.x.size),
            "spacing_m": result.spacing,
            "area_m2": area,
        },
        "table": {"resolution": table.resolution, "description": table.description},
        "results": {
            "impacts": result.n_impacts,
            "shadowed": result.shadowed,
            "clamped": result.clamped,
            "particle_mass_kg": float(result.particle_mass_kg[-1]),
            "mass_loss_kg": float(result.mass_loss_kg[-1]),
            "mass_loss_per_area_kg_m2": float(result.mass_loss_kg[-1] / area),
            "erosion_rate_kg_per_kg": result.final_erosion_rate,
            "max_depth_m": float(result.max_depth_m[-1]),
            "rms_slope": float(result.rms_slope[-1]),
        },
        "seconds": seconds,
    }


def nominal_contact_radius(case: dict, angle: float) -> float:
    """Largest contact radius (m) of one particle of the case's stream at ``angle`` (deg) on the flat plate."""
    from contact import simulate_impact

    args = case_module.impact_arguments(case)
    args["angle"] = angle
    return float(simulate_impact(**args, history=False).max_contact_radius)


def run_case(
    case: dict,
    out: Path,
    *,
    angle: float | None = None,
    series: bool = True,
    progress: bool = False,
    patch_size: float | None = None,
):
    """Run one erosion of ``case`` into ``out`` (created); returns (ErosionResult, summary dict).
    ``angle`` (deg) and ``patch_size`` (m) override the case's ``impact.angle`` and ``erosion.patch_size``."""
    from wear.erosion import erode
    from wear.response import build_response_table

    from .figures import erosion as fig

    out.mkdir(parents=True, exist_ok=True)
    response, stream, (vn, angles), kwargs = stream_setup(case, angle)
    if patch_size is not None:
        kwargs["patch_size"] = patch_size
    t0 = time.perf_counter()
    table = build_response_table(
        response,
        vn,
        angles,
        points_per_length=case["erosion"]["points_per_length"],
        description=f"ImpactResponse(pressure={response.pressure!r}, law: {response.law})",
    )
    t1 = time.perf_counter()
    result = erode(table, stream, progress=progress, **kwargs)
    t2 = time.perf_counter()
    area = result.patch_size**2
    rows = zip(
        result.time,
        result.impacts,
        result.particle_mass_kg,
        result.mass_loss_kg,
        result.mass_loss_kg / area,
        result.erosion_rate,
        result.interval_erosion_rate,
        result.max_depth_m,
        result.rms_slope,
        strict=True,
    )
    write_csv(
        out / "erosion.csv",
        [
            "time_s",
            "impacts",
            "particle_mass_kg",
            "mass_loss_kg",
            "mass_loss_per_area_kg_m2",
            "erosion_rate",
            "interval_erosion_rate",
            "max_depth_m",
            "rms_slope",
        ],
        rows,
    )
    write_csv(
        out / "response_table.csv",
        [
            "normal_speed_m_s",
            "angle_deg",
            "volume_m3",
            "sliding_volume_m3",
            "deformation_volume_m3",
            "contact_radius_m",
        ],
        table.rows(),
    )
    write_surface_vtu(out / "surface.vtu", result.x, result.y, result.surface, result.wear)
    if series:
        (out / "frames").mkdir(exist_ok=True)
        entries = [(0.0, "frames/surface_0000.vtu")]
        write_surface_vtu(out / entries[0][1], result.x, result.y, np.zeros_like(result.wear))
        for k, (t, frame) in enumerate(zip(result.frame_time, result.frames, strict=True), start=1):
            name = f"frames/surface_{k:04d}.vtu"
            write_surface_vtu(out / name, result.x, result.y, frame)
            entries.append((float(t), name))
        write_pvd(out / "erosion.pvd", entries)
        title = f"{stream.speed:g} m/s at {stream.angle:g} deg"
        fig.plot_time_series(
            result.time,
            result.mass_loss_kg,
            result.erosion_rate,
            out / "erosion.png",
            title,
            interval_rate=result.interval_erosion_rate,
        )
        fig.plot_surface(result.x, result.y, result.surface, out / "surface.png", stream.azimuth, title)
    summary = _summary(
        case,
        result,
        table,
        {"table": t1 - t0, "erosion": t2 - t1, "impacts_per_s": result.n_impacts / max(t2 - t1, 1e-9)},
    )
    text = json.dumps(summary, indent=2, default=lambda v: None if isinstance(v, float) else str(v))
    _atomic_write(out / "summary.json", lambda f: f.write(text + "\n"))
    return result, summary


def main(args: argparse.Namespace) -> int:
    if args.print_defaults:
        sys.stdout.write(case_module.dump_case(case_module.default_case(), comments=True))
        return 0
    case = build_case(args)
    out = Path(args.out)
    progress = not args.quiet and sys.stderr.isatty()
    say = (lambda *a: None) if args.quiet else print
    if args.angles is None:
        result, summary = run_case(case, out, progress=progress)
        r = summary["results"]
        say(
            f"erode: {r['impacts']} impacts on a {result.patch_size * 1e3:.4g} mm patch ({result.x.size}^2 nodes), "
            f"{summary['seconds']['erosion']:.3g} s"
        )
        say(f"  table: {summary['table']['resolution']}")
        say(
            f"  mass loss {r['mass_loss_kg']:.6g} kg ({r['mass_loss_per_area_kg_m2']:.6g} kg/m^2), erosion rate "
            f"{r['erosion_rate_kg_per_kg']:.6g} kg/kg, max depth {r['max_depth_m'] * 1e6:.4g} um -> {out}"
        )
        return 0
    angles = parse_angles(args.angles)
    out.mkdir(parents=True, exist_ok=True)
    patch = case["erosion"]["patch_size"]
    if patch is None:  # one patch for every angle: resolve the smallest nominal contact (the most oblique stream)
        patch = case["erosion"]["grid"] * min(nominal_contact_radius(case, a) for a in angles) / CELLS_PER_RADIUS
    rows = []
    for a in angles:
        result, summary = run_case(
            case, out / f"angle_{a:g}", angle=a, series=False, progress=progress, patch_size=patch
        )
        rows.append((a, result.final_erosion_rate, float(result.mass_loss_kg[-1])))
        say(
            f"erode: angle {a:g} deg: {result.n_impacts} impacts, erosion rate {result.final_erosion_rate:.6g} kg/kg, "
            f"mass loss {result.mass_loss_kg[-1]:.6g} kg"
        )
    write_csv(out / "erosion_vs_angle.csv", ["angle_deg", "erosion_rate", "mass_loss_kg"], rows)
    from .figures import erosion as fig

    fig.plot_angles(
        [r[0] for r in rows],
        [r[1] for r in rows],
        [r[2] for r in rows],
        out / "erosion_vs_angle.png",
        f"{case['impact']['speed']:g} m/s, {case['erosion']['exposure_time']:g} s",
    )
    best = max(rows, key=lambda r: r[1])
    say(f"erode: largest erosion rate {best[1]:.6g} kg/kg at {best[0]:g} deg -> {out / 'erosion_vs_angle.csv'}")
    return 0
