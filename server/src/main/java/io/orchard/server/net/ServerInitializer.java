package io.orchard.server.net;

import io.netty.channel.ChannelInitializer;
import io.netty.channel.ChannelPipeline;
import io.netty.channel.socket.SocketChannel;
import io.netty.handler.codec.LineBasedFrameDecoder;
import io.netty.handler.timeout.IdleStateHandler;
import io.orchard.protocol.MessageCodec;
import io.orchard.server.sim.Inbox;
import java.util.concurrent.TimeUnit;

/** Assembles a connection's pipeline, and does nothing else. */
final class ServerInitializer extends ChannelInitializer<SocketChannel> {

    private final MessageDecoder decoder;
    private final MessageEncoder encoder;
    private final NetLimits limits;
    private final SessionContext shared;
    private final Admission admission;
    private final HelloQueue waitingForHello;
    private final LineSlots largeLines;

    ServerInitializer(MessageCodec codec, Inbox inbox, String token, String operatorToken, NetLimits limits) {
        this.decoder = new MessageDecoder(codec);
        this.encoder = new MessageEncoder(codec);
        this.limits = limits;
        this.shared = SessionContext.of(inbox, token, operatorToken, limits);
        this.admission = new Admission(limits.maxConnections());
        this.waitingForHello = new HelloQueue(limits.maxWaitingForHello());
        this.largeLines = new LineSlots(limits.largeLinesAtOnce());
    }

    @Override
    protected void initChannel(SocketChannel channel) {
        ChannelPipeline pipeline = channel.pipeline();
        // The encoder sits at the head so that the error every later stage may write gets encoded.
        pipeline.addLast("encoder", encoder);
        pipeline.addLast("admission", admission);
        pipeline.addLast("hello", new HelloDeadline(waitingForHello, limits.helloDeadline()));
        pipeline.addLast("idle", new IdleStateHandler(limits.idleTimeout().toMillis(), 0, 0, TimeUnit.MILLISECONDS));
        pipeline.addLast("deadline", new LineDeadline(limits.lineDeadline(), System::nanoTime));
        pipeline.addLast("large", new LargeLineGate(largeLines));
        pipeline.addLast("frame", new LineBasedFrameDecoder(MessageCodec.MAX_LARGE_LINE_BYTES + 1, true, true));
        pipeline.addLast("flood", new FloodGuard(limits.messagesPerSecond(), limits.burst(), System::nanoTime,
                shared.inbox()::lockstepTicks));
        pipeline.addLast("decoder", decoder);
        pipeline.addLast("session", new SessionHandler(shared));
    }
}
