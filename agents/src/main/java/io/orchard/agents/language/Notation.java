package io.orchard.agents.language;

import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.stream.Collectors;

/**
 * Writes goals and references in the compact one-line notation of {@link Goal#notation()}, e.g.
 * {@code collect(3 banana on(table))}, {@code go-to(castle); collect(tomato)}. The grammar of
 * the notation is in {@code docs/instructions.md}.
 */
final class Notation {

    private Notation() {
    }

    static String of(Goal goal) {
        if (goal instanceof Sequence sequence) {
            // a condition's own steps run to the end of the line: one inside a sequence is bracketed
            return sequence.steps().stream().map(step -> step instanceof WhenSee ? "(" + of(step) + ")" : of(step))
                    .collect(Collectors.joining("; "));
        }
        if (goal instanceof GoTo goTo) {
            return "go-to(" + of(goTo.destination()) + ")";
        }
        if (goal instanceof Cross cross) {
            return "cross(" + of(cross.landmark()) + ")";
        }
        if (goal instanceof Head head) {
            return "head(" + head.direction().wireName() + distance(head.distance()) + ")";
        }
        if (goal instanceof RelativeMove move) {
            return "move(" + move.direction().wireName() + distance(move.distance()) + ")";
        }
        if (goal instanceof Collect collect) {
            String count = collect.isAll() ? "all " : collect.count() == 1 ? "" : collect.count() + " ";
            return "collect(" + count + of(collect.what()) + ")";
        }
        if (goal instanceof Turn turn) {
            return "turn(" + number(turn.degrees()) + ")";
        }
        if (goal instanceof Face face) {
            return "face(" + face.direction().wireName() + ")";
        }
        if (goal instanceof LookAt lookAt) {
            return "look-at(" + of(lookAt.target()) + ")";
        }
        if (goal instanceof LookFor lookFor) {
            return "look-for(" + of(lookFor.what()) + ")";
        }
        if (goal instanceof Explore explore) {
            return explore.area() == null ? "explore" : "explore(" + of(explore.area()) + ")";
        }
        if (goal instanceof Follow follow) {
            return "follow(" + of(follow.agent()) + ")";
        }
        if (goal instanceof Wait wait) {
            return wait.isUntilTold() ? "wait" : "wait(" + number(wait.seconds()) + ")";
        }
        if (goal instanceof ComeBack) {
            return "come-back";
        }
        if (goal instanceof Stop) {
            return "stop";
        }
        if (goal instanceof CarryOn) {
            return "carry-on";
        }
        if (goal instanceof Ask ask) {
            return "ask(" + ask.topic().wireName() + (ask.about() == null ? "" : ", " + of(ask.about())) + ")";
        }
        if (goal instanceof Avoid avoid) {
            return "avoid(" + of(avoid.area()) + ")";
        }
        if (goal instanceof Leave leave) {
            return "leave(" + of(leave.what()) + ")";
        }
        if (goal instanceof Only only) {
            return "only(" + of(only.what()) + ")";
        }
        if (goal instanceof Lift lift) {
            return lift.what() == null ? "lift" : "lift(" + of(lift.what()) + ")";
        }
        if (goal instanceof WhenSee when) {
            return "when-see(" + of(when.what()) + "): " + of(when.then());
        }
        throw new IllegalArgumentException("no notation for " + goal);
    }

    static String of(Reference reference) {
        if (reference.kind() == Reference.Kind.PLACE) {
            return of(reference.place());
        }
        StringBuilder text = new StringBuilder();
        if (reference.ordinal() != null) {
            text.append(ordinal(reference.ordinal())).append(' ');
        }
        if (reference.distance() != null) {
            text.append(reference.distance().wireName()).append(' ');
        }
        if (reference.size() != null) {
            text.append(reference.size().wireName()).append(' ');
        }
        text.append(reference.name() != null ? reference.name() : reference.kind().wireName());
        if (reference.id() != null) {
            text.append('#').append(reference.id());
        }
        if (reference.place() != null) {
            text.append(' ').append(of(reference.place()));
        }
        return text.toString();
    }

    static String of(Place place) {
        if (place.relation() == Place.Relation.ON_GROUND) {
            return "on-ground";
        }
        return place.relation().wireName() + "(" + (place.anchor() == null ? "here" : of(place.anchor())) + ")";
    }

    /** An ordinal as the notation writes it: 2nd, 3rd, 4th, 11th, 21st. */
    static String ordinal(int n) {
        String suffix = n % 100 >= 11 && n % 100 <= 13 ? "th" : switch (n % 10) {
            case 1 -> "st";
            case 2 -> "nd";
            case 3 -> "rd";
            default -> "th";
        };
        return n + suffix;
    }

    /** A number without needless digits: 90, 22.5, 0.333333. */
    static String number(double value) {
        return BigDecimal.valueOf(value).setScale(6, RoundingMode.HALF_EVEN).stripTrailingZeros().toPlainString();
    }

    private static String distance(Double distance) {
        return distance == null ? "" : ", " + number(distance);
    }
}
