package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import io.netty.channel.ChannelHandler.Sharable;
import io.netty.channel.ChannelHandlerContext;
import io.netty.handler.codec.MessageToByteEncoder;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ServerMessage;

/**
 * Encodes a {@code ServerMessage} as one line on the channel's own I/O thread, so the tick thread
 * never pays for per-client encoding. Lines encoded once for a broadcast arrive as buffers and pass
 * straight through. Stateless and shared.
 */
@Sharable
final class MessageEncoder extends MessageToByteEncoder<ServerMessage> {

    private final MessageCodec codec;

    MessageEncoder(MessageCodec codec) {
        super(ServerMessage.class);
        this.codec = codec;
    }

    @Override
    protected void encode(ChannelHandlerContext ctx, ServerMessage message, ByteBuf out) {
        out.writeBytes(codec.encodeLine(message));
    }
}
