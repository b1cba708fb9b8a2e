package io.orchard.server.net;

import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.value.Vec3;
import java.nio.charset.StandardCharsets;

/**
 * Reads the two lines that make most of what clients send, {@code Move} and
 * {@code PerceptionRequest}, without the JSON mapper, when they come in the one plain form that
 * clients write: fields in the order of the record, no spaces, no escapes, plain JSON numbers. Any
 * other line, and any line whose values the message refuses, is left to the codec ({@code null}),
 * which reads or refuses it as it always has: what is read here equals what the codec reads from
 * the same line ({@code FastMovesTest}). The mapper's generic reading was a sixth of an I/O
 * thread's work under load. Stateless.
 */
final class FastMoves {

    private static final byte[] MOVE = ascii("{\"type\":\"Move\",\"seq\":");
    private static final byte[] REQUEST = ascii("{\"type\":\"PerceptionRequest\",\"seq\":");
    private static final byte[] AGENT = ascii(",\"agent\":\"");
    private static final byte[] FROM = ascii(",\"from\":");
    private static final byte[] TO = ascii(",\"to\":");
    private static final byte[] EVERY = ascii(",\"every\":");
    private static final byte[] X = ascii("{\"x\":");
    private static final byte[] Y = ascii(",\"y\":");
    private static final byte[] Z = ascii(",\"z\":");
    /** Longer numbers are rare and left to the codec, which knows their limits. */
    private static final int MAX_NUMBER = 40;

    private FastMoves() {}

    /** The message on {@code line} (its newline, if any, excluded by {@code length}), or null for the codec to read. */
    static ClientMessage read(byte[] line, int length) {
        Cursor at = new Cursor(line, length);
        try {
            if (at.skip(MOVE)) {
                return move(at);
            }
            if (at.skip(REQUEST)) {
                return request(at);
            }
        } catch (IllegalArgumentException | NullPointerException e) {
            // A value the message refuses: the codec refuses it with the error the protocol promises.
        }
        return null;
    }

    private static ClientMessage move(Cursor at) {
        long seq = at.seq();
        String agent = at.skip(AGENT) ? at.plainText() : null;
        if (agent == null) {
            return null;
        }
        Vec3 from = null;
        if (at.skip(FROM)) {
            from = at.point();
            if (from == null) {
                return null;
            }
        }
        if (seq < 0 || !at.skip(TO)) {
            return null;
        }
        Vec3 to = at.point();
        if (to == null || !at.end()) {
            return null;
        }
        return new MoveMessage(seq, agent, from, to);
    }

    private static ClientMessage request(Cursor at) {
        long seq = at.seq();
        String agent = at.skip(AGENT) ? at.plainText() : null;
        if (seq < 0 || agent == null || !at.skip(EVERY)) {
            return null;
        }
        long every = at.whole(10);
        if (every < 0 || every > Integer.MAX_VALUE || !at.end()) {
            return null;
        }
        return new PerceptionRequestMessage(seq, agent, (int) every);
    }

    /** A position in the line being read. */
    private static final class Cursor {
        private final byte[] line;
        private final int length;
        private int at;

        Cursor(byte[] line, int length) {
            this.line = line;
            this.length = length;
        }

        /** Steps over {@code expected} if the line goes on with it. */
        boolean skip(byte[] expected) {
            if (length - at < expected.length) {
                return false;
            }
            for (int i = 0; i < expected.length; i++) {
                if (line[at + i] != expected[i]) {
                    return false;
                }
            }
            at += expected.length;
            return true;
        }

        /** Whether the object closes and the line ends there. */
        boolean end() {
            return at == length - 1 && line[at] == '}';
        }

        long seq() {
            return whole(18);
        }

        /** A whole number of at most {@code digits} digits without sign or leading zero; -1 if there is none. */
        long whole(int digits) {
            int start = at;
            long value = 0;
            while (at < length && line[at] >= '0' && line[at] <= '9' && at - start < digits) {
                value = value * 10 + (line[at++] - '0');
            }
            int count = at - start;
            if (count == 0 || count > 1 && line[start] == '0' || at < length && line[at] >= '0' && line[at] <= '9') {
                return -1;
            }
            return value;
        }

        /** A string of printable ASCII with nothing to unescape, the opening quote already read; null otherwise. */
        String plainText() {
            int start = at;
            while (at < length && line[at] != '"') {
                byte b = line[at];
                if (b < 0x20 || b > 0x7e || b == '\\') {
                    return null;
                }
                at++;
            }
            if (at == length) {
                return null;
            }
            String text = new String(line, start, at - start, StandardCharsets.ISO_8859_1);
            at++;
            return text;
        }

        /** {@code {"x":…,"y":…,"z":…}}; null otherwise. */
        Vec3 point() {
            if (!skip(X)) {
                return null;
            }
            double x = number();
            if (Double.isNaN(x) || !skip(Y)) {
                return null;
            }
            double y = number();
            if (Double.isNaN(y) || !skip(Z)) {
                return null;
            }
            double z = number();
            if (Double.isNaN(z) || at >= length || line[at] != '}') {
                return null;
            }
            at++;
            return new Vec3(x, y, z);
        }

        /** A JSON number, finite; NaN when there is none or it is not finite. */
        double number() {
            int start = at;
            if (at < length && line[at] == '-') {
                at++;
            }
            int digits = at;
            while (at < length && line[at] >= '0' && line[at] <= '9') {
                at++;
            }
            if (at == digits || at - digits > 1 && line[digits] == '0') {
                return Double.NaN;
            }
            boolean whole = true;
            if (at < length && line[at] == '.') {
                whole = false;
                int fraction = ++at;
                while (at < length && line[at] >= '0' && line[at] <= '9') {
                    at++;
                }
                if (at == fraction) {
                    return Double.NaN;
                }
            }
            if (at < length && (line[at] == 'e' || line[at] == 'E')) {
                whole = false;
                at++;
                if (at < length && (line[at] == '+' || line[at] == '-')) {
                    at++;
                }
                int exponent = at;
                while (at < length && line[at] >= '0' && line[at] <= '9') {
                    at++;
                }
                if (at == exponent) {
                    return Double.NaN;
                }
            }
            if (at - start > MAX_NUMBER) {
                return Double.NaN;
            }
            if (whole) {
                // The mapper reads a whole number as one and converts it: -0 is 0, not -0.0.
                if (at - digits > 18) {
                    return Double.NaN;
                }
                long value = 0;
                for (int i = digits; i < at; i++) {
                    value = value * 10 + (line[i] - '0');
                }
                return digits > start ? -value : value;
            }
            double value = Double.parseDouble(new String(line, 0, start, at - start));
            return Double.isFinite(value) ? value : Double.NaN;
        }
    }

    private static byte[] ascii(String text) {
        byte[] bytes = new byte[text.length()];
        for (int i = 0; i < bytes.length; i++) {
            bytes[i] = (byte) text.charAt(i);
        }
        return bytes;
    }
}
