package io.orchard.server.net;

import io.netty.buffer.ByteBuf;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelDuplexHandler;
import io.orchard.protocol.MessageCodec;

/**
 * Makes a line that grows past an ordinary message's length take one of the server's few places for
 * large lines ({@link LineSlots}) before more of it is read: without a place the connection stops
 * reading until one frees: it turns reading off and holds back the reads later stages ask for (the
 * framer asks for one whenever a read brought no whole line). It watches the raw bytes before
 * framing, so what a connection buffers without a place is an ordinary line and what one read
 * brings. One per channel (it holds the length of the line in progress and whether it has a place).
 */
final class LargeLineGate extends ChannelDuplexHandler implements LineSlots.Waiter {

    private final LineSlots slots;
    private ChannelHandlerContext ctx;
    /** Bytes of the line in progress so far. */
    private long lineBytes;
    private boolean holding;
    private boolean waiting;

    LargeLineGate(LineSlots slots) {
        this.slots = slots;
    }

    @Override
    public void handlerAdded(ChannelHandlerContext ctx) {
        this.ctx = ctx;
    }

    @Override
    public void channelRead(ChannelHandlerContext ctx, Object message) {
        if (message instanceof ByteBuf bytes && bytes.isReadable()) {
            int lastNewline = bytes.forEachByteDesc(b -> b != '\n');
            if (lastNewline >= 0) {
                release();
                lineBytes = bytes.writerIndex() - lastNewline - 1;
            } else {
                lineBytes += bytes.readableBytes();
            }
            if (lineBytes > MessageCodec.MAX_LINE_BYTES && !holding && !waiting) {
                if (slots.take(this)) {
                    holding = true;
                } else {
                    waiting = true;
                    ctx.channel().config().setAutoRead(false);
                }
            }
        }
        ctx.fireChannelRead(message);
    }

    @Override
    public void read(ChannelHandlerContext ctx) {
        if (!waiting) {
            ctx.read();
        }
    }

    @Override
    public void granted() {
        ctx.executor().execute(() -> {
            waiting = false;
            if (!ctx.channel().isActive()) {
                slots.give();
                return;
            }
            holding = true;
            ctx.channel().config().setAutoRead(true);
        });
    }

    private void release() {
        if (holding) {
            holding = false;
            slots.give();
        }
    }

    @Override
    public void handlerRemoved(ChannelHandlerContext ctx) {
        if (waiting) {
            slots.withdraw(this);
        }
        release();
    }
}
