package io.orchard.examples.match;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * A TCP relay in front of a server that holds every chunk of bytes, in both directions, for a
 * random few milliseconds before passing it on: a slow, jittery network, so that clients' messages
 * arrive in other orders and at other times than they would on loopback. The delays of each
 * connection are drawn from the relay's seed and the connection's number.
 */
final class DelayingRelay implements AutoCloseable {

    private final ServerSocket listener;
    private final List<Socket> sockets = new CopyOnWriteArrayList<>();

    /** A relay to {@code port} on loopback, holding chunks up to {@code maxMillis}. */
    DelayingRelay(int port, long seed, int maxMillis) throws IOException {
        listener = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        Thread accepting = new Thread(() -> {
            int connection = 0;
            try {
                while (true) {
                    Socket client = listener.accept();
                    Socket server = new Socket(InetAddress.getLoopbackAddress(), port);
                    sockets.add(client);
                    sockets.add(server);
                    connection++;
                    pump(client, server, new Random(seed * 31 + connection * 2L), maxMillis);
                    pump(server, client, new Random(seed * 31 + connection * 2L + 1), maxMillis);
                }
            } catch (IOException e) {
                // closed
            }
        }, "relay-accept");
        accepting.setDaemon(true);
        accepting.start();
    }

    /** The port clients connect to. */
    int port() {
        return listener.getLocalPort();
    }

    private static void pump(Socket from, Socket to, Random delays, int maxMillis) {
        Thread thread = new Thread(() -> {
            byte[] buffer = new byte[16 * 1024];
            try (InputStream in = from.getInputStream(); OutputStream out = to.getOutputStream()) {
                int read;
                while ((read = in.read(buffer)) >= 0) {
                    Thread.sleep(delays.nextInt(maxMillis + 1));
                    out.write(buffer, 0, read);
                    out.flush();
                }
            } catch (IOException | InterruptedException e) {
                // one side closed
            } finally {
                close(from);
                close(to);
            }
        }, "relay-pump");
        thread.setDaemon(true);
        thread.start();
    }

    private static void close(Socket socket) {
        try {
            socket.close();
        } catch (IOException e) {
            // already closed
        }
    }

    @Override
    public void close() throws IOException {
        listener.close();
        sockets.forEach(DelayingRelay::close);
    }
}
