package io.orchard.protocol;

/**
 * Checks that bytes are well-formed UTF-8 as RFC 3629 defines it, before the JSON parser sees them:
 * the parser decodes leniently, so an overlong form ({@code C0 AF} for {@code /}), a surrogate
 * ({@code ED A0 80}) or a code point beyond U+10FFFF would otherwise become a character, and a name
 * checked as letters could be smuggled in as bytes that are not. Stateless.
 */
final class Utf8 {

    private Utf8() {}

    /** What is wrong with the first malformed sequence in {@code bytes[0..length)}, or null when none is. */
    static String problem(byte[] bytes, int length) {
        int i = 0;
        while (i < length) {
            int lead = bytes[i] & 0xff;
            if (lead < 0x80) {
                i++;
                continue;
            }
            int size;
            int min = 0x80; // the second byte's range, which rules out overlong forms and surrogates
            int max = 0xbf;
            if (lead >= 0xc2 && lead <= 0xdf) {
                size = 2;
            } else if (lead >= 0xe0 && lead <= 0xef) {
                size = 3;
                if (lead == 0xe0) {
                    min = 0xa0;
                } else if (lead == 0xed) {
                    max = 0x9f;
                }
            } else if (lead >= 0xf0 && lead <= 0xf4) {
                size = 4;
                if (lead == 0xf0) {
                    min = 0x90;
                } else if (lead == 0xf4) {
                    max = 0x8f;
                }
            } else {
                return "invalid UTF-8 at byte " + i + ": " + lead(lead);
            }
            if (i + size > length) {
                return "invalid UTF-8 at byte " + i + ": a sequence of " + size
                        + " bytes cut short by the end of the line";
            }
            int second = bytes[i + 1] & 0xff;
            if (second < min || second > max) {
                if (second >= 0x80 && second <= 0xbf) {
                    String what = lead == 0xed ? "a surrogate"
                            : lead == 0xf4 ? "beyond U+10FFFF" : "an overlong encoding";
                    return "invalid UTF-8 at byte " + i + ": " + hex(bytes, i, size) + " is " + what;
                }
                return "invalid UTF-8 at byte " + (i + 1) + ": " + hex(bytes, i + 1, 1)
                        + " does not continue the sequence begun by " + hex(bytes, i, 1);
            }
            for (int k = 2; k < size; k++) {
                int next = bytes[i + k] & 0xff;
                if (next < 0x80 || next > 0xbf) {
                    return "invalid UTF-8 at byte " + (i + k) + ": " + hex(bytes, i + k, 1)
                            + " does not continue the sequence begun by " + hex(bytes, i, 1);
                }
            }
            i += size;
        }
        return null;
    }

    private static String lead(int lead) {
        String hex = String.format("0x%02X", lead);
        if (lead <= 0xbf) {
            return hex + " continues a sequence that was never begun";
        }
        if (lead <= 0xc1) {
            return hex + " begins an overlong encoding";
        }
        return hex + " is never part of UTF-8";
    }

    private static String hex(byte[] bytes, int from, int count) {
        StringBuilder text = new StringBuilder();
        for (int k = from; k < from + count && k < bytes.length; k++) {
            text.append(k == from ? "" : " ").append(String.format("0x%02X", bytes[k] & 0xff));
        }
        return text.toString();
    }
}
