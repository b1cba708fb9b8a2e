package io.orchard.viewer.model.x3d;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelLimits;
import io.orchard.viewer.model.SceneDescription;
import io.orchard.viewer.model.SceneNode;
import io.orchard.viewer.model.TestModels;
import org.junit.jupiter.api.Test;

/**
 * X3D prototypes expanded: fields with defaults and values given by instances, connected with
 * {@code IS} to attributes and to nodes; each instance's DEF names its own; nested instances;
 * what cannot be expanded refused by name.
 */
class X3dProtosTest {

    private static final String LEG = """
            <ProtoDeclare name="Leg">
              <ProtoInterface>
                <field name="length" type="SFVec3f" accessType="initializeOnly" value="0.1 1 0.1"/>
                <field name="hip" type="SFVec3f" accessType="inputOutput" value="0 0 0"/>
                <field name="foot" type="MFNode" accessType="inputOutput"/>
              </ProtoInterface>
              <ProtoBody>
                <Transform DEF="Hip"><IS><connect nodeField="translation" protoField="hip"/></IS>
                  <Transform DEF="Knee">
                    <IS><connect nodeField="children" protoField="foot"/></IS>
                    <Shape><Box><IS><connect nodeField="size" protoField="length"/></IS></Box></Shape>
                  </Transform>
                </Transform>
                <TimeSensor DEF="Swing" cycleInterval="1"/>
                <PositionInterpolator DEF="Lift" key="0 1" keyValue="0 0 0 0 1 0"/>
                <ROUTE fromNode="Swing" fromField="fraction_changed" toNode="Lift" toField="set_fraction"/>
                <ROUTE fromNode="Lift" fromField="value_changed" toNode="Hip" toField="set_translation"/>
              </ProtoBody>
            </ProtoDeclare>
            """;

    private static SceneDescription parse(String scene) throws ModelException {
        return X3dParser.parse(TestModels.x3d(scene), ModelLimits.DEFAULTS);
    }

    @Test
    void fieldsTakeTheInstancesValuesOrTheDefaults() throws ModelException {
        SceneDescription scene = parse(LEG + """
                <Group DEF="Robot">
                  <ProtoInstance name="Leg" DEF="LeftLeg"><fieldValue name="hip" value="-0.2 0 0"/>
                    <fieldValue name="foot"><Shape DEF="Shoe"><Sphere radius="0.1"/></Shape></fieldValue>
                  </ProtoInstance>
                  <ProtoInstance name="Leg"/>
                </Group>
                """);

        SceneNode left = scene.defs().get("LeftLeg");
        assertThat(left.typeName()).isEqualTo("Transform");
        assertThat(left.floats("translation")).containsExactly(-0.2f, 0, 0);
        SceneNode knee = scene.defs().get("LeftLeg.Knee");
        assertThat(knee.nodes("children")).extracting(SceneNode::typeName).containsExactly("Shape", "Shape");
        assertThat(knee.nodes("children").get(1).node("geometry").floats("size")).containsExactly(0.1f, 1, 0.1f);
        // The shoe is the instance's value, named in the scene it was written in.
        assertThat(scene.defs()).containsKeys("Shoe", "LeftLeg.Swing", "Leg#2.Hip", "Leg#2.Knee")
                .doesNotContainKeys("Hip", "Knee", "Swing", "LeftLeg.Hip");
        assertThat(scene.defs().get("Leg#2.Hip").floats("translation")).containsExactly(0, 0, 0);
        assertThat(scene.defs().get("Robot").nodes("children")).extracting(SceneNode::typeName)
                .containsExactly("Transform", "TimeSensor", "PositionInterpolator", "Transform", "TimeSensor",
                        "PositionInterpolator");
        assertThat(scene.routes()).hasSize(4);
        assertThat(scene.routes().get(1).to()).isSameAs(left);
        assertThat(scene.routes().get(3).to()).isSameAs(scene.defs().get("Leg#2.Hip"));
    }

    @Test
    void anInstanceInsideABodyIsExpandedToo() throws ModelException {
        SceneDescription scene = parse(LEG + """
                <ProtoDeclare name="Legs"><ProtoBody><Group>
                  <ProtoInstance name="Leg" DEF="Left"/><ProtoInstance name="Leg" DEF="Right"/>
                </Group></ProtoBody></ProtoDeclare>
                <ProtoInstance name="Legs" DEF="Pair"/>
                """);

        assertThat(scene.defs()).containsKeys("Pair", "Pair.Left", "Pair.Right", "Pair.Left.Knee", "Pair.Right.Knee");
    }

    @Test
    void anInstanceOfAnUndeclaredPrototypeIsRefusedByName() {
        assertThatThrownBy(() -> parse(LEG + "<ProtoInstance name='Arm'/>"))
                .isInstanceOf(ModelException.class)
                .hasMessageContaining("ProtoInstance 'Arm' names no ProtoDeclare; the model declares [Leg]");
    }

    @Test
    void aPrototypeThatInstantiatesItselfIsRefused() {
        assertThatThrownBy(() -> parse("<ProtoDeclare name='Loop'><ProtoBody><Group>"
                + "<ProtoInstance name='Loop'/></Group></ProtoBody></ProtoDeclare><ProtoInstance name='Loop'/>"))
                .hasMessageContaining("prototype instances nest deeper than " + X3dProtos.MAX_NESTING);
    }

    @Test
    void instancesThatMultiplyBeyondTheNodeLimitAreRefused() {
        StringBuilder protos = new StringBuilder("<ProtoDeclare name='P0'><ProtoBody><Group><Shape><Box/></Shape>"
                + "</Group></ProtoBody></ProtoDeclare>");
        for (int i = 1; i <= 12; i++) {
            protos.append("<ProtoDeclare name='P").append(i).append("'><ProtoBody><Group>")
                    .append("<ProtoInstance name='P").append(i - 1).append("'/>")
                    .append("<ProtoInstance name='P").append(i - 1).append("'/>")
                    .append("<ProtoInstance name='P").append(i - 1).append("'/>")
                    .append("</Group></ProtoBody></ProtoDeclare>");
        }
        assertThatThrownBy(() -> parse(protos + "<ProtoInstance name='P12'/>"))
                .isInstanceOf(ModelException.class).hasMessageContaining("more than 20000 nodes");
    }

    @Test
    void anExternPrototypesInstancesAreNotDrawnAndNothingIsFetched() throws ModelException {
        SceneDescription scene = parse("<ExternProtoDeclare name='Arm' url='\"http://127.0.0.1:9/arm.x3d\"'/>"
                + "<Group DEF='Body'><ProtoInstance name='Arm' DEF='LeftArm'/></Group>");

        assertThat(scene.defs()).containsKey("Body").doesNotContainKey("LeftArm");
        assertThat(scene.defs().get("Body").nodes("children")).isEmpty();
    }
}
