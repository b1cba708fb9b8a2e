package io.orchard.web;

import io.netty.bootstrap.ServerBootstrap;
import io.netty.channel.Channel;
import io.netty.channel.ChannelFuture;
import io.netty.channel.ChannelOption;
import io.netty.channel.EventLoopGroup;
import io.netty.channel.MultiThreadIoEventLoopGroup;
import io.netty.channel.nio.NioIoHandler;
import io.netty.channel.socket.nio.NioServerSocketChannel;
import io.netty.util.concurrent.DefaultThreadFactory;
import io.orchard.server.WebFrontEnd;
import java.io.IOException;
import java.net.BindException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.concurrent.TimeUnit;

/** The HTTP port: binds, accepts, and shuts down leaving no thread behind. */
final class PageServer implements WebFrontEnd.Serving {

    private final EventLoopGroup group;
    private final Channel channel;

    private PageServer(EventLoopGroup group, Channel channel) {
        this.group = group;
        this.channel = channel;
    }

    static PageServer start(InetSocketAddress http, InetSocketAddress game, Site site) throws IOException {
        // One thread: a page's WebSocket only passes lines on, and the game's threads come first.
        EventLoopGroup group = new MultiThreadIoEventLoopGroup(1, new DefaultThreadFactory("orchard-web", true),
                NioIoHandler.newFactory());
        try {
            ChannelFuture bound = new ServerBootstrap()
                    .group(group)
                    .channel(NioServerSocketChannel.class)
                    .childOption(ChannelOption.TCP_NODELAY, true)
                    .childHandler(new PageInitializer(site, reachable(game)))
                    .bind(http).await();
            if (!bound.isSuccess()) {
                BindException failure = new BindException("cannot serve the browser viewer on " + http.getHostString()
                        + " port " + http.getPort() + ": " + bound.cause().getMessage()
                        + " (choose another with --http-port)");
                failure.initCause(bound.cause());
                throw failure;
            }
            return new PageServer(group, bound.channel());
        } catch (InterruptedException e) {
            group.shutdownGracefully(0, 0, TimeUnit.SECONDS);
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while binding HTTP port " + http.getPort(), e);
        } catch (IOException | RuntimeException e) {
            group.shutdownGracefully(0, 0, TimeUnit.SECONDS);
            throw e;
        }
    }

    /** Where this machine reaches the game server: a server on every interface is on loopback too. */
    static InetSocketAddress reachable(InetSocketAddress game) {
        return game.getAddress() != null && game.getAddress().isAnyLocalAddress()
                ? new InetSocketAddress(InetAddress.getLoopbackAddress(), game.getPort()) : game;
    }

    @Override
    public InetSocketAddress address() {
        return (InetSocketAddress) channel.localAddress();
    }

    @Override
    public void close() {
        channel.close().syncUninterruptibly();
        group.shutdownGracefully(0, 2, TimeUnit.SECONDS).syncUninterruptibly();
    }
}
