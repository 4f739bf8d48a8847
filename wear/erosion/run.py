"""Erosion of a case: the stream, the response table and the eroded patch from a :class:`wear.Case` (SI units,
angles in degrees from the plate normal).

The case's ``[ball]`` is the particle, ``[plate]`` the plate, ``[impact]`` the stream's speed, angle, friction and
contact models, ``[wear]`` the wear law and its pressure source, ``[erosion]`` the stream's concentration or mass
flux, exposure, patch and table resolution. :func:`erode_case` runs one erosion, :func:`erode_angles` one per stream
angle on a common patch; both return :class:`ErosionRun` (no files: the command line writes them).
"""

from __future__ import annotations

import math
import re
import time
import warnings
from dataclasses import dataclass

from contact import simulate_impact
from wear.case import JOBS, TABLES, Case
from wear.erosion.memory import check_patch_memory
from wear.erosion.patch import erode
from wear.erosion.response import ImpactResponse
from wear.erosion.result import ErosionResult
from wear.erosion.stream import Stream
from wear.erosion.table import MAX_TABLE_ENTRIES, build_response_table, table_axes

__all__ = [
    "ErosionRun",
    "erode_case",
    "erode_angles",
    "impact_response",
    "nominal_contact_radius",
    "MAX_STREAM_ANGLE",
    "CELLS_PER_RADIUS",
]

#: Largest stream angle from the normal (deg): beyond it the response table has no footprints.
MAX_STREAM_ANGLE = 85.0
#: Default grid spacing: the nominal contact radius / this (as :func:`wear.erosion.erode`).
CELLS_PER_RADIUS = 4.0


@dataclass(frozen=True, eq=False)
class ErosionRun:
    """One erosion of a case: ``case``, ``result`` (:class:`wear.erosion.ErosionResult`: the stream, the response
    table, the surface and the time series) and ``seconds`` (wall times of the ``table`` and the ``erosion``, s, and
    ``impacts_per_s``)."""

    case: Case
    result: ErosionResult
    seconds: dict[str, float]

    def summary(self) -> dict:
        """The numbers of summary.json (SI units)."""
        r = self.result
        area = r.patch_size**2
        return {
            "case": self.case.to_dict(JOBS["erode"].tables),
            "stream": {
                "speed_m_s": r.stream.speed,
                "angle_deg": r.stream.angle,
                "flux_kg_m2_s": r.stream.flux,
                "plate_flux_kg_m2_s": r.stream.plate_flux,
                "exposure_time_s": r.stream.exposure_time,
            },
            "patch": {"size_m": r.patch_size, "grid": int(r.x.size), "spacing_m": r.spacing, "area_m2": area},
            "table": {"resolution": r.table.resolution, "description": r.table.description},
            "results": {
                "impacts": r.n_impacts,
                "shadowed": r.shadowed,
                "clamped": r.clamped,
                "particle_mass_kg": float(r.particle_mass_kg[-1]),
                "mass_loss_kg": float(r.mass_loss_kg[-1]),
                "mass_loss_per_area_kg_m2": float(r.mass_loss_kg[-1] / area),
                "erosion_rate_kg_per_kg": r.final_erosion_rate,
                "max_depth_m": float(r.max_depth_m[-1]),
                "rms_slope": float(r.rms_slope[-1]),
            },
            "seconds": dict(self.seconds),
        }


def _stream_angle(case: Case, angle: float | None) -> float:
    theta = case.impact.angle if angle is None else angle
    if theta > MAX_STREAM_ANGLE:
        raise ValueError(
            f"impact.angle={theta:g} is out of range: a stream angle must be in [0, {MAX_STREAM_ANGLE:g}] deg"
        )
    return theta


def _axes(case: Case, theta: float):
    """The response table's axes (normal speeds m/s, local angles deg) of the case's stream at ``theta`` (deg), refused
    in one line naming the case keys if the table would exceed :data:`wear.erosion.table.MAX_TABLE_ENTRIES`."""
    ero = case.erosion
    speeds, angles = table_axes(
        case.impact.speed, theta, angle_margin=ero.angle_margin, angle_step=ero.angle_step, speeds=ero.table_speeds
    )
    entries = speeds.size * angles.size
    if entries > MAX_TABLE_ENTRIES:
        raise ValueError(
            f"erosion.angle_step={ero.angle_step:g} over erosion.angle_margin={ero.angle_margin:g} deg with "
            f"erosion.table_speeds={ero.table_speeds} gives {angles.size} x {speeds.size} = {entries} "
            f"response-table impacts (~53 ms and 0.27 MB each): at most {MAX_TABLE_ENTRIES}; give a larger "
            "erosion.angle_step, a smaller erosion.angle_margin or fewer erosion.table_speeds"
        )
    return speeds, angles


def _check_budget(case: Case, angles: list[float]) -> None:
    """Refuse, before any impact is run, a case whose patch arrays or response tables are too large (one line naming
    the case keys)."""
    ero = case.erosion
    check_patch_memory(ero.grid, ero.frames, len(angles), grid_name="erosion.grid", frames_name="erosion.frames")
    for theta in angles:
        _axes(case, theta)


def impact_response(case: Case) -> ImpactResponse:
    """The per-impact model of the case's particles (:class:`wear.erosion.ImpactResponse`): ``[ball]``, ``[plate]``,
    the contact models of ``[impact]`` and the wear law of ``[wear]`` (its pressure source ``"fe"`` replaced, with a
    warning, by the closed form of ``impact.normal_model``, and the FE surface's local slip by the contact point's:
    the batched impacts run no FE plate)."""
    pressure, speed = case.wear.pressure, case.wear.speed
    if pressure == "fe":  # e.g. a run case given to erode: it holds everything the stream needs but this
        pressure = "thornton" if case.impact.normal_model == "thornton" else "hertz"
        speed = "sliding" if speed == "local" else speed
        warnings.warn(
            f"wear.pressure='fe' needs the FE plate, which the stream's batched impacts do not run: the "
            f"erosion uses {pressure!r}, the closed form of impact.normal_model"
            + (
                ", and the contact-point slip (wear.speed='sliding') for the FE surface's"
                if speed != case.wear.speed
                else ""
            ),
            stacklevel=2,
        )
    ball = case.ball.material()
    if math.isinf(ball.density):
        raise ValueError("ball.density=inf: the particle needs a finite density (kg/m^3)")
    imp, w = case.impact, case.wear
    return ImpactResponse(
        radius=case.ball.radius,
        ball=ball,
        plate=case.plate.material(),
        friction=imp.friction,
        law=w.wear_law(),
        pressure=pressure,
        speed_model=speed,
        restitution=imp.restitution,
        normal_model=imp.normal_model,
        tangential_model=imp.tangential_model,
        points_across=w.points_across,
        wear_law=w.law,
        constants={**w.values(), "hardness": case.plate.hardness},
        limiting_pressure=imp.limiting_pressure,
        scheme=imp.scheme,
        time_step=imp.time_step,
    )


def _stream(case: Case, theta: float) -> Stream:
    ero = case.erosion
    return Stream(case.impact.speed, theta, ero.exposure_time, azimuth=ero.azimuth, **ero.supply())


def nominal_contact_radius(case: Case, angle: float | None = None) -> float:
    """Largest contact radius (m) of one particle of the case's stream at ``angle`` (deg; default
    ``impact.angle``) on the flat plate."""
    theta = _stream_angle(case, angle)
    return float(simulate_impact(**case.impact_arguments(angle=theta), history=False).max_contact_radius)


def _case_key_error(exc: ValueError) -> ValueError:
    """``exc`` of :func:`wear.erosion.erode`, whose messages name its own arguments (``exposure_time=...``), with the
    case key the user gave instead (``erosion.exposure_time=...``)."""
    text = str(exc)
    match = re.match(r"([a-z_]+)=", text)
    if match and match.group(1) in TABLES["erosion"].keys():
        return ValueError(f"erosion.{text}")
    return exc


def erode_case(
    case: Case, *, angle: float | None = None, patch_size: float | None = None, progress: bool = False
) -> ErosionRun:
    """One erosion of ``case``: the response table over normal speed × local angle (batched impacts and the wear
    law), then the patch eroded by the stream (:func:`wear.erosion.erode`). ``angle`` (deg) and ``patch_size`` (m)
    override ``impact.angle`` and ``erosion.patch_size``; ``progress``: a progress bar on stderr."""
    theta = _stream_angle(case, angle)
    _check_budget(case, [theta])
    response, stream = impact_response(case), _stream(case, theta)
    ero = case.erosion
    speeds, angles = _axes(case, theta)
    t0 = time.perf_counter()
    table = build_response_table(
        response,
        speeds,
        angles,
        points_per_length=ero.points_per_length,
        description=f"ImpactResponse(pressure={response.pressure!r}, law: {response.law})",
    )
    t1 = time.perf_counter()
    try:
        result = erode(
            table,
            stream,
            grid=ero.grid,
            patch_size=ero.patch_size if patch_size is None else patch_size,
            seed=ero.seed,
            frames=ero.frames,
            samples=ero.samples,
            progress=progress,
        )
    except ValueError as exc:
        raise _case_key_error(exc) from None
    t2 = time.perf_counter()
    seconds = {"table": t1 - t0, "erosion": t2 - t1, "impacts_per_s": result.n_impacts / max(t2 - t1, 1e-9)}
    return ErosionRun(case, result, seconds)


def erode_angles(case: Case, angles: list[float], progress: bool = False) -> list[ErosionRun]:
    """One erosion of ``case`` per stream angle (deg), on one patch for every angle: ``erosion.patch_size``, or the
    grid resolving the smallest nominal contact (the most oblique stream).

    Examples
    --------
    Silica sand (radius 150 µm) at 20 m/s on carbon steel under DNV-RP-O501's law, on a small patch (128² cells,
    0.4 mm) for a short exposure: the plate stays nearly flat, so each angle's erosion rate (kg/kg) is the law's
    closed form E = K U^n F(α), F(α) = 0.6 (sin α + 7.2 (sin α − sin²α))^0.6 (1 − e^(−20α)) with α the angle from
    the surface (DNV-RP-O501, 2015), written out here:

    >>> import math
    >>> from wear.case import default_case
    >>> case = default_case("erode").with_(
    ...     ball={"radius": 150e-6, "E": 94e9, "nu": 0.17, "density": 2650.0, "name": "silica sand"},
    ...     plate={"E": 200e9, "nu": 0.3, "density": 7850.0, "yield_strength": 350e6, "hardness": 1.4e9},
    ...     impact={"speed": 20.0, "friction": 0.3},
    ...     wear={"law": "dnv", "dnv_K": 2e-9, "dnv_n": 2.6},
    ...     erosion={"grid": 128, "patch_size": 4e-4, "exposure_time": 1.0, "samples": 2, "frames": 1,
    ...              "table_speeds": 3, "angle_step": 5.0, "angle_margin": 10.0},
    ... )
    >>> runs = erode_angles(case, [30.0, 60.0])  # deg from the normal
    >>> def dnv(theta):
    ...     a = math.radians(90.0 - theta)
    ...     return 2e-9 * 20.0**2.6 * 0.6 * (math.sin(a) + 7.2 * (math.sin(a) - math.sin(a) ** 2)) ** 0.6 * (
    ...         1.0 - math.exp(-20.0 * a))
    >>> [bool(abs(run.result.final_erosion_rate / dnv(run.result.stream.angle) - 1) < 5e-3) for run in runs]
    [True, True]
    """
    for a in angles:
        _stream_angle(case, a)
    _check_budget(case, angles)
    patch = case.erosion.patch_size
    if patch is None:
        patch = case.erosion.grid * min(nominal_contact_radius(case, a) for a in angles) / CELLS_PER_RADIUS
    return [erode_case(case, angle=a, patch_size=patch, progress=progress) for a in angles]
