package io.orchard.agents.language;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/** The sentences of the sets of instructions, corpus.tsv, fresh.tsv, german.tsv and unseen.tsv, in file order. */
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

    /** Every sentence of the set written to judge the grammar afresh, unseen.tsv. */
    public static List<String> unseen() throws IOException {
        return sentences(List.of("/language/unseen.tsv"));
    }

    /**
     * One line of a set: its number in the file, the sentence, what is expected of it, and whether it is
     * told to an agent that speaks German (a third field "de").
     */
    public record Line(int number, String sentence, String expected, boolean german) {
    }

    /** The lines of a set, {@code /language/NAME.tsv}, each SENTENCE, TAB, EXPECTED, and optionally TAB "de". */
    public static List<Line> lines(String set) throws IOException {
        List<Line> lines = new ArrayList<>();
        try (InputStream in = Objects.requireNonNull(InstructionSets.class.getResourceAsStream(set), set);
             BufferedReader reader = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
            int number = 0;
            for (String text = reader.readLine(); text != null; text = reader.readLine()) {
                number++;
                if (text.isBlank() || text.startsWith("#")) {
                    continue;
                }
                String[] fields = text.split("\t", -1);
                boolean german = fields.length == 3 && fields[2].equals("de");
                if (fields.length != 2 && !german) {
                    throw new IllegalStateException(set + ":" + number + " must be SENTENCE<TAB>EXPECTED[<TAB>de], was '"
                            + text + "'");
                }
                lines.add(new Line(number, fields[0], fields[1].strip(), german));
            }
        }
        return lines;
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
