"""Connections to an Orchard server, blocking and asyncio: the handshake, lines out, typed messages in.

Blocking::

    with Connection.open("localhost", 7557) as c:        # Hello and Welcome: c.welcome
        registered = c.request(Register("Pyro"))            # waits for the reply with this seq
        c.send(PerceptionRequest("Pyro", every=1))
        for message in c:                                   # typed messages until the server closes
            ...

asyncio::

    c = await AsyncConnection.open("localhost", 7557)
    await c.send(Register("Pyro"))
    message = await c.receive()

Both ask for the lean form of perceptions (docs/protocol.md, section 16) unless told otherwise.
An ``Error`` the server sends in answer to a request, or to the hello, is raised as
:class:`~orchard_world.errors.ServerError`; other ``Error`` lines are handed over as messages.
"""
from __future__ import annotations

import asyncio
import socket
from typing import Iterator, List, Optional, Sequence

from .errors import ConnectionClosed, OrchardError, ServerError
from .messages import (ClientMessage, Error, Hello, ServerMessage, Welcome, decode, encode, ActionResult,
                       GraspResult, Registered)

__all__ = ["Connection", "AsyncConnection", "DEFAULT_PORT"]

DEFAULT_PORT = 7557
MAX_LINE = 8 * 1024 * 1024
_REPLIES = (Welcome, Error, Registered, ActionResult, GraspResult)


def _hello(client: str, role: str, token: Optional[str], operator_token: Optional[str],
           reads: Sequence[str]) -> Hello:
    return Hello(role=role, client=client, token=token, operator_token=operator_token, reads=tuple(reads))


def _welcomed(reply: ServerMessage, where: str) -> Welcome:
    if isinstance(reply, Error):
        raise ServerError(reply.code, f"{where} refused the hello: {reply.text}", reply.seq)
    if not isinstance(reply, Welcome):
        raise OrchardError(f"{where} answered the hello with {type(reply).__name__}, expected Welcome")
    return reply


class Connection:
    """A blocking connection: one socket, lines of JSON each way, a seq counter from 1."""

    def __init__(self, sock: socket.socket, where: str) -> None:
        self._sock = sock
        self._lines = sock.makefile("rb")
        self._where = where
        self._seq = 0
        self._pending: List[ServerMessage] = []
        self.welcome: Optional[Welcome] = None

    @classmethod
    def open(cls, host: str = "localhost", port: int = DEFAULT_PORT, *, client: str = "orchard_world",
             role: str = "agent", token: Optional[str] = None, operator_token: Optional[str] = None,
             reads: Sequence[str] = ("LeanPerception",), timeout: float = 10.0,
             read_timeout: Optional[float] = None) -> "Connection":
        """Connects and shakes hands; ``welcome`` then holds the server's Welcome.

        ``read_timeout`` (seconds, None for none) bounds the wait for each line afterwards: an
        OrchardError says so when it passes.
        """
        if not isinstance(port, int) or not 0 < port < 65536:
            raise ValueError(f"port must be a whole number from 1 to 65535, was {port!r}")
        where = f"{host}:{port}"
        try:
            sock = socket.create_connection((host, port), timeout=timeout)
        except ConnectionRefusedError:
            raise OrchardError(f"no server is listening at {where}; start one first, for example with "
                               "./orchard server") from None
        except OSError as e:
            raise OrchardError(f"cannot connect to {where}: {e.strerror or e}") from None
        sock.settimeout(read_timeout)
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        connection = cls(sock, where)
        try:
            seq = connection.send(_hello(client, role, token, operator_token, reads))
            connection.welcome = _welcomed(connection._reply(seq), where)
        except BaseException:
            connection.close()
            raise
        return connection

    @property
    def where(self) -> str:
        return self._where

    def send(self, message: ClientMessage) -> int:
        """Sends one message with the next seq, which it returns."""
        self._seq += 1
        self._write(encode(message, self._seq))
        return self._seq

    def send_all(self, messages: Sequence[ClientMessage]) -> List[int]:
        """Sends several messages in one write, each with the next seq; their seqs."""
        lines = []
        seqs = []
        for message in messages:
            self._seq += 1
            lines.append(encode(message, self._seq))
            seqs.append(self._seq)
        self._write(b"".join(lines))
        return seqs

    def _write(self, data: bytes) -> None:
        try:
            self._sock.sendall(data)
        except OSError as e:
            raise ConnectionClosed(f"{self._where} closed the connection: {e.strerror or e}") from None

    def receive(self) -> Optional[ServerMessage]:
        """The next message, or None when the server has closed the connection."""
        if self._pending:
            return self._pending.pop(0)
        return self._read()

    def _read(self) -> Optional[ServerMessage]:
        try:
            line = self._lines.readline(MAX_LINE + 2)
        except socket.timeout:
            raise OrchardError(f"{self._where} sent nothing for {self._sock.gettimeout()} s") from None
        except OSError:
            return None
        return decode(line) if line else None

    def request(self, message: ClientMessage) -> ServerMessage:
        """Sends ``message`` and returns its reply; an Error reply is raised as ServerError.

        Lines that come before the reply are kept, in order, for :meth:`receive`.
        """
        return self.reply(self.send(message))

    def reply(self, seq: int) -> ServerMessage:
        """Waits for the reply to the message sent with ``seq``, as :meth:`request` does."""
        return self._reply(seq)

    def _reply(self, seq: int) -> ServerMessage:
        while True:
            m = self._read()
            if m is None:
                raise ConnectionClosed(f"{self._where} closed the connection before answering message {seq}")
            if isinstance(m, _REPLIES) and m.seq == seq:
                if isinstance(m, Error):
                    raise ServerError(m.code, m.text, m.seq)
                return m
            self._pending.append(m)

    def __iter__(self) -> Iterator[ServerMessage]:
        while True:
            m = self.receive()
            if m is None:
                return
            yield m

    def close(self) -> None:
        try:
            self._lines.close()
            self._sock.close()
        except OSError:
            pass

    def __enter__(self) -> "Connection":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


class AsyncConnection:
    """The same connection for asyncio: ``await open(...)``, ``await send(...)``, ``await receive()``."""

    def __init__(self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter, where: str) -> None:
        self._reader = reader
        self._writer = writer
        self._where = where
        self._seq = 0
        self._pending: List[ServerMessage] = []
        self.welcome: Optional[Welcome] = None

    @classmethod
    async def open(cls, host: str = "localhost", port: int = DEFAULT_PORT, *, client: str = "orchard_world",
                   role: str = "agent", token: Optional[str] = None, operator_token: Optional[str] = None,
                   reads: Sequence[str] = ("LeanPerception",)) -> "AsyncConnection":
        """Connects and shakes hands; ``welcome`` then holds the server's Welcome."""
        if not isinstance(port, int) or not 0 < port < 65536:
            raise ValueError(f"port must be a whole number from 1 to 65535, was {port!r}")
        where = f"{host}:{port}"
        try:
            reader, writer = await asyncio.open_connection(host, port, limit=MAX_LINE + 2)
        except ConnectionRefusedError:
            raise OrchardError(f"no server is listening at {where}; start one first, for example with "
                               "./orchard server") from None
        except OSError as e:
            raise OrchardError(f"cannot connect to {where}: {e.strerror or e}") from None
        connection = cls(reader, writer, where)
        try:
            seq = await connection.send(_hello(client, role, token, operator_token, reads))
            connection.welcome = _welcomed(await connection._reply(seq), where)
        except BaseException:
            await connection.close()
            raise
        return connection

    async def send(self, message: ClientMessage) -> int:
        """Sends one message with the next seq, which it returns."""
        self._seq += 1
        self._writer.write(encode(message, self._seq))
        try:
            await self._writer.drain()
        except OSError as e:
            raise ConnectionClosed(f"{self._where} closed the connection: {e.strerror or e}") from None
        return self._seq

    async def receive(self) -> Optional[ServerMessage]:
        """The next message, or None when the server has closed the connection."""
        if self._pending:
            return self._pending.pop(0)
        return await self._read()

    async def _read(self) -> Optional[ServerMessage]:
        try:
            line = await self._reader.readline()
        except (OSError, asyncio.IncompleteReadError):
            return None
        return decode(line) if line else None

    async def request(self, message: ClientMessage) -> ServerMessage:
        """Sends ``message`` and returns its reply; an Error reply is raised as ServerError."""
        return await self._reply(await self.send(message))

    async def _reply(self, seq: int) -> ServerMessage:
        while True:
            m = await self._read()
            if m is None:
                raise ConnectionClosed(f"{self._where} closed the connection before answering message {seq}")
            if isinstance(m, _REPLIES) and m.seq == seq:
                if isinstance(m, Error):
                    raise ServerError(m.code, m.text, m.seq)
                return m
            self._pending.append(m)

    def __aiter__(self) -> "AsyncConnection":
        return self

    async def __anext__(self) -> ServerMessage:
        m = await self.receive()
        if m is None:
            raise StopAsyncIteration
        return m

    async def close(self) -> None:
        self._writer.close()
        try:
            await self._writer.wait_closed()
        except OSError:
            pass
