package io.orchard.examples.tournament;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * Writes a tournament's rows as results.csv (a header, then {@code game,seed,agent,fruit,points})
 * and results.json (an array of objects with the same fields). Agents' names are letters, digits,
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

    static Path writeJson(List<Result> results, Path dir) throws IOException {
        StringBuilder text = new StringBuilder("[\n");
        for (int i = 0; i < results.size(); i++) {
            Result r = results.get(i);
            text.append(String.format(Locale.ROOT,
                    "  {\"game\": %d, \"seed\": %d, \"agent\": \"%s\", \"fruit\": %d, \"points\": %d}%s%n", r.game(),
                    r.seed(), r.agent(), r.fruit(), r.points(), i + 1 < results.size() ? "," : ""));
        }
        text.append("]\n");
        return Files.writeString(dir.resolve(JSON), text, StandardCharsets.UTF_8);
    }
}
