import json
import math

import pytest

from orchard_world.errors import ProtocolError
from orchard_world.messages import (Body, EndTurn, Hello, LeanPerception, Move, Point2, Register, SetRotation, Unknown,
                                    Welcome, decode, encode)


def test_the_lean_perception_of_the_protocol_document_reads_in_units_and_radians():
    line = ('{"type":"LeanPerception","tick":43,"agent":"Guppy","position":[1250,0,-4025],"heading":250,'
            '"objects":[["T17","tree",650,-400,150,600],["D2","table",1200,800,100,90]],'
            '"agents":[["Bunny",400,1200,-300,40]],'
            '"fruit":[["F12","banana",1400,115,-3800,"D2"],["F13","tomato",1000,15,-4400,null]],'
            '"river":[1800,100,1400],"bridges":[["B1",2000,300,2800,3142,400]],"castle":"south-west"}')
    p = decode(line)
    assert isinstance(p, LeanPerception)
    assert (p.position.x, p.position.z, p.heading) == (12.5, -40.25, 0.25)
    assert p.objects[0].kind == "tree" and p.objects[0].at.bearing == -0.4 and p.objects[0].height == 6.0
    assert p.agents[0].name == "Bunny" and p.agents[0].radius == 0.4
    assert p.fruit[0].support == "D2" and p.fruit[0].radius == 0.25 and p.fruit[0].position.y == 1.15
    assert p.fruit[1].support is None
    assert p.river is not None and p.river.across == 1.4
    assert p.bridges[0].entry_b.bearing == math.pi, "3142 milliradians stands for pi itself"
    assert p.castle == "south-west"


def test_the_welcome_of_the_protocol_document_decodes_with_every_field():
    w = decode('{"type":"Welcome","seq":1,"protocolVersion":2,"serverVersion":"0.1.0","role":"agent","bounds":'
               '{"minX":-100.0,"minZ":-100.0,"maxX":100.0,"maxZ":100.0},"tickRate":20,"clock":"lockstep",'
               '"tick":0,"timeLimit":180.0,"phase":"waiting"}')
    assert isinstance(w, Welcome)
    assert (w.tick_rate, w.clock, w.time_limit, w.phase, w.bounds.max_z) == (20, "lockstep", 180.0, "waiting", 100.0)


def test_a_type_this_version_does_not_know_is_skipped_not_refused():
    m = decode('{"type":"JointRotated","tick":1,"agent":"Guppy","joint":"Knee"}')
    assert isinstance(m, Unknown) and m.type == "JointRotated"


@pytest.mark.parametrize("line, named", [
    ('{"type":"Tick","time":0.5}', "Tick.tick is missing"),
    ('not json', "not JSON"),
    ('[1,2]', "not a JSON object"),
    ('{"type":7}', "type must be a string"),
    ('{"type":"LeanPerception","tick":1,"agent":"A","position":[1],"heading":0,"objects":[],"agents":[],'
     '"fruit":[],"bridges":[],"castle":"north"}', "LeanPerception does not have the fields"),
])
def test_a_line_that_is_not_a_message_is_refused_naming_what_is_wrong(line, named):
    with pytest.raises(ProtocolError, match=named):
        decode(line)


def test_client_messages_are_one_line_of_compact_json_with_their_seq():
    line = encode(Move("Guppy", Point2(20.0, -35.0), start=Point2(12.5, -40.25)), 6)
    assert line.endswith(b"\n") and line.count(b"\n") == 1
    assert json.loads(line) == {"type": "Move", "seq": 6, "agent": "Guppy", "to": {"x": 20.0, "y": 0.0, "z": -35.0},
                                "from": {"x": 12.5, "y": 0.0, "z": -40.25}}
    assert json.loads(encode(Hello(client="t"), 1))["reads"] == ["LeanPerception"]
    assert json.loads(encode(SetRotation("A", 1.5), 2))["rotation"] == {"axis": {"x": 0.0, "y": 1.0, "z": 0.0},
                                                                        "angle": 1.5}


@pytest.mark.parametrize("message, named", [
    (Register("no spaces"), "'no spaces'"),
    (SetRotation("A", float("nan")), "nan"),
    (EndTurn(-1), "-1"),
    (Move("A", Point2(float("inf"), 0)), "inf"),
])
def test_a_bad_value_is_refused_before_it_is_sent_naming_it(message, named):
    with pytest.raises(ValueError, match=named):
        encode(message, 1)


def test_a_body_names_a_bad_dimension():
    with pytest.raises(ValueError, match=r"Body.radius must be a finite number > 0, was -1"):
        Body(radius=-1)
