package io.orchard.viewer.state;

import com.jme3.app.Application;
import com.jme3.app.SimpleApplication;
import com.jme3.app.state.BaseAppState;
import com.jme3.font.BitmapFont;
import com.jme3.font.BitmapText;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.shape.Quad;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Score;
import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.world.AgentView;
import io.orchard.viewer.world.LogLine;
import io.orchard.viewer.world.Sighting;
import io.orchard.viewer.world.WorldMirror;
import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;

/**
 * The panels of text over the scene, in jME's own GUI (bitmap text on translucent panels): top
 * left the source and the game time, the scoreboard and the last things said and done; top right
 * the selected agent, its body and what it perceives right now; bottom left the keys.
 */
public final class HudState extends BaseAppState {

    private static final int MOST_SCORES = 12;
    private static final int MOST_LOG_LINES = 5;
    /** The left panel's width, in the text's height: room for a score line. */
    private static final float SIDE_WIDTH = 19f;
    private static final ColorRGBA PANEL = new ColorRGBA(0f, 0f, 0f, 0.55f);
    private static final ColorRGBA TITLE = new ColorRGBA(1f, 0.9f, 0.55f, 1f);
    private static final String KEYS = "drag: turn   right drag: pan   wheel: zoom   W A S D: move   F: fly\n"
            + "click: select and follow   V: its view   Enter: instruct   L: names   K: shadows   Tab: panel   H: help   Esc: deselect";
    private static final String REPLAY_KEYS = "Space: pause   + -: speed   left/right: -/+10 s   Home: start";
    private static final String LIVE_KEYS = "the operator's: Space: pause/continue the game   G: start it";

    private final WorldMirror mirror;
    private final SimClock clock;
    private final Supplier<String> source;
    private final boolean showKeys;
    private final Node hud = new Node("hud");
    private BitmapFont font;
    private float size;
    private Panel game;
    private Panel agent;
    private Panel keys;
    private boolean helpShown = true;
    private boolean collapsed;

    /**
     * The panels showing the world of {@code mirror} at the time of {@code clock}.
     *
     * @param source   says where the messages come from (server or recording), each frame
     * @param showKeys whether to show the keys (windowed)
     */
    public HudState(WorldMirror mirror, SimClock clock, Supplier<String> source, boolean showKeys) {
        this.mirror = mirror;
        this.clock = clock;
        this.source = source;
        this.showKeys = showKeys;
    }

    @Override
    protected void initialize(Application app) {
        font = app.getAssetManager().loadFont("Interface/Fonts/Default.fnt");
        int height = app.getCamera().getHeight();
        size = Math.max(13f, Math.min(20f, height / 48f));
        Material panel = new Material(app.getAssetManager(), "Common/MatDefs/Misc/Unshaded.j3md");
        panel.setColor("Color", PANEL);
        panel.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
        game = new Panel("game", panel);
        agent = new Panel("agent", panel);
        keys = new Panel("keys", panel);
        hud.attachChild(game.node);
        hud.attachChild(agent.node);
        if (showKeys) {
            hud.attachChild(keys.node);
        }
        ((SimpleApplication) app).getGuiNode().attachChild(hud);
    }

    /** Folds the left panel to its first two lines (source and time), or unfolds it. */
    public void toggleCollapsed() {
        collapsed = !collapsed;
    }

    /**
     * The width of the screen's left side the game panel takes, in pixels, for the camera to frame
     * the world beside it: 0 when the panel is folded or the HUD is off.
     */
    public float sideWidth() {
        return !isEnabled() || collapsed || size == 0 ? 0 : size * (SIDE_WIDTH + 1.2f);
    }

    /** Shows or hides the line of keys. */
    public void toggleHelp() {
        helpShown = !helpShown;
    }

    @Override
    public void update(float tpf) {
        int width = getApplication().getCamera().getWidth();
        int height = getApplication().getCamera().getHeight();
        float margin = size * 0.6f;
        String text = gameText();
        if (collapsed) {
            String[] lines = text.split("\n", 3);
            text = lines[0] + (lines.length > 1 ? "\n" + lines[1] : "") + "   (Tab: more)";
        }
        game.show(text, TITLE, margin, height - margin);
        String selected = agentText();
        if (selected.isEmpty()) {
            agent.node.setCullHint(Node.CullHint.Always);
        } else {
            agent.node.setCullHint(Node.CullHint.Inherit);
            agent.showRight(selected, width - margin, height - margin);
        }
        if (showKeys) {
            boolean replay = getState(ReplayState.class) != null;
            keys.node.setCullHint(helpShown ? Node.CullHint.Inherit : Node.CullHint.Always);
            keys.show(KEYS + "\n" + (replay ? REPLAY_KEYS : LIVE_KEYS), null, margin, margin + keys.textHeight());
        }
    }

    private String gameText() {
        StringBuilder text = new StringBuilder("Orchard  ").append(source.get()).append('\n');
        double now = clock.now();
        text.append(String.format(Locale.ROOT, "time %.1f s", now));
        mirror.game().ifPresent(g -> text.append(String.format(Locale.ROOT, " of %.0f s", g.timeLimit())));
        text.append("   tick ").append(mirror.tick());
        if (mirror.hasWorld()) {
            text.append("   fruit left ").append(mirror.fruit().size());
            mirror.game().ifPresent(g -> text.append(" of ").append(g.fruitCount()));
        } else {
            text.append("   waiting for the world");
        }
        mirror.gameOver().ifPresent(over -> text.append("\nGAME OVER: ").append(over.reason()));
        List<Score> scores = mirror.scores();
        if (!scores.isEmpty()) {
            text.append("\n\nScores");
            for (int i = 0; i < Math.min(MOST_SCORES, scores.size()); i++) {
                Score score = scores.get(i);
                boolean here = mirror.agent(score.agent()).isPresent();
                text.append(String.format(Locale.ROOT, "\n%2d. %-14s %3d pts  %2d fruit%s", i + 1, score.agent(),
                        score.points(), score.fruit(), here ? "" : "  (left)"));
            }
            if (scores.size() > MOST_SCORES) {
                text.append("\n    and ").append(scores.size() - MOST_SCORES).append(" more");
            }
        }
        List<LogLine> log = mirror.log();
        if (!log.isEmpty()) {
            text.append("\n\nSaid and done");
            for (LogLine line : log.subList(Math.max(0, log.size() - MOST_LOG_LINES), log.size())) {
                text.append(String.format(Locale.ROOT, "\n%6.1f  %s%s", line.time(),
                        line.kind() == LogLine.Kind.PROBLEM ? "! " : "", clip(line.text(), 36)));
            }
        }
        return text.toString();
    }

    private String agentText() {
        SelectionState selection = getState(SelectionState.class);
        if (selection == null || selection.selectedName() == null) {
            return "";
        }
        AgentView view = selection.selected();
        if (view == null) {
            return selection.selectedName() + " is not in the world";
        }
        Body body = view.body();
        Vec3 at = view.positionAt(clock.now());
        Sighting seen = selection.sighting();
        StringBuilder text = new StringBuilder(view.name()).append('\n');
        text.append(String.format(Locale.ROOT, "body r %.2f  h %.2f  speed %.1f%n", body.radius(), body.height(),
                body.maxSpeed()));
        text.append(String.format(Locale.ROOT, "%s reach %.2f  at %.2f to %.2f%n", body.gripper().part(),
                body.gripper().reach(), body.gripper().minHeight(), body.gripper().maxHeight()));
        text.append(String.format(Locale.ROOT, "sight %.0f  field %.0f deg%n", body.sight().range(),
                Math.toDegrees(body.sight().fieldOfView())));
        text.append(String.format(Locale.ROOT, "at %.1f, %.1f  heading %.0f deg%n", at.x(), at.z(),
                Math.toDegrees(view.heading())));
        long trees = seen.objects().stream().filter(o -> o.kind() == ObjectKind.TREE).count();
        text.append("\nperceives now: ").append(seen.fruit().size()).append(" fruit, ").append(trees)
                .append(" trees, ").append(seen.objects().size() - trees).append(" tables, ")
                .append(seen.agents().size()).append(" agents");
        for (FruitState fruit : seen.fruit().subList(0, Math.min(6, seen.fruit().size()))) {
            text.append(String.format(Locale.ROOT, "\n  %s %s at %.1f, %.1f, %.1f", fruit.kind().wireName(), fruit.id(),
                    fruit.position().x(), fruit.position().y(), fruit.position().z()));
        }
        if (seen.fruit().size() > 6) {
            text.append("\n  ...");
        }
        for (AgentView other : seen.agents().subList(0, Math.min(4, seen.agents().size()))) {
            text.append("\n  agent ").append(other.name());
        }
        for (Obstacle obstacle : seen.objects().subList(0, Math.min(3, seen.objects().size()))) {
            text.append("\n  ").append(obstacle.kind() == ObjectKind.TREE ? "tree " : "table ").append(obstacle.id());
        }
        return text.toString();
    }

    private static String clip(String text, int most) {
        String line = text.replace('\n', ' ');
        return line.length() <= most ? line : line.substring(0, most - 3) + "...";
    }

    @Override
    protected void cleanup(Application app) {
        hud.removeFromParent();
    }

    @Override
    protected void onEnable() {
        hud.setCullHint(Node.CullHint.Inherit);
    }

    @Override
    protected void onDisable() {
        hud.setCullHint(Node.CullHint.Always);
    }

    /** A block of text on a translucent panel. */
    private final class Panel {

        final Node node;
        final BitmapText text;
        final Geometry back;
        private String shown = "";

        Panel(String name, Material material) {
            node = new Node(name + " panel");
            back = new Geometry(name + " panel back", new Quad(1, 1));
            back.setMaterial(material);
            text = new BitmapText(font);
            text.setSize(size);
            text.setColor(ColorRGBA.White);
            node.attachChild(back);
            node.attachChild(text);
        }

        float textHeight() {
            return text.getHeight();
        }

        /** Shows the text with its top left corner at (x, top); the first line in {@code first} colour. */
        void show(String content, ColorRGBA first, float x, float top) {
            setText(content, first);
            place(x, top);
        }

        /** Shows the text with its top right corner at (right, top). */
        void showRight(String content, float right, float top) {
            setText(content, TITLE);
            place(right - text.getLineWidth(), top);
        }

        private void setText(String content, ColorRGBA first) {
            if (!content.equals(shown)) {
                shown = content;
                text.setText(content);
                text.setColor(ColorRGBA.White);
                if (first != null) {
                    int end = content.indexOf('\n');
                    text.setColor(0, end < 0 ? content.length() : end, first);
                }
            }
        }

        private void place(float x, float top) {
            float pad = size * 0.4f;
            text.setLocalTranslation(x, top, 1);
            float width = this == game ? Math.max(text.getLineWidth(), size * SIDE_WIDTH) : text.getLineWidth();
            back.setLocalScale(width + 2 * pad, text.getHeight() + 2 * pad, 1);
            back.setLocalTranslation(x - pad, top - text.getHeight() - pad, 0);
        }
    }
}
