package io.orchard.viewer.world;

import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.AgentMessage;
import io.orchard.protocol.message.AgentMovedMessage;
import io.orchard.protocol.message.AgentRemovedMessage;
import io.orchard.protocol.message.AgentRotatedMessage;
import io.orchard.protocol.message.AnimationStartedMessage;
import io.orchard.protocol.message.AnimationStoppedMessage;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.FruitRemovedMessage;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.GameStartedMessage;
import io.orchard.protocol.message.JointRotatedMessage;
import io.orchard.protocol.message.SayMessage;
import io.orchard.protocol.message.ScoreUpdateMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Score;
import java.util.ArrayDeque;
import java.util.Collection;
import java.util.Collections;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * The viewer's copy of the world, kept up to date from the server's messages: the paper's
 * "applet client" that turns messages into changes of the scene, minus the scene. Listeners (the
 * scene's app states) hear of every change and draw it.
 *
 * <p>Each change carries the simulated time it happened: the time of the last {@code Tick} for a
 * live server, the recorded time for a replay. {@link #apply(ServerMessage, double)} takes that
 * time explicitly; {@link #apply(ServerMessage)} uses the last time the messages themselves told.
 *
 * <p>Not thread-safe: used on the render thread only.
 */
public final class WorldMirror {

    /** Hears of every change, on the thread that applies messages. All methods do nothing by default. */
    public interface Listener {

        /** A snapshot arrived: the static world and the fruit are known (or known anew). */
        default void worldShown(WorldSnapshotMessage snapshot) {}

        /** Everything was forgotten, before a replay rewinds. */
        default void worldCleared() {}

        /** A fruit left the world. */
        default void fruitRemoved(FruitState fruit, String eatenBy) {}

        /** An agent entered the world. */
        default void agentAdded(AgentView agent) {}

        /** An agent left the world. */
        default void agentRemoved(AgentView agent) {}

        /** An agent started a walk. */
        default void agentMoved(AgentView agent, Motion motion) {}

        /** An agent turned. */
        default void agentRotated(AgentView agent, Rotation rotation, double time) {}

        /** A joint of an agent turned. */
        default void jointRotated(AgentView agent, String joint, Rotation rotation, double time) {}

        /** An agent started an animation. */
        default void animationStarted(AgentView agent, RunningAnimation animation) {}

        /** An agent stopped an animation. */
        default void animationStopped(AgentView agent, String name, double time) {}
    }

    /** How many lines {@link #log()} keeps. */
    public static final int LOG_LINES = 50;

    private final List<Listener> listeners = new CopyOnWriteArrayList<>();
    private WorldSnapshotMessage snapshot;
    private final Map<String, FruitState> fruit = new LinkedHashMap<>();
    private final Map<String, AgentView> agents = new LinkedHashMap<>();
    private List<Score> scores = List.of();
    private GameStartedMessage game;
    private GameOverMessage over;
    private long tick;
    private double time;
    private final Deque<LogLine> log = new ArrayDeque<>();

    /** Adds a listener; it hears of changes from now on. */
    public void addListener(Listener listener) {
        listeners.add(listener);
    }

    /** Removes a listener. */
    public void removeListener(Listener listener) {
        listeners.remove(listener);
    }

    /** Applies one message at the time the messages so far have told (live servers). */
    public void apply(ServerMessage message) {
        apply(message, time);
    }

    /**
     * Applies one message that happened at simulated time {@code at} (replays pass the recorded
     * time). Messages that do not concern viewers are ignored, as are changes to agents or fruit
     * the viewer does not know.
     */
    public void apply(ServerMessage message, double at) {
        if (Double.isFinite(at) && at > time) {
            time = at;
        }
        if (message instanceof TickMessage t) {
            tick = t.tick();
            time = Math.max(time, t.time());
        } else if (message instanceof WorldSnapshotMessage s) {
            showWorld(s);
        } else if (message instanceof AgentAddedMessage added) {
            addAgent(added);
        } else if (message instanceof FruitRemovedMessage removed) {
            removeFruit(removed);
        } else if (message instanceof AgentRemovedMessage removed) {
            if (over != null) {
                // The game is over and its clients go home: the scene keeps the final state, where
                // every agent stood when the game ended, for the last picture and the prize-giving.
                if (agents.containsKey(removed.agent())) {
                    note(LogLine.Kind.EVENT, removed.agent() + " left (" + removed.reason() + ")");
                }
                return;
            }
            AgentView agent = agents.remove(removed.agent());
            if (agent != null) {
                note(LogLine.Kind.EVENT, removed.agent() + " left (" + removed.reason() + ")");
                listeners.forEach(l -> l.agentRemoved(agent));
            }
        } else if (message instanceof ScoreUpdateMessage update) {
            scores = update.scores();
        } else if (message instanceof SayMessage say) {
            note(LogLine.Kind.SAY, say.agent() + ": " + say.text());
        } else if (message instanceof GameStartedMessage started) {
            game = started;
            note(LogLine.Kind.EVENT, String.format(Locale.ROOT, "game started: seed %d, %d fruit, %.0f s",
                    started.seed(), started.fruitCount(), started.timeLimit()));
        } else if (message instanceof GameOverMessage end) {
            over = end;
            scores = end.ranking();
            note(LogLine.Kind.EVENT, "game over: " + end.reason());
        } else if (message instanceof ErrorMessage error) {
            note(LogLine.Kind.PROBLEM, "server: " + error.code().wireName() + ": " + error.text());
        } else if (message instanceof AgentMessage about) {
            AgentView agent = agents.get(about.agent());
            if (agent != null) {
                changeAgent(agent, about);
            }
        }
    }

    /** The news of an agent the viewer knows: it walks, turns, moves a joint or plays an animation. */
    private void changeAgent(AgentView agent, AgentMessage message) {
        if (message instanceof AgentMovedMessage moved) {
            Motion move = new Motion(moved.from(), moved.to(), moved.startTime(), moved.duration());
            agent.moved(move);
            listeners.forEach(l -> l.agentMoved(agent, move));
        } else if (message instanceof AgentRotatedMessage rotated) {
            agent.rotated(rotated.rotation());
            listeners.forEach(l -> l.agentRotated(agent, rotated.rotation(), time));
        } else if (message instanceof JointRotatedMessage joint) {
            agent.jointRotated(joint.joint(), joint.rotation());
            listeners.forEach(l -> l.jointRotated(agent, joint.joint(), joint.rotation(), time));
        } else if (message instanceof AnimationStartedMessage started) {
            RunningAnimation animation = new RunningAnimation(started.timeSensor(), started.loop(), time);
            agent.animationStarted(animation);
            listeners.forEach(l -> l.animationStarted(agent, animation));
        } else if (message instanceof AnimationStoppedMessage stopped) {
            agent.animationStopped(stopped.timeSensor());
            listeners.forEach(l -> l.animationStopped(agent, stopped.timeSensor(), time));
        }
    }

    /** Forgets everything but the listeners, which hear {@link Listener#worldCleared()}. */
    public void clear() {
        log.clear();
        restart();
    }

    /**
     * Forgets the world and the game but keeps the log, for a new connection whose snapshot
     * follows (the game may be another one now); the listeners hear {@link Listener#worldCleared()}.
     */
    public void restart() {
        snapshot = null;
        fruit.clear();
        agents.clear();
        scores = List.of();
        game = null;
        over = null;
        tick = 0;
        time = 0;
        listeners.forEach(Listener::worldCleared);
    }

    /** Adds a line for people to the log (the viewer's own news, such as a model that failed). */
    public void note(LogLine.Kind kind, String text) {
        log.addLast(new LogLine(time, kind, text));
        while (log.size() > LOG_LINES) {
            log.removeFirst();
        }
    }

    /** Whether a snapshot has arrived, so that there is a world to show. */
    public boolean hasWorld() {
        return snapshot != null;
    }

    /** The last snapshot: the static world (its fruit list is the fruit at that time, see {@link #fruit()}). */
    public Optional<WorldSnapshotMessage> snapshot() {
        return Optional.ofNullable(snapshot);
    }

    /** The fruit left, by id, in the snapshot's order. */
    public Collection<FruitState> fruit() {
        return Collections.unmodifiableCollection(fruit.values());
    }

    /** The agents in the world, in the order they arrived. */
    public Collection<AgentView> agents() {
        return Collections.unmodifiableCollection(agents.values());
    }

    /** The agent of that name, if it is in the world. */
    public Optional<AgentView> agent(String name) {
        return Optional.ofNullable(agents.get(name));
    }

    /** The scores, best first. */
    public List<Score> scores() {
        return scores;
    }

    /** The game's start, once it started. */
    public Optional<GameStartedMessage> game() {
        return Optional.ofNullable(game);
    }

    /** The game's end, once it ended. */
    public Optional<GameOverMessage> gameOver() {
        return Optional.ofNullable(over);
    }

    /** The last tick heard of. */
    public long tick() {
        return tick;
    }

    /** The latest simulated time the messages told, in seconds. */
    public double time() {
        return time;
    }

    /** The last {@value #LOG_LINES} lines for people, oldest first. */
    public List<LogLine> log() {
        return List.copyOf(log);
    }

    private void showWorld(WorldSnapshotMessage s) {
        if (snapshot != null) {
            List<AgentView> gone = List.copyOf(agents.values());
            agents.clear();
            gone.forEach(agent -> listeners.forEach(l -> l.agentRemoved(agent)));
        }
        snapshot = s;
        tick = s.tick();
        time = Math.max(time, s.time());
        fruit.clear();
        s.fruit().forEach(f -> fruit.put(f.id(), f));
        scores = s.scores();
        listeners.forEach(l -> l.worldShown(s));
    }

    private void addAgent(AgentAddedMessage added) {
        String name = added.agent().name();
        AgentView previous = agents.remove(name);
        if (previous != null) {
            listeners.forEach(l -> l.agentRemoved(previous));
        }
        AgentView agent = new AgentView(added.agent());
        agents.put(name, agent);
        note(LogLine.Kind.EVENT, name + " joined");
        listeners.forEach(l -> l.agentAdded(agent));
    }

    private void removeFruit(FruitRemovedMessage removed) {
        FruitState gone = fruit.remove(removed.fruit());
        if (gone != null) {
            note(LogLine.Kind.EVENT, removed.agent() + " collected " + gone.kind().wireName() + " " + gone.id());
            listeners.forEach(l -> l.fruitRemoved(gone, removed.agent()));
        }
    }
}
