package io.orchard.cli;

/** The port of a server to connect to: 1 to 65535. */
public final class Port extends Whole {

    /** A port from 1 to 65535. */
    public Port() {
        super(1, 65535, "a port 1-65535");
    }
}
