#!/usr/bin/env python3
"""A complete Orchard agent in Python 3, standard library only, written from docs/protocol.md.

It registers, perceives every few ticks, walks to the nearest fruit its gripper can reach, faces
it and grasps it; when it sees none it wanders. It plays in both realtime and lockstep games. In
lockstep it ends its setup with EndTurn, acts only on the perception of the tick whose turn is
open and then ends that turn, and draws its random numbers from the seed the server gives it:
the same seed and agents then play the same game again. It reads the lean form of the protocol
(section 16): each perception is one LeanPerception line of whole centimetres and milliradians,
and an accepted move is not answered, so it times its walks itself.

    python3 orchard_agent.py --host localhost --port 7557 --name Pyro
"""
import argparse
import json
import math
import random
import socket
import sys

BODY = {"radius": 0.45, "height": 1.7, "maxSpeed": 8.0,
        "gripper": {"part": "hands", "reach": 0.7, "minHeight": 0.0, "maxHeight": 2.2},
        "sight": {"range": 40.0, "fieldOfView": math.pi * 1.5}}
PERCEIVE_EVERY = 4
FRUIT_RADIUS = {"tomato": 0.15, "banana": 0.25, "coconut": 0.35}


def units(centimetres):
    return centimetres / 100


def radians(milliradians):
    """3142 milliradians stands for pi itself."""
    return math.pi if milliradians == 3142 else milliradians / 1000


class Connection:
    """One line of JSON per message, each with the next seq."""

    def __init__(self, host, port):
        self.sock = socket.create_connection((host, port))
        self.lines = self.sock.makefile("r", encoding="utf-8", newline="\n")
        self.seq = 0

    def send(self, message):
        self.seq += 1
        message["seq"] = self.seq
        self.sock.sendall((json.dumps(message) + "\n").encode("utf-8"))
        return self.seq

    def receive(self):
        line = self.lines.readline()
        return json.loads(line) if line else None


def connect(host, port):
    """The connection, or an exit with one line saying why there is none (no traceback)."""
    where = f"{host}:{port}"
    try:
        return Connection(host, port)
    except ConnectionRefusedError:
        sys.exit(f"orchard_agent.py: no server is listening at {where}; start one first,"
                 " for example with ./orchard server")
    except socket.gaierror:
        sys.exit(f"orchard_agent.py: unknown host '{host}'")
    except OSError as e:
        sys.exit(f"orchard_agent.py: cannot connect to {where}: {e.strerror or e}")


def heading_towards(dx, dz):
    """The heading that faces along (dx, dz): 0 faces north (-z), positive turns left."""
    return math.atan2(-dx, -dz)


class Agent:
    def __init__(self, connection, name, seed, tick_rate):
        self.c = connection
        self.name = name
        self.tick_rate = tick_rate
        self.random = random.Random(seed)
        self.position = None
        self.heading = 0.0
        self.body = BODY
        self.target = None          # fruit id we walk to
        self.walking_until = -1     # tick when the current move ends
        self.given_up = set()       # fruit we could not reach
        self.failures = {}
        self.score = 0

    def reach(self, fruit):
        return self.body["radius"] + self.body["gripper"]["reach"] + fruit["radius"]

    def graspable_height(self, fruit):
        g = self.body["gripper"]
        return g["minHeight"] <= fruit["position"]["y"] <= g["maxHeight"]

    def on_perception(self, p, tick):
        x, y, z = p["position"][:3]
        self.position = {"x": units(x), "y": units(y), "z": units(z)}
        self.heading = radians(p["heading"])
        if tick < self.walking_until:
            return
        seen = []
        for f in p["fruit"]:
            fruit_id, kind, fx, fy, fz, support = f[:6]
            seen.append({"id": fruit_id, "radius": FRUIT_RADIUS.get(kind, 0.35),
                         "position": {"x": units(fx), "y": units(fy), "z": units(fz)}})
        fruit = [f for f in seen if self.graspable_height(f) and f["id"] not in self.given_up]
        if not fruit:
            self.wander(tick)
            return
        here = self.position
        nearest = min(fruit, key=lambda f: math.hypot(f["position"]["x"] - here["x"], f["position"]["z"] - here["z"]))
        dx = nearest["position"]["x"] - here["x"]
        dz = nearest["position"]["z"] - here["z"]
        distance = math.hypot(dx, dz)
        self.target = nearest["id"]
        if distance <= self.reach(nearest) * 0.95:
            self.c.send({"type": "SetRotation", "agent": self.name,
                         "rotation": {"axis": {"x": 0, "y": 1, "z": 0}, "angle": heading_towards(dx, dz)}})
            self.c.send({"type": "GraspRequest", "agent": self.name, "fruit": nearest["id"]})
        else:
            stop = max(0.0, distance - self.reach(nearest) * 0.6)
            self.move_to(here["x"] + dx / distance * stop, here["z"] + dz / distance * stop, tick)

    def move_to(self, x, z, tick):
        here = self.position
        self.c.send({"type": "SetRotation", "agent": self.name,
                     "rotation": {"axis": {"x": 0, "y": 1, "z": 0},
                                  "angle": heading_towards(x - here["x"], z - here["z"])}})
        self.c.send({"type": "Move", "agent": self.name, "from": here, "to": {"x": x, "y": 0, "z": z}})
        # No answer comes when the move is accepted: it takes distance / maxSpeed seconds.
        duration = math.hypot(x - here["x"], z - here["z"]) / self.body["maxSpeed"]
        self.walking_until = tick + int(math.ceil(duration * self.tick_rate)) + 1

    def wander(self, tick):
        angle = self.heading + self.random.uniform(-1.5, 1.5)
        step = self.random.uniform(4, 10)
        here = self.position
        self.target = None
        self.move_to(here["x"] - math.sin(angle) * step, here["z"] - math.cos(angle) * step, tick)

    def on_result(self, r, tick):
        if r.get("action") != "Move":
            return
        if r["outcome"] == "rejected":
            # Something is in the way (the reason names it): try another direction next time.
            if self.target is not None:
                self.failures[self.target] = self.failures.get(self.target, 0) + 1
                if self.failures[self.target] >= 3:
                    self.given_up.add(self.target)
            self.walking_until = -1
        elif r["outcome"] == "blocked":
            # Another agent is in the way: the walk ends early, where the result says.
            self.position = r["position"]
            self.walking_until = tick + int(math.ceil(r["duration"] * self.tick_rate)) + 1


def main():
    parser = argparse.ArgumentParser(description="An Orchard agent in plain Python.")
    parser.add_argument("--host", default="localhost")
    parser.add_argument("--port", type=int, default=7557)
    parser.add_argument("--name", default="Pyro")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()

    c = connect(args.host, args.port)
    c.send({"type": "Hello", "protocolVersion": 2, "role": "agent", "client": "orchard_agent.py",
            "reads": ["LeanPerception"]})
    welcome = c.receive()
    if welcome is None:
        sys.exit(f"orchard_agent.py: {args.host}:{args.port} closed the connection before its welcome")
    if welcome["type"] != "Welcome":
        sys.exit("refused: " + welcome.get("text", str(welcome)))
    lockstep = welcome["clock"] == "lockstep"
    open_turn = None        # lockstep: the tick whose perception we wait for before ending its turn
    next_perception = None  # the tick of our next perception, once the first one came
    c.send({"type": "Register", "name": args.name, "body": BODY})
    agent = Agent(c, args.name, args.seed, welcome["tickRate"])
    tick = welcome["tick"]
    while True:
        m = c.receive()
        if m is None:
            break
        kind = m["type"]
        if kind == "Registered":
            agent.position = m["position"]
            agent.heading = m["heading"]
            agent.body = m["body"]
            if m.get("seed") is not None:
                agent.random = random.Random(m["seed"])  # our own seed, from the game's seed and our name
            c.send({"type": "PerceptionRequest", "agent": args.name, "every": PERCEIVE_EVERY})
            if lockstep:
                c.send({"type": "EndTurn", "tick": tick})  # the setup turn: the game starts when all are set up
        elif kind == "Error":
            print("error:", m["code"], m["text"], file=sys.stderr)
            if m["code"] in ("name_in_use", "wrong_role", "too_many_agents"):
                sys.exit(1)
        elif kind == "Tick":
            tick = m["tick"]
            if lockstep and next_perception == tick:
                open_turn = tick  # our perception follows: act on it, then end the turn
            else:
                c.send({"type": "EndTurn", "tick": tick})
        elif kind == "LeanPerception" and m["agent"] == args.name:
            next_perception = m["tick"] + PERCEIVE_EVERY
            if not lockstep or open_turn == m["tick"]:
                agent.on_perception(m, tick)
            else:
                # The turn was already over: acting now would count in whichever tick it arrived.
                x, y, z = m["position"][:3]
                agent.position = {"x": units(x), "y": units(y), "z": units(z)}
                agent.heading = radians(m["heading"])
            if open_turn == m["tick"]:
                c.send({"type": "EndTurn", "tick": tick})
                open_turn = None
        elif kind == "ActionResult" and m.get("agent") == args.name:
            agent.on_result(m, tick)
        elif kind == "GraspResult" and m["agent"] == args.name:
            if m["success"]:
                agent.score += m["points"]
                print("collected", m["fruit"], "for", m["points"], "points", flush=True)
            else:
                agent.given_up.add(m["fruit"]) if "taken" in (m.get("reason") or "") else None
        elif kind == "GameOver":
            print("game over:", m["reason"], json.dumps(m["ranking"]), flush=True)
            break


if __name__ == "__main__":
    main()
