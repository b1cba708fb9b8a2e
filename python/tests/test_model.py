"""model_info: the names, size and units of model files, read offline, and the zip rules of the server.

PythonPackageTest (the Maven build) also runs this reader and the Java one on every model of the
repository and compares their JSON and text; these tests check values worked out by hand.
"""
import io
import json
import math
import os
import stat
import zipfile
import zlib

import pytest

import orchard_world
from orchard_world.model import ModelError, of

MODELS = os.path.join(os.path.dirname(__file__), "models")


def models(name):
    return os.path.join(MODELS, name)


def test_a_binary_gltfs_nodes_clips_and_box_as_its_nodes_place_the_mesh():
    info = orchard_world.model_info(models("Lantern.glb"))

    assert (info.format, info.roots, info.joints, info.clips) == (
        "glb", ["Lantern", "node#1", "Flame"], ["Lantern", "node#1", "Flame"], ["Glow", "clip#1"])
    # The mesh twice as large under the lantern, 0.5 up; the flame turned a quarter, 0.8 up.
    assert info.min == pytest.approx((-0.2, 0.5, -0.2)) and info.max == pytest.approx((0.2, 1.1, 0.2))
    assert info.units == orchard_world.model.Units("metre", 1.0, True) and info.notes == []


def test_the_scene_named_by_scene_gives_the_roots_and_a_tall_model_is_noted_rounded_half_up():
    info = orchard_world.model_info(models("Giant.gltf"))

    assert info.roots == ["Giant", "node#2"] and info.clips == ["Stomp", "clip#1", "clip#2"]
    assert info.size[1] == 25.25
    assert info.notes == ["25.3 m tall: perhaps authored in centimetres; viewers fit a model to its agent's body unless "
                          "it asks to be shown as authored"]


def test_an_x3d_with_a_doctype_units_use_hanim_and_a_prototype():
    info = orchard_world.model_info(models("Scarecrow.x3d"))

    assert info.joints == ["Scarecrow", "Pole", "CrossBar", "Hat", "Neck", "Head", "Shadow"]
    assert info.clips == ["ScarecrowTSSway"] and info.roots == []  # the Group at the top is no joint
    assert info.units == orchard_world.model.Units("inch", 0.0254, True)
    # The head (radius 4.5 at 64 high) is measured twice, at x 0 and, used in the shadow, at x 10.
    assert info.max[0] == pytest.approx(18.0) and info.max[1] == pytest.approx(68.5)
    assert info.notes[0].startswith("1 prototype declaration(s) skipped")


def test_a_vrml_file_with_strings_comments_prototypes_and_routes():
    info = orchard_world.model_info(models("Kite.wrl"))

    assert info.roots == ["Kite", "String"] and info.joints == ["Kite", "KiteSail", "KiteTail", "String"]
    assert info.clips == ["KiteTSFlutter"] and not info.units.declared
    assert info.notes == ["2 PROTO declaration(s) skipped: the nodes of their instances are not listed or measured "
                          "here"]
    # The sail's top (0.6 up in it) turned 45 degrees about x, 2.5 up; the string from the ground.
    assert info.min[1] == pytest.approx(0.0) and info.max[1] == pytest.approx(2.5 + 0.6 * math.sqrt(0.5))


def test_the_json_has_the_fields_of_orchard_model_info_json():
    line = orchard_world.model_info(models("Lantern.glb")).to_json()

    assert list(json.loads(line)) == ["file", "format", "inside", "roots", "joints", "clips", "bounds", "units", "notes"]
    assert json.loads(line)["bounds"]["size"] == pytest.approx([0.4, 0.6, 0.4])


def test_an_x3d_reads_no_dtd_and_no_entity(tmp_path):
    # Were the DTD read, its default DEF would make every Transform a joint named FromDtd.
    (tmp_path / "defaults.dtd").write_text("<!ATTLIST Transform DEF CDATA 'FromDtd'>")
    (tmp_path / "Plain.x3d").write_text("<!DOCTYPE X3D SYSTEM 'defaults.dtd'><X3D><Scene><Transform/></Scene></X3D>")
    assert orchard_world.model_info(tmp_path / "Plain.x3d").joints == []

    (tmp_path / "Laughs.x3d").write_text("<!DOCTYPE X3D [<!ENTITY a 'aaaaaaaa'><!ENTITY b '&a;&a;&a;&a;'>]>"
                                         "<X3D><Scene><Transform DEF='&b;'/></Scene></X3D>")
    with pytest.raises(ModelError, match=r"^Laughs.x3d: X3D is not well-formed XML: it declares the entity 'a'"):
        orchard_world.model_info(tmp_path / "Laughs.x3d")


def packed(entries, method=zipfile.ZIP_DEFLATED, link=None):
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", method) as z:
        for name, data in entries.items():
            info = zipfile.ZipInfo(name)
            info.compress_type = method
            if name == link:
                info.create_system = 3
                info.external_attr = (stat.S_IFLNK | 0o777) << 16
            z.writestr(info, data)
    return out.getvalue()


def glb():
    with open(models("Lantern.glb"), "rb") as f:
        return f.read()


def test_a_zip_is_read_through_its_one_model_file_at_the_shallowest_level():
    info = of("lantern.zip", "zip", packed({"lantern/Lantern.glb": glb(), "lantern/parts/Wick.gltf": b"{}",
                                            "lantern/readme.txt": b"hi"}))

    assert (info.file, info.format, info.inside, info.joints[0]) == ("lantern.zip", "glb", "lantern/Lantern.glb",
                                                                      "Lantern")


def test_a_zip_written_to_a_stream_with_data_descriptors_is_read():
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
        with z.open("Lantern.glb", "w", force_zip64=False) as entry:
            entry.write(glb())
    unseekable = io.BytesIO()

    class Stream(io.RawIOBase):
        def writable(self):
            return True

        def write(self, b):
            return unseekable.write(b)

    with zipfile.ZipFile(Stream(), "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("Lantern.glb", glb())
    assert of("a.zip", "zip", out.getvalue()).inside == "Lantern.glb"
    assert of("b.zip", "zip", unseekable.getvalue()).inside == "Lantern.glb"


@pytest.mark.parametrize("entries, why", [
    ({"../Lantern.glb": b"x"}, r"the zip's entry '../Lantern.glb' has a '..' segment, which would leave the archive"),
    ({"/Lantern.glb": b"x"}, r"the zip's entry '/Lantern.glb' is an absolute path"),
    ({"C:/Lantern.glb": b"x"}, r"the zip's entry 'C:/Lantern.glb' is an absolute path"),
    ({"a\\Lantern.glb": b"x"}, r"has a backslash"),
    ({"a/./Lantern.glb": b"x"}, r"has an empty or '.' segment"),
    ({"a\x01.glb": b"x"}, r"has a control character"),
    ({"readme.txt": b"x"}, r"the zip holds no model file \(one of .gltf, .glb, .x3d, .wrl\) among \[readme.txt\]"),
    ({"a.glb": b"x", "b.wrl": b"y"}, r"the zip holds 2 model files side by side, \[a.glb, b.wrl\]"),
    ({"Big.gltf": bytes(5 << 20)}, r"the zip's files unpack to more than 4194304 bytes \(at entry 'Big.gltf'\)"),
    ({"Bomb.gltf": bytes(1 << 20)}, r"unpack to more than 100 times its \d+ bytes \(at entry 'Bomb.gltf'\): refused as"),
])
def test_a_zip_that_breaks_a_rule_is_refused_naming_the_entry_and_the_rule(entries, why):
    with pytest.raises(ModelError, match=r"^model.zip: .*" + why):
        of("model.zip", "zip", packed(entries))


def test_a_symbolic_link_an_encrypted_entry_and_another_listing_in_the_central_directory_are_refused():
    with pytest.raises(ModelError, match="the zip's entry 'Lantern.glb' is a symbolic link"):
        of("link.zip", "zip", packed({"Lantern.glb": b"/etc/passwd"}, link="Lantern.glb"))
    encrypted = bytearray(packed({"Lantern.glb": glb()}))
    encrypted[6] |= 1  # the local header's flag: encrypted
    with pytest.raises(ModelError, match="encrypted ZIP entry not supported"):
        of("secret.zip", "zip", bytes(encrypted))
    smuggled = packed({"Lantern.glb": glb(), "Other.txt": b"x"})
    central = smuggled.rindex(b"Other.txt")  # the central directory's copy of the name, not the local header's
    with pytest.raises(ModelError, match="central directory lists 2 entries that differ from the 2 entries it holds"):
        of("smuggled.zip", "zip", smuggled[:central] + b"Ather.txt" + smuggled[central + 9:])


def test_a_file_of_another_kind_or_broken_is_refused_naming_it(tmp_path):
    with pytest.raises(ModelError, match=r"^cat.obj: expected a model file, .gltf, .glb, .x3d, .wrl or .zip$"):
        orchard_world.model_info(tmp_path / "cat.obj")
    with pytest.raises(FileNotFoundError):
        orchard_world.model_info(tmp_path / "missing.gltf")
    for name, data, why in [("a.gltf", b"[1]", "glTF JSON is not an object"),
                            ("b.gltf", b'{"a": 1, "a": 2}', "Duplicate Object property"),
                            ("c.glb", b"glTF" + bytes(20), "not a binary glTF"),
                            ("d.x3d", b"<X3D><Scene>", "X3D is not well-formed XML"),
                            ("e.wrl", b"#VRML V1.0 ascii\n", "not a VRML97 file"),
                            ("f.wrl", b"#VRML V2.0 utf8\nTransform { children [", "VRML97 ends in the middle of a node"),
                            ("g.zip", zlib.compress(b"no zip"), "the zip does not start with a zip entry's header")]:
        (tmp_path / name).write_bytes(data)
        with pytest.raises(ModelError, match=f"^{name}: .*{why}"):
            orchard_world.model_info(tmp_path / name)
