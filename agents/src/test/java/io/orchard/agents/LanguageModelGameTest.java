package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.language.FakeLanguageModel;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Point2;
import io.orchard.server.sim.GameListener;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;

/**
 * An agent that consults a language model, in a real lockstep game: a sentence its grammar does
 * not understand is read by the model (served over HTTP on a port of its own), restated, and done.
 */
class LanguageModelGameTest {

    private static final long SEED = InstructedAgentTest.SEED;

    @Test
    void aSentenceOnlyTheModelUnderstandsIsRestatedAndCarriedOut() throws Exception {
        try (FakeLanguageModel model = new FakeLanguageModel()) {
            model.answers("{\"goal\":\"collect\",\"what\":{\"kind\":\"banana\",\"distance\":\"nearest\"},\"count\":1}");
            QuestionsAndPlacesGameTest.Listener pupil = new QuestionsAndPlacesGameTest.Listener();
            pupil.consultLanguageModel(model.model(Duration.ofSeconds(30)));
            List<String> bananas = new CopyOnWriteArrayList<>();
            GameListener listener = new GameListener() {
                @Override
                public void fruitEaten(String agent, String fruitId, FruitKind kind, double time) {
                    if (agent.equals("Pupil") && kind == FruitKind.BANANA) {
                        bananas.add(fruitId);
                    }
                }
            };
            Point2 start = Games.freeWalk(SEED, 12)[0];
            pupil.instruct("I would be ever so grateful for one of those long yellow things");

            Games.play(SEED, 40, List.of(pupil), Games.at(Map.of("Pupil", start.at(0))), listener);

            assertThat(pupil.said.get(0)).isEqualTo("I asked a language model, which read that as: collect(nearest banana).");
            assertThat(pupil.said).as("said").anyMatch(s -> s.startsWith("Done: I picked up the banana "));
            assertThat(bananas).as("bananas collected; said %s", pupil.said).isNotEmpty();
            assertThat(model.requests()).hasSize(1);
        }
    }
}
