package io.orchard.agents;

import io.orchard.agents.map.Obstruction;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Score;
import java.util.List;

/**
 * The counts behind {@link AgentStats}, kept on the controller's thread and published as snapshots
 * that any thread may read.
 */
final class Tally {

    int movesSent;
    int movesAccepted;
    int movesBlocked;
    int movesRejected;
    int obstacleRejections;
    int graspsSent;
    int graspsWon;
    int fruit;
    int points;
    int errors;
    private volatile AgentStats published = AgentStats.NONE;

    /** Counts the server's answer to a move. */
    void moveAnswered(Outcome outcome, @Nullable String reason) {
        switch (outcome) {
            case ACCEPTED -> movesAccepted++;
            case BLOCKED -> movesBlocked++;
            case REJECTED -> {
                movesRejected++;
                if (Obstruction.of(reason).isObstacle()) {
                    obstacleRejections++;
                }
            }
        }
    }

    /** Takes the agent's points and fruit from the server's scores. */
    void scored(String agent, List<Score> scores) {
        for (Score score : scores) {
            if (score.agent().equals(agent)) {
                points = score.points();
                fruit = score.fruit();
            }
        }
    }

    /** Publishes the counts so far. */
    void publish() {
        published = snapshot();
    }

    /** The counts last published. Safe from any thread. */
    AgentStats published() {
        return published;
    }

    AgentStats snapshot() {
        return new AgentStats(movesSent, movesAccepted, movesBlocked, movesRejected, obstacleRejections, graspsSent,
                graspsWon, fruit, points, errors);
    }
}
