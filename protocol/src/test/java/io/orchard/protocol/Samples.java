package io.orchard.protocol;

import io.orchard.protocol.message.*;
import io.orchard.protocol.value.*;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/** One typical instance of every message type, shared by the round-trip and golden-line tests. */
final class Samples {

    static final Body BODY = new Body(0.5, 1.2, 8.0, new Gripper("hands", 0.6, 0.0, 1.5), new Sight(30, Math.PI));
    static final Vec3 HERE = new Vec3(12.5, 0, -40.25);
    static final Vec3 THERE = new Vec3(20, 0, -35);
    static final List<Score> SCORES = List.of(new Score("Guppy", 5, 3), new Score("Bunny", 1, 1));

    static final PerceptionMessage PERCEPTION = new PerceptionMessage(43, "Guppy", HERE, 0.25,
            List.of(new PerceivedObject("T17", ObjectKind.TREE, new RelativePosition(6.5, -0.4), 1.5, 6),
                    new PerceivedObject("D2", ObjectKind.TABLE, new RelativePosition(12, 0.8), 1, 0.9)),
            List.of(new PerceivedAgent("Bunny", new RelativePosition(4, 1.2), -0.3, 0.4)),
            List.of(new PerceivedFruit("F12", FruitKind.BANANA, new Vec3(14, 1.15, -38), 0.25, "D2"),
                    new PerceivedFruit("F13", FruitKind.TOMATO, new Vec3(10, 0.15, -44), 0.15, null)));
    static final LandmarkPerceptionMessage LANDMARKS = new LandmarkPerceptionMessage(43, "Guppy",
            new PerceivedRiver(new RelativePosition(18, 0.1), 1.4),
            List.of(new PerceivedBridge("B1", new RelativePosition(20, 0.3), new RelativePosition(28, 0.25), 4)));
    static final CastlePerceptionMessage CASTLE = new CastlePerceptionMessage(43, "Guppy", Sector.SOUTH_WEST);

    private static final List<Message> ALL = List.of(
            new HelloMessage(1, 2, Role.AGENT, "guppy-controller", null),
            new RegisterMessage(2, "Guppy", BODY, ModelSpec.bundled("figure")),
            new RegisterJointMessage(3, "Guppy", "LeftKnee"),
            new RegisterTimeSensorMessage(4, "Guppy", "GuppyTSWalk"),
            new UnregisterMessage(5, "Guppy"),
            new MoveMessage(6, "Guppy", HERE, THERE),
            new SetRotationMessage(7, "Guppy", Rotation.heading(1.5707963267948966)),
            new SetJointRotationMessage(8, "Guppy", "LeftKnee", new Rotation(new Vec3(1, 0, 0), -0.5)),
            new StartAnimationMessage(9, "Guppy", "GuppyTSWalk", true),
            new StopAnimationMessage(10, "Guppy", "GuppyTSWalk"),
            new GraspRequestMessage(11, "Guppy", "F12"),
            new PerceptionRequestMessage(12, "Guppy", 0),
            new EndTurnMessage(13, 42),
            new InstructionMessage(14, "Guppy", "pick up the banana on the table", "teacher"),
            new SayMessage(15, "Guppy", "Which banana do you mean: F3 or F7?"),
            new GameControlMessage(16, GameCommand.START),
            new KeepAliveMessage(17),
            new WelcomeMessage(1, 2, "0.1.0", Role.AGENT, new Bounds(-100, -100, 100, 100), 20, ClockMode.LOCKSTEP, 0, 180.0,
                    GamePhase.WAITING),
            new ErrorMessage(6, ErrorCode.INVALID_VALUE, "from.x must be a finite number, was Infinity"),
            new RegisteredMessage(2, "Guppy", BODY, HERE, 0.0, "3f9c2a7e41b8d05c6e1f9a2b7c4d8e0f", 8071234567890123456L),
            new ActionResultMessage(6, "Guppy", "Move", Outcome.REJECTED, "path crosses tree T17", null, 0),
            new GraspResultMessage(11, "Guppy", "F12", true, null, 2),
            PERCEPTION,
            LANDMARKS,
            CASTLE,
            LeanPerceptionMessage.of(PERCEPTION, LANDMARKS, CASTLE),
            new FruitEatenMessage(44, "F12", FruitKind.BANANA, "Guppy"),
            new TickMessage(44, 2.2),
            new GameStartedMessage(0, 1998, 30, 180),
            new ScoreUpdateMessage(44, SCORES),
            new GameOverMessage(3600, "time limit reached", SCORES),
            new NewGameMessage(0, 180.0),
            new WorldSnapshotMessage(44, 2.2, new Bounds(-100, -100, 100, 100),
                    List.of(new Obstacle("T1", ObjectKind.TREE, new Point2(-20, 30), 2.5, 7),
                            new Obstacle("D1", ObjectKind.TABLE, new Point2(15, -10), 1.2, 0.9)),
                    new CastleShape(List.of(new Point2(40, 40), new Point2(60, 40), new Point2(60, 60), new Point2(40, 60)), 12),
                    new RiverShape(List.of(new Point2(-100, -5), new Point2(100, -5), new Point2(100, 5), new Point2(-100, 5))),
                    List.of(new BridgeShape("B1", new Point2(-30, -7), new Point2(-30, 7), 4)),
                    List.of(new FruitState("F1", FruitKind.COCONUT, new Vec3(-19, 2.5, 30), "T1")),
                    SCORES),
            new AgentAddedMessage(44, new AgentState("Guppy", BODY, HERE, 0, ModelSpec.of(ModelFormat.X3D,
                    "<X3D><Scene><Transform DEF='Guppy'/></Scene></X3D>".getBytes(java.nio.charset.StandardCharsets.UTF_8)),
                    List.of("LeftKnee"), List.of("GuppyTSWalk"))),
            new AgentMovedMessage(44, "Guppy", HERE, THERE, 2.2, 1.1),
            new AgentRotatedMessage(44, "Guppy", Rotation.heading(0.5)),
            new JointRotatedMessage(44, "Guppy", "LeftKnee", new Rotation(new Vec3(1, 0, 0), -0.5)),
            new AnimationStartedMessage(44, "Guppy", "GuppyTSWalk", true),
            new AnimationStoppedMessage(45, "Guppy", "GuppyTSWalk"),
            new FruitRemovedMessage(44, "F12", "Guppy"),
            new AgentRemovedMessage(50, "Bunny", "connection closed"));

    private static final Map<String, Message> BY_TYPE = ALL.stream()
            .collect(Collectors.toMap(m -> MessageTypes.nameOf(m.getClass()), Function.identity()));

    private Samples() {}

    static Message of(String type) {
        Message sample = BY_TYPE.get(type);
        if (sample == null) {
            throw new IllegalStateException("no sample for message type " + type + ": add one to Samples");
        }
        return sample;
    }

    static Stream<String> types() {
        return MessageTypes.names().stream();
    }

    static int count() {
        return ALL.size();
    }
}
