package io.orchard.viewer.agent;

import com.jme3.asset.AssetManager;
import com.jme3.material.MatParam;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.scene.Geometry;
import com.jme3.texture.Texture;
import io.orchard.protocol.value.ModelFit;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.viewer.model.BodyModel;
import io.orchard.viewer.model.BodyModels;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelLimits;
import java.util.Objects;

/**
 * Turns an agent's {@link ModelSpec} into a {@link BodyModel}, never failing: a model that
 * cannot be loaded (malformed, too large, unsafe, an unknown bundled name) becomes the model
 * package's placeholder, and the result says why. An agent that sent no model also gets the
 * placeholder, without a problem. A model is fitted to the body's height and stood on the
 * ground ({@link BodyModel#fitToHeight}) unless its spec asks for it as authored
 * ({@link ModelFit#AUTHORED}); a bundled model is made for the body already.
 *
 * <p>Loading touches no live scene and may run on any thread.
 */
public final class BodyModelLoader {

    /**
     * A model ready to show.
     *
     * @param model   the model, or the placeholder
     * @param problem why the agent's own model is not shown; null when it is, or when it sent none
     */
    public record Loaded(BodyModel model, String problem) {
    }

    private final AssetManager assets;
    private final ModelLimits limits;

    /** A loader that reads models through {@code assets}, refusing those beyond {@code limits}. */
    public BodyModelLoader(AssetManager assets, ModelLimits limits) {
        this.assets = Objects.requireNonNull(assets, "assets");
        this.limits = Objects.requireNonNull(limits, "limits");
    }

    /** Loads the model of agent {@code name} of body height {@code height}; {@code spec} may be null. */
    public Loaded load(String name, double height, ModelSpec spec) {
        if (spec == null) {
            return new Loaded(BodyModels.placeholder(name, assets), null);
        }
        try {
            ModelFormat format = spec.format();
            byte[] bytes = spec.bytes();
            if (format == ModelFormat.BUNDLED) {
                format = ModelFormat.X3D;
                bytes = BundledModels.fitted(spec.bundled(), name, height).orElse(null);
                if (bytes == null) {
                    return failed(name, "there is no bundled model named '" + spec.bundled()
                            + "'; the viewer ships " + String.join(", ", BundledModels.NAMES));
                }
            }
            BodyModel model = BodyModels.load(name, format, bytes, assets, limits);
            if (!hasGeometry(model)) {
                return failed(name, "the " + format.wireName() + " model has nothing to draw: no shape"
                        + " this viewer draws (instances of an ExternProtoDeclare, Text, an Inline"
                        + " outside the model's zip and nodes of a world are not drawn; the log names"
                        + " each node skipped)");
            }
            ModelFormat loaded = model.format().orElse(format);
            if (loaded == ModelFormat.GLTF || loaded == ModelFormat.GLB) {
                withoutPbr(model);
            }
            // A bundled model is written for the body already; every other is fitted unless its author asked not.
            if (spec.format() != ModelFormat.BUNDLED && spec.fitOrDefault() == ModelFit.BODY) {
                model.fitToHeight(height);
            }
            return new Loaded(model, null);
        } catch (ModelException e) {
            return failed(name, e.getMessage());
        } catch (RuntimeException e) {
            return failed(name, "the model could not be loaded: " + e);
        }
    }

    private static boolean hasGeometry(BodyModel model) {
        boolean[] found = new boolean[1];
        model.root().depthFirstTraversal(spatial -> found[0] |= spatial instanceof Geometry);
        return found[0];
    }

    private Loaded failed(String name, String problem) {
        return new Loaded(BodyModels.placeholder(name, assets), problem);
    }

    /**
     * Gives glTF's physically based materials a plain lit equivalent: without a light probe in
     * the scene, PBR surfaces facing away from the sun would render black.
     */
    private void withoutPbr(BodyModel model) {
        model.root().depthFirstTraversal(spatial -> {
            if (spatial instanceof Geometry geometry && geometry.getMaterial() != null
                    && geometry.getMaterial().getMaterialDef().getAssetName() != null
                    && geometry.getMaterial().getMaterialDef().getAssetName().contains("PBR")) {
                geometry.setMaterial(phong(geometry.getMaterial()));
            }
        });
    }

    private Material phong(Material pbr) {
        Material material = new Material(assets, "Common/MatDefs/Light/Lighting.j3md");
        MatParam base = pbr.getParam("BaseColor");
        ColorRGBA color = base != null ? (ColorRGBA) base.getValue() : ColorRGBA.White;
        material.setBoolean("UseMaterialColors", true);
        material.setColor("Diffuse", color);
        material.setColor("Ambient", color);
        MatParam texture = pbr.getParam("BaseColorMap");
        if (texture != null) {
            material.setTexture("DiffuseMap", (Texture) texture.getValue());
        }
        material.getAdditionalRenderState().setBlendMode(pbr.getAdditionalRenderState().getBlendMode());
        material.getAdditionalRenderState().setFaceCullMode(pbr.getAdditionalRenderState().getFaceCullMode());
        return material;
    }
}
