package io.orchard.viewer.model;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** Both encodings parse into the same scene description: nodes, fields, DEF/USE and ROUTEs. */
class SceneParsingTest {

    static SceneDescription parse(ModelFormat format, byte[] bytes) throws ModelException {
        return format == ModelFormat.X3D ? X3dParser.parse(bytes, ModelLimits.DEFAULTS)
                : VrmlParser.parse(bytes, ModelLimits.DEFAULTS);
    }

    static Stream<Arguments> figure5() {
        return Figure5Test.figure5();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("figure5")
    void figure5DescribesTheSameScene(ModelFormat format, byte[] bytes) throws ModelException {
        SceneDescription scene = parse(format, bytes);

        assertThat(scene.roots()).extracting(SceneNode::typeName).containsExactly("Transform",
                "PositionInterpolator", "TimeSensor");
        assertThat(scene.defs()).containsKeys("Guppy", "GuppyHead", "LeftKnee", "GuppyMover");
        SceneNode mover = scene.defs().get("GuppyMover");
        assertThat(mover.floats("key")).containsExactly(0f, 1f);
        assertThat(mover.floats("keyValue")).containsExactly(0f, 0f, 0f, 10f, 0f, 10f);
        SceneNode sensor = scene.roots().get(2);
        assertThat(sensor.bool("enabled")).isFalse();
        assertThat(sensor.bool("loop")).isFalse();
        assertThat(sensor.number("cycleInterval")).isEqualTo(1.0);
        assertThat(scene.routes()).hasSize(2);
        SceneDescription.ResolvedRoute move = scene.routes().get(1);
        assertThat(move.from()).isSameAs(mover);
        assertThat(move.to()).isSameAs(scene.defs().get("Guppy"));
        assertThat(move.toField().name()).isEqualTo("translation");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("figure5")
    void unsetFieldsReadAsTheirVrmlDefaults(ModelFormat format, byte[] bytes)
            throws ModelException {
        SceneNode guppy = parse(format, bytes).defs().get("Guppy");

        assertThat(guppy.has("scale")).isFalse();
        assertThat(guppy.floats("scale")).containsExactly(1f, 1f, 1f);
        assertThat(guppy.floats("rotation")).containsExactly(0f, 0f, 1f, 0f);
    }

    static Stream<Arguments> sharedNodes() {
        return Stream.of(
                Arguments.of(ModelFormat.VRML97, TestModels.vrml(
                        "DEF Skin Appearance { material Material { } }"
                                + " Shape { appearance USE Skin geometry Box { } }")),
                Arguments.of(ModelFormat.X3D, TestModels.x3d(
                        "<Shape><Appearance DEF='Skin'><Material/></Appearance><Box/></Shape>"
                                + "<Shape><Appearance USE='Skin'/><Sphere/></Shape>")));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("sharedNodes")
    void useIsTheSameNodeObject(ModelFormat format, byte[] bytes) throws ModelException {
        SceneDescription scene = parse(format, bytes);

        SceneNode lastShape = scene.roots().get(scene.roots().size() - 1);
        assertThat(lastShape.node("appearance")).isSameAs(scene.defs().get("Skin"));
    }

    @Nested
    class Vrml {

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
        void protoDeclarationsAreSkippedAndTheirInstancesKeptAsUnknownNodes()
                throws ModelException {
            SceneDescription scene = VrmlParser.parse(TestModels.vrml("""
                    PROTO Leg [ field SFVec3f size 1 1 1 exposedField MFNode kids [] ] {
                      Transform { children [ Shape { geometry Box { size IS size } } ] }
                    }
                    EXTERNPROTO Arm [ field SFFloat length ] [ "http://127.0.0.1:9/arm.wrl" ]
                    DEF Left Leg { size 1 2 1 }
                    DEF Body Group { children [ USE Left ] }
                    """), ModelLimits.DEFAULTS);

            assertThat(scene.defs().get("Left").isKnown()).isFalse();
            assertThat(scene.defs().get("Body").nodes("children")).hasSize(1);
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

    @Nested
    class X3d {

        @Test
        void containerFieldPutsAChildIntoANamedField() throws ModelException {
            SceneDescription scene = X3dParser.parse(TestModels.x3d(
                    "<Collision DEF='C'><Shape containerField='proxy'><Box/></Shape>"
                            + "<Group/></Collision>"), ModelLimits.DEFAULTS);

            SceneNode collision = scene.defs().get("C");
            assertThat(collision.node("proxy").typeName()).isEqualTo("Shape");
            assertThat(collision.nodes("children")).extracting(SceneNode::typeName)
                    .containsExactly("Group");
        }

        @Test
        void protoDeclarationsAndTheirDefNamesAreSkipped() throws ModelException {
            SceneDescription scene = X3dParser.parse(TestModels.x3d("""
                    <ProtoDeclare name="Leg"><ProtoBody><Transform DEF="Inside"/></ProtoBody>
                    </ProtoDeclare>
                    <ProtoInstance DEF="Left" name="Leg"><fieldValue name="size" value="1"/>
                    </ProtoInstance>
                    <Group DEF="Body"/>
                    """), ModelLimits.DEFAULTS);

            assertThat(scene.defs()).containsKeys("Body", "Left").doesNotContainKey("Inside");
        }

        @Test
        void unknownAttributesAreIgnored() throws ModelException {
            SceneDescription scene = X3dParser.parse(TestModels.x3d(
                    "<Transform DEF='T' translation='1 2 3' visible='true' bboxDisplay='false'"
                            + " class='x'/>"), ModelLimits.DEFAULTS);

            assertThat(scene.defs().get("T").floats("translation")).containsExactly(1, 2, 3);
        }

        @Test
        void quotedAndUnquotedStringListsAreRead() throws ModelException {
            SceneDescription scene = X3dParser.parse(TestModels.x3d(
                    "<ImageTexture DEF='A' url='\"one.png\" \"two.png\"'/>"
                            + "<ImageTexture DEF='B' url='three.png'/>"), ModelLimits.DEFAULTS);

            assertThat(scene.defs().get("A").strings("url")).containsExactly("one.png",
                    "two.png");
            assertThat(scene.defs().get("B").strings("url")).containsExactly("three.png");
        }

        @Test
        void externalDtdIsNeverRead() throws ModelException {
            // Were the DTD read, /etc/passwd would fail to parse as one.
            byte[] bytes = ("<?xml version='1.0'?><!DOCTYPE X3D SYSTEM 'file:///etc/passwd'>"
                    + "<X3D><Scene><Group DEF='G'/></Scene></X3D>").getBytes();

            assertThat(X3dParser.parse(bytes, ModelLimits.DEFAULTS).defs()).containsKey("G");
        }

        @Test
        void documentWithoutDoctypeIsRead() throws ModelException {
            byte[] bytes = "<X3D><Scene><Group DEF='G'/></Scene></X3D>".getBytes();

            assertThat(X3dParser.parse(bytes, ModelLimits.DEFAULTS).defs()).containsKey("G");
        }

        @Test
        void headAndMetaElementsAreIgnored() throws ModelException {
            SceneDescription scene = X3dParser.parse(TestModels.x3d("<Group DEF='G'/>"),
                    ModelLimits.DEFAULTS);

            assertThat(scene.roots()).extracting(SceneNode::typeName).isEqualTo(List.of("Group"));
        }
    }
}
