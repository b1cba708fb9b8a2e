package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.channel.embedded.EmbeddedChannel;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import java.time.Duration;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** The deadline for the Hello and the cap on connections waiting to send it, on embedded channels. */
class HelloDeadlineTest {

    private final HelloQueue queue = new HelloQueue(2);

    private EmbeddedChannel connect() {
        EmbeddedChannel channel = new EmbeddedChannel(new HelloDeadline(queue, Duration.ofSeconds(5)));
        channel.freezeTime();
        return channel;
    }

    private static void wait(EmbeddedChannel channel, int seconds) {
        channel.advanceTimeBy(seconds, TimeUnit.SECONDS);
        channel.runScheduledPendingTasks();
    }

    @Test
    void aConnectionThatSaysNothingIsToldWhyAndClosedAtTheDeadline() {
        EmbeddedChannel channel = connect();
        wait(channel, 4);
        assertThat(channel.isOpen()).isTrue();
        wait(channel, 1);
        ErrorMessage error = channel.readOutbound();
        assertThat(error.code()).isEqualTo(ErrorCode.IDLE);
        assertThat(error.text()).isEqualTo("no Hello within 5 s of connecting; closing");
        assertThat(channel.isOpen()).isFalse();
        assertThat(queue.size()).isZero();
    }

    @Test
    void aWelcomedConnectionLeavesTheQueueAndHasNoDeadline() {
        EmbeddedChannel channel = connect();
        channel.pipeline().remove(HelloDeadline.class); // what the session does when it welcomes the client
        assertThat(queue.size()).isZero();
        wait(channel, 60);
        assertThat(channel.isOpen()).isTrue();
        assertThat((Object) channel.readOutbound()).isNull();
    }

    @Test
    void beyondTheCapTheConnectionThatWaitedLongestIsPushedOut() {
        EmbeddedChannel first = connect();
        EmbeddedChannel second = connect();
        assertThat(first.isOpen()).isTrue();
        EmbeddedChannel third = connect();
        ErrorMessage error = first.readOutbound();
        assertThat(error.code()).isEqualTo(ErrorCode.TOO_MANY_AGENTS);
        assertThat(error.text()).contains("more than 2 connections are waiting to say Hello");
        assertThat(first.isOpen()).isFalse();
        assertThat(second.isOpen()).isTrue();
        assertThat(third.isOpen()).isTrue();
        assertThat(queue.size()).isEqualTo(2);
    }
}
