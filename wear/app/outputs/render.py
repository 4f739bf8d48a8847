"""Headless 3-D view of the deformed plate surface (pyvista, off-screen).

Off-screen rendering needs an OpenGL implementation without a display: EGL (Mesa's
``libEGL_mesa`` with the ``libgl1-mesa-dri`` drivers) or OSMesa. Where neither is installed, VTK
may abort the whole process instead of raising, so :func:`rendering_available` looks for the
libraries first and the run skips the view with a one-line hint naming the Debian packages.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import os
from pathlib import Path

import meshio
import numpy as np

from wear.app.outputs.writer import atomic_write

__all__ = ["DEBIAN_PACKAGES", "rendering_available", "render_surface", "default_exaggeration"]

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


def default_exaggeration(mesh: meshio.Mesh) -> float:
    """Depth scale factor that draws the deepest point at 15% of the surface's in-plane span (rounded)."""
    span = float(np.ptp(mesh.points[:, :2], axis=0).max())
    depth = float(np.max(np.abs(mesh.points[:, 2])))
    if depth <= 0.0:
        return 1.0
    raw = 0.15 * span / depth
    exponent = np.floor(np.log10(raw))
    mantissa = raw / 10**exponent
    nice = 1.0 if mantissa < 2 else 2.0 if mantissa < 5 else 5.0
    return float(max(nice * 10**exponent, 1.0))


def render_surface(
    mesh: meshio.Mesh,
    path: str | os.PathLike,
    *,
    scalar: str = "total_depth",
    exaggeration: float | None = None,
    window_size: tuple[int, int] = (1200, 800),
    title: str = "",
) -> Path:
    """Render a surface mesh (z = −depth, m) to a PNG with z scaled by ``exaggeration`` (stated on the image).

    Coloured by point data ``scalar`` in µm. Raises ``RuntimeError`` with the install hint if
    off-screen rendering is unavailable (check :func:`rendering_available` first to skip quietly).
    """
    ok, why = rendering_available()
    if not ok:
        raise RuntimeError(why)
    import pyvista as pv  # heavy (VTK), and only where rendering is available

    factor = default_exaggeration(mesh) if exaggeration is None else float(exaggeration)
    if factor <= 0:
        raise ValueError(f"exaggeration={factor:g} is out of range: must be > 0")
    cells = mesh.cells_dict
    if "quad" in cells:
        faces = np.hstack([np.full((len(cells["quad"]), 1), 4), cells["quad"]]).ravel()
    elif "triangle" in cells:
        faces = np.hstack([np.full((len(cells["triangle"]), 1), 3), cells["triangle"]]).ravel()
    else:
        raise ValueError("mesh has no quad or triangle cells: render_surface needs a surface mesh")
    # in-plane coordinates in mm, depth in mm × factor, so the camera sees a unit-sized scene
    points = np.asarray(mesh.points, dtype=float) * 1e3
    points[:, 2] *= factor
    poly = pv.PolyData(points, faces)
    values = np.asarray(mesh.point_data.get(scalar, -mesh.points[:, 2]), dtype=float) * 1e6
    poly.point_data[f"{scalar} (µm)"] = values
    plotter = pv.Plotter(off_screen=True, window_size=list(window_size))
    plotter.set_background("white")
    plotter.add_mesh(
        poly,
        scalars=f"{scalar} (µm)",
        cmap="viridis",
        smooth_shading=True,
        scalar_bar_args={"title": f"{scalar.replace('_', ' ')} (µm)", "color": "black", "vertical": True},
    )
    plotter.add_text(
        f"{title + '   ' if title else ''}depth exaggerated ×{factor:g} (x, y in mm)",
        position="upper_left",
        font_size=12,
        color="black",
    )
    plotter.add_axes(color="black", xlabel="x", ylabel="y", zlabel="z")
    plotter.camera_position = "iso"
    plotter.camera.elevation = -10
    plotter.camera.zoom(1.1)
    try:
        return atomic_write(path, lambda name: plotter.screenshot(name), mode="path")
    finally:
        plotter.close()
