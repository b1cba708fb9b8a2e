package io.orchard.protocol;

import com.fasterxml.jackson.annotation.JsonFormat;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.Message;
import io.orchard.protocol.message.ServerMessage;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import tools.jackson.core.JacksonException;
import tools.jackson.core.JsonParser;
import tools.jackson.core.JsonToken;
import tools.jackson.core.exc.InputCoercionException;
import tools.jackson.core.exc.StreamReadException;
import tools.jackson.databind.DeserializationFeature;
import tools.jackson.databind.ObjectReader;
import tools.jackson.databind.ObjectWriter;
import tools.jackson.databind.exc.InvalidTypeIdException;
import tools.jackson.databind.exc.ValueInstantiationException;
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

    private static final Pattern QUOTED = Pattern.compile("'([^']*)'");

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
            throw new ProtocolException(ErrorCode.MALFORMED_JSON, "a line must hold one JSON object, it starts with '"
                    + (char) (utf8[first] & 0x7f) + "'");
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
        Message message;
        try {
            message = reader.readValue(utf8, 0, length);
        } catch (JacksonException e) {
            throw translate(e);
        } catch (RuntimeException e) {
            throw new ProtocolException(ErrorCode.INVALID_VALUE, "cannot decode line: " + e);
        }
        return message;
    }

    /**
     * Decodes a line sent by a client, as the server does.
     *
     * @throws ProtocolException when the line is not a valid client message
     */
    public ClientMessage decodeClient(String line) {
        return decodeClient(line.getBytes(StandardCharsets.UTF_8));
    }

    /** Decodes a line of UTF-8 sent by a client; see {@link #decodeClient(String)}. */
    public ClientMessage decodeClient(byte[] utf8) {
        Message message = decode(utf8);
        if (message instanceof ClientMessage client) {
            return client;
        }
        throw new ProtocolException(ErrorCode.WRONG_DIRECTION,
                "type '" + MessageTypes.nameOf(message.getClass()) + "' is sent by the server, not by clients");
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

    private static ProtocolException translate(JacksonException e) {
        String path = path(e.getPath());
        String original = firstLine(e.getOriginalMessage());
        if (e instanceof InvalidTypeIdException typeId) {
            String id = typeId.getTypeId();
            if (id == null || id.isEmpty()) {
                return new ProtocolException(ErrorCode.MISSING_FIELD, "missing field 'type'");
            }
            return new ProtocolException(ErrorCode.UNKNOWN_TYPE,
                    "unknown message type '" + id + "'; known types are " + MessageTypes.names());
        }
        if (e instanceof ValueInstantiationException) {
            Throwable cause = e.getCause() == null ? e : e.getCause();
            String problem = firstLine(cause.getMessage());
            Matcher missing = Pattern.compile("^missing field '([^']*)'$").matcher(problem);
            if (missing.matches()) {
                return new ProtocolException(ErrorCode.MISSING_FIELD,
                        "missing field '" + join(path, missing.group(1)) + "'");
            }
            return new ProtocolException(ErrorCode.INVALID_VALUE, path.isEmpty() ? problem : path + "." + problem);
        }
        if (original.startsWith("Missing required creator property")) {
            Matcher name = QUOTED.matcher(original);
            String field = name.find() ? name.group(1) : "?";
            String full = path.equals(field) || path.endsWith("." + field) ? path : join(path, field);
            return new ProtocolException(ErrorCode.MISSING_FIELD, "missing field '" + full + "'");
        }
        if (original.startsWith("Trailing token")) {
            return new ProtocolException(ErrorCode.MALFORMED_JSON, "malformed JSON: more than one JSON value on the line");
        }
        if (e instanceof InputCoercionException && e.processor() instanceof JsonParser parser) {
            String field = path.isEmpty() ? String.valueOf(parser.currentName()) : path;
            return new ProtocolException(ErrorCode.INVALID_VALUE, "invalid value for '" + field + "': " + original);
        }
        if (e instanceof StreamReadException && !(e instanceof tools.jackson.databind.exc.MismatchedInputException)) {
            String where = e.getLocation() == null ? "" : " at column " + e.getLocation().getColumnNr();
            return new ProtocolException(ErrorCode.MALFORMED_JSON, "malformed JSON" + where + ": " + original);
        }
        if (path.isEmpty()) {
            return new ProtocolException(ErrorCode.MALFORMED_JSON, "a line must hold one JSON object: " + original);
        }
        return new ProtocolException(ErrorCode.INVALID_VALUE, "invalid value for '" + path + "': " + original);
    }

    private static String path(List<JacksonException.Reference> references) {
        StringBuilder path = new StringBuilder();
        for (JacksonException.Reference reference : references) {
            if (reference.getPropertyName() != null && writtenAsArray(reference.from())) {
                continue; // the element's index follows, and the check's text names the component
            }
            if (reference.getPropertyName() != null) {
                if (path.length() > 0) {
                    path.append('.');
                }
                path.append(reference.getPropertyName());
            } else if (reference.getIndex() >= 0) {
                path.append('[').append(reference.getIndex()).append(']');
            }
        }
        return path.toString();
    }

    /** Whether the value is a record written as an array of its components (a tuple of the lean form). */
    private static boolean writtenAsArray(Object from) {
        Class<?> type = from instanceof Class<?> c ? c : from == null ? null : from.getClass();
        JsonFormat format = type == null ? null : type.getAnnotation(JsonFormat.class);
        return format != null && format.shape() == JsonFormat.Shape.ARRAY;
    }

    private static String join(String path, String field) {
        return path.isEmpty() ? field : path + "." + field;
    }

    private static String firstLine(String text) {
        if (text == null) {
            return "";
        }
        int newline = text.indexOf('\n');
        String line = newline < 0 ? text : text.substring(0, newline);
        return line.replace('`', '\'').strip();
    }
}
