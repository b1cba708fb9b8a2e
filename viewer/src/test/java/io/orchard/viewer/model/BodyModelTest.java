package io.orchard.viewer.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.jme3.font.BitmapText;
import com.jme3.math.FastMath;
import com.jme3.math.Quaternion;
import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import io.orchard.protocol.value.ModelFormat;
import java.util.stream.Stream;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** The public operations the viewer maps protocol messages to. */
class BodyModelTest {

    private static final String BODY_WITHOUT_MOVER = """
            DEF Bunny Transform {
              children [
                DEF Neck Transform { translation 0 1 0 children Shape { geometry Sphere {} } }
                DEF Hop TimeSensor { cycleInterval 0.5 loop TRUE enabled FALSE }
              ]
            }
            """;

    @Test
    void bundledIsRefusedAsAFormatForItNamesAModelRatherThanEncodingOne() {
        assertThatThrownBy(() -> TestModels.load("Guppy", ModelFormat.BUNDLED,
                TestModels.vrml(BODY_WITHOUT_MOVER)))
                .isInstanceOf(ModelException.class)
                .hasMessageContaining("a bundled model is named, not sent")
                .satisfies(e -> assertThat(((ModelException) e).kind())
                        .isEqualTo(ModelException.Kind.UNSUPPORTED));
    }

    @Nested
    class Moves {

        @Test
        void modelWithoutMoverNodesMovesItsAgentTransformDirectly() throws ModelException {
            BodyModel bunny = TestModels.loadVrml("Bunny", BODY_WITHOUT_MOVER);
            Node body = (Node) TestModels.find(bunny.root(), "Bunny");

            bunny.moveTo(new Vector3f(0, 0, 0), new Vector3f(8, 0, 0), 1, 4);
            bunny.update(0);
            assertThat(body.getLocalTranslation()).isEqualTo(Vector3f.ZERO);
            bunny.update(2);

            assertThat(body.getLocalTranslation()).isEqualTo(new Vector3f(2, 0, 0));
            bunny.update(6);
            assertThat(body.getLocalTranslation()).isEqualTo(new Vector3f(8, 0, 0));
        }

        @Test
        void modelWithoutAgentTransformMovesItsRoot() throws ModelException {
            BodyModel model = TestModels.loadVrml("Stranger", BODY_WITHOUT_MOVER);

            model.moveTo(new Vector3f(1, 0, 1), new Vector3f(3, 0, 1), 0, 2);
            model.update(1);

            assertThat(model.root().getLocalTranslation()).isEqualTo(new Vector3f(2, 0, 1));
        }

        @Test
        void moverWithoutItsRouteFromTheSensorIsNotUsed() throws ModelException {
            BodyModel guppy = TestModels.loadVrml("Guppy", """
                    DEF Guppy Transform { }
                    DEF GuppyMover PositionInterpolator { key [0 1] keyValue [0 0 0, 1 0 0] }
                    DEF GuppyTSMover TimeSensor { }
                    """);

            guppy.moveTo(new Vector3f(0, 0, 0), new Vector3f(0, 0, 5), 0, 1);
            guppy.update(1);

            assertThat(TestModels.find(guppy.root(), "Guppy").getLocalTranslation())
                    .isEqualTo(new Vector3f(0, 0, 5));
        }

        static Stream<Arguments> badMoves() {
            Vector3f ok = new Vector3f(1, 2, 3);
            return Stream.of(
                    Arguments.of(new Vector3f(Float.NaN, 0, 0), ok, 0.0, 1.0, "from must be"
                            + " finite"),
                    Arguments.of(ok, new Vector3f(0, Float.POSITIVE_INFINITY, 0), 0.0, 1.0,
                            "to must be finite"),
                    Arguments.of(ok, ok, Double.NaN, 1.0, "startTime must be finite"),
                    Arguments.of(ok, ok, 0.0, -1.0, "duration must be zero or more seconds but"
                            + " is -1.0"));
        }

        @ParameterizedTest(name = "{4}")
        @MethodSource("badMoves")
        void moveWithNonFiniteOrNegativeArgumentsIsRefused(Vector3f from, Vector3f to,
                                                           double start, double duration,
                                                           String message)
                throws ModelException {
            BodyModel guppy = TestModels.loadVrml("Guppy", Figure5Test.FIGURE_5_VRML);

            assertThatThrownBy(() -> guppy.moveTo(from, to, start, duration))
                    .isInstanceOf(ModelException.class).hasMessageContaining(message);
        }
    }

    @Nested
    class Joints {

        @Test
        void jointRotationSetsTheRegisteredTransform() throws ModelException {
            BodyModel guppy = TestModels.loadVrml("Guppy", Figure5Test.FIGURE_5_VRML);

            guppy.setJointRotation("LeftKnee", new Vector3f(1, 0, 0), -FastMath.QUARTER_PI);

            Quaternion expected = new Quaternion().fromAngleAxis(-FastMath.QUARTER_PI,
                    Vector3f.UNIT_X);
            assertThat(TestModels.find(guppy.root(), "LeftKnee").getLocalRotation()
                    .isSimilar(expected, 1e-5f)).isTrue();
        }

        @Test
        void unknownJointIsRefusedNamingItAndTheKnownJoints() throws ModelException {
            BodyModel guppy = TestModels.loadVrml("Guppy", Figure5Test.FIGURE_5_VRML);

            assertThatThrownBy(() -> guppy.setJointRotation("RightElbow", Vector3f.UNIT_X, 1f))
                    .isInstanceOf(ModelException.class)
                    .hasMessageContaining("no joint (DEF'd Transform) named 'RightElbow'")
                    .hasMessageContaining("[Guppy, GuppyHead, LeftKnee]");
        }

        @Test
        void nonFiniteAngleIsRefused() throws ModelException {
            BodyModel guppy = TestModels.loadVrml("Guppy", Figure5Test.FIGURE_5_VRML);

            assertThatThrownBy(() -> guppy.setJointRotation("LeftKnee", Vector3f.UNIT_X,
                    Float.NaN)).isInstanceOf(ModelException.class)
                    .hasMessageContaining("angle must be finite");
        }

        @Test
        void zeroAxisMeansNoRotation() throws ModelException {
            BodyModel guppy = TestModels.loadVrml("Guppy", Figure5Test.FIGURE_5_VRML);

            guppy.setJointRotation("LeftKnee", Vector3f.ZERO, 2f);

            assertThat(TestModels.find(guppy.root(), "LeftKnee").getLocalRotation().isIdentity())
                    .isTrue();
        }

        @Test
        void setRotationTurnsTheAgentTransform() throws ModelException {
            BodyModel guppy = TestModels.loadVrml("Guppy", Figure5Test.FIGURE_5_VRML);

            guppy.setRotation(Vector3f.UNIT_Y, FastMath.PI);

            Quaternion expected = new Quaternion().fromAngleAxis(FastMath.PI, Vector3f.UNIT_Y);
            assertThat(TestModels.find(guppy.root(), "Guppy").getLocalRotation()
                    .isSimilar(expected, 1e-5f)).isTrue();
        }
    }

    @Nested
    class Registration {

        @Test
        void namesAreReportedForRegistrationChecks() throws ModelException {
            BodyModel bunny = TestModels.loadVrml("Bunny", BODY_WITHOUT_MOVER);

            assertThat(bunny.jointNames()).containsExactlyInAnyOrder("Bunny", "Neck");
            assertThat(bunny.timeSensorNames()).containsExactly("Hop");
            assertThat(bunny.animationNames()).containsExactly("Hop");
            assertThat(bunny.hasNode("Neck")).isTrue();
            assertThat(bunny.hasNode("Tail")).isFalse();
            assertThat(bunny.agentName()).isEqualTo("Bunny");
            assertThat(bunny.format()).contains(ModelFormat.VRML97);
            assertThat(bunny.isPlaceholder()).isFalse();
            assertThat(bunny.root().getName()).isEqualTo("Bunny model");
        }
    }

    @Nested
    class Placeholder {

        @Test
        void placeholderIsAVisibleNodeNamedAfterTheAgent() {
            BodyModel placeholder = BodyModels.placeholder("Roadrunner", TestModels.ASSETS);

            assertThat(placeholder.isPlaceholder()).isTrue();
            assertThat(placeholder.format()).isEmpty();
            assertThat(placeholder.hasNode("Roadrunner")).isTrue();
            Spatial agent = TestModels.find(placeholder.root(), "Roadrunner");
            assertThat(TestModels.geometries(agent)).hasSizeGreaterThanOrEqualTo(2);
            assertThat(agent.getWorldBound()).isNotNull();
        }

        @Test
        void placeholderCarriesTheNameAsALabel() {
            BodyModel placeholder = BodyModels.placeholder("Roadrunner", TestModels.ASSETS);

            Node label = (Node) TestModels.find(placeholder.root(), "Roadrunner label");
            assertThat(label.getChild(0)).isInstanceOfSatisfying(BitmapText.class,
                    text -> assertThat(text.getText()).isEqualTo("Roadrunner"));
        }

        @Test
        void placeholderMovesLikeAModel() throws ModelException {
            BodyModel placeholder = BodyModels.placeholder("Roadrunner", TestModels.ASSETS);

            placeholder.moveTo(new Vector3f(0, 0, 0), new Vector3f(2, 0, 2), 0, 1);
            placeholder.update(1);

            assertThat(TestModels.find(placeholder.root(), "Roadrunner").getLocalTranslation())
                    .isEqualTo(new Vector3f(2, 0, 2));
        }
    }
}
