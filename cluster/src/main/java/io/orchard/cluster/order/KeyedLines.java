package io.orchard.cluster.order;

import io.orchard.protocol.message.AgentMessage;
import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.FruitEatenMessage;
import io.orchard.protocol.message.FruitRemovedMessage;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.Message;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.server.sim.MissedTurn;
import io.orchard.server.sim.Recorder;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BiFunction;
import java.util.function.Function;

/**
 * The recorder of a part of the world: it keeps every line the part says, each with its place in
 * the tick, for the merge ({@link Merge}). The part's caller says where the lines being said belong:
 * to one cause ({@link #cause}), or by the agent ({@link #byAgent}) or the fruit ({@link #byFruit})
 * they are about, when one call of the part says lines of many agents or fruit.
 */
public final class KeyedLines implements Recorder {

    private final List<KeyedLine> lines = new ArrayList<>();
    private final Map<LineKey, Integer> said = new HashMap<>();
    /** Where what is said now belongs, from the message said (null for a missed turn's line) and the missed turn. */
    private BiFunction<Message, MissedTurn, LineKey> place = (message, missed) -> {
        throw new IllegalStateException("a line was said with no place given for it: " + message);
    };
    /**
     * The lines said last that went to one client each, in order, whose sessions report their
     * deliveries next: one for a message, three for a perception (all recorded before any is sent).
     */
    private final ArrayDeque<Integer> undelivered = new ArrayDeque<>();

    /** What is said from now on belongs to one cause, in the order said. */
    public void cause(LineKey key) {
        place = (message, missed) -> key;
    }

    /** What is said from now on in {@code step} of {@code tick} is about an agent: ordered by its name. */
    public void byAgent(long tick, LineKey.Step step) {
        place = (message, missed) -> new LineKey(tick, step, agentOf(message), 0, 0, 0);
    }

    /** What is said from now on is about a fruit, in the place {@code firstClaims} gives that fruit. */
    public void byFruit(Function<String, LineKey> firstClaims) {
        place = (message, missed) -> firstClaims.apply(fruitOf(message));
    }

    /**
     * What is said from now on are the turns missed in {@code tick}: client by client in the order of
     * their agents' names, as a missed turn names its client's agents.
     */
    public void byMissedTurn(long tick) {
        place = (message, missed) -> new LineKey(tick, LineKey.Step.MISSED, missed.agents().get(0), 0, 0, 0);
    }

    @Override
    public void accepted(long tick, double time, String client, Message message) {
        add(tick, time, null, client, message, null);
    }

    @Override
    public void sent(long tick, double time, Audience to, String client, Message message) {
        add(tick, time, to, client, message, null);
        if (to == Audience.CLIENT) {
            undelivered.add(lines.size() - 1);
        }
    }

    @Override
    public void missed(long tick, double time, String client, MissedTurn missed) {
        add(tick, time, null, client, null, missed);
    }

    private void add(long tick, double time, Audience to, String client, Message message, MissedTurn missed) {
        if (to != Audience.CLIENT) {
            undelivered.clear(); // a line to no one client: the ones before it were sent, or never will be
        }
        lines.add(new KeyedLine(next(message, missed), tick, time, to, client, message, missed, null, null));
    }

    /** The key of the next line said at the current place. */
    private LineKey next(Message message, MissedTurn missed) {
        LineKey at = place.apply(message, missed);
        return at.line(said.merge(at, 1, Integer::sum) - 1);
    }

    /**
     * {@code message} goes to {@code session}: what a part's session reports. It is the first line
     * said last to one client and not yet delivered; else a message the recording does not hold (the
     * game is over, and no longer recorded), delivered in its place all the same.
     */
    void delivered(SessionRef session, ServerMessage message) {
        Integer line = undelivered.poll();
        if (line != null) {
            lines.set(line, lines.get(line).deliveredTo(session, message));
        } else {
            caughtUp(session, message);
        }
    }

    /** A message for one client, in the current place, that is not recorded: it catches up with the game. */
    public void caughtUp(SessionRef session, ServerMessage message) {
        lines.add(KeyedLine.catchUp(next(message, null), session, message));
    }

    /** A client joins the audiences of broadcasts in the current place. */
    public void joined(SessionRef session) {
        lines.add(KeyedLine.joining(next(null, null), session));
    }

    /** Takes every line said so far. */
    public List<KeyedLine> take() {
        List<KeyedLine> taken = new ArrayList<>(lines);
        lines.clear();
        said.clear();
        undelivered.clear();
        return taken;
    }

    @Override
    public void close() {}

    private static String agentOf(Message message) {
        if (message instanceof PerceptionMessage m) {
            return m.agent();
        } else if (message instanceof LandmarkPerceptionMessage m) {
            return m.agent();
        } else if (message instanceof CastlePerceptionMessage m) {
            return m.agent();
        } else if (message instanceof AgentMessage m) {
            return m.agent();
        }
        throw new IllegalArgumentException("not about one agent: " + message);
    }

    private static String fruitOf(Message message) {
        if (message instanceof GraspResultMessage m) {
            return m.fruit();
        } else if (message instanceof FruitEatenMessage m) {
            return m.fruit();
        } else if (message instanceof FruitRemovedMessage m) {
            return m.fruit();
        }
        throw new IllegalArgumentException("not about one fruit: " + message);
    }
}
