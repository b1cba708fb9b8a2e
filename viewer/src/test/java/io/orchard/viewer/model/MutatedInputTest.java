package io.orchard.viewer.model;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.ModelFormat;
import java.util.Arrays;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.stream.IntStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Valid models with a few random bytes changed, inserted or removed, with fixed seeds: each
 * either loads or is refused with a {@link ModelException} that reports the input, never an
 * internal failure.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class MutatedInputTest {

    private static final int MUTANTS = 150;
    private static final String REPLACEMENTS = "0123456789 -.,[]{}\"'<>/=#eE\nxyzNaN";

    static Stream<Arguments> mutants() {
        return Stream.of(
                Arguments.of(ModelFormat.VRML97, TestModels.vrml(Figure5Test.FIGURE_5_VRML)),
                Arguments.of(ModelFormat.X3D, TestModels.x3d(Figure5Test.FIGURE_5_X3D)),
                Arguments.of(ModelFormat.GLTF, TestModels.resource("walker.gltf")),
                Arguments.of(ModelFormat.GLB, TestModels.walkerGlb()))
                .flatMap(a -> IntStream.range(0, MUTANTS).mapToObj(seed -> Arguments.of(
                        a.get()[0], seed, mutate((byte[]) a.get()[1], seed))));
    }

    @ParameterizedTest(name = "{0} seed {1}")
    @MethodSource("mutants")
    void mutatedModelLoadsOrIsRefusedCleanly(ModelFormat format, int seed, byte[] bytes) {
        try {
            BodyModel model = TestModels.load("Guppy", format, bytes);
            model.update(0);
            model.update(1);
        } catch (ModelException e) {
            assertThat(e.getMessage()).isNotBlank();
            if (format == ModelFormat.VRML97 || format == ModelFormat.X3D) {
                assertThat(e.getMessage()).as("an internal failure, not a report on the input")
                        .doesNotContain("could not be built");
            }
        }
    }

    private static byte[] mutate(byte[] original, int seed) {
        Random random = new Random(seed);
        byte[] bytes = original.clone();
        int edits = 1 + random.nextInt(4);
        for (int i = 0; i < edits; i++) {
            int at = random.nextInt(bytes.length);
            switch (random.nextInt(3)) {
                case 0 -> bytes[at] = (byte) REPLACEMENTS.charAt(
                        random.nextInt(REPLACEMENTS.length()));
                case 1 -> bytes = delete(bytes, at, 1 + random.nextInt(8));
                default -> bytes = duplicate(bytes, at, 1 + random.nextInt(16));
            }
        }
        return bytes;
    }

    private static byte[] delete(byte[] bytes, int at, int length) {
        int end = Math.min(bytes.length, at + length);
        byte[] result = Arrays.copyOf(bytes, bytes.length - (end - at));
        System.arraycopy(bytes, end, result, at, bytes.length - end);
        return result;
    }

    private static byte[] duplicate(byte[] bytes, int at, int length) {
        int end = Math.min(bytes.length, at + length);
        byte[] result = new byte[bytes.length + (end - at)];
        System.arraycopy(bytes, 0, result, 0, end);
        System.arraycopy(bytes, at, result, end, bytes.length - at);
        return result;
    }
}
