#!/usr/bin/env python3
"""
Peer-code reference table: first yield (von Mises) under a sliding Hertzian
sphere contact, Hertz pressure p = p0 sqrt(1 - r^2/a^2) plus full-sliding
tangential traction q = mu p acting along +x, Poisson's ratio nu = 0.3.

Provenance
----------
Closed-form stresses: G.M. Hamilton, "Explicit equations for the stresses
beneath a sliding spherical contact", Proc. IMechE 197C (1983) 53-59, as
implemented in

    library : ContactMechanics (PyPI "ContactMechanics"; authors T. Junge,
              L. Pastewka, A. Sanner; MIT licence), version printed in the
              CSV header (1.8.3 when this table was made)
    module  : ContactMechanics.ReferenceSolutions.Hertz
    functions: stress_Cartesian(x, y, z, poisson)               -> normal part
               stress_for_tangential_loading(x, y, z, poisson)  -> tangential part
    Both return (sxx, syy, szz, syz, sxz, sxy) / p0 at (x, y, z) / a.

The same code used to live in matscipy (matscipy.contact_mechanics.Hertz);
that sub-package is no longer shipped in matscipy >= 1.0 (checked: matscipy
1.3.1 from PyPI has no contact_mechanics module), so the maintained copy in
ContactMechanics is used.

Sign conventions (verified in check_integration.py against a direct numerical
integration of the Boussinesq + Cerruti point-load solutions, agreement ~1e-13 p0):
  * z is the depth into the solid (z >= 0), tension positive, compression
    negative (szz = -p0 at the centre of the surface).
  * stress_for_tangential_loading gives the field of q = p0 sqrt(1-r^2/a^2)
    acting on the solid along +x (i.e. mu = 1); surface sxz = -q.  Total
    stress = stress_Cartesian + mu * stress_for_tangential_loading.
  * With traction along +x the trailing edge is x = -a; the surface tensile
    peak is sxx(x=-a) = p0 [(1-2nu)/3 + pi mu (4+nu)/8] (Hamilton 1983).

Numerical guards added here (not in the library):
  * near the z-axis (0 < r < RC = 3e-3 a) the library formulas lose all
    precision (1/r^4 cancellation; garbage for r < ~1e-5 a).  There the stress
    is obtained by biquadratic interpolation in (x, y) from a 3x3 stencil of
    spacing RC centred on the axis (the r = 0 nodes use the library's exact
    axis branch).  Interpolation error ~1e-7 p0.
  * at z = 0, r = a exactly the library returns NaN (0/0); such points are
    evaluated at r = a (1 + 1e-15), i.e. the limit value (field is continuous).

Method
------
For each mu: (1) y = 0 plane grid, x in [-1.5, 1.5] a, z in [0, 1.5] a, step
0.005 a (601 x 301, including z = 0); surface line z = 0 at step 1e-4 a
plus the contact edges x = +-a; (2) the interior local maximum is refined with
Nelder-Mead in (x, z) from the best z > 0 grid point (xatol 1e-8), the
surface maximum with a bounded 1-D search around the best surface point
(it is a cusp at x = -a for all mu here); (3) a 3-D check over y > 0
(coarse grid + 3-D Nelder-Mead, and the surface along the contact circle)
confirms the maximum lies in y = 0.  The crossover mu at which the surface
maximum overtakes the interior one is found by bisection (brentq).
"""

import sys
import warnings

import ContactMechanics
import numpy as np
from ContactMechanics.ReferenceSolutions import Hertz
from scipy import ndimage, optimize

warnings.filterwarnings("ignore", category=RuntimeWarning)

NU = 0.3
MUS = [0.0, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.5]
RC = 3e-3  # axis guard radius / stencil spacing
EDGE_NUDGE = 1e-15
OUT = "/work/scratch/hamilton/hamilton_first_yield.csv"


def _raw(x, y, z):
    """library stresses (normal, tangential for mu=1), arrays shape (6, n)."""
    N = np.array(Hertz.stress_Cartesian(x, y, z, poisson=NU))
    T = np.array(Hertz.stress_for_tangential_loading(x, y, z, poisson=NU))
    return N, T


def stress_parts(x, y, z):
    """(normal, tangential) stress / p0, each shape (6,)+shape; guarded."""
    x, y, z = np.broadcast_arrays(np.asarray(x, float), np.asarray(y, float), np.asarray(z, float))
    shape = x.shape
    x, y, z = x.ravel().copy(), y.ravel().copy(), z.ravel().copy()
    r = np.hypot(x, y)
    # contact edge on the surface: take the (continuous) limit
    edge = (z == 0) & (np.abs(r - 1) < 1e-12)
    x[edge] *= (1 + EDGE_NUDGE) / r[edge]
    y[edge] *= (1 + EDGE_NUDGE) / r[edge]
    N, T = _raw(x, y, z)
    near = (r > 0) & (r < RC)
    if near.any():
        xn, yn, zn = x[near], y[near], z[near]
        h = RC
        nodes = (-h, 0.0, h)

        def lag(t, k):  # quadratic Lagrange basis on nodes -h, 0, h
            if k == 0:
                return t * (t - h) / (2 * h * h)
            if k == 1:
                return (h - t) * (h + t) / (h * h)
            return t * (t + h) / (2 * h * h)

        Ni = np.zeros((6, near.sum()))
        Ti = np.zeros((6, near.sum()))
        for i, xi in enumerate(nodes):
            for j, yj in enumerate(nodes):
                nN, nT = _raw(np.full_like(zn, xi), np.full_like(zn, yj), zn)
                w = lag(xn, i) * lag(yn, j)
                Ni += w * nN
                Ti += w * nT
        N[:, near] = Ni
        T[:, near] = Ti
    return N.reshape((6,) + shape), T.reshape((6,) + shape)


def stress(x, y, z, mu):
    N, T = stress_parts(x, y, z)
    return N + mu * T


def von_mises(s):
    xx, yy, zz, yz, xz, xy = s
    return np.sqrt(0.5 * ((xx - yy) ** 2 + (yy - zz) ** 2 + (zz - xx) ** 2) + 3 * (yz**2 + xz**2 + xy**2))


def vm(x, y, z, mu):
    return von_mises(stress(x, y, z, mu))


# ------------------------------------------------------------------ grids
XG = np.round(np.linspace(-1.5, 1.5, 601), 12)
ZG = np.round(np.linspace(0.0, 1.5, 301), 12)
XS = np.unique(np.concatenate([np.round(np.linspace(-1.5, 1.5, 30001), 12), [-1.0, 1.0]]))
XX, ZZ = np.meshgrid(XG, ZG)
_GRID_PARTS = stress_parts(XX, 0 * XX, ZZ)
_SURF_PARTS = stress_parts(XS, 0 * XS, 0 * XS)


def surface_max(mu):
    v = von_mises(_SURF_PARTS[0] + mu * _SURF_PARTS[1])
    i = int(np.nanargmax(v))
    x0 = XS[i]
    lo, hi = XS[max(i - 1, 0)], XS[min(i + 1, len(XS) - 1)]
    res = optimize.minimize_scalar(
        lambda t: -vm(t, 0.0, 0.0, mu)[()], bounds=(lo, hi), method="bounded", options={"xatol": 1e-10}
    )
    if -res.fun > v[i]:
        return float(res.x), float(-res.fun)
    return float(x0), float(v[i])


def interior_max(mu, start=None):
    V = von_mises(_GRID_PARTS[0] + mu * _GRID_PARTS[1])
    if start is None:
        # interior local maxima of the grid (not on the surface row or next to it,
        # where vm rises monotonically towards the trailing-edge cusp), take the largest
        Vf = np.nan_to_num(V, nan=-1.0)
        loc = Vf == ndimage.maximum_filter(Vf, size=5, mode="nearest")
        loc[:3, :] = False
        loc[-1, :] = False
        loc[:, [0, -1]] = False
        cand = np.argwhere(loc)
        i = tuple(cand[np.argmax(Vf[loc])])
        start = (XX[i], ZZ[i])

    def f(p):
        return -vm(p[0], 0.0, p[1], mu)[()] if p[1] > 0 else 1.0

    res = optimize.minimize(
        f,
        start,
        method="Nelder-Mead",
        options={
            "xatol": 1e-9,
            "fatol": 1e-13,
            "maxiter": 20000,
            "initial_simplex": [start, (start[0] + 0.01, start[1]), (start[0], start[1] + 0.01)],
        },
    )
    return float(res.x[0]), float(res.x[1]), float(-res.fun)


def check_3d(mu, xb, zb, vmax):
    """Return max over y>0 (coarse grid + 3-D refinement) and along the surface circle."""
    x = np.linspace(-1.5, 1.5, 121)
    y = np.linspace(0.0125, 1.5, 120)
    z = np.linspace(0.0, 1.5, 121)
    X, Y, Z = np.meshgrid(x, y, z, indexing="ij")
    V = vm(X, Y, Z, mu)
    i = np.unravel_index(np.nanargmax(V), V.shape)
    g = (X[i], Y[i], Z[i], V[i])

    # 3-D Nelder-Mead from the y=0 maximum, displaced to y = 0.05
    def f(p):
        return -vm(p[0], p[1], p[2], mu)[()] if p[2] >= 0 else 1.0

    res = optimize.minimize(
        f, (xb, 0.05, max(zb, 0.02)), method="Nelder-Mead", options={"xatol": 1e-8, "fatol": 1e-12, "maxiter": 20000}
    )
    th = np.linspace(0, np.pi, 3601)
    ve = vm(np.cos(th) * (1 + 1e-15), np.sin(th) * (1 + 1e-15), 0 * th, mu)
    j = int(np.nanargmax(ve))
    return g, (res.x, -res.fun), (th[j], ve[j])


def main():
    ver = ContactMechanics.__version__
    print(f"ContactMechanics {ver}, numpy {np.__version__}, nu = {NU}")

    # ---------------------------------------------------------- sanity checks
    s0 = stress(0.0, 0.0, 0.0, 0.0)
    print("\nSanity checks")
    print(
        f"  centre, surface, mu=0: sxx={s0[0]:.6f} (Hertz -(1+2nu)/2 = {-(1 + 2 * NU) / 2:.6f}), szz={s0[2]:.6f} (-1)"
    )
    se = stress(-1.0, 0.0, 0.0, 0.0)
    print(
        f"  r=a surface, mu=0: srr=sxx={se[0]:.6f}, stt=syy={se[1]:.6f}; "
        f"(1-2nu)/3 = {(1 - 2 * NU) / 3:.6f};  vm={von_mises(se):.6f} "
        f"(= sqrt(3)(1-2nu)/3 = {np.sqrt(3) * (1 - 2 * NU) / 3:.6f}; "
        f"max shear (srr-stt)/2 = {(se[0] - se[1]) / 2:.6f})"
    )
    for mu in (0.1, 0.3, 0.5):
        se = stress(-1.0, 0.0, 0.0, mu)
        ref = (1 - 2 * NU) / 3 + np.pi * mu * (4 + NU) / 8
        print(f"  trailing edge x=-a, mu={mu}: sxx={se[0]:.6f}; Hamilton (1-2nu)/3+pi mu(4+nu)/8 = {ref:.6f}")
    xb, zb, vb = interior_max(0.0, start=(0.0, 0.45))
    print(
        f"  mu=0 interior max: vm={vb:.5f} at x={xb:.2e}, z={zb:.5f} "
        f"(Johnson 1985 3.4: ~0.62 p0 at 0.48a; p0/Y = {1 / vb:.4f})"
    )

    # ---------------------------------------------------------- table
    rows = []
    print("\n  mu    p0/Y     x/a      z/a     vm_surf  (x_s)    vm_sub  (x_sub, z_sub)   3-D check")
    for mu in MUS:
        xs, vs = surface_max(mu)
        xi, zi, vi = interior_max(mu)
        if vs > vi:
            xm, zm, vmax = xs, 0.0, vs
        else:
            xm, zm, vmax = xi, zi, vi
        g, (p3, v3), (the, vth) = check_3d(mu, xm, zm, vmax)
        ok = (g[3] <= vmax + 1e-6) and (v3 <= vmax + 1e-6) and (vth <= vmax + 1e-6)
        rows.append((mu, 1 / vmax, xm, zm, vs, vi, xi, zi))
        print(
            f" {mu:4.2f}  {1 / vmax:.5f} {xm:+.5f} {zm:.5f}   {vs:.5f} ({xs:+.4f})  {vi:.5f} "
            f"({xi:+.4f}, {zi:.4f})  y>0 grid max {g[3]:.5f}, 3-D NM {v3:.5f} at y={p3[1]:.1e},"
            f" edge-circle max {vth:.5f} at theta={np.degrees(the):.1f}deg  {'OK' if ok else 'CHECK!'}"
        )

    # ---------------------------------------------------------- crossover
    def diff(mu):
        return surface_max(mu)[1] - interior_max(mu)[2]

    mu_c = optimize.brentq(diff, 0.2, 0.45, xtol=1e-7)
    xi, zi, vi = interior_max(mu_c)
    print(
        f"\nCrossover: surface max = interior max at mu = {mu_c:.5f} "
        f"(vm = {vi:.5f} p0, p0/Y = {1 / vi:.4f}; interior peak at x={xi:.4f}, z={zi:.4f})"
    )

    # ---------------------------------------------------------- write CSV
    with open(OUT, "w") as fh:
        fh.write(
            "# First yield (von Mises) under a sliding Hertzian sphere, Hertz pressure "
            "p=p0*sqrt(1-r^2/a^2) + traction q=mu*p along +x (full sliding)\n"
        )
        fh.write(
            "# Source: closed-form stresses of G.M. Hamilton, Proc IMechE 197C (1983) 53-59, "
            f"as implemented in ContactMechanics {ver} (PyPI), "
            "ContactMechanics.ReferenceSolutions.Hertz.stress_Cartesian + "
            "mu*stress_for_tangential_loading\n"
        )
        fh.write(
            "# Library cross-checked against numerical integration of Boussinesq+Cerruti "
            "point-load solutions (check_integration.py): agreement ~1e-13 p0\n"
        )
        fh.write(
            f"# nu = {NU}; conventions: z = depth (>=0), tension positive, trailing edge at x=-a; "
            "all lengths /a, stresses /p0; Y = uniaxial yield stress (von Mises)\n"
        )
        fh.write(
            "# Grid: y=0 plane, x in [-1.5,1.5], z in [0,1.5] step 0.005 (incl. z=0); "
            "surface line z=0 step 1e-4 plus x=+-1 (edge limit); "
            "refinement: Nelder-Mead in (x,z) (xatol 1e-9) for the interior peak, "
            "bounded 1-D search on the surface (max is the cusp at x=-a)\n"
        )
        fh.write(
            "# Off-plane check: 121x120x121 grid over y in (0,1.5], 3-D Nelder-Mead, "
            "and the contact-edge circle: no value exceeds the y=0 maximum\n"
        )
        fh.write(
            "# vm_subsurface_max_over_p0 = interior (z>0) local maximum of the von Mises stress; "
            "vm_surface_max_over_p0 = max on z=0\n"
        )
        fh.write(f"# Surface maximum overtakes the interior one at mu = {mu_c:.4f} (brentq bisection)\n")
        fh.write("mu,p0_over_Y,x_over_a,z_over_a,vm_surface_max_over_p0,vm_subsurface_max_over_p0\n")
        for mu, p0y, xm, zm, vs, vi, _, _ in rows:
            xm = 0.0 if abs(xm) < 1e-6 else xm
            fh.write(f"{mu:.2f},{p0y:.5f},{xm:.5f},{zm:.5f},{vs:.5f},{vi:.5f}\n")
    print(f"\nwrote {OUT}")
    return 0


SURFACE_OUT = "/work/scratch/hamilton/hamilton_surface_mu05.csv"


def surface_profile(mu=0.5, step=1.0 / 64.0):
    """Hamilton's surface stresses along the plane of incidence y = 0 (z = 0), x in [-1.5, 1.5] a at ``step``:
    the table tests/data/hamilton_surface_mu05.csv (python hamilton_reference.py --surface)."""
    x = np.round(np.arange(-1.5, 1.5 + step / 2, step), 12)
    # at r = a exactly the library returns 0/0: the field is continuous, take the limit from outside
    xe = np.where(np.abs(np.abs(x) - 1.0) < 1e-12, x * (1.0 + 1e-15), x)
    s = stress(xe, 0.0 * xe, 0.0 * xe, mu)
    with open(SURFACE_OUT, "w") as fh:
        fh.write(
            f"# Surface stresses (z = 0, y = 0) under a sliding Hertzian sphere, mu = {mu}, nu = {NU}: Hertz pressure "
            "p = p0 sqrt(1 - r^2/a^2) and traction q = mu p along +x (trailing edge x = -a)\n"
        )
        fh.write(
            "# Source: G.M. Hamilton, Proc IMechE 197C (1983) 53-59, as implemented in ContactMechanics "
            f"{ContactMechanics.__version__} (PyPI), made by tests/data/hamilton_reference.py --surface\n"
        )
        fh.write("# lengths /a, stresses /p0, tension positive; vm = von Mises\n")
        fh.write("x_over_a,sxx,syy,szz,sxz,vm\n")
        for k in range(x.size):
            xx, yy, zz, _, xz, _ = s[:, k]
            fh.write(f"{x[k]:.6f},{xx:.5f},{yy:.5f},{zz:.5f},{xz:.5f},{von_mises(s[:, k]):.5f}\n")
    print(f"wrote {SURFACE_OUT}")
    return 0


if __name__ == "__main__":
    sys.exit(surface_profile() if "--surface" in sys.argv else main())
