package io.orchard.viewer.state;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import io.orchard.protocol.message.InstructionMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.viewer.live.Backoff;
import io.orchard.viewer.live.GameControls;
import io.orchard.viewer.live.ServerLink;
import io.orchard.viewer.world.LogLine;
import io.orchard.viewer.world.WorldMirror;
import java.io.IOException;
import java.time.Duration;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;

/**
 * The connection to a live server, as a viewer ({@code Role.VIEWER}), and the clock that follows
 * it. The link's reader thread hands each message to the render thread, which applies it to the
 * {@link WorldMirror}. Between two ticks the clock runs on with the wall clock for at most one
 * tick, so that walks are drawn smoothly without ever running ahead of the server.
 *
 * <p>When the connection ends, the viewer says why in its log, on the status line and among the
 * panel's news; a windowed viewer then connects again with a growing wait ({@link ServerLink}),
 * and shows the game anew from the server's snapshot. A headless run fails instead.
 *
 * <p>It also sends what a person types for an agent as an {@code Instruction}, and the operator's
 * start, pause and continue ({@link GameControls}).
 */
public final class LiveState extends BaseAppState implements SimClock {

    private final String host;
    private final int port;
    private final String token;
    private final String operatorToken;
    private final Backoff backoff;
    private final WorldMirror mirror;
    private final RunControl control;
    private final ExecutorService io = Executors.newSingleThreadExecutor(r -> {
        Thread thread = new Thread(r, "orchard-viewer-send");
        thread.setDaemon(true);
        return thread;
    });
    private ServerLink link;
    private GameControls controls;
    private double tickPeriod = 0.05;
    private double tickTime = Double.NaN;
    private long tickWall;
    private double shown;
    private String status = "connecting";
    private boolean connectedBefore;
    /** The last reason told among the news, so that attempts failing alike are told once. */
    private String toldReason;
    private boolean closed;

    /**
     * A connection to the server at {@code host}:{@code port} that keeps {@code mirror} up to date
     * and reports its end to {@code control}.
     *
     * @param token         the server's token, or null when it needs none
     * @param operatorToken the server's operator token, or null: then the game's controls only say
     *                      whose they are
     * @param backoff       the waits before connecting again after the connection ends, or null
     *                      never to connect again (a headless run always fails instead)
     */
    public LiveState(String host, int port, String token, String operatorToken, Backoff backoff, WorldMirror mirror,
                     RunControl control) {
        this.host = host;
        this.port = port;
        this.token = token;
        this.operatorToken = operatorToken;
        this.backoff = control.headless() ? null : backoff;
        this.mirror = mirror;
        this.control = control;
    }

    @Override
    protected void initialize(Application app) {
        status = "connecting to " + host + ":" + port;
        link = new ServerLink(host, port, token, operatorToken, backoff, new ServerLink.Listener() {
            @Override
            public void connected() {
                app.enqueue(LiveState.this::connected);
            }

            @Override
            public void welcomed(WelcomeMessage welcome) {
                app.enqueue(() -> {
                    tickPeriod = 1.0 / welcome.tickRate();
                    status = "live " + host + ":" + port + " (" + welcome.clock().name().toLowerCase(Locale.ROOT)
                            + ", server " + welcome.serverVersion() + (operatorToken != null ? ", operator" : "")
                            + ")";
                });
            }

            @Override
            public void received(ServerMessage message) {
                app.enqueue(() -> receive(message));
            }

            @Override
            public void ended(String reason, Duration retryIn) {
                app.enqueue(() -> lost(reason, retryIn));
            }
        });
        controls = new GameControls(link, operatorToken != null, new GameControls.Notes() {
            @Override
            public void event(String text) {
                app.enqueue(() -> mirror.note(LogLine.Kind.EVENT, text));
            }

            @Override
            public void problem(String text) {
                app.enqueue(() -> mirror.note(LogLine.Kind.PROBLEM, text));
            }
        });
        link.start();
    }

    /** A new connection: after a lost one, the game is shown anew from the snapshot that follows. */
    private void connected() {
        if (connectedBefore) {
            mirror.restart();
            tickTime = Double.NaN;
            shown = 0;
            mirror.note(LogLine.Kind.EVENT, "connected again to " + host + ":" + port);
        }
        toldReason = null;
        connectedBefore = true;
    }

    private void receive(ServerMessage message) {
        if (message instanceof TickMessage tick) {
            tickTime = tick.time();
            tickWall = System.nanoTime();
            controls.ticked();
        }
        mirror.apply(message);
    }

    private void lost(String reason, Duration retryIn) {
        if (closed) {
            return;
        }
        status = retryIn == null ? reason : reason + "; connecting again in " + ServerLink.seconds(retryIn);
        if (!reason.equals(toldReason)) {
            mirror.note(LogLine.Kind.PROBLEM, reason);
            toldReason = reason;
        }
        tickTime = Double.NaN;
        // After the game's end a server may well go away: the screenshots then show the final state.
        if (control.headless() && (!connectedBefore || mirror.gameOver().isEmpty())) {
            // Ignored when the run has already finished: the first outcome stands.
            control.failed(connectedBefore ? reason + " before the viewer was done" : reason);
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
        return link != null && link.isConnected();
    }

    /** Pauses the game, or continues it: the operator's; anyone else is told whose it is. */
    public void togglePause() {
        controls.togglePause();
    }

    /** Starts the game without waiting for more agents: the operator's; anyone else is told whose it is. */
    public void startGame() {
        controls.start();
    }

    /**
     * Sends an instruction to the agent's controller, on a background thread; a failure is logged
     * for people to see.
     */
    public void sendInstruction(String agent, String text) {
        if (!isConnected()) {
            mirror.note(LogLine.Kind.PROBLEM, "not connected: the instruction for " + agent + " was not sent");
            return;
        }
        mirror.note(LogLine.Kind.EVENT, "you to " + agent + ": " + text);
        Application app = getApplication();
        io.execute(() -> {
            try {
                link.send(seq -> new InstructionMessage(seq, agent, text, "viewer"));
            } catch (IOException | RuntimeException e) {
                app.enqueue(() -> mirror.note(LogLine.Kind.PROBLEM, "instruction for " + agent + " not sent: "
                        + e.getMessage()));
            }
        });
    }

    @Override
    protected void cleanup(Application app) {
        closed = true;
        if (link != null) {
            link.close();
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
