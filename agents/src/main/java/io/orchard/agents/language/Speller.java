package io.orchard.agents.language;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * Corrects small typos against the known vocabulary: a word of 4 to 6 letters may be one edit
 * away from a known word, a word of 7 letters or more two edits (an edit inserts, deletes or
 * changes a letter, or swaps two neighbours); shorter words are never corrected. A known word is
 * never corrected, and a word is left alone when it is as close to two known words that mean
 * different things (after preferring those that start with the same letter), so "trun" becomes
 * "turn" rather than "run", but a typo between "tree" and "three" stays unknown.
 */
final class Speller {

    private final Map<String, String> meanings;

    /**
     * @param meanings every word that typos may be corrected into, with what it means; words that
     *                 mean the same (such as "banana" and "bananas") are not told apart
     */
    Speller(Map<String, String> meanings) {
        this.meanings = new TreeMap<>(meanings);
    }

    /** The known word this one is a typo of, or null when there is none or it is ambiguous. */
    String correct(String word) {
        int length = word.length();
        if (length < 4 || meanings.containsKey(word)) {
            return null;
        }
        int limit = length >= 7 ? 2 : 1;
        int best = limit + 1;
        List<String> candidates = new ArrayList<>();
        for (String known : meanings.keySet()) {
            if (Math.abs(known.length() - length) > limit) {
                continue;
            }
            int distance = distance(word, known, limit);
            if (distance < best) {
                best = distance;
                candidates.clear();
                candidates.add(known);
            } else if (distance == best) {
                candidates.add(known);
            }
        }
        if (candidates.isEmpty()) {
            return null;
        }
        List<String> sameStart = candidates.stream().filter(known -> known.charAt(0) == word.charAt(0)).toList();
        if (!sameStart.isEmpty()) {
            candidates = sameStart;
        }
        Set<String> senses = new TreeSet<>();
        for (String known : candidates) {
            senses.add(meanings.get(known));
        }
        if (senses.size() > 1) {
            return null;
        }
        char last = word.charAt(length - 1);
        return candidates.stream().filter(known -> known.charAt(known.length() - 1) == last)
                .findFirst().orElse(candidates.get(0));
    }

    /**
     * The optimal string alignment distance between two words (edits: insert, delete, change a
     * letter, swap two neighbours), or {@code limit + 1} when it is more than {@code limit}.
     */
    static int distance(String a, String b, int limit) {
        int n = a.length();
        int m = b.length();
        if (Math.abs(n - m) > limit) {
            return limit + 1;
        }
        int[][] d = new int[n + 1][m + 1];
        for (int i = 0; i <= n; i++) {
            d[i][0] = i;
        }
        for (int j = 0; j <= m; j++) {
            d[0][j] = j;
        }
        for (int i = 1; i <= n; i++) {
            int rowMin = Integer.MAX_VALUE;
            for (int j = 1; j <= m; j++) {
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                int value = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + cost);
                if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
                    value = Math.min(value, d[i - 2][j - 2] + 1);
                }
                d[i][j] = value;
                rowMin = Math.min(rowMin, value);
            }
            if (rowMin > limit) {
                return limit + 1;
            }
        }
        return Math.min(d[n][m], limit + 1);
    }
}
