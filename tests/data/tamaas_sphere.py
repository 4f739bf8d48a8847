#!/usr/bin/env python
"""Peer-code reference (tamaas 2.9.0, EPIC volume-integral solver) for a rigid
sphere (R = 10 mm) pressed frictionlessly into an elastic-perfectly-plastic
half-space (E = 210 GPa, nu = 0.3, Y = 210 MPa, no hardening).

Usage
  python tests/data/tamaas_sphere.py run NAME N L_over_amax Nz H_over_amax STEPS [Y_Pa]
      one tamaas run; STEPS = comma-separated F/Fc list (monotonic)
      writes runs/NAME.npz  (Y_Pa large -> elastic check)
  python tests/data/tamaas_sphere.py analyze
      compares runs, writes profiles.csv / summary.csv / convergence.txt
  python tests/data/tamaas_sphere.py all
      runs the whole campaign sequentially, then analyze

Internal units: length = mm, stress = E = 210 GPa (so E = 1, Y = 1e-3),
force = E*mm^2 = 2.1e5 N.  Outputs are converted to SI.
Surface: parabola h = -(x^2+y^2)/(2R), centre on a grid point (L/2, L/2).
Domain periodic in x, y (non-periodic Boussinesq is NOT available for
volume_2d in tamaas 2.9.0: registerNonPeriodic raises).
"""

import json
import os
import sys
import time

import numpy as np

E_SI, NU, Y_SI, R_MM = 210e9, 0.3, 210e6, 10.0
STRESS_U = E_SI  # Pa per internal stress unit
FORCE_U = E_SI * 1e-6  # N per internal force unit (E * mm^2)
FC_SI = 0.376998  # N, first yield force
AC_SI = 2.30537e-5  # m
AMAX_MM = 0.124  # expected contact radius at F/Fc = 61.4 (mm)
HERE = os.getcwd()  # runs/, profiles.csv, summary.csv, convergence.txt are written where it is run
RUNS = os.path.join(HERE, "runs")


def radial_profile(p, dx, r_edges):
    """azimuthal average of field p (N x N, centre at N/2) into bins."""
    N = p.shape[0]
    x = (np.arange(N) - N // 2) * dx
    rr = np.hypot(*np.meshgrid(x, x, indexing="ij"))
    idx = np.digitize(rr.ravel(), r_edges) - 1
    nb = len(r_edges) - 1
    ok = (idx >= 0) & (idx < nb)
    s = np.bincount(idx[ok], weights=p.ravel()[ok], minlength=nb)
    c = np.bincount(idx[ok], minlength=nb)
    with np.errstate(invalid="ignore", divide="ignore"):
        prof = s / c
    sr = np.bincount(idx[ok], weights=rr.ravel()[ok], minlength=nb)
    with np.errstate(invalid="ignore", divide="ignore"):
        rc = sr / c  # mean radius of the points in each bin
    return rc, prof


def run(name, N, L_over_amax, Nz, H_over_amax, steps, Y_Pa=Y_SI, epic_tol=1e-6, relaxation=0.3):
    import tamaas as tm
    from tamaas.nonlinear_solvers import DFSANECXXSolver

    os.makedirs(RUNS, exist_ok=True)
    L = L_over_amax * AMAX_MM
    H = H_over_amax * AMAX_MM
    dx = L / N
    Y = Y_Pa / STRESS_U
    print(
        f"[{name}] volume_2d size [H={H} mm, L={L} mm, L] grid [{Nz},{N},{N}]"
        f" dx={dx * 1e3:.3f} um dz={H / (Nz - 1) * 1e3:.3f} um Y={Y_Pa:.3e} Pa"
        f" steps F/Fc={steps}",
        flush=True,
    )
    tm.set_log_level(tm.LogLevel.warning)
    model = tm.ModelFactory.createModel(tm.model_type.volume_2d, [H, L, L], [Nz, N, N])
    model.E = 1.0
    model.nu = NU
    residual = tm.ModelFactory.createResidual(model, sigma_y=Y, hardening=0.0)
    x = (np.arange(N) - N // 2) * dx
    xx, yy = np.meshgrid(x, x, indexing="ij")
    surface = -(xx**2 + yy**2) / (2 * R_MM)
    epsolver = DFSANECXXSolver(residual)  # tolerance 1e-9 (default)
    epsolver.setToleranceManager(tm._tamaas._tolerance_manager(1e-5, 1e-9, 0.1))
    csolver = tm.PolonskyKeerRey(model, surface, 1e-12, tm.PolonskyKeerRey.pressure, tm.PolonskyKeerRey.pressure)
    epic = tm.EPICSolver(csolver, epsolver, epic_tol, relaxation=relaxation)
    z = np.linspace(0, H, Nz)  # tamaas volume grid includes both z=0 and z=H
    out = dict(
        name=name,
        N=N,
        L_mm=L,
        Nz=Nz,
        H_mm=H,
        dx_mm=dx,
        Y_Pa=Y_Pa,
        steps=np.array(steps),
        epic_tol=epic_tol,
        relaxation=relaxation,
    )
    P, info = [], []
    t0 = time.time()
    fc = FC_SI / FORCE_U
    for f in steps:
        t = time.time()
        epic.solve(f * fc / L**2)
        p = np.array(model.traction[..., 2]).copy()
        F = p.sum() * dx**2 * FORCE_U
        A = (p > 0).sum() * (dx * 1e-3) ** 2
        a = np.sqrt(A / np.pi)
        ep = np.array(model["cumulated_plastic_strain"]).reshape(Nz, N, N)
        k = np.unravel_index(np.argmax(ep), ep.shape)
        plastic = ep > 1e-8
        zdeep = z[np.nonzero(plastic.any(axis=(1, 2)))[0].max()] if plastic.any() else 0.0
        rext = np.hypot(xx, yy)[plastic.any(axis=0)].max() if plastic.any() else 0.0
        d = dict(
            F_over_Fc=f,
            F_N=F,
            a_m=a,
            pmax_Pa=p.max() * STRESS_U,
            epmax=float(ep.max()),
            epmax_depth_m=z[k[0]] * 1e-3,
            epmax_r_m=float(np.hypot(xx[k[1], k[2]], yy[k[1], k[2]])) * 1e-3,
            plastic_zdeep_m=zdeep * 1e-3,
            plastic_rmax_m=rext * 1e-3,
            ep_at_bottom=float(ep[-1].max()),
            disp_center_m=float(np.array(model.displacement)[0, N // 2, N // 2, 2]) * 1e-3,
            time_s=time.time() - t,
        )
        info.append(d)
        P.append(p * STRESS_U)
        print(
            f"[{name}] F/Fc={f:6.2f} F={F:.5g} N (err {F / (f * FC_SI) - 1:+.1e}) "
            f"a={a * 1e6:.2f} um pmax={d['pmax_Pa'] / 1e6:.1f} MPa "
            f"epmax={d['epmax']:.3e} at z={d['epmax_depth_m'] * 1e6:.1f} um "
            f"r={d['epmax_r_m'] * 1e6:.1f} um; plastic zone z<={zdeep * 1e3:.0f} um "
            f"r<={rext * 1e3:.0f} um, ep(z=H)max={d['ep_at_bottom']:.1e} "
            f"[{d['time_s']:.0f} s]",
            flush=True,
        )
        np.savez(
            os.path.join(RUNS, name + ".npz"),
            p=np.array(P),
            info=json.dumps(info),
            meta=json.dumps({k2: (v.tolist() if isinstance(v, np.ndarray) else v) for k2, v in out.items()}),
        )
    print(f"[{name}] total {time.time() - t0:.0f} s", flush=True)


def load(name):
    d = np.load(os.path.join(RUNS, name + ".npz"))
    return d["p"], json.loads(str(d["info"])), json.loads(str(d["meta"]))


def hertz(F):
    Es = E_SI / (1 - NU**2)
    R = R_MM * 1e-3
    a = (3 * F * R / (4 * Es)) ** (1 / 3)
    p0 = (6 * F * Es**2 / (np.pi**3 * R**2)) ** (1 / 3)
    return a, p0


def rms_between(nA, nB, f, lines):
    """RMS difference of profiles of runs nA, nB at load f, in units of the
    peak pressure of run nB, over r < 0.9 a (a of nB), using common bins of
    width = the coarser grid spacing."""
    try:
        pA, iA, mA = load(nA)
        pB, iB, mB = load(nB)
    except FileNotFoundError:
        lines.append(f"  {nA} vs {nB} @ F/Fc={f}: NOT OBTAINED (run missing)")
        return None
    sA = [i for i, d in enumerate(iA) if abs(d["F_over_Fc"] - f) < 1e-9]
    sB = [i for i, d in enumerate(iB) if abs(d["F_over_Fc"] - f) < 1e-9]
    if not sA or not sB:
        lines.append(f"  {nA} vs {nB} @ F/Fc={f}: NOT OBTAINED (step missing)")
        return None
    dA, dB = iA[sA[0]], iB[sB[0]]
    a = dB["a_m"] * 1e3
    w = max(mA["dx_mm"], mB["dx_mm"])
    edges = np.arange(0, 0.9 * a + 1e-12, w)
    _, prA = radial_profile(pA[sA[0]], mA["dx_mm"], edges)
    _, prB = radial_profile(pB[sB[0]], mB["dx_mm"], edges)
    pm = dB["pmax_Pa"]
    ok = np.isfinite(prA) & np.isfinite(prB)
    r = np.sqrt(np.mean(((prA - prB)[ok] / pm) ** 2))
    mx = np.max(np.abs((prA - prB)[ok] / pm))
    lines.append(
        f"  {nA} vs {nB} @ F/Fc={f}: RMS/pmax={r:.4f} max={mx:.4f} "
        f"(bins {w * 1e3:.2f} um, r<0.9a); a: {dA['a_m'] * 1e6:.2f} vs "
        f"{dB['a_m'] * 1e6:.2f} um; pmax {dA['pmax_Pa'] / 1e6:.1f} vs "
        f"{pm / 1e6:.1f} MPa; epmax {dA['epmax']:.3e} vs {dB['epmax']:.3e}"
    )
    return r


def analyze(finest=None):
    lines = []
    names = sorted(f[:-4] for f in os.listdir(RUNS) if f.endswith(".npz"))
    lines.append("runs: " + ", ".join(names))
    # elastic checks vs Hertz
    for n in names:
        if not n.startswith("elastic"):
            continue
        p, info, meta = load(n)
        d = info[-1]
        F = d["F_N"]
        a, p0 = hertz(F)
        N, dx = meta["N"], meta["dx_mm"] * 1e-3
        x = (np.arange(N) - N // 2) * dx
        rr = np.hypot(*np.meshgrid(x, x, indexing="ij"))
        ph = p0 * np.sqrt(np.clip(1 - rr**2 / a**2, 0, None))
        m = rr < 0.95 * a
        rms_pt = np.sqrt(np.mean(((p[-1] - ph)[m] / p0) ** 2))
        edges = np.arange(0, 0.95 * a + 1e-15, dx)
        rc, pr = radial_profile(p[-1], dx, edges)
        ok = np.isfinite(pr)
        rms_b = np.sqrt(np.mean(((pr - p0 * np.sqrt(1 - rc**2 / a**2))[ok] / p0) ** 2))
        lines.append(
            f"elastic check {n} (dx={dx * 1e6:.2f} um): F={F:.5g} N "
            f"a_num={d['a_m'] * 1e6:.2f} um a_Hertz={a * 1e6:.2f} um "
            f"pmax={d['pmax_Pa'] / 1e6:.1f} MPa p0={p0 / 1e6:.1f} MPa; RMS(p-pH)/p0 "
            f"r<0.95a: pointwise {rms_pt:.4f}, binned {rms_b:.4f}"
        )
    lines.append("convergence (profile RMS difference / p_max, r < 0.9 a):")
    for f in (13.4, 61.4):
        for nA, nB in (
            ("r8", "r16"),
            ("r16", "r24"),
            ("r8", "r24"),
            ("r8", "r8_L6"),
            ("r8", "r8_12steps"),
            ("r8", "r8_L8"),
            ("r8_L6", "r8_L8"),
            ("r8", "r8_24steps"),
            ("r8_12steps", "r8_24steps"),
            ("r16", "r16_L6"),
            ("r16_L6", "r16_L6_24"),
            ("r24", "r16_L6_24"),
        ):
            if nA in names or nB in names:
                rms_between(nA, nB, f, lines)
    # the reference: the finest load stepping on a grid and cell whose own errors are below it
    if finest is None:
        for cand in ("r16_L6_24", "r32", "r24", "r16", "r8"):
            if cand in names:
                finest = cand
                break
    p, info, meta = load(finest)
    dx = meta["dx_mm"]
    lines.append(f"profiles/summary from run {finest} (dx={dx * 1e3:.3f} um)")
    with open(os.path.join(HERE, "profiles.csv"), "w") as fp, open(os.path.join(HERE, "summary.csv"), "w") as fs:
        fp.write("F_over_Fc,r_m,p_Pa\n")
        fs.write(
            "F_over_Fc,F_N,a_m,p_max_Pa,max_eq_plastic_strain,"
            "depth_of_max_m,r_of_max_m,plastic_zone_depth_m,"
            "plastic_zone_radius_m,center_surface_disp_periodic_m_NOT_overlap\n"
        )
        for k, d in enumerate(info):
            a = d["a_m"] * 1e3
            edges = np.arange(0, 1.3 * a + dx, dx) - dx / 2
            edges[0] = 0
            rc, pr = radial_profile(p[k], dx, edges)
            for r_, p_ in zip(rc, pr, strict=False):
                if np.isfinite(p_):
                    fp.write(f"{d['F_over_Fc']},{r_ * 1e-3:.6e},{p_:.6e}\n")
            fs.write(
                f"{d['F_over_Fc']},{d['F_N']:.6e},{d['a_m']:.6e},"
                f"{d['pmax_Pa']:.6e},{d['epmax']:.6e},{d['epmax_depth_m']:.6e},"
                f"{d['epmax_r_m']:.6e},{d['plastic_zdeep_m']:.6e},"
                f"{d['plastic_rmax_m']:.6e},{d['disp_center_m']:.6e}\n"
            )
            if d["F_over_Fc"] in (13.4, 61.4):
                lines.append(
                    f" F/Fc={d['F_over_Fc']}: F={d['F_N']:.5g} N "
                    f"(target {d['F_over_Fc'] * FC_SI:.5g}), a={d['a_m'] * 1e6:.2f} um "
                    f"(A/Ac={(d['a_m'] / AC_SI) ** 2:.2f}), pmax={d['pmax_Pa'] / 1e6:.1f} MPa, "
                    f"epmax={d['epmax']:.3e} at z={d['epmax_depth_m'] * 1e6:.1f} um"
                )
                pm = d["pmax_Pa"]
                rs = np.linspace(0, 1.2, 13).tolist() + [0.9, 0.95, 1.05]
                ok = np.isfinite(pr)
                s = "  r/a:p/pmax " + " ".join(
                    f"{x:.2f}:{np.interp(x * a, rc[ok], pr[ok]) / pm:.3f}" for x in sorted(set(round(v, 2) for v in rs))
                )
                lines.append(s)
    txt = "\n".join(lines)
    print(txt)
    with open(os.path.join(HERE, "convergence.txt"), "w") as fh:
        fh.write(txt + "\n")


STEPS6 = [3.0, 7.0, 13.4, 25.0, 42.0, 61.4]
STEPS12 = [1.5, 3.0, 5.0, 7.0, 10.0, 13.4, 19.0, 25.0, 33.0, 42.0, 51.0, 61.4]
STEPS24 = [0.75, 1.5, 2.25, 3, 4, 5, 6, 7, 8.5, 10, 11.7, 13.4, 16, 19, 22, 25, 29, 33, 37.5, 42, 46.5, 51, 56, 61.4]
# the campaign actually run (in two/three parallel queues, see logs/)
# rN: grid spacing dx = a_max/N (a_max = 124 um), dz ~ 2 dx, H = 2.5 a_max
CAMPAIGN = [
    # name, N, L/amax, Nz, H/amax, steps, Y
    ("elastic_r8", 32, 4.0, 10, 2.5, [61.4], 1e20),
    ("elastic_r16", 64, 4.0, 20, 2.5, [61.4], 1e20),
    ("elastic_r24", 96, 4.0, 30, 2.5, [61.4], 1e20),
    ("elastic_r32", 128, 4.0, 40, 2.5, [61.4], 1e20),
    ("elastic_r16_L6", 96, 6.0, 20, 2.5, [61.4], 1e20),
    ("elastic_r16_L8", 128, 8.0, 20, 2.5, [61.4], 1e20),
    ("r8", 32, 4.0, 10, 2.5, STEPS6, Y_SI),
    ("r8_12steps", 32, 4.0, 10, 2.5, STEPS12, Y_SI),
    ("r8_24steps", 32, 4.0, 10, 2.5, STEPS24, Y_SI),
    ("r8_L6", 48, 6.0, 10, 2.5, STEPS6, Y_SI),
    ("r8_L8", 64, 8.0, 10, 2.5, STEPS6, Y_SI),
    ("r16", 64, 4.0, 20, 2.5, STEPS6, Y_SI),
    ("r16_L6", 96, 6.0, 20, 2.5, STEPS6, Y_SI),
    ("r24", 96, 4.0, 30, 2.5, STEPS6, Y_SI),
    ("r16_L6_24", 96, 6.0, 20, 2.5, STEPS24, Y_SI),  # the reference in tests/data (75 min on one core)
]

if __name__ == "__main__":
    cmd = sys.argv[1] if len(sys.argv) > 1 else "all"
    if cmd == "run":
        name = sys.argv[2]
        N, Lr, Nz, Hr = int(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5]), float(sys.argv[6])
        steps = [float(s) for s in sys.argv[7].split(",")]
        Y = float(sys.argv[8]) if len(sys.argv) > 8 else Y_SI
        run(name, N, Lr, Nz, Hr, steps, Y)
    elif cmd == "analyze":
        analyze(sys.argv[2] if len(sys.argv) > 2 else None)
    else:
        for c in CAMPAIGN:
            run(*c)
        analyze()
