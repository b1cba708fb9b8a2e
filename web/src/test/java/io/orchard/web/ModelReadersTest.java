package io.orchard.web;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.server.WorldServer;
import java.time.Duration;
import java.util.Locale;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * The page's X3D and VRML97 readers and its event graph, run in the page's own modules in Debian's
 * headless Chromium (its XML parser is the browser's): a model is untrusted input, so each way of
 * being malformed or too large is refused with a message naming what is wrong, never a hang or a
 * page that stops; and what is read is built as the formats say (DEF and USE, ROUTEs, PROTOs
 * skipped, TimeSensors started late still landing where they end).
 */
class ModelReadersTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();
    private static WorldServer server;
    private static Chromium browser;

    @BeforeAll
    static void openThePage() throws Exception {
        assertThat(Chromium.installed()).as("Debian's chromium at %s (README: what a bare machine needs)",
                Chromium.BINARY).isTrue();
        server = WorldServer.builder().port(0).httpPort(0).seed(7).start();
        browser = Chromium.start(800, 600);
        browser.open("http://127.0.0.1:" + server.httpPort().orElseThrow() + "/");
        browser.await("window.orchard && orchard.ready", Duration.ofSeconds(60));
    }

    @AfterAll
    static void stop() {
        if (browser != null) {
            browser.close();
        }
        if (server != null) {
            server.close();
        }
    }

    /**
     * Reads a model in the page and builds it for an agent named A: its DEF'd Transforms, TimeSensors,
     * its meshes and geometries; or the error, by name and message.
     */
    private static JsonNode read(String format, String text) {
        String reader = format.equals("x3d") ? "readX3d" : "readVrml97";
        return browser.evaluate("(async () => {"
                + " const reading = await import('/models/" + (format.equals("x3d") ? "x3d" : "vrml97") + ".js');"
                + " const building = await import('/models/build.js');"
                + " try {"
                + "  const built = building.buildScene(reading." + reader + "(" + JSON.writeValueAsString(text) + "), 'A');"
                + "  const meshes = [];"
                + "  built.object.traverse(o => o.isMesh && meshes.push(o));"
                + "  return { transforms: [...built.transforms.keys()], sensors: [...built.sensors.keys()],"
                + "   meshes: meshes.length, geometries: new Set(meshes.map(m => m.geometry)).size };"
                + " } catch (e) { return { error: e.constructor.name + ': ' + e.message }; }"
                + "})()");
    }

    private static String x3d(String scene) {
        return "<?xml version='1.0'?><X3D profile='Interchange' version='3.3'><Scene>" + scene + "</Scene></X3D>";
    }

    private static String error(JsonNode result) {
        assertThat(result.has("error")).as("refused, but was read: %s", result).isTrue();
        return result.get("error").asString();
    }

    @Test
    void x3dThatIsNotWellFormedXmlIsRefused() {
        assertThat(error(read("x3d", "<X3D><Scene><Transform></Scene>"))).startsWith("ModelError")
                .contains("not well-formed XML");
    }

    @Test
    void x3dWhoseRootIsNotX3dIsRefused() {
        assertThat(error(read("x3d", "<Scene><Transform/></Scene>"))).contains("root element is <Scene>, expected <X3D>");
    }

    @Test
    void aUseOfANameNotDefinedBeforeIsRefused() {
        assertThat(error(read("x3d", x3d("<Transform DEF='A'><Group USE='Later'/></Transform><Group DEF='Later'/>"))))
                .contains("USE 'Later' names no node DEF'd before it");
        assertThat(error(read("vrml97", "#VRML V2.0 utf8\nTransform { children USE Nothing }")))
                .contains("line 2:").contains("USE Nothing names no node DEF'd before it");
    }

    @Test
    void aUseInsideItsOwnDefCannotMakeACycle() {
        assertThat(error(read("x3d", x3d("<Group DEF='Loop'><Group USE='Loop'/></Group>"))))
                .contains("USE 'Loop' names no node DEF'd before it");
    }

    @Test
    void nestingDeeperThan64LevelsIsRefused() {
        String deep = "<Transform>".repeat(70) + "</Transform>".repeat(70);
        assertThat(error(read("x3d", x3d(deep)))).contains("nesting deeper than 64 levels");
        String vrml = "#VRML V2.0 utf8\n" + "Transform { children [ ".repeat(70) + "] } ".repeat(70);
        assertThat(error(read("vrml97", vrml))).contains("nesting deeper than 64 levels");
    }

    @Test
    void usesThatMultiplyPastTheLimitAreRefusedQuickly() {
        // Each level uses the one before twice: 2^30 objects from 31 elements.
        StringBuilder scene = new StringBuilder("<Shape DEF='L0'><Box/></Shape>"
                + "<Group DEF='L1'><Shape USE='L0'/><Shape USE='L0'/></Group>");
        for (int i = 2; i <= 30; i++) {
            scene.append(String.format(Locale.ROOT, "<Group DEF='L%d'><Group USE='L%d'/><Group USE='L%d'/></Group>", i,
                    i - 1, i - 1));
        }
        long start = System.nanoTime();
        String refused = error(read("x3d", x3d(scene.toString())));
        assertThat(refused).contains("more than 20000 objects (counting each USE)");
        assertThat(Duration.ofNanos(System.nanoTime() - start)).as("refused, not built").isLessThan(Duration.ofSeconds(30));
    }

    @Test
    void aFieldThatIsNotNumbersOrOfTheWrongWidthIsRefusedNamingIt() {
        assertThat(error(read("x3d", x3d("<Shape><Box size='1 x 1'/></Shape>"))))
                .contains("Box field size must hold numbers, but has 'x'");
        assertThat(error(read("x3d", x3d("<Transform DEF='T' translation='1 2'/>"))))
                .contains("Transform 'T' field translation must hold 3 numbers, has 2");
        assertThat(error(read("x3d", x3d("<Shape><IndexedFaceSet coordIndex='0 1 2 -1'>"
                + "<Coordinate point='0 0 0, 1 0 0'/></IndexedFaceSet></Shape>"))))
                .contains("coordIndex 2 is past its 2 points");
    }

    @Test
    void x3dDefAndUseShareTheirGeometryAndNamedTransformsAreJoints() {
        JsonNode built = read("x3d", x3d("<Transform DEF='A'><Transform DEF='Arm'><Shape DEF='S'><Box/></Shape>"
                + "</Transform><Transform DEF='Leg'><Shape USE='S'/></Transform><Shape USE='S'/></Transform>"
                + "<TimeSensor DEF='ATSWave'/><ROUTE fromNode='ATSWave' fromField='fraction_changed' toNode='Gone'"
                + " toField='set_fraction'/>"));
        assertThat(built.has("error")).as("%s", built).isFalse();
        assertThat(strings(built.get("transforms"))).containsExactlyInAnyOrder("A", "Arm", "Leg");
        assertThat(strings(built.get("sensors"))).containsExactly("ATSWave");
        assertThat(built.get("meshes").asInt()).as("a mesh for each use").isEqualTo(3);
        assertThat(built.get("geometries").asInt()).as("one geometry for one Box").isEqualTo(1);
    }

    @Test
    void vrml97WithoutItsHeaderOrWithAStringLeftOpenIsRefused() {
        assertThat(error(read("vrml97", "Transform {}"))).contains("must start with '#VRML V2.0 utf8'");
        assertThat(error(read("vrml97", "#VRML V2.0 utf8\nAnchor { description \"open }")))
                .contains("line 2:").contains("a string is not closed");
        assertThat(error(read("vrml97", "#VRML V2.0 utf8\nTransform { translation 1 2 }")))
                .contains("expected a value, found '}'");
    }

    @Test
    void vrml97ProtosAreSkippedScriptsReadThroughAndTheRestBuilt() {
        JsonNode built = read("vrml97", """
                #VRML V2.0 utf8
                PROTO Wheel [ field SFFloat size 1 ] { Shape { geometry Sphere { radius IS size } } }
                DEF A Transform {
                  children [
                    Wheel { size 2 }
                    DEF Arm Transform { rotation 1 0 0 0.5 children Shape { geometry Cone {} } }
                    DEF Brain Script { field SFFloat gain 1.5 eventIn SFFloat set_input url "javascript: x" }
                    Shape { appearance Appearance { material Material { diffuseColor 1 0 0 } }
                            geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] }
                                                      coordIndex [ 0 1 2 3 -1 ] solid FALSE creaseAngle 0.5 } }
                  ]
                }
                DEF ATSWave TimeSensor { cycleInterval 2 loop TRUE }
                DEF AWave OrientationInterpolator { key [ 0 1 ] keyValue [ 1 0 0 0, 1 0 0 1 ] }
                ROUTE ATSWave.fraction_changed TO AWave.set_fraction
                ROUTE AWave.value_changed TO Arm.set_rotation
                """);
        assertThat(built.has("error")).as("%s", built).isFalse();
        assertThat(strings(built.get("transforms"))).containsExactlyInAnyOrder("A", "Arm");
        assertThat(strings(built.get("sensors"))).containsExactly("ATSWave");
        assertThat(built.get("meshes").asInt()).as("the cone and the face set; not the PROTO's wheel").isEqualTo(2);
    }

    @Test
    void aTimeSensorStartedLateStillLandsWhereItEndsAndRouteLoopsEnd() {
        JsonNode result = browser.evaluate("(async () => {"
                + " const reading = await import('/models/x3d.js');"
                + " const building = await import('/models/build.js');"
                + " const built = building.buildScene(reading.readX3d(" + JSON.writeValueAsString(x3d(
                        "<Transform DEF='Arm'/><TimeSensor DEF='T' cycleInterval='1'/>"
                        + "<OrientationInterpolator DEF='Turn' key='0 1' keyValue='0 1 0 0, 0 1 0 1.2'/>"
                        + "<ScalarInterpolator DEF='P' key='0 1' keyValue='0 1'/>"
                        + "<ScalarInterpolator DEF='Q' key='0 1' keyValue='0 1'/>"
                        + "<ROUTE fromNode='T' fromField='fraction_changed' toNode='Turn' toField='set_fraction'/>"
                        + "<ROUTE fromNode='Turn' fromField='value_changed' toNode='Arm' toField='set_rotation'/>"
                        + "<ROUTE fromNode='T' fromField='fraction_changed' toNode='P' toField='set_fraction'/>"
                        + "<ROUTE fromNode='P' fromField='value_changed' toNode='Q' toField='set_fraction'/>"
                        + "<ROUTE fromNode='Q' fromField='value_changed' toNode='P' toField='set_fraction'/>"))
                + "), 'A');"
                + " const arm = built.transforms.get('Arm');"
                + " const before = 2 * Math.acos(Math.min(1, arm.rotation.w));"
                + " built.sensors.get('T').start(10, false, 1);"
                // The first step after the start is long past its end: the last value still arrives.
                + " built.graph.step(25);"
                + " return { before, after: 2 * Math.acos(Math.min(1, arm.rotation.w)) };"
                + "})()");
        assertThat(result.get("before").asDouble()).isEqualTo(0.0);
        assertThat(result.get("after").asDouble()).as("the arm turned to the last key value").isCloseTo(1.2,
                org.assertj.core.data.Offset.offset(1e-6));
    }

    @Test
    void aGltfModelIsFittedToItsBodyAndStoodOnTheGroundWhereItWalks() {
        // One triangle, authored in centimetres a metre off the ground, under a node named after the agent.
        java.nio.ByteBuffer points = java.nio.ByteBuffer.allocate(36).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        for (float v : new float[] {-30, 100, -10, 40, 300, 10, 0, 250, 30}) {
            points.putFloat(v);
        }
        String gltf = "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
                + "\"nodes\":[{\"name\":\"Tall\",\"translation\":[7,0,7],\"children\":[1]},{\"name\":\"Body\",\"mesh\":0}],"
                + "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
                + "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
                + "\"min\":[-30,100,-10],\"max\":[40,300,30]}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
                + "\"buffers\":[{\"byteLength\":36,\"uri\":\"data:application/octet-stream;base64,"
                + java.util.Base64.getEncoder().encodeToString(points.array()) + "\"}]}";
        JsonNode bounds = browser.evaluate("(async () => {"
                + " const THREE = await import('/vendor/three/build/three.module.js');"
                + " const { loadGltf } = await import('/models/gltf.js');"
                + " const bytes = new TextEncoder().encode(" + JSON.writeValueAsString(gltf) + ");"
                + " const model = await loadGltf({ format: 'gltf', bytes: () => bytes }, { name: 'Tall', body: { height: 2 } });"
                + " const at = new THREE.Vector3(3, 0, -4);"
                + " model.rig.moveTo(at, at, 0, 0);"
                + " model.rig.update(0);"
                + " model.object.updateMatrixWorld(true);"
                + " const box = new THREE.Box3().setFromObject(model.object);"
                + " return [...box.min.toArray(), ...box.max.toArray()];"
                + "})()");
        double[] expected = {3 - 0.35, 0, -4 - 0.2, 3 + 0.35, 2, -4 + 0.2};
        for (int i = 0; i < expected.length; i++) {
            assertThat(bounds.get(i).asDouble()).as("bound %d of %s", i, bounds).isCloseTo(expected[i],
                    org.assertj.core.data.Offset.offset(1e-4));
        }
    }

    private static java.util.List<String> strings(JsonNode array) {
        java.util.List<String> out = new java.util.ArrayList<>();
        array.forEach(node -> out.add(node.asString()));
        return out;
    }
}
