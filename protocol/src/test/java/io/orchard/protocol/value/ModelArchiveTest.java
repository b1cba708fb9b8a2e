package io.orchard.protocol.value;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Random;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Zips of a model's files: what is unpacked, and every unsafe archive refused by name. */
class ModelArchiveTest {

    private static final byte[] GLTF = "{\"asset\":{\"version\":\"2.0\"}}".getBytes(StandardCharsets.UTF_8);

    /** A zip written as a careless tool would: no check of the names. */
    private static byte[] rawZip(Map<String, byte[]> files) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (ZipOutputStream zip = new ZipOutputStream(out, StandardCharsets.UTF_8)) {
            for (Map.Entry<String, byte[]> file : files.entrySet()) {
                zip.putNextEntry(new ZipEntry(file.getKey()));
                zip.write(file.getValue());
                zip.closeEntry();
            }
        }
        return out.toByteArray();
    }

    private static Map<String, byte[]> files(Object... pathsAndBytes) {
        Map<String, byte[]> files = new LinkedHashMap<>();
        for (int i = 0; i < pathsAndBytes.length; i += 2) {
            files.put((String) pathsAndBytes[i], (byte[]) pathsAndBytes[i + 1]);
        }
        return files;
    }

    @Test
    void aModelWithItsFilesIsUnpackedAndItsReferencesResolveInsideTheArchive() {
        byte[] zip = ModelArchive.pack(files("Cat/scene.gltf", GLTF, "Cat/scene.bin", new byte[] {1, 2, 3},
                "Cat/textures/fur.png", new byte[] {4}, "Cat/sub/inner.gltf", GLTF));

        ModelArchive archive = ModelArchive.read(zip);

        assertThat(archive.modelPath()).isEqualTo("Cat/scene.gltf");
        assertThat(archive.modelFormat()).isEqualTo(ModelFormat.GLTF);
        assertThat(archive.modelBytes()).isEqualTo(GLTF);
        assertThat(archive.resolve("Cat/scene.gltf", "scene.bin")).isEqualTo("Cat/scene.bin");
        assertThat(archive.resolve("Cat/scene.gltf", "./textures/fur%2Epng")).isEqualTo("Cat/textures/fur.png");
        assertThat(archive.resolve("Cat/sub/inner.gltf", "../scene.bin")).isEqualTo("Cat/scene.bin");
        assertThat(archive.file("Cat/scene.bin")).hasValue(new byte[] {1, 2, 3});
    }

    @ParameterizedTest
    @ValueSource(strings = {"http://example.org/a.bin", "/etc/passwd", "../../outside.bin", "file:a.bin",
        "missing.bin"})
    void aReferenceOutsideTheArchiveIsRefusedByName(String uri) {
        ModelArchive archive = ModelArchive.read(ModelArchive.pack(files("scene.gltf", GLTF, "a.bin", new byte[1])));

        assertThatThrownBy(() -> archive.resolve("scene.gltf", uri))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("'" + uri + "'");
    }

    @ParameterizedTest
    @ValueSource(strings = {"/abs/model.x3d", "../model.x3d", "a/../../model.x3d", "C:/model.x3d",
        "a\\model.x3d", "a//model.x3d", "./model.x3d"})
    void anEntryNameThatCouldLeaveTheArchiveIsRefusedByName(String name) throws IOException {
        byte[] zip = rawZip(files("scene.x3d", GLTF, name, GLTF));

        assertThatThrownBy(() -> ModelArchive.read(zip)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("entry '" + name + "'");
    }

    @Test
    void twoEntriesOfOneNameAreRefused() throws IOException {
        byte[] zip = rawZip(files("scene.x3d", GLTF, "scenf.x3d", GLTF));
        replaceAll(zip, "scenf.x3d", "scene.x3d");

        assertThatThrownBy(() -> ModelArchive.read(zip)).hasMessageContaining("two entries named 'scene.x3d'");
    }

    @Test
    void aSymbolicLinkIsRefusedByName() throws IOException {
        byte[] zip = rawZip(files("scene.x3d", GLTF, "tex.png", "/etc/passwd".getBytes(StandardCharsets.UTF_8)));
        // Mark the second entry of the central directory as a Unix symbolic link, as `zip -y` writes one.
        ByteBuffer buffer = ByteBuffer.wrap(zip).order(ByteOrder.LITTLE_ENDIAN);
        int central = lastIndexOf(zip, "tex.png") - 46;
        assertThat(buffer.getInt(central)).isEqualTo(0x02014b50);
        buffer.putShort(central + 4, (short) (3 << 8 | 20));
        buffer.putInt(central + 38, 0120777 << 16);

        assertThatThrownBy(() -> ModelArchive.read(zip)).hasMessageContaining("'tex.png' is a symbolic link");
    }

    @Test
    void tooManyEntriesAreRefused() throws IOException {
        Map<String, byte[]> many = new LinkedHashMap<>();
        many.put("scene.x3d", GLTF);
        for (int i = 0; i < ModelArchive.MAX_ENTRIES; i++) {
            many.put("t/" + i + ".png", new byte[1]);
        }

        assertThatThrownBy(() -> ModelArchive.read(rawZip(many)))
                .hasMessageContaining("entries, at most " + ModelArchive.MAX_ENTRIES);
    }

    @Test
    void aZipBombIsRefusedByItsRatio() throws IOException {
        byte[] zeros = new byte[3 * 1024 * 1024];
        byte[] zip = rawZip(files("scene.gltf", GLTF, "scene.bin", zeros));
        assertThat(zip.length * (long) ModelArchive.MAX_RATIO).isLessThan(zeros.length);

        assertThatThrownBy(() -> ModelArchive.read(zip)).hasMessageContaining("refused as a zip bomb")
                .hasMessageContaining("'scene.bin'");
    }

    @Test
    void filesUnpackingBeyondTheModelLimitAreRefused() throws IOException {
        // Sixteen symbols a byte: compresses about two to one, no bomb by its ratio, but 5 MiB unpacked.
        Random random = new Random(7);
        byte[] half = new byte[5 * 1024 * 1024 / 2];
        for (int i = 0; i < half.length; i++) {
            half[i] = (byte) ('a' + random.nextInt(16));
        }
        byte[] zip = rawZip(files("scene.gltf", GLTF, "a.bin", half, "b.bin", half));

        assertThatThrownBy(() -> ModelArchive.read(zip))
                .hasMessageContaining("unpack to more than " + ModelSpec.MAX_MODEL_BYTES + " bytes (at entry 'b.bin')");
    }

    @Test
    void anArchiveMustHoldExactlyOneModelAtItsShallowestLevel() throws IOException {
        assertThatThrownBy(() -> ModelArchive.read(rawZip(files("a.png", new byte[1]))))
                .hasMessageContaining("holds no model file");
        assertThatThrownBy(() -> ModelArchive.read(rawZip(files("a.x3d", GLTF, "b.gltf", GLTF))))
                .hasMessageContaining("2 model files side by side, [a.x3d, b.gltf]");
        assertThat(ModelArchive.read(rawZip(files("inlines/door.x3d", GLTF, "House.X3D", GLTF))).modelPath())
                .isEqualTo("House.X3D");
    }

    @Test
    void somethingThatIsNotAZipIsRefused() {
        assertThatThrownBy(() -> ModelArchive.read(GLTF)).hasMessageContaining("does not start with a zip entry");
    }

    @Test
    void packingTheSameFilesGivesTheSameBytes() {
        Map<String, byte[]> files = files("scene.gltf", GLTF, "scene.bin", new byte[] {9});

        assertThat(ModelArchive.pack(files)).isEqualTo(ModelArchive.pack(files));
    }

    private static void replaceAll(byte[] bytes, String from, String to) {
        byte[] a = from.getBytes(StandardCharsets.UTF_8);
        byte[] b = to.getBytes(StandardCharsets.UTF_8);
        for (int i = 0; i + a.length <= bytes.length; i++) {
            if (java.util.Arrays.equals(bytes, i, i + a.length, a, 0, a.length)) {
                System.arraycopy(b, 0, bytes, i, b.length);
            }
        }
    }

    private static int lastIndexOf(byte[] bytes, String text) {
        byte[] a = text.getBytes(StandardCharsets.UTF_8);
        for (int i = bytes.length - a.length; i >= 0; i--) {
            if (java.util.Arrays.equals(bytes, i, i + a.length, a, 0, a.length)) {
                return i;
            }
        }
        return -1;
    }
}
