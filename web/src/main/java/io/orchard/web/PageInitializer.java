package io.orchard.web;

import io.netty.channel.ChannelInitializer;
import io.netty.channel.ChannelPipeline;
import io.netty.channel.socket.SocketChannel;
import io.netty.handler.codec.http.HttpObjectAggregator;
import io.netty.handler.codec.http.HttpServerCodec;
import io.netty.handler.codec.http.websocketx.WebSocketDecoderConfig;
import io.netty.handler.codec.http.websocketx.WebSocketFrameAggregator;
import io.netty.handler.codec.http.websocketx.WebSocketServerProtocolConfig;
import io.netty.handler.codec.http.websocketx.WebSocketServerProtocolHandler;
import io.orchard.protocol.MessageCodec;
import java.net.InetSocketAddress;

/** Assembles a browser connection's pipeline, and does nothing else. */
final class PageInitializer extends ChannelInitializer<SocketChannel> {

    /** The WebSocket's path; every other path is a file of the site, or not found. */
    static final String SOCKET_PATH = "/socket";

    /** A request is a line and a few headers: no page sends a body. */
    private static final int MAX_REQUEST_BYTES = 16 * 1024;

    private final Site site;
    private final InetSocketAddress game;

    PageInitializer(Site site, InetSocketAddress game) {
        this.site = site;
        this.game = game;
    }

    @Override
    protected void initChannel(SocketChannel channel) {
        ChannelPipeline pipeline = channel.pipeline();
        pipeline.addLast("http", new HttpServerCodec(4096, 8192, 8192));
        pipeline.addLast("request", new HttpObjectAggregator(MAX_REQUEST_BYTES));
        pipeline.addLast("origin", new SameOrigin(SOCKET_PATH));
        pipeline.addLast("socket", new WebSocketServerProtocolHandler(WebSocketServerProtocolConfig.newBuilder()
                .websocketPath(SOCKET_PATH)
                .checkStartsWith(false)
                // The page is a viewer: it sends hellos, instructions and game control, never a model,
                // so a frame over the protocol's line limit is refused (close code 1009).
                .decoderConfig(WebSocketDecoderConfig.newBuilder()
                        .maxFramePayloadLength(MessageCodec.MAX_LINE_BYTES)
                        .allowExtensions(false)
                        .build())
                .build()));
        pipeline.addLast("message", new WebSocketFrameAggregator(MessageCodec.MAX_LINE_BYTES));
        pipeline.addLast("site", new SiteHandler(site));
        pipeline.addLast("relay", new Relay(game));
    }
}
