package io.orchard.examples.tournament;

import java.io.PrintStream;
import java.util.Locale;
import java.util.function.LongSupplier;

/**
 * The tournament's progress. On a terminal a bar redrawn in place ({@code \r}) as the games' clocks
 * advance; elsewhere (a log, a pipe, a test) one line per finished game, so that no control
 * characters end up in files.
 *
 * <p>The time left is estimated from the games finished, once there is one: the bar's fraction is
 * simulated time, a poor measure of the wall clock before then, since the first game also pays for
 * starting up (its first simulated second can take longer than a whole later game) and a game ends
 * early when the fruit runs out.
 */
final class ProgressBar {

    private static final int WIDTH = 30;
    private static final long REDRAW_NANOS = 100_000_000;

    private final PrintStream out;
    private final boolean terminal;
    private final int games;
    private final LongSupplier nanos;
    private final long started;
    private long drawn;
    private long gameStarted;
    private long firstGame;
    private long laterGames;
    private int finished;

    ProgressBar(PrintStream out, boolean terminal, int games) {
        this(out, terminal, games, System::nanoTime);
    }

    /** A bar that reads the time from {@code nanos}, as {@link System#nanoTime()} gives it. */
    ProgressBar(PrintStream out, boolean terminal, int games, LongSupplier nanos) {
        this.out = out;
        this.terminal = terminal;
        this.games = games;
        this.nanos = nanos;
        this.started = nanos.getAsLong();
        this.gameStarted = started;
        this.drawn = started - REDRAW_NANOS;
    }

    /** The game numbered {@code game} (from 1) is {@code fraction} done; redrawn at most ten times a second. */
    synchronized void during(int game, double fraction, String label) {
        long now = nanos.getAsLong();
        if (!terminal || now - drawn < REDRAW_NANOS) {
            return;
        }
        drawn = now;
        out.print("\r" + bar((game - 1 + Math.min(1, fraction)) / games, now) + "  " + label + "\u001b[K");
        out.flush();
    }

    /** The game numbered {@code game} is over. */
    synchronized void finished(int game, String label) {
        long now = nanos.getAsLong();
        if (finished == 0) {
            firstGame = now - gameStarted;
        } else {
            laterGames += now - gameStarted;
        }
        finished++;
        gameStarted = now;
        String line = bar((double) game / games, now) + "  " + label;
        out.print(terminal ? "\r" + line + "\u001b[K" + (game == games ? "\n" : "") : line + "\n");
        out.flush();
    }

    private String bar(double done, long now) {
        int filled = (int) Math.round(done * WIDTH);
        double seconds = (now - started) / 1e9;
        String eta = finished > 0 && finished < games
                ? String.format(Locale.ROOT, ", about %.0f s left", secondsLeft(now)) : "";
        return String.format(Locale.ROOT, "[%s%s] %3.0f%% (%.0f s%s)", "#".repeat(filled), ".".repeat(WIDTH - filled),
                100 * done, seconds, eta);
    }

    /**
     * What the games not finished yet should take, at the pace of those finished: the later games
     * alone once there are some, the first carrying the start-up.
     */
    private double secondsLeft(long now) {
        double perGame = (finished > 1 ? (double) laterGames / (finished - 1) : firstGame) / 1e9;
        double intoThisGame = (now - gameStarted) / 1e9;
        return Math.max(0, perGame * (games - finished) - intoThisGame);
    }
}
