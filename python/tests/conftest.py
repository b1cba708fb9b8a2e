"""The tests play real games on real servers: ORCHARD_CLASSPATH (the Maven build sets it) or a built clone."""
from __future__ import annotations

import socket
from typing import Iterator

import pytest

from orchard_world.server import ServerProcess


@pytest.fixture
def server() -> Iterator[ServerProcess]:
    """A lockstep server on a free port, seed 1998, waiting for one agent, a 5-second game."""
    process = ServerProcess(seed=1998, time_limit=5.0, wait_for=1)
    try:
        yield process
    finally:
        process.stop()


@pytest.fixture
def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]
