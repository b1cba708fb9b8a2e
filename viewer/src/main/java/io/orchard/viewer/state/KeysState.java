package io.orchard.viewer.state;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.input.InputManager;
import com.jme3.input.KeyInput;
import com.jme3.input.controls.ActionListener;
import com.jme3.input.controls.KeyTrigger;

/**
 * The keys that are not the camera's: names on or off ({@code L}), the help line ({@code H}),
 * shadow maps on or off ({@code K}); for a live game, the operator's pause and continue
 * ({@code Space}) and start ({@code G}), which tell anyone else whose they are; and
 * for a replay pause ({@code Space}), speed ({@code +} and {@code -} double and halve it), seeking
 * ten seconds back and forth (the arrow keys) and back to the start ({@code Home}).
 */
public final class KeysState extends BaseAppState implements ActionListener {

    private static final double SEEK_STEP = 10;
    private static final String[] MAPPINGS = {"toggleNames", "toggleHud", "toggleHelp", "toggleShadows", "togglePause", "speedUp",
        "slowDown", "seekBack", "seekOn", "seekStart", "startGame"};

    private InputManager input;

    @Override
    protected void initialize(Application app) {
        input = app.getInputManager();
        input.addMapping("toggleNames", new KeyTrigger(KeyInput.KEY_L));
        input.addMapping("toggleHelp", new KeyTrigger(KeyInput.KEY_H));
        input.addMapping("toggleHud", new KeyTrigger(KeyInput.KEY_TAB));
        input.addMapping("toggleShadows", new KeyTrigger(KeyInput.KEY_K));
        input.addMapping("togglePause", new KeyTrigger(KeyInput.KEY_SPACE));
        input.addMapping("speedUp", new KeyTrigger(KeyInput.KEY_EQUALS), new KeyTrigger(KeyInput.KEY_ADD));
        input.addMapping("slowDown", new KeyTrigger(KeyInput.KEY_MINUS), new KeyTrigger(KeyInput.KEY_SUBTRACT));
        input.addMapping("seekBack", new KeyTrigger(KeyInput.KEY_LEFT));
        input.addMapping("seekOn", new KeyTrigger(KeyInput.KEY_RIGHT));
        input.addMapping("seekStart", new KeyTrigger(KeyInput.KEY_HOME));
        input.addMapping("startGame", new KeyTrigger(KeyInput.KEY_G));
        input.addListener(this, MAPPINGS);
    }

    @Override
    public void onAction(String name, boolean pressed, float tpf) {
        if (!pressed) {
            return;
        }
        AgentsState agents = getState(AgentsState.class);
        HudState hud = getState(HudState.class);
        ReplayState replay = getState(ReplayState.class);
        switch (name) {
            case "toggleNames" -> {
                if (agents != null) {
                    agents.setLabels(!agents.showLabels());
                }
            }
            case "toggleShadows" -> {
                WorldSceneState world = getState(WorldSceneState.class);
                if (world != null) {
                    world.setShadows(!world.hasShadows());
                }
            }
            case "toggleHelp" -> {
                if (hud != null) {
                    hud.toggleHelp();
                }
            }
            case "toggleHud" -> {
                if (hud != null) {
                    hud.toggleCollapsed();
                }
            }
            default -> {
                LiveState live = getState(LiveState.class);
                if (replay != null) {
                    replayKey(replay, name);
                } else if (live != null) {
                    liveKey(live, name);
                }
            }
        }
    }

    private static void liveKey(LiveState live, String name) {
        switch (name) {
            case "togglePause" -> live.togglePause();
            case "startGame" -> live.startGame();
            default -> {
            }
        }
    }

    private static void replayKey(ReplayState replay, String name) {
        switch (name) {
            case "togglePause" -> replay.setPaused(!replay.isPaused());
            case "speedUp" -> replay.setSpeed(Math.min(ReplayState.MAX_SPEED, replay.speed() * 2));
            case "slowDown" -> replay.setSpeed(Math.max(ReplayState.MIN_SPEED, replay.speed() / 2));
            case "seekBack" -> replay.seek(replay.now() - SEEK_STEP);
            case "seekOn" -> replay.seek(replay.now() + SEEK_STEP);
            case "seekStart" -> replay.seek(replay.startTime());
            default -> {
            }
        }
    }

    @Override
    protected void cleanup(Application app) {
        for (String mapping : MAPPINGS) {
            if (input.hasMapping(mapping)) {
                input.deleteMapping(mapping);
            }
        }
        input.removeListener(this);
    }

    @Override
    protected void onEnable() {
    }

    @Override
    protected void onDisable() {
    }
}
