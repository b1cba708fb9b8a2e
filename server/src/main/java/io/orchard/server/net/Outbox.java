package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.Unpooled;
import io.netty.channel.Channel;
import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelPromise;
import io.netty.util.AttributeKey;
import io.netty.util.concurrent.ScheduledFuture;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import java.nio.channels.ClosedChannelException;
import java.util.ArrayDeque;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongSupplier;
import org.slf4j.LoggerFactory;

/**
 * What waits to be written to one client, in order, handed to its socket only as fast as the
 * socket takes it: the channel's own buffer stays small, and what waits here can be dropped at
 * once when the client is cut off. A client is cut off, with a last {@code slow_consumer} error,
 * when the oldest output waiting for it has waited longer than the grace (it has fallen that far
 * behind), when more than its cap of bytes waits for it, or when the server's {@link OutputBudget}
 * is full and it has the most waiting. Bytes of a model shared with other clients are not counted
 * against its cap: the {@link ModelStore} caps them.
 *
 * <p>Everything but {@link #isCut}, {@link #ownBytes} and {@link #cutSoon} runs on the channel's
 * I/O thread.
 */
final class Outbox {

    /** The most handed to the channel at once. */
    private static final int SLICE = 64 * 1024;

    /** How long a client that was cut off has, at least, to take its last error before the connection closes. */
    private static final long LAST_WORDS_NANOS = 5_000_000_000L;

    private static final MessageCodec CODEC = new MessageCodec();

    private static final RareWarnings warnings = new RareWarnings(LoggerFactory.getLogger(Outbox.class));

    /** One buffer to write: a tick's lines for this client alone, or a model shared with others. */
    private record Piece(ByteBuf bytes, boolean shared, long queuedAt, ChannelPromise promise) {}

    /** Where a channel keeps its outbox, for the stages that write to it. */
    static final AttributeKey<Outbox> KEY = AttributeKey.valueOf(Outbox.class, "outbox");

    private final Channel channel;
    private final Object who;
    private final long graceNanos;
    private final long maxBytes;
    private final OutputBudget budget;
    private final Runnable onCut;
    private final LongSupplier nanoTime;
    private final ArrayDeque<Piece> queue = new ArrayDeque<>();
    /** When each piece handed to the channel and not yet written was queued, oldest first. */
    private final ArrayDeque<Long> inFlight = new ArrayDeque<>();
    private final AtomicLong ownBytes = new AtomicLong();
    private final ScheduledFuture<?> watch;
    private volatile boolean cut;

    /**
     * @param who   the client, for the log (its {@code toString()} when one is written)
     * @param onCut told once when the client is cut off, before its connection closes
     */
    Outbox(Channel channel, Object who, NetLimits limits, OutputBudget budget, Runnable onCut, LongSupplier nanoTime) {
        this.channel = channel;
        this.nanoTime = nanoTime;
        this.who = who;
        this.graceNanos = limits.slowConsumerGrace().toNanos();
        this.maxBytes = limits.maxPendingBytes();
        this.budget = budget;
        this.onCut = onCut;
        long every = Math.max(10_000_000L, Math.min(1_000_000_000L, graceNanos / 4));
        this.watch = channel.eventLoop().scheduleAtFixedRate(this::check, every, every, TimeUnit.NANOSECONDS);
        budget.opened(this);
        channel.closeFuture().addListener(closed -> closed());
    }

    /** Queues a buffer to write after everything queued before it, and writes what the socket takes. */
    void add(ByteBuf bytes, boolean shared) {
        add(bytes, shared, null);
    }

    /** {@link #add(ByteBuf, boolean)}, completing {@code promise} once the buffer is written (or failing it). */
    void add(ByteBuf bytes, boolean shared, ChannelPromise promise) {
        if (cut || !channel.isActive()) {
            bytes.release();
            fail(promise);
            return;
        }
        queue.add(new Piece(bytes, shared, nanoTime.getAsLong(), promise));
        if (!shared) {
            count(bytes.readableBytes());
        }
        pump();
        if (!cut && ownBytes.get() > maxBytes) {
            cut(ownBytes.get() + " bytes are waiting for this client, more than the " + maxBytes + " it may have");
        }
    }

    private static void fail(ChannelPromise promise) {
        if (promise != null) {
            promise.tryFailure(new ClosedChannelException());
        }
    }

    /**
     * Hands queued pieces to the channel while it is writable, 64 KiB at most at a time, so that
     * little is ever in the channel's own buffer; called again when the channel turns writable.
     */
    void pump() {
        boolean wrote = false;
        while (!cut && channel.isWritable() && !queue.isEmpty()) {
            Piece piece = queue.peek();
            boolean whole = piece.bytes().readableBytes() <= SLICE;
            ByteBuf bytes = whole ? queue.poll().bytes() : piece.bytes().readRetainedSlice(SLICE);
            int size = bytes.readableBytes();
            boolean shared = piece.shared();
            inFlight.add(piece.queuedAt());
            ChannelPromise promise = whole ? piece.promise() : null;
            channel.write(bytes).addListener(done -> {
                written(shared, size);
                if (promise != null) {
                    if (done.isSuccess()) {
                        promise.trySuccess();
                    } else {
                        promise.tryFailure(done.cause());
                    }
                }
            });
            wrote = true;
        }
        if (wrote) {
            channel.flush();
        }
    }

    private void written(boolean shared, int size) {
        inFlight.poll();
        if (!shared) {
            count(-size);
        }
    }

    private void count(long bytes) {
        ownBytes.addAndGet(bytes);
        budget.add(bytes);
    }

    /** Cuts the client off if it has fallen behind by more than the grace. */
    private void check() {
        if (cut) {
            return;
        }
        Long oldest = inFlight.isEmpty() ? (queue.isEmpty() ? null : queue.peek().queuedAt()) : inFlight.peek();
        if (oldest != null) {
            long behind = nanoTime.getAsLong() - oldest;
            if (behind > graceNanos) {
                cut("this client has left what it was sent unread for " + behind / 1_000_000 + " ms, longer than the "
                        + graceNanos / 1_000_000 + " ms it may");
            }
        }
    }

    /** {@link #cut}, from any thread. */
    void cutSoon(String why) {
        channel.eventLoop().execute(() -> cut(why));
    }

    /**
     * Drops what waits, tells the simulation the client is gone and sends it a last error, which it
     * gets after what its socket already holds if it reads again within 5 s (or the grace, if longer);
     * the connection closes once the error is written, or after that time if it never is.
     */
    void cut(String why) {
        if (cut || !channel.isActive()) {
            return;
        }
        cut = true;
        drop();
        warnings.warn("cutting off {}: {}", who, why);
        onCut.run();
        // Straight to the channel, behind the little it holds: the outbox takes nothing more.
        channel.writeAndFlush(Unpooled.wrappedBuffer(CODEC.encodeLine(new ErrorMessage(0, ErrorCode.SLOW_CONSUMER,
                why + "; closing")))).addListener(ChannelFutureListener.CLOSE);
        long lastWords = Math.max(LAST_WORDS_NANOS, graceNanos);
        channel.eventLoop().schedule(() -> channel.close(), lastWords, TimeUnit.NANOSECONDS);
    }

    private void drop() {
        Piece piece;
        while ((piece = queue.poll()) != null) {
            if (!piece.shared()) {
                count(-piece.bytes().readableBytes());
            }
            piece.bytes().release();
            fail(piece.promise());
        }
    }

    private void closed() {
        watch.cancel(false);
        drop();
        budget.closed(this);
    }

    /** Whether the client was cut off. Safe from any thread. */
    boolean isCut() {
        return cut;
    }

    /** Bytes waiting for this client alone. Safe from any thread. */
    long ownBytes() {
        return ownBytes.get();
    }
}
