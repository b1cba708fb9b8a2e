"""Environment steps per second with random actions, for 1, 5 and 50 learners (docs/python.md).

    python python/benchmarks/steps_per_second.py [--agents 1 5 50] [--steps 2000]

Each count plays one lockstep game on a server of its own (started first, not timed) with
ticks_per_step 1, and prints the steps per second, the agent-steps per second, and the share of
the time spent in Python (profiled separately would slow it down: here it is the process's CPU
time over the wall-clock time, the rest is the socket and the server).
"""
from __future__ import annotations

import argparse
import time

import numpy as np

from orchard_world.env import parallel_env


def measure(agents: int, steps: int) -> None:
    env = parallel_env(agents=agents, ticks_per_step=1, time_limit=steps / 20 + 10)
    try:
        env.reset(seed=1998)
        rng = np.random.default_rng(1)
        for _ in range(50):  # warm-up: the server's JIT
            env.step({a: int(rng.integers(5)) for a in env.agents})
        wall, cpu = time.perf_counter(), time.process_time()
        done = 0
        while env.agents and done < steps:
            env.step({a: int(rng.integers(5)) for a in env.agents})
            done += 1
        wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    finally:
        env.close()
    print(f"{agents:3d} agents: {done / wall:8.0f} steps/s, {done * agents / wall:8.0f} agent-steps/s, "
          f"Python {cpu / wall:4.0%} of the time")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--agents", type=int, nargs="+", default=[1, 5, 50])
    parser.add_argument("--steps", type=int, default=2000)
    args = parser.parse_args()
    for count in args.agents:
        measure(count, args.steps)


if __name__ == "__main__":
    main()
