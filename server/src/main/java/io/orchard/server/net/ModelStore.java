package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.Unpooled;
import io.orchard.protocol.value.ModelSpec;
import java.lang.ref.Reference;
import java.lang.ref.ReferenceQueue;
import java.lang.ref.WeakReference;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;

/**
 * Every agent model the server holds, each once: registrations of the same model share one copy of
 * its text, and every viewer is sent the same bytes rather than a copy of its own. It also keeps
 * the server's cap on models: the models held at once, counted by their decoded size, stay within
 * {@code modelBytesInAll}. A model counts for its decoded bytes, and at least 1 KiB.
 *
 * <p>A model is held as long as the game holds its text (an agent in the world, or one that left
 * and may come back), which the store sees through a weak reference, and after that for as long as
 * its bytes are still waiting to be sent to a client. Its bytes to send are made the first time a
 * viewer needs them, outside the Java heap: a socket writes them without copying.
 *
 * <p>Shared by every channel; safe from any thread.
 */
final class ModelStore {

    /** One model's text, seen weakly, with its size and its bytes once made. */
    private static final class Held extends WeakReference<String> {
        final int hash;
        final int size;
        /** The Base64 text as bytes, one reference kept here; null until a viewer needs it. */
        ByteBuf wire;

        Held(String data, int size, ReferenceQueue<String> gone) {
            super(data, gone);
            this.hash = data.hashCode();
            this.size = size;
        }

        /** Whether a client still has these bytes waiting to be sent. */
        boolean inFlight() {
            return wire != null && wire.refCnt() > 1;
        }
    }

    /** What {@link #admit} decided. */
    record Admitted(ModelSpec model, String refusal) {}

    private final long inAll;
    private final Map<Integer, List<Held>> byHash = new HashMap<>();
    /** Models the game let go of whose bytes are still on their way to a client. */
    private final List<Held> leaving = new ArrayList<>();
    private final ReferenceQueue<String> gone = new ReferenceQueue<>();
    private long held;

    ModelStore(long inAll) {
        this.inAll = inAll;
    }

    /**
     * What a model counts for: its decoded bytes, and at least 1 KiB, so that a million tiny models
     * cannot cost more than their count says.
     */
    static int cost(String data) {
        return Math.max(1024, decodedSize(data));
    }

    /** Decoded bytes of the Base64 text, counted from its length and padding. */
    static int decodedSize(String data) {
        int length = data.length();
        int padding = 0;
        while (padding < 2 && padding < length && data.charAt(length - 1 - padding) == '=') {
            padding++;
        }
        int whole = length / 4 * 3;
        int rest = length % 4;
        return whole + (rest == 0 ? 0 : rest - 1) - padding;
    }

    /**
     * Takes a model registered by a connection whose models so far are {@code mine}: the model to
     * hand on (the copy already held when the same text is, so that the game keeps one) or why it is
     * refused. A model new to the connection counts against {@code perConnection}; a model new to
     * the server, against the server's cap.
     */
    synchronized Admitted admit(ModelSpec model, ConnectionModels mine, long perConnection) {
        String data = model.data();
        Held same = find(data);
        String text = same == null ? data : same.get();
        int size = same == null ? cost(data) : same.size;
        if (!mine.has(text)) {
            if (mine.bytes() + size > perConnection) {
                return new Admitted(null, "model: a connection may register models of at most " + perConnection
                        + " bytes in all, this one has registered " + mine.bytes() + " and this model has " + size);
            }
            if (same == null && heldBytes() + size > inAll) {
                return new Admitted(null, "model: the server holds " + held + " bytes of models, and takes at most "
                        + inAll + "; this model has " + size + " (a bundled model costs nothing)");
            }
            mine.add(text, size);
        }
        if (same == null) {
            byHash.computeIfAbsent(data.hashCode(), h -> new ArrayList<>(1)).add(new Held(data, size, gone));
            held += size;
            return new Admitted(model, null);
        }
        return new Admitted(text == data ? model : new ModelSpec(model.format(), null, text, model.fit()), null);
    }

    /**
     * The model's Base64 text as bytes to write, shared with every other client: a new reference the
     * caller hands to a channel (which releases it once written). A model the store was never given
     * (one of a saved game) is taken in now, whatever the cap.
     */
    synchronized ByteBuf wire(String data) {
        Held model = find(data);
        if (model == null) {
            model = new Held(data, cost(data), gone);
            byHash.computeIfAbsent(model.hash, h -> new ArrayList<>(1)).add(model);
            held += model.size;
        }
        if (model.wire == null) {
            byte[] bytes = data.getBytes(StandardCharsets.US_ASCII);
            ByteBuffer direct = ByteBuffer.allocateDirect(bytes.length).put(bytes).flip();
            // Freed with the ByteBuffer once nothing refers to it, so release() never frees it.
            model.wire = Unpooled.wrappedBuffer(direct).asReadOnly();
        }
        return model.wire.retainedDuplicate();
    }

    /** Decoded bytes of the models held now, those still being sent included. */
    synchronized long heldBytes() {
        forgetGone();
        return held;
    }

    private Held find(String data) {
        forgetGone();
        List<Held> same = byHash.get(data.hashCode());
        if (same != null) {
            for (Held model : same) {
                String text = model.get();
                if (text != null && text.equals(data)) {
                    return model;
                }
            }
        }
        return null;
    }

    /** Moves the models the game let go of out of the index, and forgets those no client waits for. */
    private void forgetGone() {
        Reference<? extends String> reference;
        while ((reference = gone.poll()) != null) {
            Held model = (Held) reference;
            List<Held> same = byHash.get(model.hash);
            if (same != null && same.remove(model) && same.isEmpty()) {
                byHash.remove(model.hash);
            }
            leaving.add(model);
        }
        for (Iterator<Held> it = leaving.iterator(); it.hasNext(); ) {
            Held model = it.next();
            if (!model.inFlight()) {
                it.remove();
                held -= model.size;
                model.wire = null;
            }
        }
    }
}
