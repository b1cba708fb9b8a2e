package io.orchard.viewer.state;

import java.nio.file.Path;
import java.util.Objects;

/**
 * One screenshot to take: the frame showing simulated time {@code time}, written to {@code file}
 * as a PNG.
 *
 * @param time simulated seconds, zero or more
 * @param file the PNG to write
 */
public record Shot(double time, Path file) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Shot {
        if (!(time >= 0) || Double.isInfinite(time)) {
            throw new IllegalArgumentException("a screenshot's time must be zero or more seconds, was " + time);
        }
        Objects.requireNonNull(file, "file");
    }
}
