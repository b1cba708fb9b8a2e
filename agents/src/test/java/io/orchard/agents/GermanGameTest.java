package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.language.Language;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Point2;
import io.orchard.server.sim.GameListener;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;

/**
 * An agent that speaks German, in a real lockstep game: a German instruction is said back, carried
 * out and reported in German, a German question is answered in German, a German rule is kept and
 * listed in German, and an English sentence to the same agent is still understood and answered in
 * English.
 */
class GermanGameTest {

    private static final long SEED = InstructedAgentTest.SEED;

    @Test
    void aGermanInstructionIsSaidBackCarriedOutAndAnsweredInGermanAndEnglishStillInEnglish() throws Exception {
        RulesGameTest.Pupil pupil = new RulesGameTest.Pupil("Schueler");
        pupil.understand(Language.GERMAN);
        List<String> eaten = new CopyOnWriteArrayList<>();
        GameListener listener = new GameListener() {
            @Override
            public void fruitEaten(String agent, String fruitId, FruitKind kind, double time) {
                if (agent.equals("Schueler")) {
                    eaten.add(kind + " " + fruitId);
                }
            }

            @Override
            public void tickEnded(long tick, double time) {
                if (tick == 4) {
                    pupil.instruct("wo bist du?");
                } else if (tick == 8) {
                    pupil.instruct("geh nicht in die Nähe des Flusses");
                } else if (tick == 12) {
                    pupil.instruct("was sind deine Regeln?");
                } else if (tick == 16) {
                    pupil.instruct("where are you?");
                } else if (tick == 20) {
                    pupil.instruct("nimm die nächste Banane");
                }
            }
        };
        Point2 start = Games.freeWalk(SEED, 12)[0];

        Games.play(SEED, 40, List.of(pupil), Games.at(Map.of("Schueler", start.at(0))), listener);

        List<String> said = pupil.said;
        assertThat(said).as("said").hasSizeGreaterThan(5);
        assertThat(said.get(0)).as("said %s", said).startsWith("Ich bin ").containsPattern("(des|der) (Flusses|Schlosses"
                + "|Brücke)|im Wald|bei x");
        assertThat(said.get(1)).isEqualTo("Ab jetzt gehe ich nicht mehr in die Nähe des Flusses.");
        assertThat(said.get(2)).isEqualTo("Meine Regeln: ich gehe nicht in die Nähe des Flusses. Sag 'vergiss die "
                + "Regeln', um sie aufzuheben.");
        assertThat(said.get(3)).startsWith("I'm ").containsPattern("of the|by the|in the|at x");
        assertThat(said.get(4)).isEqualTo("Ich hebe die nächste Banane auf.");
        assertThat(said).as("said").anyMatch(s -> s.matches("Erledigt: Ich habe die Banane F\\d+ aufgehoben\\. Ich mache "
                + "allein weiter\\."));
        assertThat(eaten).as("taken; said %s", said).anyMatch(taken -> taken.startsWith("BANANA"));
    }
}
