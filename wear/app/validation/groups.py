"""The check groups of ``impactwear validate``, listed by area: each group is a function ``group(quick: bool) ->
list[Check]`` of :mod:`wear.app.validation.chung_ooi`, ``.contact``, ``.fem``, ``.laws``, ``.wall`` or ``.wear``,
imported here by name. A new group is written in the module of its subject and added to its area's tuple below.
"""

from __future__ import annotations

from collections.abc import Callable

from wear.app.validation.checks import AREAS, Check, Group
from wear.app.validation.chung_ooi import chung_ooi_test2, chung_ooi_test3, chung_ooi_test4, maw_barber_fawcett
from wear.app.validation.contact import (
    closed_forms,
    contact_halfspace,
    integration_and_energy,
    kharaz_2001,
    tabulated_law,
    thornton_1997,
)
from wear.app.validation.fem import (
    fem_elastic_plastic,
    fem_elastic_reload,
    fem_first_yield,
    fem_hertz,
    fem_worn_surface,
)
from wear.app.validation.laws import (
    calibration_round_trip,
    deformation_wear_onset,
    laws_against_measured_trends,
    wear_law_closed_forms,
)
from wear.app.validation.wall import wall_against_openfoam, wall_uniform_stream
from wear.app.validation.wear import (
    coupling,
    erosion_flux_balance,
    fe_table_source,
    hertz_impact_profile,
    impulse_identity,
    sliding_and_additivity,
    steady_track,
)

__all__ = ["BY_AREA", "CONTACT", "FEM", "GROUPS", "WEAR"]

GroupFunction = Callable[[bool], list[Check]]

#: The groups of the impact engine and its closed forms: Chung & Ooi's (2011) benchmark tests, then the others.
CONTACT: tuple[GroupFunction, ...] = (
    chung_ooi_test2,
    chung_ooi_test3,
    chung_ooi_test4,
    maw_barber_fawcett,
    thornton_1997,
    kharaz_2001,
    integration_and_energy,
    closed_forms,
    tabulated_law,
    contact_halfspace,
)

#: The groups of the axisymmetric FE plate.
FEM: tuple[GroupFunction, ...] = (
    fem_hertz,
    fem_first_yield,
    fem_elastic_plastic,
    fem_worn_surface,
    fem_elastic_reload,
)

#: The groups of the wear laws, their calibration, a component's wall and Eq. 15 over the contact patch.
WEAR: tuple[GroupFunction, ...] = (
    wear_law_closed_forms,
    deformation_wear_onset,
    calibration_round_trip,
    laws_against_measured_trends,
    wall_against_openfoam,
    wall_uniform_stream,
    steady_track,
    impulse_identity,
    hertz_impact_profile,
    sliding_and_additivity,
    fe_table_source,
    erosion_flux_balance,
    coupling,
)


#: Area → its group functions, in the order of :data:`wear.app.validation.checks.AREAS`.
BY_AREA: dict[str, tuple[GroupFunction, ...]] = {"contact": CONTACT, "fem": FEM, "wear": WEAR}

#: Group name (its function's name) → :class:`Group`, area by area (what ``impactwear validate --list`` prints).
GROUPS: dict[str, Group] = {
    function.__name__: Group(function.__name__, area, function) for area in AREAS for function in BY_AREA[area]
}
