package io.orchard.viewer.model.gltf;

import io.orchard.protocol.StrictJson;
import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelException.Kind;
import io.orchard.viewer.model.ModelLimits;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Map;
import java.util.regex.Pattern;
import tools.jackson.core.JacksonException;
import tools.jackson.core.StreamReadConstraints;
import tools.jackson.core.TokenStreamLocation;
import tools.jackson.core.exc.StreamConstraintsException;
import tools.jackson.core.exc.UnexpectedEndOfInputException;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * Reads a glTF document's JSON into a tree, strictly (RFC 8259: no comments, no trailing commas,
 * no duplicate keys, nothing after the document) and within the model's limits: nesting no
 * deeper than {@link ModelLimits#maxDepth()}, the document and each string no longer than
 * {@link ModelLimits#maxInputBytes()}, numbers no longer than {@value #MAX_NUMBER_CHARS}
 * characters, and every number finite. jME's own JSON parser recurses without a bound, so a
 * deeply nested document must be refused here, before it is handed on.
 */
final class GltfJson {

    /** Far more than any glTF number needs: a double in full is at most 24 characters. */
    static final int MAX_NUMBER_CHARS = 64;

    private static final Pattern JACKSON_SETTING = Pattern.compile(", from `[^`]*`\\)");

    /** The mapper for the limits last used: nearly always the defaults. */
    private static volatile Cached cached;

    private record Cached(ModelLimits limits, JsonMapper mapper) {
    }

    private GltfJson() {
    }

    /**
     * The document as a tree.
     *
     * @throws ModelException naming the limit, or the place and problem, if it is refused
     */
    static JsonNode read(String json, ModelLimits limits) throws ModelException {
        String text = json.startsWith("\uFEFF") ? json.substring(1) : json;
        JsonNode tree;
        try {
            tree = mapper(limits).readTree(text);
        } catch (StreamConstraintsException e) {
            // Jackson names the limit and the value; which of its settings holds it is noise here.
            String problem = JACKSON_SETTING.matcher(firstLine(e)).replaceAll(")");
            throw new ModelException(Kind.TOO_LARGE, "glTF JSON" + at(e) + " is over a limit: "
                    + problem, e);
        } catch (UnexpectedEndOfInputException e) {
            throw new ModelException(Kind.MALFORMED, "glTF JSON" + at(e)
                    + " ends too soon (truncated?): " + firstLine(e), e);
        } catch (JacksonException e) {
            throw new ModelException(Kind.MALFORMED, "glTF JSON" + at(e) + ": " + firstLine(e), e);
        }
        if (tree == null || tree.isMissingNode()) {
            throw new ModelException(Kind.MALFORMED, "glTF JSON is empty");
        }
        requireFiniteNumbers(tree);
        return tree;
    }

    private static JsonMapper mapper(ModelLimits limits) {
        Cached last = cached;
        if (last == null || !last.limits().equals(limits)) {
            last = new Cached(limits, StrictJson.builder(StreamReadConstraints.builder()
                    .maxNestingDepth(limits.maxDepth())
                    .maxDocumentLength(limits.maxInputBytes())
                    .maxStringLength(limits.maxInputBytes())
                    .maxNumberLength(MAX_NUMBER_CHARS)
                    .build()).build());
            cached = last;
        }
        return last.mapper();
    }

    /** JSON has no NaN or infinity, but a number such as 1e999 reads as one. */
    private static void requireFiniteNumbers(JsonNode tree) throws ModelException {
        Deque<Place> pending = new ArrayDeque<>();
        pending.push(new Place(tree, null, ""));
        while (!pending.isEmpty()) {
            Place place = pending.pop();
            JsonNode node = place.node();
            if (node.isNumber() && !Double.isFinite(node.doubleValue())) {
                throw new ModelException(Kind.BAD_VALUE, "glTF JSON at " + place.pointer()
                        + ": number " + node.doubleValue() + " is out of range");
            }
            if (node.isObject()) {
                for (Map.Entry<String, JsonNode> member : node.properties()) {
                    pending.push(new Place(member.getValue(), place, member.getKey()));
                }
            } else if (node.isArray()) {
                for (int i = 0; i < node.size(); i++) {
                    pending.push(new Place(node.get(i), place, Integer.toString(i)));
                }
            }
        }
    }

    /** A node and where it is, worded only when an error needs it. */
    private record Place(JsonNode node, Place parent, String name) {

        /** As a JSON pointer, such as {@code /accessors/0/max/2}; as deep as the nesting limit. */
        String pointer() {
            return parent == null ? "/" : parent.parent == null ? "/" + name
                    : parent.pointer() + "/" + name;
        }
    }

    private static String at(JacksonException e) {
        TokenStreamLocation location = e.getLocation();
        return location == null || location.getLineNr() <= 0 ? ""
                : " at line " + location.getLineNr() + ", column " + location.getColumnNr();
    }

    private static String firstLine(JacksonException e) {
        String message = e.getOriginalMessage() == null ? e.getClass().getSimpleName()
                : e.getOriginalMessage();
        int newline = message.indexOf('\n');
        return newline < 0 ? message : message.substring(0, newline);
    }
}
