package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import io.netty.util.concurrent.ScheduledFuture;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import java.time.Duration;
import java.util.concurrent.TimeUnit;

/**
 * Closes a connection that leaves a line unfinished for longer than the deadline: a "slow loris"
 * that trickles a byte now and then never sends a whole line, so the idle timeout alone would
 * never fire. It watches the raw bytes before framing: a line starts with its first byte and ends
 * with its newline. One per channel (it holds the clock of the line in progress).
 */
final class LineDeadline extends ChannelInboundHandlerAdapter {

    private final long deadlineNanos;
    private final java.util.function.LongSupplier nanoTime;
    /** When the unfinished line began (its first byte arrived), or -1 when no line is in progress. */
    private long lineStarted = -1;
    private ScheduledFuture<?> check;

    LineDeadline(Duration deadline, java.util.function.LongSupplier nanoTime) {
        this.deadlineNanos = deadline.toNanos();
        this.nanoTime = nanoTime;
    }

    @Override
    public void channelRead(ChannelHandlerContext ctx, Object message) {
        if (message instanceof ByteBuf bytes && bytes.isReadable()) {
            int lastNewline = bytes.forEachByteDesc(b -> b != '\n');
            if (lastNewline < 0) {
                if (lineStarted < 0) {
                    started(ctx);
                }
            } else if (lastNewline < bytes.writerIndex() - 1) {
                // The chunk ends a line and begins the next.
                started(ctx);
            } else {
                lineStarted = -1;
            }
        }
        ctx.fireChannelRead(message);
    }

    private void started(ChannelHandlerContext ctx) {
        lineStarted = nanoTime.getAsLong();
        if (check == null) {
            schedule(ctx, deadlineNanos);
        }
    }

    private void schedule(ChannelHandlerContext ctx, long delayNanos) {
        check = ctx.executor().schedule(() -> expire(ctx), delayNanos, TimeUnit.NANOSECONDS);
    }

    /** The check came due: close if the line that was in progress then is still unfinished. */
    void expire(ChannelHandlerContext ctx) {
        check = null;
        if (lineStarted < 0 || !ctx.channel().isActive()) {
            return;
        }
        long age = nanoTime.getAsLong() - lineStarted;
        if (age < deadlineNanos) {
            schedule(ctx, deadlineNanos - age);
            return;
        }
        ctx.writeAndFlush(new ErrorMessage(0, ErrorCode.IDLE, "a line was left unfinished for "
                + deadlineNanos / 1_000_000_000 + " s; closing")).addListener(ChannelFutureListener.CLOSE);
    }

    @Override
    public void handlerRemoved(ChannelHandlerContext ctx) {
        if (check != null) {
            check.cancel(false);
            check = null;
        }
    }

    @Override
    public void channelInactive(ChannelHandlerContext ctx) {
        handlerRemoved(ctx);
        ctx.fireChannelInactive();
    }
}
