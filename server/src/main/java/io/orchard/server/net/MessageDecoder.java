package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufUtil;
import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelHandler.Sharable;
import io.netty.channel.ChannelHandlerContext;
import io.netty.handler.codec.MessageToMessageDecoder;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.ProtocolException;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.value.Checks;
import java.util.List;

/**
 * Turns one framed line into a {@code ClientMessage}. A line that does not decode is answered with
 * an {@link ErrorMessage} naming the problem and dropped; the connection stays open, except for a
 * line that is too long, after which it closes. The most common lines are read without the
 * codec's mapper when they come in their plain form ({@link FastMoves}). Stateless, so one instance serves every channel.
 */
@Sharable
final class MessageDecoder extends MessageToMessageDecoder<ByteBuf> {

    private final MessageCodec codec;

    MessageDecoder(MessageCodec codec) {
        super(ByteBuf.class);
        this.codec = codec;
    }

    /**
     * The problem as an error may carry it: the codec quotes what it could not read, which a hostile
     * line can make longer than an error's text may be.
     */
    static String shorten(String problem) {
        return problem.length() <= Checks.MAX_TEXT ? problem : problem.substring(0, Checks.MAX_TEXT - 3) + "...";
    }

    @Override
    protected void decode(ChannelHandlerContext ctx, ByteBuf frame, List<Object> out) {
        byte[] line = ByteBufUtil.getBytes(frame);
        int length = line.length;
        while (length > 0 && (line[length - 1] == '\n' || line[length - 1] == '\r')) {
            length--;
        }
        ClientMessage plain = FastMoves.read(line, length);
        if (plain != null) {
            out.add(plain);
            return;
        }
        try {
            out.add(codec.decodeClient(line));
        } catch (ProtocolException e) {
            ErrorMessage error = new ErrorMessage(e.seq(), e.code(), shorten(e.getMessage()));
            if (e.code() == ErrorCode.LINE_TOO_LONG) {
                ctx.writeAndFlush(error).addListener(ChannelFutureListener.CLOSE);
            } else {
                ctx.writeAndFlush(error);
            }
        }
    }
}
