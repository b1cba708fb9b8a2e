package io.orchard.viewer.model;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.ModelFormat;
import io.orchard.viewer.model.vrml.VrmlParser;
import io.orchard.viewer.model.x3d.X3dParser;
import java.util.stream.Stream;
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
}
