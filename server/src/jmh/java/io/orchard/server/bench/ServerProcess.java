package io.orchard.server.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * The server in a JVM of its own ({@link LoadServer}), started with this JVM's class path, pinned to
 * the given cores with {@code taskset} when there are any. Its figures cover the whole process.
 */
final class ServerProcess implements ServerUnderLoad {

    /** Told when each tick of the server starts. */
    @FunctionalInterface
    interface Ticks {
        void started(long tick, long nanoTime);
    }

    private static final String JAVA = java.nio.file.Path.of(System.getProperty("java.home"), "bin", "java").toString();

    private final Process process;
    private final OutputStream commands;
    private final BlockingQueue<String> answers = new ArrayBlockingQueue<>(16);
    private final int port;

    /**
     * @param jvm    the server JVM's options
     * @param cpus   the cores to pin it to, as {@code taskset -c} takes them; empty for none
     * @param ticks  told the number and start ({@code System.nanoTime}) of every tick
     */
    ServerProcess(List<String> jvm, String cpus, long seed, int tickRate, int agents, int connections,
                  Ticks ticks) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>();
        if (!cpus.isEmpty()) {
            command.addAll(List.of("taskset", "-c", cpus));
        }
        command.add(JAVA);
        command.addAll(jvm);
        command.addAll(List.of("-cp", System.getProperty("java.class.path"), LoadServer.class.getName(),
                Long.toString(seed), Integer.toString(tickRate), Integer.toString(agents), Integer.toString(connections)));
        process = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.INHERIT).start();
        commands = process.getOutputStream();
        Thread reader = new Thread(() -> read(ticks), "server-process-out");
        reader.setDaemon(true);
        reader.start();
        String first = answers.poll(120, TimeUnit.SECONDS);
        if (first == null || !first.startsWith("@port ")) {
            process.destroyForcibly();
            throw new IOException("the server process did not say its port within 2 minutes: " + command);
        }
        port = Integer.parseInt(first.substring("@port ".length()));
    }

    private void read(Ticks ticks) {
        try (BufferedReader out = new BufferedReader(new InputStreamReader(process.getInputStream(),
                StandardCharsets.UTF_8))) {
            String line;
            while ((line = out.readLine()) != null) {
                if (line.startsWith("@tick ")) {
                    String[] parts = line.split(" ");
                    ticks.started(Long.parseLong(parts[1]), Long.parseLong(parts[2]));
                } else if (line.startsWith("@")) {
                    answers.put(line);
                } else {
                    System.out.println("server: " + line);
                }
            }
        } catch (IOException | InterruptedException e) {
            // the process ended
        }
    }

    @Override
    public int port() {
        return port;
    }

    @Override
    public void startWindow() {
        command("window");
    }

    @Override
    public ServerFigures endWindow() {
        command("figures");
        try {
            String answer = answers.poll(30, TimeUnit.SECONDS);
            if (answer == null || !answer.startsWith("@figures ")) {
                throw new IllegalStateException("the server process gave no figures within 30 s, said: " + answer);
            }
            return ServerFigures.parse(answer.substring("@figures ".length()));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted waiting for the server's figures", e);
        }
    }

    private void command(String line) {
        try {
            commands.write((line + "\n").getBytes(StandardCharsets.UTF_8));
            commands.flush();
        } catch (IOException e) {
            throw new IllegalStateException("the server process is gone: " + e.getMessage(), e);
        }
    }

    @Override
    public void close() throws InterruptedException {
        try {
            commands.close();
        } catch (IOException ignored) {
            // it has gone already
        }
        if (!process.waitFor(20, TimeUnit.SECONDS)) {
            process.destroyForcibly();
        }
    }
}
