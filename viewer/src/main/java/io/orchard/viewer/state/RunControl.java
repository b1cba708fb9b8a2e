package io.orchard.viewer.state;

/**
 * How app states end a run: a headless run finishes when its screenshots or measures are done and
 * fails when it cannot do them; a windowed run only reports. Safe to call from any thread.
 */
public interface RunControl {

    /** Whether the viewer renders off screen and ends by itself. */
    boolean headless();

    /** The run did what it was asked; the viewer exits with status 0. */
    void finished(String summary);

    /** The run cannot go on; the viewer exits with status 1 after printing {@code reason}. */
    void failed(String reason);

    /** A line of output for the person who started the viewer (files written, measures). */
    void report(String line);
}
