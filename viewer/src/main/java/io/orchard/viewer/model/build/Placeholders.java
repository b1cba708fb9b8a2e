package io.orchard.viewer.model.build;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.font.BitmapText;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.control.BillboardControl;
import io.orchard.viewer.model.event.LiveMaterial;
import java.awt.Color;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The stand-in body shown for an agent whose model could not be loaded: a capsule-like figure
 * of roughly an agent's size in a colour derived from its name, with the name floating above it,
 * so the agent stays visible and recognisable while the viewer reports why its model failed.
 */
public final class Placeholders {

    private static final Logger LOG = LoggerFactory.getLogger(Placeholders.class);
    static final String FONT = "Interface/Fonts/Default.fnt";

    private Placeholders() {
    }

    /** The stand-in for agent {@code agentName}, below a root node named {@code rootName}. */
    public static Node build(String rootName, String agentName, AssetManager assets) {
        Node root = new Node(rootName);
        Node agent = new Node(agentName);
        root.attachChild(agent);
        Material material = new Material(assets, LiveMaterial.LIGHTING);
        ColorRGBA color = colorFor(agentName);
        material.setBoolean("UseMaterialColors", true);
        material.setColor("Diffuse", color);
        material.setColor("Ambient", color.mult(0.4f));
        Geometry body = new Geometry(agentName + " body", Primitives.cylinder(0.3f, 1.2f, true,
                true, true));
        body.setLocalTranslation(0, 0.6f, 0);
        body.setMaterial(material);
        agent.attachChild(body);
        Geometry head = new Geometry(agentName + " head", Primitives.sphere(0.25f));
        head.setLocalTranslation(0, 1.45f, 0);
        head.setMaterial(material);
        agent.attachChild(head);
        try {
            BitmapFont font = assets.loadFont(FONT);
            BitmapText text = new BitmapText(font);
            text.setSize(0.25f);
            text.setText(agentName);
            text.setLocalTranslation(-text.getLineWidth() / 2, text.getLineHeight(), 0);
            Node label = new Node(agentName + " label");
            label.attachChild(text);
            label.setLocalTranslation(0, 1.8f, 0);
            label.addControl(new BillboardControl());
            agent.attachChild(label);
        } catch (RuntimeException e) {
            LOG.warn("placeholder for {} has no name label: font {} not available ({})",
                    agentName, FONT, e.toString());
        }
        return root;
    }

    /** A saturated colour that stays the same for the same name. */
    public static ColorRGBA colorFor(String name) {
        // Mixed, so that names that differ in one letter (Agent1, Agent2) get hues far apart.
        float hue = ((name.hashCode() * 0x9E3779B9) >>> 16) / 65536f;
        int rgb = Color.HSBtoRGB(hue, 0.65f, 0.9f);
        return new ColorRGBA(((rgb >> 16) & 0xff) / 255f, ((rgb >> 8) & 0xff) / 255f,
                (rgb & 0xff) / 255f, 1f);
    }
}
