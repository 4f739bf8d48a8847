"""The combined law: a cutting law (:data:`CUTTING_LAWS`, the case key ``wear.cutting``) plus Bitter's deformation
wear (:mod:`wear.laws.deformation`), each share reported. SI units.
"""

from __future__ import annotations

from contact import ImpactResult
from contact.checks import check_choice
from wear.laws import deformation, finnie, local
from wear.laws.declaration import Constants, Law

__all__ = ["CUTTING_LAWS", "LAW"]

#: The cutting laws the combined law may add to deformation, by name.
CUTTING_LAWS = {law.name: law for law in (local.LAW, finnie.LAW)}


def _cutting(constants: Constants) -> Law:
    """Its cutting law, ``constants["cutting"]``, or a one-line ``ValueError``."""
    return CUTTING_LAWS[check_choice("wear.cutting", constants.get("cutting"), CUTTING_LAWS)]


def _parts(constants: Constants) -> tuple[Law, ...]:
    """The laws it adds: its cutting law and deformation."""
    return _cutting(constants), deformation.LAW


def _volumes(
    constants: Constants, impact: ImpactResult, *, local: float | None, plate_work: float | None
) -> dict[str, float]:
    """The cutting and the deformation wear of one impact."""
    cutting = _cutting(constants).volumes(constants, impact, local=local, plate_work=plate_work)
    return {
        "cutting": cutting["cutting"],
        "deformation": deformation.deformation_of(constants, impact, plate_work, "combined"),
    }


LAW = Law(
    name="combined",
    description="a cutting law (local or finnie) + deformation",
    volumes=_volumes,
    inputs=("cutting",),
    parts=_parts,
)
