"""What a model file holds, read offline in pure Python: the names an agent registers, its size, its units.

The same reading as the Java ``ModelInfo`` (io.orchard.agents.model) and ``./orchard model-info``,
field for field (docs/agents.md): glTF (``.gltf``, ``.glb``): every node is a joint, by its name or
``node#i`` by its index when it has none; every animation a clip (``clip#i``); the box is that of the
meshes' positions as the nodes place them, in metres. X3D and VRML97: every DEF'd ``Transform``
(and HAnim joint) is a joint, every DEF'd ``TimeSensor`` a clip; the box is that of the ``Box``,
``Sphere``, ``Cylinder``, ``Cone`` and ``Coordinate`` points as the Transforms place them, in the
file's units. A ``.zip`` (the protocol's ``"format":"zip"``) is read through its model file, with
the server's safety rules. Nothing is fetched: no DTD, no entity, no URL.

>>> from orchard_world import model_info
>>> info = model_info("agents/src/main/resources/io/orchard/agents/zoo/models/Dwarf.x3d")  # in a clone
>>> info.roots, info.clips, info.units.name
(['Dwarf'], ['DwarfTSMover', 'DwarfTSWalk', 'DwarfTSGrasp'], 'metre')
"""
from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass, field, replace
from typing import Any, Dict, List, Optional, Sequence, Set, Tuple, Union

from ..errors import OrchardError
from . import _archive, _scene
from ._extent import IDENTITY, Extent, axis_angle, multiply, trs
from ._numbers import java_f, java_g, java_string

__all__ = ["ModelInfo", "Units", "ModelError", "read", "of", "format_of", "FORMATS"]

# The largest file read, and a model sent to a server at most.
READ_AT_MOST = 64 * 1024 * 1024
MAX_MODEL_BYTES = _archive.MAX_MODEL_BYTES
# Taller than this, in metres, a model is likely authored in centimetres.
HOUSE = 20
FORMATS = ("gltf", "glb", "x3d", "vrml97", "zip")
_JOINT_TYPES = frozenset({"Transform", "HAnimJoint", "HAnimSegment", "HAnimHumanoid"})

Vec3 = Tuple[float, float, float]


class ModelError(OrchardError, ValueError):
    """A file that is not a model of its format, or breaks a rule; the message names the file."""


@dataclass(frozen=True)
class Units:
    """A model's length unit: its name, metres in one unit, and whether the file says so (glTF does)."""
    name: str
    metres: float
    declared: bool


@dataclass(frozen=True)
class ModelInfo:
    """What a model file holds (docs/agents.md names every field)."""
    file: str
    format: str
    inside: Optional[str]
    roots: List[str]
    joints: List[str]
    clips: List[str]
    min: Optional[Vec3]
    max: Optional[Vec3]
    units: Units
    notes: List[str] = field(default_factory=list)

    @property
    def size(self) -> Optional[Vec3]:
        """The bounding box's size in the file's units; None when nothing was measured."""
        if self.min is None or self.max is None:
            return None
        return (self.max[0] - self.min[0], self.max[1] - self.min[1], self.max[2] - self.min[2])

    def to_dict(self) -> Dict[str, Any]:
        """The JSON object of ``./orchard model-info --json``, as a dict."""
        size = self.size
        bounds = None if size is None or self.min is None or self.max is None else {
            "min": list(self.min), "max": list(self.max), "size": list(size)}
        return {"file": self.file, "format": self.format, "inside": self.inside, "roots": list(self.roots),
                "joints": list(self.joints), "clips": list(self.clips), "bounds": bounds,
                "units": {"name": self.units.name, "metres": float(self.units.metres),
                          "declared": self.units.declared},
                "notes": list(self.notes)}

    def to_json(self) -> str:
        """One line of JSON, the fields of ``./orchard model-info --json``."""
        return json.dumps(self.to_dict(), separators=(",", ":"), ensure_ascii=False, allow_nan=False)

    def to_text(self) -> str:
        """The model as text for a person, one thing a line, as ``./orchard model-info`` prints it."""
        lines = [f"{self.file}: {self.format}" + (f" ({self.inside} in the zip)" if self.inside is not None else ""),
                 f"roots: {', '.join(self.roots)}",
                 f"joints ({len(self.joints)}): {', '.join(self.joints)}",
                 f"clips ({len(self.clips)}): {', '.join(self.clips)}"]
        size = self.size
        if size is not None and self.min is not None and self.max is not None:
            unit = self.units.name if self.units.name.endswith("s") else self.units.name + "s"
            lines.append(f"size: {' x '.join(java_g(v, 4) for v in size)} {unit} (x, y up, z); from "
                         f"({', '.join(java_g(v, 4) for v in self.min)}) to "
                         f"({', '.join(java_g(v, 4) for v in self.max)})")
        lines.append(f"units: {self.units.name} ({java_string(float(self.units.metres))} m)"
                     + ("" if self.units.declared else ", not declared: taken as metres"))
        lines.extend(f"note: {note}" for note in self.notes)
        return "\n".join(lines) + "\n"


def format_of(name: str) -> str:
    """The format a file's extension stands for: .gltf, .glb, .x3d, .wrl, .zip; a ModelError names others."""
    lower = name.lower()
    dot = lower.rfind(".")
    found = None if dot < 0 else "zip" if lower.endswith(".zip") else _archive.MODEL_EXTENSIONS.get(lower[dot:])
    if found is None:
        raise ModelError(f"{name}: expected a model file, .gltf, .glb, .x3d, .wrl or .zip")
    return found


def read(path: Union[str, "os.PathLike[str]"]) -> ModelInfo:
    """Reads a model file (.gltf, .glb, .x3d, .wrl or .zip), offline.

    Raises FileNotFoundError for a missing file, and ModelError naming the file when it is larger
    than 64 MiB, not of a model's extension, or not a model of its format.
    """
    name = os.path.basename(os.fspath(path))
    kind = format_of(name)
    size = os.path.getsize(path)
    if size > READ_AT_MOST:
        raise ModelError(f"{os.fspath(path)} has {size} bytes; model-info reads at most {READ_AT_MOST} (and a model "
                         f"sent to a server has at most {MAX_MODEL_BYTES})")
    with open(path, "rb") as f:
        info = of(name, kind, f.read())
    if size <= MAX_MODEL_BYTES:
        return info
    return replace(info, notes=[*info.notes, f"{size} bytes: larger than the {MAX_MODEL_BYTES} a model sent to a "
                                             "server may have"])


def of(file: str, kind: str, data: bytes) -> ModelInfo:
    """Reads a model from its bytes: ``kind`` one of FORMATS (``"zip"`` for a zip of a model's files)."""
    try:
        if kind == "zip":
            archive = _archive.read(data)
            model = of(file, archive.model_format, archive.model_bytes)
            return replace(model, file=file, inside=archive.model_path)
        if kind == "gltf":
            return _gltf(file, kind, data.decode("utf-8", "replace"))
        if kind == "glb":
            return _gltf(file, kind, _glb_json(file, data))
        if kind == "x3d":
            return _from_scene(file, kind, _scene.x3d(data))
        if kind == "vrml97":
            return _from_scene(file, kind, _scene.vrml(data))
    except (_archive.ArchiveError, _scene.SceneError, _JsonError) as e:
        raise ModelError(f"{file}: {e}") from None
    raise ValueError(f"format must be one of {', '.join(FORMATS)}, was {kind!r}")


class _JsonError(Exception):
    pass


def _strict_pairs(pairs: List[Tuple[str, Any]]) -> Dict[str, Any]:
    out: Dict[str, Any] = {}
    for key, value in pairs:
        if key in out:
            raise _JsonError(f"Duplicate Object property \"{key}\"")
        out[key] = value
    return out


def _no_constant(name: str) -> Any:
    raise _JsonError(f"Non-standard token '{name}': not JSON")


def _gltf(file: str, kind: str, text: str) -> ModelInfo:
    try:
        root = json.loads(text, object_pairs_hook=_strict_pairs, parse_constant=_no_constant)
    except (ValueError, RecursionError) as e:
        if isinstance(e, _JsonError):
            raise
        raise _JsonError(f"glTF is not JSON: {e}") from None
    if not isinstance(root, dict):
        raise ModelError(f"{file}: glTF JSON is not an object")
    nodes = root.get("nodes")
    joints = _names(nodes, "node#")
    clips = _names(root.get("animations"), "clip#")
    scenes = root.get("scenes")
    scene = _as_int(root.get("scene"), 0)
    if isinstance(scenes, list) and scene < len(scenes):
        chosen = scenes[scene] if scene >= 0 else None
        top = [_as_int(n, 0) for n in _elements(_path(chosen, "nodes"))]
    else:
        top = list(range(len(joints)))
    extent = Extent()
    visited: Set[int] = set()
    for index in top:
        _gltf_node(root, index, IDENTITY, extent, visited)
    roots = [joints[i] for i in top if 0 <= i < len(joints)]
    return _finish(file, kind, roots, joints, clips, extent, Units("metre", 1.0, True), [])


def _names(array: Any, prefix: str) -> List[str]:
    if not isinstance(array, list):
        return []
    names = []
    for i, element in enumerate(array):
        name = element.get("name") if isinstance(element, dict) else None
        names.append(name if isinstance(name, str) and name else f"{prefix}{i}")
    return names


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _as_int(value: Any, otherwise: int) -> int:
    if _is_number(value) and math.isfinite(value):
        return int(value)
    return otherwise


def _as_double(value: Any) -> float:
    return float(value) if _is_number(value) else 0.0


def _path(value: Any, key: Union[str, int]) -> Any:
    """Jackson's path(): the member or element, or None."""
    if isinstance(key, str):
        return value.get(key) if isinstance(value, dict) else None
    return value[key] if isinstance(value, list) and 0 <= key < len(value) else None


def _elements(value: Any) -> List[Any]:
    """What Jackson iterates: an array's elements, an object's values."""
    if isinstance(value, list):
        return value
    if isinstance(value, dict):
        return list(value.values())
    return []


def _numbers(array: Any, *defaults: float) -> Sequence[float]:
    if not isinstance(array, list) or len(array) != len(defaults):
        return defaults
    return [_as_double(v) for v in array]


def _gltf_node(root: Dict[str, Any], index: int, parent: Sequence[float], extent: Extent, visited: Set[int]) -> None:
    node = _path(root.get("nodes"), index)
    if not isinstance(node, dict) or index in visited:
        return
    visited.add(index)
    matrix = node.get("matrix")
    if isinstance(matrix, list) and len(matrix) == 16:
        local: Sequence[float] = [_as_double(v) for v in matrix]
    else:
        local = trs(_numbers(node.get("translation"), 0, 0, 0), _numbers(node.get("rotation"), 0, 0, 0, 1),
                    _numbers(node.get("scale"), 1, 1, 1))
    m = multiply(parent, local)
    if "mesh" in node:
        mesh = _path(root.get("meshes"), _as_int(node.get("mesh"), 0))
        for primitive in _elements(_path(mesh, "primitives")):
            position = _as_int(_path(_path(primitive, "attributes"), "POSITION"), -1)
            accessor = _path(root.get("accessors"), position)
            if isinstance(accessor, dict) and "min" in accessor and "max" in accessor:
                extent.add_box(m, _numbers(accessor["min"], 0, 0, 0), _numbers(accessor["max"], 0, 0, 0))
    for child in _elements(node.get("children")):
        _gltf_node(root, _as_int(child, 0), m, extent, visited)


def _glb_json(file: str, data: bytes) -> str:
    if len(data) < 20 or data[0:4] != b"glTF" or data[16:20] != b"JSON":
        raise ModelError(f"{file}: not a binary glTF (no 'glTF' header and JSON chunk)")
    length = int.from_bytes(data[12:16], "little", signed=True)
    if length < 0 or 20 + length > len(data):
        raise ModelError(f"{file}: its JSON chunk runs past the end of the file")
    return data[20:20 + length].decode("utf-8", "replace")


def _from_scene(file: str, kind: str, scene: _scene.Scene) -> ModelInfo:
    roots: List[str] = []
    joints: Dict[str, None] = {}
    clips: Dict[str, None] = {}
    extent = Extent()
    for node in scene.roots:
        if node.defined is not None and node.type in _JOINT_TYPES:
            roots.append(node.defined)
        _walk(node, IDENTITY, extent, joints, clips, 0)
    return _finish(file, kind, roots, list(joints), list(clips), extent,
                   Units(scene.unit_name, scene.metres_per_unit, scene.unit_declared), scene.notes)


def _walk(node: _scene.Node, parent: Sequence[float], extent: Extent, joints: Dict[str, None],
          clips: Dict[str, None], depth: int) -> None:
    if depth > 256:
        return
    m = parent
    kind = node.type
    if kind in _JOINT_TYPES:
        if node.defined is not None:
            joints.setdefault(node.defined)
        r = node.numbers("rotation", 0, 0, 1, 0)
        m = multiply(parent, trs(node.numbers("translation", 0, 0, 0),
                                 axis_angle(r[0], r[1], r[2], r[3]) if len(r) == 4 else (0, 0, 0, 1),
                                 node.numbers("scale", 1, 1, 1)))
    elif kind == "TimeSensor":
        if node.defined is not None:
            clips.setdefault(node.defined)
    elif kind == "Box":
        s = node.numbers("size", 2, 2, 2)
        extent.add_box(m, (-s[0] / 2, -s[1] / 2, -s[2] / 2), (s[0] / 2, s[1] / 2, s[2] / 2))
    elif kind == "Sphere":
        radius = node.numbers("radius", 1)[0]
        extent.add_box(m, (-radius, -radius, -radius), (radius, radius, radius))
    elif kind in ("Cylinder", "Cone"):
        radius = node.numbers("bottomRadius" if kind == "Cone" else "radius", 1)[0]
        half = node.numbers("height", 2)[0] / 2
        extent.add_box(m, (-radius, -half, -radius), (radius, half, radius))
    elif kind == "Coordinate":
        p = node.numbers("point")
        for i in range(0, len(p) - 2, 3):
            extent.add(m, p[i], p[i + 1], p[i + 2])
    for children in node.children.values():
        for child in children:
            _walk(child, m, extent, joints, clips, depth + 1)


def _finish(file: str, kind: str, roots: List[str], joints: List[str], clips: List[str], extent: Extent,
            units: Units, notes: List[str]) -> ModelInfo:
    empty = extent.is_empty()
    low = None if empty else (extent.min[0], extent.min[1], extent.min[2])
    high = None if empty else (extent.max[0], extent.max[1], extent.max[2])
    notes = list(notes)
    if low is None or high is None:
        notes.append("nothing was measured: no mesh, shape or coordinates this reader knows")
    elif (high[1] - low[1]) * units.metres > HOUSE:
        notes.append(f"{java_f((high[1] - low[1]) * units.metres, 1)} m tall: perhaps authored in centimetres; "
                     "viewers fit a model to its agent's body unless it asks to be shown as authored")
    return ModelInfo(file, kind, None, roots, joints, clips, low, high, units, notes)
