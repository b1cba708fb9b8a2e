package io.orchard.examples;

import io.orchard.agents.model.ModelInfo;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code ./orchard model-info [--json] FILE}: what a model file holds, as {@link ModelInfo} reads it
 * offline: the joints and clips an agent may register, the bounding size and the units.
 */
@Command(name = "model-info", abbreviateSynopsis = true, sortOptions = false,
        description = {"List a model file's joints, clips, size and units", "",
            "It reads a model file offline, without a server or a viewer, and prints the names an agent may register "
                    + "with RegisterJoint and RegisterTimeSensor (an unnamed glTF node or clip as node#i or clip#i, by "
                    + "its index, as viewers name it), the top-level nodes, the bounding box in the file's units and "
                    + "those units. glTF (.gltf, .glb), X3D (.x3d), VRML97 (.wrl) and a zip of a model's files (.zip) "
                    + "are read. With --json the same is one JSON object, described in docs/agents.md."},
        descriptionHeading = "%n", parameterListHeading = "%nArguments:%n", optionListHeading = "%nOptions:%n",
        footerHeading = "%nExample:%n", footer = "  ./orchard model-info --json models/Cat.gltf")
public final class ModelInfoCommand implements Callable<Integer> {

    @Parameters(paramLabel = "FILE", arity = "1", description = "The model file")
    private Path file;

    @Option(names = "--json", description = "Print one JSON object instead of text")
    private boolean json;

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help and exit")
    private boolean help;

    @Spec
    private CommandSpec spec;

    private final PrintStream out;

    /** The {@code ./orchard model-info} command, printing to {@code out}. */
    public ModelInfoCommand(PrintStream out) {
        this.out = out;
    }

    @Override
    public Integer call() throws IOException {
        if (!Files.isRegularFile(file)) {
            throw new ParameterException(spec.commandLine(), "invalid value for parameter 'FILE': '" + file
                    + "' is not a file");
        }
        try {
            ModelInfo.formatOf(file.getFileName().toString());
        } catch (IOException e) {
            throw new ParameterException(spec.commandLine(), "invalid value for parameter 'FILE': " + e.getMessage());
        }
        ModelInfo info = ModelInfo.read(file);
        out.print(json ? info.toJson() + "\n" : info.toText());
        out.flush();
        return 0;
    }
}
