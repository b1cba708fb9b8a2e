package io.orchard.viewer.state;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.InstructionMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.Role;
import io.orchard.viewer.world.LogLine;
import io.orchard.viewer.world.WorldMirror;
import java.io.IOException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The connection to a live server, as a viewer ({@code Role.VIEWER}), and the clock that follows
 * it. The connection's reader thread hands each message to the render thread, which applies it to
 * the {@link WorldMirror}. Between two ticks the clock runs on with the wall clock for at most one
 * tick, so that walks are drawn smoothly without ever running ahead of the server.
 *
 * <p>It also sends what a person types for an agent as an {@code Instruction}.
 */
public final class LiveState extends BaseAppState implements SimClock {

    private static final Logger LOG = LoggerFactory.getLogger(LiveState.class);

    private final String host;
    private final int port;
    private final String token;
    private final WorldMirror mirror;
    private final RunControl control;
    private final ExecutorService io = Executors.newSingleThreadExecutor(r -> {
        Thread thread = new Thread(r, "orchard-viewer-connect");
        thread.setDaemon(true);
        return thread;
    });
    private volatile ProtocolConnection connection;
    private double tickPeriod = 0.05;
    private double tickTime = Double.NaN;
    private long tickWall;
    private double shown;
    private String status = "connecting";
    private boolean closed;

    /**
     * A connection to the server at {@code host}:{@code port} (with its {@code token}, or null when it needs none)
     * that keeps {@code mirror} up to date and reports its end to {@code control}.
     */
    public LiveState(String host, int port, String token, WorldMirror mirror, RunControl control) {
        this.host = host;
        this.port = port;
        this.token = token;
        this.mirror = mirror;
        this.control = control;
    }

    @Override
    protected void initialize(Application app) {
        status = "connecting to " + host + ":" + port;
        io.execute(() -> connect(app));
    }

    private void connect(Application app) {
        try {
            ProtocolConnection opened = ProtocolConnection.connect(host, port, Role.VIEWER, "orchard-viewer", token,
                    new ProtocolConnection.Listener() {
                        @Override
                        public void onMessage(ServerMessage message) {
                            app.enqueue(() -> receive(message));
                        }

                        @Override
                        public void onClosed(Throwable cause) {
                            app.enqueue(() -> lost(cause));
                        }
                    });
            WelcomeMessage welcome = opened.welcome();
            connection = opened;
            app.enqueue(() -> {
                tickPeriod = 1.0 / welcome.tickRate();
                status = "live " + host + ":" + port + " (" + welcome.clock().name().toLowerCase(java.util.Locale.ROOT)
                        + ", server " + welcome.serverVersion() + ")";
            });
        } catch (IOException e) {
            String reason = "cannot connect to the server at " + host + ":" + port + ": " + e.getMessage();
            LOG.warn(reason);
            app.enqueue(() -> {
                status = reason;
                mirror.note(LogLine.Kind.PROBLEM, reason);
                if (control.headless()) {
                    control.failed(reason);
                }
            });
        }
    }

    private void receive(ServerMessage message) {
        if (message instanceof TickMessage tick) {
            tickTime = tick.time();
            tickWall = System.nanoTime();
        }
        mirror.apply(message);
    }

    private void lost(Throwable cause) {
        if (closed) {
            return;
        }
        closed = true;
        String reason = "the server closed the connection" + (cause == null ? "" : ": " + cause.getMessage());
        status = reason;
        mirror.note(LogLine.Kind.PROBLEM, reason);
        LOG.info(reason);
        // After the game's end a server may well go away: the screenshots then show the final state.
        if (control.headless() && mirror.gameOver().isEmpty()) {
            // Ignored when the run has already finished: the first outcome stands.
            control.failed(reason + " before the viewer was done");
        }
    }

    @Override
    public double now() {
        double time = mirror.time();
        if (!Double.isNaN(tickTime) && mirror.gameOver().isEmpty()) {
            double since = (System.nanoTime() - tickWall) / 1e9;
            time = Math.max(time, tickTime + Math.min(since, tickPeriod));
        }
        shown = Math.max(shown, time);
        return shown;
    }

    /** One line on where the viewer is connected, or why it is not. */
    public String status() {
        return status;
    }

    /** Whether the connection is open, so that instructions can be sent. */
    public boolean isConnected() {
        ProtocolConnection open = connection;
        return open != null && open.isOpen();
    }

    /**
     * Sends an instruction to the agent's controller, on a background thread; a failure is logged
     * for people to see.
     */
    public void sendInstruction(String agent, String text) {
        ProtocolConnection open = connection;
        if (open == null || !open.isOpen()) {
            mirror.note(LogLine.Kind.PROBLEM, "not connected: the instruction for " + agent + " was not sent");
            return;
        }
        mirror.note(LogLine.Kind.EVENT, "you to " + agent + ": " + text);
        Application app = getApplication();
        io.execute(() -> {
            try {
                open.send(seq -> new InstructionMessage(seq, agent, text, "viewer"));
            } catch (IOException | RuntimeException e) {
                app.enqueue(() -> mirror.note(LogLine.Kind.PROBLEM, "instruction for " + agent + " not sent: "
                        + e.getMessage()));
            }
        });
    }

    @Override
    protected void cleanup(Application app) {
        closed = true;
        ProtocolConnection open = connection;
        if (open != null) {
            open.close();
        }
        io.shutdownNow();
    }

    @Override
    protected void onEnable() {
    }

    @Override
    protected void onDisable() {
    }
}
