package io.orchard.server.net;

import io.netty.channel.Channel;
import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import io.netty.util.concurrent.ScheduledFuture;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import java.time.Duration;
import java.util.concurrent.TimeUnit;
import org.slf4j.LoggerFactory;

/**
 * Gives a new connection a few seconds to say {@code Hello}, and a place among the few that may
 * wait to ({@link HelloQueue}); a connection that stays silent, or is pushed out by newer ones, gets
 * an error and is closed. The session removes this stage when the {@code Hello} is welcomed. One
 * per channel (it holds the deadline).
 */
final class HelloDeadline extends ChannelInboundHandlerAdapter {

    private static final RareWarnings warnings = new RareWarnings(LoggerFactory.getLogger(HelloDeadline.class));

    private final HelloQueue queue;
    private final Duration deadline;
    private Channel channel;
    private ScheduledFuture<?> check;

    HelloDeadline(HelloQueue queue, Duration deadline) {
        this.queue = queue;
        this.deadline = deadline;
    }

    @Override
    public void channelActive(ChannelHandlerContext ctx) {
        channel = ctx.channel();
        check = ctx.executor().schedule(() -> expire(ctx), deadline.toNanos(), TimeUnit.NANOSECONDS);
        Channel pushedOut = queue.arrived(channel);
        if (pushedOut != null) {
            warnings.warn("closing {}: more than {} connections are waiting to say Hello", pushedOut.remoteAddress(),
                    queue.max());
            pushedOut.writeAndFlush(new ErrorMessage(0, ErrorCode.TOO_MANY_AGENTS, "more than " + queue.max()
                    + " connections are waiting to say Hello, and this one has waited longest; closing"))
                    .addListener(ChannelFutureListener.CLOSE);
        }
        ctx.fireChannelActive();
    }

    private void expire(ChannelHandlerContext ctx) {
        check = null;
        if (ctx.channel().isActive()) {
            warnings.warn("closing {}: no Hello within {} ms", ctx.channel().remoteAddress(), deadline.toMillis());
            ctx.writeAndFlush(new ErrorMessage(0, ErrorCode.IDLE, "no Hello within " + seconds(deadline)
                    + " of connecting; closing")).addListener(ChannelFutureListener.CLOSE);
        }
    }

    static String seconds(Duration duration) {
        return duration.toMillis() % 1000 == 0 ? duration.toSeconds() + " s" : duration.toMillis() + " ms";
    }

    @Override
    public void handlerRemoved(ChannelHandlerContext ctx) {
        // Removed by the session once welcomed, or with the rest of the pipeline when the channel closes.
        if (check != null) {
            check.cancel(false);
            check = null;
        }
        if (channel != null) {
            queue.left(channel);
        }
    }
}
