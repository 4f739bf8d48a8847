"""The tables of the models and outputs of a run: the wear law (``[wear]``), the FE plate and its coupling to the
impact (``[fem]``) and the outputs (``[output]``). SI units; the defaults are those of ``impactwear run``
(:mod:`wear.case.tables`).
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import ClassVar

from wear.case.choices import COUPLINGS, FEM_MODELS
from wear.case.schema import Table, key
from wear.law import WearLaw
from wear.laws.combined import CUTTING_LAWS
from wear.laws.registry import LAWS, wear_keys
from wear.pressure import PRESSURE_SOURCES
from wear.slip import SPEED_MODELS

__all__ = ["WearSpec", "FemSpec", "OutputSpec"]


@dataclass(frozen=True)
class WearSpec(Table):
    """The wear law (:mod:`wear.laws`): ``law`` by name (one of :data:`wear.laws.registry.LAWS`); the local law (errata
    equation 15, dw/dt = K p^α v^β): ``K`` (m^(1−β) s^(β−1) Pa^(−α)), ``alpha``, ``beta``, the ``pressure`` source along
    the impact, the sliding ``speed`` model, ``points_across`` grid points across the largest contact diameter; Finnie's
    cutting: ``cutting_fraction``, ``force_ratio``, ``depth_ratio`` (and the plate's ``hardness``); Bitter's deformation
    wear: ``deformation_factor`` ε (J/m³); ``combined``: the ``cutting`` law plus deformation; the correlations:
    ``oka_e90``, ``oka_k2``, ``dnv_K``, ``dnv_n``."""

    table: ClassVar[str] = "wear"
    law: str = key(str, "local", "wear law (wear.laws)", choices=LAWS)
    K: float = key(float, 1e-11, "wear coefficient of Eq. 15", "m^(1-beta) s^(beta-1) Pa^(-alpha)", low=0.0, high=1e-3)
    alpha: float = key(float, 1.0, "pressure exponent of Eq. 15", low=0.0, high=4.0)
    beta: float = key(float, 0.3, "sliding-speed exponent of Eq. 15", low=0.0, high=4.0)
    pressure: str = key(str, "fe", "contact pressure source", choices=PRESSURE_SOURCES)
    speed: str = key(
        str, "local", "sliding speed: the FE surface's local slip, or the contact point's", choices=SPEED_MODELS
    )
    points_across: int = key(int, 64, "wear grid points across the largest contact diameter", low=40, high=2000)
    cutting: str = key(str, "local", "the cutting law of the combined law", choices=CUTTING_LAWS)
    cutting_fraction: float = key(
        float, 0.5, "Finnie's fraction of particles cutting ideally, c", low=0.0, low_open=True, high=10.0
    )
    force_ratio: float = key(
        float, 2.0, "Finnie's ratio of vertical to horizontal force on the particle, K", low=0.1, high=20.0
    )
    depth_ratio: float = key(float, 2.0, "Finnie's ratio of contact depth to cut depth, psi", low=0.1, high=20.0)
    deformation_factor: float | None = key(
        float,
        None,
        "Bitter's deformation wear factor epsilon",
        "J/m^3",
        low=1e3,
        high=1e15,
        optional=True,
        absent="none: the deformation and combined laws need it",
    )
    oka_e90: float | None = key(
        float,
        None,
        "Oka's erosion ratio at normal incidence, 104 m/s, 326 um",
        "kg/kg",
        low=0.0,
        low_open=True,
        high=1.0,
        optional=True,
        absent="65e-9 m^3/kg x (Hv/GPa)^-0.12 x plate density (Oka & Yoshida 2005)",
    )
    oka_k2: float | None = key(
        float, None, "Oka's speed exponent", low=0.5, high=5.0, optional=True, absent="2.3 Hv^0.038"
    )
    dnv_K: float = key(
        float, 2e-9, "DNV-RP-O501 material constant K", "(kg/kg) (m/s)^-n", low=0.0, low_open=True, high=1.0
    )
    dnv_n: float = key(float, 2.6, "DNV-RP-O501 speed exponent n", low=0.5, high=5.0)

    def check(self) -> None:
        self.wear_law()
        if self.speed == "local" and self.pressure != "fe":
            raise ValueError(
                f"wear.speed='local' is the FE plate surface's slip, read with the plate's pressure: it needs "
                f"wear.pressure='fe' (got {self.pressure!r}); with a closed-form pressure set wear.speed='sliding' "
                "(the impact's contact-point slip, the paper's) or 'kinematic'"
            )

    def check_deformation_factor(self, fitted: bool) -> None:
        """A one-line ``ValueError`` if the law needs Bitter's ε and the case gives none, unless a calibration
        ``fitted`` it (it then starts from the data)."""
        reads = "deformation_factor" in wear_keys(self.law, self.values())
        if reads and self.deformation_factor is None and not fitted:
            raise ValueError(
                f"wear.deformation_factor=None: wear.law={self.law!r} needs Bitter's deformation wear "
                "factor epsilon (J/m^3)"
            )

    def wear_law(self) -> WearLaw:
        """The local law's :class:`wear.WearLaw` (Eq. 15) of this table."""
        try:
            return WearLaw(K=self.K, alpha=self.alpha, beta=self.beta)
        except ValueError as exc:
            raise ValueError(f"wear.{exc}") from None


@dataclass(frozen=True)
class FemSpec(Table):
    """The FE plate: ``model`` ("axisymmetric": the (r, z) frictionless plate; "3d": the half block with Coulomb
    friction, coupled after the axisymmetric one), ``coupling`` ("two-way": the impact runs on the FE plate's own
    force law; "one-way": the FE plate follows the impact's overlap; "none"), its ``tolerance`` and
    ``max_iterations``, the FE increments ``load_steps`` and ``unload_steps``, the ``overshoot`` of the single FE
    loading past the estimated maximum overlap, ``mesh_scale`` (multiplies the FE element sizes; > 1 coarser; the
    3-D plate has 8/mesh_scale elements across the contact radius), and the 3-D plate's ``solid_iterations``,
    ``solid_load_steps`` and ``solid_unload_steps``."""

    table: ClassVar[str] = "fem"
    coupling: str = key(str, "two-way", "impact-FE coupling (two-way = the FE normal law)", choices=COUPLINGS)
    tolerance: float = key(float, 0.005, "coupling tolerance on the max overlap change (relative)", low=1e-6, high=0.2)
    max_iterations: int = key(int, 8, "most impact runs of the coupling", low=2, high=50)
    load_steps: int = key(int, 16, "FE increments of the loading", low=2, high=2000)
    unload_steps: int = key(int, 8, "FE increments of the unloading", low=1, high=2000)
    overshoot: float = key(float, 0.1, "FE loading past the estimated max overlap (relative)", low=0.02, high=2.0)
    mesh_scale: float = key(float, 2.0, "FE element size factor (> 1 coarser)", low=0.25, high=8.0)
    model: str = key(
        str,
        "axisymmetric",
        "FE plate: axisymmetric (r, z), or 3d (impactwear run and repeat: half block, "
        "Coulomb friction; its impact runs on the plate's tangential law, mindlin_deresiewicz)",
        choices=FEM_MODELS,
    )
    solid_iterations: int = key(int, 3, "most 3-D plate cycles of the 3-D coupling", low=1, high=20)
    solid_load_steps: int = key(int, 10, "3-D plate increments of the loading", low=2, high=200)
    solid_unload_steps: int = key(int, 6, "3-D plate increments of the unloading", low=1, high=200)


@dataclass(frozen=True)
class OutputSpec(Table):
    """Outputs: ``figures`` (PNG), ``render`` (3-D view), ``plate_mesh`` (a user's meshio plate block to deform
    instead of the generated one; "" = generate), ``block_thickness`` (m) of the generated block."""

    table: ClassVar[str] = "output"
    figures: bool = key(bool, True, "write the PNG figures")
    render: bool = key(bool, True, "write the rendered 3-D view (needs EGL or OSMesa)")
    plate_mesh: str = key(str, "", 'meshio plate block to deform instead of the generated one ("": generate)')
    block_thickness: float = key(
        float, 2e-3, "thickness of the generated plate block", "m", low=0.0, low_open=True, high=1.0
    )

    def check(self) -> None:
        if self.plate_mesh and not os.path.isfile(self.plate_mesh):
            raise ValueError(f"output.plate_mesh={self.plate_mesh!r} is not a file: give a meshio-readable plate mesh")
