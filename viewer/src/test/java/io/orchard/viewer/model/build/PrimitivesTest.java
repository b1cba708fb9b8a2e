package io.orchard.viewer.model.build;

import static org.assertj.core.api.Assertions.assertThat;

import com.jme3.scene.Mesh;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** The primitives face outwards: every triangle winds counter-clockwise seen from outside. */
class PrimitivesTest {

    static Stream<Arguments> primitives() {
        return Stream.of(
                Arguments.of("sphere", Primitives.sphere(1.5f)),
                Arguments.of("cylinder", Primitives.cylinder(0.5f, 2, true, true, true)),
                Arguments.of("cone", Primitives.cone(1, 2, true, true)),
                Arguments.of("box", Primitives.box(1, 2, 3)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("primitives")
    void trianglesFaceOutwards(String name, Mesh mesh) {
        NodeBuildingTest.assertAllTrianglesFaceTheirNormals(mesh);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("primitives")
    void primitivesAreCentredOnTheOrigin(String name, Mesh mesh) {
        mesh.updateBound();

        assertThat(mesh.getBound().getCenter().length()).isLessThan(1e-5f);
    }
}
