package io.orchard.viewer.model.event;

import com.jme3.material.Material;
import com.jme3.material.RenderState.BlendMode;
import com.jme3.math.ColorRGBA;
import com.jme3.renderer.queue.RenderQueue.Bucket;
import com.jme3.scene.Geometry;
import io.orchard.viewer.model.SceneNode;
import java.util.ArrayList;
import java.util.List;

/**
 * A VRML Material at run time and the jME materials made from it (one per shape that uses it),
 * so that ROUTEd colour, shininess and transparency changes reach every one of them.
 *
 * <p>How VRML's lighting model maps onto jME: lit shapes use {@code Lighting.j3md} with
 * {@code UseMaterialColors}: Diffuse is {@code diffuseColor} with alpha {@code 1-transparency}
 * (white when a texture or per-vertex colours replace it, as VRML specifies), Ambient is
 * {@code ambientIntensity·diffuseColor + emissiveColor} (jME's lighting has no emissive term, so
 * emission shows through the scene's ambient light), Specular is {@code specularColor}, and
 * Shininess is {@code 128·shininess}. Unlit shapes (line sets, and materials with only an
 * emissive colour) use {@code Unshaded.j3md} with the emissive colour.
 */
public final class LiveMaterial implements LiveNode {

    /** The jME material definition for lit shapes. */
    public static final String LIGHTING = "Common/MatDefs/Light/Lighting.j3md";
    /** The jME material definition for unlit shapes. */
    public static final String UNSHADED = "Common/MatDefs/Misc/Unshaded.j3md";

    /** How one jME material shows this VRML Material. */
    public record Use(Material material, Geometry geometry, boolean lit, boolean whiteBase) {
    }

    private final List<Use> uses = new ArrayList<>();
    private final ColorRGBA diffuse;
    private final ColorRGBA emissive;
    private final ColorRGBA specular;
    private float ambientIntensity;
    private float shininess;
    private float transparency;

    /** The material as the Material node {@code source} describes it, not yet shown by any shape. */
    public LiveMaterial(SceneNode source) {
        this.diffuse = color(source.floats("diffuseColor"));
        this.emissive = color(source.floats("emissiveColor"));
        this.specular = color(source.floats("specularColor"));
        this.ambientIntensity = (float) source.number("ambientIntensity");
        this.shininess = (float) source.number("shininess");
        this.transparency = (float) source.number("transparency");
    }

    /**
     * Whether VRML would light this material at all: a material with black diffuse and
     * specular colours but an emissive colour only glows, so it is drawn unshaded.
     */
    public boolean isSelfLit() {
        return isBlack(diffuse) && isBlack(specular) && !isBlack(emissive);
    }

    /** Adds a jME material to keep in step with this Material, and sets its colours now. */
    public void attach(Use use) {
        uses.add(use);
        apply(use);
    }

    @Override
    public void receive(String field, Object value, EventGraph.Cascade cascade) {
        switch (field) {
            case "diffuseColor" -> set(diffuse, (float[]) value);
            case "emissiveColor" -> set(emissive, (float[]) value);
            case "specularColor" -> set(specular, (float[]) value);
            case "ambientIntensity" -> ambientIntensity = clamp((Double) value);
            case "shininess" -> shininess = clamp((Double) value);
            case "transparency" -> transparency = clamp((Double) value);
            default -> {
                return;
            }
        }
        for (Use use : uses) {
            apply(use);
        }
        cascade.emit(this, field, value);
    }

    private void apply(Use use) {
        Material material = use.material();
        float alpha = 1f - transparency;
        if (use.lit()) {
            ColorRGBA base = use.whiteBase() ? ColorRGBA.White : diffuse;
            material.setBoolean("UseMaterialColors", true);
            material.setColor("Diffuse", new ColorRGBA(base.r, base.g, base.b, alpha));
            material.setColor("Ambient", new ColorRGBA(
                    Math.min(1f, base.r * ambientIntensity + emissive.r),
                    Math.min(1f, base.g * ambientIntensity + emissive.g),
                    Math.min(1f, base.b * ambientIntensity + emissive.b), alpha));
            material.setColor("Specular", specular.clone());
            material.setFloat("Shininess", Math.max(1f, 128f * shininess));
        } else {
            ColorRGBA base = use.whiteBase() ? ColorRGBA.White : emissive;
            material.setColor("Color", new ColorRGBA(base.r, base.g, base.b, alpha));
        }
        boolean transparent = transparency > 0;
        material.getAdditionalRenderState().setBlendMode(transparent ? BlendMode.Alpha
                : BlendMode.Off);
        if (use.geometry() != null) {
            use.geometry().setQueueBucket(transparent ? Bucket.Transparent : Bucket.Inherit);
        }
    }

    private static void set(ColorRGBA color, float[] v) {
        color.set(clamp(v[0]), clamp(v[1]), clamp(v[2]), 1f);
    }

    private static ColorRGBA color(float[] v) {
        return new ColorRGBA(v[0], v[1], v[2], 1f);
    }

    private static boolean isBlack(ColorRGBA c) {
        return c.r == 0 && c.g == 0 && c.b == 0;
    }

    private static float clamp(double v) {
        return (float) Math.max(0, Math.min(1, v));
    }
}
