package io.orchard.agents.errand;

import io.orchard.agents.language.Language;
import io.orchard.agents.language.Phrasing;
import io.orchard.agents.language.Phrasing.Case;
import io.orchard.agents.language.Reference;
import io.orchard.agents.language.Reference.Kind;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sector;
import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;

/**
 * What the agent says as it carries instructions out, in the language it was last spoken to in:
 * English ("I'm at the tree T3.") or German ("Ich bin beim Baum T3."). Every sentence the errands
 * say is made here, so that the two languages say the same things.
 */
final class Speech {

    private final Supplier<Language> language;

    /** Speech in the language the agent was last spoken to in. */
    Speech(Kit kit) {
        this.language = () -> kit.language;
    }

    /** Speech in one language. */
    Speech(Language language) {
        this.language = () -> language;
    }

    private boolean de() {
        return language.get() == Language.GERMAN;
    }

    /** The language spoken. */
    Language language() {
        return language.get();
    }

    // ---- things and places ----------------------------------------------------------------------

    /** A known thing in words: "the tree T3", "the castle", "Guppy"; in German, in the case given. */
    String thing(Known known, Case grammatical) {
        if (!de()) {
            return switch (known.kind()) {
                case AGENT -> known.id();
                case CASTLE, RIVER, FOREST -> "the " + known.kind().wireName();
                case START -> "where I started";
                default -> "the " + known.kind().wireName() + " " + known.id();
            };
        }
        return switch (known.kind()) {
            case AGENT -> known.id();
            case CASTLE, RIVER, FOREST, START -> Phrasing.noun(Reference.to(known.kind()), Language.GERMAN, grammatical);
            default -> Phrasing.noun(Reference.thing(known.kind(), known.id()), Language.GERMAN, grammatical);
        };
    }

    /** A thing "the tree T3", as the subject (in English the same). */
    String thing(Known known) {
        return thing(known, Case.NOMINATIVE);
    }

    /** A reference without its article: "coconut that lies on a table", in German in the plural. */
    String bare(Reference reference) {
        if (de()) {
            return Phrasing.plural(reference, Language.GERMAN, Case.ACCUSATIVE);
        }
        String words = reference.words();
        for (String article : new String[] {"a ", "an ", "the "}) {
            if (words.startsWith(article)) {
                return words.substring(article.length());
            }
        }
        return words;
    }

    /** Where a thing is seen from a point: "12 m to the north-east", "12 m Richtung Nordosten". */
    String bearing(Point2 from, Point2 thing) {
        String sector = Grounder.compass(from, thing);
        return String.format(Locale.ROOT, de() ? "%.0f m Richtung %s" : "%.0f m to the %s", from.distance(thing),
                compass(sector));
    }

    /** A compass direction as a noun: "north-east", "Nordosten". */
    String compass(String sector) {
        return Phrasing.compass(sector, language());
    }

    /** A compass direction as an adverb: "north-east", "nordöstlich". */
    String compassOf(String sector) {
        return Phrasing.compassAdverb(sector, language());
    }

    /** "a", "a and b", "a, b and c"; "und" in German. */
    String list(List<String> parts) {
        if (parts.size() == 1) {
            return parts.get(0);
        }
        return String.join(", ", parts.subList(0, parts.size() - 1)) + (de() ? " und " : " and ")
                + parts.get(parts.size() - 1);
    }

    /** A number of fruit: "a banana", "2 tomatoes", "eine Banane", "2 Tomaten". */
    String count(int n, FruitKind kind) {
        Reference one = Reference.to(Kind.valueOf(kind.name()));
        if (de()) {
            return n == 1 ? Phrasing.noun(one, Language.GERMAN, Case.ACCUSATIVE)
                    : n + " " + Phrasing.plural(one, Language.GERMAN, Case.ACCUSATIVE);
        }
        String name = kind.name().toLowerCase(Locale.ROOT);
        return n == 1 ? "a " + name : n + " " + plural(kind);
    }

    /** Fruit of a kind in the plural: "tomatoes", "Tomaten". */
    String plural(FruitKind kind) {
        if (de()) {
            return Phrasing.plural(Reference.to(Kind.valueOf(kind.name())), Language.GERMAN, Case.ACCUSATIVE);
        }
        return kind == FruitKind.TOMATO ? "tomatoes" : kind.name().toLowerCase(Locale.ROOT) + "s";
    }

    /** A fruit the agent took, in words: "the banana F12", "die Banane F12". */
    String fruit(FruitKind kind, String id, Case grammatical) {
        return de() ? Phrasing.noun(Reference.thing(Kind.valueOf(kind.name()), id), Language.GERMAN, grammatical)
                : "the " + kind.wireName() + " " + id;
    }

    // ---- the errands --------------------------------------------------------------------------

    String carryingOn() {
        return de() ? " Ich mache allein weiter." : " Carrying on by myself.";
    }

    String waitingForAnswer(String question) {
        return de() ? "warte auf deine Antwort: " + question : "waiting for your answer: " + question;
    }

    String allRight(Known chosen) {
        return de() ? "In Ordnung, " + thing(chosen) + "." : "All right, " + thing(chosen) + ".";
    }

    String noAnswer(Known nearest) {
        return de() ? "Keine Antwort: Ich nehme das nächste, " + thing(nearest) + "."
                : "No answer: I'll take the nearest, " + thing(nearest) + ".";
    }

    String seenSoAsTold(Known seen) {
        return de() ? "Ich sehe " + thing(seen, Case.ACCUSATIVE) + ", also wie du gesagt hast:"
                : "I see " + thing(seen) + ", so as you told me:";
    }

    String goOnWithTheRest() {
        return de() ? " Ich mache mit dem Rest weiter." : " I'll go on with the rest.";
    }

    String leavingArea(String rule) {
        return de() ? "ich verlasse die Gegend, die " + rule + " mir verbietet"
                : "leaving the area " + rule + " keeps me out of";
    }

    String imWhereRuleKeepsMeOut(String rule) {
        return de() ? "Ich bin dort, wo " + rule + " mir verbietet zu sein; ich gehe weg."
                : "I'm where " + rule + " keeps me out of; I'm leaving.";
    }

    String outOfIt() {
        return de() ? "Jetzt bin ich draußen." : "I'm out of it now.";
    }

    String backWhereStarted() {
        return de() ? "Ich bin wieder da, wo ich angefangen habe." : "I'm back where I started.";
    }

    String back() {
        return de() ? "Ich bin zurück." : "I'm back.";
    }

    String throughTheForest() {
        return de() ? "Erledigt: Ich bin durch den Wald gegangen." : "Done: I went through the forest.";
    }

    String wontGoTo(Known target, String rule) {
        return de() ? "Ich gehe nicht " + toward(target) + ": Das ist gegen " + rule + "."
                : "I won't go to " + thing(target) + ": that is against " + rule + ".";
    }

    String noFreeSpot(Known target) {
        return de() ? "Ich finde keinen freien Platz " + at(target) + "."
                : "I can't find a free spot by " + thing(target) + ".";
    }

    String noWayTo(Known target) {
        return de() ? "Ich finde keinen Weg " + toward(target) + "." : "I can't find a way to " + thing(target) + ".";
    }

    String imAt(Known target) {
        return de() ? "Ich bin " + at(target) + "." : "I'm at " + thing(target) + ".";
    }

    /** "zum Baum T3", "zu Guppy". */
    private String toward(Known target) {
        String dative = thing(target, Case.DATIVE);
        return target.kind() == Kind.AGENT ? "zu " + dative : contract("zu " + dative);
    }

    /** "beim Baum T3", "bei Guppy". */
    private String at(Known target) {
        String dative = thing(target, Case.DATIVE);
        return target.kind() == Kind.AGENT ? "bei " + dative : contract("bei " + dative);
    }

    private static String contract(String text) {
        return text.replaceFirst("^zu dem ", "zum ").replaceFirst("^zu der ", "zur ").replaceFirst("^bei dem ", "beim ");
    }

    String wentTo(Reference area) {
        return de() ? "Erledigt: Ich bin " + Phrasing.where(area, Language.GERMAN) + " gegangen."
                : "Done: I went " + Phrasing.where(area, Language.ENGLISH) + ".";
    }

    String moved() {
        return de() ? "Erledigt: Ich bin gegangen." : "Done: I moved.";
    }

    String asFarAsICan(String direction) {
        return de() ? "Weiter nach " + compass(direction) + " komme ich nicht."
                : "I've gone as far " + direction + " as I can.";
    }

    String wontGoThere(String rule) {
        return de() ? "Dorthin gehe ich nicht: Das ist gegen " + rule + "."
                : "I won't go there: that is against " + rule + ".";
    }

    /** "Where you found the coconut", when the agent has taken none. */
    String neverFound(Reference fruit) {
        return de() ? "Ich habe noch keine " + bare(fruit.withDistance(null)) + " genommen, also weiß ich nicht, wo ich "
                + "eine gefunden habe." : "I haven't taken a " + bare(fruit) + " yet, so I don't know where I found one.";
    }

    String noWayThere() {
        return de() ? "Ich finde keinen Weg dorthin." : "I can't find a way there.";
    }

    String wontCross(String rule) {
        return de() ? "Ich überquere den Fluss nicht: Das ist gegen " + rule + "."
                : "I won't cross the river: that is against " + rule + ".";
    }

    String noWayOnto(String bridge) {
        return de() ? "Ich finde keinen Weg auf die Brücke " + bridge + "."
                : "I can't find a way onto the bridge " + bridge + ".";
    }

    String noWayOver(String bridge) {
        return de() ? "Ich finde keinen Weg über die Brücke " + bridge + "."
                : "I can't find a way over the bridge " + bridge + ".";
    }

    String otherSide(String bridge) {
        return de() ? "Ich bin auf der anderen Seite des Flusses, über die Brücke " + bridge + "."
                : "I'm on the other side of the river, over the bridge " + bridge + ".";
    }

    String collectedAndNoMore(int collected, Reference what) {
        return de() ? "Erledigt: Ich habe " + collected + " gesammelt und kenne keine " + bare(what) + " mehr."
                : "Done: I collected " + collected + " and know of no more " + bare(what) + ".";
    }

    String collectedAndFoundNoMore(int collected, Reference what) {
        return de() ? "Ich habe " + collected + " gesammelt und keine " + bare(what) + " mehr gefunden."
                : "I collected " + collected + ", and found no more " + bare(what) + ".";
    }

    String pickedUp(FruitKind kind, String id) {
        return de() ? "Erledigt: Ich habe " + fruit(kind, id, Case.ACCUSATIVE) + " aufgehoben."
                : "Done: I picked up " + fruit(kind, id, Case.ACCUSATIVE) + ".";
    }

    String collectedLast(int collected, FruitKind kind, String id) {
        return de() ? "Erledigt: Ich habe " + collected + " gesammelt, zuletzt " + fruit(kind, id, Case.ACCUSATIVE)
                + "." : "Done: I collected " + collected + ", the last " + fruit(kind, id, Case.ACCUSATIVE) + ".";
    }

    String got(FruitKind kind, String id, int toGo) {
        if (de()) {
            return "Ich habe " + fruit(kind, id, Case.ACCUSATIVE) + (toGo < 0 ? "." : "; noch " + toGo + ".");
        }
        return "Got " + fruit(kind, id, Case.ACCUSATIVE) + (toGo < 0 ? "." : "; " + toGo + " to go.");
    }

    String tooHigh(FruitKind kind, String id, double height, Gripper gripper) {
        return String.format(Locale.ROOT, de() ? "Ich kann %s nicht aufheben: Sie ist %.2f hoch, und mein Greifer (%s) "
                + "reicht nur von %.2f bis %.2f." : "I can't pick up %s: it is %.2f high, and my %s reaches only from %.2f "
                + "to %.2f.", fruit(kind, id, Case.ACCUSATIVE), height, gripper.part(), gripper.minHeight(),
                gripper.maxHeight());
    }

    String wontPickUp(FruitKind kind, String id, String rule) {
        return de() ? "Ich hebe " + fruit(kind, id, Case.ACCUSATIVE) + " nicht auf: Das ist gegen " + rule + "."
                : "I won't pick up " + fruit(kind, id, Case.ACCUSATIVE) + ": that is against " + rule + ".";
    }

    String cantSee(String name) {
        return de() ? "Ich sehe " + name + " nicht; ich schaue mich nach ihm um."
                : "I can't see " + name + "; I'll look around for it.";
    }

    String dontKnowWhere(Reference wanted) {
        return de() ? "Ich weiß noch nicht, wo " + Phrasing.noun(wanted, Language.GERMAN, Case.NOMINATIVE)
                + " ist; ich suche danach." : "I don't know where " + wanted.words() + " is yet; I'll look for it.";
    }

    String dontKnowOf(Reference wanted) {
        if (de()) {
            return "Ich kenne noch keine " + bare(wanted) + "; ich suche danach.";
        }
        String words = wanted.words();
        if (wanted.kind() == Kind.FRUIT && words.startsWith("a fruit")) {
            words = "any fruit" + words.substring("a fruit".length()); // not "a fruit": fruit is a mass noun
        }
        return "I don't know of " + words + " yet; I'll look for one.";
    }

    String lookedEverywhere(Reference wanted) {
        return de() ? "Ich habe überall gesucht, wohin ich komme, und keine " + bare(wanted) + " gefunden."
                : "I have looked everywhere I can reach and found no " + bare(wanted) + ".";
    }

    String iSee(Known known, Point2 here) {
        return de() ? "Ich sehe " + thing(known, Case.ACCUSATIVE) + ", " + bearing(here, known.where()) + "."
                : "I see " + thing(known) + ", " + bearing(here, known.where()) + ".";
    }

    String seenEverything() {
        return de() ? "Ich habe alles gesehen, wohin ich komme." : "I have seen everything I can reach.";
    }

    String lookedOver(Reference area) {
        return de() ? "Ich habe mir " + Phrasing.noun(area, Language.GERMAN, Case.ACCUSATIVE) + " angesehen."
                : "I have looked over " + area.words() + ".";
    }

    String lostSight(String name) {
        return de() ? "Ich habe " + name + " aus den Augen verloren." : "I've lost sight of " + name + ".";
    }

    String lookedAllAround(Reference target) {
        return de() ? "Ich habe mich ganz umgesehen und kenne keine " + bare(target) + "."
                : "I looked all around and know of no " + bare(target) + ".";
    }

    String facing(String sector) {
        return de() ? "Erledigt: Ich schaue nach " + compass(sector) + "." : "Done: I'm facing " + sector + ".";
    }

    String doneWaiting() {
        return de() ? "Ich habe fertig gewartet." : "Done waiting.";
    }

    /** How far and which way, in words: "9 metres north", "9 Meter nach Norden". */
    String metres(String metres, String direction) {
        return de() ? metres(metres) + " nach " + compass(direction) : metres + " " + direction;
    }

    /** How far, in words: "9 metres", "9 Meter". */
    String metres(String metres) {
        return de() ? metres.replace("metres", "Meter").replace("metre", "Meter") : metres;
    }

    String went(String far) {
        return de() ? "Erledigt: Ich bin " + far + " gegangen." : "Done: I went " + far + ".";
    }

    String pointNowhere(String problem, String direction) {
        return de() ? "Dieser Punkt ist " + problem + ", und ich komme von hier nicht nach " + compass(direction)
                + "; ich bin geblieben, wo ich bin." : "That point is " + problem + ", and I can't go any way "
                + direction + " from here; I stayed where I am.";
    }

    String pointNearest(String problem, String dry) {
        return de() ? "Dieser Punkt ist " + problem + "; der nächste Ort in dieser Richtung, an dem ich stehen kann, ist "
                + dry + " entfernt, und dorthin gehe ich." : "That point is " + problem + "; the nearest place I can "
                + "stand that way is " + dry + ", and I'll go there.";
    }

    String wentShort(String dry, String asked, String problem) {
        return de() ? "Erledigt: Ich bin " + dry + " gegangen, nicht die " + asked + ", um die du gebeten hast: "
                + "weiter ist " + problem + "." : "Done: I went " + dry + ", not the " + asked + " you asked: further is "
                + problem + ".";
    }

    String blockedShort(String went, String asked) {
        return de() ? "Ich bin nur " + went + " gegangen, nicht die " + asked + ", um die du gebeten hast: "
                + "weiter finde ich keinen Weg." : "I went only " + went + ", not the " + asked + " you asked: I can't "
                + "find a way further.";
    }

    String beyondTheEdge() {
        return de() ? "jenseits des Randes der Welt" : "beyond the edge of the world";
    }

    String inTheRiver() {
        return de() ? "im Fluss" : "in the river";
    }

    String against(String rule) {
        return de() ? "gegen " + rule : "against " + rule;
    }

    /** What the body cannot reach, as {@link FruitHeights} finds it. */
    String outOfReach(String words, String where, double low, double high, Gripper gripper) {
        return String.format(Locale.ROOT, de() ? "Ich kann %s nicht aufheben: Früchte, die %s, sind %.2f bis %.2f hoch, "
                + "und mein Greifer (%s) reicht nur von %.2f bis %.2f." : "I can't pick up %s: fruit that %s is %.2f to "
                + "%.2f high, and my %s reaches only from %.2f to %.2f.", de() && words.contains(", ") ? words + ","
                : words, where, low, high, gripper.part(),
                gripper.minHeight(), gripper.maxHeight());
    }

    // ---- rules ----------------------------------------------------------------------------------

    String keepToThatAlready(String statement) {
        return de() ? "Daran halte ich mich schon: " + statement + "." : "I keep to that already: " + statement + ".";
    }

    String takesThePlaceOf(String reason) {
        return de() ? " Das ersetzt " + reason + "." : " That takes the place of " + reason + ".";
    }

    String leaveFirst() {
        return de() ? " Ich stehe dort, wo sie mich nicht hinlässt, also gehe ich zuerst weg."
                : " I'm standing where it keeps me out of, so I'll leave first.";
    }

    String noRulesToForget() {
        return de() ? "Ich habe keine Regeln zu vergessen; ich tue, was ich für richtig halte."
                : "I have no rules to forget; I do as I see fit.";
    }

    String noRuleAgainstThat() {
        return de() ? "Dagegen hatte ich keine Regel; ich halte mich an die Regeln, die ich habe."
                : "I had no rule against that; I keep to the rules I have.";
    }

    String thatLifts(List<String> reasons) {
        return de() ? "; das hebt " + String.join(" und ", reasons) + " auf." : "; that lifts "
                + String.join(" and ", reasons) + ".";
    }

    String noRules() {
        return de() ? "Ich habe keine Regeln: Ich gehe, wohin ich will, und nehme jede Frucht, die ich erreiche."
                : "I have no rules: I go where I like and take any fruit I can reach.";
    }

    String rules(List<String> statements) {
        return de() ? "Meine Regeln: " + String.join("; ", statements) + ". Sag 'vergiss die Regeln', um sie "
                + "aufzuheben." : "My rules: " + String.join("; ", statements) + ". Say 'forget the rules' to lift them.";
    }

    String wontBreak(String reason) {
        return de() ? "Das tue ich nicht: Es ist gegen " + reason + ". Sag 'vergiss die Regeln', um deine Regeln "
                + "aufzuheben." : "I won't: that is against " + reason + ". Say 'forget the rules' to lift your rules.";
    }

    /** A compass direction of a heading: "north-east". */
    static String sectorOf(double heading) {
        return Sector.of(-Math.sin(heading), -Math.cos(heading)).wireName();
    }
}
