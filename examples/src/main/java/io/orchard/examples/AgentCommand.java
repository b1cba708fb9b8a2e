package io.orchard.examples;

import io.orchard.agents.cli.AgentMain;
import java.io.PrintStream;
import java.util.List;

/** {@code ./orchard agent}: one of the paper's agents, as {@link AgentMain#agent} runs it. */
final class AgentCommand implements Command {

    @Override
    public String name() {
        return "agent";
    }

    @Override
    public String summary() {
        return "run one of the paper's agents (--type dwarf, robot, bunny, guppy or roadrunner)";
    }

    @Override
    public String help() {
        return AgentMain.agentHelp();
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws Exception {
        return AgentMain.agent(args, System.in, out, err);
    }
}
