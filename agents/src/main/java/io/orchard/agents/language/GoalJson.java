package io.orchard.agents.language;

import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.ArrayNode;
import tools.jackson.databind.node.ObjectNode;

/**
 * Writes goals as JSON: an object with a {@code "goal"} discriminator ({@code "collect"},
 * {@code "go-to"}, {@code "sequence"}, ...) and the goal's fields, references as objects with
 * {@code "kind"} and only the parts an instruction said. The output is deterministic: fields
 * always come in the same order, so equal goals give equal text. The forms are documented, with
 * examples, in {@code docs/instructions.md}.
 *
 * <pre>{@code
 * {"goal":"collect",
 *  "what":{"kind":"banana","distance":"nearest","place":{"relation":"on","anchor":{"kind":"table"}}},
 *  "count":1}
 * }</pre>
 */
public final class GoalJson {

    private static final JsonMapper MAPPER = JsonMapper.builder().build();

    private GoalJson() {
    }

    /** The goal as one line of JSON. */
    public static String write(Goal goal) {
        return MAPPER.writeValueAsString(tree(goal));
    }

    /**
     * The goal this JSON describes, as {@link #write} writes it: the inverse of {@code write}, so
     * that {@code read(write(goal))} equals {@code goal}.
     *
     * @throws IllegalArgumentException when the text is not JSON or not a goal; the message names
     *                                  the bad value and what was expected
     */
    public static Goal read(String json) {
        return GoalReader.read(json);
    }

    /** The goal as indented JSON, for people to read. */
    public static String writePretty(Goal goal) {
        return MAPPER.writerWithDefaultPrettyPrinter().writeValueAsString(tree(goal));
    }

    static ObjectNode tree(Goal goal) {
        ObjectNode node = MAPPER.createObjectNode();
        if (goal instanceof Sequence sequence) {
            node.put("goal", "sequence");
            ArrayNode steps = node.putArray("steps");
            sequence.steps().forEach(step -> steps.add(tree(step)));
        } else if (goal instanceof GoTo goTo) {
            node.put("goal", "go-to");
            node.set("destination", tree(goTo.destination()));
        } else if (goal instanceof Cross cross) {
            node.put("goal", "cross");
            node.set("landmark", tree(cross.landmark()));
        } else if (goal instanceof Head head) {
            node.put("goal", "head");
            node.put("direction", head.direction().wireName());
            if (head.distance() != null) {
                node.put("distance", head.distance());
            }
        } else if (goal instanceof RelativeMove move) {
            node.put("goal", "move");
            node.put("direction", move.direction().wireName());
            if (move.distance() != null) {
                node.put("distance", move.distance());
            }
        } else if (goal instanceof ComeBack) {
            node.put("goal", "come-back");
        } else if (goal instanceof Collect collect) {
            node.put("goal", "collect");
            node.set("what", tree(collect.what()));
            if (collect.isAll()) {
                node.put("count", "all");
            } else {
                node.put("count", collect.count());
            }
        } else if (goal instanceof Turn turn) {
            node.put("goal", "turn");
            node.put("radians", turn.radians());
            node.put("degrees", Math.round(turn.degrees() * 1e6) / 1e6);
        } else if (goal instanceof Face face) {
            node.put("goal", "face");
            node.put("direction", face.direction().wireName());
        } else if (goal instanceof LookAt lookAt) {
            node.put("goal", "look-at");
            node.set("target", tree(lookAt.target()));
        } else if (goal instanceof LookFor lookFor) {
            node.put("goal", "look-for");
            node.set("what", tree(lookFor.what()));
        } else if (goal instanceof Explore explore) {
            node.put("goal", "explore");
            if (explore.area() != null) {
                node.set("area", tree(explore.area()));
            }
        } else if (goal instanceof Follow follow) {
            node.put("goal", "follow");
            node.set("agent", tree(follow.agent()));
        } else if (goal instanceof Stop) {
            node.put("goal", "stop");
        } else if (goal instanceof Wait wait) {
            node.put("goal", "wait");
            if (!wait.isUntilTold()) {
                node.put("seconds", wait.seconds());
            }
        } else if (goal instanceof CarryOn) {
            node.put("goal", "carry-on");
        } else if (goal instanceof Ask ask) {
            node.put("goal", "ask");
            node.put("topic", ask.topic().wireName());
            if (ask.about() != null) {
                node.set("about", tree(ask.about()));
            }
        } else if (goal instanceof Avoid avoid) {
            node.put("goal", "avoid");
            node.set("area", tree(avoid.area()));
        } else if (goal instanceof Leave leave) {
            node.put("goal", "leave");
            node.set("what", tree(leave.what()));
        } else if (goal instanceof Only only) {
            node.put("goal", "only");
            node.set("what", tree(only.what()));
        } else if (goal instanceof Lift lift) {
            node.put("goal", "lift");
            if (lift.what() != null) {
                node.set("what", tree(lift.what()));
            }
        } else if (goal instanceof WhenSee when) {
            node.put("goal", "when-see");
            node.set("what", tree(when.what()));
            node.set("then", tree(when.then()));
        }
        return node;
    }

    static ObjectNode tree(Reference reference) {
        ObjectNode node = MAPPER.createObjectNode();
        node.put("kind", reference.kind().wireName());
        if (reference.name() != null) {
            node.put("name", reference.name());
        }
        if (reference.size() != null) {
            node.put("size", reference.size().wireName());
        }
        if (reference.distance() != null) {
            node.put("distance", reference.distance().wireName());
        }
        if (reference.ordinal() != null) {
            node.put("ordinal", reference.ordinal());
        }
        if (reference.id() != null) {
            node.put("id", reference.id());
        }
        if (reference.place() != null) {
            ObjectNode place = node.putObject("place");
            place.put("relation", reference.place().relation().wireName());
            if (reference.place().anchor() != null) {
                place.set("anchor", tree(reference.place().anchor()));
            }
        }
        return node;
    }
}
