package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.Unpooled;
import io.netty.channel.embedded.EmbeddedChannel;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The slow-loris guard, on an embedded channel with a clock the test moves. */
class LineDeadlineTest {

    private final AtomicLong now = new AtomicLong(1_000_000_000L);
    private EmbeddedChannel channel;

    @BeforeEach
    void setUp() {
        channel = new EmbeddedChannel(new LineDeadline(Duration.ofSeconds(10), now::get));
        channel.freezeTime();
    }

    private void send(String text) {
        channel.writeInbound(Unpooled.copiedBuffer(text, StandardCharsets.UTF_8));
        ByteBuf passed = channel.readInbound();
        assertThat(passed.toString(StandardCharsets.UTF_8)).as("bytes pass through unchanged").isEqualTo(text);
        passed.release();
    }

    private void wait(int seconds) {
        now.addAndGet(TimeUnit.SECONDS.toNanos(seconds));
        channel.advanceTimeBy(seconds, TimeUnit.SECONDS);
        channel.runScheduledPendingTasks();
    }

    @Test
    void aLineTrickledForLongerThanTheDeadlineClosesTheConnection() {
        send("{\"type\":");
        wait(6);
        send("\"Hel");
        assertThat(channel.isOpen()).isTrue();
        wait(5);
        ErrorMessage error = channel.readOutbound();
        assertThat(error.code()).isEqualTo(ErrorCode.IDLE);
        assertThat(error.text()).contains("unfinished for 10 s");
        assertThat(channel.isOpen()).isFalse();
    }

    @Test
    void linesThatEndInTimeKeepTheConnectionOpenHoweverLongItLasts() {
        for (int i = 0; i < 5; i++) {
            send("{\"type\":\"EndTurn\",");
            wait(8);
            send("\"seq\":1,\"tick\":0}\n");
            wait(8);
        }
        assertThat(channel.isOpen()).isTrue();
        assertThat((Object) channel.readOutbound()).isNull();
    }

    @Test
    void theClockOfALineStartsWithItsFirstByteEvenWhenThePreviousLineEndedInTheSameChunk() {
        send("{\"a\":1}\n{\"b\":");
        wait(9);
        send("2}\n{\"c\"");
        wait(9);
        assertThat(channel.isOpen()).as("the third line began 9 s ago").isTrue();
        wait(2);
        assertThat(channel.isOpen()).isFalse();
    }

    @Test
    void silenceBetweenLinesIsNotAnUnfinishedLine() {
        send("{\"a\":1}\n");
        wait(60);
        assertThat(channel.isOpen()).isTrue();
        assertThat(channel.finish()).isFalse();
    }
}
