package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.Unpooled;
import io.netty.channel.embedded.EmbeddedChannel;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/** The rate limit, on an embedded channel with a clock the test moves. */
class FloodGuardTest {

    private final AtomicLong now = new AtomicLong();
    private final EmbeddedChannel channel = new EmbeddedChannel(new FloodGuard(10, 20, now::get));

    private int passed(int lines) {
        return passed(channel, lines);
    }

    private static int passed(EmbeddedChannel channel, int lines) {
        int passed = 0;
        for (int i = 0; i < lines && channel.isOpen(); i++) {
            ByteBuf line = Unpooled.buffer(1).writeByte('x');
            channel.writeInbound(line);
            ByteBuf out = channel.readInbound();
            if (out != null) {
                passed++;
                out.release();
            }
        }
        return passed;
    }

    @Test
    void aBurstPassesAndTheRateRefillsIt() {
        assertThat(passed(20)).isEqualTo(20);
        now.addAndGet(1_000_000_000L);
        assertThat(passed(10)).isEqualTo(10);
        assertThat(channel.isOpen()).isTrue();
        assertThat((Object) channel.readOutbound()).isNull();
    }

    @Test
    void beyondTheRateTheClientGetsALastErrorAndIsCutOff() {
        assertThat(passed(25)).isEqualTo(20);
        ErrorMessage error = channel.readOutbound();
        assertThat(error.code()).isEqualTo(ErrorCode.RATE_LIMITED);
        assertThat(error.text()).contains("more than 10 messages per second (burst 20, and 100 more for each tick of a "
                + "lockstep game)");
        assertThat(channel.isOpen()).isFalse();
        assertThat((Object) channel.readOutbound()).as("one error, not one per dropped line").isNull();
    }

    @Test
    void eachTickOfALockstepGameLetsAClientSendAHundredLinesMoreWhateverTheTimeTaken() {
        AtomicLong ticks = new AtomicLong();
        EmbeddedChannel lockstep = new EmbeddedChannel(new FloodGuard(10, 200, now::get, ticks::get));
        int passed = 0;
        for (int tick = 0; tick < 50; tick++) { // 50 ticks in no time at all: far beyond 10 lines a second
            ticks.incrementAndGet();
            passed += passed(lockstep, FloodGuard.LINES_PER_LOCKSTEP_TICK);
        }
        assertThat(passed).isEqualTo(50 * FloodGuard.LINES_PER_LOCKSTEP_TICK);
        assertThat(lockstep.isOpen()).isTrue();
        // No tick passes, no time: what is left of the burst passes, then the guard trips.
        assertThat(passed(lockstep, 150)).isEqualTo(200 - FloodGuard.LINES_PER_LOCKSTEP_TICK);
        assertThat(lockstep.isOpen()).isFalse();
        ErrorMessage error = lockstep.readOutbound();
        assertThat(error.code()).isEqualTo(ErrorCode.RATE_LIMITED);
    }

    @Test
    void theLineThatTripsTheGuardIsReleased() {
        passed(20);
        ByteBuf extra = Unpooled.buffer(1).writeByte('x');
        channel.writeInbound(extra);
        assertThat(extra.refCnt()).isZero();
        assertThat(channel.isOpen()).isFalse();
    }
}
