"""The base class of an agent, with the shape of the Java ``AgentController``.

Subclass it, decide in :meth:`Agent.decide`, act with :meth:`move_to`, :meth:`approach`,
:meth:`face`, :meth:`grasp` and :meth:`say`; :meth:`run` does the rest (handshake, registration,
perceptions, lockstep turns) and returns the game's end::

    class Picker(Agent):
        def decide(self, seen):
            fruit = self.nearest_fruit(seen)
            if fruit is None:
                if not self.walking:
                    self.wander()
            elif self.can_grasp(fruit):
                self.face(fruit.position.x, fruit.position.z)
                self.grasp(fruit.id)
            elif not self.walking:
                self.approach(fruit)

    Picker("Picker").run("localhost", 7557)
"""
from __future__ import annotations

import math
import random
import sys
from typing import List, Optional, Set

from .client import DEFAULT_PORT, Connection
from .errors import ServerError
from .messages import (ActionResult, Body, ClientMessage, EndTurn, Error, FruitEaten, GameOver, GameStarted,
                       GraspRequest, GraspResult, Instruction, KeepAlive, LeanPerception, Move, PerceivedFruit,
                       PerceptionRequest, Point2, Register, Registered, Say, SetRotation, Tick, Welcome, check_name)

__all__ = ["Agent"]


class Agent:
    """One agent: its name, its body, and what it does with each perception.

    The lifecycle (:meth:`run`) is fixed; override the ``on_...`` hooks and :meth:`decide`. The
    actions a hook asks for are sent together when it returns, and in a lockstep game the turn
    ends after them.
    """

    perceive_every = 2
    """Ticks between perceptions (1 is every tick)."""

    def __init__(self, name: str) -> None:
        self.name = check_name("agent name", name)
        self.position = Point2(0.0, 0.0)
        self.heading = 0.0
        self.tick = 0
        self.time = 0.0
        self.points = 0
        self.random = random.Random(0)
        self.welcome: Optional[Welcome] = None
        self.body_in_force: Optional[Body] = None
        self.latest: Optional[LeanPerception] = None
        self._walk_ends = -1.0
        self._approaching: Optional[str] = None
        self.out_of_reach: Set[str] = set()
        """Fruit whose approach was refused (a tree, a table, the river in the way): nearest_fruit skips them."""
        self._outbox: List[ClientMessage] = []
        self._stopped = False

    # ---- what a subclass overrides -------------------------------------------------------------

    def body(self) -> Body:
        """The body to register; the server's limits apply (``body_in_force`` is the result)."""
        return Body()

    def decide(self, seen: LeanPerception) -> None:
        """Acts on a perception; by default it does nothing."""

    def on_registered(self, registered: Registered) -> None:
        """The agent is in the world."""

    def on_game_started(self, started: GameStarted) -> None:
        """The game started (or was under way when the agent joined)."""

    def on_tick(self, tick: int, time: float) -> None:
        """A tick started."""

    def on_action_result(self, result: ActionResult) -> None:
        """An action was answered: a rejected or blocked move, a turn, a subscription."""

    def on_grasp_result(self, result: GraspResult) -> None:
        """A grasp was decided."""

    def on_fruit_eaten(self, eaten: FruitEaten) -> None:
        """Someone collected a fruit."""

    def on_error(self, error: Error) -> None:
        """The server refused something; by default printed to standard error."""
        print(f"{self.name}: {error.code}: {error.text}", file=sys.stderr)

    def on_instruction(self, text: str, sender: Optional[str]) -> None:
        """A person's instruction; by default answered with a polite refusal."""
        self.say(f"I do not follow instructions yet: {text!r}")

    def on_heard(self, agent: str, text: str) -> None:
        """Another agent said something."""

    def on_game_over(self, over: GameOver) -> None:
        """The game is over."""

    # ---- actions -------------------------------------------------------------------------------

    def move_to(self, x: float, z: float) -> None:
        """Walks straight to (x, z) at the body's top speed."""
        self._approaching = None
        speed = self.body_in_force.max_speed if self.body_in_force else 1.0
        self._outbox.append(Move(self.name, Point2(x, z)))
        self._walk_ends = self.time + math.hypot(x - self.position.x, z - self.position.z) / speed

    def approach(self, fruit: PerceivedFruit) -> None:
        """Walks straight towards ``fruit`` until it is in the gripper's reach.

        When the way is blocked (the server refuses the move: the fruit lies on a table or in a
        tree beyond reach, or behind one), the fruit goes into :attr:`out_of_reach`.
        """
        body = self.body_in_force or self.body()
        dx, dz = fruit.position.x - self.position.x, fruit.position.z - self.position.z
        distance = math.hypot(dx, dz)
        short = min(distance, (body.radius + body.gripper.reach + fruit.radius) * 0.8)
        scale = (distance - short) / distance if distance > 0 else 0.0
        self.move_to(self.position.x + dx * scale, self.position.z + dz * scale)
        self._approaching = fruit.id

    def turn_to(self, heading: float) -> None:
        """Turns to ``heading`` (radians; 0 north, positive to the left)."""
        self._outbox.append(SetRotation(self.name, heading))
        self.heading = heading

    def face(self, x: float, z: float) -> None:
        """Turns to face the ground point (x, z)."""
        self.turn_to(math.atan2(-(x - self.position.x), -(z - self.position.z)))

    def grasp(self, fruit_id: str) -> None:
        """Tries to take a fruit: it must be in reach, in front, at a height the gripper reaches."""
        self._outbox.append(GraspRequest(self.name, fruit_id))

    def say(self, text: str) -> None:
        """Says something to everyone watching."""
        self._outbox.append(Say(self.name, text))

    def wander(self, distance: float = 8.0) -> None:
        """Walks ``distance`` units in a direction drawn within a right angle of the heading."""
        angle = self.heading + self.random.uniform(-math.pi / 4, math.pi / 4)
        self.turn_to(angle)
        self.move_to(self.position.x - distance * math.sin(angle), self.position.z - distance * math.cos(angle))

    def stop(self) -> None:
        """Leaves the game after the current message."""
        self._stopped = True

    # ---- what it knows -------------------------------------------------------------------------

    @property
    def walking(self) -> bool:
        """Whether the last move is still under way."""
        return self.time < self._walk_ends

    def nearest_fruit(self, seen: LeanPerception) -> Optional[PerceivedFruit]:
        """The nearest fruit in view at a height the gripper reaches, and not out of reach, or None."""
        body = self.body_in_force or self.body()
        fruit = [f for f in seen.fruit if body.gripper.min_height <= f.position.y <= body.gripper.max_height
                 and f.id not in self.out_of_reach]
        return min(fruit, key=lambda f: (math.hypot(f.position.x - self.position.x, f.position.z - self.position.z),
                                         f.id), default=None)

    def can_grasp(self, fruit: PerceivedFruit) -> bool:
        """Whether ``fruit`` is within the gripper's reach from here (facing it aside)."""
        body = self.body_in_force or self.body()
        distance = math.hypot(fruit.position.x - self.position.x, fruit.position.z - self.position.z)
        return distance <= (body.radius + body.gripper.reach + fruit.radius) * 0.95

    # ---- the lifecycle -------------------------------------------------------------------------

    def run(self, host: str = "localhost", port: int = DEFAULT_PORT, token: Optional[str] = None) -> Optional[GameOver]:
        """Plays one game: connects, registers, perceives and decides until the game is over.

        Returns the GameOver, or None when the server closed the connection first. Raises
        OrchardError when there is no server, and ServerError when the registration is refused.
        """
        with Connection.open(host, port, client=f"orchard_world {type(self).__name__}", token=token) as c:
            assert c.welcome is not None
            self.welcome = c.welcome
            lockstep = c.welcome.clock == "lockstep"
            self.tick = c.welcome.tick
            registered = c.request(Register(self.name, self.body()))
            assert isinstance(registered, Registered)
            self.body_in_force = registered.body
            self.position = Point2(registered.position.x, registered.position.z)
            self.heading = registered.heading
            if registered.seed is not None:
                self.random = random.Random(registered.seed)
            self.on_registered(registered)
            self._outbox.append(PerceptionRequest(self.name, self.perceive_every))
            if lockstep:
                self._outbox.append(EndTurn(self.tick))
            self._flush(c)
            # Lockstep: the tick whose perception comes before its turn ends; None: the very next one.
            perceives_at: Optional[int] = None
            for m in c:
                if isinstance(m, Tick):
                    self.tick, self.time = m.tick, m.time
                    self.on_tick(m.tick, m.time)
                    if lockstep and perceives_at is not None and m.tick != perceives_at:
                        self._outbox.append(EndTurn(m.tick))
                elif isinstance(m, LeanPerception) and m.agent == self.name:
                    self.latest = m
                    self.position = Point2(m.position.x, m.position.z)
                    self.heading = m.heading
                    perceives_at = m.tick + self.perceive_every
                    self.decide(m)
                    if lockstep:
                        self._outbox.append(EndTurn(m.tick))
                elif isinstance(m, GameStarted):
                    self.on_game_started(m)
                elif isinstance(m, ActionResult) and m.agent == self.name:
                    if m.action == "Move" and m.outcome != "accepted":
                        self._walk_ends = self.time + m.duration
                        if m.outcome == "rejected" and self._approaching is not None:
                            self.out_of_reach.add(self._approaching)
                    self.on_action_result(m)
                elif isinstance(m, GraspResult) and m.agent == self.name:
                    self.points += m.points
                    self.on_grasp_result(m)
                elif isinstance(m, FruitEaten):
                    self.on_fruit_eaten(m)
                elif isinstance(m, Instruction) and m.agent == self.name:
                    self.on_instruction(m.text, m.sender)
                elif isinstance(m, Say) and m.agent != self.name:
                    self.on_heard(m.agent, m.text)
                elif isinstance(m, Error):
                    self.on_error(m)
                    if m.code in ("name_in_use", "too_many_agents", "game_not_running"):
                        raise ServerError(m.code, m.text, m.seq)
                elif isinstance(m, GameOver):
                    self.on_game_over(m)
                    return m
                self._flush(c)
                if self._stopped:
                    return None
            return None

    def _flush(self, c: Connection) -> None:
        if self._outbox:
            c.send_all(self._outbox)
            self._outbox = []

    def keep_alive(self) -> None:
        """Says "still here" to a server that closes silent connections (after 120 s)."""
        self._outbox.append(KeepAlive())
