"""Environment steps per second with random actions, for 1, 5 and 50 learners (docs/benchmarks.md).

    python python/benchmarks/steps_per_second.py [--agents 1 5 50] [--steps 3000] [--ticks-per-step 1]
                                                 [--five] [--resets 20]

Each count plays one lockstep game on a server of its own (started and warmed up first, not
timed) and prints the steps per second, the agent-steps per second, and where the wall-clock time
went: the share in Python's own work (its CPU time), the share in the server's (the CPU time of
its process, read from /proc on Linux), the rest being the wait for the socket and for the
machine's scheduler. With ``--five`` the learner plays among the paper's five (``Forage-v0``), and
the agents' process is measured too. ``--resets N`` times N resets, each a new game of a new seed
on the same server.
"""
from __future__ import annotations

import argparse
import os
import time
from typing import Any, Dict, List, Optional

import numpy as np

from orchard_world.env import parallel_env


def cpu_seconds(pid: int) -> Optional[float]:
    """The CPU time (user and system) of a process so far, or None where /proc does not say."""
    try:
        with open(f"/proc/{pid}/stat") as stat:
            fields = stat.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    except (OSError, IndexError, ValueError):
        return None


def share(pid: int, before: Optional[float], wall: float) -> str:
    after = cpu_seconds(pid)
    return "?" if before is None or after is None else f"{(after - before) / wall:4.0%}"


def measure(agents: int, steps: int, ticks_per_step: int, five: bool, resets: int) -> None:
    options: Dict[str, Any] = dict(ticks_per_step=ticks_per_step, time_limit=steps * ticks_per_step / 20 + 10)
    env = parallel_env(agents=agents, opponents=["Dwarf", "Robot", "Bunny", "Guppy", "Roadrunner"] if five else (),
                       **options)
    try:
        env.reset(seed=1998)
        rng = np.random.default_rng(1)
        for _ in range(200):  # warm-up: the server's and the agents' JIT
            env.step({a: int(rng.integers(5)) for a in env.agents})
        server = env._server.process.pid
        others: List[int] = [o.process.pid for o in env._opponents]
        before = {pid: cpu_seconds(pid) for pid in [server, *others]}
        wall, cpu = time.perf_counter(), time.process_time()
        done = 0
        while env.agents and done < steps:
            env.step({a: int(rng.integers(5)) for a in env.agents})
            done += 1
        wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
        where = f"Python {cpu / wall:4.0%}, server {share(server, before[server], wall)}"
        if others:
            where += f", the five {share(others[0], before[others[0]], wall)}"
        print(f"{agents:3d} learner{'s' if agents > 1 else ' '}{' among the five' if five else ''}, "
              f"{ticks_per_step} tick{'s' if ticks_per_step > 1 else ''}/step: {done / wall:7.0f} steps/s, "
              f"{done * agents / wall:7.0f} agent-steps/s; of the time: {where}", flush=True)
        if resets:
            started = time.perf_counter()
            for seed in range(resets):
                env.reset(seed=2000 + seed)
            print(f"    a reset (a new game of a new seed on the same server): "
                  f"{(time.perf_counter() - started) / resets * 1000:.0f} ms", flush=True)
    finally:
        env.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--agents", type=int, nargs="+", default=[1, 5, 50])
    parser.add_argument("--steps", type=int, default=3000)
    parser.add_argument("--ticks-per-step", type=int, default=1)
    parser.add_argument("--five", action="store_true", help="play among the paper's five agents")
    parser.add_argument("--resets", type=int, default=0, help="also time this many resets")
    args = parser.parse_args()
    print(f"load average {os.getloadavg()[0]:.1f} at the start", flush=True)
    for count in args.agents:
        measure(count, args.steps, args.ticks_per_step, args.five, args.resets)
    print(f"load average {os.getloadavg()[0]:.1f} at the end", flush=True)


if __name__ == "__main__":
    main()
