package io.orchard.examples;

import io.orchard.viewer.ViewerMain;
import java.io.PrintStream;
import java.util.List;

/** {@code ./orchard viewer}: the 3D viewer, windowed or headless, live or replaying, as {@link ViewerMain} runs it. */
final class ViewerCommand implements Command {

    @Override
    public String name() {
        return "viewer";
    }

    @Override
    public String summary() {
        return "watch the world in 3D, live or from a recording; headless, write screenshots";
    }

    @Override
    public String help() {
        return ViewerMain.help();
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) {
        return ViewerMain.run(args, out, err);
    }
}
