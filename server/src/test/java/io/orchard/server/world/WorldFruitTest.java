package io.orchard.server.world;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Point2;
import org.junit.jupiter.api.Test;

class WorldFruitTest {

    private final World world = SmallWorld.builder()
            .ground("F1", FruitKind.TOMATO, 30, 30)
            .ground("F2", FruitKind.COCONUT, 35, 30)
            .world();

    @Test
    void removingAFruitReportsWhetherItWasThere() {
        assertThat(world.removeFruit("F1")).isTrue();
        assertThat(world.removeFruit("F1")).isFalse();
        assertThat(world.removeFruit("F9")).isFalse();
        assertThat(world.fruitCount()).isEqualTo(1);
    }

    @Test
    void aRemovedFruitIsGoneEverywhere() {
        world.removeFruit("F1");

        assertThat(world.fruit("F1")).isEmpty();
        assertThat(world.fruit()).extracting(Fruit::id).containsExactly("F2");
        assertThat(world.fruitStates()).extracting(FruitState::id).containsExactly("F2");
        assertThat(world.fruitWithin(new Point2(30, 30), 20)).extracting(FruitState::id).containsExactly("F2");
        assertThat(world.toScenario().fruit()).extracting(FruitState::id).containsExactly("F2");
    }

    @Test
    void aWorldKeepsItsFruitInTheOrderItWasMadeWith() {
        assertThat(world.fruit()).extracting(Fruit::id).containsExactly("F1", "F2");
        assertThat(world.fruit("F2")).map(Fruit::kind).contains(FruitKind.COCONUT);
    }

    @Test
    void aSnapshotDescribesTheWholeWorld() {
        var snapshot = world.snapshot(7, 0.35, java.util.List.of());

        assertThat(snapshot.tick()).isEqualTo(7);
        assertThat(snapshot.bounds()).isEqualTo(world.bounds());
        assertThat(snapshot.castle()).isEqualTo(world.castle().shape());
        assertThat(snapshot.river()).isEqualTo(world.river().shape());
        assertThat(snapshot.fruit()).hasSize(2);
    }

    @Test
    void aRandomFreePointIsFreeAndRepeatsForTheSameSeed() {
        var first = world.randomFreePoint(new java.util.Random(3), 0.5);
        var again = world.randomFreePoint(new java.util.Random(3), 0.5);

        assertThat(first).isEqualTo(again);
        assertThat(world.checkPlace(first.onGround(), 0.5).isFree()).isTrue();
    }
}
