"""The PettingZoo ParallelEnv: learning agents in a lockstep Orchard game, among the paper's if asked."""
from __future__ import annotations

import functools
import math
import os
import secrets
import tempfile
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np
from gymnasium import spaces
from gymnasium.utils import seeding
from pettingzoo import ParallelEnv

from ..errors import OrchardError
from ..messages import Body, check_name
from ..server import JAVA_OPTIONS, SPECIES, ServerProcess, start_opponents
from . import _observe, _render
from ._game import Game, check_options
from ._game import restart as _restart_server


class OrchardParallelEnv(ParallelEnv):  # type: ignore[misc]
    """Learning agents collecting fruit in an Orchard world, all acting at once.

    The first ``reset(seed=...)`` starts a server with a lockstep game of that seed (and the
    opponents); each later one has the server restart its game with the new seed, on the same
    server and the same opponents' processes. With ``server="host:port"`` it plays on a running
    server instead, restarting its game when given the server's ``operator_token``. Each
    ``step(actions)`` is ``ticks_per_step`` ticks. Options:

    - ``agents``: how many learning agents (default 2), named ``learner_0``...; or ``names``;
    - ``opponents``: the paper's agents that play too, any of ``Dwarf``, ``Robot``, ``Bunny``,
      ``Guppy``, ``Roadrunner`` (default none);
    - ``time_limit``: the game's length in simulated seconds (default 60);
    - ``ticks_per_step``: ticks per step (default 2; 20 ticks make a simulated second);
    - ``turn_angle``: radians turned by a turn action (default pi/8);
    - ``body``: the learners' :class:`~orchard_world.messages.Body`;
    - ``render_mode``: ``"rgb_array"`` or None; ``render_size``: the frame's side in pixels (256);
    - ``server``: ``"host:port"`` of a running lockstep server to play on, instead of starting one;
      ``operator_token``: its operator token, with which each reset restarts its game (without
      it, the env plays the server's game as it is, once);
    - ``turn_deadline``: seconds a tick waits for a slow agent (default 60); ``java``: the java
      command, ``java_options``: its options (quick to start; without ``-XX:TieredStopAtLevel=1``
      a long game runs faster).
    """

    metadata = {"render_modes": ["rgb_array"], "name": "orchard_world_v0", "is_parallelizable": True,
                "render_fps": 10}

    def __init__(self, agents: int = 2, names: Optional[Sequence[str]] = None, opponents: Sequence[str] = (),
                 time_limit: float = 60.0, ticks_per_step: int = 2, turn_angle: float = math.pi / 8,
                 body: Optional[Body] = None, render_mode: Optional[str] = None, render_size: int = 256,
                 server: Optional[str] = None, turn_deadline: float = 60.0, java: str = "java",
                 java_options: Sequence[str] = JAVA_OPTIONS, operator_token: Optional[str] = None) -> None:
        if names is None:
            check_options(agents=agents)
            names = [f"learner_{i}" for i in range(agents)]
        names = [check_name("agent name", n) for n in names]
        if not names or len(set(names)) != len(names):
            raise ValueError(f"names must be one or more different agent names, was {list(names)!r}")
        clash = [n for n in names if n in SPECIES]
        if clash:
            raise ValueError(f"names must differ from the opponents' species names, was {clash[0]!r}")
        unknown = [o for o in opponents if o not in SPECIES]
        if unknown:
            raise ValueError(f"opponents must be among {', '.join(SPECIES)}, was {unknown[0]!r}")
        check_options(ticks_per_step=ticks_per_step, time_limit=time_limit, turn_deadline=turn_deadline,
                      render_size=render_size)
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode must be 'rgb_array' or None, was {render_mode!r}")
        self.address: Optional[Tuple[str, int]] = None
        if operator_token is not None and (server is None or not isinstance(operator_token, str)
                                           or not operator_token):
            raise ValueError(f"operator_token goes with server='host:port', the running server whose token it is, "
                             f"and must be a non-empty string; was {operator_token!r} with server={server!r}")
        if server is not None:
            host, _, port = server.rpartition(":")
            if not host or not port.isdigit():
                raise ValueError(f"server must be 'host:port', was {server!r}")
            self.address = (host, int(port))
        self.possible_agents: List[str] = list(names)
        self.agents: List[str] = []
        self.opponents = tuple(opponents)
        self.time_limit = float(time_limit)
        self.ticks_per_step = ticks_per_step
        self.turn_angle = turn_angle
        self.body = body or Body()
        self.render_mode = render_mode
        self.render_size = render_size
        self.turn_deadline = turn_deadline
        self.java = java
        self.java_options = tuple(java_options)
        self.metadata = dict(self.metadata, render_fps=max(1, round(20 / ticks_per_step)))
        self._np_random, _ = seeding.np_random(None)
        self._server: Optional[ServerProcess] = None
        self._opponents: list = []
        self._game: Optional[Game] = None
        # The operator's token of the server this env starts: its resets restart that server's game.
        self._operator_token = operator_token if server is not None else secrets.token_hex(16)
        self._played = False
        self._tokens = tempfile.NamedTemporaryFile(prefix="orchard-resume-tokens-", delete=False)
        self._tokens.close()
        self._cache: Dict[str, Any] = {}
        self.world_seed: Optional[int] = None

    @functools.lru_cache(maxsize=None)
    def observation_space(self, agent: str) -> spaces.Box:
        """``Box(-1, 1, (102,), float32)``: the fields of ``orchard_world.env.OBSERVATION_FIELDS``."""
        return _observe.observation_space()

    @functools.lru_cache(maxsize=None)
    def action_space(self, agent: str) -> spaces.Discrete:
        """``Discrete(5)``: stay, forward, turn left, turn right, grasp the nearest fruit."""
        return _observe.action_space()

    def reset(self, seed: Optional[int] = None, options: Optional[dict] = None
              ) -> Tuple[Dict[str, np.ndarray], Dict[str, dict]]:
        if seed is not None:
            self._np_random, _ = seeding.np_random(seed)
            self.world_seed = int(seed)
        else:
            self.world_seed = int(self._np_random.integers(1, 2 ** 31))
        started = self._server is not None and self._server.alive() and all(
            o.process.poll() is None for o in self._opponents)
        if self.address is None and not started:  # none yet, or one of its processes ended: anew
            self._end_game()
            self._server = ServerProcess(seed=self.world_seed, time_limit=self.time_limit,
                                         wait_for=len(self.possible_agents) + len(self.opponents),
                                         turn_deadline=self.turn_deadline, java=self.java,
                                         java_options=self.java_options, operator_token=self._operator_token,
                                         keep_serving=True)
            host, port = "127.0.0.1", self._server.port
            self._opponents = start_opponents(port, self.opponents, self._tokens.name, java=self.java,
                                              java_options=self.java_options, next_games=True)
        else:
            if self.address is not None:
                host, port = self.address
            else:
                assert self._server is not None
                host, port = "127.0.0.1", self._server.port
            self._restart(host, port, self.world_seed)
        self._cache.clear()
        self._game = Game(host, port, self.possible_agents, self.body, self.ticks_per_step, self.turn_angle,
                          view=self.render_mode == "rgb_array", operator_token=self._operator_token)
        self._played = True
        self.agents = list(self.possible_agents)
        return {a: self._observe(a) for a in self.agents}, {a: self._info(a) for a in self.agents}

    def _restart(self, host: str, port: int, seed: int) -> None:
        """A new game of ``seed`` on the server, as its operator; none without its token, after a first game."""
        game, self._game = self._game, None
        try:
            if self._operator_token is None:
                if self._played:
                    raise OrchardError(f"the server at {host}:{port} plays one game: give the env its operator "
                                       "token (operator_token=...) to reset it, or let the env start its own server")
            elif game is not None and game.groups:
                game.restart(seed)
            else:
                _restart_server(host, port, self._operator_token, seed)
        finally:
            if game is not None:
                game.close()

    def step(self, actions: Dict[str, Any]) -> Tuple[Dict[str, np.ndarray], Dict[str, float], Dict[str, bool],
                                                     Dict[str, bool], Dict[str, dict]]:
        game = self._game
        if game is None or not self.agents:
            raise RuntimeError("step() needs a game under way: call reset() first (and again after the game ends)")
        for agent, action in actions.items():
            if agent not in self.agents:
                raise ValueError(f"actions name {agent!r}, which is not one of the agents {self.agents}")
            if not (np.ndim(action) == 0 and float(action) == int(action) and 0 <= int(action) < len(_observe.ACTIONS)):
                raise ValueError(f"action of {agent} must be 0-{len(_observe.ACTIONS) - 1} "
                                 f"({', '.join(_observe.ACTIONS)}), was {action!r}")
        game.step({a: int(v) for a, v in actions.items()})
        live = list(self.agents)
        over = game.over
        timed_out = over is not None and over.tick >= round(self.time_limit * game.welcome.tick_rate)
        observations = {a: self._observe(a) for a in live}
        rewards = {a: float(game.learners[a].reward) for a in live}
        terminations = {a: over is not None and not timed_out for a in live}
        truncations = {a: timed_out for a in live}
        infos = {a: self._info(a) for a in live}
        if over is not None:
            self.agents = []
        return observations, rewards, terminations, truncations, infos

    def _observe(self, agent: str) -> np.ndarray:
        assert self._game is not None
        learner = self._game.learners[agent]
        if learner.perception is None:
            return np.zeros(self.observation_space(agent).shape, dtype=np.float32)
        left = max(0.0, 1.0 - self._game.time / self.time_limit)
        return _observe.observe(learner.perception, learner.body, self._game.welcome.bounds, left)

    def _info(self, agent: str) -> dict:
        assert self._game is not None
        learner = self._game.learners[agent]
        return {"points": learner.points, "tick": self._game.tick, "rejected": learner.rejected}

    def render(self) -> Optional[np.ndarray]:
        """The world from above as an RGB array (render_mode "rgb_array"): north up, learners white."""
        if self.render_mode is None:
            return None
        if self._game is None:
            return np.zeros((self.render_size, self.render_size, 3), dtype=np.uint8)
        return _render.draw(self._game.view, self.possible_agents, self.render_size, self._cache)

    @property
    def scores(self) -> Dict[str, int]:
        """Every player's points so far, opponents included."""
        return dict(self._game.scores) if self._game else {}

    def _end_game(self) -> None:
        if self._game is not None:
            self._game.close()
            self._game = None
        if self._server is not None:
            self._server.stop()  # first: the opponents' connections close with it, and they end
            self._server = None
        for process in self._opponents:
            process.stop()
        self._opponents = []

    def close(self) -> None:
        """Ends the game and stops the server and opponents this env started."""
        self._end_game()
        self.agents = []
        try:
            os.unlink(self._tokens.name)
        except OSError:
            pass

    def __del__(self) -> None:
        try:
            self._end_game()
        except Exception:
            pass
