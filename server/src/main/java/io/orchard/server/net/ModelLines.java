package io.orchard.server.net;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.value.AgentState;
import io.orchard.protocol.value.ModelSpec;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * Cuts an {@code AgentAdded} line around its model's data, so that the data, the bulk of the line,
 * can be written from the one copy every client shares ({@link ModelStore#wire}) between the two
 * pieces written for this client alone. Together the three are the line the codec writes, byte for
 * byte: Base64 needs no escaping in JSON. Stateless.
 */
final class ModelLines {

    private static final byte[] MODEL = "\"model\":{".getBytes(StandardCharsets.US_ASCII);
    private static final byte[] DATA = "\"data\":\"".getBytes(StandardCharsets.US_ASCII);

    /** The line before the model's data, and after it (from the data's closing quote, newline included). */
    record Cut(byte[] before, byte[] after) {}

    private ModelLines() {}

    /** Whether the message carries model data that is worth sharing. */
    static boolean carriesData(AgentAddedMessage message) {
        ModelSpec model = message.agent().model();
        return model != null && model.data() != null && !model.data().isEmpty();
    }

    /** The line of {@code message} cut where its model's data goes; it must {@linkplain #carriesData carry data}. */
    static Cut cut(MessageCodec codec, AgentAddedMessage message) {
        AgentState agent = message.agent();
        AgentState empty = new AgentState(agent.name(), agent.body(), agent.position(), agent.heading(),
                new ModelSpec(agent.model().format(), null, "", agent.model().fit()), agent.joints(), agent.timeSensors());
        byte[] line = codec.encodeLine(new AgentAddedMessage(message.tick(), empty));
        // Inside a JSON string every quote is escaped, so the first "model":{ is the field itself.
        int model = indexOf(line, MODEL, 0);
        int data = indexOf(line, DATA, model);
        if (model < 0 || data < 0) {
            throw new IllegalStateException("no model data in " + new String(line, StandardCharsets.UTF_8));
        }
        int end = data + DATA.length;
        return new Cut(Arrays.copyOf(line, end), Arrays.copyOfRange(line, end, line.length));
    }

    private static int indexOf(byte[] bytes, byte[] part, int from) {
        outer:
        for (int i = Math.max(0, from); i + part.length <= bytes.length; i++) {
            for (int k = 0; k < part.length; k++) {
                if (bytes[i + k] != part[k]) {
                    continue outer;
                }
            }
            return i;
        }
        return -1;
    }
}
