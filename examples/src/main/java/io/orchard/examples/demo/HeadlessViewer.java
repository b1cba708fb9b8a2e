package io.orchard.examples.demo;

import io.orchard.viewer.ViewerMain;
import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * The headless viewer, writing a screenshot every {@code every} simulated seconds into a folder, as
 * {@code ./orchard viewer --headless --every S --out DIR} does. It runs in a child JVM: without a
 * display it needs {@code xvfb-run} around it for a virtual X display, and a child also keeps a
 * stuck graphics driver out of the demo's JVM. Its lines are passed on, prefixed "viewer: ".
 */
final class HeadlessViewer implements ViewerRun {

    /** The screen xvfb-run gives the viewer, as docs/viewer.md shows it. */
    static final String SCREEN = "-screen 0 1280x720x24";

    private final Process process;
    private final CountDownLatch firstShot = new CountDownLatch(1);
    /** Where the viewer's own exit status is written under xvfb-run; null without it. */
    private final Path status;
    private final Thread pump;

    private HeadlessViewer(Process process, Path status, PrintStream out) {
        this.process = process;
        this.status = status;
        this.pump = new Thread(() -> pass(out), "orchard-demo-viewer-output");
        pump.setDaemon(true);
        pump.start();
    }

    /**
     * Starts the viewer against the server on {@code port}.
     *
     * @param xvfbRun the xvfb-run to run it under, or null when there is a display
     * @param timeout the viewer's watchdog in seconds
     */
    static HeadlessViewer start(int port, Path out, double every, Path xvfbRun, double timeout, PrintStream lines)
            throws IOException {
        List<String> command = new ArrayList<>();
        Path status = null;
        if (xvfbRun != null) {
            // xvfb-run answers with its own status when it fails to clean up after the viewer (5, on a
            // busy machine now and then): the viewer's own status is kept in a file and read from there.
            status = Files.createTempFile("orchard-viewer-exit", ".txt");
            status.toFile().deleteOnExit();
            command.addAll(List.of(xvfbRun.toString(), "-a", "-s", SCREEN, "sh", "-c",
                    "\"$@\"; s=$?; echo $s > \"$0\"; exit $s", status.toString()));
        }
        command.addAll(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx512m",
                "-cp", classPath(), ViewerMain.class.getName(), "--host", "127.0.0.1", "--port", String.valueOf(port),
                "--headless", "--every", format(every), "--out", out.toString(), "--timeout", format(timeout)));
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true);
        if (xvfbRun != null) {
            builder.environment().remove("DISPLAY"); // xvfb-run sets its own
        }
        if (System.getenv("XDG_RUNTIME_DIR") == null) {
            // Mesa complains on every frame without one.
            Path runtime = Files.createTempDirectory("orchard-xdg");
            runtime.toFile().deleteOnExit();
            builder.environment().put("XDG_RUNTIME_DIR", runtime.toString());
        }
        Process process = builder.start();
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            process.descendants().forEach(ProcessHandle::destroy);
            process.destroy();
        }, "orchard-demo-viewer-stop"));
        return new HeadlessViewer(process, status, lines);
    }

    @Override
    public boolean awaitShowing(long timeout, TimeUnit unit) throws InterruptedException {
        long deadline = System.nanoTime() + unit.toNanos(timeout);
        // A viewer that failed to start says so at once: do not wait the whole time for it.
        while (process.isAlive() && System.nanoTime() < deadline) {
            if (firstShot.await(100, TimeUnit.MILLISECONDS)) {
                return true;
            }
        }
        return firstShot.getCount() == 0;
    }

    @Override
    public Integer awaitExit(long timeout, TimeUnit unit) throws InterruptedException {
        if (!process.waitFor(timeout, unit)) {
            return null;
        }
        pump.join(2000); // its last lines
        if (status != null) {
            try {
                String saved = Files.readString(status).strip();
                if (!saved.isEmpty()) {
                    return Integer.parseInt(saved);
                }
            } catch (IOException | NumberFormatException e) {
                // fall back on what xvfb-run said
            }
        }
        return process.exitValue();
    }

    @Override
    public void stop() {
        process.descendants().forEach(ProcessHandle::destroyForcibly);
        process.destroyForcibly();
    }

    private void pass(PrintStream out) {
        try (BufferedReader in = new BufferedReader(new InputStreamReader(process.getInputStream(),
                StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                out.println("viewer: " + line);
                out.flush();
                if (line.startsWith("wrote ")) {
                    firstShot.countDown();
                }
            }
        } catch (IOException e) {
            // the viewer ended
        }
    }

    private static String classPath() {
        // Surefire runs tests from a manifest-only jar and tells the real class path here.
        String surefire = System.getProperty("surefire.test.class.path");
        return surefire != null && !surefire.isBlank() ? surefire : System.getProperty("java.class.path");
    }

    private static String format(double seconds) {
        return String.format(Locale.ROOT, "%.3f", seconds);
    }

    /** The {@code xvfb-run} on the PATH, with the Xvfb and xauth it needs; null when any is missing. */
    static Path xvfbRun() {
        Path run = onPath("xvfb-run");
        return run != null && onPath("Xvfb") != null && onPath("xauth") != null ? run : null;
    }

    private static Path onPath(String program) {
        for (String folder : System.getenv().getOrDefault("PATH", "").split(File.pathSeparator)) {
            Path candidate = Path.of(folder, program);
            if (Files.isExecutable(candidate)) {
                return candidate;
            }
        }
        return null;
    }
}
