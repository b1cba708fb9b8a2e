package io.orchard.cluster.node;

import io.orchard.cluster.order.KeyedLine;
import io.orchard.cluster.order.LineKey;
import io.orchard.cluster.parcel.Parcel;
import io.orchard.cluster.parcel.ParcelGrid;
import io.orchard.cluster.parcel.ParcelId;
import io.orchard.cluster.parcel.PathQuery;
import io.orchard.server.sim.AgentHandover;
import io.orchard.server.sim.FirstContact;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.World;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.apache.pekko.actor.typed.ActorRefResolver;
import org.apache.pekko.actor.typed.Behavior;
import org.apache.pekko.actor.typed.javadsl.Behaviors;
import org.apache.pekko.cluster.sharding.typed.javadsl.EntityTypeKey;

/**
 * A parcel of the world as a Pekko sharded entity: Pekko places it on a node and routes the tick's
 * commands to it by its id ({@code "column,row"}); it holds a {@link Parcel} and answers each command
 * with what the parcel said. It is made, on the node that hosts it, from that node's copy of the
 * world (the static things are made from the seed on every node) with fruit of its own.
 */
public final class ParcelEntity {

    /** The type of the parcels' entities. */
    public static final EntityTypeKey<ParcelCommand> TYPE = EntityTypeKey.create(ParcelCommand.class, "Parcel");

    private ParcelEntity() {}

    /** The behaviour of the parcel named {@code entityId}. */
    public static Behavior<ParcelCommand> create(String entityId, ParcelGrid grid, World world,
                                                 SimulationConfig config) {
        return Behaviors.setup(context -> {
            Parcel parcel = new Parcel(ParcelId.parse(entityId), grid, world.withOwnFruit(), config);
            ActorRefResolver resolver = ActorRefResolver.get(context.getSystem());
            return Behaviors.receive(ParcelCommand.class)
                    .onAnyMessage(command -> {
                        ParcelReply reply = handle(parcel, command);
                        resolver.<ParcelReply>resolveActorRef(command.replyTo()).tell(reply);
                        return Behaviors.same();
                    })
                    .build();
        });
    }

    private static ParcelReply handle(Parcel parcel, ParcelCommand command) {
        if (command instanceof ParcelCommand.Own c) {
            parcel.own(c.agents());
        } else if (command instanceof ParcelCommand.Release c) {
            parcel.release(c.names());
        } else if (command instanceof ParcelCommand.Perceive c) {
            parcel.ghosts(c.ghosts());
            return new ParcelReply.Said(lines(parcel.perceive(c.tick(), c.time())));
        } else if (command instanceof ParcelCommand.FirstAlong c) {
            return new ParcelReply.Contacts(parcel.firstAlong(c.paths()));
        } else if (command instanceof ParcelCommand.Apply c) {
            Map<PathQuery, FirstContact> answers = new HashMap<>();
            c.answers().forEach(a -> answers.put(a.path(), a.contact()));
            List<KeyedLine> said = parcel.apply(c.tick(), c.time(), c.acts().stream().map(Wire.Act::act).toList(),
                    answers);
            return new ParcelReply.Applied(lines(said), parcel.takeClaims().stream().map(Wire.Grasp::of).toList(),
                    parcel.owned());
        } else if (command instanceof ParcelCommand.Grasp c) {
            Map<String, LineKey> first = new HashMap<>();
            c.firstClaims().forEach(f -> first.put(f.fruit(), f.key()));
            List<Parcel.Taken> taken = new ArrayList<>();
            List<KeyedLine> said = parcel.grasp(c.tick(), c.time(), c.claims().stream().map(Wire.Grasp::claimOf).toList(),
                    first::get, taken);
            return new ParcelReply.Grasped(lines(said), taken);
        } else if (command instanceof ParcelCommand.FruitTaken c) {
            parcel.fruitTaken(c.fruit());
        } else if (command instanceof ParcelCommand.Walk c) {
            parcel.ghosts(c.ghosts());
            List<AgentHandover> left = new ArrayList<>();
            return new ParcelReply.Walked(lines(parcel.walk(c.tick(), c.time(), left)), left, parcel.owned());
        } else if (command instanceof ParcelCommand.PutWalked c) {
            parcel.walked(c.agents());
        }
        return new ParcelReply.Done();
    }

    private static List<Wire.Line> lines(List<KeyedLine> said) {
        return said.stream().map(Wire.Line::of).toList();
    }
}
