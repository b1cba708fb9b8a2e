package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.value.ModelFormat;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

class AgentModelTest {

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"Pippin.x3d", "Pippin.wrl", "Pippin.gltf"})
    void aCompleteModelPassesTheCheck(String resource) throws IOException {
        AgentModel model = AgentModel.load(AgentModelTest.class, resource);

        assertThat(model.problems("Pippin", List.of("LeftKnee"), List.of("PippinTSWalk"))).isEmpty();
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"Pippin.x3d", "Pippin.wrl", "Pippin.gltf"})
    void aModelMissingAJointIsRefusedNamingIt(String resource) throws IOException {
        AgentModel model = AgentModel.load(AgentModelTest.class, resource);

        assertThatThrownBy(() -> model.check("Pippin", List.of("LeftKnee", "RightKnee"), List.of("PippinTSWalk")))
                .isInstanceOf(ModelCheckException.class)
                .hasMessageContaining("model " + resource)
                .hasMessageContaining("no joint RightKnee")
                .satisfies(e -> assertThat(((ModelCheckException) e).problems()).hasSize(1));
    }

    @Test
    void everythingMissingIsListed() throws IOException {
        AgentModel model = AgentModel.load(AgentModelTest.class, "Pippin.x3d");

        assertThat(model.problems("Merry", List.of("Neck"), List.of("MerryTSJump", "PippinWalkKnee")))
                .containsExactly(
                        "no Transform named after the agent: the model has no node DEF 'Merry'",
                        "no joint Neck: the model has no node DEF 'Neck'",
                        "no time sensor MerryTSJump: the model has no node DEF 'MerryTSJump'",
                        "time sensor PippinWalkKnee is a OrientationInterpolator, expected a TimeSensor");
    }

    @Test
    void theX3dScanReadsElementsAndTheirDefs() throws IOException {
        AgentModel model = AgentModel.load(AgentModelTest.class, "Pippin.x3d");

        assertThat(model.nodes()).containsEntry("Pippin", "Transform").containsEntry("PippinBody", "Transform")
                .containsEntry("LeftKnee", "Transform").containsEntry("PippinTSWalk", "TimeSensor");
        assertThat(model.format()).isEqualTo(ModelFormat.X3D);
    }

    @Test
    void vrmlCommentsAndStringsHoldNoNodes() throws IOException {
        AgentModel model = AgentModel.load(AgentModelTest.class, "Pippin.wrl");

        assertThat(model.nodes()).containsKeys("Pippin", "LeftKnee", "PippinMover", "PippinTSWalk")
                .doesNotContainKeys("RightKnee", "Fake");
    }

    @Test
    void aModelRenamedForAnotherAgentPassesForIt() throws IOException {
        for (String resource : List.of("Pippin.x3d", "Pippin.wrl", "Pippin.gltf")) {
            AgentModel model = AgentModel.load(AgentModelTest.class, resource).renamed("Pippin", "Pippin2");

            assertThat(model.problems("Pippin2", List.of("LeftKnee"), List.of("Pippin2TSWalk"))).as(resource).isEmpty();
            String text = new String(model.bytes(), StandardCharsets.UTF_8);
            assertThat(text).as(resource).doesNotContain("\"Pippin\"").doesNotContain("DEF Pippin ");
        }
    }

    @Test
    void aMissingResourceIsNamedWithWhereItWasLookedFor() {
        assertThatThrownBy(() -> AgentModel.load(AgentModelTest.class, "models/Nobody.x3d"))
                .isInstanceOf(IOException.class)
                .hasMessageContaining("model 'models/Nobody.x3d' not found")
                .hasMessageContaining("/io/orchard/agents/models/Nobody.x3d");
    }

    @ParameterizedTest(name = "{0} is {1}")
    @CsvSource({"a.x3d, X3D", "b.WRL, VRML97", "c.gltf, GLTF", "d.glb, GLB"})
    void theFormatFollowsTheExtension(String file, ModelFormat format) {
        assertThat(AgentModel.formatOf(file)).isEqualTo(format);
    }

    @Test
    void anUnknownExtensionIsRefusedNamingTheKnownOnes() {
        assertThatThrownBy(() -> AgentModel.formatOf("pippin.obj"))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("'pippin.obj' has an unknown extension")
                .hasMessageContaining(".x3d").hasMessageContaining(".wrl").hasMessageContaining(".glb");
    }

    @Test
    void aBinaryGltfIsReadFromItsJsonChunk() {
        byte[] json = "{\"nodes\":[{\"name\":\"Pippin\"}]}  ".getBytes(StandardCharsets.UTF_8);
        java.nio.ByteBuffer glb = java.nio.ByteBuffer.allocate(20 + json.length).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        glb.putInt(0x46546C67).putInt(2).putInt(20 + json.length).putInt(json.length).putInt(0x4E4F534A).put(json);

        AgentModel model = AgentModel.of(ModelFormat.GLB, glb.array(), "pippin.glb");

        assertThat(model.problems("Pippin", List.of(), List.of())).isEmpty();
    }

    @Test
    void aGltfWithItsBufferAndTextureInFilesNextToItIsSentAsAZipOfThem() throws IOException {
        AgentModel model = AgentModel.load(AgentModelTest.class, "split/Split.gltf");

        assertThat(model.spec().format()).isEqualTo(ModelFormat.ZIP);
        io.orchard.protocol.value.ModelArchive sent = io.orchard.protocol.value.ModelArchive.read(model.spec().bytes());
        assertThat(sent.modelPath()).isEqualTo("Split.gltf");
        assertThat(sent.paths()).containsExactly("Split.gltf", "Split.bin", "textures/Split skin.png");
        assertThat(sent.file("Split.bin").orElseThrow()).hasSize(68);
        assertThat(sent.resolve("Split.gltf", "textures/Split%20skin.png")).isEqualTo("textures/Split skin.png");
        assertThat(model.problems("Split", List.of("node#1"), List.of("clip#0"))).isEmpty();
    }

    @Test
    void aFileOutsideTheModelsFolderIsRefusedByItsUri() {
        assertThatThrownBy(() -> AgentModel.load(AgentModelTest.class, "split/Escape.gltf"))
                .isInstanceOf(IOException.class)
                .hasMessageContaining("buffers[1].uri '../Pippin.gltf' leaves the model's folder");
    }

    @Test
    void aUrlIsNeverFetched() {
        assertThatThrownBy(() -> AgentModel.load(AgentModelTest.class, "split/Remote.gltf"))
                .isInstanceOf(IOException.class)
                .hasMessageContaining("buffers[0].uri 'https://example.com/Split.bin' is not a path relative to the model");
    }

    @Test
    void unnamedGltfNodesAndClipsAreKnownByTheirIndexNames() throws IOException {
        AgentModel model = AgentModel.load(AgentModelTest.class, "split/Split.gltf");

        assertThat(model.nodes()).containsKeys("Split", "node#1", "clip#0").doesNotContainKey("node#0");
        assertThat(model.problems("Split", List.of("node#2"), List.of("clip#1")))
                .containsExactly("no joint node#2: the model has no node DEF 'node#2'",
                        "no time sensor clip#1: the model has no animation named 'clip#1'");
    }
}
