package io.orchard.viewer;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Runs the viewer as a child JVM under {@code xvfb-run}, as CI and people run it headless: a
 * virtual X display with Mesa's software OpenGL. The tests need no display of their own.
 */
final class ViewerProcess {

    /**
     * What a run did.
     *
     * @param exit   the exit status
     * @param output standard output and error, interleaved
     */
    record Result(int exit, String output) {
    }

    private static final long LIMIT_SECONDS = 90;

    private ViewerProcess() {
    }

    /**
     * The path of {@code xvfb-run}.
     *
     * @throws AssertionError saying to install xvfb when it (or Xvfb, or xauth) is missing
     */
    static Path xvfbRun() {
        Path run = onPath("xvfb-run");
        if (run == null || onPath("Xvfb") == null || onPath("xauth") == null) {
            throw new AssertionError("the viewer's screenshot tests render under a virtual X display: install xvfb "
                    + "and xauth (Debian/Ubuntu: apt-get install xvfb xauth; .ci/run does this); xvfb-run "
                    + (run == null ? "is" : "is there but Xvfb or xauth is") + " missing from PATH "
                    + System.getenv("PATH"));
        }
        return run;
    }

    /** Runs {@code ViewerMain} with these arguments in {@code dir} and waits for it, at most 90 s. */
    static Result run(Path dir, String... args) throws IOException, InterruptedException {
        return run(dir, true, args);
    }

    /** {@link #run(Path, String...)}, with {@code XDG_RUNTIME_DIR} set to a folder of its own or not at all. */
    static Result run(Path dir, boolean runtimeDir, String... args) throws IOException, InterruptedException {
        // xvfb-run answers with its own status when it fails to clean up after the viewer (5, on a busy
        // machine now and then): the viewer's own status is kept in a file and read from there.
        Path status = Files.createTempFile(dir, "viewer-exit", ".txt");
        List<String> command = new ArrayList<>(List.of(xvfbRun().toString(), "-a", "-s", "-screen 0 1280x720x24",
                "sh", "-c", "\"$@\"; s=$?; echo $s > \"$0\"; exit $s", status.toString(),
                Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx512m",
                "-cp", classPath(), ViewerMain.class.getName()));
        command.addAll(List.of(args));
        ProcessBuilder builder = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true);
        builder.environment().remove("DISPLAY");
        builder.environment().remove("XDG_RUNTIME_DIR");
        if (runtimeDir) {
            Path runtime = Files.createDirectories(dir.resolve("xdg-runtime"));
            runtime.toFile().setExecutable(true, true);
            builder.environment().put("XDG_RUNTIME_DIR", runtime.toString());
        }
        Process process = builder.start();
        ByteArrayOutputStream output = new ByteArrayOutputStream();
        Thread reader = new Thread(() -> copy(process.getInputStream(), output), "viewer-output");
        reader.start();
        if (!process.waitFor(LIMIT_SECONDS, TimeUnit.SECONDS)) {
            process.descendants().forEach(ProcessHandle::destroyForcibly);
            process.destroyForcibly();
            reader.join(5000);
            throw new AssertionError("the viewer did not end within " + LIMIT_SECONDS + " s; its output:\n"
                    + output.toString(StandardCharsets.UTF_8));
        }
        reader.join(5000);
        String saved = Files.readString(status).strip();
        return new Result(saved.isEmpty() ? process.exitValue() : Integer.parseInt(saved),
                output.toString(StandardCharsets.UTF_8));
    }

    private static String classPath() {
        // Surefire starts tests with a manifest-only jar; it tells the real class path here.
        String surefire = System.getProperty("surefire.test.class.path");
        return surefire != null && !surefire.isBlank() ? surefire : System.getProperty("java.class.path");
    }

    private static void copy(InputStream in, ByteArrayOutputStream out) {
        try (in) {
            in.transferTo(out);
        } catch (IOException e) {
            // the process ended; what was read is kept
        }
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
