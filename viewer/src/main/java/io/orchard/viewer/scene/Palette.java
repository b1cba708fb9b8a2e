package io.orchard.viewer.scene;

import com.jme3.asset.AssetManager;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.renderer.queue.RenderQueue;
import java.util.HashMap;
import java.util.Map;

/**
 * The world's colours and the materials that show them, one material per colour so that static
 * geometry of one colour can be batched into one draw call. Colours are given in sRGB, as people
 * pick them, and converted for the gamma-correct renderer.
 */
public final class Palette {

    /** Ground agents may walk on. */
    public static final ColorRGBA GRASS = srgb(0.42f, 0.62f, 0.27f);
    /** Ground beyond the world's bounds. */
    public static final ColorRGBA MEADOW = srgb(0.33f, 0.50f, 0.24f);
    /** Ground in the shade of a tree, a table or an agent, when no shadows are computed. */
    public static final ColorRGBA SHADE = srgb(0.27f, 0.42f, 0.19f);
    /** The river. */
    public static final ColorRGBA WATER = srgb(0.16f, 0.40f, 0.78f);
    /** Castle walls. */
    public static final ColorRGBA STONE = srgb(0.74f, 0.70f, 0.63f);
    /** Battlements and towers. */
    public static final ColorRGBA DARK_STONE = srgb(0.62f, 0.59f, 0.54f);
    /** Tower roofs. */
    public static final ColorRGBA ROOF = srgb(0.45f, 0.22f, 0.30f);
    /** Tables and bridge decks. */
    public static final ColorRGBA WOOD = srgb(0.58f, 0.40f, 0.22f);
    /** Tree trunks. */
    public static final ColorRGBA BARK = srgb(0.38f, 0.26f, 0.16f);
    /** Tree crowns. */
    public static final ColorRGBA LEAVES = srgb(0.17f, 0.40f, 0.16f);
    /** Tomatoes. */
    public static final ColorRGBA TOMATO = srgb(0.90f, 0.10f, 0.06f);
    /** Bananas. */
    public static final ColorRGBA BANANA = srgb(0.97f, 0.86f, 0.18f);
    /** Coconuts. */
    public static final ColorRGBA COCONUT = srgb(0.42f, 0.27f, 0.14f);
    /** Stalks and the tomato's calyx. */
    public static final ColorRGBA STALK = srgb(0.22f, 0.45f, 0.12f);

    private final AssetManager assets;
    private final Map<ColorRGBA, Material> lit = new HashMap<>();
    private final Map<ColorRGBA, Material> flat = new HashMap<>();

    /** The colours as materials made with {@code assets}. */
    public Palette(AssetManager assets) {
        this.assets = assets;
    }

    /** A colour given in sRGB, as a linear colour for the renderer. */
    public static ColorRGBA srgb(float r, float g, float b) {
        return new ColorRGBA().setAsSrgb(r, g, b, 1f);
    }

    /** The lit (Phong) material of a colour; the same instance for the same colour. */
    public Material lit(ColorRGBA color) {
        return lit.computeIfAbsent(color, c -> {
            Material material = new Material(assets, "Common/MatDefs/Light/Lighting.j3md");
            material.setBoolean("UseMaterialColors", true);
            material.setColor("Diffuse", c);
            material.setColor("Ambient", c);
            material.setColor("Specular", ColorRGBA.Black);
            material.setFloat("Shininess", 1f);
            // No highlights, one sun: lit per vertex it looks the same, and the software renderer
            // shades the ground that fills the frame several times faster.
            material.setBoolean("VertexLighting", true);
            return material;
        });
    }

    /** An unlit material of a colour, for markers and lines; the same instance for the same colour. */
    public Material flat(ColorRGBA color) {
        return flat.computeIfAbsent(color, c -> {
            Material material = new Material(assets, "Common/MatDefs/Misc/Unshaded.j3md");
            material.setColor("Color", c);
            return material;
        });
    }

    /**
     * A new unlit see-through material (its colour's alpha is its opacity). Geometry with it
     * belongs in the {@link RenderQueue.Bucket#Transparent} bucket.
     */
    public Material translucent(ColorRGBA color) {
        Material material = new Material(assets, "Common/MatDefs/Misc/Unshaded.j3md");
        material.setColor("Color", color);
        material.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
        material.getAdditionalRenderState().setDepthWrite(false);
        material.getAdditionalRenderState().setFaceCullMode(RenderState.FaceCullMode.Off);
        return material;
    }

    /** The asset manager materials come from. */
    public AssetManager assets() {
        return assets;
    }
}
