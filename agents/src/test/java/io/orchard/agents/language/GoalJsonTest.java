package io.orchard.agents.language;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.language.Place.Relation;
import io.orchard.agents.language.Reference.Distance;
import io.orchard.agents.language.Reference.Kind;
import io.orchard.agents.language.Reference.Size;
import io.orchard.protocol.value.Sector;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

class GoalJsonTest {

    @Test
    void aCollectGoalNamesItsReferenceAndCount() {
        Reference banana = new Reference(Kind.BANANA, null, null, Distance.NEAREST,
                Place.of(Relation.ON, Reference.to(Kind.TABLE)));
        assertThat(GoalJson.write(Collect.one(banana))).isEqualTo("{\"goal\":\"collect\",\"what\":{\"kind\":"
                + "\"banana\",\"distance\":\"nearest\",\"place\":{\"relation\":\"on\",\"anchor\":"
                + "{\"kind\":\"table\"}}},\"count\":1}");
    }

    @Test
    void allIsWrittenAsAWord() {
        assertThat(GoalJson.write(Collect.all(Reference.to(Kind.FRUIT))))
                .isEqualTo("{\"goal\":\"collect\",\"what\":{\"kind\":\"fruit\"},\"count\":\"all\"}");
    }

    @Test
    void aSequenceListsItsSteps() {
        Goal goal = Sequence.of(new GoTo(Reference.to(Kind.CASTLE)), Collect.one(Reference.to(Kind.TOMATO)));
        assertThat(GoalJson.write(goal)).isEqualTo("{\"goal\":\"sequence\",\"steps\":[{\"goal\":\"go-to\","
                + "\"destination\":{\"kind\":\"castle\"}},{\"goal\":\"collect\",\"what\":{\"kind\":\"tomato\"},"
                + "\"count\":1}]}");
    }

    @Test
    void agentsAreNamedAndPartsInAFixedOrder() {
        Reference guppy = Reference.agent("Guppy");
        Reference tree = new Reference(Kind.TREE, null, Size.BIG, Distance.FARTHEST,
                Place.of(Relation.NORTH_OF, guppy));
        assertThat(GoalJson.write(new Follow(guppy)))
                .isEqualTo("{\"goal\":\"follow\",\"agent\":{\"kind\":\"agent\",\"name\":\"Guppy\"}}");
        assertThat(GoalJson.write(new GoTo(tree))).isEqualTo("{\"goal\":\"go-to\",\"destination\":{\"kind\":\"tree\","
                + "\"size\":\"big\",\"distance\":\"farthest\",\"place\":{\"relation\":\"north-of\",\"anchor\":"
                + "{\"kind\":\"agent\",\"name\":\"Guppy\"}}}}");
    }

    @Test
    void optionalPartsAreLeftOut() {
        assertThat(GoalJson.write(Explore.anywhere())).isEqualTo("{\"goal\":\"explore\"}");
        assertThat(GoalJson.write(Wait.untilTold())).isEqualTo("{\"goal\":\"wait\"}");
        assertThat(GoalJson.write(new Wait(10))).isEqualTo("{\"goal\":\"wait\",\"seconds\":10.0}");
        assertThat(GoalJson.write(new GoTo(Reference.place(Place.of(Relation.EAST_OF, null)))))
                .isEqualTo("{\"goal\":\"go-to\",\"destination\":{\"kind\":\"place\",\"place\":{\"relation\":"
                        + "\"east-of\"}}}");
    }

    @Test
    void aTurnGivesRadiansAndDegrees() {
        assertThat(GoalJson.write(Turn.right()))
                .isEqualTo("{\"goal\":\"turn\",\"radians\":-1.5707963267948966,\"degrees\":-90.0}");
    }

    @Test
    void prettyOutputIsIndentedAndMeansTheSame() {
        String pretty = GoalJson.writePretty(new Head(Sector.NORTH_EAST));
        assertThat(pretty).contains("\n").contains("\"goal\" : \"head\"").contains("\"direction\" : \"north-east\"");
        assertThat(pretty.replaceAll("\\s", "")).isEqualTo(GoalJson.write(new Head(Sector.NORTH_EAST)));
    }

    static List<Goal> everyKindOfGoal() {
        Reference castle = Reference.to(Kind.CASTLE);
        return List.of(new GoTo(castle), new Cross(Reference.to(Kind.RIVER)), new Head(Sector.SOUTH),
                new RelativeMove(RelativeMove.Direction.BACKWARD), new ComeBack(), Collect.one(Reference.to(Kind.COCONUT)),
                Turn.around(), new Face(Sector.WEST), new LookAt(castle), new LookFor(Reference.to(Kind.BANANA)),
                new Explore(Reference.to(Kind.FOREST)), Follow.agent("Dwarf"), new Stop(), new Wait(2.5),
                new CarryOn(), Sequence.of(new Stop(), new CarryOn()),
                new Avoid(Reference.place(Place.of(Relation.NEAR, Reference.to(Kind.RIVER)))),
                new Leave(Reference.to(Kind.COCONUT)), new Only(Reference.to(Kind.BANANA)), Lift.all(),
                new Lift(Reference.to(Kind.TOMATO)), new WhenSee(Reference.to(Kind.BANANA),
                        Collect.one(Reference.to(Kind.BANANA))), Ask.of(Ask.Topic.RULES),
                new GoTo(Reference.to(Kind.TABLE).withOrdinal(2, Distance.LEFTMOST)),
                new GoTo(Reference.thing(Kind.TABLE, "D3")));
    }

    @Test
    void rulesConditionsOrdinalsAndIdsAreWrittenAndReadBack() {
        Goal when = new WhenSee(Reference.agent("Roadrunner"), new Follow(Reference.agent("Roadrunner")));
        Goal second = new GoTo(Reference.to(Kind.TABLE).withOrdinal(2, Distance.LEFTMOST));
        Goal that = Collect.all(Reference.to(Kind.TOMATO).withPlace(Place.of(Relation.ON,
                Reference.thing(Kind.TABLE, "D3"))));

        assertThat(GoalJson.write(new Avoid(Reference.to(Kind.FOREST))))
                .isEqualTo("{\"goal\":\"avoid\",\"area\":{\"kind\":\"forest\"}}");
        assertThat(GoalJson.write(Lift.all())).isEqualTo("{\"goal\":\"lift\"}");
        assertThat(GoalJson.write(when)).isEqualTo("{\"goal\":\"when-see\",\"what\":{\"kind\":\"agent\","
                + "\"name\":\"Roadrunner\"},\"then\":{\"goal\":\"follow\",\"agent\":{\"kind\":\"agent\","
                + "\"name\":\"Roadrunner\"}}}");
        assertThat(GoalJson.write(second)).isEqualTo("{\"goal\":\"go-to\",\"destination\":{\"kind\":\"table\","
                + "\"distance\":\"leftmost\",\"ordinal\":2}}");
        assertThat(GoalJson.write(that)).isEqualTo("{\"goal\":\"collect\",\"what\":{\"kind\":\"tomato\","
                + "\"place\":{\"relation\":\"on\",\"anchor\":{\"kind\":\"table\",\"id\":\"D3\"}}},"
                + "\"count\":\"all\"}");
        for (Goal goal : everyKindOfGoal()) {
            assertThat(GoalJson.read(GoalJson.write(goal))).isEqualTo(goal);
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("everyKindOfGoal")
    void everyGoalHasADiscriminatorAndIsWrittenTheSameTwice(Goal goal) {
        String json = GoalJson.write(goal);
        assertThat(json).startsWith("{\"goal\":\"");
        assertThat(GoalJson.write(goal)).isEqualTo(json);
        assertThat(goal.notation()).isNotBlank();
        assertThat(goal.restatement()).endsWith(".");
    }
}
