package io.orchard.protocol;

import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.Message;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.ModelArchive;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import java.nio.charset.StandardCharsets;
import java.util.List;
import tools.jackson.core.JacksonException;
import tools.jackson.core.JsonParser;
import tools.jackson.core.JsonToken;
import tools.jackson.databind.DeserializationFeature;
import tools.jackson.databind.ObjectReader;
import tools.jackson.databind.ObjectWriter;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.jsontype.NamedType;

/**
 * Turns messages into lines and lines into messages: the one place that knows the wire format.
 *
 * <p>A line is one JSON object in UTF-8 with a {@code type} field, at most {@link #MAX_LINE_BYTES}
 * long, or {@link #MAX_LARGE_LINE_BYTES} for the messages that carry a model or a world snapshot.
 * Decoding ignores fields it does not know (so newer peers can add fields) and refuses unknown
 * types, missing required fields, values of the wrong JSON type, fractions where integers belong,
 * duplicate keys, non-finite numbers and bytes that are not strict UTF-8 (overlong forms,
 * surrogates, code points beyond U+10FFFF: the error names the byte's offset in the line). Every
 * refusal is a {@link ProtocolException} whose message names the message type, the field and the
 * bad value; decoding throws nothing else.
 *
 * <p>Instances are immutable and safe to share between threads.
 */
public final class MessageCodec {

    /** The longest ordinary line in bytes, not counting the newline: 64 KiB. */
    public static final int MAX_LINE_BYTES = 64 * 1024;

    /** The longest line of a message that carries a model or a snapshot: 8 MiB. */
    public static final int MAX_LARGE_LINE_BYTES = 8 * 1024 * 1024;

    private final ObjectReader reader;
    private final ObjectWriter writer;

    /**
     * A codec with Orchard's rules for reading lines: unknown fields are ignored, a required field that is missing
     * or null, a fraction where an integer belongs and anything after the object are refused.
     */
    public MessageCodec() {
        // Fields a newer peer adds are ignored; everything else is read as strictly as any file.
        JsonMapper.Builder builder = StrictJson.builder()
                .disable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES);
        MessageTypes.all().forEach((name, type) -> builder.registerSubtypes(new NamedType(type, name)));
        JsonMapper mapper = builder.build();
        this.reader = mapper.readerFor(Message.class);
        this.writer = mapper.writerFor(Message.class);
    }

    /** The message as one line of JSON, without the newline. */
    public String encode(Message message) {
        try {
            return writer.writeValueAsString(message);
        } catch (JacksonException e) {
            throw new IllegalStateException("cannot encode " + message, e);
        }
    }

    /** The message as one line of UTF-8 JSON, ending with a newline: what goes on the socket. */
    public byte[] encodeLine(Message message) {
        byte[] json;
        try {
            // Straight to UTF-8 bytes: no String in between.
            json = writer.writeValueAsBytes(message);
        } catch (JacksonException e) {
            throw new IllegalStateException("cannot encode " + message, e);
        }
        byte[] line = java.util.Arrays.copyOf(json, json.length + 1);
        line[json.length] = '\n';
        return line;
    }

    /**
     * Decodes one line (with or without its newline).
     *
     * @throws ProtocolException when the line is not a valid message
     */
    public Message decode(String line) {
        return decode(line.getBytes(StandardCharsets.UTF_8));
    }

    /**
     * Decodes one line of UTF-8 bytes (with or without its newline).
     *
     * @throws ProtocolException when the line is not a valid message
     */
    public Message decode(byte[] utf8) {
        int length = utf8.length;
        while (length > 0 && (utf8[length - 1] == '\n' || utf8[length - 1] == '\r')) {
            length--;
        }
        try {
            return read(utf8, length);
        } catch (ProtocolException e) {
            throw new ProtocolException(e.code(), e.getMessage(), seqOf(utf8, length));
        }
    }

    private Message read(byte[] utf8, int length) {
        if (length > MAX_LARGE_LINE_BYTES) {
            throw new ProtocolException(ErrorCode.LINE_TOO_LONG,
                    "line of " + length + " bytes is longer than the limit of " + MAX_LARGE_LINE_BYTES);
        }
        int first = 0;
        while (first < length && (utf8[first] == ' ' || utf8[first] == '\t')) {
            first++;
        }
        if (first == length) {
            throw new ProtocolException(ErrorCode.MALFORMED_JSON, "empty line: a line must hold one JSON object");
        }
        if (utf8[first] != '{') {
            // Jackson would read an array as [type, object]; the protocol has only objects.
            throw new ProtocolException(ErrorCode.MALFORMED_JSON, "a line must hold one JSON object, it starts with "
                    + start(utf8, first, length));
        }
        if (length > MAX_LINE_BYTES) {
            Class<? extends Message> type = MessageTypes.all().get(peekType(utf8, length));
            if (type == null || length > MessageTypes.maxLineBytes(type)) {
                throw new ProtocolException(ErrorCode.LINE_TOO_LONG, (type == null ? "line" : MessageTypes.nameOf(type)
                        + " line") + " of " + length + " bytes is longer than the limit of " + MAX_LINE_BYTES);
            }
        }
        String encoding = Utf8.problem(utf8, length);
        if (encoding != null) {
            throw new ProtocolException(ErrorCode.MALFORMED_JSON, encoding);
        }
        // The parser stays open until the error is told: it still stands on the value that was refused.
        JsonParser parser = reader.createParser(utf8, 0, length);
        try {
            Message message = reader.readValue(parser);
            if (parser.nextToken() != null) {
                throw new ProtocolException(ErrorCode.MALFORMED_JSON,
                        "malformed JSON: more than one JSON value on the line");
            }
            return message;
        } catch (JacksonException e) {
            throw DecodeErrors.translate(e);
        } catch (ProtocolException e) {
            throw e;
        } catch (RuntimeException e) {
            throw new ProtocolException(ErrorCode.INVALID_VALUE, "cannot decode the line: " + e.getMessage());
        } finally {
            parser.close();
        }
    }

    /** How a line that is not an object begins, for the error: a byte-order mark, a character or a byte. */
    private static String start(byte[] utf8, int first, int length) {
        if (length - first >= 3 && (utf8[first] & 0xff) == 0xEF && (utf8[first + 1] & 0xff) == 0xBB
                && (utf8[first + 2] & 0xff) == 0xBF) {
            return "a byte-order mark (bytes EF BB BF), which a line must not have";
        }
        int b = utf8[first] & 0xff;
        return b > 0x20 && b < 0x7f ? "'" + (char) b + "'" : String.format(java.util.Locale.ROOT, "the byte %02X", b);
    }

    /**
     * Decodes a line sent by a client, as the server does: a message of the server's direction is
     * refused, and so is a {@code Register} whose model is a bundled one that does not exist (one
     * not in {@link ModelSpec#BUNDLED_NAMES}) or a zip that {@link ModelArchive} refuses.
     *
     * @throws ProtocolException when the line is not a valid client message
     */
    public ClientMessage decodeClient(String line) {
        return decodeClient(line.getBytes(StandardCharsets.UTF_8));
    }

    /** Decodes a line of UTF-8 sent by a client; see {@link #decodeClient(String)}. */
    public ClientMessage decodeClient(byte[] utf8) {
        Message message = decode(utf8);
        if (!(message instanceof ClientMessage client)) {
            throw new ProtocolException(ErrorCode.WRONG_DIRECTION, "type '" + MessageTypes.nameOf(message.getClass())
                    + "' is sent by the server, not by clients", seqOf(utf8, utf8.length));
        }
        if (client instanceof RegisterMessage register && register.model() != null
                && register.model().format() == ModelFormat.BUNDLED
                && !ModelSpec.BUNDLED_NAMES.contains(register.model().bundled())) {
            // Checked here, not in ModelSpec: a viewer reading a newer server's AgentAdded shows a placeholder instead.
            throw new ProtocolException(ErrorCode.INVALID_VALUE, "model.bundled must be one of "
                    + quoted(ModelSpec.BUNDLED_NAMES) + ", was '" + register.model().bundled() + "'", register.seq());
        }
        if (client instanceof RegisterMessage register && register.model() != null
                && register.model().format() == ModelFormat.ZIP) {
            // Checked once, here, so that every viewer is sent only archives it can unpack safely.
            try {
                ModelArchive.read(register.model().bytes());
            } catch (IllegalArgumentException e) {
                throw new ProtocolException(ErrorCode.INVALID_VALUE, "model.data: " + e.getMessage(), register.seq());
            }
        }
        return client;
    }

    private static String quoted(List<String> names) {
        return String.join(", ", names.stream().map(name -> "'" + name + "'").toList());
    }

    /**
     * Decodes a line sent by the server, as clients do.
     *
     * @throws ProtocolException when the line is not a valid server message
     */
    public ServerMessage decodeServer(String line) {
        return decodeServer(line.getBytes(StandardCharsets.UTF_8));
    }

    /** Decodes a line of UTF-8 sent by the server; see {@link #decodeServer(String)}. */
    public ServerMessage decodeServer(byte[] utf8) {
        Message message = decode(utf8);
        if (message instanceof ServerMessage server) {
            return server;
        }
        throw new ProtocolException(ErrorCode.WRONG_DIRECTION,
                "type '" + MessageTypes.nameOf(message.getClass()) + "' is sent by clients, not by the server");
    }

    /**
     * The top-level {@code "seq"} of a line that failed, for its error to echo: an integer from 0 to
     * 2<sup>63</sup>&minus;1 found before the line stops being JSON (the reader passes over a
     * byte-order mark); 0 when there is none.
     */
    private long seqOf(byte[] utf8, int length) {
        try (JsonParser parser = reader.createParser(utf8, 0, length)) {
            if (parser.nextToken() != JsonToken.START_OBJECT) {
                return 0;
            }
            while (parser.nextToken() == JsonToken.PROPERTY_NAME) {
                String name = parser.currentName();
                JsonToken value = parser.nextToken();
                if (name.equals("seq")) {
                    return value == JsonToken.VALUE_NUMBER_INT && parser.getNumberType() != JsonParser.NumberType.BIG_INTEGER
                            && parser.getLongValue() >= 0 ? parser.getLongValue() : 0;
                }
                parser.skipChildren();
            }
            return 0;
        } catch (JacksonException e) {
            return 0;
        }
    }

    /** The top-level "type" of a long line, read without building the message; null if there is none. */
    private String peekType(byte[] utf8, int length) {
        try (JsonParser parser = reader.createParser(utf8, 0, length)) {
            if (parser.nextToken() != JsonToken.START_OBJECT) {
                return null;
            }
            while (parser.nextToken() == JsonToken.PROPERTY_NAME) {
                String name = parser.currentName();
                JsonToken value = parser.nextToken();
                if (name.equals("type") && value == JsonToken.VALUE_STRING) {
                    return parser.getString();
                }
                parser.skipChildren();
            }
            return null;
        } catch (JacksonException e) {
            return null;
        }
    }
}
