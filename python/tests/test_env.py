import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env
from pettingzoo.test import api_test, parallel_api_test, parallel_seed_test

import orchard_world  # noqa: F401  (registers orchard_world/Forage-v0)
from orchard_world import OrchardError, ServerError
from orchard_world.env import ACTIONS, OBSERVATION_FIELDS, ForageEnv, env, parallel_env
from orchard_world.server import ServerProcess

SHORT = dict(time_limit=3.0, ticks_per_step=4)
TOKEN = "test-operator-2f9c"


@pytest.fixture
def server_for_resets():
    """A server the env does not start: lockstep, 3-second games, kept serving, with an operator token."""
    process = ServerProcess(seed=1, time_limit=3.0, wait_for=1, operator_token=TOKEN, keep_serving=True)
    try:
        yield process
    finally:
        process.stop()


def test_pettingzoos_parallel_api_test_passes():
    e = parallel_env(agents=2, **SHORT)
    try:
        parallel_api_test(e, num_cycles=100)
    finally:
        e.close()


def test_pettingzoos_parallel_seed_test_passes():
    parallel_seed_test(lambda: parallel_env(agents=2, **SHORT), num_cycles=20)


def test_pettingzoos_aec_api_test_passes():
    e = env(agents=2, **SHORT)
    try:
        api_test(e, num_cycles=20)
    finally:
        e.close()


def test_gymnasiums_check_env_passes_on_forage_among_the_five_with_render():
    e = gym.make("orchard_world/Forage-v0", time_limit=3.0, ticks_per_step=4, render_mode="rgb_array")
    try:
        check_env(e.unwrapped, skip_render_check=False)
    finally:
        e.close()


def test_a_reset_restarts_the_game_on_the_same_server_and_the_same_seed_gives_the_same_game_among_the_five():
    e = ForageEnv(time_limit=4.0, ticks_per_step=2)

    def play(seed):
        obs, _ = e.reset(seed=seed)
        seen = [obs]
        rng = np.random.default_rng(3)
        done = False
        while not done:
            obs, reward, term, trunc, info = e.step(int(rng.integers(len(ACTIONS))))
            seen.append(obs)
            done = term or trunc
        return np.stack(seen), info["scores"]

    try:
        first = play(7)  # on the server the env started with seed 7
        java = [e._env._server.process] + [o.process for o in e._env._opponents]
        other = play(8)  # restarted with seed 8, ended by its time limit
        again = play(7)  # restarted with seed 7 again: the game of a new server of seed 7
        assert [e._env._server.process] + [o.process for o in e._env._opponents] == java
        assert all(p.poll() is None for p in java), "no Java process started anew, none ended"
    finally:
        e.close()
    assert first[0].shape[1] == len(OBSERVATION_FIELDS)
    assert np.array_equal(first[0], again[0])
    assert not np.array_equal(first[0][0], other[0][0]), "another seed, another world"
    assert first[1] == again[1] and set(first[1]) >= {"Forager", "Dwarf", "Robot", "Bunny", "Guppy", "Roadrunner"}


def test_a_running_server_is_reset_with_its_operator_token_and_plays_the_game_of_the_seed(server_for_resets):
    address = f"127.0.0.1:{server_for_resets.port}"
    e = parallel_env(agents=1, server=address, operator_token=TOKEN, **SHORT)
    fresh = parallel_env(agents=1, **SHORT)
    try:
        first, _ = e.reset(seed=5)
        moved = e.step({"learner_0": 1})[0]
        second, _ = e.reset(seed=5)
        on_a_new_server, _ = fresh.reset(seed=5)
        assert np.array_equal(first["learner_0"], second["learner_0"])
        assert np.array_equal(first["learner_0"], on_a_new_server["learner_0"])
        assert np.array_equal(moved["learner_0"], fresh.step({"learner_0": 1})[0]["learner_0"])
        assert server_for_resets.alive()
    finally:
        e.close()
        fresh.close()
    assert server_for_resets.alive(), "the env closes only what it started"


def test_without_its_operator_token_a_running_server_is_played_once_and_a_second_reset_says_why(server_for_resets):
    e = parallel_env(agents=1, server=f"127.0.0.1:{server_for_resets.port}", **SHORT)
    try:
        e.reset(seed=5)
        with pytest.raises(OrchardError, match=r"plays one game: give the env its operator token \(operator_token"):
            e.reset(seed=5)
    finally:
        e.close()


def test_a_wrong_operator_token_is_refused_naming_the_server(server_for_resets):
    e = parallel_env(agents=1, server=f"127.0.0.1:{server_for_resets.port}", operator_token="not-it", **SHORT)
    try:
        with pytest.raises(ServerError, match="unauthorized"):
            e.reset(seed=5)
    finally:
        e.close()


def test_render_draws_the_world_from_above_as_rgb():
    e = parallel_env(agents=1, render_mode="rgb_array", render_size=128, **SHORT)
    try:
        e.reset(seed=1998)
        e.step({"learner_0": 1})
        frame = e.render()
    finally:
        e.close()
    assert frame.shape == (128, 128, 3) and frame.dtype == np.uint8
    assert len({tuple(p) for p in frame.reshape(-1, 3)}) >= 4, "grass, water, trees and an agent at least"


def test_close_stops_the_server_it_started():
    e = parallel_env(agents=1, opponents=["Guppy"], **SHORT)
    e.reset(seed=5)
    processes = [e._server.process] + [o.process for o in e._opponents]
    e.close()
    assert all(p.poll() is not None for p in processes)


@pytest.mark.parametrize("options, named", [
    (dict(agents=0), "agents must be a number from 1 to 800, was 0"),
    (dict(names=["no spaces"]), "'no spaces'"),
    (dict(opponents=["Godzilla"]), "'Godzilla'"),
    (dict(ticks_per_step=0), "ticks_per_step must be a number from 1 to 100, was 0"),
    (dict(render_mode="human"), "render_mode must be 'rgb_array' or None, was 'human'"),
    (dict(server="nowhere"), "server must be 'host:port', was 'nowhere'"),
    (dict(operator_token="secret"), "operator_token goes with server='host:port'"),
])
def test_a_bad_option_is_refused_naming_it(options, named):
    with pytest.raises(ValueError, match=named.replace("(", r"\(").replace(")", r"\)")):
        parallel_env(**options)


def test_a_python_killed_mid_game_leaves_no_java_behind(tmp_path):
    import os
    import signal
    import subprocess
    import sys
    import time

    script = tmp_path / "crash.py"
    script.write_text(
        "import os, sys\n"
        "from orchard_world.env import parallel_env\n"
        "e = parallel_env(agents=1, opponents=['Guppy'], time_limit=600.0)\n"
        "e.reset(seed=3)\n"
        "print(e._server.process.pid, *[o.process.pid for o in e._opponents], flush=True)\n"
        "sys.stdin.read()\n")
    child = subprocess.Popen([sys.executable, str(script)], stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    java = [int(pid) for pid in child.stdout.readline().split()]
    assert len(java) == 2
    os.kill(child.pid, signal.SIGKILL)
    child.wait()
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline and any(_alive(pid) for pid in java):
        time.sleep(0.2)
    assert not any(_alive(pid) for pid in java), f"still running: {[p for p in java if _alive(p)]}"


def _alive(pid):
    try:
        with open(f"/proc/{pid}/stat") as stat:
            return stat.read().split(")")[-1].split()[0] != "Z"
    except FileNotFoundError:
        return False
