package io.orchard.server.sim;

import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Score;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Every agent's points and fruit. An agent's score outlives its connection: the ranking lists every
 * agent that played, best first (most points, then most fruit, then by name).
 */
final class Scoreboard {

    static final Comparator<Score> RANKING = Comparator.comparingInt(Score::points).reversed()
            .thenComparing(Comparator.comparingInt(Score::fruit).reversed())
            .thenComparing(Score::agent);

    private final Map<String, Score> scores = new LinkedHashMap<>();

    void join(String agent) {
        scores.putIfAbsent(agent, new Score(agent, 0, 0));
    }

    int collect(String agent, FruitKind kind) {
        Score old = scores.getOrDefault(agent, new Score(agent, 0, 0));
        scores.put(agent, new Score(agent, old.points() + kind.points(), old.fruit() + 1));
        return kind.points();
    }

    /** How many agents have a score. */
    int size() {
        return scores.size();
    }

    boolean has(String agent) {
        return scores.containsKey(agent);
    }

    void restore(Score score) {
        scores.put(score.agent(), score);
    }

    List<Score> ranking() {
        List<Score> ranked = new ArrayList<>(scores.values());
        ranked.sort(RANKING);
        return ranked;
    }
}
