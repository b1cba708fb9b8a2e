import asyncio

import pytest

from orchard_world import Agent, AsyncConnection, Connection, OrchardError, ServerError
from orchard_world.messages import (GameOver, LeanPerception, PerceptionRequest, Register, Registered, Tick, EndTurn,
                                    Hello)


def test_the_handshake_gives_the_welcome_and_a_registration_its_reply(server):
    with Connection.open("127.0.0.1", server.port, client="pytest") as c:
        assert c.welcome is not None and c.welcome.clock == "lockstep" and c.welcome.protocol_version == 2
        registered = c.request(Register("Pyro"))
        assert isinstance(registered, Registered) and registered.agent == "Pyro" and registered.seed is not None
        c.send_all([PerceptionRequest("Pyro", 1), EndTurn(c.welcome.tick)])
        first = [m for m in _until(c, LeanPerception)]
        assert isinstance(first[-1], LeanPerception) and first[-1].tick == 0
        assert any(isinstance(m, Tick) and m.tick == 0 for m in first)


def _until(c, kind):
    for m in c:
        yield m
        if isinstance(m, kind):
            return


def test_a_refused_registration_raises_the_servers_error_naming_the_value(server):
    with Connection.open("127.0.0.1", server.port) as c:
        c.request(Register("Pyro"))
        with pytest.raises(ServerError) as refused:
            c.request(Register("Pyro"))
        assert refused.value.code == "name_in_use" and "Pyro" in refused.value.text


def test_a_hello_in_a_version_the_server_does_not_speak_is_raised_as_version_mismatch(server):
    with pytest.raises(ServerError) as refused:
        _open_version(server.port, 99)
    assert refused.value.code == "version_mismatch" and "99" in str(refused.value)


def _open_version(port, version):
    import socket
    from orchard_world.client import _welcomed
    from orchard_world.messages import decode, encode
    with socket.create_connection(("127.0.0.1", port)) as s:
        s.sendall(encode(Hello(protocol_version=version), 1))
        _welcomed(decode(s.makefile("rb").readline()), f"127.0.0.1:{port}")


def test_without_a_server_the_error_says_so_and_names_the_address(free_port):
    with pytest.raises(OrchardError, match=f"no server is listening at 127.0.0.1:{free_port}"):
        Connection.open("127.0.0.1", free_port)


def test_a_port_out_of_range_is_named():
    with pytest.raises(ValueError, match="port must be a whole number from 1 to 65535, was 70000"):
        Connection.open("127.0.0.1", 70000)


def test_the_asyncio_connection_plays_the_same_protocol(server):
    async def play():
        c = await AsyncConnection.open("127.0.0.1", server.port, client="pytest-async")
        assert c.welcome is not None
        registered = await c.request(Register("Asyncro"))
        await c.send(PerceptionRequest("Asyncro", 1))
        await c.send(EndTurn(c.welcome.tick))
        async for m in c:
            if isinstance(m, LeanPerception):
                await c.close()
                return registered, m
        raise AssertionError("no perception")

    registered, seen = asyncio.run(play())
    assert registered.agent == "Asyncro" and seen.agent == "Asyncro" and seen.tick == 0


class Picker(Agent):
    """The module docstring's agent: to the nearest fruit, face it, grasp it."""

    perceive_every = 1

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


def test_an_agent_subclass_plays_a_whole_lockstep_game_and_collects_fruit():
    from orchard_world.server import ServerProcess
    server = ServerProcess(seed=42, time_limit=30.0, wait_for=1)
    try:
        over = Picker("Picker").run("127.0.0.1", server.port)
    finally:
        server.stop()
    assert isinstance(over, GameOver)
    assert over.ranking[0].agent == "Picker" and over.ranking[0].fruit >= 1, over


def test_a_fruit_the_agent_cannot_walk_to_is_given_up_for_another():
    from orchard_world.server import ServerProcess
    # In this world the fruit nearest to where the agent stands lies on a table, beyond reach from
    # its edge: walking to it is refused, again and again, unless the agent gives it up.
    server = ServerProcess(seed=127382042804051, time_limit=10.0, wait_for=1)
    picker = Picker("Picker")
    try:
        over = picker.run("127.0.0.1", server.port)
    finally:
        server.stop()
    assert picker.out_of_reach, "the fruit on the table"
    assert over.ranking[0].fruit >= 1, over
