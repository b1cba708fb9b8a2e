package io.orchard.agents.language;

import io.orchard.protocol.value.Sector;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import tools.jackson.core.JacksonException;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * Reads goals back from the JSON {@link GoalJson} writes, so that a goal made elsewhere (by another
 * interpreter, a student's program, a file) can be handed to an agent. Every value is checked:
 * an unknown goal, kind or relation, a missing field or a wrong type is refused with an
 * {@link IllegalArgumentException} that names it and says what was expected.
 */
final class GoalReader {

    private static final JsonMapper MAPPER = JsonMapper.builder().build();

    private GoalReader() {
    }

    static Goal read(String json) {
        JsonNode node;
        try {
            node = MAPPER.readTree(json);
        } catch (JacksonException e) {
            throw new IllegalArgumentException("a goal must be a JSON object, but the text is not JSON: "
                    + e.getOriginalMessage(), e);
        }
        return goal(node, "goal");
    }

    private static Goal goal(JsonNode node, String where) {
        if (node == null || !node.isObject()) {
            throw new IllegalArgumentException(where + " must be a JSON object with a \"goal\" field, was " + node);
        }
        String goal = text(node, "goal", where);
        return switch (goal) {
            case "sequence" -> {
                JsonNode steps = node.get("steps");
                if (steps == null || !steps.isArray() || steps.size() < 2) {
                    throw new IllegalArgumentException(where + ".steps must be an array of at least two goals, was "
                            + steps);
                }
                List<Goal> goals = new ArrayList<>();
                for (int i = 0; i < steps.size(); i++) {
                    goals.add(goal(steps.get(i), where + ".steps[" + i + "]"));
                }
                yield new Sequence(goals);
            }
            case "go-to" -> new GoTo(reference(node.get("destination"), where + ".destination"));
            case "cross" -> new Cross(reference(node.get("landmark"), where + ".landmark"));
            case "head" -> new Head(sector(text(node, "direction", where), where + ".direction"),
                    optionalNumber(node, "distance", where));
            case "move" -> new RelativeMove(direction(text(node, "direction", where), where + ".direction"),
                    optionalNumber(node, "distance", where));
            case "come-back" -> new ComeBack();
            case "collect" -> new Collect(reference(node.get("what"), where + ".what"), count(node, where));
            case "turn" -> new Turn(number(node, "radians", where));
            case "face" -> new Face(sector(text(node, "direction", where), where + ".direction"));
            case "look-at" -> new LookAt(reference(node.get("target"), where + ".target"));
            case "look-for" -> new LookFor(reference(node.get("what"), where + ".what"));
            case "explore" -> new Explore(node.has("area") ? reference(node.get("area"), where + ".area") : null);
            case "follow" -> new Follow(reference(node.get("agent"), where + ".agent"));
            case "stop" -> new Stop();
            case "wait" -> new Wait(node.has("seconds") ? number(node, "seconds", where) : Wait.UNTIL_TOLD);
            case "carry-on" -> new CarryOn();
            case "ask" -> new Ask(topic(text(node, "topic", where), where + ".topic"),
                    node.has("about") ? reference(node.get("about"), where + ".about") : null);
            case "avoid" -> new Avoid(reference(node.get("area"), where + ".area"));
            case "leave" -> new Leave(reference(node.get("what"), where + ".what"));
            case "only" -> new Only(reference(node.get("what"), where + ".what"));
            case "lift" -> new Lift(node.has("what") ? reference(node.get("what"), where + ".what") : null);
            case "when-see" -> new WhenSee(reference(node.get("what"), where + ".what"),
                    goal(node.get("then"), where + ".then"));
            default -> throw new IllegalArgumentException(where + ".goal must be one of sequence, go-to, cross, head, "
                    + "move, come-back, collect, turn, face, look-at, look-for, explore, follow, stop, wait, carry-on, "
                    + "ask, avoid, leave, only, lift, when-see; was '" + goal + "'");
        };
    }

    private static Reference reference(JsonNode node, String where) {
        if (node == null || !node.isObject()) {
            throw new IllegalArgumentException(where + " must be a reference, a JSON object with a \"kind\", was "
                    + node);
        }
        String kindName = text(node, "kind", where);
        Reference.Kind kind = Reference.Kind.ofWireName(kindName);
        if (kind == null) {
            throw new IllegalArgumentException(where + ".kind must be one of " + names(Reference.Kind.values())
                    + "; was '" + kindName + "'");
        }
        String name = node.has("name") ? text(node, "name", where) : null;
        Reference.Size size = node.has("size") ? named(Reference.Size.values(), text(node, "size", where),
                where + ".size") : null;
        Reference.Distance distance = node.has("distance") ? named(Reference.Distance.values(),
                text(node, "distance", where), where + ".distance") : null;
        Place place = null;
        if (node.has("place")) {
            JsonNode p = node.get("place");
            String at = where + ".place";
            if (!p.isObject()) {
                throw new IllegalArgumentException(at + " must be a JSON object with a \"relation\", was " + p);
            }
            Place.Relation relation = named(Place.Relation.values(), text(p, "relation", at), at + ".relation");
            place = new Place(relation, p.has("anchor") ? reference(p.get("anchor"), at + ".anchor") : null);
        }
        Integer ordinal = null;
        if (node.has("ordinal")) {
            JsonNode value = node.get("ordinal");
            if (!value.isIntegralNumber()) {
                throw new IllegalArgumentException(where + ".ordinal must be a whole number, was " + value);
            }
            ordinal = value.asInt();
        }
        String id = node.has("id") ? text(node, "id", where) : null;
        return new Reference(kind, name, size, distance, place, ordinal, id);
    }

    private static int count(JsonNode node, String where) {
        JsonNode count = node.get("count");
        if (count != null && count.isString() && count.asString().equals("all")) {
            return Collect.ALL;
        }
        if (count == null || !count.isIntegralNumber()) {
            throw new IllegalArgumentException(where + ".count must be a whole number or \"all\", was " + count);
        }
        return count.asInt();
    }

    private static String text(JsonNode node, String field, String where) {
        JsonNode value = node.get(field);
        if (value == null || !value.isString()) {
            throw new IllegalArgumentException(where + "." + field + " must be a string, was " + value);
        }
        return value.asString();
    }

    private static double number(JsonNode node, String field, String where) {
        JsonNode value = node.get(field);
        if (value == null || !value.isNumber()) {
            throw new IllegalArgumentException(where + "." + field + " must be a number, was " + value);
        }
        return value.asDouble();
    }

    private static Double optionalNumber(JsonNode node, String field, String where) {
        return node.has(field) ? number(node, field, where) : null;
    }

    private static Sector sector(String name, String where) {
        for (Sector sector : Sector.values()) {
            if (sector.wireName().equals(name)) {
                return sector;
            }
        }
        throw new IllegalArgumentException(where + " must be a compass direction such as north or south-east, was '"
                + name + "'");
    }

    private static RelativeMove.Direction direction(String name, String where) {
        for (RelativeMove.Direction direction : RelativeMove.Direction.values()) {
            if (direction.wireName().equals(name)) {
                return direction;
            }
        }
        throw new IllegalArgumentException(where + " must be forward, backward, left or right, was '" + name + "'");
    }

    private static Ask.Topic topic(String name, String where) {
        for (Ask.Topic topic : Ask.Topic.values()) {
            if (topic.wireName().equals(name)) {
                return topic;
            }
        }
        throw new IllegalArgumentException(where + " must be one of " + names(Ask.Topic.values()) + "; was '" + name
                + "'");
    }

    private static <E extends Enum<E>> E named(E[] values, String name, String where) {
        for (E value : values) {
            if (value.name().toLowerCase(Locale.ROOT).replace('_', '-').equals(name)) {
                return value;
            }
        }
        throw new IllegalArgumentException(where + " must be one of " + names(values) + "; was '" + name + "'");
    }

    private static String names(Enum<?>[] values) {
        List<String> names = new ArrayList<>();
        for (Enum<?> value : values) {
            names.add(value.name().toLowerCase(Locale.ROOT).replace('_', '-'));
        }
        return String.join(", ", names);
    }
}
