package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import io.netty.channel.ChannelHandler.Sharable;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelOutboundHandlerAdapter;
import io.netty.channel.ChannelPromise;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ServerMessage;

/**
 * Encodes a {@code ServerMessage} as one line, on the channel's own I/O thread, so the tick thread
 * never pays for per-client encoding. Once the client is welcomed the line goes into its
 * {@link Outbox}, behind what already waits there, so that no line written by a stage of the
 * pipeline (an error, the welcome) can slip into the middle of one the outbox is writing. Buffers
 * (what the outbox writes) pass straight through. Stateless and shared.
 */
@Sharable
final class MessageEncoder extends ChannelOutboundHandlerAdapter {

    private final MessageCodec codec;

    MessageEncoder(MessageCodec codec) {
        this.codec = codec;
    }

    @Override
    public void write(ChannelHandlerContext ctx, Object message, ChannelPromise promise) {
        if (!(message instanceof ServerMessage server)) {
            ctx.write(message, promise);
            return;
        }
        ByteBuf line = encode(ctx, codec, server);
        Outbox outbox = ctx.channel().attr(Outbox.KEY).get();
        if (outbox != null) {
            outbox.add(line, false, promise);
        } else {
            ctx.write(line, promise);
        }
    }

    /** The message's line, newline included, in a buffer of the channel's allocator. */
    static ByteBuf encode(ChannelHandlerContext ctx, MessageCodec codec, ServerMessage message) {
        byte[] line = codec.encodeLine(message);
        return ctx.alloc().buffer(line.length).writeBytes(line);
    }
}
