package io.orchard.viewer.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.value.ModelFormat;
import io.orchard.viewer.model.ModelException.Kind;
import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Base64;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import java.util.zip.CRC32;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Hostile and malformed models: each is refused with a {@link ModelException} of the expected
 * kind whose message names the problem, quickly, without another exception type.
 */
@Timeout(value = 20, unit = TimeUnit.SECONDS)
class HostileInputTest {

    private static final int DEEP = 100_000;

    static Stream<Arguments> hostileModels() {
        return Stream.of(
                // XML entities: nothing is expanded, nothing is read.
                refused("X3D external entity to a local file (XXE)", ModelFormat.X3D, xml(
                        "<!DOCTYPE X3D [<!ENTITY xxe SYSTEM \"file:///etc/passwd\">]>",
                        "<WorldInfo title=\"&xxe;\"/>"), Kind.UNSAFE, "entit"),
                refused("X3D external parameter entity", ModelFormat.X3D, xml(
                        "<!DOCTYPE X3D [<!ENTITY % remote SYSTEM \"http://127.0.0.1:9/x.dtd\">"
                                + " %remote;]>", "<Group/>"), Kind.UNSAFE, "entit"),
                refused("X3D billion laughs", ModelFormat.X3D, xml(billionLaughsDoctype(),
                        "<WorldInfo title=\"&lol9;\"/>"), Kind.UNSAFE, "entit"),
                refused("X3D undeclared entity reference", ModelFormat.X3D, xml("",
                        "<WorldInfo title=\"&undeclared;\"/>"), Kind.MALFORMED, "undeclared"),
                // Nesting.
                refused("X3D 100,000-deep nesting", ModelFormat.X3D, xml("",
                        "<Group>".repeat(DEEP) + "</Group>".repeat(DEEP)), Kind.TOO_LARGE,
                        "deeper than 64"),
                refused("VRML97 100,000-deep nesting", ModelFormat.VRML97, TestModels.vrml(
                        "Group { children [ ".repeat(DEEP) + "] }".repeat(DEEP)),
                        Kind.TOO_LARGE, "deeper than 64"),
                refused("VRML97 100,000-deep nesting of unknown nodes", ModelFormat.VRML97,
                        TestModels.vrml("Foo { bar ".repeat(DEEP) + "}".repeat(DEEP)),
                        Kind.TOO_LARGE, "deeper than 64"),
                refused("VRML97 100,000 unclosed brackets", ModelFormat.VRML97,
                        TestModels.vrml("Group { children " + "[".repeat(DEEP)),
                        Kind.MALFORMED, "expected a node"),
                refused("VRML97 USE chain deeper than the limit", ModelFormat.VRML97,
                        TestModels.vrml(useChain(100)), Kind.TOO_LARGE, "USEs repeat"),
                // Size and count.
                refused("VRML97 over 4 MiB", ModelFormat.VRML97, oversized(), Kind.TOO_LARGE,
                        "exceeds the limit of 4194304 bytes"),
                refused("X3D over 4 MiB", ModelFormat.X3D, oversized(), Kind.TOO_LARGE,
                        "exceeds the limit"),
                refused("glTF over 4 MiB", ModelFormat.GLTF, oversized(), Kind.TOO_LARGE,
                        "exceeds the limit"),
                refused("VRML97 with 20,001 nodes", ModelFormat.VRML97,
                        TestModels.vrml("Group {}\n".repeat(20_001)), Kind.TOO_LARGE,
                        "more than 20000 nodes"),
                refused("X3D with 20,001 nodes", ModelFormat.X3D,
                        xml("", "<Group/>".repeat(20_001)), Kind.TOO_LARGE,
                        "more than 20000 nodes"),
                refused("VRML97 USE bomb (each level USEs the previous ten times)",
                        ModelFormat.VRML97, TestModels.vrml(useBomb()), Kind.TOO_LARGE,
                        "counting each USE in full"),
                refused("VRML97 over a million array values", ModelFormat.VRML97,
                        TestModels.vrml("Coordinate { point [ " + "0 0 0 ".repeat(350_000)
                                + "] }"), Kind.TOO_LARGE, "more than 1000000 numbers"),
                // Truncation and garbage.
                refused("VRML97 truncated inside a node", ModelFormat.VRML97, truncated(
                        TestModels.vrml(Figure5Test.FIGURE_5_VRML)), Kind.MALFORMED, ""),
                refused("X3D truncated", ModelFormat.X3D, truncated(
                        TestModels.x3d(Figure5Test.FIGURE_5_X3D)), Kind.MALFORMED, "XML"),
                refused("glTF truncated", ModelFormat.GLTF, truncated(
                        TestModels.resource("walker.gltf")), Kind.MALFORMED, "truncated"),
                refused("GLB truncated", ModelFormat.GLB, truncated(TestModels.walkerGlb()),
                        Kind.MALFORMED, "GLB"),
                refused("VRML97 without its header", ModelFormat.VRML97,
                        "Group {}".getBytes(StandardCharsets.UTF_8), Kind.MALFORMED,
                        "#VRML V2.0 utf8"),
                refused("VRML97 that is not UTF-8", ModelFormat.VRML97, concat(
                        TestModels.vrml("WorldInfo { title \""), new byte[] {(byte) 0xff,
                            (byte) 0xfe}, "\" }".getBytes(StandardCharsets.UTF_8)),
                        Kind.MALFORMED, "UTF-8"),
                refused("X3D that is random bytes", ModelFormat.X3D, garbage(), Kind.MALFORMED,
                        ""),
                refused("glTF that is random bytes", ModelFormat.GLTF, garbage(),
                        Kind.MALFORMED, ""),
                refused("GLB that is random bytes", ModelFormat.GLB, garbage(), Kind.MALFORMED,
                        "GLB"),
                refused("an empty file", ModelFormat.VRML97, new byte[0], Kind.MALFORMED,
                        "empty"),
                refused("X3D whose root is not X3D", ModelFormat.X3D,
                        "<html><body/></html>".getBytes(StandardCharsets.UTF_8),
                        Kind.MALFORMED, "<X3D>"),
                // Names.
                refused("VRML97 USE of an unknown name", ModelFormat.VRML97,
                        TestModels.vrml("Group { children USE Nobody }"), Kind.UNKNOWN_NAME,
                        "USE 'Nobody'"),
                refused("X3D USE of an unknown name", ModelFormat.X3D,
                        TestModels.x3d("<Group USE=\"Nobody\"/>"), Kind.UNKNOWN_NAME,
                        "USE 'Nobody'"),
                refused("VRML97 USE of an enclosing node", ModelFormat.VRML97,
                        TestModels.vrml("DEF Loop Group { children USE Loop }"),
                        Kind.UNKNOWN_NAME, "USE 'Loop'"),
                refused("VRML97 route to a missing field", ModelFormat.VRML97, TestModels.vrml(
                        Figure5Test.FIGURE_5_VRML + "ROUTE GuppyMover.value_changed TO"
                                + " Guppy.set_wobble\n"), Kind.UNKNOWN_NAME,
                        "Transform 'Guppy' has no field 'set_wobble'"),
                refused("X3D route to a missing field", ModelFormat.X3D, TestModels.x3d(
                        Figure5Test.FIGURE_5_X3D + "<ROUTE fromNode=\"GuppyTSMover\" fromField="
                                + "\"fraction_changed\" toNode=\"GuppyMover\" toField=\"oops\"/>"),
                        Kind.UNKNOWN_NAME, "PositionInterpolator 'GuppyMover' has no field"
                                + " 'oops'"),
                refused("VRML97 route to a missing node", ModelFormat.VRML97, TestModels.vrml(
                        Figure5Test.FIGURE_5_VRML + "ROUTE GuppyMover.value_changed TO"
                                + " Ghost.set_translation\n"), Kind.UNKNOWN_NAME,
                        "no node is named 'Ghost'"),
                refused("VRML97 route between fields of different types", ModelFormat.VRML97,
                        TestModels.vrml(Figure5Test.FIGURE_5_VRML + "ROUTE"
                                + " GuppyMover.value_changed TO Guppy.set_rotation\n"),
                        Kind.BAD_VALUE, "sends SFVec3f but set_rotation takes SFRotation"),
                refused("VRML97 route from an eventIn", ModelFormat.VRML97, TestModels.vrml(
                        Figure5Test.FIGURE_5_VRML + "ROUTE GuppyMover.set_fraction TO"
                                + " GuppyMover.set_fraction\n"), Kind.UNKNOWN_NAME,
                        "no field 'set_fraction' that sends events"),
                // Values.
                refused("VRML97 NaN for a number", ModelFormat.VRML97,
                        TestModels.vrml("DEF T Transform { translation 1 NaN 0 }"),
                        Kind.BAD_VALUE, "Transform 'T' field translation: expected a number"
                                + " (SFVec3f) but found 'NaN'"),
                refused("VRML97 letters for a number", ModelFormat.VRML97,
                        TestModels.vrml("Sphere { radius abc }"), Kind.BAD_VALUE,
                        "field radius: expected a number (SFFloat) but found 'abc'"),
                refused("VRML97 malformed number", ModelFormat.VRML97,
                        TestModels.vrml("Sphere { radius 1.2.3 }"), Kind.BAD_VALUE,
                        "found '1.2.3'"),
                refused("VRML97 number beyond float range", ModelFormat.VRML97,
                        TestModels.vrml("Sphere { radius 1e999 }"), Kind.BAD_VALUE,
                        "out of range"),
                refused("VRML97 fraction where an index belongs", ModelFormat.VRML97,
                        TestModels.vrml("IndexedFaceSet { coordIndex [ 0 1 2.5 ] }"),
                        Kind.BAD_VALUE, "expected an integer (MFInt32) but found '2.5'"),
                refused("X3D letters for a number", ModelFormat.X3D,
                        TestModels.x3d("<Transform DEF=\"T\" translation=\"1 x 2\"/>"),
                        Kind.BAD_VALUE, "Transform 'T' field translation: expected a number"),
                refused("X3D too few numbers", ModelFormat.X3D,
                        TestModels.x3d("<Transform DEF=\"T\" rotation=\"0 1 0\"/>"),
                        Kind.MALFORMED, "SFRotation needs 4 numbers but 3 were given"),
                refused("X3D Infinity for a number", ModelFormat.X3D,
                        TestModels.x3d("<Transform scale=\"1 Infinity 1\"/>"),
                        Kind.BAD_VALUE, "found 'Infinity'"),
                refused("VRML97 a number for a boolean", ModelFormat.VRML97,
                        TestModels.vrml("TimeSensor { loop 1 }"), Kind.BAD_VALUE,
                        "expected TRUE or FALSE"),
                refused("VRML97 wrong node type in a node field", ModelFormat.VRML97,
                        TestModels.vrml("Shape { geometry Material {} }"), Kind.BAD_VALUE,
                        "field geometry: expected a geometry node but found Material"),
                refused("X3D wrong node type in a node field", ModelFormat.X3D,
                        TestModels.x3d("<Shape><Material containerField=\"geometry\"/></Shape>"),
                        Kind.BAD_VALUE, "expected a geometry node but found Material"),
                refused("VRML97 value for an eventOut", ModelFormat.VRML97,
                        TestModels.vrml("TimeSensor { fraction_changed 0.5 }"), Kind.BAD_VALUE,
                        "fraction_changed is an eventOut"),
                refused("VRML97 coordIndex outside the points", ModelFormat.VRML97,
                        TestModels.vrml("Shape { geometry IndexedFaceSet { coord Coordinate {"
                                + " point [0 0 0, 1 0 0, 0 1 0] } coordIndex [0 1 7 -1] } }"),
                        Kind.BAD_VALUE, "coordIndex: value 7 at position 2 is outside the 3"
                                + " points"),
                refused("VRML97 interpolator with fewer key values than keys",
                        ModelFormat.VRML97, TestModels.vrml("DEF M PositionInterpolator {"
                                + " key [0 0.5 1] keyValue [0 0 0, 1 1 1] }"), Kind.BAD_VALUE,
                        "has 3 keys but 2 key values"),
                refused("VRML97 negative box size", ModelFormat.VRML97,
                        TestModels.vrml("Shape { geometry Box { size 1 -2 1 } }"),
                        Kind.BAD_VALUE, "field size must be positive"),
                refused("VRML97 zero cycleInterval", ModelFormat.VRML97,
                        TestModels.vrml("DEF Clock TimeSensor { cycleInterval 0 }"),
                        Kind.BAD_VALUE, "cycleInterval must be positive"),
                refused("X3D image texture claiming 100000x100000 pixels", ModelFormat.X3D,
                        TestModels.x3d("<Shape><Appearance><ImageTexture url='\""
                                + pngBombUri() + "\"'/></Appearance><Box/></Shape>"),
                        Kind.TOO_LARGE, "100000x100000 pixels"),
                refused("VRML97 image texture that is a broken PNG", ModelFormat.VRML97,
                        TestModels.vrml("Shape { appearance Appearance { texture ImageTexture {"
                                + " url \"data:image/png;base64,iVBORw0KGgoAAAAAAAA=\" } }"
                                + " geometry Box {} }"), Kind.BAD_VALUE, "embedded image"),
                refused("VRML97 image texture that is not base64", ModelFormat.VRML97,
                        TestModels.vrml("Shape { appearance Appearance { texture ImageTexture {"
                                + " url \"data:image/png;base64,%%%\" } } geometry Box {} }"),
                        Kind.BAD_VALUE, "not valid base64"),
                // glTF.
                refused("glTF buffer pointing at a local file", ModelFormat.GLTF, gltfWith(
                        "\"uri\": \"data:application/octet-stream;base64,",
                        "\"uri\": \"../../../../etc/passwd\", \"ignored\": \""), Kind.UNSAFE,
                        "buffers[0].uri '../../../../etc/passwd' refers to an external"),
                refused("glTF image pointing at a URL", ModelFormat.GLTF, gltfWith(
                        "\"buffers\"", "\"images\": [{\"uri\": \"http://127.0.0.1:9/x.png\"}],"
                                + " \"buffers\""), Kind.UNSAFE, "images[0].uri"),
                refused("glTF 100,000-deep JSON", ModelFormat.GLTF,
                        ("{\"asset\": {\"version\": \"2.0\"}, \"extras\": " + "[".repeat(DEEP)
                                + "]".repeat(DEEP) + "}").getBytes(StandardCharsets.UTF_8),
                        Kind.TOO_LARGE, "nesting depth (65) exceeds the maximum allowed (64)"),
                refused("glTF node that is its own grandchild", ModelFormat.GLTF,
                        ("{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [{\"children\": [1]},"
                                + " {\"children\": [0]}]}").getBytes(StandardCharsets.UTF_8),
                        Kind.MALFORMED, "cycle"),
                refused("glTF accessor of a billion vectors", ModelFormat.GLTF,
                        ("{\"asset\": {\"version\": \"2.0\"}, \"accessors\": [{\"count\":"
                                + " 1000000000, \"type\": \"VEC3\", \"componentType\": 5126}]}")
                                .getBytes(StandardCharsets.UTF_8), Kind.TOO_LARGE,
                        "more than 1000000 values"),
                refused("GLB chunk declaring 1.5 GB", ModelFormat.GLB, glbWithHugeChunk(),
                        Kind.MALFORMED, "declares 1500000000 bytes but the file ends first"),
                refused("glTF version 1", ModelFormat.GLTF,
                        "{\"asset\": {\"version\": \"1.0\"}}".getBytes(StandardCharsets.UTF_8),
                        Kind.UNSUPPORTED, "version 1.0"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("hostileModels")
    void hostileModelIsRefusedWithModelException(String description, ModelFormat format,
                                                 byte[] bytes, Kind kind, String message) {
        assertThatThrownBy(() -> TestModels.load("Guppy", format, bytes))
                .isInstanceOf(ModelException.class)
                .hasMessageContaining(message)
                .satisfies(e -> assertThat(((ModelException) e).kind())
                        .as(e.getMessage()).isEqualTo(kind));
    }

    @Test
    void externalEntityContentNeverAppearsInTheMessage() {
        byte[] bytes = xml("<!DOCTYPE X3D [<!ENTITY xxe SYSTEM \"file:///etc/hostname\">]>",
                "<Group DEF=\"&xxe;\"/>");

        assertThatThrownBy(() -> TestModels.load("Guppy", ModelFormat.X3D, bytes))
                .isInstanceOf(ModelException.class)
                .hasMessageNotContaining(hostname());
    }

    @Test
    void smallerLimitsAreEnforced() {
        ModelLimits tight = ModelLimits.DEFAULTS.withMaxNodes(3).withMaxDepth(2);

        assertThatThrownBy(() -> BodyModels.load("Guppy", ModelFormat.VRML97,
                TestModels.vrml("Group { children [ Group { children Group {} } ] }"),
                TestModels.ASSETS, tight))
                .isInstanceOf(ModelException.class)
                .hasMessageContaining("deeper than 2 levels");
        assertThatThrownBy(() -> BodyModels.load("Guppy", ModelFormat.VRML97,
                TestModels.vrml("Group {} Group {} Group {} Group {}"), TestModels.ASSETS, tight))
                .isInstanceOf(ModelException.class)
                .hasMessageContaining("more than 3 nodes");
    }

    private static Arguments refused(String description, ModelFormat format, byte[] bytes,
                                     Kind kind, String message) {
        return Arguments.of(description, format, bytes, kind, message);
    }

    private static byte[] xml(String doctype, String scene) {
        return ("<?xml version=\"1.0\"?>\n" + doctype + "\n<X3D><Scene>" + scene
                + "</Scene></X3D>").getBytes(StandardCharsets.UTF_8);
    }

    private static String billionLaughsDoctype() {
        StringBuilder doctype = new StringBuilder("<!DOCTYPE X3D [<!ENTITY lol0 \"lol\">");
        for (int i = 1; i <= 9; i++) {
            doctype.append("<!ENTITY lol").append(i).append(" \"")
                    .append(("&lol" + (i - 1) + ";").repeat(10)).append("\">");
        }
        return doctype.append("]>").toString();
    }

    private static String useChain(int length) {
        StringBuilder body = new StringBuilder("DEF N0 Group {}\n");
        for (int i = 1; i < length; i++) {
            body.append("DEF N").append(i).append(" Group { children USE N").append(i - 1)
                    .append(" }\n");
        }
        return body.toString();
    }

    private static String useBomb() {
        StringBuilder body = new StringBuilder("DEF L0 Shape { geometry Box {} }\n");
        for (int i = 1; i <= 9; i++) {
            body.append("DEF L").append(i).append(" Group { children [")
                    .append((" USE L" + (i - 1)).repeat(10)).append(" ] }\n");
        }
        return body.toString();
    }

    private static byte[] oversized() {
        byte[] bytes = new byte[ModelLimits.DEFAULTS.maxInputBytes() + 1];
        Arrays.fill(bytes, (byte) ' ');
        return bytes;
    }

    private static byte[] truncated(byte[] bytes) {
        return Arrays.copyOf(bytes, bytes.length * 2 / 3);
    }

    private static byte[] garbage() {
        byte[] bytes = new byte[4096];
        new java.util.Random(42).nextBytes(bytes);
        return bytes;
    }

    private static byte[] concat(byte[]... parts) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (byte[] part : parts) {
            out.writeBytes(part);
        }
        return out.toByteArray();
    }

    private static byte[] gltfWith(String target, String replacement) {
        String json = new String(TestModels.resource("walker.gltf"), StandardCharsets.UTF_8);
        assertThat(json).contains(target);
        return json.replace(target, replacement).getBytes(StandardCharsets.UTF_8);
    }

    /** The walker GLB with one more chunk whose header claims 1.5 GB that are not there. */
    private static byte[] glbWithHugeChunk() {
        byte[] glb = TestModels.walkerGlb();
        ByteBuffer bigger = ByteBuffer.allocate(glb.length + 8).order(ByteOrder.LITTLE_ENDIAN);
        bigger.put(glb).putInt(1_500_000_000).putInt(0x12345678);
        bigger.putInt(8, bigger.capacity());
        return bigger.array();
    }

    /** A PNG whose header claims 100000x100000 pixels; decoding it would need 40 GB. */
    private static String pngBombUri() {
        ByteBuffer ihdr = ByteBuffer.allocate(13).order(ByteOrder.BIG_ENDIAN);
        ihdr.putInt(100_000).putInt(100_000).put((byte) 8).put((byte) 6).put((byte) 0)
                .put((byte) 0).put((byte) 0);
        ByteArrayOutputStream png = new ByteArrayOutputStream();
        png.writeBytes(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'});
        chunk(png, "IHDR", ihdr.array());
        chunk(png, "IEND", new byte[0]);
        return "data:image/png;base64," + Base64.getEncoder().encodeToString(png.toByteArray());
    }

    private static void chunk(ByteArrayOutputStream out, String type, byte[] data) {
        byte[] typeBytes = type.getBytes(StandardCharsets.US_ASCII);
        out.writeBytes(ByteBuffer.allocate(4).putInt(data.length).array());
        out.writeBytes(typeBytes);
        out.writeBytes(data);
        CRC32 crc = new CRC32();
        crc.update(typeBytes);
        crc.update(data);
        out.writeBytes(ByteBuffer.allocate(4).putInt((int) crc.getValue()).array());
    }

    private static String hostname() {
        try {
            return new String(java.nio.file.Files.readAllBytes(
                    java.nio.file.Path.of("/etc/hostname")), StandardCharsets.UTF_8).strip();
        } catch (java.io.IOException e) {
            return "no such file";
        }
    }
}
