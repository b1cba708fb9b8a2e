package io.orchard.agents.cli;

import io.orchard.agents.AgentController;
import picocli.CommandLine.Option;

/** Whether {@code agent} and {@code agents} stay for the games the server's operator restarts, shared by both. */
final class NextGamesOption {

    @Option(names = "--next-games",
            description = "Once a game is over, stay connected and play each next game the server's operator starts "
                    + "(GameControl restart), with the agents new as in a new run; leave when the server closes")
    boolean on;

    /** Has {@code agent} stay for the next game, when asked. */
    void apply(AgentController agent) {
        if (on) {
            agent.stayForNextGame();
        }
    }

    /** Whether {@code agent}, whose game is over, is to be followed by a new one for the next game. */
    boolean another(AgentController agent) {
        return on && agent.nextGameWaits();
    }
}
