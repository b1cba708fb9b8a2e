package io.orchard.agents.language;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/** The sentences of the sets of instructions, corpus.tsv, fresh.tsv and german.tsv, in file order. */
public final class InstructionSets {

    private InstructionSets() {
    }

    /** Every sentence of both sets, without the expected goals. */
    public static List<String> sentences() throws IOException {
        return sentences(List.of("/language/corpus.tsv", "/language/fresh.tsv"));
    }

    /** Every sentence of the German set, german.tsv. */
    public static List<String> german() throws IOException {
        return sentences(List.of("/language/german.tsv"));
    }

    /** Every sentence of the fresh set, fresh.tsv, as a new user typed them. */
    public static List<String> fresh() throws IOException {
        return sentences(List.of("/language/fresh.tsv"));
    }

    private static List<String> sentences(List<String> sets) throws IOException {
        List<String> sentences = new ArrayList<>();
        for (String set : sets) {
            try (InputStream in = Objects.requireNonNull(InstructionSets.class.getResourceAsStream(set), set);
                 BufferedReader lines = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
                for (String line = lines.readLine(); line != null; line = lines.readLine()) {
                    int tab = line.indexOf('\t');
                    if (!line.startsWith("#") && tab > 0) {
                        sentences.add(line.substring(0, tab));
                    }
                }
            }
        }
        return sentences;
    }
}
