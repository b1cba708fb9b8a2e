"""The protocol's messages as typed, immutable values, and their JSON lines (docs/protocol.md).

Messages a client sends have ``to_wire(seq)``, which gives the JSON object of the line; messages a
server sends are read by :func:`decode`, which gives the typed message or raises
:class:`~orchard_world.errors.ProtocolError` naming the field that is wrong. A line whose type
this version does not know decodes to :class:`Unknown`, as section 2.6 asks (skip, do not close).

Units are the protocol's: lengths in units (about a metre), angles in radians, headings with 0 to
the north (-z) and positive to the left. The lean form's centimetres and milliradians (section 16)
are converted back on reading, so a :class:`LeanPerception` holds the same numbers as the
ordinary ``Perception``, ``LandmarkPerception`` and ``CastlePerception`` together.
"""
from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, List, Optional, Tuple, Union

from .errors import ProtocolError

PROTOCOL_VERSION = 2
NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_-]{0,31}$")
FRUIT_RADIUS = {"tomato": 0.15, "banana": 0.25, "coconut": 0.35}
FRUIT_POINTS = {"tomato": 1, "banana": 2, "coconut": 3}
SECTORS = ("north", "north-east", "east", "south-east", "south", "south-west", "west", "north-west")


def check_name(what: str, name: str) -> str:
    """``name`` when it is a protocol name, else a ValueError naming it and the rule."""
    if not isinstance(name, str) or not NAME.match(name):
        raise ValueError(f"{what} must be a letter then up to 31 letters, digits, '_' or '-', was {name!r}")
    return name


# ---- values (section 6) ----------------------------------------------------------------------

@dataclass(frozen=True)
class Vec3:
    """A point in the world: x east, y up, z south."""
    x: float
    y: float
    z: float

    def wire(self) -> Dict[str, float]:
        return {"x": self.x, "y": self.y, "z": self.z}


@dataclass(frozen=True)
class Point2:
    """A point on the ground."""
    x: float
    z: float


@dataclass(frozen=True)
class Bounds:
    """The walkable rectangle; min_z is its north edge."""
    min_x: float
    min_z: float
    max_x: float
    max_z: float


@dataclass(frozen=True)
class Gripper:
    """What an agent collects fruit with."""
    part: str = "hands"
    reach: float = 0.6
    min_height: float = 0.0
    max_height: float = 1.5

    def wire(self) -> Dict[str, Any]:
        return {"part": self.part, "reach": self.reach, "minHeight": self.min_height, "maxHeight": self.max_height}


@dataclass(frozen=True)
class Sight:
    """How far and how wide an agent perceives; field_of_view is the full angle."""
    range: float = 40.0
    field_of_view: float = math.pi * 1.5

    def wire(self) -> Dict[str, Any]:
        return {"range": self.range, "fieldOfView": self.field_of_view}


@dataclass(frozen=True)
class Body:
    """An agent's body: a cylinder that walks at up to max_speed, with a gripper and sight."""
    radius: float = 0.5
    height: float = 1.5
    max_speed: float = 5.0
    gripper: Gripper = field(default_factory=Gripper)
    sight: Sight = field(default_factory=Sight)

    def __post_init__(self) -> None:
        for name in ("radius", "height", "max_speed"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
                raise ValueError(f"Body.{name} must be a finite number > 0, was {value!r}")

    def wire(self) -> Dict[str, Any]:
        return {"radius": self.radius, "height": self.height, "maxSpeed": self.max_speed,
                "gripper": self.gripper.wire(), "sight": self.sight.wire()}


@dataclass(frozen=True)
class Score:
    """One agent's standing."""
    agent: str
    points: int
    fruit: int


@dataclass(frozen=True)
class RelativePosition:
    """Where something is as the agent sees it: bearing 0 ahead, positive to the left."""
    distance: float
    bearing: float


@dataclass(frozen=True)
class PerceivedObject:
    """A tree or a table in view."""
    id: str
    kind: str
    at: RelativePosition
    radius: float
    height: float


@dataclass(frozen=True)
class PerceivedAgent:
    """Another agent in view; heading is relative to the perceiver's."""
    name: str
    at: RelativePosition
    heading: float
    radius: float


@dataclass(frozen=True)
class PerceivedFruit:
    """A fruit in view, by its absolute position; support is None on the ground."""
    id: str
    kind: str
    position: Vec3
    radius: float
    support: Optional[str] = None


@dataclass(frozen=True)
class PerceivedRiver:
    """The river: the nearest point of its bank and the direction it runs in."""
    nearest: RelativePosition
    across: float


@dataclass(frozen=True)
class PerceivedBridge:
    """A bridge by its two entries: entry_a on the agent's bank."""
    id: str
    entry_a: RelativePosition
    entry_b: RelativePosition
    width: float


# ---- client to server (section 7) ------------------------------------------------------------

@dataclass(frozen=True)
class Hello:
    role: str = "agent"
    client: str = "orchard_world"
    protocol_version: int = PROTOCOL_VERSION
    token: Optional[str] = None
    operator_token: Optional[str] = None
    reads: Tuple[str, ...] = ("LeanPerception",)

    def to_wire(self, seq: int) -> Dict[str, Any]:
        if self.role not in ("agent", "viewer"):
            raise ValueError(f"role must be one of 'agent', 'viewer', was {self.role!r}")
        m: Dict[str, Any] = {"type": "Hello", "seq": seq, "protocolVersion": self.protocol_version,
                             "role": self.role, "client": self.client}
        if self.token is not None:
            m["token"] = self.token
        if self.operator_token is not None:
            m["operatorToken"] = self.operator_token
        if self.reads:
            m["reads"] = list(self.reads)
        return m


@dataclass(frozen=True)
class Register:
    name: str
    body: Body = field(default_factory=Body)
    bundled_model: Optional[str] = "figure"

    def to_wire(self, seq: int) -> Dict[str, Any]:
        m: Dict[str, Any] = {"type": "Register", "seq": seq, "name": check_name("agent name", self.name),
                             "body": self.body.wire()}
        if self.bundled_model is not None:
            m["model"] = {"format": "bundled", "bundled": self.bundled_model}
        return m


def _agent_action(kind: str, agent: str, seq: int, **fields: Any) -> Dict[str, Any]:
    m: Dict[str, Any] = {"type": kind, "seq": seq, "agent": check_name("agent", agent)}
    m.update({k: v for k, v in fields.items() if v is not None})
    return m


@dataclass(frozen=True)
class Move:
    agent: str
    to: Point2
    start: Optional[Point2] = None

    def to_wire(self, seq: int) -> Dict[str, Any]:
        for name, p in (("to", self.to), ("from", self.start)):
            if p is not None and not (math.isfinite(p.x) and math.isfinite(p.z)):
                raise ValueError(f"Move.{name} must be a finite point, was ({p.x}, {p.z})")
        start = None if self.start is None else {"x": self.start.x, "y": 0.0, "z": self.start.z}
        return _agent_action("Move", self.agent, seq, to={"x": self.to.x, "y": 0.0, "z": self.to.z},
                             **{"from": start})


@dataclass(frozen=True)
class SetRotation:
    agent: str
    heading: float

    def to_wire(self, seq: int) -> Dict[str, Any]:
        if not math.isfinite(self.heading):
            raise ValueError(f"SetRotation.heading must be a finite number of radians, was {self.heading}")
        return _agent_action("SetRotation", self.agent, seq,
                             rotation={"axis": {"x": 0.0, "y": 1.0, "z": 0.0}, "angle": self.heading})


@dataclass(frozen=True)
class GraspRequest:
    agent: str
    fruit: str

    def to_wire(self, seq: int) -> Dict[str, Any]:
        return _agent_action("GraspRequest", self.agent, seq, fruit=self.fruit)


@dataclass(frozen=True)
class PerceptionRequest:
    agent: str
    every: int = 0

    def to_wire(self, seq: int) -> Dict[str, Any]:
        if not isinstance(self.every, int) or self.every < 0:
            raise ValueError(f"PerceptionRequest.every must be a whole number >= 0, was {self.every!r}")
        return _agent_action("PerceptionRequest", self.agent, seq, every=self.every)


@dataclass(frozen=True)
class Unregister:
    agent: str

    def to_wire(self, seq: int) -> Dict[str, Any]:
        return _agent_action("Unregister", self.agent, seq)


@dataclass(frozen=True)
class EndTurn:
    tick: int

    def to_wire(self, seq: int) -> Dict[str, Any]:
        if self.tick < 0:
            raise ValueError(f"EndTurn.tick must be >= 0, was {self.tick}")
        return {"type": "EndTurn", "seq": seq, "tick": self.tick}


@dataclass(frozen=True)
class Instruction:
    """An instruction in simple English for an agent; also how the server relays one."""
    agent: str
    text: str
    sender: Optional[str] = None

    def to_wire(self, seq: int) -> Dict[str, Any]:
        return _agent_action("Instruction", self.agent, seq, text=self.text, **{"from": self.sender})


@dataclass(frozen=True)
class Say:
    """An agent speaking to people; also how the server relays what an agent said."""
    agent: str
    text: str

    def to_wire(self, seq: int) -> Dict[str, Any]:
        return _agent_action("Say", self.agent, seq, text=self.text)


@dataclass(frozen=True)
class GameControl:
    """The operator's command: ``start``, ``pause``, ``resume``, or ``restart`` with an optional ``seed``."""
    command: str
    seed: Optional[int] = None

    def to_wire(self, seq: int) -> Dict[str, Any]:
        if self.command not in ("start", "pause", "resume", "restart"):
            raise ValueError("GameControl.command must be one of 'start', 'pause', 'resume', 'restart', was "
                             f"{self.command!r}")
        wire: Dict[str, Any] = {"type": "GameControl", "seq": seq, "command": self.command}
        if self.seed is not None:
            if self.command != "restart":
                raise ValueError(f"GameControl.seed goes only with the command 'restart', was given with "
                                 f"{self.command!r}")
            if isinstance(self.seed, bool) or not isinstance(self.seed, int) or not -2 ** 63 <= self.seed < 2 ** 63:
                raise ValueError(f"GameControl.seed must be a 64-bit whole number, was {self.seed!r}")
            wire["seed"] = self.seed
        return wire


@dataclass(frozen=True)
class KeepAlive:
    def to_wire(self, seq: int) -> Dict[str, Any]:
        return {"type": "KeepAlive", "seq": seq}


ClientMessage = Union[Hello, Register, Move, SetRotation, GraspRequest, PerceptionRequest, Unregister, EndTurn,
                      Instruction, Say, GameControl, KeepAlive]


# ---- server to client (sections 8, 9, 16) ----------------------------------------------------

@dataclass(frozen=True)
class Welcome:
    seq: int
    protocol_version: int
    server_version: str
    role: str
    bounds: Bounds
    tick_rate: int
    clock: str
    tick: int
    time_limit: Optional[float] = None
    phase: Optional[str] = None


@dataclass(frozen=True)
class Error:
    seq: int
    code: str
    text: str


@dataclass(frozen=True)
class Registered:
    seq: int
    agent: str
    body: Body
    position: Vec3
    heading: float
    resume_token: Optional[str] = None
    seed: Optional[int] = None


@dataclass(frozen=True)
class ActionResult:
    seq: int
    action: str
    outcome: str
    duration: float
    agent: Optional[str] = None
    reason: Optional[str] = None
    position: Optional[Vec3] = None


@dataclass(frozen=True)
class GraspResult:
    seq: int
    agent: str
    fruit: str
    success: bool
    points: int
    reason: Optional[str] = None


@dataclass(frozen=True)
class Perception:
    tick: int
    agent: str
    position: Vec3
    heading: float
    objects: List[PerceivedObject]
    agents: List[PerceivedAgent]
    fruit: List[PerceivedFruit]


@dataclass(frozen=True)
class LandmarkPerception:
    tick: int
    agent: str
    bridges: List[PerceivedBridge]
    river: Optional[PerceivedRiver] = None


@dataclass(frozen=True)
class CastlePerception:
    tick: int
    agent: str
    sector: str


@dataclass(frozen=True)
class LeanPerception:
    """Everything an agent perceives in one tick (section 16), in units and radians."""
    tick: int
    agent: str
    position: Vec3
    heading: float
    objects: List[PerceivedObject]
    agents: List[PerceivedAgent]
    fruit: List[PerceivedFruit]
    bridges: List[PerceivedBridge]
    castle: str
    river: Optional[PerceivedRiver] = None


@dataclass(frozen=True)
class FruitEaten:
    tick: int
    fruit: str
    kind: str
    agent: str


@dataclass(frozen=True)
class Tick:
    tick: int
    time: float


@dataclass(frozen=True)
class GameStarted:
    tick: int
    fruit_count: int
    time_limit: float
    seed: Optional[int] = None


@dataclass(frozen=True)
class ScoreUpdate:
    tick: int
    scores: List[Score]


@dataclass(frozen=True)
class GameOver:
    tick: int
    reason: str
    ranking: List[Score]


@dataclass(frozen=True)
class NewGame:
    """The operator restarted the game: a new one waits for agents at tick 0 (protocol 8.14)."""
    tick: int
    time_limit: float


@dataclass(frozen=True)
class AgentRemoved:
    tick: int
    agent: str
    reason: str


@dataclass(frozen=True)
class Obstacle:
    id: str
    kind: str
    position: Point2
    radius: float
    height: float


@dataclass(frozen=True)
class FruitState:
    id: str
    kind: str
    position: Vec3
    support: Optional[str] = None


@dataclass(frozen=True)
class BridgeShape:
    id: str
    entry_a: Point2
    entry_b: Point2
    width: float


@dataclass(frozen=True)
class WorldSnapshot:
    tick: int
    time: float
    bounds: Bounds
    obstacles: List[Obstacle]
    castle: List[Point2]
    river: List[Point2]
    bridges: List[BridgeShape]
    fruit: List[FruitState]
    scores: List[Score]


@dataclass(frozen=True)
class AgentAdded:
    tick: int
    name: str
    body: Body
    position: Vec3
    heading: float


@dataclass(frozen=True)
class AgentMoved:
    tick: int
    agent: str
    start: Vec3
    to: Vec3
    start_time: float
    duration: float


@dataclass(frozen=True)
class AgentRotated:
    tick: int
    agent: str
    heading: float


@dataclass(frozen=True)
class FruitRemoved:
    tick: int
    fruit: str
    agent: str


@dataclass(frozen=True)
class Unknown:
    """A line of a type this version does not read (joints, animations, later additions)."""
    type: str
    fields: Dict[str, Any]


ServerMessage = Union[Welcome, Error, Registered, ActionResult, GraspResult, Perception, LandmarkPerception,
                      CastlePerception, LeanPerception, FruitEaten, Tick, GameStarted, ScoreUpdate, GameOver,
                      AgentRemoved, NewGame, Instruction, Say, WorldSnapshot, AgentAdded, AgentMoved, AgentRotated,
                      FruitRemoved, Unknown]


# ---- encoding and decoding -------------------------------------------------------------------

def encode(message: ClientMessage, seq: int) -> bytes:
    """The line of ``message`` with ``seq``, newline included."""
    return (json.dumps(message.to_wire(seq), separators=(",", ":"), allow_nan=False) + "\n").encode("utf-8")


class _Fields:
    """Reads one decoded object, naming the message and field when something is missing."""

    __slots__ = ("kind", "m")

    def __init__(self, kind: str, m: Dict[str, Any]) -> None:
        self.kind = kind
        self.m = m

    def req(self, key: str) -> Any:
        value = self.m.get(key)
        if value is None:
            raise ProtocolError(f"{self.kind}.{key} is missing; expected it as docs/protocol.md says")
        return value

    def opt(self, key: str) -> Any:
        return self.m.get(key)


def _vec3(v: Dict[str, Any]) -> Vec3:
    return Vec3(float(v["x"]), float(v.get("y", 0.0)), float(v["z"]))


def _point(v: Dict[str, Any]) -> Point2:
    return Point2(float(v["x"]), float(v["z"]))


def _rel(v: Dict[str, Any]) -> RelativePosition:
    return RelativePosition(float(v["distance"]), float(v["bearing"]))


def _body(v: Dict[str, Any]) -> Body:
    g, s = v["gripper"], v["sight"]
    return Body(float(v["radius"]), float(v["height"]), float(v["maxSpeed"]),
                Gripper(g["part"], float(g["reach"]), float(g["minHeight"]), float(g["maxHeight"])),
                Sight(float(s["range"]), float(s["fieldOfView"])))


def _scores(v: List[Dict[str, Any]]) -> List[Score]:
    return [Score(s["agent"], int(s["points"]), int(s["fruit"])) for s in v]


def _bounds(v: Dict[str, Any]) -> Bounds:
    return Bounds(float(v["minX"]), float(v["minZ"]), float(v["maxX"]), float(v["maxZ"]))


def _units(centimetres: int) -> float:
    return centimetres / 100


def _radians(milliradians: int) -> float:
    return math.pi if milliradians == 3142 else milliradians / 1000


def _lean(f: _Fields) -> LeanPerception:
    x, y, z = f.req("position")[:3]
    river = f.opt("river")
    return LeanPerception(
        tick=f.req("tick"), agent=f.req("agent"), position=Vec3(_units(x), _units(y), _units(z)),
        heading=_radians(f.req("heading")),
        objects=[PerceivedObject(o[0], o[1], RelativePosition(_units(o[2]), _radians(o[3])), _units(o[4]),
                                 _units(o[5])) for o in f.req("objects")],
        agents=[PerceivedAgent(a[0], RelativePosition(_units(a[1]), _radians(a[2])), _radians(a[3]), _units(a[4]))
                for a in f.req("agents")],
        fruit=[PerceivedFruit(t[0], t[1], Vec3(_units(t[2]), _units(t[3]), _units(t[4])),
                              FRUIT_RADIUS.get(t[1], 0.35), t[5]) for t in f.req("fruit")],
        bridges=[PerceivedBridge(b[0], RelativePosition(_units(b[1]), _radians(b[2])),
                                 RelativePosition(_units(b[3]), _radians(b[4])), _units(b[5]))
                 for b in f.req("bridges")],
        castle=f.req("castle"),
        river=None if river is None else PerceivedRiver(RelativePosition(_units(river[0]), _radians(river[1])),
                                                        _radians(river[2])))


def _perception(f: _Fields) -> Perception:
    return Perception(
        tick=f.req("tick"), agent=f.req("agent"), position=_vec3(f.req("position")), heading=float(f.req("heading")),
        objects=[PerceivedObject(o["id"], o["kind"], _rel(o["at"]), float(o["radius"]), float(o["height"]))
                 for o in f.req("objects")],
        agents=[PerceivedAgent(a["name"], _rel(a["at"]), float(a["heading"]), float(a["radius"]))
                for a in f.req("agents")],
        fruit=[PerceivedFruit(t["id"], t["kind"], _vec3(t["position"]), float(t["radius"]), t.get("support"))
               for t in f.req("fruit")])


def _landmarks(f: _Fields) -> LandmarkPerception:
    r = f.opt("river")
    return LandmarkPerception(
        tick=f.req("tick"), agent=f.req("agent"),
        bridges=[PerceivedBridge(b["id"], _rel(b["entryA"]), _rel(b["entryB"]), float(b["width"]))
                 for b in f.req("bridges")],
        river=None if r is None else PerceivedRiver(_rel(r["nearest"]), float(r["across"])))


def _snapshot(f: _Fields) -> WorldSnapshot:
    return WorldSnapshot(
        tick=f.req("tick"), time=float(f.req("time")), bounds=_bounds(f.req("bounds")),
        obstacles=[Obstacle(o["id"], o["kind"], _point(o["position"]), float(o["radius"]), float(o["height"]))
                   for o in f.req("obstacles")],
        castle=[_point(p) for p in f.req("castle")["footprint"]],
        river=[_point(p) for p in f.req("river")["outline"]],
        bridges=[BridgeShape(b["id"], _point(b["entryA"]), _point(b["entryB"]), float(b["width"]))
                 for b in f.req("bridges")],
        fruit=[FruitState(t["id"], t["kind"], _vec3(t["position"]), t.get("support")) for t in f.req("fruit")],
        scores=_scores(f.req("scores")))


def _heading(rotation: Dict[str, Any]) -> float:
    angle = float(rotation["angle"])
    return -angle if float(rotation["axis"]["y"]) < 0 else angle


_DECODERS: Dict[str, Callable[[_Fields], ServerMessage]] = {
    "Welcome": lambda f: Welcome(f.req("seq"), f.req("protocolVersion"), f.req("serverVersion"), f.req("role"),
                                 _bounds(f.req("bounds")), f.req("tickRate"), f.req("clock"), f.req("tick"),
                                 f.opt("timeLimit"), f.opt("phase")),
    "Error": lambda f: Error(f.req("seq"), f.req("code"), f.req("text")),
    "Registered": lambda f: Registered(f.req("seq"), f.req("agent"), _body(f.req("body")),
                                       _vec3(f.req("position")), float(f.req("heading")), f.opt("resumeToken"),
                                       f.opt("seed")),
    "ActionResult": lambda f: ActionResult(f.req("seq"), f.req("action"), f.req("outcome"),
                                           float(f.req("duration")), f.opt("agent"), f.opt("reason"),
                                           None if f.opt("position") is None else _vec3(f.opt("position"))),
    "GraspResult": lambda f: GraspResult(f.req("seq"), f.req("agent"), f.req("fruit"), f.req("success"),
                                         f.req("points"), f.opt("reason")),
    "Perception": _perception,
    "LandmarkPerception": _landmarks,
    "CastlePerception": lambda f: CastlePerception(f.req("tick"), f.req("agent"), f.req("sector")),
    "LeanPerception": _lean,
    "FruitEaten": lambda f: FruitEaten(f.req("tick"), f.req("fruit"), f.req("kind"), f.req("agent")),
    "Tick": lambda f: Tick(f.req("tick"), float(f.req("time"))),
    "GameStarted": lambda f: GameStarted(f.req("tick"), f.req("fruitCount"), float(f.req("timeLimit")),
                                         f.opt("seed")),
    "ScoreUpdate": lambda f: ScoreUpdate(f.req("tick"), _scores(f.req("scores"))),
    "GameOver": lambda f: GameOver(f.req("tick"), f.req("reason"), _scores(f.req("ranking"))),
    "AgentRemoved": lambda f: AgentRemoved(f.req("tick"), f.req("agent"), f.req("reason")),
    "NewGame": lambda f: NewGame(f.req("tick"), float(f.req("timeLimit"))),
    "Instruction": lambda f: Instruction(f.req("agent"), f.req("text"), f.opt("from")),
    "Say": lambda f: Say(f.req("agent"), f.req("text")),
    "WorldSnapshot": _snapshot,
    "AgentAdded": lambda f: AgentAdded(f.req("tick"), f.req("agent")["name"], _body(f.req("agent")["body"]),
                                       _vec3(f.req("agent")["position"]), float(f.req("agent")["heading"])),
    "AgentMoved": lambda f: AgentMoved(f.req("tick"), f.req("agent"), _vec3(f.req("from")), _vec3(f.req("to")),
                                       float(f.req("startTime")), float(f.req("duration"))),
    "AgentRotated": lambda f: AgentRotated(f.req("tick"), f.req("agent"), _heading(f.req("rotation"))),
    "FruitRemoved": lambda f: FruitRemoved(f.req("tick"), f.req("fruit"), f.req("agent")),
}


def decode(line: Union[str, bytes]) -> ServerMessage:
    """The typed message of one line from the server; ProtocolError when it is not one."""
    try:
        m = json.loads(line)
    except ValueError as e:
        raise ProtocolError(f"the server sent a line that is not JSON ({e}): {line[:200]!r}") from None
    if not isinstance(m, dict):
        raise ProtocolError(f"the server sent a line that is not a JSON object: {line[:200]!r}")
    kind = m.get("type")
    if not isinstance(kind, str):
        raise ProtocolError(f"type must be a string naming the message, was {kind!r} in {line[:200]!r}")
    decoder = _DECODERS.get(kind)
    if decoder is None:
        return Unknown(kind, m)
    try:
        return decoder(_Fields(kind, m))
    except ProtocolError:
        raise
    except (KeyError, IndexError, TypeError, ValueError) as e:
        raise ProtocolError(f"{kind} does not have the fields docs/protocol.md gives it ({type(e).__name__}: {e}): "
                            f"{line[:200]!r}") from None
