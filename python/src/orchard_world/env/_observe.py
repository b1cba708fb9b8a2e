"""The fixed-shape observation of one agent, from its perception, and the actions it may take."""
from __future__ import annotations

import math
from typing import List, Tuple

import numpy as np
from gymnasium import spaces

from ..messages import SECTORS, Body, Bounds, LeanPerception, PerceivedFruit

NEAREST_FRUIT = 5
NEAREST_OBJECTS = 3
NEAREST_AGENTS = 3
NEAREST_BRIDGES = 2
KINDS = ("tomato", "banana", "coconut")

# The observation's fields in order; docs/python.md has the same table.
FIELDS: List[str] = ["self.x", "self.z", "self.sin_heading", "self.cos_heading", "self.time_left"]
for _i in range(NEAREST_FRUIT):
    FIELDS += [f"fruit{_i}.{n}" for n in ("present", "distance", "sin_bearing", "cos_bearing", "height",
                                           "graspable", "tomato", "banana", "coconut")]
for _i in range(NEAREST_OBJECTS):
    FIELDS += [f"object{_i}.{n}" for n in ("present", "distance", "sin_bearing", "cos_bearing", "radius", "tree")]
for _i in range(NEAREST_AGENTS):
    FIELDS += [f"agent{_i}.{n}" for n in ("present", "distance", "sin_bearing", "cos_bearing")]
FIELDS += ["river.present", "river.distance", "river.sin_bearing", "river.cos_bearing", "river.sin_across",
           "river.cos_across"]
for _i in range(NEAREST_BRIDGES):
    FIELDS += [f"bridge{_i}.{n}" for n in ("present", "distance", "sin_bearing", "cos_bearing")]
FIELDS += [f"castle.{s}" for s in SECTORS]
SIZE = len(FIELDS)

ACTIONS = ("stay", "forward", "turn_left", "turn_right", "grasp")
STAY, FORWARD, TURN_LEFT, TURN_RIGHT, GRASP = range(len(ACTIONS))


def observation_space() -> spaces.Box:
    return spaces.Box(low=-1.0, high=1.0, shape=(SIZE,), dtype=np.float32)


def action_space() -> spaces.Discrete:
    return spaces.Discrete(len(ACTIONS))


def bearing_to(p: LeanPerception, x: float, z: float) -> Tuple[float, float]:
    """Distance and bearing from the perceiving agent to the ground point (x, z) (protocol 3.3)."""
    dx, dz = x - p.position.x, z - p.position.z
    b = math.atan2(-dx, -dz) - p.heading
    b = (b + math.pi) % (2 * math.pi) - math.pi
    return math.hypot(dx, dz), b


def graspable(p: LeanPerception, body: Body, fruit: PerceivedFruit) -> bool:
    """Whether a grasp of ``fruit`` would succeed from here (protocol 10.4)."""
    distance, bearing = bearing_to(p, fruit.position.x, fruit.position.z)
    return (body.gripper.min_height <= fruit.position.y <= body.gripper.max_height
            and distance <= body.radius + body.gripper.reach + fruit.radius and abs(bearing) <= math.pi / 3)


def observe(p: LeanPerception, body: Body, bounds: Bounds, time_left: float) -> np.ndarray:
    o = np.zeros(SIZE, dtype=np.float32)
    seen = body.sight.range
    half_x, half_z = (bounds.max_x - bounds.min_x) / 2, (bounds.max_z - bounds.min_z) / 2
    o[0] = (p.position.x - (bounds.min_x + half_x)) / half_x
    o[1] = (p.position.z - (bounds.min_z + half_z)) / half_z
    o[2], o[3] = math.sin(p.heading), math.cos(p.heading)
    o[4] = time_left
    i = 5
    fruit = sorted(((bearing_to(p, f.position.x, f.position.z), f) for f in p.fruit), key=lambda e: (e[0][0], e[1].id))
    for (distance, bearing), f in fruit[:NEAREST_FRUIT]:
        o[i:i + 6] = (1, distance / seen, math.sin(bearing), math.cos(bearing), f.position.y / 4,
                      graspable(p, body, f))
        o[i + 6 + KINDS.index(f.kind) if f.kind in KINDS else i + 8] = 1
        i += 9
    i = 5 + 9 * NEAREST_FRUIT
    for t in sorted(p.objects, key=lambda t: (t.at.distance, t.id))[:NEAREST_OBJECTS]:
        o[i:i + 6] = (1, t.at.distance / seen, math.sin(t.at.bearing), math.cos(t.at.bearing), t.radius / 4,
                      t.kind == "tree")
        i += 6
    i = 5 + 9 * NEAREST_FRUIT + 6 * NEAREST_OBJECTS
    for a in sorted(p.agents, key=lambda a: (a.at.distance, a.name))[:NEAREST_AGENTS]:
        o[i:i + 4] = (1, a.at.distance / seen, math.sin(a.at.bearing), math.cos(a.at.bearing))
        i += 4
    i = 5 + 9 * NEAREST_FRUIT + 6 * NEAREST_OBJECTS + 4 * NEAREST_AGENTS
    if p.river is not None:
        r = p.river
        o[i:i + 6] = (1, r.nearest.distance / seen, math.sin(r.nearest.bearing), math.cos(r.nearest.bearing),
                      math.sin(r.across), math.cos(r.across))
    i += 6
    for b in sorted(p.bridges, key=lambda b: (b.entry_a.distance, b.id))[:NEAREST_BRIDGES]:
        o[i:i + 4] = (1, b.entry_a.distance / seen, math.sin(b.entry_a.bearing), math.cos(b.entry_a.bearing))
        i += 4
    i = SIZE - len(SECTORS)
    if p.castle in SECTORS:
        o[i + SECTORS.index(p.castle)] = 1
    return np.clip(o, -1.0, 1.0)
