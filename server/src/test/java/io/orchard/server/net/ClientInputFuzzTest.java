package io.orchard.server.net;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Hostile and broken input against the codec and the server's message handling ({@link
 * ServerUnderFuzz} says what is checked). Three ways to run it:
 * <ul>
 *   <li>every build: {@link #seededInputs()} runs 100 inputs from a fixed seed, and
 *       {@link #linesFromAClient} runs once on each input kept in
 *       {@code src/test/resources/io/orchard/server/net/ClientInputFuzzTestInputs/} (crashes found
 *       before stay fixed);</li>
 *   <li>in CI, a short fuzzing run ({@code fuzz} profile of the server's pom, or {@code -Pfuzz});</li>
 *   <li>a longer run by hand, as docs/security.md shows.</li>
 * </ul>
 */
class ClientInputFuzzTest {

    @FuzzTest(maxDuration = "10s")
    void linesFromAClient(FuzzedDataProvider data) {
        ServerUnderFuzz.run(FuzzSource.of(data));
    }

    @Test
    void seededInputs() {
        Random random = new Random(1998);
        for (int input = 0; input < 100; input++) {
            ServerUnderFuzz.run(FuzzSource.of(new Random(random.nextLong()), 400));
        }
    }
}
