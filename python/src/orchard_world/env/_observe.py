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
    return _reaches(body, fruit, distance, bearing)


def _reaches(body: Body, fruit: PerceivedFruit, distance: float, bearing: float) -> bool:
    return (body.gripper.min_height <= fruit.position.y <= body.gripper.max_height
            and distance <= body.radius + body.gripper.reach + fruit.radius and abs(bearing) <= math.pi / 3)


_FRUIT_AT = 5
_OBJECTS_AT = _FRUIT_AT + 9 * NEAREST_FRUIT
_AGENTS_AT = _OBJECTS_AT + 6 * NEAREST_OBJECTS
_RIVER_AT = _AGENTS_AT + 4 * NEAREST_AGENTS
_BRIDGES_AT = _RIVER_AT + 6
_CASTLE_AT = SIZE - len(SECTORS)
_KIND_AT = {kind: 6 + k for k, kind in enumerate(KINDS)}


def observe(p: LeanPerception, body: Body, bounds: Bounds, time_left: float) -> np.ndarray:
    # Filled as a list and made an array once: a learning agent observes hundreds of times a second.
    sin, cos = math.sin, math.cos
    o = [0.0] * SIZE
    seen = body.sight.range
    half_x, half_z = (bounds.max_x - bounds.min_x) / 2, (bounds.max_z - bounds.min_z) / 2
    o[0] = (p.position.x - (bounds.min_x + half_x)) / half_x
    o[1] = (p.position.z - (bounds.min_z + half_z)) / half_z
    o[2], o[3] = sin(p.heading), cos(p.heading)
    o[4] = time_left
    if p.fruit:
        fruit = sorted(((bearing_to(p, f.position.x, f.position.z), f.id, f) for f in p.fruit),
                       key=lambda e: (e[0][0], e[1]))
        i = _FRUIT_AT
        for (distance, bearing), _, f in fruit[:NEAREST_FRUIT]:
            o[i:i + 6] = (1.0, distance / seen, sin(bearing), cos(bearing), f.position.y / 4,
                          1.0 if _reaches(body, f, distance, bearing) else 0.0)
            o[i + _KIND_AT.get(f.kind, 8)] = 1.0
            i += 9
    i = _OBJECTS_AT
    for t in sorted(p.objects, key=lambda t: (t.at.distance, t.id))[:NEAREST_OBJECTS]:
        o[i:i + 6] = (1.0, t.at.distance / seen, sin(t.at.bearing), cos(t.at.bearing), t.radius / 4,
                      1.0 if t.kind == "tree" else 0.0)
        i += 6
    i = _AGENTS_AT
    for a in sorted(p.agents, key=lambda a: (a.at.distance, a.name))[:NEAREST_AGENTS]:
        o[i:i + 4] = (1.0, a.at.distance / seen, sin(a.at.bearing), cos(a.at.bearing))
        i += 4
    if p.river is not None:
        r = p.river
        o[_RIVER_AT:_RIVER_AT + 6] = (1.0, r.nearest.distance / seen, sin(r.nearest.bearing), cos(r.nearest.bearing),
                                      sin(r.across), cos(r.across))
    i = _BRIDGES_AT
    for b in sorted(p.bridges, key=lambda b: (b.entry_a.distance, b.id))[:NEAREST_BRIDGES]:
        o[i:i + 4] = (1.0, b.entry_a.distance / seen, sin(b.entry_a.bearing), cos(b.entry_a.bearing))
        i += 4
    if p.castle in SECTORS:
        o[_CASTLE_AT + SECTORS.index(p.castle)] = 1.0
    observation = np.array(o, dtype=np.float32)
    return np.clip(observation, -1.0, 1.0, out=observation)
