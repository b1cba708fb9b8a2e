package io.orchard.agents.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import io.orchard.protocol.StrictJson;
import io.orchard.protocol.value.ModelArchive;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.Vec3;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.Map;
import org.assertj.core.data.Offset;
import org.junit.jupiter.api.Test;
import tools.jackson.databind.JsonNode;

/** What model files hold, read offline: joints, clips, bounds and units of glTF, X3D, VRML97 and zips. */
class ModelInfoTest {

    private static final Offset<Double> CLOSE = within(1e-9);

    private static byte[] resource(String name) throws IOException {
        try (InputStream in = ModelInfoTest.class.getResourceAsStream("/io/orchard/agents/" + name)) {
            return in.readAllBytes();
        }
    }

    private static void assertVec(Vec3 actual, double x, double y, double z) {
        assertThat(actual.x()).isCloseTo(x, CLOSE);
        assertThat(actual.y()).isCloseTo(y, CLOSE);
        assertThat(actual.z()).isCloseTo(z, CLOSE);
    }

    @Test
    void anX3dModelsDefdTransformsAreJointsItsTimeSensorsClipsItsShapesMeasured() throws IOException {
        ModelInfo info = ModelInfo.of("Pippin.x3d", ModelFormat.X3D, resource("Pippin.x3d"));

        assertThat(info.roots()).containsExactly("Pippin");
        assertThat(info.joints()).containsExactly("Pippin", "PippinBody", "LeftKnee");
        assertThat(info.clips()).containsExactly("PippinTSWalk");
        assertVec(info.min(), -0.2, 0, -0.15);
        assertVec(info.max(), 0.2, 0.8, 0.15);
        assertThat(info.units()).isEqualTo(new ModelInfo.Units("metre", 1, false));
    }

    @Test
    void aVrmlModelIsReadWithoutItsCommentsAndStrings() throws IOException {
        ModelInfo info = ModelInfo.of("Pippin.wrl", ModelFormat.VRML97, resource("Pippin.wrl"));

        assertThat(info.joints()).containsExactly("Pippin", "LeftKnee");
        assertThat(info.clips()).containsExactly("PippinTSWalk");
        assertVec(info.min(), -0.15, 0, -0.05);
        assertVec(info.max(), -0.05, 0.4, 0.05);
    }

    @Test
    void aGltfsUnnamedNodesAndClipsAreListedByTheirIndexNames() throws IOException {
        ModelInfo info = ModelInfo.of("Split.gltf", ModelFormat.GLTF, resource("split/Split.gltf"));

        assertThat(info.roots()).containsExactly("Split");
        assertThat(info.joints()).containsExactly("Split", "node#1");
        assertThat(info.clips()).containsExactly("clip#0");
        assertThat(info.size()).isEqualTo(new Vec3(1, 1.6, 0));
        assertThat(info.units()).isEqualTo(new ModelInfo.Units("metre", 1, true));
    }

    @Test
    void nodesTransformsPlaceTheMeshesAndATallModelIsNoted() throws IOException {
        String gltf = """
                {"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}],
                 "nodes": [{"name": "Cat", "scale": [100, 100, 100], "translation": [300, 0, 0], "children": [1]},
                   {"name": "Body", "rotation": [0, 0, 0.7071067811865476, 0.7071067811865476], "mesh": 0}],
                 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
                 "accessors": [{"componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0],
                   "max": [0.5, 0.2, 0.1]}]}
                """;

        ModelInfo info = ModelInfo.of("Cat.gltf", ModelFormat.GLTF, gltf.getBytes(StandardCharsets.UTF_8));

        // Turned a quarter about z, (0.5, 0.2) becomes (-0.2, 0.5); then 100 times larger, 300 along x.
        assertVec(info.min(), 280, 0, 0);
        assertVec(info.max(), 300, 50, 10);
        assertThat(info.notes()).anySatisfy(note -> assertThat(note).startsWith("50.0 m tall: perhaps authored in"
                + " centimetres"));
    }

    @Test
    void anX3dUnitStatementGivesTheUnits() throws IOException {
        String x3d = "<X3D><head><unit category='length' name='centimetre' conversionFactor='0.01'/></head><Scene>"
                + "<Transform DEF='Totem' translation='250 0 0'><Shape><Box size='60 180 60'/></Shape></Transform>"
                + "</Scene></X3D>";

        ModelInfo info = ModelInfo.of("totem.x3d", ModelFormat.X3D, x3d.getBytes(StandardCharsets.UTF_8));

        assertThat(info.units()).isEqualTo(new ModelInfo.Units("centimetre", 0.01, true));
        assertThat(info.size()).isEqualTo(new Vec3(60, 180, 60));
        assertThat(info.notes()).isEmpty();
    }

    @Test
    void aZipIsReadThroughItsModelFile() throws IOException {
        Map<String, byte[]> files = new LinkedHashMap<>();
        files.put("Split/Split.gltf", resource("split/Split.gltf"));
        files.put("Split/Split.bin", resource("split/Split.bin"));

        ModelInfo info = ModelInfo.of("split.zip", ModelFormat.ZIP, ModelArchive.pack(files));

        assertThat(info.format()).isEqualTo(ModelFormat.GLTF);
        assertThat(info.inside()).isEqualTo("Split/Split.gltf");
        assertThat(info.joints()).containsExactly("Split", "node#1");
    }

    @Test
    void theJsonFormHasEveryDocumentedField() throws IOException {
        JsonNode json = StrictJson.builder().build().readTree(
                ModelInfo.of("Pippin.x3d", ModelFormat.X3D, resource("Pippin.x3d")).toJson());

        assertThat(json.propertyNames()).containsExactly("file", "format", "inside", "roots", "joints", "clips",
                "bounds", "units", "notes");
        assertThat(json.get("format").stringValue()).isEqualTo("x3d");
        assertThat(json.get("inside").isNull()).isTrue();
        assertThat(json.get("joints").get(2).stringValue()).isEqualTo("LeftKnee");
        assertThat(json.get("bounds").get("size").get(1).doubleValue()).isCloseTo(0.8, CLOSE);
        assertThat(json.get("units").get("declared").booleanValue()).isFalse();
    }

    @Test
    void somethingThatIsNotAModelIsRefusedNamingTheFile() {
        assertThatThrownBy(() -> ModelInfo.of("broken.x3d", ModelFormat.X3D, "<X3D><Scene>".getBytes()))
                .isInstanceOf(IOException.class).hasMessageStartingWith("broken.x3d: X3D is not well-formed XML");
        assertThatThrownBy(() -> ModelInfo.of("a.wrl", ModelFormat.VRML97, "#VRML V1.0 ascii".getBytes()))
                .hasMessageStartingWith("a.wrl: not a VRML97 file");
        assertThatThrownBy(() -> ModelInfo.formatOf("cat.obj")).hasMessageContaining("cat.obj: expected a model file");
    }
}
