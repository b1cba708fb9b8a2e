package io.orchard.viewer.model.gltf;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import com.jme3.anim.Joint;
import com.jme3.anim.SkinningControl;
import com.jme3.math.FastMath;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.viewer.model.BodyModel;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.SkinnedFigure;
import io.orchard.viewer.model.TestModels;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The real names of a skinned figure's joints and clips, and the index names of its unnamed ones
 * ({@code node#2}, {@code clip#1}), as .gltf and as .glb: listed, posed and played by them.
 */
class GltfNamesTest {

    static Stream<Arguments> figure() {
        return Stream.of(Arguments.of(ModelFormat.GLTF, SkinnedFigure.embedded()),
                Arguments.of(ModelFormat.GLB, SkinnedFigure.glb()));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("figure")
    void namedPartsKeepTheirNamesAndUnnamedOnesAreNamedByTheirIndex(ModelFormat format, byte[] bytes)
            throws ModelException {
        BodyModel figure = TestModels.load("Figure", format, bytes);

        assertThat(figure.animationNames()).containsExactlyInAnyOrder(SkinnedFigure.WAVE, "clip#1");
        assertThat(figure.jointNames()).contains(SkinnedFigure.HIPS, "node#2", "Flag", "Body")
                .noneMatch(name -> name.startsWith("Joint_") || name.startsWith("anim_"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("figure")
    void theNamedClipTurnsTheUnnamedSkeletonJoint(ModelFormat format, byte[] bytes) throws ModelException {
        BodyModel figure = TestModels.load("Figure", format, bytes);
        figure.update(0);

        figure.startAnimation(SkinnedFigure.WAVE, true);
        figure.update(0.5);

        assertThat(joint(figure, "node#2").getLocalRotation().toAngleAxis(null)).isCloseTo(FastMath.HALF_PI,
                within(1e-3f));
        assertThat(joint(figure, SkinnedFigure.HIPS).getLocalRotation().toAngleAxis(null)).isCloseTo(0f,
                within(1e-3f));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("figure")
    void theUnnamedClipPlaysByItsIndexName(ModelFormat format, byte[] bytes) throws ModelException {
        BodyModel figure = TestModels.load("Figure", format, bytes);
        figure.update(0);

        figure.startAnimation("clip#1", false);
        figure.update(0.5);

        assertThat(TestModels.find(figure.root(), "Flag").getLocalTranslation().y).isCloseTo(2.0f, within(1e-3f));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("figure")
    void anUnknownClipIsRefusedNamingThoseTheModelHas(ModelFormat format, byte[] bytes) throws ModelException {
        BodyModel figure = TestModels.load("Figure", format, bytes);

        assertThatThrownBy(() -> figure.startAnimation("anim_0", true)).isInstanceOf(ModelException.class)
                .hasMessageContaining("anim_0").hasMessageContaining("clip#1").hasMessageContaining(SkinnedFigure.WAVE);
    }

    private static Joint joint(BodyModel model, String name) {
        List<Joint> found = new ArrayList<>();
        model.root().depthFirstTraversal(spatial -> {
            SkinningControl skinning = spatial.getControl(SkinningControl.class);
            if (skinning != null) {
                found.add(skinning.getArmature().getJoint(name));
            }
        });
        assertThat(found).as("skeleton joint %s", name).singleElement().isNotNull();
        return found.get(0);
    }
}
