package io.orchard.server.net;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/**
 * Lines a hostile or broken client might send: mostly messages of the protocol's types whose
 * fields are sometimes right, sometimes of the wrong JSON type, out of range, NaN, huge, missing,
 * duplicated or naming someone else's agent; sometimes cut short; sometimes raw bytes. Never a
 * newline inside a line: one line is one step of the test.
 */
final class FuzzedLines {

    private static final String[] TYPES = {"Hello", "Register", "RegisterJoint", "RegisterTimeSensor", "Unregister",
        "Move", "SetRotation", "SetJointRotation", "StartAnimation", "StopAnimation", "GraspRequest",
        "PerceptionRequest", "EndTurn", "Instruction", "Say", "GameControl", "Tick", "Welcome", "Teleport"};
    private static final String[] NAMES = {"Guppy", "Bunny", "Carrot", "Nobody", "guppy", "G", "no spaces", ""};
    private static final String[] FRUIT = {"F1", "F2", "F4", "F5", "F99", "T1", ""};

    private final FuzzSource source;

    FuzzedLines(FuzzSource source) {
        this.source = source;
    }

    /** One line, without its newline. */
    byte[] next() {
        if (source.pick(0, 19) == 0) {
            byte[] raw = source.bytes(200);
            for (int i = 0; i < raw.length; i++) {
                if (raw[i] == '\n') {
                    raw[i] = ' ';
                }
            }
            return raw;
        }
        String line = message(TYPES[source.pick(0, TYPES.length - 1)]);
        int cut = source.pick(0, 29);
        if (cut == 0 && !line.isEmpty()) {
            line = line.substring(0, source.pick(0, line.length() - 1));
        }
        return line.replace('\n', ' ').getBytes(StandardCharsets.UTF_8);
    }

    private String message(String type) {
        List<String> fields = new ArrayList<>();
        fields.add(field("type", source.pick(0, 40) == 0 ? value("text") : quote(type)));
        fields.add(field("seq", value("seq")));
        switch (type) {
            case "Hello" -> {
                fields.add(field("protocolVersion", value("int")));
                fields.add(field("role", source.pick(0, 3) == 0 ? value("text") : quote(source.pick(0, 1) == 0
                        ? "agent" : "viewer")));
                fields.add(field("client", value("text")));
            }
            case "Register" -> {
                fields.add(field("name", value("name")));
                fields.add(field("body", body()));
                if (source.pick(0, 3) == 0) {
                    fields.add(field("resumeToken", value("text")));
                }
            }
            case "RegisterJoint", "SetJointRotation" -> {
                fields.add(field("agent", value("name")));
                fields.add(field("joint", value("name")));
                if (type.equals("SetJointRotation")) {
                    fields.add(field("rotation", rotation()));
                }
            }
            case "RegisterTimeSensor", "StartAnimation", "StopAnimation" -> {
                fields.add(field("agent", value("name")));
                fields.add(field("timeSensor", value("name")));
                if (type.equals("StartAnimation")) {
                    fields.add(field("loop", value("bool")));
                }
            }
            case "Unregister" -> fields.add(field("agent", value("name")));
            case "Move" -> {
                fields.add(field("agent", value("name")));
                fields.add(field("from", vec3(true)));
                fields.add(field("to", vec3(false)));
            }
            case "SetRotation" -> {
                fields.add(field("agent", value("name")));
                fields.add(field("rotation", rotation()));
            }
            case "GraspRequest" -> {
                fields.add(field("agent", value("name")));
                fields.add(field("fruit", source.pick(0, 4) == 0 ? value("text") : quote(FRUIT[source.pick(0,
                        FRUIT.length - 1)])));
            }
            case "PerceptionRequest" -> {
                fields.add(field("agent", value("name")));
                fields.add(field("every", value("int")));
            }
            case "EndTurn", "Tick" -> {
                fields.add(field("tick", value("int")));
                fields.add(field("time", value("number")));
            }
            case "Instruction", "Say" -> {
                fields.add(field("agent", value("name")));
                fields.add(field("text", value("text")));
            }
            case "GameControl" -> fields.add(field("command", quote(new String[] {"start", "pause", "resume", "explode"}
                    [source.pick(0, 3)])));
            default -> fields.add(field("x", value("any")));
        }
        int drop = source.pick(0, 40);
        if (drop < fields.size() && drop > 0) {
            fields.remove(drop);
        }
        if (source.pick(0, 29) == 0) {
            fields.add(fields.get(source.pick(0, fields.size() - 1)));
        }
        return "{" + String.join(",", fields) + "}";
    }

    private String body() {
        if (source.pick(0, 10) == 0) {
            return value("any");
        }
        return "{" + field("radius", number(0.5)) + "," + field("height", number(1.2)) + "," + field("maxSpeed",
                number(10)) + "," + field("gripper", "{" + field("part", value("name")) + "," + field("reach",
                number(0.6)) + "," + field("minHeight", number(0)) + "," + field("maxHeight", number(1.5)) + "}") + ","
                + field("sight", "{" + field("range", number(40)) + "," + field("fieldOfView", number(3.14)) + "}")
                + "}";
    }

    private String rotation() {
        return "{" + field("axis", "{\"x\":" + number(0) + ",\"y\":" + number(1) + ",\"z\":" + number(0) + "}") + ","
                + field("angle", number(1)) + "}";
    }

    /** A point: usually near where an agent could be, so that some moves are accepted. */
    private String vec3(boolean from) {
        if (source.pick(0, 10) == 0) {
            return value("any");
        }
        double usual = from ? 0 : source.pick(-12, 12) / 2.0;
        return "{\"x\":" + number(usual) + ",\"y\":" + number(0) + ",\"z\":" + number(from ? 0
                : source.pick(-12, 12) / 2.0) + "}";
    }

    /** Usually the given number, sometimes any double (written as Java writes it: NaN, Infinity, 1.0E308). */
    private String number(double usual) {
        int choice = source.pick(0, 39);
        if (choice > 1) {
            return Double.toString(usual);
        }
        return choice == 0 ? value("any") : Double.toString(source.anyDouble());
    }

    private String value(String kind) {
        int wrong = source.pick(0, 29);
        if (wrong == 0) {
            return new String[] {"null", "true", "[]", "{}", "\"7\"", "-0", "1e999", "123456789012345678901234567890",
                "[1,2", "{\"a\":"}[source.pick(0, 9)];
        }
        return switch (kind) {
            case "seq" -> Long.toString(wrong == 1 ? source.anyLong() : source.pick(1, 50));
            case "int" -> Long.toString(wrong == 1 ? source.anyLong() : source.pick(-2, 3));
            case "number" -> Double.toString(source.anyDouble());
            case "bool" -> source.pick(0, 1) == 0 ? "true" : "false";
            case "name" -> quote(wrong == 1 ? source.text(40) : NAMES[Math.max(0, source.pick(-12, NAMES.length - 1))]);
            case "text" -> quote(source.text(wrong == 1 ? 1200 : 30));
            default -> value(new String[] {"seq", "number", "bool", "name", "text"}[source.pick(0, 4)]);
        };
    }

    private static String field(String name, String value) {
        return quote(name) + ":" + value;
    }

    /** A JSON string literal; escapes quotes, backslashes and control characters. */
    static String quote(String text) {
        StringBuilder out = new StringBuilder(text.length() + 2).append('"');
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '"' || c == '\\') {
                out.append('\\').append(c);
            } else if (c < 0x20) {
                out.append(String.format("\\u%04x", (int) c));
            } else {
                out.append(c);
            }
        }
        return out.append('"').toString();
    }
}
