package io.orchard.server.net;

import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import io.netty.util.ReferenceCountUtil;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;

/**
 * Limits how many lines one connection may send: a token bucket refilled at {@code perSecond} with
 * room for a burst. A client beyond it gets a last error and is cut off, so one runaway agent cannot
 * starve the others. One per channel (it holds the bucket).
 */
final class FloodGuard extends ChannelInboundHandlerAdapter {

    private final double perSecond;
    private final double burst;
    private final java.util.function.LongSupplier nanoTime;
    private double tokens;
    private long last;
    private boolean tripped;

    FloodGuard(double perSecond, double burst, java.util.function.LongSupplier nanoTime) {
        this.perSecond = perSecond;
        this.burst = burst;
        this.nanoTime = nanoTime;
        this.tokens = burst;
        this.last = nanoTime.getAsLong();
    }

    @Override
    public void channelRead(ChannelHandlerContext ctx, Object line) {
        if (tripped) {
            ReferenceCountUtil.release(line);
            return;
        }
        long now = nanoTime.getAsLong();
        tokens = Math.min(burst, tokens + (now - last) / 1e9 * perSecond);
        last = now;
        if (tokens < 1) {
            tripped = true;
            ReferenceCountUtil.release(line);
            ctx.writeAndFlush(new ErrorMessage(0, ErrorCode.RATE_LIMITED, "more than " + (long) perSecond
                    + " messages per second (burst " + (long) burst + "); closing the connection"))
                    .addListener(ChannelFutureListener.CLOSE);
            return;
        }
        tokens -= 1;
        ctx.fireChannelRead(line);
    }
}
