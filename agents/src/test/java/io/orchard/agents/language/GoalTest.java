package io.orchard.agents.language;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.agents.language.Place.Relation;
import io.orchard.agents.language.Reference.Kind;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Sector;
import java.util.List;
import org.junit.jupiter.api.Test;

class GoalTest {

    @Test
    void onlyFruitIsCollectedAndAtLeastOne() {
        assertThatThrownBy(() -> Collect.one(Reference.to(Kind.TREE)))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("TREE");
        assertThatThrownBy(() -> new Collect(Reference.to(Kind.BANANA), 0))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("was 0");
        assertThat(Collect.all(Reference.to(Kind.FRUIT)).isAll()).isTrue();
    }

    @Test
    void aSequenceOfOneIsThatGoalAndNestedSequencesAreFlattened() {
        assertThat(Sequence.of(new Stop())).isEqualTo(new Stop());
        Goal nested = Sequence.of(new Stop(), Sequence.of(new CarryOn(), new ComeBack()));
        assertThat(nested).isEqualTo(new Sequence(List.of(new Stop(), new CarryOn(), new ComeBack())));
        assertThatThrownBy(() -> new Sequence(List.of(new Stop()))).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new Sequence(List.of(new Stop(), nested)))
                .isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void placesNeedAnAnchorExceptOnTheGroundAndByCompass() {
        assertThatThrownBy(() -> Place.of(Relation.ON, null)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("ON needs an anchor");
        assertThatThrownBy(() -> Place.of(Relation.ON_GROUND, Reference.to(Kind.TABLE)))
                .isInstanceOf(IllegalArgumentException.class);
        assertThat(Place.of(Relation.NORTH_OF, null).relation().sector()).isEqualTo(Sector.NORTH);
        assertThat(Relation.of(Sector.SOUTH_WEST)).isEqualTo(Relation.SOUTH_WEST_OF);
        assertThat(Relation.NORTH_EAST_OF.wireName()).isEqualTo("north-east-of");
    }

    @Test
    void onlyAnAgentHasANameAndOnlyAnAgentIsFollowed() {
        assertThatThrownBy(() -> new Reference(Kind.TREE, "Oak", null, null, null))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("'Oak'");
        assertThatThrownBy(() -> new Follow(Reference.to(Kind.RIVER))).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new Cross(Reference.to(Kind.CASTLE))).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void kindsKnowTheProtocolsKinds() {
        assertThat(Kind.BANANA.fruitKind()).isEqualTo(FruitKind.BANANA);
        assertThat(Kind.FRUIT.matches(FruitKind.COCONUT)).isTrue();
        assertThat(Kind.TOMATO.matches(FruitKind.COCONUT)).isFalse();
        assertThat(Kind.TABLE.objectKind()).isEqualTo(ObjectKind.TABLE);
        assertThat(Kind.CASTLE.isFruit()).isFalse();
    }

    @Test
    void aWalkIsMoreThanNothingAndAtMostAThousandMetres() {
        assertThat(new Head(io.orchard.protocol.value.Sector.NORTH).distance()).isNull();
        assertThat(new RelativeMove(RelativeMove.Direction.LEFT, 2.5).distance()).isEqualTo(2.5);
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> new Head(io.orchard.protocol.value.Sector.NORTH, 0.0))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("was 0.0");
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> new RelativeMove(RelativeMove.Direction.FORWARD, 1000.5))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("at most 1000");
    }

    @Test
    void turnsArePositiveToTheLeft() {
        assertThat(Turn.left().degrees()).isEqualTo(90, org.assertj.core.data.Offset.offset(1e-9));
        assertThat(Turn.right().radians()).isNegative();
        assertThatThrownBy(() -> new Turn(Double.NaN)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new Wait(-1)).isInstanceOf(IllegalArgumentException.class);
        assertThat(Wait.untilTold().isUntilTold()).isTrue();
    }
}
