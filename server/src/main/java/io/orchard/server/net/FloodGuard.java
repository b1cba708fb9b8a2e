package io.orchard.server.net;

import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import io.netty.util.ReferenceCountUtil;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import java.util.function.LongSupplier;

/**
 * Limits how many lines one connection may send: a token bucket refilled at {@code perSecond} with
 * room for a burst, and by {@link #LINES_PER_LOCKSTEP_TICK} for every tick a lockstep game plays. A
 * client beyond it gets a last error and is cut off, so one runaway agent cannot starve the others.
 * One per channel (it holds the bucket).
 *
 * <p>A lockstep game runs as fast as its agents end their turns, many times faster than real time,
 * and an agent that acts every tick sends more lines a second the faster it runs. A tick ends only
 * once every agent's client has ended its turn, so what the ticks add grows no faster than the
 * server plays the game: a client cannot earn lines by sending them.
 */
final class FloodGuard extends ChannelInboundHandlerAdapter {

    /** Lines a client may send for each tick of a lockstep game, besides the rate: 8 agents' actions and more. */
    static final int LINES_PER_LOCKSTEP_TICK = 100;

    private final double perSecond;
    private final double burst;
    private final LongSupplier nanoTime;
    private final LongSupplier lockstepTicks;
    private double tokens;
    private long last;
    private long ticks;
    private boolean tripped;

    FloodGuard(double perSecond, double burst, LongSupplier nanoTime) {
        this(perSecond, burst, nanoTime, () -> 0);
    }

    /** A guard whose bucket also fills with the ticks of lockstep games that {@code lockstepTicks} counts. */
    FloodGuard(double perSecond, double burst, LongSupplier nanoTime, LongSupplier lockstepTicks) {
        this.perSecond = perSecond;
        this.burst = burst;
        this.nanoTime = nanoTime;
        this.lockstepTicks = lockstepTicks;
        this.tokens = burst;
        this.last = nanoTime.getAsLong();
        this.ticks = lockstepTicks.getAsLong();
    }

    @Override
    public void channelRead(ChannelHandlerContext ctx, Object line) {
        if (tripped) {
            ReferenceCountUtil.release(line);
            return;
        }
        long now = nanoTime.getAsLong();
        long played = lockstepTicks.getAsLong();
        tokens = Math.min(burst, tokens + (now - last) / 1e9 * perSecond
                + (double) (played - ticks) * LINES_PER_LOCKSTEP_TICK);
        last = now;
        ticks = played;
        if (tokens < 1) {
            tripped = true;
            ReferenceCountUtil.release(line);
            ctx.writeAndFlush(new ErrorMessage(0, ErrorCode.RATE_LIMITED, "more than " + (long) perSecond
                    + " messages per second (burst " + (long) burst + ", and " + LINES_PER_LOCKSTEP_TICK
                    + " more for each tick of a lockstep game); closing the connection"))
                    .addListener(ChannelFutureListener.CLOSE);
            return;
        }
        tokens -= 1;
        ctx.fireChannelRead(line);
    }
}
