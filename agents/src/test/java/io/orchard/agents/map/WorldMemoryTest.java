package io.orchard.agents.map;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sector;
import io.orchard.protocol.value.Sight;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

class WorldMemoryTest {

    private final WorldMemory memory = new WorldMemory(new Bounds(-100, -100, 100, 100), 0.4,
            new Sight(40, 2 * Math.PI));

    @Nested
    class RelativeToAbsolute {

        @Test
        void treesAndTablesAreRememberedWhereTheyStandWhateverTheHeading() {
            // The same tree and table seen from two places with different headings.
            Views.from(10, 5, Math.PI / 2).tree("T1", -2, 5, 2).table("D1", 10, 20, 0.8, 0.9).into(memory);
            Views.from(-20, -30, -2.2).tree("T1", -2, 5, 2).into(memory);

            KnownObstacle tree = memory.obstacle("T1").orElseThrow();
            KnownObstacle table = memory.obstacle("D1").orElseThrow();
            assertThat(tree.centre().x()).isCloseTo(-2, within(1e-9));
            assertThat(tree.centre().z()).isCloseTo(5, within(1e-9));
            assertThat(table.centre().x()).isCloseTo(10, within(1e-9));
            assertThat(table.centre().z()).isCloseTo(20, within(1e-9));
        }

        @Test
        void aTreeBlocksWithItsTrunkAndATableWithItsTop() {
            Views.from(0, 0, 0).tree("T1", 0, -10, 2).tree("T2", 5, -10, 5).table("D1", -5, -10, 0.8, 0.9).into(memory);

            assertThat(memory.obstacle("T1").orElseThrow().blockRadius()).isCloseTo(0.3, within(1e-9));
            assertThat(memory.obstacle("T2").orElseThrow().blockRadius()).isCloseTo(0.5, within(1e-9));
            assertThat(memory.obstacle("D1").orElseThrow().blockRadius()).isCloseTo(0.8, within(1e-9));
        }

        @Test
        void otherAgentsAndBridgesAreTurnedIntoWorldCoordinates() {
            Views.from(3, 4, 2.0).agent("Bunny", 8, -1).bridge("B1", 30, 8, 30, 22, 4).into(memory);

            SeenAgent bunny = memory.agents().get(0);
            assertThat(bunny.position().x()).isCloseTo(8, within(1e-9));
            assertThat(bunny.position().z()).isCloseTo(-1, within(1e-9));
            KnownBridge bridge = memory.bridges().iterator().next();
            assertThat(bridge.entryA().distance(new Point2(30, 8))).isLessThan(1e-9);
            assertThat(bridge.entryB().distance(new Point2(30, 22))).isLessThan(1e-9);
        }

        @Test
        void fruitIsKeptAtTheAbsolutePositionItWasPerceivedAt() {
            Views.from(0, 0, 1.0).fruit("F1", FruitKind.BANANA, 2, 1.15, -3).into(memory);

            KnownFruit fruit = memory.fruit("F1").orElseThrow();
            assertThat(fruit.position().x()).isEqualTo(2);
            assertThat(fruit.height()).isEqualTo(1.15);
            assertThat(fruit.position().z()).isEqualTo(-3);
        }

        @Test
        void theAgentsOwnPlaceComesFromTheSamePerception() {
            Views.from(12, -7, 0.5).into(memory);

            assertThat(memory.position()).isEqualTo(new Point2(12, -7));
            assertThat(memory.heading()).isEqualTo(0.5);
        }

        @Test
        void aNearerSightingPlacesAnObjectBetter() {
            Views.from(0, 0, 0).tree("T1", 0, -30, 2).into(memory);
            // A second sighting, from nearer, with a slightly different position (rounding).
            Views.from(0, -25, 0).tree("T1", 0.05, -30, 2).into(memory);

            assertThat(memory.obstacle("T1").orElseThrow().centre().x()).isCloseTo(0.05, within(1e-9));
            assertThat(memory.obstacle("T1").orElseThrow().accuracy()).isCloseTo(5, within(0.01));
        }
    }

    @Nested
    class Fruit {

        @Test
        void eatenFruitIsForgottenAndNotRememberedAgain() {
            Views.from(0, 0, 0).fruit("F1", FruitKind.TOMATO, 1, 0.15, 1).into(memory);
            memory.fruitEaten("F1");
            Views.from(0, 0, 0).tick(1).fruit("F1", FruitKind.TOMATO, 1, 0.15, 1).into(memory);

            assertThat(memory.fruit()).isEmpty();
            assertThat(memory.gone("F1")).isTrue();
        }
    }

    @Nested
    class RejectedMoves {

        @Test
        void aRejectionByAKnownTreeWidensTheRoomKeptFromIt() {
            Views.from(0, 0, 0).tree("T1", 0, -5, 2).into(memory);
            long before = memory.terrainVersion();

            Obstruction what = memory.moveRejected(new Point2(0, 0), new Point2(0, -10), "path crosses tree T1");

            assertThat(what).isEqualTo(Obstruction.TREE);
            assertThat(memory.obstacle("T1").orElseThrow().margin()).isGreaterThan(0);
            assertThat(memory.terrainVersion()).isGreaterThan(before);
        }

        @Test
        void aRejectionBySomethingUnknownIsRememberedAsABlockedWay() {
            memory.moveRejected(new Point2(0, 0), new Point2(0, -10), "path crosses tree T99");
            memory.moveRejected(new Point2(0, 0), new Point2(10, 0), "path enters the river outside a bridge");
            memory.moveRejected(new Point2(0, 0), new Point2(3, 0), "from (0.00, 0.00) is not where Tester is: (1.00, 0.00)");

            assertThat(memory.learned()).extracting(LearnedBlock::what).containsExactly("tree T99", "the river");
        }
    }

    @Nested
    class Castle {

        @Test
        void sectorsSeenFromSeveralPlacesLocateTheCastle() {
            // A castle centred on (40, -40), seen from two rings of places around it.
            Point2 castle = new Point2(40, -40);
            for (double distance : new double[] {40, 14}) {
                for (int k = 0; k < 16; k++) {
                    double angle = k * Math.PI / 8 + 0.1;
                    Point2 from = new Point2(castle.x() + distance * Math.cos(angle), castle.z() + distance * Math.sin(angle));
                    Sector sector = Sector.of(castle.x() - from.x(), castle.z() - from.z());
                    Views.from(from.x(), from.z(), 0).castle(sector).into(memory);
                }
            }

            assertThat(memory.castle().located()).isTrue();
            assertThat(memory.castle().centre().orElseThrow().distance(castle)).isLessThan(4);
        }
    }
}
