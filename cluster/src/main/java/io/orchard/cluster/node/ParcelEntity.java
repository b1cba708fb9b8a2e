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
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import org.apache.pekko.actor.typed.ActorRef;
import org.apache.pekko.actor.typed.ActorRefResolver;
import org.apache.pekko.actor.typed.Behavior;
import org.apache.pekko.actor.typed.javadsl.ActorContext;
import org.apache.pekko.actor.typed.javadsl.Behaviors;
import org.apache.pekko.actor.typed.javadsl.StashBuffer;
import org.apache.pekko.cluster.sharding.typed.javadsl.EntityTypeKey;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A parcel of the world as a Pekko sharded entity: Pekko places it on a node and routes the tick's
 * commands to it by its id ({@code "column,row"}); it holds a {@link Parcel} and answers each command
 * with what the parcel said. It is made, on the node that hosts it, from that node's copy of the
 * world (the static things are made from the seed on every node) with fruit of its own.
 *
 * <p>When its node leaves, Pekko hands the parcel to another node: it gives what it holds to the
 * keeper (the tick, {@link TickSingleton}) and stops; started again elsewhere, it first asks the
 * keeper for that, and answers nothing until it has it. So a node may leave in the middle of a tick
 * and nothing of the game is lost. Its last step's answer moves with it: a step the tick asks again
 * (its command lost in the move) is answered, not done twice.
 */
public final class ParcelEntity {

    /** The type of the parcels' entities. */
    public static final EntityTypeKey<ParcelCommand> TYPE = EntityTypeKey.create(ParcelCommand.class, "Parcel");

    private static final Logger log = LoggerFactory.getLogger(ParcelEntity.class);

    /** The most commands a parcel keeps while it waits for its state. */
    private static final int STASH = 10_000;

    private final String id;
    private final ParcelGrid grid;
    private final World world;
    private final SimulationConfig config;
    private final ActorRef<TickCommand> keeper;
    private final ActorContext<ParcelCommand> context;
    private final ActorRefResolver resolver;
    private Parcel parcel;
    /** The number of the last step done, 0 for none, and its answer. */
    private long lastStep;
    private ParcelReply lastReply;

    private ParcelEntity(String id, ParcelGrid grid, World world, SimulationConfig config,
                         ActorRef<TickCommand> keeper, ActorContext<ParcelCommand> context) {
        this.id = id;
        this.grid = grid;
        this.world = world;
        this.config = config;
        this.keeper = keeper;
        this.context = context;
        this.resolver = ActorRefResolver.get(context.getSystem());
        this.parcel = fresh();
    }

    /**
     * The behaviour of the parcel named {@code entityId}, whose state the {@code keeper} keeps while
     * it moves between nodes (null: it never moves with its state, for a cluster without a tick).
     */
    public static Behavior<ParcelCommand> create(String entityId, ParcelGrid grid, World world,
                                                 SimulationConfig config, ActorRef<TickCommand> keeper) {
        return Behaviors.withStash(STASH, stash -> Behaviors.setup(context -> {
            ParcelEntity entity = new ParcelEntity(entityId, grid, world, config, keeper, context);
            if (keeper == null) {
                return entity.serving();
            }
            keeper.tell(new TickCommand.Restore(entityId, entity.self()));
            return entity.starting(stash);
        }));
    }

    private Parcel fresh() {
        return new Parcel(ParcelId.parse(id), grid, world.withOwnFruit(), config);
    }

    private String self() {
        return resolver.toSerializationFormat(context.getSelf());
    }

    /** Waiting for what the keeper kept of this parcel; every command waits with it. */
    private Behavior<ParcelCommand> starting(StashBuffer<ParcelCommand> stash) {
        return Behaviors.receive(ParcelCommand.class)
                .onMessage(ParcelCommand.Restored.class, restored -> {
                    if (restored.state() != null) {
                        parcel.restore(restored.state());
                        lastStep = restored.lastStep();
                        lastReply = restored.lastReply();
                        log.info("parcel {} taken up here with {} agents of its own", id,
                                restored.state().own().size());
                    }
                    return stash.unstashAll(serving());
                })
                .onAnyMessage(command -> {
                    stash.stash(command);
                    return Behaviors.same();
                })
                .build();
    }

    private Behavior<ParcelCommand> serving() {
        return Behaviors.receive(ParcelCommand.class)
                .onMessage(ParcelCommand.HandOff.class, handOff -> {
                    if (keeper == null) {
                        return Behaviors.stopped();
                    }
                    keeper.tell(new TickCommand.Keep(id, parcel.state(), lastStep, lastReply, self()));
                    return Behaviors.receive(ParcelCommand.class)
                            .onMessage(ParcelCommand.Kept.class, kept -> Behaviors.stopped())
                            .build();
                })
                .onMessage(ParcelCommand.Step.class, step -> {
                    if (step.number() != lastStep || lastReply == null) {
                        lastReply = handle(step.command());
                        lastStep = step.number();
                    }
                    resolver.<ParcelReply>resolveActorRef(step.replyTo()).tell(lastReply);
                    return Behaviors.same();
                })
                .onAnyMessage(command -> {
                    if (command.replyTo() != null) { // a keeper's late answer needs none
                        ParcelReply reply = handle(command);
                        resolver.<ParcelReply>resolveActorRef(command.replyTo()).tell(reply);
                    }
                    return Behaviors.same();
                })
                .build();
    }

    private ParcelReply handle(ParcelCommand command) {
        if (command instanceof ParcelCommand.Own c) {
            parcel.own(c.agents());
        } else if (command instanceof ParcelCommand.Release c) {
            return new ParcelReply.Released(parcel.release(c.names()));
        } else if (command instanceof ParcelCommand.AddGhosts c) {
            parcel.addGhosts(c.ghosts());
        } else if (command instanceof ParcelCommand.ForgetGhosts c) {
            parcel.forgetGhosts(c.names());
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
                    parcel.owned(), parcel.takeRemoved());
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
        } else if (command instanceof ParcelCommand.Reset c) {
            parcel = fresh();
            parcel.keepOnly(new HashSet<>(c.fruitLeft()));
        }
        return new ParcelReply.Done();
    }

    private static List<Wire.Line> lines(List<KeyedLine> said) {
        return said.stream().map(Wire.Line::of).toList();
    }
}
