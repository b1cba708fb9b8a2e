"""Trains a PPO policy (Stable-Baselines3) on orchard_world/Forage-v0 and plots its learning curve
against the paper's five agents in the same setting.

    pip install "./python[train]"          # stable-baselines3 (with PyTorch) and matplotlib
    python python/examples/train_forage.py --minutes 20 --plot forage-ppo.png

By default the learner, Forager, forages alone in 30-second games, a new world each episode, in
--envs games played side by side (each on a server of its own, stepped together by SB3's
SubprocVecEnv). The five are measured in the same setting: each of them alone in games of the same
length, on --games worlds, beside a Forager that stands still; the trained policy then plays the
same worlds alone, and among all five at once (the environment's default setting). The plot shows
the learner's points per training episode (each, and a moving average) with the five's means as
lines, and those evaluations as bars; --csv writes each training episode's points.

The policy learns from the points plus a reward for getting nearer to, and facing, the nearest
fruit the gripper reaches in height (``Shaping``; ``--shaping 0`` for the points alone); the plot
counts the points alone.
"""
from __future__ import annotations

import argparse
import csv
import math
import os
import time
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, cast

import gymnasium as gym
import numpy as np

import orchard_world  # noqa: F401  (registers orchard_world/Forage-v0)
from orchard_world.env import ForageEnv
from orchard_world.server import SPECIES

LEARNER = "Forager"
COLOURS = {"Dwarf": "#8c564b", "Robot": "#7f7f7f", "Bunny": "#e377c2", "Guppy": "#17becf", "Roadrunner": "#bcbd22",
           LEARNER: "#1f77b4"}


class Shaping(gym.Wrapper):  # type: ignore[misc]
    """Adds to the points the policy learns from (not to those it is scored by) a reward for progress.

    The target is the nearest fruit in view whose height the gripper reaches. While it stays the same
    fruit, a step earns ``weight`` times the units the agent got nearer to it plus a quarter of how
    much more squarely it faces it (the cosine of its bearing); moving away costs as much. The step
    on which the target changes (taken, out of view, or another one nearer) earns nothing but its
    points. A potential-based term (Ng, Harada and Russell, 1999) was tried first and taught the
    policy not to grasp: the potential falls when a fruit is taken, since the next one is farther,
    so every grasp looked like a loss until the critic had learnt far more than it had.
    """

    def __init__(self, env: gym.Env, weight: float) -> None:
        super().__init__(env)
        self.weight = weight
        self.last: Optional[Tuple[str, float, float]] = None

    def target(self) -> Optional[Tuple[str, float, float]]:
        """The target's id, its distance and the cosine of its bearing; None with no fruit in reach of height."""
        forage = cast(ForageEnv, self.env.unwrapped)
        p, gripper = forage.perception, forage.body.gripper
        if p is None:
            return None
        best = None
        for f in p.fruit:
            if gripper.min_height <= f.position.y <= gripper.max_height:
                dx, dz = f.position.x - p.position.x, f.position.z - p.position.z
                distance = math.hypot(dx, dz)
                if best is None or (distance, f.id) < (best[1], best[0]):
                    facing = (-dx * math.sin(p.heading) - dz * math.cos(p.heading)) / distance if distance else 1.0
                    best = (f.id, distance, facing)
        return best

    def reset(self, **kwargs: Any) -> Tuple[Any, Dict[str, Any]]:
        observation, info = self.env.reset(**kwargs)
        self.last = self.target()
        return observation, info

    def step(self, action: Any) -> Tuple[Any, float, bool, bool, Dict[str, Any]]:
        observation, points, terminated, truncated, info = self.env.step(action)
        reward = float(points)
        now = self.target()
        if now is not None and self.last is not None and now[0] == self.last[0]:
            reward += self.weight * ((self.last[1] - now[1]) + 0.25 * (now[2] - self.last[2]))
        self.last = now
        return observation, reward, terminated, truncated, info


def moving_average(values: Sequence[float], window: int) -> np.ndarray:
    """The mean of each value and of up to ``window - 1`` values before it."""
    cumulative = np.cumsum(np.insert(np.asarray(values, dtype=float), 0, 0.0))
    end = np.arange(1, len(values) + 1)
    start = np.maximum(0, end - window)
    return (cumulative[end] - cumulative[start]) / (end - start)


def play(make: Callable[[], gym.Env], seeds: Sequence[int], act: Callable[[np.ndarray], int]) -> List[Dict[str, int]]:
    """Everyone's points in one game of each world of ``seeds``, the learner acting by ``act``."""
    env = make()
    scores = []
    try:
        for seed in seeds:
            observation, _ = env.reset(seed=seed)
            done = False
            while not done:
                observation, _, terminated, truncated, info = env.step(act(observation))
                done = terminated or truncated
            scores.append(info["scores"])
    finally:
        env.close()
    return scores


def plot(path: str, episodes: List[Dict[str, Any]], alone: Dict[str, float], learned_alone: Optional[float],
         among: Dict[str, float], title: str, window: int) -> None:
    """The learning curve beside the five's means alone; the evaluations as bars when there are some."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    if learned_alone is None:
        figure, curve = plt.subplots(figsize=(9, 5.4), dpi=110)
    else:
        figure, (curve, bars) = plt.subplots(1, 2, figsize=(11.5, 5.4), dpi=110,
                                             gridspec_kw={"width_ratios": [2.3, 1]})
    x = [e["episode"] for e in episodes]
    points = [e[LEARNER] for e in episodes]
    curve.scatter(x, points, s=7, color=COLOURS[LEARNER], alpha=0.25, label=f"{LEARNER} (PPO), each episode")
    curve.plot(x, moving_average(points, window), color=COLOURS[LEARNER], linewidth=2.6,
               label=f"{LEARNER} (PPO), mean of {window}")
    for name in alone:
        curve.axhline(alone[name], color=COLOURS[name], linewidth=1.4, linestyle="--", label=f"{name} alone, mean")
    curve.set_xlabel("training episode (a game alone in a world of its own)")
    curve.set_ylabel("points in the game")
    curve.grid(alpha=0.3)
    curve.legend(fontsize=7.5, loc="upper left", ncol=2)
    if learned_alone is not None:
        _bars(bars, alone, learned_alone, among)
    figure.suptitle(title, fontsize=9.5)
    figure.tight_layout()
    figure.savefig(path)
    plt.close(figure)


def _bars(bars: Any, alone: Dict[str, float], learned_alone: float, among: Dict[str, float]) -> None:
    names = [LEARNER, *SPECIES]
    at = np.arange(len(names))
    bars.bar(at - 0.2, [learned_alone] + [alone[n] for n in SPECIES], width=0.4, label="alone",
             color=[COLOURS[n] for n in names], edgecolor="black", linewidth=0.5)
    bars.bar(at + 0.2, [among.get(n, 0.0) for n in names], width=0.4, label="all six in one game",
             color=[COLOURS[n] for n in names], edgecolor="black", linewidth=0.5, hatch="//", alpha=0.6)
    bars.set_xticks(at, [("PPO" if n == LEARNER else n) for n in names], rotation=30, fontsize=8)
    bars.set_title("the same worlds after training: mean points", fontsize=9)
    bars.legend(fontsize=8)
    bars.grid(alpha=0.3, axis="y")


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--minutes", type=float, default=20.0, help="wall-clock minutes to train (default 20)")
    parser.add_argument("--envs", type=int, default=4, help="games played side by side, a server each (4)")
    parser.add_argument("--time-limit", type=float, default=30.0, help="simulated seconds per episode (30)")
    parser.add_argument("--ticks-per-step", type=int, default=4, help="ticks per step (4: a fifth of a second)")
    parser.add_argument("--shaping", type=float, default=0.1,
                        help="reward per unit of progress towards fruit (default 0.1; 0 learns from the points alone)")
    parser.add_argument("--games", type=int, default=10, help="worlds the five and the trained policy are measured on")
    parser.add_argument("--seed", type=int, default=1998, help="seed of the worlds and of the policy")
    parser.add_argument("--window", type=int, default=40, help="episodes in the moving average (40)")
    parser.add_argument("--plot", default="forage-ppo.png", help="where to write the learning curve")
    parser.add_argument("--csv", help="also write each training episode's points here")
    args = parser.parse_args()

    import torch
    from stable_baselines3 import PPO
    from stable_baselines3.common.callbacks import BaseCallback
    from stable_baselines3.common.vec_env import SubprocVecEnv

    # The servers share the machine with the policy: one thread for PyTorch.
    torch.set_num_threads(1)
    gamma = 0.99
    options = dict(time_limit=args.time_limit, ticks_per_step=args.ticks_per_step)

    def learner_env() -> gym.Env:
        env = gym.make("orchard_world/Forage-v0", opponents=[], **options)
        return Shaping(env, args.shaping) if args.shaping else env

    class Progress(BaseCallback):  # type: ignore[misc]
        """Keeps every finished episode's points; stops the training once its minutes are up."""

        def __init__(self, seconds: float) -> None:
            super().__init__()
            self.until = time.monotonic() + seconds
            self.episodes: List[Dict[str, Any]] = []

        def _on_step(self) -> bool:
            for done, info in zip(self.locals["dones"], self.locals["infos"]):
                if done:
                    self.episodes.append(dict(episode=len(self.episodes) + 1, steps=self.num_timesteps,
                                              **{LEARNER: info["scores"].get(LEARNER, 0)}))
                    if len(self.episodes) % 50 == 0:
                        last = [e[LEARNER] for e in self.episodes[-50:]]
                        print(f"  episode {len(self.episodes)}, {self.num_timesteps} steps: "
                              f"{np.mean(last):.2f} points a game over the last 50", flush=True)
            return time.monotonic() < self.until

    seeds = [args.seed * 1000 + k for k in range(args.games)]
    started = time.monotonic()
    alone: Dict[str, float] = {}
    for name in SPECIES if seeds else ():
        if not alone:
            print(f"the five alone in {args.games} worlds of {args.time_limit:.0f} s, beside a Forager that stands "
                  "still", flush=True)
        games = play(lambda: gym.make("orchard_world/Forage-v0", opponents=[name], **options), seeds, lambda o: 0)
        alone[name] = float(np.mean([g.get(name, 0) for g in games]))
        print(f"  {name:<10} {alone[name]:5.1f} points a game", flush=True)

    vec = SubprocVecEnv([learner_env for _ in range(args.envs)])
    vec.seed(args.seed)
    model = PPO("MlpPolicy", vec, n_steps=256, batch_size=256, n_epochs=10, learning_rate=3e-4, gamma=gamma,
                gae_lambda=0.95, ent_coef=0.01, seed=args.seed, device="cpu", verbose=0)
    progress = Progress(args.minutes * 60)
    print(f"training for {args.minutes:.0f} minutes, {args.envs} games at once", flush=True)
    trained = time.monotonic()
    try:
        model.learn(total_timesteps=10 ** 9, callback=progress)
    finally:
        vec.close()
    seconds = time.monotonic() - trained
    episodes = progress.episodes
    if not episodes:
        raise SystemExit("no episode ended in the time given: train for longer (--minutes)")
    steps = model.num_timesteps
    print(f"{len(episodes)} episodes, {steps} steps in {seconds / 60:.1f} minutes ({steps / seconds:.0f} steps/s)")

    def act(observation: np.ndarray) -> int:
        return int(model.predict(observation, deterministic=False)[0])

    first, last = episodes[:args.window], episodes[-args.window:]
    print(f"{LEARNER}: {np.mean([e[LEARNER] for e in first]):.2f} points a game in the first {len(first)} episodes, "
          f"{np.mean([e[LEARNER] for e in last]):.2f} in the last {len(last)}")
    learned_alone: Optional[float] = None
    among: Dict[str, float] = {}
    if seeds:
        learned = play(lambda: gym.make("orchard_world/Forage-v0", opponents=[], **options), seeds, act)
        learned_alone = float(np.mean([g.get(LEARNER, 0) for g in learned]))
        among_games = play(lambda: gym.make("orchard_world/Forage-v0", **options), seeds, act)
        among = {n: float(np.mean([g.get(n, 0) for g in among_games])) for n in (LEARNER, *SPECIES)}
        print(f"on the same {args.games} worlds: alone, PPO {learned_alone:.1f}, "
              + ", ".join(f"{n} {alone[n]:.1f}" for n in SPECIES))
        print("all six in one game: " + ", ".join(f"{'PPO' if n == LEARNER else n} {among[n]:.1f}" for n in among))

    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    title = (f"PPO (Stable-Baselines3) on orchard_world/Forage-v0, alone, {args.time_limit:.0f}-s games, "
             f"{args.ticks_per_step} ticks a step, shaping weight {args.shaping:g}\n"
             f"{steps:,} steps ({len(episodes)} games) in {seconds / 60:.0f} min, {args.envs} games at once, on "
             f"{os.cpu_count()} CPU cores (load average {load:.0f}); the whole run "
             f"{(time.monotonic() - started) / 60:.0f} min")
    plot(args.plot, episodes, alone, learned_alone, among, title, args.window)
    print(f"wrote {args.plot}")
    if args.csv:
        with open(args.csv, "w", newline="") as out:
            writer = csv.DictWriter(out, fieldnames=["episode", "steps", LEARNER])
            writer.writeheader()
            writer.writerows(episodes)
        print(f"wrote {args.csv}")


if __name__ == "__main__":
    main()
