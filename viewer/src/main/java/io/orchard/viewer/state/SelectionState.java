package io.orchard.viewer.state;

import com.jme3.app.Application;
import com.jme3.app.SimpleApplication;
import com.jme3.app.state.BaseAppState;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector2f;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.renderer.queue.RenderQueue.ShadowMode;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.scene.Meshes;
import io.orchard.viewer.scene.Palette;
import io.orchard.viewer.world.AgentView;
import io.orchard.viewer.world.Picking;
import io.orchard.viewer.world.Sighting;
import io.orchard.viewer.world.ViewCone;
import io.orchard.viewer.world.WorldMirror;
import java.util.ArrayList;
import java.util.List;

/**
 * The selected agent and its point of view: a ring at its feet, its perception cone drawn on the
 * ground from its body's {@code Sight} (range and field of view, turned with its heading), and a
 * line from its eyes to everything it perceives right now, worked out by {@link ViewCone} from
 * what the viewer knows.
 */
public final class SelectionState extends BaseAppState implements WorldMirror.Listener {

    private static final ColorRGBA CONE = new ColorRGBA(1f, 0.92f, 0.3f, 0.22f);
    private static final ColorRGBA EDGE = new ColorRGBA(1f, 0.85f, 0.2f, 1f);
    private static final ColorRGBA TO_FRUIT = new ColorRGBA(1f, 0.45f, 0.1f, 1f);
    private static final ColorRGBA TO_OBJECT = new ColorRGBA(0.95f, 0.95f, 0.95f, 1f);
    private static final ColorRGBA TO_AGENT = new ColorRGBA(0.9f, 0.2f, 0.9f, 1f);

    private final WorldMirror mirror;
    private final SimClock clock;
    private final Node marks = new Node("selection");
    private final Node cone = new Node("view cone");
    private Palette palette;
    private Geometry ring;
    private Geometry toFruit;
    private Geometry toObjects;
    private Geometry toAgents;
    private String selected;
    private Sight coneSight;
    private Sighting sighting = Sighting.NOTHING;

    /** The selection among the agents of {@code mirror}, drawn at the time of {@code clock}. */
    public SelectionState(WorldMirror mirror, SimClock clock) {
        this.mirror = mirror;
        this.clock = clock;
    }

    @Override
    protected void initialize(Application app) {
        palette = new Palette(app.getAssetManager());
        marks.setShadowMode(ShadowMode.Off);
        marks.attachChild(cone);
        toFruit = lines("seen fruit", TO_FRUIT);
        toObjects = lines("seen trees and tables", TO_OBJECT);
        toAgents = lines("seen agents", TO_AGENT);
        ((SimpleApplication) app).getRootNode().attachChild(marks);
        mirror.addListener(this);
    }

    /** Selects the agent of that name (null for none). */
    public void select(String name) {
        selected = name;
        coneSight = null;
        cone.detachAllChildren();
        if (ring != null) {
            ring.removeFromParent();
            ring = null;
        }
        sighting = Sighting.NOTHING;
    }

    /** The selected agent, if it is still in the world. */
    public AgentView selected() {
        return selected == null ? null : mirror.agent(selected).orElse(null);
    }

    /** The name of the selected agent, even when it has left; null when none is selected. */
    public String selectedName() {
        return selected;
    }

    /** What the selected agent perceives this frame. */
    public Sighting sighting() {
        return sighting;
    }

    /**
     * Selects the agent under the screen point (pixels from the bottom left), or none.
     *
     * @return the agent selected, or null
     */
    public AgentView pickAt(Vector2f screen) {
        Camera camera = getApplication().getCamera();
        Vector3f near = camera.getWorldCoordinates(screen, 0f);
        Vector3f far = camera.getWorldCoordinates(screen, 1f);
        Vector3f direction = far.subtract(near).normalizeLocal();
        AgentView hit = Picking.pick(mirror.agents(), clock.now(), near.x, near.y, near.z, direction.x, direction.y,
                direction.z, 0.5);
        select(hit == null ? null : hit.name());
        return hit;
    }

    @Override
    public void agentRemoved(AgentView agent) {
        if (agent.name().equals(selected)) {
            cone.detachAllChildren();
            coneSight = null;
            if (ring != null) {
                ring.removeFromParent();
                ring = null;
            }
        }
    }

    @Override
    public void update(float tpf) {
        AgentView agent = selected();
        if (agent == null) {
            sighting = Sighting.NOTHING;
            clearLines();
            return;
        }
        double now = clock.now();
        Vec3 at = agent.positionAt(now);
        if (!agent.body().sight().equals(coneSight)) {
            buildCone(agent);
        }
        cone.setLocalTranslation((float) at.x(), 0.12f, (float) at.z());
        cone.setLocalRotation(new com.jme3.math.Quaternion().fromAngleAxis((float) agent.heading(), Vector3f.UNIT_Y));
        ring.setLocalTranslation((float) at.x(), 0.1f, (float) at.z());
        sighting = ViewCone.of(mirror, agent, now);
        Vector3f eye = new Vector3f((float) at.x(), (float) (at.y() + agent.body().height() * 0.9), (float) at.z());
        List<Vector3f> fruitEnds = new ArrayList<>();
        for (FruitState fruit : sighting.fruit()) {
            fruitEnds.add(eye);
            Vec3 centre = fruit.position();
            fruitEnds.add(new Vector3f((float) centre.x(), (float) centre.y(), (float) centre.z()));
        }
        List<Vector3f> objectEnds = new ArrayList<>();
        for (Obstacle obstacle : sighting.objects()) {
            objectEnds.add(eye);
            objectEnds.add(new Vector3f((float) obstacle.position().x(), (float) Math.min(obstacle.height(), 2.0),
                    (float) obstacle.position().z()));
        }
        List<Vector3f> agentEnds = new ArrayList<>();
        for (AgentView other : sighting.agents()) {
            Vec3 there = other.positionAt(now);
            agentEnds.add(eye);
            agentEnds.add(new Vector3f((float) there.x(), (float) (there.y() + other.body().height() * 0.6),
                    (float) there.z()));
        }
        show(toFruit, fruitEnds);
        show(toObjects, objectEnds);
        show(toAgents, agentEnds);
    }

    private void buildCone(AgentView agent) {
        coneSight = agent.body().sight();
        cone.detachAllChildren();
        float range = (float) coneSight.range();
        float field = (float) coneSight.fieldOfView();
        Geometry fan = new Geometry("cone area", Meshes.sector(range, field, 64));
        fan.setMaterial(palette.translucent(CONE));
        fan.setQueueBucket(RenderQueue.Bucket.Transparent);
        cone.attachChild(fan);
        Geometry edge = new Geometry("cone edge", Meshes.sectorOutline(range, field, 64));
        edge.setMaterial(palette.flat(EDGE));
        cone.attachChild(edge);
        float radius = (float) agent.body().radius();
        if (ring != null) {
            ring.removeFromParent();
        }
        ring = new Geometry("selection ring", Meshes.ring(radius + 0.1f, radius + 0.3f, 32));
        ring.setMaterial(palette.flat(EDGE));
        marks.attachChild(ring);
    }

    private Geometry lines(String name, ColorRGBA color) {
        Geometry geometry = new Geometry(name, Meshes.lines(List.of(new Vector3f(), new Vector3f())));
        Material material = palette.flat(color);
        geometry.setMaterial(material);
        geometry.setCullHint(Geometry.CullHint.Always);
        marks.attachChild(geometry);
        return geometry;
    }

    private static void show(Geometry geometry, List<Vector3f> ends) {
        if (ends.isEmpty()) {
            geometry.setCullHint(Geometry.CullHint.Always);
            return;
        }
        // Refill the same buffer instead of making a mesh a frame, which would churn GPU objects.
        com.jme3.scene.Mesh mesh = geometry.getMesh();
        mesh.setBuffer(com.jme3.scene.VertexBuffer.Type.Position, 3,
                com.jme3.util.BufferUtils.createFloatBuffer(ends.toArray(new Vector3f[0])));
        mesh.updateCounts();
        mesh.updateBound();
        geometry.updateModelBound();
        geometry.setCullHint(Geometry.CullHint.Never);
    }

    private void clearLines() {
        toFruit.setCullHint(Geometry.CullHint.Always);
        toObjects.setCullHint(Geometry.CullHint.Always);
        toAgents.setCullHint(Geometry.CullHint.Always);
    }

    @Override
    protected void cleanup(Application app) {
        mirror.removeListener(this);
        marks.removeFromParent();
    }

    @Override
    protected void onEnable() {
    }

    @Override
    protected void onDisable() {
    }
}
