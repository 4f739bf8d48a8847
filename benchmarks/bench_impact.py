"""Benchmark of the batched impact engine (issue 2), measured side by side in one run.

10,000 oblique impacts (angles 1-89 deg, speeds 0.5-10 m/s, steel ball R 5 mm on a steel plate, mu = 0.3,
Hertz + H-DD, default time step t_c/2000) with :func:`contact.simulate_impacts`, against a straightforward
plain-Python loop of the same model and scheme at the same time step (hence equal accuracy of the rebound
velocities, checked and printed). Prints impacts/s, contact-steps/s, ns per contact-step per core, the ratio,
and the JIT compile time (measured in a fresh numba cache) separately.

Targets (issue 2): >= 300x faster per impact than the plain implementation; >= 5e7 contact-steps/s on 2 cores;
a few ns per contact-step per core.

Run: ``python benchmarks/bench_impact.py [--impacts 10000] [--plain 20]``. Timings on a shared machine are
noisy: the load average is printed first.
"""

from __future__ import annotations

import argparse
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

_COMPILE_PROBE = """
import time
t = time.perf_counter()
from contact import Material, simulate_impacts
s = Material(E=210e9, nu=0.3, density=7800.0)
simulate_impacts(5e-3, s, s, [1.0, 2.0], [10.0, 50.0], 0.3, histories=True)
print(time.perf_counter() - t)
"""


def compile_time() -> float:
    """Seconds to import and JIT-compile the engine (batch and history kernels) with an empty numba cache."""
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache)
        out = subprocess.run(
            [sys.executable, "-c", _COMPILE_PROBE], env=env, capture_output=True, text=True, check=True
        )
    return float(out.stdout.strip().splitlines()[-1])


def plain_impact(radius, mass, e_star, g_star, speed, angle, friction, dt):
    """The same model (Hertz, H-DD with Coulomb truncation, velocity Verlet) as a plain Python loop."""
    stiff = 4.0 / 3.0 * e_star * math.sqrt(radius)
    inertia = 0.4 * mass * radius**2
    vn = speed * math.cos(math.radians(angle))
    vt = speed * math.sin(math.radians(angle))
    delta = om = xi = fn = ft = 0.0
    steps = 0
    while True:
        vn_half = vn - 0.5 * dt * fn / mass
        vt_half = vt + 0.5 * dt * ft / mass
        om_half = om - 0.5 * dt * radius * ft / inertia
        delta += dt * vn_half
        xi += dt * (vt_half - radius * om_half)
        d = max(delta, 0.0)
        fn = stiff * d * math.sqrt(d)
        k_t = 2.0 / 3.0 * 8.0 * g_star * math.sqrt(radius * d)
        ft = -k_t * xi
        if abs(ft) > friction * fn:
            sign = 1.0 if xi > 0.0 else -1.0
            ft = -sign * friction * fn
            xi = sign * friction * fn / k_t if k_t > 0.0 else 0.0
        vn = vn_half - 0.5 * dt * fn / mass
        vt = vt_half + 0.5 * dt * ft / mass
        om = om_half - 0.5 * dt * radius * ft / inertia
        steps += 1
        if fn <= 0.0 and vn < 0.0:
            return -vn, vt, om, steps


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--impacts", type=int, default=10_000)
    parser.add_argument("--plain", type=int, default=20, help="impacts run by the plain-Python loop")
    args = parser.parse_args()

    import numba

    from contact import Material, effective_modulus, effective_shear_modulus, simulate_impacts
    from contact.theory import sphere_mass

    print(f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} CPUs; numba threads {numba.get_num_threads()}")
    print(f"JIT compile (import + batch and history kernels, empty cache): {compile_time():.2f} s")

    steel = Material(E=210e9, nu=0.3, density=7800.0)
    radius, mu = 5e-3, 0.3
    rng = np.random.default_rng(1)
    speed = rng.uniform(0.5, 10.0, args.impacts)
    angle = rng.uniform(1.0, 89.0, args.impacts)
    simulate_impacts(radius, steel, steel, speed[:16], angle[:16], mu)  # load the cached kernels
    best = math.inf
    for _ in range(3):
        t0 = time.perf_counter()
        batch = simulate_impacts(radius, steel, steel, speed, angle, mu)
        best = min(best, time.perf_counter() - t0)
    steps = int(batch.steps.sum())
    threads = numba.get_num_threads()
    engine_per_impact = best / args.impacts
    print(f"\nbatched engine, {args.impacts} impacts, {steps / args.impacts:.0f} steps each: {best:.3f} s")
    print(f"  {args.impacts / best:,.0f} impacts/s   {steps / best:.3e} contact-steps/s on {threads} threads")
    print(f"  {best * threads / steps * 1e9:.2f} ns per contact-step per core (limit: a few ns)")

    mass = sphere_mass(radius, steel.density)
    e_star, g_star = effective_modulus(steel, steel), effective_shear_modulus(steel, steel)
    idx = np.linspace(0, args.impacts - 1, args.plain).astype(int)
    t0 = time.perf_counter()
    plain = [plain_impact(radius, mass, e_star, g_star, speed[i], angle[i], mu, batch.time_step[i]) for i in idx]
    plain_time = time.perf_counter() - t0
    plain_steps = sum(p[3] for p in plain)
    plain_per_impact = plain_time / len(idx)
    deviation = max(
        max(
            abs(p[0] - batch.rebound_normal_velocity[i]),
            abs(p[1] - batch.rebound_tangential_velocity[i]),
            abs(p[2] * radius - batch.spin[i] * radius),
        )
        / speed[i]
        for p, i in zip(plain, idx, strict=True)
    )
    print(f"\nplain Python loop, same model and time step, {len(idx)} impacts: {plain_time:.3f} s")
    print(f"  {1 / plain_per_impact:,.1f} impacts/s   {plain_steps / plain_time:.3e} contact-steps/s (1 core)")
    print(f"  max |rebound velocity difference| / speed vs the engine: {deviation:.1e} (equal accuracy)")
    print(
        f"\nratio per impact (engine, {threads} threads, vs plain loop): {plain_per_impact / engine_per_impact:,.0f}x"
        " (target >= 300x)"
    )
    print(f"ratio per impact per core: {plain_per_impact / (engine_per_impact * threads):,.0f}x")
    rate = steps / best
    print(f"contact-steps/s: {rate:.3e} (target >= 5e7 on 2 cores): {'met' if rate >= 5e7 else 'NOT met'}")

    t0 = time.perf_counter()
    b2 = simulate_impacts(radius, steel, steel, speed, angle, mu, scheme="paper")
    t_paper = time.perf_counter() - t0
    print(
        f"\nfor reference, the general (non-vectorised) path, paper scheme: "
        f"{int(b2.steps.sum()) / t_paper:.3e} contact-steps/s"
    )


if __name__ == "__main__":
    main()
