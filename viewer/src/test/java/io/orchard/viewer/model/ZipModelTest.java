package io.orchard.viewer.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import com.jme3.bounding.BoundingBox;
import com.jme3.scene.Geometry;
import com.jme3.texture.Texture;
import io.orchard.protocol.value.ModelArchive;
import io.orchard.protocol.value.ModelFormat;
import java.nio.charset.StandardCharsets;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * Models sent as a zip of their files: a glTF with its buffer and texture beside it, an X3D that
 * inlines a file of the zip and textures a shape with an image of it; references that would
 * leave the archive refused by name.
 */
class ZipModelTest {

    private static byte[] png(int rgb) {
        String uri = TestModels.pngDataUri(2, 2, rgb);
        return Base64.getDecoder().decode(uri.substring(uri.indexOf(',') + 1));
    }

    private static byte[] zip(Object... pathsAndFiles) {
        Map<String, byte[]> files = new LinkedHashMap<>();
        for (int i = 0; i < pathsAndFiles.length; i += 2) {
            Object file = pathsAndFiles[i + 1];
            files.put((String) pathsAndFiles[i], file instanceof String text
                    ? text.getBytes(StandardCharsets.UTF_8) : (byte[]) file);
        }
        return ModelArchive.pack(files);
    }

    private static boolean textured(Geometry geometry) {
        return geometry.getMaterial().getParamsMap().values().stream()
                .anyMatch(param -> param.getValue() instanceof Texture);
    }

    @Test
    void aGltfWithItsBufferAndTextureInFilesLoadsTexturedAndIsFittedToTheBody() throws ModelException {
        BodyModel block = TestModels.load(SplitBlock.NAME, ModelFormat.ZIP, SplitBlock.zip());
        block.fitToHeight(1.6);
        block.root().updateGeometricState();

        assertThat(block.format()).contains(ModelFormat.GLTF);
        assertThat(TestModels.geometries(block.root())).singleElement()
                .satisfies(geometry -> assertThat(textured(geometry)).as("textured").isTrue());
        BoundingBox bound = (BoundingBox) block.root().getWorldBound();
        assertThat(bound.getYExtent() * 2).isCloseTo(1.6f, within(1e-3f));
        assertThat(bound.getCenter().y - bound.getYExtent()).isCloseTo(0f, within(1e-3f));
        assertThat(bound.getXExtent() * 2).isCloseTo(0.4f, within(1e-3f));
        assertThat(bound.getCenter().x).isCloseTo(0f, within(1e-3f));
        assertThat(bound.getCenter().z).isCloseTo(0f, within(1e-3f));
    }

    @Test
    void aGltfBufferOutsideTheArchiveIsRefusedByItsUri() {
        byte[] zip = zip("scene.gltf", "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"uri\":\"../secret.bin\","
                + "\"byteLength\":4}]}");

        assertThatThrownBy(() -> TestModels.load("Scene", ModelFormat.ZIP, zip))
                .isInstanceOf(ModelException.class)
                .hasMessageContaining("scene.gltf buffers[0].uri")
                .hasMessageContaining("'../secret.bin'").hasMessageContaining("leaves the archive");
    }

    @Test
    void anX3dInlinesAFileOfTheZipWhoseTextureIsAnotherFile() throws ModelException {
        String arm = new String(TestModels.x3d("<Transform DEF='Elbow' translation='0.5 0 0'><Shape><Appearance>"
                + "<ImageTexture url='\"skin/arm.png\"'/></Appearance><Box size='0.2 0.6 0.2'/></Shape></Transform>"),
                StandardCharsets.UTF_8);
        byte[] zip = zip("robot.x3d", TestModels.x3d("<Transform DEF='Robot'><Shape><Box/></Shape>"
                        + "<Inline DEF='ArmPart' url='\"parts/arm.x3d\" \"https://example.org/arm.x3d\"'/></Transform>"),
                "parts/arm.x3d", arm, "parts/skin/arm.png", png(0x00ff00));

        BodyModel robot = TestModels.load("Robot", ModelFormat.ZIP, zip);

        assertThat(robot.hasNode("Elbow")).as("the inlined file's joint").isTrue();
        assertThat(robot.hasNode("ArmPart")).isTrue();
        List<Geometry> shapes = TestModels.geometries(robot.root());
        assertThat(shapes).hasSize(2);
        assertThat(shapes.stream().filter(ZipModelTest::textured)).hasSize(1);
    }

    @Test
    void anInlineOfItselfIsRefused() {
        byte[] zip = zip("a.x3d", TestModels.x3d("<Transform DEF='A'><Inline url='\"parts/b.x3d\"'/></Transform>"),
                "parts/b.x3d", TestModels.x3d("<Group><Inline url='\"../a.x3d\"'/></Group>"));

        assertThatThrownBy(() -> TestModels.load("A", ModelFormat.ZIP, zip))
                .hasMessageContaining("Inline 'a.x3d' inlines itself, through a.x3d -> parts/b.x3d");
    }

    @Test
    void anX3dTextureOutsideTheArchiveIsRefusedByItsUrl() {
        byte[] zip = zip("a.x3d", TestModels.x3d("<Transform DEF='A'><Shape><Appearance>"
                + "<ImageTexture url='\"/etc/skin.png\"'/></Appearance><Box/></Shape></Transform>"));

        assertThatThrownBy(() -> TestModels.load("A", ModelFormat.ZIP, zip))
                .hasMessageContaining("ImageTexture").hasMessageContaining("'/etc/skin.png'")
                .hasMessageContaining("not a path relative to the file");
    }

    @Test
    void aVrmlTextureIsReadFromTheZip() throws ModelException {
        byte[] zip = zip("a.wrl", TestModels.vrml("DEF A Transform { children Shape { appearance Appearance {"
                + " texture ImageTexture { url \"skin.png\" } } geometry Box {} } }"), "skin.png", png(0xff0000));

        BodyModel model = TestModels.load("A", ModelFormat.ZIP, zip);

        assertThat(TestModels.geometries(model.root())).singleElement()
                .satisfies(geometry -> assertThat(textured(geometry)).isTrue());
    }

    @Test
    void aZipBombIsRefusedAsTheServerRefusesIt() {
        byte[] zip = zip("a.x3d", TestModels.x3d("<Transform DEF='A'/>"), "big.bin", new byte[3 << 20]);

        assertThatThrownBy(() -> TestModels.load("A", ModelFormat.ZIP, zip))
                .isInstanceOf(ModelException.class).hasMessageContaining("zip bomb");
    }
}
