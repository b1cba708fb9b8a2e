package io.orchard.viewer.world;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.AgentMovedMessage;
import io.orchard.protocol.message.AgentRemovedMessage;
import io.orchard.protocol.message.AgentRotatedMessage;
import io.orchard.protocol.message.AnimationStartedMessage;
import io.orchard.protocol.message.AnimationStoppedMessage;
import io.orchard.protocol.message.FruitRemovedMessage;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.JointRotatedMessage;
import io.orchard.protocol.message.SayMessage;
import io.orchard.protocol.message.ScoreUpdateMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.AgentState;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.CastleShape;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.RiverShape;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Score;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

class WorldMirrorTest {

    static final Body BODY = new Body(0.5, 1.2, 8, new Gripper("hands", 0.6, 0, 1.5), new Sight(30, Math.PI));

    static WorldSnapshotMessage snapshot(double time, FruitState... fruit) {
        return new WorldSnapshotMessage(0, time, new Bounds(-50, -50, 50, 50),
                List.of(new Obstacle("T1", ObjectKind.TREE, new Point2(10, 10), 2, 6)),
                new CastleShape(List.of(new Point2(-40, -40), new Point2(-30, -40), new Point2(-30, -30),
                        new Point2(-40, -30)), 8),
                new RiverShape(List.of(new Point2(-50, 20), new Point2(50, 20), new Point2(50, 25), new Point2(-50, 25))),
                List.of(), List.of(fruit), List.of());
    }

    static AgentAddedMessage added(String name, Vec3 at, double heading) {
        return new AgentAddedMessage(0, new AgentState(name, BODY, at, heading, ModelSpec.bundled("figure"), List.of(),
                List.of()));
    }

    static final FruitState TOMATO = new FruitState("F1", FruitKind.TOMATO, new Vec3(1, 0.15, 2), null);

    /** Records what listeners hear. */
    static final class Heard implements WorldMirror.Listener {
        final List<String> events = new ArrayList<>();

        @Override
        public void worldShown(WorldSnapshotMessage snapshot) {
            events.add("world");
        }

        @Override
        public void fruitRemoved(FruitState fruit, String eatenBy) {
            events.add("fruit " + fruit.id() + " by " + eatenBy);
        }

        @Override
        public void agentAdded(AgentView agent) {
            events.add("added " + agent.name());
        }

        @Override
        public void agentRemoved(AgentView agent) {
            events.add("removed " + agent.name());
        }

        @Override
        public void agentMoved(AgentView agent, Motion motion) {
            events.add("moved " + agent.name());
        }

        @Override
        public void animationStarted(AgentView agent, RunningAnimation animation) {
            events.add("started " + animation.name() + " at " + animation.startTime());
        }

        @Override
        public void worldCleared() {
            events.add("cleared");
        }
    }

    @Test
    void snapshotShowsTheWorldAndItsFruit() {
        WorldMirror mirror = new WorldMirror();
        Heard heard = new Heard();
        mirror.addListener(heard);

        mirror.apply(snapshot(3.5, TOMATO));

        assertThat(mirror.hasWorld()).isTrue();
        assertThat(mirror.fruit()).containsExactly(TOMATO);
        assertThat(mirror.time()).isEqualTo(3.5);
        assertThat(heard.events).containsExactly("world");
    }

    @Test
    void movedAgentIsInterpolatedAlongItsWalkAsThePositionInterpolatorDid() {
        WorldMirror mirror = new WorldMirror();
        mirror.apply(snapshot(0));
        mirror.apply(added("Guppy", new Vec3(0, 0, 0), 0));

        mirror.apply(new AgentMovedMessage(1, "Guppy", new Vec3(0, 0, 0), new Vec3(10, 0, -20), 2.0, 4.0));

        AgentView guppy = mirror.agent("Guppy").orElseThrow();
        assertThat(guppy.positionAt(1.0)).isEqualTo(new Vec3(0, 0, 0));
        assertThat(guppy.positionAt(3.0)).isEqualTo(new Vec3(2.5, 0, -5));
        assertThat(guppy.positionAt(6.0)).isEqualTo(new Vec3(10, 0, -20));
        assertThat(guppy.positionAt(99)).isEqualTo(new Vec3(10, 0, -20));
    }

    @Test
    void rotationsJointsAndAnimationsAreRememberedForModelsThatLoadLater() {
        WorldMirror mirror = new WorldMirror();
        Heard heard = new Heard();
        mirror.addListener(heard);
        mirror.apply(snapshot(0));
        mirror.apply(added("Guppy", new Vec3(0, 0, 0), 0.5));
        mirror.apply(new TickMessage(4, 0.2));

        mirror.apply(new AgentRotatedMessage(4, "Guppy", Rotation.heading(1.25)));
        mirror.apply(new JointRotatedMessage(4, "Guppy", "LeftKnee", new Rotation(new Vec3(1, 0, 0), -0.5)));
        mirror.apply(new AnimationStartedMessage(4, "Guppy", "GuppyTSWalk", true), 0.25);
        mirror.apply(new AnimationStartedMessage(4, "Guppy", "GuppyTSGrasp", false), 0.3);
        mirror.apply(new AnimationStoppedMessage(4, "Guppy", "GuppyTSGrasp"), 0.35);

        AgentView guppy = mirror.agent("Guppy").orElseThrow();
        assertThat(guppy.heading()).isEqualTo(1.25);
        assertThat(guppy.jointRotations()).containsEntry("LeftKnee", new Rotation(new Vec3(1, 0, 0), -0.5));
        assertThat(guppy.runningAnimations()).containsExactly(new RunningAnimation("GuppyTSWalk", true, 0.25));
        assertThat(heard.events).contains("started GuppyTSWalk at 0.25");
    }

    @Test
    void eatenFruitLeavesAndIsLoggedWithItsEater() {
        WorldMirror mirror = new WorldMirror();
        Heard heard = new Heard();
        mirror.addListener(heard);
        mirror.apply(snapshot(0, TOMATO));

        mirror.apply(new FruitRemovedMessage(9, "F1", "Guppy"));
        mirror.apply(new FruitRemovedMessage(9, "F1", "Guppy"));

        assertThat(mirror.fruit()).isEmpty();
        assertThat(heard.events).containsExactly("world", "fruit F1 by Guppy");
        assertThat(mirror.log()).extracting(LogLine::text).containsExactly("Guppy collected tomato F1");
    }

    @Test
    void scoresSpeechAndTheEndAreKept() {
        WorldMirror mirror = new WorldMirror();
        mirror.apply(snapshot(0));
        List<Score> scores = List.of(new Score("Guppy", 3, 1));

        mirror.apply(new ScoreUpdateMessage(5, scores));
        mirror.apply(new SayMessage(7, "Guppy", "Which banana?"));
        mirror.apply(new GameOverMessage(9, "time limit reached", scores));

        assertThat(mirror.scores()).isEqualTo(scores);
        assertThat(mirror.gameOver()).isPresent();
        assertThat(mirror.log()).extracting(LogLine::text).containsExactly("Guppy: Which banana?",
                "game over: time limit reached");
    }

    @Test
    void agentsThatLeaveBeforeTheEndGoButThoseLeavingAfterItStayInTheFinalPicture() {
        WorldMirror mirror = new WorldMirror();
        Heard heard = new Heard();
        mirror.addListener(heard);
        mirror.apply(snapshot(0));
        mirror.apply(added("Guppy", new Vec3(1, 0, 1), 0));
        mirror.apply(added("Bunny", new Vec3(2, 0, 2), 0));

        mirror.apply(new AgentRemovedMessage(4, "Bunny", "disconnected"));
        mirror.apply(new GameOverMessage(9, "time limit reached", List.of(new Score("Guppy", 3, 1))));
        mirror.apply(new AgentRemovedMessage(9, "Guppy", "disconnected"));

        assertThat(mirror.agents()).extracting(AgentView::name).containsExactly("Guppy");
        assertThat(heard.events).contains("removed Bunny").doesNotContain("removed Guppy");
        assertThat(mirror.log()).extracting(LogLine::text).contains("Guppy left (disconnected)");
    }

    @Test
    void messagesAboutUnknownAgentsChangeNothing() {
        WorldMirror mirror = new WorldMirror();
        Heard heard = new Heard();
        mirror.addListener(heard);
        mirror.apply(snapshot(0));

        mirror.apply(new AgentMovedMessage(1, "Nobody", new Vec3(0, 0, 0), new Vec3(1, 0, 0), 0, 1));
        mirror.apply(new AgentRemovedMessage(1, "Nobody", "gone"));

        assertThat(heard.events).containsExactly("world");
    }

    @Nested
    class WhenAnAgentIsAddedTwice {

        @Test
        void theOldOneIsRemovedFirst() {
            WorldMirror mirror = new WorldMirror();
            Heard heard = new Heard();
            mirror.addListener(heard);
            mirror.apply(snapshot(0));

            mirror.apply(added("Guppy", new Vec3(0, 0, 0), 0));
            mirror.apply(added("Guppy", new Vec3(5, 0, 5), 0));

            assertThat(heard.events).containsExactly("world", "added Guppy", "removed Guppy", "added Guppy");
            assertThat(mirror.agent("Guppy").orElseThrow().positionAt(0)).isEqualTo(new Vec3(5, 0, 5));
        }
    }

    @Test
    void clearForgetsEverythingAndTellsTheListeners() {
        WorldMirror mirror = new WorldMirror();
        Heard heard = new Heard();
        mirror.addListener(heard);
        mirror.apply(snapshot(2, TOMATO));
        mirror.apply(added("Guppy", new Vec3(0, 0, 0), 0));

        mirror.clear();

        assertThat(mirror.hasWorld()).isFalse();
        assertThat(mirror.agents()).isEmpty();
        assertThat(mirror.fruit()).isEmpty();
        assertThat(mirror.time()).isZero();
        assertThat(heard.events).endsWith("cleared");
    }

    @Test
    void aRestartForgetsTheGameButKeepsTheLogForTheNextConnectionsSnapshot() {
        WorldMirror mirror = new WorldMirror();
        Heard heard = new Heard();
        mirror.addListener(heard);
        mirror.apply(snapshot(50, TOMATO));
        mirror.apply(added("Guppy", new Vec3(0, 0, 0), 0));
        mirror.apply(new GameOverMessage(9, "time limit reached", List.of(new Score("Guppy", 3, 1))));

        mirror.restart();
        mirror.apply(snapshot(1));

        assertThat(mirror.agents()).isEmpty();
        assertThat(mirror.fruit()).isEmpty();
        assertThat(mirror.gameOver()).as("the new connection's game").isEmpty();
        assertThat(mirror.time()).as("the new game's time, not the old one's").isEqualTo(1);
        assertThat(heard.events).containsSubsequence("cleared", "world");
        assertThat(mirror.log()).extracting(LogLine::text).contains("Guppy joined", "game over: time limit reached");
    }
}
