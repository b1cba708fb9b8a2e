"""Orchard for Python: a client of the Orchard protocol, an Agent base class, and environments.

- :mod:`orchard_world.client` — blocking and asyncio connections (docs/protocol.md, version 2);
- :mod:`orchard_world.messages` — the messages as typed values;
- :class:`Agent` — a base class with the shape of the Java ``AgentController``;
- :mod:`orchard_world.env` — PettingZoo and Gymnasium environments; importing this package
  registers ``orchard_world/Forage-v0`` with Gymnasium;
- :func:`model_info` — what a model file holds (joints, clips, size, units), read offline as
  ``./orchard model-info`` reads it (:mod:`orchard_world.model`).
"""
from __future__ import annotations

import gymnasium

from .agent import Agent
from .client import AsyncConnection, Connection
from .errors import ConnectionClosed, OrchardError, ProtocolError, ServerError, ServerStartError
from .model import ModelError, ModelInfo
from .model import read as model_info

__version__ = "0.1.0"
__all__ = ["Agent", "Connection", "AsyncConnection", "OrchardError", "ServerError", "ProtocolError",
           "ConnectionClosed", "ServerStartError", "model_info", "ModelInfo", "ModelError", "__version__"]

if "orchard_world/Forage-v0" not in gymnasium.registry:
    gymnasium.register(id="orchard_world/Forage-v0", entry_point="orchard_world.env:ForageEnv")
