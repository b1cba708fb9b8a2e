"""One lockstep game of learning agents on a server: connecting, acting, ending turns, perceiving.

Agents are driven up to 8 on a connection (the server's limit). Each env step is ``ticks_per_step``
ticks: the agents act at the first, every connection ends each tick's turn, and the perceptions of
the next step's first tick come back (subscribed every ``ticks_per_step`` ticks).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Sequence

from ..client import Connection
from ..errors import ConnectionClosed, OrchardError, ServerError
from ..messages import (ActionResult, AgentAdded, AgentMoved, AgentRotated, Body, ClientMessage, EndTurn, Error,
                        FruitRemoved, FruitState, GameControl, GameOver, GraspRequest, GraspResult, LeanPerception,
                        Move, NewGame, Point2, PerceptionRequest, Register, Registered, ScoreUpdate, SetRotation,
                        Tick, WorldSnapshot)
from . import _observe

AGENTS_PER_CONNECTION = 8


@dataclass
class Learner:
    name: str
    body: Body
    seed: Optional[int] = None
    perception: Optional[LeanPerception] = None
    reward: float = 0.0
    points: int = 0
    rejected: int = 0


@dataclass
class _Group:
    connection: Connection
    names: List[str]


@dataclass
class WorldView:
    """What a viewer connection knows of the world, for drawing it."""
    snapshot: Optional[WorldSnapshot] = None
    fruit: Dict[str, FruitState] = field(default_factory=dict)
    agents: Dict[str, List[Any]] = field(default_factory=dict)  # name -> [AgentMoved or Vec3, heading, radius]
    time: float = 0.0


class Game:
    def __init__(self, host: str, port: int, names: Sequence[str], body: Body, ticks_per_step: int,
                 turn_angle: float, view: bool, operator_token: Optional[str] = None) -> None:
        self.ticks_per_step = ticks_per_step
        self.turn_angle = turn_angle
        self.learners: Dict[str, Learner] = {n: Learner(n, body) for n in names}
        self.groups: List[_Group] = []
        self.over: Optional[GameOver] = None
        self.tick = 0
        self.time = 0.0
        self.scores: Dict[str, int] = {}
        self.viewer: Optional[Connection] = None
        self.view = WorldView()
        try:
            if view:
                self.viewer = Connection.open(host, port, role="viewer", client="orchard_world-render", reads=())
            for start in range(0, len(names), AGENTS_PER_CONNECTION):
                chunk = list(names[start:start + AGENTS_PER_CONNECTION])
                # The first connection is the operator's, which restarts the game for the next reset.
                token = operator_token if not self.groups else None
                self.groups.append(_Group(Connection.open(host, port, client="orchard_world-env",
                                                          operator_token=token), chunk))
            welcome = self.groups[0].connection.welcome
            assert welcome is not None
            self.welcome = welcome
            for g in self.groups:
                for name in g.names:
                    registered = g.connection.request(Register(name, body))
                    assert isinstance(registered, Registered)
                    learner = self.learners[name]
                    learner.body, learner.seed = registered.body, registered.seed
                assert g.connection.welcome is not None
                g.connection.send_all([PerceptionRequest(n, ticks_per_step) for n in g.names]
                                      + [EndTurn(g.connection.welcome.tick)])
            self._collect(0, perceive=True)
        except BaseException:
            self.close()
            raise

    def restart(self, seed: int) -> None:
        """Asks the server for a new game of the world of ``seed``, ending this one (protocol 11.6).

        The first connection must be the operator's. The tick under way ends with this game's turns,
        so that the server need not wait for them; returns once the new game waits for its agents.
        """
        operator = self.groups[0].connection
        ending = [] if self.over is not None else [EndTurn(self.tick)]
        seq = operator.send_all([GameControl("restart", seed), *ending])[0]
        for g in self.groups[1:]:
            if ending:
                g.connection.send_all(ending)
        await_new_game(operator, seq)

    @property
    def time_limit(self) -> float:
        return float(self.welcome.time_limit or 300.0)

    def step(self, actions: Dict[str, int]) -> None:
        """Acts, ends this step's ticks and reads the perceptions of the next step's first tick."""
        for learner in self.learners.values():
            learner.reward = 0.0
        if self.over is not None:
            return
        first = self.tick
        for g in self.groups:
            lines: List[ClientMessage] = []
            for name in g.names:
                lines.extend(self._messages(self.learners[name], actions.get(name, _observe.STAY)))
            lines.append(EndTurn(first))
            g.connection.send_all(lines)
        for k in range(1, self.ticks_per_step + 1):
            self._collect(first + k, perceive=k == self.ticks_per_step)
            if self.over is not None:
                return

    def _messages(self, learner: Learner, action: int) -> List[ClientMessage]:
        p = learner.perception
        if p is None or action == _observe.STAY:
            return []
        if action == _observe.FORWARD:
            step = learner.body.max_speed * self.ticks_per_step / self.welcome.tick_rate
            return [Move(learner.name, Point2(p.position.x - step * math.sin(p.heading),
                                              p.position.z - step * math.cos(p.heading)))]
        if action in (_observe.TURN_LEFT, _observe.TURN_RIGHT):
            turn = self.turn_angle if action == _observe.TURN_LEFT else -self.turn_angle
            return [SetRotation(learner.name, p.heading + turn)]
        if action == _observe.GRASP and p.fruit:
            reachable = [f for f in p.fruit if _observe.graspable(p, learner.body, f)]
            pool = reachable or p.fruit
            target = min(pool, key=lambda f: (_observe.bearing_to(p, f.position.x, f.position.z)[0], f.id))
            return [GraspRequest(learner.name, target.id)]
        if action not in range(len(_observe.ACTIONS)):
            raise ValueError(f"action of {learner.name} must be 0-{len(_observe.ACTIONS) - 1} "
                             f"({', '.join(_observe.ACTIONS)}), was {action!r}")
        return []

    def _collect(self, tick: int, perceive: bool) -> None:
        """Reads every connection up to the start of ``tick``, then its perceptions or ends its turn."""
        for g in self.groups:
            while self.over is None:
                m = self._next(g.connection)
                if isinstance(m, Tick) and m.tick >= tick:
                    self.tick, self.time = m.tick, m.time
                    break
            if self.over is not None:
                break
            if perceive:
                waiting = set(g.names)
                while waiting and self.over is None:
                    m = self._next(g.connection)
                    if isinstance(m, LeanPerception) and m.agent in waiting and m.tick == tick:
                        waiting.discard(m.agent)
            else:
                g.connection.send(EndTurn(tick))
        if self.viewer is not None:
            self._follow_viewer(tick)

    def _next(self, connection: Connection) -> object:
        m = connection.receive()
        if m is None:
            if self.over is None:
                raise ConnectionClosed(f"the server at {connection.where} closed the connection during tick "
                                       f"{self.tick}, before the game was over")
            return None
        if isinstance(m, LeanPerception) and m.agent in self.learners:
            self.learners[m.agent].perception = m
        elif isinstance(m, GraspResult) and m.success and m.agent in self.learners:
            self.learners[m.agent].reward += m.points
            self.learners[m.agent].points += m.points
        elif isinstance(m, ActionResult) and m.outcome == "rejected" and m.agent in self.learners:
            self.learners[m.agent or ""].rejected += 1
        elif isinstance(m, ScoreUpdate):
            self.scores = {s.agent: s.points for s in m.scores}
        elif isinstance(m, GameOver):
            self.over = m
            self.scores = {s.agent: s.points for s in m.ranking}
        elif isinstance(m, Error):
            raise ServerError(m.code, m.text, m.seq)
        return m

    def _follow_viewer(self, tick: int) -> None:
        assert self.viewer is not None
        while True:
            m = self.viewer.receive()
            if m is None or isinstance(m, GameOver):
                return
            if isinstance(m, Tick):
                self.view.time = m.time
                if m.tick >= tick:
                    return
            elif isinstance(m, WorldSnapshot):
                self.view.snapshot = m
                self.view.fruit = {f.id: f for f in m.fruit}
            elif isinstance(m, FruitRemoved):
                self.view.fruit.pop(m.fruit, None)
            elif isinstance(m, AgentAdded):
                self.view.agents[m.name] = [m.position, m.heading, m.body.radius]
            elif isinstance(m, AgentMoved) and m.agent in self.view.agents:
                self.view.agents[m.agent][0] = m
            elif isinstance(m, AgentRotated) and m.agent in self.view.agents:
                self.view.agents[m.agent][1] = m.heading

    def close(self) -> None:
        for g in self.groups:
            g.connection.close()
        if self.viewer is not None:
            self.viewer.close()
        self.groups = []
        self.viewer = None


def await_new_game(connection: Connection, seq: int) -> None:
    """Waits for the server's answer to the restart sent with ``seq``, then for its NewGame."""
    reply = connection.reply(seq)
    if isinstance(reply, ActionResult) and reply.outcome != "accepted":
        raise OrchardError(f"the server at {connection.where} did not restart its game: {reply.reason}")
    while True:
        m = connection.receive()
        if m is None:
            raise ConnectionClosed(f"the server at {connection.where} closed the connection before its new game")
        if isinstance(m, NewGame):
            return


def restart(host: str, port: int, operator_token: str, seed: int) -> None:
    """Restarts the game of the server at host:port as its operator, with a connection of its own."""
    with Connection.open(host, port, client="orchard_world-reset", operator_token=operator_token,
                         reads=()) as operator:
        await_new_game(operator, operator.send(GameControl("restart", seed)))


def check_options(**values: object) -> None:
    """Raises a ValueError naming the first option out of its range."""
    rules = {
        "agents": (1, 800), "ticks_per_step": (1, 100), "time_limit": (0.05, 86400.0), "turn_deadline": (0.001, 3600),
        "render_size": (16, 4096),
    }
    for name, value in values.items():
        low, high = rules[name]
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not low <= value <= high:
            raise ValueError(f"{name} must be a number from {low} to {high}, was {value!r}")


__all__ = ["Game", "Learner", "check_options", "restart"]
