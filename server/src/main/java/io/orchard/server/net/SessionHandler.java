package io.orchard.server.net;

import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.SimpleChannelInboundHandler;
import io.netty.handler.codec.TooLongFrameException;
import io.netty.handler.timeout.IdleStateEvent;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.ProtocolVersion;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.HelloMessage;
import io.orchard.server.sim.Inbox;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The last stage of a connection: it holds the handshake, then hands every message to the
 * simulation's {@link Inbox}. One per channel (it holds the session).
 */
final class SessionHandler extends SimpleChannelInboundHandler<ClientMessage> {

    private static final Logger log = LoggerFactory.getLogger(SessionHandler.class);

    private final Inbox inbox;
    private final AtomicLong sessionIds;
    private final byte[] token;
    private final NetLimits limits;
    private final TickWrites writes;
    private NettySession session;

    SessionHandler(Inbox inbox, AtomicLong sessionIds, String token, NetLimits limits, TickWrites writes) {
        this.writes = writes;
        this.inbox = inbox;
        this.sessionIds = sessionIds;
        this.token = token == null ? null : token.getBytes(StandardCharsets.UTF_8);
        this.limits = limits;
    }

    @Override
    protected void channelRead0(ChannelHandlerContext ctx, ClientMessage message) {
        if (session != null) {
            if (message instanceof HelloMessage) {
                ctx.writeAndFlush(new ErrorMessage(message.seq(), ErrorCode.INVALID_VALUE,
                        "Hello: the handshake is already done"));
            } else {
                inbox.received(session, message);
            }
            return;
        }
        if (!(message instanceof HelloMessage hello)) {
            ctx.writeAndFlush(new ErrorMessage(message.seq(), ErrorCode.HANDSHAKE_REQUIRED,
                    "the first message must be Hello, was " + io.orchard.protocol.MessageTypes.nameOf(message.getClass())));
            return;
        }
        if (!ProtocolVersion.isSpoken(hello.protocolVersion())) {
            refuse(ctx, hello, ErrorCode.VERSION_MISMATCH, "server speaks protocol versions " + ProtocolVersion.OLDEST
                    + " to " + ProtocolVersion.CURRENT + ", client asked for " + hello.protocolVersion());
            return;
        }
        if (token != null && !tokenMatches(hello.token())) {
            refuse(ctx, hello, ErrorCode.UNAUTHORIZED, hello.token() == null
                    ? "this server requires a token in Hello" : "wrong token");
            return;
        }
        session = new NettySession(sessionIds.incrementAndGet(), hello.role(), hello.protocolVersion(),
                ctx.channel(), limits, writes);
        ctx.writeAndFlush(inbox.welcome(hello.seq(), hello.role()));
        log.debug("{} connected as '{}'", session, hello.client());
        inbox.connected(session);
    }

    private boolean tokenMatches(String offered) {
        // MessageDigest.isEqual takes time independent of where the bytes differ.
        return offered != null && MessageDigest.isEqual(token, offered.getBytes(StandardCharsets.UTF_8));
    }

    private static void refuse(ChannelHandlerContext ctx, HelloMessage hello, ErrorCode code, String text) {
        ctx.writeAndFlush(new ErrorMessage(hello.seq(), code, text)).addListener(ChannelFutureListener.CLOSE);
    }

    @Override
    public void channelInactive(ChannelHandlerContext ctx) {
        if (session != null) {
            inbox.disconnected(session, "connection closed");
        }
        ctx.fireChannelInactive();
    }

    @Override
    public void userEventTriggered(ChannelHandlerContext ctx, Object event) {
        if (event instanceof IdleStateEvent) {
            ctx.writeAndFlush(new ErrorMessage(0, ErrorCode.IDLE, "no message for "
                    + limits.idleTimeout().toSeconds() + " s; closing")).addListener(ChannelFutureListener.CLOSE);
        } else {
            ctx.fireUserEventTriggered(event);
        }
    }

    @Override
    public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
        if (cause instanceof TooLongFrameException) {
            ctx.writeAndFlush(new ErrorMessage(0, ErrorCode.LINE_TOO_LONG, "line longer than "
                    + MessageCodec.MAX_LARGE_LINE_BYTES + " bytes; closing"))
                    .addListener(ChannelFutureListener.CLOSE);
        } else if (cause instanceof IOException) {
            ctx.close();
        } else {
            log.warn("closing {} after an unexpected error", session == null ? ctx.channel() : session, cause);
            ctx.writeAndFlush(new ErrorMessage(0, ErrorCode.INTERNAL_ERROR, "server error; closing"))
                    .addListener(ChannelFutureListener.CLOSE);
        }
    }
}
