package io.orchard.viewer.model.vrml;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelLimits;
import io.orchard.viewer.model.SceneDescription;
import io.orchard.viewer.model.SceneNode;
import io.orchard.viewer.model.TestModels;
import java.util.List;
import org.junit.jupiter.api.Test;

/** What the VRML97 parser reads beyond what both encodings share (see SceneParsingTest). */
class VrmlParsingTest {

    @Test
    void commentsCommasAndStringEscapesAreRead() throws ModelException {
        SceneDescription scene = VrmlParser.parse(TestModels.vrml("""
                # a comment
                DEF Skin ImageTexture { url [ "a \\"quoted\\" name", "b\\\\c" ] } # trailing
                DEF P Coordinate { point [ 1,2,3, 4 5 6, ] }
                """), ModelLimits.DEFAULTS);

        assertThat(scene.defs().get("Skin").strings("url"))
                .containsExactly("a \"quoted\" name", "b\\c");
        assertThat(scene.defs().get("P").floats("point")).containsExactly(1, 2, 3, 4, 5, 6);
    }

    @Test
    void singleValuesNeedNoBrackets() throws ModelException {
        SceneDescription scene = VrmlParser.parse(TestModels.vrml(
                "DEF M PositionInterpolator { key 0.5 keyValue 1 2 3 }"
                        + " DEF G Group { children Shape { } }"), ModelLimits.DEFAULTS);

        assertThat(scene.defs().get("M").floats("key")).containsExactly(0.5f);
        assertThat(scene.defs().get("M").floats("keyValue")).containsExactly(1, 2, 3);
        assertThat(scene.defs().get("G").nodes("children")).hasSize(1);
    }

    @Test
    void hexadecimalAndSignedNumbersAreRead() throws ModelException {
        SceneDescription scene = VrmlParser.parse(TestModels.vrml(
                "DEF S Switch { whichChoice 0x1 } DEF T Transform { translation +1 -2e1 .5 }"),
                ModelLimits.DEFAULTS);

        assertThat(scene.defs().get("S").integer("whichChoice")).isEqualTo(1);
        assertThat(scene.defs().get("T").floats("translation"))
                .containsExactly(1f, -20f, 0.5f);
    }

    @Test
    void protoInstancesAreExpandedWithTheirValuesAndDefaultsUnderTheirOwnNames() throws ModelException {
        SceneDescription scene = VrmlParser.parse(TestModels.vrml("""
                PROTO Leg [ field SFVec3f size 1 1 1 exposedField MFNode kids [] eventIn SFFloat bend ] {
                  DEF Hip Transform { set_scale IS bend children [ DEF Knee Transform { children IS kids }
                    Shape { geometry Box { size IS size } } ] }
                  DEF Swing TimeSensor { }
                }
                EXTERNPROTO Arm [ field SFFloat length ] [ "http://127.0.0.1:9/arm.wrl" ]
                DEF Left Leg { size 1 2 1 kids [ DEF Foot Shape { geometry Sphere { } } ] }
                DEF Body Group { children [ USE Left Leg { } Arm { length 2 } ] }
                """), ModelLimits.DEFAULTS);

        SceneNode left = scene.defs().get("Left");
        assertThat(left.typeName()).isEqualTo("Transform");
        assertThat(left.nodes("children").get(1).node("geometry").floats("size")).containsExactly(1, 2, 1);
        assertThat(scene.defs().get("Left.Knee").nodes("children")).extracting(SceneNode::typeName)
                .containsExactly("Shape");
        assertThat(scene.defs()).containsKeys("Foot", "Leg#2.Hip", "Leg#2.Knee").doesNotContainKeys("Hip", "Knee");
        assertThat(scene.defs().get("Leg#2.Hip").nodes("children").get(1).node("geometry").floats("size"))
                .containsExactly(1, 1, 1);
        List<SceneNode> body = scene.defs().get("Body").nodes("children");
        assertThat(body).hasSize(3);
        assertThat(body.get(0)).isSameAs(left);
        assertThat(body.get(2).isKnown()).as("the EXTERNPROTO's instance").isFalse();
    }

    @Test
    void aProtoThatInstantiatesItselfIsRefused() {
        assertThatThrownBy(() -> VrmlParser.parse(TestModels.vrml("PROTO Loop [ ] { Loop { } } Loop { }"),
                ModelLimits.DEFAULTS)).isInstanceOf(ModelException.class)
                .hasMessageContaining("PROTO instances nest deeper than 16");
    }

    @Test
    void scriptInterfaceDeclarationsAreReadAsAnUnknownNode() throws ModelException {
        SceneDescription scene = VrmlParser.parse(TestModels.vrml("""
                DEF Brain Script {
                  eventIn SFFloat set_level
                  eventOut SFVec3f position
                  field SFNode target DEF Inner Transform { }
                  url "javascript: function set_level(v) { }"
                }
                """), ModelLimits.DEFAULTS);

        assertThat(scene.defs()).containsKeys("Brain", "Inner");
        assertThat(scene.defs().get("Brain").childNodes()).hasSize(1);
    }

    @Test
    void routesMayAppearInsideANodeAndBeforeTheNodesTheyName() throws ModelException {
        SceneDescription scene = VrmlParser.parse(TestModels.vrml("""
                DEF Body Transform {
                  children [ DEF Clock TimeSensor { } ]
                  ROUTE Turn.value_changed TO Body.rotation
                }
                DEF Turn OrientationInterpolator { }
                ROUTE Clock.fraction_changed TO Turn.set_fraction
                """), ModelLimits.DEFAULTS);

        assertThat(scene.routes()).hasSize(2);
    }

    @Test
    void routesToNodeTypesThatAreNotBuiltAreDropped() throws ModelException {
        SceneDescription scene = VrmlParser.parse(TestModels.vrml("""
                DEF Eye Viewpoint { }
                DEF Clock TimeSensor { }
                ROUTE Clock.isActive TO Eye.set_bind
                """), ModelLimits.DEFAULTS);

        assertThat(scene.routes()).isEmpty();
    }
}
