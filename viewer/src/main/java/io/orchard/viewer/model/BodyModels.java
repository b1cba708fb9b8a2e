package io.orchard.viewer.model;

import com.jme3.asset.AssetManager;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import io.orchard.protocol.value.ModelArchive;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.viewer.model.ModelException.Kind;
import io.orchard.viewer.model.build.EventGraphRig;
import io.orchard.viewer.model.build.Placeholders;
import io.orchard.viewer.model.build.SceneBuilder;
import io.orchard.viewer.model.build.SpatialRig;
import io.orchard.viewer.model.gltf.GltfImport;
import io.orchard.viewer.model.vrml.VrmlParser;
import io.orchard.viewer.model.x3d.X3dParser;
import java.util.Objects;

/**
 * Loads agent models from the bytes a client sent, in any file {@link ModelFormat}, into
 * {@link BodyModel}s; the replacement for the paper's VRML browser. Loading is safe on hostile
 * input: nothing outside the bytes is ever read (no files, no URLs, no XML entities), every
 * {@link ModelLimits limit} is enforced while parsing, and every failure is a
 * {@link ModelException} naming what was wrong, never another exception, an out-of-memory error
 * or a hang. When loading fails, show {@link #placeholder} instead and log the exception's
 * message.
 *
 * <p>Loading builds jME spatials but touches no live scene, so a large model can be loaded on a
 * worker thread (jME's desktop asset manager is built for loading from several threads) and the
 * result attached to the scene on the render thread.
 */
public final class BodyModels {

    private BodyModels() {
    }

    /** {@link #load(String, ModelFormat, byte[], AssetManager, ModelLimits)} with defaults. */
    public static BodyModel load(String agentName, ModelFormat format, byte[] bytes,
                                 AssetManager assets) throws ModelException {
        return load(agentName, format, bytes, assets, ModelLimits.DEFAULTS);
    }

    /**
     * Loads one agent's model.
     *
     * @param agentName the name the agent registered with; the Transform (VRML97, X3D) or node
     *                  (glTF) of that name is what moves, and the paper's movement nodes are
     *                  looked up as {@code <agentName>Mover} and {@code <agentName>TSMover}
     * @param format    the file's format, from the registration or {@link ModelFormats#detect};
     *                  {@link ModelFormat#BUNDLED} names a model rather than being one, and is
     *                  refused
     * @param bytes     the whole file; neither modified nor kept
     * @param assets    the asset manager material definitions come from (a
     *                  {@code DesktopAssetManager(true)} works without a GL context)
     * @param limits    the bounds this model must stay within
     * @throws ModelException if the model is malformed, too large, unsafe, or refers to names
     *                        it does not define
     */
    public static BodyModel load(String agentName, ModelFormat format, byte[] bytes,
                                 AssetManager assets, ModelLimits limits)
            throws ModelException {
        Objects.requireNonNull(agentName, "agentName");
        Objects.requireNonNull(format, "format");
        Objects.requireNonNull(bytes, "bytes");
        Objects.requireNonNull(assets, "assets");
        Objects.requireNonNull(limits, "limits");
        try {
            return switch (format) {
                case X3D -> fromDescription(agentName, format, X3dParser.parse(bytes, limits),
                        assets, limits);
                case VRML97 -> fromDescription(agentName, format,
                        VrmlParser.parse(bytes, limits), assets, limits);
                case GLTF, GLB -> fromGltf(agentName, format,
                        GltfImport.load(agentName, format, bytes, assets, limits));
                case ZIP -> fromArchive(agentName, ModelFiles.unpack(bytes, limits), assets, limits);
                case BUNDLED -> throw new ModelException(Kind.UNSUPPORTED, "a bundled model is"
                        + " named, not sent: load the bundled model's own bytes (X3D) instead");
            };
        } catch (StackOverflowError e) {
            // The limits keep nesting far below this; it would take a tiny thread stack.
            throw new ModelException(Kind.TOO_LARGE, format + " model nests too deeply for this"
                    + " thread's stack", e);
        } catch (RuntimeException e) {
            // A defect, not bad input, if it ever happens; still the caller's one exception.
            throw new ModelException(Kind.MALFORMED, format + " model could not be built: " + e,
                    e);
        }
    }

    /**
     * A visible stand-in for an agent whose model failed to load: a coloured figure of agent
     * size with the name above it, in a node named after the agent so that moves, rotations and
     * {@link BodyModel#hasNode} work on it as on a real model. It has no joints beyond that node
     * and no animations.
     */
    public static BodyModel placeholder(String agentName, AssetManager assets) {
        Objects.requireNonNull(agentName, "agentName");
        Objects.requireNonNull(assets, "assets");
        Node root = Placeholders.build(rootName(agentName), agentName, assets);
        return new BodyModel(agentName, null, root, new SpatialRig(agentName, root));
    }

    /** The model file of a zip, its references read from the archive. */
    private static BodyModel fromArchive(String agentName, ModelArchive archive, AssetManager assets,
                                         ModelLimits limits) throws ModelException {
        ModelFormat format = archive.modelFormat();
        ModelFiles files = ModelFiles.of(archive);
        byte[] bytes = archive.modelBytes();
        return switch (format) {
            case X3D -> fromDescription(agentName, format, X3dParser.parse(bytes, limits, files), assets,
                    limits);
            case VRML97 -> fromDescription(agentName, format, VrmlParser.parse(bytes, limits, files),
                    assets, limits);
            default -> fromGltf(agentName, format,
                    GltfImport.load(agentName, format, bytes, files, assets, limits));
        };
    }

    /** The colour of agent {@code agentName}: its placeholder's, and its marker's when it is far away. */
    public static com.jme3.math.ColorRGBA colourOf(String agentName) {
        return Placeholders.colorFor(agentName);
    }

    private static BodyModel fromDescription(String agentName, ModelFormat format,
                                             SceneDescription scene, AssetManager assets,
                                             ModelLimits limits) throws ModelException {
        SceneBuilder.Result built = SceneBuilder.build(scene, rootName(agentName), assets,
                limits);
        return new BodyModel(agentName, format, built.root(),
                new EventGraphRig(agentName, built));
    }

    private static BodyModel fromGltf(String agentName, ModelFormat format, Spatial loaded) {
        Node root = new Node(rootName(agentName));
        root.attachChild(loaded);
        return new BodyModel(agentName, format, root, new SpatialRig(agentName, root));
    }

    private static String rootName(String agentName) {
        return agentName + " model";
    }
}
