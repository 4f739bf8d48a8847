"""The reduced 3-D plate the test suite runs, in one place: the default 3-D mesh (``fem.mesh_scale`` 2, 4 elements
across the contact radius) with 5 + 3 increments and at most 2 coupling cycles (the default: 10 + 6, 3 cycles), and
the repeated-impact cases built on it."""

from wear.case import JOBS

#: ``[fem]`` of the reduced 3-D plate.
REDUCED_3D = {"model": "3d", "mesh_scale": 2.0, "solid_load_steps": 5, "solid_unload_steps": 3, "solid_iterations": 2}


def repeat_case(angle: float, friction: float, impacts: int, geometry_update: bool = False, **fem):
    """``impactwear repeat``'s default case on the reduced 3-D plate (``fem`` keys laid over it): ``impacts`` at
    ``angle`` (degrees from the normal) with Coulomb ``friction``, the wear moving the surface or not
    (``geometry_update``), no figures or rendering."""
    return (
        JOBS["repeat"]
        .default_case()
        .with_(
            impact={"angle": angle, "friction": friction},
            fem={**REDUCED_3D, **fem},
            repeat={"impacts": impacts, "geometry_update": geometry_update},
            output={"render": False, "figures": False},
        )
    )


def repeat_table(result) -> str:
    """The per-impact numbers of a repeat (for the log of a run with ``-rA``)."""
    lines = ["impact dent_m pile_up_m plastic_work_J wear_m3 e_n e_t wall_s"]
    for r in result.records:
        lines.append(
            f"{r.first} {r.dent_depth:.5g} {r.pile_up_height:.5g} {r.plastic_work:.5g} {r.wear_volume:.5g} "
            f"{r.normal_restitution:.5g} {r.tangential_restitution:.5g} {r.wall_time:.1f}"
        )
    return "\n".join(lines)
