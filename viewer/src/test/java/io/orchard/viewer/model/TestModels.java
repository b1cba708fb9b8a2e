package io.orchard.viewer.model;

import com.jme3.asset.AssetManager;
import com.jme3.asset.DesktopAssetManager;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import io.orchard.protocol.value.ModelFormat;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;

/**
 * Shared fixtures of the model packages' tests: one asset manager, wrappers that make whole files
 * from fragments, and the test models.
 */
public final class TestModels {

    /** Loads jME's material definitions from the class path; needs no GL context. */
    public static final AssetManager ASSETS = new DesktopAssetManager(true);

    public static final String X3D_DOCTYPE = "<!DOCTYPE X3D PUBLIC \"ISO//Web3D//DTD X3D 3.3//EN\" "
            + "\"http://www.web3d.org/specifications/x3d-3.3.dtd\">";

    private TestModels() {
    }

    public static byte[] vrml(String body) {
        return ("#VRML V2.0 utf8\n" + body).getBytes(StandardCharsets.UTF_8);
    }

    public static byte[] x3d(String scene) {
        return ("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + X3D_DOCTYPE + "\n"
                + "<X3D profile=\"Immersive\" version=\"3.3\">\n<head><meta name=\"title\""
                + " content=\"test\"/></head>\n<Scene>\n" + scene + "\n</Scene>\n</X3D>\n")
                .getBytes(StandardCharsets.UTF_8);
    }

    public static BodyModel load(String agent, ModelFormat format, byte[] bytes)
            throws ModelException {
        return BodyModels.load(agent, format, bytes, ASSETS);
    }

    public static BodyModel loadVrml(String agent, String body) throws ModelException {
        return load(agent, ModelFormat.VRML97, vrml(body));
    }

    public static BodyModel loadX3d(String agent, String scene) throws ModelException {
        return load(agent, ModelFormat.X3D, x3d(scene));
    }

    public static byte[] resource(String name) {
        try (InputStream in = TestModels.class.getResourceAsStream(name)) {
            if (in == null) {
                throw new IllegalStateException("missing test resource " + name);
            }
            return in.readAllBytes();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** A PNG data: URI of a small image of one colour. */
    public static String pngDataUri(int width, int height, int rgb) {
        return imageDataUri("png", width, height, rgb);
    }

    /** A data: URI of a small image of one colour, in "png" or "jpeg". */
    public static String imageDataUri(String format, int width, int height, int rgb) {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                image.setRGB(x, y, rgb);
            }
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            ImageIO.write(image, format, out);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return "data:image/" + format + ";base64,"
                + Base64.getEncoder().encodeToString(out.toByteArray());
    }

    /** The first spatial of that name under {@code root}, searching depth first. */
    public static Spatial find(Node root, String name) {
        Spatial found = root.getChild(name);
        if (found == null) {
            throw new AssertionError("no spatial named " + name + " under " + root.getName());
        }
        return found;
    }

    public static List<Geometry> geometries(Spatial root) {
        List<Geometry> result = new ArrayList<>();
        root.depthFirstTraversal(s -> {
            if (s instanceof Geometry g) {
                result.add(g);
            }
        });
        return result;
    }

    /** walker.gltf repacked as binary glTF: the buffer moves into the BIN chunk. */
    public static byte[] walkerGlb() {
        String json = new String(TestModels.resource("walker.gltf"), StandardCharsets.UTF_8);
        Matcher uri = Pattern.compile("\"uri\": \"data:application/octet-stream;base64,"
                + "([^\"]*)\",\\s*").matcher(json);
        if (!uri.find()) {
            throw new IllegalStateException("walker.gltf has no embedded buffer");
        }
        byte[] bin = pad(Base64.getDecoder().decode(uri.group(1)), (byte) 0);
        byte[] text = pad(uri.replaceFirst("").getBytes(StandardCharsets.UTF_8), (byte) ' ');
        ByteBuffer glb = ByteBuffer.allocate(12 + 8 + text.length + 8 + bin.length)
                .order(ByteOrder.LITTLE_ENDIAN);
        glb.putInt(0x46546C67).putInt(2).putInt(glb.capacity());
        glb.putInt(text.length).putInt(0x4E4F534A).put(text);
        glb.putInt(bin.length).putInt(0x004E4942).put(bin);
        return glb.array();
    }

    private static byte[] pad(byte[] bytes, byte filler) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.writeBytes(bytes);
        while (out.size() % 4 != 0) {
            out.write(filler);
        }
        return out.toByteArray();
    }
}
