package io.orchard.server.world.scenario;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import tools.jackson.core.JacksonException;
import tools.jackson.core.TokenStreamLocation;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.exc.InvalidFormatException;
import tools.jackson.databind.exc.MismatchedInputException;
import tools.jackson.databind.exc.UnrecognizedPropertyException;
import tools.jackson.databind.exc.ValueInstantiationException;
import tools.jackson.databind.json.JsonMapper;

/**
 * Turns Jackson's exceptions into one line a scenario's author can act on: which object
 * ("tree T3", "the castle"), what is wrong ("unknown field 'hieght'", "missing field 'height'",
 * "radius must be greater than 0, was -1.0") and where (the path in the file, the line and column).
 */
final class JsonProblems {

    private static final Pattern MISSING = Pattern.compile("Missing required creator property '([^']*)'");
    private static final Pattern NOT_ONE_OF = Pattern.compile("not one of the values accepted for Enum class: \\[(.*)]");
    private static final Pattern NOT_A_NUMBER = Pattern.compile("Cannot coerce String value \\(\"(.*)\"\\) to `(double|int|long)`");
    private static final Pattern NULL_PRIMITIVE = Pattern.compile("Cannot map `null` into type `(double|int|long|boolean)`");

    /** The lists of a scenario and what one element of each is called. */
    private static final Map<String, String> ELEMENT = Map.of(
            "trees", "tree", "tables", "table", "bridges", "bridge", "fruit", "fruit");

    private JsonProblems() {}

    static String describe(JacksonException e, String json, JsonMapper mapper) {
        List<JacksonException.Reference> path = e.getPath();
        StringBuilder text = new StringBuilder();
        Optional<String[]> typo = misspelt(e, path, json, mapper);
        text.append(object(path, json, mapper)).append(": ").append(typo.map(t -> t[0]).orElseGet(() -> problem(e, path)));
        String where = typo.map(t -> t[1]).orElseGet(() -> path(path));
        TokenStreamLocation location = e.getLocation();
        boolean hasLine = location != null && location.getLineNr() > 0;
        if (!where.isEmpty() || hasLine) {
            text.append(" (");
            if (!where.isEmpty()) {
                text.append("at ").append(where);
            }
            if (hasLine) {
                text.append(where.isEmpty() ? "" : ", ").append("line ").append(location.getLineNr())
                        .append(", column ").append(location.getColumnNr());
            }
            text.append(')');
        }
        return text.toString();
    }

    private static String problem(JacksonException e, List<JacksonException.Reference> path) {
        if (e instanceof UnrecognizedPropertyException unknown) {
            String known = unknown.getKnownPropertyIds() == null ? "" : unknown.getKnownPropertyIds().stream()
                    .map(String::valueOf).sorted().collect(Collectors.joining(", "));
            return "unknown field '" + unknown.getPropertyName() + "'" + (known.isEmpty() ? "" : "; known fields: " + known);
        }
        if (e instanceof ValueInstantiationException) {
            Throwable cause = e.getCause();
            while (cause != null && cause.getCause() != null && cause.getCause() != cause
                    && !(cause instanceof IllegalArgumentException)) {
                cause = cause.getCause();
            }
            if (cause != null && cause.getMessage() != null) {
                return cause.getMessage();
            }
        }
        String original = e.getOriginalMessage() == null ? e.getClass().getSimpleName() : e.getOriginalMessage();
        if (e instanceof MismatchedInputException) {
            Matcher missing = MISSING.matcher(original);
            if (missing.find()) {
                return "missing field '" + missing.group(1) + "'";
            }
            Matcher notOneOf = NOT_ONE_OF.matcher(original);
            if (e instanceof InvalidFormatException invalid && notOneOf.find()) {
                String allowed = Stream.of(notOneOf.group(1).split(",\\s*")).sorted().collect(Collectors.joining(", "));
                return "unknown value '" + invalid.getValue() + "'; expected one of: " + allowed;
            }
            Matcher notANumber = NOT_A_NUMBER.matcher(original);
            if (notANumber.find()) {
                return "expected a number, found the text \"" + notANumber.group(1) + "\"";
            }
            if (NULL_PRIMITIVE.matcher(original).find() && !path.isEmpty()) {
                return last(path) + " must be a " + (original.contains("boolean") ? "boolean" : "number") + ", was null";
            }
        }
        int newline = original.indexOf('\n');
        return newline < 0 ? original : original.substring(0, newline);
    }

    /**
     * Jackson builds a record before it looks at the fields it did not know, so a misspelt field
     * ("hieght") is first reported as the missing one ("height"). The misspelling is the real
     * problem: when an object lacks a field and has one its record does not know, name that one.
     *
     * @return the problem and where it is, when there is a misspelt field
     */
    private static Optional<String[]> misspelt(JacksonException e, List<JacksonException.Reference> path, String json,
                                             JsonMapper mapper) {
        if (!(e instanceof MismatchedInputException) || !MISSING.matcher(String.valueOf(e.getOriginalMessage())).find()) {
            return Optional.empty();
        }
        List<JacksonException.Reference> objectPath = path.isEmpty() || path.get(path.size() - 1).getPropertyName() == null
                ? path : path.subList(0, path.size() - 1);
        Optional<Class<?>> type = RecordTypes.at(Scenario.class, objectPath);
        JsonNode node = tree(json, mapper);
        for (JacksonException.Reference reference : objectPath) {
            node = reference.getPropertyName() != null ? node.path(reference.getPropertyName()) : node.path(reference.getIndex());
        }
        if (type.isEmpty() || !node.isObject()) {
            return Optional.empty();
        }
        List<String> known = RecordTypes.fields(type.get());
        for (String name : node.propertyNames()) {
            if (!known.contains(name)) {
                String problem = "unknown field '" + name + "'; known fields: "
                        + known.stream().sorted().collect(Collectors.joining(", "));
                String where = path(objectPath) + (objectPath.isEmpty() ? "" : ".") + name;
                return Optional.of(new String[] {problem, where});
            }
        }
        return Optional.empty();
    }

    private static String last(List<JacksonException.Reference> path) {
        JacksonException.Reference reference = path.get(path.size() - 1);
        return reference.getPropertyName() != null ? reference.getPropertyName() : "[" + reference.getIndex() + "]";
    }

    private static JsonNode tree(String json, JsonMapper mapper) {
        try {
            return mapper.readTree(json);
        } catch (JacksonException unreadable) {
            return mapper.missingNode();
        }
    }

    /** "trees[2].position.x" */
    private static String path(List<JacksonException.Reference> path) {
        StringBuilder text = new StringBuilder();
        for (JacksonException.Reference reference : path) {
            if (reference.getPropertyName() != null) {
                if (!text.isEmpty()) {
                    text.append('.');
                }
                text.append(reference.getPropertyName());
            } else if (reference.getIndex() >= 0) {
                text.append('[').append(reference.getIndex()).append(']');
            }
        }
        return text.toString();
    }

    /** The object the problem is in: "tree T3", "fruit F2", "the castle", or "the scenario". */
    private static String object(List<JacksonException.Reference> path, String json, JsonMapper mapper) {
        if (path.isEmpty() || path.get(0).getPropertyName() == null) {
            return "the scenario";
        }
        String field = path.get(0).getPropertyName();
        String element = ELEMENT.get(field);
        if (element == null) {
            return path.size() == 1 && !List.of("castle", "river", "bounds").contains(field) ? "the scenario"
                    : "the " + field;
        }
        if (path.size() < 2 || path.get(1).getIndex() < 0) {
            return "the " + field;
        }
        int index = path.get(1).getIndex();
        return element + " " + idOf(json, mapper, field, index).orElse(field + "[" + index + "]");
    }

    private static Optional<String> idOf(String json, JsonMapper mapper, String field, int index) {
        JsonNode id = tree(json, mapper).path(field).path(index).path("id");
        return id.isString() && !id.stringValue().isBlank() ? Optional.of(id.stringValue()) : Optional.empty();
    }
}
