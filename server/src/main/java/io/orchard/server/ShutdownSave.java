package io.orchard.server;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * What the server's process does when it is asked to end (SIGTERM, Ctrl-C): it saves the game a last
 * time when it has a checkpoint file, then closes the server, which waits for the checkpoint being
 * written. Without it the JVM would end in the middle of a write, leaving the temporary file of the
 * write beside the checkpoint, and a saved game older than the last tick. A kill that cannot be
 * caught (SIGKILL, a crash) still leaves such a file; the next start removes it.
 *
 * <p>Closing this removes the hook, for a server that ends by itself.
 */
final class ShutdownSave implements AutoCloseable {

    /** How long the last save may take before the process ends without it. */
    private static final long SAVE_SECONDS = 10;

    private final Thread hook;

    private ShutdownSave(Thread hook) {
        this.hook = hook;
    }

    /** Saves {@code server}'s game (when {@code save}) and closes it when the process is asked to end. */
    static ShutdownSave install(WorldServer server, boolean save, PrintStream out) {
        Thread hook = new Thread(() -> {
            if (save && !server.closed()) {
                lastSave(server, out);
            }
            server.close();
        }, "orchard-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        return new ShutdownSave(hook);
    }

    private static void lastSave(WorldServer server, PrintStream out) {
        try {
            Path file = server.checkpoint().get(SAVE_SECONDS, TimeUnit.SECONDS);
            out.println("asked to end: the game is saved to " + file);
        } catch (ExecutionException e) {
            out.println("asked to end: the game could not be saved: " + e.getCause().getMessage());
        } catch (TimeoutException e) {
            out.println("asked to end: the game was not saved within " + SAVE_SECONDS + " s");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public void close() {
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException e) {
            // The process is ending already: the hook runs, and closes the server once.
        }
    }
}
