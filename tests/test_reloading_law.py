"""The dented plate's reloading law (:func:`fem.force_law.reloading_law`), the start of a repeated 3-D impact's
coupling, against Thornton's elastic–perfectly plastic contact (Thornton 1997, J. Appl. Mech. 64:383): loading
Hertzian to δ_y = (π p_y / 2E*)² R, then F = F_y + π p_y R (δ − δ_y); unloading from (δ*, F*) Hertzian with the
enlarged radius R_p = 4E* a_p³ / (3F*), a_p² = (2F* + F_y) / (2π p_y), to δ_p = δ* − a_p² / R_p. In that model a
dented plate reloads elastically along its unloading curve up to F* and yields again on the virgin line beyond."""

import math

import numpy as np
import pytest

from contact import Material, TabulatedLaw, effective_modulus, simulate_impact
from contact.theory import sphere_mass
from fem.force_law import reloading_law

BALL = Material(E=210e9, nu=0.3, density=7850.0, name="steel")
PLATE = Material(E=70e9, nu=0.33, density=2700.0, yield_strength=300e6)
RADIUS = 5e-3
E_STAR = effective_modulus(BALL, PLATE)
P_Y = 1.6 * PLATE.yield_strength  # a limiting pressure; any value above 0 defines the closed forms
DELTA_Y = (math.pi * P_Y / (2.0 * E_STAR)) ** 2 * RADIUS
F_Y = 4.0 / 3.0 * E_STAR * math.sqrt(RADIUS) * DELTA_Y**1.5


def thornton_loading(overlap):
    """Thornton's loading force (N) at ``overlap`` (m)."""
    d = np.asarray(overlap, float)
    hertz = 4.0 / 3.0 * E_STAR * math.sqrt(RADIUS) * np.minimum(d, DELTA_Y) ** 1.5
    return np.where(d <= DELTA_Y, hertz, F_Y + math.pi * P_Y * RADIUS * (d - DELTA_Y))


def thornton_unloading(top: float):
    """(R_p, δ_p) of Thornton's unloading from the overlap ``top`` (m)."""
    f_top = float(thornton_loading(top))
    a_p2 = (2.0 * f_top + F_Y) / (2.0 * math.pi * P_Y)
    r_p = 4.0 * E_STAR * a_p2**1.5 / (3.0 * f_top)
    return r_p, top - a_p2 / r_p


def thornton_law(top: float) -> TabulatedLaw:
    """Thornton's contact tabulated as a plate's law hands it to the impact: the loading branch to ``top`` plus a
    probe point 10% beyond (as :func:`fem.solid_coupling.plate_cycle`), the unloading curve from ``top``."""
    loading = np.r_[np.linspace(0.0, top, 81), 1.1 * top]
    r_p, residual = thornton_unloading(top)
    down = np.linspace(top, residual, 41)
    force = 4.0 / 3.0 * E_STAR * math.sqrt(r_p) * (down - residual) ** 1.5
    return TabulatedLaw(
        loading,
        thornton_loading(loading),
        np.sqrt(RADIUS * loading),
        np.array([top]),
        down[None, :],
        force[None, :],
        np.sqrt(r_p * (down - residual))[None, :],
    )


def test_reloading_law_is_thorntons_elastic_reloading_then_the_virgin_line():
    """Pointwise against Thornton's closed forms, a plate dented to δ* = 8 δ_y: from the new first contact δ' = 0
    (at the old δ_p) to δ* − δ_p the reloading force is the Hertzian unloading curve of radius R_p,
    (4/3) E* √R_p δ'^{3/2}; beyond, the virgin line F_y + π p_y R (δ_p + δ' − δ_y), also where the law continues it
    past the table it was given (to 3 × δ* − δ_p); the reloading unloads elastically from δ* − δ_p (residual 0)."""
    top = 8.0 * DELTA_Y
    r_p, residual = thornton_unloading(top)
    law = reloading_law(thornton_law(top))
    d, f = law.loading_overlap, law.loading_force
    assert d[0] == 0.0 and np.all(np.diff(d) > 0.0)
    elastic = d <= top - residual
    reload = 4.0 / 3.0 * E_STAR * math.sqrt(r_p) * d[elastic] ** 1.5
    np.testing.assert_allclose(f[elastic], reload, rtol=1e-9, atol=1e-9 * reload.max())
    np.testing.assert_allclose(f[~elastic], thornton_loading(residual + d[~elastic]), rtol=1e-9)
    assert d[-1] == pytest.approx(3.0 * (1.1 * top - residual), rel=1e-12)
    assert law.unloading_max_overlap[0] == pytest.approx(top - residual, rel=1e-12)
    assert law.residual_overlap[0] == pytest.approx(0.0, abs=1e-15)
    assert law.unloading_max_overlap[-1] == d[-1] and law.unloading_force[-1, 0] == pytest.approx(f[-1], rel=1e-12)


@pytest.mark.parametrize("fraction", [0.6, 1.0])
def test_impact_on_the_reloading_law_rebounds_elastically_below_the_dents_energy(fraction):
    """A ball that dented the plate at V₁ (Thornton's impact on its law) comes back at the speed e₁ V₁ (× √0.6
    and × 1): the reloading stores the energy the first rebound released, so up to that speed the second impact is
    elastic (Thornton's model: no new yield below F*). It rebounds with e_n = 1 within 1% and reaches, from the new
    first contact, the δ' where the Hertzian R_p curve stores ½ m v², (15 m v² / (16 E* √R_p))^{2/5}, within 1%
    (δ* − δ_p at fraction 1)."""
    mass = sphere_mass(RADIUS, BALL.density)
    first = simulate_impact(
        RADIUS, BALL, PLATE, 2.0, 0.0, 0.0, normal_model="thornton", limiting_pressure=P_Y, history=False
    )
    law = thornton_law(first.max_overlap)
    r_p, residual = thornton_unloading(first.max_overlap)
    speed = math.sqrt(fraction) * first.normal_restitution * 2.0
    second = simulate_impact(
        RADIUS, BALL, PLATE, speed, 0.0, 0.0, normal_model="tabulated", force_law=reloading_law(law), history=False
    )
    reach = (15.0 * mass * speed**2 / (16.0 * E_STAR * math.sqrt(r_p))) ** 0.4
    assert first.max_overlap > 5.0 * DELTA_Y  # the first impact did dent the plate
    assert second.normal_restitution == pytest.approx(1.0, abs=0.01)
    assert second.max_overlap == pytest.approx(reach, rel=0.01)
    assert second.max_overlap <= (first.max_overlap - residual) * 1.01


def test_reloading_law_of_a_branch_whose_peak_is_the_curves_top_within_round_off():
    """The plate's law holds its δ* twice, from two sums: the loading branch's last point and the unloading curve's
    top. Here the branch's point lies one ulp past the top, and both minus δ_p round (ties to even) to the same
    overlap: the numbers of a law from a plate's path that the earlier code refused ("loading_overlap must ... increase
    strictly"). The reloading law is valid, its elastic part the unloading curve reversed (exactly), the virgin
    branch beyond it."""
    top, peak, residual = (
        float.fromhex(h) for h in ("0x1.90c04d1319861p-21", "0x1.90c04d1319862p-21", "0x1.1f60b342d4a4bp-22")
    )
    assert peak > top and peak - residual == top - residual  # the case: the two sums tie after the shift
    loading = np.r_[np.linspace(0.0, top, 21)[:-1], peak, 1.1 * top]
    down = np.linspace(top, residual, 41)
    force = 1e3 * ((down - residual) / (top - residual)) ** 1.5
    law = TabulatedLaw(
        loading,
        1e3 * (loading / top) ** 1.2,
        np.sqrt(RADIUS * loading),
        np.array([top]),
        down[None, :],
        force[None, :],
        np.sqrt(RADIUS * (down - residual))[None, :],
    )
    reloaded = reloading_law(law)
    d, f = reloaded.loading_overlap, reloaded.loading_force
    assert d[0] == 0.0 and np.all(np.diff(d) > 0.0)
    np.testing.assert_array_equal(d[:41], down[::-1] - residual)
    np.testing.assert_array_equal(f[1:41], force[::-1][1:])
    assert d[41] == 1.1 * top - residual and f[41] == law.loading_force[-1]


def test_reloading_law_is_valid_for_laws_built_from_many_plate_paths():
    """Laws built as the plates build them (:func:`fem.force_law.force_law` from a loading path with a probe point and
    an unloading path, overlaps from a first contact δ₀ ≥ 0: on a dented plate), over 3000 random dents: every
    reloading law is a valid law whose elastic part starts at 0 and ends at exactly the old δ* − δ_p. Before the
    unloading curve's ends were pinned, 1 path in 2000 gave a loading point past the top by round-off."""
    from types import SimpleNamespace

    from fem.force_law import force_law

    rng = np.random.default_rng(1)
    for _ in range(3000):
        top = rng.uniform(1e-7, 1e-5)
        first_contact, dent = rng.uniform(0.0, 3.0) * top, top * rng.uniform(0.2, 0.95)
        down = first_contact + np.linspace(0.05, 1.0, 10) ** 1.5 * top
        force = 1e6 * (down - first_contact) ** 1.2
        up = np.r_[down, first_contact + 1.1 * top]
        loading = SimpleNamespace(
            overlap=up, force=np.r_[force, 1.1 * force[-1]], contact_radius=np.sqrt(RADIUS * (up - first_contact))
        )
        back = first_contact + np.linspace(top, dent - 0.05 * top, 7)
        unload_force = force[-1] * np.clip((back - first_contact - dent) / (top - dent), 0.0, None) ** 1.5
        unloading = SimpleNamespace(
            overlap=back,
            force=unload_force,
            contact_radius=np.sqrt(RADIUS * np.clip(back - first_contact - dent, 0, None)),
        )
        law = force_law(loading, unloading, first_contact)
        assert law.unloading_overlap[0, 0] == law.unloading_max_overlap[0]
        reloaded = reloading_law(law)  # raises if its overlaps do not increase strictly
        assert reloaded.unloading_max_overlap[0] == law.unloading_max_overlap[0] - law.unloading_overlap[0, -1]
