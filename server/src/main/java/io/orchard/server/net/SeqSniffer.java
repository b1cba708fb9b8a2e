package io.orchard.server.net;

/**
 * Finds the {@code "seq"} of a line that failed to decode, so the error can still name the message
 * it answers. Best effort: 0 when no plain {@code "seq":<digits>} is found.
 */
final class SeqSniffer {

    private static final byte[] KEY = "\"seq\"".getBytes(java.nio.charset.StandardCharsets.US_ASCII);

    private SeqSniffer() {}

    static long seqOf(byte[] line) {
        outer:
        for (int i = 0; i + KEY.length <= line.length; i++) {
            for (int k = 0; k < KEY.length; k++) {
                if (line[i + k] != KEY[k]) {
                    continue outer;
                }
            }
            int j = i + KEY.length;
            while (j < line.length && (line[j] == ' ' || line[j] == ':')) {
                j++;
            }
            long seq = 0;
            int digits = 0;
            while (j < line.length && line[j] >= '0' && line[j] <= '9' && digits < 18) {
                seq = seq * 10 + (line[j++] - '0');
                digits++;
            }
            return digits == 0 ? 0 : seq;
        }
        return 0;
    }
}
