package io.orchard.viewer.model;

import com.jme3.asset.AssetManager;
import com.jme3.asset.DesktopAssetManager;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import javax.imageio.ImageIO;

/** Shared fixtures: one asset manager, and wrappers that make whole files from fragments. */
final class TestModels {

    /** Loads jME's material definitions from the class path; needs no GL context. */
    static final AssetManager ASSETS = new DesktopAssetManager(true);

    static final String X3D_DOCTYPE = "<!DOCTYPE X3D PUBLIC \"ISO//Web3D//DTD X3D 3.3//EN\" "
            + "\"http://www.web3d.org/specifications/x3d-3.3.dtd\">";

    private TestModels() {
    }

    static byte[] vrml(String body) {
        return ("#VRML V2.0 utf8\n" + body).getBytes(StandardCharsets.UTF_8);
    }

    static byte[] x3d(String scene) {
        return ("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + X3D_DOCTYPE + "\n"
                + "<X3D profile=\"Immersive\" version=\"3.3\">\n<head><meta name=\"title\""
                + " content=\"test\"/></head>\n<Scene>\n" + scene + "\n</Scene>\n</X3D>\n")
                .getBytes(StandardCharsets.UTF_8);
    }

    static AgentModel load(String agent, ModelFormat format, byte[] bytes)
            throws ModelException {
        return AgentModels.load(agent, format, bytes, ASSETS);
    }

    static AgentModel loadVrml(String agent, String body) throws ModelException {
        return load(agent, ModelFormat.VRML97, vrml(body));
    }

    static AgentModel loadX3d(String agent, String scene) throws ModelException {
        return load(agent, ModelFormat.X3D, x3d(scene));
    }

    static byte[] resource(String name) {
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
    static String pngDataUri(int width, int height, int rgb) {
        return imageDataUri("png", width, height, rgb);
    }

    /** A data: URI of a small image of one colour, in "png" or "jpeg". */
    static String imageDataUri(String format, int width, int height, int rgb) {
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
    static Spatial find(Node root, String name) {
        Spatial found = root.getChild(name);
        if (found == null) {
            throw new AssertionError("no spatial named " + name + " under " + root.getName());
        }
        return found;
    }

    static List<Geometry> geometries(Spatial root) {
        List<Geometry> result = new ArrayList<>();
        root.depthFirstTraversal(s -> {
            if (s instanceof Geometry g) {
                result.add(g);
            }
        });
        return result;
    }
}
