package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.AgentMovedMessage;
import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.PerceivedBridge;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.PerceivedRiver;
import io.orchard.protocol.value.RelativePosition;
import io.orchard.protocol.value.Vec3;
import java.util.List;
import tools.jackson.core.io.NumberOutput;

/**
 * Writes the lines that make most of the traffic (perceptions, action results, ticks, moves for
 * viewers) straight into an array of lines ({@link LineBytes}), byte for byte as
 * {@code MessageCodec} writes them. Perceptions carry numbers rounded to thousandths, which are
 * written as fixed-point digits instead of by the general shortest-decimal algorithm: that, and
 * skipping the mapper's reflection, cuts the cost of a perception several times. Any other number
 * or string goes the general way. Stateless.
 */
final class FastLines {

    private FastLines() {}

    /** Writes the message's line into a buffer, as {@link #write(ServerMessage, LineBytes)}. */
    static boolean write(ServerMessage message, ByteBuf out) {
        LineBytes line = new LineBytes(256);
        if (!write(message, line)) {
            return false;
        }
        line.writeTo(out);
        return true;
    }

    /** Writes the message's line, newline included, and says whether it could; if not, wrote nothing. */
    static boolean write(ServerMessage message, LineBytes out) {
        if (message instanceof PerceptionMessage m) {
            perception(m, out);
        } else if (message instanceof ActionResultMessage m) {
            actionResult(m, out);
        } else if (message instanceof LandmarkPerceptionMessage m) {
            landmarks(m, out);
        } else if (message instanceof CastlePerceptionMessage m) {
            head(out, "CastlePerception");
            integer(field(out, "tick"), m.tick());
            text(field(out, ",\"agent\""), m.agent());
            text(field(out, ",\"sector\""), m.sector().wireName());
            end(out);
        } else if (message instanceof AgentMovedMessage m) {
            head(out, "AgentMoved");
            integer(field(out, "tick"), m.tick());
            text(field(out, ",\"agent\""), m.agent());
            vec3(field(out, ",\"from\""), m.from());
            vec3(field(out, ",\"to\""), m.to());
            number(field(out, ",\"startTime\""), m.startTime());
            number(field(out, ",\"duration\""), m.duration());
            end(out);
        } else if (message instanceof TickMessage m) {
            head(out, "Tick");
            integer(field(out, "tick"), m.tick());
            number(field(out, ",\"time\""), m.time());
            end(out);
        } else {
            return false;
        }
        return true;
    }

    private static void perception(PerceptionMessage m, LineBytes out) {
        head(out, "Perception");
        integer(field(out, "tick"), m.tick());
        text(field(out, ",\"agent\""), m.agent());
        vec3(field(out, ",\"position\""), m.position());
        number(field(out, ",\"heading\""), m.heading());
        out.ascii(",\"objects\":[");
        List<PerceivedObject> objects = m.objects();
        for (int i = 0; i < objects.size(); i++) {
            PerceivedObject o = objects.get(i);
            out.ascii(i == 0 ? "{\"id\":" : ",{\"id\":");
            text(out, o.id());
            text(field(out, ",\"kind\""), o.kind().wireName());
            relative(field(out, ",\"at\""), o.at());
            number(field(out, ",\"radius\""), o.radius());
            number(field(out, ",\"height\""), o.height());
            out.put('}');
        }
        out.ascii("],\"agents\":[");
        List<PerceivedAgent> agents = m.agents();
        for (int i = 0; i < agents.size(); i++) {
            PerceivedAgent a = agents.get(i);
            out.ascii(i == 0 ? "{\"name\":" : ",{\"name\":");
            text(out, a.name());
            relative(field(out, ",\"at\""), a.at());
            number(field(out, ",\"heading\""), a.heading());
            number(field(out, ",\"radius\""), a.radius());
            out.put('}');
        }
        out.ascii("],\"fruit\":[");
        List<PerceivedFruit> fruit = m.fruit();
        for (int i = 0; i < fruit.size(); i++) {
            PerceivedFruit f = fruit.get(i);
            out.ascii(i == 0 ? "{\"id\":" : ",{\"id\":");
            text(out, f.id());
            text(field(out, ",\"kind\""), f.kind().wireName());
            vec3(field(out, ",\"position\""), f.position());
            number(field(out, ",\"radius\""), f.radius());
            if (f.support() != null) {
                text(field(out, ",\"support\""), f.support());
            }
            out.put('}');
        }
        out.put(']');
        end(out);
    }

    private static void landmarks(LandmarkPerceptionMessage m, LineBytes out) {
        head(out, "LandmarkPerception");
        integer(field(out, "tick"), m.tick());
        text(field(out, ",\"agent\""), m.agent());
        PerceivedRiver river = m.river();
        if (river != null) {
            relative(field(out, ",\"river\":{\"nearest\""), river.nearest());
            number(field(out, ",\"across\""), river.across());
            out.put('}');
        }
        out.ascii(",\"bridges\":[");
        List<PerceivedBridge> bridges = m.bridges();
        for (int i = 0; i < bridges.size(); i++) {
            PerceivedBridge b = bridges.get(i);
            out.ascii(i == 0 ? "{\"id\":" : ",{\"id\":");
            text(out, b.id());
            relative(field(out, ",\"entryA\""), b.entryA());
            relative(field(out, ",\"entryB\""), b.entryB());
            number(field(out, ",\"width\""), b.width());
            out.put('}');
        }
        out.put(']');
        end(out);
    }

    private static void actionResult(ActionResultMessage m, LineBytes out) {
        head(out, "ActionResult");
        integer(field(out, "seq"), m.seq());
        if (m.agent() != null) {
            text(field(out, ",\"agent\""), m.agent());
        }
        text(field(out, ",\"action\""), m.action());
        text(field(out, ",\"outcome\""), m.outcome().wireName());
        if (m.reason() != null) {
            text(field(out, ",\"reason\""), m.reason());
        }
        if (m.position() != null) {
            vec3(field(out, ",\"position\""), m.position());
        }
        number(field(out, ",\"duration\""), m.duration());
        end(out);
    }

    // ---- pieces ----------------------------------------------------------------------------------

    private static void head(LineBytes out, String type) {
        out.ascii("{\"type\":\"");
        out.ascii(type);
        out.ascii("\",");
    }

    private static void end(LineBytes out) {
        out.put('}');
        out.put('\n');
    }

    /** Writes a field's name and colon: {@code name} is either bare ("tick") or written out (",\"agent\""). */
    private static LineBytes field(LineBytes out, String name) {
        if (name.charAt(0) == ',') {
            out.ascii(name);
        } else {
            out.put('"');
            out.ascii(name);
            out.put('"');
        }
        out.put(':');
        return out;
    }

    static void integer(LineBytes out, long value) {
        out.integer(value);
    }

    private static void vec3(LineBytes out, Vec3 v) {
        out.ascii("{\"x\":");
        number(out, v.x());
        out.ascii(",\"y\":");
        number(out, v.y());
        out.ascii(",\"z\":");
        number(out, v.z());
        out.put('}');
    }

    private static void relative(LineBytes out, RelativePosition at) {
        out.ascii("{\"distance\":");
        number(out, at.distance());
        out.ascii(",\"bearing\":");
        number(out, at.bearing());
        out.put('}');
    }

    /**
     * A double as the codec writes it (the shortest decimal that reads back as the same double, with
     * a decimal point). A number with at most three decimals below ten million is written from its
     * digits; anything else by Jackson's own algorithm.
     */
    static void number(LineBytes out, double value) {
        double magnitude = Math.abs(value);
        if (magnitude >= 1e-3 && magnitude < 1e7) {
            long thousandths = Math.round(magnitude * 1000);
            if (thousandths / 1000.0 == magnitude) {
                if (value < 0) {
                    out.put('-');
                }
                out.digits(thousandths / 1000);
                out.put('.');
                int fraction = (int) (thousandths % 1000);
                if (fraction == 0) {
                    out.put('0');
                } else {
                    out.put((char) ('0' + fraction / 100));
                    if (fraction % 100 != 0) {
                        out.put((char) ('0' + fraction / 10 % 10));
                        if (fraction % 10 != 0) {
                            out.put((char) ('0' + fraction % 10));
                        }
                    }
                }
                return;
            }
        }
        out.ascii(NumberOutput.toString(value, true));
    }

    /** A JSON string: plain printable ASCII is copied, anything else is escaped by Jackson. */
    static void text(LineBytes out, String text) {
        out.text(text);
    }
}
