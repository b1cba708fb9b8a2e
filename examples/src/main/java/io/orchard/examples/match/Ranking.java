package io.orchard.examples.match;

import io.orchard.protocol.value.Score;
import java.io.PrintStream;
import java.util.List;
import java.util.Locale;

/** Prints a game's ranking as the server's command line does, so that every program's reads alike. */
public final class Ranking {

    /** The heading line before the table; tests and scripts look for it. */
    public static final String HEADING = "Ranking:";

    private Ranking() {}

    /** Prints "Game over (reason). Ranking:" and one line per agent, best first. */
    public static void print(String reason, List<Score> ranking, PrintStream out) {
        out.println("Game over (" + reason + "). " + HEADING);
        int place = 1;
        for (Score score : ranking) {
            out.printf(Locale.ROOT, "%3d. %-16s %4d points  %3d fruit%n", place++, score.agent(), score.points(),
                    score.fruit());
        }
        out.flush();
    }
}
