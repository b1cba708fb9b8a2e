package io.orchard.agents.errand;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.language.Language;
import io.orchard.agents.language.Reference;
import io.orchard.protocol.value.Gripper;
import org.junit.jupiter.api.Test;

/** Whether a body can collect fruit where the words put it. */
class ReachTest {

    private static final Gripper MOUTH = new Gripper("mouth", 0.3, 0, 0.5);
    private static final Gripper CLAW = new Gripper("claw", 0.8, 0.2, 2.6);
    private static final Speech ENGLISH = new Speech(Language.ENGLISH);

    @Test
    void aMouthOnTheGroundCannotTakeACoconutFromATreeAndSaysWhy() {
        Reference inTree = GrounderTest.said("pick up the coconut in the tree");

        assertThat(FruitHeights.refusal(inTree, MOUTH, ENGLISH)).isEqualTo(
                "I can't pick up a coconut that hangs in a tree: fruit that hangs in a tree is 1.50 to 3.00 high,"
                        + " and my mouth reaches only from 0.00 to 0.50.");
        assertThat(FruitHeights.refusal(inTree, CLAW, ENGLISH)).isNull();
        assertThat(FruitHeights.refusal(inTree, MOUTH, new Speech(Language.GERMAN))).isEqualTo(
                "Ich kann eine Kokosnuss, die in einem Baum hängt, nicht aufheben: Früchte, die in einem Baum hängen, "
                        + "sind 1.50 bis 3.00 hoch, und mein Greifer (mouth) reicht nur von 0.00 bis 0.50.");
    }

    @Test
    void fruitOnTablesIsOutOfReachOfAMouthButNotFruitWhereverItIs() {
        Reference onTable = GrounderTest.said("grab the banana on the table");
        Reference anywhere = GrounderTest.said("pick up a coconut");
        Reference underTree = GrounderTest.said("eat the tomato under the tree");

        assertThat(FruitHeights.refusal(onTable, MOUTH, ENGLISH)).contains("lies on a table is 0.85 to 1.35 high");
        assertThat(FruitHeights.refusal(anywhere, MOUTH, ENGLISH)).isNull();
        assertThat(FruitHeights.refusal(underTree, MOUTH, ENGLISH)).isNull();
    }
}
