package io.orchard.server.net;

import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelHandler.Sharable;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.LoggerFactory;

/**
 * Takes at most so many connections at once: the one beyond gets an error and is closed before it
 * can cost anything, so thousands of connections cannot exhaust the server. Shared by every
 * channel (it holds the one count).
 */
@Sharable
final class Admission extends ChannelInboundHandlerAdapter {

    private static final RareWarnings warnings = new RareWarnings(LoggerFactory.getLogger(Admission.class));

    private final int maxConnections;
    private final AtomicInteger open = new AtomicInteger();

    Admission(int maxConnections) {
        this.maxConnections = maxConnections;
    }

    @Override
    public void channelActive(ChannelHandlerContext ctx) {
        int now = open.incrementAndGet();
        ctx.channel().closeFuture().addListener(closed -> open.decrementAndGet());
        if (now > maxConnections) {
            ctx.channel().config().setAutoRead(false);
            warnings.warn("refusing {}: {} connections are open, the most this server takes",
                    ctx.channel().remoteAddress(), maxConnections);
            ctx.writeAndFlush(new ErrorMessage(0, ErrorCode.TOO_MANY_AGENTS, "the server takes at most "
                    + maxConnections + " connections; try again later")).addListener(ChannelFutureListener.CLOSE);
            return;
        }
        ctx.fireChannelActive();
    }

    /** Connections open now. */
    int open() {
        return open.get();
    }
}
