package io.orchard.agents.errand;

import io.orchard.agents.language.Goal;
import io.orchard.agents.language.Language;
import io.orchard.agents.language.Phrasing;
import io.orchard.agents.language.Reference;
import io.orchard.agents.map.Bearings;
import io.orchard.agents.map.RiverMap;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sector;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.function.Predicate;

/**
 * Which of several things the person meant: "Which tree do you mean? 1: the nearer one, 8 m to
 * the north-east; 2: the farther one, 30 m to the west, by the river." Each choice is described in
 * words the person can answer with (nearer, farther, left, right, a compass direction, what it is
 * by, its number or id), and {@link #read(String)} reads such an answer.
 */
final class Question {

    /** At most this many choices are offered, the nearest. */
    static final int MAX_CHOICES = 4;

    private static final String[] ORDINALS = {"first", "second", "third", "fourth"};
    private static final String[] GERMAN_ORDINALS = {"erst", "zweit", "dritt", "viert"};

    private final Goal goal;
    private final Reference.Kind kind;
    private final List<Known> choices;
    private final List<Double> bearings = new ArrayList<>();
    private final List<String> cues = new ArrayList<>();
    private final List<String> sectors = new ArrayList<>();
    private final String text;

    /**
     * @param goal    the goal to pursue once the person has chosen
     * @param choices the things that fit, nearest first
     */
    Question(Goal goal, Reference.Kind kind, List<Known> choices, WorldMemory memory, Grounder grounder, Speech speech) {
        this.goal = goal;
        this.kind = kind;
        this.choices = List.copyOf(choices.subList(0, Math.min(MAX_CHOICES, choices.size())));
        boolean de = speech.language() == Language.GERMAN;
        boolean feminine = kind == Reference.Kind.BRIDGE;
        Point2 here = memory.position();
        StringBuilder asked = new StringBuilder(de ? (feminine ? "Welche " : "Welchen ")
                + Phrasing.noun(Reference.to(kind), Language.GERMAN, Phrasing.Case.ACCUSATIVE).replaceFirst("^\\S+ ", "")
                + " meinst du? " : "Which " + kind.wireName() + " do you mean? ");
        for (int i = 0; i < this.choices.size(); i++) {
            Known choice = this.choices.get(i);
            bearings.add(Bearings.bearing(here, memory.heading(), choice.where()));
            sectors.add(Grounder.compass(here, choice.where()));
            cues.add(cue(choice, memory, grounder));
        }
        for (int i = 0; i < this.choices.size(); i++) {
            Known choice = this.choices.get(i);
            asked.append(i + 1).append(": ").append(de ? germanOrdinal(i, feminine) : ordinal(i)).append(", ")
                    .append(speech.bearing(here, choice.where()));
            if (this.choices.size() == 2 && Math.abs(bearings.get(0) - bearings.get(1)) > 0.2) {
                boolean left = bearings.get(i).equals(Math.max(bearings.get(0), bearings.get(1)));
                asked.append(de ? (feminine ? ", die " : ", den ") + (left ? "linke" : "rechte") + (feminine ? "" : "n")
                        : ", the " + (left ? "left" : "right") + " one");
            }
            if (!cues.get(i).isEmpty()) {
                asked.append(de ? (cues.get(i).equals("castle") ? ", beim Schloss" : ", beim Fluss")
                        : ", by the " + cues.get(i));
            }
            asked.append(" (").append(choice.id()).append(")").append(i + 1 < this.choices.size() ? "; " : ". ");
        }
        asked.append(de ? "Sag '" + (feminine ? "die nähere" : "den näheren") + "', eine Richtung oder eine Zahl."
                : "Say 'the nearer one', a direction or a number.");
        this.text = asked.toString();
    }

    /** The question, to say. */
    String text() {
        return text;
    }

    /** The goal the question is about. */
    Goal goal() {
        return goal;
    }

    /** The kind of thing asked about. */
    Reference.Kind kind() {
        return kind;
    }

    /** The thing an answer picks out; empty when it does not pick out exactly one. */
    Optional<Known> read(String answer) {
        String said = " " + java.text.Normalizer.normalize(answer.toLowerCase(Locale.ROOT), java.text.Normalizer.Form.NFD)
                .replaceAll("\\p{M}", "").replace("ß", "ss").replaceAll("[^a-z0-9 ]", " ").replaceAll("\\s+", " ") + " ";
        said = german(said);
        List<Predicate<Integer>> exact = new ArrayList<>();
        for (int i = 0; i < choices.size(); i++) {
            String id = " " + choices.get(i).id().toLowerCase(Locale.ROOT) + " ";
            int index = i;
            if (said.contains(id) || said.contains(" " + (i + 1) + " ") || said.contains(" " + ORDINALS[i] + " ")) {
                exact.add(n -> n == index);
            }
        }
        if (!exact.isEmpty()) {
            return pick(exact); // a number, an ordinal or an id says it all: "the second nearest" is the second
        }
        List<Predicate<Integer>> tests = new ArrayList<>();
        if (said.matches(".* (near|nearer|nearest|closer|closest) .*")) {
            tests.add(n -> n == 0);
        }
        if (said.matches(".* (far|farther|farthest|further|furthest|other) .*")) {
            tests.add(n -> n == choices.size() - 1);
        }
        if (said.contains(" left ")) {
            int left = extreme(true);
            tests.add(n -> n == left);
        }
        if (said.contains(" right ")) {
            int right = extreme(false);
            tests.add(n -> n == right);
        }
        String compass = compass(said);
        if (compass != null) {
            tests.add(n -> sectors.get(n).equals(compass) || sectors.get(n).contains(compass) && unique(compass));
        }
        for (String cue : List.of("castle", "river", "bridge", "table", "tree")) {
            if (said.contains(" " + cue + " ") && cues.contains(cue)) {
                tests.add(n -> cues.get(n).equals(cue));
            }
        }
        return pick(tests);
    }

    /** The one choice every test holds for; empty when there is no test, or none or several fit. */
    private Optional<Known> pick(List<Predicate<Integer>> tests) {
        if (tests.isEmpty()) {
            return Optional.empty();
        }
        Integer picked = null;
        for (int n = 0; n < choices.size(); n++) {
            int index = n;
            if (tests.stream().allMatch(t -> t.test(index))) {
                if (picked != null) {
                    return Optional.empty();
                }
                picked = n;
            }
        }
        return picked == null ? Optional.empty() : Optional.of(choices.get(picked));
    }

    private boolean unique(String compass) {
        return sectors.stream().filter(s -> s.contains(compass)).count() == 1;
    }

    private int extreme(boolean left) {
        int best = 0;
        for (int i = 1; i < bearings.size(); i++) {
            if (left ? bearings.get(i) > bearings.get(best) : bearings.get(i) < bearings.get(best)) {
                best = i;
            }
        }
        return best;
    }

    /** A German answer in the words the English one would use: "den näheren" is "the nearer", "links" "left". */
    private static String german(String said) {
        String english = said;
        String[][] words = {{"naher(e|en|er|es)?", "nearer"}, {"nachst(e|en|er|es)?", "nearest"},
            {"weiter(e|en|er|es)?", "farther"}, {"entfernter(e|en|er|es)?", "farther"}, {"ander(e|en|er|es)", "other"},
            {"link(e|en|er|es|s)", "left"}, {"recht(e|en|er|es|s)", "right"}, {"erst(e|en|er|es)", "first"},
            {"zweit(e|en|er|es)", "second"}, {"dritt(e|en|er|es)", "third"}, {"viert(e|en|er|es)", "fourth"},
            {"(norden|nord|nordlich(e|en)?)", "north"}, {"(suden|sud|sudlich(e|en)?)", "south"},
            {"(osten|ost|ostlich(e|en)?)", "east"}, {"(westen|west|westlich(e|en)?)", "west"},
            {"(nordosten|nordost|nordostlich(e|en)?)", "north-east"}, {"(nordwesten|nordwest|nordwestlich(e|en)?)",
                "north-west"}, {"(sudosten|sudost|sudostlich(e|en)?)", "south-east"},
            {"(sudwesten|sudwest|sudwestlich(e|en)?)", "south-west"}, {"schloss", "castle"}, {"fluss", "river"},
            {"brucke", "bridge"}, {"tisch", "table"}, {"baum", "tree"}};
        for (String[] word : words) {
            english = english.replaceAll(" " + word[0] + "(?= )", " " + word[1]);
        }
        return english;
    }

    private String germanOrdinal(int i, boolean feminine) {
        String article = feminine ? "die " : "den ";
        String ending = feminine ? "e" : "en";
        if (choices.size() == 2) {
            return article + (i == 0 ? "nähere" : "weitere") + (feminine ? "" : "n");
        }
        return article + (i == 0 ? "nächst" + ending : GERMAN_ORDINALS[i] + "nächst" + ending);
    }

    private String ordinal(int i) {
        if (choices.size() == 2) {
            return i == 0 ? "the nearer one" : "the farther one";
        }
        return i == 0 ? "the nearest one" : "the " + ORDINALS[i] + " nearest";
    }

    /** The compass direction an answer names, as a sector's wire name; null when none. */
    private static String compass(String said) {
        String joined = said.replace("north east", "north-east").replace("northeast", "north-east")
                .replace("north west", "north-west").replace("northwest", "north-west")
                .replace("south east", "south-east").replace("southeast", "south-east")
                .replace("south west", "south-west").replace("southwest", "south-west");
        for (Sector sector : Sector.values()) {
            if (sector.wireName().contains("-") && joined.contains(sector.wireName())) {
                return sector.wireName();
            }
        }
        for (Sector sector : Sector.values()) {
            if (joined.contains(" " + sector.wireName() + " ") || joined.contains(" " + sector.wireName() + "ern ")) {
                return sector.wireName();
            }
        }
        return null;
    }

    /** The landmark a choice stands by, in a word; empty when it stands by none the agent knows. */
    private static String cue(Known choice, WorldMemory memory, Grounder grounder) {
        Optional<Point2> castle = grounder.castle();
        if (castle.isPresent() && castle.get().distance(choice.where()) <= Grounder.CASTLE_SIZE + Grounder.NEAR) {
            return "castle";
        }
        if (choice.kind() != Reference.Kind.BRIDGE && memory.river().side(choice.where().x(), choice.where().z(),
                Grounder.NEAR) == RiverMap.Side.WATER) {
            return "river";
        }
        return "";
    }
}
