"""Trains a PPO policy (Stable-Baselines3) on orchard_world/Forage-v0 and plots its learning curve
against the paper's five agents, who play in the same games.

    pip install "./python[train]"          # stable-baselines3 (with PyTorch) and matplotlib
    python python/examples/train_forage.py --minutes 10 --plot forage-ppo.png

The learner, Forager, plays every episode among Dwarf, Robot, Bunny, Guppy and Roadrunner, each
episode a new world (its seed drawn from --seed). For every episode the script keeps the points of
each player; the plot shows them per episode, the learner's and each of the five's, with a moving
average, so the learner's curve is read against what the five score in the very same games.
--csv writes the numbers too. It trains on the CPU, for a number of minutes of wall-clock time
rather than of steps, since how many steps a minute gives depends on the machine and its load.

The policy learns from the points plus a shaping term that rewards getting nearer to fruit and into
reach (``Shaping``; ``--shaping 0`` for the points alone): the five collect the fruit fast, and a
policy that moves at random almost never grasps one, so the points alone give it next to nothing
to learn from. The plot and the CSV count the points alone.
"""
from __future__ import annotations

import argparse
import csv
import os
import time
from typing import Any, Dict, List, Tuple

import gymnasium as gym
import numpy as np

import orchard_world  # noqa: F401  (registers orchard_world/Forage-v0)
from orchard_world.env import OBSERVATION_FIELDS
from orchard_world.server import SPECIES

LEARNER = "Forager"


class Scores(gym.Wrapper):  # type: ignore[misc]
    """Keeps, for every episode that ends, everyone's points and the steps trained so far."""

    def __init__(self, env: gym.Env) -> None:
        super().__init__(env)
        self.episodes: List[Dict[str, Any]] = []
        self.steps = 0

    def step(self, action: Any) -> Tuple[Any, float, bool, bool, Dict[str, Any]]:
        observation, reward, terminated, truncated, info = self.env.step(action)
        self.steps += 1
        if terminated or truncated:
            scores = info["scores"]
            self.episodes.append(dict(episode=len(self.episodes) + 1, steps=self.steps, seconds=time.monotonic(),
                                      **{name: scores.get(name, 0) for name in (LEARNER, *SPECIES)}))
        return observation, reward, terminated, truncated, info


class Shaping(gym.Wrapper):  # type: ignore[misc]
    """Adds a potential-based term to the points the policy learns from (not to those it is scored by).

    The potential of an observation is how near the nearest fruit in view is (1 at the agent, 0 at
    the edge of sight, 0 with none in view), and 1 more when a grasp would take it now: the policy
    is rewarded for getting nearer to fruit and into reach, a fruit's points are a long way off for
    a policy that moves at random. As the term is a difference of potentials, ``gamma * phi(next) -
    phi(now)``, it does not change which policy is best (Ng, Harada and Russell, 1999).
    """

    def __init__(self, env: gym.Env, gamma: float, weight: float) -> None:
        super().__init__(env)
        self.gamma, self.weight = gamma, weight
        fields = OBSERVATION_FIELDS
        self.present, self.distance, self.graspable = (fields.index("fruit0.present"),
                                                       fields.index("fruit0.distance"),
                                                       fields.index("fruit0.graspable"))
        self.potential = 0.0

    def phi(self, observation: np.ndarray) -> float:
        if observation[self.present] < 0.5:
            return 0.0
        return float(1.0 - observation[self.distance] + observation[self.graspable])

    def reset(self, **kwargs: Any) -> Tuple[Any, Dict[str, Any]]:
        observation, info = self.env.reset(**kwargs)
        self.potential = self.phi(observation)
        return observation, info

    def step(self, action: Any) -> Tuple[Any, float, bool, bool, Dict[str, Any]]:
        observation, reward, terminated, truncated, info = self.env.step(action)
        potential = 0.0 if terminated or truncated else self.phi(observation)
        shaped = reward + self.weight * (self.gamma * potential - self.potential)
        self.potential = potential
        return observation, shaped, terminated, truncated, info


def moving_average(values: List[float], window: int) -> np.ndarray:
    """The mean of each value and of up to ``window - 1`` values before it."""
    cumulative = np.cumsum(np.insert(np.asarray(values, dtype=float), 0, 0.0))
    end = np.arange(1, len(values) + 1)
    start = np.maximum(0, end - window)
    return (cumulative[end] - cumulative[start]) / (end - start)


def plot(episodes: List[Dict[str, Any]], path: str, title: str, window: int) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    x = [e["episode"] for e in episodes]
    figure, axes = plt.subplots(figsize=(9, 5.2), dpi=110)
    colours = {"Dwarf": "#8c564b", "Robot": "#7f7f7f", "Bunny": "#e377c2", "Guppy": "#17becf",
               "Roadrunner": "#bcbd22"}
    for name in SPECIES:
        points = [e[name] for e in episodes]
        axes.plot(x, moving_average(points, window), color=colours[name], linewidth=1.6, label=name)
    learner = [e[LEARNER] for e in episodes]
    axes.scatter(x, learner, s=9, color="#1f77b4", alpha=0.35, label=f"{LEARNER} (PPO), each episode")
    axes.plot(x, moving_average(learner, window), color="#1f77b4", linewidth=2.8,
              label=f"{LEARNER} (PPO), mean of {window}")
    axes.set_xlabel("episode (a game of its own world, among the five)")
    axes.set_ylabel("points in the episode")
    axes.set_title(title, fontsize=10)
    axes.grid(alpha=0.3)
    axes.legend(fontsize=8, loc="upper left", ncol=2)
    figure.tight_layout()
    figure.savefig(path)
    plt.close(figure)


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--minutes", type=float, default=10.0, help="wall-clock minutes to train (default 10)")
    parser.add_argument("--time-limit", type=float, default=60.0, help="simulated seconds per episode (60)")
    parser.add_argument("--ticks-per-step", type=int, default=4, help="ticks per step (4: a fifth of a second)")
    parser.add_argument("--seed", type=int, default=1998, help="seed of the worlds and of the policy")
    parser.add_argument("--window", type=int, default=20, help="episodes in the moving average (20)")
    parser.add_argument("--plot", default="forage-ppo.png", help="where to write the learning curve")
    parser.add_argument("--csv", help="also write each episode's points here")
    parser.add_argument("--shaping", type=float, default=0.5,
                        help="weight of the shaping term towards fruit (default 0.5; 0 learns from the points alone)")
    args = parser.parse_args()

    import torch
    from stable_baselines3 import PPO
    from stable_baselines3.common.callbacks import BaseCallback

    # The server and the five agents play on the same machine: one core for the policy leaves them one.
    torch.set_num_threads(1)

    class Clock(BaseCallback):  # type: ignore[misc]
        """Stops the training once its minutes are up."""

        def __init__(self, seconds: float) -> None:
            super().__init__()
            self.until = time.monotonic() + seconds

        def _on_step(self) -> bool:
            return time.monotonic() < self.until

    gamma = 0.995
    env = Scores(gym.make("orchard_world/Forage-v0", time_limit=args.time_limit,
                          ticks_per_step=args.ticks_per_step))
    learned = Shaping(env, gamma, args.shaping) if args.shaping else env
    learned.reset(seed=args.seed)
    model = PPO("MlpPolicy", learned, n_steps=1024, batch_size=128, learning_rate=3e-4, gamma=gamma,
                ent_coef=0.01, seed=args.seed, device="cpu", verbose=0)
    started = time.monotonic()
    try:
        model.learn(total_timesteps=10 ** 9, callback=Clock(args.minutes * 60))
    finally:
        env.close()
    seconds = time.monotonic() - started
    episodes = env.episodes
    if not episodes:
        raise SystemExit("no episode ended in the time given: train for longer (--minutes)")
    print(f"{len(episodes)} episodes, {env.steps} steps in {seconds / 60:.1f} minutes "
          f"({env.steps / seconds:.0f} steps/s)")
    last = episodes[-args.window:]
    for name in (LEARNER, *SPECIES):
        print(f"  {name:<10} {np.mean([e[name] for e in last]):5.1f} points per episode over the last {len(last)}")
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    title = (f"PPO (Stable-Baselines3) on orchard_world/Forage-v0 among the paper's five\n"
             f"{env.steps:,} steps in {seconds / 60:.0f} min on {os.cpu_count()} CPU cores (load average "
             f"{load:.0f}); {args.time_limit:.0f} s games, {args.ticks_per_step} ticks a step, a new world each\n"
             f"episode; learning from the points"
             + (f" and a shaping term towards fruit (weight {args.shaping})" if args.shaping else " alone")
             + "; the points are plotted")
    plot(episodes, args.plot, title, args.window)
    print(f"wrote {args.plot}")
    if args.csv:
        with open(args.csv, "w", newline="") as out:
            writer = csv.DictWriter(out, fieldnames=["episode", "steps", LEARNER, *SPECIES])
            writer.writeheader()
            for e in episodes:
                writer.writerow({k: e[k] for k in writer.fieldnames})
        print(f"wrote {args.csv}")


if __name__ == "__main__":
    main()
