"""Gymnasium's single-agent form: one learner, the Forager, among the paper's five (or a chosen set)."""
from __future__ import annotations

import math
from typing import Any, Dict, Optional, Sequence, Tuple

import gymnasium as gym
import numpy as np

from ..messages import Body
from ..server import JAVA_OPTIONS, SPECIES
from . import _observe
from ._parallel import OrchardParallelEnv

LEARNER = "Forager"


class ForageEnv(gym.Env):  # type: ignore[misc]
    """``orchard_world/Forage-v0``: collect fruit for points against the paper's agents.

    Observation ``Box(-1, 1, (102,), float32)`` and action ``Discrete(5)`` as in
    :class:`OrchardParallelEnv`; the reward is the points of the fruit grasped in the step. The
    episode ends (terminated) when the fruit is gone, or is truncated at ``time_limit``. Options:
    ``opponents`` (default the paper's five), ``time_limit`` (60), ``ticks_per_step`` (2),
    ``turn_angle``, ``body``, ``render_mode`` (``"rgb_array"``), ``render_size``, ``server``,
    ``operator_token``, ``turn_deadline``, ``java``, ``java_options``.
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 10}

    def __init__(self, opponents: Sequence[str] = SPECIES, time_limit: float = 60.0, ticks_per_step: int = 2,
                 turn_angle: float = math.pi / 8, body: Optional[Body] = None, render_mode: Optional[str] = None,
                 render_size: int = 256, server: Optional[str] = None, turn_deadline: float = 60.0,
                 java: str = "java", java_options: Sequence[str] = JAVA_OPTIONS,
                 operator_token: Optional[str] = None) -> None:
        self._env = OrchardParallelEnv(names=[LEARNER], opponents=opponents, time_limit=time_limit,
                                       ticks_per_step=ticks_per_step, turn_angle=turn_angle, body=body,
                                       render_mode=render_mode, render_size=render_size, server=server,
                                       turn_deadline=turn_deadline, java=java, java_options=java_options,
                                       operator_token=operator_token)
        self.observation_space = _observe.observation_space()
        self.action_space = _observe.action_space()
        self.render_mode = render_mode
        self.metadata = dict(self.metadata, render_fps=self._env.metadata["render_fps"])

    def reset(self, *, seed: Optional[int] = None, options: Optional[Dict[str, Any]] = None
              ) -> Tuple[np.ndarray, Dict[str, Any]]:
        super().reset(seed=seed)
        world_seed = seed if seed is not None else int(self.np_random.integers(1, 2 ** 31))
        observations, infos = self._env.reset(seed=world_seed)
        return observations[LEARNER], infos[LEARNER]

    def step(self, action: Any) -> Tuple[np.ndarray, float, bool, bool, Dict[str, Any]]:
        o, r, term, trunc, info = self._env.step({LEARNER: action})
        info = dict(info[LEARNER], scores=self._env.scores)
        return o[LEARNER], r[LEARNER], term[LEARNER], trunc[LEARNER], info

    def render(self) -> Optional[np.ndarray]:
        return self._env.render()

    def close(self) -> None:
        self._env.close()
