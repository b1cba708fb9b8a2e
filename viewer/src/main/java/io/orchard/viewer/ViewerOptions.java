package io.orchard.viewer;

import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.state.Shot;
import java.nio.file.Path;
import java.util.List;

/**
 * What the viewer is to do, as its command line says once checked as a whole (see
 * {@code ViewerCommand}): every value in range and every combination meaningful.
 *
 * @param host     the server's host
 * @param port     the server's port
 * @param token    the server's shared secret, or null
 * @param operatorToken the server's operator token, which lets the viewer start, pause and continue
 *                 the game, or null
 * @param replay   a recording to play instead of connecting, or null
 * @param speed    replay speed: simulated seconds per second
 * @param headless render off screen and exit when done
 * @param width    frame width in pixels
 * @param height   frame height in pixels
 * @param shots    screenshots at given times
 * @param every    seconds between periodic screenshots, or null
 * @param out      folder of periodic screenshots, or null
 * @param until    last time of periodic screenshots, or null for the end
 * @param camera   where a headless camera stands, or null
 * @param lookAt   what a headless camera looks at, or null
 * @param follow   an agent to select and follow, or null
 * @param hud      whether the panels of text are drawn
 * @param shadows  whether shadows are drawn
 * @param timeout  seconds after which a headless run is stopped as failed
 * @param measure  seconds of frame-rate measure, or null
 * @param reconnect whether a windowed viewer connects again when its connection ends (a headless
 *                 run never does: it fails)
 */
public record ViewerOptions(String host, int port, String token, String operatorToken, Path replay, double speed,
                            boolean headless, int width, int height, List<Shot> shots, Double every, Path out,
                            Double until, Vec3 camera, Vec3 lookAt, String follow, boolean hud, boolean shadows,
                            double timeout, Double measure, boolean reconnect) {

    /** The port the viewer connects to unless told otherwise (the server's default). */
    public static final int DEFAULT_PORT = 7557;

    /** The headless watchdog's base time in seconds, before the time the viewer must wait for a live game. */
    public static final double BASE_TIMEOUT = 60;

    /** Keeps its own copy of the screenshots asked for, so the options cannot change afterwards. */
    public ViewerOptions {
        shots = List.copyOf(shots);
    }

    /** Whether screenshots are to be taken. */
    public boolean shooting() {
        return !shots.isEmpty() || every != null;
    }
}
