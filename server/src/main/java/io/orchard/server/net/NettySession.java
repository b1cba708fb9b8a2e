package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import io.netty.channel.Channel;
import io.netty.channel.ChannelFutureListener;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Role;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.EncodedLine;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A client session over a Netty channel. What the simulation sends during a tick is collected here
 * and handed to the channel's I/O thread when the tick flushes ({@link TickWrites}), which encodes
 * it all into one buffer and writes it once: a tick costs one write per client rather than one per
 * message, and no encoding on the tick's thread. A client that stops reading is cut off, so it
 * can neither stall the tick nor grow the heap: when its channel has stayed unwritable longer than
 * the grace, or its queue passes the hard cap.
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
    private final Channel channel;
    private final NetLimits limits;
    private final TickWrites writes;
    private volatile long unwritableSince = -1;
    private List<Object> batch = new ArrayList<>();
    /** Ticks whose messages were handed to the I/O thread and not yet written. */
    private final AtomicInteger unwritten = new AtomicInteger();

    NettySession(long id, Role role, int version, Channel channel, NetLimits limits, TickWrites writes) {
        this.writes = writes;
        this.id = id;
        this.role = role;
        this.version = version;
        this.channel = channel;
        this.limits = limits;
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

    @Override
    public void send(ServerMessage message) {
        if (keepUp()) {
            batch.add(message);
        }
    }

    @Override
    public void send(EncodedLine line) {
        if (keepUp()) {
            batch.add(line);
        }
    }

    @Override
    public void flush() {
        if (batch.isEmpty()) {
            return;
        }
        List<Object> out = batch;
        batch = new ArrayList<>(Math.max(8, out.size()));
        if (!channel.isActive()) {
            return;
        }
        if (unwritten.incrementAndGet() > MAX_UNWRITTEN_TICKS) {
            // The I/O thread has not even encoded this client's last ticks: do not queue more.
            log.warn("cutting off {} client #{}: {} ticks of messages not yet written", role.wireName(), id,
                    unwritten.get());
            channel.close();
            return;
        }
        writes.submit(channel.eventLoop(), () -> write(out));
    }

    /** On the channel's I/O thread: the tick's messages, encoded one after the other into one buffer. */
    private void write(List<Object> messages) {
        unwritten.decrementAndGet();
        ByteBuf buffer = channel.alloc().buffer(messages.size() * 256);
        try {
            for (Object message : messages) {
                if (message instanceof EncodedLine line) {
                    buffer.writeBytes(line.bytes());
                } else if (!FastLines.write((ServerMessage) message, buffer)) {
                    buffer.writeBytes(CODEC.encodeLine((ServerMessage) message));
                }
            }
        } catch (RuntimeException e) {
            buffer.release();
            log.error("cannot encode a message for {}; closing", this, e);
            channel.close();
            return;
        }
        channel.writeAndFlush(buffer, channel.voidPromise());
    }

    @Override
    public void close(ErrorMessage last) {
        if (channel.isActive()) {
            channel.writeAndFlush(last).addListener(ChannelFutureListener.CLOSE);
        }
    }

    @Override
    public boolean isOpen() {
        return channel.isActive();
    }

    /** Whether this client still keeps up with what it is sent; cuts it off when it does not. */
    private boolean keepUp() {
        if (!channel.isActive()) {
            return false;
        }
        if (channel.isWritable()) {
            unwritableSince = -1;
            return true;
        }
        long now = System.nanoTime();
        if (unwritableSince < 0) {
            unwritableSince = now;
        }
        long queued = channel.bytesBeforeWritable() + channel.config().getWriteBufferHighWaterMark();
        boolean tooLong = now - unwritableSince > limits.slowConsumerGrace().toNanos();
        if (tooLong || queued > limits.maxPendingBytes()) {
            log.warn("cutting off slow {} client #{}: {} bytes unread for {} ms", role.wireName(), id, queued,
                    (now - unwritableSince) / 1_000_000);
            // The client is not reading, so a last error would only queue behind the rest: just close.
            channel.close();
            return false;
        }
        return true;
    }

    @Override
    public String toString() {
        return role.wireName() + " #" + id + " " + channel.remoteAddress();
    }
}
