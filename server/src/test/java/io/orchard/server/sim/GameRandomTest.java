package io.orchard.server.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class GameRandomTest {

    @ParameterizedTest
    @ValueSource(longs = {0, 1, 1998, -7, Long.MAX_VALUE})
    void drawsExactlyWhatRandomDrawsForTheSameSeed(long seed) {
        Random plain = new Random(seed);
        GameRandom game = new GameRandom(seed);
        for (int i = 0; i < 1000; i++) {
            assertThat(game.nextDouble()).isEqualTo(plain.nextDouble());
            assertThat(game.nextInt(17)).isEqualTo(plain.nextInt(17));
            assertThat(game.nextLong()).isEqualTo(plain.nextLong());
            assertThat(game.nextBoolean()).isEqualTo(plain.nextBoolean());
        }
    }

    @Test
    void aRestoredStateContinuesTheSequence() {
        GameRandom original = new GameRandom(42);
        for (int i = 0; i < 100; i++) {
            original.nextDouble();
        }
        GameRandom restored = new GameRandom(0);
        restored.restore(original.state());
        for (int i = 0; i < 100; i++) {
            assertThat(restored.nextDouble()).isEqualTo(original.nextDouble());
        }
    }
}
