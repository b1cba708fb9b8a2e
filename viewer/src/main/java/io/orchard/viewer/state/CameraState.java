package io.orchard.viewer.state;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.input.InputManager;
import com.jme3.input.KeyInput;
import com.jme3.input.MouseInput;
import com.jme3.input.controls.ActionListener;
import com.jme3.input.controls.AnalogListener;
import com.jme3.input.controls.KeyTrigger;
import com.jme3.input.controls.MouseAxisTrigger;
import com.jme3.input.controls.MouseButtonTrigger;
import com.jme3.math.FastMath;
import com.jme3.math.Quaternion;
import com.jme3.math.Vector2f;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.scene.Landscape;
import io.orchard.viewer.world.AgentView;
import io.orchard.viewer.world.WorldMirror;

/**
 * The camera. It orbits a point (left drag turns, right drag pans, the wheel zooms, W A S D move
 * the point), flies freely ({@code F}: W A S D and Q E move, drag to look), or looks through the
 * selected agent's eyes ({@code V}). A click selects the agent under the cursor, and the orbit then
 * follows it. Headless runs use a fixed view given on the command line, an overview of the whole
 * world, or a view from behind the followed agent.
 */
public final class CameraState extends BaseAppState implements ActionListener, AnalogListener {

    /** How the camera moves. */
    public enum Mode {
        /** Around a point, which follows the selected agent. */
        ORBIT,
        /** Free flight. */
        FLY,
        /** Through the selected agent's eyes. */
        POINT_OF_VIEW
    }

    /** The vertical field of view, in degrees. */
    public static final float FIELD_OF_VIEW = 45f;
    /** The near and far clipping distances. */
    public static final float NEAR = 0.3f;
    /** The far clipping distance. */
    public static final float FAR = 5000f;

    private static final String[] MAPPINGS = {"drag", "pan", "left", "right", "up", "down", "zoomIn", "zoomOut",
        "forward", "back", "strafeLeft", "strafeRight", "rise", "sink", "fly", "pov", "deselect"};

    private final WorldMirror mirror;
    private final SimClock clock;
    private final boolean interactive;
    private final Vector3f fixedLocation;
    private final Vector3f fixedTarget;
    private Camera camera;
    private float appliedSide;
    private InputManager input;
    private Mode mode = Mode.ORBIT;
    private final Vector3f target = new Vector3f();
    private float distance = 60;
    private float yaw = FastMath.QUARTER_PI;
    private float pitch = 0.6f;
    private final Vector3f flyAt = new Vector3f();
    private float flyYaw;
    private float flyPitch;
    private boolean dragging;
    private boolean panning;
    private float dragged;
    private boolean framed;

    /**
     * The camera over the world of {@code mirror}, following the selected agent at the time of {@code clock}.
     *
     * @param interactive   whether the mouse and keys move the camera (windowed)
     * @param fixedLocation where a headless camera stands, or null
     * @param fixedTarget   what a headless camera looks at, or null
     */
    public CameraState(WorldMirror mirror, SimClock clock, boolean interactive, Vector3f fixedLocation,
                       Vector3f fixedTarget) {
        this.mirror = mirror;
        this.clock = clock;
        this.interactive = interactive;
        this.fixedLocation = fixedLocation;
        this.fixedTarget = fixedTarget;
    }

    /** A camera of the viewer's lens for a frame of this size, as headless shots and tests use. */
    public static Camera lens(int width, int height) {
        Camera lens = new Camera(width, height);
        lens.setFrustumPerspective(FIELD_OF_VIEW, (float) width / height, NEAR, FAR);
        return lens;
    }

    @Override
    protected void initialize(Application app) {
        camera = app.getCamera();
        camera.setFrustumPerspective(FIELD_OF_VIEW, (float) camera.getWidth() / camera.getHeight(), NEAR, FAR);
        input = app.getInputManager();
        if (interactive && input != null) {
            input.setCursorVisible(true);
            input.addMapping("drag", new MouseButtonTrigger(MouseInput.BUTTON_LEFT));
            input.addMapping("pan", new MouseButtonTrigger(MouseInput.BUTTON_RIGHT));
            input.addMapping("left", new MouseAxisTrigger(MouseInput.AXIS_X, true));
            input.addMapping("right", new MouseAxisTrigger(MouseInput.AXIS_X, false));
            input.addMapping("up", new MouseAxisTrigger(MouseInput.AXIS_Y, false));
            input.addMapping("down", new MouseAxisTrigger(MouseInput.AXIS_Y, true));
            input.addMapping("zoomIn", new MouseAxisTrigger(MouseInput.AXIS_WHEEL, false));
            input.addMapping("zoomOut", new MouseAxisTrigger(MouseInput.AXIS_WHEEL, true));
            input.addMapping("forward", new KeyTrigger(KeyInput.KEY_W));
            input.addMapping("back", new KeyTrigger(KeyInput.KEY_S));
            input.addMapping("strafeLeft", new KeyTrigger(KeyInput.KEY_A));
            input.addMapping("strafeRight", new KeyTrigger(KeyInput.KEY_D));
            input.addMapping("rise", new KeyTrigger(KeyInput.KEY_E));
            input.addMapping("sink", new KeyTrigger(KeyInput.KEY_Q));
            input.addMapping("fly", new KeyTrigger(KeyInput.KEY_F));
            input.addMapping("pov", new KeyTrigger(KeyInput.KEY_V));
            input.addMapping("deselect", new KeyTrigger(KeyInput.KEY_ESCAPE));
            input.addListener(this, MAPPINGS);
        }
    }

    /** How the camera moves now. */
    public Mode mode() {
        return mode;
    }

    /** Switches between orbit, flight and the selected agent's point of view. */
    public void setMode(Mode next) {
        if (next == Mode.FLY && mode != Mode.FLY) {
            flyAt.set(camera.getLocation());
            float[] angles = camera.getRotation().toAngles(null);
            flyPitch = angles[0];
            flyYaw = angles[1];
        }
        mode = next;
    }

    @Override
    public void onAction(String name, boolean pressed, float tpf) {
        switch (name) {
            case "drag" -> {
                if (pressed) {
                    dragging = true;
                    dragged = 0;
                } else {
                    dragging = false;
                    if (dragged < 0.01f) {
                        click(input.getCursorPosition());
                    }
                }
            }
            case "pan" -> panning = pressed;
            case "fly" -> {
                if (pressed) {
                    setMode(mode == Mode.FLY ? Mode.ORBIT : Mode.FLY);
                }
            }
            case "pov" -> {
                if (pressed) {
                    setMode(mode == Mode.POINT_OF_VIEW || selection().selected() == null ? Mode.ORBIT : Mode.POINT_OF_VIEW);
                }
            }
            case "deselect" -> {
                if (pressed) {
                    selection().select(null);
                    setMode(Mode.ORBIT);
                }
            }
            default -> {
            }
        }
    }

    private void click(Vector2f cursor) {
        AgentView hit = selection().pickAt(cursor);
        if (hit == null && mode == Mode.POINT_OF_VIEW) {
            setMode(Mode.ORBIT);
        }
    }

    @Override
    public void onAnalog(String name, float value, float tpf) {
        float turn = value * 3f;
        switch (name) {
            case "left", "right", "up", "down" -> {
                if (dragging) {
                    dragged += value;
                }
                float sign = name.equals("left") || name.equals("down") ? -1 : 1;
                if (dragging && mode == Mode.ORBIT) {
                    if (name.equals("left") || name.equals("right")) {
                        yaw -= sign * turn;
                    } else {
                        pitch = FastMath.clamp(pitch - sign * turn, 0.05f, 1.5f);
                    }
                } else if (dragging && mode == Mode.FLY) {
                    if (name.equals("left") || name.equals("right")) {
                        flyYaw -= sign * turn;
                    } else {
                        flyPitch = FastMath.clamp(flyPitch + sign * turn, -1.5f, 1.5f);
                    }
                } else if (panning && mode == Mode.ORBIT) {
                    float step = value * distance;
                    Vector3f side = camera.getLeft().clone().setY(0).normalizeLocal();
                    Vector3f ahead = camera.getDirection().clone().setY(0).normalizeLocal();
                    switch (name) {
                        case "left" -> target.addLocal(side.mult(step));
                        case "right" -> target.addLocal(side.mult(-step));
                        case "up" -> target.addLocal(ahead.mult(-step));
                        default -> target.addLocal(ahead.mult(step));
                    }
                    selection().select(null);
                }
            }
            case "zoomIn" -> distance = FastMath.clamp(distance * (1 - value * 0.08f), 2, 800);
            case "zoomOut" -> distance = FastMath.clamp(distance * (1 + value * 0.08f), 2, 800);
            default -> move(name, tpf);
        }
    }

    private void move(String name, float tpf) {
        float speed = (mode == Mode.FLY ? 20f : Math.max(10f, distance)) * tpf;
        Vector3f ahead = camera.getDirection().clone();
        Vector3f side = camera.getLeft().clone();
        if (mode == Mode.ORBIT) {
            ahead.setY(0).normalizeLocal();
            side.setY(0).normalizeLocal();
        }
        Vector3f shift = switch (name) {
            case "forward" -> ahead.mult(speed);
            case "back" -> ahead.mult(-speed);
            case "strafeLeft" -> side.mult(speed);
            case "strafeRight" -> side.mult(-speed);
            case "rise" -> Vector3f.UNIT_Y.mult(speed);
            case "sink" -> Vector3f.UNIT_Y.mult(-speed);
            default -> Vector3f.ZERO;
        };
        if (mode == Mode.FLY) {
            flyAt.addLocal(shift);
        } else if (mode == Mode.ORBIT) {
            target.addLocal(shift.setY(0));
            selection().select(null);
        }
    }

    @Override
    public void update(float tpf) {
        frameBesideThePanel();
        if (!framed && mirror.hasWorld()) {
            frame(mirror.snapshot().orElseThrow());
            framed = true;
        }
        AgentView followed = selection().selected();
        double now = clock.now();
        if (mode == Mode.POINT_OF_VIEW && followed != null) {
            lookThrough(followed, now);
            return;
        }
        if (mode == Mode.FLY) {
            camera.setLocation(flyAt);
            camera.setRotation(new Quaternion().fromAngles(flyPitch, flyYaw, 0));
            return;
        }
        if (!interactive && fixedLocation != null && followed == null) {
            camera.setLocation(fixedLocation);
            camera.lookAt(fixedTarget != null ? fixedTarget : target, Vector3f.UNIT_Y);
            return;
        }
        if (followed != null) {
            Vec3 at = followed.positionAt(now);
            Vector3f wanted = new Vector3f((float) at.x(), (float) (at.y() + followed.body().height() * 0.5),
                    (float) at.z());
            if (interactive) {
                target.interpolateLocal(wanted, Math.min(1f, tpf * 6f));
            } else {
                chase(followed, wanted);
                return;
            }
        }
        Vector3f offset = new Vector3f(FastMath.cos(pitch) * FastMath.sin(yaw), FastMath.sin(pitch),
                FastMath.cos(pitch) * FastMath.cos(yaw)).multLocal(distance);
        camera.setLocation(target.add(offset));
        camera.lookAt(target, Vector3f.UNIT_Y);
    }

    /**
     * Shifts the lens so that the middle of the view is the middle of the screen beside the game
     * panel, not under it: the world is framed in the space the panel leaves.
     */
    private void frameBesideThePanel() {
        HudState hud = getState(HudState.class);
        float side = hud == null ? 0 : hud.sideWidth();
        if (side == appliedSide) {
            return;
        }
        camera.setFrustumPerspective(FIELD_OF_VIEW, (float) camera.getWidth() / camera.getHeight(), NEAR, FAR);
        float shift = (camera.getFrustumRight() - camera.getFrustumLeft()) * side / 2 / camera.getWidth();
        camera.setFrustumLeft(camera.getFrustumLeft() - shift);
        camera.setFrustumRight(camera.getFrustumRight() - shift);
        camera.update();
        appliedSide = side;
    }

    /** The whole walkable ground in view, from the south-east; or the fixed view's target. */
    private void frame(WorldSnapshotMessage snapshot) {
        Vector3f centre = Landscape.centre(snapshot.bounds());
        float size = (float) Math.max(snapshot.bounds().maxX() - snapshot.bounds().minX(),
                snapshot.bounds().maxZ() - snapshot.bounds().minZ());
        target.set(fixedTarget != null ? fixedTarget : centre);
        HudState hud = getState(HudState.class);
        float beside = hud == null ? 0 : hud.sideWidth() / camera.getWidth();
        // Beside the panel the view is narrower: further back, the whole ground still shows.
        distance = fixedTarget != null && fixedLocation == null ? 40 : size * 0.95f * (1 + beside);
        if (fixedLocation != null) {
            Vector3f offset = fixedLocation.subtract(target);
            distance = Math.max(2f, offset.length());
            yaw = FastMath.atan2(offset.x, offset.z);
            pitch = FastMath.asin(FastMath.clamp(offset.y / distance, -1f, 1f));
        }
    }

    /** From behind and well above the agent, looking past it the way it faces. */
    private void chase(AgentView agent, Vector3f centre) {
        float heading = (float) agent.heading();
        Vector3f facing = new Vector3f(-FastMath.sin(heading), 0, -FastMath.cos(heading));
        // Steep enough to look over the crowns, which hang 3 to 8 units high.
        float back = 5f + 3f * (float) agent.body().height();
        camera.setLocation(centre.subtract(facing.mult(back * 0.75f)).addLocal(0, back * 0.85f, 0));
        camera.lookAt(centre.add(facing.mult(back * 0.5f)), Vector3f.UNIT_Y);
    }

    private void lookThrough(AgentView agent, double now) {
        Vec3 at = agent.positionAt(now);
        float heading = (float) agent.heading();
        Vector3f eye = new Vector3f((float) at.x(), (float) (at.y() + agent.body().height() * 0.92), (float) at.z());
        Vector3f facing = new Vector3f(-FastMath.sin(heading), -0.12f, -FastMath.cos(heading));
        camera.setLocation(eye.add(facing.mult((float) agent.body().radius())));
        camera.lookAt(eye.add(facing.mult(10)), Vector3f.UNIT_Y);
    }

    private SelectionState selection() {
        return getState(SelectionState.class);
    }

    @Override
    protected void cleanup(Application app) {
        if (interactive && input != null) {
            for (String mapping : MAPPINGS) {
                if (input.hasMapping(mapping)) {
                    input.deleteMapping(mapping);
                }
            }
            input.removeListener(this);
        }
    }

    @Override
    protected void onEnable() {
    }

    @Override
    protected void onDisable() {
    }
}
