package io.orchard.agents.language;

import io.orchard.protocol.value.Sector;
import java.util.Arrays;
import java.util.List;
import java.util.function.Function;
import java.util.stream.Stream;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.ArrayNode;
import tools.jackson.databind.node.ObjectNode;

/**
 * The JSON Schema (draft 2020-12) of the goals {@link GoalJson} writes and {@link GoalJson#read}
 * accepts, made from the goals' own enumerations so that it cannot fall behind them. It is what a
 * language model's answer is checked against ({@link LanguageModelInterpreter}) and is published
 * as {@code docs/goal.schema.json}.
 */
public final class GoalSchema {

    private static final JsonMapper MAPPER = JsonMapper.builder().build();

    private GoalSchema() {
    }

    /** The schema, as indented JSON. */
    public static String json() {
        return MAPPER.writerWithDefaultPrettyPrinter().writeValueAsString(tree()) + "\n";
    }

    static ObjectNode tree() {
        ObjectNode schema = MAPPER.createObjectNode();
        schema.put("$schema", "https://json-schema.org/draft/2020-12/schema");
        schema.put("$id", "https://orchard.example/goal.schema.json");
        schema.put("title", "Orchard goal");
        schema.put("description", "What a person's instruction asks an agent to do, as GoalJson writes it "
                + "(docs/instructions.md).");
        schema.put("$ref", "#/$defs/goal");
        ObjectNode defs = schema.putObject("$defs");
        defs.set("goal", goal(true, true));
        defs.set("step", goal(false, true));
        defs.set("action", goal(true, false));
        defs.set("actionStep", goal(false, false));
        defs.set("reference", reference(Stream.of(Reference.Kind.values())));
        defs.set("fruitReference", reference(Stream.of(Reference.Kind.values()).filter(Reference.Kind::isFruit)));
        return schema;
    }

    /**
     * One of the goals; a sequence only when {@code withSequence}, since a step is never one; the rules,
     * lifting them, questions and carrying on only when {@code withRules}, since what a condition does is
     * an action.
     */
    private static ObjectNode goal(boolean withSequence, boolean withRules) {
        ObjectNode goal = MAPPER.createObjectNode();
        ArrayNode oneOf = goal.putArray("oneOf");
        if (withSequence) {
            ObjectNode sequence = kind("sequence", "Several goals, one after the other.");
            ObjectNode steps = property(sequence, "steps", true);
            steps.put("type", "array");
            steps.put("minItems", 2);
            steps.putObject("items").put("$ref", withRules ? "#/$defs/step" : "#/$defs/actionStep");
            oneOf.add(sequence);
        }
        actions(oneOf);
        if (withRules) {
            oneOf.add(kind("carry-on", "Go back to what it was doing by itself."));
            ObjectNode ask = kind("ask", "A question, answered from what the agent knows.");
            names(property(ask, "topic", true), Ask.Topic.values(), Ask.Topic::wireName);
            property(ask, "about", false).put("$ref", "#/$defs/reference");
            oneOf.add(ask);
            ObjectNode avoid = kind("avoid", "A rule until lifted: never go into an area.");
            property(avoid, "area", true).put("$ref", "#/$defs/reference");
            oneOf.add(avoid);
            ObjectNode leave = kind("leave", "A rule until lifted: take no fruit that fits.");
            property(leave, "what", true).put("$ref", "#/$defs/fruitReference");
            oneOf.add(leave);
            ObjectNode only = kind("only", "A rule until lifted: take only fruit that fits.");
            property(only, "what", true).put("$ref", "#/$defs/fruitReference");
            oneOf.add(only);
            ObjectNode lift = kind("lift", "Lift the rules about an area or fruit, or every rule without one.");
            property(lift, "what", false).put("$ref", "#/$defs/reference");
            oneOf.add(lift);
            ObjectNode when = kind("when-see", "A condition until lifted: each time something that fits is seen, "
                    + "do the action for it.");
            property(when, "what", true).put("$ref", "#/$defs/reference");
            property(when, "then", true).put("$ref", "#/$defs/action");
            oneOf.add(when);
        }
        return goal;
    }

    /** The goals that act: every one but the rules, lifting, questions, carrying on and sequences. */
    private static void actions(ArrayNode oneOf) {
        ObjectNode goTo = kind("go-to", "Walk to a place or an object.");
        property(goTo, "destination", true).put("$ref", "#/$defs/reference");
        oneOf.add(goTo);
        ObjectNode cross = kind("cross", "Cross the river, by a bridge.");
        property(cross, "landmark", true).put("$ref", "#/$defs/reference");
        oneOf.add(cross);
        ObjectNode head = kind("head", "Walk on in a compass direction, as far as it goes or for a distance.");
        names(property(head, "direction", true), Sector.values(), Sector::wireName);
        distance(property(head, "distance", false));
        oneOf.add(head);
        ObjectNode move = kind("move", "Step relative to the agent's own heading.");
        names(property(move, "direction", true), RelativeMove.Direction.values(), RelativeMove.Direction::wireName);
        distance(property(move, "distance", false));
        oneOf.add(move);
        oneOf.add(kind("come-back", "Come back to the person."));
        ObjectNode collect = kind("collect", "Collect fruit.");
        property(collect, "what", true).put("$ref", "#/$defs/fruitReference");
        ArrayNode count = property(collect, "count", true).putArray("oneOf");
        count.addObject().put("type", "integer").put("minimum", 1);
        count.addObject().put("const", "all");
        oneOf.add(collect);
        ObjectNode turn = kind("turn", "Turn on the spot, counterclockwise seen from above for a positive angle.");
        property(turn, "radians", true).put("type", "number");
        property(turn, "degrees", false).put("type", "number");
        oneOf.add(turn);
        ObjectNode face = kind("face", "Turn to face a compass direction.");
        names(property(face, "direction", true), Sector.values(), Sector::wireName);
        oneOf.add(face);
        ObjectNode lookAt = kind("look-at", "Turn to face an object.");
        property(lookAt, "target", true).put("$ref", "#/$defs/reference");
        oneOf.add(lookAt);
        ObjectNode lookFor = kind("look-for", "Search for something until it is seen.");
        property(lookFor, "what", true).put("$ref", "#/$defs/reference");
        oneOf.add(lookFor);
        ObjectNode explore = kind("explore", "Look around the world, or an area of it.");
        property(explore, "area", false).put("$ref", "#/$defs/reference");
        oneOf.add(explore);
        ObjectNode follow = kind("follow", "Follow an agent.");
        property(follow, "agent", true).put("$ref", "#/$defs/reference");
        oneOf.add(follow);
        oneOf.add(kind("stop", "Stop and stay until told otherwise."));
        ObjectNode wait = kind("wait", "Stay where it is, for some seconds or until told otherwise.");
        property(wait, "seconds", false).put("type", "number").put("minimum", 0);
        oneOf.add(wait);
    }

    /** A goal's object: its {@code "goal"} discriminator and no fields but those it declares. */
    private static ObjectNode kind(String name, String description) {
        ObjectNode kind = MAPPER.createObjectNode();
        kind.put("description", description);
        kind.put("type", "object");
        kind.putObject("properties").putObject("goal").put("const", name);
        kind.putArray("required").add("goal");
        kind.put("additionalProperties", false);
        return kind;
    }

    private static ObjectNode property(ObjectNode object, String name, boolean required) {
        if (required) {
            ((ArrayNode) object.get("required")).add(name);
        }
        return ((ObjectNode) object.get("properties")).putObject(name);
    }

    private static void distance(ObjectNode distance) {
        distance.put("type", "number");
        distance.put("exclusiveMinimum", 0);
        distance.put("maximum", RelativeMove.MAX_DISTANCE);
    }

    private static ObjectNode reference(Stream<Reference.Kind> kinds) {
        ObjectNode reference = MAPPER.createObjectNode();
        reference.put("type", "object");
        ObjectNode properties = reference.putObject("properties");
        names(properties.putObject("kind"), kinds.toArray(Reference.Kind[]::new), Reference.Kind::wireName);
        properties.putObject("name").put("type", "string").put("minLength", 1);
        names(properties.putObject("size"), Reference.Size.values(), Reference.Size::wireName);
        names(properties.putObject("distance"), Reference.Distance.values(), Reference.Distance::wireName);
        properties.putObject("ordinal").put("type", "integer").put("minimum", 1).put("maximum", Reference.MAX_ORDINAL);
        properties.putObject("id").put("type", "string").put("minLength", 1);
        ObjectNode place = properties.putObject("place");
        place.put("type", "object");
        ObjectNode placeProperties = place.putObject("properties");
        names(placeProperties.putObject("relation"), Place.Relation.values(), Place.Relation::wireName);
        placeProperties.putObject("anchor").put("$ref", "#/$defs/reference");
        place.putArray("required").add("relation");
        place.put("additionalProperties", false);
        reference.putArray("required").add("kind");
        reference.putObject("dependentRequired").putArray("ordinal").add("distance");
        reference.put("additionalProperties", false);
        return reference;
    }

    private static <E> void names(ObjectNode property, E[] values, Function<E, String> wireName) {
        property.put("type", "string");
        ArrayNode names = property.putArray("enum");
        List<String> all = Arrays.stream(values).map(wireName).toList();
        all.forEach(names::add);
    }
}
