"""The nodes of an X3D (XML encoding) or VRML97 file, read leniently and offline.

A type it does not know is read like any other, prototypes are skipped (their instances are nodes of
an unknown type), and nothing outside the bytes is read: no DTD, no entity, no URL. The rules are
those of the Java ``SceneReader`` (io.orchard.agents.model), so that both list the same names.
"""
from __future__ import annotations

import re
import unicodedata
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence
from xml.parsers import expat

from ._numbers import java_double, java_trim

MAX_DEPTH = 256
_X3D_SKIPPED = frozenset({"ProtoDeclare", "ExternProtoDeclare", "ROUTE", "IS", "fieldValue", "field", "connect"})


class SceneError(Exception):
    """The file is not a scene of its format; the message says why."""


class Node:
    """A node: its type, its DEF name, its fields as text and its child nodes by field."""

    __slots__ = ("type", "defined", "fields", "children")

    def __init__(self, type_: str, defined: Optional[str]) -> None:
        self.type = type_
        self.defined = defined
        self.fields: Dict[str, str] = {}
        self.children: Dict[str, List["Node"]] = {}

    def add(self, name: str, child: "Node") -> None:
        self.children.setdefault(name, []).append(child)

    def numbers(self, name: str, *defaults: float) -> Sequence[float]:
        """The numbers of a field, or ``defaults`` when it is not set or does not read as numbers."""
        text = self.fields.get(name)
        if text is None:
            return defaults
        parts = re.split(r"[ \t\n\x0b\f\r]+", java_trim(text.replace(",", " ")))
        values = []
        for part in parts:
            value = java_double(part)
            if value is None:
                return defaults
            values.append(value)
        return values


@dataclass
class Scene:
    """A file's top-level nodes, its length unit if it declares one, and what was skipped."""
    roots: List[Node]
    unit_name: str = "metre"
    metres_per_unit: float = 1.0
    unit_declared: bool = False
    notes: List[str] = field(default_factory=list)


def _local(name: str) -> str:
    return name.rpartition(" ")[2]


def x3d(data: bytes) -> Scene:
    """The nodes under an X3D document's ``Scene``, and its ``<unit category='length'>``."""
    parser = expat.ParserCreate(namespace_separator=" ")
    parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)
    roots: List[Node] = []
    defs: Dict[str, Node] = {}
    open_: List[Node] = []
    scene = Scene(roots)
    state = {"skipping": 0, "protos": 0, "in_scene": False}

    def refuse_entity(name: str, *_: object) -> None:
        raise SceneError(f"X3D is not well-formed XML: it declares the entity {name!r}; entities are not read")

    def refuse_external(*_: object) -> int:
        raise SceneError("X3D is not well-formed XML: it refers to an external entity, which is not read")

    def start(name: str, attributes: Dict[str, str]) -> None:
        local = _local(name)
        if state["skipping"] > 0 or local in _X3D_SKIPPED:
            state["skipping"] += 1
            state["protos"] += 1 if local in ("ProtoDeclare", "ExternProtoDeclare") else 0
        elif local == "unit" and attributes.get("category") == "length":
            scene.unit_declared = True
            scene.unit_name = attributes.get("name", "null")  # as the Java reader writes a missing name
            factor = attributes.get("conversionFactor")
            parsed = None if factor is None else java_double(java_trim(factor))
            scene.metres_per_unit = 1.0 if parsed is None else parsed
        elif local == "Scene":
            state["in_scene"] = True
        elif state["in_scene"]:
            if len(open_) >= MAX_DEPTH:
                raise SceneError(f"X3D nests deeper than {MAX_DEPTH} elements")
            node = _x3d_node(local, attributes, defs)
            if open_:
                open_[-1].add("children", node)
            else:
                roots.append(node)
            open_.append(node)

    def end(name: str) -> None:
        if state["skipping"] > 0:
            state["skipping"] -= 1
        elif _local(name) == "Scene":
            state["in_scene"] = False
        elif state["in_scene"] and open_:
            open_.pop()

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.EntityDeclHandler = refuse_entity
    parser.UnparsedEntityDeclHandler = refuse_entity
    parser.ExternalEntityRefHandler = refuse_external
    try:
        parser.Parse(data, True)
    except expat.ExpatError as e:
        raise SceneError(f"X3D is not well-formed XML: {e}") from None
    if state["protos"]:
        scene.notes.append(f"{state['protos']} prototype declaration(s) skipped: the nodes of their instances are not "
                           "listed or measured here (viewers expand X3D prototypes)")
    return scene


def _x3d_node(local: str, attributes: Dict[str, str], defs: Dict[str, Node]) -> Node:
    use = attributes.get("USE")
    if use is not None and use in defs:
        # The same node again: measured again where it is used, never listed twice.
        used = defs[use]
        node = Node(used.type, None)
        node.fields.update(used.fields)
        node.children.update(used.children)
        return node
    node = Node(local, attributes.get("DEF"))
    for name, value in attributes.items():
        node.fields[_local(name)] = value
    if node.defined is not None:
        defs[node.defined] = node
    return node


def vrml(data: bytes) -> Scene:
    """The nodes of a VRML97 file (``#VRML V2.0 utf8``); its units are metres."""
    text = data.decode("utf-8", "replace")
    if not text.startswith("#VRML V2.0"):
        raise SceneError("not a VRML97 file: it does not start with '#VRML V2.0 utf8'")
    tokens = _Tokens(text)
    roots: List[Node] = []
    defs: Dict[str, Optional[Node]] = {}
    protos = 0
    while tokens.peek() is not None:
        token = tokens.peek()
        if token in ("PROTO", "EXTERNPROTO"):
            protos += 1
            tokens.skip_proto()
        elif token == "ROUTE":
            tokens.skip(4)
        else:
            node = _vrml_node(tokens, defs, 0)
            if node is not None:
                roots.append(node)
    notes = [f"{protos} PROTO declaration(s) skipped: the nodes of their instances are not listed or measured here"
             ] if protos else []
    return Scene(roots, notes=notes)


def _vrml_node(tokens: "_Tokens", defs: Dict[str, Optional[Node]], depth: int) -> Optional[Node]:
    if depth > MAX_DEPTH:
        raise SceneError(f"VRML97 nests deeper than {MAX_DEPTH} nodes")
    token = tokens.next()
    if token == "USE":
        return defs.get(tokens.next())
    defined = None
    if token == "DEF":
        defined = tokens.next()
        token = tokens.next()
    if tokens.peek() != "{":
        return None  # not a node: a stray word or value, skipped
    tokens.next()
    node = Node(token, defined)
    while tokens.peek() is not None and tokens.peek() != "}":
        name = tokens.next()
        if name == "ROUTE":
            tokens.skip(3)
            continue
        if name in ("PROTO", "EXTERNPROTO"):
            tokens.skip_proto()
            continue
        _vrml_value(tokens, node, name, defs, depth)
    tokens.next()
    if defined is not None:
        defs[defined] = node
    return node


def _vrml_value(tokens: "_Tokens", node: Node, name: str, defs: Dict[str, Optional[Node]], depth: int) -> None:
    following = tokens.peek()
    if following is None:
        return
    if following == "[":
        tokens.next()
        values = []
        while tokens.peek() is not None and tokens.peek() != "]":
            if _starts_node(tokens):
                child = _vrml_node(tokens, defs, depth + 1)
                if child is not None:
                    node.add(name, child)
            else:
                values.append(tokens.next())
        tokens.next()
        node.fields[name] = java_trim(" ".join(values))
    elif _starts_node(tokens):
        child = _vrml_node(tokens, defs, depth + 1)
        if child is not None:
            node.add(name, child)
    else:
        values = []
        while tokens.peek() is not None and _is_value(tokens.peek()):  # type: ignore[arg-type]
            values.append(tokens.next())
        node.fields[name] = java_trim(" ".join(values))


def _starts_node(tokens: "_Tokens") -> bool:
    following = tokens.peek()
    assert following is not None
    return (following in ("DEF", "USE")
            or _java_letter(following[0]) and not _is_value(following) and tokens.peek_second() == "{")


def _java_letter(c: str) -> bool:
    return unicodedata.category(c) in ("Lu", "Ll", "Lt", "Lm", "Lo")


def _is_value(token: str) -> bool:
    c = token[0]
    return unicodedata.category(c) == "Nd" or c in "-+.\"" or token in ("TRUE", "FALSE", "NULL")


def _java_whitespace(c: str) -> bool:
    """Java's Character.isWhitespace."""
    if c in "\t\n\x0b\x0c\r\x1c\x1d\x1e\x1f":
        return True
    return unicodedata.category(c) in ("Zs", "Zl", "Zp") and c not in "\u00a0\u2007\u202f"


class _Tokens:
    """VRML97's tokens: braces and brackets, strings, and words; commas and comments are white space."""

    def __init__(self, text: str) -> None:
        self.tokens: List[str] = []
        self.at = 0
        i = text.find("\n") + 1
        length = len(text)
        while 0 < i < length:
            c = text[i]
            if c == "," or _java_whitespace(c):
                i += 1
            elif c == "#":
                while i < length and text[i] != "\n":
                    i += 1
            elif c in "{}[]":
                self.tokens.append(c)
                i += 1
            elif c == '"':
                end = i + 1
                while end < length and text[end] != '"':
                    end += 2 if text[end] == "\\" else 1
                self.tokens.append(text[i:min(end + 1, length)])
                i = end + 1
            else:
                end = i
                while end < length and not _java_whitespace(text[end]) and text[end] not in '{}[],#"':
                    end += 1
                self.tokens.append(text[i:end])
                i = end

    def peek(self) -> Optional[str]:
        return self.tokens[self.at] if self.at < len(self.tokens) else None

    def peek_second(self) -> Optional[str]:
        return self.tokens[self.at + 1] if self.at + 1 < len(self.tokens) else None

    def next(self) -> str:
        if self.at >= len(self.tokens):
            raise SceneError("VRML97 ends in the middle of a node")
        self.at += 1
        return self.tokens[self.at - 1]

    def skip(self, count: int) -> None:
        self.at = min(len(self.tokens), self.at + count)

    def skip_proto(self) -> None:
        """Skips PROTO name [ interface ] { body }, or EXTERNPROTO name [ interface ] url."""
        extern = self.next() == "EXTERNPROTO"
        self.next()
        self._balanced()
        if extern:
            if self.peek() == "[":
                self._balanced()
            else:
                self.next()
        else:
            self._balanced()

    def _balanced(self) -> None:
        depth = 0
        while True:
            token = self.next()
            if token in ("[", "{"):
                depth += 1
            elif token in ("]", "}"):
                depth -= 1
            if depth <= 0:
                return
