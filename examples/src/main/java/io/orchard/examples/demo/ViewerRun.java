package io.orchard.examples.demo;

import java.util.concurrent.TimeUnit;

/** A viewer the demo started: in a window in this JVM, or headless in a child JVM. */
interface ViewerRun {

    /** Waits until the viewer shows the world; false when the time ran out or the viewer ended first. */
    boolean awaitShowing(long timeout, TimeUnit unit) throws InterruptedException;

    /** Waits for the viewer to end and returns its exit status, or null when the time ran out first. */
    Integer awaitExit(long timeout, TimeUnit unit) throws InterruptedException;

    /** Ends the viewer if it still runs. */
    void stop();
}
