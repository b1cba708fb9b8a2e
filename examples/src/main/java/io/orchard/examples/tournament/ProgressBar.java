package io.orchard.examples.tournament;

import java.io.PrintStream;
import java.util.Locale;

/**
 * The tournament's progress. On a terminal a bar redrawn in place ({@code \r}) as the games' clocks
 * advance; elsewhere (a log, a pipe, a test) one line per finished game, so that no control
 * characters end up in files.
 */
final class ProgressBar {

    private static final int WIDTH = 30;
    private static final long REDRAW_NANOS = 100_000_000;

    private final PrintStream out;
    private final boolean terminal;
    private final int games;
    private final long started = System.nanoTime();
    private long drawn;

    ProgressBar(PrintStream out, boolean terminal, int games) {
        this.out = out;
        this.terminal = terminal;
        this.games = games;
    }

    /** The game numbered {@code game} (from 1) is {@code fraction} done; redrawn at most ten times a second. */
    synchronized void during(int game, double fraction, String label) {
        long now = System.nanoTime();
        if (!terminal || now - drawn < REDRAW_NANOS) {
            return;
        }
        drawn = now;
        out.print("\r" + bar((game - 1 + Math.min(1, fraction)) / games) + "  " + label + "\u001b[K");
        out.flush();
    }

    /** The game numbered {@code game} is over. */
    synchronized void finished(int game, String label) {
        String line = bar((double) game / games) + "  " + label;
        out.print(terminal ? "\r" + line + "\u001b[K" + (game == games ? "\n" : "") : line + "\n");
        out.flush();
    }

    private String bar(double done) {
        int filled = (int) Math.round(done * WIDTH);
        double seconds = (System.nanoTime() - started) / 1e9;
        String eta = done > 0 && done < 1 ? String.format(Locale.ROOT, ", about %.0f s left", seconds / done - seconds)
                : "";
        return String.format(Locale.ROOT, "[%s%s] %3.0f%% (%.0f s%s)", "#".repeat(filled), ".".repeat(WIDTH - filled),
                100 * done, seconds, eta);
    }
}
