package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.Unpooled;
import io.netty.channel.embedded.EmbeddedChannel;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * A client's queue of output and the rules that cut it off, on embedded channels: one that writes
 * at once, or one made unwritable, as a socket the client does not read from is.
 */
class OutboxTest {

    private static final MessageCodec CODEC = new MessageCodec();

    private final NetLimits limits = NetLimits.DEFAULT.withSlowConsumers(Duration.ofSeconds(2), 4096, 8192);
    private final OutputBudget budget = new OutputBudget(limits.maxPendingBytesInAll());
    private final AtomicInteger cuts = new AtomicInteger();
    private final AtomicLong now = new AtomicLong(1_000_000_000L);
    private EmbeddedChannel channel;
    private Outbox outbox;

    @BeforeEach
    void setUp() {
        channel = new EmbeddedChannel();
        channel.freezeTime();
        outbox = outbox(channel, cuts::incrementAndGet);
    }

    private Outbox outbox(EmbeddedChannel on, Runnable onCut) {
        return new Outbox(on, "test client", limits, budget, onCut, now::get);
    }

    /** The socket takes nothing more, as when the client stops reading. */
    private static void stopReading(EmbeddedChannel on) {
        on.unsafe().outboundBuffer().setUserDefinedWritability(1, false);
    }

    private static ByteBuf bytes(String text) {
        return Unpooled.copiedBuffer(text, StandardCharsets.US_ASCII);
    }

    private String written() {
        StringBuilder text = new StringBuilder();
        ByteBuf out;
        while ((out = channel.readOutbound()) != null) {
            text.append(out.toString(StandardCharsets.UTF_8));
            out.release();
        }
        return text.toString();
    }

    private void wait(int millis) {
        now.addAndGet(TimeUnit.MILLISECONDS.toNanos(millis));
        channel.advanceTimeBy(millis, TimeUnit.MILLISECONDS);
        channel.runScheduledPendingTasks();
    }

    @Test
    void whatTheSocketTakesIsWrittenInOrderAndCountsNoLonger() {
        outbox.add(bytes("one\n"), false);
        outbox.add(bytes("two\n"), true);
        outbox.add(bytes("three\n"), false);
        assertThat(written()).isEqualTo("one\ntwo\nthree\n");
        assertThat(outbox.ownBytes()).isZero();
        assertThat(budget.total()).isZero();
        wait(60_000);
        assertThat(cuts).hasValue(0);
        assertThat(channel.isOpen()).isTrue();
    }

    @Test
    void aLargePieceIsHandedOverInSlicesAsTheSocketTakesThem() {
        outbox.add(Unpooled.wrappedBuffer(new byte[200 * 1024]), true);
        int slices = 0;
        int bytes = 0;
        for (int round = 0; round < 10; round++) {
            ByteBuf out;
            while ((out = channel.readOutbound()) != null) {
                assertThat(out.readableBytes()).isLessThanOrEqualTo(64 * 1024);
                bytes += out.readableBytes();
                out.release();
                slices++;
            }
            outbox.pump(); // what the channel turning writable again does
        }
        assertThat(bytes).isEqualTo(200 * 1024);
        assertThat(slices).isEqualTo(4);
    }

    @Test
    void whatWaitsGoesOutWhenTheSocketTakesMoreAgain() {
        stopReading(channel);
        outbox.add(bytes("one\n"), false);
        assertThat(written()).isEmpty();
        assertThat(outbox.ownBytes()).isEqualTo(4);
        channel.unsafe().outboundBuffer().setUserDefinedWritability(1, true);
        outbox.pump();
        assertThat(written()).isEqualTo("one\n");
        assertThat(outbox.ownBytes()).isZero();
    }

    @Test
    void aClientWithMoreThanItsCapWaitingIsCutOffWithAnError() {
        stopReading(channel);
        outbox.add(bytes("x".repeat(1000)), false);
        outbox.add(bytes("y".repeat(5000)), true); // a shared model does not count
        assertThat(outbox.isCut()).isFalse();
        outbox.add(bytes("z".repeat(5000)), false);
        assertThat(outbox.isCut()).isTrue();
        assertThat(cuts).hasValue(1);
        ErrorMessage error = (ErrorMessage) CODEC.decode(written());
        assertThat(error.code()).isEqualTo(ErrorCode.SLOW_CONSUMER);
        assertThat(error.text()).isEqualTo("6000 bytes are waiting for this client, more than the 4096 it may have;"
                + " closing");
        assertThat(channel.isOpen()).isFalse();
        assertThat(budget.total()).isZero();
    }

    @Test
    void aClientThatLeavesItsOutputUnreadLongerThanTheGraceIsCutOff() {
        stopReading(channel);
        outbox.add(bytes("first\n"), false);
        wait(1000);
        outbox.add(bytes("second\n"), false);
        wait(1000);
        assertThat(outbox.isCut()).as("the first line has waited 2 s, no longer than the grace").isFalse();
        wait(500);
        assertThat(outbox.isCut()).isTrue();
        assertThat(cuts).hasValue(1);
        assertThat(written()).contains("slow_consumer").contains("unread for 2500 ms, longer than the 2000 ms it may");
    }

    @Test
    void whenAllClientsTogetherHaveTooMuchWaitingTheOneWithTheMostIsCutOff() {
        EmbeddedChannel second = new EmbeddedChannel();
        EmbeddedChannel third = new EmbeddedChannel();
        AtomicInteger othersCut = new AtomicInteger();
        Outbox secondBox = outbox(second, othersCut::incrementAndGet);
        Outbox thirdBox = outbox(third, othersCut::incrementAndGet);
        stopReading(channel);
        stopReading(second);
        stopReading(third);
        outbox.add(bytes("x".repeat(4090)), false);
        secondBox.add(bytes("y".repeat(3000)), false);
        assertThat(budget.total()).isEqualTo(7090);
        thirdBox.add(bytes("z".repeat(1200)), false); // 8,290 in all, beyond the 8,192 of the budget
        channel.runPendingTasks();
        assertThat(cuts).as("the client with the most waiting").hasValue(1);
        assertThat(othersCut).hasValue(0);
        assertThat(budget.total()).isEqualTo(4200);
        assertThat(written()).contains("the server has 8290 bytes waiting for its clients, more than the 8192 it keeps,"
                + " and this client has the most waiting: 4090");
    }

    @Test
    void aMessageWrittenThroughThePipelineWaitsItsTurnAndItsPromiseIsKept() {
        channel.pipeline().addFirst(new MessageEncoder(CODEC));
        channel.attr(Outbox.KEY).set(outbox);
        stopReading(channel);
        outbox.add(bytes("before\n"), false);
        var future = channel.writeAndFlush(new ErrorMessage(3, ErrorCode.INVALID_VALUE, "late"));
        assertThat(future.isDone()).isFalse();
        channel.unsafe().outboundBuffer().setUserDefinedWritability(1, true);
        outbox.pump();
        assertThat(written()).startsWith("before\n{\"type\":\"Error\",\"seq\":3");
        assertThat(future.isSuccess()).isTrue();
    }
}
