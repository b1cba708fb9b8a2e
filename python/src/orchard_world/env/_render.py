"""A top-down RGB drawing of the world as a viewer connection sees it: north up, east right."""
from __future__ import annotations

from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from ..messages import AgentMoved, Point2, Vec3, WorldSnapshot
from ._game import WorldView

GRASS = (96, 148, 72)
WATER = (64, 112, 200)
BRIDGE = (150, 110, 60)
CASTLE = (150, 150, 150)
TREE = (30, 90, 40)
TABLE = (170, 120, 70)
FRUIT = {"tomato": (220, 40, 40), "banana": (240, 220, 60), "coconut": (110, 70, 30)}
LEARNER = (255, 255, 255)
OTHER = (230, 60, 200)


class Painter:
    """Draws one world; the ground, river, bridges, castle and obstacles once, the rest each frame."""

    def __init__(self, snapshot: WorldSnapshot, size: int) -> None:
        b = snapshot.bounds
        self.size = size
        self.scale = size / max(b.max_x - b.min_x, b.max_z - b.min_z)
        self.origin = (b.min_x, b.min_z)
        xs = b.min_x + (np.arange(size) + 0.5) / self.scale
        zs = b.min_z + (np.arange(size) + 0.5) / self.scale
        self.gx, self.gz = np.meshgrid(xs, zs)
        base = np.empty((size, size, 3), dtype=np.uint8)
        base[:] = GRASS
        base[self._inside(snapshot.river)] = WATER
        for bridge in snapshot.bridges:
            base[self._near_segment(bridge.entry_a, bridge.entry_b, bridge.width / 2)] = BRIDGE
        base[self._inside(snapshot.castle)] = CASTLE
        for o in snapshot.obstacles:
            self._disc(base, o.position.x, o.position.z, o.radius, TREE if o.kind == "tree" else TABLE)
        self.base = base

    def _inside(self, polygon: Sequence[Point2]) -> np.ndarray:
        inside = np.zeros(self.gx.shape, dtype=bool)
        n = len(polygon)
        for i in range(n):
            a, c = polygon[i], polygon[(i + 1) % n]
            crosses = (a.z > self.gz) != (c.z > self.gz)
            with np.errstate(divide="ignore", invalid="ignore"):
                x_at = a.x + (self.gz - a.z) * (c.x - a.x) / (c.z - a.z)
            inside ^= crosses & (self.gx < x_at)
        return inside

    def _near_segment(self, a: Point2, c: Point2, half_width: float) -> np.ndarray:
        dx, dz = c.x - a.x, c.z - a.z
        length2 = dx * dx + dz * dz or 1.0
        t = np.clip(((self.gx - a.x) * dx + (self.gz - a.z) * dz) / length2, 0, 1)
        return np.hypot(self.gx - (a.x + t * dx), self.gz - (a.z + t * dz)) <= half_width

    def _disc(self, image: np.ndarray, x: float, z: float, radius: float, colour: Tuple[int, int, int]) -> None:
        r = max(radius * self.scale, 1.5)
        cx, cz = (x - self.origin[0]) * self.scale, (z - self.origin[1]) * self.scale
        x0, x1 = max(int(cx - r), 0), min(int(cx + r) + 2, self.size)
        z0, z1 = max(int(cz - r), 0), min(int(cz + r) + 2, self.size)
        if x0 >= x1 or z0 >= z1:
            return
        px, pz = np.meshgrid(np.arange(x0, x1) + 0.5, np.arange(z0, z1) + 0.5)
        image[z0:z1, x0:x1][(px - cx) ** 2 + (pz - cz) ** 2 <= r * r] = colour

    def frame(self, view: WorldView, learners: Sequence[str]) -> np.ndarray:
        image = self.base.copy()
        for f in view.fruit.values():
            self._disc(image, f.position.x, f.position.z, 0.6, FRUIT.get(f.kind, (0, 0, 0)))
        for name, (where, _heading, radius) in view.agents.items():
            x, z = _position(where, view.time)
            colour = LEARNER if name in learners else OTHER
            self._disc(image, x, z, max(float(radius), 3.0 / self.scale), colour)
        return image


def _position(where: object, time: float) -> Tuple[float, float]:
    if isinstance(where, AgentMoved):
        share = 1.0 if where.duration <= 0 else min(1.0, max(0.0, (time - where.start_time) / where.duration))
        return (where.start.x + (where.to.x - where.start.x) * share,
                where.start.z + (where.to.z - where.start.z) * share)
    assert isinstance(where, Vec3)
    return where.x, where.z


def draw(view: WorldView, learners: Sequence[str], size: int, cache: Dict[str, Painter]) -> np.ndarray:
    """The frame of ``view``; a black one before the world is known."""
    if view.snapshot is None:
        return np.zeros((size, size, 3), dtype=np.uint8)
    painter: Optional[Painter] = cache.get("painter")
    if painter is None or painter.size != size:
        painter = cache["painter"] = Painter(view.snapshot, size)
    return painter.frame(view, learners)


__all__: List[str] = ["draw"]
