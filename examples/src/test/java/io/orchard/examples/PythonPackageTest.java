package io.orchard.examples;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.model.ModelInfo;
import io.orchard.protocol.StrictJson;
import io.orchard.protocol.value.ModelArchive;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import java.util.zip.CRC32;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * The Python package {@code orchard-world} (python/) passes its own tests: the client against real
 * servers, PettingZoo's and Gymnasium's checks of its environments, a game of a Python agent. They
 * run with pytest in a virtual environment the build makes under target/, into which pip installs
 * the package and its dependencies from PyPI; the servers they start run on this test's class path.
 * And its pure-Python {@code model_info} reads the repository's models as {@link ModelInfo} does.
 */
class PythonPackageTest {

    private static final JsonMapper JSON = StrictJson.builder().build();
    private static final Path ROOT = PythonVenv.PACKAGE.getParent();
    /** The repository's own authored models, and those authored for the Python package's tests. */
    private static final List<String> MODEL_FOLDERS = List.of("agents/src/test/resources", "agents/src/main/resources",
            "viewer/src/test/resources", "viewer/src/main/resources", "web/src/test/resources", "python/tests/models");

    @TempDir
    Path dir;

    @Test
    void thePythonPackagesTestsPassAgainstRealServers() throws Exception {
        String output = PythonVenv.run(List.of(PythonVenv.python().toString(), "-m", "pytest", "-q", "-p",
                "no:cacheprovider", PythonVenv.PACKAGE.resolve("tests").toString()), 30);
        Matcher passed = Pattern.compile("(\\d+) passed").matcher(output);
        assertThat(passed.find()).as(output).isTrue();
        assertThat(Integer.parseInt(passed.group(1))).as(output).isGreaterThanOrEqualTo(30);
        assertThat(Pattern.compile("\\d+ (failed|skipped|errors?)\\b").matcher(output).find()).as(output).isFalse();
    }

    @Test
    void pythonsModelInfoGivesTheJsonAndTheTextOfJavasForEveryModelAndRefusesWhatJavaRefuses() throws Exception {
        List<Path> models = new ArrayList<>(repositoryModels());
        assertThat(models).hasSizeGreaterThanOrEqualTo(15);
        models.addAll(authoredHere());
        List<String> command = new ArrayList<>(List.of(PythonVenv.python().toString(), "-m", "orchard_world.model",
                "--json"));
        models.forEach(m -> command.add(m.toString()));
        String[] lines = PythonVenv.output(command, 5).out().split("\n");
        assertThat(lines).hasSize(models.size());

        StringBuilder javaText = new StringBuilder();
        List<String> read = new ArrayList<>(List.of(PythonVenv.python().toString(), "-m", "orchard_world.model"));
        List<String> refused = new ArrayList<>();
        for (int i = 0; i < models.size(); i++) {
            JsonNode java;
            try {
                ModelInfo info = ModelInfo.read(models.get(i));
                java = JSON.readTree(info.toJson());
                javaText.append(info.toText());
                read.add(models.get(i).toString());
            } catch (IOException e) {
                java = JSON.nullNode();
                refused.add(models.get(i).getFileName().toString());
            }
            JsonNode python = JSON.readTree(lines[i]);
            assertThat(same(java, python)).as("%s:%n Java   %s%n Python %s", models.get(i), java, python).isTrue();
        }
        assertThat(refused).as("the broken models written here, and they alone, are refused").containsExactly(
                "two.zip", "none.zip", "escape.zip", "bomb.zip", "large.zip", "Broken.x3d", "Entity.x3d", "Twice.gltf",
                "Old.wrl");
        assertThat(PythonVenv.run(read, 5)).isEqualTo(javaText.toString());
    }

    private static List<Path> repositoryModels() throws IOException {
        List<Path> models = new ArrayList<>();
        for (String folder : MODEL_FOLDERS) {
            try (Stream<Path> files = Files.walk(ROOT.resolve(folder))) {
                files.filter(f -> f.toString().matches(".*\\.(gltf|glb|x3d|wrl)$")).sorted().forEach(models::add);
            }
        }
        return models;
    }

    /** Zips of models, good and refused, and broken models, written for this test. */
    private List<Path> authoredHere() throws IOException {
        Path split = ROOT.resolve("agents/src/test/resources/io/orchard/agents/split");
        Map<String, byte[]> files = new LinkedHashMap<>();
        files.put("Split/Split.gltf", Files.readAllBytes(split.resolve("Split.gltf")));
        files.put("Split/Split.bin", Files.readAllBytes(split.resolve("Split.bin")));
        files.put("Split/textures/Split skin.png", Files.readAllBytes(split.resolve("textures/Split skin.png")));
        files.put("Split/extra/Other.x3d", "<X3D><Scene/></X3D>".getBytes(StandardCharsets.UTF_8));
        List<Path> written = new ArrayList<>(List.of(
                Files.write(dir.resolve("split.zip"), ModelArchive.pack(files)),
                zip("stored.zip", true, Map.of("Kite.wrl", model("Kite.wrl"))),
                zip("two.zip", false, Map.of("a.gltf", model("Giant.gltf"), "b.wrl", model("Kite.wrl"))),
                zip("none.zip", false, Map.of("readme.txt", new byte[] {'h', 'i'})),
                zip("escape.zip", false, Map.of("../Giant.gltf", model("Giant.gltf"))),
                zip("bomb.zip", false, Map.of("Bomb.gltf", new byte[1 << 20])),
                zip("large.zip", false, Map.of("Large.gltf", new byte[5 << 20]))));
        written.add(Files.writeString(dir.resolve("Broken.x3d"), "<X3D><Scene><Transform DEF='A'></Scene></X3D>"));
        written.add(Files.writeString(dir.resolve("Entity.x3d"), "<!DOCTYPE X3D [<!ENTITY far SYSTEM 'file:///etc/"
                + "hostname'>]><X3D><Scene><Transform DEF='&far;'/></Scene></X3D>"));
        written.add(Files.writeString(dir.resolve("Twice.gltf"), "{\"nodes\": [], \"nodes\": [{\"name\": \"A\"}]}"));
        written.add(Files.writeString(dir.resolve("Old.wrl"), "#VRML V1.0 ascii\nSeparator { }\n"));
        return written;
    }

    private static byte[] model(String name) throws IOException {
        return Files.readAllBytes(ROOT.resolve("python/tests/models").resolve(name));
    }

    /** A zip written by hand rather than by {@link ModelArchive#pack}, which refuses a bad name. */
    private Path zip(String name, boolean stored, Map<String, byte[]> entries) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ZipOutputStream zip = new ZipOutputStream(bytes, StandardCharsets.UTF_8)) {
            for (Map.Entry<String, byte[]> entry : new TreeMap<>(entries).entrySet()) {
                ZipEntry e = new ZipEntry(entry.getKey());
                if (stored) {
                    CRC32 crc = new CRC32();
                    crc.update(entry.getValue());
                    e.setMethod(ZipEntry.STORED);
                    e.setSize(entry.getValue().length);
                    e.setCrc(crc.getValue());
                }
                zip.putNextEntry(e);
                zip.write(entry.getValue());
                zip.closeEntry();
            }
        }
        return Files.write(dir.resolve(name), bytes.toByteArray());
    }

    /** The same JSON, numbers within rounding (Java's and Python's sine may differ in the last bit). */
    private static boolean same(JsonNode a, JsonNode b) {
        if (a.isNumber() && b.isNumber()) {
            double x = a.doubleValue();
            double y = b.doubleValue();
            return Math.abs(x - y) <= 1e-12 * Math.max(1, Math.max(Math.abs(x), Math.abs(y)));
        }
        if (a.isArray() && b.isArray() || a.isObject() && b.isObject()) {
            if (a.size() != b.size()
                    || a.isObject() && !List.copyOf(a.propertyNames()).equals(List.copyOf(b.propertyNames()))) {
                return false;
            }
            Iterator<JsonNode> x = a.values().iterator();
            Iterator<JsonNode> y = b.values().iterator();
            while (x.hasNext()) {
                if (!same(x.next(), y.next())) {
                    return false;
                }
            }
            return true;
        }
        return a.equals(b);
    }
}
