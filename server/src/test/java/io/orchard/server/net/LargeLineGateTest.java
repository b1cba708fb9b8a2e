package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.Unpooled;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelOutboundHandlerAdapter;
import io.netty.channel.embedded.EmbeddedChannel;
import io.orchard.protocol.MessageCodec;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/** The places for large lines, shared by embedded channels as they are by real ones. */
class LargeLineGateTest {

    private final LineSlots slots = new LineSlots(1);

    private EmbeddedChannel connect() {
        return new EmbeddedChannel(new LargeLineGate(slots));
    }

    private static void send(EmbeddedChannel channel, int bytes, boolean newline) {
        byte[] chunk = new byte[bytes + (newline ? 1 : 0)];
        Arrays.fill(chunk, (byte) 'x');
        if (newline) {
            chunk[bytes] = '\n';
        }
        channel.writeInbound(Unpooled.wrappedBuffer(chunk));
        ByteBuf passed = channel.readInbound();
        assertThat(passed.readableBytes()).as("bytes pass through").isEqualTo(chunk.length);
        passed.release();
    }

    @Test
    void ordinaryLinesNeedNoPlace() {
        EmbeddedChannel channel = connect();
        for (int i = 0; i < 10; i++) {
            send(channel, MessageCodec.MAX_LINE_BYTES, true);
        }
        assertThat(slots.taken()).isZero();
        assertThat(channel.config().isAutoRead()).isTrue();
    }

    @Test
    void aSecondLargeLineWaitsNotReadingUntilTheFirstEnds() {
        EmbeddedChannel first = connect();
        EmbeddedChannel second = connect();
        send(first, MessageCodec.MAX_LINE_BYTES + 1, false);
        assertThat(slots.taken()).isEqualTo(1);
        send(second, MessageCodec.MAX_LINE_BYTES + 1, false);
        assertThat(second.config().isAutoRead()).as("the second waits").isFalse();
        send(first, 10, true);
        second.runPendingTasks();
        assertThat(second.config().isAutoRead()).as("the place passed to the second").isTrue();
        assertThat(slots.taken()).isEqualTo(1);
        send(second, 10, true);
        assertThat(slots.taken()).isZero();
    }

    @Test
    void readsAskedForByLaterStagesAreHeldBackWhileItWaits() {
        AtomicInteger reads = new AtomicInteger();
        EmbeddedChannel first = connect();
        EmbeddedChannel second = new EmbeddedChannel(new ChannelOutboundHandlerAdapter() {
            @Override
            public void read(ChannelHandlerContext ctx) {
                reads.incrementAndGet();
                ctx.read();
            }
        }, new LargeLineGate(slots));
        send(first, MessageCodec.MAX_LINE_BYTES + 1, false);
        send(second, MessageCodec.MAX_LINE_BYTES + 1, false);
        reads.set(0);
        second.read(); // as the framer does when a read brought no whole line
        assertThat(reads).hasValue(0);
        send(first, 1, true);
        second.runPendingTasks();
        second.read();
        assertThat(reads.get()).isPositive();
    }

    @Test
    void aConnectionThatClosesGivesItsPlaceBackAndStopsWaiting() {
        EmbeddedChannel first = connect();
        EmbeddedChannel second = connect();
        EmbeddedChannel third = connect();
        send(first, MessageCodec.MAX_LINE_BYTES + 1, false);
        send(second, MessageCodec.MAX_LINE_BYTES + 1, false);
        send(third, MessageCodec.MAX_LINE_BYTES + 1, false);
        second.close();
        first.close();
        third.runPendingTasks();
        assertThat(third.config().isAutoRead()).isTrue();
        third.close();
        assertThat(slots.taken()).isZero();
    }
}
