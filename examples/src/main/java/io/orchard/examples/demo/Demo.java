package io.orchard.examples.demo;

import io.orchard.examples.match.Lineup;
import io.orchard.examples.match.Ranking;
import io.orchard.examples.match.Team;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Score;
import io.orchard.server.WorldServer;
import io.orchard.server.sim.GameListener;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.stream.Stream;

/**
 * One whole match: a realtime server embedded in this JVM, the paper's five agents on threads of
 * it, and a viewer. The game starts once the agents are in and the viewer shows the world, so that
 * the first screenshot is of the start; it ends at the time limit or when all fruit is collected,
 * and the ranking is printed last. A viewer in a window is the game's operator, with a token drawn
 * for this match alone: its Space pauses and continues the game.
 *
 * @param seed      the world's seed, or null to draw one
 * @param timeLimit the game's length in simulated seconds
 * @param headless  whether the viewer renders off screen, writing screenshots
 * @param shots     the screenshots' folder (headless only)
 * @param xvfbRun   the xvfb-run to run a headless viewer under, or null when there is a display
 * @param every     simulated seconds between screenshots
 * @param web       whether the server serves the browser viewer too, whose address is printed (and
 *                  opened in the desktop's browser where there is one)
 */
record Demo(Long seed, double timeLimit, boolean headless, Path shots, Path xvfbRun, double every, boolean web) {

    /** How long the agents and the viewer may take to be ready before the game starts anyway. */
    private static final long READY_SECONDS = 60;
    /** How long a headless viewer may take to write its last screenshot and end after the game. */
    private static final long VIEWER_END_SECONDS = 60;

    /** Plays the match; returns the exit status: 0, or 1 when the viewer failed or wrote no screenshot. */
    int play(PrintStream out, PrintStream err) throws IOException, InterruptedException {
        Lineup lineup = Lineup.zoo();
        CountDownLatch joined = new CountDownLatch(lineup.names().size());
        CompletableFuture<String> reason = new CompletableFuture<>();
        GameListener events = new GameListener() {
            @Override
            public void agentJoined(String agent) {
                joined.countDown();
            }

            @Override
            public void gameOver(String why, List<Score> ranking) {
                reason.complete(why);
            }
        };
        byte[] secret = new byte[16];
        new SecureRandom().nextBytes(secret);
        String operator = HexFormat.of().formatHex(secret);
        WorldServer.Builder builder = WorldServer.builder().port(0).clock(ClockMode.REALTIME).timeLimit(timeLimit)
                // Never started by the server itself: the demo starts it when the viewer is ready too.
                .waitFor(lineup.names().size() + 1).listener(events).operatorToken(operator);
        if (seed != null) {
            builder.seed(seed);
        }
        if (web) {
            builder.httpPort(0);
        }
        try (WorldServer server = builder.start()) {
            out.printf(Locale.ROOT, "Orchard demo: seed %d, server on port %d, %s, a game of at most %.0f s%n",
                    server.seed(), server.port(), String.join(", ", lineup.names()), timeLimit);
            if (web) {
                String page = "http://127.0.0.1:" + server.httpPort().orElseThrow() + "/";
                out.println("In a browser: " + page + " (operator token for the page: " + operator + ")");
                BrowserPage.open(page, headless);
            }
            if (headless) {
                out.println("Screenshots every " + format(every) + " s of the game go to " + shots().toAbsolutePath());
            }
            out.flush();
            ViewerRun viewer = headless
                    ? HeadlessViewer.start(server.port(), shots(), every, xvfbRun, timeLimit + READY_SECONDS
                            + VIEWER_END_SECONDS, out)
                    : WindowedViewer.start(server.port(), operator, out, err);
            try (Team team = Team.play(lineup.create(), "127.0.0.1", server.port())) {
                awaitReady(joined, team, viewer, err);
                server.startGame();
                out.println(headless ? "The game starts."
                        : "The game starts; Space in the viewer pauses and continues it.");
                out.flush();
                List<Score> ranking = awaitGameOver(server, viewer);
                int status = headless ? finishHeadless(viewer, out, err) : 0;
                if (!team.failures().isEmpty()) {
                    err.println("orchard demo: agents could not play: " + String.join("; ", team.failures()));
                    status = 1;
                }
                Ranking.print(reason.getNow("stopped"), ranking, out);
                if (!headless && viewer.awaitExit(0, TimeUnit.SECONDS) == null) {
                    out.println("Close the viewer's window to quit.");
                    out.flush();
                    viewer.awaitExit(Long.MAX_VALUE, TimeUnit.DAYS);
                }
                return status;
            } finally {
                viewer.stop();
            }
        }
    }

    /** Waits until every agent is in the world and the viewer shows it, or says what is missing. */
    private static void awaitReady(CountDownLatch joined, Team team, ViewerRun viewer, PrintStream err)
            throws InterruptedException {
        if (!joined.await(READY_SECONDS, TimeUnit.SECONDS)) {
            err.println("orchard demo: not every agent joined within " + READY_SECONDS + " s"
                    + (team.failures().isEmpty() ? "" : ": " + String.join("; ", team.failures())));
        }
        if (!viewer.awaitShowing(READY_SECONDS, TimeUnit.SECONDS)) {
            err.println("orchard demo: the viewer shows nothing after " + READY_SECONDS
                    + " s, or has ended; the game starts without it");
        }
    }

    /** Waits for the end of the game; closing the viewer's window ends it early. */
    private List<Score> awaitGameOver(WorldServer server, ViewerRun viewer) throws InterruptedException, IOException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos((long) (timeLimit * 2) + READY_SECONDS);
        while (System.nanoTime() < deadline) {
            try {
                return server.gameOver().get(200, TimeUnit.MILLISECONDS);
            } catch (TimeoutException e) {
                if (viewer instanceof WindowedViewer windowed && windowed.ended()) {
                    server.endGame("the viewer was closed");
                }
            } catch (ExecutionException e) {
                throw new IOException("the game failed: " + e.getCause().getMessage(), e.getCause());
            }
        }
        server.endGame("the demo ran out of time");
        try {
            return server.gameOver().get(10, TimeUnit.SECONDS);
        } catch (ExecutionException | TimeoutException e) {
            throw new IOException("the game did not end", e);
        }
    }

    /** Waits for the headless viewer's last screenshot and reports what it wrote. */
    private int finishHeadless(ViewerRun viewer, PrintStream out, PrintStream err) throws InterruptedException,
            IOException {
        Integer exit = viewer.awaitExit(VIEWER_END_SECONDS, TimeUnit.SECONDS);
        long written;
        try (Stream<Path> files = Files.list(shots())) {
            written = files.filter(file -> file.getFileName().toString().endsWith(".png")).count();
        }
        out.println(written + " screenshot" + (written == 1 ? "" : "s") + " in " + shots().toAbsolutePath());
        if (exit == null || exit != 0 || written == 0) {
            err.println("orchard demo: the headless viewer " + (exit == null ? "did not end within "
                    + VIEWER_END_SECONDS + " s of the game's end" : exit != 0 ? "failed with status " + exit
                    + " (its output is above, after 'viewer:')" : "wrote no screenshot"));
            return 1;
        }
        return 0;
    }

    private static String format(double seconds) {
        return seconds == Math.rint(seconds) ? String.valueOf((long) seconds) : String.valueOf(seconds);
    }
}
