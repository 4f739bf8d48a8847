"""Headless 3-D view of the deformed plate surface (pyvista, off-screen).

Off-screen rendering needs an OpenGL implementation without a display: EGL (Mesa's
``libEGL_mesa`` with the ``libgl1-mesa-dri`` drivers) or OSMesa. Where neither is installed, VTK
may abort the whole process instead of raising, so :func:`rendering_available` looks for the
libraries first and the run skips the view with a one-line hint naming the Debian packages.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import math
import os
from pathlib import Path
from typing import TYPE_CHECKING

import meshio
import numpy as np

from wear.app.outputs.writer import atomic_write

if TYPE_CHECKING:  # pyvista loads VTK: at run time only once rendering is known to be available
    import pyvista as pv

__all__ = [
    "DEBIAN_PACKAGES",
    "RELIEF_FRACTION",
    "rendering_available",
    "render_surface",
    "default_exaggeration",
    "exaggeration_for",
    "round_ticks",
]

#: Debian/Ubuntu packages that provide headless OpenGL for VTK (EGL via Mesa, or OSMesa).
DEBIAN_PACKAGES = "libegl1 libgl1-mesa-dri libegl-mesa0 (or libosmesa6)"


def _loadable(*names: str) -> bool:
    for name in names:
        try:
            ctypes.CDLL(name)
            return True
        except OSError:
            continue
    return False


def rendering_available() -> tuple[bool, str]:
    """(True, "") if pyvista can render off-screen here, else (False, reason with the packages to install)."""
    try:
        import pyvista  # noqa: F401
    except ImportError as exc:  # pragma: no cover - pyvista is a dependency
        return False, f"pyvista is not importable ({exc}); pip install pyvista"
    if os.environ.get("DISPLAY") and _loadable("libGL.so.1", ctypes.util.find_library("GL") or "libGL.so"):
        return True, ""
    egl = _loadable("libEGL.so.1") and _loadable("libEGL_mesa.so.0")
    osmesa = _loadable("libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so")
    if egl or osmesa:
        return True, ""
    return False, (
        "3-D view skipped: off-screen rendering needs EGL or OSMesa; "
        f"on Debian/Ubuntu install: apt-get install {DEBIAN_PACKAGES}"
    )


#: The exaggerated relief spans at most this fraction of the surface's in-plane size. With factors on the 1-2-5
#: series the next factor up is at most 2.5 × larger, so the relief always spans 10–25 % of the span: a
#: micrometre dent on a sub-millimetre patch reads as a dent without turning into a spike.
RELIEF_FRACTION = 0.25


def _floor_125(value: float) -> float:
    """The largest number of the 1-2-5 series (…, 0.5, 1, 2, 5, 10, …) that is ≤ ``value`` (> 0)."""
    exponent = math.floor(math.log10(value))
    # the relative tolerance keeps values that are exactly on the series (20.0 → 20, not 10) after round-off
    mantissa = value / 10.0**exponent * (1.0 + 1e-12)
    if mantissa >= 10.0:
        exponent, mantissa = exponent + 1, 1.0
    return (5.0 if mantissa >= 5.0 else 2.0 if mantissa >= 2.0 else 1.0) * 10.0**exponent


def exaggeration_for(relief: float, span: float, fraction: float = RELIEF_FRACTION) -> float:
    """Vertical exaggeration (≥ 1, on the 1-2-5 series) for a relief of height ``relief`` (m) on a surface of
    in-plane size ``span`` (m): the largest factor with factor × relief ≤ ``fraction`` × span.

    >>> exaggeration_for(3.75e-6, 0.4e-3)  # 3.75 µm over 0.4 mm: ×20 draws the relief at 19 % of the span
    20.0
    """
    if relief <= 0.0 or span <= 0.0:
        return 1.0
    return max(_floor_125(fraction * span / relief), 1.0)


def default_exaggeration(mesh: meshio.Mesh) -> float:
    """:func:`exaggeration_for` the surface's relief (peak-to-valley of z, pile-up included) and its largest
    in-plane extent (m)."""
    points = np.asarray(mesh.points, dtype=float)
    span = float(np.ptp(points[:, :2], axis=0).max())
    return exaggeration_for(float(np.ptp(points[:, 2])), span)


def round_ticks(low: float, high: float, count: int = 5) -> np.ndarray:
    """Round values (steps of 1, 2, 2.5 or 5 × 10^k) inside [``low``, ``high``], about ``count`` of them."""
    if not high > low:
        return np.array([low])
    raw = (high - low) / max(count - 1, 1)
    exponent = math.floor(math.log10(raw))
    step = next(m for m in (1.0, 2.0, 2.5, 5.0, 10.0) if m * 10.0**exponent >= raw * (1.0 - 1e-12)) * 10.0**exponent
    k = np.arange(math.ceil(low / step - 1e-9), math.floor(high / step + 1e-9) + 1)
    # k × step (not a running sum) so that 0 is exactly 0 and 0.3 prints as 0.3
    return k * step


def _outward_ticks(low: float, high: float, count: int = 4) -> np.ndarray:
    """At most ``count`` round values (steps of 1, 2, 2.5 or 5 × 10^k) whose first and last enclose [``low``,
    ``high``]."""
    if not high > low:
        return np.array([low])
    exponent = math.floor(math.log10((high - low) / max(count - 1, 1)))
    for m in (1.0, 2.0, 2.5, 5.0, 10.0, 20.0):
        step = m * 10.0**exponent
        k0, k1 = math.floor(low / step + 1e-9), math.ceil(high / step - 1e-9)
        if k1 - k0 <= count - 1:
            break
    return np.arange(k0, k1 + 1) * step


def render_surface(
    mesh: meshio.Mesh,
    path: str | os.PathLike,
    *,
    scalar: str = "total_depth",
    exaggeration: float | None = None,
    window_size: tuple[int, int] = (1200, 800),
    title: str = "",
) -> Path:
    """Render a surface mesh (z = −depth, m) to a PNG with z scaled by ``exaggeration`` (default
    :func:`default_exaggeration`; stated on the image).

    Coloured by point data ``scalar`` in µm (colour-bar labels at round values); box axes labelled with the true
    coordinates, x and y in mm and z in µm. Raises ``RuntimeError`` with the install hint if
    off-screen rendering is unavailable (check :func:`rendering_available` first to skip quietly).
    """
    ok, why = rendering_available()
    if not ok:
        raise RuntimeError(why)
    import pyvista as pv  # heavy (VTK), and only where rendering is available

    _silence_vtk()
    factor = default_exaggeration(mesh) if exaggeration is None else float(exaggeration)
    if factor <= 0:
        raise ValueError(f"exaggeration={factor:g} is out of range: must be > 0")
    faces = _vtk_faces(mesh)
    # in-plane coordinates in mm, depth in mm × factor, so the camera sees a unit-sized scene
    points = np.asarray(mesh.points, dtype=float) * 1e3
    points[:, 2] *= factor
    poly = pv.PolyData(points, faces)
    plotter = pv.Plotter(off_screen=True, window_size=list(window_size))
    plotter.set_background("white")
    _add_coloured_surface(plotter, poly, mesh, scalar)
    plotter.add_text(
        f"{title + ':   ' if title else ''}depth (z) exaggerated ×{factor:g}",
        position="upper_left",
        font_size=12,
        color="black",
    )
    _add_true_axes(plotter, poly, mesh, factor)
    plotter.camera_position = "iso"
    plotter.camera.elevation = -10
    plotter.camera.zoom(1.0)
    try:
        return atomic_write(path, lambda name: plotter.screenshot(name), mode="path")
    finally:
        plotter.close()


def _silence_vtk() -> None:
    """Turn VTK's stderr log and warning windows off."""
    # VTK is imported here, not at the top: only once rendering_available() has found the OpenGL libraries
    from vtkmodules.vtkCommonCore import vtkLogger, vtkObject

    # VTK logs to stderr (with colour codes) when it probes an X server it then does without ("bad X server
    # connection" off-screen): the render succeeds, and the user's terminal is not VTK's
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
    vtkObject.GlobalWarningDisplayOff()


def _vtk_faces(mesh: meshio.Mesh) -> np.ndarray:
    """The surface cells of ``mesh`` (its quads, else its triangles) as VTK's flat face array: (count, nodes...)
    per cell."""
    cells = mesh.cells_dict
    if "quad" in cells:
        return np.hstack([np.full((len(cells["quad"]), 1), 4), cells["quad"]]).ravel()
    if "triangle" in cells:
        return np.hstack([np.full((len(cells["triangle"]), 1), 3), cells["triangle"]]).ravel()
    raise ValueError("mesh has no quad or triangle cells: render_surface needs a surface mesh")


def _add_coloured_surface(plotter: pv.Plotter, poly: pv.PolyData, mesh: meshio.Mesh, scalar: str) -> None:
    """Add ``poly`` to ``plotter`` coloured by ``mesh``'s point data ``scalar`` (m; default the depth −z) in µm,
    with a colour bar labelled at round values."""
    import pyvista as pv  # see _silence_vtk: VTK only once rendering is known to be available

    values = np.asarray(mesh.point_data.get(scalar, -mesh.points[:, 2]), dtype=float) * 1e6
    poly.point_data[f"{scalar} (µm)"] = values
    bar_title = f"{scalar.replace('_', ' ')} (µm)"
    plotter.add_mesh(
        poly,
        scalars=f"{scalar} (µm)",
        cmap="viridis",
        smooth_shading=True,
        scalar_bar_args={"title": bar_title, "color": "black", "vertical": True, "fmt": "%.3g"},
    )
    # VTK spaces the bar's labels evenly between the data limits (3.75, 2.75, 1.76, …); labels at round values
    # inside the limits read like a matplotlib colour bar
    ticks = round_ticks(float(np.nanmin(values)), float(np.nanmax(values)))
    bar = plotter.scalar_bars[bar_title]
    bar.SetUseCustomLabels(True)
    bar.SetCustomLabels(pv.convert_array(ticks))


def _add_true_axes(plotter: pv.Plotter, poly: pv.PolyData, mesh: meshio.Mesh, factor: float) -> None:
    """Box axes around ``poly`` (drawn in mm, z × ``factor``) labelled with ``mesh``'s true coordinates: x, y in mm
    and z in µm."""
    from vtkmodules.vtkCommonCore import vtkStringArray  # see _silence_vtk

    # VTK puts x and y labels at round values itself; on the short z axis it would crowd ~8 of them, so z gets a
    # few round values of our own (the box's z extent widened to them) that carry the unit, as VTK draws no z
    # title there
    z_ticks = _outward_ticks(float(mesh.points[:, 2].min()) * 1e6, float(mesh.points[:, 2].max()) * 1e6)
    bounds = list(poly.bounds)
    bounds[4:] = [z_ticks[0] * 1e-3 * factor, z_ticks[-1] * 1e-3 * factor]
    axes = plotter.show_bounds(
        bounds=bounds,
        axes_ranges=[*bounds[:4], z_ticks[0], z_ticks[-1]],
        xtitle="x (mm)",
        ytitle="y (mm)",
        ztitle=" ",
        color="black",
        location="outer",
        font_size=12,
        use_2d=True,
    )
    axes.SetAxisLabels(0, None)
    axes.SetAxisLabels(1, None)
    z_labels = vtkStringArray()  # built by hand: pyvista's converter refuses the non-ASCII "µ"
    for value in z_ticks:
        z_labels.InsertNextValue(f"{value:.3g} µm")
    axes.SetAxisLabels(2, z_labels)
