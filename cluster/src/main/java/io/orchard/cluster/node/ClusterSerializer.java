package io.orchard.cluster.node;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.LongAdder;
import java.util.stream.Collectors;
import org.apache.pekko.serialization.SerializerWithStringManifest;
import tools.jackson.databind.DeserializationFeature;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.jsontype.NamedType;

/**
 * Carries the cluster's messages ({@link ClusterMessage}) between nodes as JSON, with the Jackson 3
 * that the protocol already brings (no second Jackson, and not Java serialization, which Pekko
 * refuses by default): the manifest names the message's class, the bytes are its record's fields;
 * the protocol's messages inside travel as the protocol's own lines ({@link Wire}). Pekko's
 * configuration binds it ({@code reference.conf} of this module).
 */
public final class ClusterSerializer extends SerializerWithStringManifest {

    /** Pekko's number for this serializer: unique among the serializers of a system. */
    static final int IDENTIFIER = 7557;

    /** Messages and bytes this JVM's serializers wrote: what its node sent to other nodes. */
    private static final java.util.concurrent.atomic.AtomicLong MESSAGES = new java.util.concurrent.atomic.AtomicLong();
    private static final java.util.concurrent.atomic.AtomicLong BYTES = new java.util.concurrent.atomic.AtomicLong();
    /** Bytes written by kind of message (a parcel's step by its command), to see where the traffic goes. */
    private static final Map<String, LongAdder> BYTES_BY_KIND = new ConcurrentHashMap<>();

    private static final JsonMapper MAPPER = named(JsonMapper.builder()
            .disable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES), ParcelCommand.class, ParcelReply.class)
            .build();

    /** Made by Pekko, once per actor system. */
    public ClusterSerializer() {}

    /**
     * Names each kind of the messages that travel inside others, as a parcel's step holds its command
     * and its last answer: by its record's simple name.
     */
    private static JsonMapper.Builder named(JsonMapper.Builder builder, Class<?>... sealed) {
        for (Class<?> type : sealed) {
            for (Class<?> kind : type.getPermittedSubclasses()) {
                builder.registerSubtypes(new NamedType(kind, kind.getSimpleName()));
            }
        }
        return builder;
    }

    @Override
    public int identifier() {
        return IDENTIFIER;
    }

    @Override
    public String manifest(Object message) {
        return message.getClass().getName();
    }

    @Override
    public byte[] toBinary(Object message) {
        if (!(message instanceof ClusterMessage)) {
            throw new IllegalArgumentException("this serializer carries the cluster's messages, not "
                    + message.getClass().getName());
        }
        byte[] bytes = MAPPER.writeValueAsBytes(message);
        MESSAGES.incrementAndGet();
        BYTES.addAndGet(bytes.length);
        Object kind = message instanceof ParcelCommand.Step step ? step.command() : message;
        BYTES_BY_KIND.computeIfAbsent(kind.getClass().getSimpleName(), name -> new LongAdder()).add(bytes.length);
        return bytes;
    }

    /** How many cluster messages, and how many bytes of them, this JVM has sent to other nodes so far. */
    public static long[] sent() {
        return new long[] {MESSAGES.get(), BYTES.get()};
    }

    /** How many bytes of each kind of cluster message this JVM has sent to other nodes so far, most first. */
    public static String sentByKind() {
        return BYTES_BY_KIND.entrySet().stream().map(entry -> Map.entry(entry.getKey(), entry.getValue().sum()))
                .sorted(Map.Entry.<String, Long>comparingByValue().reversed())
                .map(entry -> entry.getKey() + " " + entry.getValue()).collect(Collectors.joining(", "));
    }

    @Override
    public Object fromBinary(byte[] bytes, String manifest) {
        Class<?> type;
        try {
            type = Class.forName(manifest, false, ClusterSerializer.class.getClassLoader());
        } catch (ClassNotFoundException e) {
            throw new IllegalArgumentException("no message class " + manifest + " in this node's Orchard", e);
        }
        if (!ClusterMessage.class.isAssignableFrom(type)) {
            throw new IllegalArgumentException("manifest " + manifest + " names no cluster message");
        }
        return MAPPER.readValue(bytes, type);
    }
}
