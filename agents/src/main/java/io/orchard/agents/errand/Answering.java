package io.orchard.agents.errand;

import io.orchard.agents.language.Ask;
import io.orchard.agents.language.Language;
import io.orchard.agents.language.Phrasing;
import io.orchard.agents.language.Reference;
import io.orchard.agents.language.Reference.Kind;
import io.orchard.agents.map.KnownBridge;
import io.orchard.agents.map.KnownFruit;
import io.orchard.agents.map.KnownObstacle;
import io.orchard.agents.map.RiverMap;
import io.orchard.agents.map.SeenAgent;
import io.orchard.agents.map.ShoreSighting;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sector;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * Answers the questions a person asks an agent ({@link Ask}) from its own state and memory, in a
 * short sentence in the world's words: what it sees, where it is ("north of the river, near the
 * castle"), what it has collected, what it is doing and why, why it stopped, where something is.
 */
final class Answering {

    /** What the errands tell the answers about themselves. */
    interface State {
        /** What the agent is doing for the person, as its restatement says it; null when nothing. */
        String doing();

        /** How the last errand ended, in the agent's words; empty when none has ended. */
        String lastOutcome();

        /** Whether the person told the agent to stop, and it has stood still since. */
        boolean stopped();

        /** The fruit the agent has collected, by kind. */
        Map<FruitKind, Integer> collected();

        /** The rules in force, as the agent states them. */
        String rules();
    }

    /** Fruit hangs in trees from this height up; below it lies on tables (or the ground). */
    private static final double TREE_LOW = 1.45;

    private final Kit kit;
    private final State state;

    Answering(Kit kit, State state) {
        this.kit = kit;
        this.state = state;
    }

    private boolean de() {
        return kit.language == Language.GERMAN;
    }

    /** The answer to the question, one or two short sentences, in the language spoken. */
    String answer(Ask ask) {
        return switch (ask.topic()) {
            case SEE -> ask.about() == null ? sight() : seeing(ask.about());
            case WHERE -> (de() ? "Ich bin " : "I'm ") + whereabouts(kit.here()) + ".";
            case COLLECTED -> collected(ask.about());
            case DOING -> doing();
            case WHY -> why();
            case WHERE_IS -> whereIs(ask.about());
            case CAN -> de() ? "Ich kann zu Orten gehen, den Fluss überqueren, Früchte sammeln, erkunden, anderen "
                    + "Agenten folgen, mich drehen, warten und anhalten; und du kannst mich fragen, was ich sehe, wo ich "
                    + "bin, was ich gesammelt habe, was ich mache und warum, und wo Dinge sind."
                    : "I can go to places, cross the river, collect fruit, explore, follow other agents, turn, "
                    + "wait and stop; and you can ask me what I see, where I am, what I have collected, what I'm "
                    + "doing and why, and where things are.";
            case HEADING -> de() ? "Ich schaue nach " + kit.speech.compass(compass(kit.motor.heading())) + "."
                    : "I'm facing " + compass(kit.motor.heading()) + ".";
            case RULES -> state.rules();
        };
    }

    private String sight() {
        WorldMemory memory = kit.memory;
        Point2 here = kit.here();
        List<String> parts = new ArrayList<>();
        List<KnownFruit> fruit = inSight();
        if (!fruit.isEmpty()) {
            KnownFruit nearest = fruit.get(0);
            kit.mention(Known.fruit(nearest));
            parts.add(counted(fruit) + (de() ? " (die nächste " : " (the nearest ") + fruitWords(nearest) + ", "
                    + kit.speech.bearing(here, nearest.ground()) + ")");
        }
        double range = memory.sight().range();
        long trees = memory.obstacles().stream().filter(KnownObstacle::isTree)
                .filter(o -> o.centre().distance(here) <= range).count();
        long tables = memory.obstacles().stream().filter(o -> !o.isTree())
                .filter(o -> o.centre().distance(here) <= range).count();
        if (trees > 0) {
            parts.add(de() ? (trees == 1 ? "einen Baum" : trees + " Bäume") : trees == 1 ? "a tree" : trees + " trees");
        }
        if (tables > 0) {
            parts.add(de() ? (tables == 1 ? "einen Tisch" : tables + " Tische")
                    : tables == 1 ? "a table" : tables + " tables");
        }
        for (SeenAgent agent : memory.agents()) {
            if (agent.tick() == memory.tick()) {
                parts.add(agent.name());
            }
        }
        kit.grounder.castle().filter(c -> c.distance(here) <= range)
                .ifPresent(c -> parts.add((de() ? "das Schloss " : "the castle ") + kit.speech.bearing(here, c)));
        nearestShore().filter(s -> s.distance(here) <= range)
                .ifPresent(s -> parts.add((de() ? "den Fluss " : "the river ") + kit.speech.bearing(here, s)));
        if (parts.isEmpty()) {
            return de() ? "Ich sehe nichts als offenes Gelände." : "I see nothing but open ground.";
        }
        return (de() ? "Ich sehe " : "I see ") + kit.speech.list(parts) + ".";
    }

    private String seeing(Reference about) {
        Point2 here = kit.here();
        if (about.isFruit()) {
            List<KnownFruit> fruit = inSight().stream().filter(f -> about.kind().matches(f.kind())).toList();
            if (!fruit.isEmpty()) {
                return (de() ? "Ja: " : "Yes: ") + counted(fruit) + (de() ? ", die nächste " : ", the nearest ")
                        + kit.speech.bearing(here, fruit.get(0).ground()) + ".";
            }
            return (de() ? "Nein, ich sehe gerade keine " : "No, I don't see ")
                    + kit.speech.bare(about.withDistance(null)) + (de() ? ". " : " now. ") + whereIs(about);
        }
        Grounding grounding = kit.grounder.ground(about);
        List<Known> known = grounding instanceof Grounding.Found found ? found.matches()
                : grounding instanceof Grounding.Ambiguous ambiguous ? ambiguous.choices() : List.of();
        double range = kit.memory.sight().range();
        Optional<Known> seen = known.stream().filter(k -> k.where().distance(here) <= range + k.size()).findFirst();
        if (seen.isPresent()) {
            kit.mention(seen.get());
            return (de() ? "Ja: " : "Yes: ") + kit.speech.thing(seen.get()) + ", "
                    + kit.speech.bearing(here, seen.get().where()) + ".";
        }
        return (de() ? "Nein, nicht von hier aus. " : "No, not from here. ") + whereIs(about);
    }

    private String collected(Reference about) {
        Map<FruitKind, Integer> collected = state.collected();
        if (about != null && about.kind().fruitKind() != null) {
            int n = collected.getOrDefault(about.kind().fruitKind(), 0);
            if (de()) {
                return n == 0 ? "Ich habe noch keine " + kit.speech.plural(about.kind().fruitKind()) + " gesammelt."
                        : "Ich habe " + kit.speech.count(n, about.kind().fruitKind()) + " gesammelt.";
            }
            return n == 0 ? "I haven't collected any " + kit.speech.plural(about.kind().fruitKind()) + " yet."
                    : "I have collected " + kit.speech.count(n, about.kind().fruitKind()) + ".";
        }
        List<String> parts = new ArrayList<>();
        int total = 0;
        for (FruitKind kind : FruitKind.values()) {
            int n = collected.getOrDefault(kind, 0);
            if (n > 0) {
                parts.add(kit.speech.count(n, kind));
                total += n;
            }
        }
        if (total == 0) {
            return de() ? "Ich habe noch keine Früchte gesammelt." : "I haven't collected any fruit yet.";
        }
        if (de()) {
            return "Ich habe " + total + (total == 1 ? " Frucht gesammelt: " : " Früchte gesammelt: ")
                    + kit.speech.list(parts) + ".";
        }
        return "I have collected " + total + (total == 1 ? " fruit: " : " fruits: ") + kit.speech.list(parts) + ".";
    }

    private String doing() {
        String doing = state.doing();
        if (doing != null) {
            return de() ? capital(doing) + ", weil du mich darum gebeten hast."
                    : "I'm " + doing + ", because you asked me to.";
        }
        if (state.stopped()) {
            return de() ? "Ich stehe still, weil du mir gesagt hast, dass ich anhalten soll."
                    : "I'm standing still, because you told me to stop.";
        }
        return de() ? "Nichts, worum du gebeten hast: Ich bin auf mich gestellt und suche Früchte, weil ich das tue, wenn "
                + "mir niemand etwas anderes sagt." : "Nothing you asked: I'm on my own, looking for fruit to collect, "
                + "because that is what I do when no one tells me otherwise.";
    }

    private String why() {
        if (state.stopped()) {
            return de() ? "Du hast mir gesagt, dass ich anhalten soll; sag mir, was ich tun soll, oder sag 'mach weiter'."
                    : "You told me to stop; tell me what to do, or say 'carry on'.";
        }
        String doing = state.doing();
        if (doing != null) {
            return de() ? "Ich habe nicht angehalten: " + doing + "." : "I haven't stopped: I'm " + doing + ".";
        }
        String last = state.lastOutcome();
        if (!last.isEmpty()) {
            return (de() ? "Mein letzter Auftrag endete so: " : "My last errand ended so: ") + last;
        }
        return de() ? "Nichts hat mich angehalten; ich bin auf mich gestellt und suche Früchte."
                : "Nothing stopped me; I'm on my own, looking for fruit to collect.";
    }

    private String whereIs(Reference about) {
        Point2 here = kit.here();
        if (about.kind() == Kind.START) {
            return (de() ? "Wo ich angefangen habe, ist " : "Where I started is ")
                    + kit.speech.bearing(here, kit.grounder.start()) + ".";
        }
        List<Known> fits = kit.grounder.fitting(about);
        List<Known> chosen = fits.isEmpty() ? fits : kit.grounder.select(about, fits);
        if (chosen.isEmpty()) {
            if (de()) {
                return about.isFruit() ? "Ich kenne noch keine " + kit.speech.bare(about.withDistance(null)) + "."
                        : "Ich weiß noch nicht, wo " + Phrasing.noun(about, Language.GERMAN, Phrasing.Case.NOMINATIVE)
                        + " ist.";
            }
            return "I don't know of " + (about.isFruit() && fits.isEmpty() ? "any "
                    + kit.speech.bare(about.withDistance(null)) : about.words()) + " yet.";
        }
        Known first = chosen.get(0);
        kit.mention(first);
        String at = kit.speech.bearing(here, first.where());
        if (about.isFruit() && chosen.size() > 1) {
            return de() ? "Ich kenne " + chosen.size() + "; die nächste ist " + at + ", " + whereabouts(first.where())
                    + "." : "I know of " + chosen.size() + "; the nearest is " + at + ", " + whereabouts(first.where())
                    + ".";
        }
        return (first.kind() == Kind.AGENT ? first.id() : capital(kit.speech.thing(first))) + (de() ? " ist " : " is ")
                + at + ", " + whereabouts(first.where()) + ".";
    }

    /** Where a point is, in the world's words: "north of the river, near the castle, by the bridge B2". */
    String whereabouts(Point2 p) {
        List<String> parts = new ArrayList<>();
        Optional<Point2> shore = nearestShore();
        RiverMap.Side side = kit.memory.river().side(p.x(), p.z(), 0);
        if (side == RiverMap.Side.WATER) {
            parts.add(de() ? "im Fluss" : "in the river");
        } else if (shore.isPresent() && (side == RiverMap.Side.LOW || side == RiverMap.Side.HIGH)) {
            parts.add(kit.speech.compassOf(Grounder.compass(shore.get(), p)) + (de() ? " des Flusses" : " of the river"));
        }
        kit.grounder.castle().ifPresent(castle -> parts.add(castle.distance(p) <= Grounder.CASTLE_SIZE + Grounder.NEAR
                ? (de() ? "in der Nähe des Schlosses" : "near the castle")
                : kit.speech.compassOf(Grounder.compass(castle, p)) + (de() ? " des Schlosses" : " of the castle")));
        kit.memory.bridges().stream().min(Comparator.comparingDouble((KnownBridge b) -> b.middle().distance(p)))
                .filter(b -> b.middle().distance(p) <= b.length() / 2 + Grounder.NEAR)
                .ifPresent(b -> parts.add((de() ? "bei der Brücke " : "by the bridge ") + b.id()));
        boolean forest = kit.memory.obstacles().stream().filter(KnownObstacle::isTree)
                .filter(t -> t.centre().distance(p) <= t.radius() + 4).count() >= 2;
        if (forest) {
            parts.add(de() ? "im Wald" : "in the forest");
        }
        if (parts.isEmpty()) {
            return String.format(Locale.ROOT, de() ? "bei x %.0f, z %.0f, und ich kenne keine Landmarke in der Nähe"
                    : "at x %.0f, z %.0f, and I know no landmark near", p.x(), p.z());
        }
        return String.join(", ", parts);
    }

    private List<KnownFruit> inSight() {
        Point2 here = kit.here();
        return kit.memory.fruit().stream().filter(f -> f.seenTick() == kit.memory.tick())
                .sorted(Comparator.comparingDouble(f -> f.ground().distance(here))).toList();
    }

    private Optional<Point2> nearestShore() {
        Point2 here = kit.here();
        return kit.memory.river().sightings().stream().map(ShoreSighting::shore)
                .min(Comparator.comparingDouble(s -> s.distance(here)));
    }

    private String counted(List<KnownFruit> fruit) {
        List<String> parts = new ArrayList<>();
        for (FruitKind kind : FruitKind.values()) {
            int n = (int) fruit.stream().filter(f -> f.kind() == kind).count();
            if (n > 0) {
                parts.add(kit.speech.count(n, kind));
            }
        }
        return kit.speech.list(parts);
    }

    private String fruitWords(KnownFruit fruit) {
        if (de()) {
            String kind = Phrasing.noun(Reference.to(Kind.valueOf(fruit.kind().name())), Language.GERMAN,
                    Phrasing.Case.NOMINATIVE).replaceFirst("^eine ", "");
            return kind + (fruit.support() == null ? " auf dem Boden" : fruit.height() > TREE_LOW ? " in einem Baum"
                    : " auf einem Tisch");
        }
        String kind = fruit.kind().name().toLowerCase(Locale.ROOT);
        if (fruit.support() == null) {
            return kind + " on the ground";
        }
        return kind + (fruit.height() > TREE_LOW ? " in a tree" : " on a table");
    }

    /** The compass direction a heading faces: "north-east". */
    static String compass(double heading) {
        return Sector.of(-Math.sin(heading), -Math.cos(heading)).wireName();
    }

    private static String capital(String text) {
        return Character.toUpperCase(text.charAt(0)) + text.substring(1);
    }

}
