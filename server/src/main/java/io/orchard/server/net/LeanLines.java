package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
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
import java.nio.charset.StandardCharsets;
import java.util.List;

/**
 * Writes the three parts of a perception as one {@code LeanPerception} line straight into a
 * buffer, byte for byte as {@code MessageCodec} writes {@code LeanPerceptionMessage.of} them: every
 * number is a whole number of centimetres or milliradians, converted by {@link LeanUnits} as the
 * record does, so there is no decimal to format and no record to build. Stateless.
 */
final class LeanLines {

    private LeanLines() {}

    /** Writes the perception's lean line, newline included. */
    static void write(PerceptionMessage seen, LandmarkPerceptionMessage landmarks, CastlePerceptionMessage castle,
                      ByteBuf out) {
        ascii(out, "{\"type\":\"LeanPerception\",\"tick\":");
        FastLines.integer(out, seen.tick());
        ascii(out, ",\"agent\":");
        FastLines.text(out, seen.agent());
        Vec3 p = seen.position();
        ascii(out, ",\"position\":[");
        FastLines.integer(out, LeanUnits.centimetres(p.x()));
        out.writeByte(',');
        FastLines.integer(out, LeanUnits.centimetres(p.y()));
        out.writeByte(',');
        FastLines.integer(out, LeanUnits.centimetres(p.z()));
        ascii(out, "],\"heading\":");
        FastLines.integer(out, LeanUnits.milliradians(seen.heading()));
        ascii(out, ",\"objects\":[");
        List<PerceivedObject> objects = seen.objects();
        for (int i = 0; i < objects.size(); i++) {
            PerceivedObject o = objects.get(i);
            ascii(out, i == 0 ? "[" : ",[");
            FastLines.text(out, o.id());
            out.writeByte(',');
            FastLines.text(out, o.kind().wireName());
            out.writeByte(',');
            relative(out, o.at());
            out.writeByte(',');
            FastLines.integer(out, LeanUnits.size(o.radius()));
            out.writeByte(',');
            FastLines.integer(out, LeanUnits.size(o.height()));
            out.writeByte(']');
        }
        ascii(out, "],\"agents\":[");
        List<PerceivedAgent> agents = seen.agents();
        for (int i = 0; i < agents.size(); i++) {
            PerceivedAgent a = agents.get(i);
            ascii(out, i == 0 ? "[" : ",[");
            FastLines.text(out, a.name());
            out.writeByte(',');
            relative(out, a.at());
            out.writeByte(',');
            FastLines.integer(out, (int) LeanUnits.milliradians(a.heading()));
            out.writeByte(',');
            FastLines.integer(out, LeanUnits.size(a.radius()));
            out.writeByte(']');
        }
        ascii(out, "],\"fruit\":[");
        List<PerceivedFruit> fruit = seen.fruit();
        for (int i = 0; i < fruit.size(); i++) {
            PerceivedFruit f = fruit.get(i);
            ascii(out, i == 0 ? "[" : ",[");
            FastLines.text(out, f.id());
            out.writeByte(',');
            FastLines.text(out, f.kind().wireName());
            out.writeByte(',');
            FastLines.integer(out, LeanUnits.centimetres(f.position().x()));
            out.writeByte(',');
            FastLines.integer(out, LeanUnits.centimetres(f.position().y()));
            out.writeByte(',');
            FastLines.integer(out, LeanUnits.centimetres(f.position().z()));
            out.writeByte(',');
            if (f.support() == null) {
                ascii(out, "null");
            } else {
                FastLines.text(out, f.support());
            }
            out.writeByte(']');
        }
        out.writeByte(']');
        PerceivedRiver river = landmarks.river();
        if (river != null) {
            ascii(out, ",\"river\":[");
            relative(out, river.nearest());
            out.writeByte(',');
            FastLines.integer(out, (int) LeanUnits.milliradians(river.across()));
            out.writeByte(']');
        }
        ascii(out, ",\"bridges\":[");
        List<PerceivedBridge> bridges = landmarks.bridges();
        for (int i = 0; i < bridges.size(); i++) {
            PerceivedBridge b = bridges.get(i);
            ascii(out, i == 0 ? "[" : ",[");
            FastLines.text(out, b.id());
            out.writeByte(',');
            relative(out, b.entryA());
            out.writeByte(',');
            relative(out, b.entryB());
            out.writeByte(',');
            FastLines.integer(out, LeanUnits.size(b.width()));
            out.writeByte(']');
        }
        ascii(out, "],\"castle\":\"");
        ascii(out, castle.sector().wireName());
        ascii(out, "\"}\n");
    }

    /** A distance and a bearing as two elements of a tuple. */
    private static void relative(ByteBuf out, RelativePosition at) {
        FastLines.integer(out, LeanUnits.centimetres(at.distance()));
        out.writeByte(',');
        FastLines.integer(out, (int) LeanUnits.milliradians(at.bearing()));
    }

    private static void ascii(ByteBuf out, String text) {
        out.writeCharSequence(text, StandardCharsets.US_ASCII);
    }
}
