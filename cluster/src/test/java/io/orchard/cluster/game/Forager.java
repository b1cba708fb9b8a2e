package io.orchard.cluster.game;

import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.SayMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.SetRotationMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * A deterministic agent for tests: it decides from what it is sent alone, with random numbers drawn
 * from its name. It walks to the nearest fruit in view it can reach in height, turns to it and grasps
 * it; with none in view it wanders, now and then far (so that its paths leave its parcel's halo),
 * and now and then says where it is.
 */
final class Forager implements Player {

    final String name;
    final TestSession session;
    private final Body body;
    private final SplittableRandom random;
    private long seq;
    private Vec3 target;

    Forager(String name, TestSession session, double sight) {
        this.name = name;
        this.session = session;
        this.body = new Body(0.5, 1.2, 6, new Gripper("hands", 0.6, 0, 1.5), new Sight(sight, Math.PI * 1.2));
        this.random = new SplittableRandom(name.hashCode());
    }

    @Override
    public TestSession session() {
        return session;
    }

    @Override
    public List<ClientMessage> register() {
        return List.of(new RegisterMessage(++seq, name, body, null, null));
    }

    /** Its registration with the resume token of the agent of its name that left. */
    List<ClientMessage> resume(String token) {
        return List.of(new RegisterMessage(++seq, name, body, null, token));
    }

    /** After its registration: perceive every tick, and end the setup turn. */
    @Override
    public List<ClientMessage> setUp() {
        return setUpIn(0);
    }

    /** After its registration in a game under way: perceive every tick, and end the turn of {@code tick}. */
    List<ClientMessage> setUpIn(long tick) {
        List<ClientMessage> out = new ArrayList<>();
        List<ServerMessage> read = session.read();
        if (read.stream().noneMatch(RegisteredMessage.class::isInstance)) {
            throw new AssertionError(name + " was not registered: " + read);
        }
        out.add(new PerceptionRequestMessage(++seq, name, 1));
        out.add(new EndTurnMessage(++seq, tick));
        return out;
    }

    /** This tick's actions, from what it was sent since the last. */
    @Override
    public List<ClientMessage> act(long tick) {
        PerceptionMessage seen = null;
        for (ServerMessage message : session.read()) {
            if (message instanceof PerceptionMessage p && p.tick() == tick) {
                seen = p;
            }
        }
        List<ClientMessage> out = new ArrayList<>();
        if (seen != null) {
            decide(seen, out);
        }
        out.add(new EndTurnMessage(++seq, tick));
        return out;
    }

    private void decide(PerceptionMessage seen, List<ClientMessage> out) {
        Vec3 here = seen.position();
        PerceivedFruit nearest = null;
        for (PerceivedFruit fruit : seen.fruit()) {
            if (fruit.position().y() <= body.gripper().maxHeight() && (nearest == null
                    || here.groundDistance(fruit.position()) < here.groundDistance(nearest.position()))) {
                nearest = fruit;
            }
        }
        if (random.nextInt(200) == 0) {
            out.add(new SayMessage(++seq, name, "at " + Math.round(here.x()) + " " + Math.round(here.z())));
        }
        if (nearest != null) {
            double dx = nearest.position().x() - here.x();
            double dz = nearest.position().z() - here.z();
            double distance = Math.hypot(dx, dz);
            double facing = Math.atan2(-dx, -dz);
            if (Math.abs(Math.IEEEremainder(facing - seen.heading(), 2 * Math.PI)) > 0.02) {
                out.add(new SetRotationMessage(++seq, name, Rotation.heading(facing)));
            }
            double reach = body.radius() + body.gripper().reach();
            if (distance < reach) {
                out.add(new GraspRequestMessage(++seq, name, nearest.id()));
            } else {
                double k = (distance - reach + 0.2) / distance;
                out.add(new MoveMessage(++seq, name, here, Vec3.ground(here.x() + k * dx, here.z() + k * dz)));
            }
            target = null;
            return;
        }
        if (target == null || here.groundDistance(target) < 0.5 || random.nextInt(40) == 0) {
            double far = random.nextInt(8) == 0 ? 90 : 15;
            target = Vec3.ground(here.x() + (random.nextDouble() * 2 - 1) * far,
                    here.z() + (random.nextDouble() * 2 - 1) * far);
            out.add(new MoveMessage(++seq, name, here, target));
        }
    }
}
