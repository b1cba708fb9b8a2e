package io.orchard.viewer.model.event;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import com.jme3.material.RenderState.BlendMode;
import com.jme3.math.ColorRGBA;
import com.jme3.math.FastMath;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Spatial;
import io.orchard.viewer.model.BodyModel;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.TestModels;
import java.util.stream.Stream;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The event graph stepped with simulated time: TimeSensors, interpolators and ROUTEs. A sensor
 * drives a PositionInterpolator from (0 0 0) to (1 0 0) into a Transform, so the Transform's x
 * shows the sensor's fraction.
 */
class EventGraphTest {

    /** A model whose Transform Probe's x is the fraction of TimeSensor Clock. */
    static BodyModel probe(String clock) throws ModelException {
        return TestModels.loadVrml("Guppy", """
                DEF Probe Transform { }
                DEF Ramp PositionInterpolator { key [0 1] keyValue [0 0 0, 1 0 0] }
                DEF Clock TimeSensor { %s }
                ROUTE Clock.fraction_changed TO Ramp.set_fraction
                ROUTE Ramp.value_changed TO Probe.set_translation
                """.formatted(clock));
    }

    static float x(BodyModel model) {
        return TestModels.find(model.root(), "Probe").getLocalTranslation().x;
    }

    @Nested
    class TimeSensors {

        static Stream<Arguments> fractions() {
            return Stream.of(
                    Arguments.of("loop TRUE cycleInterval 2", new double[] {0.5, 2.5, 3.0},
                            new float[] {0.25f, 0.25f, 0.5f}),
                    // The file's times count from 1970, as in VRML: one-shot sensors finished long ago.
                    Arguments.of("loop FALSE startTime 1 cycleInterval 2",
                            new double[] {0.5, 1.5, 2.5, 3.5, 9},
                            new float[] {0f, 0f, 0f, 0f, 0f}),
                    Arguments.of("loop FALSE", new double[] {0.1, 0.5, 1.5},
                            new float[] {0f, 0f, 0f}),
                    Arguments.of("enabled FALSE loop TRUE", new double[] {0.5, 1.5},
                            new float[] {0f, 0f}),
                    Arguments.of("loop TRUE stopTime 1.5", new double[] {1.25, 2, 3},
                            new float[] {0f, 0f, 0f}),
                    Arguments.of("loop FALSE startTime 2 stopTime 1", new double[] {2.5, 3.5},
                            new float[] {0f, 0f}));
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("fractions")
        void fractionFollowsTheSensorsFields(String fields, double[] times, float[] expected)
                throws ModelException {
            BodyModel model = probe(fields);
            model.update(0);

            for (int i = 0; i < times.length; i++) {
                model.update(times[i]);
                assertThat(x(model)).as("fraction at time " + times[i])
                        .isCloseTo(expected[i], within(1e-5f));
            }
        }

        @Test
        void startAnimationRunsADisabledSensorFromTheCurrentTime() throws ModelException {
            BodyModel model = probe("enabled FALSE cycleInterval 4");
            model.update(10);

            model.startAnimation("Clock", true);
            model.update(11);
            assertThat(x(model)).isCloseTo(0.25f, within(1e-5f));
            model.update(15);

            assertThat(x(model)).isCloseTo(0.25f, within(1e-5f));
        }

        @Test
        void stopAnimationFreezesThePose() throws ModelException {
            BodyModel model = probe("loop TRUE cycleInterval 4");
            model.update(0);
            model.update(1);

            model.stopAnimation("Clock");
            model.update(2);

            assertThat(x(model)).isCloseTo(0.25f, within(1e-5f));
        }

        @Test
        void unknownAnimationIsRefusedListingTheKnownOnes() throws ModelException {
            BodyModel model = probe("");

            assertThatThrownBy(() -> model.startAnimation("Dance", false))
                    .isInstanceOf(ModelException.class)
                    .hasMessageContaining("'Dance'").hasMessageContaining("[Clock]")
                    .extracting(e -> ((ModelException) e).kind())
                    .isEqualTo(ModelException.Kind.UNKNOWN_NAME);
        }

        @Test
        void timeGoingBackwardsIsIgnored() throws ModelException {
            BodyModel model = probe("loop TRUE cycleInterval 4");
            model.update(2);

            model.update(1);
            model.update(Double.NaN);

            assertThat(x(model)).isCloseTo(0.5f, within(1e-5f));
            assertThat(model.time()).isEqualTo(2);
        }
    }

    @Nested
    class Interpolators {

        @Test
        void positionInterpolatorIsLinearBetweenUnevenKeys() throws ModelException {
            BodyModel model = TestModels.loadVrml("Guppy", """
                    DEF Probe Transform { }
                    DEF Path PositionInterpolator { key [0 0.25 1]
                      keyValue [0 0 0, 1 0 0, 1 3 0] }
                    DEF Clock TimeSensor { loop TRUE cycleInterval 8 }
                    ROUTE Clock.fraction_changed TO Path.set_fraction
                    ROUTE Path.value_changed TO Probe.translation
                    """);

            model.update(5);

            assertThat(TestModels.find(model.root(), "Probe").getLocalTranslation())
                    .isEqualTo(new Vector3f(1, 1.5f, 0));
        }

        static Stream<Arguments> orientations() {
            return Stream.of(
                    Arguments.of("quarter turn", "0 1 0 0, 0 1 0 1.5707963", FastMath.QUARTER_PI),
                    Arguments.of("shortest way across zero", "0 1 0 0.2, 0 1 0 6.0831853", 0f),
                    Arguments.of("half of a half turn", "0 1 0 0, 0 1 0 3.1", 1.55f));
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("orientations")
        void orientationInterpolatorSlerpsHalfway(String name, String keyValue, float angle)
                throws ModelException {
            BodyModel model = TestModels.loadVrml("Guppy", """
                    DEF Joint Transform { }
                    DEF Turn OrientationInterpolator { key [0 1] keyValue [%s] }
                    DEF Clock TimeSensor { loop TRUE cycleInterval 2 }
                    ROUTE Clock.fraction_changed TO Turn.set_fraction
                    ROUTE Turn.value_changed TO Joint.set_rotation
                    """.formatted(keyValue));

            model.update(1);

            Spatial joint = TestModels.find(model.root(), "Joint");
            float[] angles = joint.getLocalRotation().toAngles(null);
            assertThat(angles[1]).isCloseTo(angle, within(1e-4f));
        }

        @Test
        void scalarInterpolatorDrivesMaterialTransparency() throws ModelException {
            BodyModel model = TestModels.loadVrml("Guppy", """
                    DEF Ghost Shape {
                      appearance Appearance { material DEF Skin Material { diffuseColor 1 1 1 } }
                      geometry Box { }
                    }
                    DEF Fade ScalarInterpolator { key [0 1] keyValue [0 0.8] }
                    DEF Clock TimeSensor { loop TRUE cycleInterval 4 }
                    ROUTE Clock.fraction_changed TO Fade.set_fraction
                    ROUTE Fade.value_changed TO Skin.set_transparency
                    """);

            model.update(2);

            Geometry ghost = (Geometry) TestModels.find(model.root(), "Ghost");
            ColorRGBA diffuse = (ColorRGBA) ghost.getMaterial().getParamValue("Diffuse");
            assertThat(diffuse.a).isCloseTo(0.6f, within(1e-5f));
            assertThat(ghost.getMaterial().getAdditionalRenderState().getBlendMode())
                    .isEqualTo(BlendMode.Alpha);
        }

        @Test
        void scalarInterpolatorCanWarpAnotherInterpolatorsFraction() throws ModelException {
            BodyModel model = TestModels.loadVrml("Guppy", """
                    DEF Probe Transform { }
                    DEF Ease ScalarInterpolator { key [0 0.5 1] keyValue [0 0.1 1] }
                    DEF Ramp PositionInterpolator { key [0 1] keyValue [0 0 0, 1 0 0] }
                    DEF Clock TimeSensor { loop TRUE cycleInterval 1 }
                    ROUTE Clock.fraction_changed TO Ease.set_fraction
                    ROUTE Ease.value_changed TO Ramp.set_fraction
                    ROUTE Ramp.value_changed TO Probe.set_translation
                    """);

            model.update(0.5);

            assertThat(x(model)).isCloseTo(0.1f, within(1e-5f));
        }
    }

    @Nested
    class Routes {

        @Test
        void exposedFieldsRouteUnderAllThreeNames() throws ModelException {
            BodyModel model = TestModels.loadVrml("Guppy", """
                    DEF Probe Transform { }
                    DEF Copy Transform { }
                    DEF Ramp PositionInterpolator { key [0 1] keyValue [0 0 0, 1 0 0] }
                    DEF Clock TimeSensor { loop TRUE }
                    ROUTE Clock.fraction_changed TO Ramp.set_fraction
                    ROUTE Ramp.value_changed TO Probe.translation
                    ROUTE Probe.translation_changed TO Copy.set_translation
                    """);

            model.update(0.75);

            assertThat(TestModels.find(model.root(), "Copy").getLocalTranslation().x)
                    .isCloseTo(0.75f, within(1e-5f));
        }

        @Test
        void routeCycleSendsEachEventOncePerStep() throws ModelException {
            BodyModel model = TestModels.loadVrml("Guppy", """
                    DEF A Transform { }
                    DEF B Transform { }
                    DEF Ramp PositionInterpolator { key [0 1] keyValue [0 0 0, 1 0 0] }
                    DEF Clock TimeSensor { loop TRUE }
                    ROUTE Clock.fraction_changed TO Ramp.set_fraction
                    ROUTE Ramp.value_changed TO A.set_translation
                    ROUTE A.translation_changed TO B.set_translation
                    ROUTE B.translation_changed TO A.set_translation
                    """);

            model.update(0.5);

            assertThat(TestModels.find(model.root(), "B").getLocalTranslation().x)
                    .isCloseTo(0.5f, within(1e-5f));
        }

        @Test
        void isActiveCanEnableAnotherSensor() throws ModelException {
            BodyModel model = TestModels.loadVrml("Guppy", """
                    DEF Probe Transform { }
                    DEF Ramp PositionInterpolator { key [0 1] keyValue [0 0 0, 1 0 0] }
                    DEF Starter TimeSensor { loop TRUE cycleInterval 100 }
                    DEF Clock TimeSensor { enabled FALSE loop TRUE cycleInterval 4 }
                    ROUTE Starter.isActive TO Clock.set_enabled
                    ROUTE Clock.fraction_changed TO Ramp.set_fraction
                    ROUTE Ramp.value_changed TO Probe.set_translation
                    """);
            model.update(0);

            model.update(1);

            assertThat(x(model)).isCloseTo(0.25f, within(1e-5f));
        }

        @Test
        void x3dRoutesDriveTheSameGraph() throws ModelException {
            BodyModel model = TestModels.loadX3d("Guppy", """
                    <Transform DEF="Probe"/>
                    <PositionInterpolator DEF="Ramp" key="0 1" keyValue="0 0 0 1 0 0"/>
                    <TimeSensor DEF="Clock" loop="true" cycleInterval="2"/>
                    <ROUTE fromNode="Clock" fromField="fraction_changed" toNode="Ramp"
                           toField="set_fraction"/>
                    <ROUTE fromNode="Ramp" fromField="value_changed" toNode="Probe"
                           toField="translation"/>
                    """);

            model.update(0.5);

            assertThat(x(model)).isCloseTo(0.25f, within(1e-5f));
        }
    }
}
