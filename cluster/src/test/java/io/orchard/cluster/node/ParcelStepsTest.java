package io.orchard.cluster.node;

import static org.assertj.core.api.Assertions.assertThat;

import com.typesafe.config.ConfigFactory;
import io.orchard.cluster.order.SessionRef;
import io.orchard.cluster.parcel.OwnedAgent;
import io.orchard.cluster.parcel.ParcelGrid;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.AgentHandover;
import io.orchard.server.sim.BodyLimits;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.World;
import io.orchard.server.world.WorldGenerator;
import io.orchard.server.world.WorldOptions;
import java.time.Duration;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Function;
import org.apache.pekko.actor.typed.ActorRef;
import org.apache.pekko.actor.typed.ActorRefResolver;
import org.apache.pekko.actor.typed.ActorSystem;
import org.apache.pekko.actor.typed.Behavior;
import org.apache.pekko.actor.typed.Props;
import org.apache.pekko.actor.typed.Terminated;
import org.apache.pekko.actor.typed.javadsl.AskPattern;
import org.apache.pekko.actor.typed.javadsl.Behaviors;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * A parcel does each of the tick's steps once: a step asked again (its first command or answer lost
 * while the parcel moved between nodes) is answered as the first time, also by the parcel started
 * again on another node. Every message here goes through the cluster's serializer, as between nodes.
 */
class ParcelStepsTest {

    private static final Duration WAIT = Duration.ofSeconds(20);

    private final World world = new WorldGenerator(new SplittableRandom(1998), WorldOptions.DEFAULT).generate();
    private final SimulationConfig config = new SimulationConfig(20, ClockMode.LOCKSTEP, 60, 1, Duration.ofSeconds(2),
            8, BodyLimits.DEFAULT);
    private final ParcelGrid grid = new ParcelGrid(world.bounds(), 25, 60);
    private final ActorSystem<Void> system = ActorSystem.create(Behaviors.empty(), "parcel-steps",
            ConfigFactory.parseString("pekko.actor.serialize-messages = on").withFallback(ConfigFactory.load()));
    private final ActorRefResolver resolver = ActorRefResolver.get(system);
    private int spawned;

    @AfterEach
    void stop() {
        system.terminate();
    }

    private <T> ActorRef<T> spawn(Behavior<T> behavior) {
        return system.systemActorOf(behavior, "actor-" + ++spawned, Props.empty());
    }

    private ParcelReply ask(ActorRef<ParcelCommand> parcel, long step, Function<String, ParcelCommand> command)
            throws Exception {
        return AskPattern.<ParcelCommand, ParcelReply>ask(parcel,
                replyTo -> new ParcelCommand.Step(step, command.apply(resolver.toSerializationFormat(replyTo))), WAIT,
                system.scheduler()).toCompletableFuture().get(WAIT.toSeconds(), TimeUnit.SECONDS);
    }

    private OwnedAgent ann() {
        Vec3 at = new Vec3(world.bounds().minX() + 5, 0, world.bounds().minZ() + 5);
        Body body = new Body(0.5, 1.2, 10, new Gripper("hands", 0.6, 0, 1.5), new Sight(40, Math.PI));
        AgentHandover agent = new AgentHandover("Ann", 1, body, null, at, 0, null, List.of(), List.of(), "token-ann",
                false, 1, 0);
        return new OwnedAgent(agent, new SessionRef(1, Role.AGENT, 2), "Ann");
    }

    private String parcelOfAnn() {
        return grid.of(ann().agent().position()).toString();
    }

    private static List<String> released(ParcelReply reply) {
        assertThat(reply).isInstanceOf(ParcelReply.Released.class);
        return ((ParcelReply.Released) reply).agents().stream().map(AgentHandover::name).toList();
    }

    @Test
    void aStepAskedAgainIsAnsweredAsBeforeAndNotDoneTwice() throws Exception {
        ActorRef<ParcelCommand> parcel = spawn(ParcelEntity.create(parcelOfAnn(), grid, world, config, null));
        assertThat(ask(parcel, 7, to -> new ParcelCommand.Own(List.of(ann()), to))).isEqualTo(new ParcelReply.Done());

        assertThat(released(ask(parcel, 8, to -> new ParcelCommand.Release(List.of("Ann"), to))))
                .as("the first time, Ann is given up").containsExactly("Ann");
        assertThat(released(ask(parcel, 8, to -> new ParcelCommand.Release(List.of("Ann"), to))))
                .as("the same step again: the same answer").containsExactly("Ann");
        assertThat(released(ask(parcel, 9, to -> new ParcelCommand.Release(List.of("Ann"), to))))
                .as("a new step is done: Ann is gone already").isEmpty();
    }

    @Test
    void theLastAnswerMovesWithTheParcelToItsNextStart() throws Exception {
        ActorRef<TickCommand> keeper = spawn(Keeper.behavior(new AtomicLong()));
        String id = parcelOfAnn();
        ActorRef<ParcelCommand> first = spawn(ParcelEntity.create(id, grid, world, config, keeper));
        ask(first, 41, to -> new ParcelCommand.Own(List.of(ann()), to));
        assertThat(released(ask(first, 42, to -> new ParcelCommand.Release(List.of("Ann"), to)))).containsExactly("Ann");
        first.tell(new ParcelCommand.HandOff());
        awaitStopped(first);

        ActorRef<ParcelCommand> again = spawn(ParcelEntity.create(id, grid, world, config, keeper));
        assertThat(released(ask(again, 42, to -> new ParcelCommand.Release(List.of("Ann"), to))))
                .as("the step its node answered before the move, asked again after it").containsExactly("Ann");
        assertThat(released(ask(again, 43, to -> new ParcelCommand.Release(List.of("Ann"), to)))).isEmpty();
    }

    /** Waits until {@code actor} has stopped: a parcel handing off stops once the keeper has its state. */
    private void awaitStopped(ActorRef<?> actor) throws Exception {
        CompletableFuture<Boolean> stopped = new CompletableFuture<>();
        spawn(Behaviors.setup(context -> {
            context.watch(actor);
            return Behaviors.receiveSignal((ctx, signal) -> {
                if (signal instanceof Terminated) {
                    stopped.complete(true);
                }
                return Behaviors.same();
            });
        }));
        assertThat(stopped.get(WAIT.toSeconds(), TimeUnit.SECONDS)).isTrue();
    }
}
