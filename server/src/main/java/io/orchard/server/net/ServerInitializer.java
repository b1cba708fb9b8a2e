package io.orchard.server.net;

import io.netty.channel.ChannelInitializer;
import io.netty.channel.ChannelPipeline;
import io.netty.channel.socket.SocketChannel;
import io.netty.handler.codec.LineBasedFrameDecoder;
import io.netty.handler.timeout.IdleStateHandler;
import io.orchard.protocol.MessageCodec;
import io.orchard.server.sim.Inbox;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/** Assembles a connection's pipeline, and does nothing else. */
final class ServerInitializer extends ChannelInitializer<SocketChannel> {

    private final MessageDecoder decoder;
    private final MessageEncoder encoder;
    private final Inbox inbox;
    private final String token;
    private final NetLimits limits;
    private final AtomicLong sessionIds = new AtomicLong();
    private final Admission admission;
    private final TickWrites writes = new TickWrites();

    ServerInitializer(MessageCodec codec, Inbox inbox, String token, NetLimits limits) {
        this.decoder = new MessageDecoder(codec);
        this.encoder = new MessageEncoder(codec);
        this.inbox = inbox;
        this.token = token;
        this.limits = limits;
        this.admission = new Admission(limits.maxConnections());
    }

    @Override
    protected void initChannel(SocketChannel channel) {
        ChannelPipeline pipeline = channel.pipeline();
        // The encoder sits at the head so that the error every later stage may write gets encoded.
        pipeline.addLast("encoder", encoder);
        pipeline.addLast("admission", admission);
        pipeline.addLast("idle", new IdleStateHandler(limits.idleTimeout().toMillis(), 0, 0, TimeUnit.MILLISECONDS));
        pipeline.addLast("deadline", new LineDeadline(limits.lineDeadline(), System::nanoTime));
        pipeline.addLast("frame", new LineBasedFrameDecoder(MessageCodec.MAX_LARGE_LINE_BYTES + 1, true, true));
        pipeline.addLast("flood", new FloodGuard(limits.messagesPerSecond(), limits.burst(), System::nanoTime));
        pipeline.addLast("decoder", decoder);
        pipeline.addLast("session", new SessionHandler(inbox, sessionIds, token, limits, writes));
    }
}
