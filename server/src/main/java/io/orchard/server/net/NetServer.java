package io.orchard.server.net;

import io.netty.bootstrap.ServerBootstrap;
import io.netty.channel.Channel;
import io.netty.channel.ChannelFuture;
import io.netty.channel.ChannelOption;
import io.netty.channel.EventLoopGroup;
import io.netty.channel.MultiThreadIoEventLoopGroup;
import io.netty.channel.WriteBufferWaterMark;
import io.netty.channel.nio.NioIoHandler;
import io.netty.channel.socket.nio.NioServerSocketChannel;
import io.netty.util.concurrent.DefaultThreadFactory;
import io.orchard.protocol.MessageCodec;
import io.orchard.server.sim.Inbox;
import java.io.IOException;
import java.net.BindException;
import java.net.InetSocketAddress;
import java.util.Locale;
import java.util.concurrent.TimeUnit;

/**
 * The TCP endpoint: binds, accepts, and shuts down leaving no thread behind. Everything a
 * connection does is in the pipeline {@link ServerInitializer} assembles.
 */
public final class NetServer implements AutoCloseable {

    /** The kernel's send buffer for each client, asked for: 256 KiB (Linux doubles it for its own bookkeeping). */
    static final int SEND_BUFFER_BYTES = 256 * 1024;

    private final EventLoopGroup boss;
    private final EventLoopGroup workers;
    private final Channel channel;

    private NetServer(EventLoopGroup boss, EventLoopGroup workers, Channel channel) {
        this.boss = boss;
        this.workers = workers;
        this.channel = channel;
    }

    /**
     * Binds and starts accepting clients.
     *
     * @param address where to listen (port 0 for any free port)
     * @param inbox   the simulation that receives what clients do
     * @param token   the shared secret clients must present, or null
     * @param operatorToken the secret that lets a client start, pause and resume the game, or null
     *                      when no client may
     * @param limits  per-connection limits
     * @throws IOException          when the address cannot be bound, saying why and what to do: the
     *                              port is taken, the address is not this machine's, the port is
     *                              privileged
     * @throws InterruptedException when interrupted while binding
     */
    public static NetServer start(InetSocketAddress address, Inbox inbox, String token, String operatorToken,
                                  NetLimits limits) throws IOException, InterruptedException {
        EventLoopGroup boss = new MultiThreadIoEventLoopGroup(1, new DefaultThreadFactory("orchard-accept", true),
                NioIoHandler.newFactory());
        // One I/O thread per core, not Netty's two: the tick thread needs a core of its own.
        EventLoopGroup workers = new MultiThreadIoEventLoopGroup(Runtime.getRuntime().availableProcessors(),
                new DefaultThreadFactory("orchard-io", true), NioIoHandler.newFactory());
        try {
            ChannelFuture bound = new ServerBootstrap()
                    .group(boss, workers)
                    .channel(NioServerSocketChannel.class)
                    .option(ChannelOption.SO_BACKLOG, 1024)
                    .childOption(ChannelOption.TCP_NODELAY, true)
                    .childOption(ChannelOption.WRITE_BUFFER_WATER_MARK, waterMark(limits))
                    // A fixed send buffer, not one the kernel grows to megabytes: what a client leaves
                    // unread then waits in its outbox, where the server sees how far behind it is.
                    .childOption(ChannelOption.SO_SNDBUF, SEND_BUFFER_BYTES)
                    .childHandler(new ServerInitializer(new MessageCodec(), inbox, token, operatorToken, limits))
                    .bind(address).await();
            if (!bound.isSuccess()) {
                throw cannotListen(address, bound.cause());
            }
            return new NetServer(boss, workers, bound.channel());
        } catch (IOException | InterruptedException | RuntimeException e) {
            boss.shutdownGracefully(0, 0, TimeUnit.SECONDS);
            workers.shutdownGracefully(0, 0, TimeUnit.SECONDS);
            throw e;
        }
    }

    /**
     * Why binding failed, in words: the JDK says only "Address already in use", naming neither the
     * port nor what to do about it.
     */
    static IOException cannotListen(InetSocketAddress address, Throwable cause) {
        String reason = String.valueOf(cause.getMessage()).toLowerCase(Locale.ROOT);
        String port = "port " + address.getPort();
        String message;
        if (address.isUnresolved()) {
            message = "cannot listen on '" + address.getHostString() + "': unknown host (expected an address of this"
                    + " machine, such as 127.0.0.1, or 0.0.0.0 for every interface)";
        } else if (reason.contains("already in use")) {
            message = "cannot listen on " + port + ": address already in use (is another server running? choose"
                    + " another with --port)";
        } else if (reason.contains("assign requested address")) {
            message = "cannot listen on " + address.getHostString() + ": it is not an address of this machine"
                    + " (choose one of its own with --bind, or 0.0.0.0 for every interface)";
        } else if (reason.contains("permission denied")) {
            message = "cannot listen on " + port + ": permission denied (ports below 1024 need privileges;"
                    + " choose another with --port)";
        } else {
            message = "cannot listen on " + address.getHostString() + " " + port + ": " + cause.getMessage();
        }
        BindException failure = new BindException(message);
        failure.initCause(cause);
        return failure;
    }

    /**
     * A channel turns unwritable once 256 KiB wait in it: what waits beyond waits in the client's
     * {@link Outbox}, where it is counted and can be dropped.
     */
    static WriteBufferWaterMark waterMark(NetLimits limits) {
        int high = (int) Math.min(256L << 10, limits.maxPendingBytes());
        return new WriteBufferWaterMark(high / 2, high);
    }

    /** The address and port the server listens on. */
    public InetSocketAddress address() {
        return (InetSocketAddress) channel.localAddress();
    }

    /** The port the server listens on. */
    public int port() {
        return ((InetSocketAddress) channel.localAddress()).getPort();
    }

    /** Stops accepting, closes every connection and waits until the I/O threads have ended. */
    @Override
    public void close() {
        channel.close().syncUninterruptibly();
        boss.shutdownGracefully(0, 2, TimeUnit.SECONDS).syncUninterruptibly();
        workers.shutdownGracefully(0, 2, TimeUnit.SECONDS).syncUninterruptibly();
    }
}
