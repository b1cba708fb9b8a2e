package io.orchard.viewer;

import static org.assertj.core.api.Assertions.assertThat;

import ch.qos.logback.classic.Level;
import ch.qos.logback.classic.spi.ILoggingEvent;
import ch.qos.logback.core.read.ListAppender;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.logging.ConsoleHandler;
import java.util.logging.Handler;
import java.util.logging.Logger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.slf4j.LoggerFactory;
import org.slf4j.bridge.SLF4JBridgeHandler;

/**
 * jME's java.util.logging ends in the SLF4J log. Each test starts from JUL as a JVM starts: a
 * console handler on its root logger, here printing to a captured standard error, and no bridge.
 * The logback logger {@code com.jme3} gets a list appender, and only that, for the test.
 */
class JulToSlf4jTest {

    private final Logger julRoot = Logger.getLogger("");
    private final ch.qos.logback.classic.Logger jme =
            (ch.qos.logback.classic.Logger) LoggerFactory.getLogger("com.jme3");
    private final ListAppender<ILoggingEvent> slf4jLog = new ListAppender<>();
    private final ByteArrayOutputStream stderr = new ByteArrayOutputStream();
    private Handler[] julHandlers;
    private PrintStream realStderr;
    private boolean jmeAdditive;

    @BeforeEach
    void startFromJulsDefaults() {
        julHandlers = julRoot.getHandlers();
        SLF4JBridgeHandler.uninstall();
        for (Handler handler : julRoot.getHandlers()) {
            julRoot.removeHandler(handler);
        }
        realStderr = System.err;
        System.setErr(new PrintStream(stderr, true, StandardCharsets.UTF_8));
        julRoot.addHandler(new ConsoleHandler()); // prints to System.err as it is now
        slf4jLog.start();
        jme.addAppender(slf4jLog);
        jmeAdditive = jme.isAdditive();
        jme.setAdditive(false);
    }

    @AfterEach
    void restore() {
        jme.detachAppender(slf4jLog);
        jme.setAdditive(jmeAdditive);
        System.setErr(realStderr);
        for (Handler handler : julRoot.getHandlers()) {
            julRoot.removeHandler(handler);
        }
        for (Handler handler : julHandlers) {
            julRoot.addHandler(handler);
        }
    }

    @Test
    void withoutTheBridgeAJmeWarningGoesToStandardErrorOnly() {
        Logger.getLogger("com.jme3.asset.AssetConfig").warning("no loader for 'guppy.xyz'");

        assertThat(stderr.toString(StandardCharsets.UTF_8)).contains("no loader for 'guppy.xyz'");
        assertThat(slf4jLog.list).isEmpty();
    }

    @Test
    void aJmeWarningEndsInTheSlf4jLogAndNotOnStandardError() {
        JulToSlf4j.install();

        Logger.getLogger("com.jme3.asset.AssetConfig").warning("no loader for 'guppy.xyz'");

        assertThat(slf4jLog.list).singleElement().satisfies(event -> {
            assertThat(event.getLoggerName()).isEqualTo("com.jme3.asset.AssetConfig");
            assertThat(event.getLevel()).isEqualTo(Level.WARN);
            assertThat(event.getFormattedMessage()).isEqualTo("no loader for 'guppy.xyz'");
        });
        assertThat(stderr.toString(StandardCharsets.UTF_8)).doesNotContain("guppy.xyz");
    }

    @Test
    void installingTwiceLeavesOneBridgeAndNoOtherHandler() {
        JulToSlf4j.install();
        JulToSlf4j.install();

        assertThat(julRoot.getHandlers()).singleElement().isInstanceOf(SLF4JBridgeHandler.class);
    }
}
