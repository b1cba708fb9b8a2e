package io.orchard.cluster.game;

import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.List;

/**
 * A deterministic agent for tests that crowds with others: every 30 ticks it walks to a meeting
 * point, where it bumps into the others and stops, then back to where it started, and again.
 */
final class Crowder implements Player {

    private final String name;
    private final TestSession session;
    private final Vec3 meeting;
    private Vec3 home;
    private long seq;

    Crowder(String name, TestSession session, Vec3 meeting) {
        this.name = name;
        this.session = session;
        this.meeting = meeting;
    }

    @Override
    public TestSession session() {
        return session;
    }

    @Override
    public List<ClientMessage> register() {
        Body body = new Body(0.5, 1.2, 8, new Gripper("hands", 0.6, 0, 1.5), new Sight(20, Math.PI));
        return List.of(new RegisterMessage(++seq, name, body, null, null));
    }

    @Override
    public List<ClientMessage> setUp() {
        for (ServerMessage message : session.read()) {
            if (message instanceof RegisteredMessage registered) {
                home = registered.position();
            }
        }
        return List.of(new PerceptionRequestMessage(++seq, name, 10), new EndTurnMessage(++seq, 0));
    }

    @Override
    public List<ClientMessage> act(long tick) {
        session.read();
        List<ClientMessage> out = new ArrayList<>();
        if (tick % 30 == 0) {
            out.add(new MoveMessage(++seq, name, null, tick % 60 == 0 ? meeting : home));
        }
        out.add(new EndTurnMessage(++seq, tick));
        return out;
    }
}
