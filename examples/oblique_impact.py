"""Oblique impacts of an alumina ball on soda-lime glass
=====================================================

Oblique impacts of an alumina ball on soda-lime glass (Kharaz, Gorham & Salman 2001), H-DD model.

Sweeps the impact angle at 3.9 m/s, prints the rebound against rigid-body theory (valid in gross sliding,
large angles), and writes ``oblique_impact.csv`` (the sweep) and ``history_30deg.csv`` (one impact's time
history) into ``oblique_impact/`` of the folder named by the environment variable ``IMPACTWEAR_EXAMPLE_OUT``
(default: the current folder). SI units; angles in degrees from the plate normal.
"""

# %%
# Sweep the impact angle
# ----------------------
# Rigid-body theory in gross sliding (normal restitution 1): :math:`e_t = 1 - 2\mu/\tan\theta` once
# :math:`\tan\theta > 7\mu` (the ball slides throughout the contact).

import math
import os
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from contact import Material, simulate_impact, simulate_impacts
from wear.app.figures.common import place_legends
from wear.app.outputs.writer import write_csv

# where the outputs go
OUT = Path(os.environ.get("IMPACTWEAR_EXAMPLE_OUT", ".")) / "oblique_impact"
OUT.mkdir(parents=True, exist_ok=True)
# IMPACTWEAR_QUICK=1 (as on this page): a coarser sweep
quick = os.environ.get("IMPACTWEAR_QUICK") == "1"

ball = Material(E=380e9, nu=0.23, density=4000.0, name="alumina")
plate = Material(E=70e9, nu=0.25, density=2500.0, name="soda-lime glass")
radius, speed, mu = 2.5e-3, 3.9, 0.092
angles = np.arange(5.0, 86.0, 10.0 if quick else 2.5)
batch = simulate_impacts(radius, ball, plate, speed, angles, mu)

theta = np.radians(angles)
sliding = np.tan(theta) > 7 * mu  # rigid-body gross sliding throughout
et_theory = np.where(sliding, 1 - 2 * mu / np.tan(theta), np.nan)
print(
    f"{'angle':>6} {'e_t':>8} {'e_t rigid':>10} {'spin rad/s':>11} {'rebound':>8} "
    f"{'cp rebound':>10} {'t_s/t_c':>8}"
)
for i, a in enumerate(angles):
    print(
        f"{a:6.1f} {batch.tangential_restitution[i]:8.4f} {et_theory[i]:10.4f} "
        f"{batch.spin[i]:11.1f} "
        f"{batch.rebound_angle[i]:8.2f} {batch.contact_point_rebound_angle[i]:10.2f} "
        f"{batch.sliding_time[i] / batch.contact_time[i]:8.3f}"
    )
write_csv(
    OUT / "oblique_impact.csv",
    {
        "angle_deg": angles,
        "tangential_restitution": batch.tangential_restitution,
        "spin_rad_s": batch.spin,
        "rebound_angle_deg": batch.rebound_angle,
        "contact_point_rebound_angle_deg": batch.contact_point_rebound_angle,
        "contact_time_s": batch.contact_time,
        "sliding_time_s": batch.sliding_time,
        "max_force_N": batch.max_force,
    },
)

fig, ax = plt.subplots(figsize=(5.5, 3.8))
ax.plot(angles, batch.tangential_restitution, "o-", ms=3, label="H-DD model")
ax.plot(angles, et_theory, "k--", label="rigid body, gross sliding")
ax.set(
    xlabel="impact angle from the normal (deg)",
    ylabel="tangential restitution $e_t$",
    ylim=(-0.6, 1.05),
)
ax.legend()
fig.tight_layout()

# %%
# One impact at 30°
# -----------------
# Its time history, and the energy balance: kinetic energy in = out + work of the normal and friction forces.

r = simulate_impact(radius, ball, plate, speed, 30.0, mu, history_every=10)
h = r.history
print(
    f"30 deg: contact {r.contact_time * 1e6:.2f} us, sliding "
    f"{r.sliding_time * 1e6:.2f} us, "
    f"peak pressure {r.max_peak_pressure / 1e9:.2f} GPa, contact patch travels "
    f"{h.contact_x[-1] * 1e6:.1f} um"
)
balance = r.energy_in - r.energy_out - r.normal_work - r.friction_work
print(f"energy balance residual: {balance / r.energy_in:.1e} of the kinetic energy in")
assert math.isfinite(balance) and abs(balance) < 1e-3 * r.energy_in
write_csv(
    OUT / "history_30deg.csv",
    {
        "time_s": h.t,
        "overlap_m": h.overlap,
        "normal_force_N": h.normal_force,
        "tangential_force_N": h.tangential_force,
        "contact_radius_m": h.contact_radius,
        "peak_pressure_Pa": h.peak_pressure,
        "slip_velocity_m_s": h.slip_velocity,
        "sliding": h.sliding.astype(int),
        "contact_x_m": h.contact_x,
    },
)

fig, ax = plt.subplots(figsize=(5.5, 3.6))
ax.plot(h.t * 1e6, h.normal_force, label="normal force")
ax.plot(
    h.t * 1e6,
    np.abs(h.tangential_force),
    label="|tangential force| (it opposes the slip)",
)
ax.plot(
    h.t * 1e6, mu * h.normal_force, "k:", lw=1, label="μ × normal force (gross sliding)"
)
ax.set(xlabel="time (µs)", ylabel="force (N)", title="alumina on glass, 3.9 m/s at 30°")
place_legends(fig, [ax])  # where it covers no curve (here: above them, given room)
