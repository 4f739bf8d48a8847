"""The memory of an erosion's patch arrays: :func:`patch_memory` estimates it, :func:`check_patch_memory` refuses a
grid and a number of saved frames that would need more than :data:`MAX_PATCH_MEMORY` before any work (bytes)."""

from __future__ import annotations

import math

__all__ = ["MAX_PATCH_MEMORY", "patch_memory", "check_patch_memory"]

#: Largest estimated memory of the patch arrays (:func:`patch_memory`, B): 2 GB, refused up front rather than found
#: out as a swapping machine. Measured on the default erode case (10 frames, 2 cores), resident memory above the
#: interpreter's / the estimate: grid 1024 0.17 / 0.22 GB, 2048 0.72 / 0.87 GB, 4096 2.9 / 3.5 GB; 1024 with 100
#: frames 1.65 / 1.73 GB. A fixed bound, not a share of this machine's memory, so that a case valid on one machine is
#: valid on every one.
MAX_PATCH_MEMORY = 2e9


def patch_memory(grid: int, frames: int, runs: int = 1) -> float:
    """Estimated peak memory (B) of the patch arrays of ``runs`` erosions of a ``grid`` × ``grid`` patch saving
    ``frames`` surfaces each, all results kept (as :func:`wear.erosion.erode_angles` does): every result's frames,
    the running erosion's list of frames before it stacks them, and six more grid² arrays (wear, relief, the surface
    and the slope's temporaries), float64."""
    return ((runs + 1) * frames + 6.0) * float(grid) ** 2 * 8.0


def check_patch_memory(
    grid: int, frames: int, runs: int = 1, *, grid_name: str = "grid", frames_name: str = "frames"
) -> None:
    """A one-line ``ValueError`` naming ``grid_name`` (and ``frames_name``) if :func:`patch_memory` exceeds
    :data:`MAX_PATCH_MEMORY`."""
    need = patch_memory(grid, frames, runs)
    if need <= MAX_PATCH_MEMORY:
        return
    per_node = MAX_PATCH_MEMORY / (8.0 * float(grid) ** 2)
    most_frames = int((per_node - 6.0) // (runs + 1))
    most_grid = math.isqrt(int(MAX_PATCH_MEMORY / (8.0 * ((runs + 1) * frames + 6.0))))
    fix = f"give {grid_name} <= {most_grid}" + (f" or {frames_name} <= {most_frames}" if most_frames >= 1 else "")
    runs_text = f" and {runs} stream angles" if runs > 1 else ""
    raise ValueError(
        f"{grid_name}={grid} with {frames_name}={frames}{runs_text} needs ~{need / 1e9:.3g} GB for the patch arrays "
        f"(({runs + 1} x frames + 6) x grid^2 x 8 B): at most {MAX_PATCH_MEMORY / 1e9:g} GB; {fix}"
    )
