"""The cumulative wear map of impacts at one site (SI units, m)."""

from __future__ import annotations

import math

import numpy as np
from scipy.interpolate import RegularGridInterpolator

from wear.integrate import WearMap, wear_map

__all__ = ["WearAccumulator"]


class WearAccumulator:
    """Cumulative 2-D wear on a grid of the first impact's spacing, at first its grid padded by half its size on each
    side, extended (zeros) whenever a later impact's map reaches past it — the scar widens as the seat conforms
    (contact radius 0.18 → 0.43 mm over 10⁴ impacts of the default case), and wear outside the grid would be lost."""

    def __init__(self, first: WearMap):
        h = first.spacing
        pad_x = (first.x.size // 2) * h
        pad_y = (first.y.size // 2) * h
        self.x = np.arange(first.x[0] - pad_x, first.x[-1] + pad_x + 0.5 * h, h)
        ny = int(round((first.y[-1] + pad_y) / h))
        self.y = np.arange(-ny, ny + 1) * h
        self.depth = np.zeros((self.y.size, self.x.size))
        self.density = first.density

    def _cover(self, wm: WearMap) -> None:
        h = self.x[1] - self.x[0]
        left = max(0, math.ceil((self.x[0] - wm.x[0]) / h - 1e-9))
        right = max(0, math.ceil((wm.x[-1] - self.x[-1]) / h - 1e-9))
        half = (self.y.size - 1) // 2
        ny = max(half, math.ceil(max(abs(wm.y[0]), abs(wm.y[-1])) / h - 1e-9))
        if left or right or ny > half:
            self.x = self.x[0] + (np.arange(self.x.size + left + right) - left) * h
            self.y = np.arange(-ny, ny + 1) * h
            self.depth = np.pad(self.depth, ((ny - half, ny - half), (left, right)))

    def add(self, wm: WearMap, count: int) -> None:
        self._cover(wm)
        f = RegularGridInterpolator((wm.y, wm.x), wm.depth, bounds_error=False, fill_value=0.0)
        yy, xx = np.meshgrid(self.y, self.x, indexing="ij")
        self.depth += count * f(np.stack([yy.ravel(), xx.ravel()], axis=1)).reshape(yy.shape)

    def map(self) -> WearMap:
        return wear_map(self.x, self.y, self.depth.copy(), self.density)
