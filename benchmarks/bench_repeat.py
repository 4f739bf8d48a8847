"""Benchmark of repeated impacts at one site (issue 6 §1; not a timed test): ``python benchmarks/bench_repeat.py``.

The embedded default case (alumina ball R 2.5 mm on Ti-6Al-4V, 3 m/s at 30° from the normal, FE plate, wear on)
hit ``--impacts`` times (default 10⁴, the issue's target: "10⁴ impacts in minutes") at the default cycle-jump
fraction: wall time, impacts solved with the coupled FE impact, blocks, the final state, and the last computed
impact's peak pressure against the half-space solution of the surface it met (:mod:`wear.chain.check`).

``--fractions 0.025,0.05,0.1`` adds the cycle-jump study, side by side in the same run: the same sequence at each
``surface_fraction`` (a block moves the surface by at most that × the last computed impact's approach), each
compared with the smallest fraction (the reference) on the final surface depth, wear volume, dent, normal
restitution and peak pressure — the error the cycle jump costs against the time it saves.

``--solvers N`` first runs N impacts twice, side by side: with the plate's elastic shortcuts (the elastic predictor
of :class:`fem.Plate` and the elastic response after shakedown, :func:`fem.elastic_reload`) and with the
elastic–plastic Newton solution of every step: the speed-up and the largest difference of the records.
"""

from __future__ import annotations

import argparse
import time
import warnings

from wear import Case, repeat
from wear.case import RepeatSpec
from wear.chain.check import halfspace_check

QUANTITIES = {
    "surface depth (m)": lambda r: r.records[-1].surface_depth,
    "total wear volume (m^3)": lambda r: r.records[-1].total_wear_volume,
    "dent depth (m)": lambda r: r.records[-1].dent_depth,
    "normal restitution": lambda r: r.records[-1].normal_restitution,
    "max pressure (Pa)": lambda r: r.records[-1].max_pressure,
}


def run(impacts: int, fraction: float, shortcuts: bool = True):
    import fem

    case = Case()
    init = fem.Plate.__init__

    def plate_init(self, *args, **kwargs):
        init(self, *args, **kwargs)
        self.elastic_predictor = shortcuts

    fem.Plate.__init__ = plate_init
    t0 = time.perf_counter()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            spec = {"impacts": impacts, "surface_fraction": fraction, "elastic_after_shakedown": shortcuts}
            result = repeat(case.with_(repeat=spec))
    finally:
        fem.Plate.__init__ = init
    return result, time.perf_counter() - t0


def compare_solvers(impacts: int, fraction: float) -> None:
    fast, t_fast = run(impacts, fraction, shortcuts=True)
    full, t_full = run(impacts, fraction, shortcuts=False)
    print(
        f"{impacts} impacts, surface_fraction {fraction:g}: elastic shortcuts {t_fast:.1f} s "
        f"({fast.computed} computed, {fast.elastic_computed} of them elastic), Newton every step {t_full:.1f} s "
        f"({full.computed} computed): speed-up {t_full / t_fast:.2f}x"
    )
    worst = {}
    for a, b in zip(fast.records, full.records, strict=False):
        for name in ("surface_depth", "total_wear_volume", "dent_depth", "max_pressure", "max_force"):
            ref = getattr(b, name)
            if ref:
                worst[name] = max(worst.get(name, 0.0), abs(getattr(a, name) / ref - 1.0))
    same_rows = [(r.first, r.count) for r in fast.records] == [(r.first, r.count) for r in full.records]
    print(
        f"  same rows: {same_rows}; largest relative difference: "
        + ", ".join(f"{k} {v:.1e}" for k, v in worst.items())
        + "\n"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--impacts", type=int, default=10_000)
    parser.add_argument("--fractions", default="", help="comma-separated surface fractions for the cycle-jump study")
    parser.add_argument("--solvers", type=int, default=0, help="impacts of the side-by-side solver comparison")
    args = parser.parse_args()
    default = RepeatSpec().surface_fraction
    if args.solvers:
        compare_solvers(args.solvers, default)
    fractions = sorted({float(f) for f in args.fractions.split(",") if f} | {default})
    results = {}
    for fraction in fractions if args.fractions else [default]:
        result, wall = run(args.impacts, fraction)
        results[fraction] = result
        blocks = sum(r.kind == "block" for r in result.records)
        print(
            f"surface_fraction {fraction:g}: {args.impacts} impacts in {wall:.0f} s ({wall / 60:.1f} min), "
            f"{result.computed} solved with the FE plate ({result.elastic_computed} of them on its elastic response), "
            f"{blocks} blocks, {wall / result.computed:.1f} s per solved impact; shakedown at impact "
            f"{result.shakedown_impact}"
        )
        for note in result.notes:
            print(f"  note: {note}")
        check = halfspace_check(result)
        print(
            f"  last computed impact ({check['impact']}, Δᾱ {check['plastic_strain_increment']:.2g}): peak pressure "
            f"FE {check['fe_max_pressure_Pa']:.4g} Pa, half-space on the surface it met "
            f"{check['halfspace_max_pressure_Pa']:.4g} Pa at {check['force_N']:.4g} N"
        )
    reference = results[min(results)]
    print(f"\nfinal state after {args.impacts} impacts (relative difference to surface_fraction {min(results):g}):")
    print(f"{'quantity':28s}" + "".join(f"{f:>22g}" for f in results))
    for name, get in QUANTITIES.items():
        ref = get(reference)
        cells = "".join(f"{get(r):>12.4g} ({(get(r) - ref) / ref:+6.1%})" for r in results.values())
        print(f"{name:28s}{cells}")


if __name__ == "__main__":
    main()
