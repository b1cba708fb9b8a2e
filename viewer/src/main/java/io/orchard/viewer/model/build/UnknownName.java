package io.orchard.viewer.model.build;

import io.orchard.viewer.model.ModelException;
import java.util.Set;

/** The error both rigs give for a joint or animation the model does not have. */
final class UnknownName {

    private static final int LISTED = 20;

    private UnknownName() {
    }

    /** Names what was asked for and lists (the first {@value #LISTED} of) what the model has. */
    static ModelException error(String what, String name, Set<String> known) {
        String list = known.stream().sorted().limit(LISTED).toList()
                + (known.size() > LISTED ? " and " + (known.size() - LISTED) + " more" : "");
        return new ModelException(ModelException.Kind.UNKNOWN_NAME, "the model has no " + what
                + " named '" + name + "'; it has " + (known.isEmpty() ? "none" : list));
    }
}
