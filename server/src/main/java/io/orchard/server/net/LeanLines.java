package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.Unpooled;
import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.value.LeanUnits;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.PerceivedBridge;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.PerceivedRiver;
import io.orchard.protocol.value.RelativePosition;
import io.orchard.protocol.value.Vec3;
import java.util.Arrays;
import java.util.List;

/**
 * Writes the three parts of a perception as one {@code LeanPerception} line straight into a
 * buffer, byte for byte as {@code MessageCodec} writes {@code LeanPerceptionMessage.of} them: every
 * number is a whole number of centimetres or milliradians, converted by {@link LeanUnits} as the
 * record does, so there is no decimal to format and no record to build. The line is built in an
 * array of the writing thread and handed to the buffer at once.
 */
final class LeanLines {

    private static final ThreadLocal<Line> LINE = ThreadLocal.withInitial(Line::new);

    private LeanLines() {}

    /** Writes the perception's lean line, newline included. */
    static void write(PerceptionMessage seen, LandmarkPerceptionMessage landmarks, CastlePerceptionMessage castle,
                      ByteBuf out) {
        Line line = LINE.get();
        line.size = 0;
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
        List<PerceivedObject> objects = seen.objects();
        for (int i = 0; i < objects.size(); i++) {
            PerceivedObject o = objects.get(i);
            line.ascii(i == 0 ? "[" : ",[");
            line.text(o.id());
            line.put(',');
            line.text(o.kind().wireName());
            line.put(',');
            relative(line, o.at());
            line.put(',');
            line.integer(LeanUnits.size(o.radius()));
            line.put(',');
            line.integer(LeanUnits.size(o.height()));
            line.put(']');
        }
        line.ascii("],\"agents\":[");
        List<PerceivedAgent> agents = seen.agents();
        for (int i = 0; i < agents.size(); i++) {
            PerceivedAgent a = agents.get(i);
            line.ascii(i == 0 ? "[" : ",[");
            line.text(a.name());
            line.put(',');
            relative(line, a.at());
            line.put(',');
            line.integer((int) LeanUnits.milliradians(a.heading()));
            line.put(',');
            line.integer(LeanUnits.size(a.radius()));
            line.put(']');
        }
        line.ascii("],\"fruit\":[");
        List<PerceivedFruit> fruit = seen.fruit();
        for (int i = 0; i < fruit.size(); i++) {
            PerceivedFruit f = fruit.get(i);
            line.ascii(i == 0 ? "[" : ",[");
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
        line.put(']');
        PerceivedRiver river = landmarks.river();
        if (river != null) {
            line.ascii(",\"river\":[");
            relative(line, river.nearest());
            line.put(',');
            line.integer((int) LeanUnits.milliradians(river.across()));
            line.put(']');
        }
        line.ascii(",\"bridges\":[");
        List<PerceivedBridge> bridges = landmarks.bridges();
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
        line.ascii(castle.sector().wireName());
        line.ascii("\"}\n");
        out.writeBytes(line.bytes, 0, line.size);
    }

    /** A distance and a bearing as two elements of a tuple. */
    private static void relative(Line line, RelativePosition at) {
        line.integer(LeanUnits.centimetres(at.distance()));
        line.put(',');
        line.integer((int) LeanUnits.milliradians(at.bearing()));
    }

    /**
     * A line being built in an array of the writing thread, handed to the buffer at once: a byte
     * at a time into a buffer costs a bounds check and an index update each, which made writing a
     * line cost more than its few bytes.
     */
    private static final class Line {
        byte[] bytes = new byte[4096];
        int size;

        private void room(int more) {
            if (size + more > bytes.length) {
                bytes = Arrays.copyOf(bytes, Math.max(2 * bytes.length, size + more));
            }
        }

        void put(char c) {
            room(1);
            bytes[size++] = (byte) c;
        }

        void ascii(String text) {
            int length = text.length();
            room(length);
            for (int i = 0; i < length; i++) {
                bytes[size++] = (byte) text.charAt(i);
            }
        }

        void integer(long value) {
            if (value == Long.MIN_VALUE) {
                ascii(Long.toString(value));
                return;
            }
            room(20);
            if (value < 0) {
                bytes[size++] = '-';
                value = -value;
            }
            int first = size;
            do {
                bytes[size++] = (byte) ('0' + value % 10);
                value /= 10;
            } while (value > 0);
            for (int i = first, j = size - 1; i < j; i++, j--) {
                byte swap = bytes[i];
                bytes[i] = bytes[j];
                bytes[j] = swap;
            }
        }

        /** A JSON string: plain printable ASCII is copied, anything else is escaped as the codec escapes it. */
        void text(String text) {
            int length = text.length();
            for (int i = 0; i < length; i++) {
                char c = text.charAt(i);
                if (c < 0x20 || c > 0x7e || c == '"' || c == '\\') {
                    ByteBuf escaped = Unpooled.buffer(length + 8);
                    FastLines.text(escaped, text);
                    int n = escaped.readableBytes();
                    room(n);
                    escaped.readBytes(bytes, size, n);
                    size += n;
                    return;
                }
            }
            put('"');
            ascii(text);
            put('"');
        }
    }
}
