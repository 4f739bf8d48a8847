"""The FE plate of a case along a load–unload path: force–overlap, pressures, first yield and the dent (SI units).

The ball and the plate are the case's ``[ball]`` and ``[plate]`` (an elastic ball enters through E*, see
:func:`fem.indent`), the increments ``fem.load_steps`` and ``fem.unload_steps``, the mesh that of
``fem.mesh_scale``. The path loads to ``max_overlap`` (m), or to ``max_force`` (N: the overlap is found on the
loading), or by default to w = δ/δ_c = 20 (a plate that yields) or a = 0.05 R (an elastic one), then unloads to
zero.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np
from skfem import MeshTri

import fem
from contact import Material, effective_modulus
from contact.checks import check_number
from contact.theory import PAPER_YIELD_COEFFICIENT, FirstYield, first_yield, hertz_overlap
from fem import IndentationResult
from fem.axisymmetric.result import join
from wear.case import Case
from wear.case.check import check_work
from wear.chain.plate import case_mesh

__all__ = ["IndentRun", "indent_case", "largest_force", "DEFAULT_YIELD_MULTIPLE", "DEFAULT_ELASTIC_OVERLAP"]

#: Default depth of a plate that yields: w = δ/δ_c.
DEFAULT_YIELD_MULTIPLE = 20.0
#: Default depth of an elastic plate, × the ball radius (a = 0.05 R).
DEFAULT_ELASTIC_OVERLAP = 0.0025


@dataclass(frozen=True, eq=False)
class IndentRun:
    """An indentation of a case: ``result`` (:class:`fem.IndentationResult`, the load–unload path), the
    ``radius`` (m), the ``plate`` and ``ball`` (None: rigid) materials, the effective modulus ``e_star`` (Pa), the
    closed-form first yield with the exact C(ν) (``exact``) and with the paper's C = 1.6 (``paper``; both None for
    a plate that never yields), and the wall time ``seconds``."""

    result: IndentationResult
    radius: float
    plate: Material
    ball: Material | None
    e_star: float
    exact: FirstYield | None
    paper: FirstYield | None
    seconds: float

    def summary(self) -> dict:
        """The numbers of summary.json (SI units)."""
        res, plate, ball, fy = self.result, self.plate, self.ball, self.result.first_yield
        exact, paper = self.exact, self.paper
        peak = int(np.argmax(res.overlap))
        return {
            "fem_model": "axisymmetric",
            "radius_m": self.radius,
            "effective_modulus_Pa": self.e_star,
            "plate": {"E_Pa": plate.E, "nu": plate.nu, "yield_strength_Pa": plate.yield_strength},
            "ball": "rigid" if ball is None else {"E_Pa": ball.E, "nu": ball.nu},
            "max_overlap_m": float(res.overlap[peak]),
            "max_force_N": float(res.force[peak]),
            "max_contact_radius_m": float(res.contact_radius[peak]),
            "max_pressure_Pa": float(res.max_pressure.max()),
            "regime_at_max": res.regime[peak],
            "max_equivalent_plastic_strain": float(res.max_equivalent_plastic_strain.max()),
            "residual_depth_on_axis_m": float(res.residual_depth[0]),
            "fe_first_yield": None
            if fy is None
            else {"force_N": fy.force, "overlap_m": fy.overlap, "depth_m": fy.depth, "radius_m": fy.radius},
            "first_yield_exact_C": None
            if exact is None
            else {"C": exact.coefficient, "force_N": exact.force, "overlap_m": exact.overlap, "depth_m": exact.depth},
            "first_yield_paper_C_1.6": None if paper is None else {"force_N": paper.force, "overlap_m": paper.overlap},
            "steps": int(res.overlap.size),
            "newton_iterations": int(res.newton_iterations.sum()),
            "wall_time_s": self.seconds,
        }


def _overlap_for_force(force: float, radius: float, e_star: float, exact: FirstYield | None) -> float:
    """An overlap (m) past the one that carries ``force`` (N): Hertz, or for a plate past first yield Kogut & Etsion
    (2002) P/P_c = 1.03 w^1.425 (w ≤ 6) / 1.40 w^1.263, inverted, +25%."""
    if exact is None or force <= exact.force:
        return float(hertz_overlap(force, radius, e_star))
    ratio = force / exact.force
    w = (ratio / 1.03) ** (1 / 1.425)
    if w > 6.0:
        w = (ratio / 1.40) ** (1 / 1.263)
    return 1.25 * w * exact.overlap


def largest_force(case: Case) -> float:
    """The largest ``max_force`` (N) of :func:`indent_case` whose estimated overlap (Hertz, or Kogut & Etsion past
    first yield, +25%) stays within the ball radius that the FE plate is built for (bisection in log F to 1e-9)."""
    radius = case.ball.radius
    plate = case.plate.material()
    e_star = effective_modulus(case.ball.material(), plate)
    exact = None if plate.yield_strength is None else first_yield(radius, e_star, plate.yield_strength, plate.nu)
    # brackets in log F about Hertz's force at overlap R, 4/3 E* R^2 (Johnson 1985, Eq. 4.23)
    hertz = math.log(4.0 / 3.0 * e_star * radius**2)
    low, high = hertz - 80.0, hertz + 20.0
    while high - low > 1e-9:
        mid = 0.5 * (low + high)
        if _overlap_for_force(math.exp(mid), radius, e_star, exact) <= radius:
            low = mid
        else:
            high = mid
    return math.exp(low)


def indent_case(
    case: Case,
    *,
    max_overlap: float | None = None,
    max_force: float | None = None,
    hardening: float = 0.0,
    mesh: MeshTri | str | None = None,
) -> IndentRun:
    """Press the case's ball into its FE plate and unload (see the module docstring). ``hardening`` H (Pa): linear
    isotropic hardening; ``mesh``: a user mesh (or mesh file) instead of the case's."""
    if max_overlap is not None and max_force is not None:
        raise ValueError("max_overlap and max_force are both given: give one (m or N)")
    check_work(case, "indent")  # a runaway is refused before any work
    radius = case.ball.radius
    plate = case.plate.material()
    if plate.is_rigid:
        raise ValueError("plate.rigid=true: the FE plate needs a deformable plate (set plate.rigid = false)")
    ball_material = case.ball.material()
    ball = None if ball_material.is_rigid else ball_material
    e_star = effective_modulus(ball_material, plate)
    exact = paper = None
    if plate.yield_strength is not None:
        exact = first_yield(radius, e_star, plate.yield_strength, plate.nu)
        paper = first_yield(radius, e_star, plate.yield_strength, plate.nu, coefficient=PAPER_YIELD_COEFFICIENT)
    if max_overlap is not None:
        d_max = check_number("max_overlap", max_overlap, low=0.0, low_open=True, high=radius, units="m")
    elif max_force is not None:
        high = largest_force(case)
        max_force = check_number("max_force", max_force, low=0.0, low_open=True, high=high, units="N")
        d_max = _overlap_for_force(max_force, radius, e_star, exact)
    else:
        d_max = DEFAULT_YIELD_MULTIPLE * exact.overlap if exact is not None else DEFAULT_ELASTIC_OVERLAP * radius
    steps_in, steps_out = case.fem.load_steps, case.fem.unload_steps
    started = time.perf_counter()
    loading = d_max * np.linspace(0.0, 1.0, steps_in + 1)[1:] ** 1.5
    plate_mesh = case_mesh(case, d_max) if mesh is None else mesh
    if max_force is not None:
        load = fem.indent(radius, plate, loading, ball=ball, mesh=plate_mesh, hardening=hardening, keep_states=True)
        if load.force.max() < max_force:
            raise ValueError(
                f"max_force={max_force:g} is out of reach of the estimated path (max {load.force.max():g} N)"
            )
        d_max = float(np.interp(max_force, load.force, load.overlap))
        res = join(load, load.unload_from(d_max, steps_out), below=d_max)
    else:
        path = np.r_[loading, d_max * np.linspace(1.0, 0.0, steps_out + 1)[1:]]
        res = fem.indent(radius, plate, path, ball=ball, mesh=plate_mesh, hardening=hardening)
    return IndentRun(res, radius, plate, ball, e_star, exact, paper, time.perf_counter() - started)
