package io.orchard.agents.cli;

import io.orchard.agents.AgentController;
import java.nio.file.Path;
import picocli.CommandLine.Option;

/** Where {@code agent} and {@code agents} keep their agents' resume tokens, shared by both. */
final class ResumeTokensOption {

    @Option(names = "--resume-tokens", paramLabel = "FILE", defaultValue = "${sys:user.home}/.orchard/resume-tokens",
            description = "Keep the agents' resume tokens in FILE, readable by you alone, so that the same command "
                    + "run again after a dropped connection or a server restarted with --resume gets them back with "
                    + "their scores (default: ${DEFAULT-VALUE})")
    Path file;

    /** Has {@code agent} keep its token in the file. */
    void keep(AgentController agent) {
        agent.keepResumeTokensIn(file);
    }
}
