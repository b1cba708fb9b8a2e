package io.orchard.server.net;

import io.netty.channel.Channel;
import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelPipeline;
import io.netty.channel.SimpleChannelInboundHandler;
import io.netty.handler.codec.TooLongFrameException;
import io.netty.handler.timeout.IdleStateEvent;
import io.netty.handler.timeout.IdleStateHandler;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.ProtocolVersion;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GameControlMessage;
import io.orchard.protocol.message.HelloMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.value.Role;
import io.orchard.server.sim.Inbox;
import java.io.IOException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The last stage of a connection: it holds the handshake, then hands every message to the
 * simulation's {@link Inbox}. Once a client is welcomed it drops the stage that waited for its
 * {@code Hello}, and for a viewer, which only listens, the idle timeout. A registration's model is
 * counted against the caps on models first ({@link ModelStore}) and handed on as the one copy the
 * server keeps. Only a client that presented the operator token in its hello may control the game:
 * anyone else's {@code GameControl} is refused here, at once, and never reaches the simulation.
 * One per channel (it holds the session, whether it is the operator's, and the connection's models).
 */
final class SessionHandler extends SimpleChannelInboundHandler<ClientMessage> {

    private static final Logger log = LoggerFactory.getLogger(SessionHandler.class);

    private final SessionContext shared;
    private final Inbox inbox;
    private final ConnectionModels models = new ConnectionModels();
    private Channel channel;
    private Outbox outbox;
    private NettySession session;
    private boolean operator;

    SessionHandler(SessionContext shared) {
        this.shared = shared;
        this.inbox = shared.inbox();
    }

    /**
     * Everything the server writes to the client goes through its outbox from the start, so that a
     * client that never reads cannot pile up even the errors its bad lines earn before its Hello.
     */
    @Override
    public void channelActive(ChannelHandlerContext ctx) {
        channel = ctx.channel();
        outbox = new Outbox(channel, this, shared.limits(), shared.budget(), () -> {
            if (session != null) {
                session.end("connection closed");
            }
        }, System::nanoTime);
        channel.attr(Outbox.KEY).set(outbox);
        ctx.fireChannelActive();
    }

    @Override
    protected void channelRead0(ChannelHandlerContext ctx, ClientMessage message) {
        if (session != null) {
            if (message instanceof HelloMessage) {
                ctx.writeAndFlush(new ErrorMessage(message.seq(), ErrorCode.INVALID_VALUE,
                        "Hello: the handshake is already done"));
            } else if (message instanceof GameControlMessage control && !operator) {
                ctx.writeAndFlush(notOperator(control));
            } else if (message instanceof RegisterMessage register && session.protocolVersion() < 2
                    && register.model() != null && register.model().forVersion1() != register.model()) {
                ctx.writeAndFlush(new ErrorMessage(register.seq(), ErrorCode.INVALID_VALUE, register.model().fit() != null
                        ? "model.fit is protocol version 2; this client speaks version 1"
                        : "model.format '" + register.model().format().wireName()
                                + "' is protocol version 2; this client speaks version 1"));
            } else if (message instanceof RegisterMessage register && session.role() == Role.AGENT
                    && register.model() != null && register.model().data() != null) {
                registerWithModel(ctx, register);
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
        if (shared.token() != null && !shared.token().matches(hello.token())) {
            refuse(ctx, hello, ErrorCode.UNAUTHORIZED, hello.token() == null
                    ? "this server requires a token in Hello" : "wrong token");
            return;
        }
        // Version 1 has no operator token: a field of that name from a version 1 client is not one.
        String offered = hello.protocolVersion() >= 2 ? hello.operatorToken() : null;
        if (offered != null && (shared.operator() == null || !shared.operator().matches(offered))) {
            refuse(ctx, hello, ErrorCode.UNAUTHORIZED, shared.operator() == null
                    ? "this server has no operator token: no client controls its game; connect without one"
                    : "wrong operator token");
            return;
        }
        operator = offered != null;
        ChannelPipeline pipeline = ctx.pipeline();
        if (pipeline.get(HelloDeadline.class) != null) {
            pipeline.remove(HelloDeadline.class);
        }
        if (hello.role() == Role.VIEWER && pipeline.get(IdleStateHandler.class) != null) {
            // A viewer only listens: silence is what it does, and what it fails to read is the outbox's care.
            pipeline.remove(IdleStateHandler.class);
        }
        long id = shared.sessionIds().incrementAndGet();
        session = new NettySession(id, hello.role(), hello.protocolVersion(), ClientForms.of(hello), ctx.channel(),
                shared, outbox);
        ctx.writeAndFlush(inbox.welcome(hello.seq(), hello.role(), hello.protocolVersion()));
        log.debug("{} connected as '{}'{}", session, hello.client(), operator ? ", the operator" : "");
        inbox.connected(session);
    }

    /** A registration carrying a model: the model is counted against the caps and handed on as the one copy kept. */
    private void registerWithModel(ChannelHandlerContext ctx, RegisterMessage register) {
        ModelStore.Admitted model = shared.models().admit(register.model(), models,
                shared.limits().modelBytesPerConnection());
        if (model.refusal() != null) {
            ctx.writeAndFlush(new ErrorMessage(register.seq(), ErrorCode.INVALID_VALUE, model.refusal()));
            return;
        }
        inbox.received(session, model.model() == register.model() ? register
                : new RegisterMessage(register.seq(), register.name(), register.body(), model.model(),
                        register.resumeToken()));
    }

    /**
     * The refusal of a game control from a client that is not the operator. Version 1 knows no
     * {@code forbidden}, and a client skips a value it does not know: it is told {@code wrong_role}.
     */
    private ErrorMessage notOperator(GameControlMessage control) {
        log.debug("{}: GameControl {} refused: not the operator", session, control.command().wireName());
        String text = "GameControl " + control.command().wireName() + " is the operator's: "
                + (shared.operator() == null
                        ? "this server has no operator token, so only its console and the program that embeds it"
                                + " control the game"
                        : session.protocolVersion() < 2
                                ? "it needs the operator token in Hello, which protocol version 1 has not"
                                : "it needs the server's operator token in Hello (operatorToken)");
        return new ErrorMessage(control.seq(), session.protocolVersion() < 2 ? ErrorCode.WRONG_ROLE
                : ErrorCode.FORBIDDEN, text);
    }

    private static void refuse(ChannelHandlerContext ctx, HelloMessage hello, ErrorCode code, String text) {
        ctx.writeAndFlush(new ErrorMessage(hello.seq(), code, text)).addListener(ChannelFutureListener.CLOSE);
    }

    @Override
    public void channelInactive(ChannelHandlerContext ctx) {
        if (session != null) {
            session.end("connection closed");
        }
        ctx.fireChannelInactive();
    }

    @Override
    public void channelWritabilityChanged(ChannelHandlerContext ctx) {
        if (outbox != null) {
            outbox.pump();
        }
        ctx.fireChannelWritabilityChanged();
    }

    @Override
    public void userEventTriggered(ChannelHandlerContext ctx, Object event) {
        if (event instanceof IdleStateEvent) {
            ctx.writeAndFlush(new ErrorMessage(0, ErrorCode.IDLE, "no message for "
                    + shared.limits().idleTimeout().toSeconds() + " s; closing")).addListener(ChannelFutureListener.CLOSE);
        } else {
            ctx.fireUserEventTriggered(event);
        }
    }

    @Override
    public String toString() {
        return session != null ? session.toString() : "client " + (channel == null ? "?" : channel.remoteAddress());
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
