"""The exceptions of orchard_world: each names the bad value and what was expected."""
from __future__ import annotations

__all__ = ["OrchardError", "ServerError", "ProtocolError", "ConnectionClosed", "ServerStartError"]


class OrchardError(Exception):
    """Anything that went wrong between this program and an Orchard server."""


class ServerError(OrchardError):
    """The server answered with an ``Error`` line (docs/protocol.md, section 13).

    ``code`` is the stable error code (``name_in_use``, ``version_mismatch``...), ``text`` the
    server's words, which name the bad field and value, and ``seq`` the ``seq`` of the message it
    answers (0 for none).
    """

    def __init__(self, code: str, text: str, seq: int = 0) -> None:
        super().__init__(f"{code}: {text}")
        self.code = code
        self.text = text
        self.seq = seq


class ProtocolError(OrchardError, ValueError):
    """A line from the server that is not a message of the protocol as documented."""


class ConnectionClosed(OrchardError):
    """The server closed the connection (or it was lost) while an answer was awaited."""


class ServerStartError(OrchardError):
    """A server this package was asked to start did not come up."""
