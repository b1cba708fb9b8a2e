package io.orchard.viewer.model.x3d;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelLimits;
import io.orchard.viewer.model.SceneDescription;
import io.orchard.viewer.model.SceneNode;
import io.orchard.viewer.model.TestModels;
import java.util.List;
import org.junit.jupiter.api.Test;

/** What the X3D parser reads beyond what both encodings share (see SceneParsingTest). */
class X3dParsingTest {

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
    void aProtoInstanceIsItsBodysFirstNodeUnderTheInstancesName() throws ModelException {
        SceneDescription scene = X3dParser.parse(TestModels.x3d("""
                <ProtoDeclare name="Leg"><ProtoBody><Transform DEF="Inside"/></ProtoBody>
                </ProtoDeclare>
                <ProtoInstance DEF="Left" name="Leg"><fieldValue name="size" value="1"/>
                </ProtoInstance>
                <Group DEF="Body"/>
                """), ModelLimits.DEFAULTS);

        assertThat(scene.defs()).containsKeys("Body", "Left").doesNotContainKey("Inside");
        assertThat(scene.defs().get("Left").typeName()).isEqualTo("Transform");
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
