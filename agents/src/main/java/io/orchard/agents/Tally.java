package io.orchard.agents;

/** The counts behind {@link AgentStats}, kept on the controller's thread and published as snapshots. */
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

    AgentStats snapshot() {
        return new AgentStats(movesSent, movesAccepted, movesBlocked, movesRejected, obstacleRejections, graspsSent,
                graspsWon, fruit, points, errors);
    }
}
