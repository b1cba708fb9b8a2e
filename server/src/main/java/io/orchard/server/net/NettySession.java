package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import io.netty.channel.Channel;
import io.netty.channel.ChannelFutureListener;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Role;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.EncodedLine;
import io.orchard.server.sim.Percept;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A client session over a Netty channel. What the simulation sends during a tick is collected here
 * and handed to the channel's I/O thread when the tick flushes ({@link TickWrites}), which encodes
 * it all into one buffer and queues it in the client's {@link Outbox}: a tick costs one write per
 * client rather than one per message, and no encoding on the tick's thread. What is flushed before
 * the I/O thread took the previous flush joins it (the end of one tick and the start of the next
 * often do), so a busy server makes fewer, larger writes. The data of an agent's
 * model is not encoded per client: it is written from the one copy the {@link ModelStore} keeps for
 * every client. A client that stops reading is cut off by its outbox, so it can neither stall the
 * tick nor grow the server's memory. A perception comes as a {@link Percept}, written on the I/O
 * thread in the form the client reads ({@link ClientForms}): one {@code LeanPerception} line, or the
 * ordinary form's three ({@link TickLines}); a lean client gets no result for an accepted move
 * unless it asked.
 *
 * <p>{@link #send} and {@link #flush} are called by the simulation's thread only.
 */
final class NettySession implements ClientSession {

    private static final Logger log = LoggerFactory.getLogger(NettySession.class);
    private static final MessageCodec CODEC = new MessageCodec();
    /** Handed-over ticks a client may have waiting for its I/O thread: 10 s at 20 ticks a second. */
    private static final int MAX_UNWRITTEN_TICKS = 200;

    private final long id;
    private final Role role;
    private final int version;
    private final ClientForms forms;
    private final Channel channel;
    private final SessionContext shared;
    private final Outbox outbox;
    private final AtomicBoolean ended = new AtomicBoolean();
    private List<Object> batch = new ArrayList<>();
    /** Guards what was handed to the I/O thread and not yet taken by it. */
    private final Object handoff = new Object();
    /** Messages handed over and not yet taken: a flush before the I/O thread takes them adds to them. */
    private List<Object> waiting;
    /** Flushes whose messages wait in {@link #waiting}. */
    private int waitingFlushes;
    /** {@link #writeWaiting()}, made once rather than at every flush. */
    private final Runnable writeWaiting = this::writeWaiting;

    /**
     * Made on the channel's I/O thread, for a client that speaks protocol {@code version} on a
     * channel whose output goes through {@code outbox}.
     */
    NettySession(long id, Role role, int version, ClientForms forms, Channel channel, SessionContext shared,
                 Outbox outbox) {
        this.id = id;
        this.role = role;
        this.version = version;
        this.forms = forms;
        this.channel = channel;
        this.shared = shared;
        this.outbox = outbox;
    }

    @Override
    public long id() {
        return id;
    }

    @Override
    public Role role() {
        return role;
    }

    @Override
    public int protocolVersion() {
        return version;
    }

    // What is sent to a connection that has closed is dropped at the flush, which checks once for
    // the whole batch rather than the channel's state for every message.

    @Override
    public void send(ServerMessage message) {
        if (forms.sends(message)) {
            batch.add(version < 2 && message instanceof AgentAddedMessage added ? added.forVersion1() : message);
        }
    }

    @Override
    public void send(Percept percept) {
        batch.add(percept);
    }

    @Override
    public void send(EncodedLine line) {
        // A model of version 2 is written anew for a version 1 client, without what it does not know.
        batch.add(version < 2 && line.message() instanceof AgentAddedMessage added
                && added.forVersion1() != added ? added.forVersion1() : line);
    }

    @Override
    public void flush() {
        if (batch.isEmpty()) {
            return;
        }
        List<Object> out = batch;
        batch = new ArrayList<>(Math.max(8, out.size()));
        // Only whether the connection has ended, which is this object's: the channel's own state is
        // the network thread's memory, a cache miss per client per tick here. What goes to a channel
        // that closed a moment ago is dropped by its outbox.
        if (ended.get()) {
            return;
        }
        synchronized (handoff) {
            if (waiting != null) {
                // The I/O thread has not taken the last flush yet: these go out with it, in one write.
                if (waitingFlushes >= MAX_UNWRITTEN_TICKS) {
                    outbox.cutSoon(MAX_UNWRITTEN_TICKS + " ticks of messages for this client are not yet written");
                    return;
                }
                waiting.addAll(out);
                waitingFlushes++;
                return;
            }
            waiting = out;
            waitingFlushes = 1;
        }
        shared.writes().submit(channel.eventLoop(), writeWaiting);
    }

    /** On the channel's I/O thread: takes what waits and writes it. */
    private void writeWaiting() {
        List<Object> messages;
        synchronized (handoff) {
            messages = waiting;
            waiting = null;
            waitingFlushes = 0;
        }
        if (messages != null) {
            write(messages);
        }
    }

    /**
     * On the channel's I/O thread: the tick's messages, encoded one after the other into one buffer,
     * except the data of models, which go out from the copy every client shares.
     */
    private void write(List<Object> messages) {
        ByteBuf buffer = channel.alloc().buffer(messages.size() * 256);
        try {
            int at;
            for (int from = 0; (at = TickLines.write(messages, from, forms, buffer)) < messages.size(); from = at + 1) {
                Object carrier = messages.get(at);
                AgentAddedMessage added = (AgentAddedMessage) (carrier instanceof EncodedLine line ? line.message()
                        : carrier);
                ModelLines.Cut cut = ModelLines.cut(CODEC, added);
                outbox.add(buffer.writeBytes(cut.before()), false);
                outbox.add(shared.models().wire(added.agent().model().data()), true);
                buffer = channel.alloc().buffer(Math.max(256, cut.after().length));
                buffer.writeBytes(cut.after());
            }
        } catch (RuntimeException e) {
            buffer.release();
            log.error("cannot encode a message for {}; closing", this, e);
            channel.close();
            return;
        }
        outbox.add(buffer, false);
    }

    /** Tells the simulation, once, that this client is gone. */
    void end(String reason) {
        if (ended.compareAndSet(false, true)) {
            shared.inbox().disconnected(this, reason);
        }
    }

    @Override
    public void close(ErrorMessage last) {
        if (isOpen()) {
            // After what the client has been sent already, in the order the simulation sent it.
            flush();
            shared.writes().submit(channel.eventLoop(),
                    () -> channel.writeAndFlush(last).addListener(ChannelFutureListener.CLOSE));
        }
    }

    @Override
    public boolean isOpen() {
        return channel.isActive() && !outbox.isCut() && !ended.get();
    }

    @Override
    public String toString() {
        return role.wireName() + " #" + id + " " + channel.remoteAddress();
    }
}
