"""The whole case, :class:`Case`: one frozen table (:mod:`wear.case.tables`) per TOML table, built over a base case
from tables of values, checked key by key and against the Hertz contact time of its impact. SI units; angles in
degrees from the plate normal.
"""

from __future__ import annotations

import difflib
import math
from dataclasses import dataclass, field, fields, replace
from typing import Any

from contact import effective_modulus
from contact.theory import hertz_impact, speed_components, sphere_mass
from contact.timestep import check_time_step
from wear.case.impact_tables import BallSpec, ImpactSpec, PlateSpec
from wear.case.job_tables import CalibrationSpec, ErosionSpec, RepeatSpec, WallSpec
from wear.case.model_tables import FemSpec, OutputSpec, WearSpec
from wear.case.tables import TABLES

__all__ = ["Case"]


@dataclass(frozen=True)
class Case:
    """A whole case: one frozen table per TOML table (see each class for its keys, units and defaults).

    ``Case()`` is the default case of ``impactwear run`` (:mod:`wear.case.jobs` gives every job's default);
    :meth:`from_dict` lays tables of values over a base case (keys left out keep the base's values), checking every
    key; :meth:`with_` replaces some keys.

    Examples
    --------
    Replacing one key keeps every other key of the base case; a case is frozen, so the base is unchanged:

    >>> case = Case().with_(impact={"speed": 2.0, "angle": 45.0})
    >>> case.impact.speed, case.impact.angle, case.impact.friction == Case().impact.friction, Case().impact.speed
    (2.0, 45.0, True, 3.0)
    >>> case.ball.material() == Case().ball.material()  # the contact.Material of [ball]
    True
    """

    ball: BallSpec = field(default_factory=BallSpec)
    plate: PlateSpec = field(default_factory=PlateSpec)
    impact: ImpactSpec = field(default_factory=ImpactSpec)
    wear: WearSpec = field(default_factory=WearSpec)
    fem: FemSpec = field(default_factory=FemSpec)
    output: OutputSpec = field(default_factory=OutputSpec)
    erosion: ErosionSpec = field(default_factory=ErosionSpec)
    repeat: RepeatSpec = field(default_factory=RepeatSpec)
    calibration: CalibrationSpec = field(default_factory=CalibrationSpec)
    wall: WallSpec = field(default_factory=WallSpec)

    def __post_init__(self) -> None:
        for f in fields(self):
            if not isinstance(getattr(self, f.name), TABLES[f.name]):
                raise ValueError(f"[{f.name}]={getattr(self, f.name)!r} is not a {TABLES[f.name].__name__}")
        self.wear.check_deformation_factor(self.calibration.fits("deformation_factor"))
        self.check_time_step()

    def check_time_step(self, histories: bool = False) -> None:
        """A one-line ``ValueError`` naming ``impact.time_step`` if the given time step is not within [t_c/2e7, t_c/10]
        of the Hertz contact time t_c of the case's ball, plate and normal speed (t_c/2e6 for an impact that keeps
        its time ``histories``): :func:`contact.timestep.check_time_step`, checked when the case is built so that a
        time step that would run for hours is refused before any work."""
        if self.impact.time_step is None:
            return
        ball, plate, radius = self.ball.material(), self.plate.material(), self.ball.radius
        normal_speed, _ = speed_components(self.impact.speed, self.impact.angle)
        contact_time = hertz_impact(
            sphere_mass(radius, ball.density), radius, effective_modulus(ball, plate), normal_speed
        ).contact_time
        if math.isfinite(contact_time) and contact_time > 0.0:
            check_time_step(self.impact.time_step, contact_time, histories=histories, name="impact.time_step")

    @classmethod
    def default(cls) -> Case:
        """The default case of ``impactwear run`` (the same as ``Case()``)."""
        return cls()

    @classmethod
    def from_dict(cls, tables: dict[str, Any], base: Case | None = None) -> Case:
        """A case from a dict of tables (e.g. a TOML document) laid over ``base`` (default ``Case()``); unknown
        tables and keys and bad values are one-line ``ValueError`` naming ``table.key``."""
        base = cls() if base is None else base
        return base.with_tables(cls.tables_from_dict(tables, base))

    @staticmethod
    def tables_from_dict(tables: dict[str, Any], base: Case) -> dict[str, Any]:
        """The checked tables (name → table) of a dict of tables laid over ``base``'s, each checked on its own
        (unknown tables and keys, with the closest known name, and bad values: one-line ``ValueError`` naming
        ``table.key``); :meth:`with_tables` makes them a case."""
        if not isinstance(tables, dict):
            raise ValueError(f"case={tables!r} is not a table of tables")
        parts = {}
        for name, values in tables.items():
            if name not in TABLES:
                raise ValueError(
                    f"[{name}] is not a known case table{_closest(name, TABLES, '[{}]')}: known tables are "
                    f"{', '.join(TABLES)}"
                )
            if not isinstance(values, dict):
                raise ValueError(f"{name}={values!r} is not a table: write it as [{name}]")
            known = TABLES[name].keys()
            for k in values:
                if k not in known:
                    raise ValueError(
                        f"{name}.{k} is not a known key{_closest(k, known, name + '.{}')}: keys of [{name}] are "
                        f"{', '.join(known)}"
                    )
            parts[name] = replace(getattr(base, name), **values)
        return parts

    def with_tables(self, parts: dict[str, Any]) -> Case:
        """A copy with whole tables replaced (checked tables of :meth:`tables_from_dict`); the whole case is
        checked again (its time step)."""
        return replace(self, **parts)

    def to_dict(self, tables: tuple[str, ...] | None = None) -> dict[str, dict[str, Any]]:
        """Tables of values (None for absent optional keys), all tables or only ``tables``."""
        names = [f.name for f in fields(self)] if tables is None else tables
        return {name: getattr(self, name).values() for name in names}

    def with_(self, **tables: dict[str, Any]) -> Case:
        """A copy with some keys replaced, e.g. ``case.with_(impact={"speed": 2.0})`` (checked as in
        :meth:`from_dict`)."""
        return Case.from_dict(tables, base=self)

    def impact_arguments(self, **overrides: Any) -> dict[str, Any]:
        """Keyword arguments of :func:`contact.simulate_impact` for this case's ``[ball]``, ``[plate]`` and
        ``[impact]`` (``overrides`` replace some; with ``history``/``histories`` the time step is checked for the
        memory of the histories, :meth:`check_time_step`)."""
        imp = self.impact
        args = dict(
            radius=self.ball.radius,
            ball=self.ball.material(),
            plate=self.plate.material(),
            speed=imp.speed,
            angle=imp.angle,
            friction=imp.friction,
            restitution=imp.restitution,
            normal_model=imp.normal_model,
            tangential_model=imp.tangential_model,
            limiting_pressure=imp.limiting_pressure,
            scheme=imp.scheme,
            time_step=imp.time_step,
        )
        args.update(overrides)
        if args.get("history") or args.get("histories"):
            self.check_time_step(histories=True)
        return args


def _closest(name: str, known: Any, form: str) -> str:
    """`` (did you mean X?)`` with the known name closest to a mistyped ``name`` written in ``form``, or ""."""
    match = difflib.get_close_matches(name, list(known), n=1)
    return f" (did you mean {form.format(match[0])}?)" if match else ""
