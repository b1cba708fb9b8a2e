"""The box around a model's points as its nodes' transforms place them: 4x4 matrices, column-major as glTF writes them.

The arithmetic is done in the order the Java ``ModelInfo`` does it, so that both give the same numbers.
"""
from __future__ import annotations

import math
from typing import List, Sequence

IDENTITY = (1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0)


class Extent:
    """The lowest and highest corner of the points taken in so far."""

    def __init__(self) -> None:
        self.min = [math.inf, math.inf, math.inf]
        self.max = [-math.inf, -math.inf, -math.inf]

    def is_empty(self) -> bool:
        return not self.min[0] <= self.max[0]

    def add(self, m: Sequence[float], x: float, y: float, z: float) -> None:
        """Takes in the point (x, y, z) placed by ``m``."""
        p = (m[0] * x + m[4] * y + m[8] * z + m[12],
             m[1] * x + m[5] * y + m[9] * z + m[13],
             m[2] * x + m[6] * y + m[10] * z + m[14])
        for a in range(3):
            if math.isfinite(p[a]):
                self.min[a] = _java_min(self.min[a], p[a])
                self.max[a] = _java_max(self.max[a], p[a])

    def add_box(self, m: Sequence[float], low: Sequence[float], high: Sequence[float]) -> None:
        """Takes in the eight corners of the box from ``low`` to ``high``, placed by ``m``."""
        for corner in range(8):
            self.add(m, low[0] if corner & 1 == 0 else high[0], low[1] if corner & 2 == 0 else high[1],
                     low[2] if corner & 4 == 0 else high[2])


def _java_min(a: float, b: float) -> float:
    # Math.min: -0.0 is less than 0.0.
    if a == b == 0.0:
        return a if math.copysign(1.0, a) < 0 else b
    return a if a < b else b


def _java_max(a: float, b: float) -> float:
    if a == b == 0.0:
        return a if math.copysign(1.0, a) > 0 else b
    return a if a > b else b


def multiply(a: Sequence[float], b: Sequence[float]) -> List[float]:
    out = [0.0] * 16
    for column in range(4):
        for row in range(4):
            total = 0.0
            for k in range(4):
                total += a[k * 4 + row] * b[column * 4 + k]
            out[column * 4 + row] = total
    return out


def trs(t: Sequence[float], q: Sequence[float], s: Sequence[float]) -> List[float]:
    """Translation, then rotation by the unit quaternion (qx, qy, qz, qw), then scale, as glTF composes them."""
    x, y, z, w = q[0], q[1], q[2], q[3]
    n = math.sqrt(x * x + y * y + z * z + w * w)
    if n > 0:
        x, y, z, w = x / n, y / n, z / n, w / n
    return [
        (1 - 2 * (y * y + z * z)) * s[0], 2 * (x * y + z * w) * s[0], 2 * (x * z - y * w) * s[0], 0.0,
        2 * (x * y - z * w) * s[1], (1 - 2 * (x * x + z * z)) * s[1], 2 * (y * z + x * w) * s[1], 0.0,
        2 * (x * z + y * w) * s[2], 2 * (y * z - x * w) * s[2], (1 - 2 * (x * x + y * y)) * s[2], 0.0,
        t[0], t[1], t[2], 1.0,
    ]


def axis_angle(x: float, y: float, z: float, angle: float) -> List[float]:
    """The quaternion of a rotation by ``angle`` radians about the axis (x, y, z)."""
    length = math.sqrt(x * x + y * y + z * z)
    if length == 0:
        return [0.0, 0.0, 0.0, 1.0]
    sin = math.sin(angle / 2) / length
    return [x * sin, y * sin, z * sin, math.cos(angle / 2)]
