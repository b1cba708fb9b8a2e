package io.orchard.server.world.scenario;

import java.util.List;

/**
 * Why a scenario was refused: the one exception for every problem with a scenario, from a typo in
 * the file to two trees in the same place. Each problem names the object and what is wrong with it
 * ("tree T3 overlaps table D1", "table D1: radius must be greater than 0, was -1.0 (at tables[0],
 * line 12, column 7)").
 *
 * <p>An {@link IllegalArgumentException}, because the scenario is an argument the caller gave.
 */
public final class ScenarioException extends IllegalArgumentException {

    private static final long serialVersionUID = 1L;

    /** The most problems the message lists; {@link #problems()} has them all. */
    private static final int SHOWN = 10;

    private final List<String> problems;

    /** A scenario with one problem. */
    public ScenarioException(String problem) {
        this(List.of(problem), null);
    }

    /** A scenario with one problem, found while reading it. */
    public ScenarioException(String problem, Throwable cause) {
        this(List.of(problem), cause);
    }

    /** A scenario with one or more problems. */
    public ScenarioException(List<String> problems) {
        this(problems, null);
    }

    private ScenarioException(List<String> problems, Throwable cause) {
        super(message(problems), cause);
        this.problems = List.copyOf(problems);
    }

    private static String message(List<String> problems) {
        if (problems.isEmpty()) {
            throw new IllegalArgumentException("a scenario exception needs at least one problem");
        }
        if (problems.size() == 1) {
            return problems.get(0);
        }
        StringBuilder text = new StringBuilder(problems.size() + " problems: ");
        text.append(String.join("; ", problems.subList(0, Math.min(SHOWN, problems.size()))));
        if (problems.size() > SHOWN) {
            text.append("; and ").append(problems.size() - SHOWN).append(" more");
        }
        return text.toString();
    }

    /** Every problem found, in the order found. */
    public List<String> problems() {
        return problems;
    }
}
