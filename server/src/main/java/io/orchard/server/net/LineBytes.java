package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import java.util.Arrays;
import tools.jackson.databind.json.JsonMapper;

/**
 * Lines being written in an array, handed to a buffer at once: a byte at a time into a Netty
 * buffer costs a bounds check and an index update each, through the buffer's wrappers, which made
 * writing a line cost more than its few bytes. One per writing thread ({@link TickLines}); not
 * thread-safe.
 */
final class LineBytes {

    /** Escapes strings as the codec does, for the few that are not plain printable ASCII. */
    private static final JsonMapper STRINGS = JsonMapper.builder().build();

    private byte[] bytes;
    private int size;

    LineBytes(int capacity) {
        this.bytes = new byte[capacity];
    }

    /** Forgets what was written. */
    void clear() {
        size = 0;
    }

    /** Lets go of the array when it grew beyond {@code max} bytes, keeping one of a sixteenth of that. */
    void shrink(int max) {
        if (bytes.length > max) {
            bytes = new byte[max / 16];
        }
    }

    /** The number of bytes written. */
    int size() {
        return size;
    }

    /** Hands what was written to {@code out}. */
    void writeTo(ByteBuf out) {
        out.writeBytes(bytes, 0, size);
    }

    /** What was written, as an array of its own. */
    byte[] toArray() {
        return Arrays.copyOf(bytes, size);
    }

    private void room(int more) {
        if (size + more > bytes.length) {
            bytes = Arrays.copyOf(bytes, Math.max(2 * bytes.length, size + more));
        }
    }

    void put(char c) {
        room(1);
        bytes[size++] = (byte) c;
    }

    /** Text known to be ASCII, unquoted. */
    void ascii(String text) {
        int length = text.length();
        room(length);
        for (int i = 0; i < length; i++) {
            bytes[size++] = (byte) text.charAt(i);
        }
    }

    /** Copies {@code from[start]} up to {@code from[end]}. */
    void bytes(byte[] from, int start, int end) {
        int length = end - start;
        room(length);
        System.arraycopy(from, start, bytes, size, length);
        size += length;
    }

    void bytes(byte[] from) {
        bytes(from, 0, from.length);
    }

    /** A whole number in decimal digits. */
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
        digits(value);
    }

    /** The digits of a number not below zero. */
    void digits(long value) {
        room(19);
        int count = 1;
        for (long rest = value / 10; rest > 0; rest /= 10) {
            count++;
        }
        int at = size + count;
        size = at;
        do {
            bytes[--at] = (byte) ('0' + value % 10);
            value /= 10;
        } while (value > 0);
    }

    /** A JSON string: plain printable ASCII is copied, anything else is escaped as the codec escapes it. */
    void text(String text) {
        int length = text.length();
        for (int i = 0; i < length; i++) {
            char c = text.charAt(i);
            if (c < 0x20 || c > 0x7e || c == '"' || c == '\\') {
                bytes(STRINGS.writeValueAsBytes(text));
                return;
            }
        }
        put('"');
        ascii(text);
        put('"');
    }
}
