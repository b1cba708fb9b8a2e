"""The files of a model sent as a zip (the protocol's ``"format":"zip"``), unpacked in memory and checked.

The rules are the Java ``ModelArchive``'s (io.orchard.protocol.value): the files may unpack to at
most 4 MiB together and to at most 100 times the zip's size past the first 64 KiB (a zip bomb is
refused), at most 256 entries, no two of one name, no absolute name, no ``..`` or ``.`` segment, no
backslash or control character, no symbolic link, no encrypted entry, and one model file at the
shallowest level that has one. The entries are read one after another from the start, as Java's
``ZipInputStream`` reads them, and must be those the central directory lists. Nothing is written
to disk.
"""
from __future__ import annotations

import re
import struct
import zlib
from typing import Dict, List, Optional, Tuple

MAX_MODEL_BYTES = 4 * 1024 * 1024
MAX_ENTRIES = 256
MAX_RATIO = 100
RATIO_FREE = 64 * 1024
MODEL_EXTENSIONS = {".gltf": "gltf", ".glb": "glb", ".x3d": "x3d", ".wrl": "vrml97"}

_LOCAL_HEADER = 0x04034B50
_CENTRAL_HEADER = 0x02014B50
_END_OF_DIRECTORY = 0x06054B50
_DATA_DESCRIPTOR = 0x08074B50
_UNIX = 3
_FILE_TYPE = 0o170000
_SYMBOLIC_LINK = 0o120000
_STORED, _DEFLATED = 0, 8


class ArchiveError(Exception):
    """The zip breaks a rule; the message names the entry and the rule."""


def quote(value: str) -> str:
    return "'" + (value[:40] + "..." if len(value) > 40 else value) + "'"


class ModelArchive:
    """A zip's files by path, and which of them is the model file."""

    def __init__(self, files: Dict[str, bytes], model: str) -> None:
        self.files = files
        self.model_path = model

    @property
    def model_format(self) -> str:
        found = format_of(self.model_path)
        assert found is not None
        return found

    @property
    def model_bytes(self) -> bytes:
        return self.files[self.model_path]


def read(zip_bytes: bytes) -> ModelArchive:
    """Unpacks and checks a zip; an ArchiveError names the entry and the rule it breaks."""
    if len(zip_bytes) < 4 or struct.unpack_from("<I", zip_bytes, 0)[0] != _LOCAL_HEADER:
        raise ArchiveError("the zip does not start with a zip entry's header (bytes 50 4B 03 04)")
    central = _central_names(zip_bytes)
    files: Dict[str, bytes] = {}
    seen: List[str] = []
    total = 0
    at = 0
    while True:
        entry = _next_entry(zip_bytes, at)
        if entry is None:
            break
        name, method, flags, sizes, data_at = entry
        if len(seen) == MAX_ENTRIES:
            raise ArchiveError(f"the zip has more than {MAX_ENTRIES} entries")
        check_name(name)
        if name in seen:
            raise ArchiveError(f"the zip has two entries named {quote(name)}")
        seen.append(name)
        data, at = _unpack(zip_bytes, name, method, flags, sizes, data_at, MAX_MODEL_BYTES - total)
        if name.endswith("/"):
            continue
        total += len(data)
        allowed = MAX_RATIO * len(zip_bytes) + RATIO_FREE
        if total > allowed:
            raise ArchiveError(f"the zip's files unpack to more than {MAX_RATIO} times its {len(zip_bytes)} bytes "
                               f"(at entry {quote(name)}): refused as a zip bomb")
        files[name] = data
    if central != seen:
        raise ArchiveError(f"the zip's central directory lists {len(central)} entries that differ from the "
                           f"{len(seen)} entries it holds")
    return ModelArchive(files, _model_file(files))


def _next_entry(z: bytes, at: int) -> Optional[Tuple[str, int, int, Tuple[int, int, int], int]]:
    """The local entry at ``at``: name, method, flags, (crc, packed size, size), where its data starts; None past the last."""
    if at + 30 > len(z) or struct.unpack_from("<I", z, at)[0] != _LOCAL_HEADER:
        return None
    _, _, flags, method, _, crc, packed, size, name_length, extra_length = struct.unpack_from("<IHHHIIIIHH", z, at)
    if at + 30 + name_length + extra_length > len(z):
        raise ArchiveError("the zip cannot be read: it ends inside an entry's header")
    raw = z[at + 30:at + 30 + name_length]
    try:
        name = raw.decode("utf-8")
    except UnicodeDecodeError:
        raise ArchiveError(f"the zip cannot be read: an entry's name is not UTF-8: {raw!r}") from None
    if flags & 1:
        raise ArchiveError("the zip cannot be read: encrypted ZIP entry not supported")
    if flags & 8 and method != _DEFLATED:
        raise ArchiveError("the zip cannot be read: only DEFLATED entries can have EXT descriptor")
    extra = z[at + 30 + name_length:at + 30 + name_length + extra_length]
    if not flags & 8 and 0xFFFFFFFF in (packed, size):
        packed, size = _zip64_sizes(extra, packed, size)
    return name, method, flags, (crc, packed, size), at + 30 + name_length + extra_length


def _zip64_sizes(extra: bytes, packed: int, size: int) -> Tuple[int, int]:
    at = 0
    while at + 4 <= len(extra):
        tag, length = struct.unpack_from("<HH", extra, at)
        if tag == 1 and length >= 16:
            size, packed = struct.unpack_from("<QQ", extra, at + 4)
            break
        at += 4 + length
    return packed, size


def _unpack(z: bytes, name: str, method: int, flags: int, sizes: Tuple[int, int, int], at: int,
            room: int) -> Tuple[bytes, int]:
    """An entry's bytes, at most ``room`` of them, and where the next entry starts."""
    crc, packed, size = sizes
    too_many = ArchiveError(f"the zip's files unpack to more than {MAX_MODEL_BYTES} bytes (at entry {quote(name)})")
    if method == _STORED:
        if at + size > len(z):
            raise ArchiveError("the zip cannot be read: unexpected end of the zip in entry " + quote(name))
        if size > room:
            raise too_many
        data, end = z[at:at + size], at + size
    elif method == _DEFLATED:
        inflater = zlib.decompressobj(-15)
        try:
            data = inflater.decompress(z[at:] if flags & 8 else z[at:at + packed], room + 1)
        except zlib.error as e:
            raise ArchiveError(f"the zip cannot be read: invalid entry compressed data ({e})") from None
        if len(data) > room:
            raise too_many
        if not inflater.eof:
            raise ArchiveError("the zip cannot be read: unexpected end of ZLIB input stream in entry " + quote(name))
        used = (len(z) - at if flags & 8 else packed) - len(inflater.unused_data)
        end = at + used
        if flags & 8:
            crc, packed, size, end = _descriptor(z, end)
        if size != len(data):
            raise ArchiveError(f"the zip cannot be read: invalid entry size (expected {size} but got {len(data)} "
                               "bytes)")
        if packed != used:
            raise ArchiveError(f"the zip cannot be read: invalid entry compressed size (expected {packed} but got "
                               f"{used} bytes)")
    else:
        raise ArchiveError(f"the zip cannot be read: invalid compression method {method} in entry {quote(name)}")
    got = zlib.crc32(data) & 0xFFFFFFFF
    if got != crc:
        raise ArchiveError(f"the zip cannot be read: invalid entry CRC (expected 0x{crc:x} but got 0x{got:x})")
    return data, end


def _descriptor(z: bytes, at: int) -> Tuple[int, int, int, int]:
    """crc, packed size, size and the end of the data descriptor at ``at`` (its signature is optional)."""
    if at + 12 > len(z):
        raise ArchiveError("the zip cannot be read: it ends inside a data descriptor")
    if struct.unpack_from("<I", z, at)[0] == _DATA_DESCRIPTOR:
        if at + 16 > len(z):
            raise ArchiveError("the zip cannot be read: it ends inside a data descriptor")
        crc, packed, size = struct.unpack_from("<III", z, at + 4)
        return crc, packed, size, at + 16
    crc, packed, size = struct.unpack_from("<III", z, at)
    return crc, packed, size, at + 12


def _central_names(z: bytes) -> List[str]:
    """The names of the entries the central directory lists, refusing symbolic links, which it marks."""
    end = -1
    for at in range(len(z) - 22, max(0, len(z) - 22 - 0xFFFF) - 1, -1):
        if struct.unpack_from("<I", z, at)[0] == _END_OF_DIRECTORY:
            end = at
            break
    if end < 0:
        raise ArchiveError("the zip has no end of central directory (truncated?)")
    count, offset = struct.unpack_from("<H", z, end + 10)[0], struct.unpack_from("<I", z, end + 16)[0]
    if count > MAX_ENTRIES:
        raise ArchiveError(f"the zip has {count} entries, at most {MAX_ENTRIES} are read")
    names = []
    at = offset
    for i in range(count):
        if at + 46 > len(z) or struct.unpack_from("<I", z, at)[0] != _CENTRAL_HEADER:
            raise ArchiveError(f"the zip's central directory is damaged at entry {i}")
        made_by = struct.unpack_from("<H", z, at + 4)[0] >> 8
        name_length, extra, comment = struct.unpack_from("<HHH", z, at + 28)
        attributes = struct.unpack_from("<I", z, at + 38)[0]
        if at + 46 + name_length > len(z):
            raise ArchiveError(f"the zip's central directory is damaged at entry {i}")
        name = z[at + 46:at + 46 + name_length].decode("utf-8", "replace")
        if made_by == _UNIX and (attributes >> 16) & _FILE_TYPE == _SYMBOLIC_LINK:
            raise ArchiveError(f"the zip's entry {quote(name)} is a symbolic link; links are refused, as they may "
                               "point outside the archive")
        names.append(name)
        at += 46 + name_length + extra + comment
    return names


def check_name(name: str) -> None:
    why = None
    if not name:
        why = "is empty"
    elif name.startswith("/") or re.fullmatch(r"[A-Za-z]:[^\n\r\u0085\u2028\u2029]*", name):
        why = "is an absolute path"
    elif "\\" in name:
        why = "has a backslash (folders are separated by '/')"
    elif any(ord(c) < 0x20 or ord(c) == 0x7F for c in name):
        why = "has a control character"
    else:
        path = name[:-1] if name.endswith("/") else name
        for segment in path.split("/"):
            if segment == "..":
                why = "has a '..' segment, which would leave the archive"
            elif segment in (".", ""):
                why = "has an empty or '.' segment"
    if why is not None:
        raise ArchiveError(f"the zip's entry {quote(name)} {why}")


def format_of(name: str) -> Optional[str]:
    """The model format of a path in the archive, by its extension; None for another file."""
    dot = name.rfind(".")
    if dot < 0 or name.rfind("/") > dot:
        return None
    return MODEL_EXTENSIONS.get(name[dot:].lower())


def _model_file(files: Dict[str, bytes]) -> str:
    shallowest = None
    models: List[str] = []
    for name in files:
        if format_of(name) is None:
            continue
        depth = len(name.split("/"))
        if shallowest is None or depth < shallowest:
            shallowest, models = depth, []
        if depth == shallowest:
            models.append(name)
    listed = "[" + ", ".join(files) + "]"
    if not models:
        raise ArchiveError(f"the zip holds no model file (one of .gltf, .glb, .x3d, .wrl) among {listed}")
    if len(models) > 1:
        raise ArchiveError(f"the zip holds {len(models)} model files side by side, [{', '.join(models)}]; it must "
                           "hold one, with the files it refers to (an X3D Inline's file in a folder below it)")
    return models[0]
