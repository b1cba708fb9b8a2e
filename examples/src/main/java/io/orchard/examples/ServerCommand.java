package io.orchard.examples;

import io.orchard.server.ServerMain;
import java.io.PrintStream;
import java.util.List;

/** {@code ./orchard server}: the world server, as {@link ServerMain} runs it. */
final class ServerCommand implements Command {

    @Override
    public String name() {
        return "server";
    }

    @Override
    public String summary() {
        return "run the world server (the world, the game, the protocol on one port)";
    }

    @Override
    public String help() {
        return ServerMain.help();
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws Exception {
        return ServerMain.run(args, System.in, out, err);
    }
}
