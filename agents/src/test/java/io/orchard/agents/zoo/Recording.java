package io.orchard.agents.zoo;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.AgentMovedMessage;
import io.orchard.protocol.message.FruitRemovedMessage;
import io.orchard.protocol.message.Message;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.Point2;
import io.orchard.server.world.World;
import io.orchard.server.world.scenario.Scenario;
import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * One agent's game as the server's recording ({@code --record}, newline-delimited JSON written by
 * the server's {@code FileRecorder}) tells it: the world from the snapshot a viewer was sent, the
 * agent's body from {@code AgentAdded}, then for every tick from its joining on where it stood at
 * the start of the tick (its {@code AgentMoved} walks, interpolated as viewers do), which way it
 * faced (its {@code Perception} of the tick) and whether it took a fruit during the tick before;
 * when each fruit left the world ({@code FruitRemoved}) and when the agent first perceived it;
 * and the moves the server refused the agent, with their reasons.
 *
 * @param world     the world's snapshot: bounds, obstacles, castle, river, bridges and all fruit
 * @param body      the agent's body in force
 * @param ticks     one per tick from the agent's joining to the end of the recording
 * @param removed   the simulated time of the tick at whose start each fruit taken was gone, by id
 * @param seen      the simulated time of the tick in which the agent first perceived each fruit it did, by id
 * @param refusals  the agent's moves the server rejected, in order
 */
public record Recording(WorldSnapshotMessage world, Body body, List<Tick> ticks, Map<String, Double> removed,
                 Map<String, Double> seen, List<Refusal> refusals) {

    /**
     * The start of a tick as the agent met it.
     *
     * @param tick    the tick
     * @param time    its simulated time
     * @param at      where the agent stood
     * @param heading which way it faced, NaN when it perceived nothing in the tick
     * @param grasped whether the agent took a fruit in the tick before
     */
    public record Tick(long tick, double time, Point2 at, double heading, boolean grasped) {}

    /** The recorded world as the server models it, to ask the server's own geometry about it. */
    World model() {
        return World.fromScenario(new Scenario(Scenario.FORMAT, world.bounds(), world.castle(), world.river(),
                world.bridges(), world.obstacles().stream().filter(o -> o.kind() == ObjectKind.TREE).toList(),
                world.obstacles().stream().filter(o -> o.kind() == ObjectKind.TABLE).toList(), world.fruit()));
    }

    /** Whether the fruit was still in the world at the start of the tick. */
    boolean left(String fruit, Tick tick) {
        return removed.getOrDefault(fruit, Double.POSITIVE_INFINITY) > tick.time();
    }

    /** Whether the agent had perceived the fruit by the tick. */
    boolean known(String fruit, Tick tick) {
        return seen.getOrDefault(fruit, Double.POSITIVE_INFINITY) <= tick.time();
    }

    /**
     * A move the server rejected.
     *
     * @param time   the simulated time of the tick it was answered in
     * @param reason the server's reason: "path enters the castle"
     */
    public record Refusal(double time, String reason) {}

    private static final String[] WANTED = {"WorldSnapshot", "AgentAdded", "AgentMoved", "FruitRemoved",
        "ActionResult", "Tick", "Perception"};

    /** Reads the recording for the agent called {@code agent}. */
    public static Recording read(Path file, String agent) throws IOException {
        MessageCodec codec = new MessageCodec();
        WorldSnapshotMessage world = null;
        Body body = null;
        Point2 from = null;
        Point2 to = null;
        double start = 0;
        double duration = 0;
        Map<String, Double> removed = new HashMap<>();
        Map<String, Double> seen = new HashMap<>();
        List<String> removing = new ArrayList<>();
        boolean grasped = false;
        List<Tick> ticks = new ArrayList<>();
        List<Refusal> refusals = new ArrayList<>();
        double time = 0;
        try (BufferedReader lines = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            for (String line = lines.readLine(); line != null; line = lines.readLine()) {
                String json = message(line);
                if (json == null) {
                    continue;
                }
                Message message = codec.decode(json);
                if (message instanceof WorldSnapshotMessage snapshot && world == null) {
                    world = snapshot;
                } else if (message instanceof AgentAddedMessage added && added.agent().name().equals(agent)) {
                    body = added.agent().body();
                    from = added.agent().position().onGround();
                    to = from;
                } else if (message instanceof AgentMovedMessage moved && moved.agent().equals(agent)) {
                    from = moved.from().onGround();
                    to = moved.to().onGround();
                    start = moved.startTime();
                    duration = moved.duration();
                } else if (message instanceof FruitRemovedMessage taken) {
                    removing.add(taken.fruit());
                    grasped |= taken.agent().equals(agent);
                } else if (message instanceof ActionResultMessage result && agent.equals(result.agent())
                        && "Move".equals(result.action()) && result.outcome() == Outcome.REJECTED) {
                    refusals.add(new Refusal(time, String.valueOf(result.reason())));
                } else if (message instanceof PerceptionMessage perceived && perceived.agent().equals(agent)
                        && !ticks.isEmpty()) {
                    Tick now = ticks.get(ticks.size() - 1);
                    if (now.tick() == perceived.tick()) {
                        ticks.set(ticks.size() - 1, new Tick(now.tick(), now.time(), now.at(), perceived.heading(),
                                now.grasped()));
                    }
                    for (PerceivedFruit fruit : perceived.fruit()) {
                        seen.putIfAbsent(fruit.id(), now.time());
                    }
                } else if (message instanceof TickMessage tick) {
                    time = tick.time();
                    for (String fruit : removing) {
                        removed.put(fruit, time);
                    }
                    removing.clear();
                    if (body != null) {
                        double f = duration <= 0 ? 1 : Math.max(0, Math.min(1, (time - start) / duration));
                        Point2 at = new Point2(from.x() + (to.x() - from.x()) * f, from.z() + (to.z() - from.z()) * f);
                        ticks.add(new Tick(tick.tick(), time, at, Double.NaN, grasped));
                        grasped = false;
                    }
                }
            }
        }
        if (world == null) {
            throw new IllegalStateException(file + " holds no WorldSnapshot: record with a viewer connected");
        }
        if (body == null) {
            throw new IllegalStateException(file + " holds no AgentAdded for " + agent);
        }
        return new Recording(world, body, List.copyOf(ticks), Map.copyOf(removed), Map.copyOf(seen),
                List.copyOf(refusals));
    }

    /** The message of a recorded line when it is of a type read here; null otherwise. */
    private static String message(String line) {
        int at = line.indexOf("\"msg\":");
        if (at < 0 || !line.endsWith("}")) {
            return null; // not a whole line: a recording cut off when the server stopped
        }
        String json = line.substring(at + 6, line.length() - 1);
        for (String type : WANTED) {
            if (json.startsWith("{\"type\":\"" + type + "\"")) {
                return json;
            }
        }
        return null;
    }
}
