package io.orchard.examples.tournament;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;

/**
 * Writes a tournament's rows as results.csv (a header, then {@code game,seed,agent,fruit,points})
 * and results.json (an array of objects with the same fields and {@code missedTurns}, the lockstep
 * turns the agent's client missed, each with its tick and kind). Agents' names are letters, digits,
 * '_' and '-' (the protocol allows no others), so neither format needs quoting.
 */
final class ResultFiles {

    static final String CSV = "results.csv";
    static final String JSON = "results.json";

    private ResultFiles() {}

    static Path writeCsv(List<Result> results, Path dir) throws IOException {
        StringBuilder text = new StringBuilder("game,seed,agent,fruit,points\n");
        for (Result r : results) {
            text.append(String.format(Locale.ROOT, "%d,%d,%s,%d,%d%n", r.game(), r.seed(), r.agent(), r.fruit(),
                    r.points()));
        }
        return Files.writeString(dir.resolve(CSV), text, StandardCharsets.UTF_8);
    }

    /** Every row, each with the turns its agent's client missed (none in a game that repeats exactly). */
    static Path writeJson(List<Played> played, Path dir) throws IOException {
        List<String> rows = new ArrayList<>();
        for (Played game : played) {
            for (Result r : game.rows()) {
                String missed = game.missedBy(r.agent()).stream()
                        .map(m -> String.format(Locale.ROOT, "{\"tick\": %d, \"turn\": \"%s\"}", m.tick(),
                                m.kind().wireName()))
                        .collect(Collectors.joining(", "));
                rows.add(String.format(Locale.ROOT,
                        "  {\"game\": %d, \"seed\": %d, \"agent\": \"%s\", \"fruit\": %d, \"points\": %d, "
                                + "\"missedTurns\": [%s]}", r.game(), r.seed(), r.agent(), r.fruit(), r.points(), missed));
            }
        }
        return Files.writeString(dir.resolve(JSON), "[\n" + String.join(",\n", rows) + "\n]\n", StandardCharsets.UTF_8);
    }
}
