"""The observation and the forward step, from perceptions made here: what a learner sees first, how far it walks."""
import math

import pytest

from orchard_world.env import OBSERVATION_FIELDS
from orchard_world.env._observe import free_ahead, observe
from orchard_world.messages import (Body, Bounds, LeanPerception, PerceivedFruit, PerceivedObject, RelativePosition,
                                    Vec3)

BOUNDS = Bounds(-100.0, -100.0, 100.0, 100.0)
AT = OBSERVATION_FIELDS.index


def seeing(objects=(), fruit=()):
    """An agent at the origin facing north (-z), perceiving these."""
    return LeanPerception(tick=1, agent="Forager", position=Vec3(0.0, 0.0, 0.0), heading=0.0, objects=list(objects),
                          agents=[], fruit=list(fruit), bridges=[], castle="north")


def test_fruit_the_gripper_reaches_in_height_come_first_then_the_nearest():
    fruit = [PerceivedFruit("F1", "coconut", Vec3(0.0, 2.5, -2.0), 0.2, "T1"),     # in a tree: out of reach
             PerceivedFruit("F2", "tomato", Vec3(0.0, 0.15, -8.0), 0.15),          # on the ground
             PerceivedFruit("F3", "banana", Vec3(4.0, 1.1, 0.0), 0.25, "D1")]      # on a table, to the right
    o = observe(seeing(fruit=fruit), Body(), BOUNDS, 1.0)

    assert o[AT("fruit0.banana")] == 1 and o[AT("fruit0.sin_bearing")] == pytest.approx(-1.0)
    assert o[AT("fruit1.tomato")] == 1 and o[AT("fruit1.distance")] == pytest.approx(8 / 40)
    assert o[AT("fruit2.coconut")] == 1 and o[AT("fruit2.height")] == pytest.approx(2.5 / 4)
    tall = Body(gripper=Body().gripper.__class__(max_height=3.0))
    assert observe(seeing(fruit=fruit), tall, BOUNDS, 1.0)[AT("fruit0.coconut")] == 1, "a taller reach: nearest first"


def table(distance, bearing, radius=1.0):
    return PerceivedObject("D1", "table", RelativePosition(distance, bearing), radius, 0.9)


def test_a_forward_step_stops_short_of_a_table_or_trunk_in_the_way():
    assert free_ahead(seeing([table(2.5, 0.0)]), 0.5, 1.0) == pytest.approx(1.0), "room for the whole step"
    assert free_ahead(seeing([table(2.0, 0.0)]), 0.5, 1.0) == pytest.approx(0.5), "up to the table's edge"
    assert free_ahead(seeing([table(2.0, math.pi / 2)]), 0.5, 1.0) == 1.0, "beside it: not in the way"
    assert free_ahead(seeing([table(1.4, math.pi)]), 0.5, 1.0) == 1.0, "behind it, even overlapping by rounding"
    assert free_ahead(seeing([table(1.5, 0.0)]), 0.5, 1.0) == 0.0, "touching it already"
    tree = PerceivedObject("T1", "tree", RelativePosition(1.5, 0.0), 2.0, 6.0)  # a crown of 2: a trunk of 0.3
    assert free_ahead(seeing([tree]), 0.5, 1.0) == pytest.approx(0.7), "a tree blocks with its trunk, not its crown"
    glancing = table(2.0, math.asin(1.2 / 2.0))  # 1.2 to the side: the body's edge passes 0.3 into the table
    assert free_ahead(seeing([glancing]), 0.5, 1.0) == pytest.approx(1.6 - math.sqrt(1.5 ** 2 - 1.2 ** 2))
