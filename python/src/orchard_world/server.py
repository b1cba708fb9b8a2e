"""Starting and stopping an Orchard server (and the paper's agents) as child processes.

The Java programs are those of the Maven build: ``examples/target/classes`` and the libraries
listed in ``examples/target/classpath.txt`` of a clone, the class path ``./orchard`` runs
(``./orchard --version`` builds them once). The clone is found from ``ORCHARD_HOME``, else from
the working directory or this package's own place upwards; ``ORCHARD_CLASSPATH`` gives a class
path directly instead.

No process outlives its Python: each child holds the read end of a pipe as its standard input,
started with ``--stop-on-stdin-close`` for the server, and the kernel closes that pipe when
Python exits, however it exits. On Linux the child is also sent SIGTERM when its parent dies.
"""
from __future__ import annotations

import collections
import os
import re
import signal
import subprocess
import sys
import threading
from pathlib import Path
from typing import Deque, Dict, List, Optional, Sequence

from .errors import ServerStartError

__all__ = ["java_classpath", "ServerProcess", "start_opponents", "LAUNCHER"]

LAUNCHER = "io.orchard.examples.Orchard"
SPECIES = ("Dwarf", "Robot", "Bunny", "Guppy", "Roadrunner")
# Quick to start, which matters most for many short games: the client compiler alone, a small heap.
JAVA_OPTIONS = ("-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-Xmx512m")
_LISTENING = re.compile(r"listening on port (\d+)")


def _clone_candidates() -> List[Path]:
    places = []
    if os.environ.get("ORCHARD_HOME"):
        places.append(Path(os.environ["ORCHARD_HOME"]))
    for start in (Path.cwd(), Path(__file__).resolve().parent):
        places.extend([start, *start.parents])
    return places


def java_classpath() -> str:
    """The class path of the Orchard launcher, from ORCHARD_CLASSPATH or a built clone."""
    if os.environ.get("ORCHARD_CLASSPATH"):
        return os.environ["ORCHARD_CLASSPATH"]
    looked = []
    for place in _clone_candidates():
        listed = place / "examples" / "target" / "classpath.txt"
        if (place / "orchard").is_file() and (place / "examples").is_dir():
            if listed.is_file():
                return f"{place / 'examples' / 'target' / 'classes'}{os.pathsep}{listed.read_text().strip()}"
            looked.append(str(place))
    if looked:
        raise ServerStartError(f"the Orchard clone at {looked[0]} is not built yet: run ./orchard --version there "
                               "once (it builds), or set ORCHARD_CLASSPATH")
    raise ServerStartError("no Orchard clone found above the working directory or this package: set ORCHARD_HOME "
                           "to your clone (built once with ./orchard --version), or ORCHARD_CLASSPATH, or pass "
                           "server='host:port' to play on a running server")


def _die_with_parent() -> None:
    if sys.platform.startswith("linux"):
        try:
            import ctypes
            ctypes.CDLL("libc.so.6", use_errno=True).prctl(1, signal.SIGTERM)  # PR_SET_PDEATHSIG
        except OSError:
            pass  # the closed pipe still stops the child


class _JavaProcess:
    """A launcher command in a JVM of its own, its output kept (the last lines) for error messages."""

    def __init__(self, args: Sequence[str], java: str = "java", java_options: Sequence[str] = (),
                 environment: Optional[Dict[str, str]] = None) -> None:
        command = [java, *java_options, "-cp", java_classpath(), LAUNCHER, *args]
        self.command = command
        try:
            self.process = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                            stderr=subprocess.STDOUT, preexec_fn=_die_with_parent,
                                            close_fds=True, env=None if environment is None
                                            else {**os.environ, **environment})
        except FileNotFoundError:
            raise ServerStartError(f"cannot run {java!r}: Orchard needs a JDK 17 or newer as java on the PATH, "
                                   "or JAVA_HOME") from None
        self.output: Deque[str] = collections.deque(maxlen=40)
        self._reader = threading.Thread(target=self._drain, name="orchard-output", daemon=True)
        self._port: Optional[int] = None
        self._listening = threading.Event()

    def _drain(self) -> None:
        assert self.process.stdout is not None
        for raw in self.process.stdout:
            line = raw.decode("utf-8", "replace").rstrip()
            self.output.append(line)
            found = _LISTENING.search(line)
            if found and self._port is None:
                self._port = int(found.group(1))
                self._listening.set()
        self._listening.set()

    def stop(self, grace: float = 5.0) -> None:
        """Closes its input (it ends its game and exits), then terminates it if it does not."""
        if self.process.poll() is None and self.process.stdin is not None:
            try:
                self.process.stdin.close()
            except OSError:
                pass
        for ask in (None, self.process.terminate, self.process.kill):
            if ask is not None and self.process.poll() is None:
                ask()
            try:
                self.process.wait(grace)
                break
            except subprocess.TimeoutExpired:
                continue
        if self.process.stdin is not None and not self.process.stdin.closed:
            self.process.stdin.close()
        self._reader.join(1)


class ServerProcess(_JavaProcess):
    """``orchard server`` on a free port, stopped with its input; ``port`` once it listens.

    With ``operator_token`` (handed over in the environment, out of sight of ``ps``) a client that
    presents it controls the game; with ``keep_serving`` the server stays once a game is over, and
    the operator's restart (``GameControl restart``) starts the next game on it.
    """

    def __init__(self, *, seed: int, clock: str = "lockstep", time_limit: float = 60.0, wait_for: int = 0,
                 turn_deadline: float = 60.0, tick_rate: int = 20, extra: Sequence[str] = (),
                 java: str = "java", java_options: Sequence[str] = JAVA_OPTIONS,
                 start_timeout: float = 60.0, operator_token: Optional[str] = None,
                 keep_serving: bool = False) -> None:
        args = ["server", "--port", "0", "--seed", str(seed), "--clock", clock, "--time-limit", repr(float(time_limit)),
                "--wait-for", str(wait_for), "--turn-deadline", repr(float(turn_deadline)),
                "--tick-rate", str(tick_rate), "--quiet", "--stop-on-stdin-close",
                *(["--keep-serving"] if keep_serving else []), *extra]
        super().__init__(args, java, java_options,
                         None if operator_token is None else {"ORCHARD_OPERATOR_TOKEN": operator_token})
        self._reader.start()
        if not self._listening.wait(start_timeout) or self._port is None:
            self.stop()
            raise ServerStartError("the Orchard server did not start: " + " | ".join(self.output)
                                   + f" (command: {' '.join(self.command[:2])} ... {' '.join(args)})")

    @property
    def port(self) -> int:
        assert self._port is not None
        return self._port

    def alive(self) -> bool:
        """Whether the server still runs."""
        return self.process.poll() is None


def start_opponents(port: int, species: Sequence[str], tokens_file: str, java: str = "java",
                    java_options: Sequence[str] = JAVA_OPTIONS, next_games: bool = False) -> List[_JavaProcess]:
    """The paper's agents named in ``species`` playing on ``port``: all five in one JVM, else one each.

    With ``next_games`` they stay for each game the server's operator restarts, and play it anew.
    """
    unknown = [s for s in species if s not in SPECIES]
    if unknown:
        raise ValueError(f"opponents must be among {', '.join(SPECIES)}, was {unknown[0]!r}")
    if len(set(species)) != len(species):
        raise ValueError(f"opponents must name each species at most once, was {list(species)!r}")
    if sorted(species) == sorted(SPECIES):
        commands = [["agents", "--port", str(port), "--resume-tokens", tokens_file]]
    else:
        commands = [["agent", "--type", s, "--port", str(port), "--resume-tokens", tokens_file] for s in species]
    started = []
    for args in commands:
        process = _JavaProcess([*args, "--next-games"] if next_games else args, java, java_options)
        process._reader.start()
        started.append(process)
    return started
