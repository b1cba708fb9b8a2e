package io.orchard.agents;

/**
 * What an agent did in a game, as its controller counted it.
 *
 * @param movesSent          moves sent
 * @param movesAccepted      moves accepted as asked
 * @param movesBlocked       moves cut short by another agent
 * @param movesRejected      moves refused, for any reason
 * @param obstacleRejections moves refused because something in the world was in the way: a tree, a
 *                           table, the castle, the river or the world's edge
 * @param graspsSent         grasps tried
 * @param graspsWon          grasps that got the fruit
 * @param fruit              fruit collected
 * @param points             points scored
 * @param errors             errors the server answered with
 */
public record AgentStats(int movesSent, int movesAccepted, int movesBlocked, int movesRejected, int obstacleRejections,
                         int graspsSent, int graspsWon, int fruit, int points, int errors) {

    /** Nothing done yet. */
    public static final AgentStats NONE = new AgentStats(0, 0, 0, 0, 0, 0, 0, 0, 0, 0);

    /** The share of moves refused because an obstacle was in the way, 0 to 1 (0 without moves). */
    public double obstacleRejectionRate() {
        return movesSent == 0 ? 0 : (double) obstacleRejections / movesSent;
    }
}
