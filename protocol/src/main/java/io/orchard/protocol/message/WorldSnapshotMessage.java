package io.orchard.protocol.message;

import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.BridgeShape;
import io.orchard.protocol.value.CastleShape;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.RiverShape;
import io.orchard.protocol.value.Score;

import java.util.List;

/**
 * Sent to a viewer when it connects: every static object, every fruit left and the scores. An
 * {@link AgentAddedMessage} follows for each agent in the world; then every change.
 *
 * @param tick the current tick
 * @param time simulated seconds since the game started
 * @param bounds the walkable rectangle
 * @param obstacles trees and tables
 * @param castle the castle
 * @param river the river
 * @param bridges the bridges
 * @param fruit the fruit left
 * @param scores the scores
 */
public record WorldSnapshotMessage(long tick,
                                   double time,
                                   Bounds bounds,
                                   List<Obstacle> obstacles,
                                   CastleShape castle,
                                   RiverShape river,
                                   List<BridgeShape> bridges,
                                   List<FruitState> fruit,
                                   List<Score> scores) implements ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public WorldSnapshotMessage {
        Checks.nonNegative(tick, "tick");
        Checks.nonNegative(time, "time");
        Checks.present(bounds, "bounds");
        obstacles = Checks.list(obstacles, "obstacles");
        Checks.present(castle, "castle");
        Checks.present(river, "river");
        bridges = Checks.list(bridges, "bridges");
        fruit = Checks.list(fruit, "fruit");
        scores = Checks.list(scores, "scores");
    }
}
