package io.orchard.server.net;

import io.netty.buffer.Unpooled;
import io.netty.channel.Channel;
import io.netty.channel.ChannelFutureListener;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Role;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.EncodedLine;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A client session over a Netty channel. Writes are queued on the channel and flushed once per
 * tick. A client that stops reading is cut off, so it can neither stall the tick nor grow the heap:
 * when its channel has stayed unwritable longer than the grace, or its queue passes the hard cap.
 */
final class NettySession implements ClientSession {

    private static final Logger log = LoggerFactory.getLogger(NettySession.class);

    private final long id;
    private final Role role;
    private final Channel channel;
    private final NetLimits limits;
    private volatile long unwritableSince = -1;

    NettySession(long id, Role role, Channel channel, NetLimits limits) {
        this.id = id;
        this.role = role;
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
    public void send(ServerMessage message) {
        if (keepUp()) {
            channel.write(message, channel.voidPromise());
        }
    }

    @Override
    public void send(EncodedLine line) {
        if (keepUp()) {
            channel.write(Unpooled.wrappedBuffer(line.bytes()), channel.voidPromise());
        }
    }

    @Override
    public void flush() {
        if (channel.isActive()) {
            channel.flush();
        }
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
