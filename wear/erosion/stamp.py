r"""The per-impact height-field update of the stream erosion (:func:`wear.erosion.erode`), two engines.

:func:`stamp_impacts` (numba, ``cache=True``) and :func:`stamp_impacts_numpy` (plain numpy, vectorised over
the nodes of one footprint: the benchmark's reference) apply the same update, one impact after the other, to
the worn depth ``wear`` (m) and the ``relief`` (m: initial surface depth plus dents; surface = wear + relief)
of a periodic grid of spacing ``h`` (m), for the impact points ``positions`` (k, 2) (m). Per impact (see
:mod:`wear.erosion.patch`):

- the least-squares slope over the node offsets ``disc``, scaled by ``disc_norm`` = 1/(h Σ p²);
- the local angle and normal speed of the particle ``direction`` = (sin θ cos ψ, sin θ sin ψ, cos θ, cos ψ,
  sin ψ) at ``speed`` (m/s);
- the table's four entries at (``speed``, θ_l) and their weights (:func:`wear.erosion.table.table_entries`: axes
  ``vn_axis`` m/s, ``angle_axis`` deg, ``volume`` m³), which weigh ``shape``, ``length`` (m) and ``dent_table``
  (footprint grid origin ``u0``, ``v0`` and spacing ``du`` in units of L);
- the rotated footprint sampled at the nodes, rescaled to the interpolated volume, and added.

``scratch``/``dent_scratch`` are work arrays; ``counts`` [shadowed, clamped] and ``removed`` [m³] are
accumulated in place.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from wear.erosion.table import table_entries

__all__ = ["stamp_impacts", "stamp_impacts_numpy", "GRAZING_ANGLE"]

#: Local angles at or beyond this (deg from the local normal) count as shadowed: no impact.
GRAZING_ANGLE = 89.0


@numba.njit(cache=True)
def stamp_impacts(
    wear,
    relief,
    positions,
    h,
    disc,
    disc_norm,
    direction,
    speed,
    vn_axis,
    angle_axis,
    shape,
    volume,
    length,
    dent_table,
    u0,
    v0,
    du,
    scratch,
    dent_scratch,
    counts,
    removed,
):
    ny, nx = wear.shape
    nv, nu = shape.shape[2], shape.shape[3]
    has_dent = dent_table.shape[0] > 0
    dxs, dys, dzs = direction[0], direction[1], direction[2]
    cos_grazing = math.cos(math.radians(GRAZING_ANGLE))
    inv_du = 1.0 / du
    for k in range(positions.shape[0]):
        x0 = positions[k, 0]
        y0 = positions[k, 1]
        i0 = int(math.floor(x0 / h + 0.5)) % nx
        j0 = int(math.floor(y0 / h + 0.5)) % ny
        # least-squares plane over the disc of nodes |offset| <= slope_cells (isotropic, unlike a cross)
        sx = 0.0
        sy = 0.0
        for m in range(disc.shape[0]):
            p = disc[m, 0]
            q = disc[m, 1]
            row = (j0 + q) % ny
            col = (i0 + p) % nx
            z = wear[row, col] + relief[row, col]
            sx += p * z
            sy += q * z
        sx *= disc_norm
        sy *= disc_norm
        norm = math.sqrt(1.0 + sx * sx + sy * sy)
        nxn, nyn, nzn = sx / norm, sy / norm, 1.0 / norm
        # direction = (sin θ cos ψ, sin θ sin ψ, cos θ) with the particle moving down (−z)
        cos_l = -(dxs * nxn + dys * nyn - dzs * nzn)
        if cos_l <= cos_grazing:
            counts[0] += 1
            continue
        tx = dxs + cos_l * nxn
        ty = dys + cos_l * nyn
        th = math.sqrt(tx * tx + ty * ty)
        if th > 1e-12:
            c, s = tx / th, ty / th
        else:
            c, s = direction[3], direction[4]
        theta_l = math.degrees(math.acos(min(cos_l, 1.0)))
        entries, vol, outside = table_entries(vn_axis, angle_axis, volume, speed, theta_l)
        if outside:
            counts[1] += 1
        L = 0.0
        for a, b, w in entries:
            L += w * length[a, b]
        if vol <= 0.0 and not has_dent:
            continue
        # bounding box of the rotated footprint rectangle, in nodes
        u1 = u0 + (nu - 1) * du
        v1 = v0 + (nv - 1) * du
        xmin = ymin = 1e300
        xmax = ymax = -1e300
        for cu in (u0, u1):
            for cv in (v0, v1):
                px = L * (cu * c - cv * s)
                py = L * (cu * s + cv * c)
                xmin, xmax = min(xmin, px), max(xmax, px)
                ymin, ymax = min(ymin, py), max(ymax, py)
        ilo = int(math.ceil((x0 + xmin) / h))
        ihi = int(math.floor((x0 + xmax) / h))
        jlo = int(math.ceil((y0 + ymin) / h))
        jhi = int(math.floor((y0 + ymax) / h))
        width = ihi - ilo + 1
        total = 0.0
        inv_L = 1.0 / L
        for jj in range(jlo, jhi + 1):
            dy = jj * h - y0
            for ii in range(ilo, ihi + 1):
                dx = ii * h - x0
                fu = ((dx * c + dy * s) * inv_L - u0) * inv_du
                fv = ((-dx * s + dy * c) * inv_L - v0) * inv_du
                cell = (jj - jlo) * width + (ii - ilo)
                scratch[cell] = 0.0
                if has_dent:
                    dent_scratch[cell] = 0.0
                if fu < 0.0 or fv < 0.0 or fu >= nu - 1 or fv >= nv - 1:
                    continue
                ku = int(fu)
                kv = int(fv)
                gu = fu - ku
                gv = fv - kv
                c00 = (1.0 - gu) * (1.0 - gv)
                c01 = gu * (1.0 - gv)
                c10 = (1.0 - gu) * gv
                c11 = gu * gv
                val = 0.0
                for a, b, w in entries:
                    if w == 0.0:
                        continue
                    t = shape[a, b]
                    val += w * (c00 * t[kv, ku] + c01 * t[kv, ku + 1] + c10 * t[kv + 1, ku] + c11 * t[kv + 1, ku + 1])
                    if has_dent:
                        d = dent_table[a, b]
                        dent_scratch[cell] += (
                            w
                            * L
                            * (c00 * d[kv, ku] + c01 * d[kv, ku + 1] + c10 * d[kv + 1, ku] + c11 * d[kv + 1, ku + 1])
                        )
                scratch[cell] = val
                total += val
        if vol > 0.0 and total <= 0.0:  # footprint between nodes: put its volume on the nearest node
            wear[j0, i0] += vol / (h * h)
            removed[0] += vol
        elif vol > 0.0:
            scale = vol / (total * h * h)
            for jj in range(jlo, jhi + 1):
                row = jj % ny
                for ii in range(ilo, ihi + 1):
                    wear[row, ii % nx] += scale * scratch[(jj - jlo) * width + (ii - ilo)]
            removed[0] += vol
        if has_dent:
            for jj in range(jlo, jhi + 1):
                row = jj % ny
                for ii in range(ilo, ihi + 1):
                    relief[row, ii % nx] += dent_scratch[(jj - jlo) * width + (ii - ilo)]


def stamp_impacts_numpy(
    wear,
    relief,
    positions,
    h,
    disc,
    disc_norm,
    direction,
    speed,
    vn_axis,
    angle_axis,
    shape,
    volume,
    length,
    dent_table,
    u0,
    v0,
    du,
    scratch,
    dent_scratch,
    counts,
    removed,
):
    """Plain numpy version of :func:`stamp_impacts` (same algorithm, vectorised over the nodes of one
    footprint): the benchmark's reference. ``scratch`` arguments are unused."""
    ny, nx = wear.shape
    nv, nu = shape.shape[2], shape.shape[3]
    has_dent = dent_table.shape[0] > 0
    d = np.asarray(direction[:3])
    u1, v1 = u0 + (nu - 1) * du, v0 + (nv - 1) * du
    cos_grazing = math.cos(math.radians(GRAZING_ANGLE))
    for x0, y0 in positions:
        i0, j0 = int(math.floor(x0 / h + 0.5)) % nx, int(math.floor(y0 / h + 0.5)) % ny
        rows, cols = (j0 + disc[:, 1]) % ny, (i0 + disc[:, 0]) % nx
        z = wear[rows, cols] + relief[rows, cols]
        sx, sy = float(disc[:, 0] @ z) * disc_norm, float(disc[:, 1] @ z) * disc_norm
        n = np.array([sx, sy, 1.0]) / math.sqrt(1.0 + sx * sx + sy * sy)
        cos_l = -(d[0] * n[0] + d[1] * n[1] - d[2] * n[2])
        if cos_l <= cos_grazing:
            counts[0] += 1
            continue
        t = d[:2] + cos_l * n[:2]
        th = math.hypot(t[0], t[1])
        c, s = (t[0] / th, t[1] / th) if th > 1e-12 else (direction[3], direction[4])
        theta_l = math.degrees(math.acos(min(cos_l, 1.0)))
        entries, vol, outside = table_entries(vn_axis, angle_axis, volume, speed, theta_l)
        if outside:
            counts[1] += 1
        L = sum(w * length[a, b] for a, b, w in entries)
        if vol <= 0.0 and not has_dent:
            continue
        corners = np.array([[cu * c - cv * s, cu * s + cv * c] for cu in (u0, u1) for cv in (v0, v1)]) * L
        ii = np.arange(math.ceil((x0 + corners[:, 0].min()) / h), math.floor((x0 + corners[:, 0].max()) / h) + 1)
        jj = np.arange(math.ceil((y0 + corners[:, 1].min()) / h), math.floor((y0 + corners[:, 1].max()) / h) + 1)
        dx, dy = ii[None, :] * h - x0, jj[:, None] * h - y0
        fu = ((dx * c + dy * s) / L - u0) / du
        fv = ((-dx * s + dy * c) / L - v0) / du
        inside = (fu >= 0) & (fv >= 0) & (fu < nu - 1) & (fv < nv - 1)
        ku, kv = np.where(inside, fu, 0).astype(np.int64), np.where(inside, fv, 0).astype(np.int64)
        gu, gv = fu - ku, fv - kv
        val = np.zeros(fu.shape)
        dval = np.zeros(fu.shape)
        for a, b, w in entries:
            if w == 0.0:
                continue
            for tab, acc, factor in ((shape[a, b], val, w), (dent_table[a, b] if has_dent else None, dval, w * L)):
                if tab is None:
                    continue
                acc += factor * (
                    (1 - gu) * (1 - gv) * tab[kv, ku]
                    + gu * (1 - gv) * tab[kv, ku + 1]
                    + (1 - gu) * gv * tab[kv + 1, ku]
                    + gu * gv * tab[kv + 1, ku + 1]
                )
        val = np.where(inside, val, 0.0)
        rows, cols = np.ix_(jj % ny, ii % nx)
        total = val.sum()
        if vol > 0.0 and total <= 0.0:
            wear[j0, i0] += vol / (h * h)
            removed[0] += vol
        elif vol > 0.0:
            np.add.at(wear, (rows, cols), vol / (total * h * h) * val)
            removed[0] += vol
        if has_dent:
            np.add.at(relief, (rows, cols), np.where(inside, dval, 0.0))
