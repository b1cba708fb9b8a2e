package io.orchard.agents.language;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;

/**
 * Tells instructions that set a rule for later from those to act on now: a constraint that holds
 * until lifted ("only bananas from now on", "stay on this side of the river", "you can go near the
 * river again") or a condition ("when you see a banana, take it"). The grammar of commands would
 * read some of them as something else ("only collect bananas" as "collect bananas"), so they are
 * recognised first, and answered with what the agent can do instead.
 */
final class Rules {

    private static final Pattern CONDITION = Pattern.compile(
            "(when|whenever|if|as soon as|each time|every time) (you )?(see|find|spot|notice|meet|come across"
                    + "|encounter|get to|reach)( .*)?|if there (is|are)( .*)?");

    private static final Pattern CONSTRAINT = Pattern.compile(
            ".*\\b(from now on|only|no more|for the rest of the game)\\b.*"
                    + "|(stay|keep|steer) (away|clear|off)( .*)?|(stay|keep|remain) on (this|our|the near|your) side( .*)?"
                    + "|(leave|ignore|avoid|skip|forget)( .*)?|(you can|you may|you are allowed to|feel free to) .*\\bagain");

    private Rules() {
    }

    /** What to answer a sentence that sets a rule for later; null when it sets none. */
    static String answer(List<Tokenizer.Token> tokens) {
        List<String> words = new ArrayList<>();
        int start = 0;
        if (tokens.size() > 2 && tokens.get(0).isWord() && tokens.get(1).isPunctuation()) {
            start = 2; // "Guppy, ..."
        }
        for (Tokenizer.Token token : tokens.subList(start, tokens.size())) {
            if (token.isWord() || token.type() == Tokenizer.Type.NUMBER) {
                words.add(token.text());
            }
        }
        while (!words.isEmpty() && List.of("please", "hey", "ok", "okay", "and", "now", "so").contains(words.get(0))) {
            words.remove(0);
        }
        String sentence = String.join(" ", words);
        if (CONDITION.matcher(sentence).matches()) {
            return Answers.CONDITIONS;
        }
        if (CONSTRAINT.matcher(sentence).matches()) {
            return Answers.RULES;
        }
        return null;
    }
}
