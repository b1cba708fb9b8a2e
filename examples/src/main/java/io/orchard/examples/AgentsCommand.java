package io.orchard.examples;

import io.orchard.agents.cli.AgentMain;
import java.io.PrintStream;
import java.util.List;

/** {@code ./orchard agents}: all five of the paper's agents, as {@link AgentMain#agents} runs them. */
final class AgentsCommand implements Command {

    @Override
    public String name() {
        return "agents";
    }

    @Override
    public String summary() {
        return "run all five of the paper's agents, each on its own connection";
    }

    @Override
    public String help() {
        return AgentMain.agentsHelp();
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws Exception {
        return AgentMain.agents(args, System.in, out, err);
    }
}
