package io.orchard.viewer;

import org.slf4j.bridge.SLF4JBridgeHandler;

/**
 * Sends java.util.logging, which jMonkeyEngine logs to, into SLF4J, so that the viewer has one
 * log: jME's warnings (an asset without a loader, a driver problem) appear among the viewer's own
 * lines, under the same configuration, instead of on standard error in JUL's format. JUL's own
 * handlers are taken off its root logger, so nothing is printed twice.
 */
final class JulToSlf4j {

    private JulToSlf4j() {
    }

    /** Installs the bridge in this JVM; once installed, later calls change nothing. */
    static synchronized void install() {
        if (!SLF4JBridgeHandler.isInstalled()) {
            SLF4JBridgeHandler.removeHandlersForRootLogger();
            SLF4JBridgeHandler.install();
        }
    }
}
