package io.orchard.cluster.node;

import io.orchard.cluster.game.FirstContacts;
import io.orchard.cluster.game.ParcelLost;
import io.orchard.cluster.game.Parcels;
import io.orchard.cluster.order.KeyedLine;
import io.orchard.cluster.order.LineKey;
import io.orchard.cluster.parcel.OwnedAgent;
import io.orchard.cluster.parcel.Parcel;
import io.orchard.cluster.parcel.ParcelGrid;
import io.orchard.cluster.parcel.ParcelId;
import io.orchard.cluster.parcel.PathQuery;
import io.orchard.server.sim.AgentHandover;
import io.orchard.server.sim.FirstContact;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.World;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.BiFunction;
import java.util.function.Function;
import org.apache.pekko.actor.typed.ActorRef;
import org.apache.pekko.actor.typed.ActorRefResolver;
import org.apache.pekko.actor.typed.ActorSystem;
import org.apache.pekko.cluster.sharding.typed.javadsl.ClusterSharding;
import org.apache.pekko.cluster.sharding.typed.javadsl.Entity;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The parcels of a split game as Pekko sharded entities ({@link ParcelEntity}), wherever the cluster
 * places them: each step of the tick asks every parcel concerned at once and waits for all their
 * answers. Only parcels with agents of their own are asked to perceive and walk, with their ghosts.
 */
public final class ShardedParcels implements Parcels {

    /** How long a step waits for a parcel's answer before the tick fails. */
    static final Duration STEP_TIMEOUT = Duration.ofSeconds(30);
    /**
     * How long a step waits for a parcel's answer before asking again: a command buffered for a
     * parcel that moves between nodes is dropped by Pekko, and only asking again brings the answer.
     */
    static final Duration ASK_AGAIN = Duration.ofSeconds(2);

    private static final Logger log = LoggerFactory.getLogger(ShardedParcels.class);

    private final ClusterSharding sharding;
    private final ActorRefResolver resolver;
    private final ParcelGrid grid;
    /**
     * The last step's number. It starts anywhere, so that a tick started again on another node does
     * not number a step as one a parcel already did.
     */
    private final AtomicLong steps = new AtomicLong(ThreadLocalRandom.current().nextLong());
    private final AtomicLong askedAgain = new AtomicLong();
    /** Fails every step under way at once when the game is rolled back: a parcel may never answer. */
    private volatile CompletableFuture<Object> aborted = new CompletableFuture<>();

    /** The parcels of {@code grid}, reached from this node of {@code system}'s cluster. */
    public ShardedParcels(ActorSystem<?> system, ParcelGrid grid) {
        this.sharding = ClusterSharding.get(system);
        this.resolver = ActorRefResolver.get(system);
        this.grid = grid;
    }

    /**
     * Hosts parcels on this node of {@code system}'s cluster, each made from this node's
     * {@code world} (the same on every node), their states kept by {@code keeper} while Pekko moves
     * them (null: they move without). Every node of the cluster calls it, for the same grid, world
     * and settings.
     */
    public static void host(ActorSystem<?> system, ParcelGrid grid, World world, SimulationConfig config,
                            ActorRef<TickCommand> keeper) {
        ClusterSharding.get(system).init(Entity.of(ParcelEntity.TYPE,
                context -> ParcelEntity.create(context.getEntityId(), grid, world, config, keeper))
                .withStopMessage(new ParcelCommand.HandOff()));
    }

    /**
     * Hosts parcels on this node without a keeper ({@link #host}) and returns what reaches them: for a
     * cluster whose nodes stay.
     */
    public static ShardedParcels start(ActorSystem<?> system, ParcelGrid grid, World world, SimulationConfig config) {
        host(system, grid, world, config, null);
        return new ShardedParcels(system, grid);
    }

    /** Asks each parcel its command at once, as the tick's next step, and waits for every answer, by parcel. */
    @SuppressWarnings("unchecked")
    private <R extends ParcelReply> Map<ParcelId, R> ask(Collection<ParcelId> parcels,
                                                         Function<ParcelId, Function<String, ParcelCommand>> command) {
        long step = steps.incrementAndGet();
        long deadline = System.nanoTime() + STEP_TIMEOUT.toNanos();
        CompletableFuture<Object> abort = aborted;
        Map<ParcelId, CompletableFuture<ParcelReply>> asked = new LinkedHashMap<>();
        for (ParcelId id : parcels) {
            asked.put(id, ask(id, step, command.apply(id), deadline, abort));
        }
        Map<ParcelId, R> answers = new TreeMap<>();
        try {
            asked.forEach((id, answer) -> answers.put(id, (R) CompletableFuture.anyOf(answer, abort).join()));
        } catch (CompletionException e) {
            throw new ParcelLost("a parcel did not answer: " + e.getCause().getMessage(), e.getCause());
        }
        return answers;
    }

    /** Asks one parcel the step, and again each time its answer is late, until the deadline. */
    private CompletableFuture<ParcelReply> ask(ParcelId id, long step, Function<String, ParcelCommand> make,
                                               long deadline, CompletableFuture<Object> abort) {
        return sharding.entityRefFor(ParcelEntity.TYPE, id.toString())
                .<ParcelReply>ask(replyTo -> new ParcelCommand.Step(step, make.apply(
                        resolver.toSerializationFormat(replyTo))), ASK_AGAIN)
                .toCompletableFuture()
                .exceptionallyCompose(failure -> {
                    Throwable cause = failure instanceof CompletionException ? failure.getCause() : failure;
                    if (!(cause instanceof TimeoutException) || abort.isDone() || System.nanoTime() > deadline) {
                        return CompletableFuture.failedFuture(cause);
                    }
                    askedAgain.incrementAndGet();
                    log.warn("parcel {} did not answer step {} within {} ms: asked again", id, step,
                            ASK_AGAIN.toMillis());
                    return ask(id, step, make, deadline, abort);
                });
    }

    /** How many times a parcel was asked a step again, its answer late. */
    public long askedAgain() {
        return askedAgain.get();
    }

    private <T> void tellEach(Map<ParcelId, T> what, BiFunction<T, String, ParcelCommand> command) {
        ask(what.keySet(), id -> replyTo -> command.apply(what.get(id), replyTo));
    }

    private static List<KeyedLine> lines(Collection<? extends List<Wire.Line>> said) {
        List<KeyedLine> lines = new ArrayList<>();
        said.forEach(part -> part.forEach(line -> lines.add(line.line())));
        return lines;
    }

    /** Fails every step under way, and every step asked from now on until {@link #carryOn()}. */
    public void abort(String why) {
        aborted.completeExceptionally(new IllegalStateException(why));
    }

    /** Steps are asked again after an {@link #abort}. */
    public void carryOn() {
        if (aborted.isDone()) {
            aborted = new CompletableFuture<>();
        }
    }

    @Override
    public void reset(Set<String> fruitLeft) {
        List<String> left = List.copyOf(fruitLeft);
        ask(grid.all(), id -> replyTo -> new ParcelCommand.Reset(left, replyTo));
    }

    @Override
    public void own(Map<ParcelId, List<OwnedAgent>> owned) {
        tellEach(owned, ParcelCommand.Own::new);
    }

    @Override
    public List<AgentHandover> release(Map<ParcelId, List<String>> names) {
        Map<ParcelId, ParcelReply.Released> released = ask(names.keySet(),
                id -> replyTo -> new ParcelCommand.Release(names.get(id), replyTo));
        List<AgentHandover> all = new ArrayList<>();
        released.values().forEach(r -> all.addAll(r.agents()));
        return all;
    }

    @Override
    public void addGhosts(Map<ParcelId, List<OwnedAgent>> ghosts) {
        tellEach(ghosts, ParcelCommand.AddGhosts::new);
    }

    @Override
    public void forgetGhosts(Map<ParcelId, List<String>> names) {
        tellEach(names, ParcelCommand.ForgetGhosts::new);
    }

    @Override
    public List<KeyedLine> perceive(long tick, double time, Map<ParcelId, List<OwnedAgent>> ghosts) {
        Map<ParcelId, ParcelReply.Said> said = ask(ghosts.keySet(), id -> replyTo -> new ParcelCommand.Perceive(tick,
                time, ghosts.get(id), replyTo));
        return lines(said.values().stream().map(ParcelReply.Said::lines).toList());
    }

    @Override
    public Map<PathQuery, FirstContact> firstAlong(Map<ParcelId, List<PathQuery>> paths) {
        Map<ParcelId, ParcelReply.Contacts> answers = ask(paths.keySet(),
                id -> replyTo -> new ParcelCommand.FirstAlong(paths.get(id), replyTo));
        Map<PathQuery, FirstContact> first = new HashMap<>();
        answers.forEach((id, answer) -> FirstContacts.add(first, paths.get(id), answer.contacts()));
        return first;
    }

    @Override
    public Applied apply(long tick, double time, Map<ParcelId, List<Parcel.Act>> acts,
                         Map<PathQuery, FirstContact> answers) {
        List<ParcelCommand.PathAnswer> far = new ArrayList<>();
        answers.forEach((path, contact) -> far.add(new ParcelCommand.PathAnswer(path, contact)));
        Map<ParcelId, ParcelReply.Applied> applied = ask(acts.keySet(), id -> replyTo -> new ParcelCommand.Apply(tick,
                time, acts.get(id).stream().map(Wire.Act::of).toList(), far, replyTo));
        List<Parcel.KeyedClaim> claims = new ArrayList<>();
        List<AgentHandover> owned = new ArrayList<>();
        List<String> removed = new ArrayList<>();
        applied.values().forEach(a -> {
            a.claims().forEach(claim -> claims.add(claim.keyed()));
            owned.addAll(a.owned());
            removed.addAll(a.removed());
        });
        return new Applied(lines(applied.values().stream().map(ParcelReply.Applied::lines).toList()), claims, owned,
                removed);
    }

    @Override
    public Grasped grasp(long tick, double time, Map<ParcelId, List<Parcel.ClaimOf>> claims,
                         Map<String, LineKey> firstClaims) {
        List<ParcelCommand.FirstClaim> first = new ArrayList<>();
        firstClaims.forEach((fruit, key) -> first.add(new ParcelCommand.FirstClaim(fruit, key)));
        Map<ParcelId, ParcelReply.Grasped> grasped = ask(claims.keySet(), id -> replyTo -> new ParcelCommand.Grasp(
                tick, time, claims.get(id).stream().map(Wire.Grasp::of).toList(), first, replyTo));
        List<Parcel.Taken> taken = new ArrayList<>();
        grasped.values().forEach(g -> taken.addAll(g.taken()));
        return new Grasped(lines(grasped.values().stream().map(ParcelReply.Grasped::lines).toList()), taken);
    }

    @Override
    public void fruitTaken(Map<ParcelId, List<String>> fruit) {
        tellEach(fruit, ParcelCommand.FruitTaken::new);
    }

    @Override
    public Walked walk(long tick, double time, Map<ParcelId, List<OwnedAgent>> ghosts) {
        Map<ParcelId, ParcelReply.Walked> walked = ask(ghosts.keySet(), id -> replyTo -> new ParcelCommand.Walk(tick,
                time, ghosts.get(id), replyTo));
        List<AgentHandover> left = new ArrayList<>();
        List<AgentHandover> owned = new ArrayList<>();
        walked.values().forEach(w -> {
            left.addAll(w.left());
            owned.addAll(w.owned());
        });
        return new Walked(lines(walked.values().stream().map(ParcelReply.Walked::lines).toList()), left, owned);
    }

    @Override
    public void walked(Map<ParcelId, List<AgentHandover>> walkedTogether) {
        tellEach(walkedTogether, ParcelCommand.PutWalked::new);
    }
}
