package io.orchard.viewer.model.gltf;

import com.jme3.asset.AssetInfo;
import com.jme3.asset.AssetLoader;
import com.jme3.asset.AssetManager;
import com.jme3.scene.Spatial;
import com.jme3.scene.plugins.gltf.GlbLoader;
import com.jme3.scene.plugins.gltf.GltfLoader;
import com.jme3.scene.plugins.gltf.GltfModelKey;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelFiles;
import io.orchard.viewer.model.ModelException.Kind;
import io.orchard.viewer.model.ModelLimits;
import io.orchard.viewer.model.ParseBudget;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;

/**
 * Loads glTF and GLB from bytes in memory with jME's own loaders, after {@link GltfGuard} has
 * refused anything that would make them read files or exhaust the stack or memory. The loader
 * gets an {@link AssetInfo} over the byte array; its asset manager is used only for material
 * definitions. Unnamed nodes and clips are named by their indices first ({@link GltfNames}).
 */
public final class GltfImport {

    private GltfImport() {
    }

    /**
     * Checks a glTF or GLB model with the guard and loads it into a spatial.
     *
     * @throws ModelException if the guard or the loader refuses it
     */
    public static Spatial load(String agentName, ModelFormat format, byte[] bytes,
                               AssetManager assets, ModelLimits limits) throws ModelException {
        return load(agentName, format, bytes, ModelFiles.none(), assets, limits);
    }

    /**
     * {@link #load(String, ModelFormat, byte[], AssetManager, ModelLimits)} for a glTF whose
     * buffers and images may be other {@code files} of its zip, which are embedded first.
     */
    public static Spatial load(String agentName, ModelFormat format, byte[] file, ModelFiles files,
                               AssetManager assets, ModelLimits limits) throws ModelException {
        ParseBudget.checkSize(file, limits, format.name());
        byte[] bytes = format == ModelFormat.GLTF ? GltfEmbedding.embedded(file, files, limits) : file;
        // The files were counted unpacked; as data: URIs their Base64 takes a third more.
        ModelLimits embedded = bytes == file ? limits
                : limits.withMaxInputBytes((int) Math.min(Integer.MAX_VALUE, limits.maxInputBytes() * 4L / 3 + 4096));
        GltfGuard.check(format, bytes, embedded);
        byte[] named = GltfNames.named(format, bytes, embedded);
        String extension = format == ModelFormat.GLB ? ".glb" : ".gltf";
        GltfModelKey key = new GltfModelKey(agentName + extension);
        AssetInfo info = new AssetInfo(assets, key) {
            @Override
            public InputStream openStream() {
                return new ByteArrayInputStream(named);
            }
        };
        AssetLoader loader = format == ModelFormat.GLB ? new GlbLoader() : new GltfLoader();
        Object loaded;
        try {
            loaded = loader.load(info);
        } catch (IOException | RuntimeException e) {
            throw new ModelException(Kind.MALFORMED, format + " model could not be loaded: "
                    + e, e);
        }
        if (!(loaded instanceof Spatial spatial)) {
            throw new ModelException(Kind.MALFORMED, format + " loader returned no scene");
        }
        return spatial;
    }
}
