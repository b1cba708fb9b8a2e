package io.orchard.viewer.state;

import com.jme3.app.Application;
import com.jme3.app.SimpleApplication;
import com.jme3.app.state.BaseAppState;
import com.jme3.font.BitmapFont;
import com.jme3.font.BitmapText;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Node;
import com.jme3.scene.VertexBuffer;
import com.jme3.util.BufferUtils;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.model.BodyModels;
import io.orchard.viewer.scene.Palette;
import io.orchard.viewer.world.AgentView;
import io.orchard.viewer.world.WorldMirror;
import java.nio.FloatBuffer;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Keeps every agent and fruit visible however far the camera is, drawn over the scene in screen
 * pixels: an agent whose figure shows less than {@value #FIGURE_PX} pixels tall gets a pin of that
 * height in its colour standing on its head, and each agent its name above it in
 * {@value #LABEL_PX}-pixel text (while names are on, key {@code L}); a fruit that shows smaller than
 * {@value #FRUIT_PX} pixels gets a dot of that size in its kind's colour (tomato red, banana
 * yellow, coconut brown). Pins, dots and the labels' backs are one mesh, one draw call; each label
 * is one more.
 */
public final class MarkersState extends BaseAppState {

    /** The height of a pin, and the height under which a figure gets one, in pixels. */
    static final int FIGURE_PX = 24;
    /** The size of a fruit's dot, and the size under which a fruit gets one, in pixels. */
    static final int FRUIT_PX = 8;
    /** The height of the names' text, in pixels. */
    static final int LABEL_PX = 20;
    /** A fruit's diameter, about. */
    private static final float FRUIT_SIZE = 0.22f;
    private static final ColorRGBA OUTLINE = new ColorRGBA(0.05f, 0.05f, 0.05f, 1f);
    private static final ColorRGBA LABEL_BACK = new ColorRGBA(0f, 0f, 0f, 0.55f);

    private final WorldMirror mirror;
    private final SimClock clock;
    private final Node markers = new Node("markers");
    private final Map<String, BitmapText> labels = new HashMap<>();
    private final Mesh mesh = new Mesh();
    private Geometry quads;
    private BitmapFont font;
    private FloatBuffer positions = BufferUtils.createFloatBuffer(0);
    private FloatBuffer colours = BufferUtils.createFloatBuffer(0);
    private int count;

    /** Markers for the world of {@code mirror} at the time of {@code clock}. */
    public MarkersState(WorldMirror mirror, SimClock clock) {
        this.mirror = mirror;
        this.clock = clock;
    }

    @Override
    protected void initialize(Application app) {
        font = app.getAssetManager().loadFont("Interface/Fonts/Default.fnt");
        Material material = new Material(app.getAssetManager(), "Common/MatDefs/Misc/Unshaded.j3md");
        material.setBoolean("VertexColor", true);
        material.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
        quads = new Geometry("marker quads", mesh);
        quads.setMaterial(material);
        markers.attachChild(quads);
        // Under the panels of text, which are drawn from z = 0 up.
        markers.setLocalTranslation(0, 0, -2);
        ((SimpleApplication) app).getGuiNode().attachChild(markers);
    }

    @Override
    public void update(float tpf) {
        Camera camera = getApplication().getCamera();
        double now = clock.now();
        AgentsState agents = getState(AgentsState.class);
        boolean names = agents == null || agents.showLabels();
        count = 0;
        ensure(mirror.agents().size() * 4 + mirror.fruit().size() * 2);
        for (FruitState fruit : mirror.fruit()) {
            fruit(camera, fruit);
        }
        Map<String, BitmapText> unused = new HashMap<>(labels);
        List<float[]> taken = new ArrayList<>();
        List<Object[]> named = new ArrayList<>();
        for (AgentView agent : mirror.agents()) {
            unused.remove(agent.name());
            float[] head = agent(camera, agent, now, taken);
            if (head != null) {
                named.add(new Object[] {agent.name(), head});
            }
        }
        for (Object[] entry : named) {
            label((String) entry[0], (float[]) entry[1], names, taken);
        }
        unused.forEach((name, label) -> {
            label.removeFromParent();
            labels.remove(name);
        });
        quads.setCullHint(count == 0 ? Node.CullHint.Always : Node.CullHint.Never);
        if (count > 0) {
            mesh.setBuffer(VertexBuffer.Type.Position, 3, positions.flip());
            mesh.setBuffer(VertexBuffer.Type.Color, 4, colours.flip());
            mesh.updateCounts();
            mesh.updateBound();
            quads.updateModelBound();
        }
    }

    private void fruit(Camera camera, FruitState fruit) {
        Vec3 at = fruit.position();
        Vector3f centre = camera.getScreenCoordinates(new Vector3f((float) at.x(), (float) at.y(), (float) at.z()));
        if (!inView(camera, centre)) {
            return;
        }
        Vector3f top = camera.getScreenCoordinates(new Vector3f((float) at.x(), (float) at.y() + FRUIT_SIZE,
                (float) at.z()));
        if (top.y - centre.y >= FRUIT_PX) {
            return;
        }
        float half = FRUIT_PX / 2f;
        quad(centre.x - half - 1, centre.y - half - 1, FRUIT_PX + 2, FRUIT_PX + 2, OUTLINE);
        quad(centre.x - half, centre.y - half, FRUIT_PX, FRUIT_PX, colourOf(fruit.kind()));
    }

    /**
     * The agent's pin, when its figure shows small; returns where its name goes (the middle of its
     * head, and the lowest row free above it), or null when it is out of view.
     */
    private float[] agent(Camera camera, AgentView agent, double now, List<float[]> taken) {
        Vec3 at = agent.positionAt(now);
        Vector3f feet = camera.getScreenCoordinates(new Vector3f((float) at.x(), (float) at.y(), (float) at.z()));
        Vector3f head = camera.getScreenCoordinates(new Vector3f((float) at.x(),
                (float) (at.y() + agent.body().height()), (float) at.z()));
        if (!inView(camera, head) || !inView(camera, feet)) {
            return null;
        }
        float top = head.y + 2;
        if (head.y - feet.y < FIGURE_PX) {
            quad(head.x - 5, head.y, 10, FIGURE_PX, OUTLINE);
            ColorRGBA colour = BodyModels.colourOf(agent.name());
            // Given as sRGB, as the frame shows it: the pin's pixels are the agent's colour exactly.
            quad(head.x - 3, head.y + 2, 6, FIGURE_PX - 4, new ColorRGBA().setAsSrgb(colour.r, colour.g, colour.b, 1));
            taken.add(new float[] {head.x - 5, head.y, head.x + 5, head.y + FIGURE_PX});
            top = head.y + FIGURE_PX + 2;
        }
        return new float[] {head.x, top};
    }

    /** The agent's name above {@code at}, moved up past every pin and name it would cover. */
    private void label(String name, float[] at, boolean names, List<float[]> taken) {
        BitmapText label = labels.get(name);
        if (label == null) {
            label = new BitmapText(font);
            label.setSize(LABEL_PX);
            label.setText(name);
            label.setColor(ColorRGBA.White);
            markers.attachChild(label);
            labels.put(name, label);
        }
        label.setCullHint(names ? Node.CullHint.Inherit : Node.CullHint.Always);
        if (!names) {
            return;
        }
        float width = label.getLineWidth();
        float x = Math.round(at[0] - width / 2);
        float bottom = at[1];
        for (int tries = 0; tries < 8; tries++) {
            float[] box = {x - 3, bottom - 1, x + width + 3, bottom + label.getHeight() + 1};
            float[] hit = taken.stream().filter(other -> box[0] < other[2] && other[0] < box[2]
                    && box[1] < other[3] && other[1] < box[3]).findFirst().orElse(null);
            if (hit == null) {
                break;
            }
            bottom = hit[3] + 2;
        }
        float y = Math.round(bottom + label.getHeight());
        label.setLocalTranslation(x, y, 1);
        quad(x - 3, bottom - 1, width + 6, label.getHeight() + 2, LABEL_BACK);
        taken.add(new float[] {x - 3, bottom - 1, x + width + 3, bottom + label.getHeight() + 1});
    }

    private static boolean inView(Camera camera, Vector3f screen) {
        return screen.z > 0 && screen.z < 1 && screen.x > -50 && screen.y > -50 && screen.x < camera.getWidth() + 50
                && screen.y < camera.getHeight() + 50;
    }

    private static ColorRGBA colourOf(FruitKind kind) {
        return switch (kind) {
            case TOMATO -> Palette.TOMATO;
            case BANANA -> Palette.BANANA;
            case COCONUT -> Palette.COCONUT;
        };
    }

    private void ensure(int most) {
        if (positions.capacity() < most * 6 * 3 || mesh.getBuffer(VertexBuffer.Type.Position) == null) {
            positions = BufferUtils.createFloatBuffer(most * 2 * 6 * 3);
            colours = BufferUtils.createFloatBuffer(most * 2 * 6 * 4);
        }
        positions.clear();
        colours.clear();
    }

    /** Two triangles from (x, y), {@code w} wide and {@code h} high, in {@code colour}. */
    private void quad(float x, float y, float w, float h, ColorRGBA colour) {
        float[][] corners = {{x, y}, {x + w, y}, {x + w, y + h}, {x, y}, {x + w, y + h}, {x, y + h}};
        for (float[] corner : corners) {
            positions.put(corner[0]).put(corner[1]).put(0);
            colours.put(colour.r).put(colour.g).put(colour.b).put(colour.a);
        }
        count++;
    }

    @Override
    protected void cleanup(Application app) {
        markers.removeFromParent();
    }

    @Override
    protected void onEnable() {
        markers.setCullHint(Node.CullHint.Inherit);
    }

    @Override
    protected void onDisable() {
        markers.setCullHint(Node.CullHint.Always);
    }
}
