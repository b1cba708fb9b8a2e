package io.orchard.agents.language;

import io.orchard.agents.language.Reference.Distance;
import io.orchard.agents.language.Reference.Kind;
import io.orchard.agents.language.Reference.Size;
import java.util.List;
import java.util.Locale;

/**
 * The agent's German restatement of a goal, as {@link Restatement} gives the English one: "Ich hebe
 * die nächste Banane auf, die auf einem Tisch liegt.", "Ich gehe zum Schloss, dann hebe ich eine
 * Tomate auf." Nouns take the article, case and adjective endings German asks for.
 */
final class GermanRestatement {

    /** The grammatical cases. */
    enum Case { NOM, ACC, DAT, GEN }

    /** One clause of a restatement: its verb, and what follows it ("hebe", " eine Tomate auf"). */
    private record Clause(String verb, String rest) {

        String first() {
            return "ich " + verb + rest;
        }

        String inverted() {
            return verb + " ich" + rest;
        }
    }

    private GermanRestatement() {
    }

    static String of(Goal goal) {
        String text;
        if (goal instanceof Rule || goal instanceof Lift) {
            text = rule(goal);
        } else if (goal instanceof Sequence sequence) {
            StringBuilder steps = new StringBuilder();
            Goal previous = null;
            for (Goal step : sequence.steps()) {
                boolean rule = step instanceof Rule || step instanceof Lift;
                if (previous == null) {
                    steps.append(rule ? rule(step) : clause(step).first());
                } else if (rule || previous instanceof Rule || previous instanceof Lift) {
                    steps.append("; ").append(rule ? rule(step) : clause(step).first());
                } else {
                    steps.append(", dann ").append(clause(step).inverted());
                }
                previous = step;
            }
            text = steps.toString();
        } else if (goal instanceof Ask ask) {
            text = asked(ask);
        } else {
            text = clause(goal).first();
        }
        return Character.toUpperCase(text.charAt(0)) + text.substring(1) + ".";
    }

    /** A rule as the agent takes it on: "ab jetzt gehe ich nicht mehr in die Nähe des Flusses". */
    static String rule(Goal goal) {
        if (goal instanceof Avoid avoid) {
            Reference area = avoid.area();
            Place place = area.place();
            if (area.kind() == Kind.PLACE && place.relation() == Place.Relation.BEYOND && place.anchor() != null
                    && (place.anchor().kind() == Kind.RIVER || place.anchor().kind() == Kind.BRIDGE)) {
                return "ab jetzt bleibe ich auf dieser Seite " + noun(place.anchor(), Case.GEN);
            }
            return "ab jetzt gehe ich nicht mehr " + where(area);
        }
        if (goal instanceof Leave leave) {
            return "ab jetzt lasse ich " + all(leave.what()) + " liegen";
        }
        if (goal instanceof Only only) {
            return "ab jetzt sammle ich nur noch " + plural(only.what(), Case.ACC);
        }
        if (goal instanceof WhenSee when) {
            return "ab jetzt: immer wenn ich " + noun(when.what(), Case.ACC) + " sehe, " + then(when);
        }
        if (goal instanceof Lift lift) {
            if (lift.what() == null) {
                return "in Ordnung: Ich habe alle meine Regeln vergessen";
            }
            return "in Ordnung: Ich darf wieder " + (lift.what().isFruit() ? plural(lift.what(), Case.ACC) + " nehmen"
                    : where(lift.what()) + " gehen");
        }
        return clause(goal).first();
    }

    /** A rule as it holds: "ich gehe nicht in die Nähe des Flusses". */
    static String statement(Rule rule) {
        String text = rule(rule);
        if (text.startsWith("ab jetzt: ")) {
            return text.substring("ab jetzt: ".length());
        }
        // "ab jetzt gehe ich ..." -> "ich gehe ..."
        String rest = text.substring("ab jetzt ".length());
        int space = rest.indexOf(' ');
        String verb = rest.substring(0, space);
        return "ich " + verb + rest.substring(space + " ich".length()).replace(" nicht mehr ", " nicht ")
                .replace(" nur noch ", " nur ");
    }

    /** A rule as a reason: "deine Regel, nicht in die Nähe des Flusses zu gehen". */
    static String reason(Rule rule) {
        return "deine Regel '" + statement(rule) + "'";
    }

    private static String then(WhenSee when) {
        List<Goal> steps = when.then() instanceof Sequence sequence ? sequence.steps() : List.of(when.then());
        StringBuilder text = new StringBuilder();
        for (Goal step : steps) {
            Clause clause = clause(step);
            String noun = noun(when.what(), Case.ACC);
            String dative = noun(when.what(), Case.DAT);
            String pronoun = pronoun(when.what(), Case.ACC);
            String rest = clause.rest().replace(" zu " + dative, " dorthin").replace(" zum " + dative.replace("dem ", ""),
                    " dorthin");
            rest = step instanceof Follow ? rest.replace(dative, pronoun(when.what(), Case.DAT))
                    : rest.replace(noun, pronoun).replace(dative, pronoun(when.what(), Case.DAT));
            text.append(text.length() == 0 ? "" : ", dann ").append(new Clause(clause.verb(), rest).inverted());
        }
        return text.toString();
    }

    private static String pronoun(Reference what, Case grammatical) {
        Noun noun = Noun.of(what.kind());
        if (what.kind() == Kind.AGENT || noun.gender == 'm') {
            return grammatical == Case.DAT ? "ihm" : grammatical == Case.NOM ? "er" : "ihn";
        }
        if (noun.gender == 'n') {
            return grammatical == Case.DAT ? "ihm" : "es";
        }
        return grammatical == Case.DAT ? "ihr" : "sie";
    }

    /** A question as the agent restates it: "du hast gefragt, was ich sehe". */
    private static String asked(Ask ask) {
        return "du hast gefragt, " + switch (ask.topic()) {
            case SEE -> ask.about() == null ? "was ich sehe" : "ob ich " + plural(ask.about(), Case.ACC) + " sehe";
            case WHERE -> "wo ich bin";
            case COLLECTED -> ask.about() == null ? "was ich gesammelt habe"
                    : "wie viele " + plural(ask.about(), Case.ACC) + " ich gesammelt habe";
            case DOING -> "was ich mache";
            case WHY -> "warum ich angehalten habe";
            case WHERE_IS -> ask.about().isFruit() && ask.about().distance() == null && ask.about().id() == null
                    ? "wo die " + plural(ask.about(), Case.NOM) + " sind" : "wo " + noun(ask.about(), Case.NOM) + " ist";
            case CAN -> "was ich kann";
            case HEADING -> "wohin ich schaue";
            case RULES -> "was meine Regeln sind";
        };
    }

    // ---- clauses --------------------------------------------------------------------------------

    private static Clause clause(Goal goal) {
        if (goal instanceof GoTo goTo) {
            Reference to = goTo.destination();
            if (to.kind() == Kind.START) {
                return new Clause("gehe", " zurück zu meinem Startpunkt");
            }
            return new Clause("gehe", " " + (to.kind() == Kind.PLACE ? where(to) : toward(to)));
        }
        if (goal instanceof Cross cross) {
            Reference landmark = cross.landmark();
            return landmark.kind() == Kind.FOREST ? new Clause("durchquere", " " + noun(landmark, Case.ACC))
                    : new Clause("überquere", " " + noun(landmark, Case.ACC));
        }
        if (goal instanceof Head head) {
            String far = head.distance() == null ? "" : " " + Notation.number(head.distance()) + " Meter";
            return new Clause("gehe", far + " nach " + compass(head.direction().wireName()));
        }
        if (goal instanceof RelativeMove move) {
            String far = move.distance() == null ? "" : " " + Notation.number(move.distance()) + " Meter";
            return switch (move.direction()) {
                case FORWARD -> new Clause("gehe", far + " vorwärts");
                case BACKWARD -> new Clause("trete", far + " zurück");
                case LEFT -> new Clause("gehe", far + " nach links");
                case RIGHT -> new Clause("gehe", far + " nach rechts");
            };
        }
        if (goal instanceof ComeBack) {
            return new Clause("komme", " zurück");
        }
        if (goal instanceof Collect collect) {
            return collecting(collect);
        }
        if (goal instanceof Turn turn) {
            long degrees = Math.round(turn.degrees());
            if (degrees == 90) {
                return new Clause("drehe", " mich nach links");
            }
            if (degrees == -90) {
                return new Clause("drehe", " mich nach rechts");
            }
            if (Math.abs(degrees) == 180) {
                return new Clause("drehe", " mich um");
            }
            return new Clause("drehe", " mich um " + Notation.number(Math.abs(turn.degrees())) + " Grad nach "
                    + (turn.degrees() > 0 ? "links" : "rechts"));
        }
        if (goal instanceof Face face) {
            return new Clause("drehe", " mich nach " + compass(face.direction().wireName()));
        }
        if (goal instanceof LookAt lookAt) {
            return new Clause("schaue", " " + noun(lookAt.target(), Case.ACC) + " an");
        }
        if (goal instanceof LookFor lookFor) {
            return new Clause("suche", " " + searched(lookFor.what()));
        }
        if (goal instanceof Explore explore) {
            return new Clause("erkunde", " " + area(explore.area()));
        }
        if (goal instanceof Follow follow) {
            return new Clause("folge", " " + noun(follow.agent(), Case.DAT));
        }
        if (goal instanceof Stop) {
            return new Clause("halte", " an");
        }
        if (goal instanceof Wait wait) {
            return new Clause("warte", wait.isUntilTold() ? " hier" : " " + duration(wait.seconds()) + " hier");
        }
        if (goal instanceof CarryOn) {
            return new Clause("mache", " allein weiter");
        }
        if (goal instanceof Ask ask) {
            return new Clause("beantworte", " deine Frage");
        }
        throw new IllegalArgumentException("no German restatement for " + goal);
    }

    private static Clause collecting(Collect collect) {
        Reference what = collect.what();
        if (collect.isAll()) {
            return new Clause("sammle", " " + all(what));
        }
        if (collect.count() > 1) {
            return new Clause("sammle", " " + counted(what, collect.count()));
        }
        Phrase phrase = phrase(what, Case.ACC, false);
        return new Clause("hebe", " " + phrase.core() + " auf" + phrase.relative());
    }

    /** Where "gehe" leads, for a place or an area: "in die Nähe des Flusses", "in den Wald", "nach Norden". */
    static String where(Reference area) {
        if (area.kind() == Kind.FOREST) {
            return "in " + noun(area, Case.ACC);
        }
        if (area.kind() != Kind.PLACE) {
            return toward(area);
        }
        Place place = area.place();
        Reference anchor = place.anchor();
        return switch (place.relation()) {
            case ON -> "auf " + noun(anchor, Case.ACC);
            case IN -> "in " + noun(anchor, Case.ACC);
            case UNDER -> "unter " + noun(anchor, Case.ACC);
            case ON_GROUND -> "auf den Boden";
            case NEAR -> anchor == null ? "in meine Nähe" : "in die Nähe " + noun(anchor, Case.GEN);
            case LEFT -> "nach links";
            case RIGHT -> "nach rechts";
            case AHEAD -> "nach vorne";
            case BEHIND -> "nach hinten";
            case CLOSEST_TO -> "an die Stelle, die " + noun(anchor, Case.DAT) + " am nächsten ist";
            case FARTHEST_FROM -> "an die Stelle, die am weitesten von " + noun(anchor, Case.DAT) + " entfernt ist";
            case FOUND -> "dorthin, " + found(anchor);
            case BEYOND -> "auf die andere Seite " + noun(anchor, Case.GEN);
            case THIS_SIDE_OF -> "auf diese Seite " + noun(anchor, Case.GEN);
            default -> anchor == null ? "nach " + compass(place.relation().sector().wireName())
                    : contract(adverb(place.relation().sector().wireName()) + " von " + noun(anchor, Case.DAT));
        };
    }

    private static String toward(Reference to) {
        return contract("zu " + noun(to, Case.DAT));
    }

    private static String area(Reference area) {
        if (area == null) {
            return "die Gegend";
        }
        if (area.kind() == Kind.FOREST) {
            return noun(area, Case.ACC);
        }
        if (area.kind() != Kind.PLACE) {
            return "die Gegend " + contract("bei " + noun(area, Case.DAT));
        }
        return "die Gegend " + located(area.place(), false, false);
    }

    private static String searched(Reference what) {
        boolean one = what.distance() != null || what.size() == Size.LARGEST || what.size() == Size.SMALLEST
                || what.id() != null;
        return what.isFruit() && !one ? plural(what, Case.ACC) : noun(what, Case.ACC);
    }

    private static String duration(double seconds) {
        if (seconds >= 60 && seconds % 60 == 0) {
            long minutes = (long) (seconds / 60);
            return minutes == 1 ? "eine Minute" : minutes + " Minuten";
        }
        return Notation.number(seconds) + (seconds == 1 ? " Sekunde" : " Sekunden");
    }

    // ---- noun phrases ---------------------------------------------------------------------------

    /** A noun of the world: its gender ('m', 'f', 'n'), singular, plural, genitive and dative plural. */
    private record Noun(char gender, String singular, String plural, String genitive, String dativePlural) {

        static Noun of(Kind kind) {
            return switch (kind) {
                case FRUIT -> new Noun('f', "Frucht", "Früchte", "Frucht", "Früchten");
                case TOMATO -> new Noun('f', "Tomate", "Tomaten", "Tomate", "Tomaten");
                case BANANA -> new Noun('f', "Banane", "Bananen", "Banane", "Bananen");
                case COCONUT -> new Noun('f', "Kokosnuss", "Kokosnüsse", "Kokosnuss", "Kokosnüssen");
                case TREE -> new Noun('m', "Baum", "Bäume", "Baumes", "Bäumen");
                case TABLE -> new Noun('m', "Tisch", "Tische", "Tisches", "Tischen");
                case CASTLE -> new Noun('n', "Schloss", "Schlösser", "Schlosses", "Schlössern");
                case RIVER -> new Noun('m', "Fluss", "Flüsse", "Flusses", "Flüssen");
                case BRIDGE -> new Noun('f', "Brücke", "Brücken", "Brücke", "Brücken");
                case FOREST -> new Noun('m', "Wald", "Wälder", "Waldes", "Wäldern");
                case START -> new Noun('m', "Startpunkt", "Startpunkte", "Startpunkts", "Startpunkten");
                default -> new Noun('m', "Agent", "Agenten", "Agenten", "Agenten");
            };
        }

        String form(Case grammatical, boolean many) {
            if (many) {
                return grammatical == Case.DAT ? dativePlural : plural;
            }
            if (grammatical == Case.GEN) {
                return genitive;
            }
            if (gender == 'm' && this.singular.equals("Agent") && grammatical != Case.NOM) {
                return "Agenten";
            }
            return singular;
        }
    }

    /** A noun phrase split where a relative clause follows: "eine Banane", ", die auf einem Tisch liegt". */
    private record Phrase(String core, String relative) {
        String whole() {
            return core + relative;
        }
    }

    /** One object in words, with its article: "eine Banane, die auf einem Tisch liegt", "den nächsten Baum". */
    static String noun(Reference reference, Case grammatical) {
        return phrase(reference, grammatical, false).whole();
    }

    /** Every object of a reference, without an article: "Kokosnüsse, die auf einem Tisch liegen". */
    static String many(Reference what, Case grammatical) {
        return plural(what, grammatical);
    }

    /** Every fruit that fits, with "alle": "alle Bananen", "alle Früchte auf der anderen Seite des Flusses". */
    private static String all(Reference what) {
        return "alle " + phrase(what, Case.ACC, true).whole().replaceFirst("^die ", "");
    }

    private static String plural(Reference what, Case grammatical) {
        return phrase(what, grammatical, true).whole().replaceFirst("^(die|den|der) ", "");
    }

    private static String counted(Reference what, int count) {
        String[] numbers = {"null", "eine", "zwei", "drei", "vier", "fünf", "sechs", "sieben", "acht", "neun", "zehn",
            "elf", "zwölf"};
        String number = count < numbers.length ? numbers[count] : Integer.toString(count);
        return number + " " + plural(what, Case.ACC);
    }

    private static Phrase phrase(Reference reference, Case grammatical, boolean many) {
        if (reference.kind() == Kind.PLACE) {
            return new Phrase("die Gegend " + located(reference.place(), false, false), "");
        }
        if (reference.kind() == Kind.START) {
            return new Phrase(startpoint(grammatical), "");
        }
        if (reference.name() != null && reference.distance() == null && reference.size() == null) {
            return new Phrase(reference.name(), "");
        }
        Noun noun = Noun.of(reference.kind());
        boolean definite = many || reference.distance() != null || reference.id() != null
                || reference.size() == Size.LARGEST || reference.size() == Size.SMALLEST
                || reference.kind() == Kind.CASTLE || reference.kind() == Kind.RIVER || reference.kind() == Kind.FOREST
                || picked(reference.place());
        StringBuilder core = new StringBuilder(article(definite, noun.gender, grammatical, many));
        String adjective = adjective(reference);
        if (adjective != null) {
            core.append(core.length() > 0 ? " " : "").append(adjective)
                    .append(ending(definite, noun.gender, grammatical, many));
        }
        core.append(core.length() > 0 ? " " : "").append(reference.name() != null ? reference.name()
                : noun.form(grammatical, many));
        if (reference.id() != null) {
            core.append(' ').append(reference.id());
        }
        if (reference.distance() == Distance.LEFTMOST || reference.distance() == Distance.RIGHTMOST) {
            String side = reference.distance() == Distance.LEFTMOST ? "links" : "rechts";
            core.append(reference.ordinal() == null ? " ganz " + side : " von " + side);
        }
        String relative = "";
        if (reference.place() != null) {
            if (reference.isFruit() && lies(reference.place())) {
                String pronoun = many ? "die" : noun.gender == 'm' ? "der" : noun.gender == 'n' ? "das" : "die";
                relative = ", " + pronoun + " " + located(reference.place(), true, many);
            } else {
                core.append(' ').append(located(reference.place(), false, many));
            }
        }
        return new Phrase(core.toString(), relative);
    }

    private static String startpoint(Case grammatical) {
        return switch (grammatical) {
            case DAT -> "meinem Startpunkt";
            case GEN -> "meines Startpunkts";
            default -> "meinen Startpunkt";
        };
    }

    /** Whether fruit at this place is said to lie or hang there, in a relative clause. */
    private static boolean lies(Place place) {
        return switch (place.relation()) {
            case ON, IN, UNDER, ON_GROUND -> true;
            default -> false;
        };
    }

    /** Where an object is: "auf einem Tisch liegt" (in a relative clause), "beim Fluss", "links von mir". */
    private static String located(Place place, boolean clause, boolean many) {
        Reference anchor = place.anchor();
        String lie = many ? "liegen" : "liegt";
        String hang = many ? "hängen" : "hängt";
        return switch (place.relation()) {
            case ON -> contract("auf " + noun(anchor, Case.DAT)) + (clause ? " " + lie : "");
            case IN -> contract("in " + noun(anchor, Case.DAT)) + (clause ? " " + (anchor.kind() == Kind.TREE ? hang
                    : lie) : "");
            case UNDER -> "unter " + noun(anchor, Case.DAT) + (clause ? " " + lie : "");
            case ON_GROUND -> "auf dem Boden" + (clause ? " " + lie : "");
            case NEAR -> anchor == null ? "in meiner Nähe" : contract("bei " + noun(anchor, Case.DAT));
            case LEFT -> "links von mir";
            case RIGHT -> "rechts von mir";
            case AHEAD -> "vor mir";
            case BEHIND -> "hinter mir";
            case CLOSEST_TO -> contract("am nächsten zu " + noun(anchor, Case.DAT));
            case FARTHEST_FROM -> contract("am weitesten von " + noun(anchor, Case.DAT)) + " entfernt";
            case FOUND -> "dort, " + found(anchor);
            case BEYOND -> "auf der anderen Seite " + noun(anchor, Case.GEN);
            case THIS_SIDE_OF -> "auf dieser Seite " + noun(anchor, Case.GEN);
            default -> anchor == null ? "im " + compass(place.relation().sector().wireName())
                    : contract(adverb(place.relation().sector().wireName()) + " von " + noun(anchor, Case.DAT));
        };
    }

    /** Where the agent took the fruit: "wo ich die Kokosnuss gefunden habe", the last it took. */
    private static String found(Reference fruit) {
        String it = noun(fruit, Case.ACC).replaceFirst("^einen ", "den ").replaceFirst("^eine ", "die ")
                .replaceFirst("^ein ", "das ");
        return "wo ich " + it + " gefunden habe";
    }

    private static boolean picked(Place place) {
        return place != null && (place.relation() == Place.Relation.CLOSEST_TO
                || place.relation() == Place.Relation.FARTHEST_FROM);
    }

    /** The adjective of a reference's size, distance or ordinal, without its ending: "nächst", "zweit", "groß". */
    private static String adjective(Reference reference) {
        String superlative = reference.distance() == null ? null : switch (reference.distance()) {
            case NEAREST -> "nächst";
            case FARTHEST -> "entferntest";
            case HIGHEST -> "höchst";
            case LOWEST -> "niedrigst";
            case NORTHERNMOST -> "nördlichst";
            case SOUTHERNMOST -> "südlichst";
            case EASTERNMOST -> "östlichst";
            case WESTERNMOST -> "westlichst";
            case LEFTMOST, RIGHTMOST -> null;
        };
        if (reference.ordinal() != null) {
            String ordinal = ORDINALS[Math.min(reference.ordinal(), ORDINALS.length - 1)];
            return superlative == null ? ordinal : ordinal + superlative;
        }
        if (superlative != null) {
            return superlative;
        }
        if (reference.size() == null) {
            return null;
        }
        return switch (reference.size()) {
            case BIG -> "groß";
            case SMALL -> "klein";
            case LARGEST -> "größt";
            case SMALLEST -> "kleinst";
        };
    }

    private static final String[] ORDINALS = {"null", "erst", "zweit", "dritt", "viert", "fünft", "sechst", "siebt",
        "acht", "neunt", "zehnt", "elft", "zwölft", "dreizehnt", "vierzehnt", "fünfzehnt", "sechzehnt", "siebzehnt",
        "achtzehnt", "neunzehnt", "zwanzigst"};

    private static String article(boolean definite, char gender, Case grammatical, boolean many) {
        if (many) {
            if (!definite) {
                return "";
            }
            return switch (grammatical) {
                case DAT -> "den";
                case GEN -> "der";
                default -> "die";
            };
        }
        int g = gender == 'm' ? 0 : gender == 'f' ? 1 : 2;
        String[][] forms = definite
                ? new String[][] {{"der", "die", "das"}, {"den", "die", "das"}, {"dem", "der", "dem"}, {"des", "der", "des"}}
                : new String[][] {{"ein", "eine", "ein"}, {"einen", "eine", "ein"}, {"einem", "einer", "einem"},
                    {"eines", "einer", "eines"}};
        return forms[grammatical.ordinal()][g];
    }

    private static String ending(boolean definite, char gender, Case grammatical, boolean many) {
        if (many) {
            return definite || grammatical == Case.DAT ? "en" : grammatical == Case.GEN ? "er" : "e";
        }
        if (grammatical == Case.DAT || grammatical == Case.GEN) {
            return "en";
        }
        if (definite) {
            return grammatical == Case.ACC && gender == 'm' ? "en" : "e";
        }
        return switch (gender) {
            case 'm' -> grammatical == Case.NOM ? "er" : "en";
            case 'n' -> "es";
            default -> "e";
        };
    }

    /** "zu dem" is "zum", "von dem" "vom", "bei dem" "beim", "in dem" "im", "zu der" "zur". */
    private static String contract(String text) {
        return text.replaceFirst("^zu dem ", "zum ").replaceFirst("^zu der ", "zur ").replaceFirst("^von dem ", "vom ")
                .replaceFirst("^bei dem ", "beim ").replaceFirst("^in dem ", "im ").replaceFirst("^an dem ", "am ")
                .replace(" zu dem ", " zum ").replace(" von dem ", " vom ").replace(" bei dem ", " beim ");
    }

    static String compass(String wireName) {
        return switch (wireName) {
            case "north" -> "Norden";
            case "south" -> "Süden";
            case "east" -> "Osten";
            case "west" -> "Westen";
            case "north-east" -> "Nordosten";
            case "north-west" -> "Nordwesten";
            case "south-east" -> "Südosten";
            default -> "Südwesten";
        };
    }

    static String adverb(String wireName) {
        return switch (wireName) {
            case "north" -> "nördlich";
            case "south" -> "südlich";
            case "east" -> "östlich";
            case "west" -> "westlich";
            case "north-east" -> "nordöstlich";
            case "north-west" -> "nordwestlich";
            case "south-east" -> "südöstlich";
            default -> "südwestlich";
        };
    }

    /** A German word as it is capitalised at the start of a sentence. */
    static String capital(String text) {
        return text.isEmpty() ? text : text.substring(0, 1).toUpperCase(Locale.ROOT) + text.substring(1);
    }
}
