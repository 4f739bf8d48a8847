"""The memory of an erosion's patch arrays: :func:`patch_memory` estimates it, :func:`check_patch_memory` refuses a
grid and a number of saved frames that would need more than :func:`wear.case.budget.memory_budget` before any work
(bytes).

Measured on the default erode case (10 frames, 2 cores), resident memory above the interpreter's / the estimate: grid
1024 0.17 / 0.22 GB, 2048 0.72 / 0.87 GB, 4096 2.9 / 3.5 GB; 1024 with 100 frames 1.65 / 1.73 GB.
"""

from __future__ import annotations

from wear.case.budget import fitting_value, memory_budget

__all__ = ["patch_memory", "check_patch_memory"]


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
    :func:`wear.case.budget.memory_budget`, with the largest grid and number of frames that fit."""
    limit = memory_budget()
    need = patch_memory(grid, frames, runs)
    if need <= limit:
        return
    most_grid = fitting_value(lambda g: patch_memory(g, frames, runs), limit, 1, grid)
    most_frames = fitting_value(lambda f: patch_memory(grid, f, runs), limit, 1, frames)
    fix = f"give {grid_name} <= {most_grid}" + (f" or {frames_name} <= {most_frames}" if most_frames else "")
    runs_text = f" and {runs} stream angles" if runs > 1 else ""
    raise ValueError(
        f"{grid_name}={grid} with {frames_name}={frames}{runs_text} needs ~{need / 1e9:.3g} GB for the patch arrays "
        f"(({runs + 1} x frames + 6) x grid^2 x 8 B): at most {limit / 1e9:.3g} GB on this machine; {fix}"
    )
