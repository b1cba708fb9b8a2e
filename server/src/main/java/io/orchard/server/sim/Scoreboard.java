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
public final class Scoreboard {

    static final Comparator<Score> RANKING = Comparator.comparingInt(Score::points).reversed()
            .thenComparing(Comparator.comparingInt(Score::fruit).reversed())
            .thenComparing(Score::agent);

    private final Map<String, Score> scores = new LinkedHashMap<>();

    /** An empty scoreboard. */
    public Scoreboard() {}

    /** The agent plays: it has a score from now on, 0 unless it had one. */
    public void join(String agent) {
        scores.putIfAbsent(agent, new Score(agent, 0, 0));
    }

    /** The agent collected a fruit of this kind; returns the points it scored. */
    public int collect(String agent, FruitKind kind) {
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

    /** Sets an agent's score, as a checkpoint kept it. */
    public void restore(Score score) {
        scores.put(score.agent(), score);
    }

    /** Every agent's score, best first. */
    public List<Score> ranking() {
        List<Score> ranked = new ArrayList<>(scores.values());
        ranked.sort(RANKING);
        return ranked;
    }
}
