"""The output folder of ``impactwear repeat`` (:func:`wear.repeat`), written atomically by the one writer (SI units):

- ``repeat.csv``: one row per computed impact or cycle-jump block (columns with units,
  :data:`wear.chain.records.CSV_COLUMNS`); ``summary.json`` (case, results, notes, wall time, and
  ``halfspace_check``: the last pressure against the half-space solution, :mod:`wear.chain.check`; null on the 3-D
  plate, whose dented surface is not axisymmetric);
- ``repeat.pvd`` + ``frames/plate_NNNNNN.vtu``: the FE mesh after each saved computed impact (time = impact
  number; point data ``displacement_m``, ``wear_depth_m``, ``on_surface``; cell data ``equivalent_plastic_strain``,
  ``von_mises_stress_Pa``; on the 3-D plate the whole plate, :meth:`fem.solid.plate.SolidPlate.to_meshio`, without
  ``wear_depth_m`` and ``on_surface``);
- ``wear_map.npz``: the cumulative 2-D wear map (:func:`wear_map_arrays`: ``x_m``, ``y_m``, ``wear_depth_m``);
  ``repeat.png`` (with
  ``output.figures``): dent, pile-up, wear, plastic work, restitution, pressure and Δᾱ against the impact number.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from wear.app.figures.repeat import plot_repeat
from wear.app.outputs.writer import versions, write_csv, write_mesh, write_npz, write_pvd, write_summary
from wear.case import JOBS
from wear.chain.records import PlateState, RepeatResult
from wear.integrate import WearMap

__all__ = ["ENTRIES", "RepeatWriter", "wear_map_arrays"]

#: What ``impactwear repeat`` may write in its folder (checked against the folder before any work).
ENTRIES = ("frames", "repeat.pvd", "repeat.csv", "wear_map.npz", "summary.json", "repeat.png")


def wear_map_arrays(wm: WearMap) -> dict[str, np.ndarray]:
    """The arrays of ``wear_map.npz``: ``x_m`` (nx,), ``y_m`` (ny,) and ``wear_depth_m`` (ny, nx), the worn depth
    (m, positive into the plate) at (x_m[i], y_m[j]) in ``wear_depth_m[j, i]``."""
    return {"x_m": wm.x, "y_m": wm.y, "wear_depth_m": wm.depth}


class RepeatWriter:
    """Writes a repeated-impact run into the (temporary) folder ``out``: :meth:`on_computed` saves the FE mesh of
    every ``save_every``-th computed impact (and the first) as the run goes, :meth:`finish` the rest."""

    def __init__(self, out: Path, save_every: int) -> None:
        self.out = out
        self.save_every = save_every
        self.entries: list[tuple[float, str]] = []
        self.computed = 0
        (out / "frames").mkdir()

    def _frame(self, impact: int, plate: PlateState) -> None:
        name = f"frames/plate_{impact:06d}.vtu"
        write_mesh(self.out / name, plate.to_meshio())
        self.entries.append((float(impact), name))

    def on_computed(self, impact: int, plate: PlateState) -> None:
        """After each computed impact (``impact``: its number)."""
        self.computed += 1
        if self.save_every and (self.computed == 1 or self.computed % self.save_every == 0):
            self._frame(impact, plate)

    def finish(self, result: RepeatResult, notes: list[str]) -> dict:
        """The last frame, the .pvd, repeat.csv, wear_map.npz, summary.json and the figure; returns the summary."""
        case, out = result.case, self.out
        last = result.records[-1].last
        if case.repeat.save_every and (not self.entries or self.entries[-1][0] != last):
            self._frame(last, result.plate)
        if self.entries:
            write_pvd(out / "repeat.pvd", self.entries)
        columns = result.columns()
        write_csv(out / "repeat.csv", columns)
        wm = result.wear
        write_npz(out / "wear_map.npz", wear_map_arrays(wm))
        summary = {
            "case": case.to_dict(JOBS["repeat"].tables),
            "fem_model": case.fem.model,
            "versions": versions(),
            **result.summary(),
        }
        summary["halfspace_check"] = result.halfspace_check
        summary["notes"] = list(dict.fromkeys([*notes, *result.notes]))
        summary = write_summary(out / "summary.json", summary)
        if case.output.figures:
            plot_repeat(
                columns,
                out / "repeat.png",
                title=f"{case.repeat.impacts} impacts at one site",
                shakedown_impact=result.shakedown_impact,
                tolerance=summary["shakedown_tolerance_strain"],
            )
        return summary
