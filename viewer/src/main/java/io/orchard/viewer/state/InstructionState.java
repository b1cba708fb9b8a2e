package io.orchard.viewer.state;

import com.jme3.app.Application;
import com.jme3.app.SimpleApplication;
import com.jme3.app.state.BaseAppState;
import com.jme3.font.BitmapFont;
import com.jme3.font.BitmapText;
import com.jme3.input.KeyInput;
import com.jme3.input.RawInputListener;
import com.jme3.input.event.JoyAxisEvent;
import com.jme3.input.event.JoyButtonEvent;
import com.jme3.input.event.KeyInputEvent;
import com.jme3.input.event.MouseButtonEvent;
import com.jme3.input.event.MouseMotionEvent;
import com.jme3.input.event.TouchEvent;
import com.jme3.math.ColorRGBA;
import io.orchard.viewer.world.AgentView;

/**
 * A one-line text field for instructions to the selected agent, in the spirit of the paper's
 * agents that took natural-language instructions: Enter opens it, typing fills it, Enter sends it
 * as an {@code Instruction} to the agent's controller, Escape closes it. While it is open it takes
 * every key, so that typing does not move the camera.
 */
public final class InstructionState extends BaseAppState implements RawInputListener {

    /** The longest instruction the protocol allows. */
    public static final int MOST_CHARACTERS = 1000;

    private final LiveState live;
    private BitmapText line;
    private final StringBuilder typed = new StringBuilder();
    private boolean typing;
    private float blink;

    /**
     * The instruction field, closed.
     *
     * @param live the connection to send through, or null when replaying (nothing can be sent)
     */
    public InstructionState(LiveState live) {
        this.live = live;
    }

    @Override
    protected void initialize(Application app) {
        BitmapFont font = app.getAssetManager().loadFont("Interface/Fonts/Default.fnt");
        line = new BitmapText(font);
        line.setSize(Math.max(14f, Math.min(22f, app.getCamera().getHeight() / 40f)));
        line.setColor(new ColorRGBA(1f, 0.95f, 0.6f, 1f));
        ((SimpleApplication) app).getGuiNode().attachChild(line);
        app.getInputManager().addRawInputListener(this);
    }

    /** Whether the field is open and taking keys. */
    public boolean isTyping() {
        return typing;
    }

    @Override
    public void onKeyEvent(KeyInputEvent event) {
        if (!event.isPressed() && !event.isRepeating()) {
            if (typing) {
                event.setConsumed();
            }
            return;
        }
        AgentView agent = selected();
        if (!typing) {
            if (event.isPressed() && event.getKeyCode() == KeyInput.KEY_RETURN && agent != null) {
                typing = true;
                typed.setLength(0);
                event.setConsumed();
            }
            return;
        }
        event.setConsumed();
        switch (event.getKeyCode()) {
            case KeyInput.KEY_ESCAPE -> typing = false;
            case KeyInput.KEY_RETURN, KeyInput.KEY_NUMPADENTER -> {
                typing = false;
                String text = typed.toString().strip();
                if (!text.isEmpty() && agent != null && live != null) {
                    live.sendInstruction(agent.name(), text);
                }
            }
            case KeyInput.KEY_BACK -> {
                if (typed.length() > 0) {
                    typed.setLength(typed.length() - 1);
                }
            }
            default -> {
                char c = event.getKeyChar();
                if (c >= ' ' && c != 127 && typed.length() < MOST_CHARACTERS) {
                    typed.append(c);
                }
            }
        }
    }

    @Override
    public void update(float tpf) {
        blink = (blink + tpf) % 1f;
        AgentView agent = selected();
        String text;
        if (agent == null) {
            typing = false;
            text = "";
        } else if (live == null) {
            text = "replay: instructions go to agents of a live game only";
        } else if (typing) {
            text = "to " + agent.name() + ": " + typed + (blink < 0.5f ? "_" : " ") + "   (Enter sends, Esc cancels)";
        } else {
            text = "Enter: an instruction for " + agent.name();
        }
        if (!text.equals(line.getText())) {
            line.setText(text);
        }
        float size = line.getSize();
        line.setLocalTranslation(size * 0.6f, size * 6.2f, 1); // above the three lines of keys
    }

    private AgentView selected() {
        SelectionState selection = getState(SelectionState.class);
        return selection == null ? null : selection.selected();
    }

    @Override
    protected void cleanup(Application app) {
        app.getInputManager().removeRawInputListener(this);
        line.removeFromParent();
    }

    @Override
    protected void onEnable() {
    }

    @Override
    protected void onDisable() {
    }

    @Override
    public void beginInput() {
    }

    @Override
    public void endInput() {
    }

    @Override
    public void onJoyAxisEvent(JoyAxisEvent event) {
    }

    @Override
    public void onJoyButtonEvent(JoyButtonEvent event) {
    }

    @Override
    public void onMouseMotionEvent(MouseMotionEvent event) {
    }

    @Override
    public void onMouseButtonEvent(MouseButtonEvent event) {
    }

    @Override
    public void onTouchEvent(TouchEvent event) {
    }
}
