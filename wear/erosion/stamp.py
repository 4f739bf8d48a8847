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
        nxn, nyn, nzn = _local_normal(wear, relief, disc, disc_norm, i0, j0)
        # direction = (sin θ cos ψ, sin θ sin ψ, cos θ) with the particle moving down (−z)
        cos_l = -(dxs * nxn + dys * nyn - dzs * nzn)
        if cos_l <= cos_grazing:
            counts[0] += 1
            continue
        c, s = _tangential_axis(dxs, dys, cos_l, nxn, nyn, direction[3], direction[4])
        theta_l = math.degrees(math.acos(min(cos_l, 1.0)))
        entries, vol, outside = table_entries(vn_axis, angle_axis, volume, speed, theta_l)
        if outside:
            counts[1] += 1
        L = 0.0
        for a, b, w in entries:
            L += w * length[a, b]
        if vol <= 0.0 and not has_dent:
            continue
        ilo, ihi, jlo, jhi = _footprint_box(x0, y0, L, c, s, u0, v0, u0 + (nu - 1) * du, v0 + (nv - 1) * du, h)
        total = _sample_footprint(
            shape, dent_table, entries, x0, y0, L, c, s, u0, v0, inv_du, h, ilo, ihi, jlo, jhi, scratch, dent_scratch
        )
        if vol > 0.0 and total <= 0.0:  # footprint between nodes: put its volume on the nearest node
            wear[j0, i0] += vol / (h * h)
            removed[0] += vol
        elif vol > 0.0:
            _add_scaled(wear, scratch, vol / (total * h * h), ilo, ihi, jlo, jhi)
            removed[0] += vol
        if has_dent:
            _add(relief, dent_scratch, ilo, ihi, jlo, jhi)


# The kernel's steps below are inlined into it by numba (inline="always"): the same machine code as one function.


@numba.njit(cache=True, inline="always")
def _local_normal(wear, relief, disc, disc_norm, i0, j0):
    """Unit normal (x, y, z) of the least-squares plane of the surface wear + relief (m) over the node offsets
    ``disc`` around node (``i0``, ``j0``), periodic; ``disc_norm`` = 1/(h Σ p²) (1/m)."""
    ny, nx = wear.shape
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
    return sx / norm, sy / norm, 1.0 / norm


@numba.njit(cache=True, inline="always")
def _tangential_axis(dxs, dys, cos_l, nxn, nyn, cos_psi, sin_psi):
    """(cos, sin) of the footprint's u axis: the horizontal projection of the particle's tangential velocity
    d − (d·n)n (d = (``dxs``, ``dys``, ·), local normal (``nxn``, ``nyn``, ·), cos_l = −d·n); the stream's azimuth
    (``cos_psi``, ``sin_psi``) at normal local incidence, where that projection vanishes."""
    tx = dxs + cos_l * nxn
    ty = dys + cos_l * nyn
    th = math.sqrt(tx * tx + ty * ty)
    if th > 1e-12:
        return tx / th, ty / th
    return cos_psi, sin_psi


@numba.njit(cache=True, inline="always")
def _footprint_box(x0, y0, L, c, s, u0, v0, u1, v1, h):
    """Node index ranges (ilo, ihi, jlo, jhi), inclusive and not yet wrapped, of the bounding box of the footprint
    rectangle [u0, u1] × [v0, v1] (units of ``L``, m) rotated by (``c``, ``s``) about the impact point (``x0``,
    ``y0``) (m) on the grid of spacing ``h`` (m)."""
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
    return ilo, ihi, jlo, jhi


@numba.njit(cache=True, inline="always")
def _bilinear(t, kv, ku, c00, c01, c10, c11):
    """The grid ``t`` at cell (``kv``, ``ku``) with the bilinear weights of its four corners."""
    return c00 * t[kv, ku] + c01 * t[kv, ku + 1] + c10 * t[kv + 1, ku] + c11 * t[kv + 1, ku + 1]


@numba.njit(cache=True, inline="always")
def _sample_footprint(
    shape, dent_table, entries, x0, y0, L, c, s, u0, v0, inv_du, h, ilo, ihi, jlo, jhi, scratch, dent_scratch
):
    """Sample the table's footprint (its ``entries`` weighing ``shape`` and, if it has one, ``dent_table`` × ``L``
    (m)) at the nodes of the box [ilo, ihi] × [jlo, jhi] into ``scratch`` and ``dent_scratch`` (row-major over the
    box, 0 outside the footprint grid); the footprint is rotated by (``c``, ``s``) about the impact point (``x0``,
    ``y0``) (m), its grid of origin (``u0``, ``v0``) and spacing 1/``inv_du`` in units of ``L``. Returns the sum
    of the samples of ``shape``."""
    nv, nu = shape.shape[2], shape.shape[3]
    has_dent = dent_table.shape[0] > 0
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
                val += w * _bilinear(shape[a, b], kv, ku, c00, c01, c10, c11)
                if has_dent:
                    dent_scratch[cell] += w * L * _bilinear(dent_table[a, b], kv, ku, c00, c01, c10, c11)
            scratch[cell] = val
            total += val
    return total


@numba.njit(cache=True, inline="always")
def _add_scaled(field, values, scale, ilo, ihi, jlo, jhi):
    """Add ``scale`` × ``values`` (row-major over the box [ilo, ihi] × [jlo, jhi]) to the periodic ``field``."""
    ny, nx = field.shape
    width = ihi - ilo + 1
    for jj in range(jlo, jhi + 1):
        row = jj % ny
        for ii in range(ilo, ihi + 1):
            field[row, ii % nx] += scale * values[(jj - jlo) * width + (ii - ilo)]


@numba.njit(cache=True, inline="always")
def _add(field, values, ilo, ihi, jlo, jhi):
    """Add ``values`` (row-major over the box [ilo, ihi] × [jlo, jhi]) to the periodic ``field``."""
    ny, nx = field.shape
    width = ihi - ilo + 1
    for jj in range(jlo, jhi + 1):
        row = jj % ny
        for ii in range(ilo, ihi + 1):
            field[row, ii % nx] += values[(jj - jlo) * width + (ii - ilo)]


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
        n = _local_normal_numpy(wear, relief, disc, disc_norm, i0, j0)
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
        val, dval, inside = _sample_footprint_numpy(shape, dent_table if has_dent else None, entries, L, fu, fv)
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


def _local_normal_numpy(
    wear: np.ndarray, relief: np.ndarray, disc: np.ndarray, disc_norm: float, i0: int, j0: int
) -> np.ndarray:
    """Unit normal (x, y, z) of the least-squares plane of wear + relief (m) over the offsets ``disc`` around node
    (``i0``, ``j0``), periodic (as :func:`_local_normal`)."""
    ny, nx = wear.shape
    rows, cols = (j0 + disc[:, 1]) % ny, (i0 + disc[:, 0]) % nx
    z = wear[rows, cols] + relief[rows, cols]
    sx, sy = float(disc[:, 0] @ z) * disc_norm, float(disc[:, 1] @ z) * disc_norm
    return np.array([sx, sy, 1.0]) / math.sqrt(1.0 + sx * sx + sy * sy)


def _sample_footprint_numpy(
    shape: np.ndarray, dent_table: np.ndarray | None, entries, L: float, fu: np.ndarray, fv: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The footprint of the table's ``entries`` at the fractional footprint-grid coordinates (``fu``, ``fv``) of the
    nodes: ``shape`` sampled (0 outside the grid), ``dent_table`` × ``L`` (m) sampled (where inside; zeros without
    a dent table), and the mask of the nodes inside the grid."""
    nv, nu = shape.shape[2], shape.shape[3]
    inside = (fu >= 0) & (fv >= 0) & (fu < nu - 1) & (fv < nv - 1)
    ku, kv = np.where(inside, fu, 0).astype(np.int64), np.where(inside, fv, 0).astype(np.int64)
    gu, gv = fu - ku, fv - kv
    val = np.zeros(fu.shape)
    dval = np.zeros(fu.shape)
    for a, b, w in entries:
        if w == 0.0:
            continue
        for tab, acc, factor in (
            (shape[a, b], val, w),
            (dent_table[a, b] if dent_table is not None else None, dval, w * L),
        ):
            if tab is None:
                continue
            acc += factor * (
                (1 - gu) * (1 - gv) * tab[kv, ku]
                + gu * (1 - gv) * tab[kv, ku + 1]
                + (1 - gu) * gv * tab[kv + 1, ku]
                + gu * gv * tab[kv + 1, ku + 1]
            )
    return np.where(inside, val, 0.0), dval, inside
