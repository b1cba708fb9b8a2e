package io.orchard.viewer.model.build;

import com.jme3.asset.AssetManager;
import com.jme3.material.Material;
import com.jme3.material.RenderState.FaceCullMode;
import com.jme3.math.ColorRGBA;
import com.jme3.scene.Geometry;
import com.jme3.scene.VertexBuffer;
import com.jme3.texture.Image;
import com.jme3.texture.Texture;
import com.jme3.texture.Texture2D;
import io.orchard.viewer.model.DataUriImages;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelLimits;
import io.orchard.viewer.model.SceneNode;
import io.orchard.viewer.model.event.LiveMaterial;
import java.util.Collections;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.Map;
import java.util.Set;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Makes the jME material of each shape from its Appearance: the Material node's colours through
 * {@link LiveMaterial}, an ImageTexture's embedded image, per-vertex colours, and whether back
 * faces show ({@code solid FALSE}). Each shape gets its own jME material, so that one shape's
 * culling or vertex colours never leak to another sharing the Appearance.
 *
 * <p>An ImageTexture is read only from a {@code data:} URI. Any other URL is ignored with a
 * warning, never fetched: a model is the bytes that arrived and nothing else.
 */
final class Appearances {

    private static final Logger LOG = LoggerFactory.getLogger(Appearances.class);

    private final AssetManager assets;
    private final ModelLimits limits;
    private final Map<SceneNode, LiveMaterial> materials = new IdentityHashMap<>();
    private final Map<SceneNode, Texture> textures = new IdentityHashMap<>();
    private final Set<SceneNode> texturesWithoutImage =
            Collections.newSetFromMap(new IdentityHashMap<>());
    private final Set<String> warned = new HashSet<>();

    Appearances(AssetManager assets, ModelLimits limits) {
        this.assets = assets;
        this.limits = limits;
    }

    LiveMaterial live(SceneNode material) {
        return materials.computeIfAbsent(material, LiveMaterial::new);
    }

    /** Creates and assigns the material of {@code geometry}. */
    void apply(Geometry geometry, SceneNode appearance, FaceSets.Built shape)
            throws ModelException {
        SceneNode materialNode = appearance == null ? null
                : appearance.node("material", "Material");
        SceneNode textureNode = appearance == null ? null : appearance.node("texture");
        Texture texture = null;
        boolean hasTexCoords = geometry.getMesh().getBuffer(VertexBuffer.Type.TexCoord) != null;
        if (textureNode != null && hasTexCoords) {
            texture = texture(textureNode);
        }
        boolean whiteBase = texture != null || shape.vertexColors();
        Material material;
        if (materialNode == null) {
            material = new Material(assets, LiveMaterial.UNSHADED);
            material.setColor("Color", ColorRGBA.White.clone());
            setCommon(material, false, texture, shape);
        } else {
            LiveMaterial live = live(materialNode);
            boolean lit = !shape.lines() && !live.isSelfLit();
            material = new Material(assets, lit ? LiveMaterial.LIGHTING : LiveMaterial.UNSHADED);
            setCommon(material, lit, texture, shape);
            live.attach(new LiveMaterial.Use(material, geometry, lit, whiteBase));
        }
        geometry.setMaterial(material);
    }

    private static void setCommon(Material material, boolean lit, Texture texture,
                                  FaceSets.Built shape) {
        if (texture != null) {
            material.setTexture(lit ? "DiffuseMap" : "ColorMap", texture);
        }
        if (shape.vertexColors()) {
            material.setBoolean(lit ? "UseVertexColor" : "VertexColor", true);
        }
        if (!shape.solid()) {
            material.getAdditionalRenderState().setFaceCullMode(FaceCullMode.Off);
        }
    }

    private Texture texture(SceneNode node) throws ModelException {
        if (!node.is("ImageTexture")) {
            warnOnce(node, "{}: texture type {} is not supported; the shape is drawn untextured",
                    node.location(), node.typeName());
            return null;
        }
        Texture cached = textures.get(node);
        if (cached != null || texturesWithoutImage.contains(node)) {
            return cached;
        }
        Texture2D texture = null;
        for (String url : node.strings("url")) {
            String where = node.location() + ": " + node.label() + " field url";
            byte[] bytes = DataUriImages.bytes(url, where);
            if (bytes == null) {
                LOG.warn("{}: '{}' ignored; only embedded data: URIs are loaded, nothing is"
                        + " fetched", where, abbreviate(url));
                continue;
            }
            Image image;
            try {
                image = DataUriImages.decode(bytes, limits.maxTextureSize(), where);
            } catch (ModelException e) {
                if (e.kind() != ModelException.Kind.UNSUPPORTED) {
                    throw e;
                }
                LOG.warn("{}; the shape is drawn untextured", e.getMessage());
                continue;
            }
            texture = new Texture2D(image);
            texture.setWrap(Texture.WrapAxis.S, node.bool("repeatS") ? Texture.WrapMode.Repeat
                    : Texture.WrapMode.EdgeClamp);
            texture.setWrap(Texture.WrapAxis.T, node.bool("repeatT") ? Texture.WrapMode.Repeat
                    : Texture.WrapMode.EdgeClamp);
            break;
        }
        if (texture == null) {
            texturesWithoutImage.add(node);
        } else {
            textures.put(node, texture);
        }
        return texture;
    }

    private void warnOnce(SceneNode node, String format, Object... args) {
        if (warned.add(node.typeName())) {
            LOG.warn(format, args);
        }
    }

    private static String abbreviate(String text) {
        return text.length() <= 60 ? text : text.substring(0, 57) + "...";
    }
}
