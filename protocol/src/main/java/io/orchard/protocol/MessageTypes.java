package io.orchard.protocol;

import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.LeanPerceptionMessage;
import io.orchard.protocol.message.Message;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import java.util.ArrayDeque;
import java.util.Collections;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;

/**
 * The registry of message types, found from the sealed hierarchy so that a new record is on the
 * wire as soon as it is permitted: its name is the record's simple name without "Message".
 */
public final class MessageTypes {

    private static final Map<String, Class<? extends Message>> BY_NAME = discover();

    /**
     * Messages that may be longer than an ordinary line: those that carry an agent's model, the
     * snapshot of a whole world, and a perception in a crowded part of a large world.
     */
    private static final Set<Class<? extends Message>> LARGE = Set.of(RegisterMessage.class, AgentAddedMessage.class,
            WorldSnapshotMessage.class, PerceptionMessage.class, LeanPerceptionMessage.class);

    private MessageTypes() {}

    /** Every message type name, in a stable order (client messages first, then server messages). */
    public static Set<String> names() {
        return Collections.unmodifiableSet(BY_NAME.keySet());
    }

    /** Every message record class by its type name. */
    public static Map<String, Class<? extends Message>> all() {
        return Collections.unmodifiableMap(BY_NAME);
    }

    /** The wire name of a message type: {@code MoveMessage} is {@code Move}. */
    public static String nameOf(Class<? extends Message> type) {
        String simple = type.getSimpleName();
        return simple.endsWith("Message") ? simple.substring(0, simple.length() - "Message".length()) : simple;
    }

    /** The longest line, in bytes of UTF-8 without the newline, that a message of this type may take. */
    public static int maxLineBytes(Class<? extends Message> type) {
        return LARGE.contains(type) ? MessageCodec.MAX_LARGE_LINE_BYTES : MessageCodec.MAX_LINE_BYTES;
    }

    @SuppressWarnings("unchecked")
    private static Map<String, Class<? extends Message>> discover() {
        Map<String, Class<? extends Message>> found = new LinkedHashMap<>();
        Deque<Class<?>> pending = new ArrayDeque<>();
        pending.add(Message.class);
        while (!pending.isEmpty()) {
            Class<?> type = pending.removeFirst();
            if (type.isRecord()) {
                found.putIfAbsent(nameOf((Class<? extends Message>) type), (Class<? extends Message>) type);
            } else {
                Class<?>[] permitted = type.getPermittedSubclasses();
                java.util.Arrays.sort(permitted, (a, b) -> a.getSimpleName().compareTo(b.getSimpleName()));
                Collections.addAll(pending, permitted);
            }
        }
        return found;
    }
}
