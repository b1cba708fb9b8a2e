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
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
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
    private Function<Message, LineKey> place = message -> {
        throw new IllegalStateException("a line was said with no place given for it: " + message);
    };

    /** What is said from now on belongs to one cause, in the order said. */
    public void cause(LineKey key) {
        place = message -> key;
    }

    /** What is said from now on in {@code step} of {@code tick} is about an agent: ordered by its name. */
    public void byAgent(long tick, LineKey.Step step) {
        place = message -> new LineKey(tick, step, agentOf(message), 0, 0, 0);
    }

    /** What is said from now on is about a fruit, in the place {@code firstClaims} gives that fruit. */
    public void byFruit(Function<String, LineKey> firstClaims) {
        place = message -> firstClaims.apply(fruitOf(message));
    }

    @Override
    public void accepted(long tick, double time, String client, Message message) {
        add(tick, time, null, client, message, null);
    }

    @Override
    public void sent(long tick, double time, Audience to, String client, Message message) {
        add(tick, time, to, client, message, null);
    }

    @Override
    public void missed(long tick, double time, String client, MissedTurn missed) {
        add(tick, time, null, client, null, missed);
    }

    private void add(long tick, double time, Audience to, String client, Message message, MissedTurn missed) {
        LineKey at = place.apply(message);
        int number = said.merge(at, 1, Integer::sum) - 1;
        lines.add(new KeyedLine(at.line(number), tick, time, to, client, message, missed, null, null));
    }

    /** The last line said goes to {@code session} as {@code message}: what a part's session proxy reports. */
    void delivered(SessionRef session, ServerMessage message) {
        int last = lines.size() - 1;
        lines.set(last, lines.get(last).deliveredTo(session, message));
    }

    /** Takes every line said so far. */
    public List<KeyedLine> take() {
        List<KeyedLine> taken = new ArrayList<>(lines);
        lines.clear();
        said.clear();
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
