package io.orchard.viewer.model;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.ModelFormat;
import java.nio.charset.StandardCharsets;
import java.util.Optional;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

class ModelFormatsTest {

    @ParameterizedTest(name = "{0} -> {1}")
    @CsvSource(nullValues = "none", value = {
        "guppy.wrl, VRML97",
        "GUPPY.WRL, VRML97",
        "guppy.vrml, VRML97",
        "guppy.x3d, X3D",
        "guppy.gltf, GLTF",
        "models/guppy.glb, GLB",
        "guppy.wrz, none",
        "guppy.x3dz, none",
        "guppy, none"})
    void formatIsTakenFromTheFileExtension(String fileName, ModelFormat expected) {
        assertThat(ModelFormats.fromFileName(fileName)).isEqualTo(Optional.ofNullable(expected));
    }

    static Stream<Arguments> firstBytes() {
        return Stream.of(
                Arguments.of("#VRML V2.0 utf8\nGroup {}", ModelFormat.VRML97),
                Arguments.of("\uFEFF#VRML V2.0 utf8", ModelFormat.VRML97),
                Arguments.of("<?xml version='1.0'?><X3D/>", ModelFormat.X3D),
                Arguments.of("  <X3D profile='Immersive'/>", ModelFormat.X3D),
                Arguments.of("{\"asset\": {\"version\": \"2.0\"}}", ModelFormat.GLTF),
                Arguments.of("glTF....", ModelFormat.GLB),
                Arguments.of("#VRML V1.0 ascii", null),
                Arguments.of("<html/>", null),
                Arguments.of("{}", null));
    }

    @ParameterizedTest(name = "{1}: {0}")
    @MethodSource("firstBytes")
    void formatIsDetectedFromTheFirstBytes(String text, ModelFormat expected) {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);

        assertThat(ModelFormats.detect(bytes)).isEqualTo(Optional.ofNullable(expected));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        "agent.x3d| #VRML V2.0 utf8| VRML97",
        "agent.wrl| garbage| VRML97"})
    void detectedContentWinsOverTheFileName(String fileName, String text, ModelFormat expected) {
        assertThat(ModelFormats.detect(fileName, text.getBytes(StandardCharsets.UTF_8)))
                .contains(expected);
    }
}
