package io.orchard.examples.demo;

import io.orchard.viewer.ViewerMain;
import java.io.PrintStream;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * The viewer in a window, run by {@link ViewerMain} in this JVM on a thread of its own, as the
 * game's operator; it ends when its window is closed.
 */
final class WindowedViewer implements ViewerRun {

    /** How long a window takes to open, at most, before the game starts without waiting for it. */
    private static final long OPENING_MILLIS = 3000;

    private final CompletableFuture<Integer> exit = new CompletableFuture<>();
    private final long started = System.nanoTime();

    private WindowedViewer() {}

    /** Opens the window on the server at {@code port}, with the server's operator token. */
    static WindowedViewer start(int port, String operatorToken, PrintStream out, PrintStream err) {
        WindowedViewer viewer = new WindowedViewer();
        Thread thread = new Thread(() -> {
            try {
                // In this JVM, so the token is on no command line that ps could show.
                viewer.exit.complete(ViewerMain.run(List.of("--host", "127.0.0.1", "--port", String.valueOf(port),
                        "--operator-token", operatorToken), out, err));
            } catch (RuntimeException | Error e) {
                viewer.exit.completeExceptionally(e);
            }
        }, "orchard-demo-viewer");
        thread.setDaemon(true);
        thread.start();
        return viewer;
    }

    @Override
    public boolean awaitShowing(long timeout, TimeUnit unit) throws InterruptedException {
        // The viewer does not report when its window is up: give it the time a window takes.
        long left = OPENING_MILLIS - (System.nanoTime() - started) / 1_000_000;
        if (left > 0) {
            Thread.sleep(Math.min(left, unit.toMillis(timeout)));
        }
        return !exit.isDone();
    }

    @Override
    public Integer awaitExit(long timeout, TimeUnit unit) throws InterruptedException {
        try {
            return exit.get(timeout, unit);
        } catch (TimeoutException e) {
            return null;
        } catch (ExecutionException e) {
            return 1;
        }
    }

    /** Whether the window was closed (or failed to open). */
    boolean ended() {
        return exit.isDone();
    }

    @Override
    public void stop() {
        // The window belongs to the person watching: the JVM's exit closes it.
    }
}
