package io.orchard.viewer.model.gltf;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import com.jme3.math.FastMath;
import com.jme3.math.Quaternion;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.viewer.model.BodyModel;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelFormats;
import io.orchard.viewer.model.TestModels;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * glTF through jME's loader from bytes in memory: {@code walker.gltf} is a hand-written model
 * (a node Walker with two legs, LeftKnee and RightKnee, sharing a one-triangle mesh, and a clip
 * Walk that raises LeftKnee by 0.5 over one second), loaded as .gltf and, repacked, as .glb.
 */
class GltfLoadingTest {

    static Stream<Arguments> walker() {
        return Stream.of(
                Arguments.of(ModelFormat.GLTF, TestModels.resource("walker.gltf")),
                Arguments.of(ModelFormat.GLB, TestModels.walkerGlb()));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("walker")
    void namedNodesAreFoundByName(ModelFormat format, byte[] bytes) throws ModelException {
        BodyModel walker = TestModels.load("Walker", format, bytes);

        assertThat(walker.hasNode("LeftKnee")).isTrue();
        assertThat(walker.hasNode("Nobody")).isFalse();
        assertThat(walker.jointNames()).contains("Walker", "LeftKnee", "RightKnee");
        Spatial knee = TestModels.find(walker.root(), "LeftKnee");
        assertThat(knee.getLocalTranslation()).isEqualTo(new Vector3f(-0.2f, 0, 0));
        assertThat(TestModels.geometries(knee)).singleElement()
                .satisfies(g -> assertThat(g.getMesh().getVertexCount()).isEqualTo(3));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("walker")
    void animationClipsAreListed(ModelFormat format, byte[] bytes) throws ModelException {
        BodyModel walker = TestModels.load("Walker", format, bytes);

        assertThat(walker.animationNames()).containsExactly("Walk");
        assertThat(walker.timeSensorNames()).isEmpty();
        assertThat(walker.format()).contains(format);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("walker")
    void startedClipAdvancesWithSimulatedTime(ModelFormat format, byte[] bytes)
            throws ModelException {
        BodyModel walker = TestModels.load("Walker", format, bytes);
        Spatial knee = TestModels.find(walker.root(), "LeftKnee");
        walker.update(10.0);

        walker.startAnimation("Walk", false);
        walker.update(10.5);

        assertThat(knee.getLocalTranslation().y).isCloseTo(0.25f, within(1e-3f));
    }

    @Test
    void stoppedClipNoLongerMovesTheNode() throws ModelException {
        BodyModel walker = TestModels.load("Walker", ModelFormat.GLTF,
                TestModels.resource("walker.gltf"));
        Spatial knee = TestModels.find(walker.root(), "LeftKnee");
        walker.update(0);
        walker.startAnimation("Walk", true);
        walker.update(0.25);
        float stoppedAt = knee.getLocalTranslation().y;

        walker.stopAnimation("Walk");
        walker.update(0.75);

        assertThat(knee.getLocalTranslation().y).isEqualTo(stoppedAt);
    }

    @Test
    void sceneUpdateAloneDoesNotAdvanceClips() throws ModelException {
        BodyModel walker = TestModels.load("Walker", ModelFormat.GLTF,
                TestModels.resource("walker.gltf"));
        Spatial knee = TestModels.find(walker.root(), "LeftKnee");
        walker.update(0);
        walker.startAnimation("Walk", true);

        walker.root().updateLogicalState(0.5f);

        assertThat(knee.getLocalTranslation().y).isEqualTo(0f);
    }

    @Test
    void moveToMovesTheNodeNamedAfterTheAgent() throws ModelException {
        BodyModel walker = TestModels.load("Walker", ModelFormat.GLTF,
                TestModels.resource("walker.gltf"));
        Spatial body = TestModels.find(walker.root(), "Walker");

        walker.moveTo(new Vector3f(0, 0, 0), new Vector3f(4, 0, 8), 1, 4);
        walker.update(3);

        assertThat(body.getLocalTranslation()).isEqualTo(new Vector3f(2, 0, 4));
        assertThat(walker.root().getLocalTranslation()).isEqualTo(Vector3f.ZERO);
    }

    @Test
    void moveToMovesTheRootWhenNoNodeIsNamedAfterTheAgent() throws ModelException {
        BodyModel other = TestModels.load("Roadrunner", ModelFormat.GLTF,
                TestModels.resource("walker.gltf"));

        other.moveTo(new Vector3f(0, 0, 0), new Vector3f(4, 0, 8), 0, 2);
        other.update(2);

        assertThat(other.root().getLocalTranslation()).isEqualTo(new Vector3f(4, 0, 8));
        assertThat(other.root().getName()).isEqualTo("Roadrunner model");
    }

    @Test
    void jointRotationTurnsTheNamedNode() throws ModelException {
        BodyModel walker = TestModels.load("Walker", ModelFormat.GLTF,
                TestModels.resource("walker.gltf"));

        walker.setJointRotation("RightKnee", Vector3f.UNIT_X, FastMath.HALF_PI);

        Quaternion expected = new Quaternion().fromAngleAxis(FastMath.HALF_PI, Vector3f.UNIT_X);
        assertThat(TestModels.find(walker.root(), "RightKnee").getLocalRotation()
                .isSimilar(expected, 1e-5f)).isTrue();
    }

    @Test
    void unknownClipIsRefusedNamingIt() throws ModelException {
        BodyModel walker = TestModels.load("Walker", ModelFormat.GLTF,
                TestModels.resource("walker.gltf"));

        assertThatThrownBy(() -> walker.startAnimation("Dance", true))
                .isInstanceOf(ModelException.class)
                .hasMessageContaining("no animation clip named 'Dance'")
                .hasMessageContaining("[Walk]");
    }

    @Test
    void meshIsAttachedBelowItsNodeUnderTheMeshName() throws ModelException {
        BodyModel walker = TestModels.load("Walker", ModelFormat.GLTF,
                TestModels.resource("walker.gltf"));

        Node knee = (Node) TestModels.find(walker.root(), "RightKnee");

        assertThat(knee.getChildren()).singleElement()
                .satisfies(mesh -> assertThat(mesh.getName()).isEqualTo("Leg"));
        assertThat(TestModels.geometries(knee)).singleElement().isInstanceOf(Geometry.class);
    }

    @Test
    void formatIsDetectedFromTheBytes() {
        assertThat(ModelFormats.detect(TestModels.resource("walker.gltf")))
                .contains(ModelFormat.GLTF);
        assertThat(ModelFormats.detect(TestModels.walkerGlb())).contains(ModelFormat.GLB);
    }

}
