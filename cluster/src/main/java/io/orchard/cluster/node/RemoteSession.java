package io.orchard.cluster.node;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Role;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.EncodedLine;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.apache.pekko.actor.typed.ActorRef;

/**
 * A client connected to some node's gateway, as the tick sees it: what the game sends it is kept
 * and goes to its gateway, in one message, when the game flushes.
 */
final class RemoteSession implements ClientSession {

    private static final MessageCodec CODEC = new MessageCodec();

    private final long id;
    private final Role role;
    private final int version;
    private final ActorRef<GatewayCommand> gateway;
    private List<String> lines = new ArrayList<>();
    private volatile boolean open = true;

    RemoteSession(long id, Role role, int version, ActorRef<GatewayCommand> gateway) {
        this.id = id;
        this.role = role;
        this.version = version;
        this.gateway = gateway;
    }

    @Override
    public long id() {
        return id;
    }

    @Override
    public Role role() {
        return role;
    }

    @Override
    public int protocolVersion() {
        return version;
    }

    @Override
    public void send(ServerMessage message) {
        if (open) {
            lines.add(CODEC.encode(message));
        }
    }

    @Override
    public void send(EncodedLine line) {
        if (open) {
            // The line as encoded, once for every client, without its newline.
            byte[] bytes = line.bytes(CODEC::encodeLine);
            lines.add(new String(bytes, 0, bytes.length - 1, StandardCharsets.UTF_8));
        }
    }

    @Override
    public void flush() {
        if (!lines.isEmpty()) {
            gateway.tell(new GatewayCommand.Deliver(id, lines));
            lines = new ArrayList<>();
        }
    }

    @Override
    public void close(ErrorMessage last) {
        flush();
        gateway.tell(new GatewayCommand.Close(id, CODEC.encode(last)));
        open = false;
    }

    @Override
    public boolean isOpen() {
        return open;
    }

    /** The client's connection closed. */
    void gone() {
        open = false;
    }

    /** The gateway the client is connected to. */
    ActorRef<GatewayCommand> gateway() {
        return gateway;
    }
}
