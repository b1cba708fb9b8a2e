package io.orchard.examples;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code ./orchard model-info}: a model's joints, clips, size and units, as text and as JSON; bad files refused. */
class ModelInfoCommandTest {

    private static final String X3D = "<X3D><head><unit category='length' name='centimetre' conversionFactor='0.01'/>"
            + "</head><Scene><Transform DEF='Totem'><Transform DEF='Head' translation='0 150 0'><Shape><Box"
            + " size='40 60 40'/></Shape></Transform></Transform><TimeSensor DEF='TotemTSNod'/></Scene></X3D>";

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    @TempDir
    Path dir;

    private int run(String... args) {
        String[] line = new String[args.length + 1];
        line[0] = "model-info";
        System.arraycopy(args, 0, line, 1, args.length);
        return Orchard.run(line, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
    }

    private String out() {
        return out.toString(StandardCharsets.UTF_8);
    }

    private String err() {
        return err.toString(StandardCharsets.UTF_8);
    }

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text, StandardCharsets.UTF_8);
    }

    @Test
    void printsTheJointsClipsSizeAndUnits() throws IOException {
        assertThat(run(write("totem.x3d", X3D).toString())).isZero();

        assertThat(out()).isEqualTo("""
                totem.x3d: x3d
                roots: Totem
                joints (2): Totem, Head
                clips (1): TotemTSNod
                size: 40.00 x 60.00 x 40.00 centimetres (x, y up, z); from (-20.00, 120.0, -20.00) to (20.00, 180.0, 20.00)
                units: centimetre (0.01 m)
                """);
    }

    @Test
    void printsOneJsonObjectWithJson() throws IOException {
        assertThat(run("--json", write("totem.x3d", X3D).toString())).isZero();

        assertThat(out()).isEqualTo("{\"file\":\"totem.x3d\",\"format\":\"x3d\",\"inside\":null,\"roots\":[\"Totem\"],"
                + "\"joints\":[\"Totem\",\"Head\"],\"clips\":[\"TotemTSNod\"],\"bounds\":{\"min\":[-20.0,120.0,-20.0],"
                + "\"max\":[20.0,180.0,20.0],\"size\":[40.0,60.0,40.0]},\"units\":{\"name\":\"centimetre\","
                + "\"metres\":0.01,\"declared\":true},\"notes\":[]}\n");
    }

    @Test
    void aFileThatIsNotThereOrNotAModelIsAUsageError() throws IOException {
        assertThat(run(dir.resolve("missing.gltf").toString())).isEqualTo(2);
        assertThat(err()).contains("'" + dir.resolve("missing.gltf") + "' is not a file");
        assertThat(run(write("cat.obj", "v 0 0 0").toString())).isEqualTo(2);
        assertThat(err()).contains("cat.obj: expected a model file, .gltf, .glb, .x3d, .wrl or .zip");
    }

    @Test
    void aBrokenModelFailsWith1NamingIt() throws IOException {
        assertThat(run(write("broken.gltf", "{\"nodes\": [").toString())).isEqualTo(1);
        assertThat(err()).contains("orchard model-info: broken.gltf:");
    }
}
