package io.orchard.viewer.replay;

import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * The lines of a stream of UTF-8 text, each decoded on its own: a malformed byte is blamed on its
 * line, with its place in it, and the next line reads on. (A {@code BufferedReader} stops the whole
 * read at the first one, saying only "Input length = 1".) Not thread-safe.
 */
final class Utf8Lines implements Closeable {

    private final InputStream in;
    private final CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder(); // reports malformed input
    private final byte[] buffer = new byte[64 * 1024];
    private int position;
    private int limit;
    private byte[] line = new byte[1024];
    private int number;

    Utf8Lines(InputStream in) {
        this.in = in;
    }

    /**
     * The next line without its terminator ({@code \n} or {@code \r\n}), or null at the end.
     *
     * @throws IllegalArgumentException when the line is not UTF-8, saying at which byte of it; the
     *                                  line is consumed, so the next call reads the one after it
     * @throws IOException              when reading fails
     */
    String next() throws IOException {
        int length = 0;
        boolean any = false;
        while (true) {
            if (position == limit) {
                limit = Math.max(0, in.read(buffer));
                position = 0;
                if (limit == 0) {
                    if (!any) {
                        return null;
                    }
                    break;
                }
            }
            any = true;
            int start = position;
            while (position < limit && buffer[position] != '\n') {
                position++;
            }
            int count = position - start;
            if (length + count > line.length) {
                line = Arrays.copyOf(line, Math.max(line.length * 2, length + count));
            }
            System.arraycopy(buffer, start, line, length, count);
            length += count;
            if (position < limit) {
                position++; // the newline
                break;
            }
        }
        number++;
        if (length > 0 && line[length - 1] == '\r') {
            length--;
        }
        return decode(length);
    }

    /** The number of the line {@link #next} returned or refused last, from 1. */
    int number() {
        return number;
    }

    private String decode(int length) {
        ByteBuffer bytes = ByteBuffer.wrap(line, 0, length);
        CharBuffer chars = CharBuffer.allocate(length); // UTF-8 never makes more chars than bytes
        decoder.reset();
        CoderResult result = decoder.decode(bytes, chars, true);
        if (!result.isError()) {
            result = decoder.flush(chars);
        }
        if (result.isError()) {
            throw new IllegalArgumentException("is not UTF-8 text (a malformed byte sequence at byte "
                    + (bytes.position() + 1) + " of " + length + ")");
        }
        return chars.flip().toString();
    }

    @Override
    public void close() throws IOException {
        in.close();
    }
}
