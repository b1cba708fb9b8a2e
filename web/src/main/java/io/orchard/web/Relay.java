package io.orchard.web;

import io.netty.bootstrap.Bootstrap;
import io.netty.buffer.ByteBuf;
import io.netty.channel.Channel;
import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import io.netty.channel.ChannelInitializer;
import io.netty.channel.ChannelOption;
import io.netty.channel.socket.SocketChannel;
import io.netty.channel.socket.nio.NioSocketChannel;
import io.netty.handler.codec.LineBasedFrameDecoder;
import io.netty.handler.codec.TooLongFrameException;
import io.netty.handler.codec.http.websocketx.CloseWebSocketFrame;
import io.netty.handler.codec.http.websocketx.TextWebSocketFrame;
import io.netty.handler.codec.http.websocketx.WebSocketCloseStatus;
import io.netty.handler.codec.http.websocketx.WebSocketServerProtocolHandler;
import io.netty.util.ReferenceCountUtil;
import io.orchard.protocol.MessageCodec;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.List;

/**
 * A browser's WebSocket, once open, relayed line for line to a connection of its own to the game
 * server: each text message the page sends is one line to the server, each line the server sends
 * one text message to the page. The server sees an ordinary client, and treats it as one: its hello,
 * its limits, its token; a browser that reads too slowly stops this relay reading, and the server
 * then cuts it off as it does any slow client.
 */
final class Relay extends ChannelInboundHandlerAdapter {

    private static final byte NEWLINE = '\n';

    private final InetSocketAddress game;
    /** Lines the page sent while the server's connection was being opened: a read already under way. */
    private final List<ByteBuf> early = new ArrayList<>();
    private Channel server;

    Relay(InetSocketAddress game) {
        this.game = game;
    }

    @Override
    public void userEventTriggered(ChannelHandlerContext context, Object event) throws Exception {
        if (event instanceof WebSocketServerProtocolHandler.HandshakeComplete) {
            connect(context.channel());
        }
        super.userEventTriggered(context, event);
    }

    private void connect(Channel browser) {
        // What the page sends before the server's connection is open waits in the browser's socket.
        browser.config().setAutoRead(false);
        new Bootstrap()
                .group(browser.eventLoop())
                .channel(NioSocketChannel.class)
                .option(ChannelOption.TCP_NODELAY, true)
                .handler(new ChannelInitializer<SocketChannel>() {
                    @Override
                    protected void initChannel(SocketChannel channel) {
                        channel.pipeline().addLast("frame",
                                new LineBasedFrameDecoder(MessageCodec.MAX_LARGE_LINE_BYTES + 1, true, true));
                        channel.pipeline().addLast("page", new ToPage(browser));
                    }
                })
                .connect(game)
                .addListener((ChannelFutureListener) connected -> {
                    if (connected.isSuccess()) {
                        server = connected.channel();
                        early.forEach(server::write);
                        early.clear();
                        server.flush();
                        server.closeFuture().addListener(closed -> closeBrowser(browser));
                        browser.config().setAutoRead(true);
                    } else {
                        early.forEach(ByteBuf::release);
                        early.clear();
                        browser.writeAndFlush(new CloseWebSocketFrame(WebSocketCloseStatus.ENDPOINT_UNAVAILABLE,
                                "the game server cannot be reached")).addListener(ChannelFutureListener.CLOSE);
                    }
                });
    }

    @Override
    public void channelRead(ChannelHandlerContext context, Object message) {
        if (!(message instanceof TextWebSocketFrame frame)) {
            // Binary frames mean nothing in a protocol of text lines.
            ReferenceCountUtil.release(message);
            return;
        }
        ByteBuf line = frame.content();
        if (line.indexOf(line.readerIndex(), line.writerIndex(), NEWLINE) >= 0) {
            // One message, one line: a newline inside would smuggle in a second.
            frame.release();
            context.writeAndFlush(new CloseWebSocketFrame(WebSocketCloseStatus.INVALID_PAYLOAD_DATA,
                    "a message must be one line, without a newline")).addListener(ChannelFutureListener.CLOSE);
            return;
        }
        ByteBuf out = context.alloc().buffer(line.readableBytes() + 1);
        out.writeBytes(line).writeByte(NEWLINE);
        frame.release();
        if (server == null) {
            early.add(out);
        } else {
            server.writeAndFlush(out);
        }
    }

    @Override
    public void channelWritabilityChanged(ChannelHandlerContext context) {
        // A browser behind on reading stops the reading from the server, whose outbox then fills.
        if (server != null) {
            server.config().setAutoRead(context.channel().isWritable());
        }
        context.fireChannelWritabilityChanged();
    }

    @Override
    public void channelInactive(ChannelHandlerContext context) {
        early.forEach(ByteBuf::release);
        early.clear();
        if (server != null) {
            server.close();
        }
        context.fireChannelInactive();
    }

    @Override
    public void exceptionCaught(ChannelHandlerContext context, Throwable cause) {
        if (cause instanceof TooLongFrameException) {
            // A message sent in fragments that together pass the line limit.
            context.writeAndFlush(new CloseWebSocketFrame(WebSocketCloseStatus.MESSAGE_TOO_BIG, "a message must be"
                    + " at most " + MessageCodec.MAX_LINE_BYTES + " bytes")).addListener(ChannelFutureListener.CLOSE);
        } else {
            context.close();
        }
    }

    private static void closeBrowser(Channel browser) {
        if (browser.isActive()) {
            browser.writeAndFlush(new CloseWebSocketFrame(WebSocketCloseStatus.NORMAL_CLOSURE, "the server closed"
                    + " the connection")).addListener(ChannelFutureListener.CLOSE);
        }
    }

    /** The server's lines, each a text message to the page. */
    private static final class ToPage extends ChannelInboundHandlerAdapter {

        private final Channel browser;

        ToPage(Channel browser) {
            this.browser = browser;
        }

        @Override
        public void channelRead(ChannelHandlerContext context, Object message) {
            ByteBuf line = (ByteBuf) message;
            if (!browser.isActive()) {
                line.release();
                return;
            }
            browser.write(new TextWebSocketFrame(line));
        }

        @Override
        public void channelReadComplete(ChannelHandlerContext context) {
            browser.flush();
            context.channel().config().setAutoRead(browser.isWritable());
        }

        @Override
        public void exceptionCaught(ChannelHandlerContext context, Throwable cause) {
            context.close();
        }
    }
}
