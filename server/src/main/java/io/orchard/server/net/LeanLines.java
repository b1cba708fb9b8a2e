package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import io.orchard.protocol.value.LeanUnits;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.PerceivedBridge;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedRiver;
import io.orchard.protocol.value.RelativePosition;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.Perceivables;
import io.orchard.server.sim.Percept;
import java.util.List;

/**
 * Writes a perception as one {@code LeanPerception} line straight into a buffer, byte for byte as
 * {@code MessageCodec} writes {@code LeanPerceptionMessage.of} its three messages: every number is
 * a whole number of centimetres or milliradians, converted by {@link LeanUnits} as the record does,
 * so there is no decimal to format and no record to build. What never changes about a tree, table
 * or fruit (its id, kind and size; a fruit's place) is encoded once per world ({@link Tuples}) and
 * copied, so a thing seen costs a copy and two numbers. The line is built in an array
 * ({@link LineBytes}).
 */
final class LeanLines {

    private LeanLines() {}

    /** Writes the perception's lean line into a buffer, as {@link #write(Percept, LineBytes)}. */
    static void write(Percept seen, ByteBuf out) {
        LineBytes line = new LineBytes(4096);
        write(seen, line);
        line.writeTo(out);
    }

    /** Writes the perception's lean line, newline included. */
    static void write(Percept seen, LineBytes line) {
        Tuples tuples = seen.things().derived(Tuples.class, Tuples::new);
        line.ascii("{\"type\":\"LeanPerception\",\"tick\":");
        line.integer(seen.tick());
        line.ascii(",\"agent\":");
        line.text(seen.agent());
        Vec3 p = seen.position();
        line.ascii(",\"position\":[");
        line.integer(LeanUnits.centimetres(p.x()));
        line.put(',');
        line.integer(LeanUnits.centimetres(p.y()));
        line.put(',');
        line.integer(LeanUnits.centimetres(p.z()));
        line.ascii("],\"heading\":");
        line.integer(LeanUnits.milliradians(seen.heading()));
        line.ascii(",\"objects\":[");
        for (int k = 0; k < seen.objectCount(); k++) {
            if (k > 0) {
                line.put(',');
            }
            int index = seen.objectIndex(k);
            line.bytes(tuples.objects, tuples.objectStart[index], tuples.objectSplit[index]);
            relative(line, seen.objectDistance(k), seen.objectBearing(k));
            line.bytes(tuples.objects, tuples.objectSplit[index], tuples.objectStart[index + 1]);
        }
        line.ascii("],\"agents\":[");
        for (int k = 0; k < seen.agentCount(); k++) {
            line.ascii(k == 0 ? "[" : ",[");
            line.text(seen.agentName(k));
            line.put(',');
            relative(line, seen.agentDistance(k), seen.agentBearing(k));
            line.put(',');
            line.integer((int) LeanUnits.milliradians(seen.agentHeading(k)));
            line.put(',');
            line.integer(LeanUnits.size(seen.agentRadius(k)));
            line.put(']');
        }
        line.ascii("],\"fruit\":[");
        for (int k = 0; k < seen.fruitCount(); k++) {
            if (k > 0) {
                line.put(',');
            }
            int index = seen.fruitIndex(k);
            line.bytes(tuples.fruit, tuples.fruitStart[index], tuples.fruitStart[index + 1]);
        }
        line.put(']');
        PerceivedRiver river = seen.river();
        if (river != null) {
            line.ascii(",\"river\":[");
            relative(line, river.nearest());
            line.put(',');
            line.integer((int) LeanUnits.milliradians(river.across()));
            line.put(']');
        }
        line.ascii(",\"bridges\":[");
        List<PerceivedBridge> bridges = seen.bridges();
        for (int i = 0; i < bridges.size(); i++) {
            PerceivedBridge b = bridges.get(i);
            line.ascii(i == 0 ? "[" : ",[");
            line.text(b.id());
            line.put(',');
            relative(line, b.entryA());
            line.put(',');
            relative(line, b.entryB());
            line.put(',');
            line.integer(LeanUnits.size(b.width()));
            line.put(']');
        }
        line.ascii("],\"castle\":\"");
        line.ascii(seen.castle().wireName());
        line.ascii("\"}\n");
    }

    /** A distance and a bearing as two elements of a tuple. */
    private static void relative(LineBytes line, RelativePosition at) {
        relative(line, at.distance(), at.bearing());
    }

    private static void relative(LineBytes line, double distance, double bearing) {
        line.integer(LeanUnits.centimetres(distance));
        line.put(',');
        line.integer((int) LeanUnits.milliradians(bearing));
    }

    /**
     * The lean tuples of a world's trees, tables and fruit, encoded once: for a tree or table the
     * bytes before its distance and bearing ({@code ["T17","tree",}) and after them
     * ({@code ,150,600]}), for a fruit its whole tuple. All in one array each, so that the things of
     * one view lie close together in memory rather than behind a record and a string each.
     */
    static final class Tuples {
        final byte[] objects;
        /** Where obstacle i's bytes start (and, at i + 1, end). */
        final int[] objectStart;
        /** Where obstacle i's bytes after its distance and bearing start. */
        final int[] objectSplit;
        final byte[] fruit;
        /** Where fruit i's tuple starts (and, at i + 1, ends). */
        final int[] fruitStart;

        Tuples(Perceivables things) {
            LineBytes line = new LineBytes(1 << 16);
            objectStart = new int[things.obstacles() + 1];
            objectSplit = new int[things.obstacles()];
            for (int i = 0; i < things.obstacles(); i++) {
                Obstacle o = things.obstacle(i);
                objectStart[i] = line.size();
                line.put('[');
                line.text(o.id());
                line.put(',');
                line.text(o.kind().wireName());
                line.put(',');
                objectSplit[i] = line.size();
                line.put(',');
                line.integer(LeanUnits.size(o.radius()));
                line.put(',');
                line.integer(LeanUnits.size(o.height()));
                line.put(']');
            }
            objectStart[things.obstacles()] = line.size();
            objects = line.toArray();
            line.clear();
            fruitStart = new int[things.fruit() + 1];
            for (int i = 0; i < things.fruit(); i++) {
                PerceivedFruit f = things.fruit(i);
                fruitStart[i] = line.size();
                line.put('[');
                line.text(f.id());
                line.put(',');
                line.text(f.kind().wireName());
                line.put(',');
                line.integer(LeanUnits.centimetres(f.position().x()));
                line.put(',');
                line.integer(LeanUnits.centimetres(f.position().y()));
                line.put(',');
                line.integer(LeanUnits.centimetres(f.position().z()));
                line.put(',');
                if (f.support() == null) {
                    line.ascii("null");
                } else {
                    line.text(f.support());
                }
                line.put(']');
            }
            fruitStart[things.fruit()] = line.size();
            fruit = line.toArray();
        }
    }
}
