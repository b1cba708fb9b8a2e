package io.orchard.viewer.state;

import com.jme3.app.Application;
import com.jme3.app.SimpleApplication;
import com.jme3.app.state.BaseAppState;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import com.jme3.renderer.queue.RenderQueue.ShadowMode;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.agent.BodyModelLoader;
import io.orchard.viewer.model.BodyModel;
import io.orchard.viewer.model.BodyModels;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelLimits;
import io.orchard.viewer.scene.Meshes;
import io.orchard.viewer.scene.Palette;
import io.orchard.viewer.world.AgentView;
import io.orchard.viewer.world.LogLine;
import io.orchard.viewer.world.Motion;
import io.orchard.viewer.world.RunningAnimation;
import io.orchard.viewer.world.WorldMirror;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The agents on screen: one model per agent, loaded on a worker thread from the model it
 * registered with (or a placeholder, with the reason logged), then driven as the paper's applet
 * drove the VRML browser through the EAI: a walk becomes {@link BodyModel#moveTo}, a turn
 * {@link BodyModel#setRotation}, a joint {@link BodyModel#setJointRotation}, an animation
 * {@link BodyModel#startAnimation} or {@link BodyModel#stopAnimation}; every frame each model is
 * advanced to the clock's time.
 *
 * <p>A model that arrives after its agent has already walked, turned and started animations is
 * posed from what the {@link AgentView} remembers, with each animation started at its own start
 * time, so that it looks exactly as if it had been there all along.
 */
public final class AgentsState extends BaseAppState implements WorldMirror.Listener {

    private static final Logger LOG = LoggerFactory.getLogger(AgentsState.class);

    /** Above this many agents, names are not shown until asked for. */
    public static final int MOST_LABELS = 30;

    /**
     * Figures that show fewer pixels tall are not drawn: {@link MarkersState} pins them, and a
     * hundred of them far away would cost a thousand draw calls for a few pixels each.
     */
    static final int DRAWN_PX = 12;


    private final WorldMirror mirror;
    private final SimClock clock;
    private final ModelLimits limits;
    private final Node agentsNode = new Node("agents");
    private final Map<String, Shown> shown = new LinkedHashMap<>();
    private final Set<String> warned = new HashSet<>();
    private ExecutorService loaders;
    private BodyModelLoader loader;
    private Palette palette;
    private int pending;
    private Boolean labels;

    /** One agent on screen. */
    private static final class Shown {
        final AgentView agent;
        final Node anchor;
        final Geometry shade;
        BodyModel model;

        Shown(AgentView agent, Palette palette) {
            this.agent = agent;
            this.anchor = new Node("agent " + agent.name());
            float radius = (float) agent.body().radius() * 1.1f;
            this.shade = new Geometry(agent.name() + " shade", Meshes.ring(0, radius, 16));
            shade.setMaterial(palette.lit(Palette.SHADE));
            shade.setShadowMode(ShadowMode.Off);
            anchor.attachChild(shade);
        }
    }

    /** The agents of {@code mirror}, moved by {@code clock}, with models loaded within {@code limits}. */
    public AgentsState(WorldMirror mirror, SimClock clock, ModelLimits limits) {
        this.mirror = mirror;
        this.clock = clock;
        this.limits = limits;
    }

    @Override
    protected void initialize(Application app) {
        loader = new BodyModelLoader(app.getAssetManager(), limits);
        palette = new Palette(app.getAssetManager());
        // Two loaders: a crowd of a hundred models loads in half the time on two cores.
        loaders = Executors.newFixedThreadPool(2, r -> {
            Thread thread = new Thread(r, "orchard-model-loader");
            thread.setDaemon(true);
            return thread;
        });
        agentsNode.setShadowMode(ShadowMode.CastAndReceive);
        ((SimpleApplication) app).getRootNode().attachChild(agentsNode);
        mirror.addListener(this);
        mirror.agents().forEach(this::agentAdded);
    }

    @Override
    public void agentAdded(AgentView agent) {
        Shown entry = new Shown(agent, palette);
        shown.put(agent.name(), entry);
        agentsNode.attachChild(entry.anchor);
        pending++;
        Application app = getApplication();
        loaders.execute(() -> {
            BodyModelLoader.Loaded loaded;
            try {
                loaded = loader.load(agent.name(), agent.body().height(), agent.model().orElse(null));
            } catch (RuntimeException | StackOverflowError | OutOfMemoryError e) {
                // Never expected from the loader; still no reason to lose the agent or the viewer.
                loaded = new BodyModelLoader.Loaded(null, "loading the model failed: " + e);
            }
            BodyModelLoader.Loaded result = loaded;
            app.enqueue(() -> attach(entry, result));
        });
    }

    private void attach(Shown entry, BodyModelLoader.Loaded loaded) {
        pending--;
        if (shown.get(entry.agent.name()) != entry) {
            return; // the agent left (or came back) while its model loaded
        }
        if (loaded.problem() != null) {
            String format = entry.agent.model().map(m -> m.format().wireName()).orElse("no");
            LOG.warn("agent {}: its {} model cannot be shown, a placeholder stands in: {}", entry.agent.name(), format,
                    loaded.problem());
            mirror.note(LogLine.Kind.PROBLEM, entry.agent.name() + "'s model cannot be shown: " + loaded.problem());
        }
        entry.model = loaded.model() != null ? loaded.model()
                : BodyModels.placeholder(entry.agent.name(), getApplication().getAssetManager());
        entry.anchor.attachChild(entry.model.root());
        pose(entry);
    }

    /** Poses a model just loaded as the agent stands now, replaying its animations from their starts. */
    private void pose(Shown entry) {
        AgentView agent = entry.agent;
        BodyModel model = entry.model;
        List<RunningAnimation> running = new ArrayList<>(agent.runningAnimations());
        running.sort(Comparator.comparingDouble(RunningAnimation::startTime));
        for (RunningAnimation animation : running) {
            model.update(animation.startTime());
            drive(agent, "animation " + animation.name(), () -> model.startAnimation(animation.name(), animation.loop()));
        }
        Motion motion = agent.motion();
        Vec3 at = agent.positionAt(clock.now());
        drive(agent, "move", () -> {
            if (motion != null) {
                model.moveTo(vector(motion.from()), vector(motion.to()), motion.startTime(), motion.duration());
            } else {
                model.moveTo(vector(at), vector(at), model.time(), 0);
            }
        });
        rotate(agent, model, agent.rotation());
        agent.jointRotations().forEach((joint, rotation) -> drive(agent, "joint " + joint,
                () -> model.setJointRotation(joint, vector(rotation.axis()), (float) rotation.angle())));
        model.update(clock.now());
    }

    @Override
    public void agentRemoved(AgentView agent) {
        Shown entry = shown.remove(agent.name());
        if (entry != null) {
            entry.anchor.removeFromParent();
        }
    }

    @Override
    public void worldCleared() {
        List.copyOf(shown.values()).forEach(entry -> agentRemoved(entry.agent));
    }

    @Override
    public void agentMoved(AgentView agent, Motion motion) {
        withModel(agent, model -> drive(agent, "move",
                () -> model.moveTo(vector(motion.from()), vector(motion.to()), motion.startTime(), motion.duration())));
    }

    @Override
    public void agentRotated(AgentView agent, Rotation rotation, double time) {
        withModel(agent, model -> rotate(agent, model, rotation));
    }

    @Override
    public void jointRotated(AgentView agent, String joint, Rotation rotation, double time) {
        withModel(agent, model -> drive(agent, "joint " + joint,
                () -> model.setJointRotation(joint, vector(rotation.axis()), (float) rotation.angle())));
    }

    @Override
    public void animationStarted(AgentView agent, RunningAnimation animation) {
        withModel(agent, model -> {
            // Start it at its own time even when the frame jumps past it (replays, screenshots).
            model.update(animation.startTime());
            drive(agent, "animation " + animation.name(), () -> model.startAnimation(animation.name(), animation.loop()));
        });
    }

    @Override
    public void animationStopped(AgentView agent, String name, double time) {
        withModel(agent, model -> {
            model.update(time);
            drive(agent, "animation " + name, () -> model.stopAnimation(name));
        });
    }

    @Override
    public void update(float tpf) {
        double now = clock.now();
        WorldSceneState world = getState(WorldSceneState.class);
        Node.CullHint shades = world != null && world.hasShadows() ? Node.CullHint.Always : Node.CullHint.Inherit;
        Camera camera = getApplication().getCamera();
        for (Shown entry : shown.values()) {
            Vec3 feet = entry.agent.positionAt(now);
            entry.shade.setLocalTranslation((float) feet.x(), (float) feet.y() + 0.03f, (float) feet.z());
            entry.shade.setCullHint(shades);
            if (entry.model != null) {
                advance(entry, now);
                // A figure a few pixels tall is a blur of a dozen draw calls: its pin shows the agent instead.
                if (shownHeight(camera, feet, entry.agent.body().height()) < DRAWN_PX) {
                    entry.model.root().setCullHint(Node.CullHint.Always);
                    entry.shade.setCullHint(Node.CullHint.Always);
                } else {
                    entry.model.root().setCullHint(Node.CullHint.Inherit);
                }
            }
        }
    }

    /** How many pixels tall a body of {@code height} standing at {@code feet} shows; 0 when behind the camera. */
    private static float shownHeight(Camera camera, Vec3 feet, double height) {
        Vector3f low = camera.getScreenCoordinates(new Vector3f((float) feet.x(), (float) feet.y(), (float) feet.z()));
        Vector3f high = camera.getScreenCoordinates(new Vector3f((float) feet.x(), (float) (feet.y() + height),
                (float) feet.z()));
        return low.z > 0 && low.z < 1 ? high.y - low.y : 0;
    }

    /** Advances a model; one that fails while animating is replaced by the placeholder, posed anew. */
    private void advance(Shown entry, double now) {
        try {
            entry.model.update(now);
        } catch (RuntimeException e) {
            LOG.warn("agent {}: its model failed while animating, a placeholder stands in: {}", entry.agent.name(),
                    e.toString());
            mirror.note(LogLine.Kind.PROBLEM, entry.agent.name() + "'s model failed while animating: " + e);
            entry.model.root().removeFromParent();
            entry.model = BodyModels.placeholder(entry.agent.name(), getApplication().getAssetManager());
            entry.anchor.attachChild(entry.model.root());
            pose(entry);
        }
    }

    /** Whether every agent's model has been loaded and placed, so that a frame shows them all. */
    public boolean isSettled() {
        return pending == 0;
    }

    /** The model shown for an agent, once loaded. */
    public BodyModel model(String name) {
        Shown entry = shown.get(name);
        return entry == null ? null : entry.model;
    }

    /** Shows or hides the agents' names ({@link MarkersState} draws them); by default they show when there are at most {@value #MOST_LABELS} agents. */
    public void setLabels(boolean visible) {
        labels = visible;
    }

    /** Whether names show. */
    public boolean showLabels() {
        return labels != null ? labels : shown.size() <= MOST_LABELS;
    }

    private void rotate(AgentView agent, BodyModel model, Rotation rotation) {
        drive(agent, "rotation", () -> model.setRotation(vector(rotation.axis()), (float) rotation.angle()));
    }

    private void withModel(AgentView agent, java.util.function.Consumer<BodyModel> change) {
        Shown entry = shown.get(agent.name());
        if (entry != null && entry.model != null) {
            change.accept(entry.model);
        }
    }

    /** A call on a model, in the spirit of an EAI call: a failure is reported once and never stops the viewer. */
    private void drive(AgentView agent, String what, ModelCall call) {
        try {
            call.run();
        } catch (ModelException e) {
            if (warned.add(agent.name() + " " + what)) {
                LOG.warn("agent {}: {} cannot be shown: {}", agent.name(), what, e.getMessage());
                mirror.note(LogLine.Kind.PROBLEM, agent.name() + ": " + what + " cannot be shown: " + e.getMessage());
            }
        }
    }

    @FunctionalInterface
    private interface ModelCall {
        void run() throws ModelException;
    }

    private static Vector3f vector(Vec3 v) {
        return new Vector3f((float) v.x(), (float) v.y(), (float) v.z());
    }

    @Override
    protected void cleanup(Application app) {
        mirror.removeListener(this);
        agentsNode.removeFromParent();
        loaders.shutdownNow();
    }

    @Override
    protected void onEnable() {
    }

    @Override
    protected void onDisable() {
    }
}
