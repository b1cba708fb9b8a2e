package io.orchard.agents.goal;

import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Point2;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The structured instructions every agent understands, case-insensitive, with any full stop or
 * exclamation mark at the end ignored:
 *
 * <table>
 *   <caption>Instructions</caption>
 *   <tr><th>typed</th><th>goal</th></tr>
 *   <tr><td>{@code go to 10,-20} (also {@code go to 10 -20}, {@code goto 10, -20})</td><td>{@link Goal.GoTo}</td></tr>
 *   <tr><td>{@code collect banana} (or tomato, coconut, plurals too)</td><td>{@link Goal.Collect} of a kind</td></tr>
 *   <tr><td>{@code collect F12}</td><td>{@link Goal.Collect} of one fruit</td></tr>
 *   <tr><td>{@code collect}, {@code collect fruit}</td><td>{@link Goal.Collect} of any fruit</td></tr>
 *   <tr><td>{@code explore}</td><td>{@link Goal.Explore}</td></tr>
 *   <tr><td>{@code stop}, {@code halt}, {@code wait}</td><td>{@link Goal.Stop}</td></tr>
 *   <tr><td>{@code carry on}, {@code continue}, {@code go on}, {@code resume}</td><td>{@link Goal.CarryOn}</td></tr>
 * </table>
 */
public final class StructuredGoals implements Interpreter {

    /** What to type, for answers to instructions that were not understood. */
    public static final String USAGE =
            "try: go to X,Z | collect banana | collect F12 | explore | stop | carry on";

    private static final Pattern GO_TO = Pattern.compile(
            "(?:go ?to|walk to)\\s+\\(?\\s*(-?\\d+(?:\\.\\d+)?)\\s*(?:,\\s*|\\s+)(-?\\d+(?:\\.\\d+)?)\\s*\\)?");
    private static final Pattern COLLECT = Pattern.compile("(?:collect|get|pick up)(?:\\s+(?:a|an|the))?(?:\\s+(\\S+))?");

    @Override
    public Goal interpret(String text, WorldMemory memory) throws NotUnderstoodException {
        return parse(text);
    }

    /**
     * Reads one instruction.
     *
     * @throws NotUnderstoodException naming the text and the forms understood
     */
    public static Goal parse(String text) throws NotUnderstoodException {
        String line = text.strip().toLowerCase(Locale.ROOT).replaceAll("[.!]+$", "").strip();
        switch (line) {
            case "stop", "halt", "wait" -> {
                return new Goal.Stop();
            }
            case "carry on", "continue", "go on", "resume" -> {
                return new Goal.CarryOn();
            }
            case "explore" -> {
                return new Goal.Explore();
            }
            default -> {
                // the forms with arguments follow
            }
        }
        Matcher go = GO_TO.matcher(line);
        if (go.matches()) {
            return new Goal.GoTo(new Point2(Double.parseDouble(go.group(1)), Double.parseDouble(go.group(2))));
        }
        if (line.startsWith("go to") || line.startsWith("goto")) {
            throw new NotUnderstoodException("'" + text.strip() + "': expected two numbers after 'go to', as in 'go to 10,-20'");
        }
        Matcher collect = COLLECT.matcher(line);
        if (collect.matches()) {
            return collect(collect.group(1), text);
        }
        throw new NotUnderstoodException("'" + text.strip() + "' is not an instruction I know; " + USAGE);
    }

    private static Goal collect(String what, String text) throws NotUnderstoodException {
        if (what == null || what.equals("fruit") || what.equals("something") || what.equals("anything")) {
            return Goal.Collect.any();
        }
        String singular = what.endsWith("es") && what.startsWith("tomato") ? "tomato"
                : what.endsWith("s") ? what.substring(0, what.length() - 1) : what;
        for (FruitKind kind : FruitKind.values()) {
            if (kind.wireName().equals(singular)) {
                return new Goal.Collect(kind, null);
            }
        }
        if (what.matches("f\\d+")) {
            return new Goal.Collect(null, "F" + what.substring(1));
        }
        throw new NotUnderstoodException("'" + text.strip() + "': expected a kind of fruit (tomato, banana, coconut)"
                + " or a fruit's id (F12) after 'collect'");
    }
}
