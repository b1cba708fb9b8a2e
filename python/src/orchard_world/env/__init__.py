"""Orchard as environments for learning agents: PettingZoo's two forms and a Gymnasium one.

- :func:`parallel_env` — a PettingZoo ``ParallelEnv``: several learners acting at once;
- :func:`env` — the same as a PettingZoo ``AECEnv``, one agent at a time;
- :class:`ForageEnv` — Gymnasium's ``orchard_world/Forage-v0``: one learner among the paper's five.

Observations are ``Box(-1, 1, (102,), float32)`` with the fields :data:`OBSERVATION_FIELDS`;
actions are ``Discrete(5)``, :data:`ACTIONS`. docs/python.md explains both.
"""
from __future__ import annotations

from typing import Any

from pettingzoo.utils.conversions import parallel_to_aec

from ._forage import ForageEnv
from ._observe import ACTIONS, FIELDS as OBSERVATION_FIELDS
from ._parallel import OrchardParallelEnv

__all__ = ["parallel_env", "env", "raw_env", "ForageEnv", "OrchardParallelEnv", "ACTIONS", "OBSERVATION_FIELDS"]


def parallel_env(**options: Any) -> OrchardParallelEnv:
    """The PettingZoo ``ParallelEnv``; the options are :class:`OrchardParallelEnv`'s."""
    return OrchardParallelEnv(**options)


def raw_env(**options: Any) -> Any:
    """The AEC form of :func:`parallel_env`, as PettingZoo's ``parallel_to_aec`` makes it."""
    return parallel_to_aec(OrchardParallelEnv(**options))


def env(**options: Any) -> Any:
    """The PettingZoo ``AECEnv``: agents act in turn, the step of the world after the last."""
    return raw_env(**options)
