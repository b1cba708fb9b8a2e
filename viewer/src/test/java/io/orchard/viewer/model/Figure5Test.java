package io.orchard.viewer.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import io.orchard.protocol.value.ModelFormat;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The paper's Figure 5, the nodes every agent model must define, written as VRML97 (as in the
 * paper, with a small body of primitives in place of the "...") and as X3D.
 */
class Figure5Test {

    static final String FIGURE_5_VRML = """
            DEF Guppy Transform {
              children [
                Shape {
                  appearance Appearance { material Material { diffuseColor 0.2 0.4 0.9 } }
                  geometry Cylinder { radius 0.3 height 1.2 }
                }
                DEF GuppyHead Transform {
                  translation 0 0.9 0
                  children Shape { geometry Sphere { radius 0.25 } }
                }
                DEF LeftKnee Transform {
                  translation -0.15 -0.6 0
                  children Shape { geometry Box { size 0.1 0.5 0.1 } }
                }
              ]
            }
            # Movement animation
            DEF GuppyMover PositionInterpolator {
              key [ 0.0 1.0 ]
              keyValue [ 0 0 0,   # starting point, modified by EAI
                         10 0 10  # end point, modified by EAI
                       ]
            }
            DEF GuppyTSMove TimeSensor { cycleInterval 1.0 loop FALSE enabled FALSE }
            ROUTE GuppyTSMove.fraction_changed TO GuppyMover.set_fraction
            ROUTE GuppyMover.value_changed TO Guppy.set_translation
            """;

    static final String FIGURE_5_X3D = """
            <Transform DEF="Guppy">
              <Shape>
                <Appearance><Material diffuseColor="0.2 0.4 0.9"/></Appearance>
                <Cylinder radius="0.3" height="1.2"/>
              </Shape>
              <Transform DEF="GuppyHead" translation="0 0.9 0">
                <Shape><Sphere radius="0.25"/></Shape>
              </Transform>
              <Transform DEF="LeftKnee" translation="-0.15 -0.6 0">
                <Shape><Box size="0.1 0.5 0.1"/></Shape>
              </Transform>
            </Transform>
            <PositionInterpolator DEF="GuppyMover" key="0.0 1.0" keyValue="0 0 0, 10 0 10"/>
            <TimeSensor DEF="GuppyTSMover" cycleInterval="1.0" loop="false" enabled="false"/>
            <ROUTE fromNode="GuppyTSMover" fromField="fraction_changed"
                   toNode="GuppyMover" toField="set_fraction"/>
            <ROUTE fromNode="GuppyMover" fromField="value_changed"
                   toNode="Guppy" toField="set_translation"/>
            """;

    static Stream<Arguments> figure5() {
        return Stream.of(
                Arguments.of(ModelFormat.VRML97, TestModels.vrml(FIGURE_5_VRML)),
                Arguments.of(ModelFormat.X3D, TestModels.x3d(FIGURE_5_X3D)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("figure5")
    void figure5LoadsWithTheAgentsRequiredNodes(ModelFormat format, byte[] bytes)
            throws ModelException {
        BodyModel guppy = TestModels.load("Guppy", format, bytes);

        assertThat(guppy.hasNode("Guppy")).isTrue();
        assertThat(guppy.hasNode("GuppyMover")).isTrue();
        assertThat(guppy.jointNames()).containsExactlyInAnyOrder("Guppy", "GuppyHead",
                "LeftKnee");
        assertThat(guppy.timeSensorNames()).hasSize(1);
        Node body = (Node) TestModels.find(guppy.root(), "Guppy");
        assertThat(TestModels.geometries(body)).hasSize(3);
        assertThat(TestModels.find(guppy.root(), "LeftKnee").getLocalTranslation())
                .isEqualTo(new Vector3f(-0.15f, -0.6f, 0));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("figure5")
    void moveToInterpolatesGuppyThroughMoverAndTimeSensor(ModelFormat format, byte[] bytes)
            throws ModelException {
        BodyModel guppy = TestModels.load("Guppy", format, bytes);
        Node body = (Node) TestModels.find(guppy.root(), "Guppy");
        guppy.update(0);

        guppy.moveTo(new Vector3f(2, 0, 4), new Vector3f(6, 0, -4), 1.0, 2.0);

        guppy.update(0.5);
        assertThat(body.getLocalTranslation()).isEqualTo(Vector3f.ZERO);
        guppy.update(1.0);
        assertTranslation(body, 2, 0, 4);
        guppy.update(1.5);
        assertTranslation(body, 3, 0, 2);
        guppy.update(2.0);
        assertTranslation(body, 4, 0, 0);
        guppy.update(2.75);
        assertTranslation(body, 5.5f, 0, -3);
        guppy.update(3.0);
        assertTranslation(body, 6, 0, -4);
        guppy.update(10.0);
        assertTranslation(body, 6, 0, -4);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("figure5")
    void secondMoveContinuesFromWhereTheFirstEnded(ModelFormat format, byte[] bytes)
            throws ModelException {
        BodyModel guppy = TestModels.load("Guppy", format, bytes);
        Node body = (Node) TestModels.find(guppy.root(), "Guppy");
        guppy.moveTo(new Vector3f(0, 0, 0), new Vector3f(10, 0, 10), 0, 1);
        guppy.update(0);
        guppy.update(1);

        guppy.moveTo(new Vector3f(10, 0, 10), new Vector3f(10, 0, 20), 1, 1);
        guppy.update(1.25);

        assertTranslation(body, 10, 0, 12.5f);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("figure5")
    void moveWhoseEndHasPassedByTheNextFrameStillArrives(ModelFormat format, byte[] bytes)
            throws ModelException {
        BodyModel guppy = TestModels.load("Guppy", format, bytes);
        Node body = (Node) TestModels.find(guppy.root(), "Guppy");
        guppy.update(0);

        guppy.moveTo(new Vector3f(0, 0, 0), new Vector3f(1, 2, 3), 0.1, 0.2);
        guppy.update(5);

        assertTranslation(body, 1, 2, 3);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("figure5")
    void zeroDurationMoveJumpsAtItsStartTime(ModelFormat format, byte[] bytes)
            throws ModelException {
        BodyModel guppy = TestModels.load("Guppy", format, bytes);
        Node body = (Node) TestModels.find(guppy.root(), "Guppy");

        guppy.moveTo(new Vector3f(0, 0, 0), new Vector3f(7, 0, 7), 2, 0);
        guppy.update(1.9);
        assertThat(body.getLocalTranslation()).isEqualTo(Vector3f.ZERO);
        guppy.update(2.0);

        assertTranslation(body, 7, 0, 7);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("figure5")
    void bodyIsBuiltFromThePrimitives(ModelFormat format, byte[] bytes) throws ModelException {
        BodyModel guppy = TestModels.load("Guppy", format, bytes);

        Geometry cylinder = (Geometry) TestModels.find(guppy.root(), "Cylinder");
        assertThat(cylinder.getMesh().getBound().getCenter()).isEqualTo(Vector3f.ZERO);
        assertThat(cylinder.getMaterial().getMaterialDef().getAssetName())
                .isEqualTo("Common/MatDefs/Light/Lighting.j3md");
        assertThat(TestModels.find(guppy.root(), "Sphere")).isInstanceOf(Geometry.class);
        assertThat(TestModels.find(guppy.root(), "Box")).isInstanceOf(Geometry.class);
    }

    static void assertTranslation(Node node, float x, float y, float z) {
        Vector3f t = node.getLocalTranslation();
        assertThat(t.x).as("x").isCloseTo(x, within(1e-4f));
        assertThat(t.y).as("y").isCloseTo(y, within(1e-4f));
        assertThat(t.z).as("z").isCloseTo(z, within(1e-4f));
    }
}
