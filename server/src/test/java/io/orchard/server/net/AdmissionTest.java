package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import io.netty.channel.embedded.EmbeddedChannel;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The connection cap, shared by embedded channels as it is shared by real ones. */
class AdmissionTest {

    private final Admission admission = new Admission(2);
    private final List<io.netty.channel.Channel> activated = new ArrayList<>();

    private EmbeddedChannel connect() {
        return new EmbeddedChannel(admission, new ChannelInboundHandlerAdapter() {
            @Override
            public void channelActive(ChannelHandlerContext ctx) {
                activated.add(ctx.channel());
            }
        });
    }

    @Test
    void theConnectionBeyondTheCapIsRefusedAndAPlaceFreesWhenOneCloses() {
        EmbeddedChannel first = connect();
        EmbeddedChannel second = connect();
        EmbeddedChannel third = connect();
        assertThat(activated).containsExactly(first, second);
        ErrorMessage error = third.readOutbound();
        assertThat(error.code()).isEqualTo(ErrorCode.TOO_MANY_AGENTS);
        assertThat(error.text()).contains("at most 2 connections");
        assertThat(third.isOpen()).isFalse();
        assertThat(admission.open()).isEqualTo(2);
        first.close();
        EmbeddedChannel fourth = connect();
        assertThat(activated).contains(fourth);
        assertThat(fourth.isOpen()).isTrue();
    }
}
